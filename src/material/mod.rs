//! Ground floor `material`: the basics every stage shares, with no stage of its own — the modulus
//! kind ([`ModulusKind`]), the shift law a_T(T) and its evaluation at a temperature ([`ShiftLaw`],
//! [`AtTemperature`]), the Debye terms of one relaxation or retardation term (`debye`), parameter
//! checks with their typed error ([`MaterialError`]) and unit constants (`units`).
//!
//! Import rule: the stages sit on floors, and a module imports only from its own floor or below:
//!
//! ```text
//!   creep      (relaxation → creep spectrum)
//!   prony      (master curve → relaxation spectrum)
//!   tts        (measurement → master curve)
//!   dma        (files → measurement)
//!   material   (this module: imports nothing of the crate but `special`)
//! ```
//!
//! So `dma` may use `material` but not `tts`; `prony` may use `tts`, `dma` and `material` but not
//! `creep`. What two stages both need (a shift law, a check, a constant) moves down here.

mod checks;
mod debye;
mod kind;
mod shift_law;
pub(crate) mod units;

pub use checks::MaterialError;
pub(crate) use checks::{check_poisson, check_positive};
pub(crate) use debye::debye;
pub use kind::ModulusKind;
pub(crate) use shift_law::shift_at;
pub use shift_law::{AtTemperature, ShiftLaw};
pub(crate) use units::default_poisson;
pub(crate) use units::{GAS_CONSTANT_J_PER_MOL_K, ZERO_CELSIUS_K};
