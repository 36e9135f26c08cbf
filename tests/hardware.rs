//! The hardware side seen from the whole system: rung 2 (the bit-true fixed point against the
//! f64 golden model, within the bound of `hdl/FORMATS.md`), the fixed-point range checks, the
//! committed Verilog and post-route results being current (and the clocks the documents cite
//! being those results), and the synthesizability test of every block: Yosys'
//! `synth_ecp5` on its exported Verilog, no latches, products on DSP blocks.

use crate::support::synth::{assert_no_latch, cells, synth_ecp5, synth_ecp5_script, verilog_dir};
use shelling::agreement::{self, Workload};
use shelling::arith::{Arith, FixedBundle};
use shelling::geom::{Segment, Vec2};
use shelling::grid::GridParams;
use shelling::rays::RaySet;
use shelling::run::{GriddedScene, RunError};
use shelling::scene::Scene;
use shelling::trace::{Method, ShellParams};
use std::path::PathBuf;

#[test]
fn rung2_fixed_point_agrees_with_float_within_the_bound() {
    for ray_set in [RaySet::Angle, RaySet::Sine] {
        let w = Workload { sources: 8, ray_set, ..Workload::default() };
        let report = agreement::run(&w).expect("the paper's workload fits the fixed-point formats");
        assert_eq!(report.rows.len(), 12);
        for r in &report.rows {
            let c = &r.comparison;
            assert_eq!(c.rays, 8 * 1024);
            assert!(
                c.unexplained.is_empty() && c.distance_violations.is_empty(),
                "length {} {} {ray_set}: beyond the bound: {:?} {:?}",
                r.length,
                r.method,
                c.unexplained,
                c.distance_violations
            );
            assert!(c.rate() >= 0.995, "length {} {}: agreement {}", r.length, r.method, c.rate());
        }
        // The bound is not vacuous: somewhere the arithmetics do disagree, and are explained.
        let explained: usize =
            report.rows.iter().map(|r| r.comparison.endpoint + r.comparison.near_tie).sum();
        assert!(explained > 0, "{ray_set}: no disagreement at all; the comparison may not be running");
    }
}

#[test]
fn fixed_point_rejects_what_does_not_fit_and_names_it() {
    let seg = |ax, ay, bx, by| Segment::new(Vec2::new(ax, ay), Vec2::new(bx, by));
    let scene =
        Scene::new(vec![seg(0.0, 0.0, 10.0, 0.0), seg(100.0, 5.0, 3000.0, 5.0)]).expect("valid scene");
    let prepared = GriddedScene::new(scene, GridParams::default());
    let bundle = prepared.patch_bundle(0, RaySet::Angle, 64).expect("valid source");
    // The float model traces it; the fixed point refuses before tracing.
    assert!(prepared.trace_in(Arith::Float, Method::Deterministic, &bundle, &ShellParams::default()).is_ok());
    let err =
        prepared.trace_in(Arith::Fixed, Method::Deterministic, &bundle, &ShellParams::default()).unwrap_err();
    assert!(matches!(err, RunError::Format(_)));
    let msg = err.to_string();
    assert!(msg.contains("segment 1 endpoint b x") && msg.contains("3000"), "{msg}");
    // A scene anywhere, as long as it spans less than 2048 units, fits (translation invariance).
    let far =
        Scene::new(vec![seg(1e6, 1e6, 1e6 + 10.0, 1e6), seg(1e6 + 25.0, 1e6 + 50.0, 1e6 - 15.0, 1e6 + 50.0)])
            .expect("valid scene");
    let far = GriddedScene::new(far, GridParams::default());
    let b = far.patch_bundle(0, RaySet::Angle, 64).expect("valid source");
    let fixed = FixedBundle::new(&far.scene.segments, &b).expect("fits");
    assert!(fixed.patch(1).is_some(), "the facing patch passes the screener");
    let hits = far.trace_in(Arith::Fixed, Method::Brute, &b, &ShellParams::default()).expect("traces");
    assert!(hits.hits.iter().flatten().all(|h| h.segment == 1) && hits.hits.iter().flatten().count() > 0);
}

#[test]
fn committed_verilog_is_current() {
    let fresh = shelling_testbench::export::verilog().expect("every block exports");
    let dir = verilog_dir();
    let list = std::fs::read_to_string(dir.join(shelling_testbench::export::FILE_LIST))
        .expect("hdl/verilog/files.f is committed");
    let names: Vec<&str> = fresh.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(list.lines().collect::<Vec<_>>(), names, "hdl/verilog/files.f is stale");
    for (name, text) in &fresh {
        let committed = std::fs::read_to_string(dir.join(name)).unwrap_or_default();
        assert!(
            committed == *text,
            "hdl/verilog/{name} is stale: run `cargo run --release -- export-verilog --out hdl/verilog`"
        );
    }
}

/// The committed post-route results (`hdl/fpga/`, from `cargo xtask fpga --seeds ...`) name, for
/// every block measured, the hash of that block's own Verilog file: it must be the committed
/// file's, which [`committed_verilog_is_current`] checks against the RTL. Any change to a
/// measured block's RTL fails this test until the flow is run again, so no clock rate in the
/// documents outlives the design it was measured on; a block added or changed elsewhere leaves
/// the others' results current.
#[test]
fn committed_fpga_results_are_of_the_committed_verilog() {
    let results = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("hdl/fpga/ecp5-seeds.json");
    let text = std::fs::read_to_string(&results).expect("hdl/fpga/ecp5-seeds.json is committed");
    let json: serde_json::Value = serde_json::from_str(&text).expect("hdl/fpga/ecp5-seeds.json is JSON");
    let blocks = json["blocks"].as_array().expect("the results list blocks");
    let measured: Vec<&str> = blocks.iter().filter_map(|b| b["block"].as_str()).collect();
    for required in ["processing_element", "screener", "intersection_unit", "patch_cache"] {
        assert!(measured.contains(&required), "hdl/fpga/ecp5-seeds.json has no results of {required}");
    }
    for b in blocks {
        let block = b["block"].as_str().expect("a block is named");
        let name = format!("{block}.v");
        let committed =
            std::fs::read_to_string(verilog_dir().join(&name)).expect("the block's Verilog is committed");
        assert_eq!(
            b["verilog_hash"].as_str().expect("a block's results name its Verilog's hash"),
            shelling_testbench::export::hash(&[(name, committed)]),
            "hdl/fpga/ is stale: {block}'s Verilog changed since it was measured. Run `cargo xtask fpga --out \
             out/fpga --families ecp5 --blocks processing_element,screener,intersection_unit,patch_cache --seeds \
             1,2,3,4,5` and copy out/fpga/fpga.md to hdl/fpga/ecp5.md and out/fpga/fpga-seeds.json to \
             hdl/fpga/ecp5-seeds.json"
        );
        assert!(b["median_mhz"].is_f64(), "{block} has no median clock rate");
    }
}

/// The committed post-route results of the machine (`hdl/fpga/ecp5-machine-seeds.json`, from
/// `cargo xtask fpga --blocks machine_N`, which the headline's bench reads its clock from) are
/// of the machine's current Verilog: its export for that many PEs is not committed (half a
/// megabyte a PE), so it is exported again here and hashed. Each result is a median over three
/// placement seeds at least.
#[test]
fn committed_machine_fpga_results_are_of_the_current_machine() {
    use shelling_testbench::export::{hash, machine_block_pes, machine_verilog};
    let results = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("hdl/fpga/ecp5-machine-seeds.json");
    let text = std::fs::read_to_string(&results).expect("hdl/fpga/ecp5-machine-seeds.json is committed");
    let json: serde_json::Value = serde_json::from_str(&text).expect("the machine's results are JSON");
    let blocks = json["blocks"].as_array().expect("the results list blocks");
    assert!(!blocks.is_empty(), "hdl/fpga/ecp5-machine-seeds.json lists no machine");
    for b in blocks {
        let block = b["block"].as_str().expect("a block is named");
        let pes = machine_block_pes(block).unwrap_or_else(|| panic!("{block} is not a machine_N block"));
        let file = machine_verilog(pes).expect("the machine exports");
        // The nextpnr options the block was placed with, if any (`pnr`), are part of its command.
        let pnr = b["pnr"].as_str().map(|o| format!(" --ecp5-pnr-options \"{o}\"")).unwrap_or_default();
        assert_eq!(
            b["verilog_hash"].as_str().expect("a block's results name its Verilog's hash"),
            hash(&[file]),
            "hdl/fpga/ecp5-machine-seeds.json is stale: {block}'s Verilog changed since it was measured. Run \
             `cargo xtask fpga --out out/fpga-m --families ecp5 --blocks {block} --seeds 1,2,3{pnr}` and copy \
             its block from fpga-seeds.json to hdl/fpga/ecp5-machine-seeds.json and its rows from fpga.md to \
             hdl/fpga/ecp5-machine.md"
        );
        let seeds = b["seeds"].as_array().map_or(0, Vec::len);
        assert!(seeds >= 3, "{block}: a median of {seeds} seeds; three at least");
        assert!(b["median_mhz"].is_f64(), "{block} has no median clock rate");
    }
}

/// Every clock rate the documents cite as a post-route result, `151.0 (machine_6)` or
/// `150.4 (the PE's alone)` (the headlines' tables, which their benches write from the committed
/// results, and the tables copied from them), is the committed median of that block: a change of
/// `hdl/fpga/*-seeds.json` without the figures measured again at the new clock fails here.
#[test]
fn the_documents_cite_the_committed_post_route_clocks() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let median = |file: &str, block: &str| -> f64 {
        let text = std::fs::read_to_string(root.join("hdl/fpga").join(file)).unwrap();
        let json: serde_json::Value = serde_json::from_str(&text).unwrap();
        let blocks = json["blocks"].as_array().unwrap();
        let b = blocks.iter().find(|b| b["block"] == block && b["family"] == "ecp5");
        b.and_then(|b| b["median_mhz"].as_f64()).unwrap_or_else(|| panic!("{file} has no median of {block}"))
    };
    let mut cited = 0;
    for doc in [
        "README.md",
        "SCENES3D.md",
        "FIGURES.md",
        "RADIOSITY.md",
        "figures/headline.md",
        "figures/headline3d.md",
    ] {
        let text = std::fs::read_to_string(root.join(doc)).unwrap();
        for (at, _) in text.match_indices(" (") {
            let whose = &text[at + 2..];
            let Some(whose) = whose.find(')').map(|e| &whose[..e]) else { continue };
            let expected = if let Some(n) = whose.strip_prefix("machine_") {
                if n.is_empty() || !n.bytes().all(|c| c.is_ascii_digit()) {
                    continue;
                }
                median("ecp5-machine-seeds.json", whose)
            } else if whose == "the PE's alone" || whose == "the PE's" {
                median("ecp5-seeds.json", "processing_element")
            } else {
                continue;
            };
            let number: String =
                text[..at].chars().rev().take_while(|c| c.is_ascii_digit() || *c == '.').collect();
            let number: String = number.chars().rev().collect();
            let Ok(mhz) = number.parse::<f64>() else { continue };
            assert_eq!(
                format!("{mhz:.1}"),
                format!("{expected:.1}"),
                "{doc} cites {mhz:.1} MHz for {whose}, the committed median is {expected:.1}: measure its figures again \
                 (`cargo bench --bench machine -- --write figures/headline.md`, `--bench machine3d`) and update them"
            );
            cited += 1;
        }
    }
    assert!(cited >= 20, "the documents cite {cited} post-route clocks: the tables moved?");
}

#[test]
fn intersection_unit_synthesizes_to_dsps_without_latches() {
    let stat = synth_ecp5("intersection_unit");
    assert_no_latch("intersection_unit", &stat);
    assert_eq!(cells(&stat, "MULT18X18D"), 6, "six 18x18 multipliers, one DSP each:\n{stat}");
    assert!(cells(&stat, "DP16KD") >= 4, "the ray and direction memories map to block RAM:\n{stat}");
    assert!(cells(&stat, "LUT4") > 0 && cells(&stat, "TRELLIS_FF") > 0, "{stat}");
}

/// The intersection unit's memories are `BramOut`s: on ECP5 twelve hand-instantiated `DP16KD`s
/// (directions 4 for the 2048 rays of the two halves; per half live bits 1, keys 2, valid + id
/// 1), every one reading through its output
/// register (`REGMODE_B = "OUTREG"`), none left to Yosys' memory mapping (which never sets it).
#[test]
fn intersection_unit_block_rams_use_their_output_register() {
    let text = synth_ecp5_script(
        "intersection_unit",
        "synth_ecp5",
        "tee -o /dev/stdout stat; select -list t:DP16KD r:REGMODE_B=OUTREG %i; \
         select -assert-count 12 t:DP16KD; select -assert-count 12 t:DP16KD r:REGMODE_B=OUTREG %i",
    );
    assert_eq!(cells(&text, "DP16KD"), 12, "{text}");
}

/// Every multiplier of the intersection unit (6) and the screener (10) is a hand-instantiated
/// `MULT18X18D` with its own input and output registers (`REG_INPUTA_CLK`, `REG_OUTPUT_CLK` =
/// `"CLK0"`), none left to Yosys' mapping of a Verilog product (which leaves them off).
#[test]
fn multipliers_use_their_own_registers() {
    for (block, dsps) in [("intersection_unit", 6), ("screener", 10)] {
        let text = synth_ecp5_script(
            block,
            "synth_ecp5",
            &format!(
                "tee -o /dev/stdout stat; select -assert-count {dsps} t:MULT18X18D; \
                 select -assert-count {dsps} t:MULT18X18D r:REG_INPUTA_CLK=CLK0 %i r:REG_INPUTB_CLK=CLK0 %i \
                 r:REG_OUTPUT_CLK=CLK0 %i"
            ),
        );
        assert_eq!(cells(&text, "MULT18X18D"), dsps, "{block}: {text}");
    }
}

/// The loader has no multiplier; the screener's ten products take one DSP each and its pipelined
/// divider none (LUTs and carry chains). Both FIFOs map to LUT RAM, as do the FIFO block alone
/// (`fwft_fifo`, `prim::Fifo`), the PE's job queue (`job_queue`) and the memory arbiter's
/// request and route queues (`memory_arbiter`).
#[test]
fn patch_loader_screener_and_fifos_synthesize_without_latches() {
    let blocks =
        [("patch_loader", 0), ("screener", 10), ("fwft_fifo", 0), ("job_queue", 0), ("memory_arbiter", 0)];
    for (block, dsps) in blocks {
        let stat = synth_ecp5(block);
        assert_no_latch(block, &stat);
        assert!(cells(&stat, "TRELLIS_FF") > 0, "{block}: {stat}");
        assert_eq!(cells(&stat, "MULT18X18D"), dsps, "{block}: multipliers map to DSP blocks:\n{stat}");
        assert!(cells(&stat, "TRELLIS_DPR16X4") > 0, "{block}: the FIFO maps to LUT RAM:\n{stat}");
    }
}

/// The patch cache's five lanes (tag, four coordinates) of 1024 × 17 bits are `BramOut`s: one
/// 1024 × 18 `DP16KD` tile each, every one reading through its output register.
#[test]
fn patch_cache_synthesizes_to_block_ram_without_latches() {
    let stat = synth_ecp5_script(
        "patch_cache",
        "synth_ecp5",
        "tee -o /dev/stdout stat; select -assert-count 5 t:DP16KD; \
         select -assert-count 5 t:DP16KD r:REGMODE_B=OUTREG %i",
    );
    assert_no_latch("patch_cache", &stat);
    assert_eq!(cells(&stat, "DP16KD"), 5, "the 1024-line memories map to block RAM:\n{stat}");
    assert_eq!(cells(&stat, "MULT18X18D"), 0, "{stat}");
    assert!(cells(&stat, "LUT4") > 0 && cells(&stat, "TRELLIS_FF") > 0, "{stat}");
    println!("{stat}");
}

/// The whole processing element: its blocks' products on DSPs (6 + 10), its memories in block
/// RAM (cache, ray and direction memories) and LUT RAM (FIFOs), no latch anywhere.
#[test]
fn processing_element_synthesizes_without_latches() {
    let stat = synth_ecp5("processing_element");
    assert_no_latch("processing_element", &stat);
    assert_eq!(cells(&stat, "MULT18X18D"), 16, "{stat}");
    assert_eq!(cells(&stat, "DP16KD"), 17, "the cache's five tiles and the unit's twelve:\n{stat}");
    assert!(cells(&stat, "TRELLIS_DPR16X4") > 0, "{stat}");
    println!("{stat}");
}
