//! `viscoroll run [DIR]`: the main job — every compound under DIR → fit file → friction in the
//! scenes → report folder; `reports/ranking.csv` and `reports/index.html` (crate::pipeline::run).
//!
//! Progress: a counted bar over the work units (per compound: fit, friction and maps per scene,
//! report) on a terminal, plain log lines otherwise (stderr). `--json` prints one object
//! (the [`crate::pipeline::RunSummary`]). Exit code 1 when any compound failed.

use crate::pipeline::{run_all, run_all_with_progress, ProgressEvent, RunOptions};
use anyhow::bail;
use std::io::IsTerminal;
use std::path::PathBuf;

/// Arguments of `viscoroll run`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Folder of compounds: `compounds.toml` if present, else one compound per sub-folder and per
    /// export file.
    #[arg(default_value = "data")]
    pub dir: PathBuf,
    /// Scenes TOML [default: DIR/scenes.toml if present, else the shipped scenes].
    #[arg(long)]
    pub scenes: Option<PathBuf>,
    /// Output folder (gets fits/ and reports/).
    #[arg(long, default_value = ".")]
    pub out: PathBuf,
    /// Replace fit files made from other inputs or settings.
    #[arg(long)]
    pub force: bool,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
}

/// Run `viscoroll run`.
pub fn run(args: Args) -> anyhow::Result<()> {
    if !args.dir.is_dir() {
        bail!("{} is not a folder", args.dir.display());
    }
    let opts = RunOptions::for_folder(&args.dir, &args.out, args.scenes.as_deref(), args.force)?;
    let start = std::time::Instant::now();
    let summary = if std::io::stderr().is_terminal() {
        // A counted bar over the work units (per compound: fit, friction and maps per scene,
        // report); log lines go above it.
        let bar = indicatif::ProgressBar::new(0);
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{elapsed_precise} [{bar:30}] {pos}/{len} {wide_msg}",
            )
            .map_err(|e| anyhow::anyhow!("progress bar template: {e}"))?
            .progress_chars("=> "),
        );
        bar.enable_steady_tick(std::time::Duration::from_millis(200));
        let (b, p) = (bar.clone(), bar.clone());
        let s = run_all_with_progress(
            &opts,
            &move |line: &str| b.println(line),
            &move |ev| match ev {
                ProgressEvent::Total(n) => p.set_length(n),
                ProgressEvent::Done { compound, stage } => {
                    p.inc(1);
                    p.set_message(format!("{compound}: {stage}"));
                }
            },
        );
        bar.finish_and_clear();
        s?
    } else {
        run_all(&opts, &|line: &str| eprintln!("{line}"))?
    };
    let secs = start.elapsed().as_secs_f64();
    let failed = summary.failures();
    eprintln!(
        "{} compounds ({} failed) in {secs:.2} s; see {} and {}",
        summary.compounds.len(),
        failed,
        summary.index_html.display(),
        summary.ranking_csv.display()
    );
    if args.json {
        println!("{}", serde_json::to_string(&summary)?);
    }
    if failed > 0 {
        bail!(
            "{failed} of {} compounds failed (listed in {})",
            summary.compounds.len(),
            summary.index_html.display()
        );
    }
    Ok(())
}
