//! The parallel machine in co-simulation: sources of one scene dealt to `N` processing
//! elements that share one host memory through the memory arbiter
//! ([`shelling_testbench::machine`]), every PE's hits and counts checked against the bit-true
//! model of its source, as [`crate::cosim`] checks one PE's.
//!
//! The host deals whole sources (the radiosity method shoots from every patch), one per PE a
//! round ([`shelling_testbench::machine::run_round`]). The order matters to the PEs' caches: a
//! PE that traces neighbouring sources one after the other finds the patches the last one
//! loaded. [`spatial_order`] sorts the sources along a Z-order curve of their midpoints, and
//! [`Deal`] hands that order out either in contiguous blocks (PE `p` traces the `p`-th block,
//! round after round) or interleaved (round `r` gives PE `p` source `r·N + p`).

use crate::cosim::{check_against_model, CosimError, Engine};
use crate::geom::Segment;
use crate::limits::{check_range, MAX_TC};
use crate::run::Scheduled;
use crate::workstream::commands;
use serde::Serialize;
use shelling_hdl::arbiter::MAX_PES;
use shelling_testbench::machine::{run_round, Composed, MachineSim, Work};
use shelling_testbench::memory::HostMemory;
use shelling_testbench::pe::{self, rust_hdl_pe, CacheConfig, Command, PeSetup};
use shelling_testbench::verilated::VerilatedPe;

/// How the sources, in their order, are dealt to the PEs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum Deal {
    /// PE `p` takes the `p`-th of `N` contiguous blocks of the order, one source a round.
    #[default]
    Blocks,
    /// Round `r` gives PE `p` the source `r·N + p` of the order.
    Interleaved,
}

/// The rounds of a deal of `sources` sources to `pes` PEs: `rounds[r][p]` is the position in
/// the order of the source PE `p` traces in round `r`, if any.
pub fn deal(sources: usize, pes: usize, how: Deal) -> Vec<Vec<Option<usize>>> {
    let rounds = sources.div_ceil(pes);
    (0..rounds)
        .map(|r| {
            (0..pes)
                .map(|p| {
                    let i = match how {
                        Deal::Blocks => p * rounds + r,
                        Deal::Interleaved => r * pes + p,
                    };
                    (i < sources).then_some(i)
                })
                .collect()
        })
        .collect()
}

/// The patches `ids` of `segments` in Z-order of their midpoints (on a 1024 × 1024 grid over
/// their bounding box), so that neighbours in the order are mostly neighbours in the scene.
pub fn spatial_order(segments: &[Segment], ids: &[usize]) -> Vec<usize> {
    let mid = |k: usize| (segments[k].a + segments[k].b) * 0.5;
    let (mut lo, mut hi) = (mid(ids[0]), mid(ids[0]));
    for &k in ids {
        lo = lo.min(mid(k));
        hi = hi.max(mid(k));
    }
    let span = (hi - lo).max(glam::DVec2::splat(1e-9));
    let morton = |k: usize| {
        let q = ((mid(k) - lo) / span * 1023.0).round();
        let (x, y) = (q.x as u32, q.y as u32);
        (0..10).fold(0u32, |m, b| m | ((x >> b) & 1) << (2 * b) | ((y >> b) & 1) << (2 * b + 1))
    };
    let mut out = ids.to_vec();
    out.sort_by_key(|&k| (morton(k), k));
    out
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
    /// Verilator or rust-hdl (resolved: not `Auto`).
    pub engine: Engine,
}

/// What a machine run took.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct MachineRun {
    pub pes: usize,
    pub sources: usize,
    pub rounds: usize,
    /// Every round's setup, commands and readout, each the round's longest PE's.
    pub cycles: u64,
    pub setup_cycles: u64,
    pub command_cycles: u64,
    pub readout_cycles: u64,
    /// Rays traced (every source's bundle).
    pub rays: u64,
    /// Patches the host memory delivered, and the cycles its port was busy.
    pub memory_loads: u64,
    pub memory_busy_cycles: u64,
    /// `memory_busy_cycles / command_cycles`.
    pub memory_utilisation: f64,
    pub patch_loads: u64,
    pub cache_hits: u64,
    pub tests: u64,
    /// Cycles of each source (its PE's command phase), in the order given.
    pub source_cycles: Vec<u64>,
}

/// Runs `schedules` (sources of one scene, in the order to deal them) on the machine of
/// `config`; `progress(rounds done, rounds)` after each round. Every PE's hits and counters
/// are checked against the bit-true model of its source.
pub fn run(
    schedules: &[Scheduled],
    config: &MachineConfig,
    progress: impl FnMut(usize, usize),
) -> Result<MachineRun, CosimError> {
    if !(1..=MAX_PES).contains(&config.pes) {
        return Err(CosimError::Config(format!("--pes {}: the machine has 1 to {MAX_PES} PEs", config.pes)));
    }
    check_range("--tc", config.tc, 1, MAX_TC).map_err(CosimError::Config)?;
    match config.engine {
        Engine::Verilator => {
            let sims =
                (0..config.pes).map(|_| VerilatedPe::new()).collect::<Result<Vec<_>, _>>().map_err(|e| {
                    CosimError::Sim(format!("{}; the rust-hdl engine needs no Verilator", e.message()))
                })?;
            run_on(&mut Composed::new(sims).map_err(sim)?, schedules, config, progress)
        }
        _ => {
            let sims = (0..config.pes).map(|_| rust_hdl_pe()).collect::<Result<Vec<_>, _>>().map_err(sim)?;
            run_on(&mut Composed::new(sims).map_err(sim)?, schedules, config, progress)
        }
    }
}

fn sim(e: shelling_testbench::Error) -> CosimError {
    CosimError::Sim(e.message().to_string())
}

fn run_on<M: MachineSim>(
    machine: &mut M,
    schedules: &[Scheduled],
    config: &MachineConfig,
    mut progress: impl FnMut(usize, usize),
) -> Result<MachineRun, CosimError> {
    let Some(first) = schedules.first() else {
        return Err(CosimError::Config("no source to run".into()));
    };
    let cache = CacheConfig { lines: config.cache };
    cache.check().map_err(|e| CosimError::Config(e.message().to_string()))?;
    let mut sources: Vec<(PeSetup, Vec<Command>)> = Vec::with_capacity(schedules.len());
    let (_, patches, _) = commands(&first.stream, &first.fixed)?;
    for s in schedules {
        let (setup, p, cmds) = commands(&s.stream, &s.fixed)?;
        if p != patches {
            return Err(CosimError::Config(
                "the sources' scenes differ in fixed point: a machine's host memory holds one scene".into(),
            ));
        }
        sources.push((setup, cmds));
    }
    let mut memory = HostMemory::new(patches.clone(), config.tc).map_err(sim)?;
    let rounds = deal(sources.len(), config.pes, config.deal);
    let mut m = MachineRun {
        pes: config.pes,
        sources: sources.len(),
        rounds: rounds.len(),
        source_cycles: vec![0; sources.len()],
        ..Default::default()
    };
    for (r, round) in rounds.iter().enumerate() {
        let given: Vec<usize> = round.iter().flatten().copied().collect();
        let work: Vec<Work> =
            given.iter().map(|&i| Work { setup: &sources[i].0, commands: &sources[i].1 }).collect();
        let (hits, k) = run_round(machine, &mut memory, cache, &work).map_err(sim)?;
        for (p, &i) in given.iter().enumerate() {
            let (setup, cmds) = &sources[i];
            let (want, model) = pe::model(setup, &patches, cmds);
            check_against_model(&hits[p], &k.pes[p], &want, &model)
                .map_err(|e| CosimError::Mismatch(format!("source {i} on PE {p} in round {r}: {e}")))?;
            m.source_cycles[i] = k.pes[p].cycles;
            m.rays += setup.dirs.len() as u64;
            m.patch_loads += k.pes[p].patch_loads;
            m.cache_hits += k.pes[p].cache_hits;
            m.tests += k.pes[p].tests;
        }
        m.cycles += k.cycles;
        m.setup_cycles += k.setup_cycles;
        m.command_cycles += k.command_cycles;
        m.readout_cycles += k.readout_cycles;
        progress(r + 1, rounds.len());
    }
    m.memory_loads = memory.loads();
    m.memory_busy_cycles = memory.busy_cycles();
    m.memory_utilisation =
        if m.command_cycles > 0 { m.memory_busy_cycles as f64 / m.command_cycles as f64 } else { 0.0 };
    Ok(m)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deals_cover_every_source_once() {
        for how in [Deal::Blocks, Deal::Interleaved] {
            for (n, pes) in [(10, 3), (8, 8), (1, 4), (17, 4)] {
                let rounds = deal(n, pes, how);
                let mut seen: Vec<usize> = rounds.iter().flatten().flatten().copied().collect();
                seen.sort();
                assert_eq!(seen, (0..n).collect::<Vec<_>>(), "{how:?} {n} on {pes}");
                assert_eq!(rounds.len(), n.div_ceil(pes));
            }
        }
        assert_eq!(
            deal(5, 2, Deal::Blocks),
            vec![vec![Some(0), Some(3)], vec![Some(1), Some(4)], vec![Some(2), None]]
        );
        assert_eq!(
            deal(5, 2, Deal::Interleaved),
            vec![vec![Some(0), Some(1)], vec![Some(2), Some(3)], vec![Some(4), None]]
        );
    }
}
