//! Scheme choice and the two entry points of the dimensionless problem: at given contact length λ and
//! at given load N′ (thesis §3.2 and ch. 4).
//!
//! Input: creep terms [`CreepTerm`], λ or N′, [`ContactSettings`]; output: [`DimensionlessSolution`].
//! The thesis scheme lives in [`super::thesis`], the load loop in [`super::load`].

use super::error::ContactError;
use super::kernel::Kernel;
use super::load::{solve_at_load as load_loop, LoadSettings};
use super::{thesis, CreepTerm, DimensionlessSolution};
use serde::{Deserialize, Serialize};

/// Which discretisation solves eq. 3.25.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Scheme {
    /// The thesis' piecewise-linear collocation (first order in h = λ/n).
    #[default]
    Thesis,
}

impl Scheme {
    /// Name used in JSON and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Scheme::Thesis => "thesis",
        }
    }
}

/// Numerical settings (physics lives in [`super::scene::Scene`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactSettings {
    /// Discretisation.
    pub scheme: Scheme,
    /// Number of intervals of the thesis scheme. Default 200: the README's speed/accuracy table gives
    /// friction errors well below 1 % for one term at this n, at a few ms per solve.
    pub n: usize,
    /// Load loop settings.
    pub load: LoadSettings,
}

impl Default for ContactSettings {
    fn default() -> Self {
        Self {
            scheme: Scheme::Thesis,
            n: 200,
            load: LoadSettings::default(),
        }
    }
}

/// Solve at contact length λ.
pub fn solve_at_lambda(
    terms: &[CreepTerm],
    lambda: f64,
    settings: &ContactSettings,
) -> Result<DimensionlessSolution, ContactError> {
    let kernel = Kernel::new(terms)?;
    match settings.scheme {
        Scheme::Thesis => thesis::solve_at_lambda(&kernel, lambda, settings.n),
    }
}

/// Solve at load N′ (bracketed, safeguarded load loop; `iterations` = solves made).
pub fn solve_at_load(
    terms: &[CreepTerm],
    load: f64,
    settings: &ContactSettings,
) -> Result<DimensionlessSolution, ContactError> {
    let kernel = Kernel::new(terms)?;
    match settings.scheme {
        Scheme::Thesis => {
            thesis::check_intervals(settings.n)?;
            load_loop(load, kernel.sum_f_over_b(), &settings.load, |lambda| {
                thesis::solve_at_lambda(&kernel, lambda, settings.n)
            })
        }
    }
}
