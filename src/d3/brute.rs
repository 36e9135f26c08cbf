//! The brute-force ray–convex-polygon intersection: the 3D oracle every 3D tracer is checked
//! against, as `trace::brute` is for the 2D tracers.
//!
//! # The hit rule
//!
//! A ray `O + t·d` (`d` need not be unit; `t` is in units of `|d|`) hits polygon `P` when
//!
//! 1. it is not parallel to `P`'s plane: `d · n ≠ 0`;
//! 2. it meets the plane ahead of its origin: `t = (O_P − O) · n / (d · n) > 0` (strictly), where
//!    `O_P` is `P`'s centre;
//! 3. the meeting point `p` lies inside `P` or on its boundary, with a margin: for every edge
//!    `Vᵢ → Vᵢ₊₁`, the signed distance of `p` from the edge's line, in the plane, positive
//!    inside, is at least `−EDGE_MARGIN × size(P)`. The margin closes the cracks that rounding
//!    would open along an edge shared by two polygons, so a ray through a shared edge or corner
//!    of a closed surface hits at least one of them (a closed surface is watertight).
//!
//! Both sides block: a patch is opaque from behind too. The hit reports which side the ray
//! meets ([`Hit::front`]: `d · n < 0`, the ray arrives at the front side). The nearest hit of a
//! scene is the hit with the smallest `t`; of equal `t`, the polygon of lowest index. A polygon
//! can be skipped (the source patch a hemisphere leaves from).

use super::scene::{Polygon, Scene3};
use glam::DVec3;

/// The margin of the inside test, as a fraction of the polygon's size (see the module docs).
pub const EDGE_MARGIN: f64 = 1e-9;

/// A ray's hit: which polygon, how far, which side.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The index of the polygon hit.
    pub polygon: usize,
    /// The ray parameter of the hit point, `> 0`.
    pub t: f64,
    /// Whether the ray meets the polygon's front side.
    pub front: bool,
}

/// The ray parameter `t` at which `origin + t·direction` hits `polygon`, by the hit rule.
pub fn intersect(origin: DVec3, direction: DVec3, polygon: &Polygon) -> Option<f64> {
    let n = polygon.normal;
    let denom = direction.dot(n);
    if denom == 0.0 || !denom.is_finite() {
        return None;
    }
    let t = (polygon.centre - origin).dot(n) / denom;
    if !(t > 0.0 && t.is_finite()) {
        return None;
    }
    let p = origin + direction * t;
    let margin = -EDGE_MARGIN * polygon.size;
    let v = &polygon.vertices;
    for i in 0..v.len() {
        let a = v[i];
        let edge = v[(i + 1) % v.len()] - a;
        let distance = edge.cross(p - a).dot(n) / edge.length();
        if distance < margin {
            return None;
        }
    }
    Some(t)
}

/// The nearest hit of `origin + t·direction` in `scene`, skipping polygon `skip`, by brute force
/// over every polygon.
pub fn nearest(scene: &Scene3, origin: DVec3, direction: DVec3, skip: Option<usize>) -> Option<Hit> {
    let mut best: Option<Hit> = None;
    for (k, polygon) in scene.polygons.iter().enumerate() {
        if Some(k) == skip {
            continue;
        }
        if let Some(t) = intersect(origin, direction, polygon) {
            if best.is_none_or(|b| t < b.t) {
                best = Some(Hit { polygon: k, t, front: direction.dot(polygon.normal) < 0.0 });
            }
        }
    }
    best
}
