//! Per-point temperature correction: an isotherm's points were measured at slightly different
//! temperatures (the controller drifts during a sweep; the file records each point's temperature),
//! so each point is moved to the isotherm's temperature before shifting.
//!
//! Input: a [`Measurement`] and the local slope d log10 a_T/dT at each isotherm (from a first
//! shifting pass, `slopes_from_shifts`, or from a given law); output: a corrected [`Measurement`]
//! whose points carry the isotherm's temperature and the frequency that gives the same reduced
//! frequency there. Time–temperature superposition (docs/MATH.md §6, §12): a point at T_p and f has the
//! reduced frequency f·a_T(T_p) = f·10^(log a(T_p) − log a(T_i))·a_T(T_i), so to first order in
//! T_p − T_i it is the point (f·10^(s_i (T_p − T_i)), T_i) with s_i = d log10 a_T/dT at T_i.
//! The neglected second-order term is ½ s′ (T_p − T_i)²: for WLF near T_g (s′ ≈ 2C₁/C₂² ≈ 0.013
//! per K² with the universal constants) and |T_p − T_i| ≤ 1.5 K it is below 0.015 decade, and the
//! deviations from the isotherm's *mean* temperature are smaller than from the nominal one.

use super::settings::TemperatureBasis;
use crate::dma::Measurement;

/// d log10 a_T/dT (per K) at each temperature of `shifts` ((T in °C, log10 a_T), any order), from
/// the parabola through the point and its two neighbours in temperature (three-point derivative on
/// the uneven grid); at the two ends the secant to the neighbour. Returned in the order given.
pub(crate) fn slopes_from_shifts(shifts: &[(f64, f64)]) -> Vec<f64> {
    let n = shifts.len();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| shifts[a].0.total_cmp(&shifts[b].0));
    let mut out = vec![0.0; n];
    if n < 2 {
        return out;
    }
    for (k, &i) in order.iter().enumerate() {
        let (t, s) = shifts[i];
        out[i] = if k == 0 || k == n - 1 {
            let j = if k == 0 { order[1] } else { order[n - 2] };
            (shifts[j].1 - s) / (shifts[j].0 - t)
        } else {
            let (t0, s0) = shifts[order[k - 1]];
            let (t2, s2) = shifts[order[k + 1]];
            let (h0, h1) = (t - t0, t2 - t);
            // Derivative at the middle node of the interpolating parabola.
            -h1 / (h0 * (h0 + h1)) * s0 + (h1 - h0) / (h0 * h1) * s + h0 / (h1 * (h0 + h1)) * s2
        };
    }
    out
}

/// The measurement with every point that has a measured temperature moved to its isotherm's
/// temperature (`basis`): f → f·10^(slope·(T_p − T_i)), T_p → T_i. `slopes[i]` belongs to
/// `measurement.isotherms[i]` (0 or non-finite: that isotherm is left alone). Also returns the
/// largest |correction| in decades.
pub fn correct_point_temperatures(
    measurement: &Measurement,
    slopes: &[f64],
    basis: TemperatureBasis,
) -> (Measurement, f64) {
    let mut m = measurement.clone();
    let mut largest = 0.0f64;
    for (iso, &slope) in m.isotherms.iter_mut().zip(slopes) {
        let t_iso = match basis {
            TemperatureBasis::Mean => iso.temp_mean_c,
            TemperatureBasis::Nominal => iso.temp_nominal_c,
        };
        if !(slope.is_finite() && t_iso.is_finite()) {
            continue;
        }
        for p in &mut iso.points {
            if let Some(tp) = p.temp_c.filter(|t| t.is_finite()) {
                let d = slope * (tp - t_iso);
                largest = largest.max(d.abs());
                p.freq_hz *= 10f64.powf(d);
                p.temp_c = Some(t_iso);
            }
        }
    }
    (m, largest)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::ShiftLaw;

    #[test]
    fn three_point_slopes_are_exact_on_a_parabola() {
        // log a = 0.01 T² − 0.3 T on an uneven grid: the parabola's derivative 0.02 T − 0.3 inside
        // (exact to rounding), the secants at the ends.
        let ts = [-20.0, -14.0, -10.5, -3.0, 5.0];
        let f = |t: f64| 0.01 * t * t - 0.3 * t;
        let pts: Vec<(f64, f64)> = ts.iter().rev().map(|&t| (t, f(t))).collect();
        let s = slopes_from_shifts(&pts);
        for (k, &(t, _)) in pts.iter().enumerate() {
            let want = if t == -20.0 {
                (f(-14.0) - f(-20.0)) / 6.0
            } else if t == 5.0 {
                (f(5.0) - f(-3.0)) / 8.0
            } else {
                0.02 * t - 0.3
            };
            assert!((s[k] - want).abs() < 1e-12, "{t}: {} vs {want}", s[k]);
        }
    }

    #[test]
    fn correction_reproduces_the_reduced_frequency_of_a_linear_law() {
        // With log a linear in T the first-order correction is exact: f·a(T_p) = f′·a(T_i).
        use crate::testdata::{broad_spectrum, synthetic_measurement, SyntheticSettings};
        let law = ShiftLaw::Table {
            t_ref_c: 0.0,
            points: vec![(-100.0, 20.0), (100.0, -20.0)],
        };
        let mut m = synthetic_measurement(
            &broad_spectrum(),
            &SyntheticSettings::new(vec![0.0, 10.0], law.clone()),
        );
        for (k, p) in m.isotherms[1].points.iter_mut().enumerate() {
            p.temp_c = Some(10.0 + 0.3 * k as f64 - 1.0);
        }
        let orig = m.clone();
        let (c, largest) = correct_point_temperatures(&m, &[-0.2, -0.2], TemperatureBasis::Mean);
        for (p, q) in orig.isotherms[1].points.iter().zip(&c.isotherms[1].points) {
            let t_i = orig.isotherms[1].temp_mean_c;
            let before = p.freq_hz * 10f64.powf(law.log10_a_t(p.temp_c.unwrap()));
            let after = q.freq_hz * 10f64.powf(law.log10_a_t(t_i));
            assert!((after / before - 1.0).abs() < 1e-12);
            assert_eq!(q.temp_c, Some(t_i));
        }
        assert!(largest > 0.1);
    }

    #[test]
    fn drift_within_sweeps_is_removed_from_the_shifts() {
        // Noise-free exports of a realistic rubber with ±1.5 K drift: shifts against the true WLF
        // law (relative to the reference isotherm) between −45 and +65 °C. Without the correction
        // the drift distorts each isotherm (measured worst error 0.088 decade); with it, what
        // remains is the correction's second-order term and the spline (measured 0.0004; bound
        // 0.01, the ½ s′ΔT² bound of the module docs).
        use crate::dma::{DataPoint, Isotherm, SourceFile};
        use crate::testdata::realistic::{dma_rows, realistic_compounds, DmaProtocol};
        use crate::tts::{build_master_curve, MasterSettings};
        let c = &realistic_compounds()[1];
        let p = DmaProtocol {
            noise_storage_rel: 0.0,
            noise_loss_rel: 0.0,
            ..DmaProtocol::default()
        };
        let rows = dma_rows(c, &p);
        let isotherms: Vec<Isotherm> = (0..p.temps_c.len())
            .map(|seg| {
                let pts: Vec<_> = rows.iter().filter(|r| r.segment == seg).collect();
                let mean = pts.iter().map(|r| r.temp_c).sum::<f64>() / pts.len() as f64;
                Isotherm {
                    temp_nominal_c: p.temps_c[seg],
                    temp_mean_c: mean,
                    source: 0,
                    nominal_source: "file".into(),
                    sheet: None,
                    label: None,
                    points: pts
                        .iter()
                        .map(|r| DataPoint {
                            freq_hz: r.freq_hz,
                            storage_pa: r.storage_pa,
                            loss_pa: r.loss_pa,
                            temp_c: Some(r.temp_c),
                            line: 0,
                            flags: vec![],
                        })
                        .collect(),
                }
            })
            .collect();
        let m = Measurement {
            sources: vec![SourceFile {
                path: "synthetic".into(),
                sha256: String::new(),
                format: "synthetic".into(),
                metadata: Default::default(),
                encoding: String::new(),
                columns: vec![],
            }],
            kind: crate::material::ModulusKind::Tensile,
            poisson: 0.5,
            isotherms,
            warnings: vec![],
            issues: vec![],
            summary: Default::default(),
        };
        let worst = |correct: bool| {
            let mc = build_master_curve(
                &m,
                &MasterSettings {
                    correct_point_temperatures: correct,
                    ..MasterSettings::default()
                },
            )
            .unwrap();
            let t0 = mc.t_ref_c;
            mc.isotherms
                .iter()
                .filter(|i| (-45.0..=65.0).contains(&i.temp_c))
                .map(|i| {
                    let want = c.law.log10_a_t(i.temp_c) - c.law.log10_a_t(t0);
                    (i.log10_a_t - want).abs()
                })
                .fold(0.0, f64::max)
        };
        let (off, on) = (worst(false), worst(true));
        assert!(on <= 0.01 && off > 0.03, "without {off}, with {on}");
    }
}
