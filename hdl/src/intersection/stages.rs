//! The intersection unit's stages, each a hand-written leaf (a Rust model on plain integers and
//! a Verilog body), so that a settle pass of the simulation visits a handful of blocks instead of
//! some eighty `DFF`s (as `DFF`s they cost the simulation 2.7 times as long: PERFORMANCE.md, "Speed").
//! Their outputs are registers or functions of registers only, so they add no update pass.
//!
//! * [`IssueSequencer`]: stages 0–1, the sequencer, the current patch, the issued ray's
//!   operands and tag.
//! * [`RayProductsPipe`]: the six products of a ray direction with a patch's three vectors and
//!   their operand registers (six DSP blocks; on ECP5 the `MULT18X18D`s' own input and output
//!   registers); one leaf so that a settle pass visits one block instead of twelve.
//! * [`KeyScalePipe`]: the distance key, `q·2^-sh` saturated into `[1, 2³² − 1]` in four
//!   register stages, the bit-true [`crate::formats::key`]. It is a leaf because it is a barrel
//!   shifter: rust-hdl 0.46 simulates every `<<`, `>>` and `get_bits` of a `Bits` through a
//!   heap-allocated big integer, which made this one stage a third of the unit's simulation
//!   time.
//! * [`HitPipe`]: stages 2–8 but for the products and the key: live bit, test counter, side
//!   values, hit decision, each test's ray and id.
//! * [`NearestMerge`]: stages 8–9 and the readout's clear: comparisons, forwarding, verdict and
//!   write-back.
//!
//! Their Rust and Verilog halves are checked against each other by the unit's rung-4 replays.

use crate::formats::{from_bits, key, PRODUCT_SHIFT};
use crate::prim::clocked;
use crate::prim::mul::mult18x18d;
use rust_hdl::prelude::*;

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

/// Clocks from presenting `q` and `sh` to [`KeyScalePipe`] to their key on `key`.
pub const KEY_PIPE_LATENCY: u64 = 4;

/// The intersection unit's distance-key stage, three register stages after its input
/// registers, for a faster clock: the distance key of [`crate::formats::key`] of the `q` and `sh` presented
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
/// `a`, `b`, `w`: six [`Mul18`](crate::prim::Mul18)s in one leaf, with the patch operands held one clock longer
/// than the direction. Outputs, each `(d·x) >> 4` as 32 bits ([`crate::formats::mul`]):
/// `dx_ay`, `dy_ax`, `dx_by`, `dy_bx`, `dx_wx`, `dy_wy`.
///
/// Timing: `ax` … `wy` are presented in one clock (stage 0), `dx`, `dy` in the next (stage 1);
/// their products appear two clocks after `dx`, `dy` (stage 3), one set per clock. The
/// operand registers of stage 1 and the multipliers' input and output registers are inside the
/// leaf: in simulation they are six integers instead of six `DFF`s and six `Mul18` blocks in
/// every settle pass. Maps to six DSP blocks, as six `Mul18`s do.
///
/// On ECP5 (Verilog define `SHELLING_ECP5`) the multipliers are six [`mult18x18d`](crate::prim::mul::mult18x18d) instances
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
    /// `remaining ≠ 0` (a ray issues), kept in a register of its own.
    issue: bool,
    cur: u32,
    /// The current patch: ax, ay, bx, by, wx, wy.
    p: [u32; 6],
    p_sh: u32,
    p_id: u32,
    p_retire: bool,
    v1: bool,
    tag1: u64,
    /// A marker (a retire of no rays) was taken at the last edge.
    mark1: bool,
    /// Stage 1's patch operands: ax, ay, bx, by, wx, wy.
    o: [u32; 6],
}

/// The intersection unit's stages 0 and 1 ([`crate::intersection`]): the sequencer that issues
/// one ray of the current patch per clock, the current patch's fields, and stage 1's registers.
///
/// Ports (formats as in the unit's patch port): in `patch_valid`, `patch_ax` … `patch_wy` (18
/// bits each, two's complement), `patch_sh` (6), `patch_id` (16), `patch_first` (11: bit 10
/// the half of the ray memory), `patch_count` (11), `patch_retire`; out `full`, `busy`, `kill`,
/// `cur` (11), `v1`, `tag1` (33), `mark1`, `o_ax` … `o_wy` (18 each).
///
/// Registers: `remaining` (rays of the current patch still to issue), `full` (`remaining > 1`:
/// no patch can be taken), `issue` (`remaining ≠ 0`: after an issue, `full` before it), `cur`
/// (the ray issued in this clock while `remaining ≠ 0`), the current patch `p_*` and stage 1:
/// `v1` (a ray of a test job was issued in the clock before), `tag1` = `{ray (32…22), sh
/// (21…16), id (15…0)}` and the patch operands `o_*` of that ray. A
/// patch is taken at the rising edge when `patch_valid && !full`; otherwise a ray issues when
/// `remaining ≠ 0` (`remaining` counts down, `cur` up, its low 10 bits modulo 1024: a range
/// stays in its half). A retire of no rays is a **marker**: its take sets `mark1` for one clock,
/// beside stage 1's last ray before it. `full` is updated beside
/// `remaining` from shallow tests (`patch_count > 1` on a take, `remaining > 2` on an issue),
/// so that the unit's `patch_ready`, its complement, is a register: in the processing element
/// it feeds the slice in front of the unit, whose pop decides the take. `issue` likewise, so
/// that `kill` into the live bits' write enables is one gate of registers, not a compare of
/// `remaining`.
///
/// Outputs, all functions of the registers only (so the leaf has no combinational path from an
/// input): `full` (the register), `busy` = a ray issues, `v1` or `mark1`, `kill` = a ray of a
/// retire job issues (its live bit is cleared), and the registers `cur`, `v1`, `tag1`,
/// `mark1`, `o_*`.
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
    pub patch_first: Signal<In, Bits<11>>,
    pub patch_count: Signal<In, Bits<11>>,
    pub patch_retire: Signal<In, bool>,
    pub full: Signal<Out, bool>,
    pub busy: Signal<Out, bool>,
    pub kill: Signal<Out, bool>,
    pub cur: Signal<Out, Bits<11>>,
    pub v1: Signal<Out, bool>,
    pub tag1: Signal<Out, Bits<33>>,
    pub mark1: Signal<Out, bool>,
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
            let issue = s.issue;
            let mut n = s;
            n.v1 = issue && !s.p_retire;
            n.tag1 = ((s.cur as u64) << 22) | ((s.p_sh as u64) << 16) | s.p_id as u64;
            n.o = s.p;
            let take = self.patch_valid.val() && !s.full;
            n.mark1 = take && self.patch_retire.val() && self.patch_count.val().to_u32() == 0;
            if take {
                n.remaining = self.patch_count.val().to_u32();
                n.full = n.remaining > 1;
                n.issue = n.remaining != 0;
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
                n.issue = s.full;
                n.cur = (s.cur & 0x400) | ((s.cur + 1) & 0x3ff);
            }
            debug_assert_eq!(n.full, n.remaining > 1);
            debug_assert_eq!(n.issue, n.remaining != 0);
            self._r = n;
            let issue = n.issue;
            self.full.next = n.full;
            self.busy.next = issue || n.v1 || n.mark1;
            self.kill.next = issue && n.p_retire;
            self.cur.next = bits(n.cur);
            self.v1.next = n.v1;
            self.tag1.next = Bits::from(n.tag1);
            self.mark1.next = n.mark1;
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
        self.mark1.connect();
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
        v += "reg issue;\n";
        v += "initial begin\n   remaining = 11'd0;\n   issue = 1'b0;\n   p_retire = 1'b0;\n   p_sh = 6'd0;\n   p_id = 16'd0;\n";
        v += "   full = 1'b0;\n   cur = 11'd0;\n   v1 = 1'b0;\n   tag1 = 33'd0;\n   mark1 = 1'b0;\n";
        for o in ops {
            v += &format!("   p_{o} = 18'd0;\n   o_{o} = 18'd0;\n");
        }
        v += "end\n";
        v += "always @(*) begin\n   busy = issue || v1 || mark1;\n   kill = issue && p_retire;\nend\n";
        v += "always @(posedge clock) begin\n   v1 <= issue && !p_retire;\n   tag1 <= {cur, p_sh, p_id};\n";
        v += "   mark1 <= patch_valid && !full && patch_retire && patch_count == 11'd0;\n";
        for o in ops {
            v += &format!("   o_{o} <= p_{o};\n");
        }
        v += "   if (patch_valid && !full) begin\n      remaining <= patch_count;\n";
        v += "      issue <= patch_count != 11'd0;\n";
        v += "      full <= patch_count[10:1] != 10'd0;\n      cur <= patch_first;\n";
        for o in ops {
            v += &format!("      p_{o} <= patch_{o};\n");
        }
        v += "      p_sh <= patch_sh;\n      p_id <= patch_id;\n      p_retire <= patch_retire;\n";
        v += "   end else if (issue) begin\n      remaining <= remaining - 11'd1;\n      issue <= full;\n";
        v += "      full <= remaining[10:2] != 9'd0 || remaining[1:0] == 2'b11;\n";
        v += "      cur <= {cur[10], cur[9:0] + 10'd1};\n   end\nend\n";
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
            &[
                "full", "busy", "kill", "cur", "v1", "tag1", "mark1", "o_ax", "o_ay", "o_bx", "o_by", "o_wx",
                "o_wy",
            ],
        )
    }
}

/// The registers of [`HitPipe`], as in its Verilog: `v[k]` is stage `k`'s valid bit (index
/// 0 and 1 unused), `tag2` … `tag4` the issue's tag, `t5` … `t8` its ray and id, `mk[k]`
/// stage `k`'s marker.
#[derive(Clone, Copy, Debug, Default)]
struct HitRegs {
    v: [bool; 9],
    mk: [bool; 9],
    tag2: u64,
    tag3: u64,
    tag4: u64,
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
/// Ports: in `v1`, `tag1` (33: ray 32…22, `sh` 21…16, id 15…0) and `mark1` from
/// [`IssueSequencer`], `alive0`, `alive1` (the ray's live bit in each half's memory, arriving in
/// stage 2: the ray's half, bit 10 of its index, chooses), the products `dx_ay`, `dy_ax`,
/// `dx_by`, `dy_bx` (32 bits two's complement, arriving in stage 4); out `tests` (32, the live
/// tests so far, wrapping), `busy` (a test or a marker in stages 2 to 8), `sh4` (6: stage 4's
/// `sh`, for the key leaf), `ray6` (11: stage 6's ray, the ray-memory read), `v8` and `tag8`
/// (27: ray 26…16, id 15…0): stage 8's hit, and `mark8`: stage 8's marker (a marker rides
/// beside the tests, one register per stage).
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
    pub tag1: Signal<In, Bits<33>>,
    pub mark1: Signal<In, bool>,
    pub alive0: Signal<In, bool>,
    pub alive1: Signal<In, bool>,
    pub dx_ay: Signal<In, Bits<32>>,
    pub dy_ax: Signal<In, Bits<32>>,
    pub dx_by: Signal<In, Bits<32>>,
    pub dy_bx: Signal<In, Bits<32>>,
    pub tests: Signal<Out, Bits<32>>,
    pub busy: Signal<Out, bool>,
    pub sh4: Signal<Out, Bits<6>>,
    pub ray6: Signal<Out, Bits<11>>,
    pub v8: Signal<Out, bool>,
    pub tag8: Signal<Out, Bits<27>>,
    pub mark8: Signal<Out, bool>,
    _r: HitRegs,
}

impl Logic for HitPipe {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            let s = self._r;
            let alive = if s.tag2 >> 32 != 0 { self.alive1.val() } else { self.alive0.val() };
            let live = s.v[2] && alive;
            let mut mk = [false; 9];
            mk[2] = self.mark1.val();
            mk[3..].copy_from_slice(&s.mk[2..8]);
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
                mk,
                tag2: self.tag1.val().to_u64(),
                tag3: s.tag2,
                tag4: s.tag3,
                count: s.count.wrapping_add(live as u32),
                sa5: self.dx_ay.val().to_u32().wrapping_sub(self.dy_ax.val().to_u32()),
                sb5: self.dx_by.val().to_u32().wrapping_sub(self.dy_bx.val().to_u32()),
                t5: (((s.tag4 >> 22) << 16) | (s.tag4 & 0xffff)) as u32,
                t6: s.t5,
                t7: s.t6,
                t8: s.t7,
            };
            self._r = n;
            self.tests.next = bits(n.count);
            self.busy.next = n.v[2..].iter().chain(&n.mk[2..]).any(|&v| v);
            self.sh4.next = bits((n.tag4 >> 16) as u32 & 0x3f);
            self.ray6.next = bits(n.t6 >> 16);
            self.v8.next = n.v[8];
            self.tag8.next = bits(n.t8);
            self.mark8.next = n.mk[8];
        }
    }

    fn connect(&mut self) {
        self.tests.connect();
        self.busy.connect();
        self.sh4.connect();
        self.ray6.connect();
        self.v8.connect();
        self.tag8.connect();
        self.mark8.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(
            "\
reg v2, v3, v4, v5, v6, v7;
reg mk2, mk3, mk4, mk5, mk6, mk7;
reg [32:0] tag2;
reg [32:0] tag3;
reg [32:0] tag4;
reg [31:0] sa5;
reg [31:0] sb5;
reg [26:0] t5;
reg [26:0] t6;
reg [26:0] t7;
wire live = v2 && (tag2[32] ? alive1 : alive0);
initial begin
   v2 = 1'b0;
   v3 = 1'b0;
   v4 = 1'b0;
   v5 = 1'b0;
   v6 = 1'b0;
   v7 = 1'b0;
   v8 = 1'b0;
   mk2 = 1'b0;
   mk3 = 1'b0;
   mk4 = 1'b0;
   mk5 = 1'b0;
   mk6 = 1'b0;
   mk7 = 1'b0;
   mark8 = 1'b0;
   tag2 = 33'd0;
   tag3 = 33'd0;
   tag4 = 33'd0;
   sa5 = 32'd0;
   sb5 = 32'd0;
   t5 = 27'd0;
   t6 = 27'd0;
   t7 = 27'd0;
   tag8 = 27'd0;
   tests = 32'd0;
end
always @(*) begin
   busy = v2 || v3 || v4 || v5 || v6 || v7 || v8 || mk2 || mk3 || mk4 || mk5 || mk6 || mk7 || mark8;
   sh4 = tag4[21:16];
   ray6 = t6[26:16];
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
   t5 <= {tag4[32:22], tag4[15:0]};
   v6 <= v5 && (sa5 == 32'd0 || sa5[31]) && !sb5[31];
   t6 <= t5;
   v7 <= v6;
   t7 <= t6;
   v8 <= v7;
   tag8 <= t7;
   mk2 <= mark1;
   mk3 <= mk2;
   mk4 <= mk3;
   mk5 <= mk4;
   mk6 <= mk5;
   mk7 <= mk6;
   mark8 <= mk7;
end
"
            .into(),
        )
    }

    fn timing(&self) -> Vec<TimingInfo> {
        clocked(
            "hit_pipe",
            &["v1", "tag1", "mark1", "alive0", "alive1", "dx_ay", "dy_ax", "dx_by", "dy_bx"],
            &["tests", "busy", "sh4", "ray6", "v8", "tag8", "mark8"],
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
    /// The new hit against each half's memory word: hit flag, larger key, equal key, lower id.
    cm: [[bool; 4]; 2],
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
    /// The half of the readout word arriving now (`rd_addr`'s bit 10, a clock later).
    res_half: bool,
    mark9: bool,
    marks: u32,
}

/// The half of the ray memory a ray index (11 bits) lies in.
#[inline(always)]
fn half(ray: u32) -> usize {
    (ray >> 10 & 1) as usize
}

impl MergeRegs {
    /// Stage 9's verdict if the ray lies in half `h`: the newest of the last three writes to
    /// the ray decides, otherwise half `h`'s memory word.
    fn better_in(&self, h: usize) -> bool {
        let wins = |c: [bool; 3]| c[0] || (c[1] && c[2]);
        let cm = self.cm[h];
        let w = if self.m[0] && self.fw[0].valid {
            wins(self.c[0])
        } else if self.m[1] && self.fw[1].valid {
            wins(self.c[1])
        } else if self.m[2] && self.fw3_valid {
            wins(self.c[2])
        } else {
            !cm[0] || cm[1] || (cm[2] && cm[3])
        };
        self.v9 && w
    }

    /// Stage 9's verdict.
    fn better(&self) -> bool {
        self.better_in(half(self.ray9))
    }

    /// Half `h`'s write port: a readout's clear in that half, else stage 9's write-back.
    fn write(&self, h: usize) -> (u32, u32, u32, bool) {
        if self.rd_valid && half(self.rd_addr) == h {
            (self.rd_addr & 0x3ff, 0, 0, true)
        } else {
            (self.ray9 & 0x3ff, self.key9, 0x1_0000 | self.id9, self.better_in(h) && half(self.ray9) == h)
        }
    }
}

/// The intersection unit's stages 8 and 9, its readout clear and its marker count
/// ([`crate::intersection`]): the new hit against every candidate for its ray's nearest hit
/// (the ray memory's word and the three writes after its read), the verdict, the write-back,
/// and the clear of a ray read out. The ray memory is two halves (ray index bit 10), each a
/// memory of its own with its own write port, so that a readout's clear in one half and the
/// tests' write-backs in the other never share a port.
///
/// Ports: in `v8`, `tag8` (27: ray 26…16, id 15…0) and `mark8` from [`HitPipe`], `key` (32,
/// unsigned, from [`KeyScalePipe`]), each half's memory word `mem_key0`, `mem_key1` (32) and
/// `mem_meta0`, `mem_meta1` (17: hit flag 16, id 15…0), all arriving in stage 8; the readout
/// request `res_re`, `res_addr` (11); out each half's write port `write_address0/1` (10),
/// `write_key0/1` (32), `write_meta0/1` (17), `write_enable0/1`; `z2` (the readout answered now
/// read a ray whose clear it could not see: report zero), `res_half` (the half of the readout
/// answered now), `busy` (a test or a marker in stage 9), `fw_valid` (stage 9 wrote in the
/// clock before) and `marks` (32: markers counted so far, wrapping).
///
/// Stage 8 (registered at its end): the new key and id against both halves' memory words
/// (`cm0_*`, `cm1_*`: hit flag; in the Verilog the key compare split in halves, `gt_hi`,
/// `eq_hi`, `gt_lo`, `eq_lo` and the id's `lt`, five independent 16-bit compares combined only
/// after their registers, so that no compare longer than 16 bits, and no multiplexer, follows a
/// block RAM's output: on ECP5 that path, its routing out of the block RAM included, was the
/// slowest of the intersection unit (a median of 137.6 MHz with the lower half and the id
/// combined before the register); the model keeps the whole-word compares, the same verdict),
/// against stage 9's (`c1_*`), the last write's (`c2_*`, `fw_*`) and the one before (`c3_*`,
/// `fw2_*`); `m1` … `m3`: the ray is theirs. Stage 9 (combinational, from registers only): the
/// newest write to the ray among the last three (`fw_valid`, `fw2_valid`, `fw3_valid`: the
/// verdicts of the last three clocks) decides, without one the memory word of the ray's half;
/// each half's write enable is that half's own verdict and the ray's half bit. A hit that wins
/// is written (`{1, id}` and its key) at the end of the clock. A readout request is registered
/// (`rd_valid`, `rd_addr`) and clears its ray in the next clock on its half's port; `z1`, `z2`
/// mark a readout of the ray read (and cleared) in the clock before, two clocks on. A marker in
/// stage 9 (`mark9`) is counted at the end of the clock, the clock of the write-back of the
/// last test issued before it: `marks` shows it in the clock after, when a readout's read of
/// that test's ray sees its write. All registers are zero at power-up.
#[derive(LogicBlock, Default)]
pub struct NearestMerge {
    pub clock: Signal<In, Clock>,
    pub v8: Signal<In, bool>,
    pub tag8: Signal<In, Bits<27>>,
    pub mark8: Signal<In, bool>,
    pub key: Signal<In, Bits<32>>,
    pub mem_key0: Signal<In, Bits<32>>,
    pub mem_meta0: Signal<In, Bits<17>>,
    pub mem_key1: Signal<In, Bits<32>>,
    pub mem_meta1: Signal<In, Bits<17>>,
    pub res_re: Signal<In, bool>,
    pub res_addr: Signal<In, Bits<11>>,
    pub write_address0: Signal<Out, Bits<10>>,
    pub write_key0: Signal<Out, Bits<32>>,
    pub write_meta0: Signal<Out, Bits<17>>,
    pub write_enable0: Signal<Out, bool>,
    pub write_address1: Signal<Out, Bits<10>>,
    pub write_key1: Signal<Out, Bits<32>>,
    pub write_meta1: Signal<Out, Bits<17>>,
    pub write_enable1: Signal<Out, bool>,
    pub z2: Signal<Out, bool>,
    pub res_half: Signal<Out, bool>,
    pub busy: Signal<Out, bool>,
    pub fw_valid: Signal<Out, bool>,
    pub marks: Signal<Out, Bits<32>>,
    _r: MergeRegs,
}

impl Logic for NearestMerge {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            let s = self._r;
            let t8 = self.tag8.val().to_u32();
            let (ray8, id8) = (t8 >> 16, t8 & 0xffff);
            let key = self.key.val().to_u32();
            let cmp = |k: u32, id: u32| [key > k, key == k, id8 < id];
            let cmp_mem = |k: u32, meta: u32| [meta >> 16 != 0, key > k, key == k, id8 < (meta & 0xffff)];
            let (res_re, res_addr) = (self.res_re.val(), self.res_addr.val().to_u32());
            let n = MergeRegs {
                cm: [
                    cmp_mem(self.mem_key0.val().to_u32(), self.mem_meta0.val().to_u32()),
                    cmp_mem(self.mem_key1.val().to_u32(), self.mem_meta1.val().to_u32()),
                ],
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
                res_half: half(s.rd_addr) == 1,
                mark9: self.mark8.val(),
                marks: s.marks.wrapping_add(s.mark9 as u32),
            };
            self._r = n;
            let (a, k, m, e) = n.write(0);
            self.write_address0.next = bits(a);
            self.write_key0.next = bits(k);
            self.write_meta0.next = bits(m);
            self.write_enable0.next = e;
            let (a, k, m, e) = n.write(1);
            self.write_address1.next = bits(a);
            self.write_key1.next = bits(k);
            self.write_meta1.next = bits(m);
            self.write_enable1.next = e;
            self.z2.next = n.z2;
            self.res_half.next = n.res_half;
            self.busy.next = n.v9 || n.mark9;
            self.fw_valid.next = n.fw[0].valid;
            self.marks.next = bits(n.marks);
        }
    }

    fn connect(&mut self) {
        self.write_address0.connect();
        self.write_key0.connect();
        self.write_meta0.connect();
        self.write_enable0.connect();
        self.write_address1.connect();
        self.write_key1.connect();
        self.write_meta1.connect();
        self.write_enable1.connect();
        self.z2.connect();
        self.res_half.connect();
        self.busy.connect();
        self.fw_valid.connect();
        self.marks.connect();
    }

    fn hdl(&self) -> Verilog {
        let mut v = String::from(
            "\
wire [10:0] ray8 = tag8[26:16];
wire [15:0] id8 = tag8[15:0];
reg cm0_hit, cm0_gt_hi, cm0_eq_hi, cm0_gt_lo, cm0_eq_lo, cm0_lt;
reg cm1_hit, cm1_gt_hi, cm1_eq_hi, cm1_gt_lo, cm1_eq_lo, cm1_lt;
reg c1_gt, c1_eq, c1_lt, c2_gt, c2_eq, c2_lt, c3_gt, c3_eq, c3_lt;
reg m1, m2, m3;
reg v9;
reg [10:0] ray9;
reg [15:0] id9;
reg [31:0] key9;
reg [10:0] fw_ray;
reg [31:0] fw_key;
reg [15:0] fw_id;
reg fw2_valid;
reg [10:0] fw2_ray;
reg [31:0] fw2_key;
reg [15:0] fw2_id;
reg fw3_valid;
reg rd_valid;
reg [10:0] rd_addr;
reg z1;
reg mark9;
reg fwd, fwin, better0, better1;
initial begin
",
        );
        for h in 0..2 {
            for f in ["hit", "gt_hi", "eq_hi", "gt_lo", "eq_lo", "lt"] {
                v += &format!("   cm{h}_{f} = 1'b0;\n");
            }
        }
        for r in ["m1", "m2", "m3", "v9", "fw_valid", "fw2_valid", "fw3_valid", "mark9", "res_half"] {
            v += &format!("   {r} = 1'b0;\n");
        }
        for c in 1..=3 {
            v += &format!("   c{c}_gt = 1'b0;\n   c{c}_eq = 1'b0;\n   c{c}_lt = 1'b0;\n");
        }
        for r in ["ray9", "fw_ray", "fw2_ray", "rd_addr"] {
            v += &format!("   {r} = 11'd0;\n");
        }
        for r in ["id9", "fw_id", "fw2_id"] {
            v += &format!("   {r} = 16'd0;\n");
        }
        for r in ["key9", "fw_key", "fw2_key", "marks"] {
            v += &format!("   {r} = 32'd0;\n");
        }
        v += "   rd_valid = 1'b0;\n   z1 = 1'b0;\n   z2 = 1'b0;\nend\n";
        v += "\
always @(*) begin
   fwd = 1'b1;
   if (m1 && fw_valid) fwin = c1_gt || (c1_eq && c1_lt);
   else if (m2 && fw2_valid) fwin = c2_gt || (c2_eq && c2_lt);
   else if (m3 && fw3_valid) fwin = c3_gt || (c3_eq && c3_lt);
   else begin
      fwd = 1'b0;
      fwin = 1'b0;
   end
   better0 = v9 && (fwd ? fwin : (!cm0_hit || cm0_gt_hi || (cm0_eq_hi && (cm0_gt_lo || (cm0_eq_lo && cm0_lt)))));
   better1 = v9 && (fwd ? fwin : (!cm1_hit || cm1_gt_hi || (cm1_eq_hi && (cm1_gt_lo || (cm1_eq_lo && cm1_lt)))));
";
        for h in 0..2 {
            // `!` for half 0: the half bit is low.
            let is = if h == 1 { "" } else { "!" };
            v += &format!(
                "   if (rd_valid && {is}rd_addr[10]) begin
      write_address{h} = rd_addr[9:0];
      write_key{h} = 32'd0;
      write_meta{h} = 17'd0;
      write_enable{h} = 1'b1;
   end else begin
      write_address{h} = ray9[9:0];
      write_key{h} = key9;
      write_meta{h} = {{1'b1, id9}};
      write_enable{h} = better{h} && {is}ray9[10];
   end
"
            );
        }
        v += "   busy = v9 || mark9;\nend\nalways @(posedge clock) begin\n";
        for h in 0..2 {
            v += &format!(
                "   cm{h}_hit <= mem_meta{h}[16];
   cm{h}_gt_hi <= key[31:16] > mem_key{h}[31:16];
   cm{h}_eq_hi <= key[31:16] == mem_key{h}[31:16];
   cm{h}_gt_lo <= key[15:0] > mem_key{h}[15:0];
   cm{h}_eq_lo <= key[15:0] == mem_key{h}[15:0];
   cm{h}_lt <= id8 < mem_meta{h}[15:0];
"
            );
        }
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
   fw_valid <= ray9[10] ? better1 : better0;
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
   res_half <= rd_addr[10];
   mark9 <= mark8;
   if (mark9) marks <= marks + 32'd1;
end
";
        Verilog::Custom(v)
    }

    fn timing(&self) -> Vec<TimingInfo> {
        clocked(
            "nearest_merge",
            &[
                "v8",
                "tag8",
                "mark8",
                "key",
                "mem_key0",
                "mem_meta0",
                "mem_key1",
                "mem_meta1",
                "res_re",
                "res_addr",
            ],
            &[
                "write_address0",
                "write_key0",
                "write_meta0",
                "write_enable0",
                "write_address1",
                "write_key1",
                "write_meta1",
                "write_enable1",
                "z2",
                "res_half",
                "busy",
                "fw_valid",
                "marks",
            ],
        )
    }
}
