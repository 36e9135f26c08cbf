//! The synthesized netlist (Yosys' `-json` output): cells by type, and which flip-flops are the
//! wrapper's.

use super::wrapper::WRAPPER_NETS;
use anyhow::{Context, Result};
use serde::Deserialize;
use std::collections::{BTreeMap, HashSet};
use std::path::Path;

#[derive(Deserialize)]
struct Netlist {
    modules: BTreeMap<String, Module>,
}

#[derive(Deserialize)]
struct Module {
    #[serde(default)]
    cells: BTreeMap<String, Cell>,
    #[serde(default)]
    netnames: BTreeMap<String, NetName>,
}

#[derive(Deserialize)]
struct Cell {
    #[serde(rename = "type")]
    kind: String,
    #[serde(default)]
    connections: BTreeMap<String, Vec<Bit>>,
}

#[derive(Deserialize)]
struct NetName {
    bits: Vec<Bit>,
}

/// A signal bit: a net number, or a constant ("0", "1", "x", "z").
#[derive(Deserialize)]
#[serde(untagged)]
enum Bit {
    Net(u64),
    Const(#[allow(dead_code)] String),
}

impl Bit {
    fn net(&self) -> Option<u64> {
        match self {
            Bit::Net(n) => Some(*n),
            Bit::Const(_) => None,
        }
    }
}

/// Cell counts of a synthesized wrapper-plus-block.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct CellCounts {
    /// Every cell type and how many.
    pub by_type: BTreeMap<String, u64>,
    /// Flip-flops in the whole netlist.
    pub ffs: u64,
    /// Flip-flops of the wrapper (those whose output is a bit of a wrapper register).
    pub wrapper_ffs: u64,
}

/// Whether a cell type is a flip-flop (ECP5 `TRELLIS_FF`, iCE40 `SB_DFF*`).
pub fn is_ff(kind: &str) -> bool {
    kind == "TRELLIS_FF" || kind.starts_with("SB_DFF")
}

/// Counts the cells of module `top` in the Yosys JSON netlist at `path`.
pub fn count(path: &Path, top: &str) -> Result<CellCounts> {
    let bytes = std::fs::read(path).with_context(|| format!("reading {}", path.display()))?;
    count_json(&bytes, top).with_context(|| format!("reading the netlist {}", path.display()))
}

fn count_json(bytes: &[u8], top: &str) -> Result<CellCounts> {
    let netlist: Netlist = serde_json::from_slice(bytes)?;
    let module = netlist.modules.get(top).with_context(|| format!("no module {top}"))?;
    let wrapper_bits: HashSet<u64> = WRAPPER_NETS
        .iter()
        .filter_map(|n| module.netnames.get(*n))
        .flat_map(|n| n.bits.iter().filter_map(Bit::net))
        .collect();
    let mut counts = CellCounts::default();
    for cell in module.cells.values() {
        *counts.by_type.entry(cell.kind.clone()).or_default() += 1;
        if is_ff(&cell.kind) {
            counts.ffs += 1;
            let q = cell.connections.get("Q").and_then(|q| q.first()).and_then(Bit::net);
            if q.is_some_and(|q| wrapper_bits.contains(&q)) {
                counts.wrapper_ffs += 1;
            }
        }
    }
    Ok(counts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrapper_flip_flops_are_told_apart_by_their_output_net() {
        let json = br#"{"creator": "Yosys", "modules": {"t": {
            "attributes": {"top": "00000000000000000000000000000001"},
            "cells": {
              "a": {"type": "TRELLIS_FF", "connections": {"DI": [2], "Q": [3]}},
              "b": {"type": "TRELLIS_FF", "connections": {"DI": [3], "Q": [4]}},
              "c": {"type": "LUT4", "connections": {"A": [4], "B": ["0"], "Z": [5]}},
              "d": {"type": "TRELLIS_FF", "connections": {"DI": [5], "Q": [6]}}
            },
            "netnames": {
              "shelling_fpga_in": {"hide_name": 0, "bits": [3, 4]},
              "block.r": {"hide_name": 0, "bits": [6, "x"]}
            }}}}"#;
        let c = count_json(json, "t").unwrap();
        assert_eq!((c.ffs, c.wrapper_ffs), (3, 2));
        assert_eq!(c.by_type["LUT4"], 1);
        assert!(count_json(json, "u").is_err());
    }
}
