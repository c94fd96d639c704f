//! Second phase of the master curve: the channels the shifting compares, built from the cleaned
//! isotherms ([`Clean`]) and the vertical factors known before shifting.
//!
//! - `joint`: log10 E′ and log10 E″ (less log10 b_T), always built (the quality figures use it);
//! - `tan`: log10 tan δ, for the tan δ criterion and for fitted vertical shifts;
//! - `storage`: log10 E′ alone (the `storage` criterion);
//! - `weighted`: the joint channels each divided by its own scatter (docs/MATH.md §6): maximum
//!   likelihood with an unknown variance per channel, so a channel that cannot be superposed (an
//!   instrument resonance in E″, a secondary relaxation) gives way to the one that can. With the
//!   slope-weighted criterion each isotherm also weighs each channel by its share of the
//!   information, I_c = (median |d log M_c/d log f| / σ_c)² / Σ I (the default criterion): where
//!   E′ is flat (a plateau),
//!   its residuals say nothing about the shift and only add noise, so E″ carries it. Only on the
//!   rubbery side of the transition (median log E′ below the middle of its range over the
//!   isotherms): below T_g, E″ holds secondary relaxations that do not superpose (on the shipped
//!   EMS-CA set, E″ carrying the glassy isotherms collapsed their shifts to within 0.6 decade over
//!   55 K), so there E′ alone carries the shift, as with the `storage` criterion; except as far
//!   as E″ superposes in the glass within its points' own scatter ([`superposing_glass`],
//!   docs/MATH.md eq. 6.1), where the glass is treated as the rubbery side is.

use super::clean::Clean;
use super::settings::{MasterSettings, ShiftCriterion, ShiftSource, VerticalShift};
use super::shift::{channel_scatter, pair_shift, Prepared};
use std::cmp::Ordering::{Equal, Less};

/// The prepared channels of every isotherm.
pub(super) struct Channels {
    /// log10 E′ and log10 E″, less log10 b_T.
    pub joint: Vec<Prepared>,
    /// log10 tan δ (empty unless used).
    pub tan: Vec<Prepared>,
    /// log10 E′ alone (empty unless used).
    pub storage: Vec<Prepared>,
    /// The joint channels over their scatters (empty unless used).
    pub weighted: Vec<Prepared>,
    /// The scatters of the weighted channels, log10 units (empty unless used).
    pub channel_scatter_log10: Vec<f64>,
    /// Whether tan δ is compared.
    pub use_tan: bool,
    /// Per isotherm, the channel that carried its shift (slope-weighted criterion only).
    pub carried: Vec<Option<String>>,
}

impl Channels {
    /// Build the channels `settings` asks for; `log_b` are the vertical factors known before
    /// shifting (zero, or from temperature).
    pub(crate) fn prepare(
        iso: &[Clean],
        log_b: &[f64],
        settings: &MasterSettings,
        kind: crate::ModulusKind,
    ) -> Channels {
        let joint: Vec<Prepared> = iso
            .iter()
            .zip(log_b)
            .map(|(c, &b)| {
                Prepared::new(
                    c.x.clone(),
                    vec![
                        c.log_s.iter().map(|v| v - b).collect(),
                        c.log_l.iter().map(|v| v - b).collect(),
                    ],
                )
            })
            .collect();
        let use_tan = settings.criterion == ShiftCriterion::TanDelta
            || settings.vertical == VerticalShift::Fitted;
        let tan = if use_tan {
            tan_channels(iso)
        } else {
            Vec::new()
        };
        let storage: Vec<Prepared> = if settings.criterion == ShiftCriterion::Storage && !use_tan {
            joint
                .iter()
                .map(|p| Prepared::new(p.x.clone(), vec![p.channels[0].0.clone()]))
                .collect()
        } else {
            Vec::new()
        };
        let (weighted, channel_scatter_log10) =
            if !use_tan && storage.is_empty() && settings.shift == ShiftSource::Auto {
                weighted_channels(&joint, settings)
            } else {
                (Vec::new(), Vec::new())
            };
        let carried = carried_channels(&weighted, kind, iso.len());
        Channels {
            joint,
            tan,
            storage,
            weighted,
            channel_scatter_log10,
            use_tan,
            carried,
        }
    }

    /// The channels the shifting compares.
    pub fn shifting(&self) -> &[Prepared] {
        if self.use_tan {
            &self.tan
        } else if !self.storage.is_empty() {
            &self.storage
        } else if !self.weighted.is_empty() {
            &self.weighted
        } else {
            &self.joint
        }
    }
}

/// Each channel's share of the information about the shift in one isotherm: I_c =
/// (median |d log M_c/d log f| / σ_c)², normalised to sum 1 (equal shares if both are flat).
fn information_shares(p: &Prepared, scatter: &[f64]) -> Vec<f64> {
    let info: Vec<f64> = (0..scatter.len())
        .map(|c| (p.median_abs_slope(c) / scatter[c]).powi(2))
        .collect();
    let total: f64 = info.iter().sum();
    if total > 0.0 && total.is_finite() {
        info.iter().map(|i| i / total).collect()
    } else {
        vec![1.0 / scatter.len() as f64; scatter.len()]
    }
}

/// The tan δ channel of each isotherm: log10 E″ − log10 E′ (independent of any vertical factor).
fn tan_channels(iso: &[Clean]) -> Vec<Prepared> {
    iso.iter()
        .map(|c| {
            Prepared::new(
                c.x.clone(),
                vec![c.log_l.iter().zip(&c.log_s).map(|(l, s)| l - s).collect()],
            )
        })
        .collect()
}

/// The joint channels scaled by each channel's scatter (its floor at least), and, with the
/// slope-weighted criterion, weighted per isotherm by the information each channel carries there
/// (E′ alone below T_g unless E″ superposes in the glass, eq. 6.1); with the scatters used.
fn weighted_channels(joint: &[Prepared], settings: &MasterSettings) -> (Vec<Prepared>, Vec<f64>) {
    let floor = settings.channel_scatter_floor_log10;
    let scatter: Vec<f64> = (0..2)
        .map(|c| {
            channel_scatter(
                joint,
                c,
                settings.grid_step_decades,
                settings.min_overlap_points,
            )
            .unwrap_or(floor)
            .max(floor)
        })
        .collect();
    let slope_weighted = settings.criterion == ShiftCriterion::SlopeWeighted;
    let mut rubbery = rubbery_side(joint);
    if slope_weighted {
        superposing_glass(joint, &mut rubbery, settings);
    }
    let weighted = joint
        .iter()
        .zip(&rubbery)
        .map(|(p, &rubbery)| {
            let q = Prepared::new(
                p.x.clone(),
                (0..2)
                    .map(|c| p.channels[c].0.iter().map(|v| v / scatter[c]).collect())
                    .collect(),
            );
            if !slope_weighted {
                q
            } else if rubbery {
                q.with_weights(information_shares(p, &scatter))
            } else {
                q.with_weights(vec![1.0, 0.0])
            }
        })
        .collect();
    (weighted, scatter)
}

/// Per isotherm, the symbol of the channel that carried its shift (the larger weight), or `None`
/// for all without per-isotherm weights.
fn carried_channels(
    weighted: &[Prepared],
    kind: crate::ModulusKind,
    n: usize,
) -> Vec<Option<String>> {
    let (storage, loss, _) = kind.symbols();
    let carried: Vec<Option<String>> = weighted
        .iter()
        .map(|p| {
            let w = &p.weights;
            (w.len() == 2).then(|| if w[0] >= w[1] { storage } else { loss }.to_string())
        })
        .collect();
    if carried.iter().any(Option::is_some) {
        carried
    } else {
        vec![None; n]
    }
}

/// Extend the slope-weighted shares from the rubbery side into the glass as far as E″ superposes
/// there within the points' own scatter (docs/MATH.md §6.2): from the warmest glassy isotherm down,
/// each neighbour pair's E″ alone, at its best pairwise shift, must mismatch by at most
/// [`GLASSY_LOSS_SCATTER_FACTOR`] times the RMS the points' noise alone gives, √(σ_a² + σ_b²) (σ of
/// each isotherm from its second differences, [`point_scatter`]); the colder isotherm of a pair that
/// passes is treated as the rubbery ones are (E″ then carries it where its E′ is flat), and the
/// first pair that fails ends the run: below it E′ alone carries the glass as before. On real
/// glassy E″ with a secondary relaxation (the shipped EMS-CA sets) the first pair already fails;
/// on a thermorheologically simple synthetic glass every pair passes except where the
/// temperature's drift within a sweep, on a steep shift law, spreads the isotherm itself.
fn superposing_glass(joint: &[Prepared], rubbery: &mut [bool], settings: &MasterSettings) {
    let loss = |p: &Prepared| Prepared::new(p.x.clone(), vec![p.channels[1].0.clone()]);
    for i in (0..joint.len().saturating_sub(1)).rev() {
        if rubbery[i] {
            continue;
        }
        if !rubbery[i + 1] {
            return;
        }
        let (a, b) = (loss(&joint[i]), loss(&joint[i + 1]));
        let Some(pair) = pair_shift(
            &a,
            &b,
            settings.grid_step_decades,
            settings.min_overlap_points,
        ) else {
            return;
        };
        let (sa, sb) = (
            point_scatter(&a.channels[0].0),
            point_scatter(&b.channels[0].0),
        );
        // (a NaN mismatch or scatter passes no test: the run ends)
        let bound = GLASSY_LOSS_SCATTER_FACTOR * (sa * sa + sb * sb).sqrt();
        if !matches!(pair.rms.partial_cmp(&bound), Some(Less | Equal)) {
            return;
        }
        rubbery[i] = true;
    }
}

/// How far above the noise's own RMS a glassy E″ pair may mismatch and still count as superposing:
/// twice. The RMS of a pair's 6–26 residuals scatters by 15–30 % about the noise's, and a spline
/// through noisy points adds a little; a secondary relaxation that does not superpose mismatches
/// by ten times the noise or more (EMS-CA).
const GLASSY_LOSS_SCATTER_FACTOR: f64 = 2.0;

/// The scatter σ of one isotherm's points about a smooth curve, from second differences (robust,
/// log10 units): σ = 1.4826·median|y₋ − 2y + y₊|/√6 (white noise gives var(y₋ − 2y + y₊) = 6σ²);
/// infinite with fewer than three points (no evidence of superposition).
fn point_scatter(y: &[f64]) -> f64 {
    let mut d: Vec<f64> = y
        .windows(3)
        .map(|w| (w[0] - 2.0 * w[1] + w[2]).abs())
        .filter(|v| v.is_finite())
        .collect();
    if d.is_empty() {
        return f64::INFINITY;
    }
    d.sort_by(f64::total_cmp);
    1.4826 * d[d.len() / 2] / 6f64.sqrt()
}

/// Whether each isotherm lies on the rubbery side of the transition: its median log10 E′ below the
/// middle of the range of those medians over all isotherms.
fn rubbery_side(joint: &[Prepared]) -> Vec<bool> {
    let med: Vec<f64> = joint
        .iter()
        .map(|p| {
            let mut v = p.channels[0].0.clone();
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        })
        .collect();
    let lo = med.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = med.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let mid = 0.5 * (lo + hi);
    med.iter().map(|&m| m < mid).collect()
}
