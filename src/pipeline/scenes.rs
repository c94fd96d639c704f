//! Rolling scenes in TOML ([`SceneSet`]) and a compound's friction in them ([`friction_vs_temperature`]).
//!
//! Input: a TOML file of `[[scene]]` tables (units in the keys: `roll_radius_mm`, `load_n_per_m`,
//! `speed_m_s`, `temps_c`) and a [`CompoundFit`]; output: [`FrictionPoint`]s, one per temperature, from
//! the contact stage's error-controlled load solve (crate::contact::roll_auto, thesis eq. 3.12 for F/N) on the creep
//! spectrum shifted to each temperature (MATH.md §6).

use super::compound_fit::CompoundFit;
use super::error::{io, PipelineError};
use super::fit_compound::measured_range_c;
use super::friction_map::{friction_map, MapQuery, MapSettings, MapValue, ReducedProblem};
use crate::contact::Scene;
use crate::contact::{roll, AutoSettings, Body, ContactSettings, Scheme};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// The scenes shipped with viscoroll (data/scenes.toml, compiled in).
pub const DEFAULT_SCENES_TOML: &str = include_str!("../../data/scenes.toml");

/// One named scene: a rigid roll on the compound, at a list of temperatures.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneSpec {
    /// Name (used in file names and `rank --scene`).
    pub name: String,
    /// What it stands for.
    #[serde(default)]
    pub description: String,
    /// Roll radius in mm.
    pub roll_radius_mm: f64,
    /// Load per unit width in N/m.
    pub load_n_per_m: f64,
    /// Rolling speed in m/s.
    pub speed_m_s: f64,
    /// Temperatures in °C.
    pub temps_c: Vec<f64>,
    /// Poisson's ratio (default: the spectrum's).
    #[serde(default)]
    pub poisson: Option<f64>,
    /// Temperatures in °C of the friction maps (each solve costs; keep it short).
    #[serde(default)]
    pub map_temps_c: Vec<f64>,
    /// Speeds in m/s of the friction map against speed (at the scene's load, each map temperature).
    #[serde(default)]
    pub map_speeds_m_s: Vec<f64>,
    /// Loads per unit width in N/m of the friction map against load (at the scene's speed).
    #[serde(default)]
    pub map_loads_n_per_m: Vec<f64>,
}

impl SceneSpec {
    /// The contact scene (SI).
    pub fn scene(&self) -> Scene {
        Scene {
            radius_m: self.roll_radius_mm * 1e-3,
            load_n_per_m: self.load_n_per_m,
            speed_m_s: self.speed_m_s,
            poisson: self.poisson,
            body: Body::HalfSpace,
        }
    }
}

/// A set of scenes, as read from TOML.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneSet {
    /// The scenes, in file order.
    pub scene: Vec<SceneSpec>,
}

impl SceneSet {
    /// Parse and check a TOML text (`origin` names it in errors).
    pub fn parse(text: &str, origin: &Path) -> Result<Self, PipelineError> {
        let cfg = |message: String| PipelineError::Config {
            path: origin.to_path_buf(),
            message,
        };
        let set: SceneSet = toml::from_str(text).map_err(|e| cfg(e.to_string()))?;
        if set.scene.is_empty() {
            return Err(cfg("no [[scene]] table".into()));
        }
        for (i, s) in set.scene.iter().enumerate() {
            let at = |key: &str| format!("scene[{i}] ({}): {key}", s.name);
            if s.name.is_empty()
                || !s
                    .name
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
            {
                return Err(cfg(format!(
                    "scene[{i}]: name {:?} must be non-empty letters, digits, '-' or '_'",
                    s.name
                )));
            }
            if set.scene[..i].iter().any(|o| o.name == s.name) {
                return Err(cfg(format!("{}: duplicate name", at("name"))));
            }
            for (key, v) in [
                ("roll_radius_mm", s.roll_radius_mm),
                ("load_n_per_m", s.load_n_per_m),
                ("speed_m_s", s.speed_m_s),
            ] {
                if !(v.is_finite() && v > 0.0) {
                    return Err(cfg(format!("{} must be finite and > 0, got {v}", at(key))));
                }
            }
            if s.temps_c.is_empty() || s.temps_c.iter().any(|t| !t.is_finite() || *t < -273.15) {
                return Err(cfg(format!(
                    "{} must be a non-empty list of temperatures in °C above −273.15",
                    at("temps_c")
                )));
            }
            for (key, list) in [
                ("map_speeds_m_s", &s.map_speeds_m_s),
                ("map_loads_n_per_m", &s.map_loads_n_per_m),
            ] {
                if !list.is_empty() && s.map_temps_c.is_empty() {
                    return Err(cfg(format!("{} needs map_temps_c", at(key))));
                }
                if let Some(v) = list.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
                    return Err(cfg(format!(
                        "{} must hold finite values > 0, got {v}",
                        at(key)
                    )));
                }
            }
            s.scene().validate().map_err(|e| cfg(at(&e.to_string())))?;
        }
        Ok(set)
    }

    /// Read a TOML file.
    pub fn read(path: &Path) -> Result<Self, PipelineError> {
        let text = std::fs::read_to_string(path).map_err(io(path))?;
        Self::parse(&text, path)
    }

    /// The shipped scenes.
    pub fn shipped() -> Self {
        Self::parse(DEFAULT_SCENES_TOML, Path::new("data/scenes.toml"))
            .expect("the shipped scenes file is valid (tested)")
    }
}

/// The friction of a compound at one temperature of a scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FrictionPoint {
    /// Temperature in °C.
    pub temp_c: f64,
    /// log10 a_T used.
    pub log10_a_t: f64,
    /// Rolling-friction coefficient F*/N* (NaN when the solve failed).
    pub friction: f64,
    /// Rolling resistance per unit width in N/m.
    pub resistance_n_per_m: f64,
    /// Contact length in mm.
    pub contact_length_mm: f64,
    /// The temperature lies outside the measured ones (the shift law is extrapolated).
    pub extrapolated: bool,
    /// Why the solve failed, if it did.
    #[serde(default)]
    pub error: Option<String>,
}

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

/// Friction of `fit` at every temperature of `spec` (parallel over temperatures). A failed solve
/// gives a point with `error` set, not an error: the other temperatures still count.
pub fn friction_vs_temperature(
    fit: &CompoundFit,
    spec: &SceneSpec,
    settings: &ContactSettings,
) -> Result<Vec<FrictionPoint>, PipelineError> {
    let creep = fit.creep.as_ref().ok_or_else(|| PipelineError::NoCreep {
        compound: fit.compound.clone(),
    })?;
    let range = measured_range_c(fit);
    let scene = spec.scene();
    Ok(spec
        .temps_c
        .par_iter()
        .map(|&t| {
            let failed = |e: String, log10_a_t: f64, extrapolated: bool| FrictionPoint {
                temp_c: t,
                log10_a_t,
                friction: f64::NAN,
                resistance_n_per_m: f64::NAN,
                contact_length_mm: f64::NAN,
                extrapolated,
                error: Some(e),
            };
            let at = match creep.at_temperature(&fit.shift_law, t, range) {
                Ok(a) => a,
                Err(e) => return failed(e.to_string(), f64::NAN, true),
            };
            match roll(&scene, &at.spectrum, settings) {
                Ok(sol) => FrictionPoint {
                    temp_c: t,
                    log10_a_t: at.log10_a_t,
                    friction: sol.friction,
                    resistance_n_per_m: sol.resistance_n_per_m,
                    contact_length_mm: sol.contact_length_m * 1e3,
                    extrapolated: at.extrapolated,
                    error: None,
                },
                Err(e) => failed(e.to_string(), at.log10_a_t, at.extrapolated),
            }
        })
        .collect())
}

/// One point of a friction map (speed or load varied at a temperature).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MapPoint {
    /// Temperature in °C.
    pub temp_c: f64,
    /// Speed in m/s.
    pub speed_m_s: f64,
    /// Load per unit width in N/m.
    pub load_n_per_m: f64,
    /// F*/N* (NaN when the temperature's shift is undefined).
    pub friction: f64,
    /// Contact length in mm (NaN likewise).
    #[serde(default)]
    pub contact_length_mm: f64,
}

/// Points per axis of the 2-D (speed × load) map, log-spaced over the listed speeds and loads.
pub const GRID_POINTS: usize = 30;

/// The friction maps of one compound in one scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FrictionMaps {
    /// F/N against `map_speeds_m_s` (at the scene's load) and against `map_loads_n_per_m` (at the
    /// scene's speed), at every map temperature.
    pub points: Vec<MapPoint>,
    /// F/N on a [`GRID_POINTS`]² grid of speed × load (log-spaced between the smallest and largest
    /// listed speed and load) at every map temperature; empty unless both lists span a range.
    pub grid: Vec<MapPoint>,
    /// Interpolation error estimate of the reduced curve (relative, on F/N and contact length).
    pub error_estimate: f64,
    /// Contact solves made for the curve.
    pub solves: usize,
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
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if hi.partial_cmp(&lo) != Some(std::cmp::Ordering::Greater) {
        return vec![];
    }
    (0..GRID_POINTS)
        .map(|k| (lo.ln() + (hi.ln() - lo.ln()) * k as f64 / (GRID_POINTS - 1) as f64).exp())
        .collect()
}

/// Friction maps of `fit` in `spec` ([`FrictionMaps`]), all from one interpolant of the
/// dimensionless solution in the reduced variable s = l_g/(V·a_T) (module
/// [`super::friction_map`]: exact scaling, interpolation error ≤ `settings.tol`).
pub fn friction_maps(
    fit: &CompoundFit,
    spec: &SceneSpec,
    settings: &MapSettings,
) -> Result<FrictionMaps, PipelineError> {
    let creep = fit.creep.as_ref().ok_or_else(|| PipelineError::NoCreep {
        compound: fit.compound.clone(),
    })?;
    let problem = ReducedProblem::new(creep, spec.poisson)?;
    let (speeds, loads) = (
        log_grid(&spec.map_speeds_m_s),
        log_grid(&spec.map_loads_n_per_m),
    );
    // (temperature, speed, load, in the grid?) for every point; a_T per temperature
    let mut jobs = Vec::new();
    for &t in &spec.map_temps_c {
        for &v in &spec.map_speeds_m_s {
            jobs.push((t, v, spec.load_n_per_m, false));
        }
        for &n in &spec.map_loads_n_per_m {
            jobs.push((t, spec.speed_m_s, n, false));
        }
        if !speeds.is_empty() && !loads.is_empty() {
            for &v in &speeds {
                for &n in &loads {
                    jobs.push((t, v, n, true));
                }
            }
        }
    }
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
    let queries: Vec<MapQuery> = solvable
        .iter()
        .map(|&i| MapQuery {
            radius_m: spec.roll_radius_mm * 1e-3,
            load_n_per_m: jobs[i].2,
            speed_m_s: jobs[i].1,
            a_t: a_t_of(jobs[i].0).unwrap_or(f64::NAN),
        })
        .collect();
    let mut values: Vec<Option<MapValue>> = vec![None; jobs.len()];
    let (mut error_estimate, mut solves) = (0.0, 0);
    if !queries.is_empty() {
        let (v, curve) = friction_map(&problem, &queries, settings)?;
        for (&i, v) in solvable.iter().zip(v) {
            values[i] = Some(v);
        }
        error_estimate = curve.error_estimate;
        solves = curve.solves;
    }
    let (mut points, mut grid) = (Vec::new(), Vec::new());
    for (&(t, v, n, in_grid), value) in jobs.iter().zip(values) {
        let p = MapPoint {
            temp_c: t,
            speed_m_s: v,
            load_n_per_m: n,
            friction: value.map_or(f64::NAN, |m| m.friction),
            contact_length_mm: value.map_or(f64::NAN, |m| m.contact_length_m * 1e3),
        };
        if in_grid {
            grid.push(p);
        } else {
            points.push(p);
        }
    }
    Ok(FrictionMaps {
        points,
        grid,
        error_estimate,
        solves,
    })
}

/// Mean friction over the temperatures that solved (NaN if none did).
pub fn mean_friction(points: &[FrictionPoint]) -> f64 {
    let ok: Vec<f64> = points
        .iter()
        .map(|p| p.friction)
        .filter(|f| f.is_finite())
        .collect();
    if ok.is_empty() {
        f64::NAN
    } else {
        ok.iter().sum::<f64>() / ok.len() as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shipped_scenes_parse_with_units_in_keys() {
        let set = SceneSet::shipped();
        let idler = set
            .scene
            .iter()
            .find(|s| s.name == "conveyor-idler")
            .unwrap();
        // The issue asks for −40 … +40 °C at the idler.
        let lo = idler.temps_c.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = idler
            .temps_c
            .iter()
            .copied()
            .fold(f64::NEG_INFINITY, f64::max);
        assert_eq!((lo, hi), (-40.0, 40.0));
        assert!(set.scene.len() >= 2);
    }

    #[test]
    fn bad_scene_names_the_key() {
        let text = "[[scene]]\nname = \"a\"\nroll_radius_mm = -1\nload_n_per_m = 1\nspeed_m_s = 1\ntemps_c = [20]\n";
        let e = SceneSet::parse(text, Path::new("s.toml"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("s.toml") && e.contains("roll_radius_mm"), "{e}");
        let e = SceneSet::parse("[[scene]]\nname = \"a\"\nradius = 1\n", Path::new("s.toml"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("radius"), "{e}");
    }
}
