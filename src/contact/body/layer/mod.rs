//! Bodies beyond the half-space: a viscoelastic cover of thickness h bonded to a rigid carcass (plane
//! strain, 0 ≤ ν ≤ ½) and the Winkler foundations it is compared with (issue 14).
//!
//! Input: the dimensionless creep terms (fᵢ, bᵢ) of thesis eq. 3.7, the load N′ (eq. 3.24), the
//! dimensionless cover thickness h′ = h/(VT) and ν; output: [`BodyAnswer`] (λ, β, pressure, ρF/N,
//! error estimate, contact checks, warnings, which body was solved).
//!
//! - [`compliance`]: the layer's Fourier compliance F(|k|h) (derivation, references, limits);
//! - [`kernel`]: its steady-rolling viscoelastic kernel = half-space kernel + smooth correction;
//! - [`collocation`]: the thesis' collocation scheme with that kernel, load loop, error estimate;
//! - [`winkler`]: Winkler foundations (uniaxial columns of conveyor tools, constrained columns of the
//!   thin compressible layer) in closed form for any spectrum.

pub mod collocation;
pub mod compliance;
pub mod kernel;
pub mod roll_cover;
pub mod spectral;
pub mod winkler;

pub use collocation::{LayerAnswer, LayerSettings};
pub use compliance::WinklerColumns;
pub use kernel::LayerKernel;
pub use roll_cover::{auto_choice, roll_cover, solve_cover, CoverAnswer, CoverRoll, ModelChoice};
pub use winkler::{Winkler, WinklerAnswer};

use crate::contact::error::ContactError;
use crate::contact::load::LoadSettings;
use crate::contact::{CreepTerm, DimensionlessSolution};
use serde::{Deserialize, Serialize};

/// The body a scene is solved on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum BodyModel {
    /// Viscoelastic half-space (thesis ch. 3).
    HalfSpace,
    /// Viscoelastic layer bonded to a rigid base.
    Layer,
    /// Winkler foundation of uniaxial columns (conveyor design tools).
    Winkler,
    /// Winkler foundation of laterally constrained columns (the thin compressible layer's limit).
    WinklerConstrained,
}

impl BodyModel {
    /// Name in JSON, CSV and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            BodyModel::HalfSpace => "half-space",
            BodyModel::Layer => "layer",
            BodyModel::Winkler => "winkler",
            BodyModel::WinklerConstrained => "winkler-constrained",
        }
    }
}

/// A solution on one of the bodies, with its diagnostics.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyAnswer {
    /// The body solved.
    pub model: BodyModel,
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

/// Solve the bonded layer of dimensionless thickness `thickness` at load N′.
pub fn layer_at_load(
    terms: &[CreepTerm],
    load: f64,
    thickness: f64,
    poisson: f64,
    settings: &LayerSettings,
) -> Result<BodyAnswer, ContactError> {
    let kernel = LayerKernel::new(terms, thickness, poisson)?;
    let a = collocation::solve_layer_at_load(&kernel, load, settings)?;
    let mut solution = a.solution;
    solution.warnings.extend(a.warnings.iter().cloned());
    Ok(BodyAnswer {
        model: BodyModel::Layer,
        solution,
        error_estimate: a.error_estimate,
        min_pressure_ratio: a.min_pressure_ratio,
        min_gap_ratio: a.min_gap_ratio,
        warnings: a.warnings,
    })
}

/// Solve a Winkler foundation of `columns` of dimensionless height `thickness` at load N′.
pub fn winkler_at_load(
    terms: &[CreepTerm],
    load: f64,
    columns: WinklerColumns,
    thickness: f64,
    poisson: f64,
    settings: &LoadSettings,
) -> Result<BodyAnswer, ContactError> {
    let w = Winkler::new(terms, columns, thickness, poisson)?;
    let mut a = w.at_load(load, settings)?;
    a.solution.warnings.extend(a.warnings.iter().cloned());
    Ok(BodyAnswer {
        model: match columns {
            WinklerColumns::Uniaxial => BodyModel::Winkler,
            WinklerColumns::Constrained => BodyModel::WinklerConstrained,
        },
        error_estimate: 0.0,
        min_pressure_ratio: a.min_pressure_ratio,
        min_gap_ratio: a.min_gap_ratio,
        warnings: a.warnings,
        solution: a.solution,
    })
}

#[cfg(test)]
mod elastic_check;
#[cfg(test)]
mod tests;
