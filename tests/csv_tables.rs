//! The tables the main job writes are plain CSV (issue 29 item 5): every `*.csv` under `reports/`
//! has one header row and rows of the header's width, with no comment line — read as pandas reads
//! a file by default — and beside it a sidecar `NAME.meta.json` that validates against
//! docs/schemas/csv-meta.schema.json and names its table. friction.csv's fit warnings are in its
//! sidecar, and every row's note points at exactly that many (F1–Fn).
//!
//! The run's workbook `reports/viscoroll.xlsx`, read back with calamine, holds the same tables cell
//! for cell (a number where the CSV field reads as a finite number, else the text), and each
//! compound's master curve, shifts and Prony terms as its fit file has them, to the bit.

use crate::json_schemas::{schema, validate};
use crate::support::{data_dir, run_main, table, table_meta, temp_dir};
use calamine::{Data, Reader};
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
    check_workbook(&out);
    let _ = std::fs::remove_dir_all(&out);
}

type Book = calamine::Xlsx<std::io::BufReader<std::fs::File>>;

/// The sheet `name` as rows of cells (an empty cell as `Data::Empty`, rows padded to `width`).
fn sheet(wb: &mut Book, name: &str, width: usize) -> Vec<Vec<Data>> {
    let r = wb
        .worksheet_range(name)
        .unwrap_or_else(|e| panic!("sheet {name}: {e}"));
    assert_eq!(r.start(), Some((0, 0)), "{name}");
    (0..r.height())
        .map(|i| {
            (0..width.max(r.width()))
                .map(|j| r.get((i, j)).cloned().unwrap_or(Data::Empty))
                .collect()
        })
        .collect()
}

/// A sheet equals the CSV table at `csv`: the header as texts, each field a number where it reads
/// as a finite one (the same f64), empty where empty, else the same text.
fn same_as_csv(wb: &mut Book, name: &str, csv: &Path) {
    let (header, rows) = table(csv);
    let cells = sheet(wb, name, header.len());
    assert_eq!(cells.len(), rows.len() + 1, "{name}: rows");
    for (j, h) in header.iter().enumerate() {
        assert_eq!(cells[0][j], Data::String(h.clone()), "{name}: header");
    }
    for (i, row) in rows.iter().enumerate() {
        for (j, f) in row.iter().enumerate() {
            let want = match f.parse::<f64>() {
                Ok(v) if v.is_finite() => Data::Float(v),
                _ if f.is_empty() => Data::Empty,
                _ => Data::String(f.clone()),
            };
            assert_eq!(
                cells[i + 1][j],
                want,
                "{name} row {} column {}",
                i + 1,
                header[j]
            );
        }
    }
}

/// The cell as a number (an empty cell: None).
fn number(d: &Data) -> Option<f64> {
    match d {
        Data::Float(v) => Some(*v),
        Data::Int(v) => Some(*v as f64),
        Data::Empty => None,
        other => panic!("not a number: {other:?}"),
    }
}

fn check_workbook(out: &Path) {
    let reports = out.join("reports");
    let mut wb: Book = calamine::open_workbook(reports.join("viscoroll.xlsx")).unwrap();
    same_as_csv(&mut wb, "ranking", &reports.join("ranking.csv"));
    // contents: sheet, compound, table; six sheets per compound
    let contents = sheet(&mut wb, "contents", 3);
    let mut seen = Vec::new();
    for compound in ["ems-ca", "dmasuite-tensile", "trios-aresg2-lims"] {
        let of = |suffix: &str| -> String {
            let row = contents
                .iter()
                .find(|r| {
                    r[1] == Data::String(compound.into())
                        && matches!(&r[0], Data::String(s) if s.ends_with(&format!(" {suffix}")))
                })
                .unwrap_or_else(|| panic!("{compound} {suffix}: not in contents"));
            let Data::String(name) = &row[0] else {
                unreachable!()
            };
            name.clone()
        };
        let dir = reports.join(compound);
        same_as_csv(&mut wb, &of("friction"), &dir.join("friction.csv"));
        same_as_csv(&mut wb, &of("map"), &dir.join("friction_map.csv"));
        same_as_csv(&mut wb, &of("map 2d"), &dir.join("friction_map_2d.csv"));
        let fit = viscoroll::results::CompoundFit::read(
            &out.join("fits").join(format!("{compound}.json")),
        )
        .unwrap();
        let master = sheet(&mut wb, &of("master"), 3);
        assert_eq!(master.len(), fit.master_curve.len() + 1);
        for (row, p) in master[1..].iter().zip(&fit.master_curve) {
            let got: Vec<Option<f64>> = row.iter().map(number).collect();
            assert_eq!(
                got,
                [Some(p.reduced_freq_hz), Some(p.storage_pa), Some(p.loss_pa)]
            );
        }
        let shifts = sheet(&mut wb, &of("shifts"), 2);
        let want = &fit.tts.as_ref().unwrap().shifts;
        assert_eq!(shifts.len(), want.len() + 1);
        for (row, &(t, a)) in shifts[1..].iter().zip(want) {
            assert_eq!((number(&row[0]), number(&row[1])), (Some(t), Some(a)));
        }
        // Prony terms by τ, then E∞ without a τ; α = Eᵢ/E₀ sums with α∞ to 1.
        let prony = sheet(&mut wb, &of("prony"), 3);
        let r = &fit.relaxation;
        assert_eq!(prony.len(), r.terms.len() + 2);
        let mut terms = r.terms.clone();
        terms.sort_by(|a, b| a.tau_s.total_cmp(&b.tau_s));
        for (row, t) in prony[1..].iter().zip(&terms) {
            assert_eq!(
                (number(&row[0]), number(&row[1])),
                (Some(t.tau_s), Some(t.modulus_pa))
            );
        }
        let last = prony.last().unwrap();
        assert_eq!(
            (number(&last[0]), number(&last[1])),
            (None, Some(r.modulus_inf_pa))
        );
        let alpha: f64 = prony[1..].iter().map(|r| number(&r[2]).unwrap()).sum();
        assert!((alpha - 1.0).abs() < 1e-12, "{compound}: Σα = {alpha}");
        for s in ["friction", "map", "map 2d", "master", "shifts", "prony"] {
            seen.push(of(s));
        }
    }
    // every sheet name fits Excel and is unique without regard to case
    let names = wb.sheet_names();
    assert_eq!(names.len(), 2 + seen.len(), "{names:?}");
    let mut lower: Vec<String> = names.iter().map(|n| n.to_lowercase()).collect();
    lower.sort();
    lower.dedup();
    assert_eq!(lower.len(), names.len());
    assert!(names.iter().all(|n| n.chars().count() <= 31));
}
