//! The outcome of the main job: one [`CompoundOutcome`] per compound, its standing in each scene
//! ([`SceneStanding`], the ranking's rule) and the [`RunSummary`] that `viscoroll run --json` prints.
//!
//! Input: what the pipeline found per compound; output: plain serde data read by the ranking, the
//! index page and the CLI.
//!
//! Ranking rule ([`standing`]): a compound's figure in a scene is the mean F/N over the scene's
//! temperatures that computed and lie inside its measured temperatures (with `allow_extrapolation`,
//! the extrapolated ones too, listed). It is ranked among trusted compounds only if its fit has no
//! quality figure out of bounds and no temperature of the scene failed; otherwise it is listed apart
//! with its reasons. A failed point never enters a mean.

use super::scene::FrictionPoint;
use serde::{Deserialize, Serialize};
use std::path::PathBuf;

/// Longest error or warning line kept in outcomes and reports, in bytes (a 30 MB line in an input
/// must not become a 30 MB line in index.html).
pub const MAX_LINE_BYTES: usize = 600;

/// `s` cut to [`MAX_LINE_BYTES`] (at a character boundary) with a note of what was cut.
pub fn cap_line(s: &str) -> String {
    if s.len() <= MAX_LINE_BYTES {
        return s.to_string();
    }
    let mut end = MAX_LINE_BYTES;
    while !s.is_char_boundary(end) {
        end -= 1;
    }
    format!("{}… ({} more bytes cut)", &s[..end], s.len() - end)
}

/// A compound in one scene: its mean friction and whether it may be ranked among trusted ones.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SceneStanding {
    /// Scene name.
    pub scene: String,
    /// Mean F/N over `temps_c`; `None` when no temperature counts.
    pub mean_friction: Option<f64>,
    /// The temperatures averaged (°C).
    pub temps_c: Vec<f64>,
    /// Temperatures outside the measured ones (°C): averaged with `allow_extrapolation`, else left out.
    pub extrapolated_temps_c: Vec<f64>,
    /// Temperatures whose friction could not be computed (°C), never averaged.
    pub failed_temps_c: Vec<f64>,
    /// Why the compound is not ranked among trusted ones in this scene (empty: it is).
    pub untrusted: Vec<String>,
    /// Uncertainty band of `mean_friction` (crate::bands; `None` with `--no-bands` or without a
    /// mean).
    pub band: Option<super::scene::FrictionBand>,
    /// The ranked compounds of this scene whose order against this one is not significant (see
    /// [`PairComparison::tied`]); empty with `--no-bands`.
    pub tied_with: Vec<String>,
}

impl SceneStanding {
    /// Ranked among the trusted compounds.
    pub fn trusted(&self) -> bool {
        self.untrusted.is_empty() && self.mean_friction.is_some()
    }
}

/// The standing of a compound in `scene` (see the module docs); `fit_untrusted` holds the reasons
/// its fit is not trusted (quality figures out of bounds).
pub fn standing(
    scene: &str,
    points: &[FrictionPoint],
    fit_untrusted: &[String],
    allow_extrapolation: bool,
) -> SceneStanding {
    let failed: Vec<&FrictionPoint> = points
        .iter()
        .filter(|p| p.error.is_some() || !p.friction.is_finite())
        .collect();
    let used: Vec<&FrictionPoint> = points
        .iter()
        .filter(|p| p.error.is_none() && p.friction.is_finite())
        .filter(|p| allow_extrapolation || !p.extrapolated)
        .collect();
    let mean = (!used.is_empty())
        .then(|| used.iter().map(|p| p.friction).sum::<f64>() / used.len() as f64);
    let mut untrusted: Vec<String> = fit_untrusted.to_vec();
    for p in &failed {
        untrusted.push(cap_line(&format!(
            "friction failed at {} °C: {}",
            p.temp_c,
            p.error.as_deref().unwrap_or("not finite")
        )));
    }
    if mean.is_none() && failed.len() < points.len() {
        untrusted.push(
            "no temperature of the scene lies inside the measured ones (pass --allow-extrapolation to rank on extrapolated ones)"
                .to_string(),
        );
    }
    SceneStanding {
        scene: scene.to_string(),
        mean_friction: mean,
        temps_c: used.iter().map(|p| p.temp_c).collect(),
        extrapolated_temps_c: points
            .iter()
            .filter(|p| p.extrapolated && p.error.is_none())
            .map(|p| p.temp_c)
            .collect(),
        failed_temps_c: failed.iter().map(|p| p.temp_c).collect(),
        untrusted,
        band: None,
        tied_with: Vec::new(),
    }
}

/// The outcome of one compound.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct CompoundOutcome {
    /// Compound name (sanitised: safe as a file name).
    pub compound: String,
    /// Fit file written or reused.
    pub fit_path: Option<PathBuf>,
    /// `reused`, `fitted` or `replaced`.
    pub fit_action: Option<String>,
    /// Standing per scene (mean F/N, temperatures used, trust).
    pub standings: Vec<SceneStanding>,
    /// Friction per scene and temperature.
    pub friction: Vec<(String, Vec<FrictionPoint>)>,
    /// Why the fit is not trusted (quality figures out of bounds); empty when it is.
    pub untrusted: Vec<String>,
    /// Warnings (extrapolated temperatures, failed temperatures, contact validity, data flags).
    pub warnings: Vec<String>,
    /// The error, if the compound failed.
    pub error: Option<String>,
    /// Wall time for this compound in seconds.
    pub seconds: f64,
}

impl CompoundOutcome {
    /// The standing in `scene`, if the compound got that far.
    pub fn standing(&self, scene: &str) -> Option<&SceneStanding> {
        self.standings.iter().find(|s| s.scene == scene)
    }

    /// Finished, but not trusted in some scene (or its fit is not).
    pub fn is_untrusted(&self) -> bool {
        self.error.is_none()
            && (!self.untrusted.is_empty() || self.standings.iter().any(|s| !s.trusted()))
    }
}

/// How the main job ended, for the exit code (see `viscoroll run --help`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RunStatus {
    /// Every compound finished and is trusted in every scene (exit 0).
    AllGood,
    /// Some compound failed, or there was nothing to run (exit 1).
    Failures,
    /// Every compound finished, but some results are not trusted (exit 3).
    Untrusted,
}

/// The outcome of the main job.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct RunSummary {
    /// One per compound, in discovery order.
    pub compounds: Vec<CompoundOutcome>,
    /// Notes on skipped entries, renamed compounds, reports of compounds no longer in the folder.
    pub notes: Vec<String>,
    /// Extrapolated temperatures were averaged into the ranking.
    pub allow_extrapolation: bool,
    /// `reports/ranking.csv`.
    pub ranking_csv: PathBuf,
    /// `reports/index.html`.
    pub index_html: PathBuf,
    /// For each scene, each pair of ranked compounds: how sure their order is (empty with
    /// `--no-bands`).
    pub comparisons: Vec<PairComparison>,
}

/// Two compounds in one scene: the probability that `a` rolls with lower friction than `b`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PairComparison {
    /// Scene name.
    pub scene: String,
    /// First compound.
    pub a: String,
    /// Second compound.
    pub b: String,
    /// P(F/N of `a` < F/N of `b`) over the propagated scatter.
    pub prob_a_lower: f64,
    /// The order is not significant (neither probability reaches the significance level).
    pub tied: bool,
}

impl RunSummary {
    /// Number of failed compounds.
    pub fn failures(&self) -> usize {
        self.compounds.iter().filter(|c| c.error.is_some()).count()
    }

    /// Number of finished compounds with untrusted results.
    pub fn untrusted(&self) -> usize {
        self.compounds.iter().filter(|c| c.is_untrusted()).count()
    }

    /// How the run ended.
    pub fn status(&self) -> RunStatus {
        if self.failures() > 0 || self.compounds.is_empty() {
            RunStatus::Failures
        } else if self.untrusted() > 0 {
            RunStatus::Untrusted
        } else {
            RunStatus::AllGood
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(temp_c: f64, friction: f64, extrapolated: bool, error: Option<&str>) -> FrictionPoint {
        FrictionPoint {
            model: String::new(),
            model_reason: String::new(),
            band: None,
            error_estimate: None,
            temp_c,
            log10_a_t: 0.0,
            friction,
            resistance_n_per_m: friction * 1e3,
            contact_length_mm: 1.0,
            extrapolated,
            error: error.map(str::to_string),
            warnings: vec![],
        }
    }

    #[test]
    fn the_mean_is_over_measured_temperatures_unless_extrapolation_is_allowed() {
        let pts = [
            point(-40.0, 1.0, true, None),
            point(0.0, 2.0, false, None),
            point(20.0, 4.0, false, None),
        ];
        let s = standing("a", &pts, &[], false);
        assert_eq!(s.mean_friction, Some(3.0));
        assert_eq!(s.temps_c, [0.0, 20.0]);
        assert_eq!(s.extrapolated_temps_c, [-40.0]);
        assert!(s.trusted());
        let s = standing("a", &pts, &[], true);
        assert_eq!(s.mean_friction, Some(7.0 / 3.0));
        assert!(s.trusted());
    }

    #[test]
    fn a_failed_point_never_enters_the_mean_and_untrusts_the_scene() {
        let pts = [
            point(0.0, 2.0, false, None),
            point(10.0, f64::NAN, false, Some("no convergence")),
        ];
        let s = standing("a", &pts, &[], false);
        assert_eq!(s.mean_friction, Some(2.0));
        assert_eq!(s.failed_temps_c, [10.0]);
        assert!(!s.trusted());
        assert!(s.untrusted[0].contains("10 °C") && s.untrusted[0].contains("no convergence"));
        // A NaN without an error is a failure too.
        let s = standing("a", &[point(0.0, f64::NAN, false, None)], &[], false);
        assert_eq!(s.mean_friction, None);
        assert!(!s.trusted());
    }

    #[test]
    fn a_flagged_fit_is_not_trusted_and_only_extrapolated_temperatures_say_so() {
        let pts = [point(0.0, 2.0, false, None)];
        let s = standing(
            "a",
            &pts,
            &["prony_rms_log10_storage out of bound".into()],
            false,
        );
        assert_eq!(s.mean_friction, Some(2.0));
        assert!(!s.trusted());
        let s = standing("a", &[point(-40.0, 1.0, true, None)], &[], false);
        assert_eq!(s.mean_friction, None);
        assert!(s.untrusted[0].contains("--allow-extrapolation"));
    }

    #[test]
    fn long_lines_are_capped_at_a_character_boundary() {
        let long = "é".repeat(10_000);
        let c = cap_line(&long);
        assert!(c.len() < MAX_LINE_BYTES + 40, "{}", c.len());
        assert!(c.ends_with("more bytes cut)"));
        assert_eq!(cap_line("short"), "short");
    }
}
