//! Stage `contact`: a rigid cylinder rolling steadily on a viscoelastic half-space (thesis ch. 3–4).
//!
//! Input: a [`crate::CreepSpectrum`] (+ shift law and temperature) and a dimensional scene; output: the
//! contact solution (pressure, contact length, offset, rolling-friction coefficient).
//!
//! Dimensionless problem (thesis §3.2, eq. 3.25): lengths in units of V·T, contact on 0 ≤ ξ ≤ λ with the
//! front (leading) edge at ξ = λ, creep function γ(ζ) = Σᵢ fᵢ e^(−bᵢζ) (eq. 3.7), unknown pressure Q′(ξ)
//! and offset β, load N′ = 2∫Q′dξ (eq. 3.24), friction ρ·F/N = ∫Q′(ξ−β)dξ / ∫Q′dξ.

use serde::{Deserialize, Serialize};

mod bessel;
mod brent;
pub mod exact;
#[cfg(test)]
mod exact_tests;
mod quadrature;

pub use exact::{one_term_at_lambda, one_term_at_load, ContactExactError, OneTermExact};

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
}

pub mod auto;
pub mod chebyshev;
pub mod controlled;
pub mod error;
pub mod kernel;
pub mod layer;
pub mod load;
pub mod modes;
pub mod reduce;
pub mod scene;
pub mod solve;
pub mod thesis;

pub use error::ContactError;
pub use kernel::Kernel;
pub use load::LoadSettings;
pub use scene::{roll, DimensionlessScene, RollSolution, Scene};
pub use solve::{solve_at_lambda, solve_at_load, ContactSettings, Scheme};
pub mod rear_gap;
pub mod roll_auto;
