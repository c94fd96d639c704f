//! Contact conditions outside the contact for the `auto` scheme: the gap between the roll and the
//! surface behind the rear edge and ahead of the front edge must stay open.
//!
//! Input: the reduced problem ([`Modes`], scale s) and its [`LambdaSolution`]; output: the gap at
//! chosen points, relative to the depth scale λ²/8 (the Hertz indentation (λ/2)²/2).
//!
//! Math: eq. 3.25 holds on the contact; off it the surface displacement is still
//! ρv(ξ) = ∫₀^λ Q′(ξ′)[K(−ξ′) − K(ξ−ξ′)]dξ′ (eq. 3.19 with v(0) = 0) and the roll sits at depth
//! ξβ − ξ²/2 (eq. 3.22), so the gap is g(ξ) = ρv(ξ) − (ξβ − ξ²/2) ≥ 0 (surface below the roll).
//! With fast modes lumped, Q′K = Q̂K̂ (module [`super::reduce`]). The integral is a trapezoid sum in θ
//! (ξ′ = L(1 + cos θ)) on ≥ 128 intervals of the FFT grid, spectrally accurate for the smooth part
//! but not resolving front layers thinner than ~1/128² of the contact: a coarse check (it flags
//! penetration deeper than 1e−3 of the depth scale), and no more is claimed for it.
//!
//! When β < 0 the roll's lowest point lies behind the rear edge, where the surface is still
//! depressed and the roll can touch it again. The solver does not yet move the rear edge or add a
//! second contact zone; it reports the penetration as a warning.

use super::auto::LambdaSolution;
use super::chebyshev::sine_series_grid;
use super::kernel::Kernel;
use super::modes::Modes;
use super::CreepTerm;

/// Gap g(ξ)/(λ²/8) at each ξ outside [0, λ] (NaN if the kernel cannot be built).
pub fn gap_outside(modes: &Modes, scale: f64, sol: &LambdaSolution, xs: &[f64]) -> Vec<f64> {
    let terms: Vec<CreepTerm> = modes
        .f
        .iter()
        .zip(&modes.b)
        .map(|(&f, &b)| CreepTerm { f, b })
        .collect();
    let Ok(kernel) = Kernel::new(&terms) else {
        return vec![f64::NAN; xs.len()];
    };
    let l = 0.5 * sol.lambda;
    // at least 128 intervals even for short coefficient vectors (the elastic case has 2)
    let mut a = sol.coefficients.clone();
    if a.len() < 129 {
        a.resize(129, 0.0);
    }
    let grid = sine_series_grid(&a);
    let m = grid.len() - 1;
    let stride = (m / 128).max(1);
    let pts: Vec<(f64, f64)> = (0..=m).step_by(stride).map(|k| grid[k]).collect();
    let h = pts.get(1).map(|p| p.0 - pts[0].0).unwrap_or(0.0);
    let depth = sol.lambda * sol.lambda / 8.0;
    xs.iter()
        .map(|&x| {
            let mut s = 0.0;
            for &(th, q) in &pts {
                let w = th.sin();
                let xp = l * (1.0 + th.cos());
                if w <= 1e-12 || xp <= 0.0 || q == 0.0 {
                    continue; // both ends: sin θ = 0 and Q′ = 0 (K(0) = −∞ is never evaluated)
                }
                s += q * scale * (kernel.k(-xp) - kernel.k(x - xp)) * w;
            }
            let rho_v = l * h * s;
            (rho_v - (x * sol.beta - 0.5 * x * x)) / depth
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::auto::{solve_at_lambda, QuadratureSettings};

    #[test]
    fn hertz_gap_is_open_and_symmetric() {
        // Elastic (Hertz line contact): the gap opens on both sides, grows away from the edges and
        // is symmetric about the centre.
        let m = Modes::new(&[]);
        let sol = solve_at_lambda(&m, 2.0, QuadratureSettings::default());
        let g = gap_outside(&m, 1.0, &sol, &[-2.0, -0.5, -0.01, 2.01, 2.5, 4.0]);
        for (k, v) in g.iter().enumerate() {
            assert!(*v > 0.0, "point {k}: {v}");
        }
        assert!(g[0] > g[1] && g[1] > g[2], "{g:?}");
        // symmetric about the centre for an elastic contact (trapezoid error ≪ 1e−6 here)
        assert!((g[1] - g[4]).abs() < 1e-6 * g[1].abs(), "{g:?}");
    }
}
