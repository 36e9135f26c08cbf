//! The seam between the host's side of a run ([`crate::pe::run`]) and the simulator under it:
//! the processing element's ports as plain values ([`PeInputs`], [`PeOutputs`]) and the
//! [`PeSim`] trait, one clock cycle at a time.
//!
//! Two simulators implement it, cycle for cycle the same:
//!
//! - [`Driver<ProcessingElement>`](crate::Driver): rust-hdl's own simulation of the block, with
//!   VCD streaming and port recording;
//! - [`crate::verilated::VerilatedPe`]: the block's exported Verilog compiled by Verilator and
//!   loaded as a shared library, several times faster, without waveforms.
//!
//! The port table ([`INPUT_PORTS`], [`OUTPUT_PORTS`]) is the one list both are generated from:
//! the structs' fields, the reads and writes of the rust-hdl signals and the compiled model's C
//! glue. [`check_ports`] compares it with the block's own ports.

use crate::intersection::RayBench;
use crate::replay::PortDir;
use crate::{Driver, Error, Result};
use rust_hdl::prelude::*;
use shelling_hdl::formats::Nearest;
use shelling_hdl::formats::{from_bits, to_bits};
use shelling_hdl::machine::Machine;
use shelling_hdl::pe::{ProcessingElement, Watch};

/// A port's value as a Rust value: `bool`, an unsigned id or address, or a two's-complement
/// coordinate (sign-extended from the port's width).
pub trait PortValue: Copy {
    /// The port's bits (`width` of them, the rest zero).
    fn to_raw(self, width: usize) -> u64;
    /// The value of `width` port bits.
    fn from_raw(raw: u64, width: usize) -> Self;
}

impl PortValue for bool {
    fn to_raw(self, _: usize) -> u64 {
        self as u64
    }
    fn from_raw(raw: u64, _: usize) -> Self {
        raw & 1 != 0
    }
}

macro_rules! unsigned_port_value {
    ($($t:ty),+) => {
        $(
            impl PortValue for $t {
                fn to_raw(self, width: usize) -> u64 {
                    self as u64 & mask(width)
                }
                fn from_raw(raw: u64, width: usize) -> Self {
                    (raw & mask(width)) as $t
                }
            }
        )+
    };
}
unsigned_port_value!(u16, u32);

impl PortValue for i32 {
    fn to_raw(self, width: usize) -> u64 {
        to_bits(self as i64, width as u32)
    }
    fn from_raw(raw: u64, width: usize) -> Self {
        from_bits(raw & mask(width), width as u32) as i32
    }
}

fn mask(width: usize) -> u64 {
    if width >= 64 {
        u64::MAX
    } else {
        (1 << width) - 1
    }
}

/// A rust-hdl signal's value as port bits.
trait Wire {
    fn raw(&self) -> u64;
    fn set_raw(raw: u64) -> Self;
}

impl Wire for bool {
    fn raw(&self) -> u64 {
        *self as u64
    }
    fn set_raw(raw: u64) -> Self {
        raw & 1 != 0
    }
}

impl<const N: usize> Wire for Bits<N> {
    fn raw(&self) -> u64 {
        self.to_u64()
    }
    fn set_raw(raw: u64) -> Self {
        Bits::from(raw)
    }
}

/// Defines [`PeInputs`], [`PeOutputs`] and the port table from one list.
macro_rules! pe_ports {
    (
        inputs { $($i:ident: $it:ty = $iw:literal @ $ik:ident),+ $(,)? }
        outputs { $($o:ident: $ot:ty = $ow:literal @ $ok:ident),+ $(,)? }
    ) => {
        /// The processing element's inputs (the clock aside), as the host drives them. They
        /// hold from one cycle to the next until changed.
        #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
        pub struct PeInputs {
            $(pub $i: $it,)+
        }

        /// The processing element's outputs.
        #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
        pub struct PeOutputs {
            $(pub $o: $ot,)+
        }

        /// The inputs by name and width, in [`PeInputs::to_words`] order.
        pub const INPUT_PORTS: &[(&str, usize)] = &[$((stringify!($i), $iw)),+];
        /// The outputs by name and width, in [`PeOutputs::from_words`] order.
        pub const OUTPUT_PORTS: &[(&str, usize)] = &[$((stringify!($o), $ow)),+];

        impl PeInputs {
            /// Every input's bits, in [`INPUT_PORTS`] order.
            pub fn to_words(&self) -> [u64; INPUT_PORTS.len()] {
                [$(self.$i.to_raw($iw)),+]
            }

            fn read(u: &ProcessingElement) -> Self {
                Self { $($i: PortValue::from_raw(u.$i.val().raw(), $iw),)+ }
            }

            fn write(&self, u: &mut ProcessingElement) {
                $(u.$i.next = Wire::set_raw(self.$i.to_raw($iw));)+
            }

            /// PE `p`'s inputs as the machine's ports hold them (the memory port's, inside the
            /// machine, at their defaults).
            pub(crate) fn read_machine<const N: usize>(m: &Machine<N>, p: usize) -> Self {
                Self { $($i: machine_port!(read $ik, m, p, $i, $iw),)+ }
            }

            /// Sets the machine's ports of PE `p` (and the shared ones) to these inputs.
            pub(crate) fn write_machine<const N: usize>(&self, m: &mut Machine<N>, p: usize) {
                $(machine_port!(write $ik, m, p, $i, self.$i.to_raw($iw));)+
            }
        }

        impl PeOutputs {
            /// The outputs from their bits, in [`OUTPUT_PORTS`] order.
            pub fn from_words(w: &[u64; OUTPUT_PORTS.len()]) -> Self {
                let mut w = w.iter().copied();
                Self { $($o: PortValue::from_raw(w.next().unwrap_or(0), $ow),)+ }
            }

            fn read(u: &ProcessingElement) -> Self {
                Self { $($o: PortValue::from_raw(u.$o.val().raw(), $ow),)+ }
            }

            /// PE `p`'s outputs at the machine's ports (its memory port's, inside the machine,
            /// at their defaults).
            pub(crate) fn read_machine<const N: usize>(m: &Machine<N>, p: usize) -> Self {
                Self { $($o: machine_port!(read $ok, m, p, $o, $ow),)+ }
            }
        }
    };
}

/// A PE port at the machine's ports ([`Machine`]): `pe`, PE `p`'s own array entry; `shared`,
/// one port of every PE; `memory`, inside the machine (to the arbiter).
macro_rules! machine_port {
    (read pe, $m:ident, $p:ident, $n:ident, $w:literal) => {
        PortValue::from_raw($m.$n[$p].val().raw(), $w)
    };
    (read shared, $m:ident, $p:ident, $n:ident, $w:literal) => {
        PortValue::from_raw($m.$n.val().raw(), $w)
    };
    (read memory, $m:ident, $p:ident, $n:ident, $w:literal) => {
        Default::default()
    };
    (write pe, $m:ident, $p:ident, $n:ident, $raw:expr) => {
        $m.$n[$p].next = Wire::set_raw($raw)
    };
    (write shared, $m:ident, $p:ident, $n:ident, $raw:expr) => {
        $m.$n.next = Wire::set_raw($raw)
    };
    (write memory, $m:ident, $p:ident, $n:ident, $raw:expr) => {
        ()
    };
}

pe_ports! {
    inputs {
        dir_we: bool = 1 @ pe,
        dir_addr: u16 = 11 @ pe,
        dir_x: i32 = 18 @ pe,
        dir_y: i32 = 18 @ pe,
        origin_x: i32 = 17 @ pe,
        origin_y: i32 = 17 @ pe,
        normal_x: i32 = 18 @ pe,
        normal_y: i32 = 18 @ pe,
        first_x: i32 = 18 @ pe,
        first_y: i32 = 18 @ pe,
        last_x: i32 = 18 @ pe,
        last_y: i32 = 18 @ pe,
        cmd_valid: bool = 1 @ pe,
        cmd_retire: bool = 1 @ pe,
        cmd_sector: bool = 1 @ pe,
        cmd_id: u16 = 16 @ pe,
        cmd_first: u16 = 11 @ pe,
        cmd_count: u16 = 11 @ pe,
        cfg_cache_enable: bool = 1 @ shared,
        cfg_cache_mask: u16 = 10 @ shared,
        cfg_cache_flush: bool = 1 @ shared,
        mem_valid: bool = 1 @ memory,
        mem_ax: i32 = 17 @ memory,
        mem_ay: i32 = 17 @ memory,
        mem_bx: i32 = 17 @ memory,
        mem_by: i32 = 17 @ memory,
        res_re: bool = 1 @ pe,
        res_addr: u16 = 11 @ pe,
    }
    outputs {
        cmd_ready: bool = 1 @ pe,
        mem_req: bool = 1 @ memory,
        mem_addr: u16 = 16 @ memory,
        res_hit: bool = 1 @ pe,
        res_id: u16 = 16 @ pe,
        res_key: u32 = 32 @ pe,
        busy: bool = 1 @ pe,
        loads: u32 = 32 @ pe,
        cache_hits: u32 = 32 @ pe,
        cache_misses: u32 = 32 @ pe,
        passed: u32 = 32 @ pe,
        backward: u32 = 32 @ pe,
        back_facing: u32 = 32 @ pe,
        outside: u32 = 32 @ pe,
        near: u32 = 32 @ pe,
        tests: u32 = 32 @ pe,
        marks: u32 = 32 @ pe,
    }
}

/// A simulated processing element, stepped one clock cycle at a time from power-up.
pub trait PeSim {
    /// Changes the inputs for the coming rising edge (the clock low) and settles: the outputs
    /// then show what the logic between the registers makes of them.
    fn drive(&mut self, set: impl FnOnce(&mut PeInputs)) -> Result<()>;
    /// The rising edge: the registers take their inputs, the outputs settle.
    fn tick(&mut self) -> Result<()>;
    /// The outputs now.
    fn outputs(&self) -> PeOutputs;
    /// Rising edges since power-up.
    fn cycles(&self) -> u64;

    /// [`drive`](Self::drive), then [`tick`](Self::tick).
    fn cycle(&mut self, set: impl FnOnce(&mut PeInputs)) -> Result<()> {
        self.drive(set)?;
        self.tick()
    }
}

impl PeSim for Driver<ProcessingElement> {
    fn drive(&mut self, set: impl FnOnce(&mut PeInputs)) -> Result<()> {
        Driver::drive(self, |u| {
            let mut inputs = PeInputs::read(u);
            set(&mut inputs);
            inputs.write(u);
        })
    }

    fn tick(&mut self) -> Result<()> {
        Driver::tick(self)
    }

    fn outputs(&self) -> PeOutputs {
        PeOutputs::read(self.uut())
    }

    fn cycles(&self) -> u64 {
        Driver::cycles(self)
    }
}

/// A cycle of a [`Watched`] PE: the command handshake and the PE's [`Watch`], before the edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WatchSample {
    /// The host offers a command (`cmd_valid`).
    pub offered: bool,
    /// The PE takes one (`cmd_ready`).
    pub ready: bool,
    pub watch: Watch,
}

/// The PE on rust-hdl's simulator with every cycle's [`WatchSample`] recorded, from the first
/// cycle it is driven on (`samples[c]` is the cycle before edge `c + 1`): why the command
/// stream waits, which the ports alone do not tell.
pub struct Watched {
    pub pe: Driver<ProcessingElement>,
    pub samples: Vec<WatchSample>,
    offered: bool,
}

impl Watched {
    /// A PE fresh from power-up, nothing recorded.
    pub fn new() -> Result<Self> {
        Ok(Watched { pe: Driver::new(ProcessingElement::default())?, samples: Vec::new(), offered: false })
    }
}

impl PeSim for Watched {
    fn drive(&mut self, set: impl FnOnce(&mut PeInputs)) -> Result<()> {
        let mut offered = false;
        let r = PeSim::drive(&mut self.pe, |i| {
            set(i);
            offered = i.cmd_valid;
        });
        self.offered = offered;
        r
    }

    fn tick(&mut self) -> Result<()> {
        let u = self.pe.uut();
        self.samples.push(WatchSample { offered: self.offered, ready: u.cmd_ready.val(), watch: u.watch() });
        PeSim::tick(&mut self.pe)
    }

    fn outputs(&self) -> PeOutputs {
        PeSim::outputs(&self.pe)
    }

    fn cycles(&self) -> u64 {
        PeSim::cycles(&self.pe)
    }
}

/// The ray ports of any [`PeSim`] (a whole PE's, for [`crate::intersection::load_directions`]
/// and [`crate::intersection::read_hits`]).
pub struct PeRays<'a, S: PeSim>(pub &'a mut S);

impl<S: PeSim> RayBench for PeRays<'_, S> {
    fn cycle_rays(&mut self, write: Option<(usize, [i32; 2])>, read: Option<usize>) -> Result<()> {
        self.0.cycle(|i| {
            i.dir_we = write.is_some();
            if let Some((r, d)) = write {
                i.dir_addr = r as u16;
                [i.dir_x, i.dir_y] = d;
            }
            i.res_re = read.is_some();
            if let Some(r) = read {
                i.res_addr = r as u16;
            }
        })
    }

    fn readout(&self) -> Option<Nearest> {
        let o = self.0.outputs();
        o.res_hit.then_some(Nearest { key: o.res_key, id: o.res_id })
    }

    fn is_busy(&self) -> bool {
        self.0.outputs().busy
    }
}

/// Checks the port table against the block's own ports (names, directions and widths), so
/// that a port added to the RTL cannot be left undriven by a compiled model.
pub fn check_ports() -> Result<()> {
    let mut drv = Driver::new(ProcessingElement::default())?;
    drv.record_ports()?;
    let rec = drv.take_recording().ok_or_else(|| Error::new("the PE's ports were not recorded"))?;
    type Entry<'a> = (&'a str, bool, usize);
    let mut block: Vec<Entry> =
        rec.ports().iter().map(|p| (p.name.as_str(), p.dir == PortDir::Input, p.width)).collect();
    let mut table: Vec<Entry> = INPUT_PORTS
        .iter()
        .map(|&(n, w)| (n, true, w))
        .chain(OUTPUT_PORTS.iter().map(|&(n, w)| (n, false, w)))
        .collect();
    block.sort();
    table.sort();
    if block != table {
        let only = |a: &[Entry], b: &[Entry]| {
            a.iter()
                .filter(|p| !b.contains(p))
                .map(|&(n, input, w)| format!("{} {n} ({w} bits)", if input { "input" } else { "output" }))
                .collect::<Vec<_>>()
        };
        return Err(Error::new(format!(
            "the PE's port table (testbench/src/pe_sim.rs) is not the block's ports: only in the block: [{}]; only in the table: [{}]",
            only(&block, &table).join(", "),
            only(&table, &block).join(", ")
        )));
    }
    Ok(())
}
