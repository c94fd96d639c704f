//! The bootstrap ensemble of one compound's fit (docs/MATH.md §15, steps 1–3): the scatter of the
//! measurement estimated from the master curve, then `replicates` resampled master curves, each
//! refitted (Prony QP at the fit's own λ, exact creep conversion).
//!
//! Input: the [`MasterCurve`] the fit was made from, the [`Measurement`] (point temperatures) and
//! the [`CompoundFit`]; output: a [`BandEnsemble`] (saved in the fit file).

use super::error::BandError;
use super::rng::Rng;
use super::BandSettings;
use crate::prony::{fit_prony, MasterPoint, PronySettings, WeightRule};
use crate::results::{BandEnsemble, BandReplicate, CompoundFit, ScatterEstimate};
use crate::tts::MasterCurve;
use crate::Measurement;
use rayon::prelude::*;

/// The scatter inputs of the resampling, per master point and per isotherm.
struct Scatter {
    /// ln(E′/Ê′), ln(E″/Ê″) of each master point (eq. 15.1).
    residuals: Vec<(f64, f64)>,
    /// Fitted Ê′, Ê″ at each master point.
    fitted: Vec<(f64, f64)>,
    /// Isotherms in temperature order: (index in `MasterCurve::isotherms`, T °C, σ of the shift's
    /// random-walk increment from its inner neighbour (eq. 15.2), σ_T of its temperature, d log a_T/dT).
    chain: Vec<(usize, f64, f64, f64, f64)>,
    /// Position of the reference isotherm in `chain`.
    reference: usize,
    summary: ScatterEstimate,
}

fn rms(v: impl Iterator<Item = f64>) -> f64 {
    let (s, n) = v.fold((0.0, 0usize), |(s, n), x| (s + x * x, n + 1));
    if n == 0 {
        0.0
    } else {
        (s / n as f64).sqrt()
    }
}

/// Standard error of the mean of an isotherm's point temperatures (its drift), K; 0 without them.
fn temperature_std_k(measurement: &Measurement, index: usize) -> f64 {
    let Some(iso) = measurement.isotherms.get(index) else {
        return 0.0;
    };
    let t: Vec<f64> = iso
        .points
        .iter()
        .filter_map(|p| p.temp_c)
        .filter(|t| t.is_finite())
        .collect();
    if t.len() < 2 {
        return 0.0;
    }
    let n = t.len() as f64;
    let m = t.iter().sum::<f64>() / n;
    let var = t.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1.0);
    (var / n).sqrt()
}

fn scatter(
    master: &MasterCurve,
    measurement: &Measurement,
    fit: &CompoundFit,
) -> Result<Scatter, BandError> {
    let two_pi = 2.0 * std::f64::consts::PI;
    let mut residuals = Vec::with_capacity(master.points.len());
    let mut fitted = Vec::with_capacity(master.points.len());
    for p in &master.points {
        let w = two_pi * p.reduced_freq_hz;
        let (s, l) = (
            fit.relaxation.storage_modulus(w),
            fit.relaxation.loss_modulus(w),
        );
        let r = ((p.storage_pa / s).ln(), (p.loss_pa / l).ln());
        if !(r.0.is_finite() && r.1.is_finite()) {
            return Err(BandError::Scatter(format!(
                "the fit's residual at {:e} Hz is not finite",
                p.reduced_freq_hz
            )));
        }
        residuals.push(r);
        fitted.push((s, l));
    }
    let mut order: Vec<usize> = (0..master.isotherms.len()).collect();
    order.sort_by(|&a, &b| {
        master.isotherms[a]
            .temp_c
            .total_cmp(&master.isotherms[b].temp_c)
    });
    let sigma = |i: usize| {
        let s = master.isotherms[i].log10_a_t_std;
        if s.is_finite() {
            s
        } else {
            0.0
        }
    };
    let reference = (0..order.len())
        .min_by(|&a, &b| sigma(order[a]).total_cmp(&sigma(order[b])))
        .unwrap_or(0);
    let law = &fit.shift_law;
    let sigmas: Vec<f64> = order.iter().map(|&i| sigma(i)).collect();
    let incs = increments_of(&sigmas, reference);
    let chain: Vec<(usize, f64, f64, f64, f64)> = (0..order.len())
        .map(|k| {
            let i = order[k];
            let inc = incs[k];
            let t = master.isotherms[i].temp_c;
            let slope = (law.log10_a_t(t + 0.5) - law.log10_a_t(t - 0.5)) / 1.0;
            let t_std = temperature_std_k(measurement, master.isotherms[i].measurement_index);
            (
                i,
                t,
                inc,
                t_std,
                if slope.is_finite() { slope } else { 0.0 },
            )
        })
        .collect();
    let summary = ScatterEstimate {
        storage_rms_ln: rms(residuals.iter().map(|r| r.0)),
        loss_rms_ln: rms(residuals.iter().map(|r| r.1)),
        shift_std_max_log10: master
            .isotherms
            .iter()
            .map(|i| i.log10_a_t_std)
            .filter(|s| s.is_finite())
            .fold(0.0, f64::max),
        temp_std_max_k: chain.iter().map(|c| c.3).fold(0.0, f64::max),
        n_points: master.points.len(),
    };
    Ok(Scatter {
        residuals,
        fitted,
        chain,
        reference,
        summary,
    })
}

/// Shift errors along the temperature-ordered chain (eq. 15.2): 0 at `reference`, then each step
/// outwards adds `increments[k]`·z.
fn shift_walk(increments: &[f64], reference: usize, rng: &mut Rng) -> Vec<f64> {
    let n = increments.len();
    let mut walk = vec![0.0; n];
    for k in (reference + 1)..n {
        walk[k] = walk[k - 1] + increments[k] * rng.normal();
    }
    for k in (0..reference.min(n)).rev() {
        walk[k] = walk[k + 1] + increments[k] * rng.normal();
    }
    walk
}

/// The random-walk increment of each isotherm of the chain from the marginal standard errors
/// `sigma` (temperature order): √(max(σ_k² − M², 0)), M the largest σ between it and `reference`
/// (the walk's own σ there), 0 at `reference`. So the walk's σ at k is max(σ_k, M): each marginal
/// is kept, except where σ dips below an inner one (then the inner one's is kept).
fn increments_of(sigma: &[f64], reference: usize) -> Vec<f64> {
    let mut inc = vec![0.0; sigma.len()];
    let mut m = sigma.get(reference).copied().unwrap_or(0.0);
    for k in (reference + 1)..sigma.len() {
        inc[k] = (sigma[k].powi(2) - m * m).max(0.0).sqrt();
        m = m.max(sigma[k]);
    }
    let mut m = sigma.get(reference).copied().unwrap_or(0.0);
    for k in (0..reference.min(sigma.len())).rev() {
        inc[k] = (sigma[k].powi(2) - m * m).max(0.0).sqrt();
        m = m.max(sigma[k]);
    }
    inc
}

/// One replicate (eqs. 15.2–15.4): shifts by a random walk out from the reference isotherm,
/// moduli the fitted ones times a wild-bootstrap residual, refitted.
fn replicate(
    master: &MasterCurve,
    fit: &CompoundFit,
    sc: &Scatter,
    prony: &PronySettings,
    rng: &mut Rng,
) -> Result<BandReplicate, String> {
    let n = sc.chain.len();
    // Shift error of each isotherm (indexed like MasterCurve::isotherms) and law offset at its T.
    let mut delta = vec![0.0; master.isotherms.len()];
    let mut offsets = Vec::with_capacity(n);
    let increments: Vec<f64> = sc.chain.iter().map(|c| c.2).collect();
    let walk = shift_walk(&increments, sc.reference, rng);
    for (k, &(i, t, _, t_std, slope)) in sc.chain.iter().enumerate() {
        delta[i] = walk[k];
        offsets.push((t, walk[k] + slope * t_std * rng.normal()));
    }
    let mut points: Vec<MasterPoint> = master
        .points
        .iter()
        .zip(&sc.residuals)
        .zip(&sc.fitted)
        .map(|((p, r), f)| MasterPoint {
            reduced_freq_hz: p.reduced_freq_hz * 10f64.powf(delta[p.isotherm]),
            storage_pa: f.0 * (r.0 * rng.normal()).exp(),
            loss_pa: f.1 * (r.1 * rng.normal()).exp(),
        })
        .collect();
    points.sort_by(|a, b| a.reduced_freq_hz.total_cmp(&b.reduced_freq_hz));
    let refit = fit_prony(&points, fit.relaxation.kind, fit.relaxation.poisson, prony)
        .map_err(|e| e.to_string())?;
    let (creep, _) =
        crate::creep::relaxation_to_creep(&refit.spectrum).map_err(|e| e.to_string())?;
    Ok(BandReplicate {
        creep,
        shift_offsets: offsets,
    })
}

/// The verdict on the refits, `failed` the reasons of those that failed out of `asked`: refused
/// when more than a quarter failed ([`super::too_many_failed`]), else the ensemble's notes (how
/// many of how many failed and the first reason; none when none failed).
fn refit_verdict(failed: &[&String], asked: usize) -> Result<Vec<String>, BandError> {
    if super::friction::too_many_failed(failed.len(), asked) {
        return Err(BandError::TooFewReplicates {
            ok: asked - failed.len(),
            asked,
            first: failed.first().map_or(String::new(), |s| s.to_string()),
        });
    }
    Ok(failed
        .first()
        .map(|first| {
            crate::results::cap_line(&format!(
                "{} of {asked} bootstrap refits failed and were left out (first: {first})",
                failed.len()
            ))
        })
        .into_iter()
        .collect())
}

/// The bootstrap ensemble of `fit` (made from `master` of `measurement`), in parallel over
/// replicates. Errors when the scatter cannot be estimated or more than a quarter of the refits
/// fail (crate::bands::too_many_failed); when fewer fail, the ensemble's notes say how many of how
/// many and the first reason (they reach friction.csv, the datasheet and the ranking).
pub fn build_ensemble(
    master: &MasterCurve,
    measurement: &Measurement,
    fit: &CompoundFit,
    settings: &BandSettings,
) -> Result<BandEnsemble, BandError> {
    settings.validate()?;
    let sc = scatter(master, measurement, fit)?;
    // The fit's own λ (no λ search): one QP per replicate instead of `lambda_count`.
    let prony = PronySettings {
        weight_rule: WeightRule::Fixed {
            lambda: fit.prony_info.lambda,
        },
        ..fit.settings.prony.clone()
    };
    let results: Vec<Result<BandReplicate, String>> = (0..settings.replicates)
        .into_par_iter()
        .map(|b| {
            let mut rng = Rng::new(settings.seed, b as u64);
            replicate(master, fit, &sc, &prony, &mut rng)
        })
        .collect();
    let failed: Vec<&String> = results.iter().filter_map(|r| r.as_ref().err()).collect();
    let replicates: Vec<BandReplicate> = results.iter().filter_map(|r| r.clone().ok()).collect();
    let notes = refit_verdict(&failed, settings.replicates)?;
    Ok(BandEnsemble {
        method: format!(
            "residual bootstrap of the master curve (wild, Gaussian weights) with isotherm shifts drawn as a random walk from the shift stage's standard errors and isotherm temperatures from their drift; Prony refit at λ = {:e}, exact creep conversion",
            fit.prony_info.lambda
        ),
        replicates_requested: settings.replicates,
        seed: settings.seed,
        scatter: sc.summary,
        replicates,
        notes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn failed_refits_are_counted_and_more_than_a_quarter_refuse_the_ensemble() {
        let why = "prony: QP did not converge".to_string();
        assert!(refit_verdict(&[], 32).unwrap().is_empty());
        // 8 of 32: a quarter, kept, the note says how many of how many and why
        let notes = refit_verdict(&[&why; 8], 32).unwrap();
        assert_eq!(
            notes,
            ["8 of 32 bootstrap refits failed and were left out (first: prony: QP did not converge)"]
        );
        // 9 of 32: refused, the error says so with the reason
        let e = refit_verdict(&[&why; 9], 32).unwrap_err().to_string();
        assert!(
            e.contains("only 23 of 32") && e.contains("more than a quarter") && e.contains("QP"),
            "{e}"
        );
    }

    #[test]
    fn the_shift_walk_keeps_each_marginal_standard_error() {
        // Marginal σ growing outwards from the reference (index 2), with one dip (index 4 below
        // index 3: its increment is 0, so it keeps index 3's σ, the only place the walk is off).
        let sigma = [0.03, 0.012, 0.0, 0.01, 0.008, 0.02];
        let inc = increments_of(&sigma, 2);
        let want = [0.03, 0.012, 0.0, 0.01, 0.01, 0.02];
        let n = 40_000;
        let mut sum2 = [0.0; 6];
        let mut cross = 0.0;
        let mut rng = Rng::new(3, 0);
        for _ in 0..n {
            let w = shift_walk(&inc, 2, &mut rng);
            for k in 0..6 {
                sum2[k] += w[k] * w[k];
            }
            cross += w[0] * w[1];
        }
        for k in 0..6 {
            let sd = (sum2[k] / n as f64).sqrt();
            // The sample sd of 40 000 draws is within 1/√(2n) ≈ 0.35 % of σ; 1.5 % is > 4 of those.
            if want[k] == 0.0 {
                assert_eq!(sd, 0.0);
            } else {
                assert!(
                    (sd / want[k] - 1.0).abs() < 0.015,
                    "{k}: {sd} vs {}",
                    want[k]
                );
            }
        }
        // Neighbours share the walk: corr(δ0, δ1) = σ1/σ0 = 0.4 (independent draws would give 0).
        let corr = cross / n as f64 / (want[0] * want[1]);
        assert!((corr - 0.4).abs() < 0.03, "{corr}");
    }
}
