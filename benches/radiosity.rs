//! Radiosity speed, measured in one run (RADIOSITY.md, "Speed"):
//!
//! 1. form-factor rows per second of every technique on the default room (176 patches, R = 2048
//!    sine rays, M = 16 origins), one thread, as ratios against brute force: rounds interleave
//!    the techniques and the median round is reported;
//! 2. the wall time of the full form-factor matrix of a 10,240-patch room (1024 × 1024, patches
//!    of 0.5, four boxes of 64) at R = 1024, M = 4 on all cores, by the technique fastest in 1
//!    and by the conventional one. Goal: under 10 s on 2 cores.
//!
//! Run: `cargo bench --bench radiosity` (`-- --rounds N`; `-- --small` skips part 2;
//! `-- --full METHOD` times part 2 with that technique only).

use shelling::grid::GridParams;
use shelling::radiosity::form_factors::{self, FfParams};
use shelling::run::GriddedScene;
use shelling::scene::{room, RoomSpec};
use shelling::trace::Method;
use std::hint::black_box;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let rounds =
        args.iter().skip_while(|a| *a != "--rounds").nth(1).and_then(|v| v.parse().ok()).unwrap_or(5usize);
    let small = args.iter().any(|a| a == "--small");
    let full: Option<Method> = args.iter().skip_while(|a| *a != "--full").nth(1).map(|name| {
        *Method::ALL.iter().find(|m| m.name() == name).unwrap_or_else(|| {
            eprintln!("--full {name}: no such technique (brute, conventional, stochastic, deterministic)");
            std::process::exit(2)
        })
    });

    let prepared =
        GriddedScene::new(room(&RoomSpec::default()).expect("the default room"), GridParams::default());
    let sources: Vec<usize> = (0..prepared.scene.len()).step_by(11).collect();
    let fp = FfParams::default();
    println!(
        "default room: {} patches; {} rows per round, {} origins × {} {} rays each; {rounds} rounds, 1 thread",
        prepared.scene.len(),
        sources.len(),
        fp.origins,
        fp.rays,
        fp.ray_set
    );
    let mut times: Vec<(Method, Vec<f64>)> = Method::ALL.iter().map(|&m| (m, Vec::new())).collect();
    for _ in 0..rounds {
        for (method, t) in &mut times {
            let p = FfParams { method: *method, ..fp.clone() };
            let start = Instant::now();
            for &k in &sources {
                black_box(form_factors::row(&prepared, k, &p).expect("the row traces"));
            }
            t.push(start.elapsed().as_secs_f64());
        }
    }
    let median = |t: &[f64]| {
        let mut t = t.to_vec();
        t.sort_by(f64::total_cmp);
        t[t.len() / 2]
    };
    let brute = median(&times[0].1);
    let mut best = (Method::Brute, brute);
    println!("{:<14}{:>12}{:>16}", "method", "rows/s", "against brute");
    for (method, t) in &times {
        let m = median(t);
        if m < best.1 {
            best = (*method, m);
        }
        println!("{:<14}{:>12.1}{:>15.2}×", method.name(), sources.len() as f64 / m, brute / m);
    }
    if small {
        return;
    }

    let spec = RoomSpec {
        width: 1024.0,
        height: 1024.0,
        patch_length: 0.5,
        boxes: 4,
        box_size: 64.0,
        ..RoomSpec::default()
    };
    let big = GriddedScene::new(room(&spec).expect("the large room"), GridParams::default());
    let fp = FfParams { rays: 1024, origins: 4, ..FfParams::default() };
    let threads = rayon::current_num_threads();
    let mut methods = vec![best.0];
    if best.0 != Method::Conventional {
        methods.push(Method::Conventional);
    }
    if let Some(m) = full {
        methods = vec![m];
    }
    for method in methods {
        let p = FfParams { method, ..fp.clone() };
        let start = Instant::now();
        let rows = form_factors::rows(&big, 0..big.scene.len(), &p, || {}).expect("the rows trace");
        let wall = start.elapsed().as_secs_f64();
        let entries: usize = rows.iter().map(|r| r.entries.len()).sum();
        println!(
            "full matrix of {} patches, R = {}, M = {}, {method}, {threads} threads: {wall:.2} s wall ({} form factors; goal < 10 s on 2 cores: {})",
            big.scene.len(),
            p.rays,
            p.origins,
            entries,
            if wall < 10.0 { "met" } else { "not met" }
        );
    }
}
