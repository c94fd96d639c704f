//! The uncertainty bands through the CLI (issue 16, item 1): `run` writes them in friction.csv,
//! ranking.csv and the JSON summary (pairs and ties), `roll` on a fit file gives the same band as the
//! report's row, `--no-bands` skips them without moving any other number, and a fit made without
//! them gets its ensemble added when a later run asks for bands.

use crate::support::{bin, col, data_dir, run_main, table, temp_dir};
use std::path::Path;
use std::process::Command;

/// Two compounds of data/ (the two fast ones), one export file each at the top of `dir`.
fn two_compounds(dir: &Path) {
    let data = data_dir();
    std::fs::copy(
        data.join("pyvisco-ems-ca/freq_Eplexor_raw.xls"),
        dir.join("ems.xls"),
    )
    .unwrap();
    std::fs::copy(
        data.join("trios-aresg2-lims/frequency_sweep_tts.txt"),
        dir.join("trios.txt"),
    )
    .unwrap();
}

/// `viscoroll roll FIT --json` in the conveyor-idler scene (66.5 mm, 10 kN/m, 4 m/s) at `temp_c`.
fn roll_idler(fit: &Path, temp_c: &str, extra: &[&str]) -> std::process::Output {
    Command::new(bin())
        .arg("roll")
        .arg(fit)
        .args(["--temp-c", temp_c, "--json"])
        .args([
            "--radius-mm",
            "66.5",
            "--load-n-per-m",
            "10000",
            "--speed-m-s",
            "4",
        ])
        .args(extra)
        .output()
        .unwrap()
}

#[test]
fn run_and_roll_give_bands_and_no_bands_moves_nothing_else() {
    let dir = temp_dir("bands-in");
    two_compounds(&dir);
    let out = temp_dir("bands-out");
    let o = run_main(&dir, &out, &["--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let summary: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();

    // friction.csv: p05 < p50 < p95 at every row, the friction itself inside its band (its own
    // replicates scatter around it: a friction outside its 90 % band would mean a broken ratio).
    let (h, rows) = table(&out.join("reports/ems/friction.csv"));
    let (f, p05, p50, p95) = (
        col(&h, "friction"),
        col(&h, "friction_p05"),
        col(&h, "friction_p50"),
        col(&h, "friction_p95"),
    );
    assert_eq!(
        (p50, p95),
        (p05 + 1, p05 + 2),
        "the band columns sit together"
    );
    for r in &rows {
        let v = |i: usize| r[i].parse::<f64>().unwrap();
        assert!(v(p05) < v(p50) && v(p50) < v(p95), "{r:?}");
        assert!(v(p05) < v(f) && v(f) < v(p95), "{r:?}");
    }

    // The summary's pairs: one per scene for two ranked compounds, tied exactly when P(A < B) lies
    // strictly between 0.05 and 0.95; ranking.csv's tied_with says the same.
    let pairs = summary["comparisons"].as_array().unwrap();
    let n_scenes = summary["compounds"][0]["standings"]
        .as_array()
        .unwrap()
        .len();
    assert_eq!(pairs.len(), n_scenes);
    let (rh, rrows) = table(&out.join("reports/ranking.csv"));
    for p in pairs {
        let prob = p["prob_a_lower"].as_f64().unwrap();
        assert!((0.0..=1.0).contains(&prob));
        assert_eq!(p["tied"].as_bool().unwrap(), prob > 0.05 && prob < 0.95);
        let a_row = rrows
            .iter()
            .find(|r| {
                r[col(&rh, "scene")] == p["scene"].as_str().unwrap()
                    && r[col(&rh, "compound")] == p["a"].as_str().unwrap()
            })
            .unwrap();
        assert_eq!(
            a_row[col(&rh, "tied_with")] == p["b"].as_str().unwrap(),
            p["tied"].as_bool().unwrap()
        );
        // The ranking's order is the lower mean first: P(A < B) ≥ 0.5 up to the band's skew.
        assert!(prob > 0.3, "{p}");
    }
    for r in &rrows {
        let v = |n: &str| r[col(&rh, n)].parse::<f64>().unwrap();
        assert!(
            v("mean_friction_p05") < v("mean_friction")
                && v("mean_friction") < v("mean_friction_p95"),
            "{r:?}"
        );
    }

    // roll on the fit file: the same band as the report's row (same ensemble, same ratios).
    let half_space = rows
        .iter()
        .find(|r| r[0] == "conveyor-idler-half-space")
        .unwrap();
    let o = roll_idler(&out.join("fits/ems.json"), &half_space[1], &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(
        v["friction"].as_f64().unwrap(),
        half_space[f].parse::<f64>().unwrap()
    );
    for (key, i) in [
        ("friction_p05", p05),
        ("friction_p50", p50),
        ("friction_p95", p95),
    ] {
        assert_eq!(
            v[key].as_f64().unwrap(),
            half_space[i].parse::<f64>().unwrap(),
            "{key}"
        );
    }
    // roll --cover-mm 5 (the conveyor-idler's cover): the band solved on the covered body as the
    // report's covered row (eq. 15.6b, the same ratios), so the same band relative to the friction
    // (roll's friction is solved at its own tolerance 1e-6, the report's at 1e-3; the ratios are
    // the same numbers, so the relative band agrees to round-off: 1e-12), and not the half-space's.
    let covered = rows
        .iter()
        .find(|r| r[0] == "conveyor-idler" && r[1] == half_space[1])
        .unwrap();
    let o = roll_idler(
        &out.join("fits/ems.json"),
        &covered[1],
        &["--cover-mm", "5"],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let rel = |row: &Vec<String>, i: usize| {
        row[i].parse::<f64>().unwrap() / row[f].parse::<f64>().unwrap()
    };
    for (key, i) in [
        ("friction_p05", p05),
        ("friction_p50", p50),
        ("friction_p95", p95),
    ] {
        let got = v[key].as_f64().unwrap() / v["friction"].as_f64().unwrap();
        assert!((got / rel(covered, i) - 1.0).abs() < 1e-12, "{key}: {v}");
        // p50 is the friction itself on either body (eq. 15.5); the ends are the cover's own
        assert!(
            key == "friction_p50" || (got / rel(half_space, i) - 1.0).abs() > 1e-6,
            "{key}: the half-space's band"
        );
    }
    // --model winkler: no band, with the reason.
    let o = roll_idler(
        &out.join("fits/ems.json"),
        "20",
        &["--cover-mm", "5", "--model", "winkler"],
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v["friction_p05"].is_null() && v["bands_note"].as_str().unwrap().contains("winkler"));

    // roll --no-bands, and a bare spectrum: no band, with the reason.
    let o = roll_idler(&out.join("fits/ems.json"), "20", &["--no-bands"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(
        v["friction_p05"].is_null() && v["bands_note"].as_str().unwrap().contains("--no-bands")
    );

    // --no-bands: the band columns empty, no pairs, every other cell as with bands.
    let out2 = temp_dir("bands-nobands");
    let o = run_main(&dir, &out2, &["--json", "--no-bands"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s2: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(s2["comparisons"].as_array().unwrap().is_empty());
    let (h2, rows2) = table(&out2.join("reports/ems/friction.csv"));
    assert_eq!(h, h2);
    // the note differs only by the bands' own notes (widened by eq. 15.8 or 15.9: EMS-CA at
    // −40 °C lies beyond its measured frequencies, and its band, wider than a factor 10, leaves it
    // not determined)
    let note = col(&h, "note");
    let without_band_notes = |n: &str| {
        n.split("; ")
            .filter(|w| {
                !w.starts_with("band widened")
                    && !w.starts_with("uncertainty band")
                    // a band wider than a factor 10 makes its point not determined (issue 31)
                    && !w.starts_with("not determined: its band spans")
                    && !w.starts_with("fit warning")
            })
            .collect::<Vec<_>>()
            .join("; ")
    };
    for (a, b) in rows.iter().zip(&rows2) {
        for i in (0..p05).filter(|&i| i != note) {
            assert_eq!(a[i], b[i], "{}", h[i]);
        }
        // the fit-warnings pointer counts one more warning with bands (the single-specimen note)
        assert_eq!(without_band_notes(&a[note]), without_band_notes(&b[note]));
        assert!(b[p05..].iter().all(String::is_empty));
    }
    assert!(rows
        .iter()
        .any(|r| r[note].contains("band widened for extrapolation in frequency")));
    let fit2 = std::fs::read_to_string(out2.join("fits/ems.json")).unwrap();
    assert!(!fit2.contains("\"bands\""));

    // A later run with bands on that output reuses the fit and adds its ensemble: the same bands.
    let o = run_main(&dir, &out2, &["--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stderr).contains("ems: reused fit"));
    let (_, rows3) = table(&out2.join("reports/ems/friction.csv"));
    assert_eq!(rows, rows3);
    let fit3 = std::fs::read_to_string(out2.join("fits/ems.json")).unwrap();
    assert!(fit3.contains("\"bands\""));
    for d in [dir, out, out2] {
        let _ = std::fs::remove_dir_all(d);
    }
}

/// The first `k` replicates of the fit file's ensemble made unsolvable: a negative retardation
/// compliance, which the contact stage refuses (its spectrum check) at every temperature.
fn break_replicates(fit: &Path, k: usize) {
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(fit).unwrap()).unwrap();
    let reps = v["bands"]["replicates"].as_array_mut().unwrap();
    assert_eq!(reps.len(), 32);
    for r in reps.iter_mut().take(k) {
        for t in r["creep"]["terms"].as_array_mut().unwrap() {
            let c = t["compliance_per_pa"].as_f64().unwrap();
            t["compliance_per_pa"] = serde_json::json!(-c.abs());
        }
    }
    std::fs::write(fit, super::support::sealed_fit_json(v)).unwrap();
}

#[test]
fn failed_band_replicates_are_counted_and_too_many_refuse_the_band() {
    // One compound, one half-space scene at two temperatures (fast); the fit file's ensemble is
    // broken between runs (the fit is reused: same inputs, same band settings).
    let dir = temp_dir("bands-fail-in");
    std::fs::copy(
        data_dir().join("trios-aresg2-lims/frequency_sweep_tts.txt"),
        dir.join("trios.txt"),
    )
    .unwrap();
    let scenes = dir.join("one.toml");
    std::fs::write(
        &scenes,
        "[[scene]]\nname = \"idler\"\nroll_radius_mm = 66.5\nload_n_per_m = 10000.0\n\
         speed_m_s = 4.0\ntemps_c = [0.0, 20.0]\n",
    )
    .unwrap();
    let out = temp_dir("bands-fail-out");
    let run = || {
        let o = run_main(&dir, &out, &["--scenes", scenes.to_str().unwrap()]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    };
    run();
    let fit = out.join("fits/trios.json");
    let friction = out.join("reports/trios/friction.csv");
    let datasheet = out.join("reports/trios/datasheet.html");
    let ranking = out.join("reports/ranking.csv");
    let texts = || {
        let (h, rows) = table(&friction);
        let (rh, rrows) = table(&ranking);
        (
            rows.iter()
                .map(|r| {
                    (
                        r[col(&h, "note")].clone(),
                        r[col(&h, "friction_p05")].clone(),
                    )
                })
                .collect::<Vec<_>>(),
            std::fs::read_to_string(&datasheet).unwrap(),
            rrows[0][col(&rh, "warnings")].clone(),
            rrows[0][col(&rh, "mean_friction_p05")].clone(),
        )
    };
    let (rows, sheet, warnings, _) = texts();
    assert!(rows
        .iter()
        .all(|(n, p05)| !n.contains("uncertainty band") && !p05.is_empty()));
    assert!(!sheet.contains("uncertainty band") && !warnings.contains("uncertainty band"));

    // 5 of 32 fail (≤ a quarter): every band is kept and says how many of how many and why; and
    // the ensemble's own note on failed refits (as crate::bands::build_ensemble writes it, here
    // put in the reused fit file) reaches friction.csv's warnings, the datasheet and the ranking
    break_replicates(&fit, 5);
    let refits = "3 of 32 bootstrap refits failed and were left out (first: injected)";
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&fit).unwrap()).unwrap();
    v["bands"]["notes"] = serde_json::json!([refits]);
    std::fs::write(&fit, super::support::sealed_fit_json(v)).unwrap();
    run();
    // a fit warning of friction.csv: in its sidecar, pointed at from every row's note
    let (fit_warnings, notes) = super::support::fit_warnings_and_notes(&friction);
    assert!(
        fit_warnings.iter().any(|w| w.contains(refits)),
        "{fit_warnings:?}"
    );
    assert!(notes.iter().all(|n| n.contains("(see friction.meta.json)")));
    let (rows, sheet, warnings, mean_p05) = texts();
    let said = "uncertainty band from 27 of 32 bootstrap replicates: 5 failed";
    for (note, p05) in &rows {
        assert!(note.contains(said), "{note}");
        assert!(
            note.contains("compliance"),
            "the first failure's reason: {note}"
        );
        assert!(!p05.is_empty());
    }
    assert!(sheet.contains(said), "datasheet");
    assert!(warnings.contains(said), "ranking.csv: {warnings}");
    assert!(!mean_p05.is_empty(), "the mean's band is kept");
    assert!(sheet.contains(refits) && warnings.contains(refits));
    // and `roll --json` on the fit file gives the same note beside its band (`bands_notes`)
    let o = roll_idler(&fit, "20", &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v["friction_p05"].is_f64(), "{v}");
    let notes = v["bands_notes"].as_array().unwrap();
    assert!(
        notes.iter().any(|n| n.as_str().unwrap().contains(said)),
        "{v}"
    );

    // 9 of 32 (more than a quarter): refused, with the count and the reason, in all three places
    break_replicates(&fit, 9);
    run();
    let (rows, sheet, warnings, mean_p05) = texts();
    let said = "uncertainty band refused: 9 of 32 bootstrap replicates failed";
    for (note, p05) in &rows {
        assert!(note.contains(said), "{note}");
        assert!(p05.is_empty(), "no band: {p05}");
    }
    assert!(sheet.contains(said), "datasheet");
    assert!(warnings.contains(said), "ranking.csv: {warnings}");
    assert!(mean_p05.is_empty(), "nor a band of the mean");
    let o = roll_idler(&fit, "20", &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v["friction_p05"].is_null(), "{v}");
    assert!(v["bands_note"].as_str().unwrap().contains(said), "{v}");
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&out);
}

/// `viscoroll fit` writes the bootstrap ensemble by default and `--no-bands` skips it; `roll
/// --json` on either fit file has `friction_p05` and `friction_p95` (on the one without an ensemble
/// from the fit file alone, which its notes say), and on a bare creep spectrum null with the reason
/// in `bands_note` (issue 32, item 2).
#[test]
fn fit_writes_bands_by_default_and_roll_gives_a_band_from_any_fit_file() {
    use viscoroll::testdata::{broad_spectrum, synthetic_measurement, SyntheticSettings};
    let dir = temp_dir("fit-bands");
    let law = viscoroll::ShiftLaw::Wlf {
        t_ref_c: 20.0,
        c1: 10.0,
        c2_k: 150.0,
    };
    let temps: Vec<f64> = (0..7).map(|i| -20.0 + 10.0 * i as f64).collect();
    let settings = SyntheticSettings {
        noise_rel: 0.01,
        ..SyntheticSettings::new(temps, law)
    };
    let m = synthetic_measurement(&broad_spectrum(), &settings);
    let mpath = dir.join("m.json");
    std::fs::write(&mpath, serde_json::to_string(&m).unwrap()).unwrap();
    let fit_json = |name: &str, extra: &[&str]| {
        let path = dir.join(name);
        let o = Command::new(bin())
            .args(["fit", mpath.to_str().unwrap(), "-o", path.to_str().unwrap()])
            .args(["--tref", "20", "--json"])
            .args(extra)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        (path, v)
    };
    let (with, v) = fit_json("with.json", &[]);
    assert_eq!(v["bands_replicates"].as_u64(), Some(32), "{v}");
    assert!(v["bands_note"].is_null(), "{v}");
    let saved: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&with).unwrap()).unwrap();
    assert_eq!(saved["bands"]["replicates"].as_array().unwrap().len(), 32);
    let (without, v) = fit_json("without.json", &["--no-bands"]);
    assert!(v["bands_replicates"].is_null(), "{v}");
    assert!(
        v["bands_note"].as_str().unwrap().contains("--no-bands"),
        "{v}"
    );
    assert!(!std::fs::read_to_string(&without)
        .unwrap()
        .contains("\"bands\""));

    let band_of = |fit: &Path| {
        let o = roll_idler(fit, "10", &[]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        let (f, p05, p95) = (
            v["friction"].as_f64().unwrap(),
            v["friction_p05"].as_f64().unwrap_or(f64::NAN),
            v["friction_p95"].as_f64().unwrap_or(f64::NAN),
        );
        assert!(p05 < f && f < p95, "{v}");
        v
    };
    let v = band_of(&with);
    assert!(v["bands_note"].is_null(), "{v}");
    let v = band_of(&without);
    let notes = v["bands_notes"].as_array().unwrap();
    assert!(
        notes
            .iter()
            .any(|n| n.as_str().unwrap().contains("fit file alone")),
        "{v}"
    );

    // a bare creep spectrum: no band, and why
    let fit: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&with).unwrap()).unwrap();
    let creep = dir.join("creep.json");
    std::fs::write(&creep, serde_json::to_string(&fit["creep"]).unwrap()).unwrap();
    let o = Command::new(bin())
        .arg("roll")
        .arg(&creep)
        .args(["--json", "--radius-mm", "66.5", "--load-n-per-m", "10000"])
        .args(["--speed-m-s", "4"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(
        v["friction_p05"].is_null() && v["friction_p95"].is_null(),
        "{v}"
    );
    assert!(
        v["bands_note"]
            .as_str()
            .unwrap()
            .contains("bare creep spectrum"),
        "{v}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
