//! The bootstrap ensemble of one compound's fit (docs/MATH.md §15, steps 1–3): the scatter of the
//! measurement estimated from the master curve, then `replicates` resampled master curves, each
//! refitted (Prony QP, exact creep conversion). Each replicate also draws the fit's own choices
//! (super::model, eqs. 15.10–15.12): the shift criterion, the shift table's interpolation, the
//! regularisation weight λ and the relaxation-time grid's positions.
//!
//! Input: the [`MasterCurve`] the fit was made from, the [`Measurement`] (point temperatures, the
//! other criteria's shiftings) and the [`CompoundFit`]; output: a [`BandEnsemble`] (saved in the
//! fit file).

use super::error::BandError;
use super::model::{model_choices, ModelChoices, LAMBDA_SPREAD_DECADES};
use super::rng::Rng;
use super::BandSettings;
use crate::prony::{fit_prony, MasterPoint, PronySettings, WeightRule};
use crate::results::{
    offset_at, BandEnsemble, BandReplicate, CompoundFit, ModelErrorSummary, ScatterEstimate,
};
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
    /// Lower Cholesky factor of the shifts' covariance (docs/MATH.md eq. 6.2), indexed like
    /// `MasterCurve::isotherms`; `None` where the master curve has none (given shifts, an older
    /// file) or it is not positive semi-definite: then the random walk of eq. 15.2.
    shift_factor: Option<nalgebra::DMatrix<f64>>,
    /// The points' weights in the refits, as in the fit (docs/MATH.md eq. 5.1).
    weights: Vec<[f64; 2]>,
    summary: ScatterEstimate,
}

/// The lower Cholesky factor of a shift covariance (zero rows and columns, the reference's, kept
/// as zero): `None` unless it is square over `n` isotherms, finite and positive semi-definite
/// (a diagonal jitter of 1e-12 of its largest variance allowed for round-off).
fn shift_factor(cov: &[Vec<f64>], n: usize) -> Option<nalgebra::DMatrix<f64>> {
    if cov.len() != n
        || cov
            .iter()
            .any(|r| r.len() != n || r.iter().any(|v| !v.is_finite()))
    {
        return None;
    }
    let live: Vec<usize> = (0..n).filter(|&i| cov[i][i] > 0.0).collect();
    let top = live.iter().map(|&i| cov[i][i]).fold(0.0, f64::max);
    let m = nalgebra::DMatrix::from_fn(live.len(), live.len(), |a, b| {
        cov[live[a]][live[b]] + if a == b { 1e-12 * top } else { 0.0 }
    });
    let l = m.cholesky()?.l();
    let mut full = nalgebra::DMatrix::zeros(n, n);
    for (a, &i) in live.iter().enumerate() {
        for (b, &j) in live.iter().enumerate() {
            full[(i, j)] = l[(a, b)];
        }
    }
    Some(full)
}

fn rms(v: impl Iterator<Item = f64>) -> f64 {
    let (s, n) = v.fold((0.0, 0usize), |(s, n), x| (s + x * x, n + 1));
    if n == 0 {
        0.0
    } else {
        (s / n as f64).sqrt()
    }
}

/// Standard error of an isotherm's temperature from its point temperatures, K; 0 without them.
/// With `along_trend` (the master curve moved every point to its isotherm's temperature along the
/// drift, crate::tts::point_temps) the scatter about the least-squares line through the sweep,
/// over n − 2: the drift itself is measured and corrected, so only the readings' jitter leaves the
/// isotherm's temperature uncertain (on the synthetic exports, ±1 K of drift per sweep but 0.05 K of
/// jitter: sd/√n of the raw readings, 0.08–0.16 K, put 0.01–0.05 decade of spurious shift error on
/// the cold isotherms). Without it, the scatter about the mean (the drift uncorrected).
fn temperature_std_k(measurement: &Measurement, index: usize, along_trend: bool) -> f64 {
    let Some(iso) = measurement.isotherms.get(index) else {
        return 0.0;
    };
    let t: Vec<f64> = iso
        .points
        .iter()
        .filter_map(|p| p.temp_c)
        .filter(|t| t.is_finite())
        .collect();
    let n = t.len() as f64;
    if t.len() < if along_trend { 3 } else { 2 } {
        return 0.0;
    }
    let m = t.iter().sum::<f64>() / n;
    if !along_trend {
        let var = t.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1.0);
        return (var / n).sqrt();
    }
    let mk = (n - 1.0) / 2.0;
    let (mut sxy, mut sxx) = (0.0, 0.0);
    for (k, x) in t.iter().enumerate() {
        sxy += (k as f64 - mk) * (x - m);
        sxx += (k as f64 - mk).powi(2);
    }
    let b = sxy / sxx;
    let rss: f64 = t
        .iter()
        .enumerate()
        .map(|(k, x)| (x - m - b * (k as f64 - mk)).powi(2))
        .sum();
    (rss / (n - 2.0) / n).sqrt()
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
            let t_std = temperature_std_k(
                measurement,
                master.isotherms[i].measurement_index,
                master.settings.correct_point_temperatures,
            );
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
        shift_factor: shift_factor(
            &master.quality.shift_covariance_log10,
            master.isotherms.len(),
        ),
        weights: crate::tts::point_weights(master),
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

/// One replicate (eqs. 15.2–15.4, 15.10–15.12): shifts drawn from their covariance (or by a
/// random walk out from the reference isotherm) plus one other criterion's difference, the law's interpolation error at the middle of
/// each interval, moduli the fitted ones times a wild-bootstrap residual, refitted at a λ and on a
/// relaxation-time grid of its own.
fn replicate(
    master: &MasterCurve,
    fit: &CompoundFit,
    sc: &Scatter,
    choices: &ModelChoices,
    prony: &PronySettings,
    jitter: bool,
    rng: &mut Rng,
) -> Result<BandReplicate, String> {
    let n = sc.chain.len();
    // Shift error of each isotherm (indexed like MasterCurve::isotherms) and law offset at its T.
    let mut delta = vec![0.0; master.isotherms.len()];
    let mut offsets = Vec::with_capacity(2 * n);
    // Eq. 15.2: the shifts' errors drawn from their covariance (eq. 6.2), else by the walk.
    let walk: Vec<f64> = match &sc.shift_factor {
        Some(l) => {
            let z = nalgebra::DVector::from_fn(l.ncols(), |_, _| rng.normal());
            let d = l * z;
            sc.chain.iter().map(|c| d[c.0]).collect()
        }
        None => {
            let increments: Vec<f64> = sc.chain.iter().map(|c| c.2).collect();
            shift_walk(&increments, sc.reference, rng)
        }
    };
    // Eq. 15.10: one other criterion, weighted by a standard normal.
    let criterion = match choices.criteria.len() {
        0 => None,
        k => {
            let c = ((rng.uniform() * k as f64) as usize).min(k - 1);
            Some((&choices.criteria[c].1, rng.normal()))
        }
    };
    for (k, &(i, t, _, t_std, slope)) in sc.chain.iter().enumerate() {
        let model = criterion.map_or(0.0, |(d, w)| w * d.get(i).copied().unwrap_or(0.0));
        delta[i] = walk[k] + model;
        offsets.push((t, delta[i] + slope * t_std * rng.normal()));
    }
    // Eq. 15.11: the interpolation error at each interval's middle, one draw per replicate.
    offsets.sort_by(|a, b| a.0.total_cmp(&b.0));
    // (No draw without intervals, so the ensemble without model error is the one before issue 32.)
    let v = if choices.interpolation.is_empty() {
        0.0
    } else {
        rng.normal()
    };
    let mids: Vec<(f64, f64)> = choices
        .interpolation
        .iter()
        .map(|&(t, amp)| (t, offset_at(&offsets, t) + v * amp))
        .collect();
    offsets.extend(mids);
    offsets.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut points: Vec<MasterPoint> = master
        .points
        .iter()
        .zip(&sc.residuals)
        .zip(&sc.fitted)
        .zip(&sc.weights)
        .map(|(((p, r), f), &weight)| MasterPoint {
            reduced_freq_hz: p.reduced_freq_hz * 10f64.powf(delta[p.isotherm]),
            storage_pa: f.0 * (r.0 * rng.normal()).exp(),
            loss_pa: f.1 * (r.1 * rng.normal()).exp(),
            weight,
        })
        .collect();
    points.sort_by(|a, b| a.reduced_freq_hz.total_cmp(&b.reduced_freq_hz));
    // Eq. 15.12: λ within the search's step either way, the τ grid moved within its own step.
    let step = 1.0 / prony.terms_per_decade;
    let (u, u_lambda) = if jitter {
        (rng.uniform(), 2.0 * rng.uniform() - 1.0)
    } else {
        (0.0, 0.0)
    };
    let moved = prony.margin_decades + u * step;
    let drawn = PronySettings {
        weight_rule: WeightRule::Fixed {
            lambda: fit.prony_info.lambda * 10f64.powf(LAMBDA_SPREAD_DECADES * u_lambda),
        },
        margin_decades: if moved <= 3.0 {
            moved
        } else {
            (moved - step).max(0.0)
        },
        ..prony.clone()
    };
    let (kind, poisson) = (fit.relaxation.kind, fit.relaxation.poisson);
    let refit = fit_prony(&points, kind, poisson, &drawn).map_err(|e| e.to_string())?;
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
    let choices = if settings.model_error {
        model_choices(master, measurement)
    } else {
        ModelChoices::default()
    };
    // Around the fit's own λ (no λ search): one QP per replicate instead of `lambda_count`.
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
            replicate(
                master,
                fit,
                &sc,
                &choices,
                &prony,
                settings.model_error,
                &mut rng,
            )
        })
        .collect();
    let failed: Vec<&String> = results.iter().filter_map(|r| r.as_ref().err()).collect();
    let replicates: Vec<BandReplicate> = results.iter().filter_map(|r| r.clone().ok()).collect();
    let notes = refit_verdict(&failed, settings.replicates)?;
    Ok(BandEnsemble {
        method: format!(
            "residual bootstrap of the master curve (wild, Gaussian weights) with isotherm shifts drawn from the shift stage's covariance (a random walk from its standard errors where it has none) and isotherm temperatures from their drift; the fit's choices drawn too: another shift criterion's shifts, the shift table's interpolation error, λ within a decade of {:e} and the relaxation-time grid moved within its step; Prony refit, exact creep conversion",
            fit.prony_info.lambda
        ),
        model_error: settings.model_error.then(|| ModelErrorSummary {
            criteria: choices.criteria.iter().map(|c| c.0.to_string()).collect(),
            criterion_max_log10: choices.criterion_max_log10(),
            interpolation_max_log10: choices.interpolation_max_log10(),
            lambda_spread_decades: LAMBDA_SPREAD_DECADES,
        }),
        replicates_requested: settings.replicates,
        seed: settings.seed,
        scatter: sc.summary,
        replicates,
        notes,
    })
}

/// Note of an ensemble made from a fit file alone ([`ensemble_from_fit`]).
pub const FROM_FIT_FILE_NOTE: &str = "made from the fit file alone (it carried no ensemble): the \
     scatter of the master curve about the fit and the fit's regularisation and term positions are \
     in the band; the shifts' own scatter and the other shift criteria are not (they need the \
     isotherms: `viscoroll fit` on the measurement adds them)";

/// An ensemble for a fit file that carries none (`fit --no-bands`, a fit file from before fits
/// carried one, a master curve read already shifted): the fit's own master-curve points as one
/// isotherm at T_ref (crate::tts::master_curve_from_reduced) bootstrapped as in [`build_ensemble`].
/// The shifts cannot be resampled without the isotherms, so the band lacks their scatter; its notes
/// say so (`FROM_FIT_FILE_NOTE`).
pub fn ensemble_from_fit(
    fit: &CompoundFit,
    settings: &BandSettings,
) -> Result<BandEnsemble, BandError> {
    let t_ref = fit.shift_law.t_ref_c();
    let points = fit
        .master_curve
        .iter()
        .enumerate()
        .map(|(k, p)| crate::dma::DataPoint {
            freq_hz: p.reduced_freq_hz,
            storage_pa: p.storage_pa,
            loss_pa: p.loss_pa,
            temp_c: None,
            line: k + 1,
            flags: Vec::new(),
        })
        .collect();
    let measurement = Measurement {
        sources: Vec::new(),
        kind: fit.relaxation.kind,
        poisson: fit.relaxation.poisson,
        isotherms: vec![crate::dma::Isotherm {
            temp_nominal_c: t_ref,
            temp_mean_c: t_ref,
            source: 0,
            points,
            nominal_source: "fit file".into(),
            sheet: None,
            label: None,
        }],
        warnings: Vec::new(),
        issues: Vec::new(),
        summary: Default::default(),
    };
    let master = crate::tts::master_curve_from_reduced(&measurement, &fit.shift_law)
        .map_err(|e| BandError::Scatter(format!("the fit file's master curve: {e}")))?;
    let mut e = build_ensemble(&master, &measurement, fit, settings)?;
    e.notes.push(FROM_FIT_FILE_NOTE.to_string());
    Ok(e)
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
