//! A compound's report folder `reports/NAME/`: plots (SVG, PNG beside), `friction.csv`,
//! `friction_map.csv`, `friction_map_2d.csv` and `datasheet.html` (plots inline as SVG).
//!
//! Input: a [`CompoundFit`], its [`Measurement`] (for the raw isotherms), the friction of each scene
//! and its maps; output: files, each written atomically ([`crate::report::write_file`]). The page is
//! assembled from one function per section ([`sections`]); the tables are in [`tables`], the map
//! plots in [`maps`].

pub mod maps;
pub mod sections;
pub mod tables;
pub mod tan_delta;

pub use tan_delta::{tan_delta_at, tan_delta_peak};

use super::error::{io, write_file, ReportError};
use super::html::{esc, plot_pair, STYLE};
use super::plots;
use crate::results::{CompoundFit, FrictionMaps, FrictionPoint, SceneSpec};
use crate::Measurement;
use std::fmt::Write as _;
use std::path::Path;

/// A one-line provenance note (tool, version, compound, input hashes).
pub fn provenance_line(fit: &CompoundFit) -> String {
    let inputs: Vec<String> = fit
        .provenance
        .inputs
        .iter()
        .map(|i| format!("{} sha256={}", i.path, i.sha256))
        .collect();
    format!(
        "{} {}; compound {}; inputs: {}",
        fit.provenance.tool,
        fit.provenance.tool_version,
        fit.compound,
        inputs.join(", ")
    )
}

/// The plots of the measurement and the fit: (isotherms, master curve, shift factors) as HTML.
fn fit_plots(
    dir: &Path,
    fit: &CompoundFit,
    measurement: &Measurement,
) -> Result<(String, String, String), ReportError> {
    let iso = plot_pair(dir, "isotherms", |p| plots::plot_isotherms(measurement, p))?;
    let master = plot_pair(dir, "master", |p| {
        plots::plot_master_fit(&fit.master_curve, &fit.relaxation, p)
    })?;
    let mut laws: Vec<(&str, &crate::ShiftLaw)> = Vec::new();
    let mut shifts: Vec<(f64, f64)> = Vec::new();
    if let Some(t) = &fit.tts {
        shifts = t.shifts.clone();
        if let Some(w) = &t.wlf {
            laws.push(("WLF", w));
        }
        if let Some(a) = &t.arrhenius {
            laws.push(("Arrhenius", a));
        }
    }
    let shift = if shifts.is_empty() {
        String::new()
    } else {
        plot_pair(dir, "shift_factors", |p| {
            plots::plot_shift_factors(&shifts, &laws, p)
        })?
    };
    Ok((iso, master, shift))
}

/// F/N against temperature, one curve per scene.
fn friction_plot(
    dir: &Path,
    fit: &CompoundFit,
    friction: &[(SceneSpec, Vec<FrictionPoint>)],
) -> Result<String, ReportError> {
    let series: Vec<(String, Vec<(f64, f64)>)> = friction
        .iter()
        .map(|(s, p)| {
            (
                s.name.clone(),
                p.iter().map(|p| (p.temp_c, p.friction)).collect(),
            )
        })
        .collect();
    plot_pair(dir, "friction", |p| {
        plots::plot_lines(
            &format!("{}: rolling friction F/N against temperature", fit.compound),
            "temperature [°C]",
            "F/N",
            &series,
            false,
            p,
        )
    })
}

/// The map section: the plots against speed and load, the grid heat maps, with their CSV files named.
fn map_section(
    dir: &Path,
    friction: &[(SceneSpec, Vec<FrictionPoint>)],
    maps: &[FrictionMaps],
) -> Result<String, ReportError> {
    let (mut curves, mut grids) = (String::new(), String::new());
    for ((spec, _), map) in friction.iter().zip(maps) {
        curves.push_str(&maps::speed_and_load_plots(dir, spec, map)?);
        if let Some(html) = maps::grid_plot(dir, spec, map)? {
            grids.push_str(&html);
        }
    }
    let mut h = String::new();
    if !curves.is_empty() {
        let _ = write!(
            h,
            "<h3>Friction against speed and load</h3><p>Values in <a href=\"friction_map.csv\">friction_map.csv</a>.</p>{curves}"
        );
    }
    if !grids.is_empty() {
        let _ = write!(
            h,
            "<h3>Friction maps: speed × load</h3><p>{n}×{n} grid per map temperature, log-spaced over the listed speeds and loads; values in <a href=\"friction_map_2d.csv\">friction_map_2d.csv</a>. All maps come from one interpolant of the dimensionless contact solution in the reduced variable s = l_g/(V·a_T) (relative tolerance {tol:e}; interpolation estimate {est}).</p>{grids}",
            n = crate::results::scene::GRID_POINTS,
            tol = maps.first().map_or(f64::NAN, |m| m.tol),
            est = maps
                .iter()
                .map(|m| format!("{:.1e}", m.error_estimate))
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    Ok(h)
}

/// Write `dir/` (plots, friction tables, datasheet.html) for one compound; `maps` has one entry per
/// scene of `friction`, in the same order; `allow_extrapolation` as in the ranking (the datasheet
/// shows the compound's standing per scene by the same rule).
pub fn write_report(
    fit: &CompoundFit,
    measurement: &Measurement,
    friction: &[(SceneSpec, Vec<FrictionPoint>)],
    maps: &[FrictionMaps],
    allow_extrapolation: bool,
    dir: &Path,
) -> Result<(), ReportError> {
    std::fs::create_dir_all(dir).map_err(io(dir))?;
    let prov = provenance_line(fit);
    let flags = fit.untrusted_reasons();
    let scene_maps: Vec<(&SceneSpec, &FrictionMaps)> =
        friction.iter().map(|(s, _)| s).zip(maps).collect();
    let tol = maps.first().map_or(f64::NAN, |m| m.tol);
    write_file(
        &dir.join("friction.csv"),
        tables::friction_csv(&prov, &flags, friction).as_bytes(),
    )?;
    write_file(
        &dir.join("friction_map.csv"),
        tables::map_csv(&prov, &scene_maps).as_bytes(),
    )?;
    write_file(
        &dir.join("friction_map_2d.csv"),
        tables::grid_csv(&prov, tol, &scene_maps).as_bytes(),
    )?;

    let friction_svg = friction_plot(dir, fit, friction)?;
    let maps_html = map_section(dir, friction, maps)?;
    let (iso_svg, master_svg, shift_svg) = fit_plots(dir, fit, measurement)?;

    let mut h = format!(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{0} datasheet</title>\n<!-- {1} -->\n<style>{STYLE}</style></head><body>\n<h1>{0}: viscoelastic datasheet</h1>\n<p>Made by {1}.</p>\n",
        esc(&fit.compound),
        esc(&prov)
    );
    h.push_str(&sections::trust(fit, friction, allow_extrapolation));
    h.push_str(&sections::sources(fit));
    h.push_str(&sections::test_conditions(fit));
    let _ = write!(h, "<h2>Raw isotherms</h2>{iso_svg}");
    let _ = write!(
        h,
        "<h2>Master curve and Prony fit</h2><p>Reference temperature {:.2} °C.</p>{master_svg}",
        fit.shift_law.t_ref_c()
    );
    h.push_str(&sections::shift_factors(fit, &shift_svg));
    h.push_str(&sections::quality(fit));
    h.push_str(&sections::tan_delta(fit));
    h.push_str(&sections::friction(friction, &friction_svg));
    h.push_str(&maps_html);
    h.push_str(&sections::prony(fit));
    h.push_str(&sections::creep(fit));
    h.push_str(&sections::fea_cards(fit));
    h.push_str("</body></html>\n");
    write_file(&dir.join("datasheet.html"), h.as_bytes())
}
