//! Stage `dma` (ingest): readers for instrument exports, unit and locale handling, splitting into
//! isothermal sweeps and data checks → [`Measurement`].

use crate::ModulusKind;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Everything read from one or more DMA export files: isothermal frequency sweeps in SI units.
///
/// Moduli stay of the kind measured (`kind`: tensile E′, E″ or shear G′, G″); nothing is converted
/// silently. Flagged points stay in, with their flags.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Measurement {
    /// The input files, with their SHA-256 and detected format.
    pub sources: Vec<SourceFile>,
    /// Tensile or shear moduli.
    pub kind: ModulusKind,
    /// Poisson's ratio stated for tensile ↔ shear conversion.
    pub poisson: f64,
    /// Isothermal frequency sweeps, in order of temperature.
    pub isotherms: Vec<Isotherm>,
    /// Warnings that concern the whole measurement or a file.
    pub warnings: Vec<String>,
}

/// One input file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SourceFile {
    /// Path as given by the user.
    pub path: String,
    /// SHA-256 of the file's bytes, lower-case hex.
    pub sha256: String,
    /// Detected (or chosen) format name.
    pub format: String,
    /// Instrument metadata found in the file (key → value).
    pub metadata: BTreeMap<String, String>,
}

/// One isothermal frequency sweep.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Isotherm {
    /// Nominal (set) temperature in °C.
    pub temp_nominal_c: f64,
    /// Mean measured temperature of the points in °C.
    pub temp_mean_c: f64,
    /// Index into [`Measurement::sources`].
    pub source: usize,
    /// The points, in the order measured.
    pub points: Vec<DataPoint>,
}

/// One measured point.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DataPoint {
    /// Frequency in Hz.
    pub freq_hz: f64,
    /// Storage modulus (E′ or G′, per `Measurement::kind`) in Pa.
    pub storage_pa: f64,
    /// Loss modulus (E″ or G″) in Pa.
    pub loss_pa: f64,
    /// Measured temperature of this point in °C, when the file gives one.
    pub temp_c: Option<f64>,
    /// Where it came from: line (text) or sheet row, 1-based.
    pub line: usize,
    /// Quality flags; a flagged point is kept, never silently dropped.
    pub flags: Vec<String>,
}
