//! Rung 4: the exported Verilog of a block, under Icarus Verilog (and Verilator), reproduces the
//! recorded rust-hdl simulation; and the replay does catch a difference.

use std::path::PathBuf;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rust_hdl::prelude::*;
use shelling_testbench::{Driver, Pacing, PortDir, Recording, Result, Simulator};

use crate::streams::run_fifo;
use crate::toy::{random_vectors, run_pipeline, BusSum, Fifo, MulAddPipe, ScaledProduct};

/// A scratch directory for one replay, under Cargo's per-target temporary directory.
fn replay_dir(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join(name)
}

/// 2000 vectors through the pipeline with random idle cycles, recorded.
fn record_pipeline(seed: u64) -> Result<(Driver<MulAddPipe>, Recording)> {
    let mut drv = Driver::new(MulAddPipe::default())?;
    drv.record_ports()?;
    run_pipeline(&mut drv, &random_vectors(2000, seed), Pacing { idle: true, backpressure: false }, seed)?;
    let rec = drv.take_recording().ok_or("recording was on")?;
    Ok((drv, rec))
}

#[test]
fn ports_are_found_generically() -> Result<()> {
    let (_, rec) = record_pipeline(1)?;
    let ports: Vec<(&str, usize, PortDir)> =
        rec.ports().iter().map(|p| (p.name.as_str(), p.width, p.dir)).collect();
    assert_eq!(
        ports,
        [
            ("a", 32, PortDir::Input),
            ("b", 32, PortDir::Input),
            ("valid_in", 1, PortDir::Input),
            ("y", 32, PortDir::Output),
            ("valid_out", 1, PortDir::Output)
        ]
    );
    assert_eq!(rec.clock(), "clock");
    Ok(())
}

#[test]
fn interface_ports_are_named_as_in_the_verilog() -> Result<()> {
    let mut rng = ChaCha8Rng::seed_from_u64(0xb05);
    let mut drv = Driver::new(BusSum::default())?;
    drv.record_ports()?;
    for _ in 0..300 {
        let (data, write): (u8, bool) = (rng.random(), rng.random());
        drv.cycle(|u| {
            u.bus.data.next = bits(data.into());
            u.bus.write.next = write;
        })?;
    }
    let rec = drv.take_recording().ok_or("recording was on")?;
    let names: Vec<&str> = rec.ports().iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["bus$data", "bus$write", "bus$full", "bus$almost_full", "sum"]);
    rec.replay(drv.uut(), &replay_dir("bus_sum"), Simulator::Icarus)?;
    Ok(())
}

#[test]
fn pipeline_replays_bit_exactly_under_icarus() -> Result<()> {
    let (drv, rec) = record_pipeline(0x4e91)?;
    let report = rec.replay(drv.uut(), &replay_dir("pipeline"), Simulator::Icarus)?;
    println!("{report}");
    assert_eq!(report.cycles, rec.cycles());
    // Two outputs, compared before and after every rising edge.
    assert_eq!(report.checks, 4 * rec.cycles());
    Ok(())
}

#[test]
fn tampered_expectation_is_caught() -> Result<()> {
    let (drv, mut rec) = record_pipeline(0x4e92)?;
    rec.flip_expected_bit(100, "y", 3)?;
    let err = rec
        .replay(drv.uut(), &replay_dir("pipeline_tampered"), Simulator::Icarus)
        .expect_err("a flipped bit");
    let msg = err.message();
    assert!(msg.contains("1 of") && msg.contains("MISMATCH cycle=100 port=y phase=after"), "{msg}");
    assert!(rec.flip_expected_bit(rec.cycles(), "y", 0).is_err());
    assert!(rec.flip_expected_bit(0, "a", 0).is_err(), "inputs carry no expectation");
    Ok(())
}

#[test]
fn codegen_width_bug_is_caught() -> Result<()> {
    // `rust-hdl-notes.md` §1: `bit_cast::<16, 32>((a * b) >> 8)` is evaluated at 16 bits in Verilog.
    let mut rng = ChaCha8Rng::seed_from_u64(0xb06);
    let mut drv = Driver::new(ScaledProduct::default())?;
    drv.record_ports()?;
    for _ in 0..500 {
        let (a, b): (u16, u16) = (rng.random(), rng.random());
        drv.cycle(|u| {
            u.a.next = bits(a.into());
            u.b.next = bits(b.into());
        })?;
    }
    let rec = drv.take_recording().ok_or("recording was on")?;
    let err = rec.replay(drv.uut(), &replay_dir("scaled_product"), Simulator::Icarus).expect_err("known bug");
    println!("{err}");
    assert!(err.message().contains("port=y"), "{err}");
    Ok(())
}

#[test]
fn fifo_replays_with_dont_care_data_while_empty() -> Result<()> {
    let seed = 0xf1f0;
    let items: Vec<u16> = (0..600u16).map(|i| i.wrapping_mul(2654)).collect();
    let mut drv = Driver::new(Fifo::default())?;
    drv.record_ports()?;
    run_fifo(&mut drv, &items, Pacing { idle: true, backpressure: true }, seed)?;
    let mut rec = drv.take_recording().ok_or("recording was on")?;
    // The Verilog RAM powers up as x, rust-hdl's as 0: `data_out` means nothing while empty.
    let excluded = rec.dont_care_when("data_out", "empty", 1)?;
    assert!(excluded > 0);
    let report = rec.replay(drv.uut(), &replay_dir("fifo"), Simulator::Icarus)?;
    println!("{report}");
    Ok(())
}

#[test]
fn pipeline_replays_bit_exactly_under_verilator() -> Result<()> {
    let (drv, rec) = record_pipeline(0x4e93)?;
    let report = rec.replay(drv.uut(), &replay_dir("pipeline_verilator"), Simulator::Verilator)?;
    println!("{report}");
    assert_eq!(report.checks, 4 * rec.cycles());
    Ok(())
}
