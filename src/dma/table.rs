//! The readers' common intermediate: what each format reader hands on before columns are given a
//! meaning ([`super::columns`]). A file is a list of [`Block`]s (one per step, interval or table), each
//! with column names, units and rows of raw cells that remember where they came from.

use std::collections::BTreeMap;

/// Where a cell or row is: a text line or a sheet row (both 1-based).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Loc {
    /// Line in a text file.
    Line(usize),
    /// Row in a worksheet.
    Row {
        /// Sheet name.
        sheet: String,
        /// Row, 1-based as Excel shows it.
        row: usize,
    },
    /// The file as a whole.
    File,
}

impl std::fmt::Display for Loc {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Loc::Line(n) => write!(f, "line {n}"),
            Loc::Row { sheet, row } => write!(f, "sheet `{sheet}` row {row}"),
            Loc::File => write!(f, "whole file"),
        }
    }
}

impl Loc {
    /// The line or row number (0 for the whole file).
    pub fn number(&self) -> usize {
        match self {
            Loc::Line(n) | Loc::Row { row: n, .. } => *n,
            Loc::File => 0,
        }
    }
}

/// One cell as read.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// A number (already in the file's decimal convention).
    Num(f64),
    /// Text that did not read as a number (kept for the message).
    Text(String),
    /// Missing: empty, `---`.
    Missing,
}

/// One data row.
#[derive(Debug, Clone)]
pub struct Row {
    /// Where it is.
    pub loc: Loc,
    /// Cells, aligned with [`Block::names`] (shorter rows are missing the tail).
    pub cells: Vec<Cell>,
}

/// One table: a header and its rows.
#[derive(Debug, Clone, Default)]
pub struct Block {
    /// Column names as written (unit split off if it was inside the name).
    pub names: Vec<String>,
    /// Units as written, per column (`None`: no unit given).
    pub units: Vec<Option<String>>,
    /// Where the header is (for messages).
    pub header_loc: Option<Loc>,
    /// Data rows.
    pub rows: Vec<Row>,
    /// Set (nominal) temperature of the whole block in °C, when the format states one.
    pub nominal_c: Option<f64>,
    /// Step, interval or result name, if any.
    pub label: Option<String>,
}

/// What a format reader returns.
#[derive(Debug, Clone, Default)]
pub struct RawFile {
    /// Instrument metadata (key → value).
    pub metadata: BTreeMap<String, String>,
    /// The tables.
    pub blocks: Vec<Block>,
    /// Tensile or shear when the format (not a column name) says so: e.g. a rotational rheometer.
    pub mode_hint: Option<(crate::material::ModulusKind, String)>,
    /// What the reader skipped or repaired, each naming its line (they reach the warnings).
    pub notes: Vec<String>,
}

/// Turn a text field into a cell.
pub(crate) fn cell_from_text(s: &str, dec: super::text::Decimal) -> Cell {
    if let Some(v) = super::text::parse_number(s, dec) {
        Cell::Num(v)
    } else if super::text::is_missing_marker(s) {
        Cell::Missing
    } else {
        Cell::Text(s.trim().to_string())
    }
}

/// Whether a row of text fields is a data row: at least two numbers and no more text than numbers.
pub(crate) fn is_data_row(fields: &[String], dec: super::text::Decimal) -> bool {
    let mut num = 0;
    let mut text = 0;
    for f in fields {
        match cell_from_text(f, dec) {
            Cell::Num(_) => num += 1,
            Cell::Text(_) => text += 1,
            Cell::Missing => {}
        }
    }
    num >= 2 && text <= num
}
