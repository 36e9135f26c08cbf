//! The parallel machine in co-simulation: sources of one scene dealt to `N` processing
//! elements that share one host memory through the memory arbiter
//! ([`shelling_testbench::machine`]), every PE's hits and counts checked against the bit-true
//! model of its work, as [`crate::cosim`] checks one PE's.
//!
//! The host deals whole sources (the radiosity method shoots from every patch) or sectors of
//! every source (the paper: "when assigning sectors to processors, a ray is always processed by
//! one processor"), and each PE runs its queue on its own
//! ([`shelling_testbench::machine::run_queues`]): no PE waits for another's source to end, nor
//! for its own sources' setups and readouts (they overlap its commands, in the other half of
//! its ray memory). Every source's hits are checked; a PE's counts are checked over its queue,
//! its overlapped sources' counts being one stream.
//!
//! Whole sources: the order matters to the PEs' caches, a PE that traces neighbouring sources
//! one after the other finding the patches the last one loaded. [`spatial_order`] sorts the
//! sources along a Hilbert curve of their midpoints, and [`Deal`] hands that order out in
//! contiguous blocks of even work (PE `p` traces the `p`-th block; a source's work,
//! [`work_of`], is taken from the bit-true model of its commands before the run) or
//! interleaved (PE `p` the sources `p`, `p + N`, ...).
//!
//! Sectors: each source's bundle is cut into `N` contiguous ray ranges ([`part_range`]), PE `p`
//! taking the `p`-th range of every source. Stochastic shelling sizes each sector from the
//! previous one; each part is scheduled as a bundle of its own ([`schedule_sources`]), so each
//! PE's sectors follow one another within its own contiguous range and the rule holds unbroken.
//! A part sees the patches of its own angular range, so each PE's cache holds a slice of the
//! scene's directions rather than a region of it.

use crate::cosim::{
    check_counts, check_hits, memory_map, patch_numbers, with_vcd, CosimError, Engine, VcdWindow,
};
use crate::geom::Segment;
use crate::limits::{check_range, MAX_TC};
use crate::rays::{Bundle, RaySet};
use crate::run::{GriddedScene, Scheduled};
use crate::scene::Scene;
use crate::trace::{Method, ShellParams};
use crate::workstream::{commands, PeWork};
use serde::Serialize;
use shelling_hdl::arbiter::MAX_PES;
use shelling_hdl::formats::Nearest;
use shelling_testbench::machine::{run_queues, Composed, MachineSim, Work};
use shelling_testbench::memory::HostMemory;
use shelling_testbench::pe::{self, rust_hdl_pe, Command, MemoryMap, PeSetup};
use shelling_testbench::verilated::VerilatedPe;

/// How the sources, in their order, are dealt to the PEs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum Deal {
    /// PE `p` traces the `p`-th of `N` contiguous blocks of the order, source after source, the
    /// blocks cut where the sources' work ([`work_of`]) reaches `p/N` of the whole.
    #[default]
    Blocks,
    /// PE `p` traces the sources `p`, `p + N`, `p + 2N`, ... of the order.
    Interleaved,
    /// Every source's rays in `N` contiguous ranges, PE `p` tracing the `p`-th range of every
    /// source in the order: a ray always on one PE (the paper's rule), each PE's shells its own.
    Sectors,
}

impl Deal {
    /// The parts a source is cut into on `pes` PEs.
    pub fn parts(self, pes: usize) -> usize {
        if self == Deal::Sectors {
            pes
        } else {
            1
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Deal::Blocks => "blocks",
            Deal::Interleaved => "interleaved",
            Deal::Sectors => "sectors",
        }
    }
}

/// The deal of the sources to `pes` PEs, `work[i]` being the `i`-th source's work (any
/// measure that adds up, e.g. its tests): `queues[p]` lists, in the order PE `p` traces them,
/// the work items it is given, item `i·parts + j` being part `j` of the `i`-th source of the
/// order (`parts` is [`Deal::parts`]). Blocks are cut where the work, not the count, reaches
/// `p/N` of the whole: source `i` goes to the block its work's midpoint falls in, so the blocks
/// stay contiguous and every PE's share is within about one source of `1/N` of the work (all
/// zero work: even counts). `pes` is at least 1.
pub fn deal(work: &[u64], pes: usize, how: Deal) -> Vec<Vec<usize>> {
    let sources = work.len();
    let even = work.iter().all(|&w| w == 0);
    let weight = |i: usize| if even { 1 } else { u128::from(work[i]) };
    let total: u128 = (0..sources).map(weight).sum();
    let mut blocks = vec![Vec::new(); pes];
    let mut before = 0u128;
    for i in 0..sources {
        let w = weight(i);
        // The block of the midpoint (before + w/2) / total, in units of 1/(2·total).
        let p = ((2 * before + w) * pes as u128 / (2 * total).max(1)) as usize;
        blocks[p.min(pes - 1)].push(i);
        before += w;
    }
    (0..pes)
        .map(|p| match how {
            Deal::Blocks => std::mem::take(&mut blocks[p]),
            Deal::Interleaved => (p..sources).step_by(pes).collect(),
            Deal::Sectors => (0..sources).map(|i| i * pes + p).collect(),
        })
        .collect()
}

/// The ray range of part `j` of `parts` of a bundle of `rays` rays: contiguous, as even as can
/// be, in order.
pub fn part_range(rays: usize, parts: usize, j: usize) -> std::ops::Range<usize> {
    j * rays / parts..(j + 1) * rays / parts
}

/// The bundle's rays of `range` as a bundle of their own (the same source and ray set).
pub fn sub_bundle(bundle: &Bundle, range: std::ops::Range<usize>) -> Bundle {
    Bundle {
        source: bundle.source,
        set: bundle.set,
        rays: bundle.rays[range.clone()].to_vec(),
        angles: bundle.angles[range].to_vec(),
    }
}

/// The work items of `order`'s sources as [`deal`] numbers them: each source's bundle of `rays`
/// rays of `set`, cut into `parts` contiguous ranges, each scheduled by `method` on the bit-true
/// backend. A source's parts together trace what its whole bundle traces.
pub fn schedule_sources(
    prepared: &GriddedScene,
    order: &[usize],
    method: Method,
    set: RaySet,
    rays: usize,
    params: &ShellParams,
    parts: usize,
) -> anyhow::Result<Vec<Scheduled>> {
    use anyhow::Context;
    let mut out = Vec::with_capacity(order.len() * parts);
    for &k in order {
        let bundle = prepared.patch_bundle(k, set, rays).with_context(|| format!("source patch {k}"))?;
        out.extend(
            schedule_parts(prepared, &bundle, method, params, parts)
                .with_context(|| format!("source patch {k}"))?,
        );
    }
    Ok(out)
}

/// `bundle` cut into `parts` contiguous ranges of its rays, each scheduled by `method` on the
/// bit-true backend (the work items of one source, as [`schedule_sources`] makes them).
pub fn schedule_parts(
    prepared: &GriddedScene,
    bundle: &Bundle,
    method: Method,
    params: &ShellParams,
    parts: usize,
) -> anyhow::Result<Vec<Scheduled>> {
    let rays = bundle.len();
    if parts == 0 || parts > rays {
        anyhow::bail!("{rays} rays cannot be cut into {parts} parts: one ray at least a part");
    }
    (0..parts)
        .map(|j| Ok(prepared.schedule(method, &sub_bundle(bundle, part_range(rays, parts, j)), params)?))
        .collect()
}

/// The index of cell `(x, y)` along the Hilbert curve over a `2^bits × 2^bits` grid: cells
/// consecutive on the curve are neighbours in the grid (the curve never jumps, as a Z-order
/// curve does between its quadrants).
pub fn hilbert_index(bits: u32, x: u32, y: u32) -> u64 {
    let (mut x, mut y, mut d) = (x, y, 0u64);
    let n = 1u32 << bits;
    let mut s = n / 2;
    while s > 0 {
        let (rx, ry) = (u32::from(x & s > 0), u32::from(y & s > 0));
        d += u64::from(s) * u64::from(s) * u64::from((3 * rx) ^ ry);
        // Rotate the quadrant so that the curve inside it starts where the last one ended.
        if ry == 0 {
            if rx == 1 {
                (x, y) = (n - 1 - x, n - 1 - y);
            }
            (x, y) = (y, x);
        }
        s /= 2;
    }
    d
}

/// The patches `ids` of `segments` along a Hilbert curve of their midpoints (on a 1024 × 1024
/// grid over their bounding box), so that neighbours in the order are neighbours in the scene.
pub fn spatial_order(segments: &[Segment], ids: &[usize]) -> Vec<usize> {
    let mid = |k: usize| (segments[k].a + segments[k].b) * 0.5;
    let (mut lo, mut hi) = (mid(ids[0]), mid(ids[0]));
    for &k in ids {
        lo = lo.min(mid(k));
        hi = hi.max(mid(k));
    }
    let span = (hi - lo).max(glam::DVec2::splat(1e-9));
    let key = |k: usize| {
        let q = ((mid(k) - lo) / span * 1023.0).round();
        hilbert_index(10, q.x as u32, q.y as u32)
    };
    let mut out = ids.to_vec();
    out.sort_by_key(|&k| (key(k), k));
    out
}

/// How the host memory lays the scene's patches out (the PEs address them by index).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum Layout {
    /// Along a Hilbert curve of their midpoints ([`hilbert_ordered`]): patches near one another
    /// in the scene sit at consecutive addresses, so they fall in different lines of a PE's
    /// direct-mapped cache instead of evicting one another.
    #[default]
    Hilbert,
    /// In the scene file's order.
    File,
}

impl Layout {
    pub fn name(self) -> &'static str {
        match self {
            Layout::Hilbert => "hilbert",
            Layout::File => "file",
        }
    }
}

/// `scene` with its patches (and their materials) along a Hilbert curve of their midpoints, and
/// for each new index the old one: `(scene', old_of_new)`, `scene'.segments[i] = scene.segments[old_of_new[i]]`.
pub fn hilbert_ordered(scene: &Scene) -> (Scene, Vec<usize>) {
    let all: Vec<usize> = (0..scene.segments.len()).collect();
    let old_of_new = spatial_order(&scene.segments, &all);
    let out = Scene {
        segments: old_of_new.iter().map(|&k| scene.segments[k]).collect(),
        materials: old_of_new.iter().map(|&k| scene.material(k)).collect(),
        world: scene.world,
    };
    (out, old_of_new)
}

/// `scene` laid out as `layout` says, and for each new index the old one.
pub fn lay_out(scene: Scene, layout: Layout) -> (Scene, Vec<usize>) {
    match layout {
        Layout::Hilbert => hilbert_ordered(&scene),
        Layout::File => {
            let n = scene.segments.len();
            (scene, (0..n).collect())
        }
    }
}

/// Where the host memory puts the patches for the PEs' direct-mapped caches (with the caches
/// off it makes no difference).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum Placement {
    /// Patch `k` in slot `k` (line `k mod C`): the layout's order decides which patches share
    /// a line.
    Index,
    /// Each patch in the line where it meets the fewest patches that the same work items use
    /// ([`place_for_caches`]), from the dealt work, before the run.
    #[default]
    Lines,
}

impl Placement {
    pub fn name(self) -> &'static str {
        match self {
            Placement::Index => "index",
            Placement::Lines => "lines",
        }
    }
}

/// The slots of `patches` patches for caches of `lines` lines (slot `s` in line `s mod lines`,
/// as [`shelling_testbench::pe::MemoryMap::placed`] takes them), from the patches each PE's
/// work items ask for: `queues[p]` lists PE `p`'s items in the order it runs them, each as the
/// ids of its jobs.
///
/// Two patches meet once for every item that asks for both, and once for every two items
/// one after the other on one PE of which one asks for the one and the other for the other: a
/// direct-mapped cache that holds them in one line loses one of them to the other then. In the
/// order of their meetings, most first (then by id), each patch takes the line with a free slot
/// where it meets the patches already there least often (the lowest such line). Greedy, not
/// optimal; on the README's headline workload it lowers the host loads of a 250-line cache by
/// a fifth against the Hilbert order's slots. With `lines` at least `patches`, or 0, every
/// patch keeps its own slot.
pub fn place_for_caches(patches: usize, lines: usize, queues: &[Vec<Vec<u16>>]) -> Vec<u32> {
    use std::collections::HashMap;
    if lines == 0 || lines >= patches {
        return (0..patches as u32).collect();
    }
    let sets: Vec<Vec<Vec<u16>>> = queues
        .iter()
        .map(|q| {
            q.iter()
                .map(|ids| {
                    let mut s: Vec<u16> = ids.iter().copied().filter(|&k| (k as usize) < patches).collect();
                    s.sort_unstable();
                    s.dedup();
                    s
                })
                .collect()
        })
        .collect();
    // Meetings, one entry per pair (a < b).
    let mut meet: HashMap<u64, u32> = HashMap::new();
    let mut add = |a: u16, b: u16| {
        if a != b {
            let (a, b) = (a.min(b) as u64, a.max(b) as u64);
            *meet.entry(a << 16 | b).or_default() += 1;
        }
    };
    for q in &sets {
        for (j, s) in q.iter().enumerate() {
            for (i, &a) in s.iter().enumerate() {
                for &b in &s[i + 1..] {
                    add(a, b);
                }
                for &b in q.get(j + 1).map_or(&[][..], |n| &n[..]) {
                    add(a, b);
                }
            }
        }
    }
    let mut with: Vec<Vec<(u16, u32)>> = vec![Vec::new(); patches];
    let mut total = vec![0u64; patches];
    for (&key, &n) in &meet {
        let (a, b) = ((key >> 16) as usize, (key & 0xffff) as usize);
        with[a].push((b as u16, n));
        with[b].push((a as u16, n));
        total[a] += u64::from(n);
        total[b] += u64::from(n);
    }
    let mut order: Vec<usize> = (0..patches).collect();
    order.sort_by_key(|&a| (std::cmp::Reverse(total[a]), a));
    // Line `l` holds the slots below `patches` that are `l` modulo `lines`.
    let room: Vec<u32> = (0..lines).map(|l| ((patches - l).div_ceil(lines)) as u32).collect();
    let mut used = vec![0u32; lines];
    let mut line_of = vec![u32::MAX; patches];
    let mut cost = vec![0u64; lines];
    let mut slot = vec![0u32; patches];
    for a in order {
        for &(b, n) in &with[a] {
            if let Some(l) = line_of.get(b as usize).filter(|&&l| l != u32::MAX) {
                cost[*l as usize] += u64::from(n);
            }
        }
        let l = (0..lines)
            .filter(|&l| used[l] < room[l])
            .min_by_key(|&l| (cost[l], l))
            .expect("a slot for every patch");
        for &(b, _) in &with[a] {
            if let Some(&m) = line_of.get(b as usize).filter(|&&m| m != u32::MAX) {
                cost[m as usize] = 0;
            }
        }
        line_of[a] = l as u32;
        slot[a] = l as u32 + used[l] * lines as u32;
        used[l] += 1;
    }
    slot
}

/// How the machine is set up.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MachineConfig {
    /// Processing elements, 1 to [`MAX_PES`].
    pub pes: usize,
    /// Cycles the shared host memory takes per patch.
    pub tc: u32,
    /// Each PE's patch cache, `None` off.
    pub cache: Option<u32>,
    pub deal: Deal,
    /// Where the host memory puts the patches for the caches.
    pub place: Placement,
    /// Verilator or rust-hdl (resolved: not `Auto`).
    pub engine: Engine,
    /// A VCD of the machine's own RTL (`Machine<N>` on rust-hdl's simulation, whatever
    /// `engine` says) over a window of cycles, written whole or not at all.
    pub vcd: Option<VcdWindow>,
}

/// What a machine run took.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct MachineRun {
    pub pes: usize,
    pub sources: usize,
    /// Parts each source was cut into ([`Deal::parts`]).
    pub parts: usize,
    /// From the first setup to the last readout.
    pub cycles: u64,
    /// Summed over the sources: cycles writing directions, running commands (from the first
    /// offered to the next source's first, or to the end of the PE's queue) and reading hits.
    /// A PE's sources overlap (a setup and a readout beside the commands of another), so these
    /// add up to more than its time.
    pub setup_cycles: u64,
    pub command_cycles: u64,
    pub readout_cycles: u64,
    /// The longest PE's command stream: from its first command to the start of its last
    /// readout (the first setup and the last readout apart; every other setup and readout
    /// overlaps its commands).
    pub stream_cycles: u64,
    /// Summed over the PEs: cycles their intersection units tested a live ray.
    pub intersection_busy_cycles: u64,
    /// Rays traced (every source's bundle).
    pub rays: u64,
    /// Patches the host memory delivered, and the cycles its port was busy.
    pub memory_loads: u64,
    pub memory_busy_cycles: u64,
    /// `memory_busy_cycles / cycles`.
    pub memory_utilisation: f64,
    pub patch_loads: u64,
    pub cache_hits: u64,
    pub tests: u64,
    /// Each source's latency: from its first part's setup to its last part's readout, in the
    /// order given.
    pub source_cycles: Vec<u64>,
    /// Every work item's hits, in the order given, each ray's nearest patch by its number in the
    /// scene (not in the JSON).
    #[serde(skip)]
    pub hits: Vec<Vec<Option<Nearest>>>,
}

impl MachineRun {
    pub fn cycles_per_source(&self) -> f64 {
        self.cycles as f64 / self.sources as f64
    }

    pub fn rays_per_cycle(&self) -> f64 {
        self.rays as f64 / self.cycles as f64
    }
}

/// Most patches the host memory of a machine run holds, the scenes of its work items together:
/// the 16-bit patch ids (a cache of lines not a power of two spreads them further, [`MemoryMap`]).
pub const MAX_HOST_PATCHES: usize = 1 << shelling_hdl::formats::ID_BITS;

/// Runs `schedules` (work items of one scene, as [`schedule_sources`] makes them for
/// `config.deal`: sources in the order to deal them, each in [`Deal::parts`] parts) on the
/// machine of `config`; `progress(items done, items)` after each item's readout. Every item's
/// hits and counters are checked against the bit-true model of its commands. Items of other
/// scenes (a 3D bundle's packed sweep planes, [`crate::d3::on_pe`]) are each a whole source: their
/// scenes follow the first item's in the host memory, at most [`MAX_HOST_PATCHES`] patches in
/// all, and each item's hits name its own scene's patches.
pub fn run(
    schedules: &[Scheduled],
    config: &MachineConfig,
    progress: impl FnMut(usize, usize),
) -> Result<MachineRun, CosimError> {
    let works = schedules.iter().map(|s| commands(&s.stream, &s.fixed)).collect::<Result<Vec<_>, _>>()?;
    run_works(works, config, progress)
}

/// [`run`] of the host's work items as they are handed to the PEs (setup, patches, commands;
/// e.g. [`crate::workstream::pack`]s of several bundles).
pub fn run_works(
    schedules: Vec<PeWork>,
    config: &MachineConfig,
    progress: impl FnMut(usize, usize),
) -> Result<MachineRun, CosimError> {
    if !(1..=MAX_PES).contains(&config.pes) {
        return Err(CosimError::Config(format!("--pes {}: the machine has 1 to {MAX_PES} PEs", config.pes)));
    }
    check_range("--tc", config.tc, 1, MAX_TC).map_err(CosimError::Config)?;
    if let Some(v) = &config.vcd {
        macro_rules! rtl {
            ($($n:literal)*) => {
                match config.pes {
                    $($n => {
                        let mut drv = shelling_testbench::machine::rtl::<$n>().map_err(sim)?;
                        with_vcd(&mut drv, v, |drv| run_on(drv, &schedules, config, progress))
                    })*
                    _ => unreachable!("checked above"),
                }
            };
        }
        const _: () = assert!(MAX_PES == 8, "the VCD's machines are listed for 1 to 8 PEs");
        return rtl!(1 2 3 4 5 6 7 8);
    }
    match config.engine {
        Engine::Verilator => {
            let sims =
                (0..config.pes).map(|_| VerilatedPe::new()).collect::<Result<Vec<_>, _>>().map_err(|e| {
                    CosimError::Sim(format!("{}; the rust-hdl engine needs no Verilator", e.message()))
                })?;
            run_on(&mut Composed::threaded(sims).map_err(sim)?, &schedules, config, progress)
        }
        _ => {
            let sims = (0..config.pes).map(|_| rust_hdl_pe()).collect::<Result<Vec<_>, _>>().map_err(sim)?;
            run_on(&mut Composed::new(sims).map_err(sim)?, &schedules, config, progress)
        }
    }
}

/// A work item's weight in the deal: its ray-patch tests in the bit-true model, the intersection
/// unit's cycles, known before the run. Of the bounds known then (the tests, the loader's
/// patches, the ray port's directions) the tests alone balanced the README's headline best:
/// four PEs took 448,004 cycles (stochastic), 452,310 with the largest of the three, 449,321
/// with even counts; what the host's loads add depends on the caches and the other PEs.
pub fn work_of(model: &pe::ModelCounts) -> u64 {
    model.tests
}

fn sim(e: shelling_testbench::Error) -> CosimError {
    CosimError::Sim(e.message().to_string())
}

fn run_on<M: MachineSim>(
    machine: &mut M,
    schedules: &[PeWork],
    config: &MachineConfig,
    mut progress: impl FnMut(usize, usize),
) -> Result<MachineRun, CosimError> {
    let Some(first) = schedules.first() else {
        return Err(CosimError::Config("no source to run".into()));
    };
    let parts = config.deal.parts(config.pes);
    if !schedules.len().is_multiple_of(parts) {
        return Err(CosimError::Config(format!(
            "{} work items are not whole sources of {parts} parts",
            schedules.len()
        )));
    }
    let mut items: Vec<(PeSetup, Vec<Command>)> = Vec::with_capacity(schedules.len());
    // The host memory: the first item's scene, and after it every other scene an item names
    // (the packed planes of a 3D bundle, `crate::d3::on_pe`), each item's patch numbers offset by where
    // its scene starts (`base`).
    let mut patches = first.1.clone();
    let first_scene = patches.len();
    let (mut base, mut last_scene) = (Vec::with_capacity(schedules.len()), 0);
    for (setup, p, cmds) in schedules {
        let (setup, mut cmds) = (setup.clone(), cmds.clone());
        let at = if p[..] == patches[..first_scene] {
            0
        } else if p[..] == patches[last_scene..] {
            last_scene
        } else {
            last_scene = patches.len();
            patches.extend_from_slice(p);
            last_scene
        };
        if patches.len() > MAX_HOST_PATCHES {
            return Err(CosimError::Config(format!(
                "the work items' scenes hold {} patches together, more than the host memory's {MAX_HOST_PATCHES}",
                patches.len()
            )));
        }
        for c in &mut cmds {
            if let Command::Job { id, .. } = c {
                *id += at as u16;
            }
        }
        base.push(at);
        items.push((setup, cmds));
    }
    // Checked before the work is modelled: a bad size is named at once.
    let plain = memory_map(config.cache, patches.len())?;
    let sources = items.len() / parts;
    // The work that weighs each source in the deal, from the bit-true model of its commands
    // (the tests do not depend on where the patches are).
    let work: Vec<u64> = items
        .chunks(parts)
        .map(|s| s.iter().map(|(setup, cmds)| work_of(&pe::model(setup, &patches, cmds).1)).sum())
        .collect();
    let dealt = deal(&work, config.pes, config.deal);
    let map = match (config.cache, config.place) {
        (Some(lines), Placement::Lines) => {
            let jobs = |i: usize| items[i].1.iter().filter_map(Command::job_id);
            let queues: Vec<Vec<Vec<u16>>> =
                dealt.iter().map(|q| q.iter().map(|&i| jobs(i).collect()).collect()).collect();
            MemoryMap::placed(Some(lines), place_for_caches(patches.len(), lines as usize, &queues))
                .map_err(sim)?
        }
        _ => plain,
    };
    for (_, cmds) in &mut items {
        *cmds = map.commands(cmds);
    }
    let patches = map.memory(&patches);
    // The bit-true model of every item as the PE gets it: what its hits are checked against
    // (two patches hit at one distance: the lower address wins, as in the PE).
    let models: Vec<_> = items.iter().map(|(setup, cmds)| pe::model(setup, &patches, cmds)).collect();
    let mut memory = HostMemory::new(patches.clone(), config.tc).map_err(sim)?;
    let queues: Vec<Vec<Work>> = dealt
        .iter()
        .map(|q| q.iter().map(|&i| Work { setup: &items[i].0, commands: &items[i].1 }).collect())
        .collect();
    let k = run_queues(machine, &mut memory, map.cache(), &queues, |done| progress(done, items.len()))
        .map_err(sim)?;
    let mut m = MachineRun {
        pes: config.pes,
        sources,
        parts,
        cycles: k.cycles,
        memory_loads: memory.loads(),
        memory_busy_cycles: memory.busy_cycles(),
        source_cycles: vec![0; sources],
        hits: vec![Vec::new(); items.len()],
        ..Default::default()
    };
    let mut span = vec![(u64::MAX, 0u64); sources];
    for (p, ((q, traced), totals)) in dealt.iter().zip(&k.pes).zip(&k.totals).enumerate() {
        // Every source's hits; the PE's counts over its queue (its sources overlap in the PE,
        // so its counters cannot be split between them).
        let mut queue_model = pe::ModelCounts::default();
        for (&i, t) in q.iter().zip(traced) {
            let (setup, _) = &items[i];
            let (want, model) = &models[i];
            check_hits(&t.hits, want).map_err(|e| {
                CosimError::Mismatch(format!("source {} part {} on PE {p}: {e}", i / parts, i % parts))
            })?;
            queue_model = queue_model.plus(model);
            m.hits[i] = patch_numbers(&map, t.hits.clone())
                .into_iter()
                .map(|h| h.map(|n| Nearest { id: n.id - base[i] as u16, ..n }))
                .collect();
            let c = &t.counters;
            let s = &mut span[i / parts];
            *s = (s.0.min(t.start), s.1.max(t.end));
            m.rays += setup.dirs.len() as u64;
            m.setup_cycles += c.setup_cycles;
            m.command_cycles += c.cycles;
            m.readout_cycles += c.readout_cycles;
        }
        check_counts(totals, &queue_model)
            .map_err(|e| CosimError::Mismatch(format!("PE {p}'s {} sources: {e}", q.len())))?;
        let last_readout = traced.last().map_or(0, |t| t.counters.readout_cycles);
        m.stream_cycles = m.stream_cycles.max(totals.cycles.saturating_sub(last_readout));
        m.intersection_busy_cycles += totals.intersection_busy_cycles;
        m.patch_loads += totals.patch_loads;
        m.cache_hits += totals.cache_hits;
        m.tests += totals.tests;
    }
    m.source_cycles = span.iter().map(|&(a, b)| b - a).collect();
    m.memory_utilisation = if m.cycles > 0 { m.memory_busy_cycles as f64 / m.cycles as f64 } else { 0.0 };
    Ok(m)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deals_cover_every_item_once() {
        for how in [Deal::Blocks, Deal::Interleaved, Deal::Sectors] {
            for (n, pes) in [(10, 3), (8, 8), (1, 4), (17, 4)] {
                let queues = deal(&vec![1; n], pes, how);
                assert_eq!(queues.len(), pes);
                let mut seen: Vec<usize> = queues.iter().flatten().copied().collect();
                seen.sort();
                assert_eq!(seen, (0..n * how.parts(pes)).collect::<Vec<_>>(), "{how:?} {n} on {pes}");
            }
        }
        assert_eq!(deal(&[1; 6], 2, Deal::Blocks), vec![vec![0, 1, 2], vec![3, 4, 5]]);
        assert_eq!(deal(&[0; 6], 2, Deal::Blocks), vec![vec![0, 1, 2], vec![3, 4, 5]]);
        assert_eq!(deal(&[1; 5], 2, Deal::Interleaved), vec![vec![0, 2, 4], vec![1, 3]]);
        assert_eq!(deal(&[1; 2], 3, Deal::Sectors), vec![vec![0, 3], vec![1, 4], vec![2, 5]]);
    }

    /// Blocks are cut by work: a heavy source is a block alone, the light ones share the rest,
    /// in order; one source on many PEs leaves the others idle.
    #[test]
    fn blocks_share_the_work() {
        assert_eq!(deal(&[1, 1, 1, 9, 1, 1], 2, Deal::Blocks), vec![vec![0, 1, 2], vec![3, 4, 5]]);
        assert_eq!(deal(&[9, 1, 1, 1], 2, Deal::Blocks), vec![vec![0], vec![1, 2, 3]]);
        assert_eq!(
            deal(&[3, 3, 1, 1, 1, 1, 1, 1], 3, Deal::Blocks),
            vec![vec![0], vec![1, 2, 3], vec![4, 5, 6, 7]]
        );
        assert_eq!(deal(&[5], 3, Deal::Blocks), vec![vec![], vec![0], vec![]]);
        let work: Vec<u64> = (0..1000).map(|i| 1 + (i * 7919 % 101)).collect();
        let total: u64 = work.iter().sum();
        for q in deal(&work, 4, Deal::Blocks) {
            let share: u64 = q.iter().map(|&i| work[i]).sum();
            assert!(share.abs_diff(total / 4) <= 101, "a block of {share} of {total}");
        }
    }

    /// Misses of a direct-mapped cache of `lines` lines over each queue's requests, patch `k`
    /// in line `slot[k] mod lines`.
    fn direct_mapped_misses(queues: &[Vec<Vec<u16>>], slot: &[u32], lines: usize) -> usize {
        let mut misses = 0;
        for q in queues {
            let mut held = vec![u16::MAX; lines];
            for &k in q.iter().flatten() {
                let l = slot[k as usize] as usize % lines;
                if held[l] != k {
                    held[l] = k;
                    misses += 1;
                }
            }
        }
        misses
    }

    /// The placement fills every line's slots once, keeps the identity when every patch has a
    /// line of its own, and puts two patches that meet apart where their own slots share a line.
    #[test]
    fn placement_is_a_permutation_that_parts_patches_which_meet() {
        let q = vec![vec![vec![0u16, 2], vec![2, 0, 5], vec![1, 3]], vec![vec![4, 6], vec![6, 4]]];
        for lines in [1, 2, 3, 4, 7] {
            let slot = place_for_caches(7, lines, &q);
            let mut sorted = slot.clone();
            sorted.sort();
            assert_eq!(sorted, (0..7).collect::<Vec<u32>>(), "{lines} lines: {slot:?}");
            if lines > 1 {
                for (a, b) in [(0, 2), (4, 6), (1, 3)] {
                    assert_ne!(slot[a] % lines as u32, slot[b] % lines as u32, "{lines} lines: {slot:?}");
                }
            }
        }
        assert_eq!(place_for_caches(5, 8, &q), vec![0, 1, 2, 3, 4]);
        assert_eq!(place_for_caches(5, 0, &q), vec![0, 1, 2, 3, 4]);
        assert_eq!(place_for_caches(0, 4, &[]), Vec::<u32>::new());
    }

    /// On sources of a generated scene in Hilbert order, dealt in blocks, the placement loses
    /// fewer patches to one another in a direct-mapped cache than the Hilbert order's slots.
    #[test]
    fn placement_lowers_a_direct_mapped_caches_misses() {
        let (scene, _) =
            hilbert_ordered(&crate::scene::generate(400, 32.0, 3, crate::scene::PAPER_WORLD).unwrap());
        let prepared = GriddedScene::new(scene, crate::grid::GridParams::default());
        let order: Vec<usize> = (100..160).collect();
        let work = schedule_sources(
            &prepared,
            &order,
            Method::Stochastic,
            RaySet::Angle,
            256,
            &ShellParams::default(),
            1,
        )
        .unwrap();
        let jobs: Vec<Vec<u16>> = work
            .iter()
            .map(|s| {
                let (_, _, cmds) = commands(&s.stream, &s.fixed).unwrap();
                cmds.iter().filter_map(Command::job_id).collect()
            })
            .collect();
        for (pes, lines) in [(1, 64), (2, 100), (3, 128)] {
            let queues: Vec<Vec<Vec<u16>>> = deal(&vec![1; jobs.len()], pes, Deal::Blocks)
                .iter()
                .map(|q| q.iter().map(|&i| jobs[i].clone()).collect())
                .collect();
            let identity: Vec<u32> = (0..400).collect();
            let (before, after) = (
                direct_mapped_misses(&queues, &identity, lines),
                direct_mapped_misses(&queues, &place_for_caches(400, lines, &queues), lines),
            );
            assert!(after < before, "{pes} PEs, {lines} lines: {after} misses placed, {before} in order");
        }
    }

    /// A source's parts, each scheduled on its own, trace what its whole bundle traces: every
    /// ray's hit, for every technique.
    #[test]
    fn a_sources_parts_trace_its_rays() {
        let scene = crate::scene::generate(300, 32.0, 11, crate::scene::PAPER_WORLD).expect("scene");
        let prepared = GriddedScene::new(scene, crate::grid::GridParams::default());
        let params = ShellParams::default();
        for method in [Method::Conventional, Method::Stochastic, Method::Deterministic] {
            let whole =
                schedule_sources(&prepared, &[5, 17], method, RaySet::Angle, 256, &params, 1).unwrap();
            let parts =
                schedule_sources(&prepared, &[5, 17], method, RaySet::Angle, 256, &params, 3).unwrap();
            assert_eq!(parts.len(), 6);
            for (w, p) in whole.iter().zip(parts.chunks(3)) {
                let joined: Vec<_> = p.iter().flat_map(|s| s.trace.hits.iter().copied()).collect();
                assert_eq!(joined, w.trace.hits, "{method}: the parts' hits, then the whole bundle's");
                assert!(w.trace.hits.iter().flatten().count() > 0, "{method}: no hit at all");
            }
        }
        assert!(schedule_sources(&prepared, &[5], Method::Stochastic, RaySet::Angle, 2, &params, 3).is_err());
    }

    /// The curve visits every cell once, each step to a grid neighbour.
    #[test]
    fn the_hilbert_curve_steps_to_neighbours() {
        for bits in 1..=5u32 {
            let n = 1u32 << bits;
            let mut at = vec![None; (n * n) as usize];
            for x in 0..n {
                for y in 0..n {
                    let d = hilbert_index(bits, x, y) as usize;
                    assert!(at[d].is_none(), "{bits} bits: cell {d} twice");
                    at[d] = Some((x, y));
                }
            }
            let at: Vec<(u32, u32)> = at.into_iter().map(|c| c.expect("every cell")).collect();
            assert_eq!(at[0], (0, 0));
            for w in at.windows(2) {
                assert_eq!(w[0].0.abs_diff(w[1].0) + w[0].1.abs_diff(w[1].1), 1, "{bits} bits: {w:?}");
            }
        }
    }

    #[test]
    fn the_hilbert_order_permutes_the_scene_and_keeps_each_patch_with_its_material() {
        let mut scene = crate::scene::generate(200, 16.0, 3, crate::scene::PAPER_WORLD).expect("scene");
        for (i, m) in scene.materials.iter_mut().enumerate() {
            m.reflectance = Some(i as f64 / 1000.0);
        }
        let (z, old) = hilbert_ordered(&scene);
        let mut sorted = old.clone();
        sorted.sort();
        assert_eq!(sorted, (0..200).collect::<Vec<_>>(), "a permutation");
        assert_ne!(old, sorted, "the generator's order is not the Hilbert order");
        for (new, &k) in old.iter().enumerate() {
            assert_eq!(z.segments[new], scene.segments[k]);
            assert_eq!(z.material(new), scene.material(k));
        }
        assert_eq!(spatial_order(&z.segments, &(0..200).collect::<Vec<_>>()), (0..200).collect::<Vec<_>>());
        let (same, id) = lay_out(scene.clone(), Layout::File);
        assert_eq!((same, id), (scene, (0..200).collect()));
    }

    #[test]
    fn parts_cut_a_bundle_into_contiguous_ranges() {
        for (rays, parts) in [(1024, 8), (1000, 3), (5, 5), (7, 1)] {
            let ranges: Vec<_> = (0..parts).map(|j| part_range(rays, parts, j)).collect();
            assert_eq!(ranges[0].start, 0);
            assert_eq!(ranges[parts - 1].end, rays);
            for w in ranges.windows(2) {
                assert_eq!(w[0].end, w[1].start);
            }
            assert!(ranges.iter().all(|r| r.len() >= rays / parts && r.len() <= rays.div_ceil(parts)));
        }
    }
}
