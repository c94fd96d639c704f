//! The dimensionless problem and its solution, common to every body (thesis §3.2, eq. 3.25): the
//! ground floor of `contact`, importing nothing else of it.
//!
//! Input: nothing (plain serde data); output: [`CreepTerm`] (one term of γ(ζ), eq. 3.7),
//! [`DimensionlessScene`] (a scene made dimensionless, built by `scene`), [`DimensionlessSolution`]
//! (λ, β, N′, ρF/N, pressure, error estimate, warnings), the [`Diagnostics`] of the
//! error-controlled solvers (mode counts of the shared reduction, error parts, contact checks) and
//! a body's [`BodyAnswer`] (the solution with its error estimate, contact checks and warnings).

use serde::{Deserialize, Serialize};

/// One term fᵢ e^(−bᵢζ) of the dimensionless creep function γ(ζ) (thesis eq. 3.7–3.8):
/// fᵢ = (Jᵢ/J_g)(T/τᵢ), bᵢ = T/τᵢ.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct CreepTerm {
    /// fᵢ ≥ 0.
    pub f: f64,
    /// bᵢ > 0.
    pub b: f64,
}

/// A solution of the dimensionless problem (any scheme).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DimensionlessSolution {
    /// Scheme that produced it (`thesis`, `exact`, `auto`…).
    pub scheme: String,
    /// Contact length λ = l/(VT).
    pub lambda: f64,
    /// Offset β of the roll's lowest point from the rear edge ξ = 0 (eq. 3.22).
    pub beta: f64,
    /// Load N′ = 2∫Q′dξ (eq. 3.24).
    pub load: f64,
    /// ρ·F/N = ∫Q′(ξ−β)dξ / ∫Q′dξ (independent of ρ).
    pub friction_rho: f64,
    /// Positions ξ where the pressure is given.
    pub xi: Vec<f64>,
    /// Pressure Q′ at `xi`.
    pub pressure: Vec<f64>,
    /// Number of intervals / unknowns of the discretisation (0 for closed forms).
    pub n: usize,
    /// Iterations of the load loop (0 at given λ).
    pub iterations: usize,
    /// Estimated relative error of friction and λ, when the scheme gives one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error_estimate: Option<f64>,
    /// Diagnostics of the error-controlled solvers (mode counts, error parts, contact checks); `None`
    /// for the others. Flattened in JSON.
    #[serde(flatten)]
    pub diagnostics: Option<Diagnostics>,
    /// Warnings for the user (validity of the model, contact conditions, tolerance not reached).
    #[serde(default)]
    pub warnings: Vec<String>,
}

/// The dimensionless problem of a scene and the scales to go back.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DimensionlessScene {
    /// Creep terms fᵢ = (Jᵢ/J_g)(T/τᵢ), bᵢ = T/τᵢ (eq. 3.8).
    pub terms: Vec<CreepTerm>,
    /// Load N′ (eq. 3.24); 1/4 by the choice of T.
    pub load: f64,
    /// ρ = R/(VT).
    pub rho: f64,
    /// Characteristic time T in s.
    pub time_scale_s: f64,
    /// Length scale V·T in m (= the glassy Hertz contact length).
    pub length_scale_m: f64,
    /// q = `pressure_scale_pa`·Q′, i.e. π·VT/(R·C).
    pub pressure_scale_pa: f64,
    /// Poisson's ratio used.
    pub poisson: f64,
    /// C = (1−ν)/μ₀ in 1/Pa.
    pub compliance_factor_per_pa: f64,
}

impl DimensionlessScene {
    /// A problem given in units of V·T already (the maps' reduced problem, `viscoroll contact`):
    /// `length_scale_m` = 1, so a body's lengths are passed dimensionless; the SI scales are NaN (not
    /// a scene: not for `to_dimensional`).
    pub(crate) fn in_units_of_vt(terms: Vec<CreepTerm>, load: f64, poisson: f64) -> Self {
        DimensionlessScene {
            terms,
            load,
            rho: f64::NAN,
            time_scale_s: f64::NAN,
            length_scale_m: 1.0,
            pressure_scale_pa: f64::NAN,
            poisson,
            compliance_factor_per_pa: f64::NAN,
        }
    }
}

/// The diagnostics of an error-controlled answer (the half-space's `auto` scheme, the layer's spectral
/// solver; in [`DimensionlessSolution::diagnostics`], its warnings in
/// [`DimensionlessSolution::warnings`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Diagnostics {
    /// Modes solved for explicitly.
    pub modes_used: usize,
    /// Modes in the input (terms with f > 0).
    pub modes_total: usize,
    /// Fast modes lumped into the glassy compliance.
    pub modes_lumped: usize,
    /// Slow modes dropped.
    pub modes_dropped: usize,
    /// Estimated relative error of ρF/N.
    pub friction_error: f64,
    /// Estimated relative error of λ (at given load) or of N′ (at given λ).
    pub size_error: f64,
    /// min Q′ / max Q′ over the profile (≥ −tol when the contact condition holds).
    pub min_pressure_ratio: f64,
    /// Smallest gap outside the contact (behind the rear edge, ahead of the front edge, and around
    /// the roll's lowest point when β < 0) over the depth scale λ²/8; < 0 means the roll penetrates
    /// the surface there (accurate to ~1e−10 of λ²/8 plus the solution's own error, see
    /// `rear_gap`; NaN when the check is switched off).
    #[serde(default)]
    pub min_gap_ratio: f64,
    /// Where the smallest gap lies (ξ, < 0 behind the rear edge, > λ ahead of the front edge).
    #[serde(default)]
    pub min_gap_xi: f64,
    /// The tolerance asked for.
    pub tol: f64,
}

/// A solution on one of the bodies, with its diagnostics (which body: the caller's
/// `contact::body::Body`).
#[derive(Debug, Clone, PartialEq)]
pub struct BodyAnswer {
    /// λ, β, N′, ρF/N, pressure.
    pub solution: DimensionlessSolution,
    /// Estimated relative error of ρF/N and λ (of the body's own model).
    pub error_estimate: f64,
    /// min Q′ / max Q′.
    pub min_pressure_ratio: f64,
    /// Smallest gap outside the contact over the indentation depth.
    pub min_gap_ratio: f64,
    /// Warnings.
    pub warnings: Vec<String>,
}

impl BodyAnswer {
    /// The answer of a solution that carries its own estimate and checks (the half-space's: NaN
    /// where the scheme gives none).
    pub(crate) fn from_solution(solution: DimensionlessSolution) -> Self {
        let diag = solution.diagnostics.as_ref();
        BodyAnswer {
            error_estimate: solution.error_estimate.unwrap_or(f64::NAN),
            min_pressure_ratio: diag.map_or(f64::NAN, |d| d.min_pressure_ratio),
            min_gap_ratio: diag.map_or(f64::NAN, |d| d.min_gap_ratio),
            warnings: solution.warnings.clone(),
            solution,
        }
    }
}
