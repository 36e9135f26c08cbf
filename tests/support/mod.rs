//! Helpers shared by the test binaries of tier 1 (`tests/tests.rs`) and tier 2
//! (`tests/tier2/main.rs`).

pub mod closed3d;
pub mod replay;
pub mod synth;
pub mod tracers3d;
