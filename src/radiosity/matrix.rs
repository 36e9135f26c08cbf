//! The form-factor matrix file: a slice of rows `A..B`, or the whole matrix, and the merge of
//! slices. Rows are independent, so slices can be computed on different machines (RADIOSITY.md
//! shows a Slurm job array and `xargs -P`) and merged.
//!
//! # Format, version 1
//!
//! One JSON object:
//!
//! ```json
//! {"format": "shelling-form-factors", "version": 1,
//!  "scene": {"patches": 176, "hash": "9f1c0e2a7b3d4c11"},
//!  "rays": 2048, "origins": 16, "ray_set": "sine", "method": "deterministic", "arith": "float",
//!  "rows_from": 0, "rows_to": 88,
//!  "rows": [{"source": 0, "form_factors": [{"patch": 5, "ff": 0.0123}, ...]}, ...]}
//! ```
//!
//! `scene.hash` is the FNV-1a hash of the scene as written by `Scene::to_json`, so a matrix is
//! only ever used with the scene it was computed for.
//!
//! A matrix of a 3D (OBJ) scene has `"dim": 3` (absent: 2), `scene.patches` its polygons,
//! `scene.hash` the hash of the scene as `crate::d3::obj::to_obj` writes it (OBJ then MTL), a 3D
//! technique in `method` and `"arith": "float"`. `rows` holds one row per source of
//! `rows_from..rows_to`, in order; each row's entries ascend in `patch` and leave out zeros.
//! Unknown fields are errors.

use super::form_factors::{FfParams, Row};
use crate::arith::Arith;
use crate::d3::form_factors::Ff3Params;
use crate::d3::scene::Scene3;
use crate::d3::trace::Method3;
use crate::rays::RaySet;
use crate::scene::Scene;
use crate::trace::Method;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// The `format` field of a matrix file.
pub const FORMAT: &str = "shelling-form-factors";

/// The version of the matrix file this module writes and reads.
pub const VERSION: u32 = 1;

/// The scene a matrix belongs to.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneId {
    pub patches: usize,
    pub hash: String,
}

impl SceneId {
    pub fn of(scene: &Scene) -> SceneId {
        let h = shelling_testbench::export::fnv1a64(scene.to_json().bytes());
        SceneId { patches: scene.len(), hash: format!("{h:016x}") }
    }

    /// The id of a 3D scene: its polygons, and the hash of its OBJ and MTL text.
    pub fn of3(scene: &Scene3) -> SceneId {
        let (obj, mtl) = crate::d3::obj::to_obj(scene, "scene.mtl", "");
        let h = shelling_testbench::export::fnv1a64(obj.bytes().chain(mtl.bytes()));
        SceneId { patches: scene.polygons.len(), hash: format!("{h:016x}") }
    }
}

fn two() -> u8 {
    2
}

fn is_two(d: &u8) -> bool {
    *d == 2
}

/// A slice of the form-factor matrix, or the whole of it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MatrixFile {
    pub format: String,
    pub version: u32,
    /// 2 (a 2D scene of segments) or 3 (an OBJ scene of polygons).
    #[serde(default = "two", skip_serializing_if = "is_two")]
    pub dim: u8,
    pub scene: SceneId,
    pub rays: usize,
    pub origins: usize,
    pub ray_set: RaySet,
    /// The technique's name: a 2D one ([`Method`]) or, in 3D, a 3D one ([`Method3`]).
    pub method: String,
    pub arith: Arith,
    pub rows_from: usize,
    pub rows_to: usize,
    pub rows: Vec<Row>,
}

/// What is wrong with a matrix file or a merge.
#[derive(Debug, thiserror::Error)]
pub enum MatrixError {
    #[error("{name}: {source}")]
    Io { name: String, source: std::io::Error },
    #[error("{name}: not a form-factor matrix file: {source}")]
    Parse { name: String, source: serde_json::Error },
    #[error("{name}: {problem}")]
    Invalid { name: String, problem: String },
    #[error("{name} and {other} {problem}")]
    Mismatch { name: String, other: String, problem: String },
    #[error("the slices leave rows {from}..{to} out")]
    Gap { from: usize, to: usize },
    #[error("nothing to merge: give at least one slice")]
    Empty,
}

impl MatrixFile {
    /// The slice `rows_from..rows_to` of `rows` computed for `scene` with `p`.
    pub fn new(scene: &Scene, p: &FfParams, rows_from: usize, rows: Vec<Row>) -> MatrixFile {
        MatrixFile {
            format: FORMAT.to_string(),
            version: VERSION,
            dim: 2,
            scene: SceneId::of(scene),
            rays: p.rays,
            origins: p.origins,
            ray_set: p.ray_set,
            method: p.method.name().to_string(),
            arith: p.arith,
            rows_from,
            rows_to: rows_from + rows.len(),
            rows,
        }
    }

    /// The slice `rows_from..rows_to` of `rows` computed for the 3D `scene` with `p`, its rays
    /// the set `ray_set` names.
    pub fn new3(
        scene: &Scene3,
        p: &Ff3Params,
        ray_set: RaySet,
        rows_from: usize,
        rows: Vec<Row>,
    ) -> MatrixFile {
        MatrixFile {
            format: FORMAT.to_string(),
            version: VERSION,
            dim: 3,
            scene: SceneId::of3(scene),
            rays: p.rays,
            origins: p.origins,
            ray_set,
            method: p.method.name().to_string(),
            arith: Arith::Float,
            rows_from,
            rows_to: rows_from + rows.len(),
            rows,
        }
    }

    /// Whether the file holds every row of its scene.
    pub fn is_whole(&self) -> bool {
        self.rows_from == 0 && self.rows_to == self.scene.patches
    }

    /// Reads and checks a matrix file.
    pub fn load(path: &Path) -> Result<MatrixFile, MatrixError> {
        let name = path.display().to_string();
        let text =
            std::fs::read_to_string(path).map_err(|source| MatrixError::Io { name: name.clone(), source })?;
        let m: MatrixFile = serde_json::from_str(&text)
            .map_err(|source| MatrixError::Parse { name: name.clone(), source })?;
        m.check(&name)?;
        Ok(m)
    }

    /// The file's text.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).expect("a matrix serialises") + "\n"
    }

    /// The rules of the format; `name` is the file name errors carry.
    pub fn check(&self, name: &str) -> Result<(), MatrixError> {
        let invalid = |problem: String| Err(MatrixError::Invalid { name: name.to_string(), problem });
        if self.format != FORMAT {
            return invalid(format!("the format is {:?}, expected {FORMAT:?}", self.format));
        }
        if self.version != VERSION {
            return invalid(format!(
                "version {} is not supported (this build reads version {VERSION})",
                self.version
            ));
        }
        let known = match self.dim {
            2 => Method::ALL.iter().any(|m| m.name() == self.method),
            3 => Method3::ALL.iter().any(|m| m.name() == self.method),
            d => return invalid(format!("dim is {d}: a matrix is of a 2D (2) or a 3D (3) scene")),
        };
        if !known {
            return invalid(format!("method {:?} is not a {}D technique", self.method, self.dim));
        }
        if self.dim == 3 && self.arith != Arith::Float {
            return invalid("a 3D matrix is traced in f64: arith must be \"float\"".to_string());
        }
        if self.rows_from > self.rows_to || self.rows_to > self.scene.patches {
            return invalid(format!(
                "rows {}..{} do not lie in the scene's 0..{}",
                self.rows_from, self.rows_to, self.scene.patches
            ));
        }
        if self.rows.len() != self.rows_to - self.rows_from {
            return invalid(format!(
                "rows {}..{} need {} rows, the file has {}",
                self.rows_from,
                self.rows_to,
                self.rows_to - self.rows_from,
                self.rows.len()
            ));
        }
        for (k, row) in self.rows.iter().enumerate() {
            if row.source != self.rows_from + k {
                return invalid(format!(
                    "row {k} is of source {}, expected {}",
                    row.source,
                    self.rows_from + k
                ));
            }
            let ascending = row.entries.windows(2).all(|w| w[0].patch < w[1].patch);
            let valid = row
                .entries
                .iter()
                .all(|e| (e.patch as usize) < self.scene.patches && e.ff.is_finite() && e.ff > 0.0);
            if !ascending || !valid {
                return invalid(format!(
                    "the row of source {} must list patches below {} in ascending order with positive form factors",
                    row.source, self.scene.patches
                ));
            }
        }
        Ok(())
    }

    /// Checks that the matrix was computed for `scene` (named `name`).
    pub fn check_scene(&self, scene: &Scene, matrix: &str, name: &str) -> Result<(), MatrixError> {
        self.check_id(2, &SceneId::of(scene), matrix, name)
    }

    /// Checks that the matrix was computed for the 3D `scene` (named `name`).
    pub fn check_scene3(&self, scene: &Scene3, matrix: &str, name: &str) -> Result<(), MatrixError> {
        self.check_id(3, &SceneId::of3(scene), matrix, name)
    }

    fn check_id(&self, dim: u8, id: &SceneId, matrix: &str, name: &str) -> Result<(), MatrixError> {
        if dim != self.dim {
            return Err(MatrixError::Mismatch {
                name: matrix.to_string(),
                other: name.to_string(),
                problem: format!("do not match: the matrix is of a {}D scene, the scene is {dim}D", self.dim),
            });
        }
        if *id != self.scene {
            return Err(MatrixError::Mismatch {
                name: matrix.to_string(),
                other: name.to_string(),
                problem: format!(
                    "do not match: the matrix is of a scene of {} patches with hash {}, the scene has {} patches and hash {}",
                    self.scene.patches, self.scene.hash, id.patches, id.hash
                ),
            });
        }
        Ok(())
    }
}

/// Merges slices (each named for errors) into one file: they must share the scene and the
/// parameters and cover `0..patches` without overlap, in any order.
pub fn merge(mut slices: Vec<(String, MatrixFile)>) -> Result<MatrixFile, MatrixError> {
    if slices.is_empty() {
        return Err(MatrixError::Empty);
    }
    slices.sort_by_key(|(_, m)| m.rows_from);
    let (first_name, first) = &slices[0];
    let header =
        |m: &MatrixFile| (m.dim, m.scene.clone(), m.rays, m.origins, m.ray_set, m.method.clone(), m.arith);
    let mut next = 0;
    let mut prev_name = String::new();
    for (name, m) in &slices {
        if header(m) != header(first) {
            return Err(MatrixError::Mismatch {
                name: name.clone(),
                other: first_name.clone(),
                problem: "were computed for different scenes or with different parameters".to_string(),
            });
        }
        if m.rows_from < next {
            return Err(MatrixError::Mismatch {
                name: name.clone(),
                other: prev_name.clone(),
                problem: format!("overlap: both hold rows from {}", m.rows_from),
            });
        }
        if m.rows_from > next {
            return Err(MatrixError::Gap { from: next, to: m.rows_from });
        }
        next = m.rows_to;
        prev_name = name.clone();
    }
    if next < first.scene.patches {
        return Err(MatrixError::Gap { from: next, to: first.scene.patches });
    }
    let mut whole = slices[0].1.clone();
    whole.rows = slices.into_iter().flat_map(|(_, m)| m.rows).collect();
    whole.rows_from = 0;
    whole.rows_to = whole.rows.len();
    Ok(whole)
}
