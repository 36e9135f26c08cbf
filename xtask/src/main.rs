//! Project automation for shelling, run as `cargo xtask <task>` (the alias is in
//! `.cargo/config.toml`). Nothing depends on this crate; it depends on `shelling-testbench` for the
//! Verilog export only.
//!
//! - `cargo xtask fpga --out DIR`: synthesizes every RTL block with Yosys and places and routes it
//!   with nextpnr for ECP5 and iCE40 (once per placement seed of `--seeds`), then writes
//!   `DIR/fpga.json` (every run), `DIR/fpga-seeds.json` (each block's minimum, median and
//!   maximum fmax over the seeds) and `DIR/fpga.md` (LUTs, flip-flops, DSP blocks, block RAMs
//!   and the post-route maximum clock frequency).

mod fpga;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

#[derive(Parser)]
#[command(name = "cargo xtask", bin_name = "cargo xtask", about = "Project automation for shelling")]
struct Cli {
    #[command(subcommand)]
    task: Task,
}

#[derive(Subcommand)]
enum Task {
    /// Resources and clock rate: synthesize each block and the whole processing element with
    /// Yosys, place and route them with nextpnr for ECP5 (LFE5U-85F) and iCE40 (UP5K or HX8K),
    /// once per placement seed, and write DIR/fpga.json, DIR/fpga-seeds.json and DIR/fpga.md.
    Fpga(fpga::FpgaArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.task {
        Task::Fpga(args) => fpga::run(&args),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}
