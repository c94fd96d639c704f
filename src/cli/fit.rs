//! `viscoroll fit`: master curve + Prony fit + exact creep spectrum → a fit file (`CompoundFit`).
//!
//! Input: a measurement JSON (the serde of [`crate::Measurement`], as `viscoroll ingest -o` writes it);
//! output: `fits/NAME.json`, the file `roll`, `rank` and `export` read. The same settings as the main
//! job (`viscoroll run`): slope-weighted shifts, the table of the shifts found as the shift law, the
//! Prony QP with its GCV weight (`crate::pipeline::fit_compound`); the master-curve and Prony flags
//! are `master`'s and `run`'s (crate::cli::tuning_args). An existing fit made from the same inputs
//! with the same settings is reused; a different one is kept unless `--force` is given.
//!
//! The fit file carries the bootstrap ensemble of the uncertainty bands (crate::bands, docs/MATH.md
//! §15) by default, so that `roll` and `run` give bands from it; `--no-bands` skips it (a fit
//! reused without one gets it added, the fit itself unchanged). A master curve read already shifted
//! has no isotherms to resample: its ensemble is made from its points alone
//! (crate::bands::ensemble_from_fit, whose note says what that leaves out).
//!
//! Instead of a measurement, a master curve already shifted can be fitted: pyvisco's master-curve CSV
//! with its shift-factor CSV (`--master-curve M.csv --shift-factors S.csv`, read by
//! [`crate::dma::pyvisco`]); its shift table is the fit's shift law, and the WLF and Arrhenius fits
//! of that table go into the fit file for the cards. Without the shift-factor CSV, `--tref T` says
//! where the curve was shifted to, and the law is that one temperature's.
//!
//! Or relaxation or creep isotherms (`--time-domain FILE…`, docs/MATH.md §18): shifted in log t,
//! fitted in time (crate::pipeline::fit_time); the fit file is the same, so `roll` and `run` go on
//! from it. Such a fit is always made anew (`--force` to replace an existing file).

use crate::bands::BandSettings;
use crate::pipeline::fit_compound::{
    fit_or_reuse_master, fit_or_reuse_with_bands, FitAction, FitOptions,
};
use anyhow::Context;
use std::path::PathBuf;

/// Arguments of `viscoroll fit`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Measurement JSON written by `viscoroll ingest -o M.json` (or give --master-curve).
    #[arg(required_unless_present_any = ["master_curve", "time_domain"])]
    pub measurement: Option<PathBuf>,
    /// Relaxation E(t)/G(t) or creep D(t)/J(t) isotherms, fitted in time instead of a measurement
    /// (docs/MATH.md §18): a CSV with temperature, time and modulus or compliance columns whose
    /// headers carry their units (`T [°C], time [s], E(t) [MPa]`), or a TRIOS text export with
    /// stress-relaxation or creep steps.
    #[arg(long, value_name = "FILE", num_args = 1.., conflicts_with_all = ["measurement", "master_curve"])]
    pub time_domain: Vec<PathBuf>,
    /// A master curve already shifted, in pyvisco's CSV layout, fitted instead of a measurement:
    /// frequency domain (`f, E_stor, E_loss` over `Hz, MPa, MPa`; `G_…` for shear) or time domain
    /// (`t, E_relax` over `s, MPa`; fitted in time, docs/MATH.md §18). Without --shift-factors
    /// give --tref, the temperature it was shifted to: friction is then known at T_ref only.
    #[arg(long, value_name = "CSV", conflicts_with = "measurement")]
    pub master_curve: Option<PathBuf>,
    /// pyvisco's shift-factor CSV of the master curve (`T, log_aT` over `C, -`); its row with
    /// log_aT = 0 is the reference temperature (else give --tref).
    #[arg(long, value_name = "CSV", requires = "master_curve")]
    pub shift_factors: Option<PathBuf>,
    /// Poisson's ratio of the material (with --master-curve or --time-domain), for tensile ↔ shear.
    #[arg(long, default_value_t = 0.5)]
    pub poisson: f64,
    /// Fit file to write, e.g. `fits/NAME.json` (written atomically).
    #[arg(short = 'o', long = "output")]
    pub output: PathBuf,
    /// Compound name stored in the fit (default: the output file's stem).
    #[arg(long)]
    pub name: Option<String>,
    /// Reference temperature of the master curve in °C (default: a measured temperature near the
    /// middle of the range).
    #[arg(long, allow_negative_numbers = true, value_parser = super::temp_c)]
    pub tref: Option<f64>,
    /// The master-curve flags (the same as `master`'s).
    #[command(flatten)]
    pub tts: super::tuning_args::TtsArgs,
    /// The Prony flags (the same in `run`).
    #[command(flatten)]
    pub prony: super::tuning_args::PronyArgs,
    /// Print the trade table of terms against RMS log10 E′ and E″ on stderr.
    #[arg(long)]
    pub trade: bool,
    /// Replace an existing, different fit file.
    #[arg(long)]
    pub force: bool,
    /// Skip the bootstrap ensemble of the uncertainty bands (32 refits; `roll` then makes one from
    /// the fit file alone, without the shifts' scatter).
    #[arg(long)]
    pub no_bands: bool,
    /// Print one JSON object (a summary of the fit) on stdout.
    #[arg(long)]
    pub json: bool,
}

/// Run `viscoroll fit`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let source = source(&args)?;
    let input = args
        .measurement
        .as_ref()
        .or(args.master_curve.as_ref())
        .or(args.time_domain.first())
        .map(|p| p.display().to_string())
        .unwrap_or_default();
    let name = match &args.name {
        Some(n) => n.clone(),
        None => args
            .output
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "compound".to_string()),
    };
    let mut options = fit_options(&args)?;
    if let Some(dir) = args.output.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("{}: cannot create the folder", dir.display()))?;
    }
    let bands = (!args.no_bands).then(BandSettings::default);
    let (fit, action, no_bands) = match &source {
        Source::Measurement(measurement) => fit_or_reuse_with_bands(
            &name,
            measurement,
            &args.output,
            &options,
            args.force,
            bands.as_ref(),
        )
        .with_context(|| input.clone())?,
        Source::Master(measurement, master) => {
            options.master = master.settings.clone();
            let (mut fit, action) = fit_or_reuse_master(
                &name,
                measurement,
                master,
                &args.output,
                &options,
                args.force,
            )
            .with_context(|| input.clone())?;
            let why = match bands.as_ref().filter(|_| fit.bands.is_none()) {
                None => None,
                Some(s) => match crate::bands::ensemble_from_fit(&fit, s) {
                    Ok(e) => {
                        fit.bands = Some(e);
                        fit.write(&args.output, true)
                            .with_context(|| args.output.display().to_string())?;
                        None
                    }
                    Err(e) => Some(e.not_computed_warning()),
                },
            };
            (fit, action, why)
        }
        Source::Time(data) => time_fit_written(
            &args,
            crate::pipeline::fit_time::fit_time_data(&name, data, &options)
                .with_context(|| input.clone())?,
            bands.as_ref(),
        )?,
        Source::TimeMaster(pv) => time_fit_written(
            &args,
            crate::pipeline::fit_time::fit_pyvisco_time_master(&name, pv, &options)
                .with_context(|| input.clone())?,
            bands.as_ref(),
        )?,
    };
    print_fit(&args, &fit, action, no_bands.as_deref());
    Ok(())
}

/// A fit made in time: its bands tried (they resample frequency sweeps, so they say why not), the
/// file written (anew; `--force` replaces it).
fn time_fit_written(
    args: &Args,
    mut fit: crate::pipeline::CompoundFit,
    bands: Option<&BandSettings>,
) -> anyhow::Result<(crate::pipeline::CompoundFit, FitAction, Option<String>)> {
    let why = bands.and_then(|s| match crate::bands::ensemble_from_fit(&fit, s) {
        Ok(e) => {
            fit.bands = Some(e);
            None
        }
        Err(e) => Some(e.not_computed_warning()),
    });
    fit.write(&args.output, args.force)
        .with_context(|| args.output.display().to_string())?;
    let action = if args.force {
        FitAction::Replaced
    } else {
        FitAction::Fitted
    };
    Ok((fit, action, why))
}

/// The input: a measurement JSON, or pyvisco's master curve and shift factors (the master curve
/// built from them by the library).
fn source(args: &Args) -> anyhow::Result<Source> {
    Ok(
        match (&args.measurement, &args.master_curve, &args.shift_factors) {
            (Some(m), _, _) => Source::Measurement(read_measurement(m)?),
            (None, None, _) if !args.time_domain.is_empty() => Source::Time(
                crate::dma::time_domain::read_time_files(&args.time_domain, args.poisson)?,
            ),
            (None, Some(mc), sf) if is_time_master(mc) => {
                Source::TimeMaster(Box::new(crate::dma::pyvisco_time::read_time_master(
                    mc,
                    sf.as_deref(),
                    args.poisson,
                    args.tref,
                )?))
            }
            (None, Some(mc), sf) => {
                let pv = match sf {
                    Some(sf) => {
                        crate::dma::pyvisco::PyviscoMaster::read(mc, sf, args.poisson, args.tref)?
                    }
                    None => crate::dma::pyvisco::read_master_alone(mc, args.poisson, args.tref)?,
                };
                let master = crate::tts::master_curve_from_reduced(&pv.measurement, &pv.shift_law)
                    .with_context(|| format!("{}", mc.display()))?;
                Source::Master(pv.measurement, Box::new(master))
            }
            _ => anyhow::bail!("give a measurement JSON, or --master-curve with --shift-factors"),
        },
    )
}

/// Whether a file is pyvisco's time-domain master curve (its header; an unreadable file is not,
/// and the frequency reader then says why).
fn is_time_master(path: &std::path::Path) -> bool {
    crate::fsutil::read_regular(path, crate::limits::INPUT_BYTES_MAX)
        .is_ok_and(|b| crate::dma::pyvisco_time::is_time_master(&b))
}

/// The fit options from the flags: the main job's defaults with the flags given laid over them.
fn fit_options(args: &Args) -> anyhow::Result<FitOptions> {
    let mut options = FitOptions::default();
    options.master.tref_c = args.tref;
    args.tts
        .tuning(args.tref, Some(&args.prony))?
        .apply(&mut options);
    Ok(options)
}

/// Print the fit: one JSON object (`--json`) or a line on stderr, the trade table (`--trade`), a
/// warning when the term target is missed and one when the bands could not be made (`no_bands`).
fn print_fit(
    args: &Args,
    fit: &crate::pipeline::CompoundFit,
    action: FitAction,
    no_bands: Option<&str>,
) {
    let action = action.word();
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
            "dense_terms": info.dense_terms,
            "dense_rms_log10": info.dense_rms_log10,
            "term_target_rms_log10": info.term_target_rms_log10,
            "term_target_met": info.term_target_met,
            "term_trade": info.term_trade,
            "quality": fit.quality,
            "bands_replicates": fit.bands.as_ref().map(|b| b.replicates.len()),
            "bands_note": bands_note(args, fit, no_bands),
            "bands_notes": fit.bands.as_ref().map_or(&[][..], |b| &b.notes[..]),
        });
        outln!("{}", super::output::versioned(obj));
    } else {
        let (storage, loss, _) = fit.relaxation.kind.symbols();
        errln!(
            "{}: {action} {} (T_ref {:.2} °C; {} relaxation terms, RMS log10 {storage} {:.4}, {loss} {:.4}; {} creep terms)",
            fit.compound,
            args.output.display(),
            fit.shift_law.t_ref_c(),
            fit.relaxation.terms.len(),
            info.rms_log10_storage,
            info.rms_log10_loss,
            creep_terms,
        );
    }
    if args.trade && !args.json {
        let (storage, loss, _) = fit.relaxation.kind.symbols();
        errln!(
            "terms  RMS log10 {storage}  RMS log10 {loss}  max |log10 {storage}|  max |log10 {loss}|"
        );
        for t in &info.term_trade {
            errln!(
                "{:5}  {:12.4}  {:12.4}  {:14.3}  {:14.3}{}",
                t.n_terms,
                t.rms_log10_storage,
                t.rms_log10_loss,
                t.max_abs_log10_storage,
                t.max_abs_log10_loss,
                if t.n_terms == fit.relaxation.terms.len() {
                    "  ← kept"
                } else {
                    ""
                }
            );
        }
    }
    if let (Some(why), false) = (no_bands, args.json) {
        errln!("{}: WARNING: {why}", fit.compound);
    }
    if info.term_target_met == Some(false) {
        let t = info.term_target_rms_log10.unwrap_or_default();
        let (storage, loss, _) = fit.relaxation.kind.symbols();
        errln!(
            "{}: WARNING: the term target (RMS log10 {storage} {:.4}, {loss} {:.4}) is not met within {}; kept {} terms",
            fit.compound,
            t[0],
            t[1],
            args.prony.max_terms.map_or("the dense fit".to_string(), |n| format!("{n} terms")),
            fit.relaxation.terms.len()
        );
    }
}

/// Why the fit file carries no ensemble (null when it carries one).
fn bands_note(
    args: &Args,
    fit: &crate::pipeline::CompoundFit,
    no_bands: Option<&str>,
) -> Option<String> {
    match (&fit.bands, no_bands) {
        (Some(_), _) => None,
        (None, Some(why)) => Some(why.to_string()),
        (None, None) if args.no_bands => Some("skipped (--no-bands)".to_string()),
        (None, None) => Some("not computed".to_string()),
    }
}

/// What is fitted: a measurement (master curve built here) or a master curve read already shifted.
enum Source {
    Measurement(crate::Measurement),
    Master(crate::Measurement, Box<crate::tts::MasterCurve>),
    Time(crate::dma::time_domain::TimeData),
    /// pyvisco's time-domain master curve (`t, E_relax`), fitted in time.
    TimeMaster(Box<crate::dma::pyvisco_time::PyviscoTimeMaster>),
}

/// A measurement JSON: the bare serde of Measurement, or an object holding it under "measurement".
fn read_measurement(path: &std::path::Path) -> anyhow::Result<crate::Measurement> {
    let text = crate::fsutil::read_regular_to_string(path, crate::limits::INPUT_BYTES_MAX)
        .with_context(|| format!("{}: cannot read", path.display()))?;
    // The bare serde of Measurement, or an object holding it under "measurement"; checked like any
    // export (crate::dma::plausible).
    Ok(crate::dma::plausible::measurement_from_json(
        &path.display().to_string(),
        &text,
    )?)
}
