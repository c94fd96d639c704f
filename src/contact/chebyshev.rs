//! Chebyshev machinery of the `auto` contact scheme (MATH.md §3): the Chebyshev coefficients of the
//! exponentials e^{μ(t−1)} on [−1, 1], the exterior continuation of a finite Hilbert transform, its
//! Laplace transform along the front exterior, and the pressure √(1−t²)·Σ aₖUₖ(t).
//!
//! Input: exponents μ ≥ 0 and Chebyshev coefficient vectors; output: plain `f64` vectors.
//! Math: e^{μt} = I₀(μ) + 2Σₙ Iₙ(μ)Tₙ(t) (Abramowitz & Stegun 9.6.34), so e^{μ(t−1)} has the
//! coefficients e^{−μ}I₀(μ), 2e^{−μ}Iₙ(μ); these scaled Bessel functions come from Miller's backward
//! recurrence I_{n−1} = I_{n+1} + (2n/μ)Iₙ (A&S 9.6.26) normalised by e^{−μ}(I₀ + 2ΣIₙ) = 1 (A&S
//! 9.6.37), stable for every μ. For |t| > 1, with w = t − √(t²−1) = e^{−θ}, t = cosh θ:
//! (1/π)∫√(1−s²)U_{n−1}(s)/(t−s) ds = wⁿ (the exterior of the identity that gives Tₙ(t) inside).

/// Scaled modified Bessel functions e^{−μ}Iₙ(μ), n = 0, 1, …, trimmed where they fall below
/// 1e−18 of the largest of order n ≥ 1.
pub fn scaled_bessel_i(mu: f64) -> Vec<f64> {
    if mu <= 0.0 || !mu.is_finite() {
        return vec![1.0];
    }
    // Terms behave like exp(−n²/(2μ)) for μ ≫ 1 and like (μ/2)ⁿ/n! for μ ≪ 1; 2·ln(1e18) ≈ 83.
    let n_keep = ((83.0 * mu.max(1.0)).sqrt() + 12.0).ceil() as usize;
    // Miller: start well beyond n_keep so the start error has decayed by far more than 1e−18.
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
    // Trim relative to the largest coefficient of order n ≥ 1, not to the constant term: the
    // scheme removes the constant and divides the rest by μ (`auto`, Âⱼ = Aⱼμⱼ), so for μ ≪ 1,
    // where e^{−μ}I₀ ≈ 1 ≫ e^{−μ}I₁ ≈ μ/2, a cut at 1e−18 of the constant left an error of
    // 1e−18/μ in the divided series. At μ ≈ 4e−7 (a retardation time 1e9 times the contact time)
    // dropping the n = 2 term at 1e−18 moved β by 4e−11 relative, ρF/N by 5.6e−7 of a slow-end
    // friction (tests/contact_props.rs, case 28).
    let peak = out.iter().skip(1).cloned().fold(0.0, f64::max);
    while out.len() > 2 && *out.last().unwrap() < 1e-18 * peak {
        out.pop();
    }
    out
}

/// Chebyshev coefficients Fₙ (n ≥ 0) of e^{μ(t−1)} on [−1, 1].
pub fn exp_coefficients(mu: f64) -> Vec<f64> {
    let mut c = scaled_bessel_i(mu);
    for v in c.iter_mut().skip(1) {
        *v *= 2.0;
    }
    c
}

/// θ = acosh(1+σ) and w = e^{−θ} = 1/(1+σ+√(σ(2+σ))), both without cancellation for small σ.
pub fn theta_w(sigma: f64) -> (f64, f64) {
    let r = (sigma * (2.0 + sigma)).sqrt();
    ((sigma + r).ln_1p(), 1.0 / (1.0 + sigma + r))
}

/// The exterior function Σ_{n≥1} aₙwⁿ (`a[0]` ignored) at the points of `thetas` (θ ≥ 0, w = e^{−θ}),
/// the continuation of the finite Hilbert transform beyond the front edge t = 1.
///
/// Small θ·n_max uses the Taylor series in θ with the moments Σ nᵏaₙ (all terms of one sign for the
/// exponential components, so no cancellation); larger θ a Horner sum cut where e^{−nθ} < e^{−41},
/// run for eight points at once and two coefficients per step, s ← s·w² + (aₙw² + aₙ₋₁w)
/// (independent chains: one sum at a time is bound by the latency of its multiply-add chain).
pub fn exterior_values(a: &[f64], thetas: &[f64], ws: &[f64], out: &mut [f64]) {
    let n_max = a.len().saturating_sub(1);
    if n_max == 0 {
        out.iter_mut().for_each(|v| *v = 0.0);
        return;
    }
    const K: usize = 18; // (0.5)^k/k! < 1e−17 at k = 18
    let mut moments: Option<[f64; K]> = None;
    let mut horner: Vec<(usize, usize)> = Vec::new(); // (point, n_cut)
    for (k, (&theta, o)) in thetas.iter().zip(out.iter_mut()).enumerate() {
        if theta * n_max as f64 <= 0.5 {
            let m = moments.get_or_insert_with(|| taylor_moments::<K>(a));
            // Σ_k (−θ)^k/k! m_k
            let mut s = 0.0;
            let mut fac = 1.0;
            for (k, mk) in m.iter().enumerate() {
                if k > 0 {
                    fac *= -theta / k as f64;
                }
                s += fac * mk;
            }
            *o = s;
        } else {
            horner.push((k, ((41.0 / theta).ceil() as usize + 1).min(n_max)));
        }
    }
    const P: usize = 8;
    for chunk in horner.chunks(P) {
        let mut w = [0.0_f64; P];
        let mut n_cut = 0;
        for (wq, &(k, nc)) in w.iter_mut().zip(chunk) {
            *wq = ws[k];
            n_cut = n_cut.max(nc);
        }
        let mut w2 = [0.0_f64; P];
        for q in 0..P {
            w2[q] = w[q] * w[q];
        }
        let mut s = [0.0_f64; P];
        let mut n = n_cut;
        if n % 2 == 1 {
            for q in 0..P {
                s[q] = a[n] * w[q];
            }
            n -= 1;
        }
        // s = Σ_{m>n} aₘw^{m−n}; two steps: s ← s·w² + aₙw² + aₙ₋₁w
        while n >= 2 {
            let (an, an1) = (a[n], a[n - 1]);
            for q in 0..P {
                s[q] = s[q] * w2[q] + (an * w2[q] + an1 * w[q]);
            }
            n -= 2;
        }
        for (q, &(k, _)) in chunk.iter().enumerate() {
            out[k] = s[q];
        }
    }
}

/// The moments m_k = Σ_{n≥1} nᵏaₙ, k < K.
fn taylor_moments<const K: usize>(a: &[f64]) -> [f64; K] {
    let mut m = [0.0; K];
    let mut p: Vec<f64> = a.to_vec();
    p[0] = 0.0;
    let nf: Vec<f64> = (0..a.len()).map(|n| n as f64).collect();
    for mk in m.iter_mut() {
        // four partial sums so the additions need not wait on each other
        let mut acc = [0.0; 4];
        let chunks = p.chunks_exact(4);
        let rest: f64 = chunks.remainder().iter().sum();
        for c in chunks {
            acc[0] += c[0];
            acc[1] += c[1];
            acc[2] += c[2];
            acc[3] += c[3];
        }
        *mk = (acc[0] + acc[1]) + (acc[2] + acc[3]) + rest;
        for (v, n) in p.iter_mut().zip(&nf) {
            *v *= n;
        }
    }
    m
}

/// Q′(t)/scale = √(1−t²)Σ_{k≥0} a_{k+1}U_k(t) = Σ_{n≥1} aₙ sin(nθ) at t = cos θ (`a[0]` ignored);
/// the sine form keeps the error ~ n·ε right up to the edges, where a Clenshaw sum loses ~ n²·ε.
pub fn sine_series(a: &[f64], theta: f64) -> f64 {
    let (s1, c1) = theta.sin_cos();
    let (mut s, mut c) = (s1, c1);
    let mut acc = 0.0;
    for (n, &an) in a.iter().enumerate().skip(1) {
        acc += an * s;
        // rotate by θ; renormalise occasionally so |e^{inθ}| stays 1
        let s_new = s * c1 + c * s1;
        c = c * c1 - s * s1;
        s = s_new;
        if n % 64 == 0 {
            let r = (s * s + c * c).sqrt();
            s /= r;
            c /= r;
        }
    }
    acc
}

/// Σ_{n≥1} aₙ sin(nθ_m) at all θ_m = πm/M, m = 0…M, with M the smallest power of two ≥ len(a):
/// one complex FFT of length 2M (radix 2), O(M log M) instead of O(M·len) for the direct sums.
/// Returns (θ_m, value) pairs.
pub fn sine_series_grid(a: &[f64]) -> Vec<(f64, f64)> {
    let m = a.len().max(2).next_power_of_two();
    let p = 2 * m;
    let mut re = vec![0.0; p];
    let mut im = vec![0.0; p];
    for (n, &v) in a.iter().enumerate().skip(1) {
        re[n] = v;
    }
    fft_positive(&mut re, &mut im);
    (0..=m)
        .map(|k| (std::f64::consts::PI * k as f64 / m as f64, im[k]))
        .collect()
}

/// In-place radix-2 DFT X_k = Σ x_n e^{+2πi nk/P} (P a power of two).
fn fft_positive(re: &mut [f64], im: &mut [f64]) {
    let p = re.len();
    let mut j = 0;
    for i in 1..p {
        let mut bit = p >> 1;
        while j & bit != 0 {
            j ^= bit;
            bit >>= 1;
        }
        j |= bit;
        if i < j {
            re.swap(i, j);
            im.swap(i, j);
        }
    }
    // twiddles e^{2πik/P}, k < P/2, computed directly (no recurrence drift) once; stage `len`
    // uses every (P/len)-th
    let ang = 2.0 * std::f64::consts::PI / p as f64;
    let tw: Vec<(f64, f64)> = (0..p / 2)
        .map(|k| {
            let (s, c) = (ang * k as f64).sin_cos();
            (c, s)
        })
        .collect();
    let mut len = 2;
    while len <= p {
        let half = len / 2;
        let stride = p / len;
        for start in (0..p).step_by(len) {
            for k in 0..half {
                let (wr, wi) = tw[k * stride];
                let (a, b) = (start + k, start + k + half);
                let xr = re[b] * wr - im[b] * wi;
                let xi = re[b] * wi + im[b] * wr;
                re[b] = re[a] - xr;
                im[b] = im[a] - xi;
                re[a] += xr;
                im[a] += xi;
            }
        }
        len <<= 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
    fn miller_matches_integral_representation() {
        for &mu in &[1e-6, 0.3, 1.0, 7.5, 100.0, 2500.0] {
            let c = scaled_bessel_i(mu);
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

    /// For μ ≪ 1 the orders n ≥ 1 are tiny beside e^{−μ}I₀ ≈ 1, and the scheme divides them by μ:
    /// each must be accurate relative to itself and kept down to 1e−18 of order 1 (not of order 0).
    /// Reference: the power series Iₙ(μ) = (μ/2)ⁿ Σₖ (μ²/4)ᵏ/(k!(n+k)!) (A&S 9.6.10), all terms
    /// positive, times e^{−μ}.
    #[test]
    fn small_mu_orders_are_accurate_relative_to_themselves() {
        for &mu in &[1e-10, 3e-9, 4e-7, 1e-4, 0.05] {
            let c = scaled_bessel_i(mu);
            let series = |n: usize| -> f64 {
                let mut term =
                    (0.5 * mu).powi(n as i32) / (1..=n).map(|k| k as f64).product::<f64>();
                let mut sum = term;
                for k in 1..30 {
                    term *= 0.25 * mu * mu / (k as f64 * (n + k) as f64);
                    sum += term;
                }
                sum * (-mu).exp()
            };
            for (n, &got) in c.iter().enumerate() {
                let exact = series(n);
                assert!(
                    ((got - exact) / exact).abs() < 1e-13,
                    "mu {mu} n {n}: {got:e} vs {exact:e}"
                );
            }
            // trimmed exactly where the next order falls below 1e−18 of order 1
            assert!(series(c.len() - 1) >= 1e-18 * series(1), "mu {mu}");
            assert!(
                series(c.len()) < 1e-18 * series(1),
                "mu {mu}: {} orders",
                c.len()
            );
        }
    }

    #[test]
    fn exponential_series_reproduces_the_exponential() {
        for &mu in &[0.01, 3.0, 400.0] {
            let c = exp_coefficients(mu);
            for &t in &[-1.0, -0.3, 0.5, 0.99, 1.0] {
                let th = f64::acos(t);
                let s: f64 = c
                    .iter()
                    .enumerate()
                    .map(|(n, a)| a * (n as f64 * th).cos())
                    .sum();
                let exact = (mu * (t - 1.0)).exp();
                // summing ~√μ terms of size ≤ 1: a few ulp each
                assert!((s - exact).abs() < 1e-14, "mu {mu} t {t}: {s} vs {exact}");
            }
        }
    }

    #[test]
    fn fft_grid_matches_direct_sums() {
        let a: Vec<f64> = (0..37).map(|n| 1.0 / (1.0 + n as f64).powf(1.5)).collect();
        let grid = sine_series_grid(&a);
        assert_eq!(grid.len(), 65);
        for &(th, v) in grid.iter().step_by(5) {
            // both are sums of 36 terms of size ≤ 1: agreement to a few ulp of the sum
            assert!((v - sine_series(&a, th)).abs() < 1e-14, "θ {th}");
        }
    }

    #[test]
    fn exterior_of_t_is_w() {
        // F = t has the single coefficient F₁ = 1, whose exterior continuation is w = t − √(t²−1).
        let a = [0.0, 1.0];
        let sig = [1e-12, 1e-3, 0.5, 10.0, 1e6];
        let (th, w): (Vec<f64>, Vec<f64>) = sig.iter().map(|&s| theta_w(s)).unzip();
        let mut out = [0.0; 5];
        exterior_values(&a, &th, &w, &mut out);
        for (k, &s) in sig.iter().enumerate() {
            // w = e^{−acosh(1+σ)} = e^{−asinh(√(σ(2+σ)))}: an independent route without t²−1
            let exact = (-(s * (2.0 + s)).sqrt().asinh()).exp();
            assert!(
                (out[k] - exact).abs() < 1e-15 * exact,
                "{s}: {} vs {exact}",
                out[k]
            );
        }
    }
}
