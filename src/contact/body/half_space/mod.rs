//! The viscoelastic half-space (thesis ch. 3): a rigid roll on a half-space whose surface
//! displacement is eq. 3.19 with the kernel K(ξ) = ln|ξ| + Σ (fᵢ/bᵢ)h(bᵢξ) (docs/MATH.md §2), and the
//! three schemes that solve eq. 3.25 on it.
//!
//! Input: creep terms [`CreepTerm`], λ or N′, [`ContactSettings`]; output: [`DimensionlessSolution`].
//! This is the one place that picks the scheme ([`Scheme`]):
//! - thesis: the hat collocation of eq. 3.25–3.26 on the kernel of eq. 3.19
//!   ([`crate::contact::numerics::hat`], [`crate::contact::numerics::kernel`]), whose load loop is
//!   [`crate::contact::load`];
//! - [`exact`] (the closed-form one-term solution, eq. D1–D5 there, with its own λ search);
//! - [`auto`] (the error-controlled scheme) over the shared numerics of [`crate::contact::numerics`]
//!   (the roots κⱼ, the Chebyshev pieces, the N×N solve at λ, the mode reduction), with its lumping
//!   correction and [`rear_gap`] (the gap outside the contact).

pub(crate) mod auto;
pub(crate) mod exact;
pub(crate) mod rear_gap;

use crate::contact::error::ContactError;
use crate::contact::load::solve_at_load as load_loop;
use crate::contact::numerics::hat;
use crate::contact::numerics::kernel::Kernel;
use crate::contact::problem::{CreepTerm, DimensionlessSolution};
use crate::contact::settings::{ContactSettings, Scheme};

/// Solve at contact length λ with the scheme of `settings`.
pub fn solve_at_lambda(
    terms: &[CreepTerm],
    lambda: f64,
    settings: &ContactSettings,
) -> Result<DimensionlessSolution, ContactError> {
    match settings.scheme {
        Scheme::Thesis => hat::solve_at_lambda(&Kernel::new(terms)?, lambda, settings.n),
        Scheme::Exact => {
            Kernel::new(terms)?;
            hat::check_intervals(settings.n)?;
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
            hat::check_intervals(settings.n)?;
            load_loop(load, kernel.sum_f_over_b(), &settings.load, |lambda| {
                hat::solve_at_lambda(&kernel, lambda, settings.n)
            })
        }
        Scheme::Exact => {
            Kernel::new(terms)?;
            hat::check_intervals(settings.n)?;
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
