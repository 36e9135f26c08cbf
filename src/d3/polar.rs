//! The polar tracer: the paper's direct extension of shelling to 3D (§3.2, first proposal), with
//! the stochastic tracking mechanism of §3.1.
//!
//! * **Sectors in (Θ, Φ).** A sector is a block of the hemisphere set's cells, `w` Θ-bands by
//!   `h` Φ-cells ([`ShellParams::phi_cells`], by default [`SECTOR_PHI_CELLS`]; fewer when the
//!   set has fewer cells or the widest sector is narrower): the same rows of Φ-cells in every
//!   sector, so **Φ is the angle fixed** to pass neighbourhood information, and the sectors of
//!   a row go round in Θ, each the Θ-neighbour of the one before. The width is the 2D rule's in
//!   rays, `clamp(round(α·ADLC), w_min, w_max)` from the first shell (with relevant polygons) of
//!   the previous sector, spread over the row's `h` cells: `w = max(1, round(width / h))` bands,
//!   at most `max(1, w_max / h)`. A row starts again from [`ShellParams::first_sector`].
//! * **Shells of constant depth** `Γ` ([`ShellParams::shell_depth`], by default 4 cell sides):
//!   shell `j` of a sector holds the points at distances `[jΓ, (j + 1)Γ)` from the source in the
//!   directions of the sector's remaining rays. Its cells are those whose box comes within the
//!   stopping margin of that distance range and meets the cone around the remaining rays (axis
//!   their mean direction, half-angle the largest angle from it), by the box's circumscribed
//!   sphere: a superset of the cells that hold any point of those rays in the shell. An empty
//!   cell's macro-region counts once per shell.
//! * **Loading and screening.** Every polygon of those cells not yet loaded in this sector is
//!   loaded (before screening) and screened ([`super::trace::screen`], and its span must meet
//!   the sector's bands and cells); the survivors are the shell's relevant polygons.
//! * **Spans.** A polygon's rays are those whose (Θ, Φ) lie in its spanning angles, computed
//!   exactly by [`super::span`] (the critical points of Φ along the edges) on its registration
//!   polygon, widened for rounding: the band range holding its Θ-span and the cell range holding
//!   its Φ-span.
//! * **Subshells (tracking S).** From the neighbouring shell (the same shell index in the
//!   previous sector of the row; without one, [`ShellParams::default_adlc`] and `Γ`) the ADLC and
//!   the average flatness: the sector's cells are cut into angular subshells of `g × g` cells,
//!   `g = max(1, round(√ADLC))` (a polygon's rays cover about ADLC cells, in both angles), and
//!   the shell into radial subshells of the flatness (at least
//!   [`ShellParams::min_subshell_fraction`] of `Γ`). The relevant polygons, in order of their
//!   distance, join the radial subshell of their distance; each is tested against all remaining
//!   rays of every angular subshell its span meets; as a radial subshell closes, the rays hit
//!   before its end leave.
//! * **Shell end.** The rays whose nearest hit lies before the shell's end (less the stopping
//!   margin, [`Grid3::stop_margin`]) leave the sector's bundle.
//!
//! A polygon's flatness is the spread of its vertices' distances from the source (Def. 2.4), its
//! degree of local coherence the number of rays in its span. `adlc_estimated` is the mean of the
//! ADLC each shell's subshells were cut with, weighted by its relevant polygons (as in 2D).
//!
//! Correctness: a ray's hit point lies in a cell its shell lists, the polygon is registered there
//! (registration is conservative), and its span holds the ray, so a polygon that can hit a ray is
//! tested against it before the ray leaves; the nearest hit is brute force's (`tests/tracers3d.rs`).

use super::brute::{intersect, Hit};
use super::grid::{Grid3, RegistrationPolygon};
use super::scene::Scene3;
use super::span::{polygon_span, Span3};
use super::trace::{finish, offer, screen, Bundle3, Layout3, Method3, Screen3, Trace3, Trace3Error};
use crate::counters::Counters;
use crate::limits::MAX_SHELLS;
use crate::trace::ShellParams;
use glam::DVec3;
use std::f64::consts::TAU;

/// The default Φ-cells of a sector's row (the fixed angle, [`ShellParams::phi_cells`]), when the
/// set and the widest sector allow.
pub const SECTOR_PHI_CELLS: usize = 4;

/// What the tracker knows of a polygon for one source, computed on its first load.
#[derive(Clone, Copy, Debug)]
struct Info {
    pass: bool,
    /// The first band of the span and the number of bands (cyclic; `n_theta` for all).
    band0: usize,
    bands: usize,
    /// The cells `[cell0, cell1)` of the span.
    cell0: usize,
    cell1: usize,
    /// A lower bound of the distance from the source.
    r_min: f64,
    flatness: f64,
}

impl Info {
    fn has_band(&self, band: usize, n: usize) -> bool {
        (band + n - self.band0) % n < self.bands
    }

    fn rays(&self) -> usize {
        self.bands * (self.cell1 - self.cell0)
    }
}

/// A shell's estimate for the neighbouring sector.
#[derive(Clone, Copy, Debug)]
struct Estimate {
    adlc: f64,
    flatness: f64,
}

/// The rays of the current sector, bands `[i0, i0 + w)` by cells `[j0, j0 + h)`.
struct Sector {
    i0: usize,
    w: usize,
    j0: usize,
    h: usize,
    /// By local index `lb·h + lc`.
    alive: Vec<bool>,
    remaining: usize,
}

impl Sector {
    fn ray(&self, layout: &Layout3, local: usize) -> usize {
        (self.i0 + local / self.h) * layout.n_phi + self.j0 + local % self.h
    }
}

/// Traces `bundle` (a hemisphere set's) through `grid` by the polar technique (module docs).
pub fn trace(
    scene: &Scene3,
    grid: &Grid3,
    bundle: &Bundle3,
    params: &ShellParams,
) -> Result<Trace3, Trace3Error> {
    let layout = bundle.layout_for(Method3::Polar)?;
    let o = bundle.source.origin;
    let (glo, ghi) = grid.extent();
    let far = [0, 1, 2, 3, 4, 5, 6, 7]
        .iter()
        .map(|&c| {
            let corner = DVec3::new(
                if c & 1 == 0 { glo.x } else { ghi.x },
                if c & 2 == 0 { glo.y } else { ghi.y },
                if c & 4 == 0 { glo.z } else { ghi.z },
            );
            (corner - o).length()
        })
        .fold(0.0f64, f64::max);
    let near = (glo - o).max(o - ghi).max(DVec3::ZERO).length();
    let depth = params.shell_depth.unwrap_or(4.0 * grid.cell_size);
    let shells = (far / depth).ceil();
    if !(depth.is_finite() && depth > 0.0) || shells > MAX_SHELLS as f64 {
        return Err(Trace3Error::InvalidParams(format!(
            "the shell depth {depth} cuts the grid into {shells} shells, more than {MAX_SHELLS}"
        )));
    }
    let mut t = Tracer {
        scene,
        grid,
        bundle,
        layout,
        params,
        depth,
        margin: grid.stop_margin(),
        info: vec![None; scene.polygons.len()],
        loaded: vec![0; scene.polygons.len()],
        region_seen: vec![0; grid.region_count()],
        tick: 0,
        best: vec![None; bundle.len()],
        c: Counters::default(),
        estimate: (0.0, 0.0),
    };
    let h = params.phi_cells.min(layout.n_phi).min(params.max_sector).max(1);
    let mut j0 = 0;
    while j0 < layout.n_phi {
        let h = h.min(layout.n_phi - j0);
        let mut width = params.first_sector;
        let mut prev: Vec<Option<Estimate>> = Vec::new();
        let mut i0 = 0;
        while i0 < layout.n_theta {
            let rays = width.clamp(params.min_sector, params.max_sector);
            let w = ((rays as f64 / h as f64).round() as usize).clamp(1, (params.max_sector / h).max(1));
            let w = w.min(layout.n_theta - i0);
            let mut sector = Sector { i0, w, j0, h, alive: vec![true; w * h], remaining: w * h };
            let (cur, first) = t.sector(&mut sector, &prev, near, far);
            if let Some(a) = first {
                width = (params.sector_per_adlc * a).round() as usize;
            }
            prev = cur;
            i0 += w;
        }
        j0 += h;
    }
    let estimate = if t.estimate.1 > 0.0 { t.estimate.0 / t.estimate.1 } else { 0.0 };
    Ok(finish(t.best, t.c, Some(estimate)))
}

/// One source's trace: what every sector reads and what it changes.
struct Tracer<'a> {
    scene: &'a Scene3,
    grid: &'a Grid3,
    bundle: &'a Bundle3,
    layout: &'a Layout3,
    params: &'a ShellParams,
    depth: f64,
    margin: f64,
    info: Vec<Option<Info>>,
    /// The tick of the sector that last loaded each polygon.
    loaded: Vec<u64>,
    /// The tick of the shell that last met each macro-region.
    region_seen: Vec<u64>,
    tick: u64,
    best: Vec<Option<Hit>>,
    c: Counters,
    /// The weighted sum and weight of the ADLC the subshells were cut with.
    estimate: (f64, f64),
}

impl Tracer<'_> {
    /// Traces one sector shell by shell; returns its shells' estimates and the ADLC of its first
    /// shell with relevant polygons.
    fn sector(
        &mut self,
        sector: &mut Sector,
        prev: &[Option<Estimate>],
        near: f64,
        far: f64,
    ) -> (Vec<Option<Estimate>>, Option<f64>) {
        self.tick += 1;
        let sector_tick = self.tick;
        let mut cur = Vec::new();
        let mut first = None;
        let mut relevant = Vec::new();
        let mut r1 = 0.0;
        let mut j = 0;
        while sector.remaining > 0 && r1 < far {
            let r2 = r1 + self.depth;
            relevant.clear();
            if r2 + self.margin >= near {
                self.load_shell(sector, sector_tick, r1, r2, &mut relevant);
            }
            let here = self.shell_estimate(&relevant);
            self.track(sector, prev.get(j).copied().flatten(), r1, &mut relevant);
            self.retire(sector, r2 - self.margin);
            if first.is_none() {
                first = here.map(|e| e.adlc);
            }
            cur.push(here);
            r1 = r2;
            j += 1;
        }
        (cur, first)
    }

    /// Lists the cells of shell `[r1, r2)` over the sector's remaining rays and loads their
    /// polygons (module docs); leaves the relevant ones in `relevant`.
    fn load_shell(&mut self, sector: &Sector, sector_tick: u64, r1: f64, r2: f64, relevant: &mut Vec<usize>) {
        self.tick += 1;
        let shell_tick = self.tick;
        let o = self.bundle.source.origin;
        // The cone around the remaining rays.
        let dirs: Vec<DVec3> = (0..sector.alive.len())
            .filter(|&l| sector.alive[l])
            .map(|l| self.bundle.directions[sector.ray(self.layout, l)])
            .collect();
        let sum: DVec3 = dirs.iter().sum();
        let (axis, half) = if sum.length() > 1e-3 {
            let axis = sum.normalize();
            let cos = dirs.iter().map(|d| d.dot(axis)).fold(1.0f64, f64::min).clamp(-1.0, 1.0);
            (axis, cos.acos() + 1e-9)
        } else {
            (self.bundle.source.normal, std::f64::consts::PI)
        };
        let m = self.margin + 2.0 * self.grid.eps;
        let (inner, outer) = ((r1 - m).max(0.0), r2 + m);
        // The bounding box of {r·a : r ∈ [inner, outer], angle(a, axis) ≤ half}.
        let grid = self.grid;
        let mut cell_lo = [0usize; 3];
        let mut cell_hi = [0usize; 3];
        for k in 0..3 {
            let gamma = axis[k].clamp(-1.0, 1.0).acos();
            let top = (gamma - half).max(0.0).cos();
            let bottom = -(std::f64::consts::PI - gamma - half).max(0.0).cos();
            let vals = [inner * top, inner * bottom, outer * top, outer * bottom];
            let lo = vals.iter().fold(f64::INFINITY, |a, &b| a.min(b)) + o[k] - m;
            let hi = vals.iter().fold(f64::NEG_INFINITY, |a, &b| a.max(b)) + o[k] + m;
            let last = grid.n[k] as i64 - 1;
            let (a, b) = (grid.coord(lo, k), grid.coord(hi, k));
            if b < 0 || a > last {
                return;
            }
            cell_lo[k] = a.clamp(0, last) as usize;
            cell_hi[k] = b.clamp(0, last) as usize;
        }
        let rho = 0.5 * 3f64.sqrt() * grid.cell_size + 2.0 * grid.eps;
        for z in cell_lo[2]..=cell_hi[2] {
            for y in cell_lo[1]..=cell_hi[1] {
                for x in cell_lo[0]..=cell_hi[0] {
                    let coords = [x as u32, y as u32, z as u32];
                    let (lo, hi) = grid.cell_bounds(coords);
                    let dmin = (lo - o).max(o - hi).max(DVec3::ZERO).length();
                    let dmax = (lo - o).abs().max((hi - o).abs()).length();
                    if dmin > outer || dmax < inner {
                        continue;
                    }
                    let v = (lo + hi) * 0.5 - o;
                    let l = v.length();
                    if l > rho {
                        let angle = (v.dot(axis) / l).clamp(-1.0, 1.0).acos();
                        if angle > half + (rho / l).min(1.0).asin() + 1e-9 {
                            continue;
                        }
                    }
                    let cell = grid.index(coords);
                    if let Some(r) = grid.region_of(cell) {
                        if self.region_seen[r as usize] != shell_tick {
                            self.region_seen[r as usize] = shell_tick;
                            self.c.cells_traversed += 1;
                        }
                        continue;
                    }
                    self.c.cells_traversed += 1;
                    for &k in grid.cell_items(cell) {
                        let k = k as usize;
                        if self.loaded[k] == sector_tick {
                            continue;
                        }
                        self.loaded[k] = sector_tick;
                        self.c.patches_read_before_screening += 1;
                        let info = self.info(k);
                        if info.pass && self.meets(sector, &info) {
                            self.c.patches_read_after_screening += 1;
                            relevant.push(k);
                        }
                    }
                }
            }
        }
    }

    /// Whether a polygon's span meets the sector's bands and cells.
    fn meets(&self, sector: &Sector, info: &Info) -> bool {
        let cells = info.cell0.max(sector.j0) < info.cell1.min(sector.j0 + sector.h);
        cells && (sector.i0..sector.i0 + sector.w).any(|i| info.has_band(i, self.layout.n_theta))
    }

    /// The polygon's information for this source, computed on its first load.
    fn info(&mut self, k: usize) -> Info {
        if let Some(i) = self.info[k] {
            return i;
        }
        let p = &self.scene.polygons[k];
        let src = &self.bundle.source;
        let pass = screen(src, k, p) == Screen3::Pass;
        let mut info = Info { pass, band0: 0, bands: 0, cell0: 0, cell1: 0, r_min: 0.0, flatness: 0.0 };
        if pass {
            let reg = RegistrationPolygon::new(p);
            let l = self.layout;
            let span: Span3 =
                polygon_span(src.origin, src.normal, l.tangent, l.bitangent, &reg.vertices, p.normal);
            let n = l.n_theta;
            (info.band0, info.bands) = match span.theta {
                None => (0, n),
                Some((lo, hi)) => {
                    // Band i's rays have Θ = (i + ½)·2π/n.
                    let d = TAU / n as f64;
                    let a = (lo / d - 0.5).ceil() as i64;
                    let b = (hi / d - 0.5).floor() as i64;
                    let len = (b - a + 1).max(0) as usize;
                    if len >= n {
                        (0, n)
                    } else {
                        (a.rem_euclid(n as i64) as usize, len)
                    }
                }
            };
            info.cell0 = l.phi.partition_point(|&f| f < span.phi.0);
            info.cell1 = l.phi.partition_point(|&f| f <= span.phi.1);
            info.r_min = (span.distance - self.margin).max(0.0);
            let (dlo, dhi) = p
                .vertices
                .iter()
                .map(|v| (*v - src.origin).length())
                .fold((f64::INFINITY, 0.0f64), |(a, b), d| (a.min(d), b.max(d)));
            info.flatness = dhi - dlo;
        }
        self.info[k] = Some(info);
        info
    }

    /// What the shell's relevant polygons tell the neighbouring sector.
    fn shell_estimate(&self, relevant: &[usize]) -> Option<Estimate> {
        (!relevant.is_empty()).then(|| {
            let info = |k: usize| self.info[k].expect("relevant polygons are loaded");
            let n = relevant.len() as f64;
            Estimate {
                adlc: relevant.iter().map(|&k| info(k).rays() as f64).sum::<f64>() / n,
                flatness: relevant.iter().map(|&k| info(k).flatness).sum::<f64>() / n,
            }
        })
    }

    /// The stochastic tracking mechanism in 3D (module docs): subshells from the neighbour.
    fn track(&mut self, sector: &mut Sector, neighbour: Option<Estimate>, r1: f64, relevant: &mut [usize]) {
        let params = self.params;
        let adlc = neighbour.map_or(params.default_adlc, |x| x.adlc);
        let flat = neighbour.map_or(self.depth, |x| x.flatness);
        if !relevant.is_empty() {
            self.estimate.0 += adlc * relevant.len() as f64;
            self.estimate.1 += relevant.len() as f64;
        }
        let g = (adlc.sqrt().round() as usize).max(1);
        let step = flat.clamp(self.depth * params.min_subshell_fraction, self.depth);
        let bins = ((self.depth / step).ceil() as usize).max(1);
        let info: Vec<Info> = relevant.iter().map(|&k| self.info[k].expect("loaded")).collect();
        let mut order: Vec<usize> = (0..relevant.len()).collect();
        order.sort_unstable_by(|&a, &b| {
            info[a].r_min.total_cmp(&info[b].r_min).then(relevant[a].cmp(&relevant[b]))
        });
        let n = self.layout.n_theta;
        let o = self.bundle.source.origin;
        let mut bin = 0;
        for &q in &order {
            let (k, inf) = (relevant[q], info[q]);
            let pb = (((inf.r_min - r1) / step).floor().max(0.0) as usize).min(bins - 1);
            while bin < pb {
                bin += 1;
                self.retire(sector, r1 + bin as f64 * step - self.margin);
            }
            // The angular subshells (g × g local cells) the span meets.
            let band_blocks: Vec<bool> = {
                let mut v = vec![false; sector.w.div_ceil(g)];
                for lb in 0..sector.w {
                    if inf.has_band(sector.i0 + lb, n) {
                        v[lb / g] = true;
                    }
                }
                v
            };
            let c0 = inf.cell0.max(sector.j0) - sector.j0;
            let c1 = inf.cell1.min(sector.j0 + sector.h).saturating_sub(sector.j0);
            if c0 >= c1 {
                continue;
            }
            let (cb0, cb1) = (c0 / g, (c1 - 1) / g);
            let p = &self.scene.polygons[k];
            for local in 0..sector.alive.len() {
                let (lb, lc) = (local / sector.h, local % sector.h);
                if !sector.alive[local] || !band_blocks[lb / g] || lc / g < cb0 || lc / g > cb1 {
                    continue;
                }
                let ray = sector.ray(self.layout, local);
                let d = self.bundle.directions[ray];
                self.c.intersection_computations += 1;
                if let Some(t) = intersect(o, d, p) {
                    offer(&mut self.best[ray], k, t, d.dot(p.normal) < 0.0);
                }
            }
        }
    }

    /// Retires the remaining rays whose nearest hit lies before `limit`.
    fn retire(&self, sector: &mut Sector, limit: f64) {
        for local in 0..sector.alive.len() {
            if sector.alive[local] && self.best[sector.ray(self.layout, local)].is_some_and(|h| h.t < limit) {
                sector.alive[local] = false;
                sector.remaining -= 1;
            }
        }
    }
}
