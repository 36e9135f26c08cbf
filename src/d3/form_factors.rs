//! 3D form factors from the tracers' hemisphere bundles (issue 18 part 6).
//!
//! The form factor `F_ij` from polygon `i` to polygon `j` is the fraction of the light leaving
//! `i` diffusely that arrives at `j` first. From one point `x` of `i` it is the differential
//! form factor `F(x → j) = (1/π) ∫ cos Φ dω` over the directions in which `j` is the nearest
//! polygon; for the whole of `i` it is the mean of `F(x → j)` over `x ∈ i`. Here, as in 2D
//! (`crate::radiosity::form_factors`):
//!
//! * **Rays.** From each origin, a [`HemisphereRays`] set of `R = n_theta × n_phi` rays with
//!   `i`'s normal ([`split_rays`] chooses the two counts from `R`). With the cosine-weighted
//!   (Nusselt) set, [`Strata::Cosine`] (the default), every ray carries exactly `1/R`; with the
//!   equal-angle set each ray carries its cell's form factor. `F(x → j)` is the sum of the
//!   weights of the rays whose nearest hit is `j`, `i` itself excluded.
//! * **Origins.** `M` points spread evenly over `i` by area ([`origins`]): the polygon is cut
//!   into the triangle fan from its vertex centroid `c`, `(c, Vₖ, Vₖ₊₁)`, and the point set
//!   `(uₘ, vₘ) = ((m + ½)/M, frac(m·g))`, `m = 0..M`, `g = (√5 − 1)/2` (a rank-1 lattice:
//!   exactly stratified in `u`, golden-ratio spaced in `v`) is carried onto the polygon by an
//!   area-preserving map: `u` picks the triangle by cumulative area and the position `u'`
//!   along its outer edge, `v` the distance from `c` as `√v` of the way to that edge,
//!   `x = c + √v·((1 − u')(Vₖ − c) + u'(Vₖ₊₁ − c))`. Each origin carries weight `1/M`. With
//!   `M = 1` the only origin is `c` itself (`v₀ = 0`), the paper's single central origin.
//!
//! Every tracer answers the same question (each ray's nearest hit), and the weights are added
//! in origin and then ray order, so every technique of [`Method3::ALL`] gives bit-identical form
//! factors.
//!
//! # The error of the estimate
//!
//! * *Rays*: from one origin, the rays of the cells inside `j`'s outline (projected onto the
//!   unit disc of the Nusselt analogue) count wholly and those outside not at all; a cell cut by
//!   the outline counts wholly or not at all by where its ray falls. So `|F̂(x → j) − F(x → j)|
//!   ≤ C/R` with `C` the number of cells the outline cuts, which grows as `√R` (worst case
//!   `O(1/√R)`). The cut cells' errors have either sign, so the typical error is far smaller.
//! * *Origins*: the lattice rule on `x ↦ F(x → j)` errs by `O(log M / M)` (its discrepancy
//!   times the variation of the integrand); where `j` shares an edge with `i` or an occluder's
//!   shadow crosses `i` the integrand has a kink and the error is of that order on the kinked
//!   part. The outline of `j` is seen from the `M` origins at different phases against the ray
//!   cells, so the ray errors of the origins partly cancel in the mean.
//!
//! At the defaults ([`DEFAULT_RAYS`] = 4096 cosine rays as 128 × 32, [`DEFAULT_ORIGINS`] = 256)
//! the closed-form cases of `tests/ff3d.rs` (Howell's C-11 and C-14, the cube, coaxial discs)
//! are within 0.2 % (measured: SCENES3D.md has the table and the command). Rows of a closed
//! scene sum to 1 up to rounding, whatever `R` and `M`, since every ray hits something.

use super::grid::Grid3;
use super::hemisphere::{HemisphereError, HemisphereRays, Strata, MAX_HEMISPHERE_RAYS};
use super::scene::{Polygon, Scene3};
use super::trace::{self, Bundle3, Method3, Trace3Error};
use crate::radiosity::form_factors::{par_rows, Entry, Row, MAX_ORIGINS};
use crate::trace::ShellParams;
use glam::DVec3;

/// Rays per origin of the 3D form factors, unless asked otherwise (128 × 32, [`split_rays`]).
pub const DEFAULT_RAYS: usize = 4096;

/// Origins per source polygon of the 3D form factors, unless asked otherwise.
pub const DEFAULT_ORIGINS: usize = 256;

/// `g = (√5 − 1)/2`, the golden ratio's fractional part: the lattice's `v` step.
const GOLDEN: f64 = 0.618_033_988_749_894_8;

/// How the 3D form factors of a row are estimated.
#[derive(Clone, Debug, PartialEq)]
pub struct Ff3Params {
    /// Rays per origin, `R` (split into `n_theta × n_phi` by [`split_rays`]).
    pub rays: usize,
    /// Origins per source polygon, `M`.
    pub origins: usize,
    /// The hemisphere set: [`Strata::Cosine`] (every ray `1/R`) or [`Strata::Angle`].
    pub strata: Strata,
    /// The tracer (all give the same form factors).
    pub method: Method3,
    /// The shell parameters of the polar and sweep tracers.
    pub shells: ShellParams,
}

impl Default for Ff3Params {
    fn default() -> Self {
        Ff3Params {
            rays: DEFAULT_RAYS,
            origins: DEFAULT_ORIGINS,
            strata: Strata::Cosine,
            method: Method3::Conventional,
            shells: ShellParams::default(),
        }
    }
}

/// What keeps a 3D form-factor row from being computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Ff3Error {
    #[error("--origins must be between 1 and {MAX_ORIGINS}, got {0}")]
    BadOrigins(usize),
    #[error("--rays must be between 1 and {MAX_HEMISPHERE_RAYS}, got {0}")]
    BadRays(usize),
    #[error("--source must be between 0 and {}, got {index} (the scene has {count} polygons)", count - 1)]
    NoSuchPolygon { index: usize, count: usize },
    #[error(transparent)]
    Hemisphere(#[from] HemisphereError),
    #[error(transparent)]
    Trace(#[from] Trace3Error),
}

/// The counts `(n_theta, n_phi)` of an `r`-ray hemisphere set: `n_phi` is the divisor of `r`
/// nearest to `√(r / 2π)` in ratio (ties to the smaller), `n_theta = r / n_phi`. Near the
/// middle of the Nusselt disc (`sin² Φ = ½`) a cell is then about as wide in `Θ` as it is
/// long in `Φ`. Powers of two give `n_theta = 4·n_phi` (4096 = 128 × 32) or `8·n_phi`.
pub fn split_rays(r: usize) -> Result<(usize, usize), Ff3Error> {
    if r == 0 || r > MAX_HEMISPHERE_RAYS {
        return Err(Ff3Error::BadRays(r));
    }
    let target = (r as f64 / std::f64::consts::TAU).sqrt();
    let mut best = 1usize;
    for d in 1..=r {
        if d * d > r * 64 {
            break;
        }
        if r % d == 0 && (d as f64 / target).ln().abs() < (best as f64 / target).ln().abs() {
            best = d;
        }
    }
    Ok((r / best, best))
}

/// The `m` origins on `polygon` (module docs: a rank-1 lattice carried onto the triangle fan
/// from the vertex centroid by an area-preserving map); each carries weight `1/m`.
pub fn origins(polygon: &Polygon, m: usize) -> Result<Vec<DVec3>, Ff3Error> {
    if m == 0 || m > MAX_ORIGINS {
        return Err(Ff3Error::BadOrigins(m));
    }
    let c = polygon.centre;
    let v = &polygon.vertices;
    let n = v.len();
    // The fan's triangles' areas, cumulated.
    let areas: Vec<f64> = (0..n).map(|k| 0.5 * (v[k] - c).cross(v[(k + 1) % n] - c).length()).collect();
    let total: f64 = areas.iter().sum();
    Ok((0..m)
        .map(|i| {
            let u = (i as f64 + 0.5) / m as f64 * total;
            let w = (i as f64 * GOLDEN).fract().sqrt();
            // The triangle whose share of the area holds `u`, and `u`'s fraction of it.
            let mut below = 0.0;
            let mut k = 0;
            while k + 1 < n && below + areas[k] <= u {
                below += areas[k];
                k += 1;
            }
            // The centroid is inside a convex polygon, so no fan triangle has zero area; should
            // rounding make one so, never divide by its area.
            let along = if areas[k] > 0.0 { ((u - below) / areas[k]).clamp(0.0, 1.0) } else { 0.5 };
            c + ((v[k] - c) * (1.0 - along) + (v[(k + 1) % n] - c) * along) * w
        })
        .collect())
}

/// The hemisphere set of source polygon `k` from its vertex centroid, with `k`'s front
/// normal, and the origins its rays leave from: every origin shoots the same directions (the
/// set depends on the normal only), so [`row`] moves the set's `origin` to each in turn.
pub fn ray_set(scene: &Scene3, k: usize, p: &Ff3Params) -> Result<(HemisphereRays, Vec<DVec3>), Ff3Error> {
    let count = scene.polygons.len();
    let polygon = scene.polygons.get(k).ok_or(Ff3Error::NoSuchPolygon { index: k, count })?;
    let (n_theta, n_phi) = split_rays(p.rays)?;
    let origins = origins(polygon, p.origins)?;
    Ok((HemisphereRays::new(polygon.centre, polygon.normal, n_theta, n_phi, p.strata)?, origins))
}

/// The form-factor row of source polygon `k`, traced with `p.method` (`grid` is built over
/// `scene`; the brute-force tracer does not use it). Entries ascend in `j`, zeros left out.
pub fn row(scene: &Scene3, grid: &Grid3, k: usize, p: &Ff3Params) -> Result<Row, Ff3Error> {
    let (mut set, origins) = ray_set(scene, k, p)?;
    let scale = 1.0 / origins.len() as f64;
    let mut acc = vec![0.0f64; scene.polygons.len()];
    for origin in origins {
        set.origin = origin;
        let traced =
            trace::trace(p.method, scene, grid, &Bundle3::from_hemisphere(&set, Some(k)), &p.shells)?;
        for (hit, ray) in traced.hits.iter().zip(&set.rays) {
            if let Some(h) = hit {
                acc[h.polygon] += ray.weight * scale;
            }
        }
    }
    Ok(to_row(k, &acc))
}

/// The differential form factors `F(x → j)` of the point `origin` with normal `normal` (any
/// non-zero length): one origin, no polygon excluded; the row's `source` is
/// `usize::MAX`.
pub fn point_row(
    scene: &Scene3,
    grid: &Grid3,
    origin: DVec3,
    normal: DVec3,
    p: &Ff3Params,
) -> Result<Row, Ff3Error> {
    let (n_theta, n_phi) = split_rays(p.rays)?;
    let set = HemisphereRays::new(origin, normal, n_theta, n_phi, p.strata)?;
    let traced = trace::trace(p.method, scene, grid, &Bundle3::from_hemisphere(&set, None), &p.shells)?;
    let mut acc = vec![0.0f64; scene.polygons.len()];
    for (hit, ray) in traced.hits.iter().zip(&set.rays) {
        if let Some(h) = hit {
            acc[h.polygon] += ray.weight;
        }
    }
    Ok(to_row(usize::MAX, &acc))
}

/// The row of `acc`, zeros left out.
pub(crate) fn to_row(k: usize, acc: &[f64]) -> Row {
    let entries = acc
        .iter()
        .enumerate()
        .filter(|(_, &f)| f != 0.0)
        .map(|(j, &ff)| Entry { patch: j as u32, ff })
        .collect();
    Row { source: k, entries }
}

/// The rows of the sources `range`, computed on all cores, in order; `progress` is called once
/// per finished row.
pub fn rows(
    scene: &Scene3,
    grid: &Grid3,
    range: std::ops::Range<usize>,
    p: &Ff3Params,
    progress: impl Fn() + Sync,
) -> Result<Vec<Row>, Ff3Error> {
    par_rows(range, progress, |k| row(scene, grid, k, p))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Polygon {
        Polygon::new(vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y]).unwrap()
    }

    #[test]
    fn ray_counts_split_near_square_cells() {
        assert_eq!(split_rays(4096).unwrap(), (128, 32));
        assert_eq!(split_rays(1024).unwrap(), (64, 16));
        assert_eq!(split_rays(1).unwrap(), (1, 1));
        assert_eq!(split_rays(13).unwrap(), (13, 1));
        for r in 1..2000 {
            let (t, p) = split_rays(r).unwrap();
            assert_eq!(t * p, r);
        }
        assert_eq!(split_rays(0), Err(Ff3Error::BadRays(0)));
        assert!(split_rays(MAX_HEMISPHERE_RAYS + 1).is_err());
    }

    #[test]
    fn collinear_vertices_give_finite_origins() {
        // A square with an extra vertex in the middle of two sides (collinear vertices, which a
        // valid polygon may have): six fan triangles of two sizes.
        let p = Polygon::new(vec![
            DVec3::ZERO,
            DVec3::new(0.5, 0.0, 0.0),
            DVec3::X,
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.5, 1.0, 0.0),
            DVec3::Y,
        ])
        .unwrap();
        for m in [1, 2, 3, 7, 64, 1000] {
            assert!(origins(&p, m).unwrap().iter().all(|o| o.is_finite() && o.z == 0.0), "m = {m}");
        }
    }

    #[test]
    fn one_origin_is_the_vertex_centroid() {
        let p = square();
        assert_eq!(origins(&p, 1).unwrap(), vec![p.centre]);
        assert_eq!(origins(&p, 0), Err(Ff3Error::BadOrigins(0)));
    }

    #[test]
    fn origins_lie_inside_and_spread_evenly_by_area() {
        // A quadrilateral with unequal fan triangles: each quarter of the square [0,1]² gets
        // its share of the origins, within the lattice's stratification.
        let p = square();
        let m = 400;
        let o = origins(&p, m).unwrap();
        assert!(o.iter().all(|x| x.z == 0.0 && (0.0..=1.0).contains(&x.x) && (0.0..=1.0).contains(&x.y)));
        for (lo, hi) in [((0.0, 0.0), (0.5, 0.5)), ((0.5, 0.0), (1.0, 0.5)), ((0.0, 0.5), (0.5, 1.0))] {
            let inside = o.iter().filter(|x| x.x >= lo.0 && x.x < hi.0 && x.y >= lo.1 && x.y < hi.1).count();
            assert!((inside as f64 - m as f64 / 4.0).abs() <= 12.0, "{inside} of {m} in {lo:?}..{hi:?}");
        }
        // The mean of the origins is the area centroid (here the centre).
        let mean = o.iter().sum::<DVec3>() / m as f64;
        assert!((mean - p.centre).length() < 5e-3, "{mean}");
    }
}
