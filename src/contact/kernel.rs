//! The kernel K(ξ) of the steady rolling problem (thesis eq. 3.19) and its first two antiderivatives,
//! for the creep function γ(ζ) = Σᵢ fᵢ e^(−bᵢζ) (eq. 3.7).
//!
//! Input: the creep terms [`CreepTerm`] (fᵢ ≥ 0, bᵢ > 0); output: K, K₁ = ∫₀^ξ K, K₂ = ∫₀^ξ K₁ and the
//! hat-function averages of K that are the matrix entries of the thesis scheme ([`Kernel::hat_average`]).
//!
//! Math (MATH.md §2). Per term, ∫₀^∞ e^(−bζ) log|ξ+ζ| dζ = (log|ξ| − log b + g(bξ))/b with
//! g(x) = eˣE1(x) (x > 0), −eˣEi(−x) (x < 0). Constants cancel in eq. 3.25 (the kernel enters only as
//! K(−ξ′) − K(ξ−ξ′)), so we add (fᵢ/bᵢ)(2 log bᵢ + γ_E) per term and use
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

use super::error::{non_negative, positive, ContactError};
use super::CreepTerm;
use crate::special::{kernel_bracket, kernel_bracket_int1, kernel_bracket_int2, EULER_GAMMA};

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
    pub fn k(&self, xi: f64) -> f64 {
        let mut s = xi.abs().ln();
        for t in &self.terms {
            s += (t.f / t.b) * kernel_bracket(t.b * xi);
        }
        s
    }

    /// K₁(ξ) = ∫₀^ξ K = ξ(log|ξ| − 1) + Σ (fᵢ/bᵢ²) h₁(bᵢξ).
    pub fn k1(&self, xi: f64) -> f64 {
        let mut s = xlogx(xi) - xi;
        for t in &self.terms {
            s += (t.f / (t.b * t.b)) * kernel_bracket_int1(t.b * xi);
        }
        s
    }

    /// K₂(ξ) = ∫₀^ξ K₁ = ξ² log|ξ|/2 − 3ξ²/4 + Σ (fᵢ/bᵢ³) h₂(bᵢξ).
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
    /// (the Toeplitz structure of the thesis scheme on a uniform grid, MATH.md §2).
    ///
    /// The logarithmic part is summed in closed form without cancellation:
    /// (1/h)Δ²[ξ²log|ξ|/2] = h(D(k) + log h) with D(k) = ½Δ²[k² log|k|] (see [`half_second_diff_k2logk`]).
    /// Per term with H = bh: (fᵢ/bᵢ³)(1/h)Δ²h₂ = (fᵢ/bᵢ)·h·S(k), S(k) = Δ²h₂(kH)/H². For H < 1 S is the plain
    /// second difference (|h₂| ≲ (kH)² log so the relative loss is at most k² ε, ~1e-10 at k = 1280); for
    /// H ≥ 1 the closed form of h₂ splits S into D(k) + log H + γ_E − 3/2 + E(k)/H + Δ²h(kH)/H² with
    /// E(k) = Δ²[k log|k|], each piece cancellation-free.
    pub fn hat_averages(&self, m: usize, h: f64) -> Vec<f64> {
        let mi = m as i64;
        let len = 2 * m + 1;
        let ln_h = h.ln();
        let mut a: Vec<f64> = (-mi..=mi)
            .map(|k| h * (half_second_diff_k2logk(k) + ln_h) - 1.5 * h)
            .collect();
        // Values at k = −m−1 ..= m+1 (index k + m + 1), shared by neighbouring k.
        let mut vals = vec![0.0; len + 2];
        for t in &self.terms {
            let big_h = t.b * h;
            let c = (t.f / t.b) * h;
            if big_h < 1.0 {
                for (idx, v) in vals.iter_mut().enumerate() {
                    let k = idx as i64 - mi - 1;
                    *v = kernel_bracket_int2(k as f64 * big_h);
                }
                let inv_h2 = 1.0 / (big_h * big_h);
                for (idx, ak) in a.iter_mut().enumerate() {
                    let s = (vals[idx + 2] - 2.0 * vals[idx + 1] + vals[idx]) * inv_h2;
                    *ak += c * s;
                }
            } else {
                for (idx, v) in vals.iter_mut().enumerate() {
                    let k = idx as i64 - mi - 1;
                    *v = kernel_bracket(k as f64 * big_h);
                }
                let base = big_h.ln() + EULER_GAMMA - 1.5;
                for (idx, ak) in a.iter_mut().enumerate() {
                    let k = idx as i64 - mi;
                    let dh = vals[idx + 2] - 2.0 * vals[idx + 1] + vals[idx];
                    let s = half_second_diff_k2logk(k)
                        + base
                        + second_diff_klogk(k) / big_h
                        + dh / (big_h * big_h);
                    *ak += c * s;
                }
            }
        }
        a
    }
}

/// x log|x| with the limit 0 at x = 0.
fn xlogx(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x * x.abs().ln()
    }
}

/// D(k) = ½[(k+1)² log|k+1| − 2k² log|k| + (k−1)² log|k−1|] (0·log 0 = 0), without cancellation:
/// for |k| ≥ 2, D = log|k| + ½[(k²+1) log(1 − 1/k²) + 4|k| artanh(1/|k|)] → log|k| + 3/2.
pub fn half_second_diff_k2logk(k: i64) -> f64 {
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
pub fn second_diff_klogk(k: i64) -> f64 {
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
