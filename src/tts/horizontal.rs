//! Third phase of the master curve: the horizontal shifts log10 a_T of every isotherm relative to
//! T_ref, either automatic (pairwise chain, then global refinement: [`super::shift`]) or from a
//! given law.
//!
//! Automatic shifts are trusted only where the data determine them (docs/MATH.md §6.6): the run of
//! neighbours around the reference isotherm whose overlaps each determine their relative shift
//! ([`pair_determined`]). Isotherms beyond a pair that does not (neighbours decades apart in a steep
//! glass transition, or E′ flat below T_g) keep the shifts the overlaps gave them and are only
//! marked as not determined by overlap (a law fitted to the run and extrapolated over tens of
//! kelvin placed the glassy isotherms of the shipped EMS-CA set decades off).

use super::channels::Channels;
use super::error::TtsError;
use super::settings::{MasterSettings, ShiftSource};
use super::shift::{pair_determined, pair_shift, refine_global, Prepared};
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
    /// Covariance of the shifts (docs/MATH.md eq. 6.2; empty for a given law).
    pub covariance: Vec<Vec<f64>>,
    /// Outer iterations of the global refinement (0 for a given law).
    pub iterations: usize,
    /// The given law, if the shifts come from one.
    pub given: Option<ShiftLaw>,
    /// Whether each shift is determined by the overlaps (always true for a given law).
    pub determined: Vec<bool>,
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
            Ok(Horizontal {
                shifts: g.shifts,
                std_err: g.std_err,
                covariance: g.covariance,
                iterations: g.iterations,
                given: None,
                determined: (0..n).map(|i| lo <= i && i <= hi).collect(),
            })
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
            Ok(Horizontal {
                shifts: s,
                std_err: vec![0.0; n],
                covariance: Vec::new(),
                iterations: 0,
                given: Some(law.clone()),
                determined: vec![true; n],
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
