//! The processing element, rungs 3 and 4: random command streams (sectors, jobs, retirements)
//! against the bit-true model under several host memory latencies, the stream-order semantics
//! of retirements, its exported Verilog replayed under Icarus Verilog, and the compiled PE
//! (Verilator) against rust-hdl's simulation, port by port and source by source. Every failure
//! names its seed.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use shelling_hdl::cache::LINES;
use shelling_hdl::formats::{direction, Quantizer};
use shelling_hdl::pe::ProcessingElement;
use shelling_testbench::memory::HostMemory;
use shelling_testbench::pe::{flush_cache, model, run, CacheConfig, Command, PeCounters, PeSetup};
use shelling_testbench::pe_sim::PeInputs;
use shelling_testbench::verilated::VerilatedPe;
use shelling_testbench::{Driver, Error, PeSim, Result, Scoreboard, Simulator};
use std::path::PathBuf;

/// A source with `rays` rays over its half-circle and `patches` random patches around it.
fn scene(rng: &mut ChaCha8Rng, rays: usize, patches: usize) -> (PeSetup, Vec<[i32; 4]>) {
    let q = Quantizer { offset: [0.0, 0.0] };
    let o = [rng.random_range(300.0..1700.0), rng.random_range(300.0..1700.0)];
    let phi: f64 = rng.random_range(0.0..std::f64::consts::TAU);
    let dirs = (0..rays)
        .map(|i| {
            let a = phi - std::f64::consts::FRAC_PI_2 + (i as f64 + 0.5) * std::f64::consts::PI / rays as f64;
            direction(|| "ray".into(), [a.cos(), a.sin()]).expect("unit vector")
        })
        .collect();
    let setup = PeSetup {
        origin: q.point(|| "origin".into(), o).expect("in range"),
        normal: direction(|| "normal".into(), [phi.cos(), phi.sin()]).expect("unit"),
        dirs,
    };
    // Mostly in front of the source and facing it (the screener passes most), some not.
    let patches = (0..patches)
        .map(|k| {
            let (r, th): (f64, f64) = (rng.random_range(2.0..250.0), rng.random_range(-1.5..1.5));
            let th = if k % 5 == 0 { th + std::f64::consts::PI } else { th };
            let c = [o[0] + r * (phi + th).cos(), o[1] + r * (phi + th).sin()];
            let len: f64 = rng.random_range(0.5..80.0);
            let t: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            let a = q.point(|| "a".into(), [c[0] - len * t.cos(), c[1] - len * t.sin()]).expect("in range");
            let b = q.point(|| "b".into(), [c[0] + len * t.cos(), c[1] + len * t.sin()]).expect("in range");
            let (oq, rel) = (setup_origin(&q, o), |p: [i32; 2], o: [i32; 2]| [p[0] - o[0], p[1] - o[1]]);
            let (ra, rb) = (rel(a, oq), rel(b, oq));
            let facing = (ra[0] as i64 * rb[1] as i64 - ra[1] as i64 * rb[0] as i64) > 0;
            if facing || k % 7 == 0 {
                [a[0], a[1], b[0], b[1]]
            } else {
                [b[0], b[1], a[0], a[1]]
            }
        })
        .collect();
    (setup, patches)
}

fn setup_origin(q: &Quantizer, o: [f64; 2]) -> [i32; 2] {
    q.point(|| "origin".into(), o).expect("in range")
}

/// Sectors over the rays in order, each with jobs over ranges inside it and a few retirements.
fn commands(rng: &mut ChaCha8Rng, setup: &PeSetup, patches: usize, jobs_per_sector: usize) -> Vec<Command> {
    sectors_of(rng, setup, patches, jobs_per_sector, 128)
}

/// [`commands`] with sectors of 1 to `widest` rays.
fn sectors_of(
    rng: &mut ChaCha8Rng,
    setup: &PeSetup,
    patches: usize,
    jobs_per_sector: usize,
    widest: usize,
) -> Vec<Command> {
    let n = setup.dirs.len();
    let mut out = Vec::new();
    let mut s = 0;
    while s < n {
        let e = (s + rng.random_range(1..=widest)).min(n);
        out.push(Command::Sector { first: setup.dirs[s], last: setup.dirs[e - 1] });
        for _ in 0..jobs_per_sector {
            if rng.random_range(0..6) == 0 {
                let first = rng.random_range(s..e);
                let count = rng.random_range(0..=(e - first).min(4));
                out.push(Command::Retire { first: first as u16, count: count as u16 });
            }
            let first = rng.random_range(s..e);
            let count = rng.random_range(0..=e - first);
            out.push(Command::Job {
                id: rng.random_range(0..patches) as u16,
                first: first as u16,
                count: count as u16,
            });
        }
        s = e;
    }
    out
}

/// A random source and stream (sectors of up to `widest` rays) on rust-hdl's PE against the
/// model: hits and counters.
#[allow(clippy::too_many_arguments)]
fn check(
    name: &str,
    seed: u64,
    rays: usize,
    patches: usize,
    jobs_per_sector: usize,
    widest: usize,
    tc: u32,
    cache: CacheConfig,
) -> Result<(u64, PeCounters)> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (setup, mem) = scene(&mut rng, rays, patches);
    let cmds = sectors_of(&mut rng, &setup, patches, jobs_per_sector, widest);
    let (want, counts) = model(&setup, &mem, &cmds);
    let mut memory = HostMemory::new(mem, tc)?;
    let mut drv = Driver::new(ProcessingElement::default())?;
    let (hits, k) = run(&mut drv, &mut memory, &setup, cache, &cmds, |_, _| {})?;
    if cache.lines.is_some_and(|n| n >= 64) && k.cache_hits == 0 {
        return Err(Error::new(format!("{name} seed {seed:#x}: the cache never hit")));
    }
    let context = format!("T_c {tc}, {cache:?}");
    let mut board = Scoreboard::new(name, seed, want).with_context(context);
    board.check_all(hits.into_iter().enumerate().map(|(i, h)| (i as u64, h)))?;
    board.finish()?;
    let pairs = [
        ("loads", k.patch_loads, counts.loads),
        ("passed", k.passed, counts.passed),
        ("tests", k.tests, counts.tests),
    ];
    for (what, hw, m) in pairs {
        if hw != m {
            return Err(Error::new(format!("{name} seed {seed:#x} T_c {tc}: {what}: PE {hw}, model {m}")));
        }
    }
    if counts.tests == 0 || counts.passed == 0 || counts.passed == counts.loads {
        return Err(Error::new(format!("{name} seed {seed:#x}: a degenerate stream {counts:?}")));
    }
    println!("{name} seed {seed:#x} T_c {tc}: {counts:?}, {k:?}");
    Ok((counts.tests, k))
}

#[test]
fn random_streams_match_the_model() -> Result<()> {
    let mut tests = 0;
    let caches = [None, Some(1), Some(64), Some(LINES as u32)];
    for (k, (tc, lines)) in [1u32, 4, 16].into_iter().flat_map(|t| caches.map(|c| (t, c))).enumerate() {
        let seed = 0x9e00 + k as u64;
        let (t, c) = check("random streams", seed, 256, 300, 64, 128, tc, CacheConfig { lines })?;
        tests += t;
        // Sectors of 64 jobs: the new sector's bank is free long before it is needed.
        assert_eq!(c.drain_cycles, 0, "seed {seed:#x}: the stream waited on a sector: {c:?}");
    }
    assert!(tests >= 10_000, "only {tests} ray-patch tests");
    Ok(())
}

/// Sectors of one or two jobs, shorter than the loader and the screener hold: a sector
/// command finds the bank it takes still in use by the sector before last, and must wait for
/// its jobs to pass the screener's sector read (a job screened for the wrong sector changes
/// verdicts, and the model sees it).
#[test]
fn sectors_shorter_than_the_pipeline_wait_for_their_bank() -> Result<()> {
    let mut waited = 0;
    for (k, (tc, lines)) in [(16u32, None), (4, None), (1, Some(64)), (30, Some(16))].into_iter().enumerate()
    {
        let seed = 0x5ec7_00 + k as u64;
        let (_, c) = check("short sectors", seed, 512, 300, 2, 8, tc, CacheConfig { lines })?;
        waited += c.drain_cycles;
    }
    assert!(waited > 100, "the sector commands hardly waited ({waited} cycles): the case is not exercised");
    Ok(())
}

#[test]
fn one_ray_jobs_and_back_to_back_retirements() -> Result<()> {
    // The conventional technique's shape: one sector, one-ray jobs; then retirements of the
    // ray a job is about to test, back to back.
    let mut rng = ChaCha8Rng::seed_from_u64(0x0e1);
    let (setup, mem) = scene(&mut rng, 32, 64);
    let mut cmds = vec![Command::Sector { first: setup.dirs[0], last: setup.dirs[31] }];
    for i in 0..400 {
        let r = (i * 7 % 32) as u16;
        cmds.push(Command::Job { id: (i % 64) as u16, first: r, count: 1 });
        if i % 50 == 49 {
            cmds.push(Command::Retire { first: r, count: 1 });
            cmds.push(Command::Job { id: 5, first: r, count: 1 });
        }
    }
    let (want, counts) = model(&setup, &mem, &cmds);
    for (tc, lines) in [(1, None), (3, None), (3, Some(16))] {
        let cache = CacheConfig { lines };
        let mut memory = HostMemory::new(mem.clone(), tc)?;
        let mut drv = Driver::new(ProcessingElement::default())?;
        let (hits, k) = run(&mut drv, &mut memory, &setup, cache, &cmds, |_, _| {})?;
        let mut board =
            Scoreboard::new("one-ray jobs", 0x0e1, want.clone()).with_context(format!("T_c {tc}"));
        board.check_all(hits.into_iter().enumerate().map(|(i, h)| (i as u64, h)))?;
        board.finish()?;
        assert_eq!((k.tests, k.patch_loads), (counts.tests, counts.loads), "T_c {tc}");
        // One patch per T_c from the host memory bounds the run from below.
        assert!(k.cycles >= counts.loads * tc as u64, "T_c {tc}: {k:?}");
        // The same source again on the same PE (after the readout cleared it): the same hits,
        // and counters that count this run only.
        let mut memory = HostMemory::new(mem.clone(), tc)?;
        let (again, k2) = run(&mut drv, &mut memory, &setup, cache, &cmds, |_, _| {})?;
        assert_eq!(again, want, "T_c {tc}: a second run");
        assert_eq!((k2.tests, k2.patch_loads, k2.passed), (k.tests, k.patch_loads, k.passed), "T_c {tc}");
    }
    Ok(())
}

#[test]
fn exported_verilog_reproduces_the_simulation() -> Result<()> {
    let seed = 0x5eed_0e;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (setup, mem) = scene(&mut rng, 48, 40);
    let cmds = commands(&mut rng, &setup, 40, 4);
    let mut memory = HostMemory::new(mem, 3)?;
    let cache = CacheConfig { lines: Some(16) };
    let mut drv = Driver::new(ProcessingElement::default())?;
    drv.record_ports()?;
    run(&mut drv, &mut memory, &setup, cache, &cmds, |_, _| {})?;
    let rec = drv.take_recording().ok_or("recording was on")?;
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join("pe");
    let report =
        rec.replay(drv.uut(), &dir, Simulator::Icarus).map_err(|e| e.context(format!("seed {seed:#x}")))?;
    println!("{report:?}");
    Ok(())
}

#[test]
fn a_cache_flush_forgets_the_last_scene() -> Result<()> {
    let seed = 0xf1u64;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (setup, scene_a) = scene(&mut rng, 32, 40);
    let cmds = commands(&mut rng, &setup, 40, 4);
    // Scene B: the same patches under other ids.
    let scene_b: Vec<[i32; 4]> = scene_a.iter().rev().copied().collect();
    let (want_b, counts) = model(&setup, &scene_b, &cmds);
    let cache = CacheConfig { lines: Some(64) };
    let mut drv = Driver::new(ProcessingElement::default())?;
    run(&mut drv, &mut HostMemory::new(scene_a, 2)?, &setup, cache, &cmds, |_, _| {})?;
    // Without a flush, B's ids hit A's lines: wrong patches (so this test can tell).
    let (stale, _) =
        run(&mut drv, &mut HostMemory::new(scene_b.clone(), 2)?, &setup, cache, &cmds, |_, _| {})?;
    assert_ne!(stale, want_b, "seed {seed:#x}: the stale cache went unnoticed");
    // The flush: one cycle to raise it, then one cycle per line with `busy` high.
    assert_eq!(flush_cache(&mut drv)?, LINES as u64 + 1, "seed {seed:#x}");
    let mut memory = HostMemory::new(scene_b, 2)?;
    let (fresh, k) = run(&mut drv, &mut memory, &setup, cache, &cmds, |_, _| {})?;
    let mut board = Scoreboard::new("after a flush", seed, want_b).with_context("cache on, T_c 2");
    board.check_all(fresh.into_iter().enumerate().map(|(i, h)| (i as u64, h)))?;
    board.finish()?;
    // Every id's first load after the flush misses.
    let mut ids = cmds.iter().filter_map(Command::job_id).collect::<Vec<_>>();
    ids.sort_unstable();
    ids.dedup();
    assert!(k.memory_loads >= ids.len() as u64, "seed {seed:#x}: {k:?}");
    assert_eq!(k.memory_loads + k.cache_hits, counts.loads, "seed {seed:#x}");
    Ok(())
}

/// Both simulators of the PE under the same random inputs, every input changing at random
/// (protocol or not) for 20k cycles, the cache flushed now and then: every output must agree on
/// every cycle, before and after each rising edge.
#[test]
fn the_compiled_pe_agrees_with_rust_hdl_port_by_port() -> Result<()> {
    let seed = 0xc0_3e11u64;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut rtl = Driver::new(ProcessingElement::default())?;
    let mut fast = VerilatedPe::new()?;
    let mut busy_cycles = 0;
    for cycle in 0..20_000u64 {
        let mut i = PeInputs::default();
        let (w, d) =
            (|rng: &mut ChaCha8Rng, bits: u32| rng.random_range(0..1u64 << bits), rng.random_range(0..4));
        // Long runs of one kind of traffic, so the pipelines fill.
        let phase = (cycle / 1000) % 4;
        i.dir_we = phase == 0 && d != 0;
        i.dir_addr = w(&mut rng, 11) as u16;
        [i.dir_x, i.dir_y] = [rng.random_range(-65536..65536), rng.random_range(-65536..65536)];
        [i.origin_x, i.origin_y] = [rng.random_range(-65536..65536), rng.random_range(-65536..65536)];
        for v in
            [&mut i.normal_x, &mut i.normal_y, &mut i.first_x, &mut i.first_y, &mut i.last_x, &mut i.last_y]
        {
            *v = rng.random_range(-131072..131072);
        }
        i.cmd_valid = phase != 0 && d != 0;
        i.cmd_retire = d == 3;
        // Sector commands late only, and the first command of all (the source's origin and
        // normal, taken with it): a stream that breaks the memory protocol can leave a bank's
        // job count above zero for ever, and a sector then waits for ever.
        i.cmd_sector = cycle >= 16_000 && rng.random_range(0..8) == 0;
        if cycle == 1000 {
            (i.cmd_valid, i.cmd_sector) = (true, true);
        }
        i.cmd_id = w(&mut rng, 16) as u16;
        i.cmd_first = w(&mut rng, 11) as u16;
        i.cmd_count = w(&mut rng, 6) as u16;
        i.cfg_cache_enable = phase >= 2;
        i.cfg_cache_mask = (1u16 << rng.random_range(0..13)) - 1;
        i.cfg_cache_flush = cycle % 5000 == 4999;
        i.mem_valid = rng.random_range(0..3) == 0;
        for v in [&mut i.mem_ax, &mut i.mem_ay, &mut i.mem_bx, &mut i.mem_by] {
            *v = rng.random_range(-65536..65536);
        }
        i.res_re = phase == 3 && d == 0;
        i.res_addr = w(&mut rng, 11) as u16;
        for (edge, f) in [("before", false), ("after", true)] {
            if f {
                rtl.tick()?;
                fast.tick()?;
            } else {
                PeSim::drive(&mut rtl, |x| *x = i)?;
                fast.drive(|x| *x = i)?;
            }
            let (a, b) = (PeSim::outputs(&rtl), fast.outputs());
            if a != b {
                return Err(Error::new(format!(
                    "seed {seed:#x}: cycle {cycle}, {edge} the rising edge: rust-hdl {a:?}, compiled {b:?}; inputs {i:?}"
                )));
            }
        }
        busy_cycles += PeSim::outputs(&rtl).busy as u64;
    }
    let o = fast.outputs();
    println!("seed {seed:#x}: {o:?}, busy {busy_cycles} cycles");
    assert!(o.tests > 200 && o.loads > 1000 && o.passed > 50 && busy_cycles > 5000, "seed {seed:#x}: {o:?}");
    Ok(())
}

/// Whole sources through the host loop on both simulators: the same hits and the same
/// counters, cycles included, with the cache off and on.
#[test]
fn the_compiled_pe_runs_whole_sources_cycle_for_cycle() -> Result<()> {
    let mut fast = VerilatedPe::new()?;
    let mut tests = 0;
    for (k, (tc, lines)) in
        [(1u32, None), (4, Some(64)), (16, None), (3, Some(LINES as u32))].into_iter().enumerate()
    {
        let seed = 0xfa57_00 + k as u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let (setup, mem) = scene(&mut rng, 256, 300);
        let cmds = commands(&mut rng, &setup, 300, 96);
        let cache = CacheConfig { lines };
        let (want, _) = model(&setup, &mem, &cmds);
        let mut rtl = Driver::new(ProcessingElement::default())?;
        let a = run(&mut rtl, &mut HostMemory::new(mem.clone(), tc)?, &setup, cache, &cmds, |_, _| {})?;
        // The compiled PE runs source after source without a power-up: flush between.
        flush_cache(&mut fast)?;
        let b = run(&mut fast, &mut HostMemory::new(mem, tc)?, &setup, cache, &cmds, |_, _| {})?;
        assert_eq!(a.0, want, "seed {seed:#x}: rust-hdl against the model");
        assert_eq!(b.0, want, "seed {seed:#x}: compiled against the model");
        assert_eq!(
            a.1, b.1,
            "seed {seed:#x}: T_c {tc}, {cache:?}: rust-hdl's counters, then the compiled PE's"
        );
        tests += a.1.tests;
    }
    assert!(tests > 4000, "only {tests} ray-patch tests");
    Ok(())
}
