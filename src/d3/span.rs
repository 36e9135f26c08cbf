//! The spanning angles of a polygon seen from a source: the box in Def. 2.5's angles (Θ, Φ) that
//! holds the direction of every point of the polygon, as the polar tracer needs it to match a
//! polygon with the rays that can hit it.
//!
//! The paper names this as the direct extension's difficulty: the extremes "do not necessarily
//! occur at vertices of a patch". Here they are computed exactly, for the source `O`, its unit
//! normal `n` and the frame `(t, b)` of [`super::scene::frame`], over a convex polygon given by
//! its vertices (the tracers pass the registration polygon, which holds every point the hit rule
//! accepts).
//!
//! * **Φ, the angle from the normal.** Along an edge `p(s) = a + s·e`, `s ∈ [0, 1]`, with `a`
//!   the edge's first vertex relative to `O`, `cos Φ(s) = (α + βs) / √(A + 2Bs + Cs²)` where
//!   `α = a·n`, `β = e·n`, `A = a·a`, `B = a·e`, `C = e·e`. Its derivative has the numerator
//!   `(βA − αB) + s(βB − αC)`, linear in `s`, so `Φ` has at most one critical point on the edge,
//!   `s* = (αB − βA) / (βB − αC)` ([`edge_critical_point`]), and its extremes on the edge are at
//!   the two vertices or at `s*` when it lies inside. Over the polygon's interior `Φ` has no
//!   maximum (it grows towards the plane's horizon) and its only minimum is `Φ = 0`, where the
//!   normal's line through `O` crosses the polygon ahead of `O` (and its only maximum is `Φ = π`,
//!   where the line crosses it behind `O`). So `Φ_max` is the largest of the vertices' and
//!   critical points' values unless the line meets the polygon behind the source, when it is π,
//!   and `Φ_min` is their smallest unless the line meets the polygon ahead, when it is 0.
//! * **Θ, the azimuth.** The projection of an edge onto the `(t, b)` plane is a segment, along
//!   which the azimuth is monotone unless the segment passes through the origin; so when the
//!   projected polygon keeps away from the origin (the normal's line misses the polygon) the
//!   extremes of `Θ` are at vertices, and the span is the shortest arc holding them (less than
//!   π). When the projection contains the origin or comes near it ([`AXIS_TOLERANCE`]), every
//!   azimuth is spanned.
//!
//! Both spans are widened by a bound on the rounding of the angles of the points hit
//! (coordinates rounded by `ε·scale`, seen from at least the polygon's distance), so the span
//! errs only on the large side.

use glam::{DVec2, DVec3};
use std::f64::consts::{PI, TAU};

/// The projected polygon counts as containing the normal's line when it comes within this
/// fraction of the coordinates' scale of it (the azimuth is ill-conditioned there).
pub const AXIS_TOLERANCE: f64 = 1e-7;

/// A polygon's spanning angles from a source.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Span3 {
    /// The azimuths `[lo, hi]` (`hi − lo < 2π`, `lo` in `[−π, π]`), or `None` for every azimuth.
    pub theta: Option<(f64, f64)>,
    /// The angles from the normal, `[lo, hi]`, `0 ≤ lo ≤ hi`.
    pub phi: (f64, f64),
    /// The distance from the source to the polygon (exact up to rounding).
    pub distance: f64,
}

/// The parameter `s* ∈ (0, 1)` of the critical point of `Φ` along the edge `a + s·e` (`a`
/// relative to the source, `n` the unit normal), if there is one (module docs).
pub fn edge_critical_point(a: DVec3, e: DVec3, n: DVec3) -> Option<f64> {
    let (alpha, beta) = (a.dot(n), e.dot(n));
    let (aa, b, c) = (a.dot(a), a.dot(e), e.dot(e));
    let den = beta * b - alpha * c;
    if den == 0.0 || !den.is_finite() {
        return None;
    }
    let s = (alpha * b - beta * aa) / den;
    (s > 0.0 && s < 1.0).then_some(s)
}

/// The angle `Φ` of `v` (relative to the source) from the normal `n`, by `atan2` (accurate at
/// every angle).
pub fn phi_of(v: DVec3, n: DVec3) -> f64 {
    let h = v.dot(n);
    (v - n * h).length().atan2(h)
}

/// The distance from `o` to the convex polygon `vertices` with unit normal `normal`.
pub fn distance_to_polygon(o: DVec3, vertices: &[DVec3], normal: DVec3) -> f64 {
    let k = vertices.len();
    let h = (o - vertices[0]).dot(normal);
    let foot = o - normal * h;
    let inside =
        (0..k).all(|i| (vertices[(i + 1) % k] - vertices[i]).cross(foot - vertices[i]).dot(normal) >= 0.0);
    if inside {
        return h.abs();
    }
    (0..k)
        .map(|i| {
            let (a, e) = (vertices[i], vertices[(i + 1) % k] - vertices[i]);
            let s = ((o - a).dot(e) / e.length_squared().max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
            (a + e * s - o).length()
        })
        .fold(f64::INFINITY, f64::min)
}

/// The spanning angles of the convex polygon `vertices` (unit normal `normal`) seen from `o`
/// with unit normal `n` and frame `(t, b)`, by the module docs' rules.
pub fn polygon_span(o: DVec3, n: DVec3, t: DVec3, b: DVec3, vertices: &[DVec3], normal: DVec3) -> Span3 {
    let k = vertices.len();
    let rel: Vec<DVec3> = vertices.iter().map(|v| *v - o).collect();
    let scale = vertices.iter().chain(std::iter::once(&o)).fold(1.0f64, |m, v| m.max(v.abs().max_element()));
    let distance = distance_to_polygon(o, vertices, normal);
    // The rounding of a hit point's angles, seen from at least the polygon's distance.
    let slack = |d: f64| 1e-12 + 256.0 * f64::EPSILON * scale / d.max(f64::MIN_POSITIVE);
    // Φ over the boundary: the vertices and the edges' critical points.
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for i in 0..k {
        let (a, e) = (rel[i], rel[(i + 1) % k] - rel[i]);
        let mut take = |v: DVec3| {
            let p = phi_of(v, n);
            lo = lo.min(p);
            hi = hi.max(p);
        };
        take(a);
        if let Some(s) = edge_critical_point(a, e, n) {
            take(a + e * s);
        }
    }
    // Θ: the projected polygon, and how near it comes to the normal's line.
    let q: Vec<DVec2> = rel.iter().map(|v| DVec2::new(v.dot(t), v.dot(b))).collect();
    let cross = |i: usize| {
        let (a, c) = (q[i], q[(i + 1) % k]);
        a.perp_dot(c)
    };
    let contains = (0..k).all(|i| cross(i) > 0.0) || (0..k).all(|i| cross(i) < 0.0);
    let near = (0..k)
        .map(|i| {
            let (a, e) = (q[i], q[(i + 1) % k] - q[i]);
            let s = (-a.dot(e) / e.length_squared().max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
            (a + e * s).length()
        })
        .fold(f64::INFINITY, f64::min);
    let theta = if contains || near <= AXIS_TOLERANCE * scale {
        // The normal's line meets the polygon (or nearly): every azimuth, and Φ from 0 where it
        // meets it ahead of the source, up to π where behind (either, where the line runs
        // along the polygon's plane).
        let along = n.dot(normal);
        let ahead = (vertices[0] - o).dot(normal) * along;
        if along == 0.0 || ahead >= 0.0 {
            lo = 0.0;
        }
        if along == 0.0 || ahead <= 0.0 {
            hi = PI;
        }
        None
    } else {
        let a0 = q[0].y.atan2(q[0].x);
        let (mut dlo, mut dhi) = (0.0f64, 0.0f64);
        for p in &q[1..] {
            let mut d = p.y.atan2(p.x) - a0;
            if d > PI {
                d -= TAU;
            } else if d < -PI {
                d += TAU;
            }
            dlo = dlo.min(d);
            dhi = dhi.max(d);
        }
        let e = slack(near);
        Some((a0 + dlo - e, a0 + dhi + e))
    };
    let e = slack(distance);
    Span3 { theta, phi: ((lo - e).max(0.0), hi + e), distance }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::d3::scene::frame;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// Dense sampling of Φ along random edges finds nothing beyond the vertices and the critical
    /// point, and the critical point's value is attained.
    #[test]
    fn the_critical_point_bounds_phi_along_an_edge_as_dense_sampling_finds() {
        let seed = 18u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut interior = 0;
        for case in 0..500 {
            let n = DVec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            )
            .normalize();
            let r = |rng: &mut ChaCha8Rng| {
                DVec3::new(
                    rng.random_range(-5.0..5.0),
                    rng.random_range(-5.0..5.0),
                    rng.random_range(-5.0..5.0),
                )
            };
            let (a, e) = (r(&mut rng), r(&mut rng));
            let mut lo = phi_of(a, n).min(phi_of(a + e, n));
            let mut hi = phi_of(a, n).max(phi_of(a + e, n));
            if let Some(s) = edge_critical_point(a, e, n) {
                interior += 1;
                let p = phi_of(a + e * s, n);
                lo = lo.min(p);
                hi = hi.max(p);
            }
            let (mut slo, mut shi) = (f64::INFINITY, f64::NEG_INFINITY);
            for i in 0..=20_000 {
                let p = phi_of(a + e * (i as f64 / 20_000.0), n);
                slo = slo.min(p);
                shi = shi.max(p);
            }
            assert!(
                lo <= slo + 1e-12 && hi >= shi - 1e-12,
                "seed {seed} case {case}: {lo} {hi} vs {slo} {shi}"
            );
            assert!(slo - lo < 1e-6 && hi - shi < 1e-6, "seed {seed} case {case}: not attained");
        }
        assert!(interior > 50, "seed {seed}: the cases must exercise interior critical points ({interior})");
    }

    /// The span holds the angles of dense samples of random polygons, and is tight.
    #[test]
    fn the_span_holds_every_sampled_point_of_a_polygon() {
        let seed = 19u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let o = DVec3::new(0.5, -0.25, 0.125);
        let n = DVec3::new(0.3, -0.2, 0.9).normalize();
        let (t, b) = frame(n);
        let mut full = 0;
        for case in 0..300 {
            let c = o + DVec3::new(
                rng.random_range(-4.0..4.0),
                rng.random_range(-4.0..4.0),
                rng.random_range(-1.0..4.0),
            );
            let u = DVec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            );
            let w = u.any_orthonormal_vector() * rng.random_range(0.2..3.0);
            let u = u.normalize() * rng.random_range(0.2..3.0);
            let verts = vec![c - u - w, c + u - w, c + u + w, c - u + w];
            let normal = (u.cross(w)).normalize();
            let span = polygon_span(o, n, t, b, &verts, normal);
            full += span.theta.is_none() as usize;
            let (mut plo, mut phi_hi) = (f64::INFINITY, f64::NEG_INFINITY);
            for i in 0..=60 {
                for j in 0..=60 {
                    let p = c + u * (2.0 * i as f64 / 60.0 - 1.0) + w * (2.0 * j as f64 / 60.0 - 1.0);
                    let v = p - o;
                    let ph = phi_of(v, n);
                    plo = plo.min(ph);
                    phi_hi = phi_hi.max(ph);
                    assert!(
                        ph >= span.phi.0 && ph <= span.phi.1,
                        "seed {seed} case {case}: Φ {ph} outside {:?}",
                        span.phi
                    );
                    if let Some((lo, hi)) = span.theta {
                        let th = v.dot(b).atan2(v.dot(t));
                        let inside = (0..3).any(|k| {
                            let x = th + (k as f64 - 1.0) * TAU;
                            x >= lo && x <= hi
                        });
                        assert!(inside, "seed {seed} case {case}: Θ {th} outside [{lo}, {hi}]");
                    }
                }
            }
            // Tight: the extremes are attained on the boundary (sampled densely), where the
            // normal's line misses the polygon.
            if span.theta.is_some() {
                let (mut blo, mut bhi) = (f64::INFINITY, f64::NEG_INFINITY);
                for e in 0..4 {
                    let (a, z) = (verts[e], verts[(e + 1) % 4]);
                    for i in 0..=20_000 {
                        let ph = phi_of(a + (z - a) * (i as f64 / 20_000.0) - o, n);
                        blo = blo.min(ph);
                        bhi = bhi.max(ph);
                    }
                }
                assert!(
                    plo >= blo - 1e-12 && phi_hi <= bhi + 1e-12,
                    "seed {seed} case {case}: interior extreme"
                );
                assert!(span.phi.1 - bhi < 1e-6, "seed {seed} case {case}: Φ max is loose");
                assert!(blo - span.phi.0 < 1e-6, "seed {seed} case {case}: Φ min is loose");
            }
        }
        assert!(full > 0 && full < 300, "seed {seed}: both kinds of span must occur ({full})");
    }
}
