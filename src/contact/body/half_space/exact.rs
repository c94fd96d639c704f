//! Exact solution of the rolling-contact problem (thesis eq. 3.25) for ONE creep term γ(ζ) = f·e^(−bζ)
//! (the standard linear solid; Hunter, J. Appl. Mech. 1961, solved the same case), at a given contact
//! length λ or at a given load N′.
//!
//! Input: a [`CreepTerm`] and λ (or N′); output: [`OneTermExact`] (λ, β, N′, ρ·F/N and the pressure
//! Q′(ξ) anywhere on the contact) or a [`DimensionlessSolution`] with scheme `exact`. This is the
//! library's reference for every test of the general (piecewise-linear) solver.
//!
//! # Derivation (MATH.md §3, written out; symbols as in the thesis)
//! Problem: Q′ ≥ 0 on 0 ≤ ξ ≤ λ, zero at both edges, and β with
//! ∫₀^λ Q′(ξ′)[K(−ξ′) − K(ξ−ξ′)]dξ′ = ξβ − ξ²/2 (eq. 3.25), K(ξ) = ln|ξ| + ∫₀^∞ γ(ζ) ln|ξ+ζ| dζ
//! (eq. 3.19). At ξ = 0 both sides vanish, so eq. 3.25 is equivalent to its ξ-derivative
//!
//! (D1)  H(ξ) + G(ξ) = ξ − β on (0, λ),  H(x) = ∫₀^λ Q′(t)/(x − t) dt,  G(ξ) = f∫₀^∞ e^(−bζ) H(ξ+ζ) dζ,
//!
//! H a principal value inside the contact and the outer Hilbert transform beyond it. G′ = bG − fH, so
//! on the contact H′ = κH + 1 − b(ξ − β), κ = b + f, whose solutions are
//!
//! (D2)  H(ξ) = (b/κ)ξ + a₀ + A·e^(κ(ξ−λ)),  a₀ = (b/κ − 1 − bβ)/κ.
//!
//! (D1) then holds on the whole contact iff it holds at one point; we impose it at the front edge,
//! where G(λ) involves only the outer transform: G(λ) = λ − β − H(λ).
//!
//! Map ξ = (λ/2)(1 + y), y = cos θ ∈ [−1, 1]; c = κλ/2, p = bλ/2. Then e^(κ(ξ−λ)) = e^(c(y−1)) =
//! Ĩ₀(c) + 2Σₙ Ĩₙ(c)Tₙ(y) with Ĩₙ = e^(−c)Iₙ(c) (A&S 9.6.34) — the scaled form never overflows. With
//! ∫₋₁¹ √(1−s²)Uₙ₋₁(s)/(y−s) ds = πTₙ(y) inside and = πwⁿ, w = y − √(y²−1), outside (|y| > 1), the
//! finite Hilbert transform is inverted with Q′ bounded at both edges:
//!
//! (D3)  Q′ = (1/π) Σₙ≥₁ hₙ sin(nθ),  H = Σₙ hₙTₙ(y),  with solvability h₀ = 0,
//!
//! h₁ = bλ/(2κ) + 2AĨ₁, hₙ = 2AĨₙ (n ≥ 2), h₀ = bλ/(2κ) + a₀ + AĨ₀. The front-edge condition, with
//! y = cosh u, w = e^(−u), W(u) = e^(−2p·sinh²(u/2))·sinh u, gives (all terms positive):
//!
//! (D4)  A = (f/κ)(1/b + (λ/2)·pP) / D,  D = 1 + (f/b)Ĩ₀ + fλΣ,
//!       λ/2 − β = f/(κbD) · [E(c) + cĨ₀·pM₁ + fλΣ],   E(c) = 1 − (1+c)Ĩ₀(c),
//!
//! pM₁ = p∫₀^∞ W e^(−u) du, pP = p∫₀^∞ W (1 − e^(−u)) du (pM₁ + pP = 1), Σ = ∫₀^∞ W Σₙ Ĩₙe^(−nu) du.
//! These three integrands are analytic and positive; they are integrated by adaptive Gauss–Legendre
//! quadrature to ~1e-15. Finally (orthogonality of Uₙ with weight √(1−s²))
//!
//! (D5)  N′ = 2∫Q′dξ = λh₁/2,  ρF/N = ∫Q′(ξ−β)/∫Q′ = (λ/2 − β) + (λ/4)·h₂/h₁.
//!
//! Each quantity is a sum of positive terms (E(c) < 0 only for c ≳ 3.5, where it is O(1)), so nothing
//! cancels catastrophically for small or large κλ, bλ or f/b.
//!
//! Accuracy (tests in src/contact/exact_tests.rs): β, N′ and ρF/N agree with a 30-digit mpmath
//! evaluation (tools/gen_exact_reference.py) to ≤ 1.1e-14 relative over f/b = 1e-3…1e3, bλ = 1e-4…1e4,
//! κλ ≤ 2e4 (24 cases); the pressure satisfies eq. 3.25 by direct quadrature to ~4e-15 of
//! max|ξβ − ξ²/2|. The series has ≈ 6.6√(κλ) terms for large κλ (20927 at κλ = 1e7); inputs up to
//! κλ = 1e9 ([`MAX_KAPPA_LAMBDA`]) run (≈ 1 s per solve at κλ = 1e8, under 1 ms at 1e4, release build)
//! and bλ down to 1e-12 and below work (the quadrature range grows only like ln(1/bλ)); beyond 2e4 the
//! results are checked only through the limits and the scaling test, not against the table.
//! Check case (Goodier & Loutzenheiser, thesis Table 1): f = 10, b = 1, λ = 1 gives β/λ = 0.195197805,
//! ρF/N = 0.432188415, N′ = 0.0723787886 (G&L: 0.1952, 0.4308; thesis scheme n = 40: 0.1959, 0.43093).
//!
//! Limits: f = 0 gives Hertz (A = 0, β = λ/2, Q′ = (1/π)√(ξ(λ−ξ)), N′ = λ²/4). bλ → ∞ at fixed f/b: Hertz
//! with compliance (1 + f/b) (N′ → λ²/(4(1+f/b))). bλ → 0 at fixed f/b: the creep term vanishes
//! (∫γ ln|ξ+ζ| → (f/b)·O(bλ·ln bλ)), Hertz with the glassy compliance.

use crate::contact::error::ContactError;
use crate::contact::{CreepTerm, DimensionlessSolution};
use crate::special::gauss_legendre::Integrator;
use crate::special::{one_minus_one_plus_c_i0, scaled_bessel_i};

/// Largest κλ accepted: the series then has ~1.3e5 terms and one solve takes of the order of a second.
pub const MAX_KAPPA_LAMBDA: f64 = 1e9;

/// Smallest bλ accepted (the solution is then Hertz to about (f/b)·bλ·ln(1/bλ) anyway).
pub const MIN_B_LAMBDA: f64 = 1e-250;

/// Relative cut of the Bessel series Ĩₙ(c) (terms below it are dropped; relative to the largest order ≥ 1; see [`scaled_bessel_i`]).
const SERIES_CUT: f64 = 1e-19;
/// Relative tolerance of the adaptive quadratures (integrands are positive and analytic).
const QUAD_TOL: f64 = 1e-15;

/// The exact one-term solution at one contact length.
#[derive(Debug, Clone, PartialEq)]
pub struct OneTermExact {
    /// The creep term.
    pub term: CreepTerm,
    /// Contact length λ.
    pub lambda: f64,
    /// Offset β (eq. 3.22).
    pub beta: f64,
    /// Load N′ = 2∫Q′dξ (eq. 3.24).
    pub load: f64,
    /// ρ·F/N = ∫Q′(ξ−β)dξ / ∫Q′dξ.
    pub friction_rho: f64,
    /// Iterations of the load loop (0 at given λ).
    pub iterations: usize,
    /// hₙ for n = 1…N (index n−1): Q′ = (1/π)Σ hₙ sin(nθ), ξ = (λ/2)(1 + cos θ) (eq. D3).
    coeffs: Vec<f64>,
}

fn check_term(term: CreepTerm) -> Result<(), ContactError> {
    if !(term.f.is_finite() && term.f >= 0.0 && term.b.is_finite() && term.b > 0.0) {
        return Err(ContactError::BadTerm {
            index: 0,
            f: term.f,
            b: term.b,
        });
    }
    Ok(())
}

fn out_of_range(
    quantity: &'static str,
    value: f64,
    bound: &'static str,
    limit: f64,
) -> ContactError {
    ContactError::OutOfRange {
        scheme: "exact",
        quantity,
        value,
        bound,
        limit,
    }
}

/// The exact solution at given contact length λ (eq. D1–D5 of the module docs).
pub fn one_term_at_lambda(term: CreepTerm, lambda: f64) -> Result<OneTermExact, ContactError> {
    check_term(term)?;
    if !(lambda.is_finite() && lambda > 0.0) {
        return Err(ContactError::BadValue {
            field: "lambda".into(),
            expected: "finite and > 0",
            value: lambda,
        });
    }
    let kl = (term.b + term.f) * lambda;
    if kl > MAX_KAPPA_LAMBDA {
        return Err(out_of_range(
            "(b + f)*lambda",
            kl,
            "at most",
            MAX_KAPPA_LAMBDA,
        ));
    }
    if term.b * lambda < MIN_B_LAMBDA {
        return Err(out_of_range(
            "b*lambda",
            term.b * lambda,
            "at least",
            MIN_B_LAMBDA,
        ));
    }
    Ok(solve_with_cut(term, lambda, SERIES_CUT))
}

/// The solution with an explicit relative cut of the Bessel series (for convergence tests).
#[cfg(test)]
pub(crate) fn solve_with_cut_for_tests(term: CreepTerm, lambda: f64, cut: f64) -> OneTermExact {
    solve_with_cut(term, lambda, cut)
}

fn solve_with_cut(term: CreepTerm, lambda: f64, cut: f64) -> OneTermExact {
    let CreepTerm { f, b } = term;
    if f == 0.0 {
        // Hertz (eq. D2 with A = 0, β = λ/2): H = ξ − λ/2, h₁ = λ/2.
        return OneTermExact {
            term,
            lambda,
            beta: 0.5 * lambda,
            load: 0.25 * lambda * lambda,
            friction_rho: 0.0,
            iterations: 0,
            coeffs: vec![0.5 * lambda],
        };
    }
    let kappa = b + f;
    let c = 0.5 * kappa * lambda;
    let p = 0.5 * b * lambda;
    let i_n = scaled_bessel_i(c, cut);
    let i0 = i_n[0];
    let i1 = i_n.get(1).copied().unwrap_or(0.0);
    let i2 = i_n.get(2).copied().unwrap_or(0.0);

    let (pm1, pp, sigma) = front_edge_integrals(c, p, &i_n);

    // Eq. D4. f/κ and f/b are formed once; every sum below is of positive terms (see module docs).
    let f_over_b = f / b;
    let d = 1.0 + f_over_b * i0 + f * lambda * sigma;
    let a = (f / kappa) * (1.0 / b + 0.5 * lambda * pp) / d;
    let e = one_minus_one_plus_c_i0(c, i0);
    let half_minus_beta = (f / kappa) / b / d * (e + c * i0 * pm1 + f * lambda * sigma);
    let beta = 0.5 * lambda - half_minus_beta;

    // Eq. D3: h₁ = bλ/(2κ) + 2AĨ₁, hₙ = 2AĨₙ.
    let mut coeffs = Vec::with_capacity(i_n.len().max(2) - 1);
    coeffs.push(0.5 * lambda * (b / kappa) + 2.0 * a * i1);
    for &v in i_n.iter().skip(2) {
        coeffs.push(2.0 * a * v);
    }
    let h1 = coeffs[0];
    let h2 = 2.0 * a * i2;

    // Eq. D5.
    let load = 0.5 * lambda * h1;
    let friction_rho = half_minus_beta + 0.25 * lambda * h2 / h1;
    OneTermExact {
        term,
        lambda,
        beta,
        load,
        friction_rho,
        iterations: 0,
        coeffs,
    }
}

/// pM₁, pP and Σ of eq. D4 by adaptive quadrature in u (y = cosh u) on [0, U], where the factor
/// e^(−2p·sinh²(u/2)) has fallen below e^(−100).
fn front_edge_integrals(c: f64, p: f64, i_n: &[f64]) -> (f64, f64, f64) {
    let u_max = 2.0 * (50.0 / p).sqrt().asinh();
    // Initial panels: geometric from a quarter of the smallest feature scale (1/√c for the series,
    // 1/√p for the Gaussian-like weight, 1 for e^(−u)), so bisection starts near every scale.
    let s0 = 0.25 * 1.0f64.min(1.0 / c.sqrt()).min(1.0 / p.sqrt());
    let mut edges = vec![0.0];
    let mut s = s0;
    while s < u_max {
        edges.push(s);
        s *= 2.0;
    }
    edges.push(u_max);

    let weight = |u: f64| {
        let sh = (0.5 * u).sinh();
        (-2.0 * p * sh * sh).exp() * u.sinh()
    };
    let mut q = Integrator::new(20);
    let pm1 = p * q.integrate(|u| weight(u) * (-u).exp(), &edges, QUAD_TOL);
    let pp = p * q.integrate(|u| weight(u) * (-(-u).exp_m1()), &edges, QUAD_TOL);
    // Σₙ≥₁ Ĩₙ wⁿ by Horner in w = e^(−u) (all terms positive). Since Ĩₙ ≤ Ĩ₁, terms with n > 1 + 50/u
    // sum to less than e^(−50)/(1 − e^(−u)) ≲ 2e-22/u of the first one and are skipped: for large κλ most
    // nodes lie at u ≫ 1/√c, so this saves most of the O(N) work per node.
    let series = |u: f64| {
        let w = (-u).exp();
        let n_keep = if u > 0.0 {
            ((50.0 / u).ceil() + 2.0).min(i_n.len() as f64) as usize
        } else {
            i_n.len()
        };
        let mut acc = 0.0;
        for &v in i_n[..n_keep].iter().skip(1).rev() {
            acc = acc * w + v;
        }
        acc * w
    };
    let sigma = q.integrate(|u| weight(u) * series(u), &edges, QUAD_TOL);
    (pm1, pp, sigma)
}

/// The exact solution at given load N′: λ is found by Brent's method on ln λ in the bracket
/// [2√N′, 2√((1+f/b)N′)] (glassy and relaxed Hertz widths; N′ grows monotonically with λ), widened
/// if rounding puts the root just outside.
pub fn one_term_at_load(term: CreepTerm, load: f64) -> Result<OneTermExact, ContactError> {
    check_term(term)?;
    if !(load.is_finite() && load > 0.0) {
        return Err(ContactError::BadValue {
            field: "load N'".into(),
            expected: "finite and > 0",
            value: load,
        });
    }
    let glassy = 2.0 * load.sqrt();
    let relaxed = 2.0 * ((1.0 + term.f / term.b) * load).sqrt();
    let ln_target = load.ln();
    let eval = |t: f64| -> Result<(f64, OneTermExact), ContactError> {
        let sol = one_term_at_lambda(term, t.exp())?;
        Ok((sol.load.ln() - ln_target, sol))
    };
    let mut iterations = 0usize;
    let mut lo = glassy.ln() - 1e-9;
    let mut hi = relaxed.ln() + 1e-9;
    let (mut f_lo, mut s_lo) = eval(lo)?;
    let (mut f_hi, mut s_hi) = eval(hi)?;
    iterations += 2;
    let mut widen = 0;
    while f_lo > 0.0 || f_hi < 0.0 {
        widen += 1;
        if widen > 20 {
            return Err(ContactError::Unbracketed {
                load,
                lambda_lo: lo.exp(),
                load_lo: s_lo.load,
                lambda_hi: hi.exp(),
                load_hi: s_hi.load,
            });
        }
        if f_lo > 0.0 {
            lo -= 0.1 * widen as f64;
            (f_lo, s_lo) = eval(lo)?;
        }
        if f_hi < 0.0 {
            hi += 0.1 * widen as f64;
            (f_hi, s_hi) = eval(hi)?;
        }
        iterations += 1;
    }
    if f_lo == 0.0 {
        s_lo.iterations = iterations;
        return Ok(s_lo);
    }
    if f_hi == 0.0 {
        s_hi.iterations = iterations;
        return Ok(s_hi);
    }
    // Brent–Dekker: inverse quadratic / secant steps kept inside the bracket, bisection otherwise.
    let (mut a, mut fa) = (lo, f_lo);
    let (mut b, mut fb, mut sb) = (hi, f_hi, s_hi);
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..200 {
        if (fb > 0.0) == (fc > 0.0) {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        // ln λ to ~4 ulp: λ is then exact to a few 1e-16 relative.
        let tol = 4.0 * f64::EPSILON * b.abs().max(1.0);
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            break;
        }
        (d, e) = crate::special::brent::brent_step((a, b, c), (fa, fb, fc), m, tol, (d, e), true);
        a = b;
        fa = fb;
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        let (v, s) = eval(b)?;
        fb = v;
        sb = s;
        iterations += 1;
    }
    // `sb` is the solution at the last iterate b (the root estimate).
    sb.iterations = iterations;
    Ok(sb)
}

impl OneTermExact {
    /// Number of terms of the pressure series (eq. D3).
    pub fn series_len(&self) -> usize {
        self.coeffs.len()
    }

    /// Q′(ξ) for ξ in [0, λ] (eq. D3); 0 outside the contact.
    ///
    /// Σ hₙ sin(nθ) = sin θ · Σ hₙ Uₙ₋₁(cos θ) is summed by Clenshaw's recurrence in Reinsch's form
    /// (differences of consecutive terms), which keeps the rounding error O(N·ε) instead of O(N²·ε)
    /// near the edges; 1 − cos θ = 2(λ−ξ)/λ and 1 + cos θ = 2ξ/λ are formed without cancellation.
    pub fn pressure(&self, xi: f64) -> f64 {
        let lambda = self.lambda;
        if !(xi > 0.0 && xi < lambda) {
            return 0.0;
        }
        let back = lambda - xi;
        let sin_theta = 2.0 * (xi * back).sqrt() / lambda;
        let a = &self.coeffs;
        let n = a.len();
        let sum_u = if xi >= 0.5 * lambda {
            // x = cos θ ≥ 0: bₖ = aₖ + 2x bₖ₊₁ − bₖ₊₂ with dₖ = bₖ − bₖ₊₁,
            // dₖ = aₖ + 2(x−1)bₖ₊₁ + dₖ₊₁, bₖ = dₖ + bₖ₊₁.
            let two_xm1 = -4.0 * back / lambda;
            let (mut bk1, mut dk1) = (0.0, 0.0);
            for k in (0..n).rev() {
                let dk = a[k] + two_xm1 * bk1 + dk1;
                let bk = dk + bk1;
                bk1 = bk;
                dk1 = dk;
            }
            bk1
        } else {
            // x < 0: eₖ = bₖ + bₖ₊₁ = aₖ + 2(x+1)bₖ₊₁ − eₖ₊₁, bₖ = eₖ − bₖ₊₁.
            let two_xp1 = 4.0 * xi / lambda;
            let (mut bk1, mut ek1) = (0.0, 0.0);
            for k in (0..n).rev() {
                let ek = a[k] + two_xp1 * bk1 - ek1;
                let bk = ek - bk1;
                bk1 = bk;
                ek1 = ek;
            }
            bk1
        };
        sin_theta * sum_u / std::f64::consts::PI
    }

    /// The solution as a [`DimensionlessSolution`] with the pressure at `n_points` equally spaced
    /// points from ξ = 0 to ξ = λ (at least 2). `n` is 0: the series is exact to rounding.
    pub fn to_solution(&self, n_points: usize) -> DimensionlessSolution {
        let m = n_points.max(2);
        let xi: Vec<f64> = (0..m)
            .map(|i| self.lambda * i as f64 / (m - 1) as f64)
            .collect();
        let pressure = xi.iter().map(|&x| self.pressure(x)).collect();
        DimensionlessSolution {
            scheme: "exact".to_string(),
            lambda: self.lambda,
            beta: self.beta,
            load: self.load,
            friction_rho: self.friction_rho,
            xi,
            pressure,
            n: 0,
            iterations: self.iterations,
            error_estimate: None,
            auto: None,
            warnings: Vec::new(),
        }
    }
}
