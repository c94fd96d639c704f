//! Time-domain data: relaxation E(t) or G(t) and creep D(t) or J(t) isotherms, read from a generic
//! delimited table (columns temperature, time, modulus or compliance), a TA TRIOS text export's
//! stress-relaxation and creep steps, an Anton Paar RheoCompass export's relaxation or creep
//! intervals (`Interval Time`, `Relaxation Modulus` or `Creep Compliance`/`Nachgiebigkeit`), or a
//! Netzsch Proteus ASCII export (`##Temp./°C;Time/min;Compliance/1/MPa`) → [`TimeData`] in SI (s,
//! Pa, 1/Pa, °C). The format is told by the text (`[step]`, `#KEY:` + `##` lines, `Interval
//! data:`); an instrument's intervals without a relaxation or creep column are skipped with a note.
//! The time is the time since the step: a time-since-step column (`Step time`, `Interval Time`,
//! `Segment time`) wins over an elapsed one, and a time column that runs on from one isotherm to
//! the next is refused (never reconstructed).
//!
//! Units come from the header (in the name: `time [min]`, `E(t) (MPa)`, `J / 1/MPa`, `time_s`; or a
//! unit row); a column without one is an error naming file:line:column, never a guess. Accepted:
//! time s, ms, min, h; modulus Pa, kPa, MPa, GPa (and the other modulus spellings of
//! [`super::units::ModulusUnit`]); compliance 1/Pa, 1/kPa, 1/MPa, 1/GPa (also `Pa^-1`, `MPa-1`).
//!
//! Mode (relaxation or creep) and kind (tensile or shear) come from evidence, stated in
//! [`TimeData::evidence`]: a modulus column is relaxation, a compliance column creep; E and D
//! (Ferry's tensile creep compliance) are tensile, G and J shear, unless a metadata line
//! (`mode: tensile`) or the column name (`tensile`, `shear`) says otherwise, or the instrument says
//! (TRIOS' variables, Proteus' `#MODE`, RheoCompass' measuring system, test or device). An
//! instrument's column named by a word, not a symbol, with nothing that says tension or shear is
//! refused (a rheometer measures in shear unless a DMA fixture is used; never assumed). The isotherms are the groups of rows whose temperature stays within
//! [`SAME_ISOTHERM_K`] of the group's first row (or the TRIOS step's temperature); each nominal
//! temperature is the mean rounded to 0.1 K.

use super::table::{Block, Cell, Loc, RawFile};
pub use super::time_domain_error::TimeDataError;
use super::units::{self, ModulusUnit, TempUnit};
use super::SourceFile;
use crate::material::ModulusKind;
use serde::{Deserialize, Serialize};

/// Rows whose temperature is within this of the first row of their group are one isotherm, K.
pub const SAME_ISOTHERM_K: f64 = 1.0;
/// Points an isotherm needs (a shift needs an overlap, a fit a window).
pub const MIN_POINTS: usize = 3;

/// What the data measure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TimeMode {
    /// Relaxation modulus E(t) or G(t) after a strain step, Pa.
    Relaxation,
    /// Creep compliance D(t) or J(t) after a stress step, 1/Pa.
    Creep,
}

/// One point: time since the step and the modulus (Pa) or compliance (1/Pa).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TimePoint {
    /// Time since the step, s.
    pub time_s: f64,
    /// E(t)/G(t) in Pa, or D(t)/J(t) in 1/Pa.
    pub value: f64,
    /// Line in its file, 1-based.
    pub line: usize,
}

/// One isotherm.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TimeIsotherm {
    /// Nominal temperature, °C.
    pub temp_c: f64,
    /// Index into [`TimeData::sources`].
    pub source: usize,
    /// Points in increasing time.
    pub points: Vec<TimePoint>,
    /// The TRIOS step name, if any.
    pub label: Option<String>,
}

/// Relaxation or creep isotherms of one material, in SI.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TimeData {
    /// The files read.
    pub sources: Vec<SourceFile>,
    /// Relaxation or creep.
    pub mode: TimeMode,
    /// Tensile (E, D) or shear (G, J).
    pub kind: ModulusKind,
    /// Poisson's ratio stated for tensile ↔ shear.
    pub poisson: f64,
    /// Isotherms in increasing temperature.
    pub isotherms: Vec<TimeIsotherm>,
    /// Why the mode and kind are what they are, one line per file.
    pub evidence: Vec<String>,
    /// Steps skipped, rows repaired, conventions applied.
    pub warnings: Vec<String>,
}

impl TimeData {
    /// The symbol of the measured function: `E(t)`, `G(t)`, `D(t)` or `J(t)`.
    pub fn symbol(&self) -> &'static str {
        match (self.mode, self.kind) {
            (TimeMode::Relaxation, ModulusKind::Tensile) => "E(t)",
            (TimeMode::Relaxation, ModulusKind::Shear) => "G(t)",
            (TimeMode::Creep, ModulusKind::Tensile) => "D(t)",
            (TimeMode::Creep, ModulusKind::Shear) => "J(t)",
        }
    }
}

/// Read time-domain files (paths) as one data set.
pub fn read_time_files<P: AsRef<std::path::Path>>(
    paths: &[P],
    poisson: f64,
) -> Result<TimeData, TimeDataError> {
    let mut inputs = Vec::with_capacity(paths.len());
    for p in paths {
        let p = p.as_ref();
        let bytes =
            crate::fsutil::read_regular(p, crate::limits::INPUT_BYTES_MAX).map_err(|source| {
                TimeDataError::Io {
                    file: p.display().to_string(),
                    source,
                }
            })?;
        inputs.push((p.display().to_string(), bytes));
    }
    time_data_from_bytes(&inputs, poisson)
}

/// [`read_time_files`] on files already in memory, each as (name, bytes).
pub fn time_data_from_bytes(
    inputs: &[(String, Vec<u8>)],
    poisson: f64,
) -> Result<TimeData, TimeDataError> {
    if !(poisson > -1.0 && poisson <= 0.5) {
        return Err(TimeDataError::Setting {
            field: "poisson",
            value: poisson,
            reason: "Poisson's ratio must lie in (−1, 0.5]",
        });
    }
    let mut data: Option<TimeData> = None;
    for (si, (name, bytes)) in inputs.iter().enumerate() {
        let one = read_one(name, bytes, si, poisson)?;
        data = Some(match data {
            None => one,
            Some(mut d) => {
                if d.mode != one.mode {
                    return Err(mixed(name, "mode", one.mode, d.mode));
                }
                if d.kind != one.kind {
                    return Err(mixed(name, "kind", one.kind, d.kind));
                }
                d.sources.extend(one.sources);
                d.isotherms.extend(one.isotherms);
                d.evidence.extend(one.evidence);
                d.warnings.extend(one.warnings);
                d
            }
        });
    }
    let mut d = data.ok_or_else(|| TimeDataError::NoTimeData {
        file: String::new(),
        reason: "no files given".into(),
    })?;
    d.isotherms.sort_by(|a, b| a.temp_c.total_cmp(&b.temp_c));
    for iso in &d.isotherms {
        if iso.points.len() < MIN_POINTS {
            return Err(TimeDataError::TooFewPoints {
                file: d.sources[iso.source].path.clone(),
                temp_c: iso.temp_c,
                found: iso.points.len(),
                needed: MIN_POINTS,
            });
        }
    }
    Ok(d)
}

fn mixed(
    file: &str,
    what: &'static str,
    found: impl std::fmt::Debug,
    expected: impl std::fmt::Debug,
) -> TimeDataError {
    TimeDataError::Mixed {
        file: file.into(),
        what,
        found: format!("{found:?}").to_lowercase(),
        expected: format!("{expected:?}").to_lowercase(),
    }
}

/// Whether decoded text looks like time-domain data: a TRIOS step or a generic header naming a time
/// column and a relaxation modulus or creep compliance column (the pipeline's dispatch).
pub fn looks_like_time_data(text: &str) -> bool {
    let head: Vec<&str> = text.lines().take(60).collect();
    let lower = head.join("\n").to_lowercase();
    let trios_step =
        lower.contains("[step]") && ["relaxation", "creep"].iter().any(|w| lower.contains(w));
    // the names as written: `T` is a temperature, `t` a time (is_time_name, is_temp_name)
    let generic = head.iter().any(|l| {
        let fields: Vec<String> = l
            .split([',', ';', '\t'])
            .map(|f| units::split_name_unit(f.trim().trim_matches(['"', '\u{feff}'])).0)
            .collect();
        let lower: Vec<String> = fields.iter().map(|f| f.trim().to_lowercase()).collect();
        fields.iter().any(|f| is_time_name(f))
            && lower.iter().any(|f| value_role(f).is_some())
            && !lower
                .iter()
                .any(|f| f == "f" || f.contains("freq") || f.contains("omega"))
    });
    trios_step || generic
}

/// One file → its isotherms, with one source.
fn read_one(name: &str, bytes: &[u8], si: usize, poisson: f64) -> Result<TimeData, TimeDataError> {
    if super::detect::is_ole2(bytes) || super::detect::is_zip(bytes) {
        return Err(TimeDataError::NoTimeData {
            file: name.into(),
            reason: "a workbook; export the relaxation or creep table as CSV".into(),
        });
    }
    let decoded = super::text::decode(bytes);
    let (raw, format) = raw_table(name, &decoded.text)?;
    let mut warnings: Vec<String> = raw.notes.iter().map(|n| format!("{name}: {n}")).collect();
    let mut isotherms = Vec::new();
    let mut found: Option<(TimeMode, ModulusKind, String)> = None;
    let mut columns = Vec::new();
    for block in &raw.blocks {
        let skip = match format {
            "trios-text" => !is_time_step(block),
            "rheocompass" | "proteus" => !carries_time_data(block),
            _ => false,
        };
        if skip {
            warnings.push(format!(
                "{name}: {} `{}` holds no relaxation modulus or creep compliance against time, skipped",
                if format == "trios-text" { "step" } else { "interval" },
                block.label.as_deref().unwrap_or("?")
            ));
            continue;
        }
        let cols = block_columns(name, block, &raw, format)?;
        if let Some((mode, kind, _)) = &found {
            if *mode != cols.mode {
                return Err(mixed(name, "mode", cols.mode, mode));
            }
            if *kind != cols.kind {
                return Err(mixed(name, "kind", cols.kind, kind));
            }
        } else {
            found = Some((cols.mode, cols.kind, cols.evidence.clone()));
            columns = cols.info.clone();
        }
        isotherms.extend(block_isotherms(name, block, &cols, si)?);
    }
    let Some((mode, kind, evidence)) = found else {
        return Err(TimeDataError::NoTimeData {
            file: name.into(),
            reason: match format {
                "trios-text" => "no TRIOS step named stress relaxation or creep".into(),
                f => format!("no {f} interval with a time column and a relaxation modulus or creep compliance column"),
            },
        });
    };
    let mut metadata = raw.metadata.clone();
    metadata.insert("mode evidence".into(), evidence.clone());
    Ok(TimeData {
        sources: vec![SourceFile {
            path: name.into(),
            sha256: super::sha256_hex(bytes),
            format: format.into(),
            metadata,
            encoding: decoded.encoding.into(),
            columns,
        }],
        mode,
        kind,
        poisson,
        isotherms: merge_same_temperature(isotherms),
        evidence: vec![format!("{name}: {evidence}")],
        warnings,
    })
}

/// The file's table by the evidence its text carries: a TRIOS text export (`[step]` lines), a
/// Netzsch Proteus ASCII export (`#KEY:value` lines, a `##name/unit` header), an Anton Paar
/// RheoCompass export (`Interval data:` lines; its kind from the measuring system, test or device,
/// [`super::mode_evidence`]), else a generic delimited table.
fn raw_table(name: &str, text: &str) -> Result<(RawFile, &'static str), TimeDataError> {
    Ok(
        if text
            .lines()
            .any(|l| l.trim().eq_ignore_ascii_case("[step]"))
        {
            (super::trios::read_text(name, text)?, "trios-text")
        } else if super::proteus::looks_like(text) {
            (super::proteus::read(name, text)?, "proteus")
        } else if super::rheocompass::looks_like(text) {
            let mut raw = super::rheocompass::read(name, text)?;
            raw.mode_hint = super::mode_evidence::infer(&raw, name);
            (raw, "rheocompass")
        } else {
            (super::generic::read(name, text)?, "generic")
        },
    )
}

/// An instrument's block of time-domain data: a time column and a relaxation modulus or creep
/// compliance column, and no frequency column (a frequency sweep's interval is skipped).
fn carries_time_data(block: &Block) -> bool {
    let lower: Vec<String> = block.names.iter().map(|n| n.to_lowercase()).collect();
    block.names.iter().any(|n| is_time_name(n))
        && lower.iter().any(|n| value_role(n).is_some())
        && !lower
            .iter()
            .any(|n| n == "f" || n.contains("freq") || n.contains("omega"))
}

fn is_time_step(block: &Block) -> bool {
    let l = block.label.as_deref().unwrap_or("").to_lowercase();
    ["relaxation", "creep", "kriech", "fluage", "relaxation"]
        .iter()
        .any(|w| l.contains(w))
}

/// The meaning of a block's columns.
struct Columns {
    time: (usize, f64),
    value: (usize, f64),
    temp: Option<(usize, TempUnit)>,
    mode: TimeMode,
    kind: ModulusKind,
    evidence: String,
    info: Vec<super::ColumnInfo>,
}

/// A time column: `t` (lower case: `T` is a temperature), or a name with `time`.
fn is_time_name(name: &str) -> bool {
    let n = name.trim().to_lowercase();
    name.trim() == "t" || n.contains("time") || n.contains("zeit")
}

/// A temperature column: `T` (upper case), `temp`, `temperature…`.
fn is_temp_name(name: &str) -> bool {
    let n = name.trim().to_lowercase();
    name.trim() == "T"
        || n == "temp"
        || n.starts_with("temperature")
        || n.starts_with("temp.")
        || n.starts_with("temp ")
        || n.starts_with("temp_")
        || n == "t_c"
        || n == "temperatur"
}

/// Relaxation (modulus) or creep (compliance) column, from its name (lower case, unit split off).
fn value_role(n: &str) -> Option<TimeMode> {
    let n = n.trim();
    let symbol_is = |c: char| {
        n == c.to_string()
            || n.starts_with(&format!("{c}(t)"))
            || n.starts_with(&format!("{c}_"))
            || n.starts_with(&format!("{c} "))
    };
    if n.contains("compliance") || n.contains("nachgiebigkeit") || symbol_is('j') || symbol_is('d')
    {
        return Some(TimeMode::Creep);
    }
    // the dynamic moduli of a sweep are not E(t)
    let dynamic = [
        "storage", "loss", "complex", "speicher", "verlust", "komplex",
    ]
    .iter()
    .any(|w| n.contains(w));
    if !dynamic
        && (n.contains("modulus") || n.contains("relax") || symbol_is('e') || symbol_is('g'))
    {
        return Some(TimeMode::Relaxation);
    }
    None
}

const TIME_UNITS: &str = "s, ms, min, h";
const COMPLIANCE_UNITS: &str = "1/Pa, 1/kPa, 1/MPa, 1/GPa (also Pa^-1, MPa-1)";

fn time_factor(u: &str) -> Option<f64> {
    Some(match units::clean_unit(u).as_str() {
        "s" | "sec" | "S" => 1.0,
        "ms" => 1e-3,
        "min" => 60.0,
        "h" | "hr" => 3600.0,
        _ => return None,
    })
}

/// Factor from the written compliance unit to 1/Pa.
fn compliance_factor(u: &str) -> Option<f64> {
    let c = units::clean_unit(u);
    let m = c
        .strip_prefix("1/")
        .or_else(|| c.strip_suffix("^-1"))
        .or_else(|| c.strip_suffix("-1"))?;
    Some(1.0 / ModulusUnit::parse(m)?.to_pa())
}

/// A unit written as a snake-case suffix that [`units::split_name_unit`] does not know (`time_s`,
/// `J_1_per_MPa`).
fn snake_suffix(name: &str) -> Option<(String, String)> {
    const SUFFIXES: &[(&str, &str)] = &[
        ("_1_per_pa", "1/Pa"),
        ("_1_per_kpa", "1/kPa"),
        ("_1_per_mpa", "1/MPa"),
        ("_1_per_gpa", "1/GPa"),
        ("_per_pa", "1/Pa"),
        ("_per_mpa", "1/MPa"),
        ("_ms", "ms"),
        ("_min", "min"),
        ("_s", "s"),
        ("_h", "h"),
    ];
    let l = name.to_lowercase();
    SUFFIXES
        .iter()
        .find(|(s, _)| l.ends_with(s) && l.len() > s.len())
        .map(|(s, u)| (name[..name.len() - s.len()].to_string(), u.to_string()))
}

/// Name and unit of column `c` of `block`.
fn name_unit(block: &Block, c: usize) -> (String, Option<String>) {
    let name = block.names[c].clone();
    match block.units.get(c).cloned().flatten() {
        Some(u) => (name, Some(u)),
        None => match snake_suffix(&name) {
            Some((n, u)) => (n, Some(u)),
            None => (name, None),
        },
    }
}

/// The meaning of a block's columns: which hold time, temperature and the modulus or compliance
/// ([`column_roles`]), their units ([`column_factors`]), and tensile or shear ([`kind_evidence`]).
fn block_columns(
    file: &str,
    block: &Block,
    raw: &RawFile,
    format: &str,
) -> Result<Columns, TimeDataError> {
    let line = block.header_loc.as_ref().map_or(0, Loc::number);
    let named: Vec<(String, Option<String>)> = (0..block.names.len())
        .map(|c| name_unit(block, c))
        .collect();
    let lower: Vec<String> = named.iter().map(|(n, _)| n.to_lowercase()).collect();
    let roles = column_roles(file, line, block, &named, &lower)?;
    let (tu, tf, vq, vu, vf, temp) = column_factors(file, line, block, &named, &roles)?;
    let (time_c, value_c) = (roles.time, roles.value);
    let (kind, evidence) = kind_evidence(&lower[value_c], &block.names[value_c], roles.mode, raw)
        .or_else(|| symbol_kind(&lower[value_c], &block.names[value_c], roles.mode, format))
        .ok_or_else(|| TimeDataError::NoKind {
            file: file.into(),
            line,
            column: value_c + 1,
            name: block.names[value_c].clone(),
        })?;
    let info = [(time_c, "time", &tu), (value_c, vq, &vu)]
        .into_iter()
        .map(|(c, q, u)| super::ColumnInfo {
            name: block.names[c].clone(),
            quantity: q.into(),
            unit: u.clone(),
            index: c,
        })
        .collect();
    Ok(Columns {
        time: (time_c, tf),
        value: (value_c, vf),
        temp,
        mode: roles.mode,
        kind,
        evidence,
        info,
    })
}

/// Which columns hold what (0-based).
struct Roles {
    time: usize,
    temp: Option<usize>,
    value: usize,
    mode: TimeMode,
}

/// The time column (the time since the step — `Step time`, `Interval time`, `Segment time` — when
/// the block also has an elapsed time), the temperature column, and the one modulus or compliance
/// column (both is an error; a block without a temperature column needs the step's).
fn column_roles(
    file: &str,
    line: usize,
    block: &Block,
    named: &[(String, Option<String>)],
    lower: &[String],
) -> Result<Roles, TimeDataError> {
    let missing = |what| TimeDataError::MissingColumn {
        file: file.into(),
        line,
        what,
        found: block.names.clone(),
    };
    let since_step = |n: &str| {
        ["step", "interval", "segment"]
            .iter()
            .any(|w| n.contains(w))
    };
    let time = lower
        .iter()
        .zip(named)
        .position(|(l, (n, _))| is_time_name(n) && since_step(l))
        .or_else(|| named.iter().position(|(n, _)| is_time_name(n)))
        .ok_or_else(|| missing("time"))?;
    let temp = named.iter().position(|(n, _)| is_temp_name(n));
    let modulus = lower
        .iter()
        .position(|n| value_role(n) == Some(TimeMode::Relaxation));
    let compliance = lower
        .iter()
        .position(|n| value_role(n) == Some(TimeMode::Creep));
    let (value, mode) = match (modulus, compliance) {
        (Some(m), Some(c)) => {
            return Err(TimeDataError::BothModes {
                file: file.into(),
                line,
                modulus: block.names[m].clone(),
                compliance: block.names[c].clone(),
            })
        }
        (Some(m), None) => (m, TimeMode::Relaxation),
        (None, Some(c)) => (c, TimeMode::Creep),
        (None, None) => return Err(missing("relaxation modulus or creep compliance")),
    };
    if temp.is_none() && block.nominal_c.is_none() {
        return Err(missing("temperature"));
    }
    Ok(Roles {
        time,
        temp,
        value,
        mode,
    })
}

/// The columns' units as written and their factors to SI: (time unit, to s, value quantity, value
/// unit, to Pa or 1/Pa, temperature column and unit). A missing or unknown unit is an error naming
/// line and column.
#[allow(clippy::type_complexity)]
fn column_factors(
    file: &str,
    line: usize,
    block: &Block,
    named: &[(String, Option<String>)],
    roles: &Roles,
) -> Result<
    (
        String,
        f64,
        &'static str,
        String,
        f64,
        Option<(usize, TempUnit)>,
    ),
    TimeDataError,
> {
    let unit_of =
        |c: usize, quantity: &'static str, example: &'static str, accepted: &'static str| {
            named[c]
                .1
                .clone()
                .ok_or_else(|| TimeDataError::MissingUnit {
                    file: file.into(),
                    line,
                    column: c + 1,
                    name: block.names[c].clone(),
                    quantity,
                    example,
                    accepted,
                })
        };
    let unknown = |c: usize, quantity: &'static str, unit: &str, accepted: &'static str| {
        TimeDataError::UnknownUnit {
            file: file.into(),
            line,
            column: c + 1,
            name: block.names[c].clone(),
            quantity,
            unit: unit.into(),
            accepted,
        }
    };
    let tu = unit_of(roles.time, "time", "s", TIME_UNITS)?;
    let tf = time_factor(&tu).ok_or_else(|| unknown(roles.time, "time", &tu, TIME_UNITS))?;
    let (vq, vex, vacc) = match roles.mode {
        TimeMode::Relaxation => ("relaxation modulus", "MPa", units::MODULUS_UNITS),
        TimeMode::Creep => ("creep compliance", "1/MPa", COMPLIANCE_UNITS),
    };
    let vu = unit_of(roles.value, vq, vex, vacc)?;
    let vf = match roles.mode {
        TimeMode::Relaxation => ModulusUnit::parse(&vu).map(ModulusUnit::to_pa),
        TimeMode::Creep => compliance_factor(&vu),
    }
    .ok_or_else(|| unknown(roles.value, vq, &vu, vacc))?;
    let temp = match roles.temp {
        Some(c) => {
            let u = unit_of(c, "temperature", "°C", units::TEMP_UNITS)?;
            Some((
                c,
                TempUnit::parse(&u)
                    .ok_or_else(|| unknown(c, "temperature", &u, units::TEMP_UNITS))?,
            ))
        }
        None => None,
    };
    Ok((tu, tf, vq, vu, vf, temp))
}

/// Tensile or shear from what the file says — the column's name, a metadata line, the instrument
/// — with the sentence that says why; None when it says nothing ([`symbol_kind`] then).
fn kind_evidence(
    lower: &str,
    name: &str,
    mode: TimeMode,
    raw: &RawFile,
) -> Option<(ModulusKind, String)> {
    let meta = raw.metadata.iter().find_map(|(k, v)| {
        let (k, v) = (k.to_lowercase(), v.to_lowercase());
        (k.contains("mode") || k.contains("kind") || k.contains("geometry"))
            .then(|| {
                if v.contains("shear") || v.contains("torsion") {
                    Some(ModulusKind::Shear)
                } else if v.contains("tensile") || v.contains("tension") || v.contains("bending") {
                    Some(ModulusKind::Tensile)
                } else {
                    None
                }
            })
            .flatten()
            .map(|kd| (kd, format!("metadata `{k}: {v}`")))
    });
    let by_name = if lower.contains("shear") {
        Some((ModulusKind::Shear, format!("column `{name}` says shear")))
    } else if lower.contains("tensile") || lower.contains("young") {
        Some((
            ModulusKind::Tensile,
            format!("column `{name}` says tensile"),
        ))
    } else {
        None
    };
    let by_hint = raw
        .mode_hint
        .clone()
        .map(|(k, why)| (k, format!("the instrument: {why}")));
    let (kind, why) = by_name.or(meta).or(by_hint)?;
    Some((kind, said(mode, kind, &why)))
}

/// Tensile or shear from the column's symbol alone: G and J shear, E and D tensile (Ferry's
/// convention), and in a generic table a modulus not said to be shear is tensile. An instrument's
/// export (`rheocompass`, `proteus`) whose column is a word, not a symbol, says neither: None (a
/// rotational rheometer measures in shear unless a DMA fixture is used; never assumed).
fn symbol_kind(
    lower: &str,
    name: &str,
    mode: TimeMode,
    format: &str,
) -> Option<(ModulusKind, String)> {
    let first = lower.chars().next()?;
    let symbol = lower.len() == 1
        || [b'(', b'_', b' '].contains(&lower.as_bytes().get(1).copied().unwrap_or(b'?'));
    if matches!(format, "rheocompass" | "proteus") && !symbol {
        return None;
    }
    let (kind, why) = match first {
        'g' => (ModulusKind::Shear, format!("column `{name}` is G (shear)")),
        'j' => (
            ModulusKind::Shear,
            format!(
                "column `{name}` is J (shear creep compliance in Ferry's convention; D is tensile)"
            ),
        ),
        'd' => (
            ModulusKind::Tensile,
            format!("column `{name}` is D (tensile creep compliance in Ferry's convention)"),
        ),
        _ => (
            ModulusKind::Tensile,
            format!("column `{name}` is E or a modulus not said to be shear (tensile)"),
        ),
    };
    Some((kind, said(mode, kind, &why)))
}

/// The evidence sentence: mode, kind, and why.
fn said(mode: TimeMode, kind: ModulusKind, why: &str) -> String {
    let what = match mode {
        TimeMode::Relaxation => "relaxation (a modulus column)",
        TimeMode::Creep => "creep (a compliance column)",
    };
    format!("{what}, {}: {why}", super::columns::kind_name(kind))
}

/// The rows of a block as isotherms: consecutive rows within [`SAME_ISOTHERM_K`] of their group's
/// first row (or the whole block at the step's temperature).
fn block_isotherms(
    file: &str,
    block: &Block,
    cols: &Columns,
    si: usize,
) -> Result<Vec<TimeIsotherm>, TimeDataError> {
    let cell = |row: &super::table::Row, c: usize, quantity: &'static str, positive: bool| {
        let bad = |value: String| TimeDataError::BadCell {
            file: file.into(),
            line: row.loc.number(),
            column: c + 1,
            quantity,
            value,
        };
        match row.cells.get(c) {
            Some(Cell::Num(v)) if v.is_finite() && (!positive || *v > 0.0) => Ok(*v),
            Some(Cell::Num(v)) => Err(bad(v.to_string())),
            Some(Cell::Text(t)) => Err(bad(t.clone())),
            Some(Cell::Missing) | None => Err(bad("(empty)".into())),
        }
    };
    let mut groups: Vec<(f64, Vec<f64>, Vec<TimePoint>)> = Vec::new();
    for row in &block.rows {
        let time_s = cell(row, cols.time.0, "time", true)? * cols.time.1;
        let value = cell(row, cols.value.0, "modulus or compliance", true)? * cols.value.1;
        let temp = match cols.temp {
            Some((c, u)) => u.to_celsius(cell(row, c, "temperature", false)?),
            None => block.nominal_c.unwrap_or(f64::NAN),
        };
        let p = TimePoint {
            time_s,
            value,
            line: row.loc.number(),
        };
        match groups.last_mut() {
            Some((first, temps, pts)) if (temp - *first).abs() <= SAME_ISOTHERM_K => {
                temps.push(temp);
                pts.push(p);
            }
            _ => groups.push((temp, vec![temp], vec![p])),
        }
    }
    refuse_elapsed_time(file, block, cols, &groups)?;
    Ok(groups
        .into_iter()
        .map(|(_, temps, mut points)| {
            points.sort_by(|a, b| a.time_s.total_cmp(&b.time_s));
            let mean = temps.iter().sum::<f64>() / temps.len() as f64;
            TimeIsotherm {
                temp_c: block.nominal_c.unwrap_or((mean * 10.0).round() / 10.0),
                source: si,
                points,
                label: block.label.clone(),
            }
        })
        .collect())
}

/// A time column that runs on from one isotherm to the next (each group starting after the one
/// before it ended) is the time since the measurement started, not since each step: refused,
/// naming the first row of the second isotherm (the time since the step is never reconstructed).
fn refuse_elapsed_time(
    file: &str,
    block: &Block,
    cols: &Columns,
    groups: &[(f64, Vec<f64>, Vec<TimePoint>)],
) -> Result<(), TimeDataError> {
    let runs_on = groups.len() > 1
        && groups.windows(2).all(|w| {
            let last = w[0].2.iter().map(|p| p.time_s).fold(0.0, f64::max);
            w[1].2.first().is_some_and(|p| p.time_s > last)
        });
    match (runs_on, groups.get(1).and_then(|g| g.2.first())) {
        (true, Some(p)) => Err(TimeDataError::ElapsedTime {
            file: file.into(),
            line: p.line,
            column: cols.time.0 + 1,
            name: block.names[cols.time.0].clone(),
        }),
        _ => Ok(()),
    }
}

/// Isotherms of one file at the same nominal temperature become one.
fn merge_same_temperature(mut isos: Vec<TimeIsotherm>) -> Vec<TimeIsotherm> {
    isos.sort_by(|a, b| a.temp_c.total_cmp(&b.temp_c));
    let mut out: Vec<TimeIsotherm> = Vec::new();
    for iso in isos {
        match out.last_mut() {
            Some(last) if (last.temp_c - iso.temp_c).abs() < 1e-9 => {
                last.points.extend(iso.points);
                last.points.sort_by(|a, b| a.time_s.total_cmp(&b.time_s));
            }
            _ => out.push(iso),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str) -> Result<TimeData, TimeDataError> {
        time_data_from_bytes(&[("f.csv".into(), text.as_bytes().to_vec())], 0.5)
    }

    #[test]
    fn reads_a_generic_relaxation_table_in_its_units() {
        let d = read(
            "mode: tensile\nT [°C],time [min],E(t) [MPa]\n20,1,10\n20,2,8\n20,4,7\n40,1,6\n40.2,2,5\n40,4,4.5\n",
        )
        .unwrap();
        assert_eq!(d.mode, TimeMode::Relaxation);
        assert_eq!(d.kind, ModulusKind::Tensile);
        assert_eq!(d.isotherms.len(), 2);
        assert!((d.isotherms[1].temp_c - 40.1).abs() < 1e-9);
        let p = d.isotherms[0].points[1];
        assert_eq!((p.time_s, p.value, p.line), (120.0, 8e6, 4));
        assert!(d.evidence[0].contains("metadata"), "{:?}", d.evidence);
    }

    #[test]
    fn reads_creep_compliance_and_says_why_it_is_shear() {
        let d =
            read("temperature (K),time_s,J(t) [1/MPa]\n300,1,1\n300,10,2\n300,100,3\n").unwrap();
        assert_eq!(d.mode, TimeMode::Creep);
        assert_eq!(d.kind, ModulusKind::Shear);
        assert!(d.evidence[0].contains("Ferry"), "{:?}", d.evidence);
        assert!((d.isotherms[0].temp_c - 26.9).abs() < 1e-9);
        assert!((d.isotherms[0].points[2].value - 3e-6).abs() < 1e-18);
        let d = read("T [C],t [h],D [MPa^-1]\n0,1,1\n0,2,2\n0,3,3\n").unwrap();
        assert_eq!(
            (d.kind, d.isotherms[0].points[0].time_s),
            (ModulusKind::Tensile, 3600.0)
        );
    }

    #[test]
    fn a_header_without_units_is_refused_with_its_place() {
        let e = read("T [C],time,E(t) [MPa]\n20,1,10\n20,2,8\n20,3,7\n").unwrap_err();
        let m = e.to_string();
        assert!(
            matches!(
                e,
                TimeDataError::MissingUnit {
                    line: 1,
                    column: 2,
                    ..
                }
            ),
            "{m}"
        );
        assert!(m.starts_with("f.csv:1:2:"), "{m}");
        let e = read("T [C],time [s],E(t)\n20,1,10\n20,2,8\n20,3,7\n").unwrap_err();
        assert!(
            matches!(e, TimeDataError::MissingUnit { column: 3, .. }),
            "{e}"
        );
        let e = read("T [C],time [s],E(t) [1/MPa]\n20,1,10\n20,2,8\n20,3,7\n").unwrap_err();
        assert!(
            matches!(e, TimeDataError::UnknownUnit { column: 3, .. }),
            "{e}"
        );
        let e = read("T [C],time [fortnight],E(t) [MPa]\n20,1,10\n20,2,8\n20,3,7\n").unwrap_err();
        assert!(
            matches!(e, TimeDataError::UnknownUnit { column: 2, .. }),
            "{e}"
        );
    }

    #[test]
    fn broken_files_are_errors_not_panics() {
        let cases: &[&[u8]] = &[
            b"",
            b"\xff\xfe\x00",
            b"T [C],time [s]\n20,1\n20,2\n",
            b"T [C],time [s],E [MPa],J [1/MPa]\n20,1,1,1\n20,2,1,1\n",
            b"T [C],time [s],E [MPa]\n20,1,10\n20,-2,8\n20,3,7\n",
            b"T [C],time [s],E [MPa]\n20,1,10\n20,2,0\n20,3,7\n",
            b"T [C],time [s],E [MPa]\n20,1,10\n20,2,8\n",
            b"[step]\n",
            b"[step]\nFrequency sweep (20 \xc2\xb0C)\nAngular frequency\tStorage modulus\nrad/s\tPa\n1\t2\n",
            b"time [s],E [MPa]\n1,10\n2,8\n3,7\n",
            b"PK\x03\x04 junk",
        ];
        for (i, c) in cases.iter().enumerate() {
            let r = time_data_from_bytes(&[("f.csv".into(), c.to_vec())], 0.5);
            assert!(r.is_err(), "case {i} read: {r:?}");
        }
        // Every prefix of a good file reads or fails cleanly.
        let good = "T [C],time [s],E(t) [MPa]\n20,1,10\n20,2,8\n20,3,7\n40,1,6\n40,2,5\n40,3,4\n";
        for k in 0..good.len() {
            let _ = read(&good[..k]);
        }
    }

    #[test]
    fn reads_a_trios_stress_relaxation_step_and_skips_the_sweeps() {
        let text = "Filename\tx\n[step]\nFrequency sweep (20.0 °C)\nAngular frequency\tStorage modulus\nrad/s\tPa\n1\t2\n10\t3\n[step]\nStress Relaxation (20.0 °C)\nStep time\tRelaxation modulus\ns\tPa\n0.1\t1e6\n1\t8e5\n10\t7e5\n[step]\nStress Relaxation (40.0 °C)\nStep time\tRelaxation modulus\ns\tPa\n0.1\t6e5\n1\t5e5\n10\t4.5e5\n";
        let d = read(text).unwrap();
        assert_eq!(d.mode, TimeMode::Relaxation);
        assert_eq!(d.isotherms.len(), 2);
        assert_eq!(d.isotherms[1].temp_c, 40.0);
        assert_eq!(d.isotherms[0].points[2].value, 7e5);
        assert!(d.warnings.iter().any(|w| w.contains("Frequency sweep")));
        assert!(looks_like_time_data(text));
        assert!(!looks_like_time_data("f [Hz],E' [MPa],E'' [MPa]\n1,2,3\n"));
        // pyvisco's raw frequency data: `T` is its temperature, not a time (`run` once read it so)
        let pyvisco = "\u{feff}f,E_stor,E_loss,T,Set\nHz, MPa, MPa, C, -\n0.1,1,2,-50,0\n";
        assert!(!looks_like_time_data(pyvisco));
        assert!(looks_like_time_data("T [°C],time [s],E(t) [MPa]\n20,1,3\n"));
        assert!(looks_like_time_data("T [°C],t [s],D(t) [1/MPa]\n20,1,3\n"));
    }

    #[test]
    fn files_of_different_modes_are_not_mixed() {
        let e = time_data_from_bytes(
            &[
                (
                    "a.csv".into(),
                    b"T [C],time [s],E [MPa]\n20,1,10\n20,2,8\n20,3,7\n".to_vec(),
                ),
                (
                    "b.csv".into(),
                    b"T [C],time [s],D [1/MPa]\n20,1,1\n20,2,2\n20,3,3\n".to_vec(),
                ),
            ],
            0.5,
        )
        .unwrap_err();
        assert!(
            matches!(e, TimeDataError::Mixed { what: "mode", .. }),
            "{e}"
        );
    }
}
