//! Rung 2 of the equivalence ladder: the bit-true fixed-point datapath against the `f64` golden
//! model, ray by ray, with every disagreement explained by the error bound of `hdl/FORMATS.md`.
//!
//! A ray's two answers (float and fixed, traced by the same technique) *agree* when they name the
//! same patch, or both nothing. A disagreement is *explained* when one of the patches involved is
//! within the bound of a decision the fixed point cannot make exactly:
//!
//! * **endpoint**: the ray passes within [`lateral_bound`] of an endpoint of either patch (the
//!   side tests of a grazing endpoint can flip);
//! * **grazing**: the origin lies within [`GRAZING_DISTANCE`] of either patch's line (the
//!   screener cannot decide facing reliably, or drops the patch as *near*);
//! * **near tie**: both are hits whose float distances differ by less than the sum of their
//!   [`distance_bound`]s.
//!
//! Anything else is a bug, and [`Comparison::unexplained`] lists it.

use crate::arith::Arith;
use crate::figures::{scene_seed, source_patches, MAX_SEEDS};
use crate::geom::{cross, Hit, Ray, Segment, Vec2};
use crate::grid::GridParams;
use crate::rays::{Bundle, RaySet, MAX_BUNDLE_RAYS};
use crate::run::{GriddedScene, RunError};
use crate::scene::{self, SceneError};
use crate::trace::{Method, ShellParams, TraceResult};
use rayon::prelude::*;
use shelling_hdl::formats::{COORD_FRAC, DIR_FRAC, KEY_FRAC, PRODUCT_SHIFT};
use std::fmt;

/// Error of a point relative to the origin after quantisation: both are rounded to 2⁻⁶ per axis,
/// so the difference is off by at most 2⁻⁶ per axis.
pub const POSITION_ERROR: f64 = std::f64::consts::SQRT_2 / (1u64 << COORD_FRAC) as f64;
/// Angular error of a quantised direction: each component off by at most 2⁻¹⁷.
pub const DIRECTION_ERROR: f64 = std::f64::consts::SQRT_2 / (1u64 << (DIR_FRAC + 1)) as f64;
/// Error of a side value from the two truncated products, in world units (per unit direction).
pub const SIDE_ERROR: f64 = 2.0 * (1u64 << PRODUCT_SHIFT) as f64 / (1u64 << (COORD_FRAC + DIR_FRAC)) as f64;
/// The screener drops a patch whose line passes within 1/64 unit of the origin (*near*) and
/// decides facing from rounded coordinates: beyond this distance neither can differ from float.
pub const GRAZING_DISTANCE: f64 = 1.0 / 64.0 + 2.0 * POSITION_ERROR;

/// How far from the ray (perpendicular to it) a point at distance `r` from the origin may lie and
/// still be on the other side in fixed point: twice the sum of the position, direction and
/// truncation errors.
pub fn lateral_bound(r: f64) -> f64 {
    2.0 * (POSITION_ERROR + r * DIRECTION_ERROR + SIDE_ERROR)
}

/// Bound of `|t_fixed − t_float|` for a hit at distance `t` on a patch that the ray meets at angle
/// `β` (`sin_beta = |sin β|`): the lateral error moved along the ray by `1/sin β`, plus the key's
/// relative error (the 2⁻¹⁶ rounding of `W` and the truncated products) and its resolution
/// (`U = 2²⁶/t` in integers), plus the saturation of keys nearer than 2⁻⁶ unit.
pub fn distance_bound(t: f64, sin_beta: f64) -> f64 {
    let lateral = lateral_bound(t) / sin_beta.max(1e-12);
    let relative = t * 2f64.powi(-14);
    let resolution = 2.0 * t * t / (1u64 << KEY_FRAC) as f64;
    let saturation = if t < 1.0 / 64.0 { 1.0 / 64.0 } else { 0.0 };
    lateral + relative + resolution + saturation
}

/// Why a disagreement is within the bound.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Reason {
    Endpoint,
    Grazing,
    NearTie,
}

/// One ray whose float and fixed answers differ.
#[derive(Clone, Debug, PartialEq)]
pub struct Disagreement {
    pub ray: usize,
    pub float: Option<Hit>,
    pub fixed: Option<Hit>,
}

/// The comparison of one bundle's float and fixed traces.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Comparison {
    pub rays: usize,
    pub agree: usize,
    pub endpoint: usize,
    pub grazing: usize,
    pub near_tie: usize,
    pub unexplained: Vec<Disagreement>,
    /// Agreeing hits whose distance error exceeds [`distance_bound`].
    pub distance_violations: Vec<Disagreement>,
    /// Largest `|t_fixed − t_float| / distance_bound` over agreeing hits.
    pub worst_distance_ratio: f64,
}

impl Comparison {
    /// Adds another comparison's counts.
    pub fn merge(&mut self, o: Comparison) {
        self.rays += o.rays;
        self.agree += o.agree;
        self.endpoint += o.endpoint;
        self.grazing += o.grazing;
        self.near_tie += o.near_tie;
        self.unexplained.extend(o.unexplained);
        self.distance_violations.extend(o.distance_violations);
        self.worst_distance_ratio = self.worst_distance_ratio.max(o.worst_distance_ratio);
    }

    /// Rays beyond the documented bound: a disagreement the bound does not explain, or an
    /// agreeing hit whose distance error exceeds it.
    pub fn beyond_bound(&self) -> impl Iterator<Item = &Disagreement> {
        self.unexplained.iter().chain(&self.distance_violations)
    }

    /// The fraction of rays whose fixed-point hit names the float patch.
    pub fn rate(&self) -> f64 {
        if self.rays == 0 {
            return 1.0;
        }
        self.agree as f64 / self.rays as f64
    }
}

fn sin_beta(ray: &Ray, seg: &Segment) -> f64 {
    let e = seg.b - seg.a;
    (cross(ray.dir, e) / e.length()).abs()
}

fn endpoint_near(ray: &Ray, seg: &Segment) -> bool {
    [seg.a, seg.b].iter().any(|&x| {
        let v = x - ray.origin;
        cross(ray.dir, v).abs() <= lateral_bound(v.length())
    })
}

fn grazing(origin: Vec2, seg: &Segment) -> bool {
    let e = seg.b - seg.a;
    (cross(e, origin - seg.a) / e.length()).abs() <= GRAZING_DISTANCE
}

/// Distance along the ray to the line of `seg`, if the ray meets the line ahead.
fn line_distance(ray: &Ray, seg: &Segment) -> Option<f64> {
    let e = seg.b - seg.a;
    let den = cross(ray.dir, e);
    let t = cross(seg.a - ray.origin, e) / den;
    (den != 0.0 && t > 0.0).then_some(t)
}

/// Classifies a disagreement between the float hit `f` and the fixed hit `x` of one ray.
pub fn explain(segments: &[Segment], ray: &Ray, f: Option<Hit>, x: Option<Hit>) -> Option<Reason> {
    let patches: Vec<&Segment> = [f, x].iter().flatten().map(|h| &segments[h.segment as usize]).collect();
    if patches.iter().any(|s| endpoint_near(ray, s)) {
        return Some(Reason::Endpoint);
    }
    if patches.iter().any(|s| grazing(ray.origin, s)) {
        return Some(Reason::Grazing);
    }
    if let (Some(f), Some(x)) = (f, x) {
        let (sf, sx) = (&segments[f.segment as usize], &segments[x.segment as usize]);
        if let Some(tx) = line_distance(ray, sx) {
            let bound = distance_bound(f.t, sin_beta(ray, sf)) + distance_bound(tx, sin_beta(ray, sx));
            if (f.t - tx).abs() <= bound {
                return Some(Reason::NearTie);
            }
        }
    }
    None
}

/// Compares the float and fixed traces of one bundle.
pub fn compare(
    segments: &[Segment],
    bundle: &Bundle,
    float: &TraceResult,
    fixed: &TraceResult,
) -> Comparison {
    let mut c = Comparison { rays: bundle.len(), ..Comparison::default() };
    for (i, (ray, (&f, &x))) in bundle.rays.iter().zip(float.hits.iter().zip(&fixed.hits)).enumerate() {
        let disagreement = || Disagreement { ray: i, float: f, fixed: x };
        if f.map(|h| h.segment) == x.map(|h| h.segment) {
            c.agree += 1;
            if let (Some(f), Some(x)) = (f, x) {
                let bound = distance_bound(f.t, sin_beta(ray, &segments[f.segment as usize]));
                let ratio = (x.t - f.t).abs() / bound;
                c.worst_distance_ratio = c.worst_distance_ratio.max(ratio);
                if ratio > 1.0 {
                    c.distance_violations.push(disagreement());
                }
            }
            continue;
        }
        match explain(segments, ray, f, x) {
            Some(Reason::Endpoint) => c.endpoint += 1,
            Some(Reason::Grazing) => c.grazing += 1,
            Some(Reason::NearTie) => c.near_tie += 1,
            None => c.unexplained.push(disagreement()),
        }
    }
    c
}

/// The paper's workload traced in both arithmetics.
#[derive(Clone, Debug)]
pub struct Workload {
    pub lengths: Vec<f64>,
    pub seeds: usize,
    pub sources: usize,
    pub rays: usize,
    pub count: usize,
    pub ray_set: RaySet,
    pub methods: Vec<Method>,
}

impl Default for Workload {
    fn default() -> Self {
        Workload {
            lengths: vec![4.0, 8.0, 16.0, 32.0, 64.0, 128.0],
            seeds: 1,
            sources: 20,
            rays: 1024,
            count: 1000,
            ray_set: RaySet::Angle,
            methods: vec![Method::Stochastic, Method::Deterministic],
        }
    }
}

impl Workload {
    /// Checks the workload; the message names the offending option (as the CLI spells it).
    pub fn validate(&self) -> Result<(), AgreementError> {
        let bad = |m: String| Err(AgreementError::Invalid(m));
        if self.seeds == 0 || self.seeds > MAX_SEEDS {
            return bad(format!("--seeds must be between 1 and {MAX_SEEDS}, got {}", self.seeds));
        }
        if self.sources == 0 || self.sources > self.count {
            return bad(format!(
                "--sources must be between 1 and {} (the scene's patches), got {}",
                self.count, self.sources
            ));
        }
        if self.rays == 0 || self.rays > MAX_BUNDLE_RAYS {
            return bad(format!("--rays must be between 1 and {MAX_BUNDLE_RAYS}, got {}", self.rays));
        }
        let factors = [self.seeds, self.lengths.len(), self.sources, self.rays].map(|v| v as u64);
        crate::limits::check_product(
            "the rays traced, --seeds × lengths × --sources × --rays,",
            &factors,
            crate::limits::MAX_WORKLOAD_RAYS,
        )
        .map_err(AgreementError::Invalid)?;
        Ok(())
    }
}

/// What keeps the comparison from running.
#[derive(Debug, thiserror::Error)]
pub enum AgreementError {
    #[error("{0}")]
    Invalid(String),
    #[error(transparent)]
    Scene(#[from] SceneError),
    #[error(transparent)]
    Run(#[from] RunError),
    #[error(transparent)]
    Source(#[from] crate::rays::SourceError),
}

/// One row of the report: a segment length and a technique, summed over scenes and sources.
#[derive(Clone, Debug)]
pub struct Row {
    pub length: f64,
    pub method: Method,
    pub comparison: Comparison,
}

/// The comparison of the whole workload, one row per length and technique.
#[derive(Clone, Debug)]
pub struct Report {
    pub rows: Vec<Row>,
}

/// Traces the workload in both arithmetics and compares them ray by ray (in parallel; the rows
/// do not depend on the number of threads).
pub fn run(w: &Workload) -> Result<Report, AgreementError> {
    run_with_progress(w, |_, _| {})
}

/// [`run`], calling `progress(done, total)` as each of the `total` sources (of every scene) is
/// compared (from several threads, in any order).
pub fn run_with_progress(
    w: &Workload,
    progress: impl Fn(usize, usize) + Sync,
) -> Result<Report, AgreementError> {
    w.validate()?;
    let done = std::sync::atomic::AtomicUsize::new(0);
    let params = ShellParams::default();
    let jobs: Vec<(usize, usize)> =
        (0..w.lengths.len()).flat_map(|l| (0..w.seeds).map(move |s| (l, s))).collect();
    let per_scene = jobs
        .par_iter()
        .map(|&(l, s)| -> Result<Vec<Comparison>, AgreementError> {
            let scene = scene::generate(w.count, w.lengths[l], scene_seed(l, s), scene::PAPER_WORLD)?;
            let prepared = GriddedScene::new(scene, GridParams::default());
            let mut out = vec![Comparison::default(); w.methods.len()];
            for k in source_patches(w.count, w.sources) {
                let bundle = prepared.patch_bundle(k, w.ray_set, w.rays)?;
                for (slot, &m) in out.iter_mut().zip(&w.methods) {
                    let float = prepared.trace_in(Arith::Float, m, &bundle, &params)?;
                    let fixed = prepared.trace_in(Arith::Fixed, m, &bundle, &params)?;
                    slot.merge(compare(&prepared.scene.segments, &bundle, &float, &fixed));
                }
                progress(done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1, jobs.len() * w.sources);
            }
            Ok(out)
        })
        .collect::<Result<Vec<_>, _>>()?;
    let mut rows = Vec::new();
    for (l, &length) in w.lengths.iter().enumerate() {
        for (mi, &method) in w.methods.iter().enumerate() {
            let mut comparison = Comparison::default();
            for (j, &(jl, _)) in jobs.iter().enumerate() {
                if jl == l {
                    comparison.merge(per_scene[j][mi].clone());
                }
            }
            rows.push(Row { length, method, comparison });
        }
    }
    Ok(Report { rows })
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{:>6} {:<14} {:>9} {:>10} {:>9} {:>8} {:>9} {:>12} {:>10}",
            "length",
            "method",
            "rays",
            "same hit",
            "endpoint",
            "grazing",
            "near tie",
            "unexplained",
            "worst t/bound"
        )?;
        for r in &self.rows {
            let c = &r.comparison;
            writeln!(
                f,
                "{:>6} {:<14} {:>9} {:>9.4}% {:>9} {:>8} {:>9} {:>12} {:>10.3}",
                r.length,
                r.method.name(),
                c.rays,
                100.0 * c.rate(),
                c.endpoint,
                c.grazing,
                c.near_tie,
                c.beyond_bound().count(),
                c.worst_distance_ratio
            )?;
        }
        Ok(())
    }
}
