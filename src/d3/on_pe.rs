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
//!   by the 2D deterministic technique ([`PLANE_METHOD`]) on the bit-true backend and checked
//!   against the `f64` golden model on the same slices within the documented bound (rung 2).
//! * **Packs.** A plane is short work (64 rays at the defaults), so the planes of one bundle are
//!   packed as many as the PE's ray memory holds (16 of 64 rays) into one source of the PE
//!   ([`crate::workstream::pack`]: the directions one after another, the slices one after
//!   another in the host memory, each plane's jobs on its own rays and slices): one setup, drain
//!   and readout for the pack. A pack is co-simulated on a fresh PE ([`crate::cosim`], hits
//!   checked against the bit-true model), or is a source of the machine ([`rows_on_machine`]).
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
use crate::geom::Segment;
use crate::grid::GridParams;
use crate::radiosity::form_factors::Row;
use crate::radiosity::on_pe::{PeTotals, PE_RAY_MEMORY};
use crate::run::{GriddedScene, RunError, Scheduled};
use crate::scene::Scene;
use crate::trace::{Method, TraceError};
use crate::workstream::PeWork;
use glam::DVec3;
use shelling_hdl::formats::{Nearest, WORLD_SPAN};

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
    /// Sources of the PE: the planes packed as many as its ray memory holds.
    pub packs: usize,
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
    #[error(
        "--rays {rays} splits into {n_theta} x {n_phi} (n_theta x n_phi): the sweep planes hold two opposite \
         Θ-bands each, so n_theta must be even (e.g. --rays 1024 or 4096)"
    )]
    OddBands { rays: usize, n_theta: usize, n_phi: usize },
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

/// `p` maps onto the PE: the sweep technique, an even number of Θ-bands (two a plane), and each
/// plane's `2·n_phi` rays in its ray memory.
pub fn check_params(p: &Ff3Params) -> Result<(), On3Error> {
    if p.method != Method3::Sweep {
        return Err(On3Error::NotSweep(p.method.name()));
    }
    let (n_theta, n_phi) = super::form_factors::split_rays(p.rays)?;
    if !n_theta.is_multiple_of(2) {
        return Err(On3Error::OddBands { rays: p.rays, n_theta, n_phi });
    }
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

/// A bundle's planes: what every plane shares.
struct Planes<'a> {
    scene: &'a Scene3,
    bundle: &'a Bundle3,
    /// [`plane_scale`] of the bundle's origin.
    scale: f64,
    p: &'a Ff3Params,
}

impl Planes<'_> {
    fn source_polygon(&self) -> usize {
        self.bundle.source.patch.unwrap_or(usize::MAX)
    }

    /// `plane`'s slices scheduled for the PE (`None` when no polygon meets it), checked against
    /// the `f64` trace of the slices (rung 2); the plane's rays and agreeing rays counted.
    fn schedule(&self, plane: &SweepPlane, totals: &mut PeTotals) -> Result<Option<Scheduled>, On3Error> {
        let Some((slices, _)) = &plane.slices else { return Ok(None) };
        let scale = self.scale;
        let scaled = Scene {
            segments: slices.segments.iter().map(|g| Segment::new(g.a * scale, g.b * scale)).collect(),
            materials: slices.materials.clone(),
            world: None,
        };
        let prepared = GriddedScene::new(scaled, GridParams::default());
        let scheduled = prepared.schedule(PLANE_METHOD, &plane.bundle, &self.p.shells)?;
        let golden = prepared.trace(PLANE_METHOD, &plane.bundle, &self.p.shells)?;
        let rung2 = agreement::compare(&prepared.scene.segments, &plane.bundle, &golden, &scheduled.trace);
        if rung2.beyond_bound().count() > 0 {
            let (source_polygon, rays) = (self.source_polygon(), rung2.beyond_bound().count());
            return Err(On3Error::BeyondBound { source_polygon, rays });
        }
        totals.bundles += 1;
        totals.rays += plane.bundle.len();
        totals.golden_agree += rung2.agree;
        Ok(Some(scheduled))
    }

    /// The hardware's hits of `plane` (`hits`, patch numbers of its slices), which must be the
    /// bit-true trace's (`scheduled`), offered into `best` as their polygons.
    fn offer_hits(
        &self,
        plane: &SweepPlane,
        scheduled: &Scheduled,
        hits: &[Option<Nearest>],
        best: &mut [Option<Hit>],
    ) -> Result<(), On3Error> {
        for (i, (pe, traced)) in hits.iter().zip(&scheduled.trace.hits).enumerate() {
            let ray = plane.rays[i];
            match (pe, traced) {
                (Some(n), Some(h)) if u32::from(n.id) == h.segment => {
                    let k = plane.polygons[h.segment as usize];
                    let front = self.bundle.directions[ray].dot(self.scene.polygons[k].normal) < 0.0;
                    offer(&mut best[ray], k, h.t / self.scale, front);
                }
                (None, None) => {}
                _ => {
                    return Err(On3Error::Cosim(CosimError::Mismatch(format!(
                        "source polygon {}, plane {}: ray {i}'s hit is not the bit-true trace's",
                        self.source_polygon(),
                        plane.band
                    ))))
                }
            }
        }
        Ok(())
    }

    /// The hardware's hits of a pack's source (`hits`: its planes' rays one after another, their
    /// slices numbered one after another), each plane's offered as [`Planes::offer_hits`] does.
    fn offer_pack(
        &self,
        pack: &Pack,
        hits: &[Option<Nearest>],
        best: &mut [Option<Hit>],
    ) -> Result<(), On3Error> {
        let (mut ray, mut patch) = (0usize, 0u16);
        for (plane, scheduled) in pack {
            let n = plane.bundle.len();
            // A hit on another plane's slice wraps to a number the check below refuses.
            let own: Vec<Option<Nearest>> = hits[ray..ray + n]
                .iter()
                .map(|h| h.map(|x| Nearest { id: x.id.wrapping_sub(patch), ..x }))
                .collect();
            self.offer_hits(plane, scheduled, &own, best)?;
            ray += n;
            patch += scheduled.fixed.patches.len() as u16;
        }
        Ok(())
    }

    /// The polygons `plane` tests directly, tested by the host in `f64` and offered into `best`.
    fn host_tests(&self, plane: &SweepPlane, totals: &mut Pe3Totals, best: &mut [Option<Hit>]) {
        let o = self.bundle.source.origin;
        for &k in &plane.direct {
            let polygon = &self.scene.polygons[k];
            for &ray in &plane.rays {
                let d = self.bundle.directions[ray];
                totals.host_tests += 1;
                if let Some(t) = super::brute::intersect(o, d, polygon) {
                    offer(&mut best[ray], k, t, d.dot(polygon.normal) < 0.0);
                }
            }
        }
    }
}

/// One source of the PE: scheduled sweep planes of one bundle, packed one after another
/// ([`crate::workstream::pack`]).
type Pack = Vec<(SweepPlane, Scheduled)>;

/// A bundle's scheduled planes in packs of as many planes as the PE's ray memory holds (every
/// plane of a bundle has `2·n_phi` rays), in order.
fn packs(planes: Vec<(SweepPlane, Scheduled)>) -> Vec<Pack> {
    let per = planes.first().map_or(1, |(plane, _)| (PE_RAY_MEMORY / plane.bundle.len().max(1)).max(1));
    let mut out: Vec<Pack> = Vec::new();
    for (k, plane) in planes.into_iter().enumerate() {
        if k % per == 0 {
            out.push(Vec::with_capacity(per));
        }
        out.last_mut().expect("pushed above").push(plane);
    }
    out
}

/// What the host hands the PE for `pack`.
fn pack_work(pack: &Pack) -> Result<PeWork, On3Error> {
    let parts: Vec<_> = pack.iter().map(|(_, s)| (&s.stream, &s.fixed)).collect();
    Ok(crate::workstream::pack(&parts).map_err(CosimError::from)?)
}

/// `bundle`'s hits `best` against the 3D brute force's (over `facets`): the agreeing rays
/// counted in `totals`, the bundle too.
fn against_brute(
    scene: &Scene3,
    facets: &Facets,
    bundle: &Bundle3,
    best: &[Option<Hit>],
    totals: &mut Pe3Totals,
) {
    let brute = trace::brute_with(scene, facets, bundle);
    totals.origins += 1;
    totals.brute_agree +=
        best.iter().zip(&brute.hits).filter(|(a, b)| a.map(|h| h.polygon) == b.map(|h| h.polygon)).count();
}

/// The nearest hit of every ray of `bundle` (a hemisphere set's, `n_theta` even), its sweep
/// planes traced in packs, each on a fresh PE (module docs); the rays that agree with the 3D brute force
/// (over `facets`, the scene's) are counted.
pub fn bundle_on_pe(
    scene: &Scene3,
    facets: &Facets,
    bundle: &Bundle3,
    p: &Ff3Params,
    config: &CosimConfig,
    totals: &mut Pe3Totals,
) -> Result<Vec<Option<Hit>>, On3Error> {
    let at = Planes { scene, bundle, scale: plane_scale(scene, bundle.source.origin), p };
    let mut best = vec![None; bundle.len()];
    let mut scheduled = Vec::new();
    for plane in planes_with(scene, bundle, Slicing::Exact)? {
        at.host_tests(&plane, totals, &mut best);
        if let Some(s) = at.schedule(&plane, &mut totals.pe)? {
            scheduled.push((plane, s));
        }
    }
    for pack in packs(scheduled) {
        let run = cosim::run_work(pack_work(&pack)?, config, |_, _| {})?;
        at.offer_pack(&pack, &run.hits, &mut best)?;
        totals.packs += 1;
        totals.pe.add_pe(&run.hardware);
    }
    against_brute(scene, facets, bundle, &best, totals);
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
        self.packs += o.packs;
        self.brute_agree += o.brute_agree;
    }
}

/// The rows of the sources `range` on the PE, computed on all cores (each pack on its own fresh
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

/// Most slices of one machine run in 3D: half the host memory's patches, so that a cache of
/// any size can spread them ([`crate::machine::MAX_HOST_PATCHES`]). Whole bundles are run
/// together until the next would pass it.
pub const BATCH_PATCHES: usize = crate::machine::MAX_HOST_PATCHES / 2;

/// A bundle whose planes are on the machine: where its rays' hits go.
struct OpenBundle {
    k: usize,
    bundle: Bundle3,
    /// Each ray's weight in row `k` (the ray's, over the origins).
    weights: Vec<f64>,
    scale: f64,
    best: Vec<Option<Hit>>,
}

/// The packs of a batch, and the bundles they belong to.
#[derive(Default)]
struct Batch {
    open: Vec<OpenBundle>,
    /// Each pack (a source of the machine) and its bundle (in `open`).
    packs: Vec<(usize, Pack)>,
    slices: usize,
}

/// Every row of `scene` on the parallel machine of `config.pes` PEs: every origin's sweep planes
/// scheduled, checked and packed as [`bundle_on_pe`] does, each pack a whole source of the
/// machine (its slices a scene of their own in the shared host memory), dealt as `config.deal` says in batches
/// of whole bundles of at most [`BATCH_PATCHES`] slices, one machine run each (its cycles the
/// batches' sum). The patches stay at their index (`Placement::Index`): two slices hit at one
/// distance go to the lower, as in the bit-true trace. `progress(rows done, rows)`.
pub fn rows_on_machine(
    scene: &Scene3,
    p: &Ff3Params,
    config: &crate::machine::MachineConfig,
    progress: impl FnMut(usize, usize),
) -> Result<(Vec<Row>, Pe3Totals), On3Error> {
    rows_on_machine_in(scene, p, config, BATCH_PATCHES, progress)
}

/// [`rows_on_machine`] in batches of at most `batch_patches` slices (1 to [`BATCH_PATCHES`]).
pub fn rows_on_machine_in(
    scene: &Scene3,
    p: &Ff3Params,
    config: &crate::machine::MachineConfig,
    batch_patches: usize,
    mut progress: impl FnMut(usize, usize),
) -> Result<(Vec<Row>, Pe3Totals), On3Error> {
    use crate::machine::{self, MachineConfig, Placement};
    check_params(p)?;
    let batch_patches = batch_patches.clamp(1, BATCH_PATCHES);
    if config.deal.parts(config.pes) != 1 {
        return Err(On3Error::Cosim(CosimError::Config(
            "--deal sectors cuts a source into parts; a sweep plane is dealt whole (blocks or interleaved)"
                .into(),
        )));
    }
    let config = MachineConfig { place: Placement::Index, vcd: None, ..config.clone() };
    let n = scene.polygons.len();
    let facets = Facets::new(scene);
    let mut acc = vec![vec![0.0f64; n]; n];
    let mut totals = Pe3Totals::default();
    let mut flush = |batch: &mut Batch, totals: &mut Pe3Totals| -> Result<(), On3Error> {
        let batch = std::mem::take(batch);
        let mut open = batch.open;
        if !batch.packs.is_empty() {
            let works = batch.packs.iter().map(|(_, pack)| pack_work(pack)).collect::<Result<Vec<_>, _>>()?;
            let run = machine::run_works(works, &config, |_, _| {})?;
            totals.packs += batch.packs.len();
            for ((b, pack), hits) in batch.packs.iter().zip(&run.hits) {
                let o = &mut open[*b];
                let at = Planes { scene, bundle: &o.bundle, scale: o.scale, p };
                at.offer_pack(pack, hits, &mut o.best)?;
            }
            totals.pe.add_machine(&run);
        }
        for o in &open {
            against_brute(scene, &facets, &o.bundle, &o.best, totals);
            for (hit, w) in o.best.iter().zip(&o.weights) {
                if let Some(h) = hit {
                    acc[o.k][h.polygon] += w;
                }
            }
        }
        Ok(())
    };
    let mut batch = Batch::default();
    for k in 0..n {
        let (mut set, origins) = ray_set(scene, k, p)?;
        let weight = 1.0 / origins.len() as f64;
        for origin in origins {
            set.origin = origin;
            let bundle = Bundle3::from_hemisphere(&set, Some(k));
            let scale = plane_scale(scene, origin);
            let at = Planes { scene, bundle: &bundle, scale, p };
            let mut best = vec![None; bundle.len()];
            let mut mine = Vec::new();
            for plane in planes_with(scene, &bundle, Slicing::Exact)? {
                at.host_tests(&plane, &mut totals, &mut best);
                if let Some(scheduled) = at.schedule(&plane, &mut totals.pe)? {
                    mine.push((plane, scheduled));
                }
            }
            let slices: usize = mine.iter().map(|(plane, _)| plane.polygons.len()).sum();
            if slices > batch_patches {
                return Err(On3Error::Cosim(CosimError::Config(format!(
                    "source polygon {k}: a bundle's sweep planes hold {slices} slices, more than a machine run's \
                     {batch_patches}: use fewer --rays (fewer planes)"
                ))));
            }
            if batch.slices + slices > batch_patches {
                flush(&mut batch, &mut totals)?;
            }
            let weights = set.rays.iter().map(|r| r.weight * weight).collect();
            batch.open.push(OpenBundle { k, bundle, weights, scale, best });
            let b = batch.open.len() - 1;
            batch.packs.extend(packs(mine).into_iter().map(|pack| (b, pack)));
            batch.slices += slices;
        }
        progress(k + 1, n);
    }
    flush(&mut batch, &mut totals)?;
    totals.pe.rows = n;
    Ok((acc.iter().enumerate().map(|(k, a)| to_row(k, a)).collect(), totals))
}
