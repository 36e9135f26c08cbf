//! The 3D tracers' rung 1, shared by `tests/tracers3d.rs` (tier 1) and
//! `tests/tier2/tracers3d.rs`: every [`Method3`] traced and checked against brute force.

use glam::DVec3;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use shelling::d3::gen::generate;
use shelling::d3::grid::{Grid3, Grid3Params};
use shelling::d3::hemisphere::{HemisphereRays, Strata};
use shelling::d3::obj;
use shelling::d3::scene::{Polygon, Scene3};
use shelling::d3::trace::{self, Bundle3, Method3, Trace3};
use shelling::trace::ShellParams;

/// The shipped Cornell box.
pub fn cornell() -> Scene3 {
    obj::load(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cornell_box.obj")).unwrap()
}

/// Traces `bundle` by every method and checks each against brute force; returns the traces in
/// the order of [`Method3::ALL`].
pub fn agree_all(what: &str, scene: &Scene3, grid: &Grid3, bundle: &Bundle3) -> Vec<Trace3> {
    let params = ShellParams::default();
    let traces: Vec<Trace3> =
        Method3::ALL.iter().map(|&m| trace::trace(m, scene, grid, bundle, &params).unwrap()).collect();
    let b = &traces[0];
    assert_eq!(b.hits.len(), bundle.len(), "{what}");
    for (m, t) in Method3::ALL.iter().zip(&traces).skip(1) {
        for (i, (hb, ht)) in b.hits.iter().zip(&t.hits).enumerate() {
            assert_eq!(
                hb, ht,
                "{what}: {m}: ray {i} from {} direction {}: brute {hb:?}, {m} {ht:?}",
                bundle.source.origin, bundle.directions[i]
            );
        }
        let (cb, ct) = (&b.counters, &t.counters);
        assert_eq!(cb.actual_intersections, ct.actual_intersections, "{what}: {m}");
        assert_eq!(cb.adlc_true, ct.adlc_true, "{what}: {m}");
        // Each (ray, polygon) pair is tested at most once, and only loaded polygons are tested.
        assert!(ct.intersection_computations <= cb.intersection_computations, "{what}: {m}: {ct:?}");
        assert!(ct.patches_read_after_screening <= ct.patches_read_before_screening, "{what}: {m}: {ct:?}");
        assert!(ct.intersection_computations >= ct.actual_intersections, "{what}: {m}: {ct:?}");
        if ct.actual_intersections > 0 {
            assert!(ct.cells_traversed > 0 && ct.patches_read_after_screening > 0, "{what}: {m}: {ct:?}");
        }
        assert!(ct.adlc_estimated.is_finite() && ct.adlc_estimated >= 0.0, "{what}: {m}: {ct:?}");
    }
    assert!(b.hits.iter().flatten().all(|h| h.front && Some(h.polygon) != bundle.source.patch), "{what}");
    traces
}

/// A random point of polygon `p`.
pub fn point_on(p: &Polygon, rng: &mut ChaCha8Rng) -> DVec3 {
    let i = rng.random_range(1..p.vertices.len() - 1);
    let (mut u, mut v) = (rng.random::<f64>(), rng.random::<f64>());
    if u + v > 1.0 {
        (u, v) = (1.0 - u, 1.0 - v);
    }
    let (a, b, c) = (p.vertices[0], p.vertices[i], p.vertices[i + 1]);
    a + (b - a) * u + (c - a) * v
}

/// A hemisphere bundle from a random point of polygon `k` (an even number of bands, either
/// strata).
pub fn bundle_on(scene: &Scene3, k: usize, rng: &mut ChaCha8Rng, n_theta: usize, n_phi: usize) -> Bundle3 {
    let p = &scene.polygons[k];
    let strata = if rng.random::<bool>() { Strata::Angle } else { Strata::Cosine };
    let rays = HemisphereRays::new(point_on(p, rng), p.normal, n_theta, n_phi, strata).unwrap();
    Bundle3::from_hemisphere(&rays, Some(k))
}

/// Random scenes, random sources, random set sizes (up to `2·half_bands` bands of `cells`
/// cells): `cases` of (seed, count, size).
pub fn random_scenes(cases: &[(u64, usize, f64)], sources: usize, half_bands: usize, cells: usize) {
    for &(seed, count, size) in cases {
        let scene = generate(count, size, seed).unwrap();
        let grid = Grid3::build(&scene, Grid3Params::default()).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        for s in 0..sources {
            let k = rng.random_range(0..scene.polygons.len());
            let n_theta = 2 * rng.random_range(1..=half_bands);
            let n_phi = rng.random_range(1..=cells);
            let bundle = bundle_on(&scene, k, &mut rng, n_theta, n_phi);
            let what =
                format!("seed {seed}: {count} squares of {size}, source {s} on patch {k}, {n_theta}×{n_phi}");
            agree_all(&what, &scene, &grid, &bundle);
        }
    }
}
