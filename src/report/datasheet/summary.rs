//! The first screen of a datasheet: the sample as the export describes it (material, instrument,
//! date, operator, geometry), the quality verdict, the glass transition at 1 Hz three ways, tan δ
//! at 0 and 60 °C (10 Hz), and the friction of each scene at its temperatures with bands, the body
//! each scene was solved on and why. No hashes here (they are at the end of the page).
//!
//! Input: a [`CompoundFit`] and its friction per scene; output: HTML text.

use super::tan_delta::tan_delta_at;
use super::transitions::{onset, peak, Quantity};
use crate::report::html::{esc, num, num_band};
use crate::results::{standing, CompoundFit, FrictionPoint, SceneSpec, TrustLevel};
use std::fmt::Write as _;

/// Metadata keys read for each line of the sample table, in order of preference (compared without
/// case): the names TRIOS, EPLEXOR, Proteus, RheoCompass and generic exports use.
const KEYS: [(&str, &[&str]); 5] = [
    (
        "Material",
        &[
            "material / remark",
            "material",
            "sample name",
            "sample",
            "specimen",
            "compound",
        ],
    ),
    (
        "Instrument",
        &[
            "instrument type",
            "instrument name",
            "instrument",
            "device",
            "measuring device",
        ],
    ),
    (
        "Date",
        &[
            "date / time",
            "run date",
            "date/time",
            "date",
            "start time",
            "measurement date",
        ],
    ),
    (
        "Operator",
        &[
            "operator name",
            "operator",
            "logged-in user at run start",
            "user",
        ],
    ),
    (
        "Geometry",
        &[
            "sample shape",
            "geometry name",
            "geometry",
            "measuring system",
            "clamp",
        ],
    ),
];

/// Longest metadata value shown (characters).
const MAX_VALUE: usize = 80;

/// The sample's metadata lines (label, value), from the first source file that has each; values
/// that are placeholders (`Anonymous`, `xxx`, `MM/DD/YYYY`) are left out.
pub(crate) fn sample_lines(fit: &CompoundFit) -> Vec<(&'static str, String)> {
    let placeholder = |v: &str| {
        let v = v.trim().to_lowercase();
        v.is_empty() || v == "anonymous" || v == "xxx" || v == "mm/dd/yyyy"
    };
    let mut out = Vec::new();
    for (label, keys) in KEYS {
        let found = keys.iter().find_map(|k| {
            fit.measurement.sources.iter().find_map(|s| {
                s.metadata
                    .iter()
                    .find(|(mk, v)| mk.trim().eq_ignore_ascii_case(k) && !placeholder(v))
                    .map(|(_, v)| v.clone())
            })
        });
        if let Some(v) = found {
            let mut v: String = v.chars().take(MAX_VALUE).collect();
            if label == "Geometry" {
                for (k, unit) in [("thickness", "mm"), ("width", "mm"), ("length", "mm")] {
                    if let Some(x) = fit.measurement.sources.iter().find_map(|s| {
                        s.metadata
                            .iter()
                            .find(|(mk, _)| mk.eq_ignore_ascii_case(k))
                            .and_then(|(_, v)| v.trim().parse::<f64>().ok())
                    }) {
                        let _ = write!(v, ", {k} {x:.3} {unit}");
                    }
                }
            }
            out.push((label, v));
        }
    }
    out
}

/// The facts column: sample, measurement, verdict, transitions and tan δ.
fn facts(fit: &CompoundFit) -> String {
    let m = &fit.measurement;
    let mut h = String::from("<table class=\"kv\">");
    for (label, v) in sample_lines(fit) {
        let _ = write!(h, "<tr><td>{label}</td><td>{}</td></tr>", esc(&v));
    }
    let formats: Vec<&str> = {
        let mut f: Vec<&str> = m.sources.iter().map(|s| s.format.as_str()).collect();
        f.dedup();
        f
    };
    let (tlo, thi) = fit.measured_range_c().unwrap_or((f64::NAN, f64::NAN));
    let _ = write!(
        h,
        "<tr><td>Export</td><td>{} ({} file{})</td></tr><tr><td>Measured</td><td>{:?}, ν = {}; {} isotherms {tlo:.0} … {thi:.0} °C, {} … {} Hz</td></tr></table>",
        esc(&formats.join(", ")),
        m.sources.len(),
        if m.sources.len() == 1 { "" } else { "s" },
        m.kind,
        m.poisson,
        m.n_isotherms,
        num(m.freq_min_hz),
        num(m.freq_max_hz)
    );
    let t = |v: Option<(f64, f64)>| {
        v.map_or("outside the measured temperatures".to_string(), |(t, _)| {
            format!("{t:.1} °C")
        })
    };
    let (loss, tan) = (
        peak(fit, Quantity::Loss, 1.0),
        peak(fit, Quantity::TanDelta, 1.0),
    );
    let sym = crate::report::plots::symbols(fit.relaxation.kind);
    let _ = write!(
        h,
        "<table class=\"kv\"><tr><td>T<sub>g</sub> at 1 Hz, {} peak</td><td><b>{}</b></td></tr><tr><td>tan δ peak at 1 Hz</td><td>{}{}</td></tr><tr><td>onset of the {} drop, 1 Hz</td><td>{}</td></tr>",
        sym.1,
        t(loss),
        t(tan),
        tan.map_or(String::new(), |(_, v)| format!(" (tan δ = {v:.3})")),
        sym.0,
        onset(fit, 1.0).map_or("outside the measured temperatures".to_string(), |t| format!("{t:.1} °C"))
    );
    for tc in [0.0, 60.0] {
        let out = fit
            .measured_range_c()
            .is_some_and(|(a, b)| tc < a || tc > b);
        let _ = write!(
            h,
            "<tr><td>tan δ at {tc} °C, 10 Hz</td><td>{:.4}{}</td></tr>",
            tan_delta_at(fit, tc, 10.0),
            if out {
                " <span class=\"warn\">(extrapolated shift law)</span>"
            } else {
                ""
            }
        );
    }
    h.push_str("</table>");
    h
}

/// The bodies a scene was solved on: (body, temperatures, reason given at the first of them).
fn bodies(pts: &[FrictionPoint]) -> Vec<(&str, Vec<f64>, &str)> {
    let mut v: Vec<(&str, Vec<f64>, &str)> = Vec::new();
    for p in pts.iter().filter(|p| !p.model.is_empty()) {
        match v.iter_mut().find(|b| b.0 == p.model) {
            Some(b) => b.1.push(p.temp_c),
            None => v.push((&p.model, vec![p.temp_c], &p.model_reason)),
        }
    }
    v
}

/// How the bands stage's widened-band notes start (crate::bands::WIDENED_NOTE_START: eq. 15.8's
/// "in temperature", eq. 15.9's "in frequency").
const TAIL_NOTE_START: &str = "band widened for extrapolation";
/// How its notes on failed replicates start (crate::bands::scene).
const BAND_NOTE_STARTS: [&str; 2] = ["uncertainty band from ", "uncertainty band refused"];

/// The bands' notes under the friction matrix, one line per (scene, temperature): why a band is
/// widened (†, eqs. 15.8 and 15.9), drawn from fewer replicates or refused; the cell's tooltip
/// alone would not print nor show on a screenshot. Empty when there are none.
fn band_notes(friction: &[(SceneSpec, Vec<FrictionPoint>)]) -> String {
    let mut h = String::new();
    for (spec, pts) in friction {
        for p in pts {
            let notes: Vec<String> = p
                .warnings
                .iter()
                .filter_map(|w| {
                    if let Some(rest) = w.strip_prefix(TAIL_NOTE_START) {
                        // "(taken as one standard deviation, docs/MATH.md eq. 15.x)" → "(eq. 15.x)"
                        let short =
                            match rest.find("(taken as one standard deviation, docs/MATH.md ") {
                                Some(i) => format!(
                                    "{}({}",
                                    &rest[..i],
                                    &rest[i + "(taken as one standard deviation, docs/MATH.md "
                                        .len()..]
                                ),
                                None => rest.to_string(),
                            };
                        Some(format!("† widened{short}"))
                    } else {
                        BAND_NOTE_STARTS
                            .iter()
                            .any(|s| w.starts_with(s))
                            .then(|| w.clone())
                    }
                })
                .collect();
            if !notes.is_empty() {
                let _ = write!(
                    h,
                    "<li><b>{}</b> at {} °C: {}</li>",
                    esc(&spec.name),
                    p.temp_c,
                    esc(&notes.join("; "))
                );
            }
        }
    }
    if h.is_empty() {
        h
    } else {
        format!(
            "<details class=\"bandnotes\" open><summary>Notes on the bands (taken as one standard deviation on top of the data's scatter, docs/MATH.md §15)</summary><ul class=\"small\">{h}</ul></details>"
        )
    }
}

/// The friction matrix: a row per scene, a column per temperature, F/N with its band; then the
/// body of each scene and why.
pub(crate) fn friction_matrix(
    fit: &CompoundFit,
    friction: &[(SceneSpec, Vec<FrictionPoint>)],
    allow_extrapolation: bool,
) -> String {
    let mut temps: Vec<f64> = friction
        .iter()
        .flat_map(|(_, p)| p.iter().map(|p| p.temp_c))
        .collect();
    temps.sort_by(f64::total_cmp);
    temps.dedup();
    let banded = friction
        .iter()
        .any(|(_, p)| p.iter().any(|p| p.band.is_some()));
    let mut h = format!(
        "<h2>Rolling friction F/N</h2><p>Per scene and temperature{}; <span class=\"warn\">*</span> extrapolated shift law (outside the measured temperatures){}. The mean is the ranking's figure.</p><table><tr><th class=\"l\">scene</th><th>mean</th>",
        if banded {
            ", with the 90 % band (p05–p95) below each value (<span class=\"warn\">†</span>: band widened for extrapolation, in temperature beyond the measured ones or in frequency beyond the measured master curve; the reasons are listed under the table; the plot draws bands no further than a decade beyond each scene's curve)"
        } else {
            " (no uncertainty bands in this run)"
        },
        if allow_extrapolation {
            ", averaged because of --allow-extrapolation"
        } else {
            ", left out of the mean"
        }
    );
    for t in &temps {
        let _ = write!(h, "<th>{t} °C</th>");
    }
    h.push_str("</tr>");
    let (reasons, care) = (fit.untrusted_reasons(), fit.care_reasons());
    for (spec, pts) in friction {
        let s = standing(&spec.name, pts, &reasons, &care, allow_extrapolation);
        let _ = write!(
            h,
            "<tr><td class=\"l\">{}</td><td class=\"{}\">{}</td>",
            esc(&spec.name),
            if s.trusted() { "" } else { "bad" },
            s.mean_friction.map_or("–".into(), num)
        );
        for t in &temps {
            friction_cell(&mut h, pts.iter().find(|p| p.temp_c == *t));
        }
        h.push_str("</tr>");
    }
    h.push_str("</table>");
    h.push_str(&band_notes(friction));
    h.push_str("<ul>");
    for (spec, pts) in friction {
        scene_body(&mut h, spec, pts);
    }
    h.push_str("</ul>");
    h
}

/// One cell of the friction matrix: empty (no point at this temperature), failed (with the error),
/// or F/N with its warnings, the extrapolation mark and its band.
fn friction_cell(h: &mut String, point: Option<&FrictionPoint>) {
    match point {
        None => h.push_str("<td></td>"),
        Some(p) if p.error.is_some() || !p.friction.is_finite() => {
            let _ = write!(
                h,
                "<td class=\"bad\" title=\"{}\">failed</td>",
                esc(p.error.as_deref().unwrap_or("not finite"))
            );
        }
        Some(p) => {
            let (v, b) = num_band(p.friction, p.band.map(|b| (b.p05, b.p95)));
            let _ = write!(
                h,
                "<td{}>{v}{}{}</td>",
                if p.warnings.is_empty() {
                    String::new()
                } else {
                    format!(" class=\"warn\" title=\"{}\"", esc(&p.warnings.join("; ")))
                },
                if p.extrapolated {
                    "<span class=\"warn\">*</span>"
                } else {
                    ""
                },
                if b.is_empty() {
                    String::new()
                } else {
                    // † a band widened by the shift-law tail term (crate::bands, eq. 15.8)
                    let widened = p.warnings.iter().any(|w| w.starts_with(TAIL_NOTE_START));
                    format!(
                        "<span class=\"band\">{b}{}</span>",
                        if widened {
                            " <span class=\"warn\">†</span>"
                        } else {
                            ""
                        }
                    )
                }
            );
        }
    }
}

/// A scene's line under the matrix: its geometry and the body it was solved on (half-space, or the
/// cover's body at each temperature and why).
fn scene_body(h: &mut String, spec: &SceneSpec, pts: &[FrictionPoint]) {
    let geometry = format!(
        "R = {} mm, {} N/m, {} m/s",
        spec.roll_radius_mm, spec.load_n_per_m, spec.speed_m_s
    );
    match spec.cover_thickness_mm {
        None => {
            let _ = write!(
                h,
                "<li><b>{}</b> ({geometry}): half-space of the compound (no cover in the scene).</li>",
                esc(&spec.name)
            );
        }
        Some(c) => {
            let list: Vec<String> = bodies(pts)
                .into_iter()
                .map(|(model, temps, reason)| {
                    let t: Vec<String> = temps.iter().map(|t| t.to_string()).collect();
                    format!("{} at {} °C ({})", esc(model), t.join(", "), esc(reason))
                })
                .collect();
            let _ = write!(
                h,
                "<li><b>{}</b> ({geometry}): {c} mm cover bonded to a rigid carcass, solved as {}.</li>",
                esc(&spec.name),
                if list.is_empty() {
                    "– (no point solved)".to_string()
                } else {
                    list.join("; ")
                }
            );
        }
    }
}

/// The first screen: facts beside the friction plot, then the friction matrix.
pub(crate) fn first_screen(
    fit: &CompoundFit,
    friction: &[(SceneSpec, Vec<FrictionPoint>)],
    allow_extrapolation: bool,
    friction_svg: &str,
) -> String {
    format!(
        "{}<section class=\"first\"><div>{}</div><div>{friction_svg}</div></section>{}",
        verdict_html(fit, friction, allow_extrapolation),
        facts(fit),
        friction_matrix(fit, friction, allow_extrapolation)
    )
}

/// The compound's verdict, the worst over its scenes, in the words of ranking.csv and the index
/// (crate::results::TrustLevel), with every reason behind it.
pub(crate) fn verdict_html(
    fit: &CompoundFit,
    friction: &[(SceneSpec, Vec<FrictionPoint>)],
    allow_extrapolation: bool,
) -> String {
    let (reasons, care) = (fit.untrusted_reasons(), fit.care_reasons());
    let standings: Vec<_> = friction
        .iter()
        .map(|(spec, pts)| standing(&spec.name, pts, &reasons, &care, allow_extrapolation))
        .collect();
    let level = standings
        .iter()
        .map(|s| s.level())
        .max()
        .unwrap_or(TrustLevel::Trusted);
    let mut why: Vec<String> = Vec::new();
    for s in standings.iter().filter(|s| s.level() == level) {
        for r in s.reasons() {
            let r = if reasons.contains(r) || care.contains(r) {
                r.clone()
            } else {
                format!("{}: {r}", s.scene)
            };
            if !why.contains(&r) {
                why.push(r);
            }
        }
    }
    let class = match level {
        TrustLevel::Trusted => "ok",
        TrustLevel::UseWithCare => "warn",
        TrustLevel::NotTrusted => "bad",
    };
    let mut h = format!(
        "<p class=\"{class}\"><b>Verdict: {}.</b> {}</p>",
        level.words(),
        match level {
            TrustLevel::Trusted => format!(
                "Every check passed: {} quality figures within their bounds, the master-curve \
                 checks, contact validity, every point determined.",
                fit.quality.len()
            ),
            TrustLevel::UseWithCare => "Ranked, with these reasons:".to_string(),
            TrustLevel::NotTrusted => "Listed apart in the ranking, never ranked:".to_string(),
        }
    );
    if !why.is_empty() {
        let _ = write!(
            h,
            "<ul class=\"{class}\">{}</ul>",
            why.iter()
                .map(|r| format!("<li>{}</li>", esc(r)))
                .collect::<String>()
        );
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::datasheet::fixture::fit_with;
    use crate::results::FrictionBand;

    fn demo_fit() -> CompoundFit {
        let spectrum = serde_json::from_value(serde_json::json!({
            "kind": "tensile", "poisson": 0.5, "modulus_inf_pa": 1e6,
            "terms": [{"tau_s": 1.0, "modulus_pa": 1e8}]
        }))
        .unwrap();
        let law = crate::ShiftLaw::Arrhenius {
            t_ref_c: 0.0,
            activation_energy_j_per_mol: 200e3,
        };
        fit_with(spectrum, law, (-60.0, 60.0))
    }

    fn point(t: f64, f: f64, band: Option<FrictionBand>) -> FrictionPoint {
        FrictionPoint {
            temp_c: t,
            log10_a_t: 0.0,
            friction: f,
            resistance_n_per_m: f * 1e4,
            contact_length_mm: 1.0,
            extrapolated: t > 60.0,
            error: None,
            model: "layer".into(),
            model_reason: "cover thin against the contact".into(),
            warnings: vec![],
            band,
            specimens: vec![],
            undetermined: None,
            error_estimate: None,
        }
    }

    /// A band beyond [`super::super::BAND_CLIP_FACTOR`] times the curve's range is clipped there and
    /// each clipped end is listed as cut (so the chart marks it); a band inside is not.
    #[test]
    fn clipped_band_ends_are_marked_as_cut() {
        let b = |p05: f64, p95: f64| {
            Some(FrictionBand {
                p05,
                p50: 0.5 * (p05 + p95),
                p95,
            })
        };
        // curve range 1e-4 … 2e-4: the plot keeps 1e-5 … 2e-3
        let pts = [
            point(0.0, 1e-4, b(0.9e-4, 1.1e-4)),
            point(10.0, 2e-4, b(1e-9, 1e2)),
            point(20.0, 1.5e-4, b(1e-6, 1.6e-4)),
        ];
        let c = super::super::friction_curve("x", &pts);
        let k = super::super::BAND_CLIP_FACTOR;
        let (lo, hi) = (1e-4 / k, 2e-4 * k);
        assert_eq!(
            c.band_cut,
            vec![(10.0, hi, true), (10.0, lo, false), (20.0, lo, false)]
        );
        assert_eq!(c.band[1], (10.0, lo, hi));
        assert_eq!(c.band[0], (0.0, 0.9e-4, 1.1e-4));
    }

    #[test]
    fn first_screen_shows_metadata_verdict_transitions_and_banded_friction_without_hashes() {
        let fit = demo_fit();
        let mut spec = crate::results::SceneSet::shipped().scene[0].clone();
        spec.cover_thickness_mm = Some(5.0);
        let band = FrictionBand {
            p05: 1.1e-4,
            p50: 1.2e-4,
            p95: 1.35e-4,
        };
        let friction = vec![(
            spec,
            vec![point(20.0, 1.2e-4, Some(band)), point(80.0, 2e-4, None)],
        )];
        let h = first_screen(&fit, &friction, false, "<svg></svg>");
        // metadata escaped, the placeholder-free operator shown
        assert!(
            h.contains("SBR &lt;tread&gt;") && h.contains("A. Tester"),
            "{h}"
        );
        assert!(h.contains("Verdict: trusted."), "{h}");
        assert!(h.contains("T<sub>g</sub> at 1 Hz") && h.contains("tan δ at 60 °C, 10 Hz"));
        // the band in the value's power of ten, the extrapolated point marked
        assert!(
            h.contains("1.20·10⁻⁴") && h.contains("1.10–1.35 ·10⁻⁴"),
            "{h}"
        );
        assert!(h.contains("2.00·10⁻⁴<span class=\"warn\">*</span>"));
        // the body and its reason
        assert!(
            h.contains("layer at 20, 80 °C (cover thin against the contact)"),
            "{h}"
        );
        assert!(
            !h.to_lowercase().contains("sha"),
            "hashes on the first screen"
        );
    }
}
