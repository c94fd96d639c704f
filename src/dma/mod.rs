//! Stage `dma` (ingest): readers for instrument exports, unit and locale handling, splitting into
//! isothermal sweeps and data checks → [`Measurement`].

use crate::material::ModulusKind;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

pub(crate) mod checks;
pub(crate) mod column_map;
pub(crate) mod columns;
pub(crate) mod detect;
pub(crate) mod eplexor;
pub(crate) mod error;
pub(crate) mod generic;
pub(crate) mod isotherms;
pub(crate) mod mode_evidence;
pub(crate) mod plausible;
pub(crate) mod proteus;
pub(crate) mod pyvisco;
pub(crate) mod pyvisco_time;
mod read;
pub(crate) mod reptate;
pub(crate) mod rheocompass;
pub(crate) mod shiftfactors;
pub(crate) mod steps;
pub(crate) mod table;
pub(crate) mod text;
pub(crate) mod time_domain;
mod time_domain_error;
pub(crate) mod trios;
pub(crate) mod units;
pub(crate) mod xls_guard;
pub(crate) mod xlsx_guard;

pub(crate) use checks::Summary;
pub use checks::{CheckSettings, Flag, Issue, Severity};
pub use column_map::ColumnMap;
pub(crate) use columns::ColumnInfo;
pub use detect::Format;
#[cfg(test)]
pub(crate) use eplexor::read_eplexor_shiftlist;
pub use error::DmaError;
pub use isotherms::SplitSettings;
pub use pyvisco::PyviscoMaster;
pub use pyvisco_time::PyviscoTimeMaster;
pub(crate) use read::sha256_hex;
pub use read::{read_bytes, read_files, IngestOptions};
pub use shiftfactors::read_shift_factors;
#[cfg(test)]
pub(crate) use shiftfactors::read_shift_table;
pub use time_domain::TimeMode;

/// serde: a NaN written as `null` by serde_json reads back as NaN (flagged points are kept).
fn f64_or_nan<'de, D: serde::Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::NAN))
}

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
    /// Every finding of the checks, with file, place, column and severity.
    #[serde(default)]
    pub issues: Vec<Issue>,
    /// Counts: files, isotherms, points, flagged points, issues per flag, ranges.
    #[serde(default)]
    pub summary: Summary,
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
    /// Text encoding read (`UTF-8`, `UTF-16LE`, `windows-1252`, `Excel`…).
    #[serde(default)]
    pub encoding: String,
    /// The columns used, with their units as written.
    #[serde(default)]
    pub columns: Vec<ColumnInfo>,
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
    /// Where `temp_nominal_c` comes from: `file` (set temperature or step name), `file name`,
    /// `rounded mean` (mean measured temperature rounded to 0.5 K).
    #[serde(default)]
    pub nominal_source: String,
    /// Worksheet the points come from (then `DataPoint::line` is its row).
    #[serde(default)]
    pub sheet: Option<String>,
    /// Step, interval or result name in the file, if any.
    #[serde(default)]
    pub label: Option<String>,
}

/// One measured point.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DataPoint {
    /// Frequency in Hz.
    #[serde(deserialize_with = "f64_or_nan")]
    pub freq_hz: f64,
    /// Storage modulus (E′ or G′, per `Measurement::kind`) in Pa.
    #[serde(deserialize_with = "f64_or_nan")]
    pub storage_pa: f64,
    /// Loss modulus (E″ or G″) in Pa.
    #[serde(deserialize_with = "f64_or_nan")]
    pub loss_pa: f64,
    /// Measured temperature of this point in °C, when the file gives one.
    pub temp_c: Option<f64>,
    /// Where it came from: line (text) or sheet row, 1-based.
    pub line: usize,
    /// Quality flags; a flagged point is kept, never silently dropped.
    pub flags: Vec<String>,
}
