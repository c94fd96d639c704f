//! The bonded layer: a viscoelastic cover of thickness h bonded to a rigid carcass (plane strain,
//! 0 ≤ ν ≤ ½; issue 14). Its thin compressible limit, the constrained Winkler foundation, is
//! `contact::numerics::winkler` (the Winkler body is `body/winkler/`).
//!
//! Input: the dimensionless creep terms (fᵢ, bᵢ) of thesis eq. 3.7, the load N′ (eq. 3.24), the
//! dimensionless cover thickness h′ = h/(VT) and ν; output: [`BodyAnswer`] (λ, β, pressure, ρF/N,
//! error estimate, contact checks, warnings, which body was solved).
//!
//! - [`compliance`]: the layer's Fourier compliance F(|k|h) (derivation, references, limits);
//! - [`kernel`]: its steady-rolling viscoelastic kernel = half-space kernel + smooth correction;
//! - [`spectral`]: the spectrally convergent solver (default; the `auto` reduction with the layer
//!   term as a polynomial right-hand side);
//! - [`collocation`]: the thesis' collocation scheme with that kernel, load loop, error estimate
//!   (the fallback for covers too thin for the spectral solver).

pub(crate) mod collocation;
pub(crate) mod compliance;
pub(crate) mod kernel;
pub(crate) mod spectral;

pub use collocation::LayerSettings;
pub use kernel::LayerKernel;

use crate::contact::error::ContactError;
pub use crate::contact::problem::BodyAnswer;
use crate::contact::problem::CreepTerm;

/// The hat collocation (the fallback for very thin covers) converges to first order in λ
/// (Richardson-extrapolated); below this tolerance its cost grows past a second per point, so it is
/// solved to at least this.
pub const LAYER_TOL_FLOOR: f64 = 1e-4;

/// Solve the bonded layer of dimensionless thickness `thickness` at load N′: by the spectral solver
/// ([`spectral`]) to `settings.tol`, or, where the cover is too thin against the contact for its
/// degree cap `settings.p_max` (or `settings.spectral` is false), by the hat collocation
/// ([`collocation`]) to max(tol, [`LAYER_TOL_FLOOR`]), with a warning saying so.
pub fn layer_at_load(
    terms: &[CreepTerm],
    load: f64,
    thickness: f64,
    poisson: f64,
    settings: &LayerSettings,
) -> Result<BodyAnswer, ContactError> {
    let mut fallback_warnings = Vec::new();
    if settings.spectral {
        let spectral_settings = spectral::SpectralSettings {
            tol: settings.tol,
            p_max: settings.p_max,
            start: settings.start,
            checks: settings.checks,
        };
        match spectral::solve_spectral_at_load(terms, load, thickness, poisson, &spectral_settings)
        {
            Ok(Some(a)) => return Ok(package_layer(a, Vec::new())),
            Ok(None) => fallback_warnings.push(format!(
                "the cover is thin against the contact (h/(VT) = {thickness:.2e}): the spectral layer \
                 solver would need a degree above {}; solved by the first-order hat collocation instead",
                settings.p_max
            )),
            Err(e @ ContactError::NotConverged { .. }) => fallback_warnings.push(format!(
                "the spectral layer solver did not converge ({e}); solved by the first-order hat \
                 collocation instead"
            )),
            Err(e) => return Err(e),
        }
    }
    let kernel = LayerKernel::new(terms, thickness, poisson)?;
    let hat_settings = LayerSettings {
        tol: settings.tol.max(LAYER_TOL_FLOOR),
        ..*settings
    };
    let a = collocation::solve_layer_at_load(&kernel, load, &hat_settings)?;
    if settings.tol < LAYER_TOL_FLOOR {
        fallback_warnings.push(format!(
            "tolerance not reached: the hat collocation is solved to {:.0e} (estimate {:.1e}), not to \
             tol {:.0e} (first order; finer costs seconds)",
            LAYER_TOL_FLOOR,
            a.error_estimate,
            settings.tol
        ));
    }
    Ok(package_layer(a, fallback_warnings))
}

/// A [`collocation::LayerAnswer`] as a [`BodyAnswer`], with extra warnings first.
fn package_layer(a: collocation::LayerAnswer, mut warnings: Vec<String>) -> BodyAnswer {
    warnings.extend(a.warnings);
    let mut solution = a.solution;
    solution.warnings.extend(warnings.iter().cloned());
    BodyAnswer {
        solution,
        error_estimate: a.error_estimate,
        min_pressure_ratio: a.min_pressure_ratio,
        min_gap_ratio: a.min_gap_ratio,
        warnings,
    }
}

#[cfg(test)]
mod elastic_check;
#[cfg(test)]
mod tests;
