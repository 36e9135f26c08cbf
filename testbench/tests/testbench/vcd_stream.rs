//! VCD streaming with a cycle window.

use shelling_testbench::vcd_stream::CYCLE_PS;
use shelling_testbench::{waveform_path, Driver, Pacing, Result};

use crate::toy::{random_vectors, run_pipeline, MulAddPipe};

#[test]
fn vcd_window_is_written_and_only_the_window() -> Result<()> {
    let seed = 0x7ace;
    let path = waveform_path("testbench_pipeline_window");
    let mut drv = Driver::new(MulAddPipe::default())?;
    drv.stream_vcd(&path, 100..150)?;
    run_pipeline(&mut drv, &random_vectors(300, seed), Pacing { idle: true, backpressure: false }, seed)?;
    assert_eq!(drv.finish_vcd()?, Some(path.clone()));
    assert_eq!(drv.finish_vcd()?, None);

    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let times: Vec<u64> =
        text.lines().filter_map(|l| l.strip_prefix('#')).map(|t| t.parse().expect("timestamp")).collect();
    // Header with the hierarchy, then exactly cycles 100..150, before and after each edge.
    assert!(text.contains("$scope module uut $end") && text.contains("$scope module a1 $end"));
    assert!(text.contains("$dumpvars"));
    let expected: Vec<u64> = (100..150).flat_map(|c| [c * CYCLE_PS, c * CYCLE_PS + CYCLE_PS / 2]).collect();
    assert_eq!(times, expected);
    Ok(())
}

#[test]
fn vcd_of_a_whole_run() -> Result<()> {
    let path = waveform_path("testbench_pipeline_all");
    let mut drv = Driver::new(MulAddPipe::default())?;
    drv.stream_vcd(&path, ..)?;
    drv.idle(20)?;
    drv.finish_vcd()?;
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    assert_eq!(text.lines().filter(|l| l.starts_with('#')).count(), 40);
    Ok(())
}
