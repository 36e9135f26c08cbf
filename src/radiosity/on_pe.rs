//! Form-factor rows computed on the RTL processing element: every bundle of a row scheduled by
//! the shell scheduler, co-simulated ([`crate::cosim`]), its hits checked against the bit-true
//! model (by the co-simulation) and against the `f64` golden model within the documented bound
//! (rung 2, [`crate::agreement`]), and the row built from the PE's own hits. The PE's cycles add
//! up over the solve.
//!
//! [`row`] and [`all_rows`] run each bundle on a fresh PE, so a patch cache starts cold for
//! every bundle (the figures are an upper bound). [`all_rows_on_machine`] runs the whole matrix
//! on the parallel machine of N PEs ([`crate::machine`]): the bundles back to back on each PE,
//! its cache warm from one to the next, the PEs sharing one host memory.

use super::form_factors::{bundles, FfError, FfParams, Row, RowBuilder};
use crate::agreement;
use crate::cosim::{self, CosimConfig, CosimError};
use crate::run::{GriddedScene, RunError};
use crate::trace::{Method, TraceError};

/// The most rays of one bundle on the PE (its ray memory): the default rays of a solve on it.
pub use shelling_testbench::pe::PE_RAY_MEMORY;

/// The committed post-route results of the FPGA flow (`cargo xtask fpga --seeds ...`), embedded
/// at build time; `tests/hardware.rs` fails when they are not of the committed Verilog.
const FPGA_RESULTS: &str = include_str!("../../hdl/fpga/ecp5-seeds.json");

/// The post-route clock rate assumed for the solve's time unless another is given: the median
/// over the placement seeds of the PE on ECP5 LFE5U-85F-6 in `hdl/fpga/ecp5-seeds.json`.
pub fn pe_clock_mhz() -> f64 {
    let json: serde_json::Value =
        serde_json::from_str(FPGA_RESULTS).expect("hdl/fpga/ecp5-seeds.json is JSON");
    json["blocks"]
        .as_array()
        .and_then(|b| b.iter().find(|b| b["block"] == "processing_element" && b["family"] == "ecp5"))
        .and_then(|b| b["median_mhz"].as_f64())
        .expect("hdl/fpga/ecp5-seeds.json holds the PE's median fmax on ECP5")
}

/// The committed post-route results of the machines (`cargo xtask fpga --blocks machine_N`).
const MACHINE_FPGA_RESULTS: &str = include_str!("../../hdl/fpga/ecp5-machine-seeds.json");

/// The median post-route clock rate of the machine of `pes` PEs on ECP5 LFE5U-85F-6 in
/// `hdl/fpga/ecp5-machine-seeds.json`, if it was measured.
pub fn machine_clock_mhz(pes: usize) -> Option<f64> {
    let json: serde_json::Value = serde_json::from_str(MACHINE_FPGA_RESULTS).ok()?;
    json["blocks"]
        .as_array()?
        .iter()
        .find(|b| b["block"] == format!("machine_{pes}").as_str() && b["family"] == "ecp5")?["median_mhz"]
        .as_f64()
}

/// The hardware's side of a solve: the sums over every bundle co-simulated.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct PeTotals {
    /// Form-factor rows computed on the PE.
    pub rows: usize,
    /// Bundles co-simulated (rows × origins).
    pub bundles: usize,
    /// Rays traced.
    pub rays: usize,
    /// PE cycles, summed over the bundles; on the machine, from its first setup to its last
    /// readout.
    pub cycles: u64,
    /// Cycles the intersection unit tested a live ray.
    pub intersection_busy_cycles: u64,
    pub patch_loads: u64,
    pub cache_hits: u64,
    pub tests: u64,
    /// Rays whose nearest patch on the PE equals the `f64` golden model's (the rest differ
    /// within the documented bound).
    pub golden_agree: usize,
}

impl PeTotals {
    /// Adds a fresh PE's counts of one source.
    pub fn add_pe(&mut self, h: &shelling_testbench::pe::PeCounters) {
        self.add_counts(h.cycles, h.intersection_busy_cycles, h.patch_loads, h.cache_hits, h.tests);
    }

    /// Adds a machine run's counts (its cycles the run's time).
    pub fn add_machine(&mut self, r: &crate::machine::MachineRun) {
        self.add_counts(r.cycles, r.intersection_busy_cycles, r.patch_loads, r.cache_hits, r.tests);
    }

    fn add_counts(&mut self, cycles: u64, busy: u64, loads: u64, cache_hits: u64, tests: u64) {
        self.cycles += cycles;
        self.intersection_busy_cycles += busy;
        self.patch_loads += loads;
        self.cache_hits += cache_hits;
        self.tests += tests;
    }
}

impl std::ops::AddAssign for PeTotals {
    fn add_assign(&mut self, o: PeTotals) {
        self.rows += o.rows;
        self.bundles += o.bundles;
        self.rays += o.rays;
        self.cycles += o.cycles;
        self.intersection_busy_cycles += o.intersection_busy_cycles;
        self.patch_loads += o.patch_loads;
        self.cache_hits += o.cache_hits;
        self.tests += o.tests;
        self.golden_agree += o.golden_agree;
    }
}

/// What keeps a row from being computed on the PE.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OnPeError {
    #[error("--method brute has no hardware mapping: use conventional, stochastic or deterministic")]
    Brute,
    #[error("--rays {0}: the processing element holds at most {PE_RAY_MEMORY} rays per bundle")]
    TooManyRays(usize),
    #[error(transparent)]
    Ff(#[from] FfError),
    #[error(transparent)]
    Cosim(#[from] CosimError),
    #[error("source patch {source_patch}: the PE's hits differ from the f64 golden model beyond the documented bound on {rays} rays")]
    BeyondBound { source_patch: usize, rays: usize },
}

impl From<RunError> for OnPeError {
    fn from(e: RunError) -> Self {
        OnPeError::Ff(FfError::Run(e))
    }
}

impl From<TraceError> for OnPeError {
    fn from(e: TraceError) -> Self {
        OnPeError::Ff(FfError::Run(RunError::Trace(e)))
    }
}

/// `p` maps onto the PE: a technique with a hardware mapping, a bundle in its ray memory.
fn check_params(p: &FfParams) -> Result<(), OnPeError> {
    if p.method == Method::Brute {
        return Err(OnPeError::Brute);
    }
    if p.rays > PE_RAY_MEMORY {
        return Err(OnPeError::TooManyRays(p.rays));
    }
    Ok(())
}

/// `bundle` of source patch `k` scheduled by `p.method` on the bit-true backend, its trace
/// checked against the `f64` golden model within the documented bound (rung 2); with the rays
/// whose hit is the golden model's.
fn scheduled_within_bound(
    prepared: &GriddedScene,
    k: usize,
    bundle: &crate::rays::Bundle,
    p: &FfParams,
) -> Result<(crate::run::Scheduled, usize), OnPeError> {
    let scheduled = prepared.schedule(p.method, bundle, &p.shells)?;
    let golden = prepared.trace(p.method, bundle, &p.shells)?;
    let rung2 = agreement::compare(&prepared.scene.segments, bundle, &golden, &scheduled.trace);
    match rung2.beyond_bound().count() {
        0 => Ok((scheduled, rung2.agree)),
        rays => Err(OnPeError::BeyondBound { source_patch: k, rays }),
    }
}

/// The row of source patch `k` from the PE's hits (`p.arith` is not read: the PE's arithmetic is
/// the fixed point); the hardware's counts are added to `totals`.
pub fn row(
    prepared: &GriddedScene,
    k: usize,
    p: &FfParams,
    config: &CosimConfig,
    totals: &mut PeTotals,
) -> Result<Row, OnPeError> {
    check_params(p)?;
    let mut builder = RowBuilder::new(prepared.scene.len(), p);
    for bundle in bundles(prepared, k, p)? {
        let (scheduled, agree) = scheduled_within_bound(prepared, k, &bundle, p)?;
        let run = cosim::run(&scheduled, config, |_, _| {})?;
        builder.add_patches(run.hits.iter().map(|h| h.map(|n| n.id as usize)));
        totals.bundles += 1;
        totals.rays += bundle.len();
        totals.add_pe(&run.hardware);
        totals.golden_agree += agree;
    }
    totals.rows += 1;
    Ok(builder.finish(k))
}

/// Every row of the scene computed on the parallel machine of `config.pes` PEs: the rows'
/// bundles, source after source in the scene's order, dealt as `config.deal` says to PEs that
/// share one host memory, each PE's cache (if any) warm from bundle to bundle. Each bundle is
/// checked as [`row`] checks it: the bit-true model by the machine's co-simulation, rung 2
/// against the `f64` golden model on its bit-true trace. The machine's hits are that trace's but
/// where `config.place` ([`Placement::Lines`](crate::machine::Placement)) gave the lower address
/// to the other of two patches hit at one distance; such a bundle's hits, the machine's patches
/// at the trace's distances, are checked by rung 2 again. `totals.cycles` is the machine's time;
/// `progress(bundles done, bundles)`.
pub fn all_rows_on_machine(
    prepared: &GriddedScene,
    p: &FfParams,
    config: &crate::machine::MachineConfig,
    progress: impl FnMut(usize, usize),
) -> Result<(Vec<Row>, PeTotals), OnPeError> {
    use crate::machine;
    check_params(p)?;
    let mut totals = PeTotals::default();
    let (mut work, mut agrees, mut of_row) = (Vec::new(), Vec::new(), Vec::new());
    for k in 0..prepared.scene.len() {
        for (j, bundle) in bundles(prepared, k, p)?.into_iter().enumerate() {
            let (scheduled, agree) = scheduled_within_bound(prepared, k, &bundle, p)?;
            totals.bundles += 1;
            totals.rays += bundle.len();
            totals.golden_agree += agree;
            work.push(scheduled);
            agrees.push(agree);
            of_row.push((k, j));
        }
    }
    let run = machine::run(&work, &crate::machine::MachineConfig { vcd: None, ..config.clone() }, progress)?;
    let mut builders: Vec<RowBuilder> =
        (0..prepared.scene.len()).map(|_| RowBuilder::new(prepared.scene.len(), p)).collect();
    for (((scheduled, &agree), hits), &(k, j)) in work.iter().zip(&agrees).zip(&run.hits).zip(&of_row) {
        let mut own = scheduled.trace.clone();
        for (h, m) in own.hits.iter_mut().zip(hits) {
            *h = match (*h, m) {
                (Some(h), Some(m)) => Some(crate::geom::Hit { segment: u32::from(m.id), ..h }),
                (None, None) => None,
                _ => {
                    return Err(OnPeError::Cosim(CosimError::Mismatch(format!(
                        "source patch {k}: the machine hit a patch where the bit-true trace hit none, or none where it hit one"
                    ))))
                }
            };
        }
        if own.hits != scheduled.trace.hits {
            let bundle = &bundles(prepared, k, p)?[j];
            let golden = prepared.trace(p.method, bundle, &p.shells)?;
            let rung2 = agreement::compare(&prepared.scene.segments, bundle, &golden, &own);
            if rung2.beyond_bound().count() > 0 {
                return Err(OnPeError::BeyondBound { source_patch: k, rays: rung2.beyond_bound().count() });
            }
            totals.golden_agree = totals.golden_agree + rung2.agree - agree;
        }
        builders[k].add_patches(hits.iter().map(|h| h.map(|n| n.id as usize)));
    }
    totals.rows = prepared.scene.len();
    totals.add_machine(&run);
    let rows = builders.into_iter().enumerate().map(|(k, b)| b.finish(k)).collect();
    Ok((rows, totals))
}

/// Every row of the scene computed on the PE, in order, with the hardware's sums.
pub fn all_rows(
    prepared: &GriddedScene,
    p: &FfParams,
    config: &CosimConfig,
    mut progress: impl FnMut(usize),
) -> Result<(Vec<Row>, PeTotals), OnPeError> {
    let mut totals = PeTotals::default();
    let rows = (0..prepared.scene.len())
        .map(|k| {
            let r = row(prepared, k, p, config, &mut totals);
            progress(k + 1);
            r
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok((rows, totals))
}

/// The whole-solve table of FIGURES.md: the form-factor matrix of the default room
/// ([`crate::scene::RoomSpec::default`]) at [`PE_RAY_MEMORY`] rays and the default origins, computed on the PE by
/// each technique with the patch cache off and on, at host memory load time `tc`. Markdown, with
/// the parameters in its first line. Every row of every run is checked as [`row`] checks it. The
/// techniques' fixed-point matrices may differ where rung 2 allows (a technique's scheduler
/// screens in f64, so a ray at a patch's endpoint may be tested by one and not by another); the
/// last column is the fraction of rays whose PE hit is the f64 golden model's.
pub fn whole_solve_table(engine: cosim::Engine, tc: u32, cache: u32) -> Result<String, OnPeError> {
    use crate::grid::GridParams;
    use crate::scene::{room, RoomSpec};
    use std::fmt::Write;
    let scene = room(&RoomSpec::default()).expect("the default room is valid");
    let prepared = GriddedScene::new(scene, GridParams::default());
    let base = FfParams { rays: PE_RAY_MEMORY, arith: crate::arith::Arith::Fixed, ..FfParams::default() };
    let clock = pe_clock_mhz();
    let mut out = format!(
        "Default room ({} patches), full matrix: {} origins × {} {} rays per patch ({} bundles), T_c = {tc}, \
         patch cache of {cache} lines, {} simulation; time at {clock} MHz (the PE's median post-route rate).\n\n",
        prepared.scene.len(),
        base.origins,
        base.rays,
        base.ray_set,
        prepared.scene.len() * base.origins,
        engine.name(),
    );
    out.push_str("| method | cache | PE cycles | tests | patch loads | cache hits | pipeline efficiency | time at the clock | speedup against conventional without cache | rays with the f64 hit |\n");
    out.push_str("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    let mut conventional: Option<u64> = None;
    for method in [Method::Conventional, Method::Stochastic, Method::Deterministic] {
        for lines in [None, Some(cache)] {
            let p = FfParams { method, ..base.clone() };
            let config = CosimConfig { tc, cache: lines, vcd: None, engine };
            let (_, t) = all_rows(&prepared, &p, &config, |_| {})?;
            let base_cycles = *conventional.get_or_insert(t.cycles);
            let _ = writeln!(
                out,
                "| {method} | {} | {} | {} | {} | {} | {:.3} | {:.1} ms | {:.2}× | {:.5} |",
                lines.map_or("off".to_string(), |l| l.to_string()),
                t.cycles,
                t.tests,
                t.patch_loads,
                t.cache_hits,
                t.intersection_busy_cycles as f64 / t.cycles as f64,
                t.cycles as f64 / (clock * 1e3),
                base_cycles as f64 / t.cycles as f64,
                t.golden_agree as f64 / t.rays as f64,
            );
        }
    }
    Ok(out)
}
