//! The tables the main job writes are plain CSV (issue 29 item 5): every `*.csv` under `reports/`
//! has one header row and rows of the header's width, with no comment line — read as pandas reads
//! a file by default — and beside it a sidecar `NAME.meta.json` that validates against
//! docs/schemas/csv-meta.schema.json and names its table. friction.csv's fit warnings are in its
//! sidecar, and every row's note points at exactly that many (F1–Fn).

use crate::json_schemas::{schema, validate};
use crate::support::{data_dir, run_main, table, table_meta, temp_dir};
use std::path::{Path, PathBuf};

/// Every file under `dir` whose name ends with `suffix`, sorted.
fn files_ending(dir: &Path, suffix: &str) -> Vec<PathBuf> {
    let mut v = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            v.extend(files_ending(&p, suffix));
        } else if p.to_string_lossy().ends_with(suffix) {
            v.push(p);
        }
    }
    v.sort();
    v
}

/// One CSV table, checked strictly: the first line is the header (no `#` line), every row as
/// wide, and its sidecar valid.
fn check_table(path: &Path) {
    let text = std::fs::read_to_string(path).unwrap();
    assert!(
        !text.lines().any(|l| l.starts_with('#')),
        "{}: a comment line",
        path.display()
    );
    let (header, rows) = table(path);
    assert!(header.len() > 1 && !rows.is_empty(), "{}", path.display());
    assert!(rows.iter().all(|r| r.len() == header.len()));
    // The header is the first line as written (no line before it).
    let first = text.lines().next().unwrap();
    assert_eq!(first.split(',').next(), Some(header[0].as_str()));
    let meta = table_meta(path);
    let mut errors = Vec::new();
    validate(&schema("csv-meta"), &meta, "$", &mut errors);
    assert!(errors.is_empty(), "{}: {errors:#?}", path.display());
    let name = path.file_name().unwrap().to_str().unwrap();
    assert_eq!(meta["table"], name, "{}", path.display());
}

#[test]
fn every_table_of_the_main_job_is_one_header_and_rows_beside_a_valid_sidecar() {
    let out = temp_dir("csv-tables");
    let o = run_main(&data_dir(), &out, &["--no-bands"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let reports = out.join("reports");
    let tables = files_ending(&reports, ".csv");
    // ranking.csv and three tables for each of the three shipped compounds
    assert_eq!(tables.len(), 10, "{tables:?}");
    for t in &tables {
        check_table(t);
    }
    // Nothing else carries a sidecar: one per table.
    assert_eq!(files_ending(&reports, ".meta.json").len(), tables.len());
    for compound in ["ems-ca", "dmasuite-tensile", "trios-aresg2-lims"] {
        let friction = reports.join(compound).join("friction.csv");
        let (warnings, notes) = crate::support::fit_warnings_and_notes(&friction);
        let meta = table_meta(&friction);
        assert_eq!(meta["compound"], compound);
        assert!(!meta["inputs"].as_array().unwrap().is_empty());
        // the fit's settings, as its fit file has them
        let fit: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(out.join("fits").join(format!("{compound}.json"))).unwrap(),
        )
        .unwrap();
        assert_eq!(meta["settings"]["fit"], fit["settings"], "{compound}");
        let codes = match warnings.len() {
            0 => None,
            1 => Some("fit warning F1 (see friction.meta.json)".to_string()),
            n => Some(format!("fit warnings F1–F{n} (see friction.meta.json)")),
        };
        for n in &notes {
            match &codes {
                Some(c) => assert!(n.ends_with(c.as_str()), "{compound}: {n:?} ≠ …{c}"),
                None => assert!(!n.contains("fit warning"), "{compound}: {n:?}"),
            }
        }
    }
    let _ = std::fs::remove_dir_all(&out);
}
