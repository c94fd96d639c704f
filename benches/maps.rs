//! Benchmark of the friction maps (issue 8): a map of 30 speeds × 30 loads × 10 temperatures of two
//! shipped compounds (fitted from their raw exports in data/), from the reduced variable
//! s = l_g/(V·a_T) (src/contact/maps/) at map tolerances 1e−3 (the main job's), 1e−4,
//! 1e−5 and 1e−6.
//!
//! Grid: radius 66.5 mm (the shipped idler), speeds 0.5…40 m/s and loads 2…50 kN/m log-spaced,
//! temperatures −40…50 °C every 10 K. Prints a Markdown table: wall time of the whole map
//! (interpolant build + evaluation of the 9000 points, rayon on all threads, best of 2), node
//! solves, panels, the range of ln s, the error estimate; and for scale the time of one direct
//! `contact::roll` solve at 10 °C, 4 m/s, 10 kN/m at the main job's settings, times 9000.
//!
//! Covered maps (issue 14): the same 9000 points on a 5 mm cover (the shipped idler's), from the
//! 2-D interpolant in (ln s, ln h/l_g) of the bonded layer (src/contact/maps/covered.rs) at the main
//! job's covered tolerance 1e−3 and at 1e−2: wall time, node solves, panels and degrees, the
//! estimate (interpolation + layer solves), and one layer node solve's time for scale; the CPU
//! seconds of the map beside its wall time (on a shared machine, CPU / 2 is the 2-core figure).
//! Run: `RAYON_NUM_THREADS=2 cargo bench --bench maps` (the 2-core figure; `-- --covered-only`
//! skips the half-space table).

use std::path::PathBuf;
use std::time::Instant;
use viscoroll::contact::maps::{
    covered_map, friction_map, CoveredProblem, MapQuery, MapSettings, ReducedProblem,
};
use viscoroll::contact::Scene;
use viscoroll::contact::{roll, Body};
use viscoroll::pipeline::scenes::pipeline_contact_settings;
use viscoroll::pipeline::{fit_files, FitOptions};

#[path = "support/cpu.rs"]
mod cpu;
use cpu::cpu_s;

fn log_spaced(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| (a.ln() + (b.ln() - a.ln()) * i as f64 / (n - 1) as f64).exp())
        .collect()
}

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data");
    let covered_only = std::env::args().any(|a| a == "--covered-only");
    let mut covered_rows = Vec::new();
    println!(
        "threads: {}\n\n| compound | creep terms | tol | map time (9000 points) | solves | panels | ln s range | estimate | direct roll × 9000 |\n|---|---|---|---|---|---|---|---|---|",
        rayon::current_num_threads()
    );
    for (name, file) in [
        ("ems-ca", "pyvisco-ems-ca/freq_Eplexor_raw.xls"),
        (
            "trios-aresg2-lims",
            "trios-aresg2-lims/frequency_sweep_tts.txt",
        ),
    ] {
        let fit =
            fit_files(name, &[root.join(file)], &FitOptions::default()).expect("shipped data fits");
        let creep = fit.creep.clone().expect("creep spectrum");
        let problem = ReducedProblem::new(&creep, None).expect("valid spectrum");
        let radius_m = 0.0665;
        let mut queries = Vec::new();
        for k in 0..10 {
            let a_t = 10f64.powf(fit.shift_law.log10_a_t(-40.0 + 10.0 * k as f64));
            for &v in &log_spaced(0.5, 40.0, 30) {
                for &n in &log_spaced(2e3, 5e4, 30) {
                    queries.push(MapQuery {
                        radius_m,
                        load_n_per_m: n,
                        speed_m_s: v,
                        a_t,
                    });
                }
            }
        }
        // one direct solve for scale
        let at = creep
            .at_temperature(&fit.shift_law, 10.0, None)
            .expect("shift law");
        let scene = Scene {
            radius_m,
            load_n_per_m: 1e4,
            speed_m_s: 4.0,
            poisson: None,
            body: Body::HALF_SPACE,
        };
        let t0 = Instant::now();
        for _ in 0..5 {
            roll(&scene, &at.spectrum, &pipeline_contact_settings()).expect("solve");
        }
        let direct = t0.elapsed().as_secs_f64() / 5.0;
        covered_rows.push(covered(name, &creep, &queries));
        if covered_only {
            continue;
        }
        for tol in [1e-3, 1e-4, 1e-5, 1e-6] {
            let settings = MapSettings {
                tol,
                ..MapSettings::default()
            };
            let mut best = f64::INFINITY;
            let mut out = None;
            for _ in 0..2 {
                let t0 = Instant::now();
                let r = friction_map(&problem, &queries, &settings).expect("map builds");
                best = best.min(t0.elapsed().as_secs_f64());
                out = Some(r);
            }
            let (values, curve) = out.expect("ran");
            let (lo, hi) = curve.range();
            println!(
                "| {name} | {} | {tol:.0e} | {best:.2} s | {} | {} | [{lo:.1}, {hi:.1}] | {:.1e} | {:.1} ms × {} = {:.0} s |",
                creep.terms.len(),
                curve.solves,
                curve.panels(),
                curve.error_estimate,
                direct * 1e3,
                values.len(),
                direct * values.len() as f64
            );
        }
    }
    println!(
        "\ncovered (5 mm cover, bonded layer):\n\n| compound | tol | map time (9000 points) | CPU | solves | panels (n_x×n_y) | estimate (interp. + nodes) | one node solve |\n|---|---|---|---|---|---|---|---|"
    );
    for rows in covered_rows {
        for r in rows {
            println!("{r}");
        }
    }
}

/// The covered map of `queries` on a 5 mm cover at tolerances 1e−3 and 1e−2: table rows.
fn covered(name: &str, creep: &viscoroll::CreepSpectrum, queries: &[MapQuery]) -> Vec<String> {
    let problem = CoveredProblem::new(creep, None, 5e-3).expect("valid spectrum");
    // one node at the middle of the map for scale (10 °C, 4 m/s, 10 kN/m is inside it)
    let x = problem
        .reduced
        .reduced_time_s(0.0665, 1e4, 4.0, queries[4 * 900].a_t)
        .ln();
    let y = problem.reduced_thickness(0.0665, 1e4).ln();
    let mut rows = Vec::new();
    for tol in [1e-3, 1e-2] {
        let t0 = Instant::now();
        problem.node(x, y, 0.1 * tol).expect("node solves");
        let node = t0.elapsed().as_secs_f64();
        let settings = MapSettings::covered(tol);
        let (t0, c0) = (Instant::now(), cpu_s());
        let (_, s) = covered_map(&problem, queries, &settings).expect("covered map builds");
        let time = t0.elapsed().as_secs_f64();
        let cpu = cpu_s() - c0;
        let shapes: Vec<String> = s
            .panel_shapes()
            .iter()
            .map(|(_, (nx, ny))| format!("{nx}×{ny}"))
            .collect();
        rows.push(format!(
            "| {name} | {tol:.0e} | {time:.2} s | {cpu:.2} s | {} | {} ({}) | {:.1e} ({:.1e} + {:.1e}) | {:.0} ms |",
            s.solves,
            s.panels(),
            shapes.join(", "),
            s.error_estimate,
            s.interpolation_estimate,
            s.node_error_bound,
            node * 1e3
        ));
    }
    rows
}
