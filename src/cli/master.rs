//! `viscoroll master`: master curve by time–temperature superposition, with WLF and Arrhenius fits.
//!
//! Input: a measurement JSON (the serde of [`crate::Measurement`], as `viscoroll ingest` writes
//! it), or pyvisco's master-curve CSV with its shift factors (`--master-curve`, `--shift-factors`:
//! read already shifted, [`crate::dma::pyvisco`]); output: a [`MasterCurve`] (printed with `--json`, written with `-o`), a summary on stderr.

use crate::tts::{build_master_curve, MasterCurve, MasterSettings};
use crate::ShiftLaw;
use anyhow::{bail, Context};
use std::io::Write;
use std::path::PathBuf;

/// Arguments of `viscoroll master`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Measurement JSON (serde of `Measurement`, as written by `viscoroll ingest`), or give
    /// --master-curve.
    #[arg(required_unless_present = "master_curve")]
    pub measurement: Option<PathBuf>,
    /// A master curve already shifted, in pyvisco's CSV layout (`f, E_stor, E_loss` over `Hz, MPa,
    /// MPa`), read with --shift-factors instead of shifting a measurement.
    #[arg(
        long,
        value_name = "CSV",
        conflicts_with = "measurement",
        requires = "shift_factors"
    )]
    pub master_curve: Option<PathBuf>,
    /// pyvisco's shift-factor CSV (`T, log_aT` over `C, -`) of --master-curve.
    #[arg(long, value_name = "CSV", requires = "master_curve")]
    pub shift_factors: Option<PathBuf>,
    /// Reference temperature in °C [default: the middle isotherm's temperature].
    #[arg(long, allow_hyphen_values = true, value_parser = super::temp_c)]
    pub tref: Option<f64>,
    /// The master-curve flags (the same in `fit` and `run`).
    #[command(flatten)]
    pub tts: super::tuning_args::TtsArgs,
    /// Print the master curve as one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    /// Write the master curve JSON to this file.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Overwrite the output file if it exists.
    #[arg(long)]
    pub force: bool,
}

/// Run `viscoroll master`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let settings = settings_from(&args)?;
    if let Some(out) = &args.output {
        if out.exists() && !args.force {
            bail!("{} exists; use --force to overwrite it", out.display());
        }
    }
    let master = match (&args.measurement, &args.master_curve, &args.shift_factors) {
        (Some(path), _, _) => {
            let text = crate::fsutil::read_regular_to_string(path, crate::limits::INPUT_BYTES_MAX)
                .with_context(|| format!("cannot read {}", path.display()))?;
            // Parsed and checked like any export (impossible temperatures refused, naming file and line).
            let measurement =
                crate::dma::plausible::measurement_from_json(&path.display().to_string(), &text)?;
            build_master_curve(&measurement, &settings)?
        }
        (None, Some(mc), Some(sf)) => {
            // Read already shifted: no shifting; the table of shift factors is the law.
            let pv = crate::dma::pyvisco::PyviscoMaster::read(mc, sf, 0.5, args.tref)?;
            crate::tts::master_curve_from_reduced(&pv.measurement, &pv.shift_law)
                .with_context(|| format!("{}", mc.display()))?
        }
        _ => bail!("give a measurement JSON, or --master-curve with --shift-factors"),
    };
    let json = serde_json::to_string_pretty(&master)?;
    if let Some(out) = &args.output {
        // --force was checked before the work started.
        super::output::write_atomic(out, json.as_bytes(), true)?;
        errln!("wrote {}", out.display());
    }
    summary(&master);
    if args.json {
        let value: serde_json::Value = serde_json::from_str(&json)?;
        let mut stdout = std::io::stdout().lock();
        writeln!(stdout, "{}", super::output::versioned(value))?;
    }
    Ok(())
}

fn settings_from(args: &Args) -> anyhow::Result<MasterSettings> {
    let mut options = crate::pipeline::FitOptions {
        master: MasterSettings {
            tref_c: args.tref,
            ..MasterSettings::default()
        },
        ..Default::default()
    };
    args.tts.tuning(args.tref, None)?.apply(&mut options);
    Ok(options.master)
}

fn summary(m: &MasterCurve) {
    errln!(
        "master curve: {} isotherms, {} points, T_ref = {} °C",
        m.isotherms.len(),
        m.points.len(),
        m.t_ref_c
    );
    errln!(
        "  T (°C)   log10 aT   ±std     log10 bT  overlap RMS  {} alone  vGP (°)  KK log10",
        m.kind.symbols().1
    );
    for s in &m.isotherms {
        let opt = |v: Option<f64>, p: usize| v.map_or("-".to_string(), |v| format!("{v:.p$}"));
        errln!(
            "  {:>7.2}  {:>8.3}  {:>7.4}  {:>8.4}  {:>11}  {:>8}  {:>7}  {:>8}{}",
            s.temp_c,
            s.log10_a_t,
            s.log10_a_t_std,
            s.log10_b_t,
            opt(s.overlap_rms_log10, 4),
            opt(s.loss_overlap_rms_log10, 4),
            opt(s.vgp_rms_deg, 2),
            opt(s.kk_median_log10_ratio, 2),
            if s.flags.is_empty() { "" } else { "  !" }
        );
        if let Some(c) = &s.shift_channel {
            errln!("           shift carried by {c}");
        }
    }
    if let Some(w) = &m.wlf {
        errln!(
            "WLF:       C1 = {:.4}, C2 = {:.3} K at {} °C, RMS {:.4}",
            w.c1,
            w.c2_k,
            w.t_ref_c,
            w.rms_log10
        );
    }
    if let Some(a) = &m.arrhenius {
        errln!(
            "Arrhenius: Ea = {:.1} kJ/mol at {} °C, RMS {:.4}",
            a.activation_energy_j_per_mol / 1e3,
            a.t_ref_c,
            a.rms_log10
        );
    }
    let law = match &m.shift_law {
        ShiftLaw::Wlf { .. } => "WLF",
        ShiftLaw::Arrhenius { .. } => "Arrhenius",
        ShiftLaw::Table { .. } => "table",
    };
    errln!("shift law used: {law}");
    for w in &m.warnings {
        errln!("warning: {w}");
    }
    for f in &m.quality.flags {
        errln!("flag: {f}");
    }
}
