//! The cycle figures of `shelling figures` on a tiny sample: one length, one co-simulated
//! source, T_c 1 and 16, without and with the patch cache. The CSV has a row per technique and
//! setting, and its values obey what the hardware guarantees. And `figures --dim 3` on a small
//! 3D workload, end to end: its CSV and table, and its errors.

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

/// One co-simulated source of 256 rays in a scene of 1000 segments of length 32, on rust-hdl's
/// simulation, the load times `tcs`, without and with a 1024-line cache.
fn tiny_sample(out: PathBuf, tcs: Vec<u32>) -> FigureOptions {
    FigureOptions {
        out,
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
        tcs,
        cache_lines: 1024,
        engine: Engine::RustHdl,
    }
}

#[test]
fn cycle_figures_on_a_tiny_sample() {
    let dir = temp_dir("tiny");
    let opts = tiny_sample(dir.clone(), vec![1, 16]);
    let report = figures::run(&opts).expect("figures with the co-simulation");
    // Each source on its own, then the length's sources back to back (one here).
    assert_eq!(report.cosim_runs, 2 * 3 * 2 * 2);
    assert_eq!(report.cycles.len(), 3 * 2 * 2);
    assert!(report.to_string().contains("co-simulation"));

    assert!(dir.join("cycles.md").exists(), "no cycles.md");
    assert!(dir.join("cycles_queue.md").exists(), "no cycles_queue.md");
    assert!(dir.join("cycles_inorder.md").exists(), "no cycles_inorder.md");
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
        assert!(
            num(r, "live_runs") <= num(r, "tests") && num(r, "live_runs") <= num(r, "passed") * 1024.0,
            "{r:?}"
        );
        assert!(num(r, "passed") <= num(r, "patch_loads"), "{r:?}");
        assert!(num(r, "sectors") >= 1.0 || r["method"] == "conventional", "{r:?}");
        // The ideal in-order PE sits between the bound and the PE.
        assert!(cycles >= num(r, "inorder_bound_cycles"), "{r:?}");
        assert!(num(r, "inorder_bound_cycles") >= num(r, "bound_cycles"), "{r:?}");
        // The queue of one source: the same loads as the source alone, never under its bound.
        assert_eq!(num(r, "queue_memory_loads"), num(r, "memory_loads"), "{r:?}");
        assert!(num(r, "queue_cycles") >= num(r, "queue_bound_cycles"), "{r:?}");
        let q_eff = num(r, "queue_pipeline_efficiency");
        assert!(q_eff > 0.0 && q_eff <= 1.0, "{r:?}");
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
        ("no cache line", FigureOptions { cache_lines: 0, ..on.clone() }),
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

#[test]
fn figures_dim_3_writes_the_3d_table_and_csv() {
    use crate::cli::{fails, ok, path_arg, TempDir};
    let dir = TempDir::new("figures3d");
    let out = dir.join("f3");
    let o = path_arg(&out);
    let base =
        ["figures", "--dim", "3", "--out", o, "--seeds", "2", "--sources", "4", "--count", "300", "--quiet"];
    let mut args = base.to_vec();
    args.extend_from_slice(&["--sizes", "8,64", "--rays", "256"]);
    let stdout = ok(&args);
    assert!(stdout.contains("32 × 8") && stdout.contains("| 64 | sweep |"), "{stdout}");
    assert!(!stdout.contains("WARNING"), "every 3D tracer must agree with the conventional one:\n{stdout}");
    let csv = std::fs::read_to_string(out.join("figures3d.csv")).expect("no figures3d.csv");
    let md = std::fs::read_to_string(out.join("figures3d.md")).expect("no figures3d.md");
    assert!(md.contains("| size | method |"), "{md}");
    for fig in ["fig08", "fig09", "fig10", "fig11", "fig13"] {
        let name = std::fs::read_dir(&out)
            .unwrap()
            .filter_map(|e| e.ok()?.file_name().into_string().ok())
            .find(|n| n.starts_with(&format!("{fig}_3d_")) && n.ends_with(".svg"))
            .unwrap_or_else(|| panic!("no {fig}_3d_*.svg"));
        let svg = std::fs::read_to_string(out.join(&name)).unwrap();
        assert!(svg.contains("<svg") && svg.contains("sweep") && svg.contains("3D"), "{name}");
    }
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines[0], format!("size,method,sources,{}", shelling::counters::Counters::NAMES.join(",")));
    assert_eq!(lines.len(), 1 + 2 * 3, "{csv}");
    let col = |row: &str, name: &str| -> f64 {
        let i = lines[0].split(',').position(|c| c == name).unwrap();
        row.split(',').nth(i).unwrap().parse().unwrap()
    };
    for size in ["8", "64"] {
        let rows: Vec<&str> =
            lines[1..].iter().copied().filter(|l| l.starts_with(&format!("{size},"))).collect();
        assert_eq!(rows.len(), 3, "{csv}");
        assert!(
            rows[0].contains(",conventional,8,")
                && rows[1].contains(",polar,")
                && rows[2].contains(",sweep,")
        );
        // Every technique finds the same hits: the same actual intersections and true ADLC.
        for r in &rows[1..] {
            assert_eq!(col(r, "actual_intersections"), col(rows[0], "actual_intersections"), "{csv}");
            assert_eq!(col(r, "adlc_true"), col(rows[0], "adlc_true"), "{csv}");
            assert!(col(r, "patches_read_after_screening") <= col(r, "patches_read_before_screening"));
        }
    }
    // Larger squares are hit more: more actual intersections.
    let actual = |i: usize| col(lines[i], "actual_intersections");
    assert!(actual(4) > actual(1), "{csv}");
    // The same run gives the same bytes.
    let again = dir.join("f3b");
    let mut args = base.to_vec();
    args[4] = path_arg(&again);
    args.extend_from_slice(&["--sizes", "8,64", "--rays", "256"]);
    ok(&args);
    assert_eq!(std::fs::read_to_string(again.join("figures3d.csv")).unwrap(), csv);
    // Bad parameters, each named.
    let t = |extra: &[&str], expect: &[&str]| {
        let mut args = base.to_vec();
        args.extend_from_slice(extra);
        fails(&args, expect);
    };
    t(&["--rays", "1000"], &["--rays must be 4·k²", "900 and 1024"]);
    t(&["--rays", "2"], &["--rays", "the smallest is 4"]);
    t(&["--sizes", "8,8"], &["--sizes", "8 twice"]);
    t(&["--sizes", "0"], &["--sizes", "greater than 0"]);
    t(&["--sizes", "600"], &["--sizes", "1024/√3"]);
    t(&["--tc", "4"], &["--tc belongs to the 2D figures"]);
    t(&["--lengths", "8"], &["--lengths belongs to the 2D figures"]);
    fails(
        &["figures", "--dim", "3", "--out", o, "--count", "300", "--sources", "301"],
        &["--sources", "301"],
    );
    t(&["--cells-per-segment", "0"], &["--cells-per-segment"]);
    fails(&["figures", "--out", o, "--sizes", "8", "--quiet"], &["--sizes belongs to --dim 3"]);
    fails(&["figures", "--dim", "4", "--out", o], &["--dim", "4"]);
}

/// `doc` holds the committed `file` verbatim between the markers `<!-- NAME:begin ... -->` and
/// `<!-- NAME:end -->`.
fn holds_block(doc: &str, name: &str, file: &str) {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join(doc)).unwrap();
    let table = std::fs::read_to_string(root.join(file)).unwrap_or_else(|e| panic!("{file}: {e}"));
    let begin = format!("<!-- {name}:begin");
    let end = format!("<!-- {name}:end -->");
    let start = text.find(&begin).and_then(|s| text[s..].find("-->\n").map(|e| s + e + 4));
    let (start, end) = match (start, text.find(&end)) {
        (Some(s), Some(e)) if s < e => (s, e),
        _ => panic!("{doc} has no {begin:?} … {end:?} block"),
    };
    assert!(table.lines().count() > 2, "{file} holds no rows:\n{table}");
    assert_eq!(&text[start..end], table, "{doc}'s {name} table is not {file}: copy it over");
}

#[test]
fn the_documents_hold_the_committed_tables() {
    holds_block("FIGURES.md", "cycles-table", "figures/cycles.md");
    holds_block("FIGURES.md", "cycles-queue-table", "figures/cycles_queue.md");
    holds_block("FIGURES.md", "cycles-inorder-table", "figures/cycles_inorder.md");
    holds_block("README.md", "headline", "figures/headline.md");
    holds_block("README.md", "headline3d", "figures/headline3d.md");
}

#[test]
fn the_stall_split_of_a_tiny_sample_adds_up_and_matches_the_cycle_figures() {
    // One source of 256 rays at L = 32, T_c 1, without and with the cache: every row's
    // commands, held cycles and drain make its cycles, which are those `cycles.csv` reports for
    // the same run (the same source, the same scheduler).
    let opts = tiny_sample(PathBuf::new(), vec![1]);
    let rows = shelling::figures::stalls::measure(&opts, 1).expect("the stall split");
    assert_eq!(rows.len(), 2 * 2, "S and D, cache off and on");
    let cycle_rows = cycles::measure(&opts).expect("the cycle figures");
    for r in &rows {
        let t = &r.total;
        assert_eq!(r.sources, 1);
        assert_eq!(t.commands + t.sector + t.tags + t.memory + t.downstream + t.after, t.cycles, "{r:?}");
        assert!(t.cycles >= t.bound && t.bound > 0 && t.commands > 1, "{r:?}");
        assert!(t.starved > 0 && t.starved < t.cycles, "{r:?}");
        let c = cycle_rows
            .iter()
            .find(|c| c.method.name() == r.method && c.tc == r.tc && c.cache == r.cache)
            .unwrap_or_else(|| panic!("no cycle row for {r:?}"));
        assert_eq!(c.total.cycles, t.cycles, "{r:?}");
        assert_eq!(c.total.bound_cycles, t.bound, "{r:?}");
    }
    let table = shelling::figures::stalls::markdown(&rows);
    assert_eq!(table.lines().count(), 2 + rows.len());
}
