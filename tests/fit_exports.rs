//! `export` and `convert` from fit files (issue 17): the LS-DYNA card can always be written (at most
//! 18 cards, refit stated), the WLF law of a fit file goes into a card only when it holds, and
//! `convert` reads a fit file's spectrum.

use std::path::PathBuf;
use std::process::Command;
use viscoroll::report::cards::{read_lsdyna, LSDYNA_MAX_TERMS};
use viscoroll::testdata::{broad_spectrum, synthetic_measurement, SyntheticSettings};
use viscoroll::ShiftLaw;

fn scratch() -> PathBuf {
    let d = std::env::temp_dir().join(format!("viscoroll-fit-exports-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn viscoroll(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_viscoroll"))
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn cards_and_creep_from_a_fit_file() {
    let dir = scratch();
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
    let c = read_lsdyna(&card).unwrap();
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
    let c = read_lsdyna(&card).unwrap();
    assert!(c.terms.len() < LSDYNA_MAX_TERMS, "{card}");
    assert!(card.contains("Prony terms for LS-DYNA"), "{card}");
    let _ = std::fs::remove_dir_all(&dir);
}
