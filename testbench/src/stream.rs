//! Streams: seeded random stall patterns for the two ends of a handshake.
//!
//! - [`Pacing`] says which stalls are on: random idle cycles at the producer, random
//!   backpressure at the consumer. [`Pacing::ALL`] lists the four combinations; run every
//!   stream test under each.
//! - [`Source`] is the producer side: it holds a queue of items and, each cycle, decides whether
//!   to present the head item.
//! - [`Monitor`] is the consumer side: each cycle it decides whether it is ready, and records
//!   the items transferred, with their cycle.
//!
//! Both are independent of any block: the test reads and writes the handshake signals itself,
//! in the two phases of a [`Driver`](crate::Driver) cycle. In the drive phase, ask
//! [`Source::present`] what to offer and [`Monitor::ready`] whether to accept; in the settled
//! state before the edge, tell [`Source::accepted`] whether the transfer happens and let
//! [`Monitor::observe`] take the item; then [`Driver::tick`](crate::Driver::tick).
//!
//! - valid/ready: `present(true)` drives `valid`; a transfer is `valid && ready`.
//! - write/full (rust-hdl FIFOs): `present(!full)`, since a write while full is lost; the
//!   transfer is `write`. On the read side drive `read = ready && !empty`, observe `!empty`.
//!
//! A FIFO under random idle cycles and backpressure:
//!
//! ```
//! # use rust_hdl::prelude::*;
//! # use shelling_testbench::{Driver, Monitor, Pacing, Source};
//! # #[derive(LogicBlock, Default)]
//! # struct Fifo {
//! #     pub clock: Signal<In, Clock>,
//! #     pub write: Signal<In, Bit>,
//! #     pub data_in: Signal<In, Bits<8>>,
//! #     pub full: Signal<Out, Bit>,
//! #     pub read: Signal<In, Bit>,
//! #     pub data_out: Signal<Out, Bits<8>>,
//! #     pub empty: Signal<Out, Bit>,
//! #     fifo: SynchronousFIFO<Bits<8>, 2, 3, 1>,
//! # }
//! # impl Logic for Fifo {
//! #     #[hdl_gen]
//! #     fn update(&mut self) {
//! #         self.fifo.clock.next = self.clock.val();
//! #         self.fifo.write.next = self.write.val();
//! #         self.fifo.data_in.next = self.data_in.val();
//! #         self.fifo.read.next = self.read.val();
//! #         self.full.next = self.fifo.full.val();
//! #         self.data_out.next = self.fifo.data_out.val();
//! #         self.empty.next = self.fifo.empty.val();
//! #     }
//! # }
//! # fn main() -> shelling_testbench::Result<()> {
//! let (seed, pacing) = (42, Pacing { idle: true, backpressure: true });
//! let items: Vec<u8> = (0..200).collect();
//! let mut src = Source::new(items.iter().copied(), pacing, seed);
//! let mut mon = Monitor::new(pacing, seed);
//! let mut drv = Driver::with_clock(Fifo::default(), |f| &mut f.clock)?;
//! while mon.items().len() < items.len() {
//!     drv.drive(|u| {
//!         let item = src.present(!u.full.val());
//!         u.write.next = item.is_some();
//!         u.data_in.next = bits(item.copied().unwrap_or_default().into());
//!         u.read.next = mon.ready() && !u.empty.val();
//!     })?;
//!     let u = drv.uut(); // settled, before the rising edge
//!     src.accepted(u.write.val())?;
//!     mon.observe(drv.cycles(), !u.empty.val(), || u.data_out.val().to_u8());
//!     drv.tick()?;
//! }
//! let got: Vec<u8> = mon.items().iter().map(|r| r.item).collect();
//! assert_eq!(got, items, "seed {seed}, {pacing}");
//! # Ok(())
//! # }
//! ```
//!
//! All randomness comes from ChaCha8 seeded with a `u64`: the same seed gives the same stall
//! pattern. The source and the monitor draw from different streams of the same seed, so one
//! seed per test is enough; print it on failure (see [`Error::context`]).

use std::collections::VecDeque;
use std::fmt;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::{Error, Result};

/// Which random stalls a stream test applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Pacing {
    /// The producer inserts random idle cycles (it presents nothing).
    pub idle: bool,
    /// The consumer applies random backpressure (it is not ready).
    pub backpressure: bool,
}

impl Pacing {
    /// Neither idle cycles nor backpressure: full throughput.
    pub const NONE: Pacing = Pacing { idle: false, backpressure: false };
    /// The four combinations of {no idle, random idle} × {no backpressure, random backpressure}.
    pub const ALL: [Pacing; 4] = [
        Pacing::NONE,
        Pacing { idle: true, backpressure: false },
        Pacing { idle: false, backpressure: true },
        Pacing { idle: true, backpressure: true },
    ];
    /// Probability of an idle cycle, or of a not-ready cycle, when that stall is on.
    pub const STALL_PROBABILITY: f64 = 0.3;
}

impl fmt::Display for Pacing {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match (self.idle, self.backpressure) {
            (false, false) => "no stalls",
            (true, false) => "random idle",
            (false, true) => "random backpressure",
            (true, true) => "random idle + backpressure",
        })
    }
}

/// ChaCha8 stream numbers, so that a source and a monitor built from one seed are independent.
const SOURCE_STREAM: u64 = 1;
const MONITOR_STREAM: u64 = 2;

/// A Bernoulli stall generator on its own ChaCha8 stream.
#[derive(Clone, Debug)]
struct Stalls {
    rng: ChaCha8Rng,
    on: bool,
}

impl Stalls {
    fn new(seed: u64, stream: u64, on: bool) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        rng.set_stream(stream);
        Self { rng, on }
    }

    /// Whether this cycle stalls.
    fn draw(&mut self) -> bool {
        self.on && self.rng.random_bool(Pacing::STALL_PROBABILITY)
    }
}

/// The producer end of a handshake: offers queued items in order, with random idle cycles
/// (see the [module docs](self)).
#[derive(Clone, Debug)]
pub struct Source<T> {
    queue: VecDeque<T>,
    stalls: Stalls,
    /// The head item was presented this cycle (and, until accepted, must stay presented).
    presented: bool,
    sent: usize,
}

impl<T> Source<T> {
    /// A source of `items`, stalling as `pacing.idle` says, with stall pattern `seed`.
    pub fn new(items: impl IntoIterator<Item = T>, pacing: Pacing, seed: u64) -> Self {
        Self {
            queue: items.into_iter().collect(),
            stalls: Stalls::new(seed, SOURCE_STREAM, pacing.idle),
            presented: false,
            sent: 0,
        }
    }

    /// Drive phase, once per cycle: the item to present this cycle, or `None` (idle, blocked or
    /// nothing left). `allowed` is false when presenting is forbidden this cycle (a FIFO's
    /// `full`); pass `true` for valid/ready. An item presented but not yet accepted is presented
    /// again without an idle draw: valid must not drop before the transfer.
    pub fn present(&mut self, allowed: bool) -> Option<&T> {
        let keep = self.presented;
        self.presented = allowed && !self.queue.is_empty() && (keep || !self.stalls.draw());
        if self.presented {
            self.queue.front()
        } else {
            None
        }
    }

    /// Edge phase, once per cycle: whether the item presented this cycle was transferred
    /// (valid && ready, or write && !full). Fails if a transfer is reported for a cycle in
    /// which nothing was presented.
    pub fn accepted(&mut self, transferred: bool) -> Result<()> {
        if !transferred {
            return Ok(());
        }
        if !self.presented {
            return Err(Error::new(format!(
                "source: a transfer was reported after item #{} although nothing was presented",
                self.sent
            )));
        }
        self.queue.pop_front();
        self.presented = false;
        self.sent += 1;
        Ok(())
    }

    /// Items transferred so far.
    pub fn sent(&self) -> usize {
        self.sent
    }

    /// Whether every item has been transferred.
    pub fn is_done(&self) -> bool {
        self.queue.is_empty()
    }
}

/// An item collected by a [`Monitor`], with the cycle (the [`Driver::cycles`](crate::Driver::cycles)
/// value passed to [`Monitor::observe`]) of its transfer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Received<T> {
    /// Cycle of the transfer.
    pub cycle: u64,
    /// The item.
    pub item: T,
}

/// The consumer end of a handshake: random backpressure, and a log of what was transferred
/// (see the [module docs](self)).
#[derive(Clone, Debug)]
pub struct Monitor<T> {
    stalls: Stalls,
    ready: bool,
    items: Vec<Received<T>>,
}

impl<T> Monitor<T> {
    /// A monitor applying backpressure as `pacing.backpressure` says, with stall pattern `seed`.
    pub fn new(pacing: Pacing, seed: u64) -> Self {
        Self { stalls: Stalls::new(seed, MONITOR_STREAM, pacing.backpressure), ready: false, items: vec![] }
    }

    /// Drive phase, once per cycle: whether the consumer is ready this cycle.
    pub fn ready(&mut self) -> bool {
        self.ready = !self.stalls.draw();
        self.ready
    }

    /// Edge phase, once per cycle: if `valid` and this cycle's [`ready`](Self::ready) was true,
    /// reads the item with `read` and records it. Returns whether a transfer happened.
    pub fn observe(&mut self, cycle: u64, valid: bool, read: impl FnOnce() -> T) -> bool {
        let transfer = valid && self.ready;
        if transfer {
            self.items.push(Received { cycle, item: read() });
        }
        transfer
    }

    /// The items transferred so far, in order.
    pub fn items(&self) -> &[Received<T>] {
        &self.items
    }

    /// The items transferred, in order.
    pub fn into_items(self) -> Vec<Received<T>> {
        self.items
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A one-place valid/ready register slice in plain Rust, drained by the monitor: checks the
    /// source's stickiness and ordering under every pacing.
    #[test]
    fn source_and_monitor_through_a_register_slice() -> Result<()> {
        for pacing in Pacing::ALL {
            let seed = 0x5eed;
            let items: Vec<u32> = (0..2000).collect();
            let mut src = Source::new(items.clone(), pacing, seed);
            let mut mon = Monitor::new(pacing, seed);
            let mut slot: Option<u32> = None;
            let mut cycle = 0;
            let mut last_offer: Option<u32> = None;
            while mon.items().len() < items.len() {
                let slice_ready = slot.is_none();
                let offer = src.present(true).copied();
                if let Some(prev) = last_offer {
                    if offer != Some(prev) {
                        return Err(Error::new(format!("{pacing}: dropped valid on {prev} before transfer")));
                    }
                }
                mon.ready();
                // Edge: output transfer, then input transfer into the freed slot.
                let out = slot;
                if mon.observe(cycle, out.is_some(), || out.unwrap_or_default()) {
                    slot = None;
                }
                let transfer = offer.is_some() && slice_ready;
                src.accepted(transfer)?;
                if transfer {
                    slot = offer;
                }
                last_offer = if transfer { None } else { offer };
                cycle += 1;
                if cycle > 100 * items.len() as u64 {
                    return Err(Error::new(format!("{pacing}: no progress")));
                }
            }
            let got: Vec<u32> = mon.into_items().into_iter().map(|r| r.item).collect();
            assert_eq!(got, items, "{pacing}, seed {seed:#x}");
            assert!(src.is_done() && src.sent() == items.len());
        }
        Ok(())
    }

    #[test]
    fn transfer_without_offer_is_an_error() {
        let mut src = Source::new([1u8], Pacing::NONE, 1);
        assert!(src.present(false).is_none());
        assert!(src.accepted(true).is_err());
    }

    #[test]
    fn stalls_follow_the_pacing_and_the_seed() -> Result<()> {
        let idle_cycles = |pacing, seed| -> Result<usize> {
            let mut src = Source::new(std::iter::repeat_n(0u8, 1000), pacing, seed);
            let mut idle = 0;
            for _ in 0..1000 {
                let offered = src.present(true).is_some();
                idle += usize::from(!offered);
                src.accepted(offered)?;
            }
            Ok(idle)
        };
        assert_eq!(idle_cycles(Pacing::NONE, 7)?, 0);
        let pacing = Pacing { idle: true, backpressure: false };
        let n = idle_cycles(pacing, 7)?;
        assert!((200..400).contains(&n), "{n} idle cycles of 1000 at p = 0.3");
        assert_eq!(n, idle_cycles(pacing, 7)?);
        assert_ne!(n, idle_cycles(pacing, 8)?);
        Ok(())
    }
}
