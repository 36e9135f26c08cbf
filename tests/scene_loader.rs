//! Tests of the scene loader, writer and generator: one test per class of bad input, each
//! checking the error variant and that the message names the file and the segment.

use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

use shelling::geom::{Segment, Vec2};
use shelling::scene::*;

/// Writes `text` to a fresh file in the temporary directory and returns its path. The name holds
/// the process id and a counter, so parallel tests and test runs do not collide.
fn temp_scene(stem: &str, text: &str) -> PathBuf {
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let path = std::env::temp_dir().join(format!("shelling-scene-{}-{n}-{stem}.json", std::process::id()));
    std::fs::write(&path, text).expect("cannot write the temporary scene file");
    path
}

/// Loads `text` through a temporary file named after `stem`, removes the file, and returns the
/// error, which the test expects.
fn load_err(stem: &str, text: &str) -> (SceneError, String) {
    let path = temp_scene(stem, text);
    let result = Scene::load(&path);
    let _ = std::fs::remove_file(&path);
    match result {
        Ok(scene) => panic!("{stem}: expected an error, loaded {scene:?}"),
        Err(err) => {
            let message = err.to_string();
            assert!(message.contains(&format!("{stem}.json")), "message does not name the file: {message}");
            (err, message)
        }
    }
}

/// Asserts that `message` names segment `index`.
fn names_segment(message: &str, index: usize) {
    assert!(
        message.contains(&format!("segment {index}")),
        "message does not name segment {index}: {message}"
    );
}

/// A valid two-segment scene with `{}` in place of the second segment's body.
fn with_second(second: &str) -> String {
    format!("{{\"segments\": [\n  {{\"a\": [1, 2], \"b\": [3, 4]}},\n  {{{second}}}\n]}}")
}

fn v(x: f64, y: f64) -> Vec2 {
    Vec2::new(x, y)
}

// ----- Bad input, one class per test. -----

#[test]
fn malformed_json_gives_line_and_column() {
    let text = "{\"segments\": [\n  {\"a\": [1, 2], \"b\": [3, 4]}\n  {\"a\": [5, 6], \"b\": [7, 8]}\n]}";
    let (err, msg) = load_err("malformed", text);
    match err {
        SceneError::Malformed { line, column, .. } => {
            assert_eq!(line, 3);
            assert!(column > 0);
        }
        other => panic!("wrong variant: {other:?}"),
    }
    assert!(msg.contains("malformed JSON at line 3 column"), "{msg}");
    assert!(msg.contains("expected ',' or ']'"), "{msg}");
}

#[test]
fn truncated_file_is_reported_as_truncated() {
    let (err, msg) = load_err("truncated", "{\"segments\": [{\"a\": [1, 2], \"b\": [3,");
    assert!(matches!(err, SceneError::Truncated { line: 1, .. }), "{err:?}");
    assert!(msg.contains("truncated"), "{msg}");
}

#[test]
fn nan_token_is_a_non_finite_coordinate() {
    let (err, msg) = load_err("nan", &with_second("\"a\": [NaN, 2], \"b\": [3, 4]"));
    match &err {
        SceneError::NonFiniteCoordinate { location, point, token, .. } => {
            assert_eq!(*location, Location::Segment(1));
            assert_eq!(*point, "endpoint a");
            assert_eq!(token, "NaN");
        }
        other => panic!("wrong variant: {other:?}"),
    }
    names_segment(&msg, 1);
    assert!(msg.contains("segment 1: endpoint a has a non-finite coordinate (NaN)"), "{msg}");
}

#[test]
fn infinity_tokens_are_non_finite_coordinates() {
    for token in ["Infinity", "-Infinity", "inf", "+inf", "nan"] {
        let (err, msg) = load_err("infinity", &with_second(&format!("\"a\": [1, 2], \"b\": [3, {token}]")));
        match &err {
            SceneError::NonFiniteCoordinate { location, point, token: found, .. } => {
                assert_eq!(*location, Location::Segment(1));
                assert_eq!(*point, "endpoint b");
                assert_eq!(found, token);
            }
            other => panic!("{token}: wrong variant: {other:?}"),
        }
        names_segment(&msg, 1);
    }
}

#[test]
fn overflowing_number_is_a_non_finite_coordinate() {
    let (err, msg) = load_err("overflow", &with_second("\"a\": [1e400, 2], \"b\": [3, 4]"));
    assert!(
        matches!(&err, SceneError::NonFiniteCoordinate { location: Location::Segment(1), token, .. } if token == "1e400"),
        "{err:?}"
    );
    names_segment(&msg, 1);
    assert!(msg.contains("(1e400)"), "{msg}");
}

#[test]
fn non_number_coordinate_is_a_wrong_type() {
    let (err, msg) = load_err("string_coord", &with_second("\"a\": [1, \"two\"], \"b\": [3, 4]"));
    assert!(matches!(&err, SceneError::WrongType { location: Location::Segment(1), .. }), "{err:?}");
    names_segment(&msg, 1);
    assert!(msg.contains("y coordinate of endpoint a"), "{msg}");
    assert!(msg.contains("\"two\""), "{msg}");
}

#[test]
fn point_with_three_numbers_is_a_bad_point() {
    let (err, msg) = load_err("three", &with_second("\"a\": [1, 2], \"b\": [3, 4, 5]"));
    assert!(
        matches!(
            &err,
            SceneError::BadPoint { location: Location::Segment(1), point: "endpoint b", count: 3, .. }
        ),
        "{err:?}"
    );
    names_segment(&msg, 1);
}

#[test]
fn zero_length_segment() {
    let (err, msg) = load_err("zero", &with_second("\"a\": [5, 5], \"b\": [5, 5]"));
    assert!(matches!(&err, SceneError::ZeroLength { segment: 1, .. }), "{err:?}");
    assert!(msg.contains("segment 1 has zero length (a = b = [5, 5])"), "{msg}");
}

#[test]
fn empty_segments_array() {
    let (err, msg) = load_err("empty", "{\"segments\": []}");
    assert!(matches!(err, SceneError::NoSegments { .. }), "{err:?}");
    assert!(msg.contains("the scene has no segments"), "{msg}");
}

#[test]
fn missing_segments_field() {
    let (err, msg) = load_err("missing", "{\"version\": 1}");
    assert!(
        matches!(err, SceneError::MissingField { location: Location::Top, field: "segments", .. }),
        "{err:?}"
    );
    assert!(msg.contains("\"segments\""), "{msg}");
}

#[test]
fn unknown_top_level_field() {
    let (err, msg) = load_err("typo_top", "{\"segmnets\": [{\"a\": [1, 2], \"b\": [3, 4]}]}");
    assert!(
        matches!(&err, SceneError::UnknownField { location: Location::Top, field, .. } if field == "segmnets"),
        "{err:?}"
    );
    assert!(msg.contains("unknown field \"segmnets\""), "{msg}");
}

#[test]
fn unknown_segment_field() {
    let (err, msg) =
        load_err("typo_segment", &with_second("\"a\": [1, 2], \"b\": [3, 4], \"reflectence\": 0.5"));
    assert!(
        matches!(&err, SceneError::UnknownField { location: Location::Segment(1), field, .. } if field == "reflectence"),
        "{err:?}"
    );
    assert!(msg.contains("segment 1: unknown field \"reflectence\""), "{msg}");
}

#[test]
fn unsupported_version() {
    let (err, msg) = load_err("version", "{\"version\": 3, \"segments\": [{\"a\": [1, 2], \"b\": [3, 4]}]}");
    assert!(matches!(&err, SceneError::UnsupportedVersion { found, .. } if found == "3"), "{err:?}");
    assert!(msg.contains("version 3"), "{msg}");
    assert!(msg.contains("reads versions 1 to 2"), "{msg}");
}

#[test]
fn unsupported_version_is_reported_before_other_problems() {
    let text = "{\"segments\": [{\"a\": [1, 2], \"b\": [3, 4], \"colour\": 1}], \"version\": 0}";
    let (err, _) = load_err("version_last", text);
    assert!(matches!(&err, SceneError::UnsupportedVersion { found, .. } if found == "0"), "{err:?}");
}

#[test]
fn duplicate_field() {
    let (err, msg) = load_err("duplicate", &with_second("\"a\": [1, 2], \"b\": [3, 4], \"b\": [5, 6]"));
    assert!(
        matches!(&err, SceneError::DuplicateField { location: Location::Segment(1), field, .. } if field == "b"),
        "{err:?}"
    );
    assert!(msg.contains("segment 1: field \"b\" is given twice"), "{msg}");
}

#[test]
fn null_is_not_an_absent_value() {
    let (err, msg) = load_err("null", &with_second("\"a\": [1, 2], \"b\": [3, 4], \"emission\": null"));
    assert!(matches!(&err, SceneError::WrongType { location: Location::Segment(1), .. }), "{err:?}");
    assert!(msg.contains("segment 1: \"emission\" must be a number, found null"), "{msg}");
}

#[test]
fn segment_written_as_an_array_is_a_wrong_type() {
    let text = "{\"segments\": [{\"a\": [1, 2], \"b\": [3, 4]}, [[1, 2], [3, 4]]]}";
    let (err, msg) = load_err("array_segment", text);
    assert!(matches!(&err, SceneError::WrongType { location: Location::Segment(1), .. }), "{err:?}");
    assert!(msg.contains("segment 1: the segment must be a JSON object, found an array"), "{msg}");
}

#[test]
fn coordinate_over_the_limit() {
    let (err, msg) = load_err("limit", &with_second("\"a\": [1, 2], \"b\": [3e12, 4]"));
    assert!(
        matches!(&err, SceneError::CoordinateLimit { location: Location::Segment(1), value, .. } if *value == 3e12),
        "{err:?}"
    );
    names_segment(&msg, 1);
    assert!(msg.contains("coordinate 3e12 of endpoint b exceeds the limit 1e9"), "{msg}");
}

#[test]
fn world_with_min_not_below_max() {
    let (err, msg) = load_err(
        "world",
        "{\"world\": {\"min\": [0, 10], \"max\": [100, 10]}, \"segments\": [{\"a\": [1, 2], \"b\": [3, 4]}]}",
    );
    assert!(matches!(err, SceneError::InvalidWorld { .. }), "{err:?}");
    assert!(msg.contains("[0, 10]..[100, 10]"), "{msg}");
}

#[test]
fn segment_outside_the_world() {
    let text = "{\"world\": {\"min\": [0, 0], \"max\": [1024, 1024]}, \"segments\": [\
                {\"a\": [1, 2], \"b\": [3, 4]}, {\"a\": [1000, 2], \"b\": [1024, 4]}]}";
    let (err, msg) = load_err("outside", text);
    assert!(matches!(&err, SceneError::OutsideWorld { segment: 1, point: "endpoint b", .. }), "{err:?}");
    assert!(msg.contains("segment 1 lies outside the world [0, 0]..[1024, 1024]"), "{msg}");
}

#[test]
fn reflectance_outside_unit_interval() {
    let (err, msg) =
        load_err("reflectance", &with_second("\"a\": [1, 2], \"b\": [3, 4], \"reflectance\": 1.5"));
    assert!(
        matches!(&err, SceneError::BadMaterial { segment: 1, field: "reflectance", value, .. } if value == "1.5"),
        "{err:?}"
    );
    names_segment(&msg, 1);
    assert!(msg.contains("segment 1: reflectance 1.5 must be a finite number in [0, 1)"), "{msg}");
}

/// Loads a scene whose second segment has `field: value` and checks the material error.
fn bad_material(stem: &str, field: &str, value: &str, shown: &str) {
    let (err, msg) =
        load_err(stem, &with_second(&format!("\"a\": [1, 2], \"b\": [3, 4], \"{field}\": {value}")));
    assert!(
        matches!(&err, SceneError::BadMaterial { segment: 1, field: f, value: v, .. } if *f == field && v == shown),
        "{field} {value}: {err:?}"
    );
    names_segment(&msg, 1);
    assert!(msg.contains(&format!("{field} {shown} must be a finite number")), "{msg}");
}

#[test]
fn reflectance_one_is_rejected_in_both_versions() {
    bad_material("reflectance_one", "reflectance", "1", "1");
    bad_material("reflectance_one_point_zero", "reflectance", "1.0", "1");
    let text = "{\"version\": 1, \"segments\": [{\"a\": [1, 2], \"b\": [3, 4], \"reflectance\": 1}]}";
    let (err, _) = load_err("reflectance_one_v1", text);
    assert!(matches!(&err, SceneError::BadMaterial { segment: 0, field: "reflectance", .. }), "{err:?}");
}

#[test]
fn negative_reflectance() {
    bad_material("reflectance_negative", "reflectance", "-0.25", "-0.25");
}

#[test]
fn non_finite_reflectance() {
    bad_material("reflectance_nan", "reflectance", "NaN", "NaN");
    bad_material("reflectance_inf", "reflectance", "Infinity", "Infinity");
    bad_material("reflectance_overflow", "reflectance", "1e400", "1e400");
}

#[test]
fn negative_emission() {
    let (err, msg) = load_err("emission", &with_second("\"a\": [1, 2], \"b\": [3, 4], \"emission\": -1"));
    assert!(matches!(&err, SceneError::BadMaterial { segment: 1, field: "emission", .. }), "{err:?}");
    names_segment(&msg, 1);
    bad_material("emission_negative", "emission", "-0.5", "-0.5");
}

#[test]
fn non_finite_emission() {
    bad_material("emission_nan", "emission", "nan", "nan");
    bad_material("emission_inf", "emission", "Infinity", "Infinity");
    bad_material("emission_minus_inf", "emission", "-Infinity", "-Infinity");
    bad_material("emission_overflow", "emission", "1e400", "1e400");
}

#[test]
fn materials_of_version_1_and_2_are_read_alike() {
    for version in [1, 2] {
        let text = format!(
            "{{\"version\": {version}, \"segments\": [{{\"a\": [1, 2], \"b\": [3, 4], \"reflectance\": 0.999, \
             \"emission\": 250}}, {{\"a\": [5, 6], \"b\": [7, 8]}}]}}"
        );
        let scene = Scene::from_json_str(&text, "materials.json").expect("materials");
        assert_eq!(scene.materials[0], Material { reflectance: Some(0.999), emission: Some(250.0) });
        assert_eq!(scene.material(1).reflectance_or_default(), DEFAULT_REFLECTANCE);
        assert_eq!(scene.material(1).emission_or_default(), DEFAULT_EMISSION);
        let written = scene.to_json();
        assert!(written.contains(&format!("\"version\": {SCENE_VERSION}")), "{written}");
        assert_eq!(Scene::from_json_str(&written, "again.json").expect("written"), scene);
    }
}

#[test]
fn a_file_that_never_ends_is_refused() {
    let path = std::path::Path::new("/dev/zero");
    if !path.exists() {
        return;
    }
    let err = Scene::load(path).unwrap_err();
    assert!(matches!(err, SceneError::TooLarge { limit: MAX_SCENE_BYTES, .. }), "{err:?}");
    let msg = err.to_string();
    assert!(msg.starts_with("/dev/zero: the file is larger than 268435456 bytes (256 MiB)"), "{msg}");
}

#[test]
fn missing_file_is_an_io_error() {
    let path =
        std::env::temp_dir().join(format!("shelling-scene-{}-does-not-exist.json", std::process::id()));
    let err = Scene::load(&path).unwrap_err();
    assert!(
        matches!(&err, SceneError::Io { action: "read", source, .. } if source.kind() == std::io::ErrorKind::NotFound),
        "{err:?}"
    );
    let msg = err.to_string();
    assert!(msg.contains("does-not-exist.json"), "{msg}");
    assert_eq!(err.name(), path.display().to_string());
}

// ----- Good input and round trips. -----

#[test]
fn minimal_shape_is_accepted() {
    let scene = Scene::from_json_str("{\"segments\": [{\"a\": [1, 2], \"b\": [3, 4]}]}", "min.json")
        .expect("minimal scene");
    assert_eq!(scene.segments, vec![Segment::new(v(1.0, 2.0), v(3.0, 4.0))]);
    assert_eq!(scene.materials, vec![Material::default()]);
    assert_eq!(scene.world, None);
    assert_eq!(scene.len(), 1);
    assert!(!scene.is_empty());
    assert_eq!(scene.bounds(), Bounds::new(v(1.0, 2.0), v(3.0, 4.0)));
}

#[test]
fn full_shape_round_trips_exactly() {
    let text = r#"{
        "version": 1,
        "world": {"min": [-0.5, 0], "max": [1024, 1000.25]},
        "segments": [
            {"a": [0.1, 0.2], "b": [0.30000000000000004, 999.9999999999999], "reflectance": 0.5, "emission": 0.0},
            {"a": [1e-7, 3.141592653589793], "b": [700, 2.718281828459045], "emission": 12.75},
            {"a": [5, 5], "b": [6, 5], "reflectance": 0.75}
        ]
    }"#;
    let scene = Scene::from_json_str(text, "full.json").expect("full scene");
    assert_eq!(scene.world, Some(Bounds::new(v(-0.5, 0.0), v(1024.0, 1000.25))));
    assert_eq!(scene.segments[0].b.x, 0.30000000000000004);
    assert_eq!(scene.materials[1], Material { reflectance: None, emission: Some(12.75) });
    let json = scene.to_json();
    assert!(json.contains("\"version\": 2"), "{json}");
    let again = Scene::from_json_str(&json, "again.json").expect("written scene loads");
    assert_eq!(again, scene);
    assert_eq!(again.to_json(), json);
    // Bit-exact, not merely equal: compare the bit patterns of every coordinate.
    for (s, t) in scene.segments.iter().zip(&again.segments) {
        for (p, q) in [(s.a, t.a), (s.b, t.b)] {
            assert_eq!(p.x.to_bits(), q.x.to_bits());
            assert_eq!(p.y.to_bits(), q.y.to_bits());
        }
    }
}

#[test]
fn save_and_load_round_trip() {
    let scene = generate(50, 30.0, 7, PAPER_WORLD).expect("generated scene");
    let path = temp_scene("save", "");
    scene.save(&path).expect("save");
    let loaded = Scene::load(&path);
    let _ = std::fs::remove_file(&path);
    assert_eq!(loaded.expect("load"), scene);
}

#[test]
fn new_validates_like_the_loader() {
    let ok = Scene::new(vec![Segment::new(v(0.0, 0.0), v(1.0, 0.0))]).expect("valid");
    assert_eq!(ok.materials.len(), 1);
    let err =
        Scene::new(vec![Segment::new(v(0.0, 0.0), v(1.0, 0.0)), Segment::new(v(0.0, f64::NAN), v(1.0, 0.0))])
            .unwrap_err();
    assert!(
        matches!(&err, SceneError::NonFiniteCoordinate { location: Location::Segment(1), .. }),
        "{err:?}"
    );
    assert!(err.to_string().starts_with("<memory>: segment 1:"), "{err}");
    assert!(matches!(Scene::new(vec![]), Err(SceneError::NoSegments { .. })));
}

// ----- The generator. -----

#[test]
fn generator_is_reproducible() {
    let a = generate(200, 40.0, 42, PAPER_WORLD).expect("seed 42");
    let b = generate(200, 40.0, 42, PAPER_WORLD).expect("seed 42 again");
    let c = generate(200, 40.0, 43, PAPER_WORLD).expect("seed 43");
    assert_eq!(a, b);
    assert_ne!(a.segments, c.segments);
    assert_eq!(a.world, Some(PAPER_WORLD));
    assert_eq!(a.len(), 200);
}

#[test]
fn generator_lengths_and_containment() {
    let world = Bounds::new(v(-100.0, 50.0), v(300.0, 250.0));
    for (length, seed) in [(1.0, 1), (150.0, 2), (199.0, 3)] {
        let scene = generate(500, length, seed, world).expect("generated scene");
        for seg in &scene.segments {
            let relative = (seg.length() - length).abs() / length;
            assert!(relative <= 1e-9, "length {} for {length}", seg.length());
            assert!(world.contains(seg.a) && world.contains(seg.b), "{seg:?}");
        }
        scene.validate("check").expect("a generated scene is valid");
    }
}

#[test]
fn generator_rejects_bad_parameters() {
    let name_ok = |err: &SceneError| assert!(err.to_string().starts_with("generator: "), "{err}");

    let err = generate(0, 10.0, 1, PAPER_WORLD).unwrap_err();
    assert!(matches!(err, SceneError::NoSegments { .. }), "{err:?}");
    name_ok(&err);

    for length in [0.0, -1.0, f64::NAN, f64::INFINITY, 1024.0, 5000.0] {
        let err = generate(10, length, 1, PAPER_WORLD).unwrap_err();
        assert!(matches!(err, SceneError::InvalidLength { .. }), "{length}: {err:?}");
        name_ok(&err);
    }
    // The limit is the shorter side of the world.
    let wide = Bounds::new(v(0.0, 0.0), v(1000.0, 10.0));
    assert!(matches!(generate(1, 20.0, 1, wide), Err(SceneError::InvalidLength { .. })));
    assert!(generate(1, 9.5, 1, wide).is_ok());

    let flat = Bounds::new(v(0.0, 0.0), v(100.0, 0.0));
    let err = generate(10, 1.0, 1, flat).unwrap_err();
    assert!(matches!(err, SceneError::InvalidWorld { .. }), "{err:?}");
    name_ok(&err);

    let nan_world = Bounds::new(v(0.0, f64::NAN), v(100.0, 100.0));
    let err = generate(10, 1.0, 1, nan_world).unwrap_err();
    assert!(matches!(err, SceneError::NonFiniteCoordinate { .. }), "{err:?}");
    name_ok(&err);
}
