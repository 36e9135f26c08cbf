//! The intersection unit (bit-true model; the RTL block follows in this file).

use crate::formats::{cross, dot};
use crate::screener::model::PatchSetup;

/// The bit-true model of the intersection unit.
pub mod model {
    use super::*;

    /// A ray's nearest hit: distance key (larger is nearer) and patch id.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub struct Nearest {
        pub key: u32,
        pub id: u16,
    }

    /// Tests one ray (direction `d`, Q2.16) against a set-up patch: the distance key of the hit,
    /// or `None`. The ray hits when `a` lies on its right or on it and `b` on its left or on it;
    /// the key is `dot(d, w)·2^-sh` ([`key`]).
    #[inline]
    pub fn test(p: &PatchSetup, d: [i32; 2]) -> Option<u32> {
        let sa = cross(d, p.a);
        let sb = cross(d, p.b);
        if sa > 0 || sb < 0 {
            return None;
        }
        Some(key(dot(d, p.w), p.sh))
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
        let u = if sh >= 0 {
            q >> sh
        } else if (q >> (32 + sh as i32)) != 0 {
            u32::MAX
        } else {
            q << -sh
        };
        u.max(1)
    }

    /// `true` when a hit with `key` on patch `id` replaces `old`: a larger key (nearer), or an
    /// equal key and a lower id.
    #[inline]
    pub fn replaces(key: u32, id: u16, old: Option<Nearest>) -> bool {
        match old {
            None => true,
            Some(o) => key > o.key || (key == o.key && id < o.id),
        }
    }
}
