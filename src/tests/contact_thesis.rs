//! The thesis scheme on its check cases: Table 1 (one-parameter model), the Hertz limit with its error
//! against n, a 10-term spectrum over eight decades of λ and of speed, and the load loop where the
//! thesis' secant fails.

use viscoroll::contact::load::thesis_secant;
use viscoroll::contact::numerics::{hat, kernel::Kernel};
use viscoroll::contact::{solve_at_lambda, solve_at_load, ContactSettings, CreepTerm, Scheme};

fn settings(n: usize) -> ContactSettings {
    ContactSettings {
        scheme: Scheme::Thesis,
        n,
        ..Default::default()
    }
}

#[test]
fn table_1_one_parameter_model() {
    // Thesis Table 1: f = 10, b = 1, n = 40, at λ = 1 (docs/MATH.md §1): β/λ = 0.1959, ρF/N = 0.43093.
    // Tolerances from the issue: the printed digits are rounded and the thesis' own grid details
    // (node placement) are not stated beyond n = 40 intervals.
    let s = solve_at_lambda(&[CreepTerm { f: 10.0, b: 1.0 }], 1.0, &settings(40)).unwrap();
    let bl = s.beta / s.lambda;
    eprintln!(
        "Table 1, n = 40: beta/lambda = {bl:.6}, rho F/N = {:.6}, N' = {:.6}",
        s.friction_rho, s.load
    );
    assert!((bl - 0.1959).abs() <= 2e-4, "beta/lambda = {bl}");
    assert!(
        (s.friction_rho - 0.43093).abs() <= 5e-4,
        "rho F/N = {}",
        s.friction_rho
    );
    // The same case converges toward Goodier & Loutzenheiser's 0.1952 as n grows (first order):
    // at n = 320 within 1e-4 of it (the n = 40 → 320 change is 5.5e-4, and the Richardson limit of
    // n = 160, 320 is 0.19520).
    let f = solve_at_lambda(&[CreepTerm { f: 10.0, b: 1.0 }], 1.0, &settings(320)).unwrap();
    assert!(
        (f.beta / f.lambda - 0.1952).abs() <= 1e-4,
        "n = 320: beta/lambda = {}",
        f.beta / f.lambda
    );
}

#[test]
fn hertz_limit_error_table() {
    // f = 0: Q′ = (1/π)√(ξ(λ−ξ)), β = λ/2, N′ = λ²/4, friction 0 (docs/MATH.md §3).
    let lambda = 2.0;
    let mut prev: Option<(f64, f64)> = None;
    eprintln!("   n    |N'/(λ²/4) − 1|   max|Q' − Q'_Hertz|/max Q'   |β/λ − 1/2|   |ρF/N|");
    for n in [10, 20, 40, 80, 160, 320] {
        let s = solve_at_lambda(&[CreepTerm { f: 0.0, b: 1.0 }], lambda, &settings(n)).unwrap();
        let load_err = (s.load / (lambda * lambda / 4.0) - 1.0).abs();
        let qmax = lambda / (2.0 * std::f64::consts::PI);
        let p_err =
            s.xi.iter()
                .zip(&s.pressure)
                .map(|(&x, &q)| {
                    (q - (x * (lambda - x)).max(0.0).sqrt() / std::f64::consts::PI).abs() / qmax
                })
                .fold(0.0, f64::max);
        eprintln!(
            "{n:5} {load_err:14.3e} {p_err:22.3e} {:18.3e} {:10.3e}",
            (s.beta / s.lambda - 0.5).abs(),
            s.friction_rho.abs()
        );
        // β = λ/2 and zero friction follow from the symmetry of the discrete system: rounding only.
        assert!((s.beta / s.lambda - 0.5).abs() <= 1e-12);
        assert!(s.friction_rho.abs() <= 1e-12);
        // The pressure is the semi-ellipse up to the discretisation error.
        assert!(p_err <= 2.0 / n as f64, "n = {n}: pressure error {p_err}");
        if let Some((pl, pp)) = prev {
            // First order in h (docs/MATH.md §3): halving h halves the load error (ratio 2 ± 10 %) and
            // the pressure error falls.
            let r = pl / load_err;
            assert!((1.8..2.2).contains(&r), "n = {n}: load error ratio {r}");
            assert!(p_err < pp, "n = {n}: pressure error did not fall");
        }
        prev = Some((load_err, p_err));
    }
    // Given load: λ = 2√N′ within the first-order error (0.5/n relative at n = 80, from the table).
    let s = solve_at_load(&[], 0.7, &settings(80)).unwrap();
    assert!(
        (s.lambda / (2.0 * 0.7f64.sqrt()) - 1.0).abs() <= 0.5 / 80.0,
        "lambda = {}",
        s.lambda
    );
    assert!((s.load / 0.7 - 1.0).abs() <= 1e-8); // LoadSettings::accept_tol
}

/// 10 terms, bᵢ = 10^(−6 … 6) at unit speed, relaxed/glassy compliance ratio 1 + Σfᵢ/bᵢ = 1000.
fn ten_terms(speed: f64) -> Vec<CreepTerm> {
    (0..10)
        .map(|i| {
            let b = 10f64.powf(-6.0 + 12.0 * i as f64 / 9.0) / speed;
            CreepTerm { f: 99.9 * b, b }
        })
        .collect()
}

#[test]
fn ten_term_spectrum_finite_over_eight_decades_of_lambda() {
    let terms = ten_terms(1.0);
    let k = Kernel::new(&terms).unwrap();
    assert!((k.sum_f_over_b() - 999.0).abs() < 1e-9);
    for e in -8..=8 {
        let lambda = 10f64.powf(e as f64 / 2.0);
        let s = solve_at_lambda(&terms, lambda, &settings(80)).unwrap();
        assert!(
            s.beta.is_finite() && s.load.is_finite() && s.friction_rho.is_finite(),
            "lambda = {lambda}"
        );
        assert!(s.pressure.iter().all(|q| q.is_finite()));
        // The load lies between the relaxed and glassy Hertz loads λ²/(4·1000) and λ²/4, up to the
        // first-order discretisation error (a few % at n = 80, see the Hertz table; 10 % margin).
        let (lo, hi) = (lambda * lambda / 4000.0, lambda * lambda / 4.0);
        assert!(
            s.load > 0.9 * lo && s.load < 1.1 * hi,
            "lambda = {lambda}: N' = {} not in [{lo}, {hi}]",
            s.load
        );
    }
}

#[test]
fn ten_term_load_loop_converges_at_every_speed() {
    // Dimensionless speed s scales bᵢ by 1/s at fixed N′ = 1/4 (the scene's choice of T): λ runs
    // from ≈ 1 (glassy, s → ∞) to ≈ √1000 (relaxed, s → 0).
    for e in -8..=8 {
        let speed = 10f64.powf(e as f64 / 2.0);
        let terms = ten_terms(speed);
        let s = solve_at_load(&terms, 0.25, &settings(80)).unwrap();
        eprintln!(
            "speed {speed:9.1e}: lambda = {:9.4}, rho F/N = {:10.4e}, {} solves",
            s.lambda, s.friction_rho, s.iterations
        );
        assert!((s.load / 0.25 - 1.0).abs() <= 1e-8); // LoadSettings::accept_tol
        assert!(
            s.lambda > 0.95 && s.lambda < 1000f64.sqrt() * 1.05,
            "lambda = {}",
            s.lambda
        );
        assert!(s.iterations <= 30, "{} solves", s.iterations);
    }
}

#[test]
fn load_loop_against_the_thesis_secant_at_low_speed() {
    // Low speed, one term with compliance ratio 1000: the true λ is ≈ √1000 = 31.6 times the
    // thesis' elastic start 2√N′₀ (docs/MATH.md §3).
    let terms = [CreepTerm {
        f: 999.0 * 50.0,
        b: 50.0,
    }];
    let kernel = Kernel::new(&terms).unwrap();
    let n = 80;
    let solve = |l: f64| hat::solve_at_lambda(&kernel, l, n);
    let ours = solve_at_load(&terms, 0.25, &settings(n)).unwrap();
    eprintln!(
        "bracketed Brent: lambda = {}, {} solves",
        ours.lambda, ours.iterations
    );
    assert!((ours.load / 0.25 - 1.0).abs() <= 1e-8); // LoadSettings::accept_tol
    assert!(ours.iterations <= 6, "{} solves", ours.iterations);
    // The thesis' loop as printed (start λ₁ = 2√N′₀, λ₀ = λ₁/2 with N = 0, absolute tolerance
    // 1e-4 on N′): at N′₀ = 1/4 it reaches the same λ, but needs more solves (11 here against 5; the thesis
    // reports < 10 for its cases). The overshoot of its first step is bounded, so it does not diverge.
    let secant = thesis_secant(0.25, 1e-4, 50, solve).unwrap();
    eprintln!(
        "thesis secant: lambda = {}, {} solves",
        secant.lambda, secant.iterations
    );
    assert!((secant.lambda / ours.lambda - 1.0).abs() < 1e-3);
    assert!(secant.iterations > ours.iterations);
    // Its absolute tolerance fails for small loads: at N′₀ = 1e-6 the elastic start already meets
    // |N′ − N′₀| ≤ 1e-4 and is returned, about 30 times too short. Ours is relative.
    let small = 1e-6;
    let bad = thesis_secant(small, 1e-4, 50, solve).unwrap();
    let good = solve_at_load(&terms, small, &settings(n)).unwrap();
    eprintln!(
        "N' = 1e-6: thesis secant lambda = {} ({} solves), ours {} ({} solves)",
        bad.lambda, bad.iterations, good.lambda, good.iterations
    );
    assert!(good.lambda > 10.0 * bad.lambda);
    assert!((good.load / small - 1.0).abs() <= 1e-8); // LoadSettings::accept_tol
}
