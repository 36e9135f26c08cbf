//! A machine of `N` processing elements on one host memory, through the memory arbiter
//! (`shelling_hdl::arbiter`): the paper's shared-memory parallel architecture, cycle by cycle.
//!
//! Two simulations of the machine implement [`MachineSim`], cycle for cycle the same:
//!
//! - [`Composed`]: `N` PE simulators (rust-hdl's or the compiled one) and the arbiter's cycle
//!   model ([`Arbiter`], checked against the RTL in every cycle by
//!   `testbench/tests/arbiter.rs`) and each PE's port register (`shelling_hdl::machine::model`)
//!   stepped in lockstep: in each cycle every PE sees its port register (the arbiter's answer
//!   of the cycle before, if it was its own, the last patch answered to it, and its copy of the
//!   cache settings), the arbiter every PE's request of the cycle before (its port's request
//!   register). All those outputs
//!   are registers, so this is the cycle behaviour of the blocks wired together; it runs at the
//!   compiled PE's speed, and [`Composed::threaded`] steps half the PEs on a second thread
//!   ([`Lockstep`]);
//! - [`Driver<Machine<N>>`](crate::Driver): rust-hdl's simulation of the machine's own RTL
//!   (`shelling_hdl::machine`), VCD and all.
//!
//! The host memory is a [`HostMemory`] (one port, one patch per `T_c`) outside either.
//!
//! The host runs each PE through its own queue of sources ([`run_queues`]): a source's
//! directions are written into the PE (its ray ports are its own), its command stream runs on
//! the shared memory, its hits are read out, and the PE's next source follows at once, whatever
//! the other PEs do: one PE's setup and readout overlap the others' commands, and no PE waits
//! for another's source to end.

use crate::lockstep::{self, Lockstep};
use crate::memory::HostMemory;
use crate::pe::{
    counters, counts_since, CacheConfig, Command, CommandHost, PeCounters, PeSetup, PE_RAY_MEMORY,
};
use crate::pe_sim::{PeInputs, PeOutputs, PeSim};
use crate::{Clocked, Driver, Error, Result};
pub use shelling_hdl::arbiter::model::Arbiter;
use shelling_hdl::arbiter::MAX_PES;
use shelling_hdl::formats::Nearest;
use shelling_hdl::intersection::READOUT_LATENCY;
use shelling_hdl::machine::model::{Port, Settings};
use shelling_hdl::machine::Machine;

/// A machine simulated one clock cycle at a time from power-up: `pes()` PEs and their memory
/// arbiter; the host memory is outside, on [`MachineSim::host_request`] and
/// [`MachineSim::tick`].
pub trait MachineSim {
    /// Processing elements.
    fn pes(&self) -> usize;
    /// Sets every PE's host-side inputs for the coming edge (`set(p, inputs)`; the memory
    /// port's are the arbiter's) and settles.
    fn drive(&mut self, set: impl FnMut(usize, &mut PeInputs)) -> Result<()>;
    /// PE `p`'s outputs now (its memory port's, inside the machine, unspecified).
    fn outputs(&self, p: usize) -> PeOutputs;
    /// The machine's request to the host memory in this cycle (a register).
    fn host_request(&self) -> Option<u16>;
    /// The rising edge, with the host memory's answer `answer` on the machine's port in this
    /// cycle.
    fn tick(&mut self, answer: Option<[i32; 4]>) -> Result<()>;
}

/// `N` PE simulators and the arbiter's cycle model, in lockstep (see the module documentation).
///
/// Every output of the PE is a register, so [`MachineSim::drive`] only records each PE's
/// inputs, the host's with its port registers' in place of the memory port and the cache
/// settings (the outputs it shows are those of the last edge, as a settled simulation's would
/// be: `testbench/tests/machine.rs` checks this composition against the machine's own RTL
/// cycle for cycle), and [`MachineSim::tick`] gives every PE its inputs and its edge at once:
/// on two threads when made by [`Composed::threaded`].
pub struct Composed<S: PeSim> {
    sims: Vec<S>,
    arbiter: Arbiter,
    ports: Vec<Port>,
    /// Each PE's inputs as the host drives them, and as the PE sees them (through its port
    /// registers).
    host: Vec<PeInputs>,
    inputs: Vec<PeInputs>,
    lockstep: Option<Lockstep<S>>,
}

impl<S: PeSim> Composed<S> {
    /// The machine of `sims` (1 to [`MAX_PES`] of them, fresh or after earlier runs) with the
    /// arbiter at power-up, stepped on the caller's thread.
    pub fn new(sims: Vec<S>) -> Result<Self> {
        check_pes(sims.len())?;
        let arbiter = Arbiter::new(sims.len());
        let inputs = vec![PeInputs::default(); sims.len()];
        let ports = vec![Port::default(); sims.len()];
        Ok(Self { sims, arbiter, ports, host: inputs.clone(), inputs, lockstep: None })
    }
}

impl<S: PeSim + Send + 'static> Composed<S> {
    /// As [`Composed::new`], the PEs stepped on two threads ([`Lockstep`]) where the system has
    /// two cores and the machine two PEs, on one while the cores are busy elsewhere (its
    /// [`Pacer`](crate::lockstep::Pacer)); the same cycles and results either way.
    pub fn threaded(sims: Vec<S>) -> Result<Self> {
        let mut m = Self::new(sims)?;
        if m.sims.len() >= 2 {
            m.lockstep = Lockstep::start();
        }
        Ok(m)
    }

    /// Whether the PEs are stepped on two threads.
    pub fn is_threaded(&self) -> bool {
        self.lockstep.is_some()
    }
}

fn check_pes(n: usize) -> Result<()> {
    if !(1..=MAX_PES).contains(&n) {
        return Err(Error::new(format!("a machine has 1 to {MAX_PES} PEs, not {n}")));
    }
    Ok(())
}

impl<S: PeSim> MachineSim for Composed<S> {
    fn pes(&self) -> usize {
        self.sims.len()
    }

    fn drive(&mut self, mut set: impl FnMut(usize, &mut PeInputs)) -> Result<()> {
        for (p, ((i, host), port)) in self.inputs.iter_mut().zip(&mut self.host).zip(&self.ports).enumerate()
        {
            set(p, host);
            *i = *host;
            i.mem_valid = port.valid;
            [i.mem_ax, i.mem_ay, i.mem_bx, i.mem_by] = port.patch.map(|w| w as i32);
            (i.cfg_cache_enable, i.cfg_cache_mask, i.cfg_cache_flush) =
                (port.cache.enable, port.cache.mask, port.cache.flush);
        }
        Ok(())
    }

    fn outputs(&self, p: usize) -> PeOutputs {
        self.sims[p].outputs()
    }

    fn host_request(&self) -> Option<u16> {
        self.arbiter.outputs().host
    }

    fn tick(&mut self, answer: Option<[i32; 4]>) -> Result<()> {
        let mut requests = [None; MAX_PES];
        let a = self.arbiter.outputs();
        for (p, ((r, port), (sim, h))) in
            requests.iter_mut().zip(&mut self.ports).zip(self.sims.iter().zip(&self.host)).enumerate()
        {
            *r = port.request;
            let o = sim.outputs();
            let host =
                Settings { enable: h.cfg_cache_enable, mask: h.cfg_cache_mask, flush: h.cfg_cache_flush };
            port.step(p, o.mem_req.then_some(o.mem_addr), o.busy, &a, host);
        }
        self.arbiter
            .step(&requests[..self.sims.len()], answer.map(|m| m.map(|c| c as u32)))
            .map_err(|e| Error::new(format!("arbiter: {e}")))?;
        match &mut self.lockstep {
            Some(l) => l.cycle(&mut self.sims, &self.inputs),
            None => lockstep::step(&mut self.sims, &self.inputs),
        }
    }
}

impl<const N: usize> Clocked for Machine<N> {
    fn clock(
        &mut self,
    ) -> &mut rust_hdl::core::prelude::Signal<rust_hdl::core::prelude::In, rust_hdl::core::prelude::Clock>
    {
        &mut self.clock
    }
}

/// The machine of `N` PEs in RTL under rust-hdl, at power-up: the engine that writes the
/// machine's VCD (the composition of PE simulators has no waveform of the arbiter).
pub fn rtl<const N: usize>() -> Result<Driver<Machine<N>>> {
    Driver::new(Machine::<N>::default())
}

impl<const N: usize> MachineSim for Driver<Machine<N>> {
    fn pes(&self) -> usize {
        N
    }

    fn drive(&mut self, mut set: impl FnMut(usize, &mut PeInputs)) -> Result<()> {
        Driver::drive(self, |m| {
            for p in 0..N {
                let mut i = PeInputs::read_machine(m, p);
                set(p, &mut i);
                i.write_machine(m, p);
            }
        })
    }

    fn outputs(&self, p: usize) -> PeOutputs {
        PeOutputs::read_machine(self.uut(), p)
    }

    fn host_request(&self) -> Option<u16> {
        let m = self.uut();
        m.host_req.val().then_some(m.host_addr.val().index() as u16)
    }

    fn tick(&mut self, answer: Option<[i32; 4]>) -> Result<()> {
        Driver::drive(self, |m| {
            m.host_valid.next = answer.is_some();
            if let Some(w) = answer {
                m.host_ax.next = (w[0] as u64).into();
                m.host_ay.next = (w[1] as u64).into();
                m.host_bx.next = (w[2] as u64).into();
                m.host_by.next = (w[3] as u64).into();
            }
        })?;
        Driver::tick(self)
    }
}

/// A source for a PE: its setup and its command stream.
#[derive(Clone, Copy, Debug)]
pub struct Work<'a> {
    pub setup: &'a PeSetup,
    pub commands: &'a [Command],
}

/// One source as a PE traced it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Traced {
    pub hits: Vec<Option<Nearest>>,
    /// Its host's counts: `setup_cycles` (its directions written), `cycles` (from its first
    /// command offered to the next source's first, or to the end of the PE's queue) and
    /// `readout_cycles`, and the intersection unit's
    /// busy and stall cycles in its command phase. The PE's counters cannot be split between
    /// overlapped sources: they are the PE's, over its queue, in [`MachineCounters::totals`].
    pub counters: PeCounters,
    /// The machine cycles at which its setup began and its readout ended.
    pub start: u64,
    pub end: u64,
}

/// What a run of the machine took.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MachineCounters {
    /// From the first setup to the last readout, the host memory idle.
    pub cycles: u64,
    /// Patches the host memory delivered in the run.
    pub memory_loads: u64,
    /// Each PE's sources, in the order given.
    pub pes: Vec<Vec<Traced>>,
    /// Each PE's counters over its whole queue (loads, cache hits, screener verdicts, tests,
    /// `memory_loads` its share of the host's answers; `cycles` from its first command to its
    /// last readout, and the sums of its sources' busy, stall and drain cycles).
    pub totals: Vec<PeCounters>,
}

/// One PE's host in [`run_queues`]: its ray ports, step by step, and its command stream,
/// source by source.
///
/// The ray memory's halves alternate: source `j` lives in half `j mod 2`. In **step** `k` the
/// host writes source `k`'s directions into half `k mod 2` and reads source `k − 2`'s hits out
/// of it, one ray of each per clock (a direction write and a readout share no memory); the step
/// starts once the PE's `marks` has counted source `k − 2`'s marker, so the half holds no test
/// in flight. Source `j`'s commands start once its directions are written and source `j − 1`'s
/// commands have all been taken: the PE never waits for a source's setup or readout, and the
/// two halves keep the command stream going across sources.
struct PeHost<'a> {
    queue: &'a [Work<'a>],
    /// The step, and the clocks into it (`None`: waiting for its marker).
    step: usize,
    c: Option<usize>,
    /// The next source to stream and the one streaming, with its host.
    next_source: usize,
    streaming: Option<(usize, Box<CommandHost>)>,
    marks_base: u32,
    counters_base: [u32; 8],
    traced: Vec<Traced>,
    totals: PeCounters,
    first_command: Option<u64>,
    /// Clocks the step has waited for its marker.
    waiting: u64,
}

impl<'a> PeHost<'a> {
    fn new(queue: &'a [Work<'a>], out: &PeOutputs) -> Self {
        let traced = vec![Traced::default(); queue.len()];
        Self {
            queue,
            step: 0,
            c: None,
            next_source: 0,
            streaming: None,
            marks_base: out.marks,
            counters_base: counters(out),
            traced,
            totals: PeCounters::default(),
            first_command: None,
            waiting: 0,
        }
    }

    fn rays(&self, j: usize) -> usize {
        self.queue[j].setup.dirs.len()
    }

    /// Source `k − 2`, read out in step `k`.
    fn read_in(&self, k: usize) -> Option<usize> {
        k.checked_sub(2).filter(|&j| j < self.queue.len())
    }

    /// The clocks of step `k`: its writes, and its readouts with their latency.
    fn step_length(&self, k: usize) -> usize {
        let write = if k < self.queue.len() { self.rays(k) } else { 0 };
        let read = self.read_in(k).map_or(0, |j| self.rays(j) + READOUT_LATENCY as usize - 1);
        write.max(read)
    }

    fn done(&self) -> bool {
        self.step >= self.queue.len() + 2
    }

    /// Before this cycle's inputs: starts the step whose marker is counted (skipping empty
    /// ones), and the next source's commands once it may stream.
    fn begin(&mut self, out: &PeOutputs, now: u64) {
        let marks = out.marks.wrapping_sub(self.marks_base) as usize;
        while self.c.is_none() && !self.done() {
            if self.read_in(self.step).is_some_and(|j| marks < j + 1) {
                break;
            }
            if self.step_length(self.step) == 0 {
                self.step += 1;
            } else {
                self.c = Some(0);
                if self.step < self.queue.len() {
                    self.traced[self.step].start = now;
                }
            }
        }
        let written =
            |j: usize| self.step > j || (self.step == j && self.c.is_some_and(|c| c >= self.rays(j)));
        let free = self.streaming.as_ref().is_none_or(|(_, h)| h.all_sent());
        let j = self.next_source;
        if j < self.queue.len() && free && written(j) {
            if let Some((prev, h)) = self.streaming.take() {
                self.finish_commands(prev, &h, out, now);
            }
            let w = self.queue[j];
            self.streaming = Some((j, Box::new(CommandHost::in_half(w.setup, w.commands, *out, now, j % 2))));
            self.traced[j].counters.setup_cycles = self.rays(j) as u64;
            self.first_command.get_or_insert(now);
            self.next_source += 1;
        }
    }

    /// Source `j`'s command phase is over: its host's counts.
    fn finish_commands(&mut self, j: usize, h: &CommandHost, out: &PeOutputs, now: u64) {
        let k = h.counters(out, now, PeCounters::default());
        let t = &mut self.traced[j].counters;
        t.cycles = k.cycles;
        t.intersection_busy_cycles = k.intersection_busy_cycles;
        t.stall_cycles = k.stall_cycles;
        t.drain_cycles = k.drain_cycles;
        t.pipeline_efficiency = k.pipeline_efficiency;
        self.totals.intersection_busy_cycles += k.intersection_busy_cycles;
        self.totals.stall_cycles += k.stall_cycles;
        self.totals.drain_cycles += k.drain_cycles;
    }

    /// This cycle's inputs.
    fn drive(&self, i: &mut PeInputs, cache: CacheConfig) {
        i.dir_we = false;
        i.res_re = false;
        i.cfg_cache_enable = cache.lines.is_some();
        i.cfg_cache_mask = cache.mask();
        if let Some(c) = self.c {
            let k = self.step;
            if let Some(&d) = self.queue.get(k).and_then(|w| w.setup.dirs.get(c)) {
                i.dir_we = true;
                i.dir_addr = ((k % 2) * PE_RAY_MEMORY + c) as u16;
                [i.dir_x, i.dir_y] = d;
            }
            if let Some(j) = self.read_in(k).filter(|&j| c < self.rays(j)) {
                i.res_re = true;
                i.res_addr = ((j % 2) * PE_RAY_MEMORY + c) as u16;
            }
        }
        match &self.streaming {
            Some((_, h)) => h.offer(i),
            None => CommandHost::set_inputs(i, None),
        }
    }

    /// After the edge (cycle `now`): the readouts arriving, the step's end, the command
    /// host's counts.
    fn after_tick(&mut self, out: &PeOutputs, now: u64, limit: u64, done: &mut impl FnMut()) -> Result<()> {
        if let Some((_, h)) = &mut self.streaming {
            h.after_tick(out, now, &mut |_, _| {});
            if !h.all_sent() {
                h.check_progress(now, limit)?;
            }
        }
        let Some(c) = self.c else {
            // Waiting for a marker: once the commands before it are all taken, it comes within
            // the PE's latency (a stream that does not progress fails its host's check).
            let sent = self.streaming.as_ref().is_none_or(|(_, h)| h.all_sent());
            self.waiting = if sent { self.waiting + 1 } else { 0 };
            if self.waiting > limit {
                return Err(Error::new(format!(
                    "step {}: no marker of source {:?} after {} cycles",
                    self.step,
                    self.read_in(self.step),
                    self.waiting
                )));
            }
            return Ok(());
        };
        self.waiting = 0;
        let k = self.step;
        let latency = READOUT_LATENCY as usize;
        if let Some(j) = self.read_in(k) {
            let rays = self.rays(j);
            if c + 1 >= latency && c + 1 - latency < rays {
                let t = &mut self.traced[j];
                t.hits.push(out.res_hit.then_some(Nearest { key: out.res_key, id: out.res_id }));
                if t.hits.len() == rays {
                    t.counters.readout_cycles = (rays + latency - 1) as u64;
                    t.end = now;
                    done();
                }
            }
        }
        if c + 1 < self.step_length(k) {
            self.c = Some(c + 1);
            return Ok(());
        }
        self.step += 1;
        self.c = None;
        if self.done() {
            if let Some((prev, h)) = self.streaming.take() {
                self.finish_commands(prev, &h, out, now);
            }
            let k = counts_since(self.counters_base, out, std::mem::take(&mut self.totals));
            self.totals = PeCounters {
                cycles: now - self.first_command.unwrap_or(now),
                memory_loads: k.patch_loads - k.cache_hits,
                ..k
            };
            self.totals.pipeline_efficiency = if self.totals.cycles > 0 {
                self.totals.intersection_busy_cycles as f64 / self.totals.cycles as f64
            } else {
                0.0
            };
        }
        Ok(())
    }

    fn before_tick(&mut self, out: &PeOutputs) {
        if let Some((_, h)) = &mut self.streaming {
            h.before_tick(out);
        }
    }
}

/// Runs each PE `p` through its queue `queues[p]` of sources, one after another, sharing
/// `memory`, each PE's sources overlapped in the two halves of its ray memory ([`PeHost`]):
/// while source `j`'s commands stream, the host reads source `j − 1`'s hits out as soon as its
/// marker is counted and writes source `j + 1`'s directions, whatever the other PEs do. PEs
/// without a queue idle. `done(sources done)` after each source's readout. Returns every
/// source's hits and counts, and each PE's counters over its queue.
pub fn run_queues<M: MachineSim>(
    m: &mut M,
    memory: &mut HostMemory,
    cache: CacheConfig,
    queues: &[Vec<Work>],
    mut done: impl FnMut(usize),
) -> Result<MachineCounters> {
    let n = m.pes();
    check_pes(n)?;
    if queues.len() > n {
        return Err(Error::new(format!("a queue per PE: {n} PEs, {} queues", queues.len())));
    }
    cache.check()?;
    for w in queues.iter().flatten() {
        w.setup.check(w.commands, memory.len())?;
    }
    let mut hosts: Vec<PeHost> =
        queues.iter().enumerate().map(|(p, q)| PeHost::new(q, &m.outputs(p))).collect();
    let limit = 64 * (memory.tc() as u64 * n as u64 + 64);
    let loads_before = memory.loads();
    let mut answer: Option<[i32; 4]> = None;
    let mut now = 0u64;
    let mut finished = 0;
    loop {
        for (p, h) in hosts.iter_mut().enumerate() {
            h.begin(&m.outputs(p), now);
        }
        m.drive(|p, i| match hosts.get(p) {
            Some(h) => h.drive(i, cache),
            None => {
                i.dir_we = false;
                i.res_re = false;
                CommandHost::set_inputs(i, None);
            }
        })?;
        for (p, h) in hosts.iter_mut().enumerate() {
            h.before_tick(&m.outputs(p));
        }
        let request = m.host_request();
        m.tick(answer)?;
        answer = memory.cycle(request)?;
        now += 1;
        for (p, h) in hosts.iter_mut().enumerate() {
            if h.done() {
                continue;
            }
            h.after_tick(&m.outputs(p), now, limit, &mut || {
                finished += 1;
                done(finished);
            })
            .map_err(|e| Error::new(format!("PE {p}: {}", e.message())))?;
        }
        // Every PE done has no request outstanding: the host memory's being idle ends the run.
        if hosts.iter().all(PeHost::done) && answer.is_none() && memory.pending() == 0 && request.is_none() {
            break;
        }
    }
    let totals: Vec<PeCounters> = hosts.iter().map(|h| h.totals).collect();
    let mut k = MachineCounters {
        pes: hosts.into_iter().map(|h| h.traced).collect(),
        totals,
        cycles: now,
        ..Default::default()
    };
    k.memory_loads = memory.loads() - loads_before;
    Ok(k)
}
