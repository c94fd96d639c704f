//! The kernel K(ξ) of the steady rolling problem (thesis eq. 3.19) and its first two antiderivatives,
//! for the creep function γ(ζ) = Σᵢ fᵢ e^(−bᵢζ) (eq. 3.7).
//!
//! Input: the creep terms [`CreepTerm`] (fᵢ ≥ 0, bᵢ > 0); output: K, K₁ = ∫₀^ξ K, K₂ = ∫₀^ξ K₁ and the
//! hat-function averages of K that are the matrix entries of the thesis scheme ([`Kernel::hat_averages`]).
//!
//! Math (docs/MATH.md §2). Per term, ∫₀^∞ e^(−bζ) log|ξ+ζ| dζ = (log|bξ| − log b + g(bξ))/b with
//! g(x) = eˣE1(x) (x > 0), −eˣEi(−x) (x < 0). Constants cancel in eq. 3.25 (the kernel enters only as
//! K(−ξ′) − K(ξ−ξ′)), so we add (fᵢ/bᵢ)(log bᵢ + γ_E) per term and use
//!
//! ```text
//!   K(ξ)  = log|ξ| + Σ (fᵢ/bᵢ)  h(bᵢξ),          h(x) = log|x| + g(x) + γ_E,   h(0) = 0
//!   K₁(ξ) = ξ(log|ξ| − 1)          + Σ (fᵢ/bᵢ²) h₁(bᵢξ),  h₁(x) = ∫₀ˣ h
//!   K₂(ξ) = ξ² log|ξ|/2 − 3ξ²/4     + Σ (fᵢ/bᵢ³) h₂(bᵢξ),  h₂(x) = ∫₀ˣ h₁
//! ```
//!
//! h is evaluated only through the scaled, cancellation-free `crate::special::kernel_bracket*`
//! functions, which go to 0 like −x log|x| for small x (so a large fᵢ/bᵢ never multiplies a difference of
//! two large logarithms) and never form eˣ or E1 alone (no overflow past |x| ≈ 709). Closed forms used
//! below and in the tests: h₁(x) = x(log|x| + γ_E − 1) + h(x) and
//! h₂(x) = (x²/2)(log|x| + γ_E − 3/2) + h₁(x) (from g′ = g − 1/x).
//!
//! Units: ξ in units of V·T (thesis §3.2); K is dimensionless.

use crate::contact::error::{non_negative, positive, ContactError};
use crate::contact::problem::CreepTerm;
#[cfg(test)]
use crate::special::kernel_bracket_int1;
use crate::special::{kernel_bracket, kernel_bracket_int2, EULER_GAMMA};

/// Below this bᵢh the hat averages use the leading series term of h₂ (see [`Kernel::hat_averages`]).
const TINY_H: f64 = 1e-30;

/// The kernel of eq. 3.19 for one creep spectrum γ(ζ) = Σ fᵢ e^(−bᵢζ).
#[derive(Debug, Clone, PartialEq)]
pub struct Kernel {
    terms: Vec<CreepTerm>,
}

impl Kernel {
    /// A kernel for these terms; fᵢ must be finite and ≥ 0, bᵢ finite and > 0. Terms with fᵢ = 0 are
    /// dropped (no terms at all is the elastic half-space, K = log|ξ|).
    pub fn new(terms: &[CreepTerm]) -> Result<Self, ContactError> {
        let mut kept = Vec::with_capacity(terms.len());
        for (i, t) in terms.iter().enumerate() {
            non_negative(format!("creep term {}: f", i + 1), t.f)?;
            positive(format!("creep term {}: b", i + 1), t.b)?;
            if t.f > 0.0 {
                kept.push(*t);
            }
        }
        Ok(Self { terms: kept })
    }

    /// The terms kept (fᵢ > 0).
    pub fn terms(&self) -> &[CreepTerm] {
        &self.terms
    }

    /// Σ fᵢ/bᵢ = J∞/J_g − 1: the relaxed compliance in units of the glassy one, minus one.
    pub fn sum_f_over_b(&self) -> f64 {
        self.terms.iter().map(|t| t.f / t.b).sum()
    }

    /// K(ξ) = log|ξ| + Σ (fᵢ/bᵢ) h(bᵢξ) (eq. 3.19 up to a constant). K(0) = −∞.
    #[cfg(test)]
    pub fn k(&self, xi: f64) -> f64 {
        let mut s = xi.abs().ln();
        for t in &self.terms {
            s += (t.f / t.b) * kernel_bracket(t.b * xi);
        }
        s
    }

    /// K₁(ξ) = ∫₀^ξ K = ξ(log|ξ| − 1) + Σ (fᵢ/bᵢ²) h₁(bᵢξ).
    #[cfg(test)]
    pub fn k1(&self, xi: f64) -> f64 {
        let mut s = xlogx(xi) - xi;
        for t in &self.terms {
            s += (t.f / (t.b * t.b)) * kernel_bracket_int1(t.b * xi);
        }
        s
    }

    /// K₂(ξ) = ∫₀^ξ K₁ = ξ² log|ξ|/2 − 3ξ²/4 + Σ (fᵢ/bᵢ³) h₂(bᵢξ).
    #[cfg(test)]
    pub fn k2(&self, xi: f64) -> f64 {
        let mut s = 0.5 * xi * xlogx(xi) - 0.75 * xi * xi;
        for t in &self.terms {
            s += (t.f / (t.b * t.b * t.b)) * kernel_bracket_int2(t.b * xi);
        }
        s
    }

    /// Hat averages A(k) = ∫ φ(s) K(kh − s) ds for k = −m..=m, where φ is the hat function of half-width
    /// h and height 1 (so A(k) = (K₂((k+1)h) − 2K₂(kh) + K₂((k−1)h))/h, the second difference of K₂).
    ///
    /// Returned as a vector indexed by k + m. Costs O(m) evaluations of each special function per term
    /// (the Toeplitz structure of the thesis scheme on a uniform grid, docs/MATH.md §2).
    ///
    /// The logarithmic part is summed in closed form without cancellation:
    /// (1/h)Δ²[ξ²log|ξ|/2] = h(D(k) + log h) with D(k) = ½Δ²[k² log|k|] (see `half_second_diff_k2logk`).
    /// Per term with H = bh: (fᵢ/bᵢ³)(1/h)Δ²h₂ = (fᵢ/bᵢ)·h·S(k), S(k) = Δ²h₂(kH)/H². Where |kH| < 2, S is
    /// the plain second difference (h₂ ~ x³ log|x| is small there: relative loss ≲ k²ε). Elsewhere the
    /// closed form of h₂ splits S into D(k) + log H + γ_E − 3/2 + E(k)/H + Δ²h(kH)/H² with
    /// E(k) = Δ²[k log|k|], whose pieces do not cancel (the plain second difference of h₂ ~ x² log|x|/2
    /// would lose k²ε, ~1e-10 at k = 1280, and made the load N′(λ) noisy at the 1e-9 level).
    pub fn hat_averages(&self, m: usize, h: f64) -> Vec<f64> {
        let mi = m as i64;
        let ln_h = h.ln();
        let mut a: Vec<f64> = (-mi..=mi)
            .map(|k| h * (half_second_diff_k2logk(k) + ln_h) - 1.5 * h)
            .collect();
        for t in &self.terms {
            add_term_hat_averages(t, m, h, &mut a);
        }
        a
    }
}

/// Add the hat averages of one term's part (fᵢ/bᵢ)h(bᵢξ) of K to `a` (indexed k + m, k = −m..=m).
pub(crate) fn add_term_hat_averages(t: &CreepTerm, m: usize, h: f64, a: &mut [f64]) {
    add_term_hat_averages_with(t, m, h, a, &kernel_bracket);
}

/// The first |k| where [`add_term_hat_averages`] uses the split form (|kH| ≥ 2; 0 for H ≥ 1).
pub(crate) fn split_from(big_h: f64) -> i64 {
    if big_h >= 1.0 {
        0
    } else {
        (2.0 / big_h).ceil().min(1e18) as i64
    }
}

/// [`add_term_hat_averages`] with h(x) (`kernel_bracket`) evaluated by `bracket` at the points
/// x = kH, |k| ≥ [`split_from`] − 1, of the split form (the contact checks interpolate it).
pub(crate) fn add_term_hat_averages_with(
    t: &CreepTerm,
    m: usize,
    h: f64,
    a: &mut [f64],
    bracket: &dyn Fn(f64) -> f64,
) {
    let mi = m as i64;
    let len = 2 * m + 1;
    let big_h = t.b * h;
    let c = (t.f / t.b) * h;
    if big_h < TINY_H {
        // bh so small that h₂(kH) ~ (kH)³ log would underflow: leading term of the series
        // h₂(x) = (x³/6)(11/6 − γ_E − log|x|) + O(x⁴ log|x|), divided by H² in closed form,
        // S(k) = (H/6)[6k(11/6 − γ_E − log H) − Δ²(k³ log|k|)], relative error O(kH) < 1e-25.
        let l = 11.0 / 6.0 - EULER_GAMMA - big_h.ln();
        for (idx, ak) in a.iter_mut().enumerate() {
            let k = idx as i64 - mi;
            let p = |j: i64| {
                if j == 0 {
                    0.0
                } else {
                    (j as f64).powi(3) * (j.unsigned_abs() as f64).ln()
                }
            };
            let d2 = p(k + 1) - 2.0 * p(k) + p(k - 1);
            *ak += c * (big_h / 6.0) * (6.0 * k as f64 * l - d2);
        }
        return;
    }
    // Values at k = −m−1 ..= m+1 (index k + m + 1), shared by neighbouring k.
    let mut v_h = vec![0.0; len + 2];
    let mut v_h2 = vec![0.0; len + 2];
    // Plain second differences of h₂ where |kH| < 2 (h₂ is small there and has no large
    // pieces), the split form elsewhere (its pieces do not cancel once |x| ≳ 1).
    let split_from = split_from(big_h);
    for (idx, (vh, vh2)) in v_h.iter_mut().zip(v_h2.iter_mut()).enumerate() {
        let k = idx as i64 - mi - 1;
        let x = k as f64 * big_h;
        if k.abs() + 1 >= split_from {
            *vh = bracket(x);
        }
        if k.abs() <= split_from {
            *vh2 = kernel_bracket_int2(x);
        }
    }
    let base = big_h.ln() + EULER_GAMMA - 1.5;
    let inv_h2 = 1.0 / (big_h * big_h);
    for (idx, ak) in a.iter_mut().enumerate() {
        let k = idx as i64 - mi;
        let s = if k.abs() >= split_from {
            let dh = v_h[idx + 2] - 2.0 * v_h[idx + 1] + v_h[idx];
            half_second_diff_k2logk(k) + base + second_diff_klogk(k) / big_h + dh * inv_h2
        } else {
            (v_h2[idx + 2] - 2.0 * v_h2[idx + 1] + v_h2[idx]) * inv_h2
        };
        *ak += c * s;
    }
}

/// x log|x| with the limit 0 at x = 0.
#[cfg(test)]
fn xlogx(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x * x.abs().ln()
    }
}

/// D(k) = ½[(k+1)² log|k+1| − 2k² log|k| + (k−1)² log|k−1|] (0·log 0 = 0), without cancellation:
/// for |k| ≥ 2, D = log|k| + ½[(k²+1) log(1 − 1/k²) + 4|k| artanh(1/|k|)] → log|k| + 3/2.
pub(crate) fn half_second_diff_k2logk(k: i64) -> f64 {
    let k = k.unsigned_abs();
    match k {
        0 => 0.0,
        1 => 2.0 * std::f64::consts::LN_2,
        _ => {
            let kf = k as f64;
            let inv = 1.0 / kf;
            kf.ln() + 0.5 * ((kf * kf + 1.0) * (-inv * inv).ln_1p() + 4.0 * kf * inv.atanh())
        }
    }
}

/// E(k) = (k+1) log|k+1| − 2k log|k| + (k−1) log|k−1| (0·log 0 = 0), odd in k, without cancellation:
/// for |k| ≥ 2, E = k log(1 − 1/k²) + 2 artanh(1/k) ≈ 1/k.
pub(crate) fn second_diff_klogk(k: i64) -> f64 {
    let sign = if k < 0 { -1.0 } else { 1.0 };
    let k = k.unsigned_abs();
    let e = match k {
        0 => 0.0,
        1 => 2.0 * std::f64::consts::LN_2,
        _ => {
            let kf = k as f64;
            let inv = 1.0 / kf;
            kf * (-inv * inv).ln_1p() + 2.0 * inv.atanh()
        }
    };
    sign * e
}

#[cfg(test)]
mod tests {
    //! K, K₁, K₂ and the hat averages against direct numerical quadrature (tanh-sinh on panels in a
    //! logarithmic variable, so scales from 1e-24 to 1e24 are resolved), over b ∈ [1e-12, 1e12] and
    //! |ξ| ∈ [1e-12, 1e12].
    use super::*;

    /// ∫₀¹ φ(u) du by tanh-sinh, φ called with u (computed without cancellation near u = 0, so φ may be
    /// singular there). Step 1/64, |k h| ≤ 4: error ≈ 1e-15 for analytic φ with endpoint singularities.
    fn ts01(phi: &dyn Fn(f64) -> f64) -> f64 {
        ts01_both(&|u, _| phi(u))
    }

    /// As [`ts01`], φ called with u and 1 − u, both without cancellation.
    fn ts01_both(phi: &dyn Fn(f64, f64) -> f64) -> f64 {
        let step = 1.0 / 64.0;
        let mut s = 0.0;
        for k in -256..=256 {
            let t = k as f64 * step;
            let y = std::f64::consts::FRAC_PI_2 * t.sinh();
            let u = 1.0 / (1.0 + (-2.0 * y).exp());
            let um = 1.0 / (1.0 + (2.0 * y).exp());
            let w = std::f64::consts::FRAC_PI_2 * t.cosh() / (2.0 * y.cosh().powi(2));
            if u > 1e-200 && um > 1e-200 && w > 0.0 && w.is_finite() {
                s += w * phi(u, um);
            }
        }
        s * step
    }

    /// Eq. 3.19 per term, minus its ξ-independent part: (1/b)·∫₀^∞ e^(−t) log|1 + x/t| dt with x = bξ
    /// (from ∫e^(−bζ)[log|ξ+ζ| − log ζ]dζ, t = bζ), which is h(x)/b. Quadrature in s = log t on unit
    /// panels from min(log|x|, 0) − 45 to log 60 (tails below 1e-17 relative); the log singularity at
    /// t = −x (x < 0) sits at a panel end.
    fn bracket_by_quadrature(x: f64) -> f64 {
        let f = |s: f64, log_term: f64| (s - s.exp()).exp() * log_term;
        let lo = x.abs().ln().min(0.0) - 45.0;
        let hi = 60f64.ln();
        let mut total = 0.0;
        let mut panel = |a: f64, b: f64| {
            // regular panel: log|1 + x e^(−s)| via ln_1p
            total += (b - a)
                * ts01(&|u| {
                    let s = a + (b - a) * u;
                    f(s, ln_abs_1p(x * (-s).exp()))
                });
        };
        if x > 0.0 {
            let mut a = lo;
            while a < hi {
                panel(a, (a + 1.0).min(hi));
                a += 1.0;
            }
            return total;
        }
        let s0 = (-x).ln();
        // panels left of s0 − 1 and right of s0 + 1 are regular
        let mut a = lo;
        while a < s0 - 1.0 {
            panel(a, (a + 1.0).min(s0 - 1.0));
            a += 1.0;
        }
        let mut a = s0 + 1.0;
        while a < hi {
            panel(a, (a + 1.0).min(hi));
            a += 1.0;
        }
        // singular panels: 1 + x e^(−s) = 1 − e^(s0 − s); s = s0 ∓ u
        total += ts01(&|u| f(s0 - u, u.exp_m1().abs().ln()));
        if s0 < hi {
            total += ts01(&|u| f(s0 + u, (-u).exp_m1().abs().ln()));
        }
        total
    }

    fn ln_abs_1p(y: f64) -> f64 {
        if y > -0.5 && y < 1.0 {
            y.ln_1p()
        } else {
            (1.0 + y).abs().ln()
        }
    }

    const BS: [f64; 7] = [1e-12, 1e-8, 1e-3, 1.0, 1e3, 1e8, 1e12];
    const XIS: [f64; 9] = [1e-12, 1e-8, 1e-4, 0.1, 1.0, 7.0, 1e4, 1e8, 1e12];

    #[test]
    fn kernel_matches_quadrature_of_eq_3_19_over_24_decades() {
        // One term at a time, f chosen so f/b = 1000 (compliance ratio 1000, the worst case for
        // cancellation between log|ξ| and the bracket), and both signs of ξ.
        let mut worst: f64 = 0.0;
        for &b in &BS {
            let f = 1000.0 * b;
            let kernel = Kernel::new(&[CreepTerm { f, b }]).unwrap();
            for &m in &XIS {
                for xi in [m, -m] {
                    let got = kernel.k(xi);
                    let q = bracket_by_quadrature(b * xi);
                    let want = xi.abs().ln() + (f / b) * q;
                    // Scale of the pieces: no cancellation inside K beyond it is allowed. 1e-12: the
                    // quadrature is good to ≈ 1e-14 relative, the closed form to a few ulp.
                    let scale = xi.abs().ln().abs() + (f / b) * q.abs();
                    let err = (got - want).abs() / scale;
                    assert!(got.is_finite(), "K({xi}) not finite for b = {b}");
                    assert!(
                        err < 1e-12,
                        "b = {b}, xi = {xi}: K = {got}, quadrature {want}, rel err {err:e}"
                    );
                    worst = worst.max(err);
                }
            }
        }
        eprintln!("worst relative error of K against quadrature: {worst:.2e}");
        assert!(worst < 1e-12);
    }

    #[test]
    fn antiderivatives_match_quadrature_of_k() {
        // K₁(ξ) = ∫₀^ξ K and K₂(ξ) = ∫₀^ξ K₁ (by quadrature in t = ξe^(−s), s ∈ [0, 80]: the part
        // below ξe^(−80) is < 1e-30 of the result). Two terms spread far apart.
        for &(b1, b2) in &[(1e-12, 1e-3), (1.0, 1e6), (1e3, 1e12)] {
            let kernel = Kernel::new(&[
                CreepTerm {
                    f: 10.0 * b1,
                    b: b1,
                },
                CreepTerm {
                    f: 990.0 * b2,
                    b: b2,
                },
            ])
            .unwrap();
            for &m in &[1e-12, 1e-5, 0.3, 1.0, 50.0, 1e5, 1e12] {
                for xi in [m, -m] {
                    let int = |g: &dyn Fn(f64) -> f64| {
                        let mut s = 0.0;
                        for p in 0..80 {
                            let a = p as f64;
                            s += ts01(&|u| {
                                let e = (-(a + u)).exp();
                                xi * e * g(xi * e)
                            });
                        }
                        s
                    };
                    let k1q = int(&|t| kernel.k(t));
                    let k2q = int(&|t| kernel.k1(t));
                    let (k1, k2) = (kernel.k1(xi), kernel.k2(xi));
                    // Tolerances relative to the size of the integrand's pieces (1e-11: quadrature
                    // error ≈ 1e-14 per panel, 80 panels, plus the tested K's 1e-13).
                    let scale1 = int(&|t| {
                        t.abs().ln().abs() + kernel.sum_f_over_b() * (1.0 + t.abs().ln().abs())
                    })
                    .abs();
                    let scale2 = int(&|t| kernel.k1(t).abs()).abs();
                    assert!(
                        (k1 - k1q).abs() <= 1e-11 * scale1,
                        "K1({xi}) b=({b1},{b2}): {k1} vs {k1q}"
                    );
                    assert!(
                        (k2 - k2q).abs() <= 1e-11 * scale2,
                        "K2({xi}) b=({b1},{b2}): {k2} vs {k2q}"
                    );
                }
            }
        }
    }

    #[test]
    fn hat_averages_match_quadrature() {
        // A(k) = ∫ φ(s) K(kh − s) ds, by tanh-sinh on each half of the hat (the log singularity of K
        // at kh − s = 0 is at a half's end for k ∈ {−1, 0, 1}). Covers H = bh < 1 and ≥ 1.
        for &b in &[1e-9, 0.01, 1.0, 30.0, 1e7] {
            let kernel = Kernel::new(&[CreepTerm { f: 999.0 * b, b }]).unwrap();
            for &h in &[1e-3, 0.05, 2.0] {
                let m = 60;
                let a = kernel.hat_averages(m, h);
                for k in [-60i64, -7, -1, 0, 1, 2, 9, 60] {
                    let xk = k as f64 * h;
                    // left half s = −h(1−u): argument kh − s = h(k + 1 − u); right half s = h(1−u):
                    // h(k − 1 + u); both formed so that a zero argument is exact at the ends.
                    let kf = k as f64;
                    let arg = |c: f64, u: f64, um: f64| match k {
                        0 => h * c * um,
                        _ => h * (kf + c - c * u),
                    };
                    let left = ts01_both(&|u, um| u * kernel.k(arg(1.0, u, um))) * h;
                    let right = ts01_both(&|u, um| u * kernel.k(arg(-1.0, u, um))) * h;
                    let want = left + right;
                    let got = a[(k + m as i64) as usize];
                    // scale: |log| pieces of K near kh; 1e-9 allows the k²ε loss of the plain
                    // second difference for H < 1 (k ≤ 60: 4e-13) with a wide margin.
                    let scale = h * (xk.abs() + h).ln().abs()
                        + h * 999.0 * (1.0 + (b * (xk.abs() + h)).ln().abs());
                    assert!(
                        (got - want).abs() <= 1e-9 * scale,
                        "b={b} h={h} k={k}: {got} vs {want}"
                    );
                }
            }
        }
    }

    #[test]
    fn hat_averages_viscous_part_for_tiny_bh() {
        // bh = 1e-31 (< TINY_H) and 1e-25 (plain branch): one term's part of A(k) on its own (it is
        // ≈ 1e-29 of the elastic part) against quadrature of ∫φ(s)(f/b)h(b(kh − s))ds, to 1e-9
        // relative (series truncation O(kH) ≈ 1e-28; quadrature ≈ 1e-13; Δ²(k³ log k) loses ≈ k²ε).
        for &(b, h) in &[(1e-12, 1e-19), (1e-12, 1e-13)] {
            let f = 999.0 * b;
            let m = 60;
            let mut a = vec![0.0; 2 * m + 1];
            add_term_hat_averages(&CreepTerm { f, b }, m, h, &mut a);
            for k in [-60i64, -3, -1, 0, 1, 2, 60] {
                let kf = k as f64;
                let visc = |x: f64| (f / b) * kernel_bracket(b * x);
                let big_h = b * h;
                let arg = |c: f64, u: f64, um: f64| {
                    if k == 0 {
                        h * c * um
                    } else {
                        h * (kf + c - c * u)
                    }
                };
                let want = (ts01_both(&|u, um| u * visc(arg(1.0, u, um)))
                    + ts01_both(&|u, um| u * visc(arg(-1.0, u, um))))
                    * h;
                let idx = (k + m as i64) as usize;
                let got = a[idx];
                // scale: the k = 1 term, (f/b)·h·H·|log H|; S(0) is O(H²) and only absolutely small.
                let tol = 1e-9 * (want.abs() + (f / b) * h * big_h * big_h.ln().abs());
                assert!(
                    (got - want).abs() <= tol,
                    "b={b} h={h} k={k}: {got:e} vs {want:e}"
                );
            }
        }
    }

    #[test]
    fn integer_second_differences() {
        for k in -40i64..=40 {
            let p = |j: i64| {
                if j == 0 {
                    0.0
                } else {
                    (j as f64) * (j as f64) * (j.abs() as f64).ln()
                }
            };
            let q = |j: i64| {
                if j == 0 {
                    0.0
                } else {
                    (j as f64) * (j.abs() as f64).ln()
                }
            };
            let d = 0.5 * (p(k + 1) - 2.0 * p(k) + p(k - 1));
            let e = q(k + 1) - 2.0 * q(k) + q(k - 1);
            // direct forms lose ≈ k² ε; 1e-12 relative covers k ≤ 40.
            assert!(
                (half_second_diff_k2logk(k) - d).abs() <= 1e-12 * d.abs().max(1.0),
                "D({k})"
            );
            assert!((second_diff_klogk(k) - e).abs() <= 1e-12, "E({k})");
        }
    }

    #[test]
    fn rejects_bad_terms() {
        assert!(Kernel::new(&[CreepTerm { f: -1.0, b: 1.0 }]).is_err());
        assert!(Kernel::new(&[CreepTerm { f: 1.0, b: 0.0 }]).is_err());
        assert!(Kernel::new(&[CreepTerm {
            f: f64::NAN,
            b: 1.0
        }])
        .is_err());
        assert_eq!(
            Kernel::new(&[CreepTerm { f: 0.0, b: 1.0 }])
                .unwrap()
                .terms()
                .len(),
            0
        );
    }
}
