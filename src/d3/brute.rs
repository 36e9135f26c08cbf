//! The brute-force ray–convex-polygon intersection: the 3D oracle every 3D tracer is checked
//! against, as `trace::brute` is for the 2D tracers.
//!
//! # The hit rule
//!
//! A ray `O + t·d` (`d` need not be unit; `t` is in units of `|d|`) hits polygon `P` when
//!
//! 1. it is not parallel to `P`'s plane: `d · n ≠ 0`;
//! 2. it meets the plane ahead of its origin: `t = (O_P − O) · n / (d · n) > 0` (strictly), where
//!    `O_P` is `P`'s centre;
//! 3. the meeting point `p` lies inside `P` or on its boundary, with a margin: for every edge
//!    `Vᵢ → Vᵢ₊₁`, the signed distance of `p` from the edge's line, in the plane, positive
//!    inside, is at least `−EDGE_MARGIN × size(P)`. The margin closes the cracks that rounding
//!    would open along an edge shared by two polygons, so a ray through a shared edge or corner
//!    of a closed surface hits at least one of them (a closed surface is watertight).
//!
//! Both sides block: a patch is opaque from behind too. The hit reports which side the ray
//! meets ([`Hit::front`]: `d · n < 0`, the ray arrives at the front side). The nearest hit of a
//! scene is the hit with the smallest `t`; of equal `t`, the polygon of lowest index. A polygon
//! can be skipped (the source patch a hemisphere leaves from).
//!
//! # The prepared form
//!
//! [`Facets`] holds what the hit rule computes from a polygon alone (its edges, their lengths and
//! the margin), once per scene, so that a tracer's test ([`Facets::hit`]) does only the per-ray
//! part: the same operations on the same operands as [`intersect`], so the same bits. It also
//! decides most edges without the division by the edge's length: the sign of the numerator, or
//! its distance from `margin × length`, settles `numerator / length < margin` whenever the
//! rounding of the division cannot (thresholds 8 units in the last place away, see
//! [`Facets::hit`]), and only the rest divide. A bound on `t` lets a tracer skip the inside test
//! of a polygon whose plane lies beyond its nearest hit so far: such a hit could not be taken.

use super::scene::{Polygon, Scene3};
use super::trace::offer;
use glam::DVec3;

/// The margin of the inside test, as a fraction of the polygon's size (see the module docs).
pub const EDGE_MARGIN: f64 = 1e-9;

/// A ray's hit: which polygon, how far, which side.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The index of the polygon hit.
    pub polygon: usize,
    /// The ray parameter of the hit point, `> 0`.
    pub t: f64,
    /// Whether the ray meets the polygon's front side.
    pub front: bool,
}

/// The ray parameter `t` at which `origin + t·direction` hits `polygon`, by the hit rule.
pub fn intersect(origin: DVec3, direction: DVec3, polygon: &Polygon) -> Option<f64> {
    let n = polygon.normal;
    let denom = direction.dot(n);
    if denom == 0.0 || !denom.is_finite() {
        return None;
    }
    let t = (polygon.centre - origin).dot(n) / denom;
    if !(t > 0.0 && t.is_finite()) {
        return None;
    }
    let p = origin + direction * t;
    let margin = -EDGE_MARGIN * polygon.size;
    let v = &polygon.vertices;
    for i in 0..v.len() {
        let a = v[i];
        let edge = v[(i + 1) % v.len()] - a;
        let distance = edge.cross(p - a).dot(n) / edge.length();
        if distance < margin {
            return None;
        }
    }
    Some(t)
}

/// One edge of a prepared polygon: its first vertex `a`, `e` = the next vertex − `a`, and the
/// thresholds of the edge test on `x = e × (p − a) · n` (module docs).
#[derive(Clone, Copy, Debug)]
struct Edge {
    a: DVec3,
    e: DVec3,
    /// `|e|`, as [`intersect`] computes it.
    len: f64,
    /// `x` below this: `x / len < margin` for certain.
    reject: f64,
    /// `x` at or above this: `x / len ≥ margin` for certain.
    accept: f64,
}

/// A polygon prepared for the hit rule (module docs).
#[derive(Clone, Copy, Debug)]
pub struct Facet {
    pub normal: DVec3,
    pub centre: DVec3,
    /// `−EDGE_MARGIN × size`, as [`intersect`] computes it.
    margin: f64,
    /// Its edges in [`Facets`]' edge list.
    first: u32,
    count: u32,
}

/// Every polygon of a scene prepared for the hit rule, by index (module docs).
#[derive(Clone, Debug, Default)]
pub struct Facets {
    facets: Vec<Facet>,
    edges: Vec<Edge>,
}

impl Facets {
    /// The prepared form of `scene`'s polygons.
    pub fn new(scene: &Scene3) -> Facets {
        let mut out = Facets { facets: Vec::with_capacity(scene.polygons.len()), edges: Vec::new() };
        for polygon in &scene.polygons {
            let margin = -EDGE_MARGIN * polygon.size;
            let first = out.edges.len() as u32;
            let v = &polygon.vertices;
            for i in 0..v.len() {
                let a = v[i];
                let e = v[(i + 1) % v.len()] - a;
                let len = e.length();
                // `t = margin·len`, negative. For x < 0 with |x| > |t|(1 + 8u) (u = 2⁻⁵³), even
                // rounded |x / len| > |margin|: a certain rejection; with |x| < |t|(1 − 8u),
                // |x / len| rounds below |margin|: a certain acceptance. The factors' own
                // rounding costs at most 2u. Near underflow the division always decides.
                let t = margin * len;
                let (reject, accept) = if t.abs() >= 1e-280 && t.is_finite() {
                    (t * (1.0 + 4.0 * f64::EPSILON), t * (1.0 - 4.0 * f64::EPSILON))
                } else {
                    (f64::NEG_INFINITY, 0.0)
                };
                out.edges.push(Edge { a, e, len, reject, accept });
            }
            out.facets.push(Facet {
                normal: polygon.normal,
                centre: polygon.centre,
                margin,
                first,
                count: v.len() as u32,
            });
        }
        out
    }

    /// The number of polygons.
    pub fn len(&self) -> usize {
        self.facets.len()
    }

    pub fn is_empty(&self) -> bool {
        self.facets.is_empty()
    }

    /// Polygon `k`'s prepared form.
    #[inline]
    pub fn facet(&self, k: usize) -> &Facet {
        &self.facets[k]
    }

    /// [`intersect`] of `origin + t·direction` and polygon `k`, bit for bit, except that a hit
    /// beyond `bound` (`t > bound`) may be reported as `None` (pass `f64::INFINITY` for the
    /// exact answer).
    #[inline]
    pub fn hit(&self, k: usize, origin: DVec3, direction: DVec3, bound: f64) -> Option<f64> {
        let f = &self.facets[k];
        let n = f.normal;
        let denom = direction.dot(n);
        if denom == 0.0 || !denom.is_finite() {
            return None;
        }
        let t = (f.centre - origin).dot(n) / denom;
        if !(t > 0.0 && t.is_finite()) || t > bound {
            return None;
        }
        self.inside(k, origin, direction, t).then_some(t)
    }

    /// The last stage of [`Facets::hit`]: whether `origin + t·direction`, `t` the plane's
    /// distance as `hit` computes it, passes every edge test of polygon `k`.
    #[inline]
    pub fn inside(&self, k: usize, origin: DVec3, direction: DVec3, t: f64) -> bool {
        let f = &self.facets[k];
        let n = f.normal;
        let p = origin + direction * t;
        for edge in &self.edges[f.first as usize..(f.first + f.count) as usize] {
            let x = edge.e.cross(p - edge.a).dot(n);
            if x >= 0.0 || x >= edge.accept {
                continue;
            }
            if x < edge.reject || x / edge.len < f.margin {
                return false;
            }
        }
        true
    }
}

/// Polygons of a scene prepared for one source's rays, four to a group: each polygon's normal and
/// its numerator `(centre − O) · n` of the hit rule's `t`, so that the first stage of
/// [`Facets::hit`] (the plane's distance and its checks) runs on four polygons at once, in AVX
/// lanes where the CPU has them: lane by lane the same operations on the same operands, so the
/// same bits. The lanes that pass go on to [`Facets::inside`] one by one.
#[derive(Clone, Debug, Default)]
pub struct FacetQuads {
    quads: Vec<Quad>,
}

#[derive(Clone, Copy, Debug)]
#[repr(C, align(32))]
struct Quad {
    nx: [f64; 4],
    ny: [f64; 4],
    nz: [f64; 4],
    num: [f64; 4],
    /// The polygon of each lane; a lane without one has a zero normal, so it never passes.
    k: [u32; 4],
}

impl FacetQuads {
    /// Polygons `ks` of `facets`, for rays from `origin`.
    pub fn new(facets: &Facets, origin: DVec3, ks: &[usize]) -> FacetQuads {
        let quads = ks
            .chunks(4)
            .map(|c| {
                let mut q = Quad { nx: [0.0; 4], ny: [0.0; 4], nz: [0.0; 4], num: [0.0; 4], k: [0; 4] };
                for (lane, &k) in c.iter().enumerate() {
                    let f = facets.facet(k);
                    (q.nx[lane], q.ny[lane], q.nz[lane]) = (f.normal.x, f.normal.y, f.normal.z);
                    q.num[lane] = (f.centre - origin).dot(f.normal);
                    q.k[lane] = k as u32;
                }
                q
            })
            .collect();
        FacetQuads { quads }
    }

    /// Offers every hit of the ray `origin + t·direction` (`origin` the one given to
    /// [`FacetQuads::new`]) to `best` by the tie rule (nearer wins, of equal `t` the lower
    /// index): [`Facets::hit`] of each polygon, in the polygons' order, bounded by the nearest
    /// hit so far, since a hit beyond it could not be taken.
    #[inline]
    pub fn offer_hits(&self, facets: &Facets, origin: DVec3, direction: DVec3, best: &mut Option<Hit>) {
        let bound = |best: &Option<Hit>| best.map_or(f64::INFINITY, |b| b.t);
        for q in &self.quads {
            let (mut lanes, denom, t) = q.plane(direction, bound(best));
            while lanes != 0 {
                let lane = lanes.trailing_zeros() as usize;
                lanes &= lanes - 1;
                let k = q.k[lane] as usize;
                if t[lane] <= bound(best) && facets.inside(k, origin, direction, t[lane]) {
                    offer(best, k, t[lane], denom[lane] < 0.0);
                }
            }
        }
    }
}

impl Quad {
    /// Bit `lane` set when the lane's plane passes [`Facets::hit`]'s first stage for `direction`
    /// with `bound`; each lane's `d · n` and `t`.
    #[inline]
    fn plane(&self, d: DVec3, bound: f64) -> (u32, [f64; 4], [f64; 4]) {
        #[cfg(target_arch = "x86_64")]
        if std::is_x86_feature_detected!("avx") {
            // SAFETY: the CPU has AVX (checked just above).
            return unsafe { self.plane_avx(d, bound) };
        }
        let mut bits = 0;
        let (mut denom, mut t) = ([0.0; 4], [0.0; 4]);
        for lane in 0..4 {
            denom[lane] = d.dot(DVec3::new(self.nx[lane], self.ny[lane], self.nz[lane]));
            t[lane] = self.num[lane] / denom[lane];
            let pass = denom[lane] != 0.0
                && denom[lane].is_finite()
                && t[lane] > 0.0
                && t[lane].is_finite()
                && t[lane] <= bound;
            bits |= (pass as u32) << lane;
        }
        (bits, denom, t)
    }

    /// [`Quad::plane`] in AVX lanes: `d · n` as glam computes it, `(x·x + y·y) + z·z`.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    fn plane_avx(&self, d: DVec3, bound: f64) -> (u32, [f64; 4], [f64; 4]) {
        use std::arch::x86_64::*;
        // SAFETY: the arrays are 4 f64 each, aligned to 32 bytes by the struct's layout.
        let (nx, ny, nz, num) = unsafe {
            (
                _mm256_load_pd(self.nx.as_ptr()),
                _mm256_load_pd(self.ny.as_ptr()),
                _mm256_load_pd(self.nz.as_ptr()),
                _mm256_load_pd(self.num.as_ptr()),
            )
        };
        let denom = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(d.x), nx), _mm256_mul_pd(_mm256_set1_pd(d.y), ny)),
            _mm256_mul_pd(_mm256_set1_pd(d.z), nz),
        );
        let t = _mm256_div_pd(num, denom);
        let abs = |v: __m256d| _mm256_andnot_pd(_mm256_set1_pd(-0.0), v);
        let inf = _mm256_set1_pd(f64::INFINITY);
        let zero = _mm256_setzero_pd();
        // Ordered compares: a NaN fails each, as it fails `hit`'s.
        let pass = _mm256_and_pd(
            _mm256_and_pd(_mm256_cmp_pd::<_CMP_NEQ_OQ>(denom, zero), _mm256_cmp_pd::<_CMP_LT_OQ>(abs(denom), inf)),
            _mm256_and_pd(
                _mm256_and_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(t, zero), _mm256_cmp_pd::<_CMP_LT_OQ>(abs(t), inf)),
                _mm256_cmp_pd::<_CMP_LE_OQ>(t, _mm256_set1_pd(bound)),
            ),
        );
        let (mut dv, mut tv) = ([0.0; 4], [0.0; 4]);
        // SAFETY: each array holds 4 f64 (unaligned stores).
        unsafe {
            _mm256_storeu_pd(dv.as_mut_ptr(), denom);
            _mm256_storeu_pd(tv.as_mut_ptr(), t);
        }
        (_mm256_movemask_pd(pass) as u32, dv, tv)
    }
}

/// The nearest hit of `origin + t·direction` in `scene`, skipping polygon `skip`, by brute force
/// over every polygon.
pub fn nearest(scene: &Scene3, origin: DVec3, direction: DVec3, skip: Option<usize>) -> Option<Hit> {
    let mut best: Option<Hit> = None;
    for (k, polygon) in scene.polygons.iter().enumerate() {
        if Some(k) == skip {
            continue;
        }
        if let Some(t) = intersect(origin, direction, polygon) {
            if best.is_none_or(|b| t < b.t) {
                best = Some(Hit { polygon: k, t, front: direction.dot(polygon.normal) < 0.0 });
            }
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::d3::gen::generate;
    use crate::d3::obj;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// The prepared test gives `intersect`'s bits on rays aimed at random points of random
    /// polygons, at their vertices and at points a few units in the last place around their edges
    /// (where the margin decides), from random origins; with a bound, the same or `None` beyond it.
    #[test]
    fn the_prepared_test_is_intersect_bit_for_bit() {
        let seed = 181u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let cornell =
            obj::load(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cornell_box.obj")).unwrap();
        let mut decided = [0usize; 2];
        for scene in [generate(300, 40.0, 3).unwrap(), cornell] {
            let facets = Facets::new(&scene);
            let (lo, hi) = scene.bounds();
            for _ in 0..20_000 {
                let k = rng.random_range(0..scene.polygons.len());
                let p = &scene.polygons[k];
                let o = lo + (hi - lo) * DVec3::new(rng.random(), rng.random(), rng.random());
                let i = rng.random_range(0..p.vertices.len());
                let (a, b) = (p.vertices[i], p.vertices[(i + 1) % p.vertices.len()]);
                let target = match rng.random_range(0..4) {
                    0 => p.centre + (a - p.centre) * rng.random::<f64>(),
                    1 => a,
                    // Along an edge, pushed out or in by a hair (about the margin).
                    _ => {
                        let s: f64 = rng.random();
                        let out = (b - a).cross(p.normal).normalize();
                        a + (b - a) * s + out * (p.size * 1e-9 * rng.random_range(-3.0..3.0))
                    }
                };
                let d = target - o;
                let exact = intersect(o, d, p);
                decided[exact.is_some() as usize] += 1;
                let fast = facets.hit(k, o, d, f64::INFINITY);
                assert_eq!(exact.map(f64::to_bits), fast.map(f64::to_bits), "seed {seed}: polygon {k} from {o} along {d}");
                let bound = rng.random_range(0.0..2.0);
                let culled = facets.hit(k, o, d, bound);
                assert_eq!(culled, exact.filter(|&t| t <= bound), "seed {seed}: polygon {k}, bound {bound}");
            }
        }
        assert!(decided[0] > 1000 && decided[1] > 1000, "seed {seed}: hits and misses both occur: {decided:?}");
    }
}
