//! Geometry of the golden model: segments (2D patches), rays, and the one hit definition every
//! tracer shares.
//!
//! # The hit definition
//!
//! Patches are one-sided. A segment `a→b` has its front side to the left (normal = `(b−a)`
//! rotated +90°). A ray from `O` with direction `d` hits a segment when
//!
//! 1. the segment is not *backward* for the source (Def 2.2: both endpoints lie in the closed
//!    half-plane behind the source's plane, `(p−O)·n ≤ 0`), which no hemisphere ray can reach;
//! 2. `O` lies strictly on the segment's front side (`orient(a, b, O) > 0`);
//! 3. the ray's line separates the endpoints with `a` on the right or on the line and `b` on the
//!    left or on the line (`orient(O, P, a) ≤ 0 ≤ orient(O, P, b)` with `P = O + d`).
//!
//! Given (2), condition (3) holds exactly when the ray meets the closed segment at a distance
//! `t > 0`, arriving from the front; a ray parallel to the segment fails it (both orientations
//! are equal and non-zero). The orientations are evaluated with exact adaptive predicates, so the
//! yes/no answer is exact for the ray `O → P` as represented in `f64`: a ray through an endpoint
//! hits, a ray that misses by one ulp misses, whichever tracer asks.
//!
//! The distance `t` is computed in `f64` as `cross(a−O, e) / cross(d, e)` and clamped into the
//! interval spanned by the projections of the two endpoints, so it always names a point of the
//! segment. Nearest hit wins; an exact tie of the computed `t` goes to the lower segment index
//! ([`closer`]). Because every tracer calls [`hit`] with the same arguments, they all compute
//! bit-identical `t` values, and the tie rule is applied to identical numbers.

use glam::DVec2;

/// A 2D point or vector in world units.
pub type Vec2 = DVec2;

/// Rotates a vector by +90° (counter-clockwise).
#[inline]
pub fn perp(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

/// The 2D cross product `u × v` (the z component of the 3D cross product).
#[inline]
pub fn cross(u: Vec2, v: Vec2) -> f64 {
    u.x * v.y - u.y * v.x
}

/// Exact orientation of `c` against the directed line `a → b`: positive when `c` lies to the
/// left, negative to the right, zero when collinear (Shewchuk's adaptive predicate).
#[inline]
pub fn orient(a: Vec2, b: Vec2, c: Vec2) -> f64 {
    robust::orient2d(
        robust::Coord { x: a.x, y: a.y },
        robust::Coord { x: b.x, y: b.y },
        robust::Coord { x: c.x, y: c.y },
    )
}

/// The error-bound factor of [`orient_filter`] (`robust`'s `CCWERRBOUND_A`).
const THETA: f64 = 3.3306690621773722e-16;

/// The first stage of [`orient`]`(a, b, c)` (Shewchuk's predicate as the `robust` crate
/// implements it), given the differences `a − c` and `b − c` it starts from: the floating-point
/// determinant, and whether its error bound proves its sign, in which case it is exactly what
/// [`orient`] returns.
#[inline(always)]
fn orient_filter(ac: Vec2, bc: Vec2) -> (f64, bool) {
    let detleft = ac.x * bc.y;
    let detright = ac.y * bc.x;
    let det = detleft - detright;
    let errbound = THETA * (detleft + detright).abs();
    (det, det >= errbound || -det >= errbound)
}

/// A one-sided patch of the 2D world: the segment `a → b`, front side on its left.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    pub a: Vec2,
    pub b: Vec2,
}

impl Segment {
    pub fn new(a: Vec2, b: Vec2) -> Self {
        Segment { a, b }
    }

    /// The unit normal, pointing to the front side: `(b − a)` rotated +90°, normalised.
    pub fn normal(&self) -> Vec2 {
        perp(self.b - self.a).normalize()
    }

    pub fn midpoint(&self) -> Vec2 {
        (self.a + self.b) * 0.5
    }

    pub fn length(&self) -> f64 {
        (self.b - self.a).length()
    }

    /// Smallest distance from `p` to a point of the closed segment.
    pub fn distance_to(&self, p: Vec2) -> f64 {
        let e = self.b - self.a;
        let len2 = e.length_squared();
        let s = if len2 > 0.0 { ((p - self.a).dot(e) / len2).clamp(0.0, 1.0) } else { 0.0 };
        (self.a + e * s - p).length()
    }
}

/// A ray of a bundle: origin, direction (unit length up to rounding) and the probe point
/// `origin + dir` that, with the origin, defines the ray exactly for the orientation predicates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    pub origin: Vec2,
    pub dir: Vec2,
    pub probe: Vec2,
}

impl Ray {
    pub fn new(origin: Vec2, dir: Vec2) -> Self {
        Ray { origin, dir, probe: origin + dir }
    }

    /// The point at distance `t` along the ray.
    pub fn at(&self, t: f64) -> Vec2 {
        self.origin + self.dir * t
    }
}

/// Why a patch cannot be hit by any ray of a source (or that it can).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Facing {
    /// May be hit by rays of the hemisphere.
    Front,
    /// Wholly behind the source's plane (Def 2.2).
    Backward,
    /// The source lies behind the patch or on its line: every ray meets it from behind.
    BackFacing,
}

/// Classifies a patch against a source at `origin` with unit `normal`: the per-patch part of the
/// hit definition, which the backface screener evaluates once per patch.
#[inline]
pub fn facing(origin: Vec2, normal: Vec2, seg: &Segment) -> Facing {
    if (seg.a - origin).dot(normal) <= 0.0 && (seg.b - origin).dot(normal) <= 0.0 {
        Facing::Backward
    } else if orient(seg.a, seg.b, origin) <= 0.0 {
        Facing::BackFacing
    } else {
        Facing::Front
    }
}

/// The per-ray part of the hit definition, for a patch already known to be [`Facing::Front`]:
/// returns the distance `t > 0` at which the ray meets the segment, or `None`.
#[inline(always)]
pub fn hit_front(ray: &Ray, seg: &Segment) -> Option<f64> {
    FrontPatch::new(ray.origin, seg).hit(ray)
}

/// [`hit_front`] for one patch and many rays from one origin: what depends only on the origin
/// and the patch is computed once. [`FrontPatch::hit`] performs exactly the operations of
/// [`hit_front`] on exactly the same operands (`hit_front` is built from it), so its answers are
/// bit-identical.
#[derive(Clone, Copy, Debug)]
pub struct FrontPatch {
    /// The rays' common origin `O`.
    origin: Vec2,
    seg: Segment,
    /// `O − a` and `O − b`: the first operands of the orientation filter's products.
    oa: Vec2,
    ob: Vec2,
    /// `e = b − a`, `w = a − O`, `b − O`, and `cross(w, e)` (the numerator of `t`).
    e: Vec2,
    w: Vec2,
    wb: Vec2,
    num: f64,
}

impl FrontPatch {
    #[inline(always)]
    pub fn new(origin: Vec2, seg: &Segment) -> FrontPatch {
        let e = seg.b - seg.a;
        let w = seg.a - origin;
        FrontPatch {
            origin,
            seg: *seg,
            oa: origin - seg.a,
            ob: origin - seg.b,
            e,
            w,
            wb: seg.b - origin,
            num: cross(w, e),
        }
    }

    /// The rays' origin this patch was prepared for.
    #[inline(always)]
    pub fn origin(&self) -> Vec2 {
        self.origin
    }

    /// [`hit_front`] of `ray`, whose origin must be [`FrontPatch::origin`] (bit for bit).
    #[inline(always)]
    pub fn hit(&self, ray: &Ray) -> Option<f64> {
        debug_assert!(
            ray.origin.x.to_bits() == self.origin.x.to_bits()
                && ray.origin.y.to_bits() == self.origin.y.to_bits()
        );
        // The ray's line must have `a` on its right (or on it) and `b` on its left (or on it).
        // Both orientations go through the floating-point filter of `orient` first, side by
        // side; only when either is too close to call does the exact predicate decide.
        let p = ray.probe;
        let (da, certain_a) = orient_filter(self.oa, p - self.seg.a);
        let (db, certain_b) = orient_filter(self.ob, p - self.seg.b);
        let miss = if certain_a & certain_b {
            (da > 0.0) | (db < 0.0)
        } else {
            misses_exactly(self.origin, p, &self.seg)
        };
        if miss {
            return None;
        }
        let t = self.num / cross(ray.dir, self.e);
        Some(settle(t, self.w.dot(ray.dir), self.wb.dot(ray.dir)))
    }

    /// The hits of the rays `rays[base + k]`, one for each set bit `k` of `word`, in increasing
    /// order: `found(i, t)` for each ray `i` that hits. A ray with this patch's origin (bit for
    /// bit) is answered as by [`FrontPatch::hit`], any other as by [`hit_front`]. On x86-64 the
    /// rays go through SSE2 two at a time, each lane performing the operations of `hit` on the
    /// same operands (IEEE arithmetic rounds lane by lane as it does a scalar), so the answers
    /// are the same bits.
    #[inline(always)]
    pub fn hit_rays(&self, rays: &[Ray], base: usize, word: u64, found: impl FnMut(usize, f64)) {
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
        {
            self.hit_rays_sse2(rays, base, word, found)
        }
        #[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
        {
            let (mut word, mut found) = (word, found);
            while word != 0 {
                let i = base + word.trailing_zeros() as usize;
                word &= word - 1;
                if let Some(t) = self.hit_any(&rays[i]) {
                    found(i, t);
                }
            }
        }
    }

    /// [`FrontPatch::hit`] of `ray` if it has this patch's origin, else [`hit_front`].
    #[inline(always)]
    fn hit_any(&self, ray: &Ray) -> Option<f64> {
        let o = self.origin;
        if ray.origin.x.to_bits() == o.x.to_bits() && ray.origin.y.to_bits() == o.y.to_bits() {
            self.hit(ray)
        } else {
            hit_front(ray, &self.seg)
        }
    }

    /// The SSE2 body of [`FrontPatch::hit_rays`]: two rays per step, lane 0 and lane 1 (an odd
    /// last ray fills both). A pair not both from this patch's origin, and a lane that the
    /// filter cannot decide or whose quotient or projections are NaN, take
    /// [`FrontPatch::hit_any`]. In the other lanes the clamp of [`settle`] is
    /// `max(min(max(t, lo), hi), MIN_POSITIVE)` of SSE2's `max` and `min`: the same value for
    /// operands that are not NaN but for the sign of a zero, which the final `max` turns into
    /// `MIN_POSITIVE` either way.
    ///
    /// It is inlined into its callers (so a caller compiled for newer instructions, such as the
    /// shelling tracers' x86-64-v3 copy, encodes it with them).
    #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
    #[inline(always)]
    fn hit_rays_sse2(&self, rays: &[Ray], base: usize, mut word: u64, mut found: impl FnMut(usize, f64)) {
        // SAFETY: the build targets SSE2 (the `cfg`), so every CPU it runs on has it.
        unsafe {
            use sse2::*;
            use std::arch::x86_64::*;
            let (ax, ay, bx, by) =
                (splat(self.seg.a.x), splat(self.seg.a.y), splat(self.seg.b.x), splat(self.seg.b.y));
            let (oax, oay, obx, oby) =
                (splat(self.oa.x), splat(self.oa.y), splat(self.ob.x), splat(self.ob.y));
            let (ex, ey, num) = (splat(self.e.x), splat(self.e.y), splat(self.num));
            let (wx, wy, wbx, wby) = (splat(self.w.x), splat(self.w.y), splat(self.wb.x), splat(self.wb.y));
            let (zero, tiny) = (_mm_setzero_pd(), splat(f64::MIN_POSITIVE));
            let origin = _mm_castpd_si128(vec(self.origin));
            while word != 0 {
                let i = base + word.trailing_zeros() as usize;
                word &= word - 1;
                let j = if word != 0 { base + word.trailing_zeros() as usize } else { i };
                word &= word.wrapping_sub(1);
                let (ri, rj) = (&rays[i], &rays[j]);
                let same = _mm_and_si128(
                    _mm_cmpeq_epi32(_mm_castpd_si128(vec(ri.origin)), origin),
                    _mm_cmpeq_epi32(_mm_castpd_si128(vec(rj.origin)), origin),
                );
                if _mm_movemask_epi8(same) != 0xffff {
                    if let Some(t) = self.hit_any(ri) {
                        found(i, t);
                    }
                    if j != i {
                        if let Some(t) = self.hit_any(rj) {
                            found(j, t);
                        }
                    }
                    continue;
                }
                let (p0, p1) = (vec(ri.probe), vec(rj.probe));
                let (px, py) = (_mm_unpacklo_pd(p0, p1), _mm_unpackhi_pd(p0, p1));
                let (da, certain_a) = filter(oax, oay, _mm_sub_pd(px, ax), _mm_sub_pd(py, ay));
                let (db, certain_b) = filter(obx, oby, _mm_sub_pd(px, bx), _mm_sub_pd(py, by));
                let certain = _mm_movemask_pd(_mm_and_pd(certain_a, certain_b));
                let miss = _mm_movemask_pd(_mm_or_pd(_mm_cmpgt_pd(da, zero), _mm_cmplt_pd(db, zero)));
                // `num / cross(d, e)`, `w · d` and `wb · d` in both lanes, then `settle`.
                let (d0, d1) = (vec(ri.dir), vec(rj.dir));
                let (dx, dy) = (_mm_unpacklo_pd(d0, d1), _mm_unpackhi_pd(d0, d1));
                let t = _mm_div_pd(num, _mm_sub_pd(_mm_mul_pd(dx, ey), _mm_mul_pd(dy, ex)));
                let ta = _mm_add_pd(_mm_mul_pd(wx, dx), _mm_mul_pd(wy, dy));
                let tb = _mm_add_pd(_mm_mul_pd(wbx, dx), _mm_mul_pd(wby, dy));
                let tame = _mm_movemask_pd(_mm_and_pd(_mm_cmpord_pd(ta, tb), _mm_cmpord_pd(t, t)));
                let x = _mm_max_pd(_mm_min_pd(_mm_max_pd(t, _mm_min_pd(ta, tb)), _mm_max_pd(ta, tb)), tiny);
                // Lanes the vector answer does not settle: undecided, or a hit with a NaN about.
                let slow = !certain | (!miss & !tame);
                let fast_hit = !slow & !miss;
                if slow & 1 != 0 {
                    if let Some(t) = self.hit_any(ri) {
                        found(i, t);
                    }
                } else if fast_hit & 1 != 0 {
                    found(i, _mm_cvtsd_f64(x));
                }
                if j != i {
                    if slow & 2 != 0 {
                        if let Some(t) = self.hit_any(rj) {
                            found(j, t);
                        }
                    } else if fast_hit & 2 != 0 {
                        found(j, _mm_cvtsd_f64(_mm_unpackhi_pd(x, x)));
                    }
                }
            }
        }
    }
}

/// Helpers of [`FrontPatch::hit_rays`] on x86-64. They use SSE2 intrinsics, so they may only
/// be called where SSE2 is known to be present (the `cfg` of this module).
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
mod sse2 {
    use super::{Vec2, THETA};
    use std::arch::x86_64::*;

    #[inline(always)]
    pub(super) unsafe fn splat(v: f64) -> __m128d {
        _mm_set1_pd(v)
    }

    /// `[v.x, v.y]`.
    #[inline(always)]
    pub(super) unsafe fn vec(v: Vec2) -> __m128d {
        _mm_set_pd(v.y, v.x)
    }

    /// `orient_filter(ac, bc)` in both lanes: the determinant and whether it is certain.
    #[inline(always)]
    pub(super) unsafe fn filter(
        acx: __m128d,
        acy: __m128d,
        bcx: __m128d,
        bcy: __m128d,
    ) -> (__m128d, __m128d) {
        let sign = _mm_set1_pd(-0.0);
        let detleft = _mm_mul_pd(acx, bcy);
        let detright = _mm_mul_pd(acy, bcx);
        let det = _mm_sub_pd(detleft, detright);
        let errbound = _mm_mul_pd(_mm_set1_pd(THETA), _mm_andnot_pd(sign, _mm_add_pd(detleft, detright)));
        let certain = _mm_or_pd(_mm_cmpge_pd(det, errbound), _mm_cmpge_pd(_mm_xor_pd(det, sign), errbound));
        (det, certain)
    }
}

/// The end of [`FrontPatch::hit`] for a ray that hits: the quotient `t` clamped into the
/// interval spanned by the endpoints' projections `ta` and `tb` (their lower end if `t` is NaN),
/// so that it names a point of the segment even when the ray grazes it and the quotient is
/// ill-conditioned; then kept strictly positive (a hit is at `t > 0` by the predicates).
#[inline(always)]
fn settle(t: f64, ta: f64, tb: f64) -> f64 {
    let (lo, hi) = if ta <= tb { (ta, tb) } else { (tb, ta) };
    let t = if t.is_nan() { lo } else { t.clamp(lo, hi) };
    t.max(f64::MIN_POSITIVE)
}

/// The orientation test of [`hit_front`] by the exact predicate, for when the filter cannot
/// decide it (rare, so kept out of line).
#[cold]
#[inline(never)]
fn misses_exactly(o: Vec2, p: Vec2, seg: &Segment) -> bool {
    orient(o, p, seg.a) > 0.0 || orient(o, p, seg.b) < 0.0
}

/// The complete hit definition for one ray of a source with unit `normal`.
#[inline]
pub fn hit(ray: &Ray, normal: Vec2, seg: &Segment) -> Option<f64> {
    match facing(ray.origin, normal, seg) {
        Facing::Front => hit_front(ray, seg),
        _ => None,
    }
}

/// A ray's nearest hit so far: distance and segment index.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    pub t: f64,
    pub segment: u32,
}

/// `true` when hit `a` beats hit `b`: smaller distance, and on an exact tie the lower index.
#[inline]
pub fn closer(a: Hit, b: Option<Hit>) -> bool {
    match b {
        None => true,
        Some(b) => a.t < b.t || (a.t == b.t && a.segment < b.segment),
    }
}

/// The polar angle of `p` seen from a source at `origin` with unit `normal`: the signed angle
/// from the normal, positive towards `perp(normal)`. Points in front of the source have angles
/// in (−π/2, π/2).
#[inline]
pub fn angle_of(origin: Vec2, normal: Vec2, p: Vec2) -> f64 {
    let v = p - origin;
    v.dot(perp(normal)).atan2(v.dot(normal))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> Vec2 {
        Vec2::new(x, y)
    }

    #[test]
    fn front_hit_back_pass_parallel_miss() {
        let n = v(1.0, 0.0);
        let ray = Ray::new(v(0.0, 0.0), v(1.0, 0.0));
        // Front faces the origin: a below, b above, normal points to -x.
        let front = Segment::new(v(2.0, -1.0), v(2.0, 1.0));
        assert_eq!(front.normal(), v(-1.0, 0.0));
        assert_eq!(hit(&ray, n, &front), Some(2.0));
        // Same segment reversed: seen from behind, passes through.
        let back = Segment::new(v(2.0, 1.0), v(2.0, -1.0));
        assert_eq!(hit(&ray, n, &back), None);
        // Parallel segment on the ray's line: no hit.
        let along = Segment::new(v(3.0, 0.0), v(5.0, 0.0));
        assert_eq!(hit(&ray, n, &along), None);
    }

    #[test]
    fn endpoints_are_inclusive() {
        let n = v(1.0, 0.0);
        let ray = Ray::new(v(0.0, 0.0), v(1.0, 0.0));
        let through_a = Segment::new(v(2.0, 0.0), v(2.0, 1.0));
        let through_b = Segment::new(v(2.0, -1.0), v(2.0, 0.0));
        assert_eq!(hit(&ray, n, &through_a), Some(2.0));
        assert_eq!(hit(&ray, n, &through_b), Some(2.0));
    }

    #[test]
    fn behind_origin_and_backward_patches_are_not_hit() {
        let n = v(1.0, 0.0);
        let ray = Ray::new(v(0.0, 0.0), v(1.0, 0.0));
        let behind = Segment::new(v(-2.0, -1.0), v(-2.0, 1.0));
        assert_eq!(facing(ray.origin, n, &behind), Facing::Backward);
        assert_eq!(hit(&ray, n, &behind), None);
        // Through the origin: the origin is on its line, so it is back-facing.
        let through = Segment::new(v(0.0, -1.0), v(0.0, 1.0));
        assert_eq!(hit(&ray, n, &through), None);
    }

    #[test]
    fn ties_go_to_the_lower_index() {
        let a = Hit { t: 1.0, segment: 3 };
        let b = Hit { t: 1.0, segment: 5 };
        assert!(closer(a, Some(b)));
        assert!(!closer(b, Some(a)));
        assert!(closer(b, None));
    }
}
