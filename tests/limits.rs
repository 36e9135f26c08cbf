//! Issue 15, part 3: no parameter can make the command line lie or hang. Every numeric option
//! and origin has a range checked up front, worded by `shelling::limits` and naming the option
//! as typed; the accepted extremes still agree with brute force; origins far outside the grid
//! trace quickly; a closed pipe or a full disk ends the program without a panic; a failed
//! command leaves no partial output; and messages speak the user's words.

use crate::cli::{fails, gen_scene, ok, path_arg, shelling, text, trace_all_methods, TempDir};
use shelling::geom::Vec2;
use shelling::grid::GridParams;
use shelling::limits;
use shelling::rays::{Bundle, RaySet, Source};
use shelling::run::GriddedScene;
use shelling::scene::{self, Scene};
use shelling::staged::Staged;
use shelling::trace::{Method, ShellParams, TraceError};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The numbers `lo` and `hi` of a message "... must be between lo and hi ...".
fn range_of(message: &str) -> (String, String) {
    let rest = message.split("must be between ").nth(1).unwrap_or_else(|| panic!("no range in {message:?}"));
    let mut words = rest.split_whitespace();
    let lo = words.next().unwrap().to_string();
    assert_eq!(words.next(), Some("and"), "{message}");
    let hi = words.next().unwrap().trim_end_matches(',').to_string();
    (lo, hi)
}

#[test]
fn limits_one_wording_for_every_range() {
    assert_eq!(
        limits::check_range("--rays", 0usize, 1, limits::MAX_BUNDLE_RAYS),
        Err("--rays must be between 1 and 1048576, got 0".to_string())
    );
    // The same limit reads the same from two commands.
    let dir = TempDir::new("limits_wording");
    let scene = gen_scene(&dir, "s.json", 50, 16.0, 3);
    let s = path_arg(&scene);
    let a = fails(&["trace", "--scene", s, "--source", "0", "--rays", "2000000"], &["--rays"]);
    let b = fails(&["agreement", "--rays", "2000000"], &["--rays"]);
    assert_eq!(a, b, "trace and agreement word --rays differently");
    assert_eq!(a.trim(), "error: --rays must be between 1 and 1048576, got 2000000");
}

#[test]
fn limits_tuning_extremes_agree_with_brute_force() {
    let dir = TempDir::new("limits_extremes");
    let scene = gen_scene(&dir, "s.json", 300, 32.0, 11);
    let s = path_arg(&scene);
    let from = ["--source", "17"];
    // The shell depth's range depends on the scene: read it from the refusal of a bad value.
    let err = fails(&["trace", "--scene", s, "--source", "17", "--shell-depth", "1e-12"], &["--shell-depth"]);
    let (lo, hi) = range_of(&err);
    let err = fails(&["trace", "--scene", s, "--source", "17", "--shell-depth", "1e12"], &["--shell-depth"]);
    assert_eq!(range_of(&err), (lo.clone(), hi.clone()), "one range for both ends");
    let cases: [&[&str]; 6] = [
        &["--shell-depth", &lo],
        &["--shell-depth", &hi],
        &["--cells-per-segment", "0.001"],
        &["--cells-per-segment", "1024"],
        &["--max-sector", "1"],
        &["--max-sector", "1048576"],
    ];
    for extra in cases {
        let (hits, _) = trace_all_methods(&scene, &from, extra, 256);
        assert!(hits.iter().any(|h| h.0.is_some()), "{extra:?}: nothing hit");
    }
    // Just outside each range: refused, naming the option and the range.
    let t = |extra: &[&str], expect: &[&str]| {
        let mut args = vec!["trace", "--scene", s, "--source", "17"];
        if !extra.contains(&"--rays") {
            args.extend_from_slice(&["--rays", "16"]);
        }
        args.extend_from_slice(extra);
        fails(&args, expect)
    };
    t(&["--cells-per-segment", "0.0009"], &["--cells-per-segment must be between 0.001 and 1024", "0.0009"]);
    t(&["--cells-per-segment", "1025"], &["--cells-per-segment must be between 0.001 and 1024", "1025"]);
    t(&["--max-sector", "1048577"], &["--max-sector must be between 1 and 1048576", "1048577"]);
    t(&["--rays", "0"], &["--rays must be between 1 and 1048576, got 0"]);
    // λ·N beyond the grid's 2^22 cells.
    let big = gen_scene(&dir, "big.json", 5000, 4.0, 2);
    fails(
        &["trace", "--scene", path_arg(&big), "--source", "0", "--rays", "8", "--cells-per-segment", "1000"],
        &["--cells-per-segment", "4194304"],
    );
}

#[test]
fn limits_library_refuses_what_the_cli_refuses() {
    let scene = scene::generate(200, 16.0, 5, scene::PAPER_WORLD).unwrap();
    let p = GriddedScene::new(scene, GridParams::default());
    let bundle = p.patch_bundle(3, RaySet::Angle, 64).unwrap();
    for depth in [1e-9, 1e9] {
        let params = ShellParams { shell_depth: Some(depth), ..ShellParams::default() };
        for m in Method::ALL {
            match p.trace(m, &bundle, &params) {
                Err(TraceError::InvalidParams(e)) => assert!(e.contains("shell depth"), "{e}"),
                other => panic!("{m} with shell depth {depth}: {other:?}"),
            }
        }
    }
    let params = ShellParams { max_sector: usize::MAX, ..ShellParams::default() };
    assert!(p.trace(Method::Stochastic, &bundle, &params).is_err(), "an unbounded sector is refused");
    // A grid never has more than 2^22 cells, whatever λ the library is given.
    let q = GriddedScene::new(p.scene.clone(), GridParams { cells_per_segment: 1e9, cells_per_axis: None });
    assert!(q.grid.len() <= limits::MAX_GRID_CELLS, "{} cells", q.grid.len());
}

#[test]
fn limits_origin_outside_the_coordinate_range_is_refused() {
    let dir = TempDir::new("limits_origin");
    let scene = gen_scene(&dir, "s.json", 50, 16.0, 3);
    let s = path_arg(&scene);
    for origin in ["2e9,0", "0,-1.5e9", "1e300,1e300"] {
        fails(
            &["trace", "--scene", s, "--origin", origin, "--normal", "0,1"],
            &["--origin", "between -1000000000 and 1000000000"],
        );
        fails(
            &["cosim", "--scene", s, "--origin", origin, "--normal", "0,1", "--rays", "8"],
            &["--origin", "between -1000000000 and 1000000000"],
        );
    }
    fails(&["trace", "--scene", s, "--source", "50"], &["--source must be between 0 and 49", "50 segments"]);
}

#[test]
fn limits_origins_far_outside_the_grid_trace_quickly_and_agree() {
    let dir = TempDir::new("limits_far");
    let scene = gen_scene(&dir, "s.json", 300, 32.0, 4);
    for (origin, normal) in [("-1e9,512", "1,0"), ("5000,5000", "-1,-1"), ("1e9,1e9", "-1,-1")] {
        let start = Instant::now();
        trace_all_methods(&scene, &["--origin", origin, "--normal", normal], &[], 1024);
        assert!(start.elapsed() < Duration::from_secs(60), "{origin}: {:?}", start.elapsed());
    }
    // Near enough to hit, far enough that most shells lie before the grid: the shelling
    // techniques skip those and still find brute force's hits.
    let (hits, _) = trace_all_methods(&scene, &["--origin", "-20000,512", "--normal", "1,0"], &[], 4096);
    assert!(hits.iter().any(|h| h.0.is_some()), "nothing hit from (-20000, 512)");
    // In the library: the shells skipped are still counted as shells every ray crossed.
    let sc = Scene::load(&scene).unwrap();
    let p = GriddedScene::new(sc, GridParams::default());
    let bundle =
        Bundle::new(Source::at(Vec2::new(-1e6, 512.0), Vec2::new(1.0, 0.0)).unwrap(), RaySet::Angle, 256)
            .unwrap();
    let r = p.trace(Method::Stochastic, &bundle, &ShellParams::default()).unwrap();
    assert!(r.stats.shells > 1000 * r.stats.sectors, "{:?}", r.stats);
}

#[test]
fn limits_costs_are_bounded() {
    let dir = TempDir::new("limits_costs");
    let scene = gen_scene(&dir, "s.json", 100, 16.0, 5);
    let s = path_arg(&scene);
    let vcd = dir.join("w.vcd");
    let v = path_arg(&vcd);
    let cosim = |extra: &[&str], expect: &[&str]| {
        let mut args = vec!["cosim", "--scene", s, "--source", "3"];
        if !extra.contains(&"--rays") {
            args.extend_from_slice(&["--rays", "16"]);
        }
        args.extend_from_slice(extra);
        fails(&args, expect)
    };
    cosim(&["--tc", "0"], &["--tc must be between 1 and 1024, got 0"]);
    cosim(&["--tc", "1025"], &["--tc must be between 1 and 1024, got 1025"]);
    cosim(&["--rays", "1025"], &["--rays must be between 1 and 1024", "1025"]);
    cosim(&["--cache", "8192"], &["--cache must be between 1 and 1024, got 8192"]);
    cosim(&["--cache", "0"], &["--cache must be between 1 and 1024, got 0"]);
    cosim(&["--vcd", v, "--vcd-from", "5", "--vcd-to", "5"], &["--vcd-to", "--vcd-from", "1000000"]);
    cosim(
        &["--vcd", v, "--vcd-from", "0", "--vcd-to", "1000001"],
        &["--vcd-to must be between 1 and 1000000"],
    );
    assert!(!vcd.exists(), "a refused window writes no VCD");
    fails(&["scene", "gen", "--count", "0"], &["--count must be between 1 and 1048576, got 0"]);
    fails(&["scene", "gen", "--count", "1048577"], &["--count must be between 1 and 1048576"]);
    fails(&["scene", "gen", "--length", "1024"], &["--length", "less than 1024", "1024"]);
    fails(&["demo", "--tc", "5000"], &["--tc must be between 1 and 1024"]);
    fails(&["demo", "--rays", "2048"], &["--rays must be between 1 and 1024"]);
    fails(&["demo", "--source", "1000"], &["--source must be between 0 and 999"]);
    fails(
        &["agreement", "--seeds", "1000", "--sources", "1000", "--rays", "1048576"],
        &["--seeds × lengths"],
    );
    fails(&["agreement", "--sources", "1001"], &["--sources must be between 1 and 1000"]);
    let out = dir.join("figs");
    let o = path_arg(&out);
    let figures = |extra: &[&str], expect: &[&str]| {
        let mut args = vec!["figures", "--out", o, "--quiet"];
        args.extend_from_slice(extra);
        fails(&args, expect);
        assert!(!out.exists(), "a refused figures run creates no directory");
    };
    figures(&["--seeds", "1001"], &["--seeds must be between 1 and 1000"]);
    figures(&["--count", "2000000"], &["--count must be between 1 and 1048576"]);
    figures(&["--seeds", "1000", "--count", "100000"], &["--seeds × lengths × --count", "16777216"]);
    figures(
        &["--seeds", "1000", "--sources", "1000", "--cosim-sources", "0"],
        &["--seeds × lengths × --sources"],
    );
    figures(&["--tc", "1,2000"], &["--tc must be between 1 and 1024, got 2000"]);
    figures(&["--cosim-sources", "1000", "--tc", "1,2,3,4,5,6,7,8"], &["co-simulations", "4096"]);
    figures(&["--cache-lines", "8192"], &["--cache-lines must be between 1 and 1024"]);
    figures(&["--lengths", "8,2000"], &["--lengths", "less than 1024", "2000"]);
    figures(&["--cosim-sources", "2000"], &["--cosim-sources must be between 0 and 1000"]);
}

#[test]
fn limits_a_closed_pipe_or_a_full_disk_does_not_panic() {
    let dir = TempDir::new("limits_pipe");
    let scene = gen_scene(&dir, "s.json", 300, 32.0, 4);
    let s = path_arg(&scene);
    // `shelling trace ... --json | head -1`: the reader goes away after one line.
    let mut child = Command::new(env!("CARGO_BIN_EXE_shelling"))
        .args(["trace", "--scene", s, "--source", "1", "--rays", "65536", "--json"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdout = child.stdout.take().unwrap();
    let mut first = [0u8; 1];
    std::io::Read::read_exact(&mut stdout, &mut first).unwrap();
    drop(stdout);
    let out = child.wait_with_output().unwrap();
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "closed pipe: {} {stderr}", out.status);
    assert!(stderr.is_empty(), "closed pipe: stderr {stderr:?}");
    // Standard output on a full disk: one line of error.
    for args in [
        &["trace", "--scene", s, "--source", "1", "--json"][..],
        &["trace", "--scene", s, "--source", "1"][..],
        &["scene", "gen", "--count", "10"][..],
    ] {
        let full = std::fs::OpenOptions::new().write(true).open("/dev/full").unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_shelling")).args(args).stdout(full).output().unwrap();
        let stderr = text(&out.stderr);
        assert!(!out.status.success() && out.status.code() != Some(101), "{args:?}: {}", out.status);
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(stderr.starts_with("error: writing to standard output: "), "{args:?}: {stderr}");
    }
}

#[test]
fn limits_failed_commands_leave_no_partial_output() {
    let dir = TempDir::new("limits_partial");
    let scene = gen_scene(&dir, "s.json", 100, 16.0, 5);
    let s = path_arg(&scene);
    let vcd = dir.join("w.vcd");
    // A window past the run's last cycle: an error, and no VCD (nor its temporary) is left.
    let base = ["cosim", "--scene", s, "--source", "3", "--rays", "16", "--engine", "rust-hdl", "--vcd"];
    let mut args = base.to_vec();
    args.extend_from_slice(&[path_arg(&vcd), "--vcd-from", "900000", "--vcd-to", "900100"]);
    fails(&args, &["--vcd-from 900000", "beyond the run"]);
    let names: Vec<_> = std::fs::read_dir(&dir.0).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names, vec![std::ffi::OsString::from("s.json")], "left behind: {names:?}");
    // A window inside the run: the VCD is written.
    let mut args = base.to_vec();
    args.extend_from_slice(&[path_arg(&vcd), "--vcd-from", "0", "--vcd-to", "50"]);
    ok(&args);
    assert!(std::fs::read_to_string(&vcd).unwrap().contains("$enddefinitions"));

    // The staging helper: dropped without a commit, nothing remains; committed, the output is
    // whole, also into an existing directory.
    let target = dir.join("out");
    {
        let staged = Staged::dir(&target).unwrap();
        std::fs::write(staged.path().join("a.txt"), "a").unwrap();
    }
    assert!(!target.exists());
    assert_eq!(std::fs::read_dir(&dir.0).unwrap().count(), 2, "the temporary directory is removed");
    let staged = Staged::dir(&target).unwrap();
    std::fs::write(staged.path().join("a.txt"), "a").unwrap();
    assert_eq!(staged.final_path(&staged.path().join("a.txt")), target.join("a.txt"));
    staged.commit().unwrap();
    let staged = Staged::dir(&target).unwrap();
    std::fs::write(staged.path().join("b.txt"), "b").unwrap();
    staged.commit().unwrap();
    assert!(target.join("a.txt").exists() && target.join("b.txt").exists());
    let file = dir.join("f.json");
    {
        let staged = Staged::file(&file).unwrap();
        std::fs::write(staged.path(), "{").unwrap();
    }
    assert!(!file.exists());
    // A Verilog export or a figures run onto a file fails before writing anything.
    std::fs::write(&file, "x").unwrap();
    fails(&["export-verilog", "--out", path_arg(&file)], &["f.json"]);
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "x");
}

#[test]
fn limits_messages_use_the_users_words() {
    let dir = TempDir::new("limits_words");
    let scene = gen_scene(&dir, "s.json", 100, 16.0, 5);
    let s = path_arg(&scene);
    let internal = ["item 0", "cache None", "cache Some", "generator:", "the replay needs it"];
    let cases: [&[&str]; 5] = [
        &["cosim", "--scene", s, "--source", "3", "--rays", "2048"],
        &["scene", "gen", "--length", "5000"],
        &["scene", "gen", "--length", "nan"],
        &["demo", "--length", "-1"],
        &["figures", "--out", "x", "--lengths", "2000", "--quiet"],
    ];
    for args in cases {
        let err = fails(args, &[]);
        for word in internal {
            assert!(!err.contains(word), "{args:?}: {err}");
        }
    }
    // Progress bars stay off standard error when it is not a terminal.
    let out = shelling(&["agreement", "--sources", "1", "--rays", "64"]);
    assert!(out.status.success());
    assert!(text(&out.stderr).is_empty(), "agreement wrote to stderr: {}", text(&out.stderr));
}
