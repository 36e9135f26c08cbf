//! The paper's hardware claim, measured: a sample of the Section 5 workload co-simulated on the
//! RTL processing element ([`crate::cosim`]), cycle by cycle, for every host memory load time
//! `T_c` of [`FigureOptions::tcs`], without and with the PE's patch cache, beside the speedup
//! that Eqs. 10–11 predict from the measured `S` and ADLC.
//!
//! # Sample
//!
//! For the `i`-th segment length, the scene of the first seed ([`scene_seed`]`(i, 0)`, the
//! golden part's first scene) and the sources [`source_patches`]`(count,
//! cosim_sources)`; each source's bundle (the golden part's ray set and ray count) is scheduled
//! by the three techniques on the bit-true backend ([`GriddedScene::schedule`]) and every schedule is
//! co-simulated for every `T_c`, once on the shared host memory (no cache) and once behind a
//! patch cache of [`FigureOptions::cache_lines`] lines. Every run checks every hit against the
//! bit-true model ([`crate::cosim::run`]); a mismatch fails the command.
//!
//! Then each length's sources run back to back on one PE, for every technique, `T_c` and cache
//! setting ([`QueueTotals`], [`crate::machine::run`] with one PE): the steady state of a
//! radiosity solve, each source's setup and readout overlapping the commands of its neighbours
//! and the cache kept from source to source; every hit checked the same way.
//!
//! # Speedups and predictions
//!
//! The measured speedup of a shelling technique is the conventional technique's mean cycles
//! over its own, for the same `T_c`, in three pairings ([`Scenario`]): both on the shared memory;
//! both with the cache; and the pairing of the paper's cache remark (§4: "when a high speed
//! cache memory is allowed for each PE and the next patch can be loaded immediately from that
//! memory, the speedup factor will be the ratio of `T_c` over `T_λ`"): shelling with the cache
//! against the conventional technique on the shared memory. The predictions ([`prediction`])
//! use `T_λ = 1` (the intersection unit tests one ray–patch pair per clock), the mean measured
//! `S` ([`crate::trace::ShellStats::leaving_fraction`]) and the mean true ADLC of the
//! co-simulated sources (INTERPRETATION.md, "Eqs. 10–11 against the co-simulation").

use super::plot::{method_marker, render, tick_label, Chart, Marker, Series, XAxis};
use super::{csv_num, scene_seed, source_patches, FigureOptions, METHODS};
use crate::cosim::{self, CosimConfig};
use crate::machine::{self, Deal, MachineConfig, MachineRun, Placement};
use crate::run::{GriddedScene, Scheduled};
use crate::scene;
use crate::trace::Method;
use anyhow::{anyhow, bail, Result};
use plotters::style::RGBColor;
use rayon::prelude::*;
use shelling_testbench::pe::{ModelCounts, PeCounters, PE_RAY_MEMORY};
use std::fmt;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

/// `T_λ`: cycles per ray–patch test of the intersection unit (one test per clock).
pub const T_LAMBDA: f64 = 1.0;

/// Checks the co-simulation options (called by [`FigureOptions::validate`] when
/// `cosim_sources > 0`).
pub(super) fn validate(o: &FigureOptions) -> Result<()> {
    if o.cosim_sources > o.count {
        bail!(
            "cosim sources ({}) cannot exceed the number of segments per scene ({})",
            o.cosim_sources,
            o.count
        );
    }
    if o.rays > PE_RAY_MEMORY {
        bail!(
            "--rays must be between 1 and {PE_RAY_MEMORY} (the processing element's ray memory) for the \
             co-simulated figures (--cosim-sources 0 skips them), got {}",
            o.rays
        );
    }
    if o.tcs.is_empty() {
        bail!("at least one T_c is needed for the co-simulation");
    }
    for (i, &tc) in o.tcs.iter().enumerate() {
        if tc == 0 {
            bail!("T_c must be at least 1 cycle per patch, got 0");
        }
        if o.tcs[..i].contains(&tc) {
            bail!("T_c {tc} is listed twice");
        }
    }
    crate::limits::check_cache("cache lines", o.cache_lines).map_err(|e| anyhow!(e))?;
    Ok(())
}

/// The PE's counters summed over the co-simulated sources of one row.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CycleTotals {
    pub cycles: u64,
    pub intersection_busy_cycles: u64,
    pub stall_cycles: u64,
    pub drain_cycles: u64,
    /// Patches the PE's loader loaded (cache hits included).
    pub patch_loads: u64,
    /// Patches the host memory delivered.
    pub memory_loads: u64,
    pub cache_hits: u64,
    /// Loaded patches the screener passed.
    pub passed: u64,
    /// Ray slots of the passed patches' jobs: the cycles the intersection unit issues, live rays
    /// (`tests`) and rays retired before the job reached it (bubbles).
    pub ray_slots: u64,
    /// Ray–patch tests of live rays.
    pub tests: u64,
    /// Runs of live rays in the passed jobs' ranges ([`ModelCounts::live_runs`]): the jobs the
    /// unit would take if the host split the ranges at their retired rays.
    pub live_runs: u64,
    /// Sector changes (each drains the PE).
    pub sectors: u64,
    /// Σ over sources of `max(memory_loads · T_c, patch_loads, tests · T_λ)`: the cycles the host
    /// memory, the loader (one patch per clock) or the intersection unit need at the least.
    pub bound_cycles: u64,
    /// Σ over sources of the cycles of an ideal in-order PE on the source's commands
    /// ([`shelling_testbench::pe::inorder_cycles`]): between `bound_cycles` and `cycles`; what
    /// any PE that answers its loads and tests its jobs in command order needs at the least.
    pub inorder_cycles: u64,
}

impl CycleTotals {
    fn add(&mut self, h: &PeCounters, m: &ModelCounts, tc: u32, inorder: u64) {
        self.cycles += h.cycles;
        self.intersection_busy_cycles += h.intersection_busy_cycles;
        self.stall_cycles += h.stall_cycles;
        self.drain_cycles += h.drain_cycles;
        self.patch_loads += h.patch_loads;
        self.memory_loads += h.memory_loads;
        self.cache_hits += h.cache_hits;
        self.passed += h.passed;
        self.ray_slots += m.ray_slots;
        self.tests += h.tests;
        self.live_runs += m.live_runs;
        self.sectors += m.sectors;
        self.bound_cycles += cosim::bound_cycles(h, tc);
        self.inorder_cycles += inorder;
    }
}

/// One PE's run of all the sources of a row back to back ([`crate::machine::run`] with one PE):
/// each source's directions written and its hits read out while the commands of the one before
/// or after run, the cache (if on) kept from source to source, as in a radiosity solve that
/// shoots from every patch.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QueueTotals {
    /// From the first command to the start of the last readout
    /// ([`crate::machine::MachineRun::stream_cycles`]).
    pub cycles: u64,
    pub intersection_busy_cycles: u64,
    pub memory_loads: u64,
    pub patch_loads: u64,
    pub tests: u64,
    /// `max(memory_loads · T_c, patch_loads, tests · T_λ, rays)` over the whole queue: the host
    /// memory, the loader, the intersection unit and the host's ray port (one direction written
    /// and one hit read a clock: a source's `R` of each, beside the commands of the sources
    /// before and after it) each need that many cycles at the least. (The sum over the sources
    /// of each one's own bound is no bound here: one source's loads overlap another's tests.)
    pub bound_cycles: u64,
}

fn queue_totals(r: &MachineRun, tc: u32) -> QueueTotals {
    QueueTotals {
        cycles: r.stream_cycles,
        intersection_busy_cycles: r.intersection_busy_cycles,
        memory_loads: r.memory_loads,
        patch_loads: r.patch_loads,
        tests: r.tests,
        bound_cycles: (r.memory_loads * tc as u64).max(r.patch_loads).max(r.tests).max(r.rays),
    }
}

/// One technique at one segment length, `T_c` and cache setting.
#[derive(Clone, Debug, PartialEq)]
pub struct CycleRow {
    pub length: f64,
    pub method: Method,
    pub tc: u32,
    /// The patch cache's lines; `None`: no cache (the shared host memory).
    pub cache: Option<u32>,
    /// Sources co-simulated.
    pub sources: usize,
    pub total: CycleTotals,
    /// The same sources back to back on one PE.
    pub queue: QueueTotals,
    /// Mean over the sources of the measured `S` (shelling techniques only).
    pub s_measured: Option<f64>,
    /// Mean over the sources of the true ADLC.
    pub adlc_true: f64,
}

impl CycleRow {
    fn mean(&self, v: u64) -> f64 {
        v as f64 / self.sources.max(1) as f64
    }

    pub fn mean_cycles(&self) -> f64 {
        self.mean(self.total.cycles)
    }

    /// Intersection busy cycles over all cycles (of all the row's sources together).
    pub fn pipeline_efficiency(&self) -> f64 {
        if self.total.cycles == 0 {
            0.0
        } else {
            self.total.intersection_busy_cycles as f64 / self.total.cycles as f64
        }
    }

    /// Measured cycles over the bound of [`CycleTotals::bound_cycles`].
    pub fn overhead(&self) -> f64 {
        self.total.cycles as f64 / self.total.bound_cycles.max(1) as f64
    }

    /// The ideal in-order PE's cycles over the bound: the part of the overhead that no PE taking
    /// its jobs in command order avoids.
    pub fn inorder_overhead(&self) -> f64 {
        self.total.inorder_cycles as f64 / self.total.bound_cycles.max(1) as f64
    }

    /// The sources back to back: cycles over their bound ([`QueueTotals`]).
    pub fn queue_overhead(&self) -> f64 {
        self.queue.cycles as f64 / self.queue.bound_cycles.max(1) as f64
    }

    /// The sources back to back: the intersection unit's busy cycles over all cycles.
    pub fn queue_efficiency(&self) -> f64 {
        self.queue.intersection_busy_cycles as f64 / self.queue.cycles.max(1) as f64
    }
}

/// Which two runs a speedup compares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scenario {
    /// Both techniques on the shared host memory, no cache (Eq. 10).
    Shared,
    /// Both techniques behind the patch cache.
    Cached,
    /// The paper's cache remark (Eq. 11): shelling behind the cache, the conventional technique
    /// on the shared host memory.
    PaperCache,
}

/// The branch of Eq. 10.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Branch {
    /// `ADLC·T_λ ≤ T_c`: patches arrive slower than a bundle consumes them; `SF = S + ADLC`.
    Memory,
    /// `ADLC·T_λ > T_c`: the intersection unit is the bottleneck; `SF = (1 + S/ADLC)·T_c/T_λ`.
    Compute,
}

impl Branch {
    pub fn name(self) -> &'static str {
        match self {
            Branch::Memory => "memory",
            Branch::Compute => "compute",
        }
    }
}

/// A speedup the paper's model predicts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Prediction {
    pub value: f64,
    pub branch: Branch,
}

/// The paper's predicted speedup of shelling over the conventional technique for a scenario,
/// from the measured `S` and ADLC at `T_c` (and [`T_LAMBDA`]):
///
/// * [`Scenario::Shared`]: Eq. 10, the branch chosen by `ADLC·T_λ > T_c`;
/// * [`Scenario::PaperCache`]: Eq. 10's compute branch `(1 + S/ADLC)·T_c/T_λ` (the cache delivers
///   shelling's next patch "immediately", while the conventional technique still waits `T_c`
///   per patch), which is Eq. 11's `T_c/T_λ` at `S = 0`;
/// * [`Scenario::Cached`]: none (the model has no cache for the conventional technique).
///
/// `None` too where the model does not apply (`S ∉ [0, 1)` or no hit, ADLC = 0).
pub fn prediction(scenario: Scenario, s: f64, adlc: f64, tc: u32) -> Option<Prediction> {
    let tc = tc as f64;
    match scenario {
        Scenario::Shared => {
            let value = crate::model::speedup(s, adlc, tc, T_LAMBDA).ok()?;
            let branch = if adlc * T_LAMBDA > tc { Branch::Compute } else { Branch::Memory };
            Some(Prediction { value, branch })
        }
        Scenario::PaperCache => {
            // Checks S and ADLC as Eq. 10 does.
            crate::model::speedup(s, adlc, tc, T_LAMBDA).ok()?;
            Some(Prediction { value: (1.0 + s / adlc) * tc / T_LAMBDA, branch: Branch::Compute })
        }
        Scenario::Cached => None,
    }
}

/// A measured speedup of a shelling technique with the paper's prediction beside it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Speedup {
    pub length: f64,
    pub method: Method,
    pub tc: u32,
    pub scenario: Scenario,
    /// Conventional mean cycles over the shelling technique's.
    pub measured: f64,
    pub predicted: Option<Prediction>,
}

fn find(rows: &[CycleRow], length: f64, method: Method, tc: u32, cached: bool) -> Option<&CycleRow> {
    rows.iter()
        .find(|r| r.length == length && r.method == method && r.tc == tc && r.cache.is_some() == cached)
}

/// The speedups of every shelling row, in row order, for each scenario it takes part in
/// (a row without the cache in [`Scenario::Shared`], one with it in [`Scenario::Cached`] and
/// [`Scenario::PaperCache`]).
pub fn speedups(rows: &[CycleRow]) -> Vec<Speedup> {
    let mut out = Vec::new();
    for r in rows.iter().filter(|r| r.method != Method::Conventional) {
        let scenarios: &[(Scenario, bool)] = if r.cache.is_some() {
            &[(Scenario::Cached, true), (Scenario::PaperCache, false)]
        } else {
            &[(Scenario::Shared, false)]
        };
        for &(scenario, conv_cached) in scenarios {
            let Some(conv) = find(rows, r.length, Method::Conventional, r.tc, conv_cached) else {
                continue;
            };
            let predicted = r.s_measured.and_then(|s| prediction(scenario, s, r.adlc_true, r.tc));
            out.push(Speedup {
                length: r.length,
                method: r.method,
                tc: r.tc,
                scenario,
                measured: conv.mean_cycles() / r.mean_cycles().max(f64::MIN_POSITIVE),
                predicted,
            });
        }
    }
    out
}

fn speedup_of(sp: &[Speedup], r: &CycleRow, scenario: Scenario) -> Option<Speedup> {
    sp.iter()
        .find(|s| s.length == r.length && s.method == r.method && s.tc == r.tc && s.scenario == scenario)
        .copied()
}

/// What a co-simulation runs.
#[derive(Clone, Copy)]
enum Run {
    /// One source on a fresh PE (its index in the sample).
    Source(usize),
    /// Every sample source of a length (its index) back to back on one PE.
    Queue(usize),
}

/// What a co-simulation found.
enum Outcome {
    /// The PE's counters, the model's and the ideal in-order PE's cycles.
    Source(PeCounters, ModelCounts, u64),
    Queue(QueueTotals),
}

/// One co-simulation: a source or a queue, a technique, a `T_c` and a cache setting.
struct Job {
    what: Run,
    method: usize,
    tc: u32,
    cache: Option<u32>,
    /// Rough cycle estimate (for the order and the progress bar).
    cost: u64,
}

/// Runs `run(j, report)` for every job `j`, longest `costs` first, one job at a time on every
/// rayon thread, so that the threads finish close together; `report(done, of)` moves `bar` by
/// that fraction of the job's cost. The first failure stops the jobs not yet started and is
/// returned.
fn longest_first<T: Send>(
    costs: &[u64],
    bar: &indicatif::ProgressBar,
    run: impl Fn(usize, &mut dyn FnMut(usize, usize)) -> Result<T> + Sync,
) -> Result<Vec<T>> {
    let mut order: Vec<usize> = (0..costs.len()).collect();
    order.sort_by_key(|&j| std::cmp::Reverse(costs[j]));
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let failed = AtomicBool::new(false);
    let results: Mutex<Vec<Option<Result<T>>>> = Mutex::new((0..costs.len()).map(|_| None).collect());
    rayon::scope(|scope| {
        for _ in 0..rayon::current_num_threads() {
            scope.spawn(|_| loop {
                let n = next.fetch_add(1, Ordering::Relaxed);
                if n >= order.len() || failed.load(Ordering::Relaxed) {
                    break;
                }
                let (j, cost) = (order[n], costs[order[n]]);
                let mut reported = 0u64;
                let result = run(j, &mut |d, t| {
                    let now = cost * d as u64 / t.max(1) as u64;
                    if now > reported {
                        bar.inc(now - reported);
                        reported = now;
                    }
                });
                bar.inc(cost.saturating_sub(reported));
                bar.set_message(format!("{}/{}", done.fetch_add(1, Ordering::Relaxed) + 1, costs.len()));
                if result.is_err() {
                    failed.store(true, Ordering::Relaxed);
                }
                if let Ok(mut r) = results.lock() {
                    r[j] = Some(result);
                }
            });
        }
    });
    let results = results.into_inner().map_err(|_| anyhow!("a co-simulation worker panicked"))?;
    let mut out = Vec::with_capacity(costs.len());
    for r in results {
        match r {
            Some(Ok(v)) => out.push(v),
            Some(Err(e)) => return Err(e),
            None => {}
        }
    }
    if out.len() != costs.len() {
        bail!("{} of {} co-simulation runs did not finish", costs.len() - out.len(), costs.len());
    }
    Ok(out)
}

fn estimate(s: &Scheduled, tc: u32, cache: Option<u32>, patches: usize) -> u64 {
    let loads = s.trace.counters.patches_read_before_screening;
    let tests = s.trace.counters.intersection_computations;
    let tc = tc as u64;
    let memory = match cache {
        None => loads * tc,
        Some(_) => loads.min(patches as u64) * tc,
    };
    memory.max(tests) + loads + 1
}

/// Co-simulates the sample; returns one row per length (in the order given), cache setting (off,
/// then on), `T_c` (in the order given) and technique (in [`METHODS`] order). Writes nothing.
pub fn measure(opts: &FigureOptions) -> Result<Vec<CycleRow>> {
    Ok(measure_runs(opts)?.0)
}

/// [`measure`] and the number of co-simulation runs.
pub(super) fn measure_runs(opts: &FigureOptions) -> Result<(Vec<CycleRow>, usize)> {
    opts.validate()?;
    if opts.cosim_sources == 0 {
        return Ok((Vec::new(), 0));
    }
    let scenes: Vec<GriddedScene> = (0..opts.lengths.len())
        .into_par_iter()
        .map(|i| {
            let (length, seed) = (opts.lengths[i], scene_seed(i, 0));
            let sc = scene::generate(opts.count, length, seed, scene::PAPER_WORLD)
                .map_err(|e| anyhow!("generating the scene of length {length}, seed {seed}: {e}"))?;
            Ok(GriddedScene::new(sc, opts.grid))
        })
        .collect::<Result<_>>()?;
    let sources: Vec<(usize, usize)> = (0..opts.lengths.len())
        .flat_map(|i| source_patches(opts.count, opts.cosim_sources).into_iter().map(move |k| (i, k)))
        .collect();
    let schedules: Vec<Vec<Scheduled>> = sources
        .par_iter()
        .map(|&(i, k)| {
            let what = || format!("source patch {k} of the scene of length {}", opts.lengths[i]);
            let bundle =
                scenes[i].patch_bundle(k, opts.ray_set, opts.rays).map_err(|e| anyhow!("{}: {e}", what()))?;
            METHODS
                .iter()
                .map(|&m| {
                    scenes[i].schedule(m, &bundle, &opts.shells).map_err(|e| anyhow!("{} ({m}): {e}", what()))
                })
                .collect::<Result<Vec<_>>>()
        })
        .collect::<Result<_>>()?;

    let configs: Vec<(u32, Option<u32>)> = [None, Some(opts.cache_lines)]
        .into_iter()
        .flat_map(|c| opts.tcs.iter().map(move |&tc| (tc, c)))
        .collect();
    let mut jobs: Vec<Job> = Vec::new();
    for (source, sched) in schedules.iter().enumerate() {
        for (method, s) in sched.iter().enumerate() {
            for &(tc, cache) in &configs {
                let cost = estimate(s, tc, cache, opts.count);
                jobs.push(Job { what: Run::Source(source), method, tc, cache, cost });
            }
        }
    }
    // Each length's sample sources (indices into `sources`), a queue's work in that order.
    let of_length: Vec<Vec<usize>> = (0..opts.lengths.len())
        .map(|i| (0..sources.len()).filter(|&k| sources[k].0 == i).collect())
        .collect();
    for (length, queue) in of_length.iter().enumerate() {
        for (method, _) in METHODS.iter().enumerate() {
            for &(tc, cache) in &configs {
                let cost =
                    queue.iter().map(|&k| estimate(&schedules[k][method], tc, cache, opts.count)).sum();
                jobs.push(Job { what: Run::Queue(length), method, tc, cache, cost });
            }
        }
    }

    let total_cost: u64 = jobs.iter().map(|j| j.cost).sum();
    let bar = if opts.progress {
        let b = indicatif::ProgressBar::new(total_cost);
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "co-simulating {bar:40} {msg} runs [{elapsed_precise}, eta {eta}]",
        ) {
            b.set_style(style);
        }
        b.set_message(format!("0/{}", jobs.len()));
        b
    } else {
        indicatif::ProgressBar::hidden()
    };
    let engine = opts.engine.resolve(false);
    let costs: Vec<u64> = jobs.iter().map(|j| j.cost).collect();
    let outcomes = longest_first(&costs, &bar, |n, report| {
        let j = &jobs[n];
        let setting = || {
            format!(
                "{}, T_c {}, {}",
                METHODS[j.method],
                j.tc,
                j.cache.map_or("without the patch cache".to_string(), |n| format!(
                    "with a patch cache of {n} lines"
                ))
            )
        };
        match j.what {
            Run::Source(source) => {
                let config = CosimConfig { tc: j.tc, cache: j.cache, vcd: None, engine: opts.engine };
                let (i, k) = sources[source];
                cosim::run(&schedules[source][j.method], &config, &mut *report)
                    .map(|c| Outcome::Source(c.hardware, c.model, c.inorder_cycles))
                    .map_err(|e| {
                        anyhow!(
                            "co-simulating source patch {k} of the scene of length {} ({}): {e}",
                            opts.lengths[i],
                            setting()
                        )
                    })
            }
            Run::Queue(i) => {
                let work: Vec<Scheduled> =
                    of_length[i].iter().map(|&k| schedules[k][j.method].clone()).collect();
                let config = MachineConfig {
                    pes: 1,
                    tc: j.tc,
                    cache: j.cache,
                    deal: Deal::Blocks,
                    place: Placement::Index,
                    engine,
                    vcd: None,
                };
                machine::run(&work, &config, &mut *report)
                    .map(|r| Outcome::Queue(queue_totals(&r, j.tc)))
                    .map_err(|e| {
                        anyhow!(
                            "co-simulating the {} sources of the scene of length {} back to back ({}): {e}",
                            work.len(),
                            opts.lengths[i],
                            setting()
                        )
                    })
            }
        }
    })?;
    bar.finish_and_clear();

    // Sum in a fixed order.
    let mut rows = Vec::new();
    for (i, &length) in opts.lengths.iter().enumerate() {
        for cache in [None, Some(opts.cache_lines)] {
            for &tc in &opts.tcs {
                for (m, &method) in METHODS.iter().enumerate() {
                    let mut total = CycleTotals::default();
                    let mut queue = QueueTotals::default();
                    let (mut n, mut s_sum, mut adlc_sum) = (0usize, 0.0, 0.0);
                    for (job, outcome) in jobs.iter().zip(&outcomes) {
                        if job.method != m || job.tc != tc || job.cache != cache {
                            continue;
                        }
                        match (job.what, outcome) {
                            (Run::Source(k), Outcome::Source(h, model, inorder)) if sources[k].0 == i => {
                                total.add(h, model, tc, *inorder);
                                let trace = &schedules[k][m].trace;
                                s_sum += trace.stats.leaving_fraction();
                                adlc_sum += trace.counters.adlc_true;
                                n += 1;
                            }
                            (Run::Queue(l), Outcome::Queue(q)) if l == i => queue = *q,
                            _ => {}
                        }
                    }
                    let nf = n.max(1) as f64;
                    rows.push(CycleRow {
                        length,
                        method,
                        tc,
                        cache,
                        sources: n,
                        total,
                        queue,
                        s_measured: (method != Method::Conventional).then(|| s_sum / nf),
                        adlc_true: adlc_sum / nf,
                    });
                }
            }
        }
    }
    Ok((rows, jobs.len()))
}

/// The CSV header of `cycles.csv`.
pub const CSV_HEADER: &str = "length,method,tc,cache_lines,sources,cycles,intersection_busy_cycles,\
pipeline_efficiency,stall_cycles,drain_cycles,sectors,patch_loads,memory_loads,cache_hits,passed,ray_slots,\
tests,live_runs,bound_cycles,s_measured,adlc_true,speedup,speedup_vs_shared_conventional,predicted_speedup,\
predicted_branch,queue_cycles,queue_pipeline_efficiency,queue_memory_loads,queue_bound_cycles,\
inorder_bound_cycles";

/// The text of `cycles.csv`: per-source means (pipeline efficiency over all cycles of the row);
/// `cache_lines` 0 is the shared memory without cache. `speedup` is the conventional technique's
/// cycles (same `T_c` and cache setting) over the row's; `speedup_vs_shared_conventional` the
/// conventional technique's without the cache over the row's; `predicted_speedup` is Eq. 10 for
/// rows without the cache and Eq. 10's compute branch (Eq. 11) for rows with it, to be read
/// beside `speedup_vs_shared_conventional` ([`prediction`]). The `queue_*` columns are the
/// same sources run back to back on one PE ([`QueueTotals`]), also per source.
pub fn csv(rows: &[CycleRow]) -> String {
    let sp = speedups(rows);
    let mut out = format!("{CSV_HEADER}\n");
    for r in rows {
        let t = &r.total;
        let mut cols = vec![
            csv_num(r.length),
            r.method.name().to_string(),
            r.tc.to_string(),
            r.cache.unwrap_or(0).to_string(),
            r.sources.to_string(),
        ];
        for v in [t.cycles, t.intersection_busy_cycles] {
            cols.push(csv_num(r.mean(v)));
        }
        cols.push(csv_num(r.pipeline_efficiency()));
        for v in [
            t.stall_cycles,
            t.drain_cycles,
            t.sectors,
            t.patch_loads,
            t.memory_loads,
            t.cache_hits,
            t.passed,
            t.ray_slots,
            t.tests,
            t.live_runs,
            t.bound_cycles,
        ] {
            cols.push(csv_num(r.mean(v)));
        }
        cols.push(r.s_measured.map(csv_num).unwrap_or_default());
        cols.push(csv_num(r.adlc_true));
        let (same, paper) = if r.cache.is_some() {
            (speedup_of(&sp, r, Scenario::Cached), speedup_of(&sp, r, Scenario::PaperCache))
        } else {
            let s = speedup_of(&sp, r, Scenario::Shared);
            (s, s)
        };
        let conventional = r.method == Method::Conventional;
        let num = |s: Option<Speedup>| s.map(|s| csv_num(s.measured)).unwrap_or_default();
        cols.push(if conventional { "1".into() } else { num(same) });
        cols.push(if conventional && r.cache.is_none() { "1".into() } else { num(paper) });
        let pred = paper.and_then(|s| s.predicted);
        cols.push(pred.map(|p| csv_num(p.value)).unwrap_or_default());
        cols.push(pred.map(|p| p.branch.name().to_string()).unwrap_or_default());
        let q = &r.queue;
        cols.push(csv_num(r.mean(q.cycles)));
        cols.push(csv_num(r.queue_efficiency()));
        cols.push(csv_num(r.mean(q.memory_loads)));
        cols.push(csv_num(r.mean(q.bound_cycles)));
        cols.push(csv_num(r.mean(t.inorder_cycles)));
        out.push_str(&cols.join(","));
        out.push('\n');
    }
    out
}

/// The table of FIGURES.md ("The paper's claim, measured"), written to `cycles.md`: per length
/// and `T_c`, per-source means of the shared-memory runs, the speedups with the predictions of
/// Eqs. 10 and 11 ([`speedups`]), pipeline efficiencies and the shelling techniques' cycles over
/// the bound ([`CycleRow::overhead`]). Rows the measurement lacks are left out.
pub fn markdown(rows: &[CycleRow]) -> String {
    let sp = speedups(rows);
    let mut out = String::from(
        "| L | ADLC | S | T_c | conv. cycles | S cycles | SF S | SF D | Eq. 10 | SF S, cache | Eq. 11 \
         | SF S, both cache | eff. conv. | eff. S | eff. D | S / bound | D / bound |\n\
         |---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    let mut lengths: Vec<f64> = Vec::new();
    for r in rows {
        if !lengths.contains(&r.length) {
            lengths.push(r.length);
        }
    }
    for &l in &lengths {
        let mut tcs: Vec<u32> = Vec::new();
        for r in rows.iter().filter(|r| r.length == l) {
            if !tcs.contains(&r.tc) {
                tcs.push(r.tc);
            }
        }
        for (k, &tc) in tcs.iter().enumerate() {
            let (Some(conv), Some(s), Some(d)) = (
                find(rows, l, Method::Conventional, tc, false),
                find(rows, l, Method::Stochastic, tc, false),
                find(rows, l, Method::Deterministic, tc, false),
            ) else {
                continue;
            };
            let cached = find(rows, l, Method::Stochastic, tc, true);
            let of = |r: Option<&CycleRow>, sc| r.and_then(|r| speedup_of(&sp, r, sc));
            let sf = |x: Option<Speedup>| x.map_or_else(String::new, |x| format!("{:.1}", x.measured));
            let pred = |x: Option<Speedup>| x.and_then(|x| x.predicted);
            let shared = of(Some(s), Scenario::Shared);
            let eq10 = pred(shared).map_or_else(String::new, |p| {
                format!("{:.1} {}", p.value, if p.branch == Branch::Compute { 'c' } else { 'm' })
            });
            let paper = of(cached, Scenario::PaperCache);
            let eq11 = pred(paper).map_or_else(String::new, |p| format!("{:.1}", p.value));
            let both =
                of(cached, Scenario::Cached).map_or_else(String::new, |x| format!("{:.2}", x.measured));
            let (adlc, sm) = if k == 0 {
                (format!("{:.1}", s.adlc_true), s.s_measured.map_or_else(String::new, |v| format!("{v:.2}")))
            } else {
                (String::new(), String::new())
            };
            let cols = [
                if k == 0 { csv_num(l) } else { String::new() },
                adlc,
                sm,
                tc.to_string(),
                format!("{:.0}", conv.mean_cycles()),
                format!("{:.0}", s.mean_cycles()),
                sf(shared),
                sf(of(Some(d), Scenario::Shared)),
                eq10,
                sf(paper),
                eq11,
                both,
                format!("{:.3}", conv.pipeline_efficiency()),
                format!("{:.3}", s.pipeline_efficiency()),
                format!("{:.3}", d.pipeline_efficiency()),
                format!("{:.2}", s.overhead()),
                format!("{:.2}", d.overhead()),
            ];
            out.push_str(&format!("| {} |\n", cols.join(" | ")));
        }
    }
    out
}

/// Per length and `T_c` (in the rows' order), the shelling techniques' rows: S and D without
/// the cache, S and D with it; and whether it is the length's first. A `(length, T_c)` that
/// lacks one of the four is left out.
fn shelling_rows(rows: &[CycleRow]) -> Vec<(bool, [&CycleRow; 4])> {
    let mut out: Vec<(bool, [&CycleRow; 4])> = Vec::new();
    for r in rows.iter().filter(|r| r.method == Method::Stochastic && r.cache.is_none()) {
        let row = |m, cached| find(rows, r.length, m, r.tc, cached);
        let (Some(d), Some(sc), Some(dc)) = (
            row(Method::Deterministic, false),
            row(Method::Stochastic, true),
            row(Method::Deterministic, true),
        ) else {
            continue;
        };
        let first = out.last().is_none_or(|(_, [l, ..])| l.length != r.length);
        out.push((first, [r, d, sc, dc]));
    }
    out
}

/// The table of FIGURES.md ("Sources back to back"), written to `cycles_queue.md`: the
/// sources back to back on one PE ([`QueueTotals`]), per length and `T_c`: S's cycles per source
/// without and with the cache, and the shelling techniques' cycles over their bound and their
/// pipeline efficiency, on the shared memory and behind the cache.
pub fn queue_markdown(rows: &[CycleRow]) -> String {
    let mut out = String::from(
        "| L | T_c | S cycles | S cycles, cache | S / bound | D / bound | S / bound, cache \
         | D / bound, cache | eff. S | eff. D | eff. S, cache | eff. D, cache |\n\
         |---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for (first, [r, d, sc, dc]) in shelling_rows(rows) {
        let cols = [
            if first { csv_num(r.length) } else { String::new() },
            r.tc.to_string(),
            format!("{:.0}", r.mean(r.queue.cycles)),
            format!("{:.0}", sc.mean(sc.queue.cycles)),
            format!("{:.2}", r.queue_overhead()),
            format!("{:.2}", d.queue_overhead()),
            format!("{:.2}", sc.queue_overhead()),
            format!("{:.2}", dc.queue_overhead()),
            format!("{:.3}", r.queue_efficiency()),
            format!("{:.3}", d.queue_efficiency()),
            format!("{:.3}", sc.queue_efficiency()),
            format!("{:.3}", dc.queue_efficiency()),
        ];
        out.push_str(&format!("| {} |\n", cols.join(" | ")));
    }
    out
}

/// The table of FIGURES.md ("The PE at its bound"), written to `cycles_inorder.md`: per length
/// and `T_c`, each shelling technique's cycles over the bound (fresh PE, [`CycleRow::overhead`])
/// without and with the cache, and in parentheses the ideal in-order PE's
/// ([`CycleRow::inorder_overhead`]), with a mark where the goal (1.15) is missed.
pub fn inorder_markdown(rows: &[CycleRow]) -> String {
    let mut out =
        String::from("| L | T_c | S | D | S, cache | D, cache |\n|---:|---:|---:|---:|---:|---:|\n");
    let cell = |r: &CycleRow| {
        let miss = if r.overhead() > GOAL { " ✗" } else { "" };
        format!("{:.2} ({:.2}){miss}", r.overhead(), r.inorder_overhead())
    };
    for (first, [r, d, sc, dc]) in shelling_rows(rows) {
        let cols = [
            if first { csv_num(r.length) } else { String::new() },
            r.tc.to_string(),
            cell(r),
            cell(d),
            cell(sc),
            cell(dc),
        ];
        out.push_str(&format!("| {} |\n", cols.join(" | ")));
    }
    out
}

/// The goal for a fresh PE's cycles over the bound.
const GOAL: f64 = 1.15;

/// The table of the report.
pub(super) fn write_table(f: &mut fmt::Formatter<'_>, rows: &[CycleRow]) -> fmt::Result {
    let sp = speedups(rows);
    writeln!(
        f,
        "{:>8} {:>6} {:>4} {:<14}{:>11}{:>10}{:>7}{:>10}{:>9}{:>8}{:>9}{:>9}{:>8}{:>8}{:>9}{:>8}",
        "length",
        "cache",
        "T_c",
        "method",
        "cycles",
        "busy",
        "eff.",
        "drains",
        "loads",
        "hits",
        "/bound",
        "q/bound",
        "SF",
        "Eq.10",
        "SF shr.",
        "Eq.11"
    )?;
    for r in rows {
        let t = &r.total;
        let opt = |s: Option<f64>| s.map_or_else(|| "-".to_string(), |v| format!("{v:.2}"));
        let (same, paper) = if r.cache.is_some() {
            (speedup_of(&sp, r, Scenario::Cached), speedup_of(&sp, r, Scenario::PaperCache))
        } else {
            (speedup_of(&sp, r, Scenario::Shared), None)
        };
        writeln!(
            f,
            "{:>8} {:>6} {:>4} {:<14}{:>11.0}{:>10.0}{:>7.3}{:>10.0}{:>9.0}{:>8.0}{:>9.2}{:>9.2}{:>8}{:>8}{:>9}{:>8}",
            r.length,
            r.cache.map_or_else(|| "off".to_string(), |l| l.to_string()),
            r.tc,
            r.method.name(),
            r.mean_cycles(),
            r.mean(t.intersection_busy_cycles),
            r.pipeline_efficiency(),
            r.mean(t.drain_cycles),
            r.mean(t.memory_loads),
            r.mean(t.cache_hits),
            r.overhead(),
            r.queue_overhead(),
            opt(same.map(|s| s.measured)),
            opt(if r.cache.is_none() { same.and_then(|s| s.predicted).map(|p| p.value) } else { None }),
            opt(paper.map(|s| s.measured)),
            opt(paper.and_then(|s| s.predicted).map(|p| p.value)),
        )?;
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Plots
// ---------------------------------------------------------------------------------------------

/// One colour per `T_c` (in the order of [`FigureOptions::tcs`], repeating after six).
pub(super) const TC_COLORS: [RGBColor; 6] = [
    RGBColor(0x1f, 0x77, 0xb4),
    RGBColor(0xff, 0x7f, 0x0e),
    RGBColor(0x2c, 0xa0, 0x2c),
    RGBColor(0xd6, 0x27, 0x28),
    RGBColor(0x94, 0x67, 0xbd),
    RGBColor(0x8c, 0x56, 0x4b),
];

pub(super) fn short(m: Method) -> &'static str {
    match m {
        Method::Conventional => "conv.",
        Method::Stochastic => "S",
        Method::Deterministic => "D",
        Method::Brute => "brute",
    }
}

/// Size of the cycle charts (many series: room for the legend).
const SIZE: (u32, u32) = (1040, 760);

/// The cycle figures as `(file name, SVG text)`.
pub(super) fn svgs(opts: &FigureOptions, rows: &[CycleRow]) -> Result<Vec<(&'static str, String)>> {
    let mut lengths = opts.lengths.clone();
    lengths.sort_by(f64::total_cmp);
    let sp = speedups(rows);
    let workload = format!(
        "N = {}, R = {}, {} source{}/length",
        opts.count,
        opts.rays,
        opts.cosim_sources,
        if opts.cosim_sources == 1 { "" } else { "s" }
    );
    let cache_name = format!("{}-line patch cache", opts.cache_lines);
    let chart = |title: String, y_label: &str, series: Vec<Series>| Chart {
        size: SIZE,
        title: format!("{title} ({workload})"),
        x_label: "segment length L (log₂ scale)".to_string(),
        y_label: y_label.to_string(),
        x: XAxis::Log2(lengths.clone()),
        series,
    };
    let color = |ti: usize| TC_COLORS[ti % TC_COLORS.len()];
    let tc_label = |tc: u32| format!("T_c = {}", tick_label(tc as f64));
    let sorted = |mut v: Vec<(f64, f64)>| {
        v.sort_by(|a, b| a.0.total_cmp(&b.0));
        v
    };

    // Per-row charts: one series per (T_c, technique).
    let per_row = |cached: bool, value: &dyn Fn(&CycleRow) -> f64| -> Vec<Series> {
        let mut out = Vec::new();
        for (ti, &tc) in opts.tcs.iter().enumerate() {
            for &m in &METHODS {
                let pts = sorted(
                    rows.iter()
                        .filter(|r| r.method == m && r.tc == tc && r.cache.is_some() == cached)
                        .map(|r| (r.length, value(r)))
                        .collect(),
                );
                out.push(Series::new(
                    format!("{} {}", short(m), tc_label(tc)),
                    pts,
                    color(ti),
                    method_marker(m),
                ));
            }
        }
        out
    };
    // Speedup charts: S and D per T_c, and the prediction (dashed) where there is one.
    let speedup_series = |scenario: Scenario, model: &str| -> Vec<Series> {
        let mut out = Vec::new();
        for (ti, &tc) in opts.tcs.iter().enumerate() {
            for &m in &METHODS[1..] {
                let pts = sorted(
                    sp.iter()
                        .filter(|s| s.scenario == scenario && s.method == m && s.tc == tc)
                        .map(|s| (s.length, s.measured))
                        .collect(),
                );
                out.push(Series::new(
                    format!("{} {}", short(m), tc_label(tc)),
                    pts,
                    color(ti),
                    method_marker(m),
                ));
            }
            let pred = sorted(
                sp.iter()
                    .filter(|s| s.scenario == scenario && s.method == Method::Stochastic && s.tc == tc)
                    .filter_map(|s| s.predicted.map(|p| (s.length, p.value)))
                    .collect(),
            );
            if !pred.is_empty() {
                let mut p = Series::new(format!("{model} {}", tc_label(tc)), pred, color(ti), Marker::None);
                p.dashed = true;
                out.push(p);
            }
        }
        out
    };

    let mut out = Vec::new();
    out.push((
        "cycles_total_shared.svg",
        render(&chart(
            "Cycles per source, shared memory".into(),
            "PE cycles per source",
            per_row(false, &|r| r.mean_cycles()),
        ))?,
    ));
    out.push((
        "cycles_total_cache.svg",
        render(&chart(
            format!("Cycles per source, {cache_name}"),
            "PE cycles per source",
            per_row(true, &|r| r.mean_cycles()),
        ))?,
    ));
    out.push((
        "cycles_speedup_shared.svg",
        render(&chart(
            "Speedup over conventional, shared memory; Eq. 10 dashed".into(),
            "conventional cycles / shelling cycles",
            speedup_series(Scenario::Shared, "Eq. 10"),
        ))?,
    ));
    out.push((
        "cycles_speedup_paper_cache.svg",
        render(&chart(
            "Speedup, shelling with cache over conventional without; Eq. 11 dashed".into(),
            "conventional (no cache) cycles / shelling (cache) cycles",
            speedup_series(Scenario::PaperCache, "Eq. 11"),
        ))?,
    ));
    out.push((
        "cycles_speedup_cache.svg",
        render(&chart(
            format!("Speedup over conventional, both with a {cache_name}"),
            "conventional cycles / shelling cycles",
            speedup_series(Scenario::Cached, ""),
        ))?,
    ));
    out.push((
        "cycles_efficiency_shared.svg",
        render(&chart(
            "Pipeline efficiency, shared memory".into(),
            "intersection busy cycles / cycles",
            per_row(false, &|r| r.pipeline_efficiency()),
        ))?,
    ));
    out.push((
        "cycles_efficiency_cache.svg",
        render(&chart(
            format!("Pipeline efficiency, {cache_name}"),
            "intersection busy cycles / cycles",
            per_row(true, &|r| r.pipeline_efficiency()),
        ))?,
    ));
    Ok(out)
}

/// The SVG files the cycle figures write, in order.
pub const SVGS: [&str; 7] = [
    "cycles_total_shared.svg",
    "cycles_total_cache.svg",
    "cycles_speedup_shared.svg",
    "cycles_speedup_paper_cache.svg",
    "cycles_speedup_cache.svg",
    "cycles_efficiency_shared.svg",
    "cycles_efficiency_cache.svg",
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn predictions_follow_eqs_10_and_11() {
        // ADLC 32, S 0.5: compute-bound below T_c = 32, memory-bound from there.
        let p = prediction(Scenario::Shared, 0.5, 32.0, 16).unwrap();
        assert_eq!(p.branch, Branch::Compute);
        assert!((p.value - (1.0 + 0.5 / 32.0) * 16.0).abs() < 1e-12);
        let p = prediction(Scenario::Shared, 0.5, 32.0, 32).unwrap();
        assert_eq!(p.branch, Branch::Memory);
        assert!((p.value - 32.5).abs() < 1e-12);
        // The cache: the compute branch at every T_c; T_c/T_λ at S = 0 (Eq. 11).
        let p = prediction(Scenario::PaperCache, 0.5, 32.0, 64).unwrap();
        assert_eq!(p.branch, Branch::Compute);
        assert!((p.value - (1.0 + 0.5 / 32.0) * 64.0).abs() < 1e-12);
        assert_eq!(prediction(Scenario::PaperCache, 0.0, 8.0, 64).unwrap().value, 64.0);
        assert_eq!(prediction(Scenario::Shared, 0.0, 8.0, 64).unwrap().value, 8.0);
        assert!(prediction(Scenario::Cached, 0.5, 32.0, 16).is_none());
        assert!(prediction(Scenario::Shared, 1.0, 32.0, 16).is_none());
        assert!(prediction(Scenario::Shared, 0.5, 0.0, 16).is_none());
    }
}
