//! The paper's counters (Figures 8–11 and 13). The field names are fixed: the CLI's JSON and the
//! figures' CSV use them as they are.

use serde::{Deserialize, Serialize};
use std::ops::AddAssign;

/// Work counted by a tracer for one bundle (or summed over several).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Counters {
    /// Candidate patches found by cell traversal and loaded (Figure 8).
    pub patches_read_before_screening: u64,
    /// Loaded patches that passed the screener: backward, back-facing and, for the shelling
    /// techniques, outside the sector's angular range (Figure 9).
    pub patches_read_after_screening: u64,
    /// Cells visited; a macro-region jump counts once (Figure 10).
    pub cells_traversed: u64,
    /// Ray–patch intersection tests performed (Figure 11).
    pub intersection_computations: u64,
    /// Rays that hit something: the least number of tests any technique can do (Figure 11).
    pub actual_intersections: u64,
    /// Def 2.10 over the nearest hits (Figure 13).
    pub adlc_true: f64,
    /// What the tracking mechanism estimated; equal to `adlc_true` where a technique has none.
    pub adlc_estimated: f64,
}

impl Counters {
    /// The counter names, in CSV column order.
    pub const NAMES: [&'static str; 7] = [
        "patches_read_before_screening",
        "patches_read_after_screening",
        "cells_traversed",
        "intersection_computations",
        "actual_intersections",
        "adlc_true",
        "adlc_estimated",
    ];

    /// The counters as numbers, in [`Counters::NAMES`] order.
    pub fn values(&self) -> [f64; 7] {
        [
            self.patches_read_before_screening as f64,
            self.patches_read_after_screening as f64,
            self.cells_traversed as f64,
            self.intersection_computations as f64,
            self.actual_intersections as f64,
            self.adlc_true,
            self.adlc_estimated,
        ]
    }
}

impl AddAssign for Counters {
    /// Sums the work counters; the ADLC fields are summed too (divide for a mean).
    fn add_assign(&mut self, o: Counters) {
        self.patches_read_before_screening += o.patches_read_before_screening;
        self.patches_read_after_screening += o.patches_read_after_screening;
        self.cells_traversed += o.cells_traversed;
        self.intersection_computations += o.intersection_computations;
        self.actual_intersections += o.actual_intersections;
        self.adlc_true += o.adlc_true;
        self.adlc_estimated += o.adlc_estimated;
    }
}
