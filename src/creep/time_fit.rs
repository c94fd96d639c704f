//! Creep data to the relaxation spectrum (docs/MATH.md §18, eq. 18.2): the non-negative retardation series
//! J(t) = J_g + Σ Jⱼ(1 − e^(−t/λⱼ)) + t/η₀ fitted to reduced creep points
//! (`crate::prony::time_fit::fit_series_in_time`), then converted exactly to the relaxation
//! spectrum ([`super::creep_to_relaxation`], MATH §4), so the chain after it is the frequency path's.
//!
//! No flow term is fitted (it cannot be told from a retardation time beyond the window,
//! `crate::prony::time_fit`): the data are taken as a solid's. When J(t) still rises like t over the
//! last decade (d log J / d log t ≥ `FLOW_SLOPE`) that is said: the data may be a fluid's, whose
//! rolling has no steady state (`super::FLUID_NO_STEADY_ROLLING`), and everything beyond the
//! window rests on the assumption.

use super::{creep_to_relaxation, CreepError, CreepSpectrum, RetardationTerm};
use crate::material::ModulusKind;
use crate::prony::time_fit::{
    fit_series_in_time, time_errors, time_info, TimeBasis, TimeDatum, TimeFitInfo,
};
use crate::prony::{PronyError, PronyFit, PronySettings};

/// End slope d log J / d log t above which the creep data look like flow (a fluid's is 1).
pub(crate) const FLOW_SLOPE: f64 = 0.8;

/// Why creep data could not be fitted.
#[derive(Debug, thiserror::Error)]
pub enum CreepFitError {
    /// The QP failed.
    #[error(transparent)]
    Prony(#[from] PronyError),
    /// The retardation spectrum is not a valid solid, or the conversion failed.
    #[error(transparent)]
    Creep(#[from] CreepError),
}

/// Fit the retardation series to reduced creep points and convert it to relaxation: the
/// [`PronyFit`] of the relaxation spectrum (its info from the creep fit) and the creep spectrum.
pub(crate) fn fit_creep_in_time(
    points: &[TimeDatum],
    kind: ModulusKind,
    poisson: f64,
    settings: &PronySettings,
    function: &str,
) -> Result<(PronyFit, CreepSpectrum), CreepFitError> {
    let series = fit_series_in_time(points, TimeBasis::Retardation, settings)?;
    let mut notes = Vec::new();
    let slope = end_slope(points);
    if let Some(sl) = slope.filter(|&sl| sl >= FLOW_SLOPE) {
        notes.push(format!(
            "{function} still rises like t^{sl:.2} over the last decade of the data: it may be flow (a fluid, whose rolling has no steady state); it is fitted as a solid's creep, whose retardation times beyond the window are not determined"
        ));
    }
    let creep = CreepSpectrum {
        kind,
        poisson,
        compliance_glassy_per_pa: series.constant,
        terms: series
            .terms
            .iter()
            .rev()
            .map(|&(tau_s, compliance_per_pa)| RetardationTerm {
                compliance_per_pa,
                tau_s,
            })
            .collect(),
    };
    let (spectrum, _) = creep_to_relaxation(&creep)?;
    notes.push(format!(
        "{} retardation terms converted exactly to {} relaxation terms (docs/MATH.md §4)",
        creep.terms.len(),
        spectrum.terms.len()
    ));
    let errs = time_errors(points, |t| creep.creep_compliance(t));
    let td = TimeFitInfo::new(function, points, &series, errs, slope, notes);
    let info = time_info(&series, settings, spectrum.terms.len(), td);
    Ok((PronyFit { spectrum, info }, creep))
}

/// d log J / d log t over the last decade of `points` (least squares), if it holds 3 points.
fn end_slope(points: &[TimeDatum]) -> Option<f64> {
    let t_max = points.iter().map(|p| p.time_s).fold(0.0, f64::max);
    let last: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| p.time_s >= t_max / 10.0)
        .map(|p| (p.time_s.log10(), p.value.log10()))
        .collect();
    if last.len() < 3 {
        return None;
    }
    let n = last.len() as f64;
    let (mx, my) = last
        .iter()
        .fold((0.0, 0.0), |a, p| (a.0 + p.0 / n, a.1 + p.1 / n));
    let sxy: f64 = last.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = last.iter().map(|p| (p.0 - mx).powi(2)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::prony::synthetic::rubber_like_spectrum;

    #[test]
    fn creep_data_give_back_the_relaxation_spectrum_they_came_from() {
        let taus: Vec<f64> = (0..=20)
            .map(|k| 10f64.powf(-9.0 + 0.5 * k as f64))
            .collect();
        let truth = rubber_like_spectrum(&taus);
        let (creep, _) = crate::creep::relaxation_to_creep(&truth).unwrap();
        let n = 70;
        let pts: Vec<TimeDatum> = (0..=n)
            .map(|k| {
                let t = 1e-7 * 10f64.powf(k as f64 / 10.0);
                TimeDatum {
                    time_s: t,
                    value: creep.creep_compliance(t),
                }
            })
            .collect();
        let (fit, c) = fit_creep_in_time(
            &pts,
            ModulusKind::Tensile,
            0.5,
            &PronySettings::default(),
            "D(t)",
        )
        .unwrap();
        let info = fit.info.time_domain.as_ref().unwrap();
        assert!(info.max_abs_log10 < 2e-3, "{info:?}");
        assert!(info.notes.iter().all(|n| !n.contains("flow")), "{info:?}");
        assert!(c.compliance_glassy_per_pa > 0.0);
        // E(t) of the converted spectrum against the truth inside the window (the conversion is
        // exact, MATH §4; what is left is the fit's error, moved from J to E).
        let worst = pts
            .iter()
            .map(|p| {
                (fit.spectrum.relaxation_modulus(p.time_s) / truth.relaxation_modulus(p.time_s))
                    .log10()
                    .abs()
            })
            .fold(0.0, f64::max);
        assert!(worst < 0.01, "{worst}");
    }

    #[test]
    fn flowing_creep_data_are_said_to_look_like_flow() {
        let pts: Vec<TimeDatum> = (0..=40)
            .map(|k| {
                let t = 1e-2 * 10f64.powf(k as f64 / 10.0);
                TimeDatum {
                    time_s: t,
                    value: 1e-9 + t / 1e8,
                }
            })
            .collect();
        let (fit, _) = fit_creep_in_time(
            &pts,
            ModulusKind::Tensile,
            0.5,
            &PronySettings::default(),
            "D(t)",
        )
        .unwrap();
        let info = fit.info.time_domain.unwrap();
        // 1e-9 + t/1e8 over t = 1e2…1e3 s: slope ≈ 1 − 1e-9/J, i.e. above 0.9.
        assert!(info.end_slope.unwrap() > 0.9, "{info:?}");
        assert!(info.notes.iter().any(|n| n.contains("flow")), "{info:?}");
    }
}
