//! The job queue: a 16-entry first-word-fall-through FIFO of the jobs the processing element's
//! merger sends the intersection unit (a passed patch's setup with its ray range, or a retire),
//! so that the merger runs ahead of the unit: while the unit tests a long job, the merger goes
//! on pairing tags with verdicts and drops the patches the screener screened out, instead of
//! waiting behind the one job the unit has not taken yet.
//!
//! # Ports ([`JobQueue`])
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | rising-edge clock |
//! | `in_valid`, `in_ready` | in, out | 1, 1 | input stream; `in_ready` (fewer than [`QUEUE_DEPTH`] jobs held) is a register |
//! | `in_id`, `in_ax` … `in_wy`, `in_sh`, `in_first`, `in_count`, `in_retire` | in | 16, 6 × 18, 6, 11, 11, 1 | the job: patch setup (Q12.6 coordinates, `W` and its exponent), ray range, retire flag |
//! | `out_valid`, `out_ready` | out, in | 1, 1 | output stream; `out_valid` and every `out_*` field depend on registers only |
//! | `out_id` … `out_retire` | out | as the inputs | the job at the head |
//! | `occupied` | out | 1 | a job is held (for the PE's `busy`) |
//!
//! # Structure, latency and throughput
//!
//! A [`FifoControl`] over eight [`FifoRam`] lanes (LUT RAM): id, the six coordinates and
//! `W` components, and one lane of 29 bits for the exponent, the retire flag and the range
//! (`sh` in bits 23..28, `retire` in bit 22, `first` in bits 11..21, `count` in bits 0..10).
//!
//! **The input register.** A job taken goes first into a register (`p_valid` and the `p_*`
//! fields, loaded in every clock) and is written into the lanes one clock later, so that the
//! lanes' write enable (some forty LUT RAMs) is a register, not the end of the producer's
//! handshake logic (the processing element's merger: 7.3 ns on ECP5 before). `held` counts the
//! jobs taken and not given, the one in the register included, and `in_ready` is a register of
//! its own (`held` reaching [`QUEUE_DEPTH`] after the edge), so the queue still holds
//! [`QUEUE_DEPTH`] jobs.
//!
//! A job taken by an empty queue is on the outputs three clocks later (one in the input
//! register, two more as the lanes read before they write); one push and one pop per clock;
//! the output stream is the input stream, in
//! order, none lost or duplicated, no field mixed between jobs (proved for all time by
//! `queue.sby`). `out_ready` reaches the control's pop and the lanes' output
//! multiplexers only, no RAM address.
//!
//! # Model
//!
//! A FIFO of [`QUEUE_DEPTH`] entries: [`model::Queue`], whose `in_ready` and `out_valid` the
//! RTL matches cycle for cycle (`testbench/tests/queue.rs`, rungs 3 and 4).

use crate::prim::{FifoControl, FifoRam};
use rust_hdl::prelude::*;

/// Address bits of the queue's lanes.
pub const QUEUE_BITS: usize = 4;
/// Jobs the queue holds.
pub const QUEUE_DEPTH: usize = 1 << QUEUE_BITS;
/// Clocks from a job taken by an empty queue to the job on the outputs.
pub const LATENCY: u32 = 3;

/// The cycle model of the job queue.
pub mod model {
    use super::{LATENCY, QUEUE_DEPTH};
    use std::collections::VecDeque;

    /// The queue's state, one [`clock`](Queue::clock) per cycle.
    #[derive(Clone, Debug)]
    pub struct Queue<T> {
        /// Jobs held, oldest first; each with the cycles since its push.
        held: VecDeque<(T, u32)>,
    }

    impl<T> Default for Queue<T> {
        fn default() -> Self {
            Queue { held: VecDeque::new() }
        }
    }

    impl<T: Clone> Queue<T> {
        /// `in_ready` this cycle.
        pub fn in_ready(&self) -> bool {
            self.held.len() < QUEUE_DEPTH
        }

        /// Jobs held.
        pub fn len(&self) -> usize {
            self.held.len()
        }

        /// No job held.
        pub fn is_empty(&self) -> bool {
            self.held.is_empty()
        }

        /// The job on the outputs this cycle (`out_valid` when `Some`): the head, once three
        /// edges have passed since it was taken.
        pub fn out(&self) -> Option<&T> {
            self.held.front().filter(|(_, age)| *age >= LATENCY).map(|(t, _)| t)
        }

        /// One rising edge with `input` offered (taken if `in_ready`) and `out_ready`; returns
        /// the job that left.
        pub fn clock(&mut self, input: Option<T>, out_ready: bool) -> Option<T> {
            let take = self.in_ready();
            let out =
                if out_ready && self.out().is_some() { self.held.pop_front().map(|(t, _)| t) } else { None };
            self.held.iter_mut().for_each(|(_, age)| *age += 1);
            if let Some(t) = input.filter(|_| take) {
                self.held.push_back((t, 1));
            }
            out
        }
    }
}

/// The job queue (see the [module documentation](self)).
#[derive(LogicBlock)]
pub struct JobQueue {
    pub clock: Signal<In, Clock>,
    pub in_valid: Signal<In, bool>,
    pub in_ready: Signal<Out, bool>,
    pub in_id: Signal<In, Bits<16>>,
    pub in_ax: Signal<In, Bits<18>>,
    pub in_ay: Signal<In, Bits<18>>,
    pub in_bx: Signal<In, Bits<18>>,
    pub in_by: Signal<In, Bits<18>>,
    pub in_wx: Signal<In, Bits<18>>,
    pub in_wy: Signal<In, Bits<18>>,
    pub in_sh: Signal<In, Bits<6>>,
    pub in_first: Signal<In, Bits<11>>,
    pub in_count: Signal<In, Bits<11>>,
    pub in_retire: Signal<In, bool>,
    pub out_valid: Signal<Out, bool>,
    pub out_ready: Signal<In, bool>,
    pub out_id: Signal<Out, Bits<16>>,
    pub out_ax: Signal<Out, Bits<18>>,
    pub out_ay: Signal<Out, Bits<18>>,
    pub out_bx: Signal<Out, Bits<18>>,
    pub out_by: Signal<Out, Bits<18>>,
    pub out_wx: Signal<Out, Bits<18>>,
    pub out_wy: Signal<Out, Bits<18>>,
    pub out_sh: Signal<Out, Bits<6>>,
    pub out_first: Signal<Out, Bits<11>>,
    pub out_count: Signal<Out, Bits<11>>,
    pub out_retire: Signal<Out, bool>,
    pub occupied: Signal<Out, bool>,
    control: FifoControl<QUEUE_BITS, 5>,
    lane_id: FifoRam<16, QUEUE_BITS>,
    lane_ax: FifoRam<18, QUEUE_BITS>,
    lane_ay: FifoRam<18, QUEUE_BITS>,
    lane_bx: FifoRam<18, QUEUE_BITS>,
    lane_by: FifoRam<18, QUEUE_BITS>,
    lane_wx: FifoRam<18, QUEUE_BITS>,
    lane_wy: FifoRam<18, QUEUE_BITS>,
    /// `sh`, `retire`, `first`, `count`.
    lane_job: FifoRam<29, QUEUE_BITS>,
    /// The input register: a job taken at the last edge, written into the lanes at this one.
    p_valid: DFF<bool>,
    p_id: DFF<Bits<16>>,
    p_ax: DFF<Bits<18>>,
    p_ay: DFF<Bits<18>>,
    p_bx: DFF<Bits<18>>,
    p_by: DFF<Bits<18>>,
    p_wx: DFF<Bits<18>>,
    p_wy: DFF<Bits<18>>,
    p_job: DFF<Bits<29>>,
    /// Jobs taken and not given (the input register's included).
    held: DFF<Bits<5>>,
    /// `held` is [`QUEUE_DEPTH`].
    held_full: DFF<bool>,
    take: Signal<Local, bool>,
    push: Signal<Local, bool>,
    pop: Signal<Local, bool>,
    sh_lane: Signal<Local, Bits<29>>,
    first_lane: Signal<Local, Bits<29>>,
    count_lane: Signal<Local, Bits<29>>,
    job_in: Signal<Local, Bits<29>>,
    job_out: Signal<Local, Bits<29>>,
    retire_bit: Constant<Bits<29>>,
    one5: Constant<Bits<5>>,
    almost_full: Constant<Bits<5>>,
    full: Constant<Bits<5>>,
    empty: Constant<Bits<5>>,
}

impl Default for JobQueue {
    fn default() -> Self {
        JobQueue {
            clock: Default::default(),
            in_valid: Default::default(),
            in_ready: Default::default(),
            in_id: Default::default(),
            in_ax: Default::default(),
            in_ay: Default::default(),
            in_bx: Default::default(),
            in_by: Default::default(),
            in_wx: Default::default(),
            in_wy: Default::default(),
            in_sh: Default::default(),
            in_first: Default::default(),
            in_count: Default::default(),
            in_retire: Default::default(),
            out_valid: Default::default(),
            out_ready: Default::default(),
            out_id: Default::default(),
            out_ax: Default::default(),
            out_ay: Default::default(),
            out_bx: Default::default(),
            out_by: Default::default(),
            out_wx: Default::default(),
            out_wy: Default::default(),
            out_sh: Default::default(),
            out_first: Default::default(),
            out_count: Default::default(),
            out_retire: Default::default(),
            occupied: Default::default(),
            control: Default::default(),
            lane_id: Default::default(),
            lane_ax: Default::default(),
            lane_ay: Default::default(),
            lane_bx: Default::default(),
            lane_by: Default::default(),
            lane_wx: Default::default(),
            lane_wy: Default::default(),
            lane_job: Default::default(),
            p_valid: Default::default(),
            p_id: Default::default(),
            p_ax: Default::default(),
            p_ay: Default::default(),
            p_bx: Default::default(),
            p_by: Default::default(),
            p_wx: Default::default(),
            p_wy: Default::default(),
            p_job: Default::default(),
            held: Default::default(),
            held_full: Default::default(),
            take: Default::default(),
            push: Default::default(),
            pop: Default::default(),
            sh_lane: Default::default(),
            first_lane: Default::default(),
            count_lane: Default::default(),
            job_in: Default::default(),
            job_out: Default::default(),
            retire_bit: Constant::new((1u64 << 22).into()),
            one5: Constant::new(1u64.into()),
            almost_full: Constant::new(((QUEUE_DEPTH - 1) as u64).into()),
            full: Constant::new((QUEUE_DEPTH as u64).into()),
            empty: Constant::new(0u64.into()),
        }
    }
}

impl Logic for JobQueue {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, p_valid, p_id, p_ax, p_ay, p_bx, p_by, p_wx, p_wy, p_job, held, held_full);
        self.control.clock.next = self.clock.val();
        self.lane_id.clock.next = self.clock.val();
        self.lane_ax.clock.next = self.clock.val();
        self.lane_ay.clock.next = self.clock.val();
        self.lane_bx.clock.next = self.clock.val();
        self.lane_by.clock.next = self.clock.val();
        self.lane_wx.clock.next = self.clock.val();
        self.lane_wy.clock.next = self.clock.val();
        self.lane_job.clock.next = self.clock.val();

        // The write side: a job is taken while fewer than QUEUE_DEPTH are held, into the input
        // register; the register's job is written at the next edge.
        self.in_ready.next = !self.held_full.q.val();
        self.take.next = self.in_valid.val() & !self.held_full.q.val();
        self.push.next = self.p_valid.q.val();
        self.control.push.next = self.push.val();
        self.sh_lane.next = bit_cast::<29, 6>(self.in_sh.val());
        self.first_lane.next = bit_cast::<29, 11>(self.in_first.val());
        self.count_lane.next = bit_cast::<29, 11>(self.in_count.val());
        self.job_in.next = (self.sh_lane.val() << 23) | (self.first_lane.val() << 11) | self.count_lane.val();
        if self.in_retire.val() {
            self.job_in.next = self.job_in.val() | self.retire_bit.val();
        }
        self.p_valid.d.next = self.take.val();
        self.p_id.d.next = self.in_id.val();
        self.p_ax.d.next = self.in_ax.val();
        self.p_ay.d.next = self.in_ay.val();
        self.p_bx.d.next = self.in_bx.val();
        self.p_by.d.next = self.in_by.val();
        self.p_wx.d.next = self.in_wx.val();
        self.p_wy.d.next = self.in_wy.val();
        self.p_job.d.next = self.job_in.val();
        self.lane_id.write_data.next = self.p_id.q.val();
        self.lane_ax.write_data.next = self.p_ax.q.val();
        self.lane_ay.write_data.next = self.p_ay.q.val();
        self.lane_bx.write_data.next = self.p_bx.q.val();
        self.lane_by.write_data.next = self.p_by.q.val();
        self.lane_wx.write_data.next = self.p_wx.q.val();
        self.lane_wy.write_data.next = self.p_wy.q.val();
        self.lane_job.write_data.next = self.p_job.q.val();

        // The read side: the head, from the lanes' read registers.
        self.pop.next = self.control.valid.val() & self.out_ready.val();
        self.control.pop.next = self.pop.val();
        self.out_valid.next = self.control.valid.val();
        self.occupied.next = self.held.q.val() != self.empty.val();
        // The jobs held after this edge: full after it when full with no pop, or one short
        // with a take and no pop.
        if self.take.val() & !self.pop.val() {
            self.held.d.next = self.held.q.val() + self.one5.val();
        }
        if !self.take.val() & self.pop.val() {
            self.held.d.next = self.held.q.val() - self.one5.val();
        }
        self.held_full.d.next = ((self.held.q.val() == self.full.val()) & !self.pop.val())
            | ((self.held.q.val() == self.almost_full.val()) & self.take.val() & !self.pop.val());
        self.out_id.next = self.lane_id.read_data.val();
        self.out_ax.next = self.lane_ax.read_data.val();
        self.out_ay.next = self.lane_ay.read_data.val();
        self.out_bx.next = self.lane_bx.read_data.val();
        self.out_by.next = self.lane_by.read_data.val();
        self.out_wx.next = self.lane_wx.read_data.val();
        self.out_wy.next = self.lane_wy.read_data.val();
        self.job_out.next = self.lane_job.read_data.val();
        self.out_sh.next = self.job_out.val().get_bits::<6>(23);
        self.out_retire.next = self.job_out.val().get_bit(22);
        self.out_first.next = self.job_out.val().get_bits::<11>(11);
        self.out_count.next = self.job_out.val().get_bits::<11>(0);

        // Every lane shares the control's addresses, write enable and pop.
        self.lane_id.write_address.next = self.control.tail_address.val();
        self.lane_id.write_enable.next = self.push.val();
        self.lane_id.head_address.next = self.control.head_address.val();
        self.lane_id.next_address.next = self.control.next_address.val();
        self.lane_id.pop.next = self.pop.val();
        self.lane_ax.write_address.next = self.control.tail_address.val();
        self.lane_ax.write_enable.next = self.push.val();
        self.lane_ax.head_address.next = self.control.head_address.val();
        self.lane_ax.next_address.next = self.control.next_address.val();
        self.lane_ax.pop.next = self.pop.val();
        self.lane_ay.write_address.next = self.control.tail_address.val();
        self.lane_ay.write_enable.next = self.push.val();
        self.lane_ay.head_address.next = self.control.head_address.val();
        self.lane_ay.next_address.next = self.control.next_address.val();
        self.lane_ay.pop.next = self.pop.val();
        self.lane_bx.write_address.next = self.control.tail_address.val();
        self.lane_bx.write_enable.next = self.push.val();
        self.lane_bx.head_address.next = self.control.head_address.val();
        self.lane_bx.next_address.next = self.control.next_address.val();
        self.lane_bx.pop.next = self.pop.val();
        self.lane_by.write_address.next = self.control.tail_address.val();
        self.lane_by.write_enable.next = self.push.val();
        self.lane_by.head_address.next = self.control.head_address.val();
        self.lane_by.next_address.next = self.control.next_address.val();
        self.lane_by.pop.next = self.pop.val();
        self.lane_wx.write_address.next = self.control.tail_address.val();
        self.lane_wx.write_enable.next = self.push.val();
        self.lane_wx.head_address.next = self.control.head_address.val();
        self.lane_wx.next_address.next = self.control.next_address.val();
        self.lane_wx.pop.next = self.pop.val();
        self.lane_wy.write_address.next = self.control.tail_address.val();
        self.lane_wy.write_enable.next = self.push.val();
        self.lane_wy.head_address.next = self.control.head_address.val();
        self.lane_wy.next_address.next = self.control.next_address.val();
        self.lane_wy.pop.next = self.pop.val();
        self.lane_job.write_address.next = self.control.tail_address.val();
        self.lane_job.write_enable.next = self.push.val();
        self.lane_job.head_address.next = self.control.head_address.val();
        self.lane_job.next_address.next = self.control.next_address.val();
        self.lane_job.pop.next = self.pop.val();
    }
}
