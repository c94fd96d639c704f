//! Exponentially scaled modified Bessel functions of the first kind, Ĩₙ(c) = e^(−c)·Iₙ(c), for all
//! orders n = 0…N at one argument c > 0 (input: c; output: a `Vec<f64>`).
//!
//! Owned by the exact one-term contact solution (src/contact/exact.rs), where Ĩₙ(c) are the Chebyshev
//! coefficients of e^(c(y−1)) on [−1, 1]: e^(c·y) = I₀(c) + 2 Σₙ Iₙ(c) Tₙ(y) (Abramowitz & Stegun 9.6.34,
//! with y = cos θ). The scaling keeps every value in [0, 1] for any c: Iₙ(c) itself overflows past c ≈ 713.
//!
//! Method: Miller's backward recurrence Iₙ₋₁ = (2n/c)·Iₙ + Iₙ₊₁ (A&S 9.6.26), started far enough above the
//! last order needed that the start error has died out, run on the ratios Iₙ/Iₙ₋₁ (no overflow), and
//! normalised with the identity Ĩ₀ + 2 Σₙ≥₁ Ĩₙ = 1 (A&S 9.6.36 at y = 1, times e^(−c)). Iₙ is the
//! minimal solution of the recurrence as n grows, so the backward direction is stable; every term of the
//! normalisation sum is positive, so it loses nothing to cancellation.

/// Ĩₙ(c) = e^(−c)·Iₙ(c) for n = 0, 1, …, N, where N is the first order with Ĩₙ(c) < `rel_cut`·Ĩ₀(c)
/// (the tail beyond N is then below `rel_cut` relative to the whole series, since Ĩₙ falls faster than
/// geometrically there). `c` must be finite and > 0.
pub fn scaled_bessel_i_orders(c: f64, rel_cut: f64) -> Vec<f64> {
    debug_assert!(c > 0.0 && c.is_finite());
    // Estimate log(Ĩₙ/Ĩ₀) with the ratio Iₙ/Iₙ₋₁ ≈ c/(n + √(n² + c²)) (an Amos-type bound, close to the
    // true ratio); the order where it drops below `rel_cut` is N, the one where it drops below
    // rel_cut²·1e-10 is where the backward recurrence starts (the start error then decays by more than the
    // whole dynamic range we keep before reaching N).
    let ln_cut = rel_cut.ln();
    let ln_start = 2.0 * ln_cut - 23.0;
    let mut ln_ratio = 0.0;
    let mut n_last = None;
    let mut n = 0usize;
    let start = loop {
        n += 1;
        let nf = n as f64;
        ln_ratio += (c / (nf + nf.hypot(c))).ln();
        if n_last.is_none() && ln_ratio < ln_cut {
            n_last = Some(n);
        }
        if ln_ratio < ln_start {
            break n + 10;
        }
    };
    let n_last = n_last.unwrap_or(start);

    // Backward recurrence in ratio form: rₖ = Iₖ/Iₖ₋₁ = 1/(2k/c + rₖ₊₁) from r_{start+1} = 0 (the
    // continued fraction of the minimal solution; no overflow even for tiny c, where 2k/c is huge),
    // then Ĩₖ = rₖ·Ĩₖ₋₁ from Ĩ₀ = 1 (products underflow harmlessly to 0) and normalisation.
    let mut vals = vec![0.0f64; start + 1];
    let mut r_next = 0.0;
    for k in (1..=start).rev() {
        let r = 1.0 / (2.0 * k as f64 / c + r_next);
        vals[k] = r;
        r_next = r;
    }
    vals[0] = 1.0;
    for k in 1..=start {
        vals[k] *= vals[k - 1];
    }
    // Normalise: Ĩ₀ + 2 Σ Ĩₙ = 1; sum the small terms first.
    let mut sum = 0.0;
    for v in vals[1..=start].iter().rev() {
        sum += 2.0 * v;
    }
    sum += vals[0];
    vals.truncate(n_last + 1);
    for v in vals.iter_mut() {
        *v /= sum;
    }
    vals
}

/// E(c) = 1 − (1 + c)·Ĩ₀(c), without cancellation for small c (where E ≈ c²/4).
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

    /// Power series Iₙ(c) = Σₖ (c/2)^(2k+n)/(k!(k+n)!), all terms positive: accurate to a few ulp for
    /// moderate c. An independent reference for the recurrence.
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

    #[test]
    fn miller_matches_power_series() {
        // Series terms are all positive, so the reference is good to ~1e-15; the tolerance 1e-13 allows
        // for the recurrence's rounding over up to a few hundred steps.
        for &c in &[1e-8, 1e-3, 0.1, 1.0, 3.7, 10.0, 25.0] {
            let v = scaled_bessel_i_orders(c, 1e-18);
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
            let v = scaled_bessel_i_orders(c, 1e-18);
            for (n, &got) in v.iter().enumerate().take(6) {
                let want = hankel_scaled(n, c);
                assert!(((got - want) / want).abs() < 1e-12, "c={c} n={n}");
            }
        }
    }

    #[test]
    fn truncation_order_and_tail() {
        // The last kept order is below the cut and the series sums to one (A&S 9.6.36).
        for &c in &[1e-6, 1.0, 100.0, 5e4] {
            let v = scaled_bessel_i_orders(c, 1e-18);
            let last = *v.last().unwrap();
            assert!(last < 1e-18 * v[0] * 10.0, "c={c}");
            let s: f64 = v[0] + 2.0 * v[1..].iter().sum::<f64>();
            assert!((s - 1.0).abs() < 1e-14, "c={c}");
        }
    }

    #[test]
    fn e_of_c_small_and_continuous() {
        // E(c) = 1 − (1+c)Ĩ₀(c) ≈ c²/4 − c³/6… for small c; check against the series reference at c
        // where the direct form still has a few good digits, and continuity across the switch at c = 1/2.
        for &c in &[1e-6, 1e-3, 0.3, 0.4999, 0.5, 0.5001, 1.0, 2.0] {
            let i0 = scaled_bessel_i_orders(c, 1e-18)[0];
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
