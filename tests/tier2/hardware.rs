//! The machine's exported Verilog synthesizes (tier 2: Yosys takes over a minute on it).

use crate::support::synth::{assert_no_latch, cells, synth_ecp5};

/// The machine of two PEs (`hdl/verilog/machine.v`): twice the PE's DSPs and block RAMs, its
/// FIFOs and the arbiter's queues in LUT RAM, no latch anywhere.
#[test]
fn the_machine_synthesizes_without_latches() {
    let stat = synth_ecp5("machine");
    assert_no_latch("machine", &stat);
    assert_eq!(cells(&stat, "MULT18X18D"), 32, "two PEs of 16 multipliers:\n{stat}");
    assert_eq!(cells(&stat, "DP16KD"), 34, "two PEs' memories in block RAM (17 each):\n{stat}");
    assert!(cells(&stat, "TRELLIS_DPR16X4") > 0, "{stat}");
    println!("{stat}");
}
