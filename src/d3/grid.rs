//! The 3D underlying structure: a uniform grid of cubic cells with Devillers macro-regions over a
//! [`Scene3`], and its 3D-DDA traversal (Amanatides–Woo). The 3D counterpart of
//! [`crate::grid`].
//!
//! # Construction
//!
//! * **Bounds.** The bounding box of every vertex ([`Scene3::bounds`]), padded on every side by
//!   10⁻³ of its largest side, so no polygon lies on the outer boundary and a flat scene (every
//!   polygon in one plane) still gets a box of non-zero thickness.
//! * **Resolution rule.** Cubic cells, sized so the grid has about `λ·N` cells for `N` polygons
//!   (`λ` = [`Grid3Params::cells_per_polygon`], default 4, as in 2D): side
//!   `s = ∛(volume / (λ·N))`, at least `largest side / `[`MAX_CELLS_PER_AXIS3`]; then
//!   `nₖ = ⌈sideₖ / s⌉`, each clamped to `1..=MAX_CELLS_PER_AXIS3`. Where that would make more
//!   than [`MAX_GRID3_CELLS`] (2²²) cells, `s` is grown by factors of `1 + 2⁻¹⁰` until it does not
//!   (coarsening; a bounded loop, never a hang). For the 3D workload (1000 squares in 1024³) that
//!   is a 16³ grid of 64-unit cells. [`Grid3Params::cells_per_axis`] overrides the rule (the
//!   larger side gets that many cells, clamped, and coarsened the same way). `λ` must be finite
//!   and positive ([`Grid3Error::BadLambda`]).
//! * **Registration is conservative.** Polygon `P` is registered in every cell whose box, grown
//!   by [`Grid3::eps`] on every side, meets the *registration polygon* of `P`: its vertices
//!   projected onto the plane through its centre with its normal (the plane the hit rule of
//!   [`super::brute`] intersects, which an off-plane vertex within the planarity tolerance may
//!   miss), offset outwards in that plane by `2 × EDGE_MARGIN × size(P)` (twice the hit rule's
//!   inside margin; at a vertex the offset edges' lines meet, so the offset reaches as far as
//!   the margin's region does even at a sharp corner). Box–polygon overlap is decided by the
//!   separating-axis test on the 13 kinds of axis of a box and a convex planar polygon (the
//!   three box axes, the polygon's normal, every edge × every box axis), which is exact for the
//!   grown box; cells are only candidates when their grown box meets the plane, column by
//!   column along the normal's dominant axis, so the work is about the polygon's area in cells.
//!   `eps` is 10⁻⁸ of (the grid's largest side + the largest coordinate magnitude of its
//!   corners): far above the rounding of the traversal and of the hit rule, so a ray whose hit
//!   point (as the hit rule computes it) lies in a cell the walk visits finds the polygon listed
//!   there. A superset of the cells is registered, never a subset. The work is bounded:
//!   [`MAX_REGISTRATION_COLUMNS`] candidate columns and [`MAX_REGISTRATIONS`] registrations,
//!   else [`Grid3Error::TooMuchWork`] / [`Grid3Error::TooManyRegistrations`] (lower `λ`).
//! * **Macro-regions.** Every empty cell gets an axis-aligned box of empty cells that contains
//!   it. Greedy growth: the cells are taken in index order (x fastest, then y, then z); an empty
//!   cell that has no region yet seeds one, grown from the cell by one layer towards −x, +x, −y,
//!   +y, −z, +z in turn, each only if the whole new layer is empty (a summed-volume table answers
//!   that in O(1)), until no side can grow. The box is then the region of every cell in it that
//!   has none yet (cells already in an earlier box keep theirs; boxes may overlap). Every box is
//!   locally maximal; each region has an id.
//!
//! # Traversal
//!
//! [`Grid3::walk`], in [`super::walk`] (build and traversal live in separate files): 3D-DDA
//! (Amanatides–Woo) that crosses an empty cell's whole macro-region in one step.

use super::brute::{Facets, EDGE_MARGIN};
use super::scene::{Polygon, Scene3};
use glam::DVec3;

/// The most cells of a 3D grid (2²², as in 2D).
pub const MAX_GRID3_CELLS: usize = 1 << 22;

/// The most cells along one axis.
pub const MAX_CELLS_PER_AXIS3: usize = 4096;

/// The most (cell, polygon) candidate columns registration examines (about the total area of the
/// polygons in cell faces).
pub const MAX_REGISTRATION_COLUMNS: u64 = 1 << 27;

/// The most registrations (cell, polygon pairs) a grid holds.
pub const MAX_REGISTRATIONS: usize = 1 << 26;

/// The stopping margin of the tracers, in units of [`Grid3::eps`] (see [`Grid3::stop_margin`]):
/// the 2D grid's, for the same reason.
pub use crate::grid::STOP_MARGIN_EPS;

/// Marks a non-empty cell in the per-cell region table.
pub(crate) const NO_REGION: u32 = u32::MAX;

/// Parameters of the resolution rule.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid3Params {
    /// Target number of cells per polygon (`λ`).
    pub cells_per_polygon: f64,
    /// Explicit number of cells along the largest side; overrides `cells_per_polygon`.
    pub cells_per_axis: Option<usize>,
}

impl Default for Grid3Params {
    fn default() -> Self {
        Grid3Params { cells_per_polygon: 4.0, cells_per_axis: None }
    }
}

/// Why a grid cannot be built.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Grid3Error {
    #[error("the scene has no polygons")]
    EmptyScene,
    #[error("the cells per polygon must be finite and positive, got {0}")]
    BadLambda(f64),
    #[error(
        "registering the polygons would examine more than {MAX_REGISTRATION_COLUMNS} columns of \
         cells ({columns}); lower the cells per polygon"
    )]
    TooMuchWork { columns: u64 },
    #[error("the polygons would be registered in more than {MAX_REGISTRATIONS} cells; lower the cells per polygon")]
    TooManyRegistrations,
}

/// An inclusive box of cell indices, `lo[k]..=hi[k]` along axis `k`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CellBox {
    pub lo: [u32; 3],
    pub hi: [u32; 3],
}

impl CellBox {
    /// Whether the box contains cell `c` (by coordinates).
    pub fn contains(&self, c: [u32; 3]) -> bool {
        (0..3).all(|k| self.lo[k] <= c[k] && c[k] <= self.hi[k])
    }
}

/// A uniform grid of cubic cells over a 3D scene, each listing the polygons registered in it.
#[derive(Clone, Debug)]
pub struct Grid3 {
    /// The lower corner of cell (0, 0, 0).
    pub origin: DVec3,
    /// The side of a cell.
    pub cell_size: f64,
    /// Cells along x, y, z.
    pub n: [usize; 3],
    /// The registration margin: cell boxes are grown by this much when polygons are registered.
    pub eps: f64,
    /// Polygon lists in compressed-row form: cell `c` holds `items[offsets[c]..offsets[c + 1]]`,
    /// in increasing polygon index.
    offsets: Vec<u32>,
    items: Vec<u32>,
    /// The macro-region of each empty cell, `NO_REGION` for a non-empty one.
    pub(crate) cell_region: Vec<u32>,
    regions: Vec<CellBox>,
    /// The scene's polygons prepared for the hit rule.
    facets: Facets,
}

impl Grid3 {
    /// Builds the grid over `scene` (see the module docs for the rules).
    pub fn build(scene: &Scene3, params: Grid3Params) -> Result<Grid3, Grid3Error> {
        if scene.polygons.is_empty() {
            return Err(Grid3Error::EmptyScene);
        }
        if params.cells_per_axis.is_none()
            && !(params.cells_per_polygon.is_finite() && params.cells_per_polygon > 0.0)
        {
            return Err(Grid3Error::BadLambda(params.cells_per_polygon));
        }
        let (origin, cell_size, n) = Self::layout(scene, params);
        let hi = origin + DVec3::new(n[0] as f64, n[1] as f64, n[2] as f64) * cell_size;
        let extent = (hi - origin).max_element();
        let scale = extent + origin.abs().max(hi.abs()).max_element();
        let mut grid = Grid3 {
            origin,
            cell_size,
            n,
            eps: 1e-8 * scale,
            offsets: Vec::new(),
            items: Vec::new(),
            cell_region: Vec::new(),
            regions: Vec::new(),
            facets: Facets::new(scene),
        };
        grid.register(&scene.polygons)?;
        grid.build_macro_regions();
        Ok(grid)
    }

    /// Origin, cell side and resolution for `scene`, by the resolution rule.
    fn layout(scene: &Scene3, params: Grid3Params) -> (DVec3, f64, [usize; 3]) {
        let (lo, hi) = scene.bounds();
        let size = hi - lo;
        let pad = size.max_element() * 1e-3;
        let min = lo - DVec3::splat(pad);
        let size = size + DVec3::splat(2.0 * pad);
        let largest = size.max_element();
        let floor = largest / MAX_CELLS_PER_AXIS3 as f64;
        let mut cell = match params.cells_per_axis {
            Some(k) => largest / k.clamp(1, MAX_CELLS_PER_AXIS3) as f64,
            None => {
                let cells = (params.cells_per_polygon * scene.polygons.len() as f64).max(1.0);
                (size.x * size.y * size.z / cells).cbrt().max(floor)
            }
        };
        let count = |cell: f64, len: f64| ((len / cell).ceil() as usize).clamp(1, MAX_CELLS_PER_AXIS3);
        let total = |cell: f64| {
            (0..3).map(|k| count(cell, size[k]) as u128).product::<u128>() > MAX_GRID3_CELLS as u128
        };
        // At most MAX_GRID3_CELLS cells: coarsen. From `floor` (4096³ at most) this takes fewer
        // than 10⁴ steps.
        while total(cell) {
            cell *= 1.0 + 1.0 / 1024.0;
        }
        (min, cell, [count(cell, size.x), count(cell, size.y), count(cell, size.z)])
    }

    /// The number of cells.
    pub fn len(&self) -> usize {
        self.n[0] * self.n[1] * self.n[2]
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The world-space corners of the grid.
    pub fn extent(&self) -> (DVec3, DVec3) {
        let n = DVec3::new(self.n[0] as f64, self.n[1] as f64, self.n[2] as f64);
        (self.origin, self.origin + n * self.cell_size)
    }

    /// The stopping margin, `4·eps`, in world units: the conventional walk stops only at a cell
    /// whose exit lies beyond the nearest hit by more than this (divided by the direction's
    /// length, for `t`). A hit's point and a cell's exit are each rounded by far less than `eps`,
    /// and cells are grown by `eps` at registration, so a hit within rounding of a boundary is
    /// never taken before every polygon that might tie with it or lie nearer has been tested.
    pub fn stop_margin(&self) -> f64 {
        STOP_MARGIN_EPS * self.eps
    }

    /// The index of the cell at coordinates `c`.
    #[inline]
    pub fn index(&self, c: [u32; 3]) -> usize {
        (c[2] as usize * self.n[1] + c[1] as usize) * self.n[0] + c[0] as usize
    }

    /// The coordinates of cell `index`.
    pub fn coords(&self, index: usize) -> [u32; 3] {
        let x = index % self.n[0];
        let y = (index / self.n[0]) % self.n[1];
        let z = index / (self.n[0] * self.n[1]);
        [x as u32, y as u32, z as u32]
    }

    /// The world-space box of cell `c`, `(lo, hi)`.
    pub fn cell_bounds(&self, c: [u32; 3]) -> (DVec3, DVec3) {
        let lo = self.origin + DVec3::new(c[0] as f64, c[1] as f64, c[2] as f64) * self.cell_size;
        (lo, lo + DVec3::splat(self.cell_size))
    }

    /// The cell coordinate (possibly outside the grid) of world coordinate `v` along `axis`.
    #[inline]
    pub fn coord(&self, v: f64, axis: usize) -> i64 {
        floor_i64((v - self.origin[axis]) / self.cell_size)
    }

    /// The cell containing point `p`, or `None` outside the grid.
    pub fn cell_of(&self, p: DVec3) -> Option<[u32; 3]> {
        let mut c = [0u32; 3];
        for k in 0..3 {
            let v = self.coord(p[k], k);
            if v < 0 || v >= self.n[k] as i64 {
                return None;
            }
            c[k] = v as u32;
        }
        Some(c)
    }

    /// The polygons registered in cell `c`, in increasing index.
    #[inline]
    pub fn cell_items(&self, c: usize) -> &[u32] {
        &self.items[self.offsets[c] as usize..self.offsets[c + 1] as usize]
    }

    /// The macro-region of cell `c`, or `None` when polygons are registered in it.
    #[inline]
    pub fn region_of(&self, c: usize) -> Option<u32> {
        let r = self.cell_region[c];
        (r != NO_REGION).then_some(r)
    }

    /// The box of macro-region `r`.
    pub fn region(&self, r: u32) -> CellBox {
        self.regions[r as usize]
    }

    /// The number of macro-regions.
    pub fn region_count(&self) -> usize {
        self.regions.len()
    }

    /// The polygons of the scene the grid was built over, prepared for the hit rule.
    pub fn facets(&self) -> &Facets {
        &self.facets
    }

    /// The number of registrations (cell, polygon pairs).
    pub fn registrations(&self) -> usize {
        self.items.len()
    }

    /// The inclusive range of cell coordinates along `axis` whose boxes, grown by `2·eps`, can
    /// meet `[lo, hi]` (clamped into the grid; empty when `lo > hi` after clamping).
    fn range(&self, lo: f64, hi: f64, axis: usize) -> (i64, i64) {
        let m = 2.0 * self.eps;
        let last = self.n[axis] as i64 - 1;
        (self.coord(lo - m, axis).clamp(0, last), self.coord(hi + m, axis).clamp(0, last))
    }

    /// Registers every polygon in every cell its registration polygon meets (module docs).
    fn register(&mut self, polygons: &[Polygon]) -> Result<(), Grid3Error> {
        let shapes: Vec<RegistrationPolygon> = polygons.iter().map(RegistrationPolygon::new).collect();
        // Bound the work before doing it.
        let mut columns = 0u64;
        for q in &shapes {
            let (a, b, _) = axes(q.normal);
            let (a0, a1) = self.range(q.lo[a], q.hi[a], a);
            let (b0, b1) = self.range(q.lo[b], q.hi[b], b);
            columns += ((a1 - a0 + 1) * (b1 - b0 + 1)) as u64;
        }
        if columns > MAX_REGISTRATION_COLUMNS {
            return Err(Grid3Error::TooMuchWork { columns });
        }
        let mut pairs: Vec<(u32, u32)> = Vec::new();
        for (k, q) in shapes.iter().enumerate() {
            let mut fail = false;
            self.cells_of(q, |cell| {
                if pairs.len() >= MAX_REGISTRATIONS {
                    fail = true;
                } else {
                    pairs.push((cell as u32, k as u32));
                }
            });
            if fail {
                return Err(Grid3Error::TooManyRegistrations);
            }
        }
        // Counting sort by cell; polygons stay in increasing order within a cell.
        let cells = self.len();
        let mut offsets = vec![0u32; cells + 1];
        for &(c, _) in &pairs {
            offsets[c as usize + 1] += 1;
        }
        for c in 0..cells {
            offsets[c + 1] += offsets[c];
        }
        let mut cursor = offsets.clone();
        let mut items = vec![0u32; pairs.len()];
        for &(c, k) in &pairs {
            items[cursor[c as usize] as usize] = k;
            cursor[c as usize] += 1;
        }
        self.offsets = offsets;
        self.items = items;
        Ok(())
    }

    /// Calls `found(cell)` for every cell whose box grown by `eps` meets `q`, each once.
    fn cells_of(&self, q: &RegistrationPolygon, mut found: impl FnMut(usize)) {
        let (a, b, d) = axes(q.normal);
        let (a0, a1) = self.range(q.lo[a], q.hi[a], a);
        let (b0, b1) = self.range(q.lo[b], q.hi[b], b);
        let (d0, d1) = self.range(q.lo[d], q.hi[d], d);
        let s = self.cell_size;
        let m = 2.0 * self.eps;
        let nd = q.normal[d];
        let offset = q.normal.dot(q.centre);
        for ia in a0..=a1 {
            for ib in b0..=b1 {
                // The plane's depth over the column's rectangle (grown), at its four corners.
                let xa = [self.origin[a] + ia as f64 * s - m, self.origin[a] + (ia + 1) as f64 * s + m];
                let xb = [self.origin[b] + ib as f64 * s - m, self.origin[b] + (ib + 1) as f64 * s + m];
                let (mut zlo, mut zhi) = (f64::INFINITY, f64::NEG_INFINITY);
                for &u in &xa {
                    for &v in &xb {
                        let z = (offset - q.normal[a] * u - q.normal[b] * v) / nd;
                        zlo = zlo.min(z);
                        zhi = zhi.max(z);
                    }
                }
                let (z0, z1) = self.range(zlo, zhi, d);
                for id in z0.max(d0)..=z1.min(d1) {
                    let mut c = [0u32; 3];
                    c[a] = ia as u32;
                    c[b] = ib as u32;
                    c[d] = id as u32;
                    let (lo, hi) = self.cell_bounds(c);
                    if q.meets_box(lo - DVec3::splat(self.eps), hi + DVec3::splat(self.eps)) {
                        found(self.index(c));
                    }
                }
            }
        }
    }

    fn build_macro_regions(&mut self) {
        let [nx, ny, nz] = self.n;
        let (wx, wy) = (nx + 1, ny + 1);
        // Summed-volume table: sv[(z·wy + y)·wx + x] counts non-empty cells in [0,x)×[0,y)×[0,z).
        let mut sv = vec![0u32; wx * wy * (nz + 1)];
        let at = |x: usize, y: usize, z: usize| (z * wy + y) * wx + x;
        for z in 0..nz {
            for y in 0..ny {
                for x in 0..nx {
                    let c = (z * ny + y) * nx + x;
                    let full = (self.offsets[c + 1] > self.offsets[c]) as i64;
                    let v = full
                        + sv[at(x, y + 1, z + 1)] as i64
                        + sv[at(x + 1, y, z + 1)] as i64
                        + sv[at(x + 1, y + 1, z)] as i64
                        - sv[at(x, y, z + 1)] as i64
                        - sv[at(x, y + 1, z)] as i64
                        - sv[at(x + 1, y, z)] as i64
                        + sv[at(x, y, z)] as i64;
                    sv[at(x + 1, y + 1, z + 1)] = v as u32;
                }
            }
        }
        // Whether the inclusive box lo..=hi holds a non-empty cell.
        let occupied = |lo: [usize; 3], hi: [usize; 3]| -> bool {
            let (x0, y0, z0) = (lo[0], lo[1], lo[2]);
            let (x1, y1, z1) = (hi[0] + 1, hi[1] + 1, hi[2] + 1);
            let s = |x, y, z| sv[at(x, y, z)] as i64;
            s(x1, y1, z1) - s(x0, y1, z1) - s(x1, y0, z1) - s(x1, y1, z0)
                + s(x0, y0, z1)
                + s(x0, y1, z0)
                + s(x1, y0, z0)
                - s(x0, y0, z0)
                > 0
        };
        self.cell_region = vec![NO_REGION; self.len()];
        let mut assigned = vec![false; self.len()];
        for c in 0..self.len() {
            if assigned[c] || self.offsets[c + 1] > self.offsets[c] {
                continue;
            }
            let start = self.coords(c).map(|v| v as usize);
            let (mut lo, mut hi) = (start, start);
            loop {
                let mut grew = false;
                for k in 0..3 {
                    if lo[k] > 0 {
                        let (mut l, mut h) = (lo, hi);
                        l[k] -= 1;
                        h[k] = l[k];
                        if !occupied(l, h) {
                            lo[k] -= 1;
                            grew = true;
                        }
                    }
                    if hi[k] + 1 < self.n[k] {
                        let (mut l, mut h) = (lo, hi);
                        h[k] += 1;
                        l[k] = h[k];
                        if !occupied(l, h) {
                            hi[k] += 1;
                            grew = true;
                        }
                    }
                }
                if !grew {
                    break;
                }
            }
            let id = self.regions.len() as u32;
            self.regions.push(CellBox { lo: lo.map(|v| v as u32), hi: hi.map(|v| v as u32) });
            for z in lo[2]..=hi[2] {
                for y in lo[1]..=hi[1] {
                    for x in lo[0]..=hi[0] {
                        let i = (z * ny + y) * nx + x;
                        if !assigned[i] {
                            assigned[i] = true;
                            self.cell_region[i] = id;
                        }
                    }
                }
            }
        }
    }
}

/// `x.floor() as i64`, without the call to the C library's `floor` that x86-64 makes (it has no
/// rounding instruction before SSE4.1): the truncation, less one where it rounded a negative
/// value up. Equal for every `x`, NaN (0) and the infinities included.
#[inline]
pub(crate) fn floor_i64(x: f64) -> i64 {
    let t = x as i64;
    if (t as f64) > x {
        t.saturating_sub(1)
    } else {
        t
    }
}

/// The axes `(a, b, d)`: `d` the normal's dominant axis, `a` and `b` the other two.
fn axes(normal: DVec3) -> (usize, usize, usize) {
    let m = normal.abs();
    let d = if m.x >= m.y && m.x >= m.z {
        0
    } else if m.y >= m.z {
        1
    } else {
        2
    };
    ((d + 1) % 3, (d + 2) % 3, d)
}

/// A polygon as registration sees it (module docs): its vertices projected onto its plane and
/// offset outwards by twice the hit rule's margin.
/// The polar and sweep tracers take their spans and slices from it too, so that every hit the
/// hit rule accepts lies inside it with room to spare.
#[derive(Clone, Debug)]
pub(crate) struct RegistrationPolygon {
    /// The offset vertices, in the polygon's order.
    pub(crate) vertices: Vec<DVec3>,
    normal: DVec3,
    centre: DVec3,
    lo: DVec3,
    hi: DVec3,
}

impl RegistrationPolygon {
    pub(crate) fn new(p: &Polygon) -> RegistrationPolygon {
        let n = p.normal;
        let c = p.centre;
        let v: Vec<DVec3> = p.vertices.iter().map(|v| *v - n * (*v - c).dot(n)).collect();
        let k = v.len();
        // Outward unit normals of the edges, in the plane (inside is to the left, n × e).
        let out: Vec<DVec3> = (0..k)
            .map(|i| {
                let e = v[(i + 1) % k] - v[i];
                -n.cross(e).normalize_or_zero()
            })
            .collect();
        let m = 2.0 * EDGE_MARGIN * p.size;
        let vertices: Vec<DVec3> = (0..k)
            .map(|i| {
                // Where the two offset edge lines meet: `2m·b / |b|²` along the bisector
                // `b = o₀ + o₁` (`m / sin(½ interior angle)` from the vertex; no cancellation
                // as in `1 + o₀·o₁` at a sharp vertex).
                let b = out[(i + k - 1) % k] + out[i];
                v[i] + b * (2.0 * m / b.length_squared().max(f64::MIN_POSITIVE))
            })
            .collect();
        let (lo, hi) = vertices.iter().fold((vertices[0], vertices[0]), |(l, h), v| (l.min(*v), h.max(*v)));
        RegistrationPolygon { vertices, normal: n, centre: c, lo, hi }
    }

    /// Whether the polygon meets the closed box `[lo, hi]`: the separating-axis test over the box
    /// axes, the polygon's normal and every edge × box axis.
    fn meets_box(&self, lo: DVec3, hi: DVec3) -> bool {
        if (0..3).any(|k| self.hi[k] < lo[k] || self.lo[k] > hi[k]) {
            return false;
        }
        let centre = (lo + hi) * 0.5;
        let half = (hi - lo) * 0.5;
        let separated = |axis: DVec3| -> bool {
            let r = half.dot(axis.abs());
            let mid = centre.dot(axis);
            let (mut pmin, mut pmax) = (f64::INFINITY, f64::NEG_INFINITY);
            for v in &self.vertices {
                let x = v.dot(axis);
                pmin = pmin.min(x);
                pmax = pmax.max(x);
            }
            pmax < mid - r || pmin > mid + r
        };
        if separated(self.normal) {
            return false;
        }
        let k = self.vertices.len();
        for i in 0..k {
            let e = self.vertices[(i + 1) % k] - self.vertices[i];
            for axis in [DVec3::X, DVec3::Y, DVec3::Z] {
                let a = e.cross(axis);
                if a.length_squared() > 0.0 && separated(a) {
                    return false;
                }
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::d3::gen::{box_room, generate};
    use crate::d3::obj;
    use crate::d3::walk::Step3;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn cornell() -> Scene3 {
        obj::load(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cornell_box.obj")).unwrap()
    }

    fn scenes() -> Vec<(String, Scene3, Grid3Params)> {
        let mut v = Vec::new();
        for (seed, count, size, lambda) in [(1u64, 200, 32.0, 4.0), (2, 50, 200.0, 8.0), (3, 400, 16.0, 2.0)]
        {
            v.push((
                format!("generate({count}, {size}, {seed}) λ={lambda}"),
                generate(count, size, seed).unwrap(),
                Grid3Params { cells_per_polygon: lambda, cells_per_axis: None },
            ));
        }
        v.push((
            "box room".into(),
            box_room(),
            Grid3Params { cells_per_polygon: 40.0, cells_per_axis: None },
        ));
        v.push((
            "cornell".into(),
            cornell(),
            Grid3Params { cells_per_polygon: 1.0, cells_per_axis: Some(24) },
        ));
        v
    }

    /// A point of polygon `p` from barycentric-like weights over a fan from vertex 0.
    fn sample(p: &Polygon, rng: &mut ChaCha8Rng) -> DVec3 {
        let k = p.vertices.len();
        let i = rng.random_range(1..k - 1);
        let (mut u, mut v) = (rng.random::<f64>(), rng.random::<f64>());
        if u + v > 1.0 {
            (u, v) = (1.0 - u, 1.0 - v);
        }
        // Edges and corners sampled too.
        match rng.random_range(0..8) {
            0 => u = 0.0,
            1 => v = 0.0,
            2 => (u, v) = (1.0, 0.0),
            _ => {}
        }
        let (a, b, c) = (p.vertices[0], p.vertices[i], p.vertices[i + 1]);
        a + (b - a) * u + (c - a) * v
    }

    #[test]
    fn every_cell_a_polygon_meets_lists_it() {
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        for (name, scene, params) in scenes() {
            let g = Grid3::build(&scene, params).unwrap();
            assert!(g.len() <= MAX_GRID3_CELLS);
            for (k, p) in scene.polygons.iter().enumerate() {
                for _ in 0..200 {
                    let x = sample(p, &mut rng);
                    let c = g.cell_of(x).unwrap_or_else(|| panic!("{name}: {x} outside the grid"));
                    assert!(
                        g.cell_items(g.index(c)).contains(&(k as u32)),
                        "{name}: polygon {k} meets cell {c:?} at {x} but is not registered there"
                    );
                }
            }
        }
    }

    #[test]
    fn registration_is_not_far_too_coarse() {
        // A polygon is registered only near it: the cell's box grown by a cell meets its plane.
        for (name, scene, params) in scenes() {
            let g = Grid3::build(&scene, params).unwrap();
            for c in 0..g.len() {
                let (lo, hi) = g.cell_bounds(g.coords(c));
                let (mid, half) = ((lo + hi) * 0.5, (hi - lo) * 0.5);
                for &k in g.cell_items(c) {
                    let p = &scene.polygons[k as usize];
                    let d = (mid - p.centre).dot(p.normal).abs();
                    assert!(d <= half.dot(p.normal.abs()) * 1.0001, "{name}: polygon {k} far from cell {c}");
                }
            }
        }
    }

    #[test]
    fn macro_regions_hold_only_empty_cells_and_their_cell() {
        for (name, scene, params) in scenes() {
            let g = Grid3::build(&scene, params).unwrap();
            let mut empty = 0;
            for c in 0..g.len() {
                match g.region_of(c) {
                    None => assert!(!g.cell_items(c).is_empty(), "{name}: cell {c} empty without region"),
                    Some(r) => {
                        empty += 1;
                        assert!(g.cell_items(c).is_empty(), "{name}: cell {c} has polygons and a region");
                        let b = g.region(r);
                        assert!(b.contains(g.coords(c)), "{name}: region {r} lacks its cell {c}");
                        for z in b.lo[2]..=b.hi[2] {
                            for y in b.lo[1]..=b.hi[1] {
                                for x in b.lo[0]..=b.hi[0] {
                                    assert!(
                                        g.cell_items(g.index([x, y, z])).is_empty(),
                                        "{name}: region {r} holds non-empty cell {:?}",
                                        [x, y, z]
                                    );
                                }
                            }
                        }
                    }
                }
            }
            assert!(empty > 0 && g.region_count() <= empty, "{name}");
        }
    }

    /// The cells a ray crosses, from the parameters where it crosses grid planes: the cell at
    /// the midpoint of each pair of consecutive crossings (intervals too short to place a point
    /// robustly are skipped). The fine-step reference of the walk.
    fn reference_cells(g: &Grid3, o: DVec3, d: DVec3) -> Vec<(f64, [u32; 3])> {
        let (lo, hi) = g.extent();
        let mut ts = vec![0.0];
        for k in 0..3 {
            if d[k] != 0.0 {
                for i in 0..=g.n[k] {
                    let t = (lo[k] + i as f64 * g.cell_size - o[k]) / d[k];
                    if t > 0.0 {
                        ts.push(t);
                    }
                }
            }
        }
        ts.sort_by(f64::total_cmp);
        let mut out = Vec::new();
        let tol = 1e-7 * (hi - lo).max_element() / d.length();
        for w in ts.windows(2) {
            if w[1] - w[0] > tol {
                let t = 0.5 * (w[0] + w[1]);
                if let Some(c) = g.cell_of(o + d * t) {
                    out.push((t, c));
                }
            }
        }
        out
    }

    #[test]
    fn the_walk_visits_cells_in_order_and_never_skips_a_non_empty_cell() {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        for (name, scene, params) in scenes() {
            let g = Grid3::build(&scene, params).unwrap();
            let (lo, hi) = g.extent();
            for ray in 0..300 {
                let inside = |rng: &mut ChaCha8Rng| {
                    lo + (hi - lo) * DVec3::new(rng.random(), rng.random(), rng.random())
                };
                let mut o = inside(&mut rng);
                if ray % 3 == 0 {
                    // From outside the grid.
                    o = lo + (o - lo) * 3.0 - (hi - lo);
                }
                let mut d = inside(&mut rng) - o;
                if ray % 7 == 0 {
                    d[ray % 3] = 0.0; // parallel to a grid plane
                }
                let mut steps: Vec<Step3> = Vec::new();
                g.walk(o, d, |s| {
                    steps.push(s);
                    true
                });
                for w in steps.windows(2) {
                    assert!(w[0].t_exit <= w[1].t_enter && w[1].t_enter <= w[1].t_exit, "{name} ray {ray}");
                }
                assert!(steps.len() <= g.n.iter().sum::<usize>() + 3, "{name} ray {ray}: too many steps");
                // Every reference cell is covered, in order, by the step whose interval holds it.
                let mut at = 0;
                for (t, c) in reference_cells(&g, o, d) {
                    let covers = |s: &Step3| s.region.map_or(s.coords == c, |r| g.region(r).contains(c));
                    while at < steps.len() && !(covers(&steps[at]) && steps[at].t_exit >= t * (1.0 - 1e-9)) {
                        at += 1;
                    }
                    assert!(
                        at < steps.len(),
                        "{name} ray {ray} ({o} + t {d}): cell {c:?} at t = {t} not visited in order"
                    );
                    let s = steps[at];
                    assert!(s.t_enter <= t * (1.0 + 1e-9) + 1e-12, "{name} ray {ray}: cell {c:?} early");
                    if !g.cell_items(g.index(c)).is_empty() {
                        assert_eq!(s.region, None, "{name} ray {ray}");
                    }
                }
            }
        }
    }

    #[test]
    fn macro_regions_shorten_the_walk_through_empty_space() {
        let scene = generate(20, 32.0, 9).unwrap();
        let g =
            Grid3::build(&scene, Grid3Params { cells_per_polygon: 1.0, cells_per_axis: Some(64) }).unwrap();
        let mut steps = 0;
        let (lo, hi) = g.extent();
        g.walk(lo, hi - lo, |_| {
            steps += 1;
            true
        });
        assert!(steps < 64, "{steps} steps along the diagonal of a 64³ grid");
    }

    #[test]
    fn resolution_follows_lambda_and_is_bounded() {
        let scene = generate(1000, 32.0, 7).unwrap();
        let g = Grid3::build(&scene, Grid3Params::default()).unwrap();
        assert_eq!(g.n, [16, 16, 16], "{:?}", g.n);
        // A huge λ is coarsened to at most 2²² cells, not refused or hung.
        let g = Grid3::build(
            &generate(10, 32.0, 7).unwrap(),
            Grid3Params { cells_per_polygon: 1e12, cells_per_axis: None },
        )
        .unwrap();
        assert!(g.len() <= MAX_GRID3_CELLS && g.len() > MAX_GRID3_CELLS / 2, "{:?}", g.n);
        let g = Grid3::build(&scene, Grid3Params { cells_per_polygon: 1.0, cells_per_axis: Some(100_000) })
            .unwrap();
        assert!(g.len() <= MAX_GRID3_CELLS, "{:?}", g.n);
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let e = Grid3::build(&scene, Grid3Params { cells_per_polygon: bad, cells_per_axis: None });
            assert!(matches!(e, Err(Grid3Error::BadLambda(_))), "λ = {bad}");
        }
    }

    #[test]
    fn too_much_registration_work_is_an_error() {
        // 20000 large squares in a 2²² grid (about 170M candidate columns): refused before the
        // work, not a hang.
        let scene = generate(20_000, 590.0, 3).unwrap();
        let e = Grid3::build(&scene, Grid3Params { cells_per_polygon: 1e9, cells_per_axis: None });
        assert!(matches!(e, Err(Grid3Error::TooMuchWork { .. })), "{:?}", e.map(|g| g.n));
    }

    #[test]
    fn floor_i64_is_floor() {
        let mut rng = ChaCha8Rng::seed_from_u64(12);
        let special =
            [0.0, -0.0, 0.5, -0.5, 1.0, -1.0, -1.5, 2.0f64.powi(62), -(2.0f64.powi(63)), 1e19, -1e19];
        let random = (0..10_000).map(|_| rng.random_range(-1e6..1e6) * 10f64.powi(rng.random_range(-8..8)));
        for x in special
            .into_iter()
            .chain([f64::NAN, f64::INFINITY, f64::NEG_INFINITY, f64::MIN_POSITIVE])
            .chain(random)
        {
            assert_eq!(floor_i64(x), x.floor() as i64, "{x}");
        }
    }

    #[test]
    fn a_flat_scene_gets_a_grid() {
        let p = Polygon::new(vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0)]).unwrap();
        let scene = Scene3 { polygons: vec![p], materials: vec![] };
        let g = Grid3::build(&scene, Grid3Params::default()).unwrap();
        assert!(g.len() >= 1 && g.cell_size > 0.0);
        assert!((0..g.len()).any(|c| g.cell_items(c) == [0]));
    }
}
