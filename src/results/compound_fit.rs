//! The fit file `fits/NAME.json` ([`CompoundFit`]): everything one compound's fit produced, the input
//! of `roll`, `sweep`, `export` and the reports.
//!
//! Input: a [`Measurement`] (summarised), a [`ShiftLaw`], master-curve points, a [`PronyFit`] and,
//! once the exact relaxation → creep conversion is merged, a [`CreepSpectrum`]. Output: a JSON file,
//! written atomically (temp file + rename) and never over an existing file without `force`.
//!
//! JSON outline (units in field names):
//! ```json
//! { "format_version": 1, "compound": "EMS-CA",
//!   "measurement": { "sources": [ { "path": "…", "sha256": "…", "format": "…", "metadata": {} } ],
//!                    "kind": "tensile", "poisson": 0.5, "n_isotherms": 21, "n_points": 210, … },
//!   "shift_law": { "law": "wlf", "t_ref_c": -5.0, "c1": 13.5, "c2_k": 141.2 },
//!   "master_curve": [ { "reduced_freq_hz": 1e-12, "storage_pa": 8.9e7, "loss_pa": 1.05e7 } ],
//!   "relaxation": { … RelaxationSpectrum … }, "prony_info": { … PronyInfo … },
//!   "creep": null, "quality": [ { "name": "prony_rms_log10_storage", "value": 0.03, … } ],
//!   "settings": { "prony": { … }, "stages": { } },
//!   "provenance": { "tool": "viscoroll", "tool_version": "0.1.0", "created_utc": null,
//!                   "inputs": [ { "path": "…", "sha256": "…" } ] } }
//! ```

use crate::dma::SourceFile;
use crate::prony::{MasterPoint, PronyFit, PronyInfo, PronySettings};
use crate::{CreepSpectrum, Measurement, ModulusKind, RelaxationSpectrum, ShiftLaw};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// The fit-file format version this build writes and reads.
pub const COMPOUND_FIT_FORMAT_VERSION: u32 = 1;

/// One compound's fit, as saved in `fits/NAME.json`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CompoundFit {
    /// File format version (`COMPOUND_FIT_FORMAT_VERSION`).
    pub format_version: u32,
    /// Compound name (the file stem by default).
    pub compound: String,
    /// What was measured (sources with their SHA-256, temperatures, frequency range).
    pub measurement: MeasurementSummary,
    /// The horizontal shift law log10 a_T(T) of the master curve.
    pub shift_law: ShiftLaw,
    /// The master-curve points at the shift law's reference temperature.
    pub master_curve: Vec<MasterPoint>,
    /// The fitted relaxation spectrum at the reference temperature.
    pub relaxation: RelaxationSpectrum,
    /// Diagnostics of the Prony fit.
    pub prony_info: PronyInfo,
    /// The creep spectrum (exact conversion of `relaxation`); `None` until that conversion has run.
    #[serde(default)]
    pub creep: Option<CreepSpectrum>,
    /// The shifts found per isotherm and both fitted laws (for the datasheet); `None` in older files.
    #[serde(default)]
    pub tts: Option<TtsSummary>,
    /// Quality figures of every stage (shift residuals, fit errors, consistency checks).
    #[serde(default)]
    pub quality: Vec<QualityFigure>,
    /// Resolved settings of every stage, so the fit can be reproduced.
    pub settings: FitSettings,
    /// The bootstrap ensemble of the uncertainty bands (crate::bands); `None` when bands were not
    /// computed (`viscoroll fit`, `run --no-bands`) or in older files.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bands: Option<super::band_ensemble::BandEnsemble>,
    /// Tool, version and input hashes.
    pub provenance: Provenance,
    /// SHA-256 (hex) of the fit's own content: the compact JSON of the fit with this field absent.
    /// Set by [`CompoundFit::write`], checked and cleared by [`CompoundFit::read`], so an edited or
    /// damaged fit file is refused (`None` in memory).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub content_sha256: Option<String>,
}

/// What the master-curve stage found besides the law used: shifts per isotherm and both laws.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TtsSummary {
    /// (temperature in °C, log10 a_T) of each isotherm.
    pub shifts: Vec<(f64, f64)>,
    /// The WLF fit of the shifts, if it succeeded.
    #[serde(default)]
    pub wlf: Option<ShiftLaw>,
    /// The Arrhenius fit of the shifts, if it succeeded.
    #[serde(default)]
    pub arrhenius: Option<ShiftLaw>,
    /// RMS of the shifts about the WLF and the Arrhenius law, log10 units.
    #[serde(default)]
    pub law_rms_log10: Vec<(String, f64)>,
    /// Quality flags of the master curve (in words).
    #[serde(default)]
    pub flags: Vec<String>,
    /// Warnings of the master-curve stage.
    #[serde(default)]
    pub warnings: Vec<String>,
}

/// A summary of the [`Measurement`] a fit was made from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MeasurementSummary {
    /// The input files, with their SHA-256 and format.
    pub sources: Vec<SourceFile>,
    /// Tensile or shear moduli.
    pub kind: ModulusKind,
    /// Poisson's ratio stated for tensile ↔ shear conversion.
    pub poisson: f64,
    /// Number of isothermal sweeps.
    pub n_isotherms: usize,
    /// Number of measured points over all sweeps.
    pub n_points: usize,
    /// Nominal temperatures of the sweeps in °C, in the measurement's order.
    pub temps_nominal_c: Vec<f64>,
    /// Lowest measured frequency in Hz (NaN-free; 0 when there are no points).
    pub freq_min_hz: f64,
    /// Highest measured frequency in Hz.
    pub freq_max_hz: f64,
    /// Warnings of the ingest stage.
    #[serde(default)]
    pub warnings: Vec<String>,
}

impl MeasurementSummary {
    /// Summarise a measurement.
    pub(crate) fn from_measurement(m: &Measurement) -> Self {
        let freqs = m
            .isotherms
            .iter()
            .flat_map(|i| i.points.iter().map(|p| p.freq_hz));
        let (lo, hi) = freqs.fold((f64::INFINITY, 0.0f64), |(lo, hi), f| {
            (lo.min(f), hi.max(f))
        });
        Self {
            sources: m.sources.clone(),
            kind: m.kind,
            poisson: m.poisson,
            n_isotherms: m.isotherms.len(),
            n_points: m.isotherms.iter().map(|i| i.points.len()).sum(),
            temps_nominal_c: m.isotherms.iter().map(|i| i.temp_nominal_c).collect(),
            freq_min_hz: if lo.is_finite() { lo } else { 0.0 },
            freq_max_hz: hi,
            warnings: m.warnings.clone(),
        }
    }
}

/// One quality figure with its bound, e.g. the RMS log10 error of E′ of the Prony fit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct QualityFigure {
    /// Stable name, `stage_quantity` (e.g. `prony_rms_log10_storage`).
    pub name: String,
    /// The value.
    pub value: f64,
    /// Its unit (`"log10"`, `"K"`, `"1"`, …).
    pub unit: String,
    /// The bound it is checked against, if any (the value is flagged when above it).
    #[serde(default)]
    pub bound: Option<f64>,
    /// Whether the value is out of its bound.
    #[serde(default)]
    pub flagged: bool,
}

impl QualityFigure {
    /// A figure checked against an upper bound (flagged when `value > bound` or not finite).
    pub fn bounded(name: &str, value: f64, unit: &str, bound: f64) -> Self {
        Self {
            name: name.to_string(),
            value,
            unit: unit.to_string(),
            bound: Some(bound),
            flagged: value.is_nan() || value > bound,
        }
    }
}

/// Resolved settings of the stages that produced a fit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FitSettings {
    /// Prony-fit settings.
    pub prony: PronySettings,
    /// Settings of the other stages (e.g. `"tts"`), as the stage serialises them.
    #[serde(default)]
    pub stages: BTreeMap<String, serde_json::Value>,
}

/// Where a fit came from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Provenance {
    /// Tool name (`viscoroll`).
    pub tool: String,
    /// Tool version (the crate version).
    pub tool_version: String,
    /// Creation time, ISO 8601 UTC, when the caller wants one (left out for reproducible files).
    #[serde(default)]
    pub created_utc: Option<String>,
    /// The input files with their SHA-256.
    pub inputs: Vec<InputHash>,
}

/// One input file and its SHA-256.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct InputHash {
    /// Path as given.
    pub path: String,
    /// SHA-256 of the file's bytes, lower-case hex.
    pub sha256: String,
}

impl Provenance {
    /// This build's provenance for the given inputs, without a timestamp.
    pub(crate) fn for_inputs(inputs: Vec<InputHash>) -> Self {
        Self {
            tool: "viscoroll".to_string(),
            tool_version: env!("CARGO_PKG_VERSION").to_string(),
            created_utc: None,
            inputs,
        }
    }
}

/// Bounds the Prony quality figures are flagged against: pyvisco's published fit of EMS-CA
/// (RMS log10 error 0.04 on E′, 0.15 on E″; data/SOURCES.md), the best known reference for what a
/// good fit of real DMA data reaches.
pub(crate) const PRONY_RMS_LOG10_STORAGE_BOUND: f64 = 0.04;
/// See [`PRONY_RMS_LOG10_STORAGE_BOUND`].
pub(crate) const PRONY_RMS_LOG10_LOSS_BOUND: f64 = 0.15;

/// The Prony stage's quality figures.
pub(crate) fn prony_quality(info: &PronyInfo) -> Vec<QualityFigure> {
    vec![
        QualityFigure::bounded(
            "prony_rms_log10_storage",
            info.rms_log10_storage,
            "log10",
            PRONY_RMS_LOG10_STORAGE_BOUND,
        ),
        QualityFigure::bounded(
            "prony_rms_log10_loss",
            info.rms_log10_loss,
            "log10",
            PRONY_RMS_LOG10_LOSS_BOUND,
        ),
    ]
}

impl CompoundFit {
    /// Assemble a fit file from the stages' results. `creep` stays `None` until the exact conversion
    /// is available (INTEGRATION POINT: `crate::creep::exact` on branch `spectra`).
    pub fn new(
        compound: &str,
        measurement: &Measurement,
        shift_law: ShiftLaw,
        master_curve: Vec<MasterPoint>,
        prony: PronyFit,
        prony_settings: PronySettings,
    ) -> Self {
        let inputs = measurement
            .sources
            .iter()
            .map(|s| InputHash {
                path: s.path.clone(),
                sha256: s.sha256.clone(),
            })
            .collect();
        Self {
            format_version: COMPOUND_FIT_FORMAT_VERSION,
            compound: compound.to_string(),
            measurement: MeasurementSummary::from_measurement(measurement),
            shift_law,
            master_curve,
            quality: prony_quality(&prony.info),
            relaxation: prony.spectrum,
            prony_info: prony.info,
            creep: None,
            tts: None,
            settings: FitSettings {
                prony: prony_settings,
                stages: BTreeMap::new(),
            },
            provenance: Provenance::for_inputs(inputs),
            bands: None,
            content_sha256: None,
        }
    }

    /// Write as pretty JSON to `path`, atomically: a temp file in the same folder, flushed, then
    /// moved into place. Refuses to replace an existing file unless `force`.
    pub fn write(&self, path: &Path, force: bool) -> Result<(), CompoundFitError> {
        let io = |e| CompoundFitError::Io {
            path: path.to_path_buf(),
            source: e,
        };
        let ser = |e: serde_json::Error| CompoundFitError::Serialize {
            message: e.to_string(),
        };
        let mut sealed = self.clone();
        sealed.content_sha256 = Some(self.content_hash().map_err(ser)?);
        let mut json = serde_json::to_string_pretty(&sealed).map_err(ser)?;
        json.push('\n');
        crate::fsutil::write_atomic_durable(path, json.as_bytes(), force).map_err(|e| {
            if e.kind() == std::io::ErrorKind::AlreadyExists {
                CompoundFitError::Exists {
                    path: path.to_path_buf(),
                }
            } else {
                io(e)
            }
        })
    }

    /// The measured temperature range (°C): lowest and highest nominal isotherm temperature;
    /// `None` without isotherms. Temperatures outside it extrapolate the shift law.
    pub fn measured_range_c(&self) -> Option<(f64, f64)> {
        let t = &self.measurement.temps_nominal_c;
        let lo = t.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = t.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        (lo.is_finite() && hi.is_finite()).then_some((lo, hi))
    }

    /// Why the fit is not trusted: each quality figure out of its bound (empty when trusted).
    pub fn untrusted_reasons(&self) -> Vec<String> {
        self.quality
            .iter()
            .filter(|q| q.flagged)
            .map(|q| match q.bound {
                Some(b) => format!(
                    "{} = {:.4} {} is out of its bound {b}",
                    q.name, q.value, q.unit
                ),
                None => format!("{} = {:.4} {} is flagged", q.name, q.value, q.unit),
            })
            .collect()
    }

    /// The SHA-256 (hex) of the fit's content: its compact JSON without `content_sha256`. Numbers
    /// round-trip exactly through serde_json, so a read fit hashes as the written one did.
    pub fn content_hash(&self) -> Result<String, serde_json::Error> {
        let mut bare = self.clone();
        bare.content_sha256 = None;
        Ok(crate::dma::sha256_hex(&serde_json::to_vec(&bare)?))
    }

    /// Check everything later stages rely on: a valid shift law (a table of at least two finite,
    /// increasing rows), finite shifts, a valid relaxation spectrum (positive moduli and times) and
    /// creep spectrum within the work budget's term count, master-curve points finite and > 0, and
    /// one modulus kind throughout. Returns what is wrong, in words.
    pub fn validate(&self) -> Result<(), String> {
        self.shift_law
            .validate()
            .map_err(|e| format!("shift_law: {e}"))?;
        if let Some(t) = &self.tts {
            if let Some(i) = t
                .shifts
                .iter()
                .position(|(a, b)| !(a.is_finite() && b.is_finite()))
            {
                return Err(format!("tts.shifts[{i}] is not finite"));
            }
        }
        let budget = |key: &str, n: usize| {
            crate::limits::at_most(key, n, crate::limits::PRONY_TERMS_MAX)
                .map_err(|e| e.to_string())
        };
        budget("relaxation.terms", self.relaxation.terms.len())?;
        self.relaxation
            .validate()
            .map_err(|e| format!("relaxation: {e}"))?;
        if self.relaxation.kind != self.measurement.kind {
            return Err("relaxation.kind differs from measurement.kind".into());
        }
        if let Some(c) = &self.creep {
            budget("creep.terms", c.terms.len())?;
            c.validate().map_err(|e| format!("creep: {e}"))?;
            if c.kind != self.relaxation.kind {
                return Err("creep.kind differs from relaxation.kind".into());
            }
        }
        let bad_point = self.master_curve.iter().position(|p| {
            ![p.reduced_freq_hz, p.storage_pa, p.loss_pa]
                .iter()
                .all(|v| v.is_finite() && *v > 0.0)
        });
        if let Some(i) = bad_point {
            return Err(format!("master_curve[{i}] is not finite and > 0"));
        }
        Ok(())
    }

    /// Why results of this fit are to be used with care (issue 31): the master-curve checks that
    /// flagged something (isotherm overlap, Kramers–Kronig, van Gurp–Palmen), as one reason.
    pub(crate) fn care_reasons(&self) -> Vec<String> {
        let mut care = match &self.tts {
            Some(t) if !t.flags.is_empty() => vec![super::outcome::cap_line(&format!(
                "master curve: {} check(s) flagged: {}",
                t.flags.len(),
                t.flags.join("; ")
            ))],
            _ => vec![],
        };
        // A fit to relaxation or creep data: E″ is read from the slope of E(t) or J(t), so its
        // friction counts only at the points the data determine (crate::pipeline::fit_time,
        // docs/MATH.md eqs. 18.3 and 18.6); the others are marked, not ranked.
        if self.prony_info.time_domain.is_some() {
            care.push(
                "fitted to time-domain data (relaxation or creep): friction only where the data \
                 resolve E″ (docs/MATH.md §18); the other temperatures are marked not determined"
                    .to_string(),
            );
        }
        care
    }

    /// Read a fit file, checking its format version, its content hash ([`Self::content_hash`]) and
    /// its content ([`Self::validate`]). Only a regular file within the work budget's size is read.
    pub fn read(path: &Path) -> Result<Self, CompoundFitError> {
        let text = crate::fsutil::read_regular_to_string(path, crate::limits::INPUT_BYTES_MAX)
            .map_err(|e| CompoundFitError::Io {
                path: path.to_path_buf(),
                source: e,
            })?;
        // Check the version first, so an old or future file gets that message, not a field error.
        let version = serde_json::from_str::<VersionOnly>(&text)
            .ok()
            .and_then(|v| v.format_version);
        match version {
            Some(COMPOUND_FIT_FORMAT_VERSION) => {}
            Some(found) => {
                return Err(CompoundFitError::UnsupportedVersion {
                    path: path.to_path_buf(),
                    found,
                    supported: COMPOUND_FIT_FORMAT_VERSION,
                })
            }
            None => {}
        }
        let mut fit: CompoundFit =
            serde_json::from_str(&text).map_err(|e| CompoundFitError::Parse {
                path: path.to_path_buf(),
                line: e.line(),
                column: e.column(),
                message: e.to_string(),
            })?;
        let invalid = |reason: String| CompoundFitError::Invalid {
            path: path.to_path_buf(),
            reason,
        };
        let stored = fit.content_sha256.take();
        let actual = fit.content_hash().map_err(|e| invalid(e.to_string()))?;
        match stored {
            None => {
                return Err(invalid(
                    "it carries no content hash (written by an older viscoroll, or edited)".into(),
                ))
            }
            Some(h) if h != actual => {
                return Err(invalid(
                    "its content does not match its content hash (edited or damaged)".into(),
                ))
            }
            Some(_) => {}
        }
        fit.validate().map_err(invalid)?;
        Ok(fit)
    }
}

#[derive(Deserialize)]
struct VersionOnly {
    format_version: Option<u32>,
}

/// Why a fit file could not be written or read.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum CompoundFitError {
    /// The output file exists and `force` was not given.
    #[error("{path}: a fit file already exists; pass --force to replace it")]
    Exists {
        /// The path.
        path: PathBuf,
    },
    /// Reading or writing failed.
    #[error("{path}: {source}")]
    Io {
        /// The path.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The file is not a valid fit file.
    #[error("{path}:{line}:{column}: not a valid viscoroll fit file: {message}")]
    Parse {
        /// The path.
        path: PathBuf,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// serde's message (names the field).
        message: String,
    },
    /// The file has a format version this build does not read.
    #[error("{path}: fit-file format version {found} is not supported (this build reads version {supported})")]
    UnsupportedVersion {
        /// The path.
        path: PathBuf,
        /// Version in the file.
        found: u32,
        /// Version this build reads.
        supported: u32,
    },
    /// The file fails its content hash or its validation ([`CompoundFit::validate`]).
    #[error("{path}: not a trustworthy fit file: {reason}; fit again (`viscoroll run` refits it, or `viscoroll fit --force`)")]
    Invalid {
        /// The path.
        path: PathBuf,
        /// What is wrong.
        reason: String,
    },
    /// Serialising failed (non-finite numbers are written as null by serde_json, so this is rare).
    #[error("could not serialise the fit: {message}")]
    Serialize {
        /// serde's message.
        message: String,
    },
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dma::{DataPoint, Isotherm};
    use crate::prony::synthetic::{master_points, rubber_like_spectrum};
    use crate::prony::{fit_prony, relaxation_times_s};

    fn sample() -> CompoundFit {
        // L-curve: its search has end points without a score (`null` in JSON), which must round-trip.
        let s = PronySettings {
            weight_rule: crate::prony::WeightRule::LCurve,
            ..PronySettings::default()
        };
        let truth = rubber_like_spectrum(&relaxation_times_s(1e-2, 1e4, &s));
        let pts = master_points(&truth, 1e-2, 1e4, 5.0, 0.0, 1);
        let fit = fit_prony(&pts, ModulusKind::Tensile, 0.5, &s).unwrap();
        let m = Measurement {
            sources: vec![SourceFile {
                path: "a.txt".into(),
                sha256: "ab".repeat(32),
                format: "synthetic".into(),
                metadata: BTreeMap::new(),
                encoding: String::new(),
                columns: vec![],
            }],
            kind: ModulusKind::Tensile,
            poisson: 0.5,
            isotherms: vec![Isotherm {
                temp_nominal_c: 20.0,
                temp_mean_c: 20.1,
                source: 0,
                nominal_source: String::new(),
                sheet: None,
                label: None,
                points: [0.1, 10.0]
                    .iter()
                    .map(|&f| DataPoint {
                        freq_hz: f,
                        storage_pa: 1e7,
                        loss_pa: 1e6,
                        temp_c: None,
                        line: 1,
                        flags: vec![],
                    })
                    .collect(),
            }],
            warnings: vec![],
            issues: vec![],
            summary: Default::default(),
        };
        let law = ShiftLaw::Wlf {
            t_ref_c: 20.0,
            c1: 8.86,
            c2_k: 101.6,
        };
        CompoundFit::new("demo", &m, law, pts, fit, s)
    }

    fn temp_dir(tag: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("viscoroll-cf-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn round_trip_and_no_clobber() {
        let dir = temp_dir("rt");
        let path = dir.join("fits").join("demo.json");
        let fit = sample();
        assert_eq!(fit.measurement.n_points, 2);
        assert_eq!(
            (fit.measurement.freq_min_hz, fit.measurement.freq_max_hz),
            (0.1, 10.0)
        );
        assert_eq!(fit.provenance.inputs[0].sha256, "ab".repeat(32));
        fit.write(&path, false).unwrap();
        assert_eq!(CompoundFit::read(&path).unwrap(), fit);
        // An existing file is kept without force …
        let mut other = fit.clone();
        other.compound = "other".into();
        let err = other.write(&path, false).unwrap_err();
        assert!(matches!(err, CompoundFitError::Exists { .. }), "{err}");
        assert_eq!(CompoundFit::read(&path).unwrap().compound, "demo");
        // … and replaced with it; no temp file is left behind.
        other.write(&path, true).unwrap();
        assert_eq!(CompoundFit::read(&path).unwrap().compound, "other");
        let names: Vec<_> = std::fs::read_dir(path.parent().unwrap())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(names.len(), 1, "{names:?}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn read_errors_name_the_problem() {
        let dir = temp_dir("err");
        let p = dir.join("bad.json");
        std::fs::write(&p, "{\"format_version\": 1, \"compound\": 3}").unwrap();
        let e = CompoundFit::read(&p).unwrap_err().to_string();
        assert!(
            e.contains("bad.json:1:") && e.contains("not a valid viscoroll fit file"),
            "{e}"
        );
        std::fs::write(&p, "{\"format_version\": 99}").unwrap();
        let e = CompoundFit::read(&p).unwrap_err().to_string();
        assert!(e.contains("version 99 is not supported"), "{e}");
        let e = CompoundFit::read(&dir.join("missing.json"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("missing.json"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn quality_flags_follow_the_published_bounds() {
        let q = QualityFigure::bounded("x", 0.05, "log10", 0.04);
        assert!(q.flagged);
        assert!(!QualityFigure::bounded("x", 0.04, "log10", 0.04).flagged);
        assert!(QualityFigure::bounded("x", f64::NAN, "log10", 0.04).flagged);
    }
}
