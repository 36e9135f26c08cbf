//! Reproduction of the paper's Section 5: the measured counters of the conventional technique and
//! the two shelling techniques against the segment length (Figures 8, 9, 10, 11 and 13), and the
//! analytic `K₁(S)` of Eq. 4 with the measured `S` marked on it (Figure 7).
//!
//! The workload: for every segment length `L` and every seed, a scene of `count` random segments
//! of length `L` in the paper's world ([`crate::scene::PAPER_WORLD`]); in each scene `sources`
//! source patches spread evenly over the patch indices (`k = i·count/sources`); from each source a
//! bundle of `rays` rays traced by [`Method::Conventional`], [`Method::Stochastic`] and
//! [`Method::Deterministic`] (brute force is left out: it is the tests' oracle and far too slow).
//! Every counter is averaged over all `(scene, source)` pairs of a length: one [`Row`] per length
//! and technique.
//!
//! Scene seeds are deterministic: the scene of the `i`-th length of [`FigureOptions::lengths`]
//! (0-based, in the order given) and seed number `s` (`0..seeds`) is generated with the seed
//! [`scene_seed`]`(i, s) = 1000·i + s`; hence at most 1000 seeds per length. The jobs run in
//! parallel (rayon) but their results are summed in a fixed order, so the output does not depend
//! on the number of threads.
//!
//! [`run`] writes `figures.csv` and one SVG per figure into [`FigureOptions::out`].
//!
//! With [`FigureOptions::cosim_sources`] above zero, [`run`] also co-simulates a sample of the
//! sources on the RTL processing element for every host memory load time of
//! [`FigureOptions::tcs`], without and with the PE's patch cache, and writes the cycle counts
//! beside the speedup the paper's Eqs. 10–11 predict ([`cycles`]: `cycles.csv` and the
//! `cycles_*.svg` plots).

use crate::cosim::Engine;
use crate::counters::Counters;
use crate::grid::GridParams;
use crate::rays::{RaySet, MAX_BUNDLE_RAYS};
use crate::run::GriddedScene;
use crate::scene;
use crate::staged::Staged;
use crate::trace::{Method, ShellParams, ShellStats};
use anyhow::{anyhow, bail, Context, Result};
use plot::{method_color, method_marker, render, tick_label, Chart, Marker, Series, XAxis, CHART_SIZE, GREY};
use rayon::prelude::*;
use std::fmt;
use std::path::PathBuf;
use std::time::{Duration, Instant};

pub mod cycles;
pub mod d3;
pub mod machine;
mod plot;
pub mod stalls;

/// The techniques measured, in row order.
pub const METHODS: [Method; 3] = [Method::Conventional, Method::Stochastic, Method::Deterministic];

/// The most seeds per length that [`scene_seed`] keeps distinct.
pub const MAX_SEEDS: usize = 1000;

/// The seed of the scene of the `length_index`-th length (0-based) and seed number `seed`.
pub fn scene_seed(length_index: usize, seed: usize) -> u64 {
    1000 * length_index as u64 + seed as u64
}

/// The source patches of a scene of `count` segments: `sources` indices spread evenly,
/// `k = i·count/sources` for `i` in `0..sources` (distinct when `sources <= count`).
pub fn source_patches(count: usize, sources: usize) -> Vec<usize> {
    (0..sources).map(|i| (i as u128 * count as u128 / sources as u128) as usize).collect()
}

/// What to measure and where to write it.
#[derive(Clone, Debug)]
pub struct FigureOptions {
    /// Output directory (created if missing).
    pub out: PathBuf,
    /// Scenes per length.
    pub seeds: usize,
    /// Source patches per scene.
    pub sources: usize,
    /// Rays per source.
    pub rays: usize,
    /// Segments per scene.
    pub count: usize,
    /// Segment lengths.
    pub lengths: Vec<f64>,
    pub ray_set: RaySet,
    pub grid: GridParams,
    pub shells: ShellParams,
    /// Show a progress bar on standard error.
    pub progress: bool,
    /// Sources co-simulated on the processing element per segment length: the first seed's
    /// scene, `source_patches(count, cosim_sources)`. Zero skips the cycle-accurate figures.
    pub cosim_sources: usize,
    /// Host memory load times `T_c` (cycles per patch) co-simulated.
    pub tcs: Vec<u32>,
    /// Lines of the PE's patch cache in the runs with the cache (1 to 1024).
    pub cache_lines: u32,
    /// The simulator of the co-simulations.
    pub engine: Engine,
}

impl FigureOptions {
    /// Checks the options; the message names the offending one.
    pub fn validate(&self) -> Result<()> {
        if self.seeds == 0 || self.seeds > MAX_SEEDS {
            bail!("seeds must be between 1 and {MAX_SEEDS}, got {}", self.seeds);
        }
        if self.count == 0 {
            bail!("count (segments per scene) must be at least 1");
        }
        if self.sources == 0 {
            bail!("sources (source patches per scene) must be at least 1");
        }
        if self.sources > self.count {
            bail!(
                "sources ({}) cannot exceed the number of segments per scene ({})",
                self.sources,
                self.count
            );
        }
        if self.rays == 0 || self.rays > MAX_BUNDLE_RAYS {
            bail!("rays must be between 1 and {MAX_BUNDLE_RAYS}, got {}", self.rays);
        }
        if self.lengths.is_empty() {
            bail!("at least one segment length is needed");
        }
        for (i, &l) in self.lengths.iter().enumerate() {
            if !(l.is_finite() && l > 0.0) {
                bail!("segment lengths must be positive finite numbers, got {l}");
            }
            if self.lengths[..i].contains(&l) {
                bail!("segment length {l} is listed twice");
            }
        }
        if !(self.grid.cells_per_segment.is_finite() && self.grid.cells_per_segment > 0.0) {
            bail!("cells per segment must be a positive number, got {}", self.grid.cells_per_segment);
        }
        if self.grid.cells_per_axis == Some(0) {
            bail!("cells per axis must be at least 1");
        }
        self.shells.validate().map_err(|e| anyhow!("{e}"))?;
        if self.cosim_sources > 0 {
            cycles::validate(self)?;
        }
        Ok(())
    }
}

/// The measurement of one technique at one segment length, averaged over all sources.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    pub length: f64,
    pub method: Method,
    /// Number of `(scene, source)` pairs averaged: `seeds × sources`.
    pub sources: usize,
    /// Per-source mean of each counter; the integer counters rounded to the nearest integer
    /// (see [`Row::mean_values`] for the exact means).
    pub mean: Counters,
    /// The counters summed over all sources (the ADLC fields too).
    pub total: Counters,
    /// Mean over sources of [`ShellStats::leaving_fraction`]; shelling techniques only.
    pub s_measured: Option<f64>,
    /// Mean number of sectors per source (0 for the conventional technique).
    pub mean_sectors: f64,
    /// Mean number of shells per source (0 for the conventional technique).
    pub mean_shells: f64,
}

impl Row {
    /// Exact per-source means of the counters, in [`Counters::NAMES`] order.
    pub fn mean_values(&self) -> [f64; 7] {
        self.total.exact_means(self.sources)
    }

    /// The exact per-source mean of the counter named `name` (one of [`Counters::NAMES`]).
    pub fn mean_of(&self, name: &str) -> Option<f64> {
        self.total.exact_mean_of(self.sources, name)
    }
}

/// What [`run`] did.
#[derive(Clone, Debug)]
pub struct FigureReport {
    pub options: FigureOptions,
    pub rows: Vec<Row>,
    /// Files written, in order.
    pub files: Vec<PathBuf>,
    /// Scenes generated.
    pub scenes: usize,
    /// `(scene, source)` jobs traced (each by the three techniques).
    pub jobs: usize,
    /// Rays on which a shelling technique's nearest hit differed from the conventional one's
    /// (expected 0: all techniques share one hit definition).
    pub disagreements: u64,
    /// Wall time of the measurement.
    pub elapsed: Duration,
    /// The co-simulated cycle counts (empty when [`FigureOptions::cosim_sources`] is 0), in the
    /// order of [`cycles::measure`].
    pub cycles: Vec<cycles::CycleRow>,
    /// Co-simulation runs (source × technique × `T_c` × cache setting).
    pub cosim_runs: usize,
    /// Wall time of the co-simulations.
    pub cosim_elapsed: Duration,
}

impl fmt::Display for FigureReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let o = &self.options;
        writeln!(
            f,
            "{} scenes ({} lengths × {} seeds) of {} segments, {} sources each, {} rays per source ({} set): \
             {} jobs in {:.2} s",
            self.scenes,
            o.lengths.len(),
            o.seeds,
            o.count,
            o.sources,
            o.rays,
            o.ray_set,
            self.jobs,
            self.elapsed.as_secs_f64()
        )?;
        writeln!(f, "per-source means:")?;
        writeln!(
            f,
            "{:>8} {:<14}{:>12}{:>12}{:>12}{:>12}{:>10}{:>8}{:>10}{:>7}{:>9}{:>9}",
            "length",
            "method",
            "read before",
            "read after",
            "cells",
            "tests",
            "actual",
            "ADLC",
            "ADLC est.",
            "S",
            "sectors",
            "shells"
        )?;
        for r in &self.rows {
            let v = r.mean_values();
            let s = r.s_measured.map_or_else(|| "-".to_string(), |s| format!("{s:.3}"));
            writeln!(
                f,
                "{:>8} {:<14}{:>12.1}{:>12.1}{:>12.1}{:>12.1}{:>10.1}{:>8.2}{:>10.2}{:>7}{:>9.1}{:>9.1}",
                r.length,
                r.method.name(),
                v[0],
                v[1],
                v[2],
                v[3],
                v[4],
                v[5],
                v[6],
                s,
                r.mean_sectors,
                r.mean_shells
            )?;
        }
        if !self.cycles.is_empty() {
            writeln!(
                f,
                "co-simulation: {} sources per length, {} runs in {:.1} s ({} simulation); per-source means:",
                o.cosim_sources,
                self.cosim_runs,
                self.cosim_elapsed.as_secs_f64(),
                o.engine.name()
            )?;
            cycles::write_table(f, &self.cycles)?;
        }
        if self.disagreements > 0 {
            writeln!(
                f,
                "WARNING: {} rays where a shelling technique's hit differs from the conventional one",
                self.disagreements
            )?;
        }
        writeln!(f, "files written:")?;
        for p in &self.files {
            writeln!(f, "  {}", p.display())?;
        }
        Ok(())
    }
}

/// Counters and shell statistics of one `(scene, source)` job, per technique of [`METHODS`].
struct JobResult {
    length_index: usize,
    per_method: [(Counters, ShellStats); 3],
    disagreements: u64,
}

/// Runs the workload; returns the rows (one per length and technique) and the number of rays on
/// which the shelling techniques disagreed with the conventional one.
fn measure_inner(opts: &FigureOptions) -> Result<(Vec<Row>, usize, usize, u64)> {
    opts.validate()?;

    // Build every scene once (in parallel).
    let specs: Vec<(usize, usize)> =
        (0..opts.lengths.len()).flat_map(|i| (0..opts.seeds).map(move |s| (i, s))).collect();
    let scenes: Vec<(usize, GriddedScene)> = specs
        .par_iter()
        .map(|&(i, s)| {
            let length = opts.lengths[i];
            let seed = scene_seed(i, s);
            let sc = scene::generate(opts.count, length, seed, scene::PAPER_WORLD)
                .map_err(|e| anyhow!("generating the scene of length {length}, seed {seed}: {e}"))?;
            Ok((i, GriddedScene::new(sc, opts.grid)))
        })
        .collect::<Result<_>>()?;

    let jobs: Vec<(usize, usize)> = scenes
        .iter()
        .enumerate()
        .flat_map(|(j, (_, p))| {
            source_patches(p.scene.segments.len(), opts.sources).into_iter().map(move |k| (j, k))
        })
        .collect();

    let bar = if opts.progress {
        let b = indicatif::ProgressBar::new(jobs.len() as u64);
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "tracing {bar:40} {pos}/{len} sources [{elapsed_precise}, eta {eta}]",
        ) {
            b.set_style(style);
        }
        b
    } else {
        indicatif::ProgressBar::hidden()
    };

    let results: Vec<JobResult> = jobs
        .par_iter()
        .map(|&(j, k)| {
            let (length_index, prepared) = &scenes[j];
            let bundle = prepared.patch_bundle(k, opts.ray_set, opts.rays).map_err(|e| {
                anyhow!("source patch {k} of a scene of length {}: {e}", opts.lengths[*length_index])
            })?;
            let [a, b, c] = METHODS.map(|m| prepared.trace(m, &bundle, &opts.shells));
            let traced = [a?, b?, c?];
            let disagreements = traced[1..]
                .iter()
                .map(|t| t.hits.iter().zip(&traced[0].hits).filter(|(a, b)| a != b).count() as u64)
                .sum();
            bar.inc(1);
            Ok(JobResult {
                length_index: *length_index,
                per_method: traced.map(|t| (t.counters, t.stats)),
                disagreements,
            })
        })
        .collect::<Result<_>>()?;
    bar.finish_and_clear();

    // Sum in job order (deterministic), then average.
    #[derive(Default, Clone, Copy)]
    struct Acc {
        total: Counters,
        s_sum: f64,
        sectors: u64,
        shells: u64,
        n: usize,
    }
    let mut acc = vec![[Acc::default(); 3]; opts.lengths.len()];
    let mut disagreements = 0;
    for r in &results {
        disagreements += r.disagreements;
        for (a, (c, st)) in acc[r.length_index].iter_mut().zip(&r.per_method) {
            a.total += *c;
            a.s_sum += st.leaving_fraction();
            a.sectors += st.sectors;
            a.shells += st.shells;
            a.n += 1;
        }
    }
    let mut rows = Vec::with_capacity(opts.lengths.len() * METHODS.len());
    for (i, &length) in opts.lengths.iter().enumerate() {
        for (m, a) in METHODS.iter().zip(&acc[i]) {
            let n = a.n.max(1) as f64;
            let t = a.total;
            let mean = t.mean(n);
            let shelling = *m != Method::Conventional;
            rows.push(Row {
                length,
                method: *m,
                sources: a.n,
                mean,
                total: t,
                s_measured: shelling.then(|| a.s_sum / n),
                mean_sectors: a.sectors as f64 / n,
                mean_shells: a.shells as f64 / n,
            });
        }
    }
    Ok((rows, scenes.len(), jobs.len(), disagreements))
}

/// Runs the Section 5 workload and returns one row per length (in the order of
/// [`FigureOptions::lengths`]) and technique (in the order of [`METHODS`]). Writes nothing.
pub fn measure(opts: &FigureOptions) -> Result<Vec<Row>> {
    Ok(measure_inner(opts)?.0)
}

/// Runs the workload and writes `figures.csv` and the SVG figures into `opts.out`.
pub fn run(opts: &FigureOptions) -> Result<FigureReport> {
    let start = Instant::now();
    opts.validate()?;
    // The files are written into a temporary directory beside `out` and moved into place at
    // the end: a failed run leaves no partial figures.
    let staged = Staged::dir(&opts.out)
        .with_context(|| format!("creating the output directory {}", opts.out.display()))?;
    let (rows, scenes, jobs, disagreements) = measure_inner(opts)?;
    let elapsed = start.elapsed();
    let mut files = Vec::new();
    let mut write = |name: &str, text: String| -> Result<()> {
        let path = staged.path().join(name);
        let shown = opts.out.join(name);
        std::fs::write(&path, text).with_context(|| format!("writing {}", shown.display()))?;
        files.push(shown);
        Ok(())
    };
    write("figures.csv", csv(&rows))?;
    for (name, svg) in figure_svgs(opts, &rows)? {
        write(name, svg)?;
    }
    let (cycle_rows, cosim_runs, cosim_elapsed) = if opts.cosim_sources > 0 {
        let start = Instant::now();
        let (cycle_rows, runs) = cycles::measure_runs(opts)?;
        let cosim_elapsed = start.elapsed();
        write("cycles.csv", cycles::csv(&cycle_rows))?;
        write("cycles.md", cycles::markdown(&cycle_rows))?;
        write("cycles_queue.md", cycles::queue_markdown(&cycle_rows))?;
        write("cycles_inorder.md", cycles::inorder_markdown(&cycle_rows))?;
        for (name, svg) in cycles::svgs(opts, &cycle_rows)? {
            write(name, svg)?;
        }
        (cycle_rows, runs, cosim_elapsed)
    } else {
        (Vec::new(), 0, Duration::ZERO)
    };
    staged.commit().with_context(|| format!("moving the figures into {}", opts.out.display()))?;
    Ok(FigureReport {
        options: opts.clone(),
        rows,
        files,
        scenes,
        jobs,
        disagreements,
        elapsed,
        cycles: cycle_rows,
        cosim_runs,
        cosim_elapsed,
    })
}

/// Formats a number for the CSV: at most 6 decimals, no trailing zeros.
fn csv_num(v: f64) -> String {
    let s = format!("{v:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.into()
    }
}

/// The CSV text: header, then one line per row.
fn csv(rows: &[Row]) -> String {
    let mut out = format!("length,method,sources,{},s_measured,sectors,shells\n", Counters::NAMES.join(","));
    for r in rows {
        let mut cols = vec![csv_num(r.length), r.method.name().to_string(), r.sources.to_string()];
        cols.extend(r.mean_values().iter().map(|&v| csv_num(v)));
        cols.push(r.s_measured.map(csv_num).unwrap_or_default());
        cols.push(csv_num(r.mean_sectors));
        cols.push(csv_num(r.mean_shells));
        out.push_str(&cols.join(","));
        out.push('\n');
    }
    out
}

// ---------------------------------------------------------------------------------------------
// Figures
// ---------------------------------------------------------------------------------------------

/// The rows of technique `m`, sorted by length.
fn rows_of(rows: &[Row], m: Method) -> Vec<&Row> {
    let mut v: Vec<&Row> = rows.iter().filter(|r| r.method == m).collect();
    v.sort_by(|a, b| a.length.total_cmp(&b.length));
    v
}

/// `(length, mean of counter i)` for technique `m`.
fn counter_points(rows: &[Row], m: Method, i: usize) -> Vec<(f64, f64)> {
    rows_of(rows, m).iter().map(|r| (r.length, r.mean_values()[i])).collect()
}

/// The six figures as `(file name, SVG text)`.
fn figure_svgs(opts: &FigureOptions, rows: &[Row]) -> Result<Vec<(&'static str, String)>> {
    let mut lengths = opts.lengths.clone();
    lengths.sort_by(f64::total_cmp);
    let workload =
        format!("N = {}, R = {}, {} sources × {} seeds", opts.count, opts.rays, opts.sources, opts.seeds);
    let x_label = "segment length L (log₂ scale)".to_string();
    let per_method = |i: usize| -> Vec<Series> {
        METHODS
            .iter()
            .map(|&m| Series::new(m.name(), counter_points(rows, m, i), method_color(m), method_marker(m)))
            .collect()
    };
    let chart = |title: &str, y_label: &str, series: Vec<Series>| Chart {
        size: CHART_SIZE,
        title: format!("{title} ({workload})"),
        x_label: x_label.clone(),
        y_label: y_label.to_string(),
        x: XAxis::Log2(lengths.clone()),
        series,
    };

    let mut out = Vec::new();
    out.push((
        "fig08_patches_read_before_screening.svg",
        render(&chart(
            "Fig. 8: patches read before screening",
            "patches read before screening per source",
            per_method(0),
        ))?,
    ));
    out.push((
        "fig09_patches_read_after_screening.svg",
        render(&chart(
            "Fig. 9: patches read after screening",
            "patches read after screening per source",
            per_method(1),
        ))?,
    ));
    out.push((
        "fig10_cells_traversed.svg",
        render(&chart("Fig. 10: cells traversed", "cells traversed per source", per_method(2)))?,
    ));
    let mut s11 = per_method(3);
    let mut actual = Series::new(
        "actual intersections",
        counter_points(rows, Method::Conventional, 4),
        GREY,
        Marker::Cross,
    );
    actual.line = true;
    s11.push(actual);
    out.push((
        "fig11_intersection_computations.svg",
        render(&chart("Fig. 11: intersection computations", "ray-patch intersection tests per source", s11))?,
    ));
    let s13 = vec![
        Series::new(
            "ADLC true (all methods)",
            counter_points(rows, Method::Conventional, 5),
            GREY,
            Marker::Cross,
        ),
        Series::new(
            "ADLC estimated: stochastic",
            counter_points(rows, Method::Stochastic, 6),
            method_color(Method::Stochastic),
            method_marker(Method::Stochastic),
        ),
        Series::new(
            "ADLC estimated: deterministic",
            counter_points(rows, Method::Deterministic, 6),
            method_color(Method::Deterministic),
            method_marker(Method::Deterministic),
        ),
    ];
    out.push((
        "fig13_adlc.svg",
        render(&chart(
            "Fig. 13: average degree of local coherence",
            "ADLC (rays per distinct patch hit)",
            s13,
        ))?,
    ));
    out.push(("fig07_k1.svg", render(&k1_chart(rows, &workload)?)?));
    Ok(out)
}

/// Figure 7: the curve `K₁(S)` with the measured `S` of the stochastic runs marked on it.
fn k1_chart(rows: &[Row], workload: &str) -> Result<Chart> {
    let measured: Vec<(f64, f64)> = rows_of(rows, Method::Stochastic)
        .iter()
        .filter_map(|r| r.s_measured.map(|s| (r.length, s)))
        .filter(|(_, s)| crate::model::k1(*s).is_ok())
        .collect();
    let s_max = measured.iter().map(|m| m.1).fold(0.95f64, f64::max).min(0.99);
    let steps = 400;
    let curve: Vec<(f64, f64)> = (0..=steps)
        .map(|i| {
            let s = s_max * i as f64 / steps as f64;
            crate::model::k1(s).map(|k| (s, k))
        })
        .collect::<Result<_, _>>()
        .map_err(|e| anyhow!("evaluating K1: {e}"))?;
    let mut curve = Series::new("K₁(S) = (1+S²)/(1−S²)³", curve, GREY, Marker::None);
    curve.line = true;
    let mut points = Vec::new();
    let mut labels = Vec::new();
    for (l, s) in &measured {
        let k = crate::model::k1(*s).map_err(|e| anyhow!("evaluating K1: {e}"))?;
        points.push((*s, k));
        labels.push(format!("L={} (S={s:.3})", tick_label(*l)));
    }
    let mut marks =
        Series::new("measured S (stochastic)", points, method_color(Method::Stochastic), Marker::Circle);
    marks.line = false;
    marks.point_labels = labels;
    Ok(Chart {
        size: CHART_SIZE,
        title: format!("Fig. 7: K₁(S) with the measured S ({workload})"),
        x_label: "S (fraction of rays leaving a shell)".into(),
        y_label: "K₁(S)".into(),
        x: XAxis::Linear(0.0, 1.0),
        series: vec![curve, marks],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tiny(out: PathBuf) -> FigureOptions {
        FigureOptions {
            out,
            seeds: 1,
            sources: 3,
            rays: 64,
            count: 200,
            lengths: vec![8.0, 64.0],
            ray_set: RaySet::Angle,
            grid: GridParams::default(),
            shells: ShellParams::default(),
            progress: false,
            cosim_sources: 0,
            engine: Engine::RustHdl,
            tcs: vec![1, 16],
            cache_lines: 1024,
        }
    }

    fn temp_dir(tag: &str) -> PathBuf {
        let nanos = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map(|d| d.as_nanos())
            .unwrap_or(0);
        std::env::temp_dir().join(format!("shelling-figures-{tag}-{}-{nanos}", std::process::id()))
    }

    const SVGS: [&str; 6] = [
        "fig08_patches_read_before_screening.svg",
        "fig09_patches_read_after_screening.svg",
        "fig10_cells_traversed.svg",
        "fig11_intersection_computations.svg",
        "fig13_adlc.svg",
        "fig07_k1.svg",
    ];

    #[test]
    fn tiny_run_writes_csv_and_svgs() {
        let dir = temp_dir("run");
        let opts = tiny(dir.clone());
        let report = run(&opts).expect("tiny run");
        assert_eq!(report.rows.len(), 6);
        assert_eq!(report.disagreements, 0, "shelling hits differ from conventional ones");

        let csv = std::fs::read_to_string(dir.join("figures.csv")).expect("csv");
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines.len(), 1 + 2 * 3);
        assert_eq!(
            lines[0],
            "length,method,sources,patches_read_before_screening,patches_read_after_screening,\
             cells_traversed,intersection_computations,actual_intersections,adlc_true,adlc_estimated,\
             s_measured,sectors,shells"
        );
        for line in &lines[1..] {
            let cols: Vec<&str> = line.split(',').collect();
            assert_eq!(cols.len(), 13, "{line}");
            assert_eq!(cols[1] == "conventional", cols[10].is_empty(), "{line}");
        }

        for name in SVGS {
            let p = dir.join(name);
            let text = std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
            assert!(text.contains("<svg"), "{name} is not an SVG");
            assert!(text.contains("<text"), "{name} has no text");
            assert!(report.files.contains(&p));
        }
        let fig11 = std::fs::read_to_string(dir.join(SVGS[3])).unwrap();
        for label in ["conventional", "stochastic", "deterministic", "actual intersections"] {
            assert!(fig11.contains(label), "fig 11 legend lacks {label}");
        }
        let shown = report.to_string();
        assert!(shown.contains("stochastic") && shown.contains("figures.csv"));
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn rows_satisfy_invariants() {
        let opts = tiny(temp_dir("unused"));
        let rows = measure(&opts).expect("measure");
        assert_eq!(rows.len(), 6);
        for (r, (l, m)) in
            rows.iter().zip([8.0, 64.0].iter().flat_map(|l| METHODS.iter().map(move |m| (*l, *m))))
        {
            assert_eq!((r.length, r.method), (l, m));
            assert_eq!(r.sources, 3);
            let v = r.mean_values();
            assert!(v[1] <= v[0], "{r:?}: after screening exceeds before");
            assert!(v[3] >= v[4], "{r:?}: fewer tests than actual intersections");
            assert!(r.mean.patches_read_after_screening <= r.mean.patches_read_before_screening);
            assert!(r.mean.intersection_computations >= r.mean.actual_intersections);
            match r.method {
                Method::Conventional => {
                    assert!(r.s_measured.is_none());
                    assert_eq!(r.mean.adlc_estimated, r.mean.adlc_true);
                }
                _ => {
                    let s = r.s_measured.expect("shelling rows measure S");
                    assert!((0.0..=1.0).contains(&s), "{r:?}");
                    assert!(r.mean_sectors >= 1.0 && r.mean_shells >= 1.0, "{r:?}");
                }
            }
        }
        // All techniques find the same hits: the same actual intersections and true ADLC.
        for chunk in rows.chunks(3) {
            assert!(chunk
                .iter()
                .all(|r| r.total.actual_intersections == chunk[0].total.actual_intersections));
            assert!(chunk.iter().all(|r| (r.total.adlc_true - chunk[0].total.adlc_true).abs() < 1e-9));
        }
        // Deterministic: the same options give the same rows.
        assert_eq!(measure(&opts).expect("again"), rows);
    }

    #[test]
    fn bad_options_are_errors() {
        let base = tiny(temp_dir("bad"));
        let cases: Vec<(&str, FigureOptions)> = vec![
            ("sources 0", FigureOptions { sources: 0, ..base.clone() }),
            ("seeds 0", FigureOptions { seeds: 0, ..base.clone() }),
            ("rays 0", FigureOptions { rays: 0, ..base.clone() }),
            ("count 0", FigureOptions { count: 0, ..base.clone() }),
            ("sources > count", FigureOptions { sources: 201, ..base.clone() }),
            ("no lengths", FigureOptions { lengths: vec![], ..base.clone() }),
            ("NaN length", FigureOptions { lengths: vec![8.0, f64::NAN], ..base.clone() }),
            ("zero length", FigureOptions { lengths: vec![0.0], ..base.clone() }),
            ("negative length", FigureOptions { lengths: vec![-4.0], ..base.clone() }),
            ("infinite length", FigureOptions { lengths: vec![f64::INFINITY], ..base.clone() }),
            ("duplicate length", FigureOptions { lengths: vec![8.0, 8.0], ..base.clone() }),
        ];
        for (what, o) in cases {
            assert!(measure(&o).is_err(), "{what} accepted by measure");
            assert!(run(&o).is_err(), "{what} accepted by run");
        }
        assert!(!base.out.exists(), "a rejected run created its output directory");
    }

    #[test]
    fn helpers() {
        assert_eq!(source_patches(10, 3), vec![0, 3, 6]);
        assert_eq!(source_patches(5, 5), vec![0, 1, 2, 3, 4]);
        assert_eq!(scene_seed(2, 7), 2007);
        assert_eq!(csv_num(1.5), "1.5");
        assert_eq!(csv_num(3.0), "3");
    }
}
