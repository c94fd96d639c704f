//! Errors of the `tts` stage ([`TtsError`]): bad measurements, bad settings, shifts that cannot be
//! determined. Worded for users: each names the value and the field.

use thiserror::Error;

/// What can go wrong while building a master curve.
#[derive(Debug, Error, Clone, PartialEq)]
#[non_exhaustive]
pub enum TtsError {
    /// The measurement has no isotherm with enough usable points.
    #[error(
        "the measurement has {found} usable isotherm(s); a master curve needs at least {needed}"
    )]
    TooFewIsotherms {
        /// Isotherms with enough usable points.
        found: usize,
        /// The minimum.
        needed: usize,
    },
    /// An isotherm has too few usable points (finite, positive frequency and moduli).
    #[error(
        "isotherm {index} ({temp_c} °C) has {found} usable point(s) (finite, positive freq_hz, \
         storage_pa and loss_pa at distinct frequencies); at least {needed} are needed"
    )]
    TooFewPoints {
        /// Index of the isotherm in `Measurement::isotherms`.
        index: usize,
        /// Its temperature in °C.
        temp_c: f64,
        /// Usable points found.
        found: usize,
        /// The minimum.
        needed: usize,
    },
    /// Two isotherms have the same temperature, so no shift between them is defined.
    #[error("isotherms {first} and {second} have the same temperature {temp_c} °C")]
    DuplicateTemperature {
        /// Index of the first isotherm.
        first: usize,
        /// Index of the second isotherm.
        second: usize,
        /// The shared temperature in °C.
        temp_c: f64,
    },
    /// A temperature is not finite or below absolute zero.
    #[error("{field} = {value} °C is not a usable temperature (finite, above −273.15 °C)")]
    BadTemperature {
        /// Which field.
        field: String,
        /// Its value.
        value: f64,
    },
    /// A setting is out of range.
    #[error("setting {field} = {value} is out of range: {expected}")]
    BadSetting {
        /// Which setting.
        field: &'static str,
        /// Its value, printed.
        value: String,
        /// What was expected.
        expected: &'static str,
    },
    /// Two neighbouring isotherms cannot be overlapped by any horizontal shift.
    #[error(
        "isotherms at {temp_a_c} °C and {temp_b_c} °C share no shift with at least {min_points} \
         overlapping points; give the shift law by hand (--shift wlf:C1,C2 or a table)"
    )]
    NoOverlap {
        /// Temperature of the colder isotherm in °C.
        temp_a_c: f64,
        /// Temperature of the warmer isotherm in °C.
        temp_b_c: f64,
        /// Required overlapping points.
        min_points: usize,
    },
    /// A given shift law gives no finite shift at a measured temperature.
    #[error("the given shift law gives log10 a_T = {value} at {temp_c} °C (not finite)")]
    LawNotFinite {
        /// Temperature in °C.
        temp_c: f64,
        /// The value.
        value: f64,
    },
    /// The shift law fit failed (too few temperatures, degenerate data).
    #[error("cannot fit the {law} law to the shifts: {reason}")]
    LawFit {
        /// Which law.
        law: &'static str,
        /// Why.
        reason: String,
    },
}
