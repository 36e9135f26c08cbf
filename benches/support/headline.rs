//! What the headline benches (`machine.rs`, `machine3d.rs`) share: the median round and the
//! table's header and software rows.

use std::fmt::Write as _;

/// The median of `v` (the upper middle of an even count).
pub fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The table's header, then a row per technique and core count: `rates[i]` the rays per second
/// of `names[i]` on one core and on `threads` cores, against the baselines `core` and `cores`.
pub fn software_rows(md: &mut String, names: &[&str], rates: &[[f64; 2]], threads: usize) -> (f64, f64) {
    let best = |j: usize| rates.iter().map(|r| r[j]).fold(0.0, f64::max);
    let (core, cores) = (best(0), best(1));
    let _ = writeln!(
        md,
        "| | technique | cycles | host loads | rays per cycle | clock (MHz) | rays/s | × one core | × all cores |"
    );
    let _ = writeln!(md, "|---|---|--:|--:|--:|--:|--:|--:|--:|");
    for (name, rate) in names.iter().zip(rates) {
        for (j, who) in ["1 core".to_string(), format!("{threads} cores")].iter().enumerate() {
            let r = rate[j];
            let _ = writeln!(
                md,
                "| software, {who} | {name} | | | | | {:.1} M | {:.2} | {:.2} |",
                r / 1e6,
                r / core,
                r / cores
            );
        }
    }
    (core, cores)
}

/// Prints the table `md`, and writes it to `path` if given (`--write`).
pub fn finish(md: &str, path: Option<String>) {
    print!("{md}");
    if let Some(path) = path {
        std::fs::write(&path, md).unwrap_or_else(|e| panic!("writing {path}: {e}"));
        eprintln!("written to {path}");
    }
}
