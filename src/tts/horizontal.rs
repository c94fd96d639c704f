//! Third phase of the master curve: the horizontal shifts log10 a_T of every isotherm relative to
//! T_ref, either automatic (pairwise chain, then global refinement: [`super::shift`]) or from a
//! given law, with the overlap mismatch of each isotherm.

use super::channels::Channels;
use super::error::TtsError;
use super::settings::{MasterSettings, ShiftSource};
use super::shift::{overlap_rms, pair_shift, refine_global};
use crate::material::ShiftLaw;

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
            // Overlap figures in log10 units (not weighted).
            let overlap = if ch.weighted.is_empty() {
                g.overlap_rms
            } else {
                overlap_rms(&ch.joint, &g.shifts, reach, min_pts)
            };
            Ok(Horizontal {
                shifts: g.shifts,
                std_err: g.std_err,
                overlap,
                iterations: g.iterations,
                given: None,
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
            let overlap = overlap_rms(shifting, &s, reach, min_pts);
            Ok(Horizontal {
                shifts: s,
                std_err: vec![0.0; n],
                overlap,
                iterations: 0,
                given: Some(law.clone()),
            })
        }
    }
}
