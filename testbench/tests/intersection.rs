//! The intersection unit, rungs 3 and 4: its rust-hdl simulation equals the bit-true model on
//! seeded random ray-patch vectors and corner cases, under random idle cycles on the patch
//! stream; its exported Verilog reproduces the simulation under Icarus Verilog.
//!
//! The unit has no output stream (results are read from the ray memory when it is idle), so
//! backpressure is the unit's own: `patch_ready` falls while a patch sweeps its rays. Every test
//! prints its seed on failure.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rust_hdl::prelude::*;
use shelling_hdl::formats::PatchSetup;
use shelling_hdl::formats::{direction, Quantizer};
use shelling_hdl::intersection::IntersectionUnit;
use shelling_hdl::prim::BramOut;
use shelling_hdl::screener::model::{screen, BundleSetup, Patch, Verdict};
use shelling_testbench::intersection::{
    load_directions, model_bundle, model_bundle_counted, run_bundle, run_overlapped, stream_jobs, Job,
    RayBench, MAX_BUNDLE,
};
use shelling_testbench::{waveform_path, Design, Driver, Error, Pacing, Result, Scoreboard, Simulator};
use std::path::PathBuf;

fn driver() -> Result<Driver<IntersectionUnit>> {
    Driver::new(IntersectionUnit::default())
}

/// Runs one bundle on a fresh unit and checks every ray against the model.
fn check(name: &str, dirs: &[[i32; 2]], jobs: &[Job], pacing: Pacing, seed: u64) -> Result<u64> {
    let mut drv = driver()?;
    let (hits, cycles) = run_bundle(&mut drv, dirs, jobs, pacing, seed)?;
    let mut board = Scoreboard::new(name, seed, model_bundle(dirs, jobs)).with_context(pacing.to_string());
    board.check_all(hits.into_iter().enumerate().map(|(i, h)| (i as u64, h)))?;
    board.finish()?;
    let tests = model_bundle_counted(dirs, jobs).1;
    if drv.uut().tests.val().to_u64() != tests {
        return Err(Error::new(format!(
            "{name}: tests counter {} != {tests}",
            drv.uut().tests.val().to_u64()
        )));
    }
    Ok(cycles)
}

fn raw(rng: &mut ChaCha8Rng, bits: u32) -> i32 {
    rng.random_range(-(1i32 << (bits - 1))..(1i32 << (bits - 1)))
}

/// A patch with arbitrary 18-bit fields: exercises every datapath bit, wrap-around included.
fn raw_patch(rng: &mut ChaCha8Rng, id: u16) -> PatchSetup {
    PatchSetup {
        id,
        a: [raw(rng, 18), raw(rng, 18)],
        b: [raw(rng, 18), raw(rng, 18)],
        w: [raw(rng, 18), raw(rng, 18)],
        sh: rng.random_range(-3..=31),
    }
}

fn unit_dir(rng: &mut ChaCha8Rng) -> [i32; 2] {
    let phi: f64 = rng.random_range(0.0..std::f64::consts::TAU);
    direction(|| "ray".into(), [phi.cos(), phi.sin()]).expect("unit vector")
}

/// Realistic patches: random segments of a 2048-unit window screened by the screener's model.
fn scene_bundle(rng: &mut ChaCha8Rng, rays: usize, patches: usize) -> (Vec<[i32; 2]>, Vec<Job>) {
    let q = Quantizer { offset: [0.0, 0.0] };
    let o = [rng.random_range(200.0..1800.0), rng.random_range(200.0..1800.0)];
    let phi: f64 = rng.random_range(0.0..std::f64::consts::TAU);
    let n = [phi.cos(), phi.sin()];
    let dirs: Vec<[i32; 2]> = (0..rays)
        .map(|i| {
            let a = phi - std::f64::consts::FRAC_PI_2 + (i as f64 + 0.5) * std::f64::consts::PI / rays as f64;
            direction(|| "ray".into(), [a.cos(), a.sin()]).expect("unit vector")
        })
        .collect();
    let setup = BundleSetup {
        origin: q.point(|| "origin".into(), o).expect("in range"),
        normal: direction(|| "normal".into(), n).expect("unit"),
        first: dirs[0],
        last: dirs[rays - 1],
    };
    let mut jobs = Vec::new();
    let mut id = 0u16;
    while jobs.len() < patches {
        let c = [o[0] + rng.random_range(-150.0..150.0), o[1] + rng.random_range(-150.0..150.0)];
        let len: f64 = rng.random_range(0.05..64.0);
        let t: f64 = rng.random_range(0.0..std::f64::consts::TAU);
        let a = q.point(|| "a".into(), [c[0] - len * t.cos(), c[1] - len * t.sin()]).expect("in range");
        let b = q.point(|| "b".into(), [c[0] + len * t.cos(), c[1] + len * t.sin()]).expect("in range");
        if let Verdict::Pass(p) = screen(&setup, &Patch { id, a, b }) {
            let first = rng.random_range(0..rays) as u16;
            let count = rng.random_range(0..=rays) as u16;
            jobs.push(Job::test(p, first, count));
            if rng.random_range(0..12) == 0 {
                // Tracking: a few rays leave the bundle.
                jobs.push(Job::retire(rng.random_range(0..rays) as u16, rng.random_range(0..8)));
            }
        }
        id = id.wrapping_add(1);
    }
    (dirs, jobs)
}

#[test]
fn random_vectors_match_the_model_bit_for_bit() -> Result<()> {
    // 100 000+ ray-patch tests: raw 18-bit fields and realistic screened patches, both pacings.
    let mut total = 0u64;
    for (k, pacing) in [Pacing::NONE, Pacing { idle: true, backpressure: false }].into_iter().enumerate() {
        let seed = 0x1ee7_0000 + k as u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let dirs: Vec<[i32; 2]> = (0..128)
            .map(|i| if i % 2 == 0 { unit_dir(&mut rng) } else { [raw(&mut rng, 18), raw(&mut rng, 18)] })
            .collect();
        let jobs: Vec<Job> = (0..800)
            .map(|i| {
                let id = rng.random();
                Job::test(raw_patch(&mut rng, id), (i * 13 % 64) as u16, 64)
            })
            .collect();
        check("raw vectors", &dirs, &jobs, pacing, seed).map_err(|e| e.context(format!("seed {seed:#x}")))?;
        total += model_bundle_counted(&dirs, &jobs).1;
        let (dirs, jobs) = scene_bundle(&mut rng, 256, 200);
        check("scene vectors", &dirs, &jobs, pacing, seed)
            .map_err(|e| e.context(format!("seed {seed:#x}")))?;
        total += model_bundle_counted(&dirs, &jobs).1;
    }
    assert!(total >= 100_000, "only {total} vectors");
    Ok(())
}

#[test]
fn corner_cases() -> Result<()> {
    let seed = 7;
    let e = 1 << 16;
    let (lo, hi) = (-(1 << 17), (1 << 17) - 1);
    // Rays along +x, +y, -x, the diagonal, and the extreme raw values.
    let dirs = vec![[e, 0], [0, e], [-e, 0], [46341, 46341], [lo, lo], [hi, hi], [lo, hi], [0, 0], [0, e]];
    let w = [1 << 16, 0];
    let patch = |id, a: [i32; 2], b: [i32; 2], sh| PatchSetup { id, a, b, w, sh };
    let jobs = vec![
        // Endpoint exactly on the +x ray (side value 0) on either end: both hit.
        Job::test(patch(3, [640, 0], [640, 640], 0), 0, 8),
        Job::test(patch(2, [640, -640], [640, 0], 0), 0, 8),
        // A patch parallel to the +x ray on its line: both side values 0, hit by the model's rule.
        Job::test(patch(9, [64, 0], [128, 0], 5), 0, 1),
        // Equal keys: the lower id wins, whichever comes first.
        Job::test(patch(7, [640, -640], [640, 640], 0), 0, 8),
        Job::test(patch(5, [640, -640], [640, 640], 0), 0, 8),
        // Extreme coordinates and exponents, saturating keys.
        Job::test(PatchSetup { id: 0xffff, a: [hi, lo], b: [hi, hi], w: [hi, hi], sh: -3 }, 0, 8),
        Job::test(PatchSetup { id: 1, a: [lo, lo], b: [lo, hi], w: [lo, lo], sh: -2 }, 0, 8),
        Job::test(PatchSetup { id: 4, a: [hi, lo], b: [hi, hi], w: [hi, 0], sh: 31 }, 0, 8),
        // Zero-length bundles, back to back.
        Job::test(patch(11, [640, -640], [640, 640], 0), 3, 0),
        Job::test(patch(12, [640, -640], [640, 640], 0), 5, 0),
        // One-ray bundles on ray 8 (no other job touches it), back to back: the read-modify-write
        // hazard. Equal keys, so the lowest id (19) must survive the later, higher ones.
        Job::test(PatchSetup { id: 19, a: [64, 64], b: [-64, 64], w: [0, 1 << 16], sh: 3 }, 8, 1),
        Job::test(PatchSetup { id: 21, a: [64, 32], b: [-64, 32], w: [0, 1 << 16], sh: 3 }, 8, 1),
        Job::test(PatchSetup { id: 20, a: [64, 16], b: [-64, 16], w: [0, 1 << 16], sh: 3 }, 8, 1),
        Job::test(PatchSetup { id: 22, a: [64, 16], b: [-64, 16], w: [0, 1 << 16], sh: 3 }, 8, 1),
        // Two- and three-ray bundles wrapping around the end of the ray memory.
        Job::test(patch(30, [8, -8], [8, 8], 0), (MAX_BUNDLE - 1) as u16, 2),
        Job::test(patch(31, [8, -8], [8, 8], 0), (MAX_BUNDLE - 1) as u16, 3),
    ];
    for pacing in [Pacing::NONE, Pacing { idle: true, backpressure: false }] {
        check("corner cases", &dirs, &jobs, pacing, seed)?;
    }
    // One-ray jobs on one ray, hundreds in a row, random patches: the hazard under load.
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let dirs: Vec<[i32; 2]> = (0..4).map(|_| unit_dir(&mut rng)).collect();
    let jobs: Vec<Job> =
        (0..600).map(|i| Job::test(raw_patch(&mut rng, (i % 97) as u16), (i / 200) as u16, 1)).collect();
    check("one-ray bundles", &dirs, &jobs, Pacing::NONE, seed)?;
    let updates = model_bundle(&dirs, &jobs).iter().flatten().count();
    assert!(updates > 0, "the one-ray run never hit");
    Ok(())
}

#[test]
fn retired_rays_are_neither_tested_nor_updated() -> Result<()> {
    let e = 1 << 16;
    let dirs = vec![[e, 0]; 8];
    let w = [1 << 16, 0];
    let wall = |id, x: i32| PatchSetup { id, a: [x, -640], b: [x, 640], w: [w[0] * 64 / x, 0], sh: 0 };
    let jobs = vec![
        Job::test(wall(1, 640), 0, 8),
        Job::retire(2, 2),
        // Nearer: would replace every ray's hit, but rays 2 and 3 have left.
        Job::test(wall(2, 320), 0, 8),
        // Retire then test the same ray on the next clock (the live bit's write-then-read).
        Job::retire(5, 1),
        Job::test(wall(3, 160), 5, 1),
        // Rays beyond the written directions are dead; a retire wraps around the ray memory.
        Job::test(wall(4, 80), 6, 8),
        Job::retire((MAX_BUNDLE - 1) as u16, 2),
        Job::test(wall(5, 40), 0, 1),
    ];
    let (hits, tests) = model_bundle_counted(&dirs, &jobs);
    let ids: Vec<Option<u16>> = hits.iter().map(|h| h.map(|n| n.id)).collect();
    assert_eq!(
        ids[..8],
        [Some(2), Some(2), Some(1), Some(1), Some(2), Some(2), Some(4), Some(4)],
        "the model's reading of the stream"
    );
    assert_eq!(tests, 8 + 6 + 0 + 2 + 0);
    for pacing in [Pacing::NONE, Pacing { idle: true, backpressure: false }] {
        check("retired rays", &dirs, &jobs, pacing, 21)?;
    }
    Ok(())
}

/// Runs `bundles` overlapped in the two halves of a fresh unit ([`run_overlapped`]) and checks
/// every bundle's rays and the tests counter against the model; returns the unit and the cycles.
fn check_overlapped(
    name: &str,
    bundles: &[(Vec<[i32; 2]>, Vec<Job>)],
    seed: u64,
    record: bool,
) -> Result<(Driver<IntersectionUnit>, u64)> {
    let mut drv = driver()?;
    if record {
        drv.record_ports()?;
    }
    let (hits, cycles) = run_overlapped(&mut drv, bundles)?;
    let mut tests = 0;
    for (b, ((dirs, jobs), hits)) in bundles.iter().zip(hits).enumerate() {
        let mut board =
            Scoreboard::new(name, seed, model_bundle(dirs, jobs)).with_context(format!("bundle {b}"));
        board.check_all(hits.into_iter().enumerate().map(|(i, h)| (i as u64, h)))?;
        board.finish()?;
        tests += model_bundle_counted(dirs, jobs).1;
    }
    let counted = drv.uut().tests.val().to_u64();
    if counted != tests {
        return Err(Error::new(format!("{name}: tests counter {counted} != {tests} (seed {seed:#x})")));
    }
    let marks = drv.uut().marks.val().to_u64();
    if marks != bundles.len() as u64 {
        return Err(Error::new(format!("{name}: {marks} markers counted of {}", bundles.len())));
    }
    Ok((drv, cycles))
}

#[test]
fn bundles_overlap_in_the_two_halves_of_the_ray_memory() -> Result<()> {
    // Five bundles, each in the half its number's parity names: a bundle's readout and the
    // directions of the one after next run beside the next one's tests. Replayed on the
    // exported Verilog (rungs 4 and 5).
    let seed = 0x0ba1f;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    // Every job within its bundle's rays, as a PE's host sends them: the rays beyond keep the
    // live bits of the half's earlier bundles.
    let bundles: Vec<_> = (0..5)
        .map(|b| {
            let rays = [96, 40, 128, 64, 80][b];
            let (dirs, jobs) = scene_bundle(&mut rng, rays, 40);
            let jobs =
                jobs.into_iter().map(|j| Job { count: j.count.min((rays - j.first as usize) as u16), ..j });
            (dirs, jobs.collect())
        })
        .collect();
    let (mut drv, cycles) = check_overlapped("overlapped bundles", &bundles, seed, true)?;
    // Overlapped, the run costs about the jobs' ray slots, not the directions and readouts too.
    let slots: u64 = bundles.iter().flat_map(|(_, j)| j).map(|j| j.count as u64 + 1).sum();
    let host: u64 =
        bundles.iter().map(|(d, j)| 2 * shelling_testbench::intersection::rays_touched(d, j) as u64).sum();
    assert!(cycles < slots + host / 2 + 200, "{cycles} cycles for {slots} slots and {host} host cycles");
    let rec = drv.take_recording().ok_or("recording was on")?;
    for (design, simulator, name) in [
        (Design::Rtl, Simulator::Icarus, "intersection_unit-overlapped"),
        (Design::Rtl, Simulator::Verilator, "intersection_unit-overlapped-verilator"),
        (Design::Gates, Simulator::Icarus, "intersection_unit-overlapped-gates"),
    ] {
        let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join(name);
        let report = rec
            .replay_netlist(drv.uut(), &dir, design, simulator)
            .map_err(|e| e.context(format!("seed {seed:#x}")))?;
        assert_eq!(report.cycles, rec.cycles());
    }
    Ok(())
}

#[test]
fn a_half_is_read_out_only_after_its_last_write() -> Result<()> {
    // The last job of bundle 0 writes ray 0, the first ray its readout reads, as soon as the
    // marker behind it is counted: a marker counted a clock early reads the ray in the clock
    // of its write, before the hit.
    let e = 1 << 16;
    let wall = |id, x: i32| PatchSetup { id, a: [x, -640], b: [x, 640], w: [(1 << 16) * 64 / x, 0], sh: 0 };
    let b0 = (vec![[e, 0]; 4], vec![Job::test(wall(1, 640), 0, 4), Job::test(wall(2, 320), 0, 1)]);
    let b1 = (vec![[e, 0]; 4], vec![Job::test(wall(3, 160), 1, 2)]);
    let b2 = (vec![[e, 0]; 2], vec![Job::test(wall(4, 80), 0, 1)]);
    check_overlapped("marker timing", &[b0, b1, b2], 0, false)?;
    Ok(())
}

#[test]
fn back_to_back_patches_keep_one_test_per_clock() -> Result<()> {
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let dirs: Vec<[i32; 2]> = (0..32).map(|_| unit_dir(&mut rng)).collect();
    let jobs: Vec<Job> = (0..50).map(|i| Job::test(raw_patch(&mut rng, i), 0, 32)).collect();
    let cycles = check("throughput", &dirs, &jobs, Pacing::NONE, 3)?;
    // 1600 tests at II = 1, plus the pipeline's fill and drain.
    assert!(cycles <= 1600 + 8, "{cycles} cycles for 1600 tests");
    Ok(())
}

#[test]
fn exported_verilog_reproduces_the_simulation() -> Result<()> {
    let seed = 0x5eed;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (dirs, mut jobs) = scene_bundle(&mut rng, 64, 60);
    jobs.extend((0..60).map(|i| Job::test(raw_patch(&mut rng, i), (i % 64) as u16, (i % 5) as u16)));
    let mut drv = driver()?;
    drv.record_ports()?;
    run_bundle(&mut drv, &dirs, &jobs, Pacing { idle: true, backpressure: false }, seed)?;
    let rec = drv.take_recording().ok_or("recording was on")?;
    // Rung 4 under both simulators, and rung 5: Yosys' gate-level netlist of the same Verilog.
    for (design, simulator, name) in [
        (Design::Rtl, Simulator::Icarus, "intersection_unit"),
        (Design::Rtl, Simulator::Verilator, "intersection_unit-verilator"),
        (Design::Gates, Simulator::Icarus, "intersection_unit-gates"),
    ] {
        let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join(name);
        let report = rec
            .replay_netlist(drv.uut(), &dir, design, simulator)
            .map_err(|e| e.context(format!("seed {seed:#x}")))?;
        assert_eq!(report.cycles, rec.cycles());
        println!("{report}");
    }
    Ok(())
}

#[test]
fn vcd_on_request() -> Result<()> {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let (dirs, jobs) = scene_bundle(&mut rng, 16, 8);
    let mut drv = driver()?;
    let path = waveform_path("intersection_unit_test");
    drv.stream_vcd(&path, 0..200)?;
    run_bundle(&mut drv, &dirs, &jobs, Pacing::NONE, 11)?;
    drv.finish_vcd()?;
    let text = std::fs::read_to_string(&path).map_err(|e| Error::new(e.to_string()))?;
    for signal in ["patch_ready", "busy", "key_scale", "fw_valid"] {
        assert!(text.contains(signal), "the VCD lacks {signal}");
    }
    Ok(())
}

/// A readout of the same ray in two consecutive clocks: the second cannot see the first's
/// clear (the ray memory reads two clocks ahead), and must still report what the clear leaves,
/// no hit; so must a later readout.
#[test]
fn a_ray_read_out_twice_in_a_row_reports_no_hit_the_second_time() -> Result<()> {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let (dirs, jobs) = scene_bundle(&mut rng, 16, 8);
    let want = model_bundle(&dirs, &jobs);
    let r = want.iter().position(|h| h.is_some()).ok_or("the bundle has a hit")?;
    let mut drv = driver()?;
    load_directions(&mut drv, &dirs)?;
    stream_jobs(&mut drv, &jobs, Pacing::NONE, 5)?;
    while drv.is_busy() {
        drv.cycle_rays(None, None)?;
    }
    let mut got = vec![];
    for read in [Some(r), Some(r), None, Some(r), None, None] {
        drv.cycle_rays(None, read)?;
        got.push(drv.readout());
    }
    // Each readout appears two clocks after its request.
    assert_eq!(got[1], want[r], "the first readout");
    assert_eq!(got[2], None, "the second, one clock later");
    assert_eq!(got[4], None, "a third, after the clear");
    Ok(())
}

/// A bare [`BramOut`] behind ports, for its own tests.
#[derive(LogicBlock, Default)]
struct BramOutBench {
    clock: Signal<In, Clock>,
    read_address: Signal<In, Bits<4>>,
    write_address: Signal<In, Bits<4>>,
    write_data: Signal<In, Bits<17>>,
    write_enable: Signal<In, bool>,
    read_data: Signal<Out, Bits<17>>,
    ram: BramOut<17, 4>,
}

impl Logic for BramOutBench {
    #[hdl_gen]
    fn update(&mut self) {
        self.ram.clock.next = self.clock.val();
        self.ram.read_address.next = self.read_address.val();
        self.ram.write_address.next = self.write_address.val();
        self.ram.write_data.next = self.write_data.val();
        self.ram.write_enable.next = self.write_enable.val();
        self.read_data.next = self.ram.read_data.val();
    }
}

/// The `BramOut` leaf: its Rust model against a reference (two-clock read, zero at power-up,
/// the poison of a same-address read and write), on random traffic over 16 words (many
/// collisions); and its behavioural Verilog replays the recorded run bit-exactly under Icarus.
#[test]
fn bram_out_model_and_behavioural_verilog_agree() -> Result<()> {
    let seed = 0xb0;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut drv = Driver::with_clock(BramOutBench::default(), |b| &mut b.clock)?;
    drv.record_ports()?;
    let (mut mem, mut r1) = ([0u64; 16], 0u64);
    let mut collisions = 0;
    for cycle in 0..2000 {
        let ra = rng.random_range(0..16u64);
        let we = rng.random_bool(0.6);
        let wa = rng.random_range(0..16u64);
        let wd = rng.random_range(0..1u64 << 17);
        drv.cycle(|b| {
            b.read_address.next = ra.into();
            b.write_address.next = wa.into();
            b.write_data.next = wd.into();
            b.write_enable.next = we;
        })?;
        let out = std::mem::replace(
            &mut r1,
            if we && wa == ra {
                collisions += 1;
                !mem[ra as usize] & 0x1_ffff
            } else {
                mem[ra as usize]
            },
        );
        if we {
            mem[wa as usize] = wd;
        }
        let got = drv.uut().read_data.val().to_u64();
        assert_eq!(got, out, "cycle {cycle}, seed {seed:#x}");
    }
    assert!(collisions > 50, "{collisions} same-address reads and writes");
    let rec = drv.take_recording().ok_or("recording was on")?;
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join("bram_out");
    let report = rec.replay(drv.uut(), &dir, Simulator::Icarus)?;
    assert_eq!(report.cycles, rec.cycles());
    println!("{report}");
    Ok(())
}
