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
}

impl Body {
    /// Name used in JSON, tables and messages.
    pub fn name(&self) -> &'static str {
        match self {
            Body::HalfSpace => "half_space",
        }
    }

    /// Check the body's own parameters (finite, in range).
    pub fn validate(&self) -> Result<(), ContactError> {
        match self {
            Body::HalfSpace => Ok(()),
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
    }
}
