//! The `auto` contact scheme at given contact length λ: an exact reduction of eq. 3.25 to N linear
//! equations (N = number of creep terms), solved with Chebyshev expansions.
//!
//! Input: [`Modes`] (creep terms and their roots κⱼ) and λ; output: [`LambdaSolution`] (β, N′,
//! ρ·F/N and the Chebyshev coefficients of the pressure).
//!
//! # Formulation
//! Map the contact to t ∈ [−1, 1]: ξ = L(1+t), L = λ/2, cᵢ = bᵢL, dᵢ = fᵢL, μⱼ = κⱼL. Write
//! Q′ = √(1−t²)Σₖ a_k U_k(t) and let H̃(t) = (1/π)∫√(1−s²)φ(s)/(t−s)ds = Σₙ Fₙ Tₙ(t) inside, with
//! a_k = F_{k+1} (docs/MATH.md §3.6, §7; the bounded-at-both-ends inverse needs F₀ = 0). The derivative of
//! eq. 3.25, π[H̃ + Σᵢ Ṽᵢ] = L(1+t) − β with Ṽᵢ(t) = dᵢ∫₀^∞e^{−cᵢσ}H̃(t+σ)dσ and Ṽᵢ′ = cᵢṼᵢ − dᵢH̃,
//! forces (module [`crate::contact::numerics::modes`]) H̃(t) = p₀ + p₁t + Σⱼ Aⱼe^{μⱼ(t−1)} on the contact, where
//! matching the terms linear in t, in e^{μⱼ(t−1)} and in e^{−cᵢ(1−t)} gives
//! - p₁ = L/(πS), S = 1 + Σfᵢ/bᵢ;  (L − β)/π = p₀S + p₁Σdᵢ/cᵢ²;  F₀ = p₀ + ΣⱼAⱼe^{−μⱼ}I₀(μⱼ) = 0;
//! - for every i: ∫₀^∞e^{−cᵢσ}H̃ₑₓₜ(1+σ)dσ = (p₀+p₁)/cᵢ + p₁/cᵢ² + Σⱼ Aⱼ/(cᵢ−μⱼ),
//!
//! where H̃ₑₓₜ(t) = Σₙ≥₁ Fₙwⁿ (w = t − √(t²−1)) is the transform beyond the front edge. With
//! p₀ = −ΣAⱼĨ₀(μⱼ) this is an N×N system for Aⱼ. Then N′ = πLF₁ (∫√(1−t²)U_k = (π/2)δ_k0) and
//! ρF/N = L − β + L·F₂/(2F₁) (the first moment, ∫√(1−t²)U_k·t = (π/4)δ_k1).
//!
//! # Why this discretisation (measured)
//! There is no truncation in the pressure representation: the front-edge layers are the exact
//! exponentials e^{μⱼ(t−1)} (width 1/μⱼ in t, i.e. 1/κⱼ = V times a relaxation time in ξ), expanded
//! in Chebyshev series to 1e−18 (≈ √(83μ) terms). The only approximation is the Laplace integral,
//! done by the trapezoid rule in v = ln σ, which converges like e^{−π²/h} for integrands analytic in
//! |Im v| < π/2 (Trefethen & Weideman, SIAM Rev. 2014): h = 0.25 gives ~1e−17. Measured against the
//! exact one-term solution the results agree to ~1e−13 already at the default step (see tests and the
//! DEVLOG of the bench), against first order in h for the thesis scheme.
//! Costs: O(N·Q·√μ_max + N²·Q) with Q ≈ 200 quadrature nodes, so fast modes (large μ) are lumped
//! into the glassy compliance by [`super::reduction`] before they get here. The exterior values (the
//! O(N·Q·√μ) part, half the time of a 30-term solve) are shared by the step-h solve and the step-2h
//! check of `solve_at_lambda_checked`, whose difference gives the quadrature error estimate.

use crate::contact::numerics::chebyshev::{exp_coefficients, exterior_values, theta_w};
use crate::contact::numerics::modes::Modes;
use crate::special::chebyshev::sine_series_grid;
use crate::special::equilibrated::solve_equilibrated;
use nalgebra::{DMatrix, DVector};
use std::f64::consts::PI;

/// Numerical settings of one solve at given λ.
#[derive(Debug, Clone, Copy)]
pub struct QuadratureSettings {
    /// Trapezoid step in v = ln σ (default 0.25: error ~ e^{−π²/h} ≈ 1e−17).
    pub step: f64,
}

impl Default for QuadratureSettings {
    fn default() -> Self {
        QuadratureSettings { step: 0.25 }
    }
}

/// Solution at given λ of the (possibly reduced) dimensionless problem.
#[derive(Debug, Clone, PartialEq)]
pub struct LambdaSolution {
    /// Contact length λ.
    pub lambda: f64,
    /// Offset β of the lowest point from the rear edge.
    pub beta: f64,
    /// Load N′ = 2∫Q′dξ.
    pub load: f64,
    /// ρ·F/N.
    pub friction_rho: f64,
    /// Chebyshev coefficients Fₙ of H̃ (F₀ = 0); Q′(t) = Σₙ≥₁ Fₙ sin(nθ), t = cos θ.
    pub coefficients: Vec<f64>,
    /// Largest μⱼ = κⱼλ/2 (sets the thinnest layer, width 1/μ in t).
    pub mu_max: f64,
}

impl LambdaSolution {
    /// Pressure on the FFT grid θ_m = πm/M (M ≥ number of coefficients, so the spacing near the
    /// front edge, 1 − t ≈ (π/M)²/2 < 1/μ_max, resolves the thinnest layer): (ξ, Q′) for all m,
    /// and the subset returned as the profile: about `n_uniform` points uniform in θ plus every grid
    /// point within 30 layer widths of the front edge (at most ~40 of them, log-spaced).
    pub fn profile(&self, n_uniform: usize) -> (Vec<f64>, Vec<f64>, f64) {
        let l = 0.5 * self.lambda;
        let grid = sine_series_grid(&self.coefficients);
        let m = grid.len() - 1;
        let min_ratio = {
            let pmax = grid.iter().map(|g| g.1).fold(0.0, f64::max);
            let pmin = grid.iter().map(|g| g.1).fold(f64::INFINITY, f64::min);
            if pmax > 0.0 {
                pmin / pmax
            } else {
                0.0
            }
        };
        let stride = (m / n_uniform.max(1)).max(1);
        let mut idx: Vec<usize> = (0..=m).step_by(stride).collect();
        idx.push(m);
        if self.mu_max > 1.0 {
            // layer: 1 − t = s/μ_max, s ∈ [1e−3, 30] → θ ≈ √(2s/μ)
            for k in 0..=40 {
                let s = 1e-3 * 10f64.powf(k as f64 * 4.5 / 40.0);
                let th = (2.0 * s / self.mu_max).sqrt().min(PI);
                idx.push(((th / PI) * m as f64).round() as usize);
            }
        }
        idx.sort_unstable_by(|a, b| b.cmp(a)); // θ descending = ξ ascending
        idx.dedup();
        let xi = idx.iter().map(|&k| l * (1.0 + grid[k].0.cos())).collect();
        let p = idx.iter().map(|&k| grid[k].1).collect();
        (xi, p, min_ratio)
    }
}

/// Solve at given λ > 0 (exact reduction; see module doc).
pub fn solve_at_lambda(modes: &Modes, lambda: f64, q: QuadratureSettings) -> LambdaSolution {
    solve_impl(modes, lambda, q, false).0
}

/// Solve at given λ > 0 and, from the same exterior values, with every second quadrature node
/// (step 2h): (solution, coarse solution). The coarse one costs only its N×N assembly.
pub(crate) fn solve_at_lambda_checked(
    modes: &Modes,
    lambda: f64,
    q: QuadratureSettings,
) -> (LambdaSolution, LambdaSolution) {
    let (fine, coarse) = solve_impl(modes, lambda, q, true);
    let coarse = coarse.unwrap_or_else(|| fine.clone());
    (fine, coarse)
}

fn solve_impl(
    modes: &Modes,
    lambda: f64,
    q: QuadratureSettings,
    check: bool,
) -> (LambdaSolution, Option<LambdaSolution>) {
    let l = 0.5 * lambda;
    let n = modes.len();
    let s_ratio = modes.compliance_ratio();
    let p1 = l / (PI * s_ratio);
    if n == 0 {
        let s = finish(lambda, l, l, 0.0, vec![0.0, p1, 0.0]);
        return (s.clone(), check.then_some(s));
    }
    let c: Vec<f64> = modes.b.iter().map(|b| b * l).collect();
    let mu: Vec<f64> = (0..n).map(|j| modes.kappa(j) * l).collect();
    // Unknowns Âⱼ = Aⱼμⱼ: the components Aⱼ(e^{μⱼ(t−1)} − Ĩ₀(μⱼ)) are O(Âⱼ) for every μⱼ, so
    // slow modes (μⱼ ≪ 1) do not produce huge Aⱼ and cancelling p₀ (see `beta` below).
    let coef: Vec<Vec<f64>> = mu.iter().map(|&m| exp_coefficients(m)).collect();
    let hat: Vec<Vec<f64>> = coef
        .iter()
        .zip(&mu)
        .map(|(cf, &m)| {
            let mut h: Vec<f64> = cf.iter().map(|v| v / m).collect();
            h[0] = 0.0;
            h
        })
        .collect();
    // (1 − Ĩ₀(μ))/μ = Σₙ≥₁ 2Ĩₙ(μ)/μ exactly (the Miller normalisation), no cancellation
    let om: Vec<f64> = hat.iter().map(|h| h.iter().skip(1).sum::<f64>()).collect();
    let i0: Vec<f64> = coef.iter().map(|cf| cf[0]).collect();

    // Trapezoid nodes in v = ln σ covering σ ∈ [σ_min, σ_max]:
    // below σ_min the integrand ≤ σ_min (|H̃ₑₓₜ| ≤ 1 per unit coefficient sum), above σ_max
    // e^{−c_min σ} < e^{−60}. An odd node count, so that every second node spans the same range.
    let c_min = c.iter().cloned().fold(f64::INFINITY, f64::min);
    let c_max = c.iter().cloned().fold(0.0, f64::max);
    let v_min = (-42.0_f64).min((1e-20 / c_max.max(1.0)).ln());
    let v_max = (60.0 / c_min).ln();
    let n_nodes = (((v_max - v_min) / q.step).ceil() as usize / 2) * 2 + 1;
    let h = (v_max - v_min) / (n_nodes - 1) as f64;
    let sig: Vec<f64> = (0..n_nodes).map(|k| (v_min + k as f64 * h).exp()).collect();
    let (th, w): (Vec<f64>, Vec<f64>) = sig.iter().map(|&s| theta_w(s)).unzip();

    // Exterior values of each scaled exponential component at the nodes (row j), and the
    // trapezoid weights σₖe^{−cᵢσₖ} (row i; the ends are negligible, e^{−60} resp. ≤ 1e−20).
    let mut x = DMatrix::<f64>::zeros(n, n_nodes);
    let mut buf = vec![0.0; n_nodes];
    for j in 0..n {
        exterior_values(&hat[j], &th, &w, &mut buf);
        for k in 0..n_nodes {
            x[(j, k)] = buf[k];
        }
    }
    let mut wq = DMatrix::<f64>::zeros(n, n_nodes);
    for i in 0..n {
        for k in 0..n_nodes {
            let e = c[i] * sig[k];
            // e^{−745} underflows to 0 anyway; skip the call
            wq[(i, k)] = if e < 745.0 { sig[k] * (-e).exp() } else { 0.0 };
        }
    }
    let ctx = Assembly {
        modes,
        l,
        p1,
        c: &c,
        om: &om,
        i0: &i0,
        hat: &hat,
        mu_max: mu.iter().cloned().fold(0.0, f64::max),
        lambda,
    };
    let fine = ctx.solve(&wq, &x, &w, h);
    let coarse = check.then(|| {
        let keep: Vec<usize> = (0..n_nodes).step_by(2).collect();
        let wq2 = wq.select_columns(&keep);
        let x2 = x.select_columns(&keep);
        let w2: Vec<f64> = keep.iter().map(|&k| w[k]).collect();
        ctx.solve(&wq2, &x2, &w2, 2.0 * h)
    });
    (fine, coarse)
}

/// The λ-dependent pieces of one solve, shared by the fine and the coarse quadrature.
struct Assembly<'a> {
    modes: &'a Modes,
    l: f64,
    p1: f64,
    c: &'a [f64],
    om: &'a [f64],
    i0: &'a [f64],
    hat: &'a [Vec<f64>],
    mu_max: f64,
    lambda: f64,
}

impl Assembly<'_> {
    /// Assemble and solve the N×N system with the quadrature (weights `wq`·h, exterior values `x`,
    /// w = e^{−θ} at the nodes).
    fn solve(&self, wq: &DMatrix<f64>, x: &DMatrix<f64>, w: &[f64], h: f64) -> LambdaSolution {
        let (modes, l, p1, c) = (self.modes, self.l, self.p1, self.c);
        let n = c.len();
        // Ĝᵢⱼ = ∫e^{−cᵢσ}H̃ₑₓₜ[ĵ](1+σ)dσ = h·Σₖ wqᵢₖ xⱼₖ, M₁ᵢ = ∫e^{−cᵢσ}w dσ
        let gmat = (wq * x.transpose()) * h;
        let m1: Vec<f64> = (0..n)
            .map(|i| h * wq.row(i).iter().zip(w).map(|(a, b)| a * b).sum::<f64>())
            .collect();
        // system B̂Â = r (module doc, divided by μⱼ)
        let mut bmat = DMatrix::<f64>::zeros(n, n);
        let mut r = DVector::<f64>::zeros(n);
        for i in 0..n {
            for j in 0..n {
                let cm = l * modes.b_minus_kappa(i, j); // cᵢ − μⱼ
                                                        // Bᵢⱼ/μⱼ = Ĝ + Ĩ₀/(cμ) − 1/((c−μ)μ) = Ĝ − [c(1−Ĩ₀)/μ + Ĩ₀]/(c(c−μ))
                bmat[(i, j)] = gmat[(i, j)] - (c[i] * self.om[j] + self.i0[j]) / (c[i] * cm);
            }
            r[i] = p1 * ((1.0 / c[i] + 1.0 / (c[i] * c[i])) - m1[i]);
        }
        // row and column equilibration (columns of fast modes scale like 1/μⱼ)
        let a = solve_equilibrated(bmat, r);

        let n_coef = self.hat.iter().map(|v| v.len()).max().unwrap_or(1).max(3);
        let mut fcoef = vec![0.0; n_coef];
        for j in 0..n {
            for (k, v) in self.hat[j].iter().enumerate().skip(1) {
                fcoef[k] += a[j] * v;
            }
        }
        fcoef[1] += p1;
        // β from the equation at the front edge t = 1 (no cancellation, unlike the constant-term
        // identity (L−β)/π = p₀S + p₁Σdᵢ/cᵢ², whose two terms grow like 1/μ for slow modes):
        // π[H̃(1) + Σᵢ Ṽᵢ(1)] = 2L − β, H̃(1) = p₁ + ΣÂⱼ(1−Ĩ₀)/μⱼ, Ṽᵢ(1) = dᵢ(ΣⱼĜᵢⱼÂⱼ + p₁M₁ᵢ).
        let h1 = p1 + (0..n).map(|j| a[j] * self.om[j]).sum::<f64>();
        let v1: f64 = (0..n)
            .map(|i| {
                let d = modes.f[i] * l;
                d * ((0..n).map(|j| gmat[(i, j)] * a[j]).sum::<f64>() + p1 * m1[i])
            })
            .sum();
        let beta = 2.0 * l - PI * (h1 + v1);
        finish(self.lambda, l, beta, self.mu_max, fcoef)
    }
}

fn finish(lambda: f64, l: f64, beta: f64, mu_max: f64, fcoef: Vec<f64>) -> LambdaSolution {
    let f1 = fcoef[1];
    let f2 = fcoef[2];
    LambdaSolution {
        lambda,
        beta,
        load: PI * l * f1,
        friction_rho: l - beta + l * f2 / (2.0 * f1),
        coefficients: fcoef,
        mu_max,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::problem::CreepTerm;

    #[test]
    fn hertz_limit() {
        let m = Modes::new(&[]);
        let s = solve_at_lambda(&m, 3.0, QuadratureSettings::default());
        assert!((s.load - 2.25).abs() < 1e-14);
        assert!((s.beta - 1.5).abs() < 1e-15);
        assert!(s.friction_rho.abs() < 1e-15);
    }

    /// Composite Simpson on [a, b] with m (even) panels.
    fn simpson(fun: impl Fn(f64) -> f64, a: f64, b: f64, m: usize) -> f64 {
        let h = (b - a) / m as f64;
        let mut s = fun(a) + fun(b);
        for k in 1..m {
            s += fun(a + k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 };
        }
        s * h / 3.0
    }

    /// Residual of the differentiated eq. 3.25, π[H̃ + ΣṼᵢ](t) − (L(1+t) − β), with Ṽᵢ computed by
    /// direct quadrature of its definition (interior by Simpson in u, exterior by Simpson in
    /// s with σ = (s/(1−s))², which removes the √σ edge behaviour): independent of the reduction.
    fn residual(m: &Modes, sol: &LambdaSolution, t: f64) -> f64 {
        let l = 0.5 * sol.lambda;
        let a = &sol.coefficients;
        let h_in = |u: f64| -> f64 {
            let th = u.clamp(-1.0, 1.0).acos();
            a.iter()
                .enumerate()
                .map(|(n, v)| v * (n as f64 * th).cos())
                .sum()
        };
        let h_ext = |sig: f64| -> f64 {
            let tt: f64 = 1.0 + sig;
            let w = (-(sig * (2.0 + sig)).sqrt().asinh()).exp();
            let _ = tt;
            let mut p = 1.0;
            let mut s = 0.0;
            for v in a.iter().skip(1) {
                p *= w;
                s += v * p;
            }
            s
        };
        let mut total = h_in(t);
        for (f, b) in m.f.iter().zip(&m.b) {
            let (c, d) = (b * l, f * l);
            let inner = simpson(|u| (-c * (u - t)).exp() * h_in(u), t, 1.0, 4000);
            let outer = simpson(
                |s| {
                    if s >= 1.0 {
                        return 0.0;
                    }
                    let u = s / (1.0 - s);
                    let sig = u * u;
                    let jac = 2.0 * u / ((1.0 - s) * (1.0 - s));
                    (-c * sig).exp() * h_ext(sig) * jac
                },
                0.0,
                1.0,
                20000,
            );
            total += d * (inner + (-c * (1.0 - t)).exp() * outer);
        }
        PI * total - (l * (1.0 + t) - sol.beta)
    }

    #[test]
    fn satisfies_the_differentiated_integral_equation() {
        for terms in [
            vec![CreepTerm { f: 10.0, b: 1.0 }],
            vec![CreepTerm { f: 3.0, b: 0.5 }, CreepTerm { f: 20.0, b: 4.0 }],
        ] {
            let m = Modes::new(&terms);
            let sol = solve_at_lambda(&m, 1.0, QuadratureSettings::default());
            assert!(sol.coefficients[0].abs() < 1e-15);
            for &t in &[-0.9, -0.3, 0.2, 0.7, 0.95] {
                let r = residual(&m, &sol, t);
                eprintln!("t {t}: residual {r:e}");
                // Simpson with 4000/20000 panels on these smooth integrands: ~1e−11
                assert!(r.abs() < 1e-9, "t {t}: residual {r}");
            }
        }
    }

    #[test]
    fn table1_one_parameter_case() {
        let m = Modes::new(&[CreepTerm { f: 10.0, b: 1.0 }]);
        let s = solve_at_lambda(&m, 1.0, QuadratureSettings::default());
        // Goodier & Loutzenheiser (thesis Table 1): β/λ = 0.1952, ρF/N = 0.4308, from an
        // approximate method; the issue asks for the exact solution within 0.5 % of both.
        assert!((s.beta / 0.1952 - 1.0).abs() < 5e-3, "beta {}", s.beta);
        assert!(
            (s.friction_rho / 0.4308 - 1.0).abs() < 5e-3,
            "rhoF/N {}",
            s.friction_rho
        );
    }
}
