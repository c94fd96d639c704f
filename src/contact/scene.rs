//! Dimensional scenes: a rigid roll of radius R (m) rolling at speed V (m/s) under a load N* per unit
//! width (N/m) on a body ([`Body`], the half-space by default) with creep compliance J(t) = J_g + Σⱼ Jⱼ(1 − e^(−t/τⱼ)), to and from the
//! dimensionless problem of thesis §3.2 (docs/MATH.md §1).
//!
//! Input: [`Scene`] + [`CreepSpectrum`]; output: [`DimensionlessScene`] (creep terms fᵢ, bᵢ, N′, ρ and
//! the scales) and, after a solve, [`RollSolution`] (SI units).
//!
//! Units (thesis eq. 3.8, 3.24): lengths in V·T; C = (1−ν)/μ₀ with μ₀ the glassy shear modulus, so
//! C = 2(1−ν²)J_g for a tensile J_g = 1/E₀ and C = (1−ν)J_g for a shear J_g = 1/μ₀;
//! Q′ = (R/VT)·C·q/π, N′ = (R/VT)·C·(2/π)·N*/(VT), fᵢ = (Jᵢ/J_g)(T/τᵢ), bᵢ = T/τᵢ, ρ = R/(VT),
//! F/N = (ρF/N)/ρ and the resistance per unit width F* = (F/N)·N*.
//!
//! Characteristic time. The exact problem does not depend on T (it only rescales ξ), and neither does
//! the thesis scheme on a uniform grid, so T is chosen for conditioning only, not as τ₁ (the thesis'
//! choice, which makes λ range over many decades with the speed and the spectrum). We take
//! T = l_g/V, with l_g = 2√(2RCN*/π) the glassy (instantaneous) Hertz contact length. Then N′ = 1/4
//! exactly, λ = 1 at the glassy end and λ = √(J∞/J_g) at the relaxed end, whatever the speed, and
//! bᵢ = l_g/(Vτᵢ) is the time to cross the glassy contact in units of τᵢ: the terms that matter at this
//! speed have bᵢ ≈ 1, the others act as (nearly) glassy (bᵢ ≪ 1) or relaxed (bᵢ ≫ 1) springs.

use super::body::{self, Body};
use super::error::{non_negative, positive, ContactError};
use super::problem::{CreepTerm, DimensionlessScene, DimensionlessSolution};
use super::settings::ContactSettings;
use crate::{CreepSpectrum, ModulusKind};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// One rolling scene (SI units).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Scene {
    /// Roll radius R in m (> 0).
    pub radius_m: f64,
    /// Load per unit width N* in N/m (> 0).
    pub load_n_per_m: f64,
    /// Rolling speed V in m/s (> 0).
    pub speed_m_s: f64,
    /// Poisson's ratio ν of the body, in [0, 0.5]; `None`: the spectrum's (default 0.5).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub poisson: Option<f64>,
    /// What the roll rolls on (default: the half-space, also when absent from JSON).
    #[serde(default)]
    pub body: Body,
}

/// The solution of a scene in SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RollSolution {
    /// Rolling-friction coefficient F*/N* (eq. 3.12).
    pub friction: f64,
    /// Contact length l in m.
    pub contact_length_m: f64,
    /// How far the contact's centre lies ahead of the roll's lowest point, (λ/2 − β)·VT, in m (0 for an
    /// elastic half-space; > 0: the contact moves toward the front edge).
    pub offset_m: f64,
    /// Rolling-resistance force per unit width F* = (F/N)·N*, in N/m.
    pub resistance_n_per_m: f64,
    /// Largest nodal pressure in Pa.
    pub max_pressure_pa: f64,
    /// Positions measured from the roll's lowest point, positive toward the front edge, in m.
    pub x_m: Vec<f64>,
    /// Pressure at `x_m` in Pa.
    pub pressure_pa: Vec<f64>,
    /// The dimensionless problem solved.
    pub problem: DimensionlessScene,
    /// Its solution.
    pub dimensionless: DimensionlessSolution,
}

impl Scene {
    /// Check every field (finite, > 0; ν in [0, 0.5]).
    pub fn validate(&self) -> Result<(), ContactError> {
        positive("radius_m", self.radius_m)?;
        positive("load_n_per_m", self.load_n_per_m)?;
        positive("speed_m_s", self.speed_m_s)?;
        if let Some(nu) = self.poisson {
            check_poisson(nu)?;
        }
        self.body.validate()
    }

    /// The dimensionless problem of this scene on `spectrum` (see the module doc for T).
    pub fn dimensionless(
        &self,
        spectrum: &CreepSpectrum,
    ) -> Result<DimensionlessScene, ContactError> {
        self.validate()?;
        let nu = check_poisson(self.poisson.unwrap_or(spectrum.poisson))?;
        let jg = positive(
            "compliance_glassy_per_pa",
            spectrum.compliance_glassy_per_pa,
        )?;
        // C = (1−ν)/μ₀ (docs/MATH.md §1): tensile μ₀ = E₀/(2(1+ν)), shear μ₀ = 1/J_g.
        let c = match spectrum.kind {
            ModulusKind::Tensile => 2.0 * (1.0 - nu * nu) * jg,
            ModulusKind::Shear => (1.0 - nu) * jg,
        };
        let (r, n_star, v) = (self.radius_m, self.load_n_per_m, self.speed_m_s);
        // Glassy Hertz contact length l_g = 2√(2RCN*/π); T = l_g/V.
        let l_g = 2.0 * (2.0 * r * c * n_star / PI).sqrt();
        let t = l_g / v;
        if !(l_g.is_finite() && l_g > 0.0 && t.is_finite() && t > 0.0) {
            return Err(ContactError::BadValue {
                field: "glassy contact length 2*sqrt(2*R*C*N/pi) in m".into(),
                expected: "finite and > 0 (check the units of radius, load and compliance)",
                value: l_g,
            });
        }
        let mut terms = Vec::with_capacity(spectrum.terms.len());
        for (i, term) in spectrum.terms.iter().enumerate() {
            let ji = non_negative(
                format!("terms[{i}].compliance_per_pa"),
                term.compliance_per_pa,
            )?;
            let tau = positive(format!("terms[{i}].tau_s"), term.tau_s)?;
            let b = t / tau;
            terms.push(CreepTerm {
                f: (ji / jg) * b,
                b,
            });
        }
        let vt = v * t; // = l_g
        Ok(DimensionlessScene {
            terms,
            load: (r / vt) * c * (2.0 / PI) * n_star / vt,
            rho: r / vt,
            time_scale_s: t,
            length_scale_m: vt,
            pressure_scale_pa: PI * vt / (r * c),
            poisson: nu,
            compliance_factor_per_pa: c,
        })
    }
}

impl DimensionlessScene {
    /// Back to SI units: the scene's answer from a dimensionless solution of this problem.
    pub(crate) fn to_dimensional(
        &self,
        load_n_per_m: f64,
        sol: DimensionlessSolution,
    ) -> RollSolution {
        let vt = self.length_scale_m;
        let friction = sol.friction_rho / self.rho;
        let x_m = sol.xi.iter().map(|&x| (x - sol.beta) * vt).collect();
        let pressure_pa: Vec<f64> = sol
            .pressure
            .iter()
            .map(|&q| q * self.pressure_scale_pa)
            .collect();
        RollSolution {
            friction,
            contact_length_m: sol.lambda * vt,
            offset_m: (0.5 * sol.lambda - sol.beta) * vt,
            resistance_n_per_m: friction * load_n_per_m,
            max_pressure_pa: pressure_pa
                .iter()
                .cloned()
                .fold(f64::NEG_INFINITY, f64::max),
            x_m,
            pressure_pa,
            problem: self.clone(),
            dimensionless: sol,
        }
    }
}

/// Solve one scene at its load: on its body (`body::solve_at_load`, the one dispatch point) with
/// the scheme of `settings`.
///
/// Validity: eq. 3.22 replaces the roll by the parabola −(x−b)²/(2R). Over the contact the circle
/// departs from it by x⁴/(8R³) against x²/(2R), a relative (x/R)²/4; at the contact ends x ≈ l/2,
/// so a warning is added when (l/(2R))²/4 > 1e−3, i.e. l/R > 0.126 (the half-space assumption
/// fails at the same order).
pub fn roll(
    scene: &Scene,
    spectrum: &CreepSpectrum,
    settings: &ContactSettings,
) -> Result<RollSolution, ContactError> {
    let problem = scene.dimensionless(spectrum)?;
    let sol = body::solve_at_load(&scene.body, &problem, settings)?;
    let mut roll = problem.to_dimensional(scene.load_n_per_m, sol);
    let l_over_r = roll.contact_length_m / scene.radius_m;
    if l_over_r > 0.126 {
        roll.dimensionless.warnings.push(format!(
            "contact length / radius = {l_over_r:.3}: the parabolic roll profile (eq. 3.22) is off by \
             more than 0.1 % at the contact ends; results lose validity"
        ));
    }
    Ok(roll)
}

fn check_poisson(nu: f64) -> Result<f64, ContactError> {
    if nu.is_finite() && (0.0..=0.5).contains(&nu) {
        Ok(nu)
    } else {
        Err(ContactError::BadValue {
            field: "poisson".into(),
            expected: "in [0, 0.5]",
            value: nu,
        })
    }
}
