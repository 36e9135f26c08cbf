//! Cycle driver: steps a rust-hdl block from a plain loop, one call per clock cycle.
//!
//! rust-hdl's own `Simulation` runs every testbench and the clock in threads and hands the whole
//! design across channels on every edge (~6–9k cycles/s). [`Driver`] instead owns the block and
//! runs rust-hdl's settle loop (update passes over the whole design until nothing changes)
//! directly, which is 100× faster.
//!
//! # Cycle convention
//!
//! One clock cycle is:
//!
//! 1. **drive** ([`Driver::drive`]): the clock goes low and the caller's closure sets the inputs'
//!    `.next`; the design settles. The closure sees the block as it was after the previous rising
//!    edge settled, so it may read outputs (`u.full.val()`) to decide what to drive.
//! 2. **edge** ([`Driver::tick`]): the clock rises and the design settles again. Registers now
//!    hold what they captured; outputs read through [`Driver::uut`] are this cycle's results.
//!
//! [`Driver::cycle`] does both. Between the two calls, [`Driver::uut`] shows the settled
//! pre-edge state: the values the registers are about to capture, which is where a
//! valid/ready handshake is decided (see [`crate::stream`]).
//!
//! The falling edge is settled together with the next cycle's inputs (one settle saved per
//! cycle). Blocks must therefore be rising-edge only, as rust-hdl's widgets are (none uses
//! `neg_edge`). Inputs must only change in the drive phase: an input changed in
//! the same settle as the rising edge would be captured as its *new* value.
//!
//! # Cost: update passes
//!
//! Every settle pass runs every block's `update` and moves every signal's `.next` into its
//! value, so the simulation's cost is the passes per cycle ([`Driver::passes`]) times the design's
//! size. The clock is set with `force` (vendored rust-hdl-core, `vendor/README.md`): the top
//! block sees the new level in the first pass instead of the second, and a child block sees its
//! clock's edge in the pass its parent forwards it, not one pass later. A flat block such as the
//! intersection unit settles a cycle in five passes (eight with upstream rust-hdl): one in which
//! the registers capture, one in which the logic after them computes, one that finds nothing
//! changed, and two for the drive phase (three when an input changes). Every register still
//! captures the value its input had before the edge: a value takes at least one pass to climb
//! out of a block and one to enter another, and a block `k` levels deep captures in pass `k`,
//! one pass after its parent.
//!
//! # Clock access
//!
//! Every block of this project has a field `pub clock: Signal<In, Clock>`. [`Driver::new`]
//! takes a block implementing [`Clocked`] (one line with [`impl_clocked!`](crate::impl_clocked));
//! [`Driver::with_clock`] takes any block plus a function returning its clock, for the cases the
//! orphan rule forbids the impl (a foreign block used in an integration test).
//!
//! See the [crate-level example](crate) for a complete test.

use std::ops::RangeBounds;
use std::path::{Path, PathBuf};

use rust_hdl::core::prelude::{check_all, Atom, Block, Clock, In, Signal};

use crate::replay::{Recorder, Recording};
use crate::vcd_stream::VcdStream;
use crate::{Error, Result};

/// A block with a clock input. Implement it with [`impl_clocked!`](crate::impl_clocked) for
/// blocks whose clock field is named `clock`.
pub trait Clocked: Block {
    /// The block's clock input.
    fn clock(&mut self) -> &mut Signal<In, Clock>;
}

/// Implements [`Clocked`] for one or more block types whose clock field is `pub clock`:
/// `impl_clocked!(Pipe, Fifo);`. The types must be local to the crate that invokes the macro
/// (orphan rule); otherwise use [`Driver::with_clock`].
#[macro_export]
macro_rules! impl_clocked {
    ($($block:ty),+ $(,)?) => {
        $(
            impl $crate::Clocked for $block {
                fn clock(
                    &mut self,
                ) -> &mut $crate::rust_hdl::core::prelude::Signal<
                    $crate::rust_hdl::core::prelude::In,
                    $crate::rust_hdl::core::prelude::Clock,
                > {
                    &mut self.clock
                }
            }
        )+
    };
}

/// How many update passes a settle may take before the design is declared non-convergent.
/// Each pass propagates values one level deeper through the block hierarchy and its
/// combinational logic, so a deep design may need [`Driver::with_settle_limit`].
pub const DEFAULT_SETTLE_LIMIT: usize = 100;

/// Owns a rust-hdl block and steps it cycle by cycle (see the [module docs](self)).
pub struct Driver<B: Block> {
    uut: Box<B>,
    clock: fn(&mut B) -> &mut Signal<In, Clock>,
    cycles: u64,
    passes: u64,
    settle_limit: usize,
    vcd: Option<VcdStream>,
    recorder: Option<Recorder>,
}

impl<B: Clocked> Driver<B> {
    /// Connects and checks the block (rust-hdl's `connect_all` and `check_all`) and settles it
    /// at power-up with the clock low. Fails with the check's report if a signal is left open,
    /// a logic loop exists or an input is written, and if the design does not settle.
    pub fn new(uut: B) -> Result<Self> {
        Self::with_clock(uut, B::clock)
    }
}

impl<B: Block> Driver<B> {
    /// Like [`Driver::new`] for a block that does not implement [`Clocked`]: `clock` returns
    /// its clock input, e.g. `Driver::with_clock(fifo, |f| &mut f.clock)`.
    pub fn with_clock(uut: B, clock: fn(&mut B) -> &mut Signal<In, Clock>) -> Result<Self> {
        let mut uut = Box::new(uut);
        uut.connect_all();
        check_all(uut.as_ref())
            .map_err(|e| Error::new(format!("rust-hdl connectivity check failed: {e:?}")))?;
        let mut driver = Self {
            uut,
            clock,
            cycles: 0,
            passes: 0,
            settle_limit: DEFAULT_SETTLE_LIMIT,
            vcd: None,
            recorder: None,
        };
        driver.settle("power-up")?;
        Ok(driver)
    }

    /// Sets how many update passes one settle may take (default [`DEFAULT_SETTLE_LIMIT`]).
    pub fn with_settle_limit(mut self, passes: usize) -> Self {
        self.settle_limit = passes;
        self
    }

    /// The block, settled after the last [`drive`](Self::drive) or [`tick`](Self::tick).
    pub fn uut(&self) -> &B {
        &self.uut
    }

    /// Rising edges so far. During the drive phase of the first cycle this is 0; after the
    /// `n`-th [`tick`](Self::tick) it is `n`.
    pub fn cycles(&self) -> u64 {
        self.cycles
    }

    /// Update passes over the whole design so far (every settle, power-up included): the
    /// simulation's cost. A cycle of a flat block takes about five.
    pub fn passes(&self) -> u64 {
        self.passes
    }

    /// Drive phase: clock low, `set_inputs` writes the inputs' `.next`, the design settles.
    /// May be called more than once before a [`tick`](Self::tick); the last values count.
    pub fn drive(&mut self, set_inputs: impl FnOnce(&mut B)) -> Result<()> {
        (self.clock)(&mut self.uut).force(Clock::from(false));
        set_inputs(&mut self.uut);
        self.settle("drive")
    }

    /// Edge phase: records and dumps the settled pre-edge state (when enabled), raises the clock,
    /// settles, then records and dumps the post-edge state. Counts the cycle.
    pub fn tick(&mut self) -> Result<()> {
        if let Some(rec) = &mut self.recorder {
            rec.sample_before_edge(self.uut.as_ref())?;
        }
        if let Some(vcd) = &mut self.vcd {
            vcd.sample(self.uut.as_ref(), self.cycles, false);
        }
        (self.clock)(&mut self.uut).force(Clock::from(true));
        self.settle("rising edge")?;
        if let Some(rec) = &mut self.recorder {
            rec.sample_after_edge(self.uut.as_ref())?;
        }
        if let Some(vcd) = &mut self.vcd {
            vcd.sample(self.uut.as_ref(), self.cycles, true);
        }
        self.cycles += 1;
        Ok(())
    }

    /// One whole cycle: [`drive`](Self::drive) with `set_inputs`, then [`tick`](Self::tick).
    pub fn cycle(&mut self, set_inputs: impl FnOnce(&mut B)) -> Result<()> {
        self.drive(set_inputs)?;
        self.tick()
    }

    /// `n` cycles with the inputs left as they are.
    pub fn idle(&mut self, n: u64) -> Result<()> {
        for _ in 0..n {
            self.cycle(|_| {})?;
        }
        Ok(())
    }

    /// Starts streaming a VCD of the whole design to `path` (parent directories are created).
    /// The header (all signals, named by the block hierarchy) is written now; value changes are
    /// written only for cycles in `window` (e.g. `..` for all, `1000..1200`). Cycle `c` spans
    /// `c * 1000 ps` (inputs applied, clock low) to `c * 1000 + 500 ps` (rising edge). Replaces
    /// a stream already open, which is closed first.
    pub fn stream_vcd(&mut self, path: impl AsRef<Path>, window: impl RangeBounds<u64>) -> Result<()> {
        self.finish_vcd()?;
        self.vcd = Some(VcdStream::create(path.as_ref(), self.uut.as_ref(), window)?);
        Ok(())
    }

    /// Flushes and closes the VCD stream, reporting any write error. Returns the file's path,
    /// or `None` if no stream was open. Dropping the driver also flushes, but silently.
    pub fn finish_vcd(&mut self) -> Result<Option<PathBuf>> {
        match self.vcd.take() {
            Some(vcd) => vcd.finish().map(Some),
            None => Ok(None),
        }
    }

    /// Starts recording the top-level ports every cycle for [`Recording::replay`]. Must be
    /// called before the first cycle: the Verilog replay starts from power-up.
    pub fn record_ports(&mut self) -> Result<()> {
        if self.cycles != 0 {
            return Err(Error::new(format!(
                "record_ports must be called before the first cycle (already at cycle {}): \
                 the Verilog replay starts from power-up",
                self.cycles
            )));
        }
        let clock_id = (self.clock)(&mut self.uut).id();
        self.recorder = Some(Recorder::new(self.uut.as_ref(), clock_id)?);
        Ok(())
    }

    /// Stops recording and returns what was recorded, or `None` if not recording.
    pub fn take_recording(&mut self) -> Option<Recording> {
        self.recorder.take().map(Recorder::finish)
    }

    fn settle(&mut self, phase: &str) -> Result<()> {
        // rust-hdl's `simulate`, counting the passes.
        for _ in 0..self.settle_limit {
            self.uut.update_all();
            self.passes += 1;
            if !self.uut.has_changed() {
                return Ok(());
            }
        }
        Err(Error::new(format!(
            "design did not settle within {} update passes at cycle {} ({phase}): a \
             combinational loop, or a hierarchy deeper than the limit (Driver::with_settle_limit)",
            self.settle_limit, self.cycles
        )))
    }
}
