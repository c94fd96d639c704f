//! A table of shift factors written as text (pyvisco's `*_shift_factors.csv`: a `T,log_aT` name row,
//! a `C, -` unit row) → [`ShiftLaw::Table`]. The reference temperature is the one whose log a_T is 0.

use super::error::DmaError;
use super::table::{Cell, Loc};
use super::units::TempUnit;
use crate::ShiftLaw;

/// Read a shift-factor table: a temperature column (with its unit) and a `log_aT` column.
pub fn read_shift_factors(path: &std::path::Path) -> Result<ShiftLaw, DmaError> {
    let file = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|source| DmaError::Io {
        file: file.clone(),
        source,
    })?;
    shift_factors_from_bytes(&file, &bytes)
}

/// [`read_shift_factors`] on bytes already read.
pub fn shift_factors_from_bytes(file: &str, bytes: &[u8]) -> Result<ShiftLaw, DmaError> {
    let text = super::text::decode(bytes).text;
    let raw = super::generic::read(file, &text)?;
    let block = &raw.blocks[0];
    let loc = block.header_loc.clone().unwrap_or(Loc::File).to_string();
    let norm: Vec<String> = block
        .names
        .iter()
        .map(|n| super::columns::normalise(n))
        .collect();
    let find = |cands: &[&str]| norm.iter().position(|n| cands.contains(&n.as_str()));
    let missing = |q: &'static str, looked: &'static str| DmaError::MissingColumn {
        file: file.into(),
        location: loc.clone(),
        quantity: q,
        looked_for: looked,
        columns: block.names.join(", "),
    };
    let it = find(&["t", "temp", "temp.", "temperature"])
        .ok_or_else(|| missing("temperature", "T, Temp, Temperature"))?;
    let ia = find(&[
        "log at",
        "log a t",
        "log10 at",
        "log10 a t",
        "log(at)",
        "shift",
        "log shift",
    ])
    .ok_or_else(|| missing("log a_T", "log_aT, log10_aT, Shift"))?;
    let unit = block.units.get(it).cloned().flatten();
    let tu = match unit.as_deref() {
        Some(u) => TempUnit::parse(u).ok_or_else(|| DmaError::UnknownUnit {
            file: file.into(),
            location: loc.clone(),
            column: block.names[it].clone(),
            quantity: "temperature",
            unit: u.into(),
        })?,
        None => {
            return Err(DmaError::MissingUnit {
                file: file.into(),
                location: loc.clone(),
                column: block.names[it].clone(),
                quantity: "temperature",
                flag: "a unit row (°C or K)",
            })
        }
    };
    let mut points = Vec::new();
    for row in &block.rows {
        let get = |i: usize| match row.cells.get(i) {
            Some(Cell::Num(v)) if v.is_finite() => Ok(*v),
            other => Err(DmaError::BadNumber {
                file: file.into(),
                location: row.loc.to_string(),
                column: block.names[i].clone(),
                value: format!("{other:?}"),
            }),
        };
        points.push((tu.to_celsius(get(it)?), get(ia)?));
    }
    points.sort_by(|a, b| a.0.total_cmp(&b.0));
    let t_ref_c = points
        .iter()
        .find(|p| p.1 == 0.0)
        .map(|p| p.0)
        .ok_or_else(|| DmaError::Structure {
            file: file.into(),
            location: loc.clone(),
            message: "no row with log a_T = 0, so the reference temperature is unknown".into(),
        })?;
    Ok(ShiftLaw::Table { t_ref_c, points })
}
