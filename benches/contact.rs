//! Speed/accuracy of the thesis scheme (a bench binary that prints a table; `harness = false`).
//!
//! Measures, for n = 10 … 1280 intervals and for 1 and 10 creep terms: the wall time of one solve at
//! given λ (kernel assembly, O(n) special-function calls, plus the dense LU, O(n³)) and of one load
//! point (the bracketed Brent loop, several solves), next to the error of ρF/N and of λ against a
//! reference. The reference is Richardson's extrapolation of n = 1280 and 2560 (first order in h,
//! MATH.md §3): X_ref = 2X(2560) − X(1280).
//!
//! Cases: one term f = 10, b = 1 (thesis Table 1) at λ = 1 and at N′ = 1/4; ten terms
//! bᵢ = 10^(−6…6), Σfᵢ/bᵢ = 999 (compliance ratio 1000) at λ = 10 and at N′ = 1/4.
//!
//! Run: `cargo bench --bench contact` (about a minute on one core). Times are the median of repeats
//! filling ≈ 0.3 s (at least 3).

use std::time::{Duration, Instant};
use viscoroll::contact::{
    solve_at_lambda, solve_at_load, ContactSettings, CreepTerm, DimensionlessSolution,
};

fn settings(n: usize) -> ContactSettings {
    ContactSettings {
        n,
        ..Default::default()
    }
}

fn time<F: FnMut() -> DimensionlessSolution>(mut f: F) -> (Duration, DimensionlessSolution) {
    let mut times = Vec::new();
    let start = Instant::now();
    let mut last;
    loop {
        let t = Instant::now();
        last = std::hint::black_box(f());
        times.push(t.elapsed());
        if times.len() >= 3 && start.elapsed() > Duration::from_millis(300) {
            break;
        }
    }
    times.sort();
    (times[times.len() / 2], last)
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

fn main() {
    // cargo bench passes `--bench`; ignore arguments.
    let one = vec![CreepTerm { f: 10.0, b: 1.0 }];
    let ten: Vec<CreepTerm> = (0..10)
        .map(|i| {
            let b = 10f64.powf(-6.0 + 12.0 * i as f64 / 9.0);
            CreepTerm { f: 99.9 * b, b }
        })
        .collect();
    let ns = [10usize, 20, 40, 80, 160, 320, 640, 1280];
    for (name, terms, lambda) in [
        ("1 term (f = 10, b = 1)", &one, 1.0),
        ("10 terms (b = 1e-6…1e6, ratio 1000)", &ten, 10.0),
    ] {
        let reference = |g: &dyn Fn(usize) -> f64| 2.0 * g(2560) - g(1280);
        let fr_lambda_ref = reference(&|n| {
            solve_at_lambda(terms, lambda, &settings(n))
                .unwrap()
                .friction_rho
        });
        let at_load = |n: usize| solve_at_load(terms, 0.25, &settings(n)).unwrap();
        let s1280 = at_load(1280);
        let s2560 = at_load(2560);
        let fr_load_ref = 2.0 * s2560.friction_rho - s1280.friction_rho;
        let lam_load_ref = 2.0 * s2560.lambda - s1280.lambda;
        println!(
            "\n{name}: at lambda = {lambda} and at N' = 1/4 (reference: Richardson n = 1280, 2560)"
        );
        println!("rho F/N ref at lambda: {fr_lambda_ref:.9}; at load: rho F/N {fr_load_ref:.9}, lambda {lam_load_ref:.9}");
        println!("|    n | solve at λ (ms) | rel. err ρF/N at λ | load point (ms) | solves | rel. err ρF/N at N′ | rel. err λ at N′ |");
        println!("|-----:|----------------:|-------------------:|----------------:|-------:|--------------------:|-----------------:|");
        for &n in &ns {
            let (t_l, s_l) = time(|| solve_at_lambda(terms, lambda, &settings(n)).unwrap());
            let (t_n, s_n) = time(|| at_load(n));
            println!(
                "| {n:4} | {:15.3} | {:18.2e} | {:15.3} | {:6} | {:19.2e} | {:16.2e} |",
                ms(t_l),
                (s_l.friction_rho / fr_lambda_ref - 1.0).abs(),
                ms(t_n),
                s_n.iterations,
                (s_n.friction_rho / fr_load_ref - 1.0).abs(),
                (s_n.lambda / lam_load_ref - 1.0).abs(),
            );
        }
    }
}
