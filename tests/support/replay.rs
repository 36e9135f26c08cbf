//! Recording full-scene co-simulations on one rust-hdl PE and replaying them through the PE's
//! exported Verilog or a Yosys netlist of it: the part of rungs 4 and 5 that tier 1
//! (`tests/replay.rs`) and tier 2 (`tests/tier2/replay.rs`) share.
//!
//! The host memory answers in [`TC`] = 2 cycles per patch, so the loader's FIFO, the cache's miss
//! path and the memory port all see real latency; the bundles have [`RAYS`] rays to keep the
//! replays short (the ray count changes how long a run is, not which paths of the PE it uses).
//! Replay artefacts (the Verilog, the testbench, the vectors, the netlist) stay in
//! `target/tmp/replay/pe-*` for a closer look.

use shelling::cosim::{self, CosimConfig};
use shelling::grid::GridParams;
use shelling::rays::RaySet;
use shelling::run::GriddedScene;
use shelling::scene::{self, PAPER_WORLD};
use shelling::trace::{Method, ShellParams};
use shelling_testbench::pe::{self, rust_hdl_pe};
use shelling_testbench::{Design, Recording, Simulator};
use std::path::PathBuf;

/// Rays per source.
pub const RAYS: usize = 64;
/// Host memory cycles per patch.
pub const TC: u32 = 2;
/// Cache lines when the cache is on.
pub const CACHE_LINES: u32 = 256;

/// One scene of the paper's workload (1000 segments of one length, seeded) with one source
/// patch, traced by each of `methods`, each run with each of `caches` (`None`: the cache off).
pub struct Case {
    pub length: f64,
    pub seed: u64,
    pub source: usize,
    pub methods: &'static [Method],
    pub caches: &'static [Option<u32>],
}

/// Runs every case back to back on one PE, recording its ports from power-up, every run checked
/// against the bit-true model as it goes; the cache is flushed before each new scene.
pub fn record(cases: &[Case]) -> Recording {
    let params = ShellParams::default();
    let mut drv = rust_hdl_pe().expect("a PE");
    drv.record_ports().expect("recording from power-up");
    for c in cases {
        let scene = scene::generate(1000, c.length, c.seed, PAPER_WORLD).expect("scene");
        let prepared = GriddedScene::new(scene, GridParams::default());
        let bundle = prepared.patch_bundle(c.source, RaySet::Angle, RAYS).expect("source");
        // A new scene in the host memory: the cached patches of the last one must go.
        pe::flush_cache(&mut drv).expect("flushes");
        for &m in c.methods {
            let scheduled = prepared.schedule(m, &bundle, &params).expect("fits");
            for &cache in c.caches {
                let what =
                    format!("length {} seed {} source {} {m} cache {cache:?}", c.length, c.seed, c.source);
                let config = CosimConfig { tc: TC, cache, ..CosimConfig::default() };
                let from = drv.cycles();
                let run = cosim::run_on(&mut drv, &scheduled, &config, |_, _| {})
                    .unwrap_or_else(|e| panic!("{what}: {e}"));
                assert!(run.hardware.tests > 0, "{what}: no ray-patch test to replay");
                println!(
                    "{what}: cycles {from}..{}, {} loads, {} tests",
                    drv.cycles(),
                    run.hardware.patch_loads,
                    run.hardware.tests
                );
            }
        }
    }
    drv.take_recording().expect("recording was on")
}

/// Replays `rec` through `design` under `simulator` in `target/tmp/replay/<name>`: every output
/// of every cycle must agree bit for bit.
pub fn replay(rec: &Recording, design: Design, simulator: Simulator, name: &str) {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join(name);
    // The exported structure only: a fresh PE exports the same Verilog as the recorded one.
    let drv = rust_hdl_pe().expect("a PE");
    let report = rec
        .replay_netlist(drv.uut(), &dir, design, simulator)
        .unwrap_or_else(|e| panic!("{design} under {simulator}: {e}"));
    assert_eq!(report.cycles, rec.cycles());
    println!("{report}");
}
