//! The machine's floorplan on the LFE5U-85F: each PE's block RAMs and multipliers pinned to the
//! hard sites of its own region of the die.
//!
//! Unpinned, nextpnr spreads a PE of the machine over half the die, and the machine's critical
//! paths are wires across it (a PE's tag FIFO in one corner driving its slice's clock enable in
//! another); the post-route clock rate then varies by 15 MHz from seed to seed on one netlist.
//! Here the die is cut into two rows of regions, `ceil(N/2)` in the upper row and `floor(N/2)`
//! in the lower, each row's regions of equal width (N = 1: the whole die), or, where a region of
//! those has too few sites of a kind for its PE, into N columns by one row. (The multipliers lie
//! in three rows of the die, two of them in its upper half. Seven PEs' three lower regions hold
//! 16–18 multiplier sites each for a PE's 16, where four regions as narrow as the upper row's
//! held 13; seven columns, each the die's height, stretched a PE's loops along 35 rows and
//! routed far below 150 MHz.) PE `k` gets the `k`-th region, the upper row's left to right
//! first, and each of its `DP16KD` and `MULT18X18D` cells (named `…pes$k.…` in the flattened
//! Yosys netlist) is given a `BEL` attribute: of the sites of its kind in its region, the PE's
//! cells take those nearest the region's centre, the cells in name order along the sites in row
//! order (so that one sub-block's RAMs sit side by side, not at both ends of the region).
//! nextpnr places those cells there (a wrong site is an error, not ignored) and pulls the PE's
//! logic around them. Only the netlist handed to nextpnr is changed; Yosys' own netlist stays as
//! it wrote it.

use anyhow::{bail, Context, Result};
use serde_json::Value;
use std::collections::{BTreeMap, HashSet};
use std::path::Path;

/// Every DP16KD and MULT18X18D site of the LFE5U-85F (see the file's header).
const SITES: &str = include_str!("ecp5_85f_hard_sites.txt");

/// The die's extent that the regions divide, in nextpnr's tile coordinates (the LFE5U-85F's
/// logic columns 2-121, rows 2-93).
const DIE: Region = Region { x0: 2.0, x1: 122.0, y0: 2.0, y1: 94.0 };

/// A kind of hard cell the floorplan pins.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Kind {
    /// `DP16KD` block RAM, at sites `EBRn`.
    Bram,
    /// `MULT18X18D`, at sites `MULT18_n`.
    Mult,
}

impl Kind {
    fn of_cell(cell_type: &str) -> Option<Kind> {
        match cell_type {
            "DP16KD" => Some(Kind::Bram),
            "MULT18X18D" => Some(Kind::Mult),
            _ => None,
        }
    }

    fn cell_type(self) -> &'static str {
        match self {
            Kind::Bram => "DP16KD",
            Kind::Mult => "MULT18X18D",
        }
    }
}

/// A hard site: its nextpnr name and tile.
#[derive(Clone, Debug)]
struct Site {
    name: String,
    x: u32,
    y: u32,
    kind: Kind,
}

fn sites() -> Vec<Site> {
    SITES
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(|l| {
            let mut f = l.split('/');
            let (x, y, bel) = (f.next(), f.next(), f.next());
            let num = |s: Option<&str>, p: char| s.and_then(|s| s.strip_prefix(p)?.parse().ok());
            let kind = match bel {
                Some(b) if b.starts_with("EBR") => Kind::Bram,
                Some(b) if b.starts_with("MULT18") => Kind::Mult,
                _ => panic!("the site list has a line {l:?} that is not a DP16KD or MULT18X18D site"),
            };
            Site {
                name: l.to_string(),
                x: num(x, 'X').expect("a site's column"),
                y: num(y, 'Y').expect("a site's row"),
                kind,
            }
        })
        .collect()
}

/// A rectangle of the die, `[x0, x1) x [y0, y1)` in tiles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Region {
    pub x0: f64,
    pub x1: f64,
    pub y0: f64,
    pub y1: f64,
}

impl Region {
    fn contains(&self, s: &Site) -> bool {
        (self.x0..self.x1).contains(&f64::from(s.x)) && (self.y0..self.y1).contains(&f64::from(s.y))
    }

    fn distance2(&self, s: &Site) -> f64 {
        let (cx, cy) = ((self.x0 + self.x1) / 2.0, (self.y0 + self.y1) / 2.0);
        (f64::from(s.x) - cx).powi(2) + (f64::from(s.y) - cy).powi(2)
    }
}

/// Rows of regions over the die: the regions in each row, top row first (each row's regions of
/// equal width, the rows of equal height).
pub type Grid = Vec<usize>;

/// The grids tried for `pes` regions, in order: two rows, then one (see the file's header).
pub fn grids(pes: usize) -> Vec<Grid> {
    if pes <= 1 {
        vec![vec![1]]
    } else {
        vec![vec![pes.div_ceil(2), pes / 2], vec![pes]]
    }
}

/// PE `k`'s region in the grid `g` (the `k`-th, row by row).
pub fn region(k: usize, g: &[usize]) -> Region {
    let (mut r, mut c) = (0, k);
    while r + 1 < g.len() && c >= g[r] {
        c -= g[r];
        r += 1;
    }
    let (w, h) = ((DIE.x1 - DIE.x0) / g[r] as f64, (DIE.y1 - DIE.y0) / g.len() as f64);
    Region {
        x0: DIE.x0 + c as f64 * w,
        x1: DIE.x0 + (c + 1) as f64 * w,
        y0: DIE.y0 + r as f64 * h,
        y1: DIE.y0 + (r + 1) as f64 * h,
    }
}

/// The grid in words: `3 x 2 grid` where its rows are alike, else `4 and 3 regions in 2 rows`.
fn grid_name(g: &[usize]) -> String {
    if g.iter().all(|&n| n == g[0]) {
        format!("{} x {} grid", g[0], g.len())
    } else {
        let counts: Vec<String> = g.iter().map(usize::to_string).collect();
        format!("{} regions in {} rows", counts.join(" and "), g.len())
    }
}

/// The PE a cell of the flattened netlist belongs to: `k` of the first `pes$k.` in its name.
fn pe_of(cell: &str) -> Option<usize> {
    let (_, rest) = cell.split_once("pes$")?;
    let (k, _) = rest.split_once('.')?;
    k.parse().ok()
}

/// The sites of every PE's hard cells: `cells` are the netlist's (name, type); the result is the
/// first of [`grids`] in which every PE's region holds its cells, and the map of each pinned cell
/// to its site. Cells outside every PE are left to the placer. If no grid holds them, the first
/// grid's shortfall is the error.
pub fn assign(cells: &[(String, String)], pes: usize) -> Result<(Grid, BTreeMap<String, String>)> {
    let mut first_error = None;
    for g in grids(pes) {
        match assign_in(cells, pes, &g) {
            Ok(pins) => return Ok((g, pins)),
            Err(e) if first_error.is_none() => first_error = Some(e),
            Err(_) => {}
        }
    }
    Err(first_error.expect("at least one grid is tried"))
}

/// [`assign`] in the grid `g`.
fn assign_in(cells: &[(String, String)], pes: usize, g: &[usize]) -> Result<BTreeMap<String, String>> {
    let all = sites();
    let mut need: BTreeMap<(usize, Kind), Vec<&str>> = BTreeMap::new();
    for (name, ty) in cells {
        if let (Some(kind), Some(k)) = (Kind::of_cell(ty), pe_of(name)) {
            if k >= pes {
                bail!("the netlist has a cell {name} of PE {k}, but the machine has {pes} PEs");
            }
            need.entry((k, kind)).or_default().push(name);
        }
    }
    let mut used: HashSet<&str> = HashSet::new();
    let mut out = BTreeMap::new();
    for ((k, kind), mut mine) in need {
        mine.sort_unstable();
        let r = region(k, g);
        let mut free: Vec<&Site> = all
            .iter()
            .filter(|s| s.kind == kind && r.contains(s) && !used.contains(s.name.as_str()))
            .collect();
        // Nearest the centre first; ties by name, so that the plan does not depend on the list's order.
        free.sort_by(|a, b| r.distance2(a).total_cmp(&r.distance2(b)).then_with(|| a.name.cmp(&b.name)));
        if free.len() < mine.len() {
            bail!(
                "--floorplan regions: PE {k} of machine_{pes} has {} {} cells but its region (columns {:.0}-{:.0}, \
                 rows {:.0}-{:.0}) has {} such sites; use --floorplan none",
                mine.len(),
                kind.cell_type(),
                r.x0,
                r.x1,
                r.y0,
                r.y1,
                free.len()
            );
        }
        // The nearest sites, taken in row order: the cells sorted by name (a sub-block's side by
        // side) along each row, so that no sub-block's RAMs are split to both ends of the region.
        free.truncate(mine.len());
        free.sort_by_key(|s| (s.y, s.x));
        for (cell, site) in mine.into_iter().zip(free) {
            used.insert(&site.name);
            out.insert(cell.to_string(), site.name.clone());
        }
    }
    Ok(out)
}

/// What [`apply`] pinned: one line a PE.
pub fn describe(pins: &BTreeMap<String, String>, cells: &[(String, String)], g: &[usize]) -> String {
    let types: BTreeMap<&str, &str> = cells.iter().map(|(n, t)| (n.as_str(), t.as_str())).collect();
    let mut per: BTreeMap<usize, (usize, usize)> = BTreeMap::new();
    for (cell, k) in pins.keys().filter_map(|c| Some((c, pe_of(c)?))) {
        let e = per.entry(k).or_default();
        match types.get(cell.as_str()).copied().and_then(Kind::of_cell) {
            Some(Kind::Bram) => e.0 += 1,
            _ => e.1 += 1,
        }
    }
    let mut s = format!("regions: {} of the die, the sites nearest each centre in row order", grid_name(g));
    for (k, (b, m)) in per {
        let r = region(k, g);
        s += &format!(
            "; PE {k}: {b} DP16KD + {m} MULT18X18D in columns {:.0}-{:.0}, rows {:.0}-{:.0}",
            r.x0, r.x1, r.y0, r.y1
        );
    }
    s
}

/// Reads Yosys' netlist `src`, pins the hard cells of each of the `pes` PEs to its region and
/// writes the netlist for nextpnr to `dst`; returns the floorplan's description.
pub fn apply(src: &Path, dst: &Path, pes: usize) -> Result<String> {
    let text = std::fs::read(src).with_context(|| format!("reading {}", src.display()))?;
    let mut json: Value =
        serde_json::from_slice(&text).with_context(|| format!("reading the netlist {}", src.display()))?;
    let modules = json
        .get_mut("modules")
        .and_then(Value::as_object_mut)
        .with_context(|| format!("{} has no modules", src.display()))?;
    // The flattened top: the module that holds the hard cells.
    let top = modules
        .values_mut()
        .filter_map(|m| m.get_mut("cells").and_then(Value::as_object_mut))
        .find(|c| c.values().any(|c| c["type"].as_str().and_then(Kind::of_cell).is_some()))
        .with_context(|| format!("{} has no DP16KD or MULT18X18D cell", src.display()))?;
    let cells: Vec<(String, String)> =
        top.iter().map(|(n, c)| (n.clone(), c["type"].as_str().unwrap_or_default().to_string())).collect();
    let (g, pins) = assign(&cells, pes)?;
    for (cell, site) in &pins {
        let attrs = top
            .get_mut(cell)
            .and_then(|c| c.as_object_mut())
            .map(|c| c.entry("attributes").or_insert_with(|| Value::Object(Default::default())))
            .and_then(Value::as_object_mut)
            .with_context(|| format!("the cell {cell} has no attributes"))?;
        attrs.insert("BEL".to_string(), Value::String(site.clone()));
    }
    std::fs::write(dst, serde_json::to_vec(&json)?).with_context(|| format!("writing {}", dst.display()))?;
    Ok(describe(&pins, &cells, &g))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A machine's hard cells as the flattened netlist names them: 17 DP16KD and 16 MULT18X18D a PE.
    fn machine(pes: usize) -> Vec<(String, String)> {
        let mut cells = vec![("block.arbiter.x".to_string(), "TRELLIS_FF".to_string())];
        for k in 0..pes {
            cells.extend((0..17).map(|i| (format!("block.pes${k}.cache.lane{i}.bo_tile0"), "DP16KD".into())));
            cells.extend((0..16).map(|i| (format!("block.pes${k}.iu.m{i}"), "MULT18X18D".into())));
        }
        cells
    }

    #[test]
    fn the_site_list_is_the_devices_208_block_rams_and_156_multipliers() {
        let s = sites();
        assert_eq!(s.iter().filter(|s| s.kind == Kind::Bram).count(), 208);
        assert_eq!(s.iter().filter(|s| s.kind == Kind::Mult).count(), 156);
        let names: HashSet<&str> = s.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names.len(), s.len(), "a site listed twice");
        assert!(s.iter().all(|s| DIE.contains(s)), "a site outside the die's extent");
    }

    #[test]
    fn every_pe_gets_its_own_sites_inside_its_own_region() {
        for (pes, grid) in [
            (1, vec![1]),
            (2, vec![1, 1]),
            (3, vec![2, 1]),
            (4, vec![2, 2]),
            (6, vec![3, 3]),
            (7, vec![4, 3]),
            (8, vec![8]),
        ] {
            let cells = machine(pes);
            let (g, pins) = assign(&cells, pes).unwrap();
            assert_eq!(g, grid, "machine_{pes}'s grid");
            assert_eq!(pins.len(), 33 * pes, "machine_{pes}: every hard cell pinned");
            let mut seen = HashSet::new();
            let all = sites();
            let by_name: BTreeMap<&str, &Site> = all.iter().map(|s| (s.name.as_str(), s)).collect();
            for ((cell, ty), site) in cells.iter().filter_map(|(c, t)| Some(((c, t), pins.get(c)?))) {
                assert!(seen.insert(site.clone()), "machine_{pes}: {site} given twice");
                let s = by_name[site.as_str()];
                assert_eq!(Some(s.kind), Kind::of_cell(ty), "{cell} on {site}");
                assert!(region(pe_of(cell).unwrap(), &g).contains(s), "machine_{pes}: {cell} on {site}");
            }
        }
        // One PE's cells of a kind, in name order, sit on sites in row order: a sub-block's side by side.
        let (_, pins) = assign(&machine(4), 4).unwrap();
        let all = sites();
        let at = |site: &str| all.iter().find(|s| s.name == site).map(|s| (s.y, s.x)).unwrap();
        let rams: Vec<(u32, u32)> =
            pins.iter().filter(|(c, _)| c.contains("pes$2.cache")).map(|(_, s)| at(s)).collect();
        assert!(rams.len() == 17 && rams.windows(2).all(|w| w[0] < w[1]), "{rams:?}");
        // The regions tile the die without overlap.
        let r: Vec<Region> = (0..4).map(|k| region(k, &[2, 2])).collect();
        assert_eq!((r[0].x1, r[0].y1, r[3].x0, r[3].y0), (r[1].x0, r[2].y0, r[2].x1, r[1].y1));
        assert_eq!(region(0, &[1]), DIE);
        // Seven: four regions above, three wider ones below, together the die.
        let r: Vec<Region> = (0..7).map(|k| region(k, &[4, 3])).collect();
        assert_eq!((r[3].x1, r[4].x0, r[4].y0, r[6].x1, r[6].y1), (DIE.x1, DIE.x0, r[0].y1, DIE.x1, DIE.y1));
        assert_eq!(r[4].x1 - r[4].x0, (DIE.x1 - DIE.x0) / 3.0);
    }

    #[test]
    fn a_machine_whose_regions_are_too_small_is_refused_with_the_option() {
        // Two PEs of 80 multipliers each: no grid holds both (the device has 156). The error is
        // the first grid's: the lower half's 52 sites.
        let mut big = machine(2);
        for k in 0..2 {
            big.extend((16..80).map(|i| (format!("block.pes${k}.iu.m{i}"), "MULT18X18D".into())));
        }
        let e = assign(&big, 2).unwrap_err().to_string();
        assert!(
            e.contains("--floorplan none") && e.contains("80 MULT18X18D") && e.contains("rows 48-94) has 52"),
            "{e}"
        );
        assert!(assign(&machine(4), 3).is_err(), "a cell of a PE the machine does not have");
    }

    #[test]
    fn apply_sets_bel_on_the_hard_cells_only_and_keeps_the_netlists_order() {
        let dir = std::env::temp_dir().join(format!("shelling-floorplan-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let src = dir.join("synth.json");
        std::fs::write(
            &src,
            r#"{"creator": "Yosys", "modules": {"m": {"cells": {
                "z.pes$1.a": {"type": "DP16KD", "attributes": {"src": "x"}},
                "a.pes$0.b": {"type": "MULT18X18D", "attributes": {}},
                "b.lut": {"type": "LUT4", "attributes": {}}
            }}}}"#,
        )
        .unwrap();
        let dst = dir.join("placed.json");
        let d = apply(&src, &dst, 2).unwrap();
        assert!(d.starts_with("regions: 1 x 2 grid"), "{d}");
        let out: Value = serde_json::from_slice(&std::fs::read(&dst).unwrap()).unwrap();
        let cells = out["modules"]["m"]["cells"].as_object().unwrap();
        assert_eq!(cells.keys().collect::<Vec<_>>(), ["z.pes$1.a", "a.pes$0.b", "b.lut"]);
        let bel = |c: &str| cells[c]["attributes"]["BEL"].as_str().map(str::to_string);
        let (b, m) = (bel("z.pes$1.a").unwrap(), bel("a.pes$0.b").unwrap());
        assert!(b.contains("EBR") && m.contains("MULT18"), "{b} {m}");
        assert_eq!(cells["z.pes$1.a"]["attributes"]["src"], "x");
        assert_eq!(bel("b.lut"), None);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
