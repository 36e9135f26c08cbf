//! Radiosity on 3D scenes (RADIOSITY.md, "In 3D"): the form-factor rows of the shipped scenes
//! (a closed room's rows sum to 1, reciprocity), and the solves of `shelling::d3::radiosity` in
//! each colour channel: energy balance on a closed and an open scene, the residual of the
//! radiosity equation at both solvers' solutions and their agreement, two closed forms (the
//! total power of a closed room of uniform reflectance, the furnace), and the errors of scenes
//! that cannot be solved. The figures RADIOSITY.md quotes are printed with `--nocapture`:
//! `cargo test --test tests radiosity3d:: -- --nocapture --test-threads 1`.
//!
//! Nothing here is random: the rays and the origins are deterministic (SCENES3D.md), so every
//! figure is the same on every run.

use crate::cli::{fails, ok, parse_json, path_arg, TempDir};
use serde_json::Value;
use shelling::d3::form_factors::{self, Ff3Params};
use shelling::d3::grid::{Grid3, Grid3Params};
use shelling::d3::obj;
use shelling::d3::radiosity::{self as rad3, Solution3};
use shelling::d3::scene::{Material3, Scene3};
use shelling::d3::trace::Method3;
use shelling::radiosity::{Row, SolveError};
use std::path::Path;
use std::sync::OnceLock;

/// The solvers' tolerance here: the command line's default.
const TOLERANCE: f64 = 1e-3;

/// Shots or sweeps, per channel.
const MAX_STEPS: usize = 100_000;

/// Relative slack for sums of many f64 terms that are equal in exact arithmetic.
const ROUNDING: f64 = 1e-9;

fn shipped(name: &str) -> Scene3 {
    obj::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name)).unwrap()
}

/// A scene, how its rows were traced, and every row.
struct Traced {
    name: &'static str,
    scene: Scene3,
    params: Ff3Params,
    rows: Vec<Row>,
}

impl Traced {
    fn new(name: &'static str, scene: Scene3, params: Ff3Params) -> Traced {
        let grid = Grid3::build(&scene, Grid3Params::default()).unwrap();
        let n = scene.polygons.len();
        let rows = form_factors::rows(&scene, &grid, 0..n, &params, || {}).unwrap();
        Traced { name, scene, params, rows }
    }

    fn area(&self, j: usize) -> f64 {
        self.scene.polygons[j].area
    }

    /// The bound on the rounding of a row's sum: `R·M` additions of weights of `1/(RM)` into
    /// values at most 1, each off by at most half an ulp of 1, then the sum of the entries.
    fn row_rounding(&self) -> f64 {
        (self.params.rays * self.params.origins + self.scene.polygons.len()) as f64 * f64::EPSILON / 2.0
    }

    fn full(&self) -> Solution3 {
        rad3::full(&self.scene, self.name, &self.rows, TOLERANCE, MAX_STEPS).unwrap()
    }

    fn progressive(&self) -> Solution3 {
        rad3::progressive(&self.scene, self.name, TOLERANCE, MAX_STEPS, |i| {
            Ok::<_, SolveError>(self.rows[i].clone())
        })
        .unwrap()
    }

    /// `Σ_i B_i Σ_j (A_i F_ij − A_j F_ji)` with its terms' magnitudes: the power the rows'
    /// reciprocity error creates, signed and as a bound.
    fn reciprocity_power(&self, b: &[f64]) -> (f64, f64) {
        let (mut signed, mut bound) = (0.0, 0.0);
        for (i, row) in self.rows.iter().enumerate() {
            for e in &row.entries {
                let j = e.patch as usize;
                let d = self.area(i) * e.ff - self.area(j) * self.rows[j].get(i);
                signed += b[i] * d;
                bound += b[i] * d.abs();
            }
            // Pairs `j` sees `i` but `i` misses `j`.
            for (j, other) in self.rows.iter().enumerate() {
                if row.get(j) == 0.0 {
                    let d = -self.area(j) * other.get(i);
                    signed += b[i] * d;
                    bound += b[i] * d.abs();
                }
            }
        }
        (signed, bound)
    }
}

/// The closed box room at the defaults (4096 cosine rays from 256 origins, conventional tracer).
fn box_room() -> &'static Traced {
    static T: OnceLock<Traced> = OnceLock::new();
    T.get_or_init(|| Traced::new("box_room.obj", shipped("box_room.obj"), Ff3Params::default()))
}

/// The Cornell box at the defaults (brute force: the fastest tracer on its 26 polygons).
fn cornell() -> &'static Traced {
    static T: OnceLock<Traced> = OnceLock::new();
    T.get_or_init(|| {
        let p = Ff3Params { method: Method3::Brute, ..Ff3Params::default() };
        Traced::new("cornell_box.obj", shipped("cornell_box.obj"), p)
    })
}

/// An open scene with colours: the box room without its wall at `z = 256` (polygons 45 to 53;
/// the light is polygon 13), the floor red-ish, the other walls blue-ish, the light white with
/// `Ke = (1, 2, 0.5)`, so the three channels differ. 1024 rays from 64 origins.
fn open_room() -> &'static Traced {
    static T: OnceLock<Traced> = OnceLock::new();
    T.get_or_init(|| {
        let mut scene = shipped("box_room.obj");
        scene.polygons.truncate(45);
        scene.materials = vec![
            Material3 { name: "floor".into(), kd: [0.8, 0.3, 0.2], ke: [0.0; 3] },
            Material3 { name: "wall".into(), kd: [0.2, 0.4, 0.9], ke: [0.0; 3] },
            Material3 { name: "light".into(), kd: [0.5; 3], ke: [1.0, 2.0, 0.5] },
        ];
        let m = scene.materials.clone();
        for (k, p) in scene.polygons.iter_mut().enumerate() {
            let index = if k < 9 {
                0
            } else if k == 13 {
                2
            } else {
                1
            };
            *p = p.clone().with_material(index, &m[index]);
        }
        assert!(!scene.open_edges().is_empty());
        Traced::new("open room", scene, Ff3Params { rays: 1024, origins: 64, ..Ff3Params::default() })
    })
}

/// `B − E − ρ·(matrix)·B` of channel `c` for each polygon: `gather` from the polygon's own row
/// (`Σ_i F_ji B_i`, the full solver's equation) or else by reciprocity from the others' rows
/// (`Σ_i A_i F_ij B_i / A_j`, what progressive refinement shoots).
fn residuals(t: &Traced, s: &Solution3, c: usize, gather: bool) -> Vec<f64> {
    let surfaces = rad3::surfaces(&t.scene, c);
    let b = &s.channels[c].radiosity;
    let n = b.len();
    let mut h = vec![0.0; n];
    for (i, row) in t.rows.iter().enumerate() {
        for e in &row.entries {
            let j = e.patch as usize;
            match gather {
                true => h[i] += e.ff * b[j],
                false => h[j] += t.area(i) * e.ff * b[i] / t.area(j),
            }
        }
    }
    (0..n).map(|j| b[j] - surfaces.emission[j] - surfaces.reflectance[j] * h[j]).collect()
}

/// `Σ_j A_j |x_j|`: the norm of power.
fn power(t: &Traced, x: &[f64]) -> f64 {
    x.iter().enumerate().map(|(j, v)| t.area(j) * v.abs()).sum()
}

#[test]
fn every_row_of_the_closed_box_room_sums_to_1() {
    // Every ray from inside a closed surface hits it, so a row sums to 1 up to the rounding of
    // its R·M weights (1.2e-10 at the defaults). A square sees every square of the five other
    // walls (45) and none of its own.
    let t = box_room();
    let mut worst: f64 = 0.0;
    for (i, row) in t.rows.iter().enumerate() {
        worst = worst.max((row.sum() - 1.0).abs());
        assert!((row.sum() - 1.0).abs() <= t.row_rounding(), "row {i} sums to {}", row.sum());
        assert_eq!(row.entries.len(), 45, "row {i}: {:?}", row.entries);
        assert!(row.entries.iter().all(|e| e.patch as usize / 9 != i / 9 && e.ff > 0.0), "row {i}");
    }
    println!("box room: largest |Σ_j F_ij − 1| {worst:.2e} (bound {:.2e})", t.row_rounding());
}

/// Checks `A_i F_ij = A_j F_ji` for every pair of `t`, within the estimate's documented error at
/// the defaults (SCENES3D.md): 1 % of each side plus two ray weights, `2/R`, of each area (a
/// pair seen at grazing angles is decided by a few horizon cells). Returns the pairs checked, the worst ratio to the bound and the total
/// `Σ |A_i F_ij − A_j F_ji|` over `Σ A_i F_ij`.
fn reciprocity(t: &Traced) -> (usize, f64, f64) {
    let n = t.scene.polygons.len();
    let cell = 2.0 / t.params.rays as f64;
    let (mut pairs, mut worst, mut worst_pair, mut diff, mut total) = (0, 0.0f64, (0, 0), 0.0, 0.0);
    for i in 0..n {
        for j in i + 1..n {
            let (gij, gji) = (t.area(i) * t.rows[i].get(j), t.area(j) * t.rows[j].get(i));
            if gij + gji == 0.0 {
                continue;
            }
            pairs += 1;
            let ratio = (gij - gji).abs() / (0.01 * (gij + gji) + cell * (t.area(i) + t.area(j)));
            if ratio > worst {
                (worst, worst_pair) = (ratio, (i, j));
            }
            diff += (gij - gji).abs();
            total += gij + gji;
        }
    }
    assert!(worst <= 1.0, "{}: pair {worst_pair:?} is {worst:.2} times the bound", t.name);
    (pairs, worst, diff / total)
}

#[test]
fn reciprocity_on_the_box_room_and_the_cornell_box() {
    let (pairs, worst, mean) = reciprocity(box_room());
    println!("box room: {pairs} pairs, worst {worst:.3} of the bound, Σ|ΔAF| / ΣAF = {mean:.2e}");
    assert_eq!(pairs, 54 * 45 / 2);
    // The Cornell box's floor and ceiling are cut around the blocks and the light, so every
    // point of them sees only front faces (SCENES3D.md): every pair, theirs too.
    let (pairs, worst, mean) = reciprocity(cornell());
    println!("Cornell box: {pairs} pairs, worst {worst:.3} of the bound, Σ|ΔAF| / ΣAF = {mean:.2e}");
    assert!(pairs > 150, "{pairs} pairs see each other: the test checks too little");
}

/// Checks the energy balance of each channel of `s`, solved by progressive refinement (`full`
/// false) or the full solver, on `t`; returns each channel's `(emitted, absorbed, escaped,
/// imbalance)`.
fn balance(t: &Traced, s: &Solution3, full: bool) -> Vec<(f64, f64, f64, f64)> {
    (0..3)
        .map(|c| {
            let ch = &s.channels[c];
            let (e, a, x) = (ch.emitted, ch.absorbed, ch.escaped);
            // Escaped power is 1 − Σ_j F_ij of what leaves, so it may be a rounding below 0.
            assert!(e > 0.0 && a > 0.0 && x >= -ROUNDING * e, "{} channel {c}: {e} {a} {x}", t.name);
            let imbalance = e - a - x;
            if !full {
                // Each shot's power splits exactly into what arrives (absorbed and reflected
                // into the unshot) and what escapes: emitted = absorbed + escaped + unshot.
                assert!(
                    (imbalance - ch.unshot * e).abs() <= ROUNDING * e,
                    "{} channel {c}: emitted {e}, absorbed {a}, escaped {x}, unshot {}",
                    t.name,
                    ch.unshot * e
                );
                assert!(ch.unshot <= TOLERANCE);
            } else {
                // Gathering balances power only as far as the rows are reciprocal: emitted −
                // absorbed − escaped = Σ_i B_i Σ_j (A_i F_ij − A_j F_ji) − Σ_j A_j r_j exactly,
                // r the residual of the equation.
                let b = &ch.radiosity;
                let (signed, bound) = t.reciprocity_power(b);
                let r: f64 = residuals(t, s, c, true).iter().enumerate().map(|(j, r)| t.area(j) * r).sum();
                let total = power(t, b);
                assert!(
                    (imbalance - (signed - r)).abs() <= ROUNDING * total,
                    "{} channel {c}: imbalance {imbalance}, reciprocity {signed}, residual {r}",
                    t.name
                );
                assert!(imbalance.abs() <= bound + TOLERANCE * total);
            }
            (e, a, x, imbalance)
        })
        .collect()
}

#[test]
fn energy_balances_in_every_channel_closed_and_open() {
    // Closed: nothing escapes (but the rounding of the row sums).
    let t = box_room();
    for (solver, s, full) in [("progressive", t.progressive(), false), ("full", t.full(), true)] {
        for (c, (e, a, x, imbalance)) in balance(t, &s, full).into_iter().enumerate() {
            assert!(
                x.abs() <= t.row_rounding() * power(t, &s.channels[c].radiosity),
                "{solver}: escaped {x}"
            );
            println!(
                "box room, {solver}, channel {c}: emitted {e:.6}, absorbed {a:.6}, escaped {x:.3e}, \
                 emitted − absorbed − escaped {:.3e} of emitted",
                imbalance / e
            );
        }
    }
    // Open, coloured: a good part of the light leaves, differently in each channel.
    let t = open_room();
    for (solver, s, full) in [("progressive", t.progressive(), false), ("full", t.full(), true)] {
        let figures = balance(t, &s, full);
        for (c, (e, a, x, imbalance)) in figures.iter().enumerate() {
            assert!(*x > 0.1 * e, "{solver}: only {x} of {e} escapes through the open wall");
            println!(
                "open room, {solver}, channel {c}: emitted {e:.6}, absorbed {a:.6}, escaped {x:.6}, \
                 emitted − absorbed − escaped {:.3e} of emitted",
                imbalance / e
            );
        }
        assert!(figures[0].2 / figures[0].0 != figures[2].2 / figures[2].0, "the channels are the same");
    }
    // The Cornell box is open too (its front). Its floor and ceiling are cut around the blocks
    // and the light (SCENES3D.md), so its rows are reciprocal to their estimate's error and the
    // full solve balances power like the rooms' do: emitted − absorbed − escaped measured
    // +7.9e-4, −1.2e-4, −1.7e-4 of emitted (r, g, b; uncut it was −4.6 %), progressive's the
    // unshot 9.3e-4 to 9.9e-4. Held to 2e-3 of emitted.
    let t = cornell();
    for (solver, s, full) in [("progressive", t.progressive(), false), ("full", t.full(), true)] {
        for (c, (e, a, x, imbalance)) in balance(t, &s, full).into_iter().enumerate() {
            assert!(x > 0.1 * e, "{solver}: only {x} of {e} escapes through the open front");
            println!(
                "Cornell box, {solver}, channel {c}: emitted {e:.1}, absorbed {a:.1}, escaped {x:.1}, \
                 emitted − absorbed − escaped {:.3e} of emitted",
                imbalance / e
            );
            assert!(
                imbalance.abs() <= 2e-3 * e,
                "{solver} channel {c}: the Cornell box's solve is off balance by {imbalance} of {e}"
            );
        }
    }
}

/// The residuals and the agreement of the two solvers on `t`; returns, per channel, the full
/// solver's relative residual, progressive's against the shooting matrix, and the relative
/// difference of the two solutions in power.
fn residuals_and_agreement(t: &Traced, agree: f64) -> Vec<(f64, f64, f64)> {
    let (full, progressive) = (t.full(), t.progressive());
    (0..3)
        .map(|c| {
            let (bf, bp) = (&full.channels[c].radiosity, &progressive.channels[c].radiosity);
            // Full: the gathering equation, to the tolerance.
            let rf = residuals(t, &full, c, true);
            let full_residual = power(t, &rf) / power(t, bf);
            assert!(full_residual <= TOLERANCE, "{} channel {c}: full residual {full_residual}", t.name);
            // Progressive: B_j = E_j + ρ_j Σ_i (A_i F_ij / A_j)(B_i − ΔB_i) holds exactly, so the
            // shooting equation's residual is at most ρ_max times the unshot power.
            let shot = power(t, &residuals(t, &progressive, c, false)) / power(t, bp);
            let unshot = progressive.channels[c].unshot * progressive.channels[c].emitted / power(t, bp);
            assert!(shot <= unshot * (1.0 + ROUNDING) && unshot <= TOLERANCE, "{} channel {c}", t.name);
            // Agreement: d = B_full − B_progressive solves (I − ρF) d = r_full − r_progressive
            // (both residuals of the gathering equation), so ‖d‖ ≤ ‖r_f − r_p‖ / (1 − ‖ρF‖) in
            // the norm of power, ‖ρF‖ = max_i Σ_j A_j ρ_j F_ji / A_i (< 1 here).
            let s = rad3::surfaces(&t.scene, c);
            let mut column = vec![0.0; bf.len()];
            for (j, row) in t.rows.iter().enumerate() {
                for e in &row.entries {
                    column[e.patch as usize] += t.area(j) * s.reflectance[j] * e.ff;
                }
            }
            let norm = (0..bf.len()).map(|i| column[i] / t.area(i)).fold(0.0, f64::max);
            assert!(norm < 1.0, "{}: ‖ρF‖ = {norm}", t.name);
            let rp = residuals(t, &progressive, c, true);
            let dr: Vec<f64> = rf.iter().zip(&rp).map(|(f, p)| f - p).collect();
            let d: Vec<f64> = bf.iter().zip(bp).map(|(f, p)| f - p).collect();
            assert!(
                power(t, &d) <= power(t, &dr) / (1.0 - norm) * (1.0 + ROUNDING),
                "{} channel {c}",
                t.name
            );
            let difference = power(t, &d) / power(t, bf);
            assert!(difference <= agree, "{} channel {c}: the solvers differ by {difference:.3e}", t.name);
            (full_residual, shot, difference)
        })
        .collect()
}

#[test]
fn both_solvers_solve_the_equation_and_agree() {
    // They differ by the tolerances and the rows' reciprocity error (Σ|ΔAF| / ΣAF, printed by
    // the reciprocity test): within 2e-3 of the power on the box room, 1e-2 on the open room's
    // 1024 rays from 64 origins, 5e-3 on the Cornell box (measured 1.8e-3 to 2.1e-3; uncut,
    // 3.8e-2).
    for (t, agree) in [(box_room(), 2e-3), (open_room(), 1e-2), (cornell(), 5e-3)] {
        for (c, (full, shot, difference)) in residuals_and_agreement(t, agree).into_iter().enumerate() {
            println!(
                "{}, channel {c}: full residual {full:.2e}, progressive (shooting) residual \
                 {shot:.2e}, ‖B_full − B_progressive‖ / ‖B_full‖ = {difference:.2e}",
                t.name
            );
        }
    }
    // Polygon by polygon on the Cornell box, relative to the full solve's B. Measured: the
    // floor's power (its 7 pieces) within 2.1e-3 to 4.0e-3 (uncut, 26 %), the median polygon
    // 3.4e-3 to 4.0e-3, the worst 3.2e-2 to 4.9e-2 on the short block's side facing the back
    // wall (polygon 20; uncut, 23 %), which sees the light only at grazing angles: there the two
    // rows' estimates, A_light F_light,20 and A_20 F_20,light, differ by a factor of 2 within
    // the `2/R` bound of the reciprocity test, and its direct light is all from the light. Held
    // to 1e-2 (floor and median) and 0.1 (worst).
    let t = cornell();
    let (full, progressive) = (t.full(), t.progressive());
    for c in 0..3 {
        let (bf, bp) = (&full.channels[c].radiosity, &progressive.channels[c].radiosity);
        let mut d: Vec<(f64, usize)> = (0..bf.len()).map(|j| ((bf[j] - bp[j]).abs() / bf[j], j)).collect();
        d.sort_by(|a, b| a.partial_cmp(b).unwrap());
        let (worst, j) = d[d.len() - 1];
        let median = d[d.len() / 2].0;
        let floor = |b: &[f64]| (0..7).map(|j| t.area(j) * b[j]).sum::<f64>();
        let on_floor = (floor(bf) - floor(bp)).abs() / floor(bf);
        println!(
            "Cornell box, channel {c}: |B_full − B_progressive| / B_full worst {worst:.2e} (polygon {j}), \
             median {median:.2e}, the floor's power {on_floor:.2e}"
        );
        assert!(worst <= 0.1, "channel {c}: polygon {j}'s solutions differ by {worst:.3e}");
        assert!(median <= 1e-2 && on_floor <= 1e-2, "channel {c}: median {median:.3e}, floor {on_floor:.3e}");
    }
}

#[test]
fn a_closed_room_of_uniform_reflectance_holds_e_over_1_minus_rho() {
    // Σ_j A_j B_j = Σ_j A_j E_j / (1 − ρ) when every row sums to 1 and ρ is uniform: the
    // emitted power, reflected ρ, ρ², … times. Progressive refinement holds it exactly for the
    // power it has shot: Σ A B = (emitted − ρ·unshot) / (1 − ρ). The full solve gathers, so it
    // is off by the rows' reciprocity error besides the tolerance.
    let t = box_room();
    let rho = 0.5;
    for (solver, s) in [("progressive", t.progressive()), ("full", t.full())] {
        for c in 0..3 {
            let ch = &s.channels[c];
            let (total, exact) = (power(t, &ch.radiosity), ch.emitted / (1.0 - rho));
            let error = (total - exact) / exact;
            if solver == "progressive" {
                let shot = (ch.emitted - rho * ch.unshot * ch.emitted) / (1.0 - rho);
                assert!((total - shot).abs() <= ROUNDING * exact, "{total} against {shot}");
                assert!(error.abs() <= rho * TOLERANCE, "{solver} channel {c}: {error:.3e}");
            } else {
                let (_, reciprocity) = t.reciprocity_power(&ch.radiosity);
                let bound = (TOLERANCE * total + reciprocity) / (1.0 - rho);
                assert!((total - exact).abs() <= bound, "{solver} channel {c}: {error:.3e}");
                assert!(error.abs() <= 2e-3, "{solver} channel {c}: {error:.3e}");
            }
            println!("box room, {solver}, channel {c}: Σ A B = {total:.4} against {exact:.4} ({error:+.2e})");
        }
    }
}

#[test]
fn the_furnace_in_three_colours() {
    // Every polygon of the closed box room emits Ke = (1, 2, 3) and reflects Kd = (0.2, 0.5,
    // 0.8): B = c = Ke / (1 − Kd) on every polygon in each channel. In the norm of power,
    // ‖x‖ = Σ_j A_j |x_j|:
    // * full: (I − ρF) B = E + r, and (I − ρF) c = E since the rows sum to 1, so
    //   ‖B − c‖ ≤ ‖r‖ / (1 − ρκ), κ = max_i Σ_j A_j F_ji / A_i (1 for reciprocal rows);
    // * progressive: (I − ρG) B = E − ρ G ΔB with G_ji = A_i F_ij / A_j, ΔB the unshot, and
    //   (I − ρG) c = E − ρ c (G·1 − 1), so ‖B − c‖ ≤ ρ (U + c ‖G·1 − 1‖) / (1 − ρ), U the
    //   unshot power: it is off by the rows' reciprocity error, amplified by 1 / (1 − ρ).
    let closed = box_room();
    let m = Material3 { name: "furnace".into(), kd: [0.2, 0.5, 0.8], ke: [1.0, 2.0, 3.0] };
    let mut scene = closed.scene.clone();
    scene.polygons = scene.polygons.into_iter().map(|p| p.with_material(0, &m)).collect();
    scene.materials = vec![m.clone()];
    let t = Traced { name: "furnace", scene, params: closed.params.clone(), rows: closed.rows.clone() };
    let n = t.rows.len();
    // Σ_j A_j F_ji / A_i and Σ_i A_i F_ij / A_j (the same sums: the columns of A·F).
    let mut column = vec![0.0; n];
    for (j, row) in t.rows.iter().enumerate() {
        for e in &row.entries {
            column[e.patch as usize] += t.area(j) * e.ff;
        }
    }
    let kappa = (0..n).map(|i| column[i] / t.area(i)).fold(0.0, f64::max);
    let defect: f64 = (0..n).map(|j| (column[j] - t.area(j)).abs()).sum();
    let area: f64 = (0..n).map(|j| t.area(j)).sum();
    let (full, progressive) = (t.full(), t.progressive());
    for c in 0..3 {
        let (rho, exact) = (m.kd[c], m.ke[c] / (1.0 - m.kd[c]));
        for (solver, s) in [("full", &full), ("progressive", &progressive)] {
            let b = &s.channels[c].radiosity;
            let error: f64 = (0..n).map(|j| t.area(j) * (b[j] - exact).abs()).sum::<f64>() / (exact * area);
            let worst = b.iter().map(|b| (b - exact).abs() / exact).fold(0.0, f64::max);
            let bound = if solver == "full" {
                power(&t, &residuals(&t, s, c, true)) / (1.0 - rho * kappa) / (exact * area)
            } else {
                let unshot = s.channels[c].unshot * s.channels[c].emitted;
                rho * (unshot + exact * defect) / (1.0 - rho) / (exact * area)
            };
            assert!(error <= bound * (1.0 + ROUNDING), "{solver} channel {c}: {error:.3e} > {bound:.3e}");
            println!(
                "furnace, {solver}, ρ = {rho}: B = {exact} within {error:.2e} in power (bound {bound:.2e}), \
                 {worst:.2e} on the worst polygon"
            );
        }
    }
}

#[test]
fn scenes_that_cannot_be_solved_are_errors_naming_the_problem() {
    let room = shipped("box_room.obj");
    let (wall, light) = (material(&room, "wall"), material(&room, "light"));
    let name = "room.obj";
    let solve = |scene: &Scene3| rad3::full(scene, name, &box_room().rows, TOLERANCE, MAX_STEPS);
    // Nothing emits.
    let mut dark = room.clone();
    dark.materials[light].ke = [0.0; 3];
    assert_eq!(rad3::check(&dark, name).unwrap_err(), SolveError::NothingEmits3 { name: name.into() });
    assert_eq!(solve(&dark).unwrap_err(), SolveError::NothingEmits3 { name: name.into() });
    let err = rad3::progressive(&dark, name, TOLERANCE, MAX_STEPS, |_| -> Result<Row, SolveError> {
        panic!("no row is traced for a scene that cannot be solved")
    });
    assert!(err.unwrap_err().to_string().contains("nothing in the scene emits"));
    // A Kd channel of 1 (the loader takes it: the mean is below 1).
    let mut white = room.clone();
    white.materials[wall].kd = [0.5, 1.0, 0.5];
    let e = SolveError::ReflectsAll { name: name.into(), material: "wall".into(), channel: "green", kd: 1.0 };
    assert_eq!(solve(&white).unwrap_err(), e);
    // An emission whose power overflows.
    let mut hot = room.clone();
    hot.materials[light].ke = [f64::MAX, 1.0, 1.0];
    let e = SolveError::NotFinite { name: name.into(), channel: "red" };
    assert_eq!(solve(&hot).unwrap_err(), e);
    // One channel dark is no error: its solution is 0.
    let mut red = room;
    red.materials[light].ke = [1.0, 0.0, 0.0];
    let s = solve(&red).unwrap();
    assert!(s.channels[1].radiosity.iter().all(|&b| b == 0.0) && s.channels[1].steps == 0);
    assert!(s.channels[0].radiosity.iter().all(|&b| b > 0.0 && b.is_finite()));
}

/// The index of the material `name` of `scene`.
fn material(scene: &Scene3, name: &str) -> usize {
    scene.materials.iter().position(|m| m.name == name).unwrap()
}

/// Writes the box room to `dir` with the MTL `mtl`.
fn room_with(dir: &TempDir, mtl: &str) -> String {
    let obj =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/box_room.obj")).unwrap();
    std::fs::write(dir.join("box_room.obj"), obj).unwrap();
    std::fs::write(dir.join("box_room.mtl"), mtl).unwrap();
    path_arg(&dir.join("box_room.obj")).to_string()
}

fn all_finite(v: &Value) -> bool {
    match v {
        Value::Number(n) => n.as_f64().is_some_and(f64::is_finite),
        Value::Array(a) => a.iter().all(all_finite),
        Value::Object(o) => o.values().all(all_finite),
        _ => true,
    }
}

#[test]
fn the_command_on_obj_scenes() {
    let dir = TempDir::new("radiosity3d");
    let room = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/box_room.obj");
    let cornell = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cornell_box.obj");
    let few = ["--rays", "256", "--origins", "4", "--quiet", "--json"];
    for solver in ["progressive", "full"] {
        for scene in [room, cornell] {
            let v = parse_json(
                &ok(&[&["radiosity", "--scene", scene, "--solver", solver][..], &few].concat()),
                "radiosity",
            );
            assert!(all_finite(&v), "{v}");
            let n = if scene == room { 54 } else { 26 };
            let patches = v["patches"].as_array().unwrap();
            assert_eq!(patches.len(), n);
            for p in patches {
                let rgb: Vec<f64> =
                    p["rgb"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
                let mean = rgb.iter().sum::<f64>() / 3.0;
                assert!((p["radiosity"].as_f64().unwrap() - mean).abs() <= 1e-12 * mean.max(1.0));
            }
            assert_eq!((v["rays"].as_u64(), v["origins"].as_u64()), (Some(256), Some(4)));
            assert_eq!((v["method"].as_str(), v["ray_set"].as_str()), (Some("conventional"), Some("sine")));
            assert_eq!(v["rows"].as_u64(), Some(n as u64), "every polygon shoots or gathers once");
            let channels = v["channels"].as_array().unwrap();
            let names: Vec<&str> = channels.iter().map(|c| c["channel"].as_str().unwrap()).collect();
            assert_eq!(names, ["r", "g", "b"]);
            let f = |c: &Value, k: &str| c[k].as_f64().unwrap();
            for c in channels {
                let left = if solver == "progressive" { f(c, "unshot") * f(c, "emitted") } else { 0.0 };
                let imbalance = f(c, "emitted") - f(c, "absorbed") - f(c, "escaped") - left;
                // Exact (progressive), or up to the rows' reciprocity error, large from 4
                // origins: the room's full solve is off by −3.1 % of emitted, the Cornell box's by
                // −24 % (its small light seen from 4 points of each polygon, and each polygon
                // from 4 points of the light; measured at 256 rays −5.9 to −6.5 % from 16
                // origins, −1.0 to −1.2 % from 64, and 10⁻³ at the defaults,
                // energy_balances_in_every_channel_closed_and_open).
                if solver == "progressive" {
                    assert!(imbalance.abs() <= ROUNDING * f(c, "emitted"), "{scene} {solver}: {c}");
                } else if scene == room {
                    assert!(imbalance.abs() <= 0.05 * f(c, "emitted"), "{scene} {solver}: {c}");
                }
                if scene == room {
                    assert!(f(c, "escaped") <= 1e-9 * f(c, "emitted"), "{c}");
                } else {
                    assert!(f(c, "escaped") > 0.1 * f(c, "emitted"), "{c}");
                }
            }
            let mean = channels.iter().map(|c| f(c, "emitted")).sum::<f64>() / 3.0;
            assert!((v["emitted"].as_f64().unwrap() - mean).abs() <= 1e-9 * mean);
        }
    }
    let text = ok(&["radiosity", "--scene", room, "--rays", "256", "--origins", "4", "--quiet"]);
    assert!(text.contains("54 polygons, progressive solver") && text.contains("escaped"), "{text}");

    // Scenes that cannot be solved, and options that do not apply, by name; no row is traced.
    let lit = "newmtl light\nKd 0.5 0.5 0.5\nKe 1 1 1\n";
    let dark = room_with(&dir, "newmtl wall\nKd 0.5 0.5 0.5\nnewmtl light\nKd 0.5 0.5 0.5\nKe 0 0 0\n");
    for solver in ["progressive", "full"] {
        fails(
            &["radiosity", "--scene", &dark, "--solver", solver],
            &["nothing in the scene emits", "Ke above 0"],
        );
    }
    let white = room_with(&dir, &format!("newmtl wall\nKd 0.2 0.5 1\n{lit}"));
    fails(&["radiosity", "--scene", &white], &["material \"wall\"", "Kd 1 in the blue channel", "below 1"]);
    let grey = room_with(&dir, &format!("newmtl wall\nKd 1 1 1\n{lit}"));
    fails(&["radiosity", "--scene", &grey], &["material \"wall\"", "Kd has mean 1", "below 1"]);
    let over = room_with(&dir, &format!("newmtl wall\nKd 1.5 0.1 0.1\n{lit}"));
    fails(&["radiosity", "--scene", &over], &["material \"wall\"", "outside [0, 1]"]);
    let hot = room_with(&dir, "newmtl wall\nKd 0.5 0.5 0.5\nnewmtl light\nKd 0.5 0.5 0.5\nKe 1e308 1 1\n");
    fails(&["radiosity", "--scene", &hot], &["red channel", "not a finite number"]);
    fails(&["radiosity", "--scene", room, "--tolerance", "1"], &["--tolerance", "[1e-12, 1)"]);
    fails(
        &["radiosity", "--scene", room, "--rays", "64", "--origins", "1", "--max-steps", "3"],
        &["--max-steps", "3 steps"],
    );
    for option in [&["--svg", "x.svg"][..], &["--arith", "fixed"]] {
        fails(&[&["radiosity", "--scene", room][..], option].concat(), &[option[0], "2D scenes"]);
    }
    fails(&["radiosity", "--scene", room, "--matrix", "no-such.json", "--solver", "full"], &["no-such.json"]);
}
