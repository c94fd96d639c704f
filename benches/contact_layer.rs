//! Speed/accuracy table of the bodies of issue 14: the bonded layer (collocation, `contact::body::layer`),
//! the uniaxial and constrained Winkler foundations (closed form) and the half-space (`auto`).
//!
//! Scope: time per load point (N′ = 1/4, load loop included) and the relative error of ρF/N and λ
//! against the same body's reference: the layer at tol 1e−6 with n up to 1024 (its own estimate is
//! printed; the collocation is first order in λ, Richardson-extrapolated), the Winkler closed form is
//! exact to rounding (error column: its difference from the layer reference, i.e. the model error),
//! the half-space at tol 1e−10 (its error column likewise: the model error against the layer).
//! Spectra as in `contact_auto`: 1 term (f = 10, b = 1), 30 terms over 24 decades with J∞/J_g = 1e3.
//! Run: `cargo bench --bench contact_layer` (single thread; prints a Markdown table).

use std::time::Instant;
use viscoroll::contact::body::layer::{
    layer_at_load, winkler_at_load, LayerSettings, WinklerColumns,
};
use viscoroll::contact::half_space::auto::{solve_auto_at_load, AutoSettings};
use viscoroll::contact::load::LoadSettings;
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

/// (result, wall seconds per call): at least 0.3 s or 3 calls.
fn time_it<T>(mut f: impl FnMut() -> T) -> (T, f64) {
    let t0 = Instant::now();
    let mut out = f();
    let mut reps = 1;
    while t0.elapsed().as_secs_f64() < 0.3 || reps < 3 {
        out = f();
        reps += 1;
    }
    (out, t0.elapsed().as_secs_f64() / reps as f64)
}

fn ms(t: f64) -> String {
    if t >= 1e-3 {
        format!("{:.2} ms", t * 1e3)
    } else {
        format!("{:.0} µs", t * 1e6)
    }
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

fn main() {
    let load = 0.25;
    println!("| spectrum | h/λ_HS | ν | body | tol | time/load point | n | error ρF/N | error λ | estimate |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for (name, terms) in [
        ("1 term f=10 b=1", spectrum(1, 0.0, 0.0)),
        ("30 terms, 24 decades, J∞/J_g=1e3", spectrum(30, 24.0, 1e3)),
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
        for hr in [0.3, 3.0] {
            let h = hr * hs.lambda;
            let nu = 0.5;
            let reference = layer_at_load(
                &terms,
                load,
                h,
                nu,
                &LayerSettings {
                    tol: 1e-6,
                    n_max: 1024,
                    ..Default::default()
                },
            )
            .unwrap();
            let (rf, rl) = (reference.solution.friction_rho, reference.solution.lambda);
            println!(
                "| {name} | {hr} | {nu} | layer (reference) | 1e-6 | — | {} | — | — | {:.1e} |",
                reference.solution.n, reference.error_estimate
            );
            for tol in [1e-3, 1e-4] {
                let (a, t) = time_it(|| {
                    layer_at_load(
                        &terms,
                        load,
                        h,
                        nu,
                        &LayerSettings {
                            tol,
                            ..Default::default()
                        },
                    )
                    .unwrap()
                });
                println!(
                    "| {name} | {hr} | {nu} | layer | {tol:.0e} | {} | {} | {:.1e} | {:.1e} | {:.1e} |",
                    ms(t),
                    a.solution.n,
                    rel(a.solution.friction_rho, rf),
                    rel(a.solution.lambda, rl),
                    a.error_estimate
                );
            }
            let (w, t) = time_it(|| {
                winkler_at_load(
                    &terms,
                    load,
                    WinklerColumns::Uniaxial,
                    h,
                    nu,
                    &LoadSettings::default(),
                )
                .unwrap()
            });
            println!(
                "| {name} | {hr} | {nu} | uniaxial Winkler (model error) | exact | {} | — | {:.1e} | {:.1e} | — |",
                ms(t),
                rel(w.solution.friction_rho, rf),
                rel(w.solution.lambda, rl)
            );
            let (a, t) = time_it(|| {
                solve_auto_at_load(
                    &terms,
                    load,
                    &AutoSettings {
                        tol: 1e-6,
                        gap_check: false,
                        ..Default::default()
                    },
                )
                .unwrap()
            });
            println!(
                "| {name} | {hr} | {nu} | half-space (model error) | 1e-6 | {} | — | {:.1e} | {:.1e} | — |",
                ms(t),
                rel(a.friction_rho, rf),
                rel(a.lambda, rl)
            );
        }
    }
}
