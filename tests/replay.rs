//! Rungs 4 and 5 for the whole processing element: full-scene co-simulations, recorded port by
//! port and cycle by cycle on one rust-hdl PE, replayed through the PE's exported Verilog under
//! Icarus Verilog and under Verilator (rung 4), and through Yosys' word-level and gate-level
//! netlists of it (rung 5). Every output of every cycle must agree bit for bit.
//!
//! The vectors: the paper's workload at every segment length (1000 patches, one source per
//! length), each source traced by all three techniques, each run once with the patch cache off
//! and once with it on, back to back on the same PE (36 sources, every one checked against the
//! bit-true model as it runs). The host memory answers in `T_c` = 2 cycles per patch, so the
//! loader's FIFO, the cache's miss path and the memory port all see real latency; the bundles
//! have [`RAYS`] rays to keep the replay within CI's time (the ray count changes how long a run
//! is, not which paths of the PE it uses).
//!
//! Replay artefacts (the Verilog, the testbench, the vectors, the netlist) stay in
//! `target/tmp/replay/pe-*` for a closer look.

use shelling::cosim::{self, CosimConfig};
use shelling::grid::GridParams;
use shelling::rays::RaySet;
use shelling::run::Prepared;
use shelling::scene::{self, PAPER_WORLD};
use shelling::trace::{Method, ShellParams};
use shelling_hdl::pe::ProcessingElement;
use shelling_testbench::{pe, Design, Driver, Recording, Simulator};
use std::path::PathBuf;
use std::sync::OnceLock;

/// Rays per source.
const RAYS: usize = 64;
/// Host memory cycles per patch.
const TC: u32 = 2;
/// Cache lines when the cache is on.
const CACHE_LINES: u32 = 256;

/// The recorded vectors of all 36 sources, made once for the tests of this file.
fn vectors() -> &'static Recording {
    static VECTORS: OnceLock<Recording> = OnceLock::new();
    VECTORS.get_or_init(|| {
        let params = ShellParams::default();
        let mut drv = Driver::new(ProcessingElement::default()).expect("a PE");
        drv.record_ports().expect("recording from power-up");
        for (i, length) in [4.0, 8.0, 16.0, 32.0, 64.0, 128.0].into_iter().enumerate() {
            let seed = 70 + i as u64;
            let scene = scene::generate(1000, length, seed, PAPER_WORLD).expect("scene");
            let prepared = Prepared::new(scene, GridParams::default());
            let k = 211 * (i + 1) % 1000;
            let bundle = prepared.patch_bundle(k, RaySet::Angle, RAYS).expect("source");
            // A new scene in the host memory: the cached patches of the last one must go.
            pe::flush_cache(&mut drv).expect("flushes");
            for m in [Method::Conventional, Method::Stochastic, Method::Deterministic] {
                let scheduled = prepared.schedule(m, &bundle, &params).expect("fits");
                for cache in [None, Some(CACHE_LINES)] {
                    let config = CosimConfig { tc: TC, cache, ..CosimConfig::default() };
                    let from = drv.cycles();
                    let run = cosim::run_on(&mut drv, &scheduled, &config, |_, _| {}).unwrap_or_else(|e| {
                        panic!("length {length} seed {seed} source {k} {m} cache {cache:?}: {e}")
                    });
                    assert!(run.hardware.tests > 0, "{m}: no ray-patch test to replay");
                    println!(
                        "length {length} source {k} {m} cache {cache:?}: cycles {}..{}, {} loads, {} tests",
                        from,
                        drv.cycles(),
                        run.hardware.patch_loads,
                        run.hardware.tests
                    );
                }
            }
        }
        drv.take_recording().expect("recording was on")
    })
}

fn replay(design: Design, simulator: Simulator, name: &str) {
    let rec = vectors();
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join(name);
    // The exported structure only: a fresh PE exports the same Verilog as the recorded one.
    let drv = Driver::new(ProcessingElement::default()).expect("a PE");
    let report = rec
        .replay_netlist(drv.uut(), &dir, design, simulator)
        .unwrap_or_else(|e| panic!("{design} under {simulator}: {e}"));
    assert_eq!(report.cycles, rec.cycles());
    println!("{report}");
}

#[test]
fn whole_pe_verilog_under_icarus_reproduces_every_cycle_of_36_sources() {
    replay(Design::Rtl, Simulator::Icarus, "pe-icarus");
}

#[test]
fn whole_pe_verilog_under_verilator_reproduces_every_cycle_of_36_sources() {
    replay(Design::Rtl, Simulator::Verilator, "pe-verilator");
}

/// Rung 5. Both netlists on all the vectors: the word-level one under Icarus (four-state: an `x`
/// that synthesis lets through is a mismatch) and the gate-level one under Verilator (Icarus
/// takes about a second for ten cycles of the PE's 58,000 gates; the intersection unit's
/// gate-level netlist runs under Icarus in its own test).
#[test]
fn whole_pe_netlists_reproduce_every_cycle_of_36_sources() {
    replay(Design::Words, Simulator::Icarus, "pe-words");
    replay(Design::Gates, Simulator::Verilator, "pe-gates");
}
