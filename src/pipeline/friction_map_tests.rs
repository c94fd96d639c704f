//! Tests of the reduced-variable friction maps: the exact scaling against direct scene solves, the
//! interpolant against direct solves at random off-node points, the Chebyshev machinery on known
//! functions, and input errors.

use super::*;
use crate::contact::{roll, AutoSettings, Body, ContactSettings, Scene, Scheme};
use crate::testdata::{broad_spectrum, SplitMix64};
use crate::ShiftLaw;

fn creep() -> CreepSpectrum {
    crate::creep::relaxation_to_creep(&broad_spectrum())
        .expect("broad spectrum converts")
        .0
}

/// A WLF law with the universal constants (Williams, Landel & Ferry 1955) at T_ref = 20 °C:
/// log a_T from +12.8 at −40 °C to −2.5 at +60 °C.
fn wlf() -> ShiftLaw {
    ShiftLaw::Wlf {
        t_ref_c: 20.0,
        c1: 8.86,
        c2_k: 101.6,
    }
}

/// Reference solves: the `auto` scheme at 1e−8 (its 1e−7…1e−9 solves agree to ~1e−9).
fn reference() -> AutoSettings {
    AutoSettings {
        tol: 1e-8,
        gap_check: false,
        ..AutoSettings::default()
    }
}

/// [`reference`] for the direct solves of whole scenes.
fn reference_roll() -> ContactSettings {
    ContactSettings {
        scheme: Scheme::Auto,
        auto: reference(),
        ..ContactSettings::default()
    }
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

#[test]
fn scenes_sharing_s_share_the_dimensionless_answer() {
    let c = creep();
    let law = wlf();
    let p = ReducedProblem::new(&c, None).unwrap();
    // Base scene at 0 °C; the others change R, N*, V and T so that s = l_g/(V a_T) is unchanged:
    // l_g ∝ √(R N*), so R×9 needs V×3, N*×4 needs V×2, and T → T′ needs V×a_T(T)/a_T(T′).
    let a = |t: f64| 10f64.powf(law.log10_a_t(t));
    let (r0, n0, v0, t0) = (0.05, 5000.0, 2.0, 0.0);
    let cases = [
        (r0, n0, v0, t0),
        (9.0 * r0, n0, 3.0 * v0, t0),
        (r0, 4.0 * n0, 2.0 * v0, t0),
        (r0, n0, v0 * a(t0) / a(10.0), 10.0),
        (4.0 * r0, 0.25 * n0, v0 * a(t0) / a(-10.0), -10.0),
    ];
    let s0 = p.reduced_time_s(r0, n0, v0, a(t0));
    let mut first: Option<(f64, f64)> = None;
    for &(r, n, v, t) in &cases {
        assert!(rel(p.reduced_time_s(r, n, v, a(t)), s0) < 1e-12);
        let at = c.at_temperature(&law, t, None).unwrap();
        let scene = Scene {
            radius_m: r,
            load_n_per_m: n,
            speed_m_s: v,
            poisson: None,
            body: Body::HalfSpace,
        };
        let sol = roll(&scene, &at.spectrum, &reference_roll()).unwrap();
        let d = &sol.dimensionless;
        // Same dimensionless problem up to rounding of bᵢ (~1e−15), each solve within 1e−8 of it.
        match first {
            None => first = Some((d.friction_rho, d.lambda)),
            Some((fr, la)) => {
                assert!(
                    rel(d.friction_rho, fr) < 3e-8,
                    "{t} °C: {} vs {fr}",
                    d.friction_rho
                );
                assert!(rel(d.lambda, la) < 3e-8, "{t} °C: {} vs {la}", d.lambda);
            }
        }
        // The exact scalings back to SI: F/N = φ·l_g/R, l = λ·l_g.
        let lg = p.glassy_length_m(r, n);
        assert!(rel(sol.friction, d.friction_rho * lg / r) < 1e-12);
        assert!(rel(sol.contact_length_m, d.lambda * lg) < 1e-12);
    }
    // And the reduced solve at ln s0 is that same answer.
    let red = p.solve(s0.ln(), &reference()).unwrap();
    let (fr, la) = first.unwrap();
    assert!(rel(red.friction_rho, fr) < 3e-8 && rel(red.lambda, la) < 3e-8);
}

#[test]
fn different_s_reproduce_roll() {
    let c = creep();
    let law = wlf();
    let p = ReducedProblem::new(&c, None).unwrap();
    for &(r, n, v, t) in &[
        (0.0665, 1e4, 4.0, -30.0),
        (0.3, 2e4, 20.0, 20.0),
        (0.0665, 3e3, 0.5, 50.0),
    ] {
        let at = c.at_temperature(&law, t, None).unwrap();
        let scene = Scene {
            radius_m: r,
            load_n_per_m: n,
            speed_m_s: v,
            poisson: None,
            body: Body::HalfSpace,
        };
        let direct = roll(&scene, &at.spectrum, &reference_roll()).unwrap();
        let s = p.reduced_time_s(r, n, v, 10f64.powf(at.log10_a_t));
        let red = p.solve(s.ln(), &reference()).unwrap();
        let lg = p.glassy_length_m(r, n);
        // Both at 1e−8: agreement to a few 1e−8.
        assert!(
            rel(red.friction_rho * lg / r, direct.friction) < 3e-8,
            "{t} °C"
        );
        assert!(
            rel(red.lambda * lg, direct.contact_length_m) < 3e-8,
            "{t} °C"
        );
    }
}

#[test]
fn map_matches_direct_solves_at_random_points() {
    let c = creep();
    let law = wlf();
    let p = ReducedProblem::new(&c, None).unwrap();
    let mut rng = SplitMix64::new(8);
    let mut pick = |lo: f64, hi: f64| lo + (hi - lo) * rng.uniform();
    // 300 random scenes: V in 0.5…40 m/s, N* in 2…50 kN/m (log-uniform), T in −40…60 °C.
    let scenes: Vec<(f64, f64, f64, f64)> = (0..300)
        .map(|k| {
            let r = if k % 2 == 0 { 0.0665 } else { 0.3 };
            let v = pick(0.5f64.ln(), 40f64.ln()).exp();
            let n = pick(2e3f64.ln(), 5e4f64.ln()).exp();
            let t = pick(-40.0, 60.0);
            (r, n, v, t)
        })
        .collect();
    let queries: Vec<MapQuery> = scenes
        .iter()
        .map(|&(r, n, v, t)| MapQuery {
            radius_m: r,
            load_n_per_m: n,
            speed_m_s: v,
            a_t: 10f64.powf(law.log10_a_t(t)),
        })
        .collect();
    // Every 25th point against a direct scene solve (random points are off the nodes).
    let direct: Vec<(usize, f64, f64)> = scenes
        .iter()
        .enumerate()
        .step_by(25)
        .map(|(k, &(r, n, v, t))| {
            let at = c.at_temperature(&law, t, None).unwrap();
            let scene = Scene {
                radius_m: r,
                load_n_per_m: n,
                speed_m_s: v,
                poisson: None,
                body: Body::HalfSpace,
            };
            let d = roll(&scene, &at.spectrum, &reference_roll()).unwrap();
            (k, d.friction, d.contact_length_m)
        })
        .collect();
    // The map's tolerance must hold for F/N and the contact length at the main job's 1e−4 and at
    // 1e−6, with the 1e−8 reference's own error negligible beside it.
    for tol in [1e-4, 1e-6] {
        let settings = MapSettings {
            tol,
            ..MapSettings::default()
        };
        let (values, curve) = friction_map(&p, &queries, &settings).unwrap();
        assert!(curve.error_estimate <= 0.5 * tol);
        assert_eq!(values.len(), queries.len());
        let mut worst = 0.0f64;
        for &(k, f, l) in &direct {
            let m = values[k];
            let e = rel(m.friction, f).max(rel(m.contact_length_m, l));
            assert!(e <= tol, "tol {tol:e}: point {k} {:?}: {e:e}", scenes[k]);
            worst = worst.max(e);
        }
        eprintln!(
            "tol {tol:e}: map vs direct: worst relative error {worst:.2e}; estimate {:.2e}, {} solves, {} panels",
            curve.error_estimate,
            curve.solves,
            curve.panels()
        );
        assert!(
            worst > 0.0,
            "the map is an interpolant, not a copy of the solves"
        );
    }
}

#[test]
fn chebyshev_interpolation_is_exact_for_polynomials_and_estimates_exp() {
    // T₃ sampled at the 17 Lobatto points has coefficients δ_j3 (to rounding).
    let n = 16;
    let t: Vec<f64> = (0..=n).map(|k| (PI * k as f64 / n as f64).cos()).collect();
    let c = lobatto_coefficients(
        &t.iter()
            .map(|&x| 4.0 * x * x * x - 3.0 * x)
            .collect::<Vec<_>>(),
    );
    for (j, cj) in c.iter().enumerate() {
        let want = if j == 3 { 1.0 } else { 0.0 };
        assert!((cj - want).abs() < 1e-14, "c[{j}] = {cj}");
    }
    // e^{4x} on [−1, 1]: the degree-16 interpolant's true error (≈ 2·I₁₇(4) ≈ 1e−9, the first
    // neglected coefficient, c_j = 2I_j(4)) is below the estimate Σ_{j≥12}|c_j| ≈ 2I₁₂(4) ≈ 2e−5.
    let f = |x: f64| (4.0 * x).exp();
    let c = lobatto_coefficients(&t.iter().map(|&x| f(x)).collect::<Vec<_>>());
    let est = tail(&c);
    let err = (0..=1000)
        .map(|k| -1.0 + 2.0 * k as f64 / 1000.0)
        .map(|x| (clenshaw(&c, x) - f(x)).abs())
        .fold(0.0, f64::max);
    assert!(err <= est && est < 1e-4, "error {err:e}, estimate {est:e}");
}

#[test]
fn bad_inputs_name_the_field() {
    let c = creep();
    let p = ReducedProblem::new(&c, None).unwrap();
    let q = MapQuery {
        radius_m: 0.1,
        load_n_per_m: 1e4,
        speed_m_s: 0.0,
        a_t: 1.0,
    };
    let e = friction_map(&p, &[q], &MapSettings::default()).unwrap_err();
    assert!(e.to_string().contains("speed_m_s"), "{e}");
    let e = friction_map(&p, &[], &MapSettings::default()).unwrap_err();
    assert!(e.to_string().contains("points"), "{e}");
    let bad_tol = MapSettings {
        tol: 0.5,
        ..MapSettings::default()
    };
    let q = MapQuery {
        speed_m_s: 1.0,
        ..q
    };
    let e = friction_map(&p, &[q], &bad_tol).unwrap_err();
    assert!(e.to_string().contains("tol"), "{e}");
    let e = ReducedProblem::new(&c, Some(0.7)).unwrap_err();
    assert!(e.to_string().contains("poisson"), "{e}");
}
