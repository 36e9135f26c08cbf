//! The intersection unit: a patch, set up once by the screener, is tested against a bundle of
//! rays streamed past it, one ray-patch test per clock, and every ray keeps its nearest hit in a
//! ray memory of two halves: one bundle's tests run in one half while the host reads the last
//! bundle out of the other and writes the next one's directions into it.
//!
//! # Ports ([`IntersectionUnit`])
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | rising-edge clock |
//! | `dir_we`, `dir_addr`, `dir_x`, `dir_y` | in | 1, 11, 18, 18 | bundle setup: write ray `dir_addr`'s direction (bit 10: the half) and make it live |
//! | `patch_valid`, `patch_ready` | in, out | 1, 1 | patch stream (valid/ready) |
//! | `patch_ax`, `patch_ay`, `patch_bx`, `patch_by` | in | 4 × 18 | endpoints relative to the origin |
//! | `patch_wx`, `patch_wy`, `patch_sh` | in | 18, 18, 6 | inverse-distance vector and its exponent |
//! | `patch_id`, `patch_first`, `patch_count` | in | 16, 11, 11 | patch id; test rays `first .. first + count` (the low 10 bits mod 1024: a range stays in the half of `first`'s bit 10) |
//! | `patch_retire` | in | 1 | instead of testing, retire rays `first .. first + count` (the patch fields are ignored); with `count = 0` a **marker** |
//! | `res_re`, `res_addr` | in | 1, 11 | readout: read and clear ray `res_addr` (only in a half no test in flight touches: after the marker behind its bundle's last job is counted) |
//! | `res_hit`, `res_id`, `res_key` | out | 1, 16, 32 | the ray's nearest hit, two cycles after `res_re` ([`READOUT_LATENCY`]) |
//! | `busy` | out | 1 | a test or a marker is issuing or in flight (a test may still update the ray memory) |
//! | `tests` | out | 32 | ray-patch tests of live rays so far (wraps) |
//! | `marks` | out | 32 | markers counted so far (wraps): each in the clock after the write-back of the last test issued before it |
//!
//! A patch transfers when `patch_valid && patch_ready` before the rising edge. `patch_ready` is
//! high while fewer than two rays of the current patch remain, so the next patch is taken while
//! the current one issues its last ray: back-to-back patches leave no bubble, and a patch with
//! `patch_count = 0` is consumed in one cycle. `patch_ready` is a register (the sequencer keeps
//! `remaining > 1` in one beside the count).
//!
//! # Two halves and markers
//!
//! The ray memory holds 2048 rays, two bundles of up to 1024: bit 10 of a ray index is its half.
//! The directions are one 2048-word memory (the host writes, the tests read: separate ports);
//! the live bits, the keys and the hit records are a memory per half, each with its own ports,
//! so that the host's readout of one half (a read and a clear) and its direction writes (the
//! live bit) never meet the tests of the other half on a port. The host keeps to one rule: it
//! touches a half (directions or readout) only while no test of it is in flight. A **marker**,
//! a retire job of no rays, tells it when: the unit counts it on `marks` in the clock after the
//! write-back of the last test issued before it (it rides the pipeline beside that test, one
//! register per stage), so a host that ends each bundle's jobs with a marker reads the bundle
//! out once `marks` has counted it, while the next bundle's jobs run in the other half. A
//! marker costs no issue slot. With one bundle in half 0 and no marker the unit is the
//! one-bundle unit of before: the host writes, streams, waits for `busy` to fall, reads out.
//!
//! # Live rays
//!
//! Each ray has a live bit (a one-bit [`BramOut`] per half): writing its direction makes it
//! live, a retire job (`patch_retire`) kills the rays of its range, one per clock through the
//! same sequencer as a test, so it takes effect in stream order. A test of a dead ray occupies
//! its issue slot but neither counts nor writes (the shelling techniques' tracking: a ray that
//! found its hit leaves the bundle). All rays are dead at power-up.
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
//! * stage 0: the sequencer issues ray `cur` of the current patch (direction and both halves'
//!   live-bit reads; the ray's half picks one in stage 2);
//! * stage 1: the patch operands enter the [`RayProductsPipe`] leaf (which holds them a clock);
//! * stage 2: direction and live bit arrive; the six products start (six 18×18 DSP
//!   multipliers, latency 2); a dead ray's test goes on as a bubble and is not counted;
//! * stage 4: side values `s_a`, `s_b` and `q = dot(d, W)` (registered); `q` enters the
//!   [`KeyScalePipe`] leaf (shift by `sh`, saturating, in three register stages);
//! * stage 5: the hit decision, `s_a ≤ 0 ≤ s_b`;
//! * stage 6: the ray memory is read (both halves, at the ray's word; a half being read out reads
//!   the host's word instead);
//! * stage 8: the key and both halves' words arrive; the new key and id are compared with each
//!   candidate for the ray's nearest hit (registered: larger key, equal key, lower id), with
//!   both halves' words, so that no multiplexer follows a block RAM's output;
//! * stage 9: the newest candidate (or the word of the ray's half) picks the verdict; write back
//!   into the ray's half at the end of the clock.
//!
//! Every register of the unit is in a hand-written leaf ([`stages`]; a Rust model on plain
//! integers and a Verilog body), so that a settle pass of the simulation visits a handful of
//! blocks instead of some eighty `DFF`s: [`IssueSequencer`] (stages 0 and 1: the sequencer,
//! the current patch, the issued ray's operands and tag), [`RayProductsPipe`] and
//! [`KeyScalePipe`] (products and key), [`HitPipe`] (stages 2 to 8 but for those: live bit,
//! test counter, side values, hit decision, each test's ray and id, the markers), [`NearestMerge`]
//! (stages 8 and 9: comparisons, forwarding, verdict, write-back, the readout's clear and the
//! marker count), and the eight [`BramOut`]s. The unit's own logic is wiring, the memories'
//! address multiplexers and the readout's choice of half and zeroing, all combinational. (As 73 `DFF`s of the unit, the registers cost the
//! simulation 2.7 times as long: PERFORMANCE.md, "Speed".)
//!
//! `tests` counts a live test three clocks after its issue.
//!
//! **Forwarding.** The ray memory (per half two [`BramOut`]s: key, and valid + id) is read in stage 6,
//! so the word arriving in stage 8 has seen the writes of the tests issued four or more clocks
//! before, but not those of the three tests right before: their writes end stage 9 one and two
//! clocks after the read, and in the clock of the read (a same-address read and write, whose
//! result the block RAM does not define and [`BramOut`] poisons). In stage 8 the new key is
//! compared, in parallel, with the memory's word, with the key of the test in stage 9 (whose
//! verdict is being made) and with the last two writes (`fw_*`, `fw2_*`, registers of
//! [`NearestMerge`]); whether the ray is
//! theirs is compared there too (`m1`…`m3`). In stage 9 the newest write to the ray among the
//! three (`fw_valid`…`fw3_valid`: the verdicts of the last three clocks) decides; without one,
//! the memory's word. Every comparison starts from registers or from the block RAM's output
//! register and ends in a register; dead tests and misses write nothing. Writes to the live
//! bits never meet a read that should see them (a retire's issue reads its own ray and ignores
//! it; directions are written only into a half no test is in).
//!
//! **Readout.** `res_re` reads the ray memory's half of `res_addr` (address in the clock of
//! `res_re`, the word two clocks later on `res_*`) and clears the ray one clock later on that
//! half's write port (a write in the clock of its own read would collide), beside the other
//! half's write-backs. A readout of the same ray in the next clock cannot see that clear, so it
//! reports no hit (zero), which is what the clear leaves. Readouts stream one per clock; a half
//! is read out once the marker behind its bundle is counted, or once `busy` is low (so every
//! write to it has ended before a readout's read).
//!
//! Resources (`cargo xtask fpga --blocks intersection_unit --families ecp5`: Yosys `synth_ecp5`
//! with `SHELLING_ECP5`, nextpnr-ecp5 on the LFE5U-85F-6, seed 1): 6 `MULT18X18D` (with their
//! input and output registers), 12 `DP16KD` (directions 4, and per half live bits 1, keys 2,
//! valid + id 1, all with the output register), 1355 LUT4s and 1082 flip-flops; over placement
//! seeds 1–5 a median of 168.8 MHz (160.6–170.1; `hdl/fpga/ecp5.md`; 164.0, 159.8–172.7,
//! before the sequencer kept `remaining ≠ 0` in a register; 163.5, 156.3–172.9, with one
//! half). With the key's lower half and the id combined before their register the median
//! was 137.6 MHz (123.7–157.5). In the whole PE the merge's write enable, from the forwarding
//! choice (`m1`) to a ray-memory tile placed far off, was the critical path at one seed of five
//! (7.13 ns).
//!
//! # Models
//!
//! [`model::test`], [`key`] and [`model::replaces`] are the bit-true model (the key and the
//! [`Nearest`] record live in [`crate::formats`], shared with the stages and the hosts); the
//! testbench's `intersection::model_bundle` applies them to a whole job stream.

use crate::formats::{cross, dot, key, Nearest, PatchSetup};
use crate::prim::BramOut;
use rust_hdl::prelude::*;

pub mod stages;

use stages::{HitPipe, IssueSequencer, KeyScalePipe, NearestMerge, RayProductsPipe, KEY_PIPE_LATENCY};

/// The bit-true model of the intersection unit.
pub mod model {
    use super::*;

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

/// Bundle size limit of the unit: a bundle's ray indices are 10 bits (one half of the ray
/// memory; the unit's ray indices are [`RAY_BITS`] + 1 bits, the top one the half).
pub const RAY_BITS: usize = 10;

/// Clocks from a ray's issue (stage 0) to its ray-memory write (the end of stage 9).
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
    pub dir_addr: Signal<In, Bits<11>>,
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
    pub patch_first: Signal<In, Bits<11>>,
    pub patch_count: Signal<In, Bits<11>>,
    pub patch_retire: Signal<In, bool>,
    // Result readout (read and clear), only in a half with no test in flight.
    pub res_re: Signal<In, bool>,
    pub res_addr: Signal<In, Bits<11>>,
    pub res_hit: Signal<Out, bool>,
    pub res_id: Signal<Out, Bits<16>>,
    pub res_key: Signal<Out, Bits<32>>,
    // Status.
    pub busy: Signal<Out, bool>,
    pub tests: Signal<Out, Bits<32>>,
    pub marks: Signal<Out, Bits<32>>,
    // Stages 0 and 1: the sequencer, the current patch, the issued ray's operands.
    seq: IssueSequencer,
    /// The live bits of each half.
    alive0: BramOut<1, 10>,
    alive1: BramOut<1, 10>,
    // Stage 2: directions and live bit arrive; the six products start (stage 4: they arrive).
    dir_mem_x: BramOut<18, 11>,
    dir_mem_y: BramOut<18, 11>,
    products: RayProductsPipe,
    // Stages 2 to 8: live bit, side values, hit decision; the key from stage 4's `q` on.
    pipe: HitPipe,
    key_scale: KeyScalePipe,
    // Stages 8 and 9: the ray memory (read in stage 6), the verdict and the write-back.
    mem_key0: BramOut<32, 10>,
    mem_meta0: BramOut<17, 10>,
    mem_key1: BramOut<32, 10>,
    mem_meta1: BramOut<17, 10>,
    merge: NearestMerge,
    /// The low 10 bits of `dir_addr`, `res_addr` and the issued ray: the word in its half.
    dir_word: Signal<Local, Bits<10>>,
    res_word: Signal<Local, Bits<10>>,
    cur_word: Signal<Local, Bits<10>>,
    ray6_word: Signal<Local, Bits<10>>,
    // Constants (the Verilog-safe way to compare).
    zero32: Constant<Bits<32>>,
    zero16: Constant<Bits<16>>,
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
            marks: Default::default(),
            seq: Default::default(),
            alive0: Default::default(),
            alive1: Default::default(),
            dir_mem_x: Default::default(),
            dir_mem_y: Default::default(),
            products: Default::default(),
            pipe: Default::default(),
            key_scale: Default::default(),
            mem_key0: Default::default(),
            mem_meta0: Default::default(),
            mem_key1: Default::default(),
            mem_meta1: Default::default(),
            merge: Default::default(),
            dir_word: Default::default(),
            res_word: Default::default(),
            cur_word: Default::default(),
            ray6_word: Default::default(),
            zero32: Constant::new(0.into()),
            zero16: Constant::new(0.into()),
        }
    }
}

impl Logic for IntersectionUnit {
    #[hdl_gen]
    fn update(&mut self) {
        self.seq.clock.next = self.clock.val();
        self.alive0.clock.next = self.clock.val();
        self.alive1.clock.next = self.clock.val();
        self.dir_mem_x.clock.next = self.clock.val();
        self.dir_mem_y.clock.next = self.clock.val();
        self.products.clock.next = self.clock.val();
        self.pipe.clock.next = self.clock.val();
        self.key_scale.clock.next = self.clock.val();
        self.mem_key0.clock.next = self.clock.val();
        self.mem_meta0.clock.next = self.clock.val();
        self.mem_key1.clock.next = self.clock.val();
        self.mem_meta1.clock.next = self.clock.val();
        self.dir_word.next = bit_cast::<10, 11>(self.dir_addr.val());
        self.res_word.next = bit_cast::<10, 11>(self.res_addr.val());
        self.cur_word.next = bit_cast::<10, 11>(self.seq.cur.val());
        self.ray6_word.next = bit_cast::<10, 11>(self.pipe.ray6.val());
        self.merge.clock.next = self.clock.val();

        // Stage 0: the sequencer takes a patch while the current one issues its last ray (or
        // none is active), so back-to-back patches leave no bubble.
        self.seq.patch_valid.next = self.patch_valid.val();
        self.seq.patch_ax.next = self.patch_ax.val();
        self.seq.patch_ay.next = self.patch_ay.val();
        self.seq.patch_bx.next = self.patch_bx.val();
        self.seq.patch_by.next = self.patch_by.val();
        self.seq.patch_wx.next = self.patch_wx.val();
        self.seq.patch_wy.next = self.patch_wy.val();
        self.seq.patch_sh.next = self.patch_sh.val();
        self.seq.patch_id.next = self.patch_id.val();
        self.seq.patch_first.next = self.patch_first.val();
        self.seq.patch_count.next = self.patch_count.val();
        self.seq.patch_retire.next = self.patch_retire.val();
        self.patch_ready.next = !self.seq.full.val();
        self.dir_mem_x.read_address.next = self.seq.cur.val();
        self.dir_mem_y.read_address.next = self.seq.cur.val();
        self.dir_mem_x.write_address.next = self.dir_addr.val();
        self.dir_mem_y.write_address.next = self.dir_addr.val();
        self.dir_mem_x.write_data.next = self.dir_x.val();
        self.dir_mem_y.write_data.next = self.dir_y.val();
        self.dir_mem_x.write_enable.next = self.dir_we.val();
        self.dir_mem_y.write_enable.next = self.dir_we.val();
        // The live bits, a memory per half: a direction write revives its ray, a retire job's
        // issue kills one. (A retire's issue reads and writes the same word: its read is never
        // used. The host writes directions only into the half the tests are not in.)
        self.alive0.read_address.next = self.cur_word.val();
        self.alive0.write_address.next = self.cur_word.val();
        self.alive0.write_data.next = false.into();
        self.alive0.write_enable.next = self.seq.kill.val() & !self.seq.cur.val().get_bit(10);
        if self.dir_we.val() & !self.dir_addr.val().get_bit(10) {
            self.alive0.write_address.next = self.dir_word.val();
            self.alive0.write_data.next = true.into();
            self.alive0.write_enable.next = true;
        }
        self.alive1.read_address.next = self.cur_word.val();
        self.alive1.write_address.next = self.cur_word.val();
        self.alive1.write_data.next = false.into();
        self.alive1.write_enable.next = self.seq.kill.val() & self.seq.cur.val().get_bit(10);
        if self.dir_we.val() & self.dir_addr.val().get_bit(10) {
            self.alive1.write_address.next = self.dir_word.val();
            self.alive1.write_data.next = true.into();
            self.alive1.write_enable.next = true;
        }

        // Stage 1: the patch operands enter the products leaf; its registers hold them.
        self.products.ax.next = self.seq.o_ax.val();
        self.products.ay.next = self.seq.o_ay.val();
        self.products.bx.next = self.seq.o_bx.val();
        self.products.by.next = self.seq.o_by.val();
        self.products.wx.next = self.seq.o_wx.val();
        self.products.wy.next = self.seq.o_wy.val();
        self.pipe.v1.next = self.seq.v1.val();
        self.pipe.tag1.next = self.seq.tag1.val();
        self.pipe.mark1.next = self.seq.mark1.val();

        // Stage 2: the ray's direction and live bit arrive; the six products start.
        self.products.dx.next = self.dir_mem_x.read_data.val();
        self.products.dy.next = self.dir_mem_y.read_data.val();
        self.pipe.alive0.next = self.alive0.read_data.val().any();
        self.pipe.alive1.next = self.alive1.read_data.val().any();
        self.tests.next = self.pipe.tests.val();

        // Stage 4: the products arrive: the side values (into the pipe leaf) and the inverse
        // distance q = dot(d, W) (into the key leaf: the key q·2^-sh, clamped into
        // [1, 2^32 − 1], in stage 8).
        self.pipe.dx_ay.next = self.products.dx_ay.val();
        self.pipe.dy_ax.next = self.products.dy_ax.val();
        self.pipe.dx_by.next = self.products.dx_by.val();
        self.pipe.dy_bx.next = self.products.dy_bx.val();
        self.key_scale.q.next = self.products.dx_wx.val() + self.products.dy_wy.val();
        self.key_scale.sh.next = self.pipe.sh4.val();

        // The ray memory, a memory per half: read for stage 6's ray, or for the host's readout
        // in its half.
        self.mem_key0.read_address.next = self.ray6_word.val();
        self.mem_meta0.read_address.next = self.ray6_word.val();
        self.mem_key1.read_address.next = self.ray6_word.val();
        self.mem_meta1.read_address.next = self.ray6_word.val();
        if self.res_re.val() & !self.res_addr.val().get_bit(10) {
            self.mem_key0.read_address.next = self.res_word.val();
            self.mem_meta0.read_address.next = self.res_word.val();
        }
        if self.res_re.val() & self.res_addr.val().get_bit(10) {
            self.mem_key1.read_address.next = self.res_word.val();
            self.mem_meta1.read_address.next = self.res_word.val();
        }

        // Stages 8 and 9: the new hit against the ray's nearest so far, and the write-back
        // (or a readout's clear), each half on its own port.
        self.merge.v8.next = self.pipe.v8.val();
        self.merge.tag8.next = self.pipe.tag8.val();
        self.merge.mark8.next = self.pipe.mark8.val();
        self.merge.key.next = self.key_scale.key.val();
        self.merge.mem_key0.next = self.mem_key0.read_data.val();
        self.merge.mem_meta0.next = self.mem_meta0.read_data.val();
        self.merge.mem_key1.next = self.mem_key1.read_data.val();
        self.merge.mem_meta1.next = self.mem_meta1.read_data.val();
        self.merge.res_re.next = self.res_re.val();
        self.merge.res_addr.next = self.res_addr.val();
        self.mem_key0.write_address.next = self.merge.write_address0.val();
        self.mem_meta0.write_address.next = self.merge.write_address0.val();
        self.mem_key0.write_data.next = self.merge.write_key0.val();
        self.mem_meta0.write_data.next = self.merge.write_meta0.val();
        self.mem_key0.write_enable.next = self.merge.write_enable0.val();
        self.mem_meta0.write_enable.next = self.merge.write_enable0.val();
        self.mem_key1.write_address.next = self.merge.write_address1.val();
        self.mem_meta1.write_address.next = self.merge.write_address1.val();
        self.mem_key1.write_data.next = self.merge.write_key1.val();
        self.mem_meta1.write_data.next = self.merge.write_meta1.val();
        self.mem_key1.write_enable.next = self.merge.write_enable1.val();
        self.mem_meta1.write_enable.next = self.merge.write_enable1.val();
        self.marks.next = self.merge.marks.val();

        // Readout: the word of its half two clocks after `res_re`; zero when the same ray was
        // read (and is being cleared) in the clock before, whose clear that read could not see.
        self.res_hit.next = self.mem_meta0.read_data.val().get_bit(16) & !self.merge.z2.val();
        self.res_id.next = bit_cast::<16, 17>(self.mem_meta0.read_data.val());
        self.res_key.next = self.mem_key0.read_data.val();
        if self.merge.res_half.val() {
            self.res_hit.next = self.mem_meta1.read_data.val().get_bit(16) & !self.merge.z2.val();
            self.res_id.next = bit_cast::<16, 17>(self.mem_meta1.read_data.val());
            self.res_key.next = self.mem_key1.read_data.val();
        }
        if self.merge.z2.val() {
            self.res_id.next = self.zero16.val();
            self.res_key.next = self.zero32.val();
        }
        self.busy.next = self.seq.busy.val() | self.pipe.busy.val() | self.merge.busy.val();
    }
}
