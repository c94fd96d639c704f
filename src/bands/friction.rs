//! Friction bands of one compound in one scene (docs/MATH.md §15, steps 4–5): every replicate of
//! the ensemble solved at every temperature of the scene, as a ratio to the fit's own friction
//! solved the same way, then the band of each point and of the scene mean.
//!
//! Input: a [`CompoundFit`] with its [`BandEnsemble`], a [`Scene`], [`BandSettings`]; output:
//! per temperature the replicate ratios F_b/F̂ ([`scene_ratios`]) and from them [`FrictionBand`]s
//! ([`band_of`], [`mean_band`]).

use super::BandSettings;
use crate::contact::body::layer::{roll_cover, ModelChoice};
use crate::contact::{roll, AutoSettings, ContactSettings, Scene, Scheme};
use crate::results::{BandEnsemble, CompoundFit, FrictionBand, FrictionPoint};
use crate::CreepSpectrum;
use rayon::prelude::*;

/// z of the 95th percentile of the standard normal: the bands are 90 % (p05 … p95).
pub const Z95: f64 = 1.644_853_626_951_472_2;

fn shifted(c: &CreepSpectrum, log10_a_t: f64) -> CreepSpectrum {
    let a = 10f64.powf(log10_a_t);
    let mut s = c.clone();
    for t in &mut s.terms {
        t.tau_s *= a;
    }
    s
}

/// The contact settings of the band solves: `auto` at `settings.contact_tol`, without the gap check.
pub fn band_contact_settings(settings: &BandSettings) -> ContactSettings {
    ContactSettings {
        scheme: Scheme::Auto,
        auto: AutoSettings {
            tol: settings.contact_tol,
            gap_check: false,
            ..AutoSettings::default()
        },
        ..ContactSettings::default()
    }
}

/// Relative tolerance of a covered scene's replicate solves (eq. 15.6): the bonded layer is solved
/// as in the main job's friction table (its `COVER_TOL`, 1e−3; measured errors 3e−6 … 3e−4 in ρF/N,
/// README), the nominal friction of the ratio at the same tolerance so most of it cancels; the
/// narrowest bands measured are ±0.5 %, and an independent error of 3e−4 widens one by < 1 %.
pub const COVER_BAND_TOL: f64 = 1e-3;

/// Per temperature of `temps_c`, the ratio F_b/F̂ of each replicate b (NaN where a solve failed),
/// both on the half-space of `scene` (its body is not used; [`scene_ratios_on`] with a cover solves
/// the covered body). Parallel over (temperature, replicate).
pub fn scene_ratios(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    scene: &Scene,
    temps_c: &[f64],
    settings: &BandSettings,
) -> Vec<Vec<f64>> {
    scene_ratios_on(fit, ensemble, scene, None, temps_c, settings)
}

/// [`scene_ratios`] on a cover of `cover_m` bonded to a rigid carcass (eq. 15.6): each replicate's
/// creep spectrum, shifted by its own law, through the body `auto` chooses
/// ([`roll_cover`], at [`COVER_BAND_TOL`] or the band tolerance if looser), as the nominal
/// friction; `None`: the half-space at `settings.contact_tol`.
pub fn scene_ratios_on(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    scene: &Scene,
    cover_m: Option<f64>,
    temps_c: &[f64],
    settings: &BandSettings,
) -> Vec<Vec<f64>> {
    let Some(creep) = fit.creep.as_ref() else {
        return temps_c.iter().map(|_| Vec::new()).collect();
    };
    let scene = Scene {
        body: crate::contact::Body::HalfSpace,
        ..*scene
    };
    let cs = band_contact_settings(settings);
    let cover_tol = settings.contact_tol.max(COVER_BAND_TOL);
    let law = &fit.shift_law;
    let solve = |c: &CreepSpectrum, log10_a_t: f64| {
        if !log10_a_t.is_finite() {
            return f64::NAN;
        }
        let at = shifted(c, log10_a_t);
        match cover_m {
            Some(h_m) => roll_cover(&scene, &at, Some(h_m), ModelChoice::Auto, cover_tol)
                .map_or(f64::NAN, |r| r.roll.friction),
            None => roll(&scene, &at, &cs).map_or(f64::NAN, |r| r.friction),
        }
    };
    let nominal: Vec<f64> = temps_c
        .par_iter()
        .map(|&t| solve(creep, law.log10_a_t(t)))
        .collect();
    let nb = ensemble.replicates.len();
    let flat: Vec<f64> = (0..temps_c.len() * nb)
        .into_par_iter()
        .map(|k| {
            let (i, b) = (k / nb, k % nb);
            let r = &ensemble.replicates[b];
            solve(&r.creep, r.log10_a_t(law, temps_c[i])) / nominal[i]
        })
        .collect();
    (0..temps_c.len())
        .map(|i| flat[i * nb..(i + 1) * nb].to_vec())
        .collect()
}

/// The band of `value` from replicate ratios (eq. 15.5): d_b = ln ratio_b, mean m and standard
/// deviation s over the finite ones; p50 = value·e^m, p05/p95 = value·e^(m ∓ z₀.₉₅ s). `None` with
/// fewer than 8 finite ratios or a non-finite value.
pub fn band_of(value: f64, ratios: &[f64]) -> Option<FrictionBand> {
    let d: Vec<f64> = ratios
        .iter()
        .filter(|r| r.is_finite() && **r > 0.0)
        .map(|r| r.ln())
        .collect();
    if d.len() < 8 || !value.is_finite() {
        return None;
    }
    let n = d.len() as f64;
    let m = d.iter().sum::<f64>() / n;
    let s = (d.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1.0)).sqrt();
    Some(FrictionBand {
        p05: value * (m - Z95 * s).exp(),
        p50: value * m.exp(),
        p95: value * (m + Z95 * s).exp(),
    })
}

/// The band of the mean friction over the points at `temps_c` (the temperatures a standing
/// averages): per replicate the mean of F_t·ratio_{b,t}, as a ratio to the mean of F_t; a
/// replicate with a failed solve at one of them is left out.
pub fn mean_band(
    points: &[FrictionPoint],
    ratios: &[Vec<f64>],
    temps_c: &[f64],
) -> Option<FrictionBand> {
    let used: Vec<usize> = temps_c
        .iter()
        .filter_map(|t| points.iter().position(|p| p.temp_c == *t))
        .collect();
    if used.is_empty()
        || used
            .iter()
            .any(|&i| ratios.get(i).map_or(true, |r| r.is_empty()))
    {
        return None;
    }
    let mean: f64 = used.iter().map(|&i| points[i].friction).sum::<f64>() / used.len() as f64;
    let nb = ratios[used[0]].len();
    let r: Vec<f64> = (0..nb)
        .map(|b| {
            used.iter()
                .map(|&i| points[i].friction * ratios[i].get(b).copied().unwrap_or(f64::NAN))
                .sum::<f64>()
                / used.len() as f64
                / mean
        })
        .collect();
    band_of(mean, &r)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_log_normal_sample_gives_its_percentiles() {
        // ratios e^(σ z_k) on evenly spaced normal quantiles z_k: m = 0, s ≈ σ, so the band is
        // value·e^(±1.645σ) to the accuracy of the sample standard deviation of 2000 quantiles.
        let sigma = 0.05;
        let n = 2000;
        let ratios: Vec<f64> = (0..n)
            .map(|k| {
                let u = (k as f64 + 0.5) / n as f64;
                // inverse normal by bisection on the erf-based cdf
                let (mut lo, mut hi) = (-8.0, 8.0);
                for _ in 0..80 {
                    let mid = 0.5 * (lo + hi);
                    if super::super::compare::normal_cdf(mid) < u {
                        lo = mid
                    } else {
                        hi = mid
                    }
                }
                (sigma * 0.5 * (lo + hi)).exp()
            })
            .collect();
        let b = band_of(2.0, &ratios).unwrap();
        assert!((b.p50 / 2.0 - 1.0).abs() < 1e-9, "{b:?}");
        // The sample sd of the quantile grid is within 0.5 % of σ (tails truncated at 1/2n).
        assert!(
            ((b.p95 / 2.0).ln() / (Z95 * sigma) - 1.0).abs() < 0.005,
            "{b:?}"
        );
        assert!(
            ((b.p05 / 2.0).ln() / (-Z95 * sigma) - 1.0).abs() < 0.005,
            "{b:?}"
        );
        assert!(band_of(2.0, &ratios[..5]).is_none());
        assert!(band_of(f64::NAN, &ratios).is_none());
    }
}
