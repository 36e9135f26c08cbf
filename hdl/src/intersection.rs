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
//! | `res_hit`, `res_id`, `res_key` | out | 1, 16, 32 | the ray's nearest hit, the cycle after `res_re` |
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
//! Each ray has a live bit (a one-bit [`Bram`] beside the direction memory): writing its
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
//! One test per clock (II = 1) for any mix of bundle lengths; latency 5 clocks from issue to the
//! ray-memory write:
//!
//! * stage 0: the sequencer issues ray `cur` of the current patch (direction memory read);
//! * stage 1: direction and live bit arrive; the six products start in the [`RayProducts`]
//!   leaf (six 18×18 DSP multipliers, latency 2, the patch operands held there one clock
//!   longer); a dead ray's test goes on as a bubble;
//! * stage 3: side values `s_a`, `s_b` and `q = dot(d, W)`;
//! * stage 4: the key (shift by `sh`, saturating, in the [`KeyScale`] leaf); the ray memory is read;
//! * stage 5: compare with the ray's nearest hit and write back.
//!
//! The ray memory (two [`Bram`]s: key, and valid + id) reads before it writes, so a test of the
//! same ray one clock behind (a one-ray bundle, back to back) would see a stale entry: a
//! forwarding register holds the last write and replaces the memory's word when the rays match.
//! Two or more clocks apart, the memory already holds the write.
//!
//! # Models
//!
//! [`model::test`], [`model::key`] and [`model::replaces`] are the bit-true model; the
//! testbench's `intersection::model_bundle` applies them to a whole job stream. Resources
//! (Yosys `synth_ecp5`): 6 `MULT18X18D`, 6 `DP16KD` (directions, live bits, keys, ids), about 700 LUT4
//! and 1100 flip-flops.

use crate::formats::{cross, dot, SH_MAX, SH_MIN};
use crate::leaf::{Bram, KeyScale, RayProducts};
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
    alive_mem: Bram<1, 10>,
    live: Signal<Local, bool>,
    test_count: DFF<Bits<32>>,
    issue: Signal<Local, bool>,
    take: Signal<Local, bool>,
    // Stage 1: directions arrive; the products start (the patch operands' stage-1 registers
    // are inside the products leaf). `tagN` is stage N's ray (bits 31…22), `sh` (21…16) and
    // patch id (15…0).
    v1: DFF<bool>,
    tag1: DFF<Bits<32>>,
    dir_mem_x: Bram<18, 10>,
    dir_mem_y: Bram<18, 10>,
    products: RayProducts,
    // Stages 2 and 3: inside the multipliers; products arrive in stage 3.
    v2: DFF<bool>,
    tag2: DFF<Bits<32>>,
    v3: DFF<bool>,
    tag3: DFF<Bits<32>>,
    ray3: Signal<Local, Bits<10>>,
    sh3: Signal<Local, Bits<6>>,
    id3: Signal<Local, Bits<16>>,
    side_a: Signal<Local, Bits<32>>,
    side_b: Signal<Local, Bits<32>>,
    q: Signal<Local, Bits<32>>,
    // Stage 4: the key; the ray memory is read.
    v4: DFF<bool>,
    ray4: DFF<Bits<10>>,
    id4: DFF<Bits<16>>,
    key_scale: KeyScale,
    // Stage 5: compare with the ray's nearest hit and write back (with forwarding).
    v5: DFF<bool>,
    ray5: DFF<Bits<10>>,
    id5: DFF<Bits<16>>,
    mem_key: Bram<32, 10>,
    mem_meta: Bram<17, 10>,
    fw_valid: DFF<bool>,
    fw_ray: DFF<Bits<10>>,
    fw_key: DFF<Bits<32>>,
    fw_id: DFF<Bits<16>>,
    old_hit: Signal<Local, bool>,
    old_key: Signal<Local, Bits<32>>,
    old_id: Signal<Local, Bits<16>>,
    meta_hit: Signal<Local, bool>,
    meta_id: Signal<Local, Bits<16>>,
    better: Signal<Local, bool>,
    new_meta: Signal<Local, Bits<17>>,
    // Constants (the Verilog-safe way to compare).
    zero11: Constant<Bits<11>>,
    one11: Constant<Bits<11>>,
    one10: Constant<Bits<10>>,
    one32: Constant<Bits<32>>,
    zero32: Constant<Bits<32>>,
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
            dir_mem_x: Default::default(),
            dir_mem_y: Default::default(),
            products: Default::default(),
            v2: Default::default(),
            tag2: Default::default(),
            v3: Default::default(),
            tag3: Default::default(),
            ray3: Default::default(),
            sh3: Default::default(),
            id3: Default::default(),
            side_a: Default::default(),
            side_b: Default::default(),
            q: Default::default(),
            v4: Default::default(),
            ray4: Default::default(),
            id4: Default::default(),
            key_scale: Default::default(),
            v5: Default::default(),
            ray5: Default::default(),
            id5: Default::default(),
            mem_key: Default::default(),
            mem_meta: Default::default(),
            fw_valid: Default::default(),
            fw_ray: Default::default(),
            fw_key: Default::default(),
            fw_id: Default::default(),
            old_hit: Default::default(),
            old_key: Default::default(),
            old_id: Default::default(),
            meta_hit: Default::default(),
            meta_id: Default::default(),
            better: Default::default(),
            new_meta: Default::default(),
            zero11: Constant::new(0.into()),
            one11: Constant::new(1.into()),
            one10: Constant::new(1.into()),
            one32: Constant::new(1.into()),
            zero32: Constant::new(0.into()),
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
            test_count, v1, tag1, v2, tag2, v3, tag3, v4, ray4, id4, v5, ray5, id5, fw_valid, fw_ray, fw_key,
            fw_id
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
        // The patch operands enter the products leaf now; its stage-1 registers hold them.
        self.products.ax.next = self.p_ax.q.val();
        self.products.ay.next = self.p_ay.q.val();
        self.products.bx.next = self.p_bx.q.val();
        self.products.by.next = self.p_by.q.val();
        self.products.wx.next = self.p_wx.q.val();
        self.products.wy.next = self.p_wy.q.val();

        // Stage 1: the ray's direction is read; the six products start.
        self.products.dx.next = self.dir_mem_x.read_data.val();
        self.products.dy.next = self.dir_mem_y.read_data.val();
        // A test of a dead ray goes on as a bubble.
        self.live.next = self.v1.q.val() & self.alive_mem.read_data.val().any();
        if self.live.val() {
            self.test_count.d.next = self.test_count.q.val() + self.one32.val();
        }
        self.v2.d.next = self.live.val();
        self.tag2.d.next = self.tag1.q.val();
        self.v3.d.next = self.v2.q.val();
        self.tag3.d.next = self.tag2.q.val();

        // Stage 3: side values and the inverse distance.
        self.ray3.next = self.tag3.q.val().get_bits::<10>(22);
        self.sh3.next = self.tag3.q.val().get_bits::<6>(16);
        self.id3.next = self.tag3.q.val().get_bits::<16>(0);
        self.side_a.next = self.products.dx_ay.val() - self.products.dy_ax.val();
        self.side_b.next = self.products.dx_by.val() - self.products.dy_bx.val();
        self.q.next = self.products.dx_wx.val() + self.products.dy_wy.val();
        self.v4.d.next = self.v3.q.val()
            & ((self.side_a.val() == self.zero32.val()) | self.side_a.val().get_bit(31))
            & !self.side_b.val().get_bit(31);
        self.ray4.d.next = self.ray3.val();
        self.id4.d.next = self.id3.val();

        // Stages 4 and 5: the key q·2^-sh, clamped into [1, 2^32 − 1], in a leaf (its input
        // registers are stage 4, its output register stage 5).
        self.key_scale.q.next = self.q.val();
        self.key_scale.sh.next = self.sh3.val();
        self.v5.d.next = self.v4.q.val();
        self.ray5.d.next = self.ray4.q.val();
        self.id5.d.next = self.id4.q.val();

        // The ray memory: read for stage 4's ray, or for the host's readout.
        self.mem_key.read_address.next = self.ray4.q.val();
        self.mem_meta.read_address.next = self.ray4.q.val();
        if self.res_re.val() {
            self.mem_key.read_address.next = self.res_addr.val();
            self.mem_meta.read_address.next = self.res_addr.val();
        }

        // Stage 5: the ray's nearest hit so far, forwarded from the previous cycle's write when
        // it is the same ray (the read-modify-write hazard of a one-ray bundle).
        self.meta_hit.next = self.mem_meta.read_data.val().get_bit(16);
        self.meta_id.next = bit_cast::<16, 17>(self.mem_meta.read_data.val());
        self.old_hit.next = self.meta_hit.val();
        self.old_key.next = self.mem_key.read_data.val();
        self.old_id.next = self.meta_id.val();
        if self.fw_valid.q.val() & (self.fw_ray.q.val() == self.ray5.q.val()) {
            self.old_hit.next = true;
            self.old_key.next = self.fw_key.q.val();
            self.old_id.next = self.fw_id.q.val();
        }
        self.better.next = self.v5.q.val()
            & (!self.old_hit.val()
                | (self.key_scale.key.val() > self.old_key.val())
                | ((self.key_scale.key.val() == self.old_key.val())
                    & (self.id5.q.val() < self.old_id.val())));
        self.new_meta.next = self.hit_flag.val() | bit_cast::<17, 16>(self.id5.q.val());
        self.mem_key.write_address.next = self.ray5.q.val();
        self.mem_meta.write_address.next = self.ray5.q.val();
        self.mem_key.write_data.next = self.key_scale.key.val();
        self.mem_meta.write_data.next = self.new_meta.val();
        self.mem_key.write_enable.next = self.better.val();
        self.mem_meta.write_enable.next = self.better.val();
        if self.res_re.val() {
            // Read and clear.
            self.mem_key.write_address.next = self.res_addr.val();
            self.mem_meta.write_address.next = self.res_addr.val();
            self.mem_key.write_data.next = self.zero32.val();
            self.mem_meta.write_data.next = self.zero17.val();
            self.mem_key.write_enable.next = true;
            self.mem_meta.write_enable.next = true;
        }
        self.fw_valid.d.next = self.better.val();
        self.fw_ray.d.next = self.ray5.q.val();
        self.fw_key.d.next = self.key_scale.key.val();
        self.fw_id.d.next = self.id5.q.val();

        // Readout and status.
        self.res_hit.next = self.meta_hit.val();
        self.res_id.next = self.meta_id.val();
        self.res_key.next = self.mem_key.read_data.val();
        self.busy.next = self.issue.val()
            | self.v1.q.val()
            | self.v2.q.val()
            | self.v3.q.val()
            | self.v4.q.val()
            | self.v5.q.val();
    }
}
