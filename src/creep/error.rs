//! Errors of the `creep` stage ([`CreepError`]): invalid relaxation or creep spectra (the field and the
//! value are named), spectra the conversion cannot represent (a fluid, E∞ = 0), impossible temperature
//! shifts and failed Park & Schapery solves.
//!
//! The field checks themselves live on the ground floor ([`crate::material`]); their error arrives here as
//! [`CreepError::Material`].

use crate::material::MaterialError;

/// What went wrong in the creep stage; messages name the field and the offending value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CreepError {
    /// A field of the spectrum or a temperature is invalid, or the shift law is undefined at the
    /// temperature asked for (the shared checks of [`crate::material`]).
    #[error(transparent)]
    Material(#[from] MaterialError),
    /// The relaxation spectrum describes a fluid (E∞ = 0): its creep function has a flow term t/η₀
    /// (thesis eq. 2.11) that [`CreepSpectrum`](crate::creep::CreepSpectrum) (a solid, eq. 2.12) cannot hold
    /// (`crate::creep::fluid_to_creep` converts it with the flow term apart; the rolling contact
    /// cannot use it: `crate::creep::FLUID_NO_STEADY_ROLLING`).
    #[error(
        "modulus_inf_pa = 0: the spectrum is a fluid (its creep compliance grows without bound, \
         J(t) ~ t/η₀ with η₀ = Σ Eᵢρᵢ = {viscosity_pa_s:e} Pa·s); a creep spectrum of a solid needs \
         an equilibrium modulus E∞ > 0. {}", crate::creep::FLUID_NO_STEADY_ROLLING
    )]
    Fluid {
        /// Zero-shear viscosity η₀ = ∫E(t)dt = Σ Eᵢρᵢ in Pa·s.
        viscosity_pa_s: f64,
    },
    /// The Park & Schapery linear system could not be solved (singular matrix).
    #[error("Park & Schapery: the {rows}×{cols} collocation system is singular (condition number {condition:e})")]
    SingularSystem {
        /// Rows (collocation times).
        rows: usize,
        /// Columns (retardation times).
        cols: usize,
        /// 2-norm condition number estimate.
        condition: f64,
    },
    /// Settings of a conversion are inconsistent.
    #[error("invalid setting {setting}: {reason}")]
    InvalidSetting {
        /// The setting's name.
        setting: &'static str,
        /// Why it is invalid.
        reason: String,
    },
}
