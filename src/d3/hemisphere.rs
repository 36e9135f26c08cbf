//! Hemisphere ray sets: the rays shot from a point `O` with unit normal `n` over the hemisphere
//! `n` points into, stratified in the angles of Def. 2.5.
//!
//! # Angles
//!
//! In the local frame `(t, b, n)` of the normal ([`frame`]: Duff et al.'s orthonormal basis, so
//! the frame is a function of `n` alone), a direction is Def. 2.5's
//!
//! ```text
//! a(Θ, Φ) = sin Φ cos Θ · t + sin Φ sin Θ · b + cos Φ · n,    Θ ∈ [0, 2π),  Φ ∈ [0, π/2)
//! ```
//!
//! `Θ` is the azimuth around the normal and `Φ` the angle from it. Both sets split `Θ` into
//! `n_theta` equal **Θ-bands** `[2πi/n_theta, 2π(i+1)/n_theta)` and each band into `n_phi`
//! **Φ-cells** `[Φⱼ, Φⱼ₊₁)`, and shoot one ray per cell: `R = n_theta × n_phi` rays.
//!
//! # Numbering
//!
//! Ray `k` is cell `(i, j) = (k / n_phi, k % n_phi)`: row-major over (Θ-band, Φ-cell), so `Θ`
//! does not decrease with `k` and, within a band, `Φ` increases with `k`. A sector (Def. 2.5:
//! `Θ₁ ≤ Θ < Θ₂`, `Φ₁ ≤ Φ < Φ₂`) on cell boundaries, bands `i₀..i₁` and cells `j₀..j₁`, is
//! the `i₁ − i₀` contiguous runs `i·n_phi + j₀ .. i·n_phi + j₁` ([`HemisphereRays::sector`]);
//! a sector of whole bands (`j₀ = 0`, `j₁ = n_phi`) is one contiguous run.
//!
//! # The two sets
//!
//! The form factor from a differential area at `O` to a solid angle `dω` around `a` is
//! `cos Φ dω / π`; for a cell it is
//!
//! ```text
//! F(i, j) = (1/π) ∫∫ cos Φ sin Φ dΦ dΘ = (ΔΘ / 2π) · (sin² Φⱼ₊₁ − sin² Φⱼ),   ΔΘ = 2π / n_theta,
//! ```
//!
//! and the cells' form factors add up to 1 (the sum telescopes to `sin²(π/2) = 1`).
//!
//! * [`Strata::Angle`]: equal-angle cells, `Φⱼ = j·(π/2)/n_phi`; the ray goes through the cell's
//!   angular centre and carries the weight `F(i, j)` above (and its solid angle
//!   `ΔΘ (cos Φⱼ − cos Φⱼ₊₁)`). The equal-angle discretisation of the paper's 2D experiments.
//! * [`Strata::Cosine`]: the cosine-weighted (Nusselt analogue) set. A cell is an equal-area cell
//!   of the unit disc in `(r², Θ)` projected up onto the hemisphere (`r = sin Φ`): `sin² Φⱼ =
//!   j / n_phi`, so every cell has form factor exactly `1/R` and every ray carries weight `1/R`.
//!   The ray goes through the cell's centre in `(r², Θ)`: `sin² Φ = (j + ½)/n_phi`.

use super::scene::frame;
use glam::DVec3;
use std::f64::consts::{FRAC_PI_2, TAU};
use std::ops::Range;

/// The most rays in a set (as many as the 2D bundles allow, 2²⁰).
pub const MAX_HEMISPHERE_RAYS: usize = 1 << 20;

/// How the Φ-cells are laid out, see the module docs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Strata {
    /// Equal-angle cells in `(Θ, Φ)`, each ray weighted by its cell's form factor.
    Angle,
    /// Equal-form-factor cells (equal area in `(sin² Φ, Θ)`), each ray weighted `1/R`.
    Cosine,
}

/// One ray of a set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HemiRay {
    /// The unit direction `a(Θ, Φ)`.
    pub direction: DVec3,
    /// The azimuth `Θ` around the normal, in `[0, 2π)`.
    pub theta: f64,
    /// The angle `Φ` from the normal, in `[0, π/2)`.
    pub phi: f64,
    /// The form factor of the ray's cell: the weight of its hit in a form factor sum.
    pub weight: f64,
    /// The solid angle of the ray's cell, in steradians.
    pub solid_angle: f64,
}

/// What is wrong with a ray set's parameters.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum HemisphereError {
    #[error("the normal must be a finite non-zero vector, got {0}")]
    BadNormal(DVec3),
    #[error("the origin must be finite, got {0}")]
    BadOrigin(DVec3),
    #[error("the ray counts must be at least 1 and their product at most {MAX_HEMISPHERE_RAYS}, got {n_theta} × {n_phi}")]
    BadCount { n_theta: usize, n_phi: usize },
}

/// A hemisphere ray set: the rays from `origin` over the hemisphere of `normal`, numbered as the
/// module docs say.
#[derive(Clone, Debug, PartialEq)]
pub struct HemisphereRays {
    /// The point `O` the rays leave from.
    pub origin: DVec3,
    /// The unit normal `n`.
    pub normal: DVec3,
    /// The frame's first tangent `t` (`Θ = 0`).
    pub tangent: DVec3,
    /// The frame's second tangent `b = n × t` (`Θ = π/2`).
    pub bitangent: DVec3,
    /// The number of Θ-bands.
    pub n_theta: usize,
    /// The number of Φ-cells per band.
    pub n_phi: usize,
    /// The layout of the Φ-cells.
    pub strata: Strata,
    /// The rays, `n_theta × n_phi` of them, ray `k` in cell `(k / n_phi, k % n_phi)`.
    pub rays: Vec<HemiRay>,
}

impl HemisphereRays {
    /// The set of `n_theta × n_phi` rays from `origin` over `normal` (normalised here).
    pub fn new(
        origin: DVec3,
        normal: DVec3,
        n_theta: usize,
        n_phi: usize,
        strata: Strata,
    ) -> Result<HemisphereRays, HemisphereError> {
        if !origin.is_finite() {
            return Err(HemisphereError::BadOrigin(origin));
        }
        let length = normal.length();
        if !(length.is_finite() && length > 0.0) {
            return Err(HemisphereError::BadNormal(normal));
        }
        if n_theta == 0 || n_phi == 0 || n_theta.checked_mul(n_phi).is_none_or(|r| r > MAX_HEMISPHERE_RAYS) {
            return Err(HemisphereError::BadCount { n_theta, n_phi });
        }
        let normal = normal / length;
        let (tangent, bitangent) = frame(normal);
        let r = (n_theta * n_phi) as f64;
        let d_theta = TAU / n_theta as f64;
        // The Φ boundaries of cell j and the ray's Φ inside it.
        let cell = |j: usize| -> (f64, f64, f64) {
            let (nj, np) = (j as f64, n_phi as f64);
            match strata {
                Strata::Angle => {
                    let step = FRAC_PI_2 / np;
                    (nj * step, (nj + 1.0) * step, (nj + 0.5) * step)
                }
                Strata::Cosine => {
                    let s = |x: f64| x.clamp(0.0, 1.0).sqrt().asin();
                    (s(nj / np), s((nj + 1.0) / np), s((nj + 0.5) / np))
                }
            }
        };
        let mut rays = Vec::with_capacity(n_theta * n_phi);
        for i in 0..n_theta {
            let theta = (i as f64 + 0.5) * d_theta;
            let (st, ct) = theta.sin_cos();
            for j in 0..n_phi {
                let (lo, hi, phi) = cell(j);
                let (sp, cp) = phi.sin_cos();
                let direction = (tangent * (sp * ct) + bitangent * (sp * st) + normal * cp).normalize();
                let weight = match strata {
                    Strata::Angle => d_theta / TAU * (hi.sin().powi(2) - lo.sin().powi(2)),
                    Strata::Cosine => 1.0 / r,
                };
                let solid_angle = d_theta * (lo.cos() - hi.cos());
                rays.push(HemiRay { direction, theta, phi, weight, solid_angle });
            }
        }
        Ok(HemisphereRays { origin, normal, tangent, bitangent, n_theta, n_phi, strata, rays })
    }

    /// The number of rays `R`.
    pub fn len(&self) -> usize {
        self.rays.len()
    }

    /// Whether the set is empty (never, for a set [`HemisphereRays::new`] made).
    pub fn is_empty(&self) -> bool {
        self.rays.is_empty()
    }

    /// The index of the ray of cell `(band, cell)`.
    pub fn index(&self, band: usize, cell: usize) -> usize {
        band * self.n_phi + cell
    }

    /// The sector of bands `bands` and cells `cells` as contiguous runs of ray indices, one per
    /// band, in increasing order (empty when either range is; ranges are clipped to the set).
    pub fn sector(&self, bands: Range<usize>, cells: Range<usize>) -> Vec<Range<usize>> {
        let cells = cells.start.min(self.n_phi)..cells.end.min(self.n_phi);
        if cells.is_empty() {
            return Vec::new();
        }
        (bands.start.min(self.n_theta)..bands.end.min(self.n_theta))
            .map(|i| self.index(i, cells.start)..self.index(i, cells.start) + cells.len())
            .collect()
    }

    /// The Θ boundaries `[Θ₁, Θ₂)` of band `band`.
    pub fn band_bounds(&self, band: usize) -> (f64, f64) {
        let d = TAU / self.n_theta as f64;
        (band as f64 * d, (band + 1) as f64 * d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_ray_is_the_normal_with_weight_one() {
        for strata in [Strata::Angle, Strata::Cosine] {
            let set = HemisphereRays::new(DVec3::ZERO, DVec3::new(0.0, 2.0, 0.0), 1, 1, strata).unwrap();
            assert_eq!(set.len(), 1);
            assert!((set.rays[0].weight - 1.0).abs() < 1e-15);
            assert!(set.rays[0].direction.dot(DVec3::Y) > 0.5);
        }
    }

    #[test]
    fn sectors_are_clipped_to_the_set() {
        let set = HemisphereRays::new(DVec3::ZERO, DVec3::Z, 4, 3, Strata::Angle).unwrap();
        assert_eq!(set.sector(3..9, 2..9), vec![11..12]);
        assert!(set.sector(0..4, 2..2).is_empty());
        assert_eq!(set.sector(0..4, 0..3), vec![0..3, 3..6, 6..9, 9..12]);
    }
}
