//! Leaf blocks written by hand in both languages: a Rust model for simulation and a Verilog body
//! for export. rust-hdl has no multiplier wider than 16×16 and its `RAM` reads unwritten words as
//! `X` in Verilog; these two leaves fill the gaps. Their Rust and Verilog halves are checked
//! against each other by the rung-4 replay of every block that uses them.
//!
//! * [`Mul18`]: an 18×18 signed multiplier with registered inputs and output (latency 2, one
//!   product per clock) that maps to one DSP block (ECP5 `MULT18X18D`, Xilinx `DSP48`). It
//!   outputs the product arithmetically shifted right by [`PRODUCT_SHIFT`] as 32 bits, the
//!   bit-true [`crate::formats::mul`].
//! * [`KeyScale`]: the intersection unit's distance-key stage, `q·2^-sh` saturated into
//!   `[1, 2³² − 1]` between an input and an output register (latency 2), the bit-true
//!   [`crate::intersection::model::key`]. It is a leaf because it is a barrel shifter: rust-hdl
//!   0.46 simulates every `<<`, `>>` and `get_bits` of a `Bits` through a heap-allocated big
//!   integer, which made this one stage a third of the unit's simulation time.
//! * [`Bram`]: a simple dual-port RAM, `2^A` words of `D ≤ 32` bits, registered read
//!   (read-before-write on the same address), zero at power-up; infers block RAM.

use crate::formats::{from_bits, PRODUCT_SHIFT};
use crate::intersection::model::key;
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

/// The distance key `q·2^-sh` of [`crate::intersection::model::key`], registered in and out:
/// `key` is the key of the `q` (32 bits, two's complement) and `sh` (6 bits, two's complement)
/// presented two clocks earlier. One key per clock.
#[derive(LogicBlock, Default)]
pub struct KeyScale {
    pub clock: Signal<In, Clock>,
    pub q: Signal<In, Bits<32>>,
    pub sh: Signal<In, Bits<6>>,
    pub key: Signal<Out, Bits<32>>,
    _q: u32,
    _sh: i8,
}

impl Logic for KeyScale {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            self.key.next = Bits::from(key(self._q as i32, self._sh) as u64);
            self._q = self.q.val().to_u32();
            self._sh = from_bits(self.sh.val().to_u64(), 6) as i8;
        }
    }

    fn connect(&mut self) {
        self.key.connect();
    }

    fn hdl(&self) -> Verilog {
        // sh < -3 is clamped to -3 (SH_MIN), as in the model.
        Verilog::Custom(
            "\
reg [31:0] q_r;
reg [5:0] sh_r;
reg [31:0] k;
wire [31:0] right = q_r >> sh_r[4:0];
initial begin
   q_r = 32'd0;
   sh_r = 6'd0;
   key = 32'd0;
end
always @(*) begin
   if (q_r[31] || q_r == 32'd0) k = 32'd1;
   else if (!sh_r[5]) k = (right == 32'd0) ? 32'd1 : right;
   else if (sh_r == 6'h3f) k = {q_r[30:0], 1'b0};
   else if (sh_r == 6'h3e) k = (q_r[31:30] == 2'd0) ? {q_r[29:0], 2'b0} : 32'hffffffff;
   else k = (q_r[31:29] == 3'd0) ? {q_r[28:0], 3'b0} : 32'hffffffff;
end
always @(posedge clock) begin
   q_r <= q;
   sh_r <= sh;
   key <= k;
end
"
            .into(),
        )
    }

    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "key_scale".into(),
            clock: "clock".into(),
            inputs: vec!["q".into(), "sh".into()],
            outputs: vec!["key".into()],
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
