//! `viscoroll master`: master curve by time–temperature superposition, with WLF and Arrhenius fits.
//!
//! Input: a measurement JSON (the serde of [`crate::Measurement`], as `viscoroll ingest` writes
//! it), or pyvisco's master-curve CSV with its shift factors (`--master-curve`, `--shift-factors`:
//! read already shifted, [`crate::dma::pyvisco`]); output: a [`MasterCurve`] (printed with `--json`, written with `-o`), a summary on stderr.

use crate::tts::{
    build_master_curve, LawChoice, MasterCurve, MasterSettings, ShiftCriterion, ShiftSource,
    TemperatureBasis, VerticalShift,
};
use crate::ShiftLaw;
use anyhow::{bail, Context};
use std::io::Write;
use std::path::{Path, PathBuf};

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
    #[arg(long, allow_hyphen_values = true)]
    pub tref: Option<f64>,
    /// Horizontal shifts: `auto`, `wlf:C1,C2` (C2 in K, at --tref), `arrhenius:EA` (J/mol, at
    /// --tref), or a file: a JSON shift law, or a table with a name row (`T_C,log10_aT`, or `T,log_aT`
    /// over a unit row `C,-`; comma, semicolon, tab or white space), referred to the row with
    /// log10 aT = 0, else to --tref.
    #[arg(long, default_value = "auto")]
    pub shift: String,
    /// Vertical shift b_T: `fitted` (from the residual offset; horizontal then from tan δ) or
    /// `temperature` (T/T_ref) [default when given without a value: fitted; off when absent].
    #[arg(long, value_enum, num_args = 0..=1, default_missing_value = "fitted")]
    pub vertical: Option<VerticalArg>,
    /// What the automatic shifting compares.
    #[arg(long, value_enum, default_value = "storage")]
    pub criterion: CriterionArg,
    /// Law used as the master curve's shift law.
    #[arg(long, value_enum, default_value = "auto")]
    pub law: LawArg,
    /// Fit WLF and Arrhenius only to isotherms in this range of temperatures, `TMIN:TMAX` in °C
    /// (e.g. above T_g) [default: all].
    #[arg(long, allow_hyphen_values = true)]
    pub fit_range: Option<String>,
    /// Use the nominal (set) temperatures instead of the mean measured ones.
    #[arg(long)]
    pub nominal: bool,
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

/// `--vertical` values.
#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub enum VerticalArg {
    /// From the residual offset of log E′.
    Fitted,
    /// T/T_ref (kelvin).
    Temperature,
}

/// `--criterion` values.
#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub enum CriterionArg {
    /// log E′ and log E″ jointly (each weighted by its own scatter).
    Joint,
    /// log tan δ.
    TanDelta,
    /// log E′ only.
    Storage,
    /// log E′ and log E″, each weighted per isotherm by its local slope against its scatter (E″
    /// carries the shift where E′ is flat).
    SlopeWeighted,
}

/// `--law` values.
#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub enum LawArg {
    /// The better of WLF and Arrhenius by RMS.
    Auto,
    /// WLF.
    Wlf,
    /// Arrhenius.
    Arrhenius,
    /// The table of measured shifts.
    Table,
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
            let text = std::fs::read_to_string(path)
                .with_context(|| format!("cannot read {}", path.display()))?;
            // Parsed and checked like any export (impossible temperatures refused, naming file and line).
            let measurement =
                crate::dma::plausible::measurement_from_json(&path.display().to_string(), &text)?;
            build_master_curve(&measurement, &settings)?
        }
        (None, Some(mc), Some(sf)) => {
            // Read already shifted: no shifting; the table of shift factors is the law.
            let pv = crate::dma::pyvisco::read_master_pair(mc, sf, 0.5, args.tref)?;
            crate::tts::master_curve_from_reduced(&pv.measurement, &pv.shift_law)
                .with_context(|| format!("{}", mc.display()))?
        }
        _ => bail!("give a measurement JSON, or --master-curve with --shift-factors"),
    };
    let json = serde_json::to_string_pretty(&master)?;
    if let Some(out) = &args.output {
        // --force was checked before the work started.
        super::output::write_atomic(out, json.as_bytes(), true)?;
        eprintln!("wrote {}", out.display());
    }
    summary(&master);
    if args.json {
        let mut stdout = std::io::stdout().lock();
        writeln!(stdout, "{json}")?;
    }
    Ok(())
}

fn settings_from(args: &Args) -> anyhow::Result<MasterSettings> {
    let shift = parse_shift(&args.shift, args.tref)?;
    let law_fit_range_c = match &args.fit_range {
        None => None,
        Some(r) => {
            let (a, b) = r
                .split_once(':')
                .ok_or_else(|| anyhow::anyhow!("--fit-range expects TMIN:TMAX in °C, got {r:?}"))?;
            let parse = |v: &str| -> anyhow::Result<f64> {
                v.trim()
                    .parse::<f64>()
                    .ok()
                    .filter(|x| x.is_finite())
                    .ok_or_else(|| anyhow::anyhow!("--fit-range: {v:?} is not a temperature in °C"))
            };
            Some((parse(a)?, parse(b)?))
        }
    };
    Ok(MasterSettings {
        tref_c: args.tref,
        shift,
        criterion: match args.criterion {
            CriterionArg::Joint => ShiftCriterion::Joint,
            CriterionArg::TanDelta => ShiftCriterion::TanDelta,
            CriterionArg::SlopeWeighted => ShiftCriterion::SlopeWeighted,
            CriterionArg::Storage => ShiftCriterion::Storage,
        },
        vertical: match args.vertical {
            None => VerticalShift::None,
            Some(VerticalArg::Fitted) => VerticalShift::Fitted,
            Some(VerticalArg::Temperature) => VerticalShift::Temperature,
        },
        temperature: if args.nominal {
            TemperatureBasis::Nominal
        } else {
            TemperatureBasis::Mean
        },
        law: match args.law {
            LawArg::Auto => LawChoice::Auto,
            LawArg::Wlf => LawChoice::Wlf,
            LawArg::Arrhenius => LawChoice::Arrhenius,
            LawArg::Table => LawChoice::Table,
        },
        law_fit_range_c,
        ..MasterSettings::default()
    })
}

fn parse_number(s: &str, what: &str) -> anyhow::Result<f64> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| anyhow::anyhow!("--shift: {what} = {s:?} is not a number"))?;
    if !v.is_finite() {
        bail!("--shift: {what} = {s} is not finite");
    }
    Ok(v)
}

/// `auto`, `wlf:C1,C2`, `arrhenius:EA` or a file.
fn parse_shift(spec: &str, tref: Option<f64>) -> anyhow::Result<ShiftSource> {
    if spec == "auto" {
        return Ok(ShiftSource::Auto);
    }
    let need_tref = |form: &str| {
        tref.ok_or_else(|| {
            anyhow::anyhow!("--shift {form} needs --tref (the temperature its constants refer to)")
        })
    };
    if let Some(rest) = spec.strip_prefix("wlf:") {
        let parts: Vec<&str> = rest.split(',').collect();
        if parts.len() != 2 {
            bail!("--shift wlf:C1,C2 expects two numbers, got {rest:?}");
        }
        let c1 = parse_number(parts[0], "C1")?;
        let c2_k = parse_number(parts[1], "C2")?;
        let t_ref_c = need_tref("wlf:C1,C2")?;
        let law = ShiftLaw::Wlf { t_ref_c, c1, c2_k };
        law.validate().with_context(|| {
            format!("--shift wlf:C1,C2 needs C1 > 0 and C2 > 0 K, got C1 = {c1}, C2 = {c2_k}")
        })?;
        return Ok(ShiftSource::Given { law });
    }
    if let Some(rest) = spec.strip_prefix("arrhenius:") {
        let ea = parse_number(rest, "EA")?;
        let t_ref_c = need_tref("arrhenius:EA")?;
        let law = ShiftLaw::Arrhenius {
            t_ref_c,
            activation_energy_j_per_mol: ea,
        };
        law.validate()
            .with_context(|| format!("--shift arrhenius:EA needs EA > 0 J/mol, got {ea}"))?;
        return Ok(ShiftSource::Given { law });
    }
    let path = Path::new(spec);
    if !path.exists() {
        bail!("--shift {spec:?}: expected auto, wlf:C1,C2, arrhenius:EA or an existing file");
    }
    let text = std::fs::read_to_string(path)
        .with_context(|| format!("cannot read shift file {}", path.display()))?;
    let law = if text.trim_start().starts_with('{') {
        let law = serde_json::from_str::<ShiftLaw>(&text)
            .with_context(|| format!("{} is not a shift-law JSON", path.display()))?;
        law.validate()
            .with_context(|| format!("shift law {}", path.display()))?;
        law
    } else {
        crate::dma::shiftfactors::shift_table_from_bytes(
            &path.display().to_string(),
            text.as_bytes(),
            tref,
        )?
    };
    Ok(ShiftSource::Given { law })
}

fn summary(m: &MasterCurve) {
    eprintln!(
        "master curve: {} isotherms, {} points, T_ref = {} °C",
        m.isotherms.len(),
        m.points.len(),
        m.t_ref_c
    );
    eprintln!(
        "  T (°C)   log10 aT   ±std     log10 bT  overlap RMS  {} alone  vGP (°)  KK log10",
        m.kind.symbols().1
    );
    for s in &m.isotherms {
        let opt = |v: Option<f64>, p: usize| v.map_or("-".to_string(), |v| format!("{v:.p$}"));
        eprintln!(
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
            eprintln!("           shift carried by {c}");
        }
    }
    if let Some(w) = &m.wlf {
        eprintln!(
            "WLF:       C1 = {:.4}, C2 = {:.3} K at {} °C, RMS {:.4}",
            w.c1, w.c2_k, w.t_ref_c, w.rms_log10
        );
    }
    if let Some(a) = &m.arrhenius {
        eprintln!(
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
    eprintln!("shift law used: {law}");
    for w in &m.warnings {
        eprintln!("warning: {w}");
    }
    for f in &m.quality.flags {
        eprintln!("flag: {f}");
    }
}
