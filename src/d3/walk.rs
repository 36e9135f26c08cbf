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
//!
//! [`Grid3::walker`] gives the same steps one by one ([`Walker::next`]), for a tracer that steps
//! the walk in its own loop; [`Grid3::walk`] calls a closure per step. A single cell's exit
//! distances along the axes the walk did not leave it by are kept from the cell before (the same
//! expression of the same values), so a step from a single cell divides once per axis it leaves by.

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
        if origin.cmpgt(lo).all() && origin.cmplt(hi).all() {
            // Inside (a tracer's source, nearly always): every axis's entry is negative, so the
            // loop below would give 0 too.
            return Some(0.0);
        }
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
    #[inline]
    pub fn walk(&self, origin: DVec3, dir: DVec3, mut visit: impl FnMut(Step3) -> bool) {
        let mut w = self.walker(origin, dir);
        while let Some(step) = w.next(self) {
            if !visit(step) {
                return;
            }
        }
    }

    /// The walk of [`Grid3::walk`] as a [`Walker`], whose steps the caller takes one by one.
    #[inline(always)]
    pub fn walker(&self, origin: DVec3, dir: DVec3) -> Walker {
        let n = self.n.map(|v| v as i64);
        let mut w = Walker {
            origin,
            dir,
            n,
            stride: [1, n[0], n[0] * n[1]],
            up: [dir.x > 0.0, dir.y > 0.0, dir.z > 0.0],
            c: [0; 3],
            cell: 0,
            t: 0.0,
            tf: [f64::INFINITY; 3],
            stale: true,
            last: None,
            done: true,
        };
        if !origin.is_finite() || !dir.is_finite() || dir == DVec3::ZERO {
            return w;
        }
        let Some(t) = self.entry(origin, dir) else {
            return w;
        };
        let p = origin + dir * t;
        for k in 0..3 {
            w.c[k] = self.coord(p[k], k).clamp(0, n[k] - 1);
        }
        w.cell = ((w.c[2] * n[1] + w.c[1]) * n[0] + w.c[0]) as usize;
        w.t = t;
        w.done = false;
        w
    }
}

/// A walk in progress ([`Grid3::walker`]): [`Walker::next`] gives the steps of [`Grid3::walk`]
/// one by one.
///
/// After a step from a single cell, the axes it did not leave by keep their cell, so their
/// exit distances (the same expression of the same values) carry over, and only the axes it
/// left by get theirs anew; after a macro-region every distance is computed afresh.
#[derive(Clone, Debug)]
pub struct Walker {
    origin: DVec3,
    dir: DVec3,
    n: [i64; 3],
    /// Per axis, the change of the cell index when the coordinate steps by one.
    stride: [i64; 3],
    /// Per axis, whether the walk leaves a box by its upper face.
    up: [bool; 3],
    /// The current cell, its index and its entry distance.
    c: [i64; 3],
    cell: usize,
    t: f64,
    /// The exit distance of the current box per axis, valid unless `stale`.
    tf: [f64; 3],
    stale: bool,
    /// The last step given: the box's region (if any) and its exit distance `t_min`, from which
    /// the next call moves on.
    last: Option<(Option<u32>, f64)>,
    done: bool,
}

impl Walker {
    /// The distance to the exit face of the box `lo..=hi` along axis `k`.
    #[inline(always)]
    fn face(&self, g: &Grid3, k: usize, lo: i64, hi: i64) -> f64 {
        let d = self.dir[k];
        if d > 0.0 {
            (g.origin[k] + (hi + 1) as f64 * g.cell_size - self.origin[k]) / d
        } else if d < 0.0 {
            (g.origin[k] + lo as f64 * g.cell_size - self.origin[k]) / d
        } else {
            f64::INFINITY
        }
    }

    /// The next step of the walk through `g` (the grid that made the walker), or `None` at its end.
    #[inline(always)]
    pub fn next(&mut self, g: &Grid3) -> Option<Step3> {
        if self.done {
            return None;
        }
        if let Some((region, t_min)) = self.last.take() {
            if !self.advance(g, region, t_min) {
                self.done = true;
                return None;
            }
        }
        let r = g.cell_region[self.cell];
        let coords = self.c.map(|v| v as u32);
        let region = (r != NO_REGION).then_some(r);
        match region {
            None => {
                if self.stale {
                    for k in 0..3 {
                        self.tf[k] = self.face(g, k, self.c[k], self.c[k]);
                    }
                    self.stale = false;
                }
            }
            Some(r) => {
                let bx = g.region(r);
                for k in 0..3 {
                    self.tf[k] = self.face(g, k, bx.lo[k] as i64, bx.hi[k] as i64);
                }
                self.stale = true;
            }
        }
        let t_min = self.tf[0].min(self.tf[1]).min(self.tf[2]);
        let t_exit = t_min.max(self.t);
        let step = Step3 { cell: self.cell, coords, region, t_enter: self.t, t_exit };
        if t_min == f64::INFINITY {
            self.done = true;
        } else {
            self.last = Some((region, t_min));
        }
        Some(step)
    }

    /// Moves from the box of the last step (`region`, exit distance `t_min`) to the next;
    /// `false` when the walk leaves the grid.
    #[inline(always)]
    fn advance(&mut self, g: &Grid3, region: Option<u32>, t_min: f64) -> bool {
        let t_exit = t_min.max(self.t);
        match region {
            None => {
                // A single cell: the axes whose face is the exit step out; the others keep
                // their coordinate (the exit point's clamped into the cell is the cell's).
                let mut left = [false; 3];
                for k in 0..3 {
                    left[k] = self.tf[k] == t_min;
                    if left[k] {
                        let s = if self.up[k] { 1 } else { -1 };
                        self.c[k] += s;
                        if self.c[k] < 0 || self.c[k] >= self.n[k] {
                            return false;
                        }
                        self.cell = self.cell.wrapping_add_signed((s * self.stride[k]) as isize);
                    }
                }
                for k in 0..3 {
                    if left[k] {
                        self.tf[k] = self.face(g, k, self.c[k], self.c[k]);
                    }
                }
            }
            Some(r) => {
                // The exit point's cell, clamped into the box and never moving backwards, on
                // the axes the exit face is not on.
                let bx = g.region(r);
                let q = self.origin + self.dir * t_exit;
                for k in 0..3 {
                    let (lo, hi) = (bx.lo[k] as i64, bx.hi[k] as i64);
                    self.c[k] = if self.tf[k] == t_min {
                        if self.up[k] {
                            hi + 1
                        } else {
                            lo - 1
                        }
                    } else {
                        let v = g.coord(q[k], k).clamp(lo, hi);
                        if self.dir[k] >= 0.0 {
                            v.max(self.c[k])
                        } else {
                            v.min(self.c[k])
                        }
                    };
                    if self.c[k] < 0 || self.c[k] >= self.n[k] {
                        return false;
                    }
                }
                self.cell = ((self.c[2] * self.n[1] + self.c[1]) * self.n[0] + self.c[0]) as usize;
            }
        }
        self.t = t_exit;
        true
    }
}
