//! Prony fit on a real master curve: pyvisco's EMS-CA master curve at T_ref = −5 °C
//! (data/pyvisco-ems-ca/freq_user_master.csv, BSD-3-Clause, see its LICENSE/NOTICE), 206 points
//! over 26 decades of reduced frequency (1e-12 … 1e14 Hz).
//!
//! Published comparison (data/SOURCES.md): pyvisco's NNLS fit of its own master curve, 19 terms,
//! RMS log10 error ≈ 0.04 on E′ and ≈ 0.15 on E″.

use viscoroll::prony::{fit_prony, log10_errors, MasterPoint, PronySettings};
use viscoroll::ModulusKind;

/// Read `f [Hz], E_stor [MPa], E_loss [MPa]` (a name row, then a unit row) into points in Pa.
pub fn ems_ca_master() -> Vec<MasterPoint> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/data/pyvisco-ems-ca/freq_user_master.csv"
    );
    let mut rdr = csv::ReaderBuilder::new()
        .has_headers(true)
        .trim(csv::Trim::All)
        .from_path(path)
        .expect("open EMS-CA master curve");
    let mut out = Vec::new();
    for (i, rec) in rdr.records().enumerate() {
        let rec = rec.expect("csv record");
        if i == 0 {
            // Unit row: the conversion below relies on it.
            assert_eq!((&rec[0], &rec[1], &rec[2]), ("Hz", "MPa", "MPa"));
            continue;
        }
        let v: Vec<f64> = rec.iter().map(|s| s.parse().expect("number")).collect();
        out.push(MasterPoint {
            reduced_freq_hz: v[0],
            storage_pa: v[1] * 1e6,
            loss_pa: v[2] * 1e6,
        });
    }
    out
}

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
    let e = log10_errors(&pts, &fit.spectrum);
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
