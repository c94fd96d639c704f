//! # viscoroll
//!
//! From a rubber compound's DMA measurements to a prediction of its rolling loss.
//!
//! ```text
//!  DMA exports ──ingest──▶ Measurement ──tts──▶ MasterCurve ──prony──▶ RelaxationSpectrum
//!                                                                         │
//!                                    CreepSpectrum ◀──────creep───────────┘
//!                                         │  (+ shift law a_T for the temperature)
//!  Scene (roll radius, load, speed, T) ──▶ contact ──▶ ContactSolution (pressure, contact length, friction)
//!                                         │
//!                    report: friction maps, datasheets, rankings, FEA cards
//! ```
//!
//! Each stage is a module that takes plain serde types and returns plain serde types, so any stage can
//! be run, saved, inspected and tested alone. The `viscoroll` binary is a thin shell over this library
//! ([`cli`]). SI units inside; explicit units in field names at the edges (`freq_hz`, `load_n_per_m`).

pub mod special;

pub mod contact;
pub mod creep;
pub mod dma;
pub mod pipeline;
pub mod prony;
pub mod report;
pub mod tts;

pub mod testdata;

pub mod cli;

pub use creep::CreepSpectrum;
pub use dma::Measurement;
pub use prony::RelaxationSpectrum;
pub use tts::ShiftLaw;

/// Which modulus a spectrum or a measurement describes.
///
/// Tensile (Young's) data E and shear data G are related by E = 2(1+ν)G for an isotropic material
/// with Poisson's ratio ν; the ratio is always stated, never guessed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum ModulusKind {
    /// Young's modulus E (tension, compression, bending).
    #[default]
    Tensile,
    /// Shear modulus G.
    Shear,
}

impl ModulusKind {
    /// Factor that converts a modulus of this kind into the tensile modulus: E = factor · M.
    pub fn to_tensile_factor(self, poisson: f64) -> f64 {
        match self {
            ModulusKind::Tensile => 1.0,
            ModulusKind::Shear => 2.0 * (1.0 + poisson),
        }
    }
}
