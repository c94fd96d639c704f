//! General numerics (not specific to any stage): the scaled modified Bessel functions e^{−μ}Iₙ(μ)
//! (`bessel.rs`), one step of Brent's root finder (`brent.rs`), Gauss–Legendre rules and adaptive
//! quadrature (`gauss_legendre.rs`), Chebyshev interpolation, Clenshaw and sine series
//! (`chebyshev.rs`); and the special functions the contact kernel needs: the exponential integrals E1 and Ei in scaled forms
//! (eˣE1(x), e⁻ˣEi(x)), accurate to a few ulp over the whole double range (docs/MATH.md §2), and the
//! kernel bracket h with its two antiderivatives (for piecewise-linear collocation of eq. 3.25).
//! Owned by the foundation contact issue.
//!
//! Input: `f64`; output: `f64`. No errors: arguments outside a function's domain give NaN or the
//! signed infinity of the limit, as documented on each function; the library never panics here.
//!
//! - [`e1`], [`exp_e1`] (eˣE1, x > 0), [`ei`], [`expm_ei`] (e⁻ˣEi, x ≠ 0): `expint.rs`.
//! - [`kernel_bracket`] h(x) = ln|x| + γ + g(x), g = eˣE1(x) (x > 0), −eˣEi(−x) (x < 0), so that the
//!   kernel of thesis eq. 3.19 for γ(ζ) = Σ fᵢe^{−bᵢζ} is K(ξ) = ln|ξ| + Σ (fᵢ/bᵢ)·h(bᵢξ);
//!   [`kernel_bracket_int1`] = ∫₀ˣ h and [`kernel_bracket_int2`] = ∫₀ˣ∫₀ˢ h: `kernel_bracket.rs`
//!   (closed forms, series and branch points derived there), `kernel_taylor.rs` (generated pieces).
//!
//! Accuracy: every function is compared with mpmath values (tools/gen_special_reference.py →
//! tests/data/special_reference.csv) for |x| from 1e-30 to 1e30, both signs where defined, near
//! Ei's zero, near the zeros of h, H₁, H₂ and at every branch point. The maximal relative error is
//! below 6e-16 everywhere (≈ 2.6 × 2⁻⁵²); print the table per function and range with
//! `cargo test --release --test tests special_accuracy_table -- --nocapture`.

pub(crate) mod bessel;
pub(crate) mod brent;
pub(crate) mod chebyshev;
pub(crate) mod equilibrated;
mod expint;
pub(crate) mod gauss_legendre;
mod kernel_bracket;
mod kernel_taylor;

pub use bessel::{one_minus_one_plus_c_i0, scaled_bessel_i};
#[cfg(test)]
pub use expint::e1;
#[cfg(test)]
pub use expint::ei;
#[cfg(test)]
pub use expint::exp_e1;
pub use expint::{expm_ei, EULER_GAMMA};
#[cfg(test)]
pub use kernel_bracket::kernel_bracket_int1;
pub use kernel_bracket::{kernel_bracket, kernel_bracket_int2};
