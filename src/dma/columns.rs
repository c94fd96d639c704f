//! Gives the columns of a [`Block`] their meaning (frequency, temperature, E′/E″ or G′/G″, |E*|,
//! tan δ, phase angle, segment) from their names in English, German and French, checks and applies
//! their units, and turns rows into [`RawPoint`]s in SI (Pa, Hz, °C).
//!
//! Conversions: with |M*| and tan δ, M′ = |M*|/√(1 + tan²δ), M″ = M′·tan δ; with |M*| and the phase
//! angle δ, M′ = |M*| cos δ, M″ = |M*| sin δ; with M′ and tan δ only, M″ = M′·tan δ.

use super::error::DmaError;
use super::table::{Block, Cell, Loc, RawFile};
use super::units::{self, AngleUnit, FreqUnit, ModulusUnit, TempUnit};
use super::IngestOptions;
use crate::ModulusKind;

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

fn name_matches(raw: &str, cand: &str) -> bool {
    // Single capital letters are case-sensitive: `T` is temperature, `t` is time; `f` is frequency,
    // `F` is force.
    match cand {
        "T" => raw.trim() == "T",
        "f" => raw.trim() == "f",
        "w" => raw.trim() == "w",
        _ => normalise(raw) == cand,
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
    /// Columns used (from the first block).
    pub columns: Vec<ColumnInfo>,
}

struct Ctx<'a> {
    file: &'a str,
    loc: String,
    names: &'a [String],
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
                if !used.contains(&i) && name_matches(n, cand) {
                    return Some(i);
                }
            }
        }
        None
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

/// Map every block of a file to points.
pub fn map_file(file: &str, raw: &RawFile, opts: &IngestOptions) -> Result<Mapped, DmaError> {
    let mut points = Vec::new();
    let mut kind_seen: Option<ModulusKind> = None;
    let mut columns = Vec::new();
    if raw.blocks.iter().all(|b| b.rows.is_empty()) {
        return Err(DmaError::NoData {
            file: file.into(),
            reason: "a header was found but no row of numbers".into(),
        });
    }
    for (bi, block) in raw.blocks.iter().enumerate() {
        if block.rows.is_empty() {
            continue;
        }
        let (kind, cols) = map_block(file, bi, block, raw, opts, &mut points)?;
        if let Some(k) = kind_seen {
            if k != kind {
                return Err(DmaError::MixedMode {
                    file: file.into(),
                    found: kind_name(kind).into(),
                    expected: kind_name(k).into(),
                    why: "an earlier block of the same file".into(),
                });
            }
        }
        kind_seen = Some(kind);
        if columns.is_empty() {
            columns = cols;
        }
    }
    Ok(Mapped {
        points,
        kind: kind_seen.unwrap_or_default(),
        columns,
    })
}

/// `tensile` or `shear`.
pub fn kind_name(k: ModulusKind) -> &'static str {
    match k {
        ModulusKind::Tensile => "tensile",
        ModulusKind::Shear => "shear",
    }
}

fn map_block(
    file: &str,
    bi: usize,
    block: &Block,
    raw: &RawFile,
    opts: &IngestOptions,
    out: &mut Vec<RawPoint>,
) -> Result<(ModulusKind, Vec<ColumnInfo>), DmaError> {
    let loc = block.header_loc.clone().unwrap_or(Loc::File).to_string();
    let ctx = Ctx {
        file,
        loc,
        names: &block.names,
        units: block.units.clone(),
    };
    let mut used: Vec<usize> = Vec::new();
    let take = |q: Quantity, used: &mut Vec<usize>| -> Option<Col> {
        let i = ctx.find(q, used)?;
        used.push(i);
        Some(Col { idx: i, q })
    };
    let freq = take(Quantity::Freq, &mut used);
    let set_temp = take(Quantity::SetTemp, &mut used);
    let temp = take(Quantity::Temp, &mut used);
    let segment = take(Quantity::Segment, &mut used);
    let mut storage = None;
    let mut loss = None;
    let mut complex = None;
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
    let tan = take(Quantity::TanDelta, &mut used);
    let phase = take(Quantity::Phase, &mut used);

    let columns_list = || {
        block
            .names
            .iter()
            .zip(block.units.iter())
            .map(|(n, u)| match u {
                Some(u) if !u.is_empty() => format!("`{n}` [{u}]"),
                _ => format!("`{n}`"),
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    let missing_col = |q: &'static str, looked: &'static str| DmaError::MissingColumn {
        file: file.into(),
        location: ctx.loc.clone(),
        quantity: q,
        looked_for: looked,
        columns: columns_list(),
    };
    let freq = freq.ok_or_else(|| {
        missing_col(
            "frequency",
            "f, Freq., Frequency, Angular frequency, Frequenz, Fréquence…",
        )
    })?;

    // Which pair of columns gives M′ and M″.
    enum Source {
        StorageLoss(Col, Col),
        StorageTan(Col, Col),
        ComplexTan(Col, Col),
        ComplexPhase(Col, Col),
    }
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
    let modulus_cols: Vec<&Col> = match &source {
        Source::StorageLoss(a, b) => vec![a, b],
        Source::StorageTan(a, _) | Source::ComplexTan(a, _) | Source::ComplexPhase(a, _) => vec![a],
    };
    // Kind: from the names, else from the format, else from --mode; never guessed.
    let mut kind: Option<ModulusKind> = None;
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
                    why: format!("column `{}`", block.names[c.idx]),
                });
            }
            kind = Some(k);
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
    let kind = match kind.or(opts.mode).or(raw.mode_hint.as_ref().map(|h| h.0)) {
        Some(k) => k,
        None => {
            return Err(DmaError::AmbiguousMode {
                file: file.into(),
                location: ctx.loc.clone(),
                column: block.names[modulus_cols[0].idx].clone(),
            })
        }
    };

    let (fu, fu_s) = resolve(
        &ctx,
        freq.idx,
        Quantity::Freq,
        opts.freq_unit,
        FreqUnit::parse,
        "--freq-unit",
    )?;
    let modulus_unit = |c: &Col| {
        resolve(
            &ctx,
            c.idx,
            c.q,
            opts.modulus_unit,
            ModulusUnit::parse,
            "--modulus-unit",
        )
    };
    let temp_unit = |c: &Col| {
        resolve(
            &ctx,
            c.idx,
            c.q,
            opts.temp_unit,
            TempUnit::parse,
            "--temp-unit",
        )
    };
    let mut info = vec![ColumnInfo {
        quantity: "frequency".into(),
        name: block.names[freq.idx].clone(),
        unit: fu_s,
        index: freq.idx,
    }];
    let mut push = |c: &Col, u: String| {
        info.push(ColumnInfo {
            quantity: c.q.words().into(),
            name: block.names[c.idx].clone(),
            unit: u,
            index: c.idx,
        })
    };
    let temp_u = match &temp {
        Some(c) => {
            let (u, s) = temp_unit(c)?;
            push(c, s);
            Some(u)
        }
        None => None,
    };
    let set_u = match &set_temp {
        Some(c) => {
            let (u, s) = temp_unit(c)?;
            push(c, s);
            Some(u)
        }
        None => None,
    };
    if let Some(c) = &segment {
        push(c, String::new());
    }
    // Modulus-producing closures: (M′, M″) from a row.
    let (m1, m2, second_kind): (&Col, &Col, u8) = match &source {
        Source::StorageLoss(a, b) => (a, b, 0),
        Source::StorageTan(a, b) => (a, b, 1),
        Source::ComplexTan(a, b) => (a, b, 2),
        Source::ComplexPhase(a, b) => (a, b, 3),
    };
    let (mu1, s1) = modulus_unit(m1)?;
    push(m1, s1);
    let mut mu2 = mu1;
    let mut angle = AngleUnit::Radian;
    match second_kind {
        0 => {
            let (u, s) = modulus_unit(m2)?;
            push(m2, s);
            mu2 = u;
        }
        1 | 2 => {
            if let Some(u) = ctx.unit_of(m2.idx) {
                if !units::is_dimensionless(u) {
                    return Err(ctx.unknown_unit(m2.idx, m2.q, u));
                }
            }
            push(m2, String::new());
        }
        _ => {
            let u = ctx
                .unit_of(m2.idx)
                .ok_or_else(|| ctx.missing_unit(m2.idx, m2.q, "a unit in the file (° or rad)"))?;
            angle = AngleUnit::parse(u).ok_or_else(|| ctx.unknown_unit(m2.idx, m2.q, u))?;
            push(m2, u.to_string());
        }
    }

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
                    file: file.into(),
                    location: row.loc.to_string(),
                    column: block.names[c.idx].clone(),
                    value: t.chars().take(40).collect(),
                }),
            }
        };
        let f_raw = get(&freq)?;
        let a = get(m1)?;
        let b = get(m2)?;
        let t = match &temp {
            Some(c) => Some(get(c)?),
            None => None,
        };
        let st = match &set_temp {
            Some(c) => Some(get(c)?),
            None => None,
        };
        let seg = match &segment {
            Some(c) => Some(get(c)?),
            None => None,
        };
        if missing.len() >= 3 && f_raw.is_nan() && a.is_nan() && b.is_nan() {
            // An empty row (e.g. the blank tail of a worksheet range): not a point.
            continue;
        }
        let (storage_pa, loss_pa) = match second_kind {
            0 => (a * mu1.to_pa(), b * mu2.to_pa()),
            1 => (a * mu1.to_pa(), a * mu1.to_pa() * b),
            2 => {
                let m = a * mu1.to_pa();
                let s = m / (1.0 + b * b).sqrt();
                (s, s * b)
            }
            _ => {
                let m = a * mu1.to_pa();
                let d = angle.to_rad(b);
                (m * d.cos(), m * d.sin())
            }
        };
        let temp_c = match (t, temp_u) {
            (Some(t), Some(u)) if !t.is_nan() => Some(u.to_celsius(t)),
            _ => None,
        };
        let nominal_c = match (st, set_u) {
            (Some(t), Some(u)) if !t.is_nan() => Some(u.to_celsius(t)),
            _ => block.nominal_c,
        };
        out.push(RawPoint {
            loc: row.loc.clone(),
            block: bi,
            freq_hz: fu.to_hz(f_raw),
            storage_pa,
            loss_pa,
            temp_c,
            nominal_c,
            segment: seg.filter(|s| !s.is_nan()),
            missing,
        });
    }
    Ok((kind, info))
}
