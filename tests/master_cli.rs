//! `viscoroll master` end to end on a synthetic measurement (known WLF law).

use crate::support::{temp_dir, viscoroll};
use std::path::PathBuf;
use viscoroll::testdata::{broad_spectrum, synthetic_measurement, SyntheticSettings};
use viscoroll::ShiftLaw;

fn truth() -> ShiftLaw {
    ShiftLaw::Wlf {
        t_ref_c: 20.0,
        c1: 10.0,
        c2_k: 150.0,
    }
}

fn write_measurement(dir: &std::path::Path) -> PathBuf {
    let temps: Vec<f64> = (0..7).map(|i| -20.0 + 10.0 * i as f64).collect();
    let m = synthetic_measurement(&broad_spectrum(), &SyntheticSettings::new(temps, truth()));
    let p = dir.join("m.json");
    std::fs::write(&p, serde_json::to_string(&m).unwrap()).unwrap();
    p
}

#[test]
fn json_output_is_one_object_with_the_shifts() {
    let dir = temp_dir("master-cli-json");
    let m = write_measurement(&dir);
    let out = viscoroll(&["master", m.to_str().unwrap(), "--tref", "20", "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["t_ref_c"], 20.0);
    let isos = v["isotherms"].as_array().unwrap();
    assert_eq!(isos.len(), 7);
    // 10 frequencies over 3 decades: spline error leaves the shifts within 1e-3 of the truth.
    for iso in isos {
        let t = iso["temp_c"].as_f64().unwrap();
        let s = iso["log10_a_t"].as_f64().unwrap();
        assert!((s - truth().log10_a_t(t)).abs() < 1e-3, "{t}: {s}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn given_wlf_and_output_file_and_no_overwrite() {
    let dir = temp_dir("master-cli-given");
    let m = write_measurement(&dir);
    let o = dir.join("mc.json");
    let args = [
        "master",
        m.to_str().unwrap(),
        "--tref",
        "20",
        "--shift",
        "wlf:10,150",
        "-o",
        o.to_str().unwrap(),
    ];
    let out = viscoroll(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stdout.is_empty());
    let v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&o).unwrap()).unwrap();
    assert_eq!(v["shift_law"]["law"], "wlf");
    assert_eq!(v["shift_law"]["c1"], 10.0);
    // Second run refuses to overwrite.
    let again = viscoroll(&args);
    assert_eq!(again.status.code(), Some(1));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_arguments_fail_with_one_line() {
    let dir = temp_dir("master-cli-bad");
    let m = write_measurement(&dir);
    for shift in ["wlf:10", "wlf:a,b", "nonsense"] {
        let out = viscoroll(&[
            "master",
            m.to_str().unwrap(),
            "--tref",
            "20",
            "--shift",
            shift,
        ]);
        assert_eq!(out.status.code(), Some(1), "{shift}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim().lines().count(), 1, "{err}");
    }
    // wlf constants without a reference temperature.
    let out = viscoroll(&["master", m.to_str().unwrap(), "--shift", "wlf:10,150"]);
    assert_eq!(out.status.code(), Some(1));
    let out = viscoroll(&["master", dir.join("missing.json").to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let _ = std::fs::remove_dir_all(&dir);
}
