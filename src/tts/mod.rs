//! Stage `tts`: time–temperature superposition. Horizontal (and optional vertical) shifts of the
//! isotherms of a [`crate::Measurement`], WLF and Arrhenius fits of log a_T → master curve and
//! `ShiftLaw` (docs/MATH.md §6).

mod assess;
mod channels;
mod clean;
mod error;
pub(crate) mod fit_laws;
mod from_reduced;
mod horizontal;
mod interp;
mod law_choice;
mod master;
pub(crate) mod point_temps;
mod point_weights;
pub(crate) mod quality;
mod quality_types;
mod settings;
mod shift;
pub(crate) mod time_shift;
pub(crate) mod vertical;

pub use error::TtsError;
#[cfg(test)]
pub(crate) use fit_laws::rereference_wlf;
pub use fit_laws::{ArrheniusFit, WlfFit};
pub use from_reduced::master_curve_from_reduced;
pub use master::{build_master_curve, IsothermShift, MasterCurve, MasterPoint, MasterQuality};
pub(crate) use point_weights::point_weights;
pub use settings::{
    LawChoice, MasterSettings, ShiftCriterion, ShiftSource, TemperatureBasis, VerticalShift,
};

#[cfg(test)]
pub(crate) use crate::material::GAS_CONSTANT_J_PER_MOL_K;
