//! Prony term control (`crate::prony::terms`) on real master curves: pyvisco's EMS-CA master curve
//! (data/pyvisco-ems-ca/freq_user_master.csv, 206 points over 26 decades).

use super::shipped::ems_ca_master;
use viscoroll::prony::{fit_prony, log10_errors, PronySettings};
use viscoroll::ModulusKind;

/// The reduction (opt-in: `reduce_terms`) takes the dense grid fit to fewer terms that are no less accurate in either
/// modulus (the reported errors are recomputed from the returned spectrum, independently).
#[test]
fn reduction_is_fewer_terms_at_no_worse_accuracy() {
    let pts = ems_ca_master();
    let settings = PronySettings {
        reduce_terms: true,
        ..PronySettings::default()
    };
    let fit = fit_prony(&pts, ModulusKind::Tensile, 0.5, &settings).unwrap();
    let i = &fit.info;
    let dense = i.dense_rms_log10.unwrap();
    let e = log10_errors(&pts, &fit.spectrum);
    assert_eq!(e.rms_storage, i.rms_log10_storage);
    assert!(i.term_target_met == Some(true), "{:?}", i.term_trade);
    assert!(i.n_terms_kept < i.dense_terms.unwrap(), "{i:?}");
    assert!(
        e.rms_storage <= dense[0] && e.rms_loss <= dense[1],
        "{e:?} vs {dense:?}"
    );
    // The trade table runs from the most terms down and the choice is one of its rows.
    assert!(i.term_trade.windows(2).all(|w| w[0].n_terms > w[1].n_terms));
    assert!(i.term_trade.iter().any(|t| t.n_terms == i.n_terms_kept));
    // Every term is admissible: positive strength, time inside the grid window.
    for t in &fit.spectrum.terms {
        assert!(t.modulus_pa > 0.0);
        assert!(
            t.tau_s >= i.tau_window_s[0] * (1.0 - 1e-12)
                && t.tau_s <= i.tau_window_s[1] * (1.0 + 1e-12)
        );
    }
}

/// A cap is a cap: `max_terms` = 18 (LS-DYNA's limit) gives at most 18 terms, and positions free
/// in log τ beat the fixed grid at the same count: the dense grid at 0.6 per decade (18 times) is
/// the comparison, on the measure the fit minimises (relative residuals of E′ and E″ together,
/// i.e. RMS log10 near a good fit).
#[test]
fn max_terms_caps_the_count_and_free_positions_beat_the_grid() {
    let pts = ems_ca_master();
    let capped = PronySettings {
        max_terms: Some(18),
        ..PronySettings::default()
    };
    let fit = fit_prony(&pts, ModulusKind::Tensile, 0.5, &capped).unwrap();
    assert!(fit.spectrum.terms.len() <= 18, "{:?}", fit.info.term_trade);
    let grid = PronySettings {
        terms_per_decade: 0.6,
        reduce_terms: false,
        ..PronySettings::default()
    };
    let g = fit_prony(&pts, ModulusKind::Tensile, 0.5, &grid).unwrap();
    assert!(g.spectrum.terms.len() <= 18);
    let ss = |e: viscoroll::prony::fit::Log10Errors| e.rms_storage.powi(2) + e.rms_loss.powi(2);
    let free = ss(log10_errors(&pts, &fit.spectrum));
    let fixed = ss(log10_errors(&pts, &g.spectrum));
    assert!(free < fixed, "free {free:e} vs grid {fixed:e}");
}

/// The Pareto table for the report (run with `--ignored --nocapture`).
#[test]
#[ignore]
fn ems_ca_term_trade_table() {
    let pts = ems_ca_master();
    for (w, log) in [(1.0, false), (1.0, true), (0.2, true)] {
        let s = PronySettings {
            loss_weight: w,
            log_residuals: log,
            target_rms_log10: Some([1e-6, 1e-6]),
            ..PronySettings::default()
        };
        let fit = fit_prony(&pts, ModulusKind::Tensile, 0.5, &s).unwrap();
        eprintln!("loss_weight {w}, log residuals {log}");
        for t in fit.info.term_trade.iter().filter(|t| t.n_terms <= 30) {
            eprintln!(
                "{:3} {:.4} {:.4}",
                t.n_terms, t.rms_log10_storage, t.rms_log10_loss
            );
        }
    }
}
