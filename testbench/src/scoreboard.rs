//! Scoreboard: DUT outputs against model outputs, in order.
//!
//! Queue the model's outputs ([`Scoreboard::new`], [`Scoreboard::expect`]), feed every DUT output
//! as it appears ([`Scoreboard::check`]), and call [`Scoreboard::finish`] at the end to make sure
//! none is missing. The first mismatch is an [`Error`] naming the scoreboard, the seed, the output
//! index and the cycle, with the DUT and model values (`Debug`) one above the other:
//!
//! ```text
//! scoreboard `pipeline` (seed 0x2a, random idle): output #17 at cycle 42 differs
//!   dut:   Out { y: 1234, flag: true }
//!   model: Out { y: 1235, flag: true }
//! ```
//!
//! Use a small `#[derive(Debug, PartialEq)]` struct of the fields to compare, so the report shows
//! which one differs.

use std::collections::VecDeque;
use std::fmt::Debug;

use crate::{Error, Result};

/// Compares a stream of DUT outputs with the expected model outputs (see the [module docs](self)).
#[derive(Clone, Debug)]
pub struct Scoreboard<T> {
    name: String,
    seed: u64,
    context: String,
    expected: VecDeque<T>,
    matched: usize,
}

impl<T: Debug + PartialEq> Scoreboard<T> {
    /// A scoreboard `name` for a run with `seed`, expecting `expected` in order.
    pub fn new(name: impl Into<String>, seed: u64, expected: impl IntoIterator<Item = T>) -> Self {
        Self {
            name: name.into(),
            seed,
            context: String::new(),
            expected: expected.into_iter().collect(),
            matched: 0,
        }
    }

    /// Adds a note (e.g. the pacing) to every report of this scoreboard.
    pub fn with_context(mut self, context: impl Into<String>) -> Self {
        self.context = context.into();
        self
    }

    /// Appends an expected output (for models computed as the test goes).
    pub fn expect(&mut self, item: T) {
        self.expected.push_back(item);
    }

    /// Checks the next DUT output `dut`, produced at `cycle`, against the next expected one.
    pub fn check(&mut self, cycle: u64, dut: T) -> Result<()> {
        let index = self.matched;
        match self.expected.pop_front() {
            Some(model) if model == dut => {
                self.matched += 1;
                Ok(())
            }
            Some(model) => Err(self.error(format!(
                "output #{index} at cycle {cycle} differs\n  dut:   {dut:?}\n  model: {model:?}"
            ))),
            None => Err(self.error(format!(
                "unexpected output #{index} at cycle {cycle} (the model has no more)\n  dut:   {dut:?}"
            ))),
        }
    }

    /// Checks `(cycle, output)` pairs in order, e.g. a [`Monitor`](crate::Monitor)'s items.
    pub fn check_all(&mut self, outputs: impl IntoIterator<Item = (u64, T)>) -> Result<()> {
        outputs.into_iter().try_for_each(|(cycle, dut)| self.check(cycle, dut))
    }

    /// Outputs matched so far.
    pub fn matched(&self) -> usize {
        self.matched
    }

    /// Ends the comparison: fails if expected outputs never came. Returns how many matched.
    pub fn finish(&self) -> Result<usize> {
        match self.expected.front() {
            None => Ok(self.matched),
            Some(next) => Err(self.error(format!(
                "{} expected outputs missing after {} matched; the next one:\n  model: {next:?}",
                self.expected.len(),
                self.matched
            ))),
        }
    }

    fn error(&self, what: String) -> Error {
        let context = if self.context.is_empty() { String::new() } else { format!(", {}", self.context) };
        Error::new(format!("scoreboard `{}` (seed {:#x}{context}): {what}", self.name, self.seed))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reports_mismatch_with_index_cycle_seed_and_both_values() {
        let mut sb = Scoreboard::new("toy", 0x2a, [1, 2, 3]).with_context("random idle");
        sb.check(5, 1).unwrap();
        let msg = sb.check(9, 7).unwrap_err().to_string();
        assert_eq!(
            msg,
            "scoreboard `toy` (seed 0x2a, random idle): output #1 at cycle 9 differs\n  dut:   7\n  model: 2"
        );
    }

    #[test]
    fn reports_missing_and_extra_outputs() {
        let mut sb = Scoreboard::new("toy", 1, [1]);
        assert!(sb.finish().unwrap_err().to_string().contains("1 expected outputs missing"));
        sb.check_all([(0, 1)]).unwrap();
        assert_eq!(sb.finish(), Ok(1));
        assert!(sb.check(3, 4).unwrap_err().to_string().contains("unexpected output #1 at cycle 3"));
    }
}
