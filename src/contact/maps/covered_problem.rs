//! The covered problem of the friction maps and one node of it: the compound's reduced problem, ν and
//! the cover thickness ([`CoveredProblem`]), solved on the bonded layer at one point (s, η) of the
//! reduced plane ([`CoveredNode`]). Why (s, η) suffice is in the module doc of [`super::covered`]
//! (docs/MATH.md §13).
//!
//! Input: a [`CreepSpectrum`] at its reference temperature, ν, the cover thickness; output: nodes
//! (ln φ, ln λ, the layer solver's estimate and warnings). Below the node table
//! ([`super::nodes`]), the surface ([`super::surface`]) and the map ([`super::covered`]), which all
//! use it.

use super::reduced::ReducedProblem;
use super::FrictionMapError;
use crate::contact::body::{answer_at_load, Body, Warm};
use crate::contact::{ContactSettings, DimensionlessScene};
use crate::CreepSpectrum;

/// The compound's part of the covered problem: the half-space's [`ReducedProblem`] (Jᵢ/J_g, τᵢ, C),
/// ν and the cover thickness.
#[derive(Debug, Clone, PartialEq)]
pub struct CoveredProblem {
    /// The creep ratios and compliance factor (as for the half-space maps).
    pub reduced: ReducedProblem,
    /// Poisson's ratio of the cover.
    pub poisson: f64,
    /// Cover thickness h in m.
    pub cover_m: f64,
}

/// One solved node of the covered problem.
#[derive(Debug, Clone, PartialEq)]
pub struct CoveredNode {
    /// ln(ρF/N).
    pub ln_phi: f64,
    /// ln λ.
    pub ln_lambda: f64,
    /// The layer solver's own relative error estimate.
    pub error_estimate: f64,
    /// The layer solver's warnings.
    pub warnings: Vec<String>,
}

impl CoveredProblem {
    /// From a creep spectrum at its reference temperature, `poisson` overriding the spectrum's, and
    /// the cover thickness in m.
    pub fn new(
        spectrum: &CreepSpectrum,
        poisson: Option<f64>,
        cover_m: f64,
    ) -> Result<Self, FrictionMapError> {
        let reduced = ReducedProblem::new(spectrum, poisson)?;
        if !(cover_m.is_finite() && cover_m > 0.0) {
            return Err(FrictionMapError::BadValue {
                field: "cover thickness in m".into(),
                value: cover_m,
                expected: "finite and > 0",
            });
        }
        Ok(CoveredProblem {
            reduced,
            // ReducedProblem::new checked it in [0, 0.5]
            poisson: poisson.unwrap_or(spectrum.poisson),
            cover_m,
        })
    }

    /// The second reduced variable η = h/l_g of a scene of radius R and load N*.
    pub fn reduced_thickness(&self, radius_m: f64, load_n_per_m: f64) -> f64 {
        self.cover_m / self.reduced.glassy_length_m(radius_m, load_n_per_m)
    }

    /// Solve the dimensionless covered problem on the bonded layer at s = e^x, η = e^y (N′ = 1/4) to
    /// `tol` (the layer solver's floor applies; its warning is returned).
    #[cfg(test)]
    pub fn node(&self, x: f64, y: f64, tol: f64) -> Result<CoveredNode, FrictionMapError> {
        self.node_from(x, y, tol, None)
    }

    /// [`Self::node`] with the layer solver's load loop started from `start` = (λ guess,
    /// d ln N′/d ln λ) (a neighbouring node's answer; `None`: the solver's closed-form start). The
    /// answer does not depend on the start beyond the load loop's stopping tolerance (N′ to 1e−10).
    pub fn node_from(
        &self,
        x: f64,
        y: f64,
        tol: f64,
        start: Option<(f64, f64)>,
    ) -> Result<CoveredNode, FrictionMapError> {
        let s_s = x.exp();
        // the bonded layer as `solve_cover(…, &Body::Layer { .. }, tol)` solves it: N′ = 1/4 and the
        // cover h′ = η, lengths in units of l_g = V·T
        let problem =
            DimensionlessScene::in_units_of_vt(self.reduced.terms(s_s), 0.25, self.poisson);
        let a = answer_at_load(
            &Body::Layer {
                thickness_m: y.exp(),
            },
            &problem,
            &ContactSettings::auto(tol),
            Warm {
                start,
                checks: true,
            },
        )
        .map_err(|source| FrictionMapError::Solve { s_s, source })?
        .answer;
        let (phi, lambda) = (a.solution.friction_rho, a.solution.lambda);
        if !(phi > 0.0 && phi.is_finite()) {
            return Err(FrictionMapError::NonPositive { s_s, phi });
        }
        Ok(CoveredNode {
            ln_phi: phi.ln(),
            ln_lambda: lambda.ln(),
            error_estimate: a.error_estimate,
            warnings: a.warnings,
        })
    }
}
