//! The contact conditions outside the contact for an `auto` answer: a scan behind the rear edge
//! (incl. around the roll's lowest point when β < 0) and three points ahead of the front edge
//! ([`crate::contact::body::half_space::rear_gap`]), with the warnings they call for.
//!
//! Input: the reduced problem, the corrected solution and the settings (`gap_check` off: NaN);
//! output: the smallest gap over λ²/8 and where it lies, warnings appended.

use super::settings::AutoSettings;
use crate::contact::body::half_space::rear_gap::contact_check;
use crate::contact::numerics::at_lambda::LambdaSolution;
use crate::contact::numerics::reduction::Reduction;

/// (min gap / (λ²/8), its ξ) outside the contact, and the warnings about it (penetration; the
/// roll's lowest point behind the rear edge).
pub(super) fn gap_check(
    red: &Reduction,
    sol: &LambdaSolution,
    settings: &AutoSettings,
    warnings: &mut Vec<String>,
) -> (f64, f64) {
    // Contact conditions outside the contact (module `rear_gap`): a scan behind the rear edge
    // (incl. around the lowest point when β < 0) and three points ahead of the front edge.
    let (min_gap_ratio, min_gap_xi) = if settings.gap_check {
        let scan = contact_check(&red.modes, red.scale, sol);
        if scan.min_gap_ahead_ratio < scan.min_gap_ratio {
            (scan.min_gap_ahead_ratio, f64::NAN)
        } else {
            (scan.min_gap_ratio, scan.at_xi)
        }
    } else {
        (f64::NAN, f64::NAN)
    };
    // The gap is accurate to ~1e−10 of λ²/8 for the computed pressure, whose own error is ~tol.
    let gap_tol = settings.tol.max(1e-9);
    if min_gap_ratio < -gap_tol {
        warnings.push(format!(
            "contact condition fails: the roll penetrates the surface outside the contact (min gap \
             / (λ²/8) = {min_gap_ratio:.3e} at ξ = {min_gap_xi:.4e}); this answer is not valid. In \
             the rear-edge scans every such case was a wrong solution, fixed by a tighter --tol \
             (a genuine second contact zone was never found, and is not modelled)"
        ));
    }
    if sol.beta < 0.0 {
        let gap = if min_gap_ratio.is_nan() {
            "gap behind not checked".to_string()
        } else if min_gap_ratio >= -gap_tol {
            format!("the gap behind stays open, min gap / (λ²/8) = {min_gap_ratio:.3e}")
        } else {
            "see the contact-condition warning".to_string()
        };
        warnings.push(format!(
            "information: the roll's lowest point lies behind the rear contact edge (β = {:.4e}, \
             β/λ = {:.4e}); {gap}",
            sol.beta,
            sol.beta / sol.lambda
        ));
    }
    (min_gap_ratio, min_gap_xi)
}
