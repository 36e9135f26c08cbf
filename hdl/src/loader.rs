//! The patch loader: fetches patches by id from the host memory, buffers them in a FIFO with
//! backpressure and streams them to the screener, never dropping or duplicating one.
//!
//! # Ports ([`PatchLoader`])
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | rising-edge clock |
//! | `id_valid`, `id_ready`, `id` | in, out, in | 1, 1, 16 | id stream (valid/ready) |
//! | `id_ready_next` | out | 1 | `id_ready` after the coming edge (combinational: for a client that keeps its own ready in a register) |
//! | `mem_req`, `mem_addr` | out, out | 1, 16 | memory request: one clock pulse per patch, `mem_addr` = patch id |
//! | `mem_valid`, `mem_ax`, `mem_ay`, `mem_bx`, `mem_by` | in | 1, 4 × 17 | memory response |
//! | `out_valid`, `out_ready`, `out_id`, `out_ax` … `out_by` | out, in, out | 1, 1, 16, 4 × 17 | patch stream (valid/ready) |
//! | `loads` | out | 32 | patches fetched from memory so far (responses received), wraps at 2³² |
//!
//! Handshakes: a transfer happens in a cycle where `valid && ready` holds before the rising edge.
//! `id_ready` is a register (not a function of `id_valid` or `out_ready`); `out_valid` is a
//! register and the `out_*` data depend only on registers (the lanes' two read registers, chosen
//! by the registered pop), so no combinational path crosses the block. The `out_*` data keep their last value while `out_valid` is low (zero after
//! power-up), identically in the rust-hdl simulation and in the Verilog.
//!
//! Number formats: ids are 16-bit unsigned; coordinates are world coordinates Q11.6 unsigned in
//! 17 bits (`crate::formats`), passed through unchanged.
//!
//! # The memory port
//!
//! The host memory is not part of this block. `mem_req` is high for one cycle per request
//! (registered: the cycle after the id was accepted); requests may be issued on consecutive
//! cycles (pipelined, no limit on the number outstanding other than the FIFO space). The memory
//! must answer every request exactly once, in request order, by raising `mem_valid` for one
//! cycle with the patch's coordinates on `mem_ax` … `mem_by`, any number `T_c ≥ 1` of cycles
//! after the request (the tests use a fixed latency; the loader does not depend on it). A
//! `mem_valid` without an outstanding request is a protocol violation.
//!
//! # Structure
//!
//! A [`DEPTH`]-slot FIFO of five [`FifoRam`] lanes (id: 16 bits, four coordinates: 17 bits each,
//! 84 bits in all) sharing one set of pointers. A slot is *held* from its id's acceptance: the id
//! goes into the request registers (`req_valid`, `req_addr`, the memory request of the next
//! clock) and from them into the id lane at the next edge, which *reserves* the slot; the
//! coordinate lanes of the
//! slot are written when the response arrives (responses come in order, so a second pointer
//! suffices). An id is accepted only while fewer than [`DEPTH`] slots are held, so every
//! response in flight has a slot waiting for it: nothing can be dropped, and backpressure on the
//! output stops the id stream (`id_ready` low) instead.
//!
//! The FIFO's response pointer, read side and count of filled slots are a [`FifoControl`] (the
//! one first-word-fall-through FIFO block of the PE: a response is its push, a patch leaving its
//! pop). Counters (5 bits, `0..=16`): `reserved` (ids written into their slot, not yet sent
//! out; the loader's own) and the control's `count` (responses written, not yet sent out),
//! `count ≤ reserved ≤ reserved + req_valid ≤ DEPTH`; `full` (a register: `reserved +
//! req_valid = DEPTH` after the edge) is `id_ready`'s complement, so the accept reaches no
//! counter's clock enable. Every cycle the lanes read the head slot and the one after it into their read registers and show the second after a pop,
//! so `out_ready` reaches no RAM address (it did, through the address multiplexer, on the
//! processing element's critical path at 144 MHz); `out_valid` is set for the
//! next cycle when a filled slot remains after this cycle's pop *excluding* this cycle's write
//! (`count − pop > 0`), because the block RAM reads before it writes.
//!
//! # Latency and throughput
//!
//! An id accepted in cycle `a` is requested in cycle `a + 1`; a response in cycle
//! `a + 1 + T_c`; the patch is on the output from cycle `a + T_c + 3` on, i.e. latency
//! `T_c + 3` cycles from id transfer to patch transfer without backpressure ([`model::LATENCY`]).
//! A slot is held from acceptance until its patch leaves, `T_c + 3` cycles, and a freed slot can
//! be reused one cycle later, so the unstalled throughput is one patch per cycle while
//! `T_c + 4 ≤ DEPTH` (T_c ≤ 12) and `DEPTH` patches per `T_c + 4` cycles beyond
//! ([`model::accept_cycles`], [`model::unstalled_cycles`]).
//!
//! # Model
//!
//! [`model`]: the patches come out in id order, each exactly once (an id that repeats is fetched
//! and sent again each time), with the coordinates the memory holds; `loads` equals the number
//! of ids; plus the exact cycle counts of an unstalled stream.

use crate::prim::{FifoControl, FifoRam};
use rust_hdl::prelude::*;

/// FIFO capacity in patches (slots reserved, requested or buffered).
pub const DEPTH: usize = 16;
/// Address width of the FIFO lanes: `2^ADDR_BITS == DEPTH`.
pub const ADDR_BITS: usize = 4;

/// The transaction model of the patch loader.
pub mod model {
    use super::DEPTH;

    /// A patch as it leaves the loader: id and the world coordinates of its endpoints (Q11.6,
    /// 17 bits unsigned).
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
    pub struct Patch {
        pub id: u16,
        pub ax: u32,
        pub ay: u32,
        pub bx: u32,
        pub by: u32,
    }

    /// Cycles from an id transfer to its patch's transfer when the output is always ready:
    /// `T_c + LATENCY`.
    pub const LATENCY: u64 = 3;

    /// Mask of a 17-bit coordinate.
    pub const COORD_MASK: u32 = (1 << 17) - 1;

    /// The patches that come out for `ids`, in order, fetching each from `memory`
    /// (`id → [ax, ay, bx, by]`, masked to 17 bits), and the final value of `loads`.
    pub fn load(ids: &[u16], memory: impl Fn(u16) -> [u32; 4]) -> (Vec<Patch>, u32) {
        let patches: Vec<Patch> = ids
            .iter()
            .map(|&id| {
                let [ax, ay, bx, by] = memory(id).map(|c| c & COORD_MASK);
                Patch { id, ax, ay, bx, by }
            })
            .collect();
        (patches, ids.len() as u32)
    }

    /// The cycles in which the ids are accepted when they are offered back to back from cycle 0
    /// and the output is always ready, memory latency `tc`: `a_k = max(k, a_{k−DEPTH} + tc + 4)`.
    pub fn accept_cycles(n: usize, tc: u64) -> Vec<u64> {
        let mut a: Vec<u64> = Vec::with_capacity(n);
        for k in 0..n {
            let mut c = k as u64;
            if k >= DEPTH {
                c = c.max(a[k - DEPTH] + tc + LATENCY + 1);
            }
            if k > 0 {
                c = c.max(a[k - 1] + 1);
            }
            a.push(c);
        }
        a
    }

    /// The cycle in which patch `k` is transferred out, under the conditions of
    /// [`accept_cycles`].
    pub fn output_cycles(n: usize, tc: u64) -> Vec<u64> {
        accept_cycles(n, tc).into_iter().map(|a| a + tc + LATENCY).collect()
    }

    /// Cycles (rising edges) until the last patch of `n` has left, under the conditions of
    /// [`accept_cycles`]: `n + tc + 3` while `tc ≤ 12`.
    pub fn unstalled_cycles(n: usize, tc: u64) -> u64 {
        output_cycles(n, tc).last().map_or(0, |c| c + 1)
    }
}

/// The patch loader (see the [module documentation](self)).
#[derive(LogicBlock)]
pub struct PatchLoader {
    pub clock: Signal<In, Clock>,
    // Id stream.
    pub id_valid: Signal<In, bool>,
    pub id_ready: Signal<Out, bool>,
    pub id: Signal<In, Bits<16>>,
    /// `id_ready` after the coming edge: the complement of `full`'s next value.
    pub id_ready_next: Signal<Out, bool>,
    // Host memory port.
    pub mem_req: Signal<Out, bool>,
    pub mem_addr: Signal<Out, Bits<16>>,
    pub mem_valid: Signal<In, bool>,
    pub mem_ax: Signal<In, Bits<17>>,
    pub mem_ay: Signal<In, Bits<17>>,
    pub mem_bx: Signal<In, Bits<17>>,
    pub mem_by: Signal<In, Bits<17>>,
    // Patch stream.
    pub out_valid: Signal<Out, bool>,
    pub out_ready: Signal<In, bool>,
    pub out_id: Signal<Out, Bits<16>>,
    pub out_ax: Signal<Out, Bits<17>>,
    pub out_ay: Signal<Out, Bits<17>>,
    pub out_bx: Signal<Out, Bits<17>>,
    pub out_by: Signal<Out, Bits<17>>,
    // Status.
    pub loads: Signal<Out, Bits<32>>,
    // Pointers and counters.
    req_ptr: DFF<Bits<4>>,
    reserved: DFF<Bits<5>>,
    /// `reserved + req_valid` is [`DEPTH`]: a register of its own (set from the counters' next
    /// values), so that `id_ready` is a register.
    full: DFF<bool>,
    req_valid: DFF<bool>,
    req_addr: DFF<Bits<16>>,
    load_count: DFF<Bits<32>>,
    /// The FIFO's response pointer (its tail), read side and count of filled slots: a word is
    /// pushed when its response arrives.
    fifo: FifoControl<4, 5>,
    // The FIFO lanes.
    lane_id: FifoRam<16, 4>,
    lane_ax: FifoRam<17, 4>,
    lane_ay: FifoRam<17, 4>,
    lane_bx: FifoRam<17, 4>,
    lane_by: FifoRam<17, 4>,
    // Combinational.
    room: Signal<Local, bool>,
    full_next: Signal<Local, bool>,
    accept: Signal<Local, bool>,
    pop: Signal<Local, bool>,
    req_inc: Signal<Local, Bits<4>>,
    reserved_inc: Signal<Local, Bits<5>>,
    reserved_dec: Signal<Local, Bits<5>>,
    load_inc: Signal<Local, Bits<32>>,
    // Constants.
    depth5: Constant<Bits<5>>,
    almost5: Constant<Bits<5>>,
    almost4: Constant<Bits<5>>,
    held_all: Signal<Local, bool>,
    held_almost: Signal<Local, bool>,
    one5: Constant<Bits<5>>,
    one4: Constant<Bits<4>>,
    one32: Constant<Bits<32>>,
}

impl Default for PatchLoader {
    fn default() -> Self {
        assert_eq!(1 << ADDR_BITS, DEPTH);
        PatchLoader {
            clock: Default::default(),
            id_valid: Default::default(),
            id_ready: Default::default(),
            id_ready_next: Default::default(),
            id: Default::default(),
            mem_req: Default::default(),
            mem_addr: Default::default(),
            mem_valid: Default::default(),
            mem_ax: Default::default(),
            mem_ay: Default::default(),
            mem_bx: Default::default(),
            mem_by: Default::default(),
            out_valid: Default::default(),
            out_ready: Default::default(),
            out_id: Default::default(),
            out_ax: Default::default(),
            out_ay: Default::default(),
            out_bx: Default::default(),
            out_by: Default::default(),
            loads: Default::default(),
            req_ptr: Default::default(),
            reserved: Default::default(),
            full: Default::default(),
            req_valid: Default::default(),
            req_addr: Default::default(),
            load_count: Default::default(),
            fifo: Default::default(),
            lane_id: Default::default(),
            lane_ax: Default::default(),
            lane_ay: Default::default(),
            lane_bx: Default::default(),
            lane_by: Default::default(),
            room: Default::default(),
            full_next: Default::default(),
            accept: Default::default(),
            pop: Default::default(),
            req_inc: Default::default(),
            reserved_inc: Default::default(),
            reserved_dec: Default::default(),
            load_inc: Default::default(),
            depth5: Constant::new((DEPTH as u64).into()),
            almost5: Constant::new((DEPTH as u64 - 1).into()),
            almost4: Constant::new((DEPTH as u64 - 2).into()),
            held_all: Default::default(),
            held_almost: Default::default(),
            one5: Constant::new(1.into()),
            one4: Constant::new(1.into()),
            one32: Constant::new(1.into()),
        }
    }
}

impl PatchLoader {
    /// Slots reserved (ids accepted whose patch has not left yet), `0..=DEPTH`: for testbenches.
    pub fn reserved(&self) -> usize {
        self.reserved.q.val().index() + self.req_valid.q.val() as usize
    }

    /// Slots holding a fetched patch that has not left yet, `0..=reserved()`: for testbenches.
    pub fn filled(&self) -> usize {
        self.fifo.count.val().index()
    }
}

impl Logic for PatchLoader {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, req_ptr, reserved, full, req_valid, req_addr, load_count);
        self.fifo.clock.next = self.clock.val();
        self.lane_id.clock.next = self.clock.val();
        self.lane_ax.clock.next = self.clock.val();
        self.lane_ay.clock.next = self.clock.val();
        self.lane_bx.clock.next = self.clock.val();
        self.lane_by.clock.next = self.clock.val();

        // Handshakes.
        self.room.next = !self.full.q.val();
        self.id_ready.next = self.room.val();
        self.accept.next = self.id_valid.val() & self.room.val();
        self.pop.next = self.fifo.valid.val() & self.out_ready.val();
        self.fifo.pop.next = self.pop.val();

        // Pointer and counter arithmetic, each at its exact width.
        self.req_inc.next = self.req_ptr.q.val() + self.one4.val();
        self.reserved_inc.next = self.reserved.q.val() + self.one5.val();
        self.reserved_dec.next = self.reserved.q.val() - self.one5.val();
        self.load_inc.next = self.load_count.q.val() + self.one32.val();

        // Id accepted: reserve the next slot, write its id, issue the request (next cycle).
        // The id goes into the request registers (`req_addr` loaded in every clock, so that
        // the accept drives no clock enable) and from them into its slot at the next edge, as
        // the request leaves: the slot's reservation (`req_ptr`, `reserved`) follows the
        // registered request, not the accept.
        self.lane_id.write_address.next = self.req_ptr.q.val();
        self.lane_id.write_data.next = self.req_addr.q.val();
        self.lane_id.write_enable.next = self.req_valid.q.val();
        self.req_valid.d.next = self.accept.val();
        self.req_addr.d.next = self.id.val();
        if self.req_valid.q.val() {
            self.req_ptr.d.next = self.req_inc.val();
        }
        self.mem_req.next = self.req_valid.q.val();
        self.mem_addr.next = self.req_addr.q.val();

        // Response: fill the oldest slot awaiting one.
        self.lane_ax.write_address.next = self.fifo.tail_address.val();
        self.lane_ay.write_address.next = self.fifo.tail_address.val();
        self.lane_bx.write_address.next = self.fifo.tail_address.val();
        self.lane_by.write_address.next = self.fifo.tail_address.val();
        self.lane_ax.write_data.next = self.mem_ax.val();
        self.lane_ay.write_data.next = self.mem_ay.val();
        self.lane_bx.write_data.next = self.mem_bx.val();
        self.lane_by.write_data.next = self.mem_by.val();
        self.lane_ax.write_enable.next = self.mem_valid.val();
        self.lane_ay.write_enable.next = self.mem_valid.val();
        self.lane_bx.write_enable.next = self.mem_valid.val();
        self.lane_by.write_enable.next = self.mem_valid.val();
        self.fifo.push.next = self.mem_valid.val();
        if self.mem_valid.val() {
            self.load_count.d.next = self.load_inc.val();
        }
        self.loads.next = self.load_count.q.val();

        // Head: read the head slot and the one after it; after a pop the second is the head.
        self.lane_id.head_address.next = self.fifo.head_address.val();
        self.lane_id.next_address.next = self.fifo.next_address.val();
        self.lane_id.pop.next = self.pop.val();
        self.lane_ax.head_address.next = self.fifo.head_address.val();
        self.lane_ax.next_address.next = self.fifo.next_address.val();
        self.lane_ax.pop.next = self.pop.val();
        self.lane_ay.head_address.next = self.fifo.head_address.val();
        self.lane_ay.next_address.next = self.fifo.next_address.val();
        self.lane_ay.pop.next = self.pop.val();
        self.lane_bx.head_address.next = self.fifo.head_address.val();
        self.lane_bx.next_address.next = self.fifo.next_address.val();
        self.lane_bx.pop.next = self.pop.val();
        self.lane_by.head_address.next = self.fifo.head_address.val();
        self.lane_by.next_address.next = self.fifo.next_address.val();
        self.lane_by.pop.next = self.pop.val();
        self.out_valid.next = self.fifo.valid.val();
        self.out_id.next = self.lane_id.read_data.val();
        self.out_ax.next = self.lane_ax.read_data.val();
        self.out_ay.next = self.lane_ay.read_data.val();
        self.out_bx.next = self.lane_bx.read_data.val();
        self.out_by.next = self.lane_by.read_data.val();

        // Counters.
        if self.req_valid.q.val() & !self.pop.val() {
            self.reserved.d.next = self.reserved_inc.val();
        }
        if !self.req_valid.q.val() & self.pop.val() {
            self.reserved.d.next = self.reserved_dec.val();
        }
        // Ids held (accepted, not sent out): `reserved` and the one in the request registers.
        // Full after this edge: all DEPTH held with no pop, or one short with an id and no pop.
        self.held_all.next = (self.reserved.q.val() == self.depth5.val())
            | ((self.reserved.q.val() == self.almost5.val()) & self.req_valid.q.val());
        self.held_almost.next = ((self.reserved.q.val() == self.almost5.val()) & !self.req_valid.q.val())
            | ((self.reserved.q.val() == self.almost4.val()) & self.req_valid.q.val());
        self.full_next.next = (self.held_all.val() & !self.pop.val())
            | (self.held_almost.val() & self.accept.val() & !self.pop.val());
        self.full.d.next = self.full_next.val();
        self.id_ready_next.next = !self.full_next.val();
    }
}

#[cfg(test)]
mod tests {
    use super::model::*;
    use super::*;
    use rust_hdl::core::prelude::simulate;
    use std::collections::VecDeque;

    fn step(u: &mut PatchLoader, set: impl FnOnce(&mut PatchLoader)) {
        u.clock.next = false.into();
        set(u);
        assert!(simulate(u, 100));
        u.clock.next = true.into();
        assert!(simulate(u, 100));
    }

    fn memory(id: u16) -> [u32; 4] {
        let h = (id as u32).wrapping_mul(0x9E37_79B9);
        [h, h >> 3, h >> 7, h >> 11].map(|c| c & COORD_MASK)
    }

    /// A quick unstalled run with memory latency 2: order, data, `loads` and the exact cycle count.
    #[test]
    fn loader_quick_unstalled_run_matches_model() {
        let mut u = PatchLoader::default();
        u.connect_all();
        check_all(&u).unwrap();
        let tc = 2u64;
        let ids: Vec<u16> = (0..40u16).map(|i| i.wrapping_mul(7919)).collect();
        let (expect, loads) = load(&ids, memory);
        let mut next = 0;
        let mut inflight: VecDeque<(u64, u16)> = VecDeque::new();
        let mut got = vec![];
        let mut cycle = 0u64;
        while got.len() < ids.len() {
            let resp = inflight.front().filter(|r| r.0 == cycle).map(|r| r.1);
            if resp.is_some() {
                inflight.pop_front();
            }
            let offer = ids.get(next).copied();
            u.clock.next = false.into();
            u.id_valid.next = offer.is_some();
            u.id.next = (offer.unwrap_or(0) as u64).into();
            u.out_ready.next = true;
            u.mem_valid.next = resp.is_some();
            let m = memory(resp.unwrap_or(0));
            u.mem_ax.next = (m[0] as u64).into();
            u.mem_ay.next = (m[1] as u64).into();
            u.mem_bx.next = (m[2] as u64).into();
            u.mem_by.next = (m[3] as u64).into();
            assert!(simulate(&mut u, 100));
            if offer.is_some() && u.id_ready.val() {
                next += 1;
            }
            if u.mem_req.val() {
                inflight.push_back((cycle + tc, u.mem_addr.val().to_u16()));
            }
            if u.out_valid.val() {
                got.push(Patch {
                    id: u.out_id.val().to_u16(),
                    ax: u.out_ax.val().to_u32(),
                    ay: u.out_ay.val().to_u32(),
                    bx: u.out_bx.val().to_u32(),
                    by: u.out_by.val().to_u32(),
                });
            }
            u.clock.next = true.into();
            assert!(simulate(&mut u, 100));
            cycle += 1;
            assert!(cycle < 1000);
        }
        assert_eq!(got, expect);
        assert_eq!(u.loads.val().to_u32(), loads);
        assert_eq!(cycle, unstalled_cycles(ids.len(), tc));
        step(&mut u, |u| u.id_valid.next = false);
        assert!(!u.out_valid.val());
    }

    #[test]
    fn loader_cycle_model_limits_throughput_only_beyond_tc_12() {
        assert_eq!(unstalled_cycles(0, 5), 0);
        assert_eq!(unstalled_cycles(100, 12), 100 + 12 + 3);
        // tc = 20: 16 patches per 24 cycles.
        let a = accept_cycles(64, 20);
        assert_eq!(a[16], 24);
        assert_eq!(a[48], 72);
    }
}
