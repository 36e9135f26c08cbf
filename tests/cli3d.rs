//! The 3D forms of `trace` and `form-factors` end to end (CLI.md): OBJ scenes recognised by
//! name or content, a source polygon by index or a free 3D origin and normal, the JSON of the 2D
//! forms with a third coordinate, and every 2D-only option or bad 3D value refused by name.

use crate::cli::{fails, ok, path_arg, TempDir};
use serde_json::Value;
use shelling::d3::trace::Method3;

const CORNELL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cornell_box.obj");
const ROOM: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/box_room.obj");

fn json(args: &[&str]) -> Value {
    serde_json::from_str(&ok(args)).unwrap_or_else(|e| panic!("shelling {args:?}: not JSON: {e}"))
}

#[test]
fn trace_an_obj_scene_from_a_polygon_every_technique_the_same_hits() {
    let mut first: Option<Value> = None;
    for m in Method3::ALL {
        let v = json(&[
            "trace",
            "--scene",
            CORNELL,
            "--source",
            "7",
            "--rays",
            "256",
            "--method",
            m.name(),
            "--json",
        ]);
        assert_eq!(v["method"], m.name());
        let source = &v["source"];
        // The front ceiling piece's vertex centroid and front normal (SCENES3D.md).
        assert_eq!(source["patch"], 7);
        assert_eq!(source["normal"], serde_json::json!([0.0, -1.0, 0.0]));
        assert_eq!(source["origin"].as_array().unwrap().len(), 3);
        let rays = v["rays"].as_array().unwrap();
        assert_eq!(rays.len(), 256);
        assert!(rays.iter().all(|r| r["direction"].as_array().unwrap().len() == 3));
        assert!(rays.iter().all(|r| r["hit"] != 7), "the source polygon is never hit");
        let hits = rays.iter().filter(|r| !r["hit"].is_null()).count() as u64;
        assert_eq!(v["counters"]["actual_intersections"], hits);
        // The open front lets some rays out, the rest hit.
        assert!(hits > 128 && hits < 256, "{hits} hits");
        let hits: Vec<&Value> = rays.iter().map(|r| &r["hit"]).collect();
        match &first {
            None => first = Some(serde_json::json!(hits)),
            Some(f) => assert_eq!(f, &serde_json::json!(hits), "{m} against {}", Method3::ALL[0]),
        }
    }
}

#[test]
fn trace_from_a_free_origin_in_the_closed_room_hits_every_ray() {
    let v = json(&[
        "trace",
        "--scene",
        ROOM,
        "--origin",
        "128,1,128",
        "--normal",
        "0,2,0",
        "--rays",
        "512",
        "--ray-set",
        "sine",
        "--json",
    ]);
    assert_eq!(v["source"]["patch"], Value::Null);
    assert_eq!(v["source"]["normal"], serde_json::json!([0.0, 1.0, 0.0]));
    assert_eq!(v["source"]["ray_set"], "sine");
    assert_eq!(v["counters"]["actual_intersections"], 512);
    let text = ok(&["trace", "--scene", ROOM, "--origin", "128,1,128", "--normal", "0,1,0", "--rays", "512"]);
    assert!(text.contains("512 rays (64 × 8)") && text.contains("512 hit a polygon, 0 escaped"), "{text}");
}

#[test]
fn an_obj_scene_is_recognised_by_its_content_under_any_name() {
    let dir = TempDir::new("cli3d-content");
    let scene = dir.join("room.scene");
    std::fs::copy(ROOM, &scene).unwrap();
    std::fs::copy(ROOM.replace(".obj", ".mtl"), dir.join("box_room.mtl")).unwrap();
    let v = json(&["trace", "--scene", path_arg(&scene), "--source", "4", "--rays", "64", "--json"]);
    assert_eq!(v["counters"]["actual_intersections"], 64);
}

#[test]
fn form_factors_of_an_obj_polygon_and_of_a_free_point() {
    // The box room's floor middle square (4) to the rest: a closed room, the row sums to 1.
    let v = json(&[
        "form-factors",
        "--scene",
        ROOM,
        "--source",
        "4",
        "--rays",
        "1024",
        "--origins",
        "16",
        "--json",
    ]);
    assert_eq!(
        (v["source"].as_u64(), v["rays"].as_u64(), v["origins"].as_u64()),
        (Some(4), Some(1024), Some(16))
    );
    assert_eq!(v["method"], "conventional");
    assert!((v["sum"].as_f64().unwrap() - 1.0).abs() < 1e-12, "{}", v["sum"]);
    // A free point at the floor's centre: the differential form factor to the light, the
    // ceiling's middle square (13 = 9 + 4), against the closed form of a differential area to a
    // parallel rectangle on its axis (SCENES3D.md: 0.03411).
    let v = json(&["form-factors", "--scene", ROOM, "--origin", "128,0,128", "--normal", "0,1,0", "--json"]);
    assert_eq!((v["source"].clone(), v["origins"].as_u64()), (Value::Null, Some(1)));
    let light = v["form_factors"].as_array().unwrap().iter().find(|e| e["patch"] == 13).unwrap();
    let f = light["ff"].as_f64().unwrap();
    assert!((f - 0.03411).abs() < 1e-3, "F to the light {f}");
    let text =
        ok(&["form-factors", "--scene", CORNELL, "--source", "15", "--rays", "1024", "--origins", "4"]);
    assert!(
        text.starts_with("form factors from polygon 15 (4 origins × 1024 sine rays, conventional)"),
        "{text}"
    );
}

#[test]
fn bad_3d_values_and_2d_only_options_are_refused_by_name() {
    let t = |extra: &[&str], expect: &[&str]| {
        let mut args = vec!["trace", "--scene", CORNELL];
        args.extend_from_slice(extra);
        fails(&args, expect);
    };
    t(&["--source", "26"], &["--source", "between 0 and 25", "26 polygons", "got 26"]);
    t(&["--origin", "1,2,3", "--normal", "0,0,0"], &["--normal", "non-zero", "0,0,0"]);
    t(&["--origin", "1,2,3", "--normal", "0,inf,0"], &["--normal", "finite"]);
    t(&["--origin", "1,2", "--normal", "0,1"], &["--origin", "two coordinates", "3D"]);
    t(&["--origin", "1,2,3", "--normal", "0,1"], &["--origin", "--normal", "as many coordinates"]);
    t(&["--origin", "1,2,2e9", "--normal", "0,1,0"], &["--origin", "between"]);
    t(&["--source", "1", "--method", "stochastic"], &["--method stochastic", "2D", "brute, conventional"]);
    t(&["--source", "1", "--arith", "fixed"], &["--arith fixed", "2D"]);
    t(&["--source", "1", "--shell-depth", "3"], &["--shell-depth", "2D"]);
    t(&["--source", "1", "--max-sector", "8"], &["--max-sector", "2D"]);
    t(&["--source", "1", "--rays", "0"], &["--rays", "between 1 and 1048576", "got 0"]);
    t(
        &["--source", "1", "--method", "polar", "--phi-cells", "0"],
        &["--phi-cells", "between 1 and", "got 0"],
    );
    let f = |extra: &[&str], expect: &[&str]| {
        let mut args = vec!["form-factors", "--scene", CORNELL];
        args.extend_from_slice(extra);
        fails(&args, expect);
    };
    f(&["--source", "99"], &["--source", "between 0 and 25"]);
    f(&["--source", "1", "--origins", "0"], &["--origins", "between 1 and 4096", "got 0"]);
    f(&["--origin", "1,2,3", "--normal", "0,1,0", "--origins", "4"], &["--origins", "--source"]);
    f(&["--source", "1", "--arith", "fixed"], &["--arith fixed", "2D"]);
    f(&["--source", "1", "--method", "deterministic"], &["--method deterministic", "2D"]);
    fails(&["cosim", "--scene", CORNELL, "--source", "1"], &["--scene", "3D", "2D"]);
    fails(
        &["radiosity", "--scene", CORNELL, "--on-pe", "--method", "polar"],
        &["--method polar", "--method sweep"],
    );
    fails(
        &["radiosity", "--scene", CORNELL, "--on-pe", "--solver", "full", "--pes", "2", "--place", "lines"],
        &["--place lines", "2D scenes"],
    );
    fails(&["radiosity", "--scene", CORNELL, "--on-pe", "--pes", "2"], &["--pes 2", "--solver full"]);
    fails(&["radiosity", "--scene", CORNELL, "--on-pe", "--tc", "0"], &["--tc", "between 1 and 1024"]);
    fails(&["radiosity", "--scene", CORNELL, "--on-pe", "--rays", "3"], &["--rays 3", "3 x 1", "even"]);
    fails(&["radiosity", "--scene", CORNELL, "--svg", "x.svg"], &["--svg", "2D scenes"]);
    fails(&["radiosity", "--scene", CORNELL, "--origins", "0"], &["--origins", "between 1 and 4096"]);
    // And the other way: a 3D value on a 2D scene.
    let dir = TempDir::new("cli3d-2d");
    let scene = crate::cli::gen_scene(&dir, "s.json", 20, 32.0, 1);
    let s = path_arg(&scene);
    fails(&["trace", "--scene", s, "--origin", "1,2,3", "--normal", "0,1,0"], &["--origin", "three", "2D"]);
    fails(&["form-factors", "--scene", s, "--origin", "1,2", "--normal", "0,1"], &["--origin", "3D scenes"]);
    fails(&["trace", "--scene", s, "--source", "1", "--phi-cells", "2"], &["--phi-cells", "3D scenes"]);
    fails(
        &["form-factors", "--scene", s, "--source", "1", "--phi-cells", "2"],
        &["--phi-cells", "3D scenes"],
    );
    fails(&["figures", "--out", s, "--phi-cells", "2"], &["--phi-cells", "3D scenes"]);
}

#[test]
fn the_polar_sectors_height_changes_the_work_not_the_hits() {
    let run = |phi: &str| {
        let v = json(&[
            "trace",
            "--scene",
            CORNELL,
            "--source",
            "1",
            "--rays",
            "1024",
            "--method",
            "polar",
            "--phi-cells",
            phi,
            "--json",
        ]);
        let hits: Vec<Value> = v["rays"].as_array().unwrap().iter().map(|r| r["hit"].clone()).collect();
        (hits, v["counters"]["patches_read_before_screening"].clone())
    };
    let (one, loads_one) = run("1");
    let (four, loads_four) = run("4");
    let (all, loads_all) = run("1048576");
    assert!(one == four && four == all, "the height of a polar sector changed a hit");
    assert!(loads_one != loads_four || loads_four != loads_all, "--phi-cells changed nothing: {loads_one}");
}

#[test]
fn radiosity_of_an_obj_scene_on_the_pe() {
    // The closed room, one origin per polygon and 256 rays: every sweep plane co-simulated,
    // every hit checked; the solution is the software sweep's up to the rays that differ.
    let args =
        ["radiosity", "--scene", ROOM, "--origins", "1", "--rays", "256", "--solver", "full", "--json"];
    let pe = json(&[&args[..], &["--on-pe", "--tc", "4", "--cache", "16"]].concat());
    let sw = json(&[&args[..], &["--method", "sweep"]].concat());
    let h = &pe["hardware"];
    assert_eq!(h["plane_method"], "deterministic");
    assert_eq!((h["tc"].as_u64(), h["cache"].as_u64()), (Some(4), Some(16)));
    let polygons = pe["patches"].as_array().unwrap().len() as u64;
    // 256 rays = 32 x 8: 16 planes of 16 rays from each polygon's one origin.
    assert_eq!(h["origins"].as_u64(), Some(polygons));
    assert_eq!(h["bundles"].as_u64(), Some(16 * polygons));
    assert_eq!(h["rays"].as_u64(), Some(256 * polygons));
    assert!(h["cycles"].as_u64().unwrap() > h["tests"].as_u64().unwrap());
    assert!(h["brute_agree"].as_u64().unwrap() as f64 >= 0.999 * 256.0 * polygons as f64, "{h}");
    assert!(sw.get("hardware").is_none());
    for (a, b) in pe["patches"].as_array().unwrap().iter().zip(sw["patches"].as_array().unwrap()) {
        let (a, b) = (a["radiosity"].as_f64().unwrap(), b["radiosity"].as_f64().unwrap());
        assert!((a - b).abs() <= 1e-2 * b.abs().max(1e-9), "{a} against the software's {b}");
    }
    let text = ok(&[&args[..args.len() - 1], &["--on-pe", "--quiet"]].concat());
    assert!(text.contains("on the PE, each pack of sweep planes on a fresh one"), "{text}");
    // On the machine of two PEs: the same rows, so the same solution, in the machine's cycles.
    let m = json(&[&args[..], &["--on-pe", "--tc", "4", "--cache", "16", "--pes", "2"]].concat());
    assert_eq!(m["patches"], pe["patches"]);
    assert_eq!(m["hardware"]["pes"].as_u64(), Some(2));
    assert_eq!(m["hardware"]["bundles"], h["bundles"]);
    assert_eq!(m["hardware"]["tests"], h["tests"]);
}

#[test]
fn the_3d_matrix_in_slices_merged_and_solved() {
    // Two slices of the Cornell box's matrix and their merge are the matrix of one run; the
    // full solve from it is the traced solve; a 3D matrix fits no other scene.
    let dir = TempDir::new("cli3d-matrix");
    let (a, b, m, w) = (dir.join("a.json"), dir.join("b.json"), dir.join("m.json"), dir.join("w.json"));
    let ff = ["--rays", "256", "--origins", "2", "--method", "polar", "--quiet"];
    ok(&[&["form-factors", "--scene", CORNELL, "--rows", "0..11", "--out", path_arg(&a)][..], &ff].concat());
    ok(&[&["form-factors", "--scene", CORNELL, "--rows", "11..", "--out", path_arg(&b)][..], &ff].concat());
    ok(&[&["form-factors", "--scene", CORNELL, "--rows", "..", "--out", path_arg(&w)][..], &ff].concat());
    let merge = format!("{},{}", path_arg(&b), path_arg(&a));
    ok(&["form-factors", "--merge", &merge, "--out", path_arg(&m)]);
    let whole = std::fs::read_to_string(&w).unwrap();
    assert_eq!(std::fs::read_to_string(&m).unwrap(), whole);
    let file: Value = serde_json::from_str(&whole).unwrap();
    assert_eq!((file["dim"].as_u64(), file["method"].as_str()), (Some(3), Some("polar")));
    assert_eq!(
        (file["scene"]["patches"].as_u64(), file["rows"].as_array().map(Vec::len)),
        (Some(26), Some(26))
    );
    let solve = ["radiosity", "--scene", CORNELL, "--solver", "full", "--json"];
    let from_matrix = json(&[&solve[..], &["--matrix", path_arg(&m)]].concat());
    let traced = json(&[&solve[..], &ff].concat());
    assert_eq!(from_matrix["patches"], traced["patches"]);
    // Not the matrix of another scene, nor a slice, nor of a 2D scene.
    fails(&["radiosity", "--scene", ROOM, "--solver", "full", "--matrix", path_arg(&m)], &["do not match"]);
    fails(
        &["radiosity", "--scene", CORNELL, "--solver", "full", "--matrix", path_arg(&a)],
        &["rows 0..11", "--merge"],
    );
    let scene2 = dir.join("room.json");
    ok(&["scene", "gen", "--kind", "room", "--out", path_arg(&scene2)]);
    fails(
        &["radiosity", "--scene", path_arg(&scene2), "--solver", "full", "--matrix", path_arg(&m)],
        &["3D scene", "the scene is 2D"],
    );
    fails(
        &["form-factors", "--scene", CORNELL, "--rows", "0..2", "--source", "1", "--out", path_arg(&a)],
        &["--source"],
    );
    // A file claiming an unknown dimension or a 2D technique in 3D is refused by name.
    let bad = dir.join("bad.json");
    std::fs::write(&bad, whole.replace("\"dim\":3", "\"dim\":4")).unwrap();
    fails(&["form-factors", "--merge", path_arg(&bad), "--out", path_arg(&w)], &["dim is 4"]);
    std::fs::write(&bad, whole.replace("\"polar\"", "\"stochastic\"")).unwrap();
    fails(
        &["form-factors", "--merge", path_arg(&bad), "--out", path_arg(&w)],
        &["\"stochastic\"", "3D technique"],
    );
}
