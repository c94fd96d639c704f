//! Fourth phase of the master curve: WLF and Arrhenius fits of the shifts ([`super::fit_laws`]), the
//! choice of the master curve's [`ShiftLaw`], and the move from the reference isotherm's
//! temperature T₀ to T_ref.
//!
//! Automatic shifts are fitted at T₀ (its shift is exactly 0 there) and the law chosen there; then
//! the shifts move by the chosen law's value at T_ref, the chosen law moves exactly (same function),
//! and the other law is refitted to the moved shifts. A given law stays as given.

use super::error::TtsError;
use super::fit_laws::{fit_arrhenius, fit_wlf, ArrheniusFit, WlfFit};
use super::settings::{LawChoice, MasterSettings, VerticalShift};
use crate::material::ShiftLaw;

/// The fitted laws and the law chosen.
pub(super) struct Laws {
    /// WLF fit at T_ref.
    pub wlf: Option<WlfFit>,
    /// Arrhenius fit at T_ref.
    pub arrhenius: Option<ArrheniusFit>,
    /// The law of the master curve.
    pub shift_law: ShiftLaw,
}

/// Fit and choose the laws of `shifts` at temperatures `temps`; moves `shifts` (and, with fitted
/// vertical shifts, `log_b`) from T₀ = `temps[k0]` to `t_ref`. Fit failures become warnings.
#[allow(clippy::too_many_arguments)]
pub(super) fn fit_and_choose(
    temps: &[f64],
    shifts: &mut [f64],
    log_b: &mut [f64],
    k0: usize,
    t_ref: f64,
    given: Option<ShiftLaw>,
    settings: &MasterSettings,
    warnings: &mut Vec<String>,
) -> Result<Laws, TtsError> {
    if let Some(law) = given {
        let (wlf, arrhenius) = fit_both(temps, shifts, t_ref, settings, warnings);
        return Ok(Laws {
            wlf,
            arrhenius,
            shift_law: law,
        });
    }
    let t0 = temps[k0];
    let (w0, a0) = fit_both(temps, shifts, t0, settings, warnings);
    let law0 = choose(settings.law, temps, &w0, &a0, shifts, t0);
    if (t_ref - t0).abs() <= 1e-12 {
        return Ok(Laws {
            wlf: w0,
            arrhenius: a0,
            shift_law: law0,
        });
    }
    move_to_reference(temps, shifts, log_b, &law0, t_ref, settings)?;
    let all: Vec<(f64, f64)> = temps.iter().copied().zip(shifts.iter().copied()).collect();
    let pts: Vec<(f64, f64)> = all
        .iter()
        .copied()
        .filter(|p| in_range(settings, p))
        .collect();
    let mut tmp = Vec::new();
    let (wr, ar) = fit_both(temps, shifts, t_ref, settings, &mut tmp);
    let w = match (&law0, &w0) {
        (ShiftLaw::Wlf { .. }, Some(w)) => w.rereferenced(&pts, t_ref),
        _ => wr,
    };
    let a = match (&law0, &a0) {
        (ShiftLaw::Arrhenius { .. }, Some(a)) => Some(a.rereferenced(&pts, t_ref)),
        _ => ar,
    };
    let shift_law = match law0 {
        ShiftLaw::Table { .. } => ShiftLaw::Table {
            t_ref_c: t_ref,
            points: all.clone(),
        },
        ShiftLaw::Wlf { .. } => w
            .as_ref()
            .map(WlfFit::law)
            .unwrap_or_else(|| choose(settings.law, temps, &w, &a, shifts, t_ref)),
        ShiftLaw::Arrhenius { .. } => a
            .as_ref()
            .map(ArrheniusFit::law)
            .unwrap_or_else(|| choose(settings.law, temps, &w, &a, shifts, t_ref)),
    };
    Ok(Laws {
        wlf: w,
        arrhenius: a,
        shift_law,
    })
}

/// Whether a (T, log a_T) point lies in the settings' law-fit range (all do without one).
fn in_range(settings: &MasterSettings, p: &(f64, f64)) -> bool {
    settings
        .law_fit_range_c
        .map_or(true, |(lo, hi)| p.0 >= lo && p.0 <= hi)
}

/// WLF and Arrhenius fits of the shifts `s` at `temps` (in the law-fit range) referred to `tr`; a
/// failed fit is None and its reason a warning.
fn fit_both(
    temps: &[f64],
    s: &[f64],
    tr: f64,
    settings: &MasterSettings,
    warnings: &mut Vec<String>,
) -> (Option<WlfFit>, Option<ArrheniusFit>) {
    let pts: Vec<(f64, f64)> = temps
        .iter()
        .copied()
        .zip(s.iter().copied())
        .filter(|p| in_range(settings, p))
        .collect();
    let w = fit_wlf(&pts, tr)
        .map_err(|e| warnings.push(e.to_string()))
        .ok();
    let a = fit_arrhenius(&pts, tr)
        .map_err(|e| warnings.push(e.to_string()))
        .ok();
    (w, a)
}

/// The law chosen by `law` among the fits (Auto: the smaller RMS), falling back to the other fit
/// and then to the table of the shifts `s` at `temps` referred to `tr`.
fn choose(
    law: LawChoice,
    temps: &[f64],
    w: &Option<WlfFit>,
    a: &Option<ArrheniusFit>,
    s: &[f64],
    tr: f64,
) -> ShiftLaw {
    let table = ShiftLaw::Table {
        t_ref_c: tr,
        points: temps.iter().copied().zip(s.iter().copied()).collect(),
    };
    match (law, w, a) {
        (LawChoice::Table, _, _) => table,
        (LawChoice::Wlf, Some(w), _) => w.law(),
        (LawChoice::Arrhenius, _, Some(a)) => a.law(),
        (LawChoice::Auto, Some(w), Some(a)) => {
            if w.rms_log10 <= a.rms_log10 {
                w.law()
            } else {
                a.law()
            }
        }
        (_, Some(w), _) => w.law(),
        (_, _, Some(a)) => a.law(),
        _ => table,
    }
}

/// Refer the shifts (by `law0`'s value at `t_ref`) and, when fitted, the vertical shifts (by their
/// interpolated value at `t_ref`) to `t_ref`.
fn move_to_reference(
    temps: &[f64],
    shifts: &mut [f64],
    log_b: &mut [f64],
    law0: &ShiftLaw,
    t_ref: f64,
    settings: &MasterSettings,
) -> Result<(), TtsError> {
    let off = law0.log10_a_t(t_ref);
    if !off.is_finite() {
        return Err(TtsError::LawNotFinite {
            temp_c: t_ref,
            value: off,
        });
    }
    for s in shifts.iter_mut() {
        *s -= off;
    }
    if settings.vertical == VerticalShift::Fitted {
        let b_ref = interp_at(temps, log_b, t_ref);
        for b in log_b.iter_mut() {
            *b -= b_ref;
        }
    }
    Ok(())
}

/// A warning when the WLF fit sits at its C2 search bound (a degenerate, nearly linear WLF).
pub(super) fn degenerate_wlf_warning(wlf: &Option<WlfFit>) -> Option<String> {
    let w = wlf.as_ref()?;
    (w.c2_k > 1e4).then(|| {
        format!(
            "WLF C2 = {:.3e} K at the search bound: the shifts are nearly linear in T and WLF \
             is degenerate (C1/C2 = {:.4} per K); see the Arrhenius fit or the table",
            w.c2_k,
            w.c1 / w.c2_k
        )
    })
}

fn interp_at(temps: &[f64], vals: &[f64], t: f64) -> f64 {
    let pts: Vec<(f64, f64)> = temps.iter().copied().zip(vals.iter().copied()).collect();
    ShiftLaw::Table {
        t_ref_c: t,
        points: pts,
    }
    .log10_a_t(t)
}
