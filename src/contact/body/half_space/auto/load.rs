//! The `auto` scheme at given load N′: the mode selection, a safeguarded secant on ln N′(ln λ) and
//! the measured lumping correction, in rounds until the error estimate fits (module doc of
//! [`super`]: error budget, bracket, stopping rule).
//!
//! Input: creep terms, N′, [`AutoSettings`]; output: the [`DimensionlessSolution`] at the λ found
//! (via [`super::outcome::package`]) or a [`ContactError`].

use super::correction::{
    calibrate, lumped_weight_times_lambda, lumping_error, roundoff_floor, Correction,
};
use super::outcome::package;
use super::settings::{budgets, quad_for, validate, AutoSettings};
use crate::contact::error::ContactError;
use crate::contact::load::{iterate, Keep, SafeSecant, Seen, Step, Verdict};
use crate::contact::numerics::at_lambda::{LambdaSolution, QuadratureSettings};
use crate::contact::numerics::reduction::{
    effective_compliance, select, slow_estimate_at, solve_reduced_checked, Reduction,
};
use crate::contact::problem::{CreepTerm, DimensionlessSolution};

/// Solve at given load N′ > 0: rounds of mode selection (at the last λ), load loop and measured
/// correction, until the estimate fits the budgets or the selection cannot change (at most 4).
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
    let mut lam0 = initial_guess(terms, load);
    let mut fr_guess = 1e-2;
    let mut corr = Correction::model(terms, lam0);
    let mut total_iter = 0;
    let mut round = 0;
    loop {
        round += 1;
        let (bf, bl) = budgets(tol, fr_guess);
        let red = select(terms, lam0, bf, bl, (corr.gains.0, corr.gains.1));
        let (lp, unchased) = solve_round(terms, load, &red, &mut corr, lam0, q, settings)?;
        total_iter += lp.iterations;
        let lambda = lp.sol.lambda;
        let w_lambda = lumped_weight_times_lambda(terms, &red);
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
            let lp = LoopResult {
                iterations: total_iter,
                ..lp
            };
            return Ok(finish(
                terms,
                &red,
                lp,
                &corr,
                (e_fr, e_ld),
                unchased,
                settings,
            ));
        }
        lam0 = lambda;
        fr_guess = fr_l;
    }
}

/// Initial guess: λ = 2√(S_eff N′) with S_eff counting modes by how far they creep in the contact
/// time, c/(1+c); three fixed-point steps from the glassy width 2√N′ (no solves).
fn initial_guess(terms: &[CreepTerm], load: f64) -> f64 {
    let mut lam0 = 2.0 * load.sqrt();
    for _ in 0..3 {
        lam0 = 2.0 * (effective_compliance(terms, lam0) * load).sqrt();
    }
    lam0
}

/// One round at a fixed selection `red`: the load loop solves N′_lumped(λ)·(1 + g_N·W(λ)) = N′
/// with W(λ) = Σwᵢλ/λ, first with the gain `corr` assumed, then (after measuring it at the λ found;
/// `corr` is replaced by the measurement) once more from there if the target moved by more than
/// the loop's stopping step. Returns the loop's answer (`iterations`: solves of both loops) and the
/// λ shift not chased (0 when chased).
fn solve_round(
    terms: &[CreepTerm],
    load: f64,
    red: &Reduction,
    corr: &mut Correction,
    lam0: f64,
    q: QuadratureSettings,
    settings: &AutoSettings,
) -> Result<(LoopResult, f64), ContactError> {
    let tol = settings.tol;
    let s_full = 1.0
        + terms
            .iter()
            .filter(|t| t.f > 0.0)
            .map(|t| t.f / t.b)
            .sum::<f64>();
    let lam_glassy = 2.0 * load.sqrt();
    let w_lambda = lumped_weight_times_lambda(terms, red);
    // bracket: glassy and relaxed Hertz widths, the lower end widened by the lumping correction
    let bracket = (
        lam_glassy.ln() - 1e-9 - (1.0 + corr.gains.1.abs() * w_lambda / lam_glassy).ln(),
        (lam_glassy * s_full.sqrt()).ln() + 1e-9,
    );
    let mut lp = load_loop(
        red,
        load.ln(),
        corr.gains.1 * w_lambda,
        bracket,
        Start::Guess(lam0, model_slope(terms, lam0)),
        tol,
        q,
        settings.max_iterations,
    )?;
    let measured = calibrate(terms, red, &lp.sol, q);
    let moved = ((1.0 + measured.gains.1 * w_lambda / lp.sol.lambda)
        / (1.0 + corr.gains.1 * w_lambda / lp.sol.lambda))
        .ln()
        .abs();
    *corr = measured;
    // a target moved by less than the loop's own stopping step is not chased: its λ shift
    // counts in the error instead (like the loop's last step)
    let mut unchased = moved / lp.slope.abs().max(0.2);
    if unchased >= 0.05 * tol {
        unchased = 0.0;
        let first = lp.iterations;
        let start = Start::Solved((lp.sol.clone(), lp.num_fr, lp.num_ld), lp.slope, lp.dfr);
        lp = load_loop(
            red,
            load.ln(),
            corr.gains.1 * w_lambda,
            bracket,
            start,
            tol,
            q,
            settings.max_iterations,
        )?;
        lp.iterations += first;
    }
    Ok((lp, unchased))
}

/// The answer of the last round: the correction applied, and the error estimate (module doc of
/// [`super`]): quadrature (amplified by the calibration), reduction (`e` = ρF/N/λ absolute and N′
/// relative), the steps not taken, mapped to λ through the slope, and the round-off floor.
fn finish(
    terms: &[CreepTerm],
    red: &Reduction,
    lp: LoopResult,
    corr: &Correction,
    (e_fr, e_ld): (f64, f64),
    unchased: f64,
    settings: &AutoSettings,
) -> DimensionlessSolution {
    let lambda = lp.sol.lambda;
    // at fixed λ the quadrature error of N′ maps to λ through the slope
    let amp = 1.0 + 2.0 * corr.amplification;
    let num_ld = amp * lp.num_ld;
    let num_fr = amp * lp.num_fr;
    let slope = lp.slope.abs().max(0.2);
    // the steps not taken are first-order distances to the root (slope known to better
    // than a factor 2 from the secant): counted twice
    let size_error = 2.0 * (lp.last_step + unchased) + (num_ld + e_ld) / slope;
    let mut sol = lp.sol;
    corr.apply(terms, red, &mut sol);
    let fr = sol.friction_rho;
    let floor = roundoff_floor(&sol, red, corr);
    let friction_error =
        num_fr + e_fr * lambda / fr.abs().max(1e-300) + lp.dfr.abs().max(1.0) * size_error + floor;
    package(
        terms,
        red,
        sol,
        lp.iterations,
        (friction_error, floor),
        size_error,
        settings,
    )
}

/// The model slope d ln N′/d ln λ of N′ ≈ λ²/(4S_eff(λ)) (docs/MATH.md §3 with the effective
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
/// where k·e^{−u} = g_N·W(λ) is the lumping correction of N′ (k = g_N·Σwᵢλ, independent of λ): the
/// crate's one load loop ([`iterate`]) with the rule [`SafeSecant`], started from the guess (its
/// model slope) or from a solution already made, stopped when the step or the bracket is shorter
/// than 0.05·tol.
#[allow(clippy::too_many_arguments)]
fn load_loop(
    red: &Reduction,
    target: f64,
    k: f64,
    (a, b): (f64, f64),
    start: Start,
    tol: f64,
    q: QuadratureSettings,
    max_iter: usize,
) -> Result<LoopResult, ContactError> {
    let gval = |s: &LambdaSolution| s.load.ln() + (1.0 + k / s.lambda).ln() - target;
    let ln_fr = |s: &LambdaSolution| s.friction_rho.abs().max(1e-300).ln();
    let small = 0.05 * tol;
    // (u, ln ρF/N) of every iterate in order, for d ln(ρF/N)/d ln λ
    let mut history: Vec<(f64, f64)> = Vec::new();
    let (u0, first, slope0, mut dfr, solves) = match start {
        Start::Guess(lam0, slope0) => {
            let u = lam0.ln().clamp(a, b);
            (u, solve_reduced_checked(red, u.exp(), q)?, slope0, 1.0, 1)
        }
        Start::Solved(s, slope, dfr) => (s.0.lambda.ln(), s, slope, dfr, 0),
    };
    let g0 = gval(&first.0);
    history.push((u0, ln_fr(&first.0)));
    let mut rule = SafeSecant::new((a, b), slope0, small);
    rule.observe(u0, g0);
    let (mut last_step, mut on_root) = (0.0, false);
    let seen = Seen {
        solves,
        g: g0,
        sol: first,
    };
    let mut eval = |u: f64| -> Result<(f64, (LambdaSolution, f64, f64)), ContactError> {
        let s = solve_reduced_checked(red, u.exp(), q)?;
        history.push((u, ln_fr(&s.0)));
        Ok((gval(&s.0), s))
    };
    let found = iterate(seen, &mut rule, Keep::Last, &mut eval, &mut |t| {
        let p = t.proposal;
        if p.resid == 0.0 {
            on_root = true;
            last_step = 0.0;
            return Verdict::Done;
        }
        if p.step < small || p.width < small {
            last_step = p.step.min(p.width);
            return Verdict::Done;
        }
        if t.solves >= max_iter {
            return Verdict::Fail(ContactError::NotConverged {
                iterations: t.solves,
                lambda_lo: p.bracket.0.exp(),
                lambda_hi: p.bracket.1.exp(),
                residual: p.resid.exp_m1().abs(),
            });
        }
        Verdict::Go
    })?;
    // d ln(ρF/N)/d ln λ from the last pair of iterates far enough apart that round-off in ρF/N
    // does not dominate (an iterate that hit the root exactly is not differenced)
    let pairs = history.len() - usize::from(on_root);
    for w in history[..pairs].windows(2) {
        let ((up, lfp), (u, lf)) = (w[0], w[1]);
        if (u - up).abs() > 1e-4 {
            dfr = ((lf - lfp) / (u - up)).clamp(-10.0, 10.0);
        }
    }
    let (sol, num_fr, num_ld) = found.sol;
    Ok(LoopResult {
        sol,
        num_fr,
        num_ld,
        iterations: found.solves,
        last_step,
        slope: rule.slope,
        dfr,
    })
}
