//! The intersection unit: a patch, set up once by the screener, is tested against a bundle of
//! rays streamed past it, one ray-patch test per clock, and every ray keeps its nearest hit in a
//! ray memory.
//!
//! # Ports ([`IntersectionUnit`])
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | rising-edge clock |
//! | `dir_we`, `dir_addr`, `dir_x`, `dir_y` | in | 1, 10, 18, 18 | bundle setup: write ray `dir_addr`'s direction |
//! | `patch_valid`, `patch_ready` | in, out | 1, 1 | patch stream (valid/ready) |
//! | `patch_ax`, `patch_ay`, `patch_bx`, `patch_by` | in | 4 × 18 | endpoints relative to the origin |
//! | `patch_wx`, `patch_wy`, `patch_sh` | in | 18, 18, 6 | inverse-distance vector and its exponent |
//! | `patch_id`, `patch_first`, `patch_count` | in | 16, 10, 11 | patch id; test rays `first .. first + count` (mod 1024) |
//! | `patch_retire` | in | 1 | instead of testing, retire rays `first .. first + count` (the patch fields are ignored) |
//! | `res_re`, `res_addr` | in | 1, 10 | readout: read and clear ray `res_addr` (only while not `busy`) |
//! | `res_hit`, `res_id`, `res_key` | out | 1, 16, 32 | the ray's nearest hit, two cycles after `res_re` ([`READOUT_LATENCY`]) |
//! | `busy` | out | 1 | a test is issuing or may still update the ray memory |
//! | `tests` | out | 32 | ray-patch tests of live rays so far (wraps) |
//!
//! A patch transfers when `patch_valid && patch_ready` before the rising edge. `patch_ready` is
//! high while fewer than two rays of the current patch remain, so the next patch is taken while
//! the current one issues its last ray: back-to-back patches leave no bubble, and a patch with
//! `patch_count = 0` is consumed in one cycle.
//!
//! # Live rays
//!
//! Each ray has a live bit (a one-bit [`BramOut`] beside the direction memory): writing its
//! direction makes it live, a retire job (`patch_retire`) kills the rays of its range, one per
//! clock through the same sequencer as a test, so it takes effect in stream order. A test of a
//! dead ray occupies its issue slot but neither counts nor writes (the shelling techniques'
//! tracking: a ray that found its hit leaves the bundle). All rays are dead at power-up. The
//! host writes directions only while the unit is not busy.
//!
//! # Formats
//!
//! Directions Q2.16, coordinates Q12.6, `W` 18 bits with exponent `sh` in [−3, 31] (6 bits two's
//! complement), keys 32 bits unsigned, larger is nearer (`hdl/FORMATS.md`). A hit needs
//! `cross(d, a) ≤ 0 ≤ cross(d, b)`; its key is `dot(d, W)·2^-sh` clamped into [1, 2³² − 1].
//! It replaces the ray's hit when its key is larger, or equal with a lower id.
//!
//! # Pipeline, latency and throughput
//!
//! One test per clock (II = 1) for any mix of bundle lengths; latency [`WRITE_STAGE`] = 9 clocks
//! from issue to the ray-memory write (5 before the unit was re-pipelined for 150 MHz on ECP5).
//! Every memory is a [`BramOut`]: a block RAM read through its output register (on ECP5 a
//! `DP16KD` with `REGMODE_B = "OUTREG"`, about 1 ns clock-to-out instead of 5.8 ns), so a read
//! takes two clocks:
//!
//! * stage 0: the sequencer issues ray `cur` of the current patch (direction and live-bit read);
//! * stage 1: the patch operands enter the [`RayProductsPipe`] leaf (which holds them a clock);
//! * stage 2: direction and live bit arrive; the six products start (six 18×18 DSP
//!   multipliers, latency 2); a dead ray's test goes on as a bubble and is not counted;
//! * stage 4: side values `s_a`, `s_b` and `q = dot(d, W)` (registered); `q` enters the
//!   [`KeyScalePipe`] leaf (shift by `sh`, saturating, in three register stages);
//! * stage 5: the hit decision, `s_a ≤ 0 ≤ s_b`;
//! * stage 6: the ray memory is read;
//! * stage 8: the key and the ray memory's word arrive; the new key and id are compared with
//!   each candidate for the ray's nearest hit (registered: larger key, equal key, lower id);
//! * stage 9: the newest candidate picks the verdict; write back at the end of the clock.
//!
//! `tests` counts a live test three clocks after its issue.
//!
//! **Forwarding.** The ray memory (two [`BramOut`]s: key, and valid + id) is read in stage 6,
//! so the word arriving in stage 8 has seen the writes of the tests issued four or more clocks
//! before, but not those of the three tests right before: their writes end stage 9 one and two
//! clocks after the read, and in the clock of the read (a same-address read and write, whose
//! result the block RAM does not define and [`BramOut`] poisons). In stage 8 the new key is
//! compared, in parallel, with the memory's word, with the key of the test in stage 9 (whose
//! verdict is being made) and with the last two writes (`fw_*`, `fw2_*`); whether the ray is
//! theirs is compared there too (`m1`…`m3`). In stage 9 the newest write to the ray among the
//! three (`fw_valid`…`fw3_valid`: the verdicts of the last three clocks) decides; without one,
//! the memory's word. Every comparison starts from registers or from the block RAM's output
//! register and ends in a register; dead tests and misses write nothing. Writes to the live
//! bits never meet a read that should see them (a retire's issue reads its own ray and ignores
//! it; directions are written only while not busy).
//!
//! **Readout.** `res_re` reads the ray memory (address in the clock of `res_re`, the word two
//! clocks later on `res_*`) and clears the ray one clock later (a write in the clock of its own
//! read would collide). A readout of the same ray in the next clock cannot see that clear, so
//! it reports no hit (zero), which is what the clear leaves. Readouts stream one per clock;
//! `busy` is high while any stage holds a test (so every write has ended before a readout's
//! read).
//!
//! Resources (`cargo xtask fpga --blocks intersection_unit --families ecp5`: Yosys `synth_ecp5`
//! with `SHELLING_ECP5`, nextpnr-ecp5 on the LFE5U-85F-6, seed 1): 6 `MULT18X18D` (with their
//! input and output registers), 6 `DP16KD` (directions 2, live bits 1, keys 2, valid + id 1,
//! all with the output register), 1146 LUT4s and 1017 flip-flops; 157.4 MHz (critical path
//! 6.35 ns: the `mem_meta` block RAM's output register to the id comparison `cm_lt`).
//!
//! # Models
//!
//! [`model::test`], [`model::key`] and [`model::replaces`] are the bit-true model; the
//! testbench's `intersection::model_bundle` applies them to a whole job stream.

use crate::formats::{cross, dot, SH_MAX, SH_MIN};
use crate::leaf::{BramOut, KeyScalePipe, RayProductsPipe, KEY_PIPE_LATENCY};
use crate::screener::model::PatchSetup;
use rust_hdl::prelude::*;

/// The bit-true model of the intersection unit.
pub mod model {
    use super::*;

    /// A ray's nearest hit: distance key (larger is nearer) and patch id.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub struct Nearest {
        pub key: u32,
        pub id: u16,
    }

    /// Tests one ray (direction `d`, Q2.16) against a set-up patch: the distance key of the hit,
    /// or `None`. The ray hits when `a` lies on its right or on it and `b` on its left or on it;
    /// the key is `dot(d, w)·2^-sh` ([`key`]).
    #[inline]
    pub fn test(p: &PatchSetup, d: [i32; 2]) -> Option<u32> {
        let sa = cross(d, p.a);
        let sb = cross(d, p.b);
        if sa > 0 || sb < 0 {
            return None;
        }
        Some(key(dot(d, p.w), p.sh))
    }

    /// The distance key of a hit from `q = dot(d, w)`: `q·2^-sh`, truncated, clamped into
    /// `[1, 2³² − 1]` (a grazing hit whose `q` rounds to zero or below is the farthest key; one
    /// nearer than 2⁻⁶ units saturates). `|q| < 2^29.5`, so `q << 2` never overflows.
    #[inline]
    pub fn key(q: i32, sh: i8) -> u32 {
        if q <= 0 {
            return 1;
        }
        let q = q as u32;
        let sh = sh.clamp(SH_MIN as i8, SH_MAX as i8);
        let u = if sh >= 0 {
            q >> sh
        } else if (q >> (32 + sh as i32)) != 0 {
            u32::MAX
        } else {
            q << -sh
        };
        u.max(1)
    }

    /// `true` when a hit with `key` on patch `id` replaces `old`: a larger key (nearer), or an
    /// equal key and a lower id.
    #[inline]
    pub fn replaces(key: u32, id: u16, old: Option<Nearest>) -> bool {
        match old {
            None => true,
            Some(o) => key > o.key || (key == o.key && id < o.id),
        }
    }
}

/// Bundle size limit of the unit: ray indices are 10 bits.
pub const RAY_BITS: usize = 10;

/// Clocks from a ray's issue (stage 0) to its ray-memory write (the end of stage 6).
pub const WRITE_STAGE: u64 = 9;

// The key leaf takes `q` in stage 4; its key is compared in stage 8, the write stage's previous.
const _: () = assert!(WRITE_STAGE == 5 + KEY_PIPE_LATENCY);

/// Clocks from `res_re` to the ray's nearest hit on `res_hit`, `res_id`, `res_key`.
pub const READOUT_LATENCY: u64 = 2;

/// The intersection unit (see the [module documentation](self) for ports and timing).
#[derive(LogicBlock)]
pub struct IntersectionUnit {
    pub clock: Signal<In, Clock>,
    // Bundle setup: the ray direction memory.
    pub dir_we: Signal<In, bool>,
    pub dir_addr: Signal<In, Bits<10>>,
    pub dir_x: Signal<In, Bits<18>>,
    pub dir_y: Signal<In, Bits<18>>,
    // Patch stream.
    pub patch_valid: Signal<In, bool>,
    pub patch_ready: Signal<Out, bool>,
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
    // Result readout (read and clear), only while not busy.
    pub res_re: Signal<In, bool>,
    pub res_addr: Signal<In, Bits<10>>,
    pub res_hit: Signal<Out, bool>,
    pub res_id: Signal<Out, Bits<16>>,
    pub res_key: Signal<Out, Bits<32>>,
    // Status.
    pub busy: Signal<Out, bool>,
    pub tests: Signal<Out, Bits<32>>,
    // Stage 0: the sequencer and the current patch.
    remaining: DFF<Bits<11>>,
    cur: DFF<Bits<10>>,
    p_ax: DFF<Bits<18>>,
    p_ay: DFF<Bits<18>>,
    p_bx: DFF<Bits<18>>,
    p_by: DFF<Bits<18>>,
    p_wx: DFF<Bits<18>>,
    p_wy: DFF<Bits<18>>,
    p_sh: DFF<Bits<6>>,
    p_id: DFF<Bits<16>>,
    p_retire: DFF<bool>,
    alive_mem: BramOut<1, 10>,
    live: Signal<Local, bool>,
    test_count: DFF<Bits<32>>,
    issue: Signal<Local, bool>,
    take: Signal<Local, bool>,
    // Stage 1: the patch operands of the issued ray (they enter the products leaf, which holds
    // them one clock longer). `tagN` is stage N's ray (bits 31…22), `sh` (21…16) and patch id
    // (15…0).
    v1: DFF<bool>,
    tag1: DFF<Bits<32>>,
    o_ax: DFF<Bits<18>>,
    o_ay: DFF<Bits<18>>,
    o_bx: DFF<Bits<18>>,
    o_by: DFF<Bits<18>>,
    o_wx: DFF<Bits<18>>,
    o_wy: DFF<Bits<18>>,
    // Stage 2: directions and live bit arrive; the six products start.
    v2: DFF<bool>,
    tag2: DFF<Bits<32>>,
    dir_mem_x: BramOut<18, 10>,
    dir_mem_y: BramOut<18, 10>,
    products: RayProductsPipe,
    // Stages 3 and 4: inside the multipliers; products arrive in stage 4.
    v3: DFF<bool>,
    tag3: DFF<Bits<32>>,
    v4: DFF<bool>,
    tag4: DFF<Bits<32>>,
    ray4: Signal<Local, Bits<10>>,
    sh4: Signal<Local, Bits<6>>,
    id4: Signal<Local, Bits<16>>,
    side_a: Signal<Local, Bits<32>>,
    side_b: Signal<Local, Bits<32>>,
    q: Signal<Local, Bits<32>>,
    // Stages 5 to 7: the key in its leaf (input registers in stage 5, key in stage 8); the ray
    // memory is read in stage 6.
    v5: DFF<bool>,
    sa5: DFF<Bits<32>>,
    sb5: DFF<Bits<32>>,
    ray5: DFF<Bits<10>>,
    id5: DFF<Bits<16>>,
    key_scale: KeyScalePipe,
    v6: DFF<bool>,
    ray6: DFF<Bits<10>>,
    id6: DFF<Bits<16>>,
    v7: DFF<bool>,
    ray7: DFF<Bits<10>>,
    id7: DFF<Bits<16>>,
    // Stage 8: the key and the ray memory's word arrive.
    v8: DFF<bool>,
    ray8: DFF<Bits<10>>,
    id8: DFF<Bits<16>>,
    mem_key: BramOut<32, 10>,
    mem_meta: BramOut<17, 10>,
    // Stage 8's comparisons of the new key and id with each candidate for the ray's nearest
    // hit: the memory's word (`cm_*`, with its hit flag), and the writes one, two and three
    // clocks before stage 9's (`c1_*`: stage 9's, `c2_*`: `fw`, `c3_*`: `fw2`); `gt`: larger
    // key, `eq`: equal key, `lt`: lower id. `mK`: stage 9's ray is that of the write K back.
    cm_hit: DFF<bool>,
    cm_gt: DFF<bool>,
    cm_eq: DFF<bool>,
    cm_lt: DFF<bool>,
    c1_gt: DFF<bool>,
    c1_eq: DFF<bool>,
    c1_lt: DFF<bool>,
    c2_gt: DFF<bool>,
    c2_eq: DFF<bool>,
    c2_lt: DFF<bool>,
    c3_gt: DFF<bool>,
    c3_eq: DFF<bool>,
    c3_lt: DFF<bool>,
    m1: DFF<bool>,
    m2: DFF<bool>,
    m3: DFF<bool>,
    // Stage 9: pick the verdict and write back.
    v9: DFF<bool>,
    ray9: DFF<Bits<10>>,
    id9: DFF<Bits<16>>,
    key9: DFF<Bits<32>>,
    // The writes of the last three clocks (`fw`: the last).
    fw_valid: DFF<bool>,
    fw_ray: DFF<Bits<10>>,
    fw_key: DFF<Bits<32>>,
    fw_id: DFF<Bits<16>>,
    fw2_valid: DFF<bool>,
    fw2_ray: DFF<Bits<10>>,
    fw2_key: DFF<Bits<32>>,
    fw2_id: DFF<Bits<16>>,
    fw3_valid: DFF<bool>,
    meta_hit: Signal<Local, bool>,
    meta_id: Signal<Local, Bits<16>>,
    better: Signal<Local, bool>,
    new_meta: Signal<Local, Bits<17>>,
    // Readout: the clear one clock after the read, and the zeroing of a read of the ray
    // cleared in the same clock.
    rd_valid: DFF<bool>,
    rd_addr: DFF<Bits<10>>,
    z1: DFF<bool>,
    z2: DFF<bool>,
    // Constants (the Verilog-safe way to compare).
    zero11: Constant<Bits<11>>,
    one11: Constant<Bits<11>>,
    one10: Constant<Bits<10>>,
    one32: Constant<Bits<32>>,
    zero32: Constant<Bits<32>>,
    zero16: Constant<Bits<16>>,
    hit_flag: Constant<Bits<17>>,
    zero17: Constant<Bits<17>>,
}

impl Default for IntersectionUnit {
    fn default() -> Self {
        IntersectionUnit {
            clock: Default::default(),
            dir_we: Default::default(),
            dir_addr: Default::default(),
            dir_x: Default::default(),
            dir_y: Default::default(),
            patch_valid: Default::default(),
            patch_ready: Default::default(),
            patch_ax: Default::default(),
            patch_ay: Default::default(),
            patch_bx: Default::default(),
            patch_by: Default::default(),
            patch_wx: Default::default(),
            patch_wy: Default::default(),
            patch_sh: Default::default(),
            patch_id: Default::default(),
            patch_first: Default::default(),
            patch_count: Default::default(),
            patch_retire: Default::default(),
            res_re: Default::default(),
            res_addr: Default::default(),
            res_hit: Default::default(),
            res_id: Default::default(),
            res_key: Default::default(),
            busy: Default::default(),
            tests: Default::default(),
            remaining: Default::default(),
            cur: Default::default(),
            p_ax: Default::default(),
            p_ay: Default::default(),
            p_bx: Default::default(),
            p_by: Default::default(),
            p_wx: Default::default(),
            p_wy: Default::default(),
            p_sh: Default::default(),
            p_id: Default::default(),
            p_retire: Default::default(),
            alive_mem: Default::default(),
            live: Default::default(),
            test_count: Default::default(),
            issue: Default::default(),
            take: Default::default(),
            v1: Default::default(),
            tag1: Default::default(),
            o_ax: Default::default(),
            o_ay: Default::default(),
            o_bx: Default::default(),
            o_by: Default::default(),
            o_wx: Default::default(),
            o_wy: Default::default(),
            v2: Default::default(),
            tag2: Default::default(),
            dir_mem_x: Default::default(),
            dir_mem_y: Default::default(),
            products: Default::default(),
            v3: Default::default(),
            tag3: Default::default(),
            v4: Default::default(),
            tag4: Default::default(),
            ray4: Default::default(),
            sh4: Default::default(),
            id4: Default::default(),
            side_a: Default::default(),
            side_b: Default::default(),
            q: Default::default(),
            v5: Default::default(),
            sa5: Default::default(),
            sb5: Default::default(),
            ray5: Default::default(),
            id5: Default::default(),
            key_scale: Default::default(),
            v6: Default::default(),
            ray6: Default::default(),
            id6: Default::default(),
            v7: Default::default(),
            ray7: Default::default(),
            id7: Default::default(),
            v8: Default::default(),
            ray8: Default::default(),
            id8: Default::default(),
            mem_key: Default::default(),
            mem_meta: Default::default(),
            cm_hit: Default::default(),
            cm_gt: Default::default(),
            cm_eq: Default::default(),
            cm_lt: Default::default(),
            c1_gt: Default::default(),
            c1_eq: Default::default(),
            c1_lt: Default::default(),
            c2_gt: Default::default(),
            c2_eq: Default::default(),
            c2_lt: Default::default(),
            c3_gt: Default::default(),
            c3_eq: Default::default(),
            c3_lt: Default::default(),
            m1: Default::default(),
            m2: Default::default(),
            m3: Default::default(),
            v9: Default::default(),
            ray9: Default::default(),
            id9: Default::default(),
            key9: Default::default(),
            fw_valid: Default::default(),
            fw_ray: Default::default(),
            fw_key: Default::default(),
            fw_id: Default::default(),
            fw2_valid: Default::default(),
            fw2_ray: Default::default(),
            fw2_key: Default::default(),
            fw2_id: Default::default(),
            fw3_valid: Default::default(),
            meta_hit: Default::default(),
            meta_id: Default::default(),
            better: Default::default(),
            new_meta: Default::default(),
            rd_valid: Default::default(),
            rd_addr: Default::default(),
            z1: Default::default(),
            z2: Default::default(),
            zero11: Constant::new(0.into()),
            one11: Constant::new(1.into()),
            one10: Constant::new(1.into()),
            one32: Constant::new(1.into()),
            zero32: Constant::new(0.into()),
            zero16: Constant::new(0.into()),
            hit_flag: Constant::new(0x1_0000u64.into()),
            zero17: Constant::new(0.into()),
        }
    }
}

impl Logic for IntersectionUnit {
    #[hdl_gen]
    fn update(&mut self) {
        // Clocks and register defaults (hold).
        dff_setup!(
            self, clock, remaining, cur, p_ax, p_ay, p_bx, p_by, p_wx, p_wy, p_sh, p_id, p_retire,
            test_count, v1, tag1, o_ax, o_ay, o_bx, o_by, o_wx, o_wy, v2, tag2, v3, tag3, v4, tag4, v5, sa5,
            sb5, ray5, id5, v6, ray6, id6, v7, ray7, id7, v8, ray8, id8, cm_hit, cm_gt, cm_eq, cm_lt, c1_gt,
            c1_eq, c1_lt, c2_gt, c2_eq, c2_lt, c3_gt, c3_eq, c3_lt, m1, m2, m3, v9, ray9, id9, key9,
            fw_valid, fw_ray, fw_key, fw_id, fw2_valid, fw2_ray, fw2_key, fw2_id, fw3_valid, rd_valid,
            rd_addr, z1, z2
        );
        self.dir_mem_x.clock.next = self.clock.val();
        self.alive_mem.clock.next = self.clock.val();
        self.dir_mem_y.clock.next = self.clock.val();
        self.mem_key.clock.next = self.clock.val();
        self.mem_meta.clock.next = self.clock.val();
        self.products.clock.next = self.clock.val();
        self.key_scale.clock.next = self.clock.val();

        // Stage 0: sequencer. A patch is accepted while the current one issues its last ray
        // (or none is active), so back-to-back patches leave no bubble.
        self.issue.next = self.remaining.q.val() != self.zero11.val();
        self.patch_ready.next =
            (self.remaining.q.val() == self.zero11.val()) | (self.remaining.q.val() == self.one11.val());
        self.take.next = self.patch_valid.val()
            & ((self.remaining.q.val() == self.zero11.val()) | (self.remaining.q.val() == self.one11.val()));
        if self.take.val() {
            self.remaining.d.next = self.patch_count.val();
            self.cur.d.next = self.patch_first.val();
            self.p_ax.d.next = self.patch_ax.val();
            self.p_ay.d.next = self.patch_ay.val();
            self.p_bx.d.next = self.patch_bx.val();
            self.p_by.d.next = self.patch_by.val();
            self.p_wx.d.next = self.patch_wx.val();
            self.p_wy.d.next = self.patch_wy.val();
            self.p_sh.d.next = self.patch_sh.val();
            self.p_id.d.next = self.patch_id.val();
            self.p_retire.d.next = self.patch_retire.val();
        } else if self.issue.val() {
            self.remaining.d.next = self.remaining.q.val() - self.one11.val();
            self.cur.d.next = self.cur.q.val() + self.one10.val();
        }
        self.tests.next = self.test_count.q.val();
        self.dir_mem_x.read_address.next = self.cur.q.val();
        self.dir_mem_y.read_address.next = self.cur.q.val();
        self.dir_mem_x.write_address.next = self.dir_addr.val();
        self.dir_mem_y.write_address.next = self.dir_addr.val();
        self.dir_mem_x.write_data.next = self.dir_x.val();
        self.dir_mem_y.write_data.next = self.dir_y.val();
        self.dir_mem_x.write_enable.next = self.dir_we.val();
        self.dir_mem_y.write_enable.next = self.dir_we.val();
        // The live bits: a direction write revives its ray, a retire job's issue kills one.
        // (A retire's issue reads and writes the same word: its read is never used.)
        self.alive_mem.read_address.next = self.cur.q.val();
        self.alive_mem.write_address.next = self.cur.q.val();
        self.alive_mem.write_data.next = false.into();
        self.alive_mem.write_enable.next = self.issue.val() & self.p_retire.q.val();
        if self.dir_we.val() {
            self.alive_mem.write_address.next = self.dir_addr.val();
            self.alive_mem.write_data.next = true.into();
            self.alive_mem.write_enable.next = true;
        }
        self.v1.d.next = self.issue.val() & !self.p_retire.q.val();
        self.tag1.d.next = (bit_cast::<32, 10>(self.cur.q.val()) << 22)
            | (bit_cast::<32, 6>(self.p_sh.q.val()) << 16)
            | bit_cast::<32, 16>(self.p_id.q.val());
        self.o_ax.d.next = self.p_ax.q.val();
        self.o_ay.d.next = self.p_ay.q.val();
        self.o_bx.d.next = self.p_bx.q.val();
        self.o_by.d.next = self.p_by.q.val();
        self.o_wx.d.next = self.p_wx.q.val();
        self.o_wy.d.next = self.p_wy.q.val();

        // Stage 1: the patch operands enter the products leaf; its registers hold them.
        self.products.ax.next = self.o_ax.q.val();
        self.products.ay.next = self.o_ay.q.val();
        self.products.bx.next = self.o_bx.q.val();
        self.products.by.next = self.o_by.q.val();
        self.products.wx.next = self.o_wx.q.val();
        self.products.wy.next = self.o_wy.q.val();
        self.v2.d.next = self.v1.q.val();
        self.tag2.d.next = self.tag1.q.val();

        // Stage 2: the ray's direction arrives; the six products start.
        self.products.dx.next = self.dir_mem_x.read_data.val();
        self.products.dy.next = self.dir_mem_y.read_data.val();
        // A test of a dead ray goes on as a bubble.
        self.live.next = self.v2.q.val() & self.alive_mem.read_data.val().any();
        if self.live.val() {
            self.test_count.d.next = self.test_count.q.val() + self.one32.val();
        }
        self.v3.d.next = self.live.val();
        self.tag3.d.next = self.tag2.q.val();
        self.v4.d.next = self.v3.q.val();
        self.tag4.d.next = self.tag3.q.val();

        // Stage 4: side values and the inverse distance.
        self.ray4.next = self.tag4.q.val().get_bits::<10>(22);
        self.sh4.next = self.tag4.q.val().get_bits::<6>(16);
        self.id4.next = self.tag4.q.val().get_bits::<16>(0);
        self.side_a.next = self.products.dx_ay.val() - self.products.dy_ax.val();
        self.side_b.next = self.products.dx_by.val() - self.products.dy_bx.val();
        self.q.next = self.products.dx_wx.val() + self.products.dy_wy.val();
        self.v5.d.next = self.v4.q.val();
        self.sa5.d.next = self.side_a.val();
        self.sb5.d.next = self.side_b.val();
        self.ray5.d.next = self.ray4.val();
        self.id5.d.next = self.id4.val();

        // Stages 5 to 8: the key q·2^-sh, clamped into [1, 2^32 − 1], in a leaf (its input
        // registers are stage 5, its output register stage 8).
        self.key_scale.q.next = self.q.val();
        self.key_scale.sh.next = self.sh4.val();
        // Stage 5: does the ray hit (s_a ≤ 0 ≤ s_b)?
        self.v6.d.next = self.v5.q.val()
            & ((self.sa5.q.val() == self.zero32.val()) | self.sa5.q.val().get_bit(31))
            & !self.sb5.q.val().get_bit(31);
        self.ray6.d.next = self.ray5.q.val();
        self.id6.d.next = self.id5.q.val();
        self.v7.d.next = self.v6.q.val();
        self.ray7.d.next = self.ray6.q.val();
        self.id7.d.next = self.id6.q.val();
        self.v8.d.next = self.v7.q.val();
        self.ray8.d.next = self.ray7.q.val();
        self.id8.d.next = self.id7.q.val();

        // The ray memory: read for stage 6's ray, or for the host's readout.
        self.mem_key.read_address.next = self.ray6.q.val();
        self.mem_meta.read_address.next = self.ray6.q.val();
        if self.res_re.val() {
            self.mem_key.read_address.next = self.res_addr.val();
            self.mem_meta.read_address.next = self.res_addr.val();
        }

        // Stage 8: the new key and id against each candidate for the ray's nearest hit so far,
        // in parallel: the memory's word (read in stage 6, it has seen the writes up to three
        // clocks before stage 9's) and the three writes after it, stage 9's (this clock's), the
        // last one (fw) and the one before (fw2); and whether the ray is theirs.
        self.meta_hit.next = self.mem_meta.read_data.val().get_bit(16);
        self.meta_id.next = bit_cast::<16, 17>(self.mem_meta.read_data.val());
        self.cm_hit.d.next = self.meta_hit.val();
        self.cm_gt.d.next = self.key_scale.key.val() > self.mem_key.read_data.val();
        self.cm_eq.d.next = self.key_scale.key.val() == self.mem_key.read_data.val();
        self.cm_lt.d.next = self.id8.q.val() < self.meta_id.val();
        self.c1_gt.d.next = self.key_scale.key.val() > self.key9.q.val();
        self.c1_eq.d.next = self.key_scale.key.val() == self.key9.q.val();
        self.c1_lt.d.next = self.id8.q.val() < self.id9.q.val();
        self.c2_gt.d.next = self.key_scale.key.val() > self.fw_key.q.val();
        self.c2_eq.d.next = self.key_scale.key.val() == self.fw_key.q.val();
        self.c2_lt.d.next = self.id8.q.val() < self.fw_id.q.val();
        self.c3_gt.d.next = self.key_scale.key.val() > self.fw2_key.q.val();
        self.c3_eq.d.next = self.key_scale.key.val() == self.fw2_key.q.val();
        self.c3_lt.d.next = self.id8.q.val() < self.fw2_id.q.val();
        self.m1.d.next = self.ray8.q.val() == self.ray9.q.val();
        self.m2.d.next = self.ray8.q.val() == self.fw_ray.q.val();
        self.m3.d.next = self.ray8.q.val() == self.fw2_ray.q.val();
        self.v9.d.next = self.v8.q.val();
        self.ray9.d.next = self.ray8.q.val();
        self.id9.d.next = self.id8.q.val();
        self.key9.d.next = self.key_scale.key.val();

        // Stage 9: the newest write to the ray decides (the last one, fw, is stage 9's of the
        // previous clock); without one, the memory's word. Then write back.
        if self.m1.q.val() & self.fw_valid.q.val() {
            self.better.next =
                self.v9.q.val() & (self.c1_gt.q.val() | (self.c1_eq.q.val() & self.c1_lt.q.val()));
        } else if self.m2.q.val() & self.fw2_valid.q.val() {
            self.better.next =
                self.v9.q.val() & (self.c2_gt.q.val() | (self.c2_eq.q.val() & self.c2_lt.q.val()));
        } else if self.m3.q.val() & self.fw3_valid.q.val() {
            self.better.next =
                self.v9.q.val() & (self.c3_gt.q.val() | (self.c3_eq.q.val() & self.c3_lt.q.val()));
        } else {
            self.better.next = self.v9.q.val()
                & (!self.cm_hit.q.val() | self.cm_gt.q.val() | (self.cm_eq.q.val() & self.cm_lt.q.val()));
        }
        self.new_meta.next = self.hit_flag.val() | bit_cast::<17, 16>(self.id9.q.val());
        self.mem_key.write_address.next = self.ray9.q.val();
        self.mem_meta.write_address.next = self.ray9.q.val();
        self.mem_key.write_data.next = self.key9.q.val();
        self.mem_meta.write_data.next = self.new_meta.val();
        self.mem_key.write_enable.next = self.better.val();
        self.mem_meta.write_enable.next = self.better.val();
        if self.rd_valid.q.val() {
            // Clear a ray read out in the previous clock.
            self.mem_key.write_address.next = self.rd_addr.q.val();
            self.mem_meta.write_address.next = self.rd_addr.q.val();
            self.mem_key.write_data.next = self.zero32.val();
            self.mem_meta.write_data.next = self.zero17.val();
            self.mem_key.write_enable.next = true;
            self.mem_meta.write_enable.next = true;
        }
        self.fw_valid.d.next = self.better.val();
        self.fw_ray.d.next = self.ray9.q.val();
        self.fw_key.d.next = self.key9.q.val();
        self.fw_id.d.next = self.id9.q.val();
        self.fw2_valid.d.next = self.fw_valid.q.val();
        self.fw2_ray.d.next = self.fw_ray.q.val();
        self.fw2_key.d.next = self.fw_key.q.val();
        self.fw2_id.d.next = self.fw_id.q.val();
        self.fw3_valid.d.next = self.fw2_valid.q.val();

        // Readout: the word two clocks after `res_re`; zero when the same ray was read (and
        // is being cleared) in the clock before, whose clear that read could not see.
        self.rd_valid.d.next = self.res_re.val();
        self.rd_addr.d.next = self.res_addr.val();
        self.z1.d.next =
            self.res_re.val() & self.rd_valid.q.val() & (self.res_addr.val() == self.rd_addr.q.val());
        self.z2.d.next = self.z1.q.val();
        self.res_hit.next = self.meta_hit.val() & !self.z2.q.val();
        self.res_id.next = self.meta_id.val();
        self.res_key.next = self.mem_key.read_data.val();
        if self.z2.q.val() {
            self.res_id.next = self.zero16.val();
            self.res_key.next = self.zero32.val();
        }
        self.busy.next = self.issue.val()
            | self.v1.q.val()
            | self.v2.q.val()
            | self.v3.q.val()
            | self.v4.q.val()
            | self.v5.q.val()
            | self.v6.q.val()
            | self.v7.q.val()
            | self.v8.q.val()
            | self.v9.q.val();
    }
}
