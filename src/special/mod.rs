//! Special functions the contact kernel needs: the exponential integrals E1 and Ei in scaled forms
//! (eˣE1(x), e⁻ˣEi(x)), accurate to a few ulp over the whole double range (MATH.md §2).
//! Owned by the foundation contact issue.

mod expint;
mod kernel_bracket;

pub use expint::{e1, ei, exp_e1, expm_ei, EULER_GAMMA};
pub use kernel_bracket::{kernel_bracket, kernel_bracket_int1, kernel_bracket_int2};
