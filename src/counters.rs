//! The paper's counters (Figures 8–11 and 13). The field names are fixed: the CLI's JSON and the
//! figures' CSV use them as they are.
//!
//! The counters are declared once, in the `counters!` invocation below: the struct, its
//! [`Counters::NAMES`], [`Counters::LABELS`], [`Counters::values`], [`Counters::mean`] and the
//! sum all come from that one list, in its order (the order of the JSON fields and the CSV
//! columns).

use serde::{Deserialize, Serialize};
use std::ops::AddAssign;

/// The kind of one counter's value: a count of work (`u64`) or an ADLC (`f64`).
pub trait CounterValue: Copy + AddAssign {
    /// Whether the value is a whole count (printed without decimals).
    const INTEGRAL: bool;
    /// The value as a number.
    fn to_f64(self) -> f64;
    /// The per-source mean of a total over `n` sources: counts are rounded to whole counts.
    fn mean_of(self, n: f64) -> Self;
}

impl CounterValue for u64 {
    const INTEGRAL: bool = true;
    fn to_f64(self) -> f64 {
        self as f64
    }
    fn mean_of(self, n: f64) -> u64 {
        (self as f64 / n).round() as u64
    }
}

impl CounterValue for f64 {
    const INTEGRAL: bool = false;
    fn to_f64(self) -> f64 {
        self
    }
    fn mean_of(self, n: f64) -> f64 {
        self / n
    }
}

/// Declares [`Counters`] from one list of `label, field: type` entries (doc comments kept).
macro_rules! counters {
    ($($(#[doc = $doc:literal])* $label:literal, $field:ident: $ty:ty;)*) => {
        /// Work counted by a tracer for one bundle (or summed over several).
        #[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
        pub struct Counters {
            $($(#[doc = $doc])* pub $field: $ty,)*
        }

        impl Counters {
            /// The number of counters.
            pub const COUNT: usize = [$(stringify!($field)),*].len();

            /// The counter names, in CSV column order (the JSON field names).
            pub const NAMES: [&'static str; Self::COUNT] = [$(stringify!($field)),*];

            /// Short labels for tables, in [`Counters::NAMES`] order.
            pub const LABELS: [&'static str; Self::COUNT] = [$($label),*];

            /// Whether each counter is a whole count, in [`Counters::NAMES`] order.
            pub const INTEGRAL: [bool; Self::COUNT] = [$(<$ty as CounterValue>::INTEGRAL),*];

            /// The counters as numbers, in [`Counters::NAMES`] order.
            pub fn values(&self) -> [f64; Self::COUNT] {
                [$(self.$field.to_f64()),*]
            }

            /// The exact per-source means of these totals over `sources` sources (at least
            /// one), in [`Counters::NAMES`] order.
            pub fn exact_means(&self, sources: usize) -> [f64; Self::COUNT] {
                let n = sources.max(1) as f64;
                self.values().map(|v| v / n)
            }

            /// The exact per-source mean of the total named `name` (one of
            /// [`Counters::NAMES`]) over `sources` sources.
            pub fn exact_mean_of(&self, sources: usize, name: &str) -> Option<f64> {
                let i = Self::NAMES.iter().position(|n| *n == name)?;
                Some(self.exact_means(sources)[i])
            }

            /// The per-source mean of these totals over `n` sources: the work counts rounded to
            /// whole counts, the ADLC fields divided.
            pub fn mean(&self, n: f64) -> Counters {
                Counters { $($field: self.$field.mean_of(n)),* }
            }
        }

        impl AddAssign for Counters {
            /// Sums the work counters; the ADLC fields are summed too (divide for a mean).
            fn add_assign(&mut self, o: Counters) {
                $(self.$field += o.$field;)*
            }
        }
    };
}

counters! {
    /// Candidate patches found by cell traversal and loaded (Figure 8).
    "read before", patches_read_before_screening: u64;
    /// Loaded patches that passed the screener: backward, back-facing and, for the shelling
    /// techniques, outside the sector's angular range (Figure 9).
    "read after", patches_read_after_screening: u64;
    /// Cells visited; a macro-region jump counts once (Figure 10).
    "cells", cells_traversed: u64;
    /// Ray–patch intersection tests performed (Figure 11).
    "tests", intersection_computations: u64;
    /// Rays that hit something: the least number of tests any technique can do (Figure 11).
    "actual", actual_intersections: u64;
    /// Def 2.10 over the nearest hits (Figure 13).
    "ADLC", adlc_true: f64;
    /// What the tracking mechanism estimated; equal to `adlc_true` where a technique has none.
    "ADLC est.", adlc_estimated: f64;
}

#[cfg(test)]
mod tests {
    use super::Counters;

    #[test]
    fn names_follow_the_json_fields() {
        let json = serde_json::to_value(Counters::default()).unwrap();
        let keys: Vec<&str> = json.as_object().unwrap().keys().map(String::as_str).collect();
        let mut names = Counters::NAMES.to_vec();
        names.sort_unstable();
        let mut keys = keys;
        keys.sort_unstable();
        assert_eq!(keys, names);
        assert_eq!(Counters::INTEGRAL, [true, true, true, true, true, false, false]);
    }
}
