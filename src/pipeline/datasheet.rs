//! A compound's report folder `reports/NAME/`: plots (SVG, PNG beside), `friction.csv` and
//! `datasheet.html` (plots inline as SVG), plus small helpers shared by the index page.
//!
//! Input: a [`CompoundFit`], its [`Measurement`] (for the raw isotherms) and the friction of each
//! scene; output: files, each written atomically (temp file + rename). tan δ from the relaxation
//! spectrum (E″/E′, MATH.md §2) shifted by the fit's law (MATH.md §6); T_g is taken, as usual for DMA,
//! as the temperature of the tan δ peak at 1 Hz.

use super::compound_fit::CompoundFit;
use super::error::{io, PipelineError};
use super::fit_compound::measured_range_c;
use super::scenes::{FrictionMaps, FrictionPoint, SceneSpec};
use crate::report::{cards, plots};
use crate::Measurement;
use std::f64::consts::PI;
use std::fmt::Write as _;
use std::path::Path;

/// Write `bytes` to `path` atomically (temp file in the same folder, then rename).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), PipelineError> {
    crate::fsutil::write_atomic(path, bytes, true).map_err(io(path))
}

/// HTML-escape text.
pub fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// tan δ of the fit at `temp_c` and `freq_hz` (NaN if the shift law is undefined there).
pub fn tan_delta_at(fit: &CompoundFit, temp_c: f64, freq_hz: f64) -> f64 {
    match fit.relaxation.at_temperature(&fit.shift_law, temp_c, None) {
        Ok(a) => a.spectrum.tan_delta(2.0 * PI * freq_hz),
        Err(_) => f64::NAN,
    }
}

/// The tan δ peak at `freq_hz` over the measured temperatures, scanned in 0.1 K steps:
/// (temperature in °C, tan δ), `None` if the peak lies on an end of the range (no maximum inside).
pub fn tan_delta_peak(fit: &CompoundFit, freq_hz: f64) -> Option<(f64, f64)> {
    let (lo, hi) = measured_range_c(fit)?;
    let n = ((hi - lo) / 0.1).ceil() as usize;
    let mut best: Option<(usize, f64, f64)> = None;
    for i in 0..=n {
        let t = lo + (hi - lo) * i as f64 / n.max(1) as f64;
        let v = tan_delta_at(fit, t, freq_hz);
        if v.is_finite() && best.map_or(true, |(_, _, b)| v > b) {
            best = Some((i, t, v));
        }
    }
    let (i, t, v) = best?;
    (i > 0 && i < n).then_some((t, v))
}

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

fn law_text(law: &crate::ShiftLaw) -> String {
    match law {
        crate::ShiftLaw::Wlf { t_ref_c, c1, c2_k } => {
            format!("WLF: T_ref = {t_ref_c:.2} °C, C1 = {c1:.3}, C2 = {c2_k:.2} K")
        }
        crate::ShiftLaw::Arrhenius {
            t_ref_c,
            activation_energy_j_per_mol,
        } => format!(
            "Arrhenius: T_ref = {t_ref_c:.2} °C, E_a = {:.1} kJ/mol",
            activation_energy_j_per_mol / 1e3
        ),
        crate::ShiftLaw::Table { t_ref_c, points } => {
            format!("table of {} shifts, T_ref = {t_ref_c:.2} °C", points.len())
        }
    }
}

/// Draw `stem.svg` and its PNG twin `stem.png` in `dir`; returns the HTML to embed: the SVG inline
/// and links to both files (or a note when there is nothing to plot).
fn plot_pair<F>(dir: &Path, stem: &str, draw: F) -> Result<String, PipelineError>
where
    F: Fn(&Path) -> Result<(), plots::PlotError>,
{
    let svg = dir.join(format!("{stem}.svg"));
    match draw(&svg) {
        Ok(()) => {}
        // nothing to draw (e.g. every solve failed): say so in the datasheet instead of failing it
        Err(e @ plots::PlotError::NoData { .. }) => {
            return Ok(format!(
                "<p class=\"bad\">{}: {}</p>",
                esc(stem),
                esc(&e.to_string())
            ))
        }
        Err(e) => return Err(e.into()),
    }
    draw(&dir.join(format!("{stem}.png")))?;
    let text = std::fs::read_to_string(&svg).map_err(io(&svg))?;
    Ok(format!(
        "<figure>{text}<figcaption><a href=\"{0}.png\">{0}.png</a> · <a href=\"{0}.svg\">{0}.svg</a></figcaption></figure>\n",
        esc(stem)
    ))
}

/// The 2-D map of one scene: rows of `csv`, and `friction_SCENE_map2d.{svg,png}` (one heat-map
/// panel per map temperature); `None` when the scene has no grid.
fn write_grid(
    dir: &Path,
    spec: &SceneSpec,
    map: &FrictionMaps,
    csv: &mut String,
) -> Result<Option<String>, PipelineError> {
    if map.grid.is_empty() {
        return Ok(None);
    }
    for p in &map.grid {
        let _ = writeln!(
            csv,
            "{},{},{},{},{:e},{:e}",
            spec.name, p.temp_c, p.speed_m_s, p.load_n_per_m, p.friction, p.contact_length_mm
        );
    }
    // the grid is speed-major within each temperature (scenes::friction_maps)
    let mut speeds: Vec<f64> = Vec::new();
    let mut loads: Vec<f64> = Vec::new();
    for p in &map.grid {
        if !speeds.contains(&p.speed_m_s) {
            speeds.push(p.speed_m_s);
        }
        if !loads.contains(&p.load_n_per_m) {
            loads.push(p.load_n_per_m);
        }
    }
    let panels: Vec<plots::HeatPanel> = spec
        .map_temps_c
        .iter()
        .map(|&t| plots::HeatPanel {
            title: format!("{t} °C"),
            z: speeds
                .iter()
                .map(|&v| {
                    loads
                        .iter()
                        .map(|&n| {
                            map.grid
                                .iter()
                                .find(|p| p.temp_c == t && p.speed_m_s == v && p.load_n_per_m == n)
                                .map_or(f64::NAN, |p| p.friction)
                        })
                        .collect()
                })
                .collect(),
        })
        .collect();
    let stem = format!("friction_{}_map2d", spec.name);
    plot_pair(dir, &stem, |p| {
        plots::plot_heatmaps(
            &format!("{}: F/N over speed × load", spec.name),
            ("speed [m/s]", "load [N/m]", "F/N"),
            &speeds,
            &loads,
            &panels,
            p,
        )
    })
    .map(Some)
}

/// Write `dir/` (plots, friction.csv, datasheet.html) for one compound.
pub fn write_report(
    fit: &CompoundFit,
    measurement: &Measurement,
    friction: &[(SceneSpec, Vec<FrictionPoint>)],
    maps: &[FrictionMaps],
    dir: &Path,
) -> Result<(), PipelineError> {
    std::fs::create_dir_all(dir).map_err(io(dir))?;
    let prov = provenance_line(fit);

    // friction.csv (long format, one row per scene and temperature).
    let mut csv = format!("# {prov}\nscene,temp_c,friction,resistance_n_per_m,contact_length_mm,log10_a_t,extrapolated,error\n");
    for (spec, pts) in friction {
        for p in pts {
            let _ = writeln!(
                csv,
                "{},{},{:e},{:e},{:e},{:.6},{},{}",
                spec.name,
                p.temp_c,
                p.friction,
                p.resistance_n_per_m,
                p.contact_length_mm,
                p.log10_a_t,
                p.extrapolated,
                p.error.as_deref().unwrap_or("").replace([',', '\n'], ";")
            );
        }
    }
    write_atomic(&dir.join("friction.csv"), csv.as_bytes())?;

    let series: Vec<(String, Vec<(f64, f64)>)> = friction
        .iter()
        .map(|(s, p)| {
            (
                s.name.clone(),
                p.iter().map(|p| (p.temp_c, p.friction)).collect(),
            )
        })
        .collect();
    let friction_svg = plot_pair(dir, "friction", |p| {
        plots::plot_lines(
            &format!("{}: rolling friction F/N against temperature", fit.compound),
            "temperature [°C]",
            "F/N",
            &series,
            false,
            p,
        )
    })?;

    // Friction maps: CSV and, per scene, F/N against speed and against load (one curve per temperature).
    let mut map_csv = format!("# {prov}\nscene,temp_c,speed_m_s,load_n_per_m,friction\n");
    let mut map_svgs = String::new();
    let mut grid_csv = format!(
        "# {prov}\n# F/N on a speed × load grid at each map temperature (reduced-variable interpolant, relative tolerance {:e})\nscene,temp_c,speed_m_s,load_n_per_m,friction,contact_length_mm\n",
        super::scenes::pipeline_map_settings().tol
    );
    let mut grid_svgs = String::new();
    for ((spec, _), map) in friction.iter().zip(maps) {
        let pts = &map.points;
        for p in pts {
            let _ = writeln!(
                map_csv,
                "{},{},{},{},{:e}",
                spec.name, p.temp_c, p.speed_m_s, p.load_n_per_m, p.friction
            );
        }
        for (by_speed, list, label) in [
            (true, &spec.map_speeds_m_s, "speed [m/s]"),
            (false, &spec.map_loads_n_per_m, "load [N/m]"),
        ] {
            if list.is_empty() {
                continue;
            }
            let series: Vec<(String, Vec<(f64, f64)>)> = spec
                .map_temps_c
                .iter()
                .map(|&t| {
                    let pts: Vec<(f64, f64)> = pts
                        .iter()
                        .filter(|p| {
                            p.temp_c == t
                                && if by_speed {
                                    p.load_n_per_m == spec.load_n_per_m
                                        && list.contains(&p.speed_m_s)
                                } else {
                                    p.speed_m_s == spec.speed_m_s && list.contains(&p.load_n_per_m)
                                }
                        })
                        .map(|p| {
                            (
                                if by_speed {
                                    p.speed_m_s
                                } else {
                                    p.load_n_per_m
                                },
                                p.friction,
                            )
                        })
                        .collect();
                    (format!("{t} °C"), pts)
                })
                .collect();
            let stem = format!(
                "friction_{}_{}",
                spec.name,
                if by_speed { "speed" } else { "load" }
            );
            map_svgs.push_str(&plot_pair(dir, &stem, |p| {
                plots::plot_lines(
                    &format!("{}: F/N against {label}", spec.name),
                    label,
                    "F/N",
                    &series,
                    true,
                    p,
                )
            })?);
        }
        if let Some(html) = write_grid(dir, spec, map, &mut grid_csv)? {
            grid_svgs.push_str(&html);
        }
    }
    write_atomic(&dir.join("friction_map.csv"), map_csv.as_bytes())?;
    write_atomic(&dir.join("friction_map_2d.csv"), grid_csv.as_bytes())?;

    let iso_svg = plot_pair(dir, "isotherms", |p| plots::plot_isotherms(measurement, p))?;
    let master_svg = plot_pair(dir, "master", |p| {
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
    let shift_svg = if shifts.is_empty() {
        String::new()
    } else {
        plot_pair(dir, "shift_factors", |p| {
            plots::plot_shift_factors(&shifts, &laws, p)
        })?
    };

    // Cards (Abaqus, ANSYS, LS-DYNA) with the WLF law when there is one.
    let wlf = fit
        .tts
        .as_ref()
        .and_then(|t| t.wlf.as_ref())
        .or(match fit.shift_law {
            crate::ShiftLaw::Wlf { .. } => Some(&fit.shift_law),
            _ => None,
        });
    let opts = cards::CardOptions::default();
    let mut card_html = String::new();
    for (name, text) in [
        ("Abaqus", cards::abaqus(&fit.relaxation, wlf, &opts)),
        ("ANSYS", cards::ansys(&fit.relaxation, wlf, &opts)),
        ("LS-DYNA", cards::lsdyna(&fit.relaxation, wlf, &opts)),
    ] {
        match text {
            Ok(t) => {
                let _ = write!(card_html, "<h3>{name}</h3><pre>{}</pre>", esc(&t));
            }
            Err(e) => {
                let _ = write!(
                    card_html,
                    "<h3>{name}</h3><p class=\"bad\">{}</p>",
                    esc(&e.to_string())
                );
            }
        }
    }

    let m = &fit.measurement;
    let mut h = String::new();
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{0} datasheet</title>\n<!-- {1} -->\n<style>body{{font-family:sans-serif;max-width:1000px;margin:1em auto;padding:0 1em}}table{{border-collapse:collapse;margin:.5em 0}}td,th{{border:1px solid #bbb;padding:2px 6px;text-align:right}}th{{background:#eee}}td.l{{text-align:left}}pre{{background:#f6f6f6;padding:.5em;overflow-x:auto;font-size:11px}}.bad{{color:#b00}}svg{{max-width:100%;height:auto}}</style></head><body>\n<h1>{0}: viscoelastic datasheet</h1>\n<p>Made by {1}.</p>\n",
        esc(&fit.compound),
        esc(&prov)
    );
    h.push_str("<h2>Source files</h2><table><tr><th>file</th><th>format</th><th>SHA-256</th></tr>");
    for s in &m.sources {
        let _ = write!(
            h,
            "<tr><td class=\"l\">{}</td><td class=\"l\">{}</td><td class=\"l\"><code>{}</code></td></tr>",
            esc(&s.path),
            esc(&s.format),
            esc(&s.sha256)
        );
    }
    h.push_str("</table>");
    let (tlo, thi) = measured_range_c(fit).unwrap_or((f64::NAN, f64::NAN));
    let _ = write!(
        h,
        "<h2>Test conditions</h2><table><tr><th>mode</th><th>Poisson's ratio</th><th>isotherms</th><th>points</th><th>temperatures (°C)</th><th>frequencies (Hz)</th></tr><tr><td class=\"l\">{:?}</td><td>{}</td><td>{}</td><td>{}</td><td>{tlo:.1} … {thi:.1}</td><td>{:.3} … {:.3}</td></tr></table>",
        m.kind, m.poisson, m.n_isotherms, m.n_points, m.freq_min_hz, m.freq_max_hz
    );
    if !m.warnings.is_empty() {
        let _ = write!(
            h,
            "<details><summary>{} ingest warnings</summary><ul>{}</ul></details>",
            m.warnings.len(),
            m.warnings
                .iter()
                .map(|w| format!("<li>{}</li>", esc(w)))
                .collect::<String>()
        );
    }
    let _ = write!(h, "<h2>Raw isotherms</h2>{iso_svg}");
    let _ = write!(
        h,
        "<h2>Master curve and Prony fit</h2><p>Reference temperature {:.2} °C.</p>{master_svg}",
        fit.shift_law.t_ref_c()
    );
    let _ = write!(
        h,
        "<h2>Shift factors</h2><p>Law used: {}.</p><ul>",
        esc(&law_text(&fit.shift_law))
    );
    if let Some(t) = &fit.tts {
        for l in t.wlf.iter().chain(t.arrhenius.iter()) {
            let _ = write!(h, "<li>{}</li>", esc(&law_text(l)));
        }
        for (n, r) in &t.law_rms_log10 {
            let _ = write!(h, "<li>RMS of the shifts about {n}: {r:.3} (log10)</li>");
        }
    }
    let _ = write!(h, "</ul>{shift_svg}");

    h.push_str("<h2>Quality flags</h2><table><tr><th>figure</th><th>value</th><th>bound</th><th>flag</th></tr>");
    for q in &fit.quality {
        let _ = write!(
            h,
            "<tr><td class=\"l\">{}</td><td>{:.4} {}</td><td>{}</td><td class=\"l{}\">{}</td></tr>",
            esc(&q.name),
            q.value,
            esc(&q.unit),
            q.bound.map(|b| format!("{b}")).unwrap_or_default(),
            if q.flagged { " bad" } else { "" },
            if q.flagged { "out of bound" } else { "ok" }
        );
    }
    h.push_str("</table>");
    if let Some(t) = &fit.tts {
        if !t.flags.is_empty() || !t.warnings.is_empty() {
            let _ = write!(
                h,
                "<details><summary>{} master-curve flags and warnings</summary><ul>{}</ul></details>",
                t.flags.len() + t.warnings.len(),
                t.flags.iter().chain(&t.warnings).map(|w| format!("<li>{}</li>", esc(w))).collect::<String>()
            );
        }
    }

    h.push_str("<h2>tan δ</h2><table><tr><th>quantity</th><th>value</th></tr>");
    match tan_delta_peak(fit, 1.0) {
        Some((t, v)) => {
            let _ = write!(h, "<tr><td class=\"l\">tan δ peak at 1 Hz (T<sub>g</sub>)</td><td>{v:.3} at {t:.1} °C</td></tr>");
        }
        None => h.push_str("<tr><td class=\"l\">tan δ peak at 1 Hz (T<sub>g</sub>)</td><td>not inside the measured temperatures</td></tr>"),
    }
    for tc in [0.0, 60.0] {
        let out = measured_range_c(fit).is_some_and(|(a, b)| tc < a || tc > b);
        let _ = write!(
            h,
            "<tr><td class=\"l\">tan δ at {tc} °C, 10 Hz</td><td>{:.4}{}</td></tr>",
            tan_delta_at(fit, tc, 10.0),
            if out { " (extrapolated)" } else { "" }
        );
    }
    h.push_str("</table>");

    h.push_str("<h2>Rolling friction</h2><table><tr><th>scene</th><th>radius (mm)</th><th>load (N/m)</th><th>speed (m/s)</th><th>description</th></tr>");
    for (s, _) in friction {
        let _ = write!(
            h,
            "<tr><td class=\"l\">{}</td><td>{}</td><td>{}</td><td>{}</td><td class=\"l\">{}</td></tr>",
            esc(&s.name),
            s.roll_radius_mm,
            s.load_n_per_m,
            s.speed_m_s,
            esc(&s.description)
        );
    }
    let _ = write!(h, "</table>{friction_svg}<table><tr><th>scene</th><th>T (°C)</th><th>F/N</th><th>F* (N/m)</th><th>contact (mm)</th><th>note</th></tr>");
    for (s, pts) in friction {
        for p in pts {
            let note = match (&p.error, p.extrapolated) {
                (Some(e), _) => esc(e),
                (None, true) => "extrapolated shift law".into(),
                _ => String::new(),
            };
            let _ = write!(
                h,
                "<tr><td class=\"l\">{}</td><td>{}</td><td>{:.4e}</td><td>{:.4}</td><td>{:.3}</td><td class=\"l\">{note}</td></tr>",
                esc(&s.name),
                p.temp_c,
                p.friction,
                p.resistance_n_per_m,
                p.contact_length_mm
            );
        }
    }
    h.push_str("</table>");
    if !map_svgs.is_empty() {
        let _ = write!(
            h,
            "<h3>Friction against speed and load</h3><p>Values in <a href=\"friction_map.csv\">friction_map.csv</a>.</p>{map_svgs}"
        );
    }
    if !grid_svgs.is_empty() {
        let _ = write!(
            h,
            "<h3>Friction maps: speed × load</h3><p>{n}×{n} grid per map temperature, log-spaced over the listed speeds and loads; values in <a href=\"friction_map_2d.csv\">friction_map_2d.csv</a>. All maps come from one interpolant of the dimensionless contact solution in the reduced variable s = l_g/(V·a_T) (relative tolerance {tol:e}; interpolation estimate {est}).</p>{grid_svgs}",
            n = super::scenes::GRID_POINTS,
            tol = super::scenes::pipeline_map_settings().tol,
            est = maps
                .iter()
                .map(|m| format!("{:.1e}", m.error_estimate))
                .collect::<Vec<_>>()
                .join(", ")
        );
    }

    let r = &fit.relaxation;
    let _ = write!(
        h,
        "<h2>Prony series (relaxation, {:?}, at T_ref)</h2><p>E∞ = {:.4e} Pa, {} terms; RMS log10 error E′ {:.4}, E″ {:.4}.</p><table><tr><th>i</th><th>τ<sub>i</sub> (s)</th><th>E<sub>i</sub> (Pa)</th></tr>",
        r.kind, r.modulus_inf_pa, r.terms.len(), fit.prony_info.rms_log10_storage, fit.prony_info.rms_log10_loss
    );
    for (i, t) in r.terms.iter().enumerate() {
        let _ = write!(
            h,
            "<tr><td>{}</td><td>{:.4e}</td><td>{:.4e}</td></tr>",
            i + 1,
            t.tau_s,
            t.modulus_pa
        );
    }
    h.push_str("</table>");
    if let Some(c) = &fit.creep {
        let _ = write!(
            h,
            "<h2>Creep spectrum (exact conversion, at T_ref)</h2><p>J_g = {:.4e} 1/Pa.</p><table><tr><th>j</th><th>τ<sub>j</sub> (s)</th><th>J<sub>j</sub> (1/Pa)</th></tr>",
            c.compliance_glassy_per_pa
        );
        for (i, t) in c.terms.iter().enumerate() {
            let _ = write!(
                h,
                "<tr><td>{}</td><td>{:.4e}</td><td>{:.4e}</td></tr>",
                i + 1,
                t.tau_s,
                t.compliance_per_pa
            );
        }
        h.push_str("</table>");
    }
    let _ = writeln!(h, "<h2>FEA cards</h2>{card_html}</body></html>");
    write_atomic(&dir.join("datasheet.html"), h.as_bytes())
}
