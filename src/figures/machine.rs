//! The paper's parallel claim, measured: the machine of `N` PEs on one shared host memory
//! ([`crate::machine`]) co-simulated cycle by cycle on the Section 5 workload, for every
//! segment length, technique, PE count, host memory load time `T_c` and cache size of
//! [`MachineFigureOptions`], every hit checked against the bit-true model.
//!
//! # Sample
//!
//! For the `i`-th segment length, the scene of the first seed ([`scene_seed`]`(i, 0)`, the
//! golden part's first scene), its patches along a Hilbert curve of their midpoints in the host
//! memory ([`Layout::Hilbert`]), and a spatially compact run of `sources` of them: the `sources` from
//! the middle of that order on, so that the sources are neighbours and a PE's cache can carry
//! patches from one source to the next, as it would over a whole scene. Sources are dealt in
//! blocks of even work ([`Deal::Blocks`]); each PE runs its queue on its own. A second set of rows compares
//! the other deals, and the same sources with the patches in the file's order
//! ([`Layout::File`]), at [`MachineFigureOptions::deal_pes`] PEs, `T_c` =
//! [`MachineFigureOptions::deal_tc`] and the smallest cache.
//!
//! # Columns of `machine.csv`
//!
//! `cycles` from the first setup to the last readout; `speedup` the same row's 1-PE cycles
//! over its own; `memory_bound_cycles` = host loads · `T_c` (the shared port's floor: no
//! machine of any `N` runs these loads faster); `memory_utilisation` the port's busy cycles over
//! `cycles`.

use super::cycles::{short, TC_COLORS};
use super::plot::{method_marker, render, Chart, Series, XAxis};
use super::{csv_num, scene_seed, METHODS};
use crate::cosim::Engine;
use crate::grid::GridParams;
use crate::machine::{self, Deal, Layout, MachineConfig, MachineRun, Placement};
use crate::rays::RaySet;
use crate::run::{GriddedScene, Scheduled};
use crate::scene;
use crate::trace::{Method, ShellParams};
use anyhow::{bail, Context, Result};
use rayon::prelude::*;
use std::fmt::Write as _;
use std::path::PathBuf;

/// What the machine figures sweep.
#[derive(Clone, Debug)]
pub struct MachineFigureOptions {
    pub out: PathBuf,
    /// Segments per scene.
    pub count: usize,
    pub lengths: Vec<f64>,
    /// Sources per length (a spatially compact run, see the module documentation).
    pub sources: usize,
    pub rays: usize,
    pub pes: Vec<usize>,
    pub tcs: Vec<u32>,
    /// Each PE's cache: `None` off.
    pub caches: Vec<Option<u32>>,
    /// The deal comparison's PE count and `T_c`.
    pub deal_pes: usize,
    pub deal_tc: u32,
    pub engine: Engine,
    pub progress: bool,
}

impl Default for MachineFigureOptions {
    fn default() -> Self {
        Self {
            out: PathBuf::from("figures"),
            count: 1000,
            lengths: vec![4.0, 8.0, 16.0, 32.0, 64.0, 128.0],
            sources: 16,
            rays: 1024,
            pes: vec![1, 2, 4, 8],
            tcs: vec![1, 4, 16, 64],
            caches: vec![None, Some(128), Some(1024)],
            deal_pes: 8,
            deal_tc: 16,
            engine: Engine::Auto,
            progress: false,
        }
    }
}

/// One co-simulated machine run.
#[derive(Clone, Debug)]
pub struct MachineRow {
    pub length: f64,
    pub method: Method,
    pub tc: u32,
    pub cache: Option<u32>,
    pub pes: usize,
    pub deal: Deal,
    pub layout: Layout,
    pub run: MachineRun,
    /// The same row's cycles on one PE over these (the deal rows: blocks on one PE).
    pub speedup: f64,
}

impl MachineRow {
    pub fn memory_bound_cycles(&self) -> u64 {
        self.run.memory_loads * self.tc as u64
    }
}

/// Checks the options; the errors name them as the command line does.
pub fn validate(o: &MachineFigureOptions) -> Result<()> {
    use crate::limits::{check_cache, check_range, check_range_for, MAX_TC};
    use shelling_testbench::pe::PE_RAY_MEMORY;
    let m = anyhow::Error::msg;
    if o.lengths.is_empty() || o.lengths.iter().any(|&l| !(l > 0.0 && l < 1024.0)) {
        bail!("--lengths: each greater than 0 and less than 1024");
    }
    check_range_for("--rays", o.rays, 1, PE_RAY_MEMORY, "(the processing element's ray memory)")
        .map_err(m)?;
    check_range_for("--sources", o.sources, 1, o.count, "(--count segments per scene)").map_err(m)?;
    for &p in o.pes.iter().chain([&o.deal_pes]) {
        check_range_for("--pes", p, 1, shelling_hdl::arbiter::MAX_PES, "(the memory arbiter's ports)")
            .map_err(m)?;
    }
    if !o.pes.contains(&1) {
        bail!("--pes must include 1: the speedups are over one PE");
    }
    for &tc in o.tcs.iter().chain([&o.deal_tc]) {
        check_range("--tc", tc, 1, MAX_TC).map_err(m)?;
    }
    for c in o.caches.iter().flatten() {
        check_cache("--caches", *c).map_err(m)?;
    }
    if o.deal_pes > o.rays {
        bail!("--deal-pes {} cuts each source's {} rays into more sectors than rays", o.deal_pes, o.rays);
    }
    Ok(())
}

/// One length's scene and its sources in Hilbert order (the run the sweep takes).
/// One length's scene in both layouts, and the sources the sweep takes (the same patches) in
/// each: `(Hilbert-ordered scene, its sources, file-ordered scene, its sources)`.
fn sample(
    o: &MachineFigureOptions,
    li: usize,
) -> Result<(GriddedScene, Vec<usize>, GriddedScene, Vec<usize>)> {
    let sc = scene::generate(o.count, o.lengths[li], scene_seed(li, 0), scene::PAPER_WORLD)
        .context("generating the workload's scene")?;
    let (z, old_of_new) = machine::hilbert_ordered(&sc);
    let from = (o.count - o.sources) / 2;
    let z_ids: Vec<usize> = (from..from + o.sources).collect();
    let file_ids: Vec<usize> = z_ids.iter().map(|&k| old_of_new[k]).collect();
    let file = GriddedScene::new(sc, GridParams::default());
    let file_order = machine::spatial_order(&file.scene.segments, &file_ids);
    Ok((GriddedScene::new(z, GridParams::default()), z_ids, file, file_order))
}

/// Runs the sweep: every (length, technique, `T_c`, cache, PE count) in blocks, then the deal
/// comparison. Rows in that order.
pub fn run(o: &MachineFigureOptions) -> Result<Vec<MachineRow>> {
    validate(o)?;
    let engine = o.engine.resolve(false);
    let params = ShellParams::default();
    // Schedules per length and technique: whole sources, in `deal_pes` sectors, and whole on
    // the scene in the file's layout.
    let mut jobs: Vec<(usize, Method, u32, Option<u32>, usize, Deal, Layout)> = Vec::new();
    for li in 0..o.lengths.len() {
        for &m in &METHODS {
            for &tc in &o.tcs {
                for &cache in &o.caches {
                    for &p in &o.pes {
                        jobs.push((li, m, tc, cache, p, Deal::Blocks, Layout::Hilbert));
                    }
                }
            }
            let cache = o.caches.iter().flatten().min().copied();
            for (deal, layout) in [
                (Deal::Interleaved, Layout::Hilbert),
                (Deal::Sectors, Layout::Hilbert),
                (Deal::Blocks, Layout::File),
            ] {
                jobs.push((li, m, o.deal_tc, cache, o.deal_pes, deal, layout));
            }
        }
    }
    type Schedules = (Method, [Vec<Scheduled>; 3]);
    let schedules: Vec<Vec<Schedules>> = (0..o.lengths.len())
        .into_par_iter()
        .map(|li| {
            let (z, z_order, file, file_order) = sample(o, li)?;
            METHODS
                .iter()
                .map(|&m| {
                    let at = |g: &GriddedScene, order: &[usize], parts| {
                        machine::schedule_sources(g, order, m, RaySet::Angle, o.rays, &params, parts)
                    };
                    Ok((m, [at(&z, &z_order, 1)?, at(&z, &z_order, o.deal_pes)?, at(&file, &file_order, 1)?]))
                })
                .collect::<Result<Vec<_>>>()
        })
        .collect::<Result<_>>()?;
    // One run at a time: a compiled machine steps its PEs on two threads (`Composed::threaded`,
    // its helper spinning between edges), so runs side by side oversubscribe the cores, and
    // each then steps its PEs on one thread (the lockstep's `Pacer`): on two cores, two
    // processes of `--lengths 32 --sources 16 --pes 1,8 --tc 16 --caches 128` side by side took
    // 7.3 s, one alone 2.3 s (78.8 s side by side before the pacer).
    let runs: Vec<MachineRun> = jobs
        .iter()
        .enumerate()
        .map(|(done, &(li, m, tc, cache, pes, deal, layout))| {
            let (_, [whole, parts, file]) =
                schedules[li].iter().find(|s| s.0 == m).expect("every technique scheduled");
            let config = MachineConfig { pes, tc, cache, deal, place: Placement::Index, engine, vcd: None };
            let work = match (deal, layout) {
                (_, Layout::File) => file,
                (Deal::Sectors, _) => parts,
                _ => whole,
            };
            let r = machine::run(work, &config, |_, _| {}).with_context(|| {
                format!(
                    "length {} {m} T_c {tc} cache {cache:?} on {pes} PEs ({}, {})",
                    o.lengths[li],
                    deal.name(),
                    layout.name()
                )
            })?;
            let n = done + 1;
            if o.progress {
                eprint!("\rmachine runs {n}/{}", jobs.len());
            }
            Ok(r)
        })
        .collect::<Result<_>>()?;
    if o.progress {
        eprintln!();
    }
    let rows: Vec<MachineRow> = jobs
        .iter()
        .zip(runs)
        .map(|(&(li, method, tc, cache, pes, deal, layout), run)| MachineRow {
            length: o.lengths[li],
            method,
            tc,
            cache,
            pes,
            deal,
            layout,
            run,
            speedup: 0.0,
        })
        .collect();
    let one = |r: &MachineRow| {
        rows.iter()
            .find(|b| {
                b.pes == 1
                    && (b.deal, b.layout) == (Deal::Blocks, Layout::Hilbert)
                    && (b.length, b.method, b.tc, b.cache) == (r.length, r.method, r.tc, r.cache)
            })
            .map(|b| b.run.cycles)
    };
    let speedups: Vec<f64> =
        rows.iter().map(|r| one(r).map_or(f64::NAN, |c| c as f64 / r.run.cycles as f64)).collect();
    Ok(rows.into_iter().zip(speedups).map(|(r, speedup)| MachineRow { speedup, ..r }).collect())
}

/// `machine.csv`.
pub fn csv(rows: &[MachineRow]) -> String {
    let mut s = String::from(
        "length,method,tc,cache_lines,pes,deal,layout,sources,cycles,cycles_per_source,speedup,rays_per_cycle,\
         memory_loads,memory_bound_cycles,memory_utilisation,patch_loads,cache_hits,tests\n",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            csv_num(r.length),
            r.method,
            r.tc,
            r.cache.unwrap_or(0),
            r.pes,
            r.deal.name(),
            r.layout.name(),
            r.run.sources,
            r.run.cycles,
            csv_num(r.run.cycles_per_source()),
            csv_num(r.speedup),
            csv_num(r.run.rays_per_cycle()),
            r.run.memory_loads,
            r.memory_bound_cycles(),
            csv_num(r.run.memory_utilisation),
            r.run.patch_loads,
            r.run.cache_hits,
            r.run.tests
        );
    }
    s
}

fn cache_name(c: Option<u32>) -> String {
    c.map_or("off".into(), |c| c.to_string())
}

/// The smallest PE count whose port is at least 90 % busy, if any: where the shared memory
/// saturates.
fn saturation(rows: &[&MachineRow]) -> String {
    rows.iter()
        .filter(|r| r.run.memory_utilisation >= 0.9)
        .map(|r| r.pes)
        .min()
        .map_or("-".into(), |p| p.to_string())
}

/// `machine.md`: the summary tables FIGURES.md holds.
pub fn markdown(o: &MachineFigureOptions, rows: &[MachineRow]) -> String {
    let mut s = String::new();
    let blocks: Vec<&MachineRow> =
        rows.iter().filter(|r| (r.deal, r.layout) == (Deal::Blocks, Layout::Hilbert)).collect();
    let most = *o.pes.iter().max().unwrap_or(&1);
    let _ = writeln!(
        s,
        "Cycles per source on 1 to {most} PEs (sources dealt in blocks of even work), the speedup at {most} PEs over one, \
         the shared port's busy share at {most} PEs, and the fewest PEs that keep the port at least 90 % busy \
         (`-`: none), per segment length L, technique, `T_c` and per-PE cache (patches; `off`: every load from \
         the host memory), the patches in Hilbert order in the host memory. {} sources of {} rays per length.\n",
        o.sources, o.rays
    );
    let pes_cols: String =
        o.pes.iter().map(|p| format!(" {p} PE{} |", if *p == 1 { "" } else { "s" })).collect();
    let _ = writeln!(s, "| L | technique | T_c | cache |{pes_cols} speedup | port busy | saturates at |");
    let _ = writeln!(s, "|--:|---|--:|--:|{}--:|--:|--:|", "--:|".repeat(o.pes.len()));
    for &l in &o.lengths {
        for &m in &METHODS {
            for &tc in &o.tcs {
                for &c in &o.caches {
                    let set: Vec<&MachineRow> = blocks
                        .iter()
                        .copied()
                        .filter(|r| (r.length, r.method, r.tc, r.cache) == (l, m, tc, c))
                        .collect();
                    let cols: String = o
                        .pes
                        .iter()
                        .map(|&p| {
                            set.iter()
                                .find(|r| r.pes == p)
                                .map_or(" |".into(), |r| format!(" {:.0} |", r.run.cycles_per_source()))
                        })
                        .collect();
                    let Some(top) = set.iter().find(|r| r.pes == most) else { continue };
                    let _ = writeln!(
                        s,
                        "| {} | {} | {tc} | {} |{cols} {:.2}× | {:.0}% | {} |",
                        csv_num(l),
                        short(m),
                        cache_name(c),
                        top.speedup,
                        100.0 * top.run.memory_utilisation,
                        saturation(&set)
                    );
                }
            }
        }
    }
    let _ = writeln!(
        s,
        "\nThe deals and the host memory's layouts at {} PEs, `T_c` = {}, the smallest cache: cycles per source, host loads, and the \
         port's busy share.\n",
        o.deal_pes, o.deal_tc
    );
    let _ = writeln!(s, "| L | technique | deal | layout | per source | host loads | port busy |");
    let _ = writeln!(s, "|--:|---|---|---|--:|--:|--:|");
    let small = o.caches.iter().flatten().min().copied();
    for &l in &o.lengths {
        for &m in &METHODS {
            for (deal, layout) in [
                (Deal::Blocks, Layout::Hilbert),
                (Deal::Blocks, Layout::File),
                (Deal::Interleaved, Layout::Hilbert),
                (Deal::Sectors, Layout::Hilbert),
            ] {
                if let Some(r) = rows.iter().find(|r| {
                    (r.length, r.method, r.tc, r.cache, r.pes, r.deal, r.layout)
                        == (l, m, o.deal_tc, small, o.deal_pes, deal, layout)
                }) {
                    let _ = writeln!(
                        s,
                        "| {} | {} | {} | {} | {:.0} | {} | {:.0}% |",
                        csv_num(l),
                        short(m),
                        deal.name(),
                        layout.name(),
                        r.run.cycles_per_source(),
                        r.run.memory_loads,
                        100.0 * r.run.memory_utilisation
                    );
                }
            }
        }
    }
    s
}

/// The charts at length `l`: speedup over one PE against the PE count, one chart per cache;
/// and the port's busy share at the smallest cache.
pub fn svgs(o: &MachineFigureOptions, rows: &[MachineRow], l: f64) -> Result<Vec<(String, String)>> {
    let mut pes: Vec<f64> = o.pes.iter().map(|&p| p as f64).collect();
    pes.sort_by(f64::total_cmp);
    let chart = |title: String, y: &str, series: Vec<Series>| Chart {
        size: (1040, 760),
        title: format!("{title} (L = {}, {} sources of {} rays)", csv_num(l), o.sources, o.rays),
        x_label: "PEs on one host memory (log₂ scale)".into(),
        y_label: y.into(),
        x: XAxis::Log2(pes.clone()),
        series,
    };
    let series = |cache: Option<u32>, value: &dyn Fn(&MachineRow) -> f64| -> Vec<Series> {
        let mut out = Vec::new();
        for (ti, &tc) in o.tcs.iter().enumerate() {
            for &m in &METHODS {
                let mut pts: Vec<(f64, f64)> = rows
                    .iter()
                    .filter(|r| {
                        (r.deal, r.layout) == (Deal::Blocks, Layout::Hilbert)
                            && (r.length, r.method, r.tc, r.cache) == (l, m, tc, cache)
                    })
                    .map(|r| (r.pes as f64, value(r)))
                    .collect();
                pts.sort_by(|a, b| a.0.total_cmp(&b.0));
                out.push(Series::new(
                    format!("{} T_c = {tc}", short(m)),
                    pts,
                    TC_COLORS[ti % TC_COLORS.len()],
                    method_marker(m),
                ));
            }
        }
        out
    };
    let mut out = Vec::new();
    for &c in &o.caches {
        out.push((
            format!("machine_speedup_cache_{}.svg", cache_name(c)),
            render(&chart(
                format!("Speedup over one PE, per-PE cache {}", cache_name(c)),
                "1-PE cycles / N-PE cycles",
                series(c, &|r| r.speedup),
            ))?,
        ));
    }
    let small = o.caches.iter().flatten().min().copied();
    out.push((
        "machine_port_busy.svg".into(),
        render(&chart(
            format!("Shared host memory port busy, per-PE cache {}", cache_name(small)),
            "busy cycles / cycles",
            series(small, &|r| r.run.memory_utilisation),
        ))?,
    ));
    Ok(out)
}

/// Runs the sweep and writes `machine.csv`, `machine.md` and the charts (at L = 32 if swept,
/// else the first length) into `o.out`. Returns the rows.
pub fn write(o: &MachineFigureOptions) -> Result<Vec<MachineRow>> {
    // Written under a temporary name beside `out` and moved into place at the end, as
    // `figures --out`: a failed run leaves no partial figures.
    let staged = crate::staged::Staged::dir(&o.out)
        .with_context(|| format!("creating the output directory {}", o.out.display()))?;
    let rows = run(o)?;
    let l = if o.lengths.contains(&32.0) { 32.0 } else { o.lengths[0] };
    let mut files =
        vec![("machine.csv".to_string(), csv(&rows)), ("machine.md".to_string(), markdown(o, &rows))];
    files.extend(svgs(o, &rows, l)?);
    for (name, text) in files {
        std::fs::write(staged.path().join(&name), text)
            .with_context(|| format!("writing {}", o.out.join(&name).display()))?;
    }
    staged.commit().with_context(|| format!("moving the figures into {}", o.out.display()))?;
    Ok(rows)
}

/// The README's headline workload: the paper's scene (1000 segments of length 32 in
/// [0, 1024)², seed 7, as the README's and the tracer benchmark's), every one of its sources in
/// Hilbert order, R = 1024 rays (angle set), `T_c` = [`HEADLINE_TC`] shared by all PEs, a cache of
/// [`HEADLINE_CACHE`] patches per PE (a quarter of the scene: the cache's 256-line index with
/// the host memory map that leaves lines 250 … 255 unused, `shelling_testbench::pe::MemoryMap`),
/// sources dealt in blocks of even work ([`Deal::Blocks`]), the patches placed in the caches'
/// lines by the host ([`Placement::Lines`]).
pub const HEADLINE_TC: u32 = 16;
pub const HEADLINE_CACHE: u32 = 250;

/// The headline's scene, prepared, its patches in Hilbert order in the host memory
/// ([`Layout::Hilbert`]), and its sources in the order they are dealt (Hilbert order).
pub fn headline_scene() -> Result<(GriddedScene, Vec<usize>)> {
    let sc = scene::generate(1000, 32.0, 7, scene::PAPER_WORLD).context("the headline scene")?;
    let (z, _) = machine::hilbert_ordered(&sc);
    let n = z.segments.len();
    Ok((GriddedScene::new(z, GridParams::default()), (0..n).collect()))
}

/// The headline's machine runs: `method` on `pes` PEs over every source of the headline scene.
pub fn headline_run(method: Method, pes: usize, engine: Engine) -> Result<MachineRun> {
    let (prepared, order) = headline_scene()?;
    let work = machine::schedule_sources(
        &prepared,
        &order,
        method,
        RaySet::Angle,
        1024,
        &ShellParams::default(),
        1,
    )?;
    let config = MachineConfig {
        pes,
        tc: HEADLINE_TC,
        cache: Some(HEADLINE_CACHE),
        deal: Deal::Blocks,
        place: Placement::Lines,
        engine: engine.resolve(false),
        vcd: None,
    };
    Ok(machine::run(&work, &config, |_, _| {})?)
}
