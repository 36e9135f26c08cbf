//! The backface screener: per-patch screening and setup for the intersection unit.
//!
//! # Purpose
//!
//! For each patch loaded for the current bundle it decides, once, whether any ray of the bundle
//! can hit the patch, and if so computes the values the intersection unit needs to test the
//! patch against a ray in one clock:
//!
//! * **backward** (Def 2.2): both endpoints lie on or behind the source's plane;
//! * **back-facing**: the origin lies behind the patch or on its line (`cross(a, b) ≤ 0`);
//! * **outside the sector**: an endpoint in front of the source lies beyond the sector's first or
//!   last ray by more than [`SECTOR_MARGIN`]; the test is conservative, so it never drops a patch
//!   that some ray of the sector hits;
//! * **near**: the patch's line passes within about one coordinate LSB (1/64 world unit) of the
//!   origin, so its inverse-distance vector does not fit 18 bits even at the smallest exponent
//!   (`sh = −3`); no ray can be decided reliably against it.
//!
//! A passing patch leaves with its coordinates relative to the origin and its inverse-distance
//! vector `W = n·2^(16+sh)/K`, normalised by the exponent `sh` (see `FORMATS.md`).
//!
//! The bit-true model is [`model::screen`]; the RTL block is [`Screener`], which computes it bit for
//! bit, one patch per clock.
//!
//! # Ports ([`Screener`])
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | rising-edge clock |
//! | `origin_x`, `origin_y` | in | 17, 17 | bundle setup: ray origin, world coordinates (Q11.6 unsigned) |
//! | `normal_x/y`, `first_x/y`, `last_x/y` | in | 6 × 18 | bundle setup: source normal, sector's first and last ray (Q2.16) |
//! | `in_valid`, `in_ready`, `in_id` | in, out, in | 1, 1, 16 | patch stream in (valid/ready) |
//! | `in_ax`, `in_ay`, `in_bx`, `in_by` | in | 4 × 17 | endpoints, world coordinates (Q11.6 unsigned) |
//! | `in_bank` | in | 1 | the patch's sector bank: a tag carried to stage 3, where the sector is read |
//! | `sector_read`, `sector_bank` | out | 1, 1 | a patch is in stage 3 and reads `first`/`last` in this cycle; its `in_bank` (both registers) |
//! | `normal_bank` | out | 1 | the `in_bank` of the patch in stage 1, which reads `normal` in this cycle (a register) |
//! | `out_valid`, `out_ready`, `out_id` | out, in, out | 1, 1, 16 | every patch out (valid/ready), in acceptance order |
//! | `out_pass` | out | 1 | the patch passed; if not, only `out_id` is meaningful (the consumer drops it) |
//! | `out_ax`, `out_ay`, `out_bx`, `out_by` | out | 4 × 18 | endpoints relative to the origin (Q12.6) |
//! | `out_wx`, `out_wy`, `out_sh` | out | 18, 18, 6 | inverse-distance vector, its exponent in [−3, 31] |
//! | `passed`, `backward`, `back_facing`, `outside`, `near` | out | 5 × 32 | verdict counters, wrapping at 2³² |
//!
//! The source's setup is read once per patch: `origin` in its stage 0 (as it is accepted),
//! `normal` in its stage 1, the sector's (`first`, `last`) in its stage 3 ([`SECTOR_STAGE`]). A
//! user that changes the source or the sector while patches stream tags each patch with
//! `in_bank` and presents, in each cycle, the origin of the bank on `in_bank`, the normal of the
//! bank `normal_bank` shows and the sector of the bank `sector_bank` shows (the processing
//! element keeps two banks: each job carries its bank's origin, the normal and the sector are
//! multiplexed; with `in_bank` held low and the setup held
//! constant the screener is the one-sector block). A transfer happens
//! in a cycle where `valid && ready` holds before the rising edge. `in_ready` depends only on
//! registers (not on `in_valid` or `out_ready`); `out_valid` is a register and the `out_*` data
//! depend only on registers (the output FIFO's two read registers, chosen by the registered
//! pop), so no combinational path crosses the block. While
//! `out_valid` is low the `out_*` data show the FIFO's head slot, which may hold an old or a
//! half-written setup (zero after power-up): meaningless, but the same in the rust-hdl
//! simulation and in the Verilog. Every accepted patch is counted in exactly one counter, one
//! cycle after its verdict ([`COUNT_LATENCY`]).
//!
//! Number formats (`FORMATS.md`, [`crate::formats`]): world coordinates Q11.6 in 17 bits
//! unsigned; relative coordinates Q12.6 and directions Q2.16 in 18 bits two's complement;
//! products [`crate::formats::mul`] (18×18, shifted right by 4, 32 bits); `W` 18 bits two's
//! complement with the exponent `sh` 6 bits two's complement.
//!
//! # Pipeline
//!
//! The pipeline never stalls; a patch accepted in cycle `a` is in stage `s` in cycle `a + s`:
//!
//! * stage 0: acceptance; the coordinates relative to the origin are registered;
//! * stage 1: the products start ([`Mul18`] leaves, latency 2, one DSP each), in three groups
//!   one stage apart so that no operand register drives two multipliers: the two of `K` now;
//!   `n = (b.y − a.y, a.x − b.x)` and `|n_c|` (each negation as the reversed difference, in
//!   parallel with it);
//! * stage 2: the four products of `dot(n_s, a)` and `dot(n_s, b)` start;
//!   `nmax = max(|n_x|, |n_y|)`;
//! * stage 3: the four side products (against the sector's edges) start; the products of `K`
//!   arrive and are registered once more, as they are (the multiplier's product register
//!   drives that register only); `nmax` enters a [`Normaliser`] (stages 3–4: its leading zeros
//!   and `nmax` shifted by them, by five conditional shifts: 16 and 8 side by side, then 4, 2
//!   and 1);
//! * stage 4: `K`; the products of the dot products arrive;
//! * stage 5: `2K` enters the other [`Normaliser`] (stages 5–6); `dot(n_s, a)`, `dot(n_s, b)`;
//!   the side products arrive;
//! * stage 6: the backward and back-facing screens; the side values;
//! * stage 7: the exponent's two candidates (from the two leading-zero counts) and the
//!   comparison of the normalised values that chooses between them, each registered; the
//!   outside-the-sector screen's compares by 16-bit halves, registered;
//! * stage 8 ([`VERDICT_LATENCY`]): the exponent `sh` chosen; the outside and near screens and
//!   the verdict. The patch takes the next slot of the output FIFO (id, `a`, `b`, `sh` and the
//!   verdict written) and enters the divider with its initial remainders `floor(|n_c|·2^sh)`
//!   (one shifter by `s0 + 3`, a register, then a shift right by one when `sh = s0 − 1`: the
//!   exponent's choice is the last multiplexer before the divider);
//! * stage 9 ([`COUNT_LATENCY`]), beside the divider's first: the verdict, registered as one
//!   flag per counter, is counted;
//! * stages 9–26: the [`PipeDivider`] leaf: two pipelined restoring dividers sharing the divisor
//!   `K`, one stage per quotient bit ([`DIV_STEPS`](divider::DIV_STEPS) = 17 steps of a
//!   33-bit subtraction; latency [`DIV_LATENCY`] = 18 with its input registers). In stage 26
//!   `W = sign(n)·q` (signed by the divider, no carry chain after its last registers)
//!   completes the patch's slot;
//! * stages 27–28: the slot is read out; the patch is on the output in cycle `a + `[`LATENCY`]
//!   (28) and leaves then if `out_ready` is high.
//!
//! The stages are cut for an ECP5 (LFE5U-85F, speed grade 6) clock of 150 MHz: at most one
//! carry chain, or two or three conditional shifts, between registers; the output FIFO reads
//! the head and the slot after it every cycle (a [`FifoControl`]: fill pointer, read side and
//! count of complete slots, `rd_ptr + 1` kept in a register), so that
//! `out_ready` reaches no read address, only the registered choice between the two; the
//! counters count a registered verdict; and `in_ready` is a register (`!full`). The multipliers
//! are [`Mul18`]s, on ECP5 `MULT18X18D`s with their own input and output registers. Measured
//! (`cargo xtask fpga --blocks screener --families ecp5 --seeds 1,2,3,4,5`) the block reaches a
//! median of 155.6 MHz (151.7–161.5; `hdl/fpga/ecp5.md`; 160.6, 151.2–169.0, before the split
//! into the normaliser's and the delays' leaves: the same logic, which Yosys maps and nextpnr
//! places anew; 152.9, 150.6–160.7, before the outside compare's halves were registered and
//! the dividend formed by one shifter; 155.1, 150.4–165.4, before the divider signed `W`
//! itself; 158.6, 150.0–163.6, before the normal was read in stage 1 only, for the processing
//! element's banks; 150.4 before stage 7 registered the exponent's flags and split the outside
//! compare, 125 at seed 1 before the DSP registers). Its critical paths now: the dividend (`c_absnx` through the shifter, `sp3_8`)
//! into the divider's first remainder (seeds 1, 3, 5), `k5` into the exponent's normaliser
//! (2, 4).
//!
//! A screened-out patch goes the same way and leaves with `out_pass` low: every patch leaves in
//! acceptance order with its verdict, so a consumer that pairs patches with other information
//! (the processing element's ray ranges) stays in step without counting.
//!
//! # Backpressure: credits
//!
//! The [`Mul18`] and divider stages have no clock enable, so the pipeline cannot stall; instead
//! nothing is accepted that could not be stored. The output FIFO has [`DEPTH`] (32) slots in
//! eight [`FifoRam`] lanes (LUT RAM) sharing one read pointer: the slot is reserved in stage 8 and
//! completed in stage 26 (a second write pointer suffices, the divider's latency being fixed).
//! A credit counter counts the patches in flight: it is incremented when a patch is accepted and
//! decremented when it leaves. A patch is accepted only while the count is below [`DEPTH`], so
//! every patch in the pipeline has a slot waiting for it: nothing is dropped, and backpressure
//! on the output stops the input (`in_ready` low) instead.
//!
//! # Latency and throughput
//!
//! Without backpressure a patch accepted in cycle `a` is counted in cycle `a + 9` and leaves in
//! cycle `a + 28` ([`LATENCY`]). A credit is taken in the cycle of acceptance and returned in
//! the cycle of the transfer out (held 29 cycles); a returned credit can be taken again the next
//! cycle. With `DEPTH = 32 ≥ 29` the screener therefore accepts one patch per clock (II = 1)
//! for any mix of verdicts, as long as the output is not backpressured. The cycle counts of an
//! unstalled stream are [`model::unstalled_cycles`]: `N` patches offered back to back take
//! `N + 28` cycles. Under sustained backpressure the screener holds 32 patches and takes no
//! more until one leaves.
//!
//! # Models
//!
//! [`model::screen`] is the bit-true model of every verdict and setup; [`model::accept_cycles`],
//! [`model::output_cycles`] and [`model::unstalled_cycles`] give the exact timing of an
//! unstalled stream. Resources (Yosys `synth_ecp5`): 10 `MULT18X18D`, 144 `TRELLIS_DPR16X4` (the
//! FIFO, its LUT RAM twice for the two reads), and in nextpnr's count 5532 LUT4s (LUT RAM
//! included) and 4289 flip-flops (placement seed 1, `hdl/fpga/ecp5.md`), of which the divider
//! takes about 1000 LUT4, 580 `CCU2C` carry cells and 2000 flip-flops.

use crate::formats::{
    cross, dot, PatchSetup, COORD_W, DIR_W, ID_W, SECTOR_MARGIN, SH_MAX, SH_MIN, SH_W, WORLD_W, W_W,
};
use crate::prim::{Delay, FifoControl, FifoRam, Mul18};

pub mod divider;
pub mod normaliser;

use divider::{PipeDivider, DIV_LATENCY};
use normaliser::Normaliser;
use rust_hdl::prelude::*;

/// The bit-true model of the screener: plain integer functions.
pub mod model {
    use super::*;

    /// The bundle the screener works for (all Q-formats of `FORMATS.md`).
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
    pub struct BundleSetup {
        /// Ray origin, world coordinates (Q11.6, unsigned 17 bits).
        pub origin: [i32; 2],
        /// Unit normal of the source (Q2.16).
        pub normal: [i32; 2],
        /// Direction of the sector's first ray (Q2.16).
        pub first: [i32; 2],
        /// Direction of the sector's last ray (Q2.16).
        pub last: [i32; 2],
    }

    /// A patch as loaded from host memory: id and endpoints in world coordinates (Q11.6).
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
    pub struct Patch {
        pub id: u16,
        pub a: [i32; 2],
        pub b: [i32; 2],
    }

    /// The screener's decision on one patch.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub enum Verdict {
        Pass(PatchSetup),
        Backward,
        BackFacing,
        OutsideSector,
        Near,
    }

    /// Screens one patch for a bundle.
    pub fn screen(bundle: &BundleSetup, patch: &Patch) -> Verdict {
        let o = bundle.origin;
        let a = [patch.a[0] - o[0], patch.a[1] - o[1]];
        let b = [patch.b[0] - o[0], patch.b[1] - o[1]];
        let ha = dot(bundle.normal, a);
        let hb = dot(bundle.normal, b);
        if ha <= 0 && hb <= 0 {
            return Verdict::Backward;
        }
        // cross(a, b) = twice the area of (O, A, B): positive when O is on the front side. The
        // coordinates are 18-bit, so the difference of the truncated products fits 32 bits.
        let k = cross(a, b);
        if k <= 0 {
            return Verdict::BackFacing;
        }
        if (hb > 0 && (cross(bundle.first, b) as i64) < -SECTOR_MARGIN)
            || (ha > 0 && (cross(bundle.last, a) as i64) > SECTOR_MARGIN)
        {
            return Verdict::OutsideSector;
        }
        let n = [b[1] - a[1], a[0] - b[0]];
        let nmax = n[0].unsigned_abs().max(n[1].unsigned_abs()) as u64;
        // |W| < 2^17 needs nmax·2^sh < 2K: scaled by 2^-SH_MIN to stay in integers.
        let k2 = (2 * k as u64) << -SH_MIN;
        if nmax >= k2 {
            return Verdict::Near;
        }
        // The largest exponent with nmax·2^sh < 2K.
        let mut e = 0u32; // sh − SH_MIN
        while e < (SH_MAX - SH_MIN) as u32 && (nmax << (e + 1)) < k2 {
            e += 1;
        }
        let sh = e as i32 + SH_MIN;
        let w = n.map(|c| {
            // floor(|n|·2^(16+sh) / K), exactly.
            let q = ((c.unsigned_abs() as u128) << (16 + sh) as u32) / k as u128;
            debug_assert!(q < 1 << 17);
            if c < 0 {
                -(q as i32)
            } else {
                q as i32
            }
        });
        Verdict::Pass(PatchSetup { id: patch.id, a, b, w, sh: sh as i8 })
    }

    /// The cycles in which `n` patches offered back to back from cycle 0 are accepted when the
    /// output is always ready. A patch is accepted while fewer than [`DEPTH`] credits are taken;
    /// a credit is returned at the end of the cycle the patch leaves, whatever its verdict. With
    /// `DEPTH > LATENCY` this is cycle `k` for patch `k`.
    pub fn accept_cycles(n: usize) -> Vec<u64> {
        let mut a: Vec<u64> = Vec::with_capacity(n);
        for k in 0..n {
            let mut c = a.last().map_or(0, |&p| p + 1);
            // Credits taken in cycle c: accepted before c and returned in cycle c or later.
            while (0..k).filter(|&j| a[j] + LATENCY >= c).count() >= DEPTH {
                c += 1;
            }
            a.push(c);
        }
        a
    }

    /// The cycles in which the patches leave, under the conditions of [`accept_cycles`]:
    /// acceptance plus [`LATENCY`].
    pub fn output_cycles(n: usize) -> Vec<u64> {
        accept_cycles(n).into_iter().map(|a| a + LATENCY).collect()
    }

    /// Cycles (rising edges) until every patch has left, under the conditions of
    /// [`accept_cycles`]: `N + LATENCY` (`N + 28`), with patch `k` accepted in cycle `k`.
    pub fn unstalled_cycles(n: usize) -> u64 {
        output_cycles(n).last().map_or(0, |c| c + 1)
    }
}

// ---------------------------------------------------------------------------------------------
// The RTL block.
// ---------------------------------------------------------------------------------------------

/// Pipeline stage in which a patch reads the sector (`first`, `last`): a patch accepted in
/// cycle `a` reads it in cycle `a + SECTOR_STAGE`, when `sector_read` is high with its bank on
/// `sector_bank`.
pub const SECTOR_STAGE: u64 = 3;
/// Pipeline stage of the verdict: a patch accepted in cycle `a` is decided in cycle
/// `a + VERDICT_LATENCY` (and takes its output FIFO slot then).
pub const VERDICT_LATENCY: u64 = 8;
/// Pipeline stage of the count: a patch accepted in cycle `a` is counted in cycle
/// `a + COUNT_LATENCY`, a cycle after its verdict (the counters show it from the next cycle
/// on).
pub const COUNT_LATENCY: u64 = VERDICT_LATENCY + 1;
/// Clocks from a patch's acceptance to its setup on the output: a patch accepted in
/// cycle `a` is presented (`out_valid`) from cycle `a + LATENCY` on; with `out_ready` high it
/// leaves in that cycle. The verdict, the divider ([`DIV_LATENCY`]) and the output FIFO's write
/// and registered read: `8 + 18 + 2`.
pub const LATENCY: u64 = VERDICT_LATENCY + DIV_LATENCY + 2;
/// Output FIFO capacity in patches, and the credit limit: a patch is accepted only while fewer
/// than `DEPTH` patches are in flight (accepted and not yet out).
/// One patch per clock needs `DEPTH ≥ LATENCY + 1`.
pub const DEPTH: usize = 32;
/// Address width of the output FIFO's lanes: `2^ADDR_BITS == DEPTH`.
pub const ADDR_BITS: usize = 5;

/// Bits of the divider's dividend as stage 8 forms it: the 32-bit initial remainder
/// `floor(|n_c|·2^sh)` above the three bits a shift right (`sh` = −1, −2, −3) moves out of it.
const DIVIDEND_BITS: usize = 35;

/// The sign bit of a 32-bit side value. The sector screen flips it, so that an unsigned compare
/// orders the signed values, and compares with `2³¹ ∓ SECTOR_MARGIN`.
const SIGN32: u64 = 1 << 31;

/// The backface screener (see the [module documentation](self)): a pipeline that accepts one
/// patch per clock.
#[derive(LogicBlock)]
pub struct Screener {
    pub clock: Signal<In, Clock>,
    // Bundle setup.
    pub origin_x: Signal<In, Bits<WORLD_W>>,
    pub origin_y: Signal<In, Bits<WORLD_W>>,
    pub normal_x: Signal<In, Bits<DIR_W>>,
    pub normal_y: Signal<In, Bits<DIR_W>>,
    pub first_x: Signal<In, Bits<DIR_W>>,
    pub first_y: Signal<In, Bits<DIR_W>>,
    pub last_x: Signal<In, Bits<DIR_W>>,
    pub last_y: Signal<In, Bits<DIR_W>>,
    // Patch stream in.
    pub in_valid: Signal<In, bool>,
    pub in_ready: Signal<Out, bool>,
    pub in_id: Signal<In, Bits<ID_W>>,
    pub in_ax: Signal<In, Bits<WORLD_W>>,
    pub in_ay: Signal<In, Bits<WORLD_W>>,
    pub in_bx: Signal<In, Bits<WORLD_W>>,
    pub in_by: Signal<In, Bits<WORLD_W>>,
    /// The patch's sector bank, carried to stage 3 ([`sector_bank`](Self::sector_bank)).
    pub in_bank: Signal<In, bool>,
    // The sector read: the bank of the patch in stage 3.
    pub sector_read: Signal<Out, bool>,
    pub sector_bank: Signal<Out, bool>,
    /// The bank of the patch in stage 1, whose `normal` is read now.
    pub normal_bank: Signal<Out, bool>,
    // Every patch out, with its verdict.
    pub out_valid: Signal<Out, bool>,
    pub out_ready: Signal<In, bool>,
    pub out_id: Signal<Out, Bits<ID_W>>,
    pub out_ax: Signal<Out, Bits<COORD_W>>,
    pub out_ay: Signal<Out, Bits<COORD_W>>,
    pub out_bx: Signal<Out, Bits<COORD_W>>,
    pub out_by: Signal<Out, Bits<COORD_W>>,
    pub out_wx: Signal<Out, Bits<W_W>>,
    pub out_wy: Signal<Out, Bits<W_W>>,
    pub out_sh: Signal<Out, Bits<SH_W>>,
    pub out_pass: Signal<Out, bool>,
    // Counters.
    pub passed: Signal<Out, Bits<32>>,
    pub backward: Signal<Out, Bits<32>>,
    pub back_facing: Signal<Out, Bits<32>>,
    pub outside: Signal<Out, Bits<32>>,
    pub near: Signal<Out, Bits<32>>,
    // Credits and the output FIFO.
    used: DFF<Bits<6>>,
    res_ptr: DFF<Bits<5>>,
    /// The output FIFO's fill pointer (its tail), read side and count of complete slots: a slot
    /// is pushed when its quotients arrive.
    fifo: FifoControl<5, 6>,
    lane_id: FifoRam<16, 5>,
    lane_ax: FifoRam<18, 5>,
    lane_ay: FifoRam<18, 5>,
    lane_bx: FifoRam<18, 5>,
    lane_by: FifoRam<18, 5>,
    lane_sh: FifoRam<7, 5>,
    sh_pass: Signal<Local, Bits<7>>,
    pass_flag: Constant<Bits<7>>,
    lane_wx: FifoRam<18, 5>,
    lane_wy: FifoRam<18, 5>,
    room: Signal<Local, bool>,
    used_next: Signal<Local, Bits<6>>,
    /// `used == DEPTH` after this edge, registered: `in_ready` is `!full` with no logic in
    /// between (the loader's pop, and through it its FIFO's read address, hang on it).
    full: DFF<bool>,
    take: Signal<Local, bool>,
    pop: Signal<Local, bool>,
    reserve: Signal<Local, bool>,
    fill: Signal<Local, bool>,
    used_inc: Signal<Local, Bits<6>>,
    used_dec: Signal<Local, Bits<6>>,
    res_inc: Signal<Local, Bits<5>>,
    // Stage 0: coordinates relative to the origin.
    ext_ox: Signal<Local, Bits<COORD_W>>,
    ext_oy: Signal<Local, Bits<COORD_W>>,
    ext_ax: Signal<Local, Bits<COORD_W>>,
    ext_ay: Signal<Local, Bits<COORD_W>>,
    ext_bx: Signal<Local, Bits<COORD_W>>,
    ext_by: Signal<Local, Bits<COORD_W>>,
    // Stage 1: the products of K start; n and |n|.
    v1: DFF<bool>,
    bank1: DFF<bool>,
    id1: DFF<Bits<ID_W>>,
    ax1: DFF<Bits<COORD_W>>,
    ay1: DFF<Bits<COORD_W>>,
    bx1: DFF<Bits<COORD_W>>,
    by1: DFF<Bits<COORD_W>>,
    m_nax: Mul18,
    m_nay: Mul18,
    m_nbx: Mul18,
    m_nby: Mul18,
    m_aby: Mul18,
    m_abx: Mul18,
    m_fby: Mul18,
    m_fbx: Mul18,
    m_lay: Mul18,
    m_lax: Mul18,
    nx: Signal<Local, Bits<COORD_W>>,
    ny: Signal<Local, Bits<COORD_W>>,
    nx_neg: Signal<Local, Bits<COORD_W>>,
    ny_neg: Signal<Local, Bits<COORD_W>>,
    absnx: Signal<Local, Bits<COORD_W>>,
    absny: Signal<Local, Bits<COORD_W>>,
    // Stage 2: the products of dot(n_s, a), dot(n_s, b) start; nmax.
    v2: DFF<bool>,
    bank2: DFF<bool>,
    id2: DFF<Bits<ID_W>>,
    ax2: DFF<Bits<COORD_W>>,
    ay2: DFF<Bits<COORD_W>>,
    bx2: DFF<Bits<COORD_W>>,
    by2: DFF<Bits<COORD_W>>,
    absnx2: DFF<Bits<COORD_W>>,
    absny2: DFF<Bits<COORD_W>>,
    negx2: DFF<bool>,
    negy2: DFF<bool>,
    normal_x2: DFF<Bits<DIR_W>>,
    normal_y2: DFF<Bits<DIR_W>>,
    /// The normal again, for the products with `a` (no register drives two multipliers).
    normal_xa2: DFF<Bits<DIR_W>>,
    normal_ya2: DFF<Bits<DIR_W>>,
    nmax: Signal<Local, Bits<COORD_W>>,
    // Stage 3: the side products start; those of K arrive; nmax into its normaliser.
    v3: DFF<bool>,
    bank3: DFF<bool>,
    id3: DFF<Bits<ID_W>>,
    ax3: DFF<Bits<COORD_W>>,
    ay3: DFF<Bits<COORD_W>>,
    bx3: DFF<Bits<COORD_W>>,
    by3: DFF<Bits<COORD_W>>,
    absnx3: DFF<Bits<COORD_W>>,
    absny3: DFF<Bits<COORD_W>>,
    negx3: DFF<bool>,
    negy3: DFF<bool>,
    nmax3: DFF<Bits<COORD_W>>,
    // Stage 4: K; the products of dot(n_s, a), dot(n_s, b) arrive.
    v4: DFF<bool>,
    id4: DFF<Bits<ID_W>>,
    p_aby4: DFF<Bits<32>>,
    p_abx4: DFF<Bits<32>>,
    kk: Signal<Local, Bits<32>>,
    // Stage 5: 2K into its normaliser; the dot products; the side products arrive.
    v5: DFF<bool>,
    id5: DFF<Bits<ID_W>>,
    k5: DFF<Bits<32>>,
    p_nax5: DFF<Bits<32>>,
    p_nay5: DFF<Bits<32>>,
    p_nbx5: DFF<Bits<32>>,
    p_nby5: DFF<Bits<32>>,
    ha: Signal<Local, Bits<32>>,
    hb: Signal<Local, Bits<32>>,
    k2: Signal<Local, Bits<32>>,
    // Stage 6: the backward and back-facing screens; the side values.
    v6: DFF<bool>,
    id6: DFF<Bits<ID_W>>,
    /// `K ≤ 0` (signed), from stage 5's register: the back-facing test without a 32-bit
    /// compare in stage 6.
    k_nonpos6: DFF<bool>,
    ha6: DFF<Bits<32>>,
    hb6: DFF<Bits<32>>,
    p_fby6: DFF<Bits<32>>,
    p_fbx6: DFF<Bits<32>>,
    p_lay6: DFF<Bits<32>>,
    p_lax6: DFF<Bits<32>>,
    clz_n6: DFF<Bits<SH_W>>,
    norm_n6: DFF<Bits<32>>,
    ha_pos: Signal<Local, bool>,
    hb_pos: Signal<Local, bool>,
    is_backward: Signal<Local, bool>,
    is_back_facing: Signal<Local, bool>,
    side_f: Signal<Local, Bits<32>>,
    side_l: Signal<Local, Bits<32>>,
    // Stage 7: the exponent; the outside-the-sector screen.
    v7: DFF<bool>,
    id7: DFF<Bits<ID_W>>,
    side_f7: DFF<Bits<32>>,
    side_l7: DFF<Bits<32>>,
    clz_n7: DFF<Bits<SH_W>>,
    norm_n7: DFF<Bits<32>>,
    backward7: DFF<bool>,
    back_facing7: DFF<bool>,
    ha_open7: DFF<bool>,
    hb_open7: DFF<bool>,
    s0: Signal<Local, Bits<SH_W>>,
    s0_m1: Signal<Local, Bits<SH_W>>,
    n_hi: Signal<Local, Bits<COORD_W>>,
    e_hi: Signal<Local, Bits<COORD_W>>,
    e_lo_nz: Signal<Local, bool>,
    n_below_e: Signal<Local, bool>,
    side_f_x: Signal<Local, Bits<32>>,
    side_l_x: Signal<Local, Bits<32>>,
    /// The two outside compares by 16-bit halves, side by side: short carry chains into
    /// registers (the high halves' order and equality, the low halves' order), combined with
    /// the gates in stage 8 (`outside8`), instead of one 32-bit chain and the gates after it.
    f_hi_lt8: DFF<bool>,
    f_hi_eq8: DFF<bool>,
    f_lo_lt8: DFF<bool>,
    l_hi_gt8: DFF<bool>,
    l_hi_eq8: DFF<bool>,
    l_lo_gt8: DFF<bool>,
    ha_open8: DFF<bool>,
    hb_open8: DFF<bool>,
    // Stage 8: the verdict, the divider's inputs; the patch takes a slot.
    v8: DFF<bool>,
    id8: DFF<Bits<ID_W>>,
    /// The exponent's two candidates and the choice between them, registered apart (`exp8`
    /// is the choice): the normalised compare reaches a register through no multiplexer.
    s0_8: DFF<Bits<SH_W>>,
    s0_m1_8: DFF<Bits<SH_W>>,
    below8: DFF<bool>,
    /// What stage 8 asks of the exponent, for each candidate, from compares of the two
    /// leading-zero counts (no adder before them; both counts lie in 0…31, so `d = clz_n −
    /// clz_e` in −31…31): `near_a` is `s0 = d` near (below [`SH_MIN`]: `d ≤ −4`), `near_b` is
    /// `s0 − 1` near (`d ≤ −3`). Stage 8 chooses with `below8`.
    near_a8: DFF<bool>,
    near_b8: DFF<bool>,
    /// `s0 + 3`, the dividend's shift into [`DIVIDEND_BITS`] bits (see stage 8), from the
    /// registered `clz_n + 3`: one adder, beside `s0`'s.
    sp3_8: DFF<Bits<SH_W>>,
    /// `clz_n + 2`, `+ 3`, registered beside `clz_n7`.
    clz_n2_7: DFF<Bits<SH_W>>,
    clz_n3_7: DFF<Bits<SH_W>>,
    exp8: Signal<Local, Bits<SH_W>>,
    near8: Signal<Local, bool>,
    backward8: DFF<bool>,
    back_facing8: DFF<bool>,
    outside8: Signal<Local, bool>,
    is_near: Signal<Local, bool>,
    is_pass: Signal<Local, bool>,
    // Stage 9 (COUNT_LATENCY): the verdict of a valid patch, one flag per counter.
    pass9: DFF<bool>,
    backward9: DFF<bool>,
    back_facing9: DFF<bool>,
    outside9: DFF<bool>,
    near9: DFF<bool>,
    /// `|n_c|·2^(s0 + 3)` in [`DIVIDEND_BITS`] + 1 bits, then `|n_c|·2^(sh + 3)` (`sh` is `s0`
    /// or `s0 − 1`: a shift right by one when not `below8`).
    wide_x: Signal<Local, Bits<{ DIVIDEND_BITS + 1 }>>,
    wide_y: Signal<Local, Bits<{ DIVIDEND_BITS + 1 }>>,
    dividend_x: Signal<Local, Bits<DIVIDEND_BITS>>,
    dividend_y: Signal<Local, Bits<DIVIDEND_BITS>>,
    tag_p: Signal<Local, Bits<3>>,
    tag_x: Signal<Local, Bits<3>>,
    tag_y: Signal<Local, Bits<3>>,
    /// The stage-to-stage carry of what stages 4–7 only pass on: the coordinates and `|n|`'s
    /// magnitudes and signs from stage 3's registers, `K` from stage 5's, to stage 8.
    c_ax: Delay<Bits<COORD_W>, 5>,
    c_ay: Delay<Bits<COORD_W>, 5>,
    c_bx: Delay<Bits<COORD_W>, 5>,
    c_by: Delay<Bits<COORD_W>, 5>,
    c_absnx: Delay<Bits<COORD_W>, 5>,
    c_absny: Delay<Bits<COORD_W>, 5>,
    c_negx: Delay<bool, 5>,
    c_negy: Delay<bool, 5>,
    c_k: Delay<Bits<32>, 3>,
    /// The leading zeros of `nmax` (stages 3–4) and of `2K` (stages 5–6), normalised.
    lz_n: Normaliser,
    lz_e: Normaliser,
    // Stages 9–26: the divider; stage 26 writes W into the patch's slot.
    divider: PipeDivider,
    // Counters.
    c_passed: DFF<Bits<32>>,
    c_backward: DFF<Bits<32>>,
    c_back_facing: DFF<Bits<32>>,
    c_outside: DFF<Bits<32>>,
    c_near: DFF<Bits<32>>,
    // Constants.
    depth_m1_6: Constant<Bits<6>>,
    one6: Constant<Bits<6>>,
    one5: Constant<Bits<5>>,
    zero32: Constant<Bits<32>>,
    one32: Constant<Bits<32>>,
    msb32: Constant<Bits<32>>,
    thr_f_hi: Constant<Bits<16>>,
    thr_f_lo: Constant<Bits<16>>,
    thr_l_hi: Constant<Bits<16>>,
    thr_l_lo: Constant<Bits<16>>,
    zero14: Constant<Bits<14>>,
    zero3: Constant<Bits<3>>,
    sh1: Constant<Bits<32>>,
    c2_6: Constant<Bits<6>>,
    c3_6: Constant<Bits<6>>,
    tag_pass: Constant<Bits<3>>,
    tag_negx: Constant<Bits<3>>,
    tag_negy: Constant<Bits<3>>,
}

impl Default for Screener {
    fn default() -> Self {
        assert_eq!(1 << ADDR_BITS, DEPTH);
        assert!(DEPTH as u64 > LATENCY, "the credit limit must cover a patch's whole latency");
        Screener {
            clock: Default::default(),
            origin_x: Default::default(),
            origin_y: Default::default(),
            normal_x: Default::default(),
            normal_y: Default::default(),
            first_x: Default::default(),
            first_y: Default::default(),
            last_x: Default::default(),
            last_y: Default::default(),
            in_valid: Default::default(),
            in_ready: Default::default(),
            in_id: Default::default(),
            in_ax: Default::default(),
            in_ay: Default::default(),
            in_bx: Default::default(),
            in_by: Default::default(),
            in_bank: Default::default(),
            sector_read: Default::default(),
            sector_bank: Default::default(),
            normal_bank: Default::default(),
            out_valid: Default::default(),
            out_ready: Default::default(),
            out_id: Default::default(),
            out_ax: Default::default(),
            out_ay: Default::default(),
            out_bx: Default::default(),
            out_by: Default::default(),
            out_wx: Default::default(),
            out_wy: Default::default(),
            out_sh: Default::default(),
            out_pass: Default::default(),
            passed: Default::default(),
            backward: Default::default(),
            back_facing: Default::default(),
            outside: Default::default(),
            near: Default::default(),
            used: Default::default(),
            res_ptr: Default::default(),
            fifo: Default::default(),
            lane_id: Default::default(),
            lane_ax: Default::default(),
            lane_ay: Default::default(),
            lane_bx: Default::default(),
            lane_by: Default::default(),
            lane_sh: Default::default(),
            sh_pass: Default::default(),
            pass_flag: Constant::new(0x40u64.into()),
            lane_wx: Default::default(),
            lane_wy: Default::default(),
            room: Default::default(),
            used_next: Default::default(),
            full: Default::default(),
            take: Default::default(),
            pop: Default::default(),
            reserve: Default::default(),
            fill: Default::default(),
            used_inc: Default::default(),
            used_dec: Default::default(),
            res_inc: Default::default(),
            ext_ox: Default::default(),
            ext_oy: Default::default(),
            ext_ax: Default::default(),
            ext_ay: Default::default(),
            ext_bx: Default::default(),
            ext_by: Default::default(),
            v1: Default::default(),
            bank1: Default::default(),
            id1: Default::default(),
            ax1: Default::default(),
            ay1: Default::default(),
            bx1: Default::default(),
            by1: Default::default(),
            m_nax: Default::default(),
            m_nay: Default::default(),
            m_nbx: Default::default(),
            m_nby: Default::default(),
            m_aby: Default::default(),
            m_abx: Default::default(),
            m_fby: Default::default(),
            m_fbx: Default::default(),
            m_lay: Default::default(),
            m_lax: Default::default(),
            nx: Default::default(),
            ny: Default::default(),
            nx_neg: Default::default(),
            ny_neg: Default::default(),
            absnx: Default::default(),
            absny: Default::default(),
            v2: Default::default(),
            bank2: Default::default(),
            id2: Default::default(),
            ax2: Default::default(),
            ay2: Default::default(),
            bx2: Default::default(),
            by2: Default::default(),
            absnx2: Default::default(),
            absny2: Default::default(),
            negx2: Default::default(),
            negy2: Default::default(),
            normal_x2: Default::default(),
            normal_y2: Default::default(),
            normal_xa2: Default::default(),
            normal_ya2: Default::default(),
            nmax: Default::default(),
            v3: Default::default(),
            bank3: Default::default(),
            id3: Default::default(),
            ax3: Default::default(),
            ay3: Default::default(),
            bx3: Default::default(),
            by3: Default::default(),
            absnx3: Default::default(),
            absny3: Default::default(),
            negx3: Default::default(),
            negy3: Default::default(),
            nmax3: Default::default(),
            v4: Default::default(),
            id4: Default::default(),
            p_aby4: Default::default(),
            p_abx4: Default::default(),
            kk: Default::default(),
            v5: Default::default(),
            id5: Default::default(),
            k5: Default::default(),
            p_nax5: Default::default(),
            p_nay5: Default::default(),
            p_nbx5: Default::default(),
            p_nby5: Default::default(),
            ha: Default::default(),
            hb: Default::default(),
            k2: Default::default(),
            v6: Default::default(),
            id6: Default::default(),
            k_nonpos6: Default::default(),
            ha6: Default::default(),
            hb6: Default::default(),
            p_fby6: Default::default(),
            p_fbx6: Default::default(),
            p_lay6: Default::default(),
            p_lax6: Default::default(),
            clz_n6: Default::default(),
            norm_n6: Default::default(),
            ha_pos: Default::default(),
            hb_pos: Default::default(),
            is_backward: Default::default(),
            is_back_facing: Default::default(),
            side_f: Default::default(),
            side_l: Default::default(),
            v7: Default::default(),
            id7: Default::default(),
            side_f7: Default::default(),
            side_l7: Default::default(),
            clz_n7: Default::default(),
            norm_n7: Default::default(),
            backward7: Default::default(),
            back_facing7: Default::default(),
            ha_open7: Default::default(),
            hb_open7: Default::default(),
            s0: Default::default(),
            s0_m1: Default::default(),
            n_hi: Default::default(),
            e_hi: Default::default(),
            e_lo_nz: Default::default(),
            n_below_e: Default::default(),
            side_f_x: Default::default(),
            side_l_x: Default::default(),
            f_hi_lt8: Default::default(),
            f_hi_eq8: Default::default(),
            f_lo_lt8: Default::default(),
            l_hi_gt8: Default::default(),
            l_hi_eq8: Default::default(),
            l_lo_gt8: Default::default(),
            ha_open8: Default::default(),
            hb_open8: Default::default(),
            v8: Default::default(),
            id8: Default::default(),
            s0_8: Default::default(),
            s0_m1_8: Default::default(),
            below8: Default::default(),
            near_a8: Default::default(),
            near_b8: Default::default(),
            sp3_8: Default::default(),
            wide_x: Default::default(),
            wide_y: Default::default(),
            dividend_x: Default::default(),
            dividend_y: Default::default(),
            clz_n2_7: Default::default(),
            clz_n3_7: Default::default(),
            near8: Default::default(),
            exp8: Default::default(),
            backward8: Default::default(),
            back_facing8: Default::default(),
            outside8: Default::default(),
            is_near: Default::default(),
            is_pass: Default::default(),
            pass9: Default::default(),
            backward9: Default::default(),
            back_facing9: Default::default(),
            outside9: Default::default(),
            near9: Default::default(),
            tag_p: Default::default(),
            tag_x: Default::default(),
            tag_y: Default::default(),
            c_ax: Default::default(),
            c_ay: Default::default(),
            c_bx: Default::default(),
            c_by: Default::default(),
            c_absnx: Default::default(),
            c_absny: Default::default(),
            c_negx: Default::default(),
            c_negy: Default::default(),
            c_k: Default::default(),
            divider: Default::default(),
            lz_n: Default::default(),
            lz_e: Default::default(),
            c_passed: Default::default(),
            c_backward: Default::default(),
            c_back_facing: Default::default(),
            c_outside: Default::default(),
            c_near: Default::default(),
            depth_m1_6: Constant::new((DEPTH as u64 - 1).into()),
            one6: Constant::new(1u64.into()),
            one5: Constant::new(1u64.into()),
            zero32: Constant::new(0u64.into()),
            one32: Constant::new(1u64.into()),
            msb32: Constant::new(SIGN32.into()),
            thr_f_hi: Constant::new(((SIGN32 - SECTOR_MARGIN as u64) >> 16).into()),
            thr_f_lo: Constant::new(((SIGN32 - SECTOR_MARGIN as u64) & 0xFFFF).into()),
            thr_l_hi: Constant::new(((SIGN32 + SECTOR_MARGIN as u64) >> 16).into()),
            thr_l_lo: Constant::new(((SIGN32 + SECTOR_MARGIN as u64) & 0xFFFF).into()),
            zero14: Constant::new(0u64.into()),
            zero3: Constant::new(0u64.into()),
            sh1: Constant::new(1u64.into()),
            c2_6: Constant::new(2u64.into()),
            c3_6: Constant::new(3u64.into()),
            tag_pass: Constant::new(1u64.into()),
            tag_negx: Constant::new(2u64.into()),
            tag_negy: Constant::new(4u64.into()),
        }
    }
}

impl Screener {
    /// Patches in flight, `0..=DEPTH`: accepted and not yet out
    /// (the credit count; `in_ready` is low from the cycle it reaches [`DEPTH`]): for
    /// testbenches.
    pub fn in_flight(&self) -> usize {
        self.used.q.val().index()
    }

    /// Patches whose slot is complete in the output FIFO and has not left yet: for
    /// testbenches.
    pub fn buffered(&self) -> usize {
        self.fifo.count.val().index()
    }
}

impl Logic for Screener {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            used,
            full,
            res_ptr,
            v1,
            bank1,
            id1,
            ax1,
            ay1,
            bx1,
            by1,
            v2,
            bank2,
            id2,
            ax2,
            ay2,
            bx2,
            by2,
            absnx2,
            absny2,
            negx2,
            negy2,
            normal_x2,
            normal_y2,
            normal_xa2,
            normal_ya2,
            v3,
            bank3,
            id3,
            ax3,
            ay3,
            bx3,
            by3,
            absnx3,
            absny3,
            negx3,
            negy3,
            nmax3,
            v4,
            id4,
            p_aby4,
            p_abx4,
            v5,
            id5,
            k5,
            p_nax5,
            p_nay5,
            p_nbx5,
            p_nby5,
            v6,
            id6,
            k_nonpos6,
            ha6,
            hb6,
            p_fby6,
            p_fbx6,
            p_lay6,
            p_lax6,
            clz_n6,
            norm_n6,
            v7,
            id7,
            side_f7,
            side_l7,
            clz_n7,
            norm_n7,
            backward7,
            back_facing7,
            ha_open7,
            hb_open7,
            v8,
            id8,
            s0_8,
            s0_m1_8,
            below8,
            near_a8,
            near_b8,
            sp3_8,
            clz_n2_7,
            clz_n3_7,
            backward8,
            back_facing8,
            f_hi_lt8,
            f_hi_eq8,
            f_lo_lt8,
            l_hi_gt8,
            l_hi_eq8,
            l_lo_gt8,
            ha_open8,
            hb_open8,
            pass9,
            backward9,
            back_facing9,
            outside9,
            near9,
            c_passed,
            c_backward,
            c_back_facing,
            c_outside,
            c_near
        );
        self.fifo.clock.next = self.clock.val();
        self.m_nax.clock.next = self.clock.val();
        self.m_nay.clock.next = self.clock.val();
        self.m_nbx.clock.next = self.clock.val();
        self.m_nby.clock.next = self.clock.val();
        self.m_aby.clock.next = self.clock.val();
        self.m_abx.clock.next = self.clock.val();
        self.m_fby.clock.next = self.clock.val();
        self.m_fbx.clock.next = self.clock.val();
        self.m_lay.clock.next = self.clock.val();
        self.m_lax.clock.next = self.clock.val();
        self.c_ax.clock.next = self.clock.val();
        self.c_ay.clock.next = self.clock.val();
        self.c_bx.clock.next = self.clock.val();
        self.c_by.clock.next = self.clock.val();
        self.c_absnx.clock.next = self.clock.val();
        self.c_absny.clock.next = self.clock.val();
        self.c_negx.clock.next = self.clock.val();
        self.c_negy.clock.next = self.clock.val();
        self.c_k.clock.next = self.clock.val();
        self.divider.clock.next = self.clock.val();
        self.lz_n.clock.next = self.clock.val();
        self.lz_e.clock.next = self.clock.val();
        self.lane_id.clock.next = self.clock.val();
        self.lane_ax.clock.next = self.clock.val();
        self.lane_ay.clock.next = self.clock.val();
        self.lane_bx.clock.next = self.clock.val();
        self.lane_by.clock.next = self.clock.val();
        self.lane_sh.clock.next = self.clock.val();
        self.lane_wx.clock.next = self.clock.val();
        self.lane_wy.clock.next = self.clock.val();

        // Stage 0: a patch is accepted while fewer than DEPTH are in flight (`full`, a
        // register: no path from out_ready to in_ready). Its coordinates relative to the origin
        // (18 bits, exact) enter the pipeline, which never stalls.
        self.room.next = !self.full.q.val();
        self.in_ready.next = self.room.val();
        self.take.next = self.in_valid.val() & self.room.val();
        self.ext_ox.next = bit_cast::<COORD_W, WORLD_W>(self.origin_x.val());
        self.ext_oy.next = bit_cast::<COORD_W, WORLD_W>(self.origin_y.val());
        self.ext_ax.next = bit_cast::<COORD_W, WORLD_W>(self.in_ax.val());
        self.ext_ay.next = bit_cast::<COORD_W, WORLD_W>(self.in_ay.val());
        self.ext_bx.next = bit_cast::<COORD_W, WORLD_W>(self.in_bx.val());
        self.ext_by.next = bit_cast::<COORD_W, WORLD_W>(self.in_by.val());
        self.v1.d.next = self.take.val();
        self.bank1.d.next = self.in_bank.val();
        self.id1.d.next = self.in_id.val();
        self.ax1.d.next = self.ext_ax.val() - self.ext_ox.val();
        self.ay1.d.next = self.ext_ay.val() - self.ext_oy.val();
        self.bx1.d.next = self.ext_bx.val() - self.ext_ox.val();
        self.by1.d.next = self.ext_by.val() - self.ext_oy.val();

        // Stage 1: the products start in three groups, one stage apart, so that every
        // multiplier's operand register is a stage register of its own (no register drives two
        // multipliers): those of K now, those of the dot products with n_s in stage 2, the side
        // products in stage 3 (the source's setup is held meanwhile). n = (b.y − a.y, a.x − b.x)
        // = (B.y − A.y, A.x − B.x), so |n_c| < 2^17, and its magnitudes (each negation as the
        // reversed difference, in parallel: the same 18 bits as 0 − n_c).
        self.m_aby.a.next = self.ax1.q.val();
        self.m_aby.b.next = self.by1.q.val();
        self.m_abx.a.next = self.ay1.q.val();
        self.m_abx.b.next = self.bx1.q.val();
        self.nx.next = self.by1.q.val() - self.ay1.q.val();
        self.ny.next = self.ax1.q.val() - self.bx1.q.val();
        self.nx_neg.next = self.ay1.q.val() - self.by1.q.val();
        self.ny_neg.next = self.bx1.q.val() - self.ax1.q.val();
        self.absnx.next = self.nx.val();
        if self.nx.val().get_bit(17) {
            self.absnx.next = self.nx_neg.val();
        }
        self.absny.next = self.ny.val();
        if self.ny.val().get_bit(17) {
            self.absny.next = self.ny_neg.val();
        }
        self.v2.d.next = self.v1.q.val();
        self.bank2.d.next = self.bank1.q.val();
        self.id2.d.next = self.id1.q.val();
        self.ax2.d.next = self.ax1.q.val();
        self.ay2.d.next = self.ay1.q.val();
        self.bx2.d.next = self.bx1.q.val();
        self.by2.d.next = self.by1.q.val();
        self.absnx2.d.next = self.absnx.val();
        self.absny2.d.next = self.absny.val();
        self.negx2.d.next = self.nx.val().get_bit(17);
        self.negy2.d.next = self.ny.val().get_bit(17);
        self.normal_bank.next = self.bank1.q.val();
        self.normal_x2.d.next = self.normal_x.val();
        self.normal_y2.d.next = self.normal_y.val();
        self.normal_xa2.d.next = self.normal_x.val();
        self.normal_ya2.d.next = self.normal_y.val();

        // Stage 2: the products of dot(n_s, a) and dot(n_s, b) start (the normal read in stage
        // 1, in two registers of its own, one for a and one for b); nmax = max(|n_x|, |n_y|).
        self.m_nax.a.next = self.normal_xa2.q.val();
        self.m_nax.b.next = self.ax2.q.val();
        self.m_nay.a.next = self.normal_ya2.q.val();
        self.m_nay.b.next = self.ay2.q.val();
        self.m_nbx.a.next = self.normal_x2.q.val();
        self.m_nbx.b.next = self.bx2.q.val();
        self.m_nby.a.next = self.normal_y2.q.val();
        self.m_nby.b.next = self.by2.q.val();
        self.nmax.next = self.absny2.q.val();
        if self.absnx2.q.val() > self.absny2.q.val() {
            self.nmax.next = self.absnx2.q.val();
        }
        self.v3.d.next = self.v2.q.val();
        self.bank3.d.next = self.bank2.q.val();
        self.id3.d.next = self.id2.q.val();
        self.ax3.d.next = self.ax2.q.val();
        self.ay3.d.next = self.ay2.q.val();
        self.bx3.d.next = self.bx2.q.val();
        self.by3.d.next = self.by2.q.val();
        self.absnx3.d.next = self.absnx2.q.val();
        self.absny3.d.next = self.absny2.q.val();
        self.negx3.d.next = self.negx2.q.val();
        self.negy3.d.next = self.negy2.q.val();
        self.nmax3.d.next = self.nmax.val();

        // Stage 3: the side products start, from the sector of the patch's bank (shown on
        // `sector_bank`: the setup's `first`/`last` are read now); the products of K arrive
        // and are registered once more, as they are (the multiplier's product register drives
        // nothing else). nmax (as 32 bits) enters its normaliser (`lz_n`, stages 3–4: its
        // leading zeros and nmax shifted by them, its leading one at bit 31).
        self.sector_read.next = self.v3.q.val();
        self.sector_bank.next = self.bank3.q.val();
        self.m_fby.a.next = self.first_x.val();
        self.m_fby.b.next = self.by3.q.val();
        self.m_fbx.a.next = self.first_y.val();
        self.m_fbx.b.next = self.bx3.q.val();
        self.m_lay.a.next = self.last_x.val();
        self.m_lay.b.next = self.ay3.q.val();
        self.m_lax.a.next = self.last_y.val();
        self.m_lax.b.next = self.ax3.q.val();
        self.p_aby4.d.next = self.m_aby.p.val();
        self.p_abx4.d.next = self.m_abx.p.val();
        self.lz_n.value.next = bit_cast::<32, COORD_W>(self.nmax3.q.val());
        self.c_ax.d.next = self.ax3.q.val();
        self.c_ay.d.next = self.ay3.q.val();
        self.c_bx.d.next = self.bx3.q.val();
        self.c_by.d.next = self.by3.q.val();
        self.c_absnx.d.next = self.absnx3.q.val();
        self.c_absny.d.next = self.absny3.q.val();
        self.c_negx.d.next = self.negx3.q.val();
        self.c_negy.d.next = self.negy3.q.val();
        self.v4.d.next = self.v3.q.val();
        self.id4.d.next = self.id3.q.val();

        // Stage 4: K; the products of the dot products arrive and are registered.
        self.kk.next = self.p_aby4.q.val() - self.p_abx4.q.val();
        self.p_nax5.d.next = self.m_nax.p.val();
        self.p_nay5.d.next = self.m_nay.p.val();
        self.p_nbx5.d.next = self.m_nbx.p.val();
        self.p_nby5.d.next = self.m_nby.p.val();
        self.v5.d.next = self.v4.q.val();
        self.id5.d.next = self.id4.q.val();
        self.k5.d.next = self.kk.val();

        // Stage 5: 2K enters its normaliser (`lz_e`, stages 5–6; K < 2^31 when it passes, so
        // 2K fits 32 bits); dot(n_s, a), dot(n_s, b); the side products arrive and are
        // registered; nmax's normaliser's results are registered once more.
        self.k2.next = self.k5.q.val() << self.sh1.val();
        self.lz_e.value.next = self.k2.val();
        self.c_k.d.next = self.k5.q.val();
        self.ha.next = self.p_nax5.q.val() + self.p_nay5.q.val();
        self.hb.next = self.p_nbx5.q.val() + self.p_nby5.q.val();
        self.p_fby6.d.next = self.m_fby.p.val();
        self.p_fbx6.d.next = self.m_fbx.p.val();
        self.p_lay6.d.next = self.m_lay.p.val();
        self.p_lax6.d.next = self.m_lax.p.val();
        self.v6.d.next = self.v5.q.val();
        self.id6.d.next = self.id5.q.val();
        self.k_nonpos6.d.next = self.k5.q.val().get_bit(31) | (self.k5.q.val() == self.zero32.val());
        self.ha6.d.next = self.ha.val();
        self.hb6.d.next = self.hb.val();
        self.clz_n6.d.next = self.lz_n.clz.val();
        self.norm_n6.d.next = self.lz_n.norm.val();

        // Stage 6: the backward and back-facing screens, by priority; the side values against
        // the sector's edges.
        self.ha_pos.next = !self.ha6.q.val().get_bit(31) & (self.ha6.q.val() != self.zero32.val());
        self.hb_pos.next = !self.hb6.q.val().get_bit(31) & (self.hb6.q.val() != self.zero32.val());
        self.is_backward.next = !self.ha_pos.val() & !self.hb_pos.val();
        self.is_back_facing.next = !self.is_backward.val() & self.k_nonpos6.q.val();
        self.side_f.next = self.p_fby6.q.val() - self.p_fbx6.q.val();
        self.side_l.next = self.p_lay6.q.val() - self.p_lax6.q.val();
        self.v7.d.next = self.v6.q.val();
        self.id7.d.next = self.id6.q.val();
        self.clz_n7.d.next = self.clz_n6.q.val();
        self.clz_n2_7.d.next = self.clz_n6.q.val() + self.c2_6.val();
        self.clz_n3_7.d.next = self.clz_n6.q.val() + self.c3_6.val();
        self.norm_n7.d.next = self.norm_n6.q.val();
        self.backward7.d.next = self.is_backward.val();
        self.back_facing7.d.next = self.is_back_facing.val();
        // The outside screen's gates, with "neither backward nor back-facing" folded in here
        // (a positive h is not backward, so then back-facing is k ≤ 0), so that stage 7 has one
        // LUT after its comparisons.
        self.ha_open7.d.next = self.ha_pos.val() & !self.k_nonpos6.q.val();
        self.hb_open7.d.next = self.hb_pos.val() & !self.k_nonpos6.q.val();
        self.side_f7.d.next = self.side_f.val();
        self.side_l7.d.next = self.side_l.val();

        // Stage 7: the exponent. With s0 = clz(nmax) − clz(2K), nmax·2^s0 and 2K share their
        // leading one: the largest sh with nmax·2^sh < 2K is s0 when the normalised nmax is
        // below the normalised 2K, else s0 − 1. It lies in [−17, 31]; below −3 the patch is
        // near. Both candidates, the compare and what stage 8 asks of each candidate are
        // registered; stage 8 chooses (`exp8`, `near8`, `is_m1` …), so the compare's carry
        // chain reaches a register directly (through the exponent's multiplexer it was the
        // screener's critical path) and stage 8's verdict and shifts are one gate deeper only. The outside-the-sector screen: signed
        // comparisons with the margin as unsigned ones on the sign-flipped values.
        self.s0.next = self.clz_n7.q.val() - self.lz_e.clz.val();
        // s0 − 1 = clz_n + !clz_e (mod 64): one adder from the registers, beside s0's.
        self.s0_m1.next = self.clz_n7.q.val() + !self.lz_e.clz.val();
        // The normalised nmax (18 significant bits) has its low 14 bits zero, so it is below
        // the normalised 2K exactly when its top 18 bits are below 2K's, or equal to them with
        // 2K's low 14 bits not all zero: an 18-bit carry chain instead of a 32-bit one.
        self.n_hi.next = self.norm_n7.q.val().get_bits::<18>(14);
        self.e_hi.next = self.lz_e.norm.val().get_bits::<18>(14);
        self.e_lo_nz.next = self.lz_e.norm.val().get_bits::<14>(0) != self.zero14.val();
        self.n_below_e.next =
            (self.n_hi.val() < self.e_hi.val()) | ((self.n_hi.val() == self.e_hi.val()) & self.e_lo_nz.val());
        self.side_f_x.next = self.side_f7.q.val() ^ self.msb32.val();
        self.side_l_x.next = self.side_l7.q.val() ^ self.msb32.val();
        self.f_hi_lt8.d.next = self.side_f_x.val().get_bits::<16>(16) < self.thr_f_hi.val();
        self.f_hi_eq8.d.next = self.side_f_x.val().get_bits::<16>(16) == self.thr_f_hi.val();
        self.f_lo_lt8.d.next = self.side_f_x.val().get_bits::<16>(0) < self.thr_f_lo.val();
        self.l_hi_gt8.d.next = self.side_l_x.val().get_bits::<16>(16) > self.thr_l_hi.val();
        self.l_hi_eq8.d.next = self.side_l_x.val().get_bits::<16>(16) == self.thr_l_hi.val();
        self.l_lo_gt8.d.next = self.side_l_x.val().get_bits::<16>(0) > self.thr_l_lo.val();
        self.ha_open8.d.next = self.ha_open7.q.val();
        self.hb_open8.d.next = self.hb_open7.q.val();
        self.v8.d.next = self.v7.q.val();
        self.id8.d.next = self.id7.q.val();
        self.backward8.d.next = self.backward7.q.val();
        self.back_facing8.d.next = self.back_facing7.q.val();
        self.s0_8.d.next = self.s0.val();
        self.s0_m1_8.d.next = self.s0_m1.val();
        self.below8.d.next = self.n_below_e.val();
        self.sp3_8.d.next = self.clz_n3_7.q.val() - self.lz_e.clz.val();
        self.near_a8.d.next = self.clz_n3_7.q.val() < self.lz_e.clz.val();
        self.near_b8.d.next = self.clz_n2_7.q.val() < self.lz_e.clz.val();

        // Stage 8 (VERDICT_LATENCY): the outside and near screens and the verdict, counted; the
        // patch takes the next slot of the output FIFO and enters the divider.
        self.outside8.next = (self.hb_open8.q.val()
            & (self.f_hi_lt8.q.val() | (self.f_hi_eq8.q.val() & self.f_lo_lt8.q.val())))
            | (self.ha_open8.q.val()
                & (self.l_hi_gt8.q.val() | (self.l_hi_eq8.q.val() & self.l_lo_gt8.q.val())));
        self.exp8.next = self.s0_m1_8.q.val();
        if self.below8.q.val() {
            self.exp8.next = self.s0_8.q.val();
        }
        // sh = s0 − 1 = d − 1: near at d ≤ −3; sh = s0 = d: near at d ≤ −4.
        self.near8.next = self.near_b8.q.val();
        if self.below8.q.val() {
            self.near8.next = self.near_a8.q.val();
        }
        self.is_near.next =
            !self.backward8.q.val() & !self.back_facing8.q.val() & !self.outside8.val() & self.near8.val();
        self.is_pass.next =
            !self.backward8.q.val() & !self.back_facing8.q.val() & !self.outside8.val() & !self.is_near.val();
        self.reserve.next = self.v8.q.val();
        self.pass9.d.next = self.v8.q.val() & self.is_pass.val();
        self.backward9.d.next = self.v8.q.val() & self.backward8.q.val();
        self.back_facing9.d.next = self.v8.q.val() & self.back_facing8.q.val();
        self.outside9.d.next = self.v8.q.val() & self.outside8.val();
        self.near9.d.next = self.v8.q.val() & self.is_near.val();
        // Stage 9 (COUNT_LATENCY): the verdict counted, a cycle after it is decided, so that
        // the counters' 160 clock enables hang off five registers, not off the verdict's logic.
        if self.pass9.q.val() {
            self.c_passed.d.next = self.c_passed.q.val() + self.one32.val();
        }
        if self.backward9.q.val() {
            self.c_backward.d.next = self.c_backward.q.val() + self.one32.val();
        }
        if self.back_facing9.q.val() {
            self.c_back_facing.d.next = self.c_back_facing.q.val() + self.one32.val();
        }
        if self.outside9.q.val() {
            self.c_outside.d.next = self.c_outside.q.val() + self.one32.val();
        }
        if self.near9.q.val() {
            self.c_near.d.next = self.c_near.q.val() + self.one32.val();
        }
        self.passed.next = self.c_passed.q.val();
        self.backward.next = self.c_backward.q.val();
        self.back_facing.next = self.c_back_facing.q.val();
        self.outside.next = self.c_outside.q.val();
        self.near.next = self.c_near.q.val();
        // The dividend floor(|n_c|·2^sh)·2^16 + (bits shifted out)·2^13: the initial remainder
        // (below 2K) and, for sh < 0, the bits shifted out of |n_c|, fed in MSB first.
        // For sh in −3…31 (every patch that may pass) that is |n_c|·2^(sh + 3) in
        // DIVIDEND_BITS bits, shifted left by s0 + 3 (a register) and right by one when sh is
        // s0 − 1: `below8` reaches the divider through one multiplexer, after the shifter, and
        // the three short shifts right (sh = −1, −2, −3) are the same shifter's.
        self.wide_x.next =
            bit_cast::<{ DIVIDEND_BITS + 1 }, COORD_W>(self.c_absnx.q.val()) << self.sp3_8.q.val();
        self.wide_y.next =
            bit_cast::<{ DIVIDEND_BITS + 1 }, COORD_W>(self.c_absny.q.val()) << self.sp3_8.q.val();
        self.dividend_x.next = self.wide_x.val().get_bits::<DIVIDEND_BITS>(1);
        self.dividend_y.next = self.wide_y.val().get_bits::<DIVIDEND_BITS>(1);
        if self.below8.q.val() {
            self.dividend_x.next = self.wide_x.val().get_bits::<DIVIDEND_BITS>(0);
            self.dividend_y.next = self.wide_y.val().get_bits::<DIVIDEND_BITS>(0);
        }
        self.divider.rx.next = self.dividend_x.val().get_bits::<32>(3);
        self.divider.ry.next = self.dividend_y.val().get_bits::<32>(3);
        self.divider.fx.next = self.dividend_x.val().get_bits::<3>(0);
        self.divider.fy.next = self.dividend_y.val().get_bits::<3>(0);
        self.divider.k.next = self.c_k.q.val();
        // The tag the divider carries: a slot to complete (bit 0), the signs of n (bits 1 and 2).
        self.tag_p.next = self.zero3.val();
        if self.reserve.val() {
            self.tag_p.next = self.tag_pass.val();
        }
        self.tag_x.next = self.zero3.val();
        if self.c_negx.q.val() {
            self.tag_x.next = self.tag_negx.val();
        }
        self.tag_y.next = self.zero3.val();
        if self.c_negy.q.val() {
            self.tag_y.next = self.tag_negy.val();
        }
        self.divider.tag.next = self.tag_p.val() | self.tag_x.val() | self.tag_y.val();
        // Every patch takes the next slot of the output FIFO: id, a, b, sh and the verdict now,
        // W when the divider delivers it.
        self.lane_id.write_address.next = self.res_ptr.q.val();
        self.lane_ax.write_address.next = self.res_ptr.q.val();
        self.lane_ay.write_address.next = self.res_ptr.q.val();
        self.lane_bx.write_address.next = self.res_ptr.q.val();
        self.lane_by.write_address.next = self.res_ptr.q.val();
        self.lane_sh.write_address.next = self.res_ptr.q.val();
        self.lane_id.write_data.next = self.id8.q.val();
        self.lane_ax.write_data.next = self.c_ax.q.val();
        self.lane_ay.write_data.next = self.c_ay.q.val();
        self.lane_bx.write_data.next = self.c_bx.q.val();
        self.lane_by.write_data.next = self.c_by.q.val();
        self.sh_pass.next = bit_cast::<7, 6>(self.exp8.val());
        if self.is_pass.val() {
            self.sh_pass.next = bit_cast::<7, 6>(self.exp8.val()) | self.pass_flag.val();
        }
        self.lane_sh.write_data.next = self.sh_pass.val();
        self.lane_id.write_enable.next = self.reserve.val();
        self.lane_ax.write_enable.next = self.reserve.val();
        self.lane_ay.write_enable.next = self.reserve.val();
        self.lane_bx.write_enable.next = self.reserve.val();
        self.lane_by.write_enable.next = self.reserve.val();
        self.lane_sh.write_enable.next = self.reserve.val();
        self.res_inc.next = self.res_ptr.q.val() + self.one5.val();
        if self.reserve.val() {
            self.res_ptr.d.next = self.res_inc.val();
        }

        // Stage 26: the quotients of a patch arrive (slots fill in the order they were
        // taken: the divider's latency is fixed); W = sign(n)·q, signed by the divider,
        // completes the slot.
        self.fill.next = self.divider.tag_out.val().get_bit(0);
        self.lane_wx.write_address.next = self.fifo.tail_address.val();
        self.lane_wy.write_address.next = self.fifo.tail_address.val();
        self.lane_wx.write_data.next = self.divider.wx.val();
        self.lane_wy.write_data.next = self.divider.wy.val();
        self.lane_wx.write_enable.next = self.fill.val();
        self.lane_wy.write_enable.next = self.fill.val();
        self.fifo.push.next = self.fill.val();

        // Output: every cycle the lanes read the head slot (rd_ptr) and the one after it
        // (rd_ptr + 1) into their read registers and show the second after a pop
        // ([`FifoRam`]): no read address depends on out_ready. out_valid is set for the next
        // cycle when a complete slot remains after this cycle's pop, excluding this cycle's
        // fill (the lanes read before they write).
        self.pop.next = self.fifo.valid.val() & self.out_ready.val();
        self.fifo.pop.next = self.pop.val();
        self.lane_id.head_address.next = self.fifo.head_address.val();
        self.lane_id.next_address.next = self.fifo.next_address.val();
        self.lane_id.pop.next = self.pop.val();
        self.lane_ax.head_address.next = self.fifo.head_address.val();
        self.lane_ax.next_address.next = self.fifo.next_address.val();
        self.lane_ax.pop.next = self.pop.val();
        self.lane_ay.head_address.next = self.fifo.head_address.val();
        self.lane_ay.next_address.next = self.fifo.next_address.val();
        self.lane_ay.pop.next = self.pop.val();
        self.lane_bx.head_address.next = self.fifo.head_address.val();
        self.lane_bx.next_address.next = self.fifo.next_address.val();
        self.lane_bx.pop.next = self.pop.val();
        self.lane_by.head_address.next = self.fifo.head_address.val();
        self.lane_by.next_address.next = self.fifo.next_address.val();
        self.lane_by.pop.next = self.pop.val();
        self.lane_sh.head_address.next = self.fifo.head_address.val();
        self.lane_sh.next_address.next = self.fifo.next_address.val();
        self.lane_sh.pop.next = self.pop.val();
        self.lane_wx.head_address.next = self.fifo.head_address.val();
        self.lane_wx.next_address.next = self.fifo.next_address.val();
        self.lane_wx.pop.next = self.pop.val();
        self.lane_wy.head_address.next = self.fifo.head_address.val();
        self.lane_wy.next_address.next = self.fifo.next_address.val();
        self.lane_wy.pop.next = self.pop.val();
        self.out_valid.next = self.fifo.valid.val();
        self.out_id.next = self.lane_id.read_data.val();
        self.out_ax.next = self.lane_ax.read_data.val();
        self.out_ay.next = self.lane_ay.read_data.val();
        self.out_bx.next = self.lane_bx.read_data.val();
        self.out_by.next = self.lane_by.read_data.val();
        self.out_sh.next = bit_cast::<6, 7>(self.lane_sh.read_data.val());
        self.out_pass.next = self.lane_sh.read_data.val().get_bit(6);
        self.out_wx.next = self.lane_wx.read_data.val();
        self.out_wy.next = self.lane_wy.read_data.val();

        // Counters of the credit scheme: `used` counts a patch from its acceptance until it
        // leaves; the FIFO control's `count` counts complete slots not yet out.
        self.used_inc.next = self.used.q.val() + self.one6.val();
        self.used_dec.next = self.used.q.val() - self.one6.val();
        self.used_next.next = self.used.q.val();
        if self.take.val() & !self.pop.val() {
            self.used_next.next = self.used_inc.val();
        }
        if !self.take.val() & self.pop.val() {
            self.used_next.next = self.used_dec.val();
        }
        self.used.d.next = self.used_next.val();
        // `used_next == DEPTH` from the register's compares, chosen by the handshakes, so that
        // `out_ready` reaches `full` through the choice only, not through the count's adder and
        // compare: a take alone fills it from DEPTH − 1, a pop alone empties a slot, else it
        // stays.
        self.full.d.next = self.full.q.val();
        if self.take.val() & !self.pop.val() {
            self.full.d.next = self.used.q.val() == self.depth_m1_6.val();
        }
        if !self.take.val() & self.pop.val() {
            self.full.d.next = false;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Stage 8's flags from the leading-zero counts (`near_a8`, `near_b8`) are what the exponent
    /// itself says (near: bit 5 set and below `SH_MIN` unsigned) for every pair of counts the
    /// normalisers give (0…31 each) and both candidates.
    #[test]
    fn exponent_flags_from_the_counts_are_the_exponents() {
        let six = |v: i64| (v & 63) as u64;
        let lo = six(SH_MIN as i64);
        for n in 0..32i64 {
            for e in 0..32i64 {
                let (s0, s0_m1) = (six(n - e), six(n - e - 1));
                let near = |x: u64| x & 32 != 0 && x < lo;
                assert_eq!(near(s0), n + 3 < e, "s0, clz {n}, {e}");
                assert_eq!(near(s0_m1), n + 2 < e, "s0 - 1, clz {n}, {e}");
            }
        }
    }

    /// Stage 8's dividend, `|n_c|` shifted left by `s0 + 3` in `DIVIDEND_BITS + 1` bits and
    /// right by one when `sh = s0 − 1`, is `floor(|n_c|·2^sh)` (modulo 2³²) above the bits a
    /// shift right moves out, for every `sh` a passing patch may have (−3…31) and both
    /// candidates.
    #[test]
    fn one_shifter_forms_the_dividend_for_every_exponent() {
        let wide = (1u64 << (DIVIDEND_BITS + 1)) - 1;
        for absn in [0u64, 1, 2, 3, 5, 7, 0x2_5a5a, 0x3_ffff, 0x2_0001] {
            for sh in -3i64..=31 {
                let (r, f) = if sh >= 0 {
                    ((absn << sh) & 0xffff_ffff, 0)
                } else {
                    (absn >> -sh, (absn & ((1 << -sh) - 1)) << (3 + sh))
                };
                for below in [true, false] {
                    let s0 = if below { sh } else { sh + 1 };
                    let y = (absn << (s0 + 3) as u64) & wide;
                    let z = if below { y } else { y >> 1 } & ((1 << DIVIDEND_BITS) - 1);
                    assert_eq!((z >> 3, z & 7), (r, f), "|n_c| {absn:#x}, sh {sh}, below {below}");
                }
            }
        }
    }
}
