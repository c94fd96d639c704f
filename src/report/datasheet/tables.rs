//! The CSV tables of a compound's report folder: `friction.csv` (one row per scene and temperature),
//! `friction_map.csv` (F/N against speed and load) and `friction_map_2d.csv` (the speed × load grid).
//!
//! Input: the friction points and maps of each scene; output: CSV text (crate::report::csv_text).
//! Numbers are printed in their shortest round-trip form (`{:e}`), so a value read back is the value
//! computed.

use crate::report::csv_text::csv_text;
use crate::results::{FrictionMaps, FrictionPoint, SceneSpec};

/// `friction.csv`: scene, temperature, F/N, F* (N/m), contact length, log10 a_T, extrapolated,
/// error, `note` (every flag of the row: failure, extrapolation, contact validity), `model` (the
/// body solved, contact::body::layer), `error_estimate` (the contact solver's relative error
/// estimate of `friction`, at the scene's tolerance; empty when the solve failed) and
/// `friction_p05`, `friction_p50`, `friction_p95` (the 90 % uncertainty band, crate::bands, with
/// the between-specimen term of docs/MATH.md §16; empty with `--no-bands`), `undetermined` (why
/// the point is not determined: never ranked or averaged) and `specimen_frictions` (each
/// replicate specimen's own F/N, space-separated; empty with one). The
/// compound's own flags (`flags`: why its fit is not trusted) come first as `#` lines and, when there
/// are any, lead every row's note with `fit not trusted`. The fit's warnings (`fit_warnings`: the
/// data, the master curve, the bands; the same for every row) are written once in full as
/// `# fit warning Fk: …` lines, and every row's note ends with their codes ([`fit_warning_codes`]),
/// so a reader of one row knows to look up.
pub fn friction_csv(
    prov: &str,
    flags: &[String],
    fit_warnings: &[String],
    friction: &[(SceneSpec, Vec<FrictionPoint>)],
) -> String {
    let untrusted = !flags.is_empty();
    let codes = fit_warning_codes(fit_warnings.len());
    let rows = friction.iter().flat_map(|(spec, pts)| {
        let codes = codes.clone();
        pts.iter().map(move |p| {
            vec![
                spec.name.clone(),
                p.temp_c.to_string(),
                format!("{:e}", p.friction),
                format!("{:e}", p.resistance_n_per_m),
                format!("{:e}", p.contact_length_mm),
                format!("{:.6}", p.log10_a_t),
                p.extrapolated.to_string(),
                p.error.as_deref().unwrap_or("").replace(['\r', '\n'], " "),
                row_note(untrusted, p.note(), &codes),
                p.model.clone(),
                band_text(p.error_estimate),
                band_text(p.band.map(|b| b.p05)),
                band_text(p.band.map(|b| b.p50)),
                band_text(p.band.map(|b| b.p95)),
                p.undetermined.clone().unwrap_or_default(),
                p.specimens
                    .iter()
                    .map(|f| format!("{f:e}"))
                    .collect::<Vec<_>>()
                    .join(" "),
            ]
        })
    });
    let mut comments = vec![prov.to_string()];
    comments.extend(flags.iter().map(|f| format!("not trusted: {f}")));
    comments.extend(
        fit_warnings
            .iter()
            .enumerate()
            .map(|(k, w)| format!("fit warning F{}: {}", k + 1, w.replace(['\r', '\n'], " "))),
    );
    csv_text(
        &comments,
        &[
            "scene",
            "temp_c",
            "friction",
            "resistance_n_per_m",
            "contact_length_mm",
            "log10_a_t",
            "extrapolated",
            "error",
            "note",
            "model",
            "error_estimate",
            "friction_p05",
            "friction_p50",
            "friction_p95",
            "undetermined",
            "specimen_frictions",
        ],
        rows,
    )
}

/// The pointer a row's note carries to the `# fit warning` lines: `fit warning F1 (header)`,
/// `fit warnings F1–F4 (header)`; empty without fit warnings.
pub fn fit_warning_codes(n: usize) -> String {
    match n {
        0 => String::new(),
        1 => "fit warning F1 (header)".into(),
        n => format!("fit warnings F1–F{n} (header)"),
    }
}

/// A row's note: `fit not trusted` first when it is not, the point's own flags, the fit warnings'
/// codes last.
fn row_note(untrusted: bool, point: String, codes: &str) -> String {
    let parts = [
        if untrusted { "fit not trusted" } else { "" },
        point.as_str(),
        codes,
    ];
    parts
        .iter()
        .filter(|p| !p.is_empty())
        .copied()
        .collect::<Vec<_>>()
        .join("; ")
}

/// A band percentile as printed (empty without bands).
pub fn band_text(v: Option<f64>) -> String {
    v.map_or(String::new(), |v| format!("{v:e}"))
}

/// `friction_map.csv`: F/N against the listed speeds and loads at every map temperature.
pub fn map_csv(prov: &str, scenes: &[(&SceneSpec, &FrictionMaps)]) -> String {
    let rows = scenes.iter().flat_map(|(spec, map)| {
        map.points.iter().map(move |p| {
            vec![
                spec.name.clone(),
                p.temp_c.to_string(),
                p.speed_m_s.to_string(),
                p.load_n_per_m.to_string(),
                format!("{:e}", p.friction),
            ]
        })
    });
    csv_text(
        &[prov.to_string()],
        &["scene", "temp_c", "speed_m_s", "load_n_per_m", "friction"],
        rows,
    )
}

/// `friction_map_2d.csv`: F/N and contact length on the speed × load grid.
pub fn grid_csv(prov: &str, tol: f64, scenes: &[(&SceneSpec, &FrictionMaps)]) -> String {
    let rows = scenes.iter().flat_map(|(spec, map)| {
        map.grid.iter().map(move |p| {
            vec![
                spec.name.clone(),
                p.temp_c.to_string(),
                p.speed_m_s.to_string(),
                p.load_n_per_m.to_string(),
                format!("{:e}", p.friction),
                format!("{:e}", p.contact_length_mm),
            ]
        })
    });
    csv_text(
        &[
            prov.to_string(),
            format!("F/N on a speed × load grid at each map temperature (reduced-variable interpolant, relative tolerance {tol:e})"),
        ],
        &[
            "scene",
            "temp_c",
            "speed_m_s",
            "load_n_per_m",
            "friction",
            "contact_length_mm",
        ],
        rows,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The data rows of a CSV text, `#` lines skipped.
    fn records(text: &str) -> Vec<csv::StringRecord> {
        let body: String = text
            .lines()
            .filter(|l| !l.starts_with('#'))
            .map(|l| format!("{l}\n"))
            .collect();
        csv::Reader::from_reader(body.as_bytes())
            .records()
            .map(|r| r.unwrap())
            .collect()
    }

    #[test]
    fn every_flag_of_a_point_reaches_the_note_column() {
        let spec = crate::results::SceneSet::shipped().scene[0].clone();
        let p = |extrapolated: bool, error: Option<&str>, warnings: Vec<String>| FrictionPoint {
            model: String::new(),
            model_reason: String::new(),
            band: None,
            error_estimate: None,
            temp_c: 20.0,
            log10_a_t: 0.0,
            friction: if error.is_some() { f64::NAN } else { 1e-3 },
            resistance_n_per_m: 10.0,
            contact_length_mm: 1.0,
            extrapolated,
            error: error.map(str::to_string),
            warnings,
            specimens: vec![],
            undetermined: None,
        };
        let pts = vec![
            p(false, None, vec![]),
            p(
                true,
                None,
                vec!["contact length / radius = 0.570, results lose validity".into()],
            ),
            p(false, Some("no root, bracket [1, 2]"), vec![]),
        ];
        let text = friction_csv(
            "prov",
            &["prony_rms out of bound".into()],
            &[],
            &[(spec.clone(), pts.clone())],
        );
        assert!(text.contains("# not trusted: prony_rms out of bound"));
        assert!(!text.contains("fit warning"));
        let rows = records(&text);
        assert_eq!(&rows[0][8], "fit not trusted");
        assert!(rows[1][8].contains("extrapolated") && rows[1][8].contains("0.570"));
        assert!(rows[2][8].contains("failed: no root, bracket [1, 2]"));
        assert_eq!(&rows[2][7], "no root, bracket [1, 2]");

        // Fit warnings: once in full in the header, a code at the end of every row's note.
        let warnings = [
            "master curve: isotherm at 20 °C thinned from 40000 to 1000 points".to_string(),
            "uncertainty bands not computed: the ensemble failed".to_string(),
        ];
        let text = friction_csv("prov", &[], &warnings, &[(spec, pts)]);
        assert!(text.contains("# fit warning F1: master curve: isotherm at 20 °C thinned"));
        assert!(text.contains("# fit warning F2: uncertainty bands not computed"));
        let rows = records(&text);
        assert_eq!(&rows[0][8], "fit warnings F1–F2 (header)");
        assert!(
            rows[1][8].contains("0.570") && rows[1][8].ends_with("; fit warnings F1–F2 (header)")
        );
        assert!(rows[2][8].starts_with("failed: no root"));
        assert_eq!(fit_warning_codes(1), "fit warning F1 (header)");
    }
}
