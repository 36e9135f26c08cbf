//! The 3D tracers: every ray of a bundle's nearest hit, and the paper's counters (the 2D
//! [`Counters`], same names and meanings).
//!
//! * [`brute`]: every ray against every polygon that passes the screener; the oracle.
//! * [`conventional`]: ray by ray through the [`Grid3`] (empty space by macro-region jumps);
//!   every polygon registered in every non-empty cell the ray enters is loaded for that ray and,
//!   if it passes the screener, tested.
//!
//! # The hit definition
//!
//! A bundle ([`Bundle3`]) is a source point `O` with a unit normal `n_s` (a point on a patch and
//! the patch's normal), optionally the index of the source's own patch, and ray directions (a
//! [`HemisphereRays`] set, or any directions). Ray `i` hits polygon `P` when `P` passes the
//! screener for the source and [`super::brute::intersect`] hits it; its nearest hit is the hit of
//! smallest `t`, of equal `t` the polygon of lowest index (as [`super::brute::nearest`]).
//!
//! **Backface screening**, per polygon and source, before any test, as in 2D
//! (`crate::trace::screen`): `P` is screened out when it is
//!
//! * the source's own patch ([`Screen3::Source`]);
//! * *backward*: wholly behind the source's plane, every vertex `v` with `(v − O) · n_s ≤ 0`
//!   (Def. 2.2; [`Screen3::Backward`]);
//! * *back-facing*: the source lies behind `P`'s plane or on it, `(O − O_P) · n_P ≤ 0` with
//!   `O_P` its centre (the plane the hit rule intersects), so every ray would meet it from behind
//!   ([`Screen3::BackFacing`]).
//!
//! So every hit the tracers report is on a polygon's front side ([`Hit::front`] is true). Both
//! tracers screen by the same function and test by the same function, so they agree ray for ray
//! (rung 1).
//!
//! **How a pair is decided, fast.** Both tracers test through the scene's polygons prepared once
//! per grid ([`Facets`], [`Grid3::facets`]): [`Facets::hit`] does
//! [`super::brute::intersect`]'s operations on the same operands, so it gives the same bits.
//! Before it, a polygon's bounding cone from the source ([`Cone`]) rules out the rays that pass
//! far from it, conservatively (the rounding bounded), and a plane beyond the ray's nearest hit so
//! far is not tested inside (its hit could not be taken). Brute force runs the cones and the
//! planes four polygons at a time in AVX lanes, nearest polygons first, and its edge tests
//! through a per-source filter that falls back on the hit rule's own operations near the
//! thresholds ([`FacetQuads`]); for a source with many polygons it lists them once by direction
//! (a cube map of directions, each polygon in the cells its cone can let a ray through), and a ray
//! visits only its own cell's polygons. A pair ruled out by a cone, a cell or a bound is still a
//! test: it is decided, and the counters count it as before.
//!
//! # Counters
//!
//! * `patches_read_before_screening`: brute `R·N`; conventional, the distinct polygons of the
//!   non-empty cells a ray enters, per ray (a per-ray mailbox loads a polygon listed in several
//!   cells once per ray).
//! * `patches_read_after_screening`: the loaded polygons that pass the screener; each is tested,
//!   so `intersection_computations` is the same number.
//! * `cells_traversed`: walk steps (a macro-region jump counts once); 0 for brute.
//! * `actual_intersections`: the rays that hit something.
//! * `adlc_true` = `adlc_estimated`: Def. 2.10 over the nearest hits, the rays that hit over the
//!   distinct polygons they hit (0 when nothing is hit); neither tracer tracks anything.
//!
//! # Stopping
//!
//! The conventional walk stops after the first cell (or region) whose exit distance exceeds the
//! nearest hit found so far by more than the stopping margin, [`Grid3::stop_margin`] divided by
//! the ray direction's length (`4·eps` in world units, `eps` the registration margin). A hit's
//! point and a cell's exit are each rounded by far less than `eps`, so every polygon whose hit
//! could be nearer than or tie with the best so far lies in a cell already visited, and exact
//! ties across a cell boundary are still resolved by index.

use super::brute::{Cone, FacetQuads, Facets, Hit};
use super::grid::Grid3;
use super::hemisphere::HemisphereRays;
use super::scene::{Polygon, Scene3};
use crate::counters::Counters;
use crate::trace::ShellParams;
use glam::DVec3;

/// The source of a bundle: a point with a unit normal, and the patch it lies on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Source3 {
    pub origin: DVec3,
    /// The unit normal of the source's hemisphere.
    pub normal: DVec3,
    /// The source's own patch, never hit.
    pub patch: Option<usize>,
}

/// How a bundle's rays are stratified in (Θ, Φ): the numbering of [`HemisphereRays`] (ray `k`
/// is band `k / n_phi`, cell `k % n_phi`), which the polar and sweep tracers need.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout3 {
    /// The number of Θ-bands; band `i`'s rays have `Θ = (i + ½)·2π/n_theta`.
    pub n_theta: usize,
    /// The number of Φ-cells per band.
    pub n_phi: usize,
    /// The frame's first tangent (`Θ = 0`).
    pub tangent: DVec3,
    /// The frame's second tangent (`Θ = π/2`).
    pub bitangent: DVec3,
    /// The `Φ` of the rays of cell `j`, increasing in `j` (the same in every band).
    pub phi: Vec<f64>,
}

/// A bundle of rays from one source.
#[derive(Clone, Debug, PartialEq)]
pub struct Bundle3 {
    pub source: Source3,
    /// The ray directions (need not be unit; `t` is in units of each direction's length).
    pub directions: Vec<DVec3>,
    /// The (Θ, Φ) stratification of the directions, when they are a hemisphere set's (unit
    /// directions, in its numbering); `None` for free directions, which only the brute and
    /// conventional tracers take.
    pub layout: Option<Layout3>,
}

impl Bundle3 {
    /// The layout the polar and sweep tracers (`method`) need, checked against the directions:
    /// `n_theta × n_phi` unit directions and `n_phi` increasing angles.
    pub(crate) fn layout_for(&self, method: Method3) -> Result<&Layout3, Trace3Error> {
        let l = self.layout.as_ref().ok_or(Trace3Error::NoLayout(method))?;
        if l.n_theta.checked_mul(l.n_phi) != Some(self.directions.len()) || l.phi.len() != l.n_phi {
            return Err(Trace3Error::BadLayout(format!(
                "{} × {} cells with {} angles for {} directions",
                l.n_theta,
                l.n_phi,
                l.phi.len(),
                self.directions.len()
            )));
        }
        if let Some(i) = self
            .directions
            .iter()
            .position(|d| (d.length() - 1.0).abs().partial_cmp(&1e-12) != Some(std::cmp::Ordering::Less))
        {
            return Err(Trace3Error::BadLayout(format!("direction {i} is not a unit vector")));
        }
        if !l.phi.windows(2).all(|w| w[0] < w[1]) {
            return Err(Trace3Error::BadLayout("the cells' angles do not increase".to_string()));
        }
        Ok(l)
    }

    /// The bundle of a hemisphere ray set leaving from patch `patch`.
    pub fn from_hemisphere(rays: &HemisphereRays, patch: Option<usize>) -> Bundle3 {
        Bundle3 {
            source: Source3 { origin: rays.origin, normal: rays.normal, patch },
            directions: rays.rays.iter().map(|r| r.direction).collect(),
            layout: Some(Layout3 {
                n_theta: rays.n_theta,
                n_phi: rays.n_phi,
                tangent: rays.tangent,
                bitangent: rays.bitangent,
                phi: rays.rays[..rays.n_phi].iter().map(|r| r.phi).collect(),
            }),
        }
    }

    /// The number of rays.
    pub fn len(&self) -> usize {
        self.directions.len()
    }

    pub fn is_empty(&self) -> bool {
        self.directions.is_empty()
    }
}

/// The screener's verdict on a polygon for a source (module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Screen3 {
    /// May be hit by the source's rays.
    Pass,
    /// Wholly behind the source's plane.
    Backward,
    /// The source lies behind the polygon's plane or on it.
    BackFacing,
    /// The source's own patch.
    Source,
}

/// Screens polygon `k` for `source` (module docs).
pub fn screen(source: &Source3, k: usize, polygon: &Polygon) -> Screen3 {
    if source.patch == Some(k) {
        Screen3::Source
    } else if polygon.vertices.iter().all(|v| (*v - source.origin).dot(source.normal) <= 0.0) {
        Screen3::Backward
    } else if (source.origin - polygon.centre).dot(polygon.normal) <= 0.0 {
        Screen3::BackFacing
    } else {
        Screen3::Pass
    }
}

/// Whether polygon `k` passes the screener for `source`: `screen(source, k, polygon) ==
/// Screen3::Pass`, the same comparisons (a NaN fails `≤` as there), the cheapest first.
#[inline(always)]
pub(crate) fn passes(source: &Source3, k: usize, polygon: &Polygon) -> bool {
    // `x ≤ 0` fails: `x > 0` or `x` is a NaN.
    let above = |x: f64| x > 0.0 || x.is_nan();
    source.patch != Some(k)
        && above((source.origin - polygon.centre).dot(polygon.normal))
        && polygon.vertices.iter().any(|v| above((*v - source.origin).dot(source.normal)))
}

/// A 3D tracing technique.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method3 {
    /// Every ray against every polygon (the oracle).
    Brute,
    /// Ray by ray through the 3D grid.
    Conventional,
    /// The paper's direct extension: sectors in (Θ, Φ), shells of constant depth, subshells
    /// from the neighbouring shell (`super::polar`).
    Polar,
    /// The paper's second extension: a plane rotated about the normal, the 2D deterministic
    /// technique in each plane (`super::sweep`).
    Sweep,
}

impl Method3 {
    /// Every 3D technique, in the order the tables list them.
    pub const ALL: [Method3; 4] = [Method3::Brute, Method3::Conventional, Method3::Polar, Method3::Sweep];

    /// The technique's name on the command line and in tables.
    pub fn name(self) -> &'static str {
        match self {
            Method3::Brute => "brute",
            Method3::Conventional => "conventional",
            Method3::Polar => "polar",
            Method3::Sweep => "sweep",
        }
    }
}

/// Why a 3D trace cannot run.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Trace3Error {
    /// The polar and sweep tracers need the (Θ, Φ) numbering of a hemisphere set.
    #[error("the {0} tracer needs a hemisphere ray set (stratified in Θ and Φ), not free directions")]
    NoLayout(Method3),
    /// The layout does not describe the directions.
    #[error("the bundle's layout does not fit its directions: {0}")]
    BadLayout(String),
    /// The sweep plane holds two opposite Θ-bands, so their number must be even.
    #[error("the sweep tracer needs an even number of Θ-bands (a plane holds two opposite bands), got {0}")]
    OddBands(usize),
    /// The shell parameters are invalid (the message names the parameter).
    #[error("invalid shell parameters: {0}")]
    InvalidParams(String),
}

impl std::fmt::Display for Method3 {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// What a tracer returns.
#[derive(Clone, Debug, PartialEq)]
pub struct Trace3 {
    /// The nearest hit of each ray, by ray index.
    pub hits: Vec<Option<Hit>>,
    pub counters: Counters,
}

/// Offers hit `(k, t)` to `best`: nearer wins, of equal `t` the lower index.
#[inline]
pub(crate) fn offer(best: &mut Option<Hit>, k: usize, t: f64, front: bool) {
    if best.is_none_or(|b| t < b.t || (t == b.t && k < b.polygon)) {
        *best = Some(Hit { polygon: k, t, front });
    }
}

/// The average degree of local coherence (Def. 2.10) of a set of nearest hits: the rays that
/// hit over the distinct polygons they hit (0 when nothing is hit).
pub fn adlc3(hits: &[Option<Hit>]) -> f64 {
    let mut ids: Vec<usize> = hits.iter().flatten().map(|h| h.polygon).collect();
    let total = ids.len();
    ids.sort_unstable();
    ids.dedup();
    if total == 0 {
        0.0
    } else {
        total as f64 / ids.len() as f64
    }
}

/// Fills in the counters every tracer shares: actual intersections and the ADLC; the estimate
/// is the true value for a tracer that tracks nothing (`estimate` `None`).
pub(crate) fn finish(hits: Vec<Option<Hit>>, mut counters: Counters, estimate: Option<f64>) -> Trace3 {
    counters.actual_intersections = hits.iter().flatten().count() as u64;
    counters.adlc_true = adlc3(&hits);
    counters.adlc_estimated = estimate.unwrap_or(counters.adlc_true);
    Trace3 { hits, counters }
}

/// The bound to pass [`Facets::hit`] for a ray whose nearest hit so far is `best`: a hit beyond
/// it could not be taken.
#[inline]
fn bound(best: &Option<Hit>) -> f64 {
    best.map_or(f64::INFINITY, |b| b.t)
}

/// Every ray against every polygon that passes the screener: the oracle.
pub fn brute(scene: &Scene3, bundle: &Bundle3) -> Trace3 {
    brute_with(scene, &Facets::new(scene), bundle)
}

/// Runs `$body(args)` through a copy of it compiled for x86-64-v3 without FMA where the CPU has
/// those features: the same operations in the same order, encoded with more instructions to
/// choose from (as the 2D shelling tracers' copy, `trace_bundle_v3`), so the same bits.
macro_rules! on_v3 {
    ($body:ident($($arg:ident: $ty:ty),*) -> $ret:ty) => {{
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx,avx2,bmi1,bmi2,lzcnt,popcnt")]
        fn v3($($arg: $ty),*) -> $ret {
            $body($($arg),*)
        }
        #[cfg(target_arch = "x86_64")]
        if crate::trace::shelling::x86_64_v3() {
            // SAFETY: the CPU has the features `v3` is compiled for (just checked).
            return unsafe { v3($($arg),*) };
        }
        $body($($arg),*)
    }};
}

/// [`brute`] with the scene's polygons already prepared.
pub(crate) fn brute_with(scene: &Scene3, facets: &Facets, bundle: &Bundle3) -> Trace3 {
    on_v3!(brute_body(scene: &Scene3, facets: &Facets, bundle: &Bundle3) -> Trace3)
}

#[inline(always)]
fn brute_body(scene: &Scene3, facets: &Facets, bundle: &Bundle3) -> Trace3 {
    let passing: Vec<usize> =
        (0..scene.polygons.len()).filter(|&k| passes(&bundle.source, k, &scene.polygons[k])).collect();
    let r = bundle.len() as u64;
    let mut c = Counters {
        patches_read_before_screening: r * scene.polygons.len() as u64,
        patches_read_after_screening: r * passing.len() as u64,
        ..Counters::default()
    };
    c.intersection_computations = c.patches_read_after_screening;
    let o = bundle.source.origin;
    let quads = FacetQuads::new(facets, o, &passing);
    let mut hits = Vec::with_capacity(bundle.len());
    for &d in &bundle.directions {
        let mut best = None;
        quads.offer_hits(facets, o, d, &mut best);
        hits.push(best);
    }
    finish(hits, c, None)
}

/// What the conventional tracer knows of a polygon for the current source: the ray that last
/// loaded it, plus one (the per-ray mailbox), its screening verdict and, once it passed, its
/// bounding cone from the source ([`Cone`]), which rules out most rays before the hit rule.
#[derive(Clone, Copy)]
struct Slot {
    stamp: u32,
    /// 0 not yet screened, 1 passes, 2 screened out.
    verdict: u8,
    cone: Cone,
}

/// Ray by ray through `grid` (built over `scene`), see the module docs.
pub fn conventional(scene: &Scene3, grid: &Grid3, bundle: &Bundle3) -> Trace3 {
    debug_assert_eq!(grid.facets().len(), scene.polygons.len(), "the grid is built over the scene");
    on_v3!(conventional_body(scene: &Scene3, grid: &Grid3, bundle: &Bundle3) -> Trace3)
}

#[inline(always)]
fn conventional_body(scene: &Scene3, grid: &Grid3, bundle: &Bundle3) -> Trace3 {
    let facets = grid.facets();
    let mut slots = vec![Slot { stamp: 0, verdict: 0, cone: Cone::NONE }; scene.polygons.len()];
    let mut c = Counters::default();
    let o = bundle.source.origin;
    let mut hits = Vec::with_capacity(bundle.len());
    for (r, &d) in bundle.directions.iter().enumerate() {
        let stamp = r as u32 + 1;
        let margin = grid.stop_margin() / d.length();
        let dd = d.dot(d);
        let mut best: Option<Hit> = None;
        let mut walk = grid.walker(o, d);
        while let Some(step) = walk.next(grid) {
            c.cells_traversed += 1;
            if step.region.is_none() {
                for &k in grid.cell_items(step.cell) {
                    let k = k as usize;
                    let slot = &mut slots[k];
                    if slot.stamp == stamp {
                        continue;
                    }
                    slot.stamp = stamp;
                    c.patches_read_before_screening += 1;
                    if slot.verdict == 0 {
                        let pass = screen(&bundle.source, k, &scene.polygons[k]) == Screen3::Pass;
                        slot.verdict = if pass { 1 } else { 2 };
                        if pass {
                            slot.cone = facets.cone(k, o);
                        }
                    }
                    if slot.verdict != 1 {
                        continue;
                    }
                    c.patches_read_after_screening += 1;
                    c.intersection_computations += 1;
                    if slot.cone.misses(d, dd) {
                        continue;
                    }
                    if let Some(t) = facets.hit(k, o, d, bound(&best)) {
                        offer(&mut best, k, t, d.dot(facets.facet(k).normal) < 0.0);
                    }
                }
            }
            // Go on while a polygon beyond this cell could still be nearer (or tie).
            if matches!(best, Some(b) if b.t < step.t_exit - margin) {
                break;
            }
        }
        hits.push(best);
    }
    finish(hits, c, None)
}

/// The trace of `bundle` by `method` (`grid` is used by the grid tracers; `params`, the 2D
/// shell parameters, by polar and sweep, checked first whichever the method).
pub fn trace(
    method: Method3,
    scene: &Scene3,
    grid: &Grid3,
    bundle: &Bundle3,
    params: &ShellParams,
) -> Result<Trace3, Trace3Error> {
    params.validate().map_err(Trace3Error::InvalidParams)?;
    Ok(match method {
        Method3::Brute => brute_with(scene, grid.facets(), bundle),
        Method3::Conventional => conventional(scene, grid, bundle),
        Method3::Polar => super::polar::trace(scene, grid, bundle, params)?,
        Method3::Sweep => super::sweep::trace(scene, bundle, params)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::d3::gen::box_room;
    use crate::d3::grid::Grid3Params;
    use crate::d3::hemisphere::Strata;

    #[test]
    fn the_box_room_from_the_floor_hits_everywhere_and_both_tracers_agree() {
        let scene = box_room();
        let grid = Grid3::build(&scene, Grid3Params::default()).unwrap();
        // Patch 4 is the floor's middle square (normal +y).
        let p = &scene.polygons[4];
        let rays = HemisphereRays::new(p.centre, p.normal, 16, 8, Strata::Cosine).unwrap();
        let bundle = Bundle3::from_hemisphere(&rays, Some(4));
        let b = brute(&scene, &bundle);
        let c = conventional(&scene, &grid, &bundle);
        assert_eq!(b.hits, c.hits);
        assert!(b.hits.iter().all(|h| h.is_some_and(|h| h.front && h.polygon != 4)));
        assert_eq!(b.counters.actual_intersections, 128);
        assert_eq!(c.counters.actual_intersections, 128);
        // The floor's squares are backward (in the source's plane): screened out.
        assert_eq!(b.counters.patches_read_after_screening, 128 * (54 - 9));
        assert!(c.counters.intersection_computations < b.counters.intersection_computations);
        assert!(c.counters.cells_traversed > 0 && b.counters.cells_traversed == 0);
        assert!(b.counters.adlc_true > 1.0 && b.counters.adlc_true == c.counters.adlc_true);
    }

    #[test]
    fn screening_rules() {
        let sq = |z: f64, flip: bool| {
            let mut v = vec![
                DVec3::new(0.0, 0.0, z),
                DVec3::new(1.0, 0.0, z),
                DVec3::new(1.0, 1.0, z),
                DVec3::new(0.0, 1.0, z),
            ];
            if flip {
                v.reverse();
            }
            Polygon::new(v).unwrap()
        };
        let s = Source3 { origin: DVec3::new(0.5, 0.5, 0.0), normal: DVec3::Z, patch: Some(7) };
        // Facing down (-z), above the source: passes.
        assert_eq!(screen(&s, 0, &sq(1.0, true)), Screen3::Pass);
        assert_eq!(screen(&s, 0, &sq(1.0, false)), Screen3::BackFacing);
        assert_eq!(screen(&s, 0, &sq(-1.0, false)), Screen3::Backward);
        assert_eq!(screen(&s, 0, &sq(0.0, true)), Screen3::Backward);
        assert_eq!(screen(&s, 7, &sq(1.0, true)), Screen3::Source);
    }

    /// `passes` is `screen(..) == Screen3::Pass` on every polygon of a random scene from random
    /// sources, from polygons' centres (their own patch among them) and with random normals.
    #[test]
    fn passes_is_screen_pass() {
        use rand::{RngExt, SeedableRng};
        let seed = 184u64;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let scene = crate::d3::gen::generate(200, 80.0, 9).unwrap();
        let (lo, hi) = scene.bounds();
        let mut verdicts = [0usize; 2];
        for i in 0..200 {
            let k = rng.random_range(0..scene.polygons.len());
            let source = if i % 2 == 0 {
                let p = &scene.polygons[k];
                Source3 { origin: p.centre, normal: p.normal, patch: Some(k) }
            } else {
                let u = DVec3::new(rng.random(), rng.random(), rng.random());
                let n = DVec3::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0), rng.random());
                Source3 { origin: lo + (hi - lo) * u, normal: n.normalize(), patch: None }
            };
            for (k, p) in scene.polygons.iter().enumerate() {
                let pass = screen(&source, k, p) == Screen3::Pass;
                assert_eq!(passes(&source, k, p), pass, "seed {seed}: polygon {k}, source {source:?}");
                verdicts[pass as usize] += 1;
            }
        }
        assert!(verdicts[0] > 1000 && verdicts[1] > 1000, "seed {seed}: {verdicts:?}");
    }
}
