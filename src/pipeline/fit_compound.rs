//! One compound from its DMA exports to a [`CompoundFit`]: ingest → master curve → Prony fit → exact
//! creep spectrum; and the checks that decide whether an existing fit file can be reused.
//!
//! Input: file paths + [`FitOptions`]; output: [`CompoundFit`] (with `creep` and `tts` filled in).
//! Math: master curve docs/MATH.md §6 (crate::tts), Prony QP docs/MATH.md §5 (crate::prony), exact conversion
//! docs/MATH.md §4 (crate::creep::exact). Reuse rule: same SHA-256 of every input (as a multiset, paths
//! ignored), same settings, same tool version.

use super::error::PipelineError;
use crate::bands::BandSettings;
use crate::dma::{read_files, IngestOptions};
use crate::prony::{fit_prony, MasterPoint as PronyPoint, PronySettings};
use crate::results::{CompoundFit, QualityFigure, TtsSummary};
use crate::tts::{build_master_curve, LawChoice, MasterSettings};
use std::path::{Path, PathBuf};

/// Bound on the worst overlap RMS of the master curve (log10 units) above which it is flagged: 0.05
/// is about 12 % scatter between neighbouring isotherms, five times a good DMA's repeatability.
pub(crate) const MASTER_OVERLAP_RMS_BOUND: f64 = 0.05;

/// Settings of the whole fit, stored in the fit file so a re-run can tell whether it may reuse it.
#[derive(Debug, Clone, PartialEq)]
pub struct FitOptions {
    /// Master-curve settings.
    pub master: MasterSettings,
    /// Prony-fit settings.
    pub prony: PronySettings,
}

impl Default for FitOptions {
    fn default() -> Self {
        Self {
            // The criterion `viscoroll master` uses by default (slope-weighted: per isotherm, the
            // channel that carries the shift there; crate::tts::ShiftCriterion::SlopeWeighted).
            // The law used for friction is the table of the shifts found (a monotone cubic between
            // them, docs/MATH.md eq. 6.3; extrapolated
            // linearly from the end segments): on the shipped EMS-CA and DMA-suite sets the fitted WLF
            // and Arrhenius laws miss the shifts by 0.77–1.7 decades RMS, which would move the
            // friction curves by as much in temperature terms; WLF and Arrhenius stay in the fit file
            // (`tts`) for the datasheet and the FEA cards.
            // Each point is moved to its isotherm's temperature first (crate::tts::point_temps):
            // on the synthetic exports of tests/known_truth.rs (±1.5 K drift, 1 %/3 % noise) the
            // mean |shift error| at −40 °C fell from 0.04–0.11 to 0.016–0.019 decade (4 seeds).
            master: MasterSettings {
                law: LawChoice::Table,
                correct_point_temperatures: true,
                ..MasterSettings::default()
            },
            prony: PronySettings::default(),
        }
    }
}

impl FitOptions {
    /// The settings as stored under `settings.stages` of a fit file.
    pub(crate) fn stages(&self) -> std::collections::BTreeMap<String, serde_json::Value> {
        let mut m = std::collections::BTreeMap::new();
        m.insert(
            "tts".to_string(),
            serde_json::to_value(&self.master).unwrap_or(serde_json::Value::Null),
        );
        m
    }
}

/// Whether `fit` was made from inputs with exactly these hashes, with `options`, by this build.
pub(crate) fn fit_matches(fit: &CompoundFit, hashes: &[String], options: &FitOptions) -> bool {
    let mut have: Vec<String> = fit
        .provenance
        .inputs
        .iter()
        .map(|i| i.sha256.clone())
        .collect();
    have.sort();
    have == hashes
        && fit.settings.prony == options.prony
        && fit.settings.stages == options.stages()
        && fit.provenance.tool_version == env!("CARGO_PKG_VERSION")
        && fit.creep.is_some()
}

/// Read `files` as one measurement and fit it (see the module docs).
pub fn fit_files(
    compound: &str,
    files: &[PathBuf],
    options: &FitOptions,
) -> Result<CompoundFit, PipelineError> {
    let measurement = read_files(files, &IngestOptions::default())?;
    fit_measurement(compound, &measurement, options)
}

/// Fit one measurement: master curve, Prony series, exact creep spectrum, quality figures.
pub fn fit_measurement(
    compound: &str,
    measurement: &crate::Measurement,
    options: &FitOptions,
) -> Result<CompoundFit, PipelineError> {
    Ok(fit_measurement_master(compound, measurement, options)?.0)
}

/// [`fit_measurement`], also handing on the master curve (the bands resample it).
pub fn fit_measurement_master(
    compound: &str,
    measurement: &crate::Measurement,
    options: &FitOptions,
) -> Result<(CompoundFit, crate::tts::MasterCurve), PipelineError> {
    let master = build_master_curve(measurement, &options.master)?;
    let fit = fit_master_curve(compound, measurement, &master, options)?;
    Ok((fit, master))
}

/// Fit a master curve already built (or read already shifted, [`crate::tts::master_curve_from_reduced`]):
/// Prony series, exact creep spectrum, quality figures. `measurement` is what the master curve was
/// made from (its sources are the fit's inputs). A master curve read already shifted has one
/// isotherm; its shift law's table (when it is one) gives the shifts and the WLF and Arrhenius fits
/// stored for the datasheet and the cards.
pub fn fit_master_curve(
    compound: &str,
    measurement: &crate::Measurement,
    master: &crate::tts::MasterCurve,
    options: &FitOptions,
) -> Result<CompoundFit, PipelineError> {
    // Points of an isotherm placed by the law, not by overlap, weighted by their shift's
    // uncertainty (docs/MATH.md eq. 5.1).
    let points: Vec<PronyPoint> = master
        .points
        .iter()
        .zip(crate::tts::point_weights(master))
        .map(|(p, weight)| PronyPoint {
            weight,
            ..PronyPoint::new(p.reduced_freq_hz, p.storage_pa, p.loss_pa)
        })
        .collect();
    let prony = fit_prony(&points, master.kind, master.poisson, &options.prony)?;
    let (creep, _info) = crate::creep::relaxation_to_creep(&prony.spectrum)?;
    let mut fit = CompoundFit::new(
        compound,
        measurement,
        master.shift_law.clone(),
        points,
        prony,
        options.prony.clone(),
    );
    fit.creep = Some(creep);
    fit.settings.stages = options.stages();
    fit.quality.push(QualityFigure::bounded(
        "master_overlap_rms_max_log10",
        master.quality.overlap_rms_max_log10,
        "log10",
        MASTER_OVERLAP_RMS_BOUND,
    ));
    let mut law_rms = Vec::new();
    let shifts: Vec<(f64, f64)> = match (&master.shift_law, master.isotherms.len()) {
        (crate::ShiftLaw::Table { points, .. }, 1) => points.clone(),
        _ => master
            .isotherms
            .iter()
            .map(|i| (i.temp_c, i.log10_a_t))
            .collect(),
    };
    let (wlf, arrhenius) = if master.isotherms.len() == 1 && shifts.len() > 2 {
        // Read already shifted: fit the laws to the table that came with it.
        let t_ref = master.t_ref_c;
        (
            crate::tts::fit_laws::fit_wlf(&shifts, t_ref).ok(),
            crate::tts::fit_laws::fit_arrhenius(&shifts, t_ref).ok(),
        )
    } else {
        (master.wlf.clone(), master.arrhenius.clone())
    };
    if let Some(w) = &wlf {
        law_rms.push(("wlf".to_string(), w.rms_log10));
    }
    if let Some(a) = &arrhenius {
        law_rms.push(("arrhenius".to_string(), a.rms_log10));
    }
    fit.tts = Some(TtsSummary {
        shifts,
        wlf: wlf.as_ref().map(|w| w.law()),
        arrhenius: arrhenius.as_ref().map(|a| a.law()),
        law_rms_log10: law_rms,
        flags: master.quality.flags.clone(),
        warnings: master.warnings.clone(),
    });
    if fit.quality.iter().any(|q| q.flagged) {
        if let (Some(w), Some(tts)) = (
            worst_point(measurement, master, &fit.relaxation),
            fit.tts.as_mut(),
        ) {
            tts.warnings.push(w);
        }
    }
    Ok(fit)
}

/// A single point far off the fitted curve is reported when it is this many times the RMS log10
/// error of all other points and at least `WORST_POINT_MIN_LOG10` off: one such point is what turns a
/// good fit into one out of its quality bounds.
const WORST_POINT_RATIO: f64 = 10.0;
/// See [`WORST_POINT_RATIO`]: 0.3 decade is the data checks' outlier threshold (a factor 2).
const WORST_POINT_MIN_LOG10: f64 = 0.3;

/// When the fit is out of its bounds because of one point: that point's file, line, value and how
/// far off the fitted curve it is, with a suggestion (issue 15: a single far-off point names itself).
/// The master point is traced back to the measured point of its isotherm nearest in (log f, log E′,
/// log E″) after undoing the shifts.
fn worst_point(
    measurement: &crate::Measurement,
    master: &crate::tts::MasterCurve,
    spectrum: &crate::prony::RelaxationSpectrum,
) -> Option<String> {
    let errs: Vec<(f64, f64)> = master
        .points
        .iter()
        .map(|p| {
            let (e1, e2) = crate::prony::kernel::dynamic_moduli_pa(
                spectrum,
                2.0 * std::f64::consts::PI * p.reduced_freq_hz,
            );
            ((p.storage_pa / e1).log10(), (p.loss_pa / e2).log10())
        })
        .collect();
    let (k, loss) = errs
        .iter()
        .enumerate()
        .flat_map(|(k, e)| [(k, false, e.0), (k, true, e.1)])
        .filter(|e| e.2.is_finite())
        .max_by(|a, b| a.2.abs().total_cmp(&b.2.abs()))
        .map(|(k, loss, _)| (k, loss))?;
    let off = if loss { errs[k].1 } else { errs[k].0 };
    let others: Vec<f64> = errs
        .iter()
        .enumerate()
        .filter(|(j, _)| *j != k)
        .map(|(_, e)| if loss { e.1 } else { e.0 })
        .collect();
    let rms = (others.iter().map(|e| e * e).sum::<f64>() / others.len().max(1) as f64).sqrt();
    if !(off.abs() >= WORST_POINT_MIN_LOG10 && off.abs() >= WORST_POINT_RATIO * rms) {
        return None;
    }
    let mp = &master.points[k];
    let shift = master.isotherms.get(mp.isotherm)?;
    let iso = measurement.isotherms.get(shift.measurement_index)?;
    let file = measurement
        .sources
        .get(iso.source)
        .map_or("", |s| s.path.as_str());
    let dist = |p: &crate::dma::DataPoint| {
        (p.freq_hz.log10() + shift.log10_a_t - mp.reduced_freq_hz.log10()).abs()
            + (p.storage_pa.log10() - shift.log10_b_t - mp.storage_pa.log10()).abs()
            + (p.loss_pa.log10() - shift.log10_b_t - mp.loss_pa.log10()).abs()
    };
    let p = iso
        .points
        .iter()
        .filter(|p| dist(p).is_finite())
        .min_by(|a, b| dist(a).total_cmp(&dist(b)))?;
    let (what, value) = if loss {
        ("loss modulus", p.loss_pa)
    } else {
        ("storage modulus", p.storage_pa)
    };
    let place = match &iso.sheet {
        Some(sheet) => format!("{file}: sheet `{sheet}` row {}", p.line),
        None => format!("{file}: line {}", p.line),
    };
    Some(format!(
        "{place}: {what} {value:.4e} Pa at {:.4e} Hz, {} °C, is {off:.2} decades off the fitted curve while the other points are within {rms:.3} decade RMS: this one point breaks the fit. Check that cell (a typo or a slipped exponent?), or remove the row",
        p.freq_hz, iso.temp_nominal_c
    ))
}

/// Outcome of [`fit_or_reuse`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FitAction {
    /// The existing fit file matched and was reused.
    Reused,
    /// A new fit was made and written.
    Fitted,
    /// A different fit was replaced (`force`).
    Replaced,
    /// The fit file failed its content hash or validation (edited, damaged or older than content
    /// hashes), so it was fitted again and replaced.
    Repaired,
}

impl FitAction {
    /// The action in one word, as the CLI and the run summary show it.
    pub fn word(self) -> &'static str {
        match self {
            FitAction::Reused => "reused",
            FitAction::Fitted => "fitted",
            FitAction::Replaced => "replaced",
            FitAction::Repaired => "refitted",
        }
    }
}

/// [`fit_or_reuse`] for a master curve read already shifted (e.g. pyvisco's CSV with its shift
/// factors): `measurement` holds its reduced points and sources, `master` the curve made of them.
/// `options.master` should be `master.settings`, so that such a fit is never taken for one made
/// from the isotherms.
pub fn fit_or_reuse_master(
    compound: &str,
    measurement: &crate::Measurement,
    master: &crate::tts::MasterCurve,
    fit_path: &Path,
    options: &FitOptions,
    force: bool,
) -> Result<(CompoundFit, FitAction), PipelineError> {
    match existing(measurement, fit_path, options, force)? {
        Existing::Matches(old) => Ok((*old, FitAction::Reused)),
        Existing::Make(action) => {
            let fit = fit_master_curve(compound, measurement, master, options)?;
            fit.write(fit_path, force || action == FitAction::Repaired)?;
            Ok((fit, action))
        }
    }
}

/// What lies at a fit path.
enum Existing {
    /// A fit of these inputs with these settings by this build: reuse it.
    Matches(Box<CompoundFit>),
    /// None, or a different one that `force` lets us replace: make it (`Fitted` or `Replaced`).
    Make(FitAction),
}

/// Whether the fit at `fit_path` can be reused; a different fit without `force` is an error.
fn existing(
    measurement: &crate::Measurement,
    fit_path: &Path,
    options: &FitOptions,
    force: bool,
) -> Result<Existing, PipelineError> {
    let mut hashes: Vec<String> = measurement
        .sources
        .iter()
        .map(|s| s.sha256.clone())
        .collect();
    hashes.sort();
    if std::fs::symlink_metadata(fit_path).is_err() {
        return Ok(Existing::Make(FitAction::Fitted));
    }
    match CompoundFit::read(fit_path) {
        Ok(old) if fit_matches(&old, &hashes, options) => Ok(Existing::Matches(Box::new(old))),
        // The tool's own file, unusable as it is: fit again (the run notes it).
        // (or not a regular file at all: a symlink planted there is replaced, never followed)
        Err(
            crate::results::CompoundFitError::Invalid { .. }
            | crate::results::CompoundFitError::Parse { .. }
            | crate::results::CompoundFitError::Io { .. },
        ) => Ok(Existing::Make(FitAction::Repaired)),
        _ if !force => Err(PipelineError::FitDiffers {
            path: fit_path.to_path_buf(),
        }),
        _ => Ok(Existing::Make(FitAction::Replaced)),
    }
}

/// Whether `fit` carries an ensemble made with `settings` (with or without the fit's own
/// choices, docs/MATH.md eqs. 15.10–15.12, as `settings.model_error` asks).
fn has_ensemble(fit: &CompoundFit, settings: &BandSettings) -> bool {
    fit.bands.as_ref().is_some_and(|b| {
        b.replicates_requested == settings.replicates
            && b.seed == settings.seed
            && b.model_error.is_some() == settings.model_error
    })
}

/// [`fit_or_reuse`], and with `bands` the fit's bootstrap ensemble (crate::bands): made with a new
/// fit, or added to a reused fit that lacks one (the fit file is then rewritten with it; its fit is
/// unchanged). The third value is why the ensemble could not be made, if it could not (the fit is
/// kept; its friction then has no bands).
pub fn fit_or_reuse_with_bands(
    compound: &str,
    measurement: &crate::Measurement,
    fit_path: &Path,
    options: &FitOptions,
    force: bool,
    bands: Option<&BandSettings>,
) -> Result<(CompoundFit, FitAction, Option<String>), PipelineError> {
    let add = |fit: &mut CompoundFit, master: &crate::tts::MasterCurve, s: &BandSettings| {
        match crate::bands::build_ensemble(master, measurement, fit, s) {
            Ok(e) => {
                fit.bands = Some(e);
                None
            }
            Err(e) => {
                fit.bands = None;
                Some(e.not_computed_warning())
            }
        }
    };
    match existing(measurement, fit_path, options, force)? {
        Existing::Matches(old) => {
            let Some(s) = bands.filter(|s| !has_ensemble(&old, s)) else {
                return Ok((*old, FitAction::Reused, None));
            };
            // The same fit, its ensemble added: the master curve is rebuilt (deterministic).
            let mut fit = *old;
            let master = build_master_curve(measurement, &options.master)?;
            let why = add(&mut fit, &master, s);
            if why.is_none() {
                fit.write(fit_path, true)?;
            }
            Ok((fit, FitAction::Reused, why))
        }
        Existing::Make(action) => {
            let (mut fit, master) = fit_measurement_master(compound, measurement, options)?;
            let why = bands.and_then(|s| add(&mut fit, &master, s));
            fit.write(fit_path, force || action == FitAction::Repaired)?;
            Ok((fit, action, why))
        }
    }
}
