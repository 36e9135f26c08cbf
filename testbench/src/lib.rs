//! Testbench infrastructure for the shelling RTL: a cycle driver that steps blocks from a plain
//! loop, VCD streaming into `waveforms/`, stream drivers and monitors with random idle and
//! backpressure, and scoreboards against the bit-true models.
//!
//! Status: empty until the RTL blocks of `shelling-hdl` exist (the RTL datapath issue).
