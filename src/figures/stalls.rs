//! Where the processing element's cycles go, beside the bound of `cycles.csv`: each run's
//! cycles (from the first command to the PE idle after the last, a fresh PE per source, as
//! `cosim --json` reports `hardware.cycles`) split by what the command stream did in each of
//! them. The host offers a command in every cycle until it has sent them all, and the PE takes
//! at most one a clock, so
//!
//! cycles = commands taken + cycles the PE held the stream + cycles after the last command.
//!
//! The held cycles are split by their cause, read from the PE's registers on rust-hdl's
//! simulation ([`shelling_hdl::pe::Watch`], through [`Watched`]): a sector command waiting for
//! its bank (the sector before last still has jobs before the screener's sector read), the tag
//! FIFO full, the loader full of requests whose patches the host memory or the cache has not
//! answered yet (*memory*), or full behind a screener that takes no patch (*downstream*: the
//! screener's output, the merger, the job queue and the intersection unit are full). The cycles
//! after the last command are the pipeline's drain: the loader's, the screener's and the
//! queue's latency and the unit's backlog of tests. Beside them, the cycles in which the
//! intersection unit had no job to take (*unit starved*): where the tests are the bound, the
//! cycles over it are these, the fill before the first job among them. And the cycles the
//! cache's lookups stood still waiting for a fill (*lookups wait for a fill*): from a rewind of
//! a request for the id of a miss whose patch is not in its line yet until that request is
//! looked up; no request behind it is looked up meanwhile, so no miss behind it reaches the
//! host.
//!
//! The sample is `sources` source patches of the first seed's scene of each length
//! ([`source_patches`]), the scenes and schedules of `cycles.csv`, every T_c of the options
//! without and with the cache, stochastic and deterministic shelling; every run's hits are
//! checked as `cosim` checks them. The cycles are rust-hdl's, the same as the compiled PE's.

use super::{scene_seed, source_patches, FigureOptions, METHODS};
use crate::cosim::{run_sim, CosimConfig};
use crate::run::{GriddedScene, Scheduled};
use crate::scene;
use crate::trace::Method;
use anyhow::{anyhow, Result};
use rayon::prelude::*;
use shelling_testbench::pe_sim::{WatchSample, Watched};
use std::fmt::Write as _;

/// Sources per length in the committed table (`figures/stalls.md`).
pub const SOURCES: usize = 5;

/// One run's cycles by what the command stream did in them (or a sum of runs').
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Breakdown {
    /// Cycles from the first command to the PE idle after the last.
    pub cycles: u64,
    /// max(host loads·T_c, loads, tests): `cycles.csv`'s bound.
    pub bound: u64,
    /// Commands taken (the whole bundle's sector first).
    pub commands: u64,
    /// Cycles a sector command waited for its bank.
    pub sector: u64,
    /// Cycles the tag FIFO was full.
    pub tags: u64,
    /// Cycles the loader was full of requests the memory had not answered.
    pub memory: u64,
    /// Cycles the loader was full behind a screener that took no patch.
    pub downstream: u64,
    /// Cycles after the last command was taken.
    pub after: u64,
    /// Cycles the intersection unit had no job to take ([`shelling_hdl::pe::Watch::unit_starved`]).
    pub starved: u64,
    /// Cycles from a rewind of the cache's lookups on a request for a miss's id until the
    /// request is looked up ([`shelling_hdl::pe::Watch::fill_rewind`]).
    pub fill_waits: u64,
    /// Ray-patch tests.
    pub tests: u64,
}

impl Breakdown {
    /// The breakdown of the run whose command phase is the `cycles` cycles from the first one
    /// the host offered a command in (`samples` from power-up).
    pub fn of_run(samples: &[WatchSample], cycles: u64) -> Result<Breakdown> {
        let start =
            samples.iter().position(|s| s.offered).ok_or_else(|| anyhow!("no command was offered"))?;
        let run = samples
            .get(start..start + cycles as usize)
            .ok_or_else(|| anyhow!("the run's {cycles} cycles from cycle {start} were not all recorded"))?;
        let mut b = Breakdown { cycles, ..Breakdown::default() };
        let mut last = 0;
        let mut waiting = false;
        for (c, s) in run.iter().enumerate() {
            b.starved += s.watch.unit_starved as u64;
            waiting = (waiting | s.watch.fill_rewind) & !s.watch.lookup;
            b.fill_waits += waiting as u64;
            if !s.offered {
                continue;
            }
            last = c + 1;
            let w = s.watch;
            let cause = if s.ready {
                &mut b.commands
            } else if w.sector_waits {
                &mut b.sector
            } else if w.tags_full {
                &mut b.tags
            } else if w.loader_full && w.screener_holds {
                &mut b.downstream
            } else if w.loader_full {
                &mut b.memory
            } else {
                return Err(anyhow!("cycle {} of the run: cmd_ready low with no cause the PE shows", c));
            };
            *cause += 1;
        }
        b.after = cycles - last as u64;
        if b.commands + b.sector + b.tags + b.memory + b.downstream + b.after != cycles {
            return Err(anyhow!("the host offered no command in a cycle before its last"));
        }
        Ok(b)
    }

    fn add(&mut self, o: &Breakdown) {
        self.cycles += o.cycles;
        self.bound += o.bound;
        self.commands += o.commands;
        self.sector += o.sector;
        self.tags += o.tags;
        self.memory += o.memory;
        self.downstream += o.downstream;
        self.after += o.after;
        self.starved += o.starved;
        self.fill_waits += o.fill_waits;
        self.tests += o.tests;
    }
}

/// A length's, technique's and memory setting's runs, summed.
#[derive(Clone, Debug, PartialEq)]
pub struct StallRow {
    pub length: f64,
    /// [`METHODS`]' name.
    pub method: &'static str,
    pub tc: u32,
    /// The cache's lines, `None` off.
    pub cache: Option<u32>,
    pub sources: usize,
    pub total: Breakdown,
}

/// Runs the sample (the module documentation) with `sources` sources per length.
pub fn measure(opts: &FigureOptions, sources: usize) -> Result<Vec<StallRow>> {
    opts.validate()?;
    let patches = source_patches(opts.count, sources);
    // The shelling techniques' runs, grouped by length, technique, cache and T_c.
    let mut runs: Vec<(usize, usize, usize, u32, Option<u32>)> = Vec::new();
    for i in 0..opts.lengths.len() {
        for m in (0..METHODS.len()).filter(|&m| METHODS[m] != Method::Conventional) {
            for cache in [None, Some(opts.cache_lines)] {
                for &tc in &opts.tcs {
                    runs.extend(patches.iter().map(|&k| (i, m, k, tc, cache)));
                }
            }
        }
    }
    let scenes: Vec<GriddedScene> = (0..opts.lengths.len())
        .map(|i| {
            let sc = scene::generate(opts.count, opts.lengths[i], scene_seed(i, 0), scene::PAPER_WORLD)
                .map_err(|e| anyhow!("generating the scene of length {}: {e}", opts.lengths[i]))?;
            Ok(GriddedScene::new(sc, opts.grid))
        })
        .collect::<Result<_>>()?;
    let schedule = |i: usize, m: usize, k: usize| -> Result<Scheduled> {
        let bundle = scenes[i].patch_bundle(k, opts.ray_set, opts.rays)?;
        Ok(scenes[i].schedule(METHODS[m], &bundle, &opts.shells)?)
    };
    let each: Vec<Breakdown> = runs
        .par_iter()
        .map(|&(i, m, k, tc, cache)| {
            let what = || {
                format!(
                    "source patch {k} of length {} ({}, T_c {tc}, cache {cache:?})",
                    opts.lengths[i], METHODS[m]
                )
            };
            let s = schedule(i, m, k).map_err(|e| anyhow!("{}: {e}", what()))?;
            let mut pe = Watched::new().map_err(|e| anyhow!("{}: {e}", what()))?;
            let config = CosimConfig { tc, cache, vcd: None, engine: opts.engine };
            let run = run_sim(&mut pe, &s, &config, |_, _| {}).map_err(|e| anyhow!("{}: {e}", what()))?;
            let h = run.hardware;
            let mut b = Breakdown::of_run(&pe.samples, h.cycles).map_err(|e| anyhow!("{}: {e}", what()))?;
            b.bound = crate::cosim::bound_cycles(&h, tc);
            b.tests = h.tests;
            Ok(b)
        })
        .collect::<Result<_>>()?;
    let mut rows: Vec<StallRow> = Vec::new();
    for (&(i, m, _, tc, cache), b) in runs.iter().zip(&each) {
        let length = opts.lengths[i];
        let method = METHODS[m].name();
        match rows.last_mut() {
            Some(r) if r.length == length && r.method == method && r.tc == tc && r.cache == cache => {
                r.sources += 1;
                r.total.add(b);
            }
            _ => rows.push(StallRow { length, method, tc, cache, sources: 1, total: *b }),
        }
    }
    Ok(rows)
}

/// The rows as a Markdown table, per source (means over the sample), cycles over the bound.
pub fn markdown(rows: &[StallRow]) -> String {
    let mut s = String::from(
        "| L | technique | T_c | cache | cycles | bound | cycles / bound | commands | held: sector \
         | held: tags | held: memory | held: downstream | after the last command | tests \
         | unit starved | lookups wait for a fill |\n\
         |---:|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        let t = &r.total;
        let n = r.sources as f64;
        let f = |v: u64| format!("{:.1}", v as f64 / n);
        let cache = r.cache.map_or("off".to_string(), |l| format!("{l} lines"));
        let _ = writeln!(
            s,
            "| {} | {} | {} | {cache} | {} | {} | {:.2} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.length,
            r.method,
            r.tc,
            f(t.cycles),
            f(t.bound),
            t.cycles as f64 / t.bound.max(1) as f64,
            f(t.commands),
            f(t.sector),
            f(t.tags),
            f(t.memory),
            f(t.downstream),
            f(t.after),
            f(t.tests),
            f(t.starved),
            f(t.fill_waits)
        );
    }
    s
}

/// The committed table (`figures/stalls.md`): the sample of [`SOURCES`] sources per length with
/// the `figures` command's defaults (`cycles.csv`'s scenes, lengths, T_c values and cache).
pub fn committed_table() -> Result<String> {
    let opts = FigureOptions {
        out: std::path::PathBuf::new(),
        seeds: 1,
        sources: SOURCES,
        rays: 1024,
        count: 1000,
        lengths: vec![4.0, 8.0, 16.0, 32.0, 64.0, 128.0],
        ray_set: crate::rays::RaySet::Angle,
        grid: crate::grid::GridParams::default(),
        shells: crate::trace::ShellParams::default(),
        progress: false,
        cosim_sources: 0,
        tcs: vec![1, 4, 16, 64],
        cache_lines: 1024,
        engine: crate::cosim::Engine::RustHdl,
    };
    let rows = measure(&opts, SOURCES)?;
    Ok(format!(
        "<!-- generated by tests/tier2/stalls.rs (SHELLING_BLESS=1 cargo test --release --features tier2 \
         --test tier2 stalls); the breakdown is src/figures/stalls.rs's -->\n\
         Per source, the means over source patches {:?} of each length's scene (a fresh PE per \
         source): cycles = commands + held + after the last command.\n\n{}",
        source_patches(1000, SOURCES),
        markdown(&rows)
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use shelling_hdl::pe::Watch;

    fn sample(offered: bool, ready: bool, watch: Watch) -> WatchSample {
        WatchSample { offered, ready, watch }
    }

    #[test]
    fn a_run_splits_into_commands_held_cycles_by_cause_and_the_drain() {
        let none = Watch::default();
        let sector = Watch { sector_waits: true, tags_full: true, ..none };
        let tags = Watch { tags_full: true, loader_full: true, ..none };
        let memory = Watch { loader_full: true, ..none };
        let downstream = Watch { loader_full: true, screener_holds: true, unit_starved: true, ..none };
        let rewind = Watch { fill_rewind: true, ..memory };
        let lookup = Watch { lookup: true, ..memory };
        let samples = [
            sample(false, true, none), // setup: before the run
            sample(true, true, none),
            sample(true, false, sector),
            sample(true, false, tags),
            sample(true, false, rewind),
            sample(true, false, memory),
            sample(true, false, downstream),
            sample(true, false, lookup), // the rewound request looked up: the wait ends
            sample(true, true, memory),  // taken: held flags do not count then
            sample(false, true, none),
            sample(false, true, none),
            sample(false, true, none), // after the run
        ];
        let b = Breakdown::of_run(&samples, 10).unwrap();
        let want = Breakdown {
            cycles: 10,
            commands: 2,
            sector: 1,
            tags: 1,
            memory: 3,
            downstream: 1,
            after: 2,
            starved: 1,
            fill_waits: 3,
            ..Breakdown::default()
        };
        assert_eq!(b, want);
    }

    #[test]
    fn a_gap_in_the_stream_a_hold_without_cause_or_a_short_record_is_an_error() {
        let none = Watch::default();
        let gap = [sample(true, true, none), sample(false, true, none), sample(true, true, none)];
        assert!(Breakdown::of_run(&gap, 3).unwrap_err().to_string().contains("no command"));
        let causeless = [sample(true, false, none)];
        assert!(Breakdown::of_run(&causeless, 1).unwrap_err().to_string().contains("no cause"));
        assert!(Breakdown::of_run(&causeless, 2).unwrap_err().to_string().contains("not all recorded"));
        assert!(Breakdown::of_run(&[sample(false, true, none)], 1)
            .unwrap_err()
            .to_string()
            .contains("offered"));
    }
}
