//! The run's workbook `reports/viscoroll.xlsx`: one sheet `ranking` (reports/ranking.csv), one
//! `contents` sheet (which sheet holds which compound's table), and per compound six sheets:
//! `NAME friction`, `NAME map`, `NAME map 2d` (its report folder's friction.csv, friction_map.csv,
//! friction_map_2d.csv), `NAME master` (the fit's master curve: reduced frequency, E′, E″ in Pa),
//! `NAME shifts` (log10 a_T per isotherm) and `NAME prony` (τᵢ, Eᵢ, αᵢ = Eᵢ/E₀ and E∞ in a last row).
//!
//! Input: the [`RunSummary`] (its compounds, in order, and the ranking's path) after the CSV tables
//! are written; the tables are read back from those files (so a sheet is its CSV, cell for cell:
//! a field that reads as a finite number is a number, any other a text) and the fit from each
//! compound's fit file. Output: the .xlsx bytes (written with `rust_xlsxwriter`), written
//! atomically beside ranking.csv ([`crate::report::write_file`]). The file's creation time is set
//! to 1980-01-01 (the zip epoch) so that the same run gives the same bytes.
//!
//! Sheet names: Excel allows 31 characters, unique without regard to case. A compound's name
//! (already safe as a file name, crate::pipeline::compounds) is cut to leave room for the longest
//! suffix (` friction`); where two cut names meet, the later one ends in `~2`, `~3`, … The
//! `contents` sheet maps each sheet back to its compound.

use super::error::{write_file, ReportError};
use crate::results::{CompoundFit, RunSummary};
use rust_xlsxwriter::{DocProperties, ExcelDateTime, Workbook, Worksheet, XlsxError};
use std::path::{Path, PathBuf};

/// The workbook's file name, in `reports/`.
pub(crate) const WORKBOOK_NAME: &str = "viscoroll.xlsx";

/// Excel's longest sheet name.
const SHEET_NAME_MAX: usize = 31;

/// The per-compound sheets: (suffix of the sheet name, what it holds).
pub(crate) const COMPOUND_SHEETS: [(&str, &str); 6] = [
    ("friction", "friction.csv"),
    ("map", "friction_map.csv"),
    ("map 2d", "friction_map_2d.csv"),
    ("master", "master curve (fit file)"),
    ("shifts", "shift factors (fit file)"),
    ("prony", "Prony terms (fit file)"),
];

/// Excel's longest text in a cell; a longer field is cut, saying so.
const CELL_TEXT_MAX: usize = 32_767;

/// One sheet: its name, header and rows of text fields.
#[derive(Debug, Clone, PartialEq)]
pub struct Sheet {
    /// Sheet name (≤ 31 characters).
    pub name: String,
    /// Column names.
    pub header: Vec<String>,
    /// Rows of fields as the CSV has them.
    pub rows: Vec<Vec<String>>,
}

/// Why the workbook could not be made.
fn xlsx_error(path: &Path) -> impl FnOnce(XlsxError) -> ReportError + '_ {
    move |e| ReportError::Io {
        path: path.to_path_buf(),
        source: std::io::Error::other(e.to_string()),
    }
}

/// The sheet-name stems of `compounds` (in order): each name cut to leave room for the longest
/// suffix, unique without regard to case (`~2`, `~3`, … where cut names meet).
pub(crate) fn sheet_stems(compounds: &[&str]) -> Vec<String> {
    let room = SHEET_NAME_MAX - 1 - COMPOUND_SHEETS.iter().map(|s| s.0.len()).max().unwrap_or(0);
    let mut used: Vec<String> = vec!["ranking".into(), "contents".into()];
    let mut stems = Vec::with_capacity(compounds.len());
    for name in compounds {
        // characters Excel refuses in a sheet name (a safe compound name has none; kept for any)
        let clean: String = name
            .chars()
            .map(|c| if "[]:*?/\\'".contains(c) { '_' } else { c })
            .collect();
        let mut stem: String = clean.chars().take(room).collect();
        let mut k = 1;
        while used.contains(&stem.to_lowercase()) {
            k += 1;
            let tag = format!("~{k}");
            stem = clean.chars().take(room - tag.len()).collect::<String>() + &tag;
        }
        used.push(stem.to_lowercase());
        stems.push(stem);
    }
    stems
}

/// A CSV table read back as a sheet named `name` (one header row, rows as wide: the csv crate's
/// default).
fn csv_sheet(name: &str, path: &Path) -> Result<Sheet, ReportError> {
    let io = |e: std::io::Error| ReportError::Io {
        path: path.to_path_buf(),
        source: e,
    };
    let bytes =
        crate::fsutil::read::read_regular(path, crate::limits::INPUT_BYTES_MAX).map_err(io)?;
    let mut rd = csv::Reader::from_reader(bytes.as_slice());
    let header = rd
        .headers()
        .map_err(|e| io(std::io::Error::other(e)))?
        .iter()
        .map(str::to_string)
        .collect();
    let mut rows = Vec::new();
    for r in rd.records() {
        let r = r.map_err(|e| io(std::io::Error::other(e)))?;
        rows.push(r.iter().map(str::to_string).collect());
    }
    Ok(Sheet {
        name: name.to_string(),
        header,
        rows,
    })
}

/// A sheet from a header and rows of numbers (`None`: an empty cell).
fn number_sheet(name: String, header: &[&str], rows: Vec<Vec<Option<f64>>>) -> Sheet {
    Sheet {
        name,
        header: header.iter().map(|h| h.to_string()).collect(),
        rows: rows
            .into_iter()
            .map(|r| {
                r.into_iter()
                    .map(|v| v.map_or(String::new(), |v| format!("{v:e}")))
                    .collect()
            })
            .collect(),
    }
}

/// The three sheets of a fit: master curve, shifts, Prony terms.
pub(crate) fn fit_sheets(stem: &str, fit: &CompoundFit) -> [Sheet; 3] {
    let master = number_sheet(
        format!("{stem} master"),
        &["reduced_freq_hz", "storage_pa", "loss_pa"],
        fit.master_curve
            .iter()
            .map(|p| vec![Some(p.reduced_freq_hz), Some(p.storage_pa), Some(p.loss_pa)])
            .collect(),
    );
    let shifts = number_sheet(
        format!("{stem} shifts"),
        &["temp_c", "log10_a_t"],
        fit.tts.as_ref().map_or(Vec::new(), |t| {
            t.shifts
                .iter()
                .map(|&(t, a)| vec![Some(t), Some(a)])
                .collect()
        }),
    );
    let r = &fit.relaxation;
    let e0 = r.instantaneous_modulus();
    let mut terms = r.terms.clone();
    terms.sort_by(|a, b| a.tau_s.total_cmp(&b.tau_s));
    let mut rows: Vec<Vec<Option<f64>>> = terms
        .iter()
        .map(|t| vec![Some(t.tau_s), Some(t.modulus_pa), Some(t.modulus_pa / e0)])
        .collect();
    // E∞ last, with no time: E(t) = E∞ + Σ Eᵢ e^(−t/τᵢ)
    rows.push(vec![
        None,
        Some(r.modulus_inf_pa),
        Some(r.modulus_inf_pa / e0),
    ]);
    let prony = number_sheet(
        format!("{stem} prony"),
        &["tau_s", "modulus_pa", "alpha"],
        rows,
    );
    [master, shifts, prony]
}

/// Write one sheet: the header as text, then each field as a number where it reads as a finite one,
/// else as text (never as a formula).
fn fill(ws: &mut Worksheet, sheet: &Sheet) -> Result<(), XlsxError> {
    ws.set_name(&sheet.name)?;
    for (c, h) in sheet.header.iter().enumerate() {
        ws.write_string(0, c as u16, h)?;
    }
    for (r, row) in sheet.rows.iter().enumerate() {
        let r = r as u32 + 1;
        for (c, f) in row.iter().enumerate() {
            let c = c as u16;
            match f.parse::<f64>() {
                Ok(v) if v.is_finite() && !f.trim().is_empty() => {
                    ws.write_number(r, c, v)?;
                }
                _ if f.is_empty() => {}
                _ if f.chars().count() > CELL_TEXT_MAX => {
                    let n = f.chars().count();
                    let cut: String = f.chars().take(CELL_TEXT_MAX - 60).collect();
                    ws.write_string(
                        r,
                        c,
                        format!(
                            "{cut}… ({} more characters in the CSV)",
                            n - (CELL_TEXT_MAX - 60)
                        ),
                    )?;
                }
                _ => {
                    ws.write_string(r, c, f)?;
                }
            }
        }
    }
    Ok(())
}

/// The workbook of `sheets`, in order, as .xlsx bytes.
pub(crate) fn workbook_bytes(sheets: &[Sheet]) -> Result<Vec<u8>, XlsxError> {
    let mut wb = Workbook::new();
    let epoch = ExcelDateTime::from_ymd(1980, 1, 1)?;
    wb.set_properties(&DocProperties::new().set_creation_datetime(&epoch));
    for s in sheets {
        fill(wb.add_worksheet(), s)?;
    }
    wb.save_to_buffer()
}

/// The sheets of the run `summary` (see the module doc): the ranking, the contents, then per
/// compound that finished its six sheets. Compounds that failed have no tables; they are in the
/// ranking (listed apart, with the error).
pub(crate) fn run_sheets(summary: &RunSummary) -> Result<Vec<Sheet>, ReportError> {
    let reports: PathBuf = summary
        .ranking_csv
        .parent()
        .map_or_else(PathBuf::new, Path::to_path_buf);
    let done: Vec<&crate::results::CompoundOutcome> = summary
        .compounds
        .iter()
        .filter(|o| o.error.is_none())
        .collect();
    let names: Vec<&str> = done.iter().map(|o| o.compound.as_str()).collect();
    let stems = sheet_stems(&names);
    let mut contents = Sheet {
        name: "contents".into(),
        header: vec!["sheet".into(), "compound".into(), "table".into()],
        rows: vec![vec!["ranking".into(), String::new(), "ranking.csv".into()]],
    };
    let mut sheets = vec![csv_sheet("ranking", &summary.ranking_csv)?];
    let mut per: Vec<Sheet> = Vec::new();
    for (o, stem) in done.iter().zip(&stems) {
        let dir = reports.join(&o.compound);
        for (suffix, file) in &COMPOUND_SHEETS[..3] {
            per.push(csv_sheet(&format!("{stem} {suffix}"), &dir.join(file))?);
        }
        if let Some(p) = &o.fit_path {
            let fit = CompoundFit::read(p).map_err(|e| ReportError::Io {
                path: p.clone(),
                source: std::io::Error::other(e.to_string()),
            })?;
            per.extend(fit_sheets(stem, &fit));
        }
        for (suffix, what) in COMPOUND_SHEETS {
            contents.rows.push(vec![
                format!("{stem} {suffix}"),
                o.compound.clone(),
                what.to_string(),
            ]);
        }
    }
    sheets.push(contents);
    sheets.extend(per);
    Ok(sheets)
}

/// Write `reports/viscoroll.xlsx` for the run `summary` (beside its ranking.csv), atomically.
pub fn write_workbook(summary: &RunSummary) -> Result<PathBuf, ReportError> {
    let path = summary.ranking_csv.with_file_name(WORKBOOK_NAME);
    let sheets = run_sheets(summary)?;
    let bytes = workbook_bytes(&sheets).map_err(xlsx_error(&path))?;
    write_file(&path, &bytes)?;
    Ok(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sheet_names_fit_excel_and_are_unique_without_regard_to_case() {
        let long = "a-very-long-compound-name-from-the-lab-2026";
        let names = [long, &long.to_uppercase(), long, "ranking", "short"];
        let stems = sheet_stems(&names);
        let mut all: Vec<String> = vec!["ranking".into(), "contents".into()];
        for s in &stems {
            for (suffix, _) in COMPOUND_SHEETS {
                let n = format!("{s} {suffix}");
                assert!(n.chars().count() <= SHEET_NAME_MAX, "{n}");
                all.push(n.to_lowercase());
            }
        }
        let mut sorted = all.clone();
        sorted.sort();
        sorted.dedup();
        assert_eq!(sorted.len(), all.len(), "{all:?}");
        assert_eq!(stems[1], format!("{}~2", &long.to_uppercase()[..20]));
        assert_eq!(stems[2], format!("{}~3", &long[..20]));
        // `ranking` as a compound: its sheets have suffixes, but its stem must not be `ranking`
        assert_eq!(stems[3], "ranking~2");
        assert_eq!(stems[4], "short");
    }

    #[test]
    fn numbers_stay_numbers_and_texts_stay_texts() {
        let sheet = Sheet {
            name: "t".into(),
            header: vec!["a".into(), "b".into()],
            rows: vec![
                vec!["1.5e-3".into(), "=1+2".into()],
                vec!["NaN".into(), "0 10 20".into()],
                vec![String::new(), "x".repeat(CELL_TEXT_MAX + 5)],
            ],
        };
        let bytes = workbook_bytes(std::slice::from_ref(&sheet)).unwrap();
        // the same sheets, the same bytes (no time of its own in the file)
        std::thread::sleep(std::time::Duration::from_millis(1100));
        assert!(workbook_bytes(&[sheet]).unwrap() == bytes);
        use calamine::{Data, Reader};
        let mut wb: calamine::Xlsx<_> =
            calamine::open_workbook_from_rs(std::io::Cursor::new(bytes)).unwrap();
        let r = wb.worksheet_range("t").unwrap();
        assert_eq!(r.get_value((1, 0)), Some(&Data::Float(1.5e-3)));
        assert_eq!(r.get_value((1, 1)), Some(&Data::String("=1+2".into())));
        assert_eq!(r.get_value((2, 0)), Some(&Data::String("NaN".into())));
        assert_eq!(r.get_value((2, 1)), Some(&Data::String("0 10 20".into())));
        match r.get_value((3, 1)) {
            Some(Data::String(s)) => {
                assert!(s.chars().count() <= CELL_TEXT_MAX && s.ends_with("in the CSV)"))
            }
            other => panic!("{other:?}"),
        }
    }
}
