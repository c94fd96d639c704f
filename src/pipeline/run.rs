//! The main job ([`run_all`]): every compound of a folder → fit file → friction in the scenes →
//! report folder; then `reports/ranking.csv` and `reports/index.html`.
//!
//! Input: a folder of DMA exports, a [`SceneSet`], an output folder; output: [`RunSummary`] and files
//! (all written atomically). Compounds run in parallel (rayon), so do the temperatures of each scene;
//! one compound's failure, even a panic, is recorded and does not stop the others. The output
//! folder is locked for the run (a second run on it waits), and temporary files a killed run left
//! there are removed first. The library never prints: progress goes to the caller's `log` callback.

use super::compounds::{discover, CompoundInput};
use super::error::{io, PipelineError};
use super::fit_compound::{fit_or_reuse_master, fit_or_reuse_with_bands, FitAction, FitOptions};
use super::scenes::{friction_on_body, friction_vs_temperature, pipeline_contact_settings};
use crate::bands::BandSettings;
use crate::dma::read_files;
use crate::report::{write_index, write_ranking, write_report, write_workbook, TanDeltaProxy};
use crate::results::{
    cap_line, standing, CompoundFit, FrictionPoint, SceneSet, SceneSpec, SceneStanding,
};
use crate::Measurement;
use rayon::prelude::*;
use std::path::{Path, PathBuf};

use super::compare::compare_ranked;
pub use super::folder::{fit_path, LOCK_WAIT};
pub use crate::results::{CompoundOutcome, RunStatus, RunSummary};

/// Options of [`run_all`].
#[derive(Debug, Clone)]
pub struct RunOptions {
    /// Folder of compounds.
    pub input_dir: PathBuf,
    /// Output folder (gets `fits/` and `reports/`).
    pub out_dir: PathBuf,
    /// The scenes.
    pub scenes: SceneSet,
    /// The file the scenes were read from; `None`: the shipped scenes.
    pub scenes_file: Option<PathBuf>,
    /// Replace fit files that differ.
    pub force: bool,
    /// Fit settings (a compound's own settings in `compounds.toml` override them).
    pub fit: FitOptions,
    /// Average extrapolated temperatures into the ranking too (marked); default: measured only.
    pub allow_extrapolation: bool,
    /// Uncertainty bands (crate::bands) with these settings; `None` skips them (`--no-bands`).
    pub bands: Option<BandSettings>,
    /// Longest wait for another run that holds the output folder (`--wait`; default `LOCK_WAIT`).
    pub lock_wait: std::time::Duration,
    /// Run only this shard's compounds (`--shard K/N`, crate::pipeline::shard); `None`: all.
    pub shard: Option<super::shard::Shard>,
    /// Write the run's workbook `reports/viscoroll.xlsx` (crate::report::workbook; `--no-xlsx`
    /// skips it). A shard never writes it: the merge does.
    pub xlsx: bool,
}

impl RunOptions {
    /// The options of `viscoroll run DIR`: scenes from `scenes` if given, else `DIR/scenes.toml` if
    /// present, else the shipped scenes; default fit settings, with `tref_c` as the master curve's
    /// reference temperature if given (checked: finite, in [−273.15, 1000] °C).
    pub fn for_folder(
        input_dir: &Path,
        out_dir: &Path,
        scenes: Option<&Path>,
        tref_c: Option<f64>,
    ) -> Result<Self, PipelineError> {
        let scenes_file = scenes_file(scenes, input_dir);
        let scenes = match &scenes_file {
            Some(p) => SceneSet::read(p)?,
            None => SceneSet::shipped(),
        };
        let mut fit = FitOptions::default();
        if let Some(t) = tref_c {
            if !(t.is_finite() && (-273.15..=1000.0).contains(&t)) {
                return Err(PipelineError::Setting {
                    field: "--tref".into(),
                    message: format!("{t} is not a temperature in °C in [−273.15, 1000]"),
                });
            }
            fit.master.tref_c = Some(t);
        }
        Ok(Self {
            input_dir: input_dir.to_path_buf(),
            out_dir: out_dir.to_path_buf(),
            scenes,
            scenes_file,
            force: false,
            fit,
            allow_extrapolation: false,
            bands: Some(BandSettings::default()),
            lock_wait: LOCK_WAIT,
            shard: None,
            xlsx: true,
        })
    }
}

impl RunOptions {
    /// `run --tol`: the relative tolerance of the contact solves and friction maps of every scene
    /// that sets none of its own, checked against the range of a scene's `tol`.
    pub fn set_tol(&mut self, tol: f64) -> Result<(), PipelineError> {
        let (lo, hi) = crate::results::scene::TOL_RANGE;
        if !(lo..=hi).contains(&tol) {
            return Err(PipelineError::Setting {
                field: "--tol".into(),
                message: format!("{tol} is not a relative tolerance in [{lo:e}, {hi:e}]"),
            });
        }
        for s in self.scenes.scene.iter_mut().filter(|s| s.tol.is_none()) {
            s.tol = Some(tol);
        }
        Ok(())
    }
}

/// The scenes file of a job: `given` if any, else `DIR/scenes.toml` if it exists, else `None` (the
/// shipped scenes). `run` and `rank` choose their scenes by this one rule.
pub fn scenes_file(given: Option<&Path>, dir: &Path) -> Option<PathBuf> {
    let in_dir = dir.join("scenes.toml");
    match given {
        Some(p) => Some(p.to_path_buf()),
        None if in_dir.is_file() => Some(in_dir),
        None => None,
    }
}

/// Where the scenes came from, for the notes: the file, or the shipped scenes.
pub fn scenes_origin(file: Option<&Path>) -> String {
    match file {
        Some(p) => format!("scenes from {}", p.display()),
        None => "scenes: the shipped data/scenes.toml (no scenes.toml in the folder, no --scenes)"
            .to_string(),
    }
}

/// Friction of one compound per scene: (scene name, points).
pub type SceneFriction = Vec<(String, Vec<FrictionPoint>)>;

/// What one compound hands on: its fit, what was done with the fit file, its friction per scene,
/// per scene and temperature the bootstrap ratios F_b/F̂ (empty without bands: crate::bands) and
/// why bands are missing, if they are.
type CompoundResult = (
    CompoundFit,
    FitAction,
    SceneFriction,
    Vec<Vec<Vec<f64>>>,
    Option<String>,
);

/// One ranked fit: Ok((compound, points, standing)) or Err((compound, error)).
pub type RankedFit = Result<(String, Vec<FrictionPoint>, SceneStanding), (String, String)>;

/// A step of the main job, for a progress display ([`run_all_with_progress`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ProgressEvent<'a> {
    /// The number of work units: per compound, its fit, two per scene (friction against temperature,
    /// friction maps) and its report.
    Total(u64),
    /// One unit done (`stage`: `fit`, `friction SCENE`, `maps SCENE`, `report`, or `skipped` for the
    /// units a failed compound will not do).
    Done {
        /// The compound.
        compound: &'a str,
        /// What was done.
        stage: &'a str,
    },
}

/// Work units per compound (see [`ProgressEvent::Total`]).
fn units_per_compound(scenes: &SceneSet) -> u64 {
    2 + 2 * scenes.scene.len() as u64
}

/// The measurement of a compound: its exports read together with its ingest options, or one
/// measurement JSON written by `viscoroll ingest`.
fn measurement_of(c: &CompoundInput) -> Result<Measurement, PipelineError> {
    if let Some(why) = &c.unreadable {
        return Err(PipelineError::Setting {
            field: "folder".into(),
            message: format!("compound {}: {why}", c.name),
        });
    }
    let is_json = |p: &PathBuf| {
        p.extension()
            .is_some_and(|e| e.to_string_lossy().eq_ignore_ascii_case("json"))
    };
    if c.files.iter().any(is_json) {
        if c.files.len() != 1 {
            return Err(PipelineError::Setting {
                field: "files".into(),
                message: format!(
                    "compound {}: a measurement JSON must be its only file",
                    c.name
                ),
            });
        }
        let p = &c.files[0];
        let text = crate::fsutil::read_regular_to_string(p, crate::limits::INPUT_BYTES_MAX)
            .map_err(io(p))?;
        return Ok(crate::dma::plausible::measurement_from_json(
            &p.display().to_string(),
            &text,
        )?);
    }
    let ingest = c.settings.ingest.clone().unwrap_or_default();
    Ok(read_files(&c.files, &ingest)?)
}

/// [`measurement_of`]: the plausibility checks (crate::dma::plausible) ran in the read path —
/// impossible temperatures refused, suspected unit mix-ups in the measurement's warnings.
fn checked_measurement(c: &CompoundInput) -> Result<Measurement, PipelineError> {
    measurement_of(c)
}

/// The fit options of a compound: the run's, with the compound's own settings over them.
fn fit_options(c: &CompoundInput, opts: &RunOptions) -> FitOptions {
    let mut fit = opts.fit.clone();
    if let Some(t) = c.settings.tref_c {
        fit.master.tref_c = Some(t);
    }
    if let Some(p) = &c.settings.prony {
        fit.prony = p.clone();
    }
    c.settings.tuning.apply(&mut fit);
    fit
}

/// A compound's measurement, its fit, what was done to the fit file, why there are no bands, and
/// with replicate specimens each one's own fit (or why it failed).
struct Fitted {
    measurement: Measurement,
    fit: CompoundFit,
    action: FitAction,
    no_bands: Option<String>,
    specimen_fits: Vec<Result<CompoundFit, String>>,
    /// Each replicate specimen's own measurement (empty with one), for the datasheet's curves.
    specimens: Vec<Measurement>,
}

impl Fitted {
    /// One specimen's fit that gets no bands, and why (said only when bands were asked for).
    fn without_bands(
        measurement: Measurement,
        fit: CompoundFit,
        action: FitAction,
        opts: &RunOptions,
        why: &str,
    ) -> Self {
        Fitted {
            measurement,
            fit,
            action,
            no_bands: opts
                .bands
                .as_ref()
                .map(|_| crate::bands::not_computed(&why)),
            specimen_fits: Vec::new(),
            specimens: Vec::new(),
        }
    }
}

/// (scene with its body, its temperatures) → the friction ratios of each replicate.
type SolvedRatios = ((crate::contact::Scene, Vec<f64>), crate::bands::SceneRatios);

/// Fit (or reuse the fit of) a compound measured in isotherms, with its bands when asked.
fn fit_measured(c: &CompoundInput, opts: &RunOptions) -> Result<Fitted, PipelineError> {
    let (measurement, specimen_fits, specimens) = if c.specimens.len() >= 2 {
        pooled_specimens(c, opts)?
    } else {
        (checked_measurement(c)?, Vec::new(), Vec::new())
    };
    let (fit, action, no_bands) = fit_or_reuse_with_bands(
        &c.name,
        &measurement,
        &fit_path(&opts.out_dir, &c.name),
        &fit_options(c, opts),
        opts.force,
        opts.bands.as_ref(),
    )?;
    Ok(Fitted {
        measurement,
        fit,
        action,
        no_bands,
        specimen_fits,
        specimens,
    })
}

/// Replicate specimens: each read alone and fitted alone (its friction gives the spread between
/// specimens, crate::bands::between), and their measurements pooled for the compound's fit
/// (super::specimens); the specimens' own measurements are handed on for the datasheet.
#[allow(clippy::type_complexity)]
fn pooled_specimens(
    c: &CompoundInput,
    opts: &RunOptions,
) -> Result<
    (
        Measurement,
        Vec<Result<CompoundFit, String>>,
        Vec<Measurement>,
    ),
    PipelineError,
> {
    let ms: Vec<Measurement> = c
        .specimens
        .iter()
        .map(|files| {
            checked_measurement(&CompoundInput {
                files: files.clone(),
                specimens: Vec::new(),
                ..c.clone()
            })
        })
        .collect::<Result<_, _>>()?;
    // what could not be pooled reaches the fit's warnings, and so friction.csv and the datasheet
    let (mut pooled, notes) = super::specimens::pool(&c.name, &ms)?;
    pooled.warnings.extend(notes);
    let options = fit_options(c, opts);
    let fits = ms
        .par_iter()
        .enumerate()
        .map(|(k, m)| {
            crate::pipeline::fit_measurement(&format!("{} specimen {}", c.name, k + 1), m, &options)
                .map_err(|e| cap_line(&format!("specimen {}: {e}", k + 1)))
        })
        .collect();
    Ok((pooled, fits, ms))
}

/// Fit (or reuse the fit of) a master curve read already shifted (pyvisco's CSV pair: the compound's
/// file and `shift_factors`), checked like any export; it has no bands.
fn fit_shifted(
    c: &CompoundInput,
    shift_factors: &Path,
    opts: &RunOptions,
) -> Result<Fitted, PipelineError> {
    let poisson = c.settings.ingest.as_ref().map_or(0.5, |o| o.poisson);
    let pv = crate::dma::pyvisco::PyviscoMaster::read(
        &c.files[0],
        shift_factors,
        poisson,
        c.settings.tref_c,
    )?;
    let mut measurement = pv.measurement;
    crate::dma::plausible::refuse_impossible(&measurement).map_err(|message| {
        PipelineError::Implausible {
            compound: c.name.clone(),
            message: cap_line(&message),
        }
    })?;
    let w = crate::dma::plausible::warnings(&measurement);
    measurement.warnings.extend(w);
    let master = crate::tts::master_curve_from_reduced(&measurement, &pv.shift_law)?;
    let mut options = fit_options(c, opts);
    options.master = master.settings.clone();
    let (fit, action) = fit_or_reuse_master(
        &c.name,
        &measurement,
        &master,
        &fit_path(&opts.out_dir, &c.name),
        &options,
        opts.force,
    )?;
    // The bands resample isotherms; a master curve read already shifted has none.
    Ok(Fitted::without_bands(
        measurement,
        fit,
        action,
        opts,
        "a master curve read already shifted has no isotherms to resample",
    ))
}

/// Fit a compound of relaxation or creep isotherms (docs/MATH.md §18, `super::fit_time`): always
/// refitted from its data (a second or less) and its fit file written or replaced; it has no bands
/// (they resample frequency sweeps).
fn fit_time_domain(c: &CompoundInput, opts: &RunOptions) -> Result<Fitted, PipelineError> {
    let poisson = c.settings.ingest.as_ref().map_or(0.5, |o| o.poisson);
    let (fit, measurement) = super::fit_time::fit_time_files_with_measurement(
        &c.name,
        &c.files,
        c.settings.shift_factors.as_deref(),
        poisson,
        &fit_options(c, opts),
    )?;
    let path = fit_path(&opts.out_dir, &c.name);
    let action = if path.exists() {
        FitAction::Replaced
    } else {
        FitAction::Fitted
    };
    fit.write(&path, true)?;
    Ok(Fitted::without_bands(
        measurement,
        fit,
        action,
        opts,
        "time-domain data (the bands resample frequency sweeps)",
    ))
}

/// The friction ratios of each replicate in a scene, and each point's band from them. The ratios are
/// solved on the scene's body (a cover: eq. 15.6); scenes with the same roll, temperatures and cover
/// share them (`solved`), and scenes with the same roll and temperatures share their half-space
/// solves (`half_space`: a covered scene's regression, eq. 15.6b, and its half-space twin). The
/// replicates of a covered point are solved on `bodies`, the body each point was solved on
/// (`friction_on_body`; `None`: `auto`).
#[allow(clippy::too_many_arguments)]
fn scene_bands(
    fit: &CompoundFit,
    ensemble: &crate::results::BandEnsemble,
    spec: &SceneSpec,
    bs: &BandSettings,
    points: &mut [FrictionPoint],
    bodies: &[Option<crate::contact::Body>],
    solved: &mut Vec<SolvedRatios>,
    half_space: &mut Vec<crate::bands::HalfSpaceRatios>,
) -> Vec<Vec<f64>> {
    let scene = spec.scene();
    let key = (scene, spec.temps_c.clone());
    let r = match solved.iter().find(|(k, _)| *k == key) {
        Some((_, r)) => r.clone(),
        None => {
            let hs_scene = crate::contact::Scene {
                body: crate::contact::Body::HALF_SPACE,
                ..scene
            };
            if !half_space
                .iter()
                .any(|h| h.scene == hs_scene && h.temps_c == key.1)
            {
                if let Some(h) = crate::bands::half_space_ratios(fit, ensemble, &key.0, &key.1, bs)
                {
                    half_space.push(h);
                }
            }
            let hs = half_space
                .iter()
                .find(|h| h.scene == hs_scene && h.temps_c == key.1);
            // a cover's nominal frictions, contact lengths and bodies are the points just solved
            // (same body, tol)
            let nominal: Vec<crate::bands::CoverSolve> = points
                .iter()
                .zip(bodies)
                .map(|(p, &body)| (p.friction, p.contact_length_mm * 1e-3, body))
                .collect();
            let r =
                crate::bands::scene_bands_given(fit, ensemble, &scene, &key.1, bs, &nominal, hs);
            solved.push((key, r.clone()));
            r
        }
    };
    // each point's band, with its notes (widened: eqs. 15.8, 15.9; failed replicates) or why it
    // was refused: they reach friction.csv's note, the datasheet and the ranking
    for (i, p) in points.iter_mut().enumerate() {
        if p.error.is_none() {
            let (band, notes) = r.point_band(i, p.friction);
            p.band = band;
            p.warnings.extend(notes);
        }
    }
    r.ratios
}

fn one_compound(
    c: &CompoundInput,
    opts: &RunOptions,
    step: &dyn Fn(&str),
) -> Result<CompoundResult, PipelineError> {
    let Fitted {
        measurement,
        fit,
        action,
        no_bands,
        specimen_fits,
        specimens,
    } = fit_any(c, opts)?;
    step("fit");
    let settings = pipeline_contact_settings();
    let mut friction = Vec::new();
    let mut maps = Vec::new();
    let mut ratios = Vec::new();
    let mut solved: Vec<SolvedRatios> = Vec::new();
    let mut half_space = Vec::new();
    for spec in &opts.scenes.scene {
        let (mut points, bodies) = friction_on_body(&fit, spec, &settings)?;
        if let (Some(bs), Some(ensemble)) = (opts.bands.as_ref(), fit.bands.as_ref()) {
            ratios.push(scene_bands(
                &fit,
                ensemble,
                spec,
                bs,
                &mut points,
                &bodies,
                &mut solved,
                &mut half_space,
            ));
        } else {
            ratios.push(Vec::new());
        }
        finish_points(&fit, &specimen_fits, spec, &mut points);
        friction.push((spec.clone(), points));
        step(&format!("friction {}", spec.name));
        let m = super::scenes::friction_maps(&fit, spec, &super::scenes::pipeline_map_settings())?;
        // a map's warnings (covered surface short of its tolerance, node solver, validity) reach
        // friction.csv, the datasheet and the ranking through the scene's points
        if let Some((_, points)) = friction.last_mut() {
            for p in points.iter_mut() {
                p.warnings.extend(m.warnings.iter().cloned());
            }
        }
        maps.push(m);
        step(&format!("maps {}", spec.name));
    }
    let fit_level = own_warnings(
        c,
        opts,
        (&fit, no_bands.as_deref()),
        &specimen_fits,
        &friction,
    );
    write_report(
        &fit,
        crate::report::Measured {
            pooled: &measurement,
            specimens: &specimens,
        },
        &fit_level,
        &friction,
        &maps,
        opts.allow_extrapolation,
        &opts.out_dir.join("reports").join(&c.name),
    )?;
    step("report");
    Ok((
        fit,
        action,
        friction.into_iter().map(|(s, p)| (s.name, p)).collect(),
        ratios,
        no_bands,
    ))
}

/// The compound's fit: from time-domain data, from measured sweeps, or from a master curve read
/// already shifted (`shift_factors`).
fn fit_any(c: &CompoundInput, opts: &RunOptions) -> Result<Fitted, PipelineError> {
    match &c.settings.shift_factors {
        None if c.unreadable.is_none()
            && c.specimens.is_empty()
            && super::fit_time::files_are_time_data(&c.files) =>
        {
            fit_time_domain(c, opts)
        }
        None => fit_measured(c, opts),
        // pyvisco's time-domain master curve with its shift factors
        Some(_) if super::fit_time::files_are_time_data(&c.files) => fit_time_domain(c, opts),
        Some(sf) => fit_shifted(c, sf, opts),
    }
}

/// A scene's points finished: each specimen's own friction, what is determined, the
/// between-specimen term, the time-domain marks.
fn finish_points(
    fit: &CompoundFit,
    specimen_fits: &[Result<CompoundFit, String>],
    spec: &SceneSpec,
    points: &mut [FrictionPoint],
) {
    let settings = pipeline_contact_settings();
    let specimen_points: Vec<Vec<FrictionPoint>> = specimen_fits
        .iter()
        .map(|f| {
            f.as_ref()
                .ok()
                .and_then(|f| friction_vs_temperature(f, spec, &settings).ok())
                .unwrap_or_default()
        })
        .collect();
    super::trust::finish_points(points, &specimen_points, fit.measured_range_c());
    super::fit_time::mark_time_domain_points(fit, spec.scene().speed_m_s, points);
}

/// The compound's own warnings: the fit's, each replicate specimen that failed, and with bands
/// what every band of the compound covers (docs/MATH.md §16).
fn own_warnings(
    c: &CompoundInput,
    opts: &RunOptions,
    (fit, no_bands): (&CompoundFit, Option<&str>),
    specimen_fits: &[Result<CompoundFit, String>],
    friction: &[(SceneSpec, Vec<FrictionPoint>)],
) -> Vec<String> {
    let mut fit_level = fit_warnings(fit, no_bands, opts.bands.is_some());
    fit_level.extend(
        specimen_fits
            .iter()
            .filter_map(|f| f.as_ref().err())
            .map(|e| format!("replicate specimens: {e} (its friction left out of the spread)")),
    );
    if opts.bands.is_some() && fit.bands.is_some() {
        let sd = friction
            .iter()
            .flat_map(|(_, p)| p)
            .map(|p| crate::bands::between_sd_ln(&p.specimens))
            .fold(0.0, f64::max);
        fit_level.push(crate::bands::specimens_note(c.specimens.len().max(1), sd));
    }
    fit_level
}

/// [`one_compound`] with a panic caught and turned into the compound's error, so one bad input
/// never takes the run down.
fn one_compound_isolated(
    c: &CompoundInput,
    opts: &RunOptions,
    step: &dyn Fn(&str),
) -> Result<CompoundResult, PipelineError> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| one_compound(c, opts, step)))
        .unwrap_or_else(|payload| {
            let msg = payload
                .downcast_ref::<String>()
                .map(String::as_str)
                .or_else(|| payload.downcast_ref::<&str>().copied())
                .unwrap_or("no message");
            Err(PipelineError::Internal {
                compound: c.name.clone(),
                message: cap_line(msg),
            })
        })
}

/// Run the main job (see the module docs). Errors when the input folder cannot be read or holds no
/// compound, the output folder cannot be locked, or the ranking or index cannot be written; a
/// compound's failure is in its [`CompoundOutcome`].
pub fn run_all(
    opts: &RunOptions,
    log: &(dyn Fn(&str) + Sync),
) -> Result<RunSummary, PipelineError> {
    run_all_with_progress(opts, log, &|_| {})
}

/// The data flags of a fit: the master curve's flags and warnings (a thinned isotherm, a far-off
/// point behind an out-of-bounds fit), then the ingest warnings.
fn data_warnings(fit: &CompoundFit) -> Vec<String> {
    let mut warnings: Vec<String> = Vec::new();
    if let Some(t) = &fit.tts {
        warnings.extend(t.flags.iter().map(|f| format!("master curve: {f}")));
        warnings.extend(t.warnings.iter().map(|f| format!("master curve: {f}")));
    }
    warnings.extend(
        fit.measurement
            .warnings
            .iter()
            .map(|w| format!("ingest: {w}")),
    );
    warnings
}

/// The bands' warnings: why they were not computed (`no_bands`), else the ensemble's notes (when
/// bands were asked for).
fn band_warnings(fit: &CompoundFit, no_bands: Option<&str>, bands_on: bool) -> Vec<String> {
    let mut warnings: Vec<String> = no_bands.iter().map(|s| s.to_string()).collect();
    if bands_on {
        if let Some(e) = &fit.bands {
            warnings.extend(e.notes.iter().map(|n| format!("uncertainty bands: {n}")));
        }
    }
    warnings
}

/// The warnings of the fit that hold for every friction row (data flags, then the bands'), one
/// line each: friction.csv writes them once with a code per row.
fn fit_warnings(fit: &CompoundFit, no_bands: Option<&str>, bands_on: bool) -> Vec<String> {
    let mut warnings = data_warnings(fit);
    warnings.extend(band_warnings(fit, no_bands, bands_on));
    warnings.into_iter().map(|w| cap_line(&w)).collect()
}

/// The warnings of a compound: data flags of its fit, then per scene the extrapolated temperatures,
/// failed points and contact warnings (each distinct warning once per scene).
fn compound_warnings(fit: &CompoundFit, friction: &SceneFriction) -> Vec<String> {
    let mut warnings = data_warnings(fit);
    for (scene, pts) in friction {
        let ext: Vec<String> = pts
            .iter()
            .filter(|p| p.extrapolated)
            .map(|p| format!("{}", p.temp_c))
            .collect();
        if !ext.is_empty() {
            warnings.push(format!(
                "{scene}: shift law extrapolated beyond the measured temperatures at {} °C",
                ext.join(", ")
            ));
        }
        for p in pts.iter().filter(|p| p.error.is_some()) {
            warnings.push(format!(
                "{scene}: {} °C failed: {}",
                p.temp_c,
                p.error.as_deref().unwrap_or("")
            ));
        }
        let mut seen: Vec<&str> = Vec::new();
        for w in pts.iter().flat_map(|p| &p.warnings) {
            if !seen.contains(&w.as_str()) {
                seen.push(w);
                let at: Vec<String> = pts
                    .iter()
                    .filter(|p| p.warnings.contains(w))
                    .map(|p| p.temp_c.to_string())
                    .collect();
                // the bands' own notes (crate::bands::scene) are not the contact's
                let stage = if w.starts_with(crate::bands::WIDENED_NOTE_START)
                    || w.starts_with("uncertainty band")
                {
                    "bands"
                } else {
                    "contact"
                };
                warnings.push(format!("{scene} at {} °C: {stage}: {w}", at.join(", ")));
            }
        }
    }
    warnings.into_iter().map(|w| cap_line(&w)).collect()
}

/// The outcome record of one compound from its result, and its bootstrap ratios per scene (for
/// the bands of means over shared windows, super::trust).
fn outcome(
    c: &CompoundInput,
    opts: &RunOptions,
    result: Result<CompoundResult, PipelineError>,
    seconds: f64,
) -> (CompoundOutcome, Vec<Vec<Vec<f64>>>) {
    let specimens = c.specimens.len().max(1);
    match result {
        Ok((fit, action, friction, ratios, no_bands)) => {
            let untrusted = fit.untrusted_reasons();
            let care = fit.care_reasons();
            let mut warnings = compound_warnings(&fit, &friction);
            if action == FitAction::Repaired {
                warnings.push(format!(
                    "fits/{}.json failed its content hash or validation (edited or damaged): fitted again and replaced",
                    c.name
                ));
            }
            warnings.extend(band_warnings(
                &fit,
                no_bands.as_deref(),
                opts.bands.is_some(),
            ));
            let out = CompoundOutcome {
                compound: c.name.clone(),
                fit_path: Some(fit_path(&opts.out_dir, &c.name)),
                fit_action: Some(action.word().to_string()),
                standings: friction
                    .iter()
                    .enumerate()
                    .map(|(k, (s, p))| {
                        let mut st = standing(s, p, &untrusted, &care, opts.allow_extrapolation);
                        if let Some(r) = ratios.get(k).filter(|r| !r.is_empty()) {
                            st.band = super::trust::standing_band(p, r, &st.temps_c);
                        }
                        st
                    })
                    .collect(),
                warnings,
                untrusted,
                friction,
                error: None,
                seconds,
                specimens,
            };
            (out, ratios)
        }
        Err(e) => (
            CompoundOutcome {
                compound: c.name.clone(),
                fit_path: None,
                fit_action: None,
                standings: vec![],
                friction: vec![],
                untrusted: vec![],
                warnings: vec![],
                error: Some(cap_line(&e.to_string())),
                seconds,
                specimens,
            },
            Vec::new(),
        ),
    }
}

/// The log line of a finished compound.
fn log_line(out: &CompoundOutcome) -> String {
    match &out.error {
        None => format!(
            "{}: {}, {}, {:.2} s{}",
            out.compound,
            match out.fit_action.as_deref() {
                Some("reused") => "reused fit",
                Some("replaced") => "fit replaced (--force)",
                _ => "new fit",
            },
            crate::results::counted(out.friction.len(), "scene"),
            out.seconds,
            if out.is_untrusted() {
                " (NOT TRUSTED: see the index)"
            } else {
                ""
            }
        ),
        Some(e) => format!("{}: FAILED: {e}", out.compound),
    }
}

/// Notes on report folders of compounds that are no longer in the input (kept, not deleted: they
/// may be all that is left of a compound).
fn stale_reports(reports: &Path, compounds: &[CompoundInput]) -> Vec<String> {
    let Ok(entries) = std::fs::read_dir(reports) else {
        return vec![];
    };
    let mut v: Vec<String> = entries
        .flatten()
        .filter(|e| e.file_type().is_ok_and(|t| t.is_dir()))
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| !compounds.iter().any(|c| &c.name == n))
        .map(|n| {
            cap_line(&format!(
                "reports/{n}: compound no longer in the input folder; report of an earlier run kept, not ranked"
            ))
        })
        .collect();
    v.sort();
    v
}

/// One compound's finished work: its outcome, its bootstrap ratios per scene and temperature, and
/// its tan δ proxy for the index.
type Finished = (CompoundOutcome, Vec<Vec<Vec<f64>>>, Option<TanDeltaProxy>);

/// Every compound's outcome and ratios, in order, and the tan δ proxies of those that finished.
type AllFinished = (
    Vec<CompoundOutcome>,
    Vec<Vec<Vec<Vec<f64>>>>,
    Vec<TanDeltaProxy>,
);

/// [`run_all`], reporting each finished work unit to `progress` (first [`ProgressEvent::Total`],
/// then one [`ProgressEvent::Done`] per unit, from the worker threads): the compounds found
/// (`inputs`), the output folder locked, each compound solved (`solve_compounds`), the
/// comparisons, then the shard's file or the ranking, workbook and index (`write_run`).
pub fn run_all_with_progress(
    opts: &RunOptions,
    log: &(dyn Fn(&str) + Sync),
    progress: &(dyn Fn(ProgressEvent<'_>) + Sync),
) -> Result<RunSummary, PipelineError> {
    let (all, mut notes) = inputs(opts)?;
    // a shard locks its own folder and leaves temporary files alone (crate::pipeline::shard)
    let lock_dir = opts
        .shard
        .map_or(opts.out_dir.clone(), |s| s.dir(&opts.out_dir));
    let _lock = crate::fsutil::DirLock::acquire(&lock_dir, opts.lock_wait, &|holder| {
        log(&format!(
            "waiting up to {} s (--wait) for another viscoroll run on {}: {holder}",
            opts.lock_wait.as_secs(),
            lock_dir.display()
        ))
    })
    .map_err(io(&lock_dir))?;
    let (positions, compounds): (Vec<usize>, Vec<CompoundInput>) = all
        .iter()
        .cloned()
        .enumerate()
        .filter(|(i, _)| opts.shard.map_or(true, |s| s.takes(*i)))
        .unzip();
    let removed = match opts.shard {
        None => crate::fsutil::remove_stale_temps(&opts.out_dir, 3),
        Some(_) => 0,
    };
    if removed > 0 {
        notes.push(format!(
            "removed {removed} temporary file(s) left by an interrupted run"
        ));
    }
    for n in &notes {
        log(&format!("note: {n}"));
    }
    let (mut outcomes, ratios, proxies) = solve_compounds(&compounds, opts, log, progress);
    super::trust::share_windows(&mut outcomes, &ratios, &opts.scenes);
    let comparisons = compare_ranked(&mut outcomes, &opts.scenes);
    let reports = opts.out_dir.join("reports");
    notes.extend(stale_reports(&reports, &all));
    let summary = RunSummary {
        compounds: outcomes,
        notes,
        allow_extrapolation: opts.allow_extrapolation,
        ranking_csv: reports.join("ranking.csv"),
        index_html: reports.join("index.html"),
        comparisons,
    };
    if let Some(shard) = opts.shard {
        let file = super::shard::ShardFile {
            shard_index: shard.index,
            shard_count: shard.count,
            compounds_total: all.len(),
            positions,
            scenes: opts.scenes.clone(),
            summary,
        };
        super::shard::write_shard_file(&opts.out_dir, &file)?;
        return Ok(file.summary);
    }
    write_run(&summary, opts, &proxies)?;
    Ok(summary)
}

/// The compounds of the input folder (the run's own paths are never compounds: a second run in
/// the same folder reads only the inputs again) and the notes, the scenes' origin first.
fn inputs(opts: &RunOptions) -> Result<(Vec<CompoundInput>, Vec<String>), PipelineError> {
    if !opts.input_dir.is_dir() {
        return Err(PipelineError::NotAFolder {
            path: opts.input_dir.clone(),
        });
    }
    let own = [
        opts.out_dir.clone(),
        opts.out_dir.join("fits"),
        opts.out_dir.join("reports"),
    ]
    .into_iter()
    .chain(opts.scenes_file.clone())
    .collect::<Vec<_>>();
    let (all, mut notes) = discover(&opts.input_dir, &own)?;
    if all.is_empty() {
        return Err(PipelineError::NoCompounds {
            path: opts.input_dir.clone(),
            notes: notes.iter().take(5).cloned().collect::<Vec<_>>().join("; "),
        });
    }
    notes.insert(0, scenes_origin(opts.scenes_file.as_deref()));
    Ok((all, notes))
}

/// Each compound's outcome, bootstrap ratios and tan δ proxy (parallel over compounds, each one
/// isolated, its work units reported to `progress` and the skipped ones made up).
fn solve_compounds(
    compounds: &[CompoundInput],
    opts: &RunOptions,
    log: &(dyn Fn(&str) + Sync),
    progress: &(dyn Fn(ProgressEvent<'_>) + Sync),
) -> AllFinished {
    let per = units_per_compound(&opts.scenes);
    progress(ProgressEvent::Total(per * compounds.len() as u64));
    let done: Vec<Finished> = compounds
        .par_iter()
        .map(|c| {
            let start = std::time::Instant::now();
            let done = std::cell::Cell::new(0u64);
            let step = |stage: &str| {
                done.set(done.get() + 1);
                progress(ProgressEvent::Done {
                    compound: &c.name,
                    stage,
                });
            };
            let r = one_compound_isolated(c, opts, &step);
            for _ in done.get()..per {
                step("skipped");
            }
            let proxy = r.as_ref().ok().map(|(fit, ..)| TanDeltaProxy::of(fit));
            let (out, ratios) = outcome(c, opts, r, start.elapsed().as_secs_f64());
            log(&log_line(&out));
            (out, ratios, proxy)
        })
        .collect();
    let mut outcomes = Vec::with_capacity(done.len());
    let mut ratios = Vec::with_capacity(done.len());
    let mut proxies: Vec<TanDeltaProxy> = Vec::new();
    for (o, r, p) in done {
        outcomes.push(o);
        ratios.push(r);
        proxies.extend(p);
    }
    (outcomes, ratios, proxies)
}

/// The run's own files: the ranking, the workbook when asked for, and the index last (it reads
/// the whole summary, comparisons included).
fn write_run(
    summary: &RunSummary,
    opts: &RunOptions,
    proxies: &[TanDeltaProxy],
) -> Result<(), PipelineError> {
    write_ranking(
        &summary.ranking_csv,
        &summary.compounds,
        &opts.scenes,
        opts.allow_extrapolation,
    )?;
    if opts.xlsx {
        write_workbook(summary)?;
    }
    let reports = opts.out_dir.join("reports");
    write_index(&reports, summary, &opts.scenes, proxies)?;
    Ok(())
}

/// Friction of fit files at one scene, for `viscoroll rank`: (compound, points, standing), trusted
/// compounds first by mean friction, then the others, then the failures. With `bands` (and a fit
/// file that carries its ensemble, as `run` writes it) each point and each mean gets its band as in
/// `run`, and the ranked compounds their comparisons (`tied_with`), which are returned too.
pub fn rank_fits(
    fits: &[CompoundFit],
    spec: &SceneSpec,
    allow_extrapolation: bool,
    bands: Option<&BandSettings>,
) -> (Vec<RankedFit>, Vec<crate::results::PairComparison>) {
    let settings = pipeline_contact_settings();
    let mut v: Vec<_> = fits
        .par_iter()
        .map(|f| match friction_on_body(f, spec, &settings) {
            Ok((mut p, bodies)) => {
                for q in p.iter_mut() {
                    q.determine(f.measured_range_c());
                }
                super::fit_time::mark_time_domain_points(f, spec.scene().speed_m_s, &mut p);
                let ratios = match (bands, f.bands.as_ref()) {
                    (Some(bs), Some(ensemble)) => scene_bands(
                        f,
                        ensemble,
                        spec,
                        bs,
                        &mut p,
                        &bodies,
                        &mut vec![],
                        &mut vec![],
                    ),
                    _ => vec![],
                };
                let mut s = standing(
                    &spec.name,
                    &p,
                    &f.untrusted_reasons(),
                    &f.care_reasons(),
                    allow_extrapolation,
                );
                if !ratios.is_empty() {
                    s.band = super::trust::standing_band(&p, &ratios, &s.temps_c);
                }
                Ok((f.compound.clone(), p, s))
            }
            Err(e) => Err((f.compound.clone(), cap_line(&e.to_string()))),
        })
        .collect();
    let key = |r: &RankedFit| match r {
        Ok((_, _, s)) if s.trusted() => (0, s.mean_friction.unwrap_or(f64::INFINITY)),
        Ok((_, _, s)) => (1, s.mean_friction.unwrap_or(f64::INFINITY)),
        Err(_) => (2, f64::INFINITY),
    };
    v.sort_by(|a, b| {
        let (ka, kb) = (key(a), key(b));
        ka.0.cmp(&kb.0).then(ka.1.total_cmp(&kb.1))
    });
    let ranked: Vec<(String, crate::results::FrictionBand)> = v
        .iter()
        .filter_map(|r| r.as_ref().ok())
        .filter(|(_, _, s)| s.trusted())
        .filter_map(|(c, _, s)| s.band.map(|b| (c.clone(), b)))
        .collect();
    let pairs = crate::bands::comparisons(&spec.name, &ranked);
    for (c, _, s) in v.iter_mut().filter_map(|r| r.as_mut().ok()) {
        s.tied_with = pairs
            .iter()
            .filter(|p| p.tied && (p.a == *c || p.b == *c))
            .map(|p| if p.a == *c { p.b.clone() } else { p.a.clone() })
            .collect();
    }
    (v, pairs)
}
