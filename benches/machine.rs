//! The headline: rays per second of the machine against the best software tracer, measured in
//! one run.
//!
//! Workload ([`shelling::figures::machine::headline_scene`]): the paper's scene (1000 segments
//! of length 32 in [0, 1024)², seed 7), every one of its 1000 sources, R = 1024 rays (angle
//! set).
//!
//! - Software: the stochastic and deterministic tracers, every source once per round, on one
//!   thread and on every core (rayon, one source per task); the median round; the faster
//!   technique is the baseline.
//! - Machine: the same sources co-simulated cycle by cycle on N PEs (every hit checked against
//!   the bit-true model), `T_c` = 16 shared by all PEs, 250-patch caches per PE (a quarter of
//!   the scene: the cache's 256-line index, the host memory map leaving lines 250 … 255 unused),
//!   dealt in blocks of even work (the bit-true model's tests), the patches placed in the caches'
//!   lines by the host ([`shelling::machine::Placement::Lines`]); rays per second = rays × clock
//!   / cycles, the clock the median post-route rate of the machine of that N on ECP5
//!   (`hdl/fpga/ecp5-machine-seeds.json`) where it was measured, else the PE's alone (`hdl/fpga/ecp5-seeds.json`, said so). N is 1,
//!   4, 6 (the most that meet 150 MHz on the LFE5U-85F; seven fit it, at a median of 145.4) and 8 (more
//!   LUTs than it has).
//!
//! Run: `cargo bench --bench machine` (`-- --rounds N`; `-- --write FILE` writes the table as
//! Markdown, as `figures/headline.md` is written).

#[path = "support/headline.rs"]
mod headline;

use rayon::prelude::*;
use shelling::cosim::Engine;
use shelling::figures::machine::{headline_run, headline_scene, HEADLINE_CACHE, HEADLINE_TC};
use shelling::rays::{Bundle, RaySet};
use shelling::trace::{Method, ShellParams};
use std::fmt::Write as _;
use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

/// The median post-route clock (MHz) of `block` in the results file `file`, if measured.
fn median_mhz(file: &str, block: &str) -> Option<f64> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("hdl/fpga").join(file);
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path).ok()?).ok()?;
    json["blocks"].as_array()?.iter().find(|b| b["block"] == block)?["median_mhz"].as_f64()
}

fn main() {
    let arg = |name: &str| std::env::args().skip_while(|a| a != name).nth(1);
    let rounds: usize = arg("--rounds").and_then(|v| v.parse().ok()).unwrap_or(7);
    let (prepared, order) = headline_scene().expect("the headline scene");
    let bundles: Vec<Bundle> =
        order.iter().map(|&k| prepared.patch_bundle(k, RaySet::Angle, 1024).expect("valid source")).collect();
    let rays: usize = bundles.iter().map(Bundle::len).sum();
    let params = ShellParams::default();
    let one = |m: Method, b: &Bundle| prepared.trace(m, b, &params).expect("valid").hits.len();
    let threads = rayon::current_num_threads();

    // Software: rounds interleaved over technique, the one-core rounds before any on all cores
    // (rayon's idle workers spin for a while after a parallel round and would slow a one-core
    // round run after it); the median round.
    let software = [Method::Stochastic, Method::Deterministic];
    for &m in &software {
        black_box(bundles.iter().map(|b| one(m, b)).sum::<usize>());
    }
    let mut times = vec![[Vec::new(), Vec::new()]; software.len()];
    for j in 0..2 {
        for _ in 0..rounds {
            for (i, &m) in software.iter().enumerate() {
                let t = Instant::now();
                let hits: usize = if j == 0 {
                    bundles.iter().map(|b| one(m, b)).sum()
                } else {
                    bundles.par_iter().map(|b| one(m, b)).sum()
                };
                black_box(hits);
                times[i][j].push(t.elapsed().as_secs_f64());
            }
        }
    }
    let rates: Vec<[f64; 2]> = times
        .iter_mut()
        .map(|[a, b]| [rays as f64 / headline::median(a), rays as f64 / headline::median(b)])
        .collect();

    // The machine of 1, 4, 6 (the most measured on the LFE5U-85F) and 8 PEs, each at its own
    // measured clock where there is one.
    let pe_mhz = median_mhz("ecp5-seeds.json", "processing_element").expect("the PE's results are committed");
    let pes = [1, 4, 6, 8];
    let mut md = String::new();
    let _ = writeln!(
        md,
        "The paper's workload: 1000 segments of length 32, seed 7, every source, R = 1024 (`cargo bench --bench \
         machine`). Machine: `T_c` = {HEADLINE_TC} cycles per patch on one host memory shared by all PEs, a \
         {HEADLINE_CACHE}-patch cache per PE (a quarter of the scene), the sources in Hilbert order dealt in blocks of \
         even work, the patches placed in the caches' lines by the host (`--place lines`), every hit checked against \
         the bit-true model; software: the stochastic and deterministic \
         tracers, median of {rounds} rounds on this machine ({threads} cores; the one-core rounds first), the \
         ratios against the faster of them on one core and on all cores. The machine's clock: the median \
         post-route rate on the LFE5U-85F-6 of the machine of that many PEs where it was measured, else the \
         PE's alone (`hdl/fpga/`).\n"
    );
    // The baselines: the faster technique on one core, and the faster on all cores.
    let names: Vec<String> = software.iter().map(|m| m.to_string()).collect();
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    let (core, cores) = headline::software_rows(&mut md, &names, &rates, threads);
    for &n in &pes {
        for &m in &software {
            let run = headline_run(m, n, Engine::Auto).expect("the machine co-simulates the headline");
            let (mhz, whose) = match median_mhz("ecp5-machine-seeds.json", &format!("machine_{n}")) {
                Some(f) => (f, format!("machine_{n}")),
                None => (pe_mhz, "the PE's alone".to_string()),
            };
            let rate = run.rays as f64 * mhz * 1e6 / run.cycles as f64;
            let _ = writeln!(
                md,
                "| machine, {n} PE{} | {m} | {} | {} | {:.3} | {mhz:.1} ({whose}) | {:.1} M | **{:.2}** | {:.2} |",
                if n == 1 { "" } else { "s" },
                run.cycles,
                run.memory_loads,
                run.rays_per_cycle(),
                rate / 1e6,
                rate / core,
                rate / cores
            );
        }
    }
    headline::finish(&md, arg("--write"));
}
