//! `cargo xtask fpga --out DIR`: resources and post-route clock rate of every RTL block.
//!
//! 1. The Verilog of every block is exported fresh from the Rust source
//!    (`shelling_testbench::export::write`) into `DIR/verilog/`.
//! 2. Each block is wrapped in registers (see [`wrapper`]), synthesized by Yosys (`synth_ecp5`
//!    with `SHELLING_ECP5` defined, which instantiates the `DP16KD` block RAMs with their output
//!    register; `synth_ice40 -dsp` with `SHELLING_ICE40` defined, which gives each FIFO's second
//!    read its own memory copy) and placed and routed by nextpnr with a fixed seed, a target frequency
//!    and `--timing-allow-fail`, so that a missed target is measured rather than refused.
//!    A machine of two or more PEs on ECP5 is floorplanned first (see [`floorplan`], `--floorplan`):
//!    each PE's block RAMs and multipliers pinned to its own region of the die.
//! 3. The counts come from nextpnr's report (its log's utilisation table for a design that does
//!    not fit), less the wrapper's flip-flops, which the netlist tells apart; fmax and the
//!    critical path come from the report.
//!
//! Writes `DIR/fpga.json`, `DIR/fpga.md`, `DIR/logs/BLOCK-FAMILY-{yosys,nextpnr}.log` and the
//! intermediate files under `DIR/work/BLOCK-FAMILY/`. A design that does not fit the device is a
//! result (`"fits": false`, the bel types over capacity named, no fmax); a tool that fails is an
//! error row, and the command then exits non-zero after writing everything else.

mod floorplan;
mod netlist;
mod report;
mod tools;
mod wrapper;

use anyhow::{bail, Context, Result};
use clap::{Args, ValueEnum};
use report::{PathSummary, Report, Use};
use serde::{Deserialize, Serialize};
use shelling_hdl::arbiter::MAX_PES;
use shelling_testbench::export::{machine_block_pes, machine_verilog};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::fs::File;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};
use std::sync::Mutex;
use std::time::Instant;
use tools::{Tool, ToolKind};

/// The FPGA families.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, ValueEnum, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Family {
    /// Lattice ECP5, LFE5U-85F (CABGA381, speed grade 6 unless --ecp5-speed): nextpnr-ecp5.
    Ecp5,
    /// Lattice iCE40 (UP5K SG48 or HX8K CT256, see --ice40-device): nextpnr-ice40.
    Ice40,
}

impl Family {
    fn name(self) -> &'static str {
        match self {
            Family::Ecp5 => "ecp5",
            Family::Ice40 => "ice40",
        }
    }
}

/// The iCE40 part.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Ice40Device {
    /// iCE40UP5K, SG48: 5280 logic cells, 8 DSP (SB_MAC16), 30 block RAMs.
    Up5k,
    /// iCE40HX8K, CT256: 7680 logic cells, no DSP, 32 block RAMs.
    Hx8k,
}

/// Options of `cargo xtask fpga`.
#[derive(Args, Debug)]
pub struct FpgaArgs {
    /// Output directory: fpga.json, fpga.md, verilog/, logs/ and work/ (created).
    #[arg(long)]
    pub out: PathBuf,
    /// Blocks to run, comma-separated (default: every exported block).
    #[arg(long, value_delimiter = ',')]
    pub blocks: Vec<String>,
    /// FPGA families, comma-separated.
    #[arg(long, value_delimiter = ',', default_values = ["ecp5", "ice40"])]
    pub families: Vec<Family>,
    /// The iCE40 part.
    #[arg(long, value_enum, default_value = "up5k")]
    pub ice40_device: Ice40Device,
    /// ECP5 speed grade (nextpnr --speed): 6 is the slowest and nextpnr's default.
    #[arg(long, default_value_t = 6, value_parser = clap::value_parser!(u8).range(6..=8))]
    pub ecp5_speed: u8,
    /// Target clock frequency on ECP5, MHz (nextpnr --freq).
    #[arg(long, default_value_t = 150.0)]
    pub ecp5_mhz: f64,
    /// Options appended to Yosys' `synth_ecp5` (e.g. `-dff`: ABC9 maps across the flip-flops),
    /// space-separated, each a `-flag` or a plain word (no script separators): recorded in every
    /// row (`synth`), so that `--resume` and `--merge` never mix two syntheses. What they did
    /// to the clock rates is in PERFORMANCE.md.
    #[arg(long, default_value = "", allow_hyphen_values = true)]
    pub ecp5_synth_options: String,
    /// Options appended to nextpnr-ecp5's command (e.g. `--placer-heap-timingweight 30`),
    /// space-separated, each a `--flag` or a plain word; not the flow's own (`--seed`, `--freq`,
    /// the part, the files): recorded in every row (`pnr`), so that `--resume` places again
    /// when they change and `--merge` never mixes two. What they did is in PERFORMANCE.md.
    #[arg(long, default_value = "", allow_hyphen_values = true)]
    pub ecp5_pnr_options: String,
    /// Target clock frequency on iCE40, MHz (nextpnr --freq).
    #[arg(long, default_value_t = 50.0)]
    pub ice40_mhz: f64,
    /// nextpnr's placement seeds, comma-separated (each fixed, for reproducible results): every
    /// block is synthesized once and placed and routed once per seed; fpga.md reports the
    /// minimum, median and maximum fmax over the seeds, and the goal is judged on the median.
    #[arg(long = "seeds", alias = "seed", value_delimiter = ',', default_values_t = [1u64],
          value_parser = clap::value_parser!(u64).range(1..=1_000_000))]
    pub seeds: Vec<u64>,
    /// Jobs (one block on one family: Yosys then nextpnr) run at once.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..))]
    pub jobs: u64,
    /// Runs nothing: merges the rows of earlier runs' `fpga.json` in these directories
    /// (comma-separated; e.g. one run per seed, run side by side) for the blocks and families
    /// given, and writes the tables of them all into --out, against the Verilog exported now.
    #[arg(long, value_delimiter = ',')]
    pub merge: Vec<PathBuf>,
    /// Install the missing tools from PyPI (YoWASP) into the virtual environment
    /// $SHELLING_FPGA_VENV (default .venv-fpga at the repository root) first.
    #[arg(long)]
    pub install: bool,
    /// The machine's floorplan on ECP5 (`machine_N`, N >= 2; every other block and iCE40 are
    /// placed freely): `regions` pins each PE's block RAMs and multipliers to the sites of its own
    /// region of the die (two rows of regions, ceil(N/2) above and floor(N/2) below, or N columns
    /// by one row where a region of those has too few sites for its PE), `none` leaves them to
    /// the placer.
    /// What it does to the machines' clock rates, seed by seed, is in PERFORMANCE.md.
    #[arg(long, value_enum, default_value = "regions")]
    pub floorplan: Floorplan,
    /// Resume an interrupted run in the same --out: a block whose Verilog is the one already
    /// synthesized there is not synthesized again, and a seed whose nextpnr report is there is
    /// not placed again (its row is read from that report and log).
    #[arg(long)]
    pub resume: bool,
}

/// How the machine is floorplanned (`--floorplan`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Floorplan {
    /// Each PE's DP16KD and MULT18X18D pinned to its own region of the die.
    Regions,
    /// No cell pinned.
    None,
}

/// One block on one family, as `fpga.json` records it.
#[derive(Serialize, Deserialize, Debug, Clone)]
pub struct Row {
    pub block: String,
    pub family: Family,
    pub device: String,
    /// ECP5: LUT4s (TRELLIS_COMB: logic, carry and LUT RAM); iCE40: logic cells (ICESTORM_LC).
    pub luts: Option<u64>,
    pub ffs: Option<u64>,
    pub dsps: Option<u64>,
    pub brams: Option<u64>,
    /// ECP5 16x4 LUT RAMs (TRELLIS_RAMW; their LUTs are in `luts`); iCE40 has none.
    pub lutrams: Option<u64>,
    /// Post-route fmax; `null` when the design does not fit or a tool failed.
    pub fmax_mhz: Option<f64>,
    pub target_mhz: f64,
    /// Whether nextpnr placed and routed it; `null` when a tool failed first.
    pub fits: Option<bool>,
    /// Bel types over the device's capacity (`TYPE used/available`) when it does not fit.
    pub over_capacity: Vec<String>,
    /// A tool's failure: the tool, its command line and the tail of its log.
    pub error: Option<String>,
    /// The wrapper's flip-flops, subtracted from `ffs` (and, on iCE40, from `luts`).
    pub wrapper_ffs: Option<u64>,
    pub seed: u64,
    /// Wall-clock seconds of Yosys and of nextpnr.
    pub yosys_s: Option<f64>,
    pub nextpnr_s: Option<f64>,
    pub critical_path: Option<PathSummary>,
    /// The cells pinned before placement (`floorplan::describe`); `null`: none.
    #[serde(default)]
    pub floorplan: Option<String>,
    /// The Yosys synthesis command (`synth_ecp5 -dff`, ...); `null` in rows written before it
    /// was recorded, which used the family's plain command.
    #[serde(default)]
    pub synth: Option<String>,
    /// The options appended to nextpnr's command (`--ecp5-pnr-options`); `null`: none.
    #[serde(default)]
    pub pnr: Option<String>,
    pub tool_versions: BTreeMap<String, String>,
}

/// A family on its part: what Yosys and nextpnr are told.
#[derive(Clone, Debug)]
struct Target {
    family: Family,
    device: String,
    synth: String,
    /// Verilog defines for `read_verilog` (`-DSHELLING_ECP5` selects the hand-instantiated
    /// block RAMs of `shelling_hdl::prim::BramOut` and multipliers; `-DSHELLING_ICE40` the
    /// second memory copy of `shelling_hdl::prim::FifoRam`).
    defines: &'static str,
    nextpnr_device: Vec<String>,
    /// Options appended to nextpnr's command (`--ecp5-pnr-options`; none on iCE40).
    pnr_options: Vec<String>,
    mhz: f64,
    tool: ToolKind,
}

/// The family's plain Yosys command on the part `device` names: what the flow runs without
/// `--ecp5-synth-options`, and what every row written before `Row::synth` was recorded used.
fn plain_synth(family: Family, device: &str) -> &'static str {
    match family {
        Family::Ecp5 => "synth_ecp5",
        Family::Ice40 if device.starts_with("iCE40UP5K") => "synth_ice40 -dsp",
        Family::Ice40 => "synth_ice40",
    }
}

impl Row {
    /// The Yosys command this row's netlist was synthesized with.
    fn synth_command(&self) -> &str {
        self.synth.as_deref().unwrap_or_else(|| plain_synth(self.family, &self.device))
    }
}

impl Target {
    /// The target of `family`; on ECP5 the checked `ecp5_options` appended to its synthesis and
    /// `ecp5_pnr` to its nextpnr command.
    fn new(family: Family, args: &FpgaArgs, ecp5_options: &[&str], ecp5_pnr: &[&str]) -> Target {
        let mut target = match (family, args.ice40_device) {
            (Family::Ecp5, _) => Target {
                family,
                device: format!("LFE5U-85F-{} CABGA381", args.ecp5_speed),
                synth: String::new(),
                defines: "-DSHELLING_ECP5 ",
                nextpnr_device: strings(&[
                    "--85k",
                    "--speed",
                    &args.ecp5_speed.to_string(),
                    "--package",
                    "CABGA381",
                ]),
                pnr_options: strings(ecp5_pnr),
                mhz: args.ecp5_mhz,
                tool: ToolKind::NextpnrEcp5,
            },
            (Family::Ice40, Ice40Device::Up5k) => Target {
                family,
                device: "iCE40UP5K SG48".into(),
                synth: String::new(),
                defines: "-DSHELLING_ICE40 ",
                nextpnr_device: strings(&["--up5k", "--package", "sg48"]),
                pnr_options: Vec::new(),
                mhz: args.ice40_mhz,
                tool: ToolKind::NextpnrIce40,
            },
            (Family::Ice40, Ice40Device::Hx8k) => Target {
                family,
                device: "iCE40HX8K CT256".into(),
                synth: String::new(),
                defines: "-DSHELLING_ICE40 ",
                nextpnr_device: strings(&["--hx8k", "--package", "ct256"]),
                pnr_options: Vec::new(),
                mhz: args.ice40_mhz,
                tool: ToolKind::NextpnrIce40,
            },
        };
        let options: &[&str] = if family == Family::Ecp5 { ecp5_options } else { &[] };
        target.synth = std::iter::once(plain_synth(family, &target.device))
            .chain(options.iter().copied())
            .collect::<Vec<_>>()
            .join(" ");
        target
    }
}

fn strings(s: &[&str]) -> Vec<String> {
    s.iter().map(|s| s.to_string()).collect()
}

/// What every job shares.
struct Flow {
    /// The output directory (absolute); the tools run in it, on paths relative to it.
    out: PathBuf,
    tools: BTreeMap<ToolKind, Tool>,
    seeds: Vec<u64>,
    resume: bool,
    floorplan: Floorplan,
}

/// The words of `option`'s `text`, or what is wrong with one: each a `-flag` or a value of
/// letters, digits and `_ . = + -`, so that nothing but options reaches the tool (`what`, with
/// an `example` of the option).
fn option_words<'a>(option: &str, text: &'a str, what: &str, example: &str) -> Result<Vec<&'a str>> {
    let words: Vec<&str> = text.split_whitespace().collect();
    for w in &words {
        if !w.chars().all(|c| c.is_ascii_alphanumeric() || "_.=+-".contains(c)) {
            bail!(
                "{option} {text:?}: `{w}` is not {what} (letters, digits and _ . = + - only, e.g. {option} {example})"
            );
        }
    }
    Ok(words)
}

/// The `--ecp5-synth-options` words (`option_words`): nothing but options reaches Yosys' script.
fn synth_options(text: &str) -> Result<Vec<&str>> {
    option_words("--ecp5-synth-options", text, "a synth_ecp5 option", "-dff")
}

/// nextpnr's options that the flow sets itself: `--ecp5-pnr-options` may not give them.
const FLOW_PNR_FLAGS: [&str; 11] = [
    "--json",
    "--freq",
    "--seed",
    "--timing-allow-fail",
    "--report",
    "--speed",
    "--package",
    "--25k",
    "--45k",
    "--85k",
    "--textcfg",
];

/// The `--ecp5-pnr-options` words, or what is wrong with one: each a `--flag` or a value of
/// letters, digits and `_ . = + -`, and none of the flags the flow sets itself.
fn pnr_options(text: &str) -> Result<Vec<&str>> {
    let words =
        option_words("--ecp5-pnr-options", text, "a nextpnr option", "\"--placer-heap-timingweight 30\"")?;
    for w in &words {
        if FLOW_PNR_FLAGS.contains(&w.split('=').next().unwrap_or(w)) {
            bail!("--ecp5-pnr-options {text:?}: `{w}` is the flow's own (give it with the flow's option)");
        }
    }
    Ok(words)
}

/// Runs `cargo xtask fpga`.
pub fn run(args: &FpgaArgs) -> Result<ExitCode> {
    let ecp5_options = synth_options(&args.ecp5_synth_options)?;
    let ecp5_pnr = pnr_options(&args.ecp5_pnr_options)?;
    let repo = PathBuf::from(env!("CARGO_MANIFEST_DIR")).parent().map(Path::to_path_buf).unwrap_or_default();
    let known: Vec<&str> = shelling_testbench::export::blocks().into_iter().map(|(name, _)| name).collect();
    let blocks: Vec<String> = if args.blocks.is_empty() {
        known.iter().map(|s| s.to_string()).collect()
    } else {
        for b in &args.blocks {
            if !known.contains(&b.as_str()) && machine_block_pes(b).is_none() {
                bail!(
                    "no block `{b}`; the blocks are {}, and machine_N for the machine of N PEs (N 1 to {MAX_PES})",
                    known.join(", ")
                );
            }
        }
        args.blocks.clone()
    };
    let mut families = args.families.clone();
    families.sort();
    families.dedup();
    if families.is_empty() {
        bail!("no family given");
    }
    let targets: Vec<Target> =
        families.iter().map(|&f| Target::new(f, args, &ecp5_options, &ecp5_pnr)).collect();

    // The tools, before anything is written.
    let mut kinds = vec![ToolKind::Yosys];
    kinds.extend(targets.iter().map(|t| t.tool));
    let venv = tools::venv_dir(&repo);
    let found = tools::resolve(&kinds, &venv, args.install)?;
    for t in &found {
        eprintln!("{:<14} {} ({}; found as {})", t.kind.native(), t.path.display(), t.version, t.found_as);
    }
    let tools: BTreeMap<ToolKind, Tool> = found.into_iter().map(|t| (t.kind, t)).collect();

    std::fs::create_dir_all(&args.out).with_context(|| format!("creating {}", args.out.display()))?;
    let out = args.out.canonicalize().with_context(|| format!("resolving {}", args.out.display()))?;
    for sub in ["logs", "work"] {
        std::fs::create_dir_all(out.join(sub))
            .with_context(|| format!("creating {}/{sub}", out.display()))?;
    }
    let written = shelling_testbench::export::write(&out.join("verilog"))
        .map_err(|e| anyhow::anyhow!("exporting the Verilog: {e}"))?;
    let files =
        shelling_testbench::export::verilog().map_err(|e| anyhow::anyhow!("exporting the Verilog: {e}"))?;
    let verilog_hash = shelling_testbench::export::hash(&files);
    // Each block's own file, hashed alone: what its results are checked against.
    // Machines of more PEs than the exported one's, each into its own file.
    let mut machines = Vec::new();
    for pes in blocks.iter().filter_map(|b| machine_block_pes(b)) {
        let (name, text) = machine_verilog(pes).map_err(|e| anyhow::anyhow!("exporting the Verilog: {e}"))?;
        let path = out.join("verilog").join(&name);
        std::fs::write(&path, &text).with_context(|| format!("writing {}", path.display()))?;
        machines.push((name, text));
    }
    let block_hashes: BTreeMap<String, String> = files
        .iter()
        .chain(&machines)
        .filter_map(|(name, text)| {
            let block = name.strip_suffix(".v")?;
            Some((block.to_string(), shelling_testbench::export::hash(&[(name.clone(), text.clone())])))
        })
        .collect();
    eprintln!("exported {} files into {}", written.len(), out.join("verilog").display());

    let mut seeds = args.seeds.clone();
    seeds.sort();
    seeds.dedup();
    if seeds.len() > 16 {
        bail!("--seeds lists {} seeds: at most 16", seeds.len());
    }
    let (rows, ctx) = if args.merge.is_empty() {
        let ctx = Flow { out: out.clone(), tools, seeds, resume: args.resume, floorplan: args.floorplan };
        // Every (block, target), reported in this order; run longest first (the whole PE).
        let jobs: Vec<(String, Target)> =
            blocks.iter().flat_map(|b| targets.iter().map(move |t| (b.clone(), t.clone()))).collect();
        let mut order: Vec<usize> = (0..jobs.len()).collect();
        order.sort_by_key(|&i| jobs[i].0 != "processing_element");
        (run_all(&ctx, &jobs, &order, args.jobs as usize).into_iter().flatten().collect::<Vec<Row>>(), ctx)
    } else {
        let mut rows: Vec<Row> = Vec::new();
        for dir in &args.merge {
            let path = dir.join("fpga.json");
            let text = std::fs::read_to_string(&path)
                .with_context(|| format!("--merge: reading {}", path.display()))?;
            let read: Vec<Row> = serde_json::from_str(&text)
                .with_context(|| format!("--merge: {} is not fpga.json", path.display()))?;
            rows.extend(
                read.into_iter().filter(|r| blocks.contains(&r.block) && families.contains(&r.family)),
            );
        }
        rows.sort_by(|a, b| (&a.block, a.family, a.seed).cmp(&(&b.block, b.family, b.seed)));
        if rows.is_empty() {
            bail!("--merge: no rows of the blocks and families asked for");
        }
        if let Some(e) =
            mixed_floorplans(&rows).or_else(|| mixed_syntheses(&rows)).or_else(|| mixed_pnr(&rows))
        {
            bail!("--merge: {e}");
        }
        let mut seeds: Vec<u64> = rows.iter().map(|r| r.seed).collect();
        seeds.sort();
        seeds.dedup();
        (rows, Flow { out: out.clone(), tools, seeds, resume: false, floorplan: args.floorplan })
    };
    let spreads = spreads(&rows, &block_hashes);

    let json = serde_json::to_string_pretty(&rows)? + "\n";
    std::fs::write(out.join("fpga.json"), json)
        .with_context(|| format!("writing {}/fpga.json", out.display()))?;
    let seeds_json = SeedsFile { verilog_hash: verilog_hash.clone(), blocks: spreads.clone() };
    std::fs::write(out.join("fpga-seeds.json"), serde_json::to_string_pretty(&seeds_json)? + "\n")
        .with_context(|| format!("writing {}/fpga-seeds.json", out.display()))?;
    let md = markdown(&rows, &spreads, &ctx, &verilog_hash);
    std::fs::write(out.join("fpga.md"), &md).with_context(|| format!("writing {}/fpga.md", out.display()))?;
    println!("{md}");
    println!(
        "written: {}/fpga.json, {}/fpga-seeds.json, {}/fpga.md, logs in {}/logs",
        out.display(),
        out.display(),
        out.display(),
        out.display()
    );

    for sp in spreads.iter().filter(|s| s.block == "processing_element" && s.family == Family::Ecp5) {
        let n = sp.seeds.len();
        match sp.median_mhz {
            Some(f) if f >= sp.target_mhz => println!(
                "goal met: the PE on ECP5 at a median of {f:.1} MHz over {n} seeds >= {} MHz",
                sp.target_mhz
            ),
            Some(f) => println!(
                "goal missed: the PE on ECP5 at a median of {f:.1} MHz over {n} seeds < {} MHz",
                sp.target_mhz
            ),
            None => println!("goal not measured: the PE on ECP5 has no fmax"),
        }
    }
    let failed: Vec<&Row> = rows.iter().filter(|r| r.error.is_some()).collect();
    if failed.is_empty() {
        Ok(ExitCode::SUCCESS)
    } else {
        for r in &failed {
            eprintln!(
                "error: {} on {}: {}",
                r.block,
                r.family.name(),
                r.error.as_deref().unwrap_or_default()
            );
        }
        eprintln!("{} of {} runs failed", failed.len(), rows.len());
        Ok(ExitCode::FAILURE)
    }
}

/// Runs the jobs on `workers` threads, in `order`; returns each job's rows (one per seed) in the
/// jobs' order.
fn run_all(ctx: &Flow, jobs: &[(String, Target)], order: &[usize], workers: usize) -> Vec<Vec<Row>> {
    let queue = Mutex::new(order.iter().copied());
    let results: Mutex<Vec<Option<Vec<Row>>>> = Mutex::new(vec![None; jobs.len()]);
    let done = Mutex::new(0usize);
    std::thread::scope(|s| {
        for _ in 0..workers.min(jobs.len()).max(1) {
            s.spawn(|| loop {
                let Some(i) = queue.lock().expect("queue").next() else { break };
                let (block, target) = &jobs[i];
                let rows = run_job(ctx, block, target);
                let mut n = done.lock().expect("counter");
                *n += 1;
                for row in &rows {
                    eprintln!("[{}/{}] {}", *n, jobs.len(), summary(row));
                }
                results.lock().expect("results")[i] = Some(rows);
            });
        }
    });
    results.into_inner().expect("results").into_iter().map(|r| r.expect("every job ran")).collect()
}

fn summary(r: &Row) -> String {
    let time = |t: Option<f64>| t.map(|t| format!("{t:.1} s")).unwrap_or_else(|| "-".into());
    let outcome = match (&r.error, r.fits, r.fmax_mhz) {
        (Some(_), _, _) => "FAILED".to_string(),
        (None, Some(false), _) => format!("does not fit ({})", r.over_capacity.join(", ")),
        (None, _, Some(f)) => format!("{f:.1} MHz (target {})", r.target_mhz),
        _ => "no clocked path".to_string(),
    };
    format!(
        "{} {} seed {}: yosys {}, nextpnr {}: {outcome}",
        r.block,
        r.family.name(),
        r.seed,
        time(r.yosys_s),
        time(r.nextpnr_s)
    )
}

/// One block on one family: Yosys once, then nextpnr once per seed; one row per seed (a Yosys
/// failure gives every seed's row the error).
fn run_job(ctx: &Flow, block: &str, target: &Target) -> Vec<Row> {
    let yosys = &ctx.tools[&ToolKind::Yosys];
    let nextpnr = &ctx.tools[&target.tool];
    let mut row = Row {
        block: block.to_string(),
        family: target.family,
        device: target.device.clone(),
        luts: None,
        ffs: None,
        dsps: None,
        brams: None,
        lutrams: None,
        fmax_mhz: None,
        target_mhz: target.mhz,
        fits: None,
        over_capacity: Vec::new(),
        error: None,
        wrapper_ffs: None,
        seed: 0,
        yosys_s: None,
        nextpnr_s: None,
        critical_path: None,
        floorplan: None,
        synth: Some(target.synth.clone()),
        pnr: (!target.pnr_options.is_empty()).then(|| target.pnr_options.join(" ")),
        tool_versions: BTreeMap::from([
            ("yosys".to_string(), yosys.version.clone()),
            ("nextpnr".to_string(), nextpnr.version.clone()),
        ]),
    };
    let synthesized = synthesize(ctx, block, target, &mut row).and_then(|mut s| {
        pin(ctx, block, target, &mut s, &mut row)?;
        Ok(s)
    });
    ctx.seeds
        .iter()
        .map(|&seed| {
            let mut r = Row { seed, ..row.clone() };
            let placed = match &synthesized {
                Ok(s) => place(ctx, target, s, seed, &mut r),
                Err(e) => Err(anyhow::anyhow!("{e:#}")),
            };
            if let Err(e) = placed {
                r.error = Some(format!("{e:#}"));
            }
            r
        })
        .collect()
}

/// What synthesis leaves for place and route: the job's directory and its wrapper's flip-flops.
struct Synthesized {
    job: String,
    dir: PathBuf,
    wrapper_ffs: u64,
    /// The netlist was already there (`--resume`).
    resumed: bool,
    /// The netlist nextpnr reads: Yosys' own, or the floorplanned copy.
    placed_json: &'static str,
}

/// Yosys on one block in its wrapper; fills the flip-flop counts of `row`.
fn synthesize(ctx: &Flow, block: &str, target: &Target, row: &mut Row) -> Result<Synthesized> {
    let family = target.family.name();
    let job = format!("{block}-{family}");
    // The tools run in the job's directory on bare file names: the YoWASP builds resolve a
    // relative path with a directory against the host's root directories first (`work/x` would
    // be `/work/x`), so every file they read or write is in that directory.
    let dir = ctx.out.join("work").join(&job);
    std::fs::create_dir_all(&dir).with_context(|| format!("creating {}", dir.display()))?;
    let exported = ctx.out.join("verilog").join(format!("{block}.v"));
    let text =
        std::fs::read_to_string(&exported).with_context(|| format!("reading {}", exported.display()))?;
    let ports = wrapper::ports(&text, block)?;
    let wrap = wrapper::wrap(block, &ports);
    let source = format!("{block}.v");
    let wrapper_v = "wrapper.v";
    let same = |name: &str, body: &str| std::fs::read_to_string(dir.join(name)).is_ok_and(|t| t == body);
    if ctx.resume
        && same(&source, &text)
        && same(wrapper_v, &wrap.verilog)
        && same(SYNTH_COMMAND, &target.synth)
        && dir.join(NETLIST_JSON).is_file()
    {
        eprintln!("{job}: resumed (its netlist is of this Verilog and `{}`)", target.synth);
        let cells = netlist::count(&dir.join(NETLIST_JSON), &wrap.top)?;
        row.wrapper_ffs = Some(cells.wrapper_ffs);
        row.ffs = Some(cells.ffs - cells.wrapper_ffs);
        return Ok(Synthesized {
            job,
            dir,
            wrapper_ffs: cells.wrapper_ffs,
            resumed: true,
            placed_json: NETLIST_JSON,
        });
    }
    // The netlist is about to be made again: an older one must not be taken for it by a later
    // --resume if this synthesis fails (a stale report is removed by `place`, seed by seed).
    let _ = std::fs::remove_file(dir.join(NETLIST_JSON));
    for (name, body) in [
        (source.as_str(), text.as_str()),
        (wrapper_v, wrap.verilog.as_str()),
        (SYNTH_COMMAND, target.synth.as_str()),
    ] {
        std::fs::write(dir.join(name), body)
            .with_context(|| format!("writing {}", dir.join(name).display()))?;
    }

    let script = format!(
        "read_verilog {}{source} {wrapper_v}; {} -top {} -json {NETLIST_JSON}; stat",
        target.defines, target.synth, wrap.top
    );
    eprintln!("{job}: yosys ({} {} bits in, {} bits out)", target.synth, wrap.in_bits, wrap.out_bits);
    let yosys_args = vec!["-p".to_string(), script];
    let t = Instant::now();
    let log = ctx.out.join("logs").join(format!("{job}-yosys.log"));
    let status = tool_run(&dir, &ctx.tools[&ToolKind::Yosys], &yosys_args, &log)?;
    row.yosys_s = Some(report::round(t.elapsed().as_secs_f64(), 1));
    status.check()?;
    let cells = netlist::count(&dir.join(NETLIST_JSON), &wrap.top)?;
    row.wrapper_ffs = Some(cells.wrapper_ffs);
    row.ffs = Some(cells.ffs - cells.wrapper_ffs);
    Ok(Synthesized { job, dir, wrapper_ffs: cells.wrapper_ffs, resumed: false, placed_json: NETLIST_JSON })
}

/// The netlist Yosys writes in a job's directory.
const NETLIST_JSON: &str = "synth.json";
/// In a job's directory, the synthesis command its netlist is of (for `--resume`).
const SYNTH_COMMAND: &str = "synth-command.txt";
/// Yosys' netlist with the floorplan's `BEL` attributes, beside it.
const FLOORPLANNED_JSON: &str = "floorplanned.json";
/// In a job's directory, the floorplan a seed's report was placed with (`none` or the
/// description), and nextpnr's extra options if any.
fn floorplan_file(seed: u64) -> String {
    format!("floorplan-seed{seed}.txt")
}

/// Floorplans a synthesized machine of two or more PEs on ECP5 (see [`floorplan`]) unless
/// `--floorplan none`: writes the pinned netlist beside Yosys' and records it in `row`.
fn pin(ctx: &Flow, block: &str, target: &Target, s: &mut Synthesized, row: &mut Row) -> Result<()> {
    let pes = machine_block_pes(block).unwrap_or(0);
    if ctx.floorplan == Floorplan::None || target.family != Family::Ecp5 || pes < 2 {
        return Ok(());
    }
    let _ = std::fs::remove_file(s.dir.join(FLOORPLANNED_JSON));
    let plan = floorplan::apply(&s.dir.join(NETLIST_JSON), &s.dir.join(FLOORPLANNED_JSON), pes)?;
    eprintln!("{}: floorplan {plan}", s.job);
    s.placed_json = FLOORPLANNED_JSON;
    row.floorplan = Some(plan);
    Ok(())
}

/// nextpnr on a synthesized block with one seed; fills `row` as it goes.
fn place(ctx: &Flow, target: &Target, s: &Synthesized, seed: u64, row: &mut Row) -> Result<()> {
    let (dir, netlist_json) = (&s.dir, s.placed_json);
    let job = format!("{}-seed{seed}", s.job);
    let report_json = format!("report-seed{seed}.json");
    let report_json = report_json.as_str();
    let log = ctx.out.join("logs").join(format!("{job}-nextpnr.log"));
    // What the seed is placed with: the floorplan, and nextpnr's extra options if any (a file
    // written before they were recorded holds the floorplan alone, as a run without them does).
    let mut plan = row.floorplan.clone().unwrap_or_else(|| "none".into());
    if let Some(o) = &row.pnr {
        plan = format!("{plan}\nnextpnr options: {o}");
    }
    let plan_file = dir.join(floorplan_file(seed));
    let resumed = s.resumed
        && dir.join(report_json).is_file()
        && log.is_file()
        && std::fs::read_to_string(&plan_file).is_ok_and(|p| p == plan);
    if !resumed {
        // A stale report from an earlier run (or of another floorplan or options) must not be read
        // as this one's.
        let _ = std::fs::remove_file(dir.join(report_json));
        std::fs::write(&plan_file, &plan).with_context(|| format!("writing {}", plan_file.display()))?;
    }
    let mut args = target.nextpnr_device.clone();
    args.extend([
        "--json".to_string(),
        netlist_json.to_string(),
        "--freq".to_string(),
        target.mhz.to_string(),
        "--seed".to_string(),
        seed.to_string(),
        "--timing-allow-fail".to_string(),
        "--report".to_string(),
        report_json.to_string(),
    ]);
    args.extend(target.pnr_options.iter().cloned());
    let status = if resumed {
        // Placed by the interrupted run: a report is written only when nextpnr succeeds.
        eprintln!("{job}: resumed (its report is there)");
        Status {
            ok: true,
            tool: target.tool.native().to_string(),
            command: "(resumed)".into(),
            log: log.clone(),
            code: "resumed".into(),
        }
    } else {
        eprintln!("{job}: nextpnr ({}, {} MHz target)", target.device, target.mhz);
        let t = Instant::now();
        let status = tool_run(dir, &ctx.tools[&target.tool], &args, &log)?;
        row.nextpnr_s = Some(report::round(t.elapsed().as_secs_f64(), 1));
        status
    };
    let log_text = std::fs::read_to_string(&log).unwrap_or_default();
    let packed = report::log_utilisation(&log_text);
    let (used, fits) = if status.ok {
        let path = dir.join(report_json);
        let text = std::fs::read_to_string(&path).with_context(|| {
            format!("nextpnr succeeded but wrote no {}; {}", path.display(), status.describe())
        })?;
        let rep = Report::parse(&text).with_context(|| path.display().to_string())?;
        row.fmax_mhz = rep.fmax_mhz().map(|f| report::round(f, 2));
        row.critical_path = rep.critical_path();
        (rep.utilization, true)
    } else {
        let over = report::over_capacity(&packed);
        if over.is_empty() {
            // Not a capacity problem: a real failure.
            status.check()?;
        }
        row.over_capacity = over;
        (packed, false)
    };
    row.fits = Some(fits);
    let n = |bel: &str| used.get(bel).map(|u: &Use| u.used).unwrap_or(0);
    match target.family {
        Family::Ecp5 => {
            row.luts = Some(n("TRELLIS_COMB"));
            row.dsps = Some(n("MULT18X18D") + n("ALU54B"));
            row.brams = Some(n("DP16KD"));
            row.lutrams = Some(n("TRELLIS_RAMW"));
        }
        Family::Ice40 => {
            // Every wrapper flip-flop sits alone in a logic cell (see `wrapper`).
            row.luts = Some(n("ICESTORM_LC").saturating_sub(s.wrapper_ffs));
            row.dsps = Some(n("ICESTORM_DSP"));
            row.brams = Some(n("ICESTORM_RAM") + n("ICESTORM_SPRAM"));
        }
    }
    Ok(())
}

/// How a tool run ended, with what it takes to report a failure.
struct Status {
    ok: bool,
    tool: String,
    command: String,
    log: PathBuf,
    code: String,
}

impl Status {
    fn describe(&self) -> String {
        let text = std::fs::read_to_string(&self.log).unwrap_or_default();
        let lines: Vec<&str> = text.lines().collect();
        let tail = lines[lines.len().saturating_sub(20)..].join("\n    ");
        format!(
            "{} failed ({})\n  command: {}\n  log: {}\n  last lines:\n    {tail}",
            self.tool,
            self.code,
            self.command,
            self.log.display()
        )
    }

    fn check(&self) -> Result<()> {
        if self.ok {
            Ok(())
        } else {
            bail!(self.describe())
        }
    }
}

fn shell_quote(s: &str) -> String {
    if !s.is_empty() && s.chars().all(|c| c.is_ascii_alphanumeric() || "-_./=:+,".contains(c)) {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', r"'\''"))
    }
}

/// Runs `tool` with `args` in `dir`, its stdout and stderr into `log` after a header with the
/// command line.
fn tool_run(dir: &Path, tool: &Tool, args: &[String], log: &Path) -> Result<Status> {
    let command = format!(
        "cd {} && {} {}",
        shell_quote(&dir.to_string_lossy()),
        shell_quote(&tool.path.to_string_lossy()),
        args.iter().map(|a| shell_quote(a)).collect::<Vec<_>>().join(" ")
    );
    let mut file = File::create(log).with_context(|| format!("creating {}", log.display()))?;
    writeln!(file, "# {}\n# $ {command}\n", tool.version)?;
    let stderr = file.try_clone()?;
    let status = Command::new(&tool.path)
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(file)
        .stderr(stderr)
        .status()
        .with_context(|| format!("starting {} ({command})", tool.kind.native()))?;
    Ok(Status {
        ok: status.success(),
        tool: tool.kind.native().to_string(),
        command,
        log: log.to_path_buf(),
        code: status.to_string(),
    })
}

/// Two rows of one block and family whose `key`s differ, said (`rows` sorted by block, family
/// and seed): their seeds are not one experiment's. `what` names the two keys.
fn mixed(rows: &[Row], what: &str, key: impl Fn(&Row) -> String) -> Option<String> {
    rows.windows(2).find_map(|pair| {
        let (a, b) = (&pair[0], &pair[1]);
        let (ka, kb) = (key(a), key(b));
        ((&a.block, a.family) == (&b.block, b.family) && ka != kb).then(|| {
            format!(
                "{} on {} was {what} (seeds {} and {}): {ka} / {kb}",
                a.block,
                a.family.name(),
                a.seed,
                b.seed
            )
        })
    })
}

/// Two rows of one block and family placed with different floorplans, said.
fn mixed_floorplans(rows: &[Row]) -> Option<String> {
    mixed(rows, "placed with two floorplans", |r| r.floorplan.clone().unwrap_or_else(|| "none".into()))
}

/// Two rows of one block and family synthesized with different commands, said. A row without
/// the command (written before it was recorded) is of its part's plain one.
fn mixed_syntheses(rows: &[Row]) -> Option<String> {
    mixed(rows, "synthesized with two commands", |r| format!("`{}`", r.synth_command()))
}

/// Two rows of one block and family placed with different nextpnr options, said.
fn mixed_pnr(rows: &[Row]) -> Option<String> {
    mixed(rows, "placed with two sets of nextpnr options", |r| {
        format!("`{}`", r.pnr.as_deref().unwrap_or(""))
    })
}

/// One block on one family over the seeds: the spread of its post-route fmax, as
/// `fpga-seeds.json` records it and `fpga.md` reports it.
#[derive(Serialize, Debug, Clone)]
pub struct Spread {
    pub block: String,
    pub family: Family,
    /// The hash of the block's own exported Verilog file (`BLOCK.v`, which holds every module
    /// it instantiates; `shelling_testbench::export::hash` of that one file), so that a change
    /// to another block leaves this block's results current.
    pub verilog_hash: String,
    pub target_mhz: f64,
    /// The seeds run.
    pub seeds: Vec<u64>,
    /// fmax of each seed that placed and routed, in the order of `seeds` (`null` where not).
    pub fmax_mhz: Vec<Option<f64>>,
    pub min_mhz: Option<f64>,
    /// The median over the seeds with an fmax: the figure a goal is judged on (the lower middle
    /// value for an even count).
    pub median_mhz: Option<f64>,
    pub max_mhz: Option<f64>,
    /// The floorplan every seed was placed with (`Row::floorplan`; `--merge` refuses to mix two).
    pub floorplan: Option<String>,
    /// The options every seed's nextpnr had appended (`Row::pnr`, `--ecp5-pnr-options`;
    /// `--merge` refuses to mix two); left out when none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pnr: Option<String>,
}

/// `fpga-seeds.json`: the hash of the whole export measured and every block's spread with the
/// hash of its own Verilog file.
#[derive(Serialize, Debug)]
pub struct SeedsFile {
    pub verilog_hash: String,
    pub blocks: Vec<Spread>,
}

/// The spread of every (block, family) over its rows' seeds, in the rows' order.
fn spreads(rows: &[Row], block_hashes: &BTreeMap<String, String>) -> Vec<Spread> {
    let mut out: Vec<Spread> = Vec::new();
    for r in rows {
        let i = match out.iter().position(|s| s.block == r.block && s.family == r.family) {
            Some(i) => i,
            None => {
                out.push(Spread {
                    block: r.block.clone(),
                    family: r.family,
                    verilog_hash: block_hashes.get(&r.block).cloned().unwrap_or_default(),
                    target_mhz: r.target_mhz,
                    seeds: Vec::new(),
                    fmax_mhz: Vec::new(),
                    min_mhz: None,
                    median_mhz: None,
                    max_mhz: None,
                    floorplan: r.floorplan.clone(),
                    pnr: r.pnr.clone(),
                });
                out.len() - 1
            }
        };
        out[i].seeds.push(r.seed);
        out[i].fmax_mhz.push(r.fmax_mhz.filter(|_| r.error.is_none() && r.fits != Some(false)));
    }
    for s in &mut out {
        let mut f: Vec<f64> = s.fmax_mhz.iter().flatten().copied().collect();
        f.sort_by(f64::total_cmp);
        s.min_mhz = f.first().copied();
        s.max_mhz = f.last().copied();
        s.median_mhz = (!f.is_empty()).then(|| f[(f.len() - 1) / 2]);
    }
    out
}

fn cell(v: Option<u64>) -> String {
    v.map(|v| v.to_string()).unwrap_or_else(|| "–".into())
}

/// The Markdown of `fpga.md`: the table, the tools, the critical paths and the run times.
fn markdown(rows: &[Row], spreads: &[Spread], ctx: &Flow, verilog_hash: &str) -> String {
    let mut md = String::new();
    let _ = writeln!(
        md,
        "Measured on the exported Verilog of hash `{verilog_hash}` (`shelling_testbench::export::hash`, \
         the whole export); a block's figures are of its own file, whose hash is in the last column of \
         the first table (`tests/hardware.rs` checks it against the committed `hdl/verilog/BLOCK.v`).\n"
    );
    let mhz = |v: Option<f64>| v.map(|v| format!("{v:.1}")).unwrap_or_else(|| "–".into());
    let seeds = ctx.seeds.iter().map(u64::to_string).collect::<Vec<_>>().join(", ");
    let _ = writeln!(
        md,
        "Post-route fmax over placement seeds {seeds} (the `seeds` column counts a block's own, listed in \
         the second table; median: the lower middle value of the seeds that routed):\n\n\
         | block | family | seeds | min (MHz) | median (MHz) | max (MHz) | target (MHz) | Verilog hash |\n\
         |---|---|--:|--:|--:|--:|--:|---|"
    );
    for s in spreads {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | **{}** | {} | {} | `{}` |",
            s.block,
            s.family.name(),
            s.seeds.len(),
            mhz(s.min_mhz),
            mhz(s.median_mhz),
            mhz(s.max_mhz),
            s.target_mhz,
            s.verilog_hash
        );
    }
    let _ = writeln!(md, "\nEvery run:\n");
    let _ = writeln!(
        md,
        "| block | family | device | seed | LUTs | FFs | DSPs | BRAMs | LUT RAMs | fmax (MHz) | target (MHz) |\n\
         |---|---|---|--:|--:|--:|--:|--:|--:|--:|--:|"
    );
    for r in rows {
        let fmax = match (&r.error, r.fits, r.fmax_mhz) {
            (Some(_), _, _) => "tool failed".to_string(),
            (None, Some(false), _) => format!("does not fit: {}", r.over_capacity.join(", ")),
            (None, _, Some(f)) => format!("{f:.1}"),
            _ => "–".to_string(),
        };
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {fmax} | {} |",
            r.block,
            r.family.name(),
            r.device,
            r.seed,
            cell(r.luts),
            cell(r.ffs),
            cell(r.dsps),
            cell(r.brams),
            cell(r.lutrams),
            r.target_mhz
        );
    }
    let _ = writeln!(
        md,
        "\nLUTs: ECP5 LUT4s (logic, carry and LUT RAM); iCE40 logic cells. LUT RAMs: ECP5 16x4 \
         distributed RAMs (6 LUT4s each, counted in LUTs). BRAMs: DP16KD (18 Kbit) / SB_RAM40_4K \
         (4 Kbit). Each block is placed in a register wrapper (every port bit a flip-flop); the \
         wrapper's flip-flops are not counted. Seeds {seeds} in all, each block's in its rows; the LUT \
         and FF counts are of each \
         seed's placement (Yosys runs once per block).\n"
    );
    let mut plans: Vec<(&str, &str)> =
        rows.iter().filter_map(|r| Some((r.block.as_str(), r.floorplan.as_deref()?))).collect();
    plans.dedup();
    if !plans.is_empty() {
        let _ = writeln!(
            md,
            "Floorplans (`--floorplan regions`: each PE's block RAMs and multipliers pinned to the \
             sites of its own region of the die nearest the region's centre, a sub-block's side by \
             side along a row; every other cell placed by nextpnr; `--floorplan none`: none):\n"
        );
        for (block, plan) in plans {
            let _ = writeln!(md, "- {block}: {plan}");
        }
        let _ = writeln!(md);
    }
    // The synthesis commands, when some block's is not its part's plain one (`--ecp5-synth-options`).
    if rows.iter().any(|r| r.synth_command() != plain_synth(r.family, &r.device)) {
        let commands: BTreeSet<(&str, &str)> =
            rows.iter().map(|r| (r.block.as_str(), r.synth_command())).collect();
        let _ = writeln!(md, "Synthesis (`--ecp5-synth-options`):\n");
        for (block, command) in commands {
            let _ = writeln!(md, "- {block}: `{command}`");
        }
        let _ = writeln!(md);
    }
    // The nextpnr options, when some block was placed with any (`--ecp5-pnr-options`).
    let options: BTreeSet<(&str, &str)> =
        rows.iter().filter_map(|r| Some((r.block.as_str(), r.pnr.as_deref()?))).collect();
    if !options.is_empty() {
        let _ = writeln!(md, "Place and route (`--ecp5-pnr-options`, appended to nextpnr's command):\n");
        for (block, o) in options {
            let _ = writeln!(md, "- {block}: `{o}`");
        }
        let _ = writeln!(md);
    }
    let _ = writeln!(md, "Tools:\n");
    for t in ctx.tools.values() {
        let _ = writeln!(md, "- {}: {} ({})", t.kind.native(), t.version, t.found_as);
    }
    let _ = writeln!(md, "\nCritical paths (register to register):\n");
    for r in rows {
        if let Some(p) = &r.critical_path {
            let _ = writeln!(
                md,
                "- {} on {}, seed {}: {:.2} ns, {} logic levels, from `{}` to `{}`",
                r.block,
                r.family.name(),
                r.seed,
                p.delay_ns,
                p.logic_levels,
                p.from,
                p.to
            );
        }
    }
    let _ = writeln!(
        md,
        "\nRun times (Yosys once per block and family, counted once):\n\n| block | family | seed | Yosys (s) | nextpnr (s) |\n|---|---|--:|--:|--:|"
    );
    let secs = |t: Option<f64>| t.map(|t| format!("{t:.1}")).unwrap_or_else(|| "–".into());
    let mut total = 0.0;
    for r in rows {
        let first = ctx.seeds.first() == Some(&r.seed);
        total += if first { r.yosys_s.unwrap_or(0.0) } else { 0.0 } + r.nextpnr_s.unwrap_or(0.0);
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} |",
            r.block,
            r.family.name(),
            r.seed,
            secs(r.yosys_s),
            secs(r.nextpnr_s)
        );
    }
    let _ = writeln!(md, "\nTotal tool time: {total:.0} s.");
    md
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(block: &str, seed: u64, fmax: Option<f64>) -> Row {
        Row {
            block: block.into(),
            family: Family::Ecp5,
            device: "LFE5U-85F-6 CABGA381".into(),
            luts: None,
            ffs: None,
            dsps: None,
            brams: None,
            lutrams: None,
            fmax_mhz: fmax,
            target_mhz: 150.0,
            fits: Some(fmax.is_some()),
            over_capacity: Vec::new(),
            error: None,
            wrapper_ffs: None,
            seed,
            yosys_s: None,
            nextpnr_s: None,
            critical_path: None,
            floorplan: None,
            synth: None,
            pnr: None,
            tool_versions: BTreeMap::new(),
        }
    }

    #[test]
    fn spreads_give_min_median_max_per_block_over_the_seeds_that_routed() {
        let rows = vec![
            row("a", 1, Some(140.0)),
            row("b", 1, Some(200.0)),
            row("a", 2, Some(155.0)),
            row("a", 3, None),
            row("a", 4, Some(150.0)),
            row("a", 5, Some(149.0)),
        ];
        let hashes = BTreeMap::from([("a".to_string(), "0123456789abcdef".to_string())]);
        let s = spreads(&rows, &hashes);
        assert_eq!(s.len(), 2);
        assert_eq!((s[0].verilog_hash.as_str(), s[1].verilog_hash.as_str()), ("0123456789abcdef", ""));
        assert_eq!(s[0].seeds, vec![1, 2, 3, 4, 5]);
        assert_eq!((s[0].min_mhz, s[0].median_mhz, s[0].max_mhz), (Some(140.0), Some(149.0), Some(155.0)));
        assert_eq!((s[1].min_mhz, s[1].median_mhz, s[1].max_mhz), (Some(200.0), Some(200.0), Some(200.0)));
        let none = spreads(&[row("c", 1, None)], &hashes);
        assert_eq!(none[0].median_mhz, None);
    }

    #[test]
    fn seeds_of_one_block_placed_with_two_floorplans_are_not_merged() {
        let planned =
            |block: &str, seed: u64| Row { floorplan: Some("regions".into()), ..row(block, seed, None) };
        assert_eq!(mixed_floorplans(&[planned("a", 1), planned("a", 2), row("b", 1, None)]), None);
        let e = mixed_floorplans(&[planned("a", 1), row("a", 2, None)]).expect("two floorplans");
        assert!(
            e.contains("a on ecp5") && e.contains("seeds 1 and 2") && e.contains("regions / none"),
            "{e}"
        );
    }

    #[test]
    fn seeds_of_one_block_synthesized_two_ways_are_not_merged() {
        let synth = |seed: u64, command: &str| Row { synth: Some(command.into()), ..row("a", seed, None) };
        // A row from before the command was recorded is of the plain command.
        assert_eq!(mixed_syntheses(&[row("a", 1, None), synth(2, "synth_ecp5"), row("b", 1, None)]), None);
        let e = mixed_syntheses(&[row("a", 1, None), synth(2, "synth_ecp5 -dff")]).expect("two syntheses");
        assert!(e.contains("seeds 1 and 2") && e.contains("`synth_ecp5` / `synth_ecp5 -dff`"), "{e}");
    }

    #[test]
    fn synth_options_are_options_only() {
        assert_eq!(synth_options(" -dff  -nowidelut ").unwrap(), vec!["-dff", "-nowidelut"]);
        assert!(synth_options("").unwrap().is_empty());
        for bad in ["-dff; shell", "-run begin:end", "`x`", "-abc9|x", "$(x)"] {
            let e = synth_options(bad).map(|_| ()).expect_err(bad).to_string();
            assert!(
                e.contains("--ecp5-synth-options") && e.contains("not a synth_ecp5 option"),
                "{bad}: {e}"
            );
        }
    }

    #[test]
    fn pnr_options_are_options_only_and_not_the_flows() {
        let words = pnr_options(" --placer-heap-timingweight 30  --router router2 ").unwrap();
        assert_eq!(words, vec!["--placer-heap-timingweight", "30", "--router", "router2"]);
        assert!(pnr_options("").unwrap().is_empty());
        for bad in ["--seed 4", "--freq=200", "--report x.json", "--placer heap; rm"] {
            let e = pnr_options(bad).map(|_| ()).expect_err(bad).to_string();
            assert!(e.contains("--ecp5-pnr-options") && e.contains(bad), "{e}");
        }
    }

    #[test]
    fn merging_refuses_seeds_placed_with_two_sets_of_options() {
        let placed = |seed: u64, o: Option<&str>| Row { pnr: o.map(str::to_string), ..row("a", seed, None) };
        assert_eq!(mixed_pnr(&[placed(1, Some("--x 1")), placed(2, Some("--x 1")), row("b", 1, None)]), None);
        let e = mixed_pnr(&[placed(1, None), placed(2, Some("--x 1"))]).expect("two sets of options");
        assert!(e.contains("a on") && e.contains("seeds 1 and 2") && e.contains("`--x 1`"), "{e}");
    }

    #[test]
    fn a_spread_records_its_placement_options_and_plain_ones_are_left_out() {
        let placed = Row { pnr: Some("--placer-heap-timingweight 30".into()), ..row("a", 1, Some(150.0)) };
        let s = spreads(&[placed, row("b", 1, Some(150.0))], &BTreeMap::new());
        let json = serde_json::to_value(&s).unwrap();
        assert_eq!(json[0]["pnr"], "--placer-heap-timingweight 30");
        assert!(json[1].get("pnr").is_none(), "{}", json[1]);
    }
}
