//! `viscoroll rank FIT.json… [--scene NAME]`: compounds ordered by predicted rolling friction in a
//! scene — the temperature-averaged F/N and a table per temperature.
//!
//! `--json` prints one object: `scene`, `ranking` [{`rank`, `compound`, `mean_friction`,
//! `friction`: [{`temp_c`, `friction`, `extrapolated`, …}]}], `failed` [{`compound`, `error`}].

use crate::pipeline::{CompoundFit, SceneSet};
use anyhow::{bail, Context};
use std::path::PathBuf;

/// Arguments of `viscoroll rank`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Fit files (fits/NAME.json).
    #[arg(required = true)]
    pub fits: Vec<PathBuf>,
    /// Scene name [default: the first scene].
    #[arg(long)]
    pub scene: Option<String>,
    /// Scenes TOML [default: the shipped scenes].
    #[arg(long)]
    pub scenes: Option<PathBuf>,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
}

/// Run `viscoroll rank`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let set = match &args.scenes {
        Some(p) => SceneSet::read(p)?,
        None => SceneSet::shipped(),
    };
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
    let results = crate::pipeline::run::rank_fits(&fits, &spec);
    let mut ranking = Vec::new();
    let mut failed = Vec::new();
    for r in &results {
        match r {
            Ok((c, pts, m)) => ranking.push(serde_json::json!({
                "rank": ranking.len() + 1, "compound": c, "mean_friction": m, "friction": pts,
            })),
            Err((c, e)) => failed.push(serde_json::json!({"compound": c, "error": e})),
        }
    }
    if args.json {
        println!(
            "{}",
            serde_json::json!({"scene": spec, "ranking": ranking, "failed": failed})
        );
    } else {
        eprintln!(
            "scene {}: R = {} mm, {} N/m, {} m/s; lowest rolling friction first",
            spec.name, spec.roll_radius_mm, spec.load_n_per_m, spec.speed_m_s
        );
        let oks: Vec<_> = results.iter().filter_map(|r| r.as_ref().ok()).collect();
        let mut head = format!("{:>4} {:<24} {:>11}", "rank", "compound", "mean F/N");
        for t in &spec.temps_c {
            head.push_str(&format!(" {:>10}", format!("{t} °C")));
        }
        eprintln!("{head}");
        for (i, (c, pts, m)) in oks.iter().enumerate() {
            let mut line = format!("{:>4} {:<24} {:>11.4e}", i + 1, c, m);
            for p in pts {
                line.push_str(&format!(
                    " {:>9.3e}{}",
                    p.friction,
                    if p.extrapolated { "*" } else { " " }
                ));
            }
            eprintln!("{line}");
        }
        if oks.iter().any(|(_, p, _)| p.iter().any(|p| p.extrapolated)) {
            eprintln!("* shift law extrapolated beyond the measured temperatures");
        }
        for (c, e) in results.iter().filter_map(|r| r.as_ref().err()) {
            eprintln!("{c}: failed: {e}");
        }
    }
    if !failed.is_empty() {
        bail!("{} of {} compounds failed", failed.len(), results.len());
    }
    Ok(())
}
