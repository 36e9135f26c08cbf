//! The tracers of the golden model: each returns every ray's nearest hit and the paper's counters.
//!
//! * [`Method::Brute`]: every ray against every patch; the oracle.
//! * [`Method::Conventional`]: ray by ray through the grid, each candidate patch loaded per ray.
//! * [`Method::Stochastic`]: shelling S, tracking by neighbourhood estimates (Section 3.1).
//! * [`Method::Deterministic`]: shelling D, tracking by derived per-patch coherence (Section 3.2).
//!
//! All four use the one hit definition of [`crate::geom`], so they agree ray for ray (rung 1 of
//! the equivalence ladder). `INTERPRETATION.md` records every reading of the paper made here.

mod brute;
mod conventional;
pub(crate) mod shelling;

pub use shelling::{ShellParams, ShellStats};

use crate::counters::Counters;
use crate::geom::{
    angle_of, facing, hit_front, Facing, FrontPatch, FrontQuad, Hit, NearestHits, Segment, Vec2,
};
use crate::grid::Grid;
use crate::rays::Bundle;
use std::fmt;
use std::ops::Range;

/// A tracing technique.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// Every ray against every patch (the oracle).
    Brute,
    /// Ray by ray cell traversal; every candidate patch loaded per ray.
    Conventional,
    /// Shelling technique S: sectors, shells and subshells from neighbourhood estimates.
    Stochastic,
    /// Shelling technique D: patches sorted by angle, each matched to its rays.
    Deterministic,
}

impl Method {
    pub const ALL: [Method; 4] =
        [Method::Brute, Method::Conventional, Method::Stochastic, Method::Deterministic];

    pub fn name(self) -> &'static str {
        match self {
            Method::Brute => "brute",
            Method::Conventional => "conventional",
            Method::Stochastic => "stochastic",
            Method::Deterministic => "deterministic",
        }
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// What a tracer returns.
#[derive(Clone, Debug, PartialEq)]
pub struct TraceResult {
    pub method: Method,
    /// The nearest hit of each ray of the bundle, by ray index.
    pub hits: Vec<Option<Hit>>,
    pub counters: Counters,
    /// Shell statistics (zero for the ray-by-ray techniques).
    pub stats: ShellStats,
}

/// The scene as the tracers see it: segments and the grid built over them.
#[derive(Clone, Copy, Debug)]
pub struct SceneView<'a> {
    pub segments: &'a [Segment],
    pub grid: &'a Grid,
}

/// What keeps a trace from running.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TraceError {
    #[error("invalid shell parameters: {0}")]
    InvalidParams(String),
}

/// The per-ray part of the hit test: how a backend tests ray `i` of the bundle against a patch
/// the scheduler has already screened in (front-facing, not backward, not the source's own).
///
/// The tracers decide *which* rays meet *which* patches (the work stream); a `HitTest` decides
/// the answer. It returns a distance key: the hit distance `t` in world units, or any value with
/// the same order (smaller is nearer; equal keys tie and the lower patch index wins).
///
/// The tracers also announce the work stream's other items through the hooks below, in the
/// order they happen (no-ops by default; `crate::workstream` records them for the hardware).
pub trait HitTest {
    /// Whether the backend observes the work-stream hooks ([`HitTest::load`] and the others
    /// below) and so needs them called patch by patch in the order they happen. A backend that
    /// does not (its hooks are the default no-ops) sets it `false`, which lets a tracer take
    /// shortcuts that keep every hit and every counter but not the hooks' order (the
    /// conventional tracer's per-source screening of a cell, `conventional.rs`).
    const HOOKS: bool = true;

    /// Whether [`HitTest::hit`] is [`hit_front`] (the golden model's test), so that a tracer
    /// may take its verdicts from [`FrontQuad::certain_misses`] four patches at a time.
    const GOLDEN: bool = false;

    fn hit(&self, bundle: &Bundle, i: usize, p: u32, seg: &Segment) -> Option<f64>;

    /// [`HitTest::hit`] of patch `p` for the rays `base + k`, one for each set bit `k` of
    /// `rays`, in increasing order: `found(i, key)` is called for each ray `i` that hits. A
    /// backend may override it to share per-patch work between the rays, answering exactly as
    /// `hit` does ray by ray (which the default does).
    #[inline(always)]
    fn hit_rays(
        &self,
        bundle: &Bundle,
        p: u32,
        seg: &Segment,
        base: usize,
        rays: u64,
        mut found: impl FnMut(usize, f64),
    ) {
        for i in set_bits(base, rays) {
            if let Some(t) = self.hit(bundle, i, p, seg) {
                found(i, t);
            }
        }
    }

    /// [`HitTest::hit_rays`] with each hit offered to `nearest` ([`NearestHits::offer`] of
    /// `Hit { t: key, segment: p }`); returns the rays that hit, as bits over `base` like
    /// `rays`. A backend may override it to make the offers of several rays at once, with the
    /// same outcome (which the default has, by construction).
    #[inline(always)]
    fn offer_rays(
        &self,
        bundle: &Bundle,
        p: u32,
        seg: &Segment,
        base: usize,
        rays: u64,
        nearest: &mut NearestHits,
    ) -> u64 {
        let mut hits = 0;
        self.hit_rays(bundle, p, seg, base, rays, nearest.offering(p, base, &mut hits));
        hits
    }

    /// A sector starts: its rays (the conventional technique: one sector of the whole bundle).
    #[inline(always)]
    fn sector(&self, _rays: Range<usize>) {}

    /// Patch `p` is loaded (counted in `patches_read_before_screening`).
    #[inline(always)]
    fn load(&self, _p: u32) {}

    /// Patch `p` (loaded before) is tested against the remaining rays of the non-empty `rays`.
    #[inline(always)]
    fn span(&self, _p: u32, _rays: Range<usize>) {}

    /// Ray `i` leaves the sector's bundle (tracking): no later span tests it.
    #[inline(always)]
    fn retire(&self, _i: usize) {}
}

/// The golden model's backend: exact predicates and `f64` distances ([`hit_front`]).
#[derive(Clone, Copy, Debug, Default)]
pub struct FloatHits;

impl HitTest for FloatHits {
    const HOOKS: bool = false;
    const GOLDEN: bool = true;

    #[inline(always)]
    fn hit(&self, bundle: &Bundle, i: usize, _p: u32, seg: &Segment) -> Option<f64> {
        hit_front(&bundle.rays[i], seg)
    }

    /// The per-patch part of [`hit_front`] once per patch ([`FrontPatch::hit_rays`]).
    #[inline(always)]
    fn hit_rays(
        &self,
        bundle: &Bundle,
        _p: u32,
        seg: &Segment,
        base: usize,
        rays: u64,
        found: impl FnMut(usize, f64),
    ) {
        FrontPatch::new(bundle.source.origin, seg).hit_rays(&bundle.rays, base, rays, found);
    }

    /// The per-patch part of [`hit_front`] once per patch ([`FrontPatch::offer_rays`]).
    #[inline(always)]
    fn offer_rays(
        &self,
        bundle: &Bundle,
        p: u32,
        seg: &Segment,
        base: usize,
        rays: u64,
        nearest: &mut NearestHits,
    ) -> u64 {
        FrontPatch::new(bundle.source.origin, seg).offer_rays(&bundle.rays, p, base, rays, nearest)
    }
}

/// `base + k` for each set bit `k` of `word`, in increasing order.
#[inline(always)]
fn set_bits(base: usize, mut word: u64) -> impl Iterator<Item = usize> {
    std::iter::from_fn(move || {
        (word != 0).then(|| {
            let k = word.trailing_zeros() as usize;
            word &= word - 1;
            base + k
        })
    })
}

/// Traces `bundle` through the scene with `method` in the golden model's `f64` arithmetic. The
/// shell parameters are checked first ([`ShellParams::validate`], and the shell depth against
/// the grid and the source, [`ShellParams::validate_for`]), whichever the method.
pub fn trace(
    method: Method,
    scene: SceneView<'_>,
    bundle: &Bundle,
    params: &ShellParams,
) -> Result<TraceResult, TraceError> {
    trace_with(method, scene, bundle, params, &FloatHits)
}

/// [`trace`] with another backend for the per-ray hit test (the bit-true fixed-point model, say).
pub fn trace_with<H: HitTest>(
    method: Method,
    scene: SceneView<'_>,
    bundle: &Bundle,
    params: &ShellParams,
    hits: &H,
) -> Result<TraceResult, TraceError> {
    params.validate().map_err(TraceError::InvalidParams)?;
    params.validate_for(scene.grid, bundle.source.origin).map_err(TraceError::InvalidParams)?;
    let (hits, mut counters, stats) = match method {
        Method::Brute => {
            let (h, c) = brute::trace(scene, bundle, hits);
            (h, c, ShellStats::default())
        }
        Method::Conventional => {
            let (h, c) = conventional::trace(scene, bundle, hits);
            (h, c, ShellStats::default())
        }
        Method::Stochastic => shelling::trace(scene, bundle, params, shelling::Tracking::Stochastic, hits),
        Method::Deterministic => {
            shelling::trace(scene, bundle, params, shelling::Tracking::Deterministic, hits)
        }
    };
    let (hitting, adlc_true) = hit_summary_below(&hits, scene.segments.len());
    counters.actual_intersections = hitting as u64;
    counters.adlc_true = adlc_true;
    if matches!(method, Method::Brute | Method::Conventional) {
        // These techniques track nothing: their estimate is the true value.
        counters.adlc_estimated = counters.adlc_true;
    }
    Ok(TraceResult { method, hits, counters, stats })
}

/// The average degree of local coherence (Def 2.10) of a set of nearest hits: rays that hit
/// something, over the number of distinct patches they hit. Zero when nothing is hit.
pub fn adlc(hits: &[Option<Hit>]) -> f64 {
    hit_summary(hits).1
}

/// The number of rays that hit something, and the [`adlc`] of `hits`.
fn hit_summary(hits: &[Option<Hit>]) -> (usize, f64) {
    let max = hits.iter().fold(0u32, |m, h| m.max(h.map_or(0, |h| h.segment)));
    hit_summary_below(hits, max as usize + 1)
}

/// [`hit_summary`] of hits whose patch indices lie below `n` (a trace's hits, `n` the scene's
/// patch count), in one pass.
fn hit_summary_below(hits: &[Option<Hit>], n: usize) -> (usize, f64) {
    // Distinct patches: a bit set over the patch indices when it is small against the hits
    // (a miss marks the spare bit `n`, discounted after), else sort and count.
    let (total, distinct) = if n <= 64 * 64 + 64 * hits.len() {
        // Small sets (every scene of up to 4095 patches) live on the stack.
        let words = n / 64 + 1;
        let mut stack = [0u64; 64];
        let mut heap = Vec::new();
        let seen: &mut [u64] = if words <= stack.len() {
            &mut stack[..words]
        } else {
            heap.resize(words, 0);
            &mut heap
        };
        let (mut total, mut distinct, mut last) = (0usize, 0usize, usize::MAX);
        for h in hits {
            total += h.is_some() as usize;
            let id = h.map_or(n, |h| h.segment as usize);
            // Neighbouring rays mostly hit the same patch: skip the set's read-modify-write.
            if id != last {
                if id > n || (id == n && h.is_some()) {
                    // An index not below `n` (not a trace's hits): count the general way.
                    return hit_summary(hits);
                }
                let (w, b) = (id / 64, 1u64 << (id % 64));
                distinct += (seen[w] & b == 0) as usize;
                seen[w] |= b;
                last = id;
            }
        }
        (total, distinct - (total < hits.len()) as usize)
    } else {
        let mut ids: Vec<u32> = hits.iter().flatten().map(|h| h.segment).collect();
        let total = ids.len();
        ids.sort_unstable();
        ids.dedup();
        (total, ids.len())
    };
    if total == 0 {
        return (0, 0.0);
    }
    (total, total as f64 / distinct as f64)
}

/// The outcome of screening one patch for the current source.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Screen {
    Pass,
    Backward,
    BackFacing,
    /// The source's own patch.
    Source,
}

/// What the screener and the tracker know about a patch for one source, computed on first load.
#[derive(Clone, Debug)]
pub(crate) struct PatchInfo {
    pub screen: Screen,
    /// Rays whose angle lies in the patch's (conservatively widened) angular span.
    pub rays: Range<u32>,
    /// A lower bound of the distance from the source to the patch (0, the trivial bound, unless
    /// the cache was asked for it: only the stochastic tracker reads it).
    pub r_min: f64,
    /// Flatness (Def 2.4): the spread of the endpoints' distances from the source.
    pub flatness: f64,
    /// Lower end of the angular span (the deterministic technique sorts by it).
    pub angle_lo: f64,
}

impl PatchInfo {
    const EMPTY: PatchInfo =
        PatchInfo { screen: Screen::Pass, rays: 0..0, r_min: 0.0, flatness: 0.0, angle_lo: 0.0 };
}

/// Screens patch `p` for the bundle's source: the per-patch part of the hit definition, plus the
/// exclusion of the source's own patch.
#[inline]
pub(crate) fn screen(bundle: &Bundle, p: u32, seg: &Segment) -> Screen {
    let src = &bundle.source;
    if src.patch == Some(p) {
        return Screen::Source;
    }
    match facing(src.origin, src.normal, seg) {
        Facing::Front => Screen::Pass,
        Facing::Backward => Screen::Backward,
        Facing::BackFacing => Screen::BackFacing,
    }
}

/// What every load of a patch reads of its per-source information ([`PatchInfo`]), in 16
/// bytes, four patches to a cache line: the tick of the source it was computed for, the ray
/// range, and whether the patch passes the screener (the top bit of `end`; ray indices stay
/// below 2³¹).
#[derive(Clone, Copy, Debug)]
#[repr(C, align(16))]
pub(crate) struct PatchHot {
    pub stamp: u64,
    pub start: u32,
    pub end: u32,
}

impl PatchHot {
    const EMPTY: PatchHot = PatchHot { stamp: 0, start: 0, end: 0 };
    const PASS: u32 = 1 << 31;
}

/// The rest of a patch's [`PatchInfo`], which only the shell's relevant patches are asked for.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PatchCold {
    pub r_min: f64,
    pub flatness: f64,
    pub angle_lo: f64,
}

impl PatchCold {
    const EMPTY: PatchCold = PatchCold { r_min: 0.0, flatness: 0.0, angle_lo: 0.0 };
}

/// What the conventional tracer keeps of a patch, in one 16-byte slot (both words are read at
/// every load of the patch): the tick of the last ray that loaded it (the per-ray mailbox) and
/// the tick of the source its screening verdict is for, shifted left by one, with the verdict
/// (passes the screener) in the low bit. Ticks stay below 2⁶³.
#[derive(Clone, Copy, Debug, Default)]
#[repr(C, align(16))]
pub(crate) struct RayMailbox {
    pub ray: u64,
    pub screened: u64,
}

/// A private cell's patches that pass the screener for one source: `pass_items[start..end]` of
/// [`Scratch`] (and from `pass_quads[quads]` on), valid when `stamp` is the source's tick.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct CellPass {
    pub stamp: u64,
    pub start: u32,
    pub end: u32,
    /// The first of the list's quads in `pass_quads`.
    pub quads: u32,
}

/// Reusable per-thread working memory of the grid tracers, so that tracing a bundle allocates and
/// clears nothing proportional to the scene. Every array holds stamps: an entry is valid only if
/// its stamp equals the tick it is compared with, and ticks (64-bit) are never reused.
#[derive(Default)]
pub(crate) struct Scratch {
    /// The last tick handed out.
    pub tick: u64,
    pub hot: Vec<PatchHot>,
    pub cold: Vec<PatchCold>,
    /// The conventional tracer's per-patch mailbox and screening verdict ([`RayMailbox`]).
    pub mailbox: Vec<RayMailbox>,
    pub patch_stamp: Vec<u64>,
    /// The conventional tracer's per-source screening of private cells ([`CellPass`]).
    pub cell_pass: Vec<CellPass>,
    /// The patches of those cells that pass the screener, in cell order, for this source.
    pub pass_items: Vec<u32>,
    /// The same patches four to a [`FrontQuad`], each cell's list starting a quad.
    pub pass_quads: Vec<FrontQuad>,
    pub cell_stamp: Vec<u64>,
    pub region_stamp: Vec<u64>,
}

impl Scratch {
    /// Grows the arrays to the scene's size.
    fn fit(&mut self, scene: SceneView<'_>) {
        let n = scene.segments.len();
        if self.hot.len() < n {
            self.hot.resize(n, PatchHot::EMPTY);
            self.cold.resize(n, PatchCold::EMPTY);
            self.mailbox.resize(n, RayMailbox::default());
            self.patch_stamp.resize(n, 0);
        }
        if self.cell_stamp.len() < scene.grid.len() {
            self.cell_stamp.resize(scene.grid.len(), 0);
            self.cell_pass.resize(scene.grid.len(), CellPass::default());
        }
        if self.region_stamp.len() < scene.grid.region_count() {
            self.region_stamp.resize(scene.grid.region_count(), 0);
        }
    }
}

thread_local! {
    static SCRATCH: std::cell::RefCell<Scratch> = std::cell::RefCell::new(Scratch::default());
}

/// Runs `f` with this thread's scratch memory, fitted to the scene.
pub(crate) fn with_scratch<R>(scene: SceneView<'_>, f: impl FnOnce(&mut Scratch) -> R) -> R {
    SCRATCH.with(|cell| {
        let mut scratch = cell.borrow_mut();
        scratch.fit(scene);
        f(&mut scratch)
    })
}

/// Per-source cache of [`PatchInfo`], filled lazily as patches are loaded, and the per-sector
/// record of which patches are loaded.
pub(crate) struct ScreenCache<'a> {
    segments: &'a [Segment],
    bundle: &'a Bundle,
    /// Scale of the coordinates, for rounding bounds.
    scale: f64,
    /// The stopping margin ([`Grid::stop_margin`](crate::grid::Grid::stop_margin)).
    margin: f64,
    /// Whether [`PatchInfo::r_min`] is computed (else it is 0).
    with_r_min: bool,
    hot: &'a mut [PatchHot],
    cold: &'a mut [PatchCold],
    /// Per patch, the tick of the sector that last loaded it (a dense array of its own: most
    /// visits of a patch find it loaded already).
    loaded: &'a mut [u64],
    /// The tick that marks this source's entries.
    tick: u64,
}

impl<'a> ScreenCache<'a> {
    pub fn new(
        scene: SceneView<'a>,
        bundle: &'a Bundle,
        hot: &'a mut [PatchHot],
        cold: &'a mut [PatchCold],
        loaded: &'a mut [u64],
        tick: u64,
        with_r_min: bool,
    ) -> Self {
        let (lo, hi) = scene.grid.extent();
        let o = bundle.source.origin;
        let scale = [lo.x, lo.y, hi.x, hi.y, o.x, o.y].iter().fold(1.0f64, |m, v| m.max(v.abs()));
        ScreenCache {
            segments: scene.segments,
            bundle,
            scale,
            margin: scene.grid.stop_margin(),
            with_r_min,
            hot,
            cold,
            loaded,
            tick,
        }
    }

    /// Loads patch `p` in the sector whose tick is `sector`: `None` when the sector has loaded
    /// it already, else whether it passes the screener and the rays of its span (its
    /// information is computed on the source's first load).
    #[inline]
    pub fn load(&mut self, p: u32, sector: u64) -> Option<(bool, Range<u32>)> {
        let i = p as usize;
        if self.loaded[i] == sector {
            return None;
        }
        self.loaded[i] = sector;
        if self.hot[i].stamp != self.tick {
            let info = self.compute(p);
            debug_assert!(info.rays.end < PatchHot::PASS, "ray indices stay below 2^31");
            let pass = if info.screen == Screen::Pass { PatchHot::PASS } else { 0 };
            self.hot[i] = PatchHot { stamp: self.tick, start: info.rays.start, end: info.rays.end | pass };
            self.cold[i] = PatchCold { r_min: info.r_min, flatness: info.flatness, angle_lo: info.angle_lo };
        }
        let h = self.hot[i];
        Some((h.end & PatchHot::PASS != 0, h.start..h.end & !PatchHot::PASS))
    }

    /// The rays of the span of a patch already loaded for this source.
    #[inline]
    pub fn rays(&self, p: u32) -> Range<u32> {
        let h = self.hot[p as usize];
        debug_assert_eq!(h.stamp, self.tick, "patch information is computed on load");
        h.start..h.end & !PatchHot::PASS
    }

    /// The rest of the information about a patch already loaded for this source.
    #[inline]
    pub fn known(&self, p: u32) -> &PatchCold {
        debug_assert_eq!(self.hot[p as usize].stamp, self.tick, "patch information is computed on load");
        &self.cold[p as usize]
    }

    #[cold]
    #[inline(never)]
    fn compute(&self, p: u32) -> PatchInfo {
        let seg = &self.segments[p as usize];
        let screen = screen(self.bundle, p, seg);
        if screen != Screen::Pass {
            // Only relevant patches (which pass) are ever asked for more.
            return PatchInfo { screen, ..PatchInfo::EMPTY };
        }
        let o = self.bundle.source.origin;
        let ra = (seg.a - o).length();
        let rb = (seg.b - o).length();
        let r_min = if self.with_r_min { (seg.distance_to(o) - self.margin).max(0.0) } else { 0.0 };
        let flatness = (ra - rb).abs();
        let (lo, hi) = self.span(seg, ra, rb);
        let r = self.bundle.rays_between(lo, hi);
        PatchInfo { screen, rays: r.start as u32..r.end as u32, r_min, flatness, angle_lo: lo }
    }

    /// The conservative angular span `[lo, hi]` of a front-facing, not backward patch: the
    /// endpoints' angles (the part behind the source's plane clipped away), each widened by a
    /// bound on its rounding error.
    /// `ra` and `rb` are the endpoints' distances from the source, `(a − O).length()` and
    /// `(b − O).length()`.
    fn span(&self, seg: &Segment, ra: f64, rb: f64) -> (f64, f64) {
        use std::f64::consts::FRAC_PI_2;
        let src = &self.bundle.source;
        let (o, n) = (src.origin, src.normal);
        let slack = |r: f64| 1e-12 + 64.0 * f64::EPSILON * self.scale / r.max(f64::MIN_POSITIVE);
        let ha = (seg.a - o).dot(n);
        let hb = (seg.b - o).dot(n);
        let angle = |p: Vec2, r: f64| {
            let (a, e) = (angle_of(o, n, p), slack(r));
            (a - e, a + e)
        };
        if ha > 0.0 && hb > 0.0 {
            let (a0, a1) = angle(seg.a, ra);
            let (b0, b1) = angle(seg.b, rb);
            return (a0.min(b0), a1.max(b1));
        }
        // One endpoint is behind (or on) the plane: the span runs from the front endpoint to the
        // plane on the side where the segment crosses it.
        let (front, rf, hf, hback) = if ha > 0.0 { (seg.a, ra, ha, hb) } else { (seg.b, rb, hb, ha) };
        let back = if ha > 0.0 { seg.b } else { seg.a };
        let cut = front + (back - front) * (hf / (hf - hback));
        let side = (cut - o).dot(crate::geom::perp(n));
        let (f0, f1) = angle(front, rf);
        let tol = 1e-9 * self.scale;
        if side > tol {
            (f0, FRAC_PI_2)
        } else if side < -tol {
            (-FRAC_PI_2, f1)
        } else {
            (-FRAC_PI_2, FRAC_PI_2)
        }
    }
}

/// Offers hit `h` to ray slot `best`.
#[inline]
pub(crate) fn offer(best: &mut Option<Hit>, h: Hit) {
    if crate::geom::closer(h, *best) {
        *best = Some(h);
    }
}
