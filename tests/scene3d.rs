//! 3D scenes (issue 18, parts 1 and 2): the OBJ loader's every error with its message, the
//! shipped scenes, the generator and the writer, the hemisphere ray sets and the brute-force
//! oracle.

use glam::DVec3;
use shelling::d3::brute;
use shelling::d3::gen::{self, box_room};
use shelling::d3::hemisphere::{HemisphereRays, Strata};
use shelling::d3::obj;
use shelling::d3::{Polygon, PolygonProblem, Scene3, Scene3Error};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The repository's `scenes/` directory.
fn scenes() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes")
}

/// A fresh empty directory under the system's temporary directory.
fn temp_dir(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("shelling-scene3d-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const MTL: &str = "newmtl grey\nKd 0.5 0.5 0.5\nnewmtl lamp\nKd 0.5 0.6 0.7\nKe 3 2 1\n";

/// A unit square and a triangle, counter-clockwise seen from +z.
const GOOD: &str = "mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl grey\nf 1 2 3 4\n\
                    usemtl lamp\nf 1 2 3\n";

/// `obj` loaded as `scene.obj`, with `scene.mtl` reading as `mtl`.
fn load_with(obj_text: &str, mtl: &str) -> Result<Scene3, Scene3Error> {
    let mtl = mtl.to_string();
    obj::load_str("scene.obj", obj_text, &move |p: &Path| {
        if p == Path::new("scene.mtl") {
            Ok(mtl.clone())
        } else {
            Err(std::io::Error::new(std::io::ErrorKind::NotFound, "No such file or directory (os error 2)"))
        }
    })
}

/// The message of loading `obj` (with [`MTL`]), which must fail.
fn error(obj_text: &str) -> String {
    error_with(obj_text, MTL)
}

fn error_with(obj_text: &str, mtl: &str) -> String {
    match load_with(obj_text, mtl) {
        Ok(_) => panic!("loaded without error:\n{obj_text}"),
        Err(e) => e.to_string(),
    }
}

/// A file of the four vertices `v` and one face `f`.
fn one_face(vertices: &[[&str; 3]], face: &str) -> String {
    let mut s = String::from("mtllib scene.mtl\n");
    for v in vertices {
        s += &format!("v {} {} {}\n", v[0], v[1], v[2]);
    }
    s + "usemtl grey\n" + face + "\n"
}

#[test]
fn a_good_file_loads_with_faces_as_polygons_and_materials_per_polygon() {
    let s = load_with(GOOD, MTL).unwrap();
    assert_eq!(s.polygons.len(), 2);
    assert_eq!(s.polygons[0].vertices.len(), 4, "the quad is kept, not triangulated");
    assert_eq!(s.polygons[0].normal, DVec3::Z, "counter-clockwise seen from +z faces +z");
    assert_eq!(s.polygons[0].area, 1.0);
    assert_eq!(s.polygons[0].centre, DVec3::new(0.5, 0.5, 0.0));
    assert_eq!((s.polygons[0].reflectance, s.polygons[0].emission), (0.5, 0.0));
    assert!((s.polygons[1].reflectance - 0.6).abs() < 1e-15);
    assert_eq!(s.polygons[1].emission, 2.0);
    assert_eq!(s.materials.iter().map(|m| m.name.as_str()).collect::<Vec<_>>(), ["grey", "lamp"]);
    assert_eq!(s.materials[1].ke, [3.0, 2.0, 1.0]);
}

#[test]
fn usemtl_may_come_before_the_mtllib_and_normals_and_texture_coordinates_are_ignored() {
    let text =
        "usemtl grey\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nmtllib scene.mtl\nf 1/1/1 2/1/1 -1//1\n";
    let s = load_with(text, MTL).unwrap();
    assert_eq!(s.polygons[0].normal, DVec3::Z);
}

#[test]
fn geometry_errors_name_the_file_the_face_its_line_and_the_problem() {
    let sq = [["0", "0", "0"], ["1", "0", "0"], ["1", "1", "0"], ["0", "1", "0"]];
    let cases: Vec<(String, &str)> = vec![
        (one_face(&sq, "f 1 2"), "scene.obj: face 0 (line 7) has 2 vertices; a polygon needs at least 3"),
        (
            one_face(&[["0", "0", "0"], ["1", "nan", "0"], ["1", "1", "0"]], "f 1 2 3"),
            "scene.obj: face 0 (line 6) vertex 1 has a non-finite coordinate (NaN)",
        ),
        (
            one_face(&[["0", "0", "0"], ["1", "0", "inf"], ["1", "1", "0"]], "f 1 2 3"),
            "scene.obj: face 0 (line 6) vertex 1 has a non-finite coordinate (inf)",
        ),
        (
            one_face(&[["0", "0", "0"], ["1", "0", "1e400"], ["1", "1", "0"]], "f 1 2 3"),
            "scene.obj: face 0 (line 6) vertex 1 has a non-finite coordinate (inf)",
        ),
        (
            one_face(&[["0", "0", "0"], ["2e9", "0", "0"], ["1", "1", "0"]], "f 1 2 3"),
            "scene.obj: face 0 (line 6) vertex 1 has a coordinate of magnitude above 1e9 (2e9)",
        ),
        (
            one_face(&sq, "f 1 2 2 3"),
            "scene.obj: face 0 (line 7) vertices 1 and 2 are the same point (repeated vertex)",
        ),
        (
            one_face(&[["0", "0", "0"], ["1", "0", "0"], ["1", "0", "0"], ["0", "1", "0"]], "f 1 2 3 4"),
            "scene.obj: face 0 (line 7) vertices 1 and 2 are the same point (repeated vertex)",
        ),
        (
            one_face(&[["0", "0", "0"], ["1", "1", "1"], ["2", "2", "2"]], "f 1 2 3"),
            "scene.obj: face 0 (line 6) is degenerate: zero area (its vertices are collinear)",
        ),
        (
            one_face(&[["0", "0", "0"], ["1", "0", "0"], ["1", "1", "0.01"], ["0", "1", "0"]], "f 1 2 3 4"),
            "scene.obj: face 0 (line 7) is not planar: vertex 0 lies 2.500e-3 from the polygon's plane \
             (tolerance 1.414e-5, 1e-5 of its size)",
        ),
    ];
    for (text, expected) in &cases {
        assert_eq!(error(text), *expected, "for\n{text}");
    }
    // A dart: the turn at vertex 2 is to the right.
    let dart = "mtllib scene.mtl\nv 0 0 0\nv 2 0 0\nv 1 0.5 0\nv 2 2 0\nv 0 2 0\nusemtl grey\nf 1 2 3 4 5\n";
    assert_eq!(error(dart), "scene.obj: face 0 (line 8) is not convex: it turns the wrong way at vertex 2");
    // A pentagram: every turn is to the left, but the boundary winds twice.
    let mut star = String::from("mtllib scene.mtl\n");
    for k in 0..5 {
        let a = std::f64::consts::TAU * (2 * k) as f64 / 5.0;
        star += &format!("v {} {} 0\n", a.cos(), a.sin());
    }
    star += "usemtl grey\nf 1 2 3 4 5\n";
    assert_eq!(
        error(&star),
        "scene.obj: face 0 (line 8) is not convex: its boundary winds 2.000 times around it \
         (a convex polygon winds once)"
    );
    // The face index counts `f` lines: the second face is face 1.
    let second = format!("{GOOD}f 1 2 2\n");
    assert_eq!(
        error(&second),
        "scene.obj: face 2 (line 10) vertices 1 and 2 are the same point (repeated vertex)"
    );
}

#[test]
fn syntax_errors_name_the_line() {
    assert_eq!(
        error("mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nusemtl grey\nf 1 2 3\n"),
        "scene.obj: malformed OBJ at line 5: face 0 (line 5): vertex reference \"3\" is not a vertex \
         defined above it (2 so far)"
    );
    assert_eq!(
        error("mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl grey\nf 1 x 3\n"),
        "scene.obj: malformed OBJ at line 6: face 0 (line 6): vertex reference \"x\" is not a vertex \
         defined above it (3 so far)"
    );
    assert_eq!(
        error("mtllib scene.mtl\nv 0 0\nv 1 0 0\nv 1 1 0\nusemtl grey\nf 1 2 3\n"),
        "scene.obj: malformed OBJ: position parse error"
    );
    assert_eq!(
        error("mtllib scene.mtl\nusemtl\n"),
        "scene.obj: malformed OBJ at line 2: usemtl without a material name"
    );
}

#[test]
fn material_errors_name_the_library_the_material_or_the_face() {
    assert_eq!(
        error(&GOOD.replace("mtllib scene.mtl\n", "")),
        "scene.obj: no material library (the file has no mtllib line)"
    );
    assert_eq!(
        error(&GOOD.replace("mtllib scene.mtl", "mtllib missing.mtl")),
        "scene.obj: cannot read the material library missing.mtl: No such file or directory (os error 2)"
    );
    assert_eq!(
        error(&GOOD.replace("usemtl lamp", "usemtl paint")),
        "scene.obj: face 1 (line 9) uses material \"paint\", which no material library defines"
    );
    assert_eq!(
        error(&GOOD.replace("usemtl grey\n", "")),
        "scene.obj: face 0 (line 6) has no material (no usemtl line before it)"
    );
    assert_eq!(
        error_with(GOOD, "newmtl grey\nKd 0.5 0.5\nnewmtl lamp\nKd 1 1 1\n"),
        "scene.obj: malformed material library scene.mtl at line 2: Kd needs three numbers r g b, found \"0.5 0.5\""
    );
    assert_eq!(
        error_with(GOOD, "newmtl grey\nKd 0.5 0.5 0.5\nnewmtl lamp\nKd 1 1 1\n"),
        "scene.obj: material \"lamp\": Kd has mean 1; the reflectance must be below 1"
    );
    assert_eq!(
        error_with(GOOD, "newmtl grey\nKd 0.5 1.5 0.5\n"),
        "scene.obj: material \"grey\": Kd has a channel outside [0, 1] (1.5)"
    );
    assert_eq!(
        error_with(GOOD, "newmtl grey\nKd 0.5 0.5 0.5\nKe 1 -1 0\n"),
        "scene.obj: material \"grey\": Ke has a channel that is negative or not finite (-1)"
    );
    assert_eq!(
        error_with(GOOD, "newmtl grey\nKd 0.5 0.5 nan\n"),
        "scene.obj: material \"grey\": Kd has a channel outside [0, 1] (NaN)"
    );
    assert_eq!(
        error_with(GOOD, "newmtl grey\nKs 1 1 1\nnewmtl lamp\nKd 0 0 0\n"),
        "scene.obj: material \"grey\": has no Kd line (the reflectance)"
    );
}

#[test]
fn an_empty_scene_is_an_error() {
    assert_eq!(error("mtllib scene.mtl\nv 0 0 0\n"), "scene.obj: the scene is empty (no faces)");
    assert_eq!(error(""), "scene.obj: the scene is empty (no faces)");
    // Lines and points are not faces.
    assert_eq!(error("v 0 0 0\nv 1 0 0\nl 1 2\np 1\n"), "scene.obj: the scene is empty (no faces)");
}

#[test]
fn files_on_disk_missing_unreadable_and_their_libraries() {
    let dir = temp_dir("files");
    let missing = dir.join("nothing.obj");
    let e = obj::load(&missing).unwrap_err().to_string();
    assert_eq!(
        e,
        format!("{}: cannot read the file: No such file or directory (os error 2)", missing.display())
    );
    // A directory cannot be read as a file.
    let e = obj::load(&dir).unwrap_err().to_string();
    assert!(e.starts_with(&format!("{}: cannot read the file: ", dir.display())), "{e}");
    // Not UTF-8.
    let binary = dir.join("binary.obj");
    std::fs::write(&binary, [0xff, 0xfe, 0x00, 0x80]).unwrap();
    assert_eq!(
        obj::load(&binary).unwrap_err().to_string(),
        format!("{}: cannot read the file: not UTF-8 text", binary.display())
    );
    // The library is read beside the OBJ file; a missing one names the library.
    let scene = dir.join("scene.obj");
    std::fs::write(&scene, GOOD).unwrap();
    assert_eq!(
        obj::load(&scene).unwrap_err().to_string(),
        format!(
            "{}: cannot read the material library scene.mtl: No such file or directory (os error 2)",
            scene.display()
        )
    );
    std::fs::write(dir.join("scene.mtl"), MTL).unwrap();
    assert_eq!(obj::load(&scene).unwrap().polygons.len(), 2);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn unused_bad_vertices_are_not_errors() {
    let text = GOOD.replace("v 0 1 0\n", "v 0 1 0\nv nan 0 1e300\n");
    assert_eq!(load_with(&text, MTL).unwrap().polygons.len(), 2);
}

/// Whether `edge` is one of `edges`, either way round.
fn has_edge(edges: &[(DVec3, DVec3)], a: DVec3, b: DVec3) -> bool {
    edges.iter().any(|&(p, q)| (p, q) == (a, b) || (p, q) == (b, a))
}

/// The Cornell box's faces by index: 7 floor pieces, 4 ceiling pieces, the back wall, the right
/// wall, the left wall's 2 triangles, the light, then each block's top and 4 sides.
const FLOOR: std::ops::Range<usize> = 0..7;
const CEILING: std::ops::Range<usize> = 7..11;
const LIGHT: usize = 15;
const BLOCKS: [std::ops::Range<usize>; 2] = [16..21, 21..26];

#[test]
fn the_cornell_box_loads_with_its_faces_materials_and_orientation() {
    let s = obj::load(&scenes().join("cornell_box.obj")).unwrap();
    assert_eq!(
        s.polygons.len(),
        26,
        "floor (7 pieces), ceiling (4 pieces), back, right, left (2), light, 5 + 5 block faces"
    );
    let names: Vec<&str> = s.polygons.iter().map(|p| s.materials[p.material].name.as_str()).collect();
    let mut expected = vec!["white"; 12];
    expected.extend(["green", "red", "red", "light"]);
    expected.extend(["white"; 10]);
    assert_eq!(names, expected);
    let light = &s.polygons[LIGHT];
    assert_eq!(light.emission, 11.0);
    assert!((light.area - 130.0 * 105.0).abs() < 1e-6);
    assert_eq!(light.normal, DVec3::NEG_Y, "the light faces down");
    assert!(s.polygons.iter().filter(|p| p.emission > 0.0).count() == 1);
    assert!((s.polygons[0].reflectance - 0.705).abs() < 1e-12);
    assert!((s.polygons[12].reflectance - 0.227).abs() < 1e-12);
    assert!((s.polygons[13].reflectance - 0.2483333333333333).abs() < 1e-12);
    for k in FLOOR {
        assert_eq!(s.polygons[k].normal, DVec3::Y, "floor piece {k} faces up");
    }
    for k in CEILING {
        assert_eq!(s.polygons[k].normal, DVec3::NEG_Y, "ceiling piece {k} faces down");
    }
    // The room's faces face in, the blocks' faces face out.
    let room_centre = DVec3::new(278.0, 274.4, 279.6);
    for (k, p) in s.polygons.iter().enumerate().take(LIGHT + 1) {
        assert!((room_centre - p.centre).dot(p.normal) > 0.0, "room face {k} faces out");
    }
    for block in BLOCKS {
        let faces = &s.polygons[block.clone()];
        let centre = faces.iter().map(|p| p.centre).sum::<DVec3>() / faces.len() as f64;
        for (k, p) in block.zip(faces) {
            assert!((p.centre - centre).dot(p.normal) > 0.0, "block face {k} faces in");
        }
    }
}

/// The area of the polygon `(x, z)` seen from above (`y` up), positive counter-clockwise in
/// `(x, z)`.
fn xz_area(v: &[(f64, f64)]) -> f64 {
    (0..v.len()).map(|i| v[i].0 * v[(i + 1) % v.len()].1 - v[(i + 1) % v.len()].0 * v[i].1).sum::<f64>() / 2.0
}

#[test]
fn the_cornell_box_floor_and_ceiling_pieces_tile_them_minus_the_footprints_and_the_light() {
    let s = obj::load(&scenes().join("cornell_box.obj")).unwrap();
    // The published floor, the blocks' footprints (their sides' bottom vertices), the published
    // ceiling and the light's outline.
    let floor = [(0.0, 0.0), (552.8, 0.0), (549.6, 559.2), (0.0, 559.2)];
    let short = [(130.0, 65.0), (82.0, 225.0), (240.0, 272.0), (290.0, 114.0)];
    let tall = [(423.0, 247.0), (265.0, 296.0), (314.0, 456.0), (472.0, 406.0)];
    let ceiling = [(556.0, 0.0), (556.0, 559.2), (0.0, 559.2), (0.0, 0.0)];
    let light = [(343.0, 227.0), (343.0, 332.0), (213.0, 332.0), (213.0, 227.0)];
    for (block, footprint) in BLOCKS.into_iter().zip([short, tall]) {
        let mut bottom: Vec<(f64, f64)> = s.polygons[block]
            .iter()
            .flat_map(|p| p.vertices.iter().filter(|v| v.y == 0.0).map(|v| (v.x, v.z)))
            .collect();
        bottom.sort_by(|a, b| a.partial_cmp(b).unwrap());
        bottom.dedup();
        let mut expected = footprint.to_vec();
        expected.sort_by(|a, b| a.partial_cmp(b).unwrap());
        assert_eq!(bottom, expected, "the footprint is the block's bottom vertices");
    }
    let area = |range: std::ops::Range<usize>| s.polygons[range].iter().map(|p| p.area).sum::<f64>();
    let cases = [
        ("floor", FLOOR, 0.0, xz_area(&floor).abs() - xz_area(&short).abs() - xz_area(&tall).abs()),
        ("ceiling", CEILING, 548.8, xz_area(&ceiling).abs() - xz_area(&light).abs()),
    ];
    for (name, range, y, exact) in cases {
        assert!(s.polygons[range.clone()].iter().all(|p| p.vertices.iter().all(|v| v.y == y)), "{name}");
        let sum = area(range.clone());
        assert!((sum - exact).abs() <= 1e-6 * exact, "{name}: the pieces' areas {sum}, expected {exact}");
        // No overlap and no gap: the pieces face the same way and their edges pair up (each
        // inner edge runs once each way) but for the region's outline and its holes', so every
        // point of the region is covered once (the pieces' winding numbers sum to the region's)
        // and the areas above agree.
        let normal = s.polygons[range.start].normal;
        assert!(s.polygons[range.clone()].iter().all(|p| p.normal == normal), "{name}");
        let pieces = Scene3 { polygons: s.polygons[range].to_vec(), materials: s.materials.clone() };
        let mut open: Vec<((f64, f64), (f64, f64))> =
            pieces.open_edges().iter().map(|(a, b)| ((a.x, a.z), (b.x, b.z))).collect();
        let mut outline: Vec<((f64, f64), (f64, f64))> = Vec::new();
        let holes: &[&[(f64, f64)]] = if name == "floor" { &[&short, &tall] } else { &[&light] };
        let outer: &[(f64, f64)] = if name == "floor" { &floor } else { &ceiling };
        for ring in std::iter::once(outer).chain(holes.iter().copied()) {
            for i in 0..ring.len() {
                outline.push((ring[i], ring[(i + 1) % ring.len()]));
            }
        }
        let undirected = |e: &((f64, f64), (f64, f64))| if e.0 < e.1 { *e } else { (e.1, e.0) };
        let mut open_u: Vec<_> = open.drain(..).map(|e| undirected(&e)).collect();
        let mut outline_u: Vec<_> = outline.iter().map(undirected).collect();
        open_u.sort_by(|a, b| a.partial_cmp(b).unwrap());
        outline_u.sort_by(|a, b| a.partial_cmp(b).unwrap());
        assert_eq!(open_u, outline_u, "{name}: the pieces' open edges are not the outline and the holes'");
    }
}

#[test]
fn the_cornell_box_is_closed_but_for_its_open_front_and_the_light() {
    let s = obj::load(&scenes().join("cornell_box.obj")).unwrap();
    // The shell of six walls (the floor and the ceiling in pieces): open along the four edges of
    // the front, z = 0, the blocks' footprints and the light's outline cut in the ceiling.
    let shell = Scene3 { polygons: s.polygons[..LIGHT].to_vec(), materials: s.materials.clone() };
    let open = shell.open_edges();
    assert_eq!(open.len(), 4 + 8 + 4, "{open:?}");
    let front: Vec<_> = open.iter().filter(|(a, b)| a.z == 0.0 && b.z == 0.0).copied().collect();
    assert_eq!(front.len(), 4, "{open:?}");
    for (a, b) in [
        ((552.8, 0.0), (0.0, 0.0)),
        ((0.0, 0.0), (0.0, 548.8)),
        ((0.0, 548.8), (556.0, 548.8)),
        ((556.0, 548.8), (552.8, 0.0)),
    ] {
        assert!(has_edge(&front, DVec3::new(a.0, a.1, 0.0), DVec3::new(b.0, b.1, 0.0)), "{a:?}–{b:?}");
    }
    // Each block: open only along its four bottom edges, on the floor.
    for block in BLOCKS {
        let b = Scene3 { polygons: s.polygons[block].to_vec(), materials: s.materials.clone() };
        let open = b.open_edges();
        assert_eq!(open.len(), 4);
        assert!(open.iter().all(|(a, b)| a.y == 0.0 && b.y == 0.0));
    }
    // The whole scene: the blocks close the floor's holes; open are the front's 4 edges, the
    // ceiling's hole (4) and the light's outline 0.1 mm below it (4).
    let open = s.open_edges();
    assert_eq!(open.len(), 12, "{open:?}");
    assert_eq!(open.iter().filter(|(a, b)| a.y == 548.7 && b.y == 548.7).count(), 4, "{open:?}");
}

#[test]
fn the_box_room_is_closed_and_its_shipped_files_are_the_generators() {
    let room = box_room();
    assert_eq!(room.polygons.len(), 6 * 9);
    assert!(room.open_edges().is_empty());
    assert_eq!(room.polygons.iter().filter(|p| p.emission > 0.0).count(), 1);
    let (obj_text, mtl_text) = obj::to_obj(&room, "box_room.mtl", BOX_ROOM_COMMENT);
    if std::env::var_os("SHELLING_BLESS").is_some() {
        obj::save(&room, &scenes().join("box_room.obj"), BOX_ROOM_COMMENT).unwrap();
    }
    let shipped = std::fs::read_to_string(scenes().join("box_room.obj")).unwrap_or_default();
    let shipped_mtl = std::fs::read_to_string(scenes().join("box_room.mtl")).unwrap_or_default();
    assert!(
        shipped == obj_text && shipped_mtl == mtl_text,
        "scenes/box_room.* are stale: rerun with SHELLING_BLESS=1"
    );
    assert_eq!(obj::load(&scenes().join("box_room.obj")).unwrap(), room);
}

/// The comment at the top of `scenes/box_room.obj`.
const BOX_ROOM_COMMENT: &str =
    "The closed box room: the cube [0, 256]^3, y up, each wall split into 3 x 3 squares\n\
     facing in (counter-clockwise seen from inside), the middle square of the ceiling a light.\n\
     Generated by shelling::d3::gen::box_room; tests/scene3d.rs fails when this file is stale.";

#[test]
fn the_generator_is_seeded_inside_the_world_and_round_trips_through_the_writer() {
    let a = gen::generate(200, 32.0, 5).unwrap();
    assert_eq!(a, gen::generate(200, 32.0, 5).unwrap(), "same seed, same scene");
    assert_ne!(a, gen::generate(200, 32.0, 6).unwrap(), "another seed, another scene");
    for p in &a.polygons {
        assert_eq!(p.vertices.len(), 4);
        assert!(p.vertices.iter().all(|v| v.cmpge(DVec3::ZERO).all() && v.cmplt(DVec3::splat(1024.0)).all()));
        assert!((p.area - 32.0 * 32.0).abs() < 1e-9, "{}", p.area);
        for i in 0..4 {
            let side = (p.vertices[(i + 1) % 4] - p.vertices[i]).length();
            assert!((side - 32.0).abs() < 1e-9);
        }
    }
    // Normals spread over the sphere: about half point up, each axis's mean near 0.
    let mean = a.polygons.iter().map(|p| p.normal).sum::<DVec3>() / 200.0;
    assert!(mean.length() < 0.2, "{mean}");
    let dir = temp_dir("gen");
    let path = dir.join("patches.obj");
    obj::save(&a, &path, "test").unwrap();
    assert_eq!(obj::load(&path).unwrap(), a, "the writer's output reads back to the same scene");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_generator_checks_its_parameters() {
    let e = |c, l| gen::generate(c, l, 1).unwrap_err().to_string();
    assert_eq!(e(0, 32.0), "generator: the number of patches must be 1 to 1048576, got 0");
    assert_eq!(
        e(10, 0.0),
        "generator: the side of a patch must be greater than 0 and less than 591.207 (1024/√3), got 0"
    );
    assert!(e(10, f64::NAN).ends_with("got NaN"));
    assert!(e(10, 600.0).ends_with("got 600"));
}

#[test]
fn scene_gen_dim_3_writes_obj_and_mtl_and_dim_2_is_the_2d_generator() {
    let dir = temp_dir("cli");
    let out = dir.join("g.obj");
    let run = |args: &[&str]| Command::new(env!("CARGO_BIN_EXE_shelling")).args(args).output().unwrap();
    let o = run(&[
        "scene",
        "gen",
        "--dim",
        "3",
        "--count",
        "50",
        "--size",
        "20",
        "--seed",
        "3",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(dir.join("g.mtl").exists());
    assert_eq!(obj::load(&out).unwrap(), gen::generate(50, 20.0, 3).unwrap());
    let o = run(&["scene", "gen", "--dim", "3", "--count", "0", "--out", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(String::from_utf8_lossy(&o.stderr), "error: --count must be between 1 and 1048576, got 0\n");
    let o = run(&["scene", "gen", "--help"]);
    assert!(o.status.success());
    assert!(String::from_utf8_lossy(&o.stdout).contains("--dim <DIM>"));
    let o = run(&["scene", "gen", "--dim", "4"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--dim"), "{}", String::from_utf8_lossy(&o.stderr));
    for (args, says) in [
        (&["scene", "gen", "--dim", "3"][..], "--dim 3 needs --out"),
        (&["scene", "gen", "--dim", "3", "--length", "3", "--out", "x.obj"][..], "--length belongs to 2D"),
        (
            &["scene", "gen", "--dim", "3", "--kind", "room", "--out", "x.obj"][..],
            "--kind room belongs to 2D",
        ),
        (&["scene", "gen", "--size", "3"][..], "--size belongs to --dim 3"),
        (
            &["scene", "gen", "--dim", "3", "--size", "700", "--out", "x.obj"][..],
            "--size must be greater than 0",
        ),
    ] {
        let o = run(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(
            String::from_utf8_lossy(&o.stderr).contains(says),
            "{args:?}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
    }
    let o = run(&["scene", "gen", "--dim=2", "--count", "3"]);
    assert!(o.status.success());
    assert!(String::from_utf8_lossy(&o.stdout).contains("\"segments\""));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Seeded points and normals for the ray-set tests.
fn sources(count: usize) -> Vec<(DVec3, DVec3)> {
    use rand::{RngExt, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(18);
    (0..count)
        .map(|_| {
            let o = DVec3::new(rng.random::<f64>(), rng.random::<f64>(), rng.random::<f64>());
            let n =
                DVec3::new(rng.random::<f64>() - 0.5, rng.random::<f64>() - 0.5, rng.random::<f64>() - 0.5);
            (o * 250.0 + 3.0, n)
        })
        .collect()
}

#[test]
fn ray_set_weights_sum_to_one_and_rays_point_into_the_hemisphere() {
    for strata in [Strata::Angle, Strata::Cosine] {
        for (o, n) in sources(20).into_iter().chain([(DVec3::ZERO, DVec3::Z), (DVec3::ZERO, DVec3::NEG_Z)]) {
            let set = HemisphereRays::new(o, n, 16, 8, strata).unwrap();
            assert_eq!(set.len(), 128);
            let total: f64 = set.rays.iter().map(|r| r.weight).sum();
            assert!((total - 1.0).abs() < 1e-12, "{strata:?}: {total}");
            let omega: f64 = set.rays.iter().map(|r| r.solid_angle).sum();
            assert!((omega - std::f64::consts::TAU).abs() < 1e-12, "the cells tile the hemisphere: {omega}");
            let (t, b) = (set.tangent, set.bitangent);
            assert!(
                t.dot(set.normal).abs() < 1e-12 && b.dot(set.normal).abs() < 1e-12 && t.dot(b).abs() < 1e-12
            );
            assert!((t.cross(b) - set.normal).length() < 1e-12, "the frame is right-handed");
            for r in &set.rays {
                assert!((r.direction.length() - 1.0).abs() < 1e-12);
                assert!(r.direction.dot(set.normal) > 0.0, "a ray leaves the hemisphere");
                assert!((r.direction.dot(set.normal) - r.phi.cos()).abs() < 1e-12);
                if strata == Strata::Cosine {
                    assert_eq!(r.weight, 1.0 / 128.0);
                }
            }
        }
    }
}

#[test]
fn ray_set_angle_weights_are_the_cells_form_factors() {
    // A cell's form factor is ∫ cos Φ dω / π over it: check one cell numerically.
    let set = HemisphereRays::new(DVec3::ZERO, DVec3::Z, 4, 3, Strata::Angle).unwrap();
    let (lo, hi) = (std::f64::consts::FRAC_PI_2 / 3.0, std::f64::consts::FRAC_PI_2 * 2.0 / 3.0);
    let steps = 10_000;
    let integral: f64 = (0..steps)
        .map(|s| {
            let phi = lo + (hi - lo) * (s as f64 + 0.5) / steps as f64;
            phi.cos() * phi.sin() * (hi - lo) / steps as f64
        })
        .sum::<f64>()
        * (std::f64::consts::TAU / 4.0)
        / std::f64::consts::PI;
    assert!((set.rays[set.index(2, 1)].weight - integral).abs() < 1e-8);
}

#[test]
fn ray_set_numbering_makes_a_sector_contiguous_runs_in_both_angles() {
    for strata in [Strata::Angle, Strata::Cosine] {
        let set = HemisphereRays::new(DVec3::new(1.0, 2.0, 3.0), DVec3::new(0.3, -0.4, 0.8), 12, 5, strata)
            .unwrap();
        // Θ never decreases along the numbering; Φ increases within a band.
        for k in 1..set.len() {
            let (a, b) = (set.rays[k - 1], set.rays[k]);
            assert!(b.theta >= a.theta);
            if k % set.n_phi != 0 {
                assert!(b.theta == a.theta && b.phi > a.phi);
            }
        }
        // A sector on cell boundaries is exactly the rays whose angles lie inside it, and comes
        // as one contiguous run per band; a sector of whole bands is one run.
        let (bands, cells) = (3..7, 1..4);
        let runs = set.sector(bands.clone(), cells.clone());
        assert_eq!(runs.len(), 4);
        let (t1, t2) = (set.band_bounds(3).0, set.band_bounds(6).1);
        let phi_bound = |j: usize| match strata {
            Strata::Angle => j as f64 * std::f64::consts::FRAC_PI_2 / 5.0,
            Strata::Cosine => (j as f64 / 5.0).sqrt().asin(),
        };
        let inside: Vec<usize> = (0..set.len())
            .filter(|&k| {
                let r = set.rays[k];
                t1 <= r.theta && r.theta < t2 && phi_bound(1) <= r.phi && r.phi < phi_bound(4)
            })
            .collect();
        let from_runs: Vec<usize> = runs.iter().flat_map(|r| r.clone()).collect();
        assert_eq!(from_runs, inside);
        let whole = set.sector(2..5, 0..5);
        let flat: Vec<usize> = whole.iter().flat_map(|r| r.clone()).collect();
        assert_eq!(flat, (10..25).collect::<Vec<_>>());
    }
}

#[test]
fn ray_set_parameters_are_checked() {
    let e = |o, n, a, b| HemisphereRays::new(o, n, a, b, Strata::Angle).unwrap_err().to_string();
    assert_eq!(
        e(DVec3::ZERO, DVec3::ZERO, 4, 4),
        "the normal must be a finite non-zero vector, got [0, 0, 0]"
    );
    assert_eq!(e(DVec3::splat(f64::NAN), DVec3::Z, 4, 4), "the origin must be finite, got [NaN, NaN, NaN]");
    assert_eq!(
        e(DVec3::ZERO, DVec3::Z, 0, 4),
        "the ray counts must be at least 1 and their product at most 1048576, got 0 × 4"
    );
    assert!(HemisphereRays::new(DVec3::ZERO, DVec3::Z, 1 << 11, 1 << 10, Strata::Cosine).is_err());
}

#[test]
fn every_ray_from_inside_the_closed_box_room_hits_a_polygon() {
    let room = box_room();
    let mut rays = 0;
    for (o, n) in sources(40) {
        for strata in [Strata::Angle, Strata::Cosine] {
            let set = HemisphereRays::new(o, n, 32, 16, strata).unwrap();
            for r in &set.rays {
                let hit = brute::nearest(&room, o, r.direction, None);
                let hit = hit.unwrap_or_else(|| panic!("a ray from {o} along {} misses", r.direction));
                assert!(hit.front, "a ray from inside meets a wall's front");
                rays += 1;
            }
        }
    }
    // Rays exactly through the room's edges and corners, where squares meet.
    let centre = DVec3::splat(128.0);
    let grid = [0.0, 256.0 / 3.0, 2.0 * 256.0 / 3.0, 256.0];
    for x in grid {
        for y in grid {
            for z in grid {
                let target = DVec3::new(x, y, z);
                let on_surface = [x, y, z].iter().any(|c| *c == 0.0 || *c == 256.0);
                if on_surface {
                    let hit = brute::nearest(&room, centre, target - centre, None);
                    let hit = hit.unwrap_or_else(|| panic!("the ray to {target} misses"));
                    assert!((hit.t - 1.0).abs() < 1e-9);
                    rays += 1;
                }
            }
        }
    }
    assert!(rays > 40_000);
}

#[test]
fn the_oracle_takes_the_nearest_hit_skips_the_source_and_blocks_from_behind() {
    let s = load_with(
        "mtllib scene.mtl\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nv 0 0 2\nv 1 0 2\nv 1 1 2\nv 0 1 2\nusemtl grey\n\
         f 5 6 7 8\nf 1 2 3 4\n",
        MTL,
    )
    .unwrap();
    let o = DVec3::new(0.25, 0.5, 0.0);
    let hit = brute::nearest(&s, o, DVec3::Z, None).unwrap();
    assert_eq!((hit.polygon, hit.t, hit.front), (1, 1.0, false), "the nearer plane, met from behind");
    assert_eq!(brute::nearest(&s, o, DVec3::Z, Some(1)).unwrap().polygon, 0);
    assert_eq!(brute::nearest(&s, o, DVec3::NEG_Z, None), None, "nothing behind the origin");
    assert_eq!(brute::nearest(&s, o, DVec3::X, None), None, "parallel to both planes");
    // The boundary is inside: a ray through a corner hits.
    assert!(brute::intersect(DVec3::ZERO, DVec3::Z, &s.polygons[1]).is_some());
    assert!(brute::intersect(DVec3::new(-1e-6, 0.0, 0.0), DVec3::Z, &s.polygons[1]).is_none());
}

#[test]
fn polygon_problems_come_in_the_documented_order() {
    // A face with too few vertices and a NaN: the count is checked first.
    assert_eq!(
        Polygon::new(vec![DVec3::NAN, DVec3::ZERO]).unwrap_err(),
        PolygonProblem::TooFewVertices { count: 2 }
    );
    // Repeated and collinear: the repetition is reported.
    assert_eq!(
        Polygon::new(vec![DVec3::ZERO, DVec3::X, DVec3::X]).unwrap_err(),
        PolygonProblem::RepeatedVertex { first: 1, second: 2 }
    );
    // Collinear vertices on a convex boundary are allowed.
    let p = Polygon::new(vec![DVec3::ZERO, DVec3::X, DVec3::X * 2.0, DVec3::new(2.0, 2.0, 0.0)]).unwrap();
    assert_eq!(p.area, 2.0);
}

#[test]
fn indentation_tabs_and_crlf_are_read_as_plain_lines() {
    let text = GOOD
        .replace("mtllib scene.mtl", "  mtllib\tscene.mtl")
        .replace("usemtl grey", "\tusemtl   grey")
        .replace('\n', "\r\n");
    let mtl = MTL.replace("newmtl grey", "   newmtl\tgrey").replace('\n', "\r\n");
    let s = load_with(&text, &mtl).unwrap();
    assert_eq!(s.materials[0].name, "grey");
    assert_eq!(s, load_with(GOOD, MTL).unwrap());
}

/// Regression: `tobj` panics on a colour line with fewer than three numbers (`Kd 0.5 0.5`) and
/// slices lines at byte offsets; mangled files must give errors, never panics, and the loader's
/// own checks must catch everything before `tobj` could panic.
#[test]
fn mangled_files_give_errors_not_panics() {
    use rand::{RngExt, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1990);
    let pieces = [
        "nan", "-", "/", " ", "\t", "1e999", "0", "\n", "f ", "v ", "x", "\u{85}", "\u{3000}", "Kd ", "Ke ",
        "newmtl ", "usemtl ", "mtllib ", "-1", "//", "1e9", "#",
    ];
    let mut failed_in_reader = 0;
    for _ in 0..3000 {
        let mut obj_text = GOOD.to_string();
        let mut mtl = MTL.to_string();
        for _ in 0..rng.random_range(1..6) {
            let target = if rng.random::<bool>() { &mut obj_text } else { &mut mtl };
            let mut at = rng.random_range(0..=target.len());
            while !target.is_char_boundary(at) {
                at -= 1;
            }
            if rng.random::<bool>() && at < target.len() {
                let end = target[at..].char_indices().nth(1).map_or(target.len(), |(i, _)| at + i);
                target.replace_range(at..end, "");
            } else {
                target.insert_str(at, pieces[rng.random_range(0..pieces.len())]);
            }
        }
        if let Err(e) = load_with(&obj_text, &mtl) {
            if e.to_string().contains("the OBJ reader failed") {
                failed_in_reader += 1;
            }
        }
    }
    assert_eq!(failed_in_reader, 0);
}

/// Why `scenes/cornell_box.obj` splits the left wall: the data page's quad is not planar.
#[test]
fn the_cornell_data_pages_left_wall_quad_is_rejected_as_non_planar() {
    let wall = one_face(
        &[
            ["552.8", "0.0", "0.0"],
            ["549.6", "0.0", "559.2"],
            ["556.0", "548.8", "559.2"],
            ["556.0", "548.8", "0.0"],
        ],
        "f 1 2 3 4",
    );
    let e = error(&wall);
    assert!(e.starts_with("scene.obj: face 0 (line 7) is not planar: vertex 0 lies 8.0"), "{e}");
}

/// The form factor from a differential area to a parallel rectangle `a × b` at distance `c`,
/// with one corner straight above the area (Howell's catalogue, B-3).
fn corner_rectangle(a: f64, b: f64, c: f64) -> f64 {
    let (x, y) = (a / c, b / c);
    let (sx, sy) = ((1.0 + x * x).sqrt(), (1.0 + y * y).sqrt());
    (x / sx * (y / sx).atan() + y / sy * (x / sy).atan()) / std::f64::consts::TAU
}

#[test]
fn both_ray_sets_through_the_oracle_give_the_box_rooms_form_factors() {
    // From the centre of the floor: the whole ceiling (four corner rectangles 128 × 128 at 256)
    // and the light (four 128/3 × 128/3), against the closed form; and every ray hits a wall.
    let room = box_room();
    let o = DVec3::new(128.0, 0.0, 128.0);
    let ceiling_exact = 4.0 * corner_rectangle(128.0, 128.0, 256.0);
    let light_exact = 4.0 * corner_rectangle(128.0 / 3.0, 128.0 / 3.0, 256.0);
    assert!((ceiling_exact - 0.2394565).abs() < 1e-6, "{ceiling_exact}");
    for strata in [Strata::Angle, Strata::Cosine] {
        let set = HemisphereRays::new(o, DVec3::Y, 128, 64, strata).unwrap();
        let (mut ceiling, mut light, mut total) = (0.0, 0.0, 0.0);
        for r in &set.rays {
            let hit = brute::nearest(&room, o, r.direction, Some(4)).expect("the room is closed");
            let p = &room.polygons[hit.polygon];
            total += r.weight;
            if p.normal == DVec3::NEG_Y {
                ceiling += r.weight;
                if p.emission > 0.0 {
                    light += r.weight;
                }
            }
        }
        assert!((total - 1.0).abs() < 1e-12);
        assert!(
            (ceiling - ceiling_exact).abs() < 2e-3,
            "{strata:?}: ceiling {ceiling} against {ceiling_exact}"
        );
        assert!((light - light_exact).abs() < 2e-3, "{strata:?}: light {light} against {light_exact}");
    }
}
