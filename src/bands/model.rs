//! The fit's own model error (docs/MATH.md §15, "The fit's choices", eqs. 15.10–15.12): the
//! alternatives of the choices a fit makes that the data do not decide, drawn into every bootstrap
//! replicate on top of the data's scatter.
//!
//! Input: the [`MasterCurve`] the fit was made from and its [`Measurement`]; output:
//! `ModelChoices` (per isotherm the shift each other shift criterion finds; per interval between
//! isotherms the shift table's interpolation error), read by super::ensemble for each replicate,
//! which also draws the Prony fit's regularisation weight and term positions (eq. 15.12).
//!
//! 1. Shift criterion (eq. 15.10): the master curve is rebuilt with each other criterion of
//!    E′ alone, the slope-weighted E′/E″ and the joint E′/E″; its shift of isotherm k minus the
//!    fit's, d_(c,k), is one draw of the criterion's error (0 where the fit's shift is determined by
//!    overlap and the alternative's is not: a criterion that cannot see a shift, E′ alone on a
//!    flat rubbery plateau, has no say on it). A replicate takes one criterion c at
//!    random and adds w·d_(c,k) to every isotherm's shift (w standard normal, one per replicate).
//! 2. Shift-table interpolation (eq. 15.11): the error straight segments between isotherms would make (the
//!    law is a monotone cubic there, eq. 6.3, whose error is a fraction of it); its error at
//!    the middle of an interval of width h is L″h²/8, L″ the second difference of the shifts there.
//!    A replicate adds v·L″h²/8 at each midpoint (v standard normal, one per replicate).
//! 3. Regularisation and term positions (eq. 15.12): each replicate is refitted at
//!    λ·10^(U(−1, 1)) (the λ search's grid step, one decade, either way) on a relaxation-time grid
//!    moved by U(0, 1) of its step.

use crate::tts::{build_master_curve, MasterCurve, ShiftCriterion, ShiftSource};
use crate::Measurement;

/// Decades either side of the fit's λ that a replicate's λ is drawn from (uniform in log λ): the
/// λ search's grid step (`PronySettings::lambda_count` values over 11 decades), the resolution
/// at which the search chose it.
pub(crate) const LAMBDA_SPREAD_DECADES: f64 = 1.0;

/// The alternatives of a fit's choices (see the module docs).
#[derive(Debug, Clone, Default)]
pub(super) struct ModelChoices {
    /// Per other shift criterion (its name), d_(c,k) of each isotherm, indexed like
    /// `MasterCurve::isotherms` (eq. 15.10).
    pub criteria: Vec<(&'static str, Vec<f64>)>,
    /// (T_mid in °C, L″h²/8 in decades) of each interval between neighbouring isotherms
    /// (eq. 15.11), in temperature order.
    pub interpolation: Vec<(f64, f64)>,
}

impl ModelChoices {
    /// Largest |d_(c,k)| over the criteria and isotherms, decades.
    pub(crate) fn criterion_max_log10(&self) -> f64 {
        self.criteria
            .iter()
            .flat_map(|(_, d)| d.iter())
            .fold(0.0, |m, d| m.max(d.abs()))
    }

    /// Largest interpolation term, decades.
    pub(crate) fn interpolation_max_log10(&self) -> f64 {
        self.interpolation.iter().fold(0.0, |m, r| m.max(r.1.abs()))
    }
}

const CRITERIA: [(ShiftCriterion, &str); 3] = [
    (ShiftCriterion::Storage, "E′"),
    (ShiftCriterion::SlopeWeighted, "slope-weighted"),
    (ShiftCriterion::Joint, "joint"),
];

/// The alternatives of `master`'s choices (eqs. 15.10–15.11). A master curve with fewer than two
/// isotherms (read already shifted) or shifted by a given law has no criterion to vary; a criterion
/// whose master curve cannot be built, or lacks an isotherm, is left out.
pub(super) fn model_choices(master: &MasterCurve, measurement: &Measurement) -> ModelChoices {
    let mut choices = ModelChoices {
        interpolation: interpolation_terms(master),
        ..ModelChoices::default()
    };
    if master.isotherms.len() < 2 || master.settings.shift != ShiftSource::Auto {
        return choices;
    }
    for (criterion, name) in CRITERIA {
        if criterion == master.settings.criterion {
            continue;
        }
        let settings = crate::tts::MasterSettings {
            criterion,
            tref_c: Some(master.t_ref_c),
            ..master.settings.clone()
        };
        let Ok(alt) = build_master_curve(measurement, &settings) else {
            continue;
        };
        let d: Option<Vec<f64>> = master
            .isotherms
            .iter()
            .map(|i| {
                alt.isotherms
                    .iter()
                    .find(|a| a.measurement_index == i.measurement_index)
                    // An alternative that cannot determine a shift the fit's criterion does
                    // determine has no say there (the E′ criterion on a flat rubbery plateau).
                    .map(|a| {
                        if i.shift_determined && !a.shift_determined {
                            0.0
                        } else {
                            a.log10_a_t - i.log10_a_t
                        }
                    })
                    .filter(|d| d.is_finite())
            })
            .collect();
        if let Some(d) = d {
            choices.criteria.push((name, d));
        }
    }
    choices
}

/// Eq. 15.11 over the isotherms of `master` in temperature order: at the middle of each interval,
/// |L″|h²/8 with L″ the mean of the second differences at its two ends (the one there is at the
/// ends of the range).
fn interpolation_terms(master: &MasterCurve) -> Vec<(f64, f64)> {
    let mut s: Vec<(f64, f64)> = master
        .isotherms
        .iter()
        .map(|i| (i.temp_c, i.log10_a_t))
        .filter(|p| p.0.is_finite() && p.1.is_finite())
        .collect();
    s.sort_by(|a, b| a.0.total_cmp(&b.0));
    s.dedup_by(|a, b| (a.0 - b.0).abs() < 1e-9);
    let n = s.len();
    if n < 3 {
        return Vec::new();
    }
    // Second difference at each interior isotherm.
    let second: Vec<f64> = (1..n - 1)
        .map(|j| {
            let (a, b, c) = (s[j - 1], s[j], s[j + 1]);
            2.0 * ((c.1 - b.1) / (c.0 - b.0) - (b.1 - a.1) / (b.0 - a.0)) / (c.0 - a.0)
        })
        .collect();
    (0..n - 1)
        .map(|k| {
            // Interior isotherms k and k+1 are second[k−1] and second[k].
            let ends: Vec<f64> = [k.checked_sub(1), Some(k)]
                .into_iter()
                .flatten()
                .filter_map(|j| second.get(j).copied())
                .collect();
            let l2 = ends.iter().sum::<f64>() / ends.len().max(1) as f64;
            let h = s[k + 1].0 - s[k].0;
            (0.5 * (s[k].0 + s[k + 1].0), (l2 * h * h / 8.0).abs())
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A master curve whose only content is its isotherm shifts (for eq. 15.11).
    fn with_shifts(shifts: &[(f64, f64)]) -> MasterCurve {
        let m = crate::testdata::synthetic_measurement(
            &crate::testdata::broad_spectrum(),
            &crate::testdata::SyntheticSettings::new(
                vec![0.0, 10.0, 20.0],
                crate::ShiftLaw::Wlf {
                    t_ref_c: 10.0,
                    c1: 9.0,
                    c2_k: 120.0,
                },
            ),
        );
        let mut master = build_master_curve(&m, &Default::default()).unwrap();
        master.isotherms = shifts
            .iter()
            .enumerate()
            .map(|(k, &(t, l))| crate::tts::IsothermShift {
                temp_c: t,
                log10_a_t: l,
                ..master.isotherms[k.min(2)].clone()
            })
            .collect();
        master
    }

    #[test]
    fn the_interpolation_term_is_the_exact_error_of_linear_interpolation_on_a_parabola() {
        // L = 0.01 (T − 3)²: L″ = 0.02 everywhere, so linear interpolation misses the parabola at
        // an interval's middle by exactly L″h²/8 = 0.02·25/8 = 0.0625 (h = 5) and 0.25 (h = 10).
        let l = |t: f64| 0.01 * (t - 3.0) * (t - 3.0);
        let temps = [0.0, 5.0, 10.0, 20.0];
        let master = with_shifts(&temps.map(|t| (t, l(t))));
        let terms = interpolation_terms(&master);
        assert_eq!(terms.len(), 3);
        for (k, &(mid, amp)) in terms.iter().enumerate() {
            let (a, b) = (temps[k], temps[k + 1]);
            let linear_miss = 0.5 * (l(a) + l(b)) - l(mid);
            assert!((mid - 0.5 * (a + b)).abs() < 1e-12);
            assert!(
                (amp - linear_miss).abs() < 1e-12,
                "{k}: {amp} vs {linear_miss}"
            );
        }
        // A straight line has none.
        let master = with_shifts(&temps.map(|t| (t, 0.1 * t)));
        assert!(interpolation_terms(&master).iter().all(|r| r.1 < 1e-15));
    }

    #[test]
    fn other_criteria_find_the_exact_shifts_of_noise_free_data() {
        // Noise-free isotherms of an exact WLF law: every criterion finds the same shifts, so the
        // criterion term is (nearly) zero; a criterion term that were not a difference of two
        // shiftings of the same data would show here.
        let law = crate::ShiftLaw::Wlf {
            t_ref_c: 10.0,
            c1: 9.0,
            c2_k: 120.0,
        };
        let temps: Vec<f64> = (0..7).map(|i| -20.0 + 10.0 * i as f64).collect();
        let m = crate::testdata::synthetic_measurement(
            &crate::testdata::broad_spectrum(),
            &crate::testdata::SyntheticSettings::new(temps, law),
        );
        let master = build_master_curve(&m, &Default::default()).unwrap();
        let c = model_choices(&master, &m);
        assert!(c.criteria.len() >= 2, "{:?}", c.criteria);
        // The shift stage refines each shift to ~1e-10 on exact data; 1e-3 decade is far above
        // that and far below any noise-driven difference (~1e-2).
        assert!(
            c.criterion_max_log10() < 1e-3,
            "{}",
            c.criterion_max_log10()
        );
    }
}
