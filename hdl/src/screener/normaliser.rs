//! The screener's normaliser: the leading zeros of a 32-bit word and the word shifted left by
//! them, in two register stages. The screener has two, one for `nmax` (stages 3–4) and one for
//! `2K` (stages 5–6); the exponent `sh` is the difference of their counts (stage 7).
//!
//! # Ports ([`Normaliser`])
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | rising-edge clock |
//! | `value` | in | 32 | the word, unsigned |
//! | `norm` | out | 32 | `value << clz` ([`NORMALISER_LATENCY`] clocks later; 0 for 0), a register |
//! | `clz` | out | 6 | the leading zeros of that `value` (31 for 0), a register |
//!
//! # Latency, throughput, structure
//!
//! One word a clock; `norm` and `clz` are those of the `value` presented two clocks before.
//! Five conditional shifts, cut for a 150 MHz ECP5 clock: stage 1 the shifts by 16 and 8 side by
//! side (the top half and two bytes tested at once, then one four-way choice: by 0, 8, 16 or 24),
//! registered; stage 2 the shifts by 4, 2 and 1, registered. A shift's count bit is OR-ed in
//! (the counts are disjoint bits).
//!
//! # Models
//!
//! The bit-true model is [`normalise`]; the Rust half of this leaf computes it (on integers, not
//! through rust-hdl's `Bits` shifts, which it simulates with big integers), the Verilog half by
//! the shifts above, and the screener's rung-4 and rung-5 replays check the two against each
//! other port by port.

use crate::prim::clocked;
use rust_hdl::prelude::*;

/// Clocks from presenting `value` to [`Normaliser`] to its `norm` and `clz`.
pub const NORMALISER_LATENCY: u64 = 2;

/// The bit-true model: `(value << clz, clz)` with `clz` the leading zeros of `value`; `(0, 31)`
/// for zero (every one of the five shifts taken).
pub fn normalise(value: u32) -> (u32, u32) {
    if value == 0 {
        (0, 31)
    } else {
        let clz = value.leading_zeros();
        (value << clz, clz)
    }
}

/// Leading zeros and normalised word in two register stages (see the module's header).
#[derive(LogicBlock, Default)]
pub struct Normaliser {
    pub clock: Signal<In, Clock>,
    pub value: Signal<In, Bits<32>>,
    pub norm: Signal<Out, Bits<32>>,
    pub clz: Signal<Out, Bits<6>>,
    /// The word presented a clock before (the Verilog's first stage registers hold it halfway
    /// normalised).
    _held: u32,
}

impl Logic for Normaliser {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            let (norm, clz) = normalise(self._held);
            self.norm.next = Bits::from(norm as u64);
            self.clz.next = Bits::from(clz as u64);
            self._held = self.value.val().to_u32();
        }
    }

    fn connect(&mut self) {
        self.norm.connect();
        self.clz.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(
            // Powered up as if a zero word had been presented (the first half's count for zero is
            // 24), as the Rust half's `_held` is.
            "\
reg [31:0] half;
reg [5:0] half_clz;
reg [31:0] first;
reg [5:0] first_clz;
wire [31:0] s4 = (half[31:28] == 4'd0) ? {half[27:0], 4'd0} : half;
wire [31:0] s2 = (s4[31:30] == 2'd0) ? {s4[29:0], 2'd0} : s4;
wire [31:0] s1 = s2[31] ? s2 : {s2[30:0], 1'b0};
wire [5:0] c421 = {3'd0, half[31:28] == 4'd0, s4[31:30] == 2'd0, !s2[31]};
initial begin
   half = 32'd0;
   half_clz = 6'd24;
   norm = 32'd0;
   clz = 6'd0;
end
always @(*) begin
   if (value[31:16] == 16'd0) begin
      if (value[15:8] == 8'd0) begin
         first = {value[7:0], 24'd0};
         first_clz = 6'd24;
      end else begin
         first = {value[15:0], 16'd0};
         first_clz = 6'd16;
      end
   end else begin
      if (value[31:24] == 8'd0) begin
         first = {value[23:0], 8'd0};
         first_clz = 6'd8;
      end else begin
         first = value;
         first_clz = 6'd0;
      end
   end
end
always @(posedge clock) begin
   half <= first;
   half_clz <= first_clz;
   norm <= s1;
   clz <= half_clz | c421;
end
"
            .into(),
        )
    }

    fn timing(&self) -> Vec<TimingInfo> {
        clocked("normaliser", &["value"], &["norm", "clz"])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The model is the five conditional shifts the Verilog makes (16 and 8, then 4, 2 and 1).
    #[test]
    fn the_model_is_the_five_shifts() {
        let shifts = |v: u32| {
            let (mut v, mut c) = (v, 0u32);
            for s in [16u32, 8, 4, 2, 1] {
                if v >> (32 - s) == 0 {
                    v <<= s;
                    c |= s;
                }
            }
            (v, c)
        };
        let mut x = 0x9e37_79b9u32;
        for i in 0..32 {
            for v in [0, 1 << i, (1u32 << i).wrapping_sub(1), x >> i] {
                assert_eq!(normalise(v), shifts(v), "{v:#x}");
            }
            x = x.rotate_left(5) ^ x.wrapping_mul(0x85eb_ca6b);
        }
    }
}
