//! Test-bench infrastructure for the shelling RTL (rust-hdl 0.46).
//!
//! The pieces, one module per concern:
//!
//! - [`driver`]: [`Driver`] steps a rust-hdl block from a plain loop (no testbench threads), one
//!   call per clock cycle, optionally streaming a VCD and recording the top-level ports.
//! - [`vcd_stream`]: the VCD stream behind [`Driver::stream_vcd`]: written as the run goes, optionally
//!   only for a window of cycles; [`vcd_stream::waveform_path`] names files under `waveforms/`.
//! - [`stream`]: seeded stall patterns ([`Pacing`]), a producer-side [`Source`] that offers items
//!   with random idle cycles and a consumer-side [`Monitor`] that collects them under random
//!   backpressure, independent of any particular block.
//! - [`scoreboard`]: [`Scoreboard`] compares DUT outputs with model outputs in order and explains
//!   the first mismatch (index, cycle, seed, DUT vs model).
//! - [`export`]: the Verilog of every block, one file each, for `shelling export-verilog` and
//!   the committed copies in `hdl/verilog/`.
//! - [`memory`]: [`HostMemory`], the shared host memory as a cycle-accurate model: one port,
//!   one patch at a time, `T_c` cycles per load, requests answered in order.
//! - [`intersection`]: the intersection unit's bundle setup, paced patch stream and readout,
//!   with the bit-true model's answer ([`intersection::model_bundle`]).
//! - [`pe`]: the host's side of a whole source on the processing element (directions, commands
//!   with sector drains, host memory, readout), the PE's bit-true model and the stream-protocol
//!   check on a VCD ([`pe::check_protocol`]).
//! - [`pe_sim`]: the PE's ports as plain values and [`PeSim`], the seam between the host loop
//!   and the simulator under it.
//! - [`verilated`]: [`verilated::VerilatedPe`], the PE's exported Verilog compiled by Verilator
//!   and loaded as a shared library: the same cycles as rust-hdl's simulation, many times faster.
//! - [`waves`]: reading a VCD back (signals sampled per cycle) and the signals of a `.gtkw`.
//! - [`replay`]: rung 4 of the equivalence ladder: the ports recorded during a rust-hdl
//!   run are replayed against the block's exported Verilog under Icarus Verilog (or
//!   Verilator), which must reproduce every output bit-exactly.
//!
//! Every fallible operation returns [`Result`] with the crate's [`Error`], whose `Debug` output
//! is the plain message, so a test can return `Result<(), Error>` and still fail readably.
//!
//! A complete test: a registered adder checked against its model, a VCD of its first 20 cycles
//! in `waveforms/`, and the rung-4 replay of the run under Icarus Verilog.
//!
//! ```
//! use rust_hdl::prelude::*;
//! use shelling_testbench::{impl_clocked, waveform_path, Driver, Scoreboard, Simulator};
//!
//! /// y = a + b, registered.
//! #[derive(LogicBlock, Default)]
//! struct Adder {
//!     pub clock: Signal<In, Clock>,
//!     pub a: Signal<In, Bits<8>>,
//!     pub b: Signal<In, Bits<8>>,
//!     pub y: Signal<Out, Bits<8>>,
//!     r: DFF<Bits<8>>,
//! }
//!
//! impl Logic for Adder {
//!     #[hdl_gen]
//!     fn update(&mut self) {
//!         dff_setup!(self, clock, r);
//!         self.r.d.next = self.a.val() + self.b.val();
//!         self.y.next = self.r.q.val();
//!     }
//! }
//!
//! impl_clocked!(Adder);
//!
//! fn main() -> shelling_testbench::Result<()> {
//!     let inputs: Vec<(u8, u8)> = (0..100u8).map(|i| (i, i.wrapping_mul(37))).collect();
//!     let model = inputs.iter().map(|&(a, b)| a.wrapping_add(b));
//!     let mut board = Scoreboard::new("adder", 0, model);
//!     let mut drv = Driver::new(Adder::default())?;
//!     drv.stream_vcd(waveform_path("doc_adder"), 0..20)?; // optional
//!     drv.record_ports()?; // optional, for the replay
//!     for &(a, b) in &inputs {
//!         drv.cycle(|u| {
//!             u.a.next = bits(a.into());
//!             u.b.next = bits(b.into());
//!         })?;
//!         // The sum registered at this cycle's rising edge.
//!         board.check(drv.cycles(), drv.uut().y.val().to_u8())?;
//!     }
//!     board.finish()?;
//!     drv.finish_vcd()?;
//!     let rec = drv.take_recording().ok_or("not recording")?;
//!     rec.replay(drv.uut(), &std::env::temp_dir().join("doc_adder"), Simulator::Icarus)?;
//!     Ok(())
//! }
//! ```

pub mod driver;
pub mod error;
pub mod export;
pub mod intersection;
pub mod lockstep;
pub mod machine;
pub mod memory;
pub mod pe;
pub mod pe_sim;
pub mod replay;
pub mod scoreboard;
pub mod stream;
pub mod vcd_stream;
pub mod verilated;
pub mod waves;

pub use driver::{Clocked, Driver};
pub use error::{Error, Result};
pub use memory::HostMemory;
pub use pe_sim::PeSim;
pub use replay::{Design, Port, PortDir, Recording, ReplayReport, Simulator};
pub use scoreboard::Scoreboard;
pub use stream::{Monitor, Pacing, Received, Source};
pub use vcd_stream::waveform_path;

/// The rust-hdl version this crate is built against, re-exported so that users and the
/// [`impl_clocked!`] macro name exactly the same types.
pub use rust_hdl;
