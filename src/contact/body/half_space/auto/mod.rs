//! The error-controlled `auto` contact solver: tolerance → mode selection, quadrature step and load
//! iteration; every answer carries its error estimate and the contact-condition checks.
//!
//! Input: creep terms ([`CreepTerm`]), λ or N′, [`AutoSettings`]; output: a [`DimensionlessSolution`]
//! with `scheme = "auto"`, its [`AutoDiagnostics`] (mode counts, checks) and warnings, or a
//! [`ContactError`].
//!
//! Error budget for a relative tolerance `tol` on ρ·F/N and λ (or N′ at given λ):
//! - mode reduction ([`reduction`]): ≤ 0.3·tol, re-selected until the estimate, evaluated with
//!   the friction of the solution itself, fits. Lumped fast modes are *corrected* to first order:
//!   one extra solve at the final λ with the lumped mode of largest weight kept measures the gains
//!   (g_F, g_N, g_β) of ρF/N/λ, ln N′ and β per unit lumping weight, and g·Σwᵢ is added to the
//!   answer; the remaining error is the second-order estimate of [`reduction`]. At given load
//!   the loop solves N′_lumped(λ)(1 + g_N·W(λ)) = N′, first with the model gain, then (when the
//!   measured one moves the target) on from the λ found;
//! - quadrature ([`at_lambda`]): step h = 0.6 for tol ≥ 1e−4, 0.4 for tol ≥ 1e−7, 0.3 below
//!   (measured errors ≤ 5e−8, 2e−11, ~1e−15: ≈ e^{−π²/h} with a constant ≤ 1 on 1–30-term
//!   problems); the estimate is 10·e^{−π²/(2h)} times the difference to the same sum on every second
//!   node (step 2h, from the same exterior values: no second solve). The calibration is a difference
//!   of two solves, so its noise, amplified by Σwᵢ/w*, is added;
//! - load loop: a safeguarded secant on ln N′(ln λ) inside the bracket [2√N′, 2√(S·N′)]
//!   (MATH.md §3: N′ grows with λ; glassy and relaxed compliance bound it), started from
//!   λ = 2√(S_eff N′) with the model slope 2 − d ln S_eff/d ln λ and stopped when the step is below
//!   0.05·tol; the step not taken (and a target shift by the measured gain too small to chase)
//!   counts twice in the λ error.
//!
//! Measured (`cargo bench --bench contact_auto`, README table; CPU time of one thread per load
//! point): one term 20/32/40 µs at tol 1e−3/1e−6/1e−9; 10 terms 0.09/0.33/0.96 ms; 30 terms over 24
//! decades 0.17/0.65/1.55 ms (before the measured lumping correction: 1.7/10/51 ms), i.e. 4–6
//! solves per load point. Estimates are ≤ tol and 2–66× the true error against tol 1e−10 solves
//! (tests/contact_auto.rs); over 4400 random spectra and scenes and the measured TRIOS and EMS-CA
//! spectra over ln s = −48…8 no estimate misses (tests/contact_props.rs).
//!
//! The reported `error_estimate` is the largest of the relative errors of ρF/N and of λ (at given
//! load) or N′ (at given λ).

pub mod at_lambda;
pub mod reduction;

use super::rear_gap::contact_check;
use crate::contact::error::ContactError;
use crate::contact::{CreepTerm, DimensionlessSolution};
use at_lambda::{solve_at_lambda, solve_at_lambda_checked, LambdaSolution, QuadratureSettings};
use reduction::{
    calibration_mode, effective_compliance, lump_weight, lumped_residual, model_gains, select,
    slow_estimate_at, unlump, Reduction,
};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Settings of the `auto` scheme.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct AutoSettings {
    /// Relative tolerance on ρ·F/N and λ (default 1e−6; allowed 1e−12 … 0.1).
    pub tol: f64,
    /// Iteration limit of the load loop (default 100; a bracketed secant needs ~6).
    pub max_iterations: usize,
    /// Uniform-in-θ points of the returned pressure profile (default 200), plus ~40 in the front layer.
    pub profile_points: usize,
    /// Evaluate the gap outside the contact (default true; costs ~4 points × 129 × N kernel
    /// evaluations, ≈ 0.3 ms for one term, more than the solve itself for few terms).
    #[serde(default = "default_true")]
    pub gap_check: bool,
}

fn default_true() -> bool {
    true
}

impl Default for AutoSettings {
    fn default() -> Self {
        AutoSettings {
            tol: 1e-6,
            max_iterations: 100,
            profile_points: 200,
            gap_check: true,
        }
    }
}

/// The diagnostics of an `auto` answer (in [`DimensionlessSolution::auto`]; its warnings are in
/// [`DimensionlessSolution::warnings`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AutoDiagnostics {
    /// Modes solved for explicitly.
    pub modes_used: usize,
    /// Modes in the input (terms with f > 0).
    pub modes_total: usize,
    /// Fast modes lumped into the glassy compliance.
    pub modes_lumped: usize,
    /// Slow modes dropped.
    pub modes_dropped: usize,
    /// Estimated relative error of ρF/N.
    pub friction_error: f64,
    /// Estimated relative error of λ (at given load) or of N′ (at given λ).
    pub size_error: f64,
    /// min Q′ / max Q′ over the profile (≥ −tol when the contact condition holds).
    pub min_pressure_ratio: f64,
    /// Smallest gap outside the contact (behind the rear edge, ahead of the front edge, and around
    /// the roll's lowest point when β < 0) over the depth scale λ²/8; < 0 means the roll penetrates
    /// the surface there (accurate to ~1e−10 of λ²/8 plus the solution's own error, see
    /// [`super::rear_gap`]; NaN when the check is switched off).
    #[serde(default)]
    pub min_gap_ratio: f64,
    /// Where the smallest gap lies (ξ, < 0 behind the rear edge, > λ ahead of the front edge).
    #[serde(default)]
    pub min_gap_xi: f64,
    /// The tolerance asked for.
    pub tol: f64,
}

fn validate(terms: &[CreepTerm], tol: f64) -> Result<(), ContactError> {
    for (index, t) in terms.iter().enumerate() {
        if !(t.f >= 0.0 && t.f.is_finite() && t.b > 0.0 && t.b.is_finite()) {
            return Err(ContactError::BadTerm {
                index,
                f: t.f,
                b: t.b,
            });
        }
    }
    if !(1e-12..=0.1).contains(&tol) {
        return Err(ContactError::BadValue {
            field: "tol".into(),
            expected: "in [1e-12, 0.1]",
            value: tol,
        });
    }
    Ok(())
}

/// Trapezoid step for a tolerance: measured errors (1–30 terms) ≤ 5e−8 at h = 0.6, ≤ 2e−11 at
/// 0.4, ~1e−15 at 0.3 (≈ e^{−π²/h}).
fn quad_for(tol: f64) -> QuadratureSettings {
    QuadratureSettings {
        step: if tol >= 1e-4 {
            0.6
        } else if tol >= 1e-7 {
            0.4
        } else {
            0.3
        },
    }
}

/// Map a solution of the reduced problem back to the full problem's units.
fn unscale(red: &Reduction, mut s: LambdaSolution) -> LambdaSolution {
    s.load /= red.scale;
    for c in s.coefficients.iter_mut() {
        *c /= red.scale;
    }
    s
}

/// Solve the reduced problem at λ and map back to the full problem's units.
fn solve_reduced(red: &Reduction, lambda: f64, q: QuadratureSettings) -> LambdaSolution {
    unscale(red, solve_at_lambda(&red.modes, lambda, q))
}

/// As [`solve_reduced`], with the quadrature error estimate: (solution, relative error of ρF/N,
/// relative error of N′). The trapezoid error falls like e^{−π²/h} (module doc of
/// [`at_lambda`]; measured constant ≤ 1 for h = 0.4…0.8 on 1–30-term problems), so the error at
/// step h is about e^{−π²/(2h)} times the difference to the same sum on every second node (step
/// 2h, no extra exterior values); we take 10 times that.
fn solve_reduced_checked(
    red: &Reduction,
    lambda: f64,
    q: QuadratureSettings,
) -> (LambdaSolution, f64, f64) {
    let (fine, coarse) = solve_at_lambda_checked(&red.modes, lambda, q);
    let k = 10.0 * (-PI * PI / (2.0 * q.step)).exp();
    let e_fr = k * rel(coarse.friction_rho, fine.friction_rho);
    let e_ld = k * rel(coarse.load, fine.load);
    (unscale(red, fine), e_fr, e_ld)
}

fn budgets(tol: f64, fr_over_lambda: f64) -> (f64, f64) {
    (0.3 * tol * fr_over_lambda.abs().max(1e-300), 0.3 * tol)
}

/// Σ wᵢ·λ over the lumped modes (wᵢ ∝ 1/λ, so this is independent of λ).
fn lumped_weight_times_lambda(terms: &[CreepTerm], red: &Reduction) -> f64 {
    red.lumped
        .iter()
        .map(|&i| lump_weight(&terms[i], 1.0))
        .sum()
}

/// The measured first-order correction for the lumped modes ([`reduction`] module doc).
#[derive(Debug, Clone, Copy)]
struct Correction {
    /// Effects per unit lumping weight: Δ(ρF/N/λ), ΔN′/N′, Δβ (the measured gains g_F, g_N, g_β).
    gains: (f64, f64, f64),
    /// Σwᵢ/w* of the calibration: how much the calibration solve's noise is amplified.
    amplification: f64,
}

impl Correction {
    /// The model's gains, before any measurement (β unknown: 0).
    fn model(terms: &[CreepTerm], lambda: f64) -> Correction {
        let (g_f, g_n) = model_gains(terms, lambda);
        Correction {
            gains: (g_f, g_n, 0.0),
            amplification: 0.0,
        }
    }

    /// Apply at the solution's λ: ρF/N += λ·g_F·W, N′ ×= 1 + g_N·W, β += g_β·W (W = Σwᵢ); the
    /// pressure is scaled with N′ (the layer correction itself is not added to the profile).
    fn apply(&self, terms: &[CreepTerm], red: &Reduction, sol: &mut LambdaSolution) {
        let w = lumped_weight_times_lambda(terms, red) / sol.lambda;
        if w == 0.0 {
            return;
        }
        sol.friction_rho += sol.lambda * self.gains.0 * w;
        let f = 1.0 + self.gains.1 * w;
        sol.load *= f;
        for c in sol.coefficients.iter_mut() {
            *c *= f;
        }
        sol.beta += self.gains.2 * w;
    }
}

/// Measure the gains at the solution's λ by one solve with the lumped mode of largest weight kept,
/// or the probe that stands in for it when it is too fast to solve for
/// ([`reduction::calibration_mode`]): the probe kept minus the mode lumped is the probe's own
/// layer effect g·w_p, w_p = rᵢ/c_p. Returns the model gains (and amplification 0) when nothing is
/// lumped or the solve fails.
fn calibrate(
    terms: &[CreepTerm],
    red: &Reduction,
    sol: &LambdaSolution,
    q: QuadratureSettings,
) -> Correction {
    let lambda = sol.lambda;
    let model = Correction::model(terms, lambda);
    let Some((star, c_probe)) = calibration_mode(terms, &red.lumped, lambda) else {
        return model;
    };
    let weight = lumped_weight_times_lambda(terms, red) / lambda;
    let probe_terms;
    let terms = if c_probe.is_finite() {
        let l = 0.5 * lambda;
        let r = terms[star].f / terms[star].b;
        let mut p = terms.to_vec();
        p[star] = CreepTerm {
            f: r * c_probe / l,
            b: c_probe / l,
        };
        probe_terms = p;
        &probe_terms[..]
    } else {
        terms
    };
    let w_star = lump_weight(&terms[star], lambda);
    let with = solve_reduced(&unlump(terms, red, star), lambda, q);
    let g = (
        (with.friction_rho - sol.friction_rho) / lambda / w_star,
        (with.load - sol.load) / sol.load / w_star,
        (with.beta - sol.beta) / w_star,
    );
    if !(g.0.is_finite() && g.1.is_finite() && g.2.is_finite()) {
        return model;
    }
    Correction {
        gains: g,
        amplification: weight / w_star,
    }
}

/// Remaining lumping error after the correction (ρF/N/λ absolute, N′ relative): the second-order
/// estimate, plus, without a measurement, the whole (model) effect twice.
fn lumping_error(
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

/// Solve at given contact length λ > 0.
pub fn solve_auto_at_lambda(
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
        let (sol, num_fr, num_ld) = solve_reduced_checked(&red, lambda, q);
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

/// Relative round-off floor of the corrected ρF/N. Each solve's ρF/N = L − β + L·F₂/(2F₁) (eq. in
/// `auto`'s module doc) is a difference of O(λ) terms, so its absolute error is a few ε·(λ + |β|):
/// once for the reduced solve (none when every mode is lumped or dropped: the elastic solve gives
/// β = L and F₂ = 0 exactly), and for the lumping correction twice (the calibration is a difference
/// of two solves) times its amplification Σwᵢ/w*. Large relative to a small friction.
fn roundoff_floor(sol: &LambdaSolution, red: &Reduction, corr: &Correction) -> f64 {
    let solves = if red.modes_used > 0 { 1.0 } else { 0.0 } + 2.0 * corr.amplification;
    8.0 * f64::EPSILON * solves * (sol.lambda + sol.beta.abs()) / sol.friction_rho.abs().max(1e-300)
}

fn rel(a: f64, b: f64) -> f64 {
    // equal values (e.g. ρF/N = 0 of an all-lumped, elastic reduced problem) differ by nothing;
    // 0/0 would give NaN and swallow the rest of the estimate
    if a == b {
        0.0
    } else {
        ((a - b) / b).abs()
    }
}

/// Solve at given load N′ > 0 (the load loop).
pub fn solve_auto_at_load(
    terms: &[CreepTerm],
    load: f64,
    settings: &AutoSettings,
) -> Result<DimensionlessSolution, ContactError> {
    validate(terms, settings.tol)?;
    if !(load > 0.0 && load.is_finite()) {
        return Err(ContactError::BadValue {
            field: "load N'".into(),
            expected: "finite and > 0",
            value: load,
        });
    }
    let tol = settings.tol;
    let q = quad_for(tol);
    let s_full = 1.0
        + terms
            .iter()
            .filter(|t| t.f > 0.0)
            .map(|t| t.f / t.b)
            .sum::<f64>();
    let lam_glassy = 2.0 * load.sqrt();
    // Initial guess: λ = 2√(S_eff N′) with S_eff counting modes by how far they creep in the
    // contact time, c/(1+c); three fixed-point steps (no solves).
    let mut lam0 = lam_glassy;
    for _ in 0..3 {
        lam0 = 2.0 * (effective_compliance(terms, lam0) * load).sqrt();
    }
    let mut fr_guess = 1e-2;
    let mut corr = Correction::model(terms, lam0);
    let mut total_iter = 0;
    let mut round = 0;
    loop {
        round += 1;
        let (bf, bl) = budgets(tol, fr_guess);
        let red = select(terms, lam0, bf, bl, (corr.gains.0, corr.gains.1));
        let w_lambda = lumped_weight_times_lambda(terms, &red);
        // The loop solves N′_lumped(λ)·(1 + g_N·W(λ)) = N′ with W(λ) = w_lambda/λ: first with the
        // gain assumed, then (after measuring it at the λ found) once more from there if it moved.
        let bracket = (
            lam_glassy.ln() - 1e-9 - (1.0 + corr.gains.1.abs() * w_lambda / lam_glassy).ln(),
            (lam_glassy * s_full.sqrt()).ln() + 1e-9,
        );
        let mut lp = load_loop(
            &red,
            load.ln(),
            corr.gains.1 * w_lambda,
            bracket,
            Start::Guess(lam0, model_slope(terms, lam0)),
            tol,
            q,
            settings.max_iterations,
        )?;
        total_iter += lp.iterations;
        let measured = calibrate(terms, &red, &lp.sol, q);
        let moved = ((1.0 + measured.gains.1 * w_lambda / lp.sol.lambda)
            / (1.0 + corr.gains.1 * w_lambda / lp.sol.lambda))
            .ln()
            .abs();
        corr = measured;
        // a target moved by less than the loop's own stopping step is not chased: its λ shift
        // counts in the error instead (like the loop's last step)
        let mut unchased = moved / lp.slope.abs().max(0.2);
        if unchased >= 0.05 * tol {
            unchased = 0.0;
            let start = Start::Solved((lp.sol.clone(), lp.num_fr, lp.num_ld), lp.slope, lp.dfr);
            lp = load_loop(
                &red,
                load.ln(),
                corr.gains.1 * w_lambda,
                bracket,
                start,
                tol,
                q,
                settings.max_iterations,
            )?;
            total_iter += lp.iterations;
        }
        let lambda = lp.sol.lambda;
        let (l_fr, l_ld) = lumping_error(terms, &red, &corr, lambda);
        let (s_fr, s_ld) = slow_estimate_at(terms, &red, lambda);
        let (e_fr, e_ld) = (l_fr + s_fr, l_ld + s_ld);
        let fr_l = lp.sol.friction_rho / lambda + corr.gains.0 * w_lambda / lambda;
        let ok = e_fr <= 0.3 * tol * fr_l.abs() && e_ld <= 0.3 * tol;
        // if the next round would select the same modes it cannot do better: stop here (the
        // estimate says honestly whether the tolerance is met)
        let same = !ok && {
            let (bf2, bl2) = budgets(tol, fr_l);
            let next = select(terms, lambda, bf2, bl2, (corr.gains.0, corr.gains.1));
            next.kept == red.kept && next.lumped == red.lumped && next.dropped == red.dropped
        };
        if ok || same || round >= 4 {
            // at fixed λ the quadrature error of N′ maps to λ through the slope
            let amp = 1.0 + 2.0 * corr.amplification;
            let num_ld = amp * lp.num_ld;
            let num_fr = amp * lp.num_fr;
            let slope = lp.slope.abs().max(0.2);
            // the steps not taken are first-order distances to the root (slope known to better
            // than a factor 2 from the secant): counted twice
            let size_error = 2.0 * (lp.last_step + unchased) + (num_ld + e_ld) / slope;
            let mut sol = lp.sol;
            corr.apply(terms, &red, &mut sol);
            let fr = sol.friction_rho;
            let floor = roundoff_floor(&sol, &red, &corr);
            let friction_error = num_fr
                + e_fr * lambda / fr.abs().max(1e-300)
                + lp.dfr.abs().max(1.0) * size_error
                + floor;
            return Ok(package(
                terms,
                &red,
                sol,
                total_iter,
                (friction_error, floor),
                size_error,
                settings,
            ));
        }
        lam0 = lambda;
        fr_guess = fr_l;
    }
}

/// The model slope d ln N′/d ln λ of N′ ≈ λ²/(4S_eff(λ)) (MATH.md §3 with the effective
/// compliance of [`reduction`]): 2 − d ln S_eff/d ln λ, d S_eff/d ln λ = Σ rᵢcᵢ/(1+cᵢ)².
fn model_slope(terms: &[CreepTerm], lambda: f64) -> f64 {
    let l = 0.5 * lambda;
    let d: f64 = terms
        .iter()
        .filter(|t| t.f > 0.0)
        .map(|t| {
            let c = t.b * l;
            (t.f / t.b) * c / ((1.0 + c) * (1.0 + c))
        })
        .sum();
    (2.0 - d / effective_compliance(terms, lambda)).clamp(0.5, 2.0)
}

/// Where the load loop starts: a guess of λ, or a solution already computed (with the slope
/// d ln N′/d ln λ and d ln(ρF/N)/d ln λ known there).
enum Start {
    /// λ₀ and the slope d ln N′/d ln λ to start the secant with.
    Guess(f64, f64),
    Solved((LambdaSolution, f64, f64), f64, f64),
}

/// The load loop's answer: the (uncorrected, reduced) solution at the λ found.
struct LoopResult {
    sol: LambdaSolution,
    /// Quadrature error estimates of `sol` (relative, ρF/N and N′).
    num_fr: f64,
    num_ld: f64,
    /// Solves done.
    iterations: usize,
    /// Last |Δ ln λ|.
    last_step: f64,
    /// d ln N′/d ln λ.
    slope: f64,
    /// d ln(ρF/N)/d ln λ.
    dfr: f64,
}

/// Safeguarded secant on g(u) = ln N′(eᵘ) + ln(1 + k·e^{−u}) − ln N′₀ inside the bracket (a, b),
/// where k·e^{−u} = g_N·W(λ) is the lumping correction of N′ (k = g_N·Σwᵢλ, independent of λ).
#[allow(clippy::too_many_arguments)]
fn load_loop(
    red: &Reduction,
    target: f64,
    k: f64,
    (mut a, mut b): (f64, f64),
    start: Start,
    tol: f64,
    q: QuadratureSettings,
    max_iter: usize,
) -> Result<LoopResult, ContactError> {
    let gval = |s: &LambdaSolution| s.load.ln() + (1.0 + k / s.lambda).ln() - target;
    let eval = |u: f64| -> (f64, (LambdaSolution, f64, f64)) {
        let s = solve_reduced_checked(red, u.exp(), q);
        (gval(&s.0), s)
    };
    let (mut u, mut g, (mut sol, mut num_fr, mut num_ld), mut slope, mut dfr, mut iters) =
        match start {
            Start::Guess(lam0, slope0) => {
                let u = lam0.ln().clamp(a, b);
                let (g, s) = eval(u);
                (u, g, s, slope0, 1.0, 1)
            }
            Start::Solved(s, slope, dfr) => (s.0.lambda.ln(), gval(&s.0), s, slope, dfr, 0),
        };
    let mut prev: Option<(f64, f64, f64)> = None; // (u, g, ln fr)
    let last_step;
    loop {
        if g < 0.0 {
            a = a.max(u);
        } else {
            b = b.min(u);
        }
        if g == 0.0 {
            last_step = 0.0;
            break;
        }
        // secant with the previous point, else the last slope (2 = elastic), kept in the bracket
        let s = match prev {
            Some((up, gp, _)) if (u - up).abs() > 0.0 && (g - gp) / (u - up) > 0.0 => {
                (g - gp) / (u - up)
            }
            _ => slope,
        };
        slope = s;
        let mut un = u - g / s;
        // a converged secant step may land on the bracket end it starts from: no bisection then
        if !(un > a && un < b) && (g / s).abs() >= 0.05 * tol {
            un = 0.5 * (a + b);
        }
        let step = (un - u).abs();
        let lnfr = sol.friction_rho.abs().max(1e-300).ln();
        if let Some((up, _, lfp)) = prev {
            // only from steps long enough that round-off in ρF/N does not dominate
            if (u - up).abs() > 1e-4 {
                dfr = ((lnfr - lfp) / (u - up)).clamp(-10.0, 10.0);
            }
        }
        prev = Some((u, g, lnfr));
        if step < 0.05 * tol || (b - a) < 0.05 * tol {
            last_step = step.min(b - a);
            break;
        }
        if iters >= max_iter {
            return Err(ContactError::NotConverged {
                iterations: iters,
                lambda_lo: a.exp(),
                lambda_hi: b.exp(),
                residual: g.exp_m1().abs(),
            });
        }
        u = un;
        let (gn, sn) = eval(u);
        g = gn;
        (sol, num_fr, num_ld) = sn;
        iters += 1;
    }
    Ok(LoopResult {
        sol,
        num_fr,
        num_ld,
        iterations: iters,
        last_step,
        slope,
        dfr,
    })
}

fn package(
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
    // Contact conditions outside the contact (module `rear_gap`): a scan behind the rear edge
    // (incl. around the lowest point when β < 0) and three points ahead of the front edge.
    let (min_gap_ratio, min_gap_xi) = if settings.gap_check {
        let scan = contact_check(&red.modes, red.scale, &sol);
        if scan.min_gap_ahead_ratio < scan.min_gap_ratio {
            (scan.min_gap_ahead_ratio, f64::NAN)
        } else {
            (scan.min_gap_ratio, scan.at_xi)
        }
    } else {
        (f64::NAN, f64::NAN)
    };
    // The gap is accurate to ~1e−10 of λ²/8 for the computed pressure, whose own error is ~tol.
    let gap_tol = settings.tol.max(1e-9);
    if min_gap_ratio < -gap_tol {
        warnings.push(format!(
            "contact condition fails: the roll penetrates the surface outside the contact (min gap \
             / (λ²/8) = {min_gap_ratio:.3e} at ξ = {min_gap_xi:.4e}); this answer is not valid. In \
             the rear-edge scans every such case was a wrong solution, fixed by a tighter --tol \
             (a genuine second contact zone was never found, and is not modelled)"
        ));
    }
    if sol.beta < 0.0 {
        let gap = if min_gap_ratio.is_nan() {
            "gap behind not checked".to_string()
        } else if min_gap_ratio >= -gap_tol {
            format!("the gap behind stays open, min gap / (λ²/8) = {min_gap_ratio:.3e}")
        } else {
            "see the contact-condition warning".to_string()
        };
        warnings.push(format!(
            "information: the roll's lowest point lies behind the rear contact edge (β = {:.4e}, \
             β/λ = {:.4e}); {gap}",
            sol.beta,
            sol.beta / sol.lambda
        ));
    }
    let modes_total = terms.iter().filter(|t| t.f > 0.0).count();
    // When every mode is lumped (or dropped) the reduced problem is elastic and ρF/N = 0 exactly;
    // the relative estimates above are then 0/0 = NaN, which `f64::max` would silently drop. The
    // relative error of a zero answer against a non-zero truth is exactly 1: report that.
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
    let error_estimate = friction_error.max(size_error);
    if error_estimate > settings.tol && !zero_answer {
        let why = if floor >= 0.5 * error_estimate {
            format!(
                "ρF/N is only {:.1e} of the contact length, and its round-off alone (ρF/N = L − β + …, \
                 a difference of O(λ) terms) is {floor:.1e} relative",
                sol.friction_rho / sol.lambda
            )
        } else {
            "the rest of the estimate comes from the mode reduction, which lumps modes with \
             c = bλ/2 > 1e7 whatever the tolerance (their effect is corrected to first order and \
             its remainder estimated)"
                .to_string()
        };
        warnings.push(format!(
            "tolerance not reached: estimated relative error {error_estimate:.1e} > tol {:.0e}; {why}",
            settings.tol
        ));
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
        auto: Some(AutoDiagnostics {
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
