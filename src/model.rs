//! The analytic model of Section 4: intersection computation time of the shelling and the
//! conventional technique, shell by shell, and the speedup factor.
//!
//! Notation (the paper's): `R` rays and `P` patches in the first shell, `S` the fraction of rays
//! leaving any shell, `K = 1 − S` the fraction screened out (hit) in a shell, `T_λ` the pipeline
//! period of the intersection unit, `T_c` the arrival time of one patch (its load time from the
//! host on a shared-memory machine). Shell `i` (1-based) holds `i²P` patches and receives
//! `S^(i−1)·R` rays (Figure 6).

/// What is wrong with a model parameter.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModelError {
    #[error("S is a fraction of rays and must lie in [0, 1), got {0}")]
    BadS(f64),
    #[error("{name} must be a positive finite number, got {value}")]
    NotPositive { name: &'static str, value: f64 },
    #[error("the shell index i starts at 1, got 0")]
    ShellZero,
}

fn check_s(s: f64) -> Result<(), ModelError> {
    if (0.0..1.0).contains(&s) {
        Ok(())
    } else {
        Err(ModelError::BadS(s))
    }
}

fn positive(name: &'static str, value: f64) -> Result<(), ModelError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(ModelError::NotPositive { name, value })
    }
}

/// Eq. 4: `K₁(S) = (1 + S²) / (1 − S²)³` (Figure 7).
pub fn k1(s: f64) -> Result<f64, ModelError> {
    check_s(s)?;
    let x = s * s;
    Ok((1.0 + x) / (1.0 - x).powi(3))
}

/// Eq. 1 summed to `terms` shells: `Σ_{k<terms} (k+1)²·S^(2k)·R·P·T_λ`. Converges to Eq. 2.
pub fn t1_series(s: f64, r: f64, p: f64, t_lambda: f64, terms: usize) -> Result<f64, ModelError> {
    check_s(s)?;
    let x = s * s;
    let mut sum = 0.0;
    let mut xk = 1.0;
    for k in 0..terms {
        sum += ((k + 1) * (k + 1)) as f64 * xk;
        xk *= x;
    }
    Ok(sum * r * p * t_lambda)
}

/// Eqs. 2–3: `T₁ = K₁(S)·R·P·T_λ`, the shelling technique's total time when the bundle's
/// computation on one patch balances the arrival of the next.
pub fn t1(s: f64, r: f64, p: f64, t_lambda: f64) -> Result<f64, ModelError> {
    Ok(k1(s)? * r * p * t_lambda)
}

/// The per-shell quantities of Eqs. 5–11.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shell {
    /// Eq. 5: `ADLCᵢ = K·R / (i²·P)`.
    pub adlc: f64,
    /// Eq. 6: conventional technique's time in shell `i`.
    pub t2: f64,
    /// Eq. 7: shelling's time in shell `i` without subshells.
    pub t1: f64,
    /// Eq. 9: shelling's time in shell `i` with subshells of `ADLCᵢ` rays.
    pub t1_subshells: f64,
    /// `SFᵢ = T₂ᵢ / T₁ᵢ` with subshells (Eq. 10, evaluated from Eqs. 6 and 9).
    pub speedup: f64,
}

/// Evaluates Eqs. 5–10 for shell `i`.
///
/// The balance condition of Eqs. 9–10 is taken as `ADLCᵢ·T_λ > T_c`, as Eq. 9 writes it; Eq. 10
/// as printed drops the `i²` of `ADLCᵢ` (`(K R / P)·T_λ > T_c`), which agrees for `i = 1`.
pub fn shell(s: f64, r: f64, p: f64, i: u32, t_c: f64, t_lambda: f64) -> Result<Shell, ModelError> {
    check_s(s)?;
    positive("R", r)?;
    positive("P", p)?;
    positive("T_c", t_c)?;
    positive("T_lambda", t_lambda)?;
    if i == 0 {
        return Err(ModelError::ShellZero);
    }
    let k = 1.0 - s;
    let fi = i as f64;
    let i2p = fi * fi * p;
    let s_i1 = s.powi(i as i32 - 1);
    let adlc = k * r / i2p;
    let t2 = if adlc > 1.0 { (s_i1 * s * i2p + s_i1 * k * r) * t_c } else { s_i1 * i2p * t_c };
    let t1 = if s_i1 * r * t_lambda > t_c { s_i1 * s_i1 * r * i2p * t_lambda } else { s_i1 * i2p * t_c };
    let t1_subshells = if adlc * t_lambda > t_c { k * s_i1 * r * t_lambda } else { s_i1 * i2p * t_c };
    Ok(Shell { adlc, t2, t1, t1_subshells, speedup: t2 / t1_subshells })
}

/// Eq. 10 in closed form: `SFᵢ = (1 + S/ADLCᵢ)·T_c/T_λ` when one patch's computation outlasts
/// the next patch's arrival, `S + ADLCᵢ` otherwise. Valid where `ADLCᵢ > 1`.
pub fn speedup(s: f64, adlc_i: f64, t_c: f64, t_lambda: f64) -> Result<f64, ModelError> {
    check_s(s)?;
    positive("ADLC_i", adlc_i)?;
    positive("T_c", t_c)?;
    positive("T_lambda", t_lambda)?;
    Ok(if adlc_i * t_lambda > t_c { (1.0 + s / adlc_i) * t_c / t_lambda } else { s + adlc_i })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn k1_closed_form_matches_the_series() {
        for &s in &[0.0, 0.1, 0.5, 0.8, 0.9] {
            let closed = t1(s, 100.0, 10.0, 1.0).unwrap();
            let series = t1_series(s, 100.0, 10.0, 1.0, 2000).unwrap();
            assert!((closed - series).abs() <= 1e-9 * closed, "S = {s}: {closed} vs {series}");
        }
        assert_eq!(k1(0.0).unwrap(), 1.0);
        assert!(k1(1.0).is_err());
        assert!(k1(-0.1).is_err());
        assert!(k1(f64::NAN).is_err());
    }

    #[test]
    fn eq10_agrees_with_eqs_6_and_9() {
        for &(s, r, p, i, tc, tl) in &[
            (0.3, 1024.0, 20.0, 1, 16.0, 1.0),
            (0.3, 1024.0, 20.0, 2, 16.0, 1.0),
            (0.5, 1024.0, 50.0, 1, 64.0, 1.0),
            (0.1, 512.0, 5.0, 3, 4.0, 1.0),
        ] {
            let sh = shell(s, r, p, i, tc, tl).unwrap();
            if sh.adlc > 1.0 {
                let closed = speedup(s, sh.adlc, tc, tl).unwrap();
                assert!((closed - sh.speedup).abs() < 1e-9 * closed, "{closed} vs {}", sh.speedup);
            }
        }
    }

    #[test]
    fn optimum_speedups_of_eq11() {
        // S = 0: SF = T_c / T_λ when balanced, ADLC otherwise.
        assert_eq!(speedup(0.0, 100.0, 16.0, 1.0).unwrap(), 16.0);
        assert_eq!(speedup(0.0, 8.0, 16.0, 1.0).unwrap(), 8.0);
    }
}
