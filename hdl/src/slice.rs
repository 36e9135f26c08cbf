//! The patch slice: a two-entry register FIFO (a skid buffer) on a valid/ready patch stream,
//! whose `in_ready` is a register. The processing element puts one between the screener and the
//! merger (and the [`crate::queue::JobQueue`] between the merger and the intersection unit), so
//! that no combinational path runs from the unit's `patch_ready` through the merger into the
//! screener's output FIFO (the
//! PE's critical path at 107–120 MHz before, with most of its delay in routing between the
//! blocks).
//!
//! # Ports ([`PatchSlice`])
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | rising-edge clock |
//! | `in_valid`, `in_ready` | in, out | 1, 1 | input stream; `in_ready` is a register (high while the skid entry is free) |
//! | `in_id`, `in_ax` … `in_wy`, `in_sh`, `in_pass`, `in_first`, `in_count`, `in_retire` | in | 16, 6 × 18, 6, 1, 10, 11, 1 | the patch as the screener gives it and the tag's fields the merger adds |
//! | `out_valid`, `out_ready` | out, in | 1, 1 | output stream; `out_valid` and every `out_*` field are registers |
//! | `out_id` … `out_retire` | out | as the inputs | the patch |
//! | `occupied` | out | 1 | an entry is held (for the PE's `busy`) |
//!
//! A field a user does not need is tied to zero and its registers are removed by synthesis.
//!
//! # Behaviour, latency and throughput
//!
//! Two entries: `main` (on the outputs) and `skid`. A patch transfers in when `in_valid &&
//! in_ready` and out when `out_valid && out_ready`, before the rising edge. A patch taken into
//! an empty slice is on the outputs in the next cycle (latency 1); with `out_ready` high every
//! cycle the slice passes one patch per clock. When `out_ready` is low while `main` is full, one
//! more patch goes to `skid`, and `in_ready` falls in the next cycle. The output stream is the
//! input stream, in order, none lost or duplicated.
//!
//! `out_ready` selects only the load enable of `main` (fan-out, no logic after it); `in_ready`
//! depends on no input.
//!
//! # Model
//!
//! A FIFO of two entries: [`model::Slice`], whose `in_ready` and `out_valid` in each cycle the
//! RTL matches cycle for cycle (checked in this file's tests under random valid/ready; the
//! PE's rung-4 replays check its Verilog).

use rust_hdl::prelude::*;

/// The behavioural model of the slice, one call per clock.
pub mod model {
    use std::collections::VecDeque;

    /// The slice's state: the patches held, oldest first (at most two).
    #[derive(Clone, Debug, Default)]
    pub struct Slice<T> {
        held: VecDeque<T>,
    }

    impl<T: Clone> Slice<T> {
        /// `in_ready` this cycle: fewer than two patches held.
        pub fn in_ready(&self) -> bool {
            self.held.len() < 2
        }

        /// The patch on the outputs this cycle (`out_valid` when `Some`).
        pub fn out(&self) -> Option<&T> {
            self.held.front()
        }

        /// The rising edge: `input` offered (`in_valid`), `out_ready`. Returns the patch that
        /// left, if any.
        pub fn clock(&mut self, input: Option<T>, out_ready: bool) -> Option<T> {
            let left = if out_ready { self.held.pop_front() } else { None };
            if let (Some(p), true) = (input, self.held.len() + usize::from(left.is_some()) < 2) {
                self.held.push_back(p);
            }
            left
        }
    }
}

/// The patch slice (see the [module documentation](self)).
#[derive(LogicBlock, Default)]
pub struct PatchSlice {
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
    pub in_pass: Signal<In, bool>,
    pub in_first: Signal<In, Bits<10>>,
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
    pub out_pass: Signal<Out, bool>,
    pub out_first: Signal<Out, Bits<10>>,
    pub out_count: Signal<Out, Bits<11>>,
    pub out_retire: Signal<Out, bool>,
    pub occupied: Signal<Out, bool>,
    // main (the outputs) and skid: valid and fields.
    m_v: DFF<bool>,
    m_id: DFF<Bits<16>>,
    m_ax: DFF<Bits<18>>,
    m_ay: DFF<Bits<18>>,
    m_bx: DFF<Bits<18>>,
    m_by: DFF<Bits<18>>,
    m_wx: DFF<Bits<18>>,
    m_wy: DFF<Bits<18>>,
    m_sh: DFF<Bits<6>>,
    m_pass: DFF<bool>,
    m_first: DFF<Bits<10>>,
    m_count: DFF<Bits<11>>,
    m_retire: DFF<bool>,
    s_v: DFF<bool>,
    s_id: DFF<Bits<16>>,
    s_ax: DFF<Bits<18>>,
    s_ay: DFF<Bits<18>>,
    s_bx: DFF<Bits<18>>,
    s_by: DFF<Bits<18>>,
    s_wx: DFF<Bits<18>>,
    s_wy: DFF<Bits<18>>,
    s_sh: DFF<Bits<6>>,
    s_pass: DFF<bool>,
    s_first: DFF<Bits<10>>,
    s_count: DFF<Bits<11>>,
    s_retire: DFF<bool>,
    take: Signal<Local, bool>,
    load_main: Signal<Local, bool>,
}

impl Logic for PatchSlice {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, m_v, m_id, m_ax, m_ay, m_bx, m_by, m_wx, m_wy, m_sh, m_pass, m_first, m_count,
            m_retire, s_v, s_id, s_ax, s_ay, s_bx, s_by, s_wx, s_wy, s_sh, s_pass, s_first, s_count,
            s_retire
        );
        self.in_ready.next = !self.s_v.q.val();
        self.take.next = self.in_valid.val() & !self.s_v.q.val();
        // main takes a patch when it is empty or leaves this cycle: skid's, else the input's.
        self.load_main.next = !self.m_v.q.val() | self.out_ready.val();
        if self.load_main.val() {
            self.m_v.d.next = self.s_v.q.val() | self.take.val();
            self.s_v.d.next = false;
            if self.s_v.q.val() {
                self.m_id.d.next = self.s_id.q.val();
                self.m_ax.d.next = self.s_ax.q.val();
                self.m_ay.d.next = self.s_ay.q.val();
                self.m_bx.d.next = self.s_bx.q.val();
                self.m_by.d.next = self.s_by.q.val();
                self.m_wx.d.next = self.s_wx.q.val();
                self.m_wy.d.next = self.s_wy.q.val();
                self.m_sh.d.next = self.s_sh.q.val();
                self.m_pass.d.next = self.s_pass.q.val();
                self.m_first.d.next = self.s_first.q.val();
                self.m_count.d.next = self.s_count.q.val();
                self.m_retire.d.next = self.s_retire.q.val();
            } else {
                self.m_id.d.next = self.in_id.val();
                self.m_ax.d.next = self.in_ax.val();
                self.m_ay.d.next = self.in_ay.val();
                self.m_bx.d.next = self.in_bx.val();
                self.m_by.d.next = self.in_by.val();
                self.m_wx.d.next = self.in_wx.val();
                self.m_wy.d.next = self.in_wy.val();
                self.m_sh.d.next = self.in_sh.val();
                self.m_pass.d.next = self.in_pass.val();
                self.m_first.d.next = self.in_first.val();
                self.m_count.d.next = self.in_count.val();
                self.m_retire.d.next = self.in_retire.val();
            }
        } else {
            // main holds; a patch taken goes to skid.
            self.s_v.d.next = self.s_v.q.val() | self.take.val();
        }
        // skid's fields follow the input while it is free (they matter only with s_v).
        if !self.s_v.q.val() {
            self.s_id.d.next = self.in_id.val();
            self.s_ax.d.next = self.in_ax.val();
            self.s_ay.d.next = self.in_ay.val();
            self.s_bx.d.next = self.in_bx.val();
            self.s_by.d.next = self.in_by.val();
            self.s_wx.d.next = self.in_wx.val();
            self.s_wy.d.next = self.in_wy.val();
            self.s_sh.d.next = self.in_sh.val();
            self.s_pass.d.next = self.in_pass.val();
            self.s_first.d.next = self.in_first.val();
            self.s_count.d.next = self.in_count.val();
            self.s_retire.d.next = self.in_retire.val();
        }
        self.out_valid.next = self.m_v.q.val();
        self.out_id.next = self.m_id.q.val();
        self.out_ax.next = self.m_ax.q.val();
        self.out_ay.next = self.m_ay.q.val();
        self.out_bx.next = self.m_bx.q.val();
        self.out_by.next = self.m_by.q.val();
        self.out_wx.next = self.m_wx.q.val();
        self.out_wy.next = self.m_wy.q.val();
        self.out_sh.next = self.m_sh.q.val();
        self.out_pass.next = self.m_pass.q.val();
        self.out_first.next = self.m_first.q.val();
        self.out_count.next = self.m_count.q.val();
        self.out_retire.next = self.m_retire.q.val();
        self.occupied.next = self.m_v.q.val() | self.s_v.q.val();
    }
}

#[cfg(test)]
mod tests {
    use super::model::Slice;
    use super::*;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;
    use rust_hdl::core::prelude::simulate;

    /// Random valid/ready on both sides (seeded; the seed is printed on failure): `in_ready`,
    /// `out_valid` and the patch on the outputs equal the model's every cycle, and every patch
    /// offered comes out once, in order. With both sides always ready: one patch per clock.
    #[test]
    fn slice_matches_the_two_entry_fifo_model() {
        for seed in 0..8u64 {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let (p_in, p_out) =
                if seed == 0 { (1.0, 1.0) } else { (rng.random_range(0.2..1.0), rng.random_range(0.2..1.0)) };
            let mut u = PatchSlice::default();
            u.connect_all();
            let mut model = Slice::<u64>::default();
            let (mut next, mut got) = (0u64, vec![]);
            for cycle in 0..2000u64 {
                u.clock.next = false.into();
                let offer = rng.random_bool(p_in);
                let out_ready = rng.random_bool(p_out);
                u.in_valid.next = offer;
                u.out_ready.next = out_ready;
                // Every field carries bits of the patch number, so a swapped field shows.
                u.in_id.next = (next & 0xFFFF).into();
                u.in_ax.next = (next * 3 & 0x3_FFFF).into();
                u.in_ay.next = (next * 5 & 0x3_FFFF).into();
                u.in_bx.next = (next * 7 & 0x3_FFFF).into();
                u.in_by.next = (next * 11 & 0x3_FFFF).into();
                u.in_wx.next = (next * 13 & 0x3_FFFF).into();
                u.in_wy.next = (next * 17 & 0x3_FFFF).into();
                u.in_sh.next = (next & 0x3F).into();
                u.in_pass.next = next & 1 == 1;
                u.in_first.next = (next * 19 & 0x3FF).into();
                u.in_count.next = (next * 23 & 0x7FF).into();
                u.in_retire.next = next & 2 == 2;
                assert!(simulate(&mut u, 100), "seed {seed}");
                let ctx = format!("seed {seed}, cycle {cycle}");
                assert_eq!(u.in_ready.val(), model.in_ready(), "{ctx}: in_ready");
                assert_eq!(u.out_valid.val(), model.out().is_some(), "{ctx}: out_valid");
                assert_eq!(u.occupied.val(), model.out().is_some(), "{ctx}: occupied");
                if let Some(&p) = model.out() {
                    let fields = [
                        u.out_id.val().to_u64(),
                        u.out_ax.val().to_u64(),
                        u.out_ay.val().to_u64(),
                        u.out_bx.val().to_u64(),
                        u.out_by.val().to_u64(),
                        u.out_wx.val().to_u64(),
                        u.out_wy.val().to_u64(),
                        u.out_sh.val().to_u64(),
                        u.out_pass.val() as u64,
                        u.out_first.val().to_u64(),
                        u.out_count.val().to_u64(),
                        u.out_retire.val() as u64,
                    ];
                    let want = [
                        p & 0xFFFF,
                        p * 3 & 0x3_FFFF,
                        p * 5 & 0x3_FFFF,
                        p * 7 & 0x3_FFFF,
                        p * 11 & 0x3_FFFF,
                        p * 13 & 0x3_FFFF,
                        p * 17 & 0x3_FFFF,
                        p & 0x3F,
                        p & 1,
                        p * 19 & 0x3FF,
                        p * 23 & 0x7FF,
                        (p >> 1) & 1,
                    ];
                    assert_eq!(fields, want, "{ctx}: fields of patch {p}");
                }
                let accepted = offer && u.in_ready.val();
                if let Some(p) = model.clock(offer.then_some(next), out_ready) {
                    got.push(p);
                }
                if accepted {
                    next += 1;
                }
                u.clock.next = true.into();
                assert!(simulate(&mut u, 100), "seed {seed}");
            }
            assert_eq!(got, (0..got.len() as u64).collect::<Vec<_>>(), "seed {seed}: order");
            assert!(next - got.len() as u64 <= 2, "seed {seed}: at most two held");
            if seed == 0 {
                assert!(got.len() >= 1998, "seed 0: one patch per clock, got {}", got.len());
            }
        }
    }
}
