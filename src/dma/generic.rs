//! Generic delimited text (comma, semicolon, tab or whitespace; dot or comma decimals): a name row,
//! optionally a unit row under it, or units inside the names; metadata lines above (`key: value`);
//! several tables one after another become several blocks. Text → [`RawFile`].

use super::error::DmaError;
use super::table::{cell_from_text, is_data_row, Block, Loc, RawFile, Row};
use super::text::{self, Decimal, Delimiter};
use super::units;

/// Read a generic table from decoded text.
pub fn read(file: &str, text: &str) -> Result<RawFile, DmaError> {
    let lines: Vec<&str> = text.lines().collect();
    let (delim, dec) = text::sniff(&lines);
    let mut raw = read_with(file, &lines, delim, dec)?;
    raw.metadata.insert("delimiter".into(), delim.name().into());
    raw.metadata.insert(
        "decimal mark".into(),
        match dec {
            Decimal::Point => "point",
            Decimal::Comma => "comma",
        }
        .into(),
    );
    Ok(raw)
}

/// Whether a row of fields is a unit row: no numbers, and most cells are units (bracketed or known).
pub(crate) fn is_unit_row(fields: &[String], dec: Decimal) -> bool {
    let non_empty: Vec<&String> = fields.iter().filter(|f| !f.trim().is_empty()).collect();
    if non_empty.is_empty()
        || non_empty
            .iter()
            .any(|f| text::parse_number(f, dec).is_some())
    {
        return false;
    }
    let unitish = non_empty
        .iter()
        .filter(|f| {
            let t = f.trim();
            (t.starts_with('[') && t.ends_with(']'))
                || (t.starts_with('(') && t.ends_with(')'))
                || units::looks_like_unit(t)
        })
        .count();
    unitish * 2 > non_empty.len()
}

/// Whether the non-data line `k` is a stray line inside a table rather than the start of the next
/// one: the next non-blank line is a data row as wide as the table, and line `k` is not (a header
/// of a next table of that width would be as wide as its data).
fn stray_line(
    fields: &[Vec<String>],
    k: usize,
    data: &dyn Fn(usize) -> bool,
    blank: &dyn Fn(usize) -> bool,
    width: usize,
) -> bool {
    let Some(next) = (k + 1..fields.len()).find(|&j| !blank(j)) else {
        return false;
    };
    let filled = |j: usize| fields[j].iter().filter(|f| !f.trim().is_empty()).count();
    data(next) && fields[next].len() == width && filled(k) != width
}

/// A table's block with its column names from `name_row` and their units from `unit_row` (where it
/// has one for the column) or from the name itself (`E' [MPa]`); no rows yet.
fn header_block(fields: &[Vec<String>], name_row: usize, unit_row: Option<usize>) -> Block {
    let mut names = Vec::new();
    let mut unit_list = Vec::new();
    for (c, name) in fields[name_row].iter().enumerate() {
        let (nm, u_in_name) = units::split_name_unit(name);
        let u_row = unit_row
            .and_then(|r| fields[r].get(c))
            .map(|s| strip_brackets(s))
            .filter(|s| !s.is_empty());
        names.push(nm);
        unit_list.push(u_row.or(u_in_name));
    }
    Block {
        names,
        units: unit_list,
        header_loc: Some(Loc::Line(name_row + 1)),
        ..Block::default()
    }
}

/// Parse lines already known to be delimited by `delim` with decimal mark `dec`.
pub(crate) fn read_with(
    file: &str,
    lines: &[&str],
    delim: Delimiter,
    dec: Decimal,
) -> Result<RawFile, DmaError> {
    let fields: Vec<Vec<String>> = lines.iter().map(|l| text::split(l, delim)).collect();
    let blank_v: Vec<bool> = lines.iter().map(|l| l.trim().is_empty()).collect();
    let data_v: Vec<bool> = (0..lines.len())
        .map(|i| !blank_v[i] && is_data_row(&fields[i], dec))
        .collect();
    let blank = |i: usize| blank_v[i];
    let data = |i: usize| data_v[i];
    let n = lines.len();
    let mut raw = RawFile::default();
    let mut i = 0;
    while let Some(d) = (i..n).find(|&k| data(k)) {
        // Header rows directly above the first data row.
        let h1 = (d > i && !blank(d - 1)).then(|| d - 1);
        let Some(h1) = h1 else {
            return Err(DmaError::Structure {
                file: file.into(),
                location: Loc::Line(d + 1).to_string(),
                message: "a row of numbers with no row of column names above it".into(),
            });
        };
        let (name_row, unit_row) =
            if h1 > i && !blank(h1 - 1) && is_unit_row(&fields[h1], dec) && !data(h1 - 1) {
                (h1 - 1, Some(h1))
            } else {
                (h1, None)
            };
        for l in &lines[i..name_row] {
            metadata_line(l, &mut raw.metadata);
        }
        let mut block = header_block(&fields, name_row, unit_row);
        let mut k = d;
        while k < n {
            if blank(k) {
                k += 1;
                continue;
            }
            if !data(k) {
                if stray_line(&fields, k, &data, &blank, block.names.len()) {
                    let shown: String = lines[k]
                        .chars()
                        .take(40)
                        .flat_map(char::escape_debug)
                        .collect();
                    raw.notes.push(format!(
                        "line {}: not a data row (\"{shown}\"), skipped; the table goes on below it",
                        k + 1
                    ));
                    k += 1;
                    continue;
                }
                break;
            }
            block.rows.push(Row {
                loc: Loc::Line(k + 1),
                cells: fields[k].iter().map(|f| cell_from_text(f, dec)).collect(),
            });
            k += 1;
        }
        raw.blocks.push(block);
        i = k;
        // Lines that neither start a new table nor are data: keep as trailing text.
        let next_data = (i..n).find(|&k| data(k));
        if next_data.is_none() {
            let tail: Vec<&str> = lines[i..]
                .iter()
                .map(|l| l.trim())
                .filter(|l| !l.is_empty())
                .collect();
            if !tail.is_empty() {
                raw.metadata.insert(
                    "trailing text".into(),
                    tail.join(" | ").chars().take(200).collect(),
                );
            }
            break;
        }
    }
    if raw.blocks.is_empty() {
        return Err(DmaError::NoData {
            file: file.into(),
            reason: format!(
                "no row with two or more numbers ({} delimiter, decimal {})",
                delim.name(),
                match dec {
                    Decimal::Point => "point",
                    Decimal::Comma => "comma",
                }
            ),
        });
    }
    Ok(raw)
}

/// `key: value`, `key = value` or `key<TAB>value` → metadata.
pub(crate) fn metadata_line(line: &str, meta: &mut std::collections::BTreeMap<String, String>) {
    let l = line.trim().trim_start_matches('#').trim();
    if l.is_empty() {
        return;
    }
    let split = l
        .split_once('\t')
        .or_else(|| l.split_once(':'))
        .or_else(|| l.split_once('='))
        .or_else(|| l.split_once(';'));
    if let Some((k, v)) = split {
        let k = k.trim().trim_end_matches(':').trim();
        let v = v.trim().trim_matches(|c| c == '\t' || c == ';').trim();
        if !k.is_empty() && !v.is_empty() {
            meta.entry(k.to_string()).or_insert_with(|| v.to_string());
        }
    }
}

/// `[MPa]` → `MPa`, `(Hz)` → `Hz`, `[]` → empty.
pub(crate) fn strip_brackets(s: &str) -> String {
    let t = s.trim();
    let b = t.as_bytes();
    if b.len() >= 2
        && ((b[0] == b'[' && b[b.len() - 1] == b']') || (b[0] == b'(' && b[b.len() - 1] == b')'))
    {
        t[1..t.len() - 1].trim().to_string()
    } else {
        t.to_string()
    }
}
