//! Co-simulation: a source's work stream through the RTL processing element, cycle by cycle,
//! against the bit-true model and the host memory model.
//!
//! The shell scheduler ([`GriddedScene::schedule`](crate::run::GriddedScene::schedule)) records the work
//! stream on the bit-true backend; [`run`] turns it into the host's commands, simulates the
//! processing element of `shelling-hdl` ([`Engine`]: rust-hdl's simulation of the block, or its
//! exported Verilog compiled by Verilator, cycle for cycle the same) with a host memory of load
//! time `T_c`
//! (optionally behind the PE's patch cache), reads every ray's nearest hit back and checks it,
//! and the PE's counters, against the bit-true execution of the same commands (rung 3 for the
//! whole system). The golden `f64` hits are compared by the caller within the documented bound
//! (rung 2, [`crate::agreement`]).

use crate::limits::{check_range, MAX_TC, MAX_VCD_WINDOW};
use crate::run::Scheduled;
use crate::staged::Staged;
use crate::workstream::{commands, PeWork, StreamError};
use serde::Serialize;
use shelling_hdl::formats::Nearest;
use shelling_testbench::memory::HostMemory;
use shelling_testbench::pe::{self, MemoryMap, ModelCounts, PeCounters};
use shelling_testbench::pe::{rust_hdl_pe, RustHdlPe};
use shelling_testbench::rust_hdl::core::prelude::Block;
use shelling_testbench::verilated::VerilatedPe;
use shelling_testbench::Driver;
use shelling_testbench::PeSim;
use std::path::PathBuf;

/// The simulator the processing element runs on. Both give the same cycles, hits and counters.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, clap::ValueEnum)]
pub enum Engine {
    /// Verilator where `verilator` is on the `PATH` and no VCD is asked for, rust-hdl otherwise
    /// ([`Engine::resolve`]).
    Auto,
    /// rust-hdl's own simulation of the block: VCD windows, about 40k cycles a second.
    #[default]
    RustHdl,
    /// The exported Verilog compiled by Verilator and loaded as a shared library (built once
    /// and cached, about 15 s; needs `verilator` and a C++ compiler): tens of times faster, no
    /// VCD ([`shelling_testbench::verilated`]).
    Verilator,
}

impl Engine {
    /// The engine a run uses: [`Engine::Auto`] becomes Verilator where
    /// [`verilated::available`](shelling_testbench::verilated::available) and `vcd` is false,
    /// rust-hdl otherwise; the others stay as they are.
    pub fn resolve(self, vcd: bool) -> Engine {
        match self {
            Engine::Auto if !vcd && shelling_testbench::verilated::available() => Engine::Verilator,
            Engine::Auto => Engine::RustHdl,
            e => e,
        }
    }

    /// The engine's name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Engine::Auto => "auto",
            Engine::RustHdl => "rust-hdl",
            Engine::Verilator => "verilator",
        }
    }
}

/// How the hardware is set up for a co-simulation.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CosimConfig {
    /// Cycles the host memory takes per patch (`1 ≤ T_c ≤` [`MAX_TC`]).
    pub tc: u32,
    /// The PE's patch cache: `None` off, `Some(lines)` on (1 to 1024).
    pub cache: Option<u32>,
    /// VCD of the whole PE for cycles `from..to` of the simulation (counted from power-up): a
    /// non-empty window that must meet the run (the command line also bounds its length,
    /// [`check_vcd_window`]); rust-hdl's engine only. Written under
    /// a temporary name, renamed into place when the run passes.
    pub vcd: Option<VcdWindow>,
    /// The simulator.
    pub engine: Engine,
}

impl Default for CosimConfig {
    fn default() -> Self {
        CosimConfig { tc: 1, cache: None, vcd: None, engine: Engine::RustHdl }
    }
}

/// A VCD file and the cycles it covers, counted from the PE's power-up.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VcdWindow {
    pub path: PathBuf,
    pub from: u64,
    pub to: u64,
}

/// The result of a co-simulation: the PE's hits (equal to the bit-true model's), its counters
/// and the model's.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Cosim {
    #[serde(skip)]
    pub hits: Vec<Option<Nearest>>,
    pub hardware: PeCounters,
    pub model: ModelCounts,
    /// The cycles of an ideal in-order PE on the same commands, host memory and cache
    /// ([`pe::inorder_cycles`]): zero latencies, an unbounded window; a lower bound on
    /// `hardware.cycles`.
    pub inorder_cycles: u64,
}

/// A source's bound on a fresh PE: max(host loads·T_c, loads, tests), the cycles the host
/// memory, the loader (one patch a clock) or the intersection unit (one test a clock) need at
/// the least.
pub fn bound_cycles(h: &PeCounters, tc: u32) -> u64 {
    (h.memory_loads * tc as u64).max(h.patch_loads).max(h.tests)
}

/// What keeps a co-simulation from running or passing.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CosimError {
    #[error("invalid work stream: {0}")]
    Stream(#[from] StreamError),
    #[error("{0}")]
    Config(String),
    #[error("simulation: {0}")]
    Sim(String),
    #[error("the PE disagrees with the bit-true model: {0}")]
    Mismatch(String),
    /// The VCD window starts after the run's last cycle (the run covered `first..last`).
    #[error(
        "--vcd-from {from} is beyond the run, which ends at cycle {last} (it started at cycle {first}): the VCD \
         window {from}..{to} holds no cycle"
    )]
    VcdOutsideRun { from: u64, to: u64, first: u64, last: u64 },
}

fn sim(e: shelling_testbench::Error) -> CosimError {
    CosimError::Sim(e.message().to_string())
}

/// Co-simulates a scheduled source on a new PE of `config.engine`; `progress(done, total)`
/// reports commands sent.
pub fn run(
    scheduled: &Scheduled,
    config: &CosimConfig,
    progress: impl FnMut(usize, usize),
) -> Result<Cosim, CosimError> {
    run_work(commands(&scheduled.stream, &scheduled.fixed)?, config, progress)
}

/// Co-simulates the source `work` (the host's setup, patches and commands, e.g. a
/// [`crate::workstream::pack`] of several bundles) on a new PE of `config.engine`, every hit and
/// counter checked against the bit-true model of the same work.
pub fn run_work(
    work: PeWork,
    config: &CosimConfig,
    progress: impl FnMut(usize, usize),
) -> Result<Cosim, CosimError> {
    match config.engine.resolve(config.vcd.is_some()) {
        Engine::RustHdl | Engine::Auto => {
            let mut drv = rust_hdl_pe().map_err(sim)?;
            match &config.vcd {
                None => sim_work(&mut drv, work, config, progress),
                Some(v) => with_vcd(&mut drv, v, |drv| sim_work(drv, work, config, progress)),
            }
        }
        Engine::Verilator => {
            if config.vcd.is_some() {
                return Err(CosimError::Config(
                    "a VCD needs the rust-hdl engine: the compiled PE writes no waveforms".into(),
                ));
            }
            let mut pe = VerilatedPe::new().map_err(|e| {
                CosimError::Sim(format!("{}; the rust-hdl engine needs no Verilator", e.message()))
            })?;
            sim_work(&mut pe, work, config, progress)
        }
    }
}

/// Co-simulates a scheduled source on the PE of `drv`, which may have run sources before (its
/// readout leaves it cleared) and may be recording its ports for a replay of the exported Verilog
/// ([`shelling_testbench::Driver::record_ports`]): several sources then make one set of vectors.
/// The PE's patch cache keeps its lines from run to run: before a source of another scene, flush
/// it ([`shelling_testbench::pe::flush_cache`]), or its hits return the old scene's patches.
pub fn run_on(
    drv: &mut RustHdlPe,
    scheduled: &Scheduled,
    config: &CosimConfig,
    progress: impl FnMut(usize, usize),
) -> Result<Cosim, CosimError> {
    let Some(v) = &config.vcd else { return run_sim(drv, scheduled, config, progress) };
    with_vcd(drv, v, |drv| run_sim(drv, scheduled, config, progress))
}

/// Runs `run` on `drv` (the PE's RTL or the machine's) with the VCD window `v` streaming. The
/// VCD is written under a temporary name and renamed once the run has passed and covered the
/// window: a failed run leaves no VCD.
pub(crate) fn with_vcd<B: Block, T>(
    drv: &mut Driver<B>,
    v: &VcdWindow,
    run: impl FnOnce(&mut Driver<B>) -> Result<T, CosimError>,
) -> Result<T, CosimError> {
    if v.from >= v.to {
        return Err(CosimError::Config(format!("the VCD window {}..{} holds no cycle", v.from, v.to)));
    }
    let staged = Staged::file(&v.path)
        .map_err(|e| CosimError::Config(format!("cannot write the VCD {}: {e}", v.path.display())))?;
    let first = drv.cycles();
    drv.stream_vcd(staged.path(), v.from..v.to).map_err(sim)?;
    let result = run(drv);
    let finished = drv.finish_vcd().map_err(sim);
    let result = result?;
    finished?;
    let last = drv.cycles();
    if v.from >= last {
        return Err(CosimError::VcdOutsideRun { from: v.from, to: v.to, first, last });
    }
    staged
        .commit()
        .map_err(|e| CosimError::Config(format!("cannot write the VCD {}: {e}", v.path.display())))?;
    Ok(result)
}

/// The host memory's map for a cache of `lines` lines over `patches` patches (see
/// [`MemoryMap`]): the PE runs the mapped commands on the mapped memory.
pub(crate) fn memory_map(lines: Option<u32>, patches: usize) -> Result<MemoryMap, CosimError> {
    MemoryMap::new(lines, patches).map_err(|e| CosimError::Config(e.message().to_string()))
}

/// Hits checked against the model of the mapped commands, with their addresses turned back into
/// patch numbers (the model names only addresses that hold a patch).
pub(crate) fn patch_numbers(map: &MemoryMap, hits: Vec<Option<Nearest>>) -> Vec<Option<Nearest>> {
    hits.into_iter()
        .map(|h| h.map(|n| Nearest { id: map.patch(n.id).expect("a checked hit names a patch"), ..n }))
        .collect()
}

/// Checks a PE's hits and counters after a source against the bit-true model's (`want`,
/// `model`): every ray's hit, and the loads (from the host or the cache), passed patches and
/// tests. The error names the first ray or count that differs.
pub(crate) fn check_against_model(
    hits: &[Option<Nearest>],
    hardware: &PeCounters,
    want: &[Option<Nearest>],
    model: &ModelCounts,
) -> Result<(), CosimError> {
    check_hits(hits, want)?;
    check_counts(hardware, model)
}

/// Every ray's nearest hit against the model's.
pub(crate) fn check_hits(hits: &[Option<Nearest>], want: &[Option<Nearest>]) -> Result<(), CosimError> {
    if let Some(r) = (0..hits.len()).find(|&r| hits[r] != want[r]) {
        return Err(CosimError::Mismatch(format!(
            "ray {r}: PE {:?}, model {:?} ({} rays differ)",
            hits[r],
            want[r],
            (0..hits.len()).filter(|&r| hits[r] != want[r]).count()
        )));
    }
    Ok(())
}

/// The PE's counts (loads, passed patches, tests) against the model's.
pub(crate) fn check_counts(hardware: &PeCounters, model: &ModelCounts) -> Result<(), CosimError> {
    let pairs = [
        ("patch loads", hardware.patch_loads, model.loads),
        ("memory loads", hardware.memory_loads + hardware.cache_hits, model.loads),
        ("patches passed", hardware.passed, model.passed),
        ("tests", hardware.tests, model.tests),
    ];
    for (what, hw, m) in pairs {
        if hw != m {
            return Err(CosimError::Mismatch(format!("{what}: PE {hw}, model {m}")));
        }
    }
    Ok(())
}

/// Checks a VCD window `from..to` of the command line (cycles from power-up): non-empty and at
/// most [`MAX_VCD_WINDOW`] cycles long. ([`run_on`] takes any non-empty window, `to` =
/// `u64::MAX` for the whole run; whether it meets the run is known only after it.)
pub fn check_vcd_window(from: u64, to: u64) -> Result<(), CosimError> {
    if to <= from || to - from > MAX_VCD_WINDOW {
        return Err(CosimError::Config(format!(
            "the VCD window --vcd-from {from} --vcd-to {to} must hold 1 to {MAX_VCD_WINDOW} cycles: --vcd-to \
             must be between {} and {}",
            from.saturating_add(1),
            from.saturating_add(MAX_VCD_WINDOW)
        )));
    }
    Ok(())
}

/// Co-simulates a scheduled source on any simulator of the PE (fresh, or after earlier sources
/// as in [`run_on`]), without a VCD (`config.vcd` and `config.engine` are not read).
pub fn run_sim<S: PeSim>(
    sim_pe: &mut S,
    scheduled: &Scheduled,
    config: &CosimConfig,
    progress: impl FnMut(usize, usize),
) -> Result<Cosim, CosimError> {
    sim_work(sim_pe, commands(&scheduled.stream, &scheduled.fixed)?, config, progress)
}

/// [`run_sim`] of the host's `work`.
fn sim_work<S: PeSim>(
    sim_pe: &mut S,
    (setup, patches, cmds): PeWork,
    config: &CosimConfig,
    progress: impl FnMut(usize, usize),
) -> Result<Cosim, CosimError> {
    check_range("--tc", config.tc, 1, MAX_TC).map_err(CosimError::Config)?;
    let map = memory_map(config.cache, patches.len())?;
    let (patches, cmds) = (map.memory(&patches), map.commands(&cmds));
    let (want, model) = pe::model(&setup, &patches, &cmds);
    let inorder_cycles = pe::inorder_cycles(&setup, &patches, &cmds, config.tc as u64, map.cache());
    let mut memory = HostMemory::new(patches, config.tc).map_err(sim)?;
    let (hits, hardware) = pe::run(sim_pe, &mut memory, &setup, map.cache(), &cmds, progress).map_err(sim)?;
    check_against_model(&hits, &hardware, &want, &model)?;
    Ok(Cosim { hits: patch_numbers(&map, hits), hardware, model, inorder_cycles })
}
