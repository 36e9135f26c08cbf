//! The backface screener: per-patch screening and setup for the intersection unit.
//!
//! # Purpose
//!
//! For each patch loaded for the current bundle it decides, once, whether any ray of the bundle
//! can hit the patch, and if so computes the values the intersection unit needs to test the
//! patch against a ray in one clock:
//!
//! * **backward** (Def 2.2): both endpoints lie on or behind the source's plane;
//! * **back-facing**: the origin lies behind the patch or on its line (`cross(a, b) ≤ 0`);
//! * **outside the sector**: an endpoint in front of the source lies beyond the sector's first or
//!   last ray by more than [`SECTOR_MARGIN`]; the test is conservative, so it never drops a patch
//!   that some ray of the sector hits;
//! * **near**: the patch's line passes so close to the origin (about 1/8 world unit) that its
//!   inverse-distance vector does not fit 18 bits; no ray can be decided reliably against it.
//!
//! A passing patch leaves with its coordinates relative to the origin and its inverse-distance
//! vector `W = n·2^(16+sh)/K`, normalised by the exponent `sh` (see `FORMATS.md`).
//!
//! The bit-true model is [`model::screen`]; the RTL follows it stage by stage.

use crate::formats::{cross, dot, SECTOR_MARGIN, SH_MAX, SH_MIN};

/// The bit-true model of the screener: plain integer functions.
pub mod model {
    use super::*;

    /// The bundle the screener works for (all Q-formats of `FORMATS.md`).
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
    pub struct BundleSetup {
        /// Ray origin, world coordinates (Q11.6, unsigned 17 bits).
        pub origin: [i32; 2],
        /// Unit normal of the source (Q2.16).
        pub normal: [i32; 2],
        /// Direction of the sector's first ray (Q2.16).
        pub first: [i32; 2],
        /// Direction of the sector's last ray (Q2.16).
        pub last: [i32; 2],
    }

    /// A patch as loaded from host memory: id and endpoints in world coordinates (Q11.6).
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
    pub struct Patch {
        pub id: u16,
        pub a: [i32; 2],
        pub b: [i32; 2],
    }

    /// What the intersection unit needs of a patch.
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

    /// The screener's decision on one patch.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub enum Verdict {
        Pass(PatchSetup),
        Backward,
        BackFacing,
        OutsideSector,
        Near,
    }

    /// Screens one patch for a bundle.
    pub fn screen(bundle: &BundleSetup, patch: &Patch) -> Verdict {
        let o = bundle.origin;
        let a = [patch.a[0] - o[0], patch.a[1] - o[1]];
        let b = [patch.b[0] - o[0], patch.b[1] - o[1]];
        let ha = dot(bundle.normal, a);
        let hb = dot(bundle.normal, b);
        if ha <= 0 && hb <= 0 {
            return Verdict::Backward;
        }
        // cross(a, b) = twice the area of (O, A, B): positive when O is on the front side. The
        // coordinates are 18-bit, so the difference of the truncated products fits 32 bits.
        let k = cross(a, b);
        if k <= 0 {
            return Verdict::BackFacing;
        }
        if (hb > 0 && (cross(bundle.first, b) as i64) < -SECTOR_MARGIN)
            || (ha > 0 && (cross(bundle.last, a) as i64) > SECTOR_MARGIN)
        {
            return Verdict::OutsideSector;
        }
        let n = [b[1] - a[1], a[0] - b[0]];
        let nmax = n[0].unsigned_abs().max(n[1].unsigned_abs()) as u64;
        // |W| < 2^17 needs nmax·2^sh < 2K: scaled by 2^-SH_MIN to stay in integers.
        let k2 = (2 * k as u64) << -SH_MIN;
        if nmax >= k2 {
            return Verdict::Near;
        }
        // The largest exponent with nmax·2^sh < 2K.
        let mut e = 0u32; // sh − SH_MIN
        while e < (SH_MAX - SH_MIN) as u32 && (nmax << (e + 1)) < k2 {
            e += 1;
        }
        let sh = e as i32 + SH_MIN;
        let w = n.map(|c| {
            // floor(|n|·2^(16+sh) / K), exactly.
            let q = ((c.unsigned_abs() as u128) << (16 + sh) as u32) / k as u128;
            debug_assert!(q < 1 << 17);
            if c < 0 {
                -(q as i32)
            } else {
                q as i32
            }
        });
        Verdict::Pass(PatchSetup { id: patch.id, a, b, w, sh: sh as i8 })
    }
}
