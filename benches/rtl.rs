//! RTL simulation speed: simulated cycles per second of the intersection unit driven by the
//! testbench's cycle loop (release build), without and with VCD streaming, beside the bit-true
//! model's ray-patch tests per second on the same work (the baseline measured in the same run);
//! then the whole processing element co-simulating one source of the paper's workload (1000
//! segments of length 32, R = 1024, stochastic shelling, T_c = 16) on rust-hdl's simulation and
//! on the compiled one (its exported Verilog built by Verilator), beside the bit-true execution
//! of the same work stream; then the parallel machine of eight compiled PEs on one host memory
//! (`shelling::machine`, 16 sources of the same scene, `T_c` = 16, 256-patch caches; the PEs
//! stepped on two threads where there are two cores, as `shelling machine` steps them): machine
//! cycles per second, beside one compiled PE's cycles per second on the same sources in the
//! same run.
//!
//! Workload: bundles of 64 rays, 400 patches each with arbitrary 18-bit fields, each tested
//! against all 64 rays (25 600 tests per bundle, one per clock). Median of interleaved rounds.
//!
//! Run: `cargo bench --bench rtl` (`-- --rounds N` for more rounds, `-- --plain` for the
//! intersection unit's no-VCD simulation alone, `-- --pe` for the processing element alone and
//! `-- --machine` for the machine alone, e.g. under a profiler).

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use shelling_hdl::formats::PatchSetup;
use shelling_hdl::intersection::IntersectionUnit;
use shelling_testbench::intersection::{model_bundle, run_bundle, Job};
use shelling_testbench::{Driver, Pacing};
use std::hint::black_box;
use std::time::Instant;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let rounds = std::env::args()
        .skip_while(|a| a != "--rounds")
        .nth(1)
        .and_then(|v| v.parse().ok())
        .unwrap_or(5usize);
    // `--plain`: only the no-VCD simulation (for profiling it alone).
    let plain_only = std::env::args().any(|a| a == "--plain");
    // `--pe`: only the processing element (for profiling it alone).
    if std::env::args().any(|a| a == "--pe") {
        processing_element(rounds);
        return;
    }
    // `--machine`: only the parallel machine.
    if std::env::args().any(|a| a == "--machine") {
        machine(rounds);
        return;
    }
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let mut raw = |bits: u32| rng.random_range(-(1i32 << (bits - 1))..(1i32 << (bits - 1)));
    let dirs: Vec<[i32; 2]> = (0..64).map(|_| [raw(18), raw(18)]).collect();
    let jobs: Vec<Job> = (0..400u16)
        .map(|id| {
            let patch = PatchSetup {
                id,
                a: [raw(18), raw(18)],
                b: [raw(18), raw(18)],
                w: [raw(18), raw(18)],
                sh: (raw(6).rem_euclid(35) - 3) as i8,
            };
            Job::test(patch, 0, 64)
        })
        .collect();
    let vcd = std::env::temp_dir().join(format!("shelling-bench-{}.vcd", std::process::id()));
    let (mut plain, mut traced, mut model) = (Vec::new(), Vec::new(), Vec::new());
    let mut passes = 0.0;
    for _ in 0..rounds {
        let mut drv = Driver::new(IntersectionUnit::default()).expect("the unit connects");
        let t = Instant::now();
        run_bundle(&mut drv, &dirs, &jobs, Pacing::NONE, 1).expect("runs");
        plain.push(drv.cycles() as f64 / t.elapsed().as_secs_f64());
        passes = drv.passes() as f64 / drv.cycles() as f64;

        if plain_only {
            continue;
        }
        let mut drv = Driver::new(IntersectionUnit::default()).expect("the unit connects");
        drv.stream_vcd(&vcd, ..).expect("VCD file");
        let t = Instant::now();
        run_bundle(&mut drv, &dirs, &jobs, Pacing::NONE, 1).expect("runs");
        drv.finish_vcd().expect("VCD written");
        traced.push(drv.cycles() as f64 / t.elapsed().as_secs_f64());

        let t = Instant::now();
        black_box(model_bundle(black_box(&dirs), black_box(&jobs)));
        model.push((64 * 400) as f64 / t.elapsed().as_secs_f64());
    }
    let _ = std::fs::remove_file(&vcd);
    if plain_only {
        println!(
            "RTL simulation, no VCD: {:.0} cycles/s, {passes:.2} update passes per cycle",
            median(plain)
        );
        return;
    }
    let (p, v, m) = (median(plain), median(traced), median(model));
    println!("intersection unit, {rounds} rounds, median:");
    println!(
        "  {:<32} {:>12.0} cycles/s  ({passes:.2} update passes per cycle)",
        "RTL simulation, no VCD", p
    );
    println!("  {:<32} {:>12.0} cycles/s  ({:.2}x of no VCD)", "RTL simulation, VCD streamed", v, v / p);
    println!("  {:<32} {:>12.0} tests/s   (RTL is {:.4}x of it)", "bit-true model (baseline)", m, p / m);
    println!("  goal: >= 500000 cycles/s without VCD: {}", if p >= 5e5 { "met" } else { "NOT met" });
    processing_element(rounds);
    machine(rounds);
}

/// The machine of eight compiled PEs on 16 sources of the paper's workload: machine cycles per
/// second, and one compiled PE's on the same 16 sources (the machine's baseline, same run).
fn machine(rounds: usize) {
    use shelling::cosim::Engine;
    use shelling::grid::GridParams;
    use shelling::machine::{self, Deal, MachineConfig, Placement};
    use shelling::rays::RaySet;
    use shelling::run::GriddedScene;
    use shelling::scene::{self, PAPER_WORLD};
    use shelling::trace::{Method, ShellParams};
    let scene = scene::generate(1000, 32.0, 7, PAPER_WORLD).expect("scene");
    let prepared = GriddedScene::new(scene, GridParams::default());
    let ids: Vec<usize> = (0..16).map(|k| k * 61).collect();
    let schedules: Vec<_> = machine::spatial_order(&prepared.scene.segments, &ids)
        .into_iter()
        .map(|k| {
            let bundle = prepared.patch_bundle(k, RaySet::Angle, 1024).expect("source");
            prepared.schedule(Method::Stochastic, &bundle, &ShellParams::default()).expect("fits")
        })
        .collect();
    let config = |pes| MachineConfig {
        pes,
        tc: 16,
        cache: Some(256),
        deal: Deal::Blocks,
        place: Placement::Index,
        engine: Engine::Verilator,
        vcd: None,
    };
    let (mut rate8, mut rate1, mut cycles) = (vec![], vec![], (0, 0));
    for _ in 0..rounds {
        let t = Instant::now();
        let run8 = machine::run(&schedules, &config(8), |_, _| {}).expect("the machine co-simulates");
        rate8.push(run8.cycles as f64 / t.elapsed().as_secs_f64());
        let t = Instant::now();
        let run1 = machine::run(&schedules, &config(1), |_, _| {}).expect("one PE co-simulates");
        rate1.push(run1.cycles as f64 / t.elapsed().as_secs_f64());
        cycles = (run8.cycles, run1.cycles);
    }
    let (r8, r1) = (median(rate8), median(rate1));
    println!("machine, 16 sources (L = 32, R = 1024, stochastic, T_c = 16, 256-patch caches), {rounds} rounds, median:");
    println!("  {:<32} {:>12.0} machine cycles/s ({} cycles)", "8 compiled PEs", r8, cycles.0);
    println!(
        "  {:<32} {:>12.0} cycles/s ({} cycles; the machine {:.2}x of it)",
        "1 compiled PE (baseline)",
        r1,
        cycles.1,
        r8 / r1
    );
    println!("  goal: >= 150000 machine cycles/s at 8 PEs: {}", if r8 >= 1.5e5 { "met" } else { "NOT met" });
}

/// The PE on one source of the paper's workload: simulated cycles per second and wall time, on
/// rust-hdl's simulation and on the compiled one (Verilator; its one-time build is not timed).
fn processing_element(rounds: usize) {
    use shelling::cosim::{self, CosimConfig};
    use shelling::grid::GridParams;
    use shelling::rays::RaySet;
    use shelling::run::GriddedScene;
    use shelling::scene::{self, PAPER_WORLD};
    use shelling::trace::{Method, ShellParams};
    use shelling::workstream::execute;
    use shelling_hdl::pe::ProcessingElement;
    use shelling_testbench::verilated::VerilatedPe;
    let scene = scene::generate(1000, 32.0, 7, PAPER_WORLD).expect("scene");
    let prepared = GriddedScene::new(scene, GridParams::default());
    let bundle = prepared.patch_bundle(250, RaySet::Angle, 1024).expect("source");
    let scheduled = prepared.schedule(Method::Stochastic, &bundle, &ShellParams::default()).expect("fits");
    let config = CosimConfig { tc: 16, ..CosimConfig::default() };
    let t = Instant::now();
    drop(VerilatedPe::new().expect("the compiled PE builds (needs verilator and g++)"));
    let build = t.elapsed().as_secs_f64();
    let (mut rate, mut wall, mut fast_rate, mut fast_wall, mut model) =
        (vec![], vec![], vec![], vec![], vec![]);
    let (mut cycles, mut passes) = (0, 0.0);
    let total =
        |run: &cosim::Cosim| run.hardware.cycles + run.hardware.setup_cycles + run.hardware.readout_cycles;
    for _ in 0..rounds {
        let t = Instant::now();
        let mut drv = Driver::new(ProcessingElement::default()).expect("the PE connects");
        let run = cosim::run_on(&mut drv, &scheduled, &config, |_, _| {}).expect("co-simulates");
        let elapsed = t.elapsed().as_secs_f64();
        cycles = total(&run);
        wall.push(elapsed);
        rate.push(cycles as f64 / elapsed);
        passes = drv.passes() as f64 / drv.cycles() as f64;

        let t = Instant::now();
        let mut pe = VerilatedPe::new().expect("the compiled PE loads");
        let fast = cosim::run_sim(&mut pe, &scheduled, &config, |_, _| {}).expect("co-simulates");
        let elapsed = t.elapsed().as_secs_f64();
        assert_eq!(fast.hardware, run.hardware, "the compiled PE's counters differ from rust-hdl's");
        fast_wall.push(elapsed);
        fast_rate.push(total(&fast) as f64 / elapsed);

        let t = Instant::now();
        black_box(execute(black_box(&scheduled.stream), &scheduled.fixed).expect("valid"));
        model.push(t.elapsed().as_secs_f64());
    }
    let (r, w, fr, fw, m) = (median(rate), median(wall), median(fast_rate), median(fast_wall), median(model));
    println!(
        "processing element, one source (L = 32, R = 1024, stochastic, T_c = 16), {rounds} rounds, median:"
    );
    println!("  {:<32} {:>12} cycles (setup, stream and readout)", "simulated", cycles);
    println!(
        "  {:<32} {:>12.0} cycles/s, {:.2} s per source ({passes:.2} update passes per cycle)",
        "rust-hdl simulation, no VCD", r, w
    );
    println!(
        "  {:<32} {:>12.0} cycles/s, {:.3} s per source ({:.1}x rust-hdl; built once in {build:.1} s)",
        "compiled (Verilator)",
        fr,
        fw,
        fr / r
    );
    println!(
        "  {:<32} {:>12.6} s per source (rust-hdl takes {:.0}x as long, compiled {:.1}x)",
        "bit-true execution (baseline)",
        m,
        w / m,
        fw / m
    );
    let met = |ok: bool| if ok { "met" } else { "NOT met" };
    println!(
        "  goals: >= 300000 cycles/s: {} compiled, {} rust-hdl; a source in under 5 s: {} compiled, {} rust-hdl",
        met(fr >= 3e5),
        met(r >= 3e5),
        met(fw < 5.0),
        met(w < 5.0)
    );
}
