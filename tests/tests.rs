//! Tier 1 of the integration tests: the README's `cargo test --workspace`. Tier 2, the long
//! equivalence checks, is `tests/tier2/main.rs`.

mod cli;
mod cli3d;
mod cosim;
mod ff3d;
mod figures;
mod grid3d;
mod hardware;
mod limits;
mod radiosity;
mod radiosity3d;
mod replay;
mod scene3d;
mod scene_loader;
mod support;
mod tracers;
mod tracers3d;
mod workstream;
