//! Errors of the `contact` stage, one type for every body and scheme: bad input (named field and
//! value), input outside a scheme's range, and failed computations (singular system, unbracketed
//! load, load loop not converged). Outcomes that are data (iterations, error estimates, warnings)
//! live in [`super::DimensionlessSolution`], not here.

use thiserror::Error;

/// Everything that can go wrong in the contact stage, worded for users.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ContactError {
    /// A number that must be finite and positive (or non-negative) is not.
    #[error("{field} must be {expected}, got {value}")]
    BadValue {
        /// Name of the field or argument (e.g. `radius_m`, `creep term 2: b`).
        field: String,
        /// What was expected, in words ("> 0", "≥ 0 and finite", "in [0, 0.5]").
        expected: &'static str,
        /// The value found.
        value: f64,
    },
    /// A creep term is not usable (f ≥ 0 and b > 0, both finite, are needed).
    #[error(
        "creep term {index}: strength f = {f} and rate b = {b}; need f >= 0 and b > 0, both finite"
    )]
    BadTerm {
        /// Index of the term.
        index: usize,
        /// Its f.
        f: f64,
        /// Its b.
        b: f64,
    },
    /// A quantity lies outside the range a scheme is set up for.
    #[error("{quantity} = {value:e} is outside the {scheme} scheme's range ({bound} {limit:e})")]
    OutOfRange {
        /// The scheme.
        scheme: &'static str,
        /// The quantity, as a formula (`(b + f)*lambda`).
        quantity: &'static str,
        /// Its value.
        value: f64,
        /// "at most" or "at least".
        bound: &'static str,
        /// The limit.
        limit: f64,
    },
    /// The number of intervals is too small (or absurdly large).
    #[error("number of intervals n must be between {min} and {max}, got {n}")]
    BadIntervals {
        /// Smallest accepted n.
        min: usize,
        /// Largest accepted n.
        max: usize,
        /// The n given.
        n: usize,
    },
    /// The collocation system could not be solved (singular or non-finite).
    #[error("the collocation system at lambda = {lambda:e} (n = {n}) is singular or not finite")]
    Singular {
        /// Contact length λ of the failed solve.
        lambda: f64,
        /// Number of intervals.
        n: usize,
    },
    /// No contact length brackets the prescribed load.
    #[error(
        "load N' = {load} is not bracketed: N'({lambda_lo}) = {load_lo} and N'({lambda_hi}) = {load_hi} \
         (contact length lambda in [{lambda_lo}, {lambda_hi}])"
    )]
    Unbracketed {
        /// Prescribed load N′.
        load: f64,
        /// Lower end of the last bracket tried.
        lambda_lo: f64,
        /// Upper end of the last bracket tried.
        lambda_hi: f64,
        /// N′ at `lambda_lo`.
        load_lo: f64,
        /// N′ at `lambda_hi`.
        load_hi: f64,
    },
    /// The load iteration did not reach its tolerance (`residual` NaN when the loop does not track it).
    #[error(
        "load iteration did not converge in {iterations} solves: lambda in [{lambda_lo}, {lambda_hi}], \
         relative load error {residual:e}"
    )]
    NotConverged {
        /// Solves done.
        iterations: usize,
        /// Final bracket, lower end.
        lambda_lo: f64,
        /// Final bracket, upper end.
        lambda_hi: f64,
        /// |N′(λ) − N′₀|/N′₀ at the best point.
        residual: f64,
    },
    /// A scheme not available for this input (e.g. the exact one for several terms).
    #[error("{0}")]
    Unsupported(String),
}

/// Check that `value` is finite and > 0.
pub(crate) fn positive(field: impl Into<String>, value: f64) -> Result<f64, ContactError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(ContactError::BadValue {
            field: field.into(),
            expected: "finite and > 0",
            value,
        })
    }
}

/// Check that `value` is finite and ≥ 0.
pub(crate) fn non_negative(field: impl Into<String>, value: f64) -> Result<f64, ContactError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(ContactError::BadValue {
            field: field.into(),
            expected: "finite and >= 0",
            value,
        })
    }
}
