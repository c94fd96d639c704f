//! The viscoelastic half-space (thesis ch. 3): a rigid roll on a half-space whose surface
//! displacement is eq. 3.19 with the kernel K(ξ) = ln|ξ| + Σ (fᵢ/bᵢ)h(bᵢξ) (docs/MATH.md §2), and the
//! three schemes that solve eq. 3.25 on it.
//!
//! Input: creep terms [`CreepTerm`], λ or N′, [`ContactSettings`]; output: [`DimensionlessSolution`].
//! This is the one place that picks the scheme ([`Scheme`]); everything below hard-wires the
//! half-space:
//! - [`kernel`] (eq. 3.19 and its antiderivatives) and [`thesis`] (the piecewise-linear collocation
//!   of eq. 3.25–3.26), whose load loop is [`crate::contact::load`];
//! - [`exact`] (the closed-form one-term solution, eq. D1–D5 there, with its own λ search);
//! - [`auto`] (the error-controlled scheme), with [`modes`] (the roots κⱼ), [`chebyshev`] (the
//!   exponential layers and the exterior transform) and [`rear_gap`] (the gap outside the contact).

pub(crate) mod auto;
pub(crate) mod chebyshev;
pub(crate) mod exact;
pub(crate) mod kernel;
pub(crate) mod modes;
pub(crate) mod rear_gap;
pub(crate) mod thesis;

use crate::contact::error::ContactError;
use crate::contact::load::solve_at_load as load_loop;
use crate::contact::problem::{CreepTerm, DimensionlessSolution};
use crate::contact::settings::{ContactSettings, Scheme};
use kernel::Kernel;

/// Solve at contact length λ with the scheme of `settings`.
pub fn solve_at_lambda(
    terms: &[CreepTerm],
    lambda: f64,
    settings: &ContactSettings,
) -> Result<DimensionlessSolution, ContactError> {
    match settings.scheme {
        Scheme::Thesis => thesis::solve_at_lambda(&Kernel::new(terms)?, lambda, settings.n),
        Scheme::Exact => {
            Kernel::new(terms)?;
            thesis::check_intervals(settings.n)?;
            Ok(exact::one_term_at_lambda(one_term(terms)?, lambda)?.to_solution(settings.n + 1))
        }
        Scheme::Auto => auto::solve_auto_at_lambda(terms, lambda, &settings.auto),
    }
}

/// Solve at load N′ with the scheme of `settings` (`iterations` = solves made).
pub fn solve_at_load(
    terms: &[CreepTerm],
    load: f64,
    settings: &ContactSettings,
) -> Result<DimensionlessSolution, ContactError> {
    match settings.scheme {
        Scheme::Thesis => {
            let kernel = Kernel::new(terms)?;
            thesis::check_intervals(settings.n)?;
            load_loop(load, kernel.sum_f_over_b(), &settings.load, |lambda| {
                thesis::solve_at_lambda(&kernel, lambda, settings.n)
            })
        }
        Scheme::Exact => {
            Kernel::new(terms)?;
            thesis::check_intervals(settings.n)?;
            Ok(exact::one_term_at_load(one_term(terms)?, load)?.to_solution(settings.n + 1))
        }
        Scheme::Auto => auto::solve_auto_at_load(terms, load, &settings.auto),
    }
}

/// The single term the exact scheme needs.
fn one_term(terms: &[CreepTerm]) -> Result<CreepTerm, ContactError> {
    match terms {
        [t] => Ok(*t),
        _ => Err(ContactError::Unsupported(format!(
            "the exact scheme solves one creep term (the standard linear solid); got {} terms",
            terms.len()
        ))),
    }
}
