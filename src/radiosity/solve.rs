//! Radiosity solvers: progressive refinement and a full Gauss–Seidel solve.
//!
//! The radiosity `B_j` of patch `j` (radiant exitance, power per unit length) solves
//!
//! ```text
//! B_j = E_j + ρ_j H_j,    H_j = Σ_i F_ji B_i   (the irradiance of j)
//! ```
//!
//! with `E_j` the emission and `ρ_j` the reflectance. Power is radiosity times length.
//!
//! * [`progressive`] (Cohen, Chen, Wallace, Greenberg 1988) keeps each patch's unshot radiosity
//!   `ΔB`, starting at `E`. Each step shoots the patch `i` of greatest unshot power `ΔB_i L_i`:
//!   one form-factor row `F_i·`, and by reciprocity (`L_j F_ji = L_i F_ij`) every patch `j`
//!   receives `ΔB_i F_ij L_i / L_j` and reflects `ρ_j` of it into its `B_j` and `ΔB_j`. It stops
//!   when the unshot power is at most `tolerance` of the emitted power. It holds one row at a
//!   time: `O(N)` memory. Power is conserved exactly whenever the rows sum to 1: emitted =
//!   absorbed + unshot.
//! * [`full`] gathers over the whole sparse matrix, each patch from its own row (`H_j` from
//!   `F_j·`), Gauss–Seidel, until the residual `Σ_j L_j |B_j − E_j − ρ_j H_j|` is at most
//!   `tolerance` of `Σ_j L_j B_j`.
//!
//! The two agree up to the tolerances and the form factors' reciprocity error.

use super::form_factors::Row;
use crate::scene::Scene;

/// What the solvers know of each patch.
#[derive(Clone, Debug, PartialEq)]
pub struct Surfaces {
    pub length: Vec<f64>,
    pub reflectance: Vec<f64>,
    pub emission: Vec<f64>,
}

/// Why a solve cannot run or did not finish.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SolveError {
    #[error("{name}: nothing in the scene emits: give at least one segment an \"emission\" above 0")]
    NothingEmits { name: String },
    #[error("--tolerance must be a number in [1e-12, 1), got {0}")]
    BadTolerance(f64),
    #[error(
        "the solve did not reach the tolerance in {steps} steps (the --max-steps limit); {left:.3e} is left"
    )]
    NotConverged { steps: usize, left: f64 },
    #[error("the form-factor matrix has rows for {rows} patches, the scene has {patches}")]
    WrongSize { rows: usize, patches: usize },
    #[error(
        "{name}: nothing in the scene emits: every material's Ke is 0 in all three channels; \
         give the material of at least one polygon a Ke above 0"
    )]
    NothingEmits3 { name: String },
    #[error(
        "{name}: material \"{material}\" has Kd {kd} in the {channel} channel; radiosity needs every \
         channel of Kd below 1 (a surface of reflectance 1 absorbs nothing, so the light of a \
         closed scene never dies out)"
    )]
    ReflectsAll { name: String, material: String, channel: &'static str, kd: f64 },
    #[error(
        "{name}: the power in the {channel} channel is not a finite number (Ke times the \
         polygons' areas, or the radiosity it builds up, overflows f64); scale the scene or its Ke down"
    )]
    NotFinite { name: String, channel: &'static str },
}

/// The smallest tolerance accepted.
pub const MIN_TOLERANCE: f64 = 1e-12;

impl Surfaces {
    /// The patches of `scene` (named `name` in errors); an error when nothing emits.
    pub fn of(scene: &Scene, name: &str) -> Result<Surfaces, SolveError> {
        let n = scene.len();
        let s = Surfaces {
            length: scene.segments.iter().map(|s| s.length()).collect(),
            reflectance: (0..n).map(|i| scene.material(i).reflectance_or_default()).collect(),
            emission: (0..n).map(|i| scene.material(i).emission_or_default()).collect(),
        };
        if s.emitted() <= 0.0 {
            return Err(SolveError::NothingEmits { name: name.to_string() });
        }
        Ok(s)
    }

    pub fn len(&self) -> usize {
        self.length.len()
    }

    pub fn is_empty(&self) -> bool {
        self.length.is_empty()
    }

    /// `Σ E_j L_j`.
    pub fn emitted(&self) -> f64 {
        self.emission.iter().zip(&self.length).map(|(e, l)| e * l).sum()
    }
}

/// The result of a solve.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Solution {
    /// `B_j` of every patch.
    pub radiosity: Vec<f64>,
    /// Shots (progressive) or sweeps (full).
    pub steps: usize,
    /// What is left when it stopped, as a fraction: the unshot power over the emitted power
    /// (progressive), the relative residual (full).
    pub unshot: f64,
    /// That fraction after each step: the convergence curve.
    pub history: Vec<f64>,
    /// `Σ E_j L_j`.
    pub emitted: f64,
    /// `Σ (1 − ρ_j) H_j L_j`: the power the patches absorb.
    pub absorbed: f64,
    /// The power that leaves the scene (rays that hit nothing; zero in a closed room):
    /// progressive, `Σ` over shots of the shot power times `1 − Σ_j F_ij`; full,
    /// `Σ_i L_i B_i (1 − Σ_j F_ij)`. Emitted = absorbed + escaped (+ unshot) up to the
    /// reciprocity error of the rows.
    pub escaped: f64,
    /// The sources of the rows computed, in order (progressive: one per step; full: every
    /// patch once).
    pub rows: Vec<usize>,
}

/// `tolerance` within `[MIN_TOLERANCE, 1)`, the range both solvers accept.
pub fn check_tolerance(t: f64) -> Result<(), SolveError> {
    if (MIN_TOLERANCE..1.0).contains(&t) {
        Ok(())
    } else {
        Err(SolveError::BadTolerance(t))
    }
}

/// Progressive refinement: `row(i)` computes `F_i·` when patch `i` shoots.
pub fn progressive<E: From<SolveError>>(
    s: &Surfaces,
    tolerance: f64,
    max_steps: usize,
    mut row: impl FnMut(usize) -> Result<Row, E>,
) -> Result<Solution, E> {
    check_tolerance(tolerance)?;
    let n = s.len();
    let emitted = s.emitted();
    let mut b = s.emission.clone();
    let mut unshot = s.emission.clone();
    let mut left = emitted;
    let mut absorbed = 0.0;
    let mut escaped = 0.0;
    let mut history = Vec::new();
    let mut rows = Vec::new();
    while left > tolerance * emitted {
        if rows.len() == max_steps {
            return Err(SolveError::NotConverged { steps: max_steps, left: left / emitted }.into());
        }
        let i = (0..n)
            .max_by(|&x, &y| (unshot[x] * s.length[x]).total_cmp(&(unshot[y] * s.length[y])))
            .expect("a scene has patches");
        let shot = unshot[i];
        unshot[i] = 0.0;
        let power = shot * s.length[i];
        let row = row(i)?;
        escaped += power * (1.0 - row.sum());
        for e in row.entries {
            let j = e.patch as usize;
            let received = power * e.ff; // power arriving at j
            absorbed += (1.0 - s.reflectance[j]) * received;
            let db = s.reflectance[j] * received / s.length[j];
            b[j] += db;
            unshot[j] += db;
        }
        rows.push(i);
        // Summed afresh each step, so rounding does not drift.
        left = unshot.iter().zip(&s.length).map(|(u, l)| u * l).sum();
        history.push(left / emitted);
    }
    Ok(Solution {
        radiosity: b,
        steps: rows.len(),
        unshot: left / emitted,
        history,
        emitted,
        absorbed,
        escaped,
        rows,
    })
}

/// The full solve over the form-factor matrix `rows` (row `j` is `F_j·`), Gauss–Seidel.
pub fn full(s: &Surfaces, rows: &[Row], tolerance: f64, max_steps: usize) -> Result<Solution, SolveError> {
    check_tolerance(tolerance)?;
    if rows.len() != s.len() {
        return Err(SolveError::WrongSize { rows: rows.len(), patches: s.len() });
    }
    let emitted = s.emitted();
    let gather =
        |b: &[f64], j: usize| rows[j].entries.iter().map(|e| e.ff * b[e.patch as usize]).sum::<f64>();
    let mut b = s.emission.clone();
    let mut history = Vec::new();
    loop {
        for j in 0..s.len() {
            b[j] = s.emission[j] + s.reflectance[j] * gather(&b, j);
        }
        let (mut residual, mut total) = (0.0, 0.0);
        for j in 0..s.len() {
            residual += s.length[j] * (b[j] - s.emission[j] - s.reflectance[j] * gather(&b, j)).abs();
            total += s.length[j] * b[j];
        }
        let relative = residual / total;
        history.push(relative);
        if relative <= tolerance {
            break;
        }
        if history.len() == max_steps {
            return Err(SolveError::NotConverged { steps: max_steps, left: relative });
        }
    }
    let absorbed = (0..s.len()).map(|j| (1.0 - s.reflectance[j]) * gather(&b, j) * s.length[j]).sum::<f64>();
    let escaped = (0..s.len()).map(|i| s.length[i] * b[i] * (1.0 - rows[i].sum())).sum::<f64>();
    Ok(Solution {
        radiosity: b,
        steps: history.len(),
        unshot: *history.last().expect("one sweep at least"),
        history,
        emitted,
        absorbed,
        escaped,
        rows: (0..s.len()).collect(),
    })
}
