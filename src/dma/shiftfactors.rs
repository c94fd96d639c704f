//! The one reader of shift-factor tables written as text → [`ShiftLaw::Table`]: a name row with a
//! temperature column and a log a_T column (pyvisco's `*_shift_factors.csv`: `T,log_aT` over a
//! `C, -` unit row; or units in the names: `T_C,log10_aT`, `T [K]`), comma, semicolon, tab or
//! white space. The temperature unit comes from the file, never guessed. The reference temperature
//! is the one whose log a_T is 0, else the one the caller states.

use super::error::DmaError;
use super::table::{Cell, Loc};
use super::units::TempUnit;
use crate::material::ShiftLaw;

/// Read a shift-factor table: a temperature column (with its unit) and a `log_aT` column; the
/// reference temperature is the row with log a_T = 0.
pub fn read_shift_factors(path: &std::path::Path) -> Result<ShiftLaw, DmaError> {
    read_shift_table(path, None)
}

/// [`read_shift_factors`] with a stated reference temperature (°C) for a table that has no row
/// with log a_T = 0 (a row at 0 wins when both exist and must then agree with it).
pub fn read_shift_table(
    path: &std::path::Path,
    t_ref_c: Option<f64>,
) -> Result<ShiftLaw, DmaError> {
    let file = path.display().to_string();
    let bytes =
        crate::fsutil::read_regular(path, crate::limits::INPUT_BYTES_MAX).map_err(|source| {
            DmaError::Io {
                file: file.clone(),
                source,
            }
        })?;
    shift_table_from_bytes(&file, &bytes, t_ref_c)
}

/// [`read_shift_table`] on bytes already read.
pub(crate) fn shift_table_from_bytes(
    file: &str,
    bytes: &[u8],
    t_ref_c: Option<f64>,
) -> Result<ShiftLaw, DmaError> {
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
        "log10at",
        "log a",
        "log10 a",
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
    let structure = |message: String| DmaError::Structure {
        file: file.into(),
        location: loc.clone(),
        message,
    };
    if points.len() < 2 {
        return Err(structure("fewer than 2 rows of (T, log a_T)".into()));
    }
    if let Some(w) = points.windows(2).find(|w| w[0].0 == w[1].0) {
        return Err(structure(format!(
            "the temperature {} °C appears twice",
            w[0].0
        )));
    }
    let zero_row = points.iter().find(|p| p.1 == 0.0).map(|p| p.0);
    let t_ref_c =
        match (zero_row, t_ref_c) {
            (Some(z), _) => z,
            (None, Some(t)) => t,
            (None, None) => return Err(structure(
                "no row with log a_T = 0, so the reference temperature is unknown (state it, e.g. \
                 `viscoroll master --tref`)"
                    .into(),
            )),
        };
    Ok(ShiftLaw::Table { t_ref_c, points })
}
