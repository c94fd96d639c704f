//! The main job's covered scene against direct solves (issue 19, docs/DEVLOG.md "Bugs they catch": F/N doubled
//! in the covered map was caught by one unit test only). A standard linear solid (the compound's
//! fit with its creep spectrum replaced by the exact SLS, as in `physical_units`) as a 2 mm cover
//! bonded to a rigid carcass; `viscoroll run` writes friction.csv (each point solved by
//! `roll_cover`, body chosen by `auto`, at `COVER_TOL` = 1e−3) and friction_map.csv /
//! friction_map_2d.csv (the covered map: a 2-D interpolant of bonded-layer solves in s = l_g/(V·a_T)
//! and η = h/l_g, converted back to F*/N* = φ·l_g/R and l = λ·l_g).
//!
//! Reference, per point: the library's `roll_cover` on the bonded layer (`Body::Layer`) at
//! tol 1e−6 for the same scene in SI units with the spectrum shifted by that point's a_T — a direct
//! solve through the scene conversion of `contact::scene`, none of the map's interpolation or its
//! conversion. Tolerances from the stated ones: friction.csv 2·COVER_TOL (the solver's estimate ≤ 1e−3
//! and, where `auto` chose a cheaper body than the layer, its model error ≤ 1e−3), the maps COVER_TOL
//! (the covered map's error estimate, interpolation plus node solves, ≤ its tolerance 1e−3; it says
//! so when not), plus 1e−6 for the reference and 5e−6 for a_T printed to 6 decimals of log10.

use crate::reference::{csv_rows, job_on_sls, rel, Kind, Sls};
use std::collections::HashMap;
use viscoroll::contact::roll_cover;
use viscoroll::contact::{Body, Scene};
use viscoroll::CreepSpectrum;

const COVER_TOL: f64 = 1e-3;
const RADIUS_M: f64 = 0.1;
const COVER_M: f64 = 2e-3;

/// The SLS of `physical_units::main_job_friction_tables_and_maps_match_the_exact_sls` (the
/// realistic compound's own law at its reference temperature): E₀ = 1 GPa, E∞ = 4 MPa, τ_r = 1 ms,
/// ν = 0.3; its creep spectrum with every τ multiplied by `a_t`.
fn sls(a_t: f64) -> Sls {
    Sls {
        kind: Kind::Tensile,
        poisson: 0.3,
        glassy_pa: 1e9,
        relaxed_pa: 4e6,
        tau_relax_s: 1e-3 * a_t,
    }
}

/// The direct layer solve of one point: (F*/N*, contact length in m).
fn direct(load_n_per_m: f64, speed_m_s: f64, a_t: f64) -> (f64, f64) {
    let spectrum: CreepSpectrum = serde_json::from_str(&sls(a_t).creep_json()).expect("SLS JSON");
    let scene = Scene {
        radius_m: RADIUS_M,
        load_n_per_m,
        speed_m_s,
        poisson: Some(0.3),
        body: Body::Layer {
            thickness_m: COVER_M,
        },
    };
    let r = roll_cover(&scene, &spectrum, 1e-6).expect("direct layer solve");
    assert!(
        r.error_estimate <= 1e-6,
        "reference estimate {}",
        r.error_estimate
    );
    (r.roll.friction, r.roll.contact_length_m)
}

type Row = HashMap<String, String>;

fn f64_of(r: &Row, k: &str) -> f64 {
    r[k].parse().unwrap_or_else(|_| panic!("{k} = {}", r[k]))
}

#[test]
fn covered_friction_tables_and_maps_match_direct_layer_solves() {
    // 100 mm roll, 2 kN/m, 0.5 m/s: on the half-space the contact would run from ~0.5 mm (glassy) to
    // ~15 mm (relaxed); on the 2 mm cover it is 0.94–1.34 mm over −10…30 °C (measured), so `auto`
    // solves the bonded layer at every friction.csv point; the maps move load and speed further.
    let (dir, report) = job_on_sls(
        "covered-run",
        r#"[[scene]]
name = "covered-sls"
description = "exact SLS on a 2 mm cover"
roll_radius_mm = 100.0
load_n_per_m = 2000.0
speed_m_s = 0.5
poisson = 0.3
cover_thickness_mm = 2.0
temps_c = [-10.0, 0.0, 10.0, 20.0, 30.0]
map_temps_c = [0.0, 20.0]
map_speeds_m_s = [0.01, 0.1, 1.0, 10.0]
map_loads_n_per_m = [500.0, 2000.0, 8000.0]
"#,
        &sls(1.0),
        &["--no-bands"],
    );
    let mut a_t = HashMap::new();
    let mut worst = 0.0f64;
    let mut check = |what: &str, got: f64, want: f64, allowed: f64| {
        let e = rel(got, want).abs();
        worst = worst.max(e);
        assert!(
            e <= allowed,
            "{what}: {got} vs direct {want} ({e:.1e} > {allowed:.0e})"
        );
    };
    let table = csv_rows(&report.join("friction.csv"));
    assert_eq!(table.len(), 5, "{table:?}");
    for r in &table {
        let a = 10f64.powf(f64_of(r, "log10_a_t"));
        a_t.insert(r["temp_c"].clone(), a);
        let (friction, length_m) = direct(2000.0, 0.5, a);
        let model = r.get("model").cloned().unwrap_or_default();
        let allowed = if model == "layer" { 1.0 } else { 2.0 } * COVER_TOL + 6e-6;
        println!(
            "friction.csv T = {}: F/N {} (direct {friction:.9e}), l {} mm (direct {:.6}), body {model:?}",
            r["temp_c"],
            r["friction"],
            r["contact_length_mm"],
            length_m * 1e3
        );
        check(
            &format!("F/N at {}", r["temp_c"]),
            f64_of(r, "friction"),
            friction,
            allowed,
        );
        check(
            &format!("resistance at {}", r["temp_c"]),
            f64_of(r, "resistance_n_per_m"),
            friction * 2000.0,
            allowed,
        );
        check(
            &format!("contact length at {}", r["temp_c"]),
            f64_of(r, "contact_length_mm") * 1e-3,
            length_m,
            allowed,
        );
    }
    let mut map_rows = 0;
    for (name, stride) in [("friction_map.csv", 1), ("friction_map_2d.csv", 7)] {
        let map = csv_rows(&report.join(name));
        assert!(!map.is_empty(), "{name} is empty");
        for r in map.iter().step_by(stride) {
            let (friction, length_m) = direct(
                f64_of(r, "load_n_per_m"),
                f64_of(r, "speed_m_s"),
                a_t[&r["temp_c"]],
            );
            let allowed = COVER_TOL + 6e-6;
            check(
                &format!("{name} {r:?}"),
                f64_of(r, "friction"),
                friction,
                allowed,
            );
            if let Some(l) = r.get("contact_length_mm") {
                check(
                    &format!("{name} {r:?} contact length"),
                    l.parse::<f64>().unwrap() * 1e-3,
                    length_m,
                    allowed,
                );
            }
            map_rows += 1;
        }
    }
    println!("{map_rows} map points checked; worst relative difference {worst:.1e}");
    assert!(map_rows >= 14, "{map_rows} map points");
    let _ = std::fs::remove_dir_all(&dir);
}
