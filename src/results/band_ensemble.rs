//! The bootstrap ensemble of a compound's fit ([`BandEnsemble`]), saved in its fit file so that
//! `viscoroll roll` and a re-run give the same uncertainty bands without the measurement.
//!
//! Input: made by crate::bands (the replicates of the Prony fit and shift law, docs/MATH.md §15);
//! output: plain serde data read back by crate::bands to solve each replicate's contact.

use crate::CreepSpectrum;
use crate::ShiftLaw;
use serde::{Deserialize, Serialize};

/// What crate::bands estimated of the measurement's own scatter (the inputs of the bootstrap).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ScatterEstimate {
    /// RMS of ln(E′ measured / E′ fitted) over the master-curve points (isotherm overlap and fit
    /// residuals together).
    pub storage_rms_ln: f64,
    /// The same for E″.
    pub loss_rms_ln: f64,
    /// Largest standard error of an isotherm's shift log10 a_T, from the shift stage's least squares
    /// over the isotherm overlaps (crate::tts), decades.
    pub shift_std_max_log10: f64,
    /// Largest standard error of an isotherm's temperature from its drift during the sweep (the
    /// standard deviation of the point temperatures over √n), K; 0 when the file carries no point
    /// temperatures.
    pub temp_std_max_k: f64,
    /// Master-curve points resampled.
    pub n_points: usize,
}

/// One bootstrap replicate: the creep spectrum refitted on resampled data and its shift law.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BandReplicate {
    /// The replicate's creep spectrum at the fit's reference temperature.
    pub creep: CreepSpectrum,
    /// (T in °C, Δ log10 a_T) added to the fit's shift law: linear between rows, constant beyond the
    /// end rows.
    pub shift_offsets: Vec<(f64, f64)>,
}

impl BandReplicate {
    /// log10 a_T of the replicate at `temp_c`: the fit's law plus the interpolated offset.
    pub fn log10_a_t(&self, law: &ShiftLaw, temp_c: f64) -> f64 {
        law.log10_a_t(temp_c) + offset_at(&self.shift_offsets, temp_c)
    }
}

/// Linear interpolation in `rows` (sorted by T), constant beyond the ends; 0 without rows.
pub fn offset_at(rows: &[(f64, f64)], t: f64) -> f64 {
    match rows {
        [] => 0.0,
        [only] => only.1,
        _ => {
            let (first, last) = (rows[0], rows[rows.len() - 1]);
            if t <= first.0 {
                return first.1;
            }
            if t >= last.0 {
                return last.1;
            }
            let k = rows.partition_point(|r| r.0 <= t).clamp(1, rows.len() - 1);
            let (a, b) = (rows[k - 1], rows[k]);
            a.1 + (b.1 - a.1) * (t - a.0) / (b.0 - a.0)
        }
    }
}

/// What the replicates drew of the fit's own choices (crate::bands::model; docs/MATH.md §15,
/// eqs. 15.10–15.12).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ModelErrorSummary {
    /// The other shift criteria whose shifts were drawn (eq. 15.10); empty for a master curve
    /// read already shifted or shifted by a given law.
    pub criteria: Vec<String>,
    /// Largest difference of their shifts from the fit's, decades.
    pub criterion_max_log10: f64,
    /// Largest interpolation error of the shift table at an interval's middle (eq. 15.11), decades.
    pub interpolation_max_log10: f64,
    /// Decades either side of the fit's λ the replicates' λ were drawn from (eq. 15.12).
    pub lambda_spread_decades: f64,
}

/// The bootstrap ensemble of a fit (crate::bands; docs/MATH.md §15).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BandEnsemble {
    /// How the replicates were made, in words.
    pub method: String,
    /// Replicates asked for.
    pub replicates_requested: usize,
    /// Seed of the resampling (same seed, same replicates).
    pub seed: u64,
    /// The scatter the replicates were drawn from.
    pub scatter: ScatterEstimate,
    /// The replicates whose refit succeeded.
    pub replicates: Vec<BandReplicate>,
    /// Notes (failed refits, what the bands leave out).
    #[serde(default)]
    pub notes: Vec<String>,
    /// The fit's own choices the replicates drew (`None` in files made before they did).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub model_error: Option<ModelErrorSummary>,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_interpolate_linearly_and_hold_beyond_the_ends() {
        let rows = [(0.0, 0.1), (10.0, 0.3)];
        assert_eq!(offset_at(&rows, -5.0), 0.1);
        assert_eq!(offset_at(&rows, 20.0), 0.3);
        assert!((offset_at(&rows, 5.0) - 0.2).abs() < 1e-15);
        assert_eq!(offset_at(&[], 5.0), 0.0);
    }
}
