//! End-to-end tests of the `shelling` command line: every subcommand is run as a child process
//! (the binary Cargo builds for the integration tests) and its exit status, standard output and
//! standard error are checked. Every failure must exit non-zero, say what is wrong on standard
//! error, print nothing on standard output and never panic.

use serde_json::Value;
use shelling::counters::Counters;
use shelling::scene::Scene;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const METHODS: [&str; 4] = ["brute", "conventional", "stochastic", "deterministic"];

/// A fresh directory under the system's temporary directory, named after the test and the process,
/// removed when dropped.
pub(crate) struct TempDir(pub(crate) PathBuf);

impl TempDir {
    pub(crate) fn new(test: &str) -> TempDir {
        let path = std::env::temp_dir().join(format!("shelling-cli-{test}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&path);
        std::fs::create_dir_all(&path).expect("cannot create the temporary directory");
        TempDir(path)
    }

    pub(crate) fn join(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

pub(crate) fn path_arg(p: &Path) -> &str {
    p.to_str().expect("temporary path is not UTF-8")
}

/// Runs the binary with `args`.
pub(crate) fn shelling(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_shelling")).args(args).output().expect("cannot run the shelling binary")
}

pub(crate) fn text(bytes: &[u8]) -> String {
    String::from_utf8(bytes.to_vec()).expect("output is not UTF-8")
}

/// Runs `args`, asserts success, and returns standard output.
pub(crate) fn ok(args: &[&str]) -> String {
    let out = shelling(args);
    let (stdout, stderr) = (text(&out.stdout), text(&out.stderr));
    assert!(out.status.success(), "shelling {args:?} failed ({}):\n{stderr}", out.status);
    assert!(!stderr.contains("panicked"), "shelling {args:?} panicked:\n{stderr}");
    stdout
}

/// Runs `args`, asserts a clean failure (non-zero exit, no panic, nothing on standard output, a
/// message on standard error containing every string of `expect`), and returns standard error.
pub(crate) fn fails(args: &[&str], expect: &[&str]) -> String {
    let out = shelling(args);
    let (stdout, stderr) = (text(&out.stdout), text(&out.stderr));
    assert!(!out.status.success(), "shelling {args:?} should fail; stdout:\n{stdout}");
    assert_ne!(out.status.code(), Some(101), "shelling {args:?} exited as a panic:\n{stderr}");
    assert!(!stderr.contains("panicked"), "shelling {args:?} panicked:\n{stderr}");
    assert!(stdout.is_empty(), "shelling {args:?} failed but wrote to stdout:\n{stdout}");
    assert!(stderr.starts_with("error:"), "shelling {args:?}: stderr is not an error message:\n{stderr}");
    for e in expect {
        assert!(stderr.contains(e), "shelling {args:?}: stderr does not mention {e:?}:\n{stderr}");
    }
    stderr
}

/// Writes a generated scene into `dir` and returns its path.
pub(crate) fn gen_scene(dir: &TempDir, name: &str, count: usize, length: f64, seed: u64) -> PathBuf {
    let path = dir.join(name);
    let (count, length, seed) = (count.to_string(), length.to_string(), seed.to_string());
    ok(&["scene", "gen", "--count", &count, "--length", &length, "--seed", &seed, "--out", path_arg(&path)]);
    path
}

pub(crate) fn parse_json(stdout: &str, what: &str) -> Value {
    serde_json::from_str(stdout).unwrap_or_else(|e| panic!("{what}: stdout is not JSON ({e}):\n{stdout}"))
}

/// One ray of the `trace --json` output: its hit and distance.
pub(crate) type Hit = (Option<u64>, Option<f64>);

/// Checks the shape of a `trace --json` document (method, rays, counters) and returns the hits.
pub(crate) fn check_trace_json(doc: &Value, method: &str, rays: usize) -> Vec<Hit> {
    let obj = doc.as_object().expect("the trace JSON is not an object");
    assert_eq!(obj["method"].as_str(), Some(method), "method field");

    let counters = obj["counters"].as_object().expect("counters is not an object");
    let mut names: Vec<&str> = counters.keys().map(String::as_str).collect();
    let mut expected = Counters::NAMES.to_vec();
    names.sort_unstable();
    expected.sort_unstable();
    assert_eq!(names, expected, "counter names");
    for (name, v) in counters {
        assert!(v.is_number(), "counter {name} is not a number: {v}");
    }

    let list = obj["rays"].as_array().expect("rays is not an array");
    assert_eq!(list.len(), rays, "number of rays");
    let mut hits = Vec::with_capacity(rays);
    for (i, ray) in list.iter().enumerate() {
        assert_eq!(ray["index"].as_u64(), Some(i as u64), "ray {i}: index");
        let dir = ray["direction"].as_array().unwrap_or_else(|| panic!("ray {i}: direction is not an array"));
        assert_eq!(dir.len(), 2, "ray {i}: direction must have 2 components");
        let (dx, dy) = (dir[0].as_f64().expect("direction x"), dir[1].as_f64().expect("direction y"));
        assert!(((dx * dx + dy * dy).sqrt() - 1.0).abs() < 1e-9, "ray {i}: direction is not a unit vector");
        let hit = match &ray["hit"] {
            Value::Null => None,
            v => Some(v.as_u64().unwrap_or_else(|| panic!("ray {i}: hit {v} is not an integer"))),
        };
        let t = match &ray["t"] {
            Value::Null => None,
            v => Some(v.as_f64().unwrap_or_else(|| panic!("ray {i}: t {v} is not a number"))),
        };
        assert_eq!(hit.is_some(), t.is_some(), "ray {i}: hit and t must be both null or both set");
        if let Some(t) = t {
            assert!(t.is_finite() && t > 0.0, "ray {i}: t = {t}");
        }
        hits.push((hit, t));
    }
    let actual = hits.iter().filter(|(h, _)| h.is_some()).count() as u64;
    assert_eq!(
        counters["actual_intersections"].as_u64(),
        Some(actual),
        "actual_intersections counts the hits"
    );
    hits
}

/// Traces with every method and checks that all agree with brute force, ray by ray; returns the
/// hits and the last document.
pub(crate) fn trace_all_methods(
    scene: &Path,
    from: &[&str],
    extra: &[&str],
    rays: usize,
) -> (Vec<Hit>, Value) {
    let n = rays.to_string();
    let mut reference: Option<Vec<Hit>> = None;
    let mut last = Value::Null;
    for method in METHODS {
        let mut args = vec!["trace", "--scene", path_arg(scene)];
        args.extend_from_slice(from);
        args.extend_from_slice(&["--rays", &n, "--method", method, "--json"]);
        args.extend_from_slice(extra);
        let doc = parse_json(&ok(&args), method);
        let hits = check_trace_json(&doc, method, rays);
        match &reference {
            None => reference = Some(hits),
            Some(r) => {
                for (i, (a, b)) in r.iter().zip(&hits).enumerate() {
                    assert_eq!(a, b, "{method} differs from brute on ray {i} ({from:?} {extra:?})");
                }
            }
        }
        last = doc;
    }
    (reference.unwrap(), last)
}

// ----- scene gen -----

#[test]
fn cli_scene_gen_writes_a_reproducible_loadable_file() {
    let dir = TempDir::new("scene_gen_file");
    let a = gen_scene(&dir, "a.json", 50, 16.0, 3);
    let b = gen_scene(&dir, "b.json", 50, 16.0, 3);
    let c = gen_scene(&dir, "c.json", 50, 16.0, 4);
    let scene = Scene::load(&a).expect("the generated scene does not load");
    assert_eq!(scene.segments.len(), 50);
    for (i, s) in scene.segments.iter().enumerate() {
        let len = s.length();
        assert!((len - 16.0).abs() < 1e-6, "segment {i} has length {len}");
    }
    let bytes = |p: &Path| std::fs::read(p).unwrap();
    assert_eq!(bytes(&a), bytes(&b), "the same seed must give the same bytes");
    assert_ne!(bytes(&a), bytes(&c), "a different seed must give a different scene");
}

#[test]
fn cli_scene_gen_prints_json_without_out() {
    let dir = TempDir::new("scene_gen_stdout");
    let file = gen_scene(&dir, "s.json", 50, 16.0, 3);
    let stdout = ok(&["scene", "gen", "--count", "50", "--length", "16", "--seed", "3"]);
    let printed = parse_json(&stdout, "scene gen");
    assert_eq!(printed["segments"].as_array().map(Vec::len), Some(50));
    let saved: Value = serde_json::from_slice(&std::fs::read(&file).unwrap()).unwrap();
    assert_eq!(printed, saved, "stdout and --out must hold the same scene");
    // What was printed loads as a scene too.
    let copy = dir.join("copy.json");
    std::fs::write(&copy, &stdout).unwrap();
    assert_eq!(Scene::load(&copy).expect("printed scene does not load").segments.len(), 50);
}

#[test]
fn cli_scene_gen_rejects_bad_values() {
    fails(&["scene", "gen", "--count", "0"], &["count"]);
    fails(&["scene", "gen", "--length", "0"], &["length", "0"]);
    fails(&["scene", "gen", "--length", "nan"], &["length", "NaN"]);
    fails(&["scene", "gen", "--length", "5000"], &["length", "5000"]);
    fails(&["scene", "gen", "--length", "-3"], &["length", "-3"]);
    fails(&["scene", "gen", "--count", "x"], &["--count"]);
    let dir = TempDir::new("scene_gen_bad");
    let nowhere = dir.join("no/such/dir/s.json");
    let err =
        fails(&["scene", "gen", "--count", "5", "--out", path_arg(&nowhere)], &["s.json", "cannot write"]);
    assert_eq!(err.matches("os error").count(), 1, "the I/O error is repeated:\n{err}");
}

// ----- trace -----

#[test]
fn cli_trace_json_every_method_agrees_with_brute() {
    let dir = TempDir::new("trace_json");
    let scene = gen_scene(&dir, "s.json", 300, 32.0, 3);
    let mut hits = 0;
    for k in ["0", "7", "123"] {
        let (h, doc) = trace_all_methods(&scene, &["--source", k], &[], 64);
        hits += h.iter().filter(|(hit, _)| hit.is_some()).count();
        let patch: u64 = k.parse().unwrap();
        assert_eq!(doc["source"]["patch"].as_u64(), Some(patch));
        assert_eq!(doc["source"]["ray_set"].as_str(), Some("angle"));
        assert!(h.iter().all(|(hit, _)| *hit != Some(patch)), "a source patch hit itself");
        // Every ray lies in the half-circle around the source's normal.
        let n = &doc["source"]["normal"];
        let (nx, ny) = (n[0].as_f64().unwrap(), n[1].as_f64().unwrap());
        for ray in doc["rays"].as_array().unwrap() {
            let d = &ray["direction"];
            let dot = nx * d[0].as_f64().unwrap() + ny * d[1].as_f64().unwrap();
            assert!(dot > -1e-9, "ray {} points behind the source", ray["index"]);
        }
    }
    assert!(hits > 0, "the test scene gave no hit at all: the agreement check is empty");
}

#[test]
fn cli_trace_json_is_reproducible() {
    let dir = TempDir::new("trace_repro");
    let scene = gen_scene(&dir, "s.json", 300, 32.0, 3);
    for method in METHODS {
        let args = [
            "trace",
            "--scene",
            path_arg(&scene),
            "--source",
            "7",
            "--rays",
            "64",
            "--method",
            method,
            "--json",
        ];
        assert_eq!(ok(&args), ok(&args), "{method}: two runs differ");
    }
}

#[test]
fn cli_trace_sine_ray_set() {
    let dir = TempDir::new("trace_sine");
    let scene = gen_scene(&dir, "s.json", 300, 32.0, 3);
    let (_, doc) = trace_all_methods(&scene, &["--source", "7"], &["--ray-set", "sine"], 64);
    assert_eq!(doc["source"]["ray_set"].as_str(), Some("sine"));
    let (angle, _) = trace_all_methods(&scene, &["--source", "7"], &[], 64);
    let (sine, _) = trace_all_methods(&scene, &["--source", "7"], &["--ray-set", "sine"], 64);
    assert_ne!(angle, sine, "--ray-set sine changed nothing");
}

#[test]
fn cli_trace_free_origin() {
    let dir = TempDir::new("trace_origin");
    let scene = gen_scene(&dir, "s.json", 300, 32.0, 3);

    let (hits, doc) = trace_all_methods(&scene, &["--origin", "512,512", "--normal", "0,1"], &[], 64);
    assert!(doc["source"]["patch"].is_null(), "a free origin has no patch");
    assert_eq!(doc["source"]["origin"], serde_json::json!([512.0, 512.0]));
    assert_eq!(doc["source"]["normal"], serde_json::json!([0.0, 1.0]));
    assert!(hits.iter().any(|(h, _)| h.is_some()), "nothing hit from the centre of the scene");

    // Negative values, both as separate words and with '='; the normal comes back normalised.
    for from in [
        &["--origin", "-10,500", "--normal", "1,-0.5"][..],
        &["--origin=-10,500", "--normal=1,-0.5"][..],
        &["--normal", "1,-0.5", "--origin", "-10,500"][..],
    ] {
        let (_, doc) = trace_all_methods(&scene, from, &[], 64);
        assert_eq!(doc["source"]["origin"], serde_json::json!([-10.0, 500.0]), "{from:?}");
        let n = &doc["source"]["normal"];
        let (nx, ny) = (n[0].as_f64().unwrap(), n[1].as_f64().unwrap());
        let s = 1.25f64.sqrt();
        assert!((nx - 1.0 / s).abs() < 1e-12 && (ny + 0.5 / s).abs() < 1e-12, "{from:?}: normal {n}");
    }
}

#[test]
fn cli_trace_summary_without_json() {
    let dir = TempDir::new("trace_summary");
    let scene = gen_scene(&dir, "s.json", 300, 32.0, 3);
    for method in METHODS {
        let out =
            ok(&["trace", "--scene", path_arg(&scene), "--source", "7", "--rays", "64", "--method", method]);
        assert!(serde_json::from_str::<Value>(&out).is_err(), "{method}: summary is JSON:\n{out}");
        assert!(out.contains("64 rays"), "{method}: summary does not give the ray count:\n{out}");
        assert!(out.contains(&format!("traced with {method}")), "{method}: summary lacks the method:\n{out}");
        assert!(out.contains("read before") && out.contains("ADLC"), "{method}: no counters table:\n{out}");
        assert!(out.lines().any(|l| l.starts_with(method)), "{method}: no counters row:\n{out}");
    }
}

#[test]
fn cli_trace_rejects_missing_and_malformed_scene_files() {
    let dir = TempDir::new("trace_bad_file");
    let missing = dir.join("missing-scene.json");
    let err = fails(&["trace", "--scene", path_arg(&missing), "--source", "0"], &["missing-scene.json"]);
    assert_eq!(err.matches("os error").count(), 1, "the I/O error is repeated:\n{err}");

    let truncated = dir.join("truncated-scene.json");
    std::fs::write(&truncated, "{\"segments\": [").unwrap();
    fails(&["trace", "--scene", path_arg(&truncated), "--source", "0"], &["truncated-scene.json"]);

    let garbage = dir.join("garbage-scene.json");
    std::fs::write(&garbage, "{\"segmnets\": []}").unwrap();
    fails(&["trace", "--scene", path_arg(&garbage), "--source", "0"], &["garbage-scene.json", "segmnets"]);

    fails(&["trace", "--scene", path_arg(&dir.0), "--source", "0"], &["cannot read"]);
}

#[test]
fn cli_trace_rejects_bad_sources() {
    let dir = TempDir::new("trace_bad_source");
    let scene = gen_scene(&dir, "s.json", 50, 16.0, 3);
    let s = path_arg(&scene);
    let t = |extra: &[&str], expect: &[&str]| {
        let mut args = vec!["trace", "--scene", s];
        args.extend_from_slice(extra);
        fails(&args, expect);
    };
    t(&["--source", "50"], &["50", "50 segments"]);
    t(&["--source", "-1"], &["--source"]);
    t(&["--source", "0", "--rays", "0"], &["rays", "0"]);
    t(&["--origin", "1,1", "--normal", "0,0"], &["normal"]);
    t(&["--origin", "nan,1", "--normal", "0,1"], &["--origin", "nan"]);
    t(&["--origin", "1,2,3", "--normal", "0,1"], &["--origin", "1,2,3"]);
    t(&["--origin", "1,x", "--normal", "0,1"], &["--origin", "\"x\""]);
    t(&["--origin", "1,2", "--normal", "inf,1"], &["--normal", "inf"]);
    t(&["--source", "0", "--origin", "1,2", "--normal", "0,1"], &["--source", "--origin"]);
    t(&["--source", "0", "--normal", "0,1"], &["--source", "--normal"]);
    t(&[], &["--source", "--origin"]);
    t(&["--origin", "1,2"], &["--normal"]);
    t(&["--normal", "0,1"], &["--origin"]);
}

#[test]
fn cli_trace_rejects_bad_options() {
    let dir = TempDir::new("trace_bad_options");
    let scene = gen_scene(&dir, "s.json", 50, 16.0, 3);
    let s = path_arg(&scene);
    let t = |extra: &[&str], expect: &[&str]| {
        let mut args = vec!["trace", "--scene", s, "--source", "0", "--rays", "16"];
        args.extend_from_slice(extra);
        fails(&args, expect);
    };
    t(&["--method", "bogus"], &["--method", "bogus"]);
    t(&["--ray-set", "cosine"], &["--ray-set", "cosine"]);
    t(&["--shell-depth", "-1"], &["--shell-depth", "-1"]);
    t(&["--shell-depth", "0"], &["--shell-depth"]);
    t(&["--shell-depth", "nan"], &["--shell-depth"]);
    t(&["--cells-per-segment", "0"], &["--cells-per-segment"]);
    t(&["--cells-per-segment", "-2"], &["--cells-per-segment", "-2"]);
    t(&["--max-sector", "0"], &["--max-sector"]);
    t(&["--rays", "-5"], &["--rays"]);
    fails(&["trace", "--source", "0"], &["--scene"]);
}

// ----- help -----

#[test]
fn cli_help_mentions_every_option() {
    let cases: [(&[&str], &[&str]); 5] = [
        (
            &["trace"],
            &[
                "--scene",
                "--source",
                "--origin",
                "--normal",
                "--rays",
                "--ray-set",
                "--method",
                "--json",
                "--cells-per-segment",
                "--shell-depth",
                "--max-sector",
                "brute",
                "conventional",
                "stochastic",
                "deterministic",
                "angle",
                "sine",
            ],
        ),
        (&["scene", "gen"], &["--count", "--length", "--seed", "--out"]),
        (
            &["figures"],
            &[
                "--out",
                "--dim",
                "--sizes",
                "--seeds",
                "--sources",
                "--rays",
                "--count",
                "--lengths",
                "--ray-set",
                "--quiet",
                "--cells-per-segment",
                "--shell-depth",
                "--max-sector",
            ],
        ),
        (&["demo"], &["--seed", "--length", "--source", "--rays", "--tc", "--vcd", "--verilog"]),
        (
            &["cosim"],
            &[
                "--scene",
                "--source",
                "--origin",
                "--normal",
                "--rays",
                "--ray-set",
                "--method",
                "--tc",
                "--cache",
                "--vcd",
                "--vcd-from",
                "--vcd-to",
                "--json",
            ],
        ),
    ];
    for (command, options) in cases {
        let mut args = command.to_vec();
        args.push("--help");
        let help = ok(&args);
        for o in options {
            assert!(help.contains(o), "{command:?} --help does not mention {o}:\n{help}");
        }
    }
    let top = ok(&["--help"]);
    for c in ["demo", "scene", "trace", "figures", "cosim", "machine", "agreement", "export-verilog"] {
        assert!(top.contains(c), "--help does not list {c}:\n{top}");
    }
}

// ----- figures -----

#[test]
fn cli_figures_writes_csv_and_svgs() {
    let dir = TempDir::new("figures");
    let out = dir.join("figs");
    let args = [
        "figures",
        "--out",
        path_arg(&out),
        "--seeds",
        "1",
        "--sources",
        "2",
        "--rays",
        "32",
        "--count",
        "100",
        "--lengths",
        "8,32",
        "--cosim-sources",
        "1",
        "--tc",
        "1,4",
        "--quiet",
    ];
    ok(&args);
    let cycles = std::fs::read_to_string(out.join("cycles.csv")).expect("no cycles.csv");
    assert!(cycles.starts_with("length,method,tc,cache_lines,sources,cycles,"), "cycles.csv:\n{cycles}");
    // 2 lengths × 2 cache settings × 2 T_c × 3 techniques.
    assert_eq!(cycles.lines().count(), 1 + 2 * 2 * 2 * 3, "cycles.csv:\n{cycles}");
    let csv = std::fs::read_to_string(out.join("figures.csv")).expect("no figures.csv");
    let lines: Vec<&str> = csv.lines().collect();
    assert!(
        lines[0].starts_with("length,method,sources,patches_read_before_screening"),
        "header: {}",
        lines[0]
    );
    assert_eq!(lines.len(), 1 + 2 * 3, "figures.csv:\n{csv}");
    let columns = lines[0].split(',').count();
    for length in ["8", "32"] {
        for method in ["conventional", "stochastic", "deterministic"] {
            let prefix = format!("{length},{method},2,");
            let row = lines.iter().find(|l| l.starts_with(&prefix));
            let row = row.unwrap_or_else(|| panic!("no row {prefix}... in figures.csv:\n{csv}"));
            assert_eq!(row.split(',').count(), columns, "row {row}");
        }
    }
    for svg in [
        "fig07_k1.svg",
        "fig08_patches_read_before_screening.svg",
        "fig09_patches_read_after_screening.svg",
        "fig10_cells_traversed.svg",
        "fig11_intersection_computations.svg",
        "fig13_adlc.svg",
        "cycles_speedup_shared.svg",
        "cycles_efficiency_shared.svg",
    ] {
        let body = std::fs::read_to_string(out.join(svg)).unwrap_or_else(|e| panic!("{svg}: {e}"));
        assert!(body.contains("<svg"), "{svg} is not an SVG");
    }
}

#[test]
fn cli_figures_rejects_bad_values() {
    let dir = TempDir::new("figures_bad");
    let out = dir.join("figs");
    let o = path_arg(&out);
    let base = ["figures", "--out", o, "--seeds", "1", "--rays", "8", "--count", "100", "--quiet"];
    let t = |extra: &[&str], expect: &[&str]| {
        let mut args = base.to_vec();
        args.extend_from_slice(extra);
        fails(&args, expect);
    };
    t(&["--sources", "0"], &["sources"]);
    t(&["--lengths", "8,-8"], &["length", "-8"]);
    t(&["--lengths", "-8,8"], &["length", "-8"]);
    t(&["--lengths", "8,x"], &["--lengths", "x"]);
    t(&["--cells-per-segment", "0"], &["--cells-per-segment"]);
    t(&["--max-sector", "0"], &["--max-sector"]);
    t(&["--tc", "1,0"], &["--tc must be between 1 and 1024", "0"]);
    t(&["--tc", "4,4"], &["--tc", "4 twice"]);
    t(&["--tc", "x"], &["--tc", "x"]);
    t(&["--cache-lines", "5000"], &["--cache-lines", "between 1 and 1024", "5000"]);
    fails(&["figures", "--out", o, "--seeds", "1", "--rays", "2048", "--count", "100", "--quiet"], &["2048"]);
    fails(&["figures", "--quiet"], &["--out"]);
    // --out naming an existing file.
    let file = dir.join("a-file");
    std::fs::write(&file, "x").unwrap();
    fails(
        &["figures", "--out", path_arg(&file), "--seeds", "1", "--sources", "1", "--rays", "8", "--quiet"],
        &["a-file"],
    );
}

// ----- demo -----

#[test]
fn cli_demo_prints_the_table() {
    let dir = TempDir::new("demo");
    let (vcd, verilog) = (dir.join("demo.vcd"), dir.join("v"));
    let out =
        ok(&["demo", "--rays", "128", "--tc", "4", "--vcd", path_arg(&vcd), "--verilog", path_arg(&verilog)]);
    for method in METHODS {
        assert!(out.lines().any(|l| l.starts_with(method)), "demo: no row for {method}:\n{out}");
    }
    assert!(out.contains("every technique returned the brute-force nearest hit"), "demo:\n{out}");
    assert!(out.contains("128 rays"), "demo:\n{out}");
    // The co-simulation rows: conventional twice (without and with cache), stochastic once.
    let rows: Vec<&str> = out.lines().skip_while(|l| !l.starts_with("co-simulation")).collect();
    assert_eq!(rows.iter().filter(|l| l.starts_with("conventional")).count(), 2, "demo:\n{out}");
    assert_eq!(rows.iter().filter(|l| l.starts_with("stochastic")).count(), 1, "demo:\n{out}");
    assert!(out.contains("every PE hit equals the bit-true model's"), "demo:\n{out}");
    let text = std::fs::read_to_string(&vcd).expect("the demo writes its VCD");
    assert!(text.contains("$scope module uut") && text.contains("$enddefinitions"), "the demo's VCD header");
    assert!(verilog.join("files.f").exists() && verilog.join("processing_element.v").exists());
}

#[test]
fn cli_demo_rejects_bad_values() {
    fails(&["demo", "--rays", "0"], &["rays"]);
    fails(&["demo", "--source", "5000"], &["5000", "1000 segments"]);
    fails(&["demo", "--length", "-1"], &["length", "-1"]);
}

// ----- co-simulation -----

#[test]
fn cli_cosim_json_is_the_trace_json_plus_the_hardware() {
    let dir = TempDir::new("cosim");
    let scene = gen_scene(&dir, "s.json", 300, 32.0, 4);
    let fixed = parse_json(
        &ok(&[
            "trace",
            "--scene",
            path_arg(&scene),
            "--source",
            "7",
            "--rays",
            "128",
            "--arith",
            "fixed",
            "--json",
        ]),
        "fixed",
    );
    let want = check_trace_json(&fixed, "stochastic", 128);
    for (extra, cached) in [(&[][..], false), (&["--cache", "512"][..], true)] {
        let mut args = vec![
            "cosim",
            "--scene",
            path_arg(&scene),
            "--source",
            "7",
            "--rays",
            "128",
            "--tc",
            "8",
            "--json",
            "--engine",
            "rust-hdl",
        ];
        args.extend_from_slice(extra);
        let doc = parse_json(&ok(&args), "cosim");
        assert_eq!(check_trace_json(&doc, "stochastic", 128), want, "the PE's hits are the bit-true trace's");
        let hw = doc["hardware"].as_object().expect("hardware object");
        for k in [
            "cycles",
            "intersection_busy_cycles",
            "pipeline_efficiency",
            "patch_loads",
            "cache_hits",
            "stall_cycles",
        ] {
            assert!(hw[k].is_number(), "hardware.{k}: {:?}", hw.get(k));
        }
        let loads = hw["patch_loads"].as_u64().unwrap();
        assert_eq!(Some(loads), doc["counters"]["patches_read_before_screening"].as_u64());
        // The bound <= the ideal in-order PE <= the PE.
        let (bound, ideal) = (doc["bound_cycles"].as_u64().unwrap(), doc["inorder_cycles"].as_u64().unwrap());
        assert!(bound <= ideal && ideal <= hw["cycles"].as_u64().unwrap(), "{bound} {ideal} {hw:?}");
        let eff = hw["pipeline_efficiency"].as_f64().unwrap();
        assert!(eff > 0.0 && eff <= 1.0, "efficiency {eff}");
        if !cached {
            assert!(hw["cycles"].as_u64().unwrap() >= 8 * loads, "{hw:?}");
        }
        // The compiled PE: the same document, cycle counts included.
        let n = args.len();
        args[n - extra.len() - 1] = "verilator";
        assert_eq!(parse_json(&ok(&args), "cosim, compiled"), doc, "{extra:?}: rust-hdl's, then Verilator's");
    }
    let text = ok(&[
        "cosim",
        "--scene",
        path_arg(&scene),
        "--source",
        "7",
        "--rays",
        "64",
        "--method",
        "deterministic",
    ]);
    assert!(
        text.contains("every hit equals the bit-true model's") && text.contains("pipeline efficiency"),
        "{text}"
    );
}

/// `cosim --pes N`: the source's rays in N sectors on the machine of N PEs, every hit checked:
/// the run `machine --deal sectors` makes of that one source.
#[test]
fn cli_cosim_runs_a_source_on_several_pes() {
    let dir = TempDir::new("cosim-pes");
    let scene = gen_scene(&dir, "s.json", 200, 32.0, 8);
    let run = |pes: &'static str| {
        let args = [
            "cosim",
            "--scene",
            path_arg(&scene),
            "--source",
            "7",
            "--rays",
            "96",
            "--method",
            "conventional",
            "--tc",
            "4",
            "--cache",
            "50",
            "--engine",
            "verilator",
            "--json",
            "--pes",
            pes,
        ];
        parse_json(&ok(&args), "cosim")
    };
    let one = run("1");
    let three = run("3");
    let n = |v: &Value, k: &str| v[k].as_u64();
    assert_eq!((n(&three, "pes"), n(&three, "sources"), n(&three, "parts")), (Some(3), Some(1), Some(3)));
    assert_eq!(n(&three, "rays"), Some(96));
    assert!(n(&three, "tests") > Some(0) && n(&one["hardware"], "tests") > Some(0));
    let machine = [
        "machine",
        "--scene",
        path_arg(&scene),
        "--first",
        "7",
        "--count",
        "1",
        "--rays",
        "96",
        "--method",
        "conventional",
        "--tc",
        "4",
        "--cache",
        "50",
        "--engine",
        "verilator",
        "--json",
        "--pes",
        "3",
        "--deal",
        "sectors",
        "--layout",
        "file",
        "--place",
        "index",
    ];
    assert_eq!(parse_json(&ok(&machine), "machine"), three, "`machine --deal sectors` on the one source");
    let text = ok(&["cosim", "--scene", path_arg(&scene), "--source", "7", "--rays", "32", "--pes", "2"]);
    assert!(text.contains("on 2 PEs") && text.contains("every hit equals the bit-true model's"), "{text}");
}

#[test]
fn cli_cosim_rejects_bad_options() {
    let dir = TempDir::new("cosim-bad");
    let scene = gen_scene(&dir, "s.json", 100, 16.0, 5);
    let base = ["cosim", "--scene", path_arg(&scene), "--source", "3"];
    let with =
        |extra: &[&'static str]| -> Vec<&str> { base.iter().copied().chain(extra.iter().copied()).collect() };
    fails(&with(&["--method", "brute"]), &["brute", "no hardware mapping"]);
    fails(&with(&["--cache", "5000"]), &["--cache", "between 1 and 1024", "5000"]);
    fails(&with(&["--tc", "0"]), &["--tc", "0"]);
    fails(&with(&["--rays", "2048"]), &["2048", "1024"]);
    fails(&with(&["--pes", "9"]), &["--pes", "1 and 8", "9"]);
    fails(&with(&["--pes", "4", "--rays", "3"]), &["--pes 4", "one ray a PE", "3 rays"]);
    fails(
        &with(&["--vcd", "x.vcd", "--vcd-from", "10", "--vcd-to", "5"]),
        &["VCD window", "--vcd-from 10", "--vcd-to 5"],
    );
    fails(&with(&["--engine", "verilator", "--vcd", "x.vcd"]), &["--vcd", "--engine rust-hdl"]);
    fails(&with(&["--engine", "icarus"]), &["icarus", "rust-hdl", "verilator"]);
}

/// A negative number given to an unsigned option is refused naming that option, on every
/// command (without `allow_negative_numbers` the parser took `-1` for an unknown flag and named
/// no option).
#[test]
fn cli_negative_numbers_are_refused_by_their_option() {
    let dir = TempDir::new("negative");
    let scene = gen_scene(&dir, "s.json", 100, 16.0, 5);
    let s = path_arg(&scene);
    for (args, option) in [
        (vec!["cosim", "--scene", s, "--source", "3", "--tc", "-1"], "'--tc <TC>'"),
        (vec!["cosim", "--scene", s, "--source", "3", "--cache", "-4"], "'--cache <PATCHES>'"),
        (vec!["cosim", "--scene", s, "--source", "3", "--pes", "-2"], "'--pes <PES>'"),
        (vec!["cosim", "--scene", s, "--source", "3", "--vcd-from", "-1"], "'--vcd-from <VCD_FROM>'"),
        (vec!["machine", "--scene", s, "--tc", "-16"], "'--tc <TC>'"),
        (vec!["demo", "--tc", "-1"], "'--tc <TC>'"),
        (vec!["radiosity", "--scene", s, "--on-pe", "--tc", "-1"], "'--tc <TC>'"),
        (vec!["radiosity", "--scene", s, "--on-pe", "--clock-mhz", "-5"], "--clock-mhz"),
        (vec!["scene", "gen", "--dim", "-3"], "'--dim <DIM>'"),
    ] {
        fails(&args, &[option, "-"]);
    }
}

/// An output file whose directory is missing, or which is a directory, is refused before any
/// work, naming the option and the path (a long solve used to end in the write's error).
#[test]
fn cli_output_files_are_checked_before_any_work() {
    let dir = TempDir::new("outputs");
    let scene = gen_scene(&dir, "s.json", 100, 16.0, 5);
    let s = path_arg(&scene);
    let missing = dir.join("no-such-dir").join("x.svg");
    let missing = path_arg(&missing);
    let is_dir = path_arg(&dir.0);
    fails(&["radiosity", "--scene", s, "--svg", missing], &["--svg", "no-such-dir", "does not exist"]);
    fails(&["radiosity", "--scene", s, "--svg", is_dir], &["--svg", "is a directory"]);
    fails(&["form-factors", "--scene", s, "--rows", "0..2", "--out", missing], &["--out", "does not exist"]);
    fails(&["cosim", "--scene", s, "--source", "3", "--vcd", missing], &["--vcd", "does not exist"]);
    fails(&["demo", "--vcd", missing], &["--vcd", "does not exist"]);
}

// ----- machine -----

/// The machine's JSON: sources, parts and counts consistent with the options; more PEs take
/// fewer cycles for the same sources and the same tests; rust-hdl's PEs and the compiled ones
/// the same cycles.
#[test]
fn cli_machine_runs_sources_on_several_pes() {
    let dir = TempDir::new("machine");
    let scene = gen_scene(&dir, "s.json", 200, 32.0, 6);
    let run = |pes: &str, engine: &str, deal: &str, place: &str| {
        let args = [
            "machine",
            "--scene",
            path_arg(&scene),
            "--pes",
            pes,
            "--first",
            "10",
            "--count",
            "6",
            "--rays",
            "64",
            "--tc",
            "2",
            "--cache",
            "64",
            "--deal",
            deal,
            "--place",
            place,
            "--engine",
            engine,
            "--json",
        ];
        parse_json(&ok(&args), "machine")
    };
    let one = run("1", "verilator", "blocks", "lines");
    let three = run("3", "verilator", "blocks", "lines");
    assert_eq!((one["sources"].as_u64(), one["parts"].as_u64()), (Some(6), Some(1)));
    assert_eq!((three["sources"].as_u64(), three["parts"].as_u64()), (Some(6), Some(1)));
    let sectors = run("3", "verilator", "sectors", "lines");
    assert_eq!((sectors["sources"].as_u64(), sectors["parts"].as_u64()), (Some(6), Some(3)));
    assert_eq!(sectors["rays"], one["rays"], "the sectors of a source are its rays");
    assert_eq!(sectors["source_cycles"].as_array().map(Vec::len), Some(6));
    assert_eq!(one["rays"].as_u64(), Some(6 * 64));
    assert_eq!(one["tests"], three["tests"], "the same sources, the same ray-patch tests");
    assert!(one["tests"].as_u64().unwrap() > 0);
    let cycles = |v: &Value| v["cycles"].as_u64().unwrap();
    // Two sources a PE: its first setup and its last readout overlap no commands of its own, so
    // three PEs are well under 3x one here (1.49x).
    assert!(cycles(&three) * 4 < cycles(&one) * 3, "3 PEs {} cycles, 1 PE {}", cycles(&three), cycles(&one));
    assert_eq!(run("3", "rust-hdl", "blocks", "lines"), three, "rust-hdl's PEs, then the compiled ones");
    let index = run("3", "verilator", "blocks", "index");
    assert_eq!(index["tests"], three["tests"], "where the patches are changes no test");
    let text = ok(&["machine", "--scene", path_arg(&scene), "--pes", "2", "--count", "3", "--rays", "32"]);
    assert!(text.contains("every hit equals the bit-true model's") && text.contains("host memory"), "{text}");
}

#[test]
fn cli_machine_rejects_bad_options() {
    let dir = TempDir::new("machine-bad");
    let scene = gen_scene(&dir, "s.json", 100, 16.0, 5);
    let base = ["machine", "--scene", path_arg(&scene)];
    let with =
        |extra: &[&'static str]| -> Vec<&str> { base.iter().copied().chain(extra.iter().copied()).collect() };
    fails(&with(&["--pes", "9"]), &["--pes", "1 and 8", "9"]);
    fails(&with(&["--pes", "0"]), &["--pes", "0"]);
    fails(&with(&["--count", "0"]), &["--count", "0"]);
    fails(&with(&["--first", "99", "--count", "2"]), &["--count", "between 1 and 1", "2"]);
    fails(&with(&["--first", "100"]), &["--first", "100", "100 segments"]);
    fails(&with(&["--method", "brute"]), &["brute", "no hardware mapping"]);
    fails(&with(&["--cache", "5000"]), &["--cache", "between 1 and 1024", "5000"]);
    fails(&with(&["--tc", "0"]), &["--tc", "0"]);
    fails(&with(&["--rays", "2048"]), &["2048", "1024"]);
    fails(&with(&["--deal", "random"]), &["random", "blocks", "interleaved", "sectors"]);
    fails(&with(&["--place", "random"]), &["random", "index", "lines"]);
    fails(
        &with(&["--deal", "sectors", "--pes", "4", "--rays", "3"]),
        &["--rays 3", "--pes 4", "one ray a PE"],
    );
    // A 3-line cache spreads 50000 patches over 4 addresses for every 3: beyond 16-bit ids.
    let big = gen_scene(&dir, "big.json", 50_000, 1.0, 5);
    for cmd in [&["machine"][..], &["cosim", "--source", "0"]] {
        let args: Vec<&str> =
            cmd.iter().copied().chain(["--scene", path_arg(&big), "--cache", "3"]).collect();
        fails(&args, &["--cache 3", "16-bit ids", "power of two"]);
    }
}

/// `machine --vcd`: the machine's RTL writes the window, every signal of
/// `waveforms/machine.gtkw` is in it, and the arbiter's traffic shows (both PEs request, the
/// host port answers, each answer routed to one PE).
#[test]
fn cli_machine_writes_a_vcd_that_machine_gtkw_opens() {
    use shelling_testbench::waves::{gtkw_signals, Waves};
    let dir = TempDir::new("machine-vcd");
    let scene = gen_scene(&dir, "s.json", 200, 32.0, 6);
    let vcd = dir.join("m.vcd");
    let base =
        ["machine", "--scene", path_arg(&scene), "--pes", "2", "--count", "2", "--rays", "64", "--tc", "4"];
    let v = path_arg(&vcd);
    let text = ok(&[&base[..], &["--vcd", v, "--vcd-from", "60", "--vcd-to", "400"]].concat());
    assert!(text.contains("rust-hdl simulation"), "{text}");
    let gtkw = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("waveforms/machine.gtkw");
    let signals = gtkw_signals(&gtkw).expect("waveforms/machine.gtkw is readable");
    assert!(signals.len() >= 20, "{signals:?}");
    let names: Vec<&str> = signals.iter().map(String::as_str).collect();
    let waves = Waves::read(&vcd, &names).unwrap_or_else(|e| panic!("{}", e.message()));
    assert_eq!(waves.cycles(), 340);
    let high = |s: &str| waves.get(s).unwrap().iter().filter(|&&v| v != 0).count();
    for s in ["uut.host_req", "uut.host_valid", "uut.arbiter.pe_req$0", "uut.arbiter.pe_req$1"] {
        assert!(high(s) > 0, "{s} never high in the window");
    }
    // Each host answer goes to one PE a clock later (the arbiter's answer register).
    let get = |s: &str| waves.get(s).unwrap().to_vec();
    let (host, v0, v1) =
        (get("uut.host_valid"), get("uut.arbiter.pe_valid$0"), get("uut.arbiter.pe_valid$1"));
    for c in 0..host.len() - 1 {
        assert!(v0[c + 1] + v1[c + 1] <= 1, "cycle {c}: an answer to both PEs");
        assert_eq!(host[c], v0[c + 1] + v1[c + 1], "window cycle {c}: the host's answer, then the PEs'");
    }
    fails(&[&base[..], &["--vcd", v, "--engine", "verilator"]].concat(), &["--vcd", "rust-hdl"]);
    fails(&[&base[..], &["--vcd", v, "--vcd-from", "100000000"]].concat(), &["--vcd-from", "100000000"]);
}

#[test]
fn cli_machine_figures_sweep_and_reject_bad_options() {
    let dir = TempDir::new("machine-figures");
    let out = dir.join("mf");
    let text = ok(&[
        "machine-figures",
        "--out",
        path_arg(&out),
        "--lengths",
        "32",
        "--sources",
        "4",
        "--pes",
        "1,2",
        "--tc",
        "4",
        "--caches",
        "off,64",
        "--engine",
        "verilator",
    ]);
    assert!(text.contains("every hit checked"), "{text}");
    let csv = std::fs::read_to_string(out.join("machine.csv")).expect("machine.csv written");
    // 3 techniques × 2 caches × 2 PE counts in blocks, and 3 techniques × (2 other deals and
    // the file's layout).
    assert_eq!(csv.lines().count(), 1 + 12 + 9, "{csv}");
    assert!(csv.lines().any(|l| l.starts_with("32,stochastic,4,64,2,blocks,hilbert,4,")), "{csv}");
    assert!(csv.lines().any(|l| l.starts_with("32,deterministic,16,64,8,blocks,file,4,")), "{csv}");
    for f in [
        "machine.md",
        "machine_speedup_cache_off.svg",
        "machine_speedup_cache_64.svg",
        "machine_port_busy.svg",
    ] {
        assert!(out.join(f).exists(), "{f} written");
    }
    let base = ["machine-figures", "--out", path_arg(&out)];
    let with =
        |extra: &[&'static str]| -> Vec<&str> { base.iter().copied().chain(extra.iter().copied()).collect() };
    fails(&with(&["--caches", "5000"]), &["--caches", "between 1 and 1024", "5000"]);
    fails(&with(&["--caches", "big"]), &["--caches big"]);
    fails(&with(&["--pes", "2,4"]), &["--pes", "include 1"]);
    fails(&with(&["--pes", "1,9"]), &["--pes", "9"]);
    fails(&with(&["--tc", "0"]), &["--tc", "0"]);
    fails(&with(&["--sources", "0"]), &["--sources", "0"]);
    fails(&with(&["--lengths", "2000"]), &["--lengths", "1024"]);
}

// ----- fixed point, agreement, Verilog export -----

#[test]
fn cli_trace_fixed_arithmetic() {
    let dir = TempDir::new("fixed");
    let scene = gen_scene(&dir, "s.json", 300, 32.0, 3);
    let float = parse_json(
        &ok(&["trace", "--scene", path_arg(&scene), "--source", "5", "--rays", "256", "--json"]),
        "float",
    );
    let out = ok(&[
        "trace",
        "--scene",
        path_arg(&scene),
        "--source",
        "5",
        "--rays",
        "256",
        "--arith",
        "fixed",
        "--json",
    ]);
    let fixed = parse_json(&out, "fixed");
    assert_eq!(fixed["arith"], "fixed");
    assert_eq!(float["arith"], "float");
    let f = check_trace_json(&float, "stochastic", 256);
    let x = check_trace_json(&fixed, "stochastic", 256);
    let same = f.iter().zip(&x).filter(|(a, b)| a.0 == b.0).count();
    assert!(same >= 250, "only {same} of 256 rays agree between float and fixed");
    // A scene beyond the fixed-point window is refused with the offending value named.
    let big = dir.join("big.json");
    std::fs::write(&big, r#"{"segments": [{"a": [0, 0], "b": [10, 0]}, {"a": [100, 5], "b": [5000, 5]}]}"#)
        .unwrap();
    fails(
        &["trace", "--scene", path_arg(&big), "--source", "0", "--arith", "fixed"],
        &["fixed-point", "segment 1 endpoint b x", "5000"],
    );
}

#[test]
fn cli_agreement_reports_every_length() {
    let out = ok(&["agreement", "--sources", "2", "--rays", "128"]);
    for l in ["4", "8", "16", "32", "64", "128"] {
        assert!(out.lines().any(|line| line.trim_start().starts_with(l)), "no row for length {l}:\n{out}");
    }
    fails(&["agreement", "--sources", "0"], &["--sources"]);
}

#[test]
fn cli_export_verilog_writes_every_block_and_a_file_list() {
    let dir = TempDir::new("export");
    let out = dir.join("v");
    ok(&["export-verilog", "--out", path_arg(&out)]);
    let list = std::fs::read_to_string(out.join("files.f")).expect("files.f");
    assert!(!list.is_empty());
    for name in list.lines() {
        let v = std::fs::read_to_string(out.join(name)).expect("listed file exists");
        let module = name.trim_end_matches(".v");
        assert!(v.contains(&format!("module {module}(")), "{name} lacks module {module}");
    }
}
