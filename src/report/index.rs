//! The index page of the main job, `reports/index.html`: per scene the ranked compounds with links
//! to their datasheets, then the failed compounds, warnings and notes.
//!
//! Input: the [`CompoundOutcome`]s, the [`SceneSet`] and the notes of discovery; output: HTML text.

use super::html::{esc, STYLE};
use super::ranking::ranked;
use crate::results::{CompoundOutcome, SceneSet};
use std::fmt::Write as _;

/// The index page's HTML.
pub fn index_html(outcomes: &[CompoundOutcome], scenes: &SceneSet, notes: &[String]) -> String {
    let mut h = format!(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>viscoroll: compounds</title><style>{STYLE}</style></head><body><h1>Compounds and rolling friction</h1><p>viscoroll {}; temperature-averaged F/N per scene, lowest first.</p>",
        env!("CARGO_PKG_VERSION")
    );
    for spec in &scenes.scene {
        let _ = write!(
            h,
            "<h2>{}</h2><p>{} (R = {} mm, {} N/m, {} m/s, {} temperatures)</p><table><tr><th>rank</th><th>compound</th><th>mean F/N</th></tr>",
            esc(&spec.name),
            esc(&spec.description),
            spec.roll_radius_mm,
            spec.load_n_per_m,
            spec.speed_m_s,
            spec.temps_c.len()
        );
        for (i, (o, f)) in ranked(outcomes, &spec.name).iter().enumerate() {
            let _ = write!(
                h,
                "<tr><td>{}</td><td class=\"l\"><a href=\"{n}/datasheet.html\">{n}</a></td><td>{f:.4e}</td></tr>",
                i + 1,
                n = esc(&o.compound)
            );
        }
        h.push_str("</table>");
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
    let warned: Vec<&CompoundOutcome> =
        outcomes.iter().filter(|o| !o.warnings.is_empty()).collect();
    if !warned.is_empty() || !notes.is_empty() {
        h.push_str("<h2>Warnings and notes</h2><ul>");
        for o in warned {
            for w in &o.warnings {
                let _ = write!(h, "<li>{}: {}</li>", esc(&o.compound), esc(w));
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
