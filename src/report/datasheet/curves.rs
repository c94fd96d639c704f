//! The viscoelastic curves of a datasheet as `Chart`s: E′ and E″ and tan δ against temperature
//! at 1 and 10 Hz (the fit as lines, the measured points at those frequencies as markers, as
//! TRIOS and Proteus summaries show them), the tan δ master curve, and the relaxation modulus E(t)
//! and creep compliance J(t) at the reference temperature.
//!
//! Input: a [`CompoundFit`] and its [`Measurement`]; output: charts for
//! `crate::report::plots::plot_chart`. The fit's moduli at a temperature are the relaxation
//! spectrum shifted by the fit's law (docs/MATH.md §5.1, §6).

use super::transitions::{at, Quantity};
use crate::report::chart::{Axis, Chart, Curve, Mark, PALETTE};
use crate::report::plots::{fit_curve, symbols, thinned};
use crate::results::CompoundFit;
use crate::Measurement;

/// The two frequencies of the temperature sweeps (Hz).
pub(crate) const SWEEP_FREQS_HZ: [f64; 2] = [1.0, 10.0];

/// A measured point counts as taken at frequency f when within 2 % of it (DMA sweeps list 1 and
/// 10 Hz as set points; the recorded frequency differs by the instrument's rounding).
const FREQ_MATCH: f64 = 0.02;

/// Temperatures of the fit's sweep lines: 1 K steps over the measured range (at most 2001).
fn sweep_temps(fit: &CompoundFit) -> Vec<f64> {
    let Some((lo, hi)) = fit.measured_range_c() else {
        return vec![];
    };
    let n = ((hi - lo).ceil() as usize).clamp(1, 2000);
    (0..=n)
        .map(|i| lo + (hi - lo) * i as f64 / n as f64)
        .collect()
}

/// Measured (temperature, storage, loss) at `freq_hz`: per isotherm, its point nearest the
/// frequency if within [`FREQ_MATCH`].
fn measured_at(m: &Measurement, freq_hz: f64) -> Vec<(f64, f64, f64)> {
    m.isotherms
        .iter()
        .filter_map(|iso| {
            let p = iso.points.iter().min_by(|a, b| {
                (a.freq_hz / freq_hz)
                    .ln()
                    .abs()
                    .total_cmp(&(b.freq_hz / freq_hz).ln().abs())
            })?;
            ((p.freq_hz / freq_hz - 1.0).abs() <= FREQ_MATCH).then_some((
                iso.temp_mean_c,
                p.storage_pa,
                p.loss_pa,
            ))
        })
        .collect()
}

/// Storage and loss modulus against temperature at 1 and 10 Hz, and tan δ likewise.
pub(crate) fn temperature_sweeps(fit: &CompoundFit, m: &Measurement) -> (Chart, Chart) {
    let temps = sweep_temps(fit);
    let sym = symbols(fit.relaxation.kind);
    // measured points only when they are the same kind of modulus as the fit
    let same_kind = m.kind == fit.relaxation.kind;
    let (mut moduli, mut tan) = (Vec::new(), Vec::new());
    for (k, &f) in SWEEP_FREQS_HZ.iter().enumerate() {
        let (cs, cl) = (PALETTE[2 * k], PALETTE[2 * k + 1]);
        let line = |q: Quantity| -> Vec<(f64, f64)> {
            temps.iter().map(|&t| (t, at(fit, q, t, f))).collect()
        };
        let mark = if k == 0 { Mark::Line } else { Mark::Dashed };
        moduli.push(
            Curve::new(format!("{} {f} Hz", sym.0), line(Quantity::Storage), mark).coloured(cs),
        );
        moduli
            .push(Curve::new(format!("{} {f} Hz", sym.1), line(Quantity::Loss), mark).coloured(cl));
        tan.push(
            Curve::new(format!("tan δ {f} Hz"), line(Quantity::TanDelta), mark)
                .coloured(PALETTE[k]),
        );
        if same_kind {
            let pts = measured_at(m, f);
            if !pts.is_empty() {
                moduli.push(
                    Curve::new(
                        format!("{} measured {f} Hz", sym.0),
                        pts.iter().map(|p| (p.0, p.1)).collect(),
                        Mark::Dots,
                    )
                    .coloured(cs),
                );
                moduli.push(
                    Curve::new(
                        format!("{} measured {f} Hz", sym.1),
                        pts.iter().map(|p| (p.0, p.2)).collect(),
                        Mark::Circles,
                    )
                    .coloured(cl),
                );
                tan.push(
                    Curve::new(
                        format!("measured {f} Hz"),
                        pts.iter().map(|p| (p.0, p.2 / p.1)).collect(),
                        Mark::Dots,
                    )
                    .coloured(PALETTE[k]),
                );
            }
        }
    }
    (
        Chart {
            title: format!("{} and {} against temperature (lines: fit)", sym.0, sym.1),
            x: Axis::lin("temperature T [°C]"),
            y: Axis::log("modulus [Pa]"),
            curves: moduli,
            colour_bar: None,
        },
        Chart {
            title: "tan δ against temperature (lines: fit)".into(),
            x: Axis::lin("temperature T [°C]"),
            y: Axis::log("tan δ"),
            curves: tan,
            colour_bar: None,
        },
    )
}

/// Each replicate specimen's own measurement at 1 Hz against temperature (E′ dots, E″ circles,
/// one colour per specimen) beside the pooled fit's lines (issue 31: "the datasheet shows each
/// specimen's curves"); `None` with fewer than two specimens or none of the fit's kind.
pub(crate) fn specimen_sweeps(fit: &CompoundFit, specimens: &[Measurement]) -> Option<Chart> {
    if specimens.len() < 2 || specimens.iter().any(|m| m.kind != fit.relaxation.kind) {
        return None;
    }
    let f = SWEEP_FREQS_HZ[0];
    let temps = sweep_temps(fit);
    let sym = symbols(fit.relaxation.kind);
    let line =
        |q: Quantity| -> Vec<(f64, f64)> { temps.iter().map(|&t| (t, at(fit, q, t, f))).collect() };
    let mut curves = vec![
        Curve::new(
            format!("{} pooled fit", sym.0),
            line(Quantity::Storage),
            Mark::Line,
        )
        .coloured(PALETTE[7]),
        Curve::new(
            format!("{} pooled fit", sym.1),
            line(Quantity::Loss),
            Mark::Dashed,
        )
        .coloured(PALETTE[7]),
    ];
    for (k, m) in specimens.iter().enumerate() {
        let pts = measured_at(m, f);
        let colour = PALETTE[k % 7];
        curves.push(
            Curve::new(
                format!("{} specimen {}", sym.0, k + 1),
                pts.iter().map(|p| (p.0, p.1)).collect(),
                Mark::LineDots,
            )
            .coloured(colour),
        );
        curves.push(
            Curve::new(
                format!("{} specimen {}", sym.1, k + 1),
                pts.iter().map(|p| (p.0, p.2)).collect(),
                Mark::LineCircles,
            )
            .coloured(colour),
        );
    }
    Some(Chart {
        title: format!(
            "{} and {} of each specimen at {f} Hz (lines: pooled fit)",
            sym.0, sym.1
        ),
        x: Axis::lin("temperature T [°C]"),
        y: Axis::log("modulus [Pa]"),
        curves,
        colour_bar: None,
    })
}

/// tan δ of the master curve (points) and of the Prony fit (line) against reduced frequency.
pub(crate) fn master_tan_delta(fit: &CompoundFit) -> Chart {
    let pts = thinned(&fit.master_curve);
    let line = fit_curve(&fit.master_curve, &fit.relaxation);
    Chart {
        title: format!("tan δ master curve at {:.1} °C", fit.shift_law.t_ref_c()),
        x: Axis::log("reduced frequency a_T·f [Hz]"),
        y: Axis::log("tan δ"),
        curves: vec![
            Curve::new(
                "data",
                pts.iter()
                    .map(|p| (p.reduced_freq_hz, p.loss_pa / p.storage_pa))
                    .collect(),
                Mark::Circles,
            )
            .coloured(PALETTE[4]),
            Curve::new(
                "Prony fit",
                line.iter().map(|p| (p.0, p.2 / p.1)).collect(),
                Mark::Line,
            )
            .coloured(PALETTE[4]),
        ],
        colour_bar: None,
    }
}

/// Times of E(t) and J(t): 20 per decade over the master curve's reduced frequencies turned into
/// times t = 1/(2π f), at most 2001.
fn times(fit: &CompoundFit) -> Vec<f64> {
    let f = fit_curve(&fit.master_curve, &fit.relaxation);
    let (Some(a), Some(b)) = (f.first(), f.last()) else {
        return vec![];
    };
    let (t0, t1) = (
        (1.0 / (2.0 * std::f64::consts::PI * b.0)).log10(),
        (1.0 / (2.0 * std::f64::consts::PI * a.0)).log10(),
    );
    let n = ((t1 - t0) * 20.0).ceil().clamp(2.0, 2000.0) as usize;
    (0..=n)
        .map(|k| 10f64.powf(t0 + (t1 - t0) * k as f64 / n as f64))
        .collect()
}

/// The relaxation modulus E(t) and (when the fit has a creep spectrum) the creep compliance J(t)
/// at the reference temperature.
pub(crate) fn relaxation_and_creep(fit: &CompoundFit) -> (Chart, Option<Chart>) {
    let ts = times(fit);
    let tref = fit.shift_law.t_ref_c();
    let sym = symbols(fit.relaxation.kind).0.trim_end_matches('′');
    let e = Chart {
        title: format!("Relaxation modulus {sym}(t) at {tref:.1} °C"),
        x: Axis::log("time t [s]"),
        y: Axis::log(&format!("{sym}(t) [Pa]")),
        curves: vec![Curve::new(
            "",
            ts.iter()
                .map(|&t| (t, fit.relaxation.relaxation_modulus(t)))
                .collect(),
            Mark::Line,
        )
        .coloured(PALETTE[0])],
        colour_bar: None,
    };
    let j = fit.creep.as_ref().map(|c| Chart {
        title: format!("Creep compliance J(t) at {tref:.1} °C"),
        x: Axis::log("time t [s]"),
        y: Axis::log("J(t) [1/Pa]"),
        curves: vec![Curve::new(
            "",
            ts.iter().map(|&t| (t, c.creep_compliance(t))).collect(),
            Mark::Line,
        )
        .coloured(PALETTE[1])],
        colour_bar: None,
    });
    (e, j)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::datasheet::fixture::fit_with;
    use crate::ShiftLaw;

    /// A fit of one relaxation term (τ = 1 s, E₀ = 101 MPa, E∞ = 1 MPa) with an Arrhenius law
    /// (200 kJ/mol about 0 °C) measured over `range` (°C).
    fn one_term_fit(range: (f64, f64)) -> crate::results::CompoundFit {
        let spectrum = serde_json::from_value(serde_json::json!({
            "kind": "tensile", "poisson": 0.5, "modulus_inf_pa": 1e6,
            "terms": [{"tau_s": 1.0, "modulus_pa": 1e8}]
        }))
        .unwrap();
        let law = ShiftLaw::Arrhenius {
            t_ref_c: 0.0,
            activation_energy_j_per_mol: 200e3,
        };
        fit_with(spectrum, law, range)
    }

    #[test]
    fn creep_compliance_and_relaxation_modulus_are_reciprocal_at_the_ends() {
        // E(t) and J(t) of one material: J(0) = 1/E(0) and J(∞) = 1/E(∞) (docs/MATH.md §4), so
        // E·J → 1 at both ends of a wide enough time range.
        let fit = one_term_fit((-40.0, 40.0));
        let (e, j) = relaxation_and_creep(&fit);
        let j = j.unwrap();
        let (ep, jp) = (&e.curves[0].points, &j.curves[0].points);
        assert_eq!(ep.len(), jp.len());
        // the fixture's master curve spans 1e-2 … 1e4 Hz: t from 1.6e-5 s to 16 s. At the short
        // end E ≈ E(0) (t/τ = 1.6e-5), at the long end t = 16 τ_eff… J·E differs from 1 by the
        // transient e^(−t/τ) terms only: < 2e-4 at the short end.
        let first = ep[0].1 * jp[0].1;
        assert!((first - 1.0).abs() < 2e-4, "{first}");
        // J rises and E falls monotonically
        assert!(ep.windows(2).all(|w| w[1].1 <= w[0].1));
        assert!(jp.windows(2).all(|w| w[1].1 >= w[0].1));
    }

    /// A measurement at −10, 0 and 10 °C with points at 0.5, 1 and 10 Hz, E′ = scale·(1 + f)·(1 + T²),
    /// E″ a tenth of it.
    fn swept(scale: f64) -> crate::Measurement {
        let iso: Vec<serde_json::Value> = [-10.0f64, 0.0, 10.0]
            .iter()
            .map(|&t| {
                let pts: Vec<serde_json::Value> = [0.5f64, 1.0, 10.0]
                    .iter()
                    .map(|&f| {
                        let e = scale * (1.0 + f) * (1.0 + t * t);
                        serde_json::json!({"freq_hz": f, "storage_pa": e, "loss_pa": 0.1 * e,
                                           "temp_c": t, "line": 1, "flags": []})
                    })
                    .collect();
                serde_json::json!({"temp_nominal_c": t, "temp_mean_c": t, "source": 0,
                                   "points": pts})
            })
            .collect();
        serde_json::from_value(serde_json::json!({"sources": [], "kind": "tensile",
            "poisson": 0.5, "isotherms": iso, "warnings": []}))
        .unwrap()
    }

    #[test]
    fn each_specimen_is_drawn_with_its_own_1_hz_points() {
        let fit = one_term_fit((-10.0, 10.0));
        assert!(specimen_sweeps(&fit, &[swept(1.0)]).is_none());
        let c = specimen_sweeps(&fit, &[swept(1.0), swept(2.0)]).unwrap();
        // the pooled fit's E′ and E″, then E′ and E″ of each specimen
        assert_eq!(c.curves.len(), 6);
        for (k, scale) in [(0usize, 1.0), (1, 2.0)] {
            let (e1, e2) = (&c.curves[2 + 2 * k], &c.curves[3 + 2 * k]);
            assert_eq!(e1.points.len(), 3, "one point per isotherm, at 1 Hz only");
            for (&(t, e), &(t2, l)) in e1.points.iter().zip(&e2.points) {
                assert_eq!(t, t2);
                assert_eq!(e, scale * 2.0 * (1.0 + t * t));
                assert_eq!(l, 0.1 * e);
            }
        }
    }

    #[test]
    fn sweeps_at_1_hz_and_10_hz_shift_the_loss_peak_up_in_temperature() {
        let fit = one_term_fit((-60.0, 60.0));
        let m = crate::Measurement {
            sources: vec![],
            kind: crate::ModulusKind::Tensile,
            poisson: 0.5,
            isotherms: vec![],
            warnings: vec![],
            issues: vec![],
            summary: Default::default(),
        };
        let (moduli, tan) = temperature_sweeps(&fit, &m);
        let peak_t = |c: &Curve| {
            c.points
                .iter()
                .copied()
                .fold(
                    (f64::NAN, f64::NEG_INFINITY),
                    |a, p| if p.1 > a.1 { p } else { a },
                )
                .0
        };
        // E″ at 1 Hz and 10 Hz are curves 1 and 3; a tenfold frequency moves the peak to where
        // a_T is ten times smaller, i.e. to a higher temperature
        let (t1, t10) = (peak_t(&moduli.curves[1]), peak_t(&moduli.curves[3]));
        assert!(t10 > t1 + 1.0, "{t1} {t10}");
        assert_eq!(tan.curves.len(), 2);
    }
}
