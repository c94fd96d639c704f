//! Chebyshev and sine series: interpolation coefficients (DCT at the Lobatto points), Clenshaw's
//! evaluation of Σ cⱼTⱼ(t), and sums Σ aₙ sin(nθ) one at a time or on a whole grid by FFT.
//!
//! Input: coefficient or value vectors (`&[f64]`) and points; output: `f64` values or vectors. No
//! errors (empty input is the caller's to avoid; documented per function).
//!
//! Used by the contact stage: the auto scheme's pressure √(1−t²)ΣaₖUₖ(t) = Σ aₖ₊₁ sin((k+1)θ)
//! (t = cos θ), the gap check's e⁻ʸEi(y) table, and the friction maps' interpolants of ln φ(ln s).
//! Clenshaw (1955): b_j = c_j + 2t·b_{j+1} − b_{j+2}, Σ cⱼTⱼ(t) = c₀ + t·b₁ − b₂.

use std::f64::consts::PI;

/// Coefficients cⱼ of p(t) = Σ cⱼTⱼ(t) interpolating `v` at the Lobatto points tₖ = cos(πk/n),
/// k = 0…n (n = len − 1 ≥ 1): the DCT-I.
pub fn lobatto_coefficients(v: &[f64]) -> Vec<f64> {
    let n = v.len() - 1;
    (0..=n)
        .map(|j| {
            let mut s = 0.0;
            for (k, &vk) in v.iter().enumerate() {
                let w = if k == 0 || k == n { 0.5 } else { 1.0 };
                s += w * vk * (PI * (j * k) as f64 / n as f64).cos();
            }
            let c = 2.0 * s / n as f64;
            if j == 0 || j == n {
                0.5 * c
            } else {
                c
            }
        })
        .collect()
}

/// Coefficients cⱼ (j < n) of the interpolant of `f` on [a, b] at the n Chebyshev points of the first
/// kind, tₖ = cos(π(k + ½)/n) (the DCT-II); evaluate with [`clenshaw`] at t = (2x − a − b)/(b − a).
pub(crate) fn first_kind_coefficients<const N: usize>(
    f: impl Fn(f64) -> f64,
    a: f64,
    b: f64,
) -> [f64; N] {
    let v: Vec<f64> = (0..N)
        .map(|k| {
            let t = (PI * (k as f64 + 0.5) / N as f64).cos();
            f(0.5 * (a + b) + 0.5 * (b - a) * t)
        })
        .collect();
    let mut c = [0.0; N];
    for (j, cj) in c.iter_mut().enumerate() {
        let s: f64 = (0..N)
            .map(|k| v[k] * (PI * j as f64 * (k as f64 + 0.5) / N as f64).cos())
            .sum();
        *cj = 2.0 * s / N as f64;
    }
    c[0] *= 0.5;
    c
}

/// Clenshaw evaluation of Σ cⱼTⱼ(t) (`c` not empty).
pub(crate) fn clenshaw(c: &[f64], t: f64) -> f64 {
    let (mut b1, mut b2) = (0.0, 0.0);
    for &cj in c.iter().skip(1).rev() {
        let b0 = 2.0 * t * b1 - b2 + cj;
        b2 = b1;
        b1 = b0;
    }
    t * b1 - b2 + c[0]
}

/// Q′(t)/scale = √(1−t²)Σ_{k≥0} a_{k+1}U_k(t) = Σ_{n≥1} aₙ sin(nθ) at t = cos θ (`a[0]` ignored);
/// the sine form keeps the error ~ n·ε right up to the edges, where a Clenshaw sum loses ~ n²·ε.
pub(crate) fn sine_series(a: &[f64], theta: f64) -> f64 {
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
pub(crate) fn sine_series_grid(a: &[f64]) -> Vec<(f64, f64)> {
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
    fn interpolants_reproduce_a_polynomial_and_converge_for_the_exponential() {
        // A cubic is reproduced exactly (to rounding) by either interpolant of degree ≥ 3.
        let p = |x: f64| 1.0 - 2.0 * x + 0.5 * x * x * x;
        let lob: Vec<f64> = (0..=8).map(|k| p((PI * k as f64 / 8.0).cos())).collect();
        let cl = lobatto_coefficients(&lob);
        let cf = first_kind_coefficients::<9>(p, -1.0, 1.0);
        for &t in &[-1.0, -0.4, 0.0, 0.77, 1.0] {
            // sums of ≤ 9 terms of size ≤ 2: a few ulp
            assert!((clenshaw(&cl, t) - p(t)).abs() < 1e-14, "t {t}");
            assert!((clenshaw(&cf, t) - p(t)).abs() < 1e-14, "t {t}");
        }
        // eˣ on [0, 2] at degree 20: the truncation error 2·(1)^21/(2^20·21!) ≈ 4e−26, so rounding
        // (≈ 1e−15 of e² ≈ 7.4) is all that is left.
        let c = first_kind_coefficients::<21>(f64::exp, 0.0, 2.0);
        for &x in &[0.0, 0.3, 1.0, 1.9, 2.0] {
            let t = x - 1.0;
            assert!((clenshaw(&c, t) - x.exp()).abs() < 1e-14 * x.exp(), "x {x}");
        }
    }
}
