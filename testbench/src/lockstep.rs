//! Two threads stepping a machine's PE simulators in lockstep: each clock edge, the back half
//! of the PEs on a worker thread, the front half on the caller's, and the edge is over when
//! both are. The PEs of a machine share nothing within a cycle (the memory arbiter between them
//! is stepped before, by the caller), so splitting them changes no result, only the wall time:
//! a machine cycle of eight compiled PEs costs about half.
//!
//! An edge is a few microseconds of work, far less than waking a sleeping thread, so the worker
//! spins on an atomic generation counter while edges come; when none has come for a while (the
//! host between runs) it parks until the next, a millisecond at most.
//!
//! That pays only while the two threads have a core each. When the cores are busy with other
//! work (another machine run, a synthesis beside it), the thread that finishes its half first
//! waits for the other to be scheduled again, milliseconds an edge: two `machine-figures` runs
//! side by side on two cores took 78.8 s where one alone takes 2.3 s. So the caller watches its
//! waits ([`Pacer`]): when more than one edge in 32 of a window outlasted its spin, it steps
//! every PE itself for the next [`Pacer::ALONE`] edges (about a second), then tries two threads
//! again (the first window of a machine's life is not judged). The same two runs side by side
//! then took 7.3 s, with the same rows; on idle cores no round of `cargo bench --bench rtl --
//! --machine` stepped alone (20 rounds).

use crate::pe_sim::{PeInputs, PeSim};
use crate::{Error, Result};
use std::marker::PhantomData;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::Duration;

/// Spins on the counter before parking (the worker) or yielding (the caller).
const SPINS: u32 = 1 << 14;

/// What the caller hands the worker for one edge, and the worker's answer.
#[derive(Default)]
struct Shared {
    /// The edge to take: raised by the caller once the job's pointers are set.
    go: AtomicU64,
    /// The last edge the worker has taken.
    done: AtomicU64,
    stop: AtomicBool,
    /// The back half: its first simulator, its inputs, how many.
    sims: AtomicUsize,
    inputs: AtomicUsize,
    count: AtomicUsize,
    /// The first error (or panic) of the worker's half since the caller last looked.
    error: Mutex<Option<Error>>,
}

/// The worker thread of a machine of `S` simulators (see the [module documentation](self)).
pub struct Lockstep<S> {
    shared: Arc<Shared>,
    thread: Option<JoinHandle<()>>,
    edge: u64,
    pacer: Pacer,
    _sims: PhantomData<fn(S)>,
}

/// Whether the next edge is stepped on two threads or on the caller's alone, from how long the
/// caller waited for the worker at the last edges (see the [module documentation](self)).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Pacer {
    /// Edges of the current window on two threads, and those of them the caller waited out.
    edges: u32,
    late: u32,
    /// Edges left to step alone.
    alone: u32,
    /// Edges stepped on two threads and alone since the start.
    pub threaded_edges: u64,
    pub alone_edges: u64,
}

impl Pacer {
    /// Edges of one window on two threads (the first window of all is not judged).
    pub const WINDOW: u32 = 1 << 10;
    /// Waited-out edges in a window past which the caller steps alone.
    pub const LATE: u32 = Self::WINDOW / 32;
    /// Edges stepped alone before two threads are tried again (about a second of a machine).
    pub const ALONE: u32 = 1 << 18;

    /// Whether the coming edge goes on two threads.
    pub fn threaded(&self) -> bool {
        self.alone == 0
    }

    /// An edge was stepped: alone, or on two threads with the caller waiting past its spin
    /// (`late`) or not.
    pub fn stepped(&mut self, late: bool) {
        if self.alone > 0 {
            self.alone -= 1;
            self.alone_edges += 1;
            return;
        }
        self.threaded_edges += 1;
        // The first window warms up: the worker's first edges touch its PEs' memory for the
        // first time, and their waits (all of the first 33 in one bench round) are not the
        // cores'.
        if self.threaded_edges <= u64::from(Self::WINDOW) {
            return;
        }
        self.edges += 1;
        self.late += u32::from(late);
        if self.late > Self::LATE {
            self.alone = Self::ALONE;
        }
        if self.late > Self::LATE || self.edges == Self::WINDOW {
            (self.edges, self.late) = (0, 0);
        }
    }
}

impl<S: PeSim + Send + 'static> Lockstep<S> {
    /// Starts the worker thread; `None` if the system has one core only or the thread cannot
    /// be made (the caller then steps every PE itself).
    pub fn start() -> Option<Self> {
        if std::thread::available_parallelism().map_or(1, |n| n.get()) < 2 {
            return None;
        }
        let shared = Arc::new(Shared::default());
        let theirs = Arc::clone(&shared);
        let thread =
            std::thread::Builder::new().name("pe-lockstep".into()).spawn(move || work::<S>(&theirs)).ok()?;
        Some(Self { shared, thread: Some(thread), edge: 0, pacer: Pacer::default(), _sims: PhantomData })
    }
}

impl<S: PeSim> Lockstep<S> {
    /// One clock edge of every simulator: `sims[p]` takes `inputs[p]` (its drive and its
    /// edge, [`PeSim::cycle`]). The first error of either half is returned, after both are done.
    pub fn cycle(&mut self, sims: &mut [S], inputs: &[PeInputs]) -> Result<()> {
        assert_eq!(sims.len(), inputs.len(), "one set of inputs a PE");
        if !self.pacer.threaded() {
            self.pacer.stepped(false);
            return step(sims, inputs);
        }
        let half = sims.len() / 2;
        let (front, back) = sims.split_at_mut(half);
        let s = &self.shared;
        s.sims.store(back.as_mut_ptr() as usize, Ordering::Relaxed);
        s.inputs.store(inputs[half..].as_ptr() as usize, Ordering::Relaxed);
        s.count.store(back.len(), Ordering::Relaxed);
        self.edge += 1;
        s.go.store(self.edge, Ordering::Release);
        if let Some(t) = &self.thread {
            t.thread().unpark();
        }
        let mine = step(front, inputs);
        // The back half is borrowed until the worker has taken this edge.
        let mut spins = 0u32;
        while s.done.load(Ordering::Acquire) != self.edge {
            if spins < SPINS {
                spins += 1;
                std::hint::spin_loop();
            } else {
                std::thread::yield_now();
            }
        }
        self.pacer.stepped(spins == SPINS);
        let theirs = s.error.lock().map_or(None, |mut e| e.take());
        mine?;
        theirs.map_or(Ok(()), Err)
    }
}

impl<S> Lockstep<S> {
    /// How the edges so far were stepped.
    pub fn pacer(&self) -> &Pacer {
        &self.pacer
    }
}

/// One clock edge of each simulator on the calling thread: `sims[p]` takes `inputs[p]`.
pub fn step<S: PeSim>(sims: &mut [S], inputs: &[PeInputs]) -> Result<()> {
    sims.iter_mut().zip(inputs).try_for_each(|(sim, &i)| sim.cycle(|x| *x = i))
}

/// The worker: each edge raised, the back half's cycles; parks when edges stop coming.
fn work<S: PeSim + Send>(s: &Shared) {
    let mut taken = 0u64;
    loop {
        let mut spins = 0u32;
        let edge = loop {
            let g = s.go.load(Ordering::Acquire);
            if g != taken {
                break g;
            }
            if s.stop.load(Ordering::Relaxed) {
                return;
            }
            if spins < SPINS {
                spins += 1;
                std::hint::spin_loop();
            } else {
                std::thread::park_timeout(Duration::from_millis(1));
            }
        };
        let (sims, inputs, n) = (
            s.sims.load(Ordering::Relaxed),
            s.inputs.load(Ordering::Relaxed),
            s.count.load(Ordering::Relaxed),
        );
        let stepped = catch_unwind(AssertUnwindSafe(|| {
            // SAFETY: the caller published `n` simulators and `n` inputs from its `&mut [S]` and
            // `&[PeInputs]` and waits, without touching them, until `done` shows this edge.
            let (sims, inputs) = unsafe {
                (
                    std::slice::from_raw_parts_mut(sims as *mut S, n),
                    std::slice::from_raw_parts(inputs as *const PeInputs, n),
                )
            };
            step(sims, inputs)
        }));
        let failed = match stepped {
            Ok(r) => r.err(),
            Err(_) => Some(Error::new("a PE simulator panicked on the lockstep thread")),
        };
        if let Some(e) = failed {
            if let Ok(mut slot) = s.error.lock() {
                slot.get_or_insert(e);
            }
        }
        taken = edge;
        s.done.store(edge, Ordering::Release);
    }
}

impl<S> Drop for Lockstep<S> {
    fn drop(&mut self) {
        self.shared.stop.store(true, Ordering::Relaxed);
        if let Some(t) = self.thread.take() {
            t.thread().unpark();
            let _ = t.join();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Pacer;

    /// Feeds `n` edges, every `every`-th of them waited out (none if 0).
    fn feed(p: &mut Pacer, n: u32, every: u32) {
        for i in 0..n {
            p.stepped(every != 0 && i % every == 0);
        }
    }

    #[test]
    fn the_pacer_keeps_two_threads_while_the_waits_are_rare() {
        let mut p = Pacer::default();
        // Every edge of the first window waited out (the warm-up), then one wait in 64 edges:
        // half the threshold, window after window.
        feed(&mut p, Pacer::WINDOW, 1);
        feed(&mut p, 16 * Pacer::WINDOW, 64);
        assert!(p.threaded());
        assert_eq!((p.threaded_edges, p.alone_edges), (17 * u64::from(Pacer::WINDOW), 0));
    }

    #[test]
    fn the_pacer_steps_alone_for_a_while_when_the_waits_are_many_then_tries_again() {
        let mut p = Pacer::default();
        feed(&mut p, Pacer::WINDOW, 0);
        // Every fourth edge waited out, the first included: over the threshold at the last edge.
        feed(&mut p, 4 * Pacer::LATE + 1, 4);
        assert!(!p.threaded(), "{p:?}");
        let threaded = p.threaded_edges;
        assert_eq!(threaded, u64::from(Pacer::WINDOW + 4 * Pacer::LATE + 1));
        // Alone for ALONE edges, whatever they report, then two threads again.
        feed(&mut p, Pacer::ALONE, 1);
        assert!(p.threaded(), "{p:?}");
        assert_eq!((p.threaded_edges, p.alone_edges), (threaded, u64::from(Pacer::ALONE)));
        // And the window starts afresh: the waits before stepping alone do not count.
        feed(&mut p, Pacer::WINDOW, 0);
        assert!(p.threaded());
    }
}
