//! Block-level tests of the patch cache (`shelling_hdl::cache`), rung 3 of the equivalence
//! ladder: a loader-like client (at most 16 requests outstanding, random idle gaps, random
//! backpressure on its own output) against the host memory model (`HostMemory`) with
//! T_c ∈ {1, 3, 8}, caches of 1, 16, 256 and 1024 lines ([`LINES`]) and the cache disabled, id streams with
//! and without locality. Every response's data and order are checked against the memory, and
//! the hit/miss sequence, the host requests and every response's cycle against the model
//! (`model::Cache`, `model::schedule`). Then: hits one per clock, isolated misses, corner cases
//! (ids 0 and 0xFFFF, conflicting ids, mask changes and disabled runs over the same contents),
//! the return queue full (a pipelined host whose answers to four misses wait behind hits; and
//! random streams against a bursty host), the real patch loader through the cache, and the
//! rung-4 replays of recorded runs under Icarus Verilog.
//!
//! `cargo test --release -p shelling-testbench --test cache`

use std::collections::VecDeque;
use std::path::PathBuf;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rust_hdl::prelude::*;
use shelling_hdl::cache::model::{self, mask_for, Cache};
use shelling_hdl::cache::{PatchCache, CACHE_BITS, LINES, MISSES, QUEUE_DEPTH};
use shelling_hdl::loader::{self, PatchLoader};
use shelling_testbench::memory::answer_cycles;
use shelling_testbench::{Driver, Error, HostMemory, Monitor, Pacing, Result, Scoreboard, Simulator, Source};

/// The most requests the client keeps outstanding (the loader's FIFO depth).
const OUTSTANDING: usize = loader::DEPTH;

fn b<const N: usize>(v: u64) -> Bits<N> {
    Bits::from(v)
}

/// One random patch per id (all 2^16 unless `n` says fewer), 17-bit coordinates.
fn random_patches(seed: u64, n: usize) -> Vec<[i32; 4]> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x6d65_6d6f_7279);
    (0..n).map(|_| [0; 4].map(|_: i32| rng.random_range(0..1 << 17))).collect()
}

/// The cache's configuration for one run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Config {
    Disabled,
    /// Enabled with this many lines.
    Lines(usize),
}

impl Config {
    fn enable(self) -> bool {
        self != Config::Disabled
    }

    fn mask(self) -> u16 {
        match self {
            Config::Disabled => LINES as u16 - 1,
            Config::Lines(n) => mask_for(n).expect("a power of two up to LINES"),
        }
    }
}

impl std::fmt::Display for Config {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Config::Disabled => f.write_str("cache disabled"),
            Config::Lines(n) => write!(f, "{n} lines"),
        }
    }
}

/// What one run observed (cycles are absolute driver cycles).
#[derive(Debug, Default)]
struct Outcome {
    /// The cycle of each request.
    arrivals: Vec<u64>,
    /// The cycle of each response.
    responses: Vec<u64>,
    /// The cycle of each host request.
    host_requests: Vec<u64>,
    /// The cycle of each host answer (`mem_valid`).
    host_answers: Vec<u64>,
    /// The RTL's lookups in order: `true` for a hit (from the counters).
    lookups: Vec<bool>,
    /// The model's hit/miss sequence.
    model_hits: Vec<bool>,
    max_outstanding: usize,
    max_queued: usize,
    /// The most host answers held in the return queue at once (enabled only): the host's
    /// answers presented before a cycle less the misses answered (`resp_valid`) up to it.
    max_returned: usize,
    /// Cycles with [`MISSES`] answers held (the return queue full), and the longest run of them.
    full_cycles: u64,
    full_streak: u64,
    /// Rising edges from the first cycle of the run to the last response, inclusive.
    cycles: u64,
}

/// When the host answers its requests (always in order, exactly once each).
#[derive(Clone, Debug, PartialEq, Eq)]
enum HostTiming {
    /// [`HostMemory`]: one load at a time, `T_c` cycles each.
    Serial,
    /// Any number of loads at once, each with its own latency: a run's host request `k`, made
    /// in cycle `r`, is answered in cycle `max(r + latencies[k % len], e + 1)`, `e` the cycle
    /// of the answer before it (so at most one answer a clock, and the answers behind a slow
    /// one come back to back). While `mem_valid` is low, `mem_*` carry random words.
    Pipelined(Vec<u64>),
}

impl HostTiming {
    /// The cycle of the answer to a run's host request `k`, made in cycle `r`, the answer
    /// before it in cycle `e`.
    fn answer(&self, tc: u64, k: usize, r: u64, e: u64) -> u64 {
        match self {
            HostTiming::Serial => r.max(e) + tc,
            HostTiming::Pipelined(lat) => (r + lat[k % lat.len()]).max(e + 1),
        }
    }

    /// The longest a request waits for its answer, not counting the ones before it.
    fn latency(&self, tc: u64) -> u64 {
        match self {
            HostTiming::Serial => tc,
            HostTiming::Pipelined(lat) => lat.iter().copied().max().unwrap_or(1),
        }
    }
}

impl std::fmt::Display for HostTiming {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            HostTiming::Serial => f.write_str("serial host"),
            HostTiming::Pipelined(lat) => write!(f, "pipelined host, latencies {lat:?}"),
        }
    }
}

/// The cache under test, its host memory, and the model state, kept across runs.
struct Bench {
    drv: Driver<PatchCache>,
    mem: HostMemory,
    /// The host's timing; with [`HostTiming::Pipelined`], `mem` serves only the data.
    timing: HostTiming,
    /// The pipelined host: requests not answered yet (data, answer cycle), oldest first; the
    /// run's host requests so far; the cycle of the last answer; the words on `mem_*` while
    /// `mem_valid` is low.
    pending: VecDeque<([i32; 4], u64)>,
    seen: usize,
    last_answer: u64,
    noise: ChaCha8Rng,
    /// The host's response to present in the coming cycle.
    presented: Option<[i32; 4]>,
    model: Cache,
    /// The model's counters (wrapping, like the RTL's).
    hits: u32,
    misses: u32,
}

impl Bench {
    /// A fresh block (power-up) with a memory of `patches` answering in `tc` cycles.
    fn new(patches: Vec<[i32; 4]>, tc: u32) -> Result<Self> {
        Self::with_driver(new_driver()?, patches, tc)
    }

    fn with_driver(drv: Driver<PatchCache>, patches: Vec<[i32; 4]>, tc: u32) -> Result<Self> {
        Ok(Self {
            drv,
            mem: HostMemory::new(patches, tc)?,
            timing: HostTiming::Serial,
            pending: VecDeque::new(),
            seen: 0,
            last_answer: 0,
            noise: ChaCha8Rng::seed_from_u64(0),
            presented: None,
            model: Cache::new(0),
            hits: 0,
            misses: 0,
        })
    }

    /// A fresh block with a memory of `patches` answering as `timing` ([`HostTiming::Pipelined`]:
    /// its idle words on `mem_*` drawn from `seed`).
    fn with_host(patches: Vec<[i32; 4]>, timing: HostTiming, seed: u64) -> Result<Self> {
        Self::with_host_and_driver(new_driver()?, patches, timing, seed)
    }

    fn with_host_and_driver(
        drv: Driver<PatchCache>,
        patches: Vec<[i32; 4]>,
        timing: HostTiming,
        seed: u64,
    ) -> Result<Self> {
        let mut bench = Self::with_driver(drv, patches, 1)?;
        bench.noise = ChaCha8Rng::seed_from_u64(seed ^ 0x0ff_11fe);
        bench.set_host(timing);
        Ok(bench)
    }

    /// The host's timing from the next run on (between runs: no request outstanding).
    fn set_host(&mut self, timing: HostTiming) {
        assert!(self.pending.is_empty() && self.mem.pending() == 0, "the host is busy");
        self.timing = timing;
    }

    /// The host in one cycle (see [`HostMemory::cycle`]): `request` seen in `cycle`; returns
    /// the answer to present in the next cycle.
    fn host_cycle(&mut self, cycle: u64, request: Option<u16>) -> Result<Option<[i32; 4]>> {
        if self.timing == HostTiming::Serial {
            return self.mem.cycle(request);
        }
        if let Some(id) = request {
            let data = self.mem.patch(id).ok_or_else(|| format!("host: id {id} beyond memory"))?;
            let e = self.timing.answer(1, self.seen, cycle, self.last_answer);
            self.seen += 1;
            self.last_answer = e;
            self.pending.push_back((data, e));
        }
        if self.pending.front().is_some_and(|&(_, e)| e == cycle + 1) {
            return Ok(self.pending.pop_front().map(|(data, _)| data));
        }
        Ok(None)
    }

    /// The words on `mem_*` while `mem_valid` is low: zeros from the serial host, random words
    /// from the pipelined one.
    fn idle_words(&mut self) -> [i32; 4] {
        match self.timing {
            HostTiming::Serial => [0; 4],
            HostTiming::Pipelined(_) => [0; 4].map(|_: i32| self.noise.random_range(0..1 << 17)),
        }
    }

    /// Streams `ids` through the cache configured as `cfg` from a loader-like client: it offers
    /// a request per cycle unless idle (`pacing.idle`) or `limit` requests are outstanding; a
    /// response is held in the client until drained (`pacing.backpressure`: random stalls), and
    /// only a drained one frees its slot. Checks every cycle: the queue never exceeds its
    /// depth, host requests are the model's (misses, or every id when disabled) in order,
    /// responses carry the memory's data in request order; at the end: the hit/miss sequence,
    /// the exact response and host-request cycles, the counters, and that nothing more comes.
    fn run(&mut self, cfg: Config, ids: &[u16], pacing: Pacing, seed: u64, limit: usize) -> Result<Outcome> {
        let tc = u64::from(self.mem.tc());
        let context = match self.timing {
            HostTiming::Serial => format!("seed {seed:#x}, {cfg}, {pacing}, tc = {tc}"),
            ref host => format!("seed {seed:#x}, {cfg}, {pacing}, {host}"),
        };
        self.run_inner(cfg, ids, pacing, seed, limit).map_err(|e| e.context(context))
    }

    fn run_inner(
        &mut self,
        cfg: Config,
        ids: &[u16],
        pacing: Pacing,
        seed: u64,
        limit: usize,
    ) -> Result<Outcome> {
        assert!(limit <= OUTSTANDING);
        let tc = u64::from(self.mem.tc());
        let latency = self.timing.latency(tc);
        self.seen = 0;
        let mut out = Outcome::default();
        let expected_host: Vec<u16> = if cfg.enable() {
            self.model.set_mask(cfg.mask());
            out.model_hits = self.model.run(ids);
            for &h in &out.model_hits {
                if h {
                    self.hits = self.hits.wrapping_add(1);
                } else {
                    self.misses = self.misses.wrapping_add(1);
                }
            }
            ids.iter().zip(&out.model_hits).filter(|(_, &h)| !h).map(|(&id, _)| id).collect()
        } else {
            ids.to_vec()
        };
        let data: Vec<[i32; 4]> = ids
            .iter()
            .map(|&id| self.mem.patch(id).ok_or_else(|| format!("id {id} beyond memory")))
            .collect::<std::result::Result<_, _>>()?;
        let mut board = Scoreboard::new("cache responses", seed, data);
        let mut host_board = Scoreboard::new("host requests", seed, expected_host);
        let mut src = Source::new(ids.iter().copied(), pacing, seed);
        let mut mon = Monitor::new(pacing, seed);
        let mut held: VecDeque<()> = VecDeque::new();
        let mut outstanding = 0usize;
        let (enable, mask) = (cfg.enable(), cfg.mask());
        let start = self.drv.cycles();
        let limit_cycles = start + (latency + 8) * ids.len() as u64 + 1000;
        let (mut hits, mut misses) = self.counters();
        // Host answers presented before this cycle, and misses answered: the return queue holds
        // the difference (enabled).
        let (mut returned, mut filled, mut streak) = (0usize, 0usize, 0u64);
        while out.responses.len() < ids.len() {
            let cycle = self.drv.cycles();
            let answer = self.presented.take();
            let idle = self.idle_words();
            let offer = src.present(outstanding < limit).copied();
            mon.ready();
            self.drv.drive(|u| {
                u.cfg_enable.next = enable;
                u.cfg_mask.next = b(mask.into());
                u.req.next = offer.is_some();
                u.addr.next = b(offer.unwrap_or(0).into());
                u.mem_valid.next = answer.is_some();
                let d = answer.unwrap_or(idle).map(|c| c as u64);
                u.mem_ax.next = b(d[0]);
                u.mem_ay.next = b(d[1]);
                u.mem_bx.next = b(d[2]);
                u.mem_by.next = b(d[3]);
            })?;
            if answer.is_some() {
                out.host_answers.push(cycle);
            }
            let u = self.drv.uut();
            // The client: drain one held response (received in an earlier cycle), then issue.
            if mon.observe(cycle, !held.is_empty(), || ()) {
                held.pop_front();
                outstanding -= 1;
            }
            src.accepted(offer.is_some())?;
            if offer.is_some() {
                out.arrivals.push(cycle);
                outstanding += 1;
            }
            out.max_outstanding = out.max_outstanding.max(outstanding);
            out.max_queued = out.max_queued.max(u.queued());
            if u.queued() > QUEUE_DEPTH {
                return Err(Error::new(format!("cycle {cycle}: {} requests queued", u.queued())));
            }
            // The host.
            let request = u.mem_req.val().then(|| u.mem_addr.val().to_u16());
            if let Some(id) = request {
                host_board.check(cycle, id)?;
                out.host_requests.push(cycle);
            }
            // The response.
            if u.resp_valid.val() {
                if enable && !out.model_hits.get(out.responses.len()).copied().unwrap_or(true) {
                    filled += 1;
                }
                let d = [u.resp_ax.val(), u.resp_ay.val(), u.resp_bx.val(), u.resp_by.val()]
                    .map(|c| c.to_u32() as i32);
                if out.responses.len() == out.arrivals.len() {
                    return Err(Error::new(format!("cycle {cycle}: a response without a request")));
                }
                board.check(cycle, d)?;
                out.responses.push(cycle);
                held.push_back(());
            }
            // The return queue: a host answer enters at the edge of its cycle, a miss leaves at
            // the edge before its response. Full: every miss of the table has its answer.
            if enable {
                let held = returned.checked_sub(filled).ok_or_else(|| {
                    Error::new(format!("cycle {cycle}: {filled} misses answered, {returned} host answers"))
                })?;
                out.max_returned = out.max_returned.max(held);
                if held > MISSES || (held == MISSES && self.drv.uut().waiting() != MISSES) {
                    return Err(Error::new(format!(
                        "cycle {cycle}: {held} host answers held, {} misses waiting",
                        self.drv.uut().waiting()
                    )));
                }
                streak = if held == MISSES { streak + 1 } else { 0 };
                out.full_cycles += u64::from(held == MISSES);
                out.full_streak = out.full_streak.max(streak);
                returned += usize::from(answer.is_some());
            }
            self.presented = self.host_cycle(cycle, request)?;
            self.drv.tick()?;
            let (h, m) = self.counters();
            match (h.wrapping_sub(hits), m.wrapping_sub(misses)) {
                (0, 0) => {}
                (1, 0) => out.lookups.push(true),
                (0, 1) => out.lookups.push(false),
                d => return Err(Error::new(format!("cycle {cycle}: counters moved by {d:?}"))),
            }
            (hits, misses) = (h, m);
            if self.drv.cycles() > limit_cycles {
                return Err(Error::new(format!(
                    "no progress: {} of {} responses after {} cycles",
                    out.responses.len(),
                    ids.len(),
                    self.drv.cycles() - start
                )));
            }
        }
        board.finish()?;
        out.cycles = self.drv.cycles() - start;
        // Nothing more: no response, no host request, no lookup; the host is idle.
        for _ in 0..latency + 8 {
            let cycle = self.drv.cycles();
            let answer = self.presented.take();
            self.drv.drive(|u| {
                u.req.next = false;
                u.mem_valid.next = answer.is_some();
            })?;
            let u = self.drv.uut();
            if answer.is_some()
                || u.resp_valid.val()
                || u.mem_req.val()
                || u.queued() != 0
                || u.waiting() != 0
            {
                return Err(Error::new(format!("cycle {cycle}: activity after the last response")));
            }
            self.presented = self.host_cycle(cycle, None)?;
            self.drv.tick()?;
        }
        host_board.finish()?;
        if self.counters() != (self.hits, self.misses) || self.counters() != (hits, misses) {
            return Err(Error::new(format!(
                "counters (hits, misses) = {:?}, model {:?}",
                self.counters(),
                (self.hits, self.misses)
            )));
        }
        // The model's hit/miss sequence and exact cycles.
        if cfg.enable() {
            if out.lookups != out.model_hits {
                let k = out.lookups.iter().zip(&out.model_hits).position(|(a, b)| a != b).unwrap_or(0);
                return Err(Error::new(format!(
                    "hit/miss sequence differs from the model at request #{k} (id {}): rtl {:?}, model {:?} \
                     ({} lookups, {} requests)",
                    ids[k],
                    out.lookups.get(k),
                    out.model_hits.get(k),
                    out.lookups.len(),
                    ids.len()
                )));
            }
            let reqs: Vec<model::Request> = out
                .arrivals
                .iter()
                .zip(ids)
                .zip(&out.model_hits)
                .map(|((&cycle, &id), &hit)| model::Request { cycle, id, hit })
                .collect();
            let mut k = 0;
            let timing = model::schedule_with_host(&reqs, |r, e| {
                k += 1;
                self.timing.answer(tc, k - 1, r, e)
            });
            let responses: Vec<u64> = timing.iter().map(|t| t.response).collect();
            let host: Vec<u64> = timing.iter().filter_map(|t| t.host_request).collect();
            check_cycles("response", &out.responses, &responses)?;
            check_cycles("host request", &out.host_requests, &host)?;
        } else {
            if !out.lookups.is_empty() {
                return Err(Error::new("the counters moved while the cache was disabled"));
            }
            check_cycles("host request", &out.host_requests, &out.arrivals)?;
            let mut e = 0;
            let answers: Vec<u64> = out
                .arrivals
                .iter()
                .enumerate()
                .map(|(k, &r)| {
                    e = self.timing.answer(tc, k, r, e);
                    e
                })
                .collect();
            check_cycles("response", &out.responses, &answers)?;
        }
        Ok(out)
    }

    fn counters(&self) -> (u32, u32) {
        let u = self.drv.uut();
        (u.hits.val().to_u32(), u.misses.val().to_u32())
    }
}

/// Compares observed cycles with the model's, naming the first difference.
fn check_cycles(what: &str, got: &[u64], want: &[u64]) -> Result<()> {
    if got == want {
        return Ok(());
    }
    let k = got.iter().zip(want).position(|(a, b)| a != b).unwrap_or(got.len().min(want.len()));
    Err(Error::new(format!(
        "{what} cycles differ from the model at #{k}: rtl {:?}, model {:?} ({} vs {} in all)",
        got.get(k),
        want.get(k),
        got.len(),
        want.len()
    )))
}

fn new_driver() -> Result<Driver<PatchCache>> {
    Driver::with_clock(PatchCache::default(), |u| &mut u.clock)
}

/// Uniformly random ids below `n` (hardly any repeat).
fn uniform_ids(len: usize, seed: u64, n: usize) -> Vec<u16> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..len).map(|_| rng.random_range(0..n) as u16).collect()
}

/// Ids with locality: repeats of recent ids, a working set of 3000 ids, runs of one id, and
/// some uniformly random ids.
fn local_ids(len: usize, seed: u64) -> Vec<u16> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x10ca_1175);
    let pool: Vec<u16> = (0..3000).map(|_| rng.random()).collect();
    let mut ids: Vec<u16> = Vec::with_capacity(len);
    while ids.len() < len {
        let r: f64 = rng.random();
        let id = if r < 0.4 && !ids.is_empty() {
            let back = rng.random_range(1..=ids.len().min(8));
            ids[ids.len() - back]
        } else if r < 0.85 {
            pool[rng.random_range(0..pool.len())]
        } else {
            rng.random()
        };
        let run = if rng.random_bool(0.1) { rng.random_range(2..6) } else { 1 };
        for _ in 0..run {
            ids.push(id);
        }
    }
    ids.truncate(len);
    ids
}

/// 3 latencies × 5 configurations × 2 kinds of stream × 4 pacings × 850 requests: 102 000
/// requests. The eight runs of one latency and configuration share one block, one memory and
/// one model, so each run starts from the contents the previous one left.
#[test]
fn every_response_in_order_with_the_models_hits_and_cycles() -> Result<()> {
    let configs =
        [Config::Disabled, Config::Lines(1), Config::Lines(16), Config::Lines(256), Config::Lines(LINES)];
    let mut total = 0usize;
    let mut filled = false;
    for tc in [1u32, 3, 8] {
        for (c, cfg) in configs.into_iter().enumerate() {
            let seed0 = 0xcac4_0000 + 0x100 * u64::from(tc) + 0x10 * c as u64;
            let mut bench = Bench::new(random_patches(seed0, 1 << 16), tc)?;
            for local in [false, true] {
                for (k, pacing) in Pacing::ALL.into_iter().enumerate() {
                    let seed = seed0 + 4 * u64::from(local) + k as u64;
                    let ids = if local { local_ids(850, seed) } else { uniform_ids(850, seed, 1 << 16) };
                    let out = bench.run(cfg, &ids, pacing, seed, OUTSTANDING)?;
                    total += ids.len();
                    let hits = out.model_hits.iter().filter(|&&h| h).count();
                    println!(
                        "tc = {tc}, {cfg}, {}, {pacing}: {} cycles, {hits} hits, max {} outstanding, \
                         max {} queued",
                        if local { "locality" } else { "uniform" },
                        out.cycles,
                        out.max_outstanding,
                        out.max_queued
                    );
                    filled |= out.max_outstanding == OUTSTANDING;
                    if local && cfg == Config::Lines(LINES) {
                        assert!(hits * 2 > ids.len(), "seed {seed:#x}: a local stream should mostly hit");
                    }
                }
            }
        }
    }
    assert!(total >= 100_000);
    assert!(filled, "no run reached the client's limit of outstanding requests");
    Ok(())
}

/// A warm cache answers a back-to-back stream of hits one per clock, each `HIT_LATENCY`
/// cycles after its request: `n + HIT_LATENCY` cycles for `n` hits.
#[test]
fn a_stream_of_hits_is_answered_one_per_clock() -> Result<()> {
    for (tc, lines) in [(8u32, LINES), (3, 256), (1, 16)] {
        let seed = 0xcac4_4175 + u64::from(tc);
        let mut bench = Bench::new(random_patches(seed, 1 << 16), tc)?;
        let cfg = Config::Lines(lines);
        let warm: Vec<u16> =
            (0..lines.min(300) as u16).map(|i| i.wrapping_mul(40503) & (lines as u16 - 1) | 0x4000).collect();
        bench.run(cfg, &warm, Pacing::NONE, seed, OUTSTANDING)?;
        let mut ids = warm.clone();
        ids.extend(warm.iter().rev());
        let out = bench.run(cfg, &ids, Pacing::NONE, seed, OUTSTANDING)?;
        assert!(out.model_hits.iter().all(|&h| h), "{cfg}: all hits");
        let first = out.arrivals[0];
        for k in 0..ids.len() {
            assert_eq!(out.arrivals[k], first + k as u64, "{cfg}: request #{k} back to back");
            assert_eq!(out.responses[k], first + k as u64 + model::HIT_LATENCY, "{cfg}: response #{k}");
        }
        assert_eq!(out.cycles, model::all_hit_cycles(ids.len() as u64), "{cfg}");
        assert!(out.host_requests.is_empty());
    }
    Ok(())
}

/// Misses under misses: a back-to-back stream of misses to distinct lines, with hits between
/// them, keeps the host busy: the host requests go out one per lookup, the host answers one
/// every `T_c` cycles, and the run takes the host's time plus the pipeline's, not a miss's full
/// latency per miss; every hit behind a miss is answered in the cycle after the one before it.
#[test]
fn misses_under_misses_keep_the_host_busy() -> Result<()> {
    for tc in [4u32, 16, 64] {
        let seed = 0xcac4_3333 + u64::from(tc);
        let mut bench = Bench::new(random_patches(seed, 1 << 16), tc)?;
        let cfg = Config::Lines(LINES);
        // Warm lines 0..8; then 8 rounds of a miss to a new line and a hit.
        let warm: Vec<u16> = (0..8).collect();
        bench.run(cfg, &warm, Pacing::NONE, seed, OUTSTANDING)?;
        let ids: Vec<u16> = (0..8u16).flat_map(|k| [100 + k, k]).collect();
        let out = bench.run(cfg, &ids, Pacing::NONE, seed, OUTSTANDING)?;
        let misses = out.model_hits.iter().filter(|&&h| !h).count() as u64;
        assert_eq!(misses, 8);
        let tc = u64::from(tc);
        let bound = misses * tc + model::MISS_OVERHEAD + model::LOOKUP_DELAY + 4;
        assert!(
            out.cycles <= bound,
            "tc = {tc}: {} cycles for {misses} misses, more than the host's {} and the pipeline's",
            out.cycles,
            misses * tc
        );
        // More than one host request outstanding at once.
        let answers = answer_cycles(&out.host_requests, tc);
        assert!(
            out.host_requests.iter().skip(1).zip(&answers).any(|(r, e)| r < e),
            "tc = {tc}: one at a time"
        );
    }
    Ok(())
}

/// The host's latencies for the rounds of [`full_return_queue_rounds`], one per host request
/// of a round (`z`, `a`, `b`, `c`, `d`): `z` late, the others in different patterns of
/// `mem_valid` behind it (back to back, with gaps, `d` sooner or later).
const FULL_QUEUE_ROUNDS: [[u64; 5]; 5] =
    [[20, 1, 1, 1, 1], [20, 1, 12, 1, 3], [20, 11, 1, 12, 2], [20, 10, 11, 12, 1], [30, 1, 1, 1, 2]];

/// The return queue full (see [`four_host_answers_wait_in_a_full_return_queue_behind_hits`]):
/// warms lines 0 … 10 with ids 0 … 10, then one run per entry of `rounds` (the pipelined
/// host's latencies): a new miss `z`, the eleven hits, four new misses `a`, `b`, `c`, `d`, back
/// to back (sixteen requests, the client's limit). Checks that all four answers were held for
/// at least four clocks in a row; returns the outcomes.
fn full_return_queue_rounds(bench: &mut Bench, seed: u64, rounds: &[[u64; 5]]) -> Result<Vec<Outcome>> {
    let cfg = Config::Lines(LINES);
    let hits: Vec<u16> = (0..11).collect();
    bench.set_host(HostTiming::Pipelined(vec![1]));
    bench.run(cfg, &hits, Pacing::NONE, seed, OUTSTANDING)?;
    let mut outs = vec![];
    for (round, lat) in rounds.iter().enumerate() {
        // New ids on lines 256 + 8 · round + 0 … 4, away from the hits' lines.
        let new = |j: usize| 0x4100 + (8 * round + j) as u16;
        let ids: Vec<u16> = [new(0)].into_iter().chain(hits.iter().copied()).chain((1..5).map(new)).collect();
        assert_eq!(ids.len(), OUTSTANDING);
        bench.set_host(HostTiming::Pipelined(lat.to_vec()));
        let out = bench.run(cfg, &ids, Pacing::NONE, seed + 1 + round as u64, OUTSTANDING)?;
        println!(
            "latencies {lat:?}: host requests in {:?}, answers in {:?}, responses in {:?}, return queue \
             full {} cycles ({} in a row)",
            out.host_requests, out.host_answers, out.responses, out.full_cycles, out.full_streak
        );
        let mut hit_miss = vec![false];
        hit_miss.extend([true; 11]);
        hit_miss.extend([false; 4]);
        assert_eq!(out.model_hits, hit_miss, "latencies {lat:?}");
        assert_eq!(out.max_returned, MISSES, "latencies {lat:?}: the return queue was never full");
        assert!(
            out.full_streak >= 4,
            "latencies {lat:?}: the return queue full for {} clocks",
            out.full_streak
        );
        outs.push(out);
    }
    Ok(outs)
}

/// The return queue full, and every answer right. The cache has no `ready` on its response
/// side: the return queue (the host's answers, [`MISSES`] entries) is drained only by the
/// answer stage, which answers the answer queue in request order, one entry a clock, taking a
/// miss's patch from the return queue's head when that miss is the answer queue's head. So the
/// queue holds answers while the answer stage works through older entries: here eleven hits
/// behind a slow miss `z`, then misses `a`, `b`, `c` (the miss table full with `z`) and `d`
/// (rewound until `z`'s fill). The pipelined host answers `z` late, `a`, `b` and `c` right
/// behind it in five patterns of `mem_valid`, and `d` once it is requested after `z`'s fill:
/// the four answers are all held (the queue full: `waiting()` = [`MISSES`] too) for four
/// clocks or more while the hits are answered, with `mem_valid` low and random words on
/// `mem_*`; then released, `a` … `d` answered back to back. Every response's data in order
/// (the memory's patch of its id) and cycle (`model::schedule_with_host`), the host requests
/// and the hit/miss sequence are checked. The return lanes written in every clock, the queue
/// full or not, overwrite the head's answer with the idle words: this test fails then.
#[test]
fn four_host_answers_wait_in_a_full_return_queue_behind_hits() -> Result<()> {
    let seed = 0xcac4_f011;
    let mut bench = Bench::with_host(random_patches(seed, 1 << 16), HostTiming::Pipelined(vec![1]), seed)?;
    let outs = full_return_queue_rounds(&mut bench, seed, &FULL_QUEUE_ROUNDS)?;
    // The host's answers in different patterns: the cycles of `a`, `b`, `c`, `d` after `z`'s.
    let mut patterns: Vec<Vec<u64>> = outs
        .iter()
        .map(|out| out.host_answers[1..].iter().map(|e| e - out.host_answers[0]).collect())
        .collect();
    println!("answers of a, b, c, d after z's: {patterns:?}");
    patterns.sort();
    patterns.dedup();
    assert_eq!(patterns.len(), FULL_QUEUE_ROUNDS.len(), "the rounds' host patterns differ");
    Ok(())
}

/// Ids in clusters that can fill the return queue: a cold id (a random id `≡ 12 mod 16`,
/// hardly ever cached, never on a hot id's line), a run of 4 … 12 hot ids (0 … 11, on lines
/// 0 … 11 of any cache of 16 lines or more), then 2 … 5 cold ids; between the clusters, hot and
/// cold ids at random.
fn clustered_ids(len: usize, seed: u64) -> Vec<u16> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0xc105_7e75);
    let cold = |rng: &mut ChaCha8Rng| rng.random_range(0x0100..=0xFFFF_u16) & !0xF | 0xC;
    let mut ids = vec![];
    while ids.len() < len {
        if rng.random_bool(0.6) {
            ids.push(cold(&mut rng));
            for _ in 0..rng.random_range(4..=12) {
                ids.push(rng.random_range(0..12));
            }
            for _ in 0..rng.random_range(2..=5) {
                ids.push(cold(&mut rng));
            }
        } else {
            for _ in 0..rng.random_range(1..8) {
                ids.push(if rng.random_bool(0.7) { rng.random_range(0..12) } else { cold(&mut rng) });
            }
        }
    }
    ids.truncate(len);
    ids
}

/// Random streams against a pipelined host whose latencies are mostly short and now and then
/// long, so that the answers behind a slow one come in bursts: clustered ids
/// ([`clustered_ids`], which fill the return queue now and then) and ids with locality, 850
/// requests each, four configurations, four pacings. Every response's data, order and cycle,
/// the hit/miss sequence and the host requests against the memory and the model
/// (`model::schedule_with_host`); the return queue full in some cycles of every clustered run
/// of the enabled cache.
#[test]
fn a_bursty_host_fills_the_return_queue_in_random_streams() -> Result<()> {
    let configs = [Config::Disabled, Config::Lines(16), Config::Lines(256), Config::Lines(LINES)];
    let (mut full, mut max_streak) = (0u64, 0u64);
    for (c, cfg) in configs.into_iter().enumerate() {
        let seed0 = 0xcac4_b000 + 0x10 * c as u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed0);
        let lat: Vec<u64> = (0..61)
            .map(|_| if rng.random_bool(0.3) { rng.random_range(12..40) } else { rng.random_range(1..4) })
            .collect();
        let mut bench = Bench::with_host(random_patches(seed0, 1 << 16), HostTiming::Pipelined(lat), seed0)?;
        for clustered in [true, false] {
            for (k, pacing) in Pacing::ALL.into_iter().enumerate() {
                let seed = seed0 + 4 * u64::from(clustered) + k as u64;
                let ids = if clustered { clustered_ids(850, seed) } else { local_ids(850, seed) };
                let out = bench.run(cfg, &ids, pacing, seed, OUTSTANDING)?;
                println!(
                    "{cfg}, {}, {pacing}: {} cycles, {} hits, return queue at most {}, full {} cycles \
                     ({} in a row)",
                    if clustered { "clustered" } else { "locality" },
                    out.cycles,
                    out.model_hits.iter().filter(|&&h| h).count(),
                    out.max_returned,
                    out.full_cycles,
                    out.full_streak
                );
                if clustered && cfg.enable() {
                    assert!(
                        out.full_cycles > 0,
                        "seed {seed:#x}, {cfg}, {pacing}: the return queue never full"
                    );
                }
                full += out.full_cycles;
                max_streak = max_streak.max(out.full_streak);
            }
        }
    }
    assert!(
        full >= 100 && max_streak >= 5,
        "the return queue full {full} cycles, at most {max_streak} in a row"
    );
    Ok(())
}

/// Isolated requests (the block idle each time): a miss is answered `T_c + MISS_OVERHEAD`
/// cycles after its request, its host request `HOST_REQUEST_DELAY` cycles after it; a hit
/// `HIT_LATENCY` cycles after it. With the cache disabled a request is answered in `T_c`.
#[test]
fn isolated_requests_take_the_stated_latencies() -> Result<()> {
    for tc in [1u32, 3, 8] {
        let seed = 0xcac4_1501 + u64::from(tc);
        let mut bench = Bench::new(random_patches(seed, 1 << 16), tc)?;
        let tc = u64::from(tc);
        for (cfg, id, hit) in [
            (Config::Lines(64), 1000u16, false),
            (Config::Lines(64), 1000, true),
            (Config::Lines(64), 1064, false),
            (Config::Lines(64), 1000, false),
            (Config::Disabled, 1000, false),
            (Config::Lines(64), 1000, true),
        ] {
            let out = bench.run(cfg, &[id], Pacing::NONE, seed, OUTSTANDING)?;
            let a = out.arrivals[0];
            if !cfg.enable() {
                assert_eq!((out.host_requests[0], out.responses[0]), (a, a + tc), "disabled, tc = {tc}");
            } else if hit {
                assert!(out.model_hits[0] && out.host_requests.is_empty(), "{id}");
                assert_eq!(out.responses[0], a + model::HIT_LATENCY, "hit, tc = {tc}");
            } else {
                assert!(!out.model_hits[0], "{id}");
                assert_eq!(out.host_requests, [a + model::HOST_REQUEST_DELAY], "miss, tc = {tc}");
                assert_eq!(out.responses[0], a + tc + model::MISS_OVERHEAD, "miss, tc = {tc}");
            }
        }
    }
    Ok(())
}

/// Ids 0 and 0xFFFF (zero is also what an invalid line holds: id 0 must miss first), ids that
/// all map to one line (every access a miss in a small cache, hits in a large one), and the
/// same block run with different masks and disabled in between over the same contents.
#[test]
fn corner_cases_extreme_ids_conflicts_and_mask_changes() -> Result<()> {
    let seed = 0xcac4_c0c0;
    for tc in [1u32, 8] {
        let mut bench = Bench::new(random_patches(seed, 1 << 16), tc)?;
        let pacing = Pacing { idle: true, backpressure: true };
        let ends = [0u16, 0, 0xFFFF, 0xFFFF, 0, 0xFFFF, 0x0FFF, 0xF000, 0, 0xFFFF];
        let out = bench.run(Config::Lines(LINES), &ends, pacing, seed, OUTSTANDING)?;
        // 0x0FFF and 0xFFFF share line 4095; 0xF000 and 0 share line 0.
        assert_eq!(out.model_hits, [false, true, false, true, true, true, false, false, false, false]);
        // Conflicts: ids k·16 + 5 all map to line 5 of 16.
        let conflict: Vec<u16> = (0..200u16).map(|k| (k % 7) * 16 + 5).collect();
        let out = bench.run(Config::Lines(16), &conflict, Pacing::NONE, seed, OUTSTANDING)?;
        assert!(out.model_hits.iter().all(|&h| !h), "conflicting ids never hit in 16 lines");
        let out = bench.run(Config::Lines(1024), &conflict, Pacing::NONE, seed, OUTSTANDING)?;
        assert_eq!(out.model_hits.iter().filter(|&&h| !h).count(), 7, "7 distinct ids, 1024 lines");
        // Mask changes over the same contents, and a disabled run between them.
        let ids = local_ids(600, seed);
        for cfg in [
            Config::Lines(LINES),
            Config::Lines(16),
            Config::Disabled,
            Config::Lines(1),
            Config::Lines(LINES),
            Config::Lines(1024),
            Config::Disabled,
            Config::Lines(LINES),
        ] {
            bench.run(cfg, &ids, pacing, seed, OUTSTANDING)?;
        }
        // A client with a single request outstanding at a time.
        bench.run(Config::Lines(16), &ids[..100], Pacing::NONE, seed, 1)?;
    }
    Ok(())
}

/// A memory smaller than the id space (100 patches), enabled and disabled.
#[test]
fn a_small_memory_serves_its_own_ids() -> Result<()> {
    let seed = 0xcac4_5a11;
    let mut bench = Bench::new(random_patches(seed, 100), 3)?;
    let ids = uniform_ids(500, seed, 100);
    let pacing = Pacing { idle: true, backpressure: false };
    let out = bench.run(Config::Lines(64), &ids, pacing, seed, OUTSTANDING)?;
    assert!(out.model_hits.iter().filter(|&&h| h).count() > 200);
    bench.run(Config::Disabled, &ids, pacing, seed, OUTSTANDING)?;
    Ok(())
}

/// The real patch loader in front of the cache, as in a PE.
#[derive(LogicBlock, Default)]
struct LoaderWithCache {
    pub clock: Signal<In, Clock>,
    pub cfg_enable: Signal<In, bool>,
    pub cfg_mask: Signal<In, Bits<CACHE_BITS>>,
    pub id_valid: Signal<In, bool>,
    pub id_ready: Signal<Out, bool>,
    pub id: Signal<In, Bits<16>>,
    pub mem_req: Signal<Out, bool>,
    pub mem_addr: Signal<Out, Bits<16>>,
    pub mem_valid: Signal<In, bool>,
    pub mem_ax: Signal<In, Bits<17>>,
    pub mem_ay: Signal<In, Bits<17>>,
    pub mem_bx: Signal<In, Bits<17>>,
    pub mem_by: Signal<In, Bits<17>>,
    pub out_valid: Signal<Out, bool>,
    pub out_ready: Signal<In, bool>,
    pub out_id: Signal<Out, Bits<16>>,
    pub out_ax: Signal<Out, Bits<17>>,
    pub out_ay: Signal<Out, Bits<17>>,
    pub out_bx: Signal<Out, Bits<17>>,
    pub out_by: Signal<Out, Bits<17>>,
    loader: PatchLoader,
    cache: PatchCache,
}

impl Logic for LoaderWithCache {
    #[hdl_gen]
    fn update(&mut self) {
        self.loader.clock.next = self.clock.val();
        self.cache.clock.next = self.clock.val();
        self.cache.cfg_enable.next = self.cfg_enable.val();
        self.cache.cfg_mask.next = self.cfg_mask.val();
        self.cache.flush.next = false;
        self.loader.id_valid.next = self.id_valid.val();
        self.id_ready.next = self.loader.id_ready.val();
        self.loader.id.next = self.id.val();
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
        self.out_valid.next = self.loader.out_valid.val();
        self.loader.out_ready.next = self.out_ready.val();
        self.out_id.next = self.loader.out_id.val();
        self.out_ax.next = self.loader.out_ax.val();
        self.out_ay.next = self.loader.out_ay.val();
        self.out_bx.next = self.loader.out_bx.val();
        self.out_by.next = self.loader.out_by.val();
    }
}

/// Streams `ids` through loader + cache (`cfg`), output always ready, ids back to back; checks
/// the patches against the loader's model and the host loads against the cache model; returns
/// the cycles until the last patch left.
fn loader_run(cfg: Config, ids: &[u16], tc: u32, seed: u64) -> Result<u64> {
    let context = format!("seed {seed:#x}, {cfg}, tc = {tc}");
    let mut mem = HostMemory::new(random_patches(seed, 1 << 16), tc)?;
    let memory = |id: u16| mem.patch(id).unwrap_or_default().map(|c| c as u32);
    let (expected, _) = loader::model::load(ids, memory);
    let mut board = Scoreboard::new("loader + cache", seed, expected).with_context(context.clone());
    let loads = if cfg.enable() {
        Cache::new(cfg.mask()).run(ids).iter().filter(|&&h| !h).count() as u64
    } else {
        ids.len() as u64
    };
    let mut drv = Driver::with_clock(LoaderWithCache::default(), |u| &mut u.clock)?;
    let mut next = 0;
    let mut presented: Option<[i32; 4]> = None;
    let mut out = 0;
    while out < ids.len() {
        let offer = ids.get(next).copied();
        let answer = presented.take();
        drv.drive(|u| {
            u.cfg_enable.next = cfg.enable();
            u.cfg_mask.next = b(cfg.mask().into());
            u.id_valid.next = offer.is_some();
            u.id.next = b(offer.unwrap_or(0).into());
            u.out_ready.next = true;
            u.mem_valid.next = answer.is_some();
            let d = answer.unwrap_or_default().map(|c| c as u64);
            u.mem_ax.next = b(d[0]);
            u.mem_ay.next = b(d[1]);
            u.mem_bx.next = b(d[2]);
            u.mem_by.next = b(d[3]);
        })?;
        let u = drv.uut();
        if offer.is_some() && u.id_ready.val() {
            next += 1;
        }
        presented =
            mem.cycle(u.mem_req.val().then(|| u.mem_addr.val().to_u16())).map_err(|e| e.context(&context))?;
        if u.out_valid.val() {
            let p = loader::model::Patch {
                id: u.out_id.val().to_u16(),
                ax: u.out_ax.val().to_u32(),
                ay: u.out_ay.val().to_u32(),
                bx: u.out_bx.val().to_u32(),
                by: u.out_by.val().to_u32(),
            };
            board.check(drv.cycles(), p)?;
            out += 1;
        }
        drv.tick()?;
        if drv.cycles() > 20 * (u64::from(tc) + 4) * ids.len() as u64 + 1000 {
            return Err(Error::new(format!("{context}: no progress, {out} patches out")));
        }
    }
    board.finish()?;
    if mem.loads() != loads || mem.pending() != 0 {
        return Err(Error::new(format!("{context}: {} host loads, model {loads}", mem.loads())));
    }
    Ok(drv.cycles())
}

/// The loader through the cache delivers every patch in order, enabled or not; with locality
/// and a slow host memory (T_c = 8, one load at a time) the cache saves most of the loads and
/// the time; with the cache disabled the loader sees the memory directly.
#[test]
fn the_loader_through_the_cache_delivers_every_patch_in_order() -> Result<()> {
    let seed = 0xcac4_10ad;
    let ids = local_ids(3000, seed);
    let tc = 8;
    let off = loader_run(Config::Disabled, &ids, tc, seed)?;
    let on = loader_run(Config::Lines(1024), &ids, tc, seed)?;
    let small = loader_run(Config::Lines(16), &ids, tc, seed)?;
    println!(
        "{} patches, T_c = {tc}: {off} cycles without cache, {small} with 16 lines, {on} with 1024",
        ids.len()
    );
    assert!(on < off && on < small, "the cache should pay off on a local stream");
    // Without cache the memory serves one patch per T_c cycles.
    assert!(off >= ids.len() as u64 * u64::from(tc));
    // All hits after a warm-up: the loader's full rate.
    let repeat: Vec<u16> = (0..2000u16).map(|k| k % 100).collect();
    let cycles = loader_run(Config::Lines(LINES), &repeat, tc, seed)?;
    assert!(cycles < repeat.len() as u64 + 100 * (u64::from(tc) + 8) + 50, "{cycles} cycles");
    Ok(())
}

/// Rung 4: a recorded run (cache enabled with 1024 then 16 lines, a disabled stretch between
/// them, random idle and backpressure, T_c = 3) replayed under Icarus Verilog from the exported
/// Verilog, bit-exactly with no don't-care.
#[test]
fn recorded_run_replays_bit_exactly_under_icarus() -> Result<()> {
    let seed = 0xcac4_4e91;
    let mut drv = new_driver()?;
    drv.record_ports()?;
    let mut bench = Bench::with_driver(drv, random_patches(seed, 1 << 16), 3)?;
    let pacing = Pacing { idle: true, backpressure: true };
    let ids = local_ids(500, seed);
    bench.run(Config::Lines(1024), &ids, pacing, seed, OUTSTANDING)?;
    bench.run(Config::Disabled, &ids[..100], pacing, seed + 1, OUTSTANDING)?;
    bench.run(Config::Lines(16), &ids[..300], pacing, seed + 2, OUTSTANDING)?;
    let rec = bench.drv.take_recording().ok_or("recording was on")?;
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join("cache");
    let report = rec.replay(bench.drv.uut(), &dir, Simulator::Icarus)?;
    println!("{report}");
    assert_eq!(report.cycles, rec.cycles());
    // Ten outputs (resp_valid, 4 coordinates, mem_req, mem_addr, hits, misses, flushing), compared before
    // and after every rising edge.
    assert_eq!(report.checks, 2 * 10 * rec.cycles());
    Ok(())
}

/// Rung 4 for the full return queue: the warm-up and the rounds of
/// [`four_host_answers_wait_in_a_full_return_queue_behind_hits`] (the pipelined host, random
/// words on `mem_*` while `mem_valid` is low) replayed under Icarus Verilog, bit-exactly.
#[test]
fn a_full_return_queue_replays_bit_exactly_under_icarus() -> Result<()> {
    let seed = 0xcac4_f1f1;
    let mut drv = new_driver()?;
    drv.record_ports()?;
    let patches = random_patches(seed, 1 << 16);
    let mut bench = Bench::with_host_and_driver(drv, patches, HostTiming::Pipelined(vec![1]), seed)?;
    full_return_queue_rounds(&mut bench, seed, &FULL_QUEUE_ROUNDS)?;
    let rec = bench.drv.take_recording().ok_or("recording was on")?;
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join("cache_full_return");
    let report = rec.replay(bench.drv.uut(), &dir, Simulator::Icarus)?;
    println!("{report}");
    assert_eq!(report.cycles, rec.cycles());
    assert_eq!(report.checks, 2 * 10 * rec.cycles());
    Ok(())
}
