//! The answer of the `auto` scheme: the pressure profile, the contact checks (inside: Q′ ≥ 0;
//! outside: [`super::gap_check`]), the warnings, the zero-answer case and the error estimate, packed
//! into a [`DimensionlessSolution`] with its [`Diagnostics`].
//!
//! Input: the reduced problem, the corrected [`LambdaSolution`] and the error estimates; output: the
//! [`DimensionlessSolution`].

use super::gap_check::gap_check;
use super::settings::AutoSettings;
use crate::contact::numerics::at_lambda::LambdaSolution;
use crate::contact::numerics::reduction::Reduction;
use crate::contact::problem::Diagnostics;
use crate::contact::problem::{CreepTerm, DimensionlessSolution};

/// Pack a corrected solution with its estimates (`friction_error`, its round-off part `floor`,
/// `size_error`) into the scheme's answer.
pub(super) fn package(
    terms: &[CreepTerm],
    red: &Reduction,
    sol: LambdaSolution,
    iterations: usize,
    (friction_error, floor): (f64, f64),
    size_error: f64,
    settings: &AutoSettings,
) -> DimensionlessSolution {
    // min Q′/max Q′ over the whole FFT grid (finer than the returned profile)
    let (xi, pressure, min_pressure_ratio) = sol.profile(settings.profile_points.max(8));
    let mut warnings = Vec::new();
    if min_pressure_ratio < -settings.tol {
        warnings.push(format!(
            "pressure goes negative inside the contact (min/max = {min_pressure_ratio:.3e}): \
             the contact condition Q' ≥ 0 fails"
        ));
    }
    let (min_gap_ratio, min_gap_xi) = gap_check(red, &sol, settings, &mut warnings);
    let modes_total = terms.iter().filter(|t| t.f > 0.0).count();
    let (friction_error, size_error, zero_answer) =
        zero_answer_errors(friction_error, size_error, modes_total, &mut warnings);
    let error_estimate = friction_error.max(size_error);
    if error_estimate > settings.tol && !zero_answer {
        warnings.push(tolerance_warning(&sol, error_estimate, floor, settings.tol));
    }
    let n = sol.coefficients.len();
    DimensionlessSolution {
        scheme: "auto".into(),
        lambda: sol.lambda,
        beta: sol.beta,
        load: sol.load,
        friction_rho: sol.friction_rho,
        xi,
        pressure,
        n,
        iterations,
        error_estimate: Some(error_estimate),
        diagnostics: Some(Diagnostics {
            modes_used: red.modes_used,
            modes_total,
            modes_lumped: red.lumped.len(),
            modes_dropped: red.dropped.len(),
            friction_error,
            size_error,
            min_pressure_ratio,
            min_gap_ratio,
            min_gap_xi,
            tol: settings.tol,
        }),
        warnings,
    }
}

/// When every mode is lumped (or dropped) the reduced problem is elastic and ρF/N = 0 exactly; the
/// relative estimates are then 0/0 = NaN, which `f64::max` would silently drop. The relative error
/// of a zero answer against a non-zero truth is exactly 1: report that (and say so). Returns the
/// friction and size errors and whether the answer is such a zero.
fn zero_answer_errors(
    friction_error: f64,
    size_error: f64,
    modes_total: usize,
    warnings: &mut Vec<String>,
) -> (f64, f64, bool) {
    let zero_answer = friction_error.is_nan();
    let friction_error = if zero_answer {
        if modes_total == 0 {
            0.0 // elastic input: ρF/N = 0 is exact
        } else {
            warnings.push(
                "every creep mode was lumped or dropped: ρF/N = 0 is the elastic limit, its relative \
                 error is 100 % (the scene lies far outside the spectrum's time range)"
                    .to_string(),
            );
            1.0
        }
    } else {
        friction_error
    };
    let size_error = if size_error.is_nan() { 1.0 } else { size_error };
    (friction_error, size_error, zero_answer)
}

/// The warning for an estimate above the tolerance, with its cause: the round-off floor of a small
/// friction, or the lumping of modes too fast to solve for.
fn tolerance_warning(sol: &LambdaSolution, error_estimate: f64, floor: f64, tol: f64) -> String {
    let why = if floor >= 0.5 * error_estimate {
        format!(
            "ρF/N is only {:.1e} of the contact length, and its round-off alone (ρF/N = L − β + …, \
             a difference of O(λ) terms) is {floor:.1e} relative",
            sol.friction_rho / sol.lambda
        )
    } else {
        "the rest of the estimate comes from the mode reduction, which lumps modes with \
         c = bλ/2 > 1e7 or μ = (b + f)λ/2 > 1e9 whatever the tolerance (their effect is \
         corrected to first order and its remainder estimated)"
            .to_string()
    };
    format!("tolerance not reached: estimated relative error {error_estimate:.1e} > tol {tol:.0e}; {why}")
}
