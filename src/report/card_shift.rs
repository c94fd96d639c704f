//! The WLF law a card carries, chosen from a table of measured shifts (issue 17: never a silently
//! degenerate WLF). Input: (T in °C, log10 a_T) referred to the spectrum's T_ref; output:
//! `CardWlf` — WLF over the whole table when it holds, else WLF over the widest run of
//! neighbouring temperatures (containing T_ref) where it holds, with that range and its RMS, else
//! none and why.
//!
//! "Holds" means RMS ≤ `WLF_RMS_BOUND` decade and 0 < C2 ≤ `WLF_C2_MAX_K` K, C1 > 0. The range
//! must contain T_ref because the cards' WLF is referred to the Prony data's temperature (Abaqus
//! *TRS θ₀, ANSYS TB,SHIFT T_r, LS-DYNA TREF): log10 a_T(T_ref) = 0 is part of the law.
//!
//! `card_shift` chooses the law a fit's cards carry, with the warnings to show: the fit's own
//! Arrhenius law when it used one, else WLF as above, else (WLF withheld) an Arrhenius fit of the
//! shifts when it holds (RMS ≤ `WLF_RMS_BOUND`, E_a > 0), else none and why. Abaqus and ANSYS
//! carry Arrhenius (`*TRS, DEFINITION=ARRHENIUS`; `TB,SHIFT … TN`); LS-DYNA does not
//! (`report::cards::LSDYNA_NO_ARRHENIUS`).

use crate::tts::fit_laws::{fit_arrhenius, fit_wlf};
use crate::ShiftLaw;

/// Largest RMS (log10 decades) of the shifts about a WLF law for it to go into a card: 0.1 decade is
/// a 26 % error in every relaxation time, about what the master curve's overlap allows.
pub(crate) const WLF_RMS_BOUND: f64 = 0.1;
/// Largest C2 (K) of a WLF law that goes into a card: measured polymers have C2 of 30–300 K (WLF's
/// universal 51.6 K); a C2 of thousands of K is a straight line through the shifts in disguise
/// (issue 17 found C1 = 26185, C2 = 104763 K at 0.97 decade RMS).
pub(crate) const WLF_C2_MAX_K: f64 = 1000.0;
/// Fewest temperatures a partial-range WLF is fitted to (three constants: T_ref fixed, C1, C2 free,
/// and at least two more points to judge the fit by).
pub(crate) const WLF_MIN_TEMPERATURES: usize = 4;

/// The WLF law for a card.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum CardWlf {
    /// WLF holds over the whole table.
    Whole {
        /// The law (at T_ref).
        law: ShiftLaw,
        /// RMS of all shifts about it, decades.
        rms_log10: f64,
    },
    /// WLF holds over part of the table only.
    Range {
        /// The law (at T_ref), fitted to the shifts in `t_min_c..=t_max_c`.
        law: ShiftLaw,
        /// RMS of those shifts about it, decades.
        rms_log10: f64,
        /// Lowest temperature of the range, °C.
        t_min_c: f64,
        /// Highest temperature of the range, °C.
        t_max_c: f64,
        /// Temperatures used / in the table.
        used: usize,
        /// Temperatures in the table.
        of: usize,
        /// Why the whole table was not used.
        whole: String,
    },
    /// No WLF can go into the card.
    Withheld(String),
}

fn holds(law: &ShiftLaw, rms: f64) -> Result<(), String> {
    let ShiftLaw::Wlf { c1, c2_k, .. } = *law else {
        return Err("not WLF".into());
    };
    if rms.is_nan() || rms > WLF_RMS_BOUND {
        return Err(format!(
            "the WLF fit (C1 = {c1:.4}, C2 = {c2_k:.4} K) misses the shifts by {rms:.3} decade RMS (bound {WLF_RMS_BOUND})"
        ));
    }
    if !(c1 > 0.0 && c2_k > 0.0 && c2_k <= WLF_C2_MAX_K) {
        return Err(format!(
            "the WLF fit is degenerate (C1 = {c1:.4}, C2 = {c2_k:.4} K; a card's WLF needs C1 > 0 and 0 < C2 ≤ {WLF_C2_MAX_K} K)"
        ));
    }
    Ok(())
}

fn fit(points: &[(f64, f64)], t_ref_c: f64) -> Result<(ShiftLaw, f64), String> {
    let f = fit_wlf(points, t_ref_c).map_err(|e| e.to_string())?;
    let law = f.law();
    holds(&law, f.rms_log10)?;
    Ok((law, f.rms_log10))
}

/// The WLF law for a card from the shifts `shifts` (°C, log10 a_T) referred to `t_ref_c`.
pub(crate) fn card_wlf(shifts: &[(f64, f64)], t_ref_c: f64) -> CardWlf {
    let mut pts: Vec<(f64, f64)> = shifts
        .iter()
        .copied()
        .filter(|p| p.0.is_finite() && p.1.is_finite())
        .collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    let whole = match fit(&pts, t_ref_c) {
        Ok((law, rms_log10)) => return CardWlf::Whole { law, rms_log10 },
        Err(why) => why,
    };
    // Widest run of neighbouring temperatures containing T_ref where WLF holds; among equally
    // wide runs the lowest RMS. O(n³) fits of n ≤ a few dozen temperatures.
    let n = pts.len();
    let mut best: Option<(usize, f64, usize, usize, ShiftLaw)> = None;
    for i in 0..n {
        for j in (i + WLF_MIN_TEMPERATURES - 1)..n {
            if !(pts[i].0 <= t_ref_c && t_ref_c <= pts[j].0) {
                continue;
            }
            let width = j - i + 1;
            if best.as_ref().is_some_and(|b| width < b.0) {
                continue;
            }
            if let Ok((law, rms)) = fit(&pts[i..=j], t_ref_c) {
                let better = match &best {
                    None => true,
                    Some((w, r, ..)) => width > *w || (width == *w && rms < *r),
                };
                if better {
                    best = Some((width, rms, i, j, law));
                }
            }
        }
    }
    match best {
        Some((used, rms_log10, i, j, law)) => CardWlf::Range {
            law,
            rms_log10,
            t_min_c: pts[i].0,
            t_max_c: pts[j].0,
            used,
            of: n,
            whole,
        },
        None => CardWlf::Withheld(format!(
            "{whole}, and over no run of ≥ {WLF_MIN_TEMPERATURES} neighbouring temperatures around T_ref = {t_ref_c} °C does WLF hold"
        )),
    }
}

/// The shift law for a fit's cards and what to say about it (notes starting `WARNING:` are warnings).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct CardShift {
    /// The law, if any can go into a card.
    pub law: Option<ShiftLaw>,
    /// What the cards' reader should know (RMS, range, fallbacks, why none).
    pub notes: Vec<String>,
}

/// The shift law for the cards of a fit whose master curve found `shifts` (°C, log10 a_T at
/// `law_in_use`'s T_ref) with `law_in_use` (see the module doc for the order of choice).
pub(crate) fn card_shift(shifts: &[(f64, f64)], law_in_use: &ShiftLaw) -> CardShift {
    let t_ref_c = law_in_use.t_ref_c();
    let pts: Vec<(f64, f64)> = shifts
        .iter()
        .copied()
        .filter(|p| p.0.is_finite() && p.1.is_finite())
        .collect();
    let rms_about = |law: &ShiftLaw| -> Option<f64> {
        (!pts.is_empty()).then(|| {
            (pts.iter()
                .map(|&(t, a)| (law.log10_a_t(t) - a).powi(2))
                .sum::<f64>()
                / pts.len() as f64)
                .sqrt()
        })
    };
    if let ShiftLaw::Arrhenius {
        activation_energy_j_per_mol: ea,
        ..
    } = *law_in_use
    {
        let rms = rms_about(law_in_use)
            .map(|r| format!(", RMS {r:.3} decade about the shifts"))
            .unwrap_or_default();
        return CardShift {
            law: Some(law_in_use.clone()),
            notes: vec![format!(
                "Arrhenius shift, the master curve's own law (E_a = {:.1} kJ/mol{rms})",
                ea / 1e3
            )],
        };
    }
    if pts.is_empty() {
        return match law_in_use {
            ShiftLaw::Wlf { .. } => CardShift {
                law: Some(law_in_use.clone()),
                notes: vec!["WLF shift as given (no table of shifts to check it against)".into()],
            },
            _ => CardShift {
                law: None,
                notes: vec![
                    "WARNING: no shift card: no master-curve shifts and no WLF or Arrhenius law"
                        .into(),
                ],
            },
        };
    }
    from_table(&pts, t_ref_c)
}

/// The cards' shift from the WLF fits of the table `pts` (module doc): WLF over the whole table,
/// WLF over a range with a warning, or, WLF withheld, Arrhenius when it holds.
fn from_table(pts: &[(f64, f64)], t_ref_c: f64) -> CardShift {
    match card_wlf(pts, t_ref_c) {
        CardWlf::Whole { law, rms_log10 } => CardShift {
            law: Some(law),
            notes: vec![format!(
                "WLF shift fitted to the master curve's shifts: RMS {rms_log10:.3} decade"
            )],
        },
        CardWlf::Range {
            law,
            rms_log10,
            t_min_c,
            t_max_c,
            used,
            of,
            whole,
        } => {
            let (c1, c2) = match law {
                ShiftLaw::Wlf { c1, c2_k, .. } => (c1, c2_k),
                _ => (f64::NAN, f64::NAN),
            };
            CardShift {
                law: Some(law),
                notes: vec![format!(
                    "WARNING: WLF shift (C1 = {c1:.4}, C2 = {c2:.3} K) fitted over {t_min_c:.2} to \
                     {t_max_c:.2} degC only, where it holds ({used} of {of} temperatures, RMS \
                     {rms_log10:.3} decade): over all of them {whole}; outside that range shift \
                     the spectrum otherwise"
                )],
            }
        }
        CardWlf::Withheld(why) => arrhenius_instead(&why, pts, t_ref_c),
    }
}

/// WLF withheld (`why`): an Arrhenius fit of the table `pts` when it holds (RMS ≤ the WLF bound,
/// E_a > 0), else no shift card and why.
fn arrhenius_instead(why: &str, pts: &[(f64, f64)], t_ref_c: f64) -> CardShift {
    match fit_arrhenius(pts, t_ref_c) {
        Ok(f) if f.rms_log10 <= WLF_RMS_BOUND && f.activation_energy_j_per_mol > 0.0 => {
            CardShift {
                law: Some(f.law()),
                notes: vec![format!(
                    "WARNING: WLF withheld ({why}); an Arrhenius shift fitted to the same shifts \
                     goes into the cards instead (E_a = {:.1} kJ/mol, RMS {:.3} decade)",
                    f.activation_energy_j_per_mol / 1e3,
                    f.rms_log10
                )],
            }
        }
        Ok(f) => CardShift {
            law: None,
            notes: vec![format!(
                "WARNING: no shift card: {why}; nor does Arrhenius hold (E_a = {:.1} kJ/mol, \
                 RMS {:.3} decade, bound {WLF_RMS_BOUND}); shift in the solver",
                f.activation_energy_j_per_mol / 1e3,
                f.rms_log10
            )],
        },
        Err(e) => CardShift {
            law: None,
            notes: vec![format!(
                "WARNING: no shift card: {why}; nor can Arrhenius be fitted ({e}); shift in the solver"
            )],
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Shifts of an exact WLF law (C1 = 8.86, C2 = 101.6 K, the classic Williams–Landel–Ferry
    /// constants at T_s) above −20 °C and a glassy Arrhenius-like straight line below it.
    fn kinked() -> Vec<(f64, f64)> {
        let wlf = ShiftLaw::Wlf {
            t_ref_c: 20.0,
            c1: 8.86,
            c2_k: 101.6,
        };
        (0..15)
            .map(|k| {
                let t = -60.0 + 10.0 * k as f64;
                let a = if t >= -20.0 {
                    wlf.log10_a_t(t)
                } else {
                    wlf.log10_a_t(-20.0) + 0.05 * (-20.0 - t)
                };
                (t, a)
            })
            .collect()
    }

    #[test]
    fn exact_wlf_is_taken_whole() {
        let law = ShiftLaw::Wlf {
            t_ref_c: 20.0,
            c1: 8.86,
            c2_k: 101.6,
        };
        let pts: Vec<(f64, f64)> = (0..9)
            .map(|k| {
                let t = -20.0 + 10.0 * k as f64;
                (t, law.log10_a_t(t))
            })
            .collect();
        match card_wlf(&pts, 20.0) {
            CardWlf::Whole { law, rms_log10 } => {
                let ShiftLaw::Wlf { c1, c2_k, .. } = law else {
                    panic!()
                };
                // Exact data: the fitter's own tolerance.
                assert!(
                    (c1 - 8.86).abs() < 1e-3 && (c2_k - 101.6).abs() < 1e-2,
                    "{c1} {c2_k}"
                );
                assert!(rms_log10 < 1e-6);
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn a_kinked_table_gets_wlf_over_the_range_where_it_holds() {
        match card_wlf(&kinked(), 20.0) {
            CardWlf::Range {
                law,
                rms_log10,
                t_min_c,
                t_max_c,
                used,
                of,
                ..
            } => {
                // The exact WLF part is −20…80 °C (11 temperatures); the glassy line joins it with
                // a kink, so one more temperature (−30 °C) can still be within 0.1 decade RMS.
                assert_eq!(of, 15);
                assert_eq!(t_max_c, 80.0);
                assert!((-30.0..=-20.0).contains(&t_min_c), "{t_min_c}");
                assert!((11..=12).contains(&used), "{used}");
                assert!(rms_log10 <= WLF_RMS_BOUND);
                let ShiftLaw::Wlf { c1, c2_k, .. } = law else {
                    panic!()
                };
                assert!(
                    (c1 - 8.86).abs() < 1.0 && (c2_k - 101.6).abs() < 15.0,
                    "{c1} {c2_k}"
                );
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn no_wlf_anywhere_is_withheld_with_the_reason() {
        // A straight line with slope of the wrong sign (log a_T rising with T): C1 < 0 everywhere.
        let pts: Vec<(f64, f64)> = (0..8)
            .map(|k| (10.0 * k as f64, 0.1 * (k as f64 - 2.0)))
            .collect();
        match card_wlf(&pts, 20.0) {
            CardWlf::Withheld(why) => assert!(why.contains("no run"), "{why}"),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn a_straight_line_withholds_wlf_and_takes_arrhenius() {
        // log10 a_T falling by 0.05 decade per K over 0…60 °C: WLF's best fit runs to C2 → ∞ (a
        // straight line; degenerate), while the Arrhenius curve 1/T bends by only a few hundredths
        // of a decade over 60 K at ~300 K, well inside 0.1 decade.
        let pts: Vec<(f64, f64)> = (0..7)
            .map(|k| {
                let t = 10.0 * k as f64;
                (t, -0.05 * (t - 20.0))
            })
            .collect();
        let law_in_use = ShiftLaw::Table {
            t_ref_c: 20.0,
            points: pts.clone(),
        };
        let c = card_shift(&pts, &law_in_use);
        let Some(ShiftLaw::Arrhenius {
            t_ref_c,
            activation_energy_j_per_mol: ea,
        }) = c.law
        else {
            panic!("{c:?}")
        };
        assert_eq!(t_ref_c, 20.0);
        // The slope at T_ref: d log10 a/dT = −E_a/(R ln10 T²) = −0.05/K, so E_a ≈ 0.05 R ln10 T_ref²
        // (≈ 82 kJ/mol); the fit weighs the whole span, so within 10 %.
        let want = 0.05 * 8.314_462_618 * std::f64::consts::LN_10 * 293.15f64.powi(2);
        assert!((ea / want - 1.0).abs() < 0.1, "{ea} vs {want}");
        assert!(
            c.notes[0].starts_with("WARNING: WLF withheld"),
            "{:?}",
            c.notes
        );
    }

    #[test]
    fn the_fits_own_arrhenius_law_is_kept() {
        let law = ShiftLaw::Arrhenius {
            t_ref_c: 25.0,
            activation_energy_j_per_mol: 1.2e5,
        };
        let c = card_shift(&[], &law);
        assert_eq!(c.law, Some(law));
        assert!(!c.notes[0].starts_with("WARNING"));
    }
}
