//! A machine of several processing elements on one host memory through the memory arbiter
//! (`shelling_testbench::machine`): each PE's hits and counts are its source's, whatever the
//! others do; the PEs work in parallel (a round of N sources takes far less than N single
//! runs when the memory keeps up) and the host memory bounds them when it does not; rust-hdl's
//! PEs and the compiled ones give the same cycles. Every failure names its seed.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use shelling_hdl::machine::Machine;
use shelling_hdl::pe::ProcessingElement;
use shelling_testbench::machine::{run_queues, Composed, MachineCounters, MachineSim, Work};
use shelling_testbench::memory::HostMemory;
use shelling_testbench::pe::{flush_cache, model, run, CacheConfig, Command, ModelCounts, PeSetup};
use shelling_testbench::verilated::VerilatedPe;
use shelling_testbench::{Driver, Result, Simulator};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// `n` sources of `rays` rays at random points of one scene: each source with `patches`
/// random patches in front of it, most facing it (the scene is every source's patches), and a
/// random command stream of sectors and jobs, three jobs in four for its own patches.
fn sources(
    seed: u64,
    n: usize,
    rays: usize,
    patches: usize,
) -> (Vec<[i32; 4]>, Vec<(PeSetup, Vec<Command>)>) {
    use shelling_hdl::formats::{direction, Quantizer};
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let q = Quantizer { offset: [0.0, 0.0] };
    let point = |p: [f64; 2]| q.point(|| "point".into(), p).expect("in range");
    let mut mem: Vec<[i32; 4]> = Vec::new();
    let mut setups = Vec::new();
    for _ in 0..n {
        let o = [rng.random_range(300.0..1700.0), rng.random_range(300.0..1700.0)];
        let phi: f64 = rng.random_range(0.0..TAU);
        let dirs: Vec<[i32; 2]> = (0..rays)
            .map(|i| {
                let a = phi - FRAC_PI_2 + (i as f64 + 0.5) * PI / rays as f64;
                direction(|| "ray".into(), [a.cos(), a.sin()]).expect("unit vector")
            })
            .collect();
        setups.push(PeSetup {
            origin: point(o),
            normal: direction(|| "normal".into(), [phi.cos(), phi.sin()]).expect("unit"),
            dirs,
        });
        for k in 0..patches {
            let (r, th): (f64, f64) = (rng.random_range(2.0..250.0), rng.random_range(-1.5..1.5));
            let c = [o[0] + r * (phi + th).cos(), o[1] + r * (phi + th).sin()];
            let (len, t): (f64, f64) = (rng.random_range(0.5..80.0), rng.random_range(0.0..TAU));
            let a = point([c[0] - len * t.cos(), c[1] - len * t.sin()]);
            let b = point([c[0] + len * t.cos(), c[1] + len * t.sin()]);
            let oq = point(o);
            let (ra, rb) = ([a[0] - oq[0], a[1] - oq[1]], [b[0] - oq[0], b[1] - oq[1]]);
            let facing = (ra[0] as i64 * rb[1] as i64 - ra[1] as i64 * rb[0] as i64) > 0;
            mem.push(if facing || k % 7 == 0 { [a[0], a[1], b[0], b[1]] } else { [b[0], b[1], a[0], a[1]] });
        }
    }
    let work = setups
        .into_iter()
        .enumerate()
        .map(|(p, setup)| {
            let mut cmds = Vec::new();
            let mut s = 0;
            while s < rays {
                let e = (s + rng.random_range(16..=96)).min(rays);
                cmds.push(Command::Sector { first: setup.dirs[s], last: setup.dirs[e - 1] });
                for _ in 0..48 {
                    let first = rng.random_range(s..e);
                    let count = rng.random_range(1..=e - first);
                    let id = if rng.random_range(0..4) == 0 {
                        rng.random_range(0..mem.len())
                    } else {
                        p * patches + rng.random_range(0..patches)
                    };
                    cmds.push(Command::Job { id: id as u16, first: first as u16, count: count as u16 });
                }
                s = e;
            }
            (setup, cmds)
        })
        .collect();
    (mem, work)
}

/// Queues of `work[i]` on PE `pe_of[i]` (one source per PE: `0, 1, 2, ...`).
fn queues<'a>(work: &'a [(PeSetup, Vec<Command>)], pe_of: &[usize]) -> Vec<Vec<Work<'a>>> {
    let mut q: Vec<Vec<Work>> = vec![Vec::new(); pe_of.iter().max().map_or(0, |m| m + 1)];
    for ((setup, commands), &p) in work.iter().zip(pe_of) {
        q[p].push(Work { setup, commands });
    }
    q
}

/// `work[i]` on PE `pe_of[i]`, each PE's sources one after another, against the model, source
/// by source; returns the run's counters.
fn run_on<M: MachineSim>(
    machine: &mut M,
    seed: u64,
    mem: &[[i32; 4]],
    work: &[(PeSetup, Vec<Command>)],
    pe_of: &[usize],
    tc: u32,
    cache: CacheConfig,
) -> Result<MachineCounters> {
    let mut memory = HostMemory::new(mem.to_vec(), tc)?;
    let k = run_queues(machine, &mut memory, cache, &queues(work, pe_of), |_| {})?;
    let mut next = vec![0; k.pes.len()];
    let mut queue_counts = vec![ModelCounts::default(); k.pes.len()];
    for (i, ((setup, cmds), &p)) in work.iter().zip(pe_of).enumerate() {
        let (want, counts) = model(setup, mem, cmds);
        let traced = &k.pes[p][next[p]];
        next[p] += 1;
        assert_eq!(
            traced.hits, want,
            "seed {seed:#x}, T_c {tc}, {cache:?}: source {i}'s hits on PE {p} against the model"
        );
        assert!(counts.tests > counts.loads, "seed {seed:#x}: PE {p}'s stream is degenerate: {counts:?}");
        queue_counts[p] = queue_counts[p].plus(&counts);
    }
    // A PE's counts over its queue (its sources overlap, so its counters are not split).
    for (p, (pe, counts)) in k.totals.iter().zip(&queue_counts).enumerate() {
        assert_eq!(
            (pe.patch_loads, pe.passed, pe.tests),
            (counts.loads, counts.passed, counts.tests),
            "seed {seed:#x}, T_c {tc}: PE {p}'s loads, passed and tests over its queue against the model"
        );
    }
    let answered: u64 = k.totals.iter().map(|t| t.memory_loads).sum();
    assert_eq!(answered, k.memory_loads, "seed {seed:#x}: every host answer reached one PE");
    Ok(k)
}

/// One source per PE.
fn round<M: MachineSim>(
    machine: &mut M,
    seed: u64,
    mem: &[[i32; 4]],
    work: &[(PeSetup, Vec<Command>)],
    tc: u32,
    cache: CacheConfig,
) -> Result<MachineCounters> {
    let pe_of: Vec<usize> = (0..work.len()).collect();
    run_on(machine, seed, mem, work, &pe_of, tc, cache)
}

#[test]
fn each_pe_of_a_machine_traces_its_own_source() -> Result<()> {
    for (seed, n, tc, lines) in
        [(0x3ac1_00u64, 3usize, 1u32, None), (0x3ac1_01, 2, 4, Some(64)), (0x3ac1_02, 4, 2, None)]
    {
        let (mem, work) = sources(seed, n, 96, 120);
        let sims: Vec<Driver<ProcessingElement>> =
            (0..n).map(|_| Driver::new(ProcessingElement::default())).collect::<Result<_>>()?;
        let k = round(&mut Composed::new(sims)?, seed, &mem, &work, tc, CacheConfig { lines })?;
        println!("seed {seed:#x}: {n} PEs, T_c {tc}: {k:?}");
    }
    Ok(())
}

/// The machine's own RTL (`Machine<3>`, rust-hdl), the composition of rust-hdl's PEs and the
/// arbiter's model, and that of the compiled PEs, stepped on one thread and on two: the same
/// hits and the same counters, cycle counts included, round after round (the caches kept
/// between them).
#[test]
fn the_machine_rtl_and_its_compositions_agree() -> Result<()> {
    let seed = 0x3ac1_10;
    let (mem, work) = sources(seed, 3, 64, 80);
    let rtl_pes: Vec<Driver<ProcessingElement>> =
        (0..3).map(|_| Driver::new(ProcessingElement::default())).collect::<Result<_>>()?;
    let fast_pes = || (0..3).map(|_| VerilatedPe::new()).collect::<Result<Vec<_>>>();
    let mut machine = Driver::new(Machine::<3>::default())?;
    let (mut rtl, mut fast) = (Composed::new(rtl_pes)?, Composed::new(fast_pes()?)?);
    let mut threaded = Composed::threaded(fast_pes()?)?;
    assert!(threaded.is_threaded(), "two cores at least (`.ci/run` and this machine have them)");
    for (tc, lines) in [(2, None), (3, Some(16)), (1, Some(16))] {
        let cache = CacheConfig { lines };
        let a = round(&mut machine, seed, &mem, &work, tc, cache)?;
        let b = round(&mut rtl, seed, &mem, &work, tc, cache)?;
        let c = round(&mut fast, seed, &mem, &work, tc, cache)?;
        let d = round(&mut threaded, seed, &mem, &work, tc, cache)?;
        assert_eq!(
            a, b,
            "seed {seed:#x}, T_c {tc}, {cache:?}: the machine's RTL, then rust-hdl's PEs composed"
        );
        assert_eq!(
            b, c,
            "seed {seed:#x}, T_c {tc}, {cache:?}: rust-hdl's PEs composed, then the compiled ones"
        );
        assert_eq!(c, d, "seed {seed:#x}, T_c {tc}, {cache:?}: the compiled PEs on one thread, then on two");
    }
    Ok(())
}

/// With a fast memory the PEs overlap: a round of N sources takes much less than the N
/// sources one after another on one PE. With a slow one (T_c 16, no cache) the host memory is
/// the bound: the round's commands take at least T_c cycles a load.
#[test]
fn pes_work_in_parallel_until_the_host_memory_bounds_them() -> Result<()> {
    let seed = 0x3ac1_20;
    let n = 4;
    let (mem, work) = sources(seed, n, 128, 150);
    for (tc, parallel) in [(1u32, true), (16, false)] {
        let fast: Vec<VerilatedPe> = (0..n).map(|_| VerilatedPe::new()).collect::<Result<_>>()?;
        let k = round(&mut Composed::new(fast)?, seed, &mem, &work, tc, CacheConfig::default())?;
        let mut alone = 0;
        for (setup, cmds) in &work {
            let mut pe = VerilatedPe::new()?;
            flush_cache(&mut pe)?;
            let (_, c) = run(
                &mut pe,
                &mut HostMemory::new(mem.clone(), tc)?,
                setup,
                CacheConfig::default(),
                cmds,
                |_, _| {},
            )?;
            alone += c.setup_cycles + c.cycles + c.readout_cycles;
        }
        println!("T_c {tc}: {n} PEs {} cycles, one PE after another {alone}", k.cycles);
        if parallel {
            assert!(
                k.cycles * 2 < alone,
                "seed {seed:#x}, T_c {tc}: {n} PEs took {} cycles, one PE {alone} for the same sources",
                k.cycles
            );
        } else {
            assert!(
                k.cycles >= k.memory_loads * tc as u64,
                "seed {seed:#x}, T_c {tc}: {} loads in {} cycles",
                k.memory_loads,
                k.cycles
            );
            assert!(k.cycles * 10 < alone * 11, "T_c {tc}: the memory-bound machine no slower than one PE");
        }
    }
    Ok(())
}

#[test]
fn a_machine_refuses_more_pes_than_the_arbiter_serves() -> Result<()> {
    let sims: Vec<VerilatedPe> = (0..9).map(|_| VerilatedPe::new()).collect::<Result<_>>()?;
    let err = Composed::new(sims).err().expect("nine PEs refused");
    assert!(err.message().contains("1 to 8 PEs"), "{}", err.message());
    let (mem, work) = sources(7, 3, 8, 4);
    let mut two = Composed::new((0..2).map(|_| VerilatedPe::new()).collect::<Result<Vec<_>>>()?)?;
    let q = queues(&work, &[0, 1, 2]);
    let err =
        run_queues(&mut two, &mut HostMemory::new(mem, 1)?, CacheConfig::default(), &q, |_| {}).unwrap_err();
    assert!(err.message().contains("2 PEs, 3 queues"), "{}", err.message());
    Ok(())
}

/// A PE whose source ends early waits for the run's longest without being taken for stuck,
/// and a second run on the same memory counts only its own loads.
#[test]
fn a_pe_done_early_is_not_taken_for_stuck() -> Result<()> {
    let seed = 0x3ac1_30;
    let (mem, mut work) = sources(seed, 2, 400, 200);
    work[0].1.truncate(2);
    let tc = 64;
    let mut machine = Composed::new((0..2).map(|_| VerilatedPe::new()).collect::<Result<Vec<_>>>()?)?;
    let mut memory = HostMemory::new(mem.clone(), tc)?;
    for round in 0..2 {
        let k =
            run_queues(&mut machine, &mut memory, CacheConfig::default(), &queues(&work, &[0, 1]), |_| {})?;
        for (p, (setup, cmds)) in work.iter().enumerate() {
            assert_eq!(
                k.pes[p][0].hits,
                model(setup, &mem, cmds).0,
                "seed {seed:#x}, run {round}: PE {p}'s hits"
            );
        }
        let answered: u64 = k.totals.iter().map(|t| t.memory_loads).sum();
        assert_eq!(answered, k.memory_loads, "seed {seed:#x}, run {round}: the run's loads");
        let first = &k.pes[0][0];
        assert!(
            k.cycles > 64 * (tc as u64 * 2 + 64) + first.end,
            "seed {seed:#x}: PE 0 waited only {} cycles after its source's end at {}",
            k.cycles - first.end,
            first.end
        );
    }
    Ok(())
}

/// Each PE runs its own queue without waiting for the others: a PE with short sources reads one
/// out and sets up the next at once, while the other PE is still in its long source's commands, every
/// source's hits are its model's, and the run is shorter than the PEs' queues one after
/// another. Rust-hdl's PEs and the compiled ones composed, and the machine's own RTL, agree,
/// cycles included.
#[test]
fn each_pe_runs_its_queue_without_waiting_for_the_others() -> Result<()> {
    let seed = 0x3ac1_50;
    let (mem, mut work) = sources(seed, 4, 128, 90);
    for (_, cmds) in &mut work[1..] {
        cmds.truncate(cmds.len() / 4);
    }
    // PE 0 the long source, PE 1 the three short ones, then the same on three PEs.
    let pe_of = [0, 1, 1, 1];
    let fast = |n| (0..n).map(|_| VerilatedPe::new()).collect::<Result<Vec<_>>>();
    let slow = |n| (0..n).map(|_| Driver::new(ProcessingElement::default())).collect::<Result<Vec<_>>>();
    let cache = CacheConfig { lines: Some(32) };
    let k = run_on(&mut Composed::new(fast(2)?)?, seed, &mem, &work, &pe_of, 4, cache)?;
    let rtl = run_on(&mut Composed::new(slow(2)?)?, seed, &mem, &work, &pe_of, 4, cache)?;
    assert_eq!(k, rtl, "seed {seed:#x}: the compiled PEs and rust-hdl's");
    let mut machine = Driver::new(Machine::<2>::default())?;
    let own = run_on(&mut machine, seed, &mem, &work, &pe_of, 4, cache)?;
    assert_eq!(k, own, "seed {seed:#x}: the compiled PEs composed and the machine's own RTL");
    let long = &k.pes[0][0];
    let short = &k.pes[1];
    assert!(
        short[1].start < long.end - long.counters.readout_cycles && short[1].end < long.end,
        "seed {seed:#x}: PE 1's second source ({}..{}) did not overlap PE 0's commands (to {})",
        short[1].start,
        short[1].end,
        long.end - long.counters.readout_cycles
    );
    // Overlapped in the two halves: PE 1 writes its second source's directions before its
    // first source's readout, and streams it before that readout ends; each source's readout
    // ends after the next one's directions are written.
    assert!(
        short[1].start < short[0].end - short[0].counters.readout_cycles,
        "seed {seed:#x}: PE 1's second source set up at {} after its first one's readout began at {}",
        short[1].start,
        short[0].end - short[0].counters.readout_cycles
    );
    for w in short.windows(2) {
        assert!(
            w[1].start + w[1].counters.setup_cycles < w[0].end,
            "seed {seed:#x}: PE 1's next source ({}..{}) waited for the last one's readout (to {})",
            w[1].start,
            w[1].end,
            w[0].end
        );
    }
    let serial: u64 = k.pes.iter().flatten().map(|t| t.end - t.start).sum();
    assert!(k.cycles < serial, "seed {seed:#x}: {} cycles, {serial} one after another", k.cycles);
    Ok(())
}

/// Rung 4: a recorded round of the machine's RTL (two PEs, caches on, `T_c` = 2) replayed
/// through its exported Verilog under Verilator, every output before and after every edge.
#[test]
fn the_machine_replays_bit_exactly_under_verilator() -> Result<()> {
    let seed = 0x3ac1_40;
    let (mem, work) = sources(seed, 2, 32, 24);
    let mut machine = Driver::new(Machine::<2>::default())?;
    machine.record_ports()?;
    round(&mut machine, seed, &mem, &work, 2, CacheConfig { lines: Some(16) })?;
    let rec = machine.take_recording().ok_or("recording was on")?;
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join("machine_verilator");
    let report = rec.replay(machine.uut(), &dir, Simulator::Verilator)?;
    println!("{report}");
    assert_eq!(report.cycles, rec.cycles());
    assert!(report.cycles > 200, "seed {seed:#x}: only {} cycles recorded", report.cycles);
    Ok(())
}

/// The machine's cache settings reach each PE through its own register, taken while the PE was
/// idle in the clock before: a flush raised for one clock on the machine's port makes every
/// idle PE busy two clocks later for the cache's [`LINES`] clocks, in the RTL and in the
/// composition alike.
#[test]
fn a_flush_reaches_every_pe_through_its_own_register() -> Result<()> {
    use shelling_hdl::cache::LINES;
    fn trace<M: MachineSim>(m: &mut M) -> Result<Vec<Vec<bool>>> {
        let mut busy = Vec::new();
        for cycle in 0..LINES + 8 {
            m.drive(|_, i| {
                i.cfg_cache_enable = true;
                i.cfg_cache_mask = (LINES - 1) as u16;
                i.cfg_cache_flush = cycle == 3;
            })?;
            busy.push((0..m.pes()).map(|p| m.outputs(p).busy).collect());
            m.tick(None)?;
        }
        Ok(busy)
    }
    let rtl = trace(&mut Driver::new(Machine::<2>::default())?)?;
    let pes = (0..2).map(|_| Driver::new(ProcessingElement::default())).collect::<Result<Vec<_>>>()?;
    let composed = trace(&mut Composed::new(pes)?)?;
    assert_eq!(rtl, composed, "the machine's RTL, then its composition");
    for (cycle, busy) in rtl.iter().enumerate() {
        let want = (5..5 + LINES).contains(&cycle);
        assert_eq!(busy, &vec![want; 2], "cycle {cycle}: the flush raised in cycle 3");
    }
    Ok(())
}
