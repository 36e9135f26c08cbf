//! Tier 2, rungs 4 and 5 for the whole processing element: full-scene co-simulations, recorded
//! port by port and cycle by cycle on one rust-hdl PE, replayed through the PE's exported
//! Verilog under Icarus Verilog and under Verilator (rung 4), and through Yosys' word-level and
//! gate-level netlists of it (rung 5). Every output of every cycle must agree bit for bit.
//!
//! The vectors: the paper's workload at every segment length (1000 patches, one source per
//! length), each source traced by all three techniques, each run once with the patch cache off
//! and once with it on, back to back on the same PE (36 sources, every one checked against the
//! bit-true model as it runs; `support::replay` has the host memory and bundle settings).

use crate::support::replay::{record, replay, Case, CACHE_LINES};
use shelling::trace::Method;
use shelling_testbench::{Design, Recording, Simulator};
use std::sync::OnceLock;

const METHODS: &[Method] = &[Method::Conventional, Method::Stochastic, Method::Deterministic];
const CACHES: &[Option<u32>] = &[None, Some(CACHE_LINES)];

/// The recorded vectors of all 36 sources, made once for the tests of this file.
fn vectors() -> &'static Recording {
    static VECTORS: OnceLock<Recording> = OnceLock::new();
    VECTORS.get_or_init(|| {
        let cases: Vec<Case> = [4.0, 8.0, 16.0, 32.0, 64.0, 128.0]
            .into_iter()
            .enumerate()
            .map(|(i, length)| Case {
                length,
                seed: 70 + i as u64,
                source: 211 * (i + 1) % 1000,
                methods: METHODS,
                caches: CACHES,
            })
            .collect();
        record(&cases)
    })
}

#[test]
fn whole_pe_verilog_under_icarus_reproduces_every_cycle_of_36_sources() {
    replay(vectors(), Design::Rtl, Simulator::Icarus, "pe-icarus");
}

#[test]
fn whole_pe_verilog_under_verilator_reproduces_every_cycle_of_36_sources() {
    replay(vectors(), Design::Rtl, Simulator::Verilator, "pe-verilator");
}

/// Rung 5. Both netlists on all the vectors: the word-level one under Icarus (four-state: an `x`
/// that synthesis lets through is a mismatch) and the gate-level one under Verilator (Icarus
/// takes about a second for ten cycles of the PE's 58,000 gates; the intersection unit's
/// gate-level netlist runs under Icarus in tier 1).
#[test]
fn whole_pe_netlists_reproduce_every_cycle_of_36_sources() {
    replay(vectors(), Design::Words, Simulator::Icarus, "pe-words");
    replay(vectors(), Design::Gates, Simulator::Verilator, "pe-gates");
}
