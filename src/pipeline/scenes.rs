//! A compound's friction in the scenes ([`friction_vs_temperature`], [`friction_maps`]).
//!
//! Input: a [`SceneSpec`] (crate::results::scene) and a [`CompoundFit`]; output: [`FrictionPoint`]s, one per temperature, from
//! the contact stage's error-controlled load solve (crate::contact::roll, thesis eq. 3.12 for F/N) on the creep
//! spectrum shifted to each temperature (docs/MATH.md §6).

use super::error::PipelineError;
use super::roll_fit::fit_spectrum_at;
use crate::contact::cover::roll_cover;
use crate::contact::maps::{
    covered_map, friction_map, CoveredProblem, MapQuery, MapSettings, MapValue, ReducedProblem,
};
use crate::contact::{roll, AutoSettings, Body, ContactSettings, RollSolution, Scheme};
use crate::results::CompoundFit;
use rayon::prelude::*;

pub use crate::results::scene::{
    FrictionMaps, FrictionPoint, MapPoint, SceneSet, SceneSpec, CURVE_POINTS, GRID_POINTS,
};

/// Contact settings of the main job: the error-controlled `auto` scheme at its default relative
/// tolerance 1e-6 on friction and contact length (the same as `viscoroll roll`'s default, so a
/// friction in the reports equals `roll FIT --temp-c T` for the same scene). The thesis scheme at
/// n = 200 would be about 100× slower per load point and only accurate to ~1e-3 in λ. The exterior
/// gap check is off: it only reports, never changes the friction, and costs more than the solve for
/// few modes (it made the shipped run 2.2 s instead of 0.9 s); `viscoroll roll` still runs it.
pub fn pipeline_contact_settings() -> ContactSettings {
    ContactSettings {
        scheme: Scheme::Auto,
        auto: AutoSettings {
            gap_check: false,
            ..AutoSettings::default()
        },
        ..ContactSettings::default()
    }
}

/// Tolerance of the covered scenes' solves in the main job: the bonded layer's collocation is first
/// order in λ (Richardson-extrapolated) and costs 20–100 ms per point at 1e−3 against 0.2–0.7 s at
/// 1e−4 (`cargo bench --bench contact_layer`); its measured errors at 1e−3 are 3e−6…3e−4 in ρF/N.
pub const COVER_TOL: f64 = 1e-3;

/// The tolerance of a scene's direct contact solves: its own `tol` if set, else `default` on a
/// half-space and at least [`COVER_TOL`] on a cover.
pub(crate) fn scene_tol(spec: &SceneSpec, default: f64) -> f64 {
    spec.tol.unwrap_or(match spec.scene().body {
        Body::HalfSpace { cover_m: None } => default,
        _ => default.max(COVER_TOL),
    })
}

/// Friction of `fit` at every temperature of `spec` (parallel over temperatures), each point with
/// the solver's error estimate; the tolerance is the scene's (`scene_tol`, `settings`' as the
/// default). A failed solve gives a point with `error` set, not an error: the other temperatures
/// still count.
pub fn friction_vs_temperature(
    fit: &CompoundFit,
    spec: &SceneSpec,
    settings: &ContactSettings,
) -> Result<Vec<FrictionPoint>, PipelineError> {
    Ok(friction_on_body(fit, spec, settings)?.0)
}

/// [`friction_vs_temperature`] and, per point, the body solved (`None` where the solve failed): a
/// covered scene's bands solve each replicate on it (crate::bands::replicate_choice).
pub(crate) fn friction_on_body(
    fit: &CompoundFit,
    spec: &SceneSpec,
    settings: &ContactSettings,
) -> Result<(Vec<FrictionPoint>, Vec<Option<Body>>), PipelineError> {
    fit.creep.as_ref().ok_or_else(|| PipelineError::NoCreep {
        compound: fit.compound.clone(),
    })?;
    let scene = spec.scene();
    let tol = scene_tol(spec, settings.auto.tol);
    let mut settings = *settings;
    settings.auto.tol = tol;
    let settings = &settings;
    Ok(spec
        .temps_c
        .par_iter()
        .map(|&t| {
            // a point at this temperature: unsolved, then filled in by `failed` or `solved`
            let point = |log10_a_t: f64, extrapolated: bool| FrictionPoint {
                temp_c: t,
                log10_a_t,
                friction: f64::NAN,
                resistance_n_per_m: f64::NAN,
                contact_length_mm: f64::NAN,
                extrapolated,
                error: None,
                model: String::new(),
                model_reason: String::new(),
                band: None,
                warnings: vec![],
                specimens: vec![],
                undetermined: None,
                error_estimate: None,
            };
            let failed = |e: String, log10_a_t: f64, extrapolated: bool| {
                let error = Some(crate::results::cap_line(&e));
                (
                    FrictionPoint {
                        error,
                        ..point(log10_a_t, extrapolated)
                    },
                    None,
                )
            };
            // the same shift as `viscoroll roll FIT --temp-c T` (super::roll_fit)
            let at = match fit_spectrum_at(fit, t) {
                Ok((a, _)) => a,
                // the message of the creep stage itself, as before
                Err(PipelineError::Creep(e)) => return failed(e.to_string(), f64::NAN, true),
                Err(e) => return failed(e.to_string(), f64::NAN, true),
            };
            let solved = |r: &RollSolution,
                          model: Body,
                          model_reason: String,
                          error_estimate: Option<f64>,
                          warnings: &[String]| {
                (
                    FrictionPoint {
                        friction: r.friction,
                        resistance_n_per_m: r.resistance_n_per_m,
                        contact_length_mm: r.contact_length_m * 1e3,
                        model: model.name().to_string(),
                        model_reason,
                        error_estimate,
                        warnings: warnings
                            .iter()
                            .map(|w| crate::results::cap_line(w))
                            .collect(),
                        ..point(at.log10_a_t, at.extrapolated)
                    },
                    Some(model),
                )
            };
            if !matches!(scene.body, Body::HalfSpace { cover_m: None }) {
                // A cover: the body chosen and solved by contact::cover (auto, at COVER_TOL).
                return match roll_cover(&scene, &at.spectrum, tol) {
                    Ok(r) => solved(
                        &r.roll,
                        r.model,
                        r.reason,
                        Some(r.error_estimate + r.model_error_estimate.unwrap_or(0.0)),
                        &r.warnings,
                    ),
                    Err(e) => failed(e.to_string(), at.log10_a_t, at.extrapolated),
                };
            }
            match roll(&scene, &at.spectrum, settings) {
                Ok(r) => solved(
                    &r,
                    Body::HALF_SPACE,
                    String::new(),
                    r.dimensionless.error_estimate,
                    &r.dimensionless.warnings,
                ),
                Err(e) => failed(e.to_string(), at.log10_a_t, at.extrapolated),
            }
        })
        .unzip())
}

/// Map settings of the main job: relative tolerance 1e−6 on F/N and contact length at every map
/// point, the same as the friction against temperature and `viscoroll roll` (the interpolation
/// estimate actually reached is printed in the datasheet). Panels of six decades: a shipped scene's
/// maps (two temperatures, speeds and loads) span about five decades of s. Measured after the
/// solver's lumping correction (`cargo bench --bench maps`, 2 threads): 9000 map points of EMS-CA
/// (65 creep terms) in 0.26 s at 1e−6 (594 solves), and one compound from raw export to datasheet in
/// 0.23–0.28 s wall (before it: 1.0 s of CPU at 1e−3).
pub fn pipeline_map_settings() -> MapSettings {
    MapSettings {
        tol: 1e-6,
        panel_width: 6.0 * std::f64::consts::LN_10,
        ..MapSettings::default()
    }
}

fn log_grid(values: &[f64]) -> Vec<f64> {
    log_spaced(values, GRID_POINTS)
}

/// `n` log-spaced values from the smallest to the largest of `values` (empty unless they span a
/// range).
fn log_spaced(values: &[f64], n: usize) -> Vec<f64> {
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if hi.partial_cmp(&lo) != Some(std::cmp::Ordering::Greater) {
        return vec![];
    }
    (0..n)
        .map(|k| (lo.ln() + (hi.ln() - lo.ln()) * k as f64 / (n - 1) as f64).exp())
        .collect()
}

/// The map points of `spec` at every map temperature: (temperature, speed, load, kind) with kind 0 a
/// listed point, 1 the [`GRID_POINTS`]² grid, 2 the dense speed and load curves. The grid and the
/// curves lie inside the span of the listed points, so they leave the interpolant's range (and so
/// every listed value) unchanged.
fn map_jobs(spec: &SceneSpec) -> Vec<(f64, f64, f64, u8)> {
    let (speeds, loads) = (
        log_grid(&spec.map_speeds_m_s),
        log_grid(&spec.map_loads_n_per_m),
    );
    let (curve_speeds, curve_loads) = (
        log_spaced(&spec.map_speeds_m_s, CURVE_POINTS),
        log_spaced(&spec.map_loads_n_per_m, CURVE_POINTS),
    );
    let mut jobs = Vec::new();
    for &t in &spec.map_temps_c {
        // against speed at the scene's load, against load at its speed: listed (0), dense (2)
        for (kind, vs, ns) in [
            (0, &spec.map_speeds_m_s, &spec.map_loads_n_per_m),
            (2, &curve_speeds, &curve_loads),
        ] {
            jobs.extend(vs.iter().map(|&v| (t, v, spec.load_n_per_m, kind)));
            jobs.extend(ns.iter().map(|&n| (t, spec.speed_m_s, n, kind)));
        }
        if !speeds.is_empty() && !loads.is_empty() {
            for &v in &speeds {
                jobs.extend(loads.iter().map(|&n| (t, v, n, 1)));
            }
        }
    }
    jobs
}

/// Friction maps of `fit` in `spec` ([`FrictionMaps`]), all from one interpolant of the
/// dimensionless solution: in the reduced variable s = l_g/(V·a_T) on the half-space (module
/// `crate::contact::maps`: exact scaling, interpolation error ≤ `settings.tol`), in s and
/// η = h/l_g on the bonded layer for a covered scene (`crate::contact::maps::covered_map`, at
/// least [`COVER_TOL`]). A covered surface that cannot be built leaves the maps empty (NaN) with
/// the reason in `warnings`, so the friction against temperature still counts.
pub fn friction_maps(
    fit: &CompoundFit,
    spec: &SceneSpec,
    settings: &MapSettings,
) -> Result<FrictionMaps, PipelineError> {
    let creep = fit.creep.as_ref().ok_or_else(|| PipelineError::NoCreep {
        compound: fit.compound.clone(),
    })?;
    // the scene's own tolerance, if it sets one, over the maps' (and the covered maps' floor)
    let mut settings = *settings;
    settings.tol = spec.tol.unwrap_or(settings.tol);
    let settings = &settings;
    let jobs = map_jobs(spec);
    let a_t = |t: f64| {
        creep
            .at_temperature(&fit.shift_law, t, None)
            .ok()
            .map(|a| 10f64.powf(a.log10_a_t))
    };
    let temps_a_t: Vec<(f64, Option<f64>)> =
        spec.map_temps_c.iter().map(|&t| (t, a_t(t))).collect();
    let a_t_of = |t: f64| {
        temps_a_t
            .iter()
            .find(|(tt, _)| *tt == t)
            .and_then(|(_, a)| *a)
    };
    let solvable: Vec<usize> = (0..jobs.len())
        .filter(|&i| a_t_of(jobs[i].0).is_some())
        .collect();
    let radius_m = spec.roll_radius_mm * 1e-3;
    let queries: Vec<MapQuery> = solvable
        .iter()
        .map(|&i| MapQuery {
            radius_m,
            load_n_per_m: jobs[i].2,
            speed_m_s: jobs[i].1,
            a_t: a_t_of(jobs[i].0).unwrap_or(f64::NAN),
        })
        .collect();
    let mut values: Vec<Option<MapValue>> = vec![None; jobs.len()];
    let mut solved = MapSolve {
        values: None,
        error_estimate: 0.0,
        solves: 0,
        tol: settings.tol,
        warnings: Vec::new(),
    };
    if !queries.is_empty() {
        solved = match spec.scene().body.cover_m() {
            Some(h_m) => covered_values(
                creep,
                spec.poisson,
                h_m * 1e3,
                &queries,
                scene_tol(spec, settings.tol),
            ),
            None => {
                let problem = ReducedProblem::new(creep, spec.poisson)?;
                let (v, curve) = friction_map(&problem, &queries, settings)?;
                MapSolve {
                    values: Some(v),
                    error_estimate: curve.error_estimate,
                    solves: curve.solves,
                    tol: settings.tol,
                    warnings: Vec::new(),
                }
            }
        };
        for (&i, v) in solvable
            .iter()
            .zip(solved.values.take().into_iter().flatten())
        {
            values[i] = Some(v);
        }
    }
    let mut warnings = solved.warnings;
    let (points, grid, curves, long) = sort_map_points(&jobs, values, spec);
    // the covered body's validity check (contact::cover::roll_cover) at the listed map points
    if long > 0.3 {
        warnings.push(format!(
            "map: contact length / radius up to {long:.2} > 0.3: the flat-surface, small-strain \
             assumptions lose validity"
        ));
    }
    Ok(FrictionMaps {
        points,
        grid,
        curves,
        error_estimate: solved.error_estimate,
        solves: solved.solves,
        tol: solved.tol,
        warnings,
    })
}

/// The values of a map's interpolant at the queries (None: not built), its error estimate, solves,
/// tolerance and warnings.
struct MapSolve {
    values: Option<Vec<MapValue>>,
    error_estimate: f64,
    solves: usize,
    tol: f64,
    warnings: Vec<String>,
}

/// A covered scene's map values from the 2-D interpolant on the bonded layer (cover `h_mm`), at
/// `tol` (the scene's, [`scene_tol`]), with the covered maps' own panels and degrees
/// ([`MapSettings::covered`]). A surface that cannot be built gives no values and the reason in
/// the warnings; one short of its tolerance says so.
fn covered_values(
    creep: &crate::CreepSpectrum,
    poisson: Option<f64>,
    h_mm: f64,
    queries: &[MapQuery],
    tol: f64,
) -> MapSolve {
    let cs = MapSettings::covered(tol);
    let mut out = MapSolve {
        values: None,
        error_estimate: 0.0,
        solves: 0,
        tol,
        warnings: Vec::new(),
    };
    let covered = CoveredProblem::new(creep, poisson, h_mm * 1e-3)
        .and_then(|p| covered_map(&p, queries, &cs));
    match covered {
        Ok((v, surface)) => {
            out.error_estimate = surface.error_estimate;
            out.solves = surface.solves;
            out.warnings
                .extend(surface.warnings.iter().map(|w| format!("map node: {w}")));
            if surface.error_estimate > tol {
                out.warnings.push(format!(
                    "covered map: error estimate {:.1e} (interpolation {:.1e} + layer \
                     solves {:.1e}) exceeds its tolerance {tol:.0e}",
                    surface.error_estimate,
                    surface.interpolation_estimate,
                    surface.node_error_bound
                ));
            }
            out.values = Some(v);
        }
        Err(e) => {
            out.warnings.push(crate::results::cap_line(&format!(
                "covered map not built: {e}"
            )));
        }
    }
    out
}

/// The map points of each job sorted into listed points, grid and curves (by the job's kind, see
/// [`map_jobs`]), and the largest contact length / radius of a covered scene's listed points (0 on
/// the half-space).
fn sort_map_points(
    jobs: &[(f64, f64, f64, u8)],
    values: Vec<Option<MapValue>>,
    spec: &SceneSpec,
) -> (Vec<MapPoint>, Vec<MapPoint>, Vec<MapPoint>, f64) {
    let (mut points, mut grid, mut curves) = (Vec::new(), Vec::new(), Vec::new());
    let mut long = 0.0f64;
    for (&(t, v, n, kind), value) in jobs.iter().zip(values) {
        let p = MapPoint {
            temp_c: t,
            speed_m_s: v,
            load_n_per_m: n,
            friction: value.map_or(f64::NAN, |m| m.friction),
            contact_length_mm: value.map_or(f64::NAN, |m| m.contact_length_m * 1e3),
        };
        if kind == 0 && spec.scene().body.cover_m().is_some() {
            long = long.max(p.contact_length_mm / spec.roll_radius_mm);
        }
        match kind {
            0 => points.push(p),
            1 => grid.push(p),
            _ => curves.push(p),
        }
    }
    (points, grid, curves, long)
}
