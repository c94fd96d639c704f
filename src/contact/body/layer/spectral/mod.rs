//! A spectrally convergent solver of the bonded viscoelastic layer at given λ and at given load
//! (issue 14, "Numbers to reach").
//!
//! (Module doc: see the end of this work; draft.)

pub mod at_lambda;
pub mod at_load;
pub mod layer_term;
pub mod volterra;

pub use at_load::{solve_spectral_at_load, SpectralSettings};

#[cfg(test)]
mod tests;
