//! A machine of `N` processing elements on one host memory, through the memory arbiter
//! (`shelling_hdl::arbiter`): the paper's shared-memory parallel architecture, cycle by cycle.
//!
//! The PEs are any [`PeSim`]s (rust-hdl's or the compiled one), the arbiter its cycle model
//! ([`Arbiter`], checked against the RTL in every cycle by `testbench/tests/arbiter.rs`), the
//! host memory a [`HostMemory`] (one port, one patch per `T_c`). They step in lockstep: in each
//! cycle every PE sees the arbiter's registered answer (`mem_valid` if it is its own, the patch
//! on the shared bus), the arbiter sees every PE's registered request and the host's answer,
//! the host memory sees the arbiter's request. All those outputs are registers, so this is the
//! cycle behaviour of the blocks wired together in one design.
//!
//! The host runs the machine in rounds ([`run_round`]): each PE is given one source (its setup,
//! its command stream); the sources' directions are written (the PEs' ray ports are their own,
//! so at once: the round's setup takes the longest), the command phases run together, sharing
//! the memory, until every PE is idle, and the hits are read out (again at once). A PE that
//! ends its commands early idles until the round ends: the round is the machine's unit of work,
//! as the paper's host hands out a source per processor.

use crate::memory::HostMemory;
use crate::pe::{load_source, read_out, CacheConfig, Command, CommandHost, PeCounters, PeSetup};
use crate::pe_sim::PeSim;
use crate::{Error, Result};
use shelling_hdl::arbiter::model::Arbiter;
use shelling_hdl::arbiter::MAX_PES;
use shelling_hdl::formats::Nearest;

// A PE never has more requests outstanding than its loader holds, so its queue in the arbiter
// never overflows.
const _: () = assert!(shelling_hdl::arbiter::QUEUE_DEPTH >= shelling_hdl::loader::DEPTH);

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

/// Runs one round on `sims.len()` PEs (1 to [`MAX_PES`], `work.len()` of them given a
/// source, the rest idle), sharing `memory` through `arbiter`. Returns each worked PE's hits
/// and the round's counters.
pub fn run_round<S: PeSim>(
    sims: &mut [S],
    arbiter: &mut Arbiter,
    memory: &mut HostMemory,
    cache: CacheConfig,
    work: &[Work],
) -> Result<(Vec<Vec<Option<Nearest>>>, RoundCounters)> {
    let n = sims.len();
    if !(1..=MAX_PES).contains(&n) || work.len() > n {
        return Err(Error::new(format!(
            "a machine has 1 to {MAX_PES} PEs and one source per PE in a round: {n} PEs, {} sources",
            work.len()
        )));
    }
    cache.check()?;
    for w in work {
        w.setup.check(w.commands, memory.len())?;
    }
    let mut k = RoundCounters { pes: vec![PeCounters::default(); work.len()], ..Default::default() };

    // Setup, every PE at once.
    for (p, w) in work.iter().enumerate() {
        k.pes[p].setup_cycles = load_source(&mut sims[p], w.setup, cache)?;
        k.setup_cycles = k.setup_cycles.max(k.pes[p].setup_cycles);
    }

    // Commands: the PEs, the arbiter and the memory in lockstep. Every PE's own clock count
    // differs by its setup; the machine's is `now`.
    let mut hosts: Vec<CommandHost> = work
        .iter()
        .enumerate()
        .map(|(p, w)| CommandHost::new(w.setup, w.commands, sims[p].outputs(), 0))
        .collect();
    let mut done: Vec<Option<u64>> = vec![None; work.len()];
    let mut answer: Option<[i32; 4]> = None;
    let mut answered = vec![0u64; n];
    let mut now = 0u64;
    let limit = 64 * (memory.tc() as u64 * n as u64 + 64);
    let loads_before = memory.loads();
    let mut requests = vec![None; n];
    loop {
        let a = arbiter.outputs();
        for (p, sim) in sims.iter_mut().enumerate() {
            let cmd = hosts.get(p).and_then(|h| h.command());
            sim.drive(|i| {
                i.mem_valid = a.answer == Some(p);
                [i.mem_ax, i.mem_ay, i.mem_bx, i.mem_by] = a.patch.map(|w| w as i32);
                CommandHost::set_inputs(i, cmd);
            })?;
            let out = sim.outputs();
            if let Some(h) = hosts.get_mut(p) {
                h.before_tick(&out);
            }
            requests[p] = out.mem_req.then_some(out.mem_addr);
        }
        if let Some(p) = a.answer {
            answered[p] += 1;
        }
        arbiter
            .step(&requests, answer.map(|m| m.map(|c| c as u32)))
            .map_err(|e| Error::new(format!("arbiter: {e}")))?;
        answer = memory.cycle(a.host)?;
        for sim in sims.iter_mut() {
            sim.tick()?;
        }
        now += 1;
        let mut all = true;
        for (p, h) in hosts.iter_mut().enumerate() {
            let out = sims[p].outputs();
            h.after_tick(&out, now, &mut |_, _| {});
            if done[p].is_none() && h.finished(&out) && arbiter.queued(p) == 0 {
                done[p] = Some(now);
            }
            all &= done[p].is_some();
            // A PE done waits for the others without progress of its own.
            if done[p].is_none() {
                h.check_progress(now, limit).map_err(|e| Error::new(format!("PE {p}: {}", e.message())))?;
            }
        }
        if all
            && answer.is_none()
            && memory.pending() == 0
            && arbiter.at_host() == 0
            && arbiter.outputs().answer.is_none()
        {
            break;
        }
    }
    k.command_cycles = now;
    k.memory_loads = memory.loads() - loads_before;
    for (p, h) in hosts.iter().enumerate() {
        let end = done[p].unwrap_or(now);
        k.pes[p] = h.counters(&sims[p].outputs(), end, k.pes[p].clone());
        k.pes[p].memory_loads = answered[p];
    }

    // Readout, every PE at once.
    let mut hits = Vec::with_capacity(work.len());
    for (p, w) in work.iter().enumerate() {
        let (h, cycles) = read_out(&mut sims[p], w.setup.dirs.len())?;
        k.pes[p].readout_cycles = cycles;
        k.readout_cycles = k.readout_cycles.max(cycles);
        hits.push(h);
    }
    k.cycles = k.setup_cycles + k.command_cycles + k.readout_cycles;
    Ok((hits, k))
}
