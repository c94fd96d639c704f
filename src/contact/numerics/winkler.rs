//! A viscoelastic Winkler foundation in steady rolling, in closed form for any creep spectrum and any
//! coefficient c_W, and the coefficients of its two kinds of columns: shared below the bodies by the
//! Winkler body (`body/winkler/`), the bonded layer (its thin compressible limit, `body/layer/`) and
//! the test-only cover on springs (`body/on_springs/`).
//!
//! Input: creep terms (fᵢ, bᵢ), the coefficient c_W of ρ·v = c_W·Q′ (any c_W > 0, or
//! [`winkler_coefficient`] of columns in uniaxial stress, the conveyor tools' model, or constrained
//! ones, the thin compressible layer), and λ or N′; output: a [`DimensionlessSolution`] (scheme
//! `winkler`) with its contact checks ([`WinklerAnswer`]).
//!
//! # The coefficient of the columns
//! In the thesis' units (§3.2: lengths in V·T, Q′ = (R/VT)·C·q/π with C = (1−ν)/μ₀) the half-space's
//! scaled deflection ρ·v has the Fourier multiplier π/|k| (the transform of −log|ξ|). A Winkler
//! foundation of columns of height h′ = h/(VT) and modulus M_c, ρ·v = c_W·Q′, has c_W = π·h′/(M_c·C):
//! c_W = π·h′(1−2ν)/(2(1−ν)²) for columns in constrained compression (M = 2μ(1−ν)/(1−2ν), the
//! thin-layer limit of the bonded layer for ν < ½, `body/layer/compliance.rs`) and
//! c_W = π·h′/(2(1−ν²)) for the uniaxial columns of conveyor design tools (E = 2μ(1+ν); Jonkers 1980;
//! Rudolphi & Reicks 2006).
//!
//! # Derivation
//! Each column creeps under its own pressure only: by thesis eq. 3.6 (memory of the material that
//! passed under the load earlier, at ξ + ζ) ρv(ξ) = c_W[Q′(ξ) + Σᵢfᵢ∫₀^∞e^{−bᵢζ}Q′(ξ+ζ)dζ], i.e. the
//! multiplier c_W·Φ(k) with Φ = 1 + Σfᵢ/(bᵢ − ik) (the factor of the bonded layer's kernel,
//! `body/layer/kernel.rs`). Its inverse (the relaxation
//! form) is 1/Φ = 1 + Σⱼ rⱼ/(κⱼ − ik) with κⱼ the zeros of Φ (the roots of 1 + Σfᵢ/(bᵢ − κ) = 0,
//! `modes`) and the residues rⱼ = −1/Σᵢfᵢ/(bᵢ − κⱼ)² < 0, so
//!
//! ```text
//!   c_W·Q′(ξ) = w(ξ) + Σⱼ rⱼ ∫₀^∞ e^{−κⱼζ} w(ξ+ζ) dζ.
//! ```
//!
//! A column ahead of the front edge (ξ > λ) is unloaded and undeformed; inside the contact its
//! deflection w = ρv follows the roll, w(ξ) = [(λ−β)² − (ξ−β)²]/2 (eq. 3.22 with w(λ) = 0: the
//! column meets the roll undeformed). With s = λ − ξ (distance from the front edge) and a = λ − β,
//! w = as − s²/2 and
//!
//! ```text
//!   c_W·Q′ = as − s²/2 + Σⱼ rⱼ (a·m₁(κⱼ, s) − m₂(κⱼ, s)/2),   m_p(κ, s) = ∫₀^s e^{−κ(s−σ)}σ^p dσ,
//! ```
//!
//! m₁ = (s − m₀)/κ, m₂ = (s² − 2m₁)/κ, m₀ = (1 − e^{−κs})/κ, or the series
//! m_p = p!·s^{p+1}·Σₙ(−κs)ⁿ/(n+p+1)! when κs < 1 (no cancellation). The rear edge is where the
//! pressure falls to zero, Q′(ξ = 0) = 0: linear in a, so a (and β = λ − a) in closed form. Then
//! N′ = 2∫Q′dξ and ρF/N = ∫Q′(ξ−β)dξ/∫Q′dξ by Gauss–Legendre on panels graded geometrically toward the
//! front edge (the layers e^{−κⱼs} of width 1/κⱼ): exact to rounding, since on each panel the
//! integrand is a polynomial times exponentials that vary by at most e^{−1} over... (see `integrate`).
//! At given load N′(λ) is monotone; the load loop of [`crate::contact::load`] finds λ.
//!
//! Elastic check: no terms → Q′ = w/c_W, β = λ/2, N′ = λ³/(6c_W), i.e. the half-width
//! (3RN/(2k))^{1/3} with k = M/h (constrained) or E/h (uniaxial).
//!
//! Contact checks: Q′ ≥ 0 inside (at the quadrature nodes); behind the rear edge (ξ = −d < 0) the
//! column recovers, ρv(−d) = c_W·Σᵢfᵢe^{−bᵢd}∫₀^λe^{−bᵢξ}Q′dξ, and must stay below the roll's surface,
//! i.e. ρv(−d) ≥ w_roll(−d) = [(λ−β)² − (d+β)²]/2; ahead of the front the roll is above the undeformed
//! surface whenever β < λ.

use super::modes::Modes;
use crate::contact::error::{positive, ContactError};
use crate::contact::load::{solve_at_load as load_loop, LoadSettings};
use crate::contact::problem::{BodyAnswer, CreepTerm, DimensionlessSolution};
use crate::special::gauss_legendre::gauss_legendre;

/// Which columns a Winkler foundation is made of.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WinklerColumns {
    /// Laterally constrained columns, modulus M = 2μ(1−ν)/(1−2ν): the thin-layer limit of the bonded
    /// layer for ν < ½ (infinitely stiff at ν = ½).
    Constrained,
    /// Free uniaxial columns, modulus E = 2μ(1+ν): the conveyor design tools' model.
    Uniaxial,
}

/// c_W of ρ·v = c_W·Q′ (thesis units, module doc) for a foundation of dimensionless height `h`;
/// `None` for constrained columns at ν = ½ (rigid).
pub(crate) fn winkler_coefficient(columns: WinklerColumns, h: f64, nu: f64) -> Option<f64> {
    let pi = std::f64::consts::PI;
    match columns {
        WinklerColumns::Uniaxial => Some(pi * h / (2.0 * (1.0 - nu * nu))),
        WinklerColumns::Constrained => {
            let c = pi * h * (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu) * (1.0 - nu));
            (c > 0.0).then_some(c)
        }
    }
}

/// A Winkler foundation with its relaxation modes.
#[derive(Debug, Clone)]
pub struct Winkler {
    c_w: f64,
    modes: Modes,
    /// κⱼ and rⱼ of the relaxation form.
    relax: Vec<(f64, f64)>,
}

/// A Winkler solution with its checks.
#[derive(Debug, Clone, PartialEq)]
pub struct WinklerAnswer {
    /// The solution (pressure at the nodes used for the integrals, front edge last).
    pub solution: DimensionlessSolution,
    /// Smallest pressure over the largest.
    pub min_pressure_ratio: f64,
    /// Smallest gap behind the rear edge over the indentation depth (≥ 0: the roll leaves the body).
    pub min_gap_ratio: f64,
    /// Warnings (contact checks).
    pub warnings: Vec<String>,
}

impl WinklerAnswer {
    /// As a body's answer: closed form, so no error estimate of its own (0); the contact checks'
    /// warnings also in the solution's.
    pub(crate) fn into_body_answer(mut self) -> BodyAnswer {
        self.solution.warnings.extend(self.warnings.iter().cloned());
        BodyAnswer {
            error_estimate: 0.0,
            min_pressure_ratio: self.min_pressure_ratio,
            min_gap_ratio: self.min_gap_ratio,
            warnings: self.warnings,
            solution: self.solution,
        }
    }
}

impl Winkler {
    /// A foundation with a given c_W > 0 (the terms are not checked here: a body validates them).
    pub(crate) fn with_coefficient(terms: &[CreepTerm], c_w: f64) -> Self {
        let modes = Modes::new(terms);
        let relax = (0..modes.len())
            .map(|j| {
                let s: f64 = (0..modes.len())
                    .map(|i| {
                        let d = modes.b_minus_kappa(i, j);
                        modes.f[i] / (d * d)
                    })
                    .sum();
                (modes.kappa(j), -1.0 / s)
            })
            .collect();
        Self { c_w, modes, relax }
    }

    /// Σfᵢ/bᵢ.
    pub fn sum_f_over_b(&self) -> f64 {
        self.modes.compliance_ratio() - 1.0
    }

    /// (c_W·Q′ without the a-terms, the a-coefficient) at distance s from the front edge.
    fn parts(&self, s: f64) -> (f64, f64) {
        let mut c0 = -0.5 * s * s;
        let mut c1 = s;
        for &(k, r) in &self.relax {
            let (m1, m2) = moments(k, s);
            c0 -= 0.5 * r * m2;
            c1 += r * m1;
        }
        (c0, c1)
    }

    /// Solve at contact length λ; `nodes` sample points of the returned pressure (≥ 2).
    pub fn at_lambda(&self, lambda: f64) -> Result<WinklerAnswer, ContactError> {
        positive("lambda", lambda)?;
        let (c0, c1) = self.parts(lambda);
        let a = -c0 / c1;
        let beta = lambda - a;
        let kmax = self.relax.iter().map(|r| r.0).fold(0.0, f64::max);
        let nodes = quadrature_nodes(lambda, kmax);
        let q = |s: f64| {
            let (d0, d1) = self.parts(s);
            (d0 + a * d1) / self.c_w
        };
        let qs: Vec<f64> = nodes.iter().map(|&(s, _)| q(s)).collect();
        let (mut i0, mut i1) = (0.0, 0.0);
        let mut samples: Vec<(f64, f64)> = Vec::with_capacity(nodes.len() + 2);
        for (&(s, w), &v) in nodes.iter().zip(&qs) {
            i0 += w * v;
            i1 += w * v * (lambda - s - beta);
            samples.push((lambda - s, v));
        }
        samples.push((0.0, 0.0));
        samples.push((lambda, 0.0));
        samples.sort_by(|x, y| x.0.total_cmp(&y.0));
        let max_q = samples.iter().map(|p| p.1).fold(0.0, f64::max);
        let min_q = samples.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        let min_gap = self.min_gap(&nodes, &qs, lambda, a, beta);
        let min_pressure_ratio = min_q / max_q;
        let warnings = contact_warnings(min_pressure_ratio, min_gap, beta, lambda);
        Ok(WinklerAnswer {
            solution: DimensionlessSolution {
                scheme: "winkler".into(),
                lambda,
                beta,
                load: 2.0 * i0,
                friction_rho: i1 / i0,
                xi: samples.iter().map(|p| p.0).collect(),
                pressure: samples.iter().map(|p| p.1).collect(),
                n: 0,
                iterations: 0,
                error_estimate: Some(0.0),
                diagnostics: None,
                warnings: Vec::new(),
            },
            min_pressure_ratio,
            min_gap_ratio: min_gap,
            warnings,
        })
    }

    /// Smallest gap/indentation behind the rear edge, sampled at distances λ·2^{e/2} behind it,
    /// e = −40…20.
    fn min_gap(&self, nodes: &[(f64, f64)], qs: &[f64], lambda: f64, a: f64, beta: f64) -> f64 {
        // Recovery behind the rear edge: moments ∫₀^λ e^{−bᵢξ}Q′dξ = ∫ e^{−bᵢ(λ−s)}Q′ ds.
        let mom: Vec<f64> = self
            .modes
            .f
            .iter()
            .zip(&self.modes.b)
            .map(|(_, &b)| {
                nodes
                    .iter()
                    .zip(qs)
                    .map(|(&(s, w), &v)| w * (-b * (lambda - s)).exp() * v)
                    .sum()
            })
            .collect();
        let depth = 0.5 * a * a;
        let mut min_gap = f64::INFINITY;
        for e in -40..=20 {
            let d = lambda * 2f64.powf(e as f64 / 2.0);
            let v: f64 = self
                .modes
                .f
                .iter()
                .zip(&self.modes.b)
                .zip(&mom)
                .map(|((f, b), m)| f * (-b * d).exp() * m)
                .sum::<f64>()
                * self.c_w;
            let roll = 0.5 * (a * a - (d + beta) * (d + beta));
            min_gap = min_gap.min((v - roll) / depth);
        }
        min_gap
    }

    /// Solve at load N′ (bracketed load loop on the closed form).
    pub fn at_load(
        &self,
        load: f64,
        settings: &LoadSettings,
    ) -> Result<WinklerAnswer, ContactError> {
        positive("load N'", load)?;
        // Glassy elastic width (6c_W N′)^{1/3} as the loop's start (it starts from 2√N′).
        let scale = (6.0 * self.c_w * load).cbrt() / (2.0 * load.sqrt());
        let mut last = None;
        let sol = load_loop(load, self.sum_f_over_b(), settings, |l| {
            let ans = self.at_lambda(l * scale)?;
            let s = ans.solution.clone();
            last = Some(ans);
            Ok(s)
        })?;
        let mut ans = match last {
            Some(a) if a.solution.lambda == sol.lambda => a,
            _ => self.at_lambda(sol.lambda)?,
        };
        ans.solution.iterations = sol.iterations;
        Ok(ans)
    }
}

/// Gauss–Legendre nodes (s, weight) on panels [λ2^{−p−1}, λ2^{−p}] in s, down to below the thinnest
/// layer (relaxation rate `kmax`).
fn quadrature_nodes(lambda: f64, kmax: f64) -> Vec<(f64, f64)> {
    let levels = ((kmax * lambda).max(1.0).log2().ceil() as usize + 8).min(1100);
    let (gx, gw) = gauss_legendre(16);
    let mut nodes: Vec<(f64, f64)> = Vec::new(); // (s, weight)
    let mut hi = lambda;
    for p in 0..=levels {
        let lo = if p == levels { 0.0 } else { hi * 0.5 };
        let (mid, half) = (0.5 * (hi + lo), 0.5 * (hi - lo));
        for (x, w) in gx.iter().zip(&gw) {
            nodes.push((mid + half * x, half * w));
        }
        hi = lo;
    }
    nodes
}

/// The contact checks' warnings: negative pressure, recovery above the roll, β past the front edge.
fn contact_warnings(min_pressure_ratio: f64, min_gap: f64, beta: f64, lambda: f64) -> Vec<String> {
    let mut warnings = Vec::new();
    if min_pressure_ratio < -1e-9 {
        warnings.push(format!(
            "contact check: negative pressure inside the contact (min/max = {min_pressure_ratio:.2e})"
        ));
    }
    if min_gap < -1e-9 {
        warnings.push(format!(
            "contact check: the recovering body rises above the roll behind the contact (min gap/indentation = {min_gap:.2e})"
        ));
    }
    if beta >= lambda {
        warnings.push("contact check: the roll's lowest point lies ahead of the front edge".into());
    }
    warnings
}

/// (m₁, m₂) of the module doc for rate κ ≥ 0 at s ≥ 0.
fn moments(k: f64, s: f64) -> (f64, f64) {
    let x = k * s;
    if x < 1.0 {
        // m_p = p!·s^{p+1}·Σₙ(−x)ⁿ/(n+p+1)!
        let (mut t1, mut t2) = (0.5, 1.0 / 6.0); // 1/(n+2)!, 1/(n+3)! at n = 0
        let (mut s1, mut s2) = (0.0_f64, 0.0_f64);
        let mut pw = 1.0_f64;
        for n in 0..30 {
            s1 += pw * t1;
            s2 += pw * t2;
            if pw.abs() * t1 < 1e-18 * s1.abs() {
                break;
            }
            pw *= -x;
            t1 /= (n + 3) as f64;
            t2 /= (n + 4) as f64;
        }
        (s * s * s1, 2.0 * s * s * s * s2)
    } else {
        let m0 = -(-x).exp_m1() / k;
        let m1 = (s - m0) / k;
        let m2 = (s * s - 2.0 * m1) / k;
        (m1, m2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn moments_series_and_closed_form_agree() {
        // At κs = 1 both forms are valid; the closed form loses ≤ e·ε to cancellation there.
        for s in [0.5, 2.0] {
            let k: f64 = 1.0 / s;
            let x: f64 = k * s;
            assert_eq!(x, 1.0);
            let m0 = -(-x).exp_m1() / k;
            let m1 = (s - m0) / k;
            let m2 = (s * s - 2.0 * m1) / k;
            let (a1, a2) = moments(k * (1.0 - 1e-15), s);
            assert!((a1 / m1 - 1.0).abs() < 1e-13 && (a2 / m2 - 1.0).abs() < 1e-13);
        }
    }

    #[test]
    fn elastic_winkler_closed_form() {
        // No creep: β = λ/2, N′ = λ³/(6c_W), ρF/N = 0 (to rounding of the quadrature).
        let w = Winkler::with_coefficient(&[], 0.7);
        let a = w.at_lambda(1.3).unwrap();
        let s = &a.solution;
        assert!((s.beta - 0.65).abs() < 1e-14);
        assert!((s.load / (1.3f64.powi(3) / (6.0 * 0.7)) - 1.0).abs() < 1e-13);
        assert!(s.friction_rho.abs() < 1e-13);
    }

    #[test]
    fn uniaxial_winkler_standard_linear_solid_closed_form() {
        // One term: 1/Φ = 1 − f/(b + f − ik); for a load at given λ the pressure is
        // c_W Q′ = w(s) − f·∫₀^s e^{−(b+f)(s−σ)} w(σ)dσ. Independent check: integrate that by
        // adaptive quadrature at a few s and compare; and the rear-edge condition Q′(0) = 0.
        let t = [CreepTerm { f: 3.0, b: 2.0 }];
        let c_w = winkler_coefficient(WinklerColumns::Uniaxial, 0.4, 0.5).unwrap();
        let w = Winkler::with_coefficient(&t, c_w);
        let a = w.at_lambda(1.5).unwrap();
        let s = &a.solution;
        let (lam, aa) = (1.5, 1.5 - s.beta);
        let wf = |sg: f64| aa * sg - 0.5 * sg * sg;
        let mut integ = crate::special::gauss_legendre::Integrator::new(20);
        for (&x, &q) in s.xi.iter().zip(&s.pressure).step_by(37) {
            let sd = lam - x;
            let conv = integ.integrate(
                |sg| (-(5.0) * (sd - sg)).exp() * wf(sg),
                &[0.0, sd.max(1e-300)],
                1e-14,
            );
            let want = (wf(sd) - 3.0 * conv) / c_w;
            // Both are exact to rounding; 1e−12 of the peak pressure.
            assert!((q - want).abs() < 1e-12 * 0.5, "{x}: {q} vs {want}");
        }
        assert!(
            s.friction_rho > 0.0 && a.min_pressure_ratio >= -1e-12 && a.min_gap_ratio > -1e-9,
            "{a:?}"
        );
    }
}
