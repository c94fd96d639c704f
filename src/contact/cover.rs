//! A dimensional scene on a covered roll track: the body chosen (half-space, bonded layer, Winkler) and
//! solved, in SI units, with the validity warnings of issue 14.
//!
//! Input: [`Scene`] (its [`Body`]: the cover's thickness and the model asked for, `auto` the
//! cheapest accurate enough) and [`CreepSpectrum`]; output: [`CoverRoll`] (the [`RollSolution`] of the body solved, which body and
//! why, its error estimate and, when `auto` chose a cheaper body than the layer, the estimated
//! difference from the layer's answer).
//!
//! `auto` ([`Body::auto_choice`], criterion measured in `tests::criterion_table`, table in docs/DEVLOG.md): with λ the half-space
//! contact length (solved first, it is cheap), L = max(λ, 1/bᵢ over the modes holding ≥ 1 % of the
//! compliance, rᵢ = fᵢ/bᵢ ≥ 0.01·S) the longest length the body's memory reaches, and h′ the cover,
//! - when the half-space law [`C_HALF_SPACE`]·(L/h′)² ≤ tol: the half-space (measured: relative
//!   differences of λ ≈ 0.13(λ/h)², of ρF/N ≈ 0.5(λ/h)² for one term and 2.5(λ/h)² for the example
//!   spectrum, whose slowest strong mode reaches 1.5λ; a mode with memory longer than h makes the
//!   approach slower than quadratic, which the max(λ, 1/b) covers conservatively);
//! - when ν < ½ and the thin-layer law [`C_WINKLER`]·(h′/λ)/(1−2ν) ≤ tol: the constrained Winkler
//!   foundation (measured at ν = 0, 0.2, 0.3, 0.45, 0.49: λ differs by ≈ C(ν)·(h/λ)/(1−2ν) with
//!   C(ν) = 0.38, 0.22, 0.12, 0.10, ≤ 0.10, ρF/N by less; the rule takes the largest);
//! - otherwise the layer, to tol (the spectral solver; the hat collocation, to max(tol,
//!   [`LAYER_TOL_FLOOR`]), only for covers too thin for it, with a warning).
//!
//! Validity: the contact length should stay below about 0.3R (small strains, flat surface); the
//! indentation, estimated as the roll's depth below the higher contact edge, max(β, λ−β)²/(2ρ)·VT
//! (a lower bound of the true one), below about 30 % of the cover.

use crate::contact::body::{self, Warm};
use crate::contact::error::{positive, ContactError};
use crate::contact::problem::{BodyAnswer, CreepTerm, DimensionlessScene};
use crate::contact::scene::{RollSolution, Scene};
use crate::contact::{roll, Body, ContactSettings};
use crate::CreepSpectrum;

/// A scene's answer on the chosen body.
#[derive(Debug, Clone, PartialEq)]
pub struct CoverRoll {
    /// SI answer (friction, contact length, offset, pressure) and the dimensionless problem.
    pub roll: RollSolution,
    /// The body solved (on the scene's cover; never [`Body::Auto`]).
    pub model: Body,
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

/// A dimensionless answer on the body chosen (the core of [`roll_cover`], used by `viscoroll contact`).
#[derive(Debug, Clone, PartialEq)]
pub struct CoverAnswer {
    /// The body solved (lengths in units of V·T, as given; never [`Body::Auto`]).
    pub model: Body,
    /// Its solution, error estimate, contact checks and solver warnings.
    pub answer: BodyAnswer,
    /// Why this body (one line for the datasheet).
    pub reason: String,
    /// When `auto` chose a cheaper body than the layer: the estimated relative difference from it.
    pub model_error_estimate: Option<f64>,
}

/// Solve the dimensionless problem (creep terms, load N′) on the cover `body` (its lengths in units
/// of V·T: the thickness is h′ = h/(VT); `auto` the cheapest body accurate enough), to `tol` (module
/// doc: the layer's hat fallback to at least [`LAYER_TOL_FLOOR`]).
pub fn solve_cover(
    terms: &[CreepTerm],
    load: f64,
    poisson: f64,
    body: &Body,
    tol: f64,
) -> Result<CoverAnswer, ContactError> {
    solve_cover_with(terms, load, poisson, body, tol, Warm::default())
}

/// [`solve_cover`] with the bonded layer's load loop started from `warm.start` = (λ guess,
/// d ln N′/d ln λ), e.g. a nearby problem's answer, and its closing contact checks run or not
/// (`warm.checks`); [`Warm`]: the answer does not depend on either.
pub fn solve_cover_with(
    terms: &[CreepTerm],
    load: f64,
    poisson: f64,
    body: &Body,
    tol: f64,
    warm: Warm,
) -> Result<CoverAnswer, ContactError> {
    let problem = DimensionlessScene::in_units_of_vt(terms.to_vec(), load, poisson);
    cover_answer(&problem, body, tol, warm)
}

/// The cover's thickness of `body` (in units of V·T when the body's are), checked.
fn cover_of(body: &Body) -> Result<f64, ContactError> {
    positive("cover thickness h/(VT)", body.cover_m().unwrap_or(f64::NAN))
}

/// Solve `problem` on the cover `body` (lengths in units of `problem.length_scale_m`) through the body
/// dispatch ([`body::answer_at_load`], the half-space by the `auto` scheme at `tol`) and say why this
/// body; the model is in the units of the body given.
fn cover_answer(
    problem: &DimensionlessScene,
    body: &Body,
    tol: f64,
    warm: Warm,
) -> Result<CoverAnswer, ContactError> {
    let h = cover_of(body)? / problem.length_scale_m;
    let solved = body::answer_at_load(body, problem, &ContactSettings::auto(tol), warm)?;
    let reason = match (body.asked_for(), solved.auto) {
        (Some(reason), _) => reason,
        (None, Some(pick)) => {
            let r = h / pick.lambda_half_space;
            solved.body.auto_reason(r, pick.model_error_estimate, tol)
        }
        (None, None) => AUTO_LAYER.into(),
    };
    Ok(CoverAnswer {
        model: solved.body,
        answer: solved.answer,
        reason,
        model_error_estimate: solved.auto.map(|a| a.model_error_estimate),
    })
}

/// Why `auto` solved the layer.
const AUTO_LAYER: &str =
    "auto: the cover is neither thick nor thin enough for a cheaper body within tol: bonded layer";

/// Solve the dimensionless problem at given contact length λ on the cover `body` (lengths in units
/// of V·T; `viscoroll contact --cover --lambda`) through the body dispatch
/// ([`body::answer_at_lambda`]: the half-space by the scheme of `settings`, the bonded layer by the
/// hat collocation with `settings.n` intervals and its estimate from n/2, the Winkler foundations in
/// closed form) and say why this body; `auto` applies the criterion of [`Body::auto_choice`] at the
/// given λ with `settings.auto.tol`.
pub fn solve_cover_at_lambda(
    terms: &[CreepTerm],
    lambda: f64,
    poisson: f64,
    body: &Body,
    settings: &ContactSettings,
) -> Result<CoverAnswer, ContactError> {
    let h = cover_of(body)?;
    let problem = DimensionlessScene::in_units_of_vt(terms.to_vec(), f64::NAN, poisson);
    let solved = body::answer_at_lambda(body, &problem, lambda, settings)?;
    let reason = match (body.asked_for(), solved.auto) {
        (Some(reason), _) => reason,
        (None, Some(pick)) => format!(
            "auto: cover/contact length = {:.3}: {} within tol {:.0e} of the layer (estimated difference {:.1e})",
            h / lambda,
            solved.body.name(),
            settings.auto.tol,
            pick.model_error_estimate
        ),
        (None, None) => AUTO_LAYER.into(),
    };
    Ok(CoverAnswer {
        model: solved.body,
        answer: solved.answer,
        reason,
        model_error_estimate: solved.auto.map(|a| a.model_error_estimate),
    })
}

/// Solve `scene` on its body (`scene.body`: a half-space without a cover, or a cover and the model
/// asked for, `auto` the cheapest accurate enough) to `tol`.
pub fn roll_cover(
    scene: &Scene,
    spectrum: &CreepSpectrum,
    tol: f64,
) -> Result<CoverRoll, ContactError> {
    roll_cover_from(scene, spectrum, tol, None)
}

/// [`roll_cover`] with the layer solve started from `start` = (contact length in m, d ln N′/d ln λ),
/// e.g. the answer of a nearby spectrum on the same scene ([`Warm`]; the length is made
/// dimensionless by this spectrum's own scale VT).
pub fn roll_cover_from(
    scene: &Scene,
    spectrum: &CreepSpectrum,
    tol: f64,
    start: Option<(f64, f64)>,
) -> Result<CoverRoll, ContactError> {
    let p = scene.dimensionless(spectrum)?;
    let Some(h_m) = scene.body.cover_m() else {
        let r = roll(scene, spectrum, &ContactSettings::auto(tol))?;
        let diag = r.dimensionless.diagnostics.clone();
        return Ok(CoverRoll {
            error_estimate: r.dimensionless.error_estimate.unwrap_or(f64::NAN),
            model: Body::HALF_SPACE,
            reason: "no cover given: half-space".into(),
            model_error_estimate: None,
            cover_over_contact: None,
            min_pressure_ratio: diag.as_ref().map_or(f64::NAN, |d| d.min_pressure_ratio),
            min_gap_ratio: diag.as_ref().map_or(f64::NAN, |d| d.min_gap_ratio),
            warnings: r.dimensionless.warnings.clone(),
            roll: r,
        });
    };
    if !(h_m.is_finite() && h_m > 0.0) {
        return Err(ContactError::BadValue {
            field: "cover thickness in m".into(),
            expected: "finite and > 0",
            value: h_m,
        });
    }
    let start = start.map(|(l_m, slope)| (l_m / p.length_scale_m, slope));
    let warm = Warm {
        start,
        checks: true,
    };
    let c = cover_answer(&p, &scene.body, tol, warm)?;
    let a = c.answer;
    let model = c.model;
    let mut warnings = a.warnings;
    let mut roll = p.to_dimensional(scene.load_n_per_m, a.solution);
    if model.is_half_space() {
        // the half-space's own validity check, as `contact::roll` makes it
        let l_over_r = roll.contact_length_m / scene.radius_m;
        if l_over_r > 0.126 {
            let w = format!(
                "contact length / radius = {l_over_r:.3}: the parabolic roll profile (eq. 3.22) is off by \
                 more than 0.1 % at the contact ends; results lose validity"
            );
            roll.dimensionless.warnings.push(w.clone());
            warnings.push(w);
        }
    }
    let mut out = CoverRoll {
        roll,
        model,
        reason: c.reason,
        error_estimate: a.error_estimate,
        model_error_estimate: c.model_error_estimate,
        cover_over_contact: None,
        min_pressure_ratio: a.min_pressure_ratio,
        min_gap_ratio: a.min_gap_ratio,
        warnings,
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
    if !out.model.is_half_space() {
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
