//! The body the roll rolls on — **the seam where a new body goes**.
//!
//! Input: a [`Body`], the dimensionless problem of a scene ([`DimensionlessScene`]: creep terms, load
//! N′, and the length scale V·T that makes a body's own lengths dimensionless) and the
//! [`ContactSettings`]; output: the [`DimensionlessSolution`] (λ, β, N′, ρF/N, pressure), or a
//! [`ContactError`].
//!
//! Today there is one body, the viscoelastic half-space of the thesis ([`half_space`]: its kernel,
//! eq. 3.19, the three schemes that solve eq. 3.25 on it, and everything they hard-wire about it).
//!
//! # Adding a body
//! (docs/ARCHITECTURE.md, "Add a contact body", says the same and what is still outside the seam.)
//! 1. one new folder `body/NAME/` with `solve_at_load` and `solve_at_lambda` taking the
//!    dimensionless problem ([`crate::contact::problem`]), the body's own (dimensionless) parameters
//!    and the settings; it imports the ground (`problem`, `settings`, `error`), `load` and shared
//!    numerics, never this file, `scene` or `cover`;
//! 2. one variant in [`Body`] (its dimensional parameters, SI, with units in the names, e.g.
//!    `Layer { thickness_m }`), validated in [`Body::validate`], and its arm in [`solve_at_load`] and
//!    [`solve_at_lambda`] below, the single dispatch point (lengths go in units of
//!    `problem.length_scale_m`);
//! 3. its tests, through [`crate::contact::roll`] where they can.
//!
//! The scene carries the body (`Scene::body`, serde default = half-space, so existing JSON keeps
//! working), [`crate::contact::roll`] calls the dispatch, and the scheme is chosen by
//! [`crate::contact::Scheme`] inside the body. A scheme a body does not support is refused with
//! [`ContactError::Unsupported`]. The choice of a body for a cover (`auto`) is
//! [`crate::contact::cover`], one file over this dispatch.

pub mod half_space;
pub mod layer;

use super::error::ContactError;
use super::problem::{DimensionlessScene, DimensionlessSolution};
use super::settings::ContactSettings;
use serde::{Deserialize, Serialize};

/// What the roll rolls on (dimensional parameters, SI). JSON: `{"kind": "half_space"}`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum Body {
    /// A viscoelastic half-space (thesis ch. 3): kernel eq. 3.19.
    #[default]
    HalfSpace,
    /// A viscoelastic cover of thickness `thickness_m` bonded to a rigid carcass (plane strain,
    /// [`layer`]). Every scheme is served at given load by the layer's own error-controlled solver
    /// ([`layer::layer_at_load`]: spectral to `settings.auto.tol`, the hat collocation for covers
    /// too thin for it); at given λ by the thesis collocation with `settings.n` intervals.
    Layer {
        /// Cover thickness in m (> 0).
        thickness_m: f64,
    },
    /// A Winkler foundation of uniaxial columns of height `height_m` (conveyor design tools;
    /// [`layer::winkler`], closed form).
    Winkler {
        /// Column height in m (> 0).
        height_m: f64,
    },
    /// A Winkler foundation of laterally constrained columns (the thin compressible layer's limit).
    WinklerConstrained {
        /// Column height in m (> 0).
        height_m: f64,
    },
}

impl Body {
    /// Name used in JSON, tables and messages.
    pub fn name(&self) -> &'static str {
        match self {
            Body::HalfSpace => "half_space",
            Body::Layer { .. } => "layer",
            Body::Winkler { .. } => "winkler",
            Body::WinklerConstrained { .. } => "winkler_constrained",
        }
    }

    /// Check the body's own parameters (finite, in range).
    pub fn validate(&self) -> Result<(), ContactError> {
        match self {
            Body::HalfSpace => Ok(()),
            Body::Layer { thickness_m: h }
            | Body::Winkler { height_m: h }
            | Body::WinklerConstrained { height_m: h } => {
                super::error::positive("body thickness in m", *h).map(|_| ())
            }
        }
    }
}

/// Solve the dimensionless problem of a scene on `body` at its load `problem.load`.
pub fn solve_at_load(
    body: &Body,
    problem: &DimensionlessScene,
    settings: &ContactSettings,
) -> Result<DimensionlessSolution, ContactError> {
    body.validate()?;
    match body {
        Body::HalfSpace => half_space::solve_at_load(&problem.terms, problem.load, settings),
        Body::Layer { thickness_m } => layer::layer_at_load(
            &problem.terms,
            problem.load,
            thickness_m / problem.length_scale_m,
            problem.poisson,
            &layer::LayerSettings {
                tol: settings.auto.tol,
                n_max: 512,
                ..Default::default()
            },
        )
        .map(|a| a.solution),
        Body::Winkler { height_m } | Body::WinklerConstrained { height_m } => {
            layer::winkler_at_load(
                &problem.terms,
                problem.load,
                winkler_columns(body),
                height_m / problem.length_scale_m,
                problem.poisson,
                &settings.load,
            )
            .map(|a| a.solution)
        }
    }
}

/// Solve the dimensionless problem of a scene on `body` at contact length λ (in units of V·T).
pub fn solve_at_lambda(
    body: &Body,
    problem: &DimensionlessScene,
    lambda: f64,
    settings: &ContactSettings,
) -> Result<DimensionlessSolution, ContactError> {
    body.validate()?;
    match body {
        Body::HalfSpace => half_space::solve_at_lambda(&problem.terms, lambda, settings),
        Body::Layer { thickness_m } => {
            let k = layer::LayerKernel::new(
                &problem.terms,
                thickness_m / problem.length_scale_m,
                problem.poisson,
            )?;
            layer::collocation::solve_at_lambda(&k, lambda, settings.n)
        }
        Body::Winkler { height_m } | Body::WinklerConstrained { height_m } => {
            let w = layer::Winkler::new(
                &problem.terms,
                winkler_columns(body),
                height_m / problem.length_scale_m,
                problem.poisson,
            )?;
            Ok(w.at_lambda(lambda)?.solution)
        }
    }
}

/// The columns of a Winkler body.
fn winkler_columns(body: &Body) -> layer::WinklerColumns {
    match body {
        Body::WinklerConstrained { .. } => layer::WinklerColumns::Constrained,
        _ => layer::WinklerColumns::Uniaxial,
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

    use super::layer::{
        collocation, layer_at_load, winkler_at_load, LayerKernel, LayerSettings, Winkler,
        WinklerColumns,
    };
    use super::{solve_at_lambda, solve_at_load, Body};
    use crate::contact::load::LoadSettings;
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
            let hs = solve_at_load(&Body::HalfSpace, &p, &ContactSettings::auto(tol)).unwrap();
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
            let want = winkler_at_load(&p.terms, p.load, columns, h, 0.3, &LoadSettings::default())
                .unwrap();
            assert_eq!(got, want.solution, "{body:?}");
            let at = solve_at_lambda(&body, &p, 0.7, &settings).unwrap();
            let want_at = Winkler::new(&p.terms, columns, h, 0.3)
                .unwrap()
                .at_lambda(0.7)
                .unwrap()
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
}
