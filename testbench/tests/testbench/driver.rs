//! The cycle driver against a plain Rust model, and its error paths.

use shelling_testbench::{Driver, Pacing, Result};

use crate::toy::{random_vectors, run_pipeline, MulAddPipe, Undriven, PIPE_LATENCY};

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
