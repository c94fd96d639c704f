//! `viscoroll roll`: one dimensional scene, a rigid roll on a half-space with a given creep spectrum
//! (JSON, the serde form of [`crate::CreepSpectrum`]) → friction, contact length, offset, pressure.
//! A fit file (`fits/NAME.json`, [`crate::pipeline::CompoundFit`]) is accepted too, with `--temp-c T`:
//! its creep spectrum is moved to T by its shift law (`CreepSpectrum::at_temperature`, docs/MATH.md §6);
//! a T outside the measured temperatures is allowed and flagged (`extrapolated`, and a warning).
//!
//! `--json` prints one object: `friction`, `contact_length_mm`, `offset_mm`, `resistance_n_per_m`,
//! `max_pressure_mpa`, `x_mm`, `pressure_mpa`, the dimensionless problem (`lambda`, `beta`, `load`,
//! `rho`, `time_scale_s`, `creep`) and the numerics (`scheme`, `n`, `iterations`).

use crate::contact::{AutoSettings, Body, ContactSettings, Scene, Scheme};
use crate::pipeline::roll_fit::{roll_source_at, CreepSource, SourceRoll};
use anyhow::{bail, Context};
use std::path::PathBuf;

/// Arguments of `viscoroll roll`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Creep spectrum, JSON (`kind`, `poisson`, `compliance_glassy_per_pa`, `terms`: [{`compliance_per_pa`, `tau_s`}]),
    /// or a fit file (`viscoroll run`'s fits/NAME.json) together with --temp-c.
    #[arg(value_name = "SPECTRUM.json|FIT.json")]
    pub spectrum: PathBuf,
    /// Temperature in °C (fit files only: the spectrum is shifted there by the fit's shift law).
    #[arg(long, allow_negative_numbers = true)]
    pub temp_c: Option<f64>,
    /// Roll radius in mm (> 0).
    #[arg(long, allow_negative_numbers = true)]
    pub radius_mm: f64,
    /// Load per unit width in N/m (> 0).
    #[arg(long, allow_negative_numbers = true)]
    pub load_n_per_m: f64,
    /// Rolling speed in m/s (> 0).
    #[arg(long, allow_negative_numbers = true)]
    pub speed_m_s: f64,
    /// Poisson's ratio in [0, 0.5] (default: the spectrum's, itself 0.5 by default).
    #[arg(long, allow_negative_numbers = true)]
    pub poisson: Option<f64>,
    /// Number of intervals of the thesis scheme.
    #[arg(long, default_value_t = 200)]
    pub n: usize,
    /// Discretisation: `auto` (error-controlled, default), `thesis` (piecewise linear, `--n`) or
    /// `exact` (one creep term only).
    #[arg(long, default_value_t = Scheme::Auto)]
    pub scheme: Scheme,
    /// Relative tolerance on friction and contact length for `--scheme auto` (1e-12 … 0.1).
    #[arg(long, default_value_t = 1e-6)]
    pub tol: f64,
    /// Rubber cover thickness in mm on a rigid carcass (absent: a half-space).
    #[arg(long, allow_negative_numbers = true)]
    pub cover_mm: Option<f64>,
    /// Body: `auto` (default with a cover: the cheapest within --tol of the layer), `half-space`,
    /// `layer` (bonded to a rigid carcass) or `winkler` (uniaxial columns, as conveyor design tools).
    #[arg(long)]
    pub model: Option<String>,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
}

/// Run `viscoroll roll`.
pub fn run(args: Args) -> anyhow::Result<()> {
    for (name, v) in [
        ("--radius-mm", args.radius_mm),
        ("--load-n-per-m", args.load_n_per_m),
        ("--speed-m-s", args.speed_m_s),
    ] {
        if !(v.is_finite() && v > 0.0) {
            bail!("{name} must be finite and > 0, got {v}");
        }
    }
    super::spectrum_input::refuse_fluid_or_relaxation(&args.spectrum)?;
    let source = CreepSource::read(&args.spectrum)
        .with_context(|| format!("cannot read spectrum file {}", args.spectrum.display()))?;
    match (&source, args.temp_c) {
        (CreepSource::Fit(fit), None) => bail!(
            "{}: a fit file needs --temp-c (its spectrum is at T_ref = {} °C)",
            args.spectrum.display(),
            fit.shift_law.t_ref_c()
        ),
        (CreepSource::Spectrum(_), Some(_)) => bail!(
            "{}: --temp-c needs a fit file (a bare creep spectrum has no shift law)",
            args.spectrum.display()
        ),
        _ => {}
    }
    let scene = Scene {
        radius_m: args.radius_mm * 1e-3,
        load_n_per_m: args.load_n_per_m,
        speed_m_s: args.speed_m_s,
        poisson: args.poisson,
        body: Body::HalfSpace,
    };
    if args.cover_mm.is_some() || args.model.is_some() {
        // A cover: the body is chosen and solved by contact::body::layer (super::roll_cover).
        let (spectrum, shifted, warnings) = match (&source, args.temp_c) {
            (CreepSource::Fit(fit), Some(t)) => {
                let (at, w) = crate::pipeline::roll_fit::fit_spectrum_at(fit, t)
                    .with_context(|| format!("{}: --temp-c {t}", args.spectrum.display()))?;
                (at.spectrum.clone(), Some(at), w.into_iter().collect())
            }
            (CreepSource::Spectrum(s), _) => (s.clone(), None, Vec::new()),
            (CreepSource::Fit(_), None) => bail!("a fit file needs --temp-c"),
        };
        return super::roll_cover::run(&args, &scene, &spectrum, shifted.as_ref(), warnings);
    }
    let settings = ContactSettings {
        scheme: args.scheme,
        n: args.n,
        auto: AutoSettings {
            tol: args.tol,
            ..AutoSettings::default()
        },
        ..ContactSettings::default()
    };
    let r = roll_source_at(&source, args.temp_c, &scene, &settings)
        .with_context(|| format!("{}", args.spectrum.display()))?;
    if args.json {
        print_json(&args, &r);
    } else {
        print_text(&args, &r);
    }
    // Temperature warnings first, then the solver's (also in the JSON object).
    for w in &r.warnings {
        eprintln!("warning: {w}");
    }
    Ok(())
}

/// `--json`: one object on stdout (fields in the module doc; the `auto` diagnostics when solved so).
fn print_json(args: &Args, r: &SourceRoll) {
    let (sol, shifted, warnings) = (&r.roll, &r.shift, &r.warnings);
    let d = &sol.dimensionless;
    let auto_info = d.auto.as_ref();
    let mut obj = serde_json::json!({
        "friction": sol.friction,
        "contact_length_mm": sol.contact_length_m * 1e3,
        "offset_mm": sol.offset_m * 1e3,
        "resistance_n_per_m": sol.resistance_n_per_m,
        "max_pressure_mpa": sol.max_pressure_pa * 1e-6,
        "x_mm": sol.x_m.iter().map(|x| x * 1e3).collect::<Vec<_>>(),
        "pressure_mpa": sol.pressure_pa.iter().map(|p| p * 1e-6).collect::<Vec<_>>(),
        "radius_mm": args.radius_mm,
        "load_n_per_m": args.load_n_per_m,
        "speed_m_s": args.speed_m_s,
        "poisson": sol.problem.poisson,
        "lambda": d.lambda,
        "beta": d.beta,
        "load": d.load,
        "friction_rho": d.friction_rho,
        "rho": sol.problem.rho,
        "time_scale_s": sol.problem.time_scale_s,
        "creep": sol.problem.terms,
        "scheme": d.scheme,
        "n": d.n,
        "iterations": d.iterations,
        "temp_c": shifted.as_ref().map(|a| a.temp_c),
        "log10_a_t": shifted.as_ref().map(|a| a.log10_a_t),
        "extrapolated": shifted.as_ref().map(|a| a.extrapolated),
        "warnings": warnings,
    });
    if let Some(a) = &auto_info {
        obj["error_estimate"] = serde_json::json!(d.error_estimate);
        obj["tol"] = serde_json::json!(a.tol);
        obj["modes_used"] = serde_json::json!(a.modes_used);
        obj["modes_total"] = serde_json::json!(a.modes_total);
        obj["modes_lumped"] = serde_json::json!(a.modes_lumped);
        obj["modes_dropped"] = serde_json::json!(a.modes_dropped);
        obj["min_pressure_ratio"] = serde_json::json!(a.min_pressure_ratio);
    }
    println!("{obj}");
}

/// The human-readable answer on stderr.
fn print_text(args: &Args, r: &SourceRoll) {
    let (sol, shifted, spectrum) = (&r.roll, &r.shift, &r.spectrum);
    let d = &sol.dimensionless;
    let auto_info = d.auto.as_ref();
    if let Some(a) = &shifted {
        eprintln!(
            "at {} °C: log10 a_T = {:.4}{}",
            a.temp_c,
            a.log10_a_t,
            if a.extrapolated {
                " (extrapolated)"
            } else {
                ""
            }
        );
    }
    eprintln!(
        "roll R = {} mm, N = {} N/m, V = {} m/s on {} ({} terms, nu = {})",
        args.radius_mm,
        args.load_n_per_m,
        args.speed_m_s,
        args.spectrum.display(),
        spectrum.terms.len(),
        sol.problem.poisson
    );
    eprintln!("friction F/N        = {:.6e}", sol.friction);
    eprintln!("resistance          = {:.6e} N/m", sol.resistance_n_per_m);
    eprintln!("contact length      = {:.6} mm", sol.contact_length_m * 1e3);
    eprintln!(
        "offset (centre ahead of lowest point) = {:.6} mm",
        sol.offset_m * 1e3
    );
    eprintln!(
        "max pressure        = {:.6} MPa",
        sol.max_pressure_pa * 1e-6
    );
    eprintln!(
        "dimensionless: lambda = {:.6}, beta = {:.6}, N' = {}, rho = {:.6e}, T = {:.6e} s; {} n = {}, {} solves",
        d.lambda, d.beta, d.load, sol.problem.rho, sol.problem.time_scale_s, d.scheme, d.n, d.iterations
    );
    if let Some(a) = &auto_info {
        eprintln!(
            "auto: error estimate {:.3e} (tol {:e}), modes used {}/{} (lumped {}, dropped {})",
            d.error_estimate.unwrap_or(f64::NAN),
            a.tol,
            a.modes_used,
            a.modes_total,
            a.modes_lumped,
            a.modes_dropped
        );
    }
}
