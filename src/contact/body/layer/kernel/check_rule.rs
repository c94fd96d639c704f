//! The layer kernel's hat averages for the contact checks: the same A(j) = A_HS(j) − A_D(j) as
//! [`LayerKernel::hat_averages`] (module doc of [`super`]), to ~1e−9 of the largest difference
//! A(j) − A(0) instead of rounding, on a third to a quarter of the correction's quadrature nodes.
//!
//! Input: m and Δ (offsets j = −m…m); output: A(j) up to one constant, for
//! [`crate::contact::body::layer::collocation::contact_checks`] (the closing checks of the spectral
//! and the hat-scheme layer solves; their thresholds are 1e−3 of the indentation, so ~1e−6 of the
//! kernel is ample).
//!
//! # The correction's rule
//! A_D(j) = −∫₀^∞ (R(kh′)/k)·Re[Φ(k)·Δ·(sinc²(kΔ/2)e^{ikjΔ} − 1)] dk (eq. A_D of the parent module
//! doc; X = (m+1)Δ the largest |x| = |jΔ|, s = 1 + Σrᵢ = Φ(0) = J∞/J_g, rᵢ = fᵢ/bᵢ).
//!
//! - **Lower cut from a bound (C1).** With z = sinc²e^{ikx} − 1 = (e^{ikx} − 1) + (sinc² − 1)e^{ikx},
//!   |Re Φz| ≤ Im Φ·k|x| + Re Φ·k²x²/2 + |Φ|·k²Δ²/12, R ≤ 1, |Φ| ≤ s, and
//!   ∫₀^{k₀} Im Φ dk = Σ(fᵢ/2)ln(1 + k₀²/bᵢ²) ≤ k₀Σrᵢ/2 (ln(1 + y²) ≤ y), so the part below k₀ is at
//!   most Δ·s·(y/2 + 7y²/24), y = k₀X. The rule cuts at k₀ = 1e−12/(sX): ≤ 1e−12·Δ, far below the
//!   differences A(j) − A(0) ≳ Δ. The collocation rule's cut 1e−8·min(bᵢ, 1/X, 1/h′) reaches
//!   k ≈ 1e−20 on a spectrum down to b = 1e−12: 12 decades of nodes that carry nothing.
//! - **Low region (C2)**, k ∈ [k₀, k_mid], k_mid = min(1/X, k_hi): 14-point Gauss–Legendre panels of
//!   width 2 in v = ln k (the layer term's rule, `spectral::layer_term`): the poles of Φ at −ibᵢ lie
//!   π/2 off the real v axis, e^{ikx} with kX ≤ 1 is entire, so the ellipse parameter for the
//!   half-width 1 is π/2 + √(π²/4 + 1) ≈ 3.4 and the error ≲ 3.4^{−28} ≈ 1e−15 of a panel's part
//!   (R's complex singularities at |k| ~ 1/h′ fall here for thick covers; measured in the test).
//! - **Linear region (C3)**, k ∈ [k_mid, k_hi], k_hi = 20/h′ (R(20) ≈ (4·20²/κ)e^{−40} ≤ 7e−15;
//!   the tail beyond is ≤ 2Δ·s·R(20)/40): 16-point panels of width ≤ min(8/X, 1/h′), i.e. at most
//!   eight radians of e^{ikx} (Gauss error for e^{iωu}, ω = 4, on 16 points: (eω/32)^{32} ≈ 1e−15)
//!   and half-width ½ in t = kh′ against R's singularities at |Im t| ≳ ½ (ellipse ≥ 1 + √2,
//!   2.4^{−32} ≈ 6e−13). The poles of slow modes near k = 0 lie beyond the first panel's end k_mid:
//!   ellipse ≥ 2, ~2e−10 of their part.
//!
//! Measured against the collocation rule (test `check_rule_matches_the_collocation_rule` of the
//! parent module): ≤ 1e−8 of the largest difference allowed. The half-space part is the exact
//! [`crate::contact::half_space::kernel::Kernel::hat_averages`] (closed forms).

use super::LayerKernel;
use crate::contact::body::layer::compliance::layer_defect;
use crate::special::gauss_legendre::gauss_legendre;

/// R(t) ≤ 7e−15 beyond t = kh′ = 20 (C3).
const T_CHECK: f64 = 20.0;
/// Bound of the neglected low part relative to Δ (C1).
const LOW_CUT: f64 = 1e-12;

impl LayerKernel {
    /// [`Self::hat_averages`] to ~1e−9 of the largest difference for the contact checks (module
    /// doc of [`check_rule`](self)), j = −m…m (index j + m), up to one constant.
    pub fn check_hat_averages(&self, m: usize, delta: f64) -> Vec<f64> {
        let mut a = self.half_space.hat_averages(m, delta);
        let x_max = (m as f64 + 1.0) * delta;
        let d = self.correction_on(m, delta, &self.check_nodes(x_max));
        for (x, y) in a.iter_mut().zip(d) {
            *x -= y;
        }
        a
    }

    /// Quadrature nodes (k, weight·R(kh′)/k, low region?) of rules C1–C3 (module doc).
    fn check_nodes(&self, x_max: f64) -> Vec<(f64, f64, bool)> {
        let h = self.thickness;
        let k_hi = T_CHECK / h;
        let k_mid = (1.0 / x_max).min(k_hi);
        let s = 1.0 + self.terms.iter().map(|t| t.f / t.b).sum::<f64>();
        let k_lo = (LOW_CUT / (s * x_max)).min(0.5 * k_mid);
        let mut out = Vec::new();
        let mut panels = |a: f64, b: f64, width: f64, points: usize, log: bool| {
            let (gx, gw) = gauss_legendre(points);
            let np = ((b - a) / width).ceil().max(1.0) as usize;
            for p in 0..np {
                let lo = a + (b - a) * p as f64 / np as f64;
                let hi = a + (b - a) * (p + 1) as f64 / np as f64;
                let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
                for (x, w) in gx.iter().zip(&gw) {
                    let u = mid + half * x;
                    let (k, dk) = if log {
                        (u.exp(), u.exp() * half * w)
                    } else {
                        (u, half * w)
                    };
                    out.push((k, dk * layer_defect(k * h, self.poisson) / k, log));
                }
            }
        };
        panels(k_lo.ln(), k_mid.ln(), 2.0, 14, true);
        if k_hi > k_mid {
            panels(k_mid, k_hi, (8.0 / x_max).min(1.0 / h), 16, false);
        }
        out
    }
}
