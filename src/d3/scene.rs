//! 3D scenes: convex planar polygons with a material, and the rules they must follow.
//!
//! A [`Polygon`] is Def. 2.1's polygonal patch `P = {Vᵢ, O, n}`: its vertices in order, its
//! centre point `O` (the mean of the vertices, which lies inside a convex polygon) and the unit
//! normal `n` of its plane.
//!
//! * **Front side.** The vertices go counter-clockwise seen from the front, so the normal is the
//!   right-hand rule's `(V₁ − V₀) × (V₂ − V₁)` direction; it is computed with Newell's method
//!   (`n ∝ Σ (Vᵢ − O) × (Vᵢ₊₁ − O)`, robust to nearly collinear vertices) and normalised. A patch
//!   emits and receives light on its front side only (the half-space `n` points into). Reverse
//!   the vertex order to flip a patch.
//! * **Validity.** [`Polygon::new`] accepts a polygon when, in this order of checks: it has at
//!   least 3 vertices; every coordinate is finite and of magnitude at most [`COORD_LIMIT`]; no two
//!   vertices are the same point (closer than [`REPEAT_TOLERANCE`] × its size); its area exceeds
//!   [`AREA_TOLERANCE`] × size²; every vertex lies within [`PLANARITY_TOLERANCE`] × size of the
//!   plane through `O` with normal `n`; and it is convex: every turn, seen from the front, is to
//!   the left or straight (collinear vertices are allowed), and the boundary winds exactly once.
//!   The *size* is the diagonal of the polygon's axis-aligned bounding box.
//!
//! A [`Scene3`] is a non-empty list of polygons (a polygon's index is its position, counted from
//! 0: in an OBJ file, the face's position among the file's `f` lines) and the materials they use.
//! Reflectance and emission are kept per polygon, as scalars, so that a slice of the scene by a
//! plane can later come out as a 2D [`crate::scene::Scene`] with the same values.

use glam::DVec3;
use std::collections::HashMap;
use std::fmt;

/// The largest magnitude a coordinate may have, as in the 2D scenes (10⁹).
pub const COORD_LIMIT: f64 = 1.0e9;

/// Two vertices closer than this fraction of the polygon's size are the same point.
pub const REPEAT_TOLERANCE: f64 = 1e-9;

/// A polygon whose area is at most this fraction of its size squared has zero area.
pub const AREA_TOLERANCE: f64 = 1e-12;

/// A vertex farther than this fraction of the polygon's size from its plane makes the polygon
/// non-planar. 10⁻⁵ accepts coordinates printed with about 7 significant digits; the Cornell
/// box's left wall (3.2 mm off its plane over 780 mm) is beyond it, see `SCENES3D.md`.
pub const PLANARITY_TOLERANCE: f64 = 1e-5;

/// A turn whose cross product is below `−CONVEXITY_TOLERANCE × size²` is a turn to the right.
pub const CONVEXITY_TOLERANCE: f64 = 1e-12;

/// The largest number of polygons in a scene (as many as the 2D scenes' segments).
pub const MAX_POLYGONS: usize = 1 << 20;

/// A material: the values of an MTL `newmtl` block this crate uses.
#[derive(Clone, Debug, PartialEq)]
pub struct Material3 {
    /// The name after `newmtl`.
    pub name: String,
    /// `Kd`, the diffuse reflectance per channel, each in `[0, 1]`.
    pub kd: [f64; 3],
    /// `Ke`, the emission per channel (radiant exitance), each `≥ 0`; zero when absent.
    pub ke: [f64; 3],
}

impl Material3 {
    /// A grey material: `Kd = (reflectance, reflectance, reflectance)`, `Ke = (emission, …)`.
    pub fn grey(name: &str, reflectance: f64, emission: f64) -> Self {
        Material3 { name: name.to_string(), kd: [reflectance; 3], ke: [emission; 3] }
    }

    /// The scalar reflectance of the patches: the mean of the three `Kd` channels.
    pub fn reflectance(&self) -> f64 {
        (self.kd[0] + self.kd[1] + self.kd[2]) / 3.0
    }

    /// The scalar emission of the patches: the mean of the three `Ke` channels.
    pub fn emission(&self) -> f64 {
        (self.ke[0] + self.ke[1] + self.ke[2]) / 3.0
    }

    /// Why the values cannot be a patch's material, if they cannot: `Kd` channels must be finite
    /// and in `[0, 1]` with a mean below 1 (a radiosity solve needs reflectance below 1, as in
    /// the 2D scenes), `Ke` channels finite and `≥ 0`.
    pub fn problem(&self) -> Option<String> {
        if let Some(v) = self.kd.iter().find(|v| !(v.is_finite() && (0.0..=1.0).contains(*v))) {
            return Some(format!("Kd has a channel outside [0, 1] ({v})"));
        }
        if self.reflectance() >= 1.0 {
            return Some("Kd has mean 1; the reflectance must be below 1".to_string());
        }
        if let Some(v) = self.ke.iter().find(|v| !(v.is_finite() && **v >= 0.0)) {
            return Some(format!("Ke has a channel that is negative or not finite ({v})"));
        }
        None
    }
}

/// What is wrong with the vertices of a polygon. Vertices are numbered from 0 in their order.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PolygonProblem {
    #[error("has {count} vertices; a polygon needs at least 3")]
    TooFewVertices { count: usize },
    #[error("vertex {vertex} has a non-finite coordinate ({value})")]
    NonFinite { vertex: usize, value: f64 },
    #[error("vertex {vertex} has a coordinate of magnitude above {COORD_LIMIT:e} ({value:e})")]
    TooLarge { vertex: usize, value: f64 },
    #[error("vertices {first} and {second} are the same point (repeated vertex)")]
    RepeatedVertex { first: usize, second: usize },
    #[error("is degenerate: zero area (its vertices are collinear)")]
    ZeroArea,
    #[error(
        "is not planar: vertex {vertex} lies {distance:.3e} from the polygon's plane \
         (tolerance {tolerance:.3e}, {PLANARITY_TOLERANCE:e} of its size)"
    )]
    NonPlanar { vertex: usize, distance: f64, tolerance: f64 },
    #[error("is not convex: it turns the wrong way at vertex {vertex}")]
    NonConvex { vertex: usize },
    #[error("is not convex: its boundary winds {turns:.3} times around it (a convex polygon winds once)")]
    SelfIntersecting { turns: f64 },
}

/// A convex planar polygon with its material values: Def. 2.1's `P = {Vᵢ, O, n}`.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon {
    /// The vertices, counter-clockwise seen from the front.
    pub vertices: Vec<DVec3>,
    /// The centre point `O`: the mean of the vertices.
    pub centre: DVec3,
    /// The unit normal, pointing to the front side.
    pub normal: DVec3,
    /// The area.
    pub area: f64,
    /// The diagonal of the axis-aligned bounding box: the scale of the tolerances.
    pub size: f64,
    /// The index of the material in [`Scene3::materials`].
    pub material: usize,
    /// The material's reflectance ([`Material3::reflectance`]).
    pub reflectance: f64,
    /// The material's emission ([`Material3::emission`]).
    pub emission: f64,
}

impl Polygon {
    /// The polygon on `vertices`, checked as the module docs say, with material index 0 and
    /// reflectance and emission 0 (see [`Polygon::with_material`]).
    pub fn new(vertices: Vec<DVec3>) -> Result<Polygon, PolygonProblem> {
        let n = vertices.len();
        if n < 3 {
            return Err(PolygonProblem::TooFewVertices { count: n });
        }
        for (i, v) in vertices.iter().enumerate() {
            if let Some(&value) = v.to_array().iter().find(|c| !c.is_finite()) {
                return Err(PolygonProblem::NonFinite { vertex: i, value });
            }
            if let Some(&value) = v.to_array().iter().find(|c| c.abs() > COORD_LIMIT) {
                return Err(PolygonProblem::TooLarge { vertex: i, value });
            }
        }
        let (lo, hi) =
            vertices.iter().fold((vertices[0], vertices[0]), |(lo, hi), v| (lo.min(*v), hi.max(*v)));
        let size = (hi - lo).length();
        for i in 0..n {
            for j in i + 1..n {
                if (vertices[i] - vertices[j]).length() <= REPEAT_TOLERANCE * size {
                    return Err(PolygonProblem::RepeatedVertex { first: i, second: j });
                }
            }
        }
        // Newell's method about the centre: twice the vector area.
        let centre = vertices.iter().sum::<DVec3>() / n as f64;
        let twice_area: DVec3 =
            (0..n).map(|i| (vertices[i] - centre).cross(vertices[(i + 1) % n] - centre)).sum();
        let area = 0.5 * twice_area.length();
        if area.is_nan() || area <= AREA_TOLERANCE * size * size {
            return Err(PolygonProblem::ZeroArea);
        }
        let normal = twice_area / twice_area.length();
        // Check every vertex against the plane through the centre.
        let tolerance = PLANARITY_TOLERANCE * size;
        for (i, v) in vertices.iter().enumerate() {
            let distance = (*v - centre).dot(normal).abs();
            if distance > tolerance {
                return Err(PolygonProblem::NonPlanar { vertex: i, distance, tolerance });
            }
        }
        // Check every turn seen from the front, and that the boundary winds once.
        let mut turning = 0.0;
        for i in 0..n {
            let e0 = vertices[i] - vertices[(i + n - 1) % n];
            let e1 = vertices[(i + 1) % n] - vertices[i];
            let cross = e0.cross(e1).dot(normal);
            if cross < -CONVEXITY_TOLERANCE * size * size {
                return Err(PolygonProblem::NonConvex { vertex: i });
            }
            turning += cross.atan2(e0.dot(e1));
        }
        let turns = turning / std::f64::consts::TAU;
        if (turns - 1.0).abs() > 1e-6 {
            return Err(PolygonProblem::SelfIntersecting { turns });
        }
        Ok(Polygon { vertices, centre, normal, area, size, material: 0, reflectance: 0.0, emission: 0.0 })
    }

    /// The polygon with material `index`, whose values are `material`'s.
    pub fn with_material(mut self, index: usize, material: &Material3) -> Polygon {
        self.material = index;
        self.reflectance = material.reflectance();
        self.emission = material.emission();
        self
    }
}

/// A 3D scene: the polygons and the materials they use.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene3 {
    /// The patches, in order; a polygon's index is its position.
    pub polygons: Vec<Polygon>,
    /// The materials, in order; [`Polygon::material`] indexes this list.
    pub materials: Vec<Material3>,
}

impl Scene3 {
    /// The axis-aligned bounding box of every vertex, `(min, max)`.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        let first = self.polygons.first().map_or(DVec3::ZERO, |p| p.vertices[0]);
        self.polygons
            .iter()
            .flat_map(|p| p.vertices.iter())
            .fold((first, first), |(lo, hi), v| (lo.min(*v), hi.max(*v)))
    }

    /// The edges `(from, to)` not matched by the reverse edge `(to, from)` of another polygon,
    /// comparing vertex positions exactly, in polygon and then vertex order. A closed surface
    /// with consistent orientation (every front facing the same side) has none; an edge used
    /// twice in the same direction (a flipped neighbour) is reported too.
    pub fn open_edges(&self) -> Vec<(DVec3, DVec3)> {
        let key = |v: DVec3| [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()];
        let mut count: HashMap<([u64; 3], [u64; 3]), i64> = HashMap::new();
        let edges = || {
            self.polygons.iter().flat_map(|p| {
                let n = p.vertices.len();
                (0..n).map(move |i| (p.vertices[i], p.vertices[(i + 1) % n]))
            })
        };
        for (a, b) in edges() {
            *count.entry((key(a), key(b))).or_default() += 1;
        }
        edges().filter(|(a, b)| count.get(&(key(*b), key(*a))).copied().unwrap_or(0) != 1).collect()
    }
}

/// Where a face is: its index among the polygons, and the line of the file when there is one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FaceAt {
    /// The face's position among the faces, counted from 0.
    pub index: usize,
    /// The line of the OBJ file, counted from 1.
    pub line: Option<usize>,
}

impl fmt::Display for FaceAt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(line) => write!(f, "face {} (line {line})", self.index),
            None => write!(f, "face {}", self.index),
        }
    }
}

/// Everything that can go wrong reading, writing or generating a 3D scene. Every message starts
/// with the file's name (`generator` for the generator) and names the face where there is one.
#[derive(Debug, thiserror::Error)]
pub enum Scene3Error {
    /// The file could not be read or written.
    #[error("{name}: cannot {action} the file: {source}")]
    Io {
        name: String,
        /// `"read"` or `"write"`.
        action: &'static str,
        #[source]
        source: std::io::Error,
    },
    /// The file is longer than the limit (256 MiB, as for the 2D scenes).
    #[error("{name}: the file is larger than {limit} bytes, the limit for a scene file")]
    TooLarge { name: String, limit: u64 },
    /// The OBJ text is malformed (the `tobj` reader's message, or a line this loader checks).
    #[error("{name}: malformed OBJ{}: {message}", line.map(|l| format!(" at line {l}")).unwrap_or_default())]
    Malformed { name: String, line: Option<usize>, message: String },
    /// A face has invalid geometry.
    #[error("{name}: {face} {problem}")]
    BadFace { name: String, face: FaceAt, problem: PolygonProblem },
    /// The file has faces but no `mtllib` line.
    #[error("{name}: no material library (the file has no mtllib line)")]
    NoMaterialLibrary { name: String },
    /// A material library named by `mtllib` cannot be read.
    #[error("{name}: cannot read the material library {library}: {source}")]
    MaterialLibrary {
        name: String,
        library: String,
        #[source]
        source: std::io::Error,
    },
    /// A material library is malformed.
    #[error("{name}: malformed material library {library}{}: {message}", line.map(|l| format!(" at line {l}")).unwrap_or_default())]
    MalformedMaterialLibrary { name: String, library: String, line: Option<usize>, message: String },
    /// A face comes before any `usemtl` line.
    #[error("{name}: {face} has no material (no usemtl line before it)")]
    NoMaterial { name: String, face: FaceAt },
    /// A face's `usemtl` names a material no library defines.
    #[error("{name}: {face} uses material \"{material}\", which no material library defines")]
    UnknownMaterial { name: String, face: FaceAt, material: String },
    /// A material's values cannot be a patch's.
    #[error("{name}: material \"{material}\": {problem}")]
    BadMaterial { name: String, material: String, problem: String },
    /// The file has no faces.
    #[error("{name}: the scene is empty (no faces)")]
    Empty { name: String },
    /// More polygons than [`MAX_POLYGONS`].
    #[error("{name}: {count} faces, more than the limit of {MAX_POLYGONS}")]
    TooManyPolygons { name: String, count: usize },
    /// A generator's parameter is out of range.
    #[error("{name}: {what} must be {range}, got {value}")]
    BadParameter { name: String, what: &'static str, range: String, value: String },
    /// The generator could not place a patch inside the world.
    #[error("{name}: could not place patch {patch} inside the world in {attempts} attempts")]
    GeneratorStalled { name: String, patch: usize, attempts: u64 },
}

/// An orthonormal tangent frame `(t, b)` with `t × b = n` for the unit vector `n`: Duff et al.,
/// "Building an Orthonormal Basis, Revisited" (JCGT 2017), branchless and continuous except at
/// `n.z = −1`'s sign flip. A function of `n` alone, so every caller gets the same frame.
pub fn frame(n: DVec3) -> (DVec3, DVec3) {
    let sign = 1.0f64.copysign(n.z);
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    (DVec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x), DVec3::new(b, sign + n.y * n.y * a, -n.y))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_is_orthonormal_and_right_handed_for_every_normal() {
        let mut normals = vec![DVec3::Z, DVec3::NEG_Z, DVec3::X, DVec3::NEG_Y, DVec3::new(1e-300, 0.0, -1.0)];
        for i in 0..100 {
            let a = i as f64 * 0.7;
            normals.push(DVec3::new(a.cos() * (a * 0.3).sin(), a.sin() * (a * 0.3).sin(), (a * 0.3).cos()));
        }
        for n in normals {
            let n = n.normalize();
            let (t, b) = frame(n);
            assert!((t.length() - 1.0).abs() < 1e-12 && (b.length() - 1.0).abs() < 1e-12, "{n}");
            assert!(t.dot(b).abs() < 1e-12 && t.dot(n).abs() < 1e-12 && b.dot(n).abs() < 1e-12, "{n}");
            assert!((t.cross(b) - n).length() < 1e-12, "{n}");
        }
    }

    #[test]
    fn face_locations_print_with_and_without_a_line() {
        assert_eq!(FaceAt { index: 3, line: Some(9) }.to_string(), "face 3 (line 9)");
        assert_eq!(FaceAt { index: 3, line: None }.to_string(), "face 3");
    }

    #[test]
    fn a_clockwise_polygon_is_valid_and_faces_the_other_way() {
        let ccw = vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0)];
        let cw: Vec<DVec3> = ccw.iter().rev().copied().collect();
        assert_eq!(Polygon::new(ccw).unwrap().normal, DVec3::Z);
        assert_eq!(Polygon::new(cw).unwrap().normal, DVec3::NEG_Z);
    }

    #[test]
    fn material_means_and_problems() {
        let m = Material3 { name: "m".into(), kd: [0.3, 0.6, 0.9], ke: [0.0, 3.0, 0.0] };
        assert!((m.reflectance() - 0.6).abs() < 1e-15);
        assert_eq!(m.emission(), 1.0);
        assert_eq!(m.problem(), None);
        assert!(Material3::grey("g", 1.0, 0.0).problem().is_some());
    }
}
