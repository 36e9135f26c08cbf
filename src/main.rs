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
use shelling::limits::{self, check_range, check_range_for};
use shelling::machine;
use shelling::rays::{Bundle, RaySet, Source};
use shelling::run::{GriddedScene, TraceJson};
use shelling::scene::{self, RoomSpec, Scene};
use shelling::staged::Staged;
use shelling::trace::{Method, ShellParams};
use shelling_testbench::pe::{ModelCounts, PeCounters};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

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
    /// Co-simulate one source on the RTL processing element, cycle-accurate (on rust-hdl's
    /// simulation or on its Verilog compiled by Verilator, see --engine), fed by the shell
    /// scheduler, every hit checked against the bit-true model and the f64 golden model, with
    /// hardware cycle counts.
    Cosim(CosimArgs),
    /// Co-simulate the parallel machine: a scene's sources dealt to N processing elements that
    /// share one host memory through the memory arbiter, cycle-accurate, every PE's hits
    /// checked against the bit-true model of its source.
    Machine(MachineArgs),
    /// The machine's figures: the workload's sources on 1 to 8 PEs, every technique, T_c and
    /// cache size, co-simulated (machine.csv, machine.md and SVG charts; FIGURES.md quotes them).
    MachineFigures(MachineFiguresArgs),
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
    /// Output directory (created if missing; written whole or not at all).
    #[arg(long)]
    out: PathBuf,
}

#[derive(Args)]
struct AgreementArgs {
    /// Scenes per segment length, 1 to 1000.
    #[arg(long, default_value_t = 1, allow_negative_numbers = true)]
    seeds: usize,
    /// Source patches per scene (spread evenly over the patch indices), 1 to 1000.
    #[arg(long, default_value_t = 20, allow_negative_numbers = true)]
    sources: usize,
    /// Rays per source, 1 to 1048576; --seeds × 6 lengths × --sources × --rays at most 2^30.
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
    /// The dimension: 2 (a JSON scene of segments) or 3 (an OBJ scene of polygons, SCENES3D.md:
    /// --count random squares of side --size in [0, 1024)³; needs --out).
    #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u8).range(2..=3), allow_negative_numbers = true)]
    dim: u8,
    /// 3D: side of every square patch, greater than 0 and less than 1024/√3 (default 32).
    #[arg(long, allow_negative_numbers = true)]
    size: Option<f64>,
    /// What to generate.
    #[arg(long, value_enum, default_value_t = SceneKind::Paper)]
    kind: SceneKind,
    /// Paper: number of segments, 1 to 1048576 (default 1000).
    #[arg(long, allow_negative_numbers = true)]
    count: Option<usize>,
    /// Paper: length of every segment, in world units: greater than 0, less than 1024 (default 32).
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
    /// Output file (written whole or not at all); standard output when absent.
    #[arg(long)]
    out: Option<PathBuf>,
}

impl GenArgs {
    /// The options of `--kind room`, each with whether it was given.
    fn room_options(&self) -> [(&'static str, bool); 8] {
        [
            ("--width", self.width.is_some()),
            ("--height", self.height.is_some()),
            ("--patch-length", self.patch_length.is_some()),
            ("--boxes", self.boxes.is_some()),
            ("--box-size", self.box_size.is_some()),
            ("--lights", self.lights.is_some()),
            ("--emission", self.emission.is_some()),
            ("--reflectance", self.reflectance.is_some()),
        ]
    }

    /// The scene asked for; an option of the other kind is an error, not silently ignored.
    fn generate(&self) -> Result<Scene> {
        let room_given = self.room_options();
        let paper_given = [("--count", self.count.is_some()), ("--length", self.length.is_some())];
        if self.size.is_some() && self.dim == 2 {
            bail!("--size belongs to --dim 3 (in 2D, --length gives the segments' length)");
        }
        let (other, kind) = match self.kind {
            SceneKind::Paper => (&room_given[..], "room"),
            SceneKind::Room => (&paper_given[..], "paper"),
        };
        if let Some((option, _)) = other.iter().find(|(_, given)| *given) {
            bail!("{option} belongs to --kind {kind}, not to the --kind you asked for");
        }
        Ok(match self.kind {
            SceneKind::Paper => {
                let (count, length) = (self.count.unwrap_or(1000), self.length.unwrap_or(32.0));
                check_range("--count", count, 1, limits::MAX_COUNT).map_err(anyhow::Error::msg)?;
                limits::check_length("--length", length).map_err(anyhow::Error::msg)?;
                scene::generate(count, length, self.seed, scene::PAPER_WORLD)?
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
    /// Between 0.001 and 1024, and λ·N at most 4194304 (2^22) cells.
    #[arg(long, default_value_t = 4.0, allow_negative_numbers = true)]
    cells_per_segment: f64,
    /// Shell depth Γ in world units (default: 4 cell sides): between 1/65536 and 1024 times the
    /// grid's larger side (and at least 2^-32 of the distance from the source to the grid's
    /// farthest corner).
    #[arg(long, allow_negative_numbers = true)]
    shell_depth: Option<f64>,
    /// Widest sector in rays (the ray memory of one processing element), 1 to 1048576
    /// (default 64).
    #[arg(long, allow_negative_numbers = true)]
    max_sector: Option<usize>,
    /// 3D scenes: the polar tracer's sector height in Φ-cells (the fixed angle's rows), 1 to
    /// 1048576 (default 4; fewer where the ray set has fewer cells).
    #[arg(long, allow_negative_numbers = true)]
    phi_cells: Option<usize>,
}

impl TuneArgs {
    /// The grid's parameters for a scene of `segments` segments: `--cells-per-segment` within
    /// its range and λ·N within the grid's.
    fn grid(&self, segments: usize) -> Result<GridParams> {
        limits::check_cells_per_segment("--cells-per-segment", self.cells_per_segment, segments)
            .map_err(anyhow::Error::msg)?;
        Ok(GridParams { cells_per_segment: self.cells_per_segment, cells_per_axis: None })
    }

    /// The shell parameters; the shell depth is checked against a scene's grid by
    /// [`TuneArgs::check_depth`].
    fn shells(&self) -> Result<ShellParams> {
        let phi_cells = self.phi_cells.unwrap_or(ShellParams::default().phi_cells);
        check_range("--phi-cells", phi_cells, 1, limits::MAX_BUNDLE_RAYS).map_err(anyhow::Error::msg)?;
        if let Some(d) = self.shell_depth {
            if !(d.is_finite() && d > 0.0) {
                bail!("--shell-depth must be a positive number, got {d}");
            }
        }
        let max_sector = self.max_sector.unwrap_or(ShellParams::default().max_sector);
        check_range("--max-sector", max_sector, 1, limits::MAX_BUNDLE_RAYS).map_err(anyhow::Error::msg)?;
        let p = ShellParams {
            shell_depth: self.shell_depth,
            max_sector,
            min_sector: ShellParams::default().min_sector.min(max_sector),
            phi_cells,
            ..ShellParams::default()
        };
        p.validate().map_err(anyhow::Error::msg)?;
        Ok(p)
    }

    /// [`TuneArgs::shells`] for a 2D command, which has no use for `--phi-cells`.
    fn shells_2d(&self) -> Result<ShellParams> {
        if self.phi_cells.is_some() {
            bail!("--phi-cells belongs to 3D scenes (the polar tracer's sectors)");
        }
        self.shells()
    }

    /// `--shell-depth` against the grid of side `width`, for a source whose farthest grid
    /// corner lies `far` away.
    fn check_depth(&self, width: f64, far: f64) -> Result<()> {
        if let Some(d) = self.shell_depth {
            limits::check_shell_depth("--shell-depth", d, width, far).map_err(anyhow::Error::msg)?;
        }
        Ok(())
    }
}

/// A scene and one source's ray bundle in it.
#[derive(Args)]
#[command(group(ArgGroup::new("from").args(["source", "origin"]).required(true)))]
struct SourceArgs {
    /// Scene file: JSON segments (SCENES.md) or, for `trace`, an OBJ scene of polygons
    /// (SCENES3D.md; a `.obj` name, or any file not starting with `{`).
    #[arg(long)]
    scene: PathBuf,
    /// Source patch K (index into the scene's segments or polygons, 0 to N−1): the origin is
    /// its midpoint (3D: its vertex centroid), the normal its (front) normal; it is excluded
    /// from hits. Give either --source or --origin with --normal.
    #[arg(long, conflicts_with_all = ["origin", "normal"], allow_negative_numbers = true)]
    source: Option<usize>,
    /// Free origin X,Y (3D: X,Y,Z) with --normal instead of a source patch; each coordinate
    /// between −1e9 and 1e9, the range of scene coordinates.
    #[arg(long, value_parser = d3_cli::parse_coords, requires = "normal", allow_hyphen_values = true)]
    origin: Option<d3_cli::Coords>,
    /// Normal NX,NY (3D: NX,NY,NZ) of a free origin (normalised; must be non-zero).
    #[arg(long, value_parser = d3_cli::parse_coords, requires = "origin", allow_hyphen_values = true)]
    normal: Option<d3_cli::Coords>,
    /// Number of rays over the half-circle: 1 to 1048576 (`cosim`: 1 to 1024, the processing
    /// element's ray memory). 3D: over the hemisphere, as n_theta × n_phi (SCENES3D.md).
    #[arg(long, default_value_t = 1024, allow_negative_numbers = true)]
    rays: usize,
    /// Ray set: `angle` (uniform in angle) or `sine` (uniform in sin φ, form factor 1/R each;
    /// in 3D the cosine-weighted set, each ray 1/R).
    #[arg(long, value_enum, default_value_t = RaySet::Angle)]
    ray_set: RaySet,
}

impl SourceArgs {
    /// Checks the options that need no scene: `--rays` up to `max_rays`, `--origin` and
    /// `--normal`.
    fn check(&self, max_rays: usize, note: &str) -> Result<()> {
        check_range_for("--rays", self.rays, 1, max_rays, note).map_err(anyhow::Error::msg)?;
        d3_cli::check_origin_normal(self.origin.as_ref(), self.normal.as_ref())
    }

    /// Loads the scene, builds its grid and the bundle, checking `--source`, the grid options
    /// and the shell depth against the scene.
    fn load(&self, tune: &TuneArgs) -> Result<(GriddedScene, Bundle)> {
        let scene = Scene::load(&self.scene)?;
        let grid = tune.grid(scene.segments.len())?;
        if let Some(k) = self.source {
            let n = scene.segments.len();
            check_range_for("--source", k, 0, n - 1, &format!("(the scene has {n} segments)"))
                .map_err(anyhow::Error::msg)?;
        }
        let prepared = GriddedScene::new(scene, grid);
        let source = match (self.source, &self.origin, &self.normal) {
            (Some(k), _, _) => Source::from_patch(&prepared.scene.segments, k)?,
            (None, Some(o), Some(n)) => Source::at(o.vec2("--origin")?, n.vec2("--normal")?)?,
            _ => bail!("give either --source K or both --origin X,Y and --normal NX,NY"),
        };
        let (lo, hi) = prepared.grid.extent();
        let far = [lo, hi, Vec2::new(lo.x, hi.y), Vec2::new(hi.x, lo.y)]
            .iter()
            .fold(0.0f64, |m, c| m.max((*c - source.origin).length()));
        tune.check_depth((hi - lo).max_element(), far)?;
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
    /// Cycles the host memory takes to deliver one patch (T_c), 1 to 1024.
    #[arg(long, default_value_t = 1, allow_negative_numbers = true)]
    tc: u32,
    /// Give the PE a patch cache of this many patches (1 to 1024): a patch
    /// loaded before costs one clock instead of T_c. Without it every load goes to the host.
    #[arg(long, value_name = "PATCHES", allow_negative_numbers = true)]
    cache: Option<u32>,
    /// Co-simulate the source on the parallel machine of this many PEs (1 to 8) sharing the
    /// host memory: its rays cut into as many contiguous sectors, one a PE (a ray always on
    /// one PE), each PE with its own cache; prints the machine's report (`machine`'s).
    #[arg(long, default_value_t = 1, allow_negative_numbers = true)]
    pes: usize,
    #[command(flatten)]
    vcd: VcdArgs,
    /// Print the trace JSON (the PE's hits) with the hardware counters (with --pes above 1:
    /// the machine's JSON, as `machine --json`).
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

/// A VCD window of a co-simulation (`cosim`: the PE; `machine`: the machine's own RTL, the
/// arbiter and every PE; `waveforms/machine.gtkw` views two PEs' memory traffic).
#[derive(Args)]
struct VcdArgs {
    /// Write a VCD of the whole design to FILE (cycles --vcd-from .. --vcd-to); written whole
    /// or not at all.
    #[arg(long, value_name = "FILE")]
    vcd: Option<PathBuf>,
    /// First cycle (from power-up) written to the VCD: it must fall within the run.
    #[arg(long, requires = "vcd", default_value_t = 0, allow_negative_numbers = true)]
    vcd_from: u64,
    /// End (exclusive) of the VCD window, 1 to 1000000 cycles after --vcd-from; default 2000
    /// cycles after --vcd-from.
    #[arg(long, requires = "vcd", allow_negative_numbers = true)]
    vcd_to: Option<u64>,
}

impl VcdArgs {
    /// The window asked for, checked, and the engine that writes it (`--engine verilator` and a
    /// VCD refused).
    fn window(&self, engine: Engine) -> Result<(Option<VcdWindow>, Engine)> {
        let vcd = self.vcd.clone().map(|path| VcdWindow {
            path,
            from: self.vcd_from,
            to: self.vcd_to.unwrap_or(self.vcd_from.saturating_add(2000)),
        });
        if let Some(v) = &vcd {
            cosim::check_vcd_window(v.from, v.to)?;
            shelling::limits::check_output_file("--vcd", &v.path).map_err(anyhow::Error::msg)?;
        }
        if engine == Engine::Verilator && vcd.is_some() {
            bail!("--vcd needs --engine rust-hdl (or auto): the compiled simulation writes no waveforms");
        }
        let engine = engine.resolve(vcd.is_some());
        Ok((vcd, engine))
    }
}

#[derive(Args)]
struct MachineFiguresArgs {
    /// Output directory (created).
    #[arg(long, default_value = "figures")]
    out: PathBuf,
    /// Segment lengths, comma separated.
    #[arg(long, value_delimiter = ',', default_value = "4,8,16,32,64,128", allow_hyphen_values = true)]
    lengths: Vec<f64>,
    /// Sources per length: a spatially compact run of the scene's patches.
    #[arg(long, default_value_t = 16, allow_negative_numbers = true)]
    sources: usize,
    /// PE counts, comma separated (1 among them: the speedups are over one PE).
    #[arg(long, value_delimiter = ',', default_value = "1,2,4,8", allow_hyphen_values = true)]
    pes: Vec<usize>,
    /// Host memory load times T_c (cycles per patch), comma separated.
    #[arg(long = "tc", value_delimiter = ',', default_value = "1,4,16,64", allow_hyphen_values = true)]
    tcs: Vec<u32>,
    /// Per-PE cache sizes, comma separated: `off` or 1 to 1024 patches.
    #[arg(long, value_delimiter = ',', default_value = "off,128,1024")]
    caches: Vec<String>,
    /// The PEs' simulator (auto: Verilator where installed).
    #[arg(long, value_enum, default_value_t = Engine::Auto)]
    engine: Engine,
}

/// `--cache` against a scene of `patches` patches: a size not a power of two spreads the patches
/// over the host memory's addresses, which must stay within the 16-bit ids.
fn check_memory_map(cache: Option<u32>, patches: usize) -> Result<()> {
    if let Some(c) = cache {
        shelling_testbench::pe::MemoryMap::new(Some(c), patches)
            .map_err(|e| anyhow::anyhow!("--cache {c}: {}", e.message()))?;
    }
    Ok(())
}

fn machine_figures_cmd(a: MachineFiguresArgs) -> Result<()> {
    use shelling::figures::machine::{write, MachineFigureOptions};
    let caches = a
        .caches
        .iter()
        .map(|c| match c.as_str() {
            "off" => Ok(None),
            n => n
                .parse::<u32>()
                .map(Some)
                .map_err(|_| anyhow::anyhow!("--caches {c}: each `off` or 1 to 1024 patches")),
        })
        .collect::<Result<Vec<_>>>()?;
    let o = MachineFigureOptions {
        out: a.out,
        lengths: a.lengths,
        sources: a.sources,
        pes: a.pes,
        tcs: a.tcs,
        caches,
        engine: a.engine,
        progress: std::io::IsTerminal::is_terminal(&std::io::stderr()),
        ..Default::default()
    };
    let t = std::time::Instant::now();
    let rows = write(&o)?;
    println!(
        "{} machine runs in {:.0} s, every hit checked: {}/machine.csv, machine.md and the charts",
        rows.len(),
        t.elapsed().as_secs_f64(),
        o.out.display()
    );
    Ok(())
}

#[derive(Args)]
struct MachineArgs {
    /// Scene file: JSON segments (SCENES.md).
    #[arg(long)]
    scene: PathBuf,
    /// Processing elements, 1 to 8 (the memory arbiter's).
    #[arg(long, default_value_t = 4, allow_negative_numbers = true)]
    pes: usize,
    /// First source patch.
    #[arg(long, default_value_t = 0, allow_negative_numbers = true)]
    first: usize,
    /// Source patches from --first on (default: every one to the scene's last).
    #[arg(long, allow_negative_numbers = true)]
    count: Option<usize>,
    /// How the sources, in Hilbert order of their midpoints, are dealt to the PEs.
    #[arg(long, value_enum, default_value_t = machine::Deal::Blocks)]
    deal: machine::Deal,
    /// How the host memory lays the patches out: in Hilbert order of their midpoints (neighbours in
    /// different cache lines) or in the file's order. --first and --count are the file's indices.
    #[arg(long, value_enum, default_value_t = machine::Layout::Hilbert)]
    layout: machine::Layout,
    /// Where the host memory puts the patches for the caches: in the line where the same and the
    /// next work items on a PE use the fewest others (lines), or patch k in slot k of the
    /// layout (index). No effect without --cache.
    #[arg(long, value_enum, default_value_t = machine::Placement::Lines)]
    place: machine::Placement,
    /// Technique: conventional, stochastic or deterministic.
    #[arg(long, value_enum, default_value_t = Method::Stochastic)]
    method: Method,
    /// Cycles the shared host memory takes to deliver one patch (T_c), 1 to 1024.
    #[arg(long, default_value_t = 16, allow_negative_numbers = true)]
    tc: u32,
    /// Give each PE a patch cache of this many patches (1 to 1024).
    #[arg(long, value_name = "PATCHES", allow_negative_numbers = true)]
    cache: Option<u32>,
    /// Rays per source over its half-circle: 1 to 1024 (the processing element's ray memory).
    #[arg(long, default_value_t = 1024, allow_negative_numbers = true)]
    rays: usize,
    /// Ray set.
    #[arg(long, value_enum, default_value_t = RaySet::Angle)]
    ray_set: RaySet,
    /// The PEs' simulator (auto: Verilator where installed and no VCD is asked for).
    #[arg(long, value_enum, default_value_t = Engine::Auto)]
    engine: Engine,
    #[command(flatten)]
    vcd: VcdArgs,
    /// Print the run's counts as JSON.
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    tune: TuneArgs,
}

#[derive(Args)]
struct TraceArgs {
    #[command(flatten)]
    from: SourceArgs,
    /// Tracing technique: 2D brute, conventional, stochastic or deterministic (default
    /// stochastic); 3D any of the 3D techniques (default conventional).
    #[arg(long, value_parser = d3_cli::parse_method)]
    method: Option<d3_cli::MethodArg>,
    /// Arithmetic of the hit tests: `float` (the f64 golden model) or `fixed` (the bit-true
    /// model of the RTL datapath, hdl/FORMATS.md; the scene must fit its 2048-unit window;
    /// 2D only).
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
    /// Seed of the default scene (any 64-bit number).
    #[arg(long, default_value_t = 7, allow_negative_numbers = true)]
    seed: u64,
    /// Segment length of the default scene: greater than 0, less than 1024.
    #[arg(long, default_value_t = 32.0, allow_negative_numbers = true)]
    length: f64,
    /// Source patch, 0 to 999 (250 has an ADLC near the mean of the length-32 workload).
    #[arg(long, default_value_t = 250, allow_negative_numbers = true)]
    source: usize,
    /// Number of rays, 1 to 1024 (the processing element's ray memory).
    #[arg(long, default_value_t = 1024, allow_negative_numbers = true)]
    rays: usize,
    /// Host memory cycles per patch (T_c) of the co-simulation, 1 to 1024.
    #[arg(long, default_value_t = 16, allow_negative_numbers = true)]
    tc: u32,
    /// VCD of the stochastic co-simulation's cycles 1000..1600, or of its last 600 cycles when
    /// it ends before cycle 1000 (written whole or not at all).
    #[arg(long, default_value = "waveforms/demo.vcd")]
    vcd: PathBuf,
    /// Where to export the Verilog of every block (written whole or not at all).
    #[arg(long, default_value = "out/verilog")]
    verilog: PathBuf,
}

#[derive(Args)]
struct FiguresArgs {
    /// Output directory for figures.csv and the SVG plots (figures3d.csv and figures3d.md with
    /// --dim 3; created if missing; the files appear only when the whole run succeeds).
    #[arg(long)]
    out: PathBuf,
    /// The dimension: 2 (the paper's segments: conventional, stochastic and deterministic) or 3
    /// (the 3D workload of --count squares per --sizes: conventional, polar and sweep; --rays
    /// must be 4·k², --ray-set angle or sine picks equal-angle or cosine-weighted cells).
    #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u8).range(2..=3), allow_negative_numbers = true)]
    dim: u8,
    /// 3D: the squares' sides, comma separated: 1 to 64 distinct sizes, each greater than 0 and
    /// less than 1024/√3 (default 2,4,8,16,32,64,128,256).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    sizes: Option<Vec<f64>>,
    /// Scenes (seeds) per segment length, 1 to 1000.
    #[arg(long, default_value_t = 5, allow_negative_numbers = true)]
    seeds: usize,
    /// Source patches per scene, 1 to --count; --seeds × lengths × --sources × --rays at most
    /// 2^30.
    #[arg(long, default_value_t = 100, allow_negative_numbers = true)]
    sources: usize,
    /// Rays per source, 1 to 1048576 (1 to 1024 with the co-simulations).
    #[arg(long, default_value_t = 1024, allow_negative_numbers = true)]
    rays: usize,
    /// Segments per scene, 1 to 1048576; --seeds × lengths × --count at most 2^24.
    #[arg(long, default_value_t = 1000, allow_negative_numbers = true)]
    count: usize,
    /// Segment lengths, comma separated (e.g. 8,32): 1 to 64 distinct lengths, each greater
    /// than 0 and less than 1024.
    #[arg(long, value_delimiter = ',', default_value = "4,8,16,32,64,128", allow_hyphen_values = true)]
    lengths: Vec<f64>,
    /// Ray set.
    #[arg(long, value_enum, default_value_t = RaySet::Angle)]
    ray_set: RaySet,
    /// No progress bar.
    #[arg(long)]
    quiet: bool,
    /// Sources per segment length co-simulated on the processing element for the cycle figures
    /// (of the first seed's scene, spread over its patches), 0 to --count; 0 skips them.
    /// Lengths × --cosim-sources × T_c values × 2 at most 4096 co-simulations. The default 20 take
    /// about 80 s of CPU on the compiled PE (--engine auto finds Verilator), about an hour of CPU on
    /// rust-hdl's simulation.
    #[arg(long, default_value_t = 20, allow_negative_numbers = true)]
    cosim_sources: usize,
    /// Host memory load times T_c (cycles per patch) co-simulated, comma separated: 1 to 16
    /// distinct values, each 1 to 1024; each runs without and with the patch cache.
    #[arg(long = "tc", value_delimiter = ',', default_value = "1,4,16,64", allow_hyphen_values = true)]
    tcs: Vec<u32>,
    /// Lines of the patch cache in the co-simulations with the cache (1 to 1024).
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

fn main() -> ExitCode {
    let matches = <Cli as clap::CommandFactory>::command().get_matches();
    let given = figures_2d_given(&matches);
    let cli = match <Cli as clap::FromArgMatches>::from_arg_matches(&matches) {
        Ok(cli) => cli,
        Err(e) => e.exit(),
    };
    match run(cli, &given) {
        Ok(()) => ExitCode::SUCCESS,
        // The reader of standard output went away (`shelling ... | head`): stop quietly.
        Err(e)
            if e.downcast_ref::<StdoutError>()
                .is_some_and(|s| s.0.kind() == std::io::ErrorKind::BrokenPipe) =>
        {
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {}", message(&e));
            ExitCode::from(2)
        }
    }
}

/// Writing to standard output failed.
#[derive(Debug, thiserror::Error)]
#[error("writing to standard output: {0}")]
struct StdoutError(std::io::Error);

/// Standard output, locked and buffered, whose write errors become a [`StdoutError`] (a closed
/// pipe ends the program quietly, any other error is reported in one line).
struct Out(std::io::BufWriter<std::io::StdoutLock<'static>>);

impl Out {
    fn new() -> Out {
        Out(std::io::BufWriter::new(std::io::stdout().lock()))
    }

    fn write_fmt(&mut self, args: std::fmt::Arguments<'_>) -> Result<()> {
        self.0.write_fmt(args).map_err(|e| StdoutError(e).into())
    }

    fn flush(&mut self) -> Result<()> {
        self.0.flush().map_err(|e| StdoutError(e).into())
    }
}

/// `writeln!` to an [`Out`], returning its error.
macro_rules! say {
    ($out:expr) => { $out.write_fmt(format_args!("\n"))? };
    ($out:expr, $($arg:tt)*) => {{
        $out.write_fmt(format_args!($($arg)*))?;
        $out.write_fmt(format_args!("\n"))?;
    }};
}

// After `say!`, which they use.
mod d3_cli;
mod radiosity_cli;

/// A progress bar on standard error (hidden where standard error is not a terminal).
fn progress_bar(len: u64, template: &str) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(len);
    if let Ok(style) = indicatif::ProgressStyle::with_template(template) {
        bar.set_style(style);
    }
    bar
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

/// Writes the Verilog of every block into `dir`, whole or not at all; the paths written.
fn export_verilog(dir: &Path) -> Result<Vec<PathBuf>> {
    let staged =
        Staged::dir(dir).with_context(|| format!("cannot create the directory {}", dir.display()))?;
    let paths = shelling_testbench::export::write(staged.path()).map_err(|e| {
        anyhow::anyhow!("{}", e.message().replace(&*staged.path().to_string_lossy(), &dir.to_string_lossy()))
    })?;
    let paths = paths.iter().map(|p| staged.final_path(p)).collect();
    staged.commit().with_context(|| format!("cannot write into {}", dir.display()))?;
    Ok(paths)
}

/// `scene gen`: the scene, written to `out` (whole or not at all) or standard output.
fn scene_gen(a: GenArgs) -> Result<()> {
    if a.dim == 3 {
        return scene_gen_3d(&a);
    }
    let spinner = indicatif::ProgressBar::new_spinner();
    spinner.set_message("generating the scene");
    spinner.enable_steady_tick(std::time::Duration::from_millis(200));
    let generated = a.generate();
    spinner.finish_and_clear();
    let s = generated?;
    match a.out {
        Some(path) => {
            let name = path.display().to_string();
            let io = |source| scene::SceneError::Io { name: name.clone(), action: "write", source };
            s.validate(&name)?;
            let staged = Staged::file(&path).map_err(io)?;
            std::fs::write(staged.path(), s.to_json()).map_err(io)?;
            staged.commit().map_err(io)?;
        }
        None => {
            let mut out = Out::new();
            out.write_fmt(format_args!("{}", s.to_json()))?;
            out.flush()?;
        }
    }
    Ok(())
}

/// `scene gen --dim 3`: the 3D workload as OBJ and MTL (SCENES3D.md).
fn scene_gen_3d(a: &GenArgs) -> Result<()> {
    let two_d = [("--kind room", a.kind == SceneKind::Room), ("--length", a.length.is_some())];
    if let Some((option, _)) = two_d.iter().chain(&a.room_options()).find(|(_, given)| *given) {
        bail!("{option} belongs to 2D scenes: --dim 3 takes --count, --size, --seed and --out");
    }
    let Some(out) = &a.out else { bail!("--dim 3 needs --out FILE.obj (the MTL file is written beside it)") };
    let (count, size) = (a.count.unwrap_or(1000), a.size.unwrap_or(32.0));
    check_range("--count", count, 1, limits::MAX_COUNT).map_err(anyhow::Error::msg)?;
    let limit = shelling::d3::gen::WORLD / 3f64.sqrt();
    if !(size.is_finite() && size > 0.0 && size < limit) {
        bail!("--size must be greater than 0 and less than {limit:.3} (1024/√3), got {size}");
    }
    let scene = shelling::d3::gen::generate(count, size, a.seed)?;
    let comment = format!(
        "shelling scene gen --dim 3 --count {count} --size {size} --seed {}\n{count} squares of side {size} \
         in [0, {})^3, counter-clockwise seen from the front (SCENES3D.md)",
        a.seed,
        shelling::d3::gen::WORLD
    );
    shelling::d3::obj::save(&scene, out, &comment)?;
    Ok(())
}

/// `figures`: every option checked against its range before anything runs.
fn figures_cmd(a: FiguresArgs, given: &[&'static str]) -> Result<()> {
    let m = anyhow::Error::msg;
    if a.dim == 3 {
        return figures_3d(a, given);
    }
    if a.sizes.is_some() {
        bail!("--sizes belongs to --dim 3 (in 2D, --lengths gives the segments' lengths)");
    }
    check_range("--seeds", a.seeds, 1, figures::MAX_SEEDS).map_err(m)?;
    check_range("--count", a.count, 1, limits::MAX_COUNT).map_err(m)?;
    check_range_for("--sources", a.sources, 1, a.count, "(--count)").map_err(m)?;
    check_range("--rays", a.rays, 1, limits::MAX_BUNDLE_RAYS).map_err(m)?;
    check_range("the number of --lengths", a.lengths.len(), 1, limits::MAX_LENGTHS).map_err(m)?;
    for (i, &l) in a.lengths.iter().enumerate() {
        limits::check_length("--lengths", l).map_err(m)?;
        if a.lengths[..i].contains(&l) {
            bail!("--lengths lists {l} twice");
        }
    }
    check_range_for("--cosim-sources", a.cosim_sources, 0, a.count, "(--count)").map_err(m)?;
    if a.cosim_sources > 0 {
        check_range_for(
            "--rays",
            a.rays,
            1,
            limits::PE_RAY_MEMORY,
            "(the processing element's ray memory) for the co-simulated figures (--cosim-sources 0 skips them)",
        )
        .map_err(m)?;
        check_range("the number of --tc values", a.tcs.len(), 1, limits::MAX_TCS).map_err(m)?;
        for (i, &tc) in a.tcs.iter().enumerate() {
            check_range("--tc", tc, 1, limits::MAX_TC).map_err(m)?;
            if a.tcs[..i].contains(&tc) {
                bail!("--tc lists {tc} twice");
            }
        }
        limits::check_cache("--cache-lines", a.cache_lines).map_err(m)?;
        let runs = [a.lengths.len(), a.cosim_sources, a.tcs.len(), 2].map(|v| v as u64);
        limits::check_product(
            "the co-simulations, lengths × --cosim-sources × --tc values × 2,",
            &runs,
            limits::MAX_COSIM_RUNS,
        )
        .map_err(m)?;
    }
    let (seeds, lengths) = (a.seeds as u64, a.lengths.len() as u64);
    limits::check_product(
        "the rays traced, --seeds × lengths × --sources × --rays,",
        &[seeds, lengths, a.sources as u64, a.rays as u64],
        limits::MAX_WORKLOAD_RAYS,
    )
    .map_err(m)?;
    limits::check_product(
        "the segments held, --seeds × lengths × --count,",
        &[seeds, lengths, a.count as u64],
        limits::MAX_WORKLOAD_SEGMENTS,
    )
    .map_err(m)?;
    let grid = a.tune.grid(a.count)?;
    let shells = a.tune.shells_2d()?;
    // The scenes fill the paper's world; the grid pads it by 0.1 % on every side.
    let side = scene::PAPER_WORLD.size().max_element() * 1.002;
    a.tune.check_depth(side, side * std::f64::consts::SQRT_2)?;
    let opts = FigureOptions {
        out: a.out,
        seeds: a.seeds,
        sources: a.sources,
        rays: a.rays,
        count: a.count,
        lengths: a.lengths,
        ray_set: a.ray_set,
        grid,
        shells,
        progress: !a.quiet,
        cosim_sources: a.cosim_sources,
        tcs: a.tcs,
        cache_lines: a.cache_lines,
        engine: a.engine.resolve(false),
    };
    let report = figures::run(&opts)?;
    let mut out = Out::new();
    say!(out, "{report}");
    out.flush()
}

/// The options of `figures` that only the 2D figures take (clap's ids).
const FIGURES_2D_ONLY: [(&str, &str); 5] = [
    ("lengths", "--lengths"),
    ("cosim_sources", "--cosim-sources"),
    ("tcs", "--tc"),
    ("cache_lines", "--cache-lines"),
    ("engine", "--engine"),
];

/// The 2D-only options of `figures` given on the command line.
fn figures_2d_given(matches: &clap::ArgMatches) -> Vec<&'static str> {
    let Some(m) = matches.subcommand_matches("figures") else { return Vec::new() };
    FIGURES_2D_ONLY
        .iter()
        .filter(|(id, _)| m.value_source(id) == Some(clap::parser::ValueSource::CommandLine))
        .map(|(_, option)| *option)
        .collect()
}

/// `figures --dim 3`: the 3D workload (src/figures/d3.rs), every option checked first.
fn figures_3d(a: FiguresArgs, given: &[&'static str]) -> Result<()> {
    if let Some(option) = given.first() {
        bail!("{option} belongs to the 2D figures: --dim 3 takes --sizes, --count, --seeds, --sources, --rays, --ray-set and the tuning options");
    }
    let sizes = a.sizes.unwrap_or_else(|| figures::d3::DEFAULT_SIZES.to_vec());
    check_range("--count", a.count, 1, limits::MAX_COUNT).map_err(anyhow::Error::msg)?;
    let (seeds, n) = (a.seeds as u64, sizes.len() as u64);
    limits::check_product(
        "the rays traced, --seeds × sizes × --sources × --rays,",
        &[seeds, n, a.sources as u64, a.rays as u64],
        limits::MAX_WORKLOAD_RAYS,
    )
    .map_err(anyhow::Error::msg)?;
    limits::check_product(
        "the squares held, --seeds × sizes × --count,",
        &[seeds, n, a.count as u64],
        limits::MAX_WORKLOAD_SEGMENTS,
    )
    .map_err(anyhow::Error::msg)?;
    let shells = a.tune.shells()?;
    // The 3D scenes fill [0, 1024)³; the grid pads it by 0.1 % on every side.
    let side = shelling::d3::gen::WORLD * 1.002;
    a.tune.check_depth(side, side * 3f64.sqrt())?;
    if !(a.tune.cells_per_segment.is_finite() && a.tune.cells_per_segment > 0.0) {
        bail!("--cells-per-segment must be a positive number, got {}", a.tune.cells_per_segment);
    }
    let opts = figures::d3::Figure3Options {
        out: a.out,
        seeds: a.seeds,
        sources: a.sources,
        rays: a.rays,
        count: a.count,
        sizes,
        strata: match a.ray_set {
            RaySet::Angle => shelling::d3::hemisphere::Strata::Angle,
            RaySet::Sine => shelling::d3::hemisphere::Strata::Cosine,
        },
        grid: shelling::d3::grid::Grid3Params {
            cells_per_polygon: a.tune.cells_per_segment,
            cells_per_axis: None,
        },
        shells,
        progress: !a.quiet,
    };
    let report = figures::d3::run(&opts)?;
    let mut out = Out::new();
    say!(out, "{report}");
    out.flush()
}

/// `agreement`: the paper's workload in f64 and in fixed point, with a progress bar.
fn agreement_cmd(a: AgreementArgs) -> Result<()> {
    let w = agreement::Workload {
        seeds: a.seeds,
        sources: a.sources,
        rays: a.rays,
        ray_set: a.ray_set,
        ..Default::default()
    };
    w.validate()?;
    let bar = progress_bar(0, "comparing {bar:40} {pos}/{len} sources [{elapsed_precise}, eta {eta}]");
    let report = agreement::run_with_progress(&w, |done, total| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    });
    bar.finish_and_clear();
    let report = report?;
    let mut out = Out::new();
    out.write_fmt(format_args!("{report}"))?;
    out.flush()?;
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

fn run(cli: Cli, figures_given: &[&'static str]) -> Result<()> {
    match cli.command {
        Command::Demo(a) => demo(a),
        Command::Scene { command: SceneCommand::Gen(a) } => scene_gen(a),
        Command::Trace(a) => trace_cmd(a),
        Command::Cosim(a) => cosim_cmd(a),
        Command::Machine(a) => machine_cmd(a),
        Command::MachineFigures(a) => machine_figures_cmd(a),
        Command::FormFactors(a) => radiosity_cli::form_factors_cmd(a),
        Command::Radiosity(a) => radiosity_cli::radiosity_cmd(a),
        Command::ExportVerilog(a) => {
            let paths = export_verilog(&a.out)?;
            let mut out = Out::new();
            for p in paths {
                say!(out, "{}", p.display());
            }
            out.flush()
        }
        Command::Agreement(a) => agreement_cmd(a),
        Command::Figures(a) => figures_cmd(a, figures_given),
    }
}

fn trace_cmd(a: TraceArgs) -> Result<()> {
    a.from.check(limits::MAX_BUNDLE_RAYS, "")?;
    if d3_cli::is_3d(&a.from.scene)? {
        return d3_cli::trace_cmd(&a);
    }
    let method = d3_cli::MethodArg::two_d(a.method.as_ref(), Method::Stochastic)?;
    let shells = a.tune.shells_2d()?;
    let (prepared, bundle) = a.from.load(&a.tune)?;
    let source = bundle.source;
    let result = prepared.trace_in(a.arith, method, &bundle, &shells)?;
    let mut out = Out::new();
    if a.json {
        let json = serde_json::to_string_pretty(&TraceJson::new(&result, &bundle, a.arith))
            .context("serialising the trace")?;
        say!(out, "{json}");
    } else {
        let hits = result.hits.iter().flatten().count();
        say!(
            out,
            "{} rays from ({:.3}, {:.3}) traced with {} in {} arithmetic: {} hit a patch, {} escaped",
            bundle.len(),
            source.origin.x,
            source.origin.y,
            method,
            a.arith,
            hits,
            bundle.len() - hits
        );
        print_counters(&mut out, &[(method.name(), result.counters)])?;
        if result.stats.shells > 0 {
            say!(
                out,
                "shell structure: {} sectors, {} shells, S (fraction of rays leaving a shell) = {:.3}",
                result.stats.sectors,
                result.stats.shells,
                result.stats.leaving_fraction()
            );
        }
    }
    out.flush()
}

fn cosim_cmd(a: CosimArgs) -> Result<()> {
    let m = anyhow::Error::msg;
    if a.method == Method::Brute {
        bail!("--method brute has no hardware mapping: use conventional, stochastic or deterministic");
    }
    a.from.check(limits::PE_RAY_MEMORY, "(the processing element's ray memory)")?;
    if d3_cli::is_3d(&a.from.scene)? {
        bail!("--scene {}: an OBJ scene is 3D, and the processing element is 2D", a.from.scene.display());
    }
    check_range("--tc", a.tc, 1, limits::MAX_TC).map_err(m)?;
    if let Some(c) = a.cache {
        limits::check_cache("--cache", c).map_err(m)?;
    }
    let (vcd, engine) = a.vcd.window(a.engine)?;
    let params = a.tune.shells_2d()?;
    check_range_for("--pes", a.pes, 1, shelling_hdl::arbiter::MAX_PES, "(the memory arbiter's ports)")
        .map_err(m)?;
    let (prepared, bundle) = a.from.load(&a.tune)?;
    check_memory_map(a.cache, prepared.scene.segments.len())?;
    if a.pes > 1 {
        return cosim_machine(&a, &prepared, &bundle, &params, vcd, engine);
    }
    let scheduled = prepared.schedule(a.method, &bundle, &params)?;
    let config = CosimConfig { tc: a.tc, cache: a.cache, engine, vcd };
    let bar = progress_bar(scheduled.stream.items.len() as u64, "{bar:40} {pos}/{len} commands {elapsed}");
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
            bound_cycles: cosim::bound_cycles(&result.hardware, a.tc),
            inorder_cycles: result.inorder_cycles,
            golden: GoldenJson { rays: rung2.rays, agree: rung2.agree, explained: rung2.rays - rung2.agree },
        };
        let mut out = Out::new();
        say!(out, "{}", serde_json::to_string_pretty(&json).context("serialising the co-simulation")?);
        return out.flush();
    }
    let h = &result.hardware;
    let mut out = Out::new();
    say!(
        out,
        "{} rays, {} on the PE (T_c = {}, {} simulation): every hit equals the bit-true model's; {} of {} equal the f64 golden model's, the rest within the documented bound",
        bundle.len(),
        a.method,
        a.tc,
        config.engine.name(),
        rung2.agree,
        rung2.rays
    );
    say!(
        out,
        "cycles {}  intersection busy {}  pipeline efficiency {:.3}  stalls {} (waiting on a sector {})",
        h.cycles,
        h.intersection_busy_cycles,
        h.pipeline_efficiency,
        h.stall_cycles,
        h.drain_cycles
    );
    say!(
        out,
        "patch loads {}  cache hits {}  passed {}  screened out {}  tests {}",
        h.patch_loads,
        h.cache_hits,
        h.passed,
        h.backward + h.back_facing + h.outside + h.near,
        h.tests
    );
    let bound = cosim::bound_cycles(h, a.tc);
    say!(
        out,
        "bound {bound} (max of host loads·T_c, loads, tests)  ideal in-order PE {}  cycles / bound {:.2}",
        result.inorder_cycles,
        h.cycles as f64 / bound.max(1) as f64
    );
    out.flush()
}

fn machine_cmd(a: MachineArgs) -> Result<()> {
    let m = anyhow::Error::msg;
    if a.method == Method::Brute {
        bail!("--method brute has no hardware mapping: use conventional, stochastic or deterministic");
    }
    check_range_for("--pes", a.pes, 1, shelling_hdl::arbiter::MAX_PES, "(the memory arbiter's ports)")
        .map_err(m)?;
    check_range("--tc", a.tc, 1, limits::MAX_TC).map_err(m)?;
    if let Some(c) = a.cache {
        limits::check_cache("--cache", c).map_err(m)?;
    }
    check_range_for("--rays", a.rays, 1, limits::PE_RAY_MEMORY, "(the processing element's ray memory)")
        .map_err(m)?;
    if d3_cli::is_3d(&a.scene)? {
        bail!("--scene {}: an OBJ scene is 3D, and the processing element is 2D", a.scene.display());
    }
    let params = a.tune.shells_2d()?;
    let scene = Scene::load(&a.scene)?;
    let n = scene.segments.len();
    check_memory_map(a.cache, n)?;
    check_range_for("--first", a.first, 0, n - 1, &format!("(the scene has {n} segments)")).map_err(m)?;
    let count = a.count.unwrap_or(n - a.first);
    check_range_for("--count", count, 1, n - a.first, &format!("(--first {} of {n} segments)", a.first))
        .map_err(m)?;
    let grid = a.tune.grid(n)?;
    let (scene, old_of_new) = machine::lay_out(scene, a.layout);
    let mut new_of_old = vec![0; n];
    for (new, &old) in old_of_new.iter().enumerate() {
        new_of_old[old] = new;
    }
    let prepared = GriddedScene::new(scene, grid);
    let ids: Vec<usize> = (a.first..a.first + count).map(|k| new_of_old[k]).collect();
    let order = machine::spatial_order(&prepared.scene.segments, &ids);
    let parts = a.deal.parts(a.pes);
    if parts > a.rays {
        bail!("--deal sectors on --pes {} needs at least one ray a PE: --rays {} is fewer", a.pes, a.rays);
    }
    let (lo, hi) = prepared.grid.extent();
    for &k in &order {
        let origin = prepared.patch_bundle(k, a.ray_set, a.rays)?.source.origin;
        let far = [lo, hi, Vec2::new(lo.x, hi.y), Vec2::new(hi.x, lo.y)]
            .iter()
            .fold(0.0f64, |m, c| m.max((*c - origin).length()));
        a.tune.check_depth((hi - lo).max_element(), far)?;
    }
    let schedules =
        machine::schedule_sources(&prepared, &order, a.method, a.ray_set, a.rays, &params, parts)?;
    let (vcd, engine) = a.vcd.window(a.engine)?;
    let config = machine::MachineConfig {
        pes: a.pes,
        tc: a.tc,
        cache: a.cache,
        deal: a.deal,
        place: a.place,
        engine,
        vcd,
    };
    let bar = progress_bar(schedules.len() as u64, "{bar:40} {pos}/{len} work items {elapsed}");
    let run = machine::run(&schedules, &config, |done, _| bar.set_position(done as u64));
    bar.finish_and_clear();
    let run = run?;
    let layout = if a.layout == machine::Layout::Hilbert { "Hilbert" } else { "the file's" };
    report_machine(&run, &config, a.json, a.rays, a.method, layout)
}

/// Prints a machine run of `config` (`machine`, `cosim --pes`): its JSON, or its summary.
fn report_machine(
    run: &machine::MachineRun,
    config: &machine::MachineConfig,
    json: bool,
    rays: usize,
    method: Method,
    layout: &str,
) -> Result<()> {
    let parts = run.parts;
    let mut out = Out::new();
    if json {
        say!(out, "{}", serde_json::to_string_pretty(run).context("serialising the machine run")?);
        return out.flush();
    }
    say!(
        out,
        "{} sources of {} rays, {} on {} PEs ({} simulation), T_c = {}, caches {}, patches in {} order, dealt as {}{}: every hit equals the bit-true model's",
        run.sources,
        rays,
        method,
        run.pes,
        config.engine.name(),
        config.tc,
        config.cache.map_or("off".to_string(), |c| format!("of {c} patches, placed by {}", config.place.name())),
        layout,
        config.deal.name(),
        if parts > 1 { format!(" ({parts} per source)") } else { String::new() }
    );
    say!(
        out,
        "cycles {}  per source {:.0}  rays per cycle {:.3}  (summed over the sources, overlapped in each PE: setup {}, commands {}, readout {})",
        run.cycles,
        run.cycles_per_source(),
        run.rays_per_cycle(),
        run.setup_cycles,
        run.command_cycles,
        run.readout_cycles,
    );
    say!(
        out,
        "host memory: {} loads, busy {} of {} cycles ({:.1}%)  cache hits {} of {} patch loads  tests {}",
        run.memory_loads,
        run.memory_busy_cycles,
        run.cycles,
        100.0 * run.memory_utilisation,
        run.cache_hits,
        run.patch_loads,
        run.tests
    );
    out.flush()
}

/// `cosim --pes N`: the source's rays in `N` contiguous sectors, one a PE of the machine.
fn cosim_machine(
    a: &CosimArgs,
    prepared: &GriddedScene,
    bundle: &shelling::rays::Bundle,
    params: &shelling::trace::ShellParams,
    vcd: Option<shelling::cosim::VcdWindow>,
    engine: Engine,
) -> Result<()> {
    if a.pes > bundle.len() {
        bail!("--pes {} needs at least one ray a PE: the source has {} rays", a.pes, bundle.len());
    }
    let parts = machine::schedule_parts(prepared, bundle, a.method, params, a.pes)?;
    let config = machine::MachineConfig {
        pes: a.pes,
        tc: a.tc,
        cache: a.cache,
        deal: machine::Deal::Sectors,
        // One source: patch k at address k, as `cosim` on one PE.
        place: machine::Placement::Index,
        engine,
        vcd,
    };
    let run = machine::run(&parts, &config, |_, _| {})?;
    report_machine(&run, &config, a.json, bundle.len(), a.method, "the file's")
}

/// The `cosim` JSON output: the `trace` JSON of the PE's hits plus the hardware's counters.
#[derive(serde::Serialize)]
struct CosimJson {
    #[serde(flatten)]
    trace: TraceJson,
    hardware: PeCounters,
    model: ModelCounts,
    /// max(host loads·T_c, loads, tests) (`cosim::bound_cycles`).
    bound_cycles: u64,
    /// The ideal in-order PE's cycles (`Cosim::inorder_cycles`).
    inorder_cycles: u64,
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
    let m = anyhow::Error::msg;
    limits::check_length("--length", a.length).map_err(m)?;
    check_range_for("--source", a.source, 0, 999, "(the default scene has 1000 segments)").map_err(m)?;
    check_range_for("--rays", a.rays, 1, limits::PE_RAY_MEMORY, "(the processing element's ray memory)")
        .map_err(m)?;
    check_range("--tc", a.tc, 1, limits::MAX_TC).map_err(m)?;
    limits::check_output_file("--vcd", &a.vcd).map_err(m)?;
    let scene = scene::generate(1000, a.length, a.seed, scene::PAPER_WORLD)?;
    let prepared = GriddedScene::new(scene, GridParams::default());
    let bundle = prepared.patch_bundle(a.source, RaySet::Angle, a.rays)?;
    let params = ShellParams::default();
    let mut out = Out::new();
    say!(
        out,
        "default scene: 1000 segments of length {} in [0, 1024)², seed {}; grid {}×{} ({} macro-regions)",
        a.length,
        a.seed,
        prepared.grid.nx,
        prepared.grid.ny,
        prepared.grid.region_count()
    );
    say!(out, "source: patch {} ({} rays, angle set)\n", a.source, a.rays);
    let oracle = prepared.trace(Method::Brute, &bundle, &params)?;
    let mut rows = Vec::new();
    for method in Method::ALL {
        let r = prepared.trace(method, &bundle, &params)?;
        let disagree = r.hits.iter().zip(&oracle.hits).filter(|(x, y)| x != y).count();
        if disagree > 0 {
            bail!("{method} disagrees with brute force on {disagree} rays");
        }
        rows.push((method.name(), r.counters));
    }
    print_counters(&mut out, &rows)?;
    say!(out, "\nevery technique returned the brute-force nearest hit for all {} rays", bundle.len());

    // The hardware: conventional and stochastic shelling on the RTL processing element.
    say!(
        out,
        "\nco-simulation of the RTL processing element (rust-hdl, cycle-accurate), host memory T_c = {} cycles per patch:",
        a.tc
    );
    say!(
        out,
        "{:<14}{:>8}{:>10}{:>10}{:>10}{:>12}{:>12}{:>10}",
        "method",
        "cache",
        "loads",
        "tests",
        "cycles",
        "efficiency",
        "sector wait",
        "speedup"
    );
    out.flush()?;
    let mut base: Option<u64> = None;
    let mut window = (1000, 1600);
    for (method, cache) in
        [(Method::Conventional, None), (Method::Conventional, Some(1024)), (Method::Stochastic, None)]
    {
        let scheduled = prepared.schedule(method, &bundle, &params)?;
        let vcd =
            (method == Method::Stochastic).then(|| VcdWindow { path: a.vcd.clone(), from: 1000, to: 1600 });
        let config = CosimConfig { tc: a.tc, cache, vcd, ..CosimConfig::default() };
        let run = match cosim::run(&scheduled, &config, |_, _| {}) {
            // A run shorter than 1000 cycles (few rays): its last 600 cycles instead.
            Err(cosim::CosimError::VcdOutsideRun { last, .. }) => {
                let from = last.saturating_sub(600);
                window = (from, last);
                let vcd = Some(VcdWindow { path: a.vcd.clone(), from, to: last });
                cosim::run(&scheduled, &CosimConfig { vcd, ..config }, |_, _| {})?
            }
            run => run?,
        };
        let rung2 = agreement::compare(&prepared.scene.segments, &bundle, &oracle, &scheduled.trace);
        if rung2.beyond_bound().next().is_some() {
            bail!("{method}: the PE's hits differ from the golden model beyond the documented bound");
        }
        let h = &run.hardware;
        let speedup = base.get_or_insert(h.cycles);
        say!(
            out,
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
        out.flush()?;
    }
    say!(
        out,
        "every PE hit equals the bit-true model's and the f64 golden model's within the documented bound; \
         speedup against conventional without cache"
    );
    say!(
        out,
        "waveform: {} (cycles {}..{}; open with waveforms/demo.gtkw)",
        a.vcd.display(),
        window.0,
        window.1
    );
    let files = export_verilog(&a.verilog)?;
    say!(out, "Verilog: {} files in {}", files.len(), a.verilog.display());
    say!(
        out,
        "\nwhat the rays are for (RADIOSITY.md): `shelling scene gen --kind room --out room.json`, then \
         `shelling form-factors --scene room.json --source 3` (one row of form factors) and \
         `shelling radiosity --scene room.json --svg room.svg` (the solution; `--on-pe` computes \
         every row on the RTL processing element)"
    );
    out.flush()
}

fn print_counters(out: &mut Out, rows: &[(&str, Counters)]) -> Result<()> {
    out.write_fmt(format_args!("{:<14}", "method"))?;
    for s in Counters::LABELS {
        out.write_fmt(format_args!("{s:>12}"))?;
    }
    say!(out);
    for (m, c) in rows {
        out.write_fmt(format_args!("{m:<14}"))?;
        for (v, integral) in c.values().iter().zip(Counters::INTEGRAL) {
            if !integral {
                out.write_fmt(format_args!("{v:>12.2}"))?;
            } else {
                out.write_fmt(format_args!("{v:>12}"))?;
            }
        }
        say!(out);
    }
    Ok(())
}
