//! Helpers shared by the integration tests (one copy instead of one per file): the built binary,
//! fresh scratch folders, the shipped data, running the main job, and reading the CSV tables it
//! writes (parsed strictly with the csv crate: one header row, rows as wide, no comment lines) and
//! their sidecars (`NAME.meta.json`).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Path of the `viscoroll` binary cargo built for these tests.
pub fn bin() -> &'static str {
    env!("CARGO_BIN_EXE_viscoroll")
}

/// `viscoroll ARGS…`, its output (status, stdout, stderr); no check on the status.
pub fn viscoroll(args: &[&str]) -> Output {
    Command::new(bin())
        .args(args)
        .output()
        .expect("the viscoroll binary runs")
}

/// A fresh, empty folder `viscoroll-TAG-PID` in the system temp folder (removed first if a
/// previous run left it). Tags must differ between tests that run at the same time.
pub fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("viscoroll-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The shipped data folder (`data/`: DMA exports, compounds.toml, scenes.toml).
pub fn data_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("data")
}

/// `viscoroll run DIR --out OUT EXTRA…` (the main job), its output; no check on the status.
pub fn run_main(dir: &Path, out: &Path, extra: &[&str]) -> Output {
    Command::new(bin())
        .arg("run")
        .arg(dir)
        .arg("--out")
        .arg(out)
        .args(extra)
        .output()
        .expect("the viscoroll binary runs")
}

/// stderr as text (lossy), for assertion messages.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

pub use crate::shipped::table;

/// The sidecar `NAME.meta.json` of the table `NAME.csv` at `path`, as JSON.
pub fn table_meta(path: &Path) -> serde_json::Value {
    let p = path.with_extension("meta.json");
    let text = std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// Index of the column `name` in `header` (panics naming it if absent).
pub fn col(header: &[String], name: &str) -> usize {
    header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {header:?}"))
}

/// The column `name` of the CSV table at `path`, as text, one entry a row.
pub fn column(path: &Path, name: &str) -> Vec<String> {
    let (header, rows) = table(path);
    let c = col(&header, name);
    rows.into_iter().map(|mut r| r.swap_remove(c)).collect()
}

/// The one JSON object a `--json` command printed on stdout (the command must have succeeded).
pub fn json(out: &Output) -> serde_json::Value {
    assert!(out.status.success(), "failed: {}", stderr(out));
    serde_json::from_slice(&out.stdout).expect("one JSON object on stdout")
}

/// The number `v[key]` (panics naming the field if it is missing or not a number).
pub fn num(v: &serde_json::Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("field {key} missing or not a number in {v}"))
}

/// The fit warnings of a friction.csv (its sidecar's `warnings`, F1, F2, … in order) and its
/// note column.
pub fn fit_warnings_and_notes(path: &Path) -> (Vec<String>, Vec<String>) {
    let warnings: Vec<String> = table_meta(path)["warnings"]
        .as_array()
        .expect("warnings in the sidecar")
        .iter()
        .map(|w| w.as_str().unwrap().to_string())
        .collect();
    (warnings, column(path, "note"))
}

/// A fit file's JSON, edited on purpose by a test, sealed again with its content hash (as
/// `CompoundFit::write` does), so the edit is read as a fit the tool made.
pub fn sealed_fit_json(v: serde_json::Value) -> String {
    let mut f: viscoroll::results::CompoundFit = serde_json::from_value(v).unwrap();
    f.content_sha256 = Some(f.content_hash().unwrap());
    serde_json::to_string_pretty(&f).unwrap()
}
