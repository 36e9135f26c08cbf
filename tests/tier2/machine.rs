//! Tier 2: the machine's committed figures against the current code. `figures/machine.csv`'s
//! rows of 1 and 8 PEs at T_c 16 with caches off and of 128 patches, and the deal rows, recomputed
//! with the command FIGURES.md quotes (cycle counts are exact, so any change to the RTL, the
//! scheduler or the host shows), and the machine rows of the README's
//! headline (`figures/headline.md`, from `cargo bench --bench machine`) and of the 3D headline
//! (`figures/headline3d.md`, `cargo bench --bench machine3d`) co-simulated again.

use shelling::cosim::Engine;
use shelling::figures::machine::headline_run;
use shelling::trace::Method;
use std::path::Path;

fn committed(name: &str) -> String {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("figures").join(name);
    std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// The machine rows of a headline table: each line, its PE count and its cells.
fn machine_rows(table: &str) -> Vec<(&str, usize, Vec<&str>)> {
    table
        .lines()
        .filter(|l| l.starts_with("| machine, "))
        .map(|line| {
            let cells: Vec<&str> = line.split('|').map(str::trim).collect();
            let pes: usize = cells[1]
                .trim_start_matches("machine, ")
                .split(' ')
                .next()
                .and_then(|n| n.parse().ok())
                .unwrap_or_else(|| panic!("no PE count in {line:?}"));
            (line, pes, cells)
        })
        .collect()
}

#[test]
fn the_committed_machine_figures_are_those_of_the_current_code() {
    assert!(shelling_testbench::verilated::available(), "the machine figures need Verilator (see .ci/run)");
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("tier2-machine");
    let _ = std::fs::remove_dir_all(&out);
    // Every length (a length's scene seed is its index in the list), a subset of the rest:
    // each run is independent of the others, so its row must be the committed one.
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_shelling"))
        .args(["machine-figures", "--pes", "1,8", "--tc", "16", "--caches", "off,128", "--out"])
        .arg(&out)
        .stdout(std::process::Stdio::null())
        .status()
        .expect("runs the machine-figures command");
    assert!(
        status.success(),
        "machine-figures --pes 1,8 --tc 16 --caches off,128 --out {}: {status}",
        out.display()
    );
    let fresh = std::fs::read_to_string(out.join("machine.csv")).expect("machine.csv written");
    let old = committed("machine.csv");
    let old: std::collections::HashSet<&str> = old.lines().collect();
    let fresh: Vec<&str> = fresh.lines().skip(1).collect();
    assert!(fresh.len() > 100, "only {} fresh rows", fresh.len());
    for row in &fresh {
        assert!(
            old.contains(row),
            "figures/machine.csv is stale at {row}: run `cargo run --release -- machine-figures --out figures` \
             and update FIGURES.md"
        );
    }
}

#[test]
fn the_readmes_headline_cycles_are_those_of_the_current_code() {
    assert!(shelling_testbench::verilated::available(), "the headline needs Verilator (see .ci/run)");
    let table = committed("headline.md");
    let mut checked = 0;
    for (line, pes, cells) in machine_rows(&table) {
        let method = match cells[2] {
            "stochastic" => Method::Stochastic,
            "deterministic" => Method::Deterministic,
            m => panic!("technique {m:?} in {line:?}"),
        };
        let cycles: u64 = cells[3].parse().unwrap_or_else(|_| panic!("no cycles in {line:?}"));
        let run = headline_run(method, pes, Engine::Verilator).unwrap_or_else(|e| panic!("{e:#}"));
        assert_eq!(
            run.cycles, cycles,
            "figures/headline.md is stale ({pes} PEs, {method}): run `cargo bench --bench machine -- --write \
             figures/headline.md` and update the README"
        );
        checked += 1;
    }
    assert!(checked >= 4, "figures/headline.md has {checked} machine rows");
}

#[test]
fn the_3d_headline_cycles_are_those_of_the_current_code() {
    assert!(shelling_testbench::verilated::available(), "the headline needs Verilator (see .ci/run)");
    let table = committed("headline3d.md");
    let mut checked = 0;
    for (line, pes, cells) in machine_rows(&table) {
        let (cycles, loads): (u64, u64) = match (cells[3].parse(), cells[4].parse()) {
            (Ok(c), Ok(l)) => (c, l),
            _ => panic!("no cycles or host loads in {line:?}"),
        };
        let t =
            shelling::figures::d3::headline3d_run(pes, Engine::Verilator).unwrap_or_else(|e| panic!("{e:#}"));
        assert_eq!(
            (t.pe.cycles, t.pe.patch_loads - t.pe.cache_hits),
            (cycles, loads),
            "figures/headline3d.md is stale ({pes} PEs): run `cargo bench --bench machine3d -- --write \
             figures/headline3d.md` and update the README"
        );
        checked += 1;
    }
    assert!(checked >= 4, "figures/headline3d.md has {checked} machine rows");
}
