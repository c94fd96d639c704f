//! Optional vertical shift b_T (docs/MATH.md §6; off by default for tensile rubbers): the reduced moduli
//! are E_r(ω a_T) = E(ω, T) / b_T.
//!
//! - `temperature`: the entropy-elasticity factor b_T = ρT/(ρ_ref T_ref) with constant density,
//!   i.e. T/T_ref in kelvin (Ferry, ch. 11).
//! - `fitted`: from the residual offset in log10 E′ after the horizontal shifts: the log10 b_T that
//!   minimise Σ [(y_a − v_a) − (S_b − v_b)]² over all overlapping points (a linear least-squares
//!   problem, v_ref = 0). The horizontal shifts then come from tan δ, which b_T does not change.

use super::shift::{overlap_points, residual, Prepared};
use crate::material::ZERO_CELSIUS_K;
use nalgebra::{DMatrix, DVector};

/// log10 b_T = log10(T/T_ref) (kelvin), the constant-density entropic factor.
pub(crate) fn log10_b_t_temperature(temp_c: f64, t_ref_c: f64) -> f64 {
    ((temp_c + ZERO_CELSIUS_K) / (t_ref_c + ZERO_CELSIUS_K)).log10()
}

/// Fitted log10 b_T of each isotherm from the offset of channel 0 (log10 E′) of `iso` at the given
/// horizontal shifts, with isotherm `reference` at 0.
pub(crate) fn fit_vertical(
    iso: &[Prepared],
    shifts: &[f64],
    reference: usize,
    reach: usize,
    min_points: usize,
) -> Vec<f64> {
    let n = iso.len();
    let mut ata = DMatrix::<f64>::zeros(n, n);
    let mut atb = DVector::<f64>::zeros(n);
    for a in 0..n {
        for b in a + 1..n.min(a + reach + 1) {
            let d = shifts[b] - shifts[a];
            let ops = overlap_points(&iso[a], &iso[b], d);
            if ops.len() < min_points {
                continue;
            }
            for op in ops {
                let (r0, _) = residual(&iso[a], &iso[b], d, op, 0);
                // From a: r = r0 − v_a + v_b; from b: r = r0 − v_b + v_a.
                let (p, m) = if op.from_a { (b, a) } else { (a, b) };
                // r = r0 + v_p − v_m: row with +1 at p, −1 at m, target −r0.
                ata[(p, p)] += 1.0;
                ata[(m, m)] += 1.0;
                ata[(p, m)] -= 1.0;
                ata[(m, p)] -= 1.0;
                atb[p] -= r0;
                atb[m] += r0;
            }
        }
    }
    // Fix v_ref = 0: replace its row and column by the identity.
    for k in 0..n {
        ata[(reference, k)] = 0.0;
        ata[(k, reference)] = 0.0;
    }
    ata[(reference, reference)] = 1.0;
    atb[reference] = 0.0;
    // An isotherm overlapping nothing keeps v = 0.
    for k in 0..n {
        if ata[(k, k)] == 0.0 {
            ata[(k, k)] = 1.0;
        }
    }
    match ata.lu().solve(&atb) {
        Some(v) => v.iter().copied().collect(),
        None => vec![0.0; n],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recovers_known_vertical_offsets() {
        // Same curve, no horizontal shift, vertical offsets 0, 0.05, −0.03 decades: recovered
        // exactly (the residuals are linear in v and vanish at the truth).
        let xs: Vec<f64> = (0..11).map(|i| 0.2 * i as f64).collect();
        let offs = [0.0, 0.05, -0.03];
        let iso: Vec<Prepared> = offs
            .iter()
            .map(|&v| Prepared::new(xs.clone(), vec![xs.iter().map(|x| x * x + v).collect()]))
            .collect();
        let v = fit_vertical(&iso, &[0.0, 0.0, 0.0], 0, 2, 3);
        for (a, b) in v.iter().zip(offs) {
            assert!((a - b).abs() < 1e-12, "{a} vs {b}");
        }
    }

    #[test]
    fn temperature_factor() {
        assert!((log10_b_t_temperature(25.0, 25.0)).abs() < 1e-15);
        let v = log10_b_t_temperature(100.0, 0.0);
        assert!((10f64.powf(v) - 373.15 / 273.15).abs() < 1e-12);
    }
}
