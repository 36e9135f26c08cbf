//! RTL of the shelling processing element, in rust-hdl: the patch loader FIFO, the per-PE patch
//! cache, the backface screener and the pipelined ray/segment intersection unit, each block
//! beside its bit-true model, with Verilog export. Number formats: `FORMATS.md` and [`formats`].
//!
//! This crate knows nothing of scenes: its inputs are integers in the formats of [`formats`].

pub mod arbiter;
pub mod cache;
pub mod formats;
pub mod intersection;
pub mod loader;
pub mod machine;
pub mod pe;
pub mod prim;
pub mod queue;
pub mod screener;
pub mod slice;

#[cfg(test)]
mod tests {
    use std::path::Path;

    /// The modules of the crate a source file names in its code (not its comments): every
    /// `crate::NAME` path.
    fn crate_uses(text: &str) -> Vec<String> {
        let mut names = vec![];
        for line in text.lines().filter(|l| !l.trim_start().starts_with("//")) {
            let mut rest = line;
            while let Some(i) = rest.find("crate::") {
                rest = &rest[i + "crate::".len()..];
                let name: String =
                    rest.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
                names.push(name);
            }
        }
        names
    }

    /// The crate modules that `module` (a top-level module of the crate) may use: the layers
    /// below it (ARCHITECTURE.md, "The hardware side").
    fn allowed(module: &str, used: &str) -> bool {
        match module {
            "formats" => false,
            "prim" => used == "formats",
            "pe" | "machine" => true,
            block => used == "formats" || used == "prim" || used == block,
        }
    }

    fn visit(dir: &Path, top: Option<&str>, bad: &mut Vec<String>, seen: &mut usize) {
        for entry in std::fs::read_dir(dir).expect("hdl/src reads") {
            let path = entry.expect("hdl/src reads").path();
            let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or_default().to_string();
            if path.is_dir() {
                visit(&path, Some(top.unwrap_or(&stem)), bad, seen);
            } else if path.extension().is_some_and(|e| e == "rs") && !(top.is_none() && stem == "lib") {
                let module = top.unwrap_or(&stem);
                let text = std::fs::read_to_string(&path).expect("a source file reads");
                *seen += 1;
                for used in crate_uses(&text) {
                    if used != module && !allowed(module, &used) {
                        bad.push(format!("{} uses crate::{used}", path.display()));
                    }
                }
            }
        }
    }

    /// Inside the crate a module uses only the layers below it: `formats` nothing, `prim` only
    /// `formats`, a block only `formats`, `prim` and itself, and only `pe` and `machine` other blocks. So no
    /// import circle can form.
    #[test]
    fn modules_use_only_the_layers_below_them() {
        let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
        let (mut bad, mut seen) = (vec![], 0);
        visit(&src, None, &mut bad, &mut seen);
        assert!(seen >= 12, "only {seen} source files found under {}", src.display());
        assert!(bad.is_empty(), "layering broken:\n{}", bad.join("\n"));
        assert!(
            !allowed("prim", "screener") && !allowed("screener", "intersection") && allowed("pe", "cache")
        );
    }
}
