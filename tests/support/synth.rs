//! Yosys' ECP5 synthesis of the committed Verilog, for the synthesizability tests of both tiers.

use std::path::PathBuf;
use std::process::Command;

/// The committed exported Verilog, `hdl/verilog/`.
pub fn verilog_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("hdl").join("verilog")
}

/// Runs Yosys' ECP5 synthesis on one exported block, as the FPGA flow does (`SHELLING_ECP5`
/// defined: the `BramOut` leaves are hand-instantiated `DP16KD`s); returns its statistics.
pub fn synth_ecp5(name: &str) -> String {
    synth_ecp5_script(name, "synth_ecp5", "tee -o /dev/stdout stat")
}

/// Yosys on one exported block with `synth` for the synthesis command and `then` after it;
/// returns Yosys' output (it fails the test if Yosys fails).
pub fn synth_ecp5_script(name: &str, synth: &str, then: &str) -> String {
    let file = verilog_dir().join(format!("{name}.v"));
    let out = Command::new("yosys")
        .args([
            "-q",
            "-p",
            &format!("read_verilog -DSHELLING_ECP5 {}; {synth} -top {name}; {then}", file.display()),
        ])
        .output()
        .expect("yosys is not installed: `apt-get install yosys` (.ci/run installs it)");
    let text = String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "yosys failed on {name}:\n{text}");
    text
}

/// The count of `cell` in Yosys' statistics `stat` (its last table: the top module's total).
pub fn cells(stat: &str, cell: &str) -> usize {
    stat.lines()
        .filter_map(|l| {
            let mut w = l.split_whitespace();
            (w.next() == Some(cell)).then(|| w.next().and_then(|n| n.parse().ok())).flatten()
        })
        .last()
        .unwrap_or(0)
}

/// Fails, naming `what`, if Yosys' output `stat` shows an inferred latch.
pub fn assert_no_latch(what: &str, stat: &str) {
    for latch in ["$_DLATCH", "$dlatch", "LATCH"] {
        assert!(!stat.contains(latch), "{what}: a latch was inferred:\n{stat}");
    }
}
