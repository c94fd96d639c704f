//! The index page of the main job, `reports/index.html`, and its plots: per scene an overlay of
//! F/N against temperature for every compound (with bands when the run has them), the ranking
//! (flags, ties from the pairwise comparisons, and the tan δ proxy's rank beside the rank by
//! predicted friction), the rank at each temperature, and the compounds listed apart with their
//! reasons; then the failed compounds, warnings and notes.
//!
//! Input: the [`RunSummary`] (outcomes, notes, comparisons), the [`SceneSet`] and the tan δ proxy
//! of each compound ([`TanDeltaProxy`]); output: `index.html` and `index_SCENE.{svg,png}` in the
//! reports folder ([`write_index`]). Every text from outside (names, messages) is escaped and
//! capped in length before it gets here.

use super::chart::{Axis, Chart, Curve, Mark};
use super::datasheet::friction_curve;
use super::error::{write_file, ReportError};
use super::html::{esc, num, num_band, plot_pair, STYLE};
use super::plots;
use super::ranking::{apart, ranked, temps_text};
use crate::results::{
    CompoundFit, CompoundOutcome, PairComparison, RunSummary, SceneSet, SceneSpec,
};
use std::fmt::Write as _;
use std::path::Path;

/// The temperature (°C) and frequency (Hz) of the tan δ proxy: the rolling-resistance indicator
/// compound developers read off a DMA temperature sweep (tan δ at 60 °C, 10 Hz), the same for every
/// scene so the proxy ranks compounds once.
pub(crate) const PROXY_TEMP_C: f64 = 60.0;
/// See [`PROXY_TEMP_C`].
pub(crate) const PROXY_FREQ_HZ: f64 = 10.0;

/// A compound's tan δ proxy.
#[derive(Debug, Clone, PartialEq)]
pub struct TanDeltaProxy {
    /// The compound.
    pub compound: String,
    /// tan δ at `PROXY_TEMP_C` and `PROXY_FREQ_HZ` (NaN where the shift law is undefined).
    pub tan_delta: f64,
    /// `PROXY_TEMP_C` lies outside the measured temperatures (the shift law is extrapolated).
    pub extrapolated: bool,
}

impl TanDeltaProxy {
    /// The proxy of a fit.
    pub fn of(fit: &CompoundFit) -> Self {
        Self {
            compound: fit.compound.clone(),
            tan_delta: super::datasheet::tan_delta_at(fit, PROXY_TEMP_C, PROXY_FREQ_HZ),
            extrapolated: fit
                .measured_range_c()
                .map_or(true, |(a, b)| !(a..=b).contains(&PROXY_TEMP_C)),
        }
    }
}

/// The comparison of `a` and `b` in `scene` as P(a lower than b) and tied, if the run made one.
fn compare(cmp: &[PairComparison], scene: &str, a: &str, b: &str) -> Option<(f64, bool)> {
    cmp.iter().filter(|c| c.scene == scene).find_map(|c| {
        if c.a == a && c.b == b {
            Some((c.prob_a_lower, c.tied))
        } else if c.a == b && c.b == a {
            Some((1.0 - c.prob_a_lower, c.tied))
        } else {
            None
        }
    })
}

/// Ranks 1… of the ranked compounds by tan δ proxy (lower first; NaN last), in the order given.
fn proxy_ranks(names: &[&str], proxies: &[TanDeltaProxy]) -> Vec<Option<usize>> {
    let value = |n: &str| {
        proxies
            .iter()
            .find(|p| p.compound == n)
            .map(|p| p.tan_delta)
            .filter(|v| v.is_finite())
    };
    let mut order: Vec<(usize, f64)> = names
        .iter()
        .enumerate()
        .filter_map(|(i, n)| value(n).map(|v| (i, v)))
        .collect();
    order.sort_by(|a, b| a.1.total_cmp(&b.1));
    let mut ranks = vec![None; names.len()];
    for (r, (i, _)) in order.into_iter().enumerate() {
        ranks[i] = Some(r + 1);
    }
    ranks
}

/// How the bands' notes start (crate::bands::scene, crate::bands::window, crate::bands::tail_note).
const WIDENED_FREQUENCY: &str = "band widened for extrapolation in frequency";
const WIDENED_TEMPERATURE: &str = "band widened for extrapolation in temperature";
const BAND_FEWER: &str = "uncertainty band from ";
const BAND_REFUSED: &str = "uncertainty band refused";

/// Whether a point's warning is one of the bands' notes.
fn is_band_note(w: &str) -> bool {
    [
        WIDENED_FREQUENCY,
        WIDENED_TEMPERATURE,
        BAND_FEWER,
        BAND_REFUSED,
    ]
    .iter()
    .any(|s| w.starts_with(s))
}

/// The flags of a compound in a scene: extrapolated temperatures, the bands' notes (widened,
/// replicates failed, refused), contact validity warnings.
fn flags(o: &CompoundOutcome, scene: &str, allow_extrapolation: bool) -> String {
    let mut f: Vec<String> = Vec::new();
    if let Some(s) = o.standing(scene) {
        if !s.extrapolated_temps_c.is_empty() {
            f.push(format!(
                "extrapolated at {} °C ({})",
                temps_text(&s.extrapolated_temps_c),
                if allow_extrapolation {
                    "averaged"
                } else {
                    "left out"
                }
            ));
        }
    }
    if let Some((_, pts)) = o.friction.iter().find(|(s, _)| s == scene) {
        // the bands' own notes (crate::bands: widened by eq. 15.8 or 15.9, replicates failed,
        // refused) by kind, then the other warnings
        let at = |keep: &dyn Fn(&str) -> bool| -> Vec<String> {
            pts.iter()
                .filter(|p| p.warnings.iter().any(|w| keep(w)))
                .map(|p| p.temp_c.to_string())
                .collect()
        };
        for (what, start) in [
            ("† band widened in frequency", WIDENED_FREQUENCY),
            ("† band widened in temperature", WIDENED_TEMPERATURE),
            ("band from fewer replicates", BAND_FEWER),
            ("band refused", BAND_REFUSED),
        ] {
            let t = at(&|w| w.starts_with(start));
            if !t.is_empty() {
                f.push(format!("{what} at {} °C", t.join(" ")));
            }
        }
        let warned = at(&|w| !is_band_note(w));
        if !warned.is_empty() {
            f.push(format!("validity warnings at {} °C", warned.join(" ")));
        }
    }
    esc(&f.join("; "))
}

/// The ranking table of one scene, then the per-temperature ranks, then those listed apart.
fn scene_tables(summary: &RunSummary, spec: &SceneSpec, proxies: &[TanDeltaProxy]) -> String {
    let outcomes = &summary.compounds;
    let allow = summary.allow_extrapolation;
    let list = ranked(outcomes, &spec.name);
    let names: Vec<&str> = list.iter().map(|(o, _)| o.compound.as_str()).collect();
    let pranks = proxy_ranks(&names, proxies);
    let banded = !summary.comparisons.is_empty();
    if list.is_empty() {
        return format!(
            "<p class=\"bad\">No compound ranked in this scene.</p>{}",
            apart_table(outcomes, &spec.name)
        );
    }
    let mut h = window_words(&list);
    h.push_str("<table><tr><th>rank</th><th class=\"l\">compound</th><th>mean F/N</th><th>vs next</th><th>tan δ 60 °C, 10 Hz</th><th>rank by tan δ</th><th class=\"l\">verdict</th><th class=\"l\">flags</th></tr>");
    for (i, (o, s)) in list.iter().enumerate() {
        let next = list.get(i + 1).map(|(n, _)| n.compound.as_str());
        let vs = match next.and_then(|n| compare(&summary.comparisons, &spec.name, &o.compound, n))
        {
            Some((p, true)) => format!(
                "<span class=\"tie\">tied (P = {})</span>",
                crate::bands::prob_text(p)
            ),
            Some((p, false)) => format!("P(lower) = {}", crate::bands::prob_text(p)),
            None if next.is_some() && !banded => "–".into(),
            None => String::new(),
        };
        let proxy = proxies.iter().find(|p| p.compound == o.compound);
        let (pv, pr) = (
            proxy.map_or("–".to_string(), |p| {
                format!(
                    "{:.4}{}",
                    p.tan_delta,
                    if p.extrapolated { "*" } else { "" }
                )
            }),
            pranks[i],
        );
        let misranked = pr.is_some_and(|r| r != i + 1);
        let _ = write!(
            h,
            "<tr><td>{}</td><td class=\"l\"><a href=\"{n}/datasheet.html\">{n}</a></td><td>{}</td><td class=\"l\">{vs}</td><td>{pv}</td><td{}>{}</td>{}<td class=\"l warn\">{}</td></tr>",
            i + 1,
            s.mean_friction.map_or("–".into(), |m| {
                let (v, b) = num_band(m, s.band.map(|b| (b.p05, b.p95)));
                if b.is_empty() {
                    v
                } else {
                    format!("{v}<span class=\"band\">{b}</span>")
                }
            }),
            if misranked { " class=\"warn\" title=\"the proxy ranks this compound elsewhere\"" } else { "" },
            pr.map_or("–".into(), |r| r.to_string()),
            verdict_cell(s),
            flags(o, &spec.name, allow),
            n = esc(&o.compound)
        );
    }
    h.push_str("</table>");
    h.push_str(&covers_words(&list));
    if !banded {
        h.push_str("<p>No pairwise comparisons in this run (bands not computed): ranks are not tested for ties.</p>");
    }
    if proxies.iter().any(|p| p.extrapolated) {
        let _ = write!(h, "<p>* {PROXY_TEMP_C} °C lies outside the compound's measured temperatures (the shift law is extrapolated).</p>");
    }
    h.push_str(&per_temperature(&list, spec));
    h.push_str(&apart_table(outcomes, &spec.name));
    h
}

/// The verdict of a ranked standing as a cell: `trusted`, or `use with care` with its reasons.
fn verdict_cell(s: &crate::results::SceneStanding) -> String {
    use crate::results::TrustLevel;
    let class = match s.level() {
        TrustLevel::Trusted => "ok",
        TrustLevel::UseWithCare => "warn",
        TrustLevel::NotTrusted => "bad",
    };
    let reasons = s.reasons();
    if reasons.is_empty() {
        format!("<td class=\"l {class}\">{}</td>", s.level().words())
    } else {
        format!(
            "<td class=\"l {class}\">{}<br><small>{}</small></td>",
            s.level().words(),
            reasons
                .iter()
                .map(|r| esc(r))
                .collect::<Vec<_>>()
                .join("<br>")
        )
    }
}

/// Words on the windows the means are over: the temperatures every ranked compound shares, and
/// each compound whose own window was wider (empty when all windows are the same).
fn window_words(list: &[(&CompoundOutcome, &crate::results::SceneStanding)]) -> String {
    let narrowed: Vec<String> = list
        .iter()
        .filter(|(_, s)| !s.own_temps_c.is_empty())
        .map(|(o, s)| {
            format!(
                "{} (own window {} °C)",
                esc(&o.compound),
                temps_text(&s.own_temps_c)
            )
        })
        .collect();
    match list.first() {
        Some((_, s)) if !narrowed.is_empty() => format!(
            "<p class=\"warn\">The compounds' windows differ: every mean below is over the temperatures all ranked compounds share, {} °C. Narrowed to it: {}.</p>",
            temps_text(&s.temps_c),
            narrowed.join(", ")
        ),
        _ => String::new(),
    }
}

/// Words on what the bands cover: replicate specimens pooled, or one specimen's measurement plus
/// the default between-specimen prior (crate::bands::between).
fn covers_words(list: &[(&CompoundOutcome, &crate::results::SceneStanding)]) -> String {
    let (one, many): (Vec<_>, Vec<_>) = list
        .iter()
        .filter(|(_, s)| s.band.is_some())
        .partition(|(o, _)| o.specimens <= 1);
    let mut h = String::new();
    if !one.is_empty() {
        let _ = write!(
            h,
            "<p>Bands of {}: one specimen measured; each band covers that specimen's measurement plus the default spread between specimens (s = {} in ln F/N, from the two shipped EMS-CA specimens, docs/MATH.md §16), and every P(lower) includes it.</p>",
            one.iter().map(|(o, _)| esc(&o.compound)).collect::<Vec<_>>().join(", "),
            crate::bands::PRIOR_SD_LN
        );
    }
    for (o, _) in many {
        let _ = write!(
            h,
            "<p>Bands of {}: {} specimens pooled; each band includes the spread between them.</p>",
            esc(&o.compound),
            o.specimens
        );
    }
    h
}

/// The compounds of a scene listed apart, with their reasons (empty when there are none).
fn apart_table(outcomes: &[CompoundOutcome], scene: &str) -> String {
    let mut h = String::new();
    let apart = apart(outcomes, scene);
    if !apart.is_empty() {
        h.push_str("<h3 class=\"bad\">Not ranked (not trusted or failed)</h3><table><tr><th class=\"l\">compound</th><th>mean F/N</th><th class=\"l\">reasons</th></tr>");
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
                s.and_then(|s| s.mean_friction).map_or("–".into(), num),
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

/// The rank of each ranked compound at each temperature of the scene (1 = lowest F/N there), F/N
/// in the cell's tooltip; a rank that differs from the overall one is marked.
fn per_temperature(
    list: &[(&CompoundOutcome, &crate::results::SceneStanding)],
    spec: &SceneSpec,
) -> String {
    if list.len() < 2 {
        return String::new();
    }
    let at = |o: &CompoundOutcome, t: f64| {
        o.friction
            .iter()
            .find(|(s, _)| *s == spec.name)
            .and_then(|(_, p)| p.iter().find(|p| p.temp_c == t))
            .filter(|p| p.counts())
            .map(|p| p.friction)
    };
    let mut h = String::from("<details open><summary>Rank at each temperature (1 = lowest F/N; n.d.: not determined, – : failed; neither is ranked)</summary><table><tr><th class=\"l\">compound</th>");
    for t in &spec.temps_c {
        let _ = write!(h, "<th>{t} °C</th>");
    }
    h.push_str("</tr>");
    // ranks per temperature
    let ranks: Vec<Vec<Option<(usize, f64)>>> = spec
        .temps_c
        .iter()
        .map(|&t| {
            let mut v: Vec<(usize, f64)> = list
                .iter()
                .enumerate()
                .filter_map(|(i, (o, _))| at(o, t).map(|f| (i, f)))
                .collect();
            v.sort_by(|a, b| a.1.total_cmp(&b.1));
            let mut r = vec![None; list.len()];
            for (k, (i, f)) in v.into_iter().enumerate() {
                r[i] = Some((k + 1, f));
            }
            r
        })
        .collect();
    for (i, (o, _)) in list.iter().enumerate() {
        let _ = write!(h, "<tr><td class=\"l\">{}</td>", esc(&o.compound));
        for (k, col) in ranks.iter().enumerate() {
            match col[i] {
                Some((r, f)) => {
                    let _ = write!(
                        h,
                        "<td{} title=\"F/N = {}\">{r}</td>",
                        if r != i + 1 { " class=\"warn\"" } else { "" },
                        num(f)
                    );
                }
                None => match o
                    .friction
                    .iter()
                    .find(|(s, _)| *s == spec.name)
                    .and_then(|(_, p)| p.iter().find(|p| p.temp_c == spec.temps_c[k]))
                    .and_then(|p| p.undetermined.as_deref())
                {
                    Some(why) => {
                        let _ = write!(h, "<td class=\"warn\" title=\"{}\">n.d.</td>", esc(why));
                    }
                    None => h.push_str("<td>–</td>"),
                },
            }
        }
        h.push_str("</tr>");
    }
    h.push_str("</table></details>");
    h
}

/// A compound's colour on every chart of the run: the palette's entry by its place among the run's
/// compounds (not by its rank, which differs between scenes).
fn compound_colour(outcomes: &[CompoundOutcome], name: &str) -> plotters::style::RGBColor {
    let i = outcomes
        .iter()
        .position(|o| o.compound == name)
        .unwrap_or(0);
    super::chart::PALETTE[i % super::chart::PALETTE.len()]
}

/// The overlay of one scene: F/N against temperature of every compound that computed, with bands,
/// each compound in its own colour ([`compound_colour`]).
fn overlay_chart(outcomes: &[CompoundOutcome], spec: &SceneSpec) -> Chart {
    let ranked_names: Vec<&str> = ranked(outcomes, &spec.name)
        .iter()
        .map(|(o, _)| o.compound.as_str())
        .collect();
    let mut curves: Vec<Curve> = Vec::new();
    // ranked compounds first, in rank order, then the others (dashed)
    for n in &ranked_names {
        if let Some(o) = outcomes.iter().find(|o| o.compound == *n) {
            if let Some((_, pts)) = o.friction.iter().find(|(s, _)| *s == spec.name) {
                curves.push(
                    friction_curve(&o.compound, pts)
                        .coloured(compound_colour(outcomes, &o.compound)),
                );
            }
        }
    }
    for o in outcomes
        .iter()
        .filter(|o| o.error.is_none() && !ranked_names.contains(&o.compound.as_str()))
    {
        if let Some((_, pts)) = o.friction.iter().find(|(s, _)| *s == spec.name) {
            let mut c = friction_curve(&format!("{} (not ranked)", o.compound), pts)
                .coloured(compound_colour(outcomes, &o.compound));
            c.mark = Mark::Dashed;
            curves.push(c);
        }
    }
    Chart {
        title: format!("{}: F/N against temperature", spec.name),
        x: Axis::lin("temperature [°C]"),
        y: Axis::log("F/N"),
        curves,
        colour_bar: None,
    }
}

/// The index page's HTML; `overlays` holds the embedded overlay plot of each scene, in scene order
/// (an empty string for none).
pub fn index_html(
    summary: &RunSummary,
    scenes: &SceneSet,
    proxies: &[TanDeltaProxy],
    overlays: &[String],
) -> String {
    let rule = if summary.allow_extrapolation {
        "every temperature that computed, extrapolated ones included"
    } else {
        "the measured temperatures only"
    };
    let mut h = format!(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><meta name=\"viewport\" content=\"width=device-width\"><title>viscoroll: compounds</title><style>{STYLE}</style></head><body><h1>Compounds and rolling friction</h1><p class=\"sub\">viscoroll {}; F/N averaged per scene over {rule}, lowest first. Each compound has one verdict per scene: <i>trusted</i> (every check passed), <i>use with care</i> (ranked; the reasons are listed: master-curve checks, contact validity, points not determined, extrapolation) or <i>not trusted</i> (fit out of its quality bounds, a failed temperature: listed apart, never ranked). Points not determined (band p95/p05 &gt; {ratio}, or more than {limit} K beyond the measured temperatures) are never ranked or averaged. The tan δ proxy (tan δ at {PROXY_TEMP_C} °C and {PROXY_FREQ_HZ} Hz, the same for every scene) is ranked among the ranked compounds, lower first; where its rank differs from the rank by predicted friction it is marked.</p>",
        env!("CARGO_PKG_VERSION"),
        ratio = crate::results::UNDETERMINED_BAND_RATIO,
        limit = crate::results::EXTRAPOLATION_LIMIT_K,
    );
    for (k, spec) in scenes.scene.iter().enumerate() {
        let _ = write!(
            h,
            "<h2>{}</h2><p>{} (R = {} mm, {} N/m, {} m/s{}, {})</p><section class=\"first\"><div>{}</div><div>{}</div></section>",
            esc(&spec.name),
            esc(&spec.description),
            spec.roll_radius_mm,
            spec.load_n_per_m,
            spec.speed_m_s,
            spec.cover_thickness_mm
                .map_or(String::new(), |c| format!(", {c} mm cover")),
            crate::results::counted(spec.temps_c.len(), "temperature"),
            scene_tables(summary, spec, proxies),
            overlays.get(k).map_or("", String::as_str)
        );
    }
    let outcomes = &summary.compounds;
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
    let notes = &summary.notes;
    if !warned.is_empty() || !notes.is_empty() {
        let n: usize = warned
            .iter()
            .map(|o| o.warnings.len() + o.untrusted.len())
            .sum::<usize>()
            + notes.len();
        let _ = write!(
            h,
            "<h2>Warnings and notes</h2><details><summary>Warnings and notes ({n})</summary><ul>"
        );
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
        h.push_str("</ul></details>");
    }
    h.push_str("</body></html>\n");
    h
}

/// Write the overlay plots (`index_SCENE.{svg,png}`) and `index.html` into `dir`.
pub fn write_index(
    dir: &Path,
    summary: &RunSummary,
    scenes: &SceneSet,
    proxies: &[TanDeltaProxy],
) -> Result<(), ReportError> {
    let mut overlays = Vec::new();
    for spec in &scenes.scene {
        let chart = overlay_chart(&summary.compounds, spec);
        overlays.push(if chart.curves.is_empty() {
            String::new()
        } else {
            let mut plot = plot_pair(dir, &format!("index_{}", spec.name), |p| {
                plots::plot_chart(&chart, "overlay", p)
            })?;
            if chart.curves.iter().any(|c| !c.hollow.is_empty()) {
                plot.push_str("<p>Hollow markers: points not determined (never ranked or averaged; the reason is in friction.csv).</p>");
            }
            plot
        });
    }
    write_file(
        &dir.join("index.html"),
        index_html(summary, scenes, proxies, &overlays).as_bytes(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::ranking::tests::outcome;

    fn summary(outcomes: Vec<CompoundOutcome>, comparisons: Vec<PairComparison>) -> RunSummary {
        RunSummary {
            compounds: outcomes,
            notes: vec![],
            allow_extrapolation: false,
            ranking_csv: "r.csv".into(),
            index_html: "i.html".into(),
            comparisons,
        }
    }

    fn proxy(n: &str, v: f64) -> TanDeltaProxy {
        TanDeltaProxy {
            compound: n.into(),
            tan_delta: v,
            extrapolated: false,
        }
    }

    #[test]
    fn untrusted_compounds_show_apart_with_reasons_and_markup_is_escaped() {
        let scenes = SceneSet::shipped();
        let s = &scenes.scene[0].name;
        let outcomes = vec![
            outcome("<b>x</b>", s, &[(1e-6, false)], &["fit out of bounds"]),
            outcome("good", s, &[(1e-3, false)], &[]),
        ];
        let h = index_html(&summary(outcomes, vec![]), &scenes, &[], &[]);
        assert!(h.contains("Not ranked") && h.contains("fit out of bounds"));
        assert!(h.contains("&lt;b&gt;x&lt;/b&gt;") && !h.contains("<b>x</b>"));
        let ranked_part = &h[..h.find("Not ranked").unwrap()];
        assert!(ranked_part.contains("good/datasheet.html"));
        assert!(!ranked_part.contains("&lt;b&gt;x"));
    }

    #[test]
    fn ties_the_proxy_rank_and_per_temperature_ranks_are_shown() {
        let scenes = SceneSet::shipped();
        let s = scenes.scene[0].name.clone();
        // a lowest on average, but b lower at the first temperature; the proxy orders them b, a
        let outcomes = vec![
            outcome("a", &s, &[(2e-4, false), (1e-4, false)], &[]),
            outcome("b", &s, &[(1e-4, false), (4e-4, false)], &[]),
        ];
        let cmp = vec![PairComparison {
            scene: s.clone(),
            a: "b".into(),
            b: "a".into(),
            prob_a_lower: 0.4,
            tied: true,
        }];
        let proxies = [proxy("a", 0.2), proxy("b", 0.1)];
        let mut outcomes = outcomes;
        outcomes[0].standings[0].band = Some(crate::results::FrictionBand {
            p05: 1.4e-4,
            p50: 1.5e-4,
            p95: 1.6e-4,
        });
        let h = index_html(&summary(outcomes, cmp), &scenes, &proxies, &[]);
        let table = &h[h.find("<table>").unwrap()..h.find("</table>").unwrap()];
        // a is first; its comparison with b is the reversed pair: P(a lower) = 1 − 0.4
        assert!(table.contains("tied (P = 0.60)"), "{table}");
        // the band of a's mean under it, in its power of ten
        assert!(
            table.contains("1.50·10⁻⁴<span class=\"band\">1.40–1.60 ·10⁻⁴</span>"),
            "{table}"
        );
        // the proxy ranks a second: marked as a misrank
        let row_a = &table[table.find("a/datasheet").unwrap()..];
        assert!(row_a.contains("0.2000") && row_a.contains("class=\"warn\" title=\"the proxy"));
        // per temperature: a is rank 2 at 0 °C and 1 at 10 °C
        let per_t = &h[h.find("Rank at each temperature").unwrap()..];
        let row = &per_t[per_t.find("<td class=\"l\">a</td>").unwrap()..];
        let row = &row[..row.find("</tr>").unwrap()];
        // (the helper's points are at 0 and 10 °C; the scene's other temperatures show –)
        assert!(
            row.contains("<td class=\"warn\" title=\"F/N = 2.00·10⁻⁴\">2</td><td title=\"F/N = 1.00·10⁻⁴\">1</td>"),
            "{row}"
        );
    }

    #[test]
    fn the_overlay_draws_bands_and_sets_unranked_compounds_apart() {
        let scenes = SceneSet::shipped();
        let s = scenes.scene[0].name.clone();
        let mut good = outcome("good", &s, &[(1e-4, false), (2e-4, false)], &[]);
        for p in &mut good.friction[0].1 {
            p.band = Some(crate::results::FrictionBand {
                p05: 0.9 * p.friction,
                p50: p.friction,
                p95: 1.1 * p.friction,
            });
        }
        let bad = outcome("bad", &s, &[(3e-4, false), (4e-4, false)], &["flagged"]);
        let c = overlay_chart(&[bad, good], &scenes.scene[0]);
        assert_eq!(c.curves.len(), 2);
        assert_eq!(c.curves[0].name, "good");
        assert_eq!(c.curves[0].band.len(), 2);
        assert!((c.curves[0].band[1].2 - 2.2e-4).abs() < 1e-18);
        assert_eq!(c.curves[1].mark, Mark::Dashed);
        assert!(c.curves[1].name.contains("not ranked"));
    }

    #[test]
    fn a_compound_keeps_its_colour_on_every_overlay() {
        let scenes = SceneSet::shipped();
        let (s0, s1) = (&scenes.scene[0], &scenes.scene[1]);
        // a is lower than b in the first scene and higher in the second, so the rank order (the
        // order of the curves) flips between the two overlays
        let both = |n: &str, f0: f64, f1: f64| {
            let mut o = outcome(n, &s0.name, &[(f0, false)], &[]);
            let o1 = outcome(n, &s1.name, &[(f1, false)], &[]);
            o.friction.extend(o1.friction);
            o.standings.extend(o1.standings);
            o
        };
        let outcomes = vec![both("a", 1e-4, 3e-4), both("b", 2e-4, 1e-4)];
        let colours = |spec: &SceneSpec| -> Vec<(String, Option<plotters::style::RGBColor>)> {
            overlay_chart(&outcomes, spec)
                .curves
                .iter()
                .map(|c| (c.name.clone(), c.colour))
                .collect()
        };
        let (c0, c1) = (colours(s0), colours(s1));
        assert_eq!(c0[0].0, "a", "a ranks first in the first scene");
        assert_eq!(c1[0].0, "b", "b ranks first in the second scene");
        for name in ["a", "b"] {
            let of = |c: &[(String, Option<plotters::style::RGBColor>)]| {
                c.iter().find(|(n, _)| n == name).and_then(|(_, k)| *k)
            };
            assert!(of(&c0).is_some(), "{name} has a colour of its own");
            assert_eq!(of(&c0), of(&c1), "{name} changed colour between scenes");
        }
        assert_ne!(c0[0].1, c0[1].1, "two compounds, two colours");
    }
}
