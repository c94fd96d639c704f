//! `viscoroll roll … --cover-mm H [--model auto|half-space|layer|winkler]`: the scene on a rubber cover
//! of thickness H bonded to a rigid carcass ([`crate::contact::body::layer::roll_cover`]).
//!
//! `--json` prints the fields of `roll` plus `model` (the body solved), `model_reason`,
//! `model_error_estimate` (when `auto` chose a cheaper body than the layer: its estimated relative
//! difference from the layer's answer), `cover_mm`, `cover_over_contact`, `error_estimate`,
//! `min_pressure_ratio`, `min_gap_ratio` and `warnings` (solver, contact checks, validity).

use super::roll::Args;
use crate::contact::body::layer::{roll_cover, ModelChoice};
use crate::contact::Scene;
use crate::creep::AtTemperature;
use crate::CreepSpectrum;
use anyhow::{bail, Context};

/// Run the covered scene.
pub fn run(
    args: &Args,
    scene: &Scene,
    spectrum: &CreepSpectrum,
    shifted: Option<&AtTemperature<CreepSpectrum>>,
    mut warnings: Vec<String>,
) -> anyhow::Result<()> {
    let name = args.model.as_deref().unwrap_or("auto");
    let Some(choice) = ModelChoice::parse(name) else {
        bail!("--model `{name}` is not known (auto, half-space, layer, winkler)");
    };
    if let Some(h) = args.cover_mm {
        if !(h.is_finite() && h > 0.0) {
            bail!("--cover-mm must be finite and > 0, got {h}");
        }
    }
    if !(args.tol.is_finite() && (1e-12..=0.1).contains(&args.tol)) {
        bail!("--tol must be in [1e-12, 0.1], got {}", args.tol);
    }
    let r = roll_cover(
        scene,
        spectrum,
        args.cover_mm.map(|h| h * 1e-3),
        choice,
        args.tol,
    )
    .with_context(|| format!("{}", args.spectrum.display()))?;
    warnings.extend(r.warnings.iter().cloned());
    let sol = &r.roll;
    let d = &sol.dimensionless;
    if args.json {
        let obj = serde_json::json!({
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
            "cover_mm": args.cover_mm,
            "cover_over_contact": r.cover_over_contact,
            "model": r.model.name(),
            "model_reason": r.reason,
            "model_error_estimate": r.model_error_estimate,
            "error_estimate": r.error_estimate,
            "tol": args.tol,
            "min_pressure_ratio": r.min_pressure_ratio,
            "min_gap_ratio": r.min_gap_ratio,
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
            "temp_c": shifted.map(|a| a.temp_c),
            "log10_a_t": shifted.map(|a| a.log10_a_t),
            "extrapolated": shifted.map(|a| a.extrapolated),
            "warnings": warnings,
        });
        println!("{obj}");
    } else {
        eprintln!(
            "roll R = {} mm, N = {} N/m, V = {} m/s on {} ({} terms, nu = {}), cover {}",
            args.radius_mm,
            args.load_n_per_m,
            args.speed_m_s,
            args.spectrum.display(),
            spectrum.terms.len(),
            sol.problem.poisson,
            args.cover_mm
                .map(|h| format!("{h} mm"))
                .unwrap_or_else(|| "none".into())
        );
        eprintln!("body                = {} ({})", r.model.name(), r.reason);
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
            "error estimate {:.2e}{}",
            r.error_estimate,
            r.model_error_estimate
                .map(|e| format!(", model error estimate (vs the layer) {e:.2e}"))
                .unwrap_or_default()
        );
        for w in &warnings {
            eprintln!("warning: {w}");
        }
    }
    Ok(())
}
