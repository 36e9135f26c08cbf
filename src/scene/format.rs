//! The file side of the scene format: the structures a scene file is read into, and the writer.
//!
//! The structures are derived with serde and reject unknown fields; serde's derive also rejects
//! a field given twice. Three small hand-written pieces keep the format stricter than serde's
//! defaults: [`Object`] accepts only a JSON object where derive would also take an array,
//! [`Point`] counts the coordinates it is given, and [`present`] rejects `null` for an optional
//! field. Numbers are plain `f64`, read by serde_json with correct rounding (its
//! `float_roundtrip` feature).

use std::fmt;
use std::marker::PhantomData;

use serde::de::{self, Deserialize, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};

use super::{Scene, SCENE_VERSION};
use crate::geom::Vec2;

/// A whole scene file.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SceneFile {
    #[serde(default, deserialize_with = "present")]
    pub version: Option<f64>,
    #[serde(default, deserialize_with = "present")]
    pub world: Option<Object<WorldFile>>,
    pub segments: Vec<Object<SegmentFile>>,
}

/// The `world` object.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct WorldFile {
    pub min: Point,
    pub max: Point,
}

/// One segment.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SegmentFile {
    pub a: Point,
    pub b: Point,
    #[serde(default, deserialize_with = "present")]
    pub reflectance: Option<f64>,
    #[serde(default, deserialize_with = "present")]
    pub emission: Option<f64>,
}

/// Only the version of a file, every other field ignored: read when a file fails to load, so that
/// an unsupported version is reported before the problems it may explain.
#[derive(serde::Deserialize)]
pub(super) struct VersionProbe {
    #[serde(default, deserialize_with = "present")]
    pub version: Option<f64>,
}

/// The allowed fields of each object of the format, for unknown-field messages.
pub(super) const TOP_FIELDS: &str = "version, world, segments";
pub(super) const WORLD_FIELDS: &str = "min, max";
pub(super) const SEGMENT_FIELDS: &str = "a, b, reflectance, emission";

/// An optional field that is present: its value, where `null` is a wrong type like any other
/// (`Option`'s own deserializer would take `null` for an absent value).
fn present<'de, D: Deserializer<'de>, T: Deserialize<'de>>(deserializer: D) -> Result<Option<T>, D::Error> {
    T::deserialize(deserializer).map(Some)
}

/// A JSON object read as `T`. serde's derive also accepts an array of the field values in order;
/// the format does not.
pub(super) struct Object<T>(pub T);

impl<'de, T: Deserialize<'de>> Deserialize<'de> for Object<T> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(ObjectVisitor(PhantomData))
    }
}

struct ObjectVisitor<T>(PhantomData<T>);

impl<'de, T: Deserialize<'de>> Visitor<'de> for ObjectVisitor<T> {
    type Value = Object<T>;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON object")
    }

    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Object<T>, A::Error> {
        T::deserialize(de::value::MapAccessDeserializer::new(map)).map(Object)
    }
}

/// A point `[x, y]`. A wrong number of coordinates is an `invalid_length` error with the count
/// found, for the message.
pub(super) struct Point(pub Vec2);

impl<'de> Deserialize<'de> for Point {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(PointVisitor)
    }
}

struct PointVisitor;

impl<'de> Visitor<'de> for PointVisitor {
    type Value = Point;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an array [x, y]")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Point, A::Error> {
        let x = seq.next_element::<f64>()?;
        let y = match x {
            Some(_) => seq.next_element::<f64>()?,
            None => None,
        };
        match (x, y) {
            (Some(x), Some(y)) => {
                let mut extra = 0;
                while seq.next_element::<IgnoredAny>()?.is_some() {
                    extra += 1;
                }
                if extra > 0 {
                    return Err(de::Error::invalid_length(2 + extra, &self));
                }
                Ok(Point(Vec2::new(x, y)))
            }
            (Some(_), None) => Err(de::Error::invalid_length(1, &self)),
            _ => Err(de::Error::invalid_length(0, &self)),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The writer.
// ---------------------------------------------------------------------------------------------

/// The scene as pretty JSON in the current format version; see [`Scene::to_json`].
pub(super) fn write(scene: &Scene) -> String {
    let mut out = String::new();
    out.push_str("{\n");
    out.push_str(&format!("  \"version\": {SCENE_VERSION},\n"));
    if let Some(world) = &scene.world {
        out.push_str(&format!(
            "  \"world\": {{\"min\": {}, \"max\": {}}},\n",
            json_point(world.min),
            json_point(world.max)
        ));
    }
    if scene.segments.is_empty() {
        out.push_str("  \"segments\": []\n");
    } else {
        out.push_str("  \"segments\": [\n");
        for (i, seg) in scene.segments.iter().enumerate() {
            out.push_str(&format!("    {{\"a\": {}, \"b\": {}", json_point(seg.a), json_point(seg.b)));
            let material = scene.material(i);
            if let Some(r) = material.reflectance {
                out.push_str(&format!(", \"reflectance\": {}", json_number(r)));
            }
            if let Some(e) = material.emission {
                out.push_str(&format!(", \"emission\": {}", json_number(e)));
            }
            out.push('}');
            if i + 1 < scene.segments.len() {
                out.push(',');
            }
            out.push('\n');
        }
        out.push_str("  ]\n");
    }
    out.push_str("}\n");
    out
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
