//! One compound from time-domain data (relaxation or creep isotherms) to a [`CompoundFit`]
//! (docs/MATH.md §18): read ([`crate::dma::time_domain`]) → shift in log t
//! ([`crate::tts::time_shift`]) → Prony fit in time ([`crate::prony::time_fit`], or the retardation
//! series converted exactly, [`crate::creep::time_fit`]) → exact creep spectrum. The fit file is the
//! frequency path's, so `roll`, `rank`, `export` and the reports take it unchanged.
//!
//! Its `master_curve` holds no measured E′, E″ (there are none): it holds the fitted spectrum's E′(ω)
//! and E″(ω) at ω = 1/t_r of every reduced time t_r of the data (eq. 18.3), so its frequency window
//! is the window the data determine, and the stages after flag frequencies beyond it as they flag
//! those beyond a measured master curve. The `tts` summary says so in its warnings.
//!
//! What such a fit determines ([`mark_time_domain_points`]): friction only at the points whose
//! rolling frequency lies inside the data's window by half the contact's decade (eq. 18.3) and
//! whose tan δ the data resolve (eq. 18.6); the others are marked not determined, so `rank` and
//! `run` leave them out as they leave out points beyond the measured temperatures.

use super::error::PipelineError;
use super::fit_compound::{FitOptions, MASTER_OVERLAP_RMS_BOUND};
use crate::dma::time_domain::{read_time_files, TimeData, TimeMode};
use crate::prony::time_fit::{fit_relaxation_in_time, TimeDatum};
use crate::prony::MasterPoint as PronyPoint;
use crate::results::{CompoundFit, MeasurementSummary, QualityFigure, TtsSummary};
use std::f64::consts::PI;
use std::path::PathBuf;

/// Fit relaxation or creep isotherms (module docs). `options.master.tref_c` is the reference
/// temperature (default: the isotherm nearest the middle); the Prony settings are the frequency
/// fit's.
pub fn fit_time_data(
    compound: &str,
    data: &TimeData,
    options: &FitOptions,
) -> Result<CompoundFit, PipelineError> {
    let master = crate::tts::time_shift::shift_time_data(data, options.master.tref_c)?;
    fit_time_master_curve(compound, data, &master, options)
}

/// Fit pyvisco's time-domain master curve (`t, E_relax`, read already reduced to its T_ref with
/// its shift factors, `crate::dma::pyvisco_time`) in time, as `fit_time_data` fits shifted
/// isotherms. Without a shift file the law is a single temperature's (a_T = 1 at T_ref, known
/// nowhere else), and a warning says that the friction is then determined at T_ref only.
pub fn fit_pyvisco_time_master(
    compound: &str,
    pv: &crate::dma::pyvisco_time::PyviscoTimeMaster,
    options: &FitOptions,
) -> Result<CompoundFit, PipelineError> {
    use crate::tts::time_shift::master_from_reduced;
    let (law, note) = match &pv.shift_law {
        Some(law) => (law.clone(), None),
        None => (
            crate::ShiftLaw::single_temperature(pv.t_ref_c),
            Some(format!(
                "no shift-factor file: the master curve is known at {} °C only (a_T = 1 there, no law elsewhere), so its friction is determined at that temperature only",
                pv.t_ref_c
            )),
        ),
    };
    let mut master = master_from_reduced(&pv.data, pv.t_ref_c, law);
    master.warnings.extend(note);
    fit_time_master_curve(compound, &pv.data, &master, options)
}

/// The Prony fit in time of a time-domain master curve and the [`CompoundFit`] built from it
/// (module docs); `data` are the isotherms it was made of.
fn fit_time_master_curve(
    compound: &str,
    data: &TimeData,
    master: &crate::tts::time_shift::TimeMaster,
    options: &FitOptions,
) -> Result<CompoundFit, PipelineError> {
    let points: Vec<TimeDatum> = master
        .points
        .iter()
        .map(|p| TimeDatum {
            time_s: p.reduced_time_s,
            value: p.value,
        })
        .collect();
    let function = data.symbol();
    let prony = match data.mode {
        TimeMode::Relaxation => {
            fit_relaxation_in_time(&points, data.kind, data.poisson, &options.prony, function)?
        }
        TimeMode::Creep => {
            crate::creep::time_fit::fit_creep_in_time(
                &points,
                data.kind,
                data.poisson,
                &options.prony,
                function,
            )?
            .0
        }
    };
    // The creep spectrum the contact takes: the exact conversion of the relaxation spectrum, as on
    // the frequency path (for creep data the round trip of the fitted retardation series).
    let (creep, _) = crate::creep::relaxation_to_creep(&prony.spectrum)?;
    let curve: Vec<PronyPoint> = points
        .iter()
        .map(|p| {
            let (e1, e2) = prony.spectrum.complex_modulus(1.0 / p.time_s);
            PronyPoint::new(1.0 / (2.0 * PI * p.time_s), e1, e2)
        })
        .rev()
        .collect();
    let notes = prony
        .info
        .time_domain
        .as_ref()
        .map_or(Vec::new(), |t| t.notes.clone());
    let mut fit = CompoundFit::new(
        compound,
        &stub_measurement(data),
        master.shift_law.clone(),
        curve,
        prony,
        options.prony.clone(),
    );
    fit.measurement = summary(data);
    fit.creep = Some(creep);
    fit.settings.stages = options.stages();
    fit.settings.stages.insert(
        "time_domain".into(),
        serde_json::json!({ "mode": data.mode, "function": function }),
    );
    fit.quality.push(QualityFigure::bounded(
        "master_overlap_rms_max_log10",
        master.overlap_rms_max_log10(),
        "log10",
        MASTER_OVERLAP_RMS_BOUND,
    ));
    let mut warnings = master.warnings.clone();
    warnings.push(format!(
        "time-domain data ({function}): the master curve's E′, E″ are the fitted spectrum's at ω = 1/t of the reduced times, not measured; the fit's E′, E″ errors are those of {function}"
    ));
    warnings.extend(notes);
    let mut law_rms = Vec::new();
    if let Some(w) = &master.wlf {
        law_rms.push(("wlf".to_string(), w.rms_log10));
    }
    if let Some(a) = &master.arrhenius {
        law_rms.push(("arrhenius".to_string(), a.rms_log10));
    }
    fit.tts = Some(TtsSummary {
        shifts: master
            .shifts
            .iter()
            .map(|s| (s.temp_c, s.log10_a_t))
            .collect(),
        wlf: master.wlf.as_ref().map(|w| w.law()),
        arrhenius: master.arrhenius.as_ref().map(|a| a.law()),
        law_rms_log10: law_rms,
        flags: Vec::new(),
        warnings,
    });
    Ok(fit)
}

/// Whether a compound's files are all time-domain data, by the evidence `fit --time-domain` reads
/// ([`crate::dma::time_domain::looks_like_time_data`]: a TRIOS relaxation or creep step, or a
/// header naming a time column and a modulus or compliance column); `run` then fits them so
/// ([`fit_time_files`]). A file that cannot be read is not evidence (the DMA path reports it).
pub fn files_are_time_data(files: &[PathBuf]) -> bool {
    !files.is_empty()
        && files.iter().all(|f| {
            crate::fsutil::read_regular(f, crate::limits::INPUT_BYTES_MAX).is_ok_and(|b| {
                // decoded as the readers decode (RheoCompass writes UTF-16)
                crate::dma::time_domain::looks_like_time_data(&crate::dma::text::decode(&b).text)
            })
        })
}

/// [`fit_time_files`] with the measurement record of the data (for the reports: it holds their
/// sources, kind and ν, no isotherms of E′, E″). One file that is pyvisco's time-domain master
/// curve (`t, E_relax`, [`crate::dma::pyvisco_time`]) is fitted as such, with `shift_factors` when
/// given (else `options.master.tref_c` must state its temperature); shift factors with isotherms
/// are refused (the isotherms are shifted here).
pub fn fit_time_files_with_measurement(
    compound: &str,
    files: &[PathBuf],
    shift_factors: Option<&std::path::Path>,
    poisson: f64,
    options: &FitOptions,
) -> Result<(CompoundFit, crate::Measurement), PipelineError> {
    let pyvisco = match files {
        [one] => crate::fsutil::read_regular(one, crate::limits::INPUT_BYTES_MAX)
            .is_ok_and(|b| crate::dma::pyvisco_time::is_time_master(&b)),
        _ => false,
    };
    let (data, fit) = if pyvisco {
        let pv = crate::dma::pyvisco_time::read_time_master(
            &files[0],
            shift_factors,
            poisson,
            options.master.tref_c,
        )?;
        let fit = fit_pyvisco_time_master(compound, &pv, options)?;
        (pv.data, fit)
    } else if let Some(sf) = shift_factors {
        return Err(PipelineError::Setting {
            field: "shift_factors".into(),
            message: format!(
                "{}: shift factors go with a master curve read already shifted (pyvisco's `t, E_relax` CSV); relaxation or creep isotherms are shifted here",
                sf.display()
            ),
        });
    } else {
        let data = read_time_files(files, poisson)?;
        let fit = fit_time_data(compound, &data, options)?;
        (data, fit)
    };
    let mut m = stub_measurement(&data);
    m.warnings = fit.measurement.warnings.clone();
    Ok((fit, m))
}

/// The largest relative standard error of tan δ at a point's rolling frequency with which a
/// time-domain fit's friction counts as determined (eq. 18.6).
pub const TAN_DELTA_REL_SE_MAX: f64 = 0.1;

/// Why a friction point of a time-domain fit is not determined (None when it is, and for a fit to
/// frequency-domain data, whose E″ is measured): its rolling frequency V/l reduced to T_ref
/// (`crate::bands::window`, as the frequency path's window term reads it) must lie half a contact
/// spread inside the data's window (eq. 18.3), and the data must resolve tan δ there (eq. 18.6: the
/// local slope of log E(t) or log J(t) over that decade, from the fit's residual scatter and the
/// points in it).
pub fn time_domain_undetermined(
    fit: &CompoundFit,
    speed_m_s: f64,
    contact_length_m: f64,
    log10_a_t: f64,
) -> Option<String> {
    use crate::bands::window::{
        measured_window_hz, rolling_reduced_freq_hz, CONTACT_SPREAD_DECADES,
    };
    let td = fit.prony_info.time_domain.as_ref()?;
    let f = rolling_reduced_freq_hz(speed_m_s, contact_length_m, log10_a_t);
    if !(f.is_finite() && f > 0.0) {
        return None;
    }
    let Some((lo, hi)) = measured_window_hz(fit) else {
        return Some("the time-domain data have no window".into());
    };
    let half = 0.5 * CONTACT_SPREAD_DECADES;
    if (f / lo).log10() < half || (hi / f).log10() < half {
        return Some(format!(
            "its rolling frequency reduced to T_ref, {f:.2e} Hz, is not {half} decade inside the window of the time-domain data, {lo:.2e} … {hi:.2e} Hz (docs/MATH.md eq. 18.3)"
        ));
    }
    // eq. 18.6: the slope m of ln y against ln t over the decade around 1/(2π f) from n points of
    // relative scatter σ has the standard error σ·√(12/n)/ln 10; tan δ = tan(π m/2).
    let n = fit
        .master_curve
        .iter()
        .filter(|p| (p.reduced_freq_hz / f).log10().abs() <= half)
        .count() as f64;
    let se_slope = td.rms_log10 * (12.0 / n).sqrt();
    let (e1, e2) = fit.relaxation.complex_modulus(2.0 * PI * f);
    let tan = e2 / e1;
    let u = 0.5 * PI * (1.0 + tan * tan) * se_slope / tan;
    // a NaN u (no points in the decade) is not determined either
    (u.is_nan() || u > TAN_DELTA_REL_SE_MAX).then(|| {
        format!(
            "the time-domain data resolve its tan δ = {tan:.2e} only to ±{:.0} % (docs/MATH.md eq. 18.6; limit {:.0} %)",
            100.0 * u,
            100.0 * TAN_DELTA_REL_SE_MAX
        )
    })
}

/// Mark the points of a time-domain fit that its data do not determine
/// ([`time_domain_undetermined`]), after `FrictionPoint::determine`; other fits are left alone.
pub fn mark_time_domain_points(
    fit: &CompoundFit,
    speed_m_s: f64,
    points: &mut [crate::results::FrictionPoint],
) {
    if fit.prony_info.time_domain.is_none() {
        return;
    }
    for p in points
        .iter_mut()
        .filter(|p| p.error.is_none() && p.friction.is_finite())
    {
        let why = time_domain_undetermined(fit, speed_m_s, p.contact_length_mm * 1e-3, p.log10_a_t);
        if let Some(why) = why {
            p.undetermined = Some(match p.undetermined.take() {
                Some(u) => format!("{u}; {why}"),
                None => format!("not determined: {why}"),
            });
        }
    }
}

/// A measurement with the data's sources, kind and ν (for [`CompoundFit::new`]'s provenance).
fn stub_measurement(data: &TimeData) -> crate::Measurement {
    crate::Measurement {
        sources: data.sources.clone(),
        kind: data.kind,
        poisson: data.poisson,
        isotherms: Vec::new(),
        warnings: Vec::new(),
        issues: Vec::new(),
        summary: Default::default(),
    }
}

/// The measurement summary of time-domain data: its frequency range is 1/(2πt) of the times
/// measured.
fn summary(data: &TimeData) -> MeasurementSummary {
    let times = data
        .isotherms
        .iter()
        .flat_map(|i| i.points.iter().map(|p| p.time_s));
    let (lo, hi) = times.fold((f64::INFINITY, 0.0f64), |(lo, hi), t| {
        (lo.min(t), hi.max(t))
    });
    let mut warnings = data.warnings.clone();
    warnings.extend(data.evidence.iter().map(|e| format!("mode: {e}")));
    MeasurementSummary {
        sources: data.sources.clone(),
        kind: data.kind,
        poisson: data.poisson,
        n_isotherms: data.isotherms.len(),
        n_points: data.isotherms.iter().map(|i| i.points.len()).sum(),
        temps_nominal_c: data.isotherms.iter().map(|i| i.temp_c).collect(),
        freq_min_hz: 1.0 / (2.0 * PI * hi),
        freq_max_hz: 1.0 / (2.0 * PI * lo),
        warnings,
    }
}

#[cfg(test)]
mod tests {
    //! The accuracy table of docs/USER_GUIDE.md ("Time-domain data"): synthetic relaxation and creep
    //! isotherms and frequency sweeps of one known spectrum under one WLF law, each through its path
    //! to friction (as `rank` takes a fit file), against the truth; and the friction error split by
    //! stage. `cargo test --lib pipeline::fit_time -- --nocapture` prints both.
    use super::*;
    use crate::creep::time_fit::fit_creep_in_time;
    use crate::dma::time_domain::time_data_from_bytes;
    use crate::prony::PronySettings;
    use crate::results::SceneSpec;
    use crate::testdata::time_domain::{time_domain_csv, TimeSettings};
    use crate::testdata::{broad_spectrum, synthetic_measurement, SyntheticSettings};
    use crate::{CreepSpectrum, ModulusKind, RelaxationSpectrum, ShiftLaw};

    const NOISE: f64 = 0.01;
    const SEED: u64 = 11;

    fn law() -> ShiftLaw {
        ShiftLaw::Wlf {
            t_ref_c: 20.0,
            c1: 8.86,
            c2_k: 101.6,
        }
    }

    fn temps() -> Vec<f64> {
        (0..=20).map(|k| -40.0 + 5.0 * k as f64).collect()
    }

    fn options() -> FitOptions {
        let mut o = FitOptions::default();
        o.master.tref_c = Some(20.0);
        o
    }

    fn data(mode: TimeMode, noise_rel: f64) -> TimeData {
        let s = TimeSettings {
            temps_c: temps(),
            window_s: (1.0, 1e4),
            per_decade: 10,
            noise_rel,
            seed: SEED,
        };
        let csv = time_domain_csv(&broad_spectrum(), mode, &law(), &s);
        time_data_from_bytes(&[("synthetic.csv".into(), csv.into_bytes())], 0.5).unwrap()
    }

    fn time_fit(mode: TimeMode) -> CompoundFit {
        fit_time_data("t", &data(mode, NOISE), &options()).unwrap()
    }

    fn freq_fit() -> CompoundFit {
        let mut s = SyntheticSettings::new(temps(), law());
        s.noise_rel = NOISE;
        s.seed = SEED;
        let m = synthetic_measurement(&broad_spectrum(), &s);
        crate::pipeline::fit_measurement("f", &m, &options()).unwrap()
    }

    fn scene_spec() -> SceneSpec {
        crate::results::SceneSet::shipped()
            .scene
            .into_iter()
            .find(|s| s.name == "conveyor-idler-half-space")
            .unwrap()
    }

    /// The friction of `creep` (at T_ref) moved to `temp_c` by `law` on the scene.
    fn friction(creep: &CreepSpectrum, law: &ShiftLaw, temp_c: f64) -> f64 {
        let at = creep.at_temperature(law, temp_c, None).unwrap();
        let settings = crate::pipeline::scenes::pipeline_contact_settings();
        crate::contact::roll(&scene_spec().scene(), &at.spectrum, &settings)
            .unwrap()
            .friction
    }

    fn truth_friction(temp_c: f64) -> f64 {
        let (c, _) = crate::creep::relaxation_to_creep(&broad_spectrum()).unwrap();
        friction(&c, &law(), temp_c)
    }

    /// One scene point of a fit as `rank` sees it.
    struct Point {
        temp_c: f64,
        rel_err: f64,
        undetermined: Option<String>,
    }

    /// The fit's points on the scene through `rank`'s path (`rank_fits`: the friction, then what
    /// is determined, `mark_time_domain_points` for time-domain fits) against the truth, and
    /// whether the compound is ranked.
    fn ranked_points(fit: &CompoundFit) -> (Vec<Point>, bool) {
        let (ranked, _) =
            crate::pipeline::run::rank_fits(std::slice::from_ref(fit), &scene_spec(), false, None);
        let (_, points, standing) = ranked.into_iter().next().unwrap().unwrap();
        let v = points
            .into_iter()
            .map(|p| Point {
                temp_c: p.temp_c,
                rel_err: p.friction / truth_friction(p.temp_c) - 1.0,
                undetermined: p.undetermined,
            })
            .collect();
        (v, standing.trusted())
    }

    /// Largest |log10 a_T − truth| over the isotherms above −40 °C, and at −40 °C (the glassy
    /// plateau, where a relaxation or creep isotherm is flat).
    fn shift_error(fit: &CompoundFit) -> (f64, f64) {
        let shifts = &fit.tts.as_ref().unwrap().shifts;
        let err = |&(t, a): &(f64, f64)| (a - law().log10_a_t(t)).abs();
        (
            shifts[1..].iter().map(err).fold(0.0, f64::max),
            err(&shifts[0]),
        )
    }

    fn rms(v: &[f64]) -> f64 {
        (v.iter().map(|e| e * e).sum::<f64>() / v.len().max(1) as f64).sqrt()
    }

    /// RMS log10 error of E(t) at T_ref over 1e-12…1e6 s and of E′, E″ inside the fit's frequency
    /// window (ω = 1e-6…1e12 rad/s).
    fn moduli_errors(fit: &RelaxationSpectrum, window_hz: [f64; 2]) -> [f64; 3] {
        let truth = broad_spectrum();
        let e_t: Vec<f64> = (0..=180)
            .map(|k| 10f64.powf(-12.0 + 0.1 * k as f64))
            .map(|t| (fit.relaxation_modulus(t) / truth.relaxation_modulus(t)).log10())
            .collect();
        let (mut in1, mut in2) = (vec![], vec![]);
        for k in 0..=180 {
            let w = 10f64.powf(-6.0 + 0.1 * k as f64);
            let f = w / (2.0 * PI);
            if f >= window_hz[0] && f <= window_hz[1] {
                let ((a1, a2), (b1, b2)) = (fit.complex_modulus(w), truth.complex_modulus(w));
                in1.push((a1 / b1).log10());
                in2.push((a2 / b2).log10());
            }
        }
        [rms(&e_t), rms(&in1), rms(&in2)]
    }

    /// Largest |error| among `points` that are determined (or not), with their temperatures.
    fn worst(points: &[Point], determined: bool) -> (f64, Vec<f64>) {
        let sel: Vec<&Point> = points
            .iter()
            .filter(|p| p.undetermined.is_none() == determined)
            .collect();
        (
            sel.iter().map(|p| p.rel_err.abs()).fold(0.0, f64::max),
            sel.iter().map(|p| p.temp_c).collect(),
        )
    }

    #[test]
    fn time_domain_fits_give_the_frequency_paths_friction_where_their_data_determine_it() {
        let fits = [
            ("relaxation E(t)", time_fit(TimeMode::Relaxation)),
            ("creep D(t)", time_fit(TimeMode::Creep)),
            ("frequency E′, E″", freq_fit()),
        ];
        eprintln!("| path | max abs log10 a_T error, −35…60 °C (at −40 °C) | RMS log10 E(t), 1e-12…1e6 s | RMS log10 E′ / E″ in the fit's window | friction max rel. error at the determined points (°C) | at the points not determined (°C) | ranked |");
        let mut rows = Vec::new();
        for (name, fit) in &fits {
            let m = moduli_errors(&fit.relaxation, fit.prony_info.freq_window_hz);
            let s = shift_error(fit);
            let (points, ranked) = ranked_points(fit);
            let (det, undet) = (worst(&points, true), worst(&points, false));
            eprintln!(
                "| {name} | {:.3} ({:.2}) | {:.4} | {:.4} / {:.4} | {:.2} % ({:?}) | {:.0} % ({:?}) | {ranked} |",
                s.0, s.1, m[0], m[1], m[2], 100.0 * det.0, det.1, 100.0 * undet.0, undet.1
            );
            rows.push((s, m, points, det, ranked));
        }
        let freq_worst = rows[2].3 .0;
        // the frequency path: every point determined (the sweeps reach 3 decades further into the
        // glassy end than the time data), as accurate as the issue states (1.9 %)
        assert!(rows[2].3 .1.len() == 9 && freq_worst < 0.03, "{freq_worst}");
        for (name, (s, m, points, det, ranked)) in fits.iter().map(|f| f.0).zip(&rows[..2]) {
            // 1 % noise on 10 points a decade: a pair's shift is known to ~0.01 decade and 20 pairs
            // chain (measured ≤ 0.063); the −40 °C isotherm on the glassy plateau is placed by the
            // WLF fit of the others, 5 K extrapolated (eq. 18.5b; measured 0.07 and 0.02 decade).
            // E(t) and E′ within the noise (0.0043 decade).
            assert!(s.0 < 0.1 && s.1 < 0.15, "{name}: shifts {s:?}");
            assert!(m[0] < 0.01 && m[1] < 0.01, "{name}: {m:?}");
            // −40 and −30 °C roll at reduced frequencies at or beyond the glassy end of the data
            // (noise-free data give 13–804 % there: the breakdown test), so they are not determined.
            for t in [-40.0, -30.0] {
                let p = points.iter().find(|p| p.temp_c == t).unwrap();
                assert!(
                    p.undetermined
                        .as_deref()
                        .is_some_and(|u| u.contains("18.3")),
                    "{name} {t}: {:?}",
                    p.undetermined
                );
            }
            // The points it determines (0…40 °C here) are within twice the frequency path's worst
            // (measured 1.7 % and 2.0 % against 1.9 %), and the fit is ranked on them.
            assert!(det.1.len() >= 5, "{name}: determined at {:?}", det.1);
            assert!(
                det.0 <= 2.0 * freq_worst,
                "{name}: {} vs {freq_worst}",
                det.0
            );
            assert!(*ranked, "{name}");
        }
    }

    /// Noisy points shifted by the true law (the shifts' share taken out).
    fn true_points(d: &TimeData) -> Vec<TimeDatum> {
        let mut v: Vec<TimeDatum> = d
            .isotherms
            .iter()
            .flat_map(|i| {
                let a = 10f64.powf(law().log10_a_t(i.temp_c));
                i.points.iter().map(move |p| TimeDatum {
                    time_s: p.time_s / a,
                    value: p.value,
                })
            })
            .collect();
        v.sort_by(|a, b| a.time_s.total_cmp(&b.time_s));
        v
    }

    /// The creep spectrum the chain rolls on (the exact conversion of the fitted relaxation
    /// spectrum) and, for creep data, the fitted retardation series itself.
    fn fit_points(pts: &[TimeDatum], mode: TimeMode) -> (CreepSpectrum, Option<CreepSpectrum>) {
        let s = PronySettings::default();
        let (relax, direct) = match mode {
            TimeMode::Relaxation => (
                fit_relaxation_in_time(pts, ModulusKind::Tensile, 0.5, &s, "E(t)")
                    .unwrap()
                    .spectrum,
                None,
            ),
            TimeMode::Creep => {
                let (f, c) = fit_creep_in_time(pts, ModulusKind::Tensile, 0.5, &s, "D(t)").unwrap();
                (f.spectrum, Some(c))
            }
        };
        (crate::creep::relaxation_to_creep(&relax).unwrap().0, direct)
    }

    #[test]
    fn the_friction_error_splits_by_stage() {
        eprintln!("| data | T °C | rolling f·a_T, Hz | decades inside the data's window | full chain | true shifts | noise-free, true shifts | determined |");
        for mode in [TimeMode::Relaxation, TimeMode::Creep] {
            let fit = time_fit(mode);
            let (points, _) = ranked_points(&fit);
            let (lo, hi) = crate::bands::window::measured_window_hz(&fit).unwrap();
            let (shifted, _) = fit_points(&true_points(&data(mode, NOISE)), mode);
            let (clean, direct) = fit_points(&true_points(&data(mode, 0.0)), mode);
            for p in &points {
                let t = p.temp_c;
                let truth = truth_friction(t);
                let rel = |c: &CreepSpectrum| friction(c, &law(), t) / truth - 1.0;
                let (e_shifted, e_clean) = (rel(&shifted), rel(&clean));
                let l = crate::contact::roll(
                    &scene_spec().scene(),
                    &crate::creep::relaxation_to_creep(&broad_spectrum())
                        .unwrap()
                        .0
                        .at_temperature(&law(), t, None)
                        .unwrap()
                        .spectrum,
                    &crate::pipeline::scenes::pipeline_contact_settings(),
                )
                .unwrap()
                .contact_length_m;
                let f = crate::bands::window::rolling_reduced_freq_hz(
                    scene_spec().scene().speed_m_s,
                    l,
                    law().log10_a_t(t),
                );
                let inside = (f / lo).log10().min((hi / f).log10());
                eprintln!(
                    "| {mode:?} | {t} | {f:.1e} | {inside:.1} | {:.1} % | {:.1} % | {:.1} % | {} |",
                    100.0 * p.rel_err,
                    100.0 * e_shifted,
                    100.0 * e_clean,
                    p.undetermined.is_none()
                );
                if p.undetermined.is_none() {
                    // Noise-free data on the true shifts: the Prony basis (2 terms a decade) and the
                    // contact solver (tolerance 1e-3) alone, measured ≤ 0.04 %.
                    assert!(e_clean.abs() < 0.01, "{mode:?} {t}: {e_clean}");
                }
                if let Some(d) = &direct {
                    // The retardation series against its exact round trip (docs/MATH.md §4): the
                    // interconversion adds nothing (measured ≤ 1e-5 relative).
                    let (a, b) = (friction(d, &law(), t), friction(&clean, &law(), t));
                    assert!((a / b - 1.0).abs() < 1e-3, "{t}: {a} vs {b}");
                }
            }
        }
    }

    #[test]
    fn the_time_domain_fit_file_says_what_it_holds_and_goes_through_json() {
        let fit = time_fit(TimeMode::Creep);
        let tts = fit.tts.as_ref().unwrap();
        assert!(
            tts.warnings.iter().any(|w| w.contains("not measured")),
            "{tts:?}"
        );
        assert!(fit.measurement.warnings.iter().any(|w| w.contains("creep")));
        let back: CompoundFit =
            serde_json::from_str(&serde_json::to_string(&fit).unwrap()).unwrap();
        assert_eq!(back.prony_info.time_domain, fit.prony_info.time_domain);
        // The master curve's window is the data's: 1/(2π t) of the reduced times.
        let [f0, f1] = fit.prony_info.freq_window_hz;
        let (lo, hi) = (
            fit.master_curve[0].reduced_freq_hz,
            fit.master_curve.last().unwrap().reduced_freq_hz,
        );
        assert!((lo / f0 - 1.0).abs() < 1e-9 && (hi / f1 - 1.0).abs() < 1e-9);
    }

    #[test]
    fn roll_on_a_time_domain_fit_warns_where_its_friction_is_not_determined() {
        let source =
            crate::pipeline::roll_fit::CreepSource::Fit(Box::new(time_fit(TimeMode::Relaxation)));
        let settings = crate::pipeline::scenes::pipeline_contact_settings();
        let warned = |t: f64| {
            crate::pipeline::roll_fit::roll_source_at(
                &source,
                Some(t),
                &scene_spec().scene(),
                &settings,
            )
            .unwrap()
            .warnings
            .iter()
            .any(|w| w.starts_with("friction not determined"))
        };
        // as `rank` marks them (the accuracy test): −40 °C beyond the window, 20 °C determined
        assert!(warned(-40.0) && !warned(20.0));
    }

    #[test]
    fn a_frequency_domain_fits_points_are_left_alone() {
        let fit = freq_fit();
        assert_eq!(time_domain_undetermined(&fit, 4.0, 1e-3, 0.0), None);
    }
}
