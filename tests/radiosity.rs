//! Radiosity in flatland (RADIOSITY.md): form factors against closed forms (point to segment,
//! Hottel's crossed strings, unoccluded and around an occluder), their error in R and M, rows of
//! a closed room, reciprocity, the solvers (furnace, energy balance, progressive against full),
//! matrix slices and their merge, rows on the PE, and the commands.

use crate::cli::{fails, ok, parse_json, path_arg, TempDir};
use shelling::arith::Arith;
use shelling::cosim::{CosimConfig, Engine};
use shelling::geom::{Segment, Vec2};
use shelling::grid::GridParams;
use shelling::radiosity::form_factors::{self, FfParams, DEFAULT_RAYS};
use shelling::radiosity::matrix::{self, MatrixFile};
use shelling::radiosity::on_pe::{self, PeTotals};
use shelling::radiosity::solve::{self, Surfaces};
use shelling::rays::RaySet;
use shelling::run::GriddedScene;
use shelling::scene::{room, Material, RoomSpec, Scene};
use shelling::trace::Method;

fn v(x: f64, y: f64) -> Vec2 {
    Vec2::new(x, y)
}

fn prepared(segments: Vec<Segment>) -> GriddedScene {
    GriddedScene::new(Scene::new(segments).expect("a valid scene"), GridParams::default())
}

fn params(rays: usize, origins: usize) -> FfParams {
    FfParams { rays, origins, ..FfParams::default() }
}

fn ff(p: &GriddedScene, i: usize, j: usize, fp: &FfParams) -> f64 {
    form_factors::row(p, i, fp).expect("the row traces").get(j)
}

/// `F(x → j)` for the source at the origin facing +y and the segment `(x1, h)..(x2, h)`:
/// ½ |sin φ₂ − sin φ₁|.
fn point_to_segment(x1: f64, x2: f64, h: f64) -> f64 {
    let s = |x: f64| x / (x * x + h * h).sqrt();
    0.5 * (s(x2) - s(x1)).abs()
}

/// Hottel's crossed strings for `i = a_i → b_i`, `j = a_j → b_j` with `a_i, b_i, a_j, b_j` in
/// counter-clockwise order (the two facing each other): `(crossed − uncrossed) / 2 L_i`, each
/// string the shortest path between its ends by `len`.
fn crossed_strings(i: Segment, j: Segment, len: impl Fn(Vec2, Vec2) -> f64) -> f64 {
    let crossed = len(i.a, j.a) + len(i.b, j.b);
    let uncrossed = len(i.b, j.a) + len(i.a, j.b);
    (crossed - uncrossed) / (2.0 * i.length())
}

fn straight(p: Vec2, q: Vec2) -> f64 {
    (p - q).length()
}

/// The source of the closed-form cases: `(−1, 0) → (1, 0)`, facing +y.
fn source() -> Segment {
    Segment::new(v(-1.0, 0.0), v(1.0, 0.0))
}

#[test]
fn point_to_segment_is_exact_up_to_one_ray_weight_per_endpoint() {
    // The paper's single central origin (M = 1): the target (x1..x2 at height h) faces down.
    for (x1, x2, h) in [(-1.0, 1.0, 2.0), (0.3, 2.5, 1.0), (-3.0, -0.5, 0.7)] {
        let p = prepared(vec![source(), Segment::new(v(x2, h), v(x1, h))]);
        let exact = point_to_segment(x1, x2, h);
        for rays in [64, 256, 1024, DEFAULT_RAYS] {
            let sine = ff(&p, 0, 1, &params(rays, 1));
            assert!((sine - exact).abs() <= 2.0 / rays as f64, "sine R={rays}: {sine} vs {exact}");
            let angle = ff(&p, 0, 1, &FfParams { ray_set: RaySet::Angle, ..params(rays, 1) });
            let w = std::f64::consts::PI / (2.0 * rays as f64);
            assert!((angle - exact).abs() <= 2.0 * w, "angle R={rays}: {angle} vs {exact}");
        }
        let at_default = ff(&p, 0, 1, &params(DEFAULT_RAYS, 1));
        assert!((at_default - exact).abs() <= 1e-3, "{at_default} vs {exact}");
    }
}

/// The unoccluded pairs of the crossed-strings tests: (name, i, j), i = 0 the source.
fn unoccluded_pairs() -> Vec<(&'static str, Segment, Segment)> {
    vec![
        ("parallel", source(), Segment::new(v(1.0, 2.0), v(-1.0, 2.0))),
        ("parallel, offset", source(), Segment::new(v(2.5, 1.0), v(0.5, 1.0))),
        (
            "perpendicular, sharing a corner",
            Segment::new(v(0.0, 0.0), v(1.0, 0.0)),
            Segment::new(v(0.0, 1.0), v(0.0, 0.0)),
        ),
        ("perpendicular, apart", source(), Segment::new(v(-1.5, 3.0), v(-1.5, 0.5))),
        ("at an angle, unequal lengths", source(), Segment::new(v(2.0, 1.0), v(-0.5, 3.0))),
    ]
}

#[test]
fn crossed_strings_at_the_defaults_within_1e_3() {
    for (name, i, j) in unoccluded_pairs() {
        let exact = crossed_strings(i, j, straight);
        let p = prepared(vec![i, j]);
        let fp = FfParams::default();
        let got = ff(&p, 0, 1, &fp);
        assert!((got - exact).abs() <= 1e-3, "{name}: F = {got}, crossed strings {exact}");
        // Reciprocity of the exact values, and of the estimates within the same error.
        let back = ff(&p, 1, 0, &fp);
        let exact_back = crossed_strings(j, i, straight);
        assert!((i.length() * exact - j.length() * exact_back).abs() < 1e-12, "{name}");
        assert!((back - exact_back).abs() <= 1e-3, "{name}: F_ji = {back}, {exact_back}");
        assert!((i.length() * got - j.length() * back).abs() <= 1e-3 * (i.length() + j.length()), "{name}");
    }
}

#[test]
fn the_origin_sampling_error_falls_with_m() {
    // Enough rays that the ray error (≤ 2/R) stays well below the midpoint rule's.
    let (name, i, j) = &unoccluded_pairs()[0];
    let exact = crossed_strings(*i, *j, straight);
    let p = prepared(vec![*i, *j]);
    let err = |m| (ff(&p, 0, 1, &params(1 << 18, m)) - exact).abs();
    let (e1, e4, e16) = (err(1), err(4), err(16));
    assert!(e1 > 1e-2, "{name}: M = 1 errs by {e1}");
    assert!(e4 < e1 / 8.0 && e16 < e4 / 4.0, "{name}: errors {e1}, {e4}, {e16} do not fall as 1/M²");
}

/// Whether the segment `p..q` passes through the open interior of the box `lo..hi`.
fn through_box(p: Vec2, q: Vec2, lo: Vec2, hi: Vec2) -> bool {
    // Liang–Barsky clip against the closed box, then the clipped part's midpoint strictly inside.
    let d = q - p;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (pd, p0, l, h) in [(d.x, p.x, lo.x, hi.x), (d.y, p.y, lo.y, hi.y)] {
        if pd == 0.0 {
            if p0 < l || p0 > h {
                return false;
            }
        } else {
            let (a, b) = ((l - p0) / pd, (h - p0) / pd);
            t0 = t0.max(a.min(b));
            t1 = t1.min(a.max(b));
        }
    }
    if t1 - t0 <= 1e-12 {
        return false;
    }
    let m = p + d * (0.5 * (t0 + t1));
    lo.x < m.x && m.x < hi.x && lo.y < m.y && m.y < hi.y
}

/// The length of the path through `points`, each leg checked clear of the box `lo..hi`.
fn string(points: &[Vec2], lo: Vec2, hi: Vec2) -> f64 {
    points
        .windows(2)
        .map(|w| {
            assert!(!through_box(w[0], w[1], lo, hi), "the string {:?} → {:?} cuts the box", w[0], w[1]);
            straight(w[0], w[1])
        })
        .sum()
}

#[test]
fn an_occluded_pair_matches_crossed_strings_around_the_occluder() {
    // Two parallel plates with a flat box between them (faces out, so it blocks from every side).
    let (i, j) = (source(), Segment::new(v(1.0, 2.0), v(-1.0, 2.0)));
    let (lo, hi) = (v(-0.3, 0.9), v(0.3, 1.1));
    // The light passes left or right of the box: two windows, mirror images of each other. In
    // the left one the strings are stretched around the box's left side (corners bl, tl):
    // crossed i.a → tl → j.a and i.b → bl → j.b, uncrossed i.a → j.b and i.b → bl → tl → j.a.
    // (With the box shrunk to a point the two windows give the unoccluded crossed strings.)
    let (bl, tl) = (v(lo.x, lo.y), v(lo.x, hi.y));
    let crossed = string(&[i.a, tl, j.a], lo, hi) + string(&[i.b, bl, j.b], lo, hi);
    let uncrossed = string(&[i.a, j.b], lo, hi) + string(&[i.b, bl, tl, j.a], lo, hi);
    let exact = 2.0 * (crossed - uncrossed) / (2.0 * i.length());
    let unoccluded = crossed_strings(i, j, straight);
    assert!(exact < unoccluded - 0.05, "the box must shade: {exact} vs {unoccluded}");
    let box_sides = [
        Segment::new(v(lo.x, lo.y), v(lo.x, hi.y)),
        Segment::new(v(lo.x, hi.y), v(hi.x, hi.y)),
        Segment::new(v(hi.x, hi.y), v(hi.x, lo.y)),
        Segment::new(v(hi.x, lo.y), v(lo.x, lo.y)),
    ];
    let mut segments = vec![i, j];
    segments.extend(box_sides);
    let p = prepared(segments);
    let got = ff(&p, 0, 1, &FfParams::default());
    assert!((got - exact).abs() <= 1e-3, "F = {got}, crossed strings around the box {exact}");
}

/// The room of [`small_room`]: 64 × 64, 16 patches, no boxes, two lights.
fn small_room_scene() -> GriddedScene {
    let spec = RoomSpec { width: 64.0, height: 64.0, patch_length: 16.0, boxes: 0, ..RoomSpec::default() };
    GriddedScene::new(room(&spec).unwrap(), GridParams::default())
}

fn default_room() -> GriddedScene {
    GriddedScene::new(room(&RoomSpec::default()).expect("the default room"), GridParams::default())
}

#[test]
fn every_technique_gives_the_same_rows_and_a_closed_room_sums_to_1() {
    let p = default_room();
    let fp = params(256, 4);
    for k in [0, 40, 100, p.scene.len() - 1] {
        let want = form_factors::row(&p, k, &FfParams { method: Method::Brute, ..fp.clone() }).unwrap();
        assert!((want.sum() - 1.0).abs() < 1e-12, "row {k} sums to {}", want.sum());
        assert!(want.get(k) == 0.0, "row {k} sees itself");
        for method in Method::ALL {
            let got = form_factors::row(&p, k, &FfParams { method, ..fp.clone() }).unwrap();
            assert_eq!(got, want, "row {k}: {method} differs from brute force");
        }
        // The fixed point's hits differ from f64's at endpoints within the documented bound
        // (rung 2): a ray may slip through a corner, so a row may lose a few ray weights.
        let fixed = form_factors::row(&p, k, &FfParams { arith: Arith::Fixed, ..fp.clone() }).unwrap();
        let weight = 1.0 / (fp.rays * fp.origins) as f64;
        assert!((fixed.sum() - 1.0).abs() <= 4.0 * weight, "fixed row {k} sums to {}", fixed.sum());
        let diff: f64 = (0..p.scene.len()).map(|j| (fixed.get(j) - want.get(j)).abs()).sum();
        assert!(diff <= 4.0 / 256.0, "fixed row {k} differs from f64 by {diff} in all");
    }
}

#[test]
fn room_rows_are_reciprocal_within_the_documented_error() {
    let p = default_room();
    let fp = FfParams::default();
    let rows: Vec<_> =
        [0usize, 20, 70, 140].iter().map(|&k| form_factors::row(&p, k, &fp).unwrap()).collect();
    for a in &rows {
        for b in &rows {
            let (li, lj) = (p.scene.segments[a.source].length(), p.scene.segments[b.source].length());
            let (fij, fji) = (a.get(b.source), b.get(a.source));
            assert!(
                (li * fij - lj * fji).abs() <= 1e-3 * (li + lj),
                "L_i F_ij = {} against L_j F_ji = {} for {} and {}",
                li * fij,
                lj * fji,
                a.source,
                b.source
            );
        }
    }
}

/// A room of `spec` with every patch emitting `e` and reflecting `rho`.
fn furnace(e: f64, rho: f64) -> GriddedScene {
    let spec = RoomSpec {
        width: 128.0,
        height: 96.0,
        patch_length: 16.0,
        boxes: 1,
        box_size: 32.0,
        ..RoomSpec::default()
    };
    let mut scene = room(&spec).unwrap();
    scene.materials = vec![Material { reflectance: Some(rho), emission: Some(e) }; scene.len()];
    GriddedScene::new(scene, GridParams::default())
}

#[test]
fn the_furnace_gives_e_over_1_minus_rho() {
    let (e, rho) = (2.0, 0.6);
    let p = furnace(e, rho);
    let s = Surfaces::of(&p.scene, "furnace").unwrap();
    let fp = FfParams::default();
    let rows = form_factors::rows(&p, 0..p.scene.len(), &fp, || {}).unwrap();
    let full = solve::full(&s, &rows, 1e-9, 1000).unwrap();
    let progressive =
        solve::progressive(&s, 1e-9, 100_000, |k| Ok::<_, solve::SolveError>(rows[k].clone())).unwrap();
    let want = e / (1.0 - rho);
    for (name, sol) in [("full", &full), ("progressive", &progressive)] {
        for (j, b) in sol.radiosity.iter().enumerate() {
            assert!((b / want - 1.0).abs() <= 1e-3, "{name}: patch {j} has B = {b}, want {want}");
        }
    }
}

#[test]
fn energy_balances_and_the_solvers_agree() {
    let p = default_room();
    let s = Surfaces::of(&p.scene, "room").unwrap();
    let fp = params(1024, 8);
    let rows = form_factors::rows(&p, 0..p.scene.len(), &fp, || {}).unwrap();
    let tol = 1e-6;
    let prog =
        solve::progressive(&s, tol, 1_000_000, |k| Ok::<_, solve::SolveError>(rows[k].clone())).unwrap();
    // Progressive refinement conserves power exactly: emitted = absorbed + unshot.
    let balance = prog.emitted - prog.absorbed - prog.unshot * prog.emitted;
    assert!(
        balance.abs() <= 1e-9 * prog.emitted,
        "emitted {}, absorbed {}, unshot {}",
        prog.emitted,
        prog.absorbed,
        prog.unshot
    );
    assert!(prog.unshot <= tol && prog.history.windows(2).all(|w| w[1] <= w[0] * (1.0 + 1e-12) + 1e-300));
    let full = solve::full(&s, &rows, 1e-9, 10_000).unwrap();
    assert!(
        (full.absorbed / full.emitted - 1.0).abs() <= 1e-3,
        "full: emitted {}, absorbed {}",
        full.emitted,
        full.absorbed
    );
    // They differ by the form factors' reciprocity error (progressive shoots by reciprocity,
    // full gathers from each patch's own row): measured in power, Σ L |ΔB| / Σ L B.
    let lengths: Vec<f64> = p.scene.segments.iter().map(|s| s.length()).collect();
    let diff: f64 = (0..s.len()).map(|j| lengths[j] * (prog.radiosity[j] - full.radiosity[j]).abs()).sum();
    let total: f64 = (0..s.len()).map(|j| lengths[j] * full.radiosity[j]).sum();
    eprintln!("progressive against full: {:.3e} of the power", diff / total);
    assert!(diff / total <= 1e-2, "progressive and full solves differ by {} of the power", diff / total);
    // The progressive solve computing its own rows gives the same as from the precomputed ones.
    let own = solve::progressive(&s, tol, 1_000_000, |k| form_factors::row(&p, k, &fp)).unwrap();
    assert_eq!(own.radiosity, prog.radiosity);
}

#[test]
fn solver_errors_name_the_problem() {
    let mut scene = room(&RoomSpec::default()).unwrap();
    scene.materials.iter_mut().for_each(|m| m.emission = None);
    let e = Surfaces::of(&scene, "dark.json").unwrap_err().to_string();
    assert!(e.contains("dark.json") && e.contains("emits"), "{e}");
    let s = Surfaces::of(&room(&RoomSpec::default()).unwrap(), "room").unwrap();
    for t in [0.0, 1.0, -1.0, f64::NAN] {
        let e = solve::full(&s, &[], t, 10).unwrap_err().to_string();
        assert!(e.contains("--tolerance"), "{e}");
    }
    let e = solve::full(&s, &[], 1e-3, 10).unwrap_err().to_string();
    assert!(e.contains("rows for 0 patches"), "{e}");
    let p = default_room();
    let e = solve::progressive(&s, 1e-9, 3, |k| form_factors::row(&p, k, &params(64, 1))).unwrap_err();
    assert!(e.to_string().contains("3 steps"), "{e}");
}

#[test]
fn slices_merge_into_the_whole_matrix() {
    let p = small_room_scene();
    let fp = params(128, 2);
    let n = p.scene.len();
    let slice = |r: std::ops::Range<usize>| {
        let start = r.start;
        MatrixFile::new(&p.scene, &fp, start, form_factors::rows(&p, r, &fp, || {}).unwrap())
    };
    let whole = slice(0..n);
    let (a, b) = (slice(0..5), slice(5..n));
    let merged = matrix::merge(vec![("b".into(), b.clone()), ("a".into(), a.clone())]).unwrap();
    assert_eq!(merged, whole);
    assert!(merged.is_whole());
    let text = merged.to_json();
    let back: MatrixFile = serde_json::from_str(&text).unwrap();
    back.check("m.json").unwrap();
    assert_eq!(back, whole);
    // A gap, an overlap and a slice of another scene are errors.
    assert!(matrix::merge(vec![("a".into(), a.clone())])
        .unwrap_err()
        .to_string()
        .contains("leave rows 5..16 out"));
    let e =
        matrix::merge(vec![("a".into(), a.clone()), ("w".into(), whole.clone())]).unwrap_err().to_string();
    assert!(e.contains("overlap"), "{e}");
    let mut moved = a.clone();
    moved.scene.hash = "0".repeat(16);
    let e = matrix::merge(vec![("a".into(), moved), ("b".into(), b)]).unwrap_err().to_string();
    assert!(e.contains("different scenes"), "{e}");
}

#[test]
fn rows_on_the_pe_are_the_bit_true_rows() {
    let p = small_room_scene();
    let config = CosimConfig { tc: 2, cache: None, vcd: None, engine: Engine::RustHdl };
    for method in [Method::Conventional, Method::Stochastic, Method::Deterministic] {
        let fp = FfParams { method, arith: Arith::Fixed, ..params(64, 2) };
        let mut totals = PeTotals::default();
        for k in [0, 9] {
            let on_pe = on_pe::row(&p, k, &fp, &config, &mut totals).unwrap();
            assert_eq!(on_pe, form_factors::row(&p, k, &fp).unwrap(), "{method} row {k}");
        }
        assert_eq!((totals.rows, totals.bundles, totals.rays), (2, 4, 256));
        assert!(totals.cycles > totals.tests && totals.tests > 0, "{method}: {totals:?}");
    }
    let brute = FfParams { method: Method::Brute, ..params(64, 1) };
    let e = on_pe::row(&p, 0, &brute, &config, &mut PeTotals::default()).unwrap_err().to_string();
    assert!(e.contains("--method brute"), "{e}");
}

#[test]
fn room_generator_checks_its_options() {
    let s = room(&RoomSpec::default()).unwrap();
    assert_eq!(s.len(), 4 * 32 + 2 * 4 * 6);
    let lights = (0..s.len()).filter(|&i| s.material(i).emission_or_default() > 0.0).count();
    assert_eq!(lights, 2);
    assert_eq!(s, room(&RoomSpec::default()).unwrap(), "seeded");
    for (spec, option) in [
        (RoomSpec { width: -1.0, ..RoomSpec::default() }, "--width"),
        (RoomSpec { patch_length: 0.0, ..RoomSpec::default() }, "--patch-length"),
        (RoomSpec { reflectance: 1.0, ..RoomSpec::default() }, "--reflectance"),
        (RoomSpec { emission: f64::NAN, ..RoomSpec::default() }, "--emission"),
        (RoomSpec { lights: 0, ..RoomSpec::default() }, "--lights"),
        (RoomSpec { box_size: 200.0, ..RoomSpec::default() }, "--box-size"),
        (RoomSpec { boxes: 40, ..RoomSpec::default() }, "no free place"),
        (RoomSpec { patch_length: 1e-3, ..RoomSpec::default() }, "patches"),
    ] {
        let e = room(&spec).unwrap_err().to_string();
        assert!(e.contains(option), "{spec:?}: {e}");
    }
}

/// Writes a 64 × 64 room of 16 patches without boxes, with `lights` lights, to `path`.
fn small_room(path: &str, lights: usize) {
    let lights = lights.to_string();
    let spec = ["--width", "64", "--height", "64", "--patch-length", "16", "--boxes", "0"];
    ok(&[&["scene", "gen", "--kind", "room"][..], &spec, &["--lights", &lights, "--out", path]].concat());
}

#[test]
fn the_commands() {
    let dir = TempDir::new("radiosity");
    let scene = dir.join("room.json");
    let scene = path_arg(&scene);
    small_room(scene, 1);
    let row = parse_json(
        &ok(&[
            "form-factors",
            "--scene",
            scene,
            "--source",
            "2",
            "--rays",
            "256",
            "--origins",
            "4",
            "--json",
        ]),
        "form-factors",
    );
    assert_eq!(
        (row["source"].as_u64(), row["rays"].as_u64(), row["origins"].as_u64()),
        (Some(2), Some(256), Some(4))
    );
    let entries = row["form_factors"].as_array().unwrap();
    let sum: f64 = entries.iter().map(|e| e["ff"].as_f64().unwrap()).sum();
    assert!((sum - 1.0).abs() < 1e-12 && (row["sum"].as_f64().unwrap() - sum).abs() < 1e-12);
    assert!(entries.iter().all(|e| e["patch"].as_u64().unwrap() != 2 && e["ff"].as_f64().unwrap() > 0.0));

    // Two slices and a merge give the matrix of one run; the full solve from it is the solve.
    let (a, b, m, w) = (dir.join("a.json"), dir.join("b.json"), dir.join("m.json"), dir.join("w.json"));
    let ff = ["--rays", "128", "--origins", "2", "--quiet"];
    ok(&[&["form-factors", "--scene", scene, "--rows", "0..7", "--out", path_arg(&a)][..], &ff].concat());
    ok(&[&["form-factors", "--scene", scene, "--rows", "7..", "--out", path_arg(&b)][..], &ff].concat());
    ok(&[&["form-factors", "--scene", scene, "--rows", "..", "--out", path_arg(&w)][..], &ff].concat());
    let merge = format!("{},{}", path_arg(&b), path_arg(&a));
    ok(&["form-factors", "--merge", &merge, "--out", path_arg(&m)]);
    assert_eq!(std::fs::read_to_string(&m).unwrap(), std::fs::read_to_string(&w).unwrap());
    let from_matrix = parse_json(
        &ok(&["radiosity", "--scene", scene, "--solver", "full", "--matrix", path_arg(&m), "--json"]),
        "radiosity",
    );
    let traced = parse_json(
        &ok(&[&["radiosity", "--scene", scene, "--solver", "full", "--json"][..], &ff].concat()),
        "radiosity",
    );
    assert_eq!(from_matrix["patches"], traced["patches"]);

    let svg = dir.join("r.svg");
    let solved = parse_json(
        &ok(&[
            "radiosity",
            "--scene",
            scene,
            "--rays",
            "128",
            "--origins",
            "2",
            "--json",
            "--quiet",
            "--svg",
            path_arg(&svg),
        ]),
        "radiosity",
    );
    let patches = solved["patches"].as_array().unwrap();
    assert_eq!(patches.len(), 16);
    assert!(patches.iter().all(|p| p["radiosity"].as_f64().unwrap() > 0.0));
    assert!(solved["unshot"].as_f64().unwrap() <= 1e-3 && solved.get("hardware").is_none());
    assert!(std::fs::read_to_string(&svg).unwrap().starts_with("<svg"));

    let on_pe = parse_json(
        &ok(&[
            "radiosity",
            "--scene",
            scene,
            "--rays",
            "64",
            "--origins",
            "1",
            "--method",
            "stochastic",
            "--on-pe",
            "--engine",
            "rust-hdl",
            "--tc",
            "4",
            "--json",
            "--quiet",
        ]),
        "radiosity --on-pe",
    );
    let h = &on_pe["hardware"];
    assert!(h["cycles"].as_u64().unwrap() > 0 && h["rows"].as_u64() == on_pe["rows"].as_u64(), "{h}");
    assert_eq!(h["tc"].as_u64(), Some(4));

    // The whole matrix on the machine: the same rows (here no tie between two patches at one
    // distance goes to the other of the two under the placement), so the same solution, as each
    // bundle on a fresh PE; the same tests; fewer cycles on three PEs sharing the memory, their
    // caches warm from bundle to bundle.
    let full = |pes: Option<&'static str>| {
        let mut args = vec![
            "radiosity",
            "--scene",
            scene,
            "--solver",
            "full",
            "--rays",
            "64",
            "--origins",
            "2",
            "--on-pe",
            "--tc",
            "4",
            "--cache",
            "8",
            "--json",
            "--quiet",
        ];
        args.extend(pes.map(|n| ["--pes", n]).iter().flatten());
        parse_json(&ok(&args), "radiosity --on-pe --solver full")
    };
    let (fresh, machine) = (full(None), full(Some("3")));
    assert_eq!(
        fresh["patches"], machine["patches"],
        "the machine's solution, then each bundle's on a fresh PE"
    );
    let (hf, hm) = (&fresh["hardware"], &machine["hardware"]);
    assert_eq!(
        (hf["tests"].clone(), hf["golden_agree"].clone()),
        (hm["tests"].clone(), hm["golden_agree"].clone())
    );
    assert_eq!((hf["pes"].as_u64(), hm["pes"].as_u64(), hm["bundles"].as_u64()), (None, Some(3), Some(32)));
    assert!(hm["cycles"].as_u64() < hf["cycles"].as_u64(), "machine {hm}, fresh PEs {hf}");

    // Errors name the option or the file.
    fails(&["scene", "gen", "--kind", "paper", "--width", "10"], &["--width", "--kind room"]);
    fails(&["scene", "gen", "--kind", "room", "--count", "10"], &["--count", "--kind paper"]);
    fails(&["radiosity", "--scene", scene, "--matrix", path_arg(&m)], &["--solver full"]);
    fails(
        &["radiosity", "--scene", scene, "--solver", "full", "--matrix", path_arg(&a)],
        &["merge the slices"],
    );
    fails(&["radiosity", "--scene", scene, "--tolerance", "0"], &["--tolerance"]);
    fails(&["radiosity", "--scene", scene, "--on-pe", "--method", "brute"], &["--method brute"]);
    fails(
        &["radiosity", "--scene", scene, "--on-pe", "--solver", "full", "--pes", "9"],
        &["--pes", "9", "1 and 8"],
    );
    fails(&["radiosity", "--scene", scene, "--on-pe", "--pes", "2"], &["--pes 2", "--solver full"]);
    fails(&["radiosity", "--scene", scene, "--solver", "full", "--pes", "2"], &["--on-pe"]);
    fails(&["radiosity", "--scene", scene, "--on-pe", "--solver", "full", "--place", "index"], &["--pes"]);
    fails(&["form-factors", "--scene", scene, "--source", "99"], &["99"]);
    fails(&["form-factors", "--scene", scene, "--source", "0", "--origins", "0"], &["--origins"]);
    fails(&["form-factors", "--scene", scene, "--rows", "5..3", "--out", path_arg(&a)], &["--rows 5..3"]);
    fails(&["form-factors", "--merge", path_arg(&a), "--out", path_arg(&m)], &["leave rows 7..16 out"]);
    let other = dir.join("other.json");
    small_room(path_arg(&other), 2);
    fails(
        &["radiosity", "--scene", path_arg(&other), "--solver", "full", "--matrix", path_arg(&m)],
        &["do not match"],
    );
    let dark = dir.join("dark.json");
    std::fs::write(&dark, r#"{"segments": [{"a": [0, 0], "b": [1, 0]}]}"#).unwrap();
    fails(&["radiosity", "--scene", path_arg(&dark)], &["dark.json", "emits"]);
}
