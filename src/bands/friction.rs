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

/// Replicates of a covered scene whose ratios are solved on the covered body itself (eq. 15.6b);
/// the others are predicted from their half-space ratios by a regression on these. Eight: the
/// regression then has 6 degrees of freedom for its residual; checked against the full bootstrap
/// on the shipped compounds (`cargo bench --bench bands_cover`, README).
pub const COVER_SOLVED_REPLICATES: usize = 8;

/// What [`scene_bands_on`] hands on: per temperature the replicate ratios F_b/F̂ (with the
/// extrapolation term already drawn into them) and the extrapolation term's log standard deviation
/// (`None` at a measured temperature; eq. 15.8).
#[derive(Debug, Clone, PartialEq)]
pub struct SceneRatios {
    /// Per temperature, per replicate, F_b/F̂ (NaN where a solve failed).
    pub ratios: Vec<Vec<f64>>,
    /// Per temperature, the shift-law tail term s_tail of eq. 15.8 (ln F), `None` inside the
    /// measured temperatures.
    pub tail_ln: Vec<Option<f64>>,
}

/// [`scene_ratios`] on a cover of `cover_m` bonded to a rigid carcass (eq. 15.6): each replicate's
/// creep spectrum, shifted by its own law, through the body `auto` chooses
/// ([`roll_cover`], at [`COVER_BAND_TOL`] or the band tolerance if looser), as the nominal
/// friction; `None`: the half-space at `settings.contact_tol`. On a cover, only
/// [`COVER_SOLVED_REPLICATES`] replicates are solved on the cover; the rest come from their
/// half-space ratios (eq. 15.6b, [`predict_from_half_space`]). Points beyond the measured
/// temperatures get the shift-law tail term of eq. 15.8 ([`scene_bands_on`]).
pub fn scene_ratios_on(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    scene: &Scene,
    cover_m: Option<f64>,
    temps_c: &[f64],
    settings: &BandSettings,
) -> Vec<Vec<f64>> {
    scene_bands_on(fit, ensemble, scene, cover_m, temps_c, settings).ratios
}

/// The solver of one scene for the bands: F/N of a creep spectrum at log10 a_T on the half-space
/// or the cover (NaN on failure).
fn solver<'a>(
    scene: &'a Scene,
    cover_m: Option<f64>,
    settings: &BandSettings,
) -> impl Fn(&CreepSpectrum, f64) -> f64 + Sync + 'a {
    let scene = Scene {
        body: crate::contact::Body::HalfSpace,
        ..*scene
    };
    let cs = band_contact_settings(settings);
    let cover_tol = settings.contact_tol.max(COVER_BAND_TOL);
    move |c: &CreepSpectrum, log10_a_t: f64| {
        if !log10_a_t.is_finite() {
            return f64::NAN;
        }
        let at = shifted(c, log10_a_t);
        match cover_m {
            Some(h_m) => roll_cover(&scene, &at, Some(h_m), ModelChoice::Auto, cover_tol)
                .map_or(f64::NAN, |r| r.roll.friction),
            None => roll(&scene, &at, &cs).map_or(f64::NAN, |r| r.friction),
        }
    }
}

/// Per temperature, the ratios F_b/F̂ of the replicates `which` (indices into the ensemble), solved
/// by `solve`; parallel over (temperature, replicate).
fn solved_ratios(
    fit: &CompoundFit,
    creep: &CreepSpectrum,
    ensemble: &BandEnsemble,
    temps_c: &[f64],
    which: &[usize],
    solve: &(dyn Fn(&CreepSpectrum, f64) -> f64 + Sync),
) -> Vec<Vec<f64>> {
    let law = &fit.shift_law;
    let nominal: Vec<f64> = temps_c
        .par_iter()
        .map(|&t| solve(creep, law.log10_a_t(t)))
        .collect();
    ratios_over(fit, ensemble, temps_c, which, solve, &nominal)
}

/// Per temperature, F_b/F̂ of the replicates `which` over the given nominal frictions F̂.
fn ratios_over(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    temps_c: &[f64],
    which: &[usize],
    solve: &(dyn Fn(&CreepSpectrum, f64) -> f64 + Sync),
    nominal: &[f64],
) -> Vec<Vec<f64>> {
    let law = &fit.shift_law;
    let nb = which.len();
    let flat: Vec<f64> = (0..temps_c.len() * nb)
        .into_par_iter()
        .map(|k| {
            let (i, b) = (k / nb, which[k % nb]);
            let r = &ensemble.replicates[b];
            solve(&r.creep, r.log10_a_t(law, temps_c[i])) / nominal[i]
        })
        .collect();
    (0..temps_c.len())
        .map(|i| flat[i * nb..(i + 1) * nb].to_vec())
        .collect()
}

/// [`scene_ratios_on`] with every replicate solved on the cover (the full bootstrap of eq. 15.6,
/// 32 layer solves per temperature; the same extrapolation term): the reference the cheaper
/// estimate is checked against.
pub fn scene_ratios_full_on(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    scene: &Scene,
    cover_m: Option<f64>,
    temps_c: &[f64],
    settings: &BandSettings,
) -> Vec<Vec<f64>> {
    bands_with(fit, ensemble, scene, cover_m, temps_c, settings, true, None).ratios
}

/// A standard normal draw of replicate `b` for stream `stream` of the bands' seed: the same for
/// every temperature of a scene, so the terms it scales are correlated across temperatures as a
/// property of the replicate (conservative for the band of a scene mean).
fn replicate_normal(seed: u64, stream: u64, b: usize) -> f64 {
    super::rng::Rng::new(seed ^ stream, b as u64).normal()
}

/// Stream of the covered regression's residual draws (eq. 15.6b).
const STREAM_COVER: u64 = 0x636f_7665_7200_0001;
/// Streams of the extrapolation term's draws below and above the measured temperatures (eq. 15.8).
const STREAM_TAIL_LOW: u64 = 0x7461_696c_0000_0001;
const STREAM_TAIL_HIGH: u64 = 0x7461_696c_0000_0002;

/// The covered ratios of every replicate from their half-space ratios `hs` and the covered ratios
/// `solved` of the first `solved.len()` replicates (eq. 15.6b): the least squares line
/// y = α + βx through (x, y) = (ln hs_b, ln cov_b) of the solved ones, then for every other
/// replicate y_b = α + βx_b + σ_b z_b with σ_b² = σ²(1 + 1/n + (x_b − x̄)²/Sxx) the variance of a
/// new observation about the fitted line (σ² = RSS/(n − 2)), z_b standard normal (`z[b]`). The
/// solved replicates keep their own ratios. `None` with fewer than 5 usable pairs.
pub fn predict_from_half_space(hs: &[f64], solved: &[f64], z: &[f64]) -> Option<Vec<f64>> {
    let ln = |v: f64| (v.is_finite() && v > 0.0).then(|| v.ln());
    let pairs: Vec<(f64, f64)> = hs
        .iter()
        .zip(solved)
        .filter_map(|(&x, &y)| Some((ln(x)?, ln(y)?)))
        .collect();
    let n = pairs.len() as f64;
    if pairs.len() < 5 {
        return None;
    }
    let mx = pairs.iter().map(|p| p.0).sum::<f64>() / n;
    let my = pairs.iter().map(|p| p.1).sum::<f64>() / n;
    let sxx: f64 = pairs.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = pairs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let syy: f64 = pairs.iter().map(|p| (p.1 - my).powi(2)).sum();
    // Half-space ratios that do not move (a spread below round-off) carry no information: the
    // covered ratios are then taken as a sample of their own (β = 0, n − 1 degrees of freedom).
    let informative = sxx > 1e-24 * n;
    let (beta, var) = if informative {
        let beta = sxy / sxx;
        (beta, ((syy - beta * sxy) / (n - 2.0)).max(0.0))
    } else {
        (0.0, syy / (n - 1.0))
    };
    let alpha = my - beta * mx;
    Some(
        hs.iter()
            .enumerate()
            .map(|(b, &x)| {
                if let Some(&y) = solved.get(b) {
                    return y;
                }
                let Some(lx) = ln(x) else {
                    return f64::NAN;
                };
                let lever = if informative {
                    (lx - mx).powi(2) / sxx
                } else {
                    0.0
                };
                let sd = (var * (1.0 + 1.0 / n + lever)).sqrt();
                (alpha + beta * lx + sd * z.get(b).copied().unwrap_or(0.0)).exp()
            })
            .collect(),
    )
}

/// Shifts of the end isotherms a tail is fitted to (eq. 15.8): the five nearest the end.
const TAIL_POINTS: usize = 5;
/// A fitted law (WLF, Arrhenius) is a tail assumption only when it follows the shifts found to
/// this RMS (decades): on the shipped EMS-CA and DMA-suite sets they miss by 0.77–1.9 decades
/// and would extrapolate nothing the data support.
const TAIL_LAW_RMS_MAX: f64 = 0.3;

/// The tail assumptions at `temp_c` beyond the measured end `t_end` (eq. 15.8), as log10 a_T, each
/// agreeing with the fit's law `law` at the end isotherm: L(T_e) + q(T) − q(T_e) for
/// - q the least-squares parabola through the [`TAIL_POINTS`] shifts nearest the end (the
///   curvature the data show there, continued; held at its vertex where its slope would change
///   sign against the law's);
/// - q the WLF or Arrhenius law the shift stage fitted, when it follows the shifts to
///   [`TAIL_LAW_RMS_MAX`].
pub fn tail_alternatives(fit: &CompoundFit, temp_c: f64, t_end: f64) -> Vec<f64> {
    let law = &fit.shift_law;
    let anchor = law.log10_a_t(t_end);
    let mut out = Vec::new();
    let Some(tts) = fit.tts.as_ref() else {
        return out;
    };
    let mut pts: Vec<(f64, f64)> = tts
        .shifts
        .iter()
        .copied()
        .filter(|p| p.0.is_finite() && p.1.is_finite())
        .collect();
    pts.sort_by(|a, b| (a.0 - t_end).abs().total_cmp(&(b.0 - t_end).abs()));
    pts.truncate(TAIL_POINTS);
    if let Some((c1, c2)) = parabola(&pts, t_end) {
        // q(T) − q(T_e) = c1·d + c2·d², d = T − T_e; the slope c1 + 2c2·d must keep the law's sign
        let slope_end = (law.log10_a_t(t_end + 0.5) - law.log10_a_t(t_end - 0.5)) / 1.0;
        let d = temp_c - t_end;
        let d_used = if c2 != 0.0 {
            let vertex = -c1 / (2.0 * c2);
            let turns = (c1 + 2.0 * c2 * d) * slope_end < 0.0 && vertex * d > 0.0;
            if turns {
                vertex
            } else {
                d
            }
        } else {
            d
        };
        let q = c1 * d_used + c2 * d_used * d_used;
        if q.is_finite() {
            out.push(anchor + q);
        }
    }
    for (name, alt) in [("wlf", &tts.wlf), ("arrhenius", &tts.arrhenius)] {
        let rms = tts
            .law_rms_log10
            .iter()
            .find(|(n, _)| n == name)
            .map_or(f64::INFINITY, |r| r.1);
        if let (Some(alt), true) = (alt, rms <= TAIL_LAW_RMS_MAX) {
            let l = anchor + alt.log10_a_t(temp_c) - alt.log10_a_t(t_end);
            if l.is_finite() {
                out.push(l);
            }
        }
    }
    out
}

/// Least-squares parabola y ≈ c0 + c1·d + c2·d², d = T − `t0`, through `pts` (≥ 3 distinct T);
/// (c1, c2).
fn parabola(pts: &[(f64, f64)], t0: f64) -> Option<(f64, f64)> {
    if pts.len() < 3 {
        return None;
    }
    // normal equations of the 3 × 3 least squares, solved by Cramer's rule (well scaled: d in K
    // over tens of K; a singular set — fewer than 3 distinct T — gives None)
    let mut a = [[0.0f64; 3]; 3];
    let mut r = [0.0f64; 3];
    for &(t, y) in pts {
        let d = t - t0;
        let v = [1.0, d, d * d];
        for i in 0..3 {
            for j in 0..3 {
                a[i][j] += v[i] * v[j];
            }
            r[i] += v[i] * y;
        }
    }
    let det = |m: &[[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d0 = det(&a);
    let scale = a[0][0] * a[1][1] * a[2][2];
    // singular (or NaN): fewer than 3 distinct temperatures
    if d0.abs().partial_cmp(&(1e-12 * scale.abs())) != Some(std::cmp::Ordering::Greater) {
        return None;
    }
    let col = |k: usize| {
        let mut m = a;
        for i in 0..3 {
            m[i][k] = r[i];
        }
        det(&m) / d0
    };
    let (c1, c2) = (col(1), col(2));
    (c1.is_finite() && c2.is_finite()).then_some((c1, c2))
}

/// The shift-law tail term of a point beyond the measured temperatures (eq. 15.8): the largest
/// |ln F(L_alt(T)) − ln F(L(T))| over the tail assumptions of [`tail_alternatives`], solved on the
/// scene's body (`f0` = F(L(T)) on it); `None` inside the measured temperatures or without an
/// alternative.
fn tail_term(
    fit: &CompoundFit,
    creep: &CreepSpectrum,
    temp_c: f64,
    f0: f64,
    solve: &(dyn Fn(&CreepSpectrum, f64) -> f64 + Sync),
) -> Option<f64> {
    let (lo, hi) = fit.measured_range_c()?;
    let t_end = if temp_c < lo {
        lo
    } else if temp_c > hi {
        hi
    } else {
        return None;
    };
    tail_alternatives(fit, temp_c, t_end)
        .into_iter()
        .filter_map(|l| {
            let d = (solve(creep, l) / f0).ln();
            d.is_finite().then_some(d.abs())
        })
        .fold(None, |m: Option<f64>, d| Some(m.map_or(d, |m| m.max(d))))
}

/// The note a point's band carries when it holds the tail term `s_tail` (eq. 15.8): it reaches
/// friction.csv's `note`, the datasheet and the ranking through the point's warnings.
pub fn tail_note(s_tail: f64) -> String {
    format!(
        "band widened for extrapolation: shift-law tail assumptions that agree at the end isotherm \
         differ here by up to {:.0} % in F/N (taken as one standard deviation, docs/MATH.md eq. 15.8)",
        100.0 * s_tail.exp_m1()
    )
}

/// [`scene_ratios_on`] with the extrapolation terms it drew in (module doc, eqs. 15.6, 15.6b,
/// 15.8). The tail term enters each replicate as a factor e^(s_tail·u_b), u_b standard normal, one
/// draw per replicate and side (below, above the measured temperatures): the largest spread
/// between the tail assumptions is taken as one standard deviation, so the 90 % band spans ±1.645
/// of it and covers every alternative.
pub fn scene_bands_on(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    scene: &Scene,
    cover_m: Option<f64>,
    temps_c: &[f64],
    settings: &BandSettings,
) -> SceneRatios {
    bands_with(
        fit, ensemble, scene, cover_m, temps_c, settings, false, None,
    )
}

/// [`scene_bands_on`] on a cover with the nominal covered frictions already solved: `nominal[i]`
/// the fit's friction at `temps_c[i]` on the cover by `auto` at [`COVER_BAND_TOL`] (the main job's
/// covered points are exactly that solve: crate::pipeline's `COVER_TOL` is the same 1e−3), NaN where
/// it failed (then solved here). Saves one layer solve per temperature. Without a cover, or with a
/// band tolerance looser than [`COVER_BAND_TOL`], `nominal` is not used (the half-space's ratios
/// are over the fit solved at the band tolerance, not the report's).
pub fn scene_bands_given(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    scene: &Scene,
    cover_m: Option<f64>,
    temps_c: &[f64],
    settings: &BandSettings,
    nominal: &[f64],
) -> SceneRatios {
    let usable = cover_m.is_some()
        && settings.contact_tol <= COVER_BAND_TOL
        && nominal.len() == temps_c.len();
    bands_with(
        fit,
        ensemble,
        scene,
        cover_m,
        temps_c,
        settings,
        false,
        usable.then_some(nominal),
    )
}

/// [`scene_bands_on`] with every replicate solved on the cover (`full`), or the covered ones
/// predicted from the half-space (eq. 15.6b).
#[allow(clippy::too_many_arguments)]
fn bands_with(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    scene: &Scene,
    cover_m: Option<f64>,
    temps_c: &[f64],
    settings: &BandSettings,
    full: bool,
    nominal: Option<&[f64]>,
) -> SceneRatios {
    let Some(creep) = fit.creep.as_ref() else {
        return SceneRatios {
            ratios: temps_c.iter().map(|_| Vec::new()).collect(),
            tail_ln: vec![None; temps_c.len()],
        };
    };
    let nb = ensemble.replicates.len();
    let all: Vec<usize> = (0..nb).collect();
    let half_space = solver(scene, None, settings);
    let covered = solver(scene, cover_m, settings);
    let law = &fit.shift_law;
    // the body's nominal frictions: given (finite ones), else solved
    let body_nominal: Vec<f64> = temps_c
        .par_iter()
        .enumerate()
        .map(|(i, &t)| match nominal.and_then(|n| n.get(i)) {
            Some(&f) if f.is_finite() && f > 0.0 => f,
            _ => covered(creep, law.log10_a_t(t)),
        })
        .collect();
    let mut ratios: Vec<Vec<f64>> = match cover_m {
        None => ratios_over(fit, ensemble, temps_c, &all, &half_space, &body_nominal),
        Some(_) if full => ratios_over(fit, ensemble, temps_c, &all, &covered, &body_nominal),
        Some(_) => {
            let hs = solved_ratios(fit, creep, ensemble, temps_c, &all, &half_space);
            let k = COVER_SOLVED_REPLICATES.min(nb);
            let first: Vec<usize> = (0..k).collect();
            let sub = ratios_over(fit, ensemble, temps_c, &first, &covered, &body_nominal);
            let z: Vec<f64> = (0..nb)
                .map(|b| replicate_normal(settings.seed, STREAM_COVER, b))
                .collect();
            (0..temps_c.len())
                .map(|i| {
                    predict_from_half_space(&hs[i], &sub[i], &z).unwrap_or_else(|| {
                        // too few covered solves succeeded for the regression: all on the cover
                        ratios_over(
                            fit,
                            ensemble,
                            &temps_c[i..=i],
                            &all,
                            &covered,
                            &body_nominal[i..=i],
                        )
                        .remove(0)
                    })
                })
                .collect()
        }
    };
    let tail_ln: Vec<Option<f64>> = temps_c
        .par_iter()
        .zip(body_nominal.par_iter())
        .map(|(&t, &f0)| tail_term(fit, creep, t, f0, &covered))
        .collect();
    let (lo, _) = fit.measured_range_c().unwrap_or((f64::NAN, f64::NAN));
    for ((r, tail), &t) in ratios.iter_mut().zip(&tail_ln).zip(temps_c) {
        if let Some(s) = tail {
            let stream = if t < lo {
                STREAM_TAIL_LOW
            } else {
                STREAM_TAIL_HIGH
            };
            for (b, v) in r.iter_mut().enumerate() {
                *v *= (s * replicate_normal(settings.seed, stream, b)).exp();
            }
        }
    }
    SceneRatios { ratios, tail_ln }
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
    fn covered_ratios_follow_an_exact_line_and_keep_the_solved_ones() {
        // y = 0.01 + 1.3x exactly on the solved replicates: the fit recovers the line (RSS = 0, so
        // σ_b = 0) and every other replicate is e^(0.01 + 1.3 ln hs_b) to round-off.
        let mut rng = crate::bands::rng::Rng::new(5, 0);
        let hs: Vec<f64> = (0..32).map(|_| (0.1 * rng.normal()).exp()).collect();
        let solved: Vec<f64> = hs[..8]
            .iter()
            .map(|x| (0.01 + 1.3 * x.ln()).exp())
            .collect();
        let z: Vec<f64> = (0..32).map(|_| rng.normal()).collect();
        let out = predict_from_half_space(&hs, &solved, &z).unwrap();
        assert_eq!(out[..8], solved[..]);
        for b in 8..32 {
            let want = (0.01 + 1.3 * hs[b].ln()).exp();
            assert!((out[b] / want - 1.0).abs() < 1e-12, "{b}");
        }
        // fewer than 5 usable pairs: no prediction
        assert!(predict_from_half_space(&hs, &solved[..4], &z).is_none());
    }

    #[test]
    fn covered_ratios_carry_the_residual_scatter() {
        // ln cov = 1.3 ln hs + 0.02 ε (ε independent): the predicted ensemble's log sd must be
        // √(1.3²·0.1² + 0.02²) = 0.1315. 4000 replicates: the sample sd is known to 1.1 %; the
        // line from 8 solved ones adds its own error (β to ±0.008, i.e. 0.6 % of the sd; σ from 6
        // degrees of freedom to ±30 %, i.e. ±0.7 % of the sd): 4 % covers them.
        let mut rng = crate::bands::rng::Rng::new(11, 0);
        let n = 4000;
        let lx: Vec<f64> = (0..n).map(|_| 0.1 * rng.normal()).collect();
        let hs: Vec<f64> = lx.iter().map(|x| x.exp()).collect();
        let solved: Vec<f64> = lx[..8]
            .iter()
            .map(|x| (1.3 * x + 0.02 * rng.normal()).exp())
            .collect();
        let z: Vec<f64> = (0..n).map(|_| rng.normal()).collect();
        let out = predict_from_half_space(&hs, &solved, &z).unwrap();
        let d: Vec<f64> = out.iter().map(|r| r.ln()).collect();
        let m = d.iter().sum::<f64>() / n as f64;
        let sd = (d.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt();
        let want = (1.3f64.powi(2) * 0.01 + 0.02f64.powi(2)).sqrt();
        assert!((sd / want - 1.0).abs() < 0.04, "{sd} vs {want}");
    }

    #[test]
    fn the_tail_parabola_is_exact_on_a_parabola() {
        // y = 2 + 0.5d − 0.01d² at five temperatures: least squares returns it to round-off.
        let pts: Vec<(f64, f64)> = [0.0, 5.0, 10.0, 17.0, 25.0]
            .iter()
            .map(|&t| (t, 2.0 + 0.5 * (t - 3.0) - 0.01 * (t - 3.0) * (t - 3.0)))
            .collect();
        let (c1, c2) = parabola(&pts, 3.0).unwrap();
        assert!(
            (c1 - 0.5).abs() < 1e-12 && (c2 + 0.01).abs() < 1e-13,
            "{c1} {c2}"
        );
        // two distinct temperatures cannot define one
        assert!(parabola(&[(0.0, 1.0), (0.0, 1.0), (5.0, 2.0)], 0.0).is_none());
        assert!(tail_note(0.3).starts_with("band widened for extrapolation"));
    }

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
