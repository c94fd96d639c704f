//! Pairs of compounds in one scene (docs/MATH.md §15, step 6): the probability that A's mean
//! friction is below B's, from their bands, and the ties.
//!
//! Input: (compound, band of its scene mean) of the ranked compounds; output: [`PairComparison`]s.

use super::friction::Z95;
use crate::results::{FrictionBand, PairComparison};

/// An order is significant when its probability reaches this level (one-sided 95 %); a pair whose
/// P(A < B) lies strictly between 0.05 and 0.95 is tied.
pub const SIGNIFICANCE: f64 = 0.95;

/// Φ(x), the standard normal distribution function, from erf by Abramowitz & Stegun (1964),
/// eq. 7.1.26: absolute error below 1.5e-7 in erf, so below 7.5e-8 in Φ.
pub(crate) fn normal_cdf(x: f64) -> f64 {
    let z = x.abs() / std::f64::consts::SQRT_2;
    let t = 1.0 / (1.0 + 0.327_591_1 * z);
    let poly = t
        * (0.254_829_592
            + t * (-0.284_496_736
                + t * (1.421_413_741 + t * (-1.453_152_027 + t * 1.061_405_429))));
    // erfc(z) = poly·e^(−z²) for z ≥ 0
    let half_erfc = 0.5 * poly * (-z * z).exp();
    if x >= 0.0 {
        1.0 - half_erfc
    } else {
        half_erfc
    }
}

/// (centre, log standard deviation) of a band read as log-normal: ln p50 and ln(p95/p05)/(2 z).
fn log_normal(b: &FrictionBand) -> (f64, f64) {
    (b.p50.ln(), (b.p95 / b.p05).ln() / (2.0 * Z95))
}

/// P(F_A < F_B) for independent log-normal F_A, F_B with these bands (eq. 15.7).
pub fn prob_lower(a: &FrictionBand, b: &FrictionBand) -> f64 {
    let ((ma, sa), (mb, sb)) = (log_normal(a), log_normal(b));
    let s = (sa * sa + sb * sb).sqrt();
    if s > 0.0 && s.is_finite() {
        normal_cdf((mb - ma) / s)
    } else if ma < mb {
        1.0
    } else if ma > mb {
        0.0
    } else {
        0.5
    }
}

/// Whether a probability P(A < B) makes the pair tied: strictly between 1 − [`SIGNIFICANCE`] and
/// [`SIGNIFICANCE`].
pub fn is_tie(p: f64) -> bool {
    p < SIGNIFICANCE && p > 1.0 - SIGNIFICANCE
}

/// A probability as printed: two decimals, or as many more (up to six) as it takes for the printed
/// number to fall on the same side of the tie rule as the probability itself (issue 31: no "tied
/// (P = 0.95)" for 0.946).
pub fn prob_text(p: f64) -> String {
    for d in 2..=6 {
        let t = format!("{p:.d$}");
        if t.parse::<f64>().is_ok_and(|q| is_tie(q) == is_tie(p)) {
            return t;
        }
    }
    format!("{p:.6}")
}

/// Every pair (in the order given: the ranking's) of `ranked` compounds with a band.
pub fn comparisons(scene: &str, ranked: &[(String, FrictionBand)]) -> Vec<PairComparison> {
    let mut v = Vec::new();
    for i in 0..ranked.len() {
        for j in i + 1..ranked.len() {
            let p = prob_lower(&ranked[i].1, &ranked[j].1);
            v.push(PairComparison {
                scene: scene.to_string(),
                a: ranked[i].0.clone(),
                b: ranked[j].0.clone(),
                prob_a_lower: p,
                tied: is_tie(p),
            });
        }
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_cdf_matches_tabulated_values() {
        // Φ(0) = 0.5, Φ(1.644854) = 0.95, Φ(1.959964) = 0.975, Φ(−3) = 0.0013498980 (tables);
        // the formula's bound 7.5e-8 plus the tables' last digit.
        assert!((normal_cdf(0.0) - 0.5).abs() < 1e-7);
        assert!((normal_cdf(1.644_853_6) - 0.95).abs() < 1e-7);
        assert!((normal_cdf(1.959_964) - 0.975).abs() < 1e-7);
        assert!((normal_cdf(-3.0) - 0.001_349_898_0).abs() < 1e-7);
    }

    #[test]
    fn printed_probabilities_fall_on_the_side_of_the_tie_rule_they_are_on() {
        assert_eq!(prob_text(0.946), "0.946");
        assert_eq!(prob_text(0.9499), "0.9499");
        assert_eq!(prob_text(0.951), "0.95");
        assert_eq!(prob_text(0.0504), "0.0504");
        assert_eq!(prob_text(0.5), "0.50");
        assert_eq!(prob_text(0.99996), "1.00");
        // every printed value reads back with its probability's verdict
        for k in 0..=10_000 {
            let p = k as f64 / 10_000.0;
            let q: f64 = prob_text(p).parse().unwrap();
            assert_eq!(is_tie(q), is_tie(p), "{p} printed {}", prob_text(p));
        }
    }

    #[test]
    fn equal_bands_tie_and_separated_bands_do_not() {
        let band = |c: f64, s: f64| FrictionBand {
            p05: c * (-Z95 * s).exp(),
            p50: c,
            p95: c * (Z95 * s).exp(),
        };
        let a = band(1.0, 0.05);
        // Φ(0) by the formula: 0.5 to its bound (the coefficients sum to 1 − 1e-9).
        assert!((prob_lower(&a, &a) - 0.5).abs() < 1e-8);
        // ln ratio 0.2 against √2·0.05: z = 2.83, P = 0.99766.
        let b = band(0.2f64.exp(), 0.05);
        let p = prob_lower(&a, &b);
        assert!((p - normal_cdf(0.2 / (0.05 * 2f64.sqrt()))).abs() < 1e-12 && p > 0.997);
        let c = comparisons("s", &[("a".into(), a), ("b".into(), b), ("c".into(), a)]);
        assert_eq!(c.len(), 3);
        assert!(!c[0].tied && c[1].tied && !c[2].tied, "{c:?}");
        assert!((prob_lower(&b, &a) + p - 1.0).abs() < 2e-7);
    }
}
