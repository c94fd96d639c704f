//! The input of `export` and `convert`: a relaxation spectrum JSON ([`RelaxationSpectrum`]) or a fit
//! file ([`CompoundFit`], as `fit` and `run` write it), told apart by the fit file's
//! `format_version` + `relaxation` fields. A fit file also gives the master curve (for a refit with
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
    let text =
        std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))?;
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
