//! Rung 1 in 3D, the long sweep: every 3D tracer against brute force on the 3D workload (1000
//! squares, sizes over two orders of magnitude), from many sources with sets of up to 1024 rays,
//! and on the closed scenes from every patch. Seeded; a failure names its seed, scene, source and
//! ray. Tier 1's `tests/tracers3d.rs` has the short version.

use crate::support::tracers3d::{agree_all, bundle_on, cornell, random_scenes};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use shelling::d3::gen::box_room;
use shelling::d3::grid::{Grid3, Grid3Params};

#[test]
fn every_tracer_matches_brute_on_the_3d_workload() {
    random_scenes(
        &[
            (11, 1000, 2.0),
            (12, 1000, 8.0),
            (13, 1000, 32.0),
            (14, 1000, 128.0),
            (15, 1000, 256.0),
            (16, 3000, 32.0),
            (17, 300, 500.0),
        ],
        80,
        32,
        16,
    );
}

#[test]
fn every_tracer_matches_brute_from_every_patch_of_the_closed_scenes() {
    let mut rng = ChaCha8Rng::seed_from_u64(900);
    for (name, scene) in [("box room", box_room()), ("Cornell box", cornell())] {
        let grid = Grid3::build(&scene, Grid3Params::default()).unwrap();
        for k in 0..scene.polygons.len() {
            let bundle = bundle_on(&scene, k, &mut rng, 32, 16);
            agree_all(&format!("seed 900: {name}, source on patch {k}"), &scene, &grid, &bundle);
        }
    }
}
