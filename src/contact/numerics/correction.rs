//! The pieces of the first-order lumping correction that the half-space `auto` scheme
//! (`body/half_space/auto/correction.rs`) and the spectral layer (`body/layer/spectral/at_load.rs`)
//! share ([`super::reduction`] module doc, docs/MATH.md §8): the lumped modes' weight W, the
//! calibration solve's terms (the lumped mode of largest weight kept, or the probe that stands in for
//! it), the gains measured from it, and the gains applied to a reduced solution.
//!
//! Input: creep terms, a [`Reduction`], reduced [`LambdaSolution`]s at one λ; output: W·λ, a
//! [`Calibration`], measured [`Gains`], a corrected solution. Not here, because the two differ: how
//! often and at which degree the calibration solve is made (the layer measures its gains at degrees
//! p and p/2, for their own degree error), the amplification Σwᵢ/w* (each body sums the weights its
//! own way), the remaining-error estimate around `reduction::lumped_residual` (the half-space adds
//! the whole model effect twice when nothing was measured; the layer adds the gains' degree error
//! and their drift to the λ found) and the round-off floor (n·ε per solve on the half-space, 8ε on
//! the layer, each measured for its scheme).

use super::at_lambda::LambdaSolution;
use super::reduction::{calibration_mode, lump_weight, Reduction};
use crate::contact::problem::CreepTerm;
use std::borrow::Cow;

/// First-order gains per unit lumping weight: Δ(ρF/N/λ), ΔN′/N′, Δβ (g_F, g_N, g_β).
pub(crate) type Gains = (f64, f64, f64);

/// W·λ = Σ wᵢ·λ over the lumped modes (wᵢ ∝ 1/λ, so this is independent of λ).
pub(crate) fn lumped_weight_times_lambda(terms: &[CreepTerm], red: &Reduction) -> f64 {
    red.lumped
        .iter()
        .map(|&i| lump_weight(&terms[i], 1.0))
        .sum()
}

/// Apply gains `g` to a reduced solution at its λ, W = `w_lambda`/λ: ρF/N += λ·g_F·W,
/// N′ ×= 1 + g_N·W (the pressure coefficients with it), β += g_β·W; unchanged when nothing is lumped
/// (W = 0).
pub(crate) fn apply_gains(sol: &mut LambdaSolution, w_lambda: f64, g: Gains) {
    let w = w_lambda / sol.lambda;
    if w == 0.0 {
        return;
    }
    sol.friction_rho += sol.lambda * g.0 * w;
    let f = 1.0 + g.1 * w;
    sol.load *= f;
    for c in sol.coefficients.iter_mut() {
        *c *= f;
    }
    sol.beta += g.2 * w;
}

/// The calibration solve at λ: the lumped mode of largest weight, `star`, kept (the caller unlumps
/// it, `reduction::unlump`) in `terms` — the creep terms themselves, or with mode `star` replaced by
/// the probe that stands in for it when it is too fast to solve for (`reduction::calibration_mode`:
/// the same fᵢ/bᵢ, rate c_p/(λ/2)), so that the probe kept minus the mode lumped is the probe's own
/// effect g·w* — and w*, its lumping weight at λ.
pub(crate) struct Calibration<'a> {
    /// Index of the mode kept.
    pub star: usize,
    /// The terms the calibration solve is made with.
    pub terms: Cow<'a, [CreepTerm]>,
    /// The lumping weight w* of the mode kept (or its probe) at λ.
    pub w_star: f64,
}

/// The [`Calibration`] of the lumped modes `lumped` of `terms` at λ; `None` when nothing is lumped.
pub(crate) fn calibration<'a>(
    terms: &'a [CreepTerm],
    lumped: &[usize],
    lambda: f64,
) -> Option<Calibration<'a>> {
    let (star, c_probe) = calibration_mode(terms, lumped, lambda)?;
    let terms = if c_probe.is_finite() {
        let l = 0.5 * lambda;
        let r = terms[star].f / terms[star].b;
        let mut probe = terms.to_vec();
        probe[star] = CreepTerm {
            f: r * c_probe / l,
            b: c_probe / l,
        };
        Cow::Owned(probe)
    } else {
        Cow::Borrowed(terms)
    };
    let w_star = lump_weight(&terms[star], lambda);
    Some(Calibration {
        star,
        terms,
        w_star,
    })
}

/// The gains measured by a calibration solve `with` (the mode kept) against the reduced solution
/// `sol` at the same λ: (Δ(ρF/N)/λ, ΔN′/N′, Δβ)/w*; `None` unless all three are finite.
pub(crate) fn measured_gains(
    with: &LambdaSolution,
    sol: &LambdaSolution,
    lambda: f64,
    w_star: f64,
) -> Option<Gains> {
    let g = (
        (with.friction_rho - sol.friction_rho) / lambda / w_star,
        (with.load - sol.load) / sol.load / w_star,
        (with.beta - sol.beta) / w_star,
    );
    (g.0.is_finite() && g.1.is_finite() && g.2.is_finite()).then_some(g)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn solution(lambda: f64) -> LambdaSolution {
        LambdaSolution {
            lambda,
            beta: 0.4,
            load: 2.0,
            friction_rho: 0.03,
            coefficients: vec![1.0, -0.5],
            mu_max: 3.0,
        }
    }

    #[test]
    fn applied_gains_are_the_measured_differences_scaled_by_the_weight() {
        // A calibration solve that moved (ρF/N, N′, β) by (d_f, d_n·N′, d_b) for a mode of weight w*
        // gives gains that, applied with W = w*, reproduce exactly that move (first order is linear).
        let lambda = 1.6;
        let sol = solution(lambda);
        let w_star = 0.25;
        let mut with = sol.clone();
        with.friction_rho += 0.004;
        with.load *= 1.1;
        with.beta -= 0.02;
        let g = measured_gains(&with, &sol, lambda, w_star).unwrap();
        let mut moved = sol.clone();
        apply_gains(&mut moved, w_star * lambda, g);
        assert!((moved.friction_rho - with.friction_rho).abs() < 1e-15);
        assert!((moved.load / with.load - 1.0).abs() < 1e-15);
        assert!((moved.beta - with.beta).abs() < 1e-15);
        assert!((moved.coefficients[0] - 1.1).abs() < 1e-15);
        // nothing lumped: unchanged, whatever the gains
        let mut same = sol.clone();
        apply_gains(&mut same, 0.0, (f64::NAN, 1.0, 1.0));
        assert_eq!(same, sol);
        // a failed calibration solve gives no gains
        with.load = f64::NAN;
        assert_eq!(measured_gains(&with, &sol, lambda, w_star), None);
    }
}
