//! The processing element, rungs 3 and 4: random command streams (sectors, jobs, retirements)
//! against the bit-true model under several host memory latencies, the stream-order semantics
//! of retirements, and its exported Verilog replayed under Icarus Verilog. Every failure names
//! its seed.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use shelling_hdl::cache::LINES;
use shelling_hdl::formats::{direction, Quantizer};
use shelling_hdl::pe::ProcessingElement;
use shelling_testbench::memory::HostMemory;
use shelling_testbench::pe::{flush_cache, model, run, CacheConfig, Command, PeSetup};
use shelling_testbench::{Driver, Error, Result, Scoreboard, Simulator};
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
    let n = setup.dirs.len();
    let mut out = Vec::new();
    let mut s = 0;
    while s < n {
        let e = (s + rng.random_range(1..=128)).min(n);
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

fn check(
    name: &str,
    seed: u64,
    rays: usize,
    patches: usize,
    jobs_per_sector: usize,
    tc: u32,
    cache: CacheConfig,
) -> Result<u64> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (setup, mem) = scene(&mut rng, rays, patches);
    let cmds = commands(&mut rng, &setup, patches, jobs_per_sector);
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
    Ok(counts.tests)
}

#[test]
fn random_streams_match_the_model() -> Result<()> {
    let mut tests = 0;
    let caches = [None, Some(1), Some(64), Some(4096)];
    for (k, (tc, lines)) in [1u32, 4, 16].into_iter().flat_map(|t| caches.map(|c| (t, c))).enumerate() {
        tests += check("random streams", 0x9e00 + k as u64, 256, 300, 64, tc, CacheConfig { lines })?;
    }
    assert!(tests >= 10_000, "only {tests} ray-patch tests");
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
    let mut ids = cmds
        .iter()
        .filter_map(|c| if let Command::Job { id, .. } = c { Some(*id) } else { None })
        .collect::<Vec<_>>();
    ids.sort_unstable();
    ids.dedup();
    assert!(k.memory_loads >= ids.len() as u64, "seed {seed:#x}: {k:?}");
    assert_eq!(k.memory_loads + k.cache_hits, counts.loads, "seed {seed:#x}");
    Ok(())
}
