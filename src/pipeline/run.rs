//! The main job ([`run_all`]): every compound of a folder → fit file → friction in the scenes →
//! report folder; then `reports/ranking.csv` and `reports/index.html`.
//!
//! Input: a folder of DMA exports, a [`SceneSet`], an output folder; output: [`RunSummary`] and files
//! (all written atomically). Compounds run in parallel (rayon), so do the temperatures of each scene;
//! one compound's failure is recorded and does not stop the others. The library never prints:
//! progress goes to the caller's `log` callback.

use super::compound_fit::CompoundFit;
use super::compounds::{discover, CompoundInput};
use super::datasheet::{esc, write_atomic, write_report};
use super::error::PipelineError;
use super::fit_compound::{fit_or_reuse, FitAction, FitOptions};
use super::scenes::{
    friction_vs_temperature, mean_friction, pipeline_contact_settings, FrictionPoint, SceneSet,
};
use crate::dma::{read_files, IngestOptions};
use rayon::prelude::*;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

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

/// The outcome of one compound.
#[derive(Debug, Clone, Serialize)]
pub struct CompoundOutcome {
    /// Compound name.
    pub compound: String,
    /// Fit file written or reused.
    pub fit_path: Option<PathBuf>,
    /// `reused`, `fitted` or `replaced`.
    pub fit_action: Option<String>,
    /// Mean friction per scene (scene name, mean F/N over its temperatures).
    pub mean_friction: Vec<(String, f64)>,
    /// Friction per scene and temperature.
    pub friction: Vec<(String, Vec<FrictionPoint>)>,
    /// Warnings (extrapolated temperatures, failed temperatures).
    pub warnings: Vec<String>,
    /// The error, if the compound failed.
    pub error: Option<String>,
    /// Wall time for this compound in seconds.
    pub seconds: f64,
}

/// The outcome of [`run_all`].
#[derive(Debug, Clone, Serialize)]
pub struct RunSummary {
    /// One per compound, in discovery order.
    pub compounds: Vec<CompoundOutcome>,
    /// Notes on skipped entries.
    pub notes: Vec<String>,
    /// `reports/ranking.csv`.
    pub ranking_csv: PathBuf,
    /// `reports/index.html`.
    pub index_html: PathBuf,
}

impl RunSummary {
    /// Number of failed compounds.
    pub fn failures(&self) -> usize {
        self.compounds.iter().filter(|c| c.error.is_some()).count()
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
    let fit_path = opts.out_dir.join("fits").join(format!("{}.json", c.name));
    let (fit, action) = fit_or_reuse(&c.name, &measurement, &fit_path, &opts.fit, opts.force)?;
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
            let seconds = start.elapsed().as_secs_f64();
            let out = match r {
                Ok((_fit, action, friction)) => {
                    let mut warnings = Vec::new();
                    for (scene, pts) in &friction {
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
                    CompoundOutcome {
                        compound: c.name.clone(),
                        fit_path: Some(opts.out_dir.join("fits").join(format!("{}.json", c.name))),
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
                        friction,
                        warnings,
                        error: None,
                        seconds,
                    }
                }
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
            };
            match &out.error {
                None => log(&format!(
                    "{}: {} fit, {} scenes, {:.2} s",
                    out.compound,
                    out.fit_action.as_deref().unwrap_or(""),
                    out.friction.len(),
                    out.seconds
                )),
                Some(e) => log(&format!("{}: FAILED: {e}", out.compound)),
            }
            out
        })
        .collect();
    let reports = opts.out_dir.join("reports");
    let ranking_csv = reports.join("ranking.csv");
    let index_html = reports.join("index.html");
    write_atomic(
        &ranking_csv,
        ranking_csv_text(&outcomes, &opts.scenes).as_bytes(),
    )?;
    write_atomic(
        &index_html,
        index_text(&outcomes, &opts.scenes, &notes).as_bytes(),
    )?;
    Ok(RunSummary {
        compounds: outcomes,
        notes,
        ranking_csv,
        index_html,
    })
}

/// Successful compounds of `scene` ordered by mean friction (lowest rolling resistance first).
pub fn ranked<'a>(outcomes: &'a [CompoundOutcome], scene: &str) -> Vec<(&'a CompoundOutcome, f64)> {
    let mut v: Vec<(&CompoundOutcome, f64)> = outcomes
        .iter()
        .filter(|o| o.error.is_none())
        .filter_map(|o| {
            o.mean_friction
                .iter()
                .find(|(s, _)| s == scene)
                .map(|(_, f)| (o, *f))
        })
        .collect();
    v.sort_by(|a, b| a.1.total_cmp(&b.1));
    v
}

fn ranking_csv_text(outcomes: &[CompoundOutcome], scenes: &SceneSet) -> String {
    let mut s = format!(
        "# viscoroll {}: compounds ranked by temperature-averaged rolling friction F/N per scene (lowest first)\nscene,rank,compound,mean_friction,temps_c\n",
        env!("CARGO_PKG_VERSION")
    );
    for spec in &scenes.scene {
        let temps: Vec<String> = spec.temps_c.iter().map(|t| t.to_string()).collect();
        for (i, (o, f)) in ranked(outcomes, &spec.name).iter().enumerate() {
            let _ = writeln!(
                s,
                "{},{},{},{:e},{}",
                spec.name,
                i + 1,
                o.compound,
                f,
                temps.join(" ")
            );
        }
    }
    s
}

fn index_text(outcomes: &[CompoundOutcome], scenes: &SceneSet, notes: &[String]) -> String {
    let mut h = format!(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>viscoroll: compounds</title><style>body{{font-family:sans-serif;max-width:1000px;margin:1em auto}}table{{border-collapse:collapse}}td,th{{border:1px solid #bbb;padding:2px 6px}}.bad{{color:#b00}}</style></head><body><h1>Compounds and rolling friction</h1><p>viscoroll {}; temperature-averaged F/N per scene, lowest first.</p>",
        env!("CARGO_PKG_VERSION")
    );
    for spec in &scenes.scene {
        let _ = write!(
            h,
            "<h2>{}</h2><p>{} (R = {} mm, {} N/m, {} m/s, {} temperatures)</p><table><tr><th>rank</th><th>compound</th><th>mean F/N</th></tr>",
            esc(&spec.name),
            esc(&spec.description),
            spec.roll_radius_mm,
            spec.load_n_per_m,
            spec.speed_m_s,
            spec.temps_c.len()
        );
        for (i, (o, f)) in ranked(outcomes, &spec.name).iter().enumerate() {
            let _ = write!(
                h,
                "<tr><td>{}</td><td><a href=\"{n}/datasheet.html\">{n}</a></td><td>{f:.4e}</td></tr>",
                i + 1,
                n = esc(&o.compound)
            );
        }
        h.push_str("</table>");
    }
    let failed: Vec<&CompoundOutcome> = outcomes.iter().filter(|o| o.error.is_some()).collect();
    if !failed.is_empty() {
        h.push_str("<h2 class=\"bad\">Failed compounds</h2><ul>");
        for o in failed {
            let _ = write!(
                h,
                "<li><b>{}</b>: {}</li>",
                esc(&o.compound),
                esc(o.error.as_deref().unwrap_or(""))
            );
        }
        h.push_str("</ul>");
    }
    let warned: Vec<&CompoundOutcome> =
        outcomes.iter().filter(|o| !o.warnings.is_empty()).collect();
    if !warned.is_empty() || !notes.is_empty() {
        h.push_str("<h2>Warnings and notes</h2><ul>");
        for o in warned {
            for w in &o.warnings {
                let _ = write!(h, "<li>{}: {}</li>", esc(&o.compound), esc(w));
            }
        }
        for n in notes {
            let _ = write!(h, "<li>{}</li>", esc(n));
        }
        h.push_str("</ul>");
    }
    h.push_str("</body></html>\n");
    h
}

/// Friction of fit files at one scene, for `viscoroll rank`: (compound, points, mean).
pub fn rank_fits(fits: &[CompoundFit], spec: &super::scenes::SceneSpec) -> Vec<RankedFit> {
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
