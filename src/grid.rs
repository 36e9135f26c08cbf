//! The underlying structure: a uniform grid with macro-regions (Devillers 1989), the paper's
//! Section 3.1 "preprocessing".
//!
//! # Construction
//!
//! * **Resolution rule.** Square cells, sized so that the grid has about `λ·N` cells for `N`
//!   segments (`λ` = [`GridParams::cells_per_segment`], default 4): cell side
//!   `s = sqrt(area / (λ·N))`, `nx = ceil(width / s)`, `ny = ceil(height / s)`, each clamped to
//!   `1..=`[`MAX_CELLS_PER_AXIS`], and coarsened where they would make more than
//!   [`MAX_GRID_CELLS`] (2²²) cells. For the paper's workload (1000 segments in 1024²) that is a
//!   64 × 64 grid of 16-unit cells. [`GridParams::cells_per_axis`] overrides the rule.
//! * **Bounds.** The scene's world when it declares one, else the bounding box of its segments,
//!   padded by 0.1 % of its larger side so no segment lies on the outer boundary.
//! * **Registration is conservative.** A segment is registered in every cell whose box, grown by
//!   `eps` (10⁻⁹ of the grid's larger side) on every side, meets the segment. Rounding in the
//!   traversal is far smaller than `eps`, so a ray that truly meets a segment always visits a
//!   cell that lists it (this is what makes every tracer agree with brute force).
//! * **Macro-regions.** Every empty cell gets an axis-aligned rectangle of empty cells that
//!   contains it, grown from the cell itself: extend by one column or row towards −x, +x, −y,
//!   +y in turn, each step only if the whole new column or row is empty (a summed-area table
//!   answers that in O(1)), until no side can grow. Identical rectangles are shared, so a
//!   region has an id. Devillers' own rule is not known here; this one gives every empty cell a
//!   locally maximal box.
//!
//! # Traversal
//!
//! [`Grid::walk`] is Amanatides–Woo stepping where every empty cell is replaced by its
//! macro-region: the ray jumps to the region's exit face in one step. The next cell is taken from
//! the exit face (axis and side) and the exit point's coordinate along the face, clamped into the
//! region and kept monotone in the direction of travel, so rounding can never send the walk
//! backwards or into a loop. [`Grid::raster_convex`] lists the cells that a convex polygon
//! meets (row by row, conservatively); the shelling tracers use it (as [`Grid::raster_convex_n`],
//! the same arithmetic for a fixed vertex count) to find the cells of a shell, reading each cell
//! from a one-entry scan table ([`Grid::scan_cell`]). The rasteriser's cell coordinates
//! `⌊(v − origin) / side⌋` are taken by multiplying with the reciprocal and fall back to the
//! division wherever the two could differ (a quotient within a few ulps of an integer), so they
//! are always the division's. It takes the rows four at a time: on CPUs with AVX the four rows'
//! extents and cell ranges are computed in the lanes of vectors, each lane by the scalar
//! body's operations (`Grid::spans_avx`), so the cells are the same on every CPU.

use crate::geom::{Segment, Vec2};
use crate::scene::Bounds;

pub use crate::limits::MAX_GRID_CELLS;

/// The most cells along one axis the resolution rule will choose.
pub const MAX_CELLS_PER_AXIS: usize = 4096;

/// Marks a non-empty cell in the per-cell region table.
const NO_REGION: u32 = u32::MAX;

/// Parameters of the grid's resolution rule.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridParams {
    /// Target number of cells per segment (`λ`).
    pub cells_per_segment: f64,
    /// Explicit resolution along the larger axis; overrides `cells_per_segment`.
    pub cells_per_axis: Option<usize>,
}

impl Default for GridParams {
    fn default() -> Self {
        GridParams { cells_per_segment: 4.0, cells_per_axis: None }
    }
}

/// An inclusive rectangle of cell indices.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CellRect {
    pub x0: u32,
    pub y0: u32,
    pub x1: u32,
    pub y1: u32,
}

/// One step of a ray walk: the cell entered (or the macro-region jumped across) and the ray's
/// distances on entering and leaving it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Step {
    /// The cell the ray entered this step.
    pub cell: usize,
    /// The macro-region crossed, when the cell is empty.
    pub region: Option<u32>,
    pub t_enter: f64,
    pub t_exit: f64,
}

/// A uniform grid of square cells over the scene, each listing the segments that meet it.
#[derive(Clone, Debug)]
pub struct Grid {
    /// Lower-left corner of cell (0, 0).
    pub origin: Vec2,
    /// Side of a cell.
    pub cell_size: f64,
    pub nx: usize,
    pub ny: usize,
    /// Registration margin: cells are grown by this much when segments are registered.
    pub eps: f64,
    /// Segment lists of the cells in compressed-row form: cell `c` holds
    /// `items[offsets[c]..offsets[c + 1]]`.
    offsets: Vec<u32>,
    items: Vec<u32>,
    /// Macro-region id of each empty cell, `NO_REGION` for a non-empty one.
    cell_region: Vec<u32>,
    regions: Vec<CellRect>,
    /// Per cell, what a row scan needs in one 8-byte load ([`Grid::scan_cell`]): `[start, end]`
    /// of its segment list for a non-empty cell, `[region | EMPTY, x1 of the region]` for an
    /// empty one.
    scan: Vec<[u32; 2]>,
    /// Per segment, whether it is registered in more than one cell; and per cell, the list of
    /// its segments that are, in compressed-row form like `items` ([`Grid::cell_shared_items`]).
    segment_shared: Vec<bool>,
    shared_offsets: Vec<u32>,
    shared_items: Vec<u32>,
}

/// One cell as a row scan sees it ([`Grid::scan_cell`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CellScan<'a> {
    /// An empty cell: its macro-region, and the region's last column (where a scan along the
    /// row resumes after jumping across the region).
    Empty { region: u32, x1: u32 },
    /// A non-empty cell: the segments registered in it.
    Items(&'a [u32]),
}

/// Marks an empty cell's entry in [`Grid::scan`].
const EMPTY: u32 = 1 << 31;

/// The stopping margin of every tracer, in units of the registration margin [`Grid::eps`]:
/// see [`Grid::stop_margin`].
pub const STOP_MARGIN_EPS: f64 = 4.0;

impl Grid {
    /// The stopping margin, `4·eps`: how far every stopping rule keeps from the boundary it
    /// stops at. The conventional walk stops only at a cell whose exit lies beyond the nearest
    /// hit by more than this; a shell retires only rays whose hit lies before its outer radius
    /// less this; a shell's trapezoid reaches this much inside and beyond its radii, and a
    /// patch's nearest distance is taken this much nearer. A hit's distance and a cell's exit
    /// or a shell's radius are rounded apart, each by far less than `eps` (the module doc), and
    /// segments are registered in cells grown by `eps`: a margin of several `eps` covers both
    /// roundings and the registration together, so a hit within rounding of a boundary is never
    /// decided before every patch that might tie with it or lie nearer has been tested. That is
    /// why a tracer that tests a superset of the pairs that matter returns exactly the
    /// brute-force hits (ARCHITECTURE.md).
    #[inline]
    pub fn stop_margin(&self) -> f64 {
        STOP_MARGIN_EPS * self.eps
    }

    /// Builds the grid over `bounds` (see the module doc for the rules) and registers `segments`.
    pub fn build(segments: &[Segment], bounds: Bounds, params: GridParams) -> Grid {
        let (origin, cell_size, nx, ny) = Self::layout(segments.len(), bounds, params);
        let extent = (nx as f64 * cell_size).max(ny as f64 * cell_size);
        let mut grid = Grid {
            origin,
            cell_size,
            nx,
            ny,
            eps: extent * 1e-9,
            offsets: Vec::new(),
            items: Vec::new(),
            cell_region: Vec::new(),
            regions: Vec::new(),
            scan: Vec::new(),
            segment_shared: Vec::new(),
            shared_offsets: Vec::new(),
            shared_items: Vec::new(),
        };
        grid.register(segments);
        grid.build_macro_regions();
        grid.build_scan();
        grid
    }

    /// Chooses origin, cell size and resolution for `n` segments over `bounds`.
    fn layout(n: usize, bounds: Bounds, params: GridParams) -> (Vec2, f64, usize, usize) {
        let size = bounds.max - bounds.min;
        let pad = size.x.max(size.y) * 1e-3;
        let min = bounds.min - Vec2::splat(pad);
        let size = size + Vec2::splat(2.0 * pad);
        let cell = match params.cells_per_axis {
            Some(k) => size.x.max(size.y) / k.clamp(1, MAX_CELLS_PER_AXIS) as f64,
            None => {
                let cells = (params.cells_per_segment * n.max(1) as f64).max(1.0);
                let s = (size.x * size.y / cells).sqrt();
                // Keep within the per-axis limit for very elongated or very dense scenes.
                s.max(size.x.max(size.y) / MAX_CELLS_PER_AXIS as f64)
            }
        };
        let count = |cell: f64, len: f64| ((len / cell).ceil() as usize).clamp(1, MAX_CELLS_PER_AXIS);
        // At most MAX_GRID_CELLS cells: a finer request is coarsened (the CLI refuses it first).
        let mut cell = cell;
        while count(cell, size.x) * count(cell, size.y) > MAX_GRID_CELLS {
            cell *= 1.0 + 1.0 / 1024.0;
        }
        (min, cell, count(cell, size.x), count(cell, size.y))
    }

    /// Number of cells.
    pub fn len(&self) -> usize {
        self.nx * self.ny
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The world-space corners of the grid.
    pub fn extent(&self) -> (Vec2, Vec2) {
        let max = self.origin + Vec2::new(self.nx as f64, self.ny as f64) * self.cell_size;
        (self.origin, max)
    }

    /// The segments registered in cell `c`.
    #[inline]
    pub fn cell_items(&self, c: usize) -> &[u32] {
        &self.items[self.offsets[c] as usize..self.offsets[c + 1] as usize]
    }

    /// Whether segment `i` is registered in more than one cell. A ray's walk enters each cell at
    /// most once, so it meets a segment that is not (a private one) once: a tracer needs a
    /// per-ray mailbox only for the shared ones.
    #[inline]
    pub fn is_shared(&self, i: u32) -> bool {
        self.segment_shared[i as usize]
    }

    /// The segments of cell `c` registered in other cells too ([`Grid::is_shared`]), in the
    /// order of [`Grid::cell_items`].
    #[inline]
    pub fn cell_shared_items(&self, c: usize) -> &[u32] {
        &self.shared_items[self.shared_offsets[c] as usize..self.shared_offsets[c + 1] as usize]
    }

    /// The macro-region of cell `c`, or `None` when the cell holds segments.
    #[inline]
    pub fn region_of(&self, c: usize) -> Option<u32> {
        let r = self.cell_region[c];
        (r != NO_REGION).then_some(r)
    }

    /// Cell `c` as a row scan needs it: the same information as [`Grid::region_of`],
    /// [`Grid::region`] (its `x1`) and [`Grid::cell_items`], from one entry.
    #[inline]
    pub fn scan_cell(&self, c: usize) -> CellScan<'_> {
        let [a, b] = self.scan[c];
        if a & EMPTY != 0 {
            CellScan::Empty { region: a & !EMPTY, x1: b }
        } else {
            CellScan::Items(&self.items[a as usize..b as usize])
        }
    }

    /// The rectangle of macro-region `r`.
    pub fn region(&self, r: u32) -> CellRect {
        self.regions[r as usize]
    }

    /// Number of distinct macro-regions.
    pub fn region_count(&self) -> usize {
        self.regions.len()
    }

    #[inline]
    fn index(&self, ix: usize, iy: usize) -> usize {
        iy * self.nx + ix
    }

    /// Cell coordinate (possibly outside the grid) of a world coordinate along one axis,
    /// `floor((v − origin) / cell_size)`, given `inv = 1 / cell_size`: the quotient is taken by
    /// multiplying, which has the same floor unless it lies within a few ulps of an integer;
    /// there (and for non-finite or huge values) the division decides, so the answer is always
    /// the division's.
    #[inline(always)]
    fn coord_by(&self, v: f64, origin: f64, inv: f64) -> i64 {
        let x = v - origin;
        let q = x * inv;
        let k = floor_i64(q);
        let f = q - k as f64;
        let tol = 1e-9 * q.abs().max(1.0);
        if f > tol && f < 1.0 - tol {
            k
        } else {
            floor_i64(x / self.cell_size)
        }
    }

    fn register(&mut self, segments: &[Segment]) {
        let mut counts = vec![0u32; self.len() + 1];
        for s in segments {
            self.raster_convex(&[s.a, s.b], |iy, x0, x1| {
                for ix in x0..=x1 {
                    counts[iy * self.nx + ix] += 1;
                }
            });
        }
        // Exclusive prefix sum into offsets; reuse counts as write cursors.
        let mut offsets = vec![0u32; self.len() + 1];
        for c in 0..self.len() {
            offsets[c + 1] = offsets[c] + counts[c];
        }
        let mut cursor = offsets.clone();
        let mut items = vec![0u32; offsets[self.len()] as usize];
        for (i, s) in segments.iter().enumerate() {
            self.raster_convex(&[s.a, s.b], |iy, x0, x1| {
                for ix in x0..=x1 {
                    let c = iy * self.nx + ix;
                    items[cursor[c] as usize] = i as u32;
                    cursor[c] += 1;
                }
            });
        }
        // A segment registered in one cell only is private to it.
        let mut cells_of = vec![0u32; segments.len()];
        for &i in &items {
            cells_of[i as usize] += 1;
        }
        self.segment_shared = cells_of.iter().map(|&n| n > 1).collect();
        self.shared_offsets = Vec::with_capacity(self.len() + 1);
        self.shared_offsets.push(0);
        for c in 0..self.len() {
            let cell = &items[offsets[c] as usize..offsets[c + 1] as usize];
            self.shared_items.extend(cell.iter().filter(|&&i| self.segment_shared[i as usize]));
            self.shared_offsets.push(self.shared_items.len() as u32);
        }
        self.offsets = offsets;
        self.items = items;
    }

    fn build_scan(&mut self) {
        assert!(
            self.items.len() < EMPTY as usize && self.regions.len() < EMPTY as usize,
            "too many registrations for the grid's scan table"
        );
        self.scan = (0..self.len())
            .map(|c| match self.region_of(c) {
                Some(r) => [r | EMPTY, self.regions[r as usize].x1],
                None => [self.offsets[c], self.offsets[c + 1]],
            })
            .collect();
    }

    fn build_macro_regions(&mut self) {
        let (nx, ny) = (self.nx, self.ny);
        // Summed-area table of non-empty cells: sat[(y)*(nx+1)+x] counts cells in [0,x)×[0,y).
        let w = nx + 1;
        let mut sat = vec![0u32; w * (ny + 1)];
        for y in 0..ny {
            for x in 0..nx {
                let full = (self.offsets[self.index(x, y) + 1] > self.offsets[self.index(x, y)]) as u32;
                sat[(y + 1) * w + x + 1] = full + sat[y * w + x + 1] + sat[(y + 1) * w + x] - sat[y * w + x];
            }
        }
        let occupied = |x0: usize, y0: usize, x1: usize, y1: usize| -> bool {
            // Inclusive rectangle [x0,x1]×[y0,y1].
            sat[(y1 + 1) * w + x1 + 1] + sat[y0 * w + x0] > sat[y0 * w + x1 + 1] + sat[(y1 + 1) * w + x0]
        };
        let mut ids = std::collections::HashMap::new();
        self.cell_region = vec![NO_REGION; nx * ny];
        for y in 0..ny {
            for x in 0..nx {
                if occupied(x, y, x, y) {
                    continue;
                }
                let (mut x0, mut y0, mut x1, mut y1) = (x, y, x, y);
                loop {
                    let mut grew = false;
                    if x0 > 0 && !occupied(x0 - 1, y0, x0 - 1, y1) {
                        x0 -= 1;
                        grew = true;
                    }
                    if x1 + 1 < nx && !occupied(x1 + 1, y0, x1 + 1, y1) {
                        x1 += 1;
                        grew = true;
                    }
                    if y0 > 0 && !occupied(x0, y0 - 1, x1, y0 - 1) {
                        y0 -= 1;
                        grew = true;
                    }
                    if y1 + 1 < ny && !occupied(x0, y1 + 1, x1, y1 + 1) {
                        y1 += 1;
                        grew = true;
                    }
                    if !grew {
                        break;
                    }
                }
                let rect = CellRect { x0: x0 as u32, y0: y0 as u32, x1: x1 as u32, y1: y1 as u32 };
                let next = self.regions.len() as u32;
                let id = *ids.entry(rect).or_insert(next);
                if id == next {
                    self.regions.push(rect);
                }
                self.cell_region[y * nx + x] = id;
            }
        }
    }

    /// Calls `row(iy, ix0, ix1)` for every row of cells that the convex polygon `poly` (given by
    /// its vertices in order, at most 8; two vertices make a segment, one a point) meets, with the
    /// inclusive range of cells it meets in that row. Conservative: cells are grown by `eps`.
    pub fn raster_convex(&self, poly: &[Vec2], row: impl FnMut(usize, usize, usize)) {
        assert!(poly.len() <= 8, "raster_convex takes at most 8 vertices, got {}", poly.len());
        let mut edges = [Edge::default(); 8];
        for (i, e) in edges.iter_mut().enumerate().take(poly.len()) {
            *e = Edge::new(poly[i], poly[(i + 1) % poly.len()]);
        }
        self.raster_edges(&edges[..poly.len()], row);
    }

    /// [`Grid::raster_convex`] for a polygon of exactly `N` vertices: the same cells, computed by
    /// the same arithmetic, with the edge loop unrolled (the shelling tracers raster a
    /// quadrilateral per shell).
    #[inline]
    pub fn raster_convex_n<const N: usize>(&self, poly: &[Vec2; N], row: impl FnMut(usize, usize, usize)) {
        const { assert!(N >= 1 && N <= 8, "raster_convex_n takes 1 to 8 vertices") };
        let edges: [Edge; N] = std::array::from_fn(|i| Edge::new(poly[i], poly[(i + 1) % N]));
        self.raster_edges(&edges, row);
    }

    /// The body of the rasterisers: rows of the polygon bounded by `edges`, four at a time
    /// ([`Grid::spans`], or [`Grid::spans_avx`] on CPUs with AVX: the same cells).
    #[inline(always)]
    fn raster_edges(&self, edges: &[Edge], mut row: impl FnMut(usize, usize, usize)) {
        let inv = 1.0 / self.cell_size;
        let (mut ymin, mut ymax) = (f64::INFINITY, f64::NEG_INFINITY);
        for e in edges {
            ymin = min_of(e.y0, ymin);
            ymax = max_of(e.y1, ymax);
        }
        let (oy, eps) = (self.origin.y, self.eps);
        let iy0 = self.coord_by(ymin - eps, oy, inv).max(0);
        let iy1 = self.coord_by(ymax + eps, oy, inv).min(self.ny as i64 - 1);
        #[cfg(target_arch = "x86_64")]
        let avx = std::is_x86_feature_detected!("avx");
        let mut iy = iy0;
        while iy <= iy1 {
            let n = (iy1 - iy + 1).min(4) as usize;
            #[cfg(target_arch = "x86_64")]
            // SAFETY: the CPU has AVX (checked above).
            let spans = if avx {
                unsafe { self.spans_avx(edges, iy, n, inv) }
            } else {
                self.spans(edges, iy, n, inv)
            };
            #[cfg(not(target_arch = "x86_64"))]
            let spans = self.spans(edges, iy, n, inv);
            for (k, &(ix0, ix1)) in spans[..n].iter().enumerate() {
                if ix0 <= ix1 {
                    row((iy + k as i64) as usize, ix0 as usize, ix1 as usize);
                }
            }
            iy += 4;
        }
    }

    /// The cells that rows `iy..iy + n` (`n` ≤ 4) of the polygon bounded by `edges` meet: for
    /// each row the inclusive range `(ix0, ix1)`, which is empty (`ix0 > ix1`) when the row
    /// meets no cell.
    #[inline(always)]
    fn spans(&self, edges: &[Edge], iy: i64, n: usize, inv: f64) -> [(i64, i64); 4] {
        let (oy, eps) = (self.origin.y, self.eps);
        let mut spans = [(1, 0); 4];
        for (k, span) in spans.iter_mut().enumerate().take(n) {
            let iy = iy + k as i64;
            let lo = oy + iy as f64 * self.cell_size - eps;
            let hi = oy + (iy + 1) as f64 * self.cell_size + eps;
            // The x-extent of the polygon within the strip lo ≤ y ≤ hi: the extreme x of a
            // convex set within a strip lies on its boundary, so clip each edge to the strip.
            let (mut xmin, mut xmax) = (f64::INFINITY, f64::NEG_INFINITY);
            for &Edge { y0, y1, x0, x1, slope } in edges {
                if y1 < lo || y0 > hi {
                    continue;
                }
                let (xa, xb) = if y1 > y0 {
                    (x0 + (max_of(y0, lo) - y0) * slope, x0 + (min_of(y1, hi) - y0) * slope)
                } else {
                    (x0, x1)
                };
                xmin = min_of(xb, min_of(xa, xmin));
                xmax = max_of(xb, max_of(xa, xmax));
            }
            if xmin > xmax {
                continue;
            }
            let ix0 = self.coord_by(xmin - eps, self.origin.x, inv).max(0);
            let ix1 = self.coord_by(xmax + eps, self.origin.x, inv).min(self.nx as i64 - 1);
            *span = (ix0, ix1);
        }
        spans
    }

    /// [`Grid::spans`] with the four rows in the four lanes of AVX vectors (row `iy + k` in
    /// lane `k`). Each lane performs the scalar body's operations, in the same order, on the
    /// same operands: `max_pd(a, b)` is `a > b ? a : b`, which is [`max_of`] (and `min_pd`
    /// [`min_of`]); an edge that misses a lane's strip leaves the lane's extent as it is, as
    /// skipping the edge does; `floor_pd` is [`floor_i64`] wherever the quotient passes
    /// [`Grid::coord_by`]'s test (it lies below 2⁵² in magnitude there). Nothing is fused (FMA
    /// is not enabled). Should a lane's quotient fail the test, the scalar body answers for
    /// the four rows.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    #[inline]
    fn spans_avx(&self, edges: &[Edge], iy: i64, n: usize, inv: f64) -> [(i64, i64); 4] {
        use std::arch::x86_64::*;
        let splat = _mm256_set1_pd;
        let (eps, cs) = (splat(self.eps), splat(self.cell_size));
        let rows = _mm256_setr_pd(iy as f64, (iy + 1) as f64, (iy + 2) as f64, (iy + 3) as f64);
        let oy = splat(self.origin.y);
        // `(iy + 1) as f64` is `iy as f64 + 1` exactly (rows are far below 2⁵³).
        let lo = _mm256_sub_pd(_mm256_add_pd(oy, _mm256_mul_pd(rows, cs)), eps);
        let hi = _mm256_add_pd(_mm256_add_pd(oy, _mm256_mul_pd(_mm256_add_pd(rows, splat(1.0)), cs)), eps);
        let (mut xmin, mut xmax) = (splat(f64::INFINITY), splat(f64::NEG_INFINITY));
        for e in edges {
            let (y0, y1, x0) = (splat(e.y0), splat(e.y1), splat(e.x0));
            let (xa, xb) = if e.y1 > e.y0 {
                let slope = splat(e.slope);
                let xa = _mm256_add_pd(x0, _mm256_mul_pd(_mm256_sub_pd(_mm256_max_pd(y0, lo), y0), slope));
                let xb = _mm256_add_pd(x0, _mm256_mul_pd(_mm256_sub_pd(_mm256_min_pd(y1, hi), y0), slope));
                (xa, xb)
            } else {
                (x0, splat(e.x1))
            };
            let misses =
                _mm256_or_pd(_mm256_cmp_pd::<_CMP_LT_OQ>(y1, lo), _mm256_cmp_pd::<_CMP_GT_OQ>(y0, hi));
            xmin = _mm256_blendv_pd(_mm256_min_pd(xb, _mm256_min_pd(xa, xmin)), xmin, misses);
            xmax = _mm256_blendv_pd(_mm256_max_pd(xb, _mm256_max_pd(xa, xmax)), xmax, misses);
        }
        // Lanes past the `n` rows count as empty.
        let past = _mm256_cmp_pd::<_CMP_GE_OQ>(_mm256_setr_pd(0.0, 1.0, 2.0, 3.0), splat(n as f64));
        let empty = _mm256_or_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(xmin, xmax), past);
        // `coord_by` in every lane: the floor of the quotient, and whether it passes the test.
        let coord = |v: __m256d| {
            let q = _mm256_mul_pd(_mm256_sub_pd(v, splat(self.origin.x)), splat(inv));
            let k = _mm256_floor_pd(q);
            let f = _mm256_sub_pd(q, k);
            let abs = _mm256_andnot_pd(splat(-0.0), q);
            let tol = _mm256_mul_pd(splat(1e-9), _mm256_max_pd(abs, splat(1.0)));
            let ok = _mm256_and_pd(
                _mm256_cmp_pd::<_CMP_GT_OQ>(f, tol),
                _mm256_cmp_pd::<_CMP_LT_OQ>(f, _mm256_sub_pd(splat(1.0), tol)),
            );
            (k, ok)
        };
        let (k0, ok0) = coord(_mm256_sub_pd(xmin, eps));
        let (k1, ok1) = coord(_mm256_add_pd(xmax, eps));
        if _mm256_movemask_pd(_mm256_or_pd(_mm256_and_pd(ok0, ok1), empty)) != 15 {
            return self.spans(edges, iy, n, inv);
        }
        // Clamped into the grid as the scalar body does, and further into [-1, nx], which
        // keeps every range that is not empty as it is (and every empty one empty); the empty
        // lanes' ranges set to the empty (1, 0).
        let nx = self.nx as f64;
        let ix0 = _mm256_min_pd(_mm256_max_pd(k0, splat(0.0)), splat(nx));
        let ix1 = _mm256_max_pd(_mm256_min_pd(k1, splat(nx - 1.0)), splat(-1.0));
        let (ix0, ix1) = (_mm256_blendv_pd(ix0, splat(1.0), empty), _mm256_blendv_pd(ix1, splat(0.0), empty));
        let (mut a, mut b) = ([0i32; 4], [0i32; 4]);
        // SAFETY: `a` and `b` hold four `i32` each; unaligned stores.
        unsafe {
            _mm_storeu_si128(a.as_mut_ptr().cast(), _mm256_cvttpd_epi32(ix0));
            _mm_storeu_si128(b.as_mut_ptr().cast(), _mm256_cvttpd_epi32(ix1));
        }
        std::array::from_fn(|k| (a[k] as i64, b[k] as i64))
    }

    /// The distance along the ray at which it enters the grid, or `None` when it misses.
    fn entry(&self, origin: Vec2, dir: Vec2) -> Option<f64> {
        let (lo, hi) = self.extent();
        let mut t0: f64 = 0.0;
        let mut t1 = f64::INFINITY;
        for axis in 0..2 {
            let (o, d, l, h) = (origin[axis], dir[axis], lo[axis], hi[axis]);
            if d == 0.0 {
                if o < l || o >= h {
                    return None;
                }
            } else {
                let (a, b) = ((l - o) / d, (h - o) / d);
                t0 = t0.max(a.min(b));
                t1 = t1.min(a.max(b));
            }
        }
        (t0 <= t1).then_some(t0)
    }

    /// Walks the ray `origin + t·dir`, `t ≥ 0`, through the grid, calling `visit` for each step
    /// (a non-empty cell, or an empty cell's whole macro-region). `visit` returns `false` to stop.
    pub fn walk(&self, origin: Vec2, dir: Vec2, mut visit: impl FnMut(Step) -> bool) {
        let Some(mut t) = self.entry(origin, dir) else {
            return;
        };
        let p = origin + dir * t;
        let clamp = |v: i64, n: usize| v.clamp(0, n as i64 - 1);
        // Cell coordinates by `coord_by`: the cells of the division, mostly by a product.
        let inv = 1.0 / self.cell_size;
        let mut ix = clamp(self.coord_by(p.x, self.origin.x, inv), self.nx);
        let mut iy = clamp(self.coord_by(p.y, self.origin.y, inv), self.ny);
        let (nx, ny) = (self.nx as i64, self.ny as i64);
        let s = self.cell_size;
        loop {
            let cell = self.index(ix as usize, iy as usize);
            let region = self.region_of(cell);
            let r = match region {
                Some(r) => self.regions[r as usize],
                None => CellRect { x0: ix as u32, y0: iy as u32, x1: ix as u32, y1: iy as u32 },
            };
            // Exit distance across the box's faces on each axis.
            let face = |d: f64, o: f64, org: f64, c0: u32, c1: u32| -> f64 {
                if d > 0.0 {
                    (org + (c1 + 1) as f64 * s - o) / d
                } else if d < 0.0 {
                    (org + c0 as f64 * s - o) / d
                } else {
                    f64::INFINITY
                }
            };
            let tx = face(dir.x, origin.x, self.origin.x, r.x0, r.x1);
            let ty = face(dir.y, origin.y, self.origin.y, r.y0, r.y1);
            let t_exit = tx.min(ty).max(t);
            if !visit(Step { cell, region, t_enter: t, t_exit }) {
                return;
            }
            let q = origin + dir * t_exit;
            // Step across the exit face; the other index comes from the exit point, clamped into
            // the box and never moving against the direction of travel.
            let (jx, jy);
            if tx <= ty {
                jx = if dir.x > 0.0 { r.x1 as i64 + 1 } else { r.x0 as i64 - 1 };
            } else {
                let v = self.coord_by(q.x, self.origin.x, inv).clamp(r.x0 as i64, r.x1 as i64);
                jx = if dir.x >= 0.0 { v.max(ix) } else { v.min(ix) };
            }
            if ty <= tx {
                jy = if dir.y > 0.0 { r.y1 as i64 + 1 } else { r.y0 as i64 - 1 };
            } else {
                let v = self.coord_by(q.y, self.origin.y, inv).clamp(r.y0 as i64, r.y1 as i64);
                jy = if dir.y >= 0.0 { v.max(iy) } else { v.min(iy) };
            }
            if jx < 0 || jx >= nx || jy < 0 || jy >= ny {
                return;
            }
            ix = jx;
            iy = jy;
            t = t_exit;
        }
    }
}

/// A polygon edge for the rasterisers: its y range, the x of its lower and upper ends, and dx/dy
/// (zero for a horizontal edge).
#[derive(Clone, Copy, Debug, Default)]
struct Edge {
    y0: f64,
    y1: f64,
    x0: f64,
    x1: f64,
    slope: f64,
}

impl Edge {
    #[inline(always)]
    fn new(p: Vec2, q: Vec2) -> Edge {
        let (lo, hi) = if p.y <= q.y { (p, q) } else { (q, p) };
        let slope = if hi.y > lo.y { (hi.x - lo.x) / (hi.y - lo.y) } else { 0.0 };
        Edge { y0: lo.y, y1: hi.y, x0: lo.x, x1: hi.x, slope }
    }
}

/// `a.min(b)` for a `b` that is not NaN, in one comparison: a NaN `a` gives `b`, as `f64::min`
/// does. (The two may differ in the sign of a zero result; the rasterisers only take such values
/// apart from the non-zero `eps`, or floor them, and no sign of zero changes either.)
#[inline(always)]
fn min_of(a: f64, b: f64) -> f64 {
    if a < b {
        a
    } else {
        b
    }
}

/// `a.max(b)` for a `b` that is not NaN, in one comparison (see [`min_of`]).
#[inline(always)]
fn max_of(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

/// `floor(v)` as an integer, without a library call (saturating outside the `i64` range).
#[inline]
fn floor_i64(v: f64) -> i64 {
    let i = v as i64;
    if (i as f64) > v {
        i - 1
    } else {
        i
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bounds(w: f64) -> Bounds {
        Bounds { min: Vec2::ZERO, max: Vec2::splat(w) }
    }

    #[test]
    fn paper_workload_gets_a_64_by_64_grid() {
        let segs: Vec<Segment> = (0..1000)
            .map(|i| {
                let x = (i % 30) as f64 * 30.0 + 10.0;
                let y = (i / 30) as f64 * 30.0 + 10.0;
                Segment::new(Vec2::new(x, y), Vec2::new(x + 4.0, y))
            })
            .collect();
        let g = Grid::build(&segs, bounds(1024.0), GridParams::default());
        assert_eq!((g.nx, g.ny), (64, 64));
    }

    #[test]
    fn every_empty_cell_lies_in_its_empty_region() {
        let segs = vec![
            Segment::new(Vec2::new(100.0, 100.0), Vec2::new(300.0, 120.0)),
            Segment::new(Vec2::new(500.0, 900.0), Vec2::new(510.0, 700.0)),
        ];
        let g =
            Grid::build(&segs, bounds(1024.0), GridParams { cells_per_segment: 50.0, cells_per_axis: None });
        for iy in 0..g.ny {
            for ix in 0..g.nx {
                let c = g.index(ix, iy);
                match g.region_of(c) {
                    None => assert!(!g.cell_items(c).is_empty()),
                    Some(r) => {
                        let r = g.region(r);
                        assert!(r.x0 as usize <= ix && ix <= r.x1 as usize);
                        assert!(r.y0 as usize <= iy && iy <= r.y1 as usize);
                        for y in r.y0..=r.y1 {
                            for x in r.x0..=r.x1 {
                                assert!(g.cell_items(g.index(x as usize, y as usize)).is_empty());
                            }
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn avx_spans_are_the_scalar_spans() {
        #[cfg(target_arch = "x86_64")]
        if std::is_x86_feature_detected!("avx") {
            let segs = vec![Segment::new(Vec2::new(3.0, 5.0), Vec2::new(1000.0, 990.0))];
            let g = Grid::build(
                &segs,
                bounds(1024.0),
                GridParams { cells_per_axis: Some(64), ..Default::default() },
            );
            let inv = 1.0 / g.cell_size;
            // xorshift64*: coordinates anywhere around the grid, many on cell boundaries (where
            // the floor is decided by the division) or a hair off them, some rows horizontal.
            let mut state = 0x9e37_79b9_7f4a_7c15u64;
            let mut next = move || {
                state ^= state >> 12;
                state ^= state << 25;
                state ^= state >> 27;
                state.wrapping_mul(0x2545_f491_4f6c_dd1d)
            };
            let mut coord = |axis: f64| {
                let r = next();
                let cell = (r % 70) as f64 - 3.0;
                let at = axis + cell * g.cell_size;
                let sign = if r >> 20 & 1 == 0 { 1.0 } else { -1.0 };
                match (r >> 8) % 4 {
                    0 => at,
                    1 => at + sign * g.eps + (((r >> 16) % 5) as f64 - 2.0) * 1e-13,
                    _ => at + ((r >> 11) as f64 / (1u64 << 53) as f64) * g.cell_size,
                }
            };
            for case in 0..4000 {
                let n = 1 + case % 8;
                let mut poly: Vec<Vec2> =
                    (0..n).map(|_| Vec2::new(coord(g.origin.x), coord(g.origin.y))).collect();
                if case % 5 == 0 && n > 1 {
                    poly[1].y = poly[0].y;
                }
                let edges: Vec<Edge> = (0..n).map(|i| Edge::new(poly[i], poly[(i + 1) % n])).collect();
                for iy in -2..g.ny as i64 + 2 {
                    let rows = 1 + (iy as usize & 3);
                    let scalar = g.spans(&edges, iy, rows, inv);
                    // SAFETY: the CPU has AVX (checked above).
                    let avx = unsafe { g.spans_avx(&edges, iy, rows, inv) };
                    let nonempty = |s: &[(i64, i64)]| -> Vec<(i64, i64)> {
                        s[..rows].iter().map(|&(a, b)| if a <= b { (a, b) } else { (1, 0) }).collect()
                    };
                    assert_eq!(nonempty(&scalar), nonempty(&avx), "polygon {poly:?}, rows from {iy}");
                }
            }
        }
    }

    #[test]
    fn walk_visits_cells_in_order_and_ends() {
        let segs = vec![Segment::new(Vec2::new(700.0, 0.0), Vec2::new(700.0, 1000.0))];
        let g =
            Grid::build(&segs, bounds(1024.0), GridParams { cells_per_segment: 64.0, cells_per_axis: None });
        let mut last = 0.0;
        let mut steps = 0;
        let mut met = false;
        g.walk(Vec2::new(10.0, 500.0), Vec2::new(1.0, 0.0), |s| {
            assert!(s.t_enter >= last && s.t_exit >= s.t_enter);
            last = s.t_exit;
            steps += 1;
            met |= g.cell_items(s.cell).contains(&0);
            true
        });
        assert!(met, "the walk must reach the cell holding the segment");
        assert!(steps < 16, "empty space is crossed by macro-region jumps, took {steps} steps");
    }
}
