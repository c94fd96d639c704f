//! A compound's report folder `reports/NAME/`: plots (SVG, PNG beside), `friction.csv`,
//! `friction_map.csv`, `friction_map_2d.csv` (each with its sidecar `NAME.meta.json`,
//! crate::report::csv_meta) and `datasheet.html` (plots inline as SVG).
//!
//! Input: a [`CompoundFit`], its [`Measurement`] (for the raw isotherms), the friction of each scene
//! and its maps; output: files, each written atomically ([`crate::report::write_file`]). The page is
//! assembled from one function per section ([`sections`]); the tables are in [`tables`], the map
//! plots in [`maps`].

pub(crate) mod curves;
#[cfg(test)]
#[cfg(test)]
pub(crate) mod fixture;
pub(crate) mod maps;
pub(crate) mod sections;
pub(crate) mod summary;
pub(crate) mod tables;
pub(crate) mod tan_delta;
pub(crate) mod transitions;

pub use tan_delta::tan_delta_at;

use super::chart::{Axis, Chart, Curve, Mark};
use super::csv_meta::write_table;
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

/// F/N against temperature, one curve per scene, with its band when there is one.
fn friction_plot(
    dir: &Path,
    fit: &CompoundFit,
    friction: &[(SceneSpec, Vec<FrictionPoint>)],
) -> Result<String, ReportError> {
    let chart = Chart {
        title: format!("{}: rolling friction F/N", fit.compound),
        x: Axis::lin("temperature [°C]"),
        y: Axis::log("F/N"),
        curves: friction
            .iter()
            .map(|(s, p)| friction_curve(&s.name, p))
            .chain(specimen_curves(friction))
            .collect(),
        colour_bar: None,
    };
    plot_pair(dir, "friction", |p| {
        plots::plot_chart(&chart, "friction", p)
    })
}

/// Each replicate specimen's own F/N against temperature per scene (dashed), when the compound
/// pools several (crate::pipeline::specimens).
fn specimen_curves(friction: &[(SceneSpec, Vec<FrictionPoint>)]) -> Vec<Curve> {
    let mut v = Vec::new();
    for (s, pts) in friction {
        let n = pts.iter().map(|p| p.specimens.len()).max().unwrap_or(0);
        for k in 0..n {
            let points = pts
                .iter()
                .filter_map(|p| p.specimens.get(k).map(|&f| (p.temp_c, f)))
                .collect();
            v.push(Curve::new(
                format!("{}, specimen {}", s.name, k + 1),
                points,
                Mark::Dashed,
            ));
        }
    }
    v
}

/// Bands are drawn no further than this factor beyond the curve's own lowest and highest F/N: a
/// band widened for extrapolation (crate::bands eqs. 15.8, 15.9) can span ten decades and would
/// flatten every curve of the plot; the friction table gives it in full.
pub const BAND_CLIP_FACTOR: f64 = 10.0;

/// One scene's F/N against temperature as a curve with its band (the p05…p95 of each point that
/// has one, clipped to [`BAND_CLIP_FACTOR`] beyond the curve's range; each clipped end in
/// [`Curve::band_cut`], so the chart marks it); points not determined are drawn hollow.
pub fn friction_curve(name: &str, pts: &[FrictionPoint]) -> Curve {
    let mut c = Curve::new(
        name,
        pts.iter().map(|p| (p.temp_c, p.friction)).collect(),
        Mark::LineDots,
    );
    let f = pts
        .iter()
        .map(|p| p.friction)
        .filter(|f| f.is_finite() && *f > 0.0);
    let (lo, hi) = f.fold((f64::INFINITY, 0.0f64), |(a, b), f| (a.min(f), b.max(f)));
    let (lo, hi) = if lo <= hi {
        (lo / BAND_CLIP_FACTOR, hi * BAND_CLIP_FACTOR)
    } else {
        (0.0, f64::INFINITY)
    };
    c.band = pts
        .iter()
        .filter_map(|p| p.band.map(|b| (p.temp_c, b.p05.max(lo), b.p95.min(hi))))
        .collect();
    c.band_cut = pts
        .iter()
        .filter_map(|p| p.band.map(|b| (p.temp_c, b)))
        .flat_map(|(t, b)| {
            [
                (b.p95 > hi).then_some((t, hi, true)),
                (b.p05 < lo).then_some((t, lo, false)),
            ]
        })
        .flatten()
        .collect();
    // a point not determined is drawn hollow (issue 31)
    c.hollow = pts
        .iter()
        .enumerate()
        .filter(|(_, p)| p.undetermined.is_some())
        .map(|(i, _)| i)
        .collect();
    c
}

/// The viscoelastic curves: temperature sweeps, master curves, E(t) and J(t), isotherms and shift
/// factors, as one grid of plots.
fn curve_plots(dir: &Path, fit: &CompoundFit, measured: Measured) -> Result<String, ReportError> {
    let (sweep, sweep_tan) = curves::temperature_sweeps(fit, measured.pooled);
    let (relax, creep) = curves::relaxation_and_creep(fit);
    let mut h = String::new();
    for (stem, chart) in [
        ("sweep_moduli", Some(sweep)),
        ("sweep_tan_delta", Some(sweep_tan)),
        (
            "specimen_moduli",
            curves::specimen_sweeps(fit, measured.specimens),
        ),
        ("master_tan_delta", Some(curves::master_tan_delta(fit))),
        ("relaxation_modulus", Some(relax)),
        ("creep_compliance", creep),
    ] {
        if let Some(c) = chart {
            h.push_str(&plot_pair(dir, stem, |p| {
                plots::plot_chart(&c, "curve", p)
            })?);
        }
    }
    Ok(h)
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
            "<h3>Friction against speed and load</h3><p>Values in <a href=\"friction_map.csv\">friction_map.csv</a>.</p><div class=\"grid\">{curves}</div>"
        );
    }
    if !grids.is_empty() {
        // Per scene, the interpolant its maps come from: in s = l_g/(V·a_T) alone on a half-space,
        // in s and η = h/l_g of bonded-layer solves on a cover (crate::contact::maps::covered).
        let how = friction
            .iter()
            .zip(maps)
            .filter(|(_, m)| !m.grid.is_empty())
            .map(|((spec, _), m)| {
                let body = match spec.cover_thickness_mm {
                    Some(h) => format!(
                        "a 2-D interpolant of bonded-layer solves in s and η = h/l_g ({h} mm cover)"
                    ),
                    None => "a 1-D interpolant of half-space solves in s".to_string(),
                };
                format!(
                    "{}: {body}, relative tolerance {:e}, interpolation estimate {:.1e}, {} solves",
                    crate::report::html::esc(&spec.name),
                    m.tol,
                    m.error_estimate,
                    m.solves
                )
            })
            .collect::<Vec<_>>()
            .join("; ");
        let _ = write!(
            h,
            "<h3>Friction maps: speed × load</h3><p>{n}×{n} grid per map temperature, log-spaced over the listed speeds and loads; values in <a href=\"friction_map_2d.csv\">friction_map_2d.csv</a>. Each scene's maps come from one interpolant of its dimensionless contact solution (s = l_g/(V·a_T) the reduced time), not from a solve per point: {how}.</p>{grids}",
            n = crate::results::scene::GRID_POINTS,
        );
    }
    Ok(h)
}

/// The measurement a fit was made from: the one the fit took (pooled when the compound has
/// replicate specimens, crate::pipeline::specimens), and each specimen's own (empty with one).
#[derive(Clone, Copy)]
pub struct Measured<'a> {
    /// What the fit took.
    pub pooled: &'a Measurement,
    /// Each replicate specimen's measurement, in the compound's order.
    pub specimens: &'a [Measurement],
}

/// Write `dir/` (plots, friction tables, datasheet.html) for one compound; `maps` has one entry per
/// scene of `friction`, in the same order; `allow_extrapolation` as in the ranking (the datasheet
/// shows the compound's standing per scene by the same rule); `fit_warnings` are the warnings of
/// the fit that hold for every row (friction.csv writes them once, with a code per row).
pub fn write_report(
    fit: &CompoundFit,
    measured: Measured,
    fit_warnings: &[String],
    friction: &[(SceneSpec, Vec<FrictionPoint>)],
    maps: &[FrictionMaps],
    allow_extrapolation: bool,
    dir: &Path,
) -> Result<(), ReportError> {
    crate::fsutil::jail::create_dir_all(dir).map_err(io(dir))?;
    let prov = provenance_line(fit);
    let flags = fit.untrusted_reasons();
    let scene_maps: Vec<(&SceneSpec, &FrictionMaps)> =
        friction.iter().map(|(s, _)| s).zip(maps).collect();
    let tol = maps.first().map_or(f64::NAN, |m| m.tol);
    let meta = |table: &str, description: &str| {
        tables::compound_meta(fit, table, description, &flags, fit_warnings)
    };
    write_table(
        &dir.join("friction.csv"),
        &tables::friction_csv(&flags, fit_warnings, friction),
        &meta("friction.csv", tables::FRICTION_DESCRIPTION)
            .setting("allow_extrapolation", allow_extrapolation),
    )?;
    write_table(
        &dir.join("friction_map.csv"),
        &tables::map_csv(&scene_maps),
        &meta("friction_map.csv", tables::MAP_DESCRIPTION),
    )?;
    write_table(
        &dir.join("friction_map_2d.csv"),
        &tables::grid_csv(&scene_maps),
        &meta("friction_map_2d.csv", tables::GRID_DESCRIPTION)
            .setting("tolerance", (tol.is_finite()).then_some(tol)),
    )?;

    let friction_svg = friction_plot(dir, fit, friction)?;
    let maps_html = map_section(dir, friction, maps)?;
    let (iso_svg, master_svg, shift_svg) = fit_plots(dir, fit, measured.pooled)?;
    let curves_html = curve_plots(dir, fit, measured)?;

    let created = fit
        .provenance
        .created_utc
        .as_deref()
        .map_or(String::new(), |d| format!(", fitted {}", esc(d)));
    let mut h = format!(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><meta name=\"viewport\" content=\"width=device-width\"><title>{0} datasheet</title>\n<style>{STYLE}</style></head><body>\n<h1>{0}</h1><p class=\"sub\">Viscoelastic datasheet and rolling friction · {1} {2}{created}</p>\n",
        esc(&fit.compound),
        esc(&fit.provenance.tool),
        esc(&fit.provenance.tool_version),
    );
    h.push_str(&summary::first_screen(
        fit,
        friction,
        allow_extrapolation,
        &friction_svg,
    ));
    // the bands' own compound-level warnings (failed refits of the ensemble, bands not computed:
    // crate::pipeline's band warnings) under the friction they concern
    for w in fit_warnings
        .iter()
        .filter(|w| w.starts_with("uncertainty band"))
    {
        let _ = write!(h, "<p class=\"warn\">{}</p>", esc(w));
    }
    let _ = write!(
        h,
        "<h2>Viscoelastic curves</h2><p>Lines: the Prony fit shifted by the law used ({}); points: the measurement. Reference temperature {:.2} °C.</p><div class=\"grid\">{master_svg}{curves_html}{iso_svg}{shift_svg}</div>",
        esc(&sections::law_text(&fit.shift_law)),
        fit.shift_law.t_ref_c(),
    );
    h.push_str(&sections::shift_factors(fit, ""));
    h.push_str(&sections::friction(friction, ""));
    h.push_str(&sections::specimens(fit, friction));
    h.push_str(&sections::trust(fit, friction, allow_extrapolation));
    h.push_str(&maps_html);
    h.push_str(&sections::quality(fit));
    h.push_str(&sections::test_conditions(fit));
    h.push_str(&sections::sources(fit));
    h.push_str(&sections::prony(fit));
    h.push_str(&sections::creep(fit));
    h.push_str(&sections::fea_cards(fit));
    let _ = write!(
        h,
        "<details><summary>Provenance</summary><p>Made by {}.</p></details>",
        esc(&prov)
    );
    h.push_str("</body></html>\n");
    write_file(&dir.join("datasheet.html"), h.as_bytes())
}
