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
    // [`FrontPatch::hit`]'s operations on the same operands, with the distance's operands
    // computed only for a ray that meets the segment (most tested rays miss).
    let (o, p) = (ray.origin, ray.probe);
    let (da, certain_a) = orient_filter(o - seg.a, p - seg.a);
    let (db, certain_b) = orient_filter(o - seg.b, p - seg.b);
    let miss = if certain_a & certain_b { (da > 0.0) | (db < 0.0) } else { misses_exactly(o, p, seg) };
    if miss {
        return None;
    }
    let (e, w) = (seg.b - seg.a, seg.a - o);
    let t = cross(w, e) / cross(ray.dir, e);
    Some(settle(t, w.dot(ray.dir), (seg.b - o).dot(ray.dir)))
}

/// Four front-facing patches, their endpoints' coordinates lane by lane, for a cheap first
/// verdict of [`hit_front`] on one ray against all four ([`FrontQuad::certain_misses`]).
#[derive(Clone, Copy, Debug, Default)]
#[repr(C, align(32))]
pub struct FrontQuad {
    ax: [f64; 4],
    ay: [f64; 4],
    bx: [f64; 4],
    by: [f64; 4],
}

impl FrontQuad {
    /// Puts `seg` in lane `k` (0 to 3).
    #[inline]
    pub fn set(&mut self, k: usize, seg: &Segment) {
        (self.ax[k], self.ay[k], self.bx[k], self.by[k]) = (seg.a.x, seg.a.y, seg.b.x, seg.b.y);
    }

    /// Bit `k` set when [`hit_front`] of `ray` and lane `k`'s patch returns `None` by its
    /// floating-point filter alone (both orientations certain, and the ray's line misses): the
    /// same operations on the same operands as `hit_front`, four lanes at a time with AVX where
    /// the CPU has it, so a set bit is exactly `hit_front`'s verdict and a clear bit leaves the
    /// lane to `hit_front` itself. The bits of lanes never [`set`](FrontQuad::set) mean nothing.
    #[inline]
    pub fn certain_misses(&self, ray: &Ray) -> u32 {
        #[cfg(target_arch = "x86_64")]
        if std::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX and AVX2 (checked just above).
            return unsafe { self.certain_misses_avx(ray) };
        }
        let (o, p) = (ray.origin, ray.probe);
        (0..4).fold(0, |bits, k| {
            let (a, b) = (Vec2::new(self.ax[k], self.ay[k]), Vec2::new(self.bx[k], self.by[k]));
            let (da, certain_a) = orient_filter(o - a, p - a);
            let (db, certain_b) = orient_filter(o - b, p - b);
            bits | ((certain_a & certain_b & ((da > 0.0) | (db < 0.0))) as u32) << k
        })
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx,avx2")]
    fn certain_misses_avx(&self, ray: &Ray) -> u32 {
        use std::arch::x86_64::*;
        // SAFETY: the arrays are 4 f64 each, aligned to 32 bytes by the struct's layout.
        let (ax, ay, bx, by) = unsafe {
            (
                _mm256_load_pd(self.ax.as_ptr()),
                _mm256_load_pd(self.ay.as_ptr()),
                _mm256_load_pd(self.bx.as_ptr()),
                _mm256_load_pd(self.by.as_ptr()),
            )
        };
        let (ox, oy) = (_mm256_set1_pd(ray.origin.x), _mm256_set1_pd(ray.origin.y));
        let (px, py) = (_mm256_set1_pd(ray.probe.x), _mm256_set1_pd(ray.probe.y));
        let (da, certain_a) = avx2::filter(
            _mm256_sub_pd(ox, ax),
            _mm256_sub_pd(oy, ay),
            _mm256_sub_pd(px, ax),
            _mm256_sub_pd(py, ay),
        );
        let (db, certain_b) = avx2::filter(
            _mm256_sub_pd(ox, bx),
            _mm256_sub_pd(oy, by),
            _mm256_sub_pd(px, bx),
            _mm256_sub_pd(py, by),
        );
        let zero = _mm256_setzero_pd();
        let misses =
            _mm256_or_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(da, zero), _mm256_cmp_pd::<_CMP_LT_OQ>(db, zero));
        _mm256_movemask_pd(_mm256_and_pd(_mm256_and_pd(certain_a, certain_b), misses)) as u32
    }
}

/// [`hit_front`] for one patch and many rays from one origin: what depends only on the origin
/// and the patch is computed once. [`FrontPatch::hit`] performs exactly the operations of
/// [`hit_front`] on exactly the same operands, so its answers are
/// bit-identical (a test holds them to it).
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

    /// [`FrontPatch::hit_rays`] with each hit `t` offered to `nearest` as [`NearestHits::offer`]
    /// offers `Hit { t, segment: p }`; returns the rays that hit, as bits over `base` like
    /// `word`. On x86-64 CPUs with AVX2 four rays go at a time, their offers made in the vector
    /// lanes as well (`offer_rays_avx2`); elsewhere it is `hit_rays` and `offer`.
    #[inline(always)]
    pub fn offer_rays(&self, rays: &[Ray], p: u32, base: usize, word: u64, nearest: &mut NearestHits) -> u64 {
        #[cfg(target_arch = "x86_64")]
        if std::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2 (just checked), and so AVX.
            return unsafe { self.offer_rays_avx2(rays, p, base, word, nearest) };
        }
        let mut hits = 0;
        self.hit_rays(rays, base, word, nearest.offering(p, base, &mut hits));
        hits
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

impl FrontPatch {
    /// The AVX2 body of [`FrontPatch::offer_rays`]: the rays go a block of four at a time, ray
    /// `base + k + j` in lane `j` (`k` a multiple of 4), and each lane performs the operations
    /// of [`FrontPatch::hit_rays_sse2`] on the same operands: AVX's arithmetic, comparisons,
    /// `min` and `max` answer lane by lane exactly as SSE2's do (the predicates are the ones
    /// SSE2's comparisons encode), and nothing is fused (FMA is not enabled), so the distances
    /// are the same bits. Lanes the SSE2 body hands to [`FrontPatch::hit_any`] go there too
    /// (all of a block whose rays do not all have this patch's origin). The other lanes that hit
    /// are offered in the vector: a lane takes `(t, p)` where `t` is below its key, or equal to
    /// it and `p` below its patch index (no hit holds `+∞` and [`NearestHits::NONE`], which every
    /// key that is not NaN beats, and these are not NaN), as [`NearestHits::offer`] decides.
    ///
    /// Where the caller is compiled for these instructions (the shelling tracers' x86-64-v3
    /// copy) it may be inlined into it.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx,avx2")]
    #[inline]
    fn offer_rays_avx2(
        &self,
        rays: &[Ray],
        p: u32,
        base: usize,
        mut word: u64,
        nearest: &mut NearestHits,
    ) -> u64 {
        use avx2::*;
        use std::arch::x86_64::*;
        let splat = _mm256_set1_pd;
        let (ax, ay, bx, by) =
            (splat(self.seg.a.x), splat(self.seg.a.y), splat(self.seg.b.x), splat(self.seg.b.y));
        let (oax, oay, obx, oby) = (splat(self.oa.x), splat(self.oa.y), splat(self.ob.x), splat(self.ob.y));
        let (ex, ey, num) = (splat(self.e.x), splat(self.e.y), splat(self.num));
        let (wx, wy, wbx, wby) = (splat(self.w.x), splat(self.w.y), splat(self.wb.x), splat(self.wb.y));
        let (zero, tiny) = (_mm256_setzero_pd(), splat(f64::MIN_POSITIVE));
        let origin = _mm256_castpd_si256(pair(self.origin, self.origin));
        // The patch index, and with its top bit flipped for unsigned comparisons.
        let (pv, flip) = (_mm_set1_epi32(p as i32), _mm_set1_epi32(i32::MIN));
        let pv_signed = _mm_xor_si128(pv, flip);
        let lane_bits = _mm256_setr_epi64x(1, 2, 4, 8);
        let mut hits = 0u64;
        while word != 0 {
            // The next block with a ray to test; `valid` marks its rays to test. Past the end of
            // `rays` the last ray fills the lanes.
            let k = word.trailing_zeros() as usize & !3;
            let valid = (word >> k) as u32 & 15;
            word &= !(15u64 << k);
            let i = base + k;
            let r = match rays.get(i..i + 4) {
                Some(b) => [&b[0], &b[1], &b[2], &b[3]],
                None => {
                    let at = |j: usize| &rays[(i + j).min(rays.len() - 1)];
                    [at(0), at(1), at(2), at(3)]
                }
            };
            let same = _mm256_and_si256(
                _mm256_cmpeq_epi64(_mm256_castpd_si256(pair(r[0].origin, r[2].origin)), origin),
                _mm256_cmpeq_epi64(_mm256_castpd_si256(pair(r[1].origin, r[3].origin)), origin),
            );
            let slow = if _mm256_movemask_epi8(same) != -1 {
                valid
            } else {
                let (px, py) = lanes(r[0].probe, r[1].probe, r[2].probe, r[3].probe);
                let (da, certain_a) = filter(oax, oay, _mm256_sub_pd(px, ax), _mm256_sub_pd(py, ay));
                let (db, certain_b) = filter(obx, oby, _mm256_sub_pd(px, bx), _mm256_sub_pd(py, by));
                let certain = _mm256_and_pd(certain_a, certain_b);
                let miss = _mm256_or_pd(
                    _mm256_cmp_pd::<_CMP_GT_OS>(da, zero),
                    _mm256_cmp_pd::<_CMP_LT_OS>(db, zero),
                );
                // `num / cross(d, e)`, `w · d` and `wb · d` in every lane, then `settle`.
                let (dx, dy) = lanes(r[0].dir, r[1].dir, r[2].dir, r[3].dir);
                let t = _mm256_div_pd(num, _mm256_sub_pd(_mm256_mul_pd(dx, ey), _mm256_mul_pd(dy, ex)));
                let ta = _mm256_add_pd(_mm256_mul_pd(wx, dx), _mm256_mul_pd(wy, dy));
                let tb = _mm256_add_pd(_mm256_mul_pd(wbx, dx), _mm256_mul_pd(wby, dy));
                let tame =
                    _mm256_and_pd(_mm256_cmp_pd::<_CMP_ORD_Q>(ta, tb), _mm256_cmp_pd::<_CMP_ORD_Q>(t, t));
                let x = _mm256_max_pd(
                    _mm256_min_pd(_mm256_max_pd(t, _mm256_min_pd(ta, tb)), _mm256_max_pd(ta, tb)),
                    tiny,
                );
                // Lanes the vector answer does not settle: undecided, or a hit with a NaN about.
                let (certain, miss, tame) = (
                    _mm256_movemask_pd(certain) as u32,
                    _mm256_movemask_pd(miss) as u32,
                    _mm256_movemask_pd(tame) as u32,
                );
                let slow = (!certain | (!miss & !tame)) & valid;
                let fast_hit = !slow & !miss & valid;
                if fast_hit != 0 {
                    let bits = _mm256_set1_epi64x(fast_hit as i64);
                    let fast = _mm256_cmpeq_epi64(_mm256_and_si256(bits, lane_bits), lane_bits);
                    let (keys, patches) = nearest.block(i);
                    // SAFETY: `keys` holds four `f64` and `patches` four `u32` (16 bytes);
                    // unaligned loads and stores.
                    unsafe {
                        let old_t = _mm256_loadu_pd(keys.as_ptr());
                        let old_p = _mm_loadu_si128(patches.as_ptr().cast());
                        // `p < old_p` (unsigned), widened to the 64-bit lanes.
                        let lower =
                            _mm256_cvtepi32_epi64(_mm_cmpgt_epi32(_mm_xor_si128(old_p, flip), pv_signed));
                        let closer = _mm256_or_pd(
                            _mm256_cmp_pd::<_CMP_LT_OQ>(x, old_t),
                            _mm256_and_pd(_mm256_cmp_pd::<_CMP_EQ_OQ>(x, old_t), _mm256_castsi256_pd(lower)),
                        );
                        let take = _mm256_and_pd(closer, _mm256_castsi256_pd(fast));
                        _mm256_storeu_pd(keys.as_mut_ptr(), _mm256_blendv_pd(old_t, x, take));
                        // The low halves of the 64-bit lanes of `take`, as 32-bit lanes.
                        let take32 = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(
                            _mm256_castpd_si256(take),
                            _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7),
                        ));
                        _mm_storeu_si128(patches.as_mut_ptr().cast(), _mm_blendv_epi8(old_p, pv, take32));
                    }
                    hits |= (fast_hit as u64) << k;
                }
                slow
            };
            let mut m = slow;
            while m != 0 {
                let j = m.trailing_zeros() as usize;
                m &= m - 1;
                if let Some(t) = self.hit_any(r[j]) {
                    nearest.offer(i + j, Hit { t, segment: p });
                    hits |= 1u64 << (k + j);
                }
            }
        }
        hits
    }
}

/// Helpers of [`FrontPatch::offer_rays_avx2`]. They use AVX and AVX2 intrinsics, so they are
/// compiled for them and may only be called where the CPU is known to have them.
#[cfg(target_arch = "x86_64")]
mod avx2 {
    use super::{Vec2, THETA};
    use std::arch::x86_64::*;

    /// `[u.x, u.y, v.x, v.y]`.
    #[target_feature(enable = "avx,avx2")]
    #[inline]
    pub(super) fn pair(u: Vec2, v: Vec2) -> __m256d {
        _mm256_setr_pd(u.x, u.y, v.x, v.y)
    }

    /// The x and the y coordinates of four vectors, each in lanes 0 to 3.
    #[target_feature(enable = "avx,avx2")]
    #[inline]
    pub(super) fn lanes(v0: Vec2, v1: Vec2, v2: Vec2, v3: Vec2) -> (__m256d, __m256d) {
        let (a, b) = (pair(v0, v2), pair(v1, v3));
        (_mm256_unpacklo_pd(a, b), _mm256_unpackhi_pd(a, b))
    }

    /// `orient_filter(ac, bc)` in every lane: the determinant and whether it is certain (the
    /// SSE2 helper's operations, with the predicates its comparisons encode).
    #[target_feature(enable = "avx,avx2")]
    #[inline]
    pub(super) fn filter(acx: __m256d, acy: __m256d, bcx: __m256d, bcy: __m256d) -> (__m256d, __m256d) {
        let sign = _mm256_set1_pd(-0.0);
        let detleft = _mm256_mul_pd(acx, bcy);
        let detright = _mm256_mul_pd(acy, bcx);
        let det = _mm256_sub_pd(detleft, detright);
        let errbound =
            _mm256_mul_pd(_mm256_set1_pd(THETA), _mm256_andnot_pd(sign, _mm256_add_pd(detleft, detright)));
        let certain = _mm256_or_pd(
            _mm256_cmp_pd::<_CMP_GE_OS>(det, errbound),
            _mm256_cmp_pd::<_CMP_GE_OS>(_mm256_xor_pd(det, sign), errbound),
        );
        (det, certain)
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

/// The nearest hits of rays `0..n` so far, as the shelling tracers keep them: each ray's
/// distance key and patch index in arrays of their own, so that a hit test can read and offer
/// a block of neighbouring rays at once ([`FrontPatch::offer_rays`]). A ray without a hit holds
/// the key `+∞` and the patch [`NearestHits::NONE`]; patch indices stay below it.
#[derive(Clone, Debug)]
pub struct NearestHits {
    /// `n + 3` entries, so that a block of four from any ray lies inside.
    t: Vec<f64>,
    segment: Vec<u32>,
}

impl NearestHits {
    /// The patch index of a ray without a hit.
    pub const NONE: u32 = u32::MAX;

    /// Rays `0..n`, none hit.
    pub fn new(n: usize) -> Self {
        NearestHits { t: vec![f64::INFINITY; n + 3], segment: vec![Self::NONE; n + 3] }
    }

    /// The nearest hit of ray `i` so far.
    #[inline]
    pub fn get(&self, i: usize) -> Option<Hit> {
        let segment = self.segment[i];
        (segment != Self::NONE).then(|| Hit { t: self.t[i], segment })
    }

    /// Offers hit `h` to ray `i`: it is taken when it is [`closer`] than the ray's hit.
    #[inline(always)]
    pub fn offer(&mut self, i: usize, h: Hit) {
        debug_assert!(h.segment != Self::NONE, "patch indices stay below NearestHits::NONE");
        let (t, segment) = (self.t[i], self.segment[i]);
        // `closer(h, self.get(i))`, without a branch on the data.
        let take = (segment == Self::NONE) | (h.t < t) | ((h.t == t) & (h.segment < segment));
        self.t[i] = if take { h.t } else { t };
        self.segment[i] = if take { h.segment } else { segment };
    }

    /// The `found` of a hit test of patch `p` for rays over `base` (such as
    /// [`FrontPatch::hit_rays`]): each hit is offered, and its ray marked in `hits`, a bit over
    /// `base`.
    #[inline(always)]
    pub fn offering<'a>(&'a mut self, p: u32, base: usize, hits: &'a mut u64) -> impl FnMut(usize, f64) + 'a {
        move |i, t| {
            self.offer(i, Hit { t, segment: p });
            *hits |= 1u64 << (i - base);
        }
    }

    /// The keys and the patch indices of rays `i..i + 4` (past `n`: entries no ray holds).
    #[inline(always)]
    fn block(&mut self, i: usize) -> (&mut [f64], &mut [u32]) {
        (&mut self.t[i..i + 4], &mut self.segment[i..i + 4])
    }

    /// The key of ray `i`'s nearest hit so far (`+∞` without one).
    #[inline]
    pub fn key(&self, i: usize) -> f64 {
        self.t[i]
    }

    /// The nearest hit of every ray, by ray index.
    pub fn into_hits(self) -> Vec<Option<Hit>> {
        let n = self.t.len() - 3;
        let pairs = self.t[..n].iter().zip(&self.segment[..n]);
        pairs.map(|(&t, &segment)| (segment != Self::NONE).then_some(Hit { t, segment })).collect()
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

    /// [`FrontPatch::offer_rays`] (AVX2 where the CPU has it) answers as [`hit_front`] and
    /// [`closer`] do ray by ray: the same hits, the same bits of `t`, the same ties, also for
    /// rays of another origin, rays through endpoints and a bundle whose length is not a
    /// multiple of four.
    #[test]
    fn offer_rays_is_hit_front_and_closer() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let o = v(10.0, 20.0);
        let segs: Vec<Segment> = (0..40)
            .map(|k| {
                let a = v(next() * 60.0 - 20.0, next() * 60.0);
                let b = if k % 5 == 0 { a + v(0.0, 8.0) } else { v(next() * 60.0 - 20.0, next() * 60.0) };
                Segment::new(a, b)
            })
            .filter(|s| orient(s.a, s.b, o) > 0.0)
            .collect();
        let mut rays: Vec<Ray> = (0..70)
            .map(|i| {
                let phi = (i as f64 / 70.0) * std::f64::consts::TAU;
                Ray::new(o, v(phi.cos(), phi.sin()))
            })
            .collect();
        // Rays through endpoints, one from another origin.
        rays[5] = Ray::new(o, (segs[0].a - o).normalize());
        rays[6] = Ray::new(o, (segs[0].b - o).normalize());
        rays[33] = Ray::new(o + v(1.0, 0.5), rays[33].dir);
        // Copies of patches: exact ties of `t`, offered after and before the lower index.
        let mut segs = segs;
        segs.extend_from_within(0..6);
        for reverse in [false, true] {
            let mut nearest = NearestHits::new(rays.len());
            // What CPUs without AVX2 do: the SSE2 test, each hit offered on its own.
            let mut fallback = NearestHits::new(rays.len());
            let mut expect: Vec<Option<Hit>> = vec![None; rays.len()];
            let mut order: Vec<usize> = (0..segs.len()).collect();
            if reverse {
                order.reverse();
            }
            for p in order {
                let (seg, front) = (&segs[p], FrontPatch::new(o, &segs[p]));
                for base in [0usize, 64] {
                    let word = if base == 0 { !0u64 ^ (1 << 9) } else { (1u64 << (rays.len() - 64)) - 1 };
                    let hits = front.offer_rays(&rays, p as u32, base, word, &mut nearest);
                    let mut fallback_hits = 0;
                    front.hit_rays(&rays, base, word, fallback.offering(p as u32, base, &mut fallback_hits));
                    assert_eq!(hits, fallback_hits, "patch {p}, rays from {base}");
                    let mut want = 0u64;
                    for k in (0..64).filter(|k| word >> k & 1 != 0) {
                        if let Some(t) = hit_front(&rays[base + k], seg) {
                            want |= 1 << k;
                            let h = Hit { t, segment: p as u32 };
                            if closer(h, expect[base + k]) {
                                expect[base + k] = Some(h);
                            }
                        }
                    }
                    assert_eq!(hits, want, "patch {p}, rays from {base}");
                }
            }
            let got = nearest.into_hits();
            assert!(got.iter().flatten().count() > 20);
            assert_eq!(got, fallback.into_hits());
            for (i, (g, e)) in got.iter().zip(&expect).enumerate() {
                let bits = |h: &Option<Hit>| h.map(|h| (h.t.to_bits(), h.segment));
                assert_eq!(bits(g), bits(e), "ray {i}");
            }
        }
    }

    /// [`FrontQuad::certain_misses`] calls a lane a miss only where [`hit_front`] misses, and
    /// most misses it calls (the filter decides all but near-degenerate cases); its AVX and
    /// scalar forms give the same bits. Rays through endpoints and grazing rays included.
    #[test]
    fn front_quads_call_only_true_misses() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let o = v(3.0, -2.0);
        let segs: Vec<Segment> = (0..64)
            .map(|_| {
                Segment::new(v(next() * 40.0 - 20.0, next() * 40.0), v(next() * 40.0 - 20.0, next() * 40.0))
            })
            .filter(|s| orient(s.a, s.b, o) > 0.0)
            .collect();
        let mut rays: Vec<Ray> =
            (0..200).map(|i| Ray::new(o, v((i as f64 * 0.0314).cos(), (i as f64 * 0.0314).sin()))).collect();
        rays.extend(
            segs.iter()
                .take(8)
                .flat_map(|s| [Ray::new(o, (s.a - o).normalize()), Ray::new(o, (s.b - o).normalize())]),
        );
        let (mut called, mut missed) = (0, 0);
        for four in segs.chunks(4) {
            let mut q = FrontQuad::default();
            for (k, s) in four.iter().enumerate() {
                q.set(k, s);
            }
            for ray in &rays {
                let bits = q.certain_misses(ray);
                #[cfg(target_arch = "x86_64")]
                if std::is_x86_feature_detected!("avx2") {
                    let (o, p) = (ray.origin, ray.probe);
                    let scalar = (0..4).fold(0, |b, k| {
                        let (a, c) = (Vec2::new(q.ax[k], q.ay[k]), Vec2::new(q.bx[k], q.by[k]));
                        let (da, ca) = orient_filter(o - a, p - a);
                        let (db, cb) = orient_filter(o - c, p - c);
                        b | ((ca & cb & ((da > 0.0) | (db < 0.0))) as u32) << k
                    });
                    assert_eq!(bits, scalar, "ray {:?}", ray.dir);
                }
                for (k, s) in four.iter().enumerate() {
                    let miss = hit_front(ray, s).is_none();
                    if bits >> k & 1 != 0 {
                        assert!(miss, "lane {k} called a miss that hits: ray {:?}, {s:?}", ray.dir);
                        called += 1;
                    }
                    missed += miss as usize;
                }
            }
        }
        assert!(called * 10 >= missed * 9, "{called} of {missed} misses called");
    }

    #[test]
    fn nearest_offers_as_closer_decides() {
        let mut n = NearestHits::new(2);
        assert_eq!(n.get(0), None);
        n.offer(0, Hit { t: 2.0, segment: 5 });
        n.offer(0, Hit { t: 2.0, segment: 7 });
        assert_eq!(n.get(0), Some(Hit { t: 2.0, segment: 5 }));
        n.offer(0, Hit { t: 2.0, segment: 3 });
        n.offer(1, Hit { t: f64::INFINITY, segment: 1 });
        assert_eq!(n.key(0), 2.0);
        assert_eq!(
            n.into_hits(),
            vec![Some(Hit { t: 2.0, segment: 3 }), Some(Hit { t: f64::INFINITY, segment: 1 })]
        );
    }
}
