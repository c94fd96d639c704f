//! `viscoroll fit` end to end on a synthetic measurement from a known spectrum and WLF law: the fit
//! file reproduces the true moduli, is reused on a re-run, and is not replaced without `--force`.

use crate::support::{temp_dir, viscoroll};
use viscoroll::results::CompoundFit;
use viscoroll::testdata::{broad_spectrum, synthetic_measurement, SyntheticSettings};
use viscoroll::ShiftLaw;

#[test]
fn fit_writes_reuses_and_refuses() {
    let dir = temp_dir("fit-cli");
    let law = ShiftLaw::Wlf {
        t_ref_c: 20.0,
        c1: 10.0,
        c2_k: 150.0,
    };
    let temps: Vec<f64> = (0..7).map(|i| -20.0 + 10.0 * i as f64).collect();
    let truth = broad_spectrum();
    let m = synthetic_measurement(&truth, &SyntheticSettings::new(temps, law));
    let mpath = dir.join("m.json");
    std::fs::write(&mpath, serde_json::to_string(&m).unwrap()).unwrap();
    let out = dir.join("fits/demo.json");
    let (m_s, o_s) = (mpath.to_str().unwrap(), out.to_str().unwrap());

    let o = viscoroll(&["fit", m_s, "-o", o_s, "--tref", "20", "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["action"], "fitted");
    assert_eq!(v["compound"], "demo");

    // The fit reproduces the noise-free truth at T_ref over the measured window (reduced
    // frequencies 0.1 Hz · a_T … 100 Hz · a_T ⊂ 1e-3 … 1e5 Hz for this law): within 2 % (issue 7's
    // bound for 1 % noise; here there is no noise, so it only fails if the chain is broken).
    let fit = CompoundFit::read(&out).unwrap();
    assert!(fit.creep.is_some());
    for k in 0..=16 {
        let f_hz = 10f64.powf(-2.0 + 0.25 * k as f64);
        let w = 2.0 * std::f64::consts::PI * f_hz;
        let (e1, e2) = (
            fit.relaxation.storage_modulus(w),
            fit.relaxation.loss_modulus(w),
        );
        let (t1, t2) = (truth.storage_modulus(w), truth.loss_modulus(w));
        assert!(
            (e1 / t1 - 1.0).abs() < 0.02,
            "E′ at {f_hz} Hz: {e1} vs {t1}"
        );
        assert!(
            (e2 / t2 - 1.0).abs() < 0.02,
            "E″ at {f_hz} Hz: {e2} vs {t2}"
        );
    }

    // Same inputs and settings: reused. Other settings: refused and left alone; --force replaces.
    let o = viscoroll(&["fit", m_s, "-o", o_s, "--tref", "20", "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["action"], "reused");
    let before = std::fs::read(&out).unwrap();
    let o = viscoroll(&["fit", m_s, "-o", o_s, "--tref", "30"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--force"));
    assert_eq!(std::fs::read(&out).unwrap(), before);
    let o = viscoroll(&["fit", m_s, "-o", o_s, "--tref", "30", "--force", "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["action"], "replaced");

    // A missing measurement: one line, exit 1.
    let o = viscoroll(&["fit", "no/such.json", "-o", o_s]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(String::from_utf8_lossy(&o.stderr).trim().lines().count(), 1);
}
