//! [`RoundRobin`]: a round-robin choice among `N` requesters, one per clock, written by hand in
//! both languages (rust-hdl 0.46 kernels cannot build a rotating priority: a loop that reads a
//! signal it writes does not settle as Verilog's blocking assignments do).
//!
//! # Ports
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | rising-edge clock |
//! | `request$i` | in | 1 each | requester `i` wants a turn |
//! | `found` | out | 1 | some requester is asking (the OR of the requests) |
//! | `pick` | out | `B` | the requester granted: the first asking one after the last granted, in the order `last + 1, last + 2, …, last + N` (mod `N`); 0 while none asks |
//! | `granted$i` | out | 1 each | requester `i` is granted (`found` and `pick = i`), each formed from the requests and `last` directly, not by decoding `pick` |
//!
//! `found`, `pick` and `granted` are combinational in the requests and one register, `last` (the last
//! requester granted, 0 at power-up). At every rising edge with `found` high the grant is taken:
//! `last` becomes `pick`. So a requester that keeps asking is granted within `N` clocks, and
//! with every requester asking the grants go `1, 2, …, N − 1, 0, 1, …`.
//!
//! # Model
//!
//! [`model::RoundRobin`] on plain integers (the same as the Rust half of the block); the rung-4
//! replay of every block that uses it checks the Verilog half against it.

use rust_hdl::prelude::*;

/// The bit-true model of [`RoundRobin`](super::RoundRobin).
pub mod model {
    /// The chooser's one register.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct RoundRobin {
        /// The last requester granted.
        pub last: usize,
    }

    impl RoundRobin {
        /// The requester granted among `requests` (indexed by requester), if any asks.
        pub fn pick(&self, requests: &[bool]) -> Option<usize> {
            let n = requests.len();
            (1..=n).map(|k| (self.last + k) % n).find(|&i| requests[i])
        }

        /// One rising edge: the grant of `requests` is taken.
        pub fn step(&mut self, requests: &[bool]) -> Option<usize> {
            let pick = self.pick(requests);
            if let Some(i) = pick {
                self.last = i;
            }
            pick
        }
    }
}

/// Round-robin choice among `N` requesters with a `B`-bit index (`2^B ≥ N`): see the [module
/// documentation](self).
#[derive(LogicBlock)]
pub struct RoundRobin<const N: usize, const B: usize> {
    pub clock: Signal<In, Clock>,
    pub request: [Signal<In, bool>; N],
    pub found: Signal<Out, bool>,
    pub pick: Signal<Out, Bits<B>>,
    pub granted: [Signal<Out, bool>; N],
    _rr: model::RoundRobin,
}

impl<const N: usize, const B: usize> Default for RoundRobin<N, B> {
    fn default() -> Self {
        assert!(N >= 1 && N <= 1 << B, "RoundRobin: {N} requesters do not fit a {B}-bit index");
        RoundRobin {
            clock: Default::default(),
            request: std::array::from_fn(|_| Default::default()),
            found: Default::default(),
            pick: Default::default(),
            granted: std::array::from_fn(|_| Default::default()),
            _rr: model::RoundRobin::default(),
        }
    }
}

impl<const N: usize, const B: usize> Logic for RoundRobin<N, B> {
    fn update(&mut self) {
        let requests: [bool; N] = std::array::from_fn(|i| self.request[i].val());
        if self.clock.pos_edge() {
            self._rr.step(&requests);
        }
        let pick = self._rr.pick(&requests);
        self.found.next = pick.is_some();
        self.pick.next = Bits::from(pick.unwrap_or(0) as u64);
        for (i, g) in self.granted.iter_mut().enumerate() {
            g.next = pick == Some(i);
        }
    }

    fn connect(&mut self) {
        self.found.connect();
        self.pick.connect();
        for g in &mut self.granted {
            g.connect();
        }
    }

    fn hdl(&self) -> Verilog {
        let request = |i: usize| format!("request${i}");
        let mut v = format!("reg [{hi}:0] last;\ninitial last = {B}'d0;\n", hi = B - 1);
        // One case on `last`: its order, highest priority first, gives `pick` (an if-else
        // chain) and each grant from the requests directly (a requester is granted when it asks
        // and no requester before it in the order does), not by decoding `pick`.
        v += "always @(*) begin\n";
        v += &format!(
            "   found = {};\n   pick = {B}'d0;\n   case (last)\n",
            (0..N).map(request).collect::<Vec<_>>().join(" | ")
        );
        for last in 0..N {
            let order: Vec<usize> = (1..=N).map(|k| (last + k) % N).collect();
            let chain: Vec<String> =
                order.iter().map(|&i| format!("if ({}) pick = {B}'d{i};", request(i))).collect();
            let grants: Vec<String> = order
                .iter()
                .enumerate()
                .map(|(k, &i)| {
                    let before: String = order[..k].iter().map(|&j| format!(" & !{}", request(j))).collect();
                    format!("granted${i} = {}{before};", request(i))
                })
                .collect();
            v += &format!("      {B}'d{last}: begin {} {} end\n", chain.join(" else "), grants.join(" "));
        }
        v += &format!(
            "      default: begin pick = 0; {} end\n   endcase\nend\n",
            (0..N).map(|i| format!("granted${i} = 1'b0;")).collect::<Vec<_>>().join(" ")
        );
        v += "always @(posedge clock) begin\n   if (found) last <= pick;\nend\n";
        Verilog::Custom(v)
    }

    fn timing(&self) -> Vec<TimingInfo> {
        let inputs: Vec<String> = (0..N).map(|i| format!("request${i}")).collect();
        let inputs: Vec<&str> = inputs.iter().map(String::as_str).collect();
        let mut outputs = vec!["found".to_string(), "pick".to_string()];
        outputs.extend((0..N).map(|i| format!("granted${i}")));
        let outputs: Vec<&str> = outputs.iter().map(String::as_str).collect();
        super::clocked("round_robin", &inputs, &outputs)
    }
}

#[cfg(test)]
mod tests {
    use super::model::RoundRobin;

    /// Everyone asking: the grants rotate; one asking: it is granted every clock; a requester
    /// that keeps asking waits at most `N − 1` grants of others.
    #[test]
    fn grants_rotate_and_no_requester_waits_more_than_n_minus_one_grants() {
        let mut rr = RoundRobin::default();
        let all = [true; 4];
        let got: Vec<usize> = (0..6).filter_map(|_| rr.step(&all)).collect();
        assert_eq!(got, [1, 2, 3, 0, 1, 2]);
        let one = [false, false, true, false];
        assert_eq!((0..3).filter_map(|_| rr.step(&one)).collect::<Vec<_>>(), [2, 2, 2]);
        assert_eq!(rr.step(&[false; 4]), None);
        assert_eq!(rr.last, 2, "no grant keeps the last one");
        // Requester 0 asking among three others who always ask: granted within 4 clocks.
        let mut rr = RoundRobin { last: 0 };
        let mut waited = 0;
        while rr.step(&all) != Some(0) {
            waited += 1;
        }
        assert_eq!(waited, 3);
    }
}
