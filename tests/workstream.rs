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
use shelling_hdl::formats::{key_distance, Nearest};
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
                let count = |f: fn(&Item) -> bool| s.stream.items.iter().filter(|&i| f(i)).count() as u64;
                let sectors = count(|i| matches!(i, Item::Sector { .. }));
                let retired = count(|i| matches!(i, Item::Retire { .. }));
                // The PE is told only the retirements a later job's range needs.
                assert!(counts.retires <= retired, "{what}: {counts:?}, {retired} retired");
                match m {
                    Method::Conventional => assert_eq!((sectors, retired), (1, 0), "{what}"),
                    _ => assert!(sectors == s.trace.stats.sectors && retired > 0, "{what}"),
                }
            }
        }
    }
}

#[test]
fn the_host_trims_each_jobs_range_and_retires_late_and_loses_no_test() {
    let scene = scene::generate(1000, 16.0, 4, PAPER_WORLD).expect("scene");
    let prepared = GriddedScene::new(scene, GridParams::default());
    let bundle = prepared.patch_bundle(300, RaySet::Angle, 1024).expect("source");
    for m in [Method::Stochastic, Method::Deterministic] {
        let s = prepared.schedule(m, &bundle, &ShellParams::default()).expect("fits");
        let (setup, patches, cmds) = commands(&s.stream, &s.fixed).expect("a valid stream");
        let mut sent = cmds.iter().filter(|c| matches!(c, Command::Job { .. }));
        // The eager, untrimmed commands: each item as it comes, each job with its range as the
        // scheduler announced it, each retirement at once.
        let mut live = vec![true; s.stream.rays];
        let mut eager = Vec::new();
        for it in &s.stream.items {
            match *it {
                Item::Job { patch, ref rays } => {
                    let c = *sent.next().expect("one command per job");
                    let Command::Job { id, first, count } = c else { unreachable!() };
                    let (lo, hi) = (first as u32, first as u32 + count as u32);
                    assert_eq!(id as u32, patch, "{m}: {c:?}");
                    assert!(
                        count == 0 || (rays.start <= lo && hi <= rays.end),
                        "{m}: {c:?} outside {rays:?}"
                    );
                    if count > 0 {
                        assert!(live[lo as usize] && live[hi as usize - 1], "{m}: {c:?} ends on a dead ray");
                    }
                    for ray in rays.clone().filter(|&x| x < lo || x >= hi) {
                        assert!(!live[ray as usize], "{m}: {c:?} drops live ray {ray} of {rays:?}");
                    }
                    eager.push(Command::Job { id, first: rays.start as u16, count: rays.len() as u16 });
                }
                Item::Retire { ray } => {
                    live[ray as usize] = false;
                    eager.push(Command::Retire { first: ray as u16, count: 1 });
                }
                Item::Sector { ref rays } => eager.push(Command::Sector {
                    first: s.fixed.dirs[rays.start as usize],
                    last: s.fixed.dirs[rays.end as usize - 1],
                }),
            }
        }
        assert!(sent.next().is_none(), "{m}: more job commands than jobs");
        let (hits, late) = model(&setup, &patches, &cmds);
        let (want, full) = model(&setup, &patches, &eager);
        assert_eq!(hits, want, "{m}: hits");
        assert_eq!((late.tests, late.live_runs, late.loads), (full.tests, full.live_runs, full.loads), "{m}");
        assert!(late.ray_slots < full.ray_slots, "{m}: nothing trimmed: {late:?} vs {full:?}");
        assert!(late.retires < full.retires, "{m}: no retirement saved: {late:?} vs {full:?}");
        assert!(late.tests <= late.ray_slots && late.live_runs <= late.tests, "{m}: {late:?}");
        println!(
            "{m}: ray slots {} untrimmed, {} trimmed, {} tests in {} live runs; rays retired in the PE {} of {}",
            full.ray_slots, late.ray_slots, late.tests, late.live_runs, late.retires, full.retires
        );
    }
}

#[test]
fn a_pack_of_bundles_from_one_origin_gives_each_bundles_hits() {
    // Two bundles from one source of a scene packed into one source of the PE: the bit-true
    // model of the pack gives each bundle's own hits, the second's patches numbered after the
    // first's. Bundles from two origins, or more rays than the PE holds, are refused.
    use shelling::workstream::pack;
    let params = ShellParams::default();
    let scene = scene::generate(300, 16.0, 5, PAPER_WORLD).expect("scene");
    let prepared = GriddedScene::new(scene, GridParams::default());
    let a = prepared.patch_bundle(3, RaySet::Angle, 512).expect("source");
    let b = prepared.patch_bundle(3, RaySet::Angle, 256).expect("source");
    let (sa, sb) = (
        prepared.schedule(Method::Deterministic, &a, &params).unwrap(),
        prepared.schedule(Method::Stochastic, &b, &params).unwrap(),
    );
    let (setup, patches, cmds) = pack(&[(&sa.stream, &sa.fixed), (&sb.stream, &sb.fixed)]).unwrap();
    assert_eq!((setup.dirs.len(), patches.len()), (768, 600));
    let (hits, _) = model(&setup, &patches, &cmds);
    let mut want = Vec::new();
    for (s, base) in [(&sa, 0u16), (&sb, 300)] {
        let (setup, patches, cmds) = commands(&s.stream, &s.fixed).unwrap();
        want.extend(
            model(&setup, &patches, &cmds).0.into_iter().map(|h| h.map(|n| Nearest { id: n.id + base, ..n })),
        );
    }
    assert_eq!(hits, want);
    assert!(hits.iter().flatten().count() > 300, "the bundles hit too little to tell");
    let other = prepared
        .schedule(Method::Deterministic, &prepared.patch_bundle(4, RaySet::Angle, 64).unwrap(), &params)
        .unwrap();
    let e = pack(&[(&sa.stream, &sa.fixed), (&other.stream, &other.fixed)]).unwrap_err().to_string();
    assert!(e.contains("another ray origin"), "{e}");
    let e = pack(&[(&sa.stream, &sa.fixed), (&sa.stream, &sa.fixed), (&sb.stream, &sb.fixed)]).unwrap_err();
    assert!(e.to_string().contains("1280 rays"), "{e}");
}
