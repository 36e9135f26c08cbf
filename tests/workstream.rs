//! The work stream: recorded from every hardware technique's scheduler, executed item by item
//! in the bit-true models, it gives the bit-true tracer's hits, and it loads exactly the patches
//! the tracer counted.

use shelling::geom::Hit;
use shelling::grid::GridParams;
use shelling::rays::RaySet;
use shelling::run::GriddedScene;
use shelling::scene::{self, PAPER_WORLD};
use shelling::trace::{Method, ShellParams};
use shelling::workstream::{commands, execute, Item};
use shelling_hdl::formats::key_distance;
use shelling_testbench::pe::{model, Command};

const METHODS: [Method; 3] = [Method::Conventional, Method::Stochastic, Method::Deterministic];

#[test]
fn executing_the_stream_gives_the_bit_true_tracers_hits() {
    let params = ShellParams::default();
    for (length, seed) in [(4.0, 1u64), (32.0, 2), (128.0, 3)] {
        let scene = scene::generate(1000, length, seed, PAPER_WORLD).expect("scene");
        let prepared = GriddedScene::new(scene, GridParams::default());
        for k in [0usize, 517] {
            let bundle = prepared.patch_bundle(k, RaySet::Angle, 1024).expect("source");
            for m in METHODS {
                let what = format!("length {length} seed {seed} source {k} {m}");
                let s = prepared.schedule(m, &bundle, &params).expect("fits");
                let (hits, counts) = execute(&s.stream, &s.fixed).expect("a valid stream");
                let want: Vec<Option<Hit>> = s.trace.hits.clone();
                let got: Vec<Option<Hit>> = hits
                    .iter()
                    .map(|h| h.map(|n| Hit { t: key_distance(n.key), segment: n.id as u32 }))
                    .collect();
                assert_eq!(got, want, "{what}: hits");
                let c = &s.trace.counters;
                println!("{what}: {counts:?} tracer tests {}", c.intersection_computations);
                assert_eq!(counts.loads, c.patches_read_before_screening, "{what}: loads");
                // The hardware screens again, per sector: it tests no more than the tracer did.
                assert!(counts.tests <= c.intersection_computations, "{what}: {counts:?} vs {c:?}");
                assert!(counts.tests * 10 >= c.intersection_computations * 9, "{what}: {counts:?} vs {c:?}");
                assert!(counts.tests > 0 && counts.ray_slots >= counts.tests, "{what}: {counts:?}");
                let sectors = s.stream.items.iter().filter(|i| matches!(i, Item::Sector { .. })).count();
                match m {
                    Method::Conventional => assert_eq!((sectors, counts.retires), (1, 0), "{what}"),
                    _ => assert!(sectors as u64 == s.trace.stats.sectors && counts.retires > 0, "{what}"),
                }
            }
        }
    }
}

#[test]
fn the_host_trims_each_jobs_range_to_its_live_rays_and_loses_no_test() {
    let scene = scene::generate(1000, 16.0, 4, PAPER_WORLD).expect("scene");
    let prepared = GriddedScene::new(scene, GridParams::default());
    let bundle = prepared.patch_bundle(300, RaySet::Angle, 1024).expect("source");
    for m in [Method::Stochastic, Method::Deterministic] {
        let s = prepared.schedule(m, &bundle, &ShellParams::default()).expect("fits");
        let (setup, patches, cmds) = commands(&s.stream, &s.fixed).expect("a valid stream");
        // The untrimmed commands: each job with its range as the scheduler announced it.
        let mut jobs = s.stream.items.iter().filter_map(|i| match i {
            Item::Job { rays, .. } => Some(rays.clone()),
            _ => None,
        });
        let mut live = vec![true; s.stream.rays];
        let mut untrimmed = Vec::new();
        for c in &cmds {
            match *c {
                Command::Job { id, first, count } => {
                    let r = jobs.next().expect("one command per job");
                    let (lo, hi) = (first as u32, first as u32 + count as u32);
                    assert!(count == 0 || (r.start <= lo && hi <= r.end), "{m}: {c:?} outside {r:?}");
                    if count > 0 {
                        assert!(live[lo as usize] && live[hi as usize - 1], "{m}: {c:?} ends on a dead ray");
                    }
                    for ray in r.clone().filter(|&x| x < lo || x >= hi) {
                        assert!(!live[ray as usize], "{m}: {c:?} drops live ray {ray} of {r:?}");
                    }
                    untrimmed.push(Command::Job { id, first: r.start as u16, count: r.len() as u16 });
                }
                Command::Retire { first, count } => {
                    live[first as usize..(first + count) as usize].fill(false);
                    untrimmed.push(*c);
                }
                Command::Sector { .. } => untrimmed.push(*c),
            }
        }
        let (hits, trimmed) = model(&setup, &patches, &cmds);
        let (want, full) = model(&setup, &patches, &untrimmed);
        assert_eq!(hits, want, "{m}: hits");
        assert_eq!((trimmed.tests, trimmed.live_runs), (full.tests, full.live_runs), "{m}");
        assert!(trimmed.ray_slots < full.ray_slots, "{m}: nothing trimmed: {trimmed:?} vs {full:?}");
        assert!(trimmed.tests <= trimmed.ray_slots && trimmed.live_runs <= trimmed.tests, "{m}: {trimmed:?}");
        println!(
            "{m}: ray slots {} untrimmed, {} trimmed, {} tests in {} live runs",
            full.ray_slots, trimmed.ray_slots, trimmed.tests, trimmed.live_runs
        );
    }
}
