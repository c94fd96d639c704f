//! Round trips on synthetic measurements ([`crate::testdata`]): isotherms generated from a known
//! spectrum and a known WLF law must give that law back.

use super::*;
use crate::testdata::{broad_spectrum, log_spaced, synthetic_measurement, SyntheticSettings};

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
