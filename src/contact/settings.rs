//! Numerical settings of the contact stage: which scheme solves eq. 3.25 ([`Scheme`]) and the
//! settings of each, carried together by one [`ContactSettings`] (physics lives in
//! [`super::scene::Scene`]).
//!
//! Input: nothing (plain data, built by the caller); output: handed to [`super::roll`], to the
//! dimensionless entry points [`super::solve_at_load`] / [`super::solve_at_lambda`] and through the
//! body dispatch ([`super::body`]) to the scheme.

use super::body::half_space::auto::AutoSettings;
use super::load::LoadSettings;
use serde::{Deserialize, Serialize};

/// Which discretisation solves eq. 3.25.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Scheme {
    /// The thesis' piecewise-linear collocation (first order in h = λ/n; [`ContactSettings::n`]).
    Thesis,
    /// The exact solution for one creep term (standard linear solid); the pressure is sampled at
    /// n + 1 equally spaced points.
    Exact,
    /// The error-controlled Chebyshev–exponential scheme ([`ContactSettings::auto`], its `tol`):
    /// every answer carries its error estimate and the contact-condition checks.
    #[default]
    Auto,
}

impl Scheme {
    /// Name used in JSON and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Scheme::Thesis => "thesis",
            Scheme::Exact => "exact",
            Scheme::Auto => "auto",
        }
    }
}

impl std::str::FromStr for Scheme {
    type Err = String;

    /// `thesis`, `exact` or `auto` (the names of [`Scheme::name`]).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        [Scheme::Thesis, Scheme::Exact, Scheme::Auto]
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| format!("scheme `{s}` is not known (thesis, exact, auto)"))
    }
}

impl std::fmt::Display for Scheme {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// Numerical settings of every scheme; `scheme` picks the one used.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactSettings {
    /// Discretisation (default `auto`).
    pub scheme: Scheme,
    /// Number of intervals of the thesis scheme (and n + 1 pressure samples of the exact one).
    /// Default 200: docs/DEVLOG.md's speed/accuracy table gives friction errors well below 1 % for one
    /// term at this n, at a few ms per solve.
    pub n: usize,
    /// Load loop of the thesis scheme.
    pub load: LoadSettings,
    /// Settings of the `auto` scheme (tolerance, profile, gap check).
    pub auto: AutoSettings,
}

impl Default for ContactSettings {
    fn default() -> Self {
        Self {
            scheme: Scheme::Auto,
            n: 200,
            load: LoadSettings::default(),
            auto: AutoSettings::default(),
        }
    }
}

impl ContactSettings {
    /// The `auto` scheme at relative tolerance `tol` (other settings default).
    pub fn auto(tol: f64) -> Self {
        Self {
            scheme: Scheme::Auto,
            auto: AutoSettings {
                tol,
                ..AutoSettings::default()
            },
            ..Self::default()
        }
    }

    /// The thesis scheme with `n` intervals.
    pub fn thesis(n: usize) -> Self {
        Self {
            scheme: Scheme::Thesis,
            n,
            ..Self::default()
        }
    }
}
