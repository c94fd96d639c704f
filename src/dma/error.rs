//! Errors of the `dma` stage: one enum, worded for users, naming the file, the place (line, or sheet
//! and row), the column or field and the offending value.

/// Why a DMA export could not be read.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum DmaError {
    /// The file could not be opened or read.
    #[error("{file}: cannot read the file: {source}")]
    Io {
        /// Path as given.
        file: String,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// The content matches none of the known exports.
    #[error("{file}: not a recognised DMA export ({reason}); choose a reader with --format")]
    UnknownFormat {
        /// Path as given.
        file: String,
        /// What was looked for.
        reason: String,
    },
    /// The file's structure is not what its format requires.
    #[error("{file}: {location}: {message}")]
    Structure {
        /// Path as given.
        file: String,
        /// `line N`, `sheet `S` row N` or `whole file`.
        location: String,
        /// What was expected and what was found.
        message: String,
    },
    /// A column that is needed has no unit, and none was given on the command line.
    #[error("{file}: {location}: column `{column}` ({quantity}) has no unit; units are never guessed: give it with {flag}")]
    MissingUnit {
        /// Path as given.
        file: String,
        /// Where the header is.
        location: String,
        /// Column name as written.
        column: String,
        /// What the column holds (e.g. `storage modulus`).
        quantity: &'static str,
        /// The command-line flag that supplies it.
        flag: &'static str,
    },
    /// A column's unit is not one this quantity can be in.
    #[error("{file}: {location}: column `{column}` ({quantity}): unknown unit `{unit}` (expected {})", expected_units(.quantity))]
    UnknownUnit {
        /// Path as given.
        file: String,
        /// Where the header is.
        location: String,
        /// Column name as written.
        column: String,
        /// What the column holds.
        quantity: &'static str,
        /// The unit as written.
        unit: String,
    },
    /// The unit given on the command line contradicts the one in the file.
    #[error("{file}: {location}: column `{column}` is in `{file_unit}` but {flag} gives another unit; units in the file are not overridden")]
    UnitConflict {
        /// Path as given.
        file: String,
        /// Where the header is.
        location: String,
        /// Column name.
        column: String,
        /// Unit written in the file.
        file_unit: String,
        /// The flag.
        flag: &'static str,
    },
    /// A quantity that is needed has no column.
    #[error("{file}: {location}: no {quantity} column (looked for {looked_for}); the columns are: {columns}")]
    MissingColumn {
        /// Path as given.
        file: String,
        /// Where the header is.
        location: String,
        /// What is missing.
        quantity: &'static str,
        /// The names tried.
        looked_for: &'static str,
        /// The columns found.
        columns: String,
    },
    /// A cell that must hold a number holds something else.
    #[error("{file}: {location}: column `{column}`: cannot read `{value}` as a number")]
    BadNumber {
        /// Path as given.
        file: String,
        /// Line, or sheet and row.
        location: String,
        /// Column name.
        column: String,
        /// The cell's text.
        value: String,
    },
    /// The header was found but no data row follows.
    #[error("{file}: no data rows ({reason})")]
    NoData {
        /// Path as given.
        file: String,
        /// What was found instead.
        reason: String,
    },
    /// The moduli are named in a way that does not say tensile or shear.
    #[error("{file}: {location}: column `{column}` does not say whether it is tensile (E) or shear (G), and the file names no geometry, test or instrument that does; give --mode tensile or --mode shear")]
    AmbiguousMode {
        /// Path as given.
        file: String,
        /// Where the header is.
        location: String,
        /// The column.
        column: String,
    },
    /// Files of one measurement disagree on tensile vs shear.
    #[error("{file}: holds {found} moduli but {expected} was expected ({why})")]
    MixedMode {
        /// Path as given.
        file: String,
        /// Kind in this file.
        found: String,
        /// Kind expected.
        expected: String,
        /// Where the expectation comes from.
        why: String,
    },
    /// No measured or nominal temperature for some points.
    #[error("{file}: {location}: no temperature: the file has no temperature column and no set temperature")]
    NoTemperature {
        /// Path as given.
        file: String,
        /// Where.
        location: String,
    },
    /// The Excel workbook could not be read.
    #[error("{file}: cannot read the Excel workbook: {reason}")]
    Excel {
        /// Path as given.
        file: String,
        /// calamine's message.
        reason: String,
    },
    /// A setting is out of range.
    #[error("invalid setting {field} = {value}: {reason}")]
    Setting {
        /// The field or flag.
        field: String,
        /// The value given.
        value: String,
        /// Why it is rejected.
        reason: String,
    },
    /// No input file was given.
    #[error("no input files")]
    NoFiles,
    /// Values no polymer DMA can give (`super::plausible`); the message names file, line and
    /// column.
    #[error("implausible data: {message}")]
    Implausible {
        /// What is impossible, where, and what to check.
        message: String,
    },
}

/// The units accepted for a quantity (words as in `UnknownUnit::quantity`).
pub(crate) fn expected_units(quantity: &str) -> &'static str {
    use super::units;
    match quantity {
        "frequency" => units::FREQ_UNITS,
        "temperature" | "set temperature" => units::TEMP_UNITS,
        "phase angle" => units::ANGLE_UNITS,
        "tan δ" => "none, -, 1",
        _ => units::MODULUS_UNITS,
    }
}
