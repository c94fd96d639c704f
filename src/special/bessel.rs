//! Exponentially scaled modified Bessel functions of the first kind, Ĩₙ(μ) = e^(−μ)·Iₙ(μ), for all
//! orders n = 0…N at one argument μ ≥ 0 (input: μ and a relative cut; output: a `Vec<f64>`), and
//! E(c) = 1 − (1 + c)·Ĩ₀(c) without cancellation.
//!
//! Used by the contact stage wherever e^{μ(t−1)} is expanded in Chebyshev polynomials: the `auto`
//! scheme (one series per creep mode) and the exact one-term solution (`contact::exact`). By
//! A&S 9.6.34, e^{μt} = I₀(μ) + 2Σₙ Iₙ(μ)Tₙ(t), so e^{μ(t−1)} has the coefficients Ĩ₀(μ), 2Ĩₙ(μ). The
//! scaling keeps every value in [0, 1] for any μ (Iₙ itself overflows past μ ≈ 713).
//!
//! Method: Miller's backward recurrence I_{n−1} = I_{n+1} + (2n/μ)Iₙ (A&S 9.6.26), started far
//! enough above the last order kept that the start error has died out, rescaled when the values grow
//! large, and normalised with Ĩ₀ + 2Σₙ≥₁ Ĩₙ = 1 (A&S 9.6.36 at t = 1, times e^{−μ}). Iₙ is the
//! minimal solution of the recurrence as n grows, so the backward direction is stable; every term of
//! the normalisation sum is positive, so it loses nothing to cancellation.
//!
//! Trim: the series is cut where Ĩₙ falls below `rel_cut` times the largest order n ≥ 1, *not*
//! relative to the constant term. Both users remove the constant and divide the rest by μ (the auto
//! scheme's Âⱼ = Aⱼμⱼ; the exact solution's hₙ = 2AĨₙ), so for μ ≪ 1, where Ĩ₀ ≈ 1 ≫ Ĩ₁ ≈ μ/2, a cut
//! relative to order 0 left an error of rel_cut/μ in the divided series: at μ ≈ 4e−7 dropping the
//! n = 2 term at 1e−18 of order 0 moved β by 4e−11 relative and ρF/N by 5.6e−7 of a slow-end
//! friction (tests/contact_props.rs, case 28). This used to be written twice, with the two trims.

/// Ĩₙ(μ) = e^{−μ}Iₙ(μ) for n = 0, 1, …, N, trimmed where the orders fall below `rel_cut` times the
/// largest order n ≥ 1 (at least orders 0 and 1 are returned). μ ≤ 0 or not finite gives `[1]`.
/// `rel_cut` should lie in [1e−40, 1e−2] (the orders computed are sized for it).
pub fn scaled_bessel_i(mu: f64, rel_cut: f64) -> Vec<f64> {
    if mu <= 0.0 || !mu.is_finite() {
        return vec![1.0];
    }
    if mu < 1e-50 {
        // Power series (A&S 9.6.10): Ĩ₀ = e^{−μ}(1 + μ²/4 + …), Ĩ₁ = e^{−μ}(μ/2)(1 + μ²/8 + …),
        // Ĩ₂ = e^{−μ}(μ²/8)(1 + …) are exact to double precision here; the recurrence would overflow
        // (one step multiplies by 2n/μ > 1e50). Order 2 is kept although Ĩ₂/Ĩ₁ = μ/4 lies below any
        // cut: the exact one-term solution divides it by μ² (docs/MATH.md §10), and without it the
        // friction's constant loses a quarter (0.55 % low at c ≲ 4e-19).
        let e = (-mu).exp();
        return vec![e, 0.5 * mu * e, 0.125 * mu * mu * e];
    }
    // Terms behave like exp(−n²/(2μ)) for μ ≫ 1 and like (μ/2)ⁿ/n! for μ ≪ 1; for the cut 1e−18,
    // 2·ln(1e18) ≈ 83.
    let range = (-2.0 * rel_cut.ln()).ceil();
    let n_keep = ((range * mu.max(1.0)).sqrt() + 12.0).ceil() as usize;
    // Miller: start well beyond n_keep so the start error has decayed by far more than the cut.
    let n_start = n_keep + 30 + ((mu.max(1.0)).sqrt() * 3.0) as usize;
    let mut out = vec![0.0; n_keep + 1];
    let (mut y_next, mut y) = (0.0_f64, 1e-280_f64); // y_{n+1}, y_n
    let mut sum = 0.0; // y_0 + 2Σ y_n over n ≥ 1 (accumulated from the top)
    let mut n = n_start;
    loop {
        if n <= n_keep {
            out[n] = y;
        }
        sum += if n == 0 { y } else { 2.0 * y };
        if n == 0 {
            break;
        }
        // y_{n−1} = y_{n+1} + (2n/μ) y_n
        let y_prev = y_next + (2.0 * n as f64 / mu) * y;
        y_next = y;
        y = y_prev;
        n -= 1;
        if y.abs() > 1e250 {
            let s = 1e-250;
            y *= s;
            y_next *= s;
            sum *= s;
            for v in out.iter_mut().skip(n) {
                *v *= s;
            }
        }
    }
    for v in out.iter_mut() {
        *v /= sum;
    }
    let peak = out.iter().skip(1).cloned().fold(0.0, f64::max);
    // Orders 0–2 are always kept (see the power-series branch above).
    while out.len() > 3 && *out.last().unwrap() < rel_cut * peak {
        out.pop();
    }
    out
}

/// E(c) = 1 − (1 + c)·Ĩ₀(c), without cancellation for small c (where E ≈ c²/4); `i0_scaled` = Ĩ₀(c)
/// (used for c > 1/2 only).
///
/// For c ≤ 1/2 the product of the series e^(−c)(1 + c) = Σₘ (−1)ᵐ(1 − m)cᵐ/m! and
/// I₀(c) = Σⱼ (c/2)^(2j)/(j!)² is formed term by term; its constant term 1 cancels analytically and the
/// c¹ term vanishes, so E = −Σ_{k≥2} pₖ cᵏ with pₖ the product coefficients. Rounding: the series errs by
/// about ε·Σ|pₖ|cᵏ/|E| and the direct form by about ε/|E|; both are ≈ 50ε at c = 1/2, where we switch.
/// E changes sign near c ≈ 3.5 (Ĩ₀ ~ (2πc)^(−1/2)); there its absolute error ~ε is what matters.
pub fn one_minus_one_plus_c_i0(c: f64, i0_scaled: f64) -> f64 {
    if c > 0.5 {
        return 1.0 - (1.0 + c) * i0_scaled;
    }
    // Coefficients of e^(−c)(1+c): aₘ = (−1)ᵐ (1 − m)/m!; of I₀: b_{2j} = 1/(4ʲ (j!)²), odd zero.
    const K: usize = 40;
    let mut a = [0.0f64; K];
    let mut b = [0.0f64; K];
    let mut fact = 1.0;
    for (m, am) in a.iter_mut().enumerate() {
        if m > 0 {
            fact *= m as f64;
        }
        let sign = if m % 2 == 0 { 1.0 } else { -1.0 };
        *am = sign * (1.0 - m as f64) / fact;
    }
    let mut bj = 1.0;
    for j in 0..K / 2 {
        if j > 0 {
            bj /= 4.0 * (j as f64) * (j as f64);
        }
        b[2 * j] = bj;
    }
    // E = −Σ_{k≥2} (Σ_{m+l=k} aₘ b_l) cᵏ, summed from the highest power down (Horner).
    let mut acc = 0.0;
    for k in (2..K).rev() {
        let mut pk = 0.0;
        for m in 0..=k {
            pk += a[m] * b[k - m];
        }
        acc = acc * c + pk;
    }
    -acc * c * c
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Power series Iₙ(c) = Σₖ (c/2)^(2k+n)/(k!(k+n)!) (A&S 9.6.10), all terms positive: accurate to
    /// a few ulp for moderate c. An independent reference for the recurrence.
    fn series_scaled(n: usize, c: f64) -> f64 {
        let mut term = 1.0;
        for i in 1..=n {
            term *= c / 2.0 / i as f64;
        }
        let mut sum = term;
        for k in 1..200 {
            term *= (c / 2.0) * (c / 2.0) / (k as f64 * (k + n) as f64);
            sum += term;
            if term < 1e-18 * sum {
                break;
            }
        }
        sum * (-c).exp()
    }

    /// Hankel's asymptotic expansion (A&S 9.7.1) for c ≫ n²: e^(−c)Iₙ(c) ≈ (2πc)^(−1/2) Σ_k (−1)^k
    /// ∏_{j=1..k}(μ − (2j−1)²)/(k!(8c)^k), μ = 4n².
    fn hankel_scaled(n: usize, c: f64) -> f64 {
        let mu = 4.0 * (n * n) as f64;
        let mut term = 1.0;
        let mut sum = 1.0;
        for k in 1..30 {
            let j = (2 * k - 1) as f64;
            term *= -(mu - j * j) / (k as f64 * 8.0 * c);
            sum += term;
            if term.abs() < 1e-18 {
                break;
            }
        }
        sum / (2.0 * std::f64::consts::PI * c).sqrt()
    }

    /// Independent check: e^{−μ}Iₙ(μ) = (1/π)∫₀^π e^{μ(cos φ−1)} cos(nφ) dφ (A&S 9.6.19), by the
    /// trapezoid rule, which is spectrally accurate for this smooth periodic integrand.
    fn bessel_by_quadrature(mu: f64, n: usize) -> f64 {
        let m = 4000;
        let h = std::f64::consts::PI / m as f64;
        let mut s = 0.0;
        for k in 0..=m {
            let phi = k as f64 * h;
            let w = if k == 0 || k == m { 0.5 } else { 1.0 };
            s += w * (mu * (phi.cos() - 1.0)).exp() * (n as f64 * phi).cos();
        }
        s * h / std::f64::consts::PI
    }

    #[test]
    fn miller_matches_power_series() {
        // Series terms are all positive, so the reference is good to ~1e-15; the tolerance 1e-13 allows
        // for the recurrence's rounding over up to a few hundred steps.
        for &c in &[1e-8, 1e-3, 0.1, 1.0, 3.7, 10.0, 25.0] {
            let v = scaled_bessel_i(c, 1e-18);
            for (n, &got) in v.iter().enumerate() {
                let want = series_scaled(n, c);
                if want < 1e-250 {
                    continue;
                }
                assert!(
                    ((got - want) / want).abs() < 1e-13,
                    "c={c} n={n} got={got} want={want}"
                );
            }
        }
    }

    #[test]
    fn miller_matches_hankel_for_large_argument() {
        // For c ≥ 1e4 and n ≤ 5 the asymptotic series is accurate to far below 1e-13.
        for &c in &[1e4, 1e6, 3e8] {
            let v = scaled_bessel_i(c, 1e-18);
            for (n, &got) in v.iter().enumerate().take(6) {
                let want = hankel_scaled(n, c);
                assert!(((got - want) / want).abs() < 1e-12, "c={c} n={n}");
            }
        }
    }

    #[test]
    fn miller_matches_integral_representation() {
        for &mu in &[1e-6, 0.3, 1.0, 7.5, 100.0, 2500.0] {
            let c = scaled_bessel_i(mu, 1e-18);
            for n in [0usize, 1, 2, 5, 20, 60] {
                let exact = bessel_by_quadrature(mu, n);
                let got = c.get(n).copied().unwrap_or(0.0);
                // absolute 4e−15: both sides are O(1) sums of O(1) terms in double precision
                assert!(
                    (got - exact).abs() < 4e-15,
                    "mu {mu} n {n}: {got} vs {exact}"
                );
            }
        }
    }

    /// For μ ≪ 1 the orders n ≥ 1 are tiny beside e^{−μ}I₀ ≈ 1, and the users divide them by μ:
    /// each must be accurate relative to itself and kept down to the cut of order 1 (not of order 0).
    #[test]
    fn small_mu_orders_are_accurate_relative_to_themselves() {
        for &mu in &[1e-60, 1e-30, 1e-10, 3e-9, 4e-7, 1e-4, 0.05] {
            for &cut in &[1e-18, 1e-19] {
                let c = scaled_bessel_i(mu, cut);
                for (n, &got) in c.iter().enumerate() {
                    let exact = series_scaled(n, mu);
                    assert!(
                        ((got - exact) / exact).abs() < 1e-13,
                        "mu {mu} n {n}: {got:e} vs {exact:e}"
                    );
                }
                // trimmed exactly where the next order falls below the cut of order 1, but never
                // below order 2 (kept always: the exact one-term solution needs it)
                let s1 = series_scaled(1, mu);
                assert!(c.len() >= 3, "mu {mu}");
                assert!(
                    c.len() == 3 || series_scaled(c.len() - 1, mu) >= cut * s1,
                    "mu {mu}"
                );
                assert!(
                    series_scaled(c.len(), mu) < cut * s1,
                    "mu {mu}: {} orders",
                    c.len()
                );
            }
        }
    }

    #[test]
    fn trim_and_normalisation() {
        // The last kept order is at or above the cut relative to the largest order ≥ 1, the next one
        // (computed with a smaller cut) below it, and the series sums to one (A&S 9.6.36).
        for &c in &[1e-6, 1.0, 100.0, 5e4] {
            let v = scaled_bessel_i(c, 1e-18);
            let finer = scaled_bessel_i(c, 1e-30);
            let peak = v[1..].iter().cloned().fold(0.0, f64::max);
            assert!(*v.last().unwrap() >= 1e-18 * peak, "c={c}");
            assert!(finer[v.len()] < 1e-18 * peak, "c={c}");
            let s: f64 = v[0] + 2.0 * v[1..].iter().sum::<f64>();
            assert!((s - 1.0).abs() < 1e-14, "c={c}");
        }
    }

    #[test]
    fn e_of_c_small_and_continuous() {
        // E(c) = 1 − (1+c)Ĩ₀(c) ≈ c²/4 − c³/6… for small c; check against the series reference at c
        // where the direct form still has a few good digits, and continuity across the switch at c = 1/2.
        for &c in &[1e-6, 1e-3, 0.3, 0.4999, 0.5, 0.5001, 1.0, 2.0] {
            let i0 = scaled_bessel_i(c, 1e-18)[0];
            let e = one_minus_one_plus_c_i0(c, i0);
            let direct = 1.0 - (1.0 + c) * series_scaled(0, c);
            // Direct form error ≈ 1e-16/|E|; tolerance accordingly.
            let tol = 1e-15 / e.abs() + 1e-13;
            assert!(
                ((e - direct) / e).abs() < tol,
                "c={c} e={e} direct={direct}"
            );
        }
        let c = 1e-4;
        let e = one_minus_one_plus_c_i0(c, 0.0);
        // Leading terms from the series product: c²/4 − c³/3 (the c⁴ term is ~1e-8 relative here).
        let want = c * c / 4.0 - c * c * c / 3.0;
        assert!(((e - want) / want).abs() < 1e-7);
    }
}
