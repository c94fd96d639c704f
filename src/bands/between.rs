//! The spread between replicate specimens (docs/MATH.md §16), added to a band as one more term.
//!
//! Input: each specimen's friction at a point (or of a scene mean) and the number of specimens the
//! compound's fit pools; output: the between-specimen standard deviation of ln F
//! ([`between_sd_ln`]) and the band widened by it ([`widen`]). The bands of crate::bands::scene
//! come from one specimen's scatter (its residuals and shifts); two specimens of one material
//! differ by more than that (the shipped EMS-CA pair: 1.5–3.1× in F/N). So every band and every
//! P(lower) carries the between-specimen term, estimated from the replicates when the compound has
//! them, else the stated prior [`PRIOR_SD_LN`].
//!
//! Math (§16): with n specimens' ln F_i at a point, the sum of squares SS = Σ(ln F_i − mean)² has
//! n − 1 degrees of freedom; the prior s₀ counts as ν₀ = `PRIOR_DOF` more (a scaled inverse-χ²
//! prior): s² = (ν₀ s₀² + SS)/(ν₀ + n − 1) (eq. 16.2). The fit pools the n specimens, so it
//! estimates their mean, whose between-specimen variance is s²/n; each half of the band (in ln F)
//! grows to √(h² + z₀.₉₅² s²/n) (eq. 16.3).

use super::friction::Z95;
use crate::results::FrictionBand;

/// Prior standard deviation of ln F/N between two specimens of one compound, when the compound
/// has a single specimen (docs/MATH.md §16): from the only replicate pair shipped, the two EMS-CA
/// specimens, each fitted alone and rolled in the shipped scenes. Over its 27 scene points,
/// s₀² = mean of (ln F₁/F₂)²/2 (each pair one degree of freedom; eq. 16.4), recomputed by
/// `tests/replicates.rs`.
pub const PRIOR_SD_LN: f64 = 0.55;

/// Weight of [`PRIOR_SD_LN`] in degrees of freedom (eq. 16.2): one, since it comes from one pair
/// of specimens (its 27 points are of the same two specimens, not independent).
pub(crate) const PRIOR_DOF: f64 = 1.0;

/// Standard deviation of ln F between specimens from the specimens' frictions at one point (or
/// scene mean), pooled with the prior (eq. 16.2); the prior alone with fewer than two finite
/// positive values.
pub fn between_sd_ln(frictions: &[f64]) -> f64 {
    let d: Vec<f64> = frictions
        .iter()
        .filter(|f| f.is_finite() && **f > 0.0)
        .map(|f| f.ln())
        .collect();
    if d.len() < 2 {
        return PRIOR_SD_LN;
    }
    let m = d.iter().sum::<f64>() / d.len() as f64;
    let ss: f64 = d.iter().map(|x| (x - m) * (x - m)).sum();
    ((PRIOR_DOF * PRIOR_SD_LN * PRIOR_SD_LN + ss) / (PRIOR_DOF + (d.len() - 1) as f64)).sqrt()
}

/// `band` with the between-specimen term of `specimens` specimens whose mean the fit is, each
/// half grown in quadrature (eq. 16.3); p50 stays.
pub fn widen(band: FrictionBand, sd_ln: f64, specimens: usize) -> FrictionBand {
    let add = (Z95 * sd_ln).powi(2) / specimens.max(1) as f64;
    let lo = (band.p50 / band.p05).ln();
    let hi = (band.p95 / band.p50).ln();
    FrictionBand {
        p05: band.p50 * (-(lo * lo + add).sqrt()).exp(),
        p50: band.p50,
        p95: band.p50 * (hi * hi + add).sqrt().exp(),
    }
}

/// The words every band and comparison of a compound carries about the specimens it covers.
pub fn specimens_note(specimens: usize, sd_ln: f64) -> String {
    if specimens <= 1 {
        format!(
            "one specimen measured: the band covers that specimen's measurement, plus the default \
             between-specimen spread s = {PRIOR_SD_LN} (ln F, from the two shipped EMS-CA \
             specimens, docs/MATH.md §16)"
        )
    } else {
        format!(
            "{specimens} specimens pooled: the band includes the spread between them, s = \
             {sd_ln:.2} (ln F, with the default prior, docs/MATH.md §16)"
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sd_pools_the_data_with_the_prior() {
        // one value: the prior alone
        assert_eq!(between_sd_ln(&[2.0]), PRIOR_SD_LN);
        // two values a factor e apart: SS = 2·(1/2)² = 1/2, one degree of freedom
        let want = ((PRIOR_DOF * PRIOR_SD_LN.powi(2) + 0.5) / (PRIOR_DOF + 1.0)).sqrt();
        assert!((between_sd_ln(&[1.0, std::f64::consts::E]) - want).abs() < 1e-15);
        // many equal specimens pull the estimate towards zero, as the data say
        assert!(between_sd_ln(&[3.0; 50]) < PRIOR_SD_LN / 7.0 + 1e-12);
        // failed values do not count
        assert_eq!(between_sd_ln(&[f64::NAN, 1.0]), PRIOR_SD_LN);
    }

    #[test]
    fn widening_adds_in_quadrature_and_keeps_the_centre() {
        let b = FrictionBand {
            p05: 0.5,
            p50: 1.0,
            p95: 4.0,
        };
        let w = widen(b, 0.0, 1);
        assert!((w.p05 - 0.5).abs() < 1e-15 && (w.p95 - 4.0).abs() < 1e-14);
        let w = widen(b, 0.3, 2);
        let add = (Z95 * 0.3).powi(2) / 2.0;
        assert_eq!(w.p50, 1.0);
        assert!((w.p05.ln() + (2f64.ln().powi(2) + add).sqrt()).abs() < 1e-14);
        assert!((w.p95.ln() - (4f64.ln().powi(2) + add).sqrt()).abs() < 1e-14);
        // a zero-width band becomes ± z·s/√n
        let z = widen(
            FrictionBand {
                p05: 1.0,
                p50: 1.0,
                p95: 1.0,
            },
            0.3,
            4,
        );
        assert!((z.p95.ln() - Z95 * 0.3 / 2.0).abs() < 1e-15);
    }
}
