//! RTL of the shelling processing element, in rust-hdl: the patch loader FIFO, the backface
//! screener and the pipelined ray/segment intersection unit, each block beside its bit-true
//! model, with Verilog export.
//!
//! Status: empty. The blocks are the next piece of work (the RTL datapath issue); this crate
//! exists now so that the workspace has its final shape and the dependency rule
//! `hdl ← testbench ← shelling` holds from the start. It deliberately depends on nothing.
