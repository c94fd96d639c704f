//! Stage `creep`: the creep (retardation) spectrum that the contact solver consumes, and the
//! conversion relaxation → creep (exact, from the roots of s·Ē(s), docs/MATH.md §4; and Park & Schapery,
//! thesis eq. 2.18–2.23).
//!
//! Input: [`crate::prony::RelaxationSpectrum`]; output: [`CreepSpectrum`].

use crate::material::ModulusKind;
use serde::{Deserialize, Serialize};

/// One retardation term of a creep spectrum: Jⱼ(1 − e^(−t/τⱼ)).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RetardationTerm {
    /// Retardation strength Jⱼ in 1/Pa (> 0).
    pub compliance_per_pa: f64,
    /// Retardation time τⱼ in s (> 0).
    pub tau_s: f64,
}

/// A creep spectrum (thesis eq. 2.12): J(t) = J_g + Σⱼ Jⱼ (1 − e^(−t/τⱼ)), a viscoelastic solid.
///
/// The relaxed (long-time) compliance is J∞ = J_g + Σⱼ Jⱼ.
///
/// JSON (units in the field names):
/// ```json
/// { "kind": "tensile", "poisson": 0.5, "compliance_glassy_per_pa": 1e-9,
///   "terms": [ { "compliance_per_pa": 9e-9, "tau_s": 1e-3 } ] }
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CreepSpectrum {
    /// Whether the compliances are tensile (1/E) or shear (1/G).
    #[serde(default)]
    pub kind: ModulusKind,
    /// Poisson's ratio ν used to convert between tensile and shear (rubber: 0.5).
    #[serde(default = "crate::material::default_poisson")]
    pub poisson: f64,
    /// Glassy (instantaneous) compliance J_g = J(0) in 1/Pa.
    pub compliance_glassy_per_pa: f64,
    /// Retardation terms.
    pub terms: Vec<RetardationTerm>,
}

/// Why the rolling contact refuses a fluid (E∞ = 0; docs/MATH.md §17), for every message that does.
pub(crate) const FLUID_NO_STEADY_ROLLING: &str =
    "A fluid has no steady state in rolling on the half-space: its creep rate tends to 1/η₀ instead of \
     0, so the surface keeps tilting under every load that has passed, whose elastic slope decays only \
     like 1/distance in plane strain; the memory integral diverges logarithmically (friction at \
     E∞ = ε grows like ln(1/ε) without a limit). A cover bonded to a rigid carcass or a Winkler \
     foundation would have a steady state, but they are not solved for fluids; give a solid \
     (E∞ > 0), e.g. refit with the equilibrium modulus left free (docs/MATH.md §17).";

pub(crate) mod error;
pub(crate) mod exact;
pub(crate) mod park_schapery;
pub(crate) mod spectrum;
pub(crate) mod time_fit;

pub(crate) use crate::material::AtTemperature;
pub use error::CreepError;
pub use exact::{creep_to_relaxation, relaxation_to_creep, ExactInfo};
pub(crate) use exact::{fluid_to_creep, FluidCreep};
pub use park_schapery::{
    park_schapery, ParkSchaperyInfo, ParkSchaperySettings, ParkSchaperyVariant,
};
