//! Errors of the `creep` stage ([`CreepError`]): invalid relaxation or creep spectra (the field and the
//! value are named), spectra the conversion cannot represent (a fluid, E∞ = 0), impossible temperature
//! shifts and failed Park & Schapery solves.
//!
//! Relaxation spectra are validated here too, because the creep stage is the first consumer that needs
//! them to be physically admissible.

/// What went wrong in the creep stage; messages name the field and the offending value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CreepError {
    /// A scalar field is not finite or outside its admissible range.
    #[error("{field} = {value} is invalid: {expected}")]
    InvalidValue {
        /// The JSON field name, e.g. `terms[3].tau_s`.
        field: String,
        /// The value found.
        value: f64,
        /// What was expected, in words.
        expected: &'static str,
    },
    /// The relaxation spectrum describes a fluid (E∞ = 0): its creep function has a flow term t/η₀
    /// (thesis eq. 2.11) that [`crate::CreepSpectrum`] (a solid, eq. 2.12) cannot hold.
    #[error(
        "modulus_inf_pa = 0: the spectrum is a fluid (its creep compliance grows without bound, \
         J(t) ~ t/η₀ with η₀ = Σ Eᵢρᵢ = {viscosity_pa_s:e} Pa·s); a creep spectrum of a solid needs \
         an equilibrium modulus E∞ > 0"
    )]
    Fluid {
        /// Zero-shear viscosity η₀ = ∫E(t)dt = Σ Eᵢρᵢ in Pa·s.
        viscosity_pa_s: f64,
    },
    /// The shift law gives no finite a_T at this temperature (WLF below its asymptote T_ref − C2).
    #[error("the shift law gives log10 a_T = {log10_a_t} at {temp_c} °C (WLF below T_ref − C2?)")]
    ShiftUndefined {
        /// Requested temperature in °C.
        temp_c: f64,
        /// log10 a_T found.
        log10_a_t: f64,
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

/// Check that `value` is finite and > 0 (or ≥ 0 when `allow_zero`).
pub(crate) fn check_positive(
    field: impl FnOnce() -> String,
    value: f64,
    allow_zero: bool,
) -> Result<(), CreepError> {
    let ok = value.is_finite() && (value > 0.0 || (allow_zero && value == 0.0));
    if ok {
        Ok(())
    } else {
        Err(CreepError::InvalidValue {
            field: field(),
            value,
            expected: if allow_zero {
                "a finite number ≥ 0"
            } else {
                "a finite number > 0"
            },
        })
    }
}

/// Poisson's ratio must lie in (−1, 0.5] for an isotropic solid.
pub(crate) fn check_poisson(value: f64) -> Result<(), CreepError> {
    if value.is_finite() && value > -1.0 && value <= 0.5 {
        Ok(())
    } else {
        Err(CreepError::InvalidValue {
            field: "poisson".into(),
            value,
            expected: "Poisson's ratio in (−1, 0.5]",
        })
    }
}
