//! Netzsch Proteus ASCII export (DMA 242/303) → [`RawFile`]: header lines `#KEY:value` (among them
//! `#DECIMAL:POINT|COMMA` and `#SEPARATOR:SEMICOLON|TAB|COMMA`), then one `##` line of column headers
//! written `name/unit` (`##Temp./°C;Time/min;Freq./Hz;E'/MPa;E''/MPa;tan d`), then data rows.

use super::error::DmaError;
use super::table::{cell_from_text, Block, Loc, RawFile, Row};
use super::text::{self, Decimal, Delimiter};
use super::units;

/// Whether decoded text looks like a Proteus ASCII export.
pub fn looks_like(text: &str) -> bool {
    let mut hash_key = false;
    for l in text.lines().take(200) {
        if l.starts_with("##") {
            return hash_key;
        }
        if l.starts_with('#') && l.contains(':') {
            hash_key = true;
        }
    }
    false
}

/// Read a Proteus ASCII export.
pub fn read(file: &str, text: &str) -> Result<RawFile, DmaError> {
    let lines: Vec<&str> = text.lines().collect();
    let mut raw = RawFile::default();
    let mut dec: Option<Decimal> = None;
    let mut delim: Option<Delimiter> = None;
    let mut header: Option<usize> = None;
    for (i, l) in lines.iter().enumerate() {
        if l.starts_with("##") {
            header = Some(i);
            break;
        }
        if let Some(rest) = l.strip_prefix('#') {
            if let Some((k, v)) = rest.split_once(':') {
                let (k, v) = (k.trim(), v.trim());
                match k.to_uppercase().as_str() {
                    "DECIMAL" => dec = Some(decimal_of(file, i, v)?),
                    "SEPARATOR" => delim = Some(delimiter_of(file, i, v)?),
                    _ => {}
                }
                if !v.is_empty() {
                    raw.metadata.insert(k.to_string(), v.to_string());
                }
            }
        }
    }
    let Some(h) = header else {
        return Err(DmaError::Structure {
            file: file.into(),
            location: Loc::File.to_string(),
            message: "Proteus export without a `##` column-header line".into(),
        });
    };
    let (sn_delim, sn_dec) = text::sniff(&lines[h..]);
    let delim = delim.unwrap_or(sn_delim);
    let dec = dec.unwrap_or(sn_dec);
    let names = text::split(&lines[h][2..], delim);
    let mut block = Block {
        header_loc: Some(Loc::Line(h + 1)),
        ..Block::default()
    };
    for n in names {
        let (nm, u) = units::split_name_unit(&n);
        block.names.push(nm);
        block.units.push(u);
    }
    for (k, l) in lines.iter().enumerate().skip(h + 1) {
        if l.trim().is_empty() || l.starts_with('#') {
            continue;
        }
        block.rows.push(Row {
            loc: Loc::Line(k + 1),
            cells: text::split(l, delim)
                .iter()
                .map(|c| cell_from_text(c, dec))
                .collect(),
        });
    }
    raw.blocks.push(block);
    raw.mode_hint = raw.metadata.get("MODE").and_then(|mode| mode_hint(mode));
    Ok(raw)
}

/// The modulus kind a `#MODE:` line names (shear, or a tensile geometry), with its evidence.
fn mode_hint(mode: &str) -> Option<(crate::material::ModulusKind, String)> {
    let l = mode.to_lowercase();
    let kind = if l.contains("shear") {
        crate::material::ModulusKind::Shear
    } else if ["tension", "tensile", "bending", "compression", "cantilever"]
        .iter()
        .any(|w| l.contains(w))
    {
        crate::material::ModulusKind::Tensile
    } else {
        return None;
    };
    Some((kind, format!("#MODE:{mode}")))
}

/// The decimal mark a `#DECIMAL:` value names, or the error at line `i` (0-based).
fn decimal_of(file: &str, i: usize, v: &str) -> Result<Decimal, DmaError> {
    match v.to_uppercase().as_str() {
        "POINT" | "." => Ok(Decimal::Point),
        "COMMA" | "," => Ok(Decimal::Comma),
        _ => Err(DmaError::Structure {
            file: file.into(),
            location: Loc::Line(i + 1).to_string(),
            message: format!("#DECIMAL must be POINT or COMMA, found `{v}`"),
        }),
    }
}

/// The delimiter a `#SEPARATOR:` value names, or the error at line `i` (0-based).
fn delimiter_of(file: &str, i: usize, v: &str) -> Result<Delimiter, DmaError> {
    match v.to_uppercase().as_str() {
        "SEMICOLON" | ";" => Ok(Delimiter::Semicolon),
        "TAB" | "\\T" => Ok(Delimiter::Tab),
        "COMMA" | "," => Ok(Delimiter::Comma),
        _ => Err(DmaError::Structure {
            file: file.into(),
            location: Loc::Line(i + 1).to_string(),
            message: format!("#SEPARATOR must be SEMICOLON, TAB or COMMA, found `{v}`"),
        }),
    }
}
