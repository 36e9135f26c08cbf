//! Rung 1 in 3D for every tracer: each [`Method3`] returns exactly the brute-force nearest hit
//! (polygon, `t` and side, bit for bit) for every ray of hemisphere sets, with sensible counters,
//! on random scenes, adversarial ones (rays through shared vertices and edges, grazing polygons,
//! polygons parallel to a sweep plane, polygons through the source's plane) and the closed scenes
//! (the box room, the Cornell box). Everything is seeded; a failure names its seed, scene, source
//! and ray. The larger sweep is `tests/tier2/tracers3d.rs`.

use crate::support::tracers3d::{agree_all, bundle_on, cornell, random_scenes};
use glam::DVec3;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use shelling::d3::gen::{box_room, generate};
use shelling::d3::grid::{Grid3, Grid3Params};
use shelling::d3::hemisphere::{HemisphereRays, Strata};
use shelling::d3::scene::{Material3, Polygon, Scene3};
use shelling::d3::trace::{self, Bundle3, Method3, Source3, Trace3Error};
use shelling::trace::ShellParams;

#[test]
fn every_tracer_matches_brute_on_random_scenes() {
    random_scenes(&[(1, 200, 32.0), (2, 400, 100.0), (3, 60, 300.0)], 6, 12, 10);
}

#[test]
fn every_tracer_hits_everywhere_in_the_closed_scenes() {
    let mut rng = ChaCha8Rng::seed_from_u64(700);
    for (name, scene) in [("box room", box_room()), ("Cornell box", cornell())] {
        let grid = Grid3::build(&scene, Grid3Params::default()).unwrap();
        for s in 0..8 {
            let k = rng.random_range(0..scene.polygons.len());
            let bundle = bundle_on(&scene, k, &mut rng, 16, 8);
            let what = format!("seed 700: {name}, source {s} on patch {k}");
            let traces = agree_all(&what, &scene, &grid, &bundle);
            if name == "box room" {
                // The room is closed: every ray hits (the Cornell box has an open front).
                assert!(traces.iter().all(|t| t.counters.actual_intersections == 128), "{what}");
            }
        }
    }
}

/// The polygon on `v`, its vertex order reversed if need be so that its front faces `o`.
fn facing(mut v: Vec<DVec3>, o: DVec3) -> Result<Polygon, shelling::d3::PolygonProblem> {
    let p = Polygon::new(v.clone())?;
    if (o - p.centre).dot(p.normal) >= 0.0 {
        return Ok(p);
    }
    v.reverse();
    Polygon::new(v)
}

/// A mesh on the plane `z = 40` whose vertices lie exactly on rays of `rays` (source at the
/// origin, normal +z), facing the source: rays through its shared vertices and along its
/// shared edges.
fn mesh_on_rays(rays: &HemisphereRays) -> Scene3 {
    let m = Material3::grey("m", 0.5, 0.0);
    let at = |i: usize, j: usize| {
        let d = rays.rays[rays.index(i % rays.n_theta, j)].direction;
        d * (40.0 / d.z)
    };
    let mut polygons = Vec::new();
    for i in 0..rays.n_theta {
        for j in 0..rays.n_phi - 1 {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            for v in [vec![a, c, b], vec![a, d, c]] {
                if let Ok(p) = facing(v, rays.origin) {
                    polygons.push(p.with_material(0, &m));
                }
            }
        }
    }
    Scene3 { polygons, materials: vec![m] }
}

#[test]
fn rays_through_shared_vertices_and_edges_agree() {
    for (n_theta, n_phi, strata) in [(8, 4, Strata::Angle), (12, 6, Strata::Cosine), (16, 5, Strata::Angle)] {
        let rays = HemisphereRays::new(DVec3::ZERO, DVec3::Z, n_theta, n_phi, strata).unwrap();
        let scene = mesh_on_rays(&rays);
        assert!(scene.polygons.len() > n_theta, "the mesh must be built");
        let grid = Grid3::build(&scene, Grid3Params::default()).unwrap();
        let bundle = Bundle3::from_hemisphere(&rays, None);
        let traces = agree_all(&format!("mesh on rays {n_theta}×{n_phi}"), &scene, &grid, &bundle);
        // Every ray but the outermost cells' lies on the mesh.
        assert!(traces[0].counters.actual_intersections >= (n_theta * (n_phi - 1)) as u64);
    }
}

/// Polygons that graze the rays: in planes through the source nearly containing rays, parallel
/// (to a hair) to a sweep plane, and straddling or touching the source's plane.
fn grazing_scene(rays: &HemisphereRays, rng: &mut ChaCha8Rng) -> Scene3 {
    let m = Material3::grey("m", 0.5, 0.0);
    let mut polygons = Vec::new();
    let mut add = |v: Vec<DVec3>| {
        if let Ok(p) = facing(v, rays.origin) {
            polygons.push(p.with_material(0, &m));
        }
    };
    let (t, b, n) = (rays.tangent, rays.bitangent, rays.normal);
    for i in 0..rays.n_theta / 2 {
        let theta = (i as f64 + 0.5) * std::f64::consts::TAU / rays.n_theta as f64;
        let u = t * theta.cos() + b * theta.sin();
        let w = u.cross(n);
        // Parallel to sweep plane i, offset by a hair and by a little, on both sides.
        for off in [1e-9, 1e-4, -1e-9, 2.0] {
            let c = w * off + u * rng.random_range(-30.0..30.0) + n * rng.random_range(5.0..30.0);
            let (e1, e2) = (u * 8.0, n * 8.0);
            add(vec![c - e1 - e2, c + e1 - e2, c + e1 + e2, c - e1 + e2]);
        }
        // Crossing sweep plane i at 10⁻⁴ rad: sliced by no plane, tested directly.
        let c = u * rng.random_range(-30.0..30.0) + n * rng.random_range(5.0..30.0);
        let (e1, e2) = (u * 8.0, n * 8.0 + w * 8e-4);
        add(vec![c - e1 - e2, c + e1 - e2, c + e1 + e2, c - e1 + e2]);
        // Nearly containing a ray: a thin quad along a ray direction, tilted by a hair.
        let d = rays.rays[rays.index(i, rays.n_phi / 2)].direction;
        let side = d.cross(n).normalize_or(u);
        let lift = side.cross(d).normalize();
        let (p0, p1) = (d * 10.0, d * 60.0);
        add(vec![p0 + lift * 1e-10, p1 + lift * 1e-10, p1 + side * 3.0, p0 + side * 3.0]);
        add(vec![p0 - lift * 1e-10, p0 - side * 3.0, p1 - side * 3.0, p1 - lift * 1e-10]);
    }
    // Through the source's plane: straddling it, touching it with an edge, below it.
    for k in 0..16 {
        let a = k as f64 * std::f64::consts::TAU / 16.0;
        let dir = t * a.cos() + b * a.sin();
        let c = dir * (40.0 + 5.0 * (k % 3) as f64);
        let across = dir.cross(n);
        let lo = [-10.0, 0.0, -20.0, -1e-12][k % 4];
        let hi = lo + 15.0;
        add(vec![
            c + across * 6.0 + n * lo,
            c - across * 6.0 + n * lo,
            c - across * 6.0 + n * hi,
            c + across * 6.0 + n * hi,
        ]);
    }
    Scene3 { polygons, materials: vec![m] }
}

#[test]
fn grazing_and_straddling_polygons_agree() {
    let mut rng = ChaCha8Rng::seed_from_u64(800);
    for (s, (n_theta, n_phi)) in [(8, 6), (16, 8), (24, 3)].into_iter().enumerate() {
        let normal = DVec3::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0), 1.0).normalize();
        let o =
            DVec3::new(rng.random_range(-5.0..5.0), rng.random_range(-5.0..5.0), rng.random_range(-5.0..5.0));
        let strata = if s % 2 == 0 { Strata::Angle } else { Strata::Cosine };
        let rays = HemisphereRays::new(o, normal, n_theta, n_phi, strata).unwrap();
        let mut scene = grazing_scene(
            &HemisphereRays::new(DVec3::ZERO, normal, n_theta, n_phi, strata).unwrap(),
            &mut rng,
        );
        for p in &mut scene.polygons {
            let v: Vec<DVec3> = p.vertices.iter().map(|v| *v + o).collect();
            *p = Polygon::new(v).unwrap().with_material(0, &scene.materials[0]);
        }
        let grid = Grid3::build(&scene, Grid3Params::default()).unwrap();
        let bundle = Bundle3::from_hemisphere(&rays, None);
        let traces =
            agree_all(&format!("seed 800: grazing scene {s}, {n_theta}×{n_phi}"), &scene, &grid, &bundle);
        assert!(traces[0].counters.actual_intersections > 0, "seed 800: scene {s} must be hit");
        // The hair-thin offsets from the sweep planes put polygons in the planes' direct lists.
        let planes = shelling::d3::sweep::planes(&scene, &bundle).unwrap();
        assert!(
            planes.iter().any(|p| !p.direct.is_empty()),
            "seed 800: scene {s} must exercise the direct lists"
        );
    }
}

#[test]
fn free_directions_and_odd_bands_are_refused_with_the_reason() {
    let scene = box_room();
    let grid = Grid3::build(&scene, Grid3Params::default()).unwrap();
    let p = &scene.polygons[4];
    let free = Bundle3 {
        source: Source3 { origin: p.centre, normal: p.normal, patch: Some(4) },
        directions: vec![DVec3::Y],
        layout: None,
    };
    let params = ShellParams::default();
    for m in [Method3::Polar, Method3::Sweep] {
        let e = trace::trace(m, &scene, &grid, &free, &params).unwrap_err();
        assert_eq!(e, Trace3Error::NoLayout(m));
        assert!(e.to_string().contains("hemisphere ray set"), "{e}");
    }
    let rays = HemisphereRays::new(p.centre, p.normal, 5, 4, Strata::Cosine).unwrap();
    let odd = Bundle3::from_hemisphere(&rays, Some(4));
    let e = trace::trace(Method3::Sweep, &scene, &grid, &odd, &params).unwrap_err();
    assert!(e.to_string().contains("even number of Θ-bands") && e.to_string().contains('5'), "{e}");
    // The polar tracer takes any number of bands.
    assert!(trace::trace(Method3::Polar, &scene, &grid, &odd, &params).is_ok());
    let mut bad = Bundle3::from_hemisphere(&rays, Some(4));
    bad.directions[3] *= 2.0;
    let e = trace::trace(Method3::Polar, &scene, &grid, &bad, &params).unwrap_err();
    assert!(e.to_string().contains("direction 3 is not a unit vector"), "{e}");
}

#[test]
fn the_sweep_planes_are_2d_scenes_the_2d_tracers_take() {
    let scene = generate(300, 64.0, 9).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(9);
    let bundle = bundle_on(&scene, 17, &mut rng, 16, 8);
    let planes = shelling::d3::sweep::planes(&scene, &bundle).unwrap();
    assert_eq!(planes.len(), 8);
    for plane in &planes {
        assert_eq!(plane.bundle.len(), 16);
        assert!(plane.bundle.angles.windows(2).all(|w| w[0] < w[1]));
        let (scene2, _) = plane.slices.as_ref().expect("a plane through 300 squares meets some");
        // A valid 2D scene, which the 2D brute-force tracer can take as it is.
        scene2.validate("slice").unwrap();
        assert_eq!(scene2.segments.len(), plane.polygons.len());
        assert!(plane.polygons.windows(2).all(|w| w[0] < w[1]));
    }
}
