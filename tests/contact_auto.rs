//! The `auto` contact scheme (issue 4): exact one-term cases, load loop over speeds, mode reduction,
//! contact conditions.

use viscoroll::contact::auto::{solve_at_lambda, QuadratureSettings};
use viscoroll::contact::controlled::{solve_auto_at_lambda, solve_auto_at_load, AutoSettings};
use viscoroll::contact::modes::Modes;
use viscoroll::contact::CreepTerm;

fn settings(tol: f64) -> AutoSettings {
    AutoSettings {
        tol,
        ..AutoSettings::default()
    }
}

#[test]
fn probe_one_term_load_over_speeds() {
    let term = [CreepTerm { f: 10.0, b: 1.0 }];
    for k in -8..=8 {
        let load = 10f64.powi(k);
        let s = solve_auto_at_load(&term, load, &settings(1e-9)).unwrap();
        let m = Modes::new(&term);
        let r = solve_at_lambda(&m, s.solution.lambda, QuadratureSettings { step: 0.2 });
        eprintln!(
            "N' {load:e}: lam {:.6e} fr {:.6e} it {} est {:.2e} load err {:.2e} min p {:.2e}",
            s.solution.lambda,
            s.solution.friction_rho,
            s.solution.iterations,
            s.solution.error_estimate.unwrap(),
            (r.load / load - 1.0).abs(),
            s.min_pressure_ratio
        );
    }
    let s = solve_auto_at_lambda(&[CreepTerm { f: 1000.0, b: 1.0 }], 1.0, &settings(1e-9)).unwrap();
    eprintln!(
        "{:?}",
        (
            s.solution.beta,
            s.solution.friction_rho,
            s.solution.error_estimate,
            s.min_pressure_ratio
        )
    );
}
