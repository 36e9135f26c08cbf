//! Block-level tests of the patch loader (`shelling_hdl::loader`): every id comes out exactly
//! once, in order, with the coordinates the host memory holds, under all four pacings and
//! memory latencies T_c ∈ {1, 3, 8}; the FIFO never overflows and does fill under
//! backpressure; corner cases (no ids, back-to-back ids with exact cycle counts, a full FIFO);
//! and the rung-4 replay of a recorded run under Icarus Verilog.
//!
//! `cargo test -p shelling-testbench --test loader`

use std::collections::VecDeque;
use std::path::PathBuf;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rust_hdl::prelude::*;
use shelling_hdl::loader::model::{self, Patch, COORD_MASK};
use shelling_hdl::loader::{PatchLoader, DEPTH};
use shelling_testbench::{Driver, Error, Monitor, Pacing, Result, Scoreboard, Simulator, Source};

/// The host memory: one random patch per possible id, answering each request `tc` cycles later.
struct HostMemory {
    patches: Vec<[u32; 4]>,
    tc: u64,
    /// Requests in flight: (cycle of the answer, id).
    inflight: VecDeque<(u64, u16)>,
}

impl HostMemory {
    fn random(seed: u64, tc: u64) -> Self {
        assert!(tc >= 1);
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x6d65_6d6f_7279);
        let patches =
            (0..=u16::MAX as usize).map(|_| [0; 4].map(|_: u32| rng.random::<u32>() & COORD_MASK)).collect();
        Self { patches, tc, inflight: VecDeque::new() }
    }

    fn lookup(&self, id: u16) -> [u32; 4] {
        self.patches[id as usize]
    }

    /// Drive phase of `cycle`: the answer due now, if any.
    fn answer(&mut self, cycle: u64) -> Option<u16> {
        match self.inflight.front() {
            Some(&(due, id)) if due == cycle => {
                self.inflight.pop_front();
                Some(id)
            }
            _ => None,
        }
    }

    /// Settled pre-edge state of `cycle`: a request seen now is answered `tc` cycles later.
    fn request(&mut self, cycle: u64, id: u16) {
        self.inflight.push_back((cycle + self.tc, id));
    }
}

fn b<const N: usize>(v: u32) -> Bits<N> {
    Bits::from(v as u64)
}

/// How one run went.
#[derive(Debug, Default)]
struct Stats {
    /// Cycles until the last patch left.
    cycles: u64,
    /// Cycles with `id_ready` low (all slots reserved).
    full_cycles: u64,
    /// Cycles with all `DEPTH` slots holding a fetched patch.
    all_filled_cycles: u64,
    /// The largest number of slots reserved.
    max_reserved: usize,
    /// The output transfers' cycles.
    out_cycles: Vec<u64>,
}

/// Streams `ids` through the loader with the host memory `mem`; the output is not ready during
/// the first `hold` cycles and then follows `pacing`. Checks, every cycle: requests come in id
/// order, every answer has a slot waiting (reserved > filled), reserved ≤ DEPTH and equals the
/// ids accepted minus the patches out; at the end: the scoreboard, `loads`, and that nothing
/// more comes out or is requested.
fn run(
    drv: &mut Driver<PatchLoader>,
    ids: &[u16],
    mem: &mut HostMemory,
    pacing: Pacing,
    seed: u64,
    hold: u64,
) -> Result<Stats> {
    let (expected, loads) = model::load(ids, |id| mem.lookup(id));
    let mut board =
        Scoreboard::new("loader", seed, expected).with_context(format!("{pacing}, tc = {}", mem.tc));
    let mut src = Source::new(ids.iter().copied(), pacing, seed);
    let mut mon = Monitor::new(pacing, seed);
    let mut stats = Stats::default();
    let mut accepted = 0usize;
    let mut requested = 0usize;
    let start = drv.cycles();
    let limit = start + 20 * ids.len() as u64 + hold + 100;
    while mon.items().len() < ids.len() {
        let cycle = drv.cycles();
        let answer = mem.answer(cycle);
        let data = mem.lookup(answer.unwrap_or(0));
        let offer = src.present(true).copied();
        let ready = cycle >= start + hold && mon.ready();
        drv.drive(|u| {
            u.id_valid.next = offer.is_some();
            u.id.next = b(offer.unwrap_or(0) as u32);
            u.out_ready.next = ready;
            u.mem_valid.next = answer.is_some();
            u.mem_ax.next = b(data[0]);
            u.mem_ay.next = b(data[1]);
            u.mem_bx.next = b(data[2]);
            u.mem_by.next = b(data[3]);
        })?;
        let u = drv.uut();
        let (reserved, filled) = (u.reserved(), u.filled());
        if answer.is_some() && filled >= reserved {
            return Err(Error::new(format!(
                "cycle {cycle}: an answer arrives with no slot waiting ({filled} filled of {reserved})"
            )));
        }
        if reserved > DEPTH || filled > reserved || reserved != accepted - mon.items().len() {
            return Err(Error::new(format!(
                "cycle {cycle}: FIFO state {filled} filled / {reserved} reserved, {} ids accepted, {} out",
                accepted,
                mon.items().len()
            )));
        }
        stats.max_reserved = stats.max_reserved.max(reserved);
        stats.full_cycles += u64::from(!u.id_ready.val());
        stats.all_filled_cycles += u64::from(filled == DEPTH);
        if u.mem_req.val() {
            let addr = u.mem_addr.val().to_u16();
            if ids.get(requested) != Some(&addr) {
                return Err(Error::new(format!(
                    "cycle {cycle}: request #{requested} for id {addr}, expected {:?}",
                    ids.get(requested)
                )));
            }
            requested += 1;
            mem.request(cycle, addr);
        }
        let take = offer.is_some() && u.id_ready.val();
        src.accepted(take)?;
        accepted += usize::from(take);
        let patch = || Patch {
            id: u.out_id.val().to_u16(),
            ax: u.out_ax.val().to_u32(),
            ay: u.out_ay.val().to_u32(),
            bx: u.out_bx.val().to_u32(),
            by: u.out_by.val().to_u32(),
        };
        if mon.observe(cycle, u.out_valid.val(), patch) {
            let last = mon.items().last().ok_or("an item was observed")?;
            board.check(cycle, last.item)?;
            stats.out_cycles.push(cycle - start);
        }
        drv.tick()?;
        if drv.cycles() > limit {
            return Err(Error::new(format!(
                "no progress: {} of {} patches out",
                mon.items().len(),
                ids.len()
            )));
        }
    }
    board.finish()?;
    stats.cycles = drv.cycles() - start;
    // Nothing more: no duplicate, no stray request; the FIFO is empty.
    for _ in 0..mem.tc + 2 * model::LATENCY {
        let cycle = drv.cycles();
        if mem.answer(cycle).is_some() {
            return Err(Error::new(format!("cycle {cycle}: a request was still in flight at the end")));
        }
        drv.drive(|u| {
            u.id_valid.next = false;
            u.out_ready.next = true;
            u.mem_valid.next = false;
        })?;
        let u = drv.uut();
        if u.out_valid.val() || u.mem_req.val() {
            return Err(Error::new(format!("cycle {cycle}: output or request after the last patch")));
        }
        drv.tick()?;
    }
    let u = drv.uut();
    if u.loads.val().to_u32() != loads || u.reserved() != 0 || u.filled() != 0 {
        return Err(Error::new(format!(
            "at the end: loads = {} (model {loads}), {} slots reserved, {} filled",
            u.loads.val().to_u32(),
            u.reserved(),
            u.filled()
        )));
    }
    Ok(stats)
}

fn new_driver() -> Result<Driver<PatchLoader>> {
    Driver::with_clock(PatchLoader::default(), |u| &mut u.clock)
}

fn random_ids(n: usize, seed: u64) -> Vec<u16> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..n).map(|_| rng.random()).collect()
}

/// 3 latencies × 4 pacings × 9000 ids: 108 000 patches through the loader.
#[test]
fn every_patch_once_in_order_under_all_pacings_and_latencies() -> Result<()> {
    for tc in [1u64, 3, 8] {
        for (k, pacing) in Pacing::ALL.into_iter().enumerate() {
            let seed = 0x10ad_0000 + 16 * tc + k as u64;
            let ids = random_ids(9000, seed);
            let mut mem = HostMemory::random(seed, tc);
            let mut drv = new_driver()?;
            let stats = run(&mut drv, &ids, &mut mem, pacing, seed, 0)
                .map_err(|e| e.context(format!("seed {seed:#x}, {pacing}, tc = {tc}")))?;
            println!(
                "tc = {tc}, {pacing}: {} cycles for {} ids, id_ready low in {}, all {DEPTH} slots \
                 filled in {}, max {} reserved",
                stats.cycles,
                ids.len(),
                stats.full_cycles,
                stats.all_filled_cycles,
                stats.max_reserved
            );
            if pacing.backpressure && !pacing.idle {
                // Full: every slot reserved (fetched or in flight), so `id_ready` is low.
                assert!(
                    stats.full_cycles > 0 && stats.max_reserved == DEPTH,
                    "seed {seed:#x}, {pacing}, tc = {tc}: backpressure never filled the FIFO"
                );
            }
            if pacing == Pacing::NONE {
                assert_eq!(stats.cycles, model::unstalled_cycles(ids.len(), tc), "seed {seed:#x}, tc = {tc}");
            }
        }
    }
    Ok(())
}

#[test]
fn no_ids_no_requests_no_output() -> Result<()> {
    let seed = 0x10ad_000e;
    let mut mem = HostMemory::random(seed, 3);
    let mut drv = new_driver()?;
    let stats = run(&mut drv, &[], &mut mem, Pacing { idle: true, backpressure: true }, seed, 0)?;
    assert_eq!(stats.cycles, 0);
    for _ in 0..50 {
        drv.drive(|u| u.out_ready.next = true)?;
        let u = drv.uut();
        assert!(!u.out_valid.val() && !u.mem_req.val() && u.id_ready.val());
        drv.tick()?;
    }
    assert_eq!(drv.uut().loads.val().to_u32(), 0);
    Ok(())
}

/// Back-to-back ids with an always-ready output: one patch per cycle, each `T_c + 3` cycles
/// after its id, exactly as the model's cycle formula says; also where the FIFO depth limits
/// the throughput (T_c = 20: 16 patches per 24 cycles). Repeated ids are fetched each time.
#[test]
fn back_to_back_ids_follow_the_cycle_model() -> Result<()> {
    for tc in [1u64, 3, 8, 12, 13, 20] {
        let seed = 0x10ad_b2b0 + tc;
        let mut ids = random_ids(200, seed);
        ids[50..60].fill(7);
        let mut mem = HostMemory::random(seed, tc);
        let mut drv = new_driver()?;
        let stats = run(&mut drv, &ids, &mut mem, Pacing::NONE, seed, 0)
            .map_err(|e| e.context(format!("seed {seed:#x}, tc = {tc}")))?;
        assert_eq!(stats.out_cycles, model::output_cycles(ids.len(), tc), "tc = {tc}");
        assert_eq!(stats.cycles, model::unstalled_cycles(ids.len(), tc), "tc = {tc}");
        if tc <= 12 {
            assert_eq!(stats.cycles, ids.len() as u64 + tc + model::LATENCY);
        }
    }
    Ok(())
}

/// The output is held not ready for 100 cycles: exactly DEPTH ids are accepted and fetched,
/// `id_ready` stays low, nothing is dropped; then everything drains in order.
#[test]
fn full_fifo_stops_the_id_stream_and_drops_nothing() -> Result<()> {
    for tc in [1u64, 8] {
        let seed = 0x10ad_f011 + tc;
        let ids = random_ids(100, seed);
        let mut mem = HostMemory::random(seed, tc);
        let mut drv = new_driver()?;
        let hold = 100;
        let stats = run(&mut drv, &ids, &mut mem, Pacing::NONE, seed, hold)
            .map_err(|e| e.context(format!("seed {seed:#x}, tc = {tc}")))?;
        assert_eq!(stats.max_reserved, DEPTH);
        // Ids accepted in cycles 0..16, requested in 1..=16, answered in 1 + tc..=16 + tc: all
        // slots hold a patch from cycle 17 + tc up to the first pop, in cycle `hold`.
        assert_eq!(stats.all_filled_cycles, hold - (DEPTH as u64 + tc), "tc = {tc}");
        assert!(stats.full_cycles >= hold - DEPTH as u64, "tc = {tc}");
        assert_eq!(stats.out_cycles[0], hold);
    }
    Ok(())
}

/// Rung 4: a recorded run (random idle and backpressure, T_c = 3, a full FIFO at the start)
/// replayed under Icarus Verilog from the exported Verilog, bit-exactly with no don't-care:
/// the `out_*` data hold the block RAM read registers, defined (zero at power-up) in both.
#[test]
fn recorded_run_replays_bit_exactly_under_icarus() -> Result<()> {
    let seed = 0x10ad_4e91;
    let ids = random_ids(400, seed);
    let mut mem = HostMemory::random(seed, 3);
    let mut drv = new_driver()?;
    drv.record_ports()?;
    run(&mut drv, &ids, &mut mem, Pacing { idle: true, backpressure: true }, seed, 40)?;
    let rec = drv.take_recording().ok_or("recording was on")?;
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join("loader");
    let report = rec.replay(drv.uut(), &dir, Simulator::Icarus)?;
    println!("{report}");
    assert_eq!(report.cycles, rec.cycles());
    // Eleven outputs (id_ready, id_ready_next, mem_req, mem_addr, out_valid, out_id, 4
    // coordinates, loads), compared before and after every rising edge.
    assert_eq!(report.checks, 2 * 11 * rec.cycles());
    Ok(())
}
