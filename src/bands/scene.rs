//! The replicate ratios of one compound in one scene (docs/MATH.md §15, steps 4–5): every replicate
//! of the ensemble solved at every temperature of the scene, as a ratio to the fit's own friction
//! solved the same way (eqs. 15.5, 15.6, 15.6b), with the model-error terms of the points beyond the
//! measured temperatures (eq. 15.8) and beyond the measured frequencies (eq. 15.9) drawn in, and the
//! failed solves counted; then each point's band with its notes ([`SceneRatios::point_band`]).
//!
//! Input: a [`CompoundFit`] with its [`BandEnsemble`], a [`Scene`], [`BandSettings`]; output:
//! [`SceneRatios`].

use super::friction::{
    cover_solve, half_space_solve, predict_from_half_space, solver, tail_note, tail_term,
    too_many_failed, Solve, COVER_BAND_TOL,
};
use super::window::{
    continued_spectrum, excess, measured_window_hz, ramp_weight, rolling_reduced_freq_hz,
    window_note, WindowExcess, WindowSide,
};
use super::BandSettings;
use crate::contact::Scene;
use crate::results::{BandEnsemble, CompoundFit, FrictionBand};
use rayon::prelude::*;

/// Replicates of a covered scene whose ratios are solved on the covered body itself (eq. 15.6b);
/// the others are predicted from their half-space ratios by a regression on these. Eight: the
/// regression then has 6 degrees of freedom for its residual; checked against the full bootstrap
/// on the shipped compounds (`cargo bench --bench bands_cover`, README).
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
}

impl SceneRatios {
    fn empty(n: usize) -> Self {
        Self {
            ratios: vec![Vec::new(); n],
            tail_ln: vec![None; n],
            window: vec![None; n],
            first_failure: vec![None; n],
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
        let Some(band) = super::band_of(value, r) else {
            return (
                None,
                vec![format!(
                    "uncertainty band refused: only {} of {n} replicates solved",
                    n - failed
                )],
            );
        };
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

/// Per temperature of `temps_c`, the ratio F_b/F̂ of each replicate b (NaN where a solve failed),
/// on a cover of `cover_m` bonded to a rigid carcass (eq. 15.6): each replicate's
/// creep spectrum, shifted by its own law, through the body `auto` chooses
/// (`roll_cover`, at [`COVER_BAND_TOL`] or the band tolerance if looser), as the nominal
/// friction; `None`: the half-space at `settings.contact_tol`. On a cover, only
/// [`COVER_SOLVED_REPLICATES`] replicates are solved on the cover; the rest come from their
/// half-space ratios (eq. 15.6b, [`predict_from_half_space`]). Points beyond the measured
/// temperatures or frequencies get the terms of eqs. 15.8 and 15.9 ([`scene_bands_on`]).
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

/// [`scene_ratios_on`] with every replicate solved on the cover (the full bootstrap of eq. 15.6,
/// 32 layer solves per temperature; the same model-error terms): the reference the cheaper
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

/// [`scene_ratios_on`] with the model-error terms it drew in and the failures it met (module doc,
/// eqs. 15.6, 15.6b, 15.8, 15.9). Each term enters each replicate as a factor e^(s·u_b), u_b
/// standard normal, one draw per replicate, term and side (below, above the measured range): the
/// alternative's change is taken as one standard deviation, so the 90 % band spans ±1.645 of it.
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

/// [`scene_bands_on`] on a cover with the nominal covered solves already done: `nominal[i]` the
/// fit's friction and contact length (m) at `temps_c[i]` on the cover by `auto` at
/// [`COVER_BAND_TOL`] (the main job's covered points are exactly that solve: crate::pipeline's
/// `COVER_TOL` is the same 1e−3), NaN where it failed (then solved here). Saves one layer solve
/// per temperature. Without a cover, or with a band tolerance looser than [`COVER_BAND_TOL`],
/// `nominal` is not used (the half-space's ratios are over the fit solved at the band tolerance,
/// not the report's).
pub fn scene_bands_given(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    scene: &Scene,
    cover_m: Option<f64>,
    temps_c: &[f64],
    settings: &BandSettings,
    nominal: &[(f64, f64)],
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
/// Streams of the frequency-window term's draws below and above the measured window (eq. 15.9).
const STREAM_WINDOW_LOW: u64 = 0x7769_6e64_0000_0001;
const STREAM_WINDOW_HIGH: u64 = 0x7769_6e64_0000_0002;

/// Per temperature, per replicate of `which` (indices into the ensemble), F_b/F̂ over the given
/// nominal frictions F̂ solved by `solve`, or why it failed; parallel over (temperature, replicate).
fn ratios_over(
    fit: &CompoundFit,
    ensemble: &BandEnsemble,
    temps_c: &[f64],
    which: &[usize],
    solve: &Solve,
    nominal: &[Result<f64, String>],
) -> Vec<Vec<Result<f64, String>>> {
    let law = &fit.shift_law;
    let nb = which.len();
    let mut flat: Vec<Result<f64, String>> = (0..temps_c.len() * nb)
        .into_par_iter()
        .map(|k| {
            let (i, b) = (k / nb, which[k % nb]);
            let f0 = nominal[i]
                .as_ref()
                .map_err(|e| format!("the fit's own solve failed: {e}"))?;
            let r = &ensemble.replicates[b];
            Ok(solve(&r.creep, r.log10_a_t(law, temps_c[i]))? / f0)
        })
        .collect();
    let mut out = Vec::with_capacity(temps_c.len());
    for _ in 0..temps_c.len() {
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
    nominal: Option<&[(f64, f64)]>,
) -> SceneRatios {
    let Some(creep) = fit.creep.as_ref() else {
        return SceneRatios::empty(temps_c.len());
    };
    let nb = ensemble.replicates.len();
    let all: Vec<usize> = (0..nb).collect();
    let half_space = solver(scene, None, settings);
    let covered = solver(scene, cover_m, settings);
    let law = &fit.shift_law;
    // the fit on the half-space at the band tolerance: the half-space ratios' F̂ (and, without a
    // cover, its contact length l for the rolling frequency V/l of eq. 15.9)
    let hs_fit: Vec<Result<(f64, f64), String>> = temps_c
        .par_iter()
        .map(|&t| {
            half_space_solve(scene, creep, law.log10_a_t(t), settings)
                .map(|r| (r.friction, r.contact_length_m))
        })
        .collect();
    let hs_nominal: Vec<Result<f64, String>> = hs_fit
        .iter()
        .map(|r| r.as_ref().map(|x| x.0).map_err(Clone::clone))
        .collect();
    // the body's nominal friction and contact length: the half-space's, or on a cover given
    // (finite ones), else solved; the cover's l, shorter than the half-space's, sets V/l there
    let body_fit: Vec<Result<(f64, f64), String>> = match cover_m {
        None => hs_fit.clone(),
        Some(h_m) => temps_c
            .par_iter()
            .enumerate()
            .map(|(i, &t)| match nominal.and_then(|n| n.get(i)) {
                Some(&(f, l)) if f.is_finite() && f > 0.0 && l.is_finite() && l > 0.0 => Ok((f, l)),
                _ => cover_solve(scene, creep, law.log10_a_t(t), h_m, settings)
                    .map(|r| (r.friction, r.contact_length_m)),
            })
            .collect(),
    };
    let body_nominal: Vec<Result<f64, String>> = body_fit
        .iter()
        .map(|r| r.as_ref().map(|x| x.0).map_err(Clone::clone))
        .collect();
    let (mut ratios, first_failure): (Vec<Vec<f64>>, Vec<Option<String>>) = match cover_m {
        None => ratios_over(fit, ensemble, temps_c, &all, &half_space, &body_nominal)
            .into_iter()
            .map(split)
            .unzip(),
        Some(_) if full => ratios_over(fit, ensemble, temps_c, &all, &covered, &body_nominal)
            .into_iter()
            .map(split)
            .unzip(),
        Some(_) => {
            let hs = ratios_over(fit, ensemble, temps_c, &all, &half_space, &hs_nominal);
            let k = COVER_SOLVED_REPLICATES.min(nb);
            let first: Vec<usize> = (0..k).collect();
            let sub = ratios_over(fit, ensemble, temps_c, &first, &covered, &body_nominal);
            let z: Vec<f64> = (0..nb)
                .map(|b| replicate_normal(settings.seed, STREAM_COVER, b))
                .collect();
            hs.into_iter()
                .zip(sub)
                .enumerate()
                .map(|(i, (hs, sub))| {
                    predicted(hs, sub, &z).unwrap_or_else(|| {
                        // too few covered solves succeeded for the regression: all on the cover
                        let one = ratios_over(
                            fit,
                            ensemble,
                            &temps_c[i..=i],
                            &all,
                            &covered,
                            &body_nominal[i..=i],
                        );
                        split(one.into_iter().next().unwrap_or_default())
                    })
                })
                .unzip()
        }
    };
    let tail_ln: Vec<Option<f64>> = temps_c
        .par_iter()
        .zip(body_nominal.par_iter())
        .map(|(&t, f0)| tail_term(fit, creep, t, *f0.as_ref().ok()?, &covered))
        .collect();
    let window: Vec<Option<WindowTerm>> = temps_c
        .par_iter()
        .enumerate()
        .map(|(i, &t)| {
            let l = body_fit[i].as_ref().ok().map(|x| x.1);
            window_term(fit, scene, t, l, &body_nominal[i], &covered)
        })
        .collect();
    let (lo, _) = fit.measured_range_c().unwrap_or((f64::NAN, f64::NAN));
    for (i, r) in ratios.iter_mut().enumerate() {
        let mut terms: Vec<(f64, u64)> = Vec::new();
        if let Some(s) = tail_ln[i] {
            let low = temps_c[i] < lo;
            terms.push((
                s,
                if low {
                    STREAM_TAIL_LOW
                } else {
                    STREAM_TAIL_HIGH
                },
            ));
        }
        if let Some(WindowTerm {
            excess,
            s_ln: Ok(s),
        }) = &window[i]
        {
            let stream = match excess.side {
                WindowSide::Low => STREAM_WINDOW_LOW,
                WindowSide::High => STREAM_WINDOW_HIGH,
            };
            terms.push((*s, stream));
        }
        for (b, v) in r.iter_mut().enumerate() {
            let d: f64 = terms
                .iter()
                .map(|&(s, stream)| s * replicate_normal(settings.seed, stream, b))
                .sum();
            *v *= d.exp();
        }
    }
    SceneRatios {
        ratios,
        tail_ln,
        window,
        first_failure,
    }
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
}
