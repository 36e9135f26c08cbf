//! The processing element (PE): patch loader → backface screener → intersection unit, fed by a
//! command stream from the shell scheduler, with one port to the host memory.
//!
//! # Purpose
//!
//! One PE traces one source's bundle (up to 1024 rays) at a time, and the next source's beside
//! it: its ray memory has two halves (see [`crate::intersection`]). The host writes a source's
//! ray directions into a half, then streams commands, each one item of the work stream
//! (`src/workstream.rs`), the ray ranges in that half:
//!
//! * a **sector** (`cmd_sector`): the sector's first and last ray directions (`first_*`,
//!   `last_*`) and the source's origin and normal (`origin_*`, `normal_*`), all taken with the
//!   command; the jobs after it are screened for them;
//! * a **job**: load patch `cmd_id` from host memory, screen it for its sector and, if it
//!   passes, test it against the live rays `cmd_first .. cmd_first + cmd_count`;
//! * a **retire**: rays `cmd_first .. cmd_first + cmd_count` leave the bundle (tracking); a
//!   retire of no rays is a **marker**, counted on `marks` once every test before it has
//!   written its hit.
//!
//! Commands take effect in stream order: a retire reaches the intersection unit after every job
//! sent before it, and before any job sent after it, although jobs spend the loader's and the
//! screener's latency on the way and retires do not; a job is screened for the last sector sent
//! before it, although the next sector may arrive while it is still in the loader (the
//! paper's Figure 12, its steps overlapped: the PE never drains between sectors, nor between
//! sources). A source's nearest hits are read from its half once `marks` has counted the marker
//! that ends its commands (or when the PE is idle), while the next source's commands run in the
//! other half and the directions of the one after are written beside the readout.
//!
//! # Ports ([`ProcessingElement`])
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | rising-edge clock |
//! | `dir_we`, `dir_addr`, `dir_x`, `dir_y` | in | 1, 11, 18, 18 | write ray `dir_addr`'s direction (Q2.16; bit 10 the half); the ray becomes live |
//! | `origin_x/y`, `normal_x/y` | in | 17, 18 | the source (the screener's setup), taken with a sector command |
//! | `cmd_valid`, `cmd_ready` | in, out | 1, 1 | command stream (valid/ready) |
//! | `cmd_sector`, `cmd_retire` | in | 1, 1 | a sector, a retire, or (both low) a job |
//! | `first_x/y`, `last_x/y` | in | 18 | a sector command's first and last ray (Q2.16) |
//! | `cmd_id`, `cmd_first`, `cmd_count` | in | 16, 11, 11 | a job's patch id; a job's or a retire's ray range (in the half of `cmd_first`'s bit 10) |
//! | `cfg_cache_enable`, `cfg_cache_mask` | in | 1, 10 | the patch cache: on, and its lines − 1 (a power of two up to 1024), held during a run |
//! | `cfg_cache_flush` | in | 1 | invalidate the cache (a new scene in the host memory): raise while not `busy`; `busy` stays high for the 1024 cycles it takes ([`PatchCache`]) |
//! | `mem_req`, `mem_addr` | out | 1, 16 | host memory request (one pulse per patch) |
//! | `mem_valid`, `mem_ax` … `mem_by` | in | 1, 4 × 17 | host memory response, in request order (world coordinates, Q11.6) |
//! | `res_re`, `res_addr`, `res_hit`, `res_id`, `res_key` | in, in, out, out, out | 1, 11, 1, 16, 32 | read and clear ray `res_addr`'s nearest hit (two cycles after, [`crate::intersection::READOUT_LATENCY`]; only in a half whose marker is counted, or while not `busy`) |
//! | `busy` | out | 1 | a command is in flight (a sector waiting included), or the cache is flushing |
//! | `loads`, `cache_hits`, `cache_misses`, `passed`, `backward`, `back_facing`, `outside`, `near`, `tests` | out | 32 each | counters (wrapping): patches loaded, the cache's hits and misses, the screener's verdicts, ray-patch tests of live rays |
//! | `marks` | out | 32 | markers counted (wrapping; [`crate::intersection`]) |
//!
//! # Structure
//!
//! The loader's memory port goes through the [`PatchCache`] to the host port: with the cache off
//! it is a wire (the paper's shared memory, every load `T_c`); with it on, a patch loaded before
//! comes from block RAM (the paper's "high speed cache memory for each PE"), one per clock, 8
//! cycles after its request, and a miss does not hold the requests behind it (up to four misses
//! at the host at once; the answers in request order).
//!
//! Every command accepted writes a **tag** (first, count, and whether it is a job's or a
//! retire's, in LUT RAM) into a [`TAG_DEPTH`]-entry FIFO; a job also hands its id to the [`PatchLoader`]. The loader's patches go
//! through the [`Screener`], which reports every patch in order, passed or not (`out_pass`). The
//! **merger** at the intersection unit's input pairs the oldest tag with what it waits for: a
//! retire goes straight to the [`IntersectionUnit`] as a retire job; a job waits for its patch's
//! verdict, then goes to the unit with the tag's ray range if it passed, or is dropped.
//!
//! A [`PatchSlice`] (two entries, `in_ready` a register) sits between the screener and the
//! merger and a [`JobQueue`] between the merger and the unit: every input of the merger is a
//! register, and the unit's `patch_ready` reaches only the queue, never the screener's output
//! FIFO or the tag FIFO. The tag FIFO (a [`FifoControl`] over two [`FifoRam`] lanes) reads its
//! head and the entry after it every cycle, so that no RAM address depends on the merger's pop
//! either; its lane of the tags' kinds holds the head's kind in a register of its own
//! ([`FifoRam::head_registered`]), so that the merger's decisions are one gate of registers.
//!
//! **The job queue.** The second slice is a 16-entry [`JobQueue`] (LUT RAM): the merger pushes
//! passed jobs and retires into it and drops screened-out patches, and so runs up to sixteen
//! jobs ahead of the unit: the patches screened out behind a long job cost the unit nothing.
//!
//! **Sectors, overlapped.** The PE holds two sectors (two banks of first and last ray, and of
//! the source's origin and normal, in registers) and the bank the jobs being accepted belong
//! to. Each job's bank goes into a
//! FIFO beside the loader as its id goes in (`job_banks`, with that bank's origin), leaves it as
//! the screener takes the patch (`in_bank`), and rides the screener's pipeline to its stage 3,
//! where the screener reads the sector (`sector_bank`): the PE presents that bank's first and
//! last ray, the origin the job brought through the FIFO (no bank multiplexer before stage
//! 0's subtraction) and the normal of the
//! bank of the patch in its stage 1 (`normal_bank`). So a source change is a sector change:
//! the next source's first sector command brings its origin and normal.
//! Each bank counts its jobs accepted and not yet past that read (`jobs0`, `jobs1`). A sector
//! command takes the other bank at once if that bank's count is zero, or waits in a register
//! (`pend`) until it is, with `cmd_ready` low meanwhile; then the accepted jobs' bank flips, and
//! the bank loads the sector a clock later from a staging register that takes the command's
//! sector fields in every clock no sector waits (so every clock enable of the sectors' registers
//! is a register: `pend`, `load0`, `load1`; a job accepted in the clock its bank loads takes
//! its origin from the staging register). So
//! a sector change stalls the stream only while the sector before last still has jobs before
//! the screener's stage 3: with sectors of a few jobs and a long memory latency. Jobs before
//! the first sector command are screened for a zero sector, origin and normal (the host always
//! sends one first).
//!
//! `cmd_ready` is high while the tag FIFO has room, the loader can take an id and no sector
//! waits (for every kind of command: the condition must not depend on `cmd_retire` or
//! `cmd_sector`); it is one register (`stall`, its complement), set from the next values of
//! `tags_full`, the loader's `full` and `pend`, so that the command handshake reaches the tag
//! FIFO's write enables through one gate.
//!
//! # Latency and throughput
//!
//! A job reaches the intersection unit the loader's latency (`T_c + 3` without a cache) plus the
//! screener's plus the slice's (one clock) and the queue's (three: its input register, then
//! two) after it is accepted; the unit then issues
//! one ray per clock. Commands are taken one per clock and jobs stream back to back at one per
//! clock through the loader, the screener, the slice and the queue, so in steady state the PE
//! is bound by the slowest of the command stream (one command per clock: sectors, jobs and
//! retires), the host memory (one patch per `T_c`) and the intersection unit (one ray per
//! clock, tested or retired), the balance Section 4 of the paper is about. A testbench on
//! rust-hdl's simulation reads which of them holds the command stream, or starves the unit, and
//! whether the cache's lookups wait for a fill, in each cycle from
//! [`ProcessingElement::watch`] (`figures/stalls.md`).
//!
//! # Resources
//!
//! Yosys `synth_ecp5` and nextpnr-ecp5 of the whole PE (with a 1024-line cache, in the FPGA
//! flow's register wrapper, wrapper excluded): 10906 LUT4s, 7835 flip-flops, 16 `MULT18X18D`,
//! 17 `DP16KD` (the cache's five, the unit's twelve), 452 LUT RAMs at placement seed 1; on
//! LFE5U-85F-6 a median of 150.4 MHz over placement seeds 1–5 (146.6–162.7; 127.8–157.5 before
//! the cache's return lanes were written whenever its return queue has room; 152.8, 151.1–155.3,
//! before the sector registers' clock enables were registers and the tag kinds a lane of their
//! own, which the machine of six PEs needed and which cost the PE alone 2.4 MHz at the median;
//! 153.3, 140.8–157.3, before the bank counters counted a job a clock late and the screener's
//! and the unit's cuts of the same day; 149.4, 140.2–154.0, with the origin through a bank
//! multiplexer and `W` negated after the divider; 71.8 at seed 1 before the 150 MHz work). Its
//! critical paths: a ray-memory word into the merge's compares (seed 1), the screener's outside
//! compare into its near flag (2), its output FIFO's `head_valid` into its credit count (3),
//! the tag FIFO's read pointer into the kinds' head register (4) and the screener's dividend
//! into the divider (5) (`hdl/fpga/ecp5.md`, checked against the
//! committed Verilog by `tests/hardware.rs`;
//! PERFORMANCE.md).
//!
//! # Models
//!
//! The PE computes what `src/workstream.rs`'s `execute` computes from the same commands: the
//! screener's [`crate::screener::model::screen`] per job under the sector's setup and the
//! intersection unit's [`crate::intersection::model`] per live ray.

use crate::cache::{PatchCache, CACHE_BITS};
use crate::intersection::IntersectionUnit;
use crate::loader::PatchLoader;
use crate::prim::{FifoControl, FifoRam};
use crate::queue::JobQueue;
use crate::screener::Screener;
use crate::slice::PatchSlice;
use rust_hdl::prelude::*;

/// Address bits of the tag FIFO.
pub const TAG_BITS: usize = 6;
/// Commands the PE holds between acceptance and the intersection unit.
pub const TAG_DEPTH: usize = 1 << TAG_BITS;
/// A tag's first ray (bits 11..21) and count (bits 0..10), in the tag FIFO's lane (whether it
/// is a job's is in a lane of its own, `tag_kind`). (The update
/// function spells these bit positions as literals: the Verilog generator copies expressions.)
const TAG_WIDTH: usize = 22;

/// The processing element (see the [module documentation](self)).
#[derive(LogicBlock)]
pub struct ProcessingElement {
    pub clock: Signal<In, Clock>,
    // Rays.
    pub dir_we: Signal<In, bool>,
    pub dir_addr: Signal<In, Bits<11>>,
    pub dir_x: Signal<In, Bits<18>>,
    pub dir_y: Signal<In, Bits<18>>,
    // Source and sector.
    pub origin_x: Signal<In, Bits<17>>,
    pub origin_y: Signal<In, Bits<17>>,
    pub normal_x: Signal<In, Bits<18>>,
    pub normal_y: Signal<In, Bits<18>>,
    pub first_x: Signal<In, Bits<18>>,
    pub first_y: Signal<In, Bits<18>>,
    pub last_x: Signal<In, Bits<18>>,
    pub last_y: Signal<In, Bits<18>>,
    // Commands.
    pub cmd_valid: Signal<In, bool>,
    pub cmd_ready: Signal<Out, bool>,
    pub cmd_retire: Signal<In, bool>,
    pub cmd_sector: Signal<In, bool>,
    pub cmd_id: Signal<In, Bits<16>>,
    pub cmd_first: Signal<In, Bits<11>>,
    pub cmd_count: Signal<In, Bits<11>>,
    // The patch cache.
    pub cfg_cache_enable: Signal<In, bool>,
    pub cfg_cache_mask: Signal<In, Bits<CACHE_BITS>>,
    pub cfg_cache_flush: Signal<In, bool>,
    // Host memory.
    pub mem_req: Signal<Out, bool>,
    pub mem_addr: Signal<Out, Bits<16>>,
    pub mem_valid: Signal<In, bool>,
    pub mem_ax: Signal<In, Bits<17>>,
    pub mem_ay: Signal<In, Bits<17>>,
    pub mem_bx: Signal<In, Bits<17>>,
    pub mem_by: Signal<In, Bits<17>>,
    // Readout.
    pub res_re: Signal<In, bool>,
    pub res_addr: Signal<In, Bits<11>>,
    pub res_hit: Signal<Out, bool>,
    pub res_id: Signal<Out, Bits<16>>,
    pub res_key: Signal<Out, Bits<32>>,
    // Status and counters.
    pub busy: Signal<Out, bool>,
    pub loads: Signal<Out, Bits<32>>,
    pub cache_hits: Signal<Out, Bits<32>>,
    pub cache_misses: Signal<Out, Bits<32>>,
    pub passed: Signal<Out, Bits<32>>,
    pub backward: Signal<Out, Bits<32>>,
    pub back_facing: Signal<Out, Bits<32>>,
    pub outside: Signal<Out, Bits<32>>,
    pub near: Signal<Out, Bits<32>>,
    pub tests: Signal<Out, Bits<32>>,
    pub marks: Signal<Out, Bits<32>>,
    // The datapath.
    loader: PatchLoader,
    cache: PatchCache,
    /// The screener's patches into the merger.
    sc_slice: PatchSlice,
    /// The merger's jobs into the intersection unit.
    queue: JobQueue,
    screener: Screener,
    unit: IntersectionUnit,
    // The tag FIFO: its control, the lane of the tags' first and count (reads the head and the
    // entry after it every cycle: [`FifoControl`]), and the lane of their kinds.
    tags: FifoControl<TAG_BITS, 7>,
    tag_lane: FifoRam<TAG_WIDTH, TAG_BITS>,
    /// Each tag's kind (high: a job's, low: a retire's), the head's in a register of its own
    /// ([`FifoRam::head_registered`]): the merger's handshakes, and the slice's and queue's
    /// load enables after them, are one gate of registers.
    tag_kind: FifoRam<1, TAG_BITS>,
    /// The head is a job's tag (`valid` and a job's kind).
    head_job: Signal<Local, bool>,
    /// The head is a retire's tag.
    head_retire: Signal<Local, bool>,
    /// The command's kind (high: not a retire) as the lane's word.
    new_job: Signal<Local, Bits<1>>,
    accept: Signal<Local, bool>,
    pop: Signal<Local, bool>,
    head_tag: Signal<Local, Bits<TAG_WIDTH>>,
    head_first: Signal<Local, Bits<11>>,
    head_count: Signal<Local, Bits<11>>,
    new_tag: Signal<Local, Bits<TAG_WIDTH>>,
    // Sectors: two banks, a pending sector command, the jobs of each bank before the
    // screener's sector read.
    /// The bank of every job in the loader and that bank's origin, in order (three lanes under
    /// one control): pushed as the loader takes the id, popped as the screener takes the patch.
    /// The origin is the bank's when the job is accepted, which it stays while the job is in
    /// the loader (a bank is rewritten only when none of its jobs is before the screener's
    /// stage 3), so the screener's stage 0 reads it from the lanes' head registers instead of
    /// through a bank multiplexer.
    job_banks: FifoControl<4, 5>,
    job_bank: FifoRam<1, 4>,
    job_origin_x: FifoRam<17, 4>,
    job_origin_y: FifoRam<17, 4>,
    job_pop: Signal<Local, bool>,
    room: Signal<Local, bool>,
    job: Signal<Local, bool>,
    /// The bank the jobs accepted now belong to: the last sector command's.
    bank: DFF<bool>,
    pend: DFF<bool>,
    /// The staged sector: the command's sector fields, loaded in every clock no sector is
    /// pending (enable `!pend`, a register), so it holds the last sector command accepted from
    /// the clock after it until a clock after it reaches its bank.
    stg_first_x: DFF<Bits<18>>,
    stg_first_y: DFF<Bits<18>>,
    stg_last_x: DFF<Bits<18>>,
    stg_last_y: DFF<Bits<18>>,
    stg_origin_x: DFF<Bits<17>>,
    stg_origin_y: DFF<Bits<17>>,
    stg_normal_x: DFF<Bits<18>>,
    stg_normal_y: DFF<Bits<18>>,
    /// Bank 0 (1) loads the staged sector in this clock: set in the clock the sector takes the
    /// bank (the flip of `bank`), so that every bank register's clock enable is a register.
    load0: DFF<bool>,
    load1: DFF<bool>,
    origin0_x: DFF<Bits<17>>,
    origin0_y: DFF<Bits<17>>,
    normal0_x: DFF<Bits<18>>,
    normal0_y: DFF<Bits<18>>,
    origin1_x: DFF<Bits<17>>,
    origin1_y: DFF<Bits<17>>,
    normal1_x: DFF<Bits<18>>,
    normal1_y: DFF<Bits<18>>,
    first0_x: DFF<Bits<18>>,
    first0_y: DFF<Bits<18>>,
    last0_x: DFF<Bits<18>>,
    last0_y: DFF<Bits<18>>,
    first1_x: DFF<Bits<18>>,
    first1_y: DFF<Bits<18>>,
    last1_x: DFF<Bits<18>>,
    last1_y: DFF<Bits<18>>,
    /// Jobs of bank 0 (1) accepted and not yet past the screener's sector read.
    jobs0: DFF<Bits<7>>,
    jobs1: DFF<Bits<7>>,
    /// `jobs0 != 0`, `jobs1 != 0`, kept in registers of their own (from the counters' next
    /// values) so that no compare of a counter lies between the counters and the sector's
    /// clock enables.
    used0: DFF<bool>,
    used1: DFF<bool>,
    /// The tag FIFO holds [`TAG_DEPTH`] tags: its count's compare, registered (from the count's
    /// next value), so that `stall` (below) is set from next values.
    tags_full: DFF<bool>,
    tags_full_next: Signal<Local, bool>,
    /// `cmd_ready`'s complement in one register of its own, set from the next values of
    /// `tags_full`, the loader's `full` and `pend` (powers up low: ready), so that the command
    /// handshake reaches the tag FIFO's write enables through one gate.
    stall: DFF<bool>,
    /// The bank a pending sector overwrites (not `bank`) holds a job before its sector read: a
    /// register of its own, from the next values of `bank` and the `used` flags, so that `take`
    /// (the flip, and the next values of `pend` and the `load` registers) is one gate of
    /// registers (the command handshake, `pend`, this).
    other_busy: DFF<bool>,
    bank_next: Signal<Local, bool>,
    used0_next: Signal<Local, bool>,
    used1_next: Signal<Local, bool>,
    /// A job accepted into bank 0 (1) the clock before: the bank counters count it one clock
    /// late, so that the command handshake (`stall`, `accept`) reaches one flip-flop here, not
    /// the counters' and `used` flags' enables. No decision changes: a sector reads the count
    /// of the bank the jobs are not accepted into, and the job accepted the clock before went
    /// into the bank of this clock (a flip takes a clock with no job: a sector command, or
    /// `pend` with `cmd_ready` low); a job reaches the sector read several clocks after.
    in0: DFF<bool>,
    in1: DFF<bool>,
    sector_in: Signal<Local, bool>,
    /// A sector takes the other bank in this clock.
    take: Signal<Local, bool>,
    out0: Signal<Local, bool>,
    out1: Signal<Local, bool>,
    pend_next: Signal<Local, bool>,
    one7: Constant<Bits<7>>,
    almost_full: Constant<Bits<7>>,
    zero1: Constant<Bits<1>>,
    one1: Constant<Bits<1>>,
    full: Constant<Bits<7>>,
    zero7: Constant<Bits<7>>,
}

impl Default for ProcessingElement {
    fn default() -> Self {
        ProcessingElement {
            clock: Default::default(),
            dir_we: Default::default(),
            dir_addr: Default::default(),
            dir_x: Default::default(),
            dir_y: Default::default(),
            origin_x: Default::default(),
            origin_y: Default::default(),
            normal_x: Default::default(),
            normal_y: Default::default(),
            first_x: Default::default(),
            first_y: Default::default(),
            last_x: Default::default(),
            last_y: Default::default(),
            cmd_valid: Default::default(),
            cmd_ready: Default::default(),
            cmd_retire: Default::default(),
            cmd_sector: Default::default(),
            cmd_id: Default::default(),
            cmd_first: Default::default(),
            cmd_count: Default::default(),
            cfg_cache_enable: Default::default(),
            cfg_cache_mask: Default::default(),
            cfg_cache_flush: Default::default(),
            mem_req: Default::default(),
            mem_addr: Default::default(),
            mem_valid: Default::default(),
            mem_ax: Default::default(),
            mem_ay: Default::default(),
            mem_bx: Default::default(),
            mem_by: Default::default(),
            res_re: Default::default(),
            res_addr: Default::default(),
            res_hit: Default::default(),
            res_id: Default::default(),
            res_key: Default::default(),
            busy: Default::default(),
            loads: Default::default(),
            cache_hits: Default::default(),
            cache_misses: Default::default(),
            passed: Default::default(),
            backward: Default::default(),
            back_facing: Default::default(),
            outside: Default::default(),
            near: Default::default(),
            tests: Default::default(),
            marks: Default::default(),
            loader: Default::default(),
            cache: Default::default(),
            sc_slice: Default::default(),
            queue: Default::default(),
            screener: Default::default(),
            unit: Default::default(),
            tags: Default::default(),
            tag_lane: Default::default(),
            tag_kind: FifoRam::head_registered(),
            head_job: Default::default(),
            new_job: Default::default(),
            accept: Default::default(),
            pop: Default::default(),
            head_tag: Default::default(),
            head_retire: Default::default(),
            head_first: Default::default(),
            head_count: Default::default(),
            new_tag: Default::default(),
            job_banks: Default::default(),
            job_bank: Default::default(),
            job_origin_x: Default::default(),
            job_origin_y: Default::default(),
            job_pop: Default::default(),
            room: Default::default(),
            job: Default::default(),
            bank: Default::default(),
            pend: Default::default(),
            stg_first_x: Default::default(),
            stg_first_y: Default::default(),
            stg_last_x: Default::default(),
            stg_last_y: Default::default(),
            stg_origin_x: Default::default(),
            stg_origin_y: Default::default(),
            stg_normal_x: Default::default(),
            stg_normal_y: Default::default(),
            load0: Default::default(),
            load1: Default::default(),
            origin0_x: Default::default(),
            origin0_y: Default::default(),
            normal0_x: Default::default(),
            normal0_y: Default::default(),
            origin1_x: Default::default(),
            origin1_y: Default::default(),
            normal1_x: Default::default(),
            normal1_y: Default::default(),
            first0_x: Default::default(),
            first0_y: Default::default(),
            last0_x: Default::default(),
            last0_y: Default::default(),
            first1_x: Default::default(),
            first1_y: Default::default(),
            last1_x: Default::default(),
            last1_y: Default::default(),
            jobs0: Default::default(),
            jobs1: Default::default(),
            used0: Default::default(),
            used1: Default::default(),
            tags_full: Default::default(),
            tags_full_next: Default::default(),
            stall: Default::default(),
            other_busy: Default::default(),
            bank_next: Default::default(),
            used0_next: Default::default(),
            used1_next: Default::default(),
            in0: Default::default(),
            sector_in: Default::default(),
            take: Default::default(),
            in1: Default::default(),
            out0: Default::default(),
            out1: Default::default(),
            pend_next: Default::default(),
            one7: Constant::new(1.into()),
            almost_full: Constant::new(((TAG_DEPTH - 1) as u64).into()),
            zero1: Constant::new(0.into()),
            one1: Constant::new(1.into()),
            full: Constant::new((TAG_DEPTH as u64).into()),
            zero7: Constant::new(0.into()),
        }
    }
}

/// What holds the PE's command stream or starves its intersection unit in a cycle, as a
/// testbench reads it from rust-hdl's simulation ([`ProcessingElement::watch`]; the compiled PE
/// has its ports only).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Watch {
    /// A sector command waits for its bank (`pend`): the sector before last still has jobs
    /// before the screener's sector read.
    pub sector_waits: bool,
    /// The tag FIFO holds [`TAG_DEPTH`] commands.
    pub tags_full: bool,
    /// The loader holds [`crate::loader::DEPTH`] ids (its `id_ready` low).
    pub loader_full: bool,
    /// The loader has a patch the screener does not take (the screener's output is full).
    pub screener_holds: bool,
    /// The intersection unit would take a job (fewer than two rays of its present one are left
    /// to issue) and the job queue has none.
    pub unit_starved: bool,
    /// The cache rewinds its lookups because the oldest request not looked up is for the id of
    /// a miss whose patch is not in its line yet ([`PatchCache::fill_rewind`]): it is tried
    /// again until that fill, and no request behind it is looked up meanwhile.
    pub fill_rewind: bool,
    /// The cache accepts a lookup ([`PatchCache::lookup`]).
    pub lookup: bool,
}

impl ProcessingElement {
    /// The [`Watch`] of the present cycle (the registers' values before the coming edge).
    pub fn watch(&self) -> Watch {
        Watch {
            sector_waits: self.pend.q.val(),
            tags_full: self.tags_full.q.val(),
            loader_full: !self.loader.id_ready.val(),
            screener_holds: self.loader.out_valid.val() & !self.screener.in_ready.val(),
            unit_starved: self.unit.patch_ready.val() & !self.queue.out_valid.val(),
            fill_rewind: self.cache.fill_rewind(),
            lookup: self.cache.lookup(),
        }
    }
}

impl Logic for ProcessingElement {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            bank,
            other_busy,
            pend,
            stg_first_x,
            stg_first_y,
            stg_last_x,
            stg_last_y,
            stg_origin_x,
            stg_origin_y,
            stg_normal_x,
            stg_normal_y,
            load0,
            load1,
            origin0_x,
            origin0_y,
            normal0_x,
            normal0_y,
            origin1_x,
            origin1_y,
            normal1_x,
            normal1_y,
            first0_x,
            first0_y,
            last0_x,
            last0_y,
            first1_x,
            first1_y,
            last1_x,
            last1_y,
            jobs0,
            jobs1,
            used0,
            used1,
            in0,
            in1,
            tags_full,
            stall
        );
        self.job_banks.clock.next = self.clock.val();
        self.job_bank.clock.next = self.clock.val();
        self.job_origin_x.clock.next = self.clock.val();
        self.job_origin_y.clock.next = self.clock.val();
        self.loader.clock.next = self.clock.val();
        self.cache.clock.next = self.clock.val();
        self.screener.clock.next = self.clock.val();
        self.unit.clock.next = self.clock.val();
        self.sc_slice.clock.next = self.clock.val();
        self.queue.clock.next = self.clock.val();
        self.tags.clock.next = self.clock.val();
        self.tag_lane.clock.next = self.clock.val();
        self.tag_kind.clock.next = self.clock.val();

        // Rays and readout: straight to the intersection unit.
        self.unit.dir_we.next = self.dir_we.val();
        self.unit.dir_addr.next = self.dir_addr.val();
        self.unit.dir_x.next = self.dir_x.val();
        self.unit.dir_y.next = self.dir_y.val();
        self.unit.res_re.next = self.res_re.val();
        self.unit.res_addr.next = self.res_addr.val();
        self.res_hit.next = self.unit.res_hit.val();
        self.res_id.next = self.unit.res_id.val();
        self.res_key.next = self.unit.res_key.val();

        // The source, from the bank of the patch the screener reads it for: the origin that of
        // the patch it takes (stage 0, carried beside the job's bank in `job_banks`), the
        // normal that of the patch in its stage 1. The sector: the bank of the patch in the
        // screener's stage 3.
        self.screener.origin_x.next = self.job_origin_x.read_data.val();
        self.screener.origin_y.next = self.job_origin_y.read_data.val();
        self.screener.normal_x.next = self.normal0_x.q.val();
        self.screener.normal_y.next = self.normal0_y.q.val();
        if self.screener.normal_bank.val() {
            self.screener.normal_x.next = self.normal1_x.q.val();
            self.screener.normal_y.next = self.normal1_y.q.val();
        }
        self.screener.first_x.next = self.first0_x.q.val();
        self.screener.first_y.next = self.first0_y.q.val();
        self.screener.last_x.next = self.last0_x.q.val();
        self.screener.last_y.next = self.last0_y.q.val();
        if self.screener.sector_bank.val() {
            self.screener.first_x.next = self.first1_x.q.val();
            self.screener.first_y.next = self.first1_y.q.val();
            self.screener.last_x.next = self.last1_x.q.val();
            self.screener.last_y.next = self.last1_y.q.val();
        }

        // Commands: a tag for each job and retire, the id of a job to the loader with its
        // bank beside it; a sector into the pending register. Ready is a register.
        self.room.next = !self.stall.q.val();
        self.cmd_ready.next = self.room.val();
        self.accept.next = self.cmd_valid.val() & self.room.val();
        self.job.next = self.accept.val() & !self.cmd_retire.val() & !self.cmd_sector.val();
        self.loader.id_valid.next = self.job.val();
        self.loader.id.next = self.cmd_id.val();
        self.job_banks.push.next = self.job.val();
        self.job_pop.next = self.loader.out_valid.val() & self.screener.in_ready.val();
        self.job_banks.pop.next = self.job_pop.val();
        self.job_bank.write_data.next = self.zero1.val();
        self.job_origin_x.write_data.next = self.origin0_x.q.val();
        self.job_origin_y.write_data.next = self.origin0_y.q.val();
        if self.bank.q.val() {
            self.job_bank.write_data.next = self.one1.val();
            self.job_origin_x.write_data.next = self.origin1_x.q.val();
            self.job_origin_y.write_data.next = self.origin1_y.q.val();
        }
        // A job accepted in the clock its bank loads (the one after its sector's) takes the
        // origin from the staged sector.
        if self.load0.q.val() | self.load1.q.val() {
            self.job_origin_x.write_data.next = self.stg_origin_x.q.val();
            self.job_origin_y.write_data.next = self.stg_origin_y.q.val();
        }
        self.job_bank.write_address.next = self.job_banks.tail_address.val();
        self.job_bank.write_enable.next = self.job.val();
        self.job_bank.head_address.next = self.job_banks.head_address.val();
        self.job_bank.next_address.next = self.job_banks.next_address.val();
        self.job_bank.pop.next = self.job_pop.val();
        self.job_origin_x.write_address.next = self.job_banks.tail_address.val();
        self.job_origin_x.write_enable.next = self.job.val();
        self.job_origin_x.head_address.next = self.job_banks.head_address.val();
        self.job_origin_x.next_address.next = self.job_banks.next_address.val();
        self.job_origin_x.pop.next = self.job_pop.val();
        self.job_origin_y.write_address.next = self.job_banks.tail_address.val();
        self.job_origin_y.write_enable.next = self.job.val();
        self.job_origin_y.head_address.next = self.job_banks.head_address.val();
        self.job_origin_y.next_address.next = self.job_banks.next_address.val();
        self.job_origin_y.pop.next = self.job_pop.val();
        self.screener.in_bank.next = self.job_bank.read_data.val() == self.one1.val();

        // A sector takes the bank the jobs do not use (the other one) as soon as that bank
        // holds no job before the sector read: at once if it is free when the command is
        // taken, else from `pend`, holding the stream meanwhile. The jobs after it belong to it.
        self.sector_in.next = self.accept.val() & self.cmd_sector.val();
        // The staged sector: the command's sector fields in every clock no sector waits (in
        // the clock a sector is accepted among them), held while one does.
        if !self.pend.q.val() {
            self.stg_first_x.d.next = self.first_x.val();
            self.stg_first_y.d.next = self.first_y.val();
            self.stg_last_x.d.next = self.last_x.val();
            self.stg_last_y.d.next = self.last_y.val();
            self.stg_origin_x.d.next = self.origin_x.val();
            self.stg_origin_y.d.next = self.origin_y.val();
            self.stg_normal_x.d.next = self.normal_x.val();
            self.stg_normal_y.d.next = self.normal_y.val();
        }
        self.pend_next.next = self.pend.q.val();
        if self.sector_in.val() & self.other_busy.q.val() {
            self.pend_next.next = true;
        }
        // The sector takes the other bank: the flip now, its bank loaded from the staged
        // sector in the next clock (nothing reads that bank before: no job of it is before the
        // screener's sector read, and the jobs accepted after the flip reach the screener's
        // stage 1 several clocks later).
        self.take.next = (self.sector_in.val() | self.pend.q.val()) & !self.other_busy.q.val();
        self.bank_next.next = self.bank.q.val();
        if self.take.val() {
            self.pend_next.next = false;
            self.bank_next.next = !self.bank.q.val();
        }
        self.load0.d.next = self.take.val() & self.bank.q.val();
        self.load1.d.next = self.take.val() & !self.bank.q.val();
        if self.load0.q.val() {
            self.first0_x.d.next = self.stg_first_x.q.val();
            self.first0_y.d.next = self.stg_first_y.q.val();
            self.last0_x.d.next = self.stg_last_x.q.val();
            self.last0_y.d.next = self.stg_last_y.q.val();
            self.origin0_x.d.next = self.stg_origin_x.q.val();
            self.origin0_y.d.next = self.stg_origin_y.q.val();
            self.normal0_x.d.next = self.stg_normal_x.q.val();
            self.normal0_y.d.next = self.stg_normal_y.q.val();
        }
        if self.load1.q.val() {
            self.first1_x.d.next = self.stg_first_x.q.val();
            self.first1_y.d.next = self.stg_first_y.q.val();
            self.last1_x.d.next = self.stg_last_x.q.val();
            self.last1_y.d.next = self.stg_last_y.q.val();
            self.origin1_x.d.next = self.stg_origin_x.q.val();
            self.origin1_y.d.next = self.stg_origin_y.q.val();
            self.normal1_x.d.next = self.stg_normal_x.q.val();
            self.normal1_y.d.next = self.stg_normal_y.q.val();
        }
        self.pend.d.next = self.pend_next.val();
        self.bank.d.next = self.bank_next.val();
        // Each bank's jobs: counted in as accepted, out as they pass the sector read.
        self.in0.d.next = self.job.val() & !self.bank.q.val();
        self.in1.d.next = self.job.val() & self.bank.q.val();
        self.out0.next = self.screener.sector_read.val() & !self.screener.sector_bank.val();
        self.out1.next = self.screener.sector_read.val() & self.screener.sector_bank.val();
        if self.in0.q.val() & !self.out0.val() {
            self.jobs0.d.next = self.jobs0.q.val() + self.one7.val();
        }
        if self.out0.val() & !self.in0.q.val() & (self.jobs0.q.val() != self.zero7.val()) {
            self.jobs0.d.next = self.jobs0.q.val() - self.one7.val();
        }
        if self.in1.q.val() & !self.out1.val() {
            self.jobs1.d.next = self.jobs1.q.val() + self.one7.val();
        }
        if self.out1.val() & !self.in1.q.val() & (self.jobs1.q.val() != self.zero7.val()) {
            self.jobs1.d.next = self.jobs1.q.val() - self.one7.val();
        }
        // `used`: the counter's next value is not zero (it leaves zero on a job in alone, and
        // reaches zero from one on a job out alone).
        self.used0_next.next = self.used0.q.val();
        if self.in0.q.val() & !self.out0.val() {
            self.used0_next.next = true;
        }
        if self.out0.val() & !self.in0.q.val() & (self.jobs0.q.val() == self.one7.val()) {
            self.used0_next.next = false;
        }
        self.used1_next.next = self.used1.q.val();
        if self.in1.q.val() & !self.out1.val() {
            self.used1_next.next = true;
        }
        if self.out1.val() & !self.in1.q.val() & (self.jobs1.q.val() == self.one7.val()) {
            self.used1_next.next = false;
        }
        self.used0.d.next = self.used0_next.val();
        self.used1.d.next = self.used1_next.val();
        self.other_busy.d.next = self.used1_next.val();
        if self.bank_next.val() {
            self.other_busy.d.next = self.used0_next.val();
        }
        self.new_tag.next = (bit_cast::<TAG_WIDTH, 11>(self.cmd_first.val()) << 11)
            | bit_cast::<TAG_WIDTH, 11>(self.cmd_count.val());
        self.tags.push.next = self.accept.val() & !self.cmd_sector.val();
        // The lane and the slot kinds are written at the tail in every clock the FIFO is not
        // full, pushed or not: the tail's slot holds no tag then (a push writes it again), so
        // their write enables are a register (`tags_full`), not the command handshake. A
        // slot written without a push is read only as the entry after a head that leaves at
        // the same edge, when no tag is left (the lanes read before they write).
        self.tag_lane.write_data.next = self.new_tag.val();
        self.tag_lane.write_enable.next = !self.tags_full.q.val();
        self.tag_lane.write_address.next = self.tags.tail_address.val();
        self.tag_lane.head_address.next = self.tags.head_address.val();
        self.tag_lane.next_address.next = self.tags.next_address.val();
        self.new_job.next = self.one1.val();
        if self.cmd_retire.val() {
            self.new_job.next = self.zero1.val();
        }
        self.tag_kind.write_data.next = self.new_job.val();
        self.tag_kind.write_enable.next = !self.tags_full.q.val();
        self.tag_kind.write_address.next = self.tags.tail_address.val();
        self.tag_kind.head_address.next = self.tags.head_address.val();
        self.tag_kind.next_address.next = self.tags.next_address.val();

        // Host memory: the loader's port through the cache.
        self.cache.cfg_enable.next = self.cfg_cache_enable.val();
        self.cache.cfg_mask.next = self.cfg_cache_mask.val();
        self.cache.flush.next = self.cfg_cache_flush.val();
        self.cache.req.next = self.loader.mem_req.val();
        self.cache.addr.next = self.loader.mem_addr.val();
        self.loader.mem_valid.next = self.cache.resp_valid.val();
        self.loader.mem_ax.next = self.cache.resp_ax.val();
        self.loader.mem_ay.next = self.cache.resp_ay.val();
        self.loader.mem_bx.next = self.cache.resp_bx.val();
        self.loader.mem_by.next = self.cache.resp_by.val();
        self.mem_req.next = self.cache.mem_req.val();
        self.mem_addr.next = self.cache.mem_addr.val();
        self.cache.mem_valid.next = self.mem_valid.val();
        self.cache.mem_ax.next = self.mem_ax.val();
        self.cache.mem_ay.next = self.mem_ay.val();
        self.cache.mem_bx.next = self.mem_bx.val();
        self.cache.mem_by.next = self.mem_by.val();

        // Loader to screener.
        self.screener.in_valid.next = self.loader.out_valid.val();
        self.loader.out_ready.next = self.screener.in_ready.val();
        self.screener.in_id.next = self.loader.out_id.val();
        self.screener.in_ax.next = self.loader.out_ax.val();
        self.screener.in_ay.next = self.loader.out_ay.val();
        self.screener.in_bx.next = self.loader.out_bx.val();
        self.screener.in_by.next = self.loader.out_by.val();

        // The screener's patches go through a slice: every merger input is a register.
        self.sc_slice.in_valid.next = self.screener.out_valid.val();
        self.screener.out_ready.next = self.sc_slice.in_ready.val();
        self.sc_slice.in_id.next = self.screener.out_id.val();
        self.sc_slice.in_ax.next = self.screener.out_ax.val();
        self.sc_slice.in_ay.next = self.screener.out_ay.val();
        self.sc_slice.in_bx.next = self.screener.out_bx.val();
        self.sc_slice.in_by.next = self.screener.out_by.val();
        self.sc_slice.in_wx.next = self.screener.out_wx.val();
        self.sc_slice.in_wy.next = self.screener.out_wy.val();
        self.sc_slice.in_sh.next = self.screener.out_sh.val();
        self.sc_slice.in_pass.next = self.screener.out_pass.val();
        self.sc_slice.in_first.next = 0.into();
        self.sc_slice.in_count.next = 0.into();
        self.sc_slice.in_retire.next = false;

        // The merger: the oldest tag meets the unit (a retire) or its patch's verdict (a job);
        // what it sends goes through a second slice, whose `in_ready` is a register.
        self.head_tag.next = self.tag_lane.read_data.val();
        self.head_job.next = self.tags.valid.val() & self.tag_kind.read_data.val().any();
        self.head_retire.next = self.tags.valid.val() & !self.tag_kind.read_data.val().any();
        self.head_first.next = self.head_tag.val().get_bits::<11>(11);
        self.head_count.next = self.head_tag.val().get_bits::<11>(0);
        self.queue.in_id.next = self.sc_slice.out_id.val();
        self.queue.in_ax.next = self.sc_slice.out_ax.val();
        self.queue.in_ay.next = self.sc_slice.out_ay.val();
        self.queue.in_bx.next = self.sc_slice.out_bx.val();
        self.queue.in_by.next = self.sc_slice.out_by.val();
        self.queue.in_wx.next = self.sc_slice.out_wx.val();
        self.queue.in_wy.next = self.sc_slice.out_wy.val();
        self.queue.in_sh.next = self.sc_slice.out_sh.val();
        self.queue.in_first.next = self.head_first.val();
        self.queue.in_count.next = self.head_count.val();
        self.queue.in_retire.next = self.head_retire.val();
        self.queue.in_valid.next = false;
        self.sc_slice.out_ready.next = false;
        self.pop.next = false;
        if self.head_retire.val() {
            self.queue.in_valid.next = true;
            self.pop.next = self.queue.in_ready.val();
        }
        if self.head_job.val() & self.sc_slice.out_valid.val() {
            if self.sc_slice.out_pass.val() {
                self.queue.in_valid.next = true;
                self.sc_slice.out_ready.next = self.queue.in_ready.val();
                self.pop.next = self.queue.in_ready.val();
            } else {
                self.sc_slice.out_ready.next = true;
                self.pop.next = true;
            }
        }
        self.unit.patch_valid.next = self.queue.out_valid.val();
        self.queue.out_ready.next = self.unit.patch_ready.val();
        self.unit.patch_id.next = self.queue.out_id.val();
        self.unit.patch_ax.next = self.queue.out_ax.val();
        self.unit.patch_ay.next = self.queue.out_ay.val();
        self.unit.patch_bx.next = self.queue.out_bx.val();
        self.unit.patch_by.next = self.queue.out_by.val();
        self.unit.patch_wx.next = self.queue.out_wx.val();
        self.unit.patch_wy.next = self.queue.out_wy.val();
        self.unit.patch_sh.next = self.queue.out_sh.val();
        self.unit.patch_first.next = self.queue.out_first.val();
        self.unit.patch_count.next = self.queue.out_count.val();
        self.unit.patch_retire.next = self.queue.out_retire.val();

        // The tag FIFO's read side: the merger's pop (the head, read every cycle with the entry
        // after it, depends on no pop: see [`FifoControl`]).
        self.tags.pop.next = self.pop.val();
        self.tag_lane.pop.next = self.pop.val();
        self.tag_kind.pop.next = self.pop.val();
        // The tag FIFO full after this edge: full and no pop, or one short of full with a push
        // and no pop (no push while full: `cmd_ready` is low).
        self.tags_full_next.next = ((self.tags.count.val() == self.full.val()) & !self.pop.val())
            | ((self.tags.count.val() == self.almost_full.val())
                & self.accept.val()
                & !self.cmd_sector.val()
                & !self.pop.val());
        self.tags_full.d.next = self.tags_full_next.val();
        // Ready after this edge: the tag FIFO not full, the loader ready, no sector pending.
        self.stall.d.next =
            self.tags_full_next.val() | !self.loader.id_ready_next.val() | self.pend_next.val();

        // Status and counters.
        self.busy.next = (self.tags.count.val() != self.zero7.val())
            | self.pend.q.val()
            | self.queue.occupied.val()
            | self.unit.busy.val()
            | self.cache.flushing.val();
        self.loads.next = self.loader.loads.val();
        self.cache_hits.next = self.cache.hits.val();
        self.cache_misses.next = self.cache.misses.val();
        self.passed.next = self.screener.passed.val();
        self.backward.next = self.screener.backward.val();
        self.back_facing.next = self.screener.back_facing.val();
        self.outside.next = self.screener.outside.val();
        self.near.next = self.screener.near.val();
        self.tests.next = self.unit.tests.val();
        self.marks.next = self.unit.marks.val();
    }
}
