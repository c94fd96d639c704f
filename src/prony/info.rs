//! What a Prony fit reports besides the spectrum ([`PronyInfo`]): fit errors, term counts, the chosen
//! regularisation weight and the rule, and how the solver ended. Success carries diagnostics.

use super::WeightRule;
use serde::{Deserialize, Serialize};

/// One point of the regularisation-weight search.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LambdaCandidate {
    /// Weight λ of the second-difference term (scaled problem, dimensionless).
    pub lambda: f64,
    /// Residual norm ‖A x − 1‖ of the relative residuals of E′ and E″ together.
    pub residual_norm: f64,
    /// Seminorm ‖L x‖ of the scaled spectrum's second differences.
    pub seminorm: f64,
    /// The rule's score at this λ: L-curve curvature (largest wins) or GCV value (smallest wins);
    /// `None` where the rule gives none (end points of the L-curve, no counter-clockwise turn).
    pub score: Option<f64>,
}

/// Diagnostics of a Prony fit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PronyInfo {
    /// RMS over the points of log10(E′_fit / E′_data), each weighted as in the fit (docs/MATH.md eq. 5.1).
    pub rms_log10_storage: f64,
    /// RMS over the points of log10(E″_fit / E″_data), each weighted as in the fit (docs/MATH.md eq. 5.1).
    pub rms_log10_loss: f64,
    /// Largest |log10(E′_fit / E′_data)|.
    pub max_abs_log10_storage: f64,
    /// Largest |log10(E″_fit / E″_data)|.
    pub max_abs_log10_loss: f64,
    /// Master-curve points fitted.
    pub n_points: usize,
    /// When the master curve had more than `super::fit::THIN_ABOVE_POINTS` points: how many. The
    /// fit then used `n_points` means of equal-count groups in log-frequency (the errors above are
    /// against those means).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub thinned_from_points: Option<usize>,
    /// Relaxation times on the grid (before dropping zeros).
    pub n_terms_grid: usize,
    /// Terms kept (after dropping zeros).
    pub n_terms_kept: usize,
    /// Threshold used to drop a term (largest relative contribution to any datum).
    pub drop_threshold: f64,
    /// The rule that chose λ.
    pub weight_rule: WeightRule,
    /// The chosen λ.
    pub lambda: f64,
    /// The λ search (empty for a fixed λ).
    pub lambda_search: Vec<LambdaCandidate>,
    /// clarabel's status of the solve at the chosen λ (`Solved`, `AlmostSolved`, …).
    pub solver_status: String,
    /// Interior-point iterations of the solve at the chosen λ.
    pub iterations: u32,
    /// Interior-point iterations over all solves of the λ search.
    pub total_iterations: u32,
    /// Reduced-frequency window of the data, [min, max] in Hz.
    pub freq_window_hz: [f64; 2],
    /// Relaxation-time grid, [smallest, largest] in s.
    pub tau_window_s: [f64; 2],
    /// Modulus scale in Pa that normalises the unknowns (the largest E′ datum).
    pub modulus_scale_pa: f64,
    /// RMS log10 errors [E′, E″] of the dense grid fit before the term reduction (equal to the
    /// final ones when no reduction ran).
    #[serde(default)]
    pub dense_rms_log10: Option<[f64; 2]>,
    /// Terms of the dense grid fit (after dropping zeros) before the reduction.
    #[serde(default)]
    pub dense_terms: Option<usize>,
    /// The target [E′, E″] RMS log10 the reduction aimed for.
    #[serde(default)]
    pub term_target_rms_log10: Option<[f64; 2]>,
    /// Whether the reduced spectrum meets the target (false: `max_terms` was too few).
    #[serde(default)]
    pub term_target_met: Option<bool>,
    /// The trade of terms against errors found by the reduction (most terms first).
    #[serde(default)]
    pub term_trade: Vec<super::TermTrade>,
    /// A fit in time (docs/MATH.md §18): the time function fitted and its errors. Then the E′ and E″
    /// error fields above hold that function's errors, and `freq_window_hz` the window it determines.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub time_domain: Option<super::time_fit::TimeFitInfo>,
}
