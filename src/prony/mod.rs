//! Stage `prony`: the relaxation spectrum (Prony series, thesis eq. 2.9) and its non-negative QP fit
//! to a master curve (docs/MATH.md §5).
//!
//! Input: a master curve; output: [`RelaxationSpectrum`].

use crate::material::ModulusKind;
use serde::{Deserialize, Serialize};

mod error;
pub(crate) mod fit;
mod info;
pub(crate) mod kernel;
pub(crate) mod points;
pub(crate) mod pyvisco_csv;
mod settings;
#[cfg(test)]
pub(crate) mod synthetic;
pub(crate) mod terms;
pub(crate) mod time_fit;

pub use error::PronyError;
pub(crate) use fit::log10_errors;
#[cfg(test)]
pub(crate) use fit::relaxation_times_s;
pub use fit::{fit_prony, MasterPoint, PronyFit};
pub(crate) use info::LambdaCandidate;
pub use info::PronyInfo;
pub use settings::{PronySettings, WeightRule};
pub use terms::TermControl;
pub(crate) use terms::TermTrade;

/// One relaxation term of a Prony series: Eᵢ e^(−t/ρᵢ).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RelaxationTerm {
    /// Relaxation strength Eᵢ in Pa (≥ 0).
    pub modulus_pa: f64,
    /// Relaxation time ρᵢ in s (> 0).
    pub tau_s: f64,
}

/// A relaxation spectrum (thesis eq. 2.9): E(t) = E∞ + Σᵢ Eᵢ e^(−t/ρᵢ).
///
/// JSON (units in the field names):
/// ```json
/// { "kind": "tensile", "poisson": 0.5, "modulus_inf_pa": 1e6,
///   "terms": [ { "modulus_pa": 1e9, "tau_s": 1e-3 } ] }
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RelaxationSpectrum {
    /// Whether the moduli are tensile E or shear G.
    #[serde(default)]
    pub kind: ModulusKind,
    /// Poisson's ratio ν used to convert between tensile and shear (rubber: 0.5).
    #[serde(default = "crate::material::default_poisson")]
    pub poisson: f64,
    /// Equilibrium (relaxed, long-time) modulus E∞ in Pa.
    pub modulus_inf_pa: f64,
    /// Relaxation terms.
    pub terms: Vec<RelaxationTerm>,
}

mod spectrum;
