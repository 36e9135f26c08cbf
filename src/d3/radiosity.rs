//! Radiosity on 3D scenes: the 2D solvers of [`crate::radiosity::solve`] run on the form-factor
//! rows of [`super::form_factors`], once per colour channel.
//!
//! A polygon's radiosity `B_j` (radiant exitance, power per unit area) solves
//! `B_j = E_j + ρ_j Σ_i F_ji B_i` in each channel `c` of red, green and blue, with `E_j` the
//! material's `Ke[c]` and `ρ_j` its `Kd[c]`. The form factors depend on the geometry only, so
//! the three channels share the rows; the areas take the place of the 2D lengths
//! ([`surfaces`]).
//!
//! * [`full`]: all rows, then Gauss–Seidel in each channel.
//! * [`progressive`]: progressive refinement in each channel in turn. A row is computed when a
//!   polygon first shoots, in any channel, and kept: a polygon shoots again in the same channel
//!   and in the other two, and 3D scenes are small enough that the rows fit (`rows` counts the
//!   rows computed, each once).
//!
//! A channel in which nothing emits has the solution 0 everywhere and takes no step; a scene in
//! which nothing emits in any channel, with a `Kd` channel of 1 or whose emitted power
//! overflows is an error, before any row is traced ([`check`]). The scalar radiosity of a
//! polygon ([`Solution3::mean`]) is the mean of its three channels, as the scene's scalar
//! reflectance and emission are the means of `Kd` and `Ke`. (It is not the solve
//! with the mean reflectance: `B` is not linear in `ρ`.)

use super::scene::Scene3;
use crate::radiosity::form_factors::Row;
use crate::radiosity::solve::{self, Solution, SolveError, Surfaces};
use std::collections::HashMap;

/// The names of the channels, in the order of `Kd` and `Ke`.
pub const CHANNELS: [&str; 3] = ["r", "g", "b"];

/// What the solvers know of each polygon in `channel` (0, 1, 2: red, green, blue): its area (in
/// [`Surfaces::length`]), `Kd[channel]` and `Ke[channel]`.
pub fn surfaces(scene: &Scene3, channel: usize) -> Surfaces {
    let material = |p: &super::Polygon| &scene.materials[p.material];
    Surfaces {
        length: scene.polygons.iter().map(|p| p.area).collect(),
        reflectance: scene.polygons.iter().map(|p| material(p).kd[channel]).collect(),
        emission: scene.polygons.iter().map(|p| material(p).ke[channel]).collect(),
    }
}

/// The solution in the three channels.
#[derive(Clone, Debug, PartialEq)]
pub struct Solution3 {
    /// One solve per channel, in the order of [`CHANNELS`].
    pub channels: [Solution; 3],
    /// The distinct rows computed, in the order they were computed.
    pub rows: Vec<usize>,
}

impl Solution3 {
    /// Polygon `j`'s radiosity in the three channels.
    pub fn rgb(&self, j: usize) -> [f64; 3] {
        [0, 1, 2].map(|c| self.channels[c].radiosity[j])
    }

    /// Polygon `j`'s scalar radiosity: the mean of its three channels.
    pub fn mean(&self, j: usize) -> f64 {
        self.rgb(j).iter().sum::<f64>() / 3.0
    }

    /// The mean over the channels of a value of each channel's solution.
    pub fn mean_of(&self, value: impl Fn(&Solution) -> f64) -> f64 {
        self.channels.iter().map(value).sum::<f64>() / 3.0
    }

    /// Steps taken in all channels.
    pub fn steps(&self) -> usize {
        self.channels.iter().map(|s| s.steps).sum()
    }

    /// The largest of the channels' fractions left ([`Solution::unshot`]).
    pub fn unshot(&self) -> f64 {
        self.channels.iter().map(|s| s.unshot).fold(0.0, f64::max)
    }
}

/// The solution of a channel where nothing emits: zero everywhere, no step.
fn dark(n: usize) -> Solution {
    Solution {
        radiosity: vec![0.0; n],
        steps: 0,
        unshot: 0.0,
        history: Vec::new(),
        emitted: 0.0,
        absorbed: 0.0,
        escaped: 0.0,
        rows: Vec::new(),
    }
}

/// The names of the channels in errors, in the order of [`CHANNELS`].
const CHANNEL_NAMES: [&str; 3] = ["red", "green", "blue"];

/// What the solvers know of `scene` (named `name` in errors) in each channel, or why it cannot
/// be solved: nothing emits in any channel ([`SolveError::NothingEmits3`]); a material some
/// polygon uses has a `Kd` channel of 1 or more ([`SolveError::ReflectsAll`]: the loader allows
/// a channel of 1 when the mean is below 1, but that channel's light is never absorbed); a
/// channel's emitted power is not finite ([`SolveError::NotFinite`]). The solvers call it
/// first; a caller calls it before tracing any row, so that a bad scene costs no work.
pub fn check(scene: &Scene3, name: &str) -> Result<[Surfaces; 3], SolveError> {
    for p in &scene.polygons {
        let m = &scene.materials[p.material];
        if let Some(c) = (0..3).find(|&c| m.kd[c] >= 1.0 || m.kd[c].is_nan()) {
            return Err(SolveError::ReflectsAll {
                name: name.to_string(),
                material: m.name.clone(),
                channel: CHANNEL_NAMES[c],
                kd: m.kd[c],
            });
        }
    }
    let s = [0, 1, 2].map(|c| surfaces(scene, c));
    if let Some(c) = (0..3).find(|&c| !s[c].emitted().is_finite()) {
        return Err(SolveError::NotFinite { name: name.to_string(), channel: CHANNEL_NAMES[c] });
    }
    if s.iter().all(|s| s.emitted() <= 0.0) {
        return Err(SolveError::NothingEmits3 { name: name.to_string() });
    }
    Ok(s)
}

/// `solution`, or [`SolveError::NotFinite`] if a radiosity overflowed in some channel.
fn finite(solution: Solution3, name: &str) -> Result<Solution3, SolveError> {
    match (0..3).find(|&c| solution.channels[c].radiosity.iter().any(|b| !b.is_finite())) {
        Some(c) => Err(SolveError::NotFinite { name: name.to_string(), channel: CHANNEL_NAMES[c] }),
        None => Ok(solution),
    }
}

/// The full solve of `scene` (named `name` in errors) over its whole form-factor matrix `rows`
/// (row `j` is `F_j·`), Gauss–Seidel in each channel to `tolerance` of the relative residual.
pub fn full(
    scene: &Scene3,
    name: &str,
    rows: &[Row],
    tolerance: f64,
    max_steps: usize,
) -> Result<Solution3, SolveError> {
    solve::check_tolerance(tolerance)?;
    let [r, g, b] = check(scene, name)?;
    let n = scene.polygons.len();
    let one = |s: &Surfaces| match s.emitted() > 0.0 {
        true => solve::full(s, rows, tolerance, max_steps),
        false => Ok(dark(n)),
    };
    let solution = Solution3 { channels: [one(&r)?, one(&g)?, one(&b)?], rows: (0..rows.len()).collect() };
    finite(solution, name)
}

/// Progressive refinement of `scene` (named `name` in errors) in each channel, until the unshot
/// power is at most `tolerance` of the channel's emitted power; `row(i)` computes `F_i·` and is
/// called once per polygon that shoots. `max_steps` bounds each channel's shots.
pub fn progressive<E: From<SolveError>>(
    scene: &Scene3,
    name: &str,
    tolerance: f64,
    max_steps: usize,
    mut row: impl FnMut(usize) -> Result<Row, E>,
) -> Result<Solution3, E> {
    solve::check_tolerance(tolerance)?;
    let surfaces = check(scene, name)?;
    let n = scene.polygons.len();
    let mut kept: HashMap<usize, Row> = HashMap::new();
    let mut order = Vec::new();
    let mut solve = |s: &Surfaces| -> Result<Solution, E> {
        if s.emitted() <= 0.0 {
            return Ok(dark(n));
        }
        solve::progressive(s, tolerance, max_steps, |i| {
            if let Some(r) = kept.get(&i) {
                return Ok(r.clone());
            }
            let r = row(i)?;
            kept.insert(i, r.clone());
            order.push(i);
            Ok(r)
        })
    };
    let [r, g, b] = &surfaces;
    let channels = [solve(r)?, solve(g)?, solve(b)?];
    Ok(finite(Solution3 { channels, rows: order }, name)?)
}

/// The relative residual of the radiosity equation in every channel for `solution` against the
/// matrix `rows`: `Σ_j A_j |B_j − E_j − ρ_j Σ_i F_ji B_i|` over `Σ_j A_j B_j` (0 for a dark
/// channel). Applied to one solver's answer with another's matrix, it checks the two against
/// each other.
pub fn residual(scene: &Scene3, solution: &Solution3, rows: &[Row]) -> [f64; 3] {
    [0, 1, 2].map(|c| {
        let s = surfaces(scene, c);
        let b = &solution.channels[c].radiosity;
        let (mut residual, mut total) = (0.0, 0.0);
        for j in 0..s.len() {
            let h: f64 = rows[j].entries.iter().map(|e| e.ff * b[e.patch as usize]).sum();
            residual += s.length[j] * (b[j] - s.emission[j] - s.reflectance[j] * h).abs();
            total += s.length[j] * b[j];
        }
        if total > 0.0 {
            residual / total
        } else {
            0.0
        }
    })
}
