//! The WLF law a card carries, chosen from a table of measured shifts (issue 17: never a silently
//! degenerate WLF). Input: (T in °C, log10 a_T) referred to the spectrum's T_ref; output:
//! [`CardWlf`] — WLF over the whole table when it holds, else WLF over the widest run of
//! neighbouring temperatures (containing T_ref) where it holds, with that range and its RMS, else
//! none and why.
//!
//! "Holds" means RMS ≤ [`WLF_RMS_BOUND`] decade and 0 < C2 ≤ [`WLF_C2_MAX_K`] K, C1 > 0. The range
//! must contain T_ref because the cards' WLF is referred to the Prony data's temperature (Abaqus
//! *TRS θ₀, ANSYS TB,SHIFT T_r, LS-DYNA TREF): log10 a_T(T_ref) = 0 is part of the law.

use crate::tts::fit_laws::fit_wlf;
use crate::ShiftLaw;

/// Largest RMS (log10 decades) of the shifts about a WLF law for it to go into a card: 0.1 decade is
/// a 26 % error in every relaxation time, about what the master curve's overlap allows.
pub const WLF_RMS_BOUND: f64 = 0.1;
/// Largest C2 (K) of a WLF law that goes into a card: measured polymers have C2 of 30–300 K (WLF's
/// universal 51.6 K); a C2 of thousands of K is a straight line through the shifts in disguise
/// (issue 17 found C1 = 26185, C2 = 104763 K at 0.97 decade RMS).
pub const WLF_C2_MAX_K: f64 = 1000.0;
/// Fewest temperatures a partial-range WLF is fitted to (three constants: T_ref fixed, C1, C2 free,
/// and at least two more points to judge the fit by).
pub const WLF_MIN_TEMPERATURES: usize = 4;

/// The WLF law for a card.
#[derive(Debug, Clone, PartialEq)]
pub enum CardWlf {
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
pub fn card_wlf(shifts: &[(f64, f64)], t_ref_c: f64) -> CardWlf {
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
}
