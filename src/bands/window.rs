//! The frequency-window term of a band (docs/MATH.md eq. 15.9): a point whose rolling frequency,
//! reduced to the reference temperature, lies beyond the measured master curve's frequencies reads
//! the Prony series where no data constrain it, just as a point beyond the measured temperatures
//! reads an extrapolated shift law (eq. 15.8).
//!
//! Input: a [`CompoundFit`] (its master-curve record gives the measured window, its relaxation
//! spectrum the loss modulus at the window's edge), the point's speed, the contact length of the
//! body solved (half-space or cover) and log10 a_T; output: the [`WindowExcess`] of the point (also
//! for a point inside the window's last [`RAMP_DECADES`], where the term starts), the relaxation
//! spectrum continued beyond the edge (`continued_spectrum`) whose friction, against the fit's,
//! sizes the term, and the `ramp_weight` that makes the term continuous across the edge.

use crate::prony::{RelaxationSpectrum, RelaxationTerm};
use crate::results::CompoundFit;
use serde::{Deserialize, Serialize};

/// Which end of the measured window a point's rolling frequency lies beyond.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum WindowSide {
    /// Below the lowest measured reduced frequency (longer times than measured).
    Low,
    /// Above the highest measured reduced frequency (shorter times than measured).
    High,
}

/// How far a point's rolling frequency lies beyond the measured window.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct WindowExcess {
    /// The end it lies beyond.
    pub side: WindowSide,
    /// The rolling frequency V/l reduced to the reference temperature, f·a_T, in Hz.
    pub reduced_freq_hz: f64,
    /// The window's end on that side (lowest or highest master-curve reduced frequency), in Hz.
    pub edge_hz: f64,
    /// Decades beyond that end, Δ = |log10(f_red/f_edge)| beyond it, negative inside the window
    /// (a point within [`RAMP_DECADES`] of the edge gets the term weighted by `ramp_weight`).
    pub decades: f64,
}

/// The decades of relaxation times the continuation covers beyond the point's own frequency
/// (eq. 15.9): E′ and E″ at ω feel the terms with ωτ within about a decade of 1, and a rolling
/// contact spreads its strain rates over the contact length around V/l.
pub(crate) const CONTACT_SPREAD_DECADES: f64 = 1.0;

/// The term starts this many decades inside the window's edge and rises to its full size at the
/// edge (eq. 15.9c): the last half decade is the one the edge's slope is read over, and the Prony fit
/// there is constrained by the end isotherm's last few points only (at 4 points per decade, two or
/// three), so the fit's spectrum already ends within it while the data barely say so.
pub const RAMP_DECADES: f64 = 0.5;

/// Continued terms per decade of relaxation time (the Prony grid's usual density; at two per decade
/// a flat spectrum of Maxwell terms gives E″ flat to ±5 %).
const TERMS_PER_DECADE: f64 = 2.0;

/// The edge's slope of ln E″ against ln ω is read over this many decades inside the window.
const SLOPE_DECADES: f64 = 0.5;

/// Bound on that slope: a positive spectrum's E″ rises no faster than ω¹ and falls no faster than
/// ω⁻¹ (each Maxwell term's ωτ/(1 + ω²τ²) does), so |m| ≤ 1.
const MAX_SLOPE: f64 = 1.0;

/// At the low end the relaxed modulus E∞ gives up what the continued terms add (so E′ in the
/// window is kept); it may fall to this fraction of the fit's and no further, keeping the creep
/// compliance finite: the data then say nothing of the relaxed modulus, and the term is the
/// change of F/N when it is halved.
const MIN_RELAXED_FRACTION: f64 = 0.5;

/// The measured window (lowest, highest reduced frequency of the master-curve record) in Hz;
/// `None` without finite positive points.
pub fn measured_window_hz(fit: &CompoundFit) -> Option<(f64, f64)> {
    let f = fit
        .master_curve
        .iter()
        .map(|p| p.reduced_freq_hz)
        .filter(|f| f.is_finite() && *f > 0.0);
    let (lo, hi) = f.fold((f64::INFINITY, 0.0f64), |(lo, hi), f| {
        (lo.min(f), hi.max(f))
    });
    (lo.is_finite() && hi > 0.0).then_some((lo, hi))
}

/// The point's rolling frequency V/l (Hz) reduced by its shift, f·10^(log10 a_T).
pub(crate) fn rolling_reduced_freq_hz(
    speed_m_s: f64,
    contact_length_m: f64,
    log10_a_t: f64,
) -> f64 {
    speed_m_s / contact_length_m * 10f64.powf(log10_a_t)
}

/// Where `reduced_freq_hz` lies against the nearer end of `window` (lowest, highest; Hz): beyond
/// it (Δ > 0) or inside it by less than [`RAMP_DECADES`] (−[`RAMP_DECADES`] < Δ ≤ 0); `None`
/// further inside, or when not finite.
pub fn excess(window: (f64, f64), reduced_freq_hz: f64) -> Option<WindowExcess> {
    if !(reduced_freq_hz.is_finite() && reduced_freq_hz > 0.0) {
        return None;
    }
    let (lo, hi) = window;
    // decades beyond each end (negative inside); the nearer end, i.e. the larger Δ
    let above = (reduced_freq_hz / hi).log10();
    let below = (lo / reduced_freq_hz).log10();
    let (side, edge_hz, decades) = if above >= below {
        (WindowSide::High, hi, above)
    } else {
        (WindowSide::Low, lo, below)
    };
    (decades.is_finite() && decades > -RAMP_DECADES).then_some(WindowExcess {
        side,
        reduced_freq_hz,
        edge_hz,
        decades,
    })
}

/// The weight of the term at Δ decades beyond the edge (eq. 15.9c): 0 at Δ ≤ −[`RAMP_DECADES`],
/// 1 at Δ ≥ 0, and between them the smooth step 3x² − 2x³ of x = (Δ + [`RAMP_DECADES`]) /
/// [`RAMP_DECADES`], so that the band's width has neither a step nor a kink where the term starts
/// or where it reaches its full size.
pub(crate) fn ramp_weight(decades: f64) -> f64 {
    let x = ((decades + RAMP_DECADES) / RAMP_DECADES).clamp(0.0, 1.0);
    x * x * (3.0 - 2.0 * x)
}

/// The fit's spectrum continued beyond the window's edge (eq. 15.9): relaxation terms over
/// D = max(Δ, 0) + [`CONTACT_SPREAD_DECADES`] decades of τ past the edge time τ_e = 1/(2π f_edge),
/// at `TERMS_PER_DECADE` on a grid fixed by the edge, the last one weighted by the fraction of
/// its step that D covers (eq. 15.9b: so the spectrum, and the term, are continuous in Δ), with
/// the spectrum the data show at the edge continued: its density H_e = (2/π)·Ê″(ω_e) (the first
/// approximation H(τ) ≈ (2/π)E″(1/τ), Ferry 1980 ch. 4) and its trend, H(τ) = H_e·(τ_e/τ)^m with
/// m = d ln Ê″/d ln ω over the last `SLOPE_DECADES` inside the window (|m| ≤ `MAX_SLOPE`),
/// each term of strength H(τ_k)·ln 10/`TERMS_PER_DECADE`. Above the window (shorter times) they
/// add to the glassy modulus and leave E′, E″ inside the window almost unchanged (a term with
/// ωτ ≪ 1 adds E_i(ωτ)² to E′). Below it (longer times) E∞ gives up their sum ΔE so that E′ inside
/// the window is kept (a term with ωτ ≫ 1 adds E_i to it), ΔE capped at
/// (1 − `MIN_RELAXED_FRACTION`)·E∞. `None` when the edge's loss modulus is not finite and
/// positive.
pub(crate) fn continued_spectrum(
    relax: &RelaxationSpectrum,
    ex: &WindowExcess,
) -> Option<RelaxationSpectrum> {
    let two_pi = 2.0 * std::f64::consts::PI;
    let omega_e = two_pi * ex.edge_hz;
    let tau_e = 1.0 / omega_e;
    let loss_e = relax.loss_modulus(omega_e);
    let h_e = 2.0 / std::f64::consts::PI * loss_e;
    if !(h_e.is_finite() && h_e > 0.0 && tau_e.is_finite()) {
        return None;
    }
    // the edge's slope m = d ln E″/d ln ω over the last half decade inside the window
    let direction = match ex.side {
        WindowSide::High => -1.0,
        WindowSide::Low => 1.0,
    };
    let omega_in = omega_e * 10f64.powf(direction * SLOPE_DECADES);
    let m = ((loss_e / relax.loss_modulus(omega_in)).ln() / (omega_e / omega_in).ln())
        .clamp(-MAX_SLOPE, MAX_SLOPE);
    let m = if m.is_finite() { m } else { 0.0 };
    // D grid steps: term k covers step k, with weight min(D·TERMS_PER_DECADE − k, 1)
    let steps = (ex.decades.max(0.0) + CONTACT_SPREAD_DECADES) * TERMS_PER_DECADE;
    let n = steps.ceil().max(1.0) as usize;
    // τ_k half a grid step past the edge first (the fit's own terms reach it), strength
    // H(τ_k)·ln 10/TERMS_PER_DECADE with H(τ) = H_e·(τ_e/τ)^m
    let mut terms: Vec<RelaxationTerm> = (0..n)
        .map(|k| {
            let decades = (k as f64 + 0.5) / TERMS_PER_DECADE;
            let tau_s = tau_e * 10f64.powf(direction * decades);
            let weight = (steps - k as f64).min(1.0);
            RelaxationTerm {
                modulus_pa: weight * h_e * (tau_e / tau_s).powf(m) * std::f64::consts::LN_10
                    / TERMS_PER_DECADE,
                tau_s,
            }
        })
        .filter(|t| t.modulus_pa != 0.0)
        .collect();
    let mut out = relax.clone();
    if ex.side == WindowSide::Low {
        let added: f64 = terms.iter().map(|t| t.modulus_pa).sum();
        let room = (1.0 - MIN_RELAXED_FRACTION) * relax.modulus_inf_pa;
        if added > room {
            for t in &mut terms {
                t.modulus_pa *= room / added;
            }
        }
        out.modulus_inf_pa -= terms.iter().map(|t| t.modulus_pa).sum::<f64>();
    }
    let ok = terms
        .iter()
        .all(|t| t.modulus_pa.is_finite() && t.modulus_pa > 0.0);
    out.terms.extend(terms);
    (ok && out.modulus_inf_pa > 0.0).then_some(out)
}

/// How the notes of a widened band start (the datasheet's † finds them by it).
pub const WIDENED_NOTE_START: &str = "band widened for extrapolation";

/// The note of a point whose band holds the frequency-window term `s_window` (eq. 15.9, the
/// weighted term of eq. 15.9c inside the edge's last half decade): it reaches friction.csv's
/// `note`, the datasheet (†) and the ranking through the point's warnings.
pub fn window_note(s_window: f64, ex: &WindowExcess) -> String {
    let (end, reach) = match ex.side {
        WindowSide::High => ("top", "up to"),
        WindowSide::Low => ("bottom", "down to"),
    };
    if ex.decades <= 0.0 {
        return format!(
            "{WIDENED_NOTE_START} in frequency: the rolling frequency V/l reduced to the reference \
             temperature, {:.2e} Hz, lies {:.2} decades inside the {end} of the measured master \
             curve ({reach} {:.2e} Hz), in its last {RAMP_DECADES} decade, which few points \
             constrain; the Prony spectrum continued past the edge with the density and slope of \
             the edge changes F/N there, and that change weighted by {:.2} (the ramp into the \
             window), {}, is taken as one standard deviation (docs/MATH.md eqs. 15.9, 15.9c)",
            ex.reduced_freq_hz,
            -ex.decades,
            ex.edge_hz,
            ramp_weight(ex.decades),
            change_text(s_window)
        );
    }
    format!(
        "{WIDENED_NOTE_START} in frequency: the rolling frequency V/l reduced to the reference \
         temperature, {:.2e} Hz, lies {:.1} decades {} the measured master curve ({reach} {:.2e} Hz), and the \
         Prony spectrum continued past it with the density and slope of the edge changes F/N by {} \
         (taken as one standard deviation, docs/MATH.md eq. 15.9)",
        ex.reduced_freq_hz,
        ex.decades,
        match ex.side {
            WindowSide::High => "above",
            WindowSide::Low => "below",
        },
        ex.edge_hz,
        change_text(s_window)
    )
}

/// A change of ln F by `s` in words: "27 %" up to doubling, then "a factor 3.4" or "a factor 6.5e5"
/// (never a percentage beyond 1000 %: issue 31).
pub(crate) fn change_text(s: f64) -> String {
    let f = s.exp();
    if f < 2.0 {
        format!("{:.0} %", 100.0 * s.exp_m1())
    } else if f < 1000.0 {
        format!("a factor {f:.1}")
    } else {
        format!("a factor {f:.1e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ModulusKind;

    /// A flat spectrum: 2 terms per decade, 1 MPa each, τ from 1e-6 to 1e2 s, E∞ = 5 MPa.
    fn flat() -> RelaxationSpectrum {
        RelaxationSpectrum {
            kind: ModulusKind::Tensile,
            poisson: 0.5,
            modulus_inf_pa: 5e6,
            terms: (0..=16)
                .map(|k| RelaxationTerm {
                    modulus_pa: 1e6,
                    tau_s: 1e-6 * 10f64.powf(k as f64 / 2.0),
                })
                .collect(),
        }
    }

    #[test]
    fn the_window_excess_reads_the_decades_beyond_either_edge() {
        let w = (1e-3, 1e4);
        assert!(excess(w, 1.0).is_none());
        assert!(excess(w, f64::NAN).is_none());
        assert_eq!(change_text(0.25), "28 %");
        assert_eq!(change_text(2f64.ln() + 0.2), "a factor 2.4");
        assert_eq!(change_text(1e5f64.ln()), "a factor 1.0e5");
        let hi = excess(w, 1e6).unwrap();
        assert_eq!(hi.side, WindowSide::High);
        assert!((hi.decades - 2.0).abs() < 1e-12);
        let lo = excess(w, 1e-4).unwrap();
        assert_eq!((lo.side, lo.edge_hz), (WindowSide::Low, 1e-3));
        assert!((lo.decades - 1.0).abs() < 1e-12);
        // V/l = 4 m/s / 8 mm = 500 Hz, a_T = 10^−2: 5 Hz reduced
        assert!((rolling_reduced_freq_hz(4.0, 8e-3, -2.0) / 5.0 - 1.0).abs() < 1e-12);
    }

    #[test]
    fn the_continuation_keeps_the_window_and_extends_the_density_of_its_edge() {
        // A flat spectrum of 1 MPa per half decade has H = 1e6·2/ln 10 per unit ln τ and, away
        // from its ends, E″ = (π/2)H (the integral of ωτ/(1+ω²τ²) over ln τ is π/2): so
        // H_e = (2/π)E″ recovers H to the ripple of a two-per-decade grid, and the continued terms
        // are as strong as the fit's. A window 1e-1 … 1e3 Hz well inside the spectrum.
        let s = flat();
        let omega = |f: f64| 2.0 * std::f64::consts::PI * f;
        let ex = excess((1e-1, 1e3), 1e5).unwrap();
        let c = continued_spectrum(&s, &ex).unwrap();
        // D = 2 + 1 decades, 6 terms, each within 5 % of 1 MPa (the grid's ripple in E″)
        let added: Vec<_> = c.terms[s.terms.len()..].to_vec();
        assert_eq!(added.len(), 6);
        assert!(
            (added[0].modulus_pa / 1e6 - 1.0).abs() < 0.05,
            "{}",
            added[0].modulus_pa
        );
        // first at half a step above the edge's time, then half-decade steps to shorter times
        let tau_e = 1.0 / omega(1e3);
        assert!((added[0].tau_s / (tau_e * 10f64.powf(-0.25)) - 1.0).abs() < 1e-12);
        assert!((added[5].tau_s / (tau_e * 10f64.powf(-2.75)) - 1.0).abs() < 1e-12);
        assert_eq!(c.modulus_inf_pa, s.modulus_inf_pa);
        // Inside the window, two decades below the edge (ω = 62.8 rad/s), E′ moves by
        // Σ E_i (ωτ_i)² ≈ 35 Pa of ≈ 1e7 and E″ by Σ E_i ωτ_i = 5.6e-3·1e6/(1 − 10^−½) ≈ 8.2e3 Pa
        // of ≈ 1.36e6 (0.6 %): bounds 1e-4 and 1 %.
        let (e1, e2) = s.complex_modulus(omega(10.0));
        let (c1, c2) = c.complex_modulus(omega(10.0));
        assert!((c1 / e1 - 1.0).abs() < 1e-4, "{c1} {e1}");
        assert!((c2 / e2 - 1.0).abs() < 1e-2, "{c2} {e2}");
        // The glassy modulus grows by the six terms.
        let g = c.instantaneous_modulus() - s.instantaneous_modulus();
        assert!((g / 6e6 - 1.0).abs() < 0.05, "{g}");
        // Below the window: E∞ gives the added strength back, so E′ at the low edge's decade
        // inside is kept to the terms' (ωτ)⁻² tails; capped at half of E∞.
        let lo = excess((1e-1, 1e3), 1e-2).unwrap();
        let c = continued_spectrum(&s, &lo).unwrap();
        let added: f64 = c.terms[s.terms.len()..].iter().map(|t| t.modulus_pa).sum();
        assert!((s.modulus_inf_pa - c.modulus_inf_pa - added).abs() < 1e-6 * added);
        assert!(
            (c.modulus_inf_pa - 2.5e6).abs() < 1.0,
            "{}",
            c.modulus_inf_pa
        );
        let (e1, _) = s.complex_modulus(omega(10.0));
        let (c1, _) = c.complex_modulus(omega(10.0));
        assert!((c1 / e1 - 1.0).abs() < 1e-3, "{c1} {e1}");
    }

    #[test]
    fn the_term_starts_half_a_decade_inside_the_edge_and_grows_without_a_step() {
        let w = (1e-3, 1e4);
        // 0.3 decades inside the top: Δ = −0.3, the top's side; 0.6 inside: nothing
        let near = excess(w, 1e4 * 10f64.powf(-0.3)).unwrap();
        assert_eq!(near.side, WindowSide::High);
        assert!((near.decades + 0.3).abs() < 1e-12);
        assert!(excess(w, 1e4 * 10f64.powf(-0.6)).is_none());
        let near_lo = excess(w, 1e-3 * 10f64.powf(0.2)).unwrap();
        assert_eq!(near_lo.side, WindowSide::Low);
        assert!((near_lo.decades + 0.2).abs() < 1e-12);
        // the weight: 0 at the ramp's start, 1 at the edge and beyond, the smooth step between
        // (½ half-way, slope 3/(2·RAMP) there), no step and no kink at either end
        assert_eq!(ramp_weight(-RAMP_DECADES), 0.0);
        assert_eq!(ramp_weight(-2.0), 0.0);
        assert_eq!(ramp_weight(0.0), 1.0);
        assert_eq!(ramp_weight(3.0), 1.0);
        assert!((ramp_weight(-RAMP_DECADES / 2.0) - 0.5).abs() < 1e-15);
        let eps = 1e-7;
        let slope = (ramp_weight(-0.25 + eps) - ramp_weight(-0.25 - eps)) / (2.0 * eps);
        assert!((slope - 1.5 / RAMP_DECADES).abs() < 1e-6, "{slope}");
        for end in [-RAMP_DECADES, 0.0] {
            let slope = (ramp_weight(end + eps) - ramp_weight(end - eps)) / (2.0 * eps);
            assert!(slope.abs() < 1e-6, "{end}: {slope}");
        }
        // Inside the window the continuation is the edge's (one decade, D = 1): the same spectrum
        // at Δ = −0.3 and Δ = 0.
        let s = flat();
        let at = |d: f64| {
            let ex = WindowExcess {
                side: WindowSide::High,
                reduced_freq_hz: 1e3 * 10f64.powf(d),
                edge_hz: 1e3,
                decades: d,
            };
            continued_spectrum(&s, &ex).unwrap()
        };
        assert_eq!(at(-0.3), at(0.0));
        // Beyond it, D = Δ + 1 grows continuously: the glassy modulus (the sum of the terms) at
        // Δ = 0.5 ± 1e-9, where a term was added whole before, differs by ~1e-9 of a term;
        // half-way through a step it has half the new term (2 terms per decade, each ≈ 1 MPa).
        let g = |d: f64| at(d).instantaneous_modulus();
        assert!(
            (g(0.5 + 1e-9) - g(0.5 - 1e-9)).abs() < 1e-2,
            "{}",
            g(0.5 + 1e-9) - g(0.5 - 1e-9)
        );
        let half = g(0.75) - g(0.5);
        assert!((half / 0.5e6 - 1.0).abs() < 0.05, "{half}");
        // the note of a point inside says so, with the weight
        let n = window_note(0.1, &near);
        assert!(
            n.starts_with(WIDENED_NOTE_START)
                && n.contains("0.30 decades inside the top")
                && n.contains(&format!("weighted by {:.2}", ramp_weight(-0.3)))
                && n.contains("11 %"),
            "{n}"
        );
    }

    #[test]
    fn a_spectrum_without_loss_at_the_edge_is_not_continued() {
        // Beyond the longest term the loss vanishes as (ωτ)^−1 … but stays positive; a spectrum
        // with no terms has none at all: nothing to continue.
        let mut s = flat();
        s.terms.clear();
        let ex = excess((1e-1, 1e3), 1e5).unwrap();
        assert!(continued_spectrum(&s, &ex).is_none());
    }
}
