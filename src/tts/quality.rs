//! Quality figures of a master curve (docs/MATH.md §6), each with a stated bound and a flag:
//!
//! - **Overlap residual**: RMS mismatch (log10 units) of each isotherm's overlaps after shifting
//!   (computed by the global shift refinement, `super::shift`).
//! - **van Gurp–Palmen**: the phase angle δ = atan(E″/E′) against log10 |E*| needs no horizontal
//!   shift; for a thermorheologically simple material the isotherms fall on one curve (van Gurp &
//!   Palmen, Rheol. Bull. 67 (1998) 5). Measured here as the RMS difference in δ (degrees) between
//!   neighbouring isotherms where their |E*| ranges overlap, by linear interpolation in log10 |E*|.
//! - **Kramers–Kronig, local**: E″ ≈ (π/2) dE′/d ln ω (Booij & Thoone, Rheol. Acta 21 (1982) 15),
//!   i.e. E″ ≈ (π/2) E′ · d log10 E′/d log10 ω, with the slope from each isotherm's spline. The
//!   median of log10 (predicted/measured) per isotherm. The rule is approximate (for E′ ∝ ω^n it
//!   gives (nπ/2)/tan(nπ/2): 0.79 at n = ½), hence a wide bound.

use super::shift::Prepared;
use serde::{Deserialize, Serialize};

/// Bounds beyond which a quality figure is flagged.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct QualityBounds {
    /// Largest acceptable overlap RMS per isotherm, log10 units. Default 0.05 (12 % in modulus):
    /// ten times the scatter of 1 % noise, well below a visible misfit.
    pub overlap_rms_max_log10: f64,
    /// Largest acceptable van Gurp–Palmen RMS between neighbours, degrees. Default 2°: 1 % noise
    /// on E′ and E″ gives at most ≈ 0.8° of scatter in δ.
    pub vgp_rms_max_deg: f64,
    /// Largest acceptable |median log10(predicted E″ / measured E″)| of the local Kramers–Kronig
    /// rule, per isotherm. Default 0.3 (a factor 2), wider than the rule's own error (≤ 0.1 for
    /// power-law slopes up to ½).
    pub kk_max_abs_log10_ratio: f64,
}

impl Default for QualityBounds {
    fn default() -> Self {
        QualityBounds {
            overlap_rms_max_log10: 0.05,
            vgp_rms_max_deg: 2.0,
            kk_max_abs_log10_ratio: 0.3,
        }
    }
}

/// One isotherm's van Gurp–Palmen curve: (log10 |E*|, δ in degrees), sorted by |E*|.
fn vgp_curve(joint: &Prepared, log10_b: f64) -> Vec<(f64, f64)> {
    let (sy, ly) = (&joint.channels[0].0, &joint.channels[1].0);
    let mut c: Vec<(f64, f64)> = sy
        .iter()
        .zip(ly)
        .map(|(&s, &l)| {
            let (es, el) = (10f64.powf(s), 10f64.powf(l));
            ((es.hypot(el)).log10() - log10_b, el.atan2(es).to_degrees())
        })
        .collect();
    c.sort_by(|a, b| a.0.total_cmp(&b.0));
    c.dedup_by(|a, b| a.0 == b.0);
    c
}

fn interp(c: &[(f64, f64)], x: f64) -> Option<f64> {
    if c.len() < 2 || x < c[0].0 || x > c[c.len() - 1].0 {
        return None;
    }
    let i = c.partition_point(|p| p.0 <= x).clamp(1, c.len() - 1);
    let (x0, y0) = c[i - 1];
    let (x1, y1) = c[i];
    Some(y0 + (y1 - y0) * (x - x0) / (x1 - x0))
}

/// van Gurp–Palmen RMS (degrees) of each isotherm against its neighbours (in temperature order);
/// `None` where no |E*| range overlaps.
pub(crate) fn van_gurp_palmen(joint: &[Prepared], log10_b: &[f64]) -> Vec<Option<f64>> {
    let curves: Vec<Vec<(f64, f64)>> = joint
        .iter()
        .zip(log10_b)
        .map(|(p, &b)| vgp_curve(p, b))
        .collect();
    let n = curves.len();
    let mut sum = vec![0.0; n];
    let mut cnt = vec![0usize; n];
    for a in 0..n.saturating_sub(1) {
        let b = a + 1;
        for (from, to) in [(a, b), (b, a)] {
            for &(x, d) in &curves[from] {
                if let Some(di) = interp(&curves[to], x) {
                    let r2 = (d - di).powi(2);
                    for k in [a, b] {
                        sum[k] += r2;
                        cnt[k] += 1;
                    }
                }
            }
        }
    }
    (0..n)
        .map(|i| (cnt[i] > 0).then(|| (sum[i] / cnt[i] as f64).sqrt()))
        .collect()
}

/// Median of log10[(π/2) E′ · dlog10E′/dlog10ω / E″] over the points of one isotherm.
pub(crate) fn kramers_kronig_local(joint: &Prepared) -> Option<f64> {
    let (sy, ly) = (&joint.channels[0].0, &joint.channels[1].0);
    let mut r: Vec<f64> = joint
        .x
        .iter()
        .enumerate()
        .filter_map(|(i, &x)| {
            let slope = joint.channels[0].1.eval(x).1;
            // log10 of (π/2)·E′·slope / E″ = log10(π/2 · slope) + log10 E′ − log10 E″.
            (slope > 0.0).then(|| (std::f64::consts::FRAC_PI_2 * slope).log10() + sy[i] - ly[i])
        })
        .collect();
    if r.is_empty() {
        return None;
    }
    r.sort_by(f64::total_cmp);
    let m = r.len();
    Some(if m % 2 == 1 {
        r[m / 2]
    } else {
        0.5 * (r[m / 2 - 1] + r[m / 2])
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kk_rule_on_a_power_law() {
        // E′ = ω^n, E″ = tan(nπ/2) ω^n (the exact KK pair of a power law): the rule's ratio is
        // (nπ/2)/tan(nπ/2), 0.785 at n = ½ → log10 = −0.105.
        let n = 0.5;
        let xs: Vec<f64> = (0..11).map(|i| 0.3 * i as f64).collect();
        let p = Prepared::new(
            xs.clone(),
            vec![
                xs.iter().map(|x| n * x).collect(),
                xs.iter()
                    .map(|x| n * x + (n * std::f64::consts::FRAC_PI_2).tan().log10())
                    .collect(),
            ],
        );
        let want =
            ((n * std::f64::consts::FRAC_PI_2) / (n * std::f64::consts::FRAC_PI_2).tan()).log10();
        assert!((kramers_kronig_local(&p).unwrap() - want).abs() < 1e-12);
    }

    #[test]
    fn vgp_is_zero_for_shifted_copies_and_sees_a_change_of_shape() {
        // Horizontal shifts leave (|E*|, δ) unchanged: two isotherms sampled from one curve at
        // different frequencies give ~0 (linear interpolation error only); a changed E″ does not.
        let curve = |x: f64| (2.0 + 0.5 * x, 1.0 + 0.3 * x - 0.05 * x * x);
        let mk = |x0: f64, bump: f64| {
            let xs: Vec<f64> = (0..11).map(|i| x0 + 0.2 * i as f64).collect();
            Prepared::new(
                xs.clone(),
                vec![
                    xs.iter().map(|&x| curve(x).0).collect(),
                    xs.iter().map(|&x| curve(x).1 + bump).collect(),
                ],
            )
        };
        let same = van_gurp_palmen(&[mk(0.0, 0.0), mk(0.5, 0.0)], &[0.0, 0.0]);
        assert!(same[0].unwrap() < 0.2, "{:?}", same);
        let diff = van_gurp_palmen(&[mk(0.0, 0.0), mk(0.5, 0.5)], &[0.0, 0.0]);
        assert!(diff[0].unwrap() > 2.0, "{:?}", diff);
    }
}
