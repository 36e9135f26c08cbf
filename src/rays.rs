//! Ray bundles over the half-circle ("hemisphere") of a source, and the source itself.
//!
//! Ray `i` of `R` leaves the source at the signed angle `φᵢ` from its normal `n`, with direction
//! `dᵢ = cos φᵢ·n + sin φᵢ·n⊥`, `n⊥ = n` rotated +90°. Two sets:
//!
//! * [`RaySet::Angle`]: uniform in angle, `φᵢ = −π/2 + (i + ½)·π/R`;
//! * [`RaySet::Sine`]: uniform in `sin φ`, `sin φᵢ = −1 + (2i + 1)/R`. In 2D the point-to-segment
//!   form factor is `½(sin φ₂ − sin φ₁)`, so each ray of this set carries form factor `1/R`.
//!
//! Rays are numbered by increasing angle, which the shelling tracers rely on (a sector is a
//! contiguous index range).

use crate::geom::{perp, Ray, Segment, Vec2};
use std::f64::consts::PI;
use std::fmt;

/// Which discretisation of the half-circle a bundle uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum RaySet {
    /// Uniform in angle.
    Angle,
    /// Uniform in sin φ: each ray carries form factor 1/R.
    Sine,
}

impl fmt::Display for RaySet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            RaySet::Angle => "angle",
            RaySet::Sine => "sine",
        })
    }
}

/// The largest bundle accepted.
pub const MAX_BUNDLE_RAYS: usize = 1 << 20;

/// What is wrong with a source or a bundle request.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SourceError {
    #[error("source patch {index} does not exist: the scene has {count} segments (0..{count})")]
    NoSuchPatch { index: usize, count: usize },
    #[error("the origin {0:?} is not a finite point")]
    BadOrigin([f64; 2]),
    #[error("the normal {0:?} must be finite and non-zero")]
    BadNormal([f64; 2]),
    #[error("the number of rays must be between 1 and {MAX_BUNDLE_RAYS}, got {0}")]
    BadRayCount(usize),
}

/// A source: the point the hemisphere is centred on, its unit normal, and optionally the patch
/// it sits on (excluded from the hits).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Source {
    pub origin: Vec2,
    pub normal: Vec2,
    pub patch: Option<u32>,
}

impl Source {
    /// The source at the midpoint of patch `k`, with the patch's normal; the patch is excluded.
    pub fn from_patch(segments: &[Segment], k: usize) -> Result<Source, SourceError> {
        let seg = segments.get(k).ok_or(SourceError::NoSuchPatch { index: k, count: segments.len() })?;
        Ok(Source { origin: seg.midpoint(), normal: seg.normal(), patch: Some(k as u32) })
    }

    /// A free-standing source; the normal is normalised.
    pub fn at(origin: Vec2, normal: Vec2) -> Result<Source, SourceError> {
        if !origin.is_finite() {
            return Err(SourceError::BadOrigin(origin.to_array()));
        }
        let len = normal.length();
        if !normal.is_finite() || len.is_nan() || len <= 0.0 || !len.is_finite() {
            return Err(SourceError::BadNormal(normal.to_array()));
        }
        Ok(Source { origin, normal: normal / len, patch: None })
    }
}

/// The angle of ray `i` of `r` in the given set.
pub fn ray_angle(set: RaySet, i: usize, r: usize) -> f64 {
    let x = (2 * i + 1) as f64 / r as f64; // in (0, 2)
    match set {
        RaySet::Angle => -PI / 2.0 + x * PI / 2.0,
        RaySet::Sine => (x - 1.0).asin(),
    }
}

/// A bundle of `R` rays from a source: the rays and their angles (increasing).
#[derive(Clone, Debug)]
pub struct Bundle {
    pub source: Source,
    pub set: RaySet,
    pub rays: Vec<Ray>,
    pub angles: Vec<f64>,
}

impl Bundle {
    pub fn new(source: Source, set: RaySet, r: usize) -> Result<Bundle, SourceError> {
        if r == 0 || r > MAX_BUNDLE_RAYS {
            return Err(SourceError::BadRayCount(r));
        }
        let n = source.normal;
        let np = perp(n);
        let angles: Vec<f64> = (0..r).map(|i| ray_angle(set, i, r)).collect();
        let rays =
            angles.iter().map(|&phi| Ray::new(source.origin, n * phi.cos() + np * phi.sin())).collect();
        Ok(Bundle { source, set, rays, angles })
    }

    pub fn len(&self) -> usize {
        self.rays.len()
    }

    pub fn is_empty(&self) -> bool {
        self.rays.is_empty()
    }

    /// The half-open range of ray indices whose angles lie in `[lo, hi]`.
    pub fn rays_between(&self, lo: f64, hi: f64) -> std::ops::Range<usize> {
        let a = self.partition(lo, |p| p < lo);
        let b = self.partition(hi, |p| p <= hi);
        a..b.max(a)
    }

    /// The first index whose angle fails `below` (`angles.partition_point(below)`), where `below`
    /// holds for the angles before `phi` (in the angles' order) and fails after it. The
    /// ray set's formula guesses the index and neighbouring angles confirm it, so the answer
    /// costs a load or two instead of a binary search's chain of dependent loads; the search
    /// remains the fallback when the guess is off.
    #[inline]
    fn partition(&self, phi: f64, below: impl Fn(f64) -> bool) -> usize {
        let r = self.angles.len();
        // Ray i has φᵢ = −π/2 + (i + ½)·π/R (angle set) or sin φᵢ = −1 + (2i + 1)/R (sine set):
        // the first ray at or after φ is about ⌈(φ + π/2)·R/π − ½⌉, resp. ⌈(sin φ + 1)·R/2 − ½⌉.
        let x = match self.set {
            RaySet::Angle => (phi + PI / 2.0) * (r as f64 / PI) - 0.5,
            RaySet::Sine => (phi.clamp(-PI / 2.0, PI / 2.0).sin() + 1.0) * (r as f64 / 2.0) - 0.5,
        };
        // ⌈x⌉ clamped into [0, R] (NaN gives 0; any guess is checked below).
        let x = x.clamp(-1.0, r as f64);
        let t = x as i64;
        let g = (t + ((t as f64) < x) as i64).max(0) as usize;
        let ok_before = g == 0 || below(self.angles[g - 1]);
        let ok_at = g == r || !below(self.angles[g]);
        if ok_before && ok_at {
            return g;
        }
        self.angles.partition_point(|&p| below(p))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angle_set_is_symmetric_and_increasing() {
        let r = 8;
        let a: Vec<f64> = (0..r).map(|i| ray_angle(RaySet::Angle, i, r)).collect();
        assert!((a[0] + PI / 2.0 - PI / 16.0).abs() < 1e-15);
        for i in 0..r {
            assert!((a[i] + a[r - 1 - i]).abs() < 1e-15);
        }
        assert!(a.windows(2).all(|w| w[0] < w[1]));
    }

    #[test]
    fn sine_set_is_uniform_in_sine() {
        let r = 10;
        for i in 0..r {
            let s = ray_angle(RaySet::Sine, i, r).sin();
            assert!((s - (-1.0 + (2 * i + 1) as f64 / r as f64)).abs() < 1e-15);
        }
    }

    #[test]
    fn bad_requests_are_errors() {
        let s = Source::at(Vec2::ZERO, Vec2::Y).unwrap();
        assert_eq!(Bundle::new(s, RaySet::Angle, 0).unwrap_err(), SourceError::BadRayCount(0));
        assert!(Source::at(Vec2::ZERO, Vec2::ZERO).is_err());
        assert!(Source::at(Vec2::new(f64::NAN, 0.0), Vec2::Y).is_err());
        assert!(Source::from_patch(&[], 0).is_err());
    }
}
