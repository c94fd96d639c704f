//! An independent elastic check of the bonded layer (issue 14, item 3, 5th bullet): nothing here uses
//! the layer's hat-function kernel or its collocation.
//!
//! 1. **Compliance.** The plane-strain boundary-value problem of the module doc of
//!    [`super::compliance`] (Navier's equations for u_x = U(z) sin kx, u_z = W(z) cos kx; surface
//!    z = 0 free of shear and loaded by −p cos kx; rigid base z = h) is solved here numerically by a
//!    Chebyshev collocation in z (Trefethen, *Spectral Methods in MATLAB*, SIAM 2000, ch. 6 and 13)
//!    and its surface deflection compared with the closed form W(0) = ((1−ν)/μ)(p/|k|)F(|k|h).
//! 2. **Contact.** The elastic (f = 0) contact of a cylinder on the layer at contact length λ = 2a is
//!    solved by a Chebyshev–Bessel method written for this test: Q′(s) = √(1−u²)Σcₙ Uₙ(u), s = a·u
//!    from the contact centre (even n: the elastic contact is symmetric, β = λ/2). The derivative of
//!    eq. 3.25, ρv′(ξ) = β − ξ, with ρv = ∫Q′G_L, Ĝ_L = π(1 − R(|k|h))/|k| (module doc of
//!    [`super::kernel`]), becomes at collocation points uᵢ
//!
//!    ```text
//!      Σₙ cₙ [Tₙ₊₁(uᵢ) − (−1)^{n/2}(n+1)·Iₙ(uᵢ)] = a·uᵢ/π,   Iₙ(u) = ∫₀^∞ R(κh/a) Jₙ₊₁(κ) sin(κu)/κ dκ,
//!    ```
//!
//!    using ∫√(1−s²)Uₙ(s)/(y−s)ds = πTₙ₊₁(y) and the transform ∫√(1−u²)Uₙ(u)e^{−iκu}du =
//!    π(n+1)(−i)ⁿJₙ₊₁(κ)/κ (Gradshteyn & Ryzhik 7.355; A&S 9.1.20), and N′ = 2∫Q′ = πa·c₀. Checks of
//!    the formula: R = 0 gives Hertz (c₀ = a/π, N′ = λ²/4); R = 1 (rigid) gives I₀(u) = u, no
//!    deflection. Jₙ by Miller's backward recurrence normalised by J₀ + 2ΣJ₂ₖ = 1 (A&S 9.1.46, 9.12).
//!    The layer's hat-function collocation must converge to this answer as n doubles.

use super::compliance::{layer_defect, layer_factor};
use super::{collocation, LayerKernel};
use crate::special::gauss_legendre::gauss_legendre;
use nalgebra::{DMatrix, DVector};
use std::f64::consts::PI;

/// Chebyshev points xⱼ = cos(πj/N) and the differentiation matrix (Trefethen 2000, `cheb`).
fn cheb(n: usize) -> (Vec<f64>, DMatrix<f64>) {
    let x: Vec<f64> = (0..=n).map(|j| (PI * j as f64 / n as f64).cos()).collect();
    let c = |j: usize| if j == 0 || j == n { 2.0 } else { 1.0 };
    let mut d = DMatrix::<f64>::zeros(n + 1, n + 1);
    for i in 0..=n {
        for j in 0..=n {
            if i != j {
                let s = if (i + j) % 2 == 0 { 1.0 } else { -1.0 };
                d[(i, j)] = c(i) / c(j) * s / (x[i] - x[j]);
            }
        }
    }
    for i in 0..=n {
        let s: f64 = (0..=n).filter(|&j| j != i).map(|j| d[(i, j)]).sum();
        d[(i, i)] = -s;
    }
    (x, d)
}

/// F(kh) from the boundary-value problem (μ = 1, p = 1, h = 1, k = t), ν < ½.
fn compliance_bvp(t: f64, nu: f64, n: usize) -> f64 {
    let (_, dx) = cheb(n);
    // z = (1 − x)/2 ∈ [0, 1]: z = 0 (surface) at j = 0, z = 1 (base) at j = n; d/dz = −2 d/dx
    let d1 = dx * -2.0;
    let d2 = &d1 * &d1;
    let lam = 2.0 * nu / (1.0 - 2.0 * nu); // λ_L/μ
    let k = t;
    let m = n + 1;
    let mut a = DMatrix::<f64>::zeros(2 * m, 2 * m);
    let mut rhs = DVector::<f64>::zeros(2 * m);
    // unknowns: U at 0..m, W at m..2m
    for i in 1..n {
        for j in 0..m {
            // μU″ − (λ+2μ)k²U − (λ+μ)kW′ = 0
            a[(i, j)] = d2[(i, j)];
            a[(i, m + j)] = -(lam + 1.0) * k * d1[(i, j)];
            // (λ+2μ)W″ − μk²W + (λ+μ)kU′ = 0
            a[(m + i, m + j)] = (lam + 2.0) * d2[(i, j)];
            a[(m + i, j)] = (lam + 1.0) * k * d1[(i, j)];
        }
        a[(i, i)] -= (lam + 2.0) * k * k;
        a[(m + i, m + i)] -= k * k;
    }
    // surface: σ_xz = μ(U′ − kW) = 0; σ_zz = λ(kU + W′) + 2μW′ = −p
    for j in 0..m {
        a[(0, j)] = d1[(0, j)];
        a[(m, m + j)] = (lam + 2.0) * d1[(0, j)];
    }
    a[(0, m)] -= k;
    a[(m, 0)] += lam * k;
    rhs[m] = -1.0;
    // base: U = W = 0
    a[(n, n)] = 1.0;
    a[(m + n, m + n)] = 1.0;
    let sol = a.lu().solve(&rhs).expect("BVP solvable");
    // W(0) = ((1−ν)/μ)(p/k)F
    sol[m] * k / (1.0 - nu)
}

#[test]
fn compliance_closed_form_matches_the_boundary_value_problem() {
    // Chebyshev collocation: 32 points resolve e^{±kz} for kh ≤ 8 far below rounding (the Chebyshev
    // coefficients of e^{4x} fall below 1e−20 by degree 30); the rounding error of the second-
    // derivative matrix grows like N⁴ε ≈ 1e−10 (Trefethen 2000, ch. 6), so 32 and 40 points agree to
    // ~1e−10 and the closed form must agree with both to 1e−9.
    let mut worst: f64 = 0.0;
    for nu in [0.0, 0.25, 0.45, 0.49] {
        for t in [0.02, 0.1, 0.5, 1.0, 2.0, 4.0, 8.0] {
            let bvp = compliance_bvp(t, nu, 32);
            let finer = compliance_bvp(t, nu, 40);
            let closed = layer_factor(t, nu);
            assert!(
                (bvp - finer).abs() < 1e-9 * bvp.abs(),
                "ν {nu} t {t}: {bvp} vs {finer}"
            );
            assert!(
                (bvp - closed).abs() < 1e-9 * closed,
                "ν {nu} t {t}: BVP {bvp:.15} vs closed form {closed:.15}"
            );
            worst = worst.max((bvp - closed).abs() / closed);
        }
    }
    eprintln!("closed form vs boundary-value problem: largest relative difference {worst:.1e}");
}

/// J₀…J_nmax at x > 0 (Miller's backward recurrence, normalised by J₀ + 2ΣJ₂ₖ = 1).
fn bessel_j(x: f64, nmax: usize) -> Vec<f64> {
    let top = nmax as f64 + x;
    let start = 2 * ((top + 20.0 + (40.0 * top).sqrt()) as usize / 2 + 1);
    let mut j = vec![0.0; start + 2];
    j[start] = 1e-30;
    for k in (1..=start).rev() {
        j[k - 1] = 2.0 * k as f64 / x * j[k] - j[k + 1];
        if j[k - 1].abs() > 1e250 {
            for v in j[k - 1..].iter_mut() {
                *v *= 1e-250;
            }
        }
    }
    let norm = j[0] + 2.0 * j.iter().skip(2).step_by(2).sum::<f64>();
    j.truncate(nmax + 1);
    j.iter().map(|v| v / norm).collect()
}

#[test]
fn bessel_values() {
    // A&S Table 9.1 / 9.2 values (10 digits).
    let j = bessel_j(1.0, 3);
    assert!((j[0] - 0.765_197_686_6).abs() < 1e-10 && (j[1] - 0.440_050_585_7).abs() < 1e-10);
    let j = bessel_j(10.0, 2);
    assert!((j[0] + 0.245_935_764_5).abs() < 1e-10 && (j[1] - 0.043_472_746_17).abs() < 1e-10);
    let j = bessel_j(0.01, 30);
    assert!((j[1] - 0.004_999_937_5).abs() < 1e-12 && j[30] > 0.0 && j[30] < 1e-80);
}

/// (N′, max Q′) of the elastic contact at λ on a layer of thickness h (independent method), with `m`
/// even Chebyshev terms.
pub(crate) fn elastic_contact(lambda: f64, h: f64, nu: f64, m: usize) -> (f64, f64) {
    let a = 0.5 * lambda;
    let nmax = 2 * m; // J index n + 1 ≤ 2m − 1
    let us: Vec<f64> = (0..m)
        .map(|i| (PI * (i as f64 + 0.5) / (2 * m) as f64).cos())
        .collect();
    // I_n(u) on Gauss–Legendre panels of width ½ in κ up to R < 1e−20 (t = κh/a ≤ 27)
    let (gx, gw) = gauss_legendre(16);
    let k_hi = 27.0 * a / h;
    let panels = (k_hi / 0.5).ceil() as usize;
    let mut integ = DMatrix::<f64>::zeros(m, m); // (i, n/2)
    for p in 0..panels {
        let (lo, hi) = (p as f64 * 0.5, (p as f64 + 1.0) * 0.5);
        for (x, w) in gx.iter().zip(&gw) {
            let kappa = 0.5 * (lo + hi) + 0.5 * (hi - lo) * x;
            let weight = 0.5 * (hi - lo) * w * layer_defect(kappa * h / a, nu) / kappa;
            let j = bessel_j(kappa, nmax);
            for (i, &u) in us.iter().enumerate() {
                let s = (kappa * u).sin() * weight;
                for c in 0..m {
                    integ[(i, c)] += j[2 * c + 1] * s;
                }
            }
        }
    }
    let mut mat = DMatrix::<f64>::zeros(m, m);
    let mut rhs = DVector::<f64>::zeros(m);
    for (i, &u) in us.iter().enumerate() {
        let th = u.acos();
        for c in 0..m {
            let n = 2 * c;
            let sign = if c % 2 == 0 { 1.0 } else { -1.0 };
            mat[(i, c)] = ((n + 1) as f64 * th).cos() - sign * (n + 1) as f64 * integ[(i, c)];
        }
        rhs[i] = a * u / PI;
    }
    let c = mat.lu().solve(&rhs).expect("solvable");
    let load = PI * a * c[0];
    // max of Q′ = Σ cₙ sin((n+1)θ) over θ (u = cos θ)
    let mut qmax: f64 = 0.0;
    for k in 0..=4000 {
        let th = PI * k as f64 / 4000.0;
        let q: f64 = (0..m).map(|i| c[i] * ((2 * i + 1) as f64 * th).sin()).sum();
        qmax = qmax.max(q);
    }
    (load, qmax)
}

#[test]
fn elastic_layer_contact_against_an_independent_chebyshev_bessel_solution() {
    // Half-space check of the independent method first: N′ = λ²/4, max Q′ = λ/(2π) (Hertz).
    let (l, q) = elastic_contact(1.0, 1e6, 0.5, 8);
    assert!(
        (l - 0.25).abs() < 1e-12 && (q - 0.5 / PI).abs() < 1e-9,
        "{l} {q}"
    );
    eprintln!("| h/λ | ν | N′ independent | N′ hat n=256, 512 | Richardson | max Q′ indep. | max Q′ hat n=512 |");
    for nu in [0.5, 0.3] {
        for h in [0.1, 0.3, 1.0, 3.0] {
            let (load, qmax) = elastic_contact(1.0, h, nu, 32);
            let (load2, qmax2) = elastic_contact(1.0, h, nu, 40);
            // spectral convergence of the independent method: 32 vs 40 terms
            assert!((load - load2).abs() < 1e-9 * load, "h {h}: {load} {load2}");
            assert!((qmax - qmax2).abs() < 1e-6 * qmax, "h {h}: {qmax} {qmax2}");
            let k = LayerKernel::new(&[], h, nu).unwrap();
            let c = collocation::solve_at_lambda(&k, 1.0, 256).unwrap();
            let f = collocation::solve_at_lambda(&k, 1.0, 512).unwrap();
            let rich = 2.0 * f.load - c.load;
            let q_hat = f.pressure.iter().cloned().fold(0.0, f64::max);
            eprintln!(
                "| {h} | {nu} | {load:.9} | {:.9}, {:.9} | {rich:.9} | {qmax:.6} | {q_hat:.6} |",
                c.load, f.load
            );
            // the hat scheme converges to the independent answer: its error at n = 512 is within
            // twice its own n/2 difference (first order), and Richardson's is a fifth of that
            let diff = (f.load - c.load).abs();
            assert!((f.load - load).abs() <= 2.0 * diff + 1e-12, "h {h} ν {nu}");
            assert!(
                (rich - load).abs() <= 0.2 * diff + 1e-9 * load,
                "h {h} ν {nu}"
            );
            // β = λ/2 (symmetric elastic contact) and the peak pressure: the nodal maximum lies
            // within O(Δ²) of the continuous one plus the scheme's first-order error (≤ 1e−3 here)
            assert!((f.beta - 0.5).abs() < 1e-9, "β {}", f.beta);
            assert!(
                (q_hat - qmax).abs() < 2e-3 * qmax,
                "h {h} ν {nu}: {q_hat} vs {qmax}"
            );
            // the cover stiffens the contact: more load than Hertz at the same λ
            assert!(load > 0.25);
        }
    }
}
