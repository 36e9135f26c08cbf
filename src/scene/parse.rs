//! The loader: bytes to text, text to the file structures of `format` (with serde derive and
//! serde_json), and those to a validated [`Scene`]. A failure of serde becomes a [`SceneError`]
//! from the place it happened (`serde_path_to_error` gives the segment index and the field) and
//! the kind of the failure.
//!
//! serde_json rejects `NaN`, `Infinity` and numbers such as `1e400` as syntax errors. Where a
//! syntax error falls on such a token, the loader reports a non-finite value of the field that
//! holds it instead.

use std::io::Read;

use serde::de::DeserializeOwned;
use serde_json::error::Category;
use serde_path_to_error::Segment as Step;

use super::format::{Object, SceneFile, VersionProbe, SEGMENT_FIELDS, TOP_FIELDS, WORLD_FIELDS};
use super::{
    bad_material, number_text, Bounds, Location, Material, Scene, SceneError, FIRST_SCENE_VERSION,
    SCENE_VERSION,
};
use crate::geom::Segment;

/// The error for a file that cannot be read.
pub(super) fn read_error(name: &str, source: std::io::Error) -> SceneError {
    SceneError::Io { name: name.to_string(), action: "read", source }
}

/// Reads at most `limit` bytes and one from `reader` (so that a device that never ends is
/// refused instead of filling the memory) and checks that they are UTF-8 text.
pub(super) fn read_text(reader: impl Read, name: &str, limit: u64) -> Result<String, SceneError> {
    let mut bytes = Vec::new();
    reader.take(limit.saturating_add(1)).read_to_end(&mut bytes).map_err(|err| read_error(name, err))?;
    if bytes.len() as u64 > limit {
        return Err(SceneError::TooLarge { name: name.to_string(), limit });
    }
    String::from_utf8(bytes).map_err(|err| {
        let (line, column) = line_column(&err.as_bytes()[..err.utf8_error().valid_up_to()]);
        SceneError::Malformed {
            name: name.to_string(),
            line,
            column,
            message: "the file is not valid UTF-8 text".to_string(),
        }
    })
}

/// Parses and validates scene text; `name` is the file name errors carry.
pub(super) fn parse(text: &str, name: &str) -> Result<Scene, SceneError> {
    // serde_json takes no byte order mark; it counts as the three bytes it is in line 1's columns.
    let (body, shift) = match text.strip_prefix('\u{feff}') {
        Some(rest) => (rest, 3),
        None => (text, 0),
    };
    if body.trim().is_empty() {
        return Err(SceneError::Truncated {
            name: name.to_string(),
            line: 1,
            column: 0,
            message: "the file is empty".to_string(),
        });
    }
    let errors = Errors { name, text: body, shift };
    let file = match read::<SceneFile>(body) {
        Ok(file) => file,
        // The version is reported before anything else, since a newer format may define what
        // this reader calls an error.
        Err(failure) => return Err(errors.version_problem().unwrap_or_else(|| errors.map(failure))),
    };
    check_version(name, file.version)?;
    let world = file.world.map(|Object(w)| Bounds::new(w.min.0, w.max.0));
    let (segments, materials) = file
        .segments
        .into_iter()
        .map(|Object(s)| {
            (Segment::new(s.a.0, s.b.0), Material { reflectance: s.reflectance, emission: s.emission })
        })
        .unzip();
    let scene = Scene { segments, materials, world };
    scene.validate(name)?;
    Ok(scene)
}

/// Accepts an absent version and the versions this program reads.
fn check_version(name: &str, version: Option<f64>) -> Result<(), SceneError> {
    match version {
        Some(v) if !(FIRST_SCENE_VERSION..=SCENE_VERSION).any(|known| f64::from(known) == v) => {
            Err(SceneError::UnsupportedVersion { name: name.to_string(), found: number_text(&v) })
        }
        _ => Ok(()),
    }
}

/// How reading the text into `T` failed: inside the value, with the path to where, or after it.
enum Failure {
    Inside(serde_path_to_error::Error<serde_json::Error>),
    After(serde_json::Error),
}

/// Reads the whole text as one JSON object of type `T`.
fn read<T: DeserializeOwned>(text: &str) -> Result<T, Failure> {
    let mut de = serde_json::Deserializer::from_str(text);
    let Object(value) = serde_path_to_error::deserialize(&mut de).map_err(Failure::Inside)?;
    de.end().map_err(Failure::After)?;
    Ok(value)
}

/// A step of a path, borrowed.
#[derive(Clone, Copy)]
enum Part<'p> {
    Key(&'p str),
    Index(usize),
    Other,
}

/// What a path points at, in the words of the messages.
struct Place {
    location: Location,
    /// What the value is, such as `endpoint a` or `the y coordinate of endpoint a`.
    what: String,
    /// What the value must be, such as `an array [x, y]`.
    expected: &'static str,
    kind: Kind,
}

#[derive(Clone, Copy)]
enum Kind {
    Version,
    Point(&'static str),
    Coordinate(&'static str),
    Material(usize, &'static str),
    Other,
}

/// The place a path points at.
fn place(path: &[Part]) -> Place {
    use Part::{Index, Key};
    let other = |location, what: &str, expected| Place {
        location,
        what: what.to_string(),
        expected,
        kind: Kind::Other,
    };
    let point = |location, point: &'static str, rest: &[Part]| match rest {
        [] => {
            Place { location, what: point.to_string(), expected: "an array [x, y]", kind: Kind::Point(point) }
        }
        [Index(axis), ..] => Place {
            location,
            what: format!("the {} coordinate of {point}", if *axis == 0 { "x" } else { "y" }),
            expected: "a number",
            kind: Kind::Coordinate(point),
        },
        _ => other(location, point, "an array [x, y]"),
    };
    match path {
        [Key("version")] => Place { kind: Kind::Version, ..other(Location::Top, "\"version\"", "a number") },
        [Key("world"), Key(p @ ("min" | "max")), rest @ ..] => {
            point(Location::World, if *p == "min" { "min" } else { "max" }, rest)
        }
        [Key("world"), ..] => other(Location::World, "\"world\"", "a JSON object"),
        [Key("segments")] => other(Location::Top, "\"segments\"", "an array of segments"),
        [Key("segments"), Index(i), Key(p @ ("a" | "b")), rest @ ..] => {
            point(Location::Segment(*i), if *p == "a" { "endpoint a" } else { "endpoint b" }, rest)
        }
        [Key("segments"), Index(i), Key(f @ ("reflectance" | "emission"))] => {
            let field = if *f == "reflectance" { "reflectance" } else { "emission" };
            let what = format!("\"{field}\"");
            Place { kind: Kind::Material(*i, field), ..other(Location::Segment(*i), &what, "a number") }
        }
        [Key("segments"), Index(i), ..] => other(Location::Segment(*i), "the segment", "a JSON object"),
        _ => other(Location::Top, "the scene", "a JSON object"),
    }
}

/// Turns failures into [`SceneError`]s for one text.
struct Errors<'t> {
    name: &'t str,
    /// The text as parsed, without a byte order mark.
    text: &'t str,
    /// What to add to a column of line 1: the length of a byte order mark taken off.
    shift: usize,
}

impl Errors<'_> {
    /// The unsupported-version error, when the text is JSON enough to tell its version and the
    /// version is one this program does not read.
    fn version_problem(&self) -> Option<SceneError> {
        let problem = match read::<VersionProbe>(self.text) {
            Ok(probe) => check_version(self.name, probe.version).err(),
            Err(failure) => Some(self.map(failure)),
        };
        problem.filter(|err| matches!(err, SceneError::UnsupportedVersion { .. }))
    }

    /// The error for a failure.
    fn map(&self, failure: Failure) -> SceneError {
        let (steps, err) = match failure {
            Failure::Inside(err) => (err.path().iter().cloned().collect(), err.into_inner()),
            Failure::After(err) => (Vec::new(), err),
        };
        let path: Vec<Part> = steps
            .iter()
            .map(|step| match step {
                Step::Map { key } => Part::Key(key),
                Step::Seq { index } => Part::Index(*index),
                _ => Part::Other,
            })
            .collect();
        let message = message_of(&err);
        let found = match err.classify() {
            Category::Eof => {
                return SceneError::Truncated {
                    name: self.name.to_string(),
                    line: err.line(),
                    column: self.column(&err),
                    message: message.replace('`', "'"),
                }
            }
            Category::Syntax => {
                self.non_finite_token(&err, &message).map(|token| self.non_finite(&path, token))
            }
            Category::Data => self.data(&path, &message),
            Category::Io => None,
        };
        found.unwrap_or_else(|| SceneError::Malformed {
            name: self.name.to_string(),
            line: err.line(),
            column: self.column(&err),
            message: message.replace('`', "'"),
        })
    }

    /// The error for a data failure (a type, a field, a length), where serde's message is one of
    /// the forms its derive and its `Error` methods write.
    fn data(&self, path: &[Part], message: &str) -> Option<SceneError> {
        let name = self.name.to_string();
        let location = place(path).location;
        let quoted = |rest: &str| rest.split('`').next().unwrap_or_default().to_string();
        if let Some(rest) = message.strip_prefix("unknown field `") {
            let field = match path.last() {
                Some(Part::Key(key)) => key.to_string(),
                _ => quoted(rest),
            };
            let allowed = match location {
                Location::Top => TOP_FIELDS,
                Location::World => WORLD_FIELDS,
                Location::Segment(_) => SEGMENT_FIELDS,
            };
            return Some(SceneError::UnknownField { name, location, field, allowed });
        }
        if let Some(rest) = message.strip_prefix("duplicate field `") {
            return Some(SceneError::DuplicateField { name, location, field: quoted(rest) });
        }
        if let Some(rest) = message.strip_prefix("missing field `") {
            let field = ["segments", "min", "max", "a", "b"].into_iter().find(|f| *f == quoted(rest))?;
            return Some(SceneError::MissingField { name, location, field });
        }
        if let Some(rest) = message.strip_prefix("invalid type: ") {
            let found = found_text(&rest[..rest.rfind(", expected ")?]);
            return Some(self.wrong_type(place(path), found));
        }
        if let Some(rest) = message.strip_prefix("invalid length ") {
            let count = rest.split(',').next()?.parse().ok()?;
            if let Place { location, kind: Kind::Point(point), .. } = place(path) {
                return Some(SceneError::BadPoint { name, location, point, count });
            }
        }
        None
    }

    /// The error for a value of the wrong type at `place`; `found` describes it.
    fn wrong_type(&self, place: Place, found: String) -> SceneError {
        let name = self.name.to_string();
        match place.kind {
            Kind::Version => {
                let found = match found.strip_prefix("the string ") {
                    Some(text) => format!("{text} (a string)"),
                    None => found,
                };
                SceneError::UnsupportedVersion { name, found }
            }
            _ => SceneError::WrongType {
                name,
                location: place.location,
                what: place.what,
                expected: place.expected,
                found,
            },
        }
    }

    /// The error for a non-finite number token at `path`.
    fn non_finite(&self, path: &[Part], token: String) -> SceneError {
        let place = place(path);
        match place.kind {
            Kind::Coordinate(point) => SceneError::NonFiniteCoordinate {
                name: self.name.to_string(),
                location: place.location,
                point,
                token,
            },
            Kind::Material(segment, field) => bad_material(self.name, segment, field, token),
            Kind::Version => SceneError::UnsupportedVersion { name: self.name.to_string(), found: token },
            _ => self.wrong_type(place, format!("the non-finite number {token}")),
        }
    }

    /// The token a syntax error falls on, where it is a non-finite number: one of the words of
    /// [`is_non_finite_word`], or a number too large for an `f64`.
    fn non_finite_token(&self, err: &serde_json::Error, message: &str) -> Option<String> {
        let overflow = message == "number out of range";
        if !(overflow || ["expected value", "invalid number", "expected ident"].contains(&message)) {
            return None;
        }
        let bytes = self.text.as_bytes();
        let line_start = match err.line() {
            0 => return None,
            1 => 0,
            line => bytes.iter().enumerate().filter(|(_, &c)| c == b'\n').nth(line - 2)?.0 + 1,
        };
        let at = line_start + err.column().checked_sub(1)?;
        if is_delimiter(*bytes.get(at)?) {
            return None;
        }
        let start = bytes[..at].iter().rposition(|&c| is_delimiter(c)).map_or(0, |i| i + 1);
        let end = bytes[at..].iter().position(|&c| is_delimiter(c)).map_or(bytes.len(), |i| at + i);
        let token = std::str::from_utf8(&bytes[start..end]).ok()?;
        (overflow || is_non_finite_word(token)).then(|| token.to_string())
    }

    /// The column of an error in the file as given, counting a byte order mark.
    fn column(&self, err: &serde_json::Error) -> usize {
        if err.line() == 1 {
            err.column() + self.shift
        } else {
            err.column()
        }
    }
}

/// serde_json's message without its ` at line L column C`.
fn message_of(err: &serde_json::Error) -> String {
    let full = err.to_string();
    let suffix = format!(" at line {} column {}", err.line(), err.column());
    full.strip_suffix(&suffix).unwrap_or(&full).to_string()
}

/// A value as serde describes it (`string "x"`, `integer `5``, `sequence`) in the words of the
/// messages (`the string "x"`, `the number 5`, `an array`).
fn found_text(unexpected: &str) -> String {
    if let Some(text) = unexpected.strip_prefix("string ") {
        let short: String = text.chars().take(41).collect();
        return if short.len() < text.len() {
            format!("the string {short}...\"")
        } else {
            format!("the string {text}")
        };
    }
    let backticked = |prefix: &str| unexpected.strip_prefix(prefix).and_then(|rest| rest.strip_suffix('`'));
    if let Some(number) = backticked("integer `").or_else(|| backticked("floating point `")) {
        return match number.parse::<f64>() {
            Ok(x) => format!("the number {}", number_text(&x)),
            Err(_) => format!("the number {number}"),
        };
    }
    if let Some(boolean) = backticked("boolean `") {
        return boolean.to_string();
    }
    match unexpected {
        "sequence" => "an array",
        "map" => "an object",
        "unit value" => "null",
        other => other,
    }
    .to_string()
}

/// The bytes that end a bare token outside strings: JSON whitespace, structure and quotes.
fn is_delimiter(c: u8) -> bool {
    matches!(c, b' ' | b'\t' | b'\n' | b'\r' | b'{' | b'}' | b'[' | b']' | b',' | b':' | b'"')
}

/// Whether `s` is one of the words people write for non-finite numbers: `NaN`, `Infinity`,
/// `inf`, in any case, optionally signed.
fn is_non_finite_word(s: &str) -> bool {
    let s = s.strip_prefix(['-', '+']).unwrap_or(s);
    ["nan", "inf", "infinity"].iter().any(|word| s.eq_ignore_ascii_case(word))
}

/// The 1-based line and column just after `text`, counting columns in bytes like serde_json.
fn line_column(text: &[u8]) -> (usize, usize) {
    let line = 1 + text.iter().filter(|&&c| c == b'\n').count();
    let start = text.iter().rposition(|&c| c == b'\n').map_or(0, |newline| newline + 1);
    (line, text.len() - start + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(text: &str) -> SceneError {
        parse(text, "t.json").expect_err("the text should not load")
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
            "18446744073709551617",
        ];
        for t in texts {
            let json = format!("{{\"segments\": [{{\"a\": [0, 0], \"b\": [{t}, 1]}}]}}");
            match parse(&json, "n.json") {
                Ok(scene) => assert_eq!(scene.segments[0].b.x, t.parse::<f64>().unwrap_or(0.0)),
                Err(SceneError::CoordinateLimit { .. }) => {}
                Err(e) => panic!("{t}: {e}"),
            }
        }
    }

    #[test]
    fn duplicate_fields_are_rejected_everywhere() {
        let cases = [
            ("{\"segments\": [{\"a\": [0, 0], \"a\": [1, 1], \"b\": [2, 2]}]}", Location::Segment(0), "a"),
            (
                "{\"segments\": [{\"a\": [0, 0], \"b\": [2, 2], \"emission\": 1, \"emission\": 2}]}",
                Location::Segment(0),
                "emission",
            ),
            (
                "{\"version\": 2, \"version\": 2, \"segments\": [{\"a\": [0, 0], \"b\": [1, 1]}]}",
                Location::Top,
                "version",
            ),
            (
                "{\"world\": {\"min\": [0, 0], \"min\": [0, 0], \"max\": [9, 9]}, \"segments\": []}",
                Location::World,
                "min",
            ),
        ];
        for (text, at, name) in cases {
            match err(text) {
                SceneError::DuplicateField { location, field, .. } => {
                    assert_eq!((location, field.as_str()), (at, name), "{text}")
                }
                other => panic!("{text}: {other}"),
            }
        }
        let message = err(cases[0].0).to_string();
        assert_eq!(message, "t.json: segment 0: field \"a\" is given twice");
    }

    #[test]
    fn byte_order_mark_is_accepted_and_counted_in_columns() {
        let text = "\u{feff}{\"segments\": [{\"a\": [0, 0], \"b\": [1, 0]}]}";
        assert!(parse(text, "bom.json").is_ok());
        // The same syntax error, with and without a byte order mark before it.
        let (plain, marked) = (err("{\"segments\" 1}"), err("\u{feff}{\"segments\" 1}"));
        match (plain, marked) {
            (SceneError::Malformed { column: a, .. }, SceneError::Malformed { column: b, .. }) => {
                assert_eq!(b, a + 3)
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn non_finite_tokens_are_found_where_they_are() {
        for token in [
            "NaN",
            "nan",
            "-nan",
            "NAN",
            "Infinity",
            "-Infinity",
            "+Infinity",
            "inf",
            "-INF",
            "1e400",
            "-2.5E+999",
        ] {
            let text = format!("{{\"segments\": [\n {{\"a\": [0, 0], \"b\": [1, {token}]}}]}}");
            match err(&text) {
                SceneError::NonFiniteCoordinate {
                    location: Location::Segment(0),
                    point: "endpoint b",
                    token: t,
                    ..
                } => {
                    assert_eq!(t, token)
                }
                other => panic!("{token}: {other:?}"),
            }
        }
        // Not a non-finite token: a misspelt word, a string, and a broken number.
        for (text, what) in [
            ("{\"segments\": [{\"a\": [0, 0], \"b\": [1, nul]}]}", "malformed"),
            ("{\"segments\": [{\"a\": [0, 0], \"b\": [1, 4e]}]}", "malformed"),
            ("{\"segments\": [{\"a\": [0, 0], \"b\": [1, \"NaN\"]}]}", "string"),
        ] {
            let e = err(text);
            match what {
                "malformed" => assert!(matches!(e, SceneError::Malformed { .. }), "{text}: {e}"),
                _ => assert!(e.to_string().contains("found the string \"NaN\""), "{text}: {e}"),
            }
        }
        // Where a number is not expected at all.
        let e = err("{\"segments\": [{\"a\": NaN, \"b\": [1, 1]}]}");
        assert_eq!(
            e.to_string(),
            "t.json: segment 0: endpoint a must be an array [x, y], found the non-finite number NaN"
        );
        let e = err("{\"segments\": [{\"a\": [0, 0], \"b\": [1, 1], \"emission\": -inf}]}");
        assert_eq!(e.to_string(), "t.json: segment 0: emission -inf must be a finite number >= 0");
        let e = err("{\"world\": {\"min\": [0, Infinity], \"max\": [1, 1]}, \"segments\": []}");
        assert_eq!(e.to_string(), "t.json: world: min has a non-finite coordinate (Infinity)");
    }

    #[test]
    fn the_version_is_reported_first() {
        let e = err("{\"segments\": [{\"a\": [0, 0], \"b\": [\"x\", 1], \"typo\": 1}], \"version\": 3}");
        assert_eq!(
            e.to_string(),
            "t.json: unsupported scene format version 3 (this program reads versions 1 to 2)"
        );
        let e = err("{\"segments\": [{\"a\": [0, 0], \"b\": [1, 1]}], \"version\": \"2\"}");
        assert!(
            matches!(&e, SceneError::UnsupportedVersion { found, .. } if found == "\"2\" (a string)"),
            "{e}"
        );
        let e = err("{\"version\": NaN, \"segments\": [{\"a\": [0, 0], \"b\": [1, 1]}]}");
        assert!(matches!(&e, SceneError::UnsupportedVersion { found, .. } if found == "NaN"), "{e}");
        let e = err("{\"version\": null, \"segments\": [{\"a\": [0, 0], \"b\": [1, 1]}]}");
        assert!(matches!(&e, SceneError::UnsupportedVersion { found, .. } if found == "null"), "{e}");
        for version in ["1", "2", "2.0"] {
            let text =
                format!("{{\"version\": {version}, \"segments\": [{{\"a\": [0, 0], \"b\": [1, 1]}}]}}");
            assert!(parse(&text, "t.json").is_ok(), "{version}");
        }
    }

    #[test]
    fn wrong_types_say_what_was_found() {
        let cases = [
            ("[1, 2]", "the scene must be a JSON object, found an array"),
            ("{\"segments\": 5.5}", "\"segments\" must be an array of segments, found the number 5.5"),
            (
                "{\"segments\": [[[0, 0], [1, 1]]]}",
                "segment 0: the segment must be a JSON object, found an array",
            ),
            (
                "{\"segments\": [{\"a\": [0, null], \"b\": [1, 1]}]}",
                "segment 0: the y coordinate of endpoint a must be a number, found null",
            ),
            (
                "{\"segments\": [{\"a\": [0, 0], \"b\": true}]}",
                "segment 0: endpoint b must be an array [x, y], found true",
            ),
            (
                "{\"segments\": [{\"a\": [0, 0], \"b\": [1, 1], \"reflectance\": null}]}",
                "segment 0: \"reflectance\" must be a number, found null",
            ),
            (
                "{\"world\": [0, 0], \"segments\": []}",
                "world: \"world\" must be a JSON object, found an array",
            ),
            (
                "{\"world\": {\"min\": [0, 0], \"max\": {}}, \"segments\": []}",
                "world: max must be an array [x, y], found an object",
            ),
        ];
        for (text, message) in cases {
            assert_eq!(err(text).to_string(), format!("t.json: {message}"), "{text}");
        }
        let long = format!("{{\"segments\": [{{\"a\": [0, \"{}\"], \"b\": [1, 1]}}]}}", "x".repeat(100));
        assert!(err(&long).to_string().ends_with(&format!("found the string \"{}...\"", "x".repeat(40))));
    }

    #[test]
    fn point_lengths_are_counted() {
        for (point, count) in [("[]", 0), ("[1]", 1), ("[1, 2, 3]", 3), ("[1, 2, \"x\", [4]]", 4)] {
            let text = format!("{{\"segments\": [{{\"a\": [0, 0], \"b\": {point}}}]}}");
            assert!(
                matches!(err(&text), SceneError::BadPoint { count: c, point: "endpoint b", .. } if c == count),
                "{point}"
            );
        }
    }

    #[test]
    fn reading_stops_at_the_limit() {
        // A reader that never ends.
        let e = read_text(std::io::repeat(b' '), "endless", 1000).unwrap_err();
        assert!(matches!(e, SceneError::TooLarge { limit: 1000, .. }), "{e:?}");
        assert_eq!(e.to_string(), "endless: the file is larger than 1000 bytes, the limit for a scene file");
        // Exactly at the limit is accepted.
        let text = "{\"segments\": [{\"a\": [0, 0], \"b\": [1, 1]}]}";
        assert_eq!(read_text(text.as_bytes(), "t.json", text.len() as u64).unwrap(), text);
        let over = read_text(text.as_bytes(), "t.json", text.len() as u64 - 1);
        assert!(matches!(over, Err(SceneError::TooLarge { .. })), "{over:?}");
    }

    #[test]
    fn text_must_be_utf8() {
        let e = read_text(&b"{\n  \"a\xff\": 1}"[..], "t.json", 100).unwrap_err();
        assert!(matches!(e, SceneError::Malformed { line: 2, column: 5, .. }), "{e:?}");
    }
}
