//! Property test of the covered bodies (issue 14, "Numbers to reach": the error estimate honoured over
//! the full range): random spectra over 24 decades (1–30 terms, retardation rates log-uniform over
//! 1e−12…1e12 in units of 1/T, J∞/J_g log-uniform in 1.5…1e3), covers h/λ log-uniform from 1e−3 to
//! 1e3 (λ the half-space contact length at N′ = ¼), ν uniform on [0, ½] (one case in four exactly ½),
//! solved by `auto` at tol 1e−3 (the main job's `COVER_TOL`). Properties:
//!
//! 1. every answer is finite with λ > 0, and a body other than the layer is chosen only with a model
//!    error estimate ≤ tol;
//! 2. an answer that misses the tolerance says so (a "tolerance not reached" warning);
//! 3. the estimate is honoured: the answer differs from the bonded layer's (reference: tol 2e−5,
//!    n ≤ 1024) by at most its error estimate + its model error estimate + the reference's own
//!    estimate, for ρF/N and λ — checked wherever the reference is computable (h/λ ≥ 0.02, so that
//!    n = 1024 intervals resolve the cover 20 times, and the reference met 1e−4) and the answer claims
//!    its tolerance. The other cases (thin covers on the Winkler or flagged) are counted and printed.
//!
//! 4. the spectral layer solver alone (the layer body's default, `layer::spectral`) at tol 1e−6 and 1e−4 over
//!    the same random spectra, covers and ν: every answer it gives (it declines covers too thin for
//!    its degree cap; those, and refinements it declines, are counted) is finite, says when it
//!    misses tol, and differs from its own refinement at tol 1e−9 by at most its estimate plus the
//!    refinement's ([`spectral_run`]).
//!
//! The seed comes from `VISCOROLL_SEED` (tests/seed.rs). CI runs [`CI_CASES`]; the larger sweep is
//! `#[ignore]`d: `cargo test --release --lib layer_props::sweep -- --ignored --nocapture`.

use viscoroll::contact::body::layer::spectral::{solve_spectral_at_load, SpectralSettings};
use viscoroll::contact::body::layer::{layer_at_load, LayerSettings};
use viscoroll::contact::cover::solve_cover;
use viscoroll::contact::half_space::auto::{solve_auto_at_load, AutoSettings};
use viscoroll::contact::Body;
use viscoroll::contact::CreepTerm;

/// Cases in CI (each: a half-space solve, the `auto` answer and a layer reference at tol 2e−5).
const CI_CASES: usize = 6;
const TOL: f64 = 1e-3;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi / lo).ln() * self.next()).exp()
    }
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / b.abs()
    }
}

/// One random case of [`run`]: m terms, J∞/J_g, the creep terms, h/λ of the half-space, ν.
fn random_case(rng: &mut Rng) -> (usize, f64, Vec<CreepTerm>, f64, f64) {
    let m = 1 + (rng.next() * 30.0) as usize;
    let ratio = rng.log_uniform(1.5, 1e3);
    let weights: Vec<f64> = (0..m).map(|_| rng.next() + 0.05).collect();
    let wsum: f64 = weights.iter().sum();
    let terms: Vec<CreepTerm> = weights
        .iter()
        .map(|w| {
            let b = rng.log_uniform(1e-12, 1e12);
            CreepTerm {
                f: (ratio - 1.0) * w / wsum * b,
                b,
            }
        })
        .collect();
    let hr = rng.log_uniform(1e-3, 1e3);
    let nu = if rng.next() < 0.25 {
        0.5
    } else {
        0.5 * rng.next()
    };
    (m, ratio, terms, hr, nu)
}

/// (checked, unchecked) counts over `cases` random cases.
fn run(seed: u64, cases: usize) -> (usize, usize) {
    let mut rng = Rng(seed);
    let load = 0.25;
    let (mut checked, mut unchecked) = (0, 0);
    for case in 0..cases {
        let (m, ratio, terms, hr, nu) = random_case(&mut rng);
        let hs = solve_auto_at_load(
            &terms,
            load,
            &AutoSettings {
                tol: 1e-6,
                ..Default::default()
            },
        )
        .unwrap();
        let h = hr * hs.lambda;
        let label = format!("case {case}: {m} terms, J∞/J_g {ratio:.3e}, h/λ {hr:.3e}, ν {nu:.3}");
        let a = solve_cover(&terms, load, nu, &Body::Auto { thickness_m: h }, TOL)
            .unwrap_or_else(|e| panic!("{label}: {e}"));
        let s = &a.answer.solution;
        // 1. finite, λ > 0; a cheaper body only within tol
        assert!(
            s.lambda.is_finite() && s.lambda > 0.0 && s.friction_rho.is_finite(),
            "{label}"
        );
        if !matches!(a.model, Body::Layer { .. }) {
            let e = a.model_error_estimate.expect("model error estimate");
            assert!(e <= TOL, "{label}: {} with model error {e}", a.model.name());
        }
        // 2. a missed tolerance is said
        let flagged = a
            .answer
            .warnings
            .iter()
            .any(|w| w.contains("tolerance not reached"));
        if a.answer.error_estimate > TOL {
            assert!(
                flagged,
                "{label}: estimate {} unflagged",
                a.answer.error_estimate
            );
        }
        // 3. honoured estimate against the layer reference
        let h_over_l = h / s.lambda;
        if flagged || h_over_l < 0.02 || matches!(a.model, Body::WinklerConstrained { .. }) {
            println!(
                "{label}: {} (h/λ {h_over_l:.2e}, estimate {:.1e}{}): no reference",
                a.model.name(),
                a.answer.error_estimate,
                if flagged { ", flagged" } else { "" }
            );
            unchecked += 1;
            continue;
        }
        let r = layer_at_load(
            &terms,
            load,
            h,
            nu,
            &LayerSettings {
                tol: 2e-5,
                n_max: 1024,
                ..Default::default()
            },
        )
        .unwrap();
        if r.error_estimate > 1e-4 {
            println!(
                "{label}: reference estimate {:.1e}: unchecked",
                r.error_estimate
            );
            unchecked += 1;
            continue;
        }
        let allowed =
            a.answer.error_estimate + a.model_error_estimate.unwrap_or(0.0) + r.error_estimate;
        let ef = rel(s.friction_rho, r.solution.friction_rho);
        let el = rel(s.lambda, r.solution.lambda);
        println!(
            "{label}: {} n {}: error ρF/N {ef:.1e}, λ {el:.1e} ≤ {allowed:.1e} (estimate {:.1e}, model {:.1e}, reference {:.1e})",
            a.model.name(),
            s.n,
            a.answer.error_estimate,
            a.model_error_estimate.unwrap_or(0.0),
            r.error_estimate
        );
        assert!(ef <= allowed && el <= allowed, "{label}");
        checked += 1;
    }
    (checked, unchecked)
}

/// Property 4 of the module doc over `cases` random cases: (checked, declined as too thin).
fn spectral_run(seed: u64, cases: usize, tol: f64) -> (usize, usize) {
    let mut rng = Rng(seed ^ 0x5eed_5bec);
    let load = 0.25;
    let (mut checked, mut declined) = (0, 0);
    for case in 0..cases {
        let (m, ratio, terms, hr, nu) = random_case(&mut rng);
        let hs = solve_auto_at_load(&terms, load, &AutoSettings::default()).unwrap();
        let h = hr * hs.lambda;
        let label =
            format!("spectral case {case}: {m} terms, J∞/J_g {ratio:.3e}, h/λ {hr:.3e}, ν {nu:.3}");
        let solve = |tol: f64| {
            solve_spectral_at_load(
                &terms,
                load,
                h,
                nu,
                &SpectralSettings {
                    tol,
                    p_max: 48,
                    start: None,
                    checks: true,
                },
            )
            .unwrap_or_else(|e| panic!("{label}: {e}"))
        };
        let Some(a) = solve(tol) else {
            println!("{label}: declined (cover too thin for p ≤ 48)");
            declined += 1;
            continue;
        };
        let s = &a.solution;
        assert!(
            s.lambda.is_finite() && s.lambda > 0.0 && s.friction_rho.is_finite(),
            "{label}"
        );
        let flagged = a
            .warnings
            .iter()
            .any(|w| w.contains("tolerance not reached"));
        assert!(
            a.error_estimate <= tol || flagged,
            "{label}: unflagged {}",
            a.error_estimate
        );
        let Some(r) = solve(1e-9) else {
            // the refinement needs a degree above the cap (p grows like log(1/tol)·λ/h)
            println!("{label}: refinement declined (cover too thin for p ≤ 48 at 1e−9)");
            declined += 1;
            continue;
        };
        let allowed = a.error_estimate + r.error_estimate;
        let ef = rel(s.friction_rho, r.solution.friction_rho);
        let el = rel(s.lambda, r.solution.lambda);
        println!(
            "{label}: p {}: error ρF/N {ef:.1e}, λ {el:.1e} ≤ {allowed:.1e} (estimate {:.1e}, refinement {:.1e})",
            s.n, a.error_estimate, r.error_estimate
        );
        assert!(ef <= allowed && el <= allowed, "{label}");
        checked += 1;
    }
    (checked, declined)
}

#[test]
fn spectral_estimate_honoured_at_tol_1e6() {
    let seed = crate::tests::seed::seed("layer_props::spectral_estimate_honoured_at_tol_1e6");
    let (checked, declined) = spectral_run(seed, CI_CASES, 1e-6);
    println!("spectral: checked {checked}, declined {declined}");
}

#[test]
fn spectral_estimate_honoured_at_tol_1e4() {
    // the speed goal's tolerance: the walk stops earlier and carries further to the root
    // (`spectral::walk`), so its carry's error counts more here than at 1e−6
    let seed = crate::tests::seed::seed("layer_props::spectral_estimate_honoured_at_tol_1e4");
    let (checked, declined) = spectral_run(seed, CI_CASES, 1e-4);
    println!("spectral: checked {checked}, declined {declined}");
}

#[test]
#[ignore]
fn spectral_sweep() {
    let seed = crate::tests::seed::seed("layer_props::spectral_sweep");
    let (checked, declined) = spectral_run(seed, 60, 1e-6);
    println!("spectral: checked {checked}, declined {declined}");
    let (checked, declined) = spectral_run(seed, 60, 1e-4);
    println!("spectral: checked {checked}, declined {declined}");
}

#[test]
fn estimate_honoured_over_the_issue_range() {
    let seed = crate::tests::seed::seed("layer_props::estimate_honoured_over_the_issue_range");
    let (checked, unchecked) = run(seed, CI_CASES);
    println!("checked {checked}, without reference {unchecked}");
}

#[test]
#[ignore]
fn sweep() {
    let seed = crate::tests::seed::seed("layer_props::sweep");
    let (checked, unchecked) = run(seed, 60);
    println!("checked {checked}, without reference {unchecked}");
}
