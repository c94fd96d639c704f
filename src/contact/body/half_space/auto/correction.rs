//! The first-order correction for the lumped fast modes ([`crate::contact::numerics::reduction`] module doc): the
//! model gains, their measurement by one extra solve (calibration), applying them, and the error
//! that remains (second order, plus the round-off floor of the corrected friction). The pieces the
//! spectral layer shares (the weight W, the calibration's terms, the gains measured and applied)
//! are `contact::numerics::correction`; the calibration's single solve at the solution's degree,
//! the remaining error and the floor are this scheme's own.
//!
//! Input: the creep terms, the [`Reduction`] and a reduced [`LambdaSolution`]; output: a
//! [`Correction`] and error estimates.

use crate::contact::numerics::at_lambda::{LambdaSolution, QuadratureSettings};
pub(super) use crate::contact::numerics::correction::lumped_weight_times_lambda;
use crate::contact::numerics::correction::{apply_gains, calibration, measured_gains};
use crate::contact::numerics::reduction::{
    lumped_residual, model_gains, solve_reduced, unlump, Reduction,
};
use crate::contact::problem::CreepTerm;

/// The measured first-order correction for the lumped modes ([`reduction`] module doc).
#[derive(Debug, Clone, Copy)]
pub(super) struct Correction {
    /// Effects per unit lumping weight: Δ(ρF/N/λ), ΔN′/N′, Δβ (the measured gains g_F, g_N, g_β).
    pub(super) gains: (f64, f64, f64),
    /// Σwᵢ/w* of the calibration: how much the calibration solve's noise is amplified.
    pub(super) amplification: f64,
}

impl Correction {
    /// The model's gains, before any measurement (β unknown: 0).
    pub(super) fn model(terms: &[CreepTerm], lambda: f64) -> Correction {
        let (g_f, g_n) = model_gains(terms, lambda);
        Correction {
            gains: (g_f, g_n, 0.0),
            amplification: 0.0,
        }
    }

    /// Apply at the solution's λ: ρF/N += λ·g_F·W, N′ ×= 1 + g_N·W, β += g_β·W (W = Σwᵢ); the
    /// pressure is scaled with N′ (the layer correction itself is not added to the profile).
    pub(super) fn apply(&self, terms: &[CreepTerm], red: &Reduction, sol: &mut LambdaSolution) {
        apply_gains(sol, lumped_weight_times_lambda(terms, red), self.gains);
    }
}

/// Measure the gains at the solution's λ by one solve with the lumped mode of largest weight kept,
/// or the probe that stands in for it when it is too fast to solve for
/// ([`reduction::calibration_mode`]): the probe kept minus the mode lumped is the probe's own
/// layer effect g·w_p, w_p = rᵢ/c_p. Returns the model gains (and amplification 0) when nothing is
/// lumped or the solve fails.
pub(super) fn calibrate(
    terms: &[CreepTerm],
    red: &Reduction,
    sol: &LambdaSolution,
    q: QuadratureSettings,
) -> Correction {
    let lambda = sol.lambda;
    let model = Correction::model(terms, lambda);
    let Some(cal) = calibration(terms, &red.lumped, lambda) else {
        return model;
    };
    let weight = lumped_weight_times_lambda(terms, red) / lambda;
    let Ok(with) = solve_reduced(&unlump(&cal.terms, red, cal.star), lambda, q) else {
        return model;
    };
    let Some(g) = measured_gains(&with, sol, lambda, cal.w_star) else {
        return model;
    };
    Correction {
        gains: g,
        amplification: weight / cal.w_star,
    }
}

/// Remaining lumping error after the correction (ρF/N/λ absolute, N′ relative): the second-order
/// estimate, plus, without a measurement, the whole (model) effect twice.
pub(super) fn lumping_error(
    terms: &[CreepTerm],
    red: &Reduction,
    corr: &Correction,
    lambda: f64,
) -> (f64, f64) {
    let (e_fr, e_ld) = lumped_residual(terms, &red.lumped, lambda, (corr.gains.0, corr.gains.1));
    if corr.amplification > 0.0 {
        (e_fr, e_ld)
    } else {
        let w = lumped_weight_times_lambda(terms, red) / lambda;
        (e_fr + 2.0 * corr.gains.0 * w, e_ld + 2.0 * corr.gains.1 * w)
    }
}

/// Relative round-off floor of the corrected ρF/N. Each solve's ρF/N = L − β + L·F₂/(2F₁) (eq. in
/// `auto`'s module doc) is a difference of O(λ) terms, each a sum over the n Chebyshev
/// coefficients, so its absolute error is bounded by n·ε·(λ + |β|) (the worst-case bound of a sum of
/// n terms, Higham, *Accuracy and Stability of Numerical Algorithms*, 2nd ed., eq. 4.4; n ≥ 8):
/// once for the reduced solve (none when every mode is lumped or dropped: the elastic solve gives
/// β = L and F₂ = 0 exactly), and for the lumping correction twice (the calibration is a difference
/// of two solves) times its amplification Σwᵢ/w*. Large relative to a small friction.
///
/// The former 8ε was exceeded 4× (a tol 1e−6 solve claimed 2.8e−12 and was 1.2e−11 from a tol
/// 1e−10 one, n = 132; `VISCOROLL_SEED=0x1db992c883b85c68`, case 1 of `contact_props`).
pub(super) fn roundoff_floor(sol: &LambdaSolution, red: &Reduction, corr: &Correction) -> f64 {
    let solves = if red.modes_used > 0 { 1.0 } else { 0.0 } + 2.0 * corr.amplification;
    let n = sol.coefficients.len().max(8) as f64;
    n * f64::EPSILON * solves * (sol.lambda + sol.beta.abs()) / sol.friction_rho.abs().max(1e-300)
}
