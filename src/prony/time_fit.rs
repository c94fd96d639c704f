//! The Prony fit in time (docs/MATH.md §18): reduced relaxation points E(t) → [`PronyFit`], and the
//! retardation series of creep points J(t) → [`TimeSeries`] (which `crate::creep::time_fit` turns
//! into a relaxation spectrum by the exact interconversion).
//!
//! The same non-negative, regularised QP as the frequency fit ([`super::fit`], MATH §5), with its
//! design matrix built from the time-domain basis (eq. 18.1–18.2): with the scale S = max_k y_k and
//! unknowns x ≥ 0 (x₀ the constant E∞/S or J_g/S, x_j the strengths over S, and for creep a last
//! column x_f = S⁻¹/η₀ in 1/s), the relative residuals are
//!
//! ```text
//!   relaxation:  r_k = (x₀ + Σ_j x_j e^(−t_k/τ_j)) · S/y_k − 1
//!   creep:       r_k = (x₀ + Σ_j x_j (1 − e^(−t_k/λ_j))) · S/y_k − 1
//! ```
//!
//! The time grid is the frequency fit's ([`super::relaxation_times_s`] with f = 1/(2πt)): log-spaced
//! from t_min·10^(−margin) to t_max·10^(margin), `terms_per_decade` per decade; the weight λ is chosen
//! by the settings' rule over the same grid (GCV by default), terms below `drop_threshold` are
//! dropped. The term reduction of the frequency fit is not applied (the dense fit is kept).
//!
//! No flow term t/η₀ is fitted: within a finite window it cannot be told from a retardation time
//! beyond the window (Jⱼ(1 − e^(−t/λⱼ)) = (Jⱼ/λⱼ) t (1 + O(t/λⱼ)) for λⱼ ≫ t_max), and the grid reaches
//! 10^margin beyond t_max. With it in the QP a known solid's creep (tests) came out 34 % "flow".
//!
//! What a time window determines: E(t) on [t_min, t_max] fixes the relaxation times inside it; the
//! dynamic moduli follow from them for ω within [1/t_max, 1/t_min] (eq. 18.3). Outside it E″ comes
//! from terms the data never saw, so [`PronyInfo::freq_window_hz`] is that window and the stages
//! after flag frequencies beyond it as extrapolated, like those beyond a master curve's window.

use super::fit::{relaxation_times_s, solve_weights, Problem};
use super::{PronyError, PronyFit, PronyInfo, PronySettings, RelaxationSpectrum, RelaxationTerm};
use crate::material::ModulusKind;
use nalgebra::{DMatrix, DVector};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// One reduced time-domain point: time (s) and E(t) (Pa) or J(t) (1/Pa).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TimeDatum {
    /// Reduced time t/a_T, s.
    pub time_s: f64,
    /// The modulus (Pa) or compliance (1/Pa), reduced.
    pub value: f64,
}

/// Which series is fitted.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TimeBasis {
    /// E(t) = E∞ + Σ Eᵢ e^(−t/τᵢ) (eq. 18.1).
    Relaxation,
    /// J(t) = J_g + Σ Jⱼ (1 − e^(−t/λⱼ)) (eq. 18.2).
    Retardation,
}

/// How a time-domain fit went (saved in [`PronyInfo::time_domain`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TimeFitInfo {
    /// The function fitted: `E(t)`, `G(t)`, `D(t)` or `J(t)`.
    pub function: String,
    /// RMS over the points of log10(fit/datum) of that function.
    pub rms_log10: f64,
    /// Largest |log10(fit/datum)|.
    pub max_abs_log10: f64,
    /// Reduced time window of the data, s.
    pub time_window_s: [f64; 2],
    /// Terms on the grid and kept (retardation terms for creep).
    pub n_terms_grid: usize,
    /// Terms kept.
    pub n_terms_kept: usize,
    /// Creep: the slope d log J / d log t over the last decade of the data (1 for a fluid's flow).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub end_slope: Option<f64>,
    /// What was done on the way (flow dropped, conversion to relaxation, …).
    pub notes: Vec<String>,
}

/// A fitted time series: the constant (E∞ or J_g) and the terms (time, strength).
#[derive(Debug, Clone, PartialEq)]
pub struct TimeSeries {
    /// E∞ (Pa) or J_g (1/Pa).
    pub constant: f64,
    /// (τ or λ in s, strength in Pa or 1/Pa), increasing in time.
    pub terms: Vec<(f64, f64)>,
    /// The weight λ, solver status, iterations, the λ search, grid (for [`PronyInfo`]).
    pub lambda: f64,
    /// The solver's status.
    pub solver_status: String,
    /// Iterations of the chosen solve and of all solves.
    pub iterations: (u32, u32),
    /// The λ candidates tried.
    pub lambda_search: Vec<super::LambdaCandidate>,
    /// The time grid, s.
    pub taus: Vec<f64>,
    /// The scale S.
    pub scale: f64,
    /// Points fitted.
    pub n_points: usize,
}

impl TimeSeries {
    /// The series at `t_s`.
    pub fn at(&self, t_s: f64, basis: TimeBasis) -> f64 {
        let sum: f64 = self
            .terms
            .iter()
            .map(|&(tau, s)| match basis {
                TimeBasis::Relaxation => s * (-t_s / tau).exp(),
                TimeBasis::Retardation => s * -(-t_s / tau).exp_m1(),
            })
            .sum();
        self.constant + sum
    }
}

/// RMS and largest |log10(fit/datum)| of `f` over `points`.
pub(crate) fn time_errors(points: &[TimeDatum], f: impl Fn(f64) -> f64) -> (f64, f64) {
    let e: Vec<f64> = points
        .iter()
        .map(|p| (f(p.time_s) / p.value).log10())
        .collect();
    let rms = (e.iter().map(|v| v * v).sum::<f64>() / e.len().max(1) as f64).sqrt();
    let max = e.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    (rms, max)
}

/// Fit the series of `basis` to `points` (module docs; eq. 18.1–18.2), non-negatively.
pub(crate) fn fit_series_in_time(
    points: &[TimeDatum],
    basis: TimeBasis,
    settings: &PronySettings,
) -> Result<TimeSeries, PronyError> {
    settings.validate()?;
    check(points)?;
    let (t_min, t_max) = window(points)?;
    let taus = relaxation_times_s(1.0 / (2.0 * PI * t_max), 1.0 / (2.0 * PI * t_min), settings);
    crate::limits::at_most(
        "terms_per_decade × decades of the time window (terms)",
        taus.len(),
        crate::limits::PRONY_TERMS_MAX,
    )?;
    let scale = points.iter().map(|p| p.value).fold(0.0, f64::max);
    let (m, n) = (points.len(), taus.len());
    let mut a = DMatrix::<f64>::zeros(m, n + 1);
    for (k, p) in points.iter().enumerate() {
        let s = scale / p.value;
        a[(k, 0)] = s;
        for (j, &tau) in taus.iter().enumerate() {
            a[(k, j + 1)] = s * match basis {
                TimeBasis::Relaxation => (-p.time_s / tau).exp(),
                TimeBasis::Retardation => -(-p.time_s / tau).exp_m1(),
            };
        }
    }
    let problem = Problem::from_design(a, DVector::from_element(m, 1.0), n);
    let (lambda, solution, search, total) = solve_weights(&problem, settings)?;
    let x = &solution.x;
    let kept = |col: usize| x[col].max(0.0) * problem.col_max[col] >= settings.drop_threshold;
    let terms = (0..n)
        .filter(|&j| kept(j + 1))
        .map(|j| (taus[j], x[j + 1].max(0.0) * scale))
        .collect();
    Ok(TimeSeries {
        constant: x[0].max(0.0) * scale,
        terms,
        lambda,
        solver_status: format!("{:?}", solution.status),
        iterations: (solution.iterations, total),
        lambda_search: search,
        taus,
        scale,
        n_points: m,
    })
}

/// Fit E(t) = E∞ + Σ Eᵢ e^(−t/τᵢ) to reduced relaxation points (eq. 18.1) → the same [`PronyFit`]
/// the frequency fit hands on. `function` names the data (`E(t)` or `G(t)`) in the info.
pub(crate) fn fit_relaxation_in_time(
    points: &[TimeDatum],
    kind: ModulusKind,
    poisson: f64,
    settings: &PronySettings,
    function: &str,
) -> Result<PronyFit, PronyError> {
    let series = fit_series_in_time(points, TimeBasis::Relaxation, settings)?;
    let spectrum = RelaxationSpectrum {
        kind,
        poisson,
        modulus_inf_pa: series.constant,
        terms: series
            .terms
            .iter()
            .map(|&(tau_s, modulus_pa)| RelaxationTerm { modulus_pa, tau_s })
            .collect(),
    };
    let errs = time_errors(points, |t| spectrum.relaxation_modulus(t));
    let td = TimeFitInfo::new(function, points, &series, errs, None, Vec::new());
    let info = time_info(&series, settings, spectrum.terms.len(), td);
    Ok(PronyFit { spectrum, info })
}

impl TimeFitInfo {
    /// The info of a fit of `series` to `points`, with the errors `(rms, max)` of `function`.
    pub fn new(
        function: &str,
        points: &[TimeDatum],
        series: &TimeSeries,
        (rms, max): (f64, f64),
        end_slope: Option<f64>,
        notes: Vec<String>,
    ) -> Self {
        let (t_min, t_max) = window(points).unwrap_or((f64::NAN, f64::NAN));
        Self {
            function: function.to_string(),
            rms_log10: rms,
            max_abs_log10: max,
            time_window_s: [t_min, t_max],
            n_terms_grid: series.taus.len(),
            n_terms_kept: series.terms.len(),
            end_slope,
            notes,
        }
    }
}

/// The [`PronyInfo`] of a time-domain fit with `n_terms_kept` relaxation terms: its E′ and E″ error
/// fields hold the time function's errors (there are no E′, E″ data), `freq_window_hz` the window the
/// data determine (eq. 18.3), and `time_domain` the rest.
pub(crate) fn time_info(
    series: &TimeSeries,
    settings: &PronySettings,
    n_terms_kept: usize,
    td: TimeFitInfo,
) -> PronyInfo {
    let [t_min, t_max] = td.time_window_s;
    PronyInfo {
        rms_log10_storage: td.rms_log10,
        rms_log10_loss: td.rms_log10,
        max_abs_log10_storage: td.max_abs_log10,
        max_abs_log10_loss: td.max_abs_log10,
        n_points: series.n_points,
        thinned_from_points: None,
        n_terms_grid: series.taus.len(),
        n_terms_kept,
        drop_threshold: settings.drop_threshold,
        weight_rule: settings.weight_rule,
        lambda: series.lambda,
        lambda_search: series.lambda_search.clone(),
        solver_status: series.solver_status.clone(),
        iterations: series.iterations.0,
        total_iterations: series.iterations.1,
        freq_window_hz: [1.0 / (2.0 * PI * t_max), 1.0 / (2.0 * PI * t_min)],
        tau_window_s: [series.taus[0], series.taus[series.taus.len() - 1]],
        modulus_scale_pa: series.scale,
        dense_rms_log10: None,
        dense_terms: None,
        term_target_rms_log10: None,
        term_target_met: None,
        term_trade: Vec::new(),
        time_domain: Some(td),
    }
}

fn window(points: &[TimeDatum]) -> Result<(f64, f64), PronyError> {
    let lo = points
        .iter()
        .map(|p| p.time_s)
        .fold(f64::INFINITY, f64::min);
    let hi = points.iter().map(|p| p.time_s).fold(0.0, f64::max);
    if hi <= lo * (1.0 + 1e-12) {
        return Err(PronyError::NoFrequencyWindow {
            freq_hz: 1.0 / (2.0 * PI * lo),
        });
    }
    Ok((lo, hi))
}

fn check(points: &[TimeDatum]) -> Result<(), PronyError> {
    super::fit::check_each(points, |p| [("time_s", p.time_s), ("value", p.value)])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::prony::synthetic::rubber_like_spectrum;

    /// The truth of the tests: the shipped rubber-like spectrum (peak at 1e-4 s, 2 decades wide,
    /// E∞ = 1 MPa), 2 terms per decade over 1e-9…1e1 s.
    pub(crate) fn truth() -> RelaxationSpectrum {
        let taus: Vec<f64> = (0..=20)
            .map(|k| 10f64.powf(-9.0 + 0.5 * k as f64))
            .collect();
        rubber_like_spectrum(&taus)
    }

    /// `per_decade` log-spaced times over [t0, t1] with `f` at each.
    pub(crate) fn samples(
        t0: f64,
        t1: f64,
        per_decade: usize,
        f: impl Fn(f64) -> f64,
    ) -> Vec<TimeDatum> {
        let n = ((t1 / t0).log10() * per_decade as f64).round() as usize;
        (0..=n)
            .map(|k| {
                let t = t0 * 10f64.powf(k as f64 / per_decade as f64);
                TimeDatum {
                    time_s: t,
                    value: f(t),
                }
            })
            .collect()
    }

    /// Largest relative deviation of (E′, E″) of `fit` from `truth` over ω in [w0, w1].
    pub(crate) fn dynamic_dev(
        fit: &RelaxationSpectrum,
        truth: &RelaxationSpectrum,
        w0: f64,
        w1: f64,
    ) -> (f64, f64) {
        let (mut d1, mut d2) = (0.0f64, 0.0f64);
        for k in 0..=40 {
            let w = w0 * (w1 / w0).powf(k as f64 / 40.0);
            let (a1, a2) = fit.complex_modulus(w);
            let (b1, b2) = truth.complex_modulus(w);
            d1 = d1.max((a1 / b1 - 1.0).abs());
            d2 = d2.max((a2 / b2 - 1.0).abs());
        }
        (d1, d2)
    }

    #[test]
    fn recovers_a_known_relaxation_modulus_and_its_dynamic_moduli_inside_the_window() {
        let truth = truth();
        let pts = samples(1e-7, 1e0, 10, |t| truth.relaxation_modulus(t));
        let fit = fit_relaxation_in_time(
            &pts,
            ModulusKind::Tensile,
            0.5,
            &PronySettings::default(),
            "E(t)",
        )
        .unwrap();
        let info = fit.info.time_domain.as_ref().unwrap();
        // Noise-free data: the fit reproduces E(t) to well below a DMA's 1 % repeatability.
        assert!(info.max_abs_log10 < 2e-3, "{info:?}");
        // E′, E″ inside the determined window 1/t_max … 1/t_min (eq. 18.3), one decade in from
        // each end where the terms just outside the window still matter.
        let (d1, d2) = dynamic_dev(&fit.spectrum, &truth, 1e1, 1e6);
        assert!(d1 < 0.01 && d2 < 0.05, "E′ {d1}, E″ {d2}");
        let [f0, f1] = fit.info.freq_window_hz;
        assert!((f0 * 2.0 * PI - 1.0).abs() < 1e-12 && (f1 * 2.0 * PI / 1e7 - 1.0).abs() < 1e-9);
    }

    #[test]
    fn a_series_of_too_few_or_bad_points_is_an_error() {
        let s = PronySettings::default();
        let p = |t: f64, v: f64| TimeDatum {
            time_s: t,
            value: v,
        };
        assert!(
            fit_series_in_time(&[p(1.0, 1.0), p(2.0, 1.0)], TimeBasis::Relaxation, &s).is_err()
        );
        assert!(fit_series_in_time(
            &[p(1.0, 1.0), p(2.0, -1.0), p(3.0, 1.0)],
            TimeBasis::Relaxation,
            &s
        )
        .is_err());
        assert!(fit_series_in_time(
            &[p(1.0, 1.0), p(1.0, 2.0), p(1.0, 1.0)],
            TimeBasis::Relaxation,
            &s
        )
        .is_err());
    }
}
