//! The sweep tracer: the paper's second extension of shelling to 3D (§3.2, Figures 2 and 3). A
//! plane through the source's normal is rotated about it; each position slices the hemisphere's
//! rays and the polygons into a 2D scene of rays and segments, and the 2D deterministic technique
//! (shelling D, [`crate::trace`]) traces it, deriving each slice's actual degree of local
//! coherence by sorting the slices by angle.
//!
//! # The planes
//!
//! The hemisphere set's Θ-band `i` and band `i + n_theta/2` hold rays of opposite azimuths, so
//! plane `i` (`0 ≤ i < n_theta/2`, `n_theta` even, [`Trace3Error::OddBands`] otherwise) holds
//! both: `2·n_phi` rays. Its 2D coordinates (the paper's rotation onto the YZ-plane) are, for a
//! point `X`, `x = (X − O)·u`, `y = (X − O)·n`, with `n` the source's normal and `u` the unit
//! azimuth of band `i`'s rays: the source is at the 2D origin with normal `(0, 1)`, and 2D
//! distances are 3D distances. The plane's 2D rays are its 3D rays' directions in these
//! coordinates, numbered by increasing 2D angle as every 2D bundle is ([`SweepPlane::rays`] maps
//! them back).
//!
//! # The slices
//!
//! Every polygon that passes the 3D screener ([`super::trace::screen`]) and meets the plane
//! becomes a segment of the plane's 2D [`Scene`], in increasing polygon index (so the 2D tie rule,
//! the lower segment index, is the 3D one): the extent, along the line where the polygon's plane
//! meets the sweep plane, of its registration polygon (which holds every point the hit rule
//! accepts) within `τ` of the sweep plane, `τ` bounding how far rounding lets a ray of the plane
//! stray from it ([`slab`]). Its front side is the side the polygon's normal points to. Three
//! kinds of polygon are not sliced but tested directly against every ray of the plane (the
//! plane's [`SweepPlane::direct`] list; each test is a load and an intersection computation):
//! a polygon whose plane is within [`PARALLEL_LIMIT`] of parallel to the sweep plane (its slice
//! is ill-conditioned), one whose slice has no length, and one whose slice the 2D screener would
//! judge back-facing although the 3D screener passed it (the source within rounding of its
//! plane). Random scenes have almost none.
//!
//! # Hits
//!
//! The 2D tracer runs through [`crate::trace::trace_with`] with a [`crate::trace::HitTest`]
//! backend that decides each (ray, segment) pair it schedules in 3D, by [`super::brute::intersect`]
//! of the 3D ray against the 3D polygon, so the answer is the brute-force 3D hit exactly; the
//! 2D tracer only chooses the pairs, and the hit distance (the 3D `t`, equal to the 2D distance for
//! the unit directions of a hemisphere set) drives its retirement. The direct list's hits are then
//! offered by the 3D tie rule.
//!
//! # Counters
//!
//! The sum over the planes of the 2D tracer's counters plus the direct tests;
//! `adlc_true` is the 3D ADLC over the whole bundle and `adlc_estimated` the **ADLC captured in
//! the planes**: the rays that hit over the sum, over planes, of the distinct polygons the
//! plane's rays hit (the paper's remark that the degree of local coherence captured in 2D is far
//! less than the actual degree is `adlc_estimated` against `adlc_true`).

use super::brute::{intersect, Hit};
use super::grid::RegistrationPolygon;
use super::scene::Scene3;
use super::trace::{finish, offer, screen, Bundle3, Method3, Screen3, Trace3, Trace3Error};
use crate::counters::Counters;
use crate::geom::{angle_of, facing, Facing, Ray, Segment, Vec2};
use crate::grid::{Grid, GridParams};
use crate::rays::{Bundle, RaySet, Source};
use crate::scene::{Material, Scene};
use crate::trace::{trace_with, HitTest, Method, SceneView, ShellParams};
use glam::DVec3;
use std::f64::consts::TAU;

/// A polygon whose unit normal has a component in the sweep plane shorter than this (its plane
/// within about 10⁻³ rad of parallel to the sweep plane) is tested directly: its slice is
/// ill-conditioned.
pub const PARALLEL_LIMIT: f64 = 1e-3;

/// One position of the sweep plane: its 2D scene, grid and bundle, and the maps back to 3D.
#[derive(Clone, Debug)]
pub struct SweepPlane {
    /// The Θ-band whose azimuth is the plane's `+x` axis (the other band is `band + n_theta/2`).
    pub band: usize,
    /// The plane's `x` axis in 3D, `u`.
    pub axis: DVec3,
    /// The slices, when any polygon meets the plane: the 2D scene (segment `s` is polygon
    /// `polygons[s]`, reflectance and emission carried over) and its 2D grid.
    pub slices: Option<(Scene, Grid)>,
    /// The polygon of each segment, increasing.
    pub polygons: Vec<usize>,
    /// The polygons tested directly against every ray of the plane (module docs).
    pub direct: Vec<usize>,
    /// The plane's 2D bundle: the source at the origin with normal `(0, 1)`.
    pub bundle: Bundle,
    /// The 3D ray of each 2D ray.
    pub rays: Vec<usize>,
}

/// How far (in world units) rounding lets a ray of a plane stray from it within the scene: a
/// bound on the rounding of the rays' directions and of the coordinates, over the scene's extent.
pub fn slab(scene: &Scene3, o: DVec3) -> f64 {
    let (lo, hi) = scene.bounds();
    let scale = lo.abs().max(hi.abs()).max(o.abs()).max_element().max(1.0);
    let far = (hi - lo).length() + (o - (lo + hi) * 0.5).length();
    64.0 * f64::EPSILON * (scale + far)
}

/// What a polygon's segment in a plane is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Slicing {
    /// The extent of its registration polygon within the slab `|h| ≤ τ` ([`slab`]): a superset
    /// of every point the hit rule accepts, for a tracer whose hits are decided in 3D.
    Registration,
    /// The polygon itself cut by the plane (`h = 0`): a ray of the plane hits the segment exactly
    /// where it hits the polygon, so a 2D tracer's hit on the slices is the 3D hit (up to
    /// rounding); what the 2D hardware traces ([`super::on_pe`]).
    Exact,
}

/// The planes of `bundle` (a hemisphere set's, with an even number of Θ-bands) over `scene`,
/// the polygons sliced by their registration polygons ([`Slicing::Registration`]).
pub fn planes(scene: &Scene3, bundle: &Bundle3) -> Result<Vec<SweepPlane>, Trace3Error> {
    planes_with(scene, bundle, Slicing::Registration)
}

/// The planes of `bundle` over `scene`, the polygons sliced as `slicing` says.
pub fn planes_with(
    scene: &Scene3,
    bundle: &Bundle3,
    slicing: Slicing,
) -> Result<Vec<SweepPlane>, Trace3Error> {
    let layout = bundle.layout_for(Method3::Sweep)?;
    if !layout.n_theta.is_multiple_of(2) {
        return Err(Trace3Error::OddBands(layout.n_theta));
    }
    let src = &bundle.source;
    let pass: Vec<usize> =
        (0..scene.polygons.len()).filter(|&k| screen(src, k, &scene.polygons[k]) == Screen3::Pass).collect();
    let (regs, tau): (Vec<Vec<DVec3>>, f64) = match slicing {
        Slicing::Registration => (
            pass.iter().map(|&k| RegistrationPolygon::new(&scene.polygons[k]).vertices).collect(),
            slab(scene, src.origin),
        ),
        Slicing::Exact => (pass.iter().map(|&k| scene.polygons[k].vertices.clone()).collect(), 0.0),
    };
    let half = layout.n_theta / 2;
    let mut out = Vec::with_capacity(half);
    for band in 0..half {
        let theta = (band as f64 + 0.5) * (TAU / layout.n_theta as f64);
        let u = layout.tangent * theta.cos() + layout.bitangent * theta.sin();
        let n = src.normal;
        let m = u.cross(n);
        let to2 = |x: DVec3| Vec2::new((x - src.origin).dot(u), (x - src.origin).dot(n));
        // The plane's rays, numbered by 2D angle.
        let mut rays: Vec<(f64, usize, Vec2)> = [band, band + half]
            .iter()
            .flat_map(|&b| (0..layout.n_phi).map(move |j| b * layout.n_phi + j))
            .map(|k| {
                let d = bundle.directions[k];
                let d2 = Vec2::new(d.dot(u), d.dot(n)).normalize();
                (angle_of(Vec2::ZERO, Vec2::Y, d2), k, d2)
            })
            .collect();
        rays.sort_by(|a, b| a.0.total_cmp(&b.0));
        let source = Source { origin: Vec2::ZERO, normal: Vec2::Y, patch: None };
        let bundle2 = Bundle {
            source,
            set: RaySet::Angle,
            rays: rays.iter().map(|r| Ray::new(Vec2::ZERO, r.2)).collect(),
            angles: rays.iter().map(|r| r.0).collect(),
        };
        let mut segments = Vec::new();
        let mut materials = Vec::new();
        let mut polygons = Vec::new();
        let mut direct = Vec::new();
        for (q, &k) in pass.iter().enumerate() {
            let p = &scene.polygons[k];
            let v = &regs[q];
            let h: Vec<f64> = v.iter().map(|x| (*x - src.origin).dot(m)).collect();
            let (hlo, hhi) =
                h.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)));
            if hlo > tau || hhi < -tau {
                continue;
            }
            let n2 = Vec2::new(p.normal.dot(u), p.normal.dot(n));
            if n2.length() < PARALLEL_LIMIT {
                direct.push(k);
                continue;
            }
            // The (registration) polygon within the slab |h| ≤ τ, along the line it meets.
            let dir = crate::geom::perp(n2).normalize();
            let (mut slo, mut shi) = (f64::INFINITY, f64::NEG_INFINITY);
            let mut take = |x: DVec3| {
                let s = to2(x).dot(dir);
                slo = slo.min(s);
                shi = shi.max(s);
            };
            let c = v.len();
            for i in 0..c {
                let (a, b, ha, hb) = (v[i], v[(i + 1) % c], h[i], h[(i + 1) % c]);
                if ha.abs() <= tau {
                    take(a);
                }
                for level in [-tau, tau] {
                    if (ha - level) * (hb - level) < 0.0 {
                        take(a + (b - a) * ((level - ha) / (hb - ha)));
                    }
                }
            }
            // The line: n2·x + (O − c)·n_P = 0, its point nearest the 2D origin.
            let q0 = -n2 * ((src.origin - p.centre).dot(p.normal) / n2.length_squared());
            let q0 = q0 - dir * q0.dot(dir);
            // Front side along n2: b − a runs along −dir.
            let seg = Segment::new(q0 + dir * shi, q0 + dir * slo);
            if shi.partial_cmp(&slo) != Some(std::cmp::Ordering::Greater)
                || facing(Vec2::ZERO, Vec2::Y, &seg) == Facing::BackFacing
                || seg.a == seg.b
            {
                direct.push(k);
                continue;
            }
            segments.push(seg);
            materials.push(Material { reflectance: Some(p.reflectance), emission: Some(p.emission) });
            polygons.push(k);
        }
        let slices = if segments.is_empty() {
            None
        } else {
            let scene2 = Scene { segments, materials, world: None };
            let grid = Grid::build(&scene2.segments, scene2.bounds(), GridParams::default());
            Some((scene2, grid))
        };
        out.push(SweepPlane {
            band,
            axis: u,
            slices,
            polygons,
            direct,
            bundle: bundle2,
            rays: rays.iter().map(|r| r.1).collect(),
        });
    }
    Ok(out)
}

/// The backend that decides a plane's (ray, segment) pairs in 3D: the 3D ray against the 3D
/// polygon by the hit rule.
struct Hits3<'a> {
    scene: &'a Scene3,
    bundle: &'a Bundle3,
    plane: &'a SweepPlane,
}

impl HitTest for Hits3<'_> {
    #[inline]
    fn hit(&self, _bundle: &Bundle, i: usize, p: u32, _seg: &Segment) -> Option<f64> {
        let d = self.bundle.directions[self.plane.rays[i]];
        intersect(self.bundle.source.origin, d, &self.scene.polygons[self.plane.polygons[p as usize]])
    }
}

/// Traces `bundle` (a hemisphere set's, `n_theta` even) by the sweep technique (module docs).
pub fn trace(scene: &Scene3, bundle: &Bundle3, params: &ShellParams) -> Result<Trace3, Trace3Error> {
    let planes = planes(scene, bundle)?;
    let o = bundle.source.origin;
    let mut best: Vec<Option<Hit>> = vec![None; bundle.len()];
    let mut c = Counters::default();
    for plane in &planes {
        if let Some((scene2, grid)) = &plane.slices {
            let view = SceneView { segments: &scene2.segments, grid };
            let backend = Hits3 { scene, bundle, plane };
            let r = trace_with(Method::Deterministic, view, &plane.bundle, params, &backend)
                .map_err(|crate::trace::TraceError::InvalidParams(e)| Trace3Error::InvalidParams(e))?;
            for (i, h) in r.hits.iter().enumerate() {
                if let Some(h) = h {
                    let k = plane.polygons[h.segment as usize];
                    let ray = plane.rays[i];
                    offer(&mut best[ray], k, h.t, bundle.directions[ray].dot(scene.polygons[k].normal) < 0.0);
                }
            }
            c.patches_read_before_screening += r.counters.patches_read_before_screening;
            c.patches_read_after_screening += r.counters.patches_read_after_screening;
            c.cells_traversed += r.counters.cells_traversed;
            c.intersection_computations += r.counters.intersection_computations;
        }
        for &k in &plane.direct {
            let p = &scene.polygons[k];
            c.patches_read_before_screening += 1;
            c.patches_read_after_screening += 1;
            for &ray in &plane.rays {
                let d = bundle.directions[ray];
                c.intersection_computations += 1;
                if let Some(t) = intersect(o, d, p) {
                    offer(&mut best[ray], k, t, d.dot(p.normal) < 0.0);
                }
            }
        }
    }
    // The ADLC captured in the planes: hits over the planes' distinct polygons.
    let (mut hitting, mut distinct) = (0usize, 0usize);
    for plane in &planes {
        let mut ids: Vec<usize> = plane.rays.iter().filter_map(|&r| best[r].map(|h| h.polygon)).collect();
        hitting += ids.len();
        ids.sort_unstable();
        ids.dedup();
        distinct += ids.len();
    }
    let captured = if distinct == 0 { 0.0 } else { hitting as f64 / distinct as f64 };
    Ok(finish(best, c, Some(captured)))
}
