//! The steady-rolling kernel of a viscoelastic layer bonded to a rigid base: the half-space kernel of
//! thesis eq. 3.19 (`Kernel`) plus a smooth correction computed in Fourier space.
//!
//! Input: creep terms (fᵢ, bᵢ), the dimensionless thickness h′ = h/(VT) and ν; output: the hat-function
//! averages A(j) = ∫φ(s)K_L(jΔ − s)ds that are the matrix entries of the collocation scheme
//! ([`super::collocation`]), for j = −m…m.
//!
//! # Viscoelastic steady-rolling form
//! Thesis eq. 3.6 / 3.16: a material point now at ξ was at ξ + ζ a time ζ (units of T) ago, so
//! the deflection is ρv(ξ) = ∫G_e(ξ−ξ′)Q′(ξ′)dξ′ + ∫₀^∞γ(ζ)∫G_e(ξ+ζ−ξ′)Q′(ξ′)dξ′dζ. With the
//! transform Ĝ(k) = ∫G(x)e^{−ikx}dx the shift ξ + ζ gives e^{+ikζ}, hence (correspondence principle,
//! ν constant)
//!
//! ```text
//!   Ĝ(k) = Ĝ_e(k)·Φ(k),     Φ(k) = 1 + ∫₀^∞γ(ζ)e^{ikζ}dζ = 1 + Σᵢ fᵢ/(bᵢ − ik),
//! ```
//!
//! with Ĝ_e = π/|k| for the half-space (G_e = −log|ξ|, so the thesis' K = −G up to a constant) and
//! Ĝ_e = π·F(|k|h′)/|k| for the layer ([`super::compliance`]). Checks of the sign: Φ(0) = 1 + Σfᵢ/bᵢ
//! = J∞/J_g (the relaxed compliance at wavelengths much longer than V·τ); the same factor applied to
//! a Winkler column gives the closed form of [`super::winkler`] derived in real space (memory of the
//! material that has passed under the front part of the contact), and the thin-layer test compares
//! the two (a wrong sign of ik reverses the asymmetry and the friction changes sign).
//!
//! # The correction
//! K_L = K_HS − D with D̂(k) = −π·R(|k|h′)·Φ(k)/|k|, R = 1 − F ≥ 0. R decays like e^{−2|k|h′}, so D is
//! a C^∞ function (its transform decays exponentially) and the log singularity of K_L is exactly the
//! half-space's, which `Kernel` integrates in closed form. The hat average of
//! e^{ikx} is Δ·sinc²(kΔ/2)·e^{ikx}, so (constants do not matter: the scheme uses differences of A)
//!
//! ```text
//!   A_D(j) = −∫₀^∞ (R(kh′)/k)·Re[Φ(k)·Δ·(sinc²(kΔ/2)e^{ikjΔ} − 1)] dk,
//! ```
//!
//! the "−1" making the integral converge at k = 0 (it adds the j-independent constant −ΔD(0)); for
//! k ≥ 1/X (X = (m+1)Δ, the largest |x| needed) it is dropped again, which only changes that constant.
//!
//! # Quadrature and why it converges
//! The integrand is analytic in k on [0, ∞) except at k = 0, where it behaves like k·(const) (the −1
//! makes (e^{ikx}−1)/k finite). Its scales: the creep rates (Φ has poles at k = −ibᵢ), 1/h′ (R), and
//! the oscillation e^{ikx} with |x| ≤ X. We integrate
//! - on k ∈ [k_lo, k_mid], k_mid = min(1/X, k_hi), in v = ln k with 10-point Gauss–Legendre panels of
//!   width ≤ ½ in v: each pole −ibᵢ lies at distance ≥ 1 in |Im v| (arg), so each panel's Bernstein
//!   ellipse parameter is ≥ 4 + 2 and the error ≲ 6^{−20} per panel; below k_lo = 1e−8·min(bᵢ, 1/X)
//!   the integrand is O(k²) in v and the neglected part ≲ 1e−16 relative;
//! - on k ∈ [k_mid, k_hi] in k with 10-point panels of width ≤ min(1/X, 1/(2h′)) (at most one radian
//!   of e^{ikx}, and the nearest complex zeros of the denominator of R lie ≥ 1/(2h′)·O(1) away);
//!   k_hi = 27/h′ where R < 1e−20.
//!
//! The contact checks (`LayerKernel::check_hat_averages`) only need the kernel to ~1e−6 (their
//! thresholds are 1e−3): they use a cheaper rule of their own (module [`check_rule`]).
//!
//! Errors are therefore exponentially small in the number of nodes per panel (Trefethen, *Approximation
//! Theory and Approximation Practice*, SIAM 2013, ch. 19) and the test against a finer rule agrees to
//! rounding. Cost: O((2m+1)·(panels·10)), about (2m+1)·(300 + 270·X/h′) operations: cheap for layers
//! thicker than ~λ/20, growing like 1/h′ for thinner ones (where the Winkler / h³ limits apply).

pub(crate) mod check_rule;

use super::compliance::layer_defect;
use crate::contact::error::{positive, ContactError};
use crate::contact::numerics::kernel::Kernel;
use crate::contact::problem::CreepTerm;
use crate::special::gauss_legendre::gauss_legendre;

/// Gauss–Legendre order of each panel.
const GL_ORDER: usize = 10;
/// R(t) < 1e−20 beyond this t = kh′.
const T_MAX: f64 = 27.0;

/// Kernel of a viscoelastic layer bonded to a rigid base.
#[derive(Debug, Clone)]
pub struct LayerKernel {
    half_space: Kernel,
    terms: Vec<CreepTerm>,
    thickness: f64,
    poisson: f64,
}

impl LayerKernel {
    /// A layer of dimensionless thickness `thickness` = h/(VT) > 0 and Poisson's ratio in [0, ½].
    pub fn new(terms: &[CreepTerm], thickness: f64, poisson: f64) -> Result<Self, ContactError> {
        let half_space = Kernel::new(terms)?;
        positive("layer thickness h/(VT)", thickness)?;
        if !(poisson.is_finite() && (0.0..=0.5).contains(&poisson)) {
            return Err(ContactError::BadValue {
                field: "poisson".into(),
                expected: "in [0, 0.5]",
                value: poisson,
            });
        }
        Ok(Self {
            terms: half_space.terms().to_vec(),
            half_space,
            thickness,
            poisson,
        })
    }

    /// The half-space kernel this one corrects.
    pub fn half_space(&self) -> &Kernel {
        &self.half_space
    }

    /// Dimensionless thickness h′.
    pub fn thickness(&self) -> f64 {
        self.thickness
    }

    /// Poisson's ratio.
    pub fn poisson(&self) -> f64 {
        self.poisson
    }

    /// Φ(k) = 1 + Σ fᵢ/(bᵢ − ik) as (Re, Im).
    fn phi(&self, k: f64) -> (f64, f64) {
        let (mut re, mut im) = (1.0, 0.0);
        for t in &self.terms {
            let d = t.b * t.b + k * k;
            re += t.f * t.b / d;
            im += t.f * k / d;
        }
        (re, im)
    }

    /// Quadrature nodes (k, weight·R(kh′)/k) and whether the node is in the low (log) region; the
    /// linear panels span at most `radians` of e^{ikx} at |x| = `x_max` (module doc).
    fn nodes(&self, x_max: f64, radians: f64) -> Vec<(f64, f64, bool)> {
        let (gx, gw) = gauss_legendre(GL_ORDER);
        let h = self.thickness;
        let k_hi = T_MAX / h;
        let k_mid = (1.0 / x_max).min(k_hi);
        let b_min = self.terms.iter().map(|t| t.b).fold(f64::INFINITY, f64::min);
        let k_lo = 1e-8 * b_min.min(1.0 / x_max).min(1.0 / h);
        let mut out = Vec::new();
        let push_panel = |a: f64, b: f64, log: bool, out: &mut Vec<(f64, f64, bool)>| {
            let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
            for (x, w) in gx.iter().zip(&gw) {
                let u = mid + half * x;
                let (k, dk) = if log {
                    (u.exp(), u.exp() * half * w)
                } else {
                    (u, half * w)
                };
                out.push((k, dk * layer_defect(k * h, self.poisson) / k, log));
            }
        };
        // Log region.
        let (va, vb) = (k_lo.ln(), k_mid.ln());
        let np = ((vb - va) / 0.5).ceil().max(1.0) as usize;
        for p in 0..np {
            let a = va + (vb - va) * p as f64 / np as f64;
            let b = va + (vb - va) * (p + 1) as f64 / np as f64;
            push_panel(a, b, true, &mut out);
        }
        // Linear region.
        if k_hi > k_mid {
            let width = (radians / x_max).min(0.5 / h);
            let np = ((k_hi - k_mid) / width).ceil().max(1.0) as usize;
            for p in 0..np {
                let a = k_mid + (k_hi - k_mid) * p as f64 / np as f64;
                let b = k_mid + (k_hi - k_mid) * (p + 1) as f64 / np as f64;
                push_panel(a, b, false, &mut out);
            }
        }
        out
    }

    /// The correction's hat averages A_D(j), j = −m…m (index j + m), up to one constant.
    pub fn correction_hat_averages(&self, m: usize, delta: f64) -> Vec<f64> {
        let x_max = (m as f64 + 1.0) * delta;
        self.correction_on(m, delta, &self.nodes(x_max, 1.0))
    }

    /// The correction's hat averages A_D(j), j = −m…m, on the quadrature `nodes` (k, weight·R/k,
    /// whether k lies in the low region where the "−1" of the module doc is kept).
    fn correction_on(&self, m: usize, delta: f64, nodes: &[(f64, f64, bool)]) -> Vec<f64> {
        let mut a = vec![0.0; 2 * m + 1];
        for &(k, w, log) in nodes {
            let (pr, pi) = self.phi(k);
            let u = 0.5 * k * delta;
            let sinc = if u < 1e-4 {
                1.0 - u * u / 6.0
            } else {
                u.sin() / u
            };
            let s2 = sinc * sinc;
            // s² − 1 without cancellation: (sinc − 1)(sinc + 1), sinc − 1 = −u²/6 + u⁴/120 − …
            let s2m1 = if u < 1e-2 {
                let sm1 = -u * u / 6.0 + u.powi(4) / 120.0;
                sm1 * (sinc + 1.0)
            } else {
                s2 - 1.0
            };
            let c = -w * delta;
            if log {
                // z_j = e^{ijkΔ} − 1 by the recurrence z_{j+1} = z_j·e^{ikΔ} + (e^{ikΔ} − 1), whose
                // terms do not cancel (no trigonometric call per j; kX ≤ 1 here).
                let (rs, rc) = (k * delta).sin_cos();
                let sh = (0.5 * k * delta).sin();
                let (er, ei) = (-2.0 * sh * sh, rs); // e^{ikΔ} − 1
                let (mut zr, mut zi) = (0.0_f64, 0.0_f64);
                for j in 0..=m {
                    // s²e^{iθ} − 1 = (s² − 1)(1 + z) + z
                    let re = s2m1 * (1.0 + zr) + zr;
                    let im = s2m1 * zi + zi;
                    a[m + j] += c * (pr * re - pi * im);
                    if j > 0 {
                        a[m - j] += c * (pr * re + pi * im);
                    }
                    let nr = zr * rc - zi * rs + er;
                    zi = zr * rs + zi * rc + ei;
                    zr = nr;
                }
            } else {
                let (rs, rc) = (k * delta).sin_cos();
                let (mut s, mut co) = (0.0_f64, 1.0_f64);
                for j in 0..=m {
                    let re = s2 * co;
                    let im = s2 * s;
                    a[m + j] += c * (pr * re - pi * im);
                    if j > 0 {
                        a[m - j] += c * (pr * re + pi * im);
                    }
                    let ns = s * rc + co * rs;
                    co = co * rc - s * rs;
                    s = ns;
                }
            }
        }
        a
    }

    /// Hat averages of the layer kernel K_L = K_HS − D, j = −m…m (index j + m), up to one constant.
    pub fn hat_averages(&self, m: usize, delta: f64) -> Vec<f64> {
        let mut a = self.half_space.hat_averages(m, delta);
        let d = self.correction_hat_averages(m, delta);
        for (x, y) in a.iter_mut().zip(d) {
            *x -= y;
        }
        a
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn check_rule_matches_the_collocation_rule() {
        // The check's rule (module `check_rule`: lower cut from a bound, 14-point panels of width 2
        // in ln k, 16-point linear panels of up to eight radians, k ≤ 20/h′) against the
        // collocation's: differences A(j) − A(0) (the constant is free) relative to the largest, on
        // thin and thick covers, ν = 0…½, one term, 12 terms and 30 terms over 24 decades.
        // Measured: ≤ 5.2e−11 with the half-space part summed by class (3.4e−11 without; the former
        // four-radian rule: 1.1e−9); 1e−8 allowed, five orders
        // inside the checks' thresholds of 1e−3.
        let spectra: Vec<Vec<CreepTerm>> = vec![
            vec![CreepTerm { f: 10.0, b: 1.0 }],
            (0..12)
                .map(|k| {
                    let b = 10f64.powf(-6.0 + k as f64);
                    CreepTerm { f: 30.0 * b, b }
                })
                .collect(),
            super::super::spectral::spread_terms(30, 24.0),
        ];
        let mut worst = 0.0_f64;
        for terms in &spectra {
            for (h, nu) in [(0.05, 0.5), (0.2, 0.0), (1.0, 0.3), (10.0, 0.5)] {
                let k = LayerKernel::new(terms, h, nu).unwrap();
                let (m, delta) = (96, 1.0 / 64.0);
                let fine = k.hat_averages(m, delta);
                let fast = k.check_hat_averages(m, delta);
                let big = fine.iter().fold(0.0_f64, |a, v| a.max((v - fine[m]).abs()));
                for (a, b) in fine.iter().zip(&fast) {
                    let d = (a - fine[m]) - (b - fast[m]);
                    worst = worst.max(d.abs() / big);
                    assert!(d.abs() <= 1e-8 * big, "h {h}: {d:e} of {big:e}");
                }
            }
        }
        println!("worst difference / largest: {worst:.1e}");
    }
}
