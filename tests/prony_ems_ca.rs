//! Prony fit on a real master curve: pyvisco's EMS-CA master curve at T_ref = −5 °C
//! (data/pyvisco-ems-ca/freq_user_master.csv, BSD-3-Clause, see its LICENSE/NOTICE), 206 points
//! over 26 decades of reduced frequency (1e-12 … 1e14 Hz).
//!
//! Published comparison (data/SOURCES.md): pyvisco's NNLS fit of its own master curve, 19 terms,
//! RMS log10 error ≈ 0.04 on E′ and ≈ 0.15 on E″.

use viscoroll::prony::{fit_prony, MasterPoint, PronySettings};
use viscoroll::ModulusKind;

pub use crate::shipped::ems_ca_master;

/// Default settings (2 per decade, GCV, equal weights): the solve ends `Solved`, E″ is fitted within
/// pyvisco's published 0.15, and the reported errors are those of the returned spectrum.
///
/// E′ is not within pyvisco's 0.04 at equal weights: this master curve is not Kramers–Kronig
/// consistent (a flat E″ ≈ 11 MPa, tan δ ≈ 0.12, over ten decades where E′ rises only from 89 to
/// 200 MPa), so no positive spectrum fits both; the bound 0.10 states what equal weights reach.
#[test]
fn ems_ca_default_fit() {
    let pts = ems_ca_master();
    assert_eq!(pts.len(), 206);
    let fit = fit_prony(&pts, ModulusKind::Tensile, 0.5, &PronySettings::default()).unwrap();
    let i = &fit.info;
    assert_eq!(i.solver_status, "Solved");
    assert!(i.rms_log10_loss <= 0.15, "{i:?}");
    assert!(i.rms_log10_storage <= 0.10, "{i:?}");
    // Independent recomputation of the reported figures from the spectrum alone.
    let e = fit.spectrum.log10_errors(&pts);
    assert_eq!(
        (e.rms_storage, e.rms_loss),
        (i.rms_log10_storage, i.rms_log10_loss)
    );
    // 26 decades + 2 × 0.5 margin at 2 per decade → 55 grid times.
    assert_eq!(i.n_terms_grid, 55);
    assert!(i.n_terms_kept <= i.n_terms_grid && i.n_terms_kept == fit.spectrum.terms.len());
}

/// Fewer terms than pyvisco's 19: 0.6 per decade gives 18. With E″ down-weighted to 0.3 (E″'s
/// relative scatter is the larger one on this curve) E′ meets pyvisco's 0.04; E″ then exceeds its
/// 0.15 (the Kramers–Kronig trade-off above): the test pins both sides of that trade.
#[test]
fn ems_ca_fewer_terms_than_pyvisco() {
    let pts = ems_ca_master();
    let s = PronySettings {
        terms_per_decade: 0.6,
        loss_weight: 0.3,
        ..PronySettings::default()
    };
    let fit = fit_prony(&pts, ModulusKind::Tensile, 0.5, &s).unwrap();
    let i = &fit.info;
    assert!(i.n_terms_kept < 19, "{i:?}");
    assert!(i.rms_log10_storage <= 0.04, "{i:?}");
    assert!(i.rms_log10_loss > 0.15 && i.rms_log10_loss < 0.30, "{i:?}");
    // Equal weights with the same 18 terms: E″ within pyvisco's 0.15, E′ not within 0.04.
    let eq = PronySettings {
        loss_weight: 1.0,
        ..s
    };
    let fit = fit_prony(&pts, ModulusKind::Tensile, 0.5, &eq).unwrap();
    let i = &fit.info;
    assert!(
        i.n_terms_kept < 19 && i.rms_log10_loss <= 0.15 && i.rms_log10_storage > 0.04,
        "{i:?}"
    );
}

/// Print the figures for the report (run with `--ignored --nocapture`).
#[test]
#[ignore]
fn ems_ca_report_figures() {
    let pts = ems_ca_master();
    for (d, w) in [(2.0, 1.0), (1.0, 1.0), (0.6, 1.0), (0.6, 0.3), (2.0, 0.3)] {
        let s = PronySettings {
            terms_per_decade: d,
            loss_weight: w,
            ..PronySettings::default()
        };
        let f = fit_prony(&pts, ModulusKind::Tensile, 0.5, &s).unwrap();
        let i = &f.info;
        eprintln!(
            "per_decade={d} loss_weight={w}: rms_log10 E'={:.4} E''={:.4} max E'={:.3} E''={:.3} terms {}/{} λ={:e} {} iters {}",
            i.rms_log10_storage, i.rms_log10_loss, i.max_abs_log10_storage, i.max_abs_log10_loss,
            i.n_terms_kept, i.n_terms_grid, i.lambda, i.solver_status, i.total_iterations
        );
    }
}

/// A master curve in pyvisco's layout (`f, E_stor, E_loss` over `Hz, MPa, MPa`) under data/.
fn pyvisco_master(file: &str) -> Vec<MasterPoint> {
    let path = format!("{}/data/pyvisco-ems-ca/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let mut header = || lines.next().unwrap().replace(' ', "");
    assert_eq!(header(), "f,E_stor,E_loss");
    assert_eq!(header(), "Hz,MPa,MPa");
    lines
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.trim().parse().unwrap()).collect();
            MasterPoint::new(v[0], v[1] * 1e6, v[2] * 1e6)
        })
        .collect()
}

/// pyvisco's shipped fit (its Prony-term CSV, tools/gen_pyvisco_reference.py) and its RMS log10 of
/// E′ and E″ on `pts`, computed here from the terms alone: [`log10_errors`] of the spectrum our
/// reader makes of them (Eᵢ = αᵢE₀, E∞ = E₀(1 − Σαᵢ)). (The same numbers as numpy's evaluation of
/// pyvisco's own E_freq_norm when the files were made: 0.0493/0.4187, 0.0099/0.3844, 0.0047/0.1881.)
fn pyvisco_fit(file: &str, pts: &[MasterPoint]) -> (usize, f64, f64) {
    let path = format!("{}/data/pyvisco-ems-ca/{file}", env!("CARGO_MANIFEST_DIR"));
    let s =
        viscoroll::RelaxationSpectrum::from_pyvisco_csv(file, &std::fs::read(path).unwrap(), 0.5)
            .unwrap();
    let e = s.log10_errors(pts);
    (s.terms.len(), e.rms_storage, e.rms_loss)
}

/// Our fit at pyvisco's term count (the reduction to at most `n` terms) with E″ weighted by `w`.
fn ours(pts: &[MasterPoint], n: usize, w: f64) -> (usize, f64, f64) {
    let s = PronySettings {
        loss_weight: w,
        max_terms: Some(n),
        reduce_terms: true,
        ..PronySettings::default()
    };
    let f = fit_prony(pts, ModulusKind::Tensile, 0.5, &s).unwrap();
    let i = &f.info;
    assert_eq!(i.solver_status, "Solved");
    (i.n_terms_kept, i.rms_log10_storage, i.rms_log10_loss)
}

/// Issue 29 item 6: one setting beats pyvisco on both E′ and E″ at pyvisco's term count.
///
/// On the shipped master curve (freq_user_master.csv, 206 points) pyvisco 2.1.3 fits 26 terms:
/// 0.0493/0.4187 by default, 0.0099/0.3844 with its optimiser (α and τ free). `--loss-weight 0.12
/// --max-terms 26` gives 0.0091/0.3540: better on both than either. On the master curve pyvisco builds
/// itself from the raw data (210 points; its optimised 32-term fit 0.0047/0.1881, the issue's
/// "E″ 0.181" is of this order), `--loss-weight 0.08 --max-terms 32` gives 0.0040/0.1554. The
/// margins (≥ 8 % on each figure) are far above anything the solver's tolerance (1e-8) can move.
/// The stated pair for pyvisco, E′ 0.014 with E″ 0.181, is not reached on the shipped curve
/// by anything: there pyvisco's own optimiser and every weight of ours lie on one frontier
/// (E″ ≈ 0.35 at E′ ≈ 0.01, E″ ≈ 0.28 at E′ ≈ 0.018; the trade table), so that pair was measured on
/// another curve; on pyvisco's own raw-data master curve `--loss-weight 0.3 --max-terms 32` beats it
/// (0.0122/0.118).
#[test]
fn one_loss_weight_beats_pyvisco_on_both_moduli_at_its_term_count() {
    let pts = pyvisco_master("freq_user_master.csv");
    assert_eq!(pts.len(), 206);
    let (n, _, _) = pyvisco_fit("pyvisco_prony_terms_freq_user_master.csv", &pts);
    assert_eq!(n, 26);
    let (k, e1, e2) = ours(&pts, n, 0.12);
    assert!(k <= n);
    for file in [
        "pyvisco_prony_terms_freq_user_master.csv",
        "pyvisco_prony_terms_freq_user_master_opt.csv",
    ] {
        let (_, p1, p2) = pyvisco_fit(file, &pts);
        assert!(
            e1 < p1 && e2 < p2,
            "{file}: ours {e1}/{e2}, pyvisco {p1}/{p2}"
        );
    }
    // Default weights are today's behaviour: E″ far better than pyvisco, E′ worse.
    let (_, d1, d2) = ours(&pts, n, 1.0);
    let (_, p1, p2) = pyvisco_fit("pyvisco_prony_terms_freq_user_master_opt.csv", &pts);
    assert!(
        d2 < p2 / 4.0 && d1 > p1,
        "ours {d1}/{d2}, pyvisco {p1}/{p2}"
    );

    let raw = pyvisco_master("pyvisco_master_freq_user_raw.csv");
    assert_eq!(raw.len(), 210);
    let (n, p1, p2) = pyvisco_fit("pyvisco_prony_terms_freq_user_raw_opt.csv", &raw);
    assert_eq!(n, 32);
    let (k, e1, e2) = ours(&raw, n, 0.08);
    assert!(
        k <= n && e1 < p1 && e2 < p2,
        "ours {e1}/{e2}, pyvisco {p1}/{p2}"
    );
}

/// `fit --loss-weight W --max-terms N` is the library's setting: the fit file records the weight and
/// the same figures as [`fit_prony`] with it (the flag reaches the QP, nothing else moves).
#[test]
fn fit_flag_loss_weight_reaches_the_fit() {
    let dir = crate::support::temp_dir("loss-weight-flag");
    let data = |f: &str| format!("{}/data/pyvisco-ems-ca/{f}", env!("CARGO_MANIFEST_DIR"));
    let out = dir.join("ems.json");
    let o = crate::support::viscoroll(&[
        "fit",
        "--master-curve",
        &data("freq_user_master.csv"),
        "--shift-factors",
        &data("freq_user_master__shift_factors.csv"),
        "--max-terms",
        "26",
        "--loss-weight",
        "0.12",
        "--no-bands", // the fit's own figures are asserted, not its ensemble
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", crate::support::stderr(&o));
    let fit = viscoroll::results::CompoundFit::read(&out).unwrap();
    let (_, e1, e2) = ours(&pyvisco_master("freq_user_master.csv"), 26, 0.12);
    let i = &fit.prony_info;
    assert!((i.rms_log10_storage - e1).abs() < 1e-9 && (i.rms_log10_loss - e2).abs() < 1e-9);
    assert_eq!(fit.settings.prony.loss_weight, 0.12);
    let bad = dir.join("bad.json");
    let o = crate::support::viscoroll(&[
        "fit",
        "--master-curve",
        &data("freq_user_master.csv"),
        "--shift-factors",
        &data("freq_user_master__shift_factors.csv"),
        "--loss-weight",
        "0",
        "-o",
        bad.to_str().unwrap(),
    ]);
    let e = crate::support::stderr(&o);
    assert!(
        !o.status.success() && e.contains("loss-weight") && !bad.exists(),
        "{e}"
    );
}

/// The E′/E″ trade table of the user guide (run with `--ignored --nocapture`): RMS log10 of E′ and
/// E″ against `loss_weight`, at pyvisco's term count and for the dense grid fit, on the shipped master
/// curve and on pyvisco's own master curve from the raw data, beside pyvisco's fits.
#[test]
#[ignore]
fn ems_ca_trade_table() {
    for (master, terms) in [
        (
            "freq_user_master.csv",
            [
                "pyvisco_prony_terms_freq_user_master.csv",
                "pyvisco_prony_terms_freq_user_master_opt.csv",
            ],
        ),
        (
            "pyvisco_master_freq_user_raw.csv",
            ["pyvisco_prony_terms_freq_user_raw_opt.csv", ""],
        ),
    ] {
        let pts = pyvisco_master(master);
        let mut n = 0;
        for t in terms.iter().filter(|t| !t.is_empty()) {
            let (k, p1, p2) = pyvisco_fit(t, &pts);
            n = k;
            eprintln!("{master}: pyvisco {t}: {k} terms, E' {p1:.4}, E'' {p2:.4}");
        }
        eprintln!("| loss_weight | E′ ({n} terms) | E″ ({n} terms) | E′ (dense) | E″ (dense) |");
        for w in [1.0, 0.5, 0.3, 0.2, 0.15, 0.12, 0.1, 0.08, 0.05] {
            let (_, e1, e2) = ours(&pts, n, w);
            let s = PronySettings {
                loss_weight: w,
                ..PronySettings::default()
            };
            let f = fit_prony(&pts, ModulusKind::Tensile, 0.5, &s).unwrap();
            eprintln!(
                "| {w} | {e1:.4} | {e2:.4} | {:.4} | {:.4} |",
                f.info.rms_log10_storage, f.info.rms_log10_loss
            );
        }
    }
}
