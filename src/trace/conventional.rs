//! The conventional technique (the paper's "processing with object dataflow"): ray by ray, the
//! grid is traversed cell by cell (empty space by macro-region jumps), and every candidate patch
//! of every non-empty cell is loaded for that ray and, if it passes the screener, tested.
//!
//! A patch listed in several cells is loaded once per ray (a per-ray mailbox). The walk stops at
//! the first cell whose exit lies beyond the nearest hit found so far (by more than the grid's
//! rounding margin, so exact ties across a cell boundary are still resolved by index).
//!
//! With a backend that does not observe the work-stream hooks ([`HitTest::HOOKS`]: the golden
//! model and the bit-true model, not the hardware's recorder), two shortcuts keep every hit and
//! every counter: a cell's *private* patches (registered in it alone, [`Grid::is_shared`]) need
//! no mailbox, since the walk enters each cell once, and they are screened once per source per
//! cell, the ones that pass kept in a list, so a ray's visit loads nothing it will not test; with
//! the golden model's test ([`HitTest::GOLDEN`]) that list is also kept four to a
//! [`FrontQuad`], whose filter rules out most of a ray's misses four patches at a time. The
//! cell's shared patches go through the mailbox as with any backend. `tests/tracers.rs`
//! compares both paths' hits and counters.
//!
//! [`Grid::is_shared`]: crate::grid::Grid::is_shared

use super::{offer, screen, with_scratch, CellPass, HitTest, SceneView, Scratch, Screen};
use crate::counters::Counters;
use crate::geom::{hit_front, FrontQuad, Hit};
use crate::rays::Bundle;

pub(super) fn trace<H: HitTest>(
    scene: SceneView<'_>,
    bundle: &Bundle,
    test: &H,
) -> (Vec<Option<Hit>>, Counters) {
    let grid = scene.grid;
    let margin = grid.stop_margin();
    let mut c = Counters::default();
    let mut hits = Vec::with_capacity(bundle.len());
    test.sector(0..bundle.len());
    with_scratch(scene, |scratch| {
        // Screening verdicts are computed when a patch is first loaded for this source; the
        // per-ray mailbox loads a patch listed in several cells once per ray.
        scratch.tick += 1;
        let source_tick = scratch.tick;
        scratch.pass_items.clear();
        scratch.pass_quads.clear();
        for (r, ray) in bundle.rays.iter().enumerate() {
            scratch.tick += 1;
            let ray_tick = scratch.tick;
            let mut best: Option<Hit> = None;
            grid.walk(ray.origin, ray.dir, |step| {
                c.cells_traversed += 1;
                if step.region.is_some() {
                    return true;
                }
                let items = grid.cell_items(step.cell);
                // The patches that go through the mailbox one by one: all of them with a backend
                // that observes the hooks, else the shared ones only.
                let mailboxed = if H::HOOKS {
                    items
                } else {
                    // A private patch meets this ray here only (no mailbox), and the cell's
                    // private patches are screened once for the source.
                    let pass = private_pass(scratch, scene, bundle, step.cell, source_tick);
                    let shared = grid.cell_shared_items(step.cell);
                    let passing = &scratch.pass_items[pass.start as usize..pass.end as usize];
                    c.patches_read_before_screening += (items.len() - shared.len()) as u64;
                    c.patches_read_after_screening += passing.len() as u64;
                    c.intersection_computations += passing.len() as u64;
                    if H::GOLDEN {
                        // Four patches at a time through the test's filter; the lanes it cannot
                        // call a miss go to the test itself.
                        let quads = &scratch.pass_quads[pass.quads as usize..];
                        for (four, q) in passing.chunks(4).zip(quads) {
                            let mut maybe = !q.certain_misses(ray) & ((1 << four.len()) - 1);
                            while maybe != 0 {
                                let p = four[maybe.trailing_zeros() as usize];
                                maybe &= maybe - 1;
                                if let Some(t) = hit_front(ray, &scene.segments[p as usize]) {
                                    offer(&mut best, Hit { t, segment: p });
                                }
                            }
                        }
                    } else {
                        for &p in passing {
                            if let Some(t) = test.hit(bundle, r, p, &scene.segments[p as usize]) {
                                offer(&mut best, Hit { t, segment: p });
                            }
                        }
                    }
                    shared
                };
                for &p in mailboxed {
                    let i = p as usize;
                    let slot = &mut scratch.mailbox[i];
                    if slot.ray == ray_tick {
                        continue;
                    }
                    slot.ray = ray_tick;
                    c.patches_read_before_screening += 1;
                    test.load(p);
                    let seg = &scene.segments[i];
                    if slot.screened >> 1 != source_tick {
                        let pass = screen(bundle, p, seg) == Screen::Pass;
                        slot.screened = source_tick << 1 | pass as u64;
                    }
                    if slot.screened & 1 == 0 {
                        continue;
                    }
                    c.patches_read_after_screening += 1;
                    c.intersection_computations += 1;
                    test.span(p, r..r + 1);
                    if let Some(t) = test.hit(bundle, r, p, seg) {
                        offer(&mut best, Hit { t, segment: p });
                    }
                }
                // Continue while a patch beyond this cell could still be nearer (or tie).
                !matches!(best, Some(b) if b.t < step.t_exit - margin)
            });
            hits.push(best);
        }
    });
    (hits, c)
}

/// The private patches of `cell` that pass the screener for the source of `source_tick`, as a
/// range of `scratch.pass_items` (and its quads from `pass_quads[quads]`): computed on the
/// source's first visit of the cell, looked up on the others.
fn private_pass(
    scratch: &mut Scratch,
    scene: SceneView<'_>,
    bundle: &Bundle,
    cell: usize,
    source_tick: u64,
) -> CellPass {
    let grid = scene.grid;
    if scratch.cell_pass[cell].stamp == source_tick {
        return scratch.cell_pass[cell];
    }
    let start = scratch.pass_items.len() as u32;
    let passing = grid
        .cell_items(cell)
        .iter()
        .filter(|&&p| !grid.is_shared(p) && screen(bundle, p, &scene.segments[p as usize]) == Screen::Pass);
    scratch.pass_items.extend(passing);
    let end = scratch.pass_items.len() as u32;
    let quads = scratch.pass_quads.len() as u32;
    for four in scratch.pass_items[start as usize..].chunks(4) {
        let mut q = FrontQuad::default();
        for (k, &p) in four.iter().enumerate() {
            q.set(k, &scene.segments[p as usize]);
        }
        scratch.pass_quads.push(q);
    }
    scratch.cell_pass[cell] = CellPass { stamp: source_tick, start, end, quads };
    scratch.cell_pass[cell]
}
