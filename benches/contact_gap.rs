//! Cost of the contact-condition check outside the contact (the auto scheme's `gap_check`, issue 4 item 4):
//! time per load point of the `auto` scheme with and without `gap_check`, for the 1-, 10- and
//! 30-term spectra of `benches/contact_auto.rs`, at tol 1e−6, load N′ = 1.
//! Through the public entry `contact::solve_at_load` with `Scheme::Auto` (the settings of
//! `ContactSettings::default()` otherwise).
//! Run: `cargo bench --bench contact_gap` (single-threaded; prints a Markdown table).

use std::time::Instant;
use viscoroll::contact::{AutoSettings, CreepTerm};

#[path = "support/auto.rs"]
mod auto;
use auto::solve_auto_at_load;

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

fn time_it(mut f: impl FnMut()) -> f64 {
    let t0 = Instant::now();
    let mut reps = 0;
    while t0.elapsed().as_secs_f64() < 0.5 && reps < 2000 {
        f();
        reps += 1;
    }
    t0.elapsed().as_secs_f64() / reps as f64
}

fn main() {
    println!("| spectrum | modes used | Chebyshev terms | time without check | time with check | check |");
    println!("|---|---|---|---|---|---|");
    for (name, terms) in [
        ("1 term f=10 b=1", spectrum(1, 0.0, 0.0)),
        ("10 terms, 12 decades, J∞/J_g=1e3", spectrum(10, 12.0, 1e3)),
        ("30 terms, 24 decades, J∞/J_g=1e3", spectrum(30, 24.0, 1e3)),
    ] {
        let on = AutoSettings::default();
        let off = AutoSettings {
            gap_check: false,
            ..Default::default()
        };
        let first = solve_auto_at_load(&terms, 1.0, &on).unwrap();
        let (used, n_coef) = (first.diagnostics.as_ref().unwrap().modes_used, first.n);
        let t_off = time_it(|| {
            solve_auto_at_load(&terms, 1.0, &off).unwrap();
        });
        let t_on = time_it(|| {
            solve_auto_at_load(&terms, 1.0, &on).unwrap();
        });
        println!(
            "| {name} | {used} | {n_coef} | {:.3} ms | {:.3} ms | +{:.3} ms |",
            t_off * 1e3,
            t_on * 1e3,
            (t_on - t_off) * 1e3
        );
    }
}
