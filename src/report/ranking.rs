//! The ranking of the main job: per scene, the trusted compounds ordered by mean rolling friction
//! (lowest first), then the compounds listed apart — not trusted, or failed — with their reasons, as
//! `reports/ranking.csv`.
//!
//! Input: the [`CompoundOutcome`]s (each with its [`SceneStanding`] per scene, the rule in
//! crate::results::outcome) and the [`SceneSet`]; output: the order ([`ranked`], [`apart`]), the
//! CSV text ([`ranking_csv`], written with the csv crate, so a compound name with a comma stays one
//! field) and its sidecar `ranking.meta.json` (`ranking_meta`; both written by [`write_ranking`]).

use super::csv_meta::CsvMeta;
use super::csv_text::csv_text;
use crate::results::{CompoundOutcome, SceneSet, SceneStanding};

/// Trusted compounds of `scene` ordered by mean friction (lowest rolling resistance first).
pub fn ranked<'a>(
    outcomes: &'a [CompoundOutcome],
    scene: &str,
) -> Vec<(&'a CompoundOutcome, &'a SceneStanding)> {
    let mut v: Vec<(&CompoundOutcome, &SceneStanding)> = outcomes
        .iter()
        .filter(|o| o.error.is_none())
        .filter_map(|o| o.standing(scene).map(|s| (o, s)))
        .filter(|(_, s)| s.trusted())
        .collect();
    v.sort_by(|a, b| {
        let m = |s: &SceneStanding| s.mean_friction.unwrap_or(f64::INFINITY);
        m(a.1).total_cmp(&m(b.1))
    });
    v
}

/// The compounds of `scene` listed apart: (outcome, its standing if it got one, reasons), the
/// untrusted ones first (by mean friction), then the failed ones.
pub fn apart<'a>(
    outcomes: &'a [CompoundOutcome],
    scene: &str,
) -> Vec<(&'a CompoundOutcome, Option<&'a SceneStanding>, Vec<String>)> {
    let mut untrusted: Vec<_> = outcomes
        .iter()
        .filter(|o| o.error.is_none())
        .filter_map(|o| o.standing(scene).map(|s| (o, s)))
        .filter(|(_, s)| !s.trusted())
        .map(|(o, s)| (o, Some(s), s.untrusted.clone()))
        .collect();
    untrusted.sort_by(|a, b| {
        let m =
            |s: Option<&SceneStanding>| s.and_then(|s| s.mean_friction).unwrap_or(f64::INFINITY);
        m(a.1).total_cmp(&m(b.1))
    });
    let failed = outcomes.iter().filter_map(|o| {
        o.error
            .as_ref()
            .map(|e| (o, None, vec![format!("failed: {e}")]))
    });
    untrusted.into_iter().chain(failed).collect()
}

/// Temperatures as a space-separated list.
pub(crate) fn temps_text(t: &[f64]) -> String {
    t.iter()
        .map(|t| t.to_string())
        .collect::<Vec<_>>()
        .join(" ")
}

/// `reports/ranking.csv`: per scene, the ranked compounds (`rank` 1, 2, …; `trusted` true), then
/// those listed apart (`rank` empty, `trusted` false, reasons in `note`). `temps_c` holds the
/// temperatures averaged; `extrapolated_temps_c` those outside the measured ones (averaged only
/// with `allow_extrapolation`); `failed_temps_c` those that could not be computed;
/// `mean_friction_p05/p50/p95` the 90 % band of the mean (crate::bands; empty with `--no-bands`) and
/// `tied_with` the ranked compounds whose order against this one is not significant (P(A < B)
/// strictly between 0.05 and 0.95, crate::bands::compare; space-separated).
pub fn ranking_csv(
    outcomes: &[CompoundOutcome],
    scenes: &SceneSet,
    allow_extrapolation: bool,
) -> String {
    let mut rows = Vec::new();
    let row = |scene: &str,
               rank: String,
               o: &CompoundOutcome,
               s: Option<&SceneStanding>,
               verdict: &str,
               note: String| {
        let (models, warnings) = bodies_and_warnings(o, scene);
        vec![
            scene.to_string(),
            rank,
            o.compound.clone(),
            s.and_then(|s| s.mean_friction)
                .map_or(String::new(), |f| format!("{f:e}")),
            s.map_or(String::new(), |s| temps_text(&s.temps_c)),
            verdict.to_string(),
            s.map_or(String::new(), |s| temps_text(&s.extrapolated_temps_c)),
            s.map_or(String::new(), |s| temps_text(&s.failed_temps_c)),
            note,
            models,
            warnings,
            band(s, |b| b.p05),
            band(s, |b| b.p50),
            band(s, |b| b.p95),
            s.map_or(String::new(), |s| s.tied_with.join(" ")),
            s.map_or(String::new(), |s| temps_text(&s.own_temps_c)),
            s.map_or(String::new(), |s| temps_text(&s.undetermined_temps_c)),
            o.specimens.to_string(),
            s.filter(|s| s.band.is_some())
                .map_or(String::new(), |s| band_covers(o, s)),
        ]
    };
    for spec in &scenes.scene {
        for (i, (o, s)) in ranked(outcomes, &spec.name).into_iter().enumerate() {
            let mut note: Vec<String> = s.reasons().to_vec();
            if allow_extrapolation && !s.extrapolated_temps_c.is_empty() {
                note.push("mean includes extrapolated temperatures (their bands widened by the shift-law tail term, docs/MATH.md eq. 15.8)".to_string());
            }
            if !s.own_temps_c.is_empty() {
                note.push(format!(
                    "mean over the temperatures every ranked compound shares ({} °C), not its own window ({} °C)",
                    temps_text(&s.temps_c),
                    temps_text(&s.own_temps_c)
                ));
            }
            rows.push(row(
                &spec.name,
                (i + 1).to_string(),
                o,
                Some(s),
                s.level().words(),
                note.join("; "),
            ));
        }
        for (o, s, reasons) in apart(outcomes, &spec.name) {
            rows.push(row(
                &spec.name,
                String::new(),
                o,
                s,
                if o.error.is_some() {
                    "failed"
                } else {
                    crate::results::TrustLevel::NotTrusted.words()
                },
                reasons.join("; "),
            ));
        }
    }
    csv_text(
        &[
            "scene",
            "rank",
            "compound",
            "mean_friction",
            "temps_c",
            "verdict",
            "extrapolated_temps_c",
            "failed_temps_c",
            "note",
            "model",
            "warnings",
            "mean_friction_p05",
            "mean_friction_p50",
            "mean_friction_p95",
            "tied_with",
            "own_temps_c",
            "undetermined_temps_c",
            "specimens",
            "band_covers",
        ],
        rows,
    )
}

/// The sidecar of `reports/ranking.csv` (crate::report::csv_meta): the ranking's rule
/// (`settings.allow_extrapolation`, `settings.scenes`) and how to read the verdict.
pub(crate) fn ranking_meta(scenes: &SceneSet, allow_extrapolation: bool) -> CsvMeta {
    let rule = if allow_extrapolation {
        "over every temperature that computed, extrapolated ones included (--allow-extrapolation)"
    } else {
        "over the measured temperatures only (extrapolated ones left out)"
    };
    let names: Vec<&str> = scenes.scene.iter().map(|s| s.name.as_str()).collect();
    let mut m = CsvMeta::new(
        "ranking.csv",
        &format!("compounds ranked by temperature-averaged rolling friction F/N per scene (lowest first), {rule}"),
    )
    .setting("allow_extrapolation", allow_extrapolation)
    .setting("scenes", names);
    m.notes.push("verdict: trusted, use with care (ranked; reasons in `note`) or not trusted (listed apart with an empty rank; reasons in `note`); means over the temperatures the ranked compounds share (`own_temps_c`: a compound's own window where it is wider)".to_string());
    m
}

/// Write `reports/ranking.csv` at `path` and its sidecar (`ranking_csv`, `ranking_meta`).
pub fn write_ranking(
    path: &std::path::Path,
    outcomes: &[CompoundOutcome],
    scenes: &SceneSet,
    allow_extrapolation: bool,
) -> Result<(), super::ReportError> {
    super::csv_meta::write_table(
        path,
        &ranking_csv(outcomes, scenes, allow_extrapolation),
        &ranking_meta(scenes, allow_extrapolation),
    )
}

/// What a compound's band of `s`'s mean covers (crate::bands::between): one specimen's
/// measurement plus the default between-specimen prior, or the spread between its pooled
/// specimens' own means over the same temperatures.
fn band_covers(o: &CompoundOutcome, s: &SceneStanding) -> String {
    let pts: Vec<&crate::results::FrictionPoint> = o
        .friction
        .iter()
        .filter(|(n, _)| *n == s.scene)
        .flat_map(|(_, p)| p)
        .filter(|p| s.temps_c.contains(&p.temp_c))
        .collect();
    let n = pts.first().map_or(0, |p| p.specimens.len());
    let means: Vec<f64> = (0..n)
        .map(|k| pts.iter().map(|p| p.specimens[k]).sum::<f64>() / pts.len() as f64)
        .collect();
    crate::bands::specimens_note(o.specimens, crate::bands::between_sd_ln(&means))
}

/// A percentile of the band of a standing's mean friction, as printed (empty without one).
fn band(s: Option<&SceneStanding>, pick: fn(&crate::results::FrictionBand) -> f64) -> String {
    s.and_then(|s| s.band.as_ref())
        .map_or(String::new(), |b| format!("{:e}", pick(b)))
}

/// The bodies solved for `o` in `scene` (space-separated, contact::body::layer) and its points'
/// contact warnings (cover indentation, contact length against R, …) as "T °C: warning; …".
fn bodies_and_warnings(o: &CompoundOutcome, scene: &str) -> (String, String) {
    let mut models: Vec<&str> = Vec::new();
    let mut warnings: Vec<String> = Vec::new();
    for p in o
        .friction
        .iter()
        .filter(|(s, _)| s == scene)
        .flat_map(|(_, p)| p)
    {
        if !p.model.is_empty() && !models.contains(&p.model.as_str()) {
            models.push(&p.model);
        }
        for w in &p.warnings {
            warnings.push(format!("{} °C: {w}", p.temp_c));
        }
    }
    // the bands' compound-level warnings (failed refits, bands not computed) hold for every scene
    warnings.extend(
        o.warnings
            .iter()
            .filter(|w| w.starts_with("uncertainty band"))
            .cloned(),
    );
    (
        models.join(" "),
        warnings.join("; ").replace(['\r', '\n'], " "),
    )
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::results::FrictionPoint;

    pub(crate) fn outcome(
        name: &str,
        scene: &str,
        frictions: &[(f64, bool)],
        untrusted: &[&str],
    ) -> CompoundOutcome {
        let pts: Vec<FrictionPoint> = frictions
            .iter()
            .enumerate()
            .map(|(i, &(f, ext))| FrictionPoint {
                model: String::new(),
                model_reason: String::new(),
                band: None,
                error_estimate: None,
                temp_c: 10.0 * i as f64,
                log10_a_t: 0.0,
                friction: f,
                resistance_n_per_m: f,
                contact_length_mm: 1.0,
                extrapolated: ext,
                error: (!f.is_finite()).then(|| "solver stopped".to_string()),
                warnings: vec![],
                specimens: vec![],
                undetermined: None,
            })
            .collect();
        let untrusted: Vec<String> = untrusted.iter().map(|s| s.to_string()).collect();
        CompoundOutcome {
            compound: name.to_string(),
            fit_path: None,
            fit_action: None,
            standings: vec![crate::results::standing(
                scene,
                &pts,
                &untrusted,
                &[],
                false,
            )],
            friction: vec![(scene.to_string(), pts)],
            untrusted,
            warnings: vec![],
            error: None,
            seconds: 0.0,
            specimens: 1,
        }
    }

    /// The rows, read strictly (one header, rows as wide, no comment lines).
    fn rows(text: &str) -> Vec<csv::StringRecord> {
        assert!(text.starts_with("scene,rank,"), "{text}");
        csv::Reader::from_reader(text.as_bytes())
            .records()
            .map(|r| r.unwrap())
            .collect()
    }

    #[test]
    fn a_compound_name_with_a_comma_stays_one_field() {
        let scenes = SceneSet::shipped();
        let s = &scenes.scene[0].name;
        let outcomes = [
            outcome("b, the second", s, &[(2e-3, false)], &[]),
            outcome("a", s, &[(1e-3, false)], &[]),
        ];
        let r = rows(&ranking_csv(&outcomes, &scenes, false));
        assert_eq!(r.len(), 2);
        assert_eq!(&r[0][2], "a");
        assert_eq!(&r[1][2], "b, the second");
        assert_eq!(&r[1][1], "2");
        assert_eq!(r[1][3].parse::<f64>().unwrap(), 2e-3);
    }

    #[test]
    fn untrusted_and_failed_compounds_are_listed_apart_never_ranked() {
        let scenes = SceneSet::shipped();
        let s = &scenes.scene[0].name;
        let mut failed = outcome("broken", s, &[], &[]);
        failed.error = Some("ingest: no data".into());
        failed.standings.clear();
        let outcomes = [
            // the lowest friction, but its fit is flagged: never ranked first
            outcome(
                "flagged",
                s,
                &[(1e-6, false)],
                &["prony_rms_log10_storage out of its bound"],
            ),
            outcome("nan-point", s, &[(1e-5, false), (f64::NAN, false)], &[]),
            outcome("good", s, &[(1e-3, false), (5e-3, true)], &[]),
            failed,
        ];
        let r = rows(&ranking_csv(&outcomes, &scenes, false));
        let scene_rows: Vec<_> = r.iter().filter(|r| &r[0] == s).collect();
        assert_eq!(&scene_rows[0][2], "good");
        assert_eq!(&scene_rows[0][1], "1");
        // measured temperatures only: the extrapolated 5e-3 is left out of the mean, and listed
        assert_eq!(scene_rows[0][3].parse::<f64>().unwrap(), 1e-3);
        assert_eq!(&scene_rows[0][6], "10");
        for (row, name, reason) in [
            (1, "flagged", "prony_rms_log10_storage"),
            (2, "nan-point", "friction failed at 10 °C"),
            (3, "broken", "failed: ingest"),
        ] {
            assert_eq!(&scene_rows[row][2], name);
            assert_eq!(&scene_rows[row][1], "");
            assert_eq!(
                &scene_rows[row][5],
                if name == "broken" {
                    "failed"
                } else {
                    "not trusted"
                }
            );
            assert!(scene_rows[row][8].contains(reason), "{:?}", scene_rows[row]);
        }
        // the NaN point is never averaged: the mean is the finite point's
        assert_eq!(scene_rows[2][3].parse::<f64>().unwrap(), 1e-5);
        // with extrapolation allowed, the extrapolated temperature enters the mean, marked
        let mut good = outcomes[2].clone();
        good.standings = vec![crate::results::standing(
            s,
            &good.friction[0].1,
            &[],
            &[],
            true,
        )];
        let r = rows(&ranking_csv(&[good], &scenes, true));
        assert_eq!(r[0][3].parse::<f64>().unwrap(), 3e-3);
        assert!(r[0][8].contains("extrapolated"));
    }
}
