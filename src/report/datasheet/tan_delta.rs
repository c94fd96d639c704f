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

/// The tan δ peak at `freq_hz` over the measured temperatures, scanned in 0.1 K steps:
/// (temperature in °C, tan δ), `None` if the peak lies on an end of the range (no maximum inside).
/// The scan has at most 20 001 steps (a range wider than 2000 K is scanned more coarsely).
pub fn tan_delta_peak(fit: &CompoundFit, freq_hz: f64) -> Option<(f64, f64)> {
    let (lo, hi) = fit.measured_range_c()?;
    let n = (((hi - lo) / 0.1).ceil() as usize).min(20_000);
    let mut best: Option<(usize, f64, f64)> = None;
    for i in 0..=n {
        let t = lo + (hi - lo) * i as f64 / n.max(1) as f64;
        let v = tan_delta_at(fit, t, freq_hz);
        if v.is_finite() && best.map_or(true, |(_, _, b)| v > b) {
            best = Some((i, t, v));
        }
    }
    let (i, t, v) = best?;
    (i > 0 && i < n).then_some((t, v))
}
