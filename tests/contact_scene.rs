//! Dimensional scenes: the elastic (Hertz) closed form, tensile/shear equivalence, and the speed
//! limits of a standard linear solid (glassy and relaxed Hertz widths, friction a single bell that
//! vanishes at both ends like V and 1/V).

use std::f64::consts::PI;
use viscoroll::contact::{roll, Body, ContactError, ContactSettings, Scene, Scheme};
use viscoroll::creep::RetardationTerm;
use viscoroll::{CreepSpectrum, ModulusKind};

fn settings(n: usize) -> ContactSettings {
    ContactSettings {
        scheme: Scheme::Thesis,
        n,
        ..Default::default()
    }
}

fn sls(ratio: f64, tau_s: f64) -> CreepSpectrum {
    CreepSpectrum {
        kind: ModulusKind::Tensile,
        poisson: 0.5,
        compliance_glassy_per_pa: 1e-9,
        terms: vec![RetardationTerm {
            compliance_per_pa: (ratio - 1.0) * 1e-9,
            tau_s,
        }],
    }
}

/// Hertz line contact (plane strain): half-width a = √(4RN(1−ν²)/(πE)), p₀ = 2N/(πa).
fn hertz(radius_m: f64, load_n_per_m: f64, e_pa: f64, nu: f64) -> (f64, f64) {
    let a = (4.0 * radius_m * load_n_per_m * (1.0 - nu * nu) / (PI * e_pa)).sqrt();
    (2.0 * a, 2.0 * load_n_per_m / (PI * a))
}

#[test]
fn elastic_scene_is_hertz() {
    let spectrum = CreepSpectrum {
        kind: ModulusKind::Tensile,
        poisson: 0.5,
        compliance_glassy_per_pa: 1.0 / 5e6,
        terms: vec![],
    };
    let scene = Scene {
        radius_m: 0.15,
        load_n_per_m: 2000.0,
        speed_m_s: 5.0,
        poisson: Some(0.3),
        body: Body::HALF_SPACE,
    };
    let n = 160;
    let s = roll(&scene, &spectrum, &settings(n)).unwrap();
    let (l, p0) = hertz(0.15, 2000.0, 5e6, 0.3);
    // First-order discretisation error of λ: ≈ 0.25/n relative (Hertz table, contact_thesis);
    // the nodal pressure maximum ≈ 1.5/n below p₀ (pressure error table, 4e-3 at n = 320).
    assert!(
        (s.contact_length_m / l - 1.0).abs() <= 0.5 / n as f64,
        "l = {} vs {l}",
        s.contact_length_m
    );
    assert!(
        (s.max_pressure_pa / p0 - 1.0).abs() <= 2.0 / n as f64,
        "p = {} vs {p0}",
        s.max_pressure_pa
    );
    assert!(s.friction.abs() <= 1e-12 && s.offset_m.abs() <= 1e-12 * l);
    assert!(
        (s.problem.load - 0.25).abs() <= 1e-15,
        "N' = 1/4 by the choice of T"
    );
}

#[test]
fn shear_and_tensile_spectra_agree() {
    // The same material given as tensile J (1/E) or as shear J (1/G = 2(1+ν)/E).
    let t = sls(100.0, 1e-3);
    let nu = 0.45;
    let mut s = t.clone();
    s.kind = ModulusKind::Shear;
    s.poisson = nu;
    s.compliance_glassy_per_pa *= 2.0 * (1.0 + nu);
    s.terms[0].compliance_per_pa *= 2.0 * (1.0 + nu);
    let scene = Scene {
        radius_m: 0.1,
        load_n_per_m: 1000.0,
        speed_m_s: 0.3,
        poisson: Some(nu),
        body: Body::HALF_SPACE,
    };
    let a = roll(&scene, &t, &settings(60)).unwrap();
    let b = roll(&scene, &s, &settings(60)).unwrap();
    // Same dimensionless problem up to rounding in the scale factors; the load loop meets N′ to
    // 1e-10 (1e-8 where rounding noise of the solve, ≈ 1e-9, stops it), so λ and F/N agree to 1e-8.
    assert!((a.friction / b.friction - 1.0).abs() < 1e-8);
    assert!((a.contact_length_m / b.contact_length_m - 1.0).abs() < 1e-8);
}

#[test]
fn speed_limits_of_a_standard_linear_solid() {
    // R = 0.1 m, N = 2000 N/m, E₀ = 1 GPa, E∞ = 1 MPa (ratio 1000), τ = 1 ms. Glassy Hertz width
    // l_g ≈ 0.87 mm, so b = l_g/(Vτ) runs from 9e7 (V = 1e-8 m/s) to 9e-9 (V = 1e8 m/s).
    let spectrum = sls(1000.0, 1e-3);
    let n = 200;
    let (l_glassy, _) = hertz(0.1, 2000.0, 1e9, 0.5);
    let (l_relaxed, _) = hertz(0.1, 2000.0, 1e6, 0.5);
    let speeds: Vec<f64> = (-16..=16).map(|k| 10f64.powf(k as f64 / 2.0)).collect();
    let sols: Vec<_> = speeds
        .iter()
        .map(|&v| {
            roll(
                &Scene {
                    radius_m: 0.1,
                    load_n_per_m: 2000.0,
                    speed_m_s: v,
                    poisson: None,
                    body: Body::HALF_SPACE,
                },
                &spectrum,
                &settings(n),
            )
            .unwrap()
        })
        .collect();
    for (v, s) in speeds.iter().zip(&sols) {
        eprintln!(
            "V = {v:8.1e} m/s: l = {:.5} mm, F/N = {:.4e}, offset = {:.4e} mm, {} solves",
            s.contact_length_m * 1e3,
            s.friction,
            s.offset_m * 1e3,
            s.dimensionless.iterations
        );
    }
    let first = &sols[0];
    let last = sols.last().unwrap();
    // Ends: the Hertz widths, to the first-order discretisation error (0.5/n) plus the physical
    // remainder (b·1000 ≈ 1e-5 at the fast end, 1/b ≈ 1e-8 at the slow end).
    assert!(
        (last.contact_length_m / l_glassy - 1.0).abs() <= 0.5 / n as f64,
        "fast: {}",
        last.contact_length_m
    );
    assert!(
        (first.contact_length_m / l_relaxed - 1.0).abs() <= 0.5 / n as f64,
        "slow: {}",
        first.contact_length_m
    );
    // Friction: a single maximum, and → 0 at both ends like V (slow end, log-slope within 0.02 of 1)
    // and like log(V)/V (fast end: for bξ → 0 the kernel's viscous part is −f·ξ(log|bξ| + γ − 1),
    // so the log-slope is −1 + 1/log(1/b) ≈ −0.95 at b ≈ 1e-8; we accept [−1, −0.9]).
    let fr: Vec<f64> = sols.iter().map(|s| s.friction).collect();
    let peak = fr.iter().cloned().fold(0.0, f64::max);
    let ipeak = fr.iter().position(|&f| f == peak).unwrap();
    assert!(
        fr[..=ipeak].windows(2).all(|w| w[1] > w[0]),
        "not increasing up to the peak: {fr:?}"
    );
    assert!(
        fr[ipeak..].windows(2).all(|w| w[1] < w[0]),
        "not decreasing after the peak: {fr:?}"
    );
    assert!(ipeak > 2 && ipeak < fr.len() - 3);
    assert!(fr[0] < 1e-3 * peak && fr[fr.len() - 1] < 1e-3 * peak);
    let slope = |i: usize, j: usize| (fr[j] / fr[i]).log10() / (speeds[j] / speeds[i]).log10();
    let (s_slow, s_fast) = (slope(0, 2), slope(fr.len() - 3, fr.len() - 1));
    eprintln!("log-slopes: slow end {s_slow:.4}, fast end {s_fast:.4}; peak F/N = {peak:.4e} at V = {} m/s", speeds[ipeak]);
    assert!((s_slow - 1.0).abs() < 0.02, "slow-end slope {s_slow}");
    assert!((-1.0..-0.9).contains(&s_fast), "fast-end slope {s_fast}");
}

#[test]
fn bad_scenes_name_the_field() {
    let spectrum = sls(10.0, 1e-3);
    let bad = Scene {
        radius_m: -1.0,
        load_n_per_m: 10.0,
        speed_m_s: 1.0,
        poisson: None,
        body: Body::HALF_SPACE,
    };
    match roll(&bad, &spectrum, &settings(20)) {
        Err(ContactError::BadValue { field, .. }) => assert_eq!(field, "radius_m"),
        other => panic!("expected a radius error, got {other:?}"),
    }
    let bad = Scene {
        radius_m: 1.0,
        load_n_per_m: 10.0,
        speed_m_s: 1.0,
        poisson: Some(0.7),
        body: Body::HALF_SPACE,
    };
    assert!(matches!(
        roll(&bad, &spectrum, &settings(20)),
        Err(ContactError::BadValue { .. })
    ));
    let mut s = spectrum.clone();
    s.terms[0].tau_s = 0.0;
    let ok = Scene {
        radius_m: 1.0,
        load_n_per_m: 10.0,
        speed_m_s: 1.0,
        poisson: None,
        body: Body::HALF_SPACE,
    };
    assert!(roll(&ok, &s, &settings(20))
        .unwrap_err()
        .to_string()
        .contains("tau_s"));
}
