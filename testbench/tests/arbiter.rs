//! Block-level tests of the memory arbiter (`shelling_hdl::arbiter::MemoryArbiter`): the RTL
//! against its cycle model (`model::Arbiter`) on every output in every cycle, under random
//! requests from every PE (each keeping at most `QUEUE_DEPTH` outstanding, as a PE does) and
//! the shared host memory at several `T_c`, every answer checked to reach the PE that asked,
//! with its patch, in its order (rung 3); the round-robin wait bound; and the rung-4 replays of
//! a recorded run of its exported Verilog under Icarus Verilog and Verilator.
//!
//! `cargo test -p shelling-testbench --test arbiter`

use std::collections::VecDeque;
use std::path::PathBuf;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use shelling_hdl::arbiter::model::Arbiter;
use shelling_hdl::arbiter::{MemoryArbiter, QUEUE_DEPTH};
use shelling_testbench::{Driver, Error, HostMemory, Result, Simulator};

/// The patch of id `i` in the host memory of these tests.
fn patch(i: u16) -> [i32; 4] {
    let i = i as i32;
    [i, (i * 3 + 1) & 0x1ffff, (i * 7 + 2) & 0x1ffff, 0x1ffff - i]
}

/// What a run saw.
#[derive(Debug, Default)]
struct Seen {
    answers: Vec<usize>,
    /// The most clocks a request at the head of its queue saw granted to other PEs.
    max_wait: u64,
}

/// Runs `cycles` of random traffic from power-up: PE `i` asks with probability `rates[i]`
/// percent while it has fewer than `limit` requests outstanding. Checks the RTL against the
/// model in every cycle and every answer against the PE's own request order.
fn run<const N: usize>(
    drv: &mut Driver<MemoryArbiter<N>>,
    seed: u64,
    tc: u32,
    rates: [u32; N],
    limit: usize,
    cycles: u64,
) -> Result<Seen> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut memory = HostMemory::new((0..1024).map(patch).collect(), tc)?;
    let mut model = Arbiter::new(N);
    let mut outstanding: Vec<VecDeque<u16>> = vec![VecDeque::new(); N];
    let mut waiting = [0u64; N];
    let mut answer: Option<[i32; 4]> = None;
    let mut seen = Seen { answers: vec![0; N], ..Default::default() };
    let fail = |c: u64, what: String| Error::new(format!("seed {seed:#x}, T_c {tc}, cycle {c}: {what}"));
    for c in 0..cycles {
        let requests: [Option<u16>; N] = std::array::from_fn(|i| {
            (outstanding[i].len() < limit && rng.random_range(0..100) < rates[i])
                .then(|| rng.random_range(0..1024u16))
        });
        drv.drive(|u| {
            for i in 0..N {
                u.pe_req[i].next = requests[i].is_some();
                u.pe_addr[i].next = (requests[i].unwrap_or(0) as u64).into();
            }
            u.host_valid.next = answer.is_some();
            let a = answer.unwrap_or([0; 4]);
            u.host_ax.next = (a[0] as u64).into();
            u.host_ay.next = (a[1] as u64).into();
            u.host_bx.next = (a[2] as u64).into();
            u.host_by.next = (a[3] as u64).into();
        })?;
        // Every output is a register: compare before the edge.
        let u = drv.uut();
        let got = shelling_hdl::arbiter::model::Outputs {
            answer: (0..N).find(|&i| u.pe_valid[i].val()),
            patch: [u.pe_ax.val(), u.pe_ay.val(), u.pe_bx.val(), u.pe_by.val()].map(|b| b.to_u32()),
            host: u.host_req.val().then(|| u.host_addr.val().to_u64() as u16),
            requests: u.requests.val().to_u32(),
        };
        let valid_count = (0..N).filter(|&i| u.pe_valid[i].val()).count();
        if got != model.outputs() || valid_count > 1 {
            return Err(fail(c, format!("RTL {got:?} ({valid_count} valid), model {:?}", model.outputs())));
        }
        if let Some(pe) = got.answer {
            let id =
                outstanding[pe].pop_front().ok_or_else(|| fail(c, format!("PE {pe} answered unasked")))?;
            if got.patch != patch(id).map(|v| v as u32) {
                return Err(fail(c, format!("PE {pe} got {:?} for patch {id}", got.patch)));
            }
            seen.answers[pe] += 1;
        }
        let heads: [bool; N] = std::array::from_fn(|i| model.head_valid(i));
        for i in 0..N {
            if let Some(id) = requests[i] {
                outstanding[i].push_back(id);
            }
        }
        let presented = answer.map(|a| a.map(|v| v as u32));
        answer = memory.cycle(got.host)?;
        let grant = model.step(&requests, presented).map_err(|e| fail(c, e))?;
        // A request at the head of its queue waits each clock another PE is granted.
        for i in (0..N).filter(|&i| heads[i]) {
            waiting[i] = if grant == Some(i) { 0 } else { waiting[i] + 1 };
            seen.max_wait = seen.max_wait.max(waiting[i]);
        }
        drv.tick()?;
    }
    Ok(seen)
}

/// Four PEs at every mix of rates and `T_c` against the model, every answer to the PE that
/// asked, in its order; under a host slower than the PEs' demand the queues fill to their depth.
#[test]
fn the_arbiter_matches_its_model_and_routes_every_answer() -> Result<()> {
    for (k, (tc, rates)) in
        [(1, [100, 100, 100, 100]), (1, [30, 5, 60, 0]), (4, [100, 50, 20, 100]), (16, [100; 4])]
            .into_iter()
            .enumerate()
    {
        let seed = 0xa7b_000 + k as u64;
        let mut drv = Driver::with_clock(MemoryArbiter::<4>::default(), |u| &mut u.clock)?;
        let seen = run(&mut drv, seed, tc, rates, QUEUE_DEPTH, 2000 + 400 * tc as u64)?;
        for (i, &n) in seen.answers.iter().enumerate() {
            assert!(rates[i] == 0 || n > 50, "seed {seed:#x}: PE {i} got only {n} answers");
        }
        assert!(seen.max_wait <= 3, "seed {seed:#x}: a request waited {} grants of others", seen.max_wait);
        if rates == [100; 4] {
            assert_eq!(seen.max_wait, 3, "seed {seed:#x}: every PE asking, each waits for the three others");
        }
    }
    Ok(())
}

/// Rung 4: a recorded run (every PE asking, the host at `T_c` = 3, so the queues fill and the
/// grants rotate) replayed under Icarus Verilog and Verilator, every output before and after
/// every rising edge.
#[test]
fn recorded_run_replays_bit_exactly_under_icarus_and_verilator() -> Result<()> {
    let seed = 0xa7b_100;
    let mut drv = Driver::with_clock(MemoryArbiter::<4>::default(), |u| &mut u.clock)?;
    drv.record_ports()?;
    run(&mut drv, seed, 3, [100, 60, 30, 100], QUEUE_DEPTH, 600)?;
    let rec = drv.take_recording().ok_or("recording was on")?;
    for sim in [Simulator::Icarus, Simulator::Verilator] {
        let dir =
            PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join(format!("memory_arbiter_{sim:?}"));
        let report = rec.replay(drv.uut(), &dir, sim)?;
        println!("{report}");
        assert_eq!(report.cycles, rec.cycles());
    }
    Ok(())
}
