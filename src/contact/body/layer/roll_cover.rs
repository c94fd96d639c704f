//! A dimensional scene on a covered roll track: the body chosen (half-space, bonded layer, Winkler) and
//! solved, in SI units, with the validity warnings of issue 14.
//!
//! Input: [`Scene`], [`CreepSpectrum`], the cover thickness in m (None: half-space) and a
//! [`ModelChoice`]; output: [`CoverRoll`] (the [`RollSolution`] of the body solved, which body and
//! why, its error estimate and, when `auto` chose a cheaper body than the layer, the estimated
//! difference from the layer's answer).
//!
//! `auto` (criterion measured in `tests::criterion_table`, table in the README): with λ the half-space
//! contact length (solved first, it is cheap), L = max(λ, 1/bᵢ over the modes holding ≥ 1 % of the
//! compliance, rᵢ = fᵢ/bᵢ ≥ 0.01·S) the longest length the body's memory reaches, and h′ the cover,
//! - when the half-space law [`C_HALF_SPACE`]·(L/h′)² ≤ tol: the half-space (measured: relative
//!   differences of λ ≈ 0.13(λ/h)², of ρF/N ≈ 0.5(λ/h)² for one term and 2.5(λ/h)² for the example
//!   spectrum, whose slowest strong mode reaches 1.5λ; a mode with memory longer than h makes the
//!   approach slower than quadratic, which the max(λ, 1/b) covers conservatively);
//! - when ν < ½ and the thin-layer law [`C_WINKLER`]·(h′/λ)/(1−2ν) ≤ tol: the constrained Winkler
//!   foundation (measured at ν = 0.3: λ differs by ≈ 0.24·h/λ, ρF/N by less);
//! - otherwise the layer, to max(tol, [`LAYER_TOL_FLOOR`]).
//!
//! Validity: the contact length should stay below about 0.3R (small strains, flat surface); the
//! indentation, estimated as the roll's depth below the higher contact edge, max(β, λ−β)²/(2ρ)·VT
//! (a lower bound of the true one), below about 30 % of the cover.

use super::{layer_at_load, winkler_at_load, BodyModel, LayerSettings, WinklerColumns};
use crate::contact::error::ContactError;
use crate::contact::load::LoadSettings;
use crate::contact::scene::{RollSolution, Scene};
use crate::contact::{roll, Body, ContactSettings};
use crate::CreepSpectrum;

/// Half-space law of approach: relative difference from the layer ≤ C_HS·(L/h)² (module doc;
/// the largest measured constant is 2.5 with L = λ, here with L ≥ λ).
pub const C_HALF_SPACE: f64 = 3.0;
/// Thin compressible layer vs constrained Winkler: relative difference ≤ C_W·(h/λ)/(1−2ν) (measured
/// 0.24·h/λ at ν = 0.3, i.e. C_W = 0.1; with margin).
pub const C_WINKLER: f64 = 0.15;
/// The layer's collocation converges to first order in λ (Richardson-extrapolated); below this
/// tolerance its cost grows past a second per point, so it is solved to at least this.
pub const LAYER_TOL_FLOOR: f64 = 1e-4;

/// Which body to solve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModelChoice {
    /// The cheapest body within the tolerance of the layer (default with a cover).
    Auto,
    /// Always the half-space.
    HalfSpace,
    /// Always the bonded layer.
    Layer,
    /// The conveyor tools' Winkler foundation (uniaxial columns).
    Winkler,
}

impl ModelChoice {
    /// Parse `auto|half-space|layer|winkler`.
    pub fn parse(s: &str) -> Option<Self> {
        Some(match s {
            "auto" => ModelChoice::Auto,
            "half-space" => ModelChoice::HalfSpace,
            "layer" => ModelChoice::Layer,
            "winkler" => ModelChoice::Winkler,
            _ => return None,
        })
    }
}

/// A scene's answer on the chosen body.
#[derive(Debug, Clone, PartialEq)]
pub struct CoverRoll {
    /// SI answer (friction, contact length, offset, pressure) and the dimensionless problem.
    pub roll: RollSolution,
    /// The body solved.
    pub model: BodyModel,
    /// Why this body (one line for the datasheet).
    pub reason: String,
    /// The solver's own relative error estimate.
    pub error_estimate: f64,
    /// When `auto` chose a cheaper body than the layer: the estimated relative difference from it.
    pub model_error_estimate: Option<f64>,
    /// Cover thickness over the contact length (None without a cover).
    pub cover_over_contact: Option<f64>,
    /// min Q′ / max Q′.
    pub min_pressure_ratio: f64,
    /// Smallest gap outside the contact over the indentation depth.
    pub min_gap_ratio: f64,
    /// Solver and validity warnings.
    pub warnings: Vec<String>,
}

/// Solve `scene` on a cover of `cover_m` (None: half-space) with the body `choice`, to `tol`.
pub fn roll_cover(
    scene: &Scene,
    spectrum: &CreepSpectrum,
    cover_m: Option<f64>,
    choice: ModelChoice,
    tol: f64,
) -> Result<CoverRoll, ContactError> {
    let p = scene.dimensionless(spectrum)?;
    let half_space = |reason: String, model_err: Option<f64>| -> Result<CoverRoll, ContactError> {
        let hs_scene = Scene {
            body: Body::HalfSpace,
            ..*scene
        };
        let r = roll(&hs_scene, spectrum, &ContactSettings::auto(tol))?;
        let diag = r.dimensionless.auto.clone();
        Ok(CoverRoll {
            error_estimate: r.dimensionless.error_estimate.unwrap_or(f64::NAN),
            model: BodyModel::HalfSpace,
            reason,
            model_error_estimate: model_err,
            cover_over_contact: cover_m.map(|h| h / r.contact_length_m),
            min_pressure_ratio: diag.as_ref().map_or(f64::NAN, |d| d.min_pressure_ratio),
            min_gap_ratio: diag.as_ref().map_or(f64::NAN, |d| d.min_gap_ratio),
            warnings: r.dimensionless.warnings.clone(),
            roll: r,
        })
    };
    let Some(h_m) = cover_m else {
        if !matches!(choice, ModelChoice::Auto | ModelChoice::HalfSpace) {
            return Err(ContactError::Unsupported(
                "the layer and Winkler bodies need a cover thickness (--cover-mm / cover_thickness_mm)"
                    .into(),
            ));
        }
        return half_space("no cover given: half-space".into(), None);
    };
    if !(h_m.is_finite() && h_m > 0.0) {
        return Err(ContactError::BadValue {
            field: "cover thickness in m".into(),
            expected: "finite and > 0",
            value: h_m,
        });
    }
    let h = h_m / p.length_scale_m;
    let nu = p.poisson;
    let layer_settings = LayerSettings {
        tol: tol.max(LAYER_TOL_FLOOR),
        n_max: 512,
        ..Default::default()
    };
    let mut out = match choice {
        ModelChoice::HalfSpace => {
            half_space("half-space asked for (--model half-space)".into(), None)?
        }
        ModelChoice::Layer | ModelChoice::Auto => {
            let mut chosen = None;
            if choice == ModelChoice::Auto {
                let hs = half_space(String::new(), None)?;
                let lambda = hs.roll.dimensionless.lambda;
                let r = h / lambda;
                let s_total = 1.0 + p.terms.iter().map(|t| t.f / t.b).sum::<f64>();
                let memory = p
                    .terms
                    .iter()
                    .filter(|t| t.f / t.b >= 0.01 * s_total)
                    .map(|t| 1.0 / t.b)
                    .fold(lambda, f64::max);
                let e_hs = C_HALF_SPACE * (memory / h).powi(2);
                let e_w = (nu < 0.5).then(|| C_WINKLER * r / (1.0 - 2.0 * nu));
                if e_hs <= tol {
                    let mut hs = hs;
                    hs.reason = format!(
                        "auto: cover/contact length = {r:.3} is thick enough for the half-space \
                         (estimated difference from the layer {e_hs:.1e} ≤ tol {tol:.0e})"
                    );
                    hs.model_error_estimate = Some(e_hs);
                    chosen = Some(hs);
                } else if let Some(e_w) = e_w.filter(|&e| e <= tol) {
                    let w = winkler_at_load(
                        &p.terms,
                        p.load,
                        WinklerColumns::Constrained,
                        h,
                        nu,
                        &LoadSettings::default(),
                    )?;
                    chosen = Some(CoverRoll {
                        roll: p.to_dimensional(scene.load_n_per_m, w.solution),
                        model: BodyModel::WinklerConstrained,
                        reason: format!(
                            "auto: cover/contact length = {r:.3} is thin enough for a Winkler foundation \
                             with the constrained modulus (estimated difference from the layer {e_w:.1e} ≤ tol {tol:.0e})"
                        ),
                        error_estimate: w.error_estimate,
                        model_error_estimate: Some(e_w),
                        cover_over_contact: None,
                        min_pressure_ratio: w.min_pressure_ratio,
                        min_gap_ratio: w.min_gap_ratio,
                        warnings: w.warnings,
                    });
                }
            }
            match chosen {
                Some(c) => c,
                None => {
                    let mut a = layer_at_load(&p.terms, p.load, h, nu, &layer_settings)?;
                    if tol < LAYER_TOL_FLOOR {
                        a.warnings.push(format!(
                            "tolerance not reached: the bonded layer is solved to {LAYER_TOL_FLOOR:.0e} \
                             (estimate {:.1e}), not to tol {tol:.0e} (first-order collocation; finer costs seconds)",
                            a.error_estimate
                        ));
                    }
                    CoverRoll {
                        roll: p.to_dimensional(scene.load_n_per_m, a.solution),
                        model: BodyModel::Layer,
                        reason: if choice == ModelChoice::Auto {
                            "auto: the cover is neither thick nor thin enough for a cheaper body within tol: bonded layer".into()
                        } else {
                            "bonded layer asked for (--model layer)".into()
                        },
                        error_estimate: a.error_estimate,
                        model_error_estimate: None,
                        cover_over_contact: None,
                        min_pressure_ratio: a.min_pressure_ratio,
                        min_gap_ratio: a.min_gap_ratio,
                        warnings: a.warnings,
                    }
                }
            }
        }
        ModelChoice::Winkler => {
            let w = winkler_at_load(
                &p.terms,
                p.load,
                WinklerColumns::Uniaxial,
                h,
                nu,
                &LoadSettings::default(),
            )?;
            CoverRoll {
                roll: p.to_dimensional(scene.load_n_per_m, w.solution),
                model: BodyModel::Winkler,
                reason: "uniaxial Winkler foundation asked for (--model winkler, the conveyor design tools' model)".into(),
                error_estimate: w.error_estimate,
                model_error_estimate: None,
                cover_over_contact: None,
                min_pressure_ratio: w.min_pressure_ratio,
                min_gap_ratio: w.min_gap_ratio,
                warnings: w.warnings,
            }
        }
    };
    let d = &out.roll.dimensionless;
    out.cover_over_contact = Some(h_m / out.roll.contact_length_m);
    let depth_m = d.beta.max(d.lambda - d.beta).powi(2) / (2.0 * p.rho) * p.length_scale_m;
    if depth_m > 0.3 * h_m {
        out.warnings.push(format!(
            "indentation ≈ {:.2} mm is {:.0} % of the {:.2} mm cover (> 30 %): small-strain layer theory loses validity",
            depth_m * 1e3,
            100.0 * depth_m / h_m,
            h_m * 1e3
        ));
    }
    if out.model != BodyModel::HalfSpace {
        push_length_warning(&mut out.warnings, out.roll.contact_length_m, scene.radius_m);
    }
    Ok(out)
}

/// Warn when the contact length exceeds 0.3 R (flat-surface, small-strain assumptions).
pub fn push_length_warning(warnings: &mut Vec<String>, contact_length_m: f64, radius_m: f64) {
    let r = contact_length_m / radius_m;
    if r > 0.3 {
        warnings.push(format!(
            "contact length / radius = {r:.2} > 0.3: the flat-surface, small-strain assumptions lose validity"
        ));
    }
}
