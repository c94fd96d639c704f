use super::at_lambda::solve_at_lambda;
use crate::contact::body::half_space::auto::at_lambda::{
    solve_at_lambda as hs_solve, QuadratureSettings,
};
use crate::contact::body::half_space::modes::Modes;
use crate::contact::CreepTerm;

#[test]
fn thick_layer_is_the_half_space() {
    for terms in [
        vec![],
        vec![CreepTerm { f: 10.0, b: 1.0 }],
        vec![CreepTerm { f: 3.0, b: 0.5 }, CreepTerm { f: 20.0, b: 4.0 }],
    ] {
        let m = Modes::new(&terms);
        let hs = hs_solve(&m, 1.0, QuadratureSettings::default());
        let s = solve_at_lambda(&m, 1.0, 1e4, 0.3, 8, 0.25);
        eprintln!(
            "hs N' {} β {} F {} | layer {} {} {}",
            hs.load, hs.beta, hs.friction_rho, s.load, s.beta, s.friction_rho
        );
        // the layer approaches the half-space like (λ/h)² (module doc of `collocation`'s tests):
        // 1e−8 at h = 1e4·λ, plus the quadratures' ~1e−13
        assert!((s.load / hs.load - 1.0).abs() < 1e-7);
        assert!((s.beta - hs.beta).abs() < 1e-7 && (s.friction_rho - hs.friction_rho).abs() < 1e-7);
    }
}

#[test]
fn elastic_layer_against_the_chebyshev_bessel_solver() {
    use crate::contact::body::layer::elastic_check::elastic_contact;
    let m = Modes::new(&[]);
    for (h, nu) in [(1.0, 0.5), (0.3, 0.3), (0.1, 0.0), (0.1, 0.5)] {
        let (load, _) = elastic_contact(1.0, h, nu, 40);
        for p in [8, 16, 32, 48] {
            let s = solve_at_lambda(&m, 1.0, h, nu, p, 0.25);
            eprintln!(
                "h {h} ν {nu} p {p}: N' {} vs {load} ({:.1e}), β {}",
                s.load,
                s.load / load - 1.0,
                s.beta
            );
            // geometric convergence in p: from p = 32 on both solvers agree to rounding (the
            // reference's 40 terms converge to ~1e−13, elastic_check.rs)
            if p >= 32 {
                assert!((s.load / load - 1.0).abs() < 1e-9, "h {h} ν {nu} p {p}");
                assert!((s.beta - 0.5).abs() < 1e-12);
            }
        }
    }
}

#[test]
fn viscoelastic_layer_against_the_hat_scheme() {
    use crate::contact::body::layer::{collocation, LayerKernel};
    for (terms, h, nu) in [
        (vec![CreepTerm { f: 10.0, b: 1.0 }], 1.0, 0.5),
        (
            vec![CreepTerm { f: 3.0, b: 0.5 }, CreepTerm { f: 20.0, b: 4.0 }],
            0.3,
            0.3,
        ),
    ] {
        let m = Modes::new(&terms);
        let k = LayerKernel::new(&terms, h, nu).unwrap();
        let a = collocation::solve_at_lambda(&k, 1.0, 512).unwrap();
        let b = collocation::solve_at_lambda(&k, 1.0, 1024).unwrap();
        let rich = |f: fn(&crate::contact::DimensionlessSolution) -> f64| 2.0 * f(&b) - f(&a);
        eprintln!(
            "hat: N' {} β {} F {} (n=1024: {} {} {})",
            rich(|s| s.load),
            rich(|s| s.beta),
            rich(|s| s.friction_rho),
            b.load,
            b.beta,
            b.friction_rho
        );
        let mut prev: Option<f64> = None;
        for p in [8, 16, 32] {
            let s = solve_at_lambda(&m, 1.0, h, nu, p, 0.25);
            eprintln!("p {p}: N' {} β {} F {}", s.load, s.beta, s.friction_rho);
            if let Some(q) = prev {
                if p == 32 {
                    // converged in p (16 → 32: rounding)
                    assert!((s.friction_rho / q - 1.0).abs() < 1e-11);
                }
            }
            prev = Some(s.friction_rho);
            // the hat scheme's Richardson value is first-order extrapolated: its error is about the
            // change of the extrapolation, |X(1024) − X_R| ≈ 4e−4 relative here, and the observed
            // second-order remainder ≈ 2e−5 relative; the spectral answer must lie within 5e−5
            if p == 32 {
                assert!((s.load / rich(|s| s.load) - 1.0).abs() < 5e-5);
                assert!((s.beta - rich(|s| s.beta)).abs() < 5e-5);
                assert!((s.friction_rho / rich(|s| s.friction_rho) - 1.0).abs() < 5e-5);
            }
        }
    }
}

#[test]
fn at_load_against_the_hat_scheme() {
    use super::at_load::{solve_spectral_at_load, SpectralSettings};
    use crate::contact::body::layer::{collocation, LayerKernel, LayerSettings};
    let terms = vec![CreepTerm { f: 3.0, b: 0.5 }, CreepTerm { f: 20.0, b: 4.0 }];
    let (load, h, nu) = (0.1, 0.3, 0.3);
    let k = LayerKernel::new(&terms, h, nu).unwrap();
    let hat = collocation::solve_layer_at_load(
        &k,
        load,
        &LayerSettings {
            tol: 1e-5,
            n_max: 1024,
            ..Default::default()
        },
    )
    .unwrap();
    for tol in [1e-4, 1e-6, 1e-8] {
        let s = solve_spectral_at_load(&terms, load, h, nu, &SpectralSettings { tol, p_max: 96 })
            .unwrap()
            .unwrap();
        eprintln!(
            "tol {tol}: λ {} F {} est {:.1e} iters {} p {} warn {:?} | hat λ {} F {} est {:.1e}",
            s.solution.lambda,
            s.solution.friction_rho,
            s.error_estimate,
            s.solution.iterations,
            s.solution.n,
            s.warnings,
            hat.solution.lambda,
            hat.solution.friction_rho,
            hat.error_estimate
        );
    }
}
