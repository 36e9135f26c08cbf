//! The traversal of the 3D grid ([`Grid3`], built in [`super::grid`]): Amanatides–Woo 3D-DDA
//! in which an empty cell's whole macro-region is crossed in one step.
//!
//! The next cell is taken from the exit face of the current box (every axis whose face distance
//! equals the exit distance steps out of the box) and, along the other axes, from the exit
//! point's cell coordinate clamped into the box and never moving against the direction of
//! travel. So rounding can never send the walk backwards or into a loop: every step leaves its
//! box on at least one axis, monotonically, and a walk takes at most `nx + ny + nz` steps.
//! Distances `t` are in units of the direction's length, as in the hit rule of
//! [`super::brute`]. Counters: the tracers count one `cells_traversed` per [`Step3`].

use super::grid::{Grid3, NO_REGION};
use glam::DVec3;

/// One step of a walk: the cell entered, the macro-region crossed when it is empty, and the ray's
/// distances on entering and leaving it (the region, for an empty cell).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Step3 {
    /// The index of the cell entered.
    pub cell: usize,
    /// Its coordinates.
    pub coords: [u32; 3],
    /// The macro-region crossed, when the cell is empty.
    pub region: Option<u32>,
    pub t_enter: f64,
    pub t_exit: f64,
}

impl Grid3 {
    /// The ray parameter where `origin + t·dir`, `t ≥ 0`, enters the grid's box, if it does.
    fn entry(&self, origin: DVec3, dir: DVec3) -> Option<f64> {
        let (lo, hi) = self.extent();
        let mut t0: f64 = 0.0;
        let mut t1 = f64::INFINITY;
        for k in 0..3 {
            let (o, d) = (origin[k], dir[k]);
            if d == 0.0 {
                if o < lo[k] || o >= hi[k] {
                    return None;
                }
            } else {
                let (a, b) = ((lo[k] - o) / d, (hi[k] - o) / d);
                t0 = t0.max(a.min(b));
                t1 = t1.min(a.max(b));
            }
        }
        (t0 <= t1).then_some(t0)
    }

    /// Walks the ray `origin + t·dir`, `t ≥ 0`, through the grid, calling `visit` for each step
    /// (a non-empty cell, or an empty cell's whole macro-region), in order along the ray.
    /// `visit` returns `false` to stop. A ray with a non-finite or zero direction, or a
    /// non-finite origin, visits nothing.
    #[inline(always)]
    pub fn walk(&self, origin: DVec3, dir: DVec3, mut visit: impl FnMut(Step3) -> bool) {
        if !origin.is_finite() || !dir.is_finite() || dir == DVec3::ZERO {
            return;
        }
        let Some(mut t) = self.entry(origin, dir) else {
            return;
        };
        let p = origin + dir * t;
        let mut c = [0i64; 3];
        for k in 0..3 {
            c[k] = self.coord(p[k], k).clamp(0, self.n[k] as i64 - 1);
        }
        let s = self.cell_size;
        let n = self.n.map(|v| v as i64);
        // Per axis: the step of the coordinate and of the cell index when the walk leaves a
        // cell along it, and which face it leaves by (+1 for the upper).
        let stride = [1, n[0], n[0] * n[1]];
        let up = [dir.x > 0.0, dir.y > 0.0, dir.z > 0.0];
        let sign = up.map(|u| if u { 1i64 } else { -1 });
        // The distance to the exit face of the box `lo..=hi` along axis `k`.
        let face = |k: usize, lo: i64, hi: i64| -> f64 {
            let d = dir[k];
            if d > 0.0 {
                (self.origin[k] + (hi + 1) as f64 * s - origin[k]) / d
            } else if d < 0.0 {
                (self.origin[k] + lo as f64 * s - origin[k]) / d
            } else {
                f64::INFINITY
            }
        };
        // `tf[k]` is the exit distance of the current box along axis `k` when `known[k]`: after
        // a step from a single cell, the axes it did not leave by keep their cell, so their
        // faces and distances (the same expression of the same values) carry over.
        let mut tf = [f64::INFINITY; 3];
        let mut known = [false; 3];
        let mut cell = ((c[2] * n[1] + c[1]) * n[0] + c[0]) as usize;
        loop {
            let r = self.cell_region[cell];
            let coords = c.map(|v| v as u32);
            if r == NO_REGION {
                // A single cell: the axes whose face is the exit step out; the others keep
                // their coordinate (the exit point's clamped into the cell is the cell's).
                for k in 0..3 {
                    if !known[k] {
                        tf[k] = face(k, c[k], c[k]);
                    }
                }
                let t_min = tf[0].min(tf[1]).min(tf[2]);
                let t_exit = t_min.max(t);
                if !visit(Step3 { cell, coords, region: None, t_enter: t, t_exit }) || t_min == f64::INFINITY {
                    return;
                }
                for k in 0..3 {
                    known[k] = tf[k] != t_min;
                    if !known[k] {
                        c[k] += sign[k];
                        if c[k] < 0 || c[k] >= n[k] {
                            return;
                        }
                        cell = cell.wrapping_add_signed((sign[k] * stride[k]) as isize);
                    }
                }
                t = t_exit;
                continue;
            }
            let bx = self.region(r);
            let (lo, hi) = (bx.lo.map(i64::from), bx.hi.map(i64::from));
            for k in 0..3 {
                tf[k] = face(k, lo[k], hi[k]);
            }
            let t_min = tf[0].min(tf[1]).min(tf[2]);
            let t_exit = t_min.max(t);
            if !visit(Step3 { cell, coords, region: Some(r), t_enter: t, t_exit }) || t_min == f64::INFINITY {
                return;
            }
            // The exit point's cell, clamped into the box and never moving backwards, on the
            // axes the exit face is not on.
            let q = origin + dir * t_exit;
            for k in 0..3 {
                c[k] = if tf[k] == t_min {
                    if up[k] {
                        hi[k] + 1
                    } else {
                        lo[k] - 1
                    }
                } else {
                    let v = self.coord(q[k], k).clamp(lo[k], hi[k]);
                    if dir[k] >= 0.0 {
                        v.max(c[k])
                    } else {
                        v.min(c[k])
                    }
                };
                if c[k] < 0 || c[k] >= n[k] {
                    return;
                }
            }
            cell = ((c[2] * n[1] + c[1]) * n[0] + c[0]) as usize;
            known = [false; 3];
            t = t_exit;
        }
    }
}
