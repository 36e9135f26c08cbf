//! Leaf blocks written by hand in both languages: a Rust model for simulation and a Verilog body
//! for export. rust-hdl has no multiplier wider than 16×16 and its `RAM` reads unwritten words as
//! `X` in Verilog; these two leaves fill the gaps. Their Rust and Verilog halves are checked
//! against each other by the rung-4 replay of every block that uses them.
//!
//! * [`Mul18`]: an 18×18 signed multiplier with registered inputs and output (latency 2, one
//!   product per clock) that maps to one DSP block (ECP5 `MULT18X18D`, Xilinx `DSP48`). It
//!   outputs the product arithmetically shifted right by [`PRODUCT_SHIFT`] as 32 bits, the
//!   bit-true [`crate::formats::mul`]. On ECP5 (`SHELLING_ECP5` defined) a hand-instantiated
//!   `MULT18X18D` whose own input and output registers are the leaf's.
//! * [`RayProductsPipe`]: the intersection unit's six products of a ray direction with a
//!   patch's three vectors and their operand registers in one leaf (six DSP blocks; on ECP5 the
//!   `MULT18X18D`s' own input and output registers); a leaf so that a settle pass visits one
//!   block instead of twelve.
//! * [`KeyScalePipe`]: the intersection unit's distance-key stage, `q·2^-sh` saturated into
//!   `[1, 2³² − 1]` in four register stages, the bit-true
//!   [`crate::intersection::model::key`]. It is a leaf because it is a barrel shifter: rust-hdl
//!   0.46 simulates every `<<`, `>>` and `get_bits` of a `Bits` through a heap-allocated big
//!   integer, which made this one stage a third of the unit's simulation time.
//! * [`Bram`]: a simple dual-port RAM, `2^A` words of `D ≤ 32` bits, registered read
//!   (read-before-write on the same address), zero at power-up; infers block RAM (LUT RAM when
//!   small).
//! * [`PipeDivider`]: the screener's divider, two 17-bit quotients of one 32-bit divisor by
//!   restoring division, one compare-and-subtract stage per quotient bit (latency
//!   [`DIV_LATENCY`], one division pair per clock), the bit-true [`restoring_quotient`]. It is a
//!   leaf so that its 17 stages of registers and 32-bit subtractors cost the simulation one
//!   short Rust loop per clock instead of a hundred-odd more signals in every settle pass.
//! * [`BramOut`]: [`Bram`] with its read registered twice (two clocks from address to data); on
//!   ECP5 (`SHELLING_ECP5` defined) hand-instantiated `DP16KD`s with their output register on,
//!   0.96 ns from clock to data instead of 5.83.

use crate::formats::{from_bits, PRODUCT_SHIFT};
use crate::intersection::model::key;
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
        vec![TimingInfo {
            name: "mul18".into(),
            clock: "clock".into(),
            inputs: vec!["a".into(), "b".into()],
            outputs: vec!["p".into()],
        }]
    }
}

/// An ECP5 `MULT18X18D` instance named `name`: signed 18-bit `a` × `b` into the 36-bit wire
/// `p`, with the block's own input and output registers (`REG_INPUTA_CLK`, `REG_INPUTB_CLK`,
/// `REG_OUTPUT_CLK` = `"CLK0"`, latency 2, as [`Mul18`]'s model) on `clock`. Yosys maps a
/// product written in Verilog to a `MULT18X18D` without them, leaving about 4 ns of multiplier
/// and 3 ns of routing between two fabric registers.
fn mult18x18d(name: &str, a: &str, b: &str, p: &str) -> String {
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

/// The plain Verilog of [`RayProductsPipe`] (every simulator, the formal tasks, iCE40 and the
/// rung-5 netlists): operand registers, six signed products, registered outputs.
fn ray_products_verilog() -> String {
    let mut v = String::from(
        "\
reg signed [17:0] dx_r;
reg signed [17:0] dy_r;
",
    );
    let ops = ["ax", "ay", "bx", "by", "wx", "wy"];
    for o in ops {
        v += &format!("reg signed [17:0] {o}_1;\nreg signed [17:0] {o}_r;\n");
    }
    let products = [("dx", "ay"), ("dy", "ax"), ("dx", "by"), ("dy", "bx"), ("dx", "wx"), ("dy", "wy")];
    for (d, o) in products {
        v += &format!("wire signed [35:0] {d}_{o}_m = {d}_r * {o}_r;\n");
    }
    v += "initial begin\n   dx_r = 18'sd0;\n   dy_r = 18'sd0;\n";
    for o in ops {
        v += &format!("   {o}_1 = 18'sd0;\n   {o}_r = 18'sd0;\n");
    }
    for (d, o) in products {
        v += &format!("   {d}_{o} = 32'd0;\n");
    }
    v += "end\nalways @(posedge clock) begin\n   dx_r <= dx;\n   dy_r <= dy;\n";
    for o in ops {
        v += &format!("   {o}_1 <= {o};\n   {o}_r <= {o}_1;\n");
    }
    for (d, o) in products {
        v += &format!("   {d}_{o} <= {d}_{o}_m[{}:{}];\n", 31 + PRODUCT_SHIFT, PRODUCT_SHIFT);
    }
    v += "end\n";
    v
}

/// Quotient bits of [`PipeDivider`], one pipeline stage each.
pub const DIV_STEPS: usize = 17;
/// Clocks from presenting a division to [`PipeDivider`] to its quotients on the outputs: the
/// input registers and one register per quotient bit.
pub const DIV_LATENCY: u64 = DIV_STEPS as u64 + 1;

/// The quotient [`PipeDivider`] computes: restoring division of the dividend `r·2^16 + f·2^13`
/// (`f` three bits) by `k`, 17 quotient bits, every step on 32-bit registers exactly as the
/// Verilog does. Step 0 compares `r` itself with `k`; each further step shifts the partial
/// remainder left by one, brings in the next dividend bit (those of `f`, then zeros) and
/// subtracts `k` when the result is not below it.
///
/// When `0 < k < 2^31` and `r < 2k`, the partial remainders stay below `2k` and the result is
/// exactly `floor((r·2^16 + f·2^13) / k)`, below `2^17`. Other inputs give the same
/// (meaningless) bits in the Rust model and the Verilog.
#[inline]
pub fn restoring_quotient(r: u32, f: u32, k: u32) -> u32 {
    let (mut rem, mut fr, mut q) = (r, f & 7, 0u32);
    for step in 0..DIV_STEPS {
        let ge;
        (rem, fr, ge) = div_step(step == 0, rem, fr, k);
        q = (q << 1) | ge as u32;
    }
    q & ((1 << DIV_STEPS) - 1)
}

/// One step of [`restoring_quotient`] on a partial remainder `r` and the dividend bits still to
/// come `f` (three bits, MSB first): the new remainder, the bits left, the quotient bit.
#[inline]
fn div_step(first: bool, r: u32, f: u32, k: u32) -> (u32, u32, bool) {
    let (t, f) = if first { (r, f) } else { ((r << 1) | (f >> 2), (f << 1) & 7) };
    let ge = t >= k;
    (if ge { t.wrapping_sub(k) } else { t }, f, ge)
}

/// The registers of one stage of [`PipeDivider`].
#[derive(Clone, Copy, Debug, Default)]
struct DivStage {
    k: u32,
    r: [u32; 2],
    f: [u32; 2],
    q: [u32; 2],
    tag: u32,
}

/// Two restoring dividers sharing a divisor, pipelined: one compare-and-subtract stage per
/// quotient bit, so a new pair of divisions starts every clock. `qx`, `qy` are
/// [`restoring_quotient`]`(rx, fx, k)` and `(ry, fy, k)` of the inputs presented
/// [`DIV_LATENCY`] clocks earlier, and `tag_out` is the `tag` presented with them (a side band
/// the divider carries unchanged: valid bit, signs). All registers power up as zero, so the
/// first [`DIV_LATENCY`] outputs carry a zero tag and meaningless quotients. The Rust model
/// steps the same registers as the Verilog, stage by stage.
#[derive(LogicBlock)]
pub struct PipeDivider {
    pub clock: Signal<In, Clock>,
    pub rx: Signal<In, Bits<32>>,
    pub ry: Signal<In, Bits<32>>,
    pub fx: Signal<In, Bits<3>>,
    pub fy: Signal<In, Bits<3>>,
    pub k: Signal<In, Bits<32>>,
    pub tag: Signal<In, Bits<3>>,
    pub qx: Signal<Out, Bits<17>>,
    pub qy: Signal<Out, Bits<17>>,
    pub tag_out: Signal<Out, Bits<3>>,
    /// Stage 0 (the input registers) to stage 17, as in the Verilog, from power-up on.
    _stages: [DivStage; DIV_STEPS + 1],
}

impl Default for PipeDivider {
    fn default() -> Self {
        PipeDivider {
            clock: Default::default(),
            rx: Default::default(),
            ry: Default::default(),
            fx: Default::default(),
            fy: Default::default(),
            k: Default::default(),
            tag: Default::default(),
            qx: Default::default(),
            qy: Default::default(),
            tag_out: Default::default(),
            _stages: [DivStage::default(); DIV_STEPS + 1],
        }
    }
}

impl Logic for PipeDivider {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            // Every stage register at once: stage s from stage s − 1, then the inputs. The
            // registers power up as zero, as in the Verilog (so the first 18 outputs are the
            // same meaningless bits in both).
            for s in (1..=DIV_STEPS).rev() {
                let prev = self._stages[s - 1];
                let mut next = prev;
                for c in 0..2 {
                    let (r, f, ge) = div_step(s == 1, prev.r[c], prev.f[c], prev.k);
                    next.r[c] = r;
                    next.f[c] = f;
                    next.q[c] = ((prev.q[c] << 1) | ge as u32) & ((1 << DIV_STEPS) - 1);
                }
                self._stages[s] = next;
            }
            self._stages[0] = DivStage {
                k: self.k.val().to_u32(),
                r: [self.rx.val().to_u32(), self.ry.val().to_u32()],
                f: [self.fx.val().to_u32(), self.fy.val().to_u32()],
                q: [0, 0],
                tag: self.tag.val().to_u32(),
            };
            let last = &self._stages[DIV_STEPS];
            self.qx.next = Bits::from(last.q[0] as u64);
            self.qy.next = Bits::from(last.q[1] as u64);
            self.tag_out.next = Bits::from(last.tag as u64);
        }
    }

    fn connect(&mut self) {
        self.qx.connect();
        self.qy.connect();
        self.tag_out.connect();
    }

    fn hdl(&self) -> Verilog {
        // Stage 0 is the input registers; stage s (1..=17) holds the divisor, the two partial
        // remainders, the dividend bits still to come (MSB first), the quotient bits so far and
        // the tag after step s − 1. Each step is one 33-bit subtraction (its borrow is the
        // comparison) and a multiplexer.
        Verilog::Custom(format!(
            "\
localparam N = {n};
reg [32*(N+1)-1:0] kp;
reg [32*(N+1)-1:0] rxp;
reg [32*(N+1)-1:0] ryp;
reg [3*(N+1)-1:0] fxp;
reg [3*(N+1)-1:0] fyp;
reg [17*(N+1)-1:0] qxp;
reg [17*(N+1)-1:0] qyp;
reg [3*(N+1)-1:0] tgp;
initial begin
   kp = 0;
   rxp = 0;
   ryp = 0;
   fxp = 0;
   fyp = 0;
   qxp = 0;
   qyp = 0;
   tgp = 0;
end
always @(posedge clock) begin
   kp[31:0] <= k;
   rxp[31:0] <= rx;
   ryp[31:0] <= ry;
   fxp[2:0] <= fx;
   fyp[2:0] <= fy;
   qxp[16:0] <= 17'd0;
   qyp[16:0] <= 17'd0;
   tgp[2:0] <= tag;
end
genvar s;
generate
   for (s = 1; s <= N; s = s + 1) begin : step
      wire [31:0] dk = kp[32*(s-1) +: 32];
      wire [31:0] ax = rxp[32*(s-1) +: 32];
      wire [31:0] ay = ryp[32*(s-1) +: 32];
      wire [2:0] bx = fxp[3*(s-1) +: 3];
      wire [2:0] by = fyp[3*(s-1) +: 3];
      wire [31:0] tx = (s == 1) ? ax : {{ax[30:0], bx[2]}};
      wire [31:0] ty = (s == 1) ? ay : {{ay[30:0], by[2]}};
      wire [32:0] dx = {{1'b0, tx}} - {{1'b0, dk}};
      wire [32:0] dy = {{1'b0, ty}} - {{1'b0, dk}};
      always @(posedge clock) begin
         kp[32*s +: 32] <= dk;
         rxp[32*s +: 32] <= dx[32] ? tx : dx[31:0];
         ryp[32*s +: 32] <= dy[32] ? ty : dy[31:0];
         fxp[3*s +: 3] <= (s == 1) ? bx : {{bx[1:0], 1'b0}};
         fyp[3*s +: 3] <= (s == 1) ? by : {{by[1:0], 1'b0}};
         qxp[17*s +: 17] <= {{qxp[17*(s-1) +: 16], ~dx[32]}};
         qyp[17*s +: 17] <= {{qyp[17*(s-1) +: 16], ~dy[32]}};
         tgp[3*s +: 3] <= tgp[3*(s-1) +: 3];
      end
   end
endgenerate
always @(*) begin
   qx = qxp[17*N +: 17];
   qy = qyp[17*N +: 17];
   tag_out = tgp[3*N +: 3];
end
",
            n = DIV_STEPS
        ))
    }

    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "pipe_divider".into(),
            clock: "clock".into(),
            inputs: vec!["rx".into(), "ry".into(), "fx".into(), "fy".into(), "k".into(), "tag".into()],
            outputs: vec!["qx".into(), "qy".into(), "tag_out".into()],
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

    /// Under its preconditions (`0 < k < 2^31`, `r < 2k`) the divider's quotient is the exact
    /// floor of the dividend over `k`: on edge cases and on seeded random inputs.
    #[test]
    fn restoring_quotient_is_exact_division_under_its_preconditions() {
        let exact = |r: u32, f: u32, k: u32| (((r as u64) << 16) + ((f as u64) << 13)) / k as u64;
        let mut cases = vec![];
        for k in [1u32, 2, 3, 7, 1 << 16, (1 << 31) - 1, 0x4000_0001, 12345] {
            for r in [0u32, 1, k - 1, k, 2 * k - 1] {
                for f in 0..8 {
                    cases.push((r, f, k));
                }
            }
        }
        let mut x = 0x2545_F491_4F6C_DD1Du64;
        for _ in 0..200_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let k = ((x as u32) >> (x >> 59)).clamp(1, (1 << 31) - 1);
            let r = ((x >> 32) as u32) % (2 * k);
            cases.push((r, (x >> 40) as u32 & 7, k));
        }
        for (r, f, k) in cases {
            let q = super::restoring_quotient(r, f, k);
            assert_eq!(q as u64, exact(r, f, k), "r {r} f {f} k {k}");
            assert!(q < 1 << 17);
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

/// Simple dual-port block RAM with a two-clock registered read: `2^A` words of `D ≤ 32` bits,
/// one write and one read per clock, all words and both read registers zero at power-up. The
/// read address presented in one clock (sampled at its rising edge `t`) gives its word on
/// `read_data` after edge `t + 1`; a write presented in the same clock as that read and to the
/// same address is *not* seen by it (it is seen by reads sampled at later edges).
///
/// On ECP5 (Verilog define `SHELLING_ECP5`, set by the FPGA flow) its Verilog body instantiates
/// `DP16KD` tiles by hand, port A writing and port B reading with its output register
/// (`REGMODE_B = "OUTREG"`): about 1 ns clock-to-out instead of the 5.8 ns of the read Yosys'
/// memory mapping gives (always `NOREG`). Tile widths: 18 bits for `A ≤ 10`, 9 for `A = 11`, 4
/// for `A = 12`. Without the define (simulators, iCE40, the gate-level netlists of rung 5) the
/// body is the behavioural two-register read that the Rust `update` models bit for bit.
///
/// **A read and a write of the same address in the same clock**: the block RAM's cross-port
/// result is undefined, so the model and the behavioural Verilog both return a poison word, the
/// bitwise NOT of the word before the write: a design relying on that read fails its tests. A
/// user must forward over the write instead.
#[derive(LogicBlock)]
pub struct BramOut<const D: usize, const A: usize> {
    pub clock: Signal<In, Clock>,
    pub read_address: Signal<In, Bits<A>>,
    pub read_data: Signal<Out, Bits<D>>,
    pub write_address: Signal<In, Bits<A>>,
    pub write_data: Signal<In, Bits<D>>,
    pub write_enable: Signal<In, bool>,
    _mem: Vec<u32>,
    /// The first read register (the block RAM's latch stage).
    _r1: u32,
}

impl<const D: usize, const A: usize> Default for BramOut<D, A> {
    fn default() -> Self {
        assert!(D <= 32, "BramOut words are at most 32 bits");
        assert!(A <= 12, "BramOut has at most 4096 words");
        BramOut {
            clock: Default::default(),
            read_address: Default::default(),
            read_data: Default::default(),
            write_address: Default::default(),
            write_data: Default::default(),
            write_enable: Default::default(),
            _mem: vec![0; 1 << A],
            _r1: 0,
        }
    }
}

/// The DP16KD data width per tile of a `BramOut` with `a` address bits.
pub fn bram_out_tile_width(a: usize) -> usize {
    match a {
        0..=10 => 18,
        11 => 9,
        _ => 4,
    }
}

impl<const D: usize, const A: usize> BramOut<D, A> {
    /// The word the read of `read` returns when `write` (address, enabled) is presented in the
    /// same clock: the memory's word, or its bitwise NOT on a same-address collision.
    fn read_word(&self, read: usize, write: Option<usize>) -> u32 {
        let mask = if D == 32 { u32::MAX } else { (1u32 << D) - 1 };
        let w = self._mem[read];
        if write == Some(read) {
            !w & mask
        } else {
            w
        }
    }

    fn ecp5_body() -> String {
        let w = bram_out_tile_width(A);
        let tiles = D.div_ceil(w);
        // Address pins: the address in the top bits (13 down), the rest zero, except the two
        // byte enables of an 18-bit write port.
        let lsb = match w {
            18 => 4,
            9 => 3,
            _ => 2,
        };
        let abits = 14 - lsb; // address bits the tile uses
        let mut v = String::new();
        v += &format!("wire [{}:0] bo_rd;\n", tiles * w - 1);
        let pad = tiles * w - D;
        if pad == 0 {
            v += &format!("wire [{}:0] bo_wd = write_data;\n", tiles * w - 1);
        } else {
            v += &format!("wire [{}:0] bo_wd = {{{pad}'d0, write_data}};\n", tiles * w - 1);
        }
        v += &format!("wire [{}:0] bo_ra = read_address;\n", abits - 1);
        v += &format!("wire [{}:0] bo_wa = write_address;\n", abits - 1);
        for t in 0..tiles {
            v += &format!(
                "DP16KD #(.DATA_WIDTH_A({w}), .DATA_WIDTH_B({w}), .REGMODE_A(\"NOREG\"), \
.REGMODE_B(\"OUTREG\"), .RESETMODE(\"SYNC\"), .ASYNC_RESET_RELEASE(\"SYNC\"), \
.CSDECODE_A(\"0b000\"), .CSDECODE_B(\"0b000\"), .WRITEMODE_A(\"NORMAL\"), \
.WRITEMODE_B(\"NORMAL\"), .GSR(\"DISABLED\")) bo_tile{t} (\n"
            );
            v += "   .CLKA(clock), .WEA(write_enable), .CEA(1'b1), .OCEA(1'b1), .RSTA(1'b0),\n";
            v += "   .CSA0(1'b0), .CSA1(1'b0), .CSA2(1'b0),\n";
            v += "   .CLKB(clock), .WEB(1'b0), .CEB(1'b1), .OCEB(1'b1), .RSTB(1'b0),\n";
            v += "   .CSB0(1'b0), .CSB1(1'b0), .CSB2(1'b0)";
            for (port, addr) in [("A", "bo_wa"), ("B", "bo_ra")] {
                for pin in 0..14 {
                    let s = if pin >= lsb {
                        format!("{addr}[{}]", pin - lsb)
                    } else if w == 18 && pin < 2 && port == "A" {
                        "1'b1".to_string()
                    } else {
                        "1'b0".to_string()
                    };
                    v += &format!(",\n   .AD{port}{pin}({s})");
                }
            }
            for bit in 0..w {
                v += &format!(",\n   .DIA{bit}(bo_wd[{}]), .DOB{bit}(bo_rd[{}])", t * w + bit, t * w + bit);
            }
            for bit in w..18 {
                v += &format!(",\n   .DIA{bit}(1'b0)");
            }
            v += ",\n   .DIB0(1'b0), .DIB1(1'b0), .DIB2(1'b0), .DIB3(1'b0), .DIB4(1'b0), .DIB5(1'b0), \
.DIB6(1'b0), .DIB7(1'b0), .DIB8(1'b0), .DIB9(1'b0), .DIB10(1'b0), .DIB11(1'b0), .DIB12(1'b0), \
.DIB13(1'b0), .DIB14(1'b0), .DIB15(1'b0), .DIB16(1'b0), .DIB17(1'b0)\n);\n";
        }
        v += &format!("always @(*) read_data = bo_rd[{}:0];\n", D - 1);
        v
    }
}

impl<const D: usize, const A: usize> Logic for BramOut<D, A> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            self.read_data.next = Bits::from(self._r1 as u64);
            let write = self.write_enable.val().then(|| self.write_address.val().index());
            self._r1 = self.read_word(self.read_address.val().index(), write);
            if let Some(a) = write {
                self._mem[a] = self.write_data.val().to_u32();
            }
        }
    }

    fn connect(&mut self) {
        self.read_data.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "\
`ifdef SHELLING_ECP5
{ecp5}`else
reg [{dm}:0] mem [0:{words}];
reg [{dm}:0] r1;
reg collided;
integer i;
initial begin
   for (i = 0; i <= {words}; i = i + 1) mem[i] = {d}'d0;
   r1 = {d}'d0;
   collided = 1'b0;
   read_data = {d}'d0;
end
always @(posedge clock) begin
   // A plain registered read (read before write), so that synthesis infers block RAM; a read
   // and a write of the same address in one clock are poisoned after the read register (see
   // the Rust docs).
   r1 <= mem[read_address];
   collided <= write_enable && write_address == read_address;
   read_data <= collided ? ~r1 : r1;
   if (write_enable) begin
      mem[write_address] <= write_data;
   end
end
`endif
",
            ecp5 = Self::ecp5_body(),
            dm = D - 1,
            d = D,
            words = (1usize << A) - 1
        ))
    }

    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "bram_out".into(),
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
mod bram_out_tests {
    use super::BramOut;
    use rust_hdl::core::prelude::simulate;
    use rust_hdl::prelude::*;

    /// One clock of a `BramOut`: inputs set while the clock is low, then the rising edge.
    fn clock<const D: usize, const A: usize>(m: &mut BramOut<D, A>, ra: u64, w: Option<(u64, u64)>) {
        m.clock.next = false.into();
        m.read_address.next = ra.into();
        m.write_enable.next = w.is_some();
        if let Some((a, d)) = w {
            m.write_address.next = a.into();
            m.write_data.next = d.into();
        }
        assert!(simulate(m, 100));
        m.clock.next = true.into();
        assert!(simulate(m, 100));
    }

    fn out<const D: usize, const A: usize>(m: &BramOut<D, A>) -> u64 {
        m.read_data.val().to_u64()
    }

    /// Two-clock read, zero at power-up, a write seen by reads sampled at later edges only, and
    /// the poison of a same-address read and write.
    #[test]
    fn two_clock_read_and_poison() {
        let mut m = BramOut::<17, 10>::default();
        m.connect_all();
        clock(&mut m, 5, Some((5, 0x1_2345))); // edge 0: read 5 (collision: poison of 0), write 5
        assert_eq!(out(&m), 0, "power-up");
        clock(&mut m, 5, None); // edge 1: read 5 again
        assert_eq!(out(&m), 0x1_ffff, "edge 0's read, one clock later: the poison (NOT of 0)");
        clock(&mut m, 6, Some((7, 3))); // edge 2
        assert_eq!(out(&m), 0x1_2345, "edge 1's read sees edge 0's write");
        clock(&mut m, 7, None); // edge 3
        assert_eq!(out(&m), 0, "ray 6 was never written");
        clock(&mut m, 7, Some((7, 9))); // edge 4: collision, old word 3
        assert_eq!(out(&m), 3);
        clock(&mut m, 0, None);
        assert_eq!(out(&m), !3u64 & 0x1_ffff, "poison: NOT of the old word");
        clock(&mut m, 0, None);
        assert_eq!(out(&m), 0);
    }

    /// The Verilog body has both branches, and the ECP5 one has one `DP16KD` per 18 bits with
    /// the output register.
    #[test]
    fn verilog_has_the_ecp5_tiles() {
        let m = BramOut::<32, 10>::default();
        let Verilog::Custom(v) = m.hdl() else { panic!("custom Verilog") };
        assert!(v.contains("`ifdef SHELLING_ECP5") && v.contains("`else") && v.contains("`endif"));
        assert_eq!(v.matches("DP16KD #(").count(), 2);
        assert_eq!(v.matches("REGMODE_B(\"OUTREG\")").count(), 2);
        assert_eq!(super::bram_out_tile_width(11), 9);
        let m = BramOut::<9, 11>::default();
        let Verilog::Custom(v) = m.hdl() else { panic!("custom Verilog") };
        assert_eq!(v.matches("DP16KD #(").count(), 1);
    }
}

/// Clocks from presenting `q` and `sh` to [`KeyScalePipe`] to their key on `key`.
pub const KEY_PIPE_LATENCY: u64 = 4;

/// The intersection unit's distance-key stage, three register stages after its input
/// registers, for a faster clock: the distance key of [`crate::intersection::model::key`] of the `q` and `sh` presented
/// [`KEY_PIPE_LATENCY`] clocks earlier, one key per clock. Stage 1 selects the left shift (for
/// `sh < 0`, saturating), the value 1 (for `q < 0`) or `q` shifted right by the multiple of 8 in
/// `sh`; stage 2 shifts right by the rest (0 to 7); stage 3 raises a zero to 1.
#[derive(LogicBlock, Default)]
pub struct KeyScalePipe {
    pub clock: Signal<In, Clock>,
    pub q: Signal<In, Bits<32>>,
    pub sh: Signal<In, Bits<6>>,
    pub key: Signal<Out, Bits<32>>,
    /// The inputs of the last three clocks, newest first.
    _pipe: [(u32, i8); 3],
}

impl Logic for KeyScalePipe {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            let (q, sh) = self._pipe[2];
            self.key.next = Bits::from(key(q as i32, sh) as u64);
            self._pipe = [
                (self.q.val().to_u32(), from_bits(self.sh.val().to_u64(), 6) as i8),
                self._pipe[0],
                self._pipe[1],
            ];
        }
    }

    fn connect(&mut self) {
        self.key.connect();
    }

    fn hdl(&self) -> Verilog {
        // sh < -3 is clamped to -3 (SH_MIN), as in the model. A zero q gives zero in stages 1
        // and 2 (any shift) and 1 in stage 3, as a negative one does.
        Verilog::Custom(
            "\
reg [31:0] q_r;
reg [5:0] sh_r;
reg [31:0] c1;
reg [2:0] f1;
reg [31:0] r2;
reg [31:0] left;
reg [31:0] coarse;
initial begin
   q_r = 32'd0;
   sh_r = 6'd0;
   c1 = 32'd0;
   f1 = 3'd0;
   r2 = 32'd0;
   key = 32'd0;
end
always @(*) begin
   if (sh_r == 6'h3f) left = {q_r[30:0], 1'b0};
   else if (sh_r == 6'h3e) left = (q_r[31:30] == 2'd0) ? {q_r[29:0], 2'b0} : 32'hffffffff;
   else left = (q_r[31:29] == 3'd0) ? {q_r[28:0], 3'b0} : 32'hffffffff;
   case (sh_r[4:3])
      2'd0: coarse = q_r;
      2'd1: coarse = {8'd0, q_r[31:8]};
      2'd2: coarse = {16'd0, q_r[31:16]};
      default: coarse = {24'd0, q_r[31:24]};
   endcase
end
always @(posedge clock) begin
   q_r <= q;
   sh_r <= sh;
   if (q_r[31]) begin
      c1 <= 32'd1;
      f1 <= 3'd0;
   end else if (sh_r[5]) begin
      c1 <= left;
      f1 <= 3'd0;
   end else begin
      c1 <= coarse;
      f1 <= sh_r[2:0];
   end
   r2 <= c1 >> f1;
   key <= (r2 == 32'd0) ? 32'd1 : r2;
end
"
            .into(),
        )
    }

    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "key_scale_pipe".into(),
            clock: "clock".into(),
            inputs: vec!["q".into(), "sh".into()],
            outputs: vec!["key".into()],
        }]
    }
}

/// The intersection unit's six products of one ray direction `d` with a patch's three vectors
/// `a`, `b`, `w`: six [`Mul18`]s in one leaf, with the patch operands held one clock longer
/// than the direction. Outputs, each `(d·x) >> 4` as 32 bits ([`crate::formats::mul`]):
/// `dx_ay`, `dy_ax`, `dx_by`, `dy_bx`, `dx_wx`, `dy_wy`.
///
/// Timing: `ax` … `wy` are presented in one clock (stage 0), `dx`, `dy` in the next (stage 1);
/// their products appear two clocks after `dx`, `dy` (stage 3), one set per clock. The
/// operand registers of stage 1 and the multipliers' input and output registers are inside the
/// leaf: in simulation they are six integers instead of six `DFF`s and six `Mul18` blocks in
/// every settle pass. Maps to six DSP blocks, as six `Mul18`s do.
///
/// On ECP5 (Verilog define `SHELLING_ECP5`) the multipliers are six [`mult18x18d`] instances
/// with their own input and output registers; without the define the Verilog is plain
/// registers and products.
#[derive(LogicBlock, Default)]
pub struct RayProductsPipe {
    pub clock: Signal<In, Clock>,
    pub dx: Signal<In, Bits<18>>,
    pub dy: Signal<In, Bits<18>>,
    pub ax: Signal<In, Bits<18>>,
    pub ay: Signal<In, Bits<18>>,
    pub bx: Signal<In, Bits<18>>,
    pub by: Signal<In, Bits<18>>,
    pub wx: Signal<In, Bits<18>>,
    pub wy: Signal<In, Bits<18>>,
    pub dx_ay: Signal<Out, Bits<32>>,
    pub dy_ax: Signal<Out, Bits<32>>,
    pub dx_by: Signal<Out, Bits<32>>,
    pub dy_bx: Signal<Out, Bits<32>>,
    pub dx_wx: Signal<Out, Bits<32>>,
    pub dy_wy: Signal<Out, Bits<32>>,
    /// Stage-1 operand registers: ax, ay, bx, by, wx, wy.
    _ops: [i64; 6],
    /// Multiplier input registers: dx, dy, then the operands.
    _mul: [i64; 8],
}

impl Logic for RayProductsPipe {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            let [dx, dy, ax, ay, bx, by, wx, wy] = self._mul;
            let p = |x: i64, y: i64| Bits::<32>::from(((x * y) >> PRODUCT_SHIFT) as u32 as u64);
            self.dx_ay.next = p(dx, ay);
            self.dy_ax.next = p(dy, ax);
            self.dx_by.next = p(dx, by);
            self.dy_bx.next = p(dy, bx);
            self.dx_wx.next = p(dx, wx);
            self.dy_wy.next = p(dy, wy);
            let v = |b: Bits<18>| from_bits(b.to_u64(), 18);
            let o = self._ops;
            self._mul = [v(self.dx.val()), v(self.dy.val()), o[0], o[1], o[2], o[3], o[4], o[5]];
            self._ops = [
                v(self.ax.val()),
                v(self.ay.val()),
                v(self.bx.val()),
                v(self.by.val()),
                v(self.wx.val()),
                v(self.wy.val()),
            ];
        }
    }

    fn connect(&mut self) {
        self.dx_ay.connect();
        self.dy_ax.connect();
        self.dx_by.connect();
        self.dy_bx.connect();
        self.dx_wx.connect();
        self.dy_wy.connect();
    }

    fn hdl(&self) -> Verilog {
        let generic = ray_products_verilog();
        let ops = ["ax", "ay", "bx", "by", "wx", "wy"];
        let mut v = String::from("`ifdef SHELLING_ECP5\n");
        for o in ops {
            v += &format!("reg [17:0] {o}_1;\n");
        }
        v += "initial begin\n";
        for o in ops {
            v += &format!("   {o}_1 = 18'd0;\n");
        }
        v += "end\nalways @(posedge clock) begin\n";
        for o in ops {
            v += &format!("   {o}_1 <= {o};\n");
        }
        v += "end\n";
        let products = [("dx", "ay"), ("dy", "ax"), ("dx", "by"), ("dy", "bx"), ("dx", "wx"), ("dy", "wy")];
        for (d, o) in products {
            v += &format!("wire [35:0] {d}_{o}_p;\n");
            v += &mult18x18d(&format!("{d}_{o}_dsp"), d, &format!("{o}_1"), &format!("{d}_{o}_p"));
        }
        v += "always @(*) begin\n";
        for (d, o) in products {
            v += &format!("   {d}_{o} = {d}_{o}_p[{}:{}];\n", 31 + PRODUCT_SHIFT, PRODUCT_SHIFT);
        }
        v += "end\n`else\n";
        v += &generic;
        v += "`endif\n";
        Verilog::Custom(v)
    }

    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "ray_products_pipe".into(),
            clock: "clock".into(),
            inputs: ["dx", "dy", "ax", "ay", "bx", "by", "wx", "wy"].map(String::from).to_vec(),
            outputs: ["dx_ay", "dy_ax", "dx_by", "dy_bx", "dx_wx", "dy_wy"].map(String::from).to_vec(),
        }]
    }
}
