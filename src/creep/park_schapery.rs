//! Park & Schapery's approximate relaxation → creep conversion, as written in the seed thesis
//! (§2.2, eq. 2.18–2.23; S. W. Park and R. A. Schapery, Int. J. Solids Struct. 36 (1999) 1653–1675).
//! Kept as the seed-faithful option to compare with the exact conversion of [`super::exact`].
//!
//! Input: [`RelaxationSpectrum`] + [`ParkSchaperySettings`]; output: [`CreepSpectrum`] +
//! [`ParkSchaperyInfo`] (condition number, negative terms).
//!
//! The retardation times τⱼ are chosen beforehand (by default τⱼ = ρⱼ, the relaxation times: the case
//! ρᵢ = τⱼ of eq. 2.19 then occurs for i = j), J_g = 1/E₀ (eq. 2.20), and the strengths solve
//! A·J = B (eq. 2.21) with, at times t_k,
//!
//! ```text
//! A_kj = E∞(1 − e^(−t_k/τⱼ)) + Σᵢ Eᵢ ρᵢ/(ρᵢ − τⱼ) (e^(−t_k/ρᵢ) − e^(−t_k/τⱼ))   (eq. 2.22, ρᵢ ≠ τⱼ)
//!      the i-th term being Eᵢ (t_k/τⱼ) e^(−t_k/ρᵢ) when ρᵢ = τⱼ                    (eq. 2.19/2.22)
//! B_k  = 1 − E(t_k)/E₀                                                             (eq. 2.23)
//! ```
//!
//! Variants: collocation at t_k = a·τ_k with a = 1 or a = 1/2 (square system), or least squares at
//! t_k equidistant in log t (more rows than unknowns; thesis, end of §2.2).
//!
//! Numerics (where we leave the printed formula): the i-th term of A_kj is evaluated as
//! Eᵢ v e^(−u)(1 − e^(−(v−u)))/(v − u) with u = t/ρᵢ, v = t/τⱼ (expm1 when |v − u| < 1), which is
//! eq. 2.22 without cancellation and tends continuously to eq. 2.19 as ρᵢ → τⱼ; B_k is
//! Σ Eᵢ(1 − e^(−t_k/ρᵢ))/E₀ (expm1), not 1 − E/E₀. The columns of A are scaled to unit norm before the
//! solve (LU for collocation, SVD for least squares); the reported condition number is that of the
//! scaled matrix, which does not depend on units. A system with condition number ≥ 1/ε is refused
//! ([`CreepError::SingularSystem`]): its solution would be rounding noise.
//!
//! Why and where it breaks down: the exact retardation times interlace the relaxation times, and the
//! longest exceeds the longest relaxation time (by a factor up to E₀/E∞, ≈ 10³ for rubber); with
//! τⱼ = ρⱼ this longest time is missing, so J(t) is fitted with the wrong exponentials. Collocation
//! then matches J exactly only at the t_k and compensates in between with strengths of both signs
//! (negative Jⱼ: a non-physical, non-monotone creep function); densely spaced times (≥ 2 per decade)
//! make neighbouring columns nearly parallel, the condition number grows by orders of magnitude per
//! added term, and rounding is amplified into the strengths. See `examples/park_schapery_table.rs`.

use super::error::CreepError;
use super::{CreepSpectrum, RetardationTerm};
use crate::material::MaterialError;
use crate::prony::RelaxationSpectrum;
use nalgebra::{DMatrix, DVector};
use serde::{Deserialize, Serialize};

/// How the collocation times are chosen (thesis, end of §2.2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum ParkSchaperyVariant {
    /// Collocation at t_k = τ_k (a = 1).
    #[default]
    #[serde(rename = "collocation-1")]
    CollocationOne,
    /// Collocation at t_k = τ_k/2 (a = 1/2).
    #[serde(rename = "collocation-half")]
    CollocationHalf,
    /// Least squares at times equidistant in log t.
    LeastSquares,
}

impl ParkSchaperyVariant {
    /// The name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            ParkSchaperyVariant::CollocationOne => "collocation-1",
            ParkSchaperyVariant::CollocationHalf => "collocation-half",
            ParkSchaperyVariant::LeastSquares => "least-squares",
        }
    }
}

/// Settings of [`park_schapery`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ParkSchaperySettings {
    /// Collocation or least squares.
    pub variant: ParkSchaperyVariant,
    /// Retardation times τⱼ in s; None: the relaxation times ρᵢ (the thesis' choice, eq. 2.19 case).
    pub retardation_times_s: Option<Vec<f64>>,
    /// Least squares: sample times per decade of t (default 4, i.e. 2–4 rows per unknown for 1–2
    /// times per decade), over [min τⱼ/10, 10·max τⱼ].
    pub least_squares_points_per_decade: f64,
}

impl Default for ParkSchaperySettings {
    fn default() -> Self {
        ParkSchaperySettings {
            variant: ParkSchaperyVariant::CollocationOne,
            retardation_times_s: None,
            least_squares_points_per_decade: 4.0,
        }
    }
}

/// Diagnostics of a Park & Schapery conversion.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ParkSchaperyInfo {
    /// The variant used.
    pub variant: ParkSchaperyVariant,
    /// Rows (collocation times) of A.
    pub rows: usize,
    /// Columns (retardation times) of A.
    pub cols: usize,
    /// 2-norm condition number of A with unit-norm columns.
    pub condition_number: f64,
    /// Number of strengths Jⱼ < 0 in the result (non-physical).
    pub negative_terms: usize,
    /// RMS of (A·J − B) over the rows (0 for collocation up to rounding).
    pub residual_rms: f64,
}

/// The i-th term of A_kj without the strength Eᵢ: ρ/(ρ−τ)(e^(−t/ρ) − e^(−t/τ)) (eq. 2.22), with the
/// limit (t/τ)e^(−t/ρ) at ρ = τ (eq. 2.19).
pub fn kernel(t: f64, rho: f64, tau: f64) -> f64 {
    let u = t / rho;
    let v = t / tau;
    let d = v - u;
    if d.abs() < 1.0 {
        // (e^(−u) − e^(−v))/(v − u) = e^(−u)(1 − e^(−d))/d; (1 − e^(−d))/d → 1 as d → 0.
        let ratio = if d == 0.0 { 1.0 } else { -(-d).exp_m1() / d };
        v * (-u).exp() * ratio
    } else {
        v * ((-u).exp() - (-v).exp()) / d
    }
}

/// The retardation times ρⱼ, ascending and without repeats: the user's (each checked finite and > 0),
/// or else the relaxation times of the terms with positive strength.
fn retardation_times(
    relax: &RelaxationSpectrum,
    settings: &ParkSchaperySettings,
) -> Result<Vec<f64>, CreepError> {
    let mut taus: Vec<f64> = match &settings.retardation_times_s {
        Some(v) => {
            for (i, &t) in v.iter().enumerate() {
                if !(t.is_finite() && t > 0.0) {
                    return Err(MaterialError::InvalidValue {
                        field: format!("retardation_times_s[{i}]"),
                        value: t,
                        expected: "a finite time > 0 in s",
                    }
                    .into());
                }
            }
            v.clone()
        }
        None => relax
            .terms
            .iter()
            .filter(|t| t.modulus_pa > 0.0)
            .map(|t| t.tau_s)
            .collect(),
    };
    taus.sort_by(f64::total_cmp);
    taus.dedup();
    Ok(taus)
}

/// The times t_k the equations are written at: t = ρ, t = ρ/2, or a log grid from a decade below the
/// shortest to a decade above the longest ρ with at least two rows per unknown (least squares).
fn collocation_times(
    taus: &[f64],
    settings: &ParkSchaperySettings,
) -> Result<Vec<f64>, CreepError> {
    Ok(match settings.variant {
        ParkSchaperyVariant::CollocationOne => taus.to_vec(),
        ParkSchaperyVariant::CollocationHalf => taus.iter().map(|t| 0.5 * t).collect(),
        ParkSchaperyVariant::LeastSquares => {
            let ppd = settings.least_squares_points_per_decade;
            if !(ppd.is_finite() && ppd > 0.0) {
                return Err(CreepError::InvalidSetting {
                    setting: "least_squares_points_per_decade",
                    reason: format!("{ppd} is not a positive number"),
                });
            }
            let lo = taus[0].log10() - 1.0;
            let hi = taus[taus.len() - 1].log10() + 1.0;
            let n = (((hi - lo) * ppd).ceil() as usize + 1).max(2 * taus.len());
            (0..n)
                .map(|k| 10f64.powf(lo + (hi - lo) * k as f64 / (n - 1) as f64))
                .collect()
        }
    })
}

/// The linear system A·J = B at the times t_k for the retardation times ρⱼ (eq. 2.22, 2.23).
fn system(
    relax: &RelaxationSpectrum,
    times: &[f64],
    taus: &[f64],
    e0: f64,
) -> (DMatrix<f64>, DVector<f64>) {
    let (p, n) = (times.len(), taus.len());
    let mut a = DMatrix::<f64>::zeros(p, n);
    let mut b = DVector::<f64>::zeros(p);
    for (k, &t) in times.iter().enumerate() {
        for (j, &tau) in taus.iter().enumerate() {
            // eq. 2.22
            let mut v = -relax.modulus_inf_pa * (-t / tau).exp_m1();
            for r in &relax.terms {
                v += r.modulus_pa * kernel(t, r.tau_s, tau);
            }
            a[(k, j)] = v;
        }
        // eq. 2.23, as Σ Eᵢ(1 − e^(−t/ρᵢ))/E₀
        b[k] = relax
            .terms
            .iter()
            .map(|r| -r.modulus_pa * (-t / r.tau_s).exp_m1())
            .sum::<f64>()
            / e0;
    }
    (a, b)
}

/// Solve A·J = B with unit-norm columns (LU when square, SVD least squares otherwise): the strengths
/// Jⱼ and the condition number of the scaled A. A numerically singular system (condition ≥ 1/ε) or
/// a non-finite solution is refused.
fn solve_scaled(a: &DMatrix<f64>, b: &DVector<f64>) -> Result<(Vec<f64>, f64), CreepError> {
    let (p, n) = (a.nrows(), a.ncols());
    let scales: Vec<f64> = (0..n).map(|j| a.column(j).norm()).collect();
    let mut a_s = a.clone();
    for (j, &s) in scales.iter().enumerate() {
        if s > 0.0 {
            a_s.column_mut(j).scale_mut(1.0 / s);
        }
    }
    let sv = a_s.clone().svd(true, true);
    let smax = sv.singular_values.max();
    let smin = sv.singular_values.min();
    let condition = if smin > 0.0 {
        smax / smin
    } else {
        f64::INFINITY
    };
    let singular = || CreepError::SingularSystem {
        rows: p,
        cols: n,
        condition,
    };
    // Numerically singular (condition ≥ 1/ε): any solution would be rounding noise; refuse.
    if condition.is_nan() || condition >= 1.0 / f64::EPSILON {
        return Err(singular());
    }
    let y = if p == n {
        a_s.clone().lu().solve(b).ok_or_else(singular)?
    } else {
        sv.solve(b, 0.0).map_err(|_| singular())?
    };
    if y.iter().any(|v| !v.is_finite()) {
        return Err(singular());
    }
    Ok(((0..n).map(|j| y[j] / scales[j]).collect(), condition))
}

/// Park & Schapery's conversion (eq. 2.18–2.23). The result may hold negative strengths (counted in
/// the info): that is the method's behaviour, reported rather than hidden.
pub fn park_schapery(
    relax: &RelaxationSpectrum,
    settings: &ParkSchaperySettings,
) -> Result<(CreepSpectrum, ParkSchaperyInfo), CreepError> {
    relax.validate()?;
    if relax.modulus_inf_pa == 0.0 {
        let viscosity_pa_s = relax.terms.iter().map(|t| t.modulus_pa * t.tau_s).sum();
        return Err(CreepError::Fluid { viscosity_pa_s });
    }
    let taus = retardation_times(relax, settings)?;
    let e0 = relax.instantaneous_modulus();
    let jg = 1.0 / e0; // eq. 2.20
    if taus.is_empty() {
        return Ok((
            CreepSpectrum {
                kind: relax.kind,
                poisson: relax.poisson,
                compliance_glassy_per_pa: jg,
                terms: vec![],
            },
            ParkSchaperyInfo {
                variant: settings.variant,
                rows: 0,
                cols: 0,
                condition_number: 1.0,
                negative_terms: 0,
                residual_rms: 0.0,
            },
        ));
    }
    let times = collocation_times(&taus, settings)?;
    let (p, n) = (times.len(), taus.len());
    let (a, b) = system(relax, &times, &taus, e0);
    let (jj, condition) = solve_scaled(&a, &b)?;
    let res = &a * DVector::from_vec(jj.clone()) - &b;
    let residual_rms = (res.norm_squared() / p as f64).sqrt();
    let mut terms: Vec<RetardationTerm> = taus
        .iter()
        .zip(&jj)
        .map(|(&tau, &j)| RetardationTerm {
            compliance_per_pa: j,
            tau_s: tau,
        })
        .collect();
    terms.sort_by(|x, y| y.tau_s.total_cmp(&x.tau_s));
    let negative_terms = terms.iter().filter(|t| t.compliance_per_pa < 0.0).count();
    Ok((
        CreepSpectrum {
            kind: relax.kind,
            poisson: relax.poisson,
            compliance_glassy_per_pa: jg,
            terms,
        },
        ParkSchaperyInfo {
            variant: settings.variant,
            rows: p,
            cols: n,
            condition_number: condition,
            negative_terms,
            residual_rms,
        },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::creep::relaxation_to_creep;
    use crate::material::ModulusKind;
    use crate::prony::RelaxationTerm;

    #[test]
    fn kernel_tends_to_eq_2_19_and_matches_eq_2_22() {
        let (t, rho) = (0.7, 2.0);
        let at_equal = kernel(t, rho, rho);
        let eq_2_19 = t / rho * (-t / rho).exp();
        assert!((at_equal / eq_2_19 - 1.0).abs() < 1e-15);
        // ρ ≠ τ: eq. 2.22 written as printed (no cancellation issue at these values).
        let tau = 0.5;
        let printed = rho / (rho - tau) * ((-t / rho).exp() - (-t / tau).exp());
        assert!((kernel(t, rho, tau) / printed - 1.0).abs() < 1e-14);
        // Continuity across ρ = τ: relative change ~ the relative perturbation.
        let near = kernel(t, rho, rho * (1.0 + 1e-9));
        assert!((near / at_equal - 1.0).abs() < 1e-8);
    }

    #[test]
    fn collocation_satisfies_its_equations_and_least_squares_is_close_for_one_term() {
        // With the exact retardation time given, one term is represented exactly by every variant.
        let relax = RelaxationSpectrum {
            kind: ModulusKind::Tensile,
            poisson: 0.5,
            modulus_inf_pa: 1e6,
            terms: vec![RelaxationTerm {
                modulus_pa: 9e6,
                tau_s: 1e-3,
            }],
        };
        let (exact, _) = relaxation_to_creep(&relax).unwrap();
        for variant in [
            ParkSchaperyVariant::CollocationOne,
            ParkSchaperyVariant::CollocationHalf,
            ParkSchaperyVariant::LeastSquares,
        ] {
            let settings = ParkSchaperySettings {
                variant,
                retardation_times_s: Some(vec![exact.terms[0].tau_s]),
                ..Default::default()
            };
            let (c, info) = park_schapery(&relax, &settings).unwrap();
            assert_eq!(info.negative_terms, 0);
            // Exact representable: strength to rounding amplified by a 1-column system.
            let rel = c.terms[0].compliance_per_pa / exact.terms[0].compliance_per_pa - 1.0;
            assert!(rel.abs() < 1e-12, "{variant:?}: {rel:e}");
        }
        // With τ = ρ (the default), the single term cannot be right: J∞ misses 1/E∞.
        let (c, _) = park_schapery(&relax, &ParkSchaperySettings::default()).unwrap();
        assert!((c.compliance_relaxed() * 1e6 - 1.0).abs() > 0.1);
    }
}
