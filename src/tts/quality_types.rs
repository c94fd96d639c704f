//! What the master curve says about each isotherm ([`IsothermShift`]) and about its own quality
//! ([`MasterQuality`]): plain serde data, below both the curve's build (`master`) and its
//! assessment (`assess`), which fills them.
//!
//! Input: nothing (plain data); output: read by `master`, `assess` and the stages above.

use super::quality::QualityBounds;
use serde::{Deserialize, Serialize};

/// The shift of one isotherm and its quality figures.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct IsothermShift {
    /// Index in `Measurement::isotherms`.
    pub measurement_index: usize,
    /// Nominal temperature, °C.
    pub temp_nominal_c: f64,
    /// Temperature used for the shift laws, °C.
    pub temp_c: f64,
    /// log10 a_T relative to T_ref.
    pub log10_a_t: f64,
    /// Standard error of log10 a_T from the global least squares, docs/MATH.md eq. 6.2 (0 for the
    /// reference isotherm and for a given law).
    pub log10_a_t_std: f64,
    /// log10 b_T (0 without vertical shift).
    pub log10_b_t: f64,
    /// Points used.
    pub points_used: usize,
    /// Points left out (non-finite or non-positive f, E′ or E″; repeated frequencies merged).
    pub points_dropped: usize,
    /// RMS mismatch of log10 E′ in its overlaps with its nearest neighbours at the final shifts and
    /// vertical factors, log10 units, whatever the criterion (`None`: overlaps nothing;
    /// docs/MATH.md §6.5).
    pub overlap_rms_log10: Option<f64>,
    /// The same for log10 E″: whether E″ superposes at these shifts (a direct test of
    /// thermorheological simplicity where E′ carried the shift).
    #[serde(default)]
    pub loss_overlap_rms_log10: Option<f64>,
    /// van Gurp–Palmen RMS against its neighbours, degrees.
    pub vgp_rms_deg: Option<f64>,
    /// Median log10 of (π/2)·dE′/d ln ω over E″ (local Kramers–Kronig).
    pub kk_median_log10_ratio: Option<f64>,
    /// Quality figures out of bounds, in words.
    pub flags: Vec<String>,
    /// The channel that carried the shift (`E′` or `E″`), with the slope-weighted criterion.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shift_channel: Option<String>,
    /// Whether the overlaps with its neighbours determine its shift (docs/MATH.md §6.6); if not, the
    /// shift is still where the overlaps put it, flagged (see `MasterCurve::warnings`).
    #[serde(default = "yes")]
    pub shift_determined: bool,
}

fn yes() -> bool {
    true
}

/// Summary of the quality figures.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MasterQuality {
    /// The bounds applied.
    pub bounds: QualityBounds,
    /// Worst overlap RMS over the isotherms, log10 units.
    pub overlap_rms_max_log10: f64,
    /// RMS over all isotherms' overlap RMS, log10 units.
    pub overlap_rms_log10: f64,
    /// Worst E″-alone overlap RMS at the final shifts, log10 units.
    #[serde(default)]
    pub loss_overlap_rms_max_log10: f64,
    /// Worst van Gurp–Palmen RMS, degrees.
    pub vgp_rms_max_deg: f64,
    /// Largest |median log10 ratio| of the local Kramers–Kronig rule.
    pub kk_max_abs_log10_ratio: f64,
    /// All van Gurp–Palmen figures within bound.
    pub thermorheologically_simple: bool,
    /// Outer iterations of the global shift refinement (0 for a given law).
    pub global_iterations: usize,
    /// Joint criterion: scatter of log10 E′ and log10 E″ each superposed alone (the inverse
    /// weights), log10 units; empty for other criteria.
    pub channel_scatter_log10: Vec<f64>,
    /// Largest per-point temperature correction applied, decades of frequency (0 when off).
    #[serde(default)]
    pub point_temperature_correction_max_log10: f64,
    /// Corrected shifting passes run (0 when off).
    #[serde(default)]
    pub point_temperature_passes: usize,
    /// Every flag, prefixed with its isotherm's temperature.
    pub flags: Vec<String>,
    /// Temperatures (°C) of the isotherms whose shift the overlaps do not determine (flagged, not
    /// moved, docs/MATH.md §6.6): later stages mark results that rest on them.
    #[serde(default)]
    pub shift_not_determined_c: Vec<f64>,
    /// Temperatures (°C) of the isotherms left out of the master curve: shifts not determined by
    /// overlap and out of order (docs/MATH.md §6.6); named in the warnings.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub left_out_c: Vec<f64>,
    /// Covariance of the isotherms' log10 a_T (docs/MATH.md eq. 6.2), indexed like
    /// `MasterCurve::isotherms`, zero in the reference's row and column; empty for given shifts.
    /// The bands draw their replicates' shifts from it (§15, eq. 15.2).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub shift_covariance_log10: Vec<Vec<f64>>,
}
