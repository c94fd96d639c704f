//! Retardation modes of the `auto` scheme: the characteristic rates κⱼ of the contact problem.
//!
//! Input: creep terms fᵢe^(−bᵢζ) ([`CreepTerm`]); output: [`Modes`] (terms sorted by bᵢ, equal bᵢ
//! merged, and the roots κⱼ).
//!
//! Math (derived for this scheme, docs/MATH.md §7; §3 gives the one-term case): differentiating eq. 3.25 gives
//! H(ξ) + Σᵢ Vᵢ(ξ) = ξ − β on the contact, with H the finite Hilbert transform of Q′ and
//! Vᵢ(ξ) = fᵢ∫₀^∞e^(−bᵢζ)H(ξ+ζ)dζ, so Vᵢ′ = bᵢVᵢ − fᵢH. A solution e^{κξ} of the homogeneous system
//! needs 1 + Σᵢ fᵢ/(bᵢ − κ) = 0 (the relaxation rates of the material in units of 1/T). The left side
//! rises from −∞ to +∞ between consecutive poles bᵢ and from −∞ to 1 beyond the last, so there is
//! exactly one root κⱼ in (bⱼ, bⱼ₊₁) and one in (b_N, b_N + Σf]: N real roots. We store
//! δⱼ = κⱼ − bⱼ so that bᵢ − κⱼ = (bᵢ − bⱼ) − δⱼ keeps its digits when fⱼ ≪ bⱼ. For one term κ = b + f.

use crate::contact::problem::CreepTerm;

/// Sorted, merged creep terms and their characteristic roots.
#[derive(Debug, Clone, PartialEq)]
pub struct Modes {
    /// fᵢ, sorted by bᵢ.
    pub f: Vec<f64>,
    /// bᵢ, strictly increasing.
    pub b: Vec<f64>,
    /// δⱼ = κⱼ − bⱼ > 0.
    pub delta: Vec<f64>,
}

impl Modes {
    /// Sort, merge equal rates (relative difference < 1e−12: their sum is the same exponential),
    /// drop fᵢ = 0 terms and solve for the roots.
    pub fn new(terms: &[CreepTerm]) -> Modes {
        let mut t: Vec<CreepTerm> = terms.iter().copied().filter(|t| t.f > 0.0).collect();
        t.sort_by(|a, b| a.b.total_cmp(&b.b));
        let mut f: Vec<f64> = Vec::with_capacity(t.len());
        let mut b: Vec<f64> = Vec::with_capacity(t.len());
        for term in t {
            match b.last() {
                Some(&last) if (term.b - last).abs() <= 1e-12 * last => {
                    *f.last_mut().unwrap() += term.f;
                }
                _ => {
                    f.push(term.f);
                    b.push(term.b);
                }
            }
        }
        let delta = (0..b.len()).map(|j| root_offset(&f, &b, j)).collect();
        Modes { f, b, delta }
    }

    /// Number of terms.
    pub fn len(&self) -> usize {
        self.b.len()
    }

    /// κⱼ = bⱼ + δⱼ.
    pub(crate) fn kappa(&self, j: usize) -> f64 {
        self.b[j] + self.delta[j]
    }

    /// bᵢ − κⱼ without cancellation.
    pub(crate) fn b_minus_kappa(&self, i: usize, j: usize) -> f64 {
        (self.b[i] - self.b[j]) - self.delta[j]
    }

    /// S = 1 + Σ fᵢ/bᵢ = J∞/J_g, the relaxed-to-glassy compliance ratio.
    pub(crate) fn compliance_ratio(&self) -> f64 {
        1.0 + self.f.iter().zip(&self.b).map(|(f, b)| f / b).sum::<f64>()
    }
}

/// Root δ ∈ (0, gap) of φ(δ) = 1 + Σ_{i≠j} fᵢ/((bᵢ − bⱼ) − δ) − fⱼ/δ (increasing in δ): Newton
/// steps from δ₀ = fⱼ/(1 + Σ_{i≠j} fᵢ/(bᵢ − bⱼ)) (the root when δ ≪ every gap) inside a bracket that
/// every evaluation shrinks, with a bisection step (geometric while the bracket spans more than a
/// factor 2) whenever Newton leaves the bracket or stalls; to full precision.
fn root_offset(f: &[f64], b: &[f64], j: usize) -> f64 {
    // φ and φ′ = fⱼ/δ² + Σ_{i≠j} fᵢ/((bᵢ − bⱼ) − δ)²
    let phi = |d: f64| -> (f64, f64) {
        let mut s = 1.0 - f[j] / d;
        let mut ds = f[j] / (d * d);
        for i in 0..b.len() {
            if i != j {
                let g = (b[i] - b[j]) - d;
                s += f[i] / g;
                ds += f[i] / (g * g);
            }
        }
        (s, ds)
    };
    let mut lo = 0.0_f64;
    let mut hi = if j + 1 < b.len() {
        b[j + 1] - b[j]
    } else {
        f.iter().sum::<f64>() // φ(hi) ≥ 0 for the last root (module doc)
    };
    let denom = 1.0
        + (0..b.len())
            .filter(|&i| i != j)
            .map(|i| f[i] / (b[i] - b[j]))
            .sum::<f64>();
    let mut d = if denom > 0.0 { f[j] / denom } else { 0.5 * hi };
    if !(d > lo && d < hi) {
        d = 0.5 * hi;
    }
    let mut prev_step = f64::INFINITY;
    for _ in 0..2000 {
        let (v, dv) = phi(d);
        if v == 0.0 {
            return d;
        }
        if v < 0.0 {
            lo = d;
        } else {
            hi = d;
        }
        let newton = d - v / dv;
        let step = (newton - d).abs();
        if step <= 2.0 * f64::EPSILON * d && newton > lo && newton < hi {
            return newton;
        }
        let next = if newton > lo && newton < hi && dv.is_finite() && step < 0.5 * prev_step {
            prev_step = step;
            newton
        } else {
            prev_step = f64::INFINITY;
            if lo > 0.0 && hi > 2.0 * lo {
                (lo * hi).sqrt()
            } else if lo == 0.0 && hi > 1e-300 {
                hi * 1e-3 // φ → −∞ as δ → 0⁺: shrink towards 0 geometrically
            } else {
                0.5 * (lo + hi)
            }
        };
        if next <= lo || next >= hi || next == d {
            return d; // the bracket is down to adjacent doubles
        }
        d = next;
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_term_root_is_b_plus_f() {
        let m = Modes::new(&[CreepTerm { f: 10.0, b: 1.0 }]);
        assert!((m.kappa(0) - 11.0).abs() < 1e-14 * 11.0);
    }

    #[test]
    fn roots_solve_the_characteristic_equation() {
        let terms: Vec<CreepTerm> = (0..12)
            .map(|k| CreepTerm {
                f: 10f64.powi(k - 5) * 3.0,
                b: 10f64.powi(2 * k - 11),
            })
            .collect();
        let m = Modes::new(&terms);
        for j in 0..m.len() {
            assert!(m.kappa(j) > m.b[j]);
            if j + 1 < m.len() {
                assert!(m.kappa(j) < m.b[j + 1]);
            }
            // residual relative to the largest term of the sum: a few ulp per term
            let mut s = 1.0;
            let mut scale: f64 = 1.0;
            for i in 0..m.len() {
                let t = m.f[i] / m.b_minus_kappa(i, j);
                s += t;
                scale = scale.max(t.abs());
            }
            assert!(
                s.abs() < 1e-13 * scale,
                "root {j}: residual {s}, scale {scale}"
            );
        }
    }
}
