//! One scene on a creep spectrum from a file: a bare creep spectrum (JSON, [`CreepSpectrum`]), or a
//! compound's fit (`fits/NAME.json`, [`CompoundFit`]) whose spectrum is moved to a temperature by its
//! shift law (`CreepSpectrum::at_temperature`, docs/MATH.md §6), then rolled with [`contact::roll`].
//!
//! Input: a path (or a fit), an optional temperature in °C, a [`Scene`] and [`ContactSettings`];
//! output: [`SourceRoll`] (the contact answer, the shift applied and the warnings, temperature
//! warnings first) or a [`PipelineError`]. Used by `viscoroll roll` and by the main job
//! ([`super::scenes::friction_vs_temperature`]), so both give the same friction for the same scene.

use super::error::{io, PipelineError};
use crate::contact::{self, ContactSettings, RollSolution, Scene};
use crate::creep::AtTemperature;
use crate::results::CompoundFit;
use crate::CreepSpectrum;
use std::path::Path;

/// Where a creep spectrum comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum CreepSource {
    /// A compound's fit: its spectrum is at T_ref and needs a temperature.
    Fit(Box<CompoundFit>),
    /// A bare creep spectrum (no shift law: used as it is).
    Spectrum(CreepSpectrum),
}

impl CreepSource {
    /// Read a fit file (it has a `format_version`), a bare creep spectrum (JSON), or pyvisco's
    /// Prony-term CSV (crate::prony::pyvisco_csv, ν = 0.5), converted exactly to creep (§4). A fluid,
    /// E∞ = 0, is refused, as a relaxation spectrum or as the creep function `convert` writes for it
    /// (its `viscosity_pa_s`): no steady rolling state (docs/MATH.md §17).
    pub fn read(path: &Path) -> Result<Self, PipelineError> {
        let bytes =
            crate::fsutil::read_regular(path, crate::limits::INPUT_BYTES_MAX).map_err(io(path))?;
        if crate::prony::pyvisco_csv::looks_like_pyvisco_terms(&bytes) {
            let relax = crate::prony::pyvisco_csv::read_pyvisco_terms(
                &path.display().to_string(),
                &bytes,
                crate::material::default_poisson(),
            )?;
            let (creep, _) = crate::creep::relaxation_to_creep(&relax)?;
            return Ok(CreepSource::Spectrum(creep));
        }
        let text = String::from_utf8_lossy(&bytes).into_owned();
        let config = |message: String| PipelineError::Config {
            path: path.to_path_buf(),
            message,
        };
        let value: serde_json::Value = serde_json::from_str(&text)
            .map_err(|e| config(format!("not a creep spectrum or fit file: {e}")))?;
        if value.get("format_version").is_some() {
            Ok(CreepSource::Fit(Box::new(CompoundFit::read(path)?)))
        } else if let Some(eta) = value.get("viscosity_pa_s") {
            // A fluid's creep function as `convert` writes it (flow term t/η₀ apart).
            Err(config(format!(
                "a fluid's creep function (flow term t/η₀, viscosity_pa_s = {eta}). {}",
                crate::creep::FLUID_NO_STEADY_ROLLING
            )))
        } else {
            serde_json::from_value(value)
                .map(CreepSource::Spectrum)
                .map_err(|e| config(format!("not a creep spectrum: {e}")))
        }
    }
}

/// A scene's answer on a [`CreepSource`].
#[derive(Debug, Clone, PartialEq)]
pub struct SourceRoll {
    /// The contact answer (its own warnings in `dimensionless.warnings`).
    pub roll: RollSolution,
    /// The spectrum used (shifted to the temperature for a fit).
    pub spectrum: CreepSpectrum,
    /// The temperature, log10 a_T and whether it was extrapolated (fits only).
    pub shift: Option<AtTemperature<()>>,
    /// Every warning for the user: the temperature's first, then the solver's.
    pub warnings: Vec<String>,
}

/// The creep spectrum of `fit` at `temp_c` (°C), with a warning when the temperature lies outside
/// the measured ones (the shift law is then extrapolated).
pub fn fit_spectrum_at(
    fit: &CompoundFit,
    temp_c: f64,
) -> Result<(AtTemperature<CreepSpectrum>, Option<String>), PipelineError> {
    let creep = fit.creep.as_ref().ok_or_else(|| PipelineError::NoCreep {
        compound: fit.compound.clone(),
    })?;
    let range = fit.measured_range_c();
    let at = creep.at_temperature(&fit.shift_law, temp_c, range)?;
    let warning = at.extrapolated.then(|| {
        let (lo, hi) = range.unwrap_or((f64::NAN, f64::NAN));
        format!(
            "{temp_c} °C lies outside the measured temperatures {lo} … {hi} °C: the shift law is extrapolated"
        )
    });
    Ok((at, warning))
}

/// Roll `scene` on `source`: a fit is shifted to `temp_c` first (required); a bare spectrum takes
/// no temperature (refused: it has no shift law).
pub fn roll_source_at(
    source: &CreepSource,
    temp_c: Option<f64>,
    scene: &Scene,
    settings: &ContactSettings,
) -> Result<SourceRoll, PipelineError> {
    let config = |message: String| PipelineError::Config {
        path: Default::default(),
        message,
    };
    let mut warnings = Vec::new();
    let (spectrum, shift) = match (source, temp_c) {
        (CreepSource::Fit(fit), Some(t)) => {
            let (at, warning) = fit_spectrum_at(fit, t)?;
            warnings.extend(warning);
            let shift = AtTemperature {
                spectrum: (),
                temp_c: at.temp_c,
                log10_a_t: at.log10_a_t,
                extrapolated: at.extrapolated,
            };
            (at.spectrum, Some(shift))
        }
        (CreepSource::Fit(fit), None) => {
            return Err(config(format!(
                "a fit file needs a temperature (its spectrum is at T_ref = {} °C)",
                fit.shift_law.t_ref_c()
            )))
        }
        (CreepSource::Spectrum(s), None) => (s.clone(), None),
        (CreepSource::Spectrum(_), Some(_)) => {
            return Err(config(
                "a temperature needs a fit file (a bare creep spectrum has no shift law)".into(),
            ))
        }
    };
    let roll = contact::roll(scene, &spectrum, settings)?;
    // a time-domain fit's friction where its data do not determine it (docs/MATH.md eqs. 18.3, 18.6)
    if let (CreepSource::Fit(fit), Some(s)) = (source, &shift) {
        warnings.extend(
            super::fit_time::time_domain_undetermined(
                fit,
                scene.speed_m_s,
                roll.contact_length_m,
                s.log10_a_t,
            )
            .map(|why| format!("friction not determined: {why}")),
        );
    }
    warnings.extend(roll.dimensionless.warnings.iter().cloned());
    Ok(SourceRoll {
        roll,
        spectrum,
        shift,
        warnings,
    })
}

/// The 90 % band of the friction `friction` of `scene` at `temp_c` (crate::bands), on the scene's
/// body: on its cover (`scene.body.cover_m()`) bonded to a rigid carcass, solved as the main job
/// solves a covered scene (eq. 15.6), else on the half-space; with the band's notes (as in
/// friction.csv's note column), or why there is none. Shared by `viscoroll roll` and the Python
/// package, so both say the same.
pub fn point_band(
    source: &CreepSource,
    scene: &Scene,
    temp_c: Option<f64>,
    friction: f64,
) -> Result<(crate::results::FrictionBand, Vec<String>), String> {
    use crate::bands;
    let (CreepSource::Fit(fit), Some(t)) = (source, temp_c) else {
        return Err("a bare creep spectrum carries no measurement scatter: bands need a fit file (`viscoroll fit` or `run`)".into());
    };
    let settings = bands::BandSettings::default();
    // A fit file without an ensemble gets one made from the fit file alone (its note says what
    // that leaves out).
    let made;
    let ensemble = match fit.bands.as_ref() {
        Some(e) => e,
        None => {
            made = bands::ensemble_from_fit(fit, &settings)
                .map_err(|e| format!("no ensemble could be made from the fit file: {e}"))?;
            &made
        }
    };
    let on = bands::scene_bands_on(fit, ensemble, scene, &[t], &settings);
    let (band, mut notes) = on.point_band(0, friction);
    // The between-specimen term as `run` adds it (docs/MATH.md §16): a fit file does not carry its
    // specimens' own frictions, so the default spread of one specimen applies, and the note says so.
    let band = band.map(|b| bands::widen(b, bands::between_sd_ln(&[]), 1));
    notes.push(bands::specimens_note(1, bands::PRIOR_SD_LN));
    if fit.bands.is_none() {
        notes.push(bands::FROM_FIT_FILE_NOTE.to_string());
    }
    match band {
        Some(b) => Ok((b, notes)),
        None if notes.is_empty() => Err("too few replicate solves succeeded for a band".into()),
        None => Err(notes.join("; ")),
    }
}
