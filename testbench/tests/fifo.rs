//! Block-level tests of the first-word-fall-through FIFO (`shelling_hdl::prim::fifo`): its
//! control against the bit-true model on every output of every cycle, the FIFO of one lane
//! against a queue (every word out once, in order, `valid` two clocks after a push to an empty
//! FIFO), each under random pushes and pops at four rates (rung 3), and the rung-4 replay of a
//! recorded run of the exported `fwft_fifo` under Icarus Verilog.
//!
//! `cargo test -p shelling-testbench --test fifo`

use std::collections::VecDeque;
use std::path::PathBuf;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use shelling_hdl::prim::fifo::model::Control;
use shelling_hdl::prim::FifoControl;
use shelling_testbench::export::FwftFifo;
use shelling_testbench::{Driver, Error, Result, Simulator};

/// Push and pop probabilities (percent): the cross product of a sparse and a dense rate each.
const RATES: [(u32, u32); 4] = [(100, 100), (100, 30), (30, 100), (60, 60)];

/// The control of a 16-slot FIFO against [`Control`], every output in every cycle, under
/// random pushes (never while 16 words are held) and pops (only while `valid`).
#[test]
fn control_matches_the_model_on_every_cycle() -> Result<()> {
    for (k, (p_push, p_pop)) in RATES.into_iter().enumerate() {
        let seed = 0xf1f0_0000 + k as u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut drv = Driver::with_clock(FifoControl::<4, 5>::default(), |u| &mut u.clock)?;
        let mut m = Control::new(4);
        for cycle in 0..3000u64 {
            let u = drv.uut();
            let got = (
                u.tail_address.val().to_u32(),
                u.head_address.val().to_u32(),
                u.next_address.val().to_u32(),
                u.valid.val(),
                u.count.val().to_u32(),
            );
            let want = (m.tail, m.head, m.next(), m.valid, m.count);
            if got != want {
                return Err(Error::new(format!(
                    "seed {seed:#x}, cycle {cycle}: (tail, head, next, valid, count) = {got:?}, model {want:?}"
                )));
            }
            let push = m.count < 16 && rng.random_range(0..100) < p_push;
            let pop = m.valid && rng.random_range(0..100) < p_pop;
            drv.cycle(|u| {
                u.push.next = push;
                u.pop.next = pop;
            })?;
            m.step(push, pop);
        }
    }
    Ok(())
}

/// Runs random pushes and pops on a [`FwftFifo`] from power-up, `phases` of `(rates, cycles)`
/// one after the other, checking it against a queue: `count` is the words held, `valid` is high exactly while a word pushed before the last
/// edge is held, and then `data_out` is the oldest. Returns the words popped.
fn run_against_queue(drv: &mut Driver<FwftFifo>, seed: u64, phases: &[((u32, u32), u64)]) -> Result<usize> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut queue: VecDeque<u8> = VecDeque::new();
    let mut pushed_last = false;
    let mut popped = 0;
    let rate = |cycle: u64| {
        let mut end = 0;
        phases.iter().find(|(_, n)| {
            end += n;
            cycle < end
        })
    };
    let total: u64 = phases.iter().map(|(_, n)| n).sum();
    for cycle in 0..total {
        let rates = rate(cycle).expect("a phase for every cycle").0;
        let u = drv.uut();
        let valid = u.valid.val();
        let ctx = || format!("seed {seed:#x}, cycle {cycle}");
        if u.count.val().index() != queue.len() {
            return Err(Error::new(format!(
                "{}: count {} with {} held",
                ctx(),
                u.count.val().index(),
                queue.len()
            )));
        }
        if valid != (queue.len() > pushed_last as usize) {
            return Err(Error::new(format!("{}: valid {valid} with {} held", ctx(), queue.len())));
        }
        if valid && u.data_out.val().to_u32() as u8 != queue[0] {
            return Err(Error::new(format!(
                "{}: head {} but {} is the oldest",
                ctx(),
                u.data_out.val().to_u32(),
                queue[0]
            )));
        }
        let push = queue.len() < 16 && rng.random_range(0..100) < rates.0;
        let pop = valid && rng.random_range(0..100) < rates.1;
        let word: u8 = rng.random();
        drv.cycle(|u| {
            u.push.next = push;
            u.data_in.next = (word as u64).into();
            u.pop.next = pop;
        })?;
        if pop {
            queue.pop_front();
            popped += 1;
        }
        if push {
            queue.push_back(word);
        }
        pushed_last = push;
    }
    Ok(popped)
}

/// The FIFO of one lane against a queue at every rate: no word lost, duplicated or reordered.
#[test]
fn every_word_leaves_once_in_order() -> Result<()> {
    for (k, rates) in RATES.into_iter().enumerate() {
        let seed = 0xf1f0_1000 + k as u64;
        let mut drv = Driver::with_clock(FwftFifo::default(), |u| &mut u.clock)?;
        let popped = run_against_queue(&mut drv, seed, &[(rates, 3000)])?;
        assert!(popped > 500, "seed {seed:#x}: only {popped} words out");
    }
    Ok(())
}

/// Rung 4: a recorded run of the exported `fwft_fifo` (random pushes and pops, the FIFO full and
/// empty in turn) replayed under Icarus Verilog, bit-exactly with no don't-care.
#[test]
fn recorded_run_replays_bit_exactly_under_icarus() -> Result<()> {
    let seed = 0xf1f0_2000;
    let mut drv = Driver::with_clock(FwftFifo::default(), |u| &mut u.clock)?;
    drv.record_ports()?;
    run_against_queue(&mut drv, seed, &[((100, 30), 300), ((30, 100), 300)])?;
    let rec = drv.take_recording().ok_or("recording was on")?;
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join("fifo");
    let report = rec.replay(drv.uut(), &dir, Simulator::Icarus)?;
    println!("{report}");
    assert_eq!(report.cycles, rec.cycles());
    // Three outputs (valid, data_out, count), compared before and after every rising edge.
    assert_eq!(report.checks, 2 * 3 * rec.cycles());
    Ok(())
}
