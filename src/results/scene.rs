//! Scenes and what a compound does in them, as plain serde data: the rolling scenes read from TOML
//! ([`SceneSet`], units in the keys: `roll_radius_mm`, `load_n_per_m`, `speed_m_s`, `temps_c`), the
//! friction of a compound at each temperature of a scene ([`FrictionPoint`]) and its friction maps
//! ([`FrictionMaps`]).
//!
//! Input: TOML text; output: checked [`SceneSet`]s (every number finite and in its physical range,
//! errors naming the scene and key). The pipeline fills the result types; the report writes them.

use crate::contact::{Body, Scene};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Why a scenes file could not be used.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum SceneError {
    /// The file is not valid TOML, or a scene breaks a rule (the message names scene and key).
    #[error("{path}: {message}")]
    Invalid {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
    /// The file could not be read.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
}

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
    /// Thickness in mm of a rubber cover bonded to a rigid carcass; absent: a half-space. Read, it
    /// becomes the scene's body ([`SceneSpec::scene`]: `Body::Auto`, the cheapest body within
    /// tolerance, chosen by `contact::cover::roll_cover`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cover_thickness_mm: Option<f64>,
    /// Temperatures in °C of the friction maps (each solve costs; keep it short).
    #[serde(default)]
    pub map_temps_c: Vec<f64>,
    /// Relative tolerance of the scene's contact solves and friction maps (1e−10 … 1e−2); absent:
    /// the main job's defaults, 1e−6 on a half-space and 1e−3 on a cover (`run --tol` sets it for
    /// every scene without one).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tol: Option<f64>,
    /// Speeds in m/s of the friction map against speed (at the scene's load, each map temperature).
    #[serde(default)]
    pub map_speeds_m_s: Vec<f64>,
    /// Loads per unit width in N/m of the friction map against load (at the scene's speed).
    #[serde(default)]
    pub map_loads_n_per_m: Vec<f64>,
}

impl SceneSpec {
    /// The contact scene (SI), its body from `cover_thickness_mm`: the half-space without one, else
    /// the cover with the body chosen by `auto` (`Body::Auto`).
    pub fn scene(&self) -> Scene {
        Scene {
            radius_m: self.roll_radius_mm * 1e-3,
            load_n_per_m: self.load_n_per_m,
            speed_m_s: self.speed_m_s,
            poisson: self.poisson,
            body: match self.cover_thickness_mm {
                Some(h_mm) => Body::Auto {
                    thickness_m: h_mm * 1e-3,
                },
                None => Body::HALF_SPACE,
            },
        }
    }
}

/// The range of a scene's `tol` (and `run --tol`): the friction maps' (crate::contact::maps), the
/// narrower of theirs and the contact solver's.
pub(crate) const TOL_RANGE: (f64, f64) = (1e-10, 1e-2);

/// The physical range (exclusive lower, inclusive upper bound) of a scene's number, by key: radius
/// up to 100 m, loads up to 1e8 N/m (100 MN per metre of width: far beyond any rubber contact), speeds
/// up to 1000 m/s (above the speed of sound in rubber the steady-state theory does not apply).
pub(crate) fn range_of(key: &str) -> (f64, f64) {
    match key {
        "roll_radius_mm" => (0.0, 1e5),
        "load_n_per_m" | "map_loads_n_per_m" => (0.0, 1e8),
        "speed_m_s" | "map_speeds_m_s" => (0.0, 1e3),
        _ => (f64::NEG_INFINITY, f64::INFINITY),
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
    pub fn parse(text: &str, origin: &Path) -> Result<Self, SceneError> {
        let cfg = |message: String| SceneError::Invalid {
            path: origin.to_path_buf(),
            message,
        };
        let set: SceneSet = toml::from_str(text).map_err(|e| cfg(e.to_string()))?;
        if set.scene.is_empty() {
            return Err(cfg("no [[scene]] table".into()));
        }
        use crate::limits as lim;
        let budget = |e: lim::LimitError| cfg(e.to_string());
        lim::at_most("[[scene]] tables", set.scene.len(), lim::SCENES_MAX).map_err(budget)?;
        let points = set.scene.iter().map(|s| s.temps_c.len()).sum();
        let cells = set
            .scene
            .iter()
            .map(|s| {
                s.map_temps_c
                    .len()
                    .saturating_mul(s.map_speeds_m_s.len() + s.map_loads_n_per_m.len())
            })
            .fold(0usize, usize::saturating_add);
        lim::scene_work(
            "the scenes' work (Σ temps_c + map cells / 5)",
            points,
            cells,
        )
        .map_err(budget)?;
        for (i, s) in set.scene.iter().enumerate() {
            s.check(i, &set.scene[..i]).map_err(cfg)?;
        }
        Ok(set)
    }

    /// Read a TOML file.
    pub fn read(path: &Path) -> Result<Self, SceneError> {
        let text = crate::fsutil::read_regular_to_string(path, crate::limits::SETTINGS_BYTES_MAX)
            .map_err(|source| SceneError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        Self::parse(&text, path)
    }

    /// The shipped scenes.
    pub fn shipped() -> Self {
        Self::parse(DEFAULT_SCENES_TOML, Path::new("data/scenes.toml"))
            .expect("the shipped scenes file is valid (tested)")
    }
}

impl SceneSpec {
    /// Check scene `i` of a set (`earlier`: the scenes before it, for duplicate names): its name,
    /// ranges, lists and budgets; the message names the scene and the key.
    fn check(&self, i: usize, earlier: &[SceneSpec]) -> Result<(), String> {
        use crate::limits as lim;
        let s = self;
        lim::name(&format!("scene[{i}]: name"), &s.name).map_err(|e| e.to_string())?;
        let at = |key: &str| format!("scene[{i}] ({}): {key}", s.name);
        if s.name.is_empty()
            || !s
                .name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
        {
            return Err(format!(
                "scene[{i}]: name {:?} must be non-empty letters, digits, '-' or '_'",
                s.name
            ));
        }
        if earlier.iter().any(|o| o.name == s.name) {
            return Err(format!("{}: duplicate name", at("name")));
        }
        for (key, v) in [
            ("roll_radius_mm", s.roll_radius_mm),
            ("load_n_per_m", s.load_n_per_m),
            ("speed_m_s", s.speed_m_s),
        ] {
            let (lo, hi) = range_of(key);
            if !(v.is_finite() && v > lo && v <= hi) {
                return Err(format!(
                    "{} must be finite, > {lo} and ≤ {hi:e}, got {v}",
                    at(key)
                ));
            }
        }
        for (key, list, max) in [
            ("temps_c", &s.temps_c, lim::SCENE_TEMPS_MAX),
            ("map_temps_c", &s.map_temps_c, lim::MAP_LIST_MAX),
        ] {
            lim::at_most(&at(key), list.len(), max).map_err(|e| e.to_string())?;
            for t in list.iter() {
                lim::temperature_c(&at(key), *t).map_err(|e| e.to_string())?;
            }
        }
        if s.temps_c.is_empty() {
            return Err(format!("{} must not be empty", at("temps_c")));
        }
        for (key, list) in [
            ("map_speeds_m_s", &s.map_speeds_m_s),
            ("map_loads_n_per_m", &s.map_loads_n_per_m),
        ] {
            if !list.is_empty() && s.map_temps_c.is_empty() {
                return Err(format!("{} needs map_temps_c", at(key)));
            }
            lim::at_most(&at(key), list.len(), lim::MAP_LIST_MAX).map_err(|e| e.to_string())?;
            let (lo, hi) = range_of(key);
            if let Some(v) = list
                .iter()
                .find(|v| !(v.is_finite() && **v > lo && **v <= hi))
            {
                return Err(format!(
                    "{} must hold finite values > {lo} and ≤ {hi:e}, got {v}",
                    at(key)
                ));
            }
        }
        if let Some(t) = s.tol {
            if !(TOL_RANGE.0..=TOL_RANGE.1).contains(&t) {
                return Err(format!(
                    "{} must lie in [{:e}, {:e}], got {t}",
                    at("tol"),
                    TOL_RANGE.0,
                    TOL_RANGE.1
                ));
            }
        }
        lim::map_cells(
            &at("map_temps_c × (map_speeds_m_s + map_loads_n_per_m)"),
            s.map_temps_c.len(),
            s.map_speeds_m_s.len(),
            s.map_loads_n_per_m.len(),
        )
        .map_err(|e| e.to_string())?;
        if let Some(h) = s.cover_thickness_mm {
            if !(h.is_finite() && h > 0.0) {
                return Err(format!(
                    "{} must be finite and > 0 (omit it for a half-space), got {h}",
                    at("cover_thickness_mm")
                ));
            }
            lim::cover(&at("cover_thickness_mm"), h, s.roll_radius_mm)
                .map_err(|e| e.to_string())?;
        }
        s.scene().validate().map_err(|e| at(&e.to_string()))?;
        Ok(())
    }
}

/// The friction of a compound at one temperature of a scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FrictionPoint {
    /// Temperature in °C.
    pub temp_c: f64,
    /// log10 a_T used.
    #[serde(deserialize_with = "nan_if_null")]
    pub log10_a_t: f64,
    /// Rolling-friction coefficient F*/N* (NaN when the solve failed).
    #[serde(deserialize_with = "nan_if_null")]
    pub friction: f64,
    /// Rolling resistance per unit width in N/m.
    #[serde(deserialize_with = "nan_if_null")]
    pub resistance_n_per_m: f64,
    /// Contact length in mm.
    #[serde(deserialize_with = "nan_if_null")]
    pub contact_length_mm: f64,
    /// The temperature lies outside the measured ones (the shift law is extrapolated).
    pub extrapolated: bool,
    /// Why the solve failed, if it did.
    #[serde(default)]
    pub error: Option<String>,
    /// The body solved (`half-space`, `layer`, `winkler-constrained`, …; contact::body::layer).
    #[serde(default = "half_space_name")]
    pub model: String,
    /// Why that body (empty for a scene without a cover).
    #[serde(default)]
    pub model_reason: String,
    /// Validity warnings of the contact solve (a contact long against the roll radius, cover
    /// indentation, contact checks).
    #[serde(default)]
    pub warnings: Vec<String>,
    /// The uncertainty band of `friction` (None when bands were not computed, `--no-bands`).
    #[serde(default)]
    pub band: Option<FrictionBand>,
    /// The friction of each replicate specimen's own fit (empty with one specimen; NaN where one
    /// failed): the compound's fit pools them (crate::pipeline::specimens).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub specimens: Vec<f64>,
    /// Why the point is not determined ([`FrictionPoint::determine`]): then it is shown with its
    /// reason, hollow, and never ranked or averaged.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub undetermined: Option<String>,
    /// The contact solver's estimate of the relative error of `friction` (plus, where `auto` chose
    /// a cheaper body than the bonded layer, its estimated difference from the layer); None when
    /// the solve failed or gave none.
    #[serde(default)]
    pub error_estimate: Option<f64>,
}

/// Percentiles of F*/N* from the measurement's own scatter propagated through the pipeline.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FrictionBand {
    /// 5th percentile of F*/N*.
    pub p05: f64,
    /// Median of F*/N*.
    pub p50: f64,
    /// 95th percentile of F*/N*.
    pub p95: f64,
}

/// An f64 that JSON wrote as `null` (serde_json writes NaN so: a failed point's friction) read
/// back as NaN.
fn nan_if_null<'de, D: serde::Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::NAN))
}

fn half_space_name() -> String {
    "half-space".into()
}

/// A point whose 90 % band spans more than this ratio p95/p05 is not determined: the data leave it
/// open by more than an order of magnitude (issue 31).
pub const UNDETERMINED_BAND_RATIO: f64 = 10.0;

/// A point whose temperature lies more than this (K) beyond the measured isotherms is not
/// determined: the shift law there continues its end segment over more than one to two isotherm
/// steps (5–10 K in the shipped exports), where the data say nothing of its curvature, and the
/// tail assumptions of docs/MATH.md eq. 15.8 part fast (issue 31).
pub const EXTRAPOLATION_LIMIT_K: f64 = 10.0;

impl FrictionPoint {
    /// Decide whether the point is determined: not when its band (the measurement's and the
    /// model's terms, before the between-specimen term: that one is the same for every point and
    /// stated apart) spans more than `UNDETERMINED_BAND_RATIO`, or its temperature lies more
    /// than `EXTRAPOLATION_LIMIT_K` beyond `measured_c` (the measured temperatures). A failed
    /// point is failed, not undetermined.
    pub fn determine(&mut self, measured_c: Option<(f64, f64)>) {
        if self.error.is_some() || !self.friction.is_finite() {
            return;
        }
        let mut why = Vec::new();
        if let Some(b) = self.band {
            let r = b.p95 / b.p05;
            // a NaN ratio (a broken band) is not determined either
            if r.is_nan() || r > UNDETERMINED_BAND_RATIO {
                why.push(format!(
                    "its band spans a factor {} (p95/p05 > {UNDETERMINED_BAND_RATIO})",
                    factor_text(r)
                ));
            }
        }
        if let Some((lo, hi)) = measured_c {
            let beyond = (lo - self.temp_c).max(self.temp_c - hi);
            if beyond > EXTRAPOLATION_LIMIT_K {
                why.push(format!(
                    "the shift law is extrapolated {beyond} K beyond the measured {lo}…{hi} °C \
                     (limit {EXTRAPOLATION_LIMIT_K} K)"
                ));
            }
        }
        self.undetermined =
            (!why.is_empty()).then(|| format!("not determined: {}", why.join("; ")));
    }

    /// Computed and determined: may be ranked and averaged.
    pub fn counts(&self) -> bool {
        self.error.is_none() && self.friction.is_finite() && self.undetermined.is_none()
    }

    /// Every flag of the point in one line: failure, extrapolated shift law, contact warnings.
    pub fn note(&self) -> String {
        let mut v: Vec<String> = Vec::new();
        if let Some(e) = &self.error {
            v.push(format!("failed: {e}"));
        }
        if let Some(u) = &self.undetermined {
            v.push(u.clone());
        }
        if self.extrapolated {
            v.push("extrapolated shift law (outside the measured temperatures)".into());
        }
        v.extend(self.warnings.iter().cloned());
        super::line::cap_line(&v.join("; ").replace(['\r', '\n'], " "))
    }
}

/// A ratio as printed: "12.3", "330", "3.3e12" (no percentages beyond 1000 %: issue 31).
pub fn factor_text(r: f64) -> String {
    if r < 100.0 {
        format!("{r:.1}")
    } else if r < 1000.0 {
        format!("{r:.0}")
    } else {
        format!("{r:.1e}")
    }
}

/// Points per axis of the 2-D (speed × load) map, log-spaced over the listed speeds and loads.
pub const GRID_POINTS: usize = 30;

/// Points of each dense speed and load curve of a half-space scene's maps ([`FrictionMaps::curves`]).
pub const CURVE_POINTS: usize = 40;

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

/// The friction maps of one compound in one scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FrictionMaps {
    /// F/N against `map_speeds_m_s` (at the scene's load) and against `map_loads_n_per_m` (at the
    /// scene's speed), at every map temperature.
    pub points: Vec<MapPoint>,
    /// F/N on a `GRID_POINTS`² grid of speed × load (log-spaced between the smallest and largest
    /// listed speed and load) at every map temperature; empty unless both lists span a range.
    pub grid: Vec<MapPoint>,
    /// F/N against speed (at the scene's load) and against load (at the scene's speed) at
    /// `CURVE_POINTS` log-spaced values between the smallest and largest listed one, at every map
    /// temperature, from the same interpolant as `points` (for the datasheet's curves).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub curves: Vec<MapPoint>,
    /// Interpolation error estimate of the reduced curve (relative, on F/N and contact length).
    pub error_estimate: f64,
    /// Contact solves made for the curve.
    pub solves: usize,
    /// The relative tolerance asked of the interpolant.
    pub tol: f64,
    /// Warnings of the map (a covered surface not built or short of its tolerance, node solver
    /// warnings, validity); the pipeline copies them to the scene's friction points.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
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
    fn cover_thickness_mm_becomes_the_scenes_body() {
        // scenes.toml keeps its key: a cover is read into the scene's body (`auto` on it), its
        // absence is the half-space
        let text =
            "[[scene]]\nname = \"c\"\nroll_radius_mm = 66.5\nload_n_per_m = 1e4\nspeed_m_s = 4\n\
                    temps_c = [20]\ncover_thickness_mm = 5.0\n\n[[scene]]\nname = \"h\"\n\
                    roll_radius_mm = 66.5\nload_n_per_m = 1e4\nspeed_m_s = 4\ntemps_c = [20]\n";
        let set = SceneSet::parse(text, Path::new("s.toml")).unwrap();
        assert_eq!(set.scene[0].scene().body, Body::Auto { thickness_m: 5e-3 });
        assert_eq!(set.scene[0].scene().body.cover_m(), Some(5e-3));
        assert_eq!(set.scene[1].scene().body, Body::HALF_SPACE);
        assert_eq!(set.scene[0].scene().radius_m, 0.0665);
    }

    #[test]
    fn bad_scene_names_the_key() {
        let text = "[[scene]]\nname = \"a\"\nroll_radius_mm = -1\nload_n_per_m = 1\nspeed_m_s = 1\ntemps_c = [20]\n";
        let e = SceneSet::parse(text, Path::new("s.toml"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("s.toml") && e.contains("roll_radius_mm"), "{e}");
        for (key, v) in [
            ("speed_m_s", "1e300"),
            ("load_n_per_m", "inf"),
            ("roll_radius_mm", "nan"),
        ] {
            let text = "[[scene]]\nname = \"a\"\nroll_radius_mm = 10\nload_n_per_m = 1\nspeed_m_s = 1\ntemps_c = [20]\n"
                .replace(&format!("{key} = "), &format!("{key} = {v} #"));
            let e = SceneSet::parse(&text, Path::new("s.toml"))
                .unwrap_err()
                .to_string();
            assert!(e.contains(key), "{key}: {e}");
        }
        let text = "[[scene]]\nname = \"a\"\nroll_radius_mm = 10\nload_n_per_m = 1\nspeed_m_s = 1\ntemps_c = [1e9]\n";
        let e = SceneSet::parse(text, Path::new("s.toml"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("temps_c"), "{e}");
        let e = SceneSet::parse("[[scene]]\nname = \"a\"\nradius = 1\n", Path::new("s.toml"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("radius"), "{e}");
    }
}
