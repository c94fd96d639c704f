//! A fluid (E∞ = 0, issue 29 item 4; docs/MATH.md §17): `convert` gives its creep function with the
//! flow term t/η₀, and the rolling contact refuses it because on the half-space it has no steady state.
//! The refusal is checked against the limit it claims: friction at E∞ = ε grows like ln(1/ε) with the
//! slope the slow-mode law of §8.3 gives, so it has no E∞ → 0⁺ limit.

use crate::support::{stderr, temp_dir, viscoroll};
use std::f64::consts::{LN_10, PI};
use viscoroll::contact::{roll, ContactSettings, Scene, Scheme};
use viscoroll::creep::relaxation_to_creep;
use viscoroll::prony::{RelaxationSpectrum, RelaxationTerm};
use viscoroll::ModulusKind;

/// E(t) = E∞ + E₁e^(−t/ρ), tensile, ν = 0.5.
fn sls(e_inf_pa: f64, e1_pa: f64, rho_s: f64) -> RelaxationSpectrum {
    RelaxationSpectrum {
        kind: ModulusKind::Tensile,
        poisson: 0.5,
        modulus_inf_pa: e_inf_pa,
        terms: vec![RelaxationTerm {
            modulus_pa: e1_pa,
            tau_s: rho_s,
        }],
    }
}

/// Friction of a standard linear solid as E∞ → 0⁺ (E₁ = 1 GPa, ρ = 1 ms, η₀ = 1e6 Pa·s; R = 0.1 m,
/// N* = 2 kN/m, V = 1 m/s). Its retardation time τ = ρE₀/E∞ runs away while J₁/τ → 1/η₀, so in the
/// contact's units the term keeps f → f₀ = T/(J_g η₀) ≈ 0.87 and b = T/τ → 0. By the exact law of
/// MATH §8.3 (a slow mode's ln b is a linear kernel term, which moves only β), ρF/N rises by
/// (f₀N′/2)·ln 10 per decade of b, i.e. F/N by C·N*·ln 10/(π·V·J_g·η₀) per decade that E∞ falls
/// (C = 2(1 − ν²)J_g), whatever the rest of the solution does: no limit to converge to. Both the exact
/// one-term solution and the default `auto` scheme (the path `roll` takes) show that slope; 2e-3
/// relative covers the O(c) remainder of the law (c = bλ/2 ≤ 1e-5 here) and auto's tolerance 1e-6.
#[test]
fn friction_grows_like_ln_one_over_e_inf_without_a_limit() {
    let (e1, rho, r_m, n_per_m, v) = (1e9, 1e-3, 0.1, 2000.0, 1.0);
    let eta = e1 * rho;
    let scene = Scene {
        radius_m: r_m,
        load_n_per_m: n_per_m,
        speed_m_s: v,
        poisson: Some(0.5),
        body: Default::default(),
    };
    for scheme in [Scheme::Exact, Scheme::Auto] {
        let settings = ContactSettings {
            scheme,
            ..Default::default()
        };
        let friction: Vec<f64> = [1e4, 1e3, 1e2, 1e1]
            .iter()
            .map(|&e_inf| {
                let (creep, _) = relaxation_to_creep(&sls(e_inf, e1, rho)).unwrap();
                roll(&scene, &creep, &settings).unwrap().friction
            })
            .collect();
        let j_g = 1.0 / (e1 + 1e3);
        let c = 2.0 * (1.0 - 0.25) * j_g;
        let law = c * n_per_m * LN_10 / (PI * v * j_g * eta);
        for w in friction.windows(2) {
            let step = w[1] - w[0];
            assert!(
                (step / law - 1.0).abs() < 2e-3,
                "{scheme:?}: F/N {friction:?}, step per decade {step:e}, law {law:e}"
            );
        }
    }
}

/// `convert` on a Maxwell fluid writes J(t) = 1/E₁ + t/(E₁ρ) (no retardation term, the flow term as
/// `viscosity_pa_s`), its checks hold, and `roll` refuses both that creep function and the
/// relaxation spectrum itself, with the reason.
#[test]
fn convert_gives_the_flow_term_and_roll_refuses_a_fluid_with_the_reason() {
    let dir = temp_dir("fluid-rolling");
    let relax = dir.join("maxwell.json");
    std::fs::write(&relax, serde_json::to_string(&sls(0.0, 2e6, 1e-3)).unwrap()).unwrap();
    let creep = dir.join("creep.json");
    let o = viscoroll(&[
        "convert",
        relax.to_str().unwrap(),
        "-o",
        creep.to_str().unwrap(),
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let c = &j["creep_spectrum"];
    assert_eq!(c["compliance_glassy_per_pa"].as_f64(), Some(5e-7));
    assert_eq!(c["viscosity_pa_s"].as_f64(), Some(2e3));
    assert_eq!(c["terms"].as_array().map(Vec::len), Some(0));
    assert!(j["checks"]["max_abs_product_error"].as_f64().unwrap() < 1e-14);
    assert!(j["checks"]["relaxed_product"].is_null());
    let written: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&creep).unwrap()).unwrap();
    assert_eq!(&written, c);
    for input in [&creep, &relax] {
        let o = viscoroll(&[
            "roll",
            input.to_str().unwrap(),
            "--radius-mm",
            "100",
            "--load-n-per-m",
            "2000",
            "--speed-m-s",
            "1",
        ]);
        assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
        let e = stderr(&o);
        assert!(
            e.contains("no steady state") && e.contains("ln(1/ε)"),
            "{}: {e}",
            input.display()
        );
    }
}
