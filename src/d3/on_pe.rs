//! 3D form factors on the RTL processing element, by the paper's second extension (§3.2): "we
//! can also transform our 3D problem into a 2D problem ... slice 3D hemisphere rays and polygonal
//! patches into 2D rays on the hemisphere and line segments ... Now we can use the technique
//! described above to treat it." The 2D machine needs no change: every sweep plane of a bundle
//! ([`super::sweep`]) is a 2D scene with the source at its origin, and the PE traces it as it
//! traces any 2D bundle.
//!
//! # The mapping
//!
//! * **Slices.** Each polygon that passes the 3D screener and meets the plane becomes the
//!   segment where the plane cuts it ([`Slicing::Exact`]): a ray of the plane hits the segment
//!   exactly where it hits the polygon, so the PE's 2D hit is the 3D hit (its distance is the 3D
//!   distance, the plane's coordinates being 3D lengths). The polygons the sweep tests directly
//!   (planes within 10⁻³ rad of parallel to the sweep plane, slices of no length, the source
//!   within rounding of a polygon's plane: [`SweepPlane::direct`]) are tested by the host in
//!   `f64` and offered with the PE's hit by the 3D tie rule; their tests are counted apart
//!   ([`Pe3Totals::host_tests`]).
//! * **Scale.** A plane's coordinates are scaled by the power of two ([`plane_scale`]) that
//!   brings every vertex of the scene, seen from the origin, within 0.45 of the datapath's world
//!   window ([`WORLD_SPAN`] = 2048 units at 2⁻⁶): exact in `f64`, so no hit changes, and the
//!   scene uses the datapath's resolution whatever its units.
//! * **Schedule.** Each plane's bundle (its `2·n_phi` rays, by increasing 2D angle) is scheduled
//!   by the 2D technique `method` on the bit-true backend, checked against the `f64` golden
//!   model on the same slices within the documented bound (rung 2) and co-simulated on a fresh
//!   PE ([`crate::cosim`], hits checked against the bit-true model).
//!
//! # Checks
//!
//! Every plane: the PE's hits equal the bit-true model's (the co-simulation), which are within
//! rung 2's bound of the `f64` trace of the slices. Every bundle: its rays' polygons against the
//! 3D brute force (`f64`, the oracle): the rays that agree are counted
//! ([`Pe3Totals::brute_agree`]); the rest are rays within the fixed point's rounding of a
//! polygon's edge, or of two polygons at one distance. The rows are then as good as the
//! software's: `tests/ff3d.rs` checks them against the closed forms.

use super::brute::{Facets, Hit};
use super::form_factors::{ray_set, to_row, Ff3Error, Ff3Params};
use super::scene::Scene3;
use super::sweep::{planes_with, Slicing, SweepPlane};
use super::trace::{self, offer, Bundle3, Method3, Trace3Error};
use crate::agreement;
use crate::cosim::{self, CosimConfig, CosimError};
use crate::grid::GridParams;
use crate::radiosity::form_factors::Row;
use crate::radiosity::on_pe::{PeTotals, PE_RAY_MEMORY};
use crate::run::{GriddedScene, RunError};
use crate::scene::Scene;
use crate::trace::{Method, TraceError};
use glam::DVec3;
use shelling_hdl::formats::WORLD_SPAN;

/// The 2D technique that traces every plane on the PE: the deterministic one, which derives each
/// slice's actual degree of local coherence by sorting, as §3.2 says the sweep must.
pub const PLANE_METHOD: Method = Method::Deterministic;

/// The hardware's side of a 3D solve.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct Pe3Totals {
    /// The PE's sums over every plane co-simulated (`bundles` counts the planes; `golden_agree`
    /// the rays whose PE hit is the `f64` trace's of the slices).
    #[serde(flatten)]
    pub pe: PeTotals,
    /// 3D bundles (rows × origins).
    pub origins: usize,
    /// Ray–polygon tests the host made for the polygons the sweep tests directly.
    pub host_tests: u64,
    /// Rays whose polygon is the 3D brute force's.
    pub brute_agree: usize,
}

/// What keeps a 3D row from being computed on the PE.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum On3Error {
    #[error("--method {0} has no hardware mapping in 3D: the PE traces the sweep planes (--method sweep)")]
    NotSweep(&'static str),
    #[error(
        "--rays {rays}: a sweep plane holds 2 x {n_phi} rays, the PE at most {PE_RAY_MEMORY} rays per bundle"
    )]
    TooManyRays { rays: usize, n_phi: usize },
    #[error(transparent)]
    Ff3(#[from] Ff3Error),
    #[error("a sweep plane does not map onto the PE: {0}")]
    Run(#[from] RunError),
    #[error(transparent)]
    Cosim(#[from] CosimError),
    #[error("source polygon {source_polygon}: the PE's hits in a sweep plane differ from the f64 golden model beyond the documented bound on {rays} rays")]
    BeyondBound { source_polygon: usize, rays: usize },
}

impl From<Trace3Error> for On3Error {
    fn from(e: Trace3Error) -> Self {
        On3Error::Ff3(Ff3Error::Trace(e))
    }
}

impl From<TraceError> for On3Error {
    fn from(e: TraceError) -> Self {
        On3Error::Run(RunError::Trace(e))
    }
}

/// `p` maps onto the PE: the sweep technique, and each plane's `2·n_phi` rays in its ray memory.
pub fn check_params(p: &Ff3Params) -> Result<(), On3Error> {
    if p.method != Method3::Sweep {
        return Err(On3Error::NotSweep(p.method.name()));
    }
    let (_, n_phi) = super::form_factors::split_rays(p.rays)?;
    if 2 * n_phi > PE_RAY_MEMORY {
        return Err(On3Error::TooManyRays { rays: p.rays, n_phi });
    }
    Ok(())
}

/// The power of two by which the planes of a bundle from `o` are scaled: the largest that keeps
/// every vertex of `scene` within `0.45·WORLD_SPAN` of `o` (a plane's 2D coordinates are within
/// that distance of its origin, so its window is under `0.9·WORLD_SPAN` wide).
pub fn plane_scale(scene: &Scene3, o: DVec3) -> f64 {
    let r = scene.polygons.iter().flat_map(|p| &p.vertices).map(|v| (*v - o).length()).fold(0.0, f64::max);
    if r > 0.0 {
        2f64.powi((0.45 * WORLD_SPAN / r).log2().floor() as i32)
    } else {
        1.0
    }
}

/// One plane on the PE: its rays' hits `(polygon, t)` offered into `best`.
fn plane_on_pe(
    scene: &Scene3,
    bundle: &Bundle3,
    plane: &SweepPlane,
    scale: f64,
    p: &Ff3Params,
    config: &CosimConfig,
    totals: &mut Pe3Totals,
    best: &mut [Option<Hit>],
) -> Result<(), On3Error> {
    let source_polygon = bundle.source.patch.unwrap_or(usize::MAX);
    if let Some((slices, _)) = &plane.slices {
        let scaled = Scene {
            segments: slices
                .segments
                .iter()
                .map(|g| crate::geom::Segment::new(g.a * scale, g.b * scale))
                .collect(),
            materials: slices.materials.clone(),
            world: None,
        };
        let prepared = GriddedScene::new(scaled, GridParams::default());
        let scheduled = prepared.schedule(PLANE_METHOD, &plane.bundle, &p.shells)?;
        let golden = prepared.trace(PLANE_METHOD, &plane.bundle, &p.shells)?;
        let rung2 = agreement::compare(&prepared.scene.segments, &plane.bundle, &golden, &scheduled.trace);
        if rung2.beyond_bound().count() > 0 {
            return Err(On3Error::BeyondBound { source_polygon, rays: rung2.beyond_bound().count() });
        }
        let run = cosim::run(&scheduled, config, |_, _| {})?;
        for (i, (pe, traced)) in run.hits.iter().zip(&scheduled.trace.hits).enumerate() {
            let ray = plane.rays[i];
            match (pe, traced) {
                (Some(n), Some(h)) if u32::from(n.id) == h.segment => {
                    let k = plane.polygons[h.segment as usize];
                    let front = bundle.directions[ray].dot(scene.polygons[k].normal) < 0.0;
                    offer(&mut best[ray], k, h.t / scale, front);
                }
                (None, None) => {}
                _ => return Err(On3Error::Cosim(CosimError::Mismatch(format!(
                    "source polygon {source_polygon}, plane {}: ray {i}'s hit is not the bit-true trace's",
                    plane.band
                )))),
            }
        }
        let (h, t) = (&run.hardware, &mut totals.pe);
        t.bundles += 1;
        t.rays += plane.bundle.len();
        t.cycles += h.cycles;
        t.intersection_busy_cycles += h.intersection_busy_cycles;
        t.patch_loads += h.patch_loads;
        t.cache_hits += h.cache_hits;
        t.tests += h.tests;
        t.golden_agree += rung2.agree;
    }
    let o = bundle.source.origin;
    for &k in &plane.direct {
        let polygon = &scene.polygons[k];
        for &ray in &plane.rays {
            let d = bundle.directions[ray];
            totals.host_tests += 1;
            if let Some(t) = super::brute::intersect(o, d, polygon) {
                offer(&mut best[ray], k, t, d.dot(polygon.normal) < 0.0);
            }
        }
    }
    Ok(())
}

/// The nearest hit of every ray of `bundle` (a hemisphere set's, `n_theta` even), its sweep
/// planes traced on the PE (module docs); the rays that agree with the 3D brute force (over
/// `facets`, the scene's) are counted.
pub fn bundle_on_pe(
    scene: &Scene3,
    facets: &Facets,
    bundle: &Bundle3,
    p: &Ff3Params,
    config: &CosimConfig,
    totals: &mut Pe3Totals,
) -> Result<Vec<Option<Hit>>, On3Error> {
    let scale = plane_scale(scene, bundle.source.origin);
    let mut best = vec![None; bundle.len()];
    for plane in planes_with(scene, bundle, Slicing::Exact)? {
        plane_on_pe(scene, bundle, &plane, scale, p, config, totals, &mut best)?;
    }
    let brute = trace::brute_with(scene, facets, bundle);
    totals.origins += 1;
    totals.brute_agree +=
        best.iter().zip(&brute.hits).filter(|(a, b)| a.map(|h| h.polygon) == b.map(|h| h.polygon)).count();
    Ok(best)
}

/// The form-factor row of source polygon `k` from the PE's hits: [`super::form_factors::row`]'s
/// estimate, every origin's bundle traced by [`bundle_on_pe`].
pub fn row(
    scene: &Scene3,
    k: usize,
    p: &Ff3Params,
    config: &CosimConfig,
    totals: &mut Pe3Totals,
) -> Result<Row, On3Error> {
    check_params(p)?;
    let (mut set, origins) = ray_set(scene, k, p)?;
    let weight = 1.0 / origins.len() as f64;
    let mut acc = vec![0.0f64; scene.polygons.len()];
    let facets = Facets::new(scene);
    for origin in origins {
        set.origin = origin;
        let hits = bundle_on_pe(scene, &facets, &Bundle3::from_hemisphere(&set, Some(k)), p, config, totals)?;
        for (hit, ray) in hits.iter().zip(&set.rays) {
            if let Some(h) = hit {
                acc[h.polygon] += ray.weight * weight;
            }
        }
    }
    totals.pe.rows += 1;
    Ok(to_row(k, &acc))
}

impl std::ops::AddAssign for Pe3Totals {
    fn add_assign(&mut self, o: Pe3Totals) {
        self.pe += o.pe;
        self.origins += o.origins;
        self.host_tests += o.host_tests;
        self.brute_agree += o.brute_agree;
    }
}

/// The rows of the sources `range` on the PE, computed on all cores (each plane on its own fresh
/// PE, so the order does not change the cycles), in order, with the hardware's sums; `progress`
/// is called once per finished row.
pub fn rows(
    scene: &Scene3,
    range: std::ops::Range<usize>,
    p: &Ff3Params,
    config: &CosimConfig,
    progress: impl Fn() + Sync,
) -> Result<(Vec<Row>, Pe3Totals), On3Error> {
    check_params(p)?;
    let sum = std::sync::Mutex::new(Pe3Totals::default());
    let rows = crate::radiosity::form_factors::par_rows(range, progress, |k| {
        let mut totals = Pe3Totals::default();
        let r = row(scene, k, p, config, &mut totals)?;
        *sum.lock().expect("no row panics holding the sums") += totals;
        Ok::<_, On3Error>(r)
    })?;
    Ok((rows, sum.into_inner().expect("no row panics holding the sums")))
}
