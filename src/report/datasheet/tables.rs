//! The CSV tables of a compound's report folder: `friction.csv` (one row per scene and temperature),
//! `friction_map.csv` (F/N against speed and load) and `friction_map_2d.csv` (the speed × load grid).
//!
//! Input: the friction points and maps of each scene; output: CSV text (crate::report::csv_text),
//! one header row and no comment lines, and each table's sidecar (`compound_meta`:
//! provenance, the fit's settings, its warnings; crate::report::csv_meta).
//! Numbers are printed in their shortest round-trip form (`{:e}`), so a value read back is the value
//! computed.

use crate::report::csv_meta::CsvMeta;
use crate::report::csv_text::csv_text;
use crate::results::{CompoundFit, FrictionMaps, FrictionPoint, SceneSpec};

/// The sidecar of a compound's table `table` (crate::report::csv_meta): the fit's tool, version,
/// inputs and resolved settings (`settings.fit`), why it is not trusted (`flags`) and its
/// warnings (`fit_warnings`, numbered F1, F2, … in order).
pub(crate) fn compound_meta(
    fit: &CompoundFit,
    table: &str,
    description: &str,
    flags: &[String],
    fit_warnings: &[String],
) -> CsvMeta {
    let mut m = CsvMeta::new(table, description).setting("fit", &fit.settings);
    m.tool.clone_from(&fit.provenance.tool);
    m.tool_version.clone_from(&fit.provenance.tool_version);
    m.compound = Some(fit.compound.clone());
    m.inputs.clone_from(&fit.provenance.inputs);
    m.not_trusted = flags.to_vec();
    m.warnings = fit_warnings.to_vec();
    m
}

/// What friction.csv holds (its sidecar's `description`).
pub(crate) const FRICTION_DESCRIPTION: &str =
    "rolling friction F/N of one compound per scene and temperature, with its band and notes";
/// What friction_map.csv holds.
pub(crate) const MAP_DESCRIPTION: &str =
    "F/N against the scene's listed speeds and loads at each map temperature";
/// What friction_map_2d.csv holds; the interpolant's relative tolerance is `settings.tolerance`.
pub(crate) const GRID_DESCRIPTION: &str =
    "F/N and contact length on a speed x load grid at each map temperature (reduced-variable interpolant)";

/// `friction.csv`: scene, temperature, F/N, F* (N/m), contact length, log10 a_T, extrapolated,
/// error, `note` (every flag of the row: failure, extrapolation, contact validity), `model` (the
/// body solved, contact::body::layer), `error_estimate` (the contact solver's relative error
/// estimate of `friction`, at the scene's tolerance; empty when the solve failed) and
/// `friction_p05`, `friction_p50`, `friction_p95` (the 90 % uncertainty band, crate::bands, with
/// the between-specimen term of docs/MATH.md §16; empty with `--no-bands`), `undetermined` (why
/// the point is not determined: never ranked or averaged) and `specimen_frictions` (each
/// replicate specimen's own F/N, space-separated; empty with one). The
/// compound's own flags (`flags`: why its fit is not trusted) are every row's `not_trusted`
/// (`; `-separated) and, when there are any, lead its note with `fit not trusted`. The fit's
/// warnings (`fit_warnings`: the data, the master curve, the bands; the same for every row, and
/// long: 24 lines for EMS-CA) are written once in full, in order, in the sidecar's `warnings`
/// (friction.meta.json, [`compound_meta`]; the datasheet shows them too), and every row's note
/// ends with their codes F1–Fn ([`fit_warning_codes`]), so a reader of one row knows to look there.
pub(crate) fn friction_csv(
    flags: &[String],
    fit_warnings: &[String],
    friction: &[(SceneSpec, Vec<FrictionPoint>)],
) -> String {
    let untrusted = !flags.is_empty();
    let codes = fit_warning_codes(fit_warnings.len());
    let not_trusted = flags.join("; ").replace(['\r', '\n'], " ");
    let rows = friction.iter().flat_map(|(spec, pts)| {
        let (codes, not_trusted) = (codes.clone(), not_trusted.clone());
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
                not_trusted.clone(),
            ]
        })
    });
    csv_text(
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
            "not_trusted",
        ],
        rows,
    )
}

/// The pointer a row's note carries to the sidecar's warnings: `fit warning F1 (see
/// friction.meta.json)`, `fit warnings F1–F4 (see friction.meta.json)`; empty without fit warnings.
pub(crate) fn fit_warning_codes(n: usize) -> String {
    match n {
        0 => String::new(),
        1 => "fit warning F1 (see friction.meta.json)".into(),
        n => format!("fit warnings F1–F{n} (see friction.meta.json)"),
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
pub(crate) fn band_text(v: Option<f64>) -> String {
    v.map_or(String::new(), |v| format!("{v:e}"))
}

/// `friction_map.csv`: F/N against the listed speeds and loads at every map temperature.
pub(crate) fn map_csv(scenes: &[(&SceneSpec, &FrictionMaps)]) -> String {
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
        &["scene", "temp_c", "speed_m_s", "load_n_per_m", "friction"],
        rows,
    )
}

/// `friction_map_2d.csv`: F/N and contact length on the speed × load grid (the interpolant's
/// tolerance is in the sidecar, [`GRID_DESCRIPTION`]).
pub(crate) fn grid_csv(scenes: &[(&SceneSpec, &FrictionMaps)]) -> String {
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

    /// The data rows of a CSV text, read strictly: one header, every row as wide (the csv
    /// crate's default refuses a row of another width), no comment lines.
    fn records(text: &str) -> Vec<csv::StringRecord> {
        assert!(text.starts_with("scene,"), "{text}");
        csv::Reader::from_reader(text.as_bytes())
            .records()
            .map(|r| r.unwrap())
            .collect()
    }

    /// The column `name` of every row.
    fn column(text: &str, name: &str) -> Vec<String> {
        let mut rd = csv::Reader::from_reader(text.as_bytes());
        let c = rd
            .headers()
            .unwrap()
            .iter()
            .position(|h| h == name)
            .unwrap();
        rd.records().map(|r| r.unwrap()[c].to_string()).collect()
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
            &["prony_rms out of bound".into(), "shift rms".into()],
            &[],
            &[(spec.clone(), pts.clone())],
        );
        assert!(column(&text, "not_trusted")
            .iter()
            .all(|n| n == "prony_rms out of bound; shift rms"));
        assert!(!text.contains("fit warning"));
        let rows = records(&text);
        assert_eq!(&rows[0][8], "fit not trusted");
        assert!(rows[1][8].contains("extrapolated") && rows[1][8].contains("0.570"));
        assert!(rows[2][8].contains("failed: no root, bracket [1, 2]"));
        assert_eq!(&rows[2][7], "no root, bracket [1, 2]");

        // Fit warnings: not in the table (the sidecar holds them), a code at the end of every
        // row's note.
        let warnings = [
            "master curve: isotherm at 20 °C thinned from 40000 to 1000 points".to_string(),
            "uncertainty bands not computed: the ensemble failed".to_string(),
        ];
        let text = friction_csv(&[], &warnings, &[(spec, pts)]);
        assert!(!text.contains("thinned") && !text.contains("ensemble failed"));
        assert!(column(&text, "not_trusted").iter().all(String::is_empty));
        let rows = records(&text);
        assert_eq!(&rows[0][8], "fit warnings F1–F2 (see friction.meta.json)");
        assert!(
            rows[1][8].contains("0.570")
                && rows[1][8].ends_with("; fit warnings F1–F2 (see friction.meta.json)")
        );
        assert!(rows[2][8].starts_with("failed: no root"));
        assert_eq!(
            fit_warning_codes(1),
            "fit warning F1 (see friction.meta.json)"
        );
    }
}
