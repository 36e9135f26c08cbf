//! Driving the processing element ([`ProcessingElement`]) through a whole source, as the host
//! does: ray directions, then the command stream with the sector changes in it, the host
//! memory answering the PE's requests, then the readout. [`model`] is what it must return.
//!
//! A sector change is a command like the others: the PE keeps two sectors and never drains
//! between them. It holds the stream only while the sector before last still has jobs before
//! the screener; those cycles are counted apart ([`PeCounters::drain_cycles`]).

use crate::intersection::{load_directions, read_hits};
use crate::memory::HostMemory;
use crate::pe_sim::{PeInputs, PeOutputs, PeRays, PeSim};
use crate::{impl_clocked, Error, Result};
use shelling_hdl::cache::LINES;
use shelling_hdl::formats::{Nearest, PatchSetup};
use shelling_hdl::intersection::model::{replaces, test};
use shelling_hdl::intersection::RAY_BITS;
use shelling_hdl::pe::ProcessingElement;
use shelling_hdl::screener::model::{screen, BundleSetup, Patch, Verdict};
use std::ops::Range;

impl_clocked!(ProcessingElement);

/// Rays a PE's source holds: the size of one half of its ray memory (the bundle of one source
/// on the PE; the other half holds the source before or after it).
pub const PE_RAY_MEMORY: usize = 1 << RAY_BITS;

/// One command of the host, in stream order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Command {
    /// The sector's first and last ray directions (Q2.16): the jobs after it are screened for
    /// it.
    Sector { first: [i32; 2], last: [i32; 2] },
    /// Load patch `id`, screen it, and test it against the live rays `first .. first + count`.
    Job { id: u16, first: u16, count: u16 },
    /// Rays `first .. first + count` leave the bundle.
    Retire { first: u16, count: u16 },
}

impl Command {
    /// The patch a job loads; `None` for a sector or a retire.
    pub fn job_id(&self) -> Option<u16> {
        match *self {
            Command::Job { id, .. } => Some(id),
            _ => None,
        }
    }
}

/// The source: ray origin (Q11.6 world coordinates), normal and ray directions (Q2.16).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PeSetup {
    pub origin: [i32; 2],
    pub normal: [i32; 2],
    pub dirs: Vec<[i32; 2]>,
}

impl PeSetup {
    fn bundle(&self, first: [i32; 2], last: [i32; 2]) -> BundleSetup {
        BundleSetup { origin: self.origin, normal: self.normal, first, last }
    }

    /// Checks the commands against the bundle and a memory of `patches` patches; the error names
    /// the first bad command.
    pub fn check(&self, commands: &[Command], patches: usize) -> Result<()> {
        let n = self.dirs.len();
        if n == 0 || n > PE_RAY_MEMORY {
            return Err(Error::new(format!("a PE traces 1 to {PE_RAY_MEMORY} rays, got {n}")));
        }
        for (k, c) in commands.iter().enumerate() {
            let bad = match *c {
                Command::Job { id, first, count }
                    if id as usize >= patches || first as usize + count as usize > n =>
                {
                    Some(format!("job for patch {id} of {patches}, rays {first}+{count} of {n}"))
                }
                Command::Retire { first, count } if first as usize + count as usize > n => {
                    Some(format!("retire of rays {first}+{count} of {n}"))
                }
                _ => None,
            };
            if let Some(what) = bad {
                return Err(Error::new(format!("command {k}: {what}")));
            }
        }
        Ok(())
    }
}

/// What the bit-true model counts of a command stream.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct ModelCounts {
    pub sectors: u64,
    /// Jobs, i.e. patches loaded.
    pub loads: u64,
    /// Jobs whose patch the screener passed.
    pub passed: u64,
    /// Ray slots of passed jobs: the cycles the intersection unit issues.
    pub ray_slots: u64,
    /// Ray-patch tests of live rays.
    pub tests: u64,
    /// Maximal runs of live rays within passed jobs' ranges: the jobs the intersection unit
    /// would take if the host split every range at its retired rays (one command per run), so
    /// that `ray_slots − tests` slots would go (the price of that option, against the bubbles).
    pub live_runs: u64,
    /// Rays retired by retire commands (each costs the intersection unit a slot).
    pub retires: u64,
}

impl ModelCounts {
    /// The counts of two command streams run one after the other.
    pub fn plus(&self, o: &ModelCounts) -> ModelCounts {
        ModelCounts {
            sectors: self.sectors + o.sectors,
            loads: self.loads + o.loads,
            passed: self.passed + o.passed,
            ray_slots: self.ray_slots + o.ray_slots,
            tests: self.tests + o.tests,
            live_runs: self.live_runs + o.live_runs,
            retires: self.retires + o.retires,
        }
    }
}

/// Walks `commands` as the bit-true model runs them: the sector's screener setup, each job's
/// verdict under it and the live rays. `job` sees every job: its command index, patch id, the
/// screener's setup of the patch if it passed, its ray range and the live bits (retired rays
/// false) as they stand when the job runs. Returns the sectors and the rays retired.
fn walk(
    setup: &PeSetup,
    patches: &[[i32; 4]],
    commands: &[Command],
    mut job: impl FnMut(usize, u16, Option<&PatchSetup>, Range<usize>, &[bool]),
) -> (u64, u64) {
    let n = setup.dirs.len();
    let mut live = vec![true; n];
    let (mut sectors, mut retires) = (0, 0);
    let mut bundle = setup.bundle(setup.dirs[0], setup.dirs[n - 1]);
    for (k, cmd) in commands.iter().enumerate() {
        match *cmd {
            Command::Sector { first, last } => {
                sectors += 1;
                bundle = setup.bundle(first, last);
            }
            Command::Job { id, first, count } => {
                let m = patches[id as usize];
                let verdict = screen(&bundle, &Patch { id, a: [m[0], m[1]], b: [m[2], m[3]] });
                let passed = match &verdict {
                    Verdict::Pass(p) => Some(p),
                    _ => None,
                };
                job(k, id, passed, first as usize..first as usize + count as usize, &live);
            }
            Command::Retire { first, count } => {
                retires += count as u64;
                live[first as usize..first as usize + count as usize].fill(false);
            }
        }
    }
    (sectors, retires)
}

/// The bit-true model of a PE running `commands` for `setup` on a host memory holding
/// `patches` (`[ax, ay, bx, by]`, Q11.6): every ray's nearest hit and the counts. Before the
/// first sector command the sector is the whole bundle (first and last ray).
pub fn model(
    setup: &PeSetup,
    patches: &[[i32; 4]],
    commands: &[Command],
) -> (Vec<Option<Nearest>>, ModelCounts) {
    let mut best: Vec<Option<Nearest>> = vec![None; setup.dirs.len()];
    let mut c = ModelCounts::default();
    (c.sectors, c.retires) = walk(setup, patches, commands, |_, id, passed, rays, live| {
        c.loads += 1;
        let Some(p) = passed else { return };
        c.passed += 1;
        c.ray_slots += rays.len() as u64;
        let mut run = false;
        for r in rays {
            if !live[r] {
                run = false;
                continue;
            }
            c.live_runs += !run as u64;
            run = true;
            c.tests += 1;
            if let Some(key) = test(p, setup.dirs[r]) {
                if replaces(key, id, best[r]) {
                    best[r] = Some(Nearest { key, id });
                }
            }
        }
    });
    (best, c)
}

/// The cycles of an ideal in-order PE on `commands`: a lower bound on any PE that takes its
/// commands in order, one a clock, loads each job's patch through a host memory that serves one
/// load per `tc` cycles (a request no earlier than its command), and tests the live rays of the
/// passed jobs in command order, one a clock, a job's no earlier than its patch is there. With
/// the cache on (`cache`, empty at the start) a job whose patch hits
/// ([`shelling_hdl::cache::model::Cache`]) has it at once; every other costs the host `tc`.
/// Every latency is zero and the window unbounded, so the bound holds whatever those are: it is
/// at least `max(memory loads·tc, loads, tests)` (the bound of the figures), and more where a
/// job waits for a load that no earlier test can cover (the loads of a cold cache at the start
/// of a source, a miss when the jobs before it have no tests left).
pub fn inorder_cycles(
    setup: &PeSetup,
    patches: &[[i32; 4]],
    commands: &[Command],
    tc: u64,
    cache: CacheConfig,
) -> u64 {
    let mut cache = cache.lines.map(|_| shelling_hdl::cache::model::Cache::new(cache.mask()));
    // When the host memory is free again, and when the intersection unit is.
    let (mut host, mut unit) = (0u64, 0u64);
    walk(setup, patches, commands, |k, id, passed, rays, live| {
        let k = k as u64;
        let there = if cache.as_mut().is_some_and(|c| c.access(id)) {
            k
        } else {
            host = host.max(k) + tc;
            host
        };
        let tests = if passed.is_some() { live[rays].iter().filter(|&&l| l).count() as u64 } else { 0 };
        if tests > 0 {
            unit = unit.max(there) + tests;
        }
    });
    unit.max(host).max(commands.len() as u64)
}

/// What the PE did, counted by the host from the PE's outputs.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct PeCounters {
    /// Cycles from the first command to the PE idle after the last one.
    pub cycles: u64,
    /// Cycles the intersection unit tested a live ray (one test per clock).
    pub intersection_busy_cycles: u64,
    /// `intersection_busy_cycles / cycles`.
    pub pipeline_efficiency: f64,
    /// Cycles the PE held work but the intersection unit tested nothing (waiting for patches,
    /// filling its pipeline, bubbles of retired rays), sector waits included.
    pub stall_cycles: u64,
    /// Stall cycles in which the command stream waited on a sector change (`cmd_ready` low
    /// after a sector command until the next command was taken: the PE's bank for the new
    /// sector still held jobs of the sector before last).
    pub drain_cycles: u64,
    /// Patches loaded by the PE's loader.
    pub patch_loads: u64,
    /// Patches the host memory delivered.
    pub memory_loads: u64,
    pub cache_hits: u64,
    pub passed: u64,
    pub backward: u64,
    pub back_facing: u64,
    pub outside: u64,
    pub near: u64,
    /// Ray-patch tests of live rays.
    pub tests: u64,
    /// Cycles writing the directions and reading the hits back (not in `cycles`).
    pub setup_cycles: u64,
    pub readout_cycles: u64,
}

/// The patch cache's setting for a run: off, or on with `lines` lines (a power of two from 1 to
/// [`shelling_hdl::cache::LINES`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CacheConfig {
    pub lines: Option<u32>,
}

impl CacheConfig {
    /// Checks the size; the error names it.
    pub fn check(&self) -> Result<()> {
        match self.lines {
            Some(n) if n == 0 || !n.is_power_of_two() || n as usize > LINES => Err(Error::new(format!(
                "the patch cache holds a power of two from 1 to {LINES} patches, got {n}"
            ))),
            _ => Ok(()),
        }
    }

    /// The cache's `cfg_mask`: its lines − 1 (0 when off, when `cfg_cache_enable` is low).
    pub fn mask(&self) -> u16 {
        (self.lines.unwrap_or(1) - 1) as u16
    }
}

/// Where the host memory keeps each patch, so that a cache of any number of lines works on the
/// cache's power-of-two line index (the address's low bits, `cfg_mask`).
///
/// With the cache off or holding a power of two of lines, patch `k` is at address `k`. A cache
/// of `C` lines otherwise is the RTL's cache with the mask of `S = 2^⌈log₂ C⌉` lines and this
/// memory map: patch `k` at address `S·⌊k / C⌋ + k mod C`. Patch `k` then goes to the cache's
/// line `k mod C`, lines `C … S − 1` hold nothing, and the addresses between (`S − C` in every
/// `S`) are holes of the host memory that no command names. The cache holds at most `C`
/// patches: a per-PE cache of exactly a quarter of a 1000-patch scene is a cache of 250 lines.
/// The PE is checked against the model of what it is given (mapped commands and memory);
/// [`MemoryMap::patch`] turns its hits' addresses back into patch numbers.
///
/// A placed map ([`MemoryMap::placed`]) puts patch `k` in slot `slot[k]` instead of slot `k`
/// (the address of slot `s` as above): the host chooses which patches share a cache line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MemoryMap {
    lines: Option<u32>,
    /// Each patch's slot and each slot's patch, for a placed map.
    placement: Option<(Vec<u32>, Vec<u32>)>,
}

impl MemoryMap {
    /// The map for a cache of `lines` lines (`None`: off) over `patches` patches. Fails, naming
    /// the size, on 0 or more than [`LINES`] lines and when an address would not fit the 16-bit
    /// ids.
    pub fn new(lines: Option<u32>, patches: usize) -> Result<Self> {
        if let Some(n) = lines.filter(|&n| n == 0 || n as usize > LINES) {
            return Err(Error::new(format!("the patch cache holds 1 to {LINES} patches, got {n}")));
        }
        let map = MemoryMap { lines, placement: None };
        if let (Some(_), Some(last)) = (map.spread(), patches.checked_sub(1)) {
            let top = map.address_of(last);
            if top >= 1 << 16 {
                return Err(Error::new(format!(
                    "a {}-line cache spreads {patches} patches over {} host memory addresses, beyond the \
                     16-bit ids: use a power of two of lines",
                    lines.unwrap_or(0),
                    top + 1
                )));
            }
        }
        Ok(map)
    }

    /// The map for a cache of `lines` lines with patch `k` in slot `slot[k]` (its line
    /// `slot[k] mod C`). Fails as [`MemoryMap::new`] does, and when `slot` is not a permutation
    /// of `0 … slot.len() − 1`.
    pub fn placed(lines: Option<u32>, slot: Vec<u32>) -> Result<Self> {
        let mut patch = vec![u32::MAX; slot.len()];
        for (k, &s) in slot.iter().enumerate() {
            match patch.get_mut(s as usize) {
                Some(p) if *p == u32::MAX => *p = k as u32,
                _ => {
                    return Err(Error::new(format!(
                        "patch {k}'s slot {s}: the slots of {} patches are a permutation of 0 to {}",
                        slot.len(),
                        slot.len().saturating_sub(1)
                    )))
                }
            }
        }
        let map = MemoryMap::new(lines, slot.len())?;
        Ok(MemoryMap { placement: Some((slot, patch)), ..map })
    }

    /// Patch `k`'s slot.
    fn slot(&self, k: usize) -> usize {
        self.placement.as_ref().map_or(k, |(slot, _)| slot[k] as usize)
    }

    /// `(C, S)` for a spread map, `None` for the identity.
    fn spread(&self) -> Option<(u32, u32)> {
        self.lines.filter(|n| !n.is_power_of_two()).map(|n| (n, n.next_power_of_two()))
    }

    fn address_of(&self, k: usize) -> usize {
        let slot = self.slot(k);
        match self.spread() {
            Some((c, s)) => s as usize * (slot / c as usize) + slot % c as usize,
            None => slot,
        }
    }

    /// The cache's setting on the PE: its lines rounded up to a power of two.
    pub fn cache(&self) -> CacheConfig {
        CacheConfig { lines: self.lines.map(u32::next_power_of_two) }
    }

    /// The host memory's contents: `patches` at their addresses, zero in the holes.
    pub fn memory(&self, patches: &[[i32; 4]]) -> Vec<[i32; 4]> {
        let len = (0..patches.len()).map(|k| self.address_of(k) + 1).max().unwrap_or(0);
        let mut out = vec![[0; 4]; len];
        for (k, p) in patches.iter().enumerate() {
            out[self.address_of(k)] = *p;
        }
        out
    }

    /// `commands` with their patch numbers turned into addresses.
    pub fn commands(&self, commands: &[Command]) -> Vec<Command> {
        commands
            .iter()
            .map(|c| match *c {
                Command::Job { id, first, count } => {
                    Command::Job { id: self.address_of(id as usize) as u16, first, count }
                }
                other => other,
            })
            .collect()
    }

    /// The patch at `address`, or `None` for a hole.
    pub fn patch(&self, address: u16) -> Option<u16> {
        let slot = match self.spread() {
            Some((c, s)) => {
                let (block, line) = (address as u32 / s, address as u32 % s);
                (line < c).then_some(block * c + line)?
            }
            None => address as u32,
        };
        match &self.placement {
            Some((_, patch)) => patch.get(slot as usize).map(|&k| k as u16),
            None => Some(slot as u16),
        }
    }
}

/// The processing element on rust-hdl's simulator: the engine with VCD windows and port
/// recording (the compiled one is [`crate::verilated::VerilatedPe`]).
pub type RustHdlPe = crate::Driver<ProcessingElement>;

/// A processing element fresh from power-up on rust-hdl's simulator.
pub fn rust_hdl_pe() -> Result<RustHdlPe> {
    crate::Driver::new(ProcessingElement::default())
}

/// The host's side of one PE's command phase, one cycle at a time: the command stream (the
/// whole bundle as the first sector, then `commands`), what the PE took of it, and the counts
/// of [`PeCounters`] the loop makes. [`run`] steps one with the host memory wired to the PE;
/// a machine of several PEs (`crate::machine`) steps one per PE beside its memory arbiter.
pub struct CommandHost {
    stream: Vec<Command>,
    /// The source's origin and normal, offered with every command (the PE takes them with a
    /// sector command).
    source: [[i32; 2]; 2],
    next: usize,
    // The last command taken was a sector.
    after_sector: bool,
    // The PE's counters at the start (they wrap and run from power-up: a run counts what they
    // add).
    base: [u32; 8],
    tests_before: u32,
    start: u64,
    idle_since: u64,
    last_progress: u64,
    // This cycle's flags, from before the edge.
    busy: bool,
    waiting: bool,
    intersection_busy_cycles: u64,
    stall_cycles: u64,
    drain_cycles: u64,
}

/// The PE's counters (loads, tests, cache hits, passed, backward, back-facing, outside, near),
/// as they are now: [`counts_since`] turns two of them into counts.
pub fn counters(o: &PeOutputs) -> [u32; 8] {
    [o.loads, o.tests, o.cache_hits, o.passed, o.backward, o.back_facing, o.outside, o.near]
}

/// `k` with what the PE's counters added from `base` to `out` (they wrap).
pub fn counts_since(base: [u32; 8], out: &PeOutputs, mut k: PeCounters) -> PeCounters {
    let delta: Vec<u64> = counters(out).iter().zip(base).map(|(c, b)| c.wrapping_sub(b) as u64).collect();
    k.patch_loads = delta[0];
    k.tests = delta[1];
    k.cache_hits = delta[2];
    k.passed = delta[3];
    k.backward = delta[4];
    k.back_facing = delta[5];
    k.outside = delta[6];
    k.near = delta[7];
    k
}

impl CommandHost {
    /// The command phase of a source starting with the PE's outputs `out` at cycle `now`, its
    /// rays in the first half of the ray memory.
    pub fn new(setup: &PeSetup, commands: &[Command], out: PeOutputs, now: u64) -> Self {
        let n = setup.dirs.len();
        let whole = Command::Sector { first: setup.dirs[0], last: setup.dirs[n - 1] };
        let base = counters(&out);
        Self {
            stream: std::iter::once(whole).chain(commands.iter().copied()).collect(),
            source: [setup.origin, setup.normal],
            next: 0,
            after_sector: false,
            base,
            tests_before: base[1],
            start: now,
            idle_since: now,
            last_progress: 0,
            busy: false,
            waiting: false,
            intersection_busy_cycles: 0,
            stall_cycles: 0,
            drain_cycles: 0,
        }
    }

    /// As [`CommandHost::new`], the source's rays in half `half` (0 or 1) of the ray memory
    /// (ray `r` is the PE's ray `half · PE_RAY_MEMORY + r`), and its stream ending with a
    /// **marker** (a retire of no rays): the PE's `marks` counts it once the source's last test
    /// has written its hit, and its half may then be read out while the next source runs in
    /// the other.
    pub fn in_half(setup: &PeSetup, commands: &[Command], out: PeOutputs, now: u64, half: usize) -> Self {
        let mut h = Self::new(setup, commands, out, now);
        let off = (half * PE_RAY_MEMORY) as u16;
        for c in &mut h.stream {
            match c {
                Command::Job { first, .. } | Command::Retire { first, .. } => *first += off,
                Command::Sector { .. } => {}
            }
        }
        h.stream.push(Command::Retire { first: off, count: 0 });
        h
    }

    /// The command offered in this cycle, if any is left.
    pub fn command(&self) -> Option<Command> {
        self.stream.get(self.next).copied()
    }

    /// Sets the command ports of `i` to offer this cycle's command, and the source's origin
    /// and normal beside it.
    pub fn offer(&self, i: &mut PeInputs) {
        [[i.origin_x, i.origin_y], [i.normal_x, i.normal_y]] = self.source;
        Self::set_inputs(i, self.command());
    }

    /// Every command taken.
    pub fn all_sent(&self) -> bool {
        self.next == self.stream.len()
    }

    /// Sets the command ports of `i` to offer `cmd` (or nothing).
    pub fn set_inputs(i: &mut PeInputs, cmd: Option<Command>) {
        i.cmd_valid = cmd.is_some();
        i.cmd_retire = matches!(cmd, Some(Command::Retire { .. }));
        i.cmd_sector = matches!(cmd, Some(Command::Sector { .. }));
        match cmd {
            Some(Command::Sector { first, last }) => {
                [i.first_x, i.first_y] = first;
                [i.last_x, i.last_y] = last;
            }
            Some(Command::Job { id, first, count }) => {
                i.cmd_id = id;
                i.cmd_first = first;
                i.cmd_count = count;
            }
            Some(Command::Retire { first, count }) => {
                i.cmd_first = first;
                i.cmd_count = count;
            }
            None => {}
        }
    }

    /// Before the edge, with the PE's outputs under this cycle's inputs: the command taken, if
    /// `cmd_ready`.
    pub fn before_tick(&mut self, out: &PeOutputs) {
        self.busy = out.busy;
        self.waiting = self.after_sector && !out.cmd_ready;
        let cmd = self.command();
        if cmd.is_some() && out.cmd_ready {
            self.after_sector = matches!(cmd, Some(Command::Sector { .. }));
            self.next += 1;
        }
    }

    /// After the edge (cycle `now`): the counts; `progress(done, total)` every 256 commands.
    pub fn after_tick(&mut self, out: &PeOutputs, now: u64, progress: &mut impl FnMut(usize, usize)) {
        let tested = out.tests != self.tests_before;
        self.tests_before = out.tests;
        self.intersection_busy_cycles += tested as u64;
        if !tested && (self.busy || self.next < self.stream.len()) {
            self.stall_cycles += 1;
            self.drain_cycles += self.waiting as u64;
        }
        if tested || self.next as u64 != self.last_progress {
            self.idle_since = now;
        }
        if self.next as u64 != self.last_progress {
            self.last_progress = self.next as u64;
            if self.next.is_multiple_of(256) {
                progress(self.next - 1, self.stream.len() - 1);
            }
        }
    }

    /// Every command taken and the PE idle (its memory requests answered is the caller's to
    /// check).
    pub fn finished(&self, out: &PeOutputs) -> bool {
        self.next == self.stream.len() && !out.busy
    }

    /// Fails, naming where, once the PE has neither tested nor taken a command for more than
    /// `limit` cycles.
    pub fn check_progress(&self, now: u64, limit: u64) -> Result<()> {
        if now - self.idle_since > limit {
            return Err(Error::new(format!(
                "no progress for {} cycles at command {} of {} ({:?})",
                now - self.idle_since,
                self.next as i64 - 1,
                self.stream.len() - 1,
                self.stream.get(self.next)
            )));
        }
        Ok(())
    }

    /// `k` with the command phase's counts, the PE's outputs `out` at its end, cycle `now`.
    pub fn counters(&self, out: &PeOutputs, now: u64, mut k: PeCounters) -> PeCounters {
        k.cycles = now - self.start;
        k.intersection_busy_cycles = self.intersection_busy_cycles;
        k.stall_cycles = self.stall_cycles;
        k.drain_cycles = self.drain_cycles;
        k.pipeline_efficiency =
            if k.cycles > 0 { k.intersection_busy_cycles as f64 / k.cycles as f64 } else { 0.0 };
        counts_since(self.base, out, k)
    }
}

/// The source's setup on the PE: origin, normal, the cache's setting and the ray directions.
/// Returns the cycles it took.
pub fn load_source<S: PeSim>(sim: &mut S, setup: &PeSetup, cache: CacheConfig) -> Result<u64> {
    let start = sim.cycles();
    let (o, nm) = (setup.origin, setup.normal);
    sim.drive(|i| {
        [i.origin_x, i.origin_y] = o;
        [i.normal_x, i.normal_y] = nm;
        i.cfg_cache_enable = cache.lines.is_some();
        i.cfg_cache_mask = cache.mask();
    })?;
    load_directions(&mut PeRays(sim), &setup.dirs)?;
    Ok(sim.cycles() - start)
}

/// The readout of `rays` rays' hits (read and clear). Returns them and the cycles it took.
pub fn read_out<S: PeSim>(sim: &mut S, rays: usize) -> Result<(Vec<Option<Nearest>>, u64)> {
    let start = sim.cycles();
    let hits = read_hits(&mut PeRays(sim), rays)?;
    Ok((hits, sim.cycles() - start))
}

/// Runs a whole source on a PE fresh from power-up (or after a previous run's readout):
/// directions, commands, readout. `progress(done, total)` is called now and then with the
/// commands sent so far. A run that stops making progress is an error naming where it stopped.
/// `sim` is any simulator of the PE: rust-hdl's ([`crate::Driver`]) or the compiled one
/// ([`crate::verilated::VerilatedPe`]); both give the same cycles.
pub fn run<S: PeSim>(
    sim: &mut S,
    memory: &mut HostMemory,
    setup: &PeSetup,
    cache: CacheConfig,
    commands: &[Command],
    mut progress: impl FnMut(usize, usize),
) -> Result<(Vec<Option<Nearest>>, PeCounters)> {
    setup.check(commands, memory.len())?;
    cache.check()?;
    let mut k = PeCounters::default();
    let n = setup.dirs.len();

    k.setup_cycles = load_source(sim, setup, cache)?;

    // Commands, after the whole bundle as the first sector. The memory's answer to a request
    // is presented from the next cycle on.
    let mut host = CommandHost::new(setup, commands, sim.outputs(), sim.cycles());
    let mut response: Option<[i32; 4]> = None;
    loop {
        let cmd = host.command();
        sim.drive(|i| {
            i.mem_valid = response.is_some();
            if let Some(m) = response {
                [i.mem_ax, i.mem_ay, i.mem_bx, i.mem_by] = m;
            }
            CommandHost::set_inputs(i, cmd);
        })?;
        let out = sim.outputs();
        host.before_tick(&out);
        let request = out.mem_req.then_some(out.mem_addr);
        response = memory.cycle(request)?;
        sim.tick()?;
        let out = sim.outputs();
        host.after_tick(&out, sim.cycles(), &mut progress);
        if host.finished(&out) && response.is_none() && memory.pending() == 0 {
            break;
        }
        host.check_progress(sim.cycles(), 64 * (memory.tc() as u64 + 64))?;
    }
    progress(commands.len(), commands.len());
    k = host.counters(&sim.outputs(), sim.cycles(), k);
    k.memory_loads = memory.loads();

    let (hits, cycles) = read_out(sim, n)?;
    k.readout_cycles = cycles;
    Ok((hits, k))
}

/// Invalidates the PE's patch cache, as the host must before the first run on new host memory
/// contents (a new scene): waits until the PE is idle, raises `cfg_cache_flush` for one cycle and
/// waits out the flush ([`LINES`] cycles, `busy` high). Returns the cycles it took.
pub fn flush_cache(sim: &mut impl PeSim) -> Result<u64> {
    let start = sim.cycles();
    let limit = start + 4 * LINES as u64;
    let mut flushed = false;
    loop {
        let idle = !sim.outputs().busy;
        if idle && flushed {
            return Ok(sim.cycles() - start);
        }
        if sim.cycles() > limit {
            return Err(Error::new(format!(
                "the cache flush did not end within {} cycles (busy since cycle {start})",
                limit - start
            )));
        }
        let raise = idle && !flushed;
        sim.cycle(|i| i.cfg_cache_flush = raise)?;
        flushed |= raise;
    }
}

/// The PE's signals [`check_protocol`] reads from a VCD.
const PROTOCOL_SIGNALS: [&str; 20] = [
    "uut.loader.reserved.q",
    "uut.loader.id_valid",
    "uut.loader.id_ready",
    "uut.loader.id",
    "uut.loader.mem_req",
    "uut.loader.mem_addr",
    "uut.loader.mem_valid",
    "uut.loader.out_valid",
    "uut.loader.out_ready",
    "uut.loader.out_id",
    "uut.screener.in_valid",
    "uut.screener.in_ready",
    "uut.screener.in_id",
    "uut.screener.out_valid",
    "uut.screener.out_ready",
    "uut.screener.out_id",
    "uut.screener.used.q",
    "uut.tags.count",
    "uut.tags.push",
    "uut.busy",
];

/// What [`check_protocol`] saw.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ProtocolReport {
    pub cycles: usize,
    /// Ids accepted by the loader, in order.
    pub ids: Vec<u16>,
    pub max_loader_reserved: u64,
    pub max_screener_in_flight: u64,
    pub max_tags: u64,
}

/// Checks the PE's stream protocol on a VCD of a whole run (from power-up until the PE is idle
/// after its last command): the loader's FIFO never holds more than its depth and takes no id
/// while full; the tag FIFO likewise; the screener never has more than its credit limit in
/// flight; and every id the loader accepted was requested from memory, answered, handed to the
/// screener and left it exactly once, in order. An error names the first cycle that breaks it.
pub fn check_protocol(path: &std::path::Path) -> Result<ProtocolReport> {
    use shelling_hdl::{loader, pe, screener};
    let w = crate::waves::Waves::read(path, &PROTOCOL_SIGNALS)?;
    let s = |name: &str| w.get(name);
    let (reserved, id_valid, id_ready, id) = (
        s("uut.loader.reserved.q")?,
        s("uut.loader.id_valid")?,
        s("uut.loader.id_ready")?,
        s("uut.loader.id")?,
    );
    let (mem_req, mem_addr, mem_valid) =
        (s("uut.loader.mem_req")?, s("uut.loader.mem_addr")?, s("uut.loader.mem_valid")?);
    let (l_valid, l_ready, l_id) =
        (s("uut.loader.out_valid")?, s("uut.loader.out_ready")?, s("uut.loader.out_id")?);
    let (s_in_valid, s_in_ready, s_in_id) =
        (s("uut.screener.in_valid")?, s("uut.screener.in_ready")?, s("uut.screener.in_id")?);
    let (s_valid, s_ready, s_id) =
        (s("uut.screener.out_valid")?, s("uut.screener.out_ready")?, s("uut.screener.out_id")?);
    let (used, tags, tag_we, busy) =
        (s("uut.screener.used.q")?, s("uut.tags.count")?, s("uut.tags.push")?, s("uut.busy")?);
    let n = w.cycles();
    if n == 0 || w.first_cycle != 0 {
        return Err(Error::new(format!(
            "{}: the protocol check needs a whole run from cycle 0 (the file starts at cycle {}, {n} cycles)",
            path.display(),
            w.first_cycle
        )));
    }
    let mut r = ProtocolReport { cycles: n, ..Default::default() };
    let (mut requested, mut answered, mut to_screener, mut from_screener) = (vec![], 0usize, vec![], vec![]);
    for c in 0..n {
        let bad = |what: String| Err(Error::new(format!("{}: cycle {c}: {what}", path.display())));
        r.max_loader_reserved = r.max_loader_reserved.max(reserved[c]);
        r.max_screener_in_flight = r.max_screener_in_flight.max(used[c]);
        r.max_tags = r.max_tags.max(tags[c]);
        if reserved[c] > loader::DEPTH as u64 {
            return bad(format!("the loader holds {} patches (depth {})", reserved[c], loader::DEPTH));
        }
        if id_valid[c] & id_ready[c] == 1 {
            if reserved[c] == loader::DEPTH as u64 {
                return bad("the loader took an id while full".into());
            }
            r.ids.push(id[c] as u16);
        }
        if used[c] > screener::DEPTH as u64 {
            return bad(format!("{} patches in the screener (credit limit {})", used[c], screener::DEPTH));
        }
        if tags[c] > pe::TAG_DEPTH as u64 || (tag_we[c] == 1 && tags[c] == pe::TAG_DEPTH as u64) {
            return bad(format!(
                "the tag FIFO holds {} and writes {} (depth {})",
                tags[c],
                tag_we[c],
                pe::TAG_DEPTH
            ));
        }
        if mem_req[c] == 1 {
            requested.push(mem_addr[c] as u16);
        }
        answered += mem_valid[c] as usize;
        if l_valid[c] & l_ready[c] == 1 {
            if s_in_valid[c] & s_in_ready[c] != 1 || s_in_id[c] != l_id[c] {
                return bad("the loader's transfer is not the screener's".into());
            }
            to_screener.push(l_id[c] as u16);
        }
        if s_valid[c] & s_ready[c] == 1 {
            from_screener.push(s_id[c] as u16);
        }
    }
    if busy[n - 1] != 0 {
        return Err(Error::new(format!("{}: the PE is still busy at the end of the file", path.display())));
    }
    let stages = [
        ("requested from memory", &requested),
        ("handed to the screener", &to_screener),
        ("out of the screener", &from_screener),
    ];
    for (what, seen) in stages {
        if *seen != r.ids {
            let k = seen.iter().zip(&r.ids).position(|(a, b)| a != b).unwrap_or(seen.len().min(r.ids.len()));
            return Err(Error::new(format!(
                "{}: the ids {what} ({}) are not the {} ids accepted, in order: first difference at {k}",
                path.display(),
                seen.len(),
                r.ids.len()
            )));
        }
    }
    if answered != r.ids.len() {
        return Err(Error::new(format!(
            "{}: {answered} memory answers for {} ids",
            path.display(),
            r.ids.len()
        )));
    }
    Ok(r)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ideal in-order PE, by hand: jobs of no ray (no tests) cost the host `T_c` a load,
    /// one after the other, each no earlier than its command; behind the cache only the misses
    /// do; a job's tests follow its patch and the tests before them.
    #[test]
    fn the_ideal_in_order_pe_counts_the_host_the_hits_and_the_tests() {
        let setup = PeSetup { origin: [0, 0], normal: [0, 1 << 16], dirs: vec![[0, 1 << 16]; 8] };
        // Patch 0 lies across the rays, above the origin, facing it; patch 1 behind the origin.
        let patches = [[640, 640, -640, 640], [-640, -640, 640, -640]];
        let empty = |id| Command::Job { id, first: 0, count: 0 };
        let (off, four) = (CacheConfig { lines: None }, CacheConfig { lines: Some(4) });
        let three = [empty(0), empty(1), empty(0)];
        assert_eq!(inorder_cycles(&setup, &patches, &three, 5, off), 15);
        assert_eq!(inorder_cycles(&setup, &patches, &three, 5, four), 10, "the third load hits");
        assert_eq!(inorder_cycles(&setup, &patches, &three, 1, off), 3, "one command a clock");
        // Patch 0 against the eight rays: its tests start when it is there (cycle 5).
        let job = Command::Job { id: 0, first: 0, count: 8 };
        let (_, counts) = model(&setup, &patches, &[job]);
        assert_eq!((counts.passed, counts.tests), (1, 8), "the screener passes patch 0: {counts:?}");
        assert_eq!(inorder_cycles(&setup, &patches, &[job], 5, off), 13);
        // Retired rays are not tested; patch 1 is screened out (its rays untested).
        let retire = Command::Retire { first: 0, count: 3 };
        let stream = [retire, job, Command::Job { id: 1, first: 0, count: 8 }];
        assert_eq!(inorder_cycles(&setup, &patches, &stream, 2, off), 3 + 5);
    }

    #[test]
    fn a_spread_map_fills_the_first_lines_of_every_block_and_inverts() {
        let map = MemoryMap::new(Some(250), 1000).unwrap();
        assert_eq!(map.cache(), CacheConfig { lines: Some(256) });
        let patches: Vec<[i32; 4]> = (0..1000).map(|k| [k, k + 1, k + 2, k + 3]).collect();
        let memory = map.memory(&patches);
        assert_eq!(memory.len(), 3 * 256 + 250);
        let mut lines = vec![0usize; 256];
        for k in 0..1000u16 {
            let [a] = map.commands(&[Command::Job { id: k, first: 1, count: 2 }])[..] else { unreachable!() };
            let Command::Job { id, first: 1, count: 2 } = a else { panic!("{a:?}") };
            assert_eq!(map.patch(id), Some(k));
            assert_eq!(memory[id as usize], patches[k as usize]);
            assert_eq!(id as usize & 255, k as usize % 250);
            lines[id as usize & 255] += 1;
        }
        assert!(lines[..250].iter().all(|&n| n == 4) && lines[250..].iter().all(|&n| n == 0), "{lines:?}");
        assert_eq!((250..256).filter_map(|a| map.patch(a)).count(), 0, "holes hold no patch");
        let sector = Command::Sector { first: [1, 2], last: [3, 4] };
        assert_eq!(map.commands(&[sector]), vec![sector]);
    }

    #[test]
    fn powers_of_two_and_no_cache_keep_the_identity() {
        for lines in [None, Some(1), Some(128), Some(LINES as u32)] {
            let map = MemoryMap::new(lines, 70_000).unwrap();
            assert_eq!(map.cache(), CacheConfig { lines });
            assert_eq!((map.patch(777), map.memory(&[[1; 4]; 3]).len()), (Some(777), 3));
        }
    }

    #[test]
    fn a_placed_map_puts_each_patch_in_its_slot_and_inverts() {
        let slot: Vec<u32> = (0..10).map(|k| (k * 3) % 10).collect();
        let patches: Vec<[i32; 4]> = (0..10).map(|k| [k; 4]).collect();
        for lines in [None, Some(4), Some(3)] {
            let map = MemoryMap::placed(lines, slot.clone()).unwrap();
            let plain = MemoryMap::new(lines, 10).unwrap();
            let memory = map.memory(&patches);
            assert_eq!(memory.len(), plain.memory(&patches).len());
            for k in 0..10u16 {
                let [Command::Job { id, .. }] =
                    map.commands(&[Command::Job { id: k, first: 0, count: 1 }])[..]
                else {
                    unreachable!()
                };
                let [Command::Job { id: at, .. }] =
                    plain.commands(&[Command::Job { id: slot[k as usize] as u16, first: 0, count: 1 }])[..]
                else {
                    unreachable!()
                };
                assert_eq!((id, map.patch(id), memory[id as usize]), (at, Some(k), patches[k as usize]));
            }
        }
        for bad in [vec![0, 0], vec![0, 2]] {
            let e = MemoryMap::placed(Some(4), bad).unwrap_err();
            assert!(e.message().contains("a permutation of 0 to 1"), "{e}");
        }
    }

    #[test]
    fn bad_sizes_are_errors_that_name_them() {
        for (lines, patches, what) in
            [(0, 10, "got 0"), (1025, 10, "got 1025"), (3, 60_000, "3-line cache spreads 60000 patches")]
        {
            let e = MemoryMap::new(Some(lines), patches).unwrap_err();
            assert!(e.message().contains(what), "{e}");
        }
        assert!(MemoryMap::new(Some(3), 49_152).is_ok(), "the last address is 65535");
    }
}
