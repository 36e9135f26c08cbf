//! Wavefront OBJ + MTL: the loader ([`load`], [`load_str`]) and the writer ([`to_obj`], [`save`]).
//!
//! The loader reads the OBJ text with the `tobj` crate, faces kept as polygons (no
//! triangulation, `single_index` off, points and lines ignored), and builds one [`Polygon`] per
//! `f` line, in file order: face `k` is the `k`-th `f` line, counted from 0. Before `tobj` sees
//! the text a light pass over it records, for every `f` line, its line number, its vertex count
//! and the material named by the last `usemtl` line before it; that pass is what lets an error
//! name the face and its line, and lets a `usemtl` come before the `mtllib` that defines it.
//!
//! * `mtllib` paths are relative to the OBJ file's directory; several libraries may be named.
//! * A material is `newmtl NAME` with `Kd r g b` (required) and `Ke r g b` (optional, 0 when
//!   absent); every other MTL statement is ignored. See [`Material3`] for the scalar values.
//! * Vertex normals and texture coordinates are read and ignored: the front side is given by the
//!   vertex order alone (counter-clockwise seen from the front).
//! * Only the vertices that a face uses are checked, so an unused `v 1 nan 0` is not an error.
//!
//! The writer prints one `v` line per distinct vertex position (exact comparison), then each
//! polygon as an `f` line after a `usemtl` line when the material changes; numbers are printed in
//! the shortest form that reads back to the same `f64`, so [`load`] of [`save`] gives back an
//! equal scene.

use super::scene::{FaceAt, Material3, Polygon, Scene3, Scene3Error, MAX_POLYGONS};
use glam::DVec3;
use std::cell::RefCell;
use std::collections::HashMap;
use std::fmt::Write as _;
use std::io::Read;
use std::path::{Path, PathBuf};

/// The longest OBJ or MTL file read, as for the 2D scenes (256 MiB).
pub const MAX_FILE_BYTES: u64 = 256 << 20;

/// What the first pass knows of one `f` line.
struct FaceLine {
    line: usize,
    vertices: usize,
    material: Option<String>,
}

/// Reads a whole file, at most [`MAX_FILE_BYTES`] long.
fn read_limited(path: &Path) -> Result<String, std::io::Error> {
    let file = std::fs::File::open(path)?;
    let mut bytes = Vec::new();
    file.take(MAX_FILE_BYTES + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(std::io::Error::new(std::io::ErrorKind::FileTooLarge, "file too large"));
    }
    String::from_utf8(bytes)
        .map_err(|_| std::io::Error::new(std::io::ErrorKind::InvalidData, "not UTF-8 text"))
}

/// Loads the OBJ file at `path` and the MTL libraries it names. Errors name the file as
/// `path.display()` shows it.
pub fn load(path: &Path) -> Result<Scene3, Scene3Error> {
    let name = path.display().to_string();
    let text = read_limited(path).map_err(|source| match source.kind() {
        std::io::ErrorKind::FileTooLarge => {
            Scene3Error::TooLarge { name: name.clone(), limit: MAX_FILE_BYTES }
        }
        _ => Scene3Error::Io { name: name.clone(), action: "read", source },
    })?;
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    load_str(&name, &text, &|library: &Path| read_limited(&dir.join(library)))
}

/// Loads OBJ `text` named `name`; `read_library` gives the text of an `mtllib` library by the
/// path written in the file.
pub fn load_str(
    name: &str,
    text: &str,
    read_library: &dyn Fn(&Path) -> Result<String, std::io::Error>,
) -> Result<Scene3, Scene3Error> {
    let text = &normalise(text);
    let faces = scan(name, text)?;
    if faces.is_empty() {
        return Err(Scene3Error::Empty { name: name.to_string() });
    }
    if faces.len() > MAX_POLYGONS {
        return Err(Scene3Error::TooManyPolygons { name: name.to_string(), count: faces.len() });
    }
    if !text.lines().any(|l| l.split_whitespace().next() == Some("mtllib")) {
        return Err(Scene3Error::NoMaterialLibrary { name: name.to_string() });
    }

    // Read the libraries ourselves, so their errors keep their cause and their line.
    let library_error: RefCell<Option<Scene3Error>> = RefCell::new(None);
    let loader = |library: &Path| -> tobj::MTLLoadResult {
        let library_name = library.display().to_string();
        let fail = |e: Scene3Error| {
            library_error.borrow_mut().get_or_insert(e);
            Err(tobj::LoadError::OpenFileFailed)
        };
        let text = match read_library(library) {
            Ok(text) => text,
            Err(source) => {
                return fail(Scene3Error::MaterialLibrary {
                    name: name.to_string(),
                    library: library_name,
                    source,
                })
            }
        };
        let text = normalise(&text);
        if let Some((line, message)) = scan_mtl(&text) {
            return fail(Scene3Error::MalformedMaterialLibrary {
                name: name.to_string(),
                library: library_name,
                line: Some(line),
                message,
            });
        }
        match tobj::load_mtl_buf(&mut text.as_bytes()) {
            Ok(r) => Ok(r),
            Err(e) => fail(Scene3Error::MalformedMaterialLibrary {
                name: name.to_string(),
                library: library_name,
                line: None,
                message: e.to_string(),
            }),
        }
    };
    // `tobj`'s `merging` and `reordering` features add fields (off, by default): keep the update.
    #[allow(clippy::needless_update)]
    let options = tobj::LoadOptions {
        single_index: false,
        triangulate: false,
        ignore_points: true,
        ignore_lines: true,
        ..Default::default()
    };
    // `tobj` has panicked on malformed input before (a short `Kd` line, which `scan_mtl` now
    // catches); a panic left in it becomes an error, never a crash.
    let loaded = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        tobj::load_obj_buf(&mut text.as_bytes(), &options, loader)
    }))
    .map_err(|_| Scene3Error::Malformed {
        name: name.to_string(),
        line: None,
        message: "the OBJ reader failed on this file".to_string(),
    })?;
    if let Some(e) = library_error.into_inner() {
        return Err(e);
    }
    let (models, materials) = loaded.map_err(|e| Scene3Error::Malformed {
        name: name.to_string(),
        line: None,
        message: e.to_string(),
    })?;
    let tobj_materials = materials.map_err(|e| Scene3Error::MalformedMaterialLibrary {
        name: name.to_string(),
        library: "(mtllib)".to_string(),
        line: None,
        message: e.to_string(),
    })?;

    // Every face's vertices, in file order.
    let mut polygons_vertices: Vec<Vec<DVec3>> = Vec::with_capacity(faces.len());
    for model in &models {
        let mesh = &model.mesh;
        let mut next = 0usize;
        let arities: Vec<usize> = if mesh.face_arities.is_empty() {
            vec![3; mesh.indices.len() / 3]
        } else {
            mesh.face_arities.iter().map(|&a| a as usize).collect()
        };
        for arity in arities {
            let Some(indices) = mesh.indices.get(next..next + arity) else {
                return Err(internal(name, "face indices out of range"));
            };
            next += arity;
            let mut vertices = Vec::with_capacity(arity);
            for &i in indices {
                let i = 3 * i as usize;
                let Some(p) = mesh.positions.get(i..i + 3) else {
                    return Err(internal(name, "vertex index out of range"));
                };
                vertices.push(DVec3::new(p[0], p[1], p[2]));
            }
            polygons_vertices.push(vertices);
        }
    }
    if polygons_vertices.len() != faces.len() {
        return Err(internal(name, "the OBJ reader returned a different number of faces"));
    }

    // The materials the faces use, by name, in order of first use.
    let by_name: HashMap<&str, &tobj::Material> =
        tobj_materials.iter().map(|m| (m.name.as_str(), m)).collect();
    let mut materials: Vec<Material3> = Vec::new();
    let mut index_of: HashMap<String, usize> = HashMap::new();
    let mut polygons = Vec::with_capacity(faces.len());
    for (k, (face, vertices)) in faces.iter().zip(polygons_vertices).enumerate() {
        let at = FaceAt { index: k, line: Some(face.line) };
        if vertices.len() != face.vertices {
            return Err(internal(name, "the OBJ reader returned a face of a different length"));
        }
        let polygon = Polygon::new(vertices).map_err(|problem| Scene3Error::BadFace {
            name: name.to_string(),
            face: at,
            problem,
        })?;
        let Some(material) = &face.material else {
            return Err(Scene3Error::NoMaterial { name: name.to_string(), face: at });
        };
        let index = match index_of.get(material) {
            Some(&i) => i,
            None => {
                let Some(m) = by_name.get(material.as_str()) else {
                    return Err(Scene3Error::UnknownMaterial {
                        name: name.to_string(),
                        face: at,
                        material: material.clone(),
                    });
                };
                let Some(kd) = m.diffuse else {
                    return Err(Scene3Error::BadMaterial {
                        name: name.to_string(),
                        material: material.clone(),
                        problem: "has no Kd line (the reflectance)".to_string(),
                    });
                };
                let m = Material3 { name: material.clone(), kd, ke: m.emissive.unwrap_or([0.0; 3]) };
                if let Some(problem) = m.problem() {
                    return Err(Scene3Error::BadMaterial {
                        name: name.to_string(),
                        material: m.name,
                        problem,
                    });
                }
                materials.push(m);
                index_of.insert(material.clone(), materials.len() - 1);
                materials.len() - 1
            }
        };
        polygons.push(polygon.with_material(index, &materials[index]));
    }
    Ok(Scene3 { polygons, materials })
}

/// The text with every line's leading whitespace removed and its keyword followed by one space:
/// `tobj` takes names and paths by byte offsets from the line's start and splits at the first
/// `' '`, so an indented `newmtl` or a tab after `mtllib` would be misread. Lines are kept, so
/// line numbers do not change.
fn normalise(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 16);
    for line in text.lines() {
        let line = line.trim();
        match line.split_once(char::is_whitespace) {
            Some((keyword, rest)) => {
                out.push_str(keyword);
                out.push(' ');
                out.push_str(rest.trim_start());
            }
            None => out.push_str(line),
        }
        out.push('\n');
    }
    out
}

fn internal(name: &str, message: &str) -> Scene3Error {
    Scene3Error::Malformed { name: name.to_string(), line: None, message: message.to_string() }
}

/// The first pass over the OBJ text: every `f` line's number, vertex count and material.
fn scan(name: &str, text: &str) -> Result<Vec<FaceLine>, Scene3Error> {
    let mut faces = Vec::new();
    let mut material: Option<String> = None;
    let mut positions = 0i64;
    for (i, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => positions += 1,
            Some("usemtl") => {
                let rest = line.trim_start().strip_prefix("usemtl").unwrap_or("").trim();
                if rest.is_empty() {
                    return Err(Scene3Error::Malformed {
                        name: name.to_string(),
                        line: Some(i + 1),
                        message: "usemtl without a material name".to_string(),
                    });
                }
                material = Some(rest.to_string());
            }
            Some("f") => {
                let refs: Vec<&str> = words.collect();
                let count = refs.len();
                let face = FaceAt { index: faces.len(), line: Some(i + 1) };
                // Check each vertex reference `v`, `v/t`, `v//n` or `v/t/n` (negative: relative).
                for r in &refs {
                    let v = r.split('/').next().unwrap_or("");
                    let ok = v
                        .parse::<i64>()
                        .is_ok_and(|v| (v > 0 && v <= positions) || (v < 0 && -v <= positions));
                    if !ok {
                        return Err(Scene3Error::Malformed {
                            name: name.to_string(),
                            line: Some(i + 1),
                            message: format!(
                                "{face}: vertex reference \"{r}\" is not a vertex defined above it ({positions} so far)"
                            ),
                        });
                    }
                }
                if count < 3 {
                    return Err(Scene3Error::BadFace {
                        name: name.to_string(),
                        face,
                        problem: super::PolygonProblem::TooFewVertices { count },
                    });
                }
                faces.push(FaceLine { line: i + 1, vertices: count, material: material.clone() });
            }
            _ => {}
        }
    }
    Ok(faces)
}

/// The MTL lines `tobj` would mishandle: a colour statement without three numbers.
fn scan_mtl(text: &str) -> Option<(usize, String)> {
    for (i, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        if let Some(key @ ("Ka" | "Kd" | "Ks" | "Ke" | "Tf")) = words.next() {
            let values: Vec<&str> = words.collect();
            if values.len() < 3 || values.iter().take(3).any(|v| v.parse::<f64>().is_err()) {
                return Some((
                    i + 1,
                    format!("{key} needs three numbers r g b, found \"{}\"", values.join(" ")),
                ));
            }
        }
    }
    None
}

/// The OBJ text of `scene`, naming `mtl_name` in its `mtllib` line, and the MTL text.
pub fn to_obj(scene: &Scene3, mtl_name: &str, comment: &str) -> (String, String) {
    let mut obj = String::new();
    for line in comment.lines() {
        let _ = writeln!(obj, "# {line}");
    }
    let _ = writeln!(obj, "mtllib {mtl_name}");
    let key = |v: DVec3| [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()];
    let mut index: HashMap<[u64; 3], usize> = HashMap::new();
    for p in &scene.polygons {
        for v in &p.vertices {
            if !index.contains_key(&key(*v)) {
                index.insert(key(*v), index.len() + 1);
                let _ = writeln!(obj, "v {} {} {}", v.x, v.y, v.z);
            }
        }
    }
    let mut current = None;
    for p in &scene.polygons {
        if current != Some(p.material) {
            let _ = writeln!(obj, "usemtl {}", scene.materials[p.material].name);
            current = Some(p.material);
        }
        obj.push('f');
        for v in &p.vertices {
            let _ = write!(obj, " {}", index[&key(*v)]);
        }
        obj.push('\n');
    }
    let mut mtl = String::new();
    for m in &scene.materials {
        let _ = writeln!(mtl, "newmtl {}", m.name);
        let _ = writeln!(mtl, "Kd {} {} {}", m.kd[0], m.kd[1], m.kd[2]);
        let _ = writeln!(mtl, "Ke {} {} {}", m.ke[0], m.ke[1], m.ke[2]);
    }
    (obj, mtl)
}

/// The MTL path written beside `obj`: the same name with the extension `.mtl`.
pub fn mtl_path(obj: &Path) -> PathBuf {
    obj.with_extension("mtl")
}

/// Writes `scene` to `obj` and its materials to [`mtl_path`]`(obj)`, each whole or not at all
/// (written to a temporary file beside it, then renamed).
pub fn save(scene: &Scene3, obj: &Path, comment: &str) -> Result<(), Scene3Error> {
    let mtl = mtl_path(obj);
    let mtl_name = mtl.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let (obj_text, mtl_text) = to_obj(scene, &mtl_name, comment);
    write_whole(&mtl, &mtl_text)?;
    write_whole(obj, &obj_text)
}

fn write_whole(path: &Path, text: &str) -> Result<(), Scene3Error> {
    let io = |source| Scene3Error::Io { name: path.display().to_string(), action: "write", source };
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(format!(".tmp{}", std::process::id()));
    let tmp = PathBuf::from(tmp);
    std::fs::write(&tmp, text).map_err(io)?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        io(e)
    })
}
