//! The reduced problem of the friction maps: a spectrum's scenes depend on the reduced time
//! s = l_g/(V·a_T) only (module doc of [`super`]); its dimensionless creep terms at s and the
//! `auto` solve at N′ = 1/4 there, on the half-space through the body dispatch
//! ([`crate::contact::body::solve_at_load`]).
//!
//! Input: a [`CreepSpectrum`] (+ Poisson's ratio), s; output: [`ReducedSolution`] / [`Node`].

use super::FrictionMapError;
use crate::contact::body::{solve_at_load, Body};
use crate::contact::problem::{CreepTerm, DimensionlessScene};
use crate::contact::settings::{AutoSettings, ContactSettings, Scheme};
use crate::{CreepSpectrum, ModulusKind};
use std::f64::consts::PI;

/// The compound's part of the dimensionless problem: Jᵢ/J_g and τᵢ (at the reference temperature),
/// and the compliance factor C.
#[derive(Debug, Clone, PartialEq)]
pub struct ReducedProblem {
    /// (Jᵢ/J_g, τᵢ in s) for the terms with Jᵢ > 0.
    pub ratios: Vec<(f64, f64)>,
    /// C = (1−ν)/μ₀ in 1/Pa (as in [`crate::contact::scene`]).
    pub compliance_factor_per_pa: f64,
}

/// The solution of the dimensionless problem at one s (N′ = 1/4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReducedSolution {
    /// ρF/N.
    pub friction_rho: f64,
    /// Contact length λ (in units of l_g).
    pub lambda: f64,
    /// Offset β of the lowest point from the rear edge (in units of l_g).
    pub beta: f64,
    /// The solver's estimated relative error of ρF/N and λ.
    pub error_estimate: f64,
}

/// One solved node: x = ln s, ln φ, ln λ, β.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Node {
    /// ln s.
    pub x: f64,
    /// ln(ρF/N).
    pub ln_phi: f64,
    /// ln λ.
    pub ln_lambda: f64,
}

impl ReducedProblem {
    /// From a creep spectrum at its reference temperature; `poisson` overrides the spectrum's.
    pub fn new(spectrum: &CreepSpectrum, poisson: Option<f64>) -> Result<Self, FrictionMapError> {
        let bad = |field: String, value: f64, expected| FrictionMapError::BadValue {
            field,
            value,
            expected,
        };
        let nu = poisson.unwrap_or(spectrum.poisson);
        if !(nu.is_finite() && (0.0..=0.5).contains(&nu)) {
            return Err(bad("poisson".into(), nu, "in [0, 0.5]"));
        }
        let jg = spectrum.compliance_glassy_per_pa;
        if !(jg.is_finite() && jg > 0.0) {
            return Err(bad("compliance_glassy_per_pa".into(), jg, "finite and > 0"));
        }
        // C = (1−ν)/μ₀ (docs/MATH.md §1), as in contact::scene.
        let c = match spectrum.kind {
            ModulusKind::Tensile => 2.0 * (1.0 - nu * nu) * jg,
            ModulusKind::Shear => (1.0 - nu) * jg,
        };
        let mut ratios = Vec::with_capacity(spectrum.terms.len());
        for (i, t) in spectrum.terms.iter().enumerate() {
            if !(t.compliance_per_pa.is_finite() && t.compliance_per_pa >= 0.0) {
                return Err(bad(
                    format!("terms[{i}].compliance_per_pa"),
                    t.compliance_per_pa,
                    "finite and ≥ 0",
                ));
            }
            if !(t.tau_s.is_finite() && t.tau_s > 0.0) {
                return Err(bad(format!("terms[{i}].tau_s"), t.tau_s, "finite and > 0"));
            }
            if t.compliance_per_pa > 0.0 {
                ratios.push((t.compliance_per_pa / jg, t.tau_s));
            }
        }
        Ok(ReducedProblem {
            ratios,
            compliance_factor_per_pa: c,
        })
    }

    /// Glassy Hertz contact length l_g = 2√(2RCN*/π) in m.
    pub(crate) fn glassy_length_m(&self, radius_m: f64, load_n_per_m: f64) -> f64 {
        2.0 * (2.0 * radius_m * self.compliance_factor_per_pa * load_n_per_m / PI).sqrt()
    }

    /// The reduced variable s = l_g/(V·a_T) in s.
    pub fn reduced_time_s(
        &self,
        radius_m: f64,
        load_n_per_m: f64,
        speed_m_s: f64,
        a_t: f64,
    ) -> f64 {
        self.glassy_length_m(radius_m, load_n_per_m) / (speed_m_s * a_t)
    }

    /// The creep terms (fᵢ, bᵢ) of the dimensionless problem at reduced time `s_s`.
    pub fn terms(&self, s_s: f64) -> Vec<CreepTerm> {
        self.ratios
            .iter()
            .map(|&(r, tau)| {
                let b = s_s / tau;
                CreepTerm { f: r * b, b }
            })
            .collect()
    }

    /// Solve the dimensionless problem at N′ = 1/4 and reduced time s = e^x.
    pub fn solve(
        &self,
        x: f64,
        settings: &AutoSettings,
    ) -> Result<ReducedSolution, FrictionMapError> {
        let s_s = x.exp();
        // lengths in units of l_g (= V·T): only the terms and N′ enter the half-space's solve
        let problem = DimensionlessScene {
            terms: self.terms(s_s),
            load: 0.25,
            rho: f64::NAN,
            time_scale_s: f64::NAN,
            length_scale_m: 1.0,
            pressure_scale_pa: f64::NAN,
            poisson: f64::NAN,
            compliance_factor_per_pa: self.compliance_factor_per_pa,
        };
        let contact = ContactSettings {
            scheme: Scheme::Auto,
            auto: *settings,
            ..ContactSettings::default()
        };
        let sol = solve_at_load(&Body::HALF_SPACE, &problem, &contact)
            .map_err(|source| FrictionMapError::Solve { s_s, source })?;
        let d = &sol;
        Ok(ReducedSolution {
            friction_rho: d.friction_rho,
            lambda: d.lambda,
            beta: d.beta,
            error_estimate: d.error_estimate.unwrap_or(f64::NAN),
        })
    }

    pub(super) fn node(&self, x: f64, settings: &AutoSettings) -> Result<Node, FrictionMapError> {
        let ReducedSolution {
            friction_rho: phi,
            lambda,
            ..
        } = self.solve(x, settings)?;
        if !(phi > 0.0 && phi.is_finite()) {
            return Err(FrictionMapError::NonPositive { s_s: x.exp(), phi });
        }
        Ok(Node {
            x,
            ln_phi: phi.ln(),
            ln_lambda: lambda.ln(),
        })
    }
}

/// Tolerance of the node solves for a map tolerance `tol`: a tenth of it (so the solver's error times
/// the Lebesgue constant stays below a third of `tol`). It was capped at 1e−7 while the `auto` solver
/// returned, on the shipped TRIOS compound far on the glassy side (ln s ≈ −46…−20), frictions off
/// by up to 3 % (once 2–4×) with estimates of ~1e−6; the cause was the Bessel cut of
/// src/special/bessel.rs, and since its fix the solver's estimate holds there
/// (tests/contact_props.rs, `estimate_holds_across_the_reduced_variable_on_measured_compounds`).
pub fn node_tol(tol: f64) -> f64 {
    0.1 * tol
}
