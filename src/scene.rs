//! Scenes: the versioned JSON scene format, its loader and writer, and the random scene
//! generator of the paper's experiments.
//!
//! # The scene format, version 1
//!
//! A scene file is one JSON object:
//!
//! ```json
//! {
//!   "version": 1,
//!   "world": {"min": [0, 0], "max": [1024, 1024]},
//!   "segments": [
//!     {"a": [100, 200], "b": [300, 200], "reflectance": 0.5, "emission": 0.0},
//!     {"a": [500, 500], "b": [500, 700]}
//!   ]
//! }
//! ```
//!
//! The smallest accepted file names only the segments:
//!
//! ```json
//! {"segments": [{"a": [100, 200], "b": [300, 200]}]}
//! ```
//!
//! | field | required | meaning |
//! |---|---|---|
//! | `version` | no, defaults to 1 | The format version. Only `1` is accepted. |
//! | `world` | no | The world box `{"min": [x, y], "max": [x, y]}`: the half-open box `min ≤ p < max`. Every endpoint of every segment must lie inside it. `min` must be less than `max` in both coordinates. |
//! | `segments` | yes, non-empty | The patches of the scene, in order; a segment's index is its position in this array, counted from 0. |
//! | `segments[i].a`, `segments[i].b` | yes | The endpoints, each an array of exactly two numbers `[x, y]`. |
//! | `segments[i].reflectance` | no | A number in `[0, 1]`. |
//! | `segments[i].emission` | no | A number `≥ 0`. |
//!
//! * A segment `a → b` is one-sided: its front side lies to the left of `a → b`, and its normal is
//!   `(b − a)` rotated by +90° and normalised. Reverse the endpoints to flip a patch.
//! * Every number must be finite. `NaN`, `Infinity`, `inf` and numbers too large for an `f64`
//!   (such as `1e400`) are reported as non-finite values of the segment and field that hold them.
//! * Every coordinate must have magnitude at most [`COORD_LIMIT`] (10⁹).
//! * A segment must have non-zero length.
//! * Unknown fields are errors, at the top level, in the world and in a segment, so that a typo
//!   such as `"segmnets"` or `"reflectence"` is reported instead of silently ignored. A field
//!   given twice in the same object is an error too.
//! * An optional field is either omitted or given a value of its type; `null` is not accepted.
//!
//! Every error names the file, the segment where there is one, and the problem in plain words,
//! for example `scene.json: segment 17: endpoint a has a non-finite coordinate (NaN)`. See
//! [`SceneError`] for the full list.
//!
//! [`Scene::to_json`] writes the same format, always with `"version"`, one segment per line. It
//! prints each number in the shortest form that reads back to the same `f64`, and the loader
//! parses numbers with correct rounding, so a written scene loads back bit for bit.
//!
//! # The random scene generator
//!
//! [`generate`] places `count` segments of one given length uniformly at random in a world box:
//! for each segment it draws a midpoint uniformly in the world and a direction uniformly on the
//! circle, and draws again until both endpoints lie inside the world. The random numbers come
//! from ChaCha8 seeded with [`rand::SeedableRng::seed_from_u64`], and the geometry uses only
//! correctly rounded arithmetic (no trigonometry), so a seed gives the same scene on every run
//! and every platform.

use std::cell::Cell;
use std::collections::HashSet;
use std::fmt;
use std::path::Path;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};

use crate::geom::{Segment, Vec2};

/// The scene format version this module reads and writes.
pub const SCENE_VERSION: u32 = 1;

/// Largest accepted coordinate magnitude.
pub const COORD_LIMIT: f64 = 1.0e9;

/// Largest accepted number of segments: segment indices must fit in a `u32`.
pub const MAX_SEGMENTS: usize = u32::MAX as usize;

/// The world of the paper's experiments: the half-open square `[0, 1024)²`.
pub const PAPER_WORLD: Bounds = Bounds { min: Vec2::new(0.0, 0.0), max: Vec2::new(1024.0, 1024.0) };

/// The name that errors of [`Scene::new`] carry in place of a file name.
const MEMORY_NAME: &str = "<memory>";

/// The name that errors of [`generate`] carry in place of a file name.
const GENERATOR_NAME: &str = "generator";

/// How many placements [`generate`] tries for one segment before it gives up. With a length
/// shorter than the world's shorter side at least a few percent of the tries succeed, so this is
/// reached only when the world is too small for the precision of `f64`.
const MAX_ATTEMPTS: u64 = 1_000_000;

/// An axis-aligned box of the plane.
///
/// As a scene's world it is the half-open box `min ≤ p < max`; see [`Bounds::contains`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    pub min: Vec2,
    pub max: Vec2,
}

impl Bounds {
    /// The box from `min` to `max`.
    pub const fn new(min: Vec2, max: Vec2) -> Self {
        Bounds { min, max }
    }

    /// Whether `p` lies in the half-open box: `min.x ≤ p.x < max.x` and `min.y ≤ p.y < max.y`.
    pub fn contains(&self, p: Vec2) -> bool {
        self.min.x <= p.x && p.x < self.max.x && self.min.y <= p.y && p.y < self.max.y
    }

    /// The width and height of the box.
    pub fn size(&self) -> Vec2 {
        self.max - self.min
    }
}

impl fmt::Display for Bounds {
    /// Writes the box as `[0, 0]..[1024, 1024]`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}..{}", point_text(&self.min), point_text(&self.max))
    }
}

/// The reflectance of a segment whose file gives none.
pub const DEFAULT_REFLECTANCE: f64 = 0.5;

/// The emission of a segment whose file gives none.
pub const DEFAULT_EMISSION: f64 = 0.0;

/// The optional surface properties of one segment. `None` means the file did not give the value;
/// what a missing value means is up to the consumer of the scene.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Material {
    /// The fraction of incoming light the patch reflects, in `[0, 1]`.
    pub reflectance: Option<f64>,
    /// The light the patch emits, `≥ 0`.
    pub emission: Option<f64>,
}

impl Material {
    /// The reflectance, or [`DEFAULT_REFLECTANCE`] where the file gives none.
    pub fn reflectance_or_default(&self) -> f64 {
        self.reflectance.unwrap_or(DEFAULT_REFLECTANCE)
    }

    /// The emission, or [`DEFAULT_EMISSION`] where the file gives none.
    pub fn emission_or_default(&self) -> f64 {
        self.emission.unwrap_or(DEFAULT_EMISSION)
    }
}

/// A 2D scene: one-sided segments, their materials and an optional world box.
///
/// `materials[i]` belongs to `segments[i]`. Scenes built by this module always have one material
/// per segment; where `materials` is shorter, the missing entries count as
/// [`Material::default`], and entries beyond the last segment are ignored.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    pub segments: Vec<Segment>,
    pub materials: Vec<Material>,
    pub world: Option<Bounds>,
}

/// Where in a scene a problem was found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Location {
    /// The top-level object of the scene.
    Top,
    /// The `world` object.
    World,
    /// The segment with this index.
    Segment(usize),
}

impl Location {
    /// The segment index, where the location is a segment.
    pub fn segment(&self) -> Option<usize> {
        match self {
            Location::Segment(i) => Some(*i),
            _ => None,
        }
    }
}

impl fmt::Display for Location {
    /// Writes the prefix that error messages put before the problem: nothing, `world: ` or
    /// `segment 3: `.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Location::Top => Ok(()),
            Location::World => f.write_str("world: "),
            Location::Segment(i) => write!(f, "segment {i}: "),
        }
    }
}

/// Why a scene could not be loaded, validated, saved or generated.
///
/// Every message starts with the name of the file (or `<memory>` for [`Scene::new`] and
/// `generator` for [`generate`]), names the segment where there is one, and says what is wrong.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The file could not be read or written.
    #[error("{name}: cannot {action} the file: {source}")]
    Io {
        name: String,
        /// `"read"` or `"write"`.
        action: &'static str,
        #[source]
        source: std::io::Error,
    },

    /// The text is not valid JSON (or not valid UTF-8).
    #[error("{name}: malformed JSON at line {line} column {column}: {message}")]
    Malformed { name: String, line: usize, column: usize, message: String },

    /// The text ends in the middle of a JSON value: the file looks truncated.
    #[error(
        "{name}: the JSON ends unexpectedly at line {line} column {column} \
         (is the file truncated?): {message}"
    )]
    Truncated { name: String, line: usize, column: usize, message: String },

    /// The `version` field is not 1.
    #[error(
        "{name}: unsupported scene format version {found} \
         (this program reads version {SCENE_VERSION})"
    )]
    UnsupportedVersion { name: String, found: String },

    /// An object has a field the format does not define (often a typo).
    #[error("{name}: {location}unknown field \"{field}\" (allowed fields: {allowed})")]
    UnknownField { name: String, location: Location, field: String, allowed: &'static str },

    /// A required field is missing.
    #[error("{name}: {location}missing required field \"{field}\"")]
    MissingField { name: String, location: Location, field: &'static str },

    /// A value has the wrong JSON type, such as a string where a coordinate belongs.
    #[error("{name}: {location}{what} must be {expected}, found {found}")]
    WrongType { name: String, location: Location, what: String, expected: &'static str, found: String },

    /// A point is an array, but not of exactly two elements.
    #[error("{name}: {location}{point} must have exactly 2 coordinates [x, y], found {count}")]
    BadPoint {
        name: String,
        location: Location,
        /// `"endpoint a"`, `"endpoint b"`, `"min"` or `"max"`.
        point: &'static str,
        count: usize,
    },

    /// A coordinate is NaN, infinite or too large for an `f64`.
    #[error("{name}: {location}{point} has a non-finite coordinate ({token})")]
    NonFiniteCoordinate {
        name: String,
        location: Location,
        point: &'static str,
        /// The offending token as written in the file, such as `NaN` or `1e400`.
        token: String,
    },

    /// A coordinate's magnitude exceeds [`COORD_LIMIT`].
    #[error(
        "{name}: {location}coordinate {} of {point} exceeds the limit {}",
        number_text(.value),
        number_text(&COORD_LIMIT)
    )]
    CoordinateLimit { name: String, location: Location, point: &'static str, value: f64 },

    /// A segment's endpoints coincide (or are too close for its direction to be computed).
    #[error("{name}: segment {segment} has zero length ({})", zero_length_text(.a, .b))]
    ZeroLength { name: String, segment: usize, a: Vec2, b: Vec2 },

    /// The scene has no segments (or the generator was asked for none).
    #[error("{name}: the scene has no segments")]
    NoSegments { name: String },

    /// The scene has more than [`MAX_SEGMENTS`] segments.
    #[error("{name}: the scene has {count} segments, more than the limit {MAX_SEGMENTS}")]
    TooManySegments { name: String, count: usize },

    /// The world box is empty: `min` is not less than `max` in both coordinates.
    #[error(
        "{name}: the world {}..{} is empty: min must be less than max in both coordinates",
        point_text(.min),
        point_text(.max)
    )]
    InvalidWorld { name: String, min: Vec2, max: Vec2 },

    /// An endpoint of a segment lies outside the world.
    #[error(
        "{name}: segment {segment} lies outside the world {world}: {point} = {} \
         (the world includes min and excludes max)",
        point_text(.at)
    )]
    OutsideWorld {
        name: String,
        segment: usize,
        /// `"endpoint a"` or `"endpoint b"`.
        point: &'static str,
        at: Vec2,
        world: Bounds,
    },

    /// A material value is out of its range or not finite.
    #[error("{name}: segment {segment}: {field} {value} must be {rule}")]
    BadMaterial {
        name: String,
        segment: usize,
        /// `"reflectance"` or `"emission"`.
        field: &'static str,
        /// The value as written, such as `1.5` or `NaN`.
        value: String,
        /// The rule it breaks, such as `a finite number in [0, 1]`.
        rule: &'static str,
    },

    /// The generator was asked for a segment length that is not finite, not positive, or not
    /// shorter than the world's shorter side.
    #[error(
        "{name}: segment length {} must be finite, greater than 0 and less than {} \
         (the shorter side of the world)",
        number_text(.length),
        number_text(.limit)
    )]
    InvalidLength { name: String, length: f64, limit: f64 },

    /// The generator could not place a segment inside the world, which happens only when the
    /// world is too small for the precision of `f64`.
    #[error(
        "{name}: could not place segment {segment} of length {} inside the world {world} \
         after {attempts} attempts (the world is too small for the precision of f64)",
        number_text(.length)
    )]
    GeneratorStalled { name: String, segment: usize, length: f64, world: Bounds, attempts: u64 },
}

impl SceneError {
    /// The file name (or `<memory>`, `generator`) the error names.
    pub fn name(&self) -> &str {
        match self {
            SceneError::Io { name, .. }
            | SceneError::Malformed { name, .. }
            | SceneError::Truncated { name, .. }
            | SceneError::UnsupportedVersion { name, .. }
            | SceneError::UnknownField { name, .. }
            | SceneError::MissingField { name, .. }
            | SceneError::WrongType { name, .. }
            | SceneError::BadPoint { name, .. }
            | SceneError::NonFiniteCoordinate { name, .. }
            | SceneError::CoordinateLimit { name, .. }
            | SceneError::ZeroLength { name, .. }
            | SceneError::NoSegments { name }
            | SceneError::TooManySegments { name, .. }
            | SceneError::InvalidWorld { name, .. }
            | SceneError::OutsideWorld { name, .. }
            | SceneError::BadMaterial { name, .. }
            | SceneError::InvalidLength { name, .. }
            | SceneError::GeneratorStalled { name, .. } => name,
        }
    }

    /// The index of the segment the error is about, where there is one.
    pub fn segment(&self) -> Option<usize> {
        match self {
            SceneError::UnknownField { location, .. }
            | SceneError::MissingField { location, .. }
            | SceneError::WrongType { location, .. }
            | SceneError::BadPoint { location, .. }
            | SceneError::NonFiniteCoordinate { location, .. }
            | SceneError::CoordinateLimit { location, .. } => location.segment(),
            SceneError::ZeroLength { segment, .. }
            | SceneError::OutsideWorld { segment, .. }
            | SceneError::BadMaterial { segment, .. }
            | SceneError::GeneratorStalled { segment, .. } => Some(*segment),
            _ => None,
        }
    }
}

impl Scene {
    /// A scene of the given segments, with default materials and no world, validated like a
    /// loaded file. Errors carry the name `<memory>`.
    pub fn new(segments: Vec<Segment>) -> Result<Scene, SceneError> {
        let scene = Scene { materials: vec![Material::default(); segments.len()], segments, world: None };
        scene.validate(MEMORY_NAME)?;
        Ok(scene)
    }

    /// Parses a scene from JSON text. `name` is the file name that errors carry.
    pub fn from_json_str(text: &str, name: &str) -> Result<Scene, SceneError> {
        let root = parse_json(text, name)?;
        Reader { name }.scene(&root)
    }

    /// Reads and parses a scene file. Errors carry the path as given.
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        let name = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|source| SceneError::Io {
            name: name.clone(),
            action: "read",
            source,
        })?;
        let text = match String::from_utf8(bytes) {
            Ok(text) => text,
            Err(err) => {
                let valid = &err.as_bytes()[..err.utf8_error().valid_up_to()];
                let (line, column) = line_column(valid);
                return Err(SceneError::Malformed {
                    name,
                    line,
                    column,
                    message: "the file is not valid UTF-8 text".to_string(),
                });
            }
        };
        Scene::from_json_str(&text, &name)
    }

    /// The scene as pretty JSON in the current format version, one segment per line, ending with
    /// a newline. Optional fields are written only where they are set. Numbers are written in
    /// the shortest form that parses back to the same `f64`, so loading the text gives back an
    /// equal scene. (A non-finite number, which a valid scene cannot hold, is written as `NaN`,
    /// `Infinity` or `-Infinity`, which the loader reports as an error.)
    pub fn to_json(&self) -> String {
        let mut out = String::new();
        out.push_str("{\n");
        out.push_str(&format!("  \"version\": {SCENE_VERSION},\n"));
        if let Some(world) = &self.world {
            out.push_str(&format!(
                "  \"world\": {{\"min\": {}, \"max\": {}}},\n",
                json_point(world.min),
                json_point(world.max)
            ));
        }
        if self.segments.is_empty() {
            out.push_str("  \"segments\": []\n");
        } else {
            out.push_str("  \"segments\": [\n");
            for (i, seg) in self.segments.iter().enumerate() {
                out.push_str(&format!("    {{\"a\": {}, \"b\": {}", json_point(seg.a), json_point(seg.b)));
                let material = self.material(i);
                if let Some(r) = material.reflectance {
                    out.push_str(&format!(", \"reflectance\": {}", json_number(r)));
                }
                if let Some(e) = material.emission {
                    out.push_str(&format!(", \"emission\": {}", json_number(e)));
                }
                out.push('}');
                if i + 1 < self.segments.len() {
                    out.push(',');
                }
                out.push('\n');
            }
            out.push_str("  ]\n");
        }
        out.push_str("}\n");
        out
    }

    /// Writes the scene to a file as [`Scene::to_json`]. The scene is validated first, so every
    /// saved file loads back; errors carry the path as given.
    pub fn save(&self, path: &Path) -> Result<(), SceneError> {
        let name = path.display().to_string();
        self.validate(&name)?;
        std::fs::write(path, self.to_json()).map_err(|source| SceneError::Io {
            name,
            action: "write",
            source,
        })
    }

    /// The number of segments.
    pub fn len(&self) -> usize {
        self.segments.len()
    }

    /// Whether the scene has no segments (which a validated scene never has).
    pub fn is_empty(&self) -> bool {
        self.segments.is_empty()
    }

    /// The material of segment `i`: `materials[i]`, or the default where there is none.
    pub fn material(&self, i: usize) -> Material {
        self.materials.get(i).copied().unwrap_or_default()
    }

    /// The world if given, else the bounding box of the segments (the smallest closed box that
    /// holds every endpoint). A scene with neither world nor segments gives the empty box at the
    /// origin.
    pub fn bounds(&self) -> Bounds {
        if let Some(world) = self.world {
            return world;
        }
        let mut points = self.segments.iter().flat_map(|s| [s.a, s.b]);
        match points.next() {
            None => Bounds::new(Vec2::ZERO, Vec2::ZERO),
            Some(first) => {
                let (min, max) = points.fold((first, first), |(lo, hi), p| (lo.min(p), hi.max(p)));
                Bounds::new(min, max)
            }
        }
    }

    /// Checks the rules of the format: at least one and at most [`MAX_SEGMENTS`] segments, a
    /// valid world, finite coordinates within [`COORD_LIMIT`], non-zero lengths, endpoints inside
    /// the world, and materials in range. `name` is the name that errors carry.
    pub fn validate(&self, name: &str) -> Result<(), SceneError> {
        if self.segments.is_empty() {
            return Err(SceneError::NoSegments { name: name.to_string() });
        }
        if self.segments.len() > MAX_SEGMENTS {
            return Err(SceneError::TooManySegments { name: name.to_string(), count: self.segments.len() });
        }
        if let Some(world) = &self.world {
            check_world(name, world)?;
        }
        for (i, seg) in self.segments.iter().enumerate() {
            check_segment(name, i, seg, self.world.as_ref())?;
            check_material(name, i, &self.material(i))?;
        }
        Ok(())
    }
}

/// Generates `count` random segments of length `length` with both endpoints inside `world`.
///
/// Each segment gets a midpoint drawn uniformly in the world and a direction drawn uniformly on
/// the circle (by rejection from the square, so no trigonometry is involved), and is drawn again
/// until both endpoints lie inside the world. The result is a function of the arguments alone,
/// on every platform. Errors carry the name `generator`: `count` is 0 or above
/// [`MAX_SEGMENTS`], `world` is not a valid world, or `length` is not finite, not positive, or
/// not shorter than the shorter side of the world.
pub fn generate(count: usize, length: f64, seed: u64, world: Bounds) -> Result<Scene, SceneError> {
    let name = GENERATOR_NAME;
    check_world(name, &world)?;
    if count == 0 {
        return Err(SceneError::NoSegments { name: name.to_string() });
    }
    if count > MAX_SEGMENTS {
        return Err(SceneError::TooManySegments { name: name.to_string(), count });
    }
    let size = world.size();
    let limit = size.x.min(size.y);
    if !(length.is_finite() && length > 0.0 && length < limit) {
        return Err(SceneError::InvalidLength { name: name.to_string(), length, limit });
    }

    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let half = 0.5 * length;
    let mut segments = Vec::with_capacity(count.min(1 << 20));
    for index in 0..count {
        let mut attempts = 0;
        let segment = loop {
            if attempts == MAX_ATTEMPTS {
                return Err(SceneError::GeneratorStalled {
                    name: name.to_string(),
                    segment: index,
                    length,
                    world,
                    attempts,
                });
            }
            attempts += 1;
            // Four draws per attempt, used or not, so the stream stays simple to reason about.
            let mx = world.min.x + size.x * rng.random::<f64>();
            let my = world.min.y + size.y * rng.random::<f64>();
            let dx = 2.0 * rng.random::<f64>() - 1.0;
            let dy = 2.0 * rng.random::<f64>() - 1.0;
            // A point uniform in the unit disk (away from its centre, where normalising would
            // lose precision) gives a direction uniform on the circle.
            let r2 = dx * dx + dy * dy;
            if !(r2 > 1e-6 && r2 <= 1.0) {
                continue;
            }
            let r = r2.sqrt();
            let (ux, uy) = (dx / r, dy / r);
            let a = Vec2::new(mx - ux * half, my - uy * half);
            let b = Vec2::new(mx + ux * half, my + uy * half);
            let seg = Segment::new(a, b);
            // The length test fails only in worlds too small for f64 to place the endpoints.
            if world.contains(a) && world.contains(b) && (seg.length() - length).abs() <= 1e-9 * length {
                break seg;
            }
        };
        segments.push(segment);
    }
    Ok(Scene { materials: vec![Material::default(); segments.len()], segments, world: Some(world) })
}

// ---------------------------------------------------------------------------------------------
// Validation shared by the loader, `Scene::new`, `Scene::save` and the generator.
// ---------------------------------------------------------------------------------------------

/// Checks one coordinate: finite and within [`COORD_LIMIT`].
fn check_coordinate(
    name: &str,
    location: Location,
    point: &'static str,
    value: f64,
) -> Result<(), SceneError> {
    if !value.is_finite() {
        return Err(SceneError::NonFiniteCoordinate {
            name: name.to_string(),
            location,
            point,
            token: number_text(&value),
        });
    }
    if value.abs() > COORD_LIMIT {
        return Err(SceneError::CoordinateLimit { name: name.to_string(), location, point, value });
    }
    Ok(())
}

/// Checks a point: both coordinates finite and within [`COORD_LIMIT`].
fn check_point(name: &str, location: Location, point: &'static str, p: Vec2) -> Result<(), SceneError> {
    check_coordinate(name, location, point, p.x)?;
    check_coordinate(name, location, point, p.y)
}

/// Checks a world box: valid corners, and `min < max` in both coordinates.
fn check_world(name: &str, world: &Bounds) -> Result<(), SceneError> {
    check_point(name, Location::World, "min", world.min)?;
    check_point(name, Location::World, "max", world.max)?;
    if !(world.min.x < world.max.x && world.min.y < world.max.y) {
        return Err(SceneError::InvalidWorld { name: name.to_string(), min: world.min, max: world.max });
    }
    Ok(())
}

/// Checks one segment: valid endpoints, a non-zero length, and endpoints inside the world.
fn check_segment(name: &str, index: usize, seg: &Segment, world: Option<&Bounds>) -> Result<(), SceneError> {
    let location = Location::Segment(index);
    check_point(name, location, "endpoint a", seg.a)?;
    check_point(name, location, "endpoint b", seg.b)?;
    // A length that rounds to zero leaves the normal undefined, so it counts as zero too.
    if !(seg.length() > 0.0 && seg.normal().is_finite()) {
        return Err(SceneError::ZeroLength { name: name.to_string(), segment: index, a: seg.a, b: seg.b });
    }
    if let Some(world) = world {
        for (point, at) in [("endpoint a", seg.a), ("endpoint b", seg.b)] {
            if !world.contains(at) {
                return Err(SceneError::OutsideWorld {
                    name: name.to_string(),
                    segment: index,
                    point,
                    at,
                    world: *world,
                });
            }
        }
    }
    Ok(())
}

/// Checks the material of one segment against the ranges of the format.
fn check_material(name: &str, index: usize, material: &Material) -> Result<(), SceneError> {
    if let Some(r) = material.reflectance {
        if !(r.is_finite() && (0.0..=1.0).contains(&r)) {
            return Err(bad_material(name, index, "reflectance", number_text(&r)));
        }
    }
    if let Some(e) = material.emission {
        if !(e.is_finite() && e >= 0.0) {
            return Err(bad_material(name, index, "emission", number_text(&e)));
        }
    }
    Ok(())
}

/// The error for a material value outside its range; `value` is the value as written.
fn bad_material(name: &str, index: usize, field: &'static str, value: String) -> SceneError {
    let rule = if field == "reflectance" { "a finite number in [0, 1]" } else { "a finite number >= 0" };
    SceneError::BadMaterial { name: name.to_string(), segment: index, field, value, rule }
}

// ---------------------------------------------------------------------------------------------
// Text formatting for messages and for the writer.
// ---------------------------------------------------------------------------------------------

/// A number for an error message: plain for ordinary magnitudes (`5`, `0.25`), scientific for
/// very large or small ones (`3e12`, `1e9`), and `NaN`, `inf` or `-inf` when not finite.
fn number_text(x: &f64) -> String {
    let a = x.abs();
    if x.is_finite() && a != 0.0 && !(1e-4..1e7).contains(&a) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// A point for an error message: `[5, 5]`.
fn point_text(p: &Vec2) -> String {
    format!("[{}, {}]", number_text(&p.x), number_text(&p.y))
}

/// The detail of a zero-length message: `a = b = [5, 5]`, or both points when they differ but
/// are too close together.
fn zero_length_text(a: &Vec2, b: &Vec2) -> String {
    if a == b {
        format!("a = b = {}", point_text(a))
    } else {
        format!("a = {} and b = {} are too close together", point_text(a), point_text(b))
    }
}

/// A number for the JSON writer: the shortest text that parses back to the same `f64`.
fn json_number(x: f64) -> String {
    match serde_json::Number::from_f64(x) {
        Some(n) => n.to_string(),
        None if x.is_nan() => "NaN".to_string(),
        None if x > 0.0 => "Infinity".to_string(),
        None => "-Infinity".to_string(),
    }
}

/// A point for the JSON writer: `[1.0, 2.5]`.
fn json_point(p: Vec2) -> String {
    format!("[{}, {}]", json_number(p.x), json_number(p.y))
}

/// The 1-based line and column just after `text`, counting columns in bytes like serde_json.
fn line_column(text: &[u8]) -> (usize, usize) {
    let line = 1 + text.iter().filter(|&&c| c == b'\n').count();
    let start = text.iter().rposition(|&c| c == b'\n').map_or(0, |newline| newline + 1);
    (line, text.len() - start + 1)
}

// ---------------------------------------------------------------------------------------------
// The JSON layer: a pre-pass over the text, and a parse into a small tree that keeps document
// order and rejects duplicate keys.
// ---------------------------------------------------------------------------------------------

/// A parsed JSON value. Numbers hold the correctly rounded `f64` of their text; a non-finite
/// number (`NaN`, `Infinity`, `1e400`, ...) holds its text instead.
#[derive(Debug)]
enum Json {
    Null,
    Bool(bool),
    Number(f64),
    NonFinite(String),
    String(String),
    Array(Vec<Json>),
    Object(Vec<(String, Json)>),
}

/// A number token found by the pre-pass, in document order.
#[derive(Debug)]
enum NumberToken {
    Finite(f64),
    NonFinite(String),
}

/// The text after the pre-pass, and its number tokens in document order.
struct Prepared {
    text: String,
    numbers: Vec<NumberToken>,
}

/// The bytes that end a bare token outside strings: JSON whitespace, structure and quotes.
fn is_delimiter(c: u8) -> bool {
    matches!(c, b' ' | b'\t' | b'\n' | b'\r' | b'{' | b'}' | b'[' | b']' | b',' | b':' | b'"')
}

/// Whether `s` is exactly a JSON number: `-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?`.
fn is_json_number(s: &[u8]) -> bool {
    let digits = |i: &mut usize| {
        let start = *i;
        while s.get(*i).is_some_and(u8::is_ascii_digit) {
            *i += 1;
        }
        *i > start
    };
    let mut i = 0;
    if s.first() == Some(&b'-') {
        i += 1;
    }
    match s.get(i) {
        Some(b'0') => i += 1,
        Some(b'1'..=b'9') => {
            digits(&mut i);
        }
        _ => return false,
    }
    if s.get(i) == Some(&b'.') {
        i += 1;
        if !digits(&mut i) {
            return false;
        }
    }
    if matches!(s.get(i), Some(b'e' | b'E')) {
        i += 1;
        if matches!(s.get(i), Some(b'+' | b'-')) {
            i += 1;
        }
        if !digits(&mut i) {
            return false;
        }
    }
    i == s.len()
}

/// Whether `s` is one of the words people write for non-finite numbers: `NaN`, `Infinity`,
/// `inf`, in any case, optionally signed.
fn is_non_finite_word(s: &[u8]) -> bool {
    let s = s.strip_prefix(b"-").or_else(|| s.strip_prefix(b"+")).unwrap_or(s);
    [&b"nan"[..], b"inf", b"infinity"].iter().any(|word| s.eq_ignore_ascii_case(word))
}

/// The pre-pass. Outside strings it replaces every non-finite number token (the words of
/// [`is_non_finite_word`], and JSON numbers whose `f64` overflows) with a `0` padded with spaces
/// to the same length, so that serde_json accepts it and every line and column stays the same.
/// It records every number token in document order, with its correctly rounded value or its
/// non-finite text, since serde_json's default float parsing may be off by an ulp. A UTF-8 byte
/// order mark becomes three spaces. Everything else is copied unchanged.
fn prepare(text: &str) -> Prepared {
    let bytes = text.as_bytes();
    let mut out: Vec<u8> = Vec::with_capacity(bytes.len());
    let mut numbers = Vec::new();
    let mut i = 0;
    if bytes.starts_with(&[0xEF, 0xBB, 0xBF]) {
        out.extend_from_slice(b"   ");
        i = 3;
    }
    while i < bytes.len() {
        let c = bytes[i];
        if c == b'"' {
            // Copy a string literal up to its closing quote, stepping over escapes.
            let start = i;
            i += 1;
            while i < bytes.len() {
                match bytes[i] {
                    b'\\' => i += 2,
                    b'"' => {
                        i += 1;
                        break;
                    }
                    _ => i += 1,
                }
            }
            i = i.min(bytes.len());
            out.extend_from_slice(&bytes[start..i]);
        } else if is_delimiter(c) {
            out.push(c);
            i += 1;
        } else {
            let start = i;
            while i < bytes.len() && !is_delimiter(bytes[i]) {
                i += 1;
            }
            let token = &bytes[start..i];
            let non_finite = if is_json_number(token) {
                // A JSON number is ASCII and valid Rust float syntax, so both steps succeed;
                // should either fail, the token is left for serde_json to judge.
                match std::str::from_utf8(token).ok().and_then(|t| t.parse::<f64>().ok()) {
                    Some(value) if value.is_finite() => {
                        numbers.push(NumberToken::Finite(value));
                        false
                    }
                    Some(_) => true,
                    None => false,
                }
            } else {
                is_non_finite_word(token)
            };
            if non_finite {
                numbers.push(NumberToken::NonFinite(String::from_utf8_lossy(token).into_owned()));
                out.push(b'0');
                out.resize(out.len() + token.len() - 1, b' ');
            } else {
                out.extend_from_slice(token);
            }
        }
    }
    // Only ASCII runs were replaced, by ASCII of the same length, and every cut fell next to an
    // ASCII byte, so the bytes are still UTF-8; the fallback merely avoids a panic path.
    let text =
        String::from_utf8(out).unwrap_or_else(|err| String::from_utf8_lossy(err.as_bytes()).into_owned());
    Prepared { text, numbers }
}

/// Parses scene text into a [`Json`] tree, reporting JSON syntax errors with line and column.
fn parse_json(text: &str, name: &str) -> Result<Json, SceneError> {
    if text.trim_start_matches('\u{feff}').trim().is_empty() {
        return Err(SceneError::Truncated {
            name: name.to_string(),
            line: 1,
            column: 0,
            message: "the file is empty".to_string(),
        });
    }
    let prepared = prepare(text);
    let builder = TreeBuilder { numbers: &prepared.numbers, next: Cell::new(0) };
    let mut de = serde_json::Deserializer::from_str(&prepared.text);
    let parsed = TreeSeed(&builder).deserialize(&mut de).and_then(|root| de.end().map(|()| root));
    match parsed {
        Ok(root) if builder.next.get() == prepared.numbers.len() => Ok(root),
        // Unreachable: a successful parse visits every number token the pre-pass found.
        Ok(_) => Err(SceneError::Malformed {
            name: name.to_string(),
            line: 0,
            column: 0,
            message: "internal error: the number tokens do not match the parse".to_string(),
        }),
        Err(err) => Err(json_error(name, &err)),
    }
}

/// Converts a serde_json error into [`SceneError::Truncated`] or [`SceneError::Malformed`].
fn json_error(name: &str, err: &serde_json::Error) -> SceneError {
    let (line, column) = (err.line(), err.column());
    let full = err.to_string();
    let suffix = format!(" at line {line} column {column}");
    let message = full.strip_suffix(&suffix).unwrap_or(&full).replace('`', "'");
    let name = name.to_string();
    if err.is_eof() {
        SceneError::Truncated { name, line, column, message }
    } else {
        SceneError::Malformed { name, line, column, message }
    }
}

/// The state of one parse: the pre-pass's number tokens and how many have been used.
struct TreeBuilder<'t> {
    numbers: &'t [NumberToken],
    next: Cell<usize>,
}

impl TreeBuilder<'_> {
    /// The value of the next number token in document order. serde_json visits numbers in the
    /// order the pre-pass found them. Should the two ever disagree (which only happens on text
    /// that serde_json rejects right after), a placeholder stands in and [`parse_json`] notices.
    fn number(&self) -> Json {
        let i = self.next.get();
        self.next.set(i + 1);
        match self.numbers.get(i) {
            Some(NumberToken::Finite(value)) => Json::Number(*value),
            Some(NumberToken::NonFinite(text)) => Json::NonFinite(text.clone()),
            None => Json::Null,
        }
    }
}

/// Deserializes one [`Json`] value.
#[derive(Clone, Copy)]
struct TreeSeed<'b, 't>(&'b TreeBuilder<'t>);

impl<'de> DeserializeSeed<'de> for TreeSeed<'_, '_> {
    type Value = Json;

    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<Json, D::Error> {
        deserializer.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for TreeSeed<'_, '_> {
    type Value = Json;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }

    fn visit_bool<E: de::Error>(self, v: bool) -> Result<Json, E> {
        Ok(Json::Bool(v))
    }

    fn visit_i64<E: de::Error>(self, _: i64) -> Result<Json, E> {
        Ok(self.0.number())
    }

    fn visit_u64<E: de::Error>(self, _: u64) -> Result<Json, E> {
        Ok(self.0.number())
    }

    fn visit_f64<E: de::Error>(self, _: f64) -> Result<Json, E> {
        Ok(self.0.number())
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<Json, E> {
        Ok(Json::String(v.to_string()))
    }

    fn visit_string<E: de::Error>(self, v: String) -> Result<Json, E> {
        Ok(Json::String(v))
    }

    fn visit_unit<E: de::Error>(self) -> Result<Json, E> {
        Ok(Json::Null)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Json, A::Error> {
        let mut items = Vec::new();
        while let Some(item) = seq.next_element_seed(self)? {
            items.push(item);
        }
        Ok(Json::Array(items))
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Json, A::Error> {
        let mut entries: Vec<(String, Json)> = Vec::new();
        // Objects of the format are small; a set takes over for large ones.
        let mut seen: Option<HashSet<String>> = None;
        while let Some(key) = map.next_key::<String>()? {
            let duplicate = match &mut seen {
                Some(set) => !set.insert(key.clone()),
                None => entries.iter().any(|(k, _)| *k == key),
            };
            if duplicate {
                return Err(de::Error::custom(format!("duplicate field \"{key}\"")));
            }
            let value = map.next_value_seed(self)?;
            entries.push((key, value));
            if seen.is_none() && entries.len() >= 16 {
                seen = Some(entries.iter().map(|(k, _)| k.clone()).collect());
            }
        }
        Ok(Json::Object(entries))
    }
}

/// A short description of a JSON value for "found ..." in messages.
fn describe(value: &Json) -> String {
    match value {
        Json::Null => "null".to_string(),
        Json::Bool(b) => format!("{b}"),
        Json::Number(x) => format!("the number {}", number_text(x)),
        Json::NonFinite(text) => format!("the non-finite number {text}"),
        Json::String(s) => {
            let short: String = s.chars().take(40).collect();
            let ellipsis = if short.len() < s.len() { "..." } else { "" };
            format!("the string {short:?}{ellipsis}")
        }
        Json::Array(items) => match items.len() {
            0 => "an empty array".to_string(),
            1 => "an array of 1 element".to_string(),
            n => format!("an array of {n} elements"),
        },
        Json::Object(_) => "an object".to_string(),
    }
}

// ---------------------------------------------------------------------------------------------
// The reader: walks the tree and builds a scene, with the exact place of every problem.
// ---------------------------------------------------------------------------------------------

/// Allowed fields of each object, for unknown-field messages.
const TOP_FIELDS: &[&str] = &["version", "world", "segments"];
const WORLD_FIELDS: &[&str] = &["min", "max"];
const SEGMENT_FIELDS: &[&str] = &["a", "b", "reflectance", "emission"];

/// Walks a parsed tree; `name` is the file name errors carry.
struct Reader<'n> {
    name: &'n str,
}

impl Reader<'_> {
    /// Reads the whole scene. The version is checked first, because a newer version may define
    /// fields this reader does not know; then unknown fields, because a misspelled `segments`
    /// would otherwise be reported as missing.
    fn scene(&self, root: &Json) -> Result<Scene, SceneError> {
        let fields = self.object(root, Location::Top, "the scene")?;
        if let Some(version) = field(fields, "version") {
            self.version(version)?;
        }
        self.known_fields(fields, Location::Top, TOP_FIELDS)?;
        let world = match field(fields, "world") {
            Some(world) => Some(self.world(world)?),
            None => None,
        };
        let list = match field(fields, "segments") {
            Some(Json::Array(list)) => list,
            Some(other) => {
                return Err(self.wrong_type(Location::Top, "\"segments\"", "an array of segments", other))
            }
            None => return Err(self.missing(Location::Top, "segments")),
        };
        if list.is_empty() {
            return Err(SceneError::NoSegments { name: self.name.to_string() });
        }
        if list.len() > MAX_SEGMENTS {
            return Err(SceneError::TooManySegments { name: self.name.to_string(), count: list.len() });
        }
        // Each segment is read and checked before the next, so the first problem in document
        // order is the one reported. The checks are those of `Scene::validate`.
        let mut segments = Vec::with_capacity(list.len());
        let mut materials = Vec::with_capacity(list.len());
        for (index, item) in list.iter().enumerate() {
            let (segment, material) = self.segment(index, item)?;
            check_segment(self.name, index, &segment, world.as_ref())?;
            check_material(self.name, index, &material)?;
            segments.push(segment);
            materials.push(material);
        }
        Ok(Scene { segments, materials, world })
    }

    /// Accepts the version number 1 and nothing else.
    fn version(&self, value: &Json) -> Result<(), SceneError> {
        match value {
            Json::Number(v) if *v == f64::from(SCENE_VERSION) => Ok(()),
            Json::Number(v) => Err(self.unsupported_version(number_text(v))),
            Json::NonFinite(text) => Err(self.unsupported_version(text.clone())),
            Json::String(text) => Err(self.unsupported_version(format!("{text:?} (a string)"))),
            other => Err(self.unsupported_version(describe(other))),
        }
    }

    fn unsupported_version(&self, found: String) -> SceneError {
        SceneError::UnsupportedVersion { name: self.name.to_string(), found }
    }

    /// Reads the world box and checks it.
    fn world(&self, value: &Json) -> Result<Bounds, SceneError> {
        let location = Location::World;
        let fields = self.object(value, location, "\"world\"")?;
        self.known_fields(fields, location, WORLD_FIELDS)?;
        let min = field(fields, "min").ok_or_else(|| self.missing(location, "min"))?;
        let max = field(fields, "max").ok_or_else(|| self.missing(location, "max"))?;
        let world = Bounds::new(self.point(min, location, "min")?, self.point(max, location, "max")?);
        check_world(self.name, &world)?;
        Ok(world)
    }

    /// Reads one segment and its material; the caller checks them against the rules.
    fn segment(&self, index: usize, value: &Json) -> Result<(Segment, Material), SceneError> {
        let location = Location::Segment(index);
        let fields = self.object(value, location, "the segment")?;
        self.known_fields(fields, location, SEGMENT_FIELDS)?;
        let a = field(fields, "a").ok_or_else(|| self.missing(location, "a"))?;
        let b = field(fields, "b").ok_or_else(|| self.missing(location, "b"))?;
        let a = self.point(a, location, "endpoint a")?;
        let b = self.point(b, location, "endpoint b")?;
        let material = Material {
            reflectance: self.material_value(fields, index, "reflectance")?,
            emission: self.material_value(fields, index, "emission")?,
        };
        Ok((Segment::new(a, b), material))
    }

    /// Reads an optional material number; its range is checked by [`check_material`].
    fn material_value(
        &self,
        fields: &[(String, Json)],
        index: usize,
        key: &'static str,
    ) -> Result<Option<f64>, SceneError> {
        match field(fields, key) {
            None => Ok(None),
            Some(Json::Number(v)) => Ok(Some(*v)),
            Some(Json::NonFinite(text)) => Err(bad_material(self.name, index, key, text.clone())),
            Some(other) => {
                Err(self.wrong_type(Location::Segment(index), &format!("\"{key}\""), "a number", other))
            }
        }
    }

    /// Reads a point `[x, y]` and checks its coordinates.
    fn point(&self, value: &Json, location: Location, point: &'static str) -> Result<Vec2, SceneError> {
        let items = match value {
            Json::Array(items) => items,
            other => return Err(self.wrong_type(location, point, "an array [x, y]", other)),
        };
        if items.len() != 2 {
            return Err(SceneError::BadPoint {
                name: self.name.to_string(),
                location,
                point,
                count: items.len(),
            });
        }
        let mut xy = [0.0; 2];
        for ((slot, item), axis) in xy.iter_mut().zip(items).zip(["x", "y"]) {
            *slot = match item {
                Json::Number(v) => *v,
                Json::NonFinite(text) => {
                    return Err(SceneError::NonFiniteCoordinate {
                        name: self.name.to_string(),
                        location,
                        point,
                        token: text.clone(),
                    })
                }
                other => {
                    return Err(self.wrong_type(
                        location,
                        &format!("the {axis} coordinate of {point}"),
                        "a number",
                        other,
                    ))
                }
            };
            check_coordinate(self.name, location, point, *slot)?;
        }
        Ok(Vec2::new(xy[0], xy[1]))
    }

    /// The fields of an object, or a wrong-type error naming `what`.
    fn object<'j>(
        &self,
        value: &'j Json,
        location: Location,
        what: &str,
    ) -> Result<&'j [(String, Json)], SceneError> {
        match value {
            Json::Object(fields) => Ok(fields),
            other => Err(self.wrong_type(location, what, "a JSON object", other)),
        }
    }

    /// Fails on the first field not in `allowed`.
    fn known_fields(
        &self,
        fields: &[(String, Json)],
        location: Location,
        allowed: &'static [&'static str],
    ) -> Result<(), SceneError> {
        match fields.iter().find(|(key, _)| !allowed.contains(&key.as_str())) {
            None => Ok(()),
            Some((key, _)) => Err(SceneError::UnknownField {
                name: self.name.to_string(),
                location,
                field: key.clone(),
                allowed: match location {
                    Location::Top => "version, world, segments",
                    Location::World => "min, max",
                    Location::Segment(_) => "a, b, reflectance, emission",
                },
            }),
        }
    }

    fn missing(&self, location: Location, field: &'static str) -> SceneError {
        SceneError::MissingField { name: self.name.to_string(), location, field }
    }

    fn wrong_type(&self, location: Location, what: &str, expected: &'static str, found: &Json) -> SceneError {
        SceneError::WrongType {
            name: self.name.to_string(),
            location,
            what: what.to_string(),
            expected,
            found: describe(found),
        }
    }
}

/// The value of `key` in an object's fields (keys are unique, the parser ensures it).
fn field<'j>(fields: &'j [(String, Json)], key: &str) -> Option<&'j Json> {
    fields.iter().find(|(k, _)| k == key).map(|(_, v)| v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_number_grammar() {
        for ok in ["0", "-0", "12", "1.5", "1e5", "1E+05", "-2.5e-3", "1e400"] {
            assert!(is_json_number(ok.as_bytes()), "{ok}");
        }
        for bad in ["", "-", "01", "1.", ".5", "+1", "1e", "1e+", "0x10", "1.5.2", "NaN"] {
            assert!(!is_json_number(bad.as_bytes()), "{bad}");
        }
    }

    #[test]
    fn prepass_keeps_lengths_and_strings() {
        let text = "{\"s\": \"NaN \\\" 1e400\", \"x\": [NaN, -Infinity, 1e400, 2.5, true]}";
        let prepared = prepare(text);
        assert_eq!(prepared.text.len(), text.len());
        assert!(prepared.text.contains("\"NaN \\\" 1e400\""));
        assert_eq!(prepared.numbers.len(), 4);
        assert!(matches!(&prepared.numbers[0], NumberToken::NonFinite(t) if t == "NaN"));
        assert!(matches!(&prepared.numbers[1], NumberToken::NonFinite(t) if t == "-Infinity"));
        assert!(matches!(&prepared.numbers[2], NumberToken::NonFinite(t) if t == "1e400"));
        assert!(matches!(prepared.numbers[3], NumberToken::Finite(v) if v == 2.5));
    }

    #[test]
    fn numbers_are_correctly_rounded() {
        // Decimal texts near halfway cases, which a fast float parser may round the wrong way.
        let texts = [
            "2.2250738585072011e-308",
            "0.30000000000000004",
            "9007199254740993",
            "1.7976931348623157e308",
            "123.456789012345678",
        ];
        for t in texts {
            let json = format!("{{\"segments\": [{{\"a\": [0, 0], \"b\": [{t}, 1]}}]}}");
            match Scene::from_json_str(&json, "n.json") {
                Ok(scene) => assert_eq!(scene.segments[0].b.x, t.parse::<f64>().unwrap_or(0.0)),
                Err(SceneError::CoordinateLimit { .. }) => {}
                Err(e) => panic!("{t}: {e}"),
            }
        }
    }

    #[test]
    fn duplicate_keys_are_rejected() {
        let err = Scene::from_json_str(
            "{\"segments\": [{\"a\": [0, 0], \"a\": [1, 1], \"b\": [2, 2]}]}",
            "dup.json",
        )
        .unwrap_err();
        assert!(matches!(err, SceneError::Malformed { .. }), "{err}");
        assert!(err.to_string().contains("duplicate field \"a\""), "{err}");
    }

    #[test]
    fn byte_order_mark_is_accepted() {
        let text = "\u{feff}{\"segments\": [{\"a\": [0, 0], \"b\": [1, 0]}]}";
        assert!(Scene::from_json_str(text, "bom.json").is_ok());
    }

    #[test]
    fn number_text_forms() {
        assert_eq!(number_text(&5.0), "5");
        assert_eq!(number_text(&0.25), "0.25");
        assert_eq!(number_text(&3e12), "3e12");
        assert_eq!(number_text(&COORD_LIMIT), "1e9");
        assert_eq!(number_text(&f64::NAN), "NaN");
    }
}
