//! Closed-form 3D form factors (Howell's catalogue; REFERENCES.md) and the scenes they hold
//! for, shared by `tests/ff3d.rs` (tier 1) and `tests/tier2/ff3d.rs`.

use glam::DVec3;
use shelling::d3::scene::{Material3, Polygon, Scene3};
use std::f64::consts::PI;

/// Howell C-11: parallel, directly opposed rectangles `a × b` at distance `c`.
pub fn c11(a: f64, b: f64, c: f64) -> f64 {
    let (x, y) = (a / c, b / c);
    let (x2, y2) = (x * x, y * y);
    2.0 / (PI * x * y)
        * (((1.0 + x2) * (1.0 + y2) / (1.0 + x2 + y2)).sqrt().ln()
            + x * (1.0 + y2).sqrt() * (x / (1.0 + y2).sqrt()).atan()
            + y * (1.0 + x2).sqrt() * (y / (1.0 + x2).sqrt()).atan()
            - x * x.atan()
            - y * y.atan())
}

/// Howell C-14: from a rectangle of width `w` to a perpendicular one of height `h`, sharing an
/// edge of length `l`.
pub fn c14(w: f64, h: f64, l: f64) -> f64 {
    let (w, h) = (w / l, h / l);
    let (w2, h2) = (w * w, h * h);
    let s = (h2 + w2).sqrt();
    let log = ((1.0 + w2) * (1.0 + h2) / (1.0 + w2 + h2)).ln()
        + w2 * (w2 * (1.0 + w2 + h2) / ((1.0 + w2) * (w2 + h2))).ln()
        + h2 * (h2 * (1.0 + w2 + h2) / ((1.0 + h2) * (w2 + h2))).ln();
    1.0 / (PI * w) * (w * (1.0 / w).atan() + h * (1.0 / h).atan() - s * (1.0 / s).atan() + 0.25 * log)
}

/// Coaxial parallel discs: from the disc of radius `r1` to the disc of radius `r2` at distance
/// `a`.
pub fn discs(r1: f64, r2: f64, a: f64) -> f64 {
    let (r1, r2) = (r1 / a, r2 / a);
    let x = 1.0 + (1.0 + r2 * r2) / (r1 * r1);
    0.5 * (x - (x * x - 4.0 * (r2 / r1).powi(2)).sqrt())
}

/// A scene of `polygons`, every one of a grey material.
pub fn scene(polygons: Vec<Vec<DVec3>>) -> Scene3 {
    let m = Material3::grey("grey", 0.5, 0.0);
    Scene3 {
        polygons: polygons.into_iter().map(|v| Polygon::new(v).unwrap().with_material(0, &m)).collect(),
        materials: vec![m],
    }
}

/// C-11's scene: polygon 0 the rectangle `[0, a] × [0, b]` at `z = 0` facing +z, polygon 1 the
/// same at `z = c` facing −z.
pub fn opposed(a: f64, b: f64, c: f64) -> Scene3 {
    let lower = vec![DVec3::ZERO, DVec3::new(a, 0.0, 0.0), DVec3::new(a, b, 0.0), DVec3::new(0.0, b, 0.0)];
    let upper = lower.iter().rev().map(|v| *v + DVec3::new(0.0, 0.0, c)).collect();
    scene(vec![lower, upper])
}

/// C-14's scene: polygon 0 the rectangle `x ∈ [0, w]`, `y ∈ [0, l]` at `z = 0` facing +z,
/// polygon 1 the rectangle `z ∈ [0, h]`, `y ∈ [0, l]` at `x = 0` facing +x; they share the
/// edge `x = z = 0`.
pub fn perpendicular(w: f64, h: f64, l: f64) -> Scene3 {
    let floor = vec![DVec3::ZERO, DVec3::new(w, 0.0, 0.0), DVec3::new(w, l, 0.0), DVec3::new(0.0, l, 0.0)];
    let wall = vec![DVec3::ZERO, DVec3::new(0.0, l, 0.0), DVec3::new(0.0, l, h), DVec3::new(0.0, 0.0, h)];
    scene(vec![floor, wall])
}

/// The unit cube's six faces facing in: −x, +x, −y, +y, −z, +z (polygon `2·axis + side`).
pub fn cube() -> Scene3 {
    let mut faces = Vec::new();
    for axis in 0..3 {
        for side in 0..2 {
            let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
            let corner = |a: f64, b: f64| {
                let mut p = [0.0; 3];
                p[axis] = side as f64;
                p[u] = a;
                p[v] = b;
                DVec3::from_array(p)
            };
            // Counter-clockwise seen from inside: u then v for the face at 0, reversed at 1.
            let mut f = vec![corner(0.0, 0.0), corner(1.0, 0.0), corner(1.0, 1.0), corner(0.0, 1.0)];
            if side == 1 {
                f.reverse();
            }
            faces.push(f);
        }
    }
    scene(faces)
}

/// Two coaxial regular `n`-gons inscribed in circles of radii `r1` (at `z = 0`, facing +z) and
/// `r2` (at `z = a`, facing −z), with vertices at the same angles.
pub fn polygon_discs(r1: f64, r2: f64, a: f64, n: usize) -> Scene3 {
    let ring = |r: f64, z: f64| -> Vec<DVec3> {
        (0..n)
            .map(|k| {
                let t = 2.0 * PI * k as f64 / n as f64;
                DVec3::new(r * t.cos(), r * t.sin(), z)
            })
            .collect()
    };
    let upper = ring(r2, a).into_iter().rev().collect();
    scene(vec![ring(r1, 0.0), upper])
}

/// The exact form factor between [`polygon_discs`]' two inscribed `n`-gons lies in this
/// interval: the unoccluded `A₁F₁₂ = ∫∫ cos cos / (π r²)` grows with either surface, each
/// `n`-gon contains its incircle (radius `r·cos(π/n)`) and lies in its circumcircle, so
/// `A_disc(r₁cos)·F(r₁cos, r₂cos) ≤ A_poly·F_poly ≤ A_disc(r₁)·F(r₁, r₂)`.
pub fn polygon_discs_bracket(r1: f64, r2: f64, a: f64, n: usize) -> (f64, f64) {
    let c = (PI / n as f64).cos();
    let poly_area = 0.5 * n as f64 * r1 * r1 * (2.0 * PI / n as f64).sin();
    let g = |s: f64| PI * (s * r1).powi(2) * discs(s * r1, s * r2, a);
    (g(c) / poly_area, g(1.0) / poly_area)
}

/// The Cornell box shipped in `scenes/`.
pub fn cornell() -> Scene3 {
    shelling::d3::obj::load(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cornell_box.obj"))
        .unwrap()
}

/// The relative error of `estimate` against `exact`.
pub fn rel(estimate: f64, exact: f64) -> f64 {
    (estimate - exact).abs() / exact
}
