//! The error-controlled `auto` contact solver: tolerance → mode selection, quadrature step and load
//! iteration; every answer carries its error estimate and the contact-condition checks.
//!
//! Input: creep terms ([`CreepTerm`]), λ or N′, [`AutoSettings`]; output: [`AutoSolution`] (a
//! [`DimensionlessSolution`] with `scheme = "auto"` plus mode counts, checks and warnings).
//!
//! Error budget for a relative tolerance `tol` on ρ·F/N and λ (or N′ at given λ):
//! - mode reduction ([`super::reduce`]): ≤ 0.3·tol, re-selected until the estimate, evaluated with
//!   the friction of the solution itself, fits;
//! - quadrature ([`super::auto`]): step 0.4 for tol ≥ 1e−7 (measured error ≲ 5e−11), 0.3 below
//!   (≲ 1e−14); the estimate is the difference to a solve with 1.5× the step, which bounds the
//!   error of the finer solve because the error falls like e^{−π²/h};
//! - load loop: a safeguarded secant on ln N′(ln λ) inside the bracket [2√N′, 2√(S·N′)]
//!   (MATH.md §3: N′ grows with λ; glassy and relaxed compliance bound it), stopped when the step is
//!   below 0.05·tol; its λ error is the last step, converted with the local slope d ln N′/d ln λ.
//!
//! The reported `error_estimate` is the largest of the relative errors of ρF/N and of λ (at given
//! load) or N′ (at given λ).

use super::auto::{solve_at_lambda, LambdaSolution, QuadratureSettings};
use super::rear_gap::contact_check;
use super::reduce::{estimate_at, select, Reduction};
use super::{CreepTerm, DimensionlessSolution};
use serde::{Deserialize, Serialize};

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

/// Errors of the `auto` scheme (bad input only; outcomes are data).
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum AutoError {
    /// A creep term is not usable.
    #[error("creep term {index}: f = {f} and b = {b}; need f ≥ 0 and b > 0, both finite")]
    BadTerm {
        /// Index of the term.
        index: usize,
        /// Its f.
        f: f64,
        /// Its b.
        b: f64,
    },
    /// A scalar input is out of range.
    #[error("{name} = {value}: {expected}")]
    BadValue {
        /// The input's name.
        name: &'static str,
        /// Its value.
        value: f64,
        /// What was expected.
        expected: &'static str,
    },
    /// The scene could not be made dimensionless.
    #[error(transparent)]
    Scene(#[from] super::error::ContactError),
    /// The load loop hit its iteration limit (not seen in tests; reported, not hidden).
    #[error("load iteration did not converge in {iterations} steps: λ in [{lo}, {hi}]")]
    NotConverged {
        /// Steps taken.
        iterations: usize,
        /// Bracket lower end.
        lo: f64,
        /// Bracket upper end.
        hi: f64,
    },
}

/// A solution of the `auto` scheme with its diagnostics.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AutoSolution {
    /// λ, β, N′, ρF/N, pressure profile, iterations, `error_estimate`.
    #[serde(flatten)]
    pub solution: DimensionlessSolution,
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
    /// Human-readable warnings (validity of the model, contact conditions).
    #[serde(default)]
    pub warnings: Vec<String>,
}

fn validate(terms: &[CreepTerm], tol: f64) -> Result<(), AutoError> {
    for (index, t) in terms.iter().enumerate() {
        if !(t.f >= 0.0 && t.f.is_finite() && t.b > 0.0 && t.b.is_finite()) {
            return Err(AutoError::BadTerm {
                index,
                f: t.f,
                b: t.b,
            });
        }
    }
    if !(1e-12..=0.1).contains(&tol) {
        return Err(AutoError::BadValue {
            name: "tol",
            value: tol,
            expected: "need 1e-12 ≤ tol ≤ 0.1",
        });
    }
    Ok(())
}

fn quad_for(tol: f64) -> QuadratureSettings {
    QuadratureSettings {
        step: if tol >= 1e-7 { 0.4 } else { 0.3 },
    }
}

/// Solve the reduced problem at λ and map back to the full problem's units.
fn solve_reduced(red: &Reduction, lambda: f64, q: QuadratureSettings) -> LambdaSolution {
    let mut s = solve_at_lambda(&red.modes, lambda, q);
    s.load /= red.scale;
    for c in s.coefficients.iter_mut() {
        *c /= red.scale;
    }
    s
}

fn merge_mu(tol: f64) -> f64 {
    (1e-14 / tol).min(0.05)
}

fn budgets(tol: f64, fr_over_lambda: f64) -> (f64, f64) {
    (0.3 * tol * fr_over_lambda.abs().max(1e-300), 0.3 * tol)
}

/// Solve at given contact length λ > 0.
pub fn solve_auto_at_lambda(
    terms: &[CreepTerm],
    lambda: f64,
    settings: &AutoSettings,
) -> Result<AutoSolution, AutoError> {
    validate(terms, settings.tol)?;
    if !(lambda > 0.0 && lambda.is_finite()) {
        return Err(AutoError::BadValue {
            name: "lambda",
            value: lambda,
            expected: "need a finite λ > 0",
        });
    }
    let tol = settings.tol;
    let q = quad_for(tol);
    // First pass: budget from a friction guess of 1e−2·λ; then from the solution's own friction.
    let mut fr_guess = 1e-2;
    let mut red;
    let mut sol;
    let mut pass = 0;
    loop {
        let (bf, bl) = budgets(tol, fr_guess);
        red = select(terms, lambda, bf, bl, merge_mu(tol));
        sol = solve_reduced(&red, lambda, q);
        let fr = sol.friction_rho / lambda;
        pass += 1;
        if red.friction_over_lambda_error <= 0.3 * tol * fr.abs() || pass >= 4 {
            break;
        }
        fr_guess = 0.5 * fr.abs();
    }
    let coarse = solve_reduced(&red, lambda, QuadratureSettings { step: 1.5 * q.step });
    let fr = sol.friction_rho;
    let num_fr = rel(coarse.friction_rho, fr);
    let num_ld = rel(coarse.load, sol.load);
    let friction_error = num_fr
        + red.friction_over_lambda_error * lambda / fr.abs().max(1e-300)
        + roundoff_floor(&sol);
    let size_error = num_ld + red.load_error;
    Ok(package(
        terms,
        &red,
        sol,
        0,
        friction_error,
        size_error,
        settings,
    ))
}

/// Round-off floor of ρF/N = L − β + L·F₂/(2F₁) (eq. in `auto`'s module doc): a difference of
/// O(λ) terms, so its absolute error is a few ε·(λ + |β|), large relative to a small friction.
fn roundoff_floor(sol: &LambdaSolution) -> f64 {
    8.0 * f64::EPSILON * (sol.lambda + sol.beta.abs()) / sol.friction_rho.abs().max(1e-300)
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// Solve at given load N′ > 0 (the load loop).
pub fn solve_auto_at_load(
    terms: &[CreepTerm],
    load: f64,
    settings: &AutoSettings,
) -> Result<AutoSolution, AutoError> {
    validate(terms, settings.tol)?;
    if !(load > 0.0 && load.is_finite()) {
        return Err(AutoError::BadValue {
            name: "load",
            value: load,
            expected: "need a finite N' > 0",
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
        let l = 0.5 * lam0;
        let s_eff = 1.0
            + terms
                .iter()
                .filter(|t| t.f > 0.0)
                .map(|t| (t.f / t.b) * (t.b * l) / (1.0 + t.b * l))
                .sum::<f64>();
        lam0 = 2.0 * (s_eff * load).sqrt();
    }
    let mut fr_guess = 1e-2;
    let mut total_iter = 0;
    let mut round = 0;
    loop {
        round += 1;
        let (bf, bl) = budgets(tol, fr_guess);
        let red = select(terms, lam0, bf, bl, merge_mu(tol));
        let (sol, iters, lam_err_u, slope, dfr) = load_loop(
            &red,
            load,
            lam_glassy,
            s_full,
            lam0,
            tol,
            q,
            settings.max_iterations,
        )?;
        total_iter += iters;
        let lambda = sol.lambda;
        let fr = sol.friction_rho;
        let (e_fr, e_ld) = estimate_at(terms, &red, lambda);
        let ok = e_fr <= 0.3 * tol * (fr / lambda).abs() && e_ld <= 0.3 * tol;
        // if the next round would select the same modes it cannot do better: stop here (the
        // estimate says honestly whether the tolerance is met)
        let same = !ok && {
            let (bf2, bl2) = budgets(tol, 0.5 * (fr / lambda).abs());
            let next = select(terms, lambda, bf2, bl2, merge_mu(tol));
            next.kept == red.kept && next.lumped == red.lumped && next.dropped == red.dropped
        };
        if ok || same || round >= 4 {
            let coarse = solve_reduced(&red, lambda, QuadratureSettings { step: 1.5 * q.step });
            // at fixed λ the coarse/fine N′ difference maps to λ through the slope
            let num_ld = rel(coarse.load, sol.load);
            let num_fr = rel(coarse.friction_rho, fr);
            let slope = slope.abs().max(0.2);
            let size_error = lam_err_u + (num_ld + e_ld) / slope;
            let friction_error =
                num_fr + e_fr * lambda / fr.abs().max(1e-300) + dfr.abs().max(1.0) * size_error;
            return Ok(package(
                terms,
                &red,
                sol,
                total_iter,
                friction_error,
                size_error,
                settings,
            ));
        }
        lam0 = lambda;
        fr_guess = 0.5 * (fr / lambda).abs();
    }
}

/// Safeguarded secant on g(u) = ln N′(eᵘ) − ln N′₀ inside a sign-change bracket.
/// Returns (solution, solves, last |Δu|, slope d ln N′/d ln λ, d ln(ρF/N)/d ln λ).
#[allow(clippy::too_many_arguments)]
fn load_loop(
    red: &Reduction,
    load: f64,
    lam_glassy: f64,
    s_full: f64,
    lam0: f64,
    tol: f64,
    q: QuadratureSettings,
    max_iter: usize,
) -> Result<(LambdaSolution, usize, f64, f64, f64), AutoError> {
    let target = load.ln();
    let mut a = lam_glassy.ln() - 1e-9; // g(a) ≤ 0 (glassy bound)
    let mut b = (lam_glassy * s_full.sqrt()).ln() + 1e-9; // g(b) ≥ 0 (relaxed bound)
    let eval = |u: f64| -> (f64, LambdaSolution) {
        let s = solve_reduced(red, u.exp(), q);
        (s.load.ln() - target, s)
    };
    let mut u = lam0.ln().clamp(a, b);
    let (mut g, mut sol) = eval(u);
    let mut iters = 1;
    let mut prev: Option<(f64, f64, f64)> = None; // (u, g, ln fr)
    let mut slope = 2.0;
    let mut dfr = 1.0;
    let last_step;
    loop {
        if g < 0.0 {
            a = u;
        } else {
            b = u;
        }
        if g == 0.0 {
            last_step = 0.0;
            break;
        }
        // secant with the previous point, else slope 2 (elastic), kept inside the bracket
        let s = match prev {
            Some((up, gp, _)) if (u - up).abs() > 0.0 && (g - gp) / (u - up) > 0.0 => {
                (g - gp) / (u - up)
            }
            _ => slope,
        };
        slope = s;
        let mut un = u - g / s;
        if !(un > a && un < b) {
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
            return Err(AutoError::NotConverged {
                iterations: iters,
                lo: a.exp(),
                hi: b.exp(),
            });
        }
        u = un;
        let (gn, sn) = eval(u);
        g = gn;
        sol = sn;
        iters += 1;
    }
    Ok((sol, iters, last_step, slope, dfr))
}

fn package(
    terms: &[CreepTerm],
    red: &Reduction,
    sol: LambdaSolution,
    iterations: usize,
    friction_error: f64,
    size_error: f64,
    settings: &AutoSettings,
) -> AutoSolution {
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
    let friction_error = if friction_error.is_nan() {
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
    let n = sol.coefficients.len();
    AutoSolution {
        solution: DimensionlessSolution {
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
        },
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
        warnings,
    }
}
