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
//!
//! The whole chain, from a shipped DMA export (the EMS-CA sweeps of `data/`, data/SOURCES.md) to the
//! rolling friction of one scene at 20 °C, with the main job's defaults:
//!
//! ```
//! use std::path::PathBuf;
//! use viscoroll::contact::{Body, ContactSettings, Scene};
//! use viscoroll::pipeline::{fit_files, roll_source_at, CreepSource, FitOptions};
//!
//! let export =
//!     PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/pyvisco-ems-ca/freq_Eplexor_raw.xls");
//! // ingest → master curve (time–temperature shifts) → Prony fit → exact creep spectrum
//! let fit = fit_files("ems-ca", &[export], &FitOptions::default())?;
//! assert!(fit.creep.is_some() && fit.relaxation.terms.len() > 5);
//! // a 100 mm roll under 2 kN/m at 1 m/s on the half-space, the spectrum shifted to 20 °C
//! let scene = Scene {
//!     radius_m: 0.1,
//!     load_n_per_m: 2000.0,
//!     speed_m_s: 1.0,
//!     poisson: None,
//!     body: Body::HALF_SPACE,
//! };
//! let source = CreepSource::Fit(Box::new(fit));
//! let r = roll_source_at(&source, Some(20.0), &scene, &ContactSettings::default())?;
//! // rolling friction F/N: positive, and far below sliding friction for a rubber at room temperature
//! assert!(r.roll.friction > 0.0 && r.roll.friction < 0.1, "{}", r.roll.friction);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! From a relaxation spectrum to the rolling friction of one scene:
//!
//! ```
//! use viscoroll::contact::{roll, Body, ContactSettings, Scene};
//! use viscoroll::creep::relaxation_to_creep;
//! use viscoroll::prony::{RelaxationSpectrum, RelaxationTerm};
//! use viscoroll::ModulusKind;
//!
//! // A standard linear solid: E∞ = 3 MPa, one 1 GPa term relaxing in 1 ms.
//! let relaxation = RelaxationSpectrum {
//!     kind: ModulusKind::Tensile,
//!     poisson: 0.5,
//!     modulus_inf_pa: 3e6,
//!     terms: vec![RelaxationTerm { modulus_pa: 1e9, tau_s: 1e-3 }],
//! };
//! let (creep, _info) = relaxation_to_creep(&relaxation).unwrap();
//! // The glassy compliance is 1/E₀ (docs/MATH.md §4).
//! assert!((creep.compliance_glassy_per_pa * (1e9 + 3e6) - 1.0).abs() < 1e-12);
//!
//! // A 100 mm roll under 2 kN/m at 1 m/s.
//! let scene = Scene {
//!     radius_m: 0.1,
//!     load_n_per_m: 2000.0,
//!     speed_m_s: 1.0,
//!     poisson: None,
//!     body: Body::HALF_SPACE,
//! };
//! // The default scheme is `auto` (error-controlled, tolerance 1e-6).
//! let r = roll(&scene, &creep, &ContactSettings::default()).unwrap();
//! // Dissipation makes the friction positive; the contact lies between the glassy and relaxed
//! // Hertz lengths l = 2√(4RN(1−ν²)/(πE)).
//! let hertz = |e: f64| 2.0 * (4.0 * 0.1 * 2000.0 * 0.75 / (std::f64::consts::PI * e)).sqrt();
//! assert!(r.friction > 0.0);
//! assert!(r.contact_length_m > hertz(1e9 + 3e6) && r.contact_length_m < hertz(3e6));
//! ```

pub mod fsutil;
pub mod limits;
pub mod material;
pub(crate) mod special;

pub mod bands;
pub mod contact;
pub mod creep;
pub mod dma;
pub mod pipeline;
pub mod prony;
pub mod report;
pub mod results;
pub mod tts;

pub mod testdata;

pub mod cli;

// The crate's own tests (src/tests/) name the crate `viscoroll`, as the integration tests do.
#[cfg(test)]
extern crate self as viscoroll;
#[cfg(test)]
mod tests;

pub use creep::CreepSpectrum;
pub use dma::Measurement;
pub use material::{ModulusKind, ShiftLaw};
pub use prony::RelaxationSpectrum;
