//! The weight of each master-curve point in the Prony fit (docs/MATH.md eq. 5.1). A point whose
//! isotherm's shift the overlaps do not determine (§6.6) sits at a reduced frequency uncertain by
//! its standard error σ_a (eq. 6.2); where its
//! modulus changes with frequency, that is an error in the modulus the fit sees of about
//! |d log10 M/d log10 f|·σ_a, on top of the point's own scatter σ_M (both from a quadratic through
//! the isotherm's points). The effective-variance rule
//! (Orear 1982) weights its residual by w = σ_M/√(σ_M² + (s·σ_a)²): a flat glassy E′ keeps its
//! full weight, a steep glassy E″ placed by a law 0.3 decade uncertain counts about a twentieth.
//! Isotherms whose shift the overlaps determine keep weight 1: their σ_a is the error of the whole
//! curve against the reference, not of the point against its neighbours, which the overlap's own
//! residuals already measure.
//!
//! Input: a [`MasterCurve`]; output: one [E′, E″] weight per point, in the order of `points`.
//!
//! Reference: Orear, J. (1982), Least squares when both variables have errors, Am. J. Phys. 50,
//! 912–916.

use super::MasterCurve;

/// The smallest weight: every point still enters the fit (a weight of 0 would leave a term that
/// only such points see without any row).
const WEIGHT_MIN: f64 = 1e-3;

/// The [E′, E″] weights of `master.points` (module docs).
pub fn point_weights(master: &MasterCurve) -> Vec<[f64; 2]> {
    let mut weights = vec![[1.0, 1.0]; master.points.len()];
    let floor = master.settings.channel_scatter_floor_log10;
    for (i, iso) in master.isotherms.iter().enumerate() {
        if iso.shift_determined {
            continue;
        }
        let sigma_a = iso.log10_a_t_std;
        if sigma_a.is_nan() || sigma_a <= 0.0 {
            continue;
        }
        let idx: Vec<usize> = (0..master.points.len())
            .filter(|&k| master.points[k].isotherm == i)
            .collect();
        if idx.len() < 4 {
            continue;
        }
        let x: Vec<f64> = idx
            .iter()
            .map(|&k| master.points[k].reduced_freq_hz.log10())
            .collect();
        for (c, modulus) in [
            |p: &super::MasterPoint| p.storage_pa,
            |p: &super::MasterPoint| p.loss_pa,
        ]
        .iter()
        .enumerate()
        {
            let y: Vec<f64> = idx
                .iter()
                .map(|&k| modulus(&master.points[k]).log10())
                .collect();
            let (slope, noise) = quadratic(&x, &y);
            let spread = slope.abs() * sigma_a;
            let w = 1.0 / (1.0 + (spread / noise.max(floor)).powi(2)).sqrt();
            let w = if w.is_finite() {
                w.max(WEIGHT_MIN)
            } else {
                WEIGHT_MIN
            };
            for &k in &idx {
                weights[k][c] = w;
            }
        }
    }
    weights
}

/// The slope dy/dx at the middle of x of the least-squares quadratic through (x, y), and the RMS
/// scatter about it (√(RSS/(n − 3))): points moved to their isotherm's temperature lie unevenly in
/// x, where second differences would read the curve's slope as scatter.
fn quadratic(x: &[f64], y: &[f64]) -> (f64, f64) {
    let n = x.len();
    let mx = x.iter().sum::<f64>() / n as f64;
    let a = nalgebra::DMatrix::from_fn(n, 3, |k, j| (x[k] - mx).powi(j as i32));
    let b = nalgebra::DVector::from_column_slice(y);
    let Ok(c) = a.clone().svd(true, true).solve(&b, 1e-12) else {
        return (0.0, f64::INFINITY);
    };
    let rss = (&a * &c - &b).norm_squared();
    (c[1], (rss / (n as f64 - 3.0)).sqrt())
}
