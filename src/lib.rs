//! # shelling
//!
//! A hardware/software co-design kit for the *shelling* space partitioning of Shen, Deprettere
//! and Dewilde (EGGH 1990): form-factor ray casting of the radiosity method mapped onto a
//! pipelined intersection architecture.
//!
//! This crate is the golden model and the experiments: scenes ([`scene`]), ray bundles
//! ([`rays`]), the grid with macro-regions ([`grid`]), the four tracers ([`trace`]) with the
//! paper's counters ([`counters`]), the analytic model of Section 4 ([`model`]) the
//! reproduction of Section 5's figures ([`figures`]) and the radiosity method the paper serves
//! ([`radiosity`]: form factors and solvers). [`arith`] swaps the golden `f64` hit test
//! for the bit-true fixed-point model of the RTL (`shelling-hdl`). See `ARCHITECTURE.md` for the data flow.

pub mod agreement;
pub mod arith;
pub mod cosim;
pub mod counters;
pub mod d3;
pub mod figures;
pub mod geom;
pub mod grid;
pub mod limits;
pub mod machine;
pub mod model;
pub mod radiosity;
pub mod rays;
pub mod run;
pub mod scene;
pub mod staged;
pub mod trace;
pub mod workstream;

#[cfg(test)]
mod layering {
    use std::path::{Path, PathBuf};

    /// Every `.rs` file under `dir` (relative to the crate's root), recursively.
    fn rs_files(dir: &str) -> Vec<PathBuf> {
        let (mut files, mut dirs) = (vec![], vec![Path::new(env!("CARGO_MANIFEST_DIR")).join(dir)]);
        while let Some(dir) = dirs.pop() {
            for entry in std::fs::read_dir(&dir).expect("a source directory reads") {
                let path = entry.expect("a source directory reads").path();
                if path.is_dir() {
                    dirs.push(path);
                } else if path.extension().is_some_and(|e| e == "rs") {
                    files.push(path);
                }
            }
        }
        files
    }

    /// The rust-hdl blocks of `shelling-hdl`: every `pub struct` under `#[derive(LogicBlock…)]`.
    fn hdl_blocks() -> Vec<String> {
        let mut names = vec![];
        for path in rs_files("hdl/src") {
            let text = std::fs::read_to_string(&path).expect("a source file reads");
            let mut derive = false;
            for line in text.lines().map(str::trim) {
                if line.starts_with("#[derive(") && line.contains("LogicBlock") {
                    derive = true;
                } else if derive && line.starts_with("pub struct ") {
                    let name = &line["pub struct ".len()..];
                    names.push(name.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect());
                    derive = false;
                } else if !line.starts_with("#[") && !line.starts_with("///") {
                    derive = false;
                }
            }
        }
        names
    }

    /// `src/` reaches RTL blocks only through `shelling-testbench` (ARCHITECTURE.md,
    /// "Invariants"): no source file under it names a rust-hdl block of `shelling-hdl`; it may
    /// use `shelling-hdl`'s models, formats and constants.
    #[test]
    fn src_names_no_rtl_block() {
        let blocks = hdl_blocks();
        assert!(blocks.len() >= 10 && blocks.iter().any(|b| b == "Machine"), "blocks found: {blocks:?}");
        let files = rs_files("src");
        assert!(files.len() >= 40, "only {} source files found under src/", files.len());
        let mut bad = vec![];
        for path in files {
            let text = std::fs::read_to_string(&path).expect("a source file reads");
            for line in text.lines().filter(|l| l.contains("shelling_hdl::")) {
                let words: Vec<&str> = line.split(|c: char| !(c.is_alphanumeric() || c == '_')).collect();
                if let Some(b) = blocks.iter().find(|b| words.contains(&b.as_str())) {
                    bad.push(format!("{}: {b}: {}", path.display(), line.trim()));
                }
            }
        }
        assert!(bad.is_empty(), "src/ names RTL blocks of shelling-hdl:\n{}", bad.join("\n"));
    }
}
