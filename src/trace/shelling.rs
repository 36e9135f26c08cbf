//! The shelling techniques S (stochastic) and D (deterministic), Sections 3.1 and 3.2.
//!
//! Both share the structure: the bundle's rays (numbered by angle) are cut into **sectors**,
//! contiguous ray ranges processed one after another. Each sector is cut radially into **shells**
//! of constant depth `Γ`. Shell `j` is the annular sector between radii `[r₁, r₂)` and the angles of
//! the first and last ray still in the sector's bundle (Def 2.6); its cells are listed by
//! rasterising a convex trapezoid that contains it (split into pieces no wider than π/4). Empty
//! cells are skipped a macro-region at a time. Every patch of those
//! cells not yet loaded in this sector is loaded once (counted before screening) and screened:
//! backward, back-facing, the source's own patch, or outside the sector's angular range. The
//! survivors are the shell's relevant patches; they are tested against remaining rays, and at
//! the end of the shell every ray whose nearest hit lies before `r₂` leaves the sector's bundle.
//!
//! The two techniques differ in the **tracking mechanism**, which decides how a shell is cut into
//! subshells (which rays each patch is tested against):
//!
//! * **S** estimates, from the neighbouring shell (the same shell index in the previous sector),
//!   the ADLC and the average flatness of the patches it will meet. It cuts the sector's rays into
//!   angular subshells of `round(ADLC)` rays and the shell into radial subshells of the average
//!   flatness; a patch is tested against all remaining rays of every angular subshell its span
//!   overlaps, in order of radial subshell, and after each radial subshell the rays whose hit
//!   lies before its end leave. Without a neighbour it uses the defaults of [`ShellParams`].
//!   It knows a patch's coherence only up to a subshell, not its position: hence about twice the
//!   actual number of tests (the paper's Nyquist remark).
//! * **D** derives each patch's coherence: the patches of the shell are sorted by angle and each
//!   is tested against exactly the remaining rays inside its angular span.
//!
//! Both size the next sector from the ADLC of the first shell (with relevant patches) of the
//! previous one: `width = clamp(round(α·ADLC), w_min, w_max)`; S uses its estimate, D the derived
//! value. INTERPRETATION.md gives the reasons for each of these readings.

use super::{offer, with_scratch, HitTest, PatchCache, SceneView, Scratch, Screen};
use crate::counters::Counters;
use crate::geom::{Hit, Vec2};
use crate::rays::Bundle;
use std::f64::consts::FRAC_PI_4;

/// Which tracking mechanism cuts shells into subshells.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Tracking {
    Stochastic,
    Deterministic,
}

/// Parameters of the shell structure. The defaults are the ones every figure uses.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ShellParams {
    /// Shell depth `Γ` in world units; `None` means 4 cell sides.
    pub shell_depth: Option<f64>,
    /// Rays in the first sector (no neighbourhood information yet).
    pub first_sector: usize,
    /// `α`: sector width in rays per unit of ADLC.
    pub sector_per_adlc: f64,
    /// Narrowest sector, in rays.
    pub min_sector: usize,
    /// Widest sector, in rays: the ray memory of one processing element.
    pub max_sector: usize,
    /// ADLC assumed for a shell with no neighbour (S's default angular subshell, in rays).
    pub default_adlc: f64,
    /// Smallest radial subshell, as a fraction of `Γ`.
    pub min_subshell_fraction: f64,
}

impl Default for ShellParams {
    fn default() -> Self {
        ShellParams {
            shell_depth: None,
            first_sector: 16,
            sector_per_adlc: 4.0,
            min_sector: 4,
            max_sector: 64,
            default_adlc: 4.0,
            min_subshell_fraction: 0.125,
        }
    }
}

impl ShellParams {
    /// Checks the parameters; the message names the offending one.
    pub fn validate(&self) -> Result<(), String> {
        if let Some(d) = self.shell_depth {
            if !(d.is_finite() && d > 0.0) {
                return Err(format!("shell depth must be a positive number, got {d}"));
            }
        }
        if self.min_sector == 0 || self.min_sector > self.max_sector {
            return Err(format!(
                "sector widths must satisfy 1 <= min ({}) <= max ({})",
                self.min_sector, self.max_sector
            ));
        }
        if self.first_sector == 0 {
            return Err("the first sector must hold at least one ray".into());
        }
        if !(self.sector_per_adlc.is_finite() && self.sector_per_adlc > 0.0) {
            return Err(format!("sector_per_adlc must be positive, got {}", self.sector_per_adlc));
        }
        if !(self.default_adlc.is_finite() && self.default_adlc >= 1.0) {
            return Err(format!("default_adlc must be at least 1, got {}", self.default_adlc));
        }
        if !(self.min_subshell_fraction > 0.0 && self.min_subshell_fraction <= 1.0) {
            return Err(format!(
                "min_subshell_fraction must lie in (0, 1], got {}",
                self.min_subshell_fraction
            ));
        }
        Ok(())
    }
}

/// Statistics of the shell structure a shelling tracer built.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ShellStats {
    pub sectors: u64,
    /// Shells entered by at least one ray.
    pub shells: u64,
    /// Rays entering shells, summed over shells.
    pub rays_entering: u64,
    /// Rays leaving shells without a hit inside them, summed over shells.
    pub rays_leaving: u64,
}

impl ShellStats {
    /// The measured `S` of Section 4: the fraction of rays leaving a shell.
    pub fn leaving_fraction(&self) -> f64 {
        if self.rays_entering == 0 {
            0.0
        } else {
            self.rays_leaving as f64 / self.rays_entering as f64
        }
    }
}

/// What the tracker remembers of one shell of a sector, for the shell of the same index in the
/// next sector.
#[derive(Clone, Copy, Debug)]
struct ShellEstimate {
    adlc: f64,
    flatness: f64,
}

pub(super) fn trace<H: HitTest>(
    scene: SceneView<'_>,
    bundle: &Bundle,
    params: &ShellParams,
    tracking: Tracking,
    test: &H,
) -> (Vec<Option<Hit>>, Counters, ShellStats) {
    with_scratch(scene, |scratch| {
        let Scratch {
            tick,
            info,
            info_stamp,
            patch_stamp: loaded,
            cell_stamp: cell_seen,
            region_stamp: region_seen,
            ..
        } = scratch;
        *tick += 1;
        let cache = PatchCache::new(scene, bundle, info, info_stamp, *tick);
        trace_bundle(scene, bundle, params, tracking, test, cache, tick, loaded, cell_seen, region_seen)
    })
}

/// The body of [`trace`], on this thread's scratch memory: `loaded`, `cell_seen` and
/// `region_seen` hold stamps compared against fresh ticks per sector and per shell.
#[allow(clippy::too_many_arguments)]
fn trace_bundle<H: HitTest>(
    scene: SceneView<'_>,
    bundle: &Bundle,
    params: &ShellParams,
    tracking: Tracking,
    test: &H,
    mut cache: PatchCache<'_>,
    tick: &mut u64,
    loaded: &mut [u64],
    cell_seen: &mut [u64],
    region_seen: &mut [u64],
) -> (Vec<Option<Hit>>, Counters, ShellStats) {
    let grid = scene.grid;
    let r = bundle.len();
    let o = bundle.source.origin;
    let depth = params.shell_depth.unwrap_or(4.0 * grid.cell_size);
    let margin = 4.0 * grid.eps;
    let far = {
        let (lo, hi) = grid.extent();
        [lo, hi, Vec2::new(lo.x, hi.y), Vec2::new(hi.x, lo.y)]
            .iter()
            .fold(0.0f64, |m, c| m.max((*c - o).length()))
    };
    let mut c = Counters::default();
    let mut stats = ShellStats::default();
    let mut best: Vec<Option<Hit>> = vec![None; r];
    let mut alive = vec![false; r];
    let mut est_sum = 0.0;
    let mut est_weight = 0.0;

    let mut prev: Vec<Option<ShellEstimate>> = Vec::new();
    let mut width = params.first_sector;
    let mut s = 0usize;
    let mut relevant: Vec<u32> = Vec::new();

    while s < r {
        let e = (s + width.clamp(params.min_sector, params.max_sector)).min(r);
        stats.sectors += 1;
        *tick += 1;
        let sector = *tick;
        alive[s..e].iter_mut().for_each(|a| *a = true);
        let mut remaining = e - s;
        let mut cur: Vec<Option<ShellEstimate>> = Vec::new();
        let mut first_adlc: Option<f64> = None;
        let mut r1 = 0.0f64;
        let mut j = 0usize;
        while remaining > 0 && r1 < far {
            let r2 = r1 + depth;
            *tick += 1;
            let shell_gen = *tick;
            stats.shells += 1;
            stats.rays_entering += remaining as u64;

            // Find the shell's cells and load its new patches (screening as they arrive).
            relevant.clear();
            let mut k = s;
            while k < e {
                if !alive[k] {
                    k += 1;
                    continue;
                }
                // The shell spans the remaining rays' angles (Def 2.6: two boundary angles), in
                // pieces no wider than π/4, each from a remaining ray to the last one within π/4.
                let k0 = k;
                let mut last = k;
                while k + 1 < e && bundle.angles[k + 1] - bundle.angles[k0] <= FRAC_PI_4 {
                    k += 1;
                    if alive[k] {
                        last = k;
                    }
                }
                // The trapezoid between the piece's boundary rays, from r₁ to beyond r₂: its
                // outer edge is tangent to the arc of radius r₂ at the piece's middle angle.
                let (da, db) = (bundle.rays[k0].dir, bundle.rays[last].dir);
                k += 1;
                let cos_half = (0.5 * (1.0 + da.dot(db))).max(0.0).sqrt();
                let inner = (r1 - margin).max(0.0);
                let outer = (r2 + margin) / cos_half;
                let poly = [o + da * inner, o + da * outer, o + db * outer, o + db * inner];
                grid.raster_convex(&poly, |iy, x0, x1| {
                    let mut ix = x0;
                    while ix <= x1 {
                        let cell = iy * grid.nx + ix;
                        if let Some(reg) = grid.region_of(cell) {
                            if region_seen[reg as usize] != shell_gen {
                                region_seen[reg as usize] = shell_gen;
                                c.cells_traversed += 1;
                            }
                            ix = grid.region(reg).x1 as usize + 1;
                            continue;
                        }
                        ix += 1;
                        if cell_seen[cell] == shell_gen {
                            continue;
                        }
                        cell_seen[cell] = shell_gen;
                        c.cells_traversed += 1;
                        for &p in grid.cell_items(cell) {
                            if loaded[p as usize] == sector {
                                continue;
                            }
                            loaded[p as usize] = sector;
                            c.patches_read_before_screening += 1;
                            let info = cache.get(p);
                            let in_sector = (info.rays.start as usize) < e && (info.rays.end as usize) > s;
                            if info.screen == Screen::Pass && in_sector {
                                c.patches_read_after_screening += 1;
                                relevant.push(p);
                            }
                        }
                    }
                });
            }

            // Tracking (Section 3.1): each relevant patch's spanning angle, in rays, estimates
            // its degree of local coherence; with its flatness it feeds the shell's averages.
            let mut dlc_sum = 0usize;
            let mut flat_sum = 0.0;
            for &p in &relevant {
                let info = cache.known(p);
                dlc_sum += info.rays.len();
                flat_sum += info.flatness;
            }
            let here = (!relevant.is_empty()).then(|| ShellEstimate {
                adlc: dlc_sum as f64 / relevant.len() as f64,
                flatness: flat_sum / relevant.len() as f64,
            });

            match tracking {
                Tracking::Stochastic => {
                    let neighbour = prev.get(j).copied().flatten();
                    let adlc = neighbour.map_or(params.default_adlc, |x| x.adlc);
                    let flat = neighbour.map_or(depth, |x| x.flatness);
                    if !relevant.is_empty() {
                        est_sum += adlc * relevant.len() as f64;
                        est_weight += relevant.len() as f64;
                    }
                    let group = (adlc.round() as usize).max(1);
                    let step = flat.clamp(depth * params.min_subshell_fraction, depth);
                    let bins = ((depth / step).ceil() as usize).max(1);
                    // Patches in order of their nearest point; each joins the radial subshell of
                    // its r_min (the last one for patches reaching beyond the shell).
                    relevant.sort_by(|&a, &b| {
                        cache.known(a).r_min.total_cmp(&cache.known(b).r_min).then(a.cmp(&b))
                    });
                    let mut bin = 0usize;
                    for &p in &relevant {
                        let info = cache.known(p);
                        let pb = (((info.r_min - r1) / step).floor().max(0.0) as usize).min(bins - 1);
                        while bin < pb {
                            // Close radial subshell `bin`: rays hit before its end are done.
                            bin += 1;
                            let end = r1 + bin as f64 * step;
                            remaining -= retire(&mut alive[s..e], &best[s..e], end - margin);
                        }
                        let lo = (info.rays.start as usize).max(s);
                        let hi = (info.rays.end as usize).min(e);
                        if lo >= hi {
                            continue;
                        }
                        let g0 = s + (lo - s) / group * group;
                        let g1 = (s + ((hi - 1 - s) / group + 1) * group).min(e);
                        let seg = &scene.segments[p as usize];
                        for i in g0..g1 {
                            if alive[i] {
                                c.intersection_computations += 1;
                                if let Some(t) = test.hit(bundle, i, p, seg) {
                                    offer(&mut best[i], Hit { t, segment: p });
                                }
                            }
                        }
                    }
                }
                Tracking::Deterministic => {
                    if let Some(h) = here {
                        est_sum += h.adlc * relevant.len() as f64;
                        est_weight += relevant.len() as f64;
                    }
                    relevant.sort_by(|&a, &b| {
                        cache.known(a).angle_lo.total_cmp(&cache.known(b).angle_lo).then(a.cmp(&b))
                    });
                    for &p in &relevant {
                        let info = cache.known(p);
                        let lo = (info.rays.start as usize).max(s);
                        let hi = (info.rays.end as usize).min(e);
                        let seg = &scene.segments[p as usize];
                        for i in lo..hi.max(lo) {
                            if alive[i] {
                                c.intersection_computations += 1;
                                if let Some(t) = test.hit(bundle, i, p, seg) {
                                    offer(&mut best[i], Hit { t, segment: p });
                                }
                            }
                        }
                    }
                }
            }

            // End of shell: rays whose nearest hit lies before r₂ are done.
            remaining -= retire(&mut alive[s..e], &best[s..e], r2 - margin);
            stats.rays_leaving += remaining as u64;
            if here.is_some() && first_adlc.is_none() {
                first_adlc = here.map(|h| h.adlc);
            }
            cur.push(here);
            r1 = r2;
            j += 1;
        }
        // Rays still remaining have left the grid: they hit nothing (or already hold a hit
        // beyond the last shell, which cannot happen as every patch lies inside the grid).
        alive[s..e].iter_mut().for_each(|a| *a = false);
        if let Some(a) = first_adlc {
            width = (params.sector_per_adlc * a).round() as usize;
        }
        prev = cur;
        s = e;
    }
    c.adlc_estimated = if est_weight > 0.0 { est_sum / est_weight } else { 0.0 };
    (best, c, stats)
}

/// Retires the rays whose nearest hit lies before `limit`; returns how many left the bundle.
fn retire(alive: &mut [bool], best: &[Option<Hit>], limit: f64) -> usize {
    let mut n = 0;
    for (a, b) in alive.iter_mut().zip(best) {
        if *a && matches!(b, Some(h) if h.t < limit) {
            *a = false;
            n += 1;
        }
    }
    n
}
