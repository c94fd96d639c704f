//! Third phase of the master curve: the horizontal shifts log10 a_T of every isotherm relative to
//! T_ref, either automatic (pairwise chain, then global refinement: [`super::shift`]) or from a
//! given law, with the overlap mismatch of each isotherm.
//!
//! Automatic shifts are kept only where the data determine them (docs/MATH.md §6.6): the run of
//! neighbours around the reference isotherm whose overlaps each determine their relative shift
//! ([`pair_determined`]). Isotherms beyond a pair that does not (neighbours decades apart in a steep
//! glass transition, or E′ flat below T_g) are placed by a law (WLF, else Arrhenius) fitted to the
//! shifts of that run, and marked as not determined by overlap.

use super::channels::Channels;
use super::error::TtsError;
use super::fit_laws::{fit_arrhenius, fit_wlf};
use super::settings::{MasterSettings, ShiftSource};
use super::shift::{overlap_rms, pair_determined, pair_shift, refine_global, Prepared};
use crate::material::ShiftLaw;

/// A pair's overlap determines its relative shift when the shift's standard error from the pair
/// alone is at most this, decades: about the 0.03-decade accuracy asked of the shifts (issue 32). At
/// 0.1 a glassy isotherm of tests/master_plateau.rs, 0.4 decade of overlap from its warmer neighbour,
/// passed and sat 0.27 decade off.
const MAX_PAIR_STD_DECADES: f64 = 0.04;

/// The horizontal shifts and what came with them.
pub(super) struct Horizontal {
    /// log10 a_T of each isotherm relative to T_ref.
    pub shifts: Vec<f64>,
    /// Standard errors of the shifts (0 for a given law).
    pub std_err: Vec<f64>,
    /// RMS overlap mismatch of each isotherm, log10 units (`None`: overlaps nothing).
    pub overlap: Vec<Option<f64>>,
    /// Outer iterations of the global refinement (0 for a given law).
    pub iterations: usize,
    /// The given law, if the shifts come from one.
    pub given: Option<ShiftLaw>,
    /// Whether each shift is determined by the overlaps (always true for a given law).
    pub determined: Vec<bool>,
    /// How the shifts not determined by overlap were placed, in words (`None`: all determined).
    pub placed_by: Option<String>,
}

/// Shift the isotherms at temperatures `temps` (°C, increasing); `k0` is the reference isotherm.
pub(super) fn horizontal_shifts(
    ch: &Channels,
    temps: &[f64],
    k0: usize,
    t_ref: f64,
    settings: &MasterSettings,
) -> Result<Horizontal, TtsError> {
    let n = temps.len();
    let shifting = ch.shifting();
    let (reach, min_pts) = (settings.pair_reach, settings.min_overlap_points);
    match &settings.shift {
        ShiftSource::Auto => {
            let mut chain = vec![0.0; n];
            for i in 0..n - 1 {
                let p = pair_shift(
                    &shifting[i],
                    &shifting[i + 1],
                    settings.grid_step_decades,
                    min_pts,
                )
                .ok_or(TtsError::NoOverlap {
                    temp_a_c: temps[i],
                    temp_b_c: temps[i + 1],
                    min_points: min_pts,
                })?;
                chain[i + 1] = chain[i] + p.d;
            }
            let g = refine_global(shifting, &chain, k0, reach, min_pts);
            let (lo, hi) = determined_run(shifting, &g.shifts, k0, min_pts);
            let mut h = Horizontal {
                shifts: g.shifts,
                std_err: g.std_err,
                overlap: Vec::new(),
                iterations: g.iterations,
                given: None,
                determined: (0..n).map(|i| lo <= i && i <= hi).collect(),
                placed_by: None,
            };
            if (lo, hi) != (0, n - 1) {
                h.placed_by = Some(place_by_law(
                    &mut h,
                    shifting,
                    &chain,
                    temps,
                    k0,
                    (lo, hi),
                    settings,
                ));
            }
            // Overlap figures in log10 units (not weighted).
            h.overlap = if ch.weighted.is_empty() {
                overlap_rms(shifting, &h.shifts, reach, min_pts)
            } else {
                overlap_rms(&ch.joint, &h.shifts, reach, min_pts)
            };
            Ok(h)
        }
        ShiftSource::Given { law } => {
            let at_ref = law.log10_a_t(t_ref);
            let mut s = Vec::with_capacity(n);
            for &t in temps {
                let v = law.log10_a_t(t) - at_ref;
                if !v.is_finite() {
                    return Err(TtsError::LawNotFinite {
                        temp_c: t,
                        value: v,
                    });
                }
                s.push(v);
            }
            let overlap = overlap_rms(shifting, &s, reach, min_pts);
            Ok(Horizontal {
                shifts: s,
                std_err: vec![0.0; n],
                overlap,
                iterations: 0,
                given: Some(law.clone()),
                determined: vec![true; n],
                placed_by: None,
            })
        }
    }
}

/// The run of isotherms lo..=hi around the reference `k0` in which every neighbour pair's overlap
/// determines its relative shift at the shifts `s`.
fn determined_run(iso: &[Prepared], s: &[f64], k0: usize, min_pts: usize) -> (usize, usize) {
    let linked = |i: usize| {
        pair_determined(
            &iso[i],
            &iso[i + 1],
            s[i + 1] - s[i],
            min_pts,
            MAX_PAIR_STD_DECADES,
        )
    };
    let mut lo = k0;
    while lo > 0 && linked(lo - 1) {
        lo -= 1;
    }
    let mut hi = k0;
    while hi + 1 < iso.len() && linked(hi) {
        hi += 1;
    }
    (lo, hi)
}

/// Shift the determined run `run` again on its own (the others no longer pull on it) and place the
/// other isotherms by the law fitted to its shifts: WLF, or Arrhenius where WLF fails or does not
/// reach (its asymptote lies above the temperature). Their standard error is the spread of the two
/// laws there, at least the fit's RMS. With fewer than three isotherms in the run no law can be
/// fitted, and the shifts stay as the overlaps left them. Returns how they were placed.
fn place_by_law(
    h: &mut Horizontal,
    shifting: &[Prepared],
    chain: &[f64],
    temps: &[f64],
    k0: usize,
    (lo, hi): (usize, usize),
    settings: &MasterSettings,
) -> String {
    if hi - lo + 1 < 3 {
        return "left where the overlaps put them (fewer than three isotherms are determined, too few for a law)".to_string();
    }
    let g = refine_global(
        &shifting[lo..=hi],
        &chain[lo..=hi],
        k0 - lo,
        settings.pair_reach,
        settings.min_overlap_points,
    );
    h.shifts[lo..=hi].copy_from_slice(&g.shifts);
    h.std_err[lo..=hi].copy_from_slice(&g.std_err);
    let t0 = temps[k0];
    let pts: Vec<(f64, f64)> = temps[lo..=hi]
        .iter()
        .copied()
        .zip(g.shifts.iter().copied())
        .collect();
    let wlf = fit_wlf(&pts, t0).ok();
    let arr = fit_arrhenius(&pts, t0).ok();
    let table = ShiftLaw::Table {
        t_ref_c: t0,
        points: pts.clone(),
    };
    let mut used = Vec::new();
    for i in (0..temps.len()).filter(|i| *i < lo || *i > hi) {
        let t = temps[i];
        let w = wlf.as_ref().map(|w| (w.law().log10_a_t(t), w.rms_log10));
        let a = arr.as_ref().map(|a| (a.law().log10_a_t(t), a.rms_log10));
        let (value, rms, name) = match (w, a) {
            (Some((v, r)), _) if v.is_finite() => (v, r, "the WLF law"),
            (_, Some((v, r))) if v.is_finite() => (v, r, "the Arrhenius law"),
            _ => (table.log10_a_t(t), 0.0, "the table of their shifts"),
        };
        let spread = match (w, a) {
            (Some((x, _)), Some((y, _))) if x.is_finite() && y.is_finite() => (x - y).abs(),
            _ => 0.0,
        };
        h.shifts[i] = value;
        h.std_err[i] = spread.max(rms);
        if !used.contains(&name) {
            used.push(name);
        }
    }
    format!(
        "placed by {} fitted to the shifts of the isotherms at {:.1}…{:.1} °C, which the overlaps determine",
        used.join(" and "),
        temps[lo],
        temps[hi]
    )
}
