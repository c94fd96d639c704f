//! Numerical settings of the contact stage: which scheme solves eq. 3.25 ([`Scheme`]) and the
//! settings of each, carried together by one [`ContactSettings`] (physics lives in
//! [`super::scene::Scene`]).
//!
//! Imports nothing else of `contact`: the ground floor with [`super::problem`] and [`super::error`].
//!
//! Input: nothing (plain data, built by the caller); output: handed to [`super::roll`], to the
//! dimensionless entry points [`super::solve_at_load`] / [`super::solve_at_lambda`] and through the
//! body dispatch ([`super::body`]) to the scheme.

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

/// Settings of the `auto` scheme.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct AutoSettings {
    /// Relative tolerance on ρ·F/N and λ (default 1e−6; allowed 1e−12 … 0.1).
    pub tol: f64,
    /// Iteration limit of the load loop (default 100; a bracketed secant needs ~6).
    pub max_iterations: usize,
    /// Uniform-in-θ points of the returned pressure profile (default 200), plus ~40 in the front layer.
    pub profile_points: usize,
    /// Evaluate the gap outside the contact (default true; costs ~4 points × 129 × N kernel
    /// evaluations, ≈ 0.3 ms for one term, more than the solve itself for few terms).
    #[serde(default = "default_true")]
    pub gap_check: bool,
}

fn default_true() -> bool {
    true
}

impl Default for AutoSettings {
    fn default() -> Self {
        AutoSettings {
            tol: 1e-6,
            max_iterations: 100,
            profile_points: 200,
            gap_check: true,
        }
    }
}

/// Settings of the load loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadSettings {
    /// Relative tolerance on the load: stop when |N′(λ) − N′₀| ≤ `rel_tol`·N′₀. Default 1e-10 (far
    /// below any discretisation error, and Brent converges superlinearly, so it costs few solves).
    pub rel_tol: f64,
    /// Stop also when the bracket on λ is narrower than this, relative (the load is then accepted if
    /// within `accept_tol`). Default 1e-10: N′(λ) carries rounding noise of ≈ 1e-9 relative at n ≈ 200
    /// (the collocation matrix of a first-kind equation has condition ≈ 1e4), so Brent cannot always
    /// meet `rel_tol`; λ is then known to 1e-10 anyway.
    pub lambda_rel_tol: f64,
    /// Loosest relative load error accepted when the λ bracket has collapsed. Default 1e-8.
    pub accept_tol: f64,
    /// Largest number of solves. Default 100.
    pub max_solves: usize,
    /// How many times each end of the initial bracket may be widened by 1.25. Default 40 (a factor 7500).
    pub max_expand: usize,
}

impl Default for LoadSettings {
    fn default() -> Self {
        Self {
            rel_tol: 1e-10,
            lambda_rel_tol: 1e-10,
            accept_tol: 1e-8,
            max_solves: 100,
            max_expand: 40,
        }
    }
}
