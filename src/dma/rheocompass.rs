//! Anton Paar RheoCompass CSV export → [`RawFile`]. Despite the name: UTF-16LE with BOM, tab-separated,
//! decimal commas in German/French installations, labels in the UI language. Layout (as documented for
//! the export and described in issue 6): `Project:`/`Test:` lines, then per result a `Result:` line, an
//! `Interval and data points:` line and per interval an `Interval data:` line whose cells after the
//! label are the column names, followed by a line of bracketed units (`[rad/s]`, `[Pa]`, `[°C]`) and
//! the data rows (first cell empty). Labels recognised in English, German and French.
//!
//! The MCR rheometers measure in shear unless a DMA (tension/bending) fixture is used, so plain
//! "Storage Modulus" / "Speichermodul" / "Module de stockage" columns say neither: the kind comes
//! from the measuring system, the test name or the device in the header ([`super::mode_evidence`]),
//! else from `--mode`; never assumed.

use super::error::DmaError;
use super::table::{cell_from_text, Block, Loc, RawFile, Row};
use super::text::{self, Delimiter};
use super::units;

const RESULT: &[&str] = &["result:", "ergebnis:", "résultat:", "resultat:"];
const INTERVAL_DATA: &[&str] = &[
    "interval data:",
    "intervalldaten:",
    "données d'intervalle:",
    "donnees d'intervalle:",
    "données de l'intervalle:",
    "interval données:",
    "intervalle données:",
    "données intervalle:",
];

fn starts_with_any(s: &str, labels: &[&str]) -> Option<usize> {
    let l = s.trim_start().to_lowercase();
    labels.iter().find(|p| l.starts_with(*p)).map(|p| p.len())
}

/// Whether decoded text looks like a RheoCompass export.
pub fn looks_like(text: &str) -> bool {
    text.lines()
        .take(400)
        .any(|l| starts_with_any(l, INTERVAL_DATA).is_some())
}

/// Read a RheoCompass export.
pub fn read(file: &str, text: &str) -> Result<RawFile, DmaError> {
    let lines: Vec<&str> = text.lines().collect();
    // always tab-separated: the decimal mark is sniffed at tabs (intervals of different widths
    // can make the general sniff take the decimal commas for delimiters)
    let dec = text::sniff_decimal(&lines, Delimiter::Tab);
    let mut raw = RawFile::default();
    let mut result_label: Option<String> = None;
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        let fields = text::split(line, Delimiter::Tab);
        if starts_with_any(line, RESULT).is_some() {
            result_label = fields.get(1).cloned().filter(|s| !s.is_empty());
            i += 1;
            continue;
        }
        if starts_with_any(line, INTERVAL_DATA).is_none() {
            if raw.blocks.is_empty() && result_label.is_none() {
                super::generic::metadata_line(line, &mut raw.metadata);
            }
            i += 1;
            continue;
        }
        let names: Vec<String> = fields[1..].to_vec();
        let unit_fields: Vec<String> = lines
            .get(i + 1)
            .map(|l| text::split(l, Delimiter::Tab))
            .unwrap_or_default();
        let mut block = Block {
            nominal_c: result_label
                .as_deref()
                .and_then(super::trios::temperature_in_name),
            label: result_label.clone(),
            header_loc: Some(Loc::Line(i + 1)),
            ..Block::default()
        };
        for (c, n) in names.iter().enumerate() {
            let (nm, u_in) = units::split_name_unit(n);
            block.names.push(nm);
            let u = unit_fields
                .get(c + 1)
                .map(|s| super::generic::strip_brackets(s))
                .filter(|s| !s.is_empty());
            block.units.push(u.or(u_in));
        }
        let mut k = i + 2;
        while k < lines.len() {
            let l = lines[k];
            if l.trim().is_empty() {
                k += 1;
                continue;
            }
            if starts_with_any(l, RESULT).is_some()
                || starts_with_any(l, INTERVAL_DATA).is_some()
                || !l.starts_with('\t')
            {
                break;
            }
            let f = text::split(l, Delimiter::Tab);
            block.rows.push(Row {
                loc: Loc::Line(k + 1),
                cells: f[1..].iter().map(|c| cell_from_text(c, dec)).collect(),
            });
            k += 1;
        }
        raw.blocks.push(block);
        i = k;
    }
    if raw.blocks.is_empty() {
        return Err(DmaError::Structure {
            file: file.into(),
            location: Loc::File.to_string(),
            message: "RheoCompass export without an `Interval data:` line".into(),
        });
    }
    Ok(raw)
}
