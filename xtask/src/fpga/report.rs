//! What nextpnr reports: its JSON report (`--report`: per-clock fmax, utilization, critical
//! paths) and, for a design that does not fit (no report is written then), the utilisation table
//! of its log.

use anyhow::{Context, Result};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// nextpnr's `--report` JSON.
#[derive(Deserialize, Debug, Default)]
pub struct Report {
    #[serde(default)]
    pub fmax: BTreeMap<String, ClockFmax>,
    #[serde(default)]
    pub utilization: BTreeMap<String, Use>,
    #[serde(default)]
    pub critical_paths: Vec<CriticalPath>,
}

/// Achieved and constrained frequency of one clock, in MHz.
#[derive(Deserialize, Debug, Clone, Copy, PartialEq)]
pub struct ClockFmax {
    pub achieved: f64,
    pub constraint: f64,
}

/// Used and available bels of one type.
#[derive(Deserialize, Debug, Clone, Copy, PartialEq, Eq)]
pub struct Use {
    pub used: u64,
    pub available: u64,
}

#[derive(Deserialize, Debug)]
pub struct CriticalPath {
    pub from: String,
    pub to: String,
    #[serde(default)]
    pub path: Vec<Segment>,
}

#[derive(Deserialize, Debug)]
pub struct Segment {
    pub delay: f64,
    #[serde(rename = "type")]
    pub kind: String,
    pub from: Endpoint,
    pub to: Endpoint,
    #[serde(default)]
    pub net: Option<String>,
}

#[derive(Deserialize, Debug)]
pub struct Endpoint {
    pub cell: String,
    pub port: String,
}

/// The worst register-to-register path of a clock, as `fpga.json` records it.
#[derive(Serialize, Deserialize, Debug, Clone, PartialEq)]
pub struct PathSummary {
    /// Clock edges, as nextpnr names them (`posedge clock` ...).
    pub clock: String,
    /// Total delay in ns: clock-to-out, logic and routing.
    pub delay_ns: f64,
    /// The launching cell (a flip-flop, a block RAM or a DSP) and its port.
    pub from: String,
    /// The capturing cell and its port.
    pub to: String,
    /// Cells passed through (LUTs, carry cells...).
    pub logic_levels: usize,
    /// Nets in order; their names are the Verilog signals they come from.
    pub nets: Vec<String>,
}

impl Report {
    pub fn parse(text: &str) -> Result<Report> {
        serde_json::from_str(text).context("parsing the nextpnr report")
    }

    /// The lowest achieved fmax over the design's clocks; `None` without a clocked path.
    pub fn fmax_mhz(&self) -> Option<f64> {
        self.fmax.values().map(|c| c.achieved).reduce(f64::min)
    }

    /// The worst register-to-register path (same clock at both ends, not a port path).
    pub fn critical_path(&self) -> Option<PathSummary> {
        self.critical_paths
            .iter()
            .filter(|p| p.from == p.to && !p.from.contains("<async>") && !p.path.is_empty())
            .map(|p| PathSummary {
                clock: p.from.clone(),
                delay_ns: round(p.path.iter().map(|s| s.delay).sum(), 3),
                from: format!("{}.{}", p.path[0].from.cell, p.path[0].from.port),
                to: p.path.last().map(|s| format!("{}.{}", s.to.cell, s.to.port)).unwrap_or_default(),
                logic_levels: p.path.iter().filter(|s| s.kind == "logic").count(),
                nets: p.path.iter().filter_map(|s| s.net.clone()).collect(),
            })
            .max_by(|a, b| a.delay_ns.total_cmp(&b.delay_ns))
    }
}

/// The first "Device utilisation" table of a nextpnr log (after packing, before placement): bel
/// type to used and available. nextpnr prints it also when the design does not fit.
pub fn log_utilisation(log: &str) -> BTreeMap<String, Use> {
    let mut table = BTreeMap::new();
    let mut lines = log.lines().skip_while(|l| !l.contains("Device utilisation:")).skip(1);
    for line in lines.by_ref() {
        let body = line.trim_start_matches("Info:").trim();
        let Some((name, counts)) = body.split_once(':') else { break };
        let Some((used, rest)) = counts.split_once('/') else { break };
        let available = rest.split_whitespace().next().unwrap_or_default();
        match (used.trim().parse(), available.parse()) {
            (Ok(used), Ok(available)) => {
                table.insert(name.trim().to_string(), Use { used, available });
            }
            _ => break,
        }
    }
    table
}

/// Bel types used beyond what the device has, as `TYPE used/available`.
pub fn over_capacity(table: &BTreeMap<String, Use>) -> Vec<String> {
    table
        .iter()
        .filter(|(_, u)| u.used > u.available)
        .map(|(name, u)| format!("{name} {}/{}", u.used, u.available))
        .collect()
}

pub fn round(x: f64, digits: i32) -> f64 {
    let scale = 10f64.powi(digits);
    (x * scale).round() / scale
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The report nextpnr-ecp5 0.11 (YoWASP) wrote for the patch loader in its wrapper, seed 1.
    const ECP5_REPORT: &str = include_str!("testdata/nextpnr-ecp5-report.json");
    /// The same from Debian's nextpnr-ice40 0.4, for the UP5K.
    const ICE40_REPORT: &str = include_str!("testdata/nextpnr-ice40-report.json");
    /// The head, the utilisation table and the error of the nextpnr-ice40 log for the whole PE on
    /// the UP5K, which does not fit.
    const ICE40_LOG: &str = include_str!("testdata/nextpnr-ice40-nofit.log");

    #[test]
    fn ecp5_report_gives_fmax_utilization_and_the_critical_path() {
        let r = Report::parse(ECP5_REPORT).unwrap();
        let fmax = r.fmax_mhz().unwrap();
        assert!((fmax - 232.126).abs() < 0.01, "{fmax}");
        assert_eq!(r.utilization["TRELLIS_COMB"], Use { used: 259, available: 83640 });
        assert_eq!(r.utilization["TRELLIS_FF"].used, 513);
        assert_eq!(r.utilization["TRELLIS_RAMW"].used, 24);
        assert_eq!(r.utilization["MULT18X18D"], Use { used: 0, available: 156 });
        let p = r.critical_path().unwrap();
        assert_eq!(p.clock, "posedge $glbnet$clock$TRELLIS_IO_IN");
        assert_eq!(p.from, "sout_TRELLIS_FF_Q.Q", "the wrapper's last input stage (out_ready)");
        assert!((p.delay_ns - 1000.0 / fmax).abs() < 0.01, "the path sets the fmax: {p:?}");
        assert!(p.logic_levels > 0 && !p.nets.is_empty(), "{p:?}");
    }

    #[test]
    fn ice40_report_parses_too() {
        let r = Report::parse(ICE40_REPORT).unwrap();
        assert!((r.fmax_mhz().unwrap() - 65.28).abs() < 0.01);
        assert_eq!(r.utilization["ICESTORM_LC"], Use { used: 745, available: 5280 });
        assert_eq!(r.utilization["ICESTORM_RAM"].used, 9);
        assert!(r.critical_path().is_some());
    }

    #[test]
    fn utilisation_of_a_design_that_does_not_fit_comes_from_the_log() {
        let t = log_utilisation(ICE40_LOG);
        assert_eq!(t["ICESTORM_LC"], Use { used: 9610, available: 5280 });
        assert_eq!(t["ICESTORM_DSP"], Use { used: 48, available: 8 });
        assert_eq!(t["ICESTORM_SPRAM"], Use { used: 0, available: 4 });
        assert_eq!(t.len(), 15);
        assert_eq!(over_capacity(&t), ["ICESTORM_DSP 48/8", "ICESTORM_LC 9610/5280", "ICESTORM_RAM 135/30"]);
        assert!(log_utilisation("no table").is_empty());
    }

    #[test]
    fn a_report_that_is_not_nextpnr_json_is_an_error() {
        assert!(Report::parse("{\"fmax\": 3}").is_err());
        assert!(Report::parse("{}").unwrap().fmax_mhz().is_none());
    }
}
