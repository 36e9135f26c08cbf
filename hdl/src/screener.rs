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
//! bit (a multi-cycle unit: 3 cycles per screened-out patch, 21 per passing one).

use crate::formats::{cross, dot, SECTOR_MARGIN, SH_MAX, SH_MIN};
use crate::leaf::Mul18;
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

    /// What the intersection unit needs of a patch.
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
    pub struct PatchSetup {
        pub id: u16,
        /// Endpoints relative to the origin (Q12.6, 18 bits signed).
        pub a: [i32; 2],
        pub b: [i32; 2],
        /// Inverse-distance vector (18 bits signed, normalised by `sh`).
        pub w: [i32; 2],
        /// Exponent of `w`, in `[SH_MIN, SH_MAX]`: the key of a hit is `dot(d, w)·2^-sh`.
        pub sh: i8,
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
}

// ---------------------------------------------------------------------------------------------
// The RTL block.
// ---------------------------------------------------------------------------------------------

/// Cycles one screened-out patch occupies the unit (accept, two multiplier cycles, verdict; the
/// next patch is accepted in the verdict cycle).
pub const SCREEN_CYCLES: u64 = 3;
/// Quotient bits of the divider (one per cycle).
pub const DIV_STEPS: u64 = 17;

/// The backface screener (see the [module documentation](self)): a multi-cycle unit that takes
/// one patch at a time.
///
/// # Ports
///
/// * bundle setup, held constant while patches stream: `origin_x/y` (Q11.6, 17 bits unsigned),
///   `normal_x/y`, `first_x/y`, `last_x/y` (Q2.16, 18 bits two's complement);
/// * patch stream in (valid/ready): `in_id`, `in_ax/ay/bx/by` (world coordinates, Q11.6);
/// * passing patches out (valid/ready), in the intersection unit's format: `out_id`,
///   `out_ax/ay/bx/by` (relative to the origin, 18 bits two's complement), `out_wx/wy` (18 bits
///   two's complement) and `out_sh` (6 bits two's complement, in [−3, 31]);
/// * counters (32 bits, wrapping): `passed`, `backward`, `back_facing`, `outside`, `near`; each
///   patch accepted is counted in exactly one of them, in the cycle of its verdict.
///
/// # Timing
///
/// * Cycle 0: the patch is accepted; its coordinates relative to the origin are registered.
/// * Cycles 1–2: the ten products (ten [`Mul18`] leaves, latency 2).
/// * Cycle 3, the verdict: the sums and differences of the products, the verdict, the exponent
///   `sh` (leading-zero counts of `nmax` and `2K`, one comparison) and the divider's initial
///   remainders. A screened-out patch is counted and the next patch accepted in this cycle
///   (`in_ready` high), so a screened-out patch costs [`SCREEN_CYCLES`] = 3 cycles.
/// * Cycles 4–20: two restoring dividers (one per component of `W`), one quotient bit per cycle.
/// * Cycle 21 on: `out_valid` until `out_ready`; in the cycle of the transfer the next patch is
///   accepted. A passing patch costs 21 cycles when the consumer is ready.
///
/// `in_ready` depends combinationally on `out_ready` (a patch is accepted in the cycle the
/// previous one leaves). The bit-true model is [`model::screen`].
#[derive(LogicBlock)]
pub struct Screener {
    pub clock: Signal<In, Clock>,
    // Bundle setup.
    pub origin_x: Signal<In, Bits<17>>,
    pub origin_y: Signal<In, Bits<17>>,
    pub normal_x: Signal<In, Bits<18>>,
    pub normal_y: Signal<In, Bits<18>>,
    pub first_x: Signal<In, Bits<18>>,
    pub first_y: Signal<In, Bits<18>>,
    pub last_x: Signal<In, Bits<18>>,
    pub last_y: Signal<In, Bits<18>>,
    // Patch stream in.
    pub in_valid: Signal<In, bool>,
    pub in_ready: Signal<Out, bool>,
    pub in_id: Signal<In, Bits<16>>,
    pub in_ax: Signal<In, Bits<17>>,
    pub in_ay: Signal<In, Bits<17>>,
    pub in_bx: Signal<In, Bits<17>>,
    pub in_by: Signal<In, Bits<17>>,
    // Passing patches out.
    pub out_valid: Signal<Out, bool>,
    pub out_ready: Signal<In, bool>,
    pub out_id: Signal<Out, Bits<16>>,
    pub out_ax: Signal<Out, Bits<18>>,
    pub out_ay: Signal<Out, Bits<18>>,
    pub out_bx: Signal<Out, Bits<18>>,
    pub out_by: Signal<Out, Bits<18>>,
    pub out_wx: Signal<Out, Bits<18>>,
    pub out_wy: Signal<Out, Bits<18>>,
    pub out_sh: Signal<Out, Bits<6>>,
    // Counters.
    pub passed: Signal<Out, Bits<32>>,
    pub backward: Signal<Out, Bits<32>>,
    pub back_facing: Signal<Out, Bits<32>>,
    pub outside: Signal<Out, Bits<32>>,
    pub near: Signal<Out, Bits<32>>,
    // Sequencer.
    state: DFF<Bits<3>>,
    is_idle: Signal<Local, bool>,
    is_m1: Signal<Local, bool>,
    is_m2: Signal<Local, bool>,
    is_verdict: Signal<Local, bool>,
    is_div: Signal<Local, bool>,
    is_out: Signal<Local, bool>,
    take: Signal<Local, bool>,
    // Cycle 0: relative coordinates.
    ext_ox: Signal<Local, Bits<18>>,
    ext_oy: Signal<Local, Bits<18>>,
    ext_ax: Signal<Local, Bits<18>>,
    ext_ay: Signal<Local, Bits<18>>,
    ext_bx: Signal<Local, Bits<18>>,
    ext_by: Signal<Local, Bits<18>>,
    id: DFF<Bits<16>>,
    ax: DFF<Bits<18>>,
    ay: DFF<Bits<18>>,
    bx: DFF<Bits<18>>,
    by: DFF<Bits<18>>,
    // Cycles 1–2: products.
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
    // Cycle 3: the verdict.
    ha: Signal<Local, Bits<32>>,
    hb: Signal<Local, Bits<32>>,
    kk: Signal<Local, Bits<32>>,
    side_f: Signal<Local, Bits<32>>,
    side_l: Signal<Local, Bits<32>>,
    side_f_x: Signal<Local, Bits<32>>,
    side_l_x: Signal<Local, Bits<32>>,
    ha_pos: Signal<Local, bool>,
    hb_pos: Signal<Local, bool>,
    is_backward: Signal<Local, bool>,
    is_back_facing: Signal<Local, bool>,
    is_outside: Signal<Local, bool>,
    is_near: Signal<Local, bool>,
    is_pass: Signal<Local, bool>,
    nx: Signal<Local, Bits<18>>,
    ny: Signal<Local, Bits<18>>,
    nx_neg: Signal<Local, Bits<18>>,
    ny_neg: Signal<Local, Bits<18>>,
    absnx: Signal<Local, Bits<18>>,
    absny: Signal<Local, Bits<18>>,
    nmax: Signal<Local, Bits<18>>,
    absnx32: Signal<Local, Bits<32>>,
    absny32: Signal<Local, Bits<32>>,
    nmax32: Signal<Local, Bits<32>>,
    k2: Signal<Local, Bits<32>>,
    // Leading-zero counts by five conditional shifts: `zn*` of nmax, `ze*` of 2K.
    zn0: Signal<Local, Bits<32>>,
    zn1: Signal<Local, Bits<32>>,
    zn2: Signal<Local, Bits<32>>,
    zn3: Signal<Local, Bits<32>>,
    zn4: Signal<Local, Bits<32>>,
    zn5: Signal<Local, Bits<32>>,
    cn16_n: Signal<Local, Bits<6>>,
    cn8_n: Signal<Local, Bits<6>>,
    cn4_n: Signal<Local, Bits<6>>,
    cn2_n: Signal<Local, Bits<6>>,
    cn1_n: Signal<Local, Bits<6>>,
    clz_n: Signal<Local, Bits<6>>,
    ze0: Signal<Local, Bits<32>>,
    ze1: Signal<Local, Bits<32>>,
    ze2: Signal<Local, Bits<32>>,
    ze3: Signal<Local, Bits<32>>,
    ze4: Signal<Local, Bits<32>>,
    ze5: Signal<Local, Bits<32>>,
    ce16_e: Signal<Local, Bits<6>>,
    ce8_e: Signal<Local, Bits<6>>,
    ce4_e: Signal<Local, Bits<6>>,
    ce2_e: Signal<Local, Bits<6>>,
    ce1_e: Signal<Local, Bits<6>>,
    clz_e: Signal<Local, Bits<6>>,
    top16_n: Signal<Local, Bits<16>>,
    top8_n: Signal<Local, Bits<8>>,
    top4_n: Signal<Local, Bits<4>>,
    top2_n: Signal<Local, Bits<2>>,
    top16_e: Signal<Local, Bits<16>>,
    top8_e: Signal<Local, Bits<8>>,
    top4_e: Signal<Local, Bits<4>>,
    top2_e: Signal<Local, Bits<2>>,
    s0: Signal<Local, Bits<6>>,
    s0_m1: Signal<Local, Bits<6>>,
    sh: Signal<Local, Bits<6>>,
    sh5: Signal<Local, Bits<5>>,
    low_nx: Signal<Local, Bits<16>>,
    low_ny: Signal<Local, Bits<16>>,
    r0x: Signal<Local, Bits<32>>,
    r0y: Signal<Local, Bits<32>>,
    f0x: Signal<Local, Bits<16>>,
    f0y: Signal<Local, Bits<16>>,
    // Cycles 4–20: the dividers.
    k: DFF<Bits<32>>,
    sh_r: DFF<Bits<6>>,
    step: DFF<Bits<5>>,
    neg_x: DFF<bool>,
    neg_y: DFF<bool>,
    rx: DFF<Bits<32>>,
    ry: DFF<Bits<32>>,
    fx: DFF<Bits<16>>,
    fy: DFF<Bits<16>>,
    qx: DFF<Bits<18>>,
    qy: DFF<Bits<18>>,
    rx2: Signal<Local, Bits<32>>,
    ry2: Signal<Local, Bits<32>>,
    tx: Signal<Local, Bits<32>>,
    ty: Signal<Local, Bits<32>>,
    tx_k: Signal<Local, Bits<32>>,
    ty_k: Signal<Local, Bits<32>>,
    qx2: Signal<Local, Bits<18>>,
    qy2: Signal<Local, Bits<18>>,
    wx_neg: Signal<Local, Bits<18>>,
    wy_neg: Signal<Local, Bits<18>>,
    // Counters.
    c_passed: DFF<Bits<32>>,
    c_backward: DFF<Bits<32>>,
    c_back_facing: DFF<Bits<32>>,
    c_outside: DFF<Bits<32>>,
    c_near: DFF<Bits<32>>,
    // Constants.
    st_idle: Constant<Bits<3>>,
    st_m1: Constant<Bits<3>>,
    st_m2: Constant<Bits<3>>,
    st_verdict: Constant<Bits<3>>,
    st_div: Constant<Bits<3>>,
    st_out: Constant<Bits<3>>,
    zero18: Constant<Bits<18>>,
    zero32: Constant<Bits<32>>,
    one32: Constant<Bits<32>>,
    msb32: Constant<Bits<32>>,
    thr_f: Constant<Bits<32>>,
    thr_l: Constant<Bits<32>>,
    zero6: Constant<Bits<6>>,
    zero16: Constant<Bits<16>>,
    zero8: Constant<Bits<8>>,
    zero4: Constant<Bits<4>>,
    zero2: Constant<Bits<2>>,
    sh16: Constant<Bits<32>>,
    sh8: Constant<Bits<32>>,
    sh4: Constant<Bits<32>>,
    sh2: Constant<Bits<32>>,
    sh1: Constant<Bits<32>>,
    sh3: Constant<Bits<32>>,
    sh13: Constant<Bits<16>>,
    sh14: Constant<Bits<16>>,
    sh15: Constant<Bits<16>>,
    one6: Constant<Bits<6>>,
    c16_6: Constant<Bits<6>>,
    c8_6: Constant<Bits<6>>,
    c4_6: Constant<Bits<6>>,
    c2_6: Constant<Bits<6>>,
    c1_6: Constant<Bits<6>>,
    sh_lo: Constant<Bits<6>>,
    sh_m1: Constant<Bits<6>>,
    sh_m2: Constant<Bits<6>>,
    zero5: Constant<Bits<5>>,
    one5: Constant<Bits<5>>,
    last_step: Constant<Bits<5>>,
    one18: Constant<Bits<18>>,
}

impl Default for Screener {
    fn default() -> Self {
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
            passed: Default::default(),
            backward: Default::default(),
            back_facing: Default::default(),
            outside: Default::default(),
            near: Default::default(),
            state: Default::default(),
            is_idle: Default::default(),
            is_m1: Default::default(),
            is_m2: Default::default(),
            is_verdict: Default::default(),
            is_div: Default::default(),
            is_out: Default::default(),
            take: Default::default(),
            ext_ox: Default::default(),
            ext_oy: Default::default(),
            ext_ax: Default::default(),
            ext_ay: Default::default(),
            ext_bx: Default::default(),
            ext_by: Default::default(),
            id: Default::default(),
            ax: Default::default(),
            ay: Default::default(),
            bx: Default::default(),
            by: Default::default(),
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
            ha: Default::default(),
            hb: Default::default(),
            kk: Default::default(),
            side_f: Default::default(),
            side_l: Default::default(),
            side_f_x: Default::default(),
            side_l_x: Default::default(),
            ha_pos: Default::default(),
            hb_pos: Default::default(),
            is_backward: Default::default(),
            is_back_facing: Default::default(),
            is_outside: Default::default(),
            is_near: Default::default(),
            is_pass: Default::default(),
            nx: Default::default(),
            ny: Default::default(),
            nx_neg: Default::default(),
            ny_neg: Default::default(),
            absnx: Default::default(),
            absny: Default::default(),
            nmax: Default::default(),
            absnx32: Default::default(),
            absny32: Default::default(),
            nmax32: Default::default(),
            k2: Default::default(),
            zn0: Default::default(),
            zn1: Default::default(),
            zn2: Default::default(),
            zn3: Default::default(),
            zn4: Default::default(),
            zn5: Default::default(),
            cn16_n: Default::default(),
            cn8_n: Default::default(),
            cn4_n: Default::default(),
            cn2_n: Default::default(),
            cn1_n: Default::default(),
            clz_n: Default::default(),
            ze0: Default::default(),
            ze1: Default::default(),
            ze2: Default::default(),
            ze3: Default::default(),
            ze4: Default::default(),
            ze5: Default::default(),
            ce16_e: Default::default(),
            ce8_e: Default::default(),
            ce4_e: Default::default(),
            ce2_e: Default::default(),
            ce1_e: Default::default(),
            clz_e: Default::default(),
            top16_n: Default::default(),
            top8_n: Default::default(),
            top4_n: Default::default(),
            top2_n: Default::default(),
            top16_e: Default::default(),
            top8_e: Default::default(),
            top4_e: Default::default(),
            top2_e: Default::default(),
            s0: Default::default(),
            s0_m1: Default::default(),
            sh: Default::default(),
            sh5: Default::default(),
            low_nx: Default::default(),
            low_ny: Default::default(),
            r0x: Default::default(),
            r0y: Default::default(),
            f0x: Default::default(),
            f0y: Default::default(),
            k: Default::default(),
            sh_r: Default::default(),
            step: Default::default(),
            neg_x: Default::default(),
            neg_y: Default::default(),
            rx: Default::default(),
            ry: Default::default(),
            fx: Default::default(),
            fy: Default::default(),
            qx: Default::default(),
            qy: Default::default(),
            rx2: Default::default(),
            ry2: Default::default(),
            tx: Default::default(),
            ty: Default::default(),
            tx_k: Default::default(),
            ty_k: Default::default(),
            qx2: Default::default(),
            qy2: Default::default(),
            wx_neg: Default::default(),
            wy_neg: Default::default(),
            c_passed: Default::default(),
            c_backward: Default::default(),
            c_back_facing: Default::default(),
            c_outside: Default::default(),
            c_near: Default::default(),
            st_idle: Constant::new(0u64.into()),
            st_m1: Constant::new(1u64.into()),
            st_m2: Constant::new(2u64.into()),
            st_verdict: Constant::new(3u64.into()),
            st_div: Constant::new(4u64.into()),
            st_out: Constant::new(5u64.into()),
            zero18: Constant::new(0u64.into()),
            zero32: Constant::new(0u64.into()),
            one32: Constant::new(1u64.into()),
            msb32: Constant::new(0x8000_0000u64.into()),
            thr_f: Constant::new(0x7FFF_FF00u64.into()),
            thr_l: Constant::new(0x8000_0100u64.into()),
            zero6: Constant::new(0u64.into()),
            zero16: Constant::new(0u64.into()),
            zero8: Constant::new(0u64.into()),
            zero4: Constant::new(0u64.into()),
            zero2: Constant::new(0u64.into()),
            sh16: Constant::new(16u64.into()),
            sh8: Constant::new(8u64.into()),
            sh4: Constant::new(4u64.into()),
            sh2: Constant::new(2u64.into()),
            sh1: Constant::new(1u64.into()),
            sh3: Constant::new(3u64.into()),
            sh13: Constant::new(13u64.into()),
            sh14: Constant::new(14u64.into()),
            sh15: Constant::new(15u64.into()),
            one6: Constant::new(1u64.into()),
            c16_6: Constant::new(16u64.into()),
            c8_6: Constant::new(8u64.into()),
            c4_6: Constant::new(4u64.into()),
            c2_6: Constant::new(2u64.into()),
            c1_6: Constant::new(1u64.into()),
            sh_lo: Constant::new(61u64.into()),
            sh_m1: Constant::new(63u64.into()),
            sh_m2: Constant::new(62u64.into()),
            zero5: Constant::new(0u64.into()),
            one5: Constant::new(1u64.into()),
            last_step: Constant::new(16u64.into()),
            one18: Constant::new(1u64.into()),
        }
    }
}

impl Logic for Screener {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            state,
            id,
            ax,
            ay,
            bx,
            by,
            k,
            sh_r,
            step,
            neg_x,
            neg_y,
            rx,
            ry,
            fx,
            fy,
            qx,
            qy,
            c_passed,
            c_backward,
            c_back_facing,
            c_outside,
            c_near
        );
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

        // Sequencer.
        self.is_idle.next = self.state.q.val() == self.st_idle.val();
        self.is_m1.next = self.state.q.val() == self.st_m1.val();
        self.is_m2.next = self.state.q.val() == self.st_m2.val();
        self.is_verdict.next = self.state.q.val() == self.st_verdict.val();
        self.is_div.next = self.state.q.val() == self.st_div.val();
        self.is_out.next = self.state.q.val() == self.st_out.val();

        // Cycle 0: coordinates relative to the origin (18 bits, exact).
        self.ext_ox.next = bit_cast::<18, 17>(self.origin_x.val());
        self.ext_oy.next = bit_cast::<18, 17>(self.origin_y.val());
        self.ext_ax.next = bit_cast::<18, 17>(self.in_ax.val());
        self.ext_ay.next = bit_cast::<18, 17>(self.in_ay.val());
        self.ext_bx.next = bit_cast::<18, 17>(self.in_bx.val());
        self.ext_by.next = bit_cast::<18, 17>(self.in_by.val());

        // Cycles 1–2: the ten products of the registered patch.
        self.m_nax.a.next = self.normal_x.val();
        self.m_nax.b.next = self.ax.q.val();
        self.m_nay.a.next = self.normal_y.val();
        self.m_nay.b.next = self.ay.q.val();
        self.m_nbx.a.next = self.normal_x.val();
        self.m_nbx.b.next = self.bx.q.val();
        self.m_nby.a.next = self.normal_y.val();
        self.m_nby.b.next = self.by.q.val();
        self.m_aby.a.next = self.ax.q.val();
        self.m_aby.b.next = self.by.q.val();
        self.m_abx.a.next = self.ay.q.val();
        self.m_abx.b.next = self.bx.q.val();
        self.m_fby.a.next = self.first_x.val();
        self.m_fby.b.next = self.by.q.val();
        self.m_fbx.a.next = self.first_y.val();
        self.m_fbx.b.next = self.bx.q.val();
        self.m_lay.a.next = self.last_x.val();
        self.m_lay.b.next = self.ay.q.val();
        self.m_lax.a.next = self.last_y.val();
        self.m_lax.b.next = self.ax.q.val();

        // Cycle 3: the verdict.
        self.ha.next = self.m_nax.p.val() + self.m_nay.p.val();
        self.hb.next = self.m_nbx.p.val() + self.m_nby.p.val();
        self.kk.next = self.m_aby.p.val() - self.m_abx.p.val();
        self.side_f.next = self.m_fby.p.val() - self.m_fbx.p.val();
        self.side_l.next = self.m_lay.p.val() - self.m_lax.p.val();
        // Signed comparisons with the margin as unsigned ones on the sign-flipped values.
        self.side_f_x.next = self.side_f.val() ^ self.msb32.val();
        self.side_l_x.next = self.side_l.val() ^ self.msb32.val();
        self.ha_pos.next = !self.ha.val().get_bit(31) & (self.ha.val() != self.zero32.val());
        self.hb_pos.next = !self.hb.val().get_bit(31) & (self.hb.val() != self.zero32.val());
        // n = (b.y − a.y, a.x − b.x) = (B.y − A.y, A.x − B.x): |n_c| < 2^17.
        self.nx.next = self.by.q.val() - self.ay.q.val();
        self.ny.next = self.ax.q.val() - self.bx.q.val();
        self.nx_neg.next = self.zero18.val() - self.nx.val();
        self.ny_neg.next = self.zero18.val() - self.ny.val();
        self.absnx.next = self.nx.val();
        if self.nx.val().get_bit(17) {
            self.absnx.next = self.nx_neg.val();
        }
        self.absny.next = self.ny.val();
        if self.ny.val().get_bit(17) {
            self.absny.next = self.ny_neg.val();
        }
        self.nmax.next = self.absny.val();
        if self.absnx.val() > self.absny.val() {
            self.nmax.next = self.absnx.val();
        }
        self.absnx32.next = bit_cast::<32, 18>(self.absnx.val());
        self.absny32.next = bit_cast::<32, 18>(self.absny.val());
        self.nmax32.next = bit_cast::<32, 18>(self.nmax.val());
        self.k2.next = self.kk.val() << self.sh1.val();
        // Leading zeros of nmax: five conditional shifts.
        self.zn0.next = self.nmax32.val();
        self.top16_n.next = self.zn0.val().get_bits::<16>(16);
        self.zn1.next = self.zn0.val();
        self.cn16_n.next = self.zero6.val();
        if self.top16_n.val() == self.zero16.val() {
            self.zn1.next = self.zn0.val() << self.sh16.val();
            self.cn16_n.next = self.c16_6.val();
        }
        self.top8_n.next = self.zn1.val().get_bits::<8>(24);
        self.zn2.next = self.zn1.val();
        self.cn8_n.next = self.zero6.val();
        if self.top8_n.val() == self.zero8.val() {
            self.zn2.next = self.zn1.val() << self.sh8.val();
            self.cn8_n.next = self.c8_6.val();
        }
        self.top4_n.next = self.zn2.val().get_bits::<4>(28);
        self.zn3.next = self.zn2.val();
        self.cn4_n.next = self.zero6.val();
        if self.top4_n.val() == self.zero4.val() {
            self.zn3.next = self.zn2.val() << self.sh4.val();
            self.cn4_n.next = self.c4_6.val();
        }
        self.top2_n.next = self.zn3.val().get_bits::<2>(30);
        self.zn4.next = self.zn3.val();
        self.cn2_n.next = self.zero6.val();
        if self.top2_n.val() == self.zero2.val() {
            self.zn4.next = self.zn3.val() << self.sh2.val();
            self.cn2_n.next = self.c2_6.val();
        }
        self.zn5.next = self.zn4.val();
        self.cn1_n.next = self.zero6.val();
        if !self.zn4.val().get_bit(31) {
            self.zn5.next = self.zn4.val() << self.sh1.val();
            self.cn1_n.next = self.c1_6.val();
        }
        self.clz_n.next =
            self.cn16_n.val() | self.cn8_n.val() | self.cn4_n.val() | self.cn2_n.val() | self.cn1_n.val();
        // Leading zeros of 2K.
        self.ze0.next = self.k2.val();
        self.top16_e.next = self.ze0.val().get_bits::<16>(16);
        self.ze1.next = self.ze0.val();
        self.ce16_e.next = self.zero6.val();
        if self.top16_e.val() == self.zero16.val() {
            self.ze1.next = self.ze0.val() << self.sh16.val();
            self.ce16_e.next = self.c16_6.val();
        }
        self.top8_e.next = self.ze1.val().get_bits::<8>(24);
        self.ze2.next = self.ze1.val();
        self.ce8_e.next = self.zero6.val();
        if self.top8_e.val() == self.zero8.val() {
            self.ze2.next = self.ze1.val() << self.sh8.val();
            self.ce8_e.next = self.c8_6.val();
        }
        self.top4_e.next = self.ze2.val().get_bits::<4>(28);
        self.ze3.next = self.ze2.val();
        self.ce4_e.next = self.zero6.val();
        if self.top4_e.val() == self.zero4.val() {
            self.ze3.next = self.ze2.val() << self.sh4.val();
            self.ce4_e.next = self.c4_6.val();
        }
        self.top2_e.next = self.ze3.val().get_bits::<2>(30);
        self.ze4.next = self.ze3.val();
        self.ce2_e.next = self.zero6.val();
        if self.top2_e.val() == self.zero2.val() {
            self.ze4.next = self.ze3.val() << self.sh2.val();
            self.ce2_e.next = self.c2_6.val();
        }
        self.ze5.next = self.ze4.val();
        self.ce1_e.next = self.zero6.val();
        if !self.ze4.val().get_bit(31) {
            self.ze5.next = self.ze4.val() << self.sh1.val();
            self.ce1_e.next = self.c1_6.val();
        }
        self.clz_e.next =
            self.ce16_e.val() | self.ce8_e.val() | self.ce4_e.val() | self.ce2_e.val() | self.ce1_e.val();
        // With s0 = clz(nmax) − clz(2K), nmax·2^s0 and 2K share their leading one: the largest
        // sh with nmax·2^sh < 2K is s0 when the normalised nmax is below the normalised 2K, else
        // s0 − 1. It lies in [−17, 31]; below −3 the patch is near.
        self.s0.next = self.clz_n.val() - self.clz_e.val();
        self.s0_m1.next = self.s0.val() - self.one6.val();
        self.sh.next = self.s0_m1.val();
        if self.zn5.val() < self.ze5.val() {
            self.sh.next = self.s0.val();
        }
        self.sh5.next = self.sh.val().get_bits::<5>(0);
        // The dividers' initial remainders floor(|n_c|·2^sh) and the bits shifted out (sh < 0),
        // fed in first.
        self.low_nx.next = self.absnx32.val().get_bits::<16>(0);
        self.low_ny.next = self.absny32.val().get_bits::<16>(0);
        self.r0x.next = self.absnx32.val() << self.sh5.val();
        self.r0y.next = self.absny32.val() << self.sh5.val();
        self.f0x.next = self.zero16.val();
        self.f0y.next = self.zero16.val();
        if self.sh.val() == self.sh_m1.val() {
            self.r0x.next = self.absnx32.val() >> self.sh1.val();
            self.r0y.next = self.absny32.val() >> self.sh1.val();
            self.f0x.next = self.low_nx.val() << self.sh15.val();
            self.f0y.next = self.low_ny.val() << self.sh15.val();
        } else if self.sh.val() == self.sh_m2.val() {
            self.r0x.next = self.absnx32.val() >> self.sh2.val();
            self.r0y.next = self.absny32.val() >> self.sh2.val();
            self.f0x.next = self.low_nx.val() << self.sh14.val();
            self.f0y.next = self.low_ny.val() << self.sh14.val();
        } else if self.sh.val() == self.sh_lo.val() {
            self.r0x.next = self.absnx32.val() >> self.sh3.val();
            self.r0y.next = self.absny32.val() >> self.sh3.val();
            self.f0x.next = self.low_nx.val() << self.sh13.val();
            self.f0y.next = self.low_ny.val() << self.sh13.val();
        }
        // The verdict, by priority.
        self.is_backward.next = !self.ha_pos.val() & !self.hb_pos.val();
        self.is_back_facing.next =
            !self.is_backward.val() & (self.kk.val().get_bit(31) | (self.kk.val() == self.zero32.val()));
        self.is_outside.next = !self.is_backward.val()
            & !self.is_back_facing.val()
            & ((self.hb_pos.val() & (self.side_f_x.val() < self.thr_f.val()))
                | (self.ha_pos.val() & (self.side_l_x.val() > self.thr_l.val())));
        self.is_near.next = !self.is_backward.val()
            & !self.is_back_facing.val()
            & !self.is_outside.val()
            & self.sh.val().get_bit(5)
            & (self.sh.val() < self.sh_lo.val());
        self.is_pass.next = !self.is_backward.val()
            & !self.is_back_facing.val()
            & !self.is_outside.val()
            & !self.is_near.val();

        // Cycles 4–20: one restoring-division step per cycle and component. The partial
        // remainders stay below 2K ≤ 2^32 − 2; step 0 compares the initial remainder itself.
        self.rx2.next = self.rx.q.val() << self.sh1.val();
        self.ry2.next = self.ry.q.val() << self.sh1.val();
        self.tx.next = self.rx2.val();
        if self.fx.q.val().get_bit(15) {
            self.tx.next = self.rx2.val() | self.one32.val();
        }
        self.ty.next = self.ry2.val();
        if self.fy.q.val().get_bit(15) {
            self.ty.next = self.ry2.val() | self.one32.val();
        }
        if self.step.q.val() == self.zero5.val() {
            self.tx.next = self.rx.q.val();
            self.ty.next = self.ry.q.val();
        }
        self.tx_k.next = self.tx.val() - self.k.q.val();
        self.ty_k.next = self.ty.val() - self.k.q.val();
        self.qx2.next = self.qx.q.val() << self.one18.val();
        self.qy2.next = self.qy.q.val() << self.one18.val();
        if self.is_div.val() {
            self.step.d.next = self.step.q.val() + self.one5.val();
            if self.step.q.val() != self.zero5.val() {
                self.fx.d.next = self.fx.q.val() << self.sh1.val();
                self.fy.d.next = self.fy.q.val() << self.sh1.val();
            }
            self.rx.d.next = self.tx.val();
            self.qx.d.next = self.qx2.val();
            if self.tx.val() >= self.k.q.val() {
                self.rx.d.next = self.tx_k.val();
                self.qx.d.next = self.qx2.val() | self.one18.val();
            }
            self.ry.d.next = self.ty.val();
            self.qy.d.next = self.qy2.val();
            if self.ty.val() >= self.k.q.val() {
                self.ry.d.next = self.ty_k.val();
                self.qy.d.next = self.qy2.val() | self.one18.val();
            }
        }

        // Output.
        self.wx_neg.next = self.zero18.val() - self.qx.q.val();
        self.wy_neg.next = self.zero18.val() - self.qy.q.val();
        self.out_valid.next = self.is_out.val();
        self.out_id.next = self.id.q.val();
        self.out_ax.next = self.ax.q.val();
        self.out_ay.next = self.ay.q.val();
        self.out_bx.next = self.bx.q.val();
        self.out_by.next = self.by.q.val();
        self.out_wx.next = self.qx.q.val();
        if self.neg_x.q.val() {
            self.out_wx.next = self.wx_neg.val();
        }
        self.out_wy.next = self.qy.q.val();
        if self.neg_y.q.val() {
            self.out_wy.next = self.wy_neg.val();
        }
        self.out_sh.next = self.sh_r.q.val();

        // Handshakes and state transitions.
        self.in_ready.next = self.is_idle.val()
            | (self.is_verdict.val() & !self.is_pass.val())
            | (self.is_out.val() & self.out_ready.val());
        self.take.next = self.in_valid.val()
            & (self.is_idle.val()
                | (self.is_verdict.val() & !self.is_pass.val())
                | (self.is_out.val() & self.out_ready.val()));
        if self.is_m1.val() {
            self.state.d.next = self.st_m2.val();
        }
        if self.is_m2.val() {
            self.state.d.next = self.st_verdict.val();
        }
        if self.is_verdict.val() {
            self.state.d.next = self.st_idle.val();
            if self.is_pass.val() {
                self.state.d.next = self.st_div.val();
                self.step.d.next = self.zero5.val();
                self.k.d.next = self.kk.val();
                self.sh_r.d.next = self.sh.val();
                self.neg_x.d.next = self.nx.val().get_bit(17);
                self.neg_y.d.next = self.ny.val().get_bit(17);
                self.rx.d.next = self.r0x.val();
                self.ry.d.next = self.r0y.val();
                self.fx.d.next = self.f0x.val();
                self.fy.d.next = self.f0y.val();
                self.qx.d.next = self.zero18.val();
                self.qy.d.next = self.zero18.val();
                self.c_passed.d.next = self.c_passed.q.val() + self.one32.val();
            }
            if self.is_backward.val() {
                self.c_backward.d.next = self.c_backward.q.val() + self.one32.val();
            }
            if self.is_back_facing.val() {
                self.c_back_facing.d.next = self.c_back_facing.q.val() + self.one32.val();
            }
            if self.is_outside.val() {
                self.c_outside.d.next = self.c_outside.q.val() + self.one32.val();
            }
            if self.is_near.val() {
                self.c_near.d.next = self.c_near.q.val() + self.one32.val();
            }
        }
        if self.is_div.val() & (self.step.q.val() == self.last_step.val()) {
            self.state.d.next = self.st_out.val();
        }
        if self.is_out.val() & self.out_ready.val() {
            self.state.d.next = self.st_idle.val();
        }
        if self.take.val() {
            self.state.d.next = self.st_m1.val();
            self.id.d.next = self.in_id.val();
            self.ax.d.next = self.ext_ax.val() - self.ext_ox.val();
            self.ay.d.next = self.ext_ay.val() - self.ext_oy.val();
            self.bx.d.next = self.ext_bx.val() - self.ext_ox.val();
            self.by.d.next = self.ext_by.val() - self.ext_oy.val();
        }
        self.passed.next = self.c_passed.q.val();
        self.backward.next = self.c_backward.q.val();
        self.back_facing.next = self.c_back_facing.q.val();
        self.outside.next = self.c_outside.q.val();
        self.near.next = self.c_near.q.val();
    }
}
