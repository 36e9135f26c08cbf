//! A machine of `N` processing elements on one host memory, through the memory arbiter
//! (`shelling_hdl::arbiter`): the paper's shared-memory parallel architecture, cycle by cycle.
//!
//! Two simulations of the machine implement [`MachineSim`], cycle for cycle the same:
//!
//! - [`Composed`]: `N` PE simulators (rust-hdl's or the compiled one) and the arbiter's cycle
//!   model ([`Arbiter`], checked against the RTL in every cycle by
//!   `testbench/tests/arbiter.rs`) stepped in lockstep: in each cycle every PE sees the
//!   arbiter's registered answer (`mem_valid` if it is its own, the patch on the shared bus), the
//!   arbiter sees every PE's registered request. All those outputs are registers, so this is
//!   the cycle behaviour of the blocks wired together; it runs at the compiled PE's speed;
//! - [`Driver<Machine<N>>`](crate::Driver): rust-hdl's simulation of the machine's own RTL
//!   (`shelling_hdl::machine`), VCD and all.
//!
//! The host memory is a [`HostMemory`] (one port, one patch per `T_c`) outside either.
//!
//! The host runs the machine in rounds ([`run_round`]): each PE is given one source (its setup,
//! its command stream); the directions are written into every PE at once (each PE's ray ports
//! are its own), the command phases run together, sharing the memory, until every PE is idle,
//! and the hits are read out of every PE at once. A PE that ends its commands early idles until
//! the round ends: the round is the machine's unit of work, as the paper's host hands out a
//! source per processor.

use crate::memory::HostMemory;
use crate::pe::{CacheConfig, Command, CommandHost, PeCounters, PeSetup};
use crate::pe_sim::{PeInputs, PeOutputs, PeSim};
use crate::{Clocked, Driver, Error, Result};
pub use shelling_hdl::arbiter::model::Arbiter;
use shelling_hdl::arbiter::MAX_PES;
use shelling_hdl::formats::Nearest;
use shelling_hdl::intersection::READOUT_LATENCY;
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
pub struct Composed<S: PeSim> {
    pub sims: Vec<S>,
    pub arbiter: Arbiter,
}

impl<S: PeSim> Composed<S> {
    /// The machine of `sims` (1 to [`MAX_PES`] of them) at power-up.
    pub fn new(sims: Vec<S>) -> Result<Self> {
        check_pes(sims.len())?;
        let arbiter = Arbiter::new(sims.len());
        Ok(Self { sims, arbiter })
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
        let a = self.arbiter.outputs();
        for (p, sim) in self.sims.iter_mut().enumerate() {
            sim.drive(|i| {
                set(p, i);
                i.mem_valid = a.answer == Some(p);
                [i.mem_ax, i.mem_ay, i.mem_bx, i.mem_by] = a.patch.map(|w| w as i32);
            })?;
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
        for (r, sim) in requests.iter_mut().zip(&self.sims) {
            let o = sim.outputs();
            *r = o.mem_req.then_some(o.mem_addr);
        }
        self.arbiter
            .step(&requests[..self.sims.len()], answer.map(|m| m.map(|c| c as u32)))
            .map_err(|e| Error::new(format!("arbiter: {e}")))?;
        for sim in &mut self.sims {
            sim.tick()?;
        }
        Ok(())
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

/// One PE's work in a round: a source.
#[derive(Clone, Copy, Debug)]
pub struct Work<'a> {
    pub setup: &'a PeSetup,
    pub commands: &'a [Command],
}

/// What a round took.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RoundCounters {
    /// Cycles of the round: setup, commands and readout, each the longest PE's.
    pub cycles: u64,
    pub setup_cycles: u64,
    /// From the first command to every PE idle with every request answered.
    pub command_cycles: u64,
    pub readout_cycles: u64,
    /// Patches the host memory delivered in the round.
    pub memory_loads: u64,
    /// Each PE's counters (its `cycles` from the round's first command to its own last
    /// command done; `memory_loads` its share of the host's answers).
    pub pes: Vec<PeCounters>,
}

/// Runs one round on the machine `m` (`work.len()` of its PEs given a source, the rest idle),
/// sharing `memory`. Returns each worked PE's hits and the round's counters.
pub fn run_round<M: MachineSim>(
    m: &mut M,
    memory: &mut HostMemory,
    cache: CacheConfig,
    work: &[Work],
) -> Result<(Vec<Vec<Option<Nearest>>>, RoundCounters)> {
    let n = m.pes();
    check_pes(n)?;
    if work.len() > n {
        return Err(Error::new(format!("one source per PE in a round: {n} PEs, {} sources", work.len())));
    }
    cache.check()?;
    for w in work {
        w.setup.check(w.commands, memory.len())?;
    }
    let mut k = RoundCounters { pes: vec![PeCounters::default(); work.len()], ..Default::default() };
    let rays: Vec<usize> = work.iter().map(|w| w.setup.dirs.len()).collect();
    let longest = rays.iter().copied().max().unwrap_or(0);

    // Setup, every PE at once: its source and cache setting, then a direction a clock (as
    // `pe::load_source`), then a clock without.
    for c in 0..=longest {
        m.drive(|p, i| {
            let Some(w) = work.get(p) else { return };
            [i.origin_x, i.origin_y] = w.setup.origin;
            [i.normal_x, i.normal_y] = w.setup.normal;
            i.cfg_cache_enable = cache.lines.is_some();
            i.cfg_cache_mask = (cache.lines.unwrap_or(1) - 1) as u16;
            i.dir_we = c < rays[p];
            if c < rays[p] {
                i.dir_addr = c as u16;
                [i.dir_x, i.dir_y] = w.setup.dirs[c];
            }
        })?;
        m.tick(None)?;
    }
    k.setup_cycles = longest as u64 + 1;
    for (p, &r) in rays.iter().enumerate() {
        k.pes[p].setup_cycles = r as u64 + 1;
    }

    // Commands: every PE's stream, the arbiter and the memory, until every PE is idle and the
    // memory has answered everything.
    let mut hosts: Vec<CommandHost> = work
        .iter()
        .enumerate()
        .map(|(p, w)| CommandHost::new(w.setup, w.commands, m.outputs(p), 0))
        .collect();
    let mut done: Vec<Option<u64>> = vec![None; work.len()];
    let mut answer: Option<[i32; 4]> = None;
    let mut now = 0u64;
    let limit = 64 * (memory.tc() as u64 * n as u64 + 64);
    let loads_before = memory.loads();
    loop {
        m.drive(|p, i| CommandHost::set_inputs(i, hosts.get(p).and_then(|h| h.command())))?;
        for (p, h) in hosts.iter_mut().enumerate() {
            h.before_tick(&m.outputs(p));
        }
        let request = m.host_request();
        m.tick(answer)?;
        answer = memory.cycle(request)?;
        now += 1;
        let mut all = true;
        for (p, h) in hosts.iter_mut().enumerate() {
            let out = m.outputs(p);
            h.after_tick(&out, now, &mut |_, _| {});
            if done[p].is_none() && h.finished(&out) {
                done[p] = Some(now);
            }
            all &= done[p].is_some();
            // A PE done waits for the others without progress of its own.
            if done[p].is_none() {
                h.check_progress(now, limit).map_err(|e| Error::new(format!("PE {p}: {}", e.message())))?;
            }
        }
        // Idle PEs have no request outstanding: the host memory's being idle ends the round.
        if all && answer.is_none() && memory.pending() == 0 && request.is_none() {
            break;
        }
    }
    k.command_cycles = now;
    k.memory_loads = memory.loads() - loads_before;
    for (p, h) in hosts.iter().enumerate() {
        let end = done[p].unwrap_or(now);
        k.pes[p] = h.counters(&m.outputs(p), end, k.pes[p].clone());
        k.pes[p].memory_loads = k.pes[p].patch_loads - k.pes[p].cache_hits;
    }

    // Readout, every PE at once (as `pe::read_out`): a request a clock, each hit
    // READOUT_LATENCY clocks later.
    let latency = READOUT_LATENCY as usize;
    let mut hits: Vec<Vec<Option<Nearest>>> = rays.iter().map(|&r| Vec::with_capacity(r)).collect();
    for c in 0..longest + latency - 1 {
        for (p, &r) in rays.iter().enumerate() {
            if c < r && m.outputs(p).busy {
                return Err(Error::new(format!("PE {p}: readout while the unit is busy")));
            }
        }
        m.drive(|p, i| {
            let r = rays.get(p).copied().unwrap_or(0);
            i.res_re = c < r;
            if c < r {
                i.res_addr = c as u16;
            }
        })?;
        m.tick(None)?;
        if c + 1 >= latency {
            for (p, h) in hits.iter_mut().enumerate() {
                if c + 1 - latency < rays[p] {
                    let o = m.outputs(p);
                    h.push(o.res_hit.then_some(Nearest { key: o.res_key, id: o.res_id }));
                }
            }
        }
    }
    k.readout_cycles = (longest + latency - 1) as u64;
    for (p, &r) in rays.iter().enumerate() {
        k.pes[p].readout_cycles = (r + latency - 1) as u64;
    }
    k.cycles = k.setup_cycles + k.command_cycles + k.readout_cycles;
    Ok((hits, k))
}
