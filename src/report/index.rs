//! The index page of the main job, `reports/index.html`: per scene the ranked (trusted) compounds
//! with links to their datasheets, then the compounds listed apart with their reasons; then the
//! failed compounds, warnings (data flags, extrapolation, contact validity) and notes.
//!
//! Input: the [`CompoundOutcome`]s, the [`SceneSet`] and the notes of the run; output: HTML text.
//! Every text from outside (names, messages) is escaped and capped in length before it gets here.

use super::html::{esc, STYLE};
use super::ranking::{apart, ranked, temps_text};
use crate::results::{CompoundOutcome, SceneSet, SceneSpec};
use std::fmt::Write as _;

/// The table of one scene: ranked compounds, then those listed apart.
fn scene_section(
    outcomes: &[CompoundOutcome],
    spec: &SceneSpec,
    allow_extrapolation: bool,
) -> String {
    let mut h = format!(
        "<h2>{}</h2><p>{} (R = {} mm, {} N/m, {} m/s, {} temperatures)</p><table><tr><th>rank</th><th>compound</th><th>mean F/N</th><th>temperatures averaged (°C)</th></tr>",
        esc(&spec.name),
        esc(&spec.description),
        spec.roll_radius_mm,
        spec.load_n_per_m,
        spec.speed_m_s,
        spec.temps_c.len()
    );
    for (i, (o, s)) in ranked(outcomes, &spec.name).iter().enumerate() {
        let temps: Vec<String> = s
            .temps_c
            .iter()
            .map(|t| {
                if s.extrapolated_temps_c.contains(t) {
                    format!("{t}*")
                } else {
                    t.to_string()
                }
            })
            .collect();
        let left_out = if !allow_extrapolation && !s.extrapolated_temps_c.is_empty() {
            format!(
                " <span class=\"warn\">(extrapolated, left out: {})</span>",
                temps_text(&s.extrapolated_temps_c)
            )
        } else {
            String::new()
        };
        let _ = write!(
            h,
            "<tr><td>{}</td><td class=\"l\"><a href=\"{n}/datasheet.html\">{n}</a></td><td>{:.4e}</td><td class=\"l\">{}{left_out}</td></tr>",
            i + 1,
            s.mean_friction.unwrap_or(f64::NAN),
            temps.join(" "),
            n = esc(&o.compound)
        );
    }
    h.push_str("</table>");
    if allow_extrapolation {
        h.push_str("<p>* extrapolated shift law (outside the measured temperatures), averaged because of --allow-extrapolation.</p>");
    }
    let apart = apart(outcomes, &spec.name);
    if !apart.is_empty() {
        h.push_str("<h3 class=\"bad\">Not ranked (not trusted or failed)</h3><table><tr><th>compound</th><th>mean F/N</th><th>reasons</th></tr>");
        for (o, s, reasons) in apart {
            let link = if o.error.is_none() {
                format!(
                    "<a href=\"{n}/datasheet.html\">{n}</a>",
                    n = esc(&o.compound)
                )
            } else {
                esc(&o.compound)
            };
            let _ = write!(
                h,
                "<tr><td class=\"l\">{link}</td><td>{}</td><td class=\"l bad\">{}</td></tr>",
                s.and_then(|s| s.mean_friction)
                    .map_or(String::from("–"), |f| format!("{f:.4e}")),
                reasons
                    .iter()
                    .map(|r| esc(r))
                    .collect::<Vec<_>>()
                    .join("<br>")
            );
        }
        h.push_str("</table>");
    }
    h
}

/// The index page's HTML.
pub fn index_html(
    outcomes: &[CompoundOutcome],
    scenes: &SceneSet,
    notes: &[String],
    allow_extrapolation: bool,
) -> String {
    let rule = if allow_extrapolation {
        "every temperature that computed, extrapolated ones included (marked *)"
    } else {
        "the measured temperatures only"
    };
    let mut h = format!(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>viscoroll: compounds</title><style>{STYLE}</style></head><body><h1>Compounds and rolling friction</h1><p>viscoroll {}; F/N averaged per scene over {rule}, lowest first. Compounds whose fit is out of its quality bounds or whose friction failed at a temperature are listed apart, never ranked.</p>",
        env!("CARGO_PKG_VERSION")
    );
    for spec in &scenes.scene {
        h.push_str(&scene_section(outcomes, spec, allow_extrapolation));
    }
    let failed: Vec<&CompoundOutcome> = outcomes.iter().filter(|o| o.error.is_some()).collect();
    if !failed.is_empty() {
        h.push_str("<h2 class=\"bad\">Failed compounds</h2><ul>");
        for o in failed {
            let _ = write!(
                h,
                "<li><b>{}</b>: {}</li>",
                esc(&o.compound),
                esc(o.error.as_deref().unwrap_or(""))
            );
        }
        h.push_str("</ul>");
    }
    let warned: Vec<&CompoundOutcome> = outcomes
        .iter()
        .filter(|o| !o.warnings.is_empty() || !o.untrusted.is_empty())
        .collect();
    if !warned.is_empty() || !notes.is_empty() {
        h.push_str("<h2>Warnings and notes</h2><ul>");
        for o in warned {
            for w in o
                .untrusted
                .iter()
                .map(|u| format!("not trusted: {u}"))
                .chain(o.warnings.iter().cloned())
            {
                let _ = write!(h, "<li>{}: {}</li>", esc(&o.compound), esc(&w));
            }
        }
        for n in notes {
            let _ = write!(h, "<li>{}</li>", esc(n));
        }
        h.push_str("</ul>");
    }
    h.push_str("</body></html>\n");
    h
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::ranking::tests::outcome;

    #[test]
    fn untrusted_compounds_show_apart_with_reasons_and_markup_is_escaped() {
        let scenes = SceneSet::shipped();
        let s = &scenes.scene[0].name;
        let outcomes = [
            outcome("<b>x</b>", s, &[(1e-6, false)], &["fit out of bounds"]),
            outcome("good", s, &[(1e-3, false)], &[]),
        ];
        let h = index_html(&outcomes, &scenes, &[], false);
        assert!(h.contains("Not ranked") && h.contains("fit out of bounds"));
        assert!(h.contains("&lt;b&gt;x&lt;/b&gt;") && !h.contains("<b>x</b>"));
        let ranked_part = &h[..h.find("Not ranked").unwrap()];
        assert!(ranked_part.contains("good/datasheet.html"));
        assert!(!ranked_part.contains("&lt;b&gt;x"));
    }
}
