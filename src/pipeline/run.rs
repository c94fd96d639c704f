//! The main job ([`run_all`]): every compound of a folder → fit file → friction in the scenes →
//! report folder; then `reports/ranking.csv` and `reports/index.html`.
//!
//! Input: a folder of DMA exports, a [`SceneSet`], an output folder; output: [`RunSummary`] and files
//! (all written atomically). Compounds run in parallel (rayon), so do the temperatures of each scene;
//! one compound's failure is recorded and does not stop the others. The library never prints:
//! progress goes to the caller's `log` callback.

use super::compounds::{discover, CompoundInput};
use super::error::PipelineError;
use super::fit_compound::{fit_or_reuse, FitAction, FitOptions};
use super::scenes::{friction_vs_temperature, mean_friction, pipeline_contact_settings};
use crate::dma::{read_files, IngestOptions};
use crate::report::{index_html, ranking_csv, write_file, write_report};
use crate::results::{CompoundFit, FrictionPoint, SceneSet};
use rayon::prelude::*;
use std::path::{Path, PathBuf};

pub use crate::results::{CompoundOutcome, RunSummary};

/// Options of [`run_all`].
#[derive(Debug, Clone)]
pub struct RunOptions {
    /// Folder of compounds.
    pub input_dir: PathBuf,
    /// Output folder (gets `fits/` and `reports/`).
    pub out_dir: PathBuf,
    /// The scenes.
    pub scenes: SceneSet,
    /// Replace fit files that differ.
    pub force: bool,
    /// Fit settings.
    pub fit: FitOptions,
}

impl RunOptions {
    /// The options of `viscoroll run DIR`: scenes from `scenes` if given, else `DIR/scenes.toml` if
    /// present, else the shipped scenes; default fit settings.
    pub fn for_folder(
        input_dir: &Path,
        out_dir: &Path,
        scenes: Option<&Path>,
        force: bool,
    ) -> Result<Self, PipelineError> {
        let in_dir = input_dir.join("scenes.toml");
        let scenes = match scenes {
            Some(p) => SceneSet::read(p)?,
            None if in_dir.is_file() => SceneSet::read(&in_dir)?,
            None => SceneSet::shipped(),
        };
        Ok(Self {
            input_dir: input_dir.to_path_buf(),
            out_dir: out_dir.to_path_buf(),
            scenes,
            force,
            fit: FitOptions::default(),
        })
    }
}

/// Friction of one compound per scene: (scene name, points).
pub type SceneFriction = Vec<(String, Vec<FrictionPoint>)>;

/// One ranked fit: Ok((compound, points, mean F/N)) or Err((compound, error)).
pub type RankedFit = Result<(String, Vec<FrictionPoint>, f64), (String, String)>;

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

fn one_compound(
    c: &CompoundInput,
    opts: &RunOptions,
    step: &dyn Fn(&str),
) -> Result<(CompoundFit, FitAction, SceneFriction), PipelineError> {
    let measurement = read_files(&c.files, &IngestOptions::default())?;
    let (fit, action) = fit_or_reuse(
        &c.name,
        &measurement,
        &fit_path(&opts.out_dir, &c.name),
        &opts.fit,
        opts.force,
    )?;
    step("fit");
    let settings = pipeline_contact_settings();
    let mut friction = Vec::new();
    let mut maps = Vec::new();
    for spec in &opts.scenes.scene {
        friction.push((
            spec.clone(),
            friction_vs_temperature(&fit, spec, &settings)?,
        ));
        step(&format!("friction {}", spec.name));
        maps.push(super::scenes::friction_maps(
            &fit,
            spec,
            &super::scenes::pipeline_map_settings(),
        )?);
        step(&format!("maps {}", spec.name));
    }
    write_report(
        &fit,
        &measurement,
        &friction,
        &maps,
        &opts.out_dir.join("reports").join(&c.name),
    )?;
    step("report");
    Ok((
        fit,
        action,
        friction.into_iter().map(|(s, p)| (s.name, p)).collect(),
    ))
}

/// Run the main job (see the module docs). Errors only when the folder cannot be read or the index
/// cannot be written; a compound's failure is in its [`CompoundOutcome`].
pub fn run_all(
    opts: &RunOptions,
    log: &(dyn Fn(&str) + Sync),
) -> Result<RunSummary, PipelineError> {
    run_all_with_progress(opts, log, &|_| {})
}

/// The warnings of a compound's friction: extrapolated temperatures and failed points, per scene.
fn friction_warnings(friction: &SceneFriction) -> Vec<String> {
    let mut warnings = Vec::new();
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
    }
    warnings
}

/// The outcome record of one compound from its result.
fn outcome(
    c: &CompoundInput,
    opts: &RunOptions,
    result: Result<(CompoundFit, FitAction, SceneFriction), PipelineError>,
    seconds: f64,
) -> CompoundOutcome {
    match result {
        Ok((_fit, action, friction)) => CompoundOutcome {
            compound: c.name.clone(),
            fit_path: Some(fit_path(&opts.out_dir, &c.name)),
            fit_action: Some(
                match action {
                    FitAction::Reused => "reused",
                    FitAction::Fitted => "fitted",
                    FitAction::Replaced => "replaced",
                }
                .to_string(),
            ),
            mean_friction: friction
                .iter()
                .map(|(s, p)| (s.clone(), mean_friction(p)))
                .collect(),
            warnings: friction_warnings(&friction),
            friction,
            error: None,
            seconds,
        },
        Err(e) => CompoundOutcome {
            compound: c.name.clone(),
            fit_path: None,
            fit_action: None,
            mean_friction: vec![],
            friction: vec![],
            warnings: vec![],
            error: Some(e.to_string()),
            seconds,
        },
    }
}

/// The log line of a finished compound.
fn log_line(out: &CompoundOutcome) -> String {
    match &out.error {
        None => format!(
            "{}: {} fit, {} scenes, {:.2} s",
            out.compound,
            out.fit_action.as_deref().unwrap_or(""),
            out.friction.len(),
            out.seconds
        ),
        Some(e) => format!("{}: FAILED: {e}", out.compound),
    }
}

/// [`run_all`], reporting each finished work unit to `progress` (first [`ProgressEvent::Total`],
/// then one [`ProgressEvent::Done`] per unit, from the worker threads).
pub fn run_all_with_progress(
    opts: &RunOptions,
    log: &(dyn Fn(&str) + Sync),
    progress: &(dyn Fn(ProgressEvent<'_>) + Sync),
) -> Result<RunSummary, PipelineError> {
    let (compounds, notes) = discover(&opts.input_dir)?;
    for n in &notes {
        log(&format!("note: {n}"));
    }
    let per = units_per_compound(&opts.scenes);
    progress(ProgressEvent::Total(per * compounds.len() as u64));
    let outcomes: Vec<CompoundOutcome> = compounds
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
            let r = one_compound(c, opts, &step);
            for _ in done.get()..per {
                step("skipped");
            }
            let out = outcome(c, opts, r, start.elapsed().as_secs_f64());
            log(&log_line(&out));
            out
        })
        .collect();
    let reports = opts.out_dir.join("reports");
    let ranking_path = reports.join("ranking.csv");
    let index_path = reports.join("index.html");
    write_file(
        &ranking_path,
        ranking_csv(&outcomes, &opts.scenes).as_bytes(),
    )?;
    write_file(
        &index_path,
        index_html(&outcomes, &opts.scenes, &notes).as_bytes(),
    )?;
    Ok(RunSummary {
        compounds: outcomes,
        notes,
        ranking_csv: ranking_path,
        index_html: index_path,
    })
}

/// Friction of fit files at one scene, for `viscoroll rank`: (compound, points, mean).
pub fn rank_fits(fits: &[CompoundFit], spec: &crate::results::SceneSpec) -> Vec<RankedFit> {
    let settings = pipeline_contact_settings();
    let mut v: Vec<_> = fits
        .par_iter()
        .map(|f| match friction_vs_temperature(f, spec, &settings) {
            Ok(p) => {
                let m = mean_friction(&p);
                Ok((f.compound.clone(), p, m))
            }
            Err(e) => Err((f.compound.clone(), e.to_string())),
        })
        .collect();
    v.sort_by(|a, b| match (a, b) {
        (Ok(x), Ok(y)) => x.2.total_cmp(&y.2),
        (Ok(_), Err(_)) => std::cmp::Ordering::Less,
        (Err(_), Ok(_)) => std::cmp::Ordering::Greater,
        _ => std::cmp::Ordering::Equal,
    });
    v
}

/// Convenience: the output folder's fit path of a compound.
pub fn fit_path(out_dir: &Path, compound: &str) -> PathBuf {
    out_dir.join("fits").join(format!("{compound}.json"))
}
