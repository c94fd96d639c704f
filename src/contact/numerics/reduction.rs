//! Mode reduction of the `auto` scheme: which retardation modes a scene needs (docs/MATH.md §8).
//!
//! Input: creep terms (fᵢ, bᵢ), the contact length λ and error budgets; output: [`Reduction`] (kept,
//! lumped and dropped modes and the rescaled problem; their errors: `lumped_residual`, `slow_estimate_at`).
//!
//! With L = λ/2, cᵢ = bᵢL (contact half-time over τᵢ), rᵢ = fᵢ/bᵢ = Jᵢ/J_g:
//! - **Fast modes (cᵢ ≫ 1) are lumped into the glassy compliance.** For bξ → ∞ the kernel term
//!   (fᵢ/bᵢ)h(bᵢξ) → (fᵢ/bᵢ)(ln|ξ| + const) (docs/MATH.md §2.2; the reduction: §8), so K → s·ln|ξ| + Σ_kept, s = 1 + Σ_fast rᵢ;
//!   dividing eq. 3.25 by s gives the same problem for Q̂ = sQ′ with f̂ᵢ = fᵢ/s (β, λ and ρF/N are
//!   unchanged, N′ = N̂/s). Dropping such a mode instead would miss its whole compliance.
//!   The error is the mode's boundary layer: the kernel differs from its asymptote only within
//!   |ξ| ≲ 1/bᵢ, so to first order in 1/cᵢ a lumped mode acts like a local compliance of strength
//!   ∝ rᵢ/bᵢ, and the effects of several lumped modes add: ρF/N/λ rises by g_F·Σwᵢ and N′ by the
//!   factor 1 + g_N·Σwᵢ, wᵢ = rᵢ/cᵢ, with g_F, g_N properties of the whole problem. For one term
//!   the exact solution gives g_F = 1/(2(1+r)), g_N = 1/(1+r) (derived in docs/MATH.md §8.2; the exact values deviate by ≈ 1/c, 3 % at c = 30). In a spectrum
//!   the model g_F = 1/(2S_eff), g_N = 1/S_eff with the effective compliance at the contact time
//!   S_eff = 1 + Σrᵢcᵢ/(1+cᵢ) was within 0.82–1.14 of the measured g on random spectra (5–35 terms,
//!   J∞/J_g = 10…1e4); the isolated-mode value 1/(2(1+rᵢ)) overstates it up to S_eff/(1+rᵢ) ~ 1e3×.
//!   The solvers (the half-space's `auto` scheme, the spectral layer) therefore *measure* g once per
//!   answer (one solve with the lumped mode of largest wᵢ kept) and add the first-order correction g·Σwᵢ; what remains is the
//!   second-order term, measured ≤ 0.6·|g·Σwᵢ|/c_min on those spectra (c_min: slowest lumped mode),
//!   and estimated as 2·|g·Σwᵢ|/c_min. Selection uses the same formula with the model g (times
//!   the measured/model ratio once known). With it a tolerance of 1e−6 lumps every mode with
//!   c ≳ 3·10³ instead of c ≳ 10⁷ (the expansion of a mode costs ~√(83(1+r)c) Chebyshev terms):
//!   on the benchmark's 30-term spectrum (24 decades, J∞/J_g = 1e3) 12 of 30 modes are lumped at
//!   tol 1e−6 (10 at 1e−9, 14 at 1e−3) and the answer costs 0.64 ms instead of 10 ms (CPU, docs/DEVLOG.md).
//!   Without the correction the modes beyond the hard cap c = 1e7 alone had cost that spectrum a
//!   true error of 4.5e−8 in ρF/N, whatever the tolerance.
//! - **Slow modes (μᵢ = (1+rᵢ)cᵢ ≪ 1) are dropped.** Over the contact time they creep by only
//!   Jᵢ·t/τᵢ; their term in K is (fᵢ/bᵢ)h(bᵢξ) ≈ fᵢξ(1 − γ − ln|bᵢξ|) → 0 with bᵢ at fixed fᵢ/bᵢ.
//!   Lumping them would add their full compliance, which they never reach. Measured (same cases,
//!   c from 1e−8 to 1e−2): ρF/N/λ ≈ 0.26·r·c·ln(1/c) and 1 − N′ ≤ r·c·μ·(2 + ln(1/μ)); used with a
//!   safety factor 2, per mode in isolation. Within a spectrum the friction law is an upper bound
//!   (~700× on the benchmark's 30-term spectrum: other modes add compliance), but the N′ effect is
//!   first order in c there, so `drop_estimate` adds rᵢcᵢ/S_eff (see its doc).
//!   An exact law behind this (tests/contact_props.rs): as c → 0 the ln b part of the kernel term
//!   is linear in ξ and only shifts β, by (fᵢN′/2)·ln bᵢ, leaving pressure, λ and N′ alone; the
//!   friction law above overstates that shift ~2·S_eff times (a sharper drop estimate would need
//!   the size of the remaining −fᵢξ ln|ξ| part, not measured yet).
//!
//! Fast modes are lumped from the fastest down while the second-order estimate stays inside 0.7 of
//! the budgets (only c ≥ 30, where the first-order law holds); slow modes (μ ≤ 0.05) are dropped
//! cheapest first within the rest. Modes between are always kept.

use super::at_lambda::{
    solve_at_lambda, solve_at_lambda_checked, LambdaSolution, QuadratureSettings,
};
use crate::contact::error::ContactError;
use crate::contact::numerics::modes::Modes;
use crate::contact::problem::CreepTerm;
use std::f64::consts::PI;

/// Smallest c of a lumped mode: the first-order law of the module doc holds from here on.
const C_LUMP_MIN: f64 = 30.0;

/// The outcome of a mode selection at one λ.
#[derive(Debug, Clone)]
pub struct Reduction {
    /// Indices (into the input terms) of modes kept.
    pub kept: Vec<usize>,
    /// Modes in the reduced problem.
    pub modes_used: usize,
    /// Indices of fast modes lumped into the glassy compliance.
    pub lumped: Vec<usize>,
    /// Indices of slow modes dropped.
    pub dropped: Vec<usize>,
    /// s = 1 + Σ_lumped fᵢ/bᵢ (Q′ = Q̂/s, N′ = N̂/s).
    pub scale: f64,
    /// The reduced problem (f̂ = f/s for kept modes).
    pub modes: Modes,
}

/// Lumping weight wᵢ = rᵢ/cᵢ = fᵢ/(bᵢ²L) of a fast mode (module doc).
pub(crate) fn lump_weight(t: &CreepTerm, lambda: f64) -> f64 {
    t.f / (t.b * t.b * 0.5 * lambda)
}

/// Effective compliance ratio at the contact time, S_eff = 1 + Σ rᵢcᵢ/(1+cᵢ) (module doc).
pub(crate) fn effective_compliance(terms: &[CreepTerm], lambda: f64) -> f64 {
    let l = 0.5 * lambda;
    1.0 + terms
        .iter()
        .filter(|t| t.f > 0.0)
        .map(|t| (t.f / t.b) * (t.b * l) / (1.0 + t.b * l))
        .sum::<f64>()
}

/// Model first-order gains (g_F, g_N) of the lumping correction: 1/(2S_eff), 1/S_eff.
pub(crate) fn model_gains(terms: &[CreepTerm], lambda: f64) -> (f64, f64) {
    let s = effective_compliance(terms, lambda);
    (0.5 / s, 1.0 / s)
}

/// (ρF/N/λ error, relative N′ error) of one slow mode dropped, when its estimate applies (μ ≤ 0.05).
/// This is the isolated-mode (one-term) law, second order in c for N′; see [`drop_estimate`] for
/// the first-order term a mode has within a spectrum.
fn slow_estimate(t: &CreepTerm, l: f64) -> Option<(f64, f64)> {
    let c = t.b * l;
    let r = t.f / t.b;
    let mu = (1.0 + r) * c;
    (mu <= 0.05).then(|| {
        let fr = 2.0 * 0.3 * r * c * (1.0 + (1.0 / c).ln());
        let ld = 2.0 * r * c * mu * (2.0 + (1.0 / mu).ln());
        (fr, ld)
    })
}

/// Estimate of dropping a slow mode from a spectrum of effective compliance `s_eff`: the isolated
/// law of [`slow_estimate`] plus, for N′, the mode's share of the creep compliance reached in the
/// contact time, rᵢcᵢ/S_eff. Measured on the 30-term benchmark spectrum (λ = 46.7, S_eff = 556,
/// c = 2e−11…4e−3): the true N′ effect is first order, ≈ 0.9·c/S_eff ≈ rc/(37·S_eff), which the
/// isolated law (∝ c²) understates for c ≲ 1e−7, while its friction law overstates the true effect
/// ~700×; rᵢcᵢ/S_eff bounds the first and is ≤ 1e−10 of N′ there.
fn drop_estimate(t: &CreepTerm, l: f64, s_eff: f64) -> Option<(f64, f64)> {
    slow_estimate(t, l).map(|(fr, ld)| (fr, ld + (t.f / t.b) * t.b * l / s_eff))
}

/// Largest μ = (1 + rᵢ)cᵢ of a mode the lumping calibration solves for: its front layer needs
/// ~√(83μ) ≈ 2.9e4 Chebyshev terms (module [`crate::contact::numerics::chebyshev`]).
pub(crate) const MU_CALIBRATION_MAX: f64 = 1e7;

/// The mode the lumping calibration measures with (the half-space's `auto` scheme): the lumped mode of
/// largest weight, and the c of the probe that stands in for it when its μ = (1 + rᵢ)cᵢ exceeds
/// [`MU_CALIBRATION_MAX`] (`f64::INFINITY`: none): c_p = max(100, μ_max/(1 + rᵢ)). A mode lumped
/// beyond the cap of [`select`] can be far too fast to solve for (c ≈ 1e15 in a random slow-end
/// scene, 13 GB of coefficients); lumped, the probe and the mode are the same problem (only rᵢ
/// enters the scale s).
pub(crate) fn calibration_mode(
    terms: &[CreepTerm],
    lumped: &[usize],
    lambda: f64,
) -> Option<(usize, f64)> {
    let &star = lumped.iter().max_by(|&&a, &&b| {
        lump_weight(&terms[a], lambda).total_cmp(&lump_weight(&terms[b], lambda))
    })?;
    let t = terms[star];
    let r = t.f / t.b;
    let c_probe = if (1.0 + r) * t.b * 0.5 * lambda <= MU_CALIBRATION_MAX {
        f64::INFINITY
    } else {
        (MU_CALIBRATION_MAX / (1.0 + r)).max(100.0)
    };
    Some((star, c_probe))
}

/// Second-order estimate 2·g·Σwᵢ/c_min of the corrected lumping error of `lumped` (module doc),
/// with gains (g_F, g_N): (ρF/N/λ error, relative N′ error). c_min is the smallest c of the lumped
/// modes and of the calibration's probe ([`calibration_mode`]), whose own second-order error
/// enters the measured gain.
pub(crate) fn lumped_residual(
    terms: &[CreepTerm],
    lumped: &[usize],
    lambda: f64,
    gains: (f64, f64),
) -> (f64, f64) {
    let Some((_, c_probe)) = calibration_mode(terms, lumped, lambda) else {
        return (0.0, 0.0);
    };
    let l = 0.5 * lambda;
    let w: f64 = lumped.iter().map(|&i| lump_weight(&terms[i], lambda)).sum();
    let c_min = lumped
        .iter()
        .map(|&i| terms[i].b * l)
        .fold(c_probe, f64::min);
    (
        2.0 * gains.0.abs() * w / c_min,
        2.0 * gains.1.abs() * w / c_min,
    )
}

/// Select modes at contact length λ within the budgets (absolute on ρF/N/λ, relative on N′).
///
/// `gains` are the first-order lumping gains (g_F, g_N) to assume (the model's, or measured).
pub fn select(
    terms: &[CreepTerm],
    lambda: f64,
    fr_budget: f64,
    load_budget: f64,
    gains: (f64, f64),
) -> Reduction {
    let l = 0.5 * lambda;
    // Fast modes, fastest first, while the corrected (second-order) estimate fits in 0.7 of the
    // budgets. Hard cap: a mode with c > C_MAX needs ~√(83μ) > 3e4 Chebyshev terms; it is lumped
    // whatever the budget, and its estimate counts (so the reported error says when tol is not met).
    // The same holds for a mode whose μ ≈ (b + f)·λ/2 exceeds MU_MAX (a strong mode, f ≫ b, can
    // have a moderate c and a huge μ).
    const C_MAX: f64 = 1e7;
    let mut fast: Vec<usize> = (0..terms.len())
        .filter(|&i| terms[i].f > 0.0 && terms[i].b * l >= C_LUMP_MIN)
        .collect();
    fast.sort_by(|&a, &b| terms[b].b.total_cmp(&terms[a].b));
    let mut lumped: Vec<usize> = Vec::new();
    for &i in &fast {
        lumped.push(i);
        let (e_fr, e_ld) = lumped_residual(terms, &lumped, lambda, gains);
        let solvable = terms[i].b * l <= C_MAX && (terms[i].b + terms[i].f) * l <= MU_MAX;
        if solvable && (e_fr > 0.7 * fr_budget || e_ld > 0.7 * load_budget) {
            lumped.pop();
            break;
        }
    }
    let (mut sum_fr, mut sum_ld) = lumped_residual(terms, &lumped, lambda, gains);
    // Slow modes, cheapest first, within what is left.
    let s_eff = effective_compliance(terms, lambda);
    let mut slow: Vec<(f64, usize, f64, f64)> = Vec::new();
    for (i, t) in terms.iter().enumerate() {
        if t.f > 0.0 && !lumped.contains(&i) {
            if let Some((e_fr, e_ld)) = drop_estimate(t, l, s_eff) {
                slow.push(((e_fr / fr_budget).max(e_ld / load_budget), i, e_fr, e_ld));
            }
        }
    }
    slow.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut dropped = Vec::new();
    for &(_, i, e_fr, e_ld) in &slow {
        if sum_fr + e_fr > fr_budget || sum_ld + e_ld > load_budget {
            break;
        }
        sum_fr += e_fr;
        sum_ld += e_ld;
        dropped.push(i);
    }
    let mut kept: Vec<usize> = (0..terms.len())
        .filter(|i| terms[*i].f > 0.0 && !lumped.contains(i) && !dropped.contains(i))
        .collect();
    // Coupled modes can raise the largest root κ above every single mode's b + f: while the reduced
    // problem's largest μ = κλ/2 exceeds MU_MAX and its fastest kept mode is fast enough to lump,
    // lump it (its estimate counts); what is left above MU_MAX is refused by `check_series`.
    loop {
        let red = build(terms, kept.clone(), lumped.clone(), dropped.clone());
        let fastest = kept
            .iter()
            .copied()
            .max_by(|&a, &b| terms[a].b.total_cmp(&terms[b].b));
        match fastest {
            Some(i) if largest_mu(&red, lambda) > MU_MAX && terms[i].b * l >= C_LUMP_MIN => {
                kept.retain(|&k| k != i);
                lumped.push(i);
            }
            _ => return red,
        }
    }
}

/// The reduced problem of a given split: s = 1 + Σ_lumped rᵢ, f̂ = f/s for the kept modes.
///
/// Kept slow modes are solved for separately, however slow: with the Bessel coefficients accurate
/// for small μ (src/special/bessel.rs) 30 slow modes side by side moved ρF/N by ≤ 7e−13 under
/// random relative perturbations of 1e−12 in fᵢ, bᵢ, and 33 modes with c = 1e−22…1e−6 (the shipped
/// test spectrum far on its glassy side) agree with tighter solves to the round-off floor. (Until
/// this version, kept modes with μ ≤ min(0.05, 1e−14/tol) were merged into one term F = Σf,
/// ln B = Σf ln b/F. That is exact to first order in c — a slow mode's b only shifts β by
/// (f·N′/2)·ln b, tests/contact_props.rs — but it is an approximation the solver no longer needs;
/// it cost the 30-term benchmark 1–2 kept modes.)
pub fn build(
    terms: &[CreepTerm],
    kept: Vec<usize>,
    lumped: Vec<usize>,
    dropped: Vec<usize>,
) -> Reduction {
    let scale = 1.0 + lumped.iter().map(|&i| terms[i].f / terms[i].b).sum::<f64>();
    let reduced: Vec<CreepTerm> = kept
        .iter()
        .map(|&i| CreepTerm {
            f: terms[i].f / scale,
            b: terms[i].b,
        })
        .collect();
    Reduction {
        modes_used: reduced.len(),
        kept,
        lumped,
        dropped,
        scale,
        modes: Modes::new(&reduced),
    }
}

/// The same split with lumped mode `i` kept instead (the calibration solve of the correction).
pub(crate) fn unlump(terms: &[CreepTerm], red: &Reduction, i: usize) -> Reduction {
    let mut kept = red.kept.clone();
    kept.push(i);
    kept.sort_unstable();
    let lumped = red.lumped.iter().copied().filter(|&j| j != i).collect();
    build(terms, kept, lumped, red.dropped.clone())
}

/// Re-evaluate the error estimates of the dropped slow modes of a selection at another λ (the
/// lumped modes' error comes from the measured correction, see the half-space's `auto` scheme).
pub(crate) fn slow_estimate_at(terms: &[CreepTerm], red: &Reduction, lambda: f64) -> (f64, f64) {
    let l = 0.5 * lambda;
    let mut fr = 0.0;
    let mut ld = 0.0;
    let s_eff = effective_compliance(terms, lambda);
    for &i in &red.dropped {
        let t = &terms[i];
        match drop_estimate(t, l, s_eff) {
            Some((e_fr, e_ld)) => {
                fr += e_fr;
                ld += e_ld;
            }
            // outside the asymptotic range the whole effect is bounded by the one-term maximum
            None => {
                fr += t.f / t.b;
                ld += 1.0;
            }
        }
    }
    (fr, ld)
}
/// Map a solution of the reduced problem back to the full problem's units.
pub(super) fn unscale(red: &Reduction, mut s: LambdaSolution) -> LambdaSolution {
    s.load /= red.scale;
    for c in s.coefficients.iter_mut() {
        *c /= red.scale;
    }
    s
}

/// Largest μ = κλ/2 of a kept mode the scheme solves for. A mode's Chebyshev series needs
/// √(83μ) + 12 orders (src/special/bessel.rs): 2.9e5 at μ = 1e9, i.e. 2.3 MB and about 0.5 s per
/// mode. Fast modes beyond it are lumped ([`select`]); a slow one (c < 30 with f/b > ~3e7) makes
/// the solve refuse, so that memory and time stay bounded on any input.
pub const MU_MAX: f64 = 1e9;

/// The largest μ = κλ/2 of the reduced problem (its fastest root).
fn largest_mu(red: &Reduction, lambda: f64) -> f64 {
    (0..red.modes.len())
        .map(|j| red.modes.kappa(j) * 0.5 * lambda)
        .fold(0.0, f64::max)
}

/// Refuse a reduced problem whose largest μ = κλ/2 exceeds [`MU_MAX`].
pub(super) fn check_series(red: &Reduction, lambda: f64) -> Result<(), ContactError> {
    let mu = largest_mu(red, lambda);
    if mu > MU_MAX || mu.is_nan() {
        return Err(ContactError::OutOfRange {
            scheme: "auto",
            quantity: "mu = kappa*lambda/2 of a kept creep mode (its Chebyshev series needs sqrt(83 mu) terms)",
            value: mu,
            bound: "at most",
            limit: MU_MAX,
        });
    }
    Ok(())
}

/// Solve the reduced problem at λ and map back to the full problem's units.
pub(crate) fn solve_reduced(
    red: &Reduction,
    lambda: f64,
    q: QuadratureSettings,
) -> Result<LambdaSolution, ContactError> {
    check_series(red, lambda)?;
    Ok(unscale(red, solve_at_lambda(&red.modes, lambda, q)))
}

/// As [`solve_reduced`], with the quadrature error estimate: (solution, relative error of ρF/N,
/// relative error of N′). The trapezoid error falls like e^{−π²/h} (module doc of
/// [`at_lambda`]; measured constant ≤ 1 for h = 0.4…0.8 on 1–30-term problems), so the error at
/// step h is about e^{−π²/(2h)} times the difference to the same sum on every second node (step
/// 2h, no extra exterior values); we take 10 times that.
pub(crate) fn solve_reduced_checked(
    red: &Reduction,
    lambda: f64,
    q: QuadratureSettings,
) -> Result<(LambdaSolution, f64, f64), ContactError> {
    check_series(red, lambda)?;
    let (fine, coarse) = solve_at_lambda_checked(&red.modes, lambda, q);
    let k = 10.0 * (-PI * PI / (2.0 * q.step)).exp();
    let e_fr = k * rel(coarse.friction_rho, fine.friction_rho);
    let e_ld = k * rel(coarse.load, fine.load);
    Ok((unscale(red, fine), e_fr, e_ld))
}

/// Relative difference |a − b|/|b|, 0 for equal values.
pub(super) fn rel(a: f64, b: f64) -> f64 {
    // equal values (e.g. ρF/N = 0 of an all-lumped, elastic reduced problem) differ by nothing;
    // 0/0 would give NaN and swallow the rest of the estimate
    if a == b {
        0.0
    } else {
        ((a - b) / b).abs()
    }
}
