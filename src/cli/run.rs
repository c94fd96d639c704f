//! `viscoroll run [DIR]`: the main job — every compound under DIR → fit file → friction in the
//! scenes → report folder; `reports/ranking.csv` and `reports/index.html` (crate::pipeline::run).
//!
//! Progress: a counted bar over the work units (per compound: fit, friction and maps per scene,
//! report) on a terminal, plain log lines otherwise (stderr). `--json` prints one object: the
//! [`crate::pipeline::RunSummary`] on success, else the error object with the summary as `detail`.
//! Exit codes: 0 all trusted, 1 a compound failed (or none found), 3 finished with untrusted results.

use super::Exit;
use crate::pipeline::{run_all, run_all_with_progress, ProgressEvent, RunOptions, RunStatus};
use std::io::IsTerminal;
use std::path::PathBuf;

/// Arguments of `viscoroll run`.
#[derive(Debug, clap::Args)]
#[command(after_help = super::EXIT_CODES)]
pub struct Args {
    /// Folder of compounds: `compounds.toml` if present, else one compound per sub-folder and per
    /// export file (or measurement JSON written by `viscoroll ingest`).
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
    /// Reference temperature of the master curves in °C [default: the middle isotherm's]; a
    /// compound's `tref_c` in compounds.toml wins.
    #[arg(long, value_name = "C", allow_negative_numbers = true)]
    pub tref: Option<f64>,
    /// Rank on every temperature that computed, extrapolated ones included (marked) [default:
    /// measured temperatures only].
    #[arg(long)]
    pub allow_extrapolation: bool,
    /// Skip the uncertainty bands (p05/p50/p95 of every friction, ties in the ranking): about
    /// 1–2 s less per compound.
    #[arg(long)]
    pub no_bands: bool,
    /// The master-curve flags (the same as `master`'s; a compound's keys in compounds.toml win).
    #[command(flatten)]
    pub tts: super::tuning_args::TtsArgs,
    /// The Prony flags (the same as `fit`'s).
    #[command(flatten)]
    pub prony: super::tuning_args::PronyArgs,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
}

/// Run with a counted progress bar on stderr (log lines go above it).
fn run_with_bar(opts: &RunOptions) -> anyhow::Result<crate::pipeline::RunSummary> {
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
        opts,
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
    Ok(s?)
}

/// Run `viscoroll run`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let mut opts = RunOptions::for_folder(&args.dir, &args.out, args.scenes.as_deref(), args.tref)?;
    args.tts
        .tuning(args.tref, Some(&args.prony))?
        .apply(&mut opts.fit);
    opts.force = args.force;
    opts.allow_extrapolation = args.allow_extrapolation;
    if args.no_bands {
        opts.bands = None;
    }
    let start = std::time::Instant::now();
    let summary = if std::io::stderr().is_terminal() {
        run_with_bar(&opts)?
    } else {
        run_all(&opts, &|line: &str| eprintln!("{line}"))?
    };
    let (n, failed, untrusted) = (
        summary.compounds.len(),
        summary.failures(),
        summary.untrusted(),
    );
    eprintln!(
        "{n} compounds ({failed} failed, {untrusted} not trusted) in {:.2} s; see {} and {}",
        start.elapsed().as_secs_f64(),
        summary.index_html.display(),
        summary.ranking_csv.display()
    );
    let (code, kind, message) = match summary.status() {
        RunStatus::AllGood => {
            if args.json {
                println!("{}", serde_json::to_string(&summary)?);
            }
            return Ok(());
        }
        RunStatus::Failures => (
            1,
            "compounds_failed",
            format!(
                "{failed} of {n} compounds failed (listed in {})",
                summary.index_html.display()
            ),
        ),
        RunStatus::Untrusted => (
            3,
            "untrusted_results",
            format!(
                "finished, but {untrusted} of {n} compounds have results that are not trusted (listed apart, with reasons, in {})",
                summary.index_html.display()
            ),
        ),
    };
    Err(Exit {
        code,
        kind,
        message,
        detail: Some(serde_json::to_value(&summary)?),
    }
    .into())
}
