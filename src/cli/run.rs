//! `viscoroll run [DIR]`: the main job — every compound under DIR → fit file → friction in the
//! scenes → report folder; `reports/ranking.csv` and `reports/index.html` (crate::pipeline::run).
//!
//! Progress: a counted bar over the work units (per compound: fit, friction and maps per scene,
//! report) on a terminal, plain log lines otherwise (stderr). `--json` prints one object: the
//! [`crate::pipeline::RunSummary`] on success, else the error object with the summary as `detail`.
//! Exit codes: 0 all trusted, 1 a compound failed (or none found), 3 finished with untrusted results.
//!
//! `--shard K/N` (K from 0) runs every N-th compound in discovery order, for array jobs; the shards
//! share `--out`, and `viscoroll rank --out OUT` merges them into the ranking and index
//! (crate::pipeline::shard).

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
    #[arg(long, value_name = "C", allow_negative_numbers = true, value_parser = super::temp_c)]
    pub tref: Option<f64>,
    /// Rank on every temperature that computed, extrapolated ones included (marked) [default:
    /// measured temperatures only].
    #[arg(long)]
    pub allow_extrapolation: bool,
    /// Relative tolerance of the contact solves and friction maps for every scene without its own
    /// `tol` (1e-10 … 1e-2) [default: 1e-6 on a half-space, 1e-3 on a cover]. friction.csv gives
    /// each point's error estimate.
    #[arg(long, value_name = "TOL")]
    pub tol: Option<f64>,
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
    /// Longest wait in seconds for another run that holds the output folder's lock (it is told at
    /// once who holds it, and since when); 0 fails at once.
    #[arg(long, value_name = "SECONDS", default_value_t = crate::pipeline::run::LOCK_WAIT.as_secs())]
    pub wait: u64,
    /// Run only shard K of N (K from 0): the compounds numbered K, K+N, K+2N, … in discovery order
    /// (compounds.toml's order, else sorted names). Shards share --out; when all are done,
    /// `viscoroll rank --out OUT` writes the ranking and index.
    #[arg(long, value_name = "K/N")]
    pub shard: Option<crate::pipeline::shard::Shard>,
    /// Do not write the run's workbook reports/viscoroll.xlsx (the ranking and every compound's
    /// tables, master curve, shifts and Prony terms, a sheet each).
    #[arg(long)]
    pub no_xlsx: bool,
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
    if let Some(t) = args.tol {
        opts.set_tol(t)?;
    }
    opts.allow_extrapolation = args.allow_extrapolation;
    opts.xlsx = !args.no_xlsx;
    opts.lock_wait = std::time::Duration::from_secs(args.wait);
    if args.no_bands {
        opts.bands = None;
    }
    opts.shard = args.shard;
    let start = std::time::Instant::now();
    let summary = if std::io::stderr().is_terminal() {
        run_with_bar(&opts)?
    } else {
        run_all(&opts, &|line: &str| errln!("{line}"))?
    };
    let (n, failed, untrusted) = (
        summary.compounds.len(),
        summary.failures(),
        summary.untrusted(),
    );
    match args.shard {
        None => errln!(
            "{} ({failed} failed, {untrusted} not trusted) in {:.2} s; see {} and {}",
            crate::results::counted(n, "compound"),
            start.elapsed().as_secs_f64(),
            summary.index_html.display(),
            summary.ranking_csv.display()
        ),
        Some(s) => errln!(
            "shard {s}: {} ({failed} failed, {untrusted} not trusted) in {:.2} s; when every shard is done, `viscoroll rank --out {}` writes {} and {}",
            crate::results::counted(n, "compound"),
            start.elapsed().as_secs_f64(),
            args.out.display(),
            summary.index_html.display(),
            summary.ranking_csv.display()
        ),
    }
    finish(&summary, args.json)
}

/// The main job's answer for a finished run (or merged shards, `rank --out`): the summary on stdout
/// with `--json` and exit 0 when all is good; else the exit code of the table in `--help` (1 a
/// compound failed, 3 some results not trusted) with the summary as the error's detail.
pub(super) fn finish(summary: &crate::pipeline::RunSummary, json: bool) -> anyhow::Result<()> {
    let (n, failed, untrusted) = (
        summary.compounds.len(),
        summary.failures(),
        summary.untrusted(),
    );
    let (code, kind, message) = match summary.status() {
        RunStatus::AllGood => {
            if json {
                outln!("{}", super::output::versioned(serde_json::to_value(summary)?));
            }
            return Ok(());
        }
        RunStatus::Failures => (
            1,
            "compounds_failed",
            format!(
                "{failed} of {} failed (listed in {})",
                crate::results::counted(n, "compound"),
                summary.index_html.display()
            ),
        ),
        RunStatus::Untrusted => (
            3,
            "untrusted_results",
            format!(
                "finished, but {untrusted} of {} {} results that are not trusted (listed apart, with reasons, in {})",
                crate::results::counted(n, "compound"),
                if untrusted == 1 { "has" } else { "have" },
                summary.index_html.display()
            ),
        ),
    };
    Err(Exit {
        code,
        kind,
        message,
        detail: Some(serde_json::to_value(summary)?),
    }
    .into())
}
