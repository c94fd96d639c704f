//! `viscoroll contact` and `viscoroll roll` end to end: JSON fields, Table 1 through the CLI, and bad
//! arguments (one-line error, exit code 1, no panic).

use crate::support::{self, num, viscoroll as run};
use std::process::Output;

fn json(out: &Output) -> serde_json::Value {
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        text.trim().lines().count(),
        1,
        "exactly one JSON line on stdout: {text}"
    );
    support::json(out)
}

fn one_line_error(args: &[&str], needle: &str) {
    let out = run(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(
        out.status.code(),
        Some(1),
        "{args:?}: exit code {:?}, stderr {err}",
        out.status.code()
    );
    assert!(out.stdout.is_empty(), "{args:?}: stdout not empty");
    assert_eq!(
        err.trim().lines().count(),
        1,
        "{args:?}: not one line: {err}"
    );
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    assert!(err.contains(needle), "{args:?}: `{needle}` not in `{err}`");
}

#[test]
fn contact_json_table_1() {
    let v = json(&run(&[
        "contact", "--creep", "10:1", "--lambda", "1", "--n", "40", "--json",
    ]));
    for key in [
        "lambda",
        "beta",
        "beta_over_lambda",
        "load",
        "friction_rho",
        "n",
        "iterations",
    ] {
        num(&v, key);
    }
    assert_eq!(v["scheme"], "thesis");
    assert!(v.get("friction").is_none(), "friction only with --rho");
    // Table 1 (tolerances as in contact_thesis::table_1_one_parameter_model).
    assert!((num(&v, "beta_over_lambda") - 0.1959).abs() <= 2e-4);
    assert!((num(&v, "friction_rho") - 0.43093).abs() <= 5e-4);
    assert_eq!(num(&v, "n"), 40.0);
    assert_eq!(num(&v, "iterations"), 0.0);
    let xi = v["xi"].as_array().unwrap();
    let q = v["pressure"].as_array().unwrap();
    assert_eq!(xi.len(), 41);
    assert_eq!(q.len(), 41);
    assert_eq!(q[0].as_f64(), Some(0.0));
    assert_eq!(q[40].as_f64(), Some(0.0));
}

#[test]
fn contact_json_at_load_with_rho() {
    let v = json(&run(&[
        "contact",
        "--creep",
        "10:1,0.5:0.01",
        "--load",
        "0.5",
        "--n",
        "60",
        "--rho",
        "20",
        "--json",
    ]));
    assert!((num(&v, "load") / 0.5 - 1.0).abs() <= 1e-8);
    assert!(num(&v, "iterations") >= 2.0);
    // F/N = (ρF/N)/ρ (docs/MATH.md §1).
    assert!((num(&v, "friction") - num(&v, "friction_rho") / 20.0).abs() <= 1e-15);
}

#[test]
fn contact_human_output_goes_to_stderr() {
    let out = run(&["contact", "--creep", "0:1", "--lambda", "2", "--n", "10"]);
    assert!(out.status.success());
    assert!(out.stdout.is_empty());
    assert!(String::from_utf8_lossy(&out.stderr).contains("beta/lambda"));
}

#[test]
fn contact_bad_arguments() {
    one_line_error(
        &["contact", "--creep", "10:-1", "--lambda", "1"],
        "b must be",
    );
    one_line_error(
        &["contact", "--creep", "10:0", "--lambda", "1"],
        "b must be",
    );
    one_line_error(
        &["contact", "--creep", "-1:1", "--lambda", "1"],
        "f must be",
    );
    one_line_error(
        &["contact", "--creep", "10", "--lambda", "1"],
        "not of the form f:b",
    );
    one_line_error(
        &["contact", "--creep", "10:x", "--lambda", "1"],
        "not a number",
    );
    one_line_error(
        &["contact", "--creep", "10:1", "--lambda", "-1"],
        "--lambda",
    );
    one_line_error(&["contact", "--creep", "10:1", "--load", "0"], "--load");
    one_line_error(
        &["contact", "--creep", "10:1", "--load", "1", "--lambda", "1"],
        "only one",
    );
    one_line_error(&["contact", "--creep", "10:1"], "--lambda");
    one_line_error(
        &["contact", "--creep", "10:1", "--lambda", "1", "--n", "1"],
        "number of intervals",
    );
    one_line_error(
        &["contact", "--creep", "10:1", "--lambda", "1", "--rho", "0"],
        "--rho",
    );
    // An unknown scheme is a usage error (exit code 2, like every argument clap rejects): its first
    // line names the option and the schemes known.
    let out = run(&[
        "contact", "--creep", "10:1", "--lambda", "1", "--scheme", "magic",
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    let first = err.lines().next().unwrap_or("");
    assert!(
        first.contains("--scheme") && first.contains("thesis, exact, auto"),
        "{err}"
    );
}

const SPECTRUM: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/data/spectra/example_creep.json"
);

#[test]
fn roll_json_fields() {
    let v = json(&run(&[
        "roll",
        SPECTRUM,
        "--radius-mm",
        "100",
        "--load-n-per-m",
        "2000",
        "--speed-m-s",
        "5",
        "--scheme",
        "thesis",
        "--n",
        "120",
        "--json",
    ]));
    for key in [
        "friction",
        "contact_length_mm",
        "offset_mm",
        "resistance_n_per_m",
        "max_pressure_mpa",
    ] {
        assert!(
            num(&v, key).is_finite() && num(&v, key) > 0.0,
            "{key} = {}",
            v[key]
        );
    }
    // F* = (F/N)·N*.
    assert!((num(&v, "resistance_n_per_m") - 2000.0 * num(&v, "friction")).abs() <= 1e-12 * 2000.0);
    // Contact length between the glassy and relaxed Hertz lengths 2√(4RN(1−ν²)/(πE)) for
    // E₀ = 1 GPa and E∞ = 1/(3.333e-7 Pa⁻¹) (the spectrum file), with 1 % slack for the
    // first-order discretisation error at n = 120.
    let hertz =
        |e: f64| 2.0 * (4.0 * 0.1 * 2000.0 * 0.75 / (std::f64::consts::PI * e)).sqrt() * 1e3;
    let l = num(&v, "contact_length_mm");
    assert!(
        l > 0.99 * hertz(1e9) && l < 1.01 * hertz(1.0 / 3.333e-7),
        "l = {l} mm"
    );
    assert_eq!(v["x_mm"].as_array().unwrap().len(), 121);
}

#[test]
fn roll_bad_arguments() {
    let base = [
        "roll",
        SPECTRUM,
        "--radius-mm",
        "100",
        "--load-n-per-m",
        "2000",
        "--speed-m-s",
        "5",
    ];
    let with = |i: usize, val: &'static str| {
        let mut a = base.to_vec();
        a[i] = val;
        a
    };
    one_line_error(&with(3, "0"), "--radius-mm");
    one_line_error(&with(3, "-5"), "--radius-mm");
    one_line_error(&with(5, "-1"), "--load-n-per-m");
    one_line_error(&with(7, "0"), "--speed-m-s");
    one_line_error(&with(1, "/nonexistent/spectrum.json"), "cannot read");
    let mut a = base.to_vec();
    a.extend(["--poisson", "0.9"]);
    one_line_error(&a, "poisson");
    one_line_error(
        &with(1, concat!(env!("CARGO_MANIFEST_DIR"), "/Cargo.toml")),
        "not a creep spectrum",
    );
}

#[test]
fn contact_exact_scheme() {
    let v = json(&run(&[
        "contact", "--creep", "10:1", "--lambda", "1", "--n", "40", "--scheme", "exact", "--json",
    ]));
    assert_eq!(v["scheme"], "exact");
    // Goodier & Loutzenheiser's 0.1952 and 0.4308 within 0.5 % (as in contact_exact).
    assert!((num(&v, "beta_over_lambda") / 0.1952 - 1.0).abs() <= 5e-3);
    assert!((num(&v, "friction_rho") / 0.4308 - 1.0).abs() <= 5e-3);
    assert_eq!(v["xi"].as_array().unwrap().len(), 41);
    one_line_error(
        &[
            "contact", "--creep", "1:1,1:2", "--lambda", "1", "--scheme", "exact",
        ],
        "one creep term",
    );
}

#[test]
fn contact_cover_is_the_dimensionless_roll_cover() {
    // `contact --cover H′` is `roll --cover-mm H` in the units of V·T: the same creep terms, load and
    // h′ = H/(V·T) must give the same λ, β and ρF/N (the same computation; 1e−9 allows for the last
    // digits of V·T recovered from the JSON).
    let spectrum = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/data/spectra/example_creep.json"
    );
    let r = json(&run(&[
        "roll",
        spectrum,
        "--radius-mm",
        "66.5",
        "--load-n-per-m",
        "10000",
        "--speed-m-s",
        "4",
        "--cover-mm",
        "5",
        "--model",
        "layer",
        "--tol",
        "1e-3",
        "--json",
    ]));
    let creep: Vec<String> = r["creep"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| format!("{}:{}", num(t, "f"), num(t, "b")))
        .collect();
    let vt_mm = num(&r, "contact_length_mm") / num(&r, "lambda");
    let h = format!("{}", 5.0 / vt_mm);
    let load = format!("{}", num(&r, "load"));
    let c = json(&run(&[
        "contact",
        "--creep",
        &creep.join(","),
        "--load",
        &load,
        "--cover",
        &h,
        "--model",
        "layer",
        "--tol",
        "1e-3",
        "--rho",
        &format!("{}", num(&r, "rho")),
        "--json",
    ]));
    for key in [
        "lambda",
        "beta",
        "friction_rho",
        "error_estimate",
        "cover_over_contact",
    ] {
        let (a, b) = (num(&c, key), num(&r, key));
        // the error estimate is a difference of two solves (degree p vs p/2 of the spectral layer
        // solver), so its own relative rounding is ~1e−16/estimate ≈ 1e−11 here, amplified by the
        // input's last digits: 1e−6 of itself
        let tol = if key == "error_estimate" { 1e-6 } else { 1e-9 };
        assert!(
            (a - b).abs() <= tol * b.abs(),
            "{key}: contact {a} vs roll {b}"
        );
    }
    assert!((num(&c, "friction") - num(&r, "friction")).abs() <= 1e-9 * num(&r, "friction"));
    for key in [
        "model",
        "model_reason",
        "model_error_estimate",
        "min_pressure_ratio",
        "min_gap_ratio",
        "warnings",
        "poisson",
        "tol",
    ] {
        assert!(
            !c[key].is_null() || key == "model_error_estimate",
            "{key} missing: {c}"
        );
    }
    assert_eq!(c["model"], "layer");
}

#[test]
fn contact_cover_auto_chooses_by_the_criterion() {
    // A cover 1e4 times the contact length: auto takes the half-space (estimated difference
    // 3(λ/h)² ≈ 1e−8 ≤ tol) and its answer is the half-space's without a cover, to rounding.
    let hs = json(&run(&[
        "contact", "--creep", "10:1", "--load", "0.25", "--scheme", "auto", "--tol", "1e-6",
        "--json",
    ]));
    let thick = json(&run(&[
        "contact", "--creep", "10:1", "--load", "0.25", "--cover", "1e4", "--tol", "1e-6", "--json",
    ]));
    assert_eq!(thick["model"], "half-space");
    assert!(num(&thick, "model_error_estimate") <= 1e-6);
    assert_eq!(num(&thick, "friction_rho"), num(&hs, "friction_rho"));
    // A thin compressible cover (h′ = 1e−3, ν = 0.3): the constrained Winkler foundation; at a
    // cover of 0.3 the layer, without a model error.
    let thin = json(&run(&[
        "contact",
        "--creep",
        "10:1",
        "--load",
        "0.25",
        "--cover",
        "1e-3",
        "--poisson",
        "0.3",
        "--tol",
        "1e-2",
        "--json",
    ]));
    assert_eq!(thin["model"], "winkler-constrained");
    assert!(num(&thin, "model_error_estimate") <= 1e-2);
    let mid = json(&run(&[
        "contact", "--creep", "10:1", "--lambda", "1", "--cover", "0.3", "--n", "64", "--json",
    ]));
    assert_eq!(mid["model"], "layer");
    assert!(mid["model_error_estimate"].is_null());
    assert!(num(&mid, "error_estimate") > 0.0 && num(&mid, "error_estimate") < 0.05);
}

#[test]
fn contact_cover_bad_arguments() {
    let base = ["contact", "--creep", "10:1", "--load", "0.25"];
    let with = |extra: &[&'static str]| {
        let mut a = base.to_vec();
        a.extend_from_slice(extra);
        a
    };
    one_line_error(&with(&["--model", "layer"]), "--cover");
    one_line_error(&with(&["--cover", "0"]), "--cover");
    one_line_error(&with(&["--cover", "-1"]), "--cover");
    one_line_error(&with(&["--cover", "1", "--poisson", "0.7"]), "--poisson");
    one_line_error(&with(&["--cover", "1", "--model", "plate"]), "--model");
}

#[test]
fn cli_contact_auto_and_roll_default_report_error_and_modes() {
    let exe = env!("CARGO_BIN_EXE_viscoroll");
    let out = std::process::Command::new(exe)
        .args([
            "contact", "--creep", "10:1", "--lambda", "1", "--scheme", "auto", "--tol", "1e-9",
            "--json",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["scheme"], "auto");
    // thesis Table 1 case, exact (mpmath) ρF/N = 0.43218841466733969
    assert!((v["friction_rho"].as_f64().unwrap() / 0.432_188_414_667_339_7 - 1.0).abs() < 1e-9);
    assert!(v["error_estimate"].as_f64().unwrap() <= 1e-9);
    assert_eq!(v["modes_used"], 1);
    assert_eq!(v["modes_total"], 1);

    let dir = crate::support::temp_dir("auto");
    let spec = dir.join("spec.json");
    std::fs::write(
        &spec,
        r#"{"compliance_glassy_per_pa": 1e-9, "terms": [
            {"compliance_per_pa": 1e-7, "tau_s": 1e-3}, {"compliance_per_pa": 5e-7, "tau_s": 1e3}]}"#,
    )
    .unwrap();
    let out = std::process::Command::new(exe)
        .args([
            "roll",
            spec.to_str().unwrap(),
            "--radius-mm",
            "50",
            "--load-n-per-m",
            "1000",
        ])
        .args(["--speed-m-s", "1", "--json"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["scheme"], "auto");
    assert!(v["error_estimate"].as_f64().unwrap() <= 1e-6);
    assert_eq!(v["modes_total"], 2);
    assert!(v["friction"].as_f64().unwrap() > 0.0);
    // a bad tolerance is a one-line error, not a panic
    let out = std::process::Command::new(exe)
        .args([
            "roll",
            spec.to_str().unwrap(),
            "--radius-mm",
            "50",
            "--load-n-per-m",
            "1000",
        ])
        .args(["--speed-m-s", "1", "--tol", "0"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(String::from_utf8_lossy(&out.stderr).lines().count(), 1);
    let _ = std::fs::remove_dir_all(&dir);
}
