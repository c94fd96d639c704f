//! End to end against a known truth (issue 8, "what it must show"): DMA exports generated from known
//! relaxation spectra and WLF laws (viscoroll::testdata::realistic: four rubbers, 27–34 Prony
//! terms over 20 decades, E₀/E∞ 150–900, isotherms −60 … +100 °C every 5 K at 13 frequencies
//! 0.1–100 Hz, 1 % noise on E′ and 3 % on E″, measured temperatures within ±1.5 K of the step),
//! written to CSV files and run through the whole pipeline as
//! `viscoroll run` runs it (ingest → master curve → Prony fit → exact creep spectrum → friction, via
//! `pipeline::fit_files` and `pipeline::scenes::friction_vs_temperature`) at the shipped scenes
//! (data/scenes.toml) at −40 … +60 °C every 10 K. The reference is computed independently of every
//! fitted quantity: the true spectrum converted exactly to creep (crate::creep::exact, docs/MATH.md §4),
//! shifted by the true WLF law, through the same contact solver at the same tolerance. At −40, 10
//! and 60 °C in both scenes that true friction is also computed by an independent path (issue 19):
//! the thesis scheme with Richardson's extrapolation (n = 640/1280) at the contact length found,
//! with the thesis' §3.2 scaling written out in tests/reference.rs; it must give back the load and
//! the friction, so the truth no longer rests on the solver it checks.
//!
//! Acceptance (the figures): per compound, median relative friction error ≤ 2 %, worst ≤ 5 %
//! over both scenes × 11 temperatures, for three compounds; the fourth is a stress case with a
//! looser worst-case bound (see [`bounds`]). With the default seed every stage's figure is also held
//! to about 2–3× what it measures ([`tight_bounds`]). The table and a stage-by-stage breakdown print with
//! `cargo test --test tests known_truth -- --nocapture`.
//!
//! Measured with the default settings of `run` (slope-weighted shifts, E″ carrying a glass that
//! superposes, docs/MATH.md eq. 6.1; the shift table joined by a monotone cubic, eq. 6.3; default
//! seed, `cargo test --test tests known_truth::friction_from -- --nocapture`), 132 points
//! (4 compounds × 3 scenes × 11 temperatures):
//!
//! | compound      | median % | worst % | shift dec | Prony (spec) % |
//! |---------------|---------:|--------:|----------:|---------------:|
//! | nr-br-idler   |    0.452 |   1.351 |    0.0149 |          1.178 |
//! | nr-tread      |    0.257 |   1.011 |    0.0103 |          1.065 |
//! | sbr-tread     |    0.235 |   0.795 |    0.0196 |          0.814 |
//! | high-tg-tread |    0.177 |   2.614 |    0.0106 |          1.989 |
//! | all           |    0.265 |   2.614 |           |                |
//!
//! (With straight segments between the shifts: all 0.289 / 1.988 %.) The worst points are the
//! Prony fit at the glassy edge of the window, high-tg-tread at −40 °C (Prony 1.99 %, shifts
//! +0.63 %); next nr-br-idler conveyor-idler 50 °C −1.35 % (shifts −0.53, Prony −0.82). Over seeds
//! 1–10 (`known_truth_other_seeds`) the per-compound median is 0.09–0.55 % and the worst 2.84 %
//! (high-tg-tread, seed 3: Prony 2.07 %, shifts 0.78 %; with straight segments 2.39 %): issue 32's
//! goal (median ≤ 0.5 %, worst ≤ 2 %) is not met over seeds, and the largest share left is the
//! Prony fit at the glassy edge. That share is the data's scatter, not the fit's bias: without noise
//! the worst is 0.60 % ([`known_truth_noise_free_bias`]), the worst grows in proportion to the noise
//! (seeds 0–10: 1.52 % at half, 2.02 % at 0.7×, 2.84 % at the full 1 % / 3 %), and its sign at
//! high-tg-tread −40 °C changes with the seed (+2.8, +2.4, +1.4, +1.1, −1.2, −2.2 %); no weight rule,
//! fixed λ (1e-7 … 1e-2), term margin or loss weight brings it under 2 % (docs/DEVLOG.md, "The last
//! 2 %"). The fifth, stress compound (`known_truth_narrow_transition`):
//! median 0.69 %, worst 3.55 %.

use crate::reference::{friction_at_length, SceneSi};
use rayon::prelude::*;
use std::path::PathBuf;
use viscoroll::contact::roll_cover;
use viscoroll::contact::{roll, AutoSettings, Body, ContactSettings, Scene, Scheme};
use viscoroll::creep::relaxation_to_creep;
use viscoroll::pipeline::{fit_files, FitOptions};
use viscoroll::pipeline::{friction_vs_temperature, COVER_TOL};
use viscoroll::results::SceneSet;
use viscoroll::testdata::{dma_csv, dma_rows, realistic_compounds, DmaProtocol, RealisticCompound};
use viscoroll::CreepSpectrum;

/// Temperatures of the comparison, °C (the issue's −40 … +60 °C, every 10 K).
const TEMPS_C: [f64; 11] = [
    -40.0, -30.0, -20.0, -10.0, 0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0,
];

/// Contact tolerance of both sides: the auto scheme's error control bounds the relative error of
/// F/N by `tol`; 1e-4 is 200× below the 2 % target (and 500× below 5 %), so the solver contributes
/// at most 0.01 % + 0.01 % to a difference, while costing a fraction of the default 1e-6.
fn contact_settings() -> ContactSettings {
    ContactSettings {
        scheme: Scheme::Auto,
        auto: AutoSettings {
            tol: 1e-4,
            gap_check: false,
            ..AutoSettings::default()
        },
        ..ContactSettings::default()
    }
}

/// `println!` when the first argument is true.
macro_rules! say {
    ($on:expr, $($t:tt)*) => {
        if $on {
            println!($($t)*)
        }
    };
}

fn shifted(c: &CreepSpectrum, log10_a_t: f64) -> CreepSpectrum {
    let mut s = c.clone();
    for t in &mut s.terms {
        t.tau_s *= 10f64.powf(log10_a_t);
    }
    s
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// Temperatures (°C) at which the true friction is also computed by the independent path
/// ([`friction_at_length`]: the thesis scheme with Richardson's extrapolation and the §3.2 scaling
/// written out in tests/reference.rs), in both scenes: the glassy end, the middle, the rubbery end.
const CHECK_TEMPS_C: [f64; 3] = [-40.0, 10.0, 60.0];

/// One compound's figures, stage by stage (all relative errors as fractions).
#[derive(Debug, Clone, Default)]
struct Figures {
    name: String,
    /// Median and worst |F/N fit / F/N true − 1| over both scenes × [`TEMPS_C`].
    median: f64,
    worst: f64,
    /// Largest |fitted log a_T − true log a_T| over [`TEMPS_C`], decades.
    shift: f64,
    /// Largest |log10 fitted/true| of E′ and of E″ inside the measured reduced window.
    storage: f64,
    loss: f64,
    /// Worst |F/N of the fitted spectrum with the true shifts / F/N true − 1|.
    spectrum: f64,
    /// Worst |F/N true (auto, as the pipeline solves) / F/N independent − 1| at [`CHECK_TEMPS_C`].
    contact: f64,
    /// Worst |N′ independent at the auto contact length / N′ − 1| there.
    contact_load: f64,
    /// Worst |F/N fit / F/N independent − 1| there.
    end_to_end: f64,
    /// Worst |E*·J* − 1| of the fitted relaxation spectrum and its exact creep spectrum over the
    /// scenes' frequencies at every temperature (the interconversion's error).
    interconversion: f64,
    /// Every point: (scene, T °C, error, error of the fitted spectrum with the true shifts, shift
    /// error in decades), errors as fractions.
    points: Vec<Point>,
}

/// One compared point: (scene, T °C, error, error of the fitted spectrum with the true shifts,
/// shift error in decades), errors as fractions.
type Point = (String, f64, f64, f64, f64);

/// Per compound: the [`Figures`] over both shipped scenes at [`TEMPS_C`]; with `verbose` the
/// stage-by-stage table is printed.
fn evaluate(
    compounds: &[RealisticCompound],
    protocol: &DmaProtocol,
    options: &FitOptions,
    verbose: bool,
    independent: bool,
) -> Vec<Figures> {
    // (one folder per call: tests of the same seed and compounds run in parallel)
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let dir = std::env::temp_dir().join(format!(
        "viscoroll-truth-{}-{}-{}-{}",
        std::process::id(),
        CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed),
        protocol.seed,
        compounds.first().map_or("none", |c| c.name.as_str())
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scenes = SceneSet::shipped();
    let settings = contact_settings();
    let mut summary = Vec::new();
    for compound in compounds {
        // Ingest reads the file as `viscoroll run DIR` would (one compound per file).
        let path: PathBuf = dir.join(format!("{}.csv", compound.name));
        std::fs::write(&path, dma_csv(&dma_rows(compound, protocol))).unwrap();
        let fit = fit_files(&compound.name, &[path], options).unwrap();
        let t_ref_fit = fit.shift_law.t_ref_c();
        // The true law re-expressed at the fit's reference temperature (the fitted spectrum is the
        // material at t_ref_fit): log a(T) − log a(t_ref_fit).
        let true_shift = |t: f64| compound.law.log10_a_t(t) - compound.law.log10_a_t(t_ref_fit);
        let (true_creep, _) = relaxation_to_creep(&compound.spectrum).unwrap();
        let fit_creep = fit.creep.clone().unwrap();

        say!(
            verbose,
            "\n== {} ({}): fit T_ref {:.2} °C, {} Prony terms, RMS log10 E′ {:.4}, E″ {:.4}",
            compound.name,
            compound.description,
            t_ref_fit,
            fit.relaxation.terms.len(),
            fit.prony_info.rms_log10_storage,
            fit.prony_info.rms_log10_loss
        );
        // Stage 1: shifts. Fitted law minus the true shift relative to the fitted T_ref.
        let shift_err: Vec<(f64, f64)> = TEMPS_C
            .iter()
            .map(|&t| (t, fit.shift_law.log10_a_t(t) - true_shift(t)))
            .collect();
        say!(
            verbose,
            "shift error (decades) at T: {}",
            shift_err
                .iter()
                .map(|(t, e)| format!("{t}:{e:+.3}"))
                .collect::<Vec<_>>()
                .join(" ")
        );
        // Stage 2: the fitted moduli at t_ref_fit against the truth there, over the measured
        // reduced window and one decade beyond each end.
        let f_lo = fit
            .master_curve
            .iter()
            .map(|p| p.reduced_freq_hz)
            .fold(f64::INFINITY, f64::min);
        let f_hi = fit
            .master_curve
            .iter()
            .map(|p| p.reduced_freq_hz)
            .fold(0.0, f64::max);
        let moduli_err = |a: f64, b: f64| {
            let (mut e1, mut e2) = (0.0f64, 0.0f64);
            let n = 200;
            for k in 0..=n {
                let f = 10f64.powf(a + (b - a) * k as f64 / n as f64);
                let w = 2.0 * std::f64::consts::PI * f;
                let wt = w * 10f64.powf(compound.law.log10_a_t(t_ref_fit));
                e1 = e1.max(
                    (fit.relaxation.storage_modulus(w) / compound.spectrum.storage_modulus(wt))
                        .log10()
                        .abs(),
                );
                e2 = e2.max(
                    (fit.relaxation.loss_modulus(w) / compound.spectrum.loss_modulus(wt))
                        .log10()
                        .abs(),
                );
            }
            (e1, e2)
        };
        let (win1, win2) = moduli_err(f_lo.log10(), f_hi.log10());
        // The interconversion: E*·J* = 1 for an exact pair, over 1e-8…1e8 Hz.
        let omegas: Vec<f64> = (0..=160)
            .map(|k| 2.0 * std::f64::consts::PI * 10f64.powf(-8.0 + 0.1 * k as f64))
            .collect();
        let interconversion = fit.relaxation.max_product_error(&fit_creep, &omegas);
        let mut fig = Figures {
            name: compound.name.clone(),
            shift: shift_err.iter().map(|(_, e)| e.abs()).fold(0.0, f64::max),
            storage: win1,
            loss: win2,
            interconversion,
            ..Figures::default()
        };
        // (scene, true spectrum at T, true F/N and contact length from auto, fitted F/N, T)
        let mut checks = Vec::new();
        let (lo1, lo2) = moduli_err(f_lo.log10() - 1.0, f_lo.log10());
        let (hi1, hi2) = moduli_err(f_hi.log10(), f_hi.log10() + 1.0);
        say!(
            verbose,
            "reduced window {:.1e}…{:.1e} Hz; max |log10 fit/true| E′ {:.4} E″ {:.4} inside, \
             {:.4}/{:.4} one decade below, {:.4}/{:.4} one decade above",
            f_lo,
            f_hi,
            win1,
            win2,
            lo1,
            lo2,
            hi1,
            hi2
        );
        say!(
            verbose,
            "{:<15} {:>6} {:>11} {:>11} {:>8} {:>10} {:>9}",
            "scene",
            "T °C",
            "F/N true",
            "F/N fit",
            "err %",
            "shift dec",
            "spec err %"
        );
        let mut errs = Vec::new();
        for base in &scenes.scene {
            let mut spec = base.clone();
            spec.temps_c = TEMPS_C.to_vec();
            let got = friction_vs_temperature(&fit, &spec, &settings).unwrap();
            let scene = spec.scene();
            for p in &got {
                let true_at_t = shifted(&true_creep, compound.law.log10_a_t(p.temp_c));
                // On the scene's body: a covered scene as the pipeline solves it (auto body choice
                // at COVER_TOL), the others on the half-space.
                let on_body = |sp: &CreepSpectrum| match spec.cover_thickness_mm {
                    Some(h_mm) => {
                        roll_cover(
                            &Scene {
                                body: Body::Auto {
                                    thickness_m: h_mm * 1e-3,
                                },
                                ..scene
                            },
                            sp,
                            settings.auto.tol.max(COVER_TOL),
                        )
                        .unwrap()
                        .roll
                    }
                    None => roll(&scene, sp, &settings).unwrap(),
                };
                let truth_roll = on_body(&true_at_t);
                let truth = truth_roll.friction;
                // The independent path is the half-space's: covered scenes are not checked there.
                if independent
                    && spec.cover_thickness_mm.is_none()
                    && CHECK_TEMPS_C.contains(&p.temp_c)
                {
                    checks.push((
                        scene,
                        true_at_t,
                        truth,
                        truth_roll.contact_length_m,
                        p.friction,
                        p.temp_c,
                        spec.name.clone(),
                    ));
                }
                // The fitted spectrum with the true shifts: the error of the spectrum alone.
                let spec_only = on_body(&shifted(&fit_creep, true_shift(p.temp_c))).friction;
                fig.spectrum = fig.spectrum.max((spec_only / truth - 1.0).abs());
                fig.points.push((
                    spec.name.clone(),
                    p.temp_c,
                    p.friction / truth - 1.0,
                    spec_only / truth - 1.0,
                    p.log10_a_t - true_shift(p.temp_c),
                ));
                // A failed solve (NaN) counts as an infinite error.
                let err = (p.friction / truth - 1.0).abs();
                errs.push(if err.is_finite() { err } else { f64::INFINITY });
                say!(
                    verbose,
                    "{:<15} {:>6} {:>11.4e} {:>11.4e} {:>8.3} {:>+10.3} {:>9.3}",
                    spec.name,
                    p.temp_c,
                    truth,
                    p.friction,
                    100.0 * (p.friction / truth - 1.0),
                    p.log10_a_t - true_shift(p.temp_c),
                    100.0 * (spec_only / truth - 1.0)
                );
            }
        }
        // The independent path, in parallel (each point ≈ 1 s: two thesis solves, n = 640, 1280).
        let checked: Vec<(f64, f64, f64, String)> = checks
            .par_iter()
            .map(|(scene, spectrum, truth, length, fitted, t, name)| {
                let si = SceneSi {
                    radius_m: scene.radius_m,
                    load_n_per_m: scene.load_n_per_m,
                    speed_m_s: scene.speed_m_s,
                };
                let (independent, load_err) =
                    friction_at_length(spectrum, spectrum.poisson, &si, *length);
                (
                    truth / independent - 1.0,
                    load_err,
                    fitted / independent - 1.0,
                    format!(
                        "{name:<15} {t:>6} {independent:>11.4e} {truth:>11.4e} {:>+10.2e} {load_err:>+10.2e} {:>+9.3}",
                        truth / independent - 1.0,
                        100.0 * (fitted / independent - 1.0)
                    ),
                )
            })
            .collect();
        say!(
            verbose,
            "independent truth (thesis scheme, Richardson 640/1280, §3.2 scaling in the test):\n\
             {:<15} {:>6} {:>11} {:>11} {:>10} {:>10} {:>9}",
            "scene",
            "T °C",
            "F/N indep.",
            "F/N auto",
            "auto err",
            "N′ err",
            "fit err %"
        );
        for (c, l, e, line) in &checked {
            say!(verbose, "{line}");
            fig.contact = fig.contact.max(c.abs());
            fig.contact_load = fig.contact_load.max(l.abs());
            fig.end_to_end = fig.end_to_end.max(e.abs());
        }
        fig.worst = errs.iter().copied().fold(0.0, f64::max);
        fig.median = median(&mut errs);
        summary.push(fig);
    }
    let _ = std::fs::remove_dir_all(&dir);
    summary
}

/// The error budget of the worst points (issue 32): each point's error split by stage — the shifts
/// (the fit's error less that of its spectrum with the true shifts), the Prony fit (the fitted
/// spectrum with the true shifts against the truth, both through the same solver), the
/// interconversion (worst |E*J* − 1| of the fitted pair) and the contact solver (auto at tol 1e−4
/// against the independent path, the compound's worst).
fn print_budget(summary: &[Figures], worst: usize) {
    let mut all: Vec<(&Figures, &Point)> = summary
        .iter()
        .flat_map(|f| f.points.iter().map(move |p| (f, p)))
        .collect();
    all.sort_by(|a, b| b.1 .2.abs().total_cmp(&a.1 .2.abs()));
    println!(
        "\nerror budget, {worst} worst points (per cent of F/N; shift in decades)\n\
         compound        scene            T °C   total %  shifts %   Prony %  interconv.  contact   shift dec"
    );
    for (f, (scene, t, err, spec, shift)) in all.into_iter().take(worst) {
        println!(
            "{:<15} {:<15} {:>6} {:>8.3} {:>9.3} {:>9.3} {:>11.1e} {:>8.1e} {:>+10.4}",
            f.name,
            scene,
            t,
            100.0 * err,
            100.0 * (err - spec),
            100.0 * spec,
            f.interconversion,
            f.contact,
            shift
        );
    }
    let mut e: Vec<f64> = summary
        .iter()
        .flat_map(|f| f.points.iter().map(|p| p.2.abs()))
        .collect();
    let worst_all = e.iter().copied().fold(0.0, f64::max);
    println!(
        "all compounds: median {:.3} %, worst {:.3} % over {} points",
        100.0 * median(&mut e),
        100.0 * worst_all,
        e.len()
    );
}

fn print_summary(summary: &[Figures]) {
    println!(
        "\ncompound         median %   worst %  shift dec  E′ log10  E″ log10  spec %  contact  N′ err  end-to-end %"
    );
    for f in summary {
        println!(
            "{:<15} {:>9.3} {:>9.3} {:>10.4} {:>9.4} {:>9.4} {:>7.3} {:>8.1e} {:>7.1e} {:>13.3}",
            f.name,
            100.0 * f.median,
            100.0 * f.worst,
            f.shift,
            f.storage,
            f.loss,
            100.0 * f.spectrum,
            f.contact,
            f.contact_load,
            100.0 * f.end_to_end
        );
    }
}

/// Acceptance bounds (median, worst) on the relative friction error of a compound, for any noise
/// seed: the figures, 2 % and 5 %, for the three compounds whose glass transition lies below
/// the comparison range. The fourth, `high-tg-tread`, is the stress case: glassy at −40 °C in both
/// scenes (its friction there is 44–47× below its value at +60 °C). Its worst case depends on the
/// noise draw: 0.35–6.4 % over the default and 10 other seeds (`known_truth_other_seeds`); with the
/// default seed it is at −40 °C and comes from the fitted E″ above the scene's frequencies, towards
/// the top of the reduced window (the coldest isotherms), not from the shift (0.003 decade there).
/// Its median (≤ 0.35 % over those seeds) is held to 2 % and its worst to 10 %.
fn bounds(compound: &str) -> (f64, f64) {
    if compound == "high-tg-tread" {
        (0.02, 0.10)
    } else {
        (0.02, 0.05)
    }
}

fn failures(summary: &[Figures]) -> Vec<String> {
    summary
        .iter()
        .filter(|f| {
            let (bm, bw) = bounds(&f.name);
            !(f.median <= bm && f.worst <= bw)
        })
        .map(|f| {
            format!(
                "{}: median {:.2} %, worst {:.2} %",
                f.name,
                100.0 * f.median,
                100.0 * f.worst
            )
        })
        .collect()
}

/// Bounds of the default seed, stage by stage, per compound: about 2–3× what each measures (in
/// the comment beside them, as measured on this commit), so that a change in any stage that moves
/// its figure by that much fails here. Order: median, worst (|F/N fit/true − 1|), shift (largest
/// |Δ log a_T|, decades), E′ and E″ (largest |log10 fit/true| in the measured reduced window),
/// spectrum (worst error of the fitted spectrum with the true shifts), contact (auto at tol 1e−4
/// against the independent path: ρF/N, then N′ at auto's contact length), end to end (fit against
/// the independent path at [`CHECK_TEMPS_C`]).
///
/// The contact bounds lie below the solver's tolerance 1e−4: its answers are measured 2–66× better
/// than its estimate (docs/DEVLOG.md), here 3.6e−6…7.7e−6 in F/N and 4.9e−6…2.5e−5 in N′, part of which is
/// the reference's own error (≈ 3e−6, tests/auto_vs_richardson.rs). A lumping-correction gain 20 %
/// off or a 0.1 % error in the coupling of the auto scheme's modes moves them past the bounds
/// (issue 19). A solver change that moves them within its tolerance needs the bound re-measured.
fn tight_bounds(compound: &str) -> [f64; 9] {
    match compound {
        // 0.69 %, 1.29 %, 0.029, 0.012, 0.065, 1.48 %, 7.7e-6, 2.5e-5, 1.29 %
        "nr-br-idler" => [0.016, 0.03, 0.07, 0.03, 0.15, 0.035, 2e-5, 6e-5, 0.03],
        // 0.34 %, 0.81 %, 0.033, 0.0095, 0.033, 0.93 %, 5.3e-6, 1.8e-5, 0.81 %
        "nr-tread" => [0.008, 0.02, 0.08, 0.025, 0.08, 0.022, 1.5e-5, 4.5e-5, 0.02],
        // 0.20 %, 0.71 %, 0.018, 0.0039, 0.012, 0.75 %, 3.6e-6, 4.9e-6, 0.71 %
        "sbr-tread" => [0.005, 0.018, 0.045, 0.01, 0.03, 0.019, 1e-5, 1.5e-5, 0.018],
        // 0.20 %, 4.70 %, 0.012, 0.0032, 0.081, 4.54 %, 5.2e-6, 8.3e-6, 4.70 % (worst: the
        // stress case's glassy end, bound 2.1× as the acceptance bound 10 %)
        "high-tg-tread" => [0.005, 0.10, 0.03, 0.008, 0.2, 0.1, 1.5e-5, 2e-5, 0.1],
        _ => [0.0; 9],
    }
}

fn tight_failures(summary: &[Figures]) -> Vec<String> {
    let mut bad = Vec::new();
    for f in summary {
        let b = tight_bounds(&f.name);
        let got = [
            f.median,
            f.worst,
            f.shift,
            f.storage,
            f.loss,
            f.spectrum,
            f.contact,
            f.contact_load,
            f.end_to_end,
        ];
        let names = [
            "median",
            "worst",
            "shift",
            "E′",
            "E″",
            "spectrum",
            "contact",
            "contact N′",
            "end to end",
        ];
        for ((name, got), bound) in names.iter().zip(got).zip(b) {
            // NaN (a failed solve) fails too.
            if got > bound || got.is_nan() {
                bad.push(format!("{}: {name} {got:.3e} > {bound:.1e}", f.name));
            }
        }
    }
    bad
}

#[test]
fn friction_from_synthetic_exports_matches_the_true_spectrum() {
    let summary = evaluate(
        &realistic_compounds(),
        &DmaProtocol::default(),
        &FitOptions::default(),
        true,
        true,
    );
    print_summary(&summary);
    print_budget(&summary, 10);
    // At least three compounds held to the figures.
    assert_eq!(summary.len(), 4);
    // The interconversion is exact (docs/MATH.md §4): E*J* = 1 to rounding.
    for f in &summary {
        assert!(
            f.interconversion < 1e-9,
            "{}: {:.1e}",
            f.name,
            f.interconversion
        );
    }
    assert!(
        summary
            .iter()
            .filter(|f| bounds(&f.name) == (0.02, 0.05))
            .count()
            >= 3
    );
    let bad = failures(&summary);
    assert!(bad.is_empty(), "{bad:?}");
    let bad = tight_failures(&summary);
    assert!(bad.is_empty(), "{bad:#?}");
}

/// The same with 10 other noise and drift seeds, against the acceptance figures only and
/// without the independent contact check (about 25 s in release):
/// `cargo test --release --test tests known_truth_other_seeds -- --ignored --nocapture`.
#[test]
#[ignore = "seed sweep, ~25 s in release; run on demand"]
fn known_truth_other_seeds() {
    let mut bad = Vec::new();
    for seed in 1..=10 {
        let summary = evaluate(
            &realistic_compounds(),
            &DmaProtocol {
                seed,
                ..DmaProtocol::default()
            },
            &FitOptions::default(),
            false,
            false,
        );
        println!("\nseed {seed}");
        print_summary(&summary);
        bad.extend(
            failures(&summary)
                .into_iter()
                .map(|f| format!("seed {seed}: {f}")),
        );
    }
    assert!(bad.is_empty(), "{bad:?}");
}

/// A fifth shape (issue 32): the narrow glass transition of `non_overlapping_compounds` (T_g = −40 °C,
/// steep WLF 17.4/51.6 K), whose coldest isotherms in the default protocol lie 3–4 decades apart:
/// −59 and −55 °C are left out (§6.6), −50 °C is not determined by overlap. End to end over the
/// three shipped scenes at −40 … +60 °C, with the error budget of its worst points:
/// `cargo test --test tests known_truth_narrow -- --nocapture`. Measured: median 0.69 %, worst
/// 3.55 % (−40 °C, conveyor-idler: shifts −5.1 %, Prony +1.5 %); before the shift table's cubic
/// (docs/MATH.md eq. 6.3) and the weights of undetermined isotherms' points (eq. 5.1) the worst was
/// 47.7 % there (Prony −41 %: the −50 °C isotherm, 0.33 decade off, bent the fitted E″ by 0.3
/// decade). Bounds: median 1 %, worst 5 % (the stress case's; the 2 % is not met here).
#[test]
fn known_truth_narrow_transition() {
    let compounds = vec![viscoroll::testdata::non_overlapping_compounds()[0].clone()];
    let summary = evaluate(
        &compounds,
        &DmaProtocol::default(),
        &FitOptions::default(),
        true,
        false,
    );
    print_summary(&summary);
    print_budget(&summary, 10);
    let f = &summary[0];
    assert!(f.interconversion < 1e-9, "{:.1e}", f.interconversion);
    assert!(
        f.median <= 0.01 && f.worst <= 0.05,
        "median {:.2} %, worst {:.2} %",
        100.0 * f.median,
        100.0 * f.worst
    );
}

/// What the estimator owns (issue 32, item 4): the same four compounds from exports without noise
/// (drift kept: the per-point temperature correction, docs/MATH.md §12, is part of the chain), so
/// every error left is bias: the shifts' interpolation, the Prony fit's regularisation and term
/// positions, the contact tolerance. Measured (`cargo test --test tests known_truth_noise_free --
/// --nocapture`, default seed): median 0.051 %, worst 0.60 % over 132 points, shifts within 0.0011
/// decade (seeds 1–10: worst ≤ 0.60 %, shifts ≤ 0.0019 decade). With the default 1 % / 3 % noise the
/// worst is 2.6–2.8 %, with half that noise 1.5 %: the rest is the data's scatter carried through the fit
/// (its sign changes with the seed; docs/DEVLOG.md, "The last 2 %"). Bounds: about twice the
/// measured figures (median 0.1 %, worst 1.2 %, shifts 0.0025 decade).
#[test]
fn known_truth_noise_free_bias() {
    let summary = evaluate(
        &realistic_compounds(),
        &DmaProtocol {
            noise_storage_rel: 0.0,
            noise_loss_rel: 0.0,
            ..DmaProtocol::default()
        },
        &FitOptions::default(),
        false,
        false,
    );
    print_summary(&summary);
    let mut all: Vec<f64> = summary
        .iter()
        .flat_map(|f| f.points.iter().map(|p| p.2.abs()))
        .collect();
    let worst = all.iter().copied().fold(0.0, f64::max);
    let median_all = median(&mut all);
    println!(
        "all: median {:.3} %, worst {:.3} %",
        100.0 * median_all,
        100.0 * worst
    );
    assert!(median_all <= 0.001, "median {:.3} %", 100.0 * median_all);
    assert!(worst <= 0.012, "worst {:.3} %", 100.0 * worst);
    for f in &summary {
        assert!(
            f.shift <= 0.0025,
            "{}: shifts {:.4} decade",
            f.name,
            f.shift
        );
    }
}

/// An export of an exact model whose loss factor falls far below what a DMA resolves (the
/// noise-free narrow transition with a filled tail: E″/E′ down to ~1e-57) cannot be fitted: every λ
/// of the search ends InsufficientProgress (docs/DEVLOG.md, "The last 2 %"). The error must say why
/// and what to do, not only that the solver failed.
#[test]
fn a_loss_factor_no_dma_resolves_is_named_when_the_fit_fails() {
    let compound = viscoroll::testdata::non_overlapping_compounds()[1].clone();
    let protocol = DmaProtocol {
        noise_storage_rel: 0.0,
        noise_loss_rel: 0.0,
        ..DmaProtocol::default()
    };
    let dir = std::env::temp_dir().join(format!("viscoroll-tiny-loss-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("{}.csv", compound.name));
    std::fs::write(&path, dma_csv(&dma_rows(&compound, &protocol))).unwrap();
    let result = fit_files(&compound.name, &[path], &FitOptions::default());
    let _ = std::fs::remove_dir_all(&dir);
    let Err(err) = result else {
        panic!("the fit is expected to fail here")
    };
    let err = err.to_string();
    assert!(err.contains("far below the ~1e-4 a DMA resolves"), "{err}");
    assert!(err.contains("E″/E′ reaches"), "{err}");
}
