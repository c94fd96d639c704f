//! The input of `export` and `convert`: a relaxation spectrum JSON ([`RelaxationSpectrum`]), a fit
//! file ([`CompoundFit`], as `fit` and `run` write it), told apart by the fit file's
//! `format_version` + `relaxation` fields, or pyvisco's Prony-term CSV (a first row naming `tau_i`:
//! crate::prony::pyvisco_csv, ν = 0.5). A fit file also gives the master curve (for a refit with
//! fewer terms) and the shifts and fitted laws of its master curve (for a shift card).

use crate::pipeline::CompoundFit;
use crate::RelaxationSpectrum;
use anyhow::Context;
use std::path::Path;

/// What was read.
pub struct SpectrumInput {
    /// The relaxation spectrum (a fit file's `relaxation`).
    pub spectrum: RelaxationSpectrum,
    /// The whole fit file, when the input was one.
    pub fit: Option<CompoundFit>,
}

/// Read a relaxation spectrum JSON or a fit file.
pub fn read_spectrum_input(path: &Path) -> anyhow::Result<SpectrumInput> {
    let bytes = crate::fsutil::read_regular(path, crate::limits::INPUT_BYTES_MAX)
        .with_context(|| format!("cannot read {}", path.display()))?;
    if crate::prony::pyvisco_csv::looks_like_pyvisco_terms(&bytes) {
        let spectrum = crate::prony::pyvisco_csv::read_pyvisco_terms(
            &path.display().to_string(),
            &bytes,
            crate::material::default_poisson(),
        )?;
        return Ok(SpectrumInput {
            spectrum,
            fit: None,
        });
    }
    let text =
        String::from_utf8(bytes).with_context(|| format!("{}: not UTF-8", path.display()))?;
    let value: serde_json::Value =
        serde_json::from_str(&text).with_context(|| format!("{}: not JSON", path.display()))?;
    if value.get("format_version").is_some() && value.get("relaxation").is_some() {
        let fit = CompoundFit::read(path).with_context(|| format!("{}", path.display()))?;
        return Ok(SpectrumInput {
            spectrum: fit.relaxation.clone(),
            fit: Some(fit),
        });
    }
    let spectrum: RelaxationSpectrum = serde_json::from_value(value).with_context(|| {
        format!(
            "{}: neither a relaxation spectrum JSON (modulus_inf_pa, terms) nor a fit file",
            path.display()
        )
    })?;
    Ok(SpectrumInput {
        spectrum,
        fit: None,
    })
}

/// `roll` takes a creep spectrum or a fit file. A relaxation spectrum given instead is refused with
/// the step that is missing, and a fluid (E∞ = 0: a relaxation spectrum, or a fit file whose
/// relaxation has none) with the reason ([`crate::creep::FLUID_NO_STEADY_ROLLING`], docs/MATH.md §17).
pub fn refuse_fluid_or_relaxation(path: &Path) -> anyhow::Result<()> {
    let Ok(text) = crate::fsutil::read_regular_to_string(path, crate::limits::INPUT_BYTES_MAX)
    else {
        return Ok(()); // the reader that follows reports it
    };
    let Ok(value) = serde_json::from_str::<serde_json::Value>(&text) else {
        return Ok(());
    };
    let relaxation = if value.get("format_version").is_some() {
        value.get("relaxation")
    } else if value.get("modulus_inf_pa").is_some() && value.get("terms").is_some() {
        Some(&value)
    } else {
        None
    };
    let Some(r) = relaxation else { return Ok(()) };
    let e_inf = r.get("modulus_inf_pa").and_then(|v| v.as_f64());
    if e_inf == Some(0.0) {
        let eta: f64 = r
            .get("terms")
            .and_then(|t| t.as_array())
            .map(|ts| {
                ts.iter()
                    .map(|t| {
                        let g = |k: &str| t.get(k).and_then(|v| v.as_f64()).unwrap_or(0.0);
                        g("modulus_pa") * g("tau_s")
                    })
                    .sum()
            })
            .unwrap_or(0.0);
        anyhow::bail!(
            "{}: modulus_inf_pa = 0, a fluid (zero-shear viscosity η₀ = Σ Eᵢτᵢ = {eta:.3e} Pa·s, \
             tensile or shear as the spectrum's kind; `viscoroll convert` gives its creep function \
             with the flow term t/η₀). {}",
            path.display(),
            crate::creep::FLUID_NO_STEADY_ROLLING
        );
    }
    if value.get("format_version").is_none() {
        anyhow::bail!(
            "{}: a relaxation spectrum; roll takes a creep spectrum: convert it first \
             (`viscoroll convert {} -o creep.json`) or give a fit file",
            path.display(),
            path.display()
        );
    }
    Ok(())
}
