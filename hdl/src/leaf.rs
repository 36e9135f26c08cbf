//! Leaf blocks written by hand in both languages: a Rust model for simulation and a Verilog body
//! for export. rust-hdl has no multiplier wider than 16×16 and its `RAM` reads unwritten words as
//! `X` in Verilog; these two leaves fill the gaps. Their Rust and Verilog halves are checked
//! against each other by the rung-4 replay of every block that uses them.
//!
//! * [`Mul18`]: an 18×18 signed multiplier with registered inputs and output (latency 2, one
//!   product per clock) that maps to one DSP block (ECP5 `MULT18X18D`, Xilinx `DSP48`). It
//!   outputs the product arithmetically shifted right by [`PRODUCT_SHIFT`] as 32 bits, the
//!   bit-true [`crate::formats::mul`].
//! * [`Bram`]: a simple dual-port RAM, `2^A` words of `D ≤ 32` bits, registered read
//!   (read-before-write on the same address), zero at power-up; infers block RAM.

use crate::formats::{from_bits, PRODUCT_SHIFT};
use rust_hdl::prelude::*;

/// 18×18 signed multiplier, registered inputs and output: `p = (a·b) >> 4`, two clocks after
/// `a` and `b` are presented. Operands are two's complement in `Bits<18>`; `p` is two's
/// complement in `Bits<32>`.
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
        Verilog::Custom(format!(
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
        ))
    }

    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "mul18".into(),
            clock: "clock".into(),
            inputs: vec!["a".into(), "b".into()],
            outputs: vec!["p".into()],
        }]
    }
}

/// Simple dual-port block RAM: `2^A` words of `D` bits (D ≤ 32), one write and one registered
/// read per clock, read-before-write, all words zero at power-up.
#[derive(LogicBlock)]
pub struct Bram<const D: usize, const A: usize> {
    pub clock: Signal<In, Clock>,
    pub read_address: Signal<In, Bits<A>>,
    pub read_data: Signal<Out, Bits<D>>,
    pub write_address: Signal<In, Bits<A>>,
    pub write_data: Signal<In, Bits<D>>,
    pub write_enable: Signal<In, bool>,
    _mem: Vec<u32>,
}

impl<const D: usize, const A: usize> Default for Bram<D, A> {
    fn default() -> Self {
        assert!(D <= 32, "Bram words are at most 32 bits");
        Bram {
            clock: Default::default(),
            read_address: Default::default(),
            read_data: Default::default(),
            write_address: Default::default(),
            write_data: Default::default(),
            write_enable: Default::default(),
            _mem: vec![0; 1 << A],
        }
    }
}

impl<const D: usize, const A: usize> Logic for Bram<D, A> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            self.read_data.next = Bits::from(self._mem[self.read_address.val().index()] as u64);
            if self.write_enable.val() {
                self._mem[self.write_address.val().index()] = self.write_data.val().to_u32();
            }
        }
    }

    fn connect(&mut self) {
        self.read_data.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "\
reg [{dm}:0] mem [0:{words}];
integer i;
initial begin
   for (i = 0; i <= {words}; i = i + 1) mem[i] = {d}'d0;
   read_data = {d}'d0;
end
always @(posedge clock) begin
   read_data <= mem[read_address];
   if (write_enable) begin
      mem[write_address] <= write_data;
   end
end
",
            dm = D - 1,
            d = D,
            words = (1usize << A) - 1
        ))
    }

    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "bram".into(),
            clock: "clock".into(),
            inputs: vec![
                "read_address".into(),
                "write_address".into(),
                "write_data".into(),
                "write_enable".into(),
            ],
            outputs: vec!["read_data".into()],
        }]
    }
}
