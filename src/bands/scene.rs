//! The replicate ratios of one compound in one scene (docs/MATH.md §15, steps 4–5): every replicate
//! of the ensemble solved at every temperature of the scene, as a ratio to the fit's own friction
//! solved the same way (eqs. 15.5, 15.6, 15.6b, 15.6c), with the model-error terms of the points beyond the
//! measured temperatures (eq. 15.8) and beyond the measured frequencies (eq. 15.9) drawn in, and the
//! failed solves counted; then each point's band with its notes ([`SceneRatios::point_band`]).
//!
//! Input: a [`CompoundFit`] with its [`BandEnsemble`], a [`Scene`], [`BandSettings`]; output:
//! [`SceneRatios`].

use super::friction::{
    band_scene, cover_solver, half_space_solve, predict_from_half_space, replicate_choice, solver,
    tail_note, tail_term, too_many_failed, CoverSolve, Solve, COVER_BAND_TOL,
};
use super::window::{
    continued_spectrum, excess, measured_window_hz, ramp_weight, rolling_reduced_freq_hz,
    window_note, WindowExcess, WindowSide,
};
use super::BandSettings;
use crate::contact::Body;
use crate::contact::Scene;
use crate::results::{BandEnsemble, CompoundFit, FrictionBand};
use crate::CreepSpectrum;
use rayon::prelude::*;

/// Replicates of a covered scene whose ratios are solved on the covered body itself (eq. 15.6b);
/// the others are predicted from their half-space ratios by a regression on these. Eight: the
/// regression then has 6 degrees of freedom for its residual; checked against the full bootstrap
/// on the shipped compounds (the former bench `bands_cover`, removed in issue 30 (docs/DEVLOG.md), README).
pub const COVER_SOLVED_REPLICATES: usize = 8;

/// The frequency-window term of one point (eq. 15.9).
#[derive(Debug, Clone, PartialEq)]
pub struct WindowTerm {
    /// Where the point's reduced rolling frequency lies beyond the measured window (or inside its
    /// edge's last half decade, eq. 15.9c).
    pub excess: WindowExcess,
    /// |ln F(continued spectrum) − ln F(fit)| on the scene's body, times the ramp weight of
    /// eq. 15.9c inside the window's edge, or why it could not be solved (the band is then refused).
    pub s_ln: Result<f64, String>,
}

/// What [`scene_bands_on`] hands on, per temperature of the scene.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneRatios {
    /// Per replicate, F_b/F̂ with the model-error terms drawn in (NaN where a solve failed).
    pub ratios: Vec<Vec<f64>>,
    /// The shift-law tail term s_tail of eq. 15.8 (ln F), `None` inside the measured temperatures.
    pub tail_ln: Vec<Option<f64>>,
    /// The frequency-window term of eq. 15.9, `None` more than half a decade inside the measured
    /// reduced frequencies.
    pub window: Vec<Option<WindowTerm>>,
    /// The first failed replicate solve's reason (`None` when none failed).
    pub first_failure: Vec<Option<String>>,
    /// On a cover, the standard deviation (ln F) of the error of the covered ratios carried to
    /// this temperature from its neighbours (eq. 15.6c), drawn into every replicate; `None` where
    /// they were solved, and off a cover.
    pub carried_ln: Vec<Option<f64>>,
    /// The replicate solves' error carried into the band (ln F, per temperature): on the
    /// half-space, the fit's own solve's error estimate plus the median of the replicates' (their
    /// tolerance, [`BandSettings::contact_tol`], is looser than the report's); 0 on a cover (its
    /// ratios are solved at the main job's own 1e−3, eq. 15.6).
    pub solver_ln: Vec<f64>,
}

impl SceneRatios {
    fn empty(n: usize) -> Self {
        Self {
            ratios: vec![Vec::new(); n],
            tail_ln: vec![None; n],
            window: vec![None; n],
            first_failure: vec![None; n],
            carried_ln: vec![None; n],
            solver_ln: vec![0.0; n],
        }
    }

    /// The band of the point at temperature index `i` whose friction is `value` (eq. 15.5), with
    /// the notes it carries (widened by eq. 15.8 or 15.9; replicates that failed to solve), or
    /// `None` with the reason it was refused: more than a quarter of its replicates failed
    /// ([`too_many_failed`]), or its frequency-window term could not be solved. `(None, [])`
    /// without replicates (no bands asked for) or a failed point (`value` not finite).
    pub fn point_band(&self, i: usize, value: f64) -> (Option<FrictionBand>, Vec<String>) {
        let Some(r) = self.ratios.get(i).filter(|r| !r.is_empty()) else {
            return (None, Vec::new());
        };
        if !value.is_finite() {
            return (None, Vec::new());
        }
        let n = r.len();
        let failed = r.iter().filter(|x| !(x.is_finite() && **x > 0.0)).count();
        let why = self
            .first_failure
            .get(i)
            .cloned()
            .flatten()
            .unwrap_or_else(|| "no reason recorded".into());
        if too_many_failed(failed, n) {
            return (
                None,
                vec![format!(
                    "uncertainty band refused: {failed} of {n} bootstrap replicates failed to \
                     solve here (first: {why}), more than a quarter, so the rest would not \
                     give a band"
                )],
            );
        }
        if let Some(Some(WindowTerm { s_ln: Err(e), .. })) = self.window.get(i) {
            return (
                None,
                vec![format!(
                    "uncertainty band refused: the rolling frequency lies beyond the measured \
                     master curve and the spectrum continued past it could not be solved ({e}; \
                     docs/MATH.md eq. 15.9)"
                )],
            );
        }
        let Some(mut band) = super::band_of(value, r) else {
            return (
                None,
                vec![format!(
                    "uncertainty band refused: only {} of {n} replicates solved",
                    n - failed
                )],
            );
        };
        // the solver's error: each quantile moved outwards by it (docs/MATH.md eq. 15.5b)
        let e = self.solver_ln.get(i).copied().unwrap_or(0.0);
        if e.is_finite() && e > 0.0 {
            band.p05 *= (-e).exp();
            band.p95 *= e.exp();
        }
        let mut notes = Vec::new();
        if let Some(Some(s)) = self.tail_ln.get(i) {
            notes.push(tail_note(*s));
        }
        if let Some(Some(WindowTerm {
            excess,
            s_ln: Ok(s),
        })) = self.window.get(i)
        {
            notes.push(window_note(*s, excess));
        }
        if failed > 0 {
            notes.push(format!(
                "uncertainty band from {} of {n} bootstrap replicates: {failed} failed to solve \
                 here and were left out (first: {why})",
                n - failed
            ));
        }
        (Some(band), notes)
    }
}

/// [`scene_bands_on`] with the covered replicates solved as `mode` says: [`CoverMode::Full`] (the
/// full bootstrap of eq. 15.6, 32 layer solves per temperature) is the reference the main job's
/// [`CoverMode::Carried`] is checked against; the same model-error terms in each.
pub fn scene_bands_by(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    scene: &Scene,
    temps_c: &[f64],
    settings: &BandSettings,
    mode: CoverMode,
) -> SceneRatios {
    let job = SceneJob {
        fit,
        ensemble,
        scene: band_scene(scene),
        temps_c,
        settings,
    };
    let given = Given {
        mode,
        nominal: None,
        half_space: None,
    };
    bands_with(&job, given)
}

/// The replicate ratios of `fit`'s `ensemble` in `scene` at `temps_c`, with the model-error terms
/// drawn in and the failures met (module doc, eqs. 15.6, 15.6b, 15.6c, 15.8, 15.9). The body is the
/// scene's: on a cover (`scene.body.cover_m()`) the replicates are solved as the main job solves a
/// covered scene (`auto` on the cover, each replicate on the body the fit's solve chose), else on the
/// half-space (`band_scene`). Each term enters each replicate as a factor e^(s·u_b), u_b
/// standard normal, one draw per replicate, term and side (below, above the measured range): the
/// alternative's change is taken as one standard deviation, so the 90 % band spans ±1.645 of it.
pub fn scene_bands_on(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    scene: &Scene,
    temps_c: &[f64],
    settings: &BandSettings,
) -> SceneRatios {
    scene_bands_by(fit, ensemble, scene, temps_c, settings, CoverMode::Carried)
}

/// [`scene_bands_on`] with what the main job has already solved: `nominal[i]` = (F/N, contact
/// length in m, body) of the fit at `temps_c[i]` on the cover by `auto` at `COVER_BAND_TOL` (the
/// main job's covered points are exactly that solve: crate::pipeline's `COVER_TOL` is the same
/// 1e−3), NaN where it failed (then solved here), which saves one layer solve per temperature,
/// starts each replicate's layer solve there and solves it on the same body
/// (`replicate_choice`); and `half_space`, the replicates' half-space ratios of
/// another scene with the same roll and temperatures (`half_space_ratios`; used only when it is
/// of this scene, else solved here). Without a cover, or with a band tolerance looser than
/// `COVER_BAND_TOL`, `nominal` is not used (the half-space's ratios are over the fit solved at
/// the band tolerance, not the report's).
pub fn scene_bands_given(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    scene: &Scene,
    temps_c: &[f64],
    settings: &BandSettings,
    nominal: &[CoverSolve],
    half_space: Option<&HalfSpaceRatios>,
) -> SceneRatios {
    let scene = band_scene(scene);
    let usable = scene.body.cover_m().is_some()
        && settings.contact_tol <= COVER_BAND_TOL
        && nominal.len() == temps_c.len();
    let job = SceneJob {
        fit,
        ensemble,
        scene,
        temps_c,
        settings,
    };
    let given = Given {
        mode: CoverMode::Carried,
        nominal: usable.then_some(nominal),
        half_space,
    };
    bands_with(&job, given)
}

/// The half-space solves of the bands in one scene: the fit's own (F̂, contact length) and every
/// replicate's ratio F_b/F̂ per temperature, at the band tolerance. The same for every scene with
/// the same roll (radius, load, speed, ν) and temperatures, whatever its body: a covered scene's
/// regression (eq. 15.6b) and its half-space twin share them ([`scene_bands_given`]).
#[derive(Debug, Clone, PartialEq)]
pub struct HalfSpaceRatios {
    /// The roll they were solved for (on the half-space).
    pub scene: Scene,
    /// Its temperatures, °C.
    pub temps_c: Vec<f64>,
    /// Per temperature, the fit's (F/N, contact length in m) on the half-space, or why it failed.
    pub fit: Vec<Result<(f64, f64), String>>,
    /// Per temperature, per replicate, F_b/F̂ or why it failed.
    pub ratios: Vec<Vec<Result<f64, String>>>,
    /// Per temperature, the fit's solve's error estimate plus the median of the replicates' (ln F;
    /// eq. 15.5b).
    pub error_ln: Vec<f64>,
}

/// [`HalfSpaceRatios`] of `fit` and its `ensemble` at `temps_c` on `scene`'s roll (its body and any
/// cover ignored); `None` without a creep spectrum.
pub fn half_space_ratios(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    scene: &Scene,
    temps_c: &[f64],
    settings: &BandSettings,
) -> Option<HalfSpaceRatios> {
    let creep = fit.creep.as_ref()?;
    let scene = Scene {
        body: crate::contact::Body::HALF_SPACE,
        ..*scene
    };
    let law = &fit.shift_law;
    let solve = |c: &CreepSpectrum, t: f64| {
        half_space_solve(&scene, c, law.log10_a_t(t), settings).and_then(|r| {
            let f = r.friction;
            if f.is_finite() && f > 0.0 {
                let e = r.dimensionless.error_estimate.unwrap_or(0.0);
                Ok((f, r.contact_length_m, if e.is_finite() { e } else { 0.0 }))
            } else {
                Err(format!("F/N = {f} is not finite and positive"))
            }
        })
    };
    let fit_solves: Vec<Result<(f64, f64, f64), String>> =
        temps_c.par_iter().map(|&t| solve(creep, t)).collect();
    let nb = ensemble.replicates.len();
    let mut flat: Vec<Result<(f64, f64), String>> = (0..temps_c.len() * nb)
        .into_par_iter()
        .map(|k| {
            let (i, b) = (k / nb, k % nb);
            let (f0, _, _) = fit_solves[i]
                .as_ref()
                .map_err(|e| format!("the fit's own solve failed: {e}"))?;
            let r = &ensemble.replicates[b];
            let (f, _, e) =
                half_space_solve(&scene, &r.creep, r.log10_a_t(law, temps_c[i]), settings).map(
                    |s| {
                        let e = s.dimensionless.error_estimate.unwrap_or(0.0);
                        (s.friction, 0.0, if e.is_finite() { e } else { 0.0 })
                    },
                )?;
            if !(f.is_finite() && f > 0.0) {
                return Err(format!("F/N = {f} is not finite and positive"));
            }
            Ok((f / f0, e))
        })
        .collect();
    let mut ratios = Vec::with_capacity(temps_c.len());
    let mut error_ln = Vec::with_capacity(temps_c.len());
    for own in &fit_solves {
        let rest = flat.split_off(nb);
        let row = std::mem::replace(&mut flat, rest);
        let mut e: Vec<f64> = row
            .iter()
            .filter_map(|r| r.as_ref().ok().map(|x| x.1))
            .collect();
        e.sort_by(f64::total_cmp);
        let e0 = own.as_ref().map_or(0.0, |x| x.2);
        error_ln.push(e0 + e.get(e.len() / 2).copied().unwrap_or(0.0));
        ratios.push(row.into_iter().map(|r| r.map(|x| x.0)).collect());
    }
    Some(HalfSpaceRatios {
        scene,
        temps_c: temps_c.to_vec(),
        fit: fit_solves
            .into_iter()
            .map(|r| r.map(|(f, l, _)| (f, l)))
            .collect(),
        ratios,
        error_ln,
    })
}

/// How a covered scene's replicates are solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CoverMode {
    /// Every replicate on the cover at every temperature (eq. 15.6).
    Full,
    /// [`COVER_SOLVED_REPLICATES`] on the cover at [`cover_solved_temps`], carried to the other
    /// temperatures by eq. 15.6c, the rest by eq. 15.6b (the main job's).
    Carried,
}

/// A standard normal draw of replicate `b` for stream `stream` of the bands' seed: the same for
/// every temperature of a scene, so the terms it scales are correlated across temperatures as a
/// property of the replicate (conservative for the band of a scene mean).
fn replicate_normal(seed: u64, stream: u64, b: usize) -> f64 {
    super::rng::Rng::new(seed ^ stream, b as u64).normal()
}

/// Stream of the covered regression's residual draws (eq. 15.6b).
const STREAM_COVER: u64 = 0x636f_7665_7200_0001;
/// Stream of the draws of the carried covered ratios' error (eq. 15.6c).
const STREAM_COVER_CARRIED: u64 = 0x636f_7665_7200_0002;
/// Streams of the extrapolation term's draws below and above the measured temperatures (eq. 15.8).
const STREAM_TAIL_LOW: u64 = 0x7461_696c_0000_0001;
const STREAM_TAIL_HIGH: u64 = 0x7461_696c_0000_0002;
/// Streams of the frequency-window term's draws below and above the measured window (eq. 15.9).
const STREAM_WINDOW_LOW: u64 = 0x7769_6e64_0000_0001;
const STREAM_WINDOW_HIGH: u64 = 0x7769_6e64_0000_0002;

/// A replicate solve at temperature index i: F/N of a creep spectrum at log10 a_T, or why not.
type SolveAt<'a> = dyn Fn(usize, &CreepSpectrum, f64) -> Result<f64, String> + Sync + 'a;

/// Per temperature index of `at`, per replicate of `which` (indices into the ensemble), F_b/F̂
/// over the nominal frictions F̂ (`nominal`, by temperature index) solved by `solve`, or why it
/// failed; parallel over (temperature, replicate).
fn ratios_over(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    temps_c: &[f64],
    at: &[usize],
    which: &[usize],
    solve: &SolveAt,
    nominal: &[Result<f64, String>],
) -> Vec<Vec<Result<f64, String>>> {
    let law = &fit.shift_law;
    let nb = which.len();
    let mut flat: Vec<Result<f64, String>> = (0..at.len() * nb)
        .into_par_iter()
        .map(|k| {
            let (i, b) = (at[k / nb], which[k % nb]);
            let f0 = nominal[i]
                .as_ref()
                .map_err(|e| format!("the fit's own solve failed: {e}"))?;
            let r = &ensemble.replicates[b];
            Ok(solve(i, &r.creep, r.log10_a_t(law, temps_c[i]))? / f0)
        })
        .collect();
    let mut out = Vec::with_capacity(at.len());
    for _ in 0..at.len() {
        let rest = flat.split_off(nb);
        out.push(std::mem::replace(&mut flat, rest));
    }
    out
}

/// (values, NaN where failed; the first failure's reason).
fn split(v: Vec<Result<f64, String>>) -> (Vec<f64>, Option<String>) {
    let mut first = None;
    let values = v
        .into_iter()
        .map(|r| {
            r.unwrap_or_else(|e| {
                first.get_or_insert(e);
                f64::NAN
            })
        })
        .collect();
    (values, first)
}

/// The covered ratios of one temperature from the half-space ratios `hs` of every replicate and
/// the covered ones `sub` of the first few (eq. 15.6b), with the first failure among the values
/// used; `None` when the regression has too few usable pairs.
fn predicted(
    hs: Vec<Result<f64, String>>,
    sub: Vec<Result<f64, String>>,
    z: &[f64],
) -> Option<(Vec<f64>, Option<String>)> {
    let k = sub.len();
    // the reasons of the values the prediction uses: the solved ones' own, the others' half-space
    let reasons: Vec<Option<String>> = sub
        .iter()
        .chain(hs.iter().skip(k))
        .map(|r| r.as_ref().err().cloned())
        .collect();
    let (hs, _) = split(hs);
    let (sub, _) = split(sub);
    let v = predict_from_half_space(&hs, &sub, z)?;
    let first = v
        .iter()
        .zip(reasons)
        .find_map(|(x, r)| if x.is_finite() { None } else { r });
    Some((v, first))
}

/// Fewest temperatures of a covered scene for which its replicates are carried between
/// temperatures (eq. 15.6c): with fewer, every one is solved.
const CARRY_MIN_TEMPS: usize = 5;

/// A temperature's covered ratios are carried from its solved neighbours (eq. 15.6c) only where
/// the departures q_b there spread by at most this fraction of the half-space ratios' own spread at
/// the temperature, and the carried error's standard deviation is as small: any error in carrying
/// q then moves the band's width by about this fraction at most (the band's spread is that of
/// ln(hs_b/ĥs) + q_b); elsewhere (a cover that changes the band fast with temperature) they are
/// solved. Checked against solving every temperature by the former bench `bands_cover`, removed in issue 30 (docs/DEVLOG.md).
const CARRY_SPREAD_FRACTION: f64 = 0.1;

/// The temperatures (indices into `temps_c`) at which a covered scene's replicates are solved on
/// the cover first (eq. 15.6c): in order of temperature, the first, every other one and the last;
/// all of them with fewer than `CARRY_MIN_TEMPS` or when a temperature is not finite.
pub fn cover_solved_temps(temps_c: &[f64]) -> Vec<usize> {
    let n = temps_c.len();
    if n < CARRY_MIN_TEMPS || temps_c.iter().any(|t| !t.is_finite()) {
        return (0..n).collect();
    }
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| temps_c[a].total_cmp(&temps_c[b]));
    let mut keep: Vec<usize> = order.iter().copied().step_by(2).collect();
    if n % 2 == 0 {
        keep.push(order[n - 1]);
    }
    keep.sort_unstable();
    keep
}

/// Sample standard deviation of the finite values (NaN with fewer than two).
fn spread<'a>(v: impl Iterator<Item = &'a Result<f64, String>>) -> f64 {
    let x: Vec<f64> = v
        .filter_map(|r| r.as_ref().ok().copied())
        .filter(|x| x.is_finite())
        .collect();
    let n = x.len() as f64;
    if x.len() < 2 {
        return f64::NAN;
    }
    let m = x.iter().sum::<f64>() / n;
    (x.iter().map(|v| (v - m) * (v - m)).sum::<f64>() / (n - 1.0)).sqrt()
}

/// Per temperature, the covered ratios of one temperature, carried or solved.
type Carried = (Vec<Option<Vec<Result<f64, String>>>>, Vec<Option<f64>>);

/// The covered ratios of the solved replicates carried from the temperatures `solved` to the
/// others (eq. 15.6c), per temperature (`None` where it is to be solved: [`CARRY_SPREAD_FRACTION`]),
/// and the standard deviation of the carried ratios' error (ln F; `None` where solved). With
/// q_b(T) = ln(cov_b/ĉov) − ln(hs_b/ĥs) the departure of replicate b's cover/half-space ratio from
/// the fit's, q_b at a temperature T between solved neighbours T₋ < T < T₊ is the straight line
/// between them, and its covered ratio hs_b/ĥs·e^(q_b). The error of that line is
/// ½(T − T₋)(T₊ − T)·q″: it is measured at each interior solved temperature T_j by the line through
/// its own solved neighbours (distances a, c), e_b = q_b(T_j) − line, and scaled by
/// (T − T₋)(T₊ − T)/(a·c); its mean square over the replicates and the interior solved neighbours
/// of T (every interior solved temperature when neither neighbour is one) is the variance. Where
/// no interior solved temperature measured it, every temperature is to be solved.
fn carried(
    temps_c: &[f64],
    solved: &[usize],
    hs: &[Vec<Result<f64, String>>],
    sub: &[Vec<Result<f64, String>>],
) -> Carried {
    let n = temps_c.len();
    let k = sub.first().map_or(0, Vec::len);
    let mut order: Vec<usize> = solved.to_vec();
    order.sort_by(|&a, &b| temps_c[a].total_cmp(&temps_c[b]));
    // q at the solved temperatures, by position in `order`
    let q_at = |i: usize| -> Vec<Result<f64, String>> {
        let s = solved.iter().position(|&j| j == i).expect("a solved index");
        (0..k)
            .map(|b| {
                let c = sub[s][b].clone()?;
                let h = hs[i][b].clone()?;
                let q = (c / h).ln();
                if q.is_finite() {
                    Ok(q)
                } else {
                    Err(format!("covered/half-space ratio {c}/{h} not finite"))
                }
            })
            .collect()
    };
    let q: Vec<Vec<Result<f64, String>>> = order.iter().map(|&i| q_at(i)).collect();
    let measured = carry_errors(temps_c, &order, &q);
    let all: Vec<f64> = measured.iter().flatten().copied().collect();
    let mut out: Vec<Option<Vec<Result<f64, String>>>> = vec![None; n];
    let mut sd: Vec<Option<f64>> = vec![None; n];
    for (s, &i) in solved.iter().enumerate() {
        out[i] = Some(sub[s].clone());
    }
    if all.is_empty() {
        return (out, sd);
    }
    for i in (0..n).filter(|i| !solved.contains(i)) {
        let t = temps_c[i];
        // solved neighbours by position in `order` (the ends are always solved)
        let p1 = order
            .iter()
            .position(|&j| temps_c[j] >= t)
            .unwrap_or(order.len() - 1)
            .max(1);
        let p0 = p1 - 1;
        let (t0, t1) = (temps_c[order[p0]], temps_c[order[p1]]);
        let w = if t1 > t0 { (t - t0) / (t1 - t0) } else { 0.0 };
        let near: Vec<f64> = [measured[p0], measured[p1]].into_iter().flatten().collect();
        let per_ac2 = if near.is_empty() {
            all.iter().sum::<f64>() / all.len() as f64
        } else {
            near.iter().sum::<f64>() / near.len() as f64
        };
        let ac = (t - t0).max(0.0) * (t1 - t).max(0.0);
        let s_carried = (per_ac2 * ac * ac).sqrt();
        let s_q = spread(q[p0].iter()).max(spread(q[p1].iter()));
        let ln_hs: Vec<Result<f64, String>> = hs[i]
            .iter()
            .map(|r| r.as_ref().map(|x| x.ln()).map_err(Clone::clone))
            .collect();
        let s_hs = spread(ln_hs.iter());
        // NaN spreads (too few finite values) do not pass: solved by the caller
        let small = s_q.max(s_carried) <= CARRY_SPREAD_FRACTION * s_hs;
        if !small {
            continue;
        }
        sd[i] = Some(s_carried);
        out[i] = Some(
            (0..k)
                .map(|b| {
                    let qb = q_line(&q[p0][b], &q[p1][b], w)
                        .map_err(|e| format!("carried from a failed solve: {e}"))?;
                    let h = hs[i][b].clone()?;
                    Ok(h * qb.exp())
                })
                .collect(),
        );
    }
    (out, sd)
}

/// q on the straight line between `qa` (w = 0) and `qb` (w = 1), or the first failure.
fn q_line(qa: &Result<f64, String>, qb: &Result<f64, String>, w: f64) -> Result<f64, String> {
    Ok(qa.clone()? * (1.0 - w) + qb.clone()? * w)
}

/// The error of the line through the solved neighbours (eq. 15.6c), measured at each interior
/// solved temperature of `order` (sorted by temperature; `q` by position in it): the mean over
/// the replicates of e²/(a·c)², e = q_b(T_j) − line and a, c the distances to the neighbours;
/// `None` at the ends and where half the replicates or fewer measured it.
fn carry_errors(
    temps_c: &[f64],
    order: &[usize],
    q: &[Vec<Result<f64, String>>],
) -> Vec<Option<f64>> {
    let k = q.first().map_or(0, Vec::len);
    let mut measured: Vec<Option<f64>> = vec![None; order.len()];
    for p in 1..order.len().saturating_sub(1) {
        let (t0, t, t1) = (
            temps_c[order[p - 1]],
            temps_c[order[p]],
            temps_c[order[p + 1]],
        );
        let (a, c) = (t - t0, t1 - t);
        if !(a > 0.0 && c > 0.0) {
            continue;
        }
        let e: Vec<f64> = (0..k)
            .filter_map(|b| {
                let l = q_line(&q[p - 1][b], &q[p + 1][b], a / (a + c)).ok()?;
                Some(q[p][b].clone().ok()? - l)
            })
            .collect();
        if e.len() * 2 > k {
            measured[p] =
                Some(e.iter().map(|x| x * x).sum::<f64>() / e.len() as f64 / (a * c).powi(2));
        }
    }
    measured
}

/// The frequency-window term of the point at `temp_c` (eq. 15.9), weighted by the ramp of
/// eq. 15.9c inside the edge's last half decade: `None` further inside the measured window (or
/// without the fit's solve on the scene's body to read its contact length from).
fn window_term(
    fit: &CompoundFit,
    scene: &Scene,
    temp_c: f64,
    contact_length_m: Option<f64>,
    f0: &Result<f64, String>,
    solve: &Solve,
) -> Option<WindowTerm> {
    let log10_a_t = fit.shift_law.log10_a_t(temp_c);
    let f_red = rolling_reduced_freq_hz(scene.speed_m_s, contact_length_m?, log10_a_t);
    let ex = excess(measured_window_hz(fit)?, f_red)?;
    let s_ln = (|| {
        // no loss at the edge: nothing relaxes there, nothing to continue
        let Some(cont) = continued_spectrum(&fit.relaxation, &ex) else {
            return Ok(0.0);
        };
        let (creep, _) = crate::creep::relaxation_to_creep(&cont)
            .map_err(|e| format!("creep conversion of the continued spectrum: {e}"))?;
        let f0 = f0
            .as_ref()
            .map_err(|e| format!("the fit's own solve: {e}"))?;
        let f = solve(&creep, log10_a_t)?;
        Ok(ramp_weight(ex.decades) * (f / f0).ln().abs())
    })();
    Some(WindowTerm { excess: ex, s_ln })
}

/// One scene's band solves: the compound, its replicates, the scene (its body `auto` on the cover
/// or the half-space, [`band_scene`]), the temperatures and the settings.
#[derive(Clone, Copy)]
struct SceneJob<'a> {
    fit: &'a CompoundFit,
    ensemble: &'a BandEnsemble,
    scene: Scene,
    temps_c: &'a [f64],
    settings: &'a BandSettings,
}

/// How a [`SceneJob`]'s covered replicates are solved (`mode`) and what the caller has already
/// solved: the covered nominal frictions (F/N, contact length in m, body; [`scene_bands_given`])
/// and the half-space ratios.
struct Given<'a> {
    mode: CoverMode,
    nominal: Option<&'a [CoverSolve]>,
    half_space: Option<&'a HalfSpaceRatios>,
}

/// [`scene_bands_on`] with the covered replicates solved as `given.mode` says, the covered nominal
/// frictions given or solved, the half-space ratios given or solved: the ratios of the body
/// (eqs. 15.6, 15.6b, 15.6c), then the model-error terms drawn in (eqs. 15.6c, 15.8, 15.9).
fn bands_with(job: &SceneJob, given: Given) -> SceneRatios {
    let (fit, scene, temps_c) = (job.fit, &job.scene, job.temps_c);
    let Some(creep) = fit.creep.as_ref() else {
        return SceneRatios::empty(temps_c.len());
    };
    let hs_scene = Scene {
        body: crate::contact::Body::HALF_SPACE,
        ..*scene
    };
    // the half-space solves: the fit's F̂ and contact length (the rolling frequency V/l of eq.
    // 15.9, on a cover too: a cover shortens l by a fraction of a decade in V/l) and the ratios
    let own;
    let hs = match given
        .half_space
        .filter(|h| h.scene == hs_scene && h.temps_c == temps_c)
    {
        Some(h) => h,
        None => match half_space_ratios(fit, job.ensemble, scene, temps_c, job.settings) {
            Some(h) => {
                own = h;
                &own
            }
            None => return SceneRatios::empty(temps_c.len()),
        },
    };
    let covered = solver(scene, job.settings);
    let body_nominal = body_nominal(job, creep, hs, given.nominal);
    let f_nominal: Vec<Result<f64, String>> = body_nominal
        .iter()
        .map(|r| r.as_ref().map(|x| x.0).map_err(Clone::clone))
        .collect();
    let (mut ratios, first_failure, carried_sd) = match scene.body.cover_m() {
        None => {
            let (r, f): (Vec<Vec<f64>>, Vec<Option<String>>) =
                hs.ratios.iter().cloned().map(split).unzip();
            (r, f, vec![None; temps_c.len()])
        }
        Some(_) => cover_ratios(job, given.mode, hs, &body_nominal, &f_nominal),
    };
    let tail_ln: Vec<Option<f64>> = temps_c
        .par_iter()
        .zip(f_nominal.par_iter())
        .map(|(&t, f0)| tail_term(fit, creep, t, *f0.as_ref().ok()?, &covered))
        .collect();
    let window: Vec<Option<WindowTerm>> = temps_c
        .par_iter()
        .enumerate()
        .map(|(i, &t)| {
            // the contact length of the body solved: on a cover the covered body's, shorter
            // than the half-space's (eq. 15.9)
            let l = body_nominal[i].as_ref().ok().map(|x| x.1);
            window_term(fit, scene, t, l, &f_nominal[i], &covered)
        })
        .collect();
    let (lo, _) = fit.measured_range_c().unwrap_or((f64::NAN, f64::NAN));
    for (i, r) in ratios.iter_mut().enumerate() {
        let low = temps_c[i] < lo;
        let terms = model_terms(carried_sd[i], tail_ln[i], low, window[i].as_ref());
        for (b, v) in r.iter_mut().enumerate() {
            let d: f64 = terms
                .iter()
                .map(|&(s, stream)| s * replicate_normal(job.settings.seed, stream, b))
                .sum();
            *v *= d.exp();
        }
    }
    SceneRatios {
        ratios,
        tail_ln,
        window,
        first_failure,
        carried_ln: carried_sd,
        solver_ln: match scene.body.cover_m() {
            None => hs.error_ln.clone(),
            Some(_) => vec![0.0; temps_c.len()],
        },
    }
}

/// The model-error terms of one point, each (s, its draws' stream): the carried covered ratios'
/// error (eq. 15.6c), the shift-law tail (eq. 15.8; `low`: below the measured temperatures) and
/// the frequency window (eq. 15.9).
fn model_terms(
    carried_sd: Option<f64>,
    tail_ln: Option<f64>,
    low: bool,
    window: Option<&WindowTerm>,
) -> Vec<(f64, u64)> {
    let mut terms: Vec<(f64, u64)> = Vec::new();
    if let Some(s) = carried_sd {
        terms.push((s, STREAM_COVER_CARRIED));
    }
    if let Some(s) = tail_ln {
        let stream = if low {
            STREAM_TAIL_LOW
        } else {
            STREAM_TAIL_HIGH
        };
        terms.push((s, stream));
    }
    if let Some(WindowTerm {
        excess,
        s_ln: Ok(s),
    }) = window
    {
        let stream = match excess.side {
            WindowSide::Low => STREAM_WINDOW_LOW,
            WindowSide::High => STREAM_WINDOW_HIGH,
        };
        terms.push((*s, stream));
    }
    terms
}

/// The body's nominal (F/N, contact length, body) per temperature: the half-space's, or on a
/// cover those `nominal` gives (finite ones), else solved by `auto`.
fn body_nominal(
    job: &SceneJob,
    creep: &CreepSpectrum,
    hs: &HalfSpaceRatios,
    nominal: Option<&[CoverSolve]>,
) -> Vec<Result<CoverSolve, String>> {
    if job.scene.body.cover_m().is_none() {
        return hs
            .fit
            .iter()
            .map(|r| r.clone().map(|(f, l)| (f, l, Some(Body::HALF_SPACE))))
            .collect();
    }
    let on_cover = cover_solver(job.settings);
    let law = &job.fit.shift_law;
    job.temps_c
        .par_iter()
        .enumerate()
        .map(|(i, &t)| match nominal.and_then(|n| n.get(i)) {
            Some(&x) if x.0.is_finite() && x.0 > 0.0 => Ok(x),
            _ => on_cover(creep, law.log10_a_t(t), None, &job.scene),
        })
        .collect()
}

/// A covered scene's ratios, first failures and carried errors per temperature.
type CoverRatios = (Vec<Vec<f64>>, Vec<Option<String>>, Vec<Option<f64>>);

/// The covered ratios of a scene on a cover (eq. 15.6): each replicate solved on the
/// body of the fit's own solve at that temperature (`body_nominal`), its layer solve started from
/// the fit's contact there; every replicate at every temperature ([`CoverMode::Full`]), or
/// [`COVER_SOLVED_REPLICATES`] of them at [`cover_solved_temps`] carried to the others where that is safe ([`CoverMode::Carried`],
/// eq. 15.6c), the rest predicted from their half-space ratios (eq. 15.6b).
fn cover_ratios(
    job: &SceneJob,
    mode: CoverMode,
    hs: &HalfSpaceRatios,
    body_nominal: &[Result<CoverSolve, String>],
    f_nominal: &[Result<f64, String>],
) -> CoverRatios {
    let (fit, ensemble, temps_c) = (job.fit, job.ensemble, job.temps_c);
    let nb = ensemble.replicates.len();
    let all: Vec<usize> = (0..nb).collect();
    let every: Vec<usize> = (0..temps_c.len()).collect();
    let on_cover = cover_solver(job.settings);
    let warm = |i: usize, c: &CreepSpectrum, l: f64| {
        let own = body_nominal[i].as_ref().ok();
        let start = own
            .map(|x| x.1)
            .filter(|l| l.is_finite() && *l > 0.0)
            .map(|l| (l, f64::NAN));
        let on = replicate_choice(&job.scene, own.and_then(|x| x.2));
        on_cover(c, l, start, &on).map(|r| r.0)
    };
    let solve_all = |at: &[usize]| {
        ratios_over(fit, ensemble, temps_c, at, &all, &warm, f_nominal)
            .into_iter()
            .map(split)
            .collect::<Vec<_>>()
    };
    if mode == CoverMode::Full {
        let (r, f) = solve_all(&every).into_iter().unzip();
        return (r, f, vec![None; temps_c.len()]);
    }
    let first: Vec<usize> = (0..COVER_SOLVED_REPLICATES.min(nb)).collect();
    let at = match mode {
        CoverMode::Carried => cover_solved_temps(temps_c),
        _ => every,
    };
    let sub = ratios_over(fit, ensemble, temps_c, &at, &first, &warm, f_nominal);
    // eq. 15.6c: the other temperatures carried where that is safe, else solved
    let (partial, carried_sd) = if at.len() == temps_c.len() {
        (
            sub.into_iter().map(Some).collect(),
            vec![None; temps_c.len()],
        )
    } else {
        carried(temps_c, &at, &hs.ratios, &sub)
    };
    let rest: Vec<usize> = (0..temps_c.len())
        .filter(|&i| partial[i].is_none())
        .collect();
    let mut more = ratios_over(fit, ensemble, temps_c, &rest, &first, &warm, f_nominal).into_iter();
    let sub: Vec<Vec<Result<f64, String>>> = partial
        .into_iter()
        .map(|p| p.unwrap_or_else(|| more.next().unwrap_or_default()))
        .collect();
    let z: Vec<f64> = (0..nb)
        .map(|b| replicate_normal(job.settings.seed, STREAM_COVER, b))
        .collect();
    let (r, f) = hs
        .ratios
        .iter()
        .cloned()
        .zip(sub)
        .enumerate()
        .map(|(i, (hs, sub))| {
            predicted(hs, sub, &z).unwrap_or_else(|| {
                // too few covered solves succeeded for the regression: all on the cover
                solve_all(&[i]).into_iter().next().unwrap_or_default()
            })
        })
        .unzip();
    (r, f, carried_sd)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 32 ratios e^(0.01·k/31 − 0.005), the first `failed` of them NaN (failed solves).
    fn with_failures(failed: usize) -> SceneRatios {
        let mut r: Vec<f64> = (0..32)
            .map(|k| (0.01 * k as f64 / 31.0 - 0.005).exp())
            .collect();
        for v in r.iter_mut().take(failed) {
            *v = f64::NAN;
        }
        SceneRatios {
            ratios: vec![r],
            tail_ln: vec![None],
            window: vec![None],
            first_failure: vec![(failed > 0).then(|| "contact: λ not bracketed".to_string())],
            carried_ln: vec![None],
            solver_ln: vec![0.0],
        }
    }

    #[test]
    fn failed_replicates_are_counted_and_too_many_refuse_the_band() {
        // none failed: a band, no note
        let (b, notes) = with_failures(0).point_band(0, 1e-3);
        assert!(b.is_some() && notes.is_empty(), "{notes:?}");
        // 8 of 32 (a quarter, not more): the band, from the 24 left, says so with the reason
        let (b, notes) = with_failures(8).point_band(0, 1e-3);
        assert!(b.is_some());
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert!(
            notes[0].contains("24 of 32") && notes[0].contains("8 failed"),
            "{}",
            notes[0]
        );
        assert!(notes[0].contains("λ not bracketed"), "{}", notes[0]);
        // 9 of 32 (more than a quarter): refused, with how many, of how many and why
        let (b, notes) = with_failures(9).point_band(0, 1e-3);
        assert!(b.is_none());
        assert!(
            notes[0].starts_with("uncertainty band refused: 9 of 32")
                && notes[0].contains("λ not bracketed"),
            "{}",
            notes[0]
        );
        // band_of refuses the same ratios on its own (the mean band and `roll` use it)
        assert!(super::super::band_of(1e-3, &with_failures(9).ratios[0]).is_none());
        assert!(super::super::band_of(1e-3, &with_failures(8).ratios[0]).is_some());
        // a failed point or a run without replicates: nothing to say
        assert_eq!(with_failures(0).point_band(0, f64::NAN), (None, vec![]));
        assert_eq!(SceneRatios::empty(1).point_band(0, 1e-3), (None, vec![]));
    }

    #[test]
    fn a_window_term_is_noted_and_an_unsolved_one_refuses_the_band() {
        let ex = excess((1e-2, 1e8), 1e10).unwrap();
        let mut r = with_failures(0);
        r.window[0] = Some(WindowTerm {
            excess: ex,
            s_ln: Ok(0.25),
        });
        let (b, notes) = r.point_band(0, 1e-3);
        assert!(b.is_some());
        assert!(
            notes[0].starts_with("band widened for extrapolation in frequency")
                && notes[0].contains("2.0 decades above")
                && notes[0].contains("28 %"),
            "{}",
            notes[0]
        );
        r.window[0] = Some(WindowTerm {
            excess: ex,
            s_ln: Err("layer: no convergence".into()),
        });
        let (b, notes) = r.point_band(0, 1e-3);
        assert!(b.is_none() && notes[0].contains("layer: no convergence"));
    }

    #[test]
    fn solved_temperatures_are_the_ends_and_every_other_one() {
        // unsorted, 9 temperatures: in order of T the 1st, 3rd, … 9th
        let t = [0.0, -40.0, 40.0, -20.0, 20.0, -30.0, 30.0, -10.0, 10.0];
        let got: Vec<f64> = cover_solved_temps(&t).iter().map(|&i| t[i]).collect();
        assert_eq!(got, vec![0.0, -40.0, 40.0, -20.0, 20.0]);
        // an even count keeps the last one too; fewer than 5: all
        let t = [-40.0, -30.0, -20.0, -10.0, 0.0, 10.0];
        assert_eq!(cover_solved_temps(&t), vec![0, 2, 4, 5]);
        assert_eq!(
            cover_solved_temps(&[0.0, 10.0, 20.0, 30.0]),
            vec![0, 1, 2, 3]
        );
    }

    #[test]
    fn carried_ratios_are_exact_for_a_straight_q_and_their_error_is_measured_for_a_parabola() {
        // temperatures −40 … 40 every 10 K; 8 solved replicates, half-space ratios spread wide
        // (ln spread ≈ 0.9), q_b(T) = κ_b·T² + λ_b·T: the line between neighbours 10 K either side
        // of T lies κ_b·10² above q, and the measured error, from the line over 20 K either side
        // of an interior solved temperature (κ_b·20²), scaled by 10·10/(20·20), is the same
        let temps: Vec<f64> = (0..9).map(|i| -40.0 + 10.0 * i as f64).collect();
        let k = 8;
        let kappa: Vec<f64> = (0..k).map(|b| 1e-6 * (b as f64 - 3.5)).collect();
        let lam: Vec<f64> = (0..k).map(|b| 1e-4 * (b as f64 - 3.5)).collect();
        let hs: Vec<Vec<Result<f64, String>>> = temps
            .iter()
            .map(|_| {
                (0..32)
                    .map(|b| Ok((0.1 * (b as f64 - 15.5)).exp()))
                    .collect()
            })
            .collect();
        let q = |b: usize, t: f64| kappa[b] * t * t + lam[b] * t;
        let solved = cover_solved_temps(&temps);
        let sub: Vec<Vec<Result<f64, String>>> = solved
            .iter()
            .map(|&i| {
                (0..k)
                    .map(|b| Ok(hs[i][b].clone().unwrap() * q(b, temps[i]).exp()))
                    .collect()
            })
            .collect();
        let (out, sd) = carried(&temps, &solved, &hs, &sub);
        let rms = (kappa.iter().map(|x| x * x).sum::<f64>() / k as f64).sqrt() * 100.0;
        for i in 0..temps.len() {
            let row = out[i]
                .as_ref()
                .expect("every temperature carried or solved");
            if solved.contains(&i) {
                assert!(sd[i].is_none());
                continue;
            }
            // the carried error's standard deviation: rms over b of κ_b·10² (round-off only)
            let s = sd[i].expect("carried");
            assert!(
                (s - rms).abs() <= 1e-9 * rms,
                "T {}: {s} vs {rms}",
                temps[i]
            );
            for b in 0..k {
                let got = (row[b].clone().unwrap() / hs[i][b].clone().unwrap()).ln();
                let want = q(b, temps[i]) + kappa[b] * 100.0;
                assert!(
                    (got - want).abs() < 1e-12,
                    "T {} b {b}: {got} vs {want}",
                    temps[i]
                );
            }
        }
        // a q that spreads as much as the half-space ratios: nothing is carried
        let wide: Vec<Vec<Result<f64, String>>> = solved
            .iter()
            .map(|&i| {
                (0..k)
                    .map(|b| Ok(hs[i][b].clone().unwrap() * (0.2 * b as f64).exp()))
                    .collect()
            })
            .collect();
        let (out, sd) = carried(&temps, &solved, &hs, &wide);
        for i in (0..temps.len()).filter(|i| !solved.contains(i)) {
            assert!(out[i].is_none() && sd[i].is_none(), "T {}", temps[i]);
        }
    }

    #[test]
    fn the_solver_error_moves_each_quantile_outwards() {
        let plain = with_failures(0);
        let mut widened = with_failures(0);
        widened.solver_ln = vec![3e-4];
        let (a, _) = plain.point_band(0, 1e-3);
        let (b, _) = widened.point_band(0, 1e-3);
        let (a, b) = (a.unwrap(), b.unwrap());
        assert!(((b.p05 / a.p05).ln() + 3e-4).abs() < 1e-12);
        assert!(((b.p95 / a.p95).ln() - 3e-4).abs() < 1e-12);
        assert_eq!(a.p50, b.p50);
    }
}
