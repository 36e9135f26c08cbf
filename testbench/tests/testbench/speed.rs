//! Cycles per second of the driver on the 6-stage pipeline (printed, never asserted):
//! `cargo test -p shelling-testbench --release -- --nocapture speed`.

use std::time::Instant;

use rust_hdl::prelude::*;
use shelling_testbench::{waveform_path, Driver, Result};

use crate::toy::MulAddPipe;

/// Runs `n` back-to-back cycles with cheap pseudo-random operands; returns cycles per second.
fn cycles_per_second(drv: &mut Driver<MulAddPipe>, n: u64) -> Result<f64> {
    let mut x = 0x1234_5678_u64;
    let start = Instant::now();
    for _ in 0..n {
        x = x.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        drv.cycle(|u| {
            u.a.next = bits(x >> 32);
            u.b.next = bits(x & 0xffff_ffff);
            u.valid_in.next = true;
        })?;
    }
    Ok(n as f64 / start.elapsed().as_secs_f64())
}

#[test]
fn speed() -> Result<()> {
    let n = if cfg!(debug_assertions) { 20_000 } else { 1_000_000 };
    let mut plain = Driver::new(MulAddPipe::default())?;
    let bare = cycles_per_second(&mut plain, n)?;

    let mut traced = Driver::new(MulAddPipe::default())?;
    traced.stream_vcd(waveform_path("testbench_speed"), ..)?;
    let vcd = cycles_per_second(&mut traced, n / 100)?;
    traced.finish_vcd()?;

    let mut recorded = Driver::new(MulAddPipe::default())?;
    recorded.record_ports()?;
    let rec = cycles_per_second(&mut recorded, n / 10)?;

    let profile = if cfg!(debug_assertions) { "debug" } else { "release" };
    println!("driver speed ({profile}, 6-stage 32-bit pipeline): {bare:.0} cycles/s plain, {vcd:.0} with VCD, {rec:.0} recording ports");
    Ok(())
}
