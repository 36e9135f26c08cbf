//! The patch cache: a per-PE, direct-mapped cache of patches between the patch loader's memory
//! port and the host memory, the paper's "high speed cache memory for each PE": a patch found
//! in the cache costs one cycle of the PE's time instead of a `T_c`-cycle load from the shared
//! host memory.
//!
//! # Ports ([`PatchCache`])
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | rising-edge clock |
//! | `cfg_enable` | in | 1 | cache on; off: a combinational pass-through (see below) |
//! | `cfg_mask` | in | 12 | lines − 1 (lines a power of two, 1 … [`LINES`]); line of id = `id & cfg_mask` |
//! | `flush`, `flushing` | in, out | 1, 1 | invalidate every line: `flush` high starts it, `flushing` (a register) is high for the [`LINES`] cycles it takes |
//! | `req`, `addr` | in | 1, 16 | loader side: request, one clock pulse per patch, `addr` = patch id |
//! | `resp_valid`, `resp_ax`, `resp_ay`, `resp_bx`, `resp_by` | out | 1, 4 × 17 | loader side: response |
//! | `mem_req`, `mem_addr` | out | 1, 16 | host side: request, one clock pulse per miss |
//! | `mem_valid`, `mem_ax`, `mem_ay`, `mem_bx`, `mem_by` | in | 1, 4 × 17 | host side: response |
//! | `hits`, `misses` | out | 32, 32 | lookups that hit / missed so far (counted from the cycle after the lookup, with the response or the host request), wrap at 2³² |
//!
//! Both sides speak the protocol of the patch loader's memory port ([`crate::loader`], "The
//! memory port"): one request pulse per patch, exactly one response per request, in request
//! order, any number ≥ 1 of cycles later. The loader is the client on the `req` side; the host
//! memory serves the `mem_*` side.
//!
//! Configuration: `cfg_enable` and `cfg_mask` are held constant during a run and may change
//! only while no request is outstanding. The cache contents survive a change of either: a line
//! holds its patch's whole id, so whatever the mask, a hit always returns the right patch as
//! long as the host memory's contents do not change.
//!
//! Flush: when the host memory's contents change (a new scene), the host raises `flush` while
//! no request is outstanding. From the next cycle on `flushing` is high for [`LINES`] cycles,
//! one per line, while the tag lane is cleared line by line through its write port (the data
//! lanes keep their stale words, unreachable behind invalid tags); no request may be made
//! until `flushing` is low again. `flush` is ignored while a flush runs. The tag lanes are also
//! zero (every line invalid) at power-up.
//!
//! Number formats: ids are 16-bit unsigned; coordinates are world coordinates Q11.6 unsigned in
//! 17 bits (`crate::formats`), stored and passed through unchanged.
//!
//! # Disabled: pass-through
//!
//! With `cfg_enable` low the block is wires: `mem_req = req`, `mem_addr = addr`,
//! `resp_valid = mem_valid`, `resp_* = mem_*`, combinationally; nothing is queued, looked up
//! or stored and the counters hold. A PE without cache pays no cycle.
//!
//! # Enabled: structure
//!
//! * A request queue of [`QUEUE_DEPTH`] ids (a [`Bram`] lane with registered read, as the
//!   loader's FIFO, with five-bit pointers). The client must keep at most [`QUEUE_DEPTH`]
//!   requests outstanding (the loader does: at most one per FIFO slot, `crate::loader::DEPTH` =
//!   16); a request leaves the queue when it is answered, so the queue cannot overflow.
//! * Five [`BramOut`] lanes of [`LINES`] words, two clocks from read address to data (on ECP5
//!   block RAMs with their output register): the tag (bit 16: valid, bits 15…0: the whole id)
//!   and the four 17-bit coordinates; zero (invalid) at power-up.
//! * A speculative lookup pipeline, one request per clock, in request order:
//!   - **Q** (issue): the id of the next request to look up is at the queue lane's read
//!     register; its line is presented to the lanes and the request moves to S1, and the queue
//!     lane reads the request after it.
//!   - **S1**: the lanes' first read register.
//!   - **S2**: the lanes' output registers hold the request's line; `tag == {1, id}` is
//!     computed by 4-bit slices (on ECP5 one per block RAM tile of the tag lane), each
//!     registered, with the line's words.
//!   - **S3** (lookup): a hit is answered from the registered words; a miss issues the host
//!     request and goes to W.
//!   - **W** (wait): the miss waits for `mem_valid`; the response is written into its line
//!     (tag and data) and forwarded to the client. A `mem_valid` with no miss waiting is a
//!     protocol violation and is ignored.
//!
//!   Requests are looked up before the ones ahead of them are answered. A miss voids the three
//!   lookups behind it (in S1, S2 and S3 while it waits) and rewinds the queue's read pointer to the
//!   request after it: after the fill those are issued again, so they see the line it wrote
//!   (the lanes read before they write, and nothing is issued until the cycle after the fill).
//!   Only fills write, and nothing is issued while a fill is pending, so there is no other
//!   hazard. The tag compare feeds registers only, one per tile: no path runs from a block RAM
//!   through the compare into the pipeline's control, and each slice's compare can be placed
//!   next to its tile (the block RAMs sit far apart on the die; from the tag's tiles to one
//!   compare the routing alone took 3 ns). The queue's pointers keep `+ 1` in registers and
//!   compare each candidate for the next read with the write pointer beside the choice, so
//!   no carry chain or compare follows the pointer multiplexer.
//! * With the cache enabled every output is a register (`mem_req`, `mem_addr`, `resp_*`,
//!   counters): no combinational path crosses the block. `resp_*` are meaningful only while
//!   `resp_valid` is high (the data registers take every looked-up line's words), and
//!   `mem_addr` only while `mem_req` is, identically in the rust-hdl simulation and in the
//!   Verilog.
//!
//! # Latency and throughput (enabled)
//!
//! For a request seen (`req` high) in cycle `a` by an idle block ([`model::schedule`] gives
//! the exact cycles of any stream):
//!
//! * it is looked up (in S3) in cycle `a + 5` ([`model::LOOKUP_DELAY`]);
//! * a **hit** is answered (`resp_valid`) in cycle `a + 6` ([`model::HIT_LATENCY`]);
//! * a **miss** is requested from the host (`mem_req`) in cycle `a + 6`; the host answers in
//!   cycle `a + 6 + T_c`; the client's response follows in cycle `a + 7 + T_c`
//!   (`T_c +` [`model::MISS_OVERHEAD`]).
//!
//! Request `k` is looked up in cycle `b_k = max(a_k + 5, f_{k−1})`, where `f` is when the
//! lookup stage can next hold a valid request: `f_k = b_k + 1` after a hit, `b_k + T_c + 5`
//! after a miss ([`model::MISS_RESTART`]: its host request goes out in `b_k + 1`, the fill
//! comes in `b_k + 1 + T_c`, the next request is issued again in the cycle after it and looked
//! up three cycles later). So a stream of hits is answered **one per clock**, and each miss
//! occupies the pipeline for `T_c + 5` cycles (two more than with a one-clock read and an
//! unregistered compare, the price of a 150 MHz clock). The host sees at most one request
//! outstanding.
//!
//! # Model
//!
//! [`model::Cache`]: the direct-mapped cache state, `access(id) → hit?`. For any request
//! stream the RTL's hit/miss sequence equals the model's, its host requests are exactly the
//! missed ids in order, and the responses carry the host memory's coordinates of the requested
//! ids in request order. [`model::schedule`] gives the exact lookup, host request and response
//! cycles from the request cycles, the hit/miss sequence and `T_c`.

use crate::prim::{bram_out_tile_width, Bram, BramOut};
use rust_hdl::prelude::*;

/// Address width of the cache lanes: at most `2^CACHE_BITS` lines.
pub const CACHE_BITS: usize = 12;
/// The largest number of lines (4096 patches).
pub const LINES: usize = 1 << CACHE_BITS;
/// Request queue capacity: the most requests a client may keep outstanding.
pub const QUEUE_DEPTH: usize = 16;
/// Address width of the request queue: `2^QUEUE_BITS == QUEUE_DEPTH`.
pub const QUEUE_BITS: usize = 4;

/// The behavioural model of the patch cache: its state, and its exact timing.
pub mod model {
    use super::LINES;

    /// Cycles from a request (`req` high) to its lookup, in an idle block.
    pub const LOOKUP_DELAY: u64 = 5;
    /// Cycles from a request to its response when it hits, in an idle block: the response
    /// register after the lookup.
    pub const HIT_LATENCY: u64 = LOOKUP_DELAY + 1;
    /// Cycles from a request to its response beyond the host's `T_c` when it misses, in an idle
    /// block: the response comes `T_c + MISS_OVERHEAD` cycles after the request (the host
    /// request one cycle after the lookup, the response register one after the fill).
    pub const MISS_OVERHEAD: u64 = LOOKUP_DELAY + 2;
    /// Cycles from a miss's lookup, beyond the host's `T_c`, to the next lookup: the host
    /// request (1), the fill, then the next request's read is issued again (1), takes the lanes'
    /// two read registers (2) and its compare's register (1).
    pub const MISS_RESTART: u64 = 5;

    /// The mask for `lines` lines (a power of two, 1 … [`LINES`]), or `None`.
    pub fn mask_for(lines: usize) -> Option<u16> {
        (lines.is_power_of_two() && lines <= LINES).then(|| (lines - 1) as u16)
    }

    /// A direct-mapped cache of patch ids: line `id & mask` holds the last id that missed
    /// there. The contents survive [`Cache::set_mask`], as the RTL's memories do.
    #[derive(Clone, Debug, PartialEq, Eq)]
    pub struct Cache {
        mask: u16,
        lines: Vec<Option<u16>>,
    }

    impl Cache {
        /// An empty cache (all lines invalid, as at power-up) with line mask `mask`.
        ///
        /// # Panics
        /// If `mask` does not fit the 12-bit `cfg_mask` (`mask ≥ LINES`).
        pub fn new(mask: u16) -> Self {
            let mut cache = Self { mask: 0, lines: vec![None; LINES] };
            cache.set_mask(mask);
            cache
        }

        /// Invalidates every line (the RTL's `flush`).
        pub fn flush(&mut self) {
            self.lines.fill(None);
        }

        /// Changes the mask, keeping the contents (a new `cfg_mask` between runs).
        ///
        /// # Panics
        /// If `mask ≥ LINES`.
        pub fn set_mask(&mut self, mask: u16) {
            assert!((mask as usize) < LINES, "cache mask {mask:#x} does not fit 12 bits");
            self.mask = mask;
        }

        /// The line mask.
        pub fn mask(&self) -> u16 {
            self.mask
        }

        /// The line `id` maps to.
        pub fn line(&self, id: u16) -> usize {
            (id & self.mask) as usize
        }

        /// Looks `id` up: `true` on a hit; on a miss the line is filled with `id`.
        pub fn access(&mut self, id: u16) -> bool {
            let line = self.line(id);
            let hit = self.lines[line] == Some(id);
            self.lines[line] = Some(id);
            hit
        }

        /// The hit/miss sequence of `ids`, accessed in order.
        pub fn run(&mut self, ids: &[u16]) -> Vec<bool> {
            ids.iter().map(|&id| self.access(id)).collect()
        }
    }

    /// When one request is processed by the RTL.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub struct RequestTiming {
        /// The cycle it is in the lookup stage (S3).
        pub lookup: u64,
        /// The cycle of its host request (`mem_req`), on a miss.
        pub host_request: Option<u64>,
        /// The cycle of its response (`resp_valid`).
        pub response: u64,
    }

    /// The exact cycles of a request stream through the enabled RTL, from power-up or from an
    /// idle block (the stream's first request comes no earlier than the cycle in which the
    /// last earlier request was answered): request `k` is seen in cycle `requests[k].0`
    /// (strictly increasing) and hits when `requests[k].1`; the host answers each request `tc`
    /// cycles after it (it serves only this cache, which keeps at most one request
    /// outstanding). `b_k = max(a_k + LOOKUP_DELAY, f_{k−1})`, `f_k = b_k + 1` after a hit and
    /// `b_k + tc + MISS_RESTART` after a miss; a hit is answered in `b_k + 1`, a miss requested
    /// from the host in `b_k + 1` and answered in `b_k + tc + 2`.
    pub fn schedule(requests: &[(u64, bool)], tc: u64) -> Vec<RequestTiming> {
        let mut free = 0u64;
        requests
            .iter()
            .map(|&(a, hit)| {
                let lookup = (a + LOOKUP_DELAY).max(free);
                if hit {
                    free = lookup + 1;
                    RequestTiming { lookup, host_request: None, response: lookup + 1 }
                } else {
                    free = lookup + tc + MISS_RESTART;
                    RequestTiming { lookup, host_request: Some(lookup + 1), response: lookup + tc + 2 }
                }
            })
            .collect()
    }

    /// Cycles (rising edges) from cycle 0 until the last response of `n` hits requested back to
    /// back from cycle 0 has been presented: `n + HIT_LATENCY`; 0 for no request.
    pub fn all_hit_cycles(n: u64) -> u64 {
        if n == 0 {
            0
        } else {
            n + HIT_LATENCY
        }
    }
}

/// The patch cache (see the [module documentation](self)).
#[derive(LogicBlock)]
pub struct PatchCache {
    pub clock: Signal<In, Clock>,
    // Configuration.
    pub cfg_enable: Signal<In, bool>,
    pub cfg_mask: Signal<In, Bits<12>>,
    pub flush: Signal<In, bool>,
    pub flushing: Signal<Out, bool>,
    // Loader side.
    pub req: Signal<In, bool>,
    pub addr: Signal<In, Bits<16>>,
    pub resp_valid: Signal<Out, bool>,
    pub resp_ax: Signal<Out, Bits<17>>,
    pub resp_ay: Signal<Out, Bits<17>>,
    pub resp_bx: Signal<Out, Bits<17>>,
    pub resp_by: Signal<Out, Bits<17>>,
    // Host side.
    pub mem_req: Signal<Out, bool>,
    pub mem_addr: Signal<Out, Bits<16>>,
    pub mem_valid: Signal<In, bool>,
    pub mem_ax: Signal<In, Bits<17>>,
    pub mem_ay: Signal<In, Bits<17>>,
    pub mem_bx: Signal<In, Bits<17>>,
    pub mem_by: Signal<In, Bits<17>>,
    // Counters.
    pub hits: Signal<Out, Bits<32>>,
    pub misses: Signal<Out, Bits<32>>,
    // Request queue: five-bit pointers (slot = low four bits), so that full and empty differ.
    q_lane: Bram<16, QUEUE_BITS>,
    wr_ptr: DFF<Bits<5>>,
    /// The oldest request not yet answered.
    rd_ptr: DFF<Bits<5>>,
    /// The request whose id is at the queue lane's read register (stage Q).
    sp: DFF<Bits<5>>,
    /// `rd_ptr + 1` and `sp + 1`, each with bit 0 inverted (so that the power-up zero stands
    /// for 1): no carry chain between the pointers and the choice of the next read.
    rd_inc_x: DFF<Bits<5>>,
    sp_inc_x: DFF<Bits<5>>,
    /// That id was written before it was read: Q holds a request.
    q_valid: DFF<bool>,
    // Stages S1 and S2 (the lanes' two read registers): valid, id, tag key, line.
    v1: DFF<bool>,
    id1: DFF<Bits<16>>,
    key1: DFF<Bits<17>>,
    line1: DFF<Bits<12>>,
    v2: DFF<bool>,
    id2: DFF<Bits<16>>,
    key2: DFF<Bits<17>>,
    line2: DFF<Bits<12>>,
    // Stage S3 (lookup): S2's request, its tag compare and its line's words, registered.
    v3: DFF<bool>,
    id3: DFF<Bits<16>>,
    key3: DFF<Bits<17>>,
    line3: DFF<Bits<12>>,
    /// The tag compare by 4-bit slices of the tag (on ECP5 one per `DP16KD` tile), each
    /// registered: bits 0–3, 4–7, 8–11, 12–15 and 16.
    match3_0: DFF<bool>,
    match3_1: DFF<bool>,
    match3_2: DFF<bool>,
    match3_3: DFF<bool>,
    match3_4: DFF<bool>,
    ax3: DFF<Bits<17>>,
    ay3: DFF<Bits<17>>,
    bx3: DFF<Bits<17>>,
    by3: DFF<Bits<17>>,
    // W: a miss waiting for the host, its id, key and line.
    w_valid: DFF<bool>,
    w_id: DFF<Bits<16>>,
    w_key: DFF<Bits<17>>,
    w_line: DFF<Bits<12>>,
    // Flush: on, and the line being cleared.
    fl_on: DFF<bool>,
    fl_line: DFF<Bits<12>>,
    // Registered outputs.
    mreq: DFF<bool>,
    rv: DFF<bool>,
    rax: DFF<Bits<17>>,
    ray: DFF<Bits<17>>,
    rbx: DFF<Bits<17>>,
    rby: DFF<Bits<17>>,
    hit_count: DFF<Bits<32>>,
    miss_count: DFF<Bits<32>>,
    /// A hit in the last cycle: counted a cycle after the lookup, off the tag compare's path.
    hit_r: DFF<bool>,
    // The cache lanes: two-clock registered reads.
    tag: BramOut<17, CACHE_BITS>,
    lane_ax: BramOut<17, CACHE_BITS>,
    lane_ay: BramOut<17, CACHE_BITS>,
    lane_bx: BramOut<17, CACHE_BITS>,
    lane_by: BramOut<17, CACHE_BITS>,
    // Combinational.
    push: Signal<Local, bool>,
    issue: Signal<Local, bool>,
    tag_hit: Signal<Local, bool>,
    hit: Signal<Local, bool>,
    miss: Signal<Local, bool>,
    fill: Signal<Local, bool>,
    wr_inc: Signal<Local, Bits<5>>,
    rd_inc: Signal<Local, Bits<5>>,
    rd_next: Signal<Local, Bits<5>>,
    rd_inc2: Signal<Local, Bits<5>>,
    rd_next_inc: Signal<Local, Bits<5>>,
    sp_inc: Signal<Local, Bits<5>>,
    sp_inc2: Signal<Local, Bits<5>>,
    read_ptr: Signal<Local, Bits<5>>,
    read_inc: Signal<Local, Bits<5>>,
    ne_sp: Signal<Local, bool>,
    ne_sp_inc: Signal<Local, bool>,
    ne_rd: Signal<Local, bool>,
    ne_rd_inc: Signal<Local, bool>,
    read_new: Signal<Local, bool>,
    head_low: Signal<Local, Bits<12>>,
    head_line: Signal<Local, Bits<12>>,
    head_key: Signal<Local, Bits<17>>,
    hit_inc: Signal<Local, Bits<32>>,
    miss_inc: Signal<Local, Bits<32>>,
    fl_inc: Signal<Local, Bits<12>>,
    // Constants.
    valid_flag: Constant<Bits<17>>,
    one5: Constant<Bits<5>>,
    one32: Constant<Bits<32>>,
    one12: Constant<Bits<12>>,
    last_line: Constant<Bits<12>>,
    zero12: Constant<Bits<12>>,
    zero17: Constant<Bits<17>>,
}

impl Default for PatchCache {
    fn default() -> Self {
        assert_eq!(1 << QUEUE_BITS, QUEUE_DEPTH);
        assert_eq!(bram_out_tile_width(CACHE_BITS), 4, "the tag compare's slices are the tag's DP16KD tiles");
        PatchCache {
            clock: Default::default(),
            cfg_enable: Default::default(),
            cfg_mask: Default::default(),
            flush: Default::default(),
            flushing: Default::default(),
            req: Default::default(),
            addr: Default::default(),
            resp_valid: Default::default(),
            resp_ax: Default::default(),
            resp_ay: Default::default(),
            resp_bx: Default::default(),
            resp_by: Default::default(),
            mem_req: Default::default(),
            mem_addr: Default::default(),
            mem_valid: Default::default(),
            mem_ax: Default::default(),
            mem_ay: Default::default(),
            mem_bx: Default::default(),
            mem_by: Default::default(),
            hits: Default::default(),
            misses: Default::default(),
            q_lane: Default::default(),
            wr_ptr: Default::default(),
            rd_ptr: Default::default(),
            sp: Default::default(),
            rd_inc_x: Default::default(),
            sp_inc_x: Default::default(),
            q_valid: Default::default(),
            v1: Default::default(),
            id1: Default::default(),
            key1: Default::default(),
            line1: Default::default(),
            v2: Default::default(),
            id2: Default::default(),
            key2: Default::default(),
            line2: Default::default(),
            v3: Default::default(),
            id3: Default::default(),
            key3: Default::default(),
            line3: Default::default(),
            match3_0: Default::default(),
            match3_1: Default::default(),
            match3_2: Default::default(),
            match3_3: Default::default(),
            match3_4: Default::default(),
            ax3: Default::default(),
            ay3: Default::default(),
            bx3: Default::default(),
            by3: Default::default(),
            w_valid: Default::default(),
            w_id: Default::default(),
            w_key: Default::default(),
            w_line: Default::default(),
            fl_on: Default::default(),
            fl_line: Default::default(),
            mreq: Default::default(),
            rv: Default::default(),
            rax: Default::default(),
            ray: Default::default(),
            rbx: Default::default(),
            rby: Default::default(),
            hit_count: Default::default(),
            miss_count: Default::default(),
            hit_r: Default::default(),
            tag: Default::default(),
            lane_ax: Default::default(),
            lane_ay: Default::default(),
            lane_bx: Default::default(),
            lane_by: Default::default(),
            push: Default::default(),
            issue: Default::default(),
            tag_hit: Default::default(),
            hit: Default::default(),
            miss: Default::default(),
            fill: Default::default(),
            wr_inc: Default::default(),
            rd_inc: Default::default(),
            rd_next: Default::default(),
            rd_inc2: Default::default(),
            rd_next_inc: Default::default(),
            sp_inc: Default::default(),
            sp_inc2: Default::default(),
            read_ptr: Default::default(),
            read_inc: Default::default(),
            ne_sp: Default::default(),
            ne_sp_inc: Default::default(),
            ne_rd: Default::default(),
            ne_rd_inc: Default::default(),
            read_new: Default::default(),
            head_low: Default::default(),
            head_line: Default::default(),
            head_key: Default::default(),
            hit_inc: Default::default(),
            miss_inc: Default::default(),
            fl_inc: Default::default(),
            valid_flag: Constant::new(0x1_0000u64.into()),
            one5: Constant::new(1.into()),
            one32: Constant::new(1.into()),
            one12: Constant::new(1.into()),
            last_line: Constant::new(((LINES - 1) as u64).into()),
            zero12: Constant::new(0.into()),
            zero17: Constant::new(0.into()),
        }
    }
}

impl PatchCache {
    /// Requests held in the queue (not yet answered), `0..=QUEUE_DEPTH`: for testbenches.
    pub fn queued(&self) -> usize {
        (self.wr_ptr.q.val().index().wrapping_sub(self.rd_ptr.q.val().index())) % (2 * QUEUE_DEPTH)
    }

    /// Whether a miss is waiting for the host: for testbenches.
    pub fn waiting(&self) -> bool {
        self.w_valid.q.val()
    }
}

impl Logic for PatchCache {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, wr_ptr, rd_ptr, sp, rd_inc_x, sp_inc_x, q_valid, v1, id1, key1, line1, v2, id2,
            key2, line2, v3, id3, key3, line3, match3_0, match3_1, match3_2, match3_3, match3_4, ax3, ay3,
            bx3, by3, w_valid, w_id, w_key, w_line, fl_on, fl_line, mreq, rv, rax, ray, rbx, rby, hit_count,
            miss_count, hit_r
        );
        self.q_lane.clock.next = self.clock.val();
        self.tag.clock.next = self.clock.val();
        self.lane_ax.clock.next = self.clock.val();
        self.lane_ay.clock.next = self.clock.val();
        self.lane_bx.clock.next = self.clock.val();
        self.lane_by.clock.next = self.clock.val();

        // Pointer and counter arithmetic, each at its exact width.
        self.wr_inc.next = self.wr_ptr.q.val() + self.one5.val();
        self.rd_inc.next = self.rd_inc_x.q.val() ^ self.one5.val();
        self.rd_inc2.next = self.rd_inc.val() + self.one5.val();
        self.sp_inc.next = self.sp_inc_x.q.val() ^ self.one5.val();
        self.sp_inc2.next = self.sp_inc.val() + self.one5.val();
        self.hit_inc.next = self.hit_count.q.val() + self.one32.val();
        self.miss_inc.next = self.miss_count.q.val() + self.one32.val();

        // S2: the lanes' output registers hold the line of S2's id. While a miss waits, every
        // lookup in flight is void (it is issued again after the fill).
        self.v3.d.next = self.v2.q.val() & !self.w_valid.q.val();
        self.id3.d.next = self.id2.q.val();
        self.key3.d.next = self.key2.q.val();
        self.line3.d.next = self.line2.q.val();
        // The tag compare by slices, each registered: on ECP5 a slice is one DP16KD tile's
        // output, so each compare can sit next to its tile and only the registered bits
        // travel (the tiles are far apart).
        self.match3_0.d.next =
            self.tag.read_data.val().get_bits::<4>(0) == self.key2.q.val().get_bits::<4>(0);
        self.match3_1.d.next =
            self.tag.read_data.val().get_bits::<4>(4) == self.key2.q.val().get_bits::<4>(4);
        self.match3_2.d.next =
            self.tag.read_data.val().get_bits::<4>(8) == self.key2.q.val().get_bits::<4>(8);
        self.match3_3.d.next =
            self.tag.read_data.val().get_bits::<4>(12) == self.key2.q.val().get_bits::<4>(12);
        self.match3_4.d.next = self.tag.read_data.val().get_bit(16) == self.key2.q.val().get_bit(16);
        self.ax3.d.next = self.lane_ax.read_data.val();
        self.ay3.d.next = self.lane_ay.read_data.val();
        self.bx3.d.next = self.lane_bx.read_data.val();
        self.by3.d.next = self.lane_by.read_data.val();
        // S3: the lookup, from registers only.
        self.tag_hit.next = self.match3_0.q.val()
            & self.match3_1.q.val()
            & self.match3_2.q.val()
            & self.match3_3.q.val()
            & self.match3_4.q.val();
        self.hit.next = self.v3.q.val() & !self.w_valid.q.val() & self.tag_hit.val();
        self.miss.next = self.v3.q.val() & !self.w_valid.q.val() & !self.tag_hit.val();
        // W: the host's answer to the miss.
        self.fill.next = self.w_valid.q.val() & self.mem_valid.val();

        // Request queue: push at the tail.
        self.push.next = self.cfg_enable.val() & self.req.val();
        self.q_lane.write_address.next = self.wr_ptr.q.val().get_bits::<4>(0);
        self.q_lane.write_data.next = self.addr.val();
        self.q_lane.write_enable.next = self.push.val();
        if self.push.val() {
            self.wr_ptr.d.next = self.wr_inc.val();
        }
        // A hit or a fill answers the oldest request.
        self.rd_next.next = self.rd_ptr.q.val();
        self.rd_next_inc.next = self.rd_inc.val();
        if self.hit.val() | self.fill.val() {
            self.rd_next.next = self.rd_inc.val();
            self.rd_next_inc.next = self.rd_inc2.val();
        }
        self.rd_ptr.d.next = self.rd_next.val();
        self.rd_inc_x.d.next = self.rd_next_inc.val() ^ self.one5.val();

        // Q: issue the request at the queue lane's read register into S1, unless a miss waits;
        // then read the next one. While a miss waits, read the oldest unanswered request: after
        // the fill, the lookups start again from it.
        // The read is valid next cycle when its request was written before this edge (read
        // before write): each candidate is compared with wr_ptr beside the choice, so no
        // compare follows the pointer multiplexer.
        self.issue.next = self.q_valid.q.val() & !self.w_valid.q.val();
        self.ne_sp.next = self.sp.q.val() != self.wr_ptr.q.val();
        self.ne_sp_inc.next = self.sp_inc.val() != self.wr_ptr.q.val();
        self.ne_rd.next = self.rd_ptr.q.val() != self.wr_ptr.q.val();
        self.ne_rd_inc.next = self.rd_inc.val() != self.wr_ptr.q.val();
        self.read_ptr.next = self.sp.q.val();
        self.read_inc.next = self.sp_inc.val();
        self.read_new.next = self.ne_sp.val();
        if self.issue.val() {
            self.read_ptr.next = self.sp_inc.val();
            self.read_inc.next = self.sp_inc2.val();
            self.read_new.next = self.ne_sp_inc.val();
        }
        // (rd_next without the hit term: no hit while a miss waits. The tag compare must not
        // reach the queue's pointers.)
        if self.w_valid.q.val() {
            self.read_ptr.next = self.rd_ptr.q.val();
            self.read_inc.next = self.rd_inc.val();
            self.read_new.next = self.ne_rd.val();
            if self.mem_valid.val() {
                self.read_ptr.next = self.rd_inc.val();
                self.read_inc.next = self.rd_inc2.val();
                self.read_new.next = self.ne_rd_inc.val();
            }
        }
        self.sp.d.next = self.read_ptr.val();
        self.sp_inc_x.d.next = self.read_inc.val() ^ self.one5.val();
        self.q_lane.read_address.next = self.read_ptr.val().get_bits::<4>(0);
        self.q_valid.d.next = self.read_new.val();

        // Q: read the request's line in every lane.
        self.head_low.next = bit_cast::<12, 16>(self.q_lane.read_data.val());
        self.head_line.next = self.head_low.val() & self.cfg_mask.val();
        self.head_key.next = self.valid_flag.val() | bit_cast::<17, 16>(self.q_lane.read_data.val());
        self.tag.read_address.next = self.head_line.val();
        self.lane_ax.read_address.next = self.head_line.val();
        self.lane_ay.read_address.next = self.head_line.val();
        self.lane_bx.read_address.next = self.head_line.val();
        self.lane_by.read_address.next = self.head_line.val();
        self.v1.d.next = self.issue.val();
        self.id1.d.next = self.q_lane.read_data.val();
        self.key1.d.next = self.head_key.val();
        self.line1.d.next = self.head_line.val();
        self.v2.d.next = self.v1.q.val() & !self.w_valid.q.val();
        self.id2.d.next = self.id1.q.val();
        self.key2.d.next = self.key1.q.val();
        self.line2.d.next = self.line1.q.val();

        // A miss: request the patch (next cycle) and wait for it.
        self.mreq.d.next = self.miss.val();
        self.w_valid.d.next = (self.w_valid.q.val() & !self.mem_valid.val()) | self.miss.val();
        if !self.w_valid.q.val() {
            self.w_id.d.next = self.id3.q.val();
            self.w_key.d.next = self.key3.q.val();
            self.w_line.d.next = self.line3.q.val();
        }

        // The fill: write the line, tag and data.
        self.tag.write_address.next = self.w_line.q.val();
        self.lane_ax.write_address.next = self.w_line.q.val();
        self.lane_ay.write_address.next = self.w_line.q.val();
        self.lane_bx.write_address.next = self.w_line.q.val();
        self.lane_by.write_address.next = self.w_line.q.val();
        self.tag.write_data.next = self.w_key.q.val();
        self.lane_ax.write_data.next = self.mem_ax.val();
        self.lane_ay.write_data.next = self.mem_ay.val();
        self.lane_bx.write_data.next = self.mem_bx.val();
        self.lane_by.write_data.next = self.mem_by.val();
        self.tag.write_enable.next = self.fill.val();
        // The flush: clear one tag per cycle, line 0 to the last (no fill can be pending).
        self.fl_inc.next = self.fl_line.q.val() + self.one12.val();
        if self.fl_on.q.val() {
            self.tag.write_address.next = self.fl_line.q.val();
            self.tag.write_data.next = self.zero17.val();
            self.tag.write_enable.next = true;
            self.fl_line.d.next = self.fl_inc.val();
            if self.fl_line.q.val() == self.last_line.val() {
                self.fl_on.d.next = false;
            }
        }
        if self.flush.val() & !self.fl_on.q.val() {
            self.fl_on.d.next = true;
            self.fl_line.d.next = self.zero12.val();
        }
        self.flushing.next = self.fl_on.q.val();
        self.lane_ax.write_enable.next = self.fill.val();
        self.lane_ay.write_enable.next = self.fill.val();
        self.lane_bx.write_enable.next = self.fill.val();
        self.lane_by.write_enable.next = self.fill.val();

        // Responses: a hit from S3's words, a fill from the host. The data registers take S3's
        // words whatever the tag said (fewer loads on the lookup); they matter only with `rv`.
        self.rv.d.next = self.hit.val() | self.fill.val();
        if self.v3.q.val() {
            self.rax.d.next = self.ax3.q.val();
            self.ray.d.next = self.ay3.q.val();
            self.rbx.d.next = self.bx3.q.val();
            self.rby.d.next = self.by3.q.val();
        }
        if self.w_valid.q.val() {
            self.rax.d.next = self.mem_ax.val();
            self.ray.d.next = self.mem_ay.val();
            self.rbx.d.next = self.mem_bx.val();
            self.rby.d.next = self.mem_by.val();
        }

        // Counters, a cycle after the lookup (a miss's host request is that cycle's `mreq`).
        self.hit_r.d.next = self.hit.val();
        if self.hit_r.q.val() {
            self.hit_count.d.next = self.hit_inc.val();
        }
        if self.mreq.q.val() {
            self.miss_count.d.next = self.miss_inc.val();
        }
        self.hits.next = self.hit_count.q.val();
        self.misses.next = self.miss_count.q.val();

        // Outputs: the pipeline's registers, or wires when disabled.
        self.mem_req.next = self.req.val();
        self.mem_addr.next = self.addr.val();
        self.resp_valid.next = self.mem_valid.val();
        self.resp_ax.next = self.mem_ax.val();
        self.resp_ay.next = self.mem_ay.val();
        self.resp_bx.next = self.mem_bx.val();
        self.resp_by.next = self.mem_by.val();
        if self.cfg_enable.val() {
            self.mem_req.next = self.mreq.q.val();
            self.mem_addr.next = self.w_id.q.val();
            self.resp_valid.next = self.rv.q.val();
            self.resp_ax.next = self.rax.q.val();
            self.resp_ay.next = self.ray.q.val();
            self.resp_bx.next = self.rbx.q.val();
            self.resp_by.next = self.rby.q.val();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::model::*;
    use super::*;
    use rust_hdl::core::prelude::simulate;

    #[test]
    fn model_is_direct_mapped_and_keeps_contents_across_masks() {
        let mut c = Cache::new(mask_for(16).unwrap());
        assert_eq!(
            c.run(&[0, 0, 16, 0, 1, 17, 1, 0xFFFF, 0xFFFF]),
            [false, true, false, false, false, false, false, false, true]
        );
        // Line 0 holds 0, line 1 holds 1, line 15 holds 0xFFFF. One line: only the last id.
        c.set_mask(0);
        assert_eq!(c.run(&[0, 0, 1]), [true, true, false]);
        assert_eq!(mask_for(4096), Some(0xFFF));
        assert_eq!(mask_for(1), Some(0));
        assert_eq!(mask_for(8192), None);
        assert_eq!(mask_for(12), None);
    }

    #[test]
    fn schedule_gives_one_hit_per_clock_and_t_c_plus_5_per_miss() {
        let hits: Vec<(u64, bool)> = (0..5).map(|k| (k, true)).collect();
        let s = schedule(&hits, 8);
        assert_eq!(s.iter().map(|t| t.response).collect::<Vec<_>>(), [6, 7, 8, 9, 10]);
        assert_eq!(all_hit_cycles(5), 11);
        let s = schedule(&[(0, false), (1, true), (2, false), (30, true)], 8);
        assert_eq!(s[0], RequestTiming { lookup: 5, host_request: Some(6), response: 15 });
        assert_eq!(s[1], RequestTiming { lookup: 18, host_request: None, response: 19 });
        assert_eq!(s[2], RequestTiming { lookup: 19, host_request: Some(20), response: 29 });
        assert_eq!(s[3], RequestTiming { lookup: 35, host_request: None, response: 36 });
    }

    /// A quick directed run: a miss, hits one per clock, then two ids that evict each other, at
    /// the model's cycles.
    #[test]
    fn cache_quick_run_matches_model() {
        let mut u = PatchCache::default();
        u.connect_all();
        check_all(&u).unwrap();
        let tc = 2u64;
        let data = |id: u16| [id as u64, id as u64 + 1, id as u64 * 2, 0x1_FFFF - id as u64];
        let ids = [5u16, 5, 5, 5, 21, 5, 21];
        let mut cache = Cache::new(15);
        let expect = schedule(
            &ids.iter().enumerate().map(|(k, &id)| (k as u64, cache.access(id))).collect::<Vec<_>>(),
            tc,
        );
        let mut inflight: Option<(u64, u16)> = None;
        let mut got = vec![];
        for cycle in 0..40u64 {
            let answer = inflight.filter(|r| r.0 == cycle).map(|r| r.1);
            if answer.is_some() {
                inflight = None;
            }
            u.clock.next = false.into();
            u.cfg_enable.next = true;
            u.cfg_mask.next = 15.into();
            let req = ids.get(cycle as usize).copied();
            u.req.next = req.is_some();
            u.addr.next = (req.unwrap_or(0) as u64).into();
            u.mem_valid.next = answer.is_some();
            let m = data(answer.unwrap_or(0));
            u.mem_ax.next = m[0].into();
            u.mem_ay.next = m[1].into();
            u.mem_bx.next = m[2].into();
            u.mem_by.next = m[3].into();
            assert!(simulate(&mut u, 100));
            if u.mem_req.val() {
                assert!(inflight.is_none());
                inflight = Some((cycle + tc, u.mem_addr.val().to_u16()));
            }
            if u.resp_valid.val() {
                let d =
                    [u.resp_ax.val(), u.resp_ay.val(), u.resp_bx.val(), u.resp_by.val()].map(|b| b.to_u64());
                got.push((cycle, d));
            }
            u.clock.next = true.into();
            assert!(simulate(&mut u, 100));
        }
        let want: Vec<_> = ids.iter().zip(&expect).map(|(&id, t)| (t.response, data(id))).collect();
        assert_eq!(got, want);
        let hits = expect.iter().filter(|t| t.host_request.is_none()).count() as u32;
        assert_eq!((hits, ids.len() as u32 - hits), (3, 4));
        assert_eq!((u.hits.val().to_u32(), u.misses.val().to_u32()), (3, 4));
    }
}
