//! `export` and `convert` from fit files (issue 17): the LS-DYNA card can always be written (at most
//! 18 cards, refit stated), the WLF law of a fit file goes into a card only when it holds, and
//! `convert` reads a fit file's spectrum.

use crate::support::{temp_dir, viscoroll};
use viscoroll::report::CardContents;

const LSDYNA_MAX_TERMS: usize = CardContents::LSDYNA_MAX_TERMS;
use viscoroll::testdata::{broad_spectrum, synthetic_measurement, SyntheticSettings};
use viscoroll::ShiftLaw;

#[test]
fn cards_and_creep_from_a_fit_file() {
    let dir = temp_dir("fit-exports");
    // Shifts from an exact WLF law: the fit file's WLF fit must reproduce it and go into the card.
    let law = ShiftLaw::Wlf {
        t_ref_c: 20.0,
        c1: 10.0,
        c2_k: 150.0,
    };
    let temps: Vec<f64> = (0..7).map(|i| -20.0 + 10.0 * i as f64).collect();
    let m = synthetic_measurement(&broad_spectrum(), &SyntheticSettings::new(temps, law));
    let mpath = dir.join("m.json");
    std::fs::write(&mpath, serde_json::to_string(&m).unwrap()).unwrap();
    let fit = dir.join("demo.json");
    let (m_s, f_s) = (mpath.to_str().unwrap(), fit.to_str().unwrap());
    let o = viscoroll(&["fit", m_s, "-o", f_s, "--tref", "20", "--max-terms", "30"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));

    let o = viscoroll(&["export", f_s, "--to", "lsdyna"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let card = String::from_utf8(o.stdout).unwrap();
    let c = CardContents::from_lsdyna(&card).unwrap();
    // Prony cards = terms + the β = 0 equilibrium card.
    assert!(c.terms.len() < LSDYNA_MAX_TERMS, "{card}");
    // The WLF law of the exact shifts comes back (the master-curve stage fits it to shifts that are
    // exact up to its own shift error; 1 % on C1 and C2 is far outside that and far inside a
    // degenerate law's 100×).
    let Some(ShiftLaw::Wlf { c1, c2_k, .. }) = c.shift else {
        panic!("no WLF in {card}")
    };
    assert!(
        (c1 / 10.0 - 1.0).abs() < 0.01 && (c2_k / 150.0 - 1.0).abs() < 0.01,
        "{c1} {c2_k}"
    );
    assert!(
        card.contains("WLF shift fitted to the master curve's shifts: RMS"),
        "{card}"
    );

    for to in ["abaqus", "ansys"] {
        let o = viscoroll(&["export", f_s, "--to", to]);
        assert!(
            o.status.success(),
            "{to}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
    }
    let o = viscoroll(&["convert", f_s, "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v["checks"]["max_abs_product_error"].as_f64().unwrap() < 1e-9);

    // A bare spectrum of 33 terms: refitted to its own moduli, at most 18 cards, RMS stated.
    let spectrum = dir.join("s.json");
    std::fs::write(&spectrum, serde_json::to_string(&broad_spectrum()).unwrap()).unwrap();
    assert!(broad_spectrum().terms.len() > LSDYNA_MAX_TERMS);
    let o = viscoroll(&["export", spectrum.to_str().unwrap(), "--to", "lsdyna"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let card = String::from_utf8(o.stdout).unwrap();
    let c = CardContents::from_lsdyna(&card).unwrap();
    assert!(c.terms.len() < LSDYNA_MAX_TERMS, "{card}");
    assert!(card.contains("Prony terms for LS-DYNA"), "{card}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_wlf_that_holds_over_part_of_the_shifts_goes_into_the_card_with_its_range() {
    let dir = temp_dir("fit-exports-range");
    // Shifts: exact WLF (C1 = 8.86, C2 = 101.6 K at 20 °C) from −10 to 60 °C, and below −10 °C a
    // glassy straight line of 0.05 decade/K. WLF over all of them misses (or degenerates); over
    // −10…60 °C it is exact.
    let wlf = ShiftLaw::Wlf {
        t_ref_c: 20.0,
        c1: 8.86,
        c2_k: 101.6,
    };
    let temps: Vec<f64> = (0..12).map(|i| -50.0 + 10.0 * i as f64).collect();
    let points: Vec<(f64, f64)> = temps
        .iter()
        .map(|&t| {
            let a = if t >= -10.0 {
                wlf.log10_a_t(t)
            } else {
                wlf.log10_a_t(-10.0) + 0.05 * (-10.0 - t)
            };
            (t, a)
        })
        .collect();
    let law = ShiftLaw::Table {
        t_ref_c: 20.0,
        points,
    };
    let m = synthetic_measurement(&broad_spectrum(), &SyntheticSettings::new(temps, law));
    let mpath = dir.join("m.json");
    std::fs::write(&mpath, serde_json::to_string(&m).unwrap()).unwrap();
    let fit = dir.join("kinked.json");
    let (m_s, f_s) = (mpath.to_str().unwrap(), fit.to_str().unwrap());
    let o = viscoroll(&["fit", m_s, "-o", f_s, "--tref", "20"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = viscoroll(&["export", f_s, "--to", "abaqus"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let card = String::from_utf8(o.stdout).unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr);
    // The warning is in the card and on stderr, with the range; the law is near the true one.
    let note = card
        .lines()
        .find(|l| l.contains("fitted over"))
        .unwrap_or_else(|| panic!("{card}"));
    assert!(note.contains("only, where it holds") && stderr.contains("fitted over"));
    assert!(note.contains("to 60.00 degC"), "{note}");
    let c = CardContents::from_abaqus(&card).unwrap();
    let Some(ShiftLaw::Wlf { t_ref_c, c1, c2_k }) = c.shift else {
        panic!("no WLF in {card}")
    };
    // Shifts found by the master-curve stage from exact data: within a few 0.01 decade of the
    // law, so C1 and C2 come back within ~10 % (a degenerate law is off by 100×).
    assert!((t_ref_c - 20.0).abs() < 1e-9);
    assert!(
        (c1 / 8.86 - 1.0).abs() < 0.15 && (c2_k / 101.6 - 1.0).abs() < 0.15,
        "{c1} {c2_k}"
    );
}

#[test]
fn roll_refuses_a_fluid_and_a_relaxation_spectrum_with_the_reason() {
    let dir = temp_dir("fit-exports-fluid");
    let melt = serde_json::json!({
        "kind": "shear", "poisson": 0.5, "modulus_inf_pa": 0.0,
        "terms": [{"modulus_pa": 1e5, "tau_s": 0.1}, {"modulus_pa": 1e4, "tau_s": 10.0}]
    });
    let solid = serde_json::json!({
        "kind": "shear", "poisson": 0.5, "modulus_inf_pa": 1e5,
        "terms": [{"modulus_pa": 1e5, "tau_s": 0.1}]
    });
    // A fit file whose relaxation has no equilibrium modulus (the reader is not reached).
    let fit = serde_json::json!({"format_version": 1, "relaxation": melt.clone()});
    let args = |p: &std::path::Path| {
        vec![
            "roll".to_string(),
            p.display().to_string(),
            "--radius-mm".into(),
            "100".into(),
            "--load-n-per-m".into(),
            "2000".into(),
            "--speed-m-s".into(),
            "1".into(),
        ]
    };
    for (name, v, want) in [
        ("melt.json", &melt, "no steady state"),
        ("fit.json", &fit, "no steady state"),
        ("solid.json", &solid, "convert it first"),
    ] {
        let p = dir.join(name);
        std::fs::write(&p, v.to_string()).unwrap();
        let a = args(&p);
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        let o = viscoroll(&a);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{name}: {err}");
        assert!(err.contains(want), "{name}: {err}");
        assert_eq!(err.lines().count(), 1, "{name}: one line: {err}");
    }
    // η₀ = Σ Gᵢτᵢ = 1e5·0.1 + 1e4·10 = 1.1e5 Pa·s, stated in the refusal.
    let p = dir.join("melt.json");
    let a = args(&p);
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    let err = String::from_utf8(viscoroll(&a).stderr).unwrap();
    assert!(err.contains("1.100e5 Pa·s"), "{err}");
}
