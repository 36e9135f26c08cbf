//! The shelling techniques S (stochastic) and D (deterministic), Sections 3.1 and 3.2.
//!
//! Both share the structure: the bundle's rays (numbered by angle) are cut into **sectors**,
//! contiguous ray ranges processed one after another. Each sector is cut radially into **shells**
//! of constant depth `Γ`. Shell `j` is the annular sector between radii `[r₁, r₂)` and the angles of
//! the first and last ray still in the sector's bundle (Def 2.6); its cells are listed by
//! rasterising a convex trapezoid that contains it (split into pieces no wider than π/4). Empty
//! cells are skipped a macro-region at a time. Every patch of those
//! cells not yet loaded in this sector is loaded once (counted before screening) and screened:
//! backward, back-facing, the source's own patch, or outside the sector's angular range. The
//! survivors are the shell's relevant patches; they are tested against remaining rays, and at
//! the end of the shell every ray whose nearest hit lies before `r₂` leaves the sector's bundle.
//!
//! The two techniques differ in the **tracking mechanism**, which decides how a shell is cut into
//! subshells (which rays each patch is tested against):
//!
//! * **S** estimates, from the neighbouring shell (the same shell index in the previous sector),
//!   the ADLC and the average flatness of the patches it will meet. It cuts the sector's rays into
//!   angular subshells of `round(ADLC)` rays and the shell into radial subshells of the average
//!   flatness; a patch is tested against all remaining rays of every angular subshell its span
//!   overlaps, in order of radial subshell, and after each radial subshell the rays whose hit
//!   lies before its end leave. Without a neighbour it uses the defaults of [`ShellParams`].
//!   It knows a patch's coherence only up to a subshell, not its position: hence about twice the
//!   actual number of tests (the paper's Nyquist remark).
//! * **D** derives each patch's coherence: the patches of the shell are sorted by angle and each
//!   is tested against exactly the remaining rays inside its angular span.
//!
//! Both size the next sector from the ADLC of the first shell (with relevant patches) of the
//! previous one: `width = clamp(round(α·ADLC), w_min, w_max)`, both with the ADLC derived from
//! that shell's relevant patches once it is traversed (S's own estimate is made before the shell
//! and predicts it). INTERPRETATION.md gives the reasons for each of these readings.
//!
//! # Implementation
//!
//! The counters and statistics are the paper's figures, so everything below only changes how
//! fast the same shells, cells, loads and tests are found; each step says why its answer is the
//! one the plain reading gives.
//!
//! * **Sector state as bit sets** ([`SectorRays`]): the remaining rays and the rays holding a hit
//!   are bit sets over the sector (one word for sectors of up to 64 rays). A shell's boundary
//!   rays, the remaining rays inside a patch's span and the rays to retire come from bit
//!   operations, not from passes over the sector.
//! * **Shells beyond the grid**: per sector (that gets past its first shell), [`cone_reach`]
//!   bounds the distance to any point of the (grown) grid inside the sector's cone. Once a
//!   shell's trapezoid keeps farther than that from the source, it and every later shell of the
//!   sector meet no cell, so they are only counted and retire rays, without rasterising (most
//!   shells of rays that hit nothing).
//! * **Cells**: the trapezoid is rasterised by [`Grid::raster_convex_n`] (the same cells as
//!   `raster_convex`), and each cell is read from the grid's one-entry scan table
//!   ([`Grid::scan_cell`]). Within one piece a cell is met once, so cells are stamped only in
//!   shells of several pieces; the few macro-regions a shell meets are kept in a short list.
//! * **Patches**: [`ScreenCache::load`] checks a dense per-sector stamp first; what a load needs
//!   of a patch's per-source information (computed on its first load) takes 16 bytes, the rest
//!   (read for relevant patches only) lies apart.
//! * **Nearest hits** are kept as two arrays ([`NearestHits`]): each ray's distance key and patch
//!   index, so that a ray's retirement reads one `f64` and neighbouring rays' hits can be
//!   offered together.
//! * **Hit tests** go a word of rays at a time through the backend's `offer_rays`, which tests
//!   and offers the hits. The golden one tests a block of four neighbouring rays per step in
//!   AVX2 lanes on x86-64 CPUs that have it, and makes the block's offers in the lanes too
//!   ([`FrontPatch::offer_rays`]); elsewhere two rays per step in SSE2 lanes
//!   ([`FrontPatch::hit_rays`]). Each lane does the scalar test's operations on the same
//!   operands, and an offer takes the hit exactly when [`closer`] says so.
//! * **Instructions**: on x86-64 CPUs with AVX2 (x86-64-v3 less FMA), the body runs as a copy
//!   compiled for those instructions (`trace_bundle_v3`): the same operations in the same
//!   order, as Rust never fuses a multiply and an add by itself.
//!
//! [`Grid::raster_convex_n`]: crate::grid::Grid::raster_convex_n
//! [`FrontPatch::hit_rays`]: crate::geom::FrontPatch::hit_rays
//! [`FrontPatch::offer_rays`]: crate::geom::FrontPatch::offer_rays
//! [`NearestHits`]: crate::geom::NearestHits
//! [`closer`]: crate::geom::closer
//! [`Grid::scan_cell`]: crate::grid::Grid::scan_cell
//! [`ScreenCache::load`]: super::ScreenCache::load

use super::{with_scratch, HitTest, SceneView, Scratch, ScreenCache};
use crate::counters::Counters;
use crate::geom::{cross, Hit, NearestHits, Segment, Vec2};
use crate::grid::{CellScan, Grid};
use crate::limits::{MAX_BUNDLE_RAYS, MAX_SHELLS};
use crate::rays::Bundle;
use std::f64::consts::FRAC_PI_4;

/// Which tracking mechanism cuts shells into subshells.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Tracking {
    Stochastic,
    Deterministic,
}

/// Parameters of the shell structure. The defaults are the ones every figure uses.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ShellParams {
    /// Shell depth `Γ` in world units; `None` means 4 cell sides.
    pub shell_depth: Option<f64>,
    /// Rays in the first sector (no neighbourhood information yet).
    pub first_sector: usize,
    /// `α`: sector width in rays per unit of ADLC.
    pub sector_per_adlc: f64,
    /// Narrowest sector, in rays.
    pub min_sector: usize,
    /// Widest sector, in rays: the ray memory of one processing element.
    pub max_sector: usize,
    /// ADLC assumed for a shell with no neighbour (S's default angular subshell, in rays).
    pub default_adlc: f64,
    /// Smallest radial subshell, as a fraction of `Γ`.
    pub min_subshell_fraction: f64,
    /// The 3D polar tracer's sector height in Φ-cells (the fixed angle's rows,
    /// `crate::d3::polar`; fewer when the set has fewer cells or the widest sector is narrower).
    /// The 2D tracers do not use it.
    pub phi_cells: usize,
}

impl Default for ShellParams {
    fn default() -> Self {
        ShellParams {
            shell_depth: None,
            first_sector: 16,
            sector_per_adlc: 4.0,
            min_sector: 4,
            max_sector: 64,
            default_adlc: 4.0,
            min_subshell_fraction: 0.125,
            phi_cells: crate::d3::polar::SECTOR_PHI_CELLS,
        }
    }
}

impl ShellParams {
    /// Checks the parameters; the message names the offending one.
    pub fn validate(&self) -> Result<(), String> {
        if let Some(d) = self.shell_depth {
            if !(d.is_finite() && d > 0.0) {
                return Err(format!("shell depth must be a positive number, got {d}"));
            }
        }
        if self.min_sector == 0 || self.min_sector > self.max_sector {
            return Err(format!(
                "sector widths must satisfy 1 <= min ({}) <= max ({})",
                self.min_sector, self.max_sector
            ));
        }
        if self.max_sector > MAX_BUNDLE_RAYS {
            return Err(format!(
                "the widest sector must be at most {MAX_BUNDLE_RAYS} rays, got {}",
                self.max_sector
            ));
        }
        if self.first_sector == 0 || self.first_sector > MAX_BUNDLE_RAYS {
            return Err(format!(
                "the first sector must hold between 1 and {MAX_BUNDLE_RAYS} rays, got {}",
                self.first_sector
            ));
        }
        if !(self.sector_per_adlc.is_finite() && self.sector_per_adlc > 0.0) {
            return Err(format!("sector_per_adlc must be positive, got {}", self.sector_per_adlc));
        }
        if self.phi_cells == 0 || self.phi_cells > MAX_BUNDLE_RAYS {
            return Err(format!(
                "a polar sector must be 1 to {MAX_BUNDLE_RAYS} Φ-cells high, got {}",
                self.phi_cells
            ));
        }
        if !(self.default_adlc.is_finite() && self.default_adlc >= 1.0) {
            return Err(format!("default_adlc must be at least 1, got {}", self.default_adlc));
        }
        if !(self.min_subshell_fraction > 0.0 && self.min_subshell_fraction <= 1.0) {
            return Err(format!(
                "min_subshell_fraction must lie in (0, 1], got {}",
                self.min_subshell_fraction
            ));
        }
        Ok(())
    }

    /// Checks the shell depth against the grid and the source at `origin`: within
    /// [`shell_depth_range`](crate::limits::shell_depth_range) of the grid's larger side and
    /// the distance to its farthest corner, so that shell radii grow past the rounding of
    /// distances and a sector needs at most [`MAX_SHELLS`] shells across the grid.
    pub fn validate_for(&self, grid: &Grid, origin: Vec2) -> Result<(), String> {
        let Some(depth) = self.shell_depth else { return Ok(()) };
        let (lo, hi) = grid.extent();
        let width = (hi - lo).max_element();
        let (near, far) = (grid_near(grid, origin), grid_far(grid, origin));
        crate::limits::check_shell_depth("the shell depth", depth, width, far)?;
        let shells = ((far - near) / depth).ceil() + 1.0;
        if shells > MAX_SHELLS as f64 {
            return Err(format!(
                "the shell depth {depth} cuts the grid into {shells} shells, more than {MAX_SHELLS}"
            ));
        }
        Ok(())
    }
}

/// The distance from `o` to the nearest point of the grid's box (0 inside).
fn grid_near(grid: &Grid, o: Vec2) -> f64 {
    let (lo, hi) = grid.extent();
    (lo - o).max(o - hi).max(Vec2::ZERO).length()
}

/// The distance from `o` to the farthest corner of the grid's box.
fn grid_far(grid: &Grid, o: Vec2) -> f64 {
    let (lo, hi) = grid.extent();
    [lo, hi, Vec2::new(lo.x, hi.y), Vec2::new(hi.x, lo.y)]
        .iter()
        .fold(0.0f64, |m, c| m.max((*c - o).length()))
}

/// Statistics of the shell structure a shelling tracer built.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ShellStats {
    pub sectors: u64,
    /// Shells entered by at least one ray.
    pub shells: u64,
    /// Rays entering shells, summed over shells.
    pub rays_entering: u64,
    /// Rays leaving shells without a hit inside them, summed over shells.
    pub rays_leaving: u64,
}

impl ShellStats {
    /// The measured `S` of Section 4: the fraction of rays leaving a shell.
    pub fn leaving_fraction(&self) -> f64 {
        if self.rays_entering == 0 {
            0.0
        } else {
            self.rays_leaving as f64 / self.rays_entering as f64
        }
    }
}

/// What the tracker remembers of one shell of a sector, for the shell of the same index in the
/// next sector.
#[derive(Clone, Copy, Debug)]
struct ShellEstimate {
    adlc: f64,
    flatness: f64,
}

/// Traces `bundle` by S or D (`tracking`) with the backend `test`: the nearest hit of every ray,
/// the counters and the shell statistics. Sets up the per-source screening cache and the
/// shell stamps on this thread's scratch memory and runs [`trace_bundle`], as
/// [`trace_bundle_v3`] where the CPU has its features.
pub(super) fn trace<H: HitTest>(
    scene: SceneView<'_>,
    bundle: &Bundle,
    params: &ShellParams,
    tracking: Tracking,
    test: &H,
) -> (Vec<Option<Hit>>, Counters, ShellStats) {
    with_scratch(scene, |scratch| {
        let Scratch {
            tick, hot, cold, patch_stamp, cell_stamp: cell_seen, region_stamp: region_seen, ..
        } = scratch;
        *tick += 1;
        // Only the stochastic tracker reads the patches' distances (its radial subshells).
        let with_r_min = tracking == Tracking::Stochastic;
        let cache = ScreenCache::new(scene, bundle, hot, cold, patch_stamp, *tick, with_r_min);
        let geo = ShellGeometry::new(scene.grid, bundle.source.origin, params);
        let view = BundleView { scene, bundle, params, test, geo };
        let marks = ShellMarks { cell_seen, region_seen, regions: RegionSet::new() };
        #[cfg(target_arch = "x86_64")]
        if x86_64_v3() {
            // SAFETY: the CPU has the features `trace_bundle_v3` is compiled for (just checked).
            return unsafe { trace_bundle_v3(&view, tracking, cache, tick, marks) };
        }
        trace_bundle(&view, tracking, cache, tick, marks)
    })
}

/// Whether the CPU has the features of [`trace_bundle_v3`] (and of the 3D tracers' copies).
#[cfg(target_arch = "x86_64")]
pub(crate) fn x86_64_v3() -> bool {
    std::is_x86_feature_detected!("avx")
        && std::is_x86_feature_detected!("avx2")
        && std::is_x86_feature_detected!("bmi1")
        && std::is_x86_feature_detected!("bmi2")
        && std::is_x86_feature_detected!("lzcnt")
        && std::is_x86_feature_detected!("popcnt")
}

/// [`trace_bundle`] compiled for the newer x86-64 CPUs most machines have (x86-64-v3 without
/// FMA): the same operations in the same order, only encoded with more instructions to choose
/// from (three-operand AVX forms, a native population count, ...). Floating-point results
/// cannot change: Rust never contracts a multiply and an add into an FMA, and FMA is not
/// enabled here anyway.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx,avx2,bmi1,bmi2,lzcnt,popcnt")]
fn trace_bundle_v3<H: HitTest>(
    view: &BundleView<'_, H>,
    tracking: Tracking,
    cache: ScreenCache<'_>,
    tick: &mut u64,
    marks: ShellMarks<'_>,
) -> (Vec<Option<Hit>>, Counters, ShellStats) {
    trace_bundle(view, tracking, cache, tick, marks)
}

/// The rays of the current sector `[s, e)` as bit sets over sector-local indices (bit `i % 64`
/// of word `i / 64` stands for ray `s + i`): the rays still in the sector's bundle (`alive`),
/// and those holding a hit (`hit`). Sectors are narrow (a processing element's ray memory), so
/// this is usually one word: finding a shell's boundary rays, visiting the remaining rays of a
/// patch's span and retiring rays cost a few bit operations instead of a pass over the sector.
struct SectorRays {
    s: usize,
    e: usize,
    alive: Vec<u64>,
    hit: Vec<u64>,
    /// Number of set bits of `alive`.
    remaining: usize,
}

impl SectorRays {
    fn new() -> Self {
        SectorRays { s: 0, e: 0, alive: Vec::new(), hit: Vec::new(), remaining: 0 }
    }

    /// Starts sector `[s, e)` with every ray alive and none hit.
    fn start(&mut self, s: usize, e: usize) {
        let n = e - s;
        let words = n.div_ceil(64);
        self.alive.clear();
        self.alive.resize(words, !0);
        if !n.is_multiple_of(64) {
            self.alive[words - 1] = (1u64 << (n % 64)) - 1;
        }
        self.hit.clear();
        self.hit.resize(words, 0);
        (self.s, self.e, self.remaining) = (s, e, n);
    }

    /// The first remaining ray at or after `from`.
    #[inline]
    fn first_alive(&self, from: usize) -> Option<usize> {
        if from >= self.e {
            return None;
        }
        let i = from - self.s;
        let mut w = i / 64;
        let mut bits = self.alive[w] & (!0u64 << (i % 64));
        loop {
            if bits != 0 {
                return Some(self.s + w * 64 + bits.trailing_zeros() as usize);
            }
            w += 1;
            if w == self.alive.len() {
                return None;
            }
            bits = self.alive[w];
        }
    }

    /// The last remaining ray at or before `upto`, given that `from <= upto` is remaining.
    #[inline]
    fn last_alive(&self, from: usize, upto: usize) -> usize {
        let i = upto - self.s;
        let mut w = i / 64;
        let mut bits = self.alive[w] & (!0u64 >> (63 - i % 64));
        while bits == 0 {
            debug_assert!(w > (from - self.s) / 64, "ray {from} is remaining");
            w -= 1;
            bits = self.alive[w];
        }
        self.s + w * 64 + 63 - bits.leading_zeros() as usize
    }

    /// Tests every remaining ray in `[lo, hi)` (within the sector) against patch `p`, offering
    /// each hit to the ray's entry in `best`.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn test_span<H: HitTest>(
        &mut self,
        test: &H,
        bundle: &Bundle,
        seg: &Segment,
        p: u32,
        lo: usize,
        hi: usize,
        best: &mut NearestHits,
        c: &mut Counters,
    ) {
        if lo >= hi {
            return;
        }
        test.span(p, lo..hi);
        let (a, b) = (lo - self.s, hi - self.s);
        for w in a / 64..b.div_ceil(64) {
            let mut word = self.alive[w];
            if w == a / 64 {
                word &= !0u64 << (a % 64);
            }
            if (w + 1) * 64 > b {
                word &= !0u64 >> (64 - b % 64);
            }
            c.intersection_computations += word.count_ones() as u64;
            self.hit[w] |= test.offer_rays(bundle, p, seg, self.s + w * 64, word, best);
        }
    }

    /// Retires the remaining rays whose nearest hit lies before `limit`; returns how many left.
    fn retire<H: HitTest>(&mut self, test: &H, best: &NearestHits, limit: f64) -> usize {
        let mut n = 0;
        for w in 0..self.alive.len() {
            let mut cand = self.alive[w] & self.hit[w];
            while cand != 0 {
                let b = cand.trailing_zeros() as usize;
                cand &= cand - 1;
                // A ray with its bit in `hit` holds a hit: its key is the hit's distance.
                if best.key(self.s + w * 64 + b) < limit {
                    self.alive[w] &= !(1u64 << b);
                    test.retire(self.s + w * 64 + b);
                    n += 1;
                }
            }
        }
        self.remaining -= n;
        n
    }
}

/// An upper bound of the distance from `o` to any point of the box `[lo, hi]` seen within the
/// cone of directions from `ds` counter-clockwise to `de` (an angle below π). The part of the
/// box inside the cone is a convex polygon whose farthest vertex from `o` is a corner of the box
/// inside the cone or the exit point of a boundary ray; corners are admitted with an angular
/// tolerance, so the bound errs only on the large side. `None` when no ray of the cone meets
/// the box.
fn cone_reach(o: Vec2, ds: Vec2, de: Vec2, lo: Vec2, hi: Vec2) -> Option<f64> {
    let mut reach: Option<f64> = None;
    for c in [lo, hi, Vec2::new(lo.x, hi.y), Vec2::new(hi.x, lo.y)] {
        let v = c - o;
        let tol = 1e-9 * v.length();
        if cross(ds, v) >= -tol && cross(v, de) >= -tol {
            reach = Some(reach.unwrap_or(0.0).max(v.length()));
        }
    }
    for d in [ds, de] {
        // Slab test: the ray's parameter range inside the box.
        let (mut t0, mut t1) = (0.0f64, f64::INFINITY);
        for axis in 0..2 {
            let (p, v, l, h) = (o[axis], d[axis], lo[axis], hi[axis]);
            if v == 0.0 {
                if p < l || p > h {
                    t1 = f64::NEG_INFINITY;
                }
            } else {
                let (a, b) = ((l - p) / v, (h - p) / v);
                t0 = t0.max(a.min(b));
                t1 = t1.min(a.max(b));
            }
        }
        if t0 <= t1 {
            reach = Some(reach.unwrap_or(0.0).max(t1));
        }
    }
    reach
}

/// The macro-regions a shell has met. A shell meets a few, so they are kept in a short list
/// (no scattered stamps to touch); past its capacity the set moves into per-region stamps.
struct RegionSet {
    /// The regions met, then [`RegionSet::FREE`] (no region has that id).
    list: [u32; RegionSet::CAP],
    /// Entries of `list` in use; `CAP + 1` once the set lives in the stamps.
    n: usize,
}

impl RegionSet {
    const CAP: usize = 16;
    const FREE: u32 = u32::MAX;

    fn new() -> Self {
        RegionSet { list: [Self::FREE; Self::CAP], n: 0 }
    }

    fn clear(&mut self) {
        self.list = [Self::FREE; Self::CAP];
        self.n = 0;
    }

    /// Adds region `r`; `true` when it is new. `stamps` and `tick` hold the overflow.
    #[inline(always)]
    fn insert(&mut self, r: u32, stamps: &mut [u64], tick: u64) -> bool {
        if self.n <= Self::CAP {
            // The whole list, free entries included: a fixed number of comparisons, without a
            // branch per entry.
            if self.list.iter().fold(false, |found, &q| found | (q == r)) {
                return false;
            }
            if self.n < Self::CAP {
                self.list[self.n] = r;
                self.n += 1;
                return true;
            }
            for &q in &self.list {
                stamps[q as usize] = tick;
            }
            self.n = Self::CAP + 1;
        }
        let new = stamps[r as usize] != tick;
        stamps[r as usize] = tick;
        new
    }
}

/// The constants of a bundle's shell structure, fixed before its first sector.
struct ShellGeometry {
    /// The source.
    o: Vec2,
    /// The shell depth `Γ`.
    depth: f64,
    /// The stopping margin ([`Grid::stop_margin`]).
    margin: f64,
    /// The grid's box.
    lo_box: Vec2,
    hi_box: Vec2,
    /// How far the grid's box is grown where shells are compared against it: more than the
    /// rasteriser's tolerance.
    grow: f64,
    /// The distance to the grid's farthest corner: no shell starts beyond it.
    far: f64,
    /// The shells wholly nearer than the grid, which are only counted.
    skip: u64,
    /// The inner radius of the first shell not skipped.
    r_first: f64,
}

impl ShellGeometry {
    fn new(grid: &Grid, o: Vec2, params: &ShellParams) -> Self {
        let depth = params.shell_depth.unwrap_or(4.0 * grid.cell_size);
        let margin = grid.stop_margin();
        let (lo_box, hi_box) = grid.extent();
        let grow = 2.0 * margin + 1e-9 * (lo_box - o).abs().max((hi_box - o).abs()).max_element();
        // Shells wholly nearer than the grid (a source outside it) meet no cell: the first `skip`
        // shells are only counted. Shell `j < skip` ends at `r₂ = (j + 1)·Γ ≤ skip·Γ`, and its
        // trapezoid (pieces of at most π/4) keeps within `(r₂ + margin) / cos(π/8)` of the source,
        // nearer than the grid grown by `grow` (more than the rasteriser's tolerance). A source
        // inside the grid skips nothing.
        let skip = {
            let near = grid_near(grid, o);
            let inside = (near - grow) * (std::f64::consts::PI / 8.0).cos() * (1.0 - 1e-6) - margin;
            if near > 0.0 && inside > depth {
                (inside / depth).floor() as u64
            } else {
                0
            }
        };
        ShellGeometry {
            o,
            depth,
            margin,
            lo_box,
            hi_box,
            grow,
            far: grid_far(grid, o),
            skip,
            r_first: skip as f64 * depth,
        }
    }

    /// Room for a sector's shells across the grid, so that the common trace does not regrow
    /// the per-shell estimates.
    fn shells_hint(&self) -> usize {
        (self.far / self.depth).ceil().min(1024.0) as usize + 1
    }
}

/// Sector sizing: the next sector's width from the ADLC of the first shell (with relevant
/// patches) of the previous one, `width = clamp(round(α·ADLC), w_min, w_max)`, where the ADLC
/// is the one derived from that shell's relevant patches ([`shell_estimate`]) for both
/// trackers; the first sector has [`ShellParams::first_sector`] rays, and a sector without
/// relevant patches leaves the width as it was.
struct SectorSizing {
    width: usize,
}

impl SectorSizing {
    fn new(params: &ShellParams) -> Self {
        SectorSizing { width: params.first_sector }
    }

    /// The end of the sector that starts at ray `s` of a bundle of `r` rays.
    #[inline(always)]
    fn end(&self, params: &ShellParams, s: usize, r: usize) -> usize {
        (s + self.width.clamp(params.min_sector, params.max_sector)).min(r)
    }

    /// Sizes the next sector from the ADLC of the first shell with relevant patches, if any.
    #[inline(always)]
    fn learn(&mut self, params: &ShellParams, first_adlc: Option<f64>) {
        if let Some(a) = first_adlc {
            self.width = (params.sector_per_adlc * a).round() as usize;
        }
    }
}

/// The cone of one sector `[s, e)`: whether it lies within π/4 (every shell rasterised in one
/// piece), and what tells the shells that lie wholly beyond the grid.
struct SectorCone {
    /// The whole sector lies within π/4. (Rounded differences are monotone, so no narrower pair
    /// of rays can exceed π/4 then.)
    one_piece: bool,
    /// The boundary rays' directions.
    ds: Vec2,
    de: Vec2,
    /// A lower bound of `cos` of half the angle of any piece of a shell.
    cos_lb: f64,
    /// [`cone_reach`] of the grown grid, once worked out.
    reach: Option<f64>,
}

impl SectorCone {
    #[inline(always)]
    fn new(bundle: &Bundle, s: usize, e: usize) -> Self {
        let one_piece = bundle.angles[e - 1] - bundle.angles[s] <= FRAC_PI_4;
        let (ds, de) = (bundle.rays[s].dir, bundle.rays[e - 1].dir);
        let cos_lb = if one_piece {
            (0.5 * (1.0 + ds.dot(de))).max(0.0).sqrt()
        } else {
            (std::f64::consts::PI / 8.0).cos()
        } * (1.0 - 1e-9);
        SectorCone { one_piece, ds, de, cos_lb, reach: None }
    }

    /// Whether the shell starting at `r1`, and so every later one, lies wholly beyond the grid.
    ///
    /// `reach` bounds the distance to any point of the grid (grown by the rasteriser's tolerance
    /// and more) within the sector's cone, and a shell's trapezoid keeps at least
    /// `inner·cos_half ≥ inner·cos_lb` from the source. The first shell keeps no distance from
    /// the source: it is rasterised whatever `reach` is (where the sector's cone misses the grid
    /// it meets no cell either way), so `reach` is only worked out for sectors that get past it.
    #[inline(always)]
    fn beyond(&mut self, geo: &ShellGeometry, r1: f64) -> bool {
        let keeps = (r1 - geo.margin).max(0.0) * self.cos_lb;
        keeps > 0.0 && keeps > self.reach(geo)
    }

    fn reach(&mut self, geo: &ShellGeometry) -> f64 {
        let (ds, de) = (self.ds, self.de);
        *self.reach.get_or_insert_with(|| {
            let grow = Vec2::splat(geo.grow);
            cone_reach(geo.o, ds, de, geo.lo_box - grow, geo.hi_box + grow)
                .map_or(f64::NEG_INFINITY, |t| t * (1.0 + 1e-9) + geo.grow)
        })
    }
}

/// The per-shell stamps of cells and macro-regions met, on this thread's scratch memory: each
/// compared against a fresh tick per shell.
struct ShellMarks<'s> {
    cell_seen: &'s mut [u64],
    region_seen: &'s mut [u64],
    regions: RegionSet,
}

/// The running estimate of the ADLC the tracking mechanism worked with: each shell's value
/// weighted by its number of relevant patches ([`Counters::adlc_estimated`]).
#[derive(Default)]
struct AdlcEstimate {
    sum: f64,
    weight: f64,
}

impl AdlcEstimate {
    #[inline(always)]
    fn add(&mut self, adlc: f64, patches: usize) {
        self.sum += adlc * patches as f64;
        self.weight += patches as f64;
    }

    fn mean(&self) -> f64 {
        if self.weight > 0.0 {
            self.sum / self.weight
        } else {
            0.0
        }
    }
}

/// What every step of one bundle's trace reads and does not change.
struct BundleView<'a, H> {
    scene: SceneView<'a>,
    bundle: &'a Bundle,
    params: &'a ShellParams,
    test: &'a H,
    geo: ShellGeometry,
}

/// What the steps of one bundle's trace change: the current sector's rays, every ray's nearest
/// hit, the counters, the tracker's running estimate and the current shell's relevant patches.
struct BundleState {
    rays: SectorRays,
    best: NearestHits,
    c: Counters,
    estimate: AdlcEstimate,
    relevant: Vec<u32>,
}

/// The body of [`trace`], on this thread's scratch memory: `marks` holds stamps compared
/// against a fresh tick per shell, the cache's load stamps one per sector.
///
/// Sector after sector ([`SectorSizing`]), shell after shell: a shell wholly beyond the grid
/// only retires rays ([`pass_beyond_grid`]); any other is loaded ([`load_shell`]), its
/// relevant patches tested by the tracking mechanism ([`track_stochastic`],
/// [`track_deterministic`]), and the rays whose hit lies before its end retired.
#[inline(always)]
fn trace_bundle<H: HitTest>(
    view: &BundleView<'_, H>,
    tracking: Tracking,
    mut cache: ScreenCache<'_>,
    tick: &mut u64,
    mut marks: ShellMarks<'_>,
) -> (Vec<Option<Hit>>, Counters, ShellStats) {
    let (bundle, params, test, geo) = (view.bundle, view.params, view.test, &view.geo);
    let r = bundle.len();
    let mut stats = ShellStats::default();
    // Room for a shell's relevant patches, so that the common trace does not regrow them.
    let mut st = BundleState {
        rays: SectorRays::new(),
        best: NearestHits::new(r),
        c: Counters::default(),
        estimate: AdlcEstimate::default(),
        relevant: Vec::with_capacity(256),
    };
    let mut prev: Vec<Option<ShellEstimate>> = Vec::with_capacity(geo.shells_hint());
    let mut cur: Vec<Option<ShellEstimate>> = Vec::with_capacity(geo.shells_hint());
    let mut sizing = SectorSizing::new(params);
    let mut s = 0usize;

    while s < r {
        let e = sizing.end(params, s, r);
        stats.sectors += 1;
        *tick += 1;
        let sector = *tick;
        st.rays.start(s, e);
        test.sector(s..e);
        let mut cone = SectorCone::new(bundle, s, e);
        cur.clear();
        let mut first_adlc: Option<f64> = None;
        let mut r1 = geo.r_first;
        if geo.skip > 0 {
            stats.shells += geo.skip;
            stats.rays_entering += geo.skip * st.rays.remaining as u64;
            stats.rays_leaving += geo.skip * st.rays.remaining as u64;
        }
        // The shell index relative to the first one not skipped (the same in every sector).
        let mut j = 0usize;
        while st.rays.remaining > 0 && r1 < geo.far {
            if cone.beyond(geo, r1) {
                pass_beyond_grid(view, r1, &mut st, &mut stats, &mut cur);
                break;
            }
            let r2 = r1 + geo.depth;
            *tick += 1;
            let shell_gen = *tick;
            stats.shells += 1;
            stats.rays_entering += st.rays.remaining as u64;

            load_shell(view, &cone, r1, r2, sector, shell_gen, &mut cache, &mut marks, &mut st);
            let here = shell_estimate(&st.relevant, &cache);
            match tracking {
                Tracking::Stochastic => {
                    track_stochastic(view, prev.get(j).copied().flatten(), r1, &cache, &mut st)
                }
                Tracking::Deterministic => track_deterministic(view, here, &cache, &mut st),
            }

            // End of shell: rays whose nearest hit lies before r₂ are done.
            st.rays.retire(test, &st.best, r2 - geo.margin);
            stats.rays_leaving += st.rays.remaining as u64;
            if here.is_some() && first_adlc.is_none() {
                first_adlc = here.map(|h| h.adlc);
            }
            cur.push(here);
            r1 = r2;
            j += 1;
        }
        // Rays still remaining have left the grid: they hit nothing (or already hold a hit
        // beyond the last shell, which cannot happen as every patch lies inside the grid).
        sizing.learn(params, first_adlc);
        std::mem::swap(&mut prev, &mut cur);
        s = e;
    }
    st.c.adlc_estimated = st.estimate.mean();
    (st.best.into_hits(), st.c, stats)
}

/// The shell starting at `r1` and all later ones of the sector lie beyond the grid: they meet
/// no cell and no patch, so each only retires rays (those holding a hit do so at once, as every
/// hit lies within the cone's reach) and is recorded as a shell without patches.
#[inline(always)]
fn pass_beyond_grid<H: HitTest>(
    view: &BundleView<'_, H>,
    mut r1: f64,
    st: &mut BundleState,
    stats: &mut ShellStats,
    cur: &mut Vec<Option<ShellEstimate>>,
) {
    let geo = &view.geo;
    let BundleState { rays, best, .. } = st;
    loop {
        let r2 = r1 + geo.depth;
        stats.shells += 1;
        stats.rays_entering += rays.remaining as u64;
        rays.retire(view.test, best, r2 - geo.margin);
        stats.rays_leaving += rays.remaining as u64;
        cur.push(None);
        r1 = r2;
        if !(rays.remaining > 0 && r1 < geo.far) {
            break;
        }
    }
}

/// Shell loading: lists the cells of the shell `[r1, r2)` over the sector's remaining rays,
/// loads every patch of them not yet loaded in this sector (counted before screening, announced
/// to the backend) and leaves in `relevant` those that pass the screener and whose span meets
/// the sector, in the order met.
///
/// The shell spans the remaining rays' angles (Def 2.6: two boundary angles), in pieces no wider
/// than π/4, each from a remaining ray to the last one within π/4; each piece is rasterised as
/// the trapezoid between its boundary rays from `r1` to beyond `r2` (its outer edge tangent to
/// the arc of radius `r2` at the piece's middle angle), grown by the stopping margin. An empty
/// cell's whole macro-region is skipped and counted once per shell.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn load_shell<H: HitTest>(
    view: &BundleView<'_, H>,
    cone: &SectorCone,
    r1: f64,
    r2: f64,
    sector: u64,
    shell_gen: u64,
    cache: &mut ScreenCache<'_>,
    marks: &mut ShellMarks<'_>,
    st: &mut BundleState,
) {
    let BundleState { rays, c, relevant, .. } = st;
    let (grid, bundle, test, o, margin) =
        (view.scene.grid, view.bundle, view.test, view.geo.o, view.geo.margin);
    let (s, e, one_piece) = (rays.s, rays.e, cone.one_piece);
    let ShellMarks { cell_seen, region_seen, regions } = marks;
    relevant.clear();
    regions.clear();
    let mut k = s;
    while let Some(k0) = rays.first_alive(k) {
        let mut m = k0;
        if one_piece {
            m = e - 1;
        } else {
            while m + 1 < e && bundle.angles[m + 1] - bundle.angles[k0] <= FRAC_PI_4 {
                m += 1;
            }
        }
        let last = rays.last_alive(k0, m);
        k = m + 1;
        let (da, db) = (bundle.rays[k0].dir, bundle.rays[last].dir);
        let cos_half = (0.5 * (1.0 + da.dot(db))).max(0.0).sqrt();
        let inner = (r1 - margin).max(0.0);
        let outer = (r2 + margin) / cos_half;
        let poly = [o + da * inner, o + da * outer, o + db * outer, o + db * inner];
        grid.raster_convex_n(&poly, |iy, x0, x1| {
            let mut ix = x0;
            while ix <= x1 {
                let cell = iy * grid.nx + ix;
                let items = match grid.scan_cell(cell) {
                    CellScan::Empty { region, x1 } => {
                        if regions.insert(region, region_seen, shell_gen) {
                            c.cells_traversed += 1;
                        }
                        ix = x1 as usize + 1;
                        continue;
                    }
                    CellScan::Items(items) => items,
                };
                ix += 1;
                // A piece's rows are disjoint and a row meets each cell once, so only a shell of
                // several pieces can meet a cell twice.
                if !one_piece {
                    if cell_seen[cell] == shell_gen {
                        continue;
                    }
                    cell_seen[cell] = shell_gen;
                }
                c.cells_traversed += 1;
                for &p in items {
                    let Some((pass, rays)) = cache.load(p, sector) else { continue };
                    c.patches_read_before_screening += 1;
                    test.load(p);
                    let in_sector = (rays.start as usize) < e && (rays.end as usize) > s;
                    if pass && in_sector {
                        c.patches_read_after_screening += 1;
                        relevant.push(p);
                    }
                }
            }
        });
    }
}

/// What a shell's relevant patches tell (Section 3.1): each one's spanning angle, in rays,
/// estimates its degree of local coherence. Their mean is D's ADLC and sizes the next sector
/// ([`SectorSizing`]); with the mean flatness it is what S starts from in the shell of the same
/// index of the next sector. `None` for a shell without relevant patches.
#[inline(always)]
fn shell_estimate(relevant: &[u32], cache: &ScreenCache<'_>) -> Option<ShellEstimate> {
    let mut dlc_sum = 0usize;
    let mut flat_sum = 0.0;
    for &p in relevant {
        dlc_sum += cache.rays(p).len();
        flat_sum += cache.known(p).flatness;
    }
    (!relevant.is_empty()).then(|| ShellEstimate {
        adlc: dlc_sum as f64 / relevant.len() as f64,
        flatness: flat_sum / relevant.len() as f64,
    })
}

/// The stochastic tracking mechanism (S): neighbourhood estimates. From the neighbouring shell
/// (the same shell index in the previous sector; without one, [`ShellParams::default_adlc`]
/// and the shell depth) it takes the ADLC and the average flatness, cuts the sector's rays into
/// angular subshells of `round(ADLC)` rays and the shell into radial subshells of the flatness
/// (at least [`ShellParams::min_subshell_fraction`] of the depth). The relevant patches, in
/// order of their nearest point, each join the radial subshell of their `r_min` (the last one
/// for patches reaching beyond the shell); each is tested against all remaining rays of every
/// angular subshell its span overlaps, and as a radial subshell closes the rays hit before its
/// end leave.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn track_stochastic<H: HitTest>(
    view: &BundleView<'_, H>,
    neighbour: Option<ShellEstimate>,
    r1: f64,
    cache: &ScreenCache<'_>,
    st: &mut BundleState,
) {
    let BundleState { rays, best, c, estimate, relevant } = st;
    let (params, depth, margin) = (view.params, view.geo.depth, view.geo.margin);
    let (s, e) = (rays.s, rays.e);
    let adlc = neighbour.map_or(params.default_adlc, |x| x.adlc);
    let flat = neighbour.map_or(depth, |x| x.flatness);
    if !relevant.is_empty() {
        estimate.add(adlc, relevant.len());
    }
    let group = (adlc.round() as usize).max(1);
    let step = flat.clamp(depth * params.min_subshell_fraction, depth);
    let bins = ((depth / step).ceil() as usize).max(1);
    relevant.sort_unstable_by(|&a, &b| cache.known(a).r_min.total_cmp(&cache.known(b).r_min).then(a.cmp(&b)));
    let mut bin = 0usize;
    for &p in relevant.iter() {
        let pb = (((cache.known(p).r_min - r1) / step).floor().max(0.0) as usize).min(bins - 1);
        while bin < pb {
            // Close radial subshell `bin`: rays hit before its end are done.
            bin += 1;
            let end = r1 + bin as f64 * step;
            rays.retire(view.test, best, end - margin);
        }
        let span = cache.rays(p);
        let lo = (span.start as usize).max(s);
        let hi = (span.end as usize).min(e);
        if lo >= hi {
            continue;
        }
        let g0 = s + (lo - s) / group * group;
        let g1 = (s + ((hi - 1 - s) / group + 1) * group).min(e);
        let seg = &view.scene.segments[p as usize];
        rays.test_span(view.test, view.bundle, seg, p, g0, g1, best, c);
    }
}

/// The deterministic tracking mechanism (D): per-patch derived coherence. The shell's own
/// relevant patches give its ADLC (`here`); sorted by angle, each is tested against exactly the
/// remaining rays inside its angular span.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn track_deterministic<H: HitTest>(
    view: &BundleView<'_, H>,
    here: Option<ShellEstimate>,
    cache: &ScreenCache<'_>,
    st: &mut BundleState,
) {
    let BundleState { rays, best, c, estimate, relevant } = st;
    let (s, e) = (rays.s, rays.e);
    if let Some(h) = here {
        estimate.add(h.adlc, relevant.len());
    }
    relevant.sort_unstable_by(|&a, &b| {
        cache.known(a).angle_lo.total_cmp(&cache.known(b).angle_lo).then(a.cmp(&b))
    });
    for &p in relevant.iter() {
        let span = cache.rays(p);
        let lo = (span.start as usize).max(s);
        let hi = (span.end as usize).min(e);
        let seg = &view.scene.segments[p as usize];
        rays.test_span(view.test, view.bundle, seg, p, lo, hi, best, c);
    }
}
