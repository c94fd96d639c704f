//! RepTate data files (`.osc` frequency sweeps, `.tts` master curves) → [`RawFile`]: a first line of
//! parameters `key=value;key=value;` (`T=40;Mw=225.9;…`), then white-space or tab separated columns,
//! optionally under a row of column names and a row of units.
//!
//! RepTate's documented layout fixes the first three columns as ω (rad/s), G′ and G″ (Pa), so a file
//! without a unit row is read in those units (the metadata says so); a unit row, when present, is
//! read as written. The parameter `T` is the temperature of the sweep (°C, RepTate's convention), the
//! isotherm's nominal temperature; without it, a temperature in the file name (`…_40C_…`) is taken,
//! with the same standing. A `.tts` master curve may carry WLF constants `C1`, `C2` (K) and `Tr` (°C)
//! in its parameters (`wlf_from_parameters`).

use super::error::DmaError;
use super::table::{cell_from_text, Block, Loc, RawFile, Row};
use super::text::{self, Decimal, Delimiter};
use super::units;
#[cfg(test)]
use crate::material::ShiftLaw;
use std::collections::BTreeMap;

/// The parameters of a first line `key=value;key=value;`, or `None` if the line is not of that form.
pub fn parameters(line: &str) -> Option<BTreeMap<String, String>> {
    let mut out = BTreeMap::new();
    for part in line
        .trim()
        .split(';')
        .map(str::trim)
        .filter(|p| !p.is_empty())
    {
        let (k, v) = part.split_once('=')?;
        let k = k.trim();
        if k.is_empty()
            || !k
                .chars()
                .all(|c| c.is_alphanumeric() || c == '_' || c == '-')
        {
            return None;
        }
        out.insert(k.to_string(), v.trim().to_string());
    }
    (!out.is_empty()).then_some(out)
}

/// Whether decoded text looks like a RepTate data file: its first line is `key=value;…`.
pub(crate) fn looks_like(text: &str) -> bool {
    let mut lines = text.lines().filter(|l| !l.trim().is_empty());
    let Some(first) = lines.next() else {
        return false;
    };
    first.contains(';') && parameters(first).is_some()
}

/// A temperature written in a RepTate file name: a part `40C`, `-35C` or `T-35` between `_`, `-`
/// or `.` separators (`PI223k-14_40C_FS_PP10.osc`, `PI_13.5k_T-35.tts`).
pub(crate) fn temperature_in_file_name(path: &str) -> Option<f64> {
    let stem = std::path::Path::new(path).file_stem()?.to_str()?;
    let parts: Vec<&str> = stem.split('_').collect();
    parts.iter().rev().find_map(|p| {
        let p = p.trim();
        let num = p.strip_suffix('C').or_else(|| {
            p.strip_prefix('T')
                .filter(|r| r.starts_with('-') || r.starts_with(|c: char| c.is_ascii_digit()))
        })?;
        let ok = !num.is_empty()
            && num
                .chars()
                .enumerate()
                .all(|(i, c)| c.is_ascii_digit() || c == '.' || (i == 0 && c == '-'));
        if ok {
            num.parse::<f64>().ok()
        } else {
            None
        }
    })
}

/// The WLF law of a `.tts` file's parameters: `C1`, `C2` (K) and `Tr` (°C; else `T`), checked
/// ([`ShiftLaw::validate`]); `Ok(None)` when the file carries no C1 and C2.
#[cfg(test)]
pub(crate) fn wlf_from_parameters(
    file: &str,
    params: &BTreeMap<String, String>,
) -> Result<Option<ShiftLaw>, DmaError> {
    let num = |k: &str| -> Result<Option<f64>, DmaError> {
        match params.get(k) {
            None => Ok(None),
            Some(v) => v
                .trim()
                .parse::<f64>()
                .map(Some)
                .map_err(|_| DmaError::Structure {
                    file: file.into(),
                    location: Loc::Line(1).to_string(),
                    message: format!("parameter {k}={v} is not a number"),
                }),
        }
    };
    let (Some(c1), Some(c2_k)) = (num("C1")?, num("C2")?) else {
        return Ok(None);
    };
    let t_ref_c = match (num("Tr")?, num("T")?) {
        (Some(t), _) | (None, Some(t)) => t,
        (None, None) => {
            return Err(DmaError::Structure {
                file: file.into(),
                location: Loc::Line(1).to_string(),
                message: "WLF constants C1, C2 without a reference temperature Tr (or T)".into(),
            })
        }
    };
    let law = ShiftLaw::Wlf { t_ref_c, c1, c2_k };
    law.validate().map_err(|e| DmaError::Structure {
        file: file.into(),
        location: Loc::Line(1).to_string(),
        message: format!("WLF constants of the header: {e}"),
    })?;
    Ok(Some(law))
}

/// RepTate's fixed columns for a file without names: ω, G′, G″.
const DEFAULT_NAMES: [(&str, &str); 3] = [("w", "rad/s"), ("G'", "Pa"), ("G''", "Pa")];

/// Read a RepTate `.osc` or `.tts` file.
pub fn read(file: &str, text: &str) -> Result<RawFile, DmaError> {
    let lines: Vec<(usize, &str)> = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .collect();
    let structure = |ln: usize, message: &str| DmaError::Structure {
        file: file.into(),
        location: Loc::Line(ln).to_string(),
        message: message.into(),
    };
    let Some(&(_, first)) = lines.first() else {
        return Err(structure(1, "an empty RepTate file"));
    };
    let params = parameters(first)
        .ok_or_else(|| structure(1, "the first line is not `key=value;…` parameters"))?;
    // Data rows are aligned with spaces or tabs (white space); name and unit rows are split at tabs
    // when they have them (a unit may be blank), else at white space.
    let delim = Delimiter::Whitespace;
    let header_split = |l: &str| {
        if l.contains('\t') {
            text::split(l, Delimiter::Tab)
        } else {
            text::split(l, Delimiter::Whitespace)
        }
    };
    let mut raw = RawFile::default();
    for (k, v) in &params {
        raw.metadata.insert(k.clone(), v.clone());
    }
    let mut block = Block {
        header_loc: Some(Loc::Line(lines.get(1).map_or(1, |l| l.0 + 1))),
        ..Block::default()
    };
    let mut k = 1;
    let is_data = |l: &str| super::table::is_data_row(&text::split(l, delim), Decimal::Point);
    if lines.get(k).is_some_and(|(_, l)| !is_data(l)) {
        block.names = header_split(lines[k].1)
            .iter()
            .map(|n| units::split_name_unit(n).0)
            .collect();
        k += 1;
        if lines.get(k).is_some_and(|(_, l)| !is_data(l)) {
            block.units = header_split(lines[k].1)
                .iter()
                .map(|u| Some(super::generic::strip_brackets(u)).filter(|u| !u.is_empty()))
                .collect();
            k += 1;
        }
    } else {
        block.names = DEFAULT_NAMES.iter().map(|n| n.0.to_string()).collect();
    }
    if block.units.is_empty() {
        // RepTate's layout: ω in rad/s, then G′ and G″ in Pa.
        block.units = (0..block.names.len())
            .map(|c| DEFAULT_NAMES.get(c).map(|n| n.1.to_string()))
            .collect();
        raw.metadata.insert(
            "units".into(),
            "none written: ω in rad/s, G′ and G″ in Pa (RepTate's file layout)".into(),
        );
    }
    for &(ln, l) in &lines[k..] {
        block.rows.push(Row {
            loc: Loc::Line(ln + 1),
            cells: text::split(l, delim)
                .iter()
                .map(|c| cell_from_text(c, Decimal::Point))
                .collect(),
        });
    }
    let t = params.get("T").and_then(|t| t.trim().parse::<f64>().ok());
    block.nominal_c = t.or_else(|| temperature_in_file_name(file));
    block.label = block.nominal_c.map(|t| format!("T={t}"));
    raw.blocks.push(block);
    Ok(raw)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parameters_and_temperatures_in_names() {
        let p = parameters("T=40;Mw=225.9;chem=PI;label=PI223k_14_PP-10;PDI=1.03;").unwrap();
        assert_eq!(p["T"], "40");
        assert!(parameters("Freq G' G\"").is_none());
        assert_eq!(
            temperature_in_file_name("PI223k-14_40C_FS_PP10.osc"),
            Some(40.0)
        );
        assert_eq!(
            temperature_in_file_name("a/PI600k_-20C_02b.osc"),
            Some(-20.0)
        );
        assert_eq!(temperature_in_file_name("PI_13.5k_T-35.tts"), Some(-35.0));
        assert_eq!(temperature_in_file_name("PI_13.5k.tts"), None);
    }

    #[test]
    fn wlf_from_the_header() {
        let p = parameters("T=-35;C1=6.85;C2=150.5;Tr=25;").unwrap();
        let law = wlf_from_parameters("x.tts", &p).unwrap().unwrap();
        assert_eq!(
            law,
            ShiftLaw::Wlf {
                t_ref_c: 25.0,
                c1: 6.85,
                c2_k: 150.5
            }
        );
        assert!(wlf_from_parameters("x.tts", &parameters("T=-35;").unwrap())
            .unwrap()
            .is_none());
        let bad = parameters("T=-35;C1=6.85;C2=-1;").unwrap();
        assert!(wlf_from_parameters("x.tts", &bad).is_err());
    }
}

/// A RepTate `.tts` master curve: its reduced points as one isotherm at the reference temperature
/// (the parameter `Tr`, else `T`), and the WLF law of its header when it carries one.
#[derive(Debug, Clone, PartialEq)]
#[cfg(test)]
pub struct ReptateMaster {
    /// The reduced points (frequency = reduced frequency at `t_ref_c`), one isotherm.
    pub measurement: super::Measurement,
    /// Reference temperature of the master curve, °C.
    pub t_ref_c: f64,
    /// WLF law of the header (`C1`, `C2`, `Tr`), if given.
    pub shift_law: Option<ShiftLaw>,
}

/// Read a RepTate `.tts` master curve ([`ReptateMaster`]). A temperature column, if any, is
/// ignored: every point is at the reference temperature.
#[cfg(test)]
pub fn read_master(
    path: &std::path::Path,
    opts: &super::IngestOptions,
) -> Result<ReptateMaster, DmaError> {
    let name = path.display().to_string();
    let mut o = opts.clone();
    o.format = Some(super::Format::Reptate);
    let mut m = super::read_files(&[path], &o)?;
    let meta = &m.sources[0].metadata;
    let params: BTreeMap<String, String> = meta
        .iter()
        .filter(|(k, _)| ["T", "Tr", "C1", "C2"].contains(&k.as_str()))
        .map(|(k, v)| (k.clone(), v.clone()))
        .collect();
    let shift_law = wlf_from_parameters(&name, &params)?;
    let t_ref_c = match (
        &shift_law,
        params.get("T").and_then(|t| t.parse::<f64>().ok()),
    ) {
        (Some(l), _) => l.t_ref_c(),
        (None, Some(t)) => t,
        (None, None) => {
            return Err(DmaError::NoTemperature {
                file: name,
                location: Loc::Line(1).to_string(),
            })
        }
    };
    let mut points: Vec<super::DataPoint> = m
        .isotherms
        .drain(..)
        .flat_map(|i| i.points)
        .map(|mut p| {
            p.temp_c = None;
            p
        })
        .collect();
    points.sort_by(|a, b| a.freq_hz.total_cmp(&b.freq_hz));
    m.isotherms = vec![super::Isotherm {
        temp_nominal_c: t_ref_c,
        temp_mean_c: t_ref_c,
        source: 0,
        points,
        nominal_source: "file".into(),
        sheet: None,
        label: Some(format!("master curve at {t_ref_c} °C")),
    }];
    Ok(ReptateMaster {
        measurement: m,
        t_ref_c,
        shift_law,
    })
}
