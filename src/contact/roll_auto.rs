//! A dimensional scene solved with the error-controlled `auto` scheme.
//!
//! Input: [`Scene`] + [`CreepSpectrum`] + [`AutoSettings`]; output: [`RollAuto`] (the SI answer of
//! [`super::scene`] plus the auto scheme's diagnostics and validity warnings).
//!
//! Validity: eq. 3.22 replaces the roll by the parabola −(x−b)²/(2R). Over the contact the circle
//! departs from it by x⁴/(8R³) against x²/(2R), a relative (x/R)²/4; at the contact ends x ≈ l/2, so
//! we warn when (l/(2R))²/4 > 1e−3, i.e. l/R > 0.126 (the half-space assumption fails at the same
//! order).

use super::controlled::{solve_auto_at_load, AutoError, AutoSettings, AutoSolution};
use super::scene::{RollSolution, Scene};
use crate::CreepSpectrum;

/// A scene's SI answer with the `auto` diagnostics.
#[derive(Debug, Clone, PartialEq)]
pub struct RollAuto {
    /// Friction, contact length, offset, pressure in SI units (and the dimensionless problem).
    pub roll: RollSolution,
    /// Mode counts, error estimate, contact checks and warnings.
    pub auto: AutoSolution,
}

/// Solve one scene at its load with the `auto` scheme.
pub fn roll_auto(
    scene: &Scene,
    spectrum: &CreepSpectrum,
    settings: &AutoSettings,
) -> Result<RollAuto, AutoError> {
    let problem = scene.dimensionless(spectrum).map_err(AutoError::Scene)?;
    let mut auto = solve_auto_at_load(&problem.terms, problem.load, settings)?;
    let roll = problem.to_dimensional(scene.load_n_per_m, auto.solution.clone());
    let l_over_r = roll.contact_length_m / scene.radius_m;
    if l_over_r > 0.126 {
        auto.warnings.push(format!(
            "contact length / radius = {l_over_r:.3}: the parabolic roll profile (eq. 3.22) is off by \
             more than 0.1 % at the contact ends; results lose validity"
        ));
    }
    Ok(RollAuto { roll, auto })
}
