//! Tier 2: the co-simulated part of the committed figures (`figures/cycles.csv` and the tables
//! `figures/cycles.md` and `figures/cycles_queue.md` that FIGURES.md holds) recomputed with the
//! command FIGURES.md quotes and compared byte for byte (the cycle counts are exact, so any
//! change to the RTL, the scheduler or the host's commands shows). `SHELLING_BLESS=1` copies the fresh files over the committed
//! ones instead.

use std::path::Path;

#[test]
fn the_committed_cycle_figures_are_those_of_the_current_code() {
    assert!(
        shelling_testbench::verilated::available(),
        "the cycle figures need Verilator (an hour on rust-hdl's simulation): install it (see .ci/run)"
    );
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("tier2-figures");
    let _ = std::fs::remove_dir_all(&out);
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_shelling"))
        .args(["figures", "--out"])
        .arg(&out)
        .stdout(std::process::Stdio::null())
        .status()
        .expect("runs the figures command");
    assert!(status.success(), "figures --out {}: {status}", out.display());
    let committed = Path::new(env!("CARGO_MANIFEST_DIR")).join("figures");
    for name in ["cycles.csv", "cycles.md", "cycles_queue.md", "cycles_inorder.md"] {
        let fresh = std::fs::read_to_string(out.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        if std::env::var_os("SHELLING_BLESS").is_some() {
            std::fs::write(committed.join(name), &fresh).unwrap();
            continue;
        }
        let old = std::fs::read_to_string(committed.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(
            old == fresh,
            "figures/{name} is stale: run `cargo run --release -- figures --out figures` (or \
             SHELLING_BLESS=1 cargo test --release --features tier2 --test tier2 figures) and update FIGURES.md"
        );
    }
}
