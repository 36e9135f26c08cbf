//! Toy blocks for the test-bench's own tests: a 6-stage 32-bit pipeline with a valid bit (with
//! its Rust model and the loop that checks it against the model), an 8-entry write/full FIFO
//! built on rust-hdl's `SynchronousFIFO`, a block with an interface port, a block whose exported Verilog is known to disagree
//! with its rust-hdl simulation, one that fails rust-hdl's checks, and a ring of registers at
//! three depths of the hierarchy.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rust_hdl::prelude::*;
use shelling_testbench::{impl_clocked, Driver, Pacing, Scoreboard, Source};

/// XORed into the pipeline's result in the last stage (through a `Constant`, per the
/// safe-subset rules of `rust-hdl-notes.md`).
pub const KEY: u32 = 0x9e37_79b9;
/// Cycles from an input to its output: the input is captured at the first rising edge and the
/// result is visible after the sixth.
pub const PIPE_LATENCY: u64 = 6;

/// `y = rotl(lo16(a) * hi16(b) + (a + b), 7) ^ KEY`, one register stage per operation.
#[derive(LogicBlock)]
pub struct MulAddPipe {
    pub clock: Signal<In, Clock>,
    pub a: Signal<In, Bits<32>>,
    pub b: Signal<In, Bits<32>>,
    pub valid_in: Signal<In, Bit>,
    pub y: Signal<Out, Bits<32>>,
    pub valid_out: Signal<Out, Bit>,
    key: Constant<Bits<32>>,
    a1: DFF<Bits<32>>,
    b1: DFF<Bits<32>>,
    sum2: DFF<Bits<32>>,
    lo2: DFF<Bits<16>>,
    hi2: DFF<Bits<16>>,
    prod3: DFF<Bits<32>>,
    sum3: DFF<Bits<32>>,
    mix4: DFF<Bits<32>>,
    rot5: DFF<Bits<32>>,
    out6: DFF<Bits<32>>,
    v1: DFF<Bit>,
    v2: DFF<Bit>,
    v3: DFF<Bit>,
    v4: DFF<Bit>,
    v5: DFF<Bit>,
    v6: DFF<Bit>,
}

impl Default for MulAddPipe {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            a: Default::default(),
            b: Default::default(),
            valid_in: Default::default(),
            y: Default::default(),
            valid_out: Default::default(),
            key: Constant::new(bits(KEY.into())),
            a1: Default::default(),
            b1: Default::default(),
            sum2: Default::default(),
            lo2: Default::default(),
            hi2: Default::default(),
            prod3: Default::default(),
            sum3: Default::default(),
            mix4: Default::default(),
            rot5: Default::default(),
            out6: Default::default(),
            v1: Default::default(),
            v2: Default::default(),
            v3: Default::default(),
            v4: Default::default(),
            v5: Default::default(),
            v6: Default::default(),
        }
    }
}

impl Logic for MulAddPipe {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, a1, b1, sum2, lo2, hi2, prod3, sum3, mix4, rot5, out6, v1, v2, v3, v4, v5, v6
        );
        self.a1.d.next = self.a.val();
        self.b1.d.next = self.b.val();
        self.v1.d.next = self.valid_in.val();
        self.sum2.d.next = self.a1.q.val() + self.b1.q.val();
        self.lo2.d.next = self.a1.q.val().get_bits::<16>(0);
        self.hi2.d.next = self.b1.q.val().get_bits::<16>(16);
        self.v2.d.next = self.v1.q.val();
        self.prod3.d.next = self.lo2.q.val() * self.hi2.q.val();
        self.sum3.d.next = self.sum2.q.val();
        self.v3.d.next = self.v2.q.val();
        self.mix4.d.next = self.prod3.q.val() + self.sum3.q.val();
        self.v4.d.next = self.v3.q.val();
        self.rot5.d.next = (self.mix4.q.val() << 7) | (self.mix4.q.val() >> 25);
        self.v5.d.next = self.v4.q.val();
        self.out6.d.next = self.rot5.q.val() ^ self.key.val();
        self.v6.d.next = self.v5.q.val();
        self.y.next = self.out6.q.val();
        self.valid_out.next = self.v6.q.val();
    }
}

/// The bit-true model of [`MulAddPipe`].
pub fn mul_add_model(a: u32, b: u32) -> u32 {
    let prod = (a & 0xffff) * (b >> 16);
    prod.wrapping_add(a.wrapping_add(b)).rotate_left(7) ^ KEY
}

/// An 8-entry first-word-fall-through FIFO of 16-bit words with plain top-level ports.
#[derive(LogicBlock, Default)]
pub struct Fifo {
    pub clock: Signal<In, Clock>,
    pub write: Signal<In, Bit>,
    pub data_in: Signal<In, Bits<16>>,
    pub full: Signal<Out, Bit>,
    pub overflow: Signal<Out, Bit>,
    pub read: Signal<In, Bit>,
    pub data_out: Signal<Out, Bits<16>>,
    pub empty: Signal<Out, Bit>,
    pub underflow: Signal<Out, Bit>,
    fifo: SynchronousFIFO<Bits<16>, 3, 4, 1>,
}

impl Logic for Fifo {
    #[hdl_gen]
    fn update(&mut self) {
        self.fifo.clock.next = self.clock.val();
        self.fifo.write.next = self.write.val();
        self.fifo.data_in.next = self.data_in.val();
        self.fifo.read.next = self.read.val();
        self.full.next = self.fifo.full.val();
        self.overflow.next = self.fifo.overflow.val();
        self.data_out.next = self.fifo.data_out.val();
        self.empty.next = self.fifo.empty.val();
        self.underflow.next = self.fifo.underflow.val();
    }
}

/// `y = (a * b) >> 8` truncated to 16 bits, written the way `rust-hdl-notes.md` §1 warns
/// against: the exported Verilog evaluates the product at 16 bits, the simulation at 32.
#[derive(LogicBlock, Default)]
pub struct ScaledProduct {
    pub clock: Signal<In, Clock>,
    pub a: Signal<In, Bits<16>>,
    pub b: Signal<In, Bits<16>>,
    pub y: Signal<Out, Bits<16>>,
    r: DFF<Bits<16>>,
}

impl Logic for ScaledProduct {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, r);
        self.r.d.next = bit_cast::<16, 32>((self.a.val() * self.b.val()) >> 8);
        self.y.next = self.r.q.val();
    }
}

/// Sums the words written through an interface port (`bus$data`, `bus$write`... in Verilog).
#[derive(LogicBlock, Default)]
pub struct BusSum {
    pub clock: Signal<In, Clock>,
    pub bus: FIFOWriteResponder<Bits<8>>,
    pub sum: Signal<Out, Bits<8>>,
    acc: DFF<Bits<8>>,
}

impl Logic for BusSum {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, acc);
        self.bus.full.next = false;
        self.bus.almost_full.next = false;
        if self.bus.write.val() {
            self.acc.d.next = self.acc.q.val() + self.bus.data.val();
        }
        self.sum.next = self.acc.q.val();
    }
}

/// A block with an output nobody drives: rust-hdl's `check_all` refuses it.
#[derive(LogicBlock, Default)]
pub struct Undriven {
    pub clock: Signal<In, Clock>,
    pub y: Signal<Out, Bit>,
}

impl Logic for Undriven {
    #[hdl_gen]
    fn update(&mut self) {}
}

/// The innermost level of [`Ring`]: one register (three levels below the top).
#[derive(LogicBlock, Default)]
pub struct RingLeaf {
    pub clock: Signal<In, Clock>,
    pub d: Signal<In, Bits<16>>,
    pub q: Signal<Out, Bits<16>>,
    r3: DFF<Bits<16>>,
}

impl Logic for RingLeaf {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, r3);
        self.r3.d.next = self.d.val();
        self.q.next = self.r3.q.val();
    }
}

/// The middle level of [`Ring`]: one register (two levels below the top) feeding a
/// [`RingLeaf`]; the leaf's register comes back out combinationally.
#[derive(LogicBlock, Default)]
pub struct RingMid {
    pub clock: Signal<In, Clock>,
    pub d: Signal<In, Bits<16>>,
    pub q2: Signal<Out, Bits<16>>,
    pub q3: Signal<Out, Bits<16>>,
    r2: DFF<Bits<16>>,
    leaf: RingLeaf,
}

impl Logic for RingMid {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, r2);
        self.leaf.clock.next = self.clock.val();
        self.r2.d.next = self.d.val();
        self.leaf.d.next = self.r2.q.val();
        self.q2.next = self.r2.q.val();
        self.q3.next = self.leaf.q.val();
    }
}

/// Registers one, two and three levels deep in a ring: `r1 ← r3 + step`, `r2 ← r1`, `r3 ← r2`
/// at every rising edge. Every register must capture its input as it was before the edge,
/// whatever its depth: the check of the driver's edge timing across the hierarchy.
#[derive(LogicBlock, Default)]
pub struct Ring {
    pub clock: Signal<In, Clock>,
    pub step: Signal<In, Bits<16>>,
    pub q1: Signal<Out, Bits<16>>,
    pub q2: Signal<Out, Bits<16>>,
    pub q3: Signal<Out, Bits<16>>,
    r1: DFF<Bits<16>>,
    mid: RingMid,
}

impl Logic for Ring {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, r1);
        self.mid.clock.next = self.clock.val();
        self.r1.d.next = self.mid.q3.val() + self.step.val();
        self.mid.d.next = self.r1.q.val();
        self.q1.next = self.r1.q.val();
        self.q2.next = self.mid.q2.val();
        self.q3.next = self.mid.q3.val();
    }
}

impl_clocked!(MulAddPipe, Fifo, ScaledProduct, BusSum, Undriven, Ring);

/// Runs `vectors` through [`MulAddPipe`] in `drv`, presenting them with the source's idle
/// pattern (`pacing.idle`; the pipeline cannot stall, so backpressure does not apply), and
/// checks every valid output against [`mul_add_model`]. Returns the number of outputs checked.
pub fn run_pipeline(
    drv: &mut Driver<MulAddPipe>,
    vectors: &[(u32, u32)],
    pacing: Pacing,
    seed: u64,
) -> shelling_testbench::Result<usize> {
    let expected = vectors.iter().map(|&(a, b)| mul_add_model(a, b));
    let mut board = Scoreboard::new("mul-add pipeline", seed, expected).with_context(pacing.to_string());
    let mut src = Source::new(vectors.iter().copied(), pacing, seed);
    let mut idle_after = 0;
    while idle_after < PIPE_LATENCY {
        drv.drive(|u| {
            let item = src.present(true);
            u.valid_in.next = item.is_some();
            let (a, b) = item.copied().unwrap_or_default();
            u.a.next = bits(a.into());
            u.b.next = bits(b.into());
        })?;
        src.accepted(drv.uut().valid_in.val())?;
        drv.tick()?;
        if drv.uut().valid_out.val() {
            board.check(drv.cycles(), drv.uut().y.val().to_u32())?;
        }
        if src.is_done() {
            idle_after += 1;
        }
    }
    board.finish()
}

/// Seeded random operand pairs.
pub fn random_vectors(n: usize, seed: u64) -> Vec<(u32, u32)> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..n).map(|_| (rng.random(), rng.random())).collect()
}
