//! pyvisco's CSV layouts, both ways: a master curve (`f, E_stor, E_loss` over a unit row `Hz, MPa,
//! MPa`; `G_…` for shear) read together with its shift factors (`T, log_aT` over `C, -`), and the
//! same two layouts written.
//!
//! Input: the two files' bytes (or paths); output: [`PyviscoMaster`] — the reduced points as one
//! isotherm at the reference temperature (a [`Measurement`] that
//! [`crate::tts::master_curve_from_reduced`] turns into a master curve) and the shift table
//! ([`ShiftLaw::Table`]). Writers: [`master_csv`], [`shift_csv`] → CSV text.
//!
//! The layout is pyvisco's loader's (`load.user_master`, `load.user_shift`: two header rows, the
//! first the quantity, the second its unit; storage and loss in one unit of Pa, kPa, MPa or GPa;
//! frequency in Hz; temperature in °C). pyvisco takes the reference temperature from its user; here
//! it is the shift table's row with log a_T = 0 (the shipped EMS-CA table has one, at −5 °C), or the
//! one the caller states. Time-domain master curves (`t, E_relax`) are [`super::pyvisco_time`]'s.
//! Units are read from the file, never guessed; an unparsable cell is an error, never
//! dropped.

use super::error::DmaError;
use super::units::ModulusUnit;
use super::{DataPoint, Isotherm, Measurement, SourceFile};
use crate::material::{ModulusKind, ShiftLaw};
use std::collections::BTreeMap;

/// A pyvisco master curve with its shift factors.
#[derive(Debug, Clone, PartialEq)]
pub struct PyviscoMaster {
    /// The reduced points (frequency = reduced frequency at `t_ref_c`) as one isotherm; the sources
    /// are the master-curve file and the shift-factor file.
    pub measurement: Measurement,
    /// Reference temperature, °C.
    pub t_ref_c: f64,
    /// The shift factors as a table law referred to `t_ref_c`.
    pub shift_law: ShiftLaw,
}

impl PyviscoMaster {
    /// Read a pyvisco master curve and its shift-factor file ([`PyviscoMaster`]); `t_ref_c` is needed
    /// only when the shift table has no row with log a_T = 0.
    pub fn read(
        master: &std::path::Path,
        shifts: &std::path::Path,
        poisson: f64,
        t_ref_c: Option<f64>,
    ) -> Result<PyviscoMaster, DmaError> {
        let read = |p: &std::path::Path| {
            crate::fsutil::read_regular(p, crate::limits::INPUT_BYTES_MAX).map_err(|source| {
                DmaError::Io {
                    file: p.display().to_string(),
                    source,
                }
            })
        };
        Self::from_bytes(
            &master.display().to_string(),
            &read(master)?,
            &shifts.display().to_string(),
            &read(shifts)?,
            poisson,
            t_ref_c,
        )
    }
    /// [`PyviscoMaster::read`] on bytes already read.
    pub fn from_bytes(
        master_file: &str,
        master: &[u8],
        shift_file: &str,
        shifts: &[u8],
        poisson: f64,
        t_ref_c: Option<f64>,
    ) -> Result<PyviscoMaster, DmaError> {
        let shift_law = super::shiftfactors::shift_table_from_bytes(shift_file, shifts, t_ref_c)?;
        master_with_law(
            master_file,
            master,
            Some((shift_file, shifts)),
            shift_law,
            poisson,
        )
    }
}

/// pyvisco's frequency-domain master curve without its shift-factor file: the curve as shifted to
/// `t_ref_c` (required: the file does not say it), with the law of that one temperature (a_T = 1
/// there, unknown elsewhere), so the friction it gives is determined at `t_ref_c` only.
pub fn read_master_alone(
    master: &std::path::Path,
    poisson: f64,
    t_ref_c: Option<f64>,
) -> Result<PyviscoMaster, DmaError> {
    let file = master.display().to_string();
    let Some(t_ref) = t_ref_c.filter(|t| t.is_finite()) else {
        return Err(DmaError::Setting {
            field: "tref".into(),
            value: format!("{t_ref_c:?}"),
            reason: "a master curve without its shift-factor file needs the temperature it was \
                     shifted to (--tref)"
                .into(),
        });
    };
    let bytes =
        crate::fsutil::read_regular(master, crate::limits::INPUT_BYTES_MAX).map_err(|source| {
            DmaError::Io {
                file: file.clone(),
                source,
            }
        })?;
    let law = ShiftLaw::single_temperature(t_ref);
    let mut pv = master_with_law(&file, &bytes, None, law, poisson)?;
    pv.measurement.warnings.push(format!(
        "{file}: no shift-factor file: the master curve is known at {t_ref} °C only (a_T = 1 \
         there, no law elsewhere), so its friction is determined at that temperature only"
    ));
    Ok(pv)
}

/// The [`PyviscoMaster`] of a master-curve file and the law it was shifted by (`shifts`: the
/// shift-factor file it came from, if any).
fn master_with_law(
    master_file: &str,
    master: &[u8],
    shifts: Option<(&str, &[u8])>,
    shift_law: ShiftLaw,
    poisson: f64,
) -> Result<PyviscoMaster, DmaError> {
    // ν of an isotropic stable solid lies in (−1, 0.5] (the check of IngestOptions).
    if !(poisson > -1.0 && poisson <= 0.5) {
        return Err(DmaError::Setting {
            field: "poisson".into(),
            value: poisson.to_string(),
            reason: "Poisson's ratio must lie in (−1, 0.5]".into(),
        });
    }
    let t_ref = shift_law.t_ref_c();
    let (kind, unit_text, points) = read_master_points(master_file, master)?;
    let source =
        |path: &str, bytes: &[u8], format: &str, columns: Vec<super::ColumnInfo>| SourceFile {
            path: path.to_string(),
            sha256: super::sha256_hex(bytes),
            format: format.into(),
            metadata: BTreeMap::new(),
            encoding: super::text::decode(bytes).encoding.to_string(),
            columns,
        };
    let m = match kind {
        ModulusKind::Tensile => "E",
        ModulusKind::Shear => "G",
    };
    let col = |quantity: &str, name: String, unit: &str, index| super::ColumnInfo {
        quantity: quantity.into(),
        name,
        unit: unit.into(),
        index,
    };
    let master_columns = vec![
        col("frequency", "f".into(), "Hz", 0),
        col("storage modulus", format!("{m}_stor"), &unit_text, 1),
        col("loss modulus", format!("{m}_loss"), &unit_text, 2),
    ];
    let n = points.len();
    let measurement = Measurement {
        sources: std::iter::once(source(
            master_file,
            master,
            "pyvisco-master",
            master_columns,
        ))
        .chain(shifts.map(|(f, b)| source(f, b, "pyvisco-shift-factors", vec![])))
        .collect(),
        kind,
        poisson,
        isotherms: vec![Isotherm {
            temp_nominal_c: t_ref,
            temp_mean_c: t_ref,
            source: 0,
            points,
            nominal_source: "file".into(),
            sheet: None,
            label: Some(format!("pyvisco master curve at {t_ref} °C")),
        }],
        warnings: vec![match shifts {
            Some((shift_file, _)) => format!(
                "{master_file}: a master curve read already shifted ({n} points at {t_ref} °C, the \
                 temperature of log a_T = 0 in {shift_file})"
            ),
            None => format!(
                "{master_file}: a master curve read already shifted ({n} points at {t_ref} °C, \
                 as --tref says)"
            ),
        }],
        issues: vec![],
        summary: Default::default(),
    };
    Ok(PyviscoMaster {
        measurement,
        t_ref_c: t_ref,
        shift_law,
    })
}

/// The points of a pyvisco master-curve CSV: (kind, modulus unit as written, points in SI).
fn read_master_points(
    file: &str,
    bytes: &[u8],
) -> Result<(ModulusKind, String, Vec<DataPoint>), DmaError> {
    let text = super::text::decode(bytes).text;
    let structure = |line: usize, message: String| DmaError::Structure {
        file: file.into(),
        location: format!("line {line}"),
        message,
    };
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim_start_matches('\u{feff}')));
    let split = |l: &str| -> Vec<String> { l.split(',').map(|s| s.trim().to_string()).collect() };
    let (_, names) = lines
        .next()
        .ok_or_else(|| structure(1, "empty file".into()))?;
    let names = split(names);
    let (unit_line, units) = lines.next().ok_or_else(|| {
        structure(
            2,
            "no unit row under the name row (pyvisco's CSV has two header rows)".into(),
        )
    })?;
    let units = split(units);
    let find = |n: &str| names.iter().position(|x| x == n);
    if find("t").is_some() && find("f").is_none() {
        return Err(structure(
            1,
            "a time-domain master curve (t, E_relax): this reader takes frequency-domain curves \
             (f, E_stor, E_loss); the time-domain one is read by dma::pyvisco_time (`fit \
             --master-curve` dispatches by its header)"
                .into(),
        ));
    }
    let missing = |q: &'static str, looked: &'static str| DmaError::MissingColumn {
        file: file.into(),
        location: "line 1".into(),
        quantity: q,
        looked_for: looked,
        columns: names.join(", "),
    };
    let i_f = find("f").ok_or_else(|| missing("frequency", "f"))?;
    let (kind, m) = if find("E_stor").is_some() {
        (ModulusKind::Tensile, "E")
    } else if find("G_stor").is_some() {
        (ModulusKind::Shear, "G")
    } else {
        return Err(missing("storage modulus", "E_stor, G_stor"));
    };
    let i_s = find(&format!("{m}_stor")).ok_or_else(|| missing("storage modulus", "E_stor"))?;
    let i_l =
        find(&format!("{m}_loss")).ok_or_else(|| missing("loss modulus", "E_loss, G_loss"))?;
    let unit_of = |i: usize| units.get(i).cloned().unwrap_or_default();
    let loc = format!("line {unit_line}");
    if super::units::clean_unit(&unit_of(i_f)) != "Hz" {
        return Err(DmaError::UnknownUnit {
            file: file.into(),
            location: loc,
            column: names[i_f].clone(),
            quantity: "frequency",
            unit: unit_of(i_f),
        });
    }
    let modulus_unit = |i: usize| {
        ModulusUnit::parse(&unit_of(i)).ok_or_else(|| DmaError::UnknownUnit {
            file: file.into(),
            location: loc.clone(),
            column: names[i].clone(),
            quantity: "storage modulus",
            unit: unit_of(i),
        })
    };
    let (us, ul) = (modulus_unit(i_s)?, modulus_unit(i_l)?);
    let columns = [i_f, i_s, i_l];
    let points = master_rows(file, lines, &names, columns, [us.to_pa(), ul.to_pa()])?;
    Ok((kind, unit_of(i_s), points))
}

/// Cell `i` of data row `line` (`cells` split, `names` the header) as a number that `accept`s, or
/// the error naming file, line and column (pyvisco's frequency and time-domain CSVs alike).
pub(super) fn cell_number(
    file: &str,
    line: usize,
    names: &[String],
    cells: &[String],
    i: usize,
    accept: impl Fn(&f64) -> bool,
) -> Result<f64, DmaError> {
    let c = cells.get(i).map(String::as_str).unwrap_or("");
    c.parse::<f64>()
        .ok()
        .filter(accept)
        .ok_or_else(|| DmaError::BadNumber {
            file: file.into(),
            location: format!("line {line}"),
            column: names[i].clone(),
            value: c.to_string(),
        })
}

/// The data rows of a pyvisco master-curve CSV (after its two header rows): frequency, storage and
/// loss modulus from `columns` = [f, M′, M″], the moduli times `to_pa`. A cell that is not a finite
/// number is an error; blank lines are skipped; no row at all is an error.
fn master_rows<'a>(
    file: &str,
    lines: impl Iterator<Item = (usize, &'a str)>,
    names: &[String],
    columns: [usize; 3],
    to_pa: [f64; 2],
) -> Result<Vec<DataPoint>, DmaError> {
    let split = |l: &str| -> Vec<String> { l.split(',').map(|s| s.trim().to_string()).collect() };
    let [i_f, i_s, i_l] = columns;
    let mut points = Vec::new();
    for (line, l) in lines {
        if l.trim().is_empty() {
            continue;
        }
        let cells = split(l);
        let get = |i: usize| cell_number(file, line, names, &cells, i, |v| v.is_finite());
        points.push(DataPoint {
            freq_hz: get(i_f)?,
            storage_pa: get(i_s)? * to_pa[0],
            loss_pa: get(i_l)? * to_pa[1],
            temp_c: None,
            line,
            flags: vec![],
        });
    }
    if points.is_empty() {
        return Err(DmaError::NoData {
            file: file.into(),
            reason: "the two header rows are not followed by data".into(),
        });
    }
    Ok(points)
}

/// A number written so that reading it back gives the same `f64` (Rust's shortest round-trip form).
fn num(x: f64) -> String {
    format!("{x:?}")
}

/// pyvisco's master-curve CSV of (reduced frequency in Hz, storage in Pa, loss in Pa): names `f,
/// E_stor, E_loss` (or `G_…` for shear), units `Hz, MPa, MPa`, one row per point.
pub fn master_csv(kind: ModulusKind, points: &[(f64, f64, f64)]) -> String {
    let m = match kind {
        ModulusKind::Tensile => "E",
        ModulusKind::Shear => "G",
    };
    let mut s = format!("f,{m}_stor,{m}_loss\nHz,MPa,MPa\n");
    for &(f, e1, e2) in points {
        s.push_str(&format!("{},{},{}\n", num(f), num(e1 / 1e6), num(e2 / 1e6)));
    }
    s
}

/// pyvisco's shift-factor CSV of (temperature in °C, log10 a_T): names `T, log_aT`, units `C, -`,
/// rows from the highest temperature down (as pyvisco writes them).
pub fn shift_csv(shifts: &[(f64, f64)]) -> String {
    let mut rows = shifts.to_vec();
    rows.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut s = String::from("T,log_aT\nC,-\n");
    for (t, a) in rows {
        s.push_str(&format!("{},{}\n", num(t), num(a)));
    }
    s
}

impl PyviscoMaster {
    /// pyvisco's frequency-domain master-curve CSV of `points` (`master_csv`).
    pub fn master_csv(kind: ModulusKind, points: &[(f64, f64, f64)]) -> String {
        master_csv(kind, points)
    }

    /// pyvisco's shift-factor CSV of `shifts` (`shift_csv`).
    pub fn shift_csv(shifts: &[(f64, f64)]) -> String {
        shift_csv(shifts)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_and_layouts_are_checked() {
        let sf = b"T,log_aT\nC,-\n20,1\n30,0\n";
        let ok = PyviscoMaster::from_bytes(
            "m.csv",
            b"f,G_stor,G_loss\nHz,kPa,kPa\n1,2,3\n",
            "s.csv",
            sf,
            0.5,
            None,
        )
        .unwrap();
        assert_eq!(ok.measurement.kind, ModulusKind::Shear);
        assert_eq!(ok.t_ref_c, 30.0);
        assert_eq!(ok.measurement.isotherms[0].points[0].loss_pa, 3e3);
        for bad in [
            &b"f,E_stor,E_loss\nrad/s,MPa,MPa\n1,2,3\n"[..],
            b"f,E_stor,E_loss\nHz,mPa,MPa\n1,2,3\n",
            b"t,E_relax\ns,MPa\n1,2\n",
            b"f,E_stor,E_loss\nHz,MPa,MPa\n1,x,3\n",
            b"f,E_stor,E_loss\nHz,MPa,MPa\n",
            b"f,E_stor\nHz,MPa\n1,2\n",
        ] {
            assert!(PyviscoMaster::from_bytes("m.csv", bad, "s.csv", sf, 0.5, None).is_err());
        }
    }

    /// Poisson's ratio is checked by the reader (the CLI's `fit --poisson` used to check it alone):
    /// 0.5 is the incompressible limit and accepted, 0.7 and −1 lie outside (−1, 0.5].
    #[test]
    fn poisson_outside_its_range_is_refused() {
        let sf = b"T,log_aT\nC,-\n20,1\n30,0\n";
        let m = b"f,G_stor,G_loss\nHz,kPa,kPa\n1,2,3\n";
        assert!(PyviscoMaster::from_bytes("m.csv", m, "s.csv", sf, 0.5, None).is_ok());
        for nu in [0.7, -1.0, f64::NAN] {
            let err = PyviscoMaster::from_bytes("m.csv", m, "s.csv", sf, nu, None).unwrap_err();
            assert!(
                matches!(&err, DmaError::Setting { field, .. } if field == "poisson"),
                "{err}"
            );
        }
    }

    #[test]
    fn written_numbers_read_back_exactly() {
        let csv = master_csv(ModulusKind::Tensile, &[(1e-12, 88.796e6, 10.5e6)]);
        assert_eq!(csv, "f,E_stor,E_loss\nHz,MPa,MPa\n1e-12,88.796,10.5\n");
        assert_eq!(
            shift_csv(&[(-5.0, 0.0), (100.0, -11.7)]),
            "T,log_aT\nC,-\n100.0,-11.7\n-5.0,0.0\n"
        );
    }
}
