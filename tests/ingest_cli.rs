//! `viscoroll ingest` end to end: exit codes, one JSON object on stdout, human text on stderr,
//! atomic output that is not overwritten without --force.

use std::path::PathBuf;
use std::process::{Command, Output};
use viscoroll::dma::{self, IngestOptions, Measurement};

fn viscoroll(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_viscoroll"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap()
}

fn scratch(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("ingest_cli")
        .join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn json_report_of_the_eplexor_export() {
    let out = viscoroll(&[
        "ingest",
        "data/pyvisco-ems-ca/freq_Eplexor_raw.xls",
        "--json",
    ]);
    assert_eq!(out.status.code(), Some(0));
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert_eq!(stdout.lines().count(), 1, "one JSON object on one line");
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(v["command"], "ingest");
    assert_eq!(v["kind"], "tensile");
    let f = &v["files"][0];
    assert_eq!(f["format"], "eplexor");
    assert_eq!(f["isotherms"], 21);
    assert_eq!(f["points"], 210);
    assert_eq!(f["mode"], "tensile");
    assert_eq!(f["metadata"]["Measurement type"], "Temp. Freq. Sweep");
    assert_eq!(f["freq_range_hz"], serde_json::json!([0.1, 100.0]));
    // sha256sum data/pyvisco-ems-ca/freq_Eplexor_raw.xls
    assert_eq!(
        f["sha256"],
        "60ce5205c820699ef1f7ecdb03d31cb0f58ff105495a728ed2292ffe259b995c"
    );
    assert_eq!(v["summary"]["isotherms"], 21);
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(stderr.contains("isotherms: 21"), "{stderr}");
    assert!(stderr.contains("eplexor (Excel)"), "{stderr}");
}

#[test]
fn output_is_written_atomically_and_not_overwritten_without_force() {
    let dir = scratch("output");
    let out_path = dir.join("M.json");
    let o = out_path.to_str().unwrap();
    let input = "data/trios-aresg2-lims/frequency_sweep_tts.txt";
    let first = viscoroll(&["ingest", input, "-o", o]);
    assert_eq!(
        first.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&first.stderr)
    );
    assert!(first.stdout.is_empty(), "no --json: nothing on stdout");
    let m: Measurement = serde_json::from_slice(&std::fs::read(&out_path).unwrap()).unwrap();
    let lib = dma::read_files(&[input], &IngestOptions::default()).unwrap();
    assert_eq!(m, lib, "the file holds exactly what the library reads");
    // No temporary file left behind.
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);

    let again = viscoroll(&["ingest", input, "-o", o]);
    assert_eq!(again.status.code(), Some(1));
    let err = String::from_utf8(again.stderr).unwrap();
    assert!(
        err.contains("exists; not overwritten (use --force to replace it)"),
        "{err}"
    );
    let forced = viscoroll(&["ingest", input, "-o", o, "--force", "--json"]);
    assert_eq!(forced.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&forced.stdout).unwrap();
    assert_eq!(v["output"], o);
    assert_eq!(v["kind"], "shear");
    assert_eq!(v["summary"]["errors"], 1);
}

#[test]
fn bad_input_exits_1_with_one_line() {
    let dir = scratch("bad");
    let p = dir.join("nounit.csv");
    std::fs::write(&p, "f,E',E'',T\n1,10,1,20\n10,11,1,20\n").unwrap();
    let out = viscoroll(&["ingest", p.to_str().unwrap(), "--json"]);
    assert_eq!(out.status.code(), Some(1));
    // With --json a failure is one JSON object on stdout (issue 15), the message also on stderr.
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON object");
    assert!(v["error"].is_string() && v["kind"].is_string(), "{v}");
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.starts_with("viscoroll: "), "{err}");
    assert!(err.contains("column `f` (frequency) has no unit"), "{err}");
    // The same file with the units given on the command line.
    let ok = viscoroll(&[
        "ingest",
        p.to_str().unwrap(),
        "--freq-unit",
        "Hz",
        "--modulus-unit",
        "MPa",
        "--temp-unit",
        "C",
        "--json",
    ]);
    assert_eq!(
        ok.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );

    let bad_format = viscoroll(&["ingest", "data/dmasuite-tensile/T0.txt", "--format", "xyz"]);
    assert_eq!(bad_format.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&bad_format.stderr).contains("unknown format `xyz`"));
    let missing = viscoroll(&["ingest", "no/such.csv"]);
    assert_eq!(missing.status.code(), Some(1));
    // Usage errors (clap) exit 2.
    assert_eq!(viscoroll(&["ingest"]).status.code(), Some(2));
    assert_eq!(
        viscoroll(&["ingest", "x.csv", "--bogus"]).status.code(),
        Some(2)
    );
}

#[test]
fn several_files_in_one_measurement() {
    let out = viscoroll(&[
        "ingest",
        "data/dmasuite-tensile/T0.txt",
        "data/dmasuite-tensile/T5.txt",
        "data/dmasuite-tensile/T10.txt",
        "--json",
    ]);
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["files"].as_array().unwrap().len(), 3);
    assert_eq!(v["summary"]["isotherms"], 3);
    assert_eq!(v["summary"]["points"], 180);
    assert_eq!(v["files"][1]["nominal_temps_c"], serde_json::json!([5.0]));
}

#[test]
fn ingest_cli_takes_a_column_mapping_and_prints_the_evidence() {
    let out = Command::new(env!("CARGO_BIN_EXE_viscoroll"))
        .args([
            "ingest",
            "tests/data/formats/mapped_columns.csv",
            "--columns",
            "freq=Frq,temp=Tmp,storage=Mod1,loss=Mod2",
            "--mode",
            "tensile",
            "--json",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["files"][0]["isotherms"], 4);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("evidence: --mode"), "{err}");
    let bad = Command::new(env!("CARGO_BIN_EXE_viscoroll"))
        .args([
            "ingest",
            "tests/data/formats/mapped_columns.csv",
            "--columns",
            "frq=Frq",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("unknown key `frq`"));
}
