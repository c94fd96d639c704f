//! tan δ of a fit at a temperature and frequency, and the tan δ peak over the measured temperatures.
//!
//! tan δ = E″/E′ of the relaxation spectrum (docs/MATH.md §5.1) shifted by the fit's law (docs/MATH.md
//! §6); T_g is taken, as usual for DMA, as the temperature of the tan δ peak at 1 Hz.

use crate::results::CompoundFit;
use std::f64::consts::PI;

/// tan δ of the fit at `temp_c` and `freq_hz` (NaN if the shift law is undefined there).
pub fn tan_delta_at(fit: &CompoundFit, temp_c: f64, freq_hz: f64) -> f64 {
    match fit.relaxation.at_temperature(&fit.shift_law, temp_c, None) {
        Ok(a) => a.spectrum.tan_delta(2.0 * PI * freq_hz),
        Err(_) => f64::NAN,
    }
}
