//! pyvisco's time-domain master curve, both ways: the CSV `t, E_relax` over the unit row `s, MPa`
//! (`G_relax` for shear; the modulus in Pa, kPa, MPa or GPa), as pyvisco's `load.user_master(...,
//! domain='time')` reads it, with or without its shift-factor file (`T, log_aT` over `C, -`).
//!
//! Input: the files' bytes (or paths); output: [`PyviscoTimeMaster`] — the relaxation points as one
//! [`TimeIsotherm`] at the reference temperature (a [`TimeData`] that
//! `crate::tts::time_shift::master_from_reduced` takes without shifting it) and the shift table
//! when a shift file came with it. Writer: [`time_master_csv`] → CSV text.
//!
//! The reference temperature is the shift table's row with log a_T = 0, or the one the caller
//! states (`--tref`); without a shift file it must be stated (pyvisco asks its user for it too).
//! Mode and kind come from the file: pyvisco's time domain is relaxation only (`E_relax` tensile,
//! `G_relax` shear). Units are read from the unit row, never guessed; a cell that is not a finite
//! positive number is an error naming file, line and column.

use super::error::DmaError;
use super::time_domain::{TimeData, TimeIsotherm, TimeMode, TimePoint, MIN_POINTS};
use super::units::ModulusUnit;
use super::SourceFile;
use crate::material::{ModulusKind, ShiftLaw};
use std::collections::BTreeMap;

/// A pyvisco time-domain master curve with its shift factors.
#[derive(Debug, Clone, PartialEq)]
pub struct PyviscoTimeMaster {
    /// The relaxation points (time = reduced time at `t_ref_c`) as one isotherm; the sources are
    /// the master-curve file and the shift-factor file (when given).
    pub data: TimeData,
    /// Reference temperature, °C.
    pub t_ref_c: f64,
    /// The shift factors as a table law referred to `t_ref_c`; None without a shift file.
    pub shift_law: Option<ShiftLaw>,
}

/// Whether a CSV's first row is pyvisco's time-domain master-curve header (a `t` column and an
/// `E_relax` or `G_relax` column, no `f`).
pub fn is_time_master(bytes: &[u8]) -> bool {
    let text = super::text::decode(bytes).text;
    let first = text.lines().next().unwrap_or("");
    let names: Vec<&str> = first
        .trim_start_matches('\u{feff}')
        .split(',')
        .map(str::trim)
        .collect();
    names.contains(&"t")
        && !names.contains(&"f")
        && names.iter().any(|n| *n == "E_relax" || *n == "G_relax")
}

/// Read a pyvisco time-domain master curve and, when given, its shift-factor file
/// ([`PyviscoTimeMaster`]); `t_ref_c` is needed without a shift file, or when its table has no row
/// with log a_T = 0.
pub fn read_time_master(
    master: &std::path::Path,
    shifts: Option<&std::path::Path>,
    poisson: f64,
    t_ref_c: Option<f64>,
) -> Result<PyviscoTimeMaster, DmaError> {
    let read = |p: &std::path::Path| {
        crate::fsutil::read_regular(p, crate::limits::INPUT_BYTES_MAX)
            .map(|b| (p.display().to_string(), b))
            .map_err(|source| DmaError::Io {
                file: p.display().to_string(),
                source,
            })
    };
    let (mf, mb) = read(master)?;
    let shifts = shifts.map(read).transpose()?;
    time_master_from_bytes(
        &mf,
        &mb,
        shifts.as_ref().map(|(f, b)| (f.as_str(), b.as_slice())),
        poisson,
        t_ref_c,
    )
}

/// [`read_time_master`] on bytes already read (`shifts`: the shift file's name and bytes).
pub fn time_master_from_bytes(
    master_file: &str,
    master: &[u8],
    shifts: Option<(&str, &[u8])>,
    poisson: f64,
    t_ref_c: Option<f64>,
) -> Result<PyviscoTimeMaster, DmaError> {
    if !(poisson > -1.0 && poisson <= 0.5) {
        return Err(DmaError::Setting {
            field: "poisson".into(),
            value: poisson.to_string(),
            reason: "Poisson's ratio must lie in (−1, 0.5]".into(),
        });
    }
    let (shift_law, t_ref) = match (shifts, t_ref_c) {
        (Some((file, bytes)), t) => {
            let law = super::shiftfactors::shift_table_from_bytes(file, bytes, t)?;
            let t_ref = law.t_ref_c();
            (Some(law), t_ref)
        }
        (None, Some(t)) if t.is_finite() => (None, t),
        (None, t) => {
            return Err(DmaError::Setting {
                field: "tref".into(),
                value: t.map_or("none".into(), |t| t.to_string()),
                reason: format!(
                    "{master_file}: a master curve without its shift-factor file needs its \
                     reference temperature stated (--tref)"
                ),
            })
        }
    };
    let (kind, column, unit, points) = read_time_points(master_file, master)?;
    let source = |path: &str, bytes: &[u8], format: &str, columns| SourceFile {
        path: path.to_string(),
        sha256: super::sha256_hex(bytes),
        format: format.into(),
        metadata: BTreeMap::new(),
        encoding: super::text::decode(bytes).encoding.to_string(),
        columns,
    };
    let col = |quantity: &str, name: &str, unit: &str, index| super::ColumnInfo {
        quantity: quantity.into(),
        name: name.into(),
        unit: unit.into(),
        index,
    };
    let mut sources = vec![source(
        master_file,
        master,
        "pyvisco-time-master",
        vec![
            col("time", "t", "s", 0),
            col("relaxation modulus", &column, &unit, 1),
        ],
    )];
    if let Some((file, bytes)) = shifts {
        sources.push(source(file, bytes, "pyvisco-shift-factors", vec![]));
    }
    let n = points.len();
    let said = match shifts {
        Some((f, _)) => format!("the temperature of log a_T = 0 in {f}, or --tref"),
        None => "stated with --tref; no shift-factor file".into(),
    };
    let data = TimeData {
        sources,
        mode: TimeMode::Relaxation,
        kind,
        poisson,
        isotherms: vec![TimeIsotherm {
            temp_c: t_ref,
            source: 0,
            points,
            label: Some(format!("pyvisco master curve at {t_ref} °C")),
        }],
        evidence: vec![format!(
            "{master_file}: relaxation, {}: pyvisco's column `{column}`",
            super::columns::kind_name(kind)
        )],
        warnings: vec![format!(
            "{master_file}: a time-domain master curve read already shifted ({n} points at \
             {t_ref} °C, {said})"
        )],
    };
    Ok(PyviscoTimeMaster {
        data,
        t_ref_c: t_ref,
        shift_law,
    })
}

/// The points of pyvisco's `t, E_relax` CSV: (kind, modulus column, its unit as written, points in
/// SI sorted by time).
fn read_time_points(
    file: &str,
    bytes: &[u8],
) -> Result<(ModulusKind, String, String, Vec<TimePoint>), DmaError> {
    let text = super::text::decode(bytes).text;
    let split = |l: &str| -> Vec<String> {
        l.trim_start_matches('\u{feff}')
            .split(',')
            .map(|s| s.trim().to_string())
            .collect()
    };
    let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l));
    let names = split(lines.next().map_or("", |l| l.1));
    let units = lines
        .next()
        .map(|(_, l)| split(l))
        .ok_or_else(|| DmaError::Structure {
            file: file.into(),
            location: "line 2".into(),
            message: "no unit row under the name row (pyvisco's CSV has two header rows)".into(),
        })?;
    let find = |n: &str| names.iter().position(|x| x == n);
    let missing = |q: &'static str, looked: &'static str| DmaError::MissingColumn {
        file: file.into(),
        location: "line 1".into(),
        quantity: q,
        looked_for: looked,
        columns: names.join(", "),
    };
    let i_t = find("t").ok_or_else(|| missing("time", "t"))?;
    let (kind, i_m) = match (find("E_relax"), find("G_relax")) {
        (Some(i), _) => (ModulusKind::Tensile, i),
        (None, Some(i)) => (ModulusKind::Shear, i),
        _ => return Err(missing("relaxation modulus", "E_relax, G_relax")),
    };
    let unit_of = |i: usize| units.get(i).cloned().unwrap_or_default();
    let unknown = |i: usize, quantity: &'static str| DmaError::UnknownUnit {
        file: file.into(),
        location: "line 2".into(),
        column: names[i].clone(),
        quantity,
        unit: unit_of(i),
    };
    if super::units::clean_unit(&unit_of(i_t)) != "s" {
        return Err(unknown(i_t, "time"));
    }
    let to_pa = ModulusUnit::parse(&unit_of(i_m))
        .ok_or_else(|| unknown(i_m, "relaxation modulus"))?
        .to_pa();
    let mut points = Vec::new();
    for (line, l) in lines.filter(|(_, l)| !l.trim().is_empty()) {
        let cells = split(l);
        let get = |i: usize| {
            super::pyvisco::cell_number(file, line, &names, &cells, i, |v| {
                v.is_finite() && *v > 0.0
            })
        };
        points.push(TimePoint {
            time_s: get(i_t)?,
            value: get(i_m)? * to_pa,
            line,
        });
    }
    if points.len() < MIN_POINTS {
        return Err(DmaError::NoData {
            file: file.into(),
            reason: format!(
                "{} data rows under the two header rows; a fit needs {MIN_POINTS}",
                points.len()
            ),
        });
    }
    points.sort_by(|a, b| a.time_s.total_cmp(&b.time_s));
    Ok((kind, names[i_m].clone(), unit_of(i_m), points))
}

/// pyvisco's time-domain master-curve CSV of (reduced time in s, relaxation modulus in Pa): names
/// `t, E_relax` (`G_relax` for shear), units `s, MPa`, one row per point.
pub fn time_master_csv(kind: ModulusKind, points: &[(f64, f64)]) -> String {
    let m = match kind {
        ModulusKind::Tensile => "E",
        ModulusKind::Shear => "G",
    };
    let mut s = format!("t,{m}_relax\ns,MPa\n");
    for &(t, e) in points {
        // Rust's shortest round-trip form: read back, the same f64
        s.push_str(&format!("{t:?},{:?}\n", e / 1e6));
    }
    s
}

impl PyviscoTimeMaster {
    /// Read a time-domain master curve and its shift file, if any (`read_time_master`).
    pub fn read(
        master: &std::path::Path,
        shifts: Option<&std::path::Path>,
        poisson: f64,
        t_ref_c: Option<f64>,
    ) -> Result<Self, DmaError> {
        read_time_master(master, shifts, poisson, t_ref_c)
    }

    /// [`PyviscoTimeMaster::read`] on bytes already read (`time_master_from_bytes`).
    pub fn from_bytes(
        master_file: &str,
        master: &[u8],
        shifts: Option<(&str, &[u8])>,
        poisson: f64,
        t_ref_c: Option<f64>,
    ) -> Result<Self, DmaError> {
        time_master_from_bytes(master_file, master, shifts, poisson, t_ref_c)
    }

    /// pyvisco's time-domain master-curve CSV of `points` (`time_master_csv`).
    pub fn master_csv(kind: ModulusKind, points: &[(f64, f64)]) -> String {
        time_master_csv(kind, points)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SF: &[u8] = b"T,log_aT\nC,-\n20,1\n30,0\n";
    const M: &[u8] = b"t,E_relax\ns, MPa\n10,5\n1,7\n100,4\n";

    #[test]
    fn reads_the_layout_with_and_without_its_shift_file() {
        let with = time_master_from_bytes("m.csv", M, Some(("s.csv", SF)), 0.5, None).unwrap();
        assert_eq!(with.t_ref_c, 30.0);
        assert!(with.shift_law.is_some());
        let d = &with.data;
        assert_eq!(
            (d.mode, d.kind),
            (TimeMode::Relaxation, ModulusKind::Tensile)
        );
        assert_eq!(d.isotherms.len(), 1);
        let p = &d.isotherms[0].points;
        // sorted by time, MPa → Pa, lines as in the file
        assert_eq!((p[0].time_s, p[0].value, p[0].line), (1.0, 7e6, 4));
        let without = time_master_from_bytes("m.csv", M, None, 0.5, Some(-5.0)).unwrap();
        assert_eq!((without.t_ref_c, without.shift_law), (-5.0, None));
        assert_eq!(without.data.isotherms[0].temp_c, -5.0);
        let g = time_master_from_bytes(
            "g.csv",
            b"t,G_relax\ns,kPa\n1,3\n2,2\n3,1\n",
            None,
            0.5,
            Some(0.0),
        )
        .unwrap();
        assert_eq!(g.data.kind, ModulusKind::Shear);
        assert_eq!(g.data.isotherms[0].points[2].value, 1e3);
        assert!(is_time_master(M) && !is_time_master(b"f,E_stor,E_loss\nHz,MPa,MPa\n"));
    }

    #[test]
    fn bad_files_are_errors_naming_their_place() {
        let err = |m: &[u8], t| time_master_from_bytes("m.csv", m, None, 0.5, t).unwrap_err();
        // no shift file and no --tref: the reference temperature is not guessed
        let e = err(M, None);
        assert!(
            matches!(&e, DmaError::Setting { field, .. } if field == "tref"),
            "{e}"
        );
        let e = err(b"t,E_relax\nmin,MPa\n1,2\n2,1\n3,1\n", Some(0.0));
        assert!(
            matches!(&e, DmaError::UnknownUnit { column, .. } if column == "t"),
            "{e}"
        );
        let e = err(b"t,E_relax\ns,MPa\n1,2\n2,x\n3,1\n", Some(0.0));
        assert!(e.to_string().contains("line 4"), "{e}");
        let e = err(b"t,E_relax\ns,MPa\n1,2\n2,-1\n3,1\n", Some(0.0));
        assert!(
            matches!(&e, DmaError::BadNumber { column, .. } if column == "E_relax"),
            "{e}"
        );
        for bad in [
            &b""[..],
            b"t,E_relax\n",
            b"t,E_relax\ns,MPa\n1,2\n",
            b"t,J\ns,1/MPa\n1,2\n",
        ] {
            assert!(time_master_from_bytes("m.csv", bad, None, 0.5, Some(0.0)).is_err());
        }
    }

    #[test]
    fn written_numbers_read_back_exactly() {
        let csv = time_master_csv(ModulusKind::Tensile, &[(1e-3, 1714.266e6), (2.5, 88e6)]);
        assert_eq!(csv, "t,E_relax\ns,MPa\n0.001,1714.266\n2.5,88.0\n");
        let back = time_master_from_bytes("m.csv", csv.as_bytes(), None, 0.5, Some(0.0));
        assert!(back.is_err(), "two points are too few to fit");
    }
}
