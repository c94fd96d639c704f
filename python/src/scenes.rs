//! The stages after the fit, each the library call the CLI makes: `roll` (one dimensional scene on a
//! fit or a creep spectrum: crate::pipeline::roll_fit::roll_source_at and the band of
//! src/cli/roll.rs; with `cover_mm` or `model`, the covered body of src/cli/roll_cover.rs:
//! crate::contact::cover::roll_cover on the spectrum at the temperature), `maps` (crate::pipeline::scenes::friction_maps, as the main job makes a
//! scene's maps), `run` (crate::pipeline::run_all, as src/cli/run.rs), and the shipped scenes.
//!
//! In: JSON text of the library's serde types and an options object (crate::opts); out: JSON text.

use crate::opts::Opts;
use crate::{stage_err, to_json, Stage};
use pyo3::prelude::*;
use viscoroll::contact::roll_cover;
use viscoroll::contact::{AutoSettings, Body, ContactSettings, Scene, Scheme};
use viscoroll::pipeline::{roll_source_at, CreepSource};
use viscoroll::results::{CompoundFit, SceneSet};

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    use crate::arg;
    export!(m, c"roll", |py, a| roll(
        py,
        &arg::<String>(a, 0)?,
        arg(a, 1)?,
        &arg::<String>(a, 2)?
    ));
    export!(m, c"maps", |py, a| maps(
        py,
        &arg::<String>(a, 0)?,
        &arg::<String>(a, 1)?
    ));
    export!(m, c"run", |py, a| run(
        py,
        &arg::<String>(a, 0)?,
        &arg::<String>(a, 1)?,
        &arg::<String>(a, 2)?
    ));
    export!(m, c"shipped_scenes", |_py, _a| shipped_scenes());
    Ok(())
}

/// A fit (it has a `format_version`) or a bare creep spectrum, as `viscoroll roll` tells them apart.
fn source(json: &str) -> PyResult<CreepSource> {
    let stage = Stage::Roll;
    let value: serde_json::Value = serde_json::from_str(json).map_err(stage_err(stage))?;
    Ok(if value.get("format_version").is_some() {
        let fit: CompoundFit = serde_json::from_value(value).map_err(stage_err(stage))?;
        fit.validate()
            .map_err(|e| stage_err(stage)(anyhow::anyhow!(e)))?;
        CreepSource::Fit(Box::new(fit))
    } else {
        CreepSource::Spectrum(serde_json::from_value(value).map_err(stage_err(stage))?)
    })
}

/// The 90 % band of `friction` at `t` on the scene's body (the half-space, or its cover bonded to
/// a rigid carcass), with its notes, or why there is none: the band of `viscoroll roll`
/// (src/cli/roll_band.rs `band_or_why`, the same library calls).
fn band(
    source: &CreepSource,
    scene: &Scene,
    t: Option<f64>,
    friction: f64,
) -> (
    Result<viscoroll::results::FrictionBand, String>,
    Vec<String>,
) {
    match viscoroll::pipeline::point_band(source, scene, t, friction) {
        Ok((b, notes)) => (Ok(b), notes),
        Err(why) => (Err(why), vec![]),
    }
}

const ROLL_KEYS: &[&str] = &[
    "radius_mm",
    "load_n_per_m",
    "speed_m_s",
    "poisson",
    "n",
    "scheme",
    "tol",
    "no_bands",
    "cover_mm",
    "model",
];

/// One scene on a half-space at each temperature of `temps_c` (a fit; `None` for a bare creep
/// spectrum): a JSON list of objects with `viscoroll roll --json`'s fields.
fn roll(
    py: Python<'_>,
    source_json: &str,
    temps_c: Option<Vec<f64>>,
    options: &str,
) -> PyResult<String> {
    let stage = Stage::Roll;
    let o = Opts::parse(Stage::Roll, options, ROLL_KEYS)?;
    let need = |k: &str| -> PyResult<f64> {
        let v = o
            .f64(k)?
            .ok_or_else(|| stage_err(stage)(anyhow::anyhow!("{k} is required")))?;
        if !(v.is_finite() && v > 0.0) {
            return Err(stage_err(stage)(anyhow::anyhow!(
                "{k} must be finite and > 0, got {v}"
            )));
        }
        Ok(v)
    };
    let (radius_mm, load, speed) = (
        need("radius_mm")?,
        need("load_n_per_m")?,
        need("speed_m_s")?,
    );
    for &t in temps_c.iter().flatten() {
        viscoroll::limits::temperature_c("temp_c", t)
            .map_err(|e| stage_err(stage)(anyhow::anyhow!(e.reason)))?;
    }
    let scheme: Scheme = o
        .str("scheme")?
        .map_or(Ok(Scheme::Auto), |s| s.parse())
        .map_err(|e: String| stage_err(stage)(anyhow::anyhow!(e)))?;
    let settings = ContactSettings {
        scheme,
        n: o.usize("n")?.unwrap_or(200),
        auto: AutoSettings {
            tol: o.f64("tol")?.unwrap_or(1e-6),
            ..AutoSettings::default()
        },
        ..ContactSettings::default()
    };
    let no_bands = o.flag("no_bands")?;
    let cover = cover_options(&o, radius_mm)?;
    let source = source(source_json)?;
    let scene = Scene {
        radius_m: radius_mm * 1e-3,
        load_n_per_m: load,
        speed_m_s: speed,
        poisson: o.f64("poisson")?,
        body: Body::HALF_SPACE,
    };
    let temps: Vec<Option<f64>> = match temps_c {
        Some(ts) => ts.into_iter().map(Some).collect(),
        None => vec![None],
    };
    let answers = py.detach(|| -> Result<Vec<serde_json::Value>, anyhow::Error> {
        let mut out = Vec::new();
        for t in temps {
            if let Some((cover_m, body)) = cover {
                out.push(roll_covered(
                    &source,
                    t,
                    &scene,
                    cover_m,
                    body,
                    settings.auto.tol,
                    no_bands,
                )?);
                continue;
            }
            let r = roll_source_at(&source, t, &scene, &settings)?;
            let (b, notes) = if no_bands {
                (Err("skipped (--no-bands)".to_string()), vec![])
            } else {
                band(&source, &scene, t, r.roll.friction)
            };
            let (sol, d) = (&r.roll, &r.roll.dimensionless);
            out.push(serde_json::json!({
                "temp_c": r.shift.as_ref().map(|a| a.temp_c),
                "log10_a_t": r.shift.as_ref().map(|a| a.log10_a_t),
                "extrapolated": r.shift.as_ref().map(|a| a.extrapolated),
                "friction": sol.friction,
                "contact_length_mm": sol.contact_length_m * 1e3,
                "offset_mm": sol.offset_m * 1e3,
                "resistance_n_per_m": sol.resistance_n_per_m,
                "max_pressure_mpa": sol.max_pressure_pa * 1e-6,
                "x_mm": sol.x_m.iter().map(|x| x * 1e3).collect::<Vec<_>>(),
                "pressure_mpa": sol.pressure_pa.iter().map(|p| p * 1e-6).collect::<Vec<_>>(),
                "poisson": sol.problem.poisson,
                "lambda": d.lambda,
                "beta": d.beta,
                "scheme": d.scheme,
                "n": d.n,
                "iterations": d.iterations,
                "error_estimate": d.error_estimate,
                "friction_p05": b.as_ref().ok().map(|b| b.p05),
                "friction_p50": b.as_ref().ok().map(|b| b.p50),
                "friction_p95": b.as_ref().ok().map(|b| b.p95),
                "bands_note": b.as_ref().err(),
                "bands_notes": notes,
                "warnings": r.warnings,
            }));
        }
        Ok(out)
    });
    to_json(Stage::Roll, &answers.map_err(stage_err(stage))?)
}

/// The cover of `roll`'s options, as `viscoroll roll --cover-mm H --model M` checks them: `None`
/// without `cover_mm` and `model` (the half-space path), else (thickness in m or none, the body).
fn cover_options(o: &Opts, radius_mm: f64) -> PyResult<Option<(Option<f64>, Body)>> {
    let err = |m: String| stage_err(Stage::Roll)(anyhow::anyhow!(m));
    let (h, model) = (o.f64("cover_mm")?, o.str("model")?);
    if h.is_none() && model.is_none() {
        return Ok(None);
    }
    let name = model.unwrap_or_else(|| "auto".into());
    if !matches!(Body::choice(&name, Some(1.0)), Ok(Some(_))) {
        return Err(err(format!(
            "model `{name}` is not known (auto, half-space, layer, winkler)"
        )));
    }
    if let Some(h) = h {
        if !(h.is_finite() && h > 0.0) {
            return Err(err(format!("cover_mm must be finite and > 0, got {h}")));
        }
        viscoroll::limits::cover("cover_mm", h, radius_mm).map_err(|e| err(e.to_string()))?;
    }
    let cover_m = h.map(|h| h * 1e-3);
    let body = Body::choice(&name, cover_m)
        .map_err(|e| err(e.to_string()))?
        .ok_or_else(|| err(format!("model `{name}` is not known")))?;
    Ok(Some((cover_m, body)))
}

/// One scene on a cover at `t` (src/cli/roll_cover.rs): the spectrum at the temperature, the body
/// chosen and solved by crate::contact::cover::roll_cover, and the band solved on the body
/// the main job's bands solve. The fields of `viscoroll roll --cover-mm --json`.
fn roll_covered(
    source: &CreepSource,
    t: Option<f64>,
    scene: &Scene,
    cover_m: Option<f64>,
    body: Body,
    tol: f64,
    no_bands: bool,
) -> Result<serde_json::Value, anyhow::Error> {
    let (spectrum, shifted, mut warnings) = match (source, t) {
        (CreepSource::Fit(fit), Some(t)) => {
            let (at, w) = viscoroll::pipeline::fit_spectrum_at(fit, t)?;
            (
                at.spectrum.clone(),
                Some(at),
                w.into_iter().collect::<Vec<_>>(),
            )
        }
        (CreepSource::Spectrum(s), None) => (s.clone(), None, Vec::new()),
        (CreepSource::Fit(_), None) => anyhow::bail!("a fit needs a temperature (temp_c)"),
        (CreepSource::Spectrum(_), Some(_)) => {
            anyhow::bail!("temp_c needs a fit (a bare creep spectrum has no shift law)")
        }
    };
    let r = roll_cover(&Scene { body, ..*scene }, &spectrum, tol)?;
    warnings.extend(r.warnings.iter().cloned());
    let (b, notes) = match body {
        _ if no_bands => (Err("skipped (--no-bands)".to_string()), vec![]),
        Body::Winkler { .. } => (Err("--model winkler: the bands are solved on the body `auto` chooses (the layer or a body within tol of it), not on the uniaxial Winkler model".to_string()), vec![]),
        Body::HalfSpace { .. } => band(source, scene, t, r.roll.friction),
        _ => band(source, &Scene { body, ..*scene }, t, r.roll.friction),
    };
    let sol = &r.roll;
    Ok(serde_json::json!({
        "temp_c": shifted.as_ref().map(|a| a.temp_c),
        "log10_a_t": shifted.as_ref().map(|a| a.log10_a_t),
        "extrapolated": shifted.as_ref().map(|a| a.extrapolated),
        "friction": sol.friction,
        "contact_length_mm": sol.contact_length_m * 1e3,
        "offset_mm": sol.offset_m * 1e3,
        "resistance_n_per_m": sol.resistance_n_per_m,
        "max_pressure_mpa": sol.max_pressure_pa * 1e-6,
        "x_mm": sol.x_m.iter().map(|x| x * 1e3).collect::<Vec<_>>(),
        "pressure_mpa": sol.pressure_pa.iter().map(|p| p * 1e-6).collect::<Vec<_>>(),
        "poisson": sol.problem.poisson,
        "cover_mm": cover_m.map(|h| h * 1e3),
        "cover_over_contact": r.cover_over_contact,
        "model": r.model.name(),
        "model_reason": r.reason,
        "model_error_estimate": r.model_error_estimate,
        "error_estimate": r.error_estimate,
        "min_pressure_ratio": r.min_pressure_ratio,
        "min_gap_ratio": r.min_gap_ratio,
        "friction_p05": b.as_ref().ok().map(|b| b.p05),
        "friction_p50": b.as_ref().ok().map(|b| b.p50),
        "friction_p95": b.as_ref().ok().map(|b| b.p95),
        "bands_note": b.as_ref().err(),
        "bands_notes": notes,
        "warnings": warnings,
    }))
}

/// One scene (JSON of a `[[scene]]` table of scenes.toml), checked as scenes.toml is.
fn scene_spec(json: &str) -> PyResult<viscoroll::results::SceneSpec> {
    let stage = Stage::Maps;
    let spec: serde_json::Value = serde_json::from_str(json).map_err(stage_err(stage))?;
    let set: SceneSet =
        serde_json::from_value(serde_json::json!({ "scene": [spec] })).map_err(stage_err(stage))?;
    let text = toml::to_string(&set).map_err(stage_err(stage))?;
    let mut set =
        SceneSet::parse(&text, std::path::Path::new("scene")).map_err(stage_err(stage))?;
    Ok(set.scene.remove(0))
}

/// The friction maps of a fit (JSON) in one scene (JSON, with `map_temps_c`, `map_speeds_m_s`,
/// `map_loads_n_per_m`), as the main job makes them: `FrictionMaps` JSON.
fn maps(py: Python<'_>, fit_json: &str, scene_json: &str) -> PyResult<String> {
    let stage = Stage::Maps;
    let fit: CompoundFit = serde_json::from_str(fit_json).map_err(stage_err(stage))?;
    fit.validate()
        .map_err(|e| stage_err(stage)(anyhow::anyhow!(e)))?;
    let spec = scene_spec(scene_json)?;
    let m = py
        .detach(|| {
            viscoroll::pipeline::friction_maps(
                &fit,
                &spec,
                &viscoroll::pipeline::pipeline_map_settings(),
            )
        })
        .map_err(stage_err(stage))?;
    to_json(Stage::Maps, &m)
}

const RUN_KEYS: &[&str] = &[
    "scenes",
    "force",
    "tref",
    "allow_extrapolation",
    "tol",
    "no_bands",
    "shard",
    "no_xlsx",
    "shift",
    "vertical",
    "criterion",
    "law",
    "fit_range",
    "nominal",
    "max_terms",
    "target_rms",
    "reduce",
];

/// The main job on a folder, into `out` (fits/ and reports/, as `viscoroll run DIR --out OUT`):
/// (RunSummary JSON, the log lines).
fn run(py: Python<'_>, dir: &str, out: &str, options: &str) -> PyResult<(String, Vec<String>)> {
    use viscoroll::pipeline::{run_all, RunOptions};
    let stage = Stage::Run;
    let o = Opts::parse(Stage::Run, options, RUN_KEYS)?;
    let scenes = o.str("scenes")?.map(std::path::PathBuf::from);
    let tref = o.f64("tref")?;
    let mut opts = RunOptions::for_folder(dir.as_ref(), out.as_ref(), scenes.as_deref(), tref)
        .map_err(stage_err(stage))?;
    let (_, tuning) = crate::stages::fit_tuning(&o, Stage::Run)?;
    tuning.apply(&mut opts.fit);
    opts.force = o.flag("force")?;
    if let Some(t) = o.f64("tol")? {
        opts.set_tol(t).map_err(stage_err(stage))?;
    }
    opts.allow_extrapolation = o.flag("allow_extrapolation")?;
    if o.flag("no_bands")? {
        opts.bands = None;
    }
    opts.xlsx = !o.flag("no_xlsx")?;
    if let Some(s) = o.str("shard")? {
        opts.shard = Some(
            s.parse()
                .map_err(|e: String| stage_err(stage)(anyhow::anyhow!(e)))?,
        );
    }
    let log = std::sync::Mutex::new(Vec::new());
    let summary = py
        .detach(|| {
            run_all(&opts, &|line: &str| {
                if let Ok(mut l) = log.lock() {
                    l.push(line.to_string());
                }
            })
        })
        .map_err(stage_err(stage))?;
    let lines = log.into_inner().unwrap_or_default();
    Ok((to_json(Stage::Run, &summary)?, lines))
}

/// The shipped scenes (data/scenes.toml, compiled in), as a JSON list of scene tables.
fn shipped_scenes() -> PyResult<String> {
    to_json(Stage::Run, &SceneSet::shipped().scene)
}
