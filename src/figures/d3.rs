//! `shelling figures --dim 3`: the paper's Figures 8–11 and 13 on the 3D workload, both 3D
//! extensions (polar and sweep, `crate::d3`) against the conventional technique.
//!
//! The workload: for every patch size `L` and every seed, a scene of `count` random squares of
//! side `L` in `[0, 1024)³` ([`crate::d3::gen::generate`], seeded by [`super::scene_seed`] as in
//! 2D); in each scene `sources` source patches spread evenly over the indices
//! ([`super::source_patches`]); from the centre of each a hemisphere set of `rays` rays, stratified
//! `4k × k` in (Θ, Φ) (`rays = 4k²`: bands and cells of equal angle, `π/2k`, an even number of
//! bands for the sweep's planes), traced by [`METHODS3`]. Every counter is averaged over the
//! `(scene, source)` pairs of a size: one [`Row3`] per size and technique. The sweep's
//! `adlc_estimated` is the ADLC captured in its planes (`crate::d3::sweep`), which FIGURES.md
//! sets beside the true 3D ADLC.
//!
//! [`run`] writes `figures3d.csv`, `figures3d.md` (the same means as a markdown table) and the
//! charts of [`svgs`] into [`Figure3Options::out`].

use super::plot::{method_color, method_marker, render, Chart, Marker, Series, XAxis, CHART_SIZE, GREY};
use super::{csv_num, scene_seed, source_patches, MAX_SEEDS};
use crate::counters::Counters;
use crate::d3::gen::{generate, WORLD};
use crate::d3::grid::{Grid3, Grid3Params};
use crate::d3::hemisphere::{HemisphereRays, Strata};
use crate::d3::trace::{trace, Bundle3, Method3};
use crate::limits::{MAX_COUNT, MAX_LENGTHS};
use crate::staged::Staged;
use crate::trace::{Method, ShellParams};
use anyhow::{anyhow, bail, Context, Result};
use rayon::prelude::*;
use std::fmt;
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// The techniques measured, in row order.
pub const METHODS3: [Method3; 3] = [Method3::Conventional, Method3::Polar, Method3::Sweep];

/// The default patch sizes: two orders of magnitude.
pub const DEFAULT_SIZES: [f64; 8] = [2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0, 256.0];

/// The number of Θ-bands and Φ-cells of a set of `rays` rays: `(4k, k)` for `rays = 4k²`, or
/// an error naming the option and the nearest valid counts.
pub fn stratification(option: &str, rays: usize) -> Result<(usize, usize)> {
    let k = ((rays / 4) as f64).sqrt().floor() as usize;
    let k = (k.saturating_sub(1)..=k + 1).rev().find(|k| 4 * k * k <= rays).unwrap_or(0);
    if k >= 1 && 4 * k * k == rays {
        return Ok((4 * k, k));
    }
    let nearest = if k == 0 {
        "the smallest is 4".to_string()
    } else {
        format!("the nearest are {} and {}", 4 * k * k, 4 * (k + 1) * (k + 1))
    };
    bail!(
        "{option} must be 4·k² for the (Θ, Φ) stratification of 4k bands by k cells (e.g. 256 or \
         1024 = 4·16²), got {rays}; {nearest}"
    )
}

/// What to measure and where to write it.
#[derive(Clone, Debug)]
pub struct Figure3Options {
    /// Output directory (created if missing).
    pub out: PathBuf,
    /// Scenes per size.
    pub seeds: usize,
    /// Source patches per scene.
    pub sources: usize,
    /// Rays per source, `4k²`.
    pub rays: usize,
    /// Squares per scene.
    pub count: usize,
    /// Patch sizes (the squares' sides).
    pub sizes: Vec<f64>,
    /// The hemisphere set's layout of Φ-cells.
    pub strata: Strata,
    pub grid: Grid3Params,
    pub shells: ShellParams,
    /// Show a progress bar on standard error.
    pub progress: bool,
}

impl Figure3Options {
    /// Checks the options; the message names the offending one as the command line spells it.
    pub fn validate(&self) -> Result<()> {
        if self.seeds == 0 || self.seeds > MAX_SEEDS {
            bail!("--seeds must be between 1 and {MAX_SEEDS}, got {}", self.seeds);
        }
        if self.count == 0 || self.count > MAX_COUNT {
            bail!("--count must be between 1 and {MAX_COUNT}, got {}", self.count);
        }
        if self.sources == 0 || self.sources > self.count {
            bail!("--sources must be between 1 and {} (--count), got {}", self.count, self.sources);
        }
        stratification("--rays", self.rays)?;
        if self.sizes.is_empty() || self.sizes.len() > MAX_LENGTHS {
            bail!("--sizes must list 1 to {MAX_LENGTHS} sizes, got {}", self.sizes.len());
        }
        let limit = WORLD / 3f64.sqrt();
        for (i, &s) in self.sizes.iter().enumerate() {
            if !(s.is_finite() && s > 0.0 && s < limit) {
                bail!("--sizes must be greater than 0 and less than {limit:.3} (1024/√3), got {s}");
            }
            if self.sizes[..i].contains(&s) {
                bail!("--sizes lists {s} twice");
            }
        }
        if !(self.grid.cells_per_polygon.is_finite() && self.grid.cells_per_polygon > 0.0) {
            bail!("--cells-per-segment must be a positive number, got {}", self.grid.cells_per_polygon);
        }
        self.shells.validate().map_err(|e| anyhow!("{e}"))
    }
}

/// The measurement of one technique at one patch size, averaged over all sources.
#[derive(Clone, Debug, PartialEq)]
pub struct Row3 {
    pub size: f64,
    pub method: Method3,
    /// Number of `(scene, source)` pairs averaged: `seeds × sources`.
    pub sources: usize,
    /// The counters summed over all sources (the ADLC fields too).
    pub total: Counters,
}

impl Row3 {
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
pub struct Figure3Report {
    pub options: Figure3Options,
    pub rows: Vec<Row3>,
    /// Files written, in order.
    pub files: Vec<PathBuf>,
    /// Scenes generated.
    pub scenes: usize,
    /// `(scene, source)` jobs traced (each by the three techniques).
    pub jobs: usize,
    /// Rays on which polar's or sweep's nearest hit differed from the conventional one's
    /// (expected 0: one hit definition).
    pub disagreements: u64,
    /// Wall time of the measurement.
    pub elapsed: Duration,
}

impl fmt::Display for Figure3Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let o = &self.options;
        let (bands, cells) = stratification("--rays", o.rays).map_err(|_| fmt::Error)?;
        writeln!(
            f,
            "{} 3D scenes ({} sizes × {} seeds) of {} squares, {} sources each, {} rays per source \
             ({bands} × {cells}, {:?} cells): {} jobs in {:.2} s",
            self.scenes,
            o.sizes.len(),
            o.seeds,
            o.count,
            o.sources,
            o.rays,
            o.strata,
            self.jobs,
            self.elapsed.as_secs_f64()
        )?;
        writeln!(f, "per-source means (sweep's ADLC est. = the ADLC captured in its planes):")?;
        f.write_str(&table(&self.rows))?;
        if self.disagreements > 0 {
            writeln!(
                f,
                "WARNING: {} rays where polar or sweep differ from the conventional hit",
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

/// The rows as a markdown table.
pub fn table(rows: &[Row3]) -> String {
    let mut s = String::from(
        "| size | method | read before | read after | cells | tests | actual | ADLC | ADLC est. |\n\
         |---:|:---|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        let v = r.mean_values();
        s.push_str(&format!(
            "| {} | {} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1} | {:.2} | {:.2} |\n",
            r.size, r.method, v[0], v[1], v[2], v[3], v[4], v[5], v[6]
        ));
    }
    s
}

/// The CSV text: header, then one line per row (per-source means).
pub fn csv(rows: &[Row3]) -> String {
    let mut out = format!("size,method,sources,{}\n", Counters::NAMES.join(","));
    for r in rows {
        let mut cols = vec![csv_num(r.size), r.method.name().to_string(), r.sources.to_string()];
        cols.extend(r.mean_values().iter().map(|&v| csv_num(v)));
        out.push_str(&cols.join(","));
        out.push('\n');
    }
    out
}

/// The 2D technique whose colour and marker a 3D one takes in the charts: the conventional
/// technique its own, polar (sectors and shells, like stochastic shelling) the stochastic one's,
/// the sweep (the deterministic technique in each plane) the deterministic one's.
fn look(m: Method3) -> Method {
    match m {
        Method3::Brute => Method::Brute,
        Method3::Conventional => Method::Conventional,
        Method3::Polar => Method::Stochastic,
        Method3::Sweep => Method::Deterministic,
    }
}

/// Figures 8–11 and 13 in 3D as `(file name, SVG text)`: per-source means over the patch size,
/// one series per technique of the rows; Figure 11 with the actual intersections, Figure 13 the
/// true 3D ADLC beside each technique's estimate (the sweep's is the ADLC its planes capture).
pub fn svgs(opts: &Figure3Options, rows: &[Row3]) -> Result<Vec<(&'static str, String)>> {
    let mut sizes = opts.sizes.clone();
    sizes.sort_by(f64::total_cmp);
    let workload =
        format!("N = {}, R = {}, {} sources × {} seeds", opts.count, opts.rays, opts.sources, opts.seeds);
    let mut methods: Vec<Method3> = Vec::new();
    for r in rows {
        if !methods.contains(&r.method) {
            methods.push(r.method);
        }
    }
    let points = |m: Method3, i: usize| -> Vec<(f64, f64)> {
        rows.iter().filter(|r| r.method == m).map(|r| (r.size, r.mean_values()[i])).collect()
    };
    let series = |m: Method3, label: String, i: usize| {
        Series::new(label, points(m, i), method_color(look(m)), method_marker(look(m)))
    };
    let per_method =
        |i: usize| -> Vec<Series> { methods.iter().map(|&m| series(m, m.name().into(), i)).collect() };
    let chart = |title: &str, y_label: &str, series: Vec<Series>| Chart {
        size: CHART_SIZE,
        title: format!("{title}, 3D ({workload})"),
        x_label: "patch size L (log₂ scale)".to_string(),
        y_label: y_label.to_string(),
        x: XAxis::Log2(sizes.clone()),
        series,
    };
    let first = methods.first().copied().ok_or_else(|| anyhow!("no rows to plot"))?;
    let mut s11 = per_method(3);
    s11.push(Series::new("actual intersections", points(first, 4), GREY, Marker::Cross));
    let mut s13 = vec![Series::new("ADLC true (all methods)", points(first, 5), GREY, Marker::Cross)];
    for &m in methods.iter().filter(|&&m| m != Method3::Conventional) {
        let what = if m == Method3::Sweep { "captured in its planes" } else { "estimated" };
        s13.push(series(m, format!("ADLC {what}: {}", m.name()), 6));
    }
    Ok(vec![
        (
            "fig08_3d_patches_read_before_screening.svg",
            render(&chart(
                "Fig. 8: patches read before screening",
                "patches read per source",
                per_method(0),
            ))?,
        ),
        (
            "fig09_3d_patches_read_after_screening.svg",
            render(&chart("Fig. 9: patches read after screening", "patches per source", per_method(1)))?,
        ),
        (
            "fig10_3d_cells_traversed.svg",
            render(&chart("Fig. 10: cells traversed", "cells traversed per source", per_method(2)))?,
        ),
        (
            "fig11_3d_intersection_computations.svg",
            render(&chart("Fig. 11: intersection computations", "ray-polygon tests per source", s11))?,
        ),
        (
            "fig13_3d_adlc.svg",
            render(&chart(
                "Fig. 13: average degree of local coherence",
                "ADLC (rays per distinct patch hit)",
                s13,
            ))?,
        ),
    ])
}

/// Runs the workload: one row per size (in the order of [`Figure3Options::sizes`]) and technique
/// (in the order of [`METHODS3`]), the scenes and jobs counted, and the disagreements.
pub fn measure(opts: &Figure3Options) -> Result<(Vec<Row3>, usize, usize, u64)> {
    opts.validate()?;
    let (bands, cells) = stratification("--rays", opts.rays)?;
    let specs: Vec<(usize, usize)> =
        (0..opts.sizes.len()).flat_map(|i| (0..opts.seeds).map(move |s| (i, s))).collect();
    let scenes = specs
        .par_iter()
        .map(|&(i, s)| {
            let (size, seed) = (opts.sizes[i], scene_seed(i, s));
            let scene = generate(opts.count, size, seed)
                .map_err(|e| anyhow!("generating the 3D scene of size {size}, seed {seed}: {e}"))?;
            let grid = Grid3::build(&scene, opts.grid)
                .map_err(|e| anyhow!("the grid of the 3D scene of size {size}, seed {seed}: {e}"))?;
            Ok((i, scene, grid))
        })
        .collect::<Result<Vec<_>>>()?;
    let jobs: Vec<(usize, usize)> = (0..scenes.len())
        .flat_map(|j| source_patches(opts.count, opts.sources).into_iter().map(move |k| (j, k)))
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
    let results = jobs
        .par_iter()
        .map(|&(j, k)| {
            let (i, scene, grid) = &scenes[j];
            let p = &scene.polygons[k];
            let rays = HemisphereRays::new(p.centre, p.normal, bands, cells, opts.strata)
                .map_err(|e| anyhow!("source patch {k}: {e}"))?;
            let bundle = Bundle3::from_hemisphere(&rays, Some(k));
            let traced = METHODS3
                .iter()
                .map(|&m| trace(m, scene, grid, &bundle, &opts.shells).map_err(|e| anyhow!("{m}: {e}")))
                .collect::<Result<Vec<_>>>()?;
            let disagreements: u64 = traced[1..]
                .iter()
                .map(|t| t.hits.iter().zip(&traced[0].hits).filter(|(a, b)| a != b).count() as u64)
                .sum();
            bar.inc(1);
            Ok((*i, traced.iter().map(|t| t.counters).collect::<Vec<_>>(), disagreements))
        })
        .collect::<Result<Vec<_>>>()?;
    bar.finish_and_clear();
    // Sum in job order (deterministic whatever the threads).
    let mut acc = vec![vec![(Counters::default(), 0usize); METHODS3.len()]; opts.sizes.len()];
    let mut disagreements = 0;
    for (i, counters, d) in &results {
        disagreements += d;
        for (a, c) in acc[*i].iter_mut().zip(counters) {
            a.0 += *c;
            a.1 += 1;
        }
    }
    let rows = opts
        .sizes
        .iter()
        .enumerate()
        .flat_map(|(i, &size)| {
            let acc = &acc;
            METHODS3.iter().enumerate().map(move |(m, &method)| Row3 {
                size,
                method,
                sources: acc[i][m].1,
                total: acc[i][m].0,
            })
        })
        .collect();
    Ok((rows, scenes.len(), jobs.len(), disagreements))
}

/// Runs the workload and writes `figures3d.csv` and `figures3d.md` into `opts.out` (whole or not
/// at all).
pub fn run(opts: &Figure3Options) -> Result<Figure3Report> {
    let start = Instant::now();
    opts.validate()?;
    let staged = Staged::dir(&opts.out)
        .with_context(|| format!("creating the output directory {}", opts.out.display()))?;
    let (rows, scenes, jobs, disagreements) = measure(opts)?;
    let elapsed = start.elapsed();
    let mut files = Vec::new();
    let (bands, cells) = stratification("--rays", opts.rays)?;
    let md = format!(
        "# 3D figures\n\n{} squares per scene, sizes {:?}, {} seeds, {} sources per scene, {} rays \
         ({bands} × {cells}, {:?} cells); per-source means. The sweep's ADLC est. is the ADLC \
         captured in its planes.\n\n{}",
        opts.count,
        opts.sizes,
        opts.seeds,
        opts.sources,
        opts.rays,
        opts.strata,
        table(&rows)
    );
    let mut texts = vec![("figures3d.csv", csv(&rows)), ("figures3d.md", md)];
    texts.extend(svgs(opts, &rows)?);
    for (name, text) in texts {
        let path = staged.path().join(name);
        let shown = opts.out.join(name);
        std::fs::write(&path, text).with_context(|| format!("writing {}", shown.display()))?;
        files.push(shown);
    }
    staged.commit().with_context(|| format!("moving the figures into {}", opts.out.display()))?;
    Ok(Figure3Report { options: opts.clone(), rows, files, scenes, jobs, disagreements, elapsed })
}

/// The 3D headline's rays per origin (`cargo bench --bench machine3d`, `figures/headline3d.md`).
pub const HEADLINE3D_RAYS: usize = 4096;
/// The 3D headline's origins per polygon.
pub const HEADLINE3D_ORIGINS: usize = 16;

/// The 3D headline's scene: the shipped Cornell box (`scenes/cornell_box.obj`, embedded).
pub fn headline3d_scene() -> Result<crate::d3::scene::Scene3> {
    const OBJ: &str = include_str!("../../scenes/cornell_box.obj");
    const MTL: &str = include_str!("../../scenes/cornell_box.mtl");
    let mtl = |_: &std::path::Path| Ok(MTL.to_string());
    Ok(crate::d3::obj::load_str("scenes/cornell_box.obj", OBJ, &mtl)?)
}

/// The 3D headline's estimate, by `method`: [`HEADLINE3D_RAYS`] cosine rays from each of
/// [`HEADLINE3D_ORIGINS`] origins.
pub fn headline3d_params(method: Method3) -> crate::d3::form_factors::Ff3Params {
    crate::d3::form_factors::Ff3Params {
        rays: HEADLINE3D_RAYS,
        origins: HEADLINE3D_ORIGINS,
        method,
        ..Default::default()
    }
}

/// The 3D headline's machine run: every row of [`headline3d_scene`] on `pes` PEs
/// ([`crate::d3::on_pe::rows_on_machine`]), `T_c` = [`super::machine::HEADLINE_TC`] shared by all
/// PEs, each PE's cache a quarter of the polygons, every hit checked.
pub fn headline3d_run(pes: usize, engine: crate::cosim::Engine) -> Result<crate::d3::on_pe::Pe3Totals> {
    use crate::machine::{Deal, MachineConfig, Placement};
    let scene = headline3d_scene()?;
    let config = MachineConfig {
        pes,
        tc: super::machine::HEADLINE_TC,
        cache: Some((scene.polygons.len() / 4) as u32),
        deal: Deal::Blocks,
        place: Placement::Index,
        engine: engine.resolve(false),
        vcd: None,
    };
    let (_, totals) =
        crate::d3::on_pe::rows_on_machine(&scene, &headline3d_params(Method3::Sweep), &config, |_, _| {})?;
    Ok(totals)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stratification_takes_4k2_rays_and_names_the_nearest_otherwise() {
        assert_eq!(stratification("--rays", 1024).unwrap(), (64, 16));
        assert_eq!(stratification("--rays", 4).unwrap(), (4, 1));
        let e = stratification("--rays", 1000).unwrap_err().to_string();
        assert!(e.contains("--rays must be 4·k²") && e.contains("900 and 1024"), "{e}");
        let e = stratification("--rays", 1).unwrap_err().to_string();
        assert!(e.contains("got 1;") && e.contains("the smallest is 4"), "{e}");
    }
}
