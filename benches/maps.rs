//! Benchmark of the friction maps (issue 8) through the public entry `pipeline::friction_maps`: the
//! maps of one scene with 10 map temperatures (−40…50 °C every 10 K), 30 speeds (0.5…40 m/s) and
//! 30 loads (2…50 kN/m), log-spaced, roll radius 66.5 mm (the shipped idler), for two shipped
//! compounds fitted from their raw exports in data/. The scene's maps are its 30 × 30 grid of speed ×
//! load at every map temperature (the 9000 points of this bench before issue 30), the curves
//! against speed and load and the listed points: all from one interpolant in the reduced variable
//! s = l_g/(V·a_T) (src/contact/maps/), at map tolerances 1e−3, 1e−4, 1e−5 and 1e−6 (the main job's:
//! `pipeline::pipeline_map_settings`).
//!
//! Prints a Markdown table: wall time of all the scene's maps (rayon on all threads, best of 2),
//! their CPU seconds, the points evaluated, contact solves, the error estimate; and for scale the time
//! of one direct `contact::roll` solve at 10 °C, 4 m/s, 10 kN/m at the main job's contact settings
//! (auto scheme, tol 1e−6, no gap check), times the map points.
//!
//! Covered maps (issue 14): the same maps on a 5 mm cover (the shipped idler's), from the 2-D
//! interpolant in (ln s, ln h/l_g) of the bonded layer (src/contact/maps/covered.rs) at the main
//! job's covered tolerance 1e−3 and at 1e−2: wall and CPU time, node solves, the estimate, and one
//! direct layer solve (`contact::roll_cover`, `Body::Layer`, at a tenth of the map tolerance as the
//! map's nodes are) for scale.
//!
//! Dropped with issue 30's public API (the maps' interpolants are crate-internal): the panel counts,
//! panel shapes and ln s range of the interpolant, and the split of the covered estimate into its
//! interpolation and node parts (the datasheet prints the estimate).
//! Run: `RAYON_NUM_THREADS=2 cargo bench --bench maps` (the 2-core figure; `-- --covered-only`
//! skips the half-space table).

use std::path::PathBuf;
use std::time::Instant;
use viscoroll::contact::{roll, roll_cover, AutoSettings, Body, ContactSettings, Scene, Scheme};
use viscoroll::pipeline::{fit_files, friction_maps, pipeline_map_settings, FitOptions};
use viscoroll::results::{CompoundFit, SceneSpec};

#[path = "support/cpu.rs"]
mod cpu;
use cpu::cpu_s;

fn log_spaced(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| (a.ln() + (b.ln() - a.ln()) * i as f64 / (n - 1) as f64).exp())
        .collect()
}

/// The bench's scene: the idler's roll at 10 °C with the 10 × 30 × 30 maps, on `cover_mm`.
fn spec(cover_mm: Option<f64>) -> SceneSpec {
    SceneSpec {
        name: "maps-bench".into(),
        description: String::new(),
        roll_radius_mm: 66.5,
        load_n_per_m: 1e4,
        speed_m_s: 4.0,
        temps_c: vec![10.0],
        poisson: None,
        cover_thickness_mm: cover_mm,
        map_temps_c: (0..10).map(|k| -40.0 + 10.0 * k as f64).collect(),
        tol: None,
        map_speeds_m_s: log_spaced(0.5, 40.0, 30),
        map_loads_n_per_m: log_spaced(2e3, 5e4, 30),
    }
}

/// The main job's contact settings (auto, no gap check), at `tol`.
fn contact_settings(tol: f64) -> ContactSettings {
    ContactSettings {
        scheme: Scheme::Auto,
        auto: AutoSettings {
            tol,
            gap_check: false,
            ..AutoSettings::default()
        },
        ..ContactSettings::default()
    }
}

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data");
    let covered_only = std::env::args().any(|a| a == "--covered-only");
    let mut covered_rows = Vec::new();
    println!(
        "threads: {}\n\n| compound | creep terms | tol | map time | CPU | points | solves | estimate | direct roll × points |\n|---|---|---|---|---|---|---|---|---|",
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
        covered_rows.push(covered(name, &fit));
        if covered_only {
            continue;
        }
        // one direct solve for scale
        let at = creep
            .at_temperature(&fit.shift_law, 10.0, None)
            .expect("shift law");
        let scene = spec(None).scene();
        let t0 = Instant::now();
        for _ in 0..5 {
            roll(&scene, &at.spectrum, &contact_settings(1e-6)).expect("solve");
        }
        let direct = t0.elapsed().as_secs_f64() / 5.0;
        for tol in [1e-3, 1e-4, 1e-5, 1e-6] {
            let mut settings = pipeline_map_settings();
            settings.tol = tol;
            let (mut best, mut cpu) = (f64::INFINITY, f64::INFINITY);
            let mut out = None;
            for _ in 0..2 {
                let (t0, c0) = (Instant::now(), cpu_s());
                let r = friction_maps(&fit, &spec(None), &settings).expect("maps build");
                best = best.min(t0.elapsed().as_secs_f64());
                cpu = cpu.min(cpu_s() - c0);
                out = Some(r);
            }
            let maps = out.expect("ran");
            let points = maps.points.len() + maps.grid.len() + maps.curves.len();
            println!(
                "| {name} | {} | {tol:.0e} | {best:.2} s | {cpu:.2} s | {points} | {} | {:.1e} | {:.1} ms × {points} = {:.0} s |",
                creep.terms.len(),
                maps.solves,
                maps.error_estimate,
                direct * 1e3,
                direct * points as f64
            );
        }
    }
    println!(
        "\ncovered (5 mm cover, bonded layer):\n\n| compound | tol | map time | CPU | points | solves | estimate | one layer solve at tol/10 |\n|---|---|---|---|---|---|---|---|"
    );
    for rows in covered_rows {
        for r in rows {
            println!("{r}");
        }
    }
}

/// The covered maps of the bench's scene on a 5 mm cover at tolerances 1e−3 and 1e−2: table rows.
fn covered(name: &str, fit: &CompoundFit) -> Vec<String> {
    let spec = spec(Some(5.0));
    let creep = fit.creep.as_ref().expect("creep spectrum");
    // one layer solve at the middle of the map for scale (10 °C, 4 m/s, 10 kN/m is inside it)
    let at = creep
        .at_temperature(&fit.shift_law, 10.0, None)
        .expect("shift law");
    let layer = Scene {
        body: Body::Layer { thickness_m: 5e-3 },
        ..spec.scene()
    };
    let mut rows = Vec::new();
    for tol in [1e-3, 1e-2] {
        let t0 = Instant::now();
        roll_cover(&layer, &at.spectrum, 0.1 * tol).expect("layer solves");
        let node = t0.elapsed().as_secs_f64();
        let mut settings = pipeline_map_settings();
        settings.tol = tol;
        let (t0, c0) = (Instant::now(), cpu_s());
        let maps = friction_maps(fit, &spec, &settings).expect("covered maps build");
        let time = t0.elapsed().as_secs_f64();
        let cpu = cpu_s() - c0;
        rows.push(format!(
            "| {name} | {tol:.0e} | {time:.2} s | {cpu:.2} s | {} | {} | {:.1e} | {:.0} ms |",
            maps.points.len() + maps.grid.len() + maps.curves.len(),
            maps.solves,
            maps.error_estimate,
            node * 1e3
        ));
    }
    rows
}
