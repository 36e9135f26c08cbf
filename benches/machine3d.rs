//! The headline in 3D: form-factor rays per second of the machine on the Cornell box against the
//! 3D software tracers, measured in one run.
//!
//! Workload: `scenes/cornell_box.obj` (26 polygons), every polygon's form-factor row, R = 4096
//! cosine-weighted rays from each of M = 16 origins ([`ORIGINS`]).
//!
//! - Software: every 3D technique (brute force, conventional, polar, sweep: the same rows)
//!   computing the rows, on one thread and on every core (rayon, a row a task); the median of
//!   the rounds; the fastest technique is the baseline.
//! - Machine: the rows' sweep planes co-simulated cycle by cycle on N PEs
//!   ([`shelling::d3::on_pe::rows_on_machine`]: every plane a source, every hit checked against
//!   the bit-true model), `T_c` = 16 cycles per patch on one host memory shared by all PEs, a
//!   cache of a quarter of the scene's polygons per PE; rays per second = rays × clock / cycles,
//!   the clock the median post-route rate of the machine of that N on ECP5 where it was measured,
//!   else the PE's alone (`hdl/fpga/`, said so). N is 1, 2, 4 and 6.
//!
//! Run: `cargo bench --bench machine3d` (`-- --rounds N`; `-- --write FILE` writes the table as
//! Markdown, as `figures/headline3d.md` is written).

#[path = "support/headline.rs"]
mod headline;

use shelling::cosim::Engine;
use shelling::d3::form_factors as ff3;
use shelling::d3::grid::{Grid3, Grid3Params};
use shelling::d3::trace::Method3;
use shelling::figures::d3::{
    headline3d_params as params, headline3d_run, headline3d_scene, HEADLINE3D_ORIGINS as ORIGINS,
    HEADLINE3D_RAYS as RAYS,
};
use shelling::figures::machine::HEADLINE_TC as TC;
use shelling::radiosity::on_pe::{machine_clock_mhz, pe_clock_mhz};
use std::fmt::Write as _;
use std::hint::black_box;
use std::time::Instant;

fn main() {
    let arg = |name: &str| std::env::args().skip_while(|a| a != name).nth(1);
    let rounds: usize = arg("--rounds").and_then(|v| v.parse().ok()).unwrap_or(3);
    let scene = headline3d_scene().expect("the shipped Cornell box");
    let grid = Grid3::build(&scene, Grid3Params::default()).expect("its grid");
    let n = scene.polygons.len();
    let rays = (n * ORIGINS * RAYS) as f64;
    let threads = rayon::current_num_threads();

    // Software: the one-core rounds before any on all cores (rayon's idle workers spin for a
    // while after a parallel round); the median round.
    let software = Method3::ALL;
    let mut times = vec![[Vec::new(), Vec::new()]; software.len()];
    for j in 0..2 {
        for _ in 0..rounds {
            for (i, &m) in software.iter().enumerate() {
                let p = params(m);
                let t = Instant::now();
                let rows = if j == 0 {
                    (0..n).map(|k| ff3::row(&scene, &grid, k, &p).expect("a row")).collect::<Vec<_>>()
                } else {
                    ff3::rows(&scene, &grid, 0..n, &p, || {}).expect("the rows")
                };
                black_box(rows);
                times[i][j].push(t.elapsed().as_secs_f64());
            }
        }
    }
    let rates: Vec<[f64; 2]> =
        times.iter_mut().map(|[a, b]| [rays / headline::median(a), rays / headline::median(b)]).collect();

    let mut md = String::new();
    let _ = writeln!(
        md,
        "The Cornell box (`scenes/cornell_box.obj`, {n} polygons): every polygon's form-factor row, {RAYS} cosine \
         rays from each of {ORIGINS} origins (`cargo bench --bench machine3d`). Machine: every row's sweep planes \
         (64 planes of 64 rays an origin), packed 16 planes a source of the PEs, `T_c` = {TC} cycles per patch on one host memory shared by all \
         PEs, a {}-patch cache per PE (a quarter of the polygons), every hit checked against the bit-true \
         model; software: the four 3D techniques (the same rows), median of {rounds} rounds on this machine \
         ({threads} cores; the one-core rounds first), the ratios against the fastest on one core and on all \
         cores. The machine's clock: the median post-route rate on the LFE5U-85F-6 of the machine of that many \
         PEs where it was measured, else the PE's alone (`hdl/fpga/`).\n",
        n / 4
    );
    let names: Vec<&str> = software.iter().map(|m| m.name()).collect();
    let (core, cores) = headline::software_rows(&mut md, &names, &rates, threads);
    for pes in [1, 2, 4, 6] {
        let t = headline3d_run(pes, Engine::Auto).expect("the machine's rows");
        let (mhz, whose) = match machine_clock_mhz(pes) {
            Some(f) => (f, format!("machine_{pes}")),
            None => (pe_clock_mhz(), "the PE's alone".to_string()),
        };
        let rate = rays * mhz * 1e6 / t.pe.cycles as f64;
        let _ = writeln!(
            md,
            "| machine, {pes} PE{} | sweep | {} | {} | {:.3} | {mhz:.1} ({whose}) | {:.1} M | **{:.2}** | {:.2} |",
            if pes == 1 { "" } else { "s" },
            t.pe.cycles,
            t.pe.patch_loads - t.pe.cache_hits,
            rays / t.pe.cycles as f64,
            rate / 1e6,
            rate / core,
            rate / cores
        );
    }
    headline::finish(&md, arg("--write"));
}
