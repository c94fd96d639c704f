//! Speed/accuracy of the thesis scheme (a bench binary that prints a table; `harness = false`).
//!
//! Measures, for n = 10 … 1280 intervals and for 1 and 10 creep terms: the wall time of one solve at
//! given λ (kernel assembly, O(n) special-function calls, plus the dense LU, O(n³)) and of one load
//! point (the bracketed Brent loop, several solves), next to the error of ρF/N and of λ against a
//! reference: the exact solution for one term (`contact::exact`); for ten terms Richardson's
//! extrapolation of n = 1280 and 2560 (first order in h, docs/MATH.md §3): X_ref = 2X(2560) − X(1280).
//! A second table gives the error against the exact solution at given load over seven decades of
//! speed (one term, b = 1e-3 … 1e3, f/b = 10, N′ = 1/4) and the observed order.
//!
//! Cases: one term f = 10, b = 1 (thesis Table 1) at λ = 1 and at N′ = 1/4; ten terms
//! bᵢ = 10^(−6…6), Σfᵢ/bᵢ = 999 (compliance ratio 1000) at λ = 10 and at N′ = 1/4.
//!
//! Run: `cargo bench --bench contact` (about a minute on one core). Times are the median of repeats
//! filling ≈ 0.3 s (at least 3).

use std::time::{Duration, Instant};
use viscoroll::contact::{
    one_term_at_lambda, one_term_at_load, solve_at_lambda, solve_at_load, ContactSettings,
    CreepTerm, DimensionlessSolution, Scheme,
};

fn settings(n: usize) -> ContactSettings {
    ContactSettings {
        scheme: Scheme::Thesis,
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
        let at_load = |n: usize| solve_at_load(terms, 0.25, &settings(n)).unwrap();
        let (fr_lambda_ref, fr_load_ref, lam_load_ref, what) = if terms.len() == 1 {
            let e = one_term_at_lambda(terms[0], lambda).unwrap();
            let el = one_term_at_load(terms[0], 0.25).unwrap();
            (e.friction_rho, el.friction_rho, el.lambda, "exact solution")
        } else {
            let r = |n| {
                solve_at_lambda(terms, lambda, &settings(n))
                    .unwrap()
                    .friction_rho
            };
            let (s1280, s2560) = (at_load(1280), at_load(2560));
            (
                2.0 * r(2560) - r(1280),
                2.0 * s2560.friction_rho - s1280.friction_rho,
                2.0 * s2560.lambda - s1280.lambda,
                "Richardson n = 1280, 2560",
            )
        };
        println!("\n{name}: at lambda = {lambda} and at N' = 1/4 (reference: {what})");
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

    // Thesis scheme against the exact one-term solution at given load over seven decades of speed.
    println!("\nThesis scheme vs exact, one term f/b = 10, N' = 1/4, speed ∝ 1/b: relative errors of lambda | rho F/N");
    let bs: Vec<f64> = (-3..=3).map(|e| 10f64.powi(e)).collect();
    let exact: Vec<_> = bs
        .iter()
        .map(|&b| one_term_at_load(CreepTerm { f: 10.0 * b, b }, 0.25).unwrap())
        .collect();
    let mut header = String::from("|    n |");
    for b in &bs {
        header += &format!(" b = {b:<7e}     |");
    }
    println!("{header}");
    println!("|-----:|{}", "-----------------:|".repeat(bs.len()));
    let mut rows: Vec<Vec<(f64, f64)>> = Vec::new();
    for &n in &ns {
        let row: Vec<(f64, f64)> = bs
            .iter()
            .zip(&exact)
            .map(|(&b, e)| {
                let s = solve_at_load(&[CreepTerm { f: 10.0 * b, b }], 0.25, &settings(n)).unwrap();
                (
                    (s.lambda / e.lambda - 1.0).abs(),
                    (s.friction_rho / e.friction_rho - 1.0).abs(),
                )
            })
            .collect();
        let mut line = format!("| {n:4} |");
        for (el, ef) in &row {
            line += &format!(" {el:.1e} / {ef:.1e} |");
        }
        println!("{line}");
        rows.push(row);
    }
    for (label, i, j) in [
        ("order 40→1280", 2usize, ns.len() - 1),
        ("order 640→1280", ns.len() - 2, ns.len() - 1),
    ] {
        let span = (ns[j] as f64 / ns[i] as f64).log2();
        let mut line = format!("| {label} |");
        for (ri, rj) in rows[i].iter().zip(&rows[j]) {
            let ol = (ri.0 / rj.0).log2() / span;
            let of = (ri.1 / rj.1).log2() / span;
            line += &format!(" {ol:7.2} / {of:7.2} |");
        }
        println!("{line}");
    }
    for (b, e) in bs.iter().zip(&exact) {
        println!(
            "exact b = {b:e}: lambda {:.9}, rho F/N {:.9e}",
            e.lambda, e.friction_rho
        );
    }
}
