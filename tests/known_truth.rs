//! End to end against a known truth (issue 8, "what it must show"): DMA exports generated from known
//! relaxation spectra and WLF laws (viscoroll::testdata::realistic: four rubbers, 27–34 Prony
//! terms over 20 decades, E₀/E∞ 150–900, isotherms −60 … +100 °C every 5 K at 13 frequencies
//! 0.1–100 Hz, 1 % noise on E′ and 3 % on E″, measured temperatures within ±1.5 K of the step),
//! written to CSV files and run through the whole pipeline as
//! `viscoroll run` runs it (ingest → master curve → Prony fit → exact creep spectrum → friction, via
//! `pipeline::fit_files` and `pipeline::scenes::friction_vs_temperature`) at the shipped scenes
//! (data/scenes.toml) at −40 … +60 °C every 10 K. The reference is computed independently of every
//! fitted quantity: the true spectrum converted exactly to creep (crate::creep::exact, MATH.md §4),
//! shifted by the true WLF law, through the same contact solver at the same tolerance.
//!
//! Acceptance (the figures): per compound, median relative friction error ≤ 2 %, worst ≤ 5 %
//! over both scenes × 11 temperatures, for three compounds; the fourth is a stress case with a
//! looser worst-case bound (see [`bounds`]). The table and a stage-by-stage breakdown print with
//! `cargo test --test tests known_truth -- --nocapture`.

use std::path::PathBuf;
use viscoroll::contact::controlled::AutoSettings;
use viscoroll::contact::layer::{roll_cover, ModelChoice};
use viscoroll::contact::roll_auto::roll_auto;
use viscoroll::creep::relaxation_to_creep;
use viscoroll::pipeline::scenes::{friction_vs_temperature, SceneSet, COVER_TOL};
use viscoroll::pipeline::{fit_files, FitOptions};
use viscoroll::testdata::realistic::{
    dma_csv, dma_rows, realistic_compounds, DmaProtocol, RealisticCompound,
};
use viscoroll::testdata::{loss_modulus, storage_modulus};
use viscoroll::CreepSpectrum;

/// Temperatures of the comparison, °C (the issue's −40 … +60 °C, every 10 K).
const TEMPS_C: [f64; 11] = [
    -40.0, -30.0, -20.0, -10.0, 0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0,
];

/// Contact tolerance of both sides: the auto scheme's error control bounds the relative error of
/// F/N by `tol`; 1e-4 is 200× below the 2 % target (and 500× below 5 %), so the solver contributes
/// at most 0.01 % + 0.01 % to a difference, while costing a fraction of the default 1e-6.
fn contact_settings() -> AutoSettings {
    AutoSettings {
        tol: 1e-4,
        gap_check: false,
        ..AutoSettings::default()
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

/// Per compound: (name, median, worst relative friction error) over both shipped scenes at
/// [`TEMPS_C`]; with `verbose` the stage-by-stage table is printed.
fn evaluate(
    compounds: &[RealisticCompound],
    protocol: &DmaProtocol,
    options: &FitOptions,
    verbose: bool,
) -> Vec<(String, f64, f64)> {
    let dir = std::env::temp_dir().join(format!(
        "viscoroll-truth-{}-{}",
        std::process::id(),
        protocol.seed
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
                    (fit.relaxation.storage_modulus(w) / storage_modulus(&compound.spectrum, wt))
                        .log10()
                        .abs(),
                );
                e2 = e2.max(
                    (fit.relaxation.loss_modulus(w) / loss_modulus(&compound.spectrum, wt))
                        .log10()
                        .abs(),
                );
            }
            (e1, e2)
        };
        let (win1, win2) = moduli_err(f_lo.log10(), f_hi.log10());
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
                // On the scene's body: a covered scene as the pipeline solves it (auto body choice
                // at COVER_TOL), the others on the half-space.
                let friction_on = |sp: &viscoroll::CreepSpectrum| match spec.cover_thickness_mm {
                    Some(h_mm) => {
                        roll_cover(
                            &scene,
                            sp,
                            Some(h_mm * 1e-3),
                            ModelChoice::Auto,
                            settings.tol.max(COVER_TOL),
                        )
                        .unwrap()
                        .roll
                        .friction
                    }
                    None => roll_auto(&scene, sp, &settings).unwrap().roll.friction,
                };
                let truth = friction_on(&shifted(&true_creep, compound.law.log10_a_t(p.temp_c)));
                // The fitted spectrum with the true shifts: the error of the spectrum alone.
                let spec_only = friction_on(&shifted(&fit_creep, true_shift(p.temp_c)));
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
        let worst = errs.iter().copied().fold(0.0, f64::max);
        let med = median(&mut errs);
        summary.push((compound.name.clone(), med, worst));
    }
    let _ = std::fs::remove_dir_all(&dir);
    summary
}

fn print_summary(summary: &[(String, f64, f64)]) {
    println!("\ncompound         median %   worst %");
    for (n, m, w) in summary {
        println!("{n:<15} {:>9.3} {:>9.3}", 100.0 * m, 100.0 * w);
    }
}

/// Bounds (median, worst) on the relative friction error of a compound: the acceptance
/// figures, 2 % and 5 %, for the three compounds whose glass transition lies below the comparison
/// range. The fourth, `high-tg-tread`, is the stress case: glassy at −40 °C in both scenes (its
/// friction there is 44–47× below its value at +60 °C). Its worst case depends on the noise draw:
/// 0.35–6.4 % over the default and 10 other seeds (`known_truth_other_seeds`); with the default
/// seed it is at −40 °C and comes from the fitted E″ above the scene's frequencies, towards the top
/// of the reduced window (the coldest isotherms), not from the shift (0.003 decade there). Its
/// median (≤ 0.35 % over those seeds) is held to 2 % and its worst to 10 %.
fn bounds(compound: &str) -> (f64, f64) {
    if compound == "high-tg-tread" {
        (0.02, 0.10)
    } else {
        (0.02, 0.05)
    }
}

fn failures(summary: &[(String, f64, f64)]) -> Vec<String> {
    summary
        .iter()
        .filter(|(n, m, w)| {
            let (bm, bw) = bounds(n);
            !(*m <= bm && *w <= bw)
        })
        .map(|(n, m, w)| format!("{n}: median {:.2} %, worst {:.2} %", 100.0 * m, 100.0 * w))
        .collect()
}

#[test]
fn friction_from_synthetic_exports_matches_the_true_spectrum() {
    let summary = evaluate(
        &realistic_compounds(),
        &DmaProtocol::default(),
        &FitOptions::default(),
        true,
    );
    print_summary(&summary);
    // At least three compounds held to the figures.
    assert_eq!(summary.len(), 4);
    assert!(
        summary
            .iter()
            .filter(|(n, _, _)| bounds(n) == (0.02, 0.05))
            .count()
            >= 3
    );
    let bad = failures(&summary);
    assert!(bad.is_empty(), "{bad:?}");
}

/// The same with 10 other noise and drift seeds (about 25 s in release):
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
