//! The thesis scheme (Padyala 2009, §3.2 eq. 3.25–3.26 and Fig. 3), exactly as written: at a given
//! contact length λ, piecewise-linear pressure Q′ on n equal intervals of [0, λ], zero at both ends,
//! collocation of eq. 3.25 at the n nodes ξ₁ … ξₙ (eq. 3.25 holds trivially at ξ₀ = 0), unknowns the
//! n − 1 interior nodal pressures and the offset β. Shared: the half-space's thesis scheme is
//! [`solve_at_lambda`] on the kernel of [`super::kernel`]; the bonded layer's hat scheme assembles its
//! own kernel's averages and solves them with `solve_hat_system`.
//!
//! Input: a [`Kernel`], λ and n; output: a [`DimensionlessSolution`] (scheme `thesis`).
//!
//! Eq. 3.25: ∫₀^λ Q′(ξ′)[K(−ξ′) − K(ξ−ξ′)] dξ′ = ξβ − ξ²/2. With Q′ = Σⱼ Qⱼ φⱼ (hat functions of
//! half-width h = λ/n), ∫ φⱼ(ξ′)K(ξᵢ−ξ′)dξ′ = A(i−j), the second difference of K₂ over h
//! ([`Kernel::hat_averages`]). Row i (i = 1…n):
//!
//! ```text
//!   Σⱼ Qⱼ [A(−j) − A(i−j)] − ξᵢ β = −ξᵢ²/2,     j = 1 … n−1
//! ```
//!
//! A depends on i − j only (Toeplitz), so assembly needs O(n) special-function calls per term (at most
//! 2(2n + 3)), not O(n²).
//! The dense system is solved by LU with partial pivoting (nalgebra). Integrated quantities are exact
//! for the piecewise-linear pressure: ∫Q′ = hΣQⱼ, ∫Q′ξ = hΣQⱼξⱼ, so N′ = 2hΣQⱼ (eq. 3.24) and
//! ρF/N = ΣQⱼ(ξⱼ − β)/ΣQⱼ (eq. 3.20 with eq. 3.22).
//!
//! Accuracy (docs/MATH.md §3): λ, β and N′ converge like h (first order); where the front-edge layer of width
//! ≈ 1/(b+f) is unresolved the nodal pressure zig-zags (the thesis' "jagged" front edge).

use super::kernel::Kernel;
use crate::contact::error::{positive, ContactError};
use crate::contact::problem::DimensionlessSolution;
use nalgebra::{DMatrix, DVector};

/// Smallest number of intervals (one interior unknown plus β).
pub(crate) const MIN_INTERVALS: usize = 2;
/// Largest number of intervals accepted: the work budget's [`crate::limits::CONTACT_N_MAX`] (a dense
/// n × n LU; 20 000² doubles were 3.2 GB).
pub(crate) const MAX_INTERVALS: usize = crate::limits::CONTACT_N_MAX;

/// Check n against [`MIN_INTERVALS`]..=[`MAX_INTERVALS`].
pub(crate) fn check_intervals(n: usize) -> Result<usize, ContactError> {
    if (MIN_INTERVALS..=MAX_INTERVALS).contains(&n) {
        Ok(n)
    } else {
        Err(ContactError::BadIntervals {
            min: MIN_INTERVALS,
            max: MAX_INTERVALS,
            n,
        })
    }
}

/// Solve eq. 3.25 by the thesis scheme at contact length `lambda` with `n` intervals.
pub fn solve_at_lambda(
    kernel: &Kernel,
    lambda: f64,
    n: usize,
) -> Result<DimensionlessSolution, ContactError> {
    positive("lambda", lambda)?;
    check_intervals(n)?;
    let h = lambda / n as f64;
    // a[k + n] = A(k), k = −n..=n.
    let a = kernel.hat_averages(n, h);
    solve_hat_system(&a, n, lambda, "thesis")
}

/// Assemble and solve the collocation system above for the hat averages `a` of any kernel of the form
/// K(ξ) + const (a[k + c] = A(k), c = a.len()/2 ≥ n; the bonded layer's hat scheme uses it
/// too); `scheme` names the result.
pub(crate) fn solve_hat_system(
    a: &[f64],
    n: usize,
    lambda: f64,
    scheme: &str,
) -> Result<DimensionlessSolution, ContactError> {
    let h = lambda / n as f64;
    let centre = (a.len() / 2) as i64;
    let at = |k: i64| a[(k + centre) as usize];
    let xi = |i: usize| lambda * (i as f64) / (n as f64);

    let mut m = DMatrix::<f64>::zeros(n, n);
    let mut rhs = DVector::<f64>::zeros(n);
    for r in 0..n {
        let i = r + 1;
        for j in 1..n {
            m[(r, j - 1)] = at(-(j as i64)) - at(i as i64 - j as i64);
        }
        let x = xi(i);
        m[(r, n - 1)] = -x;
        rhs[r] = -0.5 * x * x;
    }
    let sol = m
        .lu()
        .solve(&rhs)
        .filter(|s| s.iter().all(|v| v.is_finite()))
        .ok_or(ContactError::Singular { lambda, n })?;

    let beta = sol[n - 1];
    let mut pressure = vec![0.0; n + 1];
    pressure[1..n].copy_from_slice(&sol.as_slice()[..n - 1]);
    let xs: Vec<f64> = (0..=n).map(xi).collect();
    let (sum_q, sum_qx) = (1..n).fold((0.0, 0.0), |(s, sx), j| {
        (s + pressure[j], sx + pressure[j] * (xs[j] - beta))
    });
    Ok(DimensionlessSolution {
        scheme: scheme.to_string(),
        lambda,
        beta,
        load: 2.0 * h * sum_q,
        friction_rho: sum_qx / sum_q,
        xi: xs,
        pressure,
        n,
        iterations: 0,
        error_estimate: None,
        diagnostics: None,
        warnings: Vec::new(),
    })
}
