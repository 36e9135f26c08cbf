//! The radiosity commands of the command line: `form-factors` and `radiosity` (RADIOSITY.md).

use super::{Out, TuneArgs};
use anyhow::{bail, Context, Result};
use clap::{ArgGroup, Args, ValueEnum};
use shelling::arith::Arith;
use shelling::cosim::{CosimConfig, Engine};
use shelling::d3::trace::Method3;
use shelling::limits::{self, check_range, check_range_for};
use shelling::machine::{Deal, MachineConfig, Placement};
use shelling::radiosity::form_factors::{self, FfParams, Row, DEFAULT_ORIGINS, DEFAULT_RAYS, MAX_ORIGINS};
use shelling::radiosity::matrix::{self, MatrixFile};
use shelling::radiosity::on_pe::{self, PeTotals, PE_RAY_MEMORY};
use shelling::radiosity::solve::{self, Solution, Surfaces};
use shelling::rays::{RaySet, MAX_BUNDLE_RAYS};
use shelling::run::GriddedScene;
use shelling::scene::{self, RoomSpec, Scene};
use shelling::staged::Staged;
use shelling::trace::Method;
use shelling_hdl::arbiter::MAX_PES;
use std::ops::Range;
use std::path::{Path, PathBuf};

/// The most steps of a solve `--max-steps` accepts.
const MAX_STEPS: usize = 10_000_000;

/// How each form-factor row is estimated.
#[derive(Args, Clone)]
pub struct FfArgs {
    /// Rays per origin, 1 to 1048576 (default 2048, 3D 4096 as n_theta × n_phi; with
    /// `radiosity --on-pe` in 2D at most and by default 1024, the PE's ray memory; in 3D an
    /// even n_theta with 2·n_phi ≤ 1024).
    #[arg(long, allow_negative_numbers = true)]
    rays: Option<usize>,
    /// Origins per source patch, stratified along it (1 to 4096; default 16, 3D 256, spread
    /// over the polygon); 1 is the paper's centre.
    #[arg(long, allow_negative_numbers = true)]
    origins: Option<usize>,
    /// Ray set: `sine` (each ray carries form factor 1/R; in 3D the cosine-weighted set) or
    /// `angle` (each ray its cell's).
    #[arg(long, value_enum, default_value_t = RaySet::Sine)]
    ray_set: RaySet,
    /// Tracing technique, all giving the same form factors in f64: 2D brute, conventional,
    /// stochastic or deterministic (default deterministic); 3D any 3D technique (default
    /// conventional).
    #[arg(long, value_parser = super::d3_cli::parse_method)]
    method: Option<super::d3_cli::MethodArg>,
    /// Arithmetic of the hit tests: `float` or `fixed` (the RTL's bit-true model; 2D only).
    #[arg(long, value_enum, default_value_t = Arith::Float)]
    arith: Arith,
}

impl FfArgs {
    /// The parameters; `on_pe` sets the default rays to the PE's ray memory.
    fn params(&self, tune: &TuneArgs, on_pe: bool) -> Result<FfParams> {
        let (rays, max) = match on_pe {
            false => (self.rays.unwrap_or(DEFAULT_RAYS), MAX_BUNDLE_RAYS),
            true => (self.rays.unwrap_or(PE_RAY_MEMORY), PE_RAY_MEMORY),
        };
        let note = if on_pe { "with --on-pe (the PE's ray memory)" } else { "" };
        check_range_for("--rays", rays, 1, max, note).map_err(anyhow::Error::msg)?;
        let origins = self.origins.unwrap_or(DEFAULT_ORIGINS);
        check_range("--origins", origins, 1, MAX_ORIGINS).map_err(anyhow::Error::msg)?;
        Ok(FfParams {
            rays,
            origins,
            ray_set: self.ray_set,
            method: super::d3_cli::MethodArg::two_d(self.method.as_ref(), Method::Deterministic)?,
            arith: self.arith,
            shells: tune.shells_2d()?,
        })
    }
}

#[derive(Args)]
#[command(group(ArgGroup::new("what").args(["source", "rows", "merge", "origin"]).required(true)))]
pub struct FormFactorsArgs {
    /// Scene file: JSON segments (SCENES.md) or an OBJ scene of polygons (SCENES3D.md; a
    /// `.obj` name, or any file not starting with `{`); not used with --merge.
    #[arg(long, required_unless_present = "merge", conflicts_with = "merge")]
    scene: Option<PathBuf>,
    /// One row: the form factors from source patch K (3D: polygon K, in the file's order).
    #[arg(long, value_name = "K", allow_negative_numbers = true)]
    source: Option<usize>,
    /// 3D only: the differential form factors of the point X,Y,Z (with --normal) to every
    /// polygon, from one origin.
    #[arg(long, value_parser = super::d3_cli::parse_coords, requires = "normal", conflicts_with = "source",
          allow_hyphen_values = true)]
    origin: Option<super::d3_cli::Coords>,
    /// 3D only: the normal NX,NY,NZ of --origin (normalised; must be non-zero).
    #[arg(long, value_parser = super::d3_cli::parse_coords, requires = "origin", allow_hyphen_values = true)]
    normal: Option<super::d3_cli::Coords>,
    /// The rows A..B (sources A to B−1) as a matrix slice file (RADIOSITY.md); `..` alone is
    /// every row.
    #[arg(long, value_name = "A..B", value_parser = parse_rows, requires = "out")]
    rows: Option<RowsArg>,
    /// Merge matrix slice files (comma separated) into one matrix file (--out).
    #[arg(long, value_name = "FILES", value_delimiter = ',', num_args = 1.., requires = "out",
          conflicts_with_all = ["rays", "origins", "ray_set", "method", "arith", "cells_per_segment", "shell_depth", "max_sector", "origin"])]
    merge: Vec<PathBuf>,
    /// Output file of --rows and --merge.
    #[arg(long, value_name = "FILE")]
    out: Option<PathBuf>,
    /// With --source (or, 3D, --origin): print the row as JSON.
    #[arg(long)]
    json: bool,
    /// No progress bar.
    #[arg(long)]
    quiet: bool,
    #[command(flatten)]
    ff: FfArgs,
    #[command(flatten)]
    tune: TuneArgs,
}

/// `A..B`, `A..` or `..B` (open ends: the first and the last row).
#[derive(Clone, Copy, Debug)]
pub struct RowsArg {
    from: Option<usize>,
    to: Option<usize>,
}

fn parse_rows(s: &str) -> Result<RowsArg, String> {
    let (a, b) = s.split_once("..").ok_or_else(|| format!("expected A..B (such as 0..100), got {s:?}"))?;
    let num = |t: &str| -> Result<Option<usize>, String> {
        let t = t.trim();
        if t.is_empty() {
            return Ok(None);
        }
        t.parse().map(Some).map_err(|_| format!("{t:?} is not a row number (in {s:?})"))
    };
    Ok(RowsArg { from: num(a)?, to: num(b)? })
}

impl RowsArg {
    fn resolve(self, patches: usize) -> Result<Range<usize>> {
        let (a, b) = (self.from.unwrap_or(0), self.to.unwrap_or(patches));
        if a >= b || b > patches {
            bail!("--rows {a}..{b} must be a non-empty range within the scene's 0..{patches}");
        }
        Ok(a..b)
    }
}

#[derive(serde::Serialize)]
struct RowJson<'a> {
    source: usize,
    rays: usize,
    origins: usize,
    ray_set: RaySet,
    method: Method,
    arith: Arith,
    #[serde(rename = "form_factors")]
    entries: &'a [form_factors::Entry],
    sum: f64,
}

/// A progress bar of `len` `what`s on standard error, hidden with `--quiet`.
fn progress_bar(len: usize, what: &str, quiet: bool) -> indicatif::ProgressBar {
    if quiet {
        return indicatif::ProgressBar::hidden();
    }
    super::progress_bar(len as u64, &format!("{{bar:40}} {{pos}}/{{len}} {what} {{elapsed}} {{msg}}"))
}

/// Writes `text` to `path` under a temporary name, renamed on success ([`Staged`]), so a failed
/// write leaves nothing behind.
fn write_file(path: &Path, text: &str) -> Result<()> {
    let context = || format!("writing {}", path.display());
    let staged = Staged::file(path).with_context(context)?;
    std::fs::write(staged.path(), text).with_context(context)?;
    staged.commit().with_context(context)?;
    Ok(())
}

/// `--shell-depth` against the grid of `prepared`, for origins anywhere in it.
fn check_depth(tune: &TuneArgs, prepared: &GriddedScene) -> Result<()> {
    let (lo, hi) = prepared.grid.extent();
    tune.check_depth((hi - lo).max_element(), (hi - lo).length())
}

pub fn form_factors_cmd(a: FormFactorsArgs) -> Result<()> {
    let mut out = Out::new();
    if let Some(target) = &a.out {
        limits::check_output_file("--out", target).map_err(anyhow::Error::msg)?;
    }
    if !a.merge.is_empty() {
        let slices = a
            .merge
            .iter()
            .map(|p| Ok((p.display().to_string(), MatrixFile::load(p)?)))
            .collect::<Result<Vec<_>>>()?;
        let whole = matrix::merge(slices)?;
        let target = a.out.as_deref().expect("clap requires --out");
        write_file(target, &whole.to_json())?;
        say!(out, "{}: {} rows of {} merged", target.display(), whole.rows.len(), whole.scene.patches);
        return out.flush();
    }
    let path = a.scene.as_deref().expect("clap requires --scene");
    if super::d3_cli::is_3d(path)? {
        return form_factors_3d(&a, path);
    }
    if a.origin.is_some() {
        bail!("--origin belongs to 3D scenes (2D form factors are from whole segments: give --source K)");
    }
    let params = a.ff.params(&a.tune, false)?;
    let scene = Scene::load(path)?;
    let grid = a.tune.grid(scene.len())?;
    let prepared = GriddedScene::new(scene, grid);
    check_depth(&a.tune, &prepared)?;
    if let Some(k) = a.source {
        let row = form_factors::row(&prepared, k, &params)?;
        if a.json {
            let json = RowJson {
                source: k,
                rays: params.rays,
                origins: params.origins,
                ray_set: params.ray_set,
                method: params.method,
                arith: params.arith,
                entries: &row.entries,
                sum: row.sum(),
            };
            say!(out, "{}", serde_json::to_string_pretty(&json)?);
        } else {
            say!(
                out,
                "form factors from patch {k} ({} origins × {} {} rays, {}, {}): {} patches seen, sum {:.6}",
                params.origins,
                params.rays,
                params.ray_set,
                params.method,
                params.arith,
                row.entries.len(),
                row.sum()
            );
            let mut top = row.entries.clone();
            top.sort_by(|x, y| y.ff.total_cmp(&x.ff));
            say!(out, "{:>8}{:>14}", "patch", "F");
            for e in top.iter().take(10) {
                say!(out, "{:>8}{:>14.6}", e.patch, e.ff);
            }
        }
        return out.flush();
    }
    let range =
        a.rows.expect("clap requires one of --source, --rows, --merge").resolve(prepared.scene.len())?;
    let bar = progress_bar(range.len(), "rows", a.quiet);
    let rows = form_factors::rows(&prepared, range.clone(), &params, || bar.inc(1));
    bar.finish_and_clear();
    let file = MatrixFile::new(&prepared.scene, &params, range.start, rows?);
    write_matrix(&a, &file)
}

/// The rows of the whole matrix file at `path`, which `of_scene` checks is of the scene solved
/// (it is given the file and its name).
fn whole_matrix(
    path: &Path,
    of_scene: impl Fn(&MatrixFile, &str) -> Result<(), matrix::MatrixError>,
) -> Result<Vec<Row>> {
    let m = MatrixFile::load(path)?;
    of_scene(&m, &path.display().to_string())?;
    if !m.is_whole() {
        bail!(
            "{}: holds rows {}..{} of {}: merge the slices first (form-factors --merge)",
            path.display(),
            m.rows_from,
            m.rows_to,
            m.scene.patches
        );
    }
    Ok(m.rows)
}

/// Writes the matrix slice `file` to `--out` and says what it holds.
fn write_matrix(a: &FormFactorsArgs, file: &MatrixFile) -> Result<()> {
    let target = a.out.as_deref().expect("clap requires --out");
    write_file(target, &file.to_json())?;
    let mut out = Out::new();
    say!(
        out,
        "{}: rows {}..{} of {} ({} form factors)",
        target.display(),
        file.rows_from,
        file.rows_to,
        file.scene.patches,
        file.rows.iter().map(|r| r.entries.len()).sum::<usize>()
    );
    out.flush()
}

/// `form-factors` on an OBJ scene: the options of 2D scenes only refused by name.
fn form_factors_3d(a: &FormFactorsArgs, path: &Path) -> Result<()> {
    if a.ff.arith != Arith::Float {
        bail!("--arith fixed belongs to 2D scenes: in 3D, form-factors traces in f64");
    }
    if let Some(rows) = a.rows {
        return matrix_3d(a, path, rows);
    }
    super::d3_cli::form_factors_cmd(super::d3_cli::FormFactors3 {
        scene: path,
        source: a.source,
        origin: a.origin.as_ref(),
        normal: a.normal.as_ref(),
        rays: a.ff.rays,
        origins: a.ff.origins,
        ray_set: a.ff.ray_set,
        method: a.ff.method.as_ref(),
        json: a.json,
        tune: &a.tune,
    })
}

/// `form-factors --rows A..B --out FILE` on an OBJ scene: the slice of the 3D matrix, as in 2D.
fn matrix_3d(a: &FormFactorsArgs, path: &Path, rows: RowsArg) -> Result<()> {
    use shelling::d3::form_factors as ff3;
    if a.origin.is_some() || a.source.is_some() {
        bail!("--rows is a slice of the matrix: not with --source or --origin");
    }
    let params = params_3d(&a.ff, &a.tune, Method3::Conventional)?;
    let (scene, grid) = super::d3_cli::load(path, &a.tune)?;
    let range = rows.resolve(scene.polygons.len())?;
    let bar = progress_bar(range.len(), "rows", a.quiet);
    let done = ff3::rows(&scene, &grid, range.clone(), &params, || bar.inc(1));
    bar.finish_and_clear();
    write_matrix(a, &MatrixFile::new3(&scene, &params, a.ff.ray_set, range.start, done?))
}

/// The 3D estimate's parameters from the options: `--rays` (default 4096), `--origins` (256),
/// `--ray-set`, `--method` (a 3D technique, default `default`) and the polar sectors.
fn params_3d(
    ff: &FfArgs,
    tune: &TuneArgs,
    default: Method3,
) -> Result<shelling::d3::form_factors::Ff3Params> {
    use shelling::d3::form_factors as ff3;
    let method = super::d3_cli::MethodArg::three_d(ff.method.as_ref(), default)?;
    let rays = ff.rays.unwrap_or(ff3::DEFAULT_RAYS);
    check_range("--rays", rays, 1, shelling::d3::hemisphere::MAX_HEMISPHERE_RAYS)
        .map_err(anyhow::Error::msg)?;
    let origins = ff.origins.unwrap_or(ff3::DEFAULT_ORIGINS);
    check_range("--origins", origins, 1, MAX_ORIGINS).map_err(anyhow::Error::msg)?;
    Ok(ff3::Ff3Params {
        rays,
        origins,
        strata: super::d3_cli::strata(ff.ray_set),
        method,
        shells: super::d3_cli::polar_params(tune)?,
    })
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Solver {
    /// Progressive refinement: shoot the patch of most unshot power, one row per step.
    Progressive,
    /// Gauss–Seidel over the whole form-factor matrix.
    Full,
}

#[derive(Args)]
pub struct RadiosityArgs {
    /// Scene file: JSON segments (SCENES.md) or an OBJ scene (SCENES3D.md); default: the
    /// default room of `scene gen --kind room`.
    #[arg(long)]
    scene: Option<PathBuf>,
    /// The solver.
    #[arg(long, value_enum, default_value_t = Solver::Progressive)]
    solver: Solver,
    /// When to stop, in [1e-12, 1): the unshot power over the emitted power (progressive), the
    /// relative residual (full).
    #[arg(long, default_value_t = 1e-3, allow_negative_numbers = true)]
    tolerance: f64,
    /// The most steps (shots or sweeps), 1 to 10^7; reaching it is an error.
    #[arg(long, default_value_t = 100_000, allow_negative_numbers = true)]
    max_steps: usize,
    /// A form-factor matrix file of the scene (form-factors --rows/--merge) for the full solver,
    /// instead of tracing.
    #[arg(long, value_name = "FILE",
          conflicts_with_all = ["rays", "origins", "ray_set", "method", "arith", "on_pe", "cells_per_segment", "shell_depth", "max_sector"])]
    matrix: Option<PathBuf>,
    /// Compute every form-factor row on the RTL processing element (co-simulated, every hit
    /// checked), and report the PE's cycles of the whole solve.
    #[arg(long, conflicts_with = "arith")]
    on_pe: bool,
    /// With --on-pe: host memory cycles per patch (T_c, 1 to 1024).
    #[arg(long, default_value_t = 1, requires = "on_pe", allow_negative_numbers = true)]
    tc: u32,
    /// With --on-pe: the PE's patch cache, in patches (1 to 1024).
    #[arg(long, value_name = "PATCHES", requires = "on_pe", allow_negative_numbers = true)]
    cache: Option<u32>,
    /// With --on-pe: the PE's simulator (auto: Verilator where installed).
    #[arg(long, value_enum, default_value_t = Engine::Auto, requires = "on_pe")]
    engine: Engine,
    /// With --on-pe and --solver full: compute the whole matrix on the parallel machine of this
    /// many PEs (1 to 8), the bundles back to back on each PE, its cache warm between them, the
    /// PEs sharing one host memory; without it, each bundle on a fresh PE.
    #[arg(long, requires = "on_pe", allow_negative_numbers = true)]
    pes: Option<usize>,
    /// With --pes: where the host memory puts the patches for the caches (as `machine --place`;
    /// default lines). 2D scenes only: a 3D solve's slices are new patches in every plane and
    /// stay at their index.
    #[arg(long, value_enum, requires = "pes")]
    place: Option<Placement>,
    /// With --on-pe: the clock rate of the solve's time, in MHz (default: the median post-route
    /// rate on ECP5 of the PE, hdl/fpga/ecp5.md, or with --pes of the machine of that many PEs
    /// where it was measured, hdl/fpga/ecp5-machine.md, else the PE's).
    #[arg(long, requires = "on_pe", allow_negative_numbers = true)]
    clock_mhz: Option<f64>,
    /// Print the solution as JSON.
    #[arg(long)]
    json: bool,
    /// Draw the scene coloured by radiosity and the convergence curve into FILE (SVG).
    #[arg(long, value_name = "FILE")]
    svg: Option<PathBuf>,
    /// No progress bar.
    #[arg(long)]
    quiet: bool,
    #[command(flatten)]
    ff: FfArgs,
    #[command(flatten)]
    tune: TuneArgs,
}

#[derive(serde::Serialize)]
struct PatchJson {
    index: usize,
    radiosity: f64,
}

#[derive(serde::Serialize)]
struct HardwareJson {
    engine: &'static str,
    method: Method,
    tc: u32,
    cache: Option<u32>,
    #[serde(flatten)]
    totals: PeTotals,
    /// The machine's PEs (`--pes`), or none: each bundle on a fresh PE.
    pes: Option<usize>,
    clock_mhz: f64,
    /// The PE's (the machine's) cycles at `clock_mhz`.
    seconds: f64,
}

#[derive(serde::Serialize)]
struct SolutionJson {
    scene: String,
    solver: Solver,
    patches: Vec<PatchJson>,
    steps: usize,
    unshot: f64,
    emitted: f64,
    absorbed: f64,
    /// Form-factor rows computed.
    rows: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    hardware: Option<HardwareJson>,
}

pub fn radiosity_cmd(a: RadiosityArgs) -> Result<()> {
    let mut out = Out::new();
    if let Some(svg) = &a.svg {
        limits::check_output_file("--svg", svg).map_err(anyhow::Error::msg)?;
    }
    solve::check_tolerance(a.tolerance)?;
    check_range("--max-steps", a.max_steps, 1, MAX_STEPS).map_err(anyhow::Error::msg)?;
    if a.matrix.is_some() && a.solver != Solver::Full {
        bail!("--matrix needs --solver full: progressive refinement computes its rows as it shoots");
    }
    if a.on_pe {
        if a.ff.method.as_ref().is_some_and(|m| m.0 == Method::Brute.name()) {
            bail!("--method brute has no hardware mapping: use conventional, stochastic or deterministic");
        }
        check_range("--tc", a.tc, 1, limits::MAX_TC).map_err(anyhow::Error::msg)?;
        if let Some(c) = a.cache {
            limits::check_cache("--cache", c).map_err(anyhow::Error::msg)?;
        }
        if let Some(c) = a.clock_mhz.filter(|c| !(c.is_finite() && *c > 0.0 && *c <= 10_000.0)) {
            bail!("--clock-mhz must be a positive number up to 10000, got {c}");
        }
        if let Some(n) = a.pes {
            check_range("--pes", n, 1, MAX_PES).map_err(anyhow::Error::msg)?;
            if a.solver != Solver::Full {
                bail!(
                    "--pes {n} needs --solver full: the machine computes the whole matrix before the solve"
                );
            }
        }
    }
    if let Some(p) = a.scene.as_deref() {
        if super::d3_cli::is_3d(p)? {
            return radiosity_3d(&a, p);
        }
    }
    let (scene, name) = match &a.scene {
        Some(p) => (Scene::load(p)?, p.display().to_string()),
        None => (scene::room(&RoomSpec::default())?, "the default room".to_string()),
    };
    let surfaces = Surfaces::of(&scene, &name)?;
    let mut params = a.ff.params(&a.tune, a.on_pe)?;
    if a.on_pe {
        params.arith = Arith::Fixed;
    }
    let grid = a.tune.grid(scene.len())?;
    let prepared = GriddedScene::new(scene, grid);
    check_depth(&a.tune, &prepared)?;
    let engine = a.engine.resolve(false);
    let config = CosimConfig { tc: a.tc, cache: a.cache, vcd: None, engine };
    let clock_mhz =
        a.clock_mhz.or_else(|| a.pes.and_then(on_pe::machine_clock_mhz)).unwrap_or_else(on_pe::pe_clock_mhz);
    let mut totals = PeTotals::default();
    let mut row = |k: usize| -> Result<Row> {
        Ok(if a.on_pe {
            on_pe::row(&prepared, k, &params, &config, &mut totals)?
        } else {
            form_factors::row(&prepared, k, &params)?
        })
    };

    let solution: Solution = match a.solver {
        Solver::Progressive => {
            // The number of shots is not known in advance: a spinner with the count.
            let bar = match a.quiet {
                true => indicatif::ProgressBar::hidden(),
                false => indicatif::ProgressBar::new_spinner(),
            };
            let mut shots = 0u64;
            let s = solve::progressive(&surfaces, a.tolerance, a.max_steps, |k| {
                shots += 1;
                bar.set_message(format!("{shots} shots (patch {k})"));
                bar.tick();
                row(k)
            });
            bar.finish_and_clear();
            s?
        }
        Solver::Full => {
            let rows: Vec<Row> = match &a.matrix {
                Some(path) => whole_matrix(path, |m, p| m.check_scene(&prepared.scene, p, &name))?,
                None if a.on_pe && a.pes.is_some() => {
                    let machine = MachineConfig {
                        pes: a.pes.unwrap_or(1),
                        tc: a.tc,
                        cache: a.cache,
                        deal: Deal::Blocks,
                        place: a.place.unwrap_or(Placement::Lines),
                        engine,
                        vcd: None,
                    };
                    let bar = progress_bar(
                        prepared.scene.len() * params.origins,
                        "bundles on the machine",
                        a.quiet,
                    );
                    let done = on_pe::all_rows_on_machine(&prepared, &params, &machine, |k, _| {
                        bar.set_position(k as u64)
                    });
                    bar.finish_and_clear();
                    let (rows, t) = done?;
                    totals = t;
                    rows
                }
                None if a.on_pe => {
                    let bar = progress_bar(prepared.scene.len(), "rows on the PE", a.quiet);
                    let done = on_pe::all_rows(&prepared, &params, &config, |k| bar.set_position(k as u64));
                    bar.finish_and_clear();
                    let (rows, t) = done?;
                    totals = t;
                    rows
                }
                None => {
                    let bar = progress_bar(prepared.scene.len(), "rows", a.quiet);
                    let rows = form_factors::rows(&prepared, 0..prepared.scene.len(), &params, || bar.inc(1));
                    bar.finish_and_clear();
                    rows?
                }
            };
            solve::full(&surfaces, &rows, a.tolerance, a.max_steps)?
        }
    };

    let hardware = a.on_pe.then(|| HardwareJson {
        engine: engine.name(),
        method: params.method,
        tc: a.tc,
        cache: a.cache,
        totals,
        pes: a.pes,
        clock_mhz,
        seconds: totals.cycles as f64 / (clock_mhz * 1e6),
    });
    if let Some(path) = &a.svg {
        let what = match a.solver {
            Solver::Progressive => "unshot / emitted",
            Solver::Full => "relative residual",
        };
        let title = format!("radiosity of {name} ({:?} solver)", a.solver).to_lowercase();
        let svg = shelling::radiosity::svg::render(&prepared.scene, &solution, &title, what)
            .map_err(anyhow::Error::msg)?;
        write_file(path, &svg)?;
    }
    if a.json {
        let json = SolutionJson {
            scene: name,
            solver: a.solver,
            patches: solution
                .radiosity
                .iter()
                .enumerate()
                .map(|(index, &radiosity)| PatchJson { index, radiosity })
                .collect(),
            steps: solution.steps,
            unshot: solution.unshot,
            emitted: solution.emitted,
            absorbed: solution.absorbed,
            rows: solution.rows.len(),
            hardware,
        };
        say!(out, "{}", serde_json::to_string_pretty(&json)?);
        return out.flush();
    }
    let (lo, hi) =
        solution.radiosity.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &b| (l.min(b), h.max(b)));
    say!(
        out,
        "{name}: {} patches, {} solver, {} steps, {} form-factor rows ({} origins × {} {} rays, {})",
        prepared.scene.len(),
        format!("{:?}", a.solver).to_lowercase(),
        solution.steps,
        solution.rows.len(),
        params.origins,
        params.rays,
        params.ray_set,
        params.method
    );
    say!(
        out,
        "radiosity {lo:.6} to {hi:.6}; left {:.3e}; emitted {:.6}, absorbed {:.6}",
        solution.unshot,
        solution.emitted,
        solution.absorbed
    );
    if let Some(h) = &hardware {
        say!(
            out,
            "on {} ({} simulation, T_c = {}, cache {}): {} bundles, {} cycles = {:.3} ms at {} MHz; every hit equals the bit-true model's, {} of {} rays the f64 golden model's (the rest within the documented bound)",
            h.pes.map_or("the PE, each bundle on a fresh one".to_string(), |n| format!("the machine of {n} PE{}", if n == 1 { "" } else { "s" })),
            h.engine,
            h.tc,
            h.cache.map_or("off".to_string(), |c| format!("{c} patches")),
            h.totals.bundles,
            h.totals.cycles,
            h.seconds * 1e3,
            h.clock_mhz,
            h.totals.golden_agree,
            h.totals.rays
        );
    }
    if let Some(path) = &a.svg {
        say!(out, "picture: {}", path.display());
    }
    out.flush()
}

#[derive(serde::Serialize)]
struct PatchJson3 {
    index: usize,
    /// The mean of the three channels.
    radiosity: f64,
    rgb: [f64; 3],
}

#[derive(serde::Serialize)]
struct ChannelJson {
    channel: &'static str,
    steps: usize,
    unshot: f64,
    emitted: f64,
    absorbed: f64,
    escaped: f64,
}

/// `radiosity --json` on an OBJ scene: the 2D shape (the scalar values the means over the
/// channels, `steps` their sum, `unshot` their largest) with each polygon's `rgb`, the
/// `escaped` power, the estimate's parameters and each channel's own figures.
#[derive(serde::Serialize)]
struct SolutionJson3 {
    scene: String,
    solver: Solver,
    patches: Vec<PatchJson3>,
    steps: usize,
    unshot: f64,
    emitted: f64,
    absorbed: f64,
    escaped: f64,
    rows: usize,
    rays: usize,
    origins: usize,
    ray_set: RaySet,
    method: &'static str,
    channels: Vec<ChannelJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    hardware: Option<Hardware3Json>,
}

/// `radiosity --on-pe --json` on an OBJ scene: the PE's side of the solve.
#[derive(serde::Serialize)]
struct Hardware3Json {
    engine: &'static str,
    /// The 2D technique of every sweep plane.
    plane_method: Method,
    tc: u32,
    cache: Option<u32>,
    /// The machine's PEs (`--pes`), or none: each pack of planes on a fresh PE.
    pes: Option<usize>,
    #[serde(flatten)]
    totals: shelling::d3::on_pe::Pe3Totals,
    clock_mhz: f64,
    /// The PE's cycles at `clock_mhz`.
    seconds: f64,
}

/// `radiosity` on an OBJ scene (RADIOSITY.md, "In 3D"): the 3D form factors of every polygon
/// and the 2D solvers in each colour channel; the options of 2D scenes only refused by name.
fn radiosity_3d(a: &RadiosityArgs, path: &Path) -> Result<()> {
    use shelling::d3::form_factors as ff3;
    use shelling::d3::on_pe as on_pe3;
    use shelling::d3::radiosity::{self as rad3, CHANNELS};
    let two_d = [("--arith fixed", a.ff.arith != Arith::Float), ("--svg", a.svg.is_some())];
    if let Some((option, _)) = two_d.iter().find(|(_, given)| *given) {
        bail!(
            "{option} belongs to 2D scenes: in 3D, radiosity traces every row with the 3D tracers in f64 \
             (or, with --on-pe, its sweep planes on the PE)"
        );
    }
    if let Some(p) = a.place {
        bail!(
            "--place {} belongs to 2D scenes: in 3D, every sweep plane's slices are new patches and stay at their index",
            p.to_possible_value().expect("a value").get_name()
        );
    }
    let default_method = if a.on_pe { Method3::Sweep } else { Method3::Conventional };
    let params = params_3d(&a.ff, &a.tune, default_method)?;
    let (rays, origins, method) = (params.rays, params.origins, params.method);
    let (scene, grid) = super::d3_cli::load(path, &a.tune)?;
    if a.on_pe {
        on_pe3::check_params(&params)?;
    }
    let config = CosimConfig { tc: a.tc, cache: a.cache, vcd: None, engine: a.engine.resolve(false) };
    let name = path.display().to_string();
    // A scene that cannot be solved is refused before any row is traced.
    rad3::check(&scene, &name)?;
    let n = scene.polygons.len();
    let mut totals = on_pe3::Pe3Totals::default();
    let solution = match a.solver {
        Solver::Progressive => {
            let bar = progress_bar(n, "rows", a.quiet);
            let s = rad3::progressive(&scene, &name, a.tolerance, a.max_steps, |k| {
                let r = match a.on_pe {
                    true => {
                        on_pe3::row(&scene, k, &params, &config, &mut totals).map_err(anyhow::Error::from)
                    }
                    false => ff3::row(&scene, &grid, k, &params).map_err(anyhow::Error::from),
                };
                bar.inc(1);
                r
            });
            bar.finish_and_clear();
            s?
        }
        Solver::Full => {
            let bar = progress_bar(n, "rows", a.quiet);
            let rows = match (a.on_pe, a.pes) {
                _ if a.matrix.is_some() => {
                    let path = a.matrix.as_deref().expect("matched");
                    whole_matrix(path, |m, p| m.check_scene3(&scene, p, &name))?
                }
                (true, Some(pes)) => {
                    let machine = MachineConfig {
                        pes,
                        tc: a.tc,
                        cache: a.cache,
                        deal: Deal::Blocks,
                        place: Placement::Index,
                        engine: config.engine,
                        vcd: None,
                    };
                    let done =
                        on_pe3::rows_on_machine(&scene, &params, &machine, |k, _| bar.set_position(k as u64));
                    let (rows, t) = done?;
                    totals = t;
                    rows
                }
                (true, None) => {
                    on_pe3::rows(&scene, 0..n, &params, &config, || bar.inc(1)).map(|(rows, t)| {
                        totals = t;
                        rows
                    })?
                }
                (false, _) => ff3::rows(&scene, &grid, 0..n, &params, || bar.inc(1))?,
            };
            bar.finish_and_clear();
            rad3::full(&scene, &name, &rows, a.tolerance, a.max_steps)?
        }
    };
    let clock_mhz =
        a.clock_mhz.or_else(|| a.pes.and_then(on_pe::machine_clock_mhz)).unwrap_or_else(on_pe::pe_clock_mhz);
    let hardware = a.on_pe.then(|| Hardware3Json {
        engine: config.engine.name(),
        pes: a.pes,
        plane_method: on_pe3::PLANE_METHOD,
        tc: a.tc,
        cache: a.cache,
        totals,
        clock_mhz,
        seconds: totals.pe.cycles as f64 / (clock_mhz * 1e6),
    });
    let mut out = Out::new();
    if a.json {
        let json = SolutionJson3 {
            scene: name,
            solver: a.solver,
            patches: (0..n)
                .map(|j| PatchJson3 { index: j, radiosity: solution.mean(j), rgb: solution.rgb(j) })
                .collect(),
            steps: solution.steps(),
            unshot: solution.unshot(),
            emitted: solution.mean_of(|s| s.emitted),
            absorbed: solution.mean_of(|s| s.absorbed),
            escaped: solution.mean_of(|s| s.escaped),
            rows: solution.rows.len(),
            rays,
            origins,
            ray_set: a.ff.ray_set,
            method: method.name(),
            channels: CHANNELS
                .iter()
                .zip(&solution.channels)
                .map(|(&channel, s)| ChannelJson {
                    channel,
                    steps: s.steps,
                    unshot: s.unshot,
                    emitted: s.emitted,
                    absorbed: s.absorbed,
                    escaped: s.escaped,
                })
                .collect(),
            hardware,
        };
        say!(out, "{}", serde_json::to_string_pretty(&json)?);
        return out.flush();
    }
    say!(
        out,
        "{name}: {n} polygons, {} solver, {} steps, {} form-factor rows ({origins} origins × {rays} {} rays, {method})",
        format!("{:?}", a.solver).to_lowercase(),
        solution.steps(),
        solution.rows.len(),
        a.ff.ray_set,
    );
    for (c, s) in CHANNELS.iter().zip(&solution.channels) {
        say!(
            out,
            "{c}: {} steps, left {:.3e}; emitted {:.6}, absorbed {:.6}, escaped {:.6}",
            s.steps,
            s.unshot,
            s.emitted,
            s.absorbed,
            s.escaped
        );
    }
    if let Some(h) = &hardware {
        let t = &h.totals;
        say!(
            out,
            "on {} ({} simulation, T_c = {}, cache {}): {} planes of {} bundles in {} packs, {} cycles = {:.3} ms \
             at {} MHz; every hit equals the bit-true model's, {} of {} rays the f64 golden model's of the slices; {} \
             host tests of polygons parallel to a plane; {} of {} rays hit the 3D brute force's polygon",
            h.pes.map_or("the PE, each pack of sweep planes on a fresh one".to_string(), |n| format!(
                "the machine of {n} PE{}, the packs of sweep planes its sources",
                if n == 1 { "" } else { "s" }
            )),
            h.engine,
            h.tc,
            h.cache.map_or("off".to_string(), |c| format!("{c} patches")),
            t.pe.bundles,
            t.origins,
            t.packs,
            t.pe.cycles,
            h.seconds * 1e3,
            h.clock_mhz,
            t.pe.golden_agree,
            t.pe.rays,
            t.host_tests,
            t.brute_agree,
            t.origins * rays
        );
    }
    say!(out, "{:>8}{:>14}{:>14}{:>14}{:>14}", "polygon", "B", "r", "g", "b");
    for j in 0..n {
        let [r, g, b] = solution.rgb(j);
        say!(out, "{j:>8}{:>14.6}{r:>14.6}{g:>14.6}{b:>14.6}", solution.mean(j));
    }
    out.flush()
}
