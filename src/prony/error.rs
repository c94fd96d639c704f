//! Errors of the Prony fit ([`PronyError`]): bad input data or settings, worded for users.

use thiserror::Error;

/// Why a Prony fit could not be made. How a solve *ended* (solver status) is data in
/// [`crate::prony::PronyInfo`], not an error, unless no usable solution exists.
#[derive(Debug, Error, Clone, PartialEq)]
#[non_exhaustive]
pub enum PronyError {
    /// Too few master-curve points to fit anything.
    #[error("the master curve has {found} points; the Prony fit needs at least {needed}")]
    TooFewPoints {
        /// Points given.
        found: usize,
        /// Minimum needed.
        needed: usize,
    },
    /// A point has a value that cannot be used (non-finite, or not > 0).
    #[error("master-curve point {index}: {field} = {value} must be finite and > 0")]
    BadPoint {
        /// 0-based index of the point.
        index: usize,
        /// Field name (`reduced_freq_hz`, `storage_pa`, `loss_pa`).
        field: &'static str,
        /// The offending value.
        value: f64,
    },
    /// All points are at one frequency: there is no window to place relaxation times over.
    #[error("all master-curve points have the same reduced frequency {freq_hz} Hz")]
    NoFrequencyWindow {
        /// The single frequency in Hz.
        freq_hz: f64,
    },
    /// A setting or the fit it implies is beyond the work budget (crate::limits).
    #[error("Prony setting {0}")]
    Budget(#[from] crate::limits::LimitError),
    /// A setting is out of its range.
    #[error("Prony setting `{field}` = {value} is invalid: {reason}")]
    BadSetting {
        /// Setting name.
        field: &'static str,
        /// Its value.
        value: f64,
        /// What is expected.
        reason: &'static str,
    },
    /// The QP solver could not be set up or returned no usable solution.
    #[error("the Prony QP solver failed: {0}")]
    Solver(String),
    /// A Prony-term file (pyvisco's CSV, crate::prony::pyvisco_csv) cannot be read.
    #[error("{file}, line {line}: {message}")]
    TermsFile {
        /// The file.
        file: String,
        /// 1-based line.
        line: usize,
        /// What is wrong.
        message: String,
    },
}
