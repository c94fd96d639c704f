//! The master curve: input a [`Measurement`] and [`MasterSettings`], output a [`MasterCurve`]
//! (reduced-frequency points, the shift of each isotherm, WLF and Arrhenius fits, the chosen
//! [`ShiftLaw`], quality figures and the settings used). docs/MATH.md §6.
//!
//! Phases, each in its own file: clean each isotherm ([`super::clean`]) → optional vertical factor
//! from temperature → the channels compared ([`super::channels`]) → horizontal shifts, automatic or
//! from a given law ([`super::horizontal`]) → optional fitted vertical shifts ([`super::vertical`])
//! → WLF and Arrhenius fits and the move to T_ref ([`super::law_choice`]) → quality figures
//! ([`super::assess`]) → reduced points ω_r = a_T ω, E_r = E / b_T (here).

use super::assess::assess;
use super::channels::Channels;
use super::clean::{clean, Clean};
use super::error::TtsError;
use super::fit_laws::{ArrheniusFit, WlfFit};
use super::horizontal::{horizontal_shifts, Horizontal};
use super::law_choice::{degenerate_wlf_warning, fit_and_choose};
use super::point_temps::{correct_point_temperatures, slopes_from_shifts};
pub use super::quality_types::{IsothermShift, MasterQuality};
use super::settings::{MasterSettings, ShiftSource, TemperatureBasis, VerticalShift};
use super::vertical::{fit_vertical, log10_b_t_temperature};
use crate::dma::Measurement;
use crate::material::{ModulusKind, ShiftLaw};
use serde::{Deserialize, Serialize};

/// One point of the master curve.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MasterPoint {
    /// Reduced frequency a_T · f in Hz.
    pub reduced_freq_hz: f64,
    /// Reduced storage modulus E′/b_T in Pa.
    pub storage_pa: f64,
    /// Reduced loss modulus E″/b_T in Pa.
    pub loss_pa: f64,
    /// Temperature of the isotherm it came from, °C.
    pub temp_c: f64,
    /// Index of that isotherm in `MasterCurve::isotherms`.
    pub isotherm: usize,
}

/// A master curve with its shift law and quality figures.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MasterCurve {
    /// Tensile or shear moduli.
    pub kind: ModulusKind,
    /// Poisson's ratio carried from the measurement.
    pub poisson: f64,
    /// Reference temperature, °C.
    pub t_ref_c: f64,
    /// Points sorted by reduced frequency.
    pub points: Vec<MasterPoint>,
    /// Shift of each isotherm, in order of temperature.
    pub isotherms: Vec<IsothermShift>,
    /// WLF fit of the shifts at T_ref (`None` if it failed, see `warnings`).
    pub wlf: Option<WlfFit>,
    /// Arrhenius fit of the shifts at T_ref.
    pub arrhenius: Option<ArrheniusFit>,
    /// The law used from here on (the better fit, or as chosen or given).
    pub shift_law: ShiftLaw,
    /// Quality figures.
    pub quality: MasterQuality,
    /// The settings used (resolved: `tref_c` is filled in).
    pub settings: MasterSettings,
    /// Warnings (isotherms skipped, a law that failed to fit, …).
    pub warnings: Vec<String>,
}

/// Build the master curve of `measurement` (see the module docs); with
/// `correct_point_temperatures`, first move every point to its isotherm's temperature
/// (`super::point_temps`) with the slopes of the given law or of a first shifting pass.
pub fn build_master_curve(
    measurement: &Measurement,
    settings: &MasterSettings,
) -> Result<MasterCurve, TtsError> {
    let has_point_temps = measurement
        .isotherms
        .iter()
        .any(|i| i.points.iter().any(|p| p.temp_c.is_some()));
    if !settings.correct_point_temperatures || !has_point_temps {
        return build_once(measurement, settings);
    }
    settings.validate()?;
    let temp_of = |i: &crate::dma::Isotherm| match settings.temperature {
        TemperatureBasis::Mean => i.temp_mean_c,
        TemperatureBasis::Nominal => i.temp_nominal_c,
    };
    let slopes_of = |mc: &MasterCurve| {
        let shifts: Vec<(f64, f64)> = mc
            .isotherms
            .iter()
            .map(|i| (i.temp_c, i.log10_a_t))
            .collect();
        let mut by_index = vec![f64::NAN; measurement.isotherms.len()];
        for (i, v) in mc.isotherms.iter().zip(slopes_from_shifts(&shifts)) {
            by_index[i.measurement_index] = v;
        }
        by_index
    };
    let (mut mc, largest, passes) = match &settings.shift {
        // Central difference of the law over ±0.5 K (its curvature error is far below the
        // correction's own second-order term); one pass.
        ShiftSource::Given { law } => {
            let slopes: Vec<f64> = measurement
                .isotherms
                .iter()
                .map(|i| {
                    let t = temp_of(i);
                    law.log10_a_t(t + 0.5) - law.log10_a_t(t - 0.5)
                })
                .collect();
            let (corrected, largest) =
                correct_point_temperatures(measurement, &slopes, settings.temperature);
            (build_once(&corrected, settings)?, largest, 1)
        }
        // Slopes from the shifts of the previous pass, applied to the measured points, until the
        // shifts move by less than POINT_TEMPERATURE_TOL_LOG10 (a fixed point: the slopes of the
        // corrected shifts reproduce them). On the shipped DMA-suite set (3 K drift per sweep) the
        // first correction moved the end shifts by 0.65 decade, the second by 0.045.
        ShiftSource::Auto => {
            let mut mc = build_once(measurement, settings)?;
            let mut largest = 0.0;
            let mut passes = 0;
            while passes < POINT_TEMPERATURE_MAX_PASSES {
                let (corrected, l) =
                    correct_point_temperatures(measurement, &slopes_of(&mc), settings.temperature);
                let next = build_once(&corrected, settings)?;
                let moved = mc
                    .isotherms
                    .iter()
                    .zip(&next.isotherms)
                    .map(|(a, b)| (a.log10_a_t - b.log10_a_t).abs())
                    .fold(0.0, f64::max);
                mc = next;
                largest = l;
                passes += 1;
                if moved < POINT_TEMPERATURE_TOL_LOG10 {
                    break;
                }
            }
            (mc, largest, passes)
        }
    };
    mc.quality.point_temperature_correction_max_log10 = largest;
    mc.quality.point_temperature_passes = passes;
    Ok(mc)
}

/// The per-point temperature correction stops when no shift moves by more than this (decades):
/// a tenth of the shift error the correction removes at the cold end of the synthetic tests.
const POINT_TEMPERATURE_TOL_LOG10: f64 = 0.005;
/// At most this many corrected shifting passes (each costs one master-curve construction).
const POINT_TEMPERATURE_MAX_PASSES: usize = 4;

fn build_once(
    measurement: &Measurement,
    settings: &MasterSettings,
) -> Result<MasterCurve, TtsError> {
    settings.validate()?;
    let mut warnings = Vec::new();
    let mut iso = clean(measurement, settings.temperature, &mut warnings)?;
    let t_ref = settings.tref_c.unwrap_or(iso[(iso.len() - 1) / 2].temp);
    let mut shifted = shift_isotherms(&iso, t_ref, settings, measurement.kind)?;
    let left_out = out_of_order(&shifted.1);
    let mut left_out_c = Vec::new();
    if !left_out.is_empty() {
        left_out_c = left_out.iter().map(|&i| iso[i].temp).collect();
        warnings.push(format!(
            "isotherms at {} °C left out of the master curve: their shifts are not determined by \
             overlap and fall out of order (a_T must fall as the temperature rises), so no reading \
             of them is consistent (docs/MATH.md §6.6); their data stay in the measurement",
            left_out_c
                .iter()
                .map(|t| format!("{t:.1}"))
                .collect::<Vec<_>>()
                .join(", ")
        ));
        let mut k = 0;
        iso.retain(|_| {
            k += 1;
            !left_out.contains(&(k - 1))
        });
        shifted = shift_isotherms(&iso, t_ref, settings, measurement.kind)?;
    }
    let (ch, mut h, mut log_b, k0) = shifted;
    let n = iso.len();
    let temps: Vec<f64> = iso.iter().map(|c| c.temp).collect();
    if settings.vertical == VerticalShift::Fitted {
        log_b = fit_vertical(
            &ch.joint,
            &h.shifts,
            k0,
            settings.pair_reach,
            settings.min_overlap_points,
        );
    }
    let undetermined: Vec<String> = (0..n)
        .filter(|&i| !h.determined[i])
        .map(|i| format!("{:.1}", temps[i]))
        .collect();
    if !undetermined.is_empty() {
        warnings.push(format!(
            "shift not determined by overlap at {} °C (neighbouring isotherms too far apart, or a \
             flat modulus): left where the overlaps put them; check these isotherms",
            undetermined.join(", ")
        ));
    }
    let laws = fit_and_choose(
        &temps,
        &mut h.shifts,
        &mut log_b,
        k0,
        t_ref,
        h.given.take(),
        settings,
        &mut warnings,
    )?;
    warnings.extend(degenerate_wlf_warning(&laws.wlf));
    let (isotherms, mut quality) = assess(&iso, &ch, &h, &log_b, settings, measurement.kind);
    quality.left_out_c = left_out_c;
    quality.shift_covariance_log10 = std::mem::take(&mut h.covariance);
    let points = reduced_points(&iso, &h.shifts, &log_b);
    let mut resolved = settings.clone();
    resolved.tref_c = Some(t_ref);
    Ok(MasterCurve {
        kind: measurement.kind,
        poisson: measurement.poisson,
        t_ref_c: t_ref,
        points,
        isotherms,
        wlf: laws.wlf,
        arrhenius: laws.arrhenius,
        shift_law: laws.shift_law,
        quality,
        settings: resolved,
        warnings,
    })
}

/// The channels and horizontal shifts of `iso` at reference temperature `t_ref`: the channels, the
/// shifts, the vertical factors known before shifting and the reference isotherm's index.
fn shift_isotherms(
    iso: &[Clean],
    t_ref: f64,
    settings: &MasterSettings,
    kind: ModulusKind,
) -> Result<(Channels, Horizontal, Vec<f64>, usize), TtsError> {
    let n = iso.len();
    let temps: Vec<f64> = iso.iter().map(|c| c.temp).collect();
    let k0 = (0..n)
        .min_by(|&a, &b| {
            (temps[a] - t_ref)
                .abs()
                .total_cmp(&(temps[b] - t_ref).abs())
        })
        .unwrap_or(0);
    // Vertical factor from temperature (known before shifting).
    let log_b: Vec<f64> = match settings.vertical {
        VerticalShift::Temperature => temps
            .iter()
            .map(|&t| log10_b_t_temperature(t, t_ref))
            .collect(),
        _ => vec![0.0; n],
    };
    let ch = Channels::prepare(iso, &log_b, settings, kind);
    let h = horizontal_shifts(&ch, &temps, k0, t_ref, settings)?;
    Ok((ch, h, log_b, k0))
}

/// The isotherms to leave out of the master curve (docs/MATH.md §6.6): walking out from the run
/// of determined shifts, the first isotherm whose shift is not determined and breaks the order
/// (log10 a_T must fall strictly as the temperature rises) and every isotherm beyond it. Such
/// shifts are wherever the overlap scan ran out; a Prony fit of the points they place would fit
/// a master curve no material has.
fn out_of_order(h: &Horizontal) -> Vec<usize> {
    let (s, det) = (&h.shifts, &h.determined);
    let n = s.len();
    let Some(lo) = det.iter().position(|&d| d) else {
        return Vec::new();
    };
    let hi = det.iter().rposition(|&d| d).unwrap_or(lo);
    let mut out = Vec::new();
    if let Some(i) = (0..lo).rev().find(|&i| s[i] <= s[i + 1]) {
        out.extend(0..=i);
    }
    if let Some(i) = (hi + 1..n).find(|&i| s[i] >= s[i - 1]) {
        out.extend(i..n);
    }
    out
}

/// The reduced points ω_r = a_T ω, E_r = E / b_T of every isotherm, sorted by reduced frequency.
fn reduced_points(iso: &[Clean], shifts: &[f64], log_b: &[f64]) -> Vec<MasterPoint> {
    let mut points = Vec::new();
    for (i, c) in iso.iter().enumerate() {
        let (a, b) = (10f64.powf(shifts[i]), 10f64.powf(log_b[i]));
        for k in 0..c.x.len() {
            points.push(MasterPoint {
                reduced_freq_hz: 10f64.powf(c.x[k]) * a,
                storage_pa: 10f64.powf(c.log_s[k]) / b,
                loss_pa: 10f64.powf(c.log_l[k]) / b,
                temp_c: c.temp,
                isotherm: i,
            });
        }
    }
    points.sort_by(|p, q| p.reduced_freq_hz.total_cmp(&q.reduced_freq_hz));
    points
}

#[cfg(test)]
mod roundtrip_tests {
    // Round trips on synthetic measurements ([`crate::testdata`]): isotherms generated from a known
    // spectrum and a known WLF law must give that law back.

    use super::*;
    use crate::testdata::{broad_spectrum, log_spaced, synthetic_measurement, SyntheticSettings};
    use crate::tts::{rereference_wlf, ShiftCriterion};

    /// WLF used to generate the data: C₁ = 10, C₂ = 150 K at 20 °C; isotherms −40…80 °C every 10 K,
    /// so neighbours overlap by 1.3 decades (cold end) to 2.6 decades (warm end) of their 3 decades.
    fn truth() -> ShiftLaw {
        ShiftLaw::Wlf {
            t_ref_c: 20.0,
            c1: 10.0,
            c2_k: 150.0,
        }
    }

    fn temps() -> Vec<f64> {
        (0..13).map(|i| -40.0 + 10.0 * i as f64).collect()
    }

    fn wlf_of(m: &MasterCurve) -> (f64, f64) {
        let w = m.wlf.as_ref().unwrap();
        (w.c1, w.c2_k)
    }

    #[test]
    fn noise_free_round_trip_recovers_wlf() {
        // 20 frequencies per decade (61 over 0.1–100 Hz): the clamped spline's O(h⁴) error is then
        // ~1e-9 in log10, so the shifts and the WLF constants come back to ~1e-7 relative; 1e-6 is the
        // bound asked for.
        let mut s = SyntheticSettings::new(temps(), truth());
        s.freqs_hz = log_spaced(0.1, 100.0, 61);
        let m = synthetic_measurement(&broad_spectrum(), &s);
        for criterion in [
            ShiftCriterion::Storage,
            ShiftCriterion::Joint,
            ShiftCriterion::TanDelta,
        ] {
            let mc = build_master_curve(
                &m,
                &MasterSettings {
                    tref_c: Some(20.0),
                    criterion,
                    ..Default::default()
                },
            )
            .unwrap();
            let (c1, c2) = wlf_of(&mc);
            eprintln!(
                "noise-free {criterion:?}: C1 rel err {:.2e}, C2 rel err {:.2e}",
                c1 / 10.0 - 1.0,
                c2 / 150.0 - 1.0
            );
            assert!((c1 / 10.0 - 1.0).abs() < 1e-6, "C1 = {c1}");
            assert!((c2 / 150.0 - 1.0).abs() < 1e-6, "C2 = {c2}");
            for iso in &mc.isotherms {
                let want = truth().log10_a_t(iso.temp_c);
                // log tan δ, a difference of two curves, has larger 4th derivatives, so its spline
                // error is ~10× that of log E′ (measured 1.2e-6 at worst): 1e-5 for it.
                let tol = if criterion == ShiftCriterion::TanDelta {
                    1e-5
                } else {
                    1e-6
                };
                assert!(
                    (iso.log10_a_t - want).abs() < tol,
                    "{}: {} vs {want}",
                    iso.temp_c,
                    iso.log10_a_t
                );
            }
            assert!(matches!(mc.shift_law, ShiftLaw::Wlf { .. }));
            assert!(mc.quality.flags.is_empty(), "{:?}", mc.quality.flags);
        }
    }

    #[test]
    fn noisy_round_trip_within_five_percent_and_monotonic() {
        // 1 % multiplicative noise, EMS-CA layout (10 frequencies over 3 decades), actual temperatures
        // up to ±1 K off nominal: C₁ and C₂ within 5 % (the bound) for several seeds, shifts
        // strictly decreasing with temperature.
        for (seed, criterion) in (1..=6).zip(
            [
                ShiftCriterion::Storage,
                ShiftCriterion::Joint,
                ShiftCriterion::TanDelta,
            ]
            .into_iter()
            .cycle(),
        ) {
            let mut s = SyntheticSettings::new(temps(), truth());
            s.noise_rel = 0.01;
            s.temp_offset_k = 1.0;
            s.seed = seed;
            let m = synthetic_measurement(&broad_spectrum(), &s);
            let mc = build_master_curve(
                &m,
                &MasterSettings {
                    tref_c: Some(20.0),
                    criterion,
                    ..Default::default()
                },
            )
            .unwrap();
            let (c1, c2) = wlf_of(&mc);
            eprintln!(
                "1 % noise seed {seed} {criterion:?}: C1 rel err {:.2e}, C2 rel err {:.2e}",
                c1 / 10.0 - 1.0,
                c2 / 150.0 - 1.0
            );
            assert!((c1 / 10.0 - 1.0).abs() < 0.05, "seed {seed}: C1 = {c1}");
            assert!((c2 / 150.0 - 1.0).abs() < 0.05, "seed {seed}: C2 = {c2}");
            for w in mc.isotherms.windows(2) {
                assert!(
                    w[1].log10_a_t < w[0].log10_a_t,
                    "seed {seed}: not monotonic"
                );
            }
        }
    }

    #[test]
    fn default_reference_is_the_middle_isotherm_and_rereferencing_is_exact() {
        let m = synthetic_measurement(&broad_spectrum(), &SyntheticSettings::new(temps(), truth()));
        let mid = build_master_curve(&m, &MasterSettings::default()).unwrap();
        assert_eq!(mid.t_ref_c, 20.0);
        assert_eq!(mid.isotherms[6].log10_a_t, 0.0);
        // At T_ref = 25 °C (not measured) the WLF constants must be the exact re-referencing of
        // those at 20 °C (the offset at 25 °C comes from the same WLF law).
        let at25 = build_master_curve(
            &m,
            &MasterSettings {
                tref_c: Some(25.0),
                ..Default::default()
            },
        )
        .unwrap();
        let w20 = mid.wlf.as_ref().unwrap();
        let (c1, c2) = rereference_wlf(w20.c1, w20.c2_k, 20.0, 25.0).unwrap();
        let w25 = at25.wlf.as_ref().unwrap();
        assert!((w25.c1 / c1 - 1.0).abs() < 1e-6 && (w25.c2_k / c2 - 1.0).abs() < 1e-6);
    }

    #[test]
    fn given_law_is_used_as_is() {
        let m = synthetic_measurement(&broad_spectrum(), &SyntheticSettings::new(temps(), truth()));
        let st = MasterSettings {
            tref_c: Some(20.0),
            shift: ShiftSource::Given { law: truth() },
            ..Default::default()
        };
        let mc = build_master_curve(&m, &st).unwrap();
        assert_eq!(mc.shift_law, truth());
        for iso in &mc.isotherms {
            assert_eq!(iso.log10_a_t, truth().log10_a_t(iso.temp_c));
        }
        // The true law superposes the data: overlap RMS at the 10-points-per-3-decades spline error
        // (a few 1e-3 at most).
        assert!(
            mc.quality.overlap_rms_max_log10 < 5e-3,
            "{}",
            mc.quality.overlap_rms_max_log10
        );
    }

    #[test]
    fn mis_shifted_and_inconsistent_isotherms_are_flagged() {
        // (a) The true shifts with the 20 °C isotherm moved 0.4 decade: its E′ overlap with its
        // neighbours is off by about |d log E′/d log f|·0.4 (the true law gives < 5e-3), so it and
        // nothing far from it is flagged against the 0.05 bound.
        let m = synthetic_measurement(&broad_spectrum(), &SyntheticSettings::new(temps(), truth()));
        let table = ShiftLaw::Table {
            t_ref_c: 20.0,
            points: temps()
                .iter()
                .map(|&t| (t, truth().log10_a_t(t) + if t == 20.0 { 0.4 } else { 0.0 }))
                .collect(),
        };
        let st = MasterSettings {
            tref_c: Some(0.0),
            shift: ShiftSource::Given { law: table },
            ..Default::default()
        };
        let mc = build_master_curve(&m, &st).unwrap();
        let bound = mc.quality.bounds.overlap_rms_max_log10;
        for iso in &mc.isotherms {
            let o = iso.overlap_rms_log10.unwrap();
            let flagged = iso.flags.iter().any(|f| f.starts_with("overlap RMS"));
            if (iso.temp_c - 20.0).abs() < 1.0 {
                assert!(o > bound && flagged, "{}: {o} {:?}", iso.temp_c, iso.flags);
            }
            if (iso.temp_c - 20.0).abs() > 15.0 {
                assert!(o < 5e-3 && !flagged, "{}: {o} {:?}", iso.temp_c, iso.flags);
            }
        }
        // (b) Inconsistent data, shifted automatically: E′ of the 20 °C isotherm raised by 30 %
        // (0.11 decade), E″ left alone. No horizontal shift superposes both moduli, so whichever
        // carries the shift, the other's overlap at that isotherm exceeds the bound and is flagged
        // (measured: E′ 0.015, E″ 0.083 with the default criterion).
        let mut m = m;
        for iso in &mut m.isotherms {
            if (iso.temp_mean_c - 20.0).abs() < 1.0 {
                for p in &mut iso.points {
                    p.storage_pa *= 1.3;
                }
            }
        }
        let mc = build_master_curve(&m, &MasterSettings::default()).unwrap();
        let iso = mc
            .isotherms
            .iter()
            .find(|i| (i.temp_c - 20.0).abs() < 1.0)
            .unwrap();
        let (e1, e2) = (
            iso.overlap_rms_log10.unwrap(),
            iso.loss_overlap_rms_log10.unwrap(),
        );
        assert!(e1.max(e2) > bound, "{e1} {e2}");
        assert!(
            iso.flags.iter().any(|f| f.contains("overlap RMS")),
            "{e1} {e2} {:?}",
            iso.flags
        );
    }

    #[test]
    fn tan_delta_and_fitted_vertical_shift() {
        // Data multiplied by b_T = 10^(0.002 (T − 20)) (a made-up vertical factor): with a fitted
        // vertical shift (horizontal from tan δ) both a_T and b_T come back.
        let mut m = synthetic_measurement(&broad_spectrum(), &{
            let mut s = SyntheticSettings::new(temps(), truth());
            s.freqs_hz = log_spaced(0.1, 100.0, 31);
            s
        });
        for iso in &mut m.isotherms {
            let b = 10f64.powf(0.002 * (iso.temp_mean_c - 20.0));
            for p in &mut iso.points {
                p.storage_pa *= b;
                p.loss_pa *= b;
            }
        }
        let st = MasterSettings {
            tref_c: Some(20.0),
            vertical: VerticalShift::Fitted,
            ..Default::default()
        };
        let mc = build_master_curve(&m, &st).unwrap();
        for iso in &mc.isotherms {
            let want = 0.002 * (iso.temp_c - 20.0);
            // Interpolation error of 10 points per decade: 1e-4 in log10.
            assert!(
                (iso.log10_b_t - want).abs() < 1e-4,
                "{}: {} vs {want}",
                iso.temp_c,
                iso.log10_b_t
            );
            let a = truth().log10_a_t(iso.temp_c);
            assert!(
                (iso.log10_a_t - a).abs() < 1e-3,
                "{}: {} vs {a}",
                iso.temp_c,
                iso.log10_a_t
            );
        }
    }

    #[test]
    fn bad_input_gives_errors_not_panics() {
        let mut m = synthetic_measurement(
            &broad_spectrum(),
            &SyntheticSettings::new(vec![0.0, 10.0], truth()),
        );
        m.isotherms[1].temp_mean_c = 0.0;
        assert!(matches!(
            build_master_curve(&m, &MasterSettings::default()),
            Err(TtsError::DuplicateTemperature { .. })
        ));
        m.isotherms.truncate(1);
        assert!(matches!(
            build_master_curve(&m, &MasterSettings::default()),
            Err(TtsError::TooFewIsotherms { .. })
        ));
        let st = MasterSettings {
            tref_c: Some(f64::NAN),
            ..Default::default()
        };
        assert!(matches!(
            build_master_curve(&m, &st),
            Err(TtsError::BadTemperature { .. })
        ));
    }
}

#[cfg(test)]
mod left_out_tests {
    use super::*;

    fn h(shifts: &[f64], determined: &[bool]) -> Horizontal {
        Horizontal {
            shifts: shifts.to_vec(),
            std_err: vec![0.0; shifts.len()],
            covariance: Vec::new(),
            iterations: 0,
            given: None,
            determined: determined.to_vec(),
        }
    }

    #[test]
    fn an_undetermined_shift_out_of_order_is_left_out_with_everything_beyond_it() {
        // cold end: 10.9, then 8.2 at the coldest, breaking the order (a_T must fall with T);
        // warm end: −0.5 after −1.0
        let (t, f) = (true, false);
        let got = out_of_order(&h(
            &[8.2, 10.9, 7.9, 5.5, 3.3, 2.0, 0.0, -1.0, -0.5],
            &[f, f, f, f, t, t, t, t, f],
        ));
        assert_eq!(got, vec![0, 8]);
        // in order, determined or not: nothing left out
        assert!(out_of_order(&h(&[9.0, 7.0, 3.3, 2.0, 0.0], &[f, f, t, t, t])).is_empty());
        // a determined run out of order is not this rule's business (§6.6 calls it determined)
        assert!(out_of_order(&h(&[1.0, 2.0, 0.0], &[t, t, t])).is_empty());
    }
}
