//! A machine of `N` processing elements on one host memory, through the memory arbiter
//! (`shelling_hdl::arbiter`): the paper's shared-memory parallel architecture, cycle by cycle.
//!
//! Two simulations of the machine implement [`MachineSim`], cycle for cycle the same:
//!
//! - [`Composed`]: `N` PE simulators (rust-hdl's or the compiled one) and the arbiter's cycle
//!   model ([`Arbiter`], checked against the RTL in every cycle by
//!   `testbench/tests/arbiter.rs`) and each PE's port register (`shelling_hdl::machine::model`)
//!   stepped in lockstep: in each cycle every PE sees its port register (the arbiter's answer
//!   of the cycle before, if it was its own, and the last patch answered to it), the arbiter
//!   every PE's request of the cycle before (its port's request register). All those outputs
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

use crate::lockstep::Lockstep;
use crate::memory::HostMemory;
use crate::pe::{CacheConfig, Command, CommandHost, PeCounters, PeSetup};
use crate::pe_sim::{PeInputs, PeOutputs, PeSim};
use crate::{Clocked, Driver, Error, Result};
pub use shelling_hdl::arbiter::model::Arbiter;
use shelling_hdl::arbiter::MAX_PES;
use shelling_hdl::formats::Nearest;
use shelling_hdl::intersection::READOUT_LATENCY;
use shelling_hdl::machine::model::Port;
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
/// inputs (the outputs it shows are those of the last edge, as a settled simulation's would
/// be: `testbench/tests/machine.rs` checks this composition against the machine's own RTL
/// cycle for cycle), and [`MachineSim::tick`] gives every PE its inputs and its edge at once:
/// on two threads when made by [`Composed::threaded`].
pub struct Composed<S: PeSim> {
    sims: Vec<S>,
    arbiter: Arbiter,
    ports: Vec<Port>,
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
        Ok(Self { sims, arbiter, ports, inputs, lockstep: None })
    }
}

impl<S: PeSim + Send + 'static> Composed<S> {
    /// As [`Composed::new`], the PEs stepped on two threads ([`Lockstep`]) where the system has
    /// two cores and the machine two PEs; the same cycles and results either way.
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
        for (p, (i, port)) in self.inputs.iter_mut().zip(&self.ports).enumerate() {
            set(p, i);
            i.mem_valid = port.valid;
            [i.mem_ax, i.mem_ay, i.mem_bx, i.mem_by] = port.patch.map(|w| w as i32);
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
        for (p, ((r, port), sim)) in requests.iter_mut().zip(&mut self.ports).zip(&self.sims).enumerate() {
            *r = port.request;
            let o = sim.outputs();
            port.step(p, o.mem_req.then_some(o.mem_addr), &a);
        }
        self.arbiter
            .step(&requests[..self.sims.len()], answer.map(|m| m.map(|c| c as u32)))
            .map_err(|e| Error::new(format!("arbiter: {e}")))?;
        match &mut self.lockstep {
            Some(l) => l.cycle(&mut self.sims, &self.inputs),
            None => self.sims.iter_mut().zip(&self.inputs).try_for_each(|(sim, &i)| sim.cycle(|x| *x = i)),
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
    /// Its counters (`cycles` its command phase's; `memory_loads` its share of the host's
    /// answers; `setup_cycles` and `readout_cycles` its own).
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
}

/// Where one PE is in its queue.
enum Phase {
    /// Writing the directions: the `c`-th clock of `rays + 1`.
    Setup(usize),
    Commands(Box<CommandHost>),
    /// Reading the hits: the `c`-th clock of `rays + READOUT_LATENCY - 1`; and, when a source
    /// follows, writing its directions at once (the `s`-th clock of its setup), the ray memory's
    /// direction and hit words being separate memories.
    Readout {
        c: usize,
        s: usize,
    },
    Done,
}

/// Runs each PE `p` through its queue `queues[p]` of sources, one after another, sharing
/// `memory`: a PE writes its next source's directions while it reads the last one's hits out,
/// and starts its commands when both are done, whatever the others do; so one PE's setup and
/// readout (on its own ray ports) overlap each other and the others' commands on the shared
/// memory. PEs without a queue idle. `done(sources done)` after each source's
/// readout. Returns every source's hits and counters.
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
    let mut k = MachineCounters { pes: vec![Vec::new(); queues.len()], ..Default::default() };
    let mut phase: Vec<Phase> =
        queues.iter().map(|q| if q.is_empty() { Phase::Done } else { Phase::Setup(0) }).collect();
    let mut current: Vec<Traced> = vec![Traced::default(); queues.len()];
    let latency = READOUT_LATENCY as usize;
    let limit = 64 * (memory.tc() as u64 * n as u64 + 64);
    let loads_before = memory.loads();
    let mut answer: Option<[i32; 4]> = None;
    let mut now = 0u64;
    let mut finished = 0;
    loop {
        // This cycle's inputs, PE by PE from its phase.
        for (p, ph) in phase.iter().enumerate() {
            if let Phase::Readout { c, .. } = ph {
                if *c < queues[p][k.pes[p].len()].setup.dirs.len() && m.outputs(p).busy {
                    return Err(Error::new(format!("PE {p}: readout while the unit is busy")));
                }
            }
        }
        m.drive(|p, i| {
            i.dir_we = false;
            i.res_re = false;
            let at = k.pes.get(p).map_or(0, Vec::len);
            let mut set_up = |setup: &PeSetup, c: usize| {
                [i.origin_x, i.origin_y] = setup.origin;
                [i.normal_x, i.normal_y] = setup.normal;
                i.cfg_cache_enable = cache.lines.is_some();
                i.cfg_cache_mask = (cache.lines.unwrap_or(1) - 1) as u16;
                if let Some(&d) = setup.dirs.get(c) {
                    i.dir_we = true;
                    i.dir_addr = c as u16;
                    [i.dir_x, i.dir_y] = d;
                }
            };
            let cmd = match phase.get(p) {
                Some(Phase::Setup(c)) => {
                    set_up(queues[p][at].setup, *c);
                    None
                }
                Some(Phase::Commands(h)) => h.command(),
                Some(&Phase::Readout { c, s }) => {
                    if let Some(next) = queues[p].get(at + 1) {
                        set_up(next.setup, s);
                    }
                    i.res_re = c < queues[p][at].setup.dirs.len();
                    i.res_addr = c as u16;
                    None
                }
                _ => None,
            };
            CommandHost::set_inputs(i, cmd);
        })?;
        for (p, ph) in phase.iter_mut().enumerate() {
            if let Phase::Commands(h) = ph {
                h.before_tick(&m.outputs(p));
            }
        }
        let request = m.host_request();
        m.tick(answer)?;
        answer = memory.cycle(request)?;
        now += 1;
        let mut all = true;
        for (p, ph) in phase.iter_mut().enumerate() {
            let Some(work) = queues[p].get(k.pes[p].len()) else { continue };
            let out = m.outputs(p);
            let rays = work.setup.dirs.len();
            let t = &mut current[p];
            match ph {
                Phase::Setup(c) => {
                    if *c == 0 {
                        t.start = now - 1;
                    }
                    *c += 1;
                    if *c > rays {
                        t.counters.setup_cycles = *c as u64;
                        *ph =
                            Phase::Commands(Box::new(CommandHost::new(work.setup, work.commands, out, now)));
                    }
                }
                Phase::Commands(h) => {
                    h.after_tick(&out, now, &mut |_, _| {});
                    if h.finished(&out) {
                        t.counters = h.counters(&out, now, t.counters);
                        t.counters.memory_loads = t.counters.patch_loads - t.counters.cache_hits;
                        *ph = Phase::Readout { c: 0, s: 0 };
                    } else {
                        h.check_progress(now, limit)
                            .map_err(|e| Error::new(format!("PE {p}: {}", e.message())))?;
                    }
                }
                Phase::Readout { c, s } => {
                    let next = queues[p].get(k.pes[p].len() + 1);
                    if next.is_some_and(|nx| *s <= nx.setup.dirs.len()) {
                        *s += 1;
                    }
                    if *c + 1 >= latency && *c + 1 - latency < rays {
                        t.hits.push(out.res_hit.then_some(Nearest { key: out.res_key, id: out.res_id }));
                    }
                    *c += 1;
                    if *c == rays + latency - 1 {
                        t.counters.readout_cycles = *c as u64;
                        t.end = now;
                        k.pes[p].push(std::mem::take(t));
                        finished += 1;
                        done(finished);
                        *ph = match next {
                            None => Phase::Done,
                            Some(nx) => {
                                // Its setup began with this readout, `c` clocks ago.
                                t.start = now - *c as u64;
                                if *s > nx.setup.dirs.len() {
                                    t.counters.setup_cycles = *s as u64;
                                    Phase::Commands(Box::new(CommandHost::new(
                                        nx.setup,
                                        nx.commands,
                                        out,
                                        now,
                                    )))
                                } else {
                                    Phase::Setup(*s)
                                }
                            }
                        };
                    }
                }
                Phase::Done => {}
            }
            all &= matches!(ph, Phase::Done);
        }
        // Every PE done has no request outstanding: the host memory's being idle ends the run.
        if all && answer.is_none() && memory.pending() == 0 && request.is_none() {
            break;
        }
    }
    k.cycles = now;
    k.memory_loads = memory.loads() - loads_before;
    Ok(k)
}
