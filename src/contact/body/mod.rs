//! The body the roll rolls on — **the seam where a new body goes**.
//!
//! Input: a [`Body`], the dimensionless problem of a scene ([`DimensionlessScene`]: creep terms, load
//! N′, and the length scale V·T that makes a body's own lengths dimensionless) and the
//! [`ContactSettings`]; output: the [`DimensionlessSolution`] (λ, β, N′, ρF/N, pressure), or a
//! [`ContactError`].
//!
//! One enum, [`Body`], names the body, its model and, for a cover, the choice of model: the
//! viscoelastic half-space of the thesis ([`half_space`]: the three schemes that solve eq. 3.25 on
//! the kernel of eq. 3.19), the bonded layer ([`layer`]), the Winkler foundations ([`winkler`]), and `auto` (the
//! cheapest of them accurate enough, [`Body::auto_choice`]; its reasons and estimates are
//! `contact::cover`'s). The dispatch below resolves `auto` and calls the body's folder.
//!
//! # Adding a body
//! (docs/ARCHITECTURE.md, "Add a contact body", says the same and what is still outside the seam.)
//! 1. one new folder `body/NAME/` with `solve_at_load` (answering a [`BodyAnswer`]) and
//!    `solve_at_lambda` taking the dimensionless problem's parts ([`crate::contact::problem`]), the
//!    body's own dimensionless parameters and the settings, and the conversion of its SI parameters
//!    to dimensionless ones (given the [`DimensionlessScene`]); it imports the ground (`problem`,
//!    `settings`, `error`), `load` and the shared numerics ([`crate::contact::numerics`]), never
//!    another body's folder, this file, `scene` or `cover`;
//! 2. one variant in [`Body`] (its dimensional parameters, SI, with units in the names, e.g.
//!    `Layer { thickness_m }`), with its arms in [`Body::name`] (the serde name too),
//!    [`Body::asked_for`], [`Body::validate`], [`Body::cover_m`], [`Body::with_cover`] and in
//!    [`answer_at_load`] and [`answer_at_lambda`] below, the single dispatch point (lengths go in
//!    units of `problem.length_scale_m`); to be chosen by `auto` or by name, also in
//!    [`Body::auto_choice`] / [`Body::choice`];
//! 3. its tests at the foot of its folder, through [`crate::contact::roll`] where they can.
//!
//! A body for tests only is the same with `#[cfg(test)]` on its `mod`, its variant and each of its
//! arms (an arm of its own: a cfg cannot sit inside an or-pattern); `body/on_springs/` is one, and it
//! took this file and its folder.
//!
//! The scene carries the body (`Scene::body`, serde default = half-space, so existing JSON keeps
//! working), [`crate::contact::roll`] calls the dispatch, and the scheme is chosen by
//! [`crate::contact::Scheme`] inside the body. A scheme a body does not support is refused with
//! [`ContactError::Unsupported`]. The choice of a body for a cover (`auto`) is
//! [`crate::contact::cover`], one file over this dispatch.

pub(crate) mod half_space;
pub(crate) mod layer;
#[cfg(test)]
pub(crate) mod on_springs;
pub(crate) mod winkler;

use super::error::ContactError;
use super::numerics::winkler::WinklerColumns;
use super::problem::{BodyAnswer, CreepTerm, DimensionlessScene, DimensionlessSolution};
use super::settings::ContactSettings;
use serde::{Deserialize, Serialize};

/// What the roll rolls on — the body, its model and, for a cover, the choice of model (dimensional
/// parameters, SI). The one enum for all three: a scene's body (`Scene::body`), the model asked for
/// by name (`--model`, [`Body::choice`]) and the model a cover was solved on
/// (`contact::cover::CoverRoll::model`).
///
/// JSON: `{"kind": "half-space"}`, `{"kind": "layer", "thickness_m": 0.005}`, …; the names are
/// [`Body::name`] (kebab-case, as in CSV tables and on the command line). The old snake-case
/// spellings of scene JSON (`half_space`, `winkler_constrained`) still load.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
#[non_exhaustive]
pub enum Body {
    /// A viscoelastic half-space (thesis ch. 3): kernel eq. 3.19. With `cover_m`, a cover of that
    /// thickness solved as a half-space (a cover thick against the contact; the thickness serves the
    /// validity checks only, `contact::cover`).
    #[serde(alias = "half_space")]
    HalfSpace {
        /// Thickness in m of the cover this half-space stands for (None: no cover).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        cover_m: Option<f64>,
    },
    /// A viscoelastic cover of thickness `thickness_m` bonded to a rigid carcass (plane strain,
    /// `layer`). Every scheme is served at given load by the layer's own error-controlled solver
    /// (`layer::layer_at_load`: spectral to `settings.auto.tol`, the hat collocation for covers
    /// too thin for it); at given λ by the thesis collocation with `settings.n` intervals.
    Layer {
        /// Cover thickness in m (> 0).
        thickness_m: f64,
    },
    /// A Winkler foundation of uniaxial columns of height `height_m` (conveyor design tools;
    /// `winkler`, closed form).
    Winkler {
        /// Column height in m (> 0).
        height_m: f64,
    },
    /// A Winkler foundation of laterally constrained columns (the thin compressible layer's limit).
    #[serde(alias = "winkler_constrained")]
    WinklerConstrained {
        /// Column height in m (> 0).
        height_m: f64,
    },
    /// A cover of thickness `thickness_m` bonded to a rigid carcass, solved on the cheapest body
    /// accurate enough: the half-space, the constrained Winkler foundation or the layer, by the
    /// criterion of [`Body::auto_choice`] (the choice and its reasons: `contact::cover`).
    Auto {
        /// Cover thickness in m (> 0).
        thickness_m: f64,
    },
    /// TEST ONLY: a cover of thickness `thickness_m` on springs of stiffness `stiffness_pa_per_m`
    /// per unit area under it ([`on_springs`]).
    #[cfg(test)]
    OnSprings {
        /// Cover thickness in m (> 0).
        thickness_m: f64,
        /// Springs' stiffness per unit area in Pa/m (> 0).
        stiffness_pa_per_m: f64,
    },
}

impl Default for Body {
    /// The half-space without a cover (also when `body` is absent from scene JSON).
    fn default() -> Self {
        Body::HALF_SPACE
    }
}

/// Half-space law of approach: relative difference from the layer ≤ C_HS·(L/h)² (`contact::cover`'s
/// module doc; the largest measured constant is 2.5 with L = λ, here with L ≥ λ).
pub const C_HALF_SPACE: f64 = 3.0;
/// Thin compressible layer vs constrained Winkler: relative difference ≤ C_W·(h/λ)/(1−2ν). Measured
/// (`contact::cover`'s `tests::criterion_table`, docs/DEVLOG.md) over ν = 0, 0.2, 0.3, 0.45, 0.49 at
/// h/λ ≈ 0.01–1: the ratio difference·(1−2ν)/(h/λ) is 0.35–0.38 at ν = 0, 0.20–0.22 at ν = 0.2,
/// 0.09–0.12 at ν = 0.3 and 0.45, ≤ 0.10 at ν = 0.49; one constant for all ν, the largest measured with
/// a little margin. At ν = 0.49 the spectral solver reaches the linear range
/// (`tests::criterion_nu049`: C → 0.11 below h/λ ≈ 0.04, down to h/λ = 0.009), so the rule holds there
/// with a margin of 3.6.
pub const C_WINKLER: f64 = 0.4;

impl Body {
    /// The half-space without a cover.
    pub const HALF_SPACE: Body = Body::HalfSpace { cover_m: None };

    /// Name in JSON, CSV tables, messages and on the command line.
    pub fn name(&self) -> &'static str {
        match self {
            Body::HalfSpace { .. } => "half-space",
            Body::Layer { .. } => "layer",
            Body::Winkler { .. } => "winkler",
            Body::WinklerConstrained { .. } => "winkler-constrained",
            Body::Auto { .. } => "auto",
            #[cfg(test)]
            Body::OnSprings { .. } => "on-springs",
        }
    }

    /// The body asked for by `name` (`auto|half-space|layer|winkler`, `--model`) on a cover of
    /// `cover_m` (None: no cover): `Ok(None)` for an unknown name; without a cover `auto` and
    /// `half-space` are the half-space, and the layer and Winkler bodies are refused.
    pub fn choice(name: &str, cover_m: Option<f64>) -> Result<Option<Body>, ContactError> {
        let needs_cover = || {
            ContactError::Unsupported(
                "the layer and Winkler bodies need a cover thickness (--cover-mm / cover_thickness_mm)"
                    .into(),
            )
        };
        Ok(Some(match (name, cover_m) {
            ("auto", Some(h)) => Body::Auto { thickness_m: h },
            ("auto" | "half-space", None) => Body::HALF_SPACE,
            ("half-space", Some(h)) => Body::HalfSpace { cover_m: Some(h) },
            ("layer", Some(h)) => Body::Layer { thickness_m: h },
            ("winkler", Some(h)) => Body::Winkler { height_m: h },
            ("layer" | "winkler", None) => return Err(needs_cover()),
            _ => return Ok(None),
        }))
    }

    /// Why this body was solved when asked for by name (the reason line of `contact::cover`'s answer
    /// and the datasheet); `None` for `auto`, whose reason depends on the answer.
    pub fn asked_for(&self) -> Option<String> {
        Some(match self {
            Body::HalfSpace { .. } => "half-space asked for (--model half-space)".into(),
            Body::Layer { .. } => "bonded layer asked for (--model layer)".into(),
            Body::Winkler { .. } => {
                "uniaxial Winkler foundation asked for (--model winkler, the conveyor \
                                     design tools' model)"
                    .into()
            }
            Body::WinklerConstrained { .. } => "constrained Winkler foundation asked for".into(),
            Body::Auto { .. } => return None,
            #[cfg(test)]
            Body::OnSprings { .. } => "cover on springs asked for".into(),
        })
    }

    /// Why `auto` chose this body for a cover of `cover_over_contact` half-space contact lengths,
    /// its estimated difference from the layer `estimate` being within `tol` (the reason line of
    /// `contact::cover`'s answer): `auto` chooses the half-space for thick covers and the
    /// constrained Winkler foundation for thin ones ([`Body::auto_choice`]).
    pub fn auto_reason(&self, cover_over_contact: f64, estimate: f64, tol: f64) -> String {
        let (r, e) = (cover_over_contact, estimate);
        match self {
            Body::HalfSpace { .. } => format!(
                "auto: cover/contact length = {r:.3} is thick enough for the half-space \
                 (estimated difference from the layer {e:.1e} ≤ tol {tol:.0e})"
            ),
            _ => format!(
                "auto: cover/contact length = {r:.3} is thin enough for a Winkler foundation \
                 with the constrained modulus (estimated difference from the layer {e:.1e} ≤ tol {tol:.0e})"
            ),
        }
    }

    /// Whether the body is the half-space (on a cover or not): its validity limit is its own
    /// (the parabolic roll profile, checked by `contact::roll`), not a cover's.
    pub fn is_half_space(&self) -> bool {
        matches!(self, Body::HalfSpace { .. })
    }

    /// The thickness in m of the cover the body stands for (None: a half-space without a cover).
    pub fn cover_m(&self) -> Option<f64> {
        match *self {
            Body::HalfSpace { cover_m } => cover_m,
            Body::Layer { thickness_m } | Body::Auto { thickness_m } => Some(thickness_m),
            Body::Winkler { height_m } | Body::WinklerConstrained { height_m } => Some(height_m),
            #[cfg(test)]
            Body::OnSprings { thickness_m, .. } => Some(thickness_m),
        }
    }

    /// The same kind of body on a cover of `cover_m` (the half-space keeps `cover_m` for its checks).
    pub fn with_cover(&self, cover_m: f64) -> Body {
        match self {
            Body::HalfSpace { .. } => Body::HalfSpace {
                cover_m: Some(cover_m),
            },
            Body::Layer { .. } => Body::Layer {
                thickness_m: cover_m,
            },
            Body::Winkler { .. } => Body::Winkler { height_m: cover_m },
            Body::WinklerConstrained { .. } => Body::WinklerConstrained { height_m: cover_m },
            Body::Auto { .. } => Body::Auto {
                thickness_m: cover_m,
            },
            #[cfg(test)]
            Body::OnSprings {
                stiffness_pa_per_m, ..
            } => Body::OnSprings {
                thickness_m: cover_m,
                stiffness_pa_per_m: *stiffness_pa_per_m,
            },
        }
    }

    /// Check the body's own parameters (finite, in range).
    pub fn validate(&self) -> Result<(), ContactError> {
        match self {
            Body::HalfSpace { cover_m: None } => Ok(()),
            Body::HalfSpace { cover_m: Some(h) }
            | Body::Layer { thickness_m: h }
            | Body::Auto { thickness_m: h }
            | Body::Winkler { height_m: h }
            | Body::WinklerConstrained { height_m: h } => {
                super::error::positive("body thickness in m", *h).map(|_| ())
            }
            #[cfg(test)]
            Body::OnSprings {
                thickness_m,
                stiffness_pa_per_m,
            } => {
                super::error::positive("body thickness in m", *thickness_m)?;
                super::error::positive("spring stiffness in Pa/m", *stiffness_pa_per_m).map(|_| ())
            }
        }
    }

    /// The `auto` criterion (`contact::cover`'s module doc): given the half-space contact length
    /// `lambda`, the cover h′ = `thickness` (in units of V·T) and ν, the cheaper body within `tol` of
    /// the layer (on a cover of h′) and its estimated difference from the layer, or `None` (solve the
    /// layer).
    pub fn auto_choice(
        terms: &[CreepTerm],
        lambda: f64,
        thickness: f64,
        poisson: f64,
        tol: f64,
    ) -> Option<(Body, f64)> {
        let s_total = 1.0 + terms.iter().map(|t| t.f / t.b).sum::<f64>();
        let memory = terms
            .iter()
            .filter(|t| t.f / t.b >= 0.01 * s_total)
            .map(|t| 1.0 / t.b)
            .fold(lambda, f64::max);
        let e_hs = C_HALF_SPACE * (memory / thickness).powi(2);
        let e_w = (poisson < 0.5).then(|| C_WINKLER * (thickness / lambda) / (1.0 - 2.0 * poisson));
        if e_hs <= tol {
            Some((
                Body::HalfSpace {
                    cover_m: Some(thickness),
                },
                e_hs,
            ))
        } else {
            e_w.filter(|&e| e <= tol).map(|e| {
                (
                    Body::WinklerConstrained {
                        height_m: thickness,
                    },
                    e,
                )
            })
        }
    }
}

/// How a body with a load loop of its own (the bonded layer) is started and closed; the other
/// bodies ignore it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Warm {
    /// Start of the load loop (λ guess in units of `problem.length_scale_m`, d ln N′/d ln λ), e.g. a
    /// neighbouring problem's answer; `None`: the solver's closed-form start. The answer does not
    /// depend on it beyond the load loop's stopping tolerance.
    pub start: Option<(f64, f64)>,
    /// Run the closing contact checks (the same answer; without them the check ratios are NaN and no
    /// check warning is raised).
    pub checks: bool,
}

impl Default for Warm {
    /// A cold start, with the checks.
    fn default() -> Self {
        Warm {
            start: None,
            checks: true,
        }
    }
}

/// A body's answer at given load and the body that gave it.
#[derive(Debug, Clone, PartialEq)]
pub struct Solved {
    /// The body solved (never [`Body::Auto`]: the one `auto` chose, on the same cover).
    pub body: Body,
    /// Its solution, error estimate, contact checks and warnings.
    pub answer: BodyAnswer,
    /// When `auto` chose a cheaper body than the layer: why.
    pub auto: Option<AutoPick>,
}

/// Why `auto` chose a cheaper body than the layer ([`Body::auto_choice`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AutoPick {
    /// The estimated relative difference of the body chosen from the layer.
    pub model_error_estimate: f64,
    /// The contact length λ the criterion was applied at (units of V·T): at given load the
    /// half-space's, at given λ the λ given.
    pub lambda_half_space: f64,
}

/// Solve the dimensionless problem of a scene on `body` at its load `problem.load`.
pub fn solve_at_load(
    body: &Body,
    problem: &DimensionlessScene,
    settings: &ContactSettings,
) -> Result<DimensionlessSolution, ContactError> {
    answer_at_load(body, problem, settings, Warm::default()).map(|s| s.answer.solution)
}

/// [`solve_at_load`] with the body's error estimate, checks and warnings, the body solved (`auto`
/// resolved) and a warm start: the single dispatch at given load. The bonded layer is solved to
/// `settings.auto.tol` (its hat fallback to at least [`layer::LAYER_TOL_FLOOR`]), the Winkler
/// foundations by the load loop `settings.load`, the half-space by the scheme of `settings`.
pub fn answer_at_load(
    body: &Body,
    problem: &DimensionlessScene,
    settings: &ContactSettings,
    warm: Warm,
) -> Result<Solved, ContactError> {
    body.validate()?;
    let solved = |answer| Solved {
        body: *body,
        answer,
        auto: None,
    };
    let (terms, load, nu) = (&problem.terms, problem.load, problem.poisson);
    match *body {
        Body::HalfSpace { .. } => Ok(solved(BodyAnswer::from_solution(
            half_space::solve_at_load(terms, load, settings)?,
        ))),
        Body::Auto { thickness_m } => {
            let hs = answer_at_load(&Body::HALF_SPACE, problem, settings, warm)?.answer;
            let lambda = hs.solution.lambda;
            let (chosen, estimate) = auto_at(problem, thickness_m, lambda, settings);
            let mut s = match chosen {
                Body::HalfSpace { .. } => solved(hs),
                _ => answer_at_load(&chosen, problem, settings, warm)?,
            };
            s.body = chosen;
            s.auto = estimate.map(|e| AutoPick {
                model_error_estimate: e,
                lambda_half_space: lambda,
            });
            Ok(s)
        }
        Body::Layer { thickness_m } => layer::layer_at_load(
            terms,
            load,
            thickness_m / problem.length_scale_m,
            nu,
            &layer::LayerSettings {
                tol: settings.auto.tol,
                n_max: 512,
                start: warm.start,
                checks: warm.checks,
                ..Default::default()
            },
        )
        .map(solved),
        Body::Winkler { height_m } | Body::WinklerConstrained { height_m } => {
            winkler::answer_at_load(problem, winkler_columns(body), height_m, &settings.load)
                .map(solved)
        }
        #[cfg(test)]
        Body::OnSprings {
            thickness_m,
            stiffness_pa_per_m,
        } => on_springs::solve_at_load(
            terms,
            load,
            thickness_m / problem.length_scale_m,
            on_springs::compliance(problem, stiffness_pa_per_m),
            nu,
            &settings.load,
        )
        .map(solved),
    }
}

/// Solve the dimensionless problem of a scene on `body` at contact length λ (in units of V·T).
#[cfg(test)]
pub fn solve_at_lambda(
    body: &Body,
    problem: &DimensionlessScene,
    lambda: f64,
    settings: &ContactSettings,
) -> Result<DimensionlessSolution, ContactError> {
    answer_at_lambda(body, problem, lambda, settings).map(|s| s.answer.solution)
}

/// [`solve_at_lambda`] with the body's error estimate, checks and warnings and the body solved
/// (`auto` resolved by its criterion at the given λ and `settings.auto.tol`): the single dispatch at
/// given λ. The half-space by the scheme of `settings`; the bonded layer by the hat collocation with
/// `settings.n` intervals, its error estimated from the same solve at n/2
/// ([`layer::collocation::answer_at_lambda`]); the Winkler foundations in closed form.
pub fn answer_at_lambda(
    body: &Body,
    problem: &DimensionlessScene,
    lambda: f64,
    settings: &ContactSettings,
) -> Result<Solved, ContactError> {
    body.validate()?;
    let solved = |answer| Solved {
        body: *body,
        answer,
        auto: None,
    };
    let (terms, nu) = (&problem.terms, problem.poisson);
    match *body {
        Body::HalfSpace { .. } => Ok(solved(BodyAnswer::from_solution(
            half_space::solve_at_lambda(terms, lambda, settings)?,
        ))),
        Body::Auto { thickness_m } => {
            let (chosen, estimate) = auto_at(problem, thickness_m, lambda, settings);
            let mut s = answer_at_lambda(&chosen, problem, lambda, settings)?;
            s.auto = estimate.map(|e| AutoPick {
                model_error_estimate: e,
                lambda_half_space: lambda,
            });
            Ok(s)
        }
        Body::Layer { thickness_m } => {
            let k = layer::LayerKernel::new(terms, thickness_m / problem.length_scale_m, nu)?;
            layer::collocation::answer_at_lambda(&k, lambda, settings.n).map(solved)
        }
        Body::Winkler { height_m } | Body::WinklerConstrained { height_m } => {
            winkler::answer_at_lambda(problem, winkler_columns(body), height_m, lambda).map(solved)
        }
        #[cfg(test)]
        Body::OnSprings {
            thickness_m,
            stiffness_pa_per_m,
        } => on_springs::solve_at_lambda(
            terms,
            lambda,
            thickness_m / problem.length_scale_m,
            on_springs::compliance(problem, stiffness_pa_per_m),
            nu,
        )
        .map(|sol| solved(BodyAnswer::from_solution(sol))),
    }
}

/// The body `auto` chooses on a cover of `thickness_m` ([`Body::auto_choice`] at `settings.auto.tol`)
/// given the half-space contact length `lambda_hs` (in units of V·T): the half-space or the
/// constrained Winkler foundation on the cover with its estimated difference from the layer, else
/// the layer (`None`).
fn auto_at(
    problem: &DimensionlessScene,
    thickness_m: f64,
    lambda_hs: f64,
    settings: &ContactSettings,
) -> (Body, Option<f64>) {
    let h = thickness_m / problem.length_scale_m;
    match Body::auto_choice(
        &problem.terms,
        lambda_hs,
        h,
        problem.poisson,
        settings.auto.tol,
    ) {
        Some((chosen, e)) => (chosen.with_cover(thickness_m), Some(e)),
        None => (Body::Layer { thickness_m }, None),
    }
}

/// The columns of a Winkler body.
fn winkler_columns(body: &Body) -> WinklerColumns {
    match body {
        Body::WinklerConstrained { .. } => WinklerColumns::Constrained,
        _ => WinklerColumns::Uniaxial,
    }
}

#[cfg(test)]
mod tests {
    //! The dispatch arms of [`super::solve_at_load`] and [`super::solve_at_lambda`] for the layer and
    //! Winkler bodies, against the layer functions they must call: the body's thickness in metres is
    //! divided by the scene's length scale V·T (here 2.5e−3 m, so a missing or inverted division changes
    //! h′ by a factor 6 or more), the layer's tolerance is the scene's `auto.tol` (the spectral solver;
    //! `layer_at_load` floors only its hat fallback), at given λ the layer uses `settings.n` intervals,
    //! and the two Winkler bodies keep their columns apart. The same inputs give bit-identical results, so equality is exact.

    use super::layer::{collocation, layer_at_load, LayerKernel, LayerSettings};
    use super::{solve_at_lambda, solve_at_load, Body};
    use crate::contact::load::LoadSettings;
    use crate::contact::numerics::winkler::{winkler_coefficient, Winkler, WinklerColumns};
    use crate::contact::{ContactSettings, CreepTerm, DimensionlessScene};

    const LENGTH_SCALE_M: f64 = 2.5e-3;

    fn problem(poisson: f64) -> DimensionlessScene {
        DimensionlessScene {
            terms: vec![CreepTerm { f: 10.0, b: 1.0 }, CreepTerm { f: 0.5, b: 0.05 }],
            load: 0.25,
            rho: 40.0,
            time_scale_s: 1e-3,
            length_scale_m: LENGTH_SCALE_M,
            pressure_scale_pa: 1e6,
            poisson,
            compliance_factor_per_pa: 1e-6,
        }
    }

    #[test]
    fn layer_arm_at_load_calls_the_layer_with_h_over_vt_and_the_scene_tol() {
        let p = problem(0.5);
        let h_m = 1.5e-3; // h′ = 0.6
        let body = Body::Layer { thickness_m: h_m };
        for tol in [1e-3, 1e-6] {
            let got = solve_at_load(&body, &p, &ContactSettings::auto(tol)).unwrap();
            let want = layer_at_load(
                &p.terms,
                p.load,
                h_m / LENGTH_SCALE_M,
                p.poisson,
                &LayerSettings {
                    tol,
                    n_max: 512,
                    ..Default::default()
                },
            )
            .unwrap();
            assert_eq!(got, want.solution, "tol {tol}");
            assert_eq!(got.scheme, "layer-spectral");
            // and it is not the half-space's answer (the cover matters at h′ = 0.6)
            let hs = solve_at_load(&Body::HALF_SPACE, &p, &ContactSettings::auto(tol)).unwrap();
            assert!((hs.lambda - got.lambda).abs() > 0.1 * got.lambda);
        }
    }

    #[test]
    fn layer_arm_at_lambda_uses_the_collocation_with_settings_n() {
        let p = problem(0.3);
        let h_m = 1e-3;
        let body = Body::Layer { thickness_m: h_m };
        let settings = ContactSettings {
            n: 48,
            ..ContactSettings::default()
        };
        let got = solve_at_lambda(&body, &p, 0.8, &settings).unwrap();
        let k = LayerKernel::new(&p.terms, h_m / LENGTH_SCALE_M, 0.3).unwrap();
        let want = collocation::solve_at_lambda(&k, 0.8, 48).unwrap();
        assert_eq!(got, want);
        assert_eq!(got.n, 48);
    }

    #[test]
    fn winkler_arms_keep_their_columns() {
        let p = problem(0.3);
        let h_m = 5e-4; // h′ = 0.2
        let h = h_m / LENGTH_SCALE_M;
        let settings = ContactSettings::default();
        let mut answers = Vec::new();
        for (body, columns) in [
            (Body::Winkler { height_m: h_m }, WinklerColumns::Uniaxial),
            (
                Body::WinklerConstrained { height_m: h_m },
                WinklerColumns::Constrained,
            ),
        ] {
            let got = solve_at_load(&body, &p, &settings).unwrap();
            let foundation =
                Winkler::with_coefficient(&p.terms, winkler_coefficient(columns, h, 0.3).unwrap());
            let want = foundation
                .at_load(p.load, &LoadSettings::default())
                .unwrap()
                .into_body_answer();
            assert_eq!(got, want.solution, "{body:?}");
            let at = solve_at_lambda(&body, &p, 0.7, &settings).unwrap();
            let want_at = foundation
                .at_lambda(0.7)
                .unwrap()
                .into_body_answer()
                .solution;
            assert_eq!(at, want_at, "{body:?}");
            answers.push(got.lambda);
        }
        // uniaxial columns (E = 2μ(1+ν)) are softer than constrained ones (M = 2μ(1−ν)/(1−2ν)) at ν = 0.3:
        // E/M = (1+ν)(1−2ν)/(1−ν) = 0.74, so the uniaxial contact is longer, by (M/E)^{1/3} ≈ 1.1 elastically
        assert!(answers[0] > 1.05 * answers[1], "{answers:?}");
    }

    #[test]
    fn bodies_refuse_bad_thickness_and_the_rigid_constrained_winkler() {
        let p = problem(0.5);
        let s = ContactSettings::default();
        for body in [
            Body::Layer { thickness_m: 0.0 },
            Body::Winkler { height_m: -1.0 },
            Body::WinklerConstrained { height_m: f64::NAN },
        ] {
            assert!(solve_at_load(&body, &p, &s).is_err(), "{body:?}");
            assert!(solve_at_lambda(&body, &p, 1.0, &s).is_err(), "{body:?}");
        }
        // constrained columns are rigid at ν = ½: refused, not solved
        let e = solve_at_load(&Body::WinklerConstrained { height_m: 1e-3 }, &p, &s);
        assert!(e.is_err());
    }

    #[test]
    fn one_spelling_and_the_old_ones_still_load() {
        // the names written are `Body::name` (kebab-case, as in CSV and on the command line) …
        let all = [
            Body::HALF_SPACE,
            Body::HalfSpace {
                cover_m: Some(4e-3),
            },
            Body::Layer { thickness_m: 5e-3 },
            Body::Winkler { height_m: 2e-3 },
            Body::WinklerConstrained { height_m: 2e-3 },
            Body::Auto { thickness_m: 6e-3 },
        ];
        for body in all {
            let v = serde_json::to_value(body).unwrap();
            assert_eq!(v["kind"], body.name(), "{v}");
            assert_eq!(serde_json::from_value::<Body>(v).unwrap(), body);
        }
        assert_eq!(
            serde_json::to_string(&Body::HALF_SPACE).unwrap(),
            r#"{"kind":"half-space"}"#
        );
        // … and the snake-case spellings of older scene files load as the same bodies
        let old: Body = serde_json::from_str(r#"{"kind": "half_space"}"#).unwrap();
        assert_eq!(old, Body::HALF_SPACE);
        let old: Body =
            serde_json::from_str(r#"{"kind": "winkler_constrained", "height_m": 0.002}"#).unwrap();
        assert_eq!(old, Body::WinklerConstrained { height_m: 2e-3 });
        // a scene without `body` is on the half-space
        let scene: crate::contact::Scene =
            serde_json::from_str(r#"{"radius_m": 0.1, "load_n_per_m": 1000.0, "speed_m_s": 1.0}"#)
                .unwrap();
        assert_eq!(scene.body, Body::HALF_SPACE);
        let scene: crate::contact::Scene = serde_json::from_str(
            r#"{"radius_m": 0.1, "load_n_per_m": 1000.0, "speed_m_s": 1.0, "body": {"kind": "half_space"}}"#,
        )
        .unwrap();
        assert_eq!(scene.body, Body::HALF_SPACE);
    }

    #[test]
    fn the_choice_by_name_puts_the_body_on_the_cover() {
        let h = Some(5e-3);
        assert_eq!(
            Body::choice("auto", h).unwrap(),
            Some(Body::Auto { thickness_m: 5e-3 })
        );
        assert_eq!(
            Body::choice("layer", h).unwrap(),
            Some(Body::Layer { thickness_m: 5e-3 })
        );
        assert_eq!(
            Body::choice("half-space", h).unwrap(),
            Some(Body::HalfSpace { cover_m: h })
        );
        assert_eq!(
            Body::choice("winkler", h).unwrap(),
            Some(Body::Winkler { height_m: 5e-3 })
        );
        assert_eq!(Body::choice("auto", None).unwrap(), Some(Body::HALF_SPACE));
        assert_eq!(
            Body::choice("half-space", None).unwrap(),
            Some(Body::HALF_SPACE)
        );
        assert!(Body::choice("layer", None).is_err());
        assert!(Body::choice("winkler", None).is_err());
        assert_eq!(Body::choice("half_spacey", h).unwrap(), None);
        for b in [
            Body::HALF_SPACE,
            Body::Layer { thickness_m: 1.0 },
            Body::Auto { thickness_m: 1.0 },
        ] {
            assert_eq!(b.with_cover(2.0).cover_m(), Some(2.0));
            assert_eq!(b.with_cover(2.0).name(), b.name());
        }
    }

    #[test]
    fn auto_at_given_load_is_the_body_the_criterion_names() {
        // through the dispatch: `auto` on a thick cover is the half-space, on a thin compressible one
        // the constrained Winkler foundation, in between the layer (each bit-identical to the
        // dispatch on that body)
        let p = problem(0.3);
        let s = ContactSettings::auto(1e-3);
        let hs = solve_at_load(&Body::HALF_SPACE, &p, &s).unwrap();
        for h_m in [
            1e-4 * LENGTH_SCALE_M,
            0.5 * LENGTH_SCALE_M,
            1e4 * LENGTH_SCALE_M,
        ] {
            let want =
                match Body::auto_choice(&p.terms, hs.lambda, h_m / LENGTH_SCALE_M, p.poisson, 1e-3)
                {
                    Some((b, _)) => b.with_cover(h_m),
                    None => Body::Layer { thickness_m: h_m },
                };
            let got = solve_at_load(&Body::Auto { thickness_m: h_m }, &p, &s).unwrap();
            assert_eq!(got, solve_at_load(&want, &p, &s).unwrap(), "{want:?}");
        }
        let thick = Body::auto_choice(&p.terms, hs.lambda, 1e4, 0.3, 1e-3);
        assert!(
            matches!(thick, Some((Body::HalfSpace { .. }, _))),
            "{thick:?}"
        );
        let thin = Body::auto_choice(&p.terms, hs.lambda, 1e-4, 0.3, 1e-3);
        assert!(
            matches!(thin, Some((Body::WinklerConstrained { .. }, _))),
            "{thin:?}"
        );
        assert_eq!(Body::auto_choice(&p.terms, hs.lambda, 0.5, 0.3, 1e-3), None);
    }
}
