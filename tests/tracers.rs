//! Rung 1 of the equivalence ladder: every tracer returns the brute-force nearest hit for every
//! ray, on seeded random scenes of every length and both ray sets, on property-generated scenes
//! and on adversarial ones; plus the counter invariants.

use proptest::prelude::*;
use shelling::geom::{Segment, Vec2};
use shelling::grid::GridParams;
use shelling::rays::{Bundle, RaySet, Source};
use shelling::run::GriddedScene;
use shelling::scene::{self, Bounds, Scene};
use shelling::trace::{trace_with, FloatHits, HitTest, Method, ShellParams, TraceResult};

fn v(x: f64, y: f64) -> Vec2 {
    Vec2::new(x, y)
}

fn seg(ax: f64, ay: f64, bx: f64, by: f64) -> Segment {
    Segment::new(v(ax, ay), v(bx, by))
}

/// The golden model's hit test in a backend that observes the work-stream hooks.
struct Hooked;

impl HitTest for Hooked {
    const HOOKS: bool = true;

    fn hit(&self, bundle: &Bundle, i: usize, p: u32, seg: &Segment) -> Option<f64> {
        FloatHits.hit(bundle, i, p, seg)
    }
}

/// Traces `bundle` with every method and checks each against brute force and the counter
/// invariants. `what` names the case (seed, source) so a failure can be replayed.
fn check(p: &GriddedScene, bundle: &Bundle, params: &ShellParams, what: &str) -> Vec<TraceResult> {
    let oracle = p.trace(Method::Brute, bundle, params).unwrap();
    let mut results = vec![];
    for method in Method::ALL {
        let r = p.trace(method, bundle, params).unwrap();
        for (i, (got, want)) in r.hits.iter().zip(&oracle.hits).enumerate() {
            assert_eq!(
                got, want,
                "{what}: {method} disagrees with brute force on ray {i} (direction {:?})",
                bundle.rays[i].dir
            );
        }
        // A backend that observes the work-stream hooks takes the tracers' patch-by-patch path
        // (the conventional tracer's per-source cell screening is only for backends that do
        // not): the same hits and the same counters.
        let hooked = trace_with(method, p.view(), bundle, params, &Hooked).unwrap();
        assert_eq!(hooked.hits, r.hits, "{what}: {method} with hooks observed");
        assert_eq!(hooked.counters, r.counters, "{what}: {method} with hooks observed");
        let c = &r.counters;
        assert!(c.patches_read_after_screening <= c.patches_read_before_screening, "{what}: {method}: {c:?}");
        assert!(c.intersection_computations >= c.actual_intersections, "{what}: {method}: {c:?}");
        assert!(c.intersection_computations <= bundle.len() as u64 * p.scene.len() as u64);
        assert_eq!(c.actual_intersections, oracle.counters.actual_intersections);
        assert_eq!(c.adlc_true, oracle.counters.adlc_true);
        let (lo, hi) = p.grid.extent();
        let o = bundle.source.origin;
        let inside = o.x >= lo.x && o.y >= lo.y && o.x < hi.x && o.y < hi.y;
        if method != Method::Brute && inside {
            assert!(c.cells_traversed > 0, "{what}: {method} traversed no cells");
        }
        if matches!(method, Method::Brute | Method::Conventional) {
            assert_eq!(c.patches_read_after_screening, c.intersection_computations);
            assert_eq!(c.adlc_estimated, c.adlc_true);
        } else {
            let s = r.stats.leaving_fraction();
            assert!((0.0..=1.0).contains(&s), "{what}: {method}: S = {s}");
        }
        results.push(r);
    }
    results
}

#[test]
fn every_tracer_matches_brute_force_on_the_papers_workload_shapes() {
    let params = ShellParams::default();
    for (li, &length) in [4.0, 8.0, 16.0, 32.0, 64.0, 128.0].iter().enumerate() {
        for set in [RaySet::Angle, RaySet::Sine] {
            let seed = 100 + li as u64;
            let scene = scene::generate(300, length, seed, scene::PAPER_WORLD).unwrap();
            let p = GriddedScene::new(scene, GridParams::default());
            for k in [0usize, 77, 151, 299] {
                let bundle = p.patch_bundle(k, set, 256).unwrap();
                check(&p, &bundle, &params, &format!("length {length} seed {seed} source {k} {set}"));
            }
        }
    }
}

#[test]
fn every_tracer_matches_brute_force_on_a_full_size_scene() {
    let scene = scene::generate(1000, 32.0, 7, scene::PAPER_WORLD).unwrap();
    let p = GriddedScene::new(scene, GridParams::default());
    for k in [3usize, 500] {
        let bundle = p.patch_bundle(k, RaySet::Angle, 1024).unwrap();
        check(&p, &bundle, &ShellParams::default(), &format!("1000 × 32, seed 7, source {k}"));
    }
}

#[test]
fn shell_parameters_do_not_change_hits() {
    let scene = scene::generate(400, 16.0, 3, scene::PAPER_WORLD).unwrap();
    let p = GriddedScene::new(scene, GridParams::default());
    let bundle = p.patch_bundle(10, RaySet::Sine, 300).unwrap();
    for params in [
        ShellParams { shell_depth: Some(1.0), ..Default::default() },
        ShellParams { shell_depth: Some(2000.0), ..Default::default() },
        ShellParams { min_sector: 1, max_sector: 1, first_sector: 1, ..Default::default() },
        ShellParams { max_sector: 1024, first_sector: 1024, ..Default::default() },
        ShellParams { default_adlc: 1.0, min_subshell_fraction: 1.0, ..Default::default() },
    ] {
        params.validate().unwrap();
        check(&p, &bundle, &params, &format!("{params:?}"));
    }
}

#[test]
fn grid_resolution_does_not_change_hits() {
    let scene = scene::generate(200, 64.0, 11, scene::PAPER_WORLD).unwrap();
    for cells in [0.01, 1.0, 40.0] {
        let p =
            GriddedScene::new(scene.clone(), GridParams { cells_per_segment: cells, cells_per_axis: None });
        let bundle = p.patch_bundle(5, RaySet::Angle, 200).unwrap();
        check(&p, &bundle, &ShellParams::default(), &format!("λ = {cells}"));
    }
}

fn prepared(segments: Vec<Segment>) -> GriddedScene {
    GriddedScene::new(Scene::new(segments).unwrap(), GridParams::default())
}

/// A closed square room, walls facing inwards, with a source on the floor: every ray hits a wall.
#[test]
fn closed_room_every_ray_hits() {
    let segments = vec![
        seg(0.0, 0.0, 100.0, 0.0),
        seg(100.0, 0.0, 100.0, 100.0),
        seg(100.0, 100.0, 0.0, 100.0),
        seg(0.0, 100.0, 0.0, 0.0),
        // A pillar inside, its faces facing out (clockwise).
        seg(40.0, 40.0, 40.0, 60.0),
        seg(40.0, 60.0, 60.0, 60.0),
        seg(60.0, 60.0, 60.0, 40.0),
        seg(60.0, 40.0, 40.0, 40.0),
    ];
    let p = prepared(segments);
    for k in 0..8 {
        for set in [RaySet::Angle, RaySet::Sine] {
            let bundle = p.patch_bundle(k, set, 301).unwrap();
            let r = check(&p, &bundle, &ShellParams::default(), &format!("room, source {k}"));
            if k < 4 {
                // From a wall, every ray hits some wall or a pillar.
                assert!(r[0].hits.iter().all(|h| h.is_some()), "room source {k}: a ray escaped");
            } else {
                // The pillar's outside faces the room: its rays hit the walls.
                assert!(r[0].hits.iter().all(|h| h.is_some_and(|h| h.segment < 4)));
            }
        }
    }
}

/// Rays through shared endpoints: an exact tie goes to the lower index; both segments agree.
#[test]
fn ties_at_shared_endpoints_go_to_the_lower_index() {
    // Odd R: the middle ray (φ = 0) is exactly the normal (0, 1), through x = 500.
    let segments = vec![
        seg(400.0, 10.0, 600.0, 10.0), // the source at (500, 10), normal pointing up (+y)
        seg(512.0, 600.0, 500.0, 600.0),
        seg(500.0, 600.0, 488.0, 600.0),
        seg(518.0, 700.0, 500.0, 700.0),
        seg(500.0, 700.0, 500.0, 720.0), // collinear with the middle ray: parallel, no hit
        seg(500.0, 650.0, 500.0, 640.0),
    ];
    let p = prepared(segments.clone());
    let bundle = p.patch_bundle(0, RaySet::Angle, 101).unwrap();
    assert_eq!(bundle.rays[50].dir, v(0.0, 1.0));
    let r = check(&p, &bundle, &ShellParams::default(), "shared endpoints");
    let mid = r[0].hits[50].unwrap();
    assert_eq!((mid.segment, mid.t), (1, 590.0));
    // Reversing the order of the two touching segments flips the winner to the new lower index.
    let mut swapped = segments;
    swapped.swap(1, 2);
    let p = prepared(swapped);
    let r = check(&p, &bundle, &ShellParams::default(), "shared endpoints, swapped");
    assert_eq!(r[0].hits[50].unwrap().segment, 1);
}

#[test]
fn collinear_touching_and_overlapping_segments() {
    let segments = vec![
        seg(100.0, 0.0, 0.0, 0.0), // normal -y
        seg(0.0, 0.0, 100.0, 0.0), // the same line, other orientation: the source, normal +y
        // Collinear overlapping pieces on y = 50, facing down (towards the source).
        seg(80.0, 50.0, 20.0, 50.0),
        seg(60.0, 50.0, 40.0, 50.0),
        seg(100.0, 50.0, 60.0, 50.0),
        // T junction touching the y = 50 line from above, and a V touching it from below.
        seg(50.0, 50.0, 50.0, 90.0),
        seg(70.0, 30.0, 75.0, 50.0),
        seg(75.0, 50.0, 80.0, 30.0),
        // A segment lying along the source's own line, beyond it.
        seg(150.0, 0.0, 120.0, 0.0),
    ];
    let p = prepared(segments);
    for set in [RaySet::Angle, RaySet::Sine] {
        for r in [1usize, 2, 3, 64, 257] {
            let bundle = p.patch_bundle(1, set, r).unwrap();
            check(&p, &bundle, &ShellParams::default(), &format!("collinear, R = {r}"));
        }
    }
}

#[test]
fn segments_through_behind_and_backwards_are_not_hit() {
    let o = v(500.0, 500.0);
    let segments = vec![
        seg(490.0, 480.0, 510.0, 520.0), // through the origin
        seg(400.0, 450.0, 600.0, 450.0), // wholly behind the source plane (y < 500)
        seg(600.0, 490.0, 400.0, 490.0), // behind, facing the source's back
        seg(450.0, 600.0, 550.0, 600.0), // in front but seen from the back (normal +y)
        seg(320.0, 700.0, 300.0, 400.0), // crossing the source's plane, front-facing
        seg(700.0, 700.0, 680.0, 400.0), // crossing the plane, back-facing
    ];
    let p = prepared(segments);
    let source = Source::at(o, v(0.0, 1.0)).unwrap();
    let bundle = Bundle::new(source, RaySet::Angle, 512).unwrap();
    let r = check(&p, &bundle, &ShellParams::default(), "through/behind");
    for h in r[0].hits.iter().flatten() {
        assert_eq!(h.segment, 4, "only the front-facing segment crossing the plane can be hit");
    }
    assert!(r[0].hits.iter().any(|h| h.is_some()));
}

#[test]
fn empty_hemisphere_hits_nothing() {
    let segments =
        vec![seg(0.0, 0.0, 10.0, 0.0), seg(0.0, -50.0, 100.0, -60.0), seg(30.0, -5.0, 20.0, -70.0)];
    let p = prepared(segments);
    let bundle = p.patch_bundle(0, RaySet::Angle, 128).unwrap();
    let r = check(&p, &bundle, &ShellParams::default(), "empty hemisphere");
    assert!(r.iter().all(|t| t.hits.iter().all(|h| h.is_none())));
}

/// Segments on cell boundaries and rays along them: the places where grid walks go wrong.
#[test]
fn segments_and_rays_along_cell_boundaries() {
    let world = Bounds { min: v(0.0, 0.0), max: v(64.0, 64.0) };
    let mut segments = vec![seg(24.0, 0.0, 40.0, 0.0)]; // source at (32, 0), normal +y
    for i in 1..8 {
        let x = 8.0 * i as f64;
        // Short vertical pieces on grid lines, alternating orientation, and horizontal ones.
        segments.push(seg(x, 8.0 * i as f64, x, 8.0 * i as f64 + 8.0));
        segments.push(seg(x + 8.0, 40.0, x, 40.0));
    }
    let mut scene = Scene::new(segments).unwrap();
    scene.world = Some(world);
    for cells in [1.0, 4.0, 16.0] {
        let p =
            GriddedScene::new(scene.clone(), GridParams { cells_per_segment: cells, cells_per_axis: None });
        for r in [7usize, 8, 65, 128] {
            let bundle = p.patch_bundle(0, RaySet::Angle, r).unwrap();
            check(&p, &bundle, &ShellParams::default(), &format!("grid lines, λ = {cells}, R = {r}"));
        }
        // A free origin exactly on a grid corner, axis-aligned normal.
        let source = Source::at(v(32.0, 16.0), v(1.0, 0.0)).unwrap();
        let bundle = Bundle::new(source, RaySet::Angle, 33).unwrap();
        check(&p, &bundle, &ShellParams::default(), "origin on a grid corner");
    }
}

/// An origin outside the scene's grid: rays must enter the grid first.
#[test]
fn origin_outside_the_grid() {
    let scene = scene::generate(200, 32.0, 5, scene::PAPER_WORLD).unwrap();
    let p = GriddedScene::new(scene, GridParams::default());
    for (o, n) in
        [(v(-100.0, 500.0), v(1.0, 0.0)), (v(2000.0, 2000.0), v(-1.0, -1.0)), (v(500.0, -50.0), v(0.0, -1.0))]
    {
        let bundle = Bundle::new(Source::at(o, n).unwrap(), RaySet::Sine, 200).unwrap();
        check(&p, &bundle, &ShellParams::default(), &format!("origin {o:?}"));
    }
}

fn arb_point(grid: bool) -> impl Strategy<Value = Vec2> {
    if grid {
        // Small integer coordinates: many exact collinearities, shared endpoints, grid lines.
        (0i32..12, 0i32..12).prop_map(|(x, y)| v(x as f64 * 8.0, y as f64 * 8.0)).boxed()
    } else {
        (0.0f64..96.0, 0.0f64..96.0).prop_map(|(x, y)| v(x, y)).boxed()
    }
}

fn arb_scene() -> impl Strategy<Value = Vec<Segment>> {
    any::<bool>().prop_flat_map(|grid| {
        prop::collection::vec((arb_point(grid), arb_point(grid)), 2..40).prop_map(|pairs| {
            pairs.into_iter().filter(|(a, b)| a != b).map(|(a, b)| Segment::new(a, b)).collect::<Vec<_>>()
        })
    })
}

/// `PROPTEST_CASES` if set, else `default` (a literal `cases` would override the variable).
fn proptest_cases(default: u32) -> u32 {
    std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: proptest_cases(96), ..ProptestConfig::default() })]

    /// Any scene, any source patch or free origin, any ray count: all tracers agree with brute
    /// force. proptest prints the minimal failing scene and its seed (saved under
    /// `proptest-regressions/`, replayed first on the next run); `PROPTEST_CASES` changes the
    /// count (96 by default).
    #[test]
    fn tracers_agree_on_arbitrary_scenes(
        segments in arb_scene(),
        k in 0usize..40,
        rays in 1usize..200,
        sine in any::<bool>(),
        free in prop::option::of((arb_point(false), -1.0f64..1.0, -1.0f64..1.0)),
        cells in prop::sample::select(vec![0.5, 4.0, 30.0]),
        depth in prop::option::of(1.0f64..50.0),
    ) {
        prop_assume!(segments.len() >= 2);
        let p = GriddedScene::new(Scene::new(segments).unwrap(), GridParams { cells_per_segment: cells, cells_per_axis: None });
        let source = match free {
            Some((o, nx, ny)) if nx != 0.0 || ny != 0.0 => Source::at(o, v(nx, ny)).unwrap(),
            _ => Source::from_patch(&p.scene.segments, k % p.scene.len()).unwrap(),
        };
        let set = if sine { RaySet::Sine } else { RaySet::Angle };
        let bundle = Bundle::new(source, set, rays).unwrap();
        let params = ShellParams { shell_depth: depth, ..Default::default() };
        check(&p, &bundle, &params, &format!("{source:?}"));
    }
}

#[test]
fn invalid_shell_parameters_are_errors_not_hangs() {
    let p = prepared(vec![seg(0.0, 0.0, 10.0, 0.0), seg(10.0, 10.0, 0.0, 10.0)]);
    let bundle = p.patch_bundle(0, RaySet::Angle, 8).unwrap();
    for bad in [
        ShellParams { shell_depth: Some(0.0), ..Default::default() },
        ShellParams { shell_depth: Some(-1.0), ..Default::default() },
        ShellParams { shell_depth: Some(f64::NAN), ..Default::default() },
        ShellParams { min_sector: 10, max_sector: 5, ..Default::default() },
        ShellParams { first_sector: 0, ..Default::default() },
        ShellParams { default_adlc: 0.5, ..Default::default() },
        ShellParams { min_subshell_fraction: 0.0, ..Default::default() },
        ShellParams { phi_cells: 0, ..Default::default() },
    ] {
        for method in Method::ALL {
            let err = p.trace(method, &bundle, &bad).unwrap_err();
            assert!(err.to_string().starts_with("invalid shell parameters"), "{err}");
        }
    }
}
