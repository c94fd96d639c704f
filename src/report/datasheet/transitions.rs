//! The glass transition of a fit at one frequency, the three ways DMA reports give it: the peak of
//! the loss modulus E″(T), the peak of tan δ(T), and the onset of the drop of the storage modulus
//! (intersection of the glassy tangent and the tangent at the inflection of log E′(T), the
//! construction of ASTM E1640).
//!
//! Input: a [`CompoundFit`] (its relaxation spectrum shifted by its law, docs/MATH.md §5.1 and §6)
//! and a frequency; output: temperatures in °C, each `None` when the feature lies on an end of the
//! measured temperatures (no maximum or inflection inside them).

use crate::results::CompoundFit;
use std::f64::consts::PI;

/// What the scan reads at each temperature.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// Storage modulus E′ (Pa).
    Storage,
    /// Loss modulus E″ (Pa).
    Loss,
    /// tan δ = E″/E′.
    TanDelta,
}

/// `q` of the fit at `temp_c` and `freq_hz` (NaN where the shift law is undefined).
pub fn at(fit: &CompoundFit, q: Quantity, temp_c: f64, freq_hz: f64) -> f64 {
    let w = 2.0 * PI * freq_hz;
    match fit.relaxation.at_temperature(&fit.shift_law, temp_c, None) {
        Ok(a) => match q {
            Quantity::Storage => a.spectrum.storage_modulus(w),
            Quantity::Loss => a.spectrum.loss_modulus(w),
            Quantity::TanDelta => a.spectrum.tan_delta(w),
        },
        Err(_) => f64::NAN,
    }
}

/// The temperatures of the scan over the measured range: 0.1 K steps, at most 20 001 of them.
fn scan(fit: &CompoundFit) -> Option<Vec<f64>> {
    let (lo, hi) = fit.measured_range_c()?;
    let n = (((hi - lo) / 0.1).ceil() as usize).clamp(1, 20_000);
    Some(
        (0..=n)
            .map(|i| lo + (hi - lo) * i as f64 / n as f64)
            .collect(),
    )
}

/// The maximum of `q` at `freq_hz` over the measured temperatures: (°C, value), `None` when it
/// lies on an end of the range.
pub fn peak(fit: &CompoundFit, q: Quantity, freq_hz: f64) -> Option<(f64, f64)> {
    let temps = scan(fit)?;
    let mut best: Option<(usize, f64)> = None;
    for (i, &t) in temps.iter().enumerate() {
        let v = at(fit, q, t, freq_hz);
        if v.is_finite() && best.map_or(true, |(_, b)| v > b) {
            best = Some((i, v));
        }
    }
    let (i, v) = best?;
    (i > 0 && i + 1 < temps.len()).then_some((temps[i], v))
}

/// The onset of the storage modulus drop at `freq_hz` (°C): where the tangent to log10 E′(T) at
/// the lowest measured temperature (the glassy side) meets the tangent at the inflection (the
/// steepest descent); `None` when the steepest descent lies on an end of the range or the tangents
/// meet outside it.
pub(crate) fn onset(fit: &CompoundFit, freq_hz: f64) -> Option<f64> {
    let temps = scan(fit)?;
    let y: Vec<f64> = temps
        .iter()
        .map(|&t| at(fit, Quantity::Storage, t, freq_hz).log10())
        .collect();
    if temps.len() < 5 || y.iter().any(|v| !v.is_finite()) {
        return None;
    }
    // central differences inside, one-sided at the low end
    let slope = |i: usize| (y[i + 1] - y[i - 1]) / (temps[i + 1] - temps[i - 1]);
    let (mut i_min, mut s_min) = (1, slope(1));
    for i in 2..temps.len() - 1 {
        let s = slope(i);
        if s < s_min {
            (i_min, s_min) = (i, s);
        }
    }
    if i_min <= 1 || i_min + 2 >= temps.len() || s_min >= 0.0 {
        return None;
    }
    let s_g = (y[1] - y[0]) / (temps[1] - temps[0]);
    if s_g <= s_min {
        return None;
    }
    // y0 + s_g (T − T0) = y_i + s_min (T − T_i)
    let t = (y[i_min] - y[0] + s_g * temps[0] - s_min * temps[i_min]) / (s_g - s_min);
    (t > temps[0] && t < temps[i_min]).then_some(t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::datasheet::fixture::fit_with;
    use crate::{RelaxationSpectrum, ShiftLaw};

    /// A standard linear solid: E(t) = E∞ + E₁ e^(−t/τ), τ = 1 s at T_ref, under an Arrhenius law.
    fn sls(e_inf: f64, e1: f64) -> RelaxationSpectrum {
        serde_json::from_value(serde_json::json!({
            "kind": "tensile", "poisson": 0.5, "modulus_inf_pa": e_inf,
            "terms": [{"tau_s": 1.0, "modulus_pa": e1}]
        }))
        .unwrap()
    }

    const LAW: ShiftLaw = ShiftLaw::Arrhenius {
        t_ref_c: 0.0,
        activation_energy_j_per_mol: 200e3,
    };

    /// The temperature where the shift law gives log10 a_T = `l` (bisection; a_T falls with T).
    fn temp_of_log_a_t(l: f64) -> f64 {
        let (mut a, mut b) = (-100.0, 200.0);
        for _ in 0..200 {
            let m = 0.5 * (a + b);
            if LAW.log10_a_t(m) > l {
                a = m
            } else {
                b = m
            }
        }
        0.5 * (a + b)
    }

    #[test]
    fn loss_and_tan_delta_peaks_match_the_standard_linear_solid() {
        let (e_inf, e1) = (1e6, 1e8);
        let fit = fit_with(sls(e_inf, e1), LAW, (-80.0, 80.0));
        let f = 1.0;
        let w = 2.0 * PI * f;
        // E″ = E₁ωτa_T/(1+(ωτa_T)²) peaks where ω τ a_T = 1.
        let t_loss = temp_of_log_a_t(-(w * 1.0f64).log10());
        // tan δ = E₁x/(E∞(1+x²) + E₁x²), x = ωτa_T, peaks at x = √(E∞/(E∞+E₁)).
        let x = (e_inf / (e_inf + e1)).sqrt();
        let t_tan = temp_of_log_a_t((x / w).log10());
        let (tp, vp) = peak(&fit, Quantity::Loss, f).unwrap();
        // the scan's 0.1 K step bounds the error by 0.05 K (+ rounding)
        assert!((tp - t_loss).abs() < 0.06, "{tp} vs {t_loss}");
        assert!((vp - e1 / 2.0).abs() < 1e-3 * e1, "{vp}");
        let (tt, vt) = peak(&fit, Quantity::TanDelta, f).unwrap();
        assert!((tt - t_tan).abs() < 0.06, "{tt} vs {t_tan}");
        let tan_max = e1 * x / (e_inf * (1.0 + x * x) + e1 * x * x);
        assert!((vt - tan_max).abs() < 1e-4 * tan_max, "{vt} vs {tan_max}");
        // the onset of the E′ drop lies below both peaks
        let on = onset(&fit, f).unwrap();
        assert!(on < tt && on < tp, "{on}");
    }

    #[test]
    fn a_peak_on_an_end_of_the_range_is_not_reported() {
        // the loss peak at 1 Hz lies near −6 °C; a range of 20 … 80 °C only sees its tail
        let fit = fit_with(sls(1e6, 1e8), LAW, (20.0, 80.0));
        assert!(peak(&fit, Quantity::Loss, 1.0).is_none());
        assert!(onset(&fit, 1.0).is_none());
    }
}
