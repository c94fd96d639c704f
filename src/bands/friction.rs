//! Friction bands of one compound in one scene (docs/MATH.md §15, steps 4–5): every replicate of
//! the ensemble solved at every temperature of the scene, as a ratio to the fit's own friction
//! solved the same way, then the band of each point and of the scene mean.
//!
//! Input: a [`CompoundFit`], a [`Scene`], [`BandSettings`]; output: the solver of the replicate
//! solves ([`solver`], `cover_solver`), the covered regression (eq. 15.6b), the shift-law tail term (eq. 15.8) and,
//! from replicate ratios F_b/F̂ (assembled per scene in super::scene), [`FrictionBand`]s
//! ([`band_of`], [`mean_band`]).

use super::BandSettings;
use crate::contact::body::{answer_at_load, Warm};
use crate::contact::{roll, AutoSettings, Body, ContactSettings, RollSolution, Scene, Scheme};
use crate::results::{CompoundFit, FrictionBand, FrictionPoint};
use crate::CreepSpectrum;

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

/// A replicate solve: F/N of a creep spectrum at log10 a_T, or why it failed.
pub(crate) type Solve<'a> = dyn Fn(&CreepSpectrum, f64) -> Result<f64, String> + Sync + 'a;

/// The scene the bands solve, the one place the bands read a scene's body: `scene`'s roll on its
/// cover (`Body::cover_m`; its body `auto` there, each replicate then on its own body,
/// [`replicate_choice`]) or on the half-space (no cover).
pub(crate) fn band_scene(scene: &Scene) -> Scene {
    let body = match scene.body.cover_m() {
        Some(thickness_m) => Body::Auto { thickness_m },
        None => Body::HALF_SPACE,
    };
    Scene { body, ..*scene }
}

/// The solver of one scene for the bands: F/N of a creep spectrum at log10 a_T on the scene's
/// body: on a cover (`scene.body.cover_m()`) by `cover_solver` started cold, else on the
/// half-space by `auto` at the band tolerance; or the solver's error.
pub fn solver<'a>(
    scene: &'a Scene,
    settings: &BandSettings,
) -> impl Fn(&CreepSpectrum, f64) -> Result<f64, String> + Sync + 'a {
    let cs = band_contact_settings(settings);
    let on_cover = scene.body.cover_m().map(|_| cover_solver(settings));
    move |c: &CreepSpectrum, log10_a_t: f64| match &on_cover {
        Some(solve) => solve(c, log10_a_t, None, scene).map(|r| r.0),
        None => {
            if !log10_a_t.is_finite() {
                return Err(format!("log10 a_T is not finite ({log10_a_t})"));
            }
            let f = roll(scene, &shifted(c, log10_a_t), &cs)
                .map_err(|e| e.to_string())?
                .friction;
            positive_friction(f)
        }
    }
}

fn positive_friction(f: f64) -> Result<f64, String> {
    if f.is_finite() && f > 0.0 {
        Ok(f)
    } else {
        Err(format!("F/N = {f} is not finite and positive"))
    }
}

/// The scene a replicate of a covered scene is solved on: `scene` (its body `auto` on the cover,
/// `band_scene`) on the body the fit's own solve at that temperature chose (`model`, on the same
/// cover), so that F_b/F̂ is a ratio on one body and the replicate skips the `auto` choice (its
/// half-space solve with the gap check costs about a third of a replicate's layer solve; measured by
/// the former bench `bands_levers`, removed in issue 30: docs/DEVLOG.md); `scene` itself when the fit's body is not known or is one
/// `roll_cover` cannot be asked for by name (the constrained Winkler foundation).
pub fn replicate_choice(scene: &Scene, model: Option<Body>) -> Scene {
    match model {
        Some(body @ (Body::Layer { .. } | Body::HalfSpace { .. } | Body::Winkler { .. })) => {
            Scene { body, ..*scene }
        }
        _ => *scene,
    }
}

/// One covered solve of the bands: F/N, contact length in m, the body solved (`None`: not known).
pub type CoverSolve = (f64, f64, Option<Body>);

/// A covered solve of the bands ([`cover_solver`]): creep spectrum, log10 a_T, start, the scene
/// (its body with its cover).
pub(crate) trait CoverSolver:
    Fn(&CreepSpectrum, f64, Option<(f64, f64)>, &Scene) -> Result<CoverSolve, String> + Sync
{
}

impl<F> CoverSolver for F where
    F: Fn(&CreepSpectrum, f64, Option<(f64, f64)>, &Scene) -> Result<CoverSolve, String> + Sync
{
}

/// The covered solver of the bands: F/N, contact length in m and body of a creep spectrum at
/// log10 a_T in a scene whose body is on a cover bonded to a rigid carcass (the scene's body through
/// the body dispatch [`answer_at_load`], as the main job's [`roll_cover_from`](crate::contact::cover::roll_cover_from)
/// solves it, at [`COVER_BAND_TOL`] or the band tolerance if looser), the layer solve started
/// from `start` = (contact length in m, d ln N′/d ln λ) when given (the fit's own covered solve at
/// the same temperature: a replicate's contact differs from it by its scatter, a few per cent; the
/// answer does not depend on the start beyond the load loop's stopping tolerance), or the
/// solver's error. The layer's closing contact checks are skipped ([`Warm::checks`]): they only
/// read the solution (same F/N to the bit, `cover_solver_skips_only_the_checks`) and their ratios
/// and warnings are not in what this hands on; the main job's own solve at each point keeps them
/// (its friction point's warnings).
pub(crate) fn cover_solver(settings: &BandSettings) -> impl CoverSolver {
    let cs = ContactSettings::auto(settings.contact_tol.max(COVER_BAND_TOL));
    move |c: &CreepSpectrum, log10_a_t: f64, start: Option<(f64, f64)>, scene: &Scene| {
        if !log10_a_t.is_finite() {
            return Err(format!("log10 a_T is not finite ({log10_a_t})"));
        }
        let p = scene
            .dimensionless(&shifted(c, log10_a_t))
            .map_err(|e| e.to_string())?;
        let warm = Warm {
            start: start.map(|(l_m, slope)| (l_m / p.length_scale_m, slope)),
            checks: false,
        };
        let s = answer_at_load(&scene.body, &p, &cs, warm).map_err(|e| e.to_string())?;
        let r = p.to_dimensional(scene.load_n_per_m, s.answer.solution);
        Ok((
            positive_friction(r.friction)?,
            r.contact_length_m,
            Some(s.body),
        ))
    }
}

/// The fit's own half-space solve at the band tolerance (its friction is the half-space ratios'
/// F̂; its contact length gives the rolling frequency of eq. 15.9).
pub(crate) fn half_space_solve(
    scene: &Scene,
    creep: &CreepSpectrum,
    log10_a_t: f64,
    settings: &BandSettings,
) -> Result<RollSolution, String> {
    let scene = Scene {
        body: crate::contact::Body::HALF_SPACE,
        ..*scene
    };
    if !log10_a_t.is_finite() {
        return Err(format!("log10 a_T is not finite ({log10_a_t})"));
    }
    roll(
        &scene,
        &shifted(creep, log10_a_t),
        &band_contact_settings(settings),
    )
    .map_err(|e| e.to_string())
}

/// A band is refused when more than a quarter of its replicates failed (to refit, or to solve at
/// its point): the rest would be a smaller sample no longer drawn at random (the failures may
/// cluster where the material is hardest to solve), so the band would be reported from few,
/// possibly biased, replicates.
pub fn too_many_failed(failed: usize, total: usize) -> bool {
    failed * 4 > total
}

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
/// - q the least-squares parabola through the `TAIL_POINTS` shifts nearest the end (the
///   curvature the data show there, continued; held at its vertex where its slope would change
///   sign against the law's);
/// - q the WLF or Arrhenius law the shift stage fitted, when it follows the shifts to
///   `TAIL_LAW_RMS_MAX`.
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
pub(super) fn tail_term(
    fit: &CompoundFit,
    creep: &CreepSpectrum,
    temp_c: f64,
    f0: f64,
    solve: &Solve,
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
            let d = (solve(creep, l).ok()? / f0).ln();
            d.is_finite().then_some(d.abs())
        })
        .fold(None, |m: Option<f64>, d| Some(m.map_or(d, |m| m.max(d))))
}

/// The note a point's band carries when it holds the tail term `s_tail` (eq. 15.8): it reaches
/// friction.csv's `note`, the datasheet and the ranking through the point's warnings.
pub fn tail_note(s_tail: f64) -> String {
    format!(
        "{} in temperature: shift-law tail assumptions that agree at the end isotherm \
         differ here by up to {} in F/N (taken as one standard deviation, docs/MATH.md eq. 15.8)",
        super::window::WIDENED_NOTE_START,
        super::window::change_text(s_tail)
    )
}

/// The band of `value` from replicate ratios (eq. 15.5): d_b = ln ratio_b over the finite ones,
/// their mean m and standard deviation s, and their root-mean-square distance from the fit itself,
/// r = √(s² + m²); p50 = value, p05/p95 = value·e^(∓z₀.₉₅ r). The refits' offset m from the fit is
/// spread, not a correction: the held-out calibration covered the truth in 81 % of points with
/// the band centred on the refits (value·e^(m ± z s)), 80 % with the offset reflected (the basic
/// bootstrap) and 88 % centred on the fit (docs/MATH.md §15, "Calibration"). `None` with fewer than
/// 8 finite ratios, more than a quarter of them failed (NaN or ≤ 0, [`too_many_failed`]) or a
/// non-finite value.
pub fn band_of(value: f64, ratios: &[f64]) -> Option<FrictionBand> {
    let d: Vec<f64> = ratios
        .iter()
        .filter(|r| r.is_finite() && **r > 0.0)
        .map(|r| r.ln())
        .collect();
    if d.len() < 8 || !value.is_finite() || too_many_failed(ratios.len() - d.len(), ratios.len()) {
        return None;
    }
    let n = d.len() as f64;
    let m = d.iter().sum::<f64>() / n;
    let s2 = d.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1.0);
    let r = (s2 + m * m).sqrt();
    Some(FrictionBand {
        p05: value * (-Z95 * r).exp(),
        p50: value,
        p95: value * (Z95 * r).exp(),
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
        // issue 31: a huge spread is a factor, never "334869476303865 %"
        let n = tail_note(3.3e12f64.ln());
        assert!(
            n.contains("by up to a factor 3.3e12 in F/N") && !n.contains('%'),
            "{n}"
        );
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
        // The refits offset from the fit by m = 0.1 (twice σ): the band stays centred on the fit
        // and its half-width is z·√(s² + m²), the refits' root-mean-square distance from it.
        let offset: Vec<f64> = ratios.iter().map(|r| r * 0.1f64.exp()).collect();
        let b = band_of(2.0, &offset).unwrap();
        let r = (sigma * sigma + 0.01f64).sqrt();
        assert_eq!(b.p50, 2.0);
        assert!(
            ((b.p95 / 2.0).ln() / (Z95 * r) - 1.0).abs() < 0.005,
            "{b:?}"
        );
        assert!(
            ((b.p05 / 2.0).ln() / (-Z95 * r) - 1.0).abs() < 0.005,
            "{b:?}"
        );
        assert!(band_of(2.0, &ratios[..5]).is_none());
        assert!(band_of(f64::NAN, &ratios).is_none());
    }

    #[test]
    fn cover_solver_skips_only_the_checks() {
        // The bands' covered solver (closing checks skipped) against the same solve with them
        // (`roll_cover_from`): F/N and contact length the same to the bit, cold and warm-started,
        // on the layer and by `auto`, on the example spectrum (R 66.5 mm, 10 kN/m, 4 m/s) on 5 and
        // 10 mm covers.
        use crate::contact::cover::roll_cover_from;
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/data/spectra/example_creep.json"
        ))
        .unwrap();
        let spec: CreepSpectrum = serde_json::from_str(&text).unwrap();
        let scene = Scene {
            radius_m: 0.0665,
            load_n_per_m: 10_000.0,
            speed_m_s: 4.0,
            poisson: None,
            body: crate::contact::Body::HALF_SPACE,
        };
        let bs = BandSettings::default();
        let tol = bs.contact_tol.max(COVER_BAND_TOL);
        for h_m in [5e-3, 10e-3] {
            let solve = cover_solver(&bs);
            for choice in [
                Body::Layer { thickness_m: h_m },
                Body::Auto { thickness_m: h_m },
            ] {
                let on = Scene {
                    body: choice,
                    ..scene
                };
                let cold = roll_cover_from(&on, &spec, tol, None).unwrap();
                assert!(
                    cold.min_gap_ratio.is_finite(),
                    "the reference ran its checks"
                );
                let l = cold.roll.contact_length_m;
                for start in [None, Some((1.03 * l, f64::NAN))] {
                    let with = roll_cover_from(&on, &spec, tol, start).unwrap();
                    let (f, l_m, model) = solve(&spec, 0.0, start, &on).unwrap();
                    assert_eq!(
                        f.to_bits(),
                        with.roll.friction.to_bits(),
                        "{h_m} {choice:?}"
                    );
                    assert_eq!(l_m.to_bits(), with.roll.contact_length_m.to_bits());
                    assert_eq!(model, Some(with.model));
                }
            }
        }
    }
}
