//! 3D tracer speed, as ratios measured in one run: rays per second of each 3D tracer
//! (`Method3::ALL`) against parry3d's BVH ray casts on the same scene, single thread.
//!
//! Workloads: the 3D workload (`scene gen --dim 3`: 1000 squares of side 32 in [0, 1024)³,
//! seed 7) and the Cornell box (`scenes/cornell_box.obj`, 26 polygons). From each of 16
//! source polygons (spread over the indices), the cosine-weighted hemisphere set of R = 1024
//! rays (64 × 16) from its vertex centroid. Every method traces every bundle once per round;
//! rounds are interleaved so drift of the machine hits all methods alike, and the median round
//! is reported. The grids are built once, before timing; the per-bundle work (screening) is
//! timed. The hemisphere sets are made once.
//!
//! Run: `cargo bench --bench tracers3d` (`-- --rounds N` for more rounds; for profiling,
//! `-- --methods conventional,polar` times only those tracers beside parry3d and `-- --scene
//! workload` or `cornell` runs that scene alone).
//!
//! parry3d casts against the polygons' fan triangles in f32 with back-face culling
//! (`RayCullingMode::IgnoreBackfaces`), which is the tracers' screening: it is a speed
//! baseline, not an oracle; the rays whose nearest polygon differs are counted and printed.

use parry3d::math::Vector as PVec;
use parry3d::query::{Ray as PRay, RayCullingMode};
use parry3d::shape::TriMesh;
use shelling::d3::grid::{Grid3, Grid3Params};
use shelling::d3::hemisphere::{HemisphereRays, Strata};
use shelling::d3::trace::{self, Bundle3, Method3};
use shelling::d3::{gen, obj, Scene3};
use std::hint::black_box;
use std::time::Instant;

/// One workload: the scene, its grid, its bundles and parry3d's mesh of it.
struct Workload {
    name: &'static str,
    scene: Scene3,
    grid: Grid3,
    bundles: Vec<Bundle3>,
    mesh: TriMesh,
    /// The polygon of each triangle of `mesh`.
    polygon_of: Vec<usize>,
}

impl Workload {
    fn new(name: &'static str, scene: Scene3) -> Workload {
        let grid = Grid3::build(&scene, Grid3Params::default()).expect("the benchmark scene has a grid");
        let n = scene.polygons.len();
        let bundles = (0..16)
            .map(|i| {
                let k = i * n / 16;
                let p = &scene.polygons[k];
                let set = HemisphereRays::new(p.centre, p.normal, 64, 16, Strata::Cosine).expect("valid set");
                Bundle3::from_hemisphere(&set, Some(k))
            })
            .collect();
        let mut vertices = Vec::new();
        let mut indices = Vec::new();
        let mut polygon_of = Vec::new();
        for (k, p) in scene.polygons.iter().enumerate() {
            let base = vertices.len() as u32;
            vertices.extend(p.vertices.iter().map(|v| PVec::new(v.x as f32, v.y as f32, v.z as f32)));
            for i in 1..p.vertices.len() as u32 - 1 {
                indices.push([base, base + i, base + i + 1]);
                polygon_of.push(k);
            }
        }
        let mesh = TriMesh::new(vertices, indices).expect("the benchmark mesh is valid");
        Workload { name, scene, grid, bundles, mesh, polygon_of }
    }

    fn rays(&self) -> usize {
        self.bundles.iter().map(Bundle3::len).sum()
    }

    /// parry3d's nearest polygon of every ray, bundle after bundle.
    fn parry(&self) -> Vec<Option<usize>> {
        let mut hits = Vec::with_capacity(self.rays());
        for b in &self.bundles {
            let o = b.source.origin;
            let origin = PVec::new(o.x as f32, o.y as f32, o.z as f32);
            for d in &b.directions {
                let ray = PRay::new(origin, PVec::new(d.x as f32, d.y as f32, d.z as f32));
                let hit =
                    self.mesh.cast_local_ray_with_culling(&ray, f32::MAX, RayCullingMode::IgnoreBackfaces);
                hits.push(hit.map(|h| self.polygon_of[h.subshape as usize]));
            }
        }
        hits
    }

    /// `method`'s nearest polygon of every ray.
    fn run(&self, method: Method3) -> Vec<Option<usize>> {
        let mut hits = Vec::with_capacity(self.rays());
        for b in &self.bundles {
            hits.extend(
                trace::trace(method, &self.scene, &self.grid, b, &shelling::trace::ShellParams::default())
                    .expect("default parameters are valid")
                    .hits
                    .iter()
                    .map(|h| h.map(|h| h.polygon)),
            );
        }
        hits
    }
}

fn main() {
    let rounds = std::env::args()
        .skip_while(|a| a != "--rounds")
        .nth(1)
        .and_then(|v| v.parse().ok())
        .unwrap_or(7usize);
    // `--methods brute,polar` times only those tracers (for profiling; parry3d always runs).
    let list = |option: &str| -> Option<Vec<String>> {
        std::env::args()
            .skip_while(|a| a != option)
            .nth(1)
            .map(|v| v.split(',').map(str::to_string).collect())
    };
    let only = list("--methods");
    // `--scene workload` or `--scene cornell`: that scene alone (for profiling).
    let scene = list("--scene");
    let wanted = |key: &str| scene.as_ref().is_none_or(|s| s.iter().any(|n| n == key));
    let cornell = obj::load(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cornell_box.obj"))
        .expect("the Cornell box loads");
    let mut workloads = Vec::new();
    if wanted("workload") {
        workloads.push(Workload::new(
            "3D workload (1000 squares of side 32, seed 7)",
            gen::generate(1000, 32.0, 7).expect("valid"),
        ));
    }
    if wanted("cornell") {
        workloads.push(Workload::new("Cornell box (26 polygons)", cornell));
    }
    println!("3D tracer speed: R = 1024 cosine rays (64 × 16) from 16 sources, {rounds} rounds, 1 thread");
    for w in &workloads {
        let methods: Vec<Method3> = Method3::ALL
            .into_iter()
            .filter(|m| only.as_ref().is_none_or(|o| o.iter().any(|n| n == m.name())))
            .collect();
        // Warm up (and compare the hits), then interleaved timed rounds.
        let base_hits = w.parry();
        // Under `--methods` (profiling) brute force runs only if named.
        let differ = match only.is_none() || methods.contains(&Method3::Brute) {
            true => {
                let oracle = w.run(Method3::Brute);
                base_hits.iter().zip(&oracle).filter(|(a, b)| a != b).count().to_string()
            }
            false => "(not compared)".to_string(),
        };
        for &m in &methods {
            black_box(w.run(m));
        }
        let mut times: Vec<Vec<f64>> = vec![Vec::new(); methods.len() + 1];
        for _ in 0..rounds {
            let t = Instant::now();
            black_box(w.parry());
            times[0].push(t.elapsed().as_secs_f64());
            for (i, &m) in methods.iter().enumerate() {
                let t = Instant::now();
                black_box(w.run(m));
                times[i + 1].push(t.elapsed().as_secs_f64());
            }
        }
        let median = |v: &mut Vec<f64>| {
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        };
        let rays = w.rays() as f64;
        let base = rays / median(&mut times[0]);
        println!(
            "\n{}: {} rays; parry3d's nearest polygon differs from brute force's on {differ}",
            w.name,
            w.rays()
        );
        println!("{:<14}{:>16}{:>14}", "method", "rays/s", "× parry3d");
        println!("{:<14}{:>16.0}{:>14.2}", "parry3d", base, 1.0);
        for (i, m) in methods.iter().enumerate() {
            let rate = rays / median(&mut times[i + 1]);
            println!("{:<14}{:>16.0}{:>14.2}", m.name(), rate, rate / base);
        }
    }
}
