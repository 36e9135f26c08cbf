//! The whole system, rungs 2 and 3: the shell scheduler's work stream co-simulated on the RTL
//! processing element returns, for every ray, the bit-true tracer's nearest hit, and the f64
//! golden model's within the documented bound; the PE's counters equal the scheduler's.

use shelling::agreement;
use shelling::cosim::{self, CosimConfig};
use shelling::geom::Hit;
use shelling::grid::GridParams;
use shelling::rays::RaySet;
use shelling::run::GriddedScene;
use shelling::scene::{self, PAPER_WORLD};
use shelling::trace::{Method, ShellParams};
use shelling_hdl::formats::key_distance;

/// The PE's nearest hits in the tracer's terms (distance from the key, segment from the id).
fn tracer_hits(run: &cosim::Cosim) -> Vec<Option<Hit>> {
    run.hits.iter().map(|h| h.map(|n| Hit { t: key_distance(n.key), segment: n.id as u32 })).collect()
}

#[test]
fn the_pe_returns_the_schedulers_hits_for_every_technique_and_length() {
    let params = ShellParams::default();
    // One source per length; T_c 1 and 16 alternate.
    for (i, length) in [4.0, 8.0, 16.0, 32.0, 64.0, 128.0].into_iter().enumerate() {
        let seed = 40 + i as u64;
        let scene = scene::generate(1000, length, seed, PAPER_WORLD).expect("scene");
        let prepared = GriddedScene::new(scene, GridParams::default());
        let k = 137 * (i + 1) % 1000;
        let bundle = prepared.patch_bundle(k, RaySet::Angle, 1024).expect("source");
        for m in [Method::Conventional, Method::Stochastic, Method::Deterministic] {
            let what = format!("length {length} seed {seed} source {k} {m}");
            let tc = if i % 2 == 0 { 1 } else { 16 };
            let scheduled = prepared.schedule(m, &bundle, &params).expect("fits");
            let run = cosim::run(
                &scheduled,
                &CosimConfig {
                    tc,
                    cache: if i % 3 == 2 { Some(1024) } else { None },
                    vcd: None,
                    ..CosimConfig::default()
                },
                |_, _| {},
            )
            .unwrap_or_else(|e| panic!("{what}: {e}"));
            assert_eq!(tracer_hits(&run), scheduled.trace.hits, "{what}: the PE against the bit-true tracer");
            let c = &scheduled.trace.counters;
            let h = &run.hardware;
            assert_eq!(h.patch_loads, c.patches_read_before_screening, "{what}: loads");
            assert!(h.tests <= c.intersection_computations && h.tests > 0, "{what}: {h:?} vs {c:?}");
            assert!(h.cycles >= h.memory_loads * tc as u64, "{what}: the memory bounds the cycles: {h:?}");
            let golden = prepared.trace(m, &bundle, &params).expect("traces");
            let rung2 = agreement::compare(&prepared.scene.segments, &bundle, &golden, &scheduled.trace);
            assert!(
                rung2.unexplained.is_empty() && rung2.distance_violations.is_empty(),
                "{what}: beyond the bound: {:?} {:?}",
                rung2.unexplained,
                rung2.distance_violations
            );
            println!("{what} T_c {tc}: {h:?}");
        }
    }
}

#[test]
fn the_waveform_of_a_whole_source_keeps_the_stream_protocol() {
    use shelling::cosim::VcdWindow;
    use shelling_testbench::pe::check_protocol;
    use shelling_testbench::waves::{gtkw_signals, Waves};
    let scene = scene::generate(1000, 32.0, 5, PAPER_WORLD).expect("scene");
    let prepared = GriddedScene::new(scene, GridParams::default());
    let bundle = prepared.patch_bundle(300, RaySet::Angle, 1024).expect("source");
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cosim-vcd");
    for (m, tc, cache) in [(Method::Stochastic, 4, None), (Method::Conventional, 2, Some(256))] {
        let scheduled = prepared.schedule(m, &bundle, &ShellParams::default()).expect("fits");
        let path = dir.join(format!("{m}.vcd"));
        let vcd = Some(VcdWindow { path: path.clone(), from: 0, to: u64::MAX });
        let run =
            cosim::run(&scheduled, &CosimConfig { tc, cache, vcd, ..CosimConfig::default() }, |_, _| {})
                .expect("co-simulates");
        let report = check_protocol(&path).unwrap_or_else(|e| panic!("{m}: {e}"));
        assert_eq!(report.ids.len() as u64, run.hardware.patch_loads, "{m}");
        assert!(
            report.max_loader_reserved > 1 && report.max_tags > 1,
            "{m}: the FIFOs never filled: {report:?}"
        );
        // The committed GTKWave save file names signals this VCD has.
        let gtkw = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("waveforms").join("demo.gtkw");
        let signals = gtkw_signals(&gtkw).expect("readable");
        assert!(signals.len() > 40, "{signals:?}");
        let names: Vec<&str> = signals.iter().map(String::as_str).collect();
        Waves::read(&path, &names).unwrap_or_else(|e| panic!("demo.gtkw: {e}"));
        println!(
            "{m}: {} cycles, {} ids, FIFO peaks: loader {}, screener {}, tags {}",
            report.cycles,
            report.ids.len(),
            report.max_loader_reserved,
            report.max_screener_in_flight,
            report.max_tags
        );
    }
    // A window writes only its cycles.
    let scheduled = prepared.schedule(Method::Stochastic, &bundle, &ShellParams::default()).expect("fits");
    let path = dir.join("window.vcd");
    let vcd = Some(VcdWindow { path: path.clone(), from: 1500, to: 1700 });
    cosim::run(&scheduled, &CosimConfig { tc: 4, cache: None, vcd, ..CosimConfig::default() }, |_, _| {})
        .expect("co-simulates");
    let w = Waves::read(&path, &["uut.busy", "uut.clock"]).expect("readable");
    assert_eq!((w.first_cycle, w.cycles()), (1500, 200));
    assert!(check_protocol(&path).is_err(), "a window is not a whole run");
}

/// The compiled PE (Verilator) over a broader sample than rust-hdl's simulation can afford in a
/// test: four sources per length, every technique, host memory and cache settings that vary
/// from run to run (small caches that evict, T_c from 1 to 16). Every hit and counter is checked
/// against the bit-true model by `cosim::run`, and the hits against the bit-true tracer here.
#[test]
fn the_compiled_pe_returns_the_schedulers_hits_across_the_workload() {
    let params = ShellParams::default();
    let mut runs = 0;
    let mut tests = 0;
    for (i, length) in [4.0, 8.0, 16.0, 32.0, 64.0, 128.0].into_iter().enumerate() {
        let seed = 70 + i as u64;
        let scene = scene::generate(1000, length, seed, PAPER_WORLD).expect("scene");
        let prepared = GriddedScene::new(scene, GridParams::default());
        for s in 0..4 {
            let k = (251 * s + 97 * i + 13) % 1000;
            let bundle = prepared.patch_bundle(k, RaySet::Angle, 1024).expect("source");
            for (j, m) in
                [Method::Conventional, Method::Stochastic, Method::Deterministic].into_iter().enumerate()
            {
                let v = i + s + j;
                let (tc, cache) = ([1, 3, 16][v % 3], [None, Some(16), Some(256), Some(1024)][v % 4]);
                let what = format!("length {length} seed {seed} source {k} {m} T_c {tc} cache {cache:?}");
                let scheduled = prepared.schedule(m, &bundle, &params).expect("fits");
                let config =
                    CosimConfig { tc, cache, engine: cosim::Engine::Verilator, ..CosimConfig::default() };
                let run =
                    cosim::run(&scheduled, &config, |_, _| {}).unwrap_or_else(|e| panic!("{what}: {e}"));
                assert_eq!(
                    tracer_hits(&run),
                    scheduled.trace.hits,
                    "{what}: the PE against the bit-true tracer"
                );
                assert_eq!(
                    run.hardware.patch_loads, scheduled.trace.counters.patches_read_before_screening,
                    "{what}: loads"
                );
                // The bound of the figures <= the ideal in-order PE <= the PE.
                let h = &run.hardware;
                let bound = cosim::bound_cycles(h, tc);
                assert!(
                    bound <= run.inorder_cycles && run.inorder_cycles <= h.cycles,
                    "{what}: bound {bound}, ideal in-order PE {}, PE {}",
                    run.inorder_cycles,
                    h.cycles
                );
                if cache.is_some_and(|n| n >= 256) && m != Method::Conventional {
                    assert!(run.hardware.cache_hits > 0, "{what}: the cache never hit: {:?}", run.hardware);
                }
                runs += 1;
                tests += run.hardware.tests;
            }
        }
    }
    println!("{runs} runs, {tests} ray-patch tests on the compiled PE");
    assert!(runs == 72 && tests > 100_000, "{runs} runs, {tests} tests");
}

/// A cache of a size that is not a power of two (a quarter of the 1000-patch scene: 250 lines)
/// is a direct-mapped cache of that many lines: patch `k` in line `k mod 250`, so its host loads
/// are exactly the misses of that cache over the source's patch loads, and every hit is the
/// bit-true tracer's (patch numbers, not the spread host memory's addresses).
#[test]
fn a_cache_of_any_size_is_direct_mapped_on_the_patch_number_modulo_its_lines() {
    use shelling::workstream::commands;
    use shelling_testbench::pe::Command;
    let scene = scene::generate(1000, 32.0, 7, PAPER_WORLD).expect("scene");
    let prepared = GriddedScene::new(scene, GridParams::default());
    let bundle = prepared.patch_bundle(12, RaySet::Angle, 1024).expect("source");
    for (m, lines) in [(Method::Stochastic, 250u32), (Method::Conventional, 37)] {
        let scheduled = prepared.schedule(m, &bundle, &ShellParams::default()).expect("fits");
        let (_, _, cmds) = commands(&scheduled.stream, &scheduled.fixed).expect("stream");
        let mut cache = vec![None; lines as usize];
        let misses = cmds
            .iter()
            .filter_map(Command::job_id)
            .filter(|&id| cache[id as usize % lines as usize].replace(id) != Some(id))
            .count() as u64;
        let config = CosimConfig {
            tc: 4,
            cache: Some(lines),
            engine: cosim::Engine::Verilator,
            ..CosimConfig::default()
        };
        let run = cosim::run(&scheduled, &config, |_, _| {}).unwrap_or_else(|e| panic!("{m} {lines}: {e}"));
        assert_eq!(tracer_hits(&run), scheduled.trace.hits, "{m} {lines}: the hits, by patch number");
        assert_eq!(
            run.hardware.memory_loads, misses,
            "{m} {lines}: host loads = the {lines}-line cache's misses"
        );
        assert!(run.hardware.cache_hits > 0 && misses > 0, "{m} {lines}: {:?}", run.hardware);
    }
}
