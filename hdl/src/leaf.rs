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
//! * [`IssueSequencer`], [`HitPipe`], [`NearestMerge`]: the intersection unit's stages 0–1,
//!   2–8 (but for the products and the key) and 8–9 with the readout's clear: its sequencer,
//!   valid bits, tags, side values, comparisons and forwarding registers, some eighty
//!   registers that were `DFF`s and cost the simulation most of its time (2.7 times as long:
//!   README, "Speed"). Their outputs are registers or functions of registers only, so they add
//!   no update pass.

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
        clocked("mul18", &["a", "b"], &["p"])
    }
}

/// The timing of a leaf clocked by `clock`: its name, its inputs, its outputs.
fn clocked(name: &str, inputs: &[&str], outputs: &[&str]) -> Vec<TimingInfo> {
    let strings = |l: &[&str]| l.iter().map(|s| s.to_string()).collect();
    vec![TimingInfo {
        name: name.into(),
        clock: "clock".into(),
        inputs: strings(inputs),
        outputs: strings(outputs),
    }]
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
        clocked("pipe_divider", &["rx", "ry", "fx", "fy", "k", "tag"], &["qx", "qy", "tag_out"])
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
        clocked("bram", &["read_address", "write_address", "write_data", "write_enable"], &["read_data"])
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

/// The storage of a first-word-fall-through FIFO: `2^A` words of `D ≤ 32` bits (LUT RAM on an
/// FPGA), one write per clock and two registered reads, the head and the word after it, so that
/// no read address depends on this clock's pop.
///
/// Ports: `write_address`, `write_data`, `write_enable` (a write, seen by reads at later edges:
/// read before write); `head_address` (the FIFO's read pointer) and `next_address` (the read
/// pointer plus one), both sampled at every rising edge; `pop` (the head leaves in this clock);
/// out `read_data`, the word at the head after the edge: the `next_address` read when `pop` was
/// high at that edge, else the `head_address` read. So with the read pointer advanced on a pop,
/// `read_data` is always the word at the read pointer as of the previous clock's memory.
///
/// Latency one clock from address to `read_data`; one write and one pop per clock. `read_data`
/// is a function of registers only (two read registers and a registered `pop` before one
/// multiplexer): a consumer's `ready` that decides the pop reaches one flip-flop and the
/// read pointer, not the RAM's address pins (with a single read at `pop ? next : head` it ran
/// through the address multiplexer into every LUT RAM of the FIFO: 5.8 ns of routing in the
/// processing element). ECP5 synthesis duplicates the LUT RAM for the second read port. For
/// iCE40 (Verilog define `SHELLING_ICE40`, set by the FPGA flow) the body keeps a second copy of
/// the memory for that read, written alongside: with one memory and two reads Yosys' iCE40
/// mapping keeps 16-word lanes in flip-flops (the loader at 42 MHz instead of 65). All
/// words and registers are zero at power-up. The Rust `update` is the bit-true model.
#[derive(LogicBlock)]
pub struct FifoRam<const D: usize, const A: usize> {
    pub clock: Signal<In, Clock>,
    pub write_address: Signal<In, Bits<A>>,
    pub write_data: Signal<In, Bits<D>>,
    pub write_enable: Signal<In, bool>,
    pub head_address: Signal<In, Bits<A>>,
    pub next_address: Signal<In, Bits<A>>,
    pub pop: Signal<In, bool>,
    pub read_data: Signal<Out, Bits<D>>,
    _mem: Vec<u32>,
}

impl<const D: usize, const A: usize> Default for FifoRam<D, A> {
    fn default() -> Self {
        assert!(D <= 32, "FifoRam words are at most 32 bits");
        FifoRam {
            clock: Default::default(),
            write_address: Default::default(),
            write_data: Default::default(),
            write_enable: Default::default(),
            head_address: Default::default(),
            next_address: Default::default(),
            pop: Default::default(),
            read_data: Default::default(),
            _mem: vec![0; 1 << A],
        }
    }
}

impl<const D: usize, const A: usize> Logic for FifoRam<D, A> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            let read = if self.pop.val() { self.next_address.val() } else { self.head_address.val() };
            self.read_data.next = Bits::from(self._mem[read.index()] as u64);
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
reg [{dm}:0] head_r;
reg [{dm}:0] next_r;
reg popped;
integer i;
`ifdef SHELLING_ICE40
// A copy for the second read (the same writes): one read port per memory.
reg [{dm}:0] mem_n [0:{words}];
initial for (i = 0; i <= {words}; i = i + 1) mem_n[i] = {d}'d0;
always @(posedge clock) begin
   next_r <= mem_n[next_address];
   if (write_enable) begin
      mem_n[write_address] <= write_data;
   end
end
`else
always @(posedge clock) next_r <= mem[next_address];
`endif
initial begin
   for (i = 0; i <= {words}; i = i + 1) mem[i] = {d}'d0;
   head_r = {d}'d0;
   next_r = {d}'d0;
   popped = 1'b0;
end
always @(posedge clock) begin
   head_r <= mem[head_address];
   popped <= pop;
   if (write_enable) begin
      mem[write_address] <= write_data;
   end
end
always @(*) read_data = popped ? next_r : head_r;
",
            dm = D - 1,
            d = D,
            words = (1usize << A) - 1
        ))
    }

    fn timing(&self) -> Vec<TimingInfo> {
        clocked(
            "fifo_ram",
            &["write_address", "write_data", "write_enable", "head_address", "next_address", "pop"],
            &["read_data"],
        )
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
        clocked("bram_out", &["read_address", "write_address", "write_data", "write_enable"], &["read_data"])
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
        clocked("key_scale_pipe", &["q", "sh"], &["key"])
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
        clocked(
            "ray_products_pipe",
            &["dx", "dy", "ax", "ay", "bx", "by", "wx", "wy"],
            &["dx_ay", "dy_ax", "dx_by", "dy_bx", "dx_wx", "dy_wy"],
        )
    }
}

/// A `Bits<N>` from a plain integer (the low `N` bits).
#[inline(always)]
fn bits<const N: usize>(v: u32) -> Bits<N> {
    Bits::from(v as u64)
}

/// The registers of [`IssueSequencer`], as in its Verilog.
#[derive(Clone, Copy, Debug, Default)]
struct IssueRegs {
    remaining: u32,
    /// `remaining > 1`, kept in a register of its own.
    full: bool,
    cur: u32,
    /// The current patch: ax, ay, bx, by, wx, wy.
    p: [u32; 6],
    p_sh: u32,
    p_id: u32,
    p_retire: bool,
    v1: bool,
    tag1: u32,
    /// Stage 1's patch operands: ax, ay, bx, by, wx, wy.
    o: [u32; 6],
}

/// The intersection unit's stages 0 and 1 ([`crate::intersection`]): the sequencer that issues
/// one ray of the current patch per clock, the current patch's fields, and stage 1's registers.
///
/// Ports (formats as in the unit's patch port): in `patch_valid`, `patch_ax` … `patch_wy` (18
/// bits each, two's complement), `patch_sh` (6), `patch_id` (16), `patch_first` (10),
/// `patch_count` (11), `patch_retire`; out `full`, `busy`, `kill`, `cur` (10), `v1`,
/// `tag1` (32), `o_ax` … `o_wy` (18 each).
///
/// Registers: `remaining` (rays of the current patch still to issue), `full` (`remaining > 1`:
/// no patch can be taken), `cur` (the ray issued in this clock while `remaining ≠ 0`), the
/// current patch `p_*` and stage 1: `v1` (a ray of a test job was issued in the clock before),
/// `tag1` = `{ray (31…22), sh (21…16), id (15…0)}` and the patch operands `o_*` of that ray. A
/// patch is taken at the rising edge when `patch_valid && !full`; otherwise a ray issues when
/// `remaining ≠ 0` (`remaining` counts down, `cur` up, modulo 1024). `full` is updated beside
/// `remaining` from shallow tests (`patch_count > 1` on a take, `remaining > 2` on an issue),
/// so that the unit's `patch_ready`, its complement, is a register: in the processing element
/// it feeds the slice in front of the unit, whose pop decides the take.
///
/// Outputs, all functions of the registers only (so the leaf has no combinational path from an
/// input): `full` (the register), `busy` = a ray issues or `v1`, `kill` = a ray of a
/// retire job issues (its live bit is cleared), and the registers `cur`, `v1`, `tag1`, `o_*`.
/// Latency: `v1`, `tag1` and `o_*` describe the ray issued one clock earlier. All registers
/// are zero at power-up.
#[derive(LogicBlock, Default)]
pub struct IssueSequencer {
    pub clock: Signal<In, Clock>,
    pub patch_valid: Signal<In, bool>,
    pub patch_ax: Signal<In, Bits<18>>,
    pub patch_ay: Signal<In, Bits<18>>,
    pub patch_bx: Signal<In, Bits<18>>,
    pub patch_by: Signal<In, Bits<18>>,
    pub patch_wx: Signal<In, Bits<18>>,
    pub patch_wy: Signal<In, Bits<18>>,
    pub patch_sh: Signal<In, Bits<6>>,
    pub patch_id: Signal<In, Bits<16>>,
    pub patch_first: Signal<In, Bits<10>>,
    pub patch_count: Signal<In, Bits<11>>,
    pub patch_retire: Signal<In, bool>,
    pub full: Signal<Out, bool>,
    pub busy: Signal<Out, bool>,
    pub kill: Signal<Out, bool>,
    pub cur: Signal<Out, Bits<10>>,
    pub v1: Signal<Out, bool>,
    pub tag1: Signal<Out, Bits<32>>,
    pub o_ax: Signal<Out, Bits<18>>,
    pub o_ay: Signal<Out, Bits<18>>,
    pub o_bx: Signal<Out, Bits<18>>,
    pub o_by: Signal<Out, Bits<18>>,
    pub o_wx: Signal<Out, Bits<18>>,
    pub o_wy: Signal<Out, Bits<18>>,
    _r: IssueRegs,
}

impl Logic for IssueSequencer {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            let s = self._r;
            let issue = s.remaining != 0;
            let mut n = s;
            n.v1 = issue && !s.p_retire;
            n.tag1 = (s.cur << 22) | (s.p_sh << 16) | s.p_id;
            n.o = s.p;
            if self.patch_valid.val() && !s.full {
                n.remaining = self.patch_count.val().to_u32();
                n.full = n.remaining > 1;
                n.cur = self.patch_first.val().to_u32();
                n.p = [
                    self.patch_ax.val().to_u32(),
                    self.patch_ay.val().to_u32(),
                    self.patch_bx.val().to_u32(),
                    self.patch_by.val().to_u32(),
                    self.patch_wx.val().to_u32(),
                    self.patch_wy.val().to_u32(),
                ];
                n.p_sh = self.patch_sh.val().to_u32();
                n.p_id = self.patch_id.val().to_u32();
                n.p_retire = self.patch_retire.val();
            } else if issue {
                n.remaining = s.remaining - 1;
                n.full = s.remaining > 2;
                n.cur = (s.cur + 1) & 0x3ff;
            }
            debug_assert_eq!(n.full, n.remaining > 1);
            self._r = n;
            let issue = n.remaining != 0;
            self.full.next = n.full;
            self.busy.next = issue || n.v1;
            self.kill.next = issue && n.p_retire;
            self.cur.next = bits(n.cur);
            self.v1.next = n.v1;
            self.tag1.next = bits(n.tag1);
            self.o_ax.next = bits(n.o[0]);
            self.o_ay.next = bits(n.o[1]);
            self.o_bx.next = bits(n.o[2]);
            self.o_by.next = bits(n.o[3]);
            self.o_wx.next = bits(n.o[4]);
            self.o_wy.next = bits(n.o[5]);
        }
    }

    fn connect(&mut self) {
        self.full.connect();
        self.busy.connect();
        self.kill.connect();
        self.cur.connect();
        self.v1.connect();
        self.tag1.connect();
        self.o_ax.connect();
        self.o_ay.connect();
        self.o_bx.connect();
        self.o_by.connect();
        self.o_wx.connect();
        self.o_wy.connect();
    }

    fn hdl(&self) -> Verilog {
        let ops = ["ax", "ay", "bx", "by", "wx", "wy"];
        let mut v = String::from("reg [10:0] remaining;\nreg p_retire;\nreg [5:0] p_sh;\nreg [15:0] p_id;\n");
        for o in ops {
            v += &format!("reg [17:0] p_{o};\n");
        }
        v += "wire issue = remaining != 11'd0;\n";
        v += "initial begin\n   remaining = 11'd0;\n   p_retire = 1'b0;\n   p_sh = 6'd0;\n   p_id = 16'd0;\n";
        v += "   full = 1'b0;\n   cur = 10'd0;\n   v1 = 1'b0;\n   tag1 = 32'd0;\n";
        for o in ops {
            v += &format!("   p_{o} = 18'd0;\n   o_{o} = 18'd0;\n");
        }
        v += "end\n";
        v += "always @(*) begin\n   busy = issue || v1;\n   kill = issue && p_retire;\nend\n";
        v += "always @(posedge clock) begin\n   v1 <= issue && !p_retire;\n   tag1 <= {cur, p_sh, p_id};\n";
        for o in ops {
            v += &format!("   o_{o} <= p_{o};\n");
        }
        v += "   if (patch_valid && !full) begin\n      remaining <= patch_count;\n";
        v += "      full <= patch_count[10:1] != 10'd0;\n      cur <= patch_first;\n";
        for o in ops {
            v += &format!("      p_{o} <= patch_{o};\n");
        }
        v += "      p_sh <= patch_sh;\n      p_id <= patch_id;\n      p_retire <= patch_retire;\n";
        v += "   end else if (issue) begin\n      remaining <= remaining - 11'd1;\n";
        v += "      full <= remaining[10:2] != 9'd0 || remaining[1:0] == 2'b11;\n      cur <= cur + 10'd1;\n   end\nend\n";
        Verilog::Custom(v)
    }

    fn timing(&self) -> Vec<TimingInfo> {
        clocked(
            "issue_sequencer",
            &[
                "patch_valid",
                "patch_ax",
                "patch_ay",
                "patch_bx",
                "patch_by",
                "patch_wx",
                "patch_wy",
                "patch_sh",
                "patch_id",
                "patch_first",
                "patch_count",
                "patch_retire",
            ],
            &["full", "busy", "kill", "cur", "v1", "tag1", "o_ax", "o_ay", "o_bx", "o_by", "o_wx", "o_wy"],
        )
    }
}

/// The registers of [`HitPipe`], as in its Verilog: `v[k]` is stage `k`'s valid bit (index
/// 0 and 1 unused), `tag2` … `tag4` the issue's tag, `t5` … `t8` its ray and id.
#[derive(Clone, Copy, Debug, Default)]
struct HitRegs {
    v: [bool; 9],
    tag2: u32,
    tag3: u32,
    tag4: u32,
    count: u32,
    sa5: u32,
    sb5: u32,
    t5: u32,
    t6: u32,
    t7: u32,
    t8: u32,
}

/// The intersection unit's stages 2 to 8 ([`crate::intersection`]) but for the products and the
/// key (the [`RayProductsPipe`] and [`KeyScalePipe`] leaves beside it): the live bit, the test
/// counter, the side values, the hit decision, and each test's ray and patch id until its key
/// arrives.
///
/// Ports: in `v1`, `tag1` (32: ray 31…22, `sh` 21…16, id 15…0) from [`IssueSequencer`], `alive`
/// (the ray's live bit, arriving in stage 2), the products `dx_ay`, `dy_ax`, `dx_by`, `dy_bx`
/// (32 bits two's complement, arriving in stage 4); out `tests` (32, the live tests so far,
/// wrapping), `busy` (a test in stages 2 to 8), `sh4` (6: stage 4's `sh`, for the key leaf),
/// `ray6` (10: stage 6's ray, the ray-memory read), `v8` and `tag8` (26: ray 25…16, id 15…0):
/// stage 8's hit.
///
/// Stages (one register set each, clock by clock): 2 takes `v1`, `tag1`; 3: the test is live
/// (`v2 && alive`; `tests` counts it); 4: a copy; 5: `sa5 = dx_ay − dy_ax`, `sb5 = dx_by −
/// dy_bx` (32 bits, wrapping), the ray and id; 6: hit = `v5 && sa5 ≤ 0 ≤ sb5` (signed); 7, 8:
/// copies. So `v8`, `tag8` describe the ray issued eight clocks before, `tests` counts a live
/// test three clocks after its issue. Outputs are registers or functions of registers only.
/// All registers are zero at power-up.
#[derive(LogicBlock, Default)]
pub struct HitPipe {
    pub clock: Signal<In, Clock>,
    pub v1: Signal<In, bool>,
    pub tag1: Signal<In, Bits<32>>,
    pub alive: Signal<In, bool>,
    pub dx_ay: Signal<In, Bits<32>>,
    pub dy_ax: Signal<In, Bits<32>>,
    pub dx_by: Signal<In, Bits<32>>,
    pub dy_bx: Signal<In, Bits<32>>,
    pub tests: Signal<Out, Bits<32>>,
    pub busy: Signal<Out, bool>,
    pub sh4: Signal<Out, Bits<6>>,
    pub ray6: Signal<Out, Bits<10>>,
    pub v8: Signal<Out, bool>,
    pub tag8: Signal<Out, Bits<26>>,
    _r: HitRegs,
}

impl Logic for HitPipe {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            let s = self._r;
            let live = s.v[2] && self.alive.val();
            let n = HitRegs {
                v: [
                    false,
                    false,
                    self.v1.val(),
                    live,
                    s.v[3],
                    s.v[4],
                    s.v[5] && (s.sa5 == 0 || s.sa5 >> 31 != 0) && s.sb5 >> 31 == 0,
                    s.v[6],
                    s.v[7],
                ],
                tag2: self.tag1.val().to_u32(),
                tag3: s.tag2,
                tag4: s.tag3,
                count: s.count.wrapping_add(live as u32),
                sa5: self.dx_ay.val().to_u32().wrapping_sub(self.dy_ax.val().to_u32()),
                sb5: self.dx_by.val().to_u32().wrapping_sub(self.dy_bx.val().to_u32()),
                t5: ((s.tag4 >> 22) << 16) | (s.tag4 & 0xffff),
                t6: s.t5,
                t7: s.t6,
                t8: s.t7,
            };
            self._r = n;
            self.tests.next = bits(n.count);
            self.busy.next = n.v[2..].iter().any(|&v| v);
            self.sh4.next = bits((n.tag4 >> 16) & 0x3f);
            self.ray6.next = bits(n.t6 >> 16);
            self.v8.next = n.v[8];
            self.tag8.next = bits(n.t8);
        }
    }

    fn connect(&mut self) {
        self.tests.connect();
        self.busy.connect();
        self.sh4.connect();
        self.ray6.connect();
        self.v8.connect();
        self.tag8.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(
            "\
reg v2, v3, v4, v5, v6, v7;
reg [31:0] tag2;
reg [31:0] tag3;
reg [31:0] tag4;
reg [31:0] sa5;
reg [31:0] sb5;
reg [25:0] t5;
reg [25:0] t6;
reg [25:0] t7;
wire live = v2 && alive;
initial begin
   v2 = 1'b0;
   v3 = 1'b0;
   v4 = 1'b0;
   v5 = 1'b0;
   v6 = 1'b0;
   v7 = 1'b0;
   v8 = 1'b0;
   tag2 = 32'd0;
   tag3 = 32'd0;
   tag4 = 32'd0;
   sa5 = 32'd0;
   sb5 = 32'd0;
   t5 = 26'd0;
   t6 = 26'd0;
   t7 = 26'd0;
   tag8 = 26'd0;
   tests = 32'd0;
end
always @(*) begin
   busy = v2 || v3 || v4 || v5 || v6 || v7 || v8;
   sh4 = tag4[21:16];
   ray6 = t6[25:16];
end
always @(posedge clock) begin
   v2 <= v1;
   tag2 <= tag1;
   v3 <= live;
   tag3 <= tag2;
   if (live) tests <= tests + 32'd1;
   v4 <= v3;
   tag4 <= tag3;
   v5 <= v4;
   sa5 <= dx_ay - dy_ax;
   sb5 <= dx_by - dy_bx;
   t5 <= {tag4[31:22], tag4[15:0]};
   v6 <= v5 && (sa5 == 32'd0 || sa5[31]) && !sb5[31];
   t6 <= t5;
   v7 <= v6;
   t7 <= t6;
   v8 <= v7;
   tag8 <= t7;
end
"
            .into(),
        )
    }

    fn timing(&self) -> Vec<TimingInfo> {
        clocked(
            "hit_pipe",
            &["v1", "tag1", "alive", "dx_ay", "dy_ax", "dx_by", "dy_bx"],
            &["tests", "busy", "sh4", "ray6", "v8", "tag8"],
        )
    }
}

/// One write of [`NearestMerge`]'s forwarding registers: verdict (written), ray, key, id.
#[derive(Clone, Copy, Debug, Default)]
struct MergeWrite {
    valid: bool,
    ray: u32,
    key: u32,
    id: u32,
}

/// The registers of [`NearestMerge`], as in its Verilog.
#[derive(Clone, Copy, Debug, Default)]
struct MergeRegs {
    /// The new hit against the memory's word: hit flag, larger key, equal key, lower id.
    cm: [bool; 4],
    /// Against stage 9's write, the last one and the one before (`c1`, `c2`, `c3`): larger
    /// key, equal key, lower id.
    c: [[bool; 3]; 3],
    /// Stage 9's ray is that of the write one, two, three clocks back (`m1` … `m3`).
    m: [bool; 3],
    v9: bool,
    ray9: u32,
    id9: u32,
    key9: u32,
    /// The writes of the last two clocks (`fw`, `fw2`).
    fw: [MergeWrite; 2],
    fw3_valid: bool,
    rd_valid: bool,
    rd_addr: u32,
    z1: bool,
    z2: bool,
}

impl MergeRegs {
    /// Stage 9's verdict: the newest of the last three writes to the ray decides, otherwise the
    /// memory's word.
    fn better(&self) -> bool {
        let wins = |c: [bool; 3]| c[0] || (c[1] && c[2]);
        let w = if self.m[0] && self.fw[0].valid {
            wins(self.c[0])
        } else if self.m[1] && self.fw[1].valid {
            wins(self.c[1])
        } else if self.m[2] && self.fw3_valid {
            wins(self.c[2])
        } else {
            !self.cm[0] || self.cm[1] || (self.cm[2] && self.cm[3])
        };
        self.v9 && w
    }
}

/// The intersection unit's stages 8 and 9 and its readout clear ([`crate::intersection`]): the
/// new hit against every candidate for its ray's nearest hit (the ray memory's word and the
/// three writes after its read), the verdict, the write-back, and the clear of a ray read out.
///
/// Ports: in `v8`, `tag8` (26: ray 25…16, id 15…0) from [`HitPipe`], `key` (32, unsigned, from
/// [`KeyScalePipe`]), the ray memory's word `mem_key` (32) and `mem_meta` (17: hit flag 16, id
/// 15…0), all arriving in stage 8; the readout request `res_re`, `res_addr` (10); out the ray
/// memory's write port `write_address` (10), `write_key` (32), `write_meta` (17),
/// `write_enable`, `z2` (the readout answered now read a ray whose clear it could not see:
/// report zero), `busy` (a test in stage 9) and `fw_valid` (stage 9 wrote in the clock
/// before).
///
/// Stage 8 (registered at its end): the new key and id against the memory's word (`cm_*`: hit
/// flag, larger key, equal key, lower id), against stage 9's (`c1_*`), the last write's
/// (`c2_*`, `fw_*`) and the one before (`c3_*`, `fw2_*`); `m1` … `m3`: the ray is theirs.
/// Stage 9 (combinational, from registers only): the newest write to the ray among the last
/// three (`fw_valid`, `fw2_valid`, `fw3_valid`: the verdicts of the last three clocks)
/// decides, without one the memory's word; a hit that wins is written (`{1, id}` and its key)
/// at the end of the clock. A readout request is registered (`rd_valid`, `rd_addr`) and clears
/// its ray in the next clock, in place of stage 9's write; `z1`, `z2` mark a readout of the
/// ray read (and cleared) in the clock before, two clocks on. All registers are zero at
/// power-up.
#[derive(LogicBlock, Default)]
pub struct NearestMerge {
    pub clock: Signal<In, Clock>,
    pub v8: Signal<In, bool>,
    pub tag8: Signal<In, Bits<26>>,
    pub key: Signal<In, Bits<32>>,
    pub mem_key: Signal<In, Bits<32>>,
    pub mem_meta: Signal<In, Bits<17>>,
    pub res_re: Signal<In, bool>,
    pub res_addr: Signal<In, Bits<10>>,
    pub write_address: Signal<Out, Bits<10>>,
    pub write_key: Signal<Out, Bits<32>>,
    pub write_meta: Signal<Out, Bits<17>>,
    pub write_enable: Signal<Out, bool>,
    pub z2: Signal<Out, bool>,
    pub busy: Signal<Out, bool>,
    pub fw_valid: Signal<Out, bool>,
    _r: MergeRegs,
}

impl Logic for NearestMerge {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            let s = self._r;
            let t8 = self.tag8.val().to_u32();
            let (ray8, id8) = (t8 >> 16, t8 & 0xffff);
            let key = self.key.val().to_u32();
            let (mem_key, meta) = (self.mem_key.val().to_u32(), self.mem_meta.val().to_u32());
            let cmp = |k: u32, id: u32| [key > k, key == k, id8 < id];
            let (res_re, res_addr) = (self.res_re.val(), self.res_addr.val().to_u32());
            let n = MergeRegs {
                cm: [meta >> 16 != 0, key > mem_key, key == mem_key, id8 < (meta & 0xffff)],
                c: [cmp(s.key9, s.id9), cmp(s.fw[0].key, s.fw[0].id), cmp(s.fw[1].key, s.fw[1].id)],
                m: [ray8 == s.ray9, ray8 == s.fw[0].ray, ray8 == s.fw[1].ray],
                v9: self.v8.val(),
                ray9: ray8,
                id9: id8,
                key9: key,
                fw: [MergeWrite { valid: s.better(), ray: s.ray9, key: s.key9, id: s.id9 }, s.fw[0]],
                fw3_valid: s.fw[1].valid,
                rd_valid: res_re,
                rd_addr: res_addr,
                z1: res_re && s.rd_valid && res_addr == s.rd_addr,
                z2: s.z1,
            };
            self._r = n;
            if n.rd_valid {
                self.write_address.next = bits(n.rd_addr);
                self.write_key.next = bits(0);
                self.write_meta.next = bits(0);
                self.write_enable.next = true;
            } else {
                self.write_address.next = bits(n.ray9);
                self.write_key.next = bits(n.key9);
                self.write_meta.next = bits(0x1_0000 | n.id9);
                self.write_enable.next = n.better();
            }
            self.z2.next = n.z2;
            self.busy.next = n.v9;
            self.fw_valid.next = n.fw[0].valid;
        }
    }

    fn connect(&mut self) {
        self.write_address.connect();
        self.write_key.connect();
        self.write_meta.connect();
        self.write_enable.connect();
        self.z2.connect();
        self.busy.connect();
        self.fw_valid.connect();
    }

    fn hdl(&self) -> Verilog {
        let mut v = String::from(
            "\
wire [9:0] ray8 = tag8[25:16];
wire [15:0] id8 = tag8[15:0];
reg cm_hit, cm_gt, cm_eq, cm_lt;
reg c1_gt, c1_eq, c1_lt, c2_gt, c2_eq, c2_lt, c3_gt, c3_eq, c3_lt;
reg m1, m2, m3;
reg v9;
reg [9:0] ray9;
reg [15:0] id9;
reg [31:0] key9;
reg [9:0] fw_ray;
reg [31:0] fw_key;
reg [15:0] fw_id;
reg fw2_valid;
reg [9:0] fw2_ray;
reg [31:0] fw2_key;
reg [15:0] fw2_id;
reg fw3_valid;
reg rd_valid;
reg [9:0] rd_addr;
reg z1;
reg better;
initial begin
",
        );
        for r in [
            "cm_hit",
            "cm_gt",
            "cm_eq",
            "cm_lt",
            "m1",
            "m2",
            "m3",
            "v9",
            "fw_valid",
            "fw2_valid",
            "fw3_valid",
        ] {
            v += &format!("   {r} = 1'b0;\n");
        }
        for c in 1..=3 {
            v += &format!("   c{c}_gt = 1'b0;\n   c{c}_eq = 1'b0;\n   c{c}_lt = 1'b0;\n");
        }
        for r in ["ray9", "fw_ray", "fw2_ray", "rd_addr"] {
            v += &format!("   {r} = 10'd0;\n");
        }
        for r in ["id9", "fw_id", "fw2_id"] {
            v += &format!("   {r} = 16'd0;\n");
        }
        for r in ["key9", "fw_key", "fw2_key"] {
            v += &format!("   {r} = 32'd0;\n");
        }
        v += "   rd_valid = 1'b0;\n   z1 = 1'b0;\n   z2 = 1'b0;\nend\n";
        v += "\
always @(*) begin
   if (m1 && fw_valid) better = v9 && (c1_gt || (c1_eq && c1_lt));
   else if (m2 && fw2_valid) better = v9 && (c2_gt || (c2_eq && c2_lt));
   else if (m3 && fw3_valid) better = v9 && (c3_gt || (c3_eq && c3_lt));
   else better = v9 && (!cm_hit || cm_gt || (cm_eq && cm_lt));
   if (rd_valid) begin
      write_address = rd_addr;
      write_key = 32'd0;
      write_meta = 17'd0;
      write_enable = 1'b1;
   end else begin
      write_address = ray9;
      write_key = key9;
      write_meta = {1'b1, id9};
      write_enable = better;
   end
   busy = v9;
end
always @(posedge clock) begin
   cm_hit <= mem_meta[16];
   cm_gt <= key > mem_key;
   cm_eq <= key == mem_key;
   cm_lt <= id8 < mem_meta[15:0];
";
        for (c, (k, id)) in
            [("c1", ("key9", "id9")), ("c2", ("fw_key", "fw_id")), ("c3", ("fw2_key", "fw2_id"))]
        {
            v += &format!("   {c}_gt <= key > {k};\n   {c}_eq <= key == {k};\n   {c}_lt <= id8 < {id};\n");
        }
        v += "\
   m1 <= ray8 == ray9;
   m2 <= ray8 == fw_ray;
   m3 <= ray8 == fw2_ray;
   v9 <= v8;
   ray9 <= ray8;
   id9 <= id8;
   key9 <= key;
   fw_valid <= better;
   fw_ray <= ray9;
   fw_key <= key9;
   fw_id <= id9;
   fw2_valid <= fw_valid;
   fw2_ray <= fw_ray;
   fw2_key <= fw_key;
   fw2_id <= fw_id;
   fw3_valid <= fw2_valid;
   rd_valid <= res_re;
   rd_addr <= res_addr;
   z1 <= res_re && rd_valid && res_addr == rd_addr;
   z2 <= z1;
end
";
        Verilog::Custom(v)
    }

    fn timing(&self) -> Vec<TimingInfo> {
        clocked(
            "nearest_merge",
            &["v8", "tag8", "key", "mem_key", "mem_meta", "res_re", "res_addr"],
            &["write_address", "write_key", "write_meta", "write_enable", "z2", "busy", "fw_valid"],
        )
    }
}
