//! Scenes: the versioned JSON scene format, its loader and writer, and the random scene
//! generator of the paper's experiments.
//!
//! The module is split by concern: this file holds the types, the rules of a valid scene and the
//! public API; `format` the file's structure and the writer; `parse` the loader (text to file
//! structures to [`Scene`], with every error placed); `gen` the random generator [`generate`]; `room` the closed rooms of the radiosity
//! experiments ([`room`]).
//!
//! # The scene format, version 2
//!
//! A scene file is one JSON object:
//!
//! ```json
//! {
//!   "version": 2,
//!   "world": {"min": [0, 0], "max": [1024, 1024]},
//!   "segments": [
//!     {"a": [100, 200], "b": [300, 200], "reflectance": 0.5, "emission": 0.0},
//!     {"a": [500, 500], "b": [500, 700], "emission": 10.0}
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
//! | `version` | no, defaults to 1 | The format version: `1` or `2`. |
//! | `world` | no | The world box `{"min": [x, y], "max": [x, y]}`: the half-open box `min ≤ p < max`. Every endpoint of every segment must lie inside it. `min` must be less than `max` in both coordinates. |
//! | `segments` | yes, non-empty | The patches of the scene, in order; a segment's index is its position in this array, counted from 0. |
//! | `segments[i].a`, `segments[i].b` | yes | The endpoints, each an array of exactly two numbers `[x, y]`. |
//! | `segments[i].reflectance` | no, defaults to [`DEFAULT_REFLECTANCE`] (0.5) | The fraction of incoming light the front side reflects: a number in `[0, 1)`. |
//! | `segments[i].emission` | no, defaults to [`DEFAULT_EMISSION`] (0) | The light the front side emits, as radiant exitance (power per unit length of the segment): a number `≥ 0`. |
//!
//! Versions 1 and 2 have the same fields and are read alike; version 2 gives the material values
//! their radiosity meaning above. Reflectance 1 is an error in both versions (version 1 allowed
//! it), since a radiosity solve needs a reflectance below 1.
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
//! * A file is at most [`MAX_SCENE_BYTES`] (256 MiB) long.
//!
//! Every error names the file, the segment where there is one, and the problem in plain words,
//! for example `scene.json: segment 17: endpoint a has a non-finite coordinate (NaN)`. See
//! [`SceneError`] for the full list.
//!
//! [`Scene::to_json`] writes the current version, always with `"version"`, one segment per line.
//! It prints each number in the shortest form that reads back to the same `f64`, and the loader
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

use std::fmt;
use std::io::Read;
use std::path::Path;

use crate::geom::{Segment, Vec2};

mod format;
mod gen;
mod parse;
mod room;

pub use gen::generate;
pub use room::{room, RoomError, RoomSpec, MAX_ROOM_PATCHES};

/// The scene format version this module writes.
pub const SCENE_VERSION: u32 = 2;

/// The oldest scene format version this module reads; it reads every version from this one to
/// [`SCENE_VERSION`].
pub const FIRST_SCENE_VERSION: u32 = 1;

/// Largest accepted coordinate magnitude.
pub const COORD_LIMIT: f64 = 1.0e9;

/// Largest accepted number of segments: segment indices must fit in a `u32`.
pub const MAX_SEGMENTS: usize = u32::MAX as usize;

/// Largest accepted scene file, in bytes (256 MiB, some ten million segments). The loader reads
/// no more than this and one byte, so a path such as `/dev/zero` gives an error instead of
/// filling the memory.
pub const MAX_SCENE_BYTES: u64 = 256 << 20;

/// The world of the paper's experiments: the half-open square `[0, 1024)²`.
pub const PAPER_WORLD: Bounds = Bounds { min: Vec2::new(0.0, 0.0), max: Vec2::new(1024.0, 1024.0) };

/// The name that errors of [`Scene::new`] carry in place of a file name.
const MEMORY_NAME: &str = "<memory>";

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
/// the accessors [`Material::reflectance_or_default`] and [`Material::emission_or_default`] give
/// the format's defaults in its place.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Material {
    /// The fraction of incoming light the front side reflects, in `[0, 1)`.
    pub reflectance: Option<f64>,
    /// The light the front side emits: radiant exitance (power per unit length), `≥ 0`.
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

    /// The file is longer than [`MAX_SCENE_BYTES`] (or than the limit it was read with), as a
    /// device such as `/dev/zero` is.
    #[error("{name}: the file is larger than {}, the limit for a scene file", bytes_text(*.limit))]
    TooLarge { name: String, limit: u64 },

    /// The text is not valid JSON (or not valid UTF-8).
    #[error("{name}: malformed JSON at line {line} column {column}: {message}")]
    Malformed { name: String, line: usize, column: usize, message: String },

    /// The text ends in the middle of a JSON value: the file looks truncated.
    #[error(
        "{name}: the JSON ends unexpectedly at line {line} column {column} \
         (is the file truncated?): {message}"
    )]
    Truncated { name: String, line: usize, column: usize, message: String },

    /// The `version` field is not a version this program reads (1 or 2).
    #[error(
        "{name}: unsupported scene format version {found} \
         (this program reads versions {FIRST_SCENE_VERSION} to {SCENE_VERSION})"
    )]
    UnsupportedVersion { name: String, found: String },

    /// An object has a field the format does not define (often a typo).
    #[error("{name}: {location}unknown field \"{field}\" (allowed fields: {allowed})")]
    UnknownField { name: String, location: Location, field: String, allowed: &'static str },

    /// An object gives the same field twice.
    #[error("{name}: {location}field \"{field}\" is given twice")]
    DuplicateField { name: String, location: Location, field: String },

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
        /// The rule it breaks, such as `a finite number in [0, 1)`.
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
            | SceneError::TooLarge { name, .. }
            | SceneError::Malformed { name, .. }
            | SceneError::Truncated { name, .. }
            | SceneError::UnsupportedVersion { name, .. }
            | SceneError::UnknownField { name, .. }
            | SceneError::DuplicateField { name, .. }
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
            | SceneError::DuplicateField { location, .. }
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

    /// Parses a scene from JSON text (version 1 or 2). `name` is the file name that errors
    /// carry.
    pub fn from_json_str(text: &str, name: &str) -> Result<Scene, SceneError> {
        parse::parse(text, name)
    }

    /// Reads and parses a scene file of at most [`MAX_SCENE_BYTES`]. Errors carry the path as
    /// given.
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        let name = path.display().to_string();
        let file = std::fs::File::open(path).map_err(|source| parse::read_error(&name, source))?;
        Scene::from_reader(file, &name)
    }

    /// Reads and parses a scene from `reader`, reading at most [`MAX_SCENE_BYTES`] and one byte.
    /// `name` is the file name that errors carry.
    pub fn from_reader(reader: impl Read, name: &str) -> Result<Scene, SceneError> {
        let text = parse::read_text(reader, name, MAX_SCENE_BYTES)?;
        parse::parse(&text, name)
    }

    /// The scene as pretty JSON in the current format version, one segment per line, ending with
    /// a newline. Optional fields are written only where they are set. Numbers are written in
    /// the shortest form that parses back to the same `f64`, so loading the text gives back an
    /// equal scene. (A non-finite number, which a valid scene cannot hold, is written as `NaN`,
    /// `Infinity` or `-Infinity`, which the loader reports as an error.)
    pub fn to_json(&self) -> String {
        format::write(self)
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

/// Checks the material of one segment against the ranges of the format: reflectance in `[0, 1)`
/// (a radiosity solve needs it below 1), emission finite and `≥ 0`.
fn check_material(name: &str, index: usize, material: &Material) -> Result<(), SceneError> {
    if let Some(r) = material.reflectance {
        if !(0.0..1.0).contains(&r) {
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
    let rule = if field == "reflectance" { "a finite number in [0, 1)" } else { "a finite number >= 0" };
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

/// A byte count for an error message: `268435456 bytes (256 MiB)`, or `100 bytes`.
fn bytes_text(bytes: u64) -> String {
    const MIB: u64 = 1 << 20;
    if bytes >= MIB && bytes % MIB == 0 {
        format!("{bytes} bytes ({} MiB)", bytes / MIB)
    } else {
        format!("{bytes} bytes")
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn number_text_forms() {
        assert_eq!(number_text(&5.0), "5");
        assert_eq!(number_text(&0.25), "0.25");
        assert_eq!(number_text(&3e12), "3e12");
        assert_eq!(number_text(&COORD_LIMIT), "1e9");
        assert_eq!(number_text(&f64::NAN), "NaN");
        assert_eq!(bytes_text(MAX_SCENE_BYTES), "268435456 bytes (256 MiB)");
        assert_eq!(bytes_text(100), "100 bytes");
    }
}
