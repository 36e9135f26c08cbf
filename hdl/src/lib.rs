//! RTL of the shelling processing element, in rust-hdl: the patch loader FIFO, the per-PE patch
//! cache, the backface screener and the pipelined ray/segment intersection unit, each block
//! beside its bit-true model, with Verilog export. Number formats: `FORMATS.md` and [`formats`].
//!
//! This crate knows nothing of scenes: its inputs are integers in the formats of [`formats`].

pub mod cache;
pub mod formats;
pub mod intersection;
pub mod leaf;
pub mod loader;
pub mod pe;
pub mod screener;
pub mod slice;
