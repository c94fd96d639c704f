//! Stage `contact`: a rigid cylinder rolling steadily on a viscoelastic body (thesis ch. 3–4).
//!
//! Input: a [`crate::CreepSpectrum`] (already at the scene's temperature) and a dimensional
//! [`Scene`] (roll, load, speed, and the [`Body`] it rolls on), with [`ContactSettings`] (the
//! [`Scheme`]: thesis, exact or auto); output: the [`RollSolution`] (pressure, contact length,
//! offset, rolling-friction coefficient, error estimate and warnings) or a [`ContactError`].
//!
//! Layout: the ground, importing nothing else of contact: `problem` (the dimensionless problem and
//! solution common to every body), `settings` (every scheme's settings), `error`; `load` (the
//! load loop) on it; `numerics` (what several bodies share: the half-space kernel and its hat
//! collocation, modes, Chebyshev pieces, the solve at λ, the mode reduction, the closed-form Winkler
//! foundation) on the ground and `load`; `body` (the seam: one enum, one dispatch; a folder per body:
//! `body::half_space` the three schemes on the half-space, `body::layer` the bonded cover,
//! `body::winkler` the Winkler foundations) over them; `scene` (to and from the dimensionless problem, [`roll`]), `cover` (the
//! choice of body for a cover) and `maps` (friction maps of a spectrum from one reduced variable)
//! over the dispatch.
//!
//! Dimensionless problem (thesis §3.2, eq. 3.25): lengths in units of V·T, contact on 0 ≤ ξ ≤ λ with the
//! front (leading) edge at ξ = λ, creep function γ(ζ) = Σᵢ fᵢ e^(−bᵢζ) (eq. 3.7), unknown pressure Q′(ξ)
//! and offset β, load N′ = 2∫Q′dξ (eq. 3.24), friction ρ·F/N = ∫Q′(ξ−β)dξ / ∫Q′dξ.

pub(crate) mod body;
pub(crate) mod cover;
pub(crate) mod error;
pub(crate) mod load;
pub(crate) mod maps;
pub(crate) mod numerics;
pub(crate) mod problem;
pub(crate) mod scene;
pub(crate) mod settings;

pub(crate) use body::half_space;
pub use body::half_space::exact::{one_term_at_lambda, one_term_at_load, OneTermExact};
pub use body::Body;
pub use cover::roll_cover;
pub use error::ContactError;
pub(crate) use problem::DimensionlessScene;
pub use problem::{CreepTerm, Diagnostics, DimensionlessSolution};
pub use scene::{roll, RollSolution, Scene};
pub use settings::{AutoSettings, ContactSettings, LoadSettings, Scheme};

/// Solve the dimensionless problem on the half-space at contact length λ (the scheme of
/// `settings`). For another body use `body::solve_at_lambda` with a `DimensionlessScene`.
pub fn solve_at_lambda(
    terms: &[CreepTerm],
    lambda: f64,
    settings: &ContactSettings,
) -> Result<DimensionlessSolution, ContactError> {
    half_space::solve_at_lambda(terms, lambda, settings)
}

/// Solve the dimensionless problem on the half-space at load N′ (the scheme of `settings`,
/// `iterations` = solves made). For another body use `body::solve_at_load`.
pub fn solve_at_load(
    terms: &[CreepTerm],
    load: f64,
    settings: &ContactSettings,
) -> Result<DimensionlessSolution, ContactError> {
    half_space::solve_at_load(terms, load, settings)
}
