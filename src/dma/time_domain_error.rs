//! Errors of the time-domain reader ([`super::time_domain`]): one enum, worded for users, naming the
//! file, the line and the column (1-based) and the offending text.

use super::error::DmaError;

/// Why relaxation or creep data could not be read.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum TimeDataError {
    /// The file could not be opened or read.
    #[error("{file}: cannot read the file: {source}")]
    Io {
        /// Path as given.
        file: String,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// The table layer refused the file (no table, a header missing, …).
    #[error(transparent)]
    Table(#[from] DmaError),
    /// No table of the file holds time-domain data.
    #[error("{file}: no relaxation or creep table: {reason}")]
    NoTimeData {
        /// Path as given.
        file: String,
        /// What was looked for and what was found.
        reason: String,
    },
    /// A column the data need is not there.
    #[error("{file}:{line}: no {what} column among {found:?}")]
    MissingColumn {
        /// Path as given.
        file: String,
        /// Line of the header, 1-based.
        line: usize,
        /// `time`, `temperature`, `modulus or compliance`.
        what: &'static str,
        /// The column names found.
        found: Vec<String>,
    },
    /// A column's header carries no unit (units are never guessed).
    #[error("{file}:{line}:{column}: column `{name}` ({quantity}) carries no unit in its header; units are never guessed: write it in the name (`{name} [{example}]`) or in a unit row; accepted: {accepted}")]
    MissingUnit {
        /// Path as given.
        file: String,
        /// Line of the header, 1-based.
        line: usize,
        /// Column, 1-based.
        column: usize,
        /// Column name as written.
        name: String,
        /// What the column holds.
        quantity: &'static str,
        /// A unit the message shows as an example.
        example: &'static str,
        /// Accepted spellings.
        accepted: &'static str,
    },
    /// The time column runs on across the isotherms: elapsed time, not the time since each step.
    #[error("{file}:{line}:{column}: column `{name}` runs on from one isotherm to the next, so it is the time since the measurement started, not since each step; the time since the step is never reconstructed: export the step's (segment's, interval's) time")]
    ElapsedTime {
        /// Path as given.
        file: String,
        /// First row of the second isotherm, 1-based.
        line: usize,
        /// Column, 1-based.
        column: usize,
        /// Column name as written.
        name: String,
    },
    /// An instrument's export does not say whether it measured in tension or in shear.
    #[error("{file}:{line}:{column}: column `{name}`: the file does not say whether it was measured in tension or in shear (no measuring system, geometry, test name or #MODE line that tells, and the column is not a symbol E/G/D/J); a rotational rheometer measures in shear unless a DMA fixture is used, which is never assumed: add a `mode: shear` (or `mode: tensile`) line to the header, or export the test with its measuring system")]
    NoKind {
        /// Path as given.
        file: String,
        /// Line of the header, 1-based.
        line: usize,
        /// Column, 1-based.
        column: usize,
        /// Column name as written.
        name: String,
    },
    /// A column's unit is not one this quantity can have.
    #[error("{file}:{line}:{column}: column `{name}` ({quantity}) has unit `{unit}`, which is not one of {accepted}")]
    UnknownUnit {
        /// Path as given.
        file: String,
        /// Line of the header, 1-based.
        line: usize,
        /// Column, 1-based.
        column: usize,
        /// Column name as written.
        name: String,
        /// What the column holds.
        quantity: &'static str,
        /// The unit as written.
        unit: String,
        /// Accepted spellings.
        accepted: &'static str,
    },
    /// Both a modulus and a compliance column: which one to fit is not for this tool to guess.
    #[error("{file}:{line}: both a modulus column (`{modulus}`) and a compliance column (`{compliance}`); give a file with one of them")]
    BothModes {
        /// Path as given.
        file: String,
        /// Line of the header, 1-based.
        line: usize,
        /// The modulus column's name.
        modulus: String,
        /// The compliance column's name.
        compliance: String,
    },
    /// A cell that must be a positive finite number is not.
    #[error("{file}:{line}:{column}: {quantity} `{value}` is not a positive finite number")]
    BadCell {
        /// Path as given.
        file: String,
        /// Line, 1-based.
        line: usize,
        /// Column, 1-based.
        column: usize,
        /// What the column holds.
        quantity: &'static str,
        /// The cell as read.
        value: String,
    },
    /// Files or tables of one data set disagree on what they hold.
    #[error("{file}: {what} here is {found}, but {expected} in the files before it; give one kind of data per compound")]
    Mixed {
        /// Path as given.
        file: String,
        /// `mode` or `kind`.
        what: &'static str,
        /// What this file holds.
        found: String,
        /// What the ones before it hold.
        expected: String,
    },
    /// An isotherm with too few points to shift or fit.
    #[error(
        "{file}: the isotherm at {temp_c} °C has {found} points; at least {needed} are needed"
    )]
    TooFewPoints {
        /// Path as given.
        file: String,
        /// Its temperature, °C.
        temp_c: f64,
        /// Points found.
        found: usize,
        /// Points needed.
        needed: usize,
    },
    /// A setting out of range (Poisson's ratio).
    #[error("{field} = {value}: {reason}")]
    Setting {
        /// The setting.
        field: &'static str,
        /// Its value.
        value: f64,
        /// Why it is refused.
        reason: &'static str,
    },
}
