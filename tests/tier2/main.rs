//! Tier 2 of the tests (`cargo test --release --workspace --features tier2 --test tier2`): the long
//! equivalence checks, which tier 1 (`tests/tests.rs`) represents with short vectors.

// Each tier uses its own part of the shared helpers.
#[allow(dead_code)]
#[path = "../support/mod.rs"]
mod support;

mod ff3d;
mod figures;
mod hardware;
mod machine;
mod radiosity;
mod replay;
mod stalls;
mod tracers3d;
