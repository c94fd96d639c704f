//! Stage `contact`: a rigid cylinder rolling steadily on a viscoelastic body (thesis ch. 3–4).
//!
//! Input: a [`crate::CreepSpectrum`] (already at the scene's temperature) and a dimensional
//! [`Scene`] (roll, load, speed, and the [`Body`] it rolls on), with [`ContactSettings`] (the
//! [`Scheme`]: thesis, exact or auto); output: the [`RollSolution`] (pressure, contact length,
//! offset, rolling-friction coefficient, error estimate and warnings) or a [`ContactError`].
//!
//! Layout: [`scene`] (to and from the dimensionless problem, [`roll`]), [`settings`], [`error`],
//! [`load`] (the load loop of the thesis scheme), [`body`] (the seam: one enum, one dispatch;
//! [`body::half_space`] holds the half-space kernel, modes, reduction and the three schemes),
//! [`maps`] (friction maps of a spectrum from one reduced variable, half-space only).
//!
//! Dimensionless problem (thesis §3.2, eq. 3.25): lengths in units of V·T, contact on 0 ≤ ξ ≤ λ with the
//! front (leading) edge at ξ = λ, creep function γ(ζ) = Σᵢ fᵢ e^(−bᵢζ) (eq. 3.7), unknown pressure Q′(ξ)
//! and offset β, load N′ = 2∫Q′dξ (eq. 3.24), friction ρ·F/N = ∫Q′(ξ−β)dξ / ∫Q′dξ.

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
    /// Diagnostics of the `auto` scheme (mode counts, error parts, contact checks); `None` for the
    /// others. Flattened in JSON.
    #[serde(flatten)]
    pub auto: Option<AutoDiagnostics>,
    /// Warnings for the user (validity of the model, contact conditions, tolerance not reached).
    #[serde(default)]
    pub warnings: Vec<String>,
}

pub mod body;
pub mod error;
pub mod load;
pub mod maps;
pub mod scene;
pub mod settings;

pub use body::half_space;
pub use body::half_space::auto::{AutoDiagnostics, AutoSettings};
pub use body::half_space::exact::{one_term_at_lambda, one_term_at_load, OneTermExact};
pub use body::Body;
pub use error::ContactError;
pub use load::LoadSettings;
pub use scene::{roll, DimensionlessScene, RollSolution, Scene};
pub use settings::{ContactSettings, Scheme};

/// Solve the dimensionless problem on the half-space at contact length λ (the scheme of
/// `settings`). For another body use [`body::solve_at_lambda`] with a [`DimensionlessScene`].
pub fn solve_at_lambda(
    terms: &[CreepTerm],
    lambda: f64,
    settings: &ContactSettings,
) -> Result<DimensionlessSolution, ContactError> {
    half_space::solve_at_lambda(terms, lambda, settings)
}

/// Solve the dimensionless problem on the half-space at load N′ (the scheme of `settings`,
/// `iterations` = solves made). For another body use [`body::solve_at_load`].
pub fn solve_at_load(
    terms: &[CreepTerm],
    load: f64,
    settings: &ContactSettings,
) -> Result<DimensionlessSolution, ContactError> {
    half_space::solve_at_load(terms, load, settings)
}
