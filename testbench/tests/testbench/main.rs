//! Integration tests of `shelling-testbench` on the toy blocks of `toy.rs`.
//!
//! `cargo test -p shelling-testbench`; the speed report:
//! `cargo test -p shelling-testbench --release -- --nocapture speed`.

mod driver;
mod replay;
mod speed;
mod streams;
mod toy;
mod vcd_stream;
