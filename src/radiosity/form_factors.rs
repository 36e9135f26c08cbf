//! Form factors from the bundles of the tracers.
//!
//! The form factor `F_ij` from patch `i` to patch `j` of a 2D scene is the fraction of the
//! light leaving `i` (diffusely) that arrives at `j` first. From one point `x` of `i` it is the
//! point-to-segment form factor `F(x → j) = ½ ∫ cos φ dφ` over the angles `φ` (from `i`'s normal)
//! under which `j` is the nearest patch; for the whole of `i` it is the mean of `F(x → j)` over
//! `x ∈ i`. Here:
//!
//! * **Rays.** A bundle of `R` rays from `x` ([`crate::rays`]) gives each ray the form factor of
//!   its angular cell: with the `sine` set every ray carries exactly `1/R` (the 2D Nusselt
//!   analogue: cells of equal `sin φ`); with the `angle` set ray `k` at `φ_k` carries
//!   `½(sin(φ_k + π/2R) − sin(φ_k − π/2R))`. The weights sum to 1. `F(x → j)` is the sum of the
//!   weights of the rays whose nearest hit is `j`.
//! * **Origins.** `M` stratified points along `i`, at fractions `(m + ½)/M` of the way from `a`
//!   to `b` (the midpoint rule; the paper's single central origin is `M = 1`), each with `i`'s
//!   normal and `i` excluded from the hits; `F_ij` is the mean over the `M` origins.
//!
//! Every technique and both arithmetics answer the same question (each ray's nearest hit), and
//! the weights are added in ray order, so every technique gives bit-identical form factors in
//! `f64`; the fixed-point arithmetic gives the form factors of its own hits.
//!
//! # The error of the estimate
//!
//! * *Rays*: from one origin, a patch seen whole, between the angles `φ₁ < φ₂`, gets the weight
//!   of every cell whose ray falls in `[φ₁, φ₂]`; a cell cut by an endpoint counts wholly or not
//!   at all. So `|F̂(x → j) − F(x → j)| ≤ w` per visible endpoint, with `w` the largest weight
//!   of a cell there: `1/R` for the sine set, at most `π/(2R)` for the angle set. The errors of
//!   the `M` origins have different phases and partly cancel in the mean.
//! * *Origins*: the midpoint rule on `x ↦ F(x → j)`, which is smooth where `j` is seen whole,
//!   errs by `O(L_i² / (M² d²))` for patches at distance `d`; near a corner (`d → 0`) and where
//!   an occluder's shadow edge crosses `i` the integrand has a kink and the error is `O(1/M)`
//!   of the kinked part.
//!
//! At the defaults ([`DEFAULT_RAYS`] = 2048 sine rays, [`DEFAULT_ORIGINS`] = 16) the estimates
//! of the closed-form cases in `tests/radiosity.rs` are within 1e-3 (measured: see
//! RADIOSITY.md). Rows of a closed room sum to 1 up to rounding, whatever `R` and `M`.

use crate::arith::Arith;
use crate::geom::Vec2;
use crate::rays::{Bundle, RaySet, Source, SourceError};
use crate::run::{GriddedScene, RunError};
use crate::trace::{Method, ShellParams, TraceResult};
use std::f64::consts::PI;

/// Rays per origin of the form factors, unless asked otherwise.
pub const DEFAULT_RAYS: usize = 2048;

/// Origins per source patch of the form factors, unless asked otherwise.
pub const DEFAULT_ORIGINS: usize = 16;

/// The most origins per patch accepted.
pub const MAX_ORIGINS: usize = 1 << 12;

/// How the form factors of a row are estimated.
#[derive(Clone, Debug, PartialEq)]
pub struct FfParams {
    /// Rays per origin.
    pub rays: usize,
    /// Origins per source patch.
    pub origins: usize,
    pub ray_set: RaySet,
    pub method: Method,
    pub arith: Arith,
    pub shells: ShellParams,
}

impl Default for FfParams {
    fn default() -> Self {
        FfParams {
            rays: DEFAULT_RAYS,
            origins: DEFAULT_ORIGINS,
            ray_set: RaySet::Sine,
            method: Method::Deterministic,
            arith: Arith::Float,
            shells: ShellParams::default(),
        }
    }
}

/// What keeps a form-factor row from being computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FfError {
    #[error("--origins must be between 1 and {MAX_ORIGINS}, got {0}")]
    BadOrigins(usize),
    #[error(transparent)]
    Source(#[from] SourceError),
    #[error(transparent)]
    Run(#[from] RunError),
    /// A solve that computes its rows as it goes ends with the solver's error.
    #[error(transparent)]
    Solve(#[from] super::solve::SolveError),
}

/// One row of the form-factor matrix: `F_ij` of source `i` to every patch `j` it sees,
/// ascending in `j`, zeros left out.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Row {
    pub source: usize,
    #[serde(rename = "form_factors")]
    pub entries: Vec<Entry>,
}

/// One non-zero form factor of a row.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Entry {
    pub patch: u32,
    pub ff: f64,
}

impl Row {
    /// `Σ_j F_ij`: 1 in a closed environment, less where rays escape.
    pub fn sum(&self) -> f64 {
        self.entries.iter().map(|e| e.ff).sum()
    }

    /// `F_ij`, zero where the row has no entry.
    pub fn get(&self, j: usize) -> f64 {
        self.entries.binary_search_by_key(&(j as u32), |e| e.patch).map_or(0.0, |k| self.entries[k].ff)
    }
}

/// The form factor each ray of an `r`-ray bundle of `set` carries; they sum to 1.
pub fn ray_weights(set: RaySet, r: usize) -> Vec<f64> {
    match set {
        RaySet::Sine => vec![1.0 / r as f64; r],
        RaySet::Angle => {
            let h = PI / (2.0 * r as f64);
            (0..r)
                .map(|k| {
                    let phi = -PI / 2.0 + (2 * k + 1) as f64 * h;
                    0.5 * ((phi + h).sin() - (phi - h).sin())
                })
                .collect()
        }
    }
}

/// The `m` stratified origins on patch `k` (fractions `(i + ½)/m` from `a` to `b`).
pub fn origins(prepared: &GriddedScene, k: usize, m: usize) -> Result<Vec<Vec2>, FfError> {
    if m == 0 || m > MAX_ORIGINS {
        return Err(FfError::BadOrigins(m));
    }
    let segments = &prepared.scene.segments;
    let seg = segments.get(k).ok_or(SourceError::NoSuchPatch { index: k, count: segments.len() })?;
    Ok((0..m).map(|i| seg.a + (seg.b - seg.a) * ((2 * i + 1) as f64 / (2 * m) as f64)).collect())
}

/// The bundles of source patch `k`: one per origin, with `k`'s normal, `k` excluded.
pub fn bundles(prepared: &GriddedScene, k: usize, p: &FfParams) -> Result<Vec<Bundle>, FfError> {
    let normal = Source::from_patch(&prepared.scene.segments, k)?.normal;
    origins(prepared, k, p.origins)?
        .into_iter()
        .map(|origin| Ok(Bundle::new(Source { origin, normal, patch: Some(k as u32) }, p.ray_set, p.rays)?))
        .collect()
}

/// Accumulates the form factors of traced bundles into a row: `traces[m]` is the trace of
/// `bundles[m]`; every hit adds its ray's weight over the number of bundles.
pub struct RowBuilder {
    acc: Vec<f64>,
    weights: Vec<f64>,
    scale: f64,
}

impl RowBuilder {
    /// For a scene of `patches` patches and `origins` bundles of `params`.
    pub fn new(patches: usize, p: &FfParams) -> RowBuilder {
        RowBuilder {
            acc: vec![0.0; patches],
            weights: ray_weights(p.ray_set, p.rays),
            scale: 1.0 / p.origins as f64,
        }
    }

    /// Adds the hits of one bundle's trace.
    pub fn add(&mut self, trace: &TraceResult) {
        self.add_patches(trace.hits.iter().map(|h| h.map(|h| h.segment as usize)));
    }

    /// Adds one bundle's hits given as the patch each ray hits, in ray order.
    pub fn add_patches(&mut self, hits: impl IntoIterator<Item = Option<usize>>) {
        for (hit, w) in hits.into_iter().zip(&self.weights) {
            if let Some(j) = hit {
                self.acc[j] += w * self.scale;
            }
        }
    }

    /// The row of source `k`, zeros left out.
    pub fn finish(self, k: usize) -> Row {
        let entries = self
            .acc
            .iter()
            .enumerate()
            .filter(|(_, &f)| f != 0.0)
            .map(|(j, &ff)| Entry { patch: j as u32, ff })
            .collect();
        Row { source: k, entries }
    }
}

/// The form-factor row of source patch `k`, traced with `p.method` in `p.arith`.
pub fn row(prepared: &GriddedScene, k: usize, p: &FfParams) -> Result<Row, FfError> {
    let mut builder = RowBuilder::new(prepared.scene.len(), p);
    for bundle in bundles(prepared, k, p)? {
        builder.add(&prepared.trace_in(p.arith, p.method, &bundle, &p.shells)?);
    }
    Ok(builder.finish(k))
}

/// The rows of the sources `range`, computed on all cores, in order.
pub fn rows(
    prepared: &GriddedScene,
    range: std::ops::Range<usize>,
    p: &FfParams,
    progress: impl Fn() + Sync,
) -> Result<Vec<Row>, FfError> {
    par_rows(range, progress, |k| row(prepared, k, p))
}

/// `row(k)` for every source `k` of `range` on all cores, in order, calling `progress` once per
/// finished row (the 2D and the 3D rows alike).
pub(crate) fn par_rows<E: Send>(
    range: std::ops::Range<usize>,
    progress: impl Fn() + Sync,
    row: impl Fn(usize) -> Result<Row, E> + Sync,
) -> Result<Vec<Row>, E> {
    use rayon::prelude::*;
    range
        .into_par_iter()
        .map(|k| {
            let r = row(k);
            progress();
            r
        })
        .collect()
}
