//! The degree and lumping arithmetic that the spectral load solve ([`super::at_load`]) and its secant
//! walk ([`super::walk`]) share: the degree rule p(L/h′, tol), the degree error from the p/2
//! comparison and the next degree after a failed check (module doc of [`super`], "Convergence"),
//! and the lumping correction's pieces (W = Σwᵢ, the amplification Σwᵢ/w*, the corrected solution;
//! module doc of [`crate::contact::numerics::reduction`]).
//!
//! Input: solutions at λ ([`LambdaSolution`]), creep terms and their [`Reduction`]; output: degrees,
//! error figures and corrected solutions. Below both of its users, so that they do not import each
//! other.

use crate::contact::numerics::at_lambda::LambdaSolution;
use crate::contact::numerics::correction::apply_gains;
use crate::contact::numerics::reduction::{calibration_mode, lump_weight, Reduction};
use crate::contact::problem::CreepTerm;

/// Degree p for a contact of half-length L on a cover h′ at `tol`: the measured convergence of the
/// layer term (tests: the error falls like 10^{−2.5·p·h′/L}), rounded up to a multiple of 4, ≥ 8.
pub fn degree_for(l: f64, thickness: f64, tol: f64) -> usize {
    let p = 0.5 * (1.0 / tol).log10() * l / thickness;
    ((p / 4.0).ceil() as usize * 4).max(8)
}

/// Solutions at degrees p, p/2 and p/4 at one λ.
pub(crate) type Triple = (LambdaSolution, LambdaSolution, LambdaSolution);

/// N′ and the coefficients of a reduced solution divided by s = 1 + Σ_lumped fᵢ/bᵢ.
pub(crate) fn unscale(red: &Reduction, mut s: LambdaSolution) -> LambdaSolution {
    s.load /= red.scale;
    for c in s.coefficients.iter_mut() {
        *c /= red.scale;
    }
    s
}

/// The share of tol the p/2 check leaves to the degree: 0.3·tol over the lumping's amplification
/// 1 + 2·Σwᵢ/w* of the calibration's error (the estimate counts the degree error that many times,
/// `at_load::estimate`; without it a cover at h/λ_HS = 0.03 with Σwᵢ/w* = 1.2 passed the check and
/// missed tol, estimate 1.2e−4 at 1e−4).
pub(crate) fn degree_budget(terms: &[CreepTerm], red: &Reduction, lambda: f64, tol: f64) -> f64 {
    0.3 * tol / (1.0 + 2.0 * amplification(terms, red, lambda))
}

/// Σwᵢ/w* at λ: the lumped modes' weight over the calibration mode's (or its probe's), 0 when
/// nothing is lumped (`at_load::calibrate`).
pub(crate) fn amplification(terms: &[CreepTerm], red: &Reduction, lambda: f64) -> f64 {
    let Some((star, c_probe)) = calibration_mode(terms, &red.lumped, lambda) else {
        return 0.0;
    };
    let weight: f64 = red
        .lumped
        .iter()
        .map(|&i| lump_weight(&terms[i], lambda))
        .sum();
    // the probe (b = c_probe/L, f/b kept) has the weight (f/b)/c_probe
    let w_star = if c_probe.is_finite() {
        terms[star].f / terms[star].b / c_probe
    } else {
        lump_weight(&terms[star], lambda)
    };
    let a = weight / w_star;
    if a.is_finite() {
        a
    } else {
        0.0
    }
}

/// A reduced solution at λ with the lumping correction of gains `g` applied (W = Σwᵢ at λ;
/// `numerics::correction::apply_gains`).
pub(crate) fn corrected(
    mut s: LambdaSolution,
    w_lambda: f64,
    g: (f64, f64, f64),
) -> LambdaSolution {
    apply_gains(&mut s, w_lambda, g);
    s
}

/// (ρF/N, λ) error of the degree-p solution `full` from its difference with the p/2 one `half` at
/// the same λ (module doc of [`super`]): the λ error from the N′ error through d ln N′/d ln λ ≥ ½,
/// and ρF/N moves with λ at most twice as fast.
pub(crate) fn degree_error(half: &LambdaSolution, full: &LambdaSolution) -> (f64, f64) {
    let e_ld = rel(half.load, full.load);
    let e_fr =
        rel(half.friction_rho, full.friction_rho).max((half.beta - full.beta).abs() / full.lambda);
    let e_lambda = 2.0 * e_ld;
    (e_fr + 2.0 * e_lambda, e_lambda)
}

/// Decades per degree by which the degree error falls at L/h′ (measured on 1-, 10- and 30-term
/// spectra, h/λ_HS = 0.05…3, ν = 0.3 and ½, against degree 80: 1.2 decades per degree at
/// L/h′ ≈ 0.2, 0.9 at 1.1, 0.7 at 2.2, 0.5 at 4.4; the fit 1.2/(1 + 0.3·L/h′) lies at or below
/// each).
fn decay_rate(l_over_h: f64) -> f64 {
    1.2 / (1.0 + 0.3 * l_over_h)
}

/// The degree after a p/2 check that failed with error `e` at degree p: the p/2 error falls by
/// [`decay_rate`] decades per degree, so q/2 = p/2 + log₁₀(10e/tol)/rate brings it to tol/10
/// (a third of the check's 0.3·tol); a multiple of 4 between p + 4 and 4p, at most `cap`. The p/2
/// check at q still decides (one more step when the rate was optimistic).
pub(crate) fn next_degree(p: usize, e: f64, tol: f64, l_over_h: f64, cap: usize) -> usize {
    let rate = decay_rate(l_over_h);
    let half = 0.5 * p as f64 + (10.0 * e / tol).log10().max(0.0) / rate;
    let q = ((2.0 * half / 4.0).ceil().min(1e6) as usize * 4).clamp(p + 4, 4 * p);
    q.min(cap)
}

pub(crate) fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / a.abs().max(b.abs())
    }
}
