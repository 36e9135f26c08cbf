//! The machine: `N` processing elements sharing one host memory port through the memory
//! arbiter, the paper's shared-memory parallel architecture in one design.
//!
//! # Purpose
//!
//! Each PE ([`ProcessingElement`]) keeps its own command stream, ray memory, patch cache,
//! screener and intersection unit; the host drives each through its own ports. Their host
//! memory ports meet in one [`MemoryArbiter`], whose single port is the machine's.
//!
//! # Ports ([`Machine`])
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | rising-edge clock of every PE and the arbiter |
//! | `dir_we$i` … `res_addr$i` | in | as the PE's | PE `i`'s host ports: directions, source, sectors, commands, readout (`pe.rs`) |
//! | `cmd_ready$i` … `marks$i` | out | as the PE's | PE `i`'s outputs: command ready, readout, `busy`, its counters and its markers |
//! | `cfg_cache_enable`, `cfg_cache_mask`, `cfg_cache_flush` | in | 1, 10, 1 | every PE's cache setting (one scene, one size), taken by each PE's copy of them in a clock after one when that PE was not `busy` (raise a flush when every PE has been idle a clock: one raised while a PE is busy is lost to it; a PE's `busy` rises two clocks after the flush) |
//! | `host_req`, `host_addr` | out | 1, 16 | the shared host memory's request: one per clock at most |
//! | `host_valid`, `host_ax` … `host_by` | in | 1, 17 each | its answers, in request order |
//! | `requests` | out | 32 | requests sent to the host since power-up (wrapping) |
//!
//! # Latency and throughput
//!
//! Each PE's as `pe.rs` documents, with every patch load [`LOAD_LATENCY`] = 6 clocks longer:
//! [`crate::arbiter::LATENCY`] = 4 in the arbiter (its queue, grant and answer registers) and
//! [`PORT_LATENCY`] = 2 in each PE's port registers (one on the request's way, one on the
//! answer's). The host port is shared: one request per clock to the host, answered one per
//! `T_c`.
//!
//! The port registers are there for the clock: without them the arbiter's answer register
//! drove every PE's loader across the die through the cache's pass-through multiplexer, the
//! machine's critical path. Each PE's copy of the patch is loaded only on that PE's answers,
//! so synthesis cannot merge the copies into one register. For the same reason each PE has its
//! own copy of the cache settings, loaded while that PE was idle (its `busy` of the clock before
//! low, a register, so that the PE's `busy` logic does not reach them): one register
//! driving every PE's cache from the middle of the die was the critical path once the PEs had
//! their own regions.
//!
//! # Formats
//!
//! The PEs' (`hdl/FORMATS.md`); ids and patch words pass through the arbiter unchanged.
//!
//! # Models
//!
//! The machine is its parts wired together through its port registers ([`model::Port`]),
//! every output a register, so stepping the PEs' simulations,
//! [`crate::arbiter::model::Arbiter`] and the port registers in lockstep
//! (`shelling_testbench::machine`) is its cycle model; `testbench/tests/machine.rs` checks that
//! this block and that composition give every PE the same hits and counters, cycle counts
//! included, run after run and with each PE on its own queue of sources, and replays a recorded
//! run through its exported Verilog under Verilator (rung 4).
//!
//! # Resources
//!
//! N times the PE's (17 `DP16KD` each), plus the arbiter and the port registers. On the
//! LFE5U-85F-6 four PEs take 44,313 LUT4s (53 %), 32,069 FFs, 68 of 208 `DP16KD`s and 64
//! `MULT18X18D`s and route at 150.9 MHz, the median of placement seeds 1 to 3 (150.8–155.0;
//! `hdl/fpga/ecp5-machine.md`, `cargo xtask fpga --blocks machine_4`), with each PE's block RAMs
//! and multipliers pinned to its own quadrant of the die by the flow's floorplan and each PE's
//! inputs in its own stretch of the register wrapper's chain. The critical paths: a screener's
//! dividend shift into its divider (seed 1), a divider step (2), a PE's stall register (3).
//! Six PEs take 66,452 LUT4s (79 %), 48,054 FFs, 102 `DP16KD`s and 96 `MULT18X18D`s and route
//! at 151.0 MHz, the median of seeds 1 to 3 (147.8–152.6), floorplanned in a 3 × 2 grid of
//! regions and placed with nextpnr's analytic placer at timing weight 30 (`--ecp5-pnr-options
//! "--placer-heap-timingweight 30"`; 143.7 without it, while four PEs do better without it); the
//! critical paths: a screener's dividend shift into its divider (seed 1), a screener's normaliser
//! into a compare (2), the unit's key into its merge's compare (3). Seven PEs fit the device
//! (77,029 LUT4s, 92 %, by nextpnr's packer) and route below 150 MHz on the flow's floorplan
//! of four regions above and three below: a median of 145.4 over seeds 1–3 (138.9–148.2; 132.0
//! and 132.7 on seven tall columns), the critical paths in PEs' intersection units
//! (`key_scale`, the merge compare; PERFORMANCE.md).

use crate::arbiter::{MemoryArbiter, QUEUE_DEPTH};
use crate::pe::ProcessingElement;
use rust_hdl::prelude::*;

/// Clocks the port registers add to a load: one on the request's way, one on the answer's.
pub const PORT_LATENCY: u64 = 2;
/// Clocks the machine adds to each patch load against a PE wired to the memory directly.
pub const LOAD_LATENCY: u64 = crate::arbiter::LATENCY + PORT_LATENCY;

/// The cycle model of the machine's own registers: each PE's port register.
pub mod model {
    use crate::arbiter::model::Outputs;

    /// A PE's port registers: the request on its way to the arbiter (`request`, the PE's
    /// `mem_req` with `mem_addr` one clock later), the answer the PE sees: `valid` (its
    /// `mem_valid`) and the patch (its `mem_ax` … `mem_by`), the last one answered to it, and
    /// its copy of the machine's cache settings (`cache`, what its `cfg_cache_*` see), taken
    /// when the PE's `busy` of the clock before (`was_busy`) is low.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct Port {
        pub request: Option<u16>,
        pub valid: bool,
        pub patch: [u32; 4],
        pub cache: Settings,
        pub was_busy: bool,
    }

    /// The cache settings a PE sees: `cfg_cache_enable`, `cfg_cache_mask`, `cfg_cache_flush`.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct Settings {
        pub enable: bool,
        pub mask: u16,
        pub flush: bool,
    }

    impl Port {
        /// One rising edge of PE `p`'s port registers, with the PE's request `request` and its
        /// `busy`, the arbiter's outputs `a` and the machine's cache settings `host` before it.
        pub fn step(&mut self, p: usize, request: Option<u16>, busy: bool, a: &Outputs, host: Settings) {
            // The settings are taken while the PE was idle in the clock before; a flush is a
            // pulse.
            if !self.was_busy {
                self.cache = host;
            } else {
                self.cache.flush = false;
            }
            self.was_busy = busy;
            self.request = request;
            self.valid = a.answer == Some(p);
            if self.valid {
                self.patch = a.patch;
            }
        }
    }
}

// A PE never has more requests outstanding than its loader holds, so its queue in the arbiter
// never overflows.
const _: () = assert!(QUEUE_DEPTH >= crate::loader::DEPTH);

/// Declares [`Machine`] from the list of the PE's host ports: each becomes an array of `N`
/// ports of the machine, wired to PE `i`'s.
macro_rules! machine {
    (
        inputs { $($i:ident: $it:ty),+ $(,)? }
        outputs { $($o:ident: $ot:ty),+ $(,)? }
    ) => {
        /// `N` processing elements on one host memory port (see the [module documentation](self)).
        #[derive(LogicBlock)]
        pub struct Machine<const N: usize> {
            pub clock: Signal<In, Clock>,
            $(pub $i: [Signal<In, $it>; N],)+
            $(pub $o: [Signal<Out, $ot>; N],)+
            pub cfg_cache_enable: Signal<In, bool>,
            pub cfg_cache_mask: Signal<In, Bits<{ crate::cache::CACHE_BITS }>>,
            pub cfg_cache_flush: Signal<In, bool>,
            pub host_req: Signal<Out, bool>,
            pub host_addr: Signal<Out, Bits<16>>,
            pub host_valid: Signal<In, bool>,
            pub host_ax: Signal<In, Bits<17>>,
            pub host_ay: Signal<In, Bits<17>>,
            pub host_bx: Signal<In, Bits<17>>,
            pub host_by: Signal<In, Bits<17>>,
            pub requests: Signal<Out, Bits<32>>,
            pes: [ProcessingElement; N],
            arbiter: MemoryArbiter<N>,
            // Each PE's port registers: its request one clock on its way to the arbiter, the
            // arbiter's answer one clock later, so that neither crosses the die with logic
            // on either side.
            port_req: [DFF<bool>; N],
            port_addr: [DFF<Bits<{ crate::formats::ID_BITS as usize }>>; N],
            port_valid: [DFF<bool>; N],
            port_ax: [DFF<Bits<{ crate::arbiter::WORD_BITS }>>; N],
            port_ay: [DFF<Bits<{ crate::arbiter::WORD_BITS }>>; N],
            port_bx: [DFF<Bits<{ crate::arbiter::WORD_BITS }>>; N],
            port_by: [DFF<Bits<{ crate::arbiter::WORD_BITS }>>; N],
            // Each PE's copy of the cache settings, taken while it was idle in the clock before
            // (`was_busy`, its `busy` a clock late): no two copies are the same register, so
            // synthesis keeps one beside each PE, and no path runs from `busy`'s logic into them.
            was_busy: [DFF<bool>; N],
            cfg_enable: [DFF<bool>; N],
            cfg_mask: [DFF<Bits<{ crate::cache::CACHE_BITS }>>; N],
            cfg_flush: [DFF<bool>; N],
        }

        impl<const N: usize> Default for Machine<N> {
            fn default() -> Self {
                Machine {
                    clock: Default::default(),
                    $($i: std::array::from_fn(|_| Default::default()),)+
                    $($o: std::array::from_fn(|_| Default::default()),)+
                    cfg_cache_enable: Default::default(),
                    cfg_cache_mask: Default::default(),
                    cfg_cache_flush: Default::default(),
                    host_req: Default::default(),
                    host_addr: Default::default(),
                    host_valid: Default::default(),
                    host_ax: Default::default(),
                    host_ay: Default::default(),
                    host_bx: Default::default(),
                    host_by: Default::default(),
                    requests: Default::default(),
                    pes: std::array::from_fn(|_| Default::default()),
                    arbiter: Default::default(),
                    port_req: std::array::from_fn(|_| Default::default()),
                    port_addr: std::array::from_fn(|_| Default::default()),
                    port_valid: std::array::from_fn(|_| Default::default()),
                    port_ax: std::array::from_fn(|_| Default::default()),
                    port_ay: std::array::from_fn(|_| Default::default()),
                    port_bx: std::array::from_fn(|_| Default::default()),
                    port_by: std::array::from_fn(|_| Default::default()),
                    was_busy: std::array::from_fn(|_| Default::default()),
                    cfg_enable: std::array::from_fn(|_| Default::default()),
                    cfg_mask: std::array::from_fn(|_| Default::default()),
                    cfg_flush: std::array::from_fn(|_| Default::default()),
                }
            }
        }

        impl<const N: usize> Logic for Machine<N> {
            #[hdl_gen]
            fn update(&mut self) {
                self.arbiter.clock.next = self.clock.val();
                for i in 0..N {
                    self.pes[i].clock.next = self.clock.val();
                    $(self.pes[i].$i.next = self.$i[i].val();)+
                    $(self.$o[i].next = self.pes[i].$o.val();)+
                    self.was_busy[i].clock.next = self.clock.val();
                    self.was_busy[i].d.next = self.pes[i].busy.val();
                    self.cfg_enable[i].clock.next = self.clock.val();
                    self.cfg_mask[i].clock.next = self.clock.val();
                    self.cfg_flush[i].clock.next = self.clock.val();
                    self.cfg_enable[i].d.next = self.cfg_enable[i].q.val();
                    self.cfg_mask[i].d.next = self.cfg_mask[i].q.val();
                    self.cfg_flush[i].d.next = false;
                    if !self.was_busy[i].q.val() {
                        self.cfg_enable[i].d.next = self.cfg_cache_enable.val();
                        self.cfg_mask[i].d.next = self.cfg_cache_mask.val();
                        self.cfg_flush[i].d.next = self.cfg_cache_flush.val();
                    }
                    self.pes[i].cfg_cache_enable.next = self.cfg_enable[i].q.val();
                    self.pes[i].cfg_cache_mask.next = self.cfg_mask[i].q.val();
                    self.pes[i].cfg_cache_flush.next = self.cfg_flush[i].q.val();
                    self.port_req[i].clock.next = self.clock.val();
                    self.port_addr[i].clock.next = self.clock.val();
                    self.port_req[i].d.next = self.pes[i].mem_req.val();
                    self.port_addr[i].d.next = self.pes[i].mem_addr.val();
                    self.arbiter.pe_req[i].next = self.port_req[i].q.val();
                    self.arbiter.pe_addr[i].next = self.port_addr[i].q.val();
                    // The port register: loaded only on this PE's own answers, so no two
                    // PEs' copies of the patch are the same register (synthesis keeps one
                    // beside each PE rather than merging them into one across the die).
                    self.port_valid[i].clock.next = self.clock.val();
                    self.port_ax[i].clock.next = self.clock.val();
                    self.port_ay[i].clock.next = self.clock.val();
                    self.port_bx[i].clock.next = self.clock.val();
                    self.port_by[i].clock.next = self.clock.val();
                    self.port_valid[i].d.next = self.arbiter.pe_valid[i].val();
                    self.port_ax[i].d.next = self.port_ax[i].q.val();
                    self.port_ay[i].d.next = self.port_ay[i].q.val();
                    self.port_bx[i].d.next = self.port_bx[i].q.val();
                    self.port_by[i].d.next = self.port_by[i].q.val();
                    if self.arbiter.pe_valid[i].val() {
                        self.port_ax[i].d.next = self.arbiter.pe_ax.val();
                        self.port_ay[i].d.next = self.arbiter.pe_ay.val();
                        self.port_bx[i].d.next = self.arbiter.pe_bx.val();
                        self.port_by[i].d.next = self.arbiter.pe_by.val();
                    }
                    self.pes[i].mem_valid.next = self.port_valid[i].q.val();
                    self.pes[i].mem_ax.next = self.port_ax[i].q.val();
                    self.pes[i].mem_ay.next = self.port_ay[i].q.val();
                    self.pes[i].mem_bx.next = self.port_bx[i].q.val();
                    self.pes[i].mem_by.next = self.port_by[i].q.val();
                }
                self.host_req.next = self.arbiter.host_req.val();
                self.host_addr.next = self.arbiter.host_addr.val();
                self.arbiter.host_valid.next = self.host_valid.val();
                self.arbiter.host_ax.next = self.host_ax.val();
                self.arbiter.host_ay.next = self.host_ay.val();
                self.arbiter.host_bx.next = self.host_bx.val();
                self.arbiter.host_by.next = self.host_by.val();
                self.requests.next = self.arbiter.requests.val();
            }
        }
    };
}

machine! {
    inputs {
        dir_we: bool,
        dir_addr: Bits<11>,
        dir_x: Bits<18>,
        dir_y: Bits<18>,
        origin_x: Bits<17>,
        origin_y: Bits<17>,
        normal_x: Bits<18>,
        normal_y: Bits<18>,
        first_x: Bits<18>,
        first_y: Bits<18>,
        last_x: Bits<18>,
        last_y: Bits<18>,
        cmd_valid: bool,
        cmd_retire: bool,
        cmd_sector: bool,
        cmd_id: Bits<16>,
        cmd_first: Bits<11>,
        cmd_count: Bits<11>,
        res_re: bool,
        res_addr: Bits<11>,
    }
    outputs {
        cmd_ready: bool,
        res_hit: bool,
        res_id: Bits<16>,
        res_key: Bits<32>,
        busy: bool,
        loads: Bits<32>,
        cache_hits: Bits<32>,
        cache_misses: Bits<32>,
        passed: Bits<32>,
        backward: Bits<32>,
        back_facing: Bits<32>,
        outside: Bits<32>,
        near: Bits<32>,
        tests: Bits<32>,
        marks: Bits<32>,
    }
}
