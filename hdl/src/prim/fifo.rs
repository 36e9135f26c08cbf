//! The first-word-fall-through FIFO of every block that buffers a stream: [`FifoControl`], its
//! pointers, word count and registered head-valid flag over one or more [`FifoRam`] lanes, and
//! [`Fifo`], a FIFO of one lane built from it.
//!
//! # Ports ([`FifoControl`])
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | rising-edge clock |
//! | `push` | in | 1 | a word is written at `tail_address` at this edge (the lanes' write enable) |
//! | `pop` | in | 1 | the head leaves at this edge; only while `valid` |
//! | `tail_address` | out | `A` | the write address of the next word pushed |
//! | `head_address`, `next_address` | out | `A`, `A` | the lanes' head and next read addresses (to [`FifoRam`]'s ports of the same names) |
//! | `valid` | out | 1 | the lanes' `read_data` is the head word (a register) |
//! | `count` | out | `C = A + 1` | words pushed and not popped, `0..=2^A` |
//!
//! Every output is a register or a function of registers only: `pop` reaches no RAM address (the
//! lanes read the head and the word after it in every clock and show the second after a pop), so
//! a consumer's `ready` may depend on anything downstream. `head_address + 1` is kept in a register
//! (`next_address`) of its own (bit 0 inverted, so that its power-up zero stands for 1): no carry chain before the
//! lanes' second read address.
//!
//! # Timing
//!
//! A word pushed at edge `t` is counted after `t`; `valid` rises after edge `t + 1` if it is the
//! head (the lanes read before they write, so the word is in their read registers one edge after
//! its write): write to `valid` two clocks, as rust-hdl's `SynchronousFIFO`. `valid` is set for
//! the next clock when a word pushed before this clock remains after this clock's pop
//! (`count − pop ≠ 0`). One push and one pop per clock, in any mix. A push while `count = 2^A`
//! overwrites the head's slot, and a pop while `valid` is low corrupts the count: the user
//! prevents both (every user here holds a credit or reservation count ahead of the push).
//! All registers are zero at power-up.
//!
//! # Model
//!
//! [`model::Control`] steps the same registers on plain integers; `testbench/tests/fifo.rs`
//! checks the block against it and against a queue (rung 3), and the exported Verilog of
//! [`Fifo`] against the rust-hdl simulation (rung 4). `fifo.sby` proves, on that Verilog, that
//! [`Fifo`] moves words between its handshakes with no loss, no duplication and in order.

use super::ram::FifoRam;
use rust_hdl::prelude::*;

/// The bit-true model of [`FifoControl`].
pub mod model {
    /// The registers of [`super::FifoControl`] with `a` address bits.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct Control {
        pub tail: u32,
        pub head: u32,
        pub count: u32,
        pub valid: bool,
        /// Address bits `A`.
        pub a: u32,
    }

    impl Control {
        /// The control of a FIFO with `2^a` slots, at power-up.
        pub fn new(a: u32) -> Control {
            Control { a, ..Control::default() }
        }

        /// `head + 1` modulo `2^a`: the `next_address` port.
        pub fn next(&self) -> u32 {
            (self.head + 1) & ((1 << self.a) - 1)
        }

        /// One rising edge with `push` and `pop` presented before it.
        pub fn step(&mut self, push: bool, pop: bool) {
            let mask = (1 << self.a) - 1;
            let left = self.count - pop as u32;
            self.valid = left != 0;
            if pop {
                self.head = (self.head + 1) & mask;
            }
            if push {
                self.tail = (self.tail + 1) & mask;
            }
            self.count = left + push as u32;
        }
    }
}

/// The pointers, word count and head-valid flag of a first-word-fall-through FIFO whose storage
/// is [`FifoRam`] lanes: see the [module documentation](self). `A` address bits (`2^A` slots),
/// `C = A + 1` count bits.
#[derive(LogicBlock)]
pub struct FifoControl<const A: usize, const C: usize> {
    pub clock: Signal<In, Clock>,
    pub push: Signal<In, bool>,
    pub pop: Signal<In, bool>,
    pub tail_address: Signal<Out, Bits<A>>,
    pub head_address: Signal<Out, Bits<A>>,
    pub next_address: Signal<Out, Bits<A>>,
    pub valid: Signal<Out, bool>,
    pub count: Signal<Out, Bits<C>>,
    tail_ptr: DFF<Bits<A>>,
    rd_ptr: DFF<Bits<A>>,
    /// `rd_ptr + 1` with bit 0 inverted.
    rd_inc_x: DFF<Bits<A>>,
    words: DFF<Bits<C>>,
    head_valid: DFF<bool>,
    rd_inc: Signal<Local, Bits<A>>,
    rd_inc2: Signal<Local, Bits<A>>,
    one_a: Constant<Bits<A>>,
    one_c: Constant<Bits<C>>,
    zero_c: Constant<Bits<C>>,
}

impl<const A: usize, const C: usize> Default for FifoControl<A, C> {
    fn default() -> Self {
        assert_eq!(C, A + 1, "FifoControl: the count needs one bit more than the addresses");
        assert!(A >= 1, "FifoControl: at least two slots");
        FifoControl {
            clock: Default::default(),
            push: Default::default(),
            pop: Default::default(),
            tail_address: Default::default(),
            head_address: Default::default(),
            next_address: Default::default(),
            valid: Default::default(),
            count: Default::default(),
            tail_ptr: Default::default(),
            rd_ptr: Default::default(),
            rd_inc_x: Default::default(),
            words: Default::default(),
            head_valid: Default::default(),
            rd_inc: Default::default(),
            rd_inc2: Default::default(),
            one_a: Constant::new(1u64.into()),
            one_c: Constant::new(1u64.into()),
            zero_c: Constant::new(0u64.into()),
        }
    }
}

impl<const A: usize, const C: usize> Logic for FifoControl<A, C> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, tail_ptr, rd_ptr, rd_inc_x, words, head_valid);
        // The write side: the next word goes to the tail.
        self.tail_address.next = self.tail_ptr.q.val();
        if self.push.val() {
            self.tail_ptr.d.next = self.tail_ptr.q.val() + self.one_a.val();
        }
        // The read side: the head and the slot after it; after a pop the second is the head.
        self.rd_inc.next = self.rd_inc_x.q.val() ^ self.one_a.val();
        self.rd_inc2.next = self.rd_inc.val() + self.one_a.val();
        self.head_address.next = self.rd_ptr.q.val();
        self.next_address.next = self.rd_inc.val();
        if self.pop.val() {
            self.rd_ptr.d.next = self.rd_inc.val();
            self.rd_inc_x.d.next = self.rd_inc2.val() ^ self.one_a.val();
        }
        // Valid next clock when a word written before this edge remains (read before write):
        // `words − pop ≠ 0`, written as two compares of the register, no subtraction before
        // the flag.
        self.head_valid.d.next = (self.words.q.val() != self.zero_c.val())
            & !(self.pop.val() & (self.words.q.val() == self.one_c.val()));
        self.valid.next = self.head_valid.q.val();
        if self.push.val() & !self.pop.val() {
            self.words.d.next = self.words.q.val() + self.one_c.val();
        }
        if !self.push.val() & self.pop.val() {
            self.words.d.next = self.words.q.val() - self.one_c.val();
        }
        self.count.next = self.words.q.val();
    }
}

/// A first-word-fall-through FIFO of `2^A` words of `D` bits: one [`FifoRam`] lane under a
/// [`FifoControl`]. In: `push` with `data_in` (written at the edge; the user keeps `count`
/// below `2^A`), `pop` (the head leaves at the edge; only while `valid`). Out: `valid` and
/// `data_out` (the head word, from registers only), `count`. Latency two clocks from a push to
/// `valid` on an empty FIFO; one push and one pop per clock.
#[derive(LogicBlock)]
pub struct Fifo<const D: usize, const A: usize, const C: usize> {
    pub clock: Signal<In, Clock>,
    pub push: Signal<In, bool>,
    pub data_in: Signal<In, Bits<D>>,
    pub pop: Signal<In, bool>,
    pub valid: Signal<Out, bool>,
    pub data_out: Signal<Out, Bits<D>>,
    pub count: Signal<Out, Bits<C>>,
    control: FifoControl<A, C>,
    lane: FifoRam<D, A>,
}

impl<const D: usize, const A: usize, const C: usize> Default for Fifo<D, A, C> {
    fn default() -> Self {
        Fifo {
            clock: Default::default(),
            push: Default::default(),
            data_in: Default::default(),
            pop: Default::default(),
            valid: Default::default(),
            data_out: Default::default(),
            count: Default::default(),
            control: Default::default(),
            lane: Default::default(),
        }
    }
}

impl<const D: usize, const A: usize, const C: usize> Logic for Fifo<D, A, C> {
    #[hdl_gen]
    fn update(&mut self) {
        self.control.clock.next = self.clock.val();
        self.lane.clock.next = self.clock.val();
        self.control.push.next = self.push.val();
        self.control.pop.next = self.pop.val();
        self.lane.write_address.next = self.control.tail_address.val();
        self.lane.write_data.next = self.data_in.val();
        self.lane.write_enable.next = self.push.val();
        self.lane.head_address.next = self.control.head_address.val();
        self.lane.next_address.next = self.control.next_address.val();
        self.lane.pop.next = self.pop.val();
        self.valid.next = self.control.valid.val();
        self.data_out.next = self.lane.read_data.val();
        self.count.next = self.control.count.val();
    }
}
