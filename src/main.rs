//! The `shelling` command line: scenes, tracing, the paper's figures and the demo.

use anyhow::{bail, Context, Result};
use clap::{ArgGroup, Args, Parser, Subcommand};
use shelling::agreement;
use shelling::arith::Arith;
use shelling::cosim::{self, CosimConfig, Engine, VcdWindow};
use shelling::counters::Counters;
use shelling::figures::{self, FigureOptions};
use shelling::geom::Vec2;
use shelling::grid::GridParams;
use shelling::rays::{Bundle, RaySet, Source};
use shelling::run::{Prepared, TraceJson};
use shelling::scene::{self, RoomSpec, Scene};
use shelling::trace::{Method, ShellParams};
use shelling_testbench::pe::{ModelCounts, PeCounters};
use std::path::PathBuf;
use std::process::ExitCode;

mod radiosity_cli;

#[derive(Parser)]
#[command(
    name = "shelling",
    version,
    about = "Shelling: form-factor ray casting on a pipelined intersection architecture",
    long_about = "Golden model and experiments of Shen, Deprettere and Dewilde (EGGH 1990): the \
                  conventional technique and the stochastic and deterministic shelling techniques \
                  over a uniform grid with macro-regions, with the paper's counters and figures."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run the built-in default scene: every technique against brute force (the counters
    /// table), conventional and stochastic shelling on the RTL processing element (cycles, a VCD
    /// window), the Verilog export, and pointers to the radiosity commands.
    Demo(DemoArgs),
    /// Scene files: generate the paper's workload or a closed room.
    Scene {
        #[command(subcommand)]
        command: SceneCommand,
    },
    /// Trace one source's ray bundle through a scene with one technique.
    Trace(TraceArgs),
    /// Reproduce the paper's Figures 7, 8, 9, 10, 11 and 13 (CSV and SVG plots), and measure its
    /// claim on the RTL processing element (cycles, efficiency, speedup against Eqs. 10-11).
    Figures(FiguresArgs),
    /// Rung 2: trace the paper's workload in f64 and in the bit-true fixed point, compare the
    /// nearest patch of every ray and explain every disagreement by the documented error bound.
    Agreement(AgreementArgs),
    /// Co-simulate one source on the RTL processing element (cycle-accurate, rust-hdl), fed by
    /// the shell scheduler, every hit checked against the bit-true model and the f64 golden
    /// model, with hardware cycle counts.
    Cosim(CosimArgs),
    /// Form factors F_ij of a scene's patches from the tracers' bundles: one row (--source), a
    /// slice of the matrix into a file (--rows), or the merge of slices (--merge).
    FormFactors(radiosity_cli::FormFactorsArgs),
    /// Solve a scene's radiosity (progressive refinement or a full solve), optionally with every
    /// form-factor row computed on the RTL processing element (--on-pe).
    Radiosity(radiosity_cli::RadiosityArgs),
    /// Write the Verilog of every RTL block (one file per block, module named after it) and a
    /// file list `files.f`, for Yosys, nextpnr or vendor tools.
    ExportVerilog(ExportArgs),
}

#[derive(Args)]
struct ExportArgs {
    /// Output directory (created if missing).
    #[arg(long)]
    out: PathBuf,
}

#[derive(Args)]
struct AgreementArgs {
    /// Scenes per segment length.
    #[arg(long, default_value_t = 1, allow_negative_numbers = true)]
    seeds: usize,
    /// Source patches per scene (spread evenly over the patch indices).
    #[arg(long, default_value_t = 20, allow_negative_numbers = true)]
    sources: usize,
    /// Rays per source.
    #[arg(long, default_value_t = 1024, allow_negative_numbers = true)]
    rays: usize,
    /// Ray set.
    #[arg(long, value_enum, default_value_t = RaySet::Angle)]
    ray_set: RaySet,
}

#[derive(Subcommand)]
enum SceneCommand {
    /// Write a scene, seeded and reproducible: N random segments of length L inside [0, 1024)²
    /// (--kind paper), or a closed room for radiosity (--kind room).
    Gen(GenArgs),
}

/// What `scene gen` generates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum SceneKind {
    /// The paper's workload: random segments of one length in [0, 1024)².
    Paper,
    /// A closed room for radiosity: walls split into patches facing in, boxes, lights.
    Room,
}

#[derive(Args)]
struct GenArgs {
    /// What to generate.
    #[arg(long, value_enum, default_value_t = SceneKind::Paper)]
    kind: SceneKind,
    /// Paper: number of segments (at least 1; default 1000).
    #[arg(long, allow_negative_numbers = true)]
    count: Option<usize>,
    /// Paper: length of every segment, in world units (positive, less than 1024; default 32).
    #[arg(long, allow_negative_numbers = true)]
    length: Option<f64>,
    /// Room: inner width (default 256).
    #[arg(long, allow_negative_numbers = true)]
    width: Option<f64>,
    /// Room: inner height (default 256).
    #[arg(long, allow_negative_numbers = true)]
    height: Option<f64>,
    /// Room: longest patch; walls and box sides are split into equal patches (default 8).
    #[arg(long, allow_negative_numbers = true)]
    patch_length: Option<f64>,
    /// Room: square boxes inside, placed at random by --seed (default 2).
    #[arg(long, allow_negative_numbers = true)]
    boxes: Option<usize>,
    /// Room: side of each box (default 48).
    #[arg(long, allow_negative_numbers = true)]
    box_size: Option<f64>,
    /// Room: emissive patches in the middle of the ceiling (default 2).
    #[arg(long, allow_negative_numbers = true)]
    lights: Option<usize>,
    /// Room: emission of each light, radiant exitance (default 1).
    #[arg(long, allow_negative_numbers = true)]
    emission: Option<f64>,
    /// Room: reflectance of every patch, in [0, 1) (default 0.5).
    #[arg(long, allow_negative_numbers = true)]
    reflectance: Option<f64>,
    /// Seed of the random generator: the same seed gives the same scene on every machine.
    #[arg(long, default_value_t = 7, allow_negative_numbers = true)]
    seed: u64,
    /// Output file; standard output when absent.
    #[arg(long)]
    out: Option<PathBuf>,
}

impl GenArgs {
    /// The scene asked for; an option of the other kind is an error, not silently ignored.
    fn generate(&self) -> Result<Scene> {
        let room_given = [
            ("--width", self.width.is_some()),
            ("--height", self.height.is_some()),
            ("--patch-length", self.patch_length.is_some()),
            ("--boxes", self.boxes.is_some()),
            ("--box-size", self.box_size.is_some()),
            ("--lights", self.lights.is_some()),
            ("--emission", self.emission.is_some()),
            ("--reflectance", self.reflectance.is_some()),
        ];
        let paper_given = [("--count", self.count.is_some()), ("--length", self.length.is_some())];
        let (other, kind) = match self.kind {
            SceneKind::Paper => (&room_given[..], "room"),
            SceneKind::Room => (&paper_given[..], "paper"),
        };
        if let Some((option, _)) = other.iter().find(|(_, given)| *given) {
            bail!("{option} belongs to --kind {kind}, not to the --kind you asked for");
        }
        Ok(match self.kind {
            SceneKind::Paper => {
                let count = self.count.unwrap_or(1000);
                if count == 0 {
                    bail!("--count must be at least 1, got 0");
                }
                scene::generate(count, self.length.unwrap_or(32.0), self.seed, scene::PAPER_WORLD)?
            }
            SceneKind::Room => {
                let d = RoomSpec::default();
                scene::room(&RoomSpec {
                    width: self.width.unwrap_or(d.width),
                    height: self.height.unwrap_or(d.height),
                    patch_length: self.patch_length.unwrap_or(d.patch_length),
                    boxes: self.boxes.unwrap_or(d.boxes),
                    box_size: self.box_size.unwrap_or(d.box_size),
                    lights: self.lights.unwrap_or(d.lights),
                    emission: self.emission.unwrap_or(d.emission),
                    reflectance: self.reflectance.unwrap_or(d.reflectance),
                    seed: self.seed,
                })?
            }
        })
    }
}

/// Options shared by every command that traces: the grid and the shell structure.
#[derive(Args, Clone)]
struct TuneArgs {
    /// Grid resolution: target number of cells per segment (λ); the grid has about λ·N cells.
    #[arg(long, default_value_t = 4.0, allow_negative_numbers = true)]
    cells_per_segment: f64,
    /// Shell depth Γ in world units, positive (default: 4 cell sides).
    #[arg(long, allow_negative_numbers = true)]
    shell_depth: Option<f64>,
    /// Widest sector in rays (the ray memory of one processing element), at least 1.
    #[arg(long, default_value_t = ShellParams::default().max_sector, allow_negative_numbers = true)]
    max_sector: usize,
}

impl TuneArgs {
    fn grid(&self) -> Result<GridParams> {
        if !(self.cells_per_segment.is_finite() && self.cells_per_segment > 0.0) {
            bail!("--cells-per-segment must be a positive number, got {}", self.cells_per_segment);
        }
        Ok(GridParams { cells_per_segment: self.cells_per_segment, cells_per_axis: None })
    }

    fn shells(&self) -> Result<ShellParams> {
        if let Some(d) = self.shell_depth {
            if !(d.is_finite() && d > 0.0) {
                bail!("--shell-depth must be a positive number, got {d}");
            }
        }
        if self.max_sector == 0 {
            bail!("--max-sector must be at least 1, got 0");
        }
        let p = ShellParams {
            shell_depth: self.shell_depth,
            max_sector: self.max_sector,
            min_sector: ShellParams::default().min_sector.min(self.max_sector),
            ..ShellParams::default()
        };
        p.validate().map_err(|e| anyhow::anyhow!("{e}"))?;
        Ok(p)
    }
}

/// A scene and one source's ray bundle in it.
#[derive(Args)]
#[command(group(ArgGroup::new("from").args(["source", "origin"]).required(true)))]
struct SourceArgs {
    /// Scene file (JSON, see SCENES.md).
    #[arg(long)]
    scene: PathBuf,
    /// Source patch K (index into the scene's segments): the origin is its midpoint, the normal its
    /// normal; it is excluded from hits. Give either --source or --origin with --normal.
    #[arg(long, conflicts_with_all = ["origin", "normal"], allow_negative_numbers = true)]
    source: Option<usize>,
    /// Free origin X,Y (with --normal) instead of a source patch.
    #[arg(long, value_parser = parse_vec2, requires = "normal", allow_hyphen_values = true)]
    origin: Option<Vec2>,
    /// Normal NX,NY of a free origin (normalised; must be non-zero).
    #[arg(long, value_parser = parse_vec2, requires = "origin", allow_hyphen_values = true)]
    normal: Option<Vec2>,
    /// Number of rays over the half-circle.
    #[arg(long, default_value_t = 1024, allow_negative_numbers = true)]
    rays: usize,
    /// Ray set: `angle` (uniform in angle) or `sine` (uniform in sin φ, form factor 1/R each).
    #[arg(long, value_enum, default_value_t = RaySet::Angle)]
    ray_set: RaySet,
}

impl SourceArgs {
    /// Loads the scene, builds its grid and the bundle.
    fn load(&self, grid: GridParams) -> Result<(Prepared, Bundle)> {
        let scene = Scene::load(&self.scene)?;
        let prepared = Prepared::new(scene, grid);
        let source = match (self.source, self.origin, self.normal) {
            (Some(k), _, _) => Source::from_patch(&prepared.scene.segments, k)?,
            (None, Some(o), Some(n)) => Source::at(o, n)?,
            _ => bail!("give either --source K or both --origin X,Y and --normal NX,NY"),
        };
        let bundle = Bundle::new(source, self.ray_set, self.rays)?;
        Ok((prepared, bundle))
    }
}

#[derive(Args)]
struct CosimArgs {
    #[command(flatten)]
    from: SourceArgs,
    /// Technique: conventional, stochastic or deterministic (brute force has no hardware
    /// mapping).
    #[arg(long, value_enum, default_value_t = Method::Stochastic)]
    method: Method,
    /// Cycles the host memory takes to deliver one patch (T_c, at least 1).
    #[arg(long, default_value_t = 1)]
    tc: u32,
    /// Give the PE a patch cache of this many patches (a power of two up to 4096): a patch
    /// loaded before costs one clock instead of T_c. Without it every load goes to the host.
    #[arg(long, value_name = "PATCHES")]
    cache: Option<u32>,
    /// Write a VCD of the whole PE to FILE (cycles --vcd-from .. --vcd-to).
    #[arg(long, value_name = "FILE")]
    vcd: Option<PathBuf>,
    /// First cycle (from power-up) written to the VCD.
    #[arg(long, requires = "vcd", default_value_t = 0)]
    vcd_from: u64,
    /// End (exclusive) of the VCD window; default 2000 cycles after --vcd-from.
    #[arg(long, requires = "vcd")]
    vcd_to: Option<u64>,
    /// Print the trace JSON (the PE's hits) with the hardware counters.
    #[arg(long)]
    json: bool,
    /// The PE's simulator: rust-hdl's (VCD windows) or the exported Verilog compiled by
    /// Verilator (built once and cached; tens of times faster, no VCD); auto takes Verilator
    /// where it is installed and no VCD is asked for. All give the same cycles.
    #[arg(long, value_enum, default_value_t = Engine::Auto)]
    engine: Engine,
    #[command(flatten)]
    tune: TuneArgs,
}

#[derive(Args)]
struct TraceArgs {
    #[command(flatten)]
    from: SourceArgs,
    /// Tracing technique.
    #[arg(long, value_enum, default_value_t = Method::Stochastic)]
    method: Method,
    /// Arithmetic of the hit tests: `float` (the f64 golden model) or `fixed` (the bit-true
    /// model of the RTL datapath, hdl/FORMATS.md; the scene must fit its 2048-unit window).
    #[arg(long, value_enum, default_value_t = Arith::Float)]
    arith: Arith,
    /// Print the full result as JSON (every ray's hit and the counters).
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    tune: TuneArgs,
}

#[derive(Args)]
struct DemoArgs {
    /// Seed of the default scene.
    #[arg(long, default_value_t = 7, allow_negative_numbers = true)]
    seed: u64,
    /// Segment length of the default scene.
    #[arg(long, default_value_t = 32.0, allow_negative_numbers = true)]
    length: f64,
    /// Source patch (250 has an ADLC near the mean of the length-32 workload).
    #[arg(long, default_value_t = 250, allow_negative_numbers = true)]
    source: usize,
    /// Number of rays.
    #[arg(long, default_value_t = 1024, allow_negative_numbers = true)]
    rays: usize,
    /// Host memory cycles per patch (T_c) of the co-simulation.
    #[arg(long, default_value_t = 16)]
    tc: u32,
    /// VCD of the stochastic co-simulation's cycles 1000..1600.
    #[arg(long, default_value = "waveforms/demo.vcd")]
    vcd: PathBuf,
    /// Where to export the Verilog of every block.
    #[arg(long, default_value = "out/verilog")]
    verilog: PathBuf,
}

#[derive(Args)]
struct FiguresArgs {
    /// Output directory for figures.csv and the SVG plots.
    #[arg(long)]
    out: PathBuf,
    /// Scenes (seeds) per segment length.
    #[arg(long, default_value_t = 5, allow_negative_numbers = true)]
    seeds: usize,
    /// Source patches per scene.
    #[arg(long, default_value_t = 100, allow_negative_numbers = true)]
    sources: usize,
    /// Rays per source.
    #[arg(long, default_value_t = 1024, allow_negative_numbers = true)]
    rays: usize,
    /// Segments per scene.
    #[arg(long, default_value_t = 1000, allow_negative_numbers = true)]
    count: usize,
    /// Segment lengths, comma separated (e.g. 8,32).
    #[arg(long, value_delimiter = ',', default_value = "4,8,16,32,64,128", allow_hyphen_values = true)]
    lengths: Vec<f64>,
    /// Ray set.
    #[arg(long, value_enum, default_value_t = RaySet::Angle)]
    ray_set: RaySet,
    /// No progress bar.
    #[arg(long)]
    quiet: bool,
    /// Sources per segment length co-simulated on the processing element for the cycle figures
    /// (of the first seed's scene, spread over its patches); 0 skips them. The default 20 take
    /// about 80 s of CPU on the compiled PE (--engine auto finds Verilator), about an hour of CPU on
    /// rust-hdl's simulation.
    #[arg(long, default_value_t = 20, allow_negative_numbers = true)]
    cosim_sources: usize,
    /// Host memory load times T_c (cycles per patch) co-simulated, comma separated; each runs
    /// without and with the patch cache.
    #[arg(long = "tc", value_delimiter = ',', default_value = "1,4,16,64", allow_hyphen_values = true)]
    tcs: Vec<u32>,
    /// Lines of the patch cache in the co-simulations with the cache (a power of two up to 4096).
    #[arg(long, default_value_t = 1024, allow_negative_numbers = true)]
    cache_lines: u32,
    /// The PE's simulator for the co-simulations: rust-hdl's, or the exported Verilog compiled
    /// by Verilator (built once and cached; tens of times faster); auto takes Verilator where it
    /// is installed. All give the same cycles.
    #[arg(long, value_enum, default_value_t = Engine::Auto)]
    engine: Engine,
    #[command(flatten)]
    tune: TuneArgs,
}

fn parse_vec2(s: &str) -> Result<Vec2, String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 2 {
        return Err(format!("expected two numbers X,Y, got {s:?}"));
    }
    let num = |p: &str| -> Result<f64, String> {
        let v: f64 = p.parse().map_err(|_| format!("{p:?} is not a number"))?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(format!("{p:?} is not a finite number"))
        }
    };
    Ok(Vec2::new(num(parts[0])?, num(parts[1])?))
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", message(&e));
            ExitCode::from(2)
        }
    }
}

/// The error and its causes, joined by ": ", leaving out a cause whose text the message already
/// holds (the scene errors repeat their I/O error in their own text).
fn message(e: &anyhow::Error) -> String {
    let mut text = e.to_string();
    for cause in e.chain().skip(1) {
        let cause = cause.to_string();
        if !text.contains(&cause) {
            text.push_str(": ");
            text.push_str(&cause);
        }
    }
    text
}

fn run(cli: Cli) -> Result<()> {
    match cli.command {
        Command::Demo(a) => demo(a),
        Command::Scene { command: SceneCommand::Gen(a) } => {
            let s = a.generate()?;
            match a.out {
                Some(path) => s.save(&path)?,
                None => println!("{}", s.to_json()),
            }
            Ok(())
        }
        Command::Trace(a) => trace_cmd(a),
        Command::Cosim(a) => cosim_cmd(a),
        Command::FormFactors(a) => radiosity_cli::form_factors_cmd(a),
        Command::Radiosity(a) => radiosity_cli::radiosity_cmd(a),
        Command::ExportVerilog(a) => {
            let paths =
                shelling_testbench::export::write(&a.out).map_err(|e| anyhow::anyhow!("{}", e.message()))?;
            for p in paths {
                println!("{}", p.display());
            }
            Ok(())
        }
        Command::Agreement(a) => {
            let w = shelling::agreement::Workload {
                seeds: a.seeds,
                sources: a.sources,
                rays: a.rays,
                ray_set: a.ray_set,
                ..Default::default()
            };
            let report = shelling::agreement::run(&w)?;
            print!("{report}");
            let bad: usize = report.rows.iter().map(|r| r.comparison.beyond_bound().count()).sum();
            if bad > 0 {
                for r in &report.rows {
                    for d in r.comparison.beyond_bound().take(5) {
                        eprintln!("length {} {}: {d:?}", r.length, r.method);
                    }
                }
                bail!("{bad} rays differ beyond the documented error bound");
            }
            Ok(())
        }
        Command::Figures(a) => {
            let opts = FigureOptions {
                out: a.out,
                seeds: a.seeds,
                sources: a.sources,
                rays: a.rays,
                count: a.count,
                lengths: a.lengths,
                ray_set: a.ray_set,
                grid: a.tune.grid()?,
                shells: a.tune.shells()?,
                progress: !a.quiet,
                cosim_sources: a.cosim_sources,
                tcs: a.tcs,
                cache_lines: a.cache_lines,
                engine: a.engine.resolve(false),
            };
            let report = figures::run(&opts)?;
            println!("{report}");
            Ok(())
        }
    }
}

fn trace_cmd(a: TraceArgs) -> Result<()> {
    let (prepared, bundle) = a.from.load(a.tune.grid()?)?;
    let source = bundle.source;
    let result = prepared.trace_in(a.arith, a.method, &bundle, &a.tune.shells()?)?;
    if a.json {
        let json = serde_json::to_string_pretty(&TraceJson::new(&result, &bundle, a.arith))
            .context("serialising the trace")?;
        println!("{json}");
    } else {
        let hits = result.hits.iter().flatten().count();
        println!(
            "{} rays from ({:.3}, {:.3}) traced with {} in {} arithmetic: {} hit a patch, {} escaped",
            bundle.len(),
            source.origin.x,
            source.origin.y,
            a.method,
            a.arith,
            hits,
            bundle.len() - hits
        );
        print_counters(&[(a.method, result.counters)]);
        if result.stats.shells > 0 {
            println!(
                "shell structure: {} sectors, {} shells, S (fraction of rays leaving a shell) = {:.3}",
                result.stats.sectors,
                result.stats.shells,
                result.stats.leaving_fraction()
            );
        }
    }
    Ok(())
}

fn cosim_cmd(a: CosimArgs) -> Result<()> {
    if a.method == Method::Brute {
        bail!("--method brute has no hardware mapping: use conventional, stochastic or deterministic");
    }
    let (prepared, bundle) = a.from.load(a.tune.grid()?)?;
    let params = a.tune.shells()?;
    let scheduled = prepared.schedule(a.method, &bundle, &params)?;
    let vcd =
        a.vcd.map(|path| VcdWindow { path, from: a.vcd_from, to: a.vcd_to.unwrap_or(a.vcd_from + 2000) });
    if a.engine == Engine::Verilator && vcd.is_some() {
        bail!("--vcd needs --engine rust-hdl (or auto): the compiled PE writes no waveforms");
    }
    let config = CosimConfig { tc: a.tc, cache: a.cache, engine: a.engine.resolve(vcd.is_some()), vcd };
    let bar = indicatif::ProgressBar::new(scheduled.stream.items.len() as u64);
    if let Ok(style) = indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} commands {elapsed}") {
        bar.set_style(style);
    }
    let result = cosim::run(&scheduled, &config, |done, _| bar.set_position(done as u64));
    bar.finish_and_clear();
    let result = result?;
    let golden = prepared.trace(a.method, &bundle, &params)?;
    let rung2 = agreement::compare(&prepared.scene.segments, &bundle, &golden, &scheduled.trace);
    let beyond: Vec<_> = rung2.beyond_bound().collect();
    if !beyond.is_empty() {
        bail!("the PE's hits differ from the f64 golden model beyond the documented bound: {beyond:?}");
    }
    if a.json {
        let json = CosimJson {
            trace: TraceJson::new(&scheduled.trace, &bundle, Arith::Fixed),
            hardware: result.hardware,
            model: result.model,
            golden: GoldenJson { rays: rung2.rays, agree: rung2.agree, explained: rung2.rays - rung2.agree },
        };
        println!("{}", serde_json::to_string_pretty(&json).context("serialising the co-simulation")?);
        return Ok(());
    }
    let h = &result.hardware;
    println!(
        "{} rays, {} on the PE (T_c = {}, {} simulation): every hit equals the bit-true model's; {} of {} equal the f64 golden model's, the rest within the documented bound",
        bundle.len(),
        a.method,
        a.tc,
        config.engine.name(),
        rung2.agree,
        rung2.rays
    );
    println!(
        "cycles {}  intersection busy {}  pipeline efficiency {:.3}  stalls {} (sector drains {})",
        h.cycles, h.intersection_busy_cycles, h.pipeline_efficiency, h.stall_cycles, h.drain_cycles
    );
    println!(
        "patch loads {}  cache hits {}  passed {}  screened out {}  tests {}",
        h.patch_loads,
        h.cache_hits,
        h.passed,
        h.backward + h.back_facing + h.outside + h.near,
        h.tests
    );
    Ok(())
}

/// The `cosim` JSON output: the `trace` JSON of the PE's hits plus the hardware's counters.
#[derive(serde::Serialize)]
struct CosimJson {
    #[serde(flatten)]
    trace: TraceJson,
    hardware: PeCounters,
    model: ModelCounts,
    golden: GoldenJson,
}

/// The PE's hits against the f64 golden model's.
#[derive(serde::Serialize)]
struct GoldenJson {
    rays: usize,
    agree: usize,
    /// Rays whose nearest patch differs, every one explained by the documented bound.
    explained: usize,
}

fn demo(a: DemoArgs) -> Result<()> {
    let scene = scene::generate(1000, a.length, a.seed, scene::PAPER_WORLD)?;
    let prepared = Prepared::new(scene, GridParams::default());
    let bundle = prepared.patch_bundle(a.source, RaySet::Angle, a.rays)?;
    let params = ShellParams::default();
    println!(
        "default scene: 1000 segments of length {} in [0, 1024)², seed {}; grid {}×{} ({} macro-regions)",
        a.length,
        a.seed,
        prepared.grid.nx,
        prepared.grid.ny,
        prepared.grid.region_count()
    );
    println!("source: patch {} ({} rays, angle set)\n", a.source, a.rays);
    let oracle = prepared.trace(Method::Brute, &bundle, &params)?;
    let mut rows = Vec::new();
    for method in Method::ALL {
        let r = prepared.trace(method, &bundle, &params)?;
        let disagree = r.hits.iter().zip(&oracle.hits).filter(|(x, y)| x != y).count();
        if disagree > 0 {
            bail!("{method} disagrees with brute force on {disagree} rays");
        }
        rows.push((method, r.counters));
    }
    print_counters(&rows);
    println!("\nevery technique returned the brute-force nearest hit for all {} rays", bundle.len());

    // The hardware: conventional and stochastic shelling on the RTL processing element.
    println!(
        "\nco-simulation of the RTL processing element (rust-hdl, cycle-accurate), host memory T_c = {} cycles per patch:",
        a.tc
    );
    println!(
        "{:<14}{:>8}{:>10}{:>10}{:>10}{:>12}{:>12}{:>10}",
        "method", "cache", "loads", "tests", "cycles", "efficiency", "drains", "speedup"
    );
    let mut base: Option<u64> = None;
    for (method, cache) in
        [(Method::Conventional, None), (Method::Conventional, Some(1024)), (Method::Stochastic, None)]
    {
        let scheduled = prepared.schedule(method, &bundle, &params)?;
        let vcd =
            (method == Method::Stochastic).then(|| VcdWindow { path: a.vcd.clone(), from: 1000, to: 1600 });
        let run = cosim::run(
            &scheduled,
            &CosimConfig { tc: a.tc, cache, vcd, ..CosimConfig::default() },
            |_, _| {},
        )?;
        let rung2 = agreement::compare(&prepared.scene.segments, &bundle, &oracle, &scheduled.trace);
        if rung2.beyond_bound().next().is_some() {
            bail!("{method}: the PE's hits differ from the golden model beyond the documented bound");
        }
        let h = &run.hardware;
        let speedup = base.get_or_insert(h.cycles);
        println!(
            "{:<14}{:>8}{:>10}{:>10}{:>10}{:>12.3}{:>12}{:>9.2}×",
            method.name(),
            cache.map_or("-".to_string(), |c| c.to_string()),
            h.patch_loads,
            h.tests,
            h.cycles,
            h.pipeline_efficiency,
            h.drain_cycles,
            *speedup as f64 / h.cycles as f64
        );
    }
    println!(
        "every PE hit equals the bit-true model's and the f64 golden model's within the documented bound; \
         speedup against conventional without cache"
    );
    println!("waveform: {} (cycles 1000..1600; open with waveforms/demo.gtkw)", a.vcd.display());
    let files =
        shelling_testbench::export::write(&a.verilog).map_err(|e| anyhow::anyhow!("{}", e.message()))?;
    println!("Verilog: {} files in {}", files.len(), a.verilog.display());
    println!(
        "\nwhat the rays are for (RADIOSITY.md): `shelling scene gen --kind room --out room.json`, then \
         `shelling form-factors --scene room.json --source 3` (one row of form factors) and \
         `shelling radiosity --scene room.json --svg room.svg` (the solution; `--on-pe` computes \
         every row on the RTL processing element)"
    );
    Ok(())
}

fn print_counters(rows: &[(Method, Counters)]) {
    let short = ["read before", "read after", "cells", "tests", "actual", "ADLC", "ADLC est."];
    print!("{:<14}", "method");
    for s in short {
        print!("{s:>12}");
    }
    println!();
    for (m, c) in rows {
        print!("{:<14}", m.name());
        for (i, v) in c.values().iter().enumerate() {
            if i >= 5 {
                print!("{v:>12.2}");
            } else {
                print!("{v:>12}");
            }
        }
        println!();
    }
}
