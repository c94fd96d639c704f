//! The outcome of the main job: one [`CompoundOutcome`] per compound, its standing in each scene
//! ([`SceneStanding`], the ranking's rule) and the [`RunSummary`] that `viscoroll run --json` prints.
//!
//! Input: what the pipeline found per compound; output: plain serde data read by the ranking, the
//! index page and the CLI.
//!
//! Ranking rule ([`standing`]): a compound's figure in a scene is the mean F/N over the scene's
//! temperatures that computed, are determined (`FrictionPoint::determine`) and lie inside its
//! measured temperatures (with `allow_extrapolation`, the extrapolated ones too, listed); with
//! other compounds ranked, over the temperatures they all share (crate::pipeline::trust). Its
//! verdict has three levels ([`TrustLevel`]): *not trusted* (listed apart with its reasons) when a
//! quality figure of its fit is out of bounds, a temperature of the scene failed or nothing is
//! left to average; else *use with care* (ranked, with its reasons) when a master-curve check
//! flagged something (overlap, Kramers–Kronig, van Gurp–Palmen), a contact solve it averages
//! warned of its validity, a point is not determined, or extrapolated temperatures are averaged
//! in; else *trusted*. A failed or undetermined point never enters a mean.

pub use super::line::cap_line;
#[cfg(test)]
pub use super::line::MAX_LINE_BYTES;
use super::scene::FrictionPoint;
use serde::{Deserialize, Serialize};
use std::path::PathBuf;

/// The trust levels of a compound's result in a scene, worst last (issue 31).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TrustLevel {
    /// Every check passed.
    Trusted,
    /// Ranked, but some check flagged something: the reasons say what.
    UseWithCare,
    /// Not ranked: a quality figure out of its bound, a failed temperature, nothing to average.
    NotTrusted,
}

impl TrustLevel {
    /// The level in words, as every output writes it.
    pub fn words(self) -> &'static str {
        match self {
            TrustLevel::Trusted => "trusted",
            TrustLevel::UseWithCare => "use with care",
            TrustLevel::NotTrusted => "not trusted",
        }
    }
}

/// Whether a point's warning is one of the bands' own notes (crate::bands: widened by eq. 15.8 or
/// 15.9, replicates failed, refused) rather than a validity warning of the contact solve.
pub fn is_band_note(w: &str) -> bool {
    w.starts_with("band widened") || w.starts_with("uncertainty band")
}

/// A compound in one scene: its mean friction and its trust verdict.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SceneStanding {
    /// Scene name.
    pub scene: String,
    /// Mean F/N over `temps_c`; `None` when no temperature counts.
    pub mean_friction: Option<f64>,
    /// The temperatures averaged (°C): with other compounds ranked in the scene, those they all
    /// share (crate::pipeline::trust).
    pub temps_c: Vec<f64>,
    /// The compound's own window (°C) when `temps_c` was narrowed to the temperatures the ranked
    /// compounds share; empty when they are the same.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub own_temps_c: Vec<f64>,
    /// Temperatures outside the measured ones (°C): averaged with `allow_extrapolation`, else left out.
    pub extrapolated_temps_c: Vec<f64>,
    /// Temperatures whose friction could not be computed (°C), never averaged.
    pub failed_temps_c: Vec<f64>,
    /// Temperatures whose friction is not determined (°C, `FrictionPoint::undetermined`), never
    /// averaged or ranked.
    pub undetermined_temps_c: Vec<f64>,
    /// Why the compound is not trusted in this scene (empty: it is ranked).
    pub untrusted: Vec<String>,
    /// Why it is ranked but to be used with care (empty with `untrusted`: trusted).
    pub care: Vec<String>,
    /// Uncertainty band of `mean_friction` (crate::bands; `None` with `--no-bands` or without a
    /// mean).
    pub band: Option<super::scene::FrictionBand>,
    /// The ranked compounds of this scene whose order against this one is not significant (see
    /// [`PairComparison::tied`]); empty with `--no-bands`.
    pub tied_with: Vec<String>,
}

impl SceneStanding {
    /// Ranked (trusted or to be used with care).
    pub fn trusted(&self) -> bool {
        self.level() != TrustLevel::NotTrusted
    }

    /// The verdict's level.
    pub fn level(&self) -> TrustLevel {
        if !self.untrusted.is_empty() || self.mean_friction.is_none() {
            TrustLevel::NotTrusted
        } else if !self.care.is_empty() {
            TrustLevel::UseWithCare
        } else {
            TrustLevel::Trusted
        }
    }

    /// The reasons behind the level (none for trusted).
    pub fn reasons(&self) -> &[String] {
        match self.level() {
            TrustLevel::Trusted => &[],
            TrustLevel::UseWithCare => &self.care,
            TrustLevel::NotTrusted => &self.untrusted,
        }
    }

    /// The verdict in one line: `trusted`, `use with care (…)`, `not trusted (…)`.
    pub fn verdict(&self) -> String {
        let r = self.reasons();
        if r.is_empty() {
            self.level().words().to_string()
        } else {
            format!("{} ({})", self.level().words(), r.join("; "))
        }
    }
}

/// The standing of a compound in `scene` (see the module docs); `fit_untrusted` holds the reasons
/// its fit is not trusted (quality figures out of bounds), `fit_care` those it is to be used with
/// care (master-curve checks flagged: crate::results::CompoundFit::care_reasons).
pub fn standing(
    scene: &str,
    points: &[FrictionPoint],
    fit_untrusted: &[String],
    fit_care: &[String],
    allow_extrapolation: bool,
) -> SceneStanding {
    let failed: Vec<&FrictionPoint> = points
        .iter()
        .filter(|p| p.error.is_some() || !p.friction.is_finite())
        .collect();
    let undetermined: Vec<f64> = points
        .iter()
        .filter(|p| p.error.is_none() && p.friction.is_finite() && p.undetermined.is_some())
        .map(|p| p.temp_c)
        .collect();
    let used: Vec<&FrictionPoint> = points
        .iter()
        .filter(|p| p.counts())
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
            "no temperature of the scene is both determined and inside the measured ones (pass --allow-extrapolation to rank on extrapolated ones)"
                .to_string(),
        );
    }
    SceneStanding {
        scene: scene.to_string(),
        mean_friction: mean,
        temps_c: used.iter().map(|p| p.temp_c).collect(),
        own_temps_c: Vec::new(),
        extrapolated_temps_c: points
            .iter()
            .filter(|p| p.extrapolated && p.error.is_none())
            .map(|p| p.temp_c)
            .collect(),
        failed_temps_c: failed.iter().map(|p| p.temp_c).collect(),
        care: care_reasons(&used, &undetermined, fit_care),
        undetermined_temps_c: undetermined,
        untrusted,
        band: None,
        tied_with: Vec::new(),
    }
}

/// Why a scene's result is to be used with care: the fit's (master-curve checks), validity
/// warnings of the contact solves at the temperatures averaged (not the bands' notes, not the
/// solver's `information:` lines), points not determined (left out), extrapolated temperatures
/// averaged in.
fn care_reasons(used: &[&FrictionPoint], undetermined: &[f64], fit_care: &[String]) -> Vec<String> {
    let mut care: Vec<String> = fit_care.to_vec();
    let temps = |v: &[f64]| {
        v.iter()
            .map(|t| t.to_string())
            .collect::<Vec<_>>()
            .join(" ")
    };
    let mut warned: Vec<&str> = Vec::new();
    let mut at: Vec<f64> = Vec::new();
    for p in used {
        let mut any = false;
        for w in p
            .warnings
            .iter()
            .filter(|w| !is_band_note(w) && !w.starts_with("information:"))
        {
            any = true;
            if !warned.contains(&w.as_str()) {
                warned.push(w);
            }
        }
        if any {
            at.push(p.temp_c);
        }
    }
    if !warned.is_empty() {
        care.push(cap_line(&format!(
            "contact validity at {} °C: {}",
            temps(&at),
            warned.join("; ")
        )));
    }
    if !undetermined.is_empty() {
        care.push(format!(
            "not determined at {} °C (left out of the mean and the ranks)",
            temps(undetermined)
        ));
    }
    let ext: Vec<f64> = used
        .iter()
        .filter(|p| p.extrapolated)
        .map(|p| p.temp_c)
        .collect();
    if !ext.is_empty() {
        care.push(format!(
            "extrapolated temperatures {} °C averaged in",
            temps(&ext)
        ));
    }
    care
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
    /// Replicate specimens its fit pools (1: one specimen; its bands then carry the default
    /// between-specimen prior, crate::bands::between).
    pub specimens: usize,
}

impl CompoundOutcome {
    /// The standing in `scene`, if the compound got that far.
    pub fn standing(&self, scene: &str) -> Option<&SceneStanding> {
        self.standings.iter().find(|s| s.scene == scene)
    }

    /// Finished, but not trusted in some scene (or its fit is not).
    pub(crate) fn is_untrusted(&self) -> bool {
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
            specimens: vec![],
            undetermined: None,
        }
    }

    #[test]
    fn the_mean_is_over_measured_temperatures_unless_extrapolation_is_allowed() {
        let pts = [
            point(-40.0, 1.0, true, None),
            point(0.0, 2.0, false, None),
            point(20.0, 4.0, false, None),
        ];
        let s = standing("a", &pts, &[], &[], false);
        assert_eq!(s.mean_friction, Some(3.0));
        assert_eq!(s.temps_c, [0.0, 20.0]);
        assert_eq!(s.extrapolated_temps_c, [-40.0]);
        assert!(s.trusted());
        let s = standing("a", &pts, &[], &[], true);
        assert_eq!(s.mean_friction, Some(7.0 / 3.0));
        assert!(s.trusted());
    }

    #[test]
    fn a_failed_point_never_enters_the_mean_and_untrusts_the_scene() {
        let pts = [
            point(0.0, 2.0, false, None),
            point(10.0, f64::NAN, false, Some("no convergence")),
        ];
        let s = standing("a", &pts, &[], &[], false);
        assert_eq!(s.mean_friction, Some(2.0));
        assert_eq!(s.failed_temps_c, [10.0]);
        assert!(!s.trusted());
        assert!(s.untrusted[0].contains("10 °C") && s.untrusted[0].contains("no convergence"));
        // A NaN without an error is a failure too.
        let s = standing("a", &[point(0.0, f64::NAN, false, None)], &[], &[], false);
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
            &[],
            false,
        );
        assert_eq!(s.mean_friction, Some(2.0));
        assert!(!s.trusted());
        let s = standing("a", &[point(-40.0, 1.0, true, None)], &[], &[], false);
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
