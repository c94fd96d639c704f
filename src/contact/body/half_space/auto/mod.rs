//! The error-controlled `auto` contact solver: tolerance → mode selection, quadrature step and load
//! iteration; every answer carries its error estimate and the contact-condition checks.
//!
//! Input: creep terms ([`CreepTerm`]), λ or N′, [`AutoSettings`]; output: a [`DimensionlessSolution`]
//! with `scheme = "auto"`, its [`Diagnostics`](crate::contact::problem::Diagnostics) (mode counts, checks) and warnings, or a
//! [`ContactError`].
//!
//! Error budget for a relative tolerance `tol` on ρ·F/N and λ (or N′ at given λ; docs/MATH.md §9):
//! - mode reduction ([`reduction`](crate::contact::numerics::reduction)): ≤ 0.3·tol, re-selected until the estimate, evaluated with
//!   the friction of the solution itself, fits. Lumped fast modes are *corrected* to first order:
//!   one extra solve at the final λ with the lumped mode of largest weight kept measures the gains
//!   (g_F, g_N, g_β) of ρF/N/λ, ln N′ and β per unit lumping weight, and g·Σwᵢ is added to the
//!   answer; the remaining error is the second-order estimate of [`reduction`](crate::contact::numerics::reduction). At given load
//!   the loop solves N′_lumped(λ)(1 + g_N·W(λ)) = N′, first with the model gain, then (when the
//!   measured one moves the target) on from the λ found;
//! - quadrature ([`at_lambda`](crate::contact::numerics::at_lambda)): step h = 0.6 for tol ≥ 1e−4, 0.4 for tol ≥ 1e−7, 0.3 below
//!   (measured errors ≤ 5e−8, 2e−11, ~1e−15: ≈ e^{−π²/h} with a constant ≤ 1 on 1–30-term
//!   problems); the estimate is 10·e^{−π²/(2h)} times the difference to the same sum on every second
//!   node (step 2h, from the same exterior values: no second solve). The calibration is a difference
//!   of two solves, so its noise, amplified by Σwᵢ/w*, is added;
//! - load loop: a safeguarded secant on ln N′(ln λ) inside the bracket [2√N′, 2√(S·N′)]
//!   (docs/MATH.md §3: N′ grows with λ; glassy and relaxed compliance bound it), started from
//!   λ = 2√(S_eff N′) with the model slope 2 − d ln S_eff/d ln λ and stopped when the step is below
//!   0.05·tol; the step not taken (and a target shift by the measured gain too small to chase)
//!   counts twice in the λ error.
//!
//! Measured (`cargo bench --bench contact_auto`, docs/DEVLOG.md table; CPU time of one thread per load
//! point): one term 20/32/40 µs at tol 1e−3/1e−6/1e−9; 10 terms 0.09/0.33/0.96 ms; 30 terms over 24
//! decades 0.17/0.65/1.55 ms (before the measured lumping correction: 1.7/10/51 ms), i.e. 4–6
//! solves per load point. Estimates are ≤ tol and 2–66× the true error against tol 1e−10 solves
//! (tests/contact_auto.rs); over 4400 random spectra and scenes and the measured TRIOS and EMS-CA
//! spectra over ln s = −48…8 no estimate misses (tests/contact_props.rs).
//!
//! The reported `error_estimate` is the largest of the relative errors of ρF/N and of λ (at given
//! load) or N′ (at given λ).

mod correction;
mod gap_check;
mod load;
mod outcome;
mod settings;

pub use load::solve_auto_at_load;
pub use settings::AutoSettings;

use crate::contact::error::ContactError;
use crate::contact::numerics::reduction::{select, slow_estimate_at, solve_reduced_checked};
use crate::contact::problem::{CreepTerm, DimensionlessSolution};
use correction::{
    calibrate, lumped_weight_times_lambda, lumping_error, roundoff_floor, Correction,
};
use outcome::package;
use settings::{budgets, quad_for, validate};

/// Solve at given contact length λ > 0.
pub(crate) fn solve_auto_at_lambda(
    terms: &[CreepTerm],
    lambda: f64,
    settings: &AutoSettings,
) -> Result<DimensionlessSolution, ContactError> {
    validate(terms, settings.tol)?;
    if !(lambda > 0.0 && lambda.is_finite()) {
        return Err(ContactError::BadValue {
            field: "lambda".into(),
            expected: "finite and > 0",
            value: lambda,
        });
    }
    let tol = settings.tol;
    let q = quad_for(tol);
    // First pass: budget from a friction guess of 1e−2·λ and the model gains; then from the
    // solution's own friction and the measured gains.
    let mut fr_guess = 1e-2;
    let mut corr = Correction::model(terms, lambda);
    let mut pass = 0;
    let (red, sol, e_fr, e_ld, num_fr, num_ld) = loop {
        pass += 1;
        let (bf, bl) = budgets(tol, fr_guess);
        let red = select(terms, lambda, bf, bl, (corr.gains.0, corr.gains.1));
        let (sol, num_fr, num_ld) = solve_reduced_checked(&red, lambda, q)?;
        corr = calibrate(terms, &red, &sol, q);
        let (l_fr, l_ld) = lumping_error(terms, &red, &corr, lambda);
        let (s_fr, s_ld) = slow_estimate_at(terms, &red, lambda);
        let (e_fr, e_ld) = (l_fr + s_fr, l_ld + s_ld);
        let fr = sol.friction_rho / lambda
            + corr.gains.0 * lumped_weight_times_lambda(terms, &red) / lambda;
        if (e_fr <= 0.3 * tol * fr.abs() && e_ld <= 0.3 * tol) || pass >= 4 {
            break (red, sol, e_fr, e_ld, num_fr, num_ld);
        }
        fr_guess = fr.abs();
    };
    let mut sol = sol;
    corr.apply(terms, &red, &mut sol);
    let fr = sol.friction_rho;
    // the calibration is a difference of two solves with the same quadrature: its noise is at most
    // twice their error, amplified by Σwᵢ/w*
    let amp = 1.0 + 2.0 * corr.amplification;
    let floor = roundoff_floor(&sol, &red, &corr);
    let friction_error = amp * num_fr + e_fr * lambda / fr.abs().max(1e-300) + floor;
    let size_error = amp * num_ld + e_ld;
    Ok(package(
        terms,
        &red,
        sol,
        0,
        (friction_error, floor),
        size_error,
        settings,
    ))
}
