//! The dispatch arms of [`super::solve_at_load`] and [`super::solve_at_lambda`] for the layer and
//! Winkler bodies, against the layer functions they must call: the body's thickness in metres is
//! divided by the scene's length scale V·T (here 2.5e−3 m, so a missing or inverted division changes
//! h′ by a factor 6 or more), the layer's tolerance is the scene's `auto.tol` (the spectral solver;
//! `layer_at_load` floors only its hat fallback), at given λ the layer uses `settings.n` intervals,
//! and the two Winkler bodies keep their columns apart. The same inputs give bit-identical results, so equality is exact.

use super::layer::{
    collocation, layer_at_load, winkler_at_load, LayerKernel, LayerSettings, Winkler,
    WinklerColumns,
};
use super::{solve_at_lambda, solve_at_load, Body};
use crate::contact::load::LoadSettings;
use crate::contact::{ContactSettings, CreepTerm, DimensionlessScene};

const LENGTH_SCALE_M: f64 = 2.5e-3;

fn problem(poisson: f64) -> DimensionlessScene {
    DimensionlessScene {
        terms: vec![CreepTerm { f: 10.0, b: 1.0 }, CreepTerm { f: 0.5, b: 0.05 }],
        load: 0.25,
        rho: 40.0,
        time_scale_s: 1e-3,
        length_scale_m: LENGTH_SCALE_M,
        pressure_scale_pa: 1e6,
        poisson,
        compliance_factor_per_pa: 1e-6,
    }
}

#[test]
fn layer_arm_at_load_calls_the_layer_with_h_over_vt_and_the_scene_tol() {
    let p = problem(0.5);
    let h_m = 1.5e-3; // h′ = 0.6
    let body = Body::Layer { thickness_m: h_m };
    for tol in [1e-3, 1e-6] {
        let got = solve_at_load(&body, &p, &ContactSettings::auto(tol)).unwrap();
        let want = layer_at_load(
            &p.terms,
            p.load,
            h_m / LENGTH_SCALE_M,
            p.poisson,
            &LayerSettings {
                tol,
                n_max: 512,
                ..Default::default()
            },
        )
        .unwrap();
        assert_eq!(got, want.solution, "tol {tol}");
        assert_eq!(got.scheme, "layer-spectral");
        // and it is not the half-space's answer (the cover matters at h′ = 0.6)
        let hs = solve_at_load(&Body::HalfSpace, &p, &ContactSettings::auto(tol)).unwrap();
        assert!((hs.lambda - got.lambda).abs() > 0.1 * got.lambda);
    }
}

#[test]
fn layer_arm_at_lambda_uses_the_collocation_with_settings_n() {
    let p = problem(0.3);
    let h_m = 1e-3;
    let body = Body::Layer { thickness_m: h_m };
    let settings = ContactSettings {
        n: 48,
        ..ContactSettings::default()
    };
    let got = solve_at_lambda(&body, &p, 0.8, &settings).unwrap();
    let k = LayerKernel::new(&p.terms, h_m / LENGTH_SCALE_M, 0.3).unwrap();
    let want = collocation::solve_at_lambda(&k, 0.8, 48).unwrap();
    assert_eq!(got, want);
    assert_eq!(got.n, 48);
}

#[test]
fn winkler_arms_keep_their_columns() {
    let p = problem(0.3);
    let h_m = 5e-4; // h′ = 0.2
    let h = h_m / LENGTH_SCALE_M;
    let settings = ContactSettings::default();
    let mut answers = Vec::new();
    for (body, columns) in [
        (Body::Winkler { height_m: h_m }, WinklerColumns::Uniaxial),
        (
            Body::WinklerConstrained { height_m: h_m },
            WinklerColumns::Constrained,
        ),
    ] {
        let got = solve_at_load(&body, &p, &settings).unwrap();
        let want =
            winkler_at_load(&p.terms, p.load, columns, h, 0.3, &LoadSettings::default()).unwrap();
        assert_eq!(got, want.solution, "{body:?}");
        let at = solve_at_lambda(&body, &p, 0.7, &settings).unwrap();
        let want_at = Winkler::new(&p.terms, columns, h, 0.3)
            .unwrap()
            .at_lambda(0.7)
            .unwrap()
            .solution;
        assert_eq!(at, want_at, "{body:?}");
        answers.push(got.lambda);
    }
    // uniaxial columns (E = 2μ(1+ν)) are softer than constrained ones (M = 2μ(1−ν)/(1−2ν)) at ν = 0.3:
    // E/M = (1+ν)(1−2ν)/(1−ν) = 0.74, so the uniaxial contact is longer, by (M/E)^{1/3} ≈ 1.1 elastically
    assert!(answers[0] > 1.05 * answers[1], "{answers:?}");
}

#[test]
fn bodies_refuse_bad_thickness_and_the_rigid_constrained_winkler() {
    let p = problem(0.5);
    let s = ContactSettings::default();
    for body in [
        Body::Layer { thickness_m: 0.0 },
        Body::Winkler { height_m: -1.0 },
        Body::WinklerConstrained { height_m: f64::NAN },
    ] {
        assert!(solve_at_load(&body, &p, &s).is_err(), "{body:?}");
        assert!(solve_at_lambda(&body, &p, 1.0, &s).is_err(), "{body:?}");
    }
    // constrained columns are rigid at ν = ½: refused, not solved
    let e = solve_at_load(&Body::WinklerConstrained { height_m: 1e-3 }, &p, &s);
    assert!(e.is_err());
}
