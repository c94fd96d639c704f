//! Every `--json` output carries `schema_version` and matches its published JSON Schema in
//! docs/schemas/ (issue 29 item 5, part): each command is run on the shipped data, its stdout parsed
//! and validated, and a failing command's error object against `error.schema.json`.
//!
//! The schemas use a small subset of JSON Schema (2020-12): `type` (a name or a list), `required`,
//! `properties`, `additionalProperties` (true/false), `items`, `const`, `enum`, and the annotations
//! `$schema`, `title`, `description`. [`validate`] checks exactly that subset and refuses any other
//! keyword, so a schema cannot rely on a rule this test would not check.

use crate::support::{data_dir, stderr, temp_dir, viscoroll};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// The published schema `docs/schemas/NAME.schema.json`.
pub(crate) fn schema(name: &str) -> Value {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("docs/schemas/{name}.schema.json"));
    serde_json::from_str(&std::fs::read_to_string(&p).unwrap()).unwrap()
}

fn type_ok(t: &str, v: &Value) -> bool {
    match t {
        "object" => v.is_object(),
        "array" => v.is_array(),
        "string" => v.is_string(),
        "boolean" => v.is_boolean(),
        "null" => v.is_null(),
        "number" => v.is_number(),
        "integer" => v.is_i64() || v.is_u64(),
        other => panic!("unknown type {other}"),
    }
}

/// The errors of `v` against `s` (empty: valid), each with its JSON path.
pub(crate) fn validate(s: &Value, v: &Value, path: &str, errors: &mut Vec<String>) {
    let s = s.as_object().expect("a schema is an object");
    for (k, rule) in s {
        match k.as_str() {
            "$schema" | "title" | "description" => {}
            "type" => {
                let ok = match rule {
                    Value::String(t) => type_ok(t, v),
                    Value::Array(ts) => ts.iter().any(|t| type_ok(t.as_str().unwrap(), v)),
                    _ => panic!("{path}: bad type rule {rule}"),
                };
                if !ok {
                    errors.push(format!("{path}: {v} is not of type {rule}"));
                }
            }
            "const" if v != rule => errors.push(format!("{path}: {v} ≠ {rule}")),
            "enum" if !rule.as_array().unwrap().contains(v) => {
                errors.push(format!("{path}: {v} not in {rule}"))
            }
            "const" | "enum" => {}
            "required" => {
                if let Some(o) = v.as_object() {
                    for r in rule.as_array().unwrap() {
                        if !o.contains_key(r.as_str().unwrap()) {
                            errors.push(format!("{path}: missing required {r}"));
                        }
                    }
                }
            }
            "properties" => {
                if let Some(o) = v.as_object() {
                    for (name, sub) in rule.as_object().unwrap() {
                        if let Some(x) = o.get(name) {
                            validate(sub, x, &format!("{path}.{name}"), errors);
                        }
                    }
                }
            }
            "additionalProperties" => {
                if rule == &Value::Bool(false) {
                    let known = s.get("properties").and_then(Value::as_object);
                    for name in v.as_object().into_iter().flat_map(|o| o.keys()) {
                        if !known.is_some_and(|p| p.contains_key(name)) {
                            errors.push(format!("{path}: unexpected field {name}"));
                        }
                    }
                } else {
                    assert_eq!(rule, &Value::Bool(true), "{path}: additionalProperties");
                }
            }
            "items" => {
                for (i, x) in v.as_array().into_iter().flatten().enumerate() {
                    validate(rule, x, &format!("{path}[{i}]"), errors);
                }
            }
            other => panic!("{path}: keyword {other} is not checked by this test"),
        }
    }
}

/// The validator itself: it catches what it claims to.
#[test]
fn the_validator_catches_type_required_const_and_unknown_fields() {
    let s = serde_json::json!({"type": "object", "required": ["a", "schema_version"],
        "properties": {"schema_version": {"const": 1}, "a": {"type": ["number", "null"]},
        "b": {"type": "array", "items": {"type": "string"}}}, "additionalProperties": false});
    let check = |v: Value| {
        let mut e = Vec::new();
        validate(&s, &v, "$", &mut e);
        e
    };
    assert!(check(serde_json::json!({"a": 1.5, "schema_version": 1, "b": ["x"]})).is_empty());
    assert!(check(serde_json::json!({"a": null, "schema_version": 1})).is_empty());
    for bad in [
        serde_json::json!({"schema_version": 1}),
        serde_json::json!({"a": "x", "schema_version": 1}),
        serde_json::json!({"a": 1, "schema_version": 2}),
        serde_json::json!({"a": 1, "schema_version": 1, "b": [1]}),
        serde_json::json!({"a": 1, "schema_version": 1, "c": 0}),
    ] {
        assert_eq!(check(bad.clone()).len(), 1, "{bad}");
    }
}

/// Run `viscoroll ARGS… --json`, expect `ok` (success or not), and return its one JSON object.
fn json_of(args: &[&str], ok: bool) -> Value {
    let mut a: Vec<&str> = args.to_vec();
    a.push("--json");
    let o = viscoroll(&a);
    assert_eq!(o.status.success(), ok, "{args:?}: {}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let mut lines = text.lines().filter(|l| !l.trim().is_empty());
    let v: Value = serde_json::from_str(lines.next().expect("one JSON object")).unwrap();
    assert!(
        lines.next().is_none(),
        "{args:?}: more than one line on stdout"
    );
    v
}

fn assert_valid(name: &str, v: &Value) {
    assert_eq!(v["schema_version"], 1, "{name}: {v}");
    let mut errors = Vec::new();
    validate(&schema(name), v, "$", &mut errors);
    assert!(errors.is_empty(), "{name}: {errors:#?}");
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn every_json_output_matches_its_schema() {
    let dir = temp_dir("json-schemas");
    let data = data_dir();
    let pv = |f: &str| data.join("pyvisco-ems-ca").join(f);
    let raw = pv("freq_user_raw.csv");
    let meas = dir.join("m.json");
    assert_valid(
        "ingest",
        &json_of(&["ingest", s(&raw), "-o", s(&meas)], true),
    );
    assert_valid("master", &json_of(&["master", s(&meas)], true));
    let fit = dir.join("fits/ems.json");
    assert_valid(
        "fit",
        &json_of(&["fit", s(&meas), "--no-bands", "-o", s(&fit)], true),
    );
    assert_valid("convert", &json_of(&["convert", s(&fit)], true));
    let spectrum = data.join("spectra/example_creep.json");
    let scene = [
        "--radius-mm",
        "100",
        "--load-n-per-m",
        "2000",
        "--speed-m-s",
        "1",
    ];
    let mut roll = vec!["roll", s(&spectrum)];
    roll.extend(scene);
    assert_valid("roll", &json_of(&roll, true));
    let mut roll_fit = vec!["roll", s(&fit), "--temp-c", "20", "--cover-mm", "5"];
    roll_fit.extend(scene);
    assert_valid("roll", &json_of(&roll_fit, true));
    assert_valid(
        "contact",
        &json_of(&["contact", "--creep", "10:1", "--lambda", "1"], true),
    );
    assert_valid(
        "contact",
        &json_of(
            &["contact", "--creep", "10:1", "--load", "0.25", "--rho", "3"],
            true,
        ),
    );
    let card = dir.join("out/ems.inp");
    assert_valid(
        "export",
        &json_of(&["export", s(&fit), "--to", "abaqus", "-o", s(&card)], true),
    );
    let pyv = dir.join("out/ems.csv");
    assert_valid(
        "export",
        &json_of(&["export", s(&fit), "--to", "pyvisco", "-o", s(&pyv)], true),
    );
    let input: PathBuf = dir.join("in");
    std::fs::create_dir_all(&input).unwrap();
    std::fs::copy(&raw, input.join("ems.csv")).unwrap();
    let out = dir.join("run");
    assert_valid(
        "run",
        &json_of(&["run", s(&input), "--out", s(&out), "--no-bands"], true),
    );
    let fits = out.join("fits/ems.json");
    assert_valid("rank", &json_of(&["rank", s(&fits), "--no-bands"], true));
    // A failure: the error object, for any command.
    for args in [
        vec!["roll", "no-such-file.json", "--radius-mm", "1"],
        vec!["convert", "no-such-file.json"],
        vec!["fit", "--loss-weight", "0", "no-such-file.json"],
    ] {
        assert_valid("error", &json_of(&args, false));
    }
}

/// A schema per command that has `--json` (and the error object), and no schema for nothing.
#[test]
fn a_schema_for_every_command_with_json() {
    let mut have: Vec<String> =
        std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/schemas"))
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
    have.sort();
    let mut want: Vec<String> = Vec::new();
    for cmd in [
        "ingest", "master", "fit", "convert", "export", "roll", "contact", "run", "rank",
    ] {
        let o = viscoroll(&[cmd, "--help"]);
        assert!(
            String::from_utf8_lossy(&o.stdout).contains("--json"),
            "{cmd}"
        );
        want.push(format!("{cmd}.schema.json"));
    }
    want.push("error.schema.json".into());
    // not a command's output: the sidecar of every CSV table (tests/csv_tables.rs)
    want.push("csv-meta.schema.json".into());
    want.sort();
    assert_eq!(have, want);
}
