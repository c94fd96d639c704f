//! `viscoroll roll … --cover-mm H [--model auto|half-space|layer|winkler]`: the scene on a rubber cover
//! of thickness H bonded to a rigid carcass ([`crate::contact::cover::roll_cover`]).
//!
//! `--json` prints the fields of `roll` plus `model` (the body solved), `model_reason`,
//! `model_error_estimate` (when `auto` chose a cheaper body than the layer: its estimated relative
//! difference from the layer's answer), `cover_mm`, `cover_over_contact`, `error_estimate`,
//! `min_pressure_ratio`, `min_gap_ratio`, `warnings` (solver, contact checks, validity) and the 90 %
//! band `friction_p05/p50/p95` with `bands_note` (a fit file made by `viscoroll run`: solved on the
//! cover as in the main job, docs/MATH.md eq. 15.6); printed by the shared [`super::roll_print`]. Warnings also go to stderr.

use super::roll_args::Args;
use super::roll_band::{band, band_fields};
use super::roll_print::{Answer, Shift};
use crate::contact::cover::roll_cover;
use crate::contact::Body;
use crate::contact::Scene;
use crate::creep::AtTemperature;
use crate::pipeline::roll_fit::CreepSource;
use crate::CreepSpectrum;
use anyhow::{bail, Context};

/// Run the covered scene.
pub fn run(
    args: &Args,
    source: &CreepSource,
    scene: &Scene,
    spectrum: &CreepSpectrum,
    shifted: Option<&AtTemperature<CreepSpectrum>>,
    mut warnings: Vec<String>,
) -> anyhow::Result<()> {
    let name = args.model.as_deref().unwrap_or("auto");
    let cover_m = args.cover_mm.map(|h| h * 1e-3);
    let Some(body) =
        Body::choice(name, cover_m).with_context(|| format!("{}", args.spectrum.display()))?
    else {
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
    let on_body = Scene { body, ..*scene };
    let r = roll_cover(&on_body, spectrum, args.tol)
        .with_context(|| format!("{}", args.spectrum.display()))?;
    warnings.extend(r.warnings.iter().cloned());
    // The band is solved on the body the main job's bands solve (`auto`, eq. 15.6): on the cover,
    // or on the half-space when one was asked for; the uniaxial Winkler model has none.
    let band = match body {
        Body::Winkler { .. } => Err("--model winkler: the bands are solved on the body `auto` chooses (the layer or a body within tol of it), not on the uniaxial Winkler model".to_string()).into(),
        Body::HalfSpace { .. } => band(args, source, scene, r.roll.friction),
        _ => band(args, source, &on_body, r.roll.friction),
    };
    let json_extra = serde_json::json!({
        "cover_mm": args.cover_mm,
        "cover_over_contact": r.cover_over_contact,
        "model": r.model.name(),
        "model_reason": r.reason,
        "model_error_estimate": r.model_error_estimate,
        "error_estimate": r.error_estimate,
        "tol": args.tol,
        "min_pressure_ratio": r.min_pressure_ratio,
        "min_gap_ratio": r.min_gap_ratio,
    });
    let mut json_extra = json_extra.as_object().cloned().unwrap_or_default();
    let band_line = band_fields(&band, &mut json_extra);
    Answer {
        args,
        sol: &r.roll,
        shift: shifted.map(|a| Shift {
            temp_c: a.temp_c,
            log10_a_t: a.log10_a_t,
            extrapolated: a.extrapolated,
        }),
        terms: spectrum.terms.len(),
        warnings: &warnings,
        json_extra,
        header_suffix: format!(
            ", cover {}",
            args.cover_mm
                .map(|h| format!("{h} mm"))
                .unwrap_or_else(|| "none".into())
        ),
        lines_after_header: vec![format!(
            "body                = {} ({})",
            r.model.name(),
            r.reason
        )],
        lines_after: vec![
            format!(
                "error estimate {:.2e}{}",
                r.error_estimate,
                r.model_error_estimate
                    .map(|e| format!(", model error estimate (vs the layer) {e:.2e}"))
                    .unwrap_or_default()
            ),
            band_line,
        ],
    }
    .print();
    Ok(())
}
