//! The CSV tables of a compound's report folder: `friction.csv` (one row per scene and temperature),
//! `friction_map.csv` (F/N against speed and load) and `friction_map_2d.csv` (the speed × load grid).
//!
//! Input: the friction points and maps of each scene; output: CSV text (crate::report::csv_text).
//! Numbers are printed in their shortest round-trip form (`{:e}`), so a value read back is the value
//! computed.

use crate::report::csv_text::csv_text;
use crate::results::{FrictionMaps, FrictionPoint, SceneSpec};

/// `friction.csv`: scene, temperature, F/N, F* (N/m), contact length, log10 a_T, extrapolated, error,
/// the body solved (`model`) and the point's warnings (`; `-separated).
pub fn friction_csv(prov: &str, friction: &[(SceneSpec, Vec<FrictionPoint>)]) -> String {
    let rows = friction.iter().flat_map(|(spec, pts)| {
        pts.iter().map(move |p| {
            vec![
                spec.name.clone(),
                p.temp_c.to_string(),
                format!("{:e}", p.friction),
                format!("{:e}", p.resistance_n_per_m),
                format!("{:e}", p.contact_length_mm),
                format!("{:.6}", p.log10_a_t),
                p.extrapolated.to_string(),
                p.error.as_deref().unwrap_or("").replace(['\r', '\n'], " "),
                p.model.clone(),
                p.warnings.join("; ").replace(['\r', '\n'], " "),
            ]
        })
    });
    csv_text(
        &[prov.to_string()],
        &[
            "scene",
            "temp_c",
            "friction",
            "resistance_n_per_m",
            "contact_length_mm",
            "log10_a_t",
            "extrapolated",
            "error",
            "model",
            "warnings",
        ],
        rows,
    )
}

/// `friction_map.csv`: F/N against the listed speeds and loads at every map temperature.
pub fn map_csv(prov: &str, scenes: &[(&SceneSpec, &FrictionMaps)]) -> String {
    let rows = scenes.iter().flat_map(|(spec, map)| {
        map.points.iter().map(move |p| {
            vec![
                spec.name.clone(),
                p.temp_c.to_string(),
                p.speed_m_s.to_string(),
                p.load_n_per_m.to_string(),
                format!("{:e}", p.friction),
            ]
        })
    });
    csv_text(
        &[prov.to_string()],
        &["scene", "temp_c", "speed_m_s", "load_n_per_m", "friction"],
        rows,
    )
}

/// `friction_map_2d.csv`: F/N and contact length on the speed × load grid.
pub fn grid_csv(prov: &str, tol: f64, scenes: &[(&SceneSpec, &FrictionMaps)]) -> String {
    let rows = scenes.iter().flat_map(|(spec, map)| {
        map.grid.iter().map(move |p| {
            vec![
                spec.name.clone(),
                p.temp_c.to_string(),
                p.speed_m_s.to_string(),
                p.load_n_per_m.to_string(),
                format!("{:e}", p.friction),
                format!("{:e}", p.contact_length_mm),
            ]
        })
    });
    csv_text(
        &[
            prov.to_string(),
            format!("F/N on a speed × load grid at each map temperature (reduced-variable interpolant, relative tolerance {tol:e})"),
        ],
        &[
            "scene",
            "temp_c",
            "speed_m_s",
            "load_n_per_m",
            "friction",
            "contact_length_mm",
        ],
        rows,
    )
}
