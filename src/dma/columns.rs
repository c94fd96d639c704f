//! Gives the columns of a [`Block`] their meaning (frequency, temperature, E′/E″ or G′/G″, |E*|,
//! tan δ, phase angle, segment) from their names in English, German and French, checks and applies
//! their units, and turns rows into [`RawPoint`]s in SI (Pa, Hz, °C).
//!
//! Conversions: with |M*| and tan δ, M′ = |M*|/√(1 + tan²δ), M″ = M′·tan δ; with |M*| and the phase
//! angle δ, M′ = |M*| cos δ, M″ = |M*| sin δ; with M′ and tan δ only, M″ = M′·tan δ.

use super::column_map::{mapping_key, ColumnMap};
use super::error::DmaError;
use super::table::{Block, Cell, Loc, RawFile};
use super::units::{self, AngleUnit, FreqUnit, ModulusUnit, TempUnit};
use super::IngestOptions;
use crate::material::ModulusKind;

/// What a column holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Quantity {
    /// Frequency (Hz or rad/s by its unit).
    Freq,
    /// Measured temperature.
    Temp,
    /// Set (nominal) temperature.
    SetTemp,
    /// Storage modulus; the kind if the name says it.
    Storage(Option<ModulusKind>),
    /// Loss modulus.
    Loss(Option<ModulusKind>),
    /// Magnitude of the complex modulus.
    Complex(Option<ModulusKind>),
    /// Loss factor tan δ.
    TanDelta,
    /// Phase angle δ.
    Phase,
    /// Segment / isotherm number.
    Segment,
}

impl Quantity {
    fn words(self) -> &'static str {
        match self {
            Quantity::Freq => "frequency",
            Quantity::Temp => "temperature",
            Quantity::SetTemp => "set temperature",
            Quantity::Storage(_) => "storage modulus",
            Quantity::Loss(_) => "loss modulus",
            Quantity::Complex(_) => "complex modulus",
            Quantity::TanDelta => "tan δ",
            Quantity::Phase => "phase angle",
            Quantity::Segment => "segment",
        }
    }
}

const T: Option<ModulusKind> = Some(ModulusKind::Tensile);
const S: Option<ModulusKind> = Some(ModulusKind::Shear);

/// Names, normalised by [`normalise`], in order of preference per quantity.
fn candidates(q: Quantity) -> &'static [&'static str] {
    match q {
        Quantity::Freq => &[
            "f",
            "freq",
            "freq.",
            "frequency",
            "frequenz",
            "fréquence",
            "frequence",
            "frequency f",
            "angular frequency",
            "omega",
            "ω",
            "kreisfrequenz",
            "fréquence angulaire",
            "angular frequency ω",
            "w",
        ],
        Quantity::Temp => &[
            "T",
            "ts",
            "temp",
            "temp.",
            "temperature",
            "temperatur",
            "température",
            "temperature t",
            "sample temperature",
            "probentemperatur",
            "température échantillon",
            "t sample",
        ],
        Quantity::SetTemp => &[
            "set temperature",
            "temperature set",
            "t set",
            "tset",
            "soll-temperatur",
            "solltemperatur",
            "température de consigne",
            "nominal temperature",
        ],
        Quantity::Storage(Some(ModulusKind::Tensile)) => &[
            "e'",
            "e stor",
            "estor",
            "e storage",
            "storage modulus e'",
            "e' storage modulus",
            "tensile storage modulus",
            "speichermodul e'",
            "module de stockage e'",
            "young's storage modulus",
        ],
        Quantity::Storage(Some(ModulusKind::Shear)) => &[
            "g'",
            "g stor",
            "gstor",
            "g storage",
            "storage modulus g'",
            "g' storage modulus",
            "shear storage modulus",
            "speichermodul g'",
            "module de stockage g'",
        ],
        Quantity::Storage(None) => &[
            "storage modulus",
            "speichermodul",
            "module de stockage",
            "module de conservation",
        ],
        Quantity::Loss(Some(ModulusKind::Tensile)) => &[
            "e''",
            "e loss",
            "eloss",
            "loss modulus e''",
            "e'' loss modulus",
            "tensile loss modulus",
            "verlustmodul e''",
            "module de perte e''",
        ],
        Quantity::Loss(Some(ModulusKind::Shear)) => &[
            "g''",
            "g loss",
            "gloss",
            "loss modulus g''",
            "g'' loss modulus",
            "shear loss modulus",
            "verlustmodul g''",
            "module de perte g''",
        ],
        Quantity::Loss(None) => &["loss modulus", "verlustmodul", "module de perte"],
        Quantity::Complex(Some(ModulusKind::Tensile)) => &[
            "|e*|",
            "e*",
            "|e|*",
            "complex modulus e*",
            "complex modulus |e*|",
            "|e*| complex modulus",
        ],
        Quantity::Complex(Some(ModulusKind::Shear)) => &[
            "|g*|",
            "g*",
            "|g|*",
            "complex shear modulus",
            "complex modulus g*",
            "complex modulus |g*|",
            "komplexer schubmodul",
        ],
        Quantity::Complex(None) => &["complex modulus", "komplexer modul", "module complexe"],
        Quantity::TanDelta => &[
            "tan delta",
            "tan δ",
            "tanδ",
            "tan(delta)",
            "tan(δ)",
            "tan d",
            "tand",
            "tan",
            "loss factor",
            "verlustfaktor",
            "facteur de perte",
            "damping factor",
            "tan delta (-)",
        ],
        Quantity::Phase => &[
            "phase angle",
            "δ",
            "delta",
            "phasenwinkel",
            "angle de phase",
            "phase angle δ",
            "phase",
            "phase shift angle",
            "phasenverschiebungswinkel",
        ],
        Quantity::Segment => &[
            "set",
            "segment",
            "seg",
            "seg.",
            "step",
            "isotherm",
            "segment number",
        ],
    }
}

/// Lower case, one space, primes and quotes unified (`E"` → `e''`, `E_stor` → `e stor`).
pub fn normalise(name: &str) -> String {
    let mut s = String::with_capacity(name.len());
    for c in name.trim().chars() {
        match c {
            '’' | '‘' | '´' | '′' | '`' => s.push('\''),
            '″' | '“' | '”' | '"' => s.push_str("''"),
            '_' => s.push(' '),
            _ => s.extend(c.to_lowercase()),
        }
    }
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

fn name_matches(raw: &str, normalised: &str, cand: &str) -> bool {
    // Single capital letters are case-sensitive: `T` is temperature, `t` is time; `f` is frequency,
    // `F` is force.
    match cand {
        "T" => raw.trim() == "T",
        "f" => raw.trim() == "f",
        "w" => raw.trim() == "w",
        _ => normalised == cand,
    }
}

/// One resolved column, recorded in the `Measurement` for provenance.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ColumnInfo {
    /// What it holds (`frequency`, `storage modulus`, …).
    pub quantity: String,
    /// Name as written.
    pub name: String,
    /// Unit as written (or given on the command line).
    pub unit: String,
    /// 0-based column index.
    pub index: usize,
}

/// A point before isotherms are formed.
#[derive(Debug, Clone)]
pub struct RawPoint {
    /// Where it came from.
    pub loc: Loc,
    /// Index of the block in the file.
    pub block: usize,
    /// Hz.
    pub freq_hz: f64,
    /// Pa.
    pub storage_pa: f64,
    /// Pa.
    pub loss_pa: f64,
    /// Measured temperature, °C.
    pub temp_c: Option<f64>,
    /// Set temperature, °C.
    pub nominal_c: Option<f64>,
    /// Segment number from the file.
    pub segment: Option<f64>,
    /// Names of the needed columns that were empty or `---` in this row.
    pub missing: Vec<String>,
}

/// The points of one file with the columns used.
#[derive(Debug, Clone)]
pub struct Mapped {
    /// Points in file order.
    pub points: Vec<RawPoint>,
    /// Tensile or shear.
    pub kind: ModulusKind,
    /// Why tensile or shear: a column name, `--mode`, or what the file says (geometry, test name,
    /// instrument).
    pub mode_evidence: String,
    /// Columns used (from the first block).
    pub columns: Vec<ColumnInfo>,
    /// Steps skipped, each named with the reason.
    pub notes: Vec<String>,
}

struct Ctx<'a> {
    file: &'a str,
    loc: String,
    names: &'a [String],
    normalised: Vec<String>,
    units: Vec<Option<String>>,
}

struct Col {
    idx: usize,
    q: Quantity,
}

impl Ctx<'_> {
    fn find(&self, q: Quantity, used: &[usize]) -> Option<usize> {
        for cand in candidates(q) {
            for (i, n) in self.names.iter().enumerate() {
                if !used.contains(&i) && name_matches(n, &self.normalised[i], cand) {
                    return Some(i);
                }
            }
        }
        None
    }

    /// The column a user mapped by `name` (see [`ColumnMap`]).
    fn find_mapped(&self, name: &str) -> Option<usize> {
        let key = mapping_key(name);
        self.names
            .iter()
            .position(|n| n.trim() == name.trim())
            .or_else(|| self.names.iter().position(|n| mapping_key(n) == key))
    }

    fn unit_of(&self, i: usize) -> Option<&str> {
        self.units
            .get(i)
            .and_then(|u| u.as_deref())
            .filter(|u| !u.trim().is_empty())
    }

    fn missing_unit(&self, i: usize, q: Quantity, flag: &'static str) -> DmaError {
        DmaError::MissingUnit {
            file: self.file.into(),
            location: self.loc.clone(),
            column: self.names[i].clone(),
            quantity: q.words(),
            flag,
        }
    }

    fn unknown_unit(&self, i: usize, q: Quantity, unit: &str) -> DmaError {
        DmaError::UnknownUnit {
            file: self.file.into(),
            location: self.loc.clone(),
            column: self.names[i].clone(),
            quantity: q.words(),
            unit: unit.into(),
        }
    }
}

/// Resolve one unit: the file's, else the command line's; both → they must agree.
fn resolve<U: PartialEq + Copy>(
    ctx: &Ctx,
    i: usize,
    q: Quantity,
    given: Option<U>,
    parse: fn(&str) -> Option<U>,
    flag: &'static str,
) -> Result<(U, String), DmaError> {
    match (ctx.unit_of(i), given) {
        (Some(u), g) => {
            let parsed = parse(u).ok_or_else(|| ctx.unknown_unit(i, q, u))?;
            if let Some(g) = g {
                if g != parsed {
                    return Err(DmaError::UnitConflict {
                        file: ctx.file.into(),
                        location: ctx.loc.clone(),
                        column: ctx.names[i].clone(),
                        file_unit: u.into(),
                        flag,
                    });
                }
            }
            Ok((parsed, u.to_string()))
        }
        (None, Some(g)) => Ok((g, flag.to_string())),
        (None, None) => Err(ctx.missing_unit(i, q, flag)),
    }
}

/// Map every block of a file to points. In a file of several steps, a step that is not an
/// oscillatory frequency sweep (by its name, [`super::steps`]; by missing frequency or modulus
/// columns; or by a single frequency) is skipped with a note naming it; a file with no usable
/// sweep is an error that names the skipped steps.
pub fn map_file(file: &str, raw: &RawFile, opts: &IngestOptions) -> Result<Mapped, DmaError> {
    let mut points = Vec::new();
    let mut kind_seen: Option<(ModulusKind, String)> = None;
    let mut columns = Vec::new();
    let mut notes = Vec::new();
    if raw.blocks.iter().all(|b| b.rows.is_empty()) {
        return Err(DmaError::NoData {
            file: file.into(),
            reason: "a header was found but no row of numbers".into(),
        });
    }
    let several = raw.blocks.iter().filter(|b| !b.rows.is_empty()).count() > 1;
    let step_name = |bi: usize, b: &Block| {
        b.label.clone().unwrap_or_else(|| {
            format!(
                "block {} ({})",
                bi + 1,
                b.header_loc.clone().unwrap_or(Loc::File)
            )
        })
    };
    for (bi, block) in raw.blocks.iter().enumerate() {
        if block.rows.is_empty() {
            continue;
        }
        if let Some(why) = block.label.as_deref().and_then(super::steps::not_a_sweep) {
            notes.push(format!("step `{}` skipped: {why}", step_name(bi, block)));
            continue;
        }
        let before = points.len();
        let (kind, cols) = match map_block(file, bi, block, raw, opts, &mut points) {
            Ok(r) => r,
            Err(DmaError::MissingColumn { quantity, .. }) if several => {
                notes.push(format!(
                    "step `{}` skipped: no {quantity} column, not an oscillatory frequency sweep",
                    step_name(bi, block)
                ));
                continue;
            }
            Err(e) => return Err(e),
        };
        if several && block.label.is_some() {
            let f = points[before..]
                .iter()
                .map(|p| p.freq_hz)
                .filter(|f| f.is_finite() && *f > 0.0);
            let (lo, hi) = f.fold((f64::INFINITY, 0.0f64), |(a, b), v| (a.min(v), b.max(v)));
            // Under 1 % of spread: one frequency (a time, amplitude or temperature sweep).
            if hi > 0.0 && hi <= lo * 1.01 {
                points.truncate(before);
                notes.push(format!(
                    "step `{}` skipped: a single frequency ({lo:.4} Hz), not a frequency sweep",
                    step_name(bi, block)
                ));
                continue;
            }
        }
        if let Some((k, _)) = &kind_seen {
            if *k != kind.0 {
                return Err(DmaError::MixedMode {
                    file: file.into(),
                    found: kind_name(kind.0).into(),
                    expected: kind_name(*k).into(),
                    why: "an earlier block of the same file".into(),
                });
            }
        }
        if kind_seen.is_none() {
            kind_seen = Some(kind);
        }
        if columns.is_empty() {
            columns = cols;
        }
    }
    let Some((kind, mode_evidence)) = kind_seen else {
        return Err(DmaError::NoData {
            file: file.into(),
            reason: format!(
                "no usable oscillatory frequency sweep: {}",
                if notes.is_empty() {
                    "no step holds one".to_string()
                } else {
                    notes.join("; ")
                }
            ),
        });
    };
    Ok(Mapped {
        points,
        kind,
        mode_evidence,
        columns,
        notes,
    })
}

/// `tensile` or `shear`.
pub fn kind_name(k: ModulusKind) -> &'static str {
    match k {
        ModulusKind::Tensile => "tensile",
        ModulusKind::Shear => "shear",
    }
}

/// The columns found in one block, by quantity.
struct Found {
    freq: Col,
    set_temp: Option<Col>,
    temp: Option<Col>,
    segment: Option<Col>,
    source: Source,
}

/// Which pair of columns gives M′ and M″.
enum Source {
    StorageLoss(Col, Col),
    StorageTan(Col, Col),
    ComplexTan(Col, Col),
    ComplexPhase(Col, Col),
}

impl Source {
    /// The modulus columns (those that carry the kind in their names).
    fn modulus_cols(&self) -> Vec<&Col> {
        match self {
            Source::StorageLoss(a, b) => vec![a, b],
            Source::StorageTan(a, _) | Source::ComplexTan(a, _) | Source::ComplexPhase(a, _) => {
                vec![a]
            }
        }
    }

    /// (first column, second column, how the second combines with the first).
    fn parts(&self) -> (&Col, &Col, Combine) {
        match self {
            Source::StorageLoss(a, b) => (a, b, Combine::Loss),
            Source::StorageTan(a, b) => (a, b, Combine::StorageTan),
            Source::ComplexTan(a, b) => (a, b, Combine::ComplexTan),
            Source::ComplexPhase(a, b) => (a, b, Combine::ComplexPhase),
        }
    }
}

/// How (M′, M″) follow from the two modulus columns (a, b) (module docs).
#[derive(Clone, Copy)]
enum Combine {
    /// a = M′, b = M″.
    Loss,
    /// a = M′, b = tan δ.
    StorageTan,
    /// a = |M*|, b = tan δ.
    ComplexTan,
    /// a = |M*|, b = δ.
    ComplexPhase,
}

/// The units of the columns used, and the columns recorded for provenance.
struct Units {
    freq: FreqUnit,
    temp: Option<TempUnit>,
    set_temp: Option<TempUnit>,
    first: ModulusUnit,
    second: ModulusUnit,
    angle: AngleUnit,
    info: Vec<ColumnInfo>,
}

/// Map one block: find the columns, choose the modulus source, decide the kind, resolve the units,
/// convert the rows.
fn map_block(
    file: &str,
    bi: usize,
    block: &Block,
    raw: &RawFile,
    opts: &IngestOptions,
    out: &mut Vec<RawPoint>,
) -> Result<((ModulusKind, String), Vec<ColumnInfo>), DmaError> {
    let loc = block.header_loc.clone().unwrap_or(Loc::File).to_string();
    let ctx = Ctx {
        file,
        loc,
        names: &block.names,
        normalised: block.names.iter().map(|n| normalise(n)).collect(),
        units: block.units.clone(),
    };
    let found = find_columns(&ctx, block, &opts.columns)?;
    let kind = decide_kind(&ctx, &found.source, raw, opts)?;
    let units = resolve_units(&ctx, &found, opts)?;
    convert_rows(&ctx, bi, block, &found, &units, out)?;
    Ok((kind, units.info))
}

/// The columns the user mapped (`--columns`, compounds.toml), each of which must exist.
fn mapped_columns(ctx: &Ctx, map: &ColumnMap) -> Result<Vec<usize>, DmaError> {
    let mut used: Vec<usize> = Vec::new();
    for (key, name) in map.entries() {
        let i = ctx.find_mapped(name).ok_or_else(|| DmaError::Setting {
            field: format!("columns.{key}"),
            value: name.to_string(),
            reason: format!(
                "{}: {}: no column of that name; the columns are {}",
                ctx.file,
                ctx.loc,
                ctx.names
                    .iter()
                    .map(|n| format!("`{n}`"))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        })?;
        used.push(i);
    }
    Ok(used)
}

/// A quantity's column is missing: the error lists the block's columns with their units.
fn missing_column(ctx: &Ctx, block: &Block, q: &'static str, looked: &'static str) -> DmaError {
    let columns = block
        .names
        .iter()
        .zip(block.units.iter())
        .map(|(n, u)| match u {
            Some(u) if !u.is_empty() => format!("`{n}` [{u}]"),
            _ => format!("`{n}`"),
        })
        .collect::<Vec<_>>()
        .join(", ");
    DmaError::MissingColumn {
        file: ctx.file.into(),
        location: ctx.loc.clone(),
        quantity: q,
        looked_for: looked,
        columns,
    }
}

/// Two columns `a` and `b` both mean the `key` modulus.
fn duplicate_column(ctx: &Ctx, a: usize, b: usize, key: &str) -> DmaError {
    DmaError::Structure {
        file: ctx.file.into(),
        location: ctx.loc.clone(),
        message: format!(
            "two columns mean the {key} modulus: `{}` (column {}) and `{}` (column {}); pick one with --columns {key}=NAME (or `columns` in compounds.toml)",
            ctx.names[a],
            a + 1,
            ctx.names[b],
            b + 1
        ),
    }
}

/// Find the columns of each quantity (those the user mapped first, by the given name), and which
/// pair gives M′ and M″.
fn find_columns(ctx: &Ctx, block: &Block, map: &ColumnMap) -> Result<Found, DmaError> {
    let mut used = mapped_columns(ctx, map)?;
    let mapped = |name: &Option<String>, q: Quantity| {
        name.as_deref()
            .and_then(|n| ctx.find_mapped(n))
            .map(|idx| Col { idx, q })
    };
    let take = |q: Quantity, used: &mut Vec<usize>| -> Option<Col> {
        let i = ctx.find(q, used)?;
        used.push(i);
        Some(Col { idx: i, q })
    };
    let freq = mapped(&map.freq, Quantity::Freq).or_else(|| take(Quantity::Freq, &mut used));
    let set_temp =
        mapped(&map.set_temp, Quantity::SetTemp).or_else(|| take(Quantity::SetTemp, &mut used));
    let temp = mapped(&map.temp, Quantity::Temp).or_else(|| take(Quantity::Temp, &mut used));
    let segment =
        mapped(&map.segment, Quantity::Segment).or_else(|| take(Quantity::Segment, &mut used));
    // A mapped modulus column's kind comes from its name if that says it, else from the evidence.
    let kind_of = |name: &Option<String>, make: fn(Option<ModulusKind>) -> Quantity| {
        name.as_deref().and_then(|n| ctx.find_mapped(n)).map(|idx| {
            let k = [T, S]
                .into_iter()
                .find(|&k| {
                    candidates(make(k))
                        .iter()
                        .any(|c| name_matches(&ctx.names[idx], &ctx.normalised[idx], c))
                })
                .flatten();
            Col { idx, q: make(k) }
        })
    };
    let mut storage = kind_of(&map.storage, Quantity::Storage);
    let mut loss = kind_of(&map.loss, Quantity::Loss);
    let mut complex = kind_of(&map.complex, Quantity::Complex);
    for k in [T, S, None] {
        if storage.is_none() {
            storage = take(Quantity::Storage(k), &mut used);
        }
        if loss.is_none() {
            loss = take(Quantity::Loss(k), &mut used);
        }
        if complex.is_none() {
            complex = take(Quantity::Complex(k), &mut used);
        }
    }
    // A second column with the meaning of a modulus taken by name is an error, not a silent choice.
    for (col, key, given) in [
        (&storage, "storage", &map.storage),
        (&loss, "loss", &map.loss),
        (&complex, "complex", &map.complex),
    ] {
        if let (Some(c), None) = (col, given) {
            if let Some(j) = ctx.find(c.q, &used) {
                return Err(duplicate_column(ctx, c.idx, j, key));
            }
        }
    }
    let tan =
        mapped(&map.tan_delta, Quantity::TanDelta).or_else(|| take(Quantity::TanDelta, &mut used));
    let phase = mapped(&map.phase, Quantity::Phase).or_else(|| take(Quantity::Phase, &mut used));

    let missing_col = |q: &'static str, looked: &'static str| missing_column(ctx, block, q, looked);
    let freq = freq.ok_or_else(|| {
        missing_col(
            "frequency",
            "f, Freq., Frequency, Angular frequency, Frequenz, Fréquence…",
        )
    })?;
    let source = match (storage, loss, complex, tan, phase) {
        (Some(s), Some(l), _, _, _) => Source::StorageLoss(s, l),
        (Some(s), None, _, Some(t), _) => Source::StorageTan(s, t),
        (None, _, Some(c), Some(t), _) => Source::ComplexTan(c, t),
        (None, _, Some(c), None, Some(p)) => Source::ComplexPhase(c, p),
        _ => {
            return Err(missing_col(
                "modulus",
                "E′ and E″ (or G′ and G″, Storage/Loss modulus, Speichermodul/Verlustmodul, Module de stockage/de perte), or |E*| with tan δ or the phase angle",
            ))
        }
    };
    Ok(Found {
        freq,
        set_temp,
        temp,
        segment,
        source,
    })
}

/// Kind: from the names, else from --mode, else from what the file says of its test
/// ([`super::mode_evidence`]); never guessed. With the reason in words.
fn decide_kind(
    ctx: &Ctx,
    source: &Source,
    raw: &RawFile,
    opts: &IngestOptions,
) -> Result<(ModulusKind, String), DmaError> {
    let file = ctx.file;
    let modulus_cols = source.modulus_cols();
    let mut kind: Option<ModulusKind> = None;
    let mut why = String::new();
    for c in &modulus_cols {
        let k = match c.q {
            Quantity::Storage(k) | Quantity::Loss(k) | Quantity::Complex(k) => k,
            _ => None,
        };
        if let Some(k) = k {
            if kind.is_some_and(|prev| prev != k) {
                return Err(DmaError::MixedMode {
                    file: file.into(),
                    found: kind_name(k).into(),
                    expected: kind_name(kind.unwrap_or_default()).into(),
                    why: format!("column `{}`", ctx.names[c.idx]),
                });
            }
            kind = Some(k);
            why = format!("column `{}`", ctx.names[c.idx]);
        }
    }
    if let (Some(k), Some(m)) = (kind, opts.mode) {
        if k != m {
            return Err(DmaError::MixedMode {
                file: file.into(),
                found: kind_name(k).into(),
                expected: kind_name(m).into(),
                why: "--mode".into(),
            });
        }
    }
    if let Some(k) = kind {
        return Ok((k, why));
    }
    if let Some(m) = opts.mode {
        return Ok((m, "--mode".into()));
    }
    match super::mode_evidence::infer(raw, file) {
        Some(e) => Ok(e),
        None => Err(DmaError::AmbiguousMode {
            file: file.into(),
            location: ctx.loc.clone(),
            column: ctx.names[modulus_cols[0].idx].clone(),
        }),
    }
}

/// The unit of every column used: the file's, else the command line's (never guessed).
fn resolve_units(ctx: &Ctx, found: &Found, opts: &IngestOptions) -> Result<Units, DmaError> {
    let names = ctx.names;
    let (fu, fu_s) = resolve(
        ctx,
        found.freq.idx,
        Quantity::Freq,
        opts.freq_unit,
        FreqUnit::parse,
        "--freq-unit",
    )?;
    let modulus_unit = |c: &Col| {
        resolve(
            ctx,
            c.idx,
            c.q,
            opts.modulus_unit,
            ModulusUnit::parse,
            "--modulus-unit",
        )
    };
    let temp_unit = |c: &Col| {
        resolve(
            ctx,
            c.idx,
            c.q,
            opts.temp_unit,
            TempUnit::parse,
            "--temp-unit",
        )
    };
    let mut info = vec![ColumnInfo {
        quantity: "frequency".into(),
        name: names[found.freq.idx].clone(),
        unit: fu_s,
        index: found.freq.idx,
    }];
    let mut push = |c: &Col, u: String| {
        info.push(ColumnInfo {
            quantity: c.q.words().into(),
            name: names[c.idx].clone(),
            unit: u,
            index: c.idx,
        })
    };
    let temp_u = match &found.temp {
        Some(c) => {
            let (u, s) = temp_unit(c)?;
            push(c, s);
            Some(u)
        }
        None => None,
    };
    let set_u = match &found.set_temp {
        Some(c) => {
            let (u, s) = temp_unit(c)?;
            push(c, s);
            Some(u)
        }
        None => None,
    };
    if let Some(c) = &found.segment {
        push(c, String::new());
    }
    let (m1, m2, combine) = found.source.parts();
    let (mu1, s1) = modulus_unit(m1)?;
    push(m1, s1);
    let mut mu2 = mu1;
    let mut angle = AngleUnit::Radian;
    match combine {
        Combine::Loss => {
            let (u, s) = modulus_unit(m2)?;
            push(m2, s);
            mu2 = u;
        }
        Combine::StorageTan | Combine::ComplexTan => {
            if let Some(u) = ctx.unit_of(m2.idx) {
                if !units::is_dimensionless(u) {
                    return Err(ctx.unknown_unit(m2.idx, m2.q, u));
                }
            }
            push(m2, String::new());
        }
        Combine::ComplexPhase => {
            let u = ctx
                .unit_of(m2.idx)
                .ok_or_else(|| ctx.missing_unit(m2.idx, m2.q, "a unit in the file (° or rad)"))?;
            angle = AngleUnit::parse(u).ok_or_else(|| ctx.unknown_unit(m2.idx, m2.q, u))?;
            push(m2, u.to_string());
        }
    }
    Ok(Units {
        freq: fu,
        temp: temp_u,
        set_temp: set_u,
        first: mu1,
        second: mu2,
        angle,
        info,
    })
}

/// Every row of the block → a [`RawPoint`] in SI; empty rows skipped, text in a number column an
/// error, empty cells NaN and named in `missing`.
fn convert_rows(
    ctx: &Ctx,
    bi: usize,
    block: &Block,
    found: &Found,
    units: &Units,
    out: &mut Vec<RawPoint>,
) -> Result<(), DmaError> {
    let (m1, m2, combine) = found.source.parts();
    let (mu1, mu2) = (units.first, units.second);
    for row in &block.rows {
        let mut missing = Vec::new();
        let mut get = |c: &Col| -> Result<f64, DmaError> {
            match row.cells.get(c.idx).unwrap_or(&Cell::Missing) {
                Cell::Num(v) => Ok(*v),
                Cell::Missing => {
                    missing.push(block.names[c.idx].clone());
                    Ok(f64::NAN)
                }
                Cell::Text(t) => Err(DmaError::BadNumber {
                    file: ctx.file.into(),
                    location: row.loc.to_string(),
                    column: block.names[c.idx].clone(),
                    value: t.chars().take(40).collect(),
                }),
            }
        };
        let f_raw = get(&found.freq)?;
        let a = get(m1)?;
        let b = get(m2)?;
        let t = match &found.temp {
            Some(c) => Some(get(c)?),
            None => None,
        };
        let st = match &found.set_temp {
            Some(c) => Some(get(c)?),
            None => None,
        };
        let seg = match &found.segment {
            Some(c) => Some(get(c)?),
            None => None,
        };
        if missing.len() >= 3 && f_raw.is_nan() && a.is_nan() && b.is_nan() {
            // An empty row (e.g. the blank tail of a worksheet range): not a point.
            continue;
        }
        let (storage_pa, loss_pa) = match combine {
            Combine::Loss => (a * mu1.to_pa(), b * mu2.to_pa()),
            Combine::StorageTan => (a * mu1.to_pa(), a * mu1.to_pa() * b),
            Combine::ComplexTan => {
                let m = a * mu1.to_pa();
                let s = m / (1.0 + b * b).sqrt();
                (s, s * b)
            }
            Combine::ComplexPhase => {
                let m = a * mu1.to_pa();
                let d = units.angle.to_rad(b);
                (m * d.cos(), m * d.sin())
            }
        };
        let temp_c = match (t, units.temp) {
            (Some(t), Some(u)) if !t.is_nan() => Some(u.to_celsius(t)),
            _ => None,
        };
        let nominal_c = match (st, units.set_temp) {
            (Some(t), Some(u)) if !t.is_nan() => Some(u.to_celsius(t)),
            _ => block.nominal_c,
        };
        out.push(RawPoint {
            loc: row.loc.clone(),
            block: bi,
            freq_hz: units.freq.to_hz(f_raw),
            storage_pa,
            loss_pa,
            temp_c,
            nominal_c,
            segment: seg.filter(|s| !s.is_nan()),
            missing,
        });
    }
    Ok(())
}
