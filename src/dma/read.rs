//! Entry point of the `dma` stage: files (paths or bytes) + [`IngestOptions`] → [`Measurement`].
//! Reads each file, hashes it (SHA-256), detects or takes its format, runs its reader, gives the
//! columns their meaning and SI units, splits isotherms, sorts them by temperature and runs the checks.

use super::checks::{self, CheckSettings};
use super::column_map::ColumnMap;
use super::columns::{self, kind_name, RawPoint};
use super::detect::{self, Format};
use super::error::DmaError;
use super::isotherms::{self, SplitSettings};
use super::table::{Loc, RawFile};
use super::units::{FreqUnit, ModulusUnit, TempUnit};
use super::{eplexor, generic, proteus, reptate, rheocompass, text, trios};
use super::{DataPoint, Isotherm, Measurement, SourceFile};
use crate::material::ModulusKind;
use sha2::{Digest, Sha256};

/// How to read the files; everything the command line can state.
#[derive(Debug, Clone, PartialEq)]
pub struct IngestOptions {
    /// Force a reader instead of detecting it (`--format`).
    pub format: Option<Format>,
    /// Unit of modulus columns that have none in the file (`--modulus-unit`).
    pub modulus_unit: Option<ModulusUnit>,
    /// Unit of the frequency column if the file has none (`--freq-unit`).
    pub freq_unit: Option<FreqUnit>,
    /// Unit of temperature columns if the file has none (`--temp-unit`).
    pub temp_unit: Option<TempUnit>,
    /// Tensile or shear when the file does not say (`--mode`).
    pub mode: Option<ModulusKind>,
    /// Columns named by the user (`--columns`, compounds.toml), for exports whose names no reader
    /// knows; empty by default.
    pub columns: ColumnMap,
    /// Poisson's ratio stated for shear ↔ tensile conversion (`--poisson`); default 0.5
    /// (incompressible rubber, ARCHITECTURE.md conventions).
    pub poisson: f64,
    /// Isotherm split settings.
    pub split: SplitSettings,
    /// Check settings.
    pub checks: CheckSettings,
}

impl Default for IngestOptions {
    fn default() -> Self {
        IngestOptions {
            format: None,
            modulus_unit: None,
            freq_unit: None,
            temp_unit: None,
            mode: None,
            columns: ColumnMap::default(),
            poisson: 0.5,
            split: SplitSettings::default(),
            checks: CheckSettings::default(),
        }
    }
}

impl IngestOptions {
    /// Set a unit from its text: `which` is `modulus`, `freq` or `temp`. The error lists the
    /// units known (the caller names its key or flag before it).
    pub fn set_unit(&mut self, which: &str, text: &str) -> Result<(), String> {
        use super::units::{FREQ_UNITS, MODULUS_UNITS, TEMP_UNITS};
        let none = |known: &str| format!("`{text}`: expected one of {known}");
        match which {
            "modulus" => {
                self.modulus_unit =
                    Some(ModulusUnit::parse(text).ok_or_else(|| none(MODULUS_UNITS))?)
            }
            "freq" => self.freq_unit = Some(FreqUnit::parse(text).ok_or_else(|| none(FREQ_UNITS))?),
            "temp" => self.temp_unit = Some(TempUnit::parse(text).ok_or_else(|| none(TEMP_UNITS))?),
            _ => return Err(format!("{which}: not a unit (modulus, freq or temp)")),
        }
        Ok(())
    }

    fn validate(&self) -> Result<(), DmaError> {
        // ν of an isotropic stable solid lies in (−1, 0.5].
        if !(self.poisson > -1.0 && self.poisson <= 0.5) {
            return Err(DmaError::Setting {
                field: "poisson".into(),
                value: self.poisson.to_string(),
                reason: "Poisson's ratio must lie in (−1, 0.5]".into(),
            });
        }
        if self.checks.outlier_log10.is_nan() || self.checks.outlier_log10 <= 0.0 {
            return Err(DmaError::Setting {
                field: "outlier_log10".into(),
                value: self.checks.outlier_log10.to_string(),
                reason: "must be positive".into(),
            });
        }
        Ok(())
    }
}

/// SHA-256 of bytes, lower-case hex.
pub fn sha256_hex(bytes: &[u8]) -> String {
    let d = Sha256::digest(bytes);
    d.iter().map(|b| format!("{b:02x}")).collect()
}

/// Read one or more export files into one measurement.
pub fn read_files<P: AsRef<std::path::Path>>(
    paths: &[P],
    opts: &IngestOptions,
) -> Result<Measurement, DmaError> {
    let mut inputs = Vec::with_capacity(paths.len());
    for p in paths {
        let name = p.as_ref().display().to_string();
        let bytes = crate::fsutil::read_regular(p.as_ref(), crate::limits::INPUT_BYTES_MAX)
            .map_err(|source| DmaError::Io {
                file: name.clone(),
                source,
            })?;
        inputs.push((name, bytes));
    }
    read_bytes(&inputs, opts)
}

/// Read files already in memory, each as (name, bytes).
pub fn read_bytes(
    inputs: &[(String, Vec<u8>)],
    opts: &IngestOptions,
) -> Result<Measurement, DmaError> {
    opts.validate()?;
    if inputs.is_empty() {
        return Err(DmaError::NoFiles);
    }
    let mut m = Measurement {
        sources: Vec::new(),
        kind: ModulusKind::Tensile,
        poisson: opts.poisson,
        isotherms: Vec::new(),
        warnings: Vec::new(),
        issues: Vec::new(),
        summary: Default::default(),
    };
    let mut kind: Option<(ModulusKind, String)> = None;
    for (si, (name, bytes)) in inputs.iter().enumerate() {
        let (format, raw, encoding) = parse_one(name, bytes, opts)?;
        let mapped = columns::map_file(name, &raw, opts)?;
        for n in raw.notes.iter().chain(&mapped.notes) {
            m.warnings.push(format!("{name}: {n}"));
        }
        one_mode(&mut kind, name, mapped.kind)?;
        let name_temp = isotherms::temperature_from_file_name(name);
        let mut points = mapped.points;
        temperatures_from_name(name, name_temp, &mut points, &mut m.warnings)?;
        let labels: Vec<Option<String>> = raw.blocks.iter().map(|b| b.label.clone()).collect();
        m.isotherms
            .extend(file_isotherms(points, name_temp, si, &labels, opts));
        let mut metadata = raw.metadata;
        metadata.insert("mode evidence".into(), mapped.mode_evidence.clone());
        m.sources.push(SourceFile {
            path: name.clone(),
            sha256: sha256_hex(bytes),
            format: format.name().to_string(),
            metadata,
            encoding: encoding.to_string(),
            columns: mapped.columns,
        });
    }
    m.kind = kind.map(|k| k.0).unwrap_or_default();
    snap_nominals_to_step_grid(&mut m.isotherms);
    // In order of temperature (stable: equal temperatures keep file order).
    m.isotherms
        .sort_by(|a, b| a.temp_mean_c.total_cmp(&b.temp_mean_c));
    checks::run(&mut m, &opts.checks);
    super::plausible::check(&mut m)?;
    Ok(m)
}

/// Every file must hold the same kind of modulus as the first (`kind`: that kind and the first
/// file's name, set by the first call).
fn one_mode(
    kind: &mut Option<(ModulusKind, String)>,
    name: &str,
    found: ModulusKind,
) -> Result<(), DmaError> {
    match kind {
        Some((k, first)) if *k != found => Err(DmaError::MixedMode {
            file: name.to_string(),
            found: kind_name(found).into(),
            expected: kind_name(*k).into(),
            why: format!("{first} holds {} moduli", kind_name(*k)),
        }),
        None => {
            *kind = Some((found, name.to_string()));
            Ok(())
        }
        _ => Ok(()),
    }
}

/// A file without temperatures takes the one in its name (`name_temp`, with a warning); with
/// neither, the first point without one is an error.
fn temperatures_from_name(
    name: &str,
    name_temp: Option<f64>,
    points: &mut [RawPoint],
    warnings: &mut Vec<String>,
) -> Result<(), DmaError> {
    let no_temp = points
        .iter()
        .find(|p| p.temp_c.is_none() && p.nominal_c.is_none())
        .map(|p| p.loc.to_string());
    let Some(p) = no_temp else { return Ok(()) };
    match name_temp {
        Some(t) => {
            warnings.push(format!(
                "{name}: no temperature in the file; using {t} °C from the file name"
            ));
            for p in points.iter_mut().filter(|p| p.nominal_c.is_none()) {
                p.nominal_c = Some(t);
            }
            Ok(())
        }
        None => Err(DmaError::NoTemperature {
            file: name.to_string(),
            location: p,
        }),
    }
}

/// The isotherms of file `si`: its points split by temperature, each labelled by its first point's
/// block label, missing cells flagged.
fn file_isotherms(
    points: Vec<RawPoint>,
    name_temp: Option<f64>,
    si: usize,
    labels: &[Option<String>],
    opts: &IngestOptions,
) -> Vec<Isotherm> {
    let sheet = points.first().and_then(|p| match &p.loc {
        Loc::Row { sheet, .. } => Some(sheet.clone()),
        _ => None,
    });
    isotherms::split(points, name_temp, &opts.split)
        .into_iter()
        .map(|g| {
            let label = g
                .points
                .first()
                .and_then(|p| labels.get(p.block).cloned().flatten());
            Isotherm {
                temp_nominal_c: g.nominal_c,
                temp_mean_c: g.mean_c,
                source: si,
                points: g
                    .points
                    .into_iter()
                    .map(|p| DataPoint {
                        freq_hz: p.freq_hz,
                        storage_pa: p.storage_pa,
                        loss_pa: p.loss_pa,
                        temp_c: p.temp_c,
                        line: p.loc.number(),
                        flags: if p.missing.is_empty() {
                            Vec::new()
                        } else {
                            vec![checks::Flag::Missing.as_str().to_string()]
                        },
                    })
                    .collect(),
                nominal_source: g.nominal_source.to_string(),
                sheet: sheet.clone(),
                label,
            }
        })
        .collect()
}

/// Nominals from rounded means only: snap them to the step grid of all isotherms.
fn snap_nominals_to_step_grid(isos: &mut [Isotherm]) {
    if isos.iter().all(|i| i.nominal_source == "rounded mean") {
        let means: Vec<f64> = isos.iter().map(|i| i.temp_mean_c).collect();
        if let Some(grid) = isotherms::step_grid(&means) {
            for iso in isos.iter_mut() {
                iso.temp_nominal_c = isotherms::on_grid(iso.temp_mean_c, grid);
                iso.nominal_source = "step grid".into();
            }
        }
    }
}

fn parse_one(
    name: &str,
    bytes: &[u8],
    opts: &IngestOptions,
) -> Result<(Format, RawFile, &'static str), DmaError> {
    let excel = detect::is_ole2(bytes) || detect::is_zip(bytes);
    if excel {
        let f = opts.format.unwrap_or(Format::Eplexor);
        if f != Format::Eplexor {
            return Err(DmaError::UnknownFormat {
                file: name.into(),
                reason: format!("an Excel workbook cannot be read as `{}`", f.name()),
            });
        }
        return Ok((f, eplexor::read(name, bytes)?, "Excel"));
    }
    if bytes.is_empty() {
        return Err(DmaError::NoData {
            file: name.into(),
            reason: "the file is empty".into(),
        });
    }
    let decoded = text::decode(bytes);
    let format = opts
        .format
        .unwrap_or_else(|| detect::detect(bytes, &decoded.text));
    let t = decoded.text.as_str();
    let raw = match format {
        Format::Eplexor => {
            return Err(DmaError::UnknownFormat {
                file: name.into(),
                reason: "`eplexor` needs an Excel workbook (.xls or .xlsx); this is text".into(),
            })
        }
        Format::TriosLims => trios::read_lims(name, t)?,
        Format::TriosText => trios::read_text(name, t)?,
        Format::Rheocompass => rheocompass::read(name, t)?,
        Format::Proteus => proteus::read(name, t)?,
        Format::Reptate => reptate::read(name, t)?,
        Format::Generic => generic::read(name, t)?,
    };
    let mut raw = raw;
    drop_rows_without_numbers(&mut raw, t);
    note_unread_lines(&mut raw, t);
    Ok((format, raw, decoded.encoding))
}

/// A row with no finite number in it is no data row, whatever the reader took it for (a stray text line
/// inside a TRIOS or Proteus table): it leaves the table with a note naming its line, so the rows
/// around it are read, instead of failing the file on its first text cell.
fn drop_rows_without_numbers(raw: &mut RawFile, text: &str) {
    use super::table::Cell;
    let lines: Vec<&str> = text.lines().collect();
    for b in &mut raw.blocks {
        b.rows.retain(|r| {
            if r.cells.iter().any(|c| matches!(c, Cell::Num(v) if v.is_finite())) {
                return true;
            }
            let shown: String = match r.loc {
                Loc::Line(n) => lines.get(n.wrapping_sub(1)).copied().unwrap_or(""),
                _ => "",
            }
            .chars()
            .take(40)
            .flat_map(char::escape_debug)
            .collect();
            raw.notes.push(format!(
                "{}: not a data row (\"{shown}\": no number in it), skipped; the table goes on below it",
                r.loc
            ));
            false
        });
    }
}

/// Lines inside a table that no reader took as a row (issue 28 item 6, as one mechanism for every
/// text format): between a block's first and last row, a non-blank line that is not a row of it is
/// named in a note (which reaches the warnings), unless the reader named it already. The rows
/// around it are read; nothing inside a table is skipped without a word.
fn note_unread_lines(raw: &mut RawFile, text: &str) {
    let lines: Vec<&str> = text.lines().collect();
    let mut unread = Vec::new();
    for b in &raw.blocks {
        let mut rows: Vec<usize> = b
            .rows
            .iter()
            .filter_map(|r| match r.loc {
                Loc::Line(n) => Some(n),
                _ => None,
            })
            .collect();
        rows.sort_unstable();
        let (Some(&first), Some(&last)) = (rows.first(), rows.last()) else {
            continue;
        };
        for n in first..last {
            let line = lines.get(n.wrapping_sub(1)).copied().unwrap_or("");
            if line.trim().is_empty() || rows.binary_search(&n).is_ok() {
                continue;
            }
            let named = format!("line {n}:");
            if raw.notes.iter().any(|x| x.starts_with(&named)) {
                continue;
            }
            let shown: String = line.chars().take(40).flat_map(char::escape_debug).collect();
            unread.push(format!(
                "line {n}: not a data row (\"{shown}\"), skipped; the table goes on below it"
            ));
        }
    }
    raw.notes.extend(unread);
}

impl Measurement {
    /// The same measurement as tensile moduli: shear data multiplied by 2(1 + ν) with the stated
    /// Poisson's ratio (E = 2(1 + ν) G, isotropic material); tensile data returned unchanged.
    pub fn to_tensile(&self) -> Measurement {
        let factor = self.kind.to_tensile_factor(self.poisson);
        let mut m = self.clone();
        if self.kind == ModulusKind::Shear {
            for iso in &mut m.isotherms {
                for p in &mut iso.points {
                    p.storage_pa *= factor;
                    p.loss_pa *= factor;
                }
            }
            m.kind = ModulusKind::Tensile;
            m.warnings.push(format!(
                "shear moduli converted to tensile with E = 2(1 + ν) G, ν = {}",
                self.poisson
            ));
        }
        m
    }
}
