//! 3D form factors (`shelling::d3::form_factors`, SCENES3D.md) against closed forms at the
//! default settings (4096 cosine rays from each of 64 origins): Howell's C-11 and C-14, the
//! unit cube's rows, coaxial discs approximated by regular polygons (the polygons' own error
//! bracketed exactly by the disc formula), reciprocity on the Cornell box; and every tracer
//! giving the same rows. Each tolerance is the documented 1 %; the errors measured at these
//! settings are in SCENES3D.md.

use crate::support::closed3d::{self, c11, c14, rel};
use shelling::d3::form_factors::{self, Ff3Params};
use shelling::d3::grid::{Grid3, Grid3Params};
use shelling::d3::scene::Scene3;
use shelling::d3::trace::Method3;
use shelling::radiosity::Row;

/// The documented bound at the defaults, relative to the exact value.
const TOLERANCE: f64 = 0.01;

fn grid(scene: &Scene3) -> Grid3 {
    Grid3::build(scene, Grid3Params::default()).unwrap()
}

fn row(scene: &Scene3, k: usize) -> Row {
    form_factors::row(scene, &grid(scene), k, &Ff3Params::default()).unwrap()
}

#[test]
fn howell_c11_parallel_opposed_rectangles() {
    // REFERENCES.md's values: X = Y = 1 gives 0.199825; a = 1, b = 1.5, c = 0.5 gives 0.475576.
    assert!((c11(1.0, 1.0, 1.0) - 0.199825).abs() < 1e-6);
    assert!((c11(1.0, 1.5, 0.5) - 0.475576).abs() < 1e-6);
    for (a, b, c) in [(1.0, 1.0, 1.0), (1.0, 1.5, 0.5), (2.0, 0.5, 1.0)] {
        let scene = closed3d::opposed(a, b, c);
        let exact = c11(a, b, c);
        for k in 0..2 {
            let f = row(&scene, k).get(1 - k);
            assert!(rel(f, exact) <= TOLERANCE, "C-11 {a}×{b} at {c}, from {k}: {f} against {exact}");
        }
    }
}

#[test]
fn howell_c14_perpendicular_rectangles_with_a_common_edge() {
    assert!((c14(1.0, 1.0, 1.0) - 0.200044).abs() < 1e-6);
    for (w, h, l) in [(1.0, 1.0, 1.0), (0.5, 2.0, 1.0), (1.0, 1.0, 3.0)] {
        let scene = closed3d::perpendicular(w, h, l);
        // From the floor (width w) to the wall (height h), and back (the same formula, w and h
        // swapped).
        for (k, exact) in [(0, c14(w, h, l)), (1, c14(h, w, l))] {
            let f = row(&scene, k).get(1 - k);
            assert!(rel(f, exact) <= TOLERANCE, "C-14 w {w} h {h} l {l}, from {k}: {f} against {exact}");
        }
    }
}

#[test]
fn every_row_of_the_closed_cube_sums_to_1_and_matches_c11_and_c14() {
    // REFERENCES.md's check: 4 · 0.200044 + 0.199825 = 1.
    assert!((4.0 * c14(1.0, 1.0, 1.0) + c11(1.0, 1.0, 1.0) - 1.0).abs() < 2e-6);
    let scene = closed3d::cube();
    let rows = form_factors::rows(&scene, &grid(&scene), 0..6, &Ff3Params::default(), || {}).unwrap();
    for (i, r) in rows.iter().enumerate() {
        assert!((r.sum() - 1.0).abs() < 1e-12, "row {i} sums to {}", r.sum());
        assert_eq!(r.get(i), 0.0, "face {i} sees itself");
        for j in (0..6).filter(|&j| j != i) {
            let exact = if j / 2 == i / 2 { c11(1.0, 1.0, 1.0) } else { c14(1.0, 1.0, 1.0) };
            assert!(rel(r.get(j), exact) <= TOLERANCE, "cube F[{i}][{j}] = {} against {exact}", r.get(j));
        }
    }
}

#[test]
fn coaxial_discs_as_regular_polygons() {
    // REFERENCES.md's values for the discs themselves.
    assert!((closed3d::discs(0.1, 0.2, 0.5) - 0.1339).abs() < 1e-4);
    assert!((closed3d::discs(0.5, 1.0, 2.0) - 0.1922).abs() < 1e-4);
    let n = 64;
    for (r1, r2, a) in [(0.1, 0.2, 0.5), (0.5, 1.0, 2.0), (1.0, 1.0, 0.5)] {
        let (lo, hi) = closed3d::polygon_discs_bracket(r1, r2, a, n);
        // The bracket is narrow: the 64-gons are within 0.5 % of the discs.
        assert!(hi / lo - 1.0 < 5e-3, "bracket {lo}..{hi}");
        let scene = closed3d::polygon_discs(r1, r2, a, n);
        let f = row(&scene, 0).get(1);
        let exact_within = f.clamp(lo, hi);
        assert!(
            rel(f, exact_within) <= TOLERANCE,
            "discs {r1}, {r2} at {a} as {n}-gons: {f}, the exact polygon value lies in {lo}..{hi}"
        );
    }
}

#[test]
fn reciprocity_on_the_cornell_box() {
    // A_i F_ij = A_j F_ji for every pair, within the two estimates' documented errors (1 % of
    // each plus 2/R for a pair seen at grazing angles, where a few horizon cells decide it). The
    // floor and the ceiling are cut around the blocks and the light (SCENES3D.md), so every
    // pair is checked, the floor's and the ceiling's pieces too.
    let scene = closed3d::cornell();
    let n = scene.polygons.len();
    // Brute force is the fastest tracer on the Cornell box's 26 polygons (PERFORMANCE.md);
    // every tracer gives the same rows (the last test).
    let p = Ff3Params { method: Method3::Brute, ..Ff3Params::default() };
    let rows = form_factors::rows(&scene, &grid(&scene), 0..n, &p, || {}).unwrap();
    let (cells, mut worst, mut pairs) = (2.0 / p.rays as f64, (0.0, 0, 0), 0);
    for i in 0..n {
        for j in i + 1..n {
            let (ai, aj) = (scene.polygons[i].area, scene.polygons[j].area);
            let (gij, gji) = (ai * rows[i].get(j), aj * rows[j].get(i));
            let bound = TOLERANCE * (gij + gji) + cells * (ai + aj);
            pairs += (gij + gji > 0.0) as usize;
            if (gij - gji).abs() / bound > worst.0 {
                worst = ((gij - gji).abs() / bound, i, j);
            }
        }
    }
    println!(
        "Cornell box at the defaults: {pairs} pairs, worst {:.3} of the bound, pair {:?}",
        worst.0,
        (worst.1, worst.2)
    );
    assert!(pairs > 150 && worst.0 > 0.0, "{pairs} pairs see each other: the test checks too little");
    assert!(
        worst.0 <= 1.0,
        "pair {:?}: |A_i F_ij − A_j F_ji| is {:.2} times the bound",
        (worst.1, worst.2),
        worst.0
    );
}

#[test]
fn every_tracer_gives_the_same_rows() {
    let scene = closed3d::cornell();
    let grid = grid(&scene);
    for k in [0, 7, 15, 16, scene.polygons.len() - 1] {
        let rows: Vec<(Method3, Row)> = Method3::ALL
            .iter()
            .map(|&method| {
                let p = Ff3Params { rays: 1024, origins: 16, method, ..Ff3Params::default() };
                (method, form_factors::row(&scene, &grid, k, &p).unwrap())
            })
            .collect();
        assert!(!rows[0].1.entries.is_empty());
        for (m, r) in &rows[1..] {
            assert_eq!(r, &rows[0].1, "source {k}: {m} against {}", rows[0].0);
        }
    }
}

/// `rays` cosine rays from `origins` origins by the sweep technique.
fn sweep(rays: usize, origins: usize) -> Ff3Params {
    Ff3Params { rays, origins, method: Method3::Sweep, ..Ff3Params::default() }
}

#[test]
fn rows_on_the_pe_are_the_sweeps_rows() {
    use shelling::cosim::CosimConfig;
    use shelling::d3::on_pe::{self, Pe3Totals};
    // The closed cube: no ray meets an edge within rounding, so every ray's polygon on the PE
    // is the 3D brute force's and the row is the software's, bit for bit.
    let cube = closed3d::cube();
    let p = sweep(1024, 3);
    let mut t = Pe3Totals::default();
    let pe = on_pe::row(&cube, 0, &p, &CosimConfig::default(), &mut t).unwrap();
    assert_eq!(pe, row_with(&cube, 0, &p));
    assert!((pe.sum() - 1.0).abs() < 1e-12);
    assert_eq!((t.origins, t.pe.bundles, t.pe.rays), (3, 3 * 32, 3 * 1024), "64 x 16 rays: 32 planes of 32");
    assert_eq!((t.brute_agree, t.pe.golden_agree, t.pe.rows), (3 * 1024, 3 * 1024, 1));
    assert_eq!(t.packs, 3, "a bundle's 32 planes of 32 rays are one source of the PE");
    assert!(t.pe.tests >= 3 * 1024 && t.pe.cycles > t.pe.tests && t.pe.patch_loads > 0, "{t:?}");
    // The Cornell box, a light's row and a block's: where a ray's polygon differs from the
    // software's (a ray within rounding of an edge), its weight moves from one entry to
    // another, so the rows differ by at most twice the weight of those rays.
    let cornell = shelling::d3::obj::load(std::path::Path::new("scenes/cornell_box.obj")).unwrap();
    let p = sweep(4096, 2);
    for k in [0, cornell.polygons.len() - 1] {
        let mut t = Pe3Totals::default();
        let pe = on_pe::row(&cornell, k, &p, &CosimConfig::default(), &mut t).unwrap();
        let sw = row_with(&cornell, k, &p);
        let moved = (2 * 4096 - t.brute_agree) as f64 / (2.0 * 4096.0);
        let diff: f64 = (0..cornell.polygons.len()).map(|j| (pe.get(j) - sw.get(j)).abs()).sum();
        assert!(t.brute_agree as f64 >= 0.999 * 2.0 * 4096.0, "row {k}: {t:?}");
        assert!(
            diff <= 2.0 * moved + 1e-12,
            "row {k}: the rows differ by {diff}, {moved} of the weight moved"
        );
        assert!(!pe.entries.is_empty());
    }
}

#[test]
fn rows_on_the_machine_are_the_rows_on_fresh_pes() {
    use shelling::cosim::{CosimConfig, Engine};
    use shelling::d3::on_pe::{self, On3Error};
    use shelling::machine::{Deal, MachineConfig, Placement};
    // Every row of the closed cube on a machine of two PEs sharing a host memory at T_c = 4, in
    // one machine run and in batches of at most 100 slices (a bundle's 32 planes hold 96): the
    // rows of the PEs one plane at a time, bit for bit, with as many planes, rays and agreeing
    // rays; the machine's cycles are its own.
    let cube = closed3d::cube();
    let p = sweep(1024, 2);
    let pe = CosimConfig { tc: 4, cache: Some(16), ..CosimConfig::default() };
    let (fresh, ft) = on_pe::rows(&cube, 0..6, &p, &pe, || {}).unwrap();
    let machine = MachineConfig {
        pes: 2,
        tc: 4,
        cache: Some(16),
        deal: Deal::Blocks,
        place: Placement::Lines,
        engine: Engine::Auto.resolve(false),
        vcd: None,
    };
    let (whole, wt) = on_pe::rows_on_machine(&cube, &p, &machine, |_, _| {}).unwrap();
    let (batched, bt) = on_pe::rows_on_machine_in(&cube, &p, &machine, 100, |_, _| {}).unwrap();
    for (t, rows) in [(wt, &whole), (bt, &batched)] {
        assert_eq!(rows, &fresh);
        assert_eq!((t.pe.rows, t.pe.bundles, t.pe.rays, t.origins), (6, 6 * 2 * 32, 6 * 2 * 1024, 12));
        assert_eq!(
            (t.pe.golden_agree, t.brute_agree, t.pe.tests),
            (ft.pe.golden_agree, ft.brute_agree, ft.pe.tests)
        );
        assert!(t.pe.cycles > 0 && t.pe.patch_loads >= t.pe.cache_hits);
    }
    assert_ne!(wt.pe.cycles, bt.pe.cycles, "the batches drain the machine between them");
    // A bundle larger than the batch is refused, naming the way out.
    let e = on_pe::rows_on_machine_in(&cube, &p, &machine, 50, |_, _| {}).unwrap_err();
    assert!(matches!(e, On3Error::Cosim(_)) && e.to_string().contains("fewer --rays"), "{e}");
    let sectors = MachineConfig { deal: Deal::Sectors, ..machine };
    assert!(on_pe::rows_on_machine(&cube, &p, &sectors, |_, _| {})
        .unwrap_err()
        .to_string()
        .contains("--deal sectors"));
}

#[test]
fn a_plane_fits_the_datapath_at_the_largest_power_of_two_scale() {
    use shelling::d3::on_pe::plane_scale;
    use shelling_hdl::formats::WORLD_SPAN;
    for scene in [closed3d::cube(), closed3d::opposed(2.0, 0.5, 1.0)] {
        for o in [glam::DVec3::ZERO, glam::DVec3::new(0.5, 0.5, 0.0)] {
            let s = plane_scale(&scene, o);
            let r = scene
                .polygons
                .iter()
                .flat_map(|p| &p.vertices)
                .map(|v| (*v - o).length())
                .fold(0.0, f64::max);
            assert_eq!(s.log2().fract(), 0.0, "{s} is a power of two");
            assert!(r * s <= 0.45 * WORLD_SPAN && 2.0 * r * s > 0.45 * WORLD_SPAN, "r {r}, scale {s}");
        }
    }
}

fn row_with(scene: &Scene3, k: usize, p: &Ff3Params) -> Row {
    form_factors::row(scene, &grid(scene), k, p).unwrap()
}

#[test]
fn rows_on_the_pe_of_the_3d_workload() {
    use shelling::cosim::CosimConfig;
    use shelling::d3::on_pe::{self, Pe3Totals};
    // Random squares of three sizes (most planes meet none, a few meet many): every ray on the
    // brute force's polygon, so the rows are the software sweep's, bit for bit.
    for (size, seed) in [(2.0, 3u64), (8.0, 1), (64.0, 2)] {
        let scene = shelling::d3::gen::generate(300, size, seed).unwrap();
        let p = sweep(1024, 2);
        for k in [0, 150] {
            let mut t = Pe3Totals::default();
            let pe = on_pe::row(&scene, k, &p, &CosimConfig::default(), &mut t).unwrap();
            assert_eq!((t.brute_agree, t.host_tests), (2 * 1024, 0), "size {size}, row {k}: {t:?}");
            assert_eq!(pe, row_with(&scene, k, &p), "size {size}, row {k}");
            assert!(t.pe.bundles > 0 && t.pe.golden_agree == t.pe.rays, "size {size}, row {k}: {t:?}");
        }
    }
}
