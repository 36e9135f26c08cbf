//! The 18×18 signed multiplier [`Mul18`] and the ECP5 `MULT18X18D` instantiation
//! ([`mult18x18d`]) that it and the intersection unit's `RayProductsPipe` use when the Verilog is
//! read with `SHELLING_ECP5` defined (as the FPGA flow and the ECP5 synthesis tests do).
//!
//! Latency 2 clocks (input and output registers), one product per clock. The product is
//! arithmetically shifted right by [`PRODUCT_SHIFT`] into 32 bits: the bit-true
//! [`crate::formats::mul`].

use super::clocked;
use crate::formats::{from_bits, PRODUCT_SHIFT};
use rust_hdl::prelude::*;

/// 18×18 signed multiplier, registered inputs and output: `p = (a·b) >> 4`, two clocks after
/// `a` and `b` are presented. Operands are two's complement in `Bits<18>`; `p` is two's
/// complement in `Bits<32>`.
///
/// On ECP5 (Verilog define `SHELLING_ECP5`) the Verilog is one [`mult18x18d`] instance with its
/// input and output registers on (the same latency); without the define, plain registers and a
/// product.
#[derive(LogicBlock, Default)]
pub struct Mul18 {
    pub clock: Signal<In, Clock>,
    pub a: Signal<In, Bits<18>>,
    pub b: Signal<In, Bits<18>>,
    pub p: Signal<Out, Bits<32>>,
    _a: i64,
    _b: i64,
}

impl Logic for Mul18 {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            let prod = (self._a * self._b) >> PRODUCT_SHIFT;
            self.p.next = Bits::from(prod as u32 as u64);
            self._a = from_bits(self.a.val().to_u64(), 18);
            self._b = from_bits(self.b.val().to_u64(), 18);
        }
    }

    fn connect(&mut self) {
        self.p.connect();
    }

    fn hdl(&self) -> Verilog {
        let mut v = String::from("`ifdef SHELLING_ECP5\nwire [35:0] p_w;\n");
        v += &mult18x18d("dsp", "a", "b", "p_w");
        v += &format!(
            "always @(*) begin\n   p = p_w[{hi}:{lo}];\nend\n`else\n",
            hi = 31 + PRODUCT_SHIFT,
            lo = PRODUCT_SHIFT
        );
        v += &format!(
            "\
reg signed [17:0] a_r;
reg signed [17:0] b_r;
wire signed [35:0] prod;
initial begin
   a_r = 18'sd0;
   b_r = 18'sd0;
   p = 32'd0;
end
assign prod = a_r * b_r;
always @(posedge clock) begin
   a_r <= a;
   b_r <= b;
   p <= prod[{hi}:{lo}];
end
",
            hi = 31 + PRODUCT_SHIFT,
            lo = PRODUCT_SHIFT
        );
        v += "`endif\n";
        Verilog::Custom(v)
    }

    fn timing(&self) -> Vec<TimingInfo> {
        clocked("mul18", &["a", "b"], &["p"])
    }
}

/// An ECP5 `MULT18X18D` instance named `name`: signed 18-bit `a` × `b` into the 36-bit wire
/// `p`, with the block's own input and output registers (`REG_INPUTA_CLK`, `REG_INPUTB_CLK`,
/// `REG_OUTPUT_CLK` = `"CLK0"`, latency 2, as [`Mul18`]'s model) on `clock`. Yosys maps a
/// product written in Verilog to a `MULT18X18D` without them, leaving about 4 ns of multiplier
/// and 3 ns of routing between two fabric registers.
pub(crate) fn mult18x18d(name: &str, a: &str, b: &str, p: &str) -> String {
    let mut v = String::from(
        "MULT18X18D #(.REG_INPUTA_CLK(\"CLK0\"), .REG_INPUTB_CLK(\"CLK0\"), \
.REG_OUTPUT_CLK(\"CLK0\"), .GSR(\"DISABLED\"), .RESETMODE(\"SYNC\")) ",
    );
    v += &format!(
        "{name} (\n   .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0)"
    );
    for i in 0..18 {
        v += &format!(",\n   .A{i}({a}[{i}]), .B{i}({b}[{i}]), .C{i}(1'b0)");
    }
    for i in 0..36 {
        v += &format!(",\n   .P{i}({p}[{i}])");
    }
    v += "\n);\n";
    v
}
