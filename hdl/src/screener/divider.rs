//! The screener's divider: two 17-bit quotients of one 32-bit divisor by restoring division,
//! one compare-and-subtract stage per quotient bit (latency [`DIV_LATENCY`], one division pair
//! per clock), the bit-true [`restoring_quotient`]. [`PipeDivider`] is a hand-written leaf (a
//! Rust model stepping the same registers as its Verilog body) so that its 17 stages of
//! registers and 32-bit subtractors cost the simulation one short Rust loop per clock instead of
//! a hundred-odd more signals in every settle pass.

use crate::prim::clocked;
use rust_hdl::prelude::*;

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
    /// `−q >> 1` of the stage before, 17 bits: kept by the last stage only.
    nh: [u32; 2],
    tag: u32,
}

/// Two restoring dividers sharing a divisor, pipelined: one compare-and-subtract stage per
/// quotient bit, so a new pair of divisions starts every clock. `qx`, `qy` are
/// [`restoring_quotient`]`(rx, fx, k)` and `(ry, fy, k)` of the inputs presented
/// [`DIV_LATENCY`] clocks earlier, and `tag_out` is the `tag` presented with them (a side band
/// the divider carries unchanged: valid bit, signs). All registers power up as zero, so the
/// first [`DIV_LATENCY`] outputs carry a zero tag and meaningless quotients. `wx`, `wy` are
/// the quotients with the signs of `tag_out`'s bits 1 and 2 (18 bits, two's complement: `W =
/// sign(n)·q`). The negation has no carry chain after the last stage's registers: with
/// `q = 2·h + b`, `−q` is `2·(−h)` when `b = 0` (the last stage registers `−h` from the stage
/// before's `h`, beside its own subtraction) and `2·!h + 1` when `b = 1`. The Rust model steps
/// the same registers as the Verilog, stage by stage.
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
    pub wx: Signal<Out, Bits<18>>,
    pub wy: Signal<Out, Bits<18>>,
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
            wx: Default::default(),
            wy: Default::default(),
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
                    if s == DIV_STEPS {
                        next.nh[c] = prev.q[c].wrapping_neg() & ((1 << DIV_STEPS) - 1);
                    }
                }
                self._stages[s] = next;
            }
            self._stages[0] = DivStage {
                k: self.k.val().to_u32(),
                r: [self.rx.val().to_u32(), self.ry.val().to_u32()],
                f: [self.fx.val().to_u32(), self.fy.val().to_u32()],
                q: [0, 0],
                nh: [0, 0],
                tag: self.tag.val().to_u32(),
            };
            let last = &self._stages[DIV_STEPS];
            self.qx.next = Bits::from(last.q[0] as u64);
            self.qy.next = Bits::from(last.q[1] as u64);
            let signed = |c: usize| {
                let (q, h) = (last.q[c], last.q[c] >> 1);
                let w = if last.tag >> (c + 1) & 1 == 0 {
                    q
                } else if q & 1 == 1 {
                    (!h & ((1 << DIV_STEPS) - 1)) << 1 | 1
                } else {
                    last.nh[c] << 1
                };
                Bits::from(w as u64)
            };
            self.wx.next = signed(0);
            self.wy.next = signed(1);
            self.tag_out.next = Bits::from(last.tag as u64);
        }
    }

    fn connect(&mut self) {
        self.qx.connect();
        self.qy.connect();
        self.wx.connect();
        self.wy.connect();
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
reg [16:0] nhx;
reg [16:0] nhy;
initial begin
   kp = 0;
   rxp = 0;
   ryp = 0;
   fxp = 0;
   fyp = 0;
   qxp = 0;
   qyp = 0;
   tgp = 0;
   nhx = 0;
   nhy = 0;
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
always @(posedge clock) begin
   nhx <= 17'd0 - qxp[17*(N-1) +: 17];
   nhy <= 17'd0 - qyp[17*(N-1) +: 17];
end
always @(*) begin
   qx = qxp[17*N +: 17];
   qy = qyp[17*N +: 17];
   tag_out = tgp[3*N +: 3];
   wx = !tag_out[1] ? {{1'b0, qx}} : qx[0] ? {{1'b1, ~qx[16:1], 1'b1}} : {{nhx, 1'b0}};
   wy = !tag_out[2] ? {{1'b0, qy}} : qy[0] ? {{1'b1, ~qy[16:1], 1'b1}} : {{nhy, 1'b0}};
end
",
            n = DIV_STEPS
        ))
    }

    fn timing(&self) -> Vec<TimingInfo> {
        clocked("pipe_divider", &["rx", "ry", "fx", "fy", "k", "tag"], &["qx", "qy", "wx", "wy", "tag_out"])
    }
}

#[cfg(test)]
mod tests {
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
}
