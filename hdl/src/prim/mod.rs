//! Generic primitives, each written by hand in both languages: a Rust model on plain integers
//! for simulation and a Verilog body for export. rust-hdl 0.46 has no multiplier wider than
//! 16×16 and its `RAM` reads unwritten words as `X` in Verilog; these parts fill the gaps. Their
//! Rust and Verilog halves are checked against each other by the rung-4 replay of every block
//! that uses them, and alone by their own tests (`testbench/tests/`).
//!
//! * [`mul`]: [`Mul18`], an 18×18 signed multiplier with registered inputs and output (latency
//!   2, one product per clock) that maps to one DSP block (ECP5 `MULT18X18D`, Xilinx `DSP48`),
//!   and the ECP5 `MULT18X18D` instantiation it shares with the intersection unit's products.
//! * [`ram`]: [`Bram`] (a simple dual-port RAM, registered read), [`BramOut`] (its read
//!   registered twice; on ECP5 hand-instantiated `DP16KD`s with their output register on) and
//!   [`FifoRam`] (the storage of a first-word-fall-through FIFO: head and next read, a registered
//!   pop).
//! * [`fifo`]: [`FifoControl`], the pointers, word count and registered head-valid flag of a
//!   first-word-fall-through FIFO over [`FifoRam`] lanes (every FIFO of the processing element),
//!   and [`Fifo`], a FIFO of one lane.
//! * [`delay`]: [`Delay`], a word carried through `D` register stages (a pipeline's
//!   stage-to-stage carry).
//! * [`rr`]: [`RoundRobin`], a round-robin choice among `N` requesters, one grant per clock
//!   (the memory arbiter's).
//!
//! A part here knows nothing of the blocks that use it. The blocks' own hand-written stages live
//! beside them (`intersection::stages`, `screener::divider`).

pub mod delay;
pub mod fifo;
pub mod mul;
pub mod ram;
pub mod rr;

pub use delay::Delay;
pub use fifo::{Fifo, FifoControl};
pub use mul::Mul18;
pub use ram::{bram_out_tile_width, Bram, BramOut, FifoRam};
pub use rr::RoundRobin;

use rust_hdl::prelude::*;

/// The timing of a leaf clocked by `clock`: its name, its inputs, its outputs.
pub(crate) fn clocked(name: &str, inputs: &[&str], outputs: &[&str]) -> Vec<TimingInfo> {
    let strings = |l: &[&str]| l.iter().map(|s| s.to_string()).collect();
    vec![TimingInfo {
        name: name.into(),
        clock: "clock".into(),
        inputs: strings(inputs),
        outputs: strings(outputs),
    }]
}

#[cfg(test)]
mod tests {
    use rust_hdl::prelude::*;

    fn check<const N: usize>() {
        let mask = if N == 64 { u64::MAX } else { (1u64 << N) - 1 };
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        for _ in 0..200 {
            x = x.rotate_left(17) ^ x.wrapping_mul(0x2545_F491_4F6C_DD1D);
            let v = x & mask;
            let b: Bits<N> = Bits::from(v);
            for k in [0u64, 1, 2, 5, 16, (N as u64).saturating_sub(1), N as u64, 31, 32, 40] {
                let right = if k >= 64 { 0 } else { v >> k };
                let left = if k >= 64 { 0 } else { (v << k) & mask };
                assert_eq!((b >> k).to_u64(), right, "Bits<{N}> {v:#x} >> {k}");
                assert_eq!((b << k).to_u64(), left, "Bits<{N}> {v:#x} << {k}");
            }
            if N >= 8 {
                assert_eq!(b.get_bits::<5>(3).to_u64(), (v >> 3) & 31, "Bits<{N}> {v:#x} get_bits");
            }
        }
    }

    /// rust-hdl-core is vendored with native shifts for `Bits` of 32 bits or fewer
    /// (vendor/README.md): they must agree with integer shifts, as the upstream big-integer ones
    /// did, at every width this project uses (and a long one, which takes upstream's path).
    #[test]
    fn patched_shifts_agree_with_integer_shifts() {
        check::<1>();
        check::<5>();
        check::<6>();
        check::<10>();
        check::<16>();
        check::<17>();
        check::<18>();
        check::<31>();
        check::<32>();
        check::<40>();
    }
}
