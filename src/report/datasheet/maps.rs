//! The friction-map plots of a datasheet: per scene, F/N against speed and against load (one curve
//! per map temperature), and the speed × load heat maps (`friction_SCENE_map2d`).
//!
//! Input: a scene and its [`FrictionMaps`]; output: SVG/PNG files and the HTML that embeds them.

use crate::report::chart::{Axis, Chart, Curve, Mark, PALETTE};
use crate::report::error::ReportError;
use crate::report::html::plot_pair;
use crate::report::plots;
use crate::results::{FrictionMaps, MapPoint, SceneSpec};
use std::path::Path;

/// The points of `pts` on the speed curve (at the scene's load; `by_speed`) or the load curve (at
/// the scene's speed) at temperature `t`, as (speed or load, F/N) sorted by x.
fn on_curve(spec: &SceneSpec, pts: &[MapPoint], t: f64, by_speed: bool) -> Vec<(f64, f64)> {
    let mut v: Vec<(f64, f64)> = pts
        .iter()
        .filter(|p| {
            p.temp_c == t
                && if by_speed {
                    p.load_n_per_m == spec.load_n_per_m
                } else {
                    p.speed_m_s == spec.speed_m_s
                }
        })
        .map(|p| {
            let x = if by_speed {
                p.speed_m_s
            } else {
                p.load_n_per_m
            };
            (x, p.friction)
        })
        .collect();
    v.sort_by(|a, b| a.0.total_cmp(&b.0));
    v.dedup_by(|a, b| a.0 == b.0);
    v
}

/// F/N against speed (at the scene's load) and load (at the scene's speed), one plot each, per map
/// temperature a line through the map's dense curve ([`FrictionMaps::curves`], from the same
/// interpolant as the listed points: in s on a half-space, in s and h/l_g on a cover) and the listed
/// points as dots; a map without dense curves (one written before they existed, or a covered
/// surface that could not be built) shows the listed points joined.
pub(crate) fn speed_and_load_plots(
    dir: &Path,
    spec: &SceneSpec,
    map: &FrictionMaps,
) -> Result<String, ReportError> {
    let mut html = String::new();
    for (by_speed, list, label) in [
        (true, &spec.map_speeds_m_s, "speed [m/s]"),
        (false, &spec.map_loads_n_per_m, "load [N/m]"),
    ] {
        if list.is_empty() {
            continue;
        }
        let mut curves = Vec::new();
        for (i, &t) in spec.map_temps_c.iter().enumerate() {
            let colour = PALETTE[i % PALETTE.len()];
            let listed: Vec<(f64, f64)> = on_curve(spec, &map.points, t, by_speed)
                .into_iter()
                .filter(|p| list.contains(&p.0))
                .collect();
            let dense = on_curve(spec, &map.curves, t, by_speed);
            if dense.len() >= 2 {
                curves.push(Curve::new(format!("{t} °C"), dense, Mark::Line).coloured(colour));
                curves.push(Curve::new("", listed, Mark::Dots).coloured(colour));
            } else {
                curves.push(
                    Curve::new(format!("{t} °C (listed points)"), listed, Mark::LineDots)
                        .coloured(colour),
                );
            }
        }
        let chart = Chart {
            title: format!("{}: F/N against {label}", spec.name),
            x: Axis::log(label),
            y: Axis::log("F/N"),
            curves,
            colour_bar: None,
        };
        let stem = format!(
            "friction_{}_{}",
            spec.name,
            if by_speed { "speed" } else { "load" }
        );
        html.push_str(&plot_pair(dir, &stem, |p| {
            plots::plot_chart(&chart, "friction map", p)
        })?);
    }
    Ok(html)
}

/// Distinct values in first-seen order (the grid is speed-major within each temperature).
fn distinct(values: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut v: Vec<f64> = Vec::new();
    for x in values {
        if !v.contains(&x) {
            v.push(x);
        }
    }
    v
}

/// The heat maps of the speed × load grid (`friction_SCENE_map2d.{svg,png}`, one panel per map
/// temperature); `None` when the scene has no grid.
pub(crate) fn grid_plot(
    dir: &Path,
    spec: &SceneSpec,
    map: &FrictionMaps,
) -> Result<Option<String>, ReportError> {
    if map.grid.is_empty() {
        return Ok(None);
    }
    // The axes have at most GRID_POINTS values each, so `distinct` is cheap.
    let speeds = distinct(map.grid.iter().map(|p| p.speed_m_s));
    let loads = distinct(map.grid.iter().map(|p| p.load_n_per_m));
    let panels: Vec<plots::HeatPanel> = spec
        .map_temps_c
        .iter()
        .map(|&t| {
            let at_t: Vec<_> = map.grid.iter().filter(|p| p.temp_c == t).collect();
            plots::HeatPanel {
                title: format!("{t} °C"),
                z: speeds
                    .iter()
                    .map(|&v| {
                        loads
                            .iter()
                            .map(|&n| {
                                at_t.iter()
                                    .find(|p| p.speed_m_s == v && p.load_n_per_m == n)
                                    .map_or(f64::NAN, |p| p.friction)
                            })
                            .collect()
                    })
                    .collect(),
            }
        })
        .collect();
    let stem = format!("friction_{}_map2d", spec.name);
    let html = plot_pair(dir, &stem, |p| {
        plots::plot_heatmaps(
            &format!("{}: F/N over speed × load", spec.name),
            ("speed [m/s]", "load [N/m]", "F/N"),
            &speeds,
            &loads,
            &panels,
            p,
        )
    })?;
    // Adjacent cells drawn with anti-aliased edges show white seams in a browser (seen in headless
    // Chromium at 1400 px): the cells are rendered with crisp edges instead. The plot is kept at its
    // own width (900 px) rather than stretched to the page, so its labels stay the size of the others.
    let svg = dir.join(format!("{stem}.svg"));
    if let Ok(text) = std::fs::read_to_string(&svg) {
        let crisp = crisp_edges(&text);
        if crisp != text {
            crate::report::error::write_file(&svg, crisp.as_bytes())?;
        }
    }
    Ok(Some(format!(
        "<div style=\"max-width:900px\">{}</div>",
        crisp_edges(&html)
    )))
}

/// `shape-rendering="crispEdges"` on the (first) `<svg>` element of `text`.
fn crisp_edges(text: &str) -> String {
    if text.contains("shape-rendering=\"crispEdges\"") {
        return text.to_string();
    }
    text.replacen("<svg ", "<svg shape-rendering=\"crispEdges\" ", 1)
}
