//! The cycle driver against a plain Rust model, and its error paths.

use shelling_testbench::{Driver, Pacing, Result};

use crate::toy::{random_vectors, run_pipeline, MulAddPipe, Ring, Undriven, PIPE_LATENCY};

#[test]
fn pipeline_matches_model_over_random_vectors() -> Result<()> {
    for (seed, pacing) in
        [(0x5eed_0001, Pacing::NONE), (0x5eed_0002, Pacing { idle: true, backpressure: false })]
    {
        let vectors = random_vectors(10_000, seed);
        let mut drv = Driver::new(MulAddPipe::default())?;
        let checked = run_pipeline(&mut drv, &vectors, pacing, seed)?;
        assert_eq!(checked, vectors.len());
        if pacing == Pacing::NONE {
            // Back to back: one result per cycle after the pipeline filled.
            assert_eq!(drv.cycles(), vectors.len() as u64 + PIPE_LATENCY - 1);
        }
    }
    Ok(())
}

/// Registers one, two and three levels below the top each capture their input as it was before
/// the edge (the driver forces the top clock, and rust-hdl-core is vendored to show an edge one
/// pass earlier: `vendor/README.md`), whatever the input pattern.
#[test]
fn registers_at_every_depth_capture_their_pre_edge_inputs() -> Result<()> {
    let mut drv = Driver::new(Ring::default())?;
    let (mut r1, mut r2, mut r3) = (0u16, 0u16, 0u16);
    for cycle in 0..200u64 {
        let step = (cycle * 7919 % 13) as u16;
        drv.cycle(|u| u.step.next = (step as u64).into())?;
        (r1, r2, r3) = (r3.wrapping_add(step), r1, r2);
        let u = drv.uut();
        let got = (u.q1.val().index() as u16, u.q2.val().index() as u16, u.q3.val().index() as u16);
        assert_eq!(got, (r1, r2, r3), "cycle {cycle} (step {step})");
    }
    Ok(())
}

#[test]
fn latency_is_six_cycles() -> Result<()> {
    let mut drv = Driver::new(MulAddPipe::default())?;
    drv.cycle(|u| u.valid_in.next = true)?;
    drv.cycle(|u| u.valid_in.next = false)?;
    let valid_after = (2..=8)
        .map(|_| drv.idle(1).map(|()| (drv.cycles(), drv.uut().valid_out.val())))
        .collect::<Result<Vec<_>>>()?;
    let cycles: Vec<u64> = valid_after.iter().filter(|(_, v)| *v).map(|(c, _)| *c).collect();
    assert_eq!(cycles, vec![PIPE_LATENCY]);
    Ok(())
}

#[test]
fn failed_rust_hdl_checks_are_errors() {
    let err = Driver::new(Undriven::default()).err().expect("an undriven output must be refused");
    assert!(err.message().contains("connectivity check failed"), "{err}");
}

#[test]
fn unsettled_design_is_an_error() -> Result<()> {
    let mut drv = Driver::new(MulAddPipe::default())?.with_settle_limit(1);
    let err = drv.cycle(|u| u.valid_in.next = true).expect_err("one pass cannot settle the pipeline");
    assert!(err.message().contains("did not settle within 1 update passes at cycle 0"), "{err}");
    Ok(())
}

#[test]
fn recording_must_start_at_power_up() -> Result<()> {
    let mut drv = Driver::new(MulAddPipe::default())?;
    drv.idle(1)?;
    assert!(drv.record_ports().is_err());
    assert!(drv.take_recording().is_none());
    Ok(())
}
