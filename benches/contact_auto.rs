//! Benchmark table of the `auto` contact scheme against the thesis scheme (issue 4).
//!
//! Scope: time per load point (solve at given N′, load loop included) and achieved relative error
//! of ρF/N and λ, for 1-, 10- and 30-term spectra, at tol = 1e−3, 1e−6, 1e−9; next to it the thesis
//! scheme's smallest n (doubling from 10 up to 1280) reaching the same friction error, and its time.
//! References: the exact one-term solution (`contact::one_term_at_load`, ≤ 1e−10) for one term;
//! the auto scheme at tol 1e−10 for the spectra (its estimate is printed).
//! Times are CPU time of the (single) thread per load point, and wall time next to it (on a shared
//! machine the wall time includes waiting for a core). Times are without the optional gap check
//! outside the contact (`gap_check: false`); one line prints its cost for the one-term case.
//! The auto scheme runs through the public entry `contact::solve_at_load` with `Scheme::Auto`.
//! Run: `cargo bench --bench contact_auto` (single-threaded; prints a Markdown table).

use std::time::Instant;
use viscoroll::contact::{
    one_term_at_load, solve_at_load, AutoSettings, ContactSettings, CreepTerm, Scheme,
};

#[path = "support/auto.rs"]
mod auto;
use auto::solve_auto_at_load;

fn spectrum(n: usize, decades: f64, ratio: f64) -> Vec<CreepTerm> {
    if n == 1 {
        return vec![CreepTerm { f: 10.0, b: 1.0 }];
    }
    // log-spaced rates over `decades` centred on 1, equal strengths with Σ r = ratio − 1
    (0..n)
        .map(|k| {
            let b = 10f64.powf(-decades / 2.0 + decades * k as f64 / (n - 1) as f64);
            let r = (ratio - 1.0) / n as f64;
            CreepTerm { f: r * b, b }
        })
        .collect()
}

/// CPU time of this thread in seconds (Linux: /proc/thread-self/schedstat, first field in ns);
/// None elsewhere.
fn cpu_seconds() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: f64 = s.split_whitespace().next()?.parse().ok()?;
    Some(ns * 1e-9)
}

/// (result, wall time per call, CPU time per call): the machine is shared, so the wall time can
/// exceed the CPU time of the single thread by the load.
fn time_it<T>(mut f: impl FnMut() -> T) -> (T, f64, f64) {
    let c0 = cpu_seconds();
    let t0 = Instant::now();
    let mut out = f();
    let mut reps = 1;
    while t0.elapsed().as_secs_f64() < 0.3 && reps < 2000 {
        out = f();
        reps += 1;
    }
    let wall = t0.elapsed().as_secs_f64() / reps as f64;
    let cpu = match (c0, cpu_seconds()) {
        (Some(a), Some(b)) => (b - a) / reps as f64,
        _ => f64::NAN,
    };
    (out, wall, cpu)
}

fn micros(t: f64) -> String {
    if t >= 1e-3 {
        format!("{:.2} ms", t * 1e3)
    } else {
        format!("{:.0} µs", t * 1e6)
    }
}

fn main() {
    let load = 1.0;
    println!("| spectrum | tol | auto CPU time/load point | (wall) | modes used | error ρF/N | error λ | estimate | thesis n (same ρF/N error) | thesis time |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for (name, terms) in [
        ("1 term f=10 b=1", spectrum(1, 0.0, 0.0)),
        ("10 terms, 12 decades, J∞/J_g=1e3", spectrum(10, 12.0, 1e3)),
        ("30 terms, 24 decades, J∞/J_g=1e3", spectrum(30, 24.0, 1e3)),
    ] {
        let reference = solve_auto_at_load(
            &terms,
            load,
            &AutoSettings {
                tol: 1e-10,
                ..Default::default()
            },
        )
        .unwrap();
        // one term: the independent exact solution (contact::exact, ≤ 1e−10)
        let (fr_ref, lam_ref) = if terms.len() == 1 {
            let e = one_term_at_load(terms[0], load).unwrap();
            (e.friction_rho, e.lambda)
        } else {
            (reference.friction_rho, reference.lambda)
        };
        // thesis scheme errors against n (computed once per spectrum)
        let mut thesis: Vec<(usize, f64, f64)> = Vec::new();
        let mut n = 10;
        while n <= 1280 {
            let settings = ContactSettings {
                scheme: Scheme::Thesis,
                n,
                ..Default::default()
            };
            let (s, _, t) = time_it(|| solve_at_load(&terms, load, &settings).unwrap());
            thesis.push((n, ((s.friction_rho - fr_ref) / fr_ref).abs(), t));
            n *= 2;
        }
        for tol in [1e-3, 1e-6, 1e-9] {
            // the solve alone; the optional gap check adds ~4·129·N kernel evaluations
            let settings = AutoSettings {
                tol,
                gap_check: false,
                ..Default::default()
            };
            let (s, wall, t) = time_it(|| solve_auto_at_load(&terms, load, &settings).unwrap());
            let e_fr = ((s.friction_rho - fr_ref) / fr_ref).abs();
            let e_l = ((s.lambda - lam_ref) / lam_ref).abs();
            let th = thesis.iter().find(|(_, e, _)| *e <= e_fr.max(1e-15));
            let (tn, tt) = match th {
                Some((n, _, t)) => (format!("{n}"), format!("{:.3} ms", t * 1e3)),
                None => {
                    let (n, e, t) = thesis.last().unwrap();
                    (
                        format!("not reached (n={n}: error {e:.1e})"),
                        format!("{:.3} ms", t * 1e3),
                    )
                }
            };
            println!(
                "| {name} | {tol:.0e} | {} | {} | {}/{} | {e_fr:.1e} | {e_l:.1e} | {:.1e} | {tn} | {tt} |",
                micros(t),
                micros(wall),
                s.diagnostics.as_ref().unwrap().modes_used,
                s.diagnostics.as_ref().unwrap().modes_total,
                s.error_estimate.unwrap()
            );
        }
        if terms.len() == 1 {
            let (_, wall, t) =
                time_it(|| solve_auto_at_load(&terms, load, &AutoSettings::default()).unwrap());
            println!(
                "| {name}: tol 1e-6 with gap check | | {} | {} | | | | | | |",
                micros(t),
                micros(wall)
            );
        }
        println!(
            "| {name}: reference tol 1e-10 | | | | {}/{} | | | {:.1e} | | |",
            reference.diagnostics.as_ref().unwrap().modes_used,
            reference.diagnostics.as_ref().unwrap().modes_total,
            reference.error_estimate.unwrap()
        );
    }
}
