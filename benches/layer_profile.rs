//! Where the time of one spectral layer load point goes (issue 14 speed goals): per load point at
//! tol 1e−4 and 1e−6 on the 30-term spectrum of `contact_layer` (24 decades, J∞/J_g = 1e3, N′ = ¼,
//! ν = ½, h/λ_HS = 0.03…10), the solves at given λ it made, and at the λ found the time of one solve
//! at λ split into its layer term (the κ quadrature) and the rest, and the closing contact checks
//! alone (`contact_checks` on the answer's 64 intervals, as the solver runs them).
//! Times are CPU time of the bench's thread (the machine is shared). Run: `cargo bench --bench
//! layer_profile` (single thread; prints a Markdown table).

use viscoroll::contact::body::layer::collocation::contact_checks;
use viscoroll::contact::body::layer::spectral::at_lambda::solve_at_lambda;
use viscoroll::contact::body::layer::spectral::degree::degree_for;
use viscoroll::contact::body::layer::spectral::layer_term::LayerTerm;
use viscoroll::contact::body::layer::spectral::{solve_spectral_at_load, SpectralSettings};
use viscoroll::contact::body::layer::LayerKernel;
use viscoroll::contact::half_space::auto::{solve_auto_at_load, AutoSettings};
use viscoroll::contact::numerics::reduction::select;
use viscoroll::contact::CreepTerm;

fn spectrum(n: usize, decades: f64, ratio: f64) -> Vec<CreepTerm> {
    if n == 1 {
        return vec![CreepTerm { f: 10.0, b: 1.0 }];
    }
    (0..n)
        .map(|k| {
            let b = 10f64.powf(-decades / 2.0 + decades * k as f64 / (n - 1) as f64);
            let r = (ratio - 1.0) / n as f64;
            CreepTerm { f: r * b, b }
        })
        .collect()
}

/// CPU time of this thread in seconds (/proc/thread-self/schedstat, first field in ns): the machine
/// these figures come from is shared, and wall time counts the waits for a core.
pub fn cpu_seconds() -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<f64>().ok())
        .map_or_else(|| f64::NAN, |ns| ns * 1e-9)
}

/// (result, CPU seconds per call): at least 0.3 s of CPU or 3 calls.
fn time_it<T>(mut f: impl FnMut() -> T) -> (T, f64) {
    let t0 = cpu_seconds();
    let mut out = f();
    let mut reps = 1;
    while cpu_seconds() - t0 < 0.3 || reps < 3 {
        out = f();
        reps += 1;
    }
    (out, (cpu_seconds() - t0) / reps as f64)
}

fn main() {
    let load = 0.25;
    println!("| spectrum | h/λ_HS | tol | time/load point | solves at λ | p | one solve at λ | of which layer term | checks | estimate |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for (name, terms) in [
        ("1 term", spectrum(1, 0.0, 0.0)),
        ("30 terms", spectrum(30, 24.0, 1e3)),
    ] {
        let hs = solve_auto_at_load(
            &terms,
            load,
            &AutoSettings {
                tol: 1e-10,
                gap_check: false,
                ..Default::default()
            },
        )
        .unwrap();
        for hr in [0.03, 0.1, 0.3, 1.0, 3.0, 10.0] {
            let h = hr * hs.lambda;
            let nu = 0.5;
            for tol in [1e-4, 1e-6] {
                let st = SpectralSettings {
                    tol,
                    p_max: 48,
                    start: None,
                    checks: true,
                };
                let (a, t) = time_it(|| {
                    solve_spectral_at_load(&terms, load, h, nu, &st)
                        .unwrap()
                        .unwrap()
                });
                let lam = a.solution.lambda;
                let p = a.solution.n;
                let fr = a.solution.friction_rho / lam;
                let red = select(&terms, lam, 0.3 * tol * fr, 0.3 * tol, (0.0, 0.0));
                let (_, t_l) = time_it(|| solve_at_lambda(&red.modes, lam, h, nu, p, 0.4));
                let (_, t_lt) = time_it(|| LayerTerm::new(&red.modes, 0.5 * lam, h, nu, p));
                let kernel = LayerKernel::new(&terms, h, nu).unwrap();
                let mut d = a.solution.clone();
                d.n = 64;
                d.xi = d.xi.iter().step_by(2).copied().collect();
                d.pressure = d.pressure.iter().step_by(2).copied().collect();
                let (_, t_ck) = time_it(|| contact_checks(&kernel, &d).unwrap());
                println!(
                    "| {name} | {hr} | {tol:.0e} | {:.2} ms | {} | {p} (start {}, L/h {:.2}) | {:.3} ms | {:.3} ms | {:.3} ms | {:.1e} |",
                    t * 1e3,
                    a.solution.iterations,
                    degree_for(0.5 * lam, h, tol),
                    0.5 * lam / h,
                    t_l * 1e3,
                    t_lt * 1e3,
                    t_ck * 1e3,
                    a.error_estimate
                );
            }
        }
    }
}
