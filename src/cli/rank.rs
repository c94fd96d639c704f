//! `viscoroll rank FIT.json… [--scene NAME]`: compounds ordered by predicted rolling friction in a
//! scene — the temperature-averaged F/N (measured temperatures only unless `--allow-extrapolation`)
//! and a table per temperature; compounds not trusted (fit out of bounds, a failed temperature) are
//! listed apart, never ranked.
//!
//! Scenes as `run` takes them: `--scenes FILE`, else `./scenes.toml` if present, else the shipped
//! scenes (said on stderr). The bands are those of `run` (from the ensemble the fit file carries;
//! `--no-bands` skips them).
//!
//! `--json` prints one object: `scene`, `scenes_from`, `ranking` [{`rank`, `compound`,
//! `mean_friction`, `band`, `standing`, `friction`: [{`temp_c`, `friction`, `band`, `extrapolated`,
//! …}]}], `apart` [{`compound`, `mean_friction`, `reasons`}], `failed` [{`compound`, `error`}],
//! `comparisons` [{`a`, `b`, `prob_a_lower`, `tied`}]. Exit 1 when a fit failed, 3 when some
//! compound is not trusted.
//!
//! `viscoroll rank --out OUT` (no fit files) merges the finished shards of `run --shard K/N` in OUT
//! into `reports/ranking.csv` and `reports/index.html`, the whole run's ranking and index, and
//! prints and exits as `viscoroll run` does (crate::pipeline::shard).

use super::Exit;
use crate::pipeline::{CompoundFit, SceneSet};
use anyhow::{bail, Context};
use std::path::{Path, PathBuf};

/// Arguments of `viscoroll rank`.
#[derive(Debug, clap::Args)]
#[command(after_help = super::EXIT_CODES)]
pub struct Args {
    /// Fit files (fits/NAME.json).
    #[arg(required_unless_present = "out", conflicts_with = "out")]
    pub fits: Vec<PathBuf>,
    /// Merge the finished shards of `run --shard K/N --out OUT` into OUT's ranking and index
    /// (instead of ranking fit files in one scene).
    #[arg(long, value_name = "OUT")]
    pub out: Option<PathBuf>,
    /// Scene name [default: the first scene].
    #[arg(long)]
    pub scene: Option<String>,
    /// Scenes TOML [default: ./scenes.toml if present, else the shipped scenes].
    #[arg(long)]
    pub scenes: Option<PathBuf>,
    /// Skip the uncertainty bands (and so the ties).
    #[arg(long)]
    pub no_bands: bool,
    /// Average extrapolated temperatures too (marked *).
    #[arg(long)]
    pub allow_extrapolation: bool,
    /// With --out: do not write the run's workbook reports/viscoroll.xlsx.
    #[arg(long, requires = "out")]
    pub no_xlsx: bool,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
}

/// Run `viscoroll rank`.
pub fn run(args: Args) -> anyhow::Result<()> {
    if let Some(out) = &args.out {
        return merge(out, !args.no_xlsx, args.json);
    }
    let file = crate::pipeline::run::scenes_file(args.scenes.as_deref(), Path::new("."));
    let set = match &file {
        Some(p) => SceneSet::read(p)?,
        None => SceneSet::shipped(),
    };
    let origin = crate::pipeline::run::scenes_origin(file.as_deref());
    let spec = match &args.scene {
        None => set.scene[0].clone(),
        Some(n) => match set.scene.iter().find(|s| &s.name == n) {
            Some(s) => s.clone(),
            None => {
                let names: Vec<&str> = set.scene.iter().map(|s| s.name.as_str()).collect();
                bail!("--scene {n:?}: no such scene (have: {})", names.join(", "))
            }
        },
    };
    let mut fits = Vec::new();
    for p in &args.fits {
        fits.push(CompoundFit::read(p).with_context(|| "reading fit files")?);
    }
    let bands = (!args.no_bands).then(crate::bands::BandSettings::default);
    let (results, comparisons) =
        crate::pipeline::run::rank_fits(&fits, &spec, args.allow_extrapolation, bands.as_ref());
    let (mut ranking, mut apart, mut failed) = (Vec::new(), Vec::new(), Vec::new());
    for r in &results {
        match r {
            Ok((c, pts, s)) if s.trusted() => ranking.push(serde_json::json!({
                "rank": ranking.len() + 1, "compound": c, "mean_friction": s.mean_friction,
                "verdict": s.verdict(), "band": s.band, "standing": s, "friction": pts,
            })),
            Ok((c, _, s)) => apart.push(serde_json::json!({
                "compound": c, "mean_friction": s.mean_friction, "reasons": s.untrusted,
            })),
            Err((c, e)) => failed.push(serde_json::json!({"compound": c, "error": e})),
        }
    }
    let obj = serde_json::json!({
        "scene": spec, "scenes_from": origin, "ranking": ranking, "apart": apart,
        "failed": failed, "comparisons": comparisons,
    });
    if !args.json {
        let others = set.scene.len() - 1;
        if args.scene.is_none() && others > 0 {
            errln!("{origin}; ranking its first scene ({others} more: --scene NAME)");
        } else {
            errln!("{origin}");
        }
        print_table(&spec, &results);
    }
    if failed.is_empty() && apart.is_empty() {
        if args.json {
            outln!("{}", super::output::versioned(obj));
        }
        return Ok(());
    }
    let (code, kind, message) = if !failed.is_empty() {
        (
            1,
            "compounds_failed",
            format!(
                "{} of {} failed",
                failed.len(),
                crate::results::counted(results.len(), "compound")
            ),
        )
    } else {
        (
            3,
            "untrusted_results",
            format!(
                "{} of {} not trusted and listed apart",
                apart.len(),
                crate::results::counted(results.len(), "compound")
            ),
        )
    };
    Err(Exit {
        code,
        kind,
        message,
        detail: Some(obj),
    }
    .into())
}

/// The human table on stderr: ranked compounds with F/N per temperature, then the others.
fn print_table(spec: &crate::results::SceneSpec, results: &[crate::pipeline::run::RankedFit]) {
    errln!(
        "scene {}: R = {} mm, {} N/m, {} m/s; lowest rolling friction first",
        spec.name,
        spec.roll_radius_mm,
        spec.load_n_per_m,
        spec.speed_m_s
    );
    let mut head = format!(
        "{:>4} {:<24} {:>11} {:>23}",
        "rank", "compound", "mean F/N", "90 % band of the mean"
    );
    for t in &spec.temps_c {
        head.push_str(&format!(" {:>10}", format!("{t} °C")));
    }
    errln!("{head}");
    let mut rank = 0;
    for (c, pts, s) in results.iter().filter_map(|r| r.as_ref().ok()) {
        let label = if s.trusted() {
            rank += 1;
            rank.to_string()
        } else {
            "–".to_string()
        };
        let band = s.band.map_or("–".to_string(), |b| {
            format!("{:.3e} … {:.3e}", b.p05, b.p95)
        });
        let mut line = format!(
            "{label:>4} {:<24} {:>11.4e} {band:>23}",
            c,
            s.mean_friction.unwrap_or(f64::NAN)
        );
        for p in pts {
            line.push_str(&format!(
                " {:>9.3e}{}",
                p.friction,
                if p.extrapolated { "*" } else { " " }
            ));
        }
        errln!("{line}");
    }
    errln!("* shift law extrapolated beyond the measured temperatures (averaged only with --allow-extrapolation)");
    for (c, _, s) in results
        .iter()
        .filter_map(|r| r.as_ref().ok())
        .filter(|(_, _, s)| s.trusted() && !s.tied_with.is_empty())
    {
        errln!(
            "{c}: order against {} not significant (tied)",
            s.tied_with.join(", ")
        );
    }
    for (c, _, s) in results
        .iter()
        .filter_map(|r| r.as_ref().ok())
        .filter(|(_, _, s)| !s.trusted())
    {
        errln!("{c}: not ranked: {}", s.untrusted.join("; "));
    }
    for (c, e) in results.iter().filter_map(|r| r.as_ref().err()) {
        errln!("{c}: failed: {e}");
    }
}

/// `rank --out OUT`: merge the shards; output and exit code as `viscoroll run`'s.
fn merge(out: &std::path::Path, xlsx: bool, json: bool) -> anyhow::Result<()> {
    let summary = crate::pipeline::shard::merge_shards(out, xlsx)?;
    let (n, failed, untrusted) = (
        summary.compounds.len(),
        summary.failures(),
        summary.untrusted(),
    );
    errln!(
        "{n} compounds merged from the shards ({failed} failed, {untrusted} not trusted); see {} and {}",
        summary.index_html.display(),
        summary.ranking_csv.display()
    );
    super::run::finish(&summary, json)
}
