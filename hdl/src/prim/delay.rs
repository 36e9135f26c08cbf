//! [`Delay`]: a word carried unchanged through `D` register stages (a pipeline's stage-to-stage
//! carry of the fields a stage only passes on).
//!
//! # Ports
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | rising-edge clock |
//! | `d` | in | `W` | the word |
//! | `q` | out | `W` | after a clock edge, the `d` of `D - 1` edges before (`D = 1`: a register), zero until then |
//!
//! `T` is a `Bits<W>` or `bool` (`W` = 1). One word a clock, latency `D` (at least 1). Its Rust
//! half is a ring of `D - 1` words (one block in a settle pass instead of `D` `DFF`s); its Verilog `D` registers in a
//! chain, each set to zero at power-up. Checked against each other by the replays of the blocks
//! that use it and alone by `testbench/tests/screener.rs`.

use super::clocked;
use rust_hdl::prelude::*;

/// `d` delayed by `D` clocks (see the module's header): `T` a `Bits<W>` or `bool`.
#[derive(LogicBlock)]
pub struct Delay<T: Synth, const D: usize> {
    pub clock: Signal<In, Clock>,
    pub d: Signal<In, T>,
    pub q: Signal<Out, T>,
    /// The words taken at the last `D - 1` edges, the oldest at `_next`.
    _ring: Vec<T>,
    _next: usize,
}

impl<T: Synth, const D: usize> Default for Delay<T, D> {
    fn default() -> Self {
        assert!(D >= 1, "Delay<_, {D}>: D at least 1");
        Self {
            clock: Default::default(),
            d: Default::default(),
            q: Default::default(),
            _ring: vec![T::default(); D - 1],
            _next: 0,
        }
    }
}

impl<T: Synth, const D: usize> Logic for Delay<T, D> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            // As a chain of D registers: `q` takes the word taken D - 1 edges before.
            let d = self.d.val();
            if D == 1 {
                self.q.next = d;
            } else {
                self.q.next = self._ring[self._next];
                self._ring[self._next] = d;
                self._next = (self._next + 1) % (D - 1);
            }
        }
    }

    fn connect(&mut self) {
        self.q.connect();
    }

    fn hdl(&self) -> Verilog {
        let w = T::BITS;
        let range = if w == 1 { String::new() } else { format!("[{}:0] ", w - 1) };
        let mut v = String::new();
        for i in 1..D {
            v += &format!("reg {range}s{i};\n");
        }
        v += "initial begin\n";
        for i in 1..D {
            v += &format!("   s{i} = {w}'d0;\n");
        }
        v += &format!("   q = {w}'d0;\nend\nalways @(posedge clock) begin\n");
        let mut from = "d".to_string();
        for i in 1..D {
            v += &format!("   s{i} <= {from};\n");
            from = format!("s{i}");
        }
        v += &format!("   q <= {from};\nend\n");
        Verilog::Custom(v)
    }

    fn timing(&self) -> Vec<TimingInfo> {
        clocked("delay", &["d"], &["q"])
    }
}
