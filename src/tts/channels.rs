//! Second phase of the master curve: the channels the shifting compares, built from the cleaned
//! isotherms ([`Clean`]) and the vertical factors known before shifting.
//!
//! - `joint`: log10 E′ and log10 E″ (less log10 b_T), always built (the quality figures use it);
//! - `tan`: log10 tan δ, for the tan δ criterion and for fitted vertical shifts;
//! - `storage`: log10 E′ alone, the default criterion;
//! - `weighted`: the joint channels each divided by its own scatter (docs/MATH.md §6): maximum
//!   likelihood with an unknown variance per channel, so a channel that cannot be superposed (an
//!   instrument resonance in E″, a secondary relaxation) gives way to the one that can.

use super::clean::Clean;
use super::settings::{MasterSettings, ShiftCriterion, ShiftSource, VerticalShift};
use super::shift::{channel_scatter, Prepared};

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
}

impl Channels {
    /// Build the channels `settings` asks for; `log_b` are the vertical factors known before
    /// shifting (zero, or from temperature).
    pub fn prepare(iso: &[Clean], log_b: &[f64], settings: &MasterSettings) -> Channels {
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
        let tan: Vec<Prepared> = if use_tan {
            iso.iter()
                .map(|c| {
                    Prepared::new(
                        c.x.clone(),
                        vec![c.log_l.iter().zip(&c.log_s).map(|(l, s)| l - s).collect()],
                    )
                })
                .collect()
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
        let mut channel_scatter_log10 = Vec::new();
        let weighted: Vec<Prepared> =
            if !use_tan && storage.is_empty() && settings.shift == ShiftSource::Auto {
                let floor = settings.channel_scatter_floor_log10;
                channel_scatter_log10 = (0..2)
                    .map(|c| {
                        channel_scatter(
                            &joint,
                            c,
                            settings.grid_step_decades,
                            settings.min_overlap_points,
                        )
                        .unwrap_or(floor)
                        .max(floor)
                    })
                    .collect();
                joint
                    .iter()
                    .map(|p| {
                        Prepared::new(
                            p.x.clone(),
                            (0..2)
                                .map(|c| {
                                    p.channels[c]
                                        .0
                                        .iter()
                                        .map(|v| v / channel_scatter_log10[c])
                                        .collect()
                                })
                                .collect(),
                        )
                    })
                    .collect()
            } else {
                Vec::new()
            };
        Channels {
            joint,
            tan,
            storage,
            weighted,
            channel_scatter_log10,
            use_tan,
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
