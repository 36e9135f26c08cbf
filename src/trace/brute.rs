//! The oracle: every ray of the bundle against every patch of the scene.
//!
//! Counters: every patch is read for every ray (`R·N` before screening); the patches that pass
//! the screener are tested (`after screening` = `intersection computations`). No cells.

use super::{offer, screen, HitTest, SceneView, Screen};
use crate::counters::Counters;
use crate::geom::Hit;
use crate::rays::Bundle;

pub(super) fn trace<H: HitTest>(
    scene: SceneView<'_>,
    bundle: &Bundle,
    test: &H,
) -> (Vec<Option<Hit>>, Counters) {
    let passing: Vec<u32> = (0..scene.segments.len() as u32)
        .filter(|&p| screen(bundle, p, &scene.segments[p as usize]) == Screen::Pass)
        .collect();
    let mut c = Counters::default();
    let r = bundle.len() as u64;
    c.patches_read_before_screening = r * scene.segments.len() as u64;
    c.patches_read_after_screening = r * passing.len() as u64;
    c.intersection_computations = c.patches_read_after_screening;
    let hits = (0..bundle.len())
        .map(|i| {
            let mut best = None;
            for &p in &passing {
                if let Some(t) = test.hit(bundle, i, p, &scene.segments[p as usize]) {
                    offer(&mut best, Hit { t, segment: p });
                }
            }
            best
        })
        .collect();
    (hits, c)
}
