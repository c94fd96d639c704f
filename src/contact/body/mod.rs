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
//! 1. one new file (or folder) `body/NAME.rs` with `solve_at_load` and `solve_at_lambda` taking
//!    the dimensionless problem, the body's own (dimensionless) parameters and the settings;
//! 2. one variant in [`Body`] (its dimensional parameters, SI, with units in the names, e.g.
//!    `Layer { thickness_m }`), validated in [`Body::validate`];
//! 3. its arm in [`solve_at_load`] and [`solve_at_lambda`] below, the single dispatch point (lengths
//!    go in units of `problem.length_scale_m`).
//!
//! Nothing else changes: the scene carries the body (`Scene::body`, serde default = half-space, so
//! existing JSON keeps working), [`crate::contact::roll`] and the friction maps call the dispatch,
//! and the scheme is chosen by [`crate::contact::Scheme`] inside the body. A scheme a body does not
//! support is refused with [`ContactError::Unsupported`].

pub mod half_space;
pub mod layer;

use super::error::ContactError;
use super::scene::DimensionlessScene;
use super::settings::ContactSettings;
use super::DimensionlessSolution;
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
mod dispatch_tests;
