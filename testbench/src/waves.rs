//! Reading a VCD back: the values of chosen signals at every cycle, for protocol checks on a
//! waveform a run has written ([`Driver::stream_vcd`](crate::Driver::stream_vcd)).
//!
//! [`Waves::read`] keeps only the signals asked for, by hierarchical path (`uut.loader.reserved.q`),
//! and samples them at the settled pre-edge state of each cycle (time `c * CYCLE_PS`, where a
//! valid/ready handshake is decided), which the VCD writer dumps once per cycle.

use crate::vcd_stream::CYCLE_PS;
use crate::{Error, Result};
use std::collections::HashMap;
use std::fs::File;
use std::io::BufReader;
use std::path::Path;
use vcd::{Command, IdCode, Parser, Value};

/// Sampled values of some signals, one per cycle of the file's window.
#[derive(Clone, Debug)]
pub struct Waves {
    /// The first cycle sampled.
    pub first_cycle: u64,
    signals: HashMap<String, Vec<u64>>,
}

fn to_u64(bits: &[Value]) -> Option<u64> {
    bits.iter().try_fold(0u64, |acc, v| match v {
        Value::V0 => Some(acc << 1),
        Value::V1 => Some((acc << 1) | 1),
        _ => None,
    })
}

impl Waves {
    /// Reads `path` and samples `signals` (hierarchical paths, dot-separated) at every cycle's
    /// pre-edge time. A signal missing from the file, or wider than 64 bits, or holding X or Z
    /// when sampled, is an error that names it.
    pub fn read(path: &Path, signals: &[&str]) -> Result<Waves> {
        let io = |e: std::io::Error| Error::new(format!("reading {}: {e}", path.display()));
        let file = File::open(path).map_err(io)?;
        let mut parser = Parser::new(BufReader::new(file));
        let header = parser.parse_header().map_err(io)?;
        let mut codes: HashMap<IdCode, Vec<usize>> = HashMap::new();
        for (k, name) in signals.iter().enumerate() {
            let parts: Vec<&str> = name.split('.').collect();
            let var = header
                .find_var(&parts)
                .ok_or_else(|| Error::new(format!("{}: no signal `{name}`", path.display())))?;
            if var.size > 64 {
                return Err(Error::new(format!("`{name}` is {} bits wide (at most 64)", var.size)));
            }
            codes.entry(var.code).or_default().push(k);
        }
        let mut current: Vec<Option<u64>> = vec![None; signals.len()];
        let mut samples: Vec<Vec<u64>> = vec![Vec::new(); signals.len()];
        let mut first_cycle: Option<u64> = None;
        let mut time = 0u64;
        for cmd in parser.by_ref() {
            match cmd.map_err(io)? {
                Command::Timestamp(t) => {
                    // The cycles whose pre-edge time lies in [time, t) see the current values.
                    let mut c = time.div_ceil(CYCLE_PS);
                    while c * CYCLE_PS < t {
                        if current.iter().all(Option::is_some) {
                            first_cycle.get_or_insert(c);
                            for (k, v) in current.iter().enumerate() {
                                samples[k].push(v.unwrap_or_default());
                            }
                        } else if first_cycle.is_some() {
                            let k = current.iter().position(Option::is_none).unwrap_or_default();
                            return Err(Error::new(format!(
                                "`{}` is unknown (X or Z) at cycle {c}",
                                signals[k]
                            )));
                        }
                        c += 1;
                    }
                    time = t;
                }
                Command::ChangeScalar(code, v) => {
                    for &k in codes.get(&code).into_iter().flatten() {
                        current[k] = to_u64(&[v]);
                    }
                }
                Command::ChangeVector(code, bits) => {
                    for &k in codes.get(&code).into_iter().flatten() {
                        current[k] = to_u64(&bits);
                    }
                }
                _ => {}
            }
        }
        let signals = signals.iter().map(|s| s.to_string()).zip(samples).collect();
        Ok(Waves { first_cycle: first_cycle.unwrap_or(0), signals })
    }

    /// Cycles sampled.
    pub fn cycles(&self) -> usize {
        self.signals.values().next().map_or(0, Vec::len)
    }

    /// The samples of `signal`, one per cycle from [`Waves::first_cycle`].
    pub fn get(&self, signal: &str) -> Result<&[u64]> {
        self.signals
            .get(signal)
            .map(Vec::as_slice)
            .ok_or_else(|| Error::new(format!("`{signal}` was not read")))
    }
}

/// The signals a GTKWave save file (`.gtkw`) shows: its lines that are not directives (`[..]`),
/// flags (`@..`), group and comment markers (`-..`, `*..`).
pub fn gtkw_signals(path: &Path) -> Result<Vec<String>> {
    let text =
        std::fs::read_to_string(path).map_err(|e| Error::new(format!("reading {}: {e}", path.display())))?;
    Ok(text
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with(['[', '@', '-', '*']))
        .map(String::from)
        .collect())
}
