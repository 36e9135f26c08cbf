//! The work stream: recorded from every hardware technique's scheduler, executed item by item
//! in the bit-true models, it gives the bit-true tracer's hits, and it loads exactly the patches
//! the tracer counted.

use shelling::geom::Hit;
use shelling::grid::GridParams;
use shelling::rays::RaySet;
use shelling::run::GriddedScene;
use shelling::scene::{self, PAPER_WORLD};
use shelling::trace::{Method, ShellParams};
use shelling::workstream::{execute, Item};
use shelling_hdl::formats::key_distance;

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
