//! `viscoroll fit`: master curve + Prony fit + exact creep spectrum → a fit file (`CompoundFit`).
//!
//! Input: a measurement JSON (the serde of [`crate::Measurement`], as `viscoroll ingest -o` writes it);
//! output: `fits/NAME.json`, the file `roll`, `rank` and `export` read. The same settings as the main
//! job (`viscoroll run`): shifts on log E′, the table of the shifts found as the shift law, the Prony
//! QP with its GCV weight (`crate::pipeline::fit_compound`). An existing fit made from the same inputs
//! with the same settings is reused; a different one is kept unless `--force` is given.

use crate::pipeline::fit_compound::{fit_or_reuse, FitAction, FitOptions};
use anyhow::Context;
use std::path::PathBuf;

/// Arguments of `viscoroll fit`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Measurement JSON written by `viscoroll ingest -o M.json`.
    pub measurement: PathBuf,
    /// Fit file to write, e.g. `fits/NAME.json` (written atomically).
    #[arg(short = 'o', long = "output")]
    pub output: PathBuf,
    /// Compound name stored in the fit (default: the output file's stem).
    #[arg(long)]
    pub name: Option<String>,
    /// Reference temperature of the master curve in °C (default: a measured temperature near the
    /// middle of the range).
    #[arg(long, allow_negative_numbers = true)]
    pub tref: Option<f64>,
    /// Replace an existing, different fit file.
    #[arg(long)]
    pub force: bool,
    /// Print one JSON object (a summary of the fit) on stdout.
    #[arg(long)]
    pub json: bool,
}

/// Run `viscoroll fit`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let text = std::fs::read_to_string(&args.measurement)
        .with_context(|| format!("{}: cannot read", args.measurement.display()))?;
    let value: serde_json::Value = serde_json::from_str(&text)
        .with_context(|| format!("{}: not JSON", args.measurement.display()))?;
    // The bare serde of Measurement, or an object holding it under "measurement".
    let inner = value.get("measurement").cloned().unwrap_or(value);
    let measurement: crate::Measurement = serde_json::from_value(inner)
        .with_context(|| format!("{}: not a measurement", args.measurement.display()))?;
    let name = match &args.name {
        Some(n) => n.clone(),
        None => args
            .output
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "compound".to_string()),
    };
    let mut options = FitOptions::default();
    options.master.tref_c = args.tref;
    if let Some(dir) = args.output.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("{}: cannot create the folder", dir.display()))?;
    }
    let (fit, action) = fit_or_reuse(&name, &measurement, &args.output, &options, args.force)
        .with_context(|| format!("{}", args.measurement.display()))?;
    let action = match action {
        FitAction::Reused => "reused",
        FitAction::Fitted => "fitted",
        FitAction::Replaced => "replaced",
    };
    let info = &fit.prony_info;
    let creep_terms = fit.creep.as_ref().map_or(0, |c| c.terms.len());
    if args.json {
        let obj = serde_json::json!({
            "compound": fit.compound,
            "output": args.output.display().to_string(),
            "action": action,
            "t_ref_c": fit.shift_law.t_ref_c(),
            "shift_law": fit.shift_law,
            "relaxation_terms": fit.relaxation.terms.len(),
            "creep_terms": creep_terms,
            "rms_log10_storage": info.rms_log10_storage,
            "rms_log10_loss": info.rms_log10_loss,
            "quality": fit.quality,
        });
        println!("{obj}");
    } else {
        eprintln!(
            "{}: {action} {} (T_ref {:.2} °C; {} relaxation terms, RMS log10 E′ {:.4}, E″ {:.4}; {} creep terms)",
            fit.compound,
            args.output.display(),
            fit.shift_law.t_ref_c(),
            fit.relaxation.terms.len(),
            info.rms_log10_storage,
            info.rms_log10_loss,
            creep_terms,
        );
    }
    Ok(())
}
