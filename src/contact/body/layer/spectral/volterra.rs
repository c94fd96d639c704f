//! The inverse of the contact's Volterra operator on Chebyshev series (the viscoelastic memory of
//! the half-space part of the layer equation, module doc of [`super`]).
//!
//! Input: a mode's exponent μ > 0 and the Chebyshev coefficients of f on the contact t ∈ [−1, 1];
//! output: the Chebyshev coefficients of Y\[f\](t) = ∫_t^1 e^{−μ(u−t)}f(u)du, either exact
//! ([`memory_exact`]) or up to a multiple of e^{μ(t−1)} ([`memory_polynomial`]).
//!
//! # Exact form (slow and moderate μ)
//! y = Y\[f\] solves y′ = μy − f, y(1) = 0, i.e. y = 𝒥[f − μy] with 𝒥g = ∫_t^1 g. With the Chebyshev
//! antiderivative (∫T₀ = T₁, ∫T₁ = T₂/4, ∫Tₙ = Tₙ₊₁/(2(n+1)) − Tₙ₋₁/(2(n−1)); Mason & Handscomb,
//! *Chebyshev Polynomials*, CRC 2003, §2.4.4) the coefficients n ≥ 1 satisfy, for n ≥ 2,
//!
//! ```text
//!   yₙ − (μ/2n)(yₙ₋₁ − yₙ₊₁) = −(fₙ₋₁ − fₙ₊₁)/(2n),     n = 1: y₁ − μ(y₀ − y₂/2) = −(f₀ − f₂/2),
//! ```
//!
//! and y(1) = Σyₙ = 0 closes the system. Truncated at M coefficients (yₘ = 0, the tau method) it is
//! tridiagonal in y₁…y_{M−1} with y₀ a parameter: y = u + y₀v, then y₀ = −Σu/(1 + Σv). The
//! tridiagonal part is solved by Gaussian elimination with partial pivoting (backward stable for
//! tridiagonal matrices; Higham, *Accuracy and Stability of Numerical Algorithms*, SIAM 2002, §9.6),
//! factored once per μ and applied to all right-hand sides of a solve together (the p + 1 basis
//! polynomials of a slow mode, stored row by row so that each elimination step runs across them:
//! [`memory_exact_add`]; the same operations per right-hand side as one at a time, bit for bit).
//! Like Miller's algorithm for Bessel functions, the truncated solve picks the decaying solution of
//! the three-term recurrence, so it is stable where the forward recurrence is not. y has the
//! coefficients of f convolved with those of e^{μ(t−1)}, which fall below 1e−18 after ≈ √(83μ)
//! orders (module [`crate::special::bessel`]), so M = deg f + √(83μ) + 12 truncates below rounding.
//!
//! # Polynomial form (fast μ)
//! For μ large against deg(f)² the polynomial solution P = (μ − d/dt)⁻¹f = Σₖ f⁽ᵏ⁾/μᵏ⁺¹ is short and
//! Y\[f\] = P − P(1)e^{μ(t−1)}. Its terms grow like e^{m²/(2μ)} for f = Tₘ (the Laplace transform of
//! Tₘ(1+s)), so it is used only where that stays below e² (`POLY_MIN_MU`).

/// μ from which the polynomial form is used for degree m: μ ≥ max(m²/4, 30) (growth ≤ e²).
pub fn poly_min_mu(m: usize) -> f64 {
    ((m * m) as f64 / 4.0).max(30.0)
}

/// Tridiagonal system (sub-diagonal `dl[i]` = A[i+1][i], diagonal `d`, super-diagonal `du[i]` =
/// A[i][i+1]) solved for several right-hand sides by Gaussian elimination with partial pivoting.
struct Tridiagonal {
    n: usize,
    d: Vec<f64>,
    du: Vec<f64>,
    du2: Vec<f64>,
    /// Per elimination step: (rows swapped, multiplier).
    steps: Vec<(bool, f64)>,
}

impl Tridiagonal {
    fn factor(mut dl: Vec<f64>, mut d: Vec<f64>, mut du: Vec<f64>) -> Tridiagonal {
        let n = d.len();
        let mut du2 = vec![0.0; n];
        let mut steps = Vec::with_capacity(n);
        for i in 0..n.saturating_sub(1) {
            if d[i].abs() >= dl[i].abs() {
                let fact = if d[i] != 0.0 { dl[i] / d[i] } else { 0.0 };
                d[i + 1] -= fact * du[i];
                steps.push((false, fact));
            } else {
                // swap rows i and i + 1: row i becomes (dl[i], d[i+1], du[i+1])
                let fact = d[i] / dl[i];
                d[i] = dl[i];
                let temp = d[i + 1];
                d[i + 1] = du[i] - fact * temp;
                if i + 2 < n {
                    du2[i] = du[i + 1];
                    du[i + 1] = -fact * du2[i];
                }
                du[i] = temp;
                steps.push((true, fact));
            }
            dl[i] = 0.0;
        }
        Tridiagonal {
            n,
            d,
            du,
            du2,
            steps,
        }
    }

    /// [`Tridiagonal::solve`] for `r` right-hand sides at once, stored row by row (`b[i·r + c]` is
    /// row i of right-hand side c): the same operations on each right-hand side in the same order, so
    /// the same results bit for bit, but the inner loops run across the right-hand sides (independent,
    /// vectorisable) instead of waiting on one elimination chain (test `blocked_solve_is_the_scalar_solve`).
    fn solve_rows(&self, b: &mut [f64], r: usize) {
        let n = self.n;
        if n == 0 || r == 0 {
            return;
        }
        for (i, &(swap, fact)) in self.steps.iter().enumerate() {
            let (lo, hi) = b[i * r..(i + 2) * r].split_at_mut(r);
            if swap {
                for (x, y) in lo.iter_mut().zip(hi.iter_mut()) {
                    let t = *x;
                    *x = *y;
                    *y = t - fact * *x;
                }
            } else {
                for (x, y) in lo.iter().zip(hi.iter_mut()) {
                    *y -= fact * x;
                }
            }
        }
        let dn = self.d[n - 1];
        for v in b[(n - 1) * r..n * r].iter_mut() {
            *v /= dn;
        }
        if n > 1 {
            let (du, d) = (self.du[n - 2], self.d[n - 2]);
            let (lo, hi) = b[(n - 2) * r..n * r].split_at_mut(r);
            for (x, y) in lo.iter_mut().zip(hi.iter()) {
                *x = (*x - du * y) / d;
            }
        }
        for i in (0..n.saturating_sub(2)).rev() {
            let (du, du2, d) = (self.du[i], self.du2[i], self.d[i]);
            let (lo, hi) = b[i * r..(i + 3) * r].split_at_mut(r);
            let (h1, h2) = hi.split_at(r);
            for ((x, y), z) in lo.iter_mut().zip(h1).zip(h2) {
                *x = (*x - du * y - du2 * z) / d;
            }
        }
    }

    #[cfg(test)]
    fn solve(&self, b: &mut [f64]) {
        let n = self.n;
        for (i, &(swap, fact)) in self.steps.iter().enumerate() {
            if swap {
                let t = b[i];
                b[i] = b[i + 1];
                b[i + 1] = t - fact * b[i];
            } else {
                b[i + 1] -= fact * b[i];
            }
        }
        if n == 0 {
            return;
        }
        b[n - 1] /= self.d[n - 1];
        if n > 1 {
            b[n - 2] = (b[n - 2] - self.du[n - 2] * b[n - 1]) / self.d[n - 2];
        }
        for i in (0..n.saturating_sub(2)).rev() {
            b[i] = (b[i] - self.du[i] * b[i + 1] - self.du2[i] * b[i + 2]) / self.d[i];
        }
    }
}

/// Coefficient n of the antiderivative of Σ fₖTₖ (n ≥ 1; module doc).
fn antiderivative(f: &[f64], n: usize) -> f64 {
    let at = |k: usize| f.get(k).copied().unwrap_or(0.0);
    if n == 1 {
        at(0) - 0.5 * at(2)
    } else {
        (at(n - 1) - at(n + 1)) / (2.0 * n as f64)
    }
}

/// Exact Y\[f\] = ∫_t^1 e^{−μ(u−t)}f(u)du for each f of `fs` (Chebyshev coefficients), μ > 0, with
/// `m` coefficients (module doc: m ≥ deg f + √(83μ) + 12 truncates below rounding).
#[cfg(test)]
pub fn memory_exact(mu: f64, fs: &[&[f64]], m: usize) -> Vec<Vec<f64>> {
    let mut out = vec![Vec::new(); fs.len()];
    memory_exact_add(mu, fs, m, 1.0, &mut out);
    out
}

/// `out[c] += s·Y[fs[c]]` ([`memory_exact`]; `out[c]` grown to m.max(4) coefficients, s·Y
/// computed as in `add_scaled` of the caller: each coefficient once, then added). All right-hand
/// sides share the factorisation and are eliminated together (`Tridiagonal::solve_rows`).
pub fn memory_exact_add(mu: f64, fs: &[&[f64]], m: usize, s: f64, out: &mut [Vec<f64>]) {
    let m = m.max(4);
    let n = m - 1; // unknowns y₁ … y_{m−1}
    let tri = tridiagonal(mu, n);
    let mut v = vec![0.0; n];
    v[0] = mu;
    tri.solve_rows(&mut v, 1);
    let sv: f64 = v.iter().sum();
    let r = fs.len();
    // row k − 1 holds −(antiderivative coefficient k) of every f
    // (coefficients k > len f vanish: only the first len f rows are filled)
    let mut u = vec![0.0; n * r];
    for (c, f) in fs.iter().enumerate() {
        for k in 1..m.min(f.len() + 1) {
            u[(k - 1) * r + c] = -antiderivative(f, k);
        }
    }
    tri.solve_rows(&mut u, r);
    // Σu per right-hand side, in row order (as `Iterator::sum`, which starts from −0.0)
    let mut su = vec![-0.0; r];
    for row in u.chunks_exact(r) {
        for (a, x) in su.iter_mut().zip(row) {
            *a += x;
        }
    }
    for (c, dst) in out.iter_mut().enumerate().take(r) {
        let y0 = -su[c] / (1.0 + sv);
        if dst.len() < m {
            dst.resize(m, 0.0);
        }
        dst[0] += s * y0;
        for ((d, row), vk) in dst[1..m].iter_mut().zip(u.chunks_exact(r)).zip(&v) {
            *d += s * (row[c] + y0 * vk);
        }
    }
}

/// The tau system of the module doc in y₁ … y_n, factored.
fn tridiagonal(mu: f64, n: usize) -> Tridiagonal {
    let mut dl = vec![0.0; n.saturating_sub(1)];
    let d = vec![1.0; n];
    let mut du = vec![0.0; n.saturating_sub(1)];
    for r in 0..n {
        let k = r + 1;
        let s = if k == 1 {
            0.5 * mu
        } else {
            mu / (2.0 * k as f64)
        };
        if r + 1 < n {
            du[r] = s;
        }
        if r >= 1 {
            dl[r - 1] = -s;
        }
    }
    Tridiagonal::factor(dl, d, du)
}

/// The polynomial P = (μ − d/dt)⁻¹f (same length as f) and P(1): Y\[f\] = P − P(1)e^{μ(t−1)}.
pub fn memory_polynomial(mu: f64, f: &[f64]) -> (Vec<f64>, f64) {
    let m = f.len();
    let mut y = vec![0.0; m];
    // derivative coefficients dₙ of y: d_{n−1} = d_{n+1} + 2n·yₙ, d₀ halved
    let (mut d_next, mut d_cur) = (0.0, 0.0); // d_{n+1}, d_n
    for n in (0..m).rev() {
        let dn = if n == 0 { 0.5 * d_cur } else { d_cur };
        y[n] = (f[n] + dn) / mu;
        if n >= 1 {
            let d_prev = d_next + 2.0 * n as f64 * y[n];
            d_next = d_cur;
            d_cur = d_prev;
        }
    }
    let p1 = y.iter().sum();
    (y, p1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::chebyshev::clenshaw;

    /// ∫_t^1 e^{−μ(u−t)}Tₘ(u)du by composite Simpson (independent of the recurrences).
    fn direct(mu: f64, m: usize, t: f64) -> f64 {
        let k = 20000;
        let h = (1.0 - t) / k as f64;
        let g = |u: f64| (-mu * (u - t)).exp() * (m as f64 * u.clamp(-1.0, 1.0).acos()).cos();
        let mut s = g(t) + g(1.0);
        for i in 1..k {
            s += g(t + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
        }
        s * h / 3.0
    }

    /// The straightforward [`memory_exact`]: one scalar tridiagonal solve per f (the form before
    /// the blocked elimination).
    fn memory_exact_scalar(mu: f64, fs: &[&[f64]], m: usize) -> Vec<Vec<f64>> {
        let m = m.max(4);
        let n = m - 1;
        let tri = tridiagonal(mu, n);
        let mut v = vec![0.0; n];
        v[0] = mu;
        tri.solve(&mut v);
        let sv: f64 = v.iter().sum();
        fs.iter()
            .map(|f| {
                let mut u: Vec<f64> = (1..m).map(|k| -antiderivative(f, k)).collect();
                tri.solve(&mut u);
                let y0 = -u.iter().sum::<f64>() / (1.0 + sv);
                let mut y = Vec::with_capacity(m);
                y.push(y0);
                y.extend(u.iter().zip(&v).map(|(a, b)| a + y0 * b));
                y
            })
            .collect()
    }

    #[test]
    fn blocked_solve_is_the_scalar_solve() {
        // the blocked elimination does each right-hand side's operations in the same order as the
        // scalar solve, so the results must agree bit for bit (also the scaled accumulation of
        // `memory_exact_add` against scaling the scalar result), for μ where the elimination
        // pivots (μ ≫ 1) and where it does not, and for dense and basis right-hand sides
        for &mu in &[1e-6_f64, 0.3, 5.0, 40.0, 900.0] {
            let p = 12;
            let mut fs: Vec<Vec<f64>> = (0..=p)
                .map(|m| {
                    let mut v = vec![0.0; m + 1];
                    v[m] = 1.0;
                    v
                })
                .collect();
            fs.push(
                (0..9)
                    .map(|k| (0.7 * k as f64).sin() / (1.0 + k as f64))
                    .collect(),
            );
            let refs: Vec<&[f64]> = fs.iter().map(|v| v.as_slice()).collect();
            let size = p + 1 + (83.0 * mu).sqrt().ceil() as usize + 12;
            let a = memory_exact(mu, &refs, size);
            let b = memory_exact_scalar(mu, &refs, size);
            assert_eq!(a, b, "μ {mu}");
            let s = -0.37;
            let mut acc: Vec<Vec<f64>> = (0..fs.len()).map(|c| vec![0.25 * c as f64; 3]).collect();
            let mut want = acc.clone();
            memory_exact_add(mu, &refs, size, s, &mut acc);
            for (w, y) in want.iter_mut().zip(&b) {
                w.resize(y.len(), 0.0);
                for (d, v) in w.iter_mut().zip(y) {
                    *d += s * v;
                }
            }
            assert_eq!(acc, want, "μ {mu}");
        }
    }

    #[test]
    fn exact_memory_matches_quadrature() {
        // Simpson with 20000 panels on these integrands: error ≲ 1e−12 (μ ≤ 40: h⁴μ⁴/180 ≈ 1e−14).
        for &mu in &[1e-6_f64, 0.3, 5.0, 40.0] {
            for m in [0usize, 1, 3, 8] {
                let mut f = vec![0.0; m + 1];
                f[m] = 1.0;
                let size = m + 1 + (83.0 * mu).sqrt().ceil() as usize + 12;
                let y = &memory_exact(mu, &[&f], size)[0];
                for &t in &[-1.0, -0.4, 0.3, 0.9, 1.0] {
                    let want = direct(mu, m, t);
                    let got = clenshaw(y, t);
                    assert!(
                        (got - want).abs() < 1e-11,
                        "μ {mu} m {m} t {t}: {got} vs {want}"
                    );
                }
            }
        }
    }

    #[test]
    fn polynomial_memory_is_exact_with_the_exponential() {
        // P − P(1)e^{μ(t−1)} is the exact memory; growth e^{m²/(2μ)} ≤ e at μ = 64, m = 8.
        for &mu in &[64.0_f64, 200.0] {
            for m in [0usize, 2, 8] {
                let mut f = vec![0.0; m + 1];
                f[m] = 1.0;
                let (p, p1) = memory_polynomial(mu, &f);
                for &t in &[-0.7_f64, 0.2, 0.99] {
                    let got = clenshaw(&p, t) - p1 * (mu * (t - 1.0)).exp();
                    let want = direct(mu, m, t);
                    assert!(
                        (got - want).abs() < 1e-11,
                        "μ {mu} m {m} t {t}: {got} vs {want}"
                    );
                }
            }
        }
    }
}
