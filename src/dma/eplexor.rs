//! Netzsch-Gabo EPLEXOR Excel exports (.xls BIFF and .xlsx, read with `calamine`) → [`RawFile`]:
//! - sheet `Exported Data`: a name row, a unit row, data rows; `---` marks a missing value; no
//!   segment column (isotherms are split where the frequency drops back, [`super::isotherms`]);
//! - sheet `Data header`: instrument settings, kept as metadata (`label:` cells with the value to the
//!   right or below);
//! - sheet `Shiftlist` (master-curve exports): `Ref.Temp.` / `25.0 °C`, `WLF` / `C1 : 13.50` /
//!   `C2 : 141.19 K` written inside strings, then `Temp.` / `Shift` rows of (T in °C, log10 a_T),
//!   read by [`read_eplexor_shiftlist`] as a [`ShiftLaw`].

use super::error::DmaError;
use super::table::{Block, Cell, Loc, RawFile, Row};
#[cfg(test)]
use super::text;
use super::text::Decimal;
#[cfg(test)]
use super::units::TempUnit;
#[cfg(test)]
use crate::material::ShiftLaw;
use calamine::{open_workbook_auto_from_rs, Data, Range, Reader, Sheets};
use std::io::Cursor;

/// Name of the data sheet.
pub(crate) const DATA_SHEET: &str = "Exported Data";
/// Name of the metadata sheet.
pub(crate) const HEADER_SHEET: &str = "Data header";
/// Name of the shift-factor sheet.
pub(crate) const SHIFT_SHEET: &str = "Shiftlist";

type Book = Sheets<Cursor<Vec<u8>>>;

fn open(file: &str, bytes: &[u8]) -> Result<Book, DmaError> {
    // calamine 0.31 panics on some damaged workbooks (e.g. a truncated .xls: a slice index in its
    // compound-file reader); turn that into an error instead of letting user input crash the program.
    if super::detect::is_ole2(bytes) {
        super::xls_guard::check(bytes).map_err(|reason| DmaError::Excel {
            file: file.into(),
            reason,
        })?;
    }
    if super::detect::is_zip(bytes) {
        super::xlsx_guard::check(bytes).map_err(|reason| DmaError::Excel {
            file: file.into(),
            reason,
        })?;
    }
    let owned = bytes.to_vec();
    let opened = std::panic::catch_unwind(move || open_workbook_auto_from_rs(Cursor::new(owned)));
    match opened {
        Ok(Ok(book)) => Ok(book),
        Ok(Err(e)) => Err(DmaError::Excel {
            file: file.into(),
            reason: e.to_string(),
        }),
        Err(_) => Err(DmaError::Excel {
            file: file.into(),
            reason: "the workbook is damaged (the Excel reader failed on it)".into(),
        }),
    }
}

fn sheet(file: &str, book: &mut Book, name: &str) -> Result<Option<Range<Data>>, DmaError> {
    if !book.sheet_names().iter().any(|s| s == name) {
        return Ok(None);
    }
    book.worksheet_range(name)
        .map(Some)
        .map_err(|e| DmaError::Excel {
            file: file.into(),
            reason: format!("sheet `{name}`: {e}"),
        })
}

fn cell_text(d: &Data) -> String {
    match d {
        Data::Empty => String::new(),
        Data::String(s) => s.trim().to_string(),
        Data::Float(f) => f.to_string(),
        Data::Int(i) => i.to_string(),
        Data::Bool(b) => b.to_string(),
        other => other.to_string(),
    }
}

fn to_cell(d: &Data) -> Cell {
    match d {
        Data::Float(f) => Cell::Num(*f),
        Data::Int(i) => Cell::Num(*i as f64),
        Data::Empty => Cell::Missing,
        Data::String(s) => super::table::cell_from_text(s, Decimal::Point),
        Data::Bool(b) => Cell::Text(b.to_string()),
        other => Cell::Text(other.to_string()),
    }
}

/// Read an EPLEXOR workbook's data and metadata.
pub fn read(file: &str, bytes: &[u8]) -> Result<RawFile, DmaError> {
    let mut book = open(file, bytes)?;
    let names = book.sheet_names().to_vec();
    let Some(range) = sheet(file, &mut book, DATA_SHEET)? else {
        return Err(DmaError::Structure {
            file: file.into(),
            location: Loc::File.to_string(),
            message: format!(
                "Excel workbook without a sheet `{DATA_SHEET}` (sheets: {}); not an EPLEXOR export",
                names.join(", ")
            ),
        });
    };
    let mut raw = RawFile::default();
    let (r0, c0) = range.start().unwrap_or((0, 0));
    let rows: Vec<&[Data]> = range.rows().collect();
    if rows.len() < 2 {
        return Err(DmaError::Structure {
            file: file.into(),
            location: format!("sheet `{DATA_SHEET}`"),
            message: "fewer than two rows: a name row and a unit row are expected".into(),
        });
    }
    if c0 != 0 {
        raw.metadata
            .insert("first column".into(), format!("{}", c0 + 1));
    }
    let loc = |r: usize| Loc::Row {
        sheet: DATA_SHEET.into(),
        row: r0 as usize + r + 1,
    };
    let mut block = Block {
        names: rows[0].iter().map(cell_text).collect(),
        units: rows[1]
            .iter()
            .map(|d| Some(cell_text(d)).filter(|s| !s.is_empty()))
            .collect(),
        header_loc: Some(loc(0)),
        ..Block::default()
    };
    for (r, row) in rows.iter().enumerate().skip(2) {
        if row.iter().all(|d| matches!(d, Data::Empty)) {
            continue;
        }
        block.rows.push(Row {
            loc: loc(r),
            cells: row.iter().map(to_cell).collect(),
        });
    }
    raw.blocks.push(block);
    if let Some(h) = sheet(file, &mut book, HEADER_SHEET)? {
        header_metadata(&h, &mut raw.metadata);
    }
    if names.iter().any(|s| s == SHIFT_SHEET) {
        raw.metadata.insert(
            "Shiftlist".into(),
            "present: this export is a master curve (read it with read_eplexor_shiftlist)".into(),
        );
    }
    raw.metadata.insert("sheets".into(), names.join(", "));
    Ok(raw)
}

/// `Label:` cells with their value to the right (same row) or, in a row of labels, below.
fn header_metadata(h: &Range<Data>, meta: &mut std::collections::BTreeMap<String, String>) {
    let rows: Vec<&[Data]> = h.rows().collect();
    for (r, row) in rows.iter().enumerate() {
        let texts: Vec<String> = row.iter().map(cell_text).collect();
        // A row of column labels followed by a `Values:` row: pair them.
        let next: Option<Vec<String>> = rows.get(r + 1).map(|n| n.iter().map(cell_text).collect());
        if let Some(next) = &next {
            let tag = next.first().map(|s| s.trim_end_matches(':')).unwrap_or("");
            if (tag == "Values" || tag == "Limits") && texts.first().is_some_and(|s| s.is_empty()) {
                let mut label = String::new();
                for (c, t) in texts.iter().enumerate().skip(1) {
                    if !t.is_empty() {
                        label = t.trim_end_matches(':').to_string();
                    }
                    let v = next.get(c).cloned().unwrap_or_default();
                    if !label.is_empty() && !v.is_empty() {
                        let key = format!("{label} ({})", tag.to_lowercase());
                        meta.entry(key)
                            .and_modify(|e| {
                                e.push_str(" … ");
                                e.push_str(&v)
                            })
                            .or_insert(v);
                    }
                }
                // The `Limits:` row pairs with the same labels.
                if let Some(n2) = rows.get(r + 2) {
                    let n2: Vec<String> = n2.iter().map(cell_text).collect();
                    if n2.first().map(|s| s.as_str()) == Some("Limits:") {
                        for (c, t) in texts.iter().enumerate().skip(1) {
                            let v = n2.get(c).cloned().unwrap_or_default();
                            if !t.is_empty() && !v.is_empty() {
                                meta.insert(format!("{} (limit)", t.trim_end_matches(':')), v);
                            }
                        }
                    }
                }
                continue;
            }
        }
        for (c, t) in texts.iter().enumerate() {
            let Some(stripped) = t.strip_suffix(':') else {
                // `Material / Remark:  EMS-CA`: label and value in one cell.
                if let Some((k, v)) = t.split_once(':') {
                    if c == 0 && !v.trim().is_empty() && texts.iter().skip(1).all(|s| s.is_empty())
                    {
                        meta.insert(k.trim().to_string(), v.trim().to_string());
                    }
                }
                continue;
            };
            if stripped == "Values" || stripped == "Limits" {
                continue;
            }
            let right = texts.get(c + 1).filter(|s| !s.is_empty());
            let below = next
                .as_ref()
                .and_then(|n| n.get(c))
                .filter(|s| !s.is_empty());
            if let Some(v) = right.filter(|v| !v.ends_with(':')) {
                meta.insert(stripped.trim().to_string(), v.clone());
            } else if let Some(v) = below {
                meta.insert(stripped.trim().to_string(), v.clone());
            }
        }
    }
}

/// Number in a string like `C1 : 13.50`, `C2 : 141.19 K`, `25.0 °C`: the first number after the
/// last `:` (or in the whole string).
#[cfg(test)]
fn number_in(s: &str) -> Option<f64> {
    let tail = s.rsplit(':').next().unwrap_or(s).trim();
    let num: String = tail
        .chars()
        .take_while(|c| c.is_ascii_digit() || matches!(c, '-' | '+' | '.' | 'e' | 'E'))
        .collect();
    text::parse_number(&num, Decimal::Point).filter(|v| v.is_finite())
}

/// Read the `Shiftlist` sheet of an EPLEXOR master-curve export: the table of (T in °C, log10 a_T)
/// as [`ShiftLaw::Table`] (sorted by temperature) and, when the sheet states it, the WLF law the
/// instrument software fitted as [`ShiftLaw::Wlf`].
#[cfg(test)]
pub fn read_eplexor_shiftlist(
    path: &std::path::Path,
) -> Result<(ShiftLaw, Option<ShiftLaw>), DmaError> {
    let file = path.display().to_string();
    let bytes =
        crate::fsutil::read_regular(path, crate::limits::INPUT_BYTES_MAX).map_err(|source| {
            DmaError::Io {
                file: file.clone(),
                source,
            }
        })?;
    shiftlist_from_bytes(&file, &bytes)
}

/// [`read_eplexor_shiftlist`] on bytes already read.
#[cfg(test)]
pub(crate) fn shiftlist_from_bytes(
    file: &str,
    bytes: &[u8],
) -> Result<(ShiftLaw, Option<ShiftLaw>), DmaError> {
    let mut book = open(file, bytes)?;
    let Some(range) = sheet(file, &mut book, SHIFT_SHEET)? else {
        return Err(DmaError::Structure {
            file: file.into(),
            location: Loc::File.to_string(),
            message: format!("no sheet `{SHIFT_SHEET}`: not an EPLEXOR master-curve export"),
        });
    };
    let structure = |r: usize, message: String| DmaError::Structure {
        file: file.into(),
        location: Loc::Row {
            sheet: SHIFT_SHEET.into(),
            row: r + 1,
        }
        .to_string(),
        message,
    };
    let mut t_ref = None;
    let mut c1 = None;
    let mut c2 = None;
    let mut points = Vec::new();
    let mut in_table = false;
    for (r, row) in range.rows().enumerate() {
        let texts: Vec<String> = row.iter().map(cell_text).collect();
        let first = texts.first().map(|s| s.as_str()).unwrap_or("");
        if first.starts_with("Ref") {
            let v = texts.get(1).cloned().unwrap_or_default();
            let t = number_in(&v).ok_or_else(|| {
                structure(r, format!("reference temperature `{v}` has no number"))
            })?;
            let unit = if v.trim_end().ends_with('K') {
                TempUnit::Kelvin
            } else if v.contains('C') {
                TempUnit::Celsius
            } else {
                return Err(structure(
                    r,
                    format!("reference temperature `{v}` has no unit (°C or K)"),
                ));
            };
            t_ref = Some(unit.to_celsius(t));
        } else if first == "WLF" {
            for t in &texts[1..] {
                let key = t.trim_start();
                if key.starts_with("C1") {
                    c1 = number_in(t);
                } else if key.starts_with("C2") {
                    c2 = number_in(t);
                }
            }
        } else if first.starts_with("Temp") {
            in_table = true;
        } else if in_table {
            if let (Some(a), Some(b)) = (row.first(), row.get(1)) {
                match (to_cell(a), to_cell(b)) {
                    (Cell::Num(t), Cell::Num(s)) => points.push((t, s)),
                    (Cell::Missing, Cell::Missing) => {}
                    _ => {
                        return Err(structure(
                            r,
                            format!(
                                "expected (temperature, shift), found `{}`, `{}`",
                                cell_text(a),
                                cell_text(b)
                            ),
                        ))
                    }
                }
            }
        }
    }
    let t_ref_c = t_ref.ok_or_else(|| structure(0, "no `Ref.Temp.` row".into()))?;
    if points.is_empty() {
        return Err(structure(0, "no (Temp., Shift) rows".into()));
    }
    points.sort_by(|a, b| a.0.total_cmp(&b.0));
    let wlf = match (c1, c2) {
        (Some(c1), Some(c2_k)) => Some(ShiftLaw::Wlf { t_ref_c, c1, c2_k }),
        _ => None,
    };
    Ok((ShiftLaw::Table { t_ref_c, points }, wlf))
}
