//! Block-level tests of the processing element's job queue (`shelling_hdl::queue::JobQueue`):
//! the RTL against its cycle model (`model::Queue`) on `in_ready`, `out_valid`, `occupied` and
//! every field of the head in every cycle, under random offers and random `out_ready` at four
//! rates, every job out once and in order (rung 3), and the rung-4 replay of a recorded run of
//! its exported Verilog under Icarus Verilog.
//!
//! `cargo test -p shelling-testbench --test queue`

use std::path::PathBuf;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use shelling_hdl::queue::model::Queue;
use shelling_hdl::queue::{JobQueue, QUEUE_DEPTH};
use shelling_testbench::{Driver, Error, Result, Simulator};

/// Offer and `out_ready` probabilities (percent).
const RATES: [(u32, u32); 4] = [(100, 100), (100, 20), (20, 100), (60, 60)];

/// A job's fields as port bits: id, six coordinates, sh, first, count, retire.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Job([u64; 10], bool);

const WIDTHS: [u32; 10] = [16, 18, 18, 18, 18, 18, 18, 6, 10, 11];

fn random_job(rng: &mut ChaCha8Rng) -> Job {
    Job(WIDTHS.map(|w| rng.random_range(0..1u64 << w)), rng.random_range(0..2) == 1)
}

fn head(u: &JobQueue) -> Job {
    Job(
        [
            u.out_id.val().to_u64(),
            u.out_ax.val().to_u64(),
            u.out_ay.val().to_u64(),
            u.out_bx.val().to_u64(),
            u.out_by.val().to_u64(),
            u.out_wx.val().to_u64(),
            u.out_wy.val().to_u64(),
            u.out_sh.val().to_u64(),
            u.out_first.val().to_u64(),
            u.out_count.val().to_u64(),
        ],
        u.out_retire.val(),
    )
}

fn offer(u: &mut JobQueue, job: Option<Job>) {
    u.in_valid.next = job.is_some();
    let Job(f, retire) = job.unwrap_or(Job([0; 10], false));
    u.in_id.next = f[0].into();
    u.in_ax.next = f[1].into();
    u.in_ay.next = f[2].into();
    u.in_bx.next = f[3].into();
    u.in_by.next = f[4].into();
    u.in_wx.next = f[5].into();
    u.in_wy.next = f[6].into();
    u.in_sh.next = f[7].into();
    u.in_first.next = f[8].into();
    u.in_count.next = f[9].into();
    u.in_retire.next = retire;
}

/// Runs random traffic from power-up against the model, `phases` of `(rates, cycles)` one after
/// the other; returns the jobs out and the cycles the queue was full.
fn run(drv: &mut Driver<JobQueue>, seed: u64, phases: &[((u32, u32), u64)]) -> Result<(usize, u64)> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut m: Queue<Job> = Queue::default();
    let (mut sent, mut out, mut full) = (Vec::new(), 0usize, 0u64);
    let mut next = random_job(&mut rng);
    let rates = phases.iter().flat_map(|&(r, n)| std::iter::repeat_n(r, n as usize));
    for (cycle, rates) in rates.enumerate() {
        let job = (rng.random_range(0..100) < rates.0).then_some(next);
        let ready = rng.random_range(0..100) < rates.1;
        drv.drive(|u| {
            offer(u, job);
            u.out_ready.next = ready;
        })?;
        let u = drv.uut();
        let got = (u.in_ready.val(), u.out_valid.val().then(|| head(u)), u.occupied.val());
        let want = (m.in_ready(), m.out().copied(), m.len() != 0);
        if got != want {
            return Err(Error::new(format!(
                "seed {seed:#x}, cycle {cycle}: (in_ready, head, occupied) = {got:?}, model {want:?}"
            )));
        }
        full += !m.in_ready() as u64;
        if job.is_some() && m.in_ready() {
            sent.push(next);
            next = random_job(&mut rng);
        }
        if let Some(left) = m.clock(job, ready) {
            if left != sent[out] {
                return Err(Error::new(format!("seed {seed:#x}, cycle {cycle}: job {out} out of order")));
            }
            out += 1;
        }
        drv.tick()?;
    }
    Ok((out, full))
}

/// The queue against its model at every rate: the same handshakes and heads in every cycle,
/// every job out once, in order; the queue full now and then where the output is slow.
#[test]
fn the_queue_matches_its_model_on_every_cycle() -> Result<()> {
    for (k, rates) in RATES.into_iter().enumerate() {
        let seed = 0x9e_e000 + k as u64;
        let mut drv = Driver::with_clock(JobQueue::default(), |u| &mut u.clock)?;
        let (out, full) = run(&mut drv, seed, &[(rates, 4000)])?;
        assert!(out > 700, "seed {seed:#x}: only {out} jobs out");
        assert!(rates.0 <= rates.1 || full > 0, "seed {seed:#x}: never full at {rates:?}");
    }
    Ok(())
}

/// Rung 4: a recorded run (the queue filled to its depth, then drained) replayed under Icarus
/// Verilog, every output before and after every rising edge.
#[test]
fn recorded_run_replays_bit_exactly_under_icarus() -> Result<()> {
    let seed = 0x9e_e100;
    let mut drv = Driver::with_clock(JobQueue::default(), |u| &mut u.clock)?;
    drv.record_ports()?;
    let (_, full) = run(&mut drv, seed, &[((100, 20), 200), ((20, 100), 200)])?;
    assert!(full > 0, "seed {seed:#x}: never full");
    let rec = drv.take_recording().ok_or("recording was on")?;
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join("job_queue");
    let report = rec.replay(drv.uut(), &dir, Simulator::Icarus)?;
    println!("{report}; depth {QUEUE_DEPTH}");
    assert_eq!(report.cycles, rec.cycles());
    Ok(())
}
