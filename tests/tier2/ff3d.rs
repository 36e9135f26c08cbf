//! Tier 2 of the 3D form factors: the closed-form cases of `tests/ff3d.rs` at the defaults and at
//! four times the rays, the origins or both, the table of relative errors
//! printed (SCENES3D.md quotes it: `cargo test --release --features tier2 --test tier2 ff3d:: --
//! --nocapture`), and the largest settings held to 0.3 %.

use crate::support::closed3d::{self, c11, c14, rel};
use shelling::d3::form_factors::{self, Ff3Params, DEFAULT_ORIGINS, DEFAULT_RAYS};
use shelling::d3::grid::{Grid3, Grid3Params};
use shelling::d3::scene::Scene3;
use shelling::d3::trace::Method3;

#[test]
fn closed_forms_converge_with_rays_and_origins() {
    let n = 64;
    let (dlo, dhi) = closed3d::polygon_discs_bracket(0.5, 1.0, 2.0, n);
    // (name, scene, from, to, exact or bracket)
    let cases: Vec<(&str, Scene3, usize, usize, (f64, f64))> = vec![
        ("C-11 1×1 at 1", closed3d::opposed(1.0, 1.0, 1.0), 0, 1, (c11(1.0, 1.0, 1.0), c11(1.0, 1.0, 1.0))),
        (
            "C-11 1×1.5 at 0.5",
            closed3d::opposed(1.0, 1.5, 0.5),
            0,
            1,
            (c11(1.0, 1.5, 0.5), c11(1.0, 1.5, 0.5)),
        ),
        (
            "C-14 1,1,1 floor",
            closed3d::perpendicular(1.0, 1.0, 1.0),
            0,
            1,
            (c14(1.0, 1.0, 1.0), c14(1.0, 1.0, 1.0)),
        ),
        (
            "C-14 1,1,1 wall",
            closed3d::perpendicular(1.0, 1.0, 1.0),
            1,
            0,
            (c14(1.0, 1.0, 1.0), c14(1.0, 1.0, 1.0)),
        ),
        (
            "C-14 0.5,2,1",
            closed3d::perpendicular(0.5, 2.0, 1.0),
            0,
            1,
            (c14(0.5, 2.0, 1.0), c14(0.5, 2.0, 1.0)),
        ),
        ("discs 0.5,1 at 2", closed3d::polygon_discs(0.5, 1.0, 2.0, n), 0, 1, (dlo, dhi)),
    ];
    let settings = [
        (DEFAULT_RAYS, DEFAULT_ORIGINS),
        (4 * DEFAULT_RAYS, DEFAULT_ORIGINS),
        (DEFAULT_RAYS, 4 * DEFAULT_ORIGINS),
        (4 * DEFAULT_RAYS, 4 * DEFAULT_ORIGINS),
    ];
    let mut table = format!("{:<20}", "case (relative error)");
    for (r, m) in settings {
        table += &format!("{:>16}", format!("R {r}, M {m}"));
    }
    table.push('\n');
    let mut worst_last = 0.0f64;
    for (name, scene, i, j, (lo, hi)) in &cases {
        let grid = Grid3::build(scene, Grid3Params::default()).unwrap();
        table += &format!("{name:<20}");
        for (s, &(rays, origins)) in settings.iter().enumerate() {
            let p = Ff3Params { rays, origins, method: Method3::Brute, ..Ff3Params::default() };
            let f = form_factors::row(scene, &grid, *i, &p).unwrap().get(*j);
            let exact = f.clamp(*lo, *hi);
            let e = (f - exact) / exact;
            table += &format!("{:>+16.5}", e);
            assert!(rel(f, exact) <= 0.01, "{name}, R {rays}, M {origins}: {f} against {lo}..{hi}");
            if s == settings.len() - 1 {
                worst_last = worst_last.max(e.abs());
            }
        }
        table.push('\n');
    }
    println!("{table}");
    assert!(worst_last <= 3e-3, "at the largest settings the worst error is {worst_last}:\n{table}");
}
