//! Pre-check of an `.xlsx` workbook (a zip of XML parts) before `calamine` opens it.
//!
//! calamine 0.31 inflates each part it reads in full and builds a sheet as a dense rows × columns
//! array spanning its cell addresses (`Range::from_sparse`). A zip bomb (a few kB inflating to
//! gigabytes) or one cell far from the others (A1 and XFD1048576: 1.7·10¹⁰ cells) makes it allocate
//! without bound and abort the process. This module reads the zip's parts through a limit on the
//! inflated bytes (`MAX_PART_BYTES` per part, `MAX_TOTAL_BYTES` in all, never trusting the
//! declared sizes), and scans every worksheet's cell and row addresses (`r="…"`, and the
//! `<dimension ref="…">` claim) for the sheet's extent, refusing more than `MAX_CELLS`.
//! Files that are not a readable zip pass through to calamine, which refuses them itself.
//! Format: ECMA-376 Part 1 §18.3.1 (worksheet `dimension`, `row`, `c` elements and their `r`).

use std::io::{Cursor, Read};

/// Largest inflated size of one part (256 MiB: a 1e6-row sheet of five numeric columns is ~60 MB).
pub(crate) const MAX_PART_BYTES: u64 = 256 << 20;
/// Largest inflated size of all parts together.
pub(crate) const MAX_TOTAL_BYTES: u64 = 512 << 20;
/// Largest sheet extent, rows × columns of the bounding box of its cells (calamine keeps 32 bytes a
/// cell: 2·10⁷ cells are 640 MB).
pub(crate) const MAX_CELLS: u64 = 20_000_000;

/// The bounding box of the addresses seen: (min row, max row, min col, max col), 1-based.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Extent {
    rows: (u64, u64),
    cols: (u64, u64),
}

impl Extent {
    fn add(&mut self, row: Option<u64>, col: Option<u64>) {
        if let Some(r) = row {
            self.rows = (self.rows.0.min(r), self.rows.1.max(r));
        }
        if let Some(c) = col {
            self.cols = (self.cols.0.min(c), self.cols.1.max(c));
        }
    }

    fn cells(&self) -> u64 {
        let span = |(lo, hi): (u64, u64)| if hi >= lo { hi - lo + 1 } else { 0 };
        span(self.rows).saturating_mul(span(self.cols))
    }
}

/// An A1-style address (`B12`, a row number `12`, a column `B`): (row, column), 1-based.
fn parse_ref(s: &[u8]) -> (Option<u64>, Option<u64>) {
    let s: Vec<u8> = s.iter().copied().filter(|&b| b != b'$').collect();
    let split = s.iter().position(|b| b.is_ascii_digit()).unwrap_or(s.len());
    let (letters, digits) = s.split_at(split);
    let col = (!letters.is_empty() && letters.iter().all(u8::is_ascii_alphabetic)).then(|| {
        letters.iter().fold(0u64, |acc, b| {
            acc.saturating_mul(26)
                .saturating_add(u64::from(b.to_ascii_uppercase() - b'A' + 1))
        })
    });
    let row = (!digits.is_empty() && digits.iter().all(u8::is_ascii_digit)).then(|| {
        digits.iter().fold(0u64, |acc, b| {
            acc.saturating_mul(10).saturating_add(u64::from(b - b'0'))
        })
    });
    (row, col)
}

/// Every `r="…"` address and `<dimension ref="A:B">` range in a worksheet's XML.
fn sheet_extent(xml: &[u8]) -> Extent {
    let mut e = Extent {
        rows: (u64::MAX, 0),
        cols: (u64::MAX, 0),
    };
    let mut i = 0;
    while i + 3 < xml.len() {
        let key_len = if xml[i..].starts_with(b" r=\"") {
            4
        } else if xml[i..].starts_with(b" ref=\"") && xml[..i].ends_with(b"<dimension") {
            6
        } else {
            i += 1;
            continue;
        };
        let start = i + key_len;
        let end = xml[start..]
            .iter()
            .position(|&b| b == b'"')
            .map_or(xml.len(), |p| start + p);
        for part in xml[start..end].split(|&b| b == b':') {
            let (r, c) = parse_ref(part);
            e.add(r, c);
        }
        i = end;
    }
    e
}

/// The limits of [`check_with`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Limits {
    /// Largest inflated size of one part, bytes.
    pub part_bytes: u64,
    /// Largest inflated size of all parts, bytes.
    pub total_bytes: u64,
    /// Largest sheet extent, cells.
    pub cells: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            part_bytes: MAX_PART_BYTES,
            total_bytes: MAX_TOTAL_BYTES,
            cells: MAX_CELLS,
        }
    }
}

/// Check an `.xlsx` (zip) workbook; `Err(reason)` if calamine would allocate without bound on it.
pub fn check(bytes: &[u8]) -> Result<(), String> {
    check_with(bytes, &Limits::default())
}

/// [`check`] with other limits.
pub(crate) fn check_with(bytes: &[u8], limits: &Limits) -> Result<(), String> {
    let (max_part, max_total, max_cells) = (limits.part_bytes, limits.total_bytes, limits.cells);
    let Ok(mut zip) = zip::ZipArchive::new(Cursor::new(bytes)) else {
        return Ok(()); // not a zip calamine can open either: it says why
    };
    let mut total = 0u64;
    for i in 0..zip.len() {
        let Ok(part) = zip.by_index(i) else {
            continue; // calamine reports unreadable parts
        };
        let name = part.name().to_string();
        let mut data = Vec::new();
        let read = part.take(max_part + 1).read_to_end(&mut data);
        let n = data.len() as u64;
        if n > max_part {
            return Err(format!(
                "part `{name}` inflates to more than {} MiB: refused (a damaged workbook or a zip bomb)",
                max_part >> 20
            ));
        }
        total += n;
        if total > max_total {
            return Err(format!(
                "the workbook inflates to more than {} MiB: refused (a damaged workbook or a zip bomb)",
                max_total >> 20
            ));
        }
        if read.is_err() {
            continue; // calamine reports the damaged part
        }
        if name.starts_with("xl/worksheets/") && name.ends_with(".xml") {
            let e = sheet_extent(&data);
            if e.cells() > max_cells {
                return Err(format!(
                    "sheet `{name}` spans rows {}–{} × columns {}–{} ({} cells, more than {max_cells}): refused (a damaged workbook or a stray far cell)",
                    e.rows.0, e.rows.1, e.cols.0, e.cols.1, e.cells()
                ));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write as _;

    fn zip_of(parts: &[(&str, &[u8])]) -> Vec<u8> {
        let mut w = zip::ZipWriter::new(Cursor::new(Vec::new()));
        let opts = zip::write::SimpleFileOptions::default()
            .compression_method(zip::CompressionMethod::Deflated);
        for (name, data) in parts {
            w.start_file(*name, opts).unwrap();
            w.write_all(data).unwrap();
        }
        w.finish().unwrap().into_inner()
    }

    #[test]
    fn addresses_parse_to_rows_and_columns() {
        assert_eq!(parse_ref(b"A1"), (Some(1), Some(1)));
        assert_eq!(parse_ref(b"XFD1048576"), (Some(1_048_576), Some(16_384)));
        assert_eq!(parse_ref(b"$B$12"), (Some(12), Some(2)));
        assert_eq!(parse_ref(b"7"), (Some(7), None));
    }

    #[test]
    fn a_far_cell_or_a_huge_dimension_is_refused_a_small_sheet_passes() {
        let small = br#"<worksheet><dimension ref="A1:C3"/><sheetData><row r="1"><c r="A1"><v>1</v></c><c r="C3"><v>2</v></c></row></sheetData></worksheet>"#;
        assert!(check(&zip_of(&[("xl/worksheets/sheet1.xml", small)])).is_ok());
        let far = br#"<worksheet><sheetData><row r="1"><c r="A1"><v>1</v></c></row><row r="1048576"><c r="XFD1048576"><v>2</v></c></row></sheetData></worksheet>"#;
        let e = check(&zip_of(&[("xl/worksheets/sheet1.xml", far)])).unwrap_err();
        assert!(e.contains("sheet1.xml") && e.contains("1048576"), "{e}");
        let dim = br#"<worksheet><dimension ref="A1:XFD1048576"/><sheetData/></worksheet>"#;
        assert!(check(&zip_of(&[("xl/worksheets/sheet1.xml", dim)])).is_err());
    }

    #[test]
    fn a_zip_bomb_is_refused_before_it_is_inflated_in_full() {
        // 16 MiB of zeros deflate to about 16 kB (ratio ~1000, as in a real bomb); with a 1 MiB
        // limit per part the guard stops after 1 MiB + 1 byte, whatever the header claims.
        let zeros = vec![0u8; 16 << 20];
        let bomb = zip_of(&[("xl/sharedStrings.xml", &zeros)]);
        assert!(bomb.len() < 64 << 10, "{}", bomb.len());
        let limits = Limits {
            part_bytes: 1 << 20,
            total_bytes: 4 << 20,
            cells: MAX_CELLS,
        };
        let e = check_with(&bomb, &limits).unwrap_err();
        assert!(e.contains("zip bomb"), "{e}");
        // Many parts each under the part limit: the total limit catches them.
        let quarter = vec![0u8; 900 << 10];
        let parts: Vec<(String, &[u8])> = (0..6)
            .map(|i| (format!("xl/p{i}.xml"), &quarter[..]))
            .collect();
        let parts: Vec<(&str, &[u8])> = parts.iter().map(|(n, d)| (n.as_str(), *d)).collect();
        let e = check_with(&zip_of(&parts), &limits).unwrap_err();
        assert!(e.contains("the workbook inflates"), "{e}");
    }

    #[test]
    fn not_a_zip_passes_through() {
        assert!(check(b"PK\x03\x04 but nothing else").is_ok());
    }
}
