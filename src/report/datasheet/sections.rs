//! The HTML sections of a datasheet, one function each, in page order: source files, test
//! conditions, shift factors, quality flags, rolling friction, Prony series, creep spectrum, FEA
//! cards (tan δ is in the summary). Each takes the fit (and what else it shows) and returns HTML text.

use crate::report::html::{esc, num};
use crate::report::{card_shift, cards};
use crate::results::{CompoundFit, FrictionPoint, SceneSpec};
use crate::ShiftLaw;
use std::fmt::Write as _;

/// A shift law in words.
pub(crate) fn law_text(law: &ShiftLaw) -> String {
    match law {
        ShiftLaw::Wlf { t_ref_c, c1, c2_k } => {
            format!("WLF: T_ref = {t_ref_c:.2} °C, C1 = {c1:.3}, C2 = {c2_k:.2} K")
        }
        ShiftLaw::Arrhenius {
            t_ref_c,
            activation_energy_j_per_mol,
        } => format!(
            "Arrhenius: T_ref = {t_ref_c:.2} °C, E_a = {:.1} kJ/mol",
            activation_energy_j_per_mol / 1e3
        ),
        ShiftLaw::Table { t_ref_c, points } => {
            format!("table of {} shifts, T_ref = {t_ref_c:.2} °C", points.len())
        }
    }
}

/// The verdict first: whether the fit is trusted, and per scene the mean F/N by the ranking's rule
/// with the temperatures it averages, leaves out or could not compute.
pub(crate) fn trust(
    fit: &CompoundFit,
    friction: &[(SceneSpec, Vec<FrictionPoint>)],
    allow_extrapolation: bool,
) -> String {
    let (reasons, care) = (fit.untrusted_reasons(), fit.care_reasons());
    let mut h = String::from("<h3>Standing in the ranking</h3>");
    h.push_str("<table><tr><th>scene</th><th>mean F/N</th><th>averaged over (°C)</th><th>extrapolated (°C)</th><th>failed (°C)</th><th>not determined (°C)</th><th>verdict</th></tr>");
    for (spec, pts) in friction {
        let s = crate::results::standing(&spec.name, pts, &reasons, &care, allow_extrapolation);
        let list = |t: &[f64]| {
            t.iter()
                .map(|t| t.to_string())
                .collect::<Vec<_>>()
                .join(" ")
        };
        let _ = write!(
            h,
            "<tr><td class=\"l\">{}</td><td>{}</td><td class=\"l\">{}</td><td class=\"l\">{}{}</td><td class=\"l\">{}</td><td class=\"l\">{}</td><td class=\"l{}\">{}</td></tr>",
            esc(&spec.name),
            s.mean_friction.map_or("–".to_string(), |f| format!("{f:.4e}")),
            list(&s.temps_c),
            list(&s.extrapolated_temps_c),
            if s.extrapolated_temps_c.is_empty() { "" } else if allow_extrapolation { " (averaged)" } else { " (left out)" },
            list(&s.failed_temps_c),
            list(&s.undetermined_temps_c),
            match s.level() {
                crate::results::TrustLevel::Trusted => "",
                crate::results::TrustLevel::UseWithCare => " warn",
                crate::results::TrustLevel::NotTrusted => " bad",
            },
            esc(&s.verdict())
        );
    }
    h.push_str("</table>");
    h
}

/// The replicate specimens (issue 31): each one's own F/N beside the pooled fit's and its band,
/// per scene and temperature, and whether the band holds it; empty with one specimen.
pub fn specimens(fit: &CompoundFit, friction: &[(SceneSpec, Vec<FrictionPoint>)]) -> String {
    let n = friction
        .iter()
        .flat_map(|(_, p)| p)
        .map(|p| p.specimens.len())
        .max()
        .unwrap_or(0);
    if n < 2 {
        return String::new();
    }
    let mut h = format!(
        "<h3>Replicate specimens</h3><p>{n} specimens pooled (their files: {}). Each specimen fitted alone and rolled in the same scenes; the pooled fit's band includes the spread between them (docs/MATH.md §16). Dashed in the friction plot.</p><table><tr><th>scene</th><th>T (°C)</th><th>pooled F/N</th><th>band p05…p95</th>",
        esc(&fit
            .measurement
            .sources
            .iter()
            .map(|s| s.path.as_str())
            .collect::<Vec<_>>()
            .join(", "))
    );
    for k in 0..n {
        let _ = write!(h, "<th>specimen {}</th>", k + 1);
    }
    h.push_str("<th>ratio max/min</th></tr>");
    for (spec, pts) in friction {
        for p in pts.iter().filter(|p| p.specimens.len() == n) {
            let _ = write!(
                h,
                "<tr><td class=\"l\">{}</td><td>{}</td><td>{}</td><td>{}</td>",
                esc(&spec.name),
                p.temp_c,
                num(p.friction),
                p.band
                    .map_or("–".into(), |b| format!("{}…{}", num(b.p05), num(b.p95)))
            );
            for &f in &p.specimens {
                let inside = p.band.is_some_and(|b| f >= b.p05 && f <= b.p95);
                let _ = write!(
                    h,
                    "<td{}>{}</td>",
                    if p.band.is_some() && !inside {
                        " class=\"bad\" title=\"outside the band\""
                    } else {
                        ""
                    },
                    num(f)
                );
            }
            let (lo, hi) = p
                .specimens
                .iter()
                .fold((f64::INFINITY, 0.0f64), |(a, b), &f| (a.min(f), b.max(f)));
            let _ = write!(h, "<td>{:.2}</td></tr>", hi / lo);
        }
    }
    h.push_str("</table>");
    h
}

/// Source files with format and SHA-256.
pub fn sources(fit: &CompoundFit) -> String {
    let mut h = format!(
        "<details><summary>Source files and their SHA-256 ({})</summary><table><tr><th>file</th><th>format</th><th>SHA-256</th></tr>",
        fit.measurement.sources.len()
    );
    for s in &fit.measurement.sources {
        let _ = write!(
            h,
            "<tr><td class=\"l\">{}</td><td class=\"l\">{}</td><td class=\"l\"><code>{}</code></td></tr>",
            esc(&s.path),
            esc(&s.format),
            esc(&s.sha256)
        );
    }
    h.push_str("</table>");
    for s in &fit.measurement.sources {
        if !s.metadata.is_empty() {
            let _ = write!(
                h,
                "<details><summary>Metadata of {} ({} entries)</summary><table>{}</table></details>",
                esc(&s.path),
                s.metadata.len(),
                s.metadata
                    .iter()
                    .map(|(k, v)| format!("<tr><td class=\"l\">{}</td><td class=\"l\">{}</td></tr>", esc(k), esc(v)))
                    .collect::<String>()
            );
        }
    }
    h.push_str("</details>");
    h
}

/// Mode, Poisson's ratio, counts and ranges of the measurement, and the ingest warnings.
pub(crate) fn test_conditions(fit: &CompoundFit) -> String {
    let m = &fit.measurement;
    let (tlo, thi) = fit.measured_range_c().unwrap_or((f64::NAN, f64::NAN));
    let mut h = format!(
        "<h2>Measurement</h2><table><tr><th>mode</th><th>Poisson's ratio</th><th>isotherms</th><th>points</th><th>temperatures (°C)</th><th>frequencies (Hz)</th></tr><tr><td class=\"l\">{:?}</td><td>{}</td><td>{}</td><td>{}</td><td>{tlo:.1} … {thi:.1}</td><td>{:.3} … {:.3}</td></tr></table>",
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
    h
}

/// The law used, both fitted laws with their RMS, and the shift-factor plot.
pub fn shift_factors(fit: &CompoundFit, shift_svg: &str) -> String {
    let mut h = format!(
        "<h3>Shift laws</h3><p>Law used: {}.</p><ul>",
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
    h
}

/// The quality figures against their bounds, and the master curve's flags and warnings.
pub fn quality(fit: &CompoundFit) -> String {
    let mut h = String::from(
        "<h2>Fit quality</h2><table><tr><th>figure</th><th>value</th><th>bound</th><th>flag</th></tr>",
    );
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
                t.flags
                    .iter()
                    .chain(&t.warnings)
                    .map(|w| format!("<li>{}</li>", esc(w)))
                    .collect::<String>()
            );
        }
    }
    h
}

/// The scenes and (collapsed) the table of F/N per scene and temperature with its band, contact
/// length and notes; `friction_svg` (may be empty) goes between them.
pub fn friction(friction: &[(SceneSpec, Vec<FrictionPoint>)], friction_svg: &str) -> String {
    let mut h = String::from("<h2>Rolling friction: scenes and details</h2><table><tr><th class=\"l\">scene</th><th>radius (mm)</th><th>load (N/m)</th><th>speed (m/s)</th><th>cover (mm)</th><th class=\"l\">description</th></tr>");
    for (s, _) in friction {
        let _ = write!(
            h,
            "<tr><td class=\"l\">{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td class=\"l\">{}</td></tr>",
            esc(&s.name),
            s.roll_radius_mm,
            s.load_n_per_m,
            s.speed_m_s,
            s.cover_thickness_mm.map_or("–".into(), |c| c.to_string()),
            esc(&s.description)
        );
    }
    let rows: usize = friction.iter().map(|(_, p)| p.len()).sum();
    let _ = write!(h, "</table>{friction_svg}<details><summary>Friction table ({rows} rows; also in <a href=\"friction.csv\">friction.csv</a>)</summary><table><tr><th>scene</th><th>T (°C)</th><th>F/N</th><th>p05</th><th>p95</th><th>F* (N/m)</th><th>contact (mm)</th><th>body</th><th>note</th></tr>");
    for (s, pts) in friction {
        for p in pts {
            let note = esc(&p.note());
            let (p05, p95) = p.band.map_or(("–".to_string(), "–".to_string()), |b| {
                (format!("{:.4e}", b.p05), format!("{:.4e}", b.p95))
            });
            let _ = write!(
                h,
                "<tr><td class=\"l\">{}</td><td>{}</td><td>{:.4e}</td><td>{p05}</td><td>{p95}</td><td>{:.4}</td><td>{:.3}</td><td class=\"l\">{}</td><td class=\"l\">{note}</td></tr>",
                esc(&s.name),
                p.temp_c,
                p.friction,
                p.resistance_n_per_m,
                p.contact_length_mm,
                esc(&p.model)
            );
        }
    }
    h.push_str("</table></details>");
    h
}

/// The relaxation spectrum's Prony terms.
pub fn prony(fit: &CompoundFit) -> String {
    let r = &fit.relaxation;
    let (storage, loss, inf) = r.kind.symbols();
    let mut h = format!(
        "<h2>Spectra and FEA cards</h2><details><summary>Prony series (relaxation, {:?}, at T_ref): {inf} = {:.4e} Pa, {} terms; RMS log10 error {storage} {:.4}, {loss} {:.4}</summary><table><tr><th>i</th><th>τ<sub>i</sub> (s)</th><th>{}<sub>i</sub> (Pa)</th></tr>",
        r.kind, r.modulus_inf_pa, r.terms.len(), fit.prony_info.rms_log10_storage, fit.prony_info.rms_log10_loss, r.kind.letter()
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
    h.push_str("</table></details>");
    h
}

/// The creep spectrum's terms (empty when the fit has none).
pub fn creep(fit: &CompoundFit) -> String {
    let Some(c) = &fit.creep else {
        return String::new();
    };
    let mut h = format!(
        "<details><summary>Creep spectrum (exact conversion, at T_ref): J_g = {:.4e} 1/Pa, {} terms</summary><table><tr><th>j</th><th>τ<sub>j</sub> (s)</th><th>J<sub>j</sub> (1/Pa)</th></tr>",
        c.compliance_glassy_per_pa,
        c.terms.len()
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
    h.push_str("</table></details>");
    h
}

/// Abaqus, ANSYS and LS-DYNA cards with the shift law each can carry (`card_shift`: WLF where it
/// holds, else Arrhenius; a card that cannot be written says why), with the warnings about the law.
pub(crate) fn fea_cards(fit: &CompoundFit) -> String {
    let shifts = fit.tts.as_ref().map(|t| t.shifts.as_slice()).unwrap_or(&[]);
    let chosen = card_shift::card_shift(shifts, &fit.shift_law);
    let opts = cards::CardOptions::default();
    let mut h = String::new();
    let note = |h: &mut String, n: &str| {
        let class = if n.starts_with("WARNING") {
            "warn"
        } else {
            "l"
        };
        let _ = write!(h, "<p class=\"{class}\">{}</p>", esc(n));
    };
    for n in &chosen.notes {
        note(&mut h, &format!("FEA cards' shift: {n}"));
    }
    for target in [
        cards::CardTarget::Abaqus,
        cards::CardTarget::Ansys,
        cards::CardTarget::Lsdyna,
    ] {
        let name = target.name();
        match cards::card(target, &fit.relaxation, chosen.law.as_ref(), &opts) {
            Ok((t, notes)) => {
                for n in &notes {
                    note(&mut h, &format!("{name} card: {n}"));
                }
                let _ = write!(
                    h,
                    "<details><summary>{name} card</summary><pre>{}</pre></details>",
                    esc(&t)
                );
            }
            Err(e) => {
                let _ = write!(
                    h,
                    "<p class=\"bad\">{name} card: {}</p>",
                    esc(&e.to_string())
                );
            }
        }
    }
    h
}
