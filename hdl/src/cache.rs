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
//! | `cfg_mask` | in | 10 | lines − 1 (lines a power of two, 1 … [`LINES`]); line of id = `id & cfg_mask` |
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
//! A non-blocking, in-order cache: lookups run ahead of the answers, so a miss does not stop
//! the hits and misses behind it; up to [`MISSES`] misses are outstanding at the host at once,
//! and every request is answered in request order.
//!
//! * A request queue of [`QUEUE_DEPTH`] ids (a [`Bram`] lane with registered read, as the
//!   loader's FIFO, with five-bit pointers). The client must keep at most [`QUEUE_DEPTH`]
//!   requests outstanding (the loader does: at most one per FIFO slot, `crate::loader::DEPTH` =
//!   16); a request leaves the queue when its lookup is accepted, and stays in the answer queue
//!   until it is answered, so neither queue can overflow.
//! * Five [`BramOut`] lanes of [`LINES`] words, two clocks from read address to data (on ECP5
//!   one block RAM tile each, 1024 × 18, with its output register): the tag (bit 16: valid,
//!   bits 15…0: the whole id) and the four 17-bit coordinates; zero (invalid) at power-up.
//! * A lookup pipeline, one request per clock, in request order:
//!   - **Q** (issue): the id of the next request to look up is at the queue lane's read
//!     register; its line is presented to the lanes and the request moves to S1, and the queue
//!     lane reads the request after it.
//!   - **S1**: the lanes' first read register.
//!   - **S2**: the lanes' output registers hold the request's line; `tag == {1, id}` is
//!     computed and registered, with the line's words; and the staleness check (below),
//!     registered.
//!   - **S3** (lookup): the request is accepted, a hit with its words or a miss, into the
//!     answer queue; a miss also into the miss table, and its host request goes out in the
//!     next cycle. Or it is not accepted (below) and the lookups are rewound to it.
//! * The **miss table**: the ids and lines of the [`MISSES`] newest misses accepted and not yet
//!   answered (registers), oldest first, and the id and line filled in the last cycle.
//! * The **answer queue** ([`FifoControl`] over [`FifoRam`] lanes, [`QUEUE_DEPTH`] entries):
//!   every accepted request in order, a hit with its four words, a miss with its id and line.
//!   The **return queue** ([`MISSES`] entries): the host's answers, in order, until their turn.
//! * The **answer**: the answer queue's head is answered (`resp_*` registered) when it is a hit,
//!   or a miss whose patch is at the return queue's head; a miss's patch is then written into
//!   its line (tag and data) and the miss leaves the table. One answer per clock. A
//!   `mem_valid` while no miss is outstanding is a protocol violation and is ignored.
//!
//! Staleness. A request reads its line in Q, but a miss ahead of it writes that line only when
//! it is answered: the words read may be older than the model's line. In S1 the request's line
//! and id are compared with the table's entries, the last fill, S3's request if it is a miss
//! (it enters the table at that edge), and S2's if it turns out a miss in S3; each compare is
//! registered and they are combined in S2. If none matches, the words read are the model's. If some match by line only, the newest of them (a different id) holds the line
//! in the model: the request is a miss, whatever the stale tag says, and its host request goes
//! out at once (misses to one line are filled in order). If one matches the request's own id,
//! its patch is not in the line yet: S3 does not accept it and rewinds the lookups (the request
//! and the two behind it are void, and Q reads it again), until that fill is in the line; so
//! also when the table is full. The conditions of a rewind are registers (the staleness check's
//! and the table's valid bits): the tag compare reaches no pointer. The tag compare feeds one
//! register: no path runs from a block RAM through the compare into the pipeline's control,
//! and the compare can be placed next to the tag's tile. (With 4096 lines, four tiles a lane
//! far apart on the die, the compare was cut in four slices, one per tile; the lanes' 25 block
//! RAMs were most of the PE's, and 1024 lines hold the paper's scenes.)
//! The queue's pointers keep `+ 1` in registers and compare each candidate for the next read
//! with the write pointer beside the choice, so no carry chain or compare follows the pointer
//! multiplexer.
//!
//! With the cache enabled every output is a register (`mem_req`, `mem_addr`, `resp_*`,
//! counters): no combinational path crosses the block. `resp_*` are meaningful only while
//! `resp_valid` is high, and `mem_addr` only while `mem_req` is, identically in the rust-hdl
//! simulation and in the Verilog.
//!
//! # Latency and throughput (enabled)
//!
//! For a request seen (`req` high) in cycle `a` by an idle block:
//!
//! * it is looked up (in S3) in cycle `a + 5` ([`model::LOOKUP_DELAY`]);
//! * a **hit** is answered (`resp_valid`) in cycle `a + 8` ([`model::HIT_LATENCY`]: the answer
//!   queue's two clocks and the response register);
//! * a **miss** is requested from the host (`mem_req`) in cycle `a + 6`
//!   ([`model::HOST_REQUEST_DELAY`]); the host answers in cycle `a + 6 + T_c`; the client's
//!   response follows in cycle `a + 9 + T_c` (`T_c +` [`model::MISS_OVERHEAD`]).
//!
//! A stream of hits is answered **one per clock**; lookups go on behind a miss, so the host
//! gets the next miss's request while it serves the first (up to [`MISSES`] outstanding), and a
//! host serving one load per `T_c` cycles is kept busy: a stream with `m` misses takes about
//! `max(m·T_c, requests)` cycles plus the latency. A request for the id of a miss still
//! outstanding waits for that miss's fill (a rewind costs [`model::REWIND_DELAY`] cycles per
//! try). [`model::schedule`] gives the exact lookup, host request and response cycles of any
//! stream.
//!
//! # Model
//!
//! [`model::Cache`]: the direct-mapped cache state, `access(id) → hit?`. For any request
//! stream the RTL's hit/miss sequence equals the model's, its host requests are exactly the
//! missed ids in order, and the responses carry the host memory's coordinates of the requested
//! ids in request order. [`model::schedule`] steps the RTL's control on plain values and gives
//! the exact lookup, host request and response cycles from the request cycles and ids, the
//! hit/miss sequence and `T_c`.
//!
//! # Verification
//!
//! The simulation tests (`testbench/tests/cache.rs`) check the model's claims above on random
//! streams: every response's data, order and cycle, the hit/miss sequence and the host
//! requests, for 1 to 1024 lines, disabled and across mask changes (the flush: the processing
//! element's tests, `testbench/tests/pe.rs`), and with hosts of varying latency
//! ([`model::schedule_with_host`]) whose answers fill the return queue, four of them held behind
//! hits while the host is idle. `cache.sby` proves on the exported Verilog, for
//! every input sequence (k-induction; `hdl/FORMAL.md`), that every request is answered exactly
//! once, in request order, with the host memory's patch of its id (no answer lost, duplicated,
//! reordered or carrying another patch), given a client within [`QUEUE_DEPTH`] and a host that
//! answers its requests in order with the right patch; and that at most [`MISSES`] host
//! requests are outstanding, each for an id that a request still outstanding asked for and none
//! for an id already outstanding at the host (a request for a miss's id waits for its fill).
//! The proof is of the enabled cache with one to four lines (`cfg_mask` ≤ 3: the harness cuts
//! the line memories to four words) and without a flush (which walks all [`LINES`] lines).

use crate::prim::{bram_out_tile_width, Bram, BramOut, FifoControl, FifoRam};
use rust_hdl::prelude::*;

/// Address width of the cache lanes: at most `2^CACHE_BITS` lines.
pub const CACHE_BITS: usize = 10;
/// The largest number of lines (1024 patches): one `DP16KD` tile (1024 × 18) a lane on ECP5.
pub const LINES: usize = 1 << CACHE_BITS;
/// Request queue capacity: the most requests a client may keep outstanding.
pub const QUEUE_DEPTH: usize = 16;
/// Address width of the request queue: `2^QUEUE_BITS == QUEUE_DEPTH`.
pub const QUEUE_BITS: usize = 4;
/// The answer queue's meta word: `{miss, line, id}`.
const META_WIDTH: usize = 16 + CACHE_BITS + 1;
const _: () = assert!(META_WIDTH == 27, "the miss flag is bit 26 of the meta word");
/// The most misses outstanding (accepted, not yet answered): the miss table's entries.
pub const MISSES: usize = 4;
/// Address width of the return queue: `2^MISS_BITS == MISSES`.
pub const MISS_BITS: usize = 2;

/// The behavioural model of the patch cache: its state, and its exact timing.
pub mod model {
    use super::{CACHE_BITS, LINES};

    /// Cycles from a request (`req` high) to its lookup, in an idle block.
    pub const LOOKUP_DELAY: u64 = 5;
    /// Cycles from a request to its response when it hits, in an idle block: the answer queue
    /// (two clocks from its push to its head) and the response register after the lookup.
    pub const HIT_LATENCY: u64 = LOOKUP_DELAY + 3;
    /// Cycles from a request to its host request when it misses, in an idle block.
    pub const HOST_REQUEST_DELAY: u64 = LOOKUP_DELAY + 1;
    /// Cycles from a request to its response beyond the host's `T_c` when it misses, in an idle
    /// block: the response comes `T_c + MISS_OVERHEAD` cycles after the request (the host
    /// request one cycle after the lookup, the return queue's two clocks, the response
    /// register).
    pub const MISS_OVERHEAD: u64 = LOOKUP_DELAY + 4;
    /// Cycles from a lookup that is not accepted (its line may be stale, or the miss table is
    /// full) to its next lookup: it is read again from the request queue and passes S1 and S2.
    pub const REWIND_DELAY: u64 = 4;

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
        /// If `mask` does not fit the `CACHE_BITS`-bit `cfg_mask` (`mask ≥ LINES`).
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
            assert!((mask as usize) < LINES, "cache mask {mask:#x} does not fit {CACHE_BITS} bits");
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
        /// The cycle it is accepted in the lookup stage (S3).
        pub lookup: u64,
        /// The cycle of its host request (`mem_req`), on a miss.
        pub host_request: Option<u64>,
        /// The cycle of its response (`resp_valid`).
        pub response: u64,
    }

    /// One request of a stream for [`schedule`].
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub struct Request {
        /// The cycle it is seen (`req` high); strictly increasing along the stream.
        pub cycle: u64,
        /// Its patch id.
        pub id: u16,
        /// Whether it hits ([`Cache::access`] in stream order).
        pub hit: bool,
    }

    /// The exact cycles of a request stream through the enabled RTL, from power-up or from an
    /// idle block, with a host that serves its requests in order, one at a time, `tc` cycles
    /// each (`testbench::memory::HostMemory`: request `k`, made in cycle `r_k`, is answered in
    /// `e_k = max(r_k, e_{k−1}) + tc`). The RTL's control stepped on plain values, cycle by
    /// cycle, register by register:
    ///
    /// * the request queue is read one request ahead (Q); the request read moves to S1, S2
    ///   and S3 one stage per cycle;
    /// * S3 accepts its request unless its own id may be on its way into its line (computed in
    ///   S1 and S2: a miss to the same id not yet filled, or filled since its read)
    ///   or the miss table holds [`super::MISSES`] misses; otherwise S3 rewinds (S1 and S2
    ///   void, Q reads the request again);
    /// * an accepted request enters the answer queue (at its head two cycles later); a miss
    ///   enters the table and is requested from the host in the next cycle; the host's answer
    ///   enters the return queue (at its head two cycles later);
    /// * the head of the answer queue is answered (`resp_valid` in the next cycle) when it is a
    ///   hit or its patch is at the head of the return queue; a miss then fills its line and
    ///   leaves the table.
    pub fn schedule(requests: &[Request], tc: u64) -> Vec<RequestTiming> {
        schedule_with_host(requests, |r, last| r.max(last) + tc)
    }

    /// [`schedule`] with any host that answers its requests in order, one per cycle at most:
    /// `host(r, e)` is the cycle in which the host answers (presents `mem_valid` for) its next
    /// request, made in cycle `r`, when it answered the one before in cycle `e` (0 before the
    /// first); it must be later than both. [`schedule`] is the host memory's
    /// `host(r, e) = max(r, e) + tc`.
    pub fn schedule_with_host(
        requests: &[Request],
        mut host_answer: impl FnMut(u64, u64) -> u64,
    ) -> Vec<RequestTiming> {
        use std::collections::VecDeque;
        let n = requests.len();
        let mut out: Vec<RequestTiming> =
            vec![RequestTiming { lookup: 0, host_request: None, response: 0 }; n];
        let (mut sp, mut rd, mut q_valid) = (0usize, 0usize, false);
        let (mut s1, mut s2, mut s3): (Option<usize>, Option<usize>, Option<usize>) = (None, None, None);
        let mut conf3 = false;
        // The ids of the misses accepted and not yet filled.
        let mut table: VecDeque<u16> = VecDeque::new();
        let (mut f1, mut f2): (Option<u16>, Option<u16>) = (None, None);
        // (request, cycle pushed) of the answer queue; (cycle pushed) of the return queue.
        let mut answers: VecDeque<(usize, u64)> = VecDeque::new();
        let mut returns: VecDeque<u64> = VecDeque::new();
        // Host answers still to come: their cycles.
        let mut host: VecDeque<u64> = VecDeque::new();
        let mut last_answer = 0u64;
        let mut answered = 0usize;
        let start = requests.first().map_or(0, |r| r.cycle);
        let mut t = start;
        while answered < n {
            assert!(
                t <= start.max(last_answer) + (n as u64 + 1) * 64 + 1024,
                "the cache model stalled at cycle {t}"
            );
            // Requests written into the queue before this cycle's edge.
            let written = requests.iter().take_while(|r| r.cycle < t).count();
            // S3.
            let rewind = s3.is_some() && (conf3 || table.len() == super::MISSES);
            let accept = if rewind { None } else { s3 };
            // S2's staleness check, for S3 next cycle.
            let conflict = s2.is_some_and(|k| {
                let id = requests[k].id;
                table.contains(&id)
                    || f1 == Some(id)
                    || f2 == Some(id)
                    || s3.is_some_and(|j| !requests[j].hit && requests[j].id == id)
            });
            // The answer stage.
            let head = answers.front().filter(|&&(_, pushed)| pushed + 2 <= t).map(|&(k, _)| k);
            let ret_ready = returns.front().is_some_and(|&pushed| pushed + 2 <= t);
            let answer = head.filter(|&k| requests[k].hit || ret_ready);
            let fill = answer.filter(|&k| !requests[k].hit).map(|k| requests[k].id);
            // The host's answer presented in this cycle enters the return queue.
            if host.front() == Some(&t) {
                host.pop_front();
                returns.push_back(t);
            }
            // The edge.
            if let Some(k) = answer {
                answers.pop_front();
                out[k].response = t + 1;
                answered += 1;
            }
            if fill.is_some() {
                returns.pop_front();
                table.pop_front();
            }
            (f2, f1) = (f1, fill);
            if let Some(k) = accept {
                out[k].lookup = t;
                answers.push_back((k, t));
                rd += 1;
                if !requests[k].hit {
                    table.push_back(requests[k].id);
                    let r = t + 1;
                    out[k].host_request = Some(r);
                    let e = host_answer(r, last_answer);
                    assert!(e > r && e > last_answer, "the host answers in order, after the request");
                    last_answer = e;
                    host.push_back(last_answer);
                }
            }
            let issue = q_valid && !rewind;
            let next = if rewind {
                rd
            } else if issue {
                sp + 1
            } else {
                sp
            };
            (s3, s2, s1) = if rewind { (None, None, None) } else { (s2, s1, issue.then_some(sp)) };
            conf3 = conflict;
            sp = next;
            q_valid = sp < written;
            t += 1;
        }
        out
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
    pub cfg_mask: Signal<In, Bits<CACHE_BITS>>,
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
    /// The oldest request not yet accepted by the lookup (S3).
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
    line1: DFF<Bits<CACHE_BITS>>,
    v2: DFF<bool>,
    id2: DFF<Bits<16>>,
    key2: DFF<Bits<17>>,
    line2: DFF<Bits<CACHE_BITS>>,
    // Stage S3 (lookup): S2's request, its tag compare and its line's words, registered.
    v3: DFF<bool>,
    id3: DFF<Bits<16>>,
    line3: DFF<Bits<CACHE_BITS>>,
    /// The tag compare, registered (on ECP5 beside the tag's one `DP16KD` tile).
    match3: DFF<bool>,
    /// S3's line may be stale: a miss to it was outstanding when S3's request read the lanes
    /// (`lconf3`); one of those misses was S3's own id (`iconf3`).
    lconf3: DFF<bool>,
    iconf3: DFF<bool>,
    ax3: DFF<Bits<17>>,
    ay3: DFF<Bits<17>>,
    bx3: DFF<Bits<17>>,
    by3: DFF<Bits<17>>,
    // The miss table: the ids and lines of the misses accepted and not yet filled, oldest at
    // `t_rp`.
    t_id0: DFF<Bits<16>>,
    t_id1: DFF<Bits<16>>,
    t_id2: DFF<Bits<16>>,
    t_id3: DFF<Bits<16>>,
    t_line0: DFF<Bits<CACHE_BITS>>,
    t_line1: DFF<Bits<CACHE_BITS>>,
    t_line2: DFF<Bits<CACHE_BITS>>,
    t_line3: DFF<Bits<CACHE_BITS>>,
    t_v0: DFF<bool>,
    t_v1: DFF<bool>,
    t_v2: DFF<bool>,
    t_v3: DFF<bool>,
    /// Some entry is valid (the OR of the `t_v*`), registered from their next values.
    t_any: DFF<bool>,
    /// Misses in the table (`0..=MISSES`), and "the table is full" as a register of its own
    /// (from the count's next value), so that the accept and the rewind are one gate of
    /// registers.
    t_n: DFF<Bits<3>>,
    t_full: DFF<bool>,
    t_wp: DFF<Bits<2>>,
    t_rp: DFF<Bits<2>>,
    /// The id and line filled in the last cycle (out of the table, maybe not yet seen by a read).
    f_id1: DFF<Bits<16>>,
    f_line1: DFF<Bits<CACHE_BITS>>,
    f_v1: DFF<bool>,
    /// The staleness check's compares, made in S1 and registered into S2, against each source
    /// of a fill S1's request may not have read: the table's four entries, the last fill,
    /// S3's request if a miss, and S2's (a miss or not is known a cycle later). `mi*`: the
    /// same id; `ml*`: the same line.
    mi0: DFF<bool>,
    mi1: DFF<bool>,
    mi2: DFF<bool>,
    mi3: DFF<bool>,
    mif: DFF<bool>,
    mis3: DFF<bool>,
    mis2: DFF<bool>,
    ml0: DFF<bool>,
    ml1: DFF<bool>,
    ml2: DFF<bool>,
    ml3: DFF<bool>,
    mlf: DFF<bool>,
    mls3: DFF<bool>,
    mls2: DFF<bool>,
    // The answer queue: every accepted request in order; a hit with its words, a miss with
    // its id and line ({miss, line, id} in the meta lane).
    ans: FifoControl<QUEUE_BITS, 5>,
    ans_ax: FifoRam<17, QUEUE_BITS>,
    ans_ay: FifoRam<17, QUEUE_BITS>,
    ans_bx: FifoRam<17, QUEUE_BITS>,
    ans_by: FifoRam<17, QUEUE_BITS>,
    ans_meta: FifoRam<META_WIDTH, QUEUE_BITS>,
    // The host's answers to the misses, in order, until their turn comes.
    ret: FifoControl<MISS_BITS, 3>,
    ret_ax: FifoRam<17, MISS_BITS>,
    ret_ay: FifoRam<17, MISS_BITS>,
    ret_bx: FifoRam<17, MISS_BITS>,
    ret_by: FifoRam<17, MISS_BITS>,
    // Flush: on, and the line being cleared.
    fl_on: DFF<bool>,
    fl_line: DFF<Bits<CACHE_BITS>>,
    // Registered outputs.
    mreq: DFF<bool>,
    maddr: DFF<Bits<16>>,
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
    table_full: Signal<Local, bool>,
    ret_push: Signal<Local, bool>,
    /// The return queue holds [`MISSES`] answers: from the count's next value, so that the
    /// return lanes' write enables are a register (`!ret_full`), not the host's `mem_valid`.
    ret_full: DFF<bool>,
    waiting_any: Signal<Local, bool>,
    tv0_next: Signal<Local, bool>,
    tv1_next: Signal<Local, bool>,
    tv2_next: Signal<Local, bool>,
    tv3_next: Signal<Local, bool>,
    rewind: Signal<Local, bool>,
    accept: Signal<Local, bool>,
    tag_hit: Signal<Local, bool>,
    hit: Signal<Local, bool>,
    miss: Signal<Local, bool>,
    line_conflict: Signal<Local, bool>,
    id_conflict: Signal<Local, bool>,
    miss3: Signal<Local, bool>,
    head_id_fill: Signal<Local, Bits<16>>,
    head_miss: Signal<Local, bool>,
    answer: Signal<Local, bool>,
    fill: Signal<Local, bool>,
    meta_in: Signal<Local, Bits<META_WIDTH>>,
    head_key_fill: Signal<Local, Bits<17>>,
    head_line_fill: Signal<Local, Bits<CACHE_BITS>>,
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
    read_new: Signal<Local, bool>,
    head_low: Signal<Local, Bits<CACHE_BITS>>,
    head_line: Signal<Local, Bits<CACHE_BITS>>,
    head_key: Signal<Local, Bits<17>>,
    hit_inc: Signal<Local, Bits<32>>,
    miss_inc: Signal<Local, Bits<32>>,
    fl_inc: Signal<Local, Bits<CACHE_BITS>>,
    t_wp_inc: Signal<Local, Bits<2>>,
    t_rp_inc: Signal<Local, Bits<2>>,
    // Constants.
    valid_flag: Constant<Bits<17>>,
    miss_flag: Constant<Bits<META_WIDTH>>,
    one5: Constant<Bits<5>>,
    one32: Constant<Bits<32>>,
    one_line: Constant<Bits<CACHE_BITS>>,
    one3: Constant<Bits<3>>,
    misses3: Constant<Bits<3>>,
    almost3: Constant<Bits<3>>,
    one2: Constant<Bits<2>>,
    slot0: Constant<Bits<2>>,
    slot1: Constant<Bits<2>>,
    slot2: Constant<Bits<2>>,
    slot3: Constant<Bits<2>>,
    last_line: Constant<Bits<CACHE_BITS>>,
    zero_line: Constant<Bits<CACHE_BITS>>,
    zero17: Constant<Bits<17>>,
}

impl Default for PatchCache {
    fn default() -> Self {
        assert_eq!(1 << QUEUE_BITS, QUEUE_DEPTH);
        assert_eq!(1 << MISS_BITS, MISSES);
        assert_eq!(bram_out_tile_width(CACHE_BITS), 18, "each cache lane is one DP16KD tile wide");
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
            line3: Default::default(),
            match3: Default::default(),
            lconf3: Default::default(),
            iconf3: Default::default(),
            ax3: Default::default(),
            ay3: Default::default(),
            bx3: Default::default(),
            by3: Default::default(),
            t_id0: Default::default(),
            t_id1: Default::default(),
            t_id2: Default::default(),
            t_id3: Default::default(),
            t_line0: Default::default(),
            t_line1: Default::default(),
            t_line2: Default::default(),
            t_line3: Default::default(),
            t_v0: Default::default(),
            t_v1: Default::default(),
            t_v2: Default::default(),
            t_v3: Default::default(),
            t_any: Default::default(),
            t_n: Default::default(),
            t_full: Default::default(),
            t_wp: Default::default(),
            t_rp: Default::default(),
            f_id1: Default::default(),
            f_line1: Default::default(),
            f_v1: Default::default(),
            mi0: Default::default(),
            mi1: Default::default(),
            mi2: Default::default(),
            mi3: Default::default(),
            mif: Default::default(),
            mis3: Default::default(),
            mis2: Default::default(),
            ml0: Default::default(),
            ml1: Default::default(),
            ml2: Default::default(),
            ml3: Default::default(),
            mlf: Default::default(),
            mls3: Default::default(),
            mls2: Default::default(),
            ans: Default::default(),
            ans_ax: Default::default(),
            ans_ay: Default::default(),
            ans_bx: Default::default(),
            ans_by: Default::default(),
            ans_meta: Default::default(),
            ret: Default::default(),
            ret_ax: Default::default(),
            ret_ay: Default::default(),
            ret_bx: Default::default(),
            ret_by: Default::default(),
            fl_on: Default::default(),
            fl_line: Default::default(),
            mreq: Default::default(),
            maddr: Default::default(),
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
            table_full: Default::default(),
            ret_push: Default::default(),
            ret_full: Default::default(),
            waiting_any: Default::default(),
            tv0_next: Default::default(),
            tv1_next: Default::default(),
            tv2_next: Default::default(),
            tv3_next: Default::default(),
            rewind: Default::default(),
            accept: Default::default(),
            tag_hit: Default::default(),
            hit: Default::default(),
            miss: Default::default(),
            line_conflict: Default::default(),
            id_conflict: Default::default(),
            miss3: Default::default(),
            head_id_fill: Default::default(),
            head_miss: Default::default(),
            answer: Default::default(),
            fill: Default::default(),
            meta_in: Default::default(),
            head_key_fill: Default::default(),
            head_line_fill: Default::default(),
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
            read_new: Default::default(),
            head_low: Default::default(),
            head_line: Default::default(),
            head_key: Default::default(),
            hit_inc: Default::default(),
            miss_inc: Default::default(),
            fl_inc: Default::default(),
            t_wp_inc: Default::default(),
            t_rp_inc: Default::default(),
            valid_flag: Constant::new(0x1_0000u64.into()),
            miss_flag: Constant::new((1u64 << (META_WIDTH - 1)).into()),
            one5: Constant::new(1.into()),
            one32: Constant::new(1.into()),
            one_line: Constant::new(1.into()),
            one3: Constant::new(1.into()),
            misses3: Constant::new((MISSES as u64).into()),
            almost3: Constant::new((MISSES as u64 - 1).into()),
            one2: Constant::new(1.into()),
            slot0: Constant::new(0.into()),
            slot1: Constant::new(1.into()),
            slot2: Constant::new(2.into()),
            slot3: Constant::new(3.into()),
            last_line: Constant::new(((LINES - 1) as u64).into()),
            zero_line: Constant::new(0.into()),
            zero17: Constant::new(0.into()),
        }
    }
}
impl PatchCache {
    /// The lookup in S3 is rewound because its own id is a miss not yet in its line (it waits
    /// for that fill): for testbenches ([`crate::pe::Watch::fill_rewind`]).
    pub fn fill_rewind(&self) -> bool {
        self.v3.q.val() & self.iconf3.q.val()
    }

    /// A lookup is accepted in this cycle (a hit or a miss): for testbenches.
    pub fn lookup(&self) -> bool {
        self.accept.val()
    }

    /// Requests taken and not yet answered (in the request queue or the answer queue),
    /// `0..=QUEUE_DEPTH`: for testbenches.
    pub fn queued(&self) -> usize {
        let in_queue =
            (self.wr_ptr.q.val().index().wrapping_sub(self.rd_ptr.q.val().index())) % (2 * QUEUE_DEPTH);
        in_queue + self.ans.count.val().index()
    }

    /// Misses accepted and not yet answered (waiting for the host or for their turn): for
    /// testbenches.
    pub fn waiting(&self) -> usize {
        [&self.t_v0, &self.t_v1, &self.t_v2, &self.t_v3].iter().filter(|v| v.q.val()).count()
    }
}

impl Logic for PatchCache {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, wr_ptr, rd_ptr, sp, rd_inc_x, sp_inc_x, q_valid, v1, id1, key1, line1, v2, id2,
            key2, line2, v3, id3, line3, match3, lconf3, iconf3, ax3, ay3, bx3, by3, t_id0, t_id1, t_id2,
            t_id3, t_line0, t_line1, t_line2, t_line3, t_v0, t_v1, t_v2, t_v3, t_any, t_n, t_full, t_wp,
            t_rp, f_id1, f_line1, f_v1, mi0, mi1, mi2, mi3, mif, mis3, mis2, ml0, ml1, ml2, ml3, mlf, mls3,
            mls2, fl_on, fl_line, mreq, maddr, rv, rax, ray, rbx, rby, hit_count, miss_count, hit_r,
            ret_full
        );
        self.q_lane.clock.next = self.clock.val();
        self.tag.clock.next = self.clock.val();
        self.lane_ax.clock.next = self.clock.val();
        self.lane_ay.clock.next = self.clock.val();
        self.lane_bx.clock.next = self.clock.val();
        self.lane_by.clock.next = self.clock.val();
        self.ans.clock.next = self.clock.val();
        self.ans_ax.clock.next = self.clock.val();
        self.ans_ay.clock.next = self.clock.val();
        self.ans_bx.clock.next = self.clock.val();
        self.ans_by.clock.next = self.clock.val();
        self.ans_meta.clock.next = self.clock.val();
        self.ret.clock.next = self.clock.val();
        self.ret_ax.clock.next = self.clock.val();
        self.ret_ay.clock.next = self.clock.val();
        self.ret_bx.clock.next = self.clock.val();
        self.ret_by.clock.next = self.clock.val();

        // Pointer and counter arithmetic, each at its exact width.
        self.wr_inc.next = self.wr_ptr.q.val() + self.one5.val();
        self.rd_inc.next = self.rd_inc_x.q.val() ^ self.one5.val();
        self.rd_inc2.next = self.rd_inc.val() + self.one5.val();
        self.sp_inc.next = self.sp_inc_x.q.val() ^ self.one5.val();
        self.sp_inc2.next = self.sp_inc.val() + self.one5.val();
        self.hit_inc.next = self.hit_count.q.val() + self.one32.val();
        self.miss_inc.next = self.miss_count.q.val() + self.one32.val();
        self.t_wp_inc.next = self.t_wp.q.val() + self.one2.val();
        self.t_rp_inc.next = self.t_rp.q.val() + self.one2.val();

        // S3: the lookup, from registers only. A request whose own id may be on its way into its
        // line (`iconf3`), or any request while the miss table is full, is not accepted: the
        // lookups are rewound to it (it and the two behind it are void, and it is read again
        // from the queue). Neither condition depends on the tag compare, so the compare reaches
        // no pointer. A request whose line is on its way to another id (`lconf3` only) is a
        // miss whatever the stale tag says.
        self.table_full.next = self.t_full.q.val();
        self.waiting_any.next = self.t_any.q.val();
        self.rewind.next = self.v3.q.val() & (self.iconf3.q.val() | self.table_full.val());
        self.accept.next = self.v3.q.val() & !self.iconf3.q.val() & !self.table_full.val();
        self.tag_hit.next = self.match3.q.val();
        self.miss3.next = self.lconf3.q.val() | !self.tag_hit.val();
        self.hit.next = self.accept.val() & !self.miss3.val();
        self.miss.next = self.accept.val() & self.miss3.val();

        // S2: the lanes' output registers hold the line of S2's id. Void while S3 rewinds.
        self.v3.d.next = self.v2.q.val() & !self.rewind.val();
        self.id3.d.next = self.id2.q.val();
        self.line3.d.next = self.line2.q.val();
        // The tag compare, registered: it can sit next to the tag's tile, and only its bit
        // travels to the pipeline's control.
        self.match3.d.next = self.tag.read_data.val() == self.key2.q.val();
        self.ax3.d.next = self.lane_ax.read_data.val();
        self.ay3.d.next = self.lane_ay.read_data.val();
        self.bx3.d.next = self.lane_bx.read_data.val();
        self.by3.d.next = self.lane_by.read_data.val();
        // The staleness check. A request reads its line in Q, in cycle `c`; a fill of that line
        // in `c` or later, for a miss ahead of it, is not in the words it read. In S1 (`c + 1`)
        // such a miss is in the table (not filled by the last edge), or was filled in `c`
        // (`f_*1`), or is S3's request, a miss (it enters the table at this edge), or S2's
        // request, if that is a miss in S3 next cycle. The compares are made here, each
        // registered, and combined in S2. If one of them is S2's own id, its patch is not in
        // the line yet: the request must wait for it; if only the line matches, the newest of
        // those misses holds the line in the model: the request is a miss.
        self.mi0.d.next = self.t_v0.q.val() & (self.t_id0.q.val() == self.id1.q.val());
        self.mi1.d.next = self.t_v1.q.val() & (self.t_id1.q.val() == self.id1.q.val());
        self.mi2.d.next = self.t_v2.q.val() & (self.t_id2.q.val() == self.id1.q.val());
        self.mi3.d.next = self.t_v3.q.val() & (self.t_id3.q.val() == self.id1.q.val());
        self.mif.d.next = self.f_v1.q.val() & (self.f_id1.q.val() == self.id1.q.val());
        self.mis3.d.next = self.v3.q.val() & self.miss3.val() & (self.id3.q.val() == self.id1.q.val());
        self.mis2.d.next = self.v2.q.val() & (self.id2.q.val() == self.id1.q.val());
        self.ml0.d.next = self.t_v0.q.val() & (self.t_line0.q.val() == self.line1.q.val());
        self.ml1.d.next = self.t_v1.q.val() & (self.t_line1.q.val() == self.line1.q.val());
        self.ml2.d.next = self.t_v2.q.val() & (self.t_line2.q.val() == self.line1.q.val());
        self.ml3.d.next = self.t_v3.q.val() & (self.t_line3.q.val() == self.line1.q.val());
        self.mlf.d.next = self.f_v1.q.val() & (self.f_line1.q.val() == self.line1.q.val());
        self.mls3.d.next = self.v3.q.val() & self.miss3.val() & (self.line3.q.val() == self.line1.q.val());
        self.mls2.d.next = self.v2.q.val() & (self.line2.q.val() == self.line1.q.val());
        // S2: the compares combined (S3's request now was S2's then).
        self.id_conflict.next = self.mi0.q.val()
            | self.mi1.q.val()
            | self.mi2.q.val()
            | self.mi3.q.val()
            | self.mif.q.val()
            | self.mis3.q.val()
            | (self.mis2.q.val() & self.v3.q.val() & self.miss3.val());
        self.line_conflict.next = self.ml0.q.val()
            | self.ml1.q.val()
            | self.ml2.q.val()
            | self.ml3.q.val()
            | self.mlf.q.val()
            | self.mls3.q.val()
            | (self.mls2.q.val() & self.v3.q.val() & self.miss3.val());
        self.lconf3.d.next = self.line_conflict.val();
        self.iconf3.d.next = self.id_conflict.val();

        // Request queue: push at the tail.
        self.push.next = self.cfg_enable.val() & self.req.val();
        self.q_lane.write_address.next = self.wr_ptr.q.val().get_bits::<4>(0);
        self.q_lane.write_data.next = self.addr.val();
        self.q_lane.write_enable.next = self.push.val();
        if self.push.val() {
            self.wr_ptr.d.next = self.wr_inc.val();
        }
        // An accepted request leaves the request queue.
        self.rd_next.next = self.rd_ptr.q.val();
        self.rd_next_inc.next = self.rd_inc.val();
        if self.accept.val() {
            self.rd_next.next = self.rd_inc.val();
            self.rd_next_inc.next = self.rd_inc2.val();
        }
        self.rd_ptr.d.next = self.rd_next.val();
        self.rd_inc_x.d.next = self.rd_next_inc.val() ^ self.one5.val();

        // Q: issue the request at the queue lane's read register into S1, unless S3 rewinds;
        // then read the next one. On a rewind, read the oldest request not accepted (S3's):
        // the lookups start again from it.
        // The read is valid next cycle when its request was written before this edge (read
        // before write): each candidate is compared with wr_ptr beside the choice, so no
        // compare follows the pointer multiplexer.
        self.issue.next = self.q_valid.q.val() & !self.rewind.val();
        self.ne_sp.next = self.sp.q.val() != self.wr_ptr.q.val();
        self.ne_sp_inc.next = self.sp_inc.val() != self.wr_ptr.q.val();
        self.ne_rd.next = self.rd_ptr.q.val() != self.wr_ptr.q.val();
        self.read_ptr.next = self.sp.q.val();
        self.read_inc.next = self.sp_inc.val();
        self.read_new.next = self.ne_sp.val();
        if self.issue.val() {
            self.read_ptr.next = self.sp_inc.val();
            self.read_inc.next = self.sp_inc2.val();
            self.read_new.next = self.ne_sp_inc.val();
        }
        if self.rewind.val() {
            self.read_ptr.next = self.rd_ptr.q.val();
            self.read_inc.next = self.rd_inc.val();
            self.read_new.next = self.ne_rd.val();
        }
        self.sp.d.next = self.read_ptr.val();
        self.sp_inc_x.d.next = self.read_inc.val() ^ self.one5.val();
        self.q_lane.read_address.next = self.read_ptr.val().get_bits::<4>(0);
        self.q_valid.d.next = self.read_new.val();

        // Q: read the request's line in every lane.
        self.head_low.next = bit_cast::<CACHE_BITS, 16>(self.q_lane.read_data.val());
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
        self.v2.d.next = self.v1.q.val() & !self.rewind.val();
        self.id2.d.next = self.id1.q.val();
        self.key2.d.next = self.key1.q.val();
        self.line2.d.next = self.line1.q.val();

        // S3 accepts: into the answer queue, a hit with its words, a miss with its id and line.
        self.meta_in.next = (bit_cast::<META_WIDTH, CACHE_BITS>(self.line3.q.val()) << 16)
            | bit_cast::<META_WIDTH, 16>(self.id3.q.val());
        if self.miss3.val() {
            self.meta_in.next = self.meta_in.val() | self.miss_flag.val();
        }
        self.ans.push.next = self.accept.val();
        self.ans_ax.write_data.next = self.ax3.q.val();
        self.ans_ay.write_data.next = self.ay3.q.val();
        self.ans_bx.write_data.next = self.bx3.q.val();
        self.ans_by.write_data.next = self.by3.q.val();
        self.ans_meta.write_data.next = self.meta_in.val();
        // A miss: request the patch from the host (next cycle) and enter the table. The free
        // entry at `t_wp` takes S3's id and line in every cycle (off the tag compare's path); a
        // miss makes it valid.
        self.mreq.d.next = self.miss.val();
        self.maddr.d.next = self.id3.q.val();
        if self.miss.val() {
            self.t_wp.d.next = self.t_wp_inc.val();
        }
        if !self.t_v0.q.val() & (self.t_wp.q.val() == self.slot0.val()) {
            self.t_id0.d.next = self.id3.q.val();
            self.t_line0.d.next = self.line3.q.val();
        }
        if !self.t_v1.q.val() & (self.t_wp.q.val() == self.slot1.val()) {
            self.t_id1.d.next = self.id3.q.val();
            self.t_line1.d.next = self.line3.q.val();
        }
        if !self.t_v2.q.val() & (self.t_wp.q.val() == self.slot2.val()) {
            self.t_id2.d.next = self.id3.q.val();
            self.t_line2.d.next = self.line3.q.val();
        }
        if !self.t_v3.q.val() & (self.t_wp.q.val() == self.slot3.val()) {
            self.t_id3.d.next = self.id3.q.val();
            self.t_line3.d.next = self.line3.q.val();
        }
        // The host's answers wait in order for their turn (one ignored while no miss waits: a
        // protocol violation).
        self.ret_push.next = self.cfg_enable.val() & self.mem_valid.val() & self.waiting_any.val();
        self.ret.push.next = self.ret_push.val();
        self.ret_ax.write_data.next = self.mem_ax.val();
        self.ret_ay.write_data.next = self.mem_ay.val();
        self.ret_bx.write_data.next = self.mem_bx.val();
        self.ret_by.write_data.next = self.mem_by.val();

        // The answer: the head of the answer queue when it is a hit, or a miss whose patch has
        // come; a miss's patch is written into its line (tag and data) as it is answered.
        // Bit 26 is `META_WIDTH - 1` (a literal: the Verilog has no name for the constant).
        self.head_miss.next = self.ans_meta.read_data.val().get_bit(26);
        self.answer.next = self.ans.valid.val() & (!self.head_miss.val() | self.ret.valid.val());
        self.fill.next = self.answer.val() & self.head_miss.val();
        self.ans.pop.next = self.answer.val();
        self.ret.pop.next = self.fill.val();
        self.rv.d.next = self.answer.val();
        self.rax.d.next = self.ans_ax.read_data.val();
        self.ray.d.next = self.ans_ay.read_data.val();
        self.rbx.d.next = self.ans_bx.read_data.val();
        self.rby.d.next = self.ans_by.read_data.val();
        if self.head_miss.val() {
            self.rax.d.next = self.ret_ax.read_data.val();
            self.ray.d.next = self.ret_ay.read_data.val();
            self.rbx.d.next = self.ret_bx.read_data.val();
            self.rby.d.next = self.ret_by.read_data.val();
        }
        // The table's count: a miss enters, a fill leaves. Full after this edge: full with no
        // fill (no miss enters a full table), or one short with a miss and no fill.
        if self.miss.val() & !self.fill.val() {
            self.t_n.d.next = self.t_n.q.val() + self.one3.val();
        }
        if self.fill.val() & !self.miss.val() {
            self.t_n.d.next = self.t_n.q.val() - self.one3.val();
        }
        self.t_full.d.next = ((self.t_n.q.val() == self.misses3.val()) & !self.fill.val())
            | ((self.t_n.q.val() == self.almost3.val()) & self.miss.val() & !self.fill.val());
        // The fill leaves the table (the oldest miss) and is remembered for two cycles.
        if self.fill.val() {
            self.t_rp.d.next = self.t_rp_inc.val();
        }
        // Entry 0: valid from its miss, invalid from its fill.
        self.tv0_next.next = self.t_v0.q.val();
        if self.miss.val() & (self.t_wp.q.val() == self.slot0.val()) {
            self.tv0_next.next = true;
        }
        if self.fill.val() & (self.t_rp.q.val() == self.slot0.val()) {
            self.tv0_next.next = false;
        }
        self.t_v0.d.next = self.tv0_next.val();
        // Entry 1: valid from its miss, invalid from its fill.
        self.tv1_next.next = self.t_v1.q.val();
        if self.miss.val() & (self.t_wp.q.val() == self.slot1.val()) {
            self.tv1_next.next = true;
        }
        if self.fill.val() & (self.t_rp.q.val() == self.slot1.val()) {
            self.tv1_next.next = false;
        }
        self.t_v1.d.next = self.tv1_next.val();
        // Entry 2: valid from its miss, invalid from its fill.
        self.tv2_next.next = self.t_v2.q.val();
        if self.miss.val() & (self.t_wp.q.val() == self.slot2.val()) {
            self.tv2_next.next = true;
        }
        if self.fill.val() & (self.t_rp.q.val() == self.slot2.val()) {
            self.tv2_next.next = false;
        }
        self.t_v2.d.next = self.tv2_next.val();
        // Entry 3: valid from its miss, invalid from its fill.
        self.tv3_next.next = self.t_v3.q.val();
        if self.miss.val() & (self.t_wp.q.val() == self.slot3.val()) {
            self.tv3_next.next = true;
        }
        if self.fill.val() & (self.t_rp.q.val() == self.slot3.val()) {
            self.tv3_next.next = false;
        }
        self.t_v3.d.next = self.tv3_next.val();
        // Some miss waits after this edge: a register of its own, so that a host answer's
        // push is one gate of `mem_valid` and registers.
        self.t_any.d.next =
            self.tv0_next.val() | self.tv1_next.val() | self.tv2_next.val() | self.tv3_next.val();
        self.head_line_fill.next = self.ans_meta.read_data.val().get_bits::<CACHE_BITS>(16);
        self.head_id_fill.next = self.ans_meta.read_data.val().get_bits::<16>(0);
        self.head_key_fill.next = self.valid_flag.val() | bit_cast::<17, 16>(self.head_id_fill.val());
        self.f_v1.d.next = self.fill.val();
        self.f_id1.d.next = self.head_id_fill.val();
        self.f_line1.d.next = self.head_line_fill.val();

        // The answer and return queues' lanes.
        self.ans_ax.write_address.next = self.ans.tail_address.val();
        self.ans_ay.write_address.next = self.ans.tail_address.val();
        self.ans_bx.write_address.next = self.ans.tail_address.val();
        self.ans_by.write_address.next = self.ans.tail_address.val();
        self.ans_meta.write_address.next = self.ans.tail_address.val();
        self.ans_ax.write_enable.next = self.accept.val();
        self.ans_ay.write_enable.next = self.accept.val();
        self.ans_bx.write_enable.next = self.accept.val();
        self.ans_by.write_enable.next = self.accept.val();
        self.ans_meta.write_enable.next = self.accept.val();
        self.ans_ax.head_address.next = self.ans.head_address.val();
        self.ans_ay.head_address.next = self.ans.head_address.val();
        self.ans_bx.head_address.next = self.ans.head_address.val();
        self.ans_by.head_address.next = self.ans.head_address.val();
        self.ans_meta.head_address.next = self.ans.head_address.val();
        self.ans_ax.next_address.next = self.ans.next_address.val();
        self.ans_ay.next_address.next = self.ans.next_address.val();
        self.ans_bx.next_address.next = self.ans.next_address.val();
        self.ans_by.next_address.next = self.ans.next_address.val();
        self.ans_meta.next_address.next = self.ans.next_address.val();
        self.ans_ax.pop.next = self.answer.val();
        self.ans_ay.pop.next = self.answer.val();
        self.ans_bx.pop.next = self.answer.val();
        self.ans_by.pop.next = self.answer.val();
        self.ans_meta.pop.next = self.answer.val();
        self.ret_ax.write_address.next = self.ret.tail_address.val();
        self.ret_ay.write_address.next = self.ret.tail_address.val();
        self.ret_bx.write_address.next = self.ret.tail_address.val();
        self.ret_by.write_address.next = self.ret.tail_address.val();
        // The return lanes are written at the tail in every clock the queue is not full, an
        // answer pushed or not: the tail's slot holds no answer then (a push writes it again),
        // so their write enables are a register; a slot written without a push is read only
        // as the entry after a head that leaves at the same edge, when no answer is left.
        self.ret_full.d.next = ((self.ret.count.val() == self.misses3.val()) & !self.fill.val())
            | ((self.ret.count.val() == self.almost3.val()) & self.ret_push.val() & !self.fill.val());
        self.ret_ax.write_enable.next = !self.ret_full.q.val();
        self.ret_ay.write_enable.next = !self.ret_full.q.val();
        self.ret_bx.write_enable.next = !self.ret_full.q.val();
        self.ret_by.write_enable.next = !self.ret_full.q.val();
        self.ret_ax.head_address.next = self.ret.head_address.val();
        self.ret_ay.head_address.next = self.ret.head_address.val();
        self.ret_bx.head_address.next = self.ret.head_address.val();
        self.ret_by.head_address.next = self.ret.head_address.val();
        self.ret_ax.next_address.next = self.ret.next_address.val();
        self.ret_ay.next_address.next = self.ret.next_address.val();
        self.ret_bx.next_address.next = self.ret.next_address.val();
        self.ret_by.next_address.next = self.ret.next_address.val();
        self.ret_ax.pop.next = self.fill.val();
        self.ret_ay.pop.next = self.fill.val();
        self.ret_bx.pop.next = self.fill.val();
        self.ret_by.pop.next = self.fill.val();

        // The fill: write the line, tag and data.
        self.tag.write_address.next = self.head_line_fill.val();
        self.lane_ax.write_address.next = self.head_line_fill.val();
        self.lane_ay.write_address.next = self.head_line_fill.val();
        self.lane_bx.write_address.next = self.head_line_fill.val();
        self.lane_by.write_address.next = self.head_line_fill.val();
        self.tag.write_data.next = self.head_key_fill.val();
        self.lane_ax.write_data.next = self.ret_ax.read_data.val();
        self.lane_ay.write_data.next = self.ret_ay.read_data.val();
        self.lane_bx.write_data.next = self.ret_bx.read_data.val();
        self.lane_by.write_data.next = self.ret_by.read_data.val();
        self.tag.write_enable.next = self.fill.val();
        // The flush: clear one tag per cycle, line 0 to the last (no fill can be pending).
        self.fl_inc.next = self.fl_line.q.val() + self.one_line.val();
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
            self.fl_line.d.next = self.zero_line.val();
        }
        self.flushing.next = self.fl_on.q.val();
        self.lane_ax.write_enable.next = self.fill.val();
        self.lane_ay.write_enable.next = self.fill.val();
        self.lane_bx.write_enable.next = self.fill.val();
        self.lane_by.write_enable.next = self.fill.val();

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
            self.mem_addr.next = self.maddr.q.val();
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
        assert_eq!(mask_for(1024), Some(0x3FF));
        assert_eq!(mask_for(1), Some(0));
        assert_eq!(mask_for(2048), None);
        assert_eq!(mask_for(12), None);
    }

    fn stream(reqs: &[(u64, u16, bool)]) -> Vec<Request> {
        reqs.iter().map(|&(cycle, id, hit)| Request { cycle, id, hit }).collect()
    }

    #[test]
    fn schedule_gives_one_hit_per_clock_and_overlaps_misses() {
        let hits: Vec<_> = (0..5).map(|k| (k, k as u16, true)).collect();
        let s = schedule(&stream(&hits), 8);
        assert_eq!(s.iter().map(|t| t.response).collect::<Vec<_>>(), [8, 9, 10, 11, 12]);
        assert_eq!(all_hit_cycles(5), 13);
        // Two misses in flight at once; the hit between them answered right after the first.
        let s = schedule(&stream(&[(0, 1, false), (1, 2, true), (2, 3, false), (30, 4, true)]), 8);
        assert_eq!(s[0], RequestTiming { lookup: 5, host_request: Some(6), response: 17 });
        assert_eq!(s[1], RequestTiming { lookup: 6, host_request: None, response: 18 });
        assert_eq!(s[2], RequestTiming { lookup: 7, host_request: Some(8), response: 25 });
        assert_eq!(s[3], RequestTiming { lookup: 35, host_request: None, response: 38 });
        // Another id of the same line does not wait: a miss (lookup 6), the host's next load.
        let s = schedule(&stream(&[(0, 7, false), (1, 23, false)]), 8);
        assert_eq!(s[1], RequestTiming { lookup: 6, host_request: Some(7), response: 25 });
        // The same id twice: the second waits for the first's fill (in cycle 16): it is
        // rewound in 6, 10, 14 (the miss in the table) and 18 (its read in 15 came before the
        // fill), and accepted in 22.
        let s = schedule(&stream(&[(0, 7, false), (1, 7, true)]), 8);
        assert_eq!(s[0], RequestTiming { lookup: 5, host_request: Some(6), response: 17 });
        assert_eq!(s[1], RequestTiming { lookup: 22, host_request: None, response: 25 });
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
        let reqs: Vec<_> = ids.iter().enumerate().map(|(k, &id)| (k as u64, id, cache.access(id))).collect();
        let expect = schedule(&stream(&reqs), tc);
        // The host: in order, one at a time, `tc` cycles each.
        let mut host: std::collections::VecDeque<(u64, u16)> = Default::default();
        let mut last = 0u64;
        let mut got = vec![];
        for cycle in 0..60u64 {
            let answer = host.front().filter(|r| r.0 == cycle).map(|r| r.1);
            if answer.is_some() {
                host.pop_front();
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
                last = last.max(cycle) + tc;
                host.push_back((last, u.mem_addr.val().to_u16()));
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
