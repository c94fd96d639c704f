//! Friction maps of a covered scene from two reduced variables: the compound's rolling friction on a
//! cover of thickness h bonded to a rigid carcass, over many speeds, loads and temperatures, from a
//! 2-D interpolant of the dimensionless layer solution ([`CoveredSurface`]).
//!
//! Input: a [`CreepSpectrum`] at its reference temperature, the cover thickness and map points
//! ([`MapQuery`]); output: per point F*/N* and contact length ([`MapValue`]) and the surface (its
//! error estimate, solve count, node warnings).
//!
//! # Why two variables suffice (exact; docs/MATH.md §13)
//! As for the half-space ([`super`]): with T = l_g/V and VT = l_g, a scene (R, N*, V, T) has the
//! creep terms bᵢ = s/τᵢ, fᵢ = (Jᵢ/J_g)·bᵢ with s = l_g/(V·a_T), and the load N′ = 1/4. The cover
//! enters [`crate::contact::cover::roll_cover`] only as its dimensionless thickness
//! h′ = h/(VT) = h/l_g, the **second reduced variable η = h/l_g**, and ν through the layer's
//! compliance (a property of the compound, fixed for a map). So the dimensionless covered problem
//! and its solution φ = ρF/N, λ depend on the compound and on (s, η) alone; back in SI units
//! F*/N* = φ(s, η)·l_g/R and l = λ(s, η)·l_g as on the half-space. A scene's speed and temperature
//! move s only, its radius and load move both (l_g ∝ √(R N*)), the cover moves η only. The tests check
//! this against direct `roll_cover` solves of scenes sharing (s, η).
//!
//! # Which body
//! The surface interpolates the **bonded layer throughout** (the full model), not the body that
//! `auto` would pick per point: `auto` switches to the half-space when 3(L/h)² ≤ tol and (ν < ½) to
//! the constrained Winkler foundation when 0.4(h/λ)/(1−2ν) ≤ tol, and each switch is a jump of up to
//! tol in the answer along a curve of the (s, η) plane that no panel edge follows; a Chebyshev
//! series across such a jump converges like 1/n and its tail estimate stays large. Splitting the
//! panels at the criterion would need that curve (it depends on λ and on the modes' memory, known
//! only after solving) and would put the cheaper bodies' model error (≤ tol) into the map anyway.
//! The layer is smooth in (s, η) (its kernel is analytic in h′ and the creep terms are analytic
//! in s), and where `auto` would have chosen a cheaper body the layer agrees with it to tol.
//!
//! The cost is that every node is a layer solve; see [`CoveredSurface`] for the settings and the
//! measured cost.

use super::covered_problem::CoveredProblem;
use super::surface::CoveredSurface;
use super::{FrictionMapError, MapQuery, MapSettings, MapValue};
use rayon::prelude::*;

/// Friction and contact length at every query on the cover of `problem`, from one surface built over
/// the rectangle of (ln s, ln η) the queries need (module doc). Queries must have finite positive
/// fields.
pub fn covered_map(
    problem: &CoveredProblem,
    queries: &[MapQuery],
    settings: &MapSettings,
) -> Result<(Vec<MapValue>, CoveredSurface), FrictionMapError> {
    let xs = super::reduced_times(&problem.reduced, queries)?;
    let ys: Vec<f64> = queries
        .iter()
        .map(|q| problem.reduced_thickness(q.radius_m, q.load_n_per_m).ln())
        .collect();
    if let Some(i) = ys.iter().position(|y| !y.is_finite()) {
        return Err(FrictionMapError::BadValue {
            field: format!("point {i}: ln(h/l_g)"),
            value: ys[i],
            expected: "finite (cover or load out of range)",
        });
    }
    let range = |v: &[f64]| {
        (
            v.iter().copied().fold(f64::INFINITY, f64::min),
            v.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        )
    };
    let surface = CoveredSurface::build(problem, range(&xs), range(&ys), settings)?;
    let values = queries
        .par_iter()
        .zip(xs.par_iter().zip(ys.par_iter()))
        .map(|(q, (&x, &y))| {
            let (phi, lambda) = surface
                .eval(x, y)
                .expect("every query lies in the surface's rectangle by construction");
            let lg = problem.reduced.glassy_length_m(q.radius_m, q.load_n_per_m);
            MapValue {
                // F*/N* = (ρF/N)/ρ with ρ = R/l_g; l = λ·l_g.
                friction: phi * lg / q.radius_m,
                contact_length_m: lambda * lg,
            }
        })
        .collect();
    Ok((values, surface))
}
