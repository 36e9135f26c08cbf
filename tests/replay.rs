//! Tier 1, rung 4 for the whole processing element: one scene of the paper's workload (length
//! 32), one source traced by conventional shelling with the patch cache on and by stochastic
//! and deterministic shelling with it off, recorded on one rust-hdl PE and replayed through the
//! PE's exported Verilog under Icarus Verilog and under Verilator. Every output of every cycle
//! must agree bit for bit. Tier 2 (`tests/tier2/replay.rs`) replays 36 sources and the PE's
//! netlists (rung 5).

use crate::support::replay::{record, replay, Case, CACHE_LINES};
use shelling::trace::Method;
use shelling_testbench::{Design, Recording, Simulator};
use std::sync::OnceLock;

fn vectors() -> &'static Recording {
    static VECTORS: OnceLock<Recording> = OnceLock::new();
    VECTORS.get_or_init(|| {
        record(&[
            Case {
                length: 32.0,
                seed: 73,
                source: 844,
                methods: &[Method::Conventional],
                caches: &[Some(CACHE_LINES)],
            },
            Case {
                length: 32.0,
                seed: 73,
                source: 844,
                methods: &[Method::Stochastic, Method::Deterministic],
                caches: &[None],
            },
        ])
    })
}

#[test]
fn whole_pe_verilog_under_icarus_reproduces_every_cycle_of_one_scene() {
    replay(vectors(), Design::Rtl, Simulator::Icarus, "pe-icarus-one");
}

#[test]
fn whole_pe_verilog_under_verilator_reproduces_every_cycle_of_one_scene() {
    replay(vectors(), Design::Rtl, Simulator::Verilator, "pe-verilator-one");
}
