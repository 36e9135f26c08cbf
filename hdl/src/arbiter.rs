//! The memory arbiter: the host memory ports of `N` processing elements onto the one port of
//! the shared host memory (the paper's "shared memory parallel architecture").
//!
//! # Purpose
//!
//! Each processing element asks the host memory for patches through its own port (`mem_req`
//! pulses with an id, answers in request order: `loader.rs`, "The memory port"). The arbiter
//! queues each PE's requests, sends them to the host memory one per clock in round-robin order
//! among the PEs that have one waiting, remembers which PE each request at the host came from,
//! and hands every answer back to that PE, in order.
//!
//! # Ports ([`MemoryArbiter`])
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | rising-edge clock |
//! | `pe_req$i`, `pe_addr$i` | in | 1, 16 | PE `i`'s request: a pulse per patch with its id (the PE's `mem_req`, `mem_addr`) |
//! | `pe_valid$i` | out | 1 | PE `i`'s answer (its `mem_valid`): one pulse per request, in its request order |
//! | `pe_ax`, `pe_ay`, `pe_bx`, `pe_by` | out | 17 each | the answer's patch, to every PE's `mem_ax` … `mem_by` (read by the PE whose `pe_valid` is high) |
//! | `host_req`, `host_addr` | out | 1, 16 | the request to the host memory: a pulse per patch, one per clock at most |
//! | `host_valid`, `host_ax` … `host_by` | in | 1, 17 each | the host memory's answer, in request order |
//! | `requests` | out | 32 | requests sent to the host since power-up (wrapping) |
//!
//! Every output is a register but `host_addr`, the granted queue's head chosen by the grant
//! register (registers and one multiplexer).
//!
//! # Structure
//!
//! * **Request queues.** One first-word-fall-through [`Fifo`] of [`QUEUE_DEPTH`] ids per PE
//!   (LUT RAM). A PE has at most [`QUEUE_DEPTH`] requests outstanding (the patch loader's
//!   reservations: it asks only for patches it has room for), so its queue never overflows; the
//!   processing element's own limit is what makes that true, and `machine.rs` asserts the two
//!   depths agree.
//! * **The choice.** A [`RoundRobin`] over the queues' head-valid flags grants one queue per
//!   clock: the first with a request after the one granted last. The grant goes into the
//!   **grant register** (one flag per PE): for the clock after the grant the granted queue's
//!   head is on the host port (`host_req` is the register's OR), and it leaves the queue at the
//!   next edge. Its PE number goes into the **route queue** (a [`Fifo`] of [`ROUTE_DEPTH`] =
//!   `8 × 16` PE numbers: every request at the host at once, whatever the mix) at the grant.
//!   Since a queue pops a clock after its grant, the round-robin does not read the queues'
//!   `valid` but `asks`, one register per queue: the flag as the queue would show it had it
//!   popped at the grant, set from its count less the pop still pending, as [`FifoControl`](crate::prim::FifoControl)
//!   sets `valid` from its count and the edge's pop. So the ports behave as
//!   with the queues popped at the grant, cycle for cycle, while the round-robin's choice
//!   reaches only registers beside it: popped at the grant, the choice drove each queue's pop,
//!   count and head-valid flag across the die, the six-PE machine's critical path at two of
//!   three placement seeds.
//! * **Answers.** The host answers in request order, so the route queue's head is the PE of the
//!   answer arriving: `pe_valid` of that PE and the patch are registered and the head popped.
//!
//! Why round-robin: the host memory is the machine's bottleneck, every PE's work is alike, and
//! a PE that waits stalls its whole pipeline; round-robin gives every PE an equal share of the
//! port whenever several ask, never lets one PE's burst (sixteen requests after a sector change)
//! hold the others up by more than one grant each, and costs one register and a rotating
//! priority encoder (`N ≤ 8`). A fixed priority would starve the last PEs under load; an
//! oldest-first order would need a timestamp per request for little gain, since the queues
//! already keep each PE's requests in order.
//!
//! # Latency and throughput
//!
//! A request seen on `pe_req` at edge `t` is in its queue's head register after edge `t + 1`;
//! granted at edge `t + 2` if no other PE's turn comes first; on `host_req` from edge `t + 2`
//! (the cycle after). The host's answer on `host_valid` at edge `a` is on `pe_valid` after edge
//! `a`. So against a PE wired to the memory directly, each request costs four more clocks: a
//! patch loaded in `T_c + 4` instead of `T_c` cycles from the PE's request. One request to the
//! host per clock and one answer per clock. A request at the head of its queue is granted
//! within `N` clocks (each other PE granted at most once before it).
//!
//! # Formats
//!
//! Ids are [`ID_BITS`] bits, the patch's coordinates 17-bit world coordinates (Q11.6, the host
//! memory's words), passed through unchanged.
//!
//! # Models
//!
//! [`model::Arbiter`] steps the port behaviour on plain values (its queues pop at the grant, the
//! block's a clock later, with the same outputs in every cycle); `testbench/tests/arbiter.rs`
//! checks the block against it in every cycle (rung 3) and the exported Verilog against the
//! rust-hdl simulation (rung 4). `arbiter.sby` proves, on the Verilog, that no request is lost
//! or duplicated, that every answer goes to the PE that asked, with its patch, in its order, and
//! the bound on a PE's wait.

use crate::formats::ID_BITS;
use crate::prim::{Fifo, RoundRobin};
use rust_hdl::prelude::*;

/// The most processing elements an arbiter serves.
pub const MAX_PES: usize = 8;
/// Bits of a PE number.
pub const PE_BITS: usize = 3;
/// Address bits of a PE's request queue.
pub const QUEUE_BITS: usize = 4;
/// Requests a PE's queue holds: the most a PE may have outstanding.
pub const QUEUE_DEPTH: usize = 1 << QUEUE_BITS;
/// Address bits of the route queue.
pub const ROUTE_BITS: usize = 7;
/// Requests at the host at once: every PE's outstanding requests.
pub const ROUTE_DEPTH: usize = 1 << ROUTE_BITS;
/// Bits of the host memory's patch coordinates.
pub const WORD_BITS: usize = 17;
/// Clocks the arbiter adds to a load: a PE's request reaches the host memory three clocks
/// after its pulse when no other PE's turn comes first, and the answer the PE one clock after
/// the host's.
pub const LATENCY: u64 = 4;

const ID: usize = ID_BITS as usize;

/// The cycle model of [`MemoryArbiter`].
pub mod model {
    use super::{QUEUE_BITS, QUEUE_DEPTH, ROUTE_BITS, ROUTE_DEPTH};
    use crate::prim::fifo::model::Control;
    use crate::prim::rr::model::RoundRobin;
    use std::collections::VecDeque;

    /// A FIFO of values under the FIFO block's control registers.
    #[derive(Clone, Debug)]
    struct Queue<T> {
        control: Control,
        words: VecDeque<T>,
    }

    impl<T: Copy> Queue<T> {
        fn new(bits: usize) -> Self {
            Self { control: Control::new(bits as u32), words: VecDeque::new() }
        }
        fn head(&self) -> Option<T> {
            self.control.valid.then(|| self.words[0])
        }
        fn step(&mut self, push: Option<T>, pop: bool) {
            self.control.step(push.is_some(), pop);
            if pop {
                self.words.pop_front();
            }
            if let Some(w) = push {
                self.words.push_back(w);
            }
        }
    }

    /// The arbiter's outputs in one cycle.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct Outputs {
        /// The PE answered, if any (`pe_valid`), with the patch (`pe_ax` …).
        pub answer: Option<usize>,
        pub patch: [u32; 4],
        /// The request to the host (`host_req`, `host_addr`).
        pub host: Option<u16>,
        pub requests: u32,
    }

    /// The registers of [`super::MemoryArbiter`] with `n` PEs.
    #[derive(Clone, Debug)]
    pub struct Arbiter {
        queues: Vec<Queue<u16>>,
        route: Queue<usize>,
        rr: RoundRobin,
        out: Outputs,
    }

    impl Arbiter {
        /// An arbiter of `n` PEs at power-up.
        pub fn new(n: usize) -> Self {
            assert!((1..=super::MAX_PES).contains(&n), "an arbiter serves 1 to 8 PEs");
            Self {
                queues: (0..n).map(|_| Queue::new(QUEUE_BITS)).collect(),
                route: Queue::new(ROUTE_BITS),
                rr: RoundRobin::default(),
                out: Outputs::default(),
            }
        }

        /// The outputs (registers) in this cycle.
        pub fn outputs(&self) -> Outputs {
            self.out
        }

        /// Requests held for PE `i` (in its queue, not yet sent to the host).
        pub fn queued(&self, i: usize) -> usize {
            self.queues[i].words.len()
        }

        /// Whether PE `i`'s queue shows a request at its head (it asks for a turn).
        pub fn head_valid(&self, i: usize) -> bool {
            self.queues[i].control.valid
        }

        /// Requests at the host, not yet answered.
        pub fn at_host(&self) -> usize {
            self.route.words.len()
        }

        /// One rising edge: `requests[i]` is PE `i`'s request in this cycle, `answer` the host's.
        /// Returns the PE granted at this edge. Fails (naming it) on what the block cannot take:
        /// a request to a full queue, an answer with no request at the host.
        pub fn step(
            &mut self,
            requests: &[Option<u16>],
            answer: Option<[u32; 4]>,
        ) -> Result<Option<usize>, String> {
            let mut valid = [false; super::MAX_PES];
            for (v, q) in valid.iter_mut().zip(&self.queues) {
                *v = q.control.valid;
            }
            let grant = self.rr.step(&valid[..self.queues.len()]);
            if answer.is_some() && self.route.head().is_none() {
                return Err("a host answer with no request at the host".into());
            }
            let routed = answer.and_then(|_| self.route.head());
            let mut host = None;
            for (i, q) in self.queues.iter_mut().enumerate() {
                if requests[i].is_some() && q.words.len() >= QUEUE_DEPTH {
                    return Err(format!("PE {i} has more than {QUEUE_DEPTH} requests waiting"));
                }
                if grant == Some(i) {
                    host = q.head();
                }
                q.step(requests[i], grant == Some(i));
            }
            if self.route.words.len() >= ROUTE_DEPTH && grant.is_some() {
                return Err(format!("more than {ROUTE_DEPTH} requests at the host"));
            }
            self.route.step(grant, answer.is_some());
            self.out = Outputs {
                answer: routed,
                patch: answer.unwrap_or(self.out.patch),
                host,
                requests: self.out.requests.wrapping_add(grant.is_some() as u32),
            };
            Ok(grant)
        }
    }
}

/// The memory arbiter of `N ≤ 8` processing elements (see the [module documentation](self)).
#[derive(LogicBlock)]
pub struct MemoryArbiter<const N: usize> {
    pub clock: Signal<In, Clock>,
    // The PEs' ports.
    pub pe_req: [Signal<In, bool>; N],
    pub pe_addr: [Signal<In, Bits<ID>>; N],
    pub pe_valid: [Signal<Out, bool>; N],
    pub pe_ax: Signal<Out, Bits<WORD_BITS>>,
    pub pe_ay: Signal<Out, Bits<WORD_BITS>>,
    pub pe_bx: Signal<Out, Bits<WORD_BITS>>,
    pub pe_by: Signal<Out, Bits<WORD_BITS>>,
    // The host memory's port.
    pub host_req: Signal<Out, bool>,
    pub host_addr: Signal<Out, Bits<ID>>,
    pub host_valid: Signal<In, bool>,
    pub host_ax: Signal<In, Bits<WORD_BITS>>,
    pub host_ay: Signal<In, Bits<WORD_BITS>>,
    pub host_bx: Signal<In, Bits<WORD_BITS>>,
    pub host_by: Signal<In, Bits<WORD_BITS>>,
    pub requests: Signal<Out, Bits<32>>,
    // Requests.
    queues: [Fifo<ID, QUEUE_BITS, 5>; N],
    rr: RoundRobin<N, PE_BITS>,
    /// Each queue's head-valid flag as it would be with the queue popped at its grant: the
    /// round-robin's requests (see "Structure").
    asks: [DFF<bool>; N],
    /// The grant register, one-hot: the queue whose head is on the host port in this clock and
    /// leaves it at the next edge.
    grant: [DFF<bool>; N],
    grant_any: DFF<bool>,
    /// The granted queue's head.
    granted: Signal<Local, Bits<ID>>,
    count: DFF<Bits<32>>,
    // Answers.
    route: Fifo<PE_BITS, ROUTE_BITS, 8>,
    valid_r: [DFF<bool>; N],
    ax_r: DFF<Bits<WORD_BITS>>,
    ay_r: DFF<Bits<WORD_BITS>>,
    bx_r: DFF<Bits<WORD_BITS>>,
    by_r: DFF<Bits<WORD_BITS>>,
    zero_id: Constant<Bits<ID>>,
    one: Constant<Bits<32>>,
    zero_count: Constant<Bits<5>>,
    one_count: Constant<Bits<5>>,
    two_count: Constant<Bits<5>>,
}

impl<const N: usize> Default for MemoryArbiter<N> {
    fn default() -> Self {
        assert!((1..=MAX_PES).contains(&N), "MemoryArbiter: 1 to {MAX_PES} PEs, not {N}");
        assert!(ROUTE_DEPTH >= MAX_PES * QUEUE_DEPTH, "the route queue holds every request at the host");
        MemoryArbiter {
            clock: Default::default(),
            pe_req: std::array::from_fn(|_| Default::default()),
            pe_addr: std::array::from_fn(|_| Default::default()),
            pe_valid: std::array::from_fn(|_| Default::default()),
            pe_ax: Default::default(),
            pe_ay: Default::default(),
            pe_bx: Default::default(),
            pe_by: Default::default(),
            host_req: Default::default(),
            host_addr: Default::default(),
            host_valid: Default::default(),
            host_ax: Default::default(),
            host_ay: Default::default(),
            host_bx: Default::default(),
            host_by: Default::default(),
            requests: Default::default(),
            queues: std::array::from_fn(|_| Default::default()),
            rr: Default::default(),
            asks: std::array::from_fn(|_| Default::default()),
            grant: std::array::from_fn(|_| Default::default()),
            grant_any: Default::default(),
            granted: Default::default(),
            count: Default::default(),
            route: Default::default(),
            valid_r: std::array::from_fn(|_| Default::default()),
            ax_r: Default::default(),
            ay_r: Default::default(),
            bx_r: Default::default(),
            by_r: Default::default(),
            zero_id: Constant::new(0u64.into()),
            one: Constant::new(1u64.into()),
            zero_count: Constant::new(0u64.into()),
            one_count: Constant::new(1u64.into()),
            two_count: Constant::new(2u64.into()),
        }
    }
}

impl<const N: usize> Logic for MemoryArbiter<N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, grant_any, count, ax_r, ay_r, bx_r, by_r);
        self.rr.clock.next = self.clock.val();
        self.route.clock.next = self.clock.val();
        // Each PE's requests into its queue. The round-robin grants among the `asks` flags; the
        // grant goes into the grant register, and the queue it names shows its head on the host
        // port for a clock and pops it at the next edge, a clock after the grant. `asks` is the
        // queue's head-valid flag as it would be had the queue popped at the grant: from its
        // count less the pop still pending (`grant`), as `FifoControl` sets `valid` from its
        // count and this edge's pop.
        self.granted.next = self.zero_id.val();
        for i in 0..N {
            self.queues[i].clock.next = self.clock.val();
            self.queues[i].push.next = self.pe_req[i].val();
            self.queues[i].data_in.next = self.pe_addr[i].val();
            self.rr.request[i].next = self.asks[i].q.val();
            self.asks[i].clock.next = self.clock.val();
            self.grant[i].clock.next = self.clock.val();
            self.grant[i].d.next = self.rr.granted[i].val();
            // Words left once the pending pop is done: none, or exactly one.
            self.asks[i].d.next = self.queues[i].count.val() != self.zero_count.val();
            if self.grant[i].q.val() {
                self.asks[i].d.next = self.queues[i].count.val() != self.one_count.val();
            }
            if self.rr.granted[i].val() {
                if self.grant[i].q.val() {
                    if self.queues[i].count.val() == self.two_count.val() {
                        self.asks[i].d.next = false;
                    }
                } else if self.queues[i].count.val() == self.one_count.val() {
                    self.asks[i].d.next = false;
                }
            }
            self.queues[i].pop.next = self.grant[i].q.val();
            if self.grant[i].q.val() {
                self.granted.next = self.queues[i].data_out.val();
            }
        }
        // The granted request on the host port; its PE into the route queue at the grant.
        self.grant_any.d.next = self.rr.found.val();
        self.route.push.next = self.rr.found.val();
        self.route.data_in.next = self.rr.pick.val();
        if self.rr.found.val() {
            self.count.d.next = self.count.q.val() + self.one.val();
        }
        self.host_req.next = self.grant_any.q.val();
        self.host_addr.next = self.granted.val();
        self.requests.next = self.count.q.val();
        // The host's answer to the PE at the route queue's head.
        self.route.pop.next = self.host_valid.val();
        for i in 0..N {
            self.valid_r[i].clock.next = self.clock.val();
            self.valid_r[i].d.next = false;
            if self.route.data_out.val().index() == i {
                self.valid_r[i].d.next = self.host_valid.val();
            }
            self.pe_valid[i].next = self.valid_r[i].q.val();
        }
        if self.host_valid.val() {
            self.ax_r.d.next = self.host_ax.val();
            self.ay_r.d.next = self.host_ay.val();
            self.bx_r.d.next = self.host_bx.val();
            self.by_r.d.next = self.host_by.val();
        }
        self.pe_ax.next = self.ax_r.q.val();
        self.pe_ay.next = self.ay_r.q.val();
        self.pe_bx.next = self.bx_r.q.val();
        self.pe_by.next = self.by_r.q.val();
    }
}

#[cfg(test)]
mod tests {
    use super::model::Arbiter;

    /// Two PEs asking at once, then one alone: round-robin grants, answers routed back in order.
    #[test]
    fn the_model_alternates_and_routes_answers_back() {
        let mut a = Arbiter::new(2);
        let none = [None, None];
        a.step(&[Some(10), Some(20)], None).unwrap();
        a.step(&[Some(11), Some(21)], None).unwrap();
        // Both heads valid now (two clocks after the first push): 1 first (after last = 0).
        let mut sent = vec![];
        for _ in 0..6 {
            a.step(&none, None).unwrap();
            sent.extend(a.outputs().host);
        }
        assert_eq!(sent, [20, 10, 21, 11]);
        let mut answered = vec![];
        for k in 0..5 {
            a.step(&none, (k < 4).then_some([k, 0, 0, 0])).unwrap();
            answered.extend(a.outputs().answer.map(|pe| (pe, a.outputs().patch[0])));
        }
        assert_eq!(answered, [(1, 0), (0, 1), (1, 2), (0, 3)]);
        assert!(a.step(&none, Some([0; 4])).is_err(), "an answer with nothing at the host");
    }
}
