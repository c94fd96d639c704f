//! The typed error of the bands stage.

use thiserror::Error;

/// Why an uncertainty band could not be computed.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum BandError {
    /// The fit's residuals are not finite (the scatter cannot be estimated).
    #[error("the scatter cannot be estimated: {0}")]
    Scatter(String),
    /// Too few replicates refitted (each failure's reason is in the message).
    #[error("only {ok} of {asked} bootstrap refits succeeded, more than a quarter failed (first failure: {first})")]
    TooFewReplicates {
        /// Succeeded.
        ok: usize,
        /// Asked for.
        asked: usize,
        /// The first failure's reason.
        first: String,
    },
    /// The band settings are out of range.
    #[error("band settings: {0}")]
    Settings(String),
}

impl BandError {
    /// The warning a fit carries when its bands could not be made, as every front end prints it
    /// (the main job, `viscoroll fit`, the Python package): one line, capped in length.
    pub fn not_computed_warning(&self) -> String {
        not_computed(self)
    }
}

/// "uncertainty bands not computed: `why`", capped to one line of `results::cap_line`'s length.
pub(crate) fn not_computed(why: &dyn std::fmt::Display) -> String {
    crate::results::cap_line(&format!("uncertainty bands not computed: {why}"))
}
