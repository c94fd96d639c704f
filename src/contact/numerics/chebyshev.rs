//! Chebyshev machinery of the `auto` contact scheme (docs/MATH.md §7, §10): the Chebyshev coefficients of the
//! exponentials e^{μ(t−1)} on [−1, 1], the exterior continuation of a finite Hilbert transform, its
//! Laplace transform along the front exterior, and the pressure √(1−t²)·Σ aₖUₖ(t).
//!
//! Input: exponents μ ≥ 0 and Chebyshev coefficient vectors; output: plain `f64` vectors.
//! Math: e^{μt} = I₀(μ) + 2Σₙ Iₙ(μ)Tₙ(t) (Abramowitz & Stegun 9.6.34), so e^{μ(t−1)} has the
//! coefficients e^{−μ}I₀(μ), 2e^{−μ}Iₙ(μ) ([`crate::special::scaled_bessel_i`], Miller's backward
//! recurrence, trimmed relative to order 1). The pressure sums Σ aₙ sin(nθ) are in
//! [`crate::special::chebyshev`]. For |t| > 1, with w = t − √(t²−1) = e^{−θ}, t = cosh θ:
//! (1/π)∫√(1−s²)U_{n−1}(s)/(t−s) ds = wⁿ (the exterior of the identity that gives Tₙ(t) inside).

use crate::special::scaled_bessel_i;

/// Relative cut of the Bessel series (see [`scaled_bessel_i`]): 1e−18 of the largest order ≥ 1.
const BESSEL_CUT: f64 = 1e-18;

/// Chebyshev coefficients Fₙ (n ≥ 0) of e^{μ(t−1)} on [−1, 1].
pub(crate) fn exp_coefficients(mu: f64) -> Vec<f64> {
    let mut c = scaled_bessel_i(mu, BESSEL_CUT);
    for v in c.iter_mut().skip(1) {
        *v *= 2.0;
    }
    c
}

/// θ = acosh(1+σ) and w = e^{−θ} = 1/(1+σ+√(σ(2+σ))), both without cancellation for small σ.
pub(crate) fn theta_w(sigma: f64) -> (f64, f64) {
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
pub(crate) fn exterior_values(a: &[f64], thetas: &[f64], ws: &[f64], out: &mut [f64]) {
    exterior_values_by(a, thetas, ws, |k| taylor_factors(thetas[k]), out);
}

/// Terms of the Taylor branch of [`exterior_values`]: (0.5)^k/k! < 1e−17 at k = 18.
const K: usize = 18;

/// The Taylor branch's factors (−θ)^k/k!, k < K, each from the previous one by ·(−θ/k).
fn taylor_factors(theta: f64) -> [f64; K] {
    let mut f = [0.0; K];
    let mut fac = 1.0;
    for (k, v) in f.iter_mut().enumerate() {
        if k > 0 {
            fac *= -theta / k as f64;
        }
        *v = fac;
    }
    f
}

/// Points θ (w = e^{−θ}) at which many series' exterior functions are wanted, with the Taylor
/// factors of [`exterior_values`] formed once for all series (they depend on θ alone):
/// [`ExteriorPoints::values`] gives `exterior_values`' results bit for bit.
pub(crate) struct ExteriorPoints {
    thetas: Vec<f64>,
    ws: Vec<f64>,
    /// Taylor factors at the points with θ ≤ 0.5 (the only ones the Taylor branch can take).
    factors: Vec<[f64; K]>,
}

impl ExteriorPoints {
    /// The points θ with w = e^{−θ} (as from [`theta_w`]).
    pub fn new(thetas: Vec<f64>, ws: Vec<f64>) -> Self {
        let factors = thetas
            .iter()
            .map(|&t| {
                if t <= 0.5 {
                    taylor_factors(t)
                } else {
                    [0.0; K]
                }
            })
            .collect();
        ExteriorPoints {
            thetas,
            ws,
            factors,
        }
    }

    /// [`exterior_values`] of the series `a` at these points.
    pub fn values(&self, a: &[f64], out: &mut [f64]) {
        exterior_values_by(a, &self.thetas, &self.ws, |k| self.factors[k], out);
    }
}

/// [`exterior_values`] with the Taylor factors of point k from `factors(k)`.
fn exterior_values_by(
    a: &[f64],
    thetas: &[f64],
    ws: &[f64],
    factors: impl Fn(usize) -> [f64; K],
    out: &mut [f64],
) {
    let n_max = a.len().saturating_sub(1);
    if n_max == 0 {
        out.iter_mut().for_each(|v| *v = 0.0);
        return;
    }
    let mut moments: Option<[f64; K]> = None;
    let mut horner: Vec<(usize, usize)> = Vec::new(); // (point, n_cut)
    for (k, (&theta, o)) in thetas.iter().zip(out.iter_mut()).enumerate() {
        if theta * n_max as f64 <= 0.5 {
            let m = moments.get_or_insert_with(|| taylor_moments::<K>(a));
            // Σ_k (−θ)^k/k! m_k
            let mut s = 0.0;
            for (fac, mk) in factors(k).iter().zip(m.iter()) {
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

#[cfg(test)]
mod tests {
    use super::*;

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
    fn exterior_points_give_exterior_values_bit_for_bit() {
        // the shared Taylor factors are the ones exterior_values forms per call, so the results
        // must be identical; series long and short (Taylor branch at small θ·n, Horner beyond)
        let sig: Vec<f64> = (0..60)
            .map(|k| 1e-14 * 10f64.powf(0.3 * k as f64))
            .collect();
        let (th, w): (Vec<f64>, Vec<f64>) = sig.iter().map(|&s| theta_w(s)).unzip();
        let points = ExteriorPoints::new(th.clone(), w.clone());
        assert_eq!(points.thetas.len(), sig.len());
        for a in [
            vec![0.0, 1.0],
            exp_coefficients(0.3),
            exp_coefficients(40.0),
            exp_coefficients(5e4),
            (0..70)
                .map(|n| (0.37 * n as f64).cos() / (1.0 + n as f64))
                .collect(),
        ] {
            let mut want = vec![0.0; sig.len()];
            let mut got = vec![0.0; sig.len()];
            exterior_values(&a, &th, &w, &mut want);
            points.values(&a, &mut got);
            assert_eq!(
                got.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                want.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
            );
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
