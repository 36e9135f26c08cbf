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
//!
//! Two conservative filters run before it, each deciding a pair only where rounding cannot change
//! the answer: a polygon's bounding [`Cone`] from the source rules out the rays that pass far
//! from it, and [`FacetQuads`] (one source's polygons, four to a group in AVX lanes) decides an
//! edge from two products per ray (`SourceEdge`'s filter) unless it lies within a rounding
//! bound of its threshold, where the hit rule's own operations decide. For a source with many
//! polygons, `DirBins` lists them by direction once, so that a ray visits only the polygons whose
//! cones could let it through, each still through its cone and the hit rule's own inside test.

use super::grid::RegistrationPolygon;
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
    /// The largest distance of a vertex of the registration polygon
    /// ([`super::grid::RegistrationPolygon`], which holds every point the hit rule accepts) from
    /// the centre.
    radius: f64,
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
            let radius = RegistrationPolygon::new(polygon)
                .vertices
                .iter()
                .map(|v| (*v - polygon.centre).length())
                .fold(0.0, f64::max);
            out.facets.push(Facet {
                normal: polygon.normal,
                centre: polygon.centre,
                margin,
                radius,
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

    /// Polygon `k`'s bounding cone seen from `origin` (see [`Cone`]).
    pub fn cone(&self, k: usize, origin: DVec3) -> Cone {
        let f = &self.facets[k];
        let v = f.centre - origin;
        let d2 = v.dot(v);
        let dist = d2.sqrt();
        let scale = origin.abs().max_element() + f.centre.abs().max_element() + dist + f.radius;
        let r = f.radius * (1.0 + 1e-9) + 1e-12 * scale;
        let q = d2 - r * r - 64.0 * f64::EPSILON * d2;
        Cone { v, q: if q > 0.0 { q } else { f64::NEG_INFINITY } }
    }

    /// The last stage of [`Facets::hit`]: whether `origin + t·direction`, `t` the plane's
    /// distance as `hit` computes it, passes every edge test of polygon `k`.
    #[inline(always)]
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

    /// [`Facets::inside`]'s test of edge `i` of polygon `k` alone: whether it passes.
    #[inline(never)]
    fn edge_passes(&self, k: usize, i: usize, origin: DVec3, direction: DVec3, t: f64) -> bool {
        let f = &self.facets[k];
        let edge = &self.edges[f.first as usize + i];
        let x = edge.e.cross(origin + direction * t - edge.a).dot(f.normal);
        !(x < 0.0 && x < edge.accept && (x < edge.reject || x / edge.len < f.margin))
    }

    /// The edges' parts of [`Facets::inside`] that depend on the source `origin` alone, for
    /// [`SourceEdge`]'s filter.
    fn source_edges(&self, k: usize, origin: DVec3, out: &mut Vec<SourceEdge>) {
        let f = &self.facets[k];
        for edge in &self.edges[f.first as usize..(f.first + f.count) as usize] {
            out.push(SourceEdge {
                alpha: edge.e.cross(origin - edge.a).dot(f.normal),
                w: f.normal.cross(edge.e),
                s: origin.abs().max_element() + edge.a.abs().max_element(),
                scale: 128.0 * f64::EPSILON * edge.e.abs().max_element(),
                reject: edge.reject,
                accept: edge.accept,
            });
        }
    }
}

/// One edge of a polygon for one source `O`: the edge test's numerator `x = e × (p − a) · n` at
/// `p = O + t·d` is `α + t·(d · w)` with `α = e × (O − a) · n` and `w = n × e`, up to rounding.
/// Computed that way (two products less than the hit rule's), it decides the edge when it lies
/// farther than a bound `B` on the two computations' difference from the thresholds of
/// [`Facets::hit`] (`x ≥ accept`: passes; `x < reject`: fails); otherwise the hit rule's own
/// operations decide. `B = 128·ε·|e|∞·(|O|∞ + |a|∞ + |t|·|d|₁)` (`ε` = 2⁻⁵², twice the unit
/// roundoff): the rounding of `x` as the hit rule computes it (the point, its difference with
/// `a`, the cross and dot products) is at most `29u·|e|∞·(|O|∞ + |a|∞ + |t|·|d|∞)` and that of
/// `α + t·(d · w)` at most `29u·|e|∞·(|O|∞ + |a|∞) + 13u·|t|·|e|∞·|d|₁` (`u = ε/2`), so `B` is
/// twice their sum.
#[derive(Clone, Copy, Debug)]
struct SourceEdge {
    alpha: f64,
    w: DVec3,
    /// `|O|∞ + |a|∞`.
    s: f64,
    /// `128·ε·|e|∞`.
    scale: f64,
    reject: f64,
    accept: f64,
}

/// A polygon's bounding cone from a ray origin `O`: a conservative test that rules out the rays
/// that pass far from it, made before the hit rule.
///
/// Every point the hit rule accepts lies in the registration polygon (`RegistrationPolygon`, up
/// to the rounding of the point), so within the polygon's `radius` of its centre `c`. With
/// `v = c − O`, `D = |v|` and `r = radius·(1 + 10⁻⁹) + 10⁻¹²·(|O|∞ + |c|∞ + D + radius)` (far
/// above the rounding of the hit point, of `v` and of these products), a ray `O + t·d` misses
/// when `O` lies outside the sphere of radius `r` and the ray's line passes outside it or the
/// ray points away from it: `(d·v)·|d·v| < |d|²·q`, `q = D² − r² − 64u·D²` (`u = 2⁻⁵³`; the last
/// term covers the rounding of `D²`, `d·v` and the products). When `q ≤ 0` (`O` inside or near
/// the sphere) nothing is ruled out (`q = −∞`).
#[derive(Clone, Copy, Debug)]
pub struct Cone {
    v: DVec3,
    q: f64,
}

impl Cone {
    /// The cone that rules nothing out.
    pub const NONE: Cone = Cone { v: DVec3::ZERO, q: f64::NEG_INFINITY };

    /// Whether the ray along `d` (`dd = d·d`) certainly misses the polygon.
    #[inline]
    pub fn misses(&self, d: DVec3, dd: f64) -> bool {
        let dv = d.dot(self.v);
        dv * dv.abs() < dd * self.q
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
    /// The quads' cones, by quad.
    cones: Vec<ConeQuad>,
    /// The polygons' edges for the source, in the order of the quads' lanes (`Quad::e`); empty
    /// for a source with bins.
    edges: Vec<SourceEdge>,
    /// Whether the CPU has AVX (detected once).
    avx: bool,
    /// The polygons by direction, for a source with many polygons.
    bins: Option<DirBins>,
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
    /// The first of each lane's edges in `FacetQuads::edges`, and their number.
    e: [u32; 4],
    count: [u32; 4],
}

/// The [`Cone`]s of a [`Quad`]'s lanes (`v` and `q`), apart so that the first pass over a
/// source's polygons reads them alone; a lane without a polygon rules every ray out.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(32))]
struct ConeQuad {
    vx: [f64; 4],
    vy: [f64; 4],
    vz: [f64; 4],
    q: [f64; 4],
}

impl FacetQuads {
    /// Polygons `ks` of `facets`, for rays from `origin`, nearest first (by the distance of
    /// their bounding spheres: the nearer polygons' hits then bound the farther ones' tests;
    /// the order cannot change a ray's nearest hit, which the tie rule decides), except with
    /// direction bins ([`DirBins`], many polygons), where they keep the order of `ks`.
    pub fn new(facets: &Facets, origin: DVec3, ks: &[usize]) -> FacetQuads {
        // A source with many polygons gets direction bins, and its rays' few inside tests are
        // the hit rule's own (no per-source edge data to make). Its rays visit few polygons
        // each, so they keep the given order.
        let binned = ks.len().div_ceil(4) >= BIN_MIN_QUADS;
        let ks: Vec<usize> = if binned {
            ks.to_vec()
        } else {
            let mut ks: Vec<(f64, usize)> = ks
                .iter()
                .map(|&k| {
                    let f = facets.facet(k);
                    ((f.centre - origin).length() - f.radius, k)
                })
                .collect();
            ks.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            ks.into_iter().map(|(_, k)| k).collect()
        };
        let mut edges = Vec::new();
        let mut cones = Vec::with_capacity(ks.len().div_ceil(4));
        let quads = ks
            .chunks(4)
            .map(|c| {
                let z = [0.0; 4];
                let mut q = Quad { nx: z, ny: z, nz: z, num: z, k: [0; 4], e: [0; 4], count: [0; 4] };
                let mut cq = ConeQuad { vx: z, vy: z, vz: z, q: [f64::INFINITY; 4] };
                for (lane, &k) in c.iter().enumerate() {
                    if !binned {
                        q.e[lane] = edges.len() as u32;
                        facets.source_edges(k, origin, &mut edges);
                        q.count[lane] = edges.len() as u32 - q.e[lane];
                    }
                    let f = facets.facet(k);
                    (q.nx[lane], q.ny[lane], q.nz[lane]) = (f.normal.x, f.normal.y, f.normal.z);
                    q.num[lane] = (f.centre - origin).dot(f.normal);
                    let cone = facets.cone(k, origin);
                    (cq.vx[lane], cq.vy[lane], cq.vz[lane], cq.q[lane]) =
                        (cone.v.x, cone.v.y, cone.v.z, cone.q);
                    q.k[lane] = k as u32;
                }
                cones.push(cq);
                q
            })
            .collect();
        #[cfg(target_arch = "x86_64")]
        let avx = std::is_x86_feature_detected!("avx");
        #[cfg(not(target_arch = "x86_64"))]
        let avx = false;
        let bins = binned.then(|| DirBins::new(&cones));
        FacetQuads { quads, cones, edges, avx, bins }
    }

    /// Offers every hit of the ray `origin + t·direction` (`origin` the one given to
    /// [`FacetQuads::new`]) to `best` by the tie rule (nearer wins, of equal `t` the lower
    /// index): [`Facets::hit`] of each polygon, in the polygons' order, bounded by the nearest
    /// hit so far, since a hit beyond it could not be taken. With direction bins (a source with
    /// many polygons, [`DirBins`]), only the polygons listed in the ray's cell are visited, one
    /// by one: every other polygon's cone rules the ray out.
    #[inline(always)]
    pub fn offer_hits(&self, facets: &Facets, origin: DVec3, direction: DVec3, best: &mut Option<Hit>) {
        let dd = direction.dot(direction);
        if let Some(bins) = &self.bins {
            if let Some(c) = bins.cell(direction, dd) {
                for &j in bins.everywhere.iter().chain(bins.polygons(c)) {
                    self.offer_lane(j as usize, facets, origin, direction, dd, best);
                }
                return;
            }
        }
        let d1 = direction.abs().element_sum();
        #[cfg(target_arch = "x86_64")]
        // SAFETY (every `unsafe` of this loop): `self.avx` says the CPU has AVX (`FacetQuads::new`).
        let ray = self.avx.then(|| unsafe { AvxRay::new(direction, dd) });
        let bound = |best: &Option<Hit>| best.map_or(f64::INFINITY, |b| b.t);
        for (q, c) in self.quads.iter().zip(&self.cones) {
            #[cfg(target_arch = "x86_64")]
            let misses = match &ray {
                Some(ray) => unsafe { c.misses_avx(ray) },
                None => c.misses(direction, dd),
            };
            #[cfg(not(target_arch = "x86_64"))]
            let misses = c.misses(direction, dd);
            if misses == 0b1111 {
                // Every lane's cone rules the ray out (the usual case in a large scene).
                continue;
            }
            #[cfg(target_arch = "x86_64")]
            let (lanes, denom, t) = match &ray {
                Some(ray) => unsafe { q.plane_avx(ray, bound(best)) },
                None => q.plane(direction, bound(best)),
            };
            #[cfg(not(target_arch = "x86_64"))]
            let (lanes, denom, t) = q.plane(direction, bound(best));
            let mut lanes = lanes & !misses;
            while lanes != 0 {
                let lane = lanes.trailing_zeros() as usize;
                lanes &= lanes - 1;
                let (k, t) = (q.k[lane] as usize, t[lane]);
                // A hit beyond the nearest so far, or at its distance from a polygon of higher
                // index, could not be taken (the tie rule).
                if best.is_some_and(|b| t > b.t || (t == b.t && k > b.polygon)) {
                    continue;
                }
                let inside = if self.edges.is_empty() {
                    // A source with bins has no filter data: the hit rule's own test.
                    facets.inside(k, origin, direction, t)
                } else {
                    // `Facets::inside`, edge by edge through `SourceEdge`'s filter.
                    let first = q.e[lane] as usize;
                    let edges = &self.edges[first..first + q.count[lane] as usize];
                    edges.iter().enumerate().all(|(i, e)| {
                        let x = e.alpha + t * direction.dot(e.w);
                        let b = e.scale * (e.s + t * d1);
                        if x - b >= e.accept {
                            true
                        } else if x + b < e.reject {
                            false
                        } else {
                            facets.edge_passes(k, i, origin, direction, t)
                        }
                    })
                };
                if inside {
                    offer(best, k, t, denom[lane] < 0.0);
                }
            }
        }
    }

    /// [`FacetQuads::offer_hits`] for the polygon in place `j` of the order (quad `j / 4`, lane
    /// `j % 4`) alone: its cone ([`Cone::misses`]), its plane ([`Quad::plane`]'s operations),
    /// then [`Facets::inside`].
    #[inline(always)]
    fn offer_lane(
        &self,
        j: usize,
        facets: &Facets,
        origin: DVec3,
        direction: DVec3,
        dd: f64,
        best: &mut Option<Hit>,
    ) {
        let (qi, lane) = (j >> 2, j & 3);
        let c = &self.cones[qi];
        let cone = Cone { v: DVec3::new(c.vx[lane], c.vy[lane], c.vz[lane]), q: c.q[lane] };
        if cone.misses(direction, dd) {
            return;
        }
        let q = &self.quads[qi];
        let denom = direction.dot(DVec3::new(q.nx[lane], q.ny[lane], q.nz[lane]));
        let t = q.num[lane] / denom;
        let pass = denom != 0.0
            && denom.is_finite()
            && t > 0.0
            && t.is_finite()
            // A hit beyond the nearest so far, or at its distance from a polygon of higher
            // index, could not be taken (the tie rule).
            && best.is_none_or(|b| t < b.t || (t == b.t && (q.k[lane] as usize) < b.polygon));
        if pass && facets.inside(q.k[lane] as usize, origin, direction, t) {
            offer(best, q.k[lane] as usize, t, denom < 0.0);
        }
    }
}

/// A source's polygons by direction, on a cube map (six faces of `BIN_SIDE²` cells): a polygon
/// is listed in every cell that a direction its cone does not rule out can fall in, so a ray
/// need visit only the polygons of its own cell (each still through its cone: the list is
/// conservative, the cones decide).
///
/// A direction `d` falls in the face of its largest component `|d_f|` (ties to the lower axis,
/// x before y before z), at `u = d_i / |d_f|`, `v = d_j / |d_f|` (`i < j` the other two axes),
/// cell `⌊(u + 1)/2 · BIN_SIDE⌋` clamped to the face. A [`Cone`] (`v`, `q > 0`) rules out a
/// direction at an angle `θ` from its axis `a = v/|v|` with `sin θ > √(1 − q/|v|²)` (up to the
/// rounding of its test, 10⁻¹⁵ relative) or pointing away; over the directions it lets through,
/// in the open half-space of face `f` (`a_f > s`, `s` that sine grown by 10⁻⁶), `u` lies between
/// the roots of `(a_f² − s²)u² − 2a_i a_f u + a_i² − s² = 0` (the planes `d_i = u·d_f` tangent
/// to the cone), and so does `v` with `a_j`; these intervals, grown by 10⁻⁶, bound the cells. A
/// cone that is not that far inside a face's half-space is listed in the whole face if it could
/// reach the face at all (its axis within `asin s + 54.8°` of the face's), and a cone that rules
/// nothing out (`q ≤ 0`: the source inside or near its sphere) is visited by every ray.
#[derive(Clone, Debug)]
struct DirBins {
    /// Cell `c`'s polygons (places in the quads' order) are `items[start[c]..start[c + 1]]`,
    /// in increasing order.
    start: Vec<u32>,
    items: Vec<u32>,
    /// The polygons every ray visits (their cones rule nothing out).
    everywhere: Vec<u32>,
}

/// The cells along a side of a face of [`DirBins`].
const BIN_SIDE: usize = 32;
/// The fewest quads for which a source gets [`DirBins`] (below, the cells cost more than they
/// save).
const BIN_MIN_QUADS: usize = 8;

impl DirBins {
    fn new(cones: &[ConeQuad]) -> DirBins {
        let m = BIN_SIDE;
        let cells = 6 * m * m;
        // (place, face, [u0, u1, v0, v1]), cells inclusive.
        let mut rects: Vec<(u32, u8, [u8; 4])> = Vec::new();
        let mut everywhere = Vec::new();
        for (qi, cq) in cones.iter().enumerate() {
            for lane in 0..4 {
                if cq.q[lane] == f64::INFINITY {
                    // No polygon in this lane.
                    continue;
                }
                let j = (4 * qi + lane) as u32;
                let v = DVec3::new(cq.vx[lane], cq.vy[lane], cq.vz[lane]);
                if !Self::cone_cells(v, cq.q[lane], |face, r| rects.push((j, face as u8, r))) {
                    everywhere.push(j);
                }
            }
        }
        // Count, sum, then fill from the back (a polygon has at most one entry per cell, so
        // each cell's list comes out in increasing order).
        let mut start = vec![0u32; cells + 1];
        for &(_, face, r) in &rects {
            for u in r[0]..=r[1] {
                let row = (face as usize * m + u as usize) * m;
                for c in &mut start[row + r[2] as usize..=row + r[3] as usize] {
                    *c += 1;
                }
            }
        }
        let mut total = 0;
        for c in &mut start[..cells] {
            total += *c;
            *c = total;
        }
        start[cells] = total;
        let mut items = vec![0u32; total as usize];
        for &(j, face, r) in rects.iter().rev() {
            for u in r[0]..=r[1] {
                let row = (face as usize * m + u as usize) * m;
                for c in row + r[2] as usize..=row + r[3] as usize {
                    start[c] -= 1;
                    items[start[c] as usize] = j;
                }
            }
        }
        DirBins { start, items, everywhere }
    }

    /// Calls `push(face, [u0, u1, v0, v1])` with the cells (inclusive ranges) of each face that
    /// the cone (`v`, `q`) can let a direction through in (the type's docs); false when the
    /// cone rules nothing out (then nothing is pushed).
    #[inline(always)]
    fn cone_cells(v: DVec3, q: f64, mut push: impl FnMut(usize, [u8; 4])) -> bool {
        let m = BIN_SIDE;
        let d2 = v.dot(v);
        let cos2 = q / d2;
        if !(q > 0.0 && d2 > 0.0 && cos2.is_finite()) {
            return false;
        }
        let s = (1.0 - cos2).max(0.0).sqrt() + 1e-6;
        if s >= 0.99 {
            return false;
        }
        let a = v / d2.sqrt();
        // (Clamped to the face first: truncation is then the floor.)
        let cell = |u: f64| ((u + 1.0) * 0.5 * m as f64).clamp(0.0, (m - 1) as f64) as u8;
        let whole = [0, (m - 1) as u8, 0, (m - 1) as u8];
        for face in 0..6 {
            let (f, sign) = (face / 2, if face % 2 == 0 { 1.0 } else { -1.0 });
            let (i, j) = match f {
                0 => (1, 2),
                1 => (0, 2),
                _ => (0, 1),
            };
            let af = sign * a[f];
            if af > s + 0.05 {
                let inv = 1.0 / (af * af - s * s);
                let range = |ai: f64| {
                    let root = s * (ai * ai + af * af - s * s).max(0.0).sqrt();
                    let (lo, hi) = ((ai * af - root) * inv, (ai * af + root) * inv);
                    (lo - 1e-6 * (1.0 + lo.abs()), hi + 1e-6 * (1.0 + hi.abs()))
                };
                let (u0, u1) = range(a[i]);
                let (v0, v1) = range(a[j]);
                if u1 < -1.0 || u0 > 1.0 || v1 < -1.0 || v0 > 1.0 {
                    continue;
                }
                push(face, [cell(u0), cell(u1), cell(v0), cell(v1)]);
            } else if s >= 0.25 {
                // A wide cone near the face's plane: the whole face if it could reach it. The
                // face's corners lie acos(1/√3) = 54.7356° from its axis.
                if af.clamp(-1.0, 1.0).acos() <= s.asin() + 0.9554 + 1e-3 {
                    push(face, whole);
                }
            }
            // Otherwise (a cone of half-angle below 14.5° whose axis lies 72.5° or more from
            // the face's) it is 58° or more from the axis, beyond the face's corners.
        }
        true
    }

    /// The cell of direction `d` (`dd = d·d`), or `None` when `d` is not a direction the bins
    /// can place (zero, not finite, or so short or long that its cone tests lose precision):
    /// then every quad is visited.
    #[inline(always)]
    fn cell(&self, d: DVec3, dd: f64) -> Option<usize> {
        if !(1e-200..=1e200).contains(&dd) {
            return None;
        }
        let m = BIN_SIDE;
        let (ax, ay, az) = (d.x.abs(), d.y.abs(), d.z.abs());
        let (face, big, u, v) = if ax >= ay && ax >= az {
            (usize::from(d.x < 0.0), ax, d.y, d.z)
        } else if ay >= az {
            (2 + usize::from(d.y < 0.0), ay, d.x, d.z)
        } else {
            (4 + usize::from(d.z < 0.0), az, d.x, d.y)
        };
        let half = 0.5 * m as f64;
        let inv = half / big;
        let cu = ((u * inv + half).floor() as isize).clamp(0, m as isize - 1) as usize;
        let cv = ((v * inv + half).floor() as isize).clamp(0, m as isize - 1) as usize;
        Some((face * m + cu) * m + cv)
    }

    /// The polygons listed in cell `c`.
    #[inline(always)]
    fn polygons(&self, c: usize) -> &[u32] {
        &self.items[self.start[c] as usize..self.start[c + 1] as usize]
    }
}

impl ConeQuad {
    /// Bit `lane` set when the lane's cone rules the ray along `d` (`dd = d·d`) out
    /// ([`Cone::misses`]; [`ConeQuad::misses_avx`] in AVX lanes).
    #[inline(always)]
    fn misses(&self, d: DVec3, dd: f64) -> u32 {
        (0..4).fold(0, |bits, lane| {
            let cone = Cone { v: DVec3::new(self.vx[lane], self.vy[lane], self.vz[lane]), q: self.q[lane] };
            bits | (cone.misses(d, dd) as u32) << lane
        })
    }

    /// [`ConeQuad::misses`] in AVX lanes.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    fn misses_avx(&self, ray: &AvxRay) -> u32 {
        use std::arch::x86_64::*;
        // SAFETY: the arrays are 4 f64 each, aligned to 32 bytes by the struct's layout.
        let load = |a: &[f64; 4]| unsafe { _mm256_load_pd(a.as_ptr()) };
        let dv = ray.dot(load(&self.vx), load(&self.vy), load(&self.vz));
        let abs = _mm256_andnot_pd(ray.sign, dv);
        let misses =
            _mm256_cmp_pd::<_CMP_LT_OQ>(_mm256_mul_pd(dv, abs), _mm256_mul_pd(ray.dd, load(&self.q)));
        _mm256_movemask_pd(misses) as u32
    }
}

/// A ray's direction broadcast to AVX lanes, made once per ray.
#[cfg(target_arch = "x86_64")]
struct AvxRay {
    dx: std::arch::x86_64::__m256d,
    dy: std::arch::x86_64::__m256d,
    dz: std::arch::x86_64::__m256d,
    /// `d·d`.
    dd: std::arch::x86_64::__m256d,
    /// `−0.0`, the sign bit.
    sign: std::arch::x86_64::__m256d,
}

#[cfg(target_arch = "x86_64")]
impl AvxRay {
    #[target_feature(enable = "avx")]
    fn new(d: DVec3, dd: f64) -> AvxRay {
        use std::arch::x86_64::*;
        AvxRay {
            dx: _mm256_set1_pd(d.x),
            dy: _mm256_set1_pd(d.y),
            dz: _mm256_set1_pd(d.z),
            dd: _mm256_set1_pd(dd),
            sign: _mm256_set1_pd(-0.0),
        }
    }

    /// `d · (x, y, z)` lane by lane as glam computes a dot product, `(x·x + y·y) + z·z`.
    #[target_feature(enable = "avx")]
    fn dot(
        &self,
        x: std::arch::x86_64::__m256d,
        y: std::arch::x86_64::__m256d,
        z: std::arch::x86_64::__m256d,
    ) -> std::arch::x86_64::__m256d {
        use std::arch::x86_64::*;
        _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(self.dx, x), _mm256_mul_pd(self.dy, y)),
            _mm256_mul_pd(self.dz, z),
        )
    }
}

impl Quad {
    /// Bit `lane` set when the lane's plane passes [`Facets::hit`]'s first stage for `d` with
    /// `bound`; each lane's `d · n` and `t` ([`Quad::plane_avx`] in AVX lanes).
    #[inline(always)]
    fn plane(&self, d: DVec3, bound: f64) -> (u32, [f64; 4], [f64; 4]) {
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

    /// [`Quad::plane`] in AVX lanes, the same operations lane by lane.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    fn plane_avx(&self, ray: &AvxRay, bound: f64) -> (u32, [f64; 4], [f64; 4]) {
        use std::arch::x86_64::*;
        // SAFETY: the arrays are 4 f64 each, aligned to 32 bytes by the struct's layout.
        let load = |a: &[f64; 4]| unsafe { _mm256_load_pd(a.as_ptr()) };
        let denom = ray.dot(load(&self.nx), load(&self.ny), load(&self.nz));
        let t = _mm256_div_pd(load(&self.num), denom);
        let abs = |v: __m256d| _mm256_andnot_pd(ray.sign, v);
        let inf = _mm256_set1_pd(f64::INFINITY);
        let zero = _mm256_setzero_pd();
        // Ordered compares: a NaN fails each, as it fails `hit`'s.
        let pass = _mm256_and_pd(
            _mm256_and_pd(
                _mm256_cmp_pd::<_CMP_NEQ_OQ>(denom, zero),
                _mm256_cmp_pd::<_CMP_LT_OQ>(abs(denom), inf),
            ),
            _mm256_and_pd(
                _mm256_and_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(t, zero), _mm256_cmp_pd::<_CMP_LT_OQ>(abs(t), inf)),
                _mm256_cmp_pd::<_CMP_LE_OQ>(t, _mm256_set1_pd(bound)),
            ),
        );
        let (mut dn, mut tv) = ([0.0; 4], [0.0; 4]);
        // SAFETY: each array holds 4 f64 (unaligned stores).
        unsafe {
            _mm256_storeu_pd(dn.as_mut_ptr(), denom);
            _mm256_storeu_pd(tv.as_mut_ptr(), t);
        }
        (_mm256_movemask_pd(pass) as u32, dn, tv)
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

    /// Whether the ray `o + t·d` hits: the quads' nearest hit must be brute force's by
    /// `intersect` and the tie rule (the assertion names the seed and the ray).
    fn same_hit_as_brute_force(
        scene: &Scene3,
        facets: &Facets,
        quads: &FacetQuads,
        o: DVec3,
        d: DVec3,
        seed: u64,
    ) -> bool {
        let mut expect = None;
        for (k, q) in scene.polygons.iter().enumerate() {
            if let Some(t) = intersect(o, d, q) {
                offer(&mut expect, k, t, d.dot(q.normal) < 0.0);
            }
        }
        let mut got = None;
        quads.offer_hits(facets, o, d, &mut got);
        assert_eq!(got, expect, "seed {seed}: from {o} along {d}");
        expect.is_some()
    }

    fn cornell() -> Scene3 {
        obj::load(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cornell_box.obj")).unwrap()
    }

    /// A point of `p` to aim a ray at: an inner point, a vertex, or a point of an edge pushed out
    /// or in by a hair (about the margin, where it decides).
    fn aim(p: &Polygon, rng: &mut ChaCha8Rng) -> DVec3 {
        let i = rng.random_range(0..p.vertices.len());
        let (a, b) = (p.vertices[i], p.vertices[(i + 1) % p.vertices.len()]);
        match rng.random_range(0..4) {
            0 => p.centre + (a - p.centre) * rng.random::<f64>(),
            1 => a,
            _ => {
                let out = (b - a).cross(p.normal).normalize();
                a + (b - a) * rng.random::<f64>() + out * (p.size * 1e-9 * rng.random_range(-3.0..3.0))
            }
        }
    }

    /// The prepared test gives `intersect`'s bits on rays aimed at random points of random
    /// polygons, at their vertices and at points a few units in the last place around their edges
    /// (where the margin decides), from random origins; with a bound, the same or `None` beyond it.
    #[test]
    fn the_prepared_test_is_intersect_bit_for_bit() {
        let seed = 181u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut decided = [0usize; 2];
        for scene in [generate(300, 40.0, 3).unwrap(), cornell()] {
            let facets = Facets::new(&scene);
            let (lo, hi) = scene.bounds();
            for _ in 0..20_000 {
                let k = rng.random_range(0..scene.polygons.len());
                let p = &scene.polygons[k];
                let o = lo + (hi - lo) * DVec3::new(rng.random(), rng.random(), rng.random());
                let d = aim(p, &mut rng) - o;
                let exact = intersect(o, d, p);
                decided[exact.is_some() as usize] += 1;
                let fast = facets.hit(k, o, d, f64::INFINITY);
                assert_eq!(
                    exact.map(f64::to_bits),
                    fast.map(f64::to_bits),
                    "seed {seed}: polygon {k} from {o} along {d}"
                );
                let bound = rng.random_range(0.0..2.0);
                let culled = facets.hit(k, o, d, bound);
                assert_eq!(culled, exact.filter(|&t| t <= bound), "seed {seed}: polygon {k}, bound {bound}");
            }
        }
        assert!(
            decided[0] > 1000 && decided[1] > 1000,
            "seed {seed}: hits and misses both occur: {decided:?}"
        );
    }

    /// The quads' nearest hit (cones, planes in lanes, the edges through the source's filter) is
    /// the nearest hit by `intersect` and the tie rule, on rays aimed at vertices, edges (a hair
    /// in or out) and inner points, from origins inside and outside the scenes, near and far.
    #[test]
    fn the_quads_nearest_hit_is_the_hit_rules() {
        let seed = 182u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut hits = 0;
        for scene in [generate(200, 60.0, 4).unwrap(), cornell()] {
            let facets = Facets::new(&scene);
            let (lo, hi) = scene.bounds();
            let all: Vec<usize> = (0..scene.polygons.len()).collect();
            for source in 0..60 {
                let far = if source % 3 == 0 { 1e4 } else { 1.0 };
                let o = (lo + (hi - lo) * DVec3::new(rng.random(), rng.random(), rng.random())) * far;
                let quads = FacetQuads::new(&facets, o, &all);
                for _ in 0..300 {
                    let p = &scene.polygons[rng.random_range(0..scene.polygons.len())];
                    let d = (aim(p, &mut rng) - o) * rng.random_range(0.5..2.0);
                    hits += same_hit_as_brute_force(&scene, &facets, &quads, o, d, seed) as usize;
                }
            }
        }
        assert!(hits > 10_000, "seed {seed}: the rays must hit ({hits})");
    }

    /// A cone's cells hold every direction its test lets through: directions on the cone's
    /// boundary (the hardest, each where the cone's test turns), inside it, and on the cube
    /// map's seams, for cones narrow and wide, near and far, in every orientation.
    #[test]
    fn a_cones_cells_hold_every_direction_it_lets_through() {
        let seed = 185u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut checked = 0;
        for case in 0..400 {
            let v = DVec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            ) * 10f64.powf(rng.random_range(-3.0..6.0));
            // Half-angles from 10⁻⁶ rad to 80°.
            let alpha = match case % 3 {
                0 => 10f64.powf(rng.random_range(-6.0..-1.0)),
                1 => rng.random_range(0.01..0.3),
                _ => rng.random_range(0.3..1.4),
            };
            let d2 = v.dot(v);
            let cone = Cone { v, q: d2 * alpha.cos().powi(2) };
            let z = [0.0; 4];
            let mut cq = ConeQuad { vx: z, vy: z, vz: z, q: [f64::INFINITY; 4] };
            let lane = case % 4;
            (cq.vx[lane], cq.vy[lane], cq.vz[lane], cq.q[lane]) = (v.x, v.y, v.z, cone.q);
            let bins = DirBins::new(&[cq]);
            let a = v.normalize();
            let w0 = a.any_orthonormal_vector();
            let w1 = a.cross(w0);
            for i in 0..500 {
                let phi = rng.random_range(0.0..std::f64::consts::TAU);
                let w = w0 * phi.cos() + w1 * phi.sin();
                let theta = match i % 4 {
                    0 => alpha * (1.0 + rng.random_range(-1e-9..1e-9)),
                    1 => alpha * rng.random::<f64>(),
                    _ => alpha,
                };
                let mut d = (a * theta.cos() + w * theta.sin()) * rng.random_range(0.1..10.0);
                if i % 4 == 3 {
                    // Onto a seam of the cube map.
                    let (p, q) = (rng.random_range(0..3), rng.random_range(0..3));
                    if p != q {
                        d[q] = d[p].abs() * d[q].signum();
                    }
                }
                if cone.misses(d, d.dot(d)) {
                    continue;
                }
                let c = bins.cell(d, d.dot(d)).expect("a direction of sane length has a cell");
                let listed =
                    bins.everywhere.contains(&(lane as u32)) || bins.polygons(c).contains(&(lane as u32));
                assert!(listed, "seed {seed}: cone {v} of half-angle {alpha}, direction {d} (cell {c})");
                checked += 1;
            }
        }
        assert!(checked > 100_000 / 2, "seed {seed}: directions the cones let through ({checked})");
    }

    /// The direction bins (a source with many polygons) lose no hit: on scenes of many polygons,
    /// from origins inside, outside and far, rays aimed at vertices, edges (a hair in or out) and
    /// inner points, then put on the cube map's seams (two or three components of equal size,
    /// a component zero), on the axes, and scaled to tiny and huge lengths (where the bins stand
    /// aside); each ray's nearest hit is the hit rule's by `intersect`.
    #[test]
    fn the_direction_bins_lose_no_hit() {
        let seed = 183u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut hits = 0;
        for (n, side, scene_seed) in [(400, 40.0, 5), (120, 200.0, 6), (60, 8.0, 8)] {
            let scene = generate(n, side, scene_seed).unwrap();
            let facets = Facets::new(&scene);
            let (lo, hi) = scene.bounds();
            let all: Vec<usize> = (0..scene.polygons.len()).collect();
            for source in 0..40 {
                let far = match source % 4 {
                    0 => 1e4,
                    1 => 3.0,
                    _ => 1.0,
                };
                let o = (lo + (hi - lo) * DVec3::new(rng.random(), rng.random(), rng.random())) * far;
                let quads = FacetQuads::new(&facets, o, &all);
                assert!(quads.bins.is_some(), "seed {seed}: {n} polygons have bins");
                for _ in 0..400 {
                    let p = &scene.polygons[rng.random_range(0..scene.polygons.len())];
                    let mut d = aim(p, &mut rng) - o;
                    let (i, j) = (rng.random_range(0..3), rng.random_range(0..3));
                    match rng.random_range(0..8) {
                        // On a seam between two faces, or at a cube corner.
                        0 if i != j => d[j] = d[i].abs() * if rng.random() { 1.0 } else { -1.0 },
                        1 => {
                            let m = d.abs().max_element();
                            d = DVec3::new(m * d.x.signum(), m * d.y.signum(), m * d.z.signum());
                        }
                        // On a face's centre line, or an axis.
                        2 => d[i] = 0.0,
                        3 => {
                            let keep = d[i];
                            d = DVec3::ZERO;
                            d[i] = keep;
                        }
                        // Between two cells of a face, to the last bit.
                        4 => {
                            let f = d.abs().max_element();
                            let cells = 32.0;
                            let u = ((d[i] / f + 1.0) * 0.5 * cells).round() / cells * 2.0 - 1.0;
                            if d[i].abs() < f {
                                d[i] = u * f;
                            }
                        }
                        5 => d *= 1e-120,
                        6 => d *= 1e120,
                        _ => {}
                    }
                    hits += same_hit_as_brute_force(&scene, &facets, &quads, o, d, seed) as usize;
                }
            }
        }
        assert!(hits > 10_000, "seed {seed}: the rays must hit ({hits})");
    }
}
