//! `viscoroll convert` and `viscoroll export` end to end: exit codes, one JSON object on stdout,
//! refusals with a one-line error.

use crate::support::temp_dir;
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_viscoroll"))
}

const SPECTRUM: &str = r#"{ "kind": "tensile", "poisson": 0.5, "modulus_inf_pa": 1e6,
  "terms": [ { "modulus_pa": 9e6, "tau_s": 1e-3 }, { "modulus_pa": 9e8, "tau_s": 1e-7 } ] }"#;

#[test]
fn convert_prints_one_json_object_with_its_checks() {
    let d = temp_dir("spectra-convert");
    let f = d.join("relax.json");
    std::fs::write(&f, SPECTRUM).unwrap();
    let out = bin()
        .args(["convert"])
        .arg(&f)
        .arg("--json")
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["method"], "exact");
    assert_eq!(v["creep_spectrum"]["terms"].as_array().unwrap().len(), 2);
    // Exact conversion: the product identity to rounding (1e-13: see tests/spectra_exact.rs).
    assert!(v["checks"]["max_abs_product_error"].as_f64().unwrap() < 1e-13);
    // -o writes the creep spectrum, which reads back as a CreepSpectrum; no overwrite without --force.
    let o = d.join("creep.json");
    let out = bin()
        .arg("convert")
        .arg(&f)
        .arg("-o")
        .arg(&o)
        .args([
            "--method",
            "park-schapery",
            "--park-schapery-variant",
            "least-squares",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let c: viscoroll::CreepSpectrum =
        serde_json::from_str(&std::fs::read_to_string(&o).unwrap()).unwrap();
    assert_eq!(c.terms.len(), 2);
    let out = bin()
        .arg("convert")
        .arg(&f)
        .arg("-o")
        .arg(&o)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--force"));
}

/// A fluid converts exactly with its flow term (tests/fluid_rolling.rs); Park & Schapery's method has
/// no flow term and refuses it in one line.
#[test]
fn park_schapery_refuses_a_fluid_in_one_line() {
    let d = temp_dir("spectra-fluid");
    let f = d.join("fluid.json");
    std::fs::write(
        &f,
        r#"{ "modulus_inf_pa": 0, "terms": [ { "modulus_pa": 1e6, "tau_s": 1 } ] }"#,
    )
    .unwrap();
    let out = bin()
        .args(["convert", "--method", "park-schapery", "--json"])
        .arg(&f)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    // With --json a failure is one JSON object on stdout (issue 15), the message also on stderr.
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON object");
    assert!(v["error"].is_string() && v["kind"].is_string(), "{v}");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("fluid"), "{err}");
}

#[test]
fn export_writes_each_card() {
    let d = temp_dir("spectra-export");
    let f = d.join("relax.json");
    std::fs::write(&f, SPECTRUM).unwrap();
    for (to, marker) in [
        ("abaqus", "*VISCOELASTIC, TIME=PRONY"),
        ("ansys", "TB,PRONY,1,1,2,SHEAR"),
        ("lsdyna", "*MAT_GENERAL_VISCOELASTIC"),
    ] {
        let out = bin()
            .arg("export")
            .arg(&f)
            .args(["--to", to, "--wlf", "25,13.5,141.19"])
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(String::from_utf8_lossy(&out.stdout).contains(marker));
    }
    let out = bin()
        .arg("export")
        .arg(&f)
        .args(["--to", "ansys", "--json"])
        .output()
        .unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["format"], "ansys");
    let out = bin()
        .arg("export")
        .arg(&f)
        .args(["--to", "abaqus", "--wlf", "25,13.5"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--wlf"));
}
