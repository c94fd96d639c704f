//! The ranking of the main job: compounds ordered by temperature-averaged rolling friction per scene
//! (lowest first), as `reports/ranking.csv`.
//!
//! Input: the [`CompoundOutcome`]s and the [`SceneSet`]; output: the order ([`ranked`]) and the CSV
//! text ([`ranking_csv`], written with the csv crate, so a compound name with a comma stays one field).

use super::csv_text::csv_text;
use crate::results::{CompoundOutcome, SceneSet};

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

/// `reports/ranking.csv`: scene, rank, compound, mean F/N, the temperatures averaged.
pub fn ranking_csv(outcomes: &[CompoundOutcome], scenes: &SceneSet) -> String {
    let mut rows = Vec::new();
    for spec in &scenes.scene {
        let temps: Vec<String> = spec.temps_c.iter().map(|t| t.to_string()).collect();
        for (i, (o, f)) in ranked(outcomes, &spec.name).iter().enumerate() {
            // The bodies solved and the points' warnings (cover validity, …) of this scene.
            let pts = o
                .friction
                .iter()
                .filter(|(s, _)| *s == spec.name)
                .flat_map(|(_, p)| p);
            let mut models: Vec<&str> = Vec::new();
            let mut warnings: Vec<String> = Vec::new();
            for p in pts {
                if !p.model.is_empty() && !models.contains(&p.model.as_str()) {
                    models.push(&p.model);
                }
                for w in &p.warnings {
                    let w = format!("{} °C: {w}", p.temp_c);
                    warnings.push(w);
                }
            }
            rows.push(vec![
                spec.name.clone(),
                (i + 1).to_string(),
                o.compound.clone(),
                format!("{f:e}"),
                temps.join(" "),
                models.join(" "),
                warnings.join("; ").replace(['\r', '\n'], " "),
            ]);
        }
    }
    csv_text(
        &[format!(
            "viscoroll {}: compounds ranked by temperature-averaged rolling friction F/N per scene (lowest first)",
            env!("CARGO_PKG_VERSION")
        )],
        &[
            "scene",
            "rank",
            "compound",
            "mean_friction",
            "temps_c",
            "model",
            "warnings",
        ],
        rows,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    pub(crate) fn outcome(name: &str, scene: &str, mean: f64) -> CompoundOutcome {
        CompoundOutcome {
            compound: name.to_string(),
            fit_path: None,
            fit_action: None,
            mean_friction: vec![(scene.to_string(), mean)],
            friction: vec![],
            warnings: vec![],
            error: None,
            seconds: 0.0,
        }
    }

    #[test]
    fn a_compound_name_with_a_comma_stays_one_field() {
        let scenes = SceneSet::shipped();
        let s = &scenes.scene[0].name;
        let outcomes = [outcome("b, the second", s, 2e-3), outcome("a", s, 1e-3)];
        let text = ranking_csv(&outcomes, &scenes);
        let body: String = text
            .lines()
            .filter(|l| !l.starts_with('#'))
            .map(|l| format!("{l}\n"))
            .collect();
        let mut rd = csv::Reader::from_reader(body.as_bytes());
        let rows: Vec<csv::StringRecord> = rd.records().map(|r| r.unwrap()).collect();
        assert_eq!(rows.len(), 2);
        assert_eq!(&rows[0][2], "a");
        assert_eq!(&rows[1][2], "b, the second");
        assert_eq!(&rows[1][1], "2");
        assert_eq!(rows[1][3].parse::<f64>().unwrap(), 2e-3);
    }
}
