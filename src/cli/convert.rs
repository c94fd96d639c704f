//! `viscoroll convert`: a relaxation spectrum (JSON, [`crate::RelaxationSpectrum`]) → a creep spectrum
//! (JSON, [`crate::CreepSpectrum`]), exactly (docs/MATH.md §4, default) or by Park & Schapery (thesis
//! eq. 2.18–2.23), with the checks that tell how good the result is.
//!
//! `--json` prints one object: `{ "method", "variant", "input", "output", "creep_spectrum", "checks":
//! { "max_abs_product_error", "omega_min_rad_s", "omega_max_rad_s", "glassy_product", "relaxed_product",
//! "negative_terms" }, "info" }`. A fluid (E∞ = 0, exact method) converts with its flow term t/η₀
//! (docs/MATH.md §17): the creep spectrum then carries `viscosity_pa_s` and `relaxed_product` is null. Without `--json` and without `-o` the creep spectrum JSON goes to
//! stdout; a summary always goes to stderr (unless `--json`).

use crate::creep::exact::max_product_error;
use crate::creep::{
    fluid_to_creep, park_schapery, relaxation_to_creep, ParkSchaperySettings, ParkSchaperyVariant,
};
use anyhow::Context;
use std::path::PathBuf;

/// Conversion method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Method {
    /// Exact: roots and residues of s·Ē(s) (docs/MATH.md §4).
    Exact,
    /// Park & Schapery's collocation / least squares (thesis eq. 2.18–2.23), τⱼ = ρⱼ.
    ParkSchapery,
}

/// Park & Schapery variant.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Variant {
    /// Collocation at t_k = τ_k.
    #[value(name = "collocation-1")]
    Collocation1,
    /// Collocation at t_k = τ_k/2.
    CollocationHalf,
    /// Least squares at 4 times per decade.
    LeastSquares,
}

/// Arguments of `viscoroll convert`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Relaxation spectrum JSON file (fields `modulus_inf_pa`, `terms[].modulus_pa`, `terms[].tau_s`,
    /// optional `kind`, `poisson`) or a fit file (`fits/NAME.json`; its `relaxation` is converted).
    pub spectrum: PathBuf,
    /// Conversion method.
    #[arg(long, value_enum, default_value = "exact")]
    pub method: Method,
    /// Park & Schapery variant (with --method park-schapery).
    #[arg(long, value_enum, default_value = "collocation-1")]
    pub park_schapery_variant: Variant,
    /// Write the creep spectrum JSON to this file (atomically).
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
    /// Overwrite OUT if it exists.
    #[arg(long)]
    pub force: bool,
    /// Print one JSON object (result and checks) on stdout.
    #[arg(long)]
    pub json: bool,
}

/// Run `viscoroll convert`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let relax = super::spectrum_input::read_spectrum_input(&args.spectrum)?.spectrum;
    relax
        .validate()
        .with_context(|| format!("{}", args.spectrum.display()))?;
    let (creep, variant, info, viscosity_pa_s) = convert(&relax, &args)?;
    let (wmin, wmax, omegas) = crate::creep::exact::check_frequencies(&relax);
    let product = match viscosity_pa_s {
        Some(viscosity_pa_s) => crate::creep::FluidCreep {
            solid: creep.clone(),
            viscosity_pa_s,
        }
        .max_product_error(&relax, &omegas),
        None => max_product_error(&relax, &creep, &omegas),
    };
    let glassy = creep.creep_compliance(0.0) * relax.instantaneous_modulus();
    // A fluid has no relaxed compliance: J(t) grows like t/η₀.
    let relaxed = viscosity_pa_s
        .is_none()
        .then(|| creep.compliance_relaxed() * relax.modulus_inf_pa);
    let negative = creep
        .terms
        .iter()
        .filter(|t| t.compliance_per_pa < 0.0)
        .count();

    // The creep spectrum as written: a fluid's carries its flow term as `viscosity_pa_s`, which
    // `roll` refuses with the reason (crate::pipeline::roll_fit::CreepSource::read).
    let mut creep_json = serde_json::to_value(&creep)?;
    if let (Some(eta), Some(obj)) = (viscosity_pa_s, creep_json.as_object_mut()) {
        obj.insert("viscosity_pa_s".into(), eta.into());
    }
    if let Some(out) = &args.output {
        super::output::write_atomic(
            out,
            serde_json::to_string_pretty(&creep_json)?.as_bytes(),
            args.force,
        )?;
    }
    let method = match args.method {
        Method::Exact => "exact",
        Method::ParkSchapery => "park-schapery",
    };
    if args.json {
        let obj = serde_json::json!({
            "method": method,
            "variant": variant,
            "input": args.spectrum.display().to_string(),
            "output": args.output.as_ref().map(|p| p.display().to_string()),
            "creep_spectrum": creep_json,
            "checks": {
                "max_abs_product_error": product,
                "omega_min_rad_s": wmin,
                "omega_max_rad_s": wmax,
                "glassy_product": glassy,
                "relaxed_product": relaxed,
                "negative_terms": negative,
            },
            "info": info,
        });
        outln!("{}", super::output::versioned(obj));
    } else {
        if args.output.is_none() {
            outln!("{}", serde_json::to_string_pretty(&creep_json)?);
        }
        errln!(
            "viscoroll convert: {method}{}: {} retardation terms; max |E*J* − 1| = {product:.2e} over ω = {wmin:.1e}…{wmax:.1e} rad/s; J(0)·E₀ = {glassy:.15}; {}{}",
            variant.map(|v| format!(" ({v})")).unwrap_or_default(),
            creep.terms.len(),
            match (relaxed, viscosity_pa_s) {
                (Some(r), _) => format!("J∞·E∞ = {r:.15}"),
                (None, eta) => format!(
                    "a fluid (E∞ = 0): flow term t/η₀, η₀ = {:.6e} Pa·s",
                    eta.unwrap_or(f64::NAN)
                ),
            },
            if negative > 0 {
                format!("; WARNING: {negative} negative strengths (non-physical)")
            } else {
                String::new()
            }
        );
    }
    Ok(())
}

/// The creep spectrum of `relax` by the method `args` asks for: (spectrum, Park–Schapery variant,
/// the method's info, a fluid's viscosity η₀ in Pa·s).
fn convert(
    relax: &crate::RelaxationSpectrum,
    args: &Args,
) -> anyhow::Result<(
    crate::CreepSpectrum,
    Option<&'static str>,
    serde_json::Value,
    Option<f64>,
)> {
    // A fluid (E∞ = 0) converts exactly with its flow term t/η₀ (docs/MATH.md §17).
    let fluid = relax.modulus_inf_pa == 0.0 && args.method == Method::Exact;
    let mut viscosity_pa_s = None;
    let (creep, variant, info) = match args.method {
        Method::Exact if fluid => {
            let (f, info) = fluid_to_creep(relax)?;
            viscosity_pa_s = Some(f.viscosity_pa_s);
            (f.solid, None, serde_json::to_value(info)?)
        }
        Method::Exact => {
            let (c, info) = relaxation_to_creep(relax)?;
            (c, None, serde_json::to_value(info)?)
        }
        Method::ParkSchapery => {
            let variant = match args.park_schapery_variant {
                Variant::Collocation1 => ParkSchaperyVariant::CollocationOne,
                Variant::CollocationHalf => ParkSchaperyVariant::CollocationHalf,
                Variant::LeastSquares => ParkSchaperyVariant::LeastSquares,
            };
            let settings = ParkSchaperySettings {
                variant,
                ..Default::default()
            };
            let (c, info) = park_schapery(relax, &settings)?;
            (c, Some(variant.name()), serde_json::to_value(info)?)
        }
    };
    Ok((creep, variant, info, viscosity_pa_s))
}
