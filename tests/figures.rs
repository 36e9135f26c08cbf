//! The cycle figures of `shelling figures` on a tiny sample: one length, one co-simulated
//! source, T_c 1 and 16, without and with the patch cache. The CSV has a row per technique and
//! setting, and its values obey what the hardware guarantees.

use shelling::cosim::Engine;
use shelling::figures::cycles::{self, CSV_HEADER, SVGS};
use shelling::figures::{self, FigureOptions, METHODS};
use shelling::grid::GridParams;
use shelling::rays::RaySet;
use shelling::trace::ShellParams;
use std::collections::HashMap;
use std::path::PathBuf;

fn temp_dir(tag: &str) -> PathBuf {
    let nanos =
        std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map(|d| d.as_nanos()).unwrap_or(0);
    std::env::temp_dir().join(format!("shelling-cycle-figures-{tag}-{}-{nanos}", std::process::id()))
}

#[test]
fn cycle_figures_on_a_tiny_sample() {
    let dir = temp_dir("tiny");
    let opts = FigureOptions {
        out: dir.clone(),
        seeds: 1,
        sources: 1,
        rays: 256,
        count: 1000,
        lengths: vec![32.0],
        ray_set: RaySet::Angle,
        grid: GridParams::default(),
        shells: ShellParams::default(),
        progress: false,
        cosim_sources: 1,
        tcs: vec![1, 16],
        cache_lines: 1024,
        engine: Engine::RustHdl,
    };
    let report = figures::run(&opts).expect("figures with the co-simulation");
    assert_eq!(report.cosim_runs, 3 * 2 * 2);
    assert_eq!(report.cycles.len(), 3 * 2 * 2);
    assert!(report.to_string().contains("co-simulation"));

    let text = std::fs::read_to_string(dir.join("cycles.csv")).expect("cycles.csv");
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().expect("header").split(',').collect();
    assert_eq!(header.join(","), CSV_HEADER);
    let rows: Vec<HashMap<&str, &str>> =
        lines.map(|l| header.iter().copied().zip(l.split(',')).collect()).collect();
    assert_eq!(rows.len(), 12);
    let num = |r: &HashMap<&str, &str>, k: &str| -> f64 {
        r[k].parse().unwrap_or_else(|_| panic!("{k} = {:?} is not a number", r[k]))
    };
    let mut seen = Vec::new();
    for r in &rows {
        let (tc, cache) = (num(r, "tc"), num(r, "cache_lines"));
        seen.push((r["method"].to_string(), tc as u32, cache as u32));
        assert_eq!(r["length"], "32");
        assert_eq!(r["sources"], "1");
        let cycles = num(r, "cycles");
        let eff = num(r, "pipeline_efficiency");
        assert!(eff > 0.0 && eff <= 1.0, "{r:?}");
        assert!((eff - num(r, "intersection_busy_cycles") / cycles).abs() < 1e-5, "{r:?}");
        assert!(num(r, "tests") >= num(r, "intersection_busy_cycles"), "{r:?}");
        assert!(num(r, "ray_slots") >= num(r, "tests"), "{r:?}");
        assert!(num(r, "passed") <= num(r, "patch_loads"), "{r:?}");
        assert!(num(r, "sectors") >= 1.0 || r["method"] == "conventional", "{r:?}");
        assert!(cycles >= num(r, "bound_cycles"), "{r:?}");
        assert!(num(r, "drain_cycles") <= num(r, "stall_cycles"), "{r:?}");
        if cache == 0.0 {
            assert_eq!(num(r, "cache_hits"), 0.0, "{r:?}");
            assert_eq!(num(r, "memory_loads"), num(r, "patch_loads"), "{r:?}");
            assert!(cycles >= num(r, "memory_loads") * tc, "the memory bounds the cycles: {r:?}");
        } else {
            assert_eq!(num(r, "memory_loads") + num(r, "cache_hits"), num(r, "patch_loads"), "{r:?}");
        }
        if r["method"] == "conventional" {
            assert!(r["s_measured"].is_empty() && r["predicted_speedup"].is_empty(), "{r:?}");
            assert_eq!(num(r, "speedup"), 1.0);
        } else {
            let s = num(r, "s_measured");
            assert!((0.0..1.0).contains(&s), "{r:?}");
            assert!(num(r, "adlc_true") > 1.0, "{r:?}");
            assert!(num(r, "predicted_speedup") > 0.0, "{r:?}");
            assert!(["memory", "compute"].contains(&r["predicted_branch"]), "{r:?}");
            // The paper's claim at T_c 16, on one source: shelling beats the conventional
            // technique on the shared memory, and behind the cache it beats the conventional
            // technique without one (Eq. 11's pairing). With both behind the cache the two are
            // close on a single source (FIGURES.md: 1.02–2.3× over 20 sources), so that row
            // is not asserted here.
            if tc == 16.0 {
                if cache == 0.0 {
                    assert!(num(r, "speedup") > 1.0, "shelling is faster at T_c 16: {r:?}");
                }
                assert!(num(r, "speedup_vs_shared_conventional") > 1.0, "{r:?}");
            }
        }
    }
    let mut want = Vec::new();
    for cache in [0, 1024] {
        for tc in [1, 16] {
            for m in METHODS {
                want.push((m.name().to_string(), tc, cache));
            }
        }
    }
    assert_eq!(seen, want, "rows in order: cache, T_c, technique");

    // The speedups and their predictions agree with the rows.
    for s in cycles::speedups(&report.cycles) {
        assert!(s.measured > 0.0 && s.measured.is_finite(), "{s:?}");
        assert_eq!(s.predicted.is_some(), s.scenario != cycles::Scenario::Cached, "{s:?}");
    }

    for name in SVGS {
        let p = dir.join(name);
        let svg = std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
        assert!(svg.contains("<svg") && svg.contains("T_c = 16"), "{name}");
        assert!(report.files.contains(&p), "{name} not reported");
    }
    let shared = std::fs::read_to_string(dir.join("cycles_speedup_shared.svg")).unwrap();
    assert!(shared.contains("Eq. 10"), "the shared-memory speedup plot lacks the prediction");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn cycle_figures_can_be_skipped_and_reject_bad_options() {
    let dir = temp_dir("skip");
    let base = FigureOptions {
        out: dir.clone(),
        seeds: 1,
        sources: 1,
        rays: 64,
        count: 100,
        lengths: vec![16.0],
        ray_set: RaySet::Angle,
        grid: GridParams::default(),
        shells: ShellParams::default(),
        progress: false,
        cosim_sources: 0,
        tcs: vec![1, 16],
        cache_lines: 1024,
        engine: Engine::RustHdl,
    };
    let report = figures::run(&base).expect("figures without the co-simulation");
    assert!(report.cycles.is_empty() && report.cosim_runs == 0);
    assert!(!dir.join("cycles.csv").exists());
    let _ = std::fs::remove_dir_all(&dir);

    let on = FigureOptions { cosim_sources: 1, ..base };
    let bad = [
        ("no T_c", FigureOptions { tcs: vec![], ..on.clone() }),
        ("T_c 0", FigureOptions { tcs: vec![0], ..on.clone() }),
        ("T_c twice", FigureOptions { tcs: vec![4, 4], ..on.clone() }),
        ("cache not a power of two", FigureOptions { cache_lines: 1000, ..on.clone() }),
        ("cache too large", FigureOptions { cache_lines: 8192, ..on.clone() }),
        ("too many rays for the PE", FigureOptions { rays: 2048, ..on.clone() }),
        ("more sources than patches", FigureOptions { cosim_sources: 101, ..on.clone() }),
    ];
    for (what, o) in bad {
        assert!(o.validate().is_err(), "{what} accepted");
        assert!(cycles::measure(&o).is_err(), "{what} accepted by measure");
    }
    assert!(!dir.exists(), "a rejected run created its output directory");
}
