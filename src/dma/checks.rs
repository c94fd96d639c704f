//! Data checks on a [`Measurement`]: missing and NaN values, zero or negative moduli and frequencies,
//! duplicate frequencies, non-monotonic frequency within an isotherm, points far off their
//! neighbours, a single isotherm, a nominal temperature far from the measured one. Each finding is an
//! [`Issue`] naming file, line (or sheet and row) and column; flagged points stay in the measurement
//! with their [`Flag`]s, never dropped. Counts go into the [`Summary`].
//!
//! Outliers: with x = log10 f and y = log10 M′ (or M″), an interior point's residual against the
//! straight line through its two neighbours is r_i = y_i − [y_{i−1} + (y_{i+1} − y_{i−1})
//! (x_i − x_{i−1})/(x_{i+1} − x_{i−1})]. A point is an outlier when |r_i| exceeds
//! `outlier_log10` and is the largest of r_{i−1}, r_i, r_{i+1} (one bad point also disturbs the
//! residuals of its neighbours, by about half as much).

use super::{DataPoint, Isotherm, Measurement};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// The message of an outlier: the value, how far off, and a suggestion — a whole number of decades
/// off is a slipped unit or exponent, anything else a typo or a bad reading.
fn outlier_message(what: &str, value: f64, off_log10: f64, threshold: f64) -> String {
    let decades = off_log10.round();
    let hint = if decades.abs() >= 1.0 && (off_log10 - decades).abs() < 0.15 {
        format!(
            "about 10^{decades} times {}: a slipped exponent or unit in this cell? The value {:.4e} Pa would fit",
            if decades > 0.0 { "too high" } else { "too low" },
            value / 10f64.powf(decades)
        )
    } else {
        "a typo or a bad reading? Check the cell".to_string()
    };
    format!(
        "{what} {value:.4e} Pa is {off_log10:.2} decades off the line through its neighbours (threshold {threshold}): {hint}; the point is kept, flagged, and can pull the master curve and the Prony fit"
    )
}

/// What is wrong with a point, an isotherm or the measurement (serialised as snake_case strings).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Flag {
    /// A needed cell was empty or `---`.
    Missing,
    /// A value is NaN.
    NotANumber,
    /// A modulus or the frequency is zero or negative.
    NonPositive,
    /// The same frequency appears twice in one isotherm.
    DuplicateFrequency,
    /// The frequency goes against the sweep direction.
    NonMonotonic,
    /// Far off the line through its neighbours (log–log).
    Outlier,
    /// The measurement has only one isotherm (no master curve can be built).
    SingleIsotherm,
    /// The mean measured temperature is far from the nominal one.
    NominalOffset,
}

impl Flag {
    /// The string stored in [`DataPoint::flags`].
    pub fn as_str(self) -> &'static str {
        match self {
            Flag::Missing => "missing",
            Flag::NotANumber => "not_a_number",
            Flag::NonPositive => "non_positive",
            Flag::DuplicateFrequency => "duplicate_frequency",
            Flag::NonMonotonic => "non_monotonic",
            Flag::Outlier => "outlier",
            Flag::SingleIsotherm => "single_isotherm",
            Flag::NominalOffset => "nominal_offset",
        }
    }
    /// Whether the point cannot be used as it is (error) or only deserves a look (warning).
    pub fn severity(self) -> Severity {
        match self {
            Flag::Missing | Flag::NotANumber | Flag::NonPositive => Severity::Error,
            _ => Severity::Warning,
        }
    }
}

/// Error: the point (or file) cannot be used as it is; warning: worth a look.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Severity {
    /// Unusable as is.
    Error,
    /// Worth a look.
    Warning,
}

/// One finding of the checks.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Issue {
    /// Error or warning.
    pub severity: Severity,
    /// What kind.
    pub flag: Flag,
    /// File path as given (empty for the whole measurement).
    pub file: String,
    /// `line N`, `sheet `S` row N`, `isotherm at 25 °C` or `whole measurement`.
    pub location: String,
    /// Column name as written in the file (empty if none applies).
    pub column: String,
    /// The message, naming all of the above.
    pub message: String,
}

/// Counts for the report.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Summary {
    /// Input files.
    pub files: usize,
    /// Isotherms.
    pub isotherms: usize,
    /// Points (flagged ones included).
    pub points: usize,
    /// Points with at least one flag.
    pub flagged_points: usize,
    /// Issues of severity error.
    pub errors: usize,
    /// Issues of severity warning.
    pub warnings: usize,
    /// Number of issues per flag.
    pub by_flag: BTreeMap<String, usize>,
    /// Lowest and highest mean isotherm temperature, °C.
    pub temp_range_c: Option<(f64, f64)>,
    /// Lowest and highest frequency, Hz.
    pub freq_range_hz: Option<(f64, f64)>,
}

/// Settings of the checks.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct CheckSettings {
    /// Outlier threshold on the log10 residual. Default 0.3 (a factor 2): measured sweeps are smooth
    /// in log–log to a few hundredths of a decade between neighbours.
    pub outlier_log10: f64,
    /// Two frequencies closer than this relative difference are duplicates. Default 1e-9.
    pub duplicate_rel: f64,
    /// Warn when |mean measured − nominal| exceeds this (K). Default 1 K.
    pub nominal_offset_k: f64,
}

impl Default for CheckSettings {
    fn default() -> Self {
        CheckSettings {
            outlier_log10: 0.3,
            duplicate_rel: 1e-9,
            nominal_offset_k: 1.0,
        }
    }
}

fn column_name(m: &Measurement, source: usize, quantity: &str) -> String {
    m.sources
        .get(source)
        .and_then(|s| s.columns.iter().find(|c| c.quantity == quantity))
        .map(|c| c.name.clone())
        .unwrap_or_default()
}

fn location(sheet: &Option<String>, line: usize) -> String {
    match sheet {
        Some(s) => format!("sheet `{s}` row {line}"),
        None => format!("line {line}"),
    }
}

/// For each point: whether an earlier point (lower index) with a valid frequency lies within
/// `rel`·f of its frequency — the duplicate test, in O(n log n) instead of comparing every pair (a
/// 1e6-point isotherm took hours that way). Sorted by frequency, the window [f(1−rel), f(1+rel)]
/// moves monotonically, so a sliding-window minimum of the original indices answers each point: an
/// earlier twin exists iff the smallest index in its window is below its own.
fn earlier_twins(points: &[DataPoint], rel: f64) -> Vec<bool> {
    let mut order: Vec<(f64, usize)> = points
        .iter()
        .enumerate()
        .filter(|(_, p)| p.freq_hz > 0.0 && p.freq_hz.is_finite())
        .map(|(i, p)| (p.freq_hz, i))
        .collect();
    order.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    let mut out = vec![false; points.len()];
    let (mut lo, mut hi) = (0usize, 0usize);
    // indices into `order`, their original indices increasing from front to back
    let mut deque: std::collections::VecDeque<usize> = std::collections::VecDeque::new();
    for k in 0..order.len() {
        let f = order[k].0;
        while hi < order.len() && order[hi].0 - f <= rel * f {
            while deque.back().is_some_and(|&b| order[b].1 >= order[hi].1) {
                deque.pop_back();
            }
            deque.push_back(hi);
            hi += 1;
        }
        while f - order[lo].0 > rel * f {
            lo += 1;
        }
        while deque.front().is_some_and(|&d| d < lo) {
            deque.pop_front();
        }
        if let Some(&d) = deque.front() {
            out[order[k].1] = order[d].1 < order[k].1;
        }
    }
    out
}

/// Add `flag` to a point's flags unless it is there already.
fn add_point_flag(p: &mut DataPoint, flag: Flag) {
    if !p.flags.iter().any(|f| f == flag.as_str()) {
        p.flags.push(flag.as_str().to_string());
    }
}

/// Where an isotherm's findings point: its file, sheet and the column names as written, and the list
/// they are appended to.
struct Findings<'a> {
    file: String,
    sheet: Option<String>,
    col_f: String,
    col_s: String,
    col_l: String,
    col_t: String,
    issues: &'a mut Vec<Issue>,
}

impl<'a> Findings<'a> {
    /// The file, sheet and column names of isotherm `ii` of `m`.
    fn of(m: &Measurement, ii: usize, issues: &'a mut Vec<Issue>) -> Self {
        let src = m.isotherms[ii].source;
        let file = m
            .sources
            .get(src)
            .map(|s| s.path.clone())
            .unwrap_or_default();
        let either = |first: &str, second: &str| {
            let s = column_name(m, src, first);
            if s.is_empty() {
                column_name(m, src, second)
            } else {
                s
            }
        };
        Findings {
            file,
            sheet: m.isotherms[ii].sheet.clone(),
            col_f: column_name(m, src, "frequency"),
            col_s: either("storage modulus", "complex modulus"),
            col_l: either("loss modulus", "tan δ"),
            col_t: column_name(m, src, "temperature"),
            issues,
        }
    }

    /// Append one finding at `line` of `column`.
    fn push(&mut self, flag: Flag, line: usize, column: &str, what: String) {
        let file = &self.file;
        self.issues.push(Issue {
            severity: flag.severity(),
            flag,
            file: file.clone(),
            location: location(&self.sheet, line),
            column: column.to_string(),
            message: format!(
                "{file}: {}: column `{column}`: {what}",
                location(&self.sheet, line)
            ),
        });
    }
}

/// A frequency usable for the sweep checks: positive and finite.
fn valid_freq(p: &DataPoint) -> bool {
    p.freq_hz > 0.0 && p.freq_hz.is_finite()
}

/// Value checks: a missing or NaN value, a zero or negative frequency or modulus, a NaN temperature.
fn check_values(iso: &mut Isotherm, out: &mut Findings) {
    let (col_f, col_s, col_l) = (out.col_f.clone(), out.col_s.clone(), out.col_l.clone());
    for p in iso.points.iter_mut() {
        for (v, col, what) in [
            (p.freq_hz, &col_f, "frequency"),
            (p.storage_pa, &col_s, "storage modulus"),
            (p.loss_pa, &col_l, "loss modulus"),
        ] {
            if v.is_nan() {
                let missing = p.flags.iter().any(|f| f == Flag::Missing.as_str());
                if missing {
                    out.push(
                        Flag::Missing,
                        p.line,
                        col,
                        format!("{what} is missing; the point is kept, flagged `missing`"),
                    );
                } else {
                    add_point_flag(p, Flag::NotANumber);
                    out.push(
                        Flag::NotANumber,
                        p.line,
                        col,
                        format!("{what} is NaN; the point is kept, flagged `not_a_number`"),
                    );
                }
            } else if v <= 0.0 {
                add_point_flag(p, Flag::NonPositive);
                out.push(
                    Flag::NonPositive,
                    p.line,
                    col,
                    format!(
                        "{what} {v:e} is not positive; the point is kept, flagged `non_positive`"
                    ),
                );
            }
        }
        if p.temp_c.is_some_and(|t| t.is_nan()) {
            add_point_flag(p, Flag::NotANumber);
            let col_t = out.col_t.clone();
            out.push(
                Flag::NotANumber,
                p.line,
                &col_t,
                "temperature is NaN".into(),
            );
        }
    }
}

/// Sweep checks: a frequency seen earlier in the isotherm (within `duplicate_rel`), a frequency
/// against the sweep direction (set by the first and last valid frequencies).
fn check_sweep(iso: &mut Isotherm, set: &CheckSettings, out: &mut Findings) {
    let first = iso.points.iter().find(|p| valid_freq(p)).map(|p| p.freq_hz);
    let last = iso
        .points
        .iter()
        .rev()
        .find(|p| valid_freq(p))
        .map(|p| p.freq_hz);
    let ascending = match (first, last) {
        (Some(a), Some(b)) => b >= a,
        _ => true,
    };
    let has_earlier_twin = earlier_twins(&iso.points, set.duplicate_rel);
    let col_f = out.col_f.clone();
    let temp_nominal_c = iso.temp_nominal_c;
    let mut prev: Option<f64> = None;
    for (p, &dup) in iso.points.iter_mut().zip(&has_earlier_twin) {
        if !valid_freq(p) {
            continue;
        }
        let fi = p.freq_hz;
        let line = p.line;
        if dup {
            add_point_flag(p, Flag::DuplicateFrequency);
            out.push(
                Flag::DuplicateFrequency,
                line,
                &col_f,
                format!(
                    "frequency {fi} Hz appears twice in the isotherm at {:.1} °C",
                    temp_nominal_c
                ),
            );
        } else if let Some(pf) = prev {
            if (ascending && fi < pf) || (!ascending && fi > pf) {
                add_point_flag(p, Flag::NonMonotonic);
                out.push(Flag::NonMonotonic, line, &col_f, format!("frequency {fi} Hz after {pf} Hz goes against the sweep of the isotherm at {:.1} °C", temp_nominal_c));
            }
        }
        prev = Some(fi);
    }
}

/// Outliers (the residual rule of the module doc), on points with positive finite values only and
/// not flagged as duplicates.
fn check_outliers(iso: &mut Isotherm, set: &CheckSettings, out: &mut Findings) {
    let n = iso.points.len();
    let idx: Vec<usize> = (0..n)
        .filter(|&i| {
            let p = &iso.points[i];
            valid_freq(p)
                && p.storage_pa > 0.0
                && p.loss_pa > 0.0
                && p.storage_pa.is_finite()
                && p.loss_pa.is_finite()
                && !p
                    .flags
                    .iter()
                    .any(|f| f == Flag::DuplicateFrequency.as_str())
        })
        .collect();
    if idx.len() < 3 {
        return;
    }
    let (col_s, col_l) = (out.col_s.clone(), out.col_l.clone());
    for (sel, col) in [(0usize, &col_s), (1, &col_l)] {
        let y = |k: usize| {
            let p = &iso.points[idx[k]];
            if sel == 0 {
                p.storage_pa.log10()
            } else {
                p.loss_pa.log10()
            }
        };
        let x = |k: usize| iso.points[idx[k]].freq_hz.log10();
        let mut r = vec![0.0; idx.len()];
        for (k, rk) in r.iter_mut().enumerate().take(idx.len() - 1).skip(1) {
            let dx = x(k + 1) - x(k - 1);
            if dx.abs() < 1e-12 {
                continue;
            }
            let pred = y(k - 1) + (y(k + 1) - y(k - 1)) * (x(k) - x(k - 1)) / dx;
            *rk = y(k) - pred;
        }
        for k in 1..idx.len() - 1 {
            if r[k].abs() > set.outlier_log10
                && r[k].abs() >= r[k - 1].abs()
                && r[k].abs() >= r[k + 1].abs()
            {
                let p = &mut iso.points[idx[k]];
                let line = p.line;
                let value = if sel == 0 { p.storage_pa } else { p.loss_pa };
                add_point_flag(p, Flag::Outlier);
                let what = if sel == 0 {
                    "storage modulus"
                } else {
                    "loss modulus"
                };
                out.push(
                    Flag::Outlier,
                    line,
                    col,
                    outlier_message(what, value, r[k], set.outlier_log10),
                );
            }
        }
    }
}

/// The mean measured temperature against the nominal one.
fn check_nominal(iso: &Isotherm, set: &CheckSettings, out: &mut Findings) {
    if (iso.temp_mean_c - iso.temp_nominal_c).abs() > set.nominal_offset_k {
        let line = iso.points.first().map(|p| p.line).unwrap_or(0);
        let col_t = out.col_t.clone();
        out.push(
            Flag::NominalOffset,
            line,
            &col_t,
            format!(
                "mean measured temperature {:.2} °C is {:.2} K from the nominal {} °C ({})",
                iso.temp_mean_c,
                iso.temp_mean_c - iso.temp_nominal_c,
                iso.temp_nominal_c,
                iso.nominal_source
            ),
        );
    }
}

/// The counts of the summary: files, isotherms, points, flagged points, temperature and frequency
/// ranges, and the issues by severity and flag.
fn summarise(m: &Measurement, issues: &[Issue]) -> Summary {
    let mut s = Summary {
        files: m.sources.len(),
        isotherms: m.isotherms.len(),
        ..Summary::default()
    };
    for iso in &m.isotherms {
        s.points += iso.points.len();
        s.flagged_points += iso.points.iter().filter(|p| !p.flags.is_empty()).count();
        let t = iso.temp_mean_c;
        s.temp_range_c = Some(match s.temp_range_c {
            None => (t, t),
            Some((a, b)) => (a.min(t), b.max(t)),
        });
        for p in &iso.points {
            if p.freq_hz > 0.0 && p.freq_hz.is_finite() {
                let f = p.freq_hz;
                s.freq_range_hz = Some(match s.freq_range_hz {
                    None => (f, f),
                    Some((a, b)) => (a.min(f), b.max(f)),
                });
            }
        }
    }
    for i in issues {
        match i.severity {
            Severity::Error => s.errors += 1,
            Severity::Warning => s.warnings += 1,
        }
        *s.by_flag.entry(i.flag.as_str().to_string()).or_insert(0) += 1;
    }
    s
}

/// Run every check, flag points, append issues (and their messages to `warnings`), fill the summary.
pub fn run(m: &mut Measurement, set: &CheckSettings) {
    let mut issues: Vec<Issue> = Vec::new();
    for ii in 0..m.isotherms.len() {
        let mut out = Findings::of(m, ii, &mut issues);
        let iso = &mut m.isotherms[ii];
        check_values(iso, &mut out);
        check_sweep(iso, set, &mut out);
        check_outliers(iso, set, &mut out);
        check_nominal(iso, set, &mut out);
    }
    if m.isotherms.len() == 1 {
        issues.push(Issue {
            severity: Severity::Warning,
            flag: Flag::SingleIsotherm,
            file: String::new(),
            location: "whole measurement".into(),
            column: String::new(),
            message: format!(
                "only one isotherm (at {:.1} °C): a master curve needs several temperatures",
                m.isotherms[0].temp_mean_c
            ),
        });
    }
    let s = summarise(m, &issues);
    m.warnings.extend(issues.iter().map(|i| i.message.clone()));
    m.issues.extend(issues);
    m.summary = s;
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(freq_hz: f64) -> DataPoint {
        DataPoint {
            freq_hz,
            storage_pa: 1e6,
            loss_pa: 1e5,
            temp_c: None,
            line: 0,
            flags: vec![],
        }
    }

    /// The definition, pair by pair (quadratic): an earlier valid point within rel·f.
    fn pairwise(points: &[DataPoint], rel: f64) -> Vec<bool> {
        let valid = |p: &DataPoint| p.freq_hz > 0.0 && p.freq_hz.is_finite();
        (0..points.len())
            .map(|i| {
                valid(&points[i])
                    && points[..i].iter().any(|q| {
                        valid(q) && (q.freq_hz - points[i].freq_hz).abs() <= rel * points[i].freq_hz
                    })
            })
            .collect()
    }

    #[test]
    fn earlier_twins_match_the_pairwise_definition() {
        // Repeated, near-equal, invalid and unordered frequencies from a fixed pseudo-random walk.
        let mut x = 12345u64;
        for len in [0usize, 1, 2, 7, 50, 400] {
            let pts: Vec<DataPoint> = (0..len)
                .map(|_| {
                    x = x
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    let r = (x >> 33) % 40;
                    point(match r {
                        0 => f64::NAN,
                        1 => -1.0,
                        _ => 1.0 + (r / 3) as f64 * 0.1 + if r % 3 == 0 { 1e-9 } else { 0.0 },
                    })
                })
                .collect();
            for rel in [0.0, 1e-6, 0.05] {
                assert_eq!(
                    earlier_twins(&pts, rel),
                    pairwise(&pts, rel),
                    "len {len} rel {rel}"
                );
            }
        }
    }
}
