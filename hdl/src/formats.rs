//! The number formats of the datapath and the conversions into them (see `FORMATS.md`).
//!
//! Every value the hardware sees is a two's-complement integer with an implied binary point:
//!
//! | quantity | bits | format | unit of one LSB |
//! |---|---|---|---|
//! | world coordinate (host side, after the scene offset) | 17 unsigned | Q11.6 | 2⁻⁶ world units |
//! | coordinate relative to the ray origin `a = A − O` | 18 signed | Q12.6 | 2⁻⁶ |
//! | ray direction and source normal `d` | 18 signed | Q2.16 | 2⁻¹⁶ |
//! | product `x·y` of two 18-bit values ([`mul`]) | 32 signed | product ≫ 4 | 2⁻⁴ of the product's LSB |
//! | side value `cross(d, a)` | 32 signed | | 2⁻²⁶ (world units × unit direction) |
//! | per-patch inverse-distance vector `W` | 18 signed | normalised, exponent `sh` | see `FORMATS.md` |
//! | distance key `U ≈ 2²⁶ / t` | 32 unsigned | Q6.26 | larger is nearer |
//!
//! Conversions round to nearest (ties away from zero). Values that do not fit are errors
//! ([`FormatError`]), never wrapped.
//!
//! The records that cross from one block's model to another's live here too, so that no block
//! imports another: [`PatchSetup`] (the screener's output, the intersection unit's input),
//! [`Nearest`] (a ray's nearest hit) and [`key`] (the distance key, computed by the intersection
//! unit's key stage).

/// Fraction bits of a coordinate.
pub const COORD_FRAC: u32 = 6;
/// Width of a coordinate relative to the ray origin (signed).
pub const COORD_BITS: u32 = 18;
/// The span of world coordinates the datapath can hold: every endpoint and the origin must lie
/// within `[offset, offset + WORLD_SPAN)` on each axis, after rounding.
pub const WORLD_SPAN: f64 = (1u64 << (COORD_BITS - 1 - COORD_FRAC)) as f64;
/// Fraction bits of a direction component.
pub const DIR_FRAC: u32 = 16;
/// Width of a direction component (signed).
pub const DIR_BITS: u32 = 18;
/// Right shift applied to every 18×18 product so that sums fit in 32 bits.
pub const PRODUCT_SHIFT: u32 = 4;
/// Fraction bits of the distance key: `U = 2^KEY_FRAC / t`.
pub const KEY_FRAC: u32 = 26;
/// Largest per-patch exponent `sh`.
pub const SH_MAX: i32 = 31;
/// Smallest per-patch exponent `sh` (a left shift of the key, saturating).
pub const SH_MIN: i32 = -3;
/// Width of the per-patch exponent `sh` (two's complement).
pub const SH_BITS: u32 = 6;
/// Margin of the sector screen, in LSBs of a side value (see `FORMATS.md`).
pub const SECTOR_MARGIN: i64 = 256;
/// Width of a patch id.
pub const ID_BITS: u32 = 16;
/// Width of a component of a patch's inverse-distance vector `W` (signed, normalised by `sh`).
pub const W_BITS: u32 = 18;

// The widths above as the RTL's `Bits<N>` widths (const generics take `usize`).
/// A coordinate relative to the ray origin, and what is formed from them (`n`, `|n|`, `nmax`).
pub const COORD_W: usize = COORD_BITS as usize;
/// A world coordinate: unsigned, the relative coordinate's width less its sign (Q11.6).
pub const WORLD_W: usize = COORD_W - 1;
/// A direction component (the source's normal, a sector's edges, a ray).
pub const DIR_W: usize = DIR_BITS as usize;
/// A patch id.
pub const ID_W: usize = ID_BITS as usize;
/// The exponent `sh`, and the leading-zero counts it is formed from.
pub const SH_W: usize = SH_BITS as usize;
/// A component of `W`.
pub const W_W: usize = W_BITS as usize;

/// Smallest and largest value of a signed `bits`-wide integer.
pub const fn signed_range(bits: u32) -> (i64, i64) {
    (-(1i64 << (bits - 1)), (1i64 << (bits - 1)) - 1)
}

/// A value that does not fit its format.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FormatError {
    #[error("{what} = {value} is not a finite number")]
    NotFinite { what: String, value: f64 },
    #[error(
        "{what} = {value} lies outside the fixed-point range: every coordinate must lie within \
         [{lo}, {hi}) (a window of {span} world units at 1/{scale} resolution, Q11.6)"
    )]
    OutOfRange { what: String, value: f64, lo: f64, hi: f64, span: f64, scale: u32 },
    #[error("{what} = {value} is not a unit-vector component in [-1, 1]")]
    BadDirection { what: String, value: f64 },
    #[error("the scene has {count} patches; patch ids are {bits} bits wide (at most {max})")]
    TooManyPatches { count: usize, bits: u32, max: usize },
}

/// The quantiser of world coordinates: subtracts an integer offset (so that any scene spanning
/// less than [`WORLD_SPAN`] units per axis fits, wherever it lies) and rounds to 2⁻⁶.
///
/// Rounding after an integer offset is translation invariant, so relative coordinates do not
/// depend on the offset chosen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quantizer {
    pub offset: [f64; 2],
}

impl Quantizer {
    /// The quantiser whose window starts at the floor of the smallest coordinate of `points`.
    pub fn covering(points: impl IntoIterator<Item = [f64; 2]>) -> Quantizer {
        let mut lo = [f64::INFINITY; 2];
        for p in points {
            for k in 0..2 {
                if p[k].is_finite() {
                    lo[k] = lo[k].min(p[k]);
                }
            }
        }
        Quantizer { offset: lo.map(|v| if v.is_finite() { v.floor() } else { 0.0 }) }
    }

    /// The quantised coordinate (Q11.6, unsigned 17 bits) of `value` on `axis`.
    pub fn coord(&self, what: impl Fn() -> String, axis: usize, value: f64) -> Result<i32, FormatError> {
        if !value.is_finite() {
            return Err(FormatError::NotFinite { what: what(), value });
        }
        let scale = (1u32 << COORD_FRAC) as f64;
        let q = ((value - self.offset[axis]) * scale).round();
        if !(0.0..(1u64 << (COORD_BITS - 1)) as f64).contains(&q) {
            let lo = self.offset[axis];
            return Err(FormatError::OutOfRange {
                what: what(),
                value,
                lo,
                hi: lo + WORLD_SPAN,
                span: WORLD_SPAN,
                scale: 1 << COORD_FRAC,
            });
        }
        Ok(q as i32)
    }

    /// Both coordinates of a point.
    pub fn point(&self, what: impl Fn() -> String, p: [f64; 2]) -> Result<[i32; 2], FormatError> {
        Ok([
            self.coord(|| format!("{} x", what()), 0, p[0])?,
            self.coord(|| format!("{} y", what()), 1, p[1])?,
        ])
    }
}

/// Quantises a unit vector's components to Q2.16.
pub fn direction(what: impl Fn() -> String, v: [f64; 2]) -> Result<[i32; 2], FormatError> {
    let mut out = [0; 2];
    for k in 0..2 {
        let x = v[k];
        if !x.is_finite() || x.abs() > 1.0 + 1e-9 {
            return Err(FormatError::BadDirection { what: format!("{} component {k}", what()), value: x });
        }
        out[k] = (x.clamp(-1.0, 1.0) * (1u32 << DIR_FRAC) as f64).round() as i32;
    }
    Ok(out)
}

/// The 18×18 signed product as the multiplier block computes it: exact, then arithmetic shift
/// right by [`PRODUCT_SHIFT`] (rounding toward −∞). Both operands must be 18-bit values; the
/// result then lies in [−2³⁰, 2³⁰]. A direction (|component| ≤ 2¹⁶) times an 18-bit value lies
/// in [−2²⁹, 2²⁹], so a sum or difference of two such products fits 32 bits.
#[inline]
pub fn mul(x: i32, y: i32) -> i32 {
    debug_assert!(fits_signed(x as i64, DIR_BITS) && fits_signed(y as i64, COORD_BITS));
    ((x as i64 * y as i64) >> PRODUCT_SHIFT) as i32
}

/// `cross(d, p) = d.x·p.y − d.y·p.x` from two truncated products: the side value of point `p`
/// against the ray with direction `d` (positive when `p` lies to the left of the ray).
#[inline]
pub fn cross(d: [i32; 2], p: [i32; 2]) -> i32 {
    // The datapath is 32 bits wide and wraps; inside the formats' ranges it never does.
    mul(d[0], p[1]).wrapping_sub(mul(d[1], p[0]))
}

/// `d·p` from two truncated products.
#[inline]
pub fn dot(d: [i32; 2], p: [i32; 2]) -> i32 {
    mul(d[0], p[0]).wrapping_add(mul(d[1], p[1]))
}

/// `true` when `v` fits a signed `bits`-wide integer.
#[inline]
pub const fn fits_signed(v: i64, bits: u32) -> bool {
    let (lo, hi) = signed_range(bits);
    v >= lo && v <= hi
}

/// The distance in world units a key stands for: `2^KEY_FRAC / U`. Strictly decreasing in `U`,
/// so distances compare exactly as keys do.
#[inline]
pub fn key_distance(key: u32) -> f64 {
    (1u64 << KEY_FRAC) as f64 / key.max(1) as f64
}

/// Two's-complement bits of a signed value in a `bits`-wide field (for ports and VCDs).
#[inline]
pub const fn to_bits(v: i64, bits: u32) -> u64 {
    (v as u64) & ((1u64 << bits) - 1)
}

/// The signed value of a `bits`-wide two's-complement field.
#[inline]
pub const fn from_bits(v: u64, bits: u32) -> i64 {
    let shift = 64 - bits;
    ((v << shift) as i64) >> shift
}

/// What the intersection unit needs of a patch: the screener's output, set up for one bundle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct PatchSetup {
    pub id: u16,
    /// Endpoints relative to the origin (Q12.6, 18 bits signed).
    pub a: [i32; 2],
    pub b: [i32; 2],
    /// Inverse-distance vector (18 bits signed, normalised by `sh`).
    pub w: [i32; 2],
    /// Exponent of `w`, in `[SH_MIN, SH_MAX]`: the key of a hit is `dot(d, w)·2^-sh`.
    pub sh: i8,
}

/// A ray's nearest hit: distance key (larger is nearer) and patch id.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Nearest {
    pub key: u32,
    pub id: u16,
}

/// The distance key of a hit from `q = dot(d, w)`: `q·2^-sh`, truncated, clamped into
/// `[1, 2³² − 1]` (a grazing hit whose `q` rounds to zero or below is the farthest key; one
/// nearer than 2⁻⁶ units saturates). `|q| < 2^29.5`, so `q << 2` never overflows.
#[inline]
pub fn key(q: i32, sh: i8) -> u32 {
    if q <= 0 {
        return 1;
    }
    let q = q as u32;
    let sh = sh.clamp(SH_MIN as i8, SH_MAX as i8);
    let u = if sh >= 0 {
        q >> sh
    } else if (q >> (32 + sh as i32)) != 0 {
        u32::MAX
    } else {
        q << -sh
    };
    u.max(1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coordinates_round_and_range_check() {
        let q = Quantizer::covering([[10.3, -5.0], [900.0, 7.5]]);
        assert_eq!(q.offset, [10.0, -5.0]);
        assert_eq!(q.coord(|| "x".into(), 0, 10.3).unwrap(), (0.3f64 * 64.0).round() as i32);
        assert!(q.coord(|| "x".into(), 0, 10.0 + WORLD_SPAN).is_err());
        assert!(q.coord(|| "x".into(), 0, 9.99).is_err());
        assert!(matches!(q.coord(|| "x".into(), 0, f64::NAN), Err(FormatError::NotFinite { .. })));
        let e = q.coord(|| "segment 3 endpoint b".into(), 1, 5000.0).unwrap_err().to_string();
        assert!(e.contains("segment 3 endpoint b") && e.contains("5000"), "{e}");
    }

    #[test]
    fn directions_and_products() {
        assert_eq!(direction(|| "d".into(), [1.0, -0.5]).unwrap(), [65536, -32768]);
        assert!(direction(|| "d".into(), [1.5, 0.0]).is_err());
        // Products round toward −∞ and fit 32 bits at the extremes.
        assert_eq!(mul(-1, 1), -1);
        assert_eq!(mul(65536, -131072), -(1 << 29));
        assert_eq!(mul(-131072, -131072), 1 << 30);
        assert_eq!(from_bits(to_bits(-5, 18), 18), -5);
    }

    #[test]
    fn keys_order_as_distances() {
        assert!(key_distance(100) > key_distance(101));
        assert_eq!(key_distance(1 << 26), 1.0);
    }
}
