//! Tracer speed, as ratios measured in one run: rays per second of each tracer against parry2d's
//! BVH ray casts on the same scene, single thread.
//!
//! Workload (issue: golden model, item 10): 1000 segments of length 32 in [0, 1024)², seed 7;
//! bundles of R = 1024 rays (angle set) from 16 source patches. Every method traces every bundle
//! once per round; rounds are interleaved so drift of the machine hits all methods alike, and the
//! median round is reported. Per-source work (screening, shell structure) is included.
//!
//! Run: `cargo bench --bench tracers` (`-- --rounds N` for more rounds; `-- --only NAME` times
//! only parry2d and the named method, e.g. to profile it with `perf record`).
//!
//! parry2d casts two-sided segments and uses f32; it is a speed baseline, not an oracle.

use parry2d::math::Vector as PVec;
use parry2d::query::{Ray as PRay, RayCast};
use parry2d::shape::Polyline;
use shelling::grid::GridParams;
use shelling::rays::{Bundle, RaySet};
use shelling::run::GriddedScene;
use shelling::scene;
use shelling::trace::{Method, ShellParams};
use std::hint::black_box;
use std::time::Instant;

fn main() {
    let rounds = std::env::args()
        .skip_while(|a| a != "--rounds")
        .nth(1)
        .and_then(|v| v.parse().ok())
        .unwrap_or(7usize);
    let only: Option<String> = std::env::args().skip_while(|a| a != "--only").nth(1);
    let scene = scene::generate(1000, 32.0, 7, scene::PAPER_WORLD).expect("the benchmark scene is valid");
    let prepared = GriddedScene::new(scene, GridParams::default());
    let sources: Vec<usize> = (0..16).map(|i| i * 1000 / 16).collect();
    let bundles: Vec<Bundle> = sources
        .iter()
        .map(|&k| prepared.patch_bundle(k, RaySet::Angle, 1024).expect("valid source"))
        .collect();
    let rays: usize = bundles.iter().map(Bundle::len).sum();
    let params = ShellParams::default();

    let mut vertices = Vec::new();
    let mut indices = Vec::new();
    for s in &prepared.scene.segments {
        let i = vertices.len() as u32;
        vertices.push(PVec::new(s.a.x as f32, s.a.y as f32));
        vertices.push(PVec::new(s.b.x as f32, s.b.y as f32));
        indices.push([i, i + 1]);
    }
    let polyline = Polyline::new(vertices, Some(indices));

    let parry = || {
        let mut hits = 0usize;
        for b in &bundles {
            for (i, ray) in b.rays.iter().enumerate() {
                // Skip the source patch itself as the tracers do: start a hair off the surface.
                let o = ray.origin + ray.dir * 1e-3;
                let r = PRay::new(
                    PVec::new(o.x as f32, o.y as f32),
                    PVec::new(ray.dir.x as f32, ray.dir.y as f32),
                );
                hits += polyline.cast_local_ray(&r, f32::MAX, true).is_some() as usize;
                black_box(i);
            }
        }
        hits
    };
    let methods: Vec<Method> =
        [Method::Brute, Method::Conventional, Method::Stochastic, Method::Deterministic]
            .into_iter()
            .filter(|m| only.as_deref().is_none_or(|o| o == m.name()))
            .collect();
    let run = |m: Method| {
        let mut hits = 0usize;
        for b in &bundles {
            hits += prepared
                .trace(m, b, &params)
                .expect("default parameters are valid")
                .hits
                .iter()
                .flatten()
                .count();
        }
        hits
    };

    // Warm up, then interleaved timed rounds.
    black_box(parry());
    for &m in &methods {
        black_box(run(m));
    }
    let mut times: Vec<Vec<f64>> = vec![Vec::new(); methods.len() + 1];
    for _ in 0..rounds {
        let t = Instant::now();
        black_box(parry());
        times[0].push(t.elapsed().as_secs_f64());
        for (i, &m) in methods.iter().enumerate() {
            let t = Instant::now();
            black_box(run(m));
            times[i + 1].push(t.elapsed().as_secs_f64());
        }
    }
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let base = rays as f64 / median(&mut times[0]);
    println!(
        "tracer speed: 1000 segments × length 32, R = 1024, {} sources, {rounds} rounds, 1 thread",
        bundles.len()
    );
    println!("{:<14}{:>16}{:>14}", "method", "rays/s", "× parry2d");
    println!("{:<14}{:>16.0}{:>14.2}", "parry2d", base, 1.0);
    for (i, m) in methods.iter().enumerate() {
        let rate = rays as f64 / median(&mut times[i + 1]);
        println!("{:<14}{:>16.0}{:>14.2}", m.name(), rate, rate / base);
    }
}
