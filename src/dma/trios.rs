//! TA Instruments TRIOS exports → [`RawFile`]:
//! - "Export to LIMS" text: `[Section]` blocks of `key<TAB>value` lines, then one `[Step]` per step
//!   with `Step name<TAB>Frequency sweep (150.0 °C)`, a `Variables` row, a `Units` row and rows that
//!   begin `Data point`;
//! - plain text/CSV export: header lines, then per step a `[step]` line, the step name, a column-name
//!   row, a unit row and the data rows (tab- or comma-separated).
//!
//! The set temperature of a step is read from its name. Tensile vs shear: TRIOS writes "Storage
//! modulus" for both, so the kind is taken from the other columns of the file (torque or G*-type
//! columns → shear, from a rotational rheometer; E*-type or tension columns → tensile), else `--mode`.

use super::error::DmaError;
use super::generic::metadata_line;
use super::table::{cell_from_text, Block, Loc, RawFile, Row};
use super::text::{self, Decimal, Delimiter};
use super::units::{self, TempUnit};
use crate::material::ModulusKind;

/// Set temperature written in a step name: the last `(… <number> °C)` or `<number> °C`.
pub(crate) fn temperature_in_name(name: &str) -> Option<f64> {
    let chars: Vec<char> = name.chars().collect();
    // Scan for a number followed (optionally after spaces) by a temperature unit.
    let mut best = None;
    let mut k = 0;
    while k < chars.len() {
        if chars[k].is_ascii_digit()
            || (chars[k] == '-' && k + 1 < chars.len() && chars[k + 1].is_ascii_digit())
        {
            let start = k;
            k += 1;
            while k < chars.len()
                && (chars[k].is_ascii_digit()
                    || ((chars[k] == '.' || chars[k] == ',')
                        && chars.get(k + 1).is_some_and(|c| c.is_ascii_digit())))
            {
                k += 1;
            }
            // A decimal comma (`-42,5 °C`, German/French step names) reads as a point.
            let num: String = chars[start..k]
                .iter()
                .map(|&c| if c == ',' { '.' } else { c })
                .collect();
            let mut j = k;
            while j < chars.len() && chars[j] == ' ' {
                j += 1;
            }
            let rest: String = chars[j..].iter().take(3).collect();
            let unit = if rest.starts_with("°C") || rest.starts_with("ºC") || rest.starts_with("℃")
            {
                Some(TempUnit::Celsius)
            } else if rest.starts_with('K') && !rest[1..].starts_with(|c: char| c.is_alphabetic()) {
                Some(TempUnit::Kelvin)
            } else if rest.starts_with('C') && !rest[1..].starts_with(|c: char| c.is_alphabetic()) {
                Some(TempUnit::Celsius)
            } else {
                None
            };
            if let (Some(u), Ok(v)) = (unit, num.parse::<f64>()) {
                best = Some(u.to_celsius(v));
            }
        } else {
            k += 1;
        }
    }
    best
}

/// Tensile or shear from the names of all columns, when they say.
pub(crate) fn mode_from_variables(names: &[String]) -> Option<(ModulusKind, String)> {
    for n in names {
        let l = n.to_lowercase();
        if l.contains("torque") || l.contains("g*") || l.contains("shear") || l.contains("g'") {
            return Some((
                ModulusKind::Shear,
                format!("column `{n}`: a rotational (shear) measurement"),
            ));
        }
    }
    for n in names {
        let l = n.to_lowercase();
        if l.contains("e*") || l.contains("e'") || l.contains("tension") || l.contains("tensile") {
            return Some((
                ModulusKind::Tensile,
                format!("column `{n}`: a tensile measurement"),
            ));
        }
    }
    None
}

/// Read a TRIOS "Export to LIMS" text.
pub(crate) fn read_lims(file: &str, text: &str) -> Result<RawFile, DmaError> {
    let mut raw = RawFile::default();
    let mut section = String::new();
    let mut block: Option<Block> = None;
    let mut all_names = Vec::new();
    for (ln, line) in text.lines().enumerate() {
        let t = line.trim_end_matches(['\r', '\n']);
        if t.trim().is_empty() {
            continue;
        }
        if t.starts_with('[') && t.trim_end().ends_with(']') {
            section = t.trim()[1..t.trim().len() - 1].to_string();
            if let Some(b) = block.take() {
                raw.blocks.push(b);
            }
            if section.eq_ignore_ascii_case("step") {
                block = Some(Block {
                    header_loc: Some(Loc::Line(ln + 1)),
                    ..Block::default()
                });
            }
            continue;
        }
        let fields: Vec<&str> = t.split('\t').collect();
        match block.as_mut() {
            Some(b) => match fields[0].trim() {
                "Step name" => {
                    let name = fields.get(1).map(|s| s.trim()).unwrap_or("").to_string();
                    b.nominal_c = temperature_in_name(&name);
                    b.label = Some(name);
                }
                "Variables" => {
                    b.names = fields[1..].iter().map(|s| s.trim().to_string()).collect();
                    b.header_loc = Some(Loc::Line(ln + 1));
                    all_names.extend(b.names.iter().cloned());
                }
                "Units" => {
                    b.units = fields[1..]
                        .iter()
                        .map(|s| Some(s.trim().to_string()).filter(|s| !s.is_empty()))
                        .collect();
                }
                "Data point" => {
                    if b.names.is_empty() {
                        return Err(DmaError::Structure {
                            file: file.into(),
                            location: Loc::Line(ln + 1).to_string(),
                            message: "`Data point` row before the `Variables` row of its step"
                                .into(),
                        });
                    }
                    b.rows.push(Row {
                        loc: Loc::Line(ln + 1),
                        cells: fields[1..]
                            .iter()
                            .map(|f| cell_from_text(f, Decimal::Point))
                            .collect(),
                    });
                }
                // Inside a step only its keys and `Data point` rows are read; any other line
                // there is named, as super::read names the lines between data rows no reader took.
                _ if !b.names.is_empty() => raw.notes.push(format!(
                    "line {}: not a data row (\"{}\"), skipped; the table goes on below it",
                    ln + 1,
                    t.chars()
                        .take(40)
                        .flat_map(char::escape_debug)
                        .collect::<String>()
                )),
                _ => {}
            },
            None => {
                if let (Some(k), Some(v)) = (fields.first(), fields.get(1)) {
                    let (k, v) = (k.trim(), v.trim());
                    if !k.is_empty() && !v.is_empty() && !section.starts_with("Procedure") {
                        raw.metadata.entry(k.to_string()).or_insert(v.to_string());
                    }
                }
            }
        }
    }
    if let Some(b) = block.take() {
        raw.blocks.push(b);
    }
    if raw.blocks.is_empty() {
        return Err(DmaError::Structure {
            file: file.into(),
            location: Loc::File.to_string(),
            message: "TRIOS LIMS export without any `[Step]` block".into(),
        });
    }
    raw.mode_hint = mode_from_variables(&all_names);
    Ok(raw)
}

/// Read a TRIOS plain text/CSV export (`[step]` blocks).
pub(crate) fn read_text(file: &str, text: &str) -> Result<RawFile, DmaError> {
    let lines: Vec<&str> = text.lines().collect();
    let (delim, dec) = text::sniff(&lines);
    let delim = if delim == Delimiter::Whitespace {
        Delimiter::Tab
    } else {
        delim
    };
    let mut raw = RawFile::default();
    let mut all_names = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let l = lines[i].trim();
        if !l.eq_ignore_ascii_case("[step]") {
            if raw.blocks.is_empty() {
                metadata_line(lines[i], &mut raw.metadata);
            }
            i += 1;
            continue;
        }
        // [step], step name, names, units, data…
        let name_line = i + 1;
        let label = lines
            .get(name_line)
            .map(|s| s.trim().trim_matches('"').to_string());
        let header = i + 2;
        if header + 1 >= lines.len() {
            return Err(DmaError::Structure {
                file: file.into(),
                location: Loc::Line(i + 1).to_string(),
                message: "`[step]` not followed by a step name, a column-name row and a unit row"
                    .into(),
            });
        }
        let names: Vec<String> = text::split(lines[header], delim);
        let unit_fields: Vec<String> = text::split(lines[header + 1], delim);
        let mut block = Block {
            nominal_c: label.as_deref().and_then(temperature_in_name),
            label,
            header_loc: Some(Loc::Line(header + 1)),
            ..Block::default()
        };
        for (c, n) in names.iter().enumerate() {
            let (nm, u_in) = units::split_name_unit(n);
            block.names.push(nm);
            let u = unit_fields
                .get(c)
                .map(|s| super::generic::strip_brackets(s))
                .filter(|s| !s.is_empty());
            block.units.push(u.or(u_in));
        }
        all_names.extend(block.names.iter().cloned());
        let mut k = header + 2;
        while k < lines.len() {
            let t = lines[k].trim();
            if t.is_empty() {
                k += 1;
                continue;
            }
            if t.eq_ignore_ascii_case("[step]") {
                break;
            }
            let fields = text::split(lines[k], delim);
            block.rows.push(Row {
                loc: Loc::Line(k + 1),
                cells: fields.iter().map(|f| cell_from_text(f, dec)).collect(),
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
            message: "TRIOS text export without any `[step]` line".into(),
        });
    }
    raw.mode_hint = mode_from_variables(&all_names);
    raw.metadata.insert("delimiter".into(), delim.name().into());
    Ok(raw)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_temperature_from_step_names() {
        assert_eq!(
            temperature_in_name("Frequency sweep (150.0 °C)"),
            Some(150.0)
        );
        assert_eq!(
            temperature_in_name("Frequency sweep (-40.0 °C)"),
            Some(-40.0)
        );
        // 298.15 − 273.15 in binary floating point: within one rounding of 25.
        assert!(
            (temperature_in_name("Frequency sweep - 2 (298.15 K)").unwrap() - 25.0).abs() < 1e-12
        );
        assert_eq!(temperature_in_name("Frequency sweep 3"), None);
        assert_eq!(temperature_in_name("FS -42,5 °C"), Some(-42.5));
        assert_eq!(temperature_in_name("Sweep 2, 25 °C"), Some(25.0));
    }
}
