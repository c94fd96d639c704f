//! Settings of the `auto` scheme and what follows from them: the input checks, the quadrature step
//! for a tolerance, and the error budgets of the mode reduction (module doc of [`super`]).
//!
//! Input: [`AutoSettings`] (plain serde data) and the creep terms; output: checked input,
//! [`QuadratureSettings`], budgets.

use crate::contact::error::ContactError;
use crate::contact::numerics::at_lambda::QuadratureSettings;
use crate::contact::problem::CreepTerm;
pub use crate::contact::settings::AutoSettings;

/// Largest strength f/b of one creep term the auto scheme takes (see [`validate`]).
pub const MAX_MODE_STRENGTH: f64 = 1e15;

pub(super) fn validate(terms: &[CreepTerm], tol: f64) -> Result<(), ContactError> {
    for (index, t) in terms.iter().enumerate() {
        if !(t.f >= 0.0 && t.f.is_finite() && t.b > 0.0 && t.b.is_finite()) {
            return Err(ContactError::BadTerm {
                index,
                f: t.f,
                b: t.b,
            });
        }
    }
    // A mode's μ = (1 + f/b)·c sizes its Chebyshev series (√(83μ) orders, special::bessel), so an
    // absurd strength f/b would ask for an unbounded series (b ≈ 1, f ≈ 1e300 overflowed it). A
    // polymer's J∞/J_g spans about 3–4 decades (glassy ~1 GPa to rubbery ~1 MPa); 1e15 leaves
    // eleven more and keeps every kept mode's series bounded.
    for t in terms {
        let r = t.f / t.b;
        if r > MAX_MODE_STRENGTH {
            return Err(ContactError::OutOfRange {
                scheme: "auto",
                quantity: "f/b of a creep term",
                value: r,
                bound: "at most",
                limit: MAX_MODE_STRENGTH,
            });
        }
    }
    if !(1e-12..=0.1).contains(&tol) {
        return Err(ContactError::BadValue {
            field: "tol".into(),
            expected: "in [1e-12, 0.1]",
            value: tol,
        });
    }
    Ok(())
}

/// Trapezoid step for a tolerance: measured errors (1–30 terms) ≤ 5e−8 at h = 0.6, ≤ 2e−11 at
/// 0.4, ~1e−15 at 0.3 (≈ e^{−π²/h}).
pub(super) fn quad_for(tol: f64) -> QuadratureSettings {
    QuadratureSettings {
        step: if tol >= 1e-4 {
            0.6
        } else if tol >= 1e-7 {
            0.4
        } else {
            0.3
        },
    }
}

/// Error budgets of the mode reduction (ρF/N/λ absolute, N′ relative): 0.3·tol each, the first
/// times the friction over λ.
pub(super) fn budgets(tol: f64, fr_over_lambda: f64) -> (f64, f64) {
    (0.3 * tol * fr_over_lambda.abs().max(1e-300), 0.3 * tol)
}
