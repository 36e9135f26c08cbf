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

use super::grid::{CellBox, Grid3};
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
        loop {
            let coords = c.map(|v| v as u32);
            let cell = self.index(coords);
            let region = self.region_of(cell);
            let bx = match region {
                Some(r) => self.region(r),
                None => CellBox { lo: coords, hi: coords },
            };
            // The exit distance across the box's faces on each axis.
            let mut tf = [f64::INFINITY; 3];
            for k in 0..3 {
                let d = dir[k];
                if d > 0.0 {
                    tf[k] = (self.origin[k] + (bx.hi[k] + 1) as f64 * s - origin[k]) / d;
                } else if d < 0.0 {
                    tf[k] = (self.origin[k] + bx.lo[k] as f64 * s - origin[k]) / d;
                }
            }
            let t_min = tf[0].min(tf[1]).min(tf[2]);
            let t_exit = t_min.max(t);
            if !visit(Step3 { cell, coords, region, t_enter: t, t_exit }) {
                return;
            }
            if t_min == f64::INFINITY {
                return;
            }
            let q = origin + dir * t_exit;
            let mut next = [0i64; 3];
            for k in 0..3 {
                next[k] = if tf[k] == t_min {
                    if dir[k] > 0.0 {
                        bx.hi[k] as i64 + 1
                    } else {
                        bx.lo[k] as i64 - 1
                    }
                } else {
                    let v = self.coord(q[k], k).clamp(bx.lo[k] as i64, bx.hi[k] as i64);
                    if dir[k] >= 0.0 {
                        v.max(c[k])
                    } else {
                        v.min(c[k])
                    }
                };
                if next[k] < 0 || next[k] >= self.n[k] as i64 {
                    return;
                }
            }
            c = next;
            t = t_exit;
        }
    }
}
