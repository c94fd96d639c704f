//! `viscoroll run` on hostile or awkward input folders (issue 15): each class of bad input has a test
//! here — empty folders, bad files that must fail alone (zip bomb, far cell, an isotherm at 1e9 °C,
//! a 30 MB line), names that try to leave the output folder, untrusted fits (exit 3), two runs on one
//! output folder, temp files of a killed run, reports of removed compounds, usage errors, scene
//! numbers out of range, `--tref` and measurement JSON. Inputs are synthetic exports of a known
//! rubber-like material, written by [`rubber_csv`].

use crate::support::{bin, fit_warnings_and_notes, run_main, temp_dir};
use std::io::Write as _;
use std::path::Path;
use std::process::Command;

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// A generic CSV export of a rubber-like material (E∞ = 1 MPa, one 100 MPa term at 1 ms, a weak
/// power law, WLF shifts about 20 °C): `n` log-spaced frequencies 0.1–100 Hz per temperature.
pub fn rubber_csv(temps_c: &[f64], n: usize) -> String {
    let mut s = String::from("temperature [°C],frequency [Hz],E' [Pa],E'' [Pa]\n");
    for &t in temps_c {
        let a_t = 10f64.powf(-8.0 * (t - 20.0) / (100.0 + t - 20.0));
        for k in 0..n {
            let f = 10f64.powf(-1.0 + 3.0 * k as f64 / (n - 1).max(1) as f64);
            let w = 2.0 * std::f64::consts::PI * f * a_t;
            let x = w * 1e-3;
            let e1 = 1e6 + 1e8 * x * x / (1.0 + x * x) + 1e6 * w.powf(0.2);
            let e2 = 1e8 * x / (1.0 + x * x) + 2e5 * w.powf(0.2);
            s.push_str(&format!("{t},{f:.6e},{e1:.6e},{e2:.6e}\n"));
        }
    }
    s
}

fn zip_of(parts: &[(&str, &[u8])]) -> Vec<u8> {
    let mut w = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let opts = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated);
    for (name, data) in parts {
        w.start_file(*name, opts).unwrap();
        w.write_all(data).unwrap();
    }
    w.finish().unwrap().into_inner()
}

#[test]
fn an_empty_folder_exits_1_with_a_message_and_one_json_object() {
    let dir = temp_dir("hard-empty-in");
    let out = temp_dir("hard-empty-out");
    std::fs::write(dir.join("notes.md"), "not an export").unwrap();
    let o = run_main(&dir, &out, &["--json"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        text(&o.stderr).contains("no DMA export"),
        "{}",
        text(&o.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v["error"].as_str().unwrap().contains("no DMA export"));
    assert_eq!(v["exit_code"], 1);
    assert_eq!(text(&o.stdout).lines().count(), 1);
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn bad_files_fail_alone_and_the_good_compound_still_gets_its_report() {
    let dir = temp_dir("hard-bad-in");
    let out = temp_dir("hard-bad-out");
    std::fs::write(dir.join("good.csv"), rubber_csv(&[0.0, 20.0, 40.0], 20)).unwrap();
    // An isotherm at 1e9 °C: refused at ingest (it used to hang the shift-law fits).
    std::fs::write(dir.join("hot.csv"), rubber_csv(&[0.0, 1e9], 20)).unwrap();
    // A zip bomb: 300 MiB of zeros in a ~300 kB .xlsx (more than the guard's 256 MiB per part).
    let zeros = vec![0u8; 300 << 20];
    std::fs::write(
        dir.join("bomb.xlsx"),
        zip_of(&[("xl/sharedStrings.xml", &zeros)]),
    )
    .unwrap();
    drop(zeros);
    // One far cell: calamine would allocate 1.7e10 cells for it.
    let far = br#"<worksheet><sheetData><row r="1"><c r="A1"><v>1</v></c></row><row r="1048576"><c r="XFD1048576"><v>2</v></c></row></sheetData></worksheet>"#;
    std::fs::write(
        dir.join("far.xlsx"),
        zip_of(&[("xl/worksheets/sheet1.xml", far)]),
    )
    .unwrap();
    // A 30 MB line: its error must not become a 30 MB line of index.html.
    let mut long = rubber_csv(&[0.0, 20.0], 5);
    long.push_str(&"x".repeat(30 << 20));
    long.push('\n');
    std::fs::write(dir.join("long.csv"), long).unwrap();

    let o = run_main(&dir, &out, &["--no-bands"]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(out.join("reports/good/datasheet.html").is_file(), "{err}");
    let index = std::fs::read_to_string(out.join("reports/index.html")).unwrap();
    for (name, reason) in [
        ("hot", "above 1000 °C"),
        ("bomb", "zip bomb"),
        ("far", "far cell"),
    ] {
        let line = err
            .lines()
            .find(|l| l.starts_with(&format!("{name}: FAILED")))
            .unwrap_or_else(|| panic!("{name} did not fail: {err}"));
        assert!(line.contains(reason), "{line}");
        assert!(index.contains(&format!("<b>{name}</b>")), "{name}");
    }
    // Every line kept short: the index stays small, whatever `long` did.
    assert!(index.len() < 100_000, "index.html is {} bytes", index.len());
    assert!(err.lines().all(|l| l.len() < 2000), "a long stderr line");
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn names_are_sanitised_so_nothing_is_written_outside_the_output_folder() {
    let base = temp_dir("hard-names");
    let (dir, out) = (base.join("in"), base.join("out"));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("a.csv"), rubber_csv(&[0.0, 20.0, 40.0], 12)).unwrap();
    let listing: String = ["../escape", "/abs/olute", "a/b", "a_b", "..", "C:\\\\win"]
        .iter()
        .map(|n| format!("[[compound]]\nname = \"{n}\"\nfiles = [\"a.csv\"]\n"))
        .collect();
    std::fs::write(dir.join("compounds.toml"), listing).unwrap();
    let o = run_main(&dir, &out, &[]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    // Only `in` and `out` under the base folder; nothing at /abs.
    let mut top: Vec<String> = std::fs::read_dir(&base)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    top.sort();
    assert_eq!(top, ["in", "out"]);
    assert!(!Path::new("/abs/olute.json").exists());
    let mut fits: Vec<String> = std::fs::read_dir(out.join("fits"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    fits.sort();
    assert_eq!(fits.len(), 6, "{fits:?}");
    assert!(
        fits.iter()
            .all(|f| !f.contains("..") && !f.starts_with('.')),
        "{fits:?}"
    );
    let _ = std::fs::remove_dir_all(&base);
}

/// Issue 15, per-compound settings: an export whose column names no reader knows (`T`, `Frq`,
/// `Mod1`, `Mod2`) fails without a mapping, naming the columns; with `columns` (a table or the
/// `ingest --columns` string) and `mode` in compounds.toml, `run` fits it, and both forms give the
/// same fit as the same data under the generic reader's names. A bad key is refused naming it.
#[test]
fn compounds_toml_maps_the_columns_of_an_unknown_export() {
    let base = temp_dir("hard-colmap");
    let (dir, out) = (base.join("in"), base.join("out"));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = rubber_csv(&[0.0, 20.0, 40.0], 12);
    let (header, body) = csv.split_once('\n').unwrap();
    assert_eq!(header, "temperature [°C],frequency [Hz],E' [Pa],E'' [Pa]");
    std::fs::write(
        dir.join("odd.csv"),
        format!("T [°C],Frq [Hz],Mod1 [Pa],Mod2 [Pa]\n{body}"),
    )
    .unwrap();
    std::fs::write(dir.join("plain.csv.ref"), &csv).unwrap();
    let listing = |columns: &str| {
        format!(
            "[[compound]]\nname = \"odd\"\nfiles = [\"odd.csv\"]\nmode = \"tensile\"\n{columns}\n\
             [[compound]]\nname = \"plain\"\nfiles = [\"plain.csv.ref\"]\nformat = \"generic\"\n"
        )
    };
    std::fs::write(dir.join("compounds.toml"), listing("")).unwrap();
    let o = run_main(&dir, &out, &["--no-bands"]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("no frequency column") && err.contains("`Frq`"),
        "{err}"
    );
    let friction = |name: &str| {
        std::fs::read_to_string(out.join(format!("reports/{name}/friction.csv"))).unwrap()
    };
    for columns in [
        r#"columns = { temp = "T", freq = "Frq", storage = "Mod1", loss = "Mod2" }"#,
        r#"columns = "temp=T,freq=Frq,storage=Mod1,loss=Mod2""#,
    ] {
        std::fs::write(dir.join("compounds.toml"), listing(columns)).unwrap();
        let o = run_main(&dir, &out, &["--force", "--no-bands"]);
        assert!(o.status.success(), "{columns}: {}", text(&o.stderr));
        // Same numbers, so the friction tables agree past their first column header lines.
        let (a, b) = (friction("odd"), friction("plain"));
        assert_eq!(
            a.lines().skip(1).collect::<Vec<_>>(),
            b.lines().skip(1).collect::<Vec<_>>()
        );
    }
    std::fs::write(
        dir.join("compounds.toml"),
        listing(r#"columns = { frq = "Frq" }"#),
    )
    .unwrap();
    let o = run_main(&dir, &out, &["--force", "--no-bands"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        text(&o.stderr).contains("unknown key `frq`"),
        "{}",
        text(&o.stderr)
    );
    let _ = std::fs::remove_dir_all(&base);
}

#[test]
fn an_untrusted_fit_is_listed_apart_and_the_run_exits_3() {
    let dir = temp_dir("hard-untrusted-in");
    let out = temp_dir("hard-untrusted-out");
    std::fs::write(dir.join("a.csv"), rubber_csv(&[0.0, 20.0, 40.0], 20)).unwrap();
    // One Prony term per five decades cannot follow the data: RMS log10 errors far above bounds.
    std::fs::write(
        dir.join("compounds.toml"),
        "[[compound]]\nname = \"coarse\"\nfiles = [\"a.csv\"]\nprony = { terms_per_decade = 0.2 }\n[[compound]]\nname = \"fine\"\nfiles = [\"a.csv\"]\n",
    )
    .unwrap();
    let o = run_main(&dir, &out, &["--json"]);
    assert_eq!(o.status.code(), Some(3), "{}", text(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["kind"], "untrusted_results");
    assert_eq!(v["detail"]["compounds"].as_array().unwrap().len(), 2);
    let ranking = std::fs::read_to_string(out.join("reports/ranking.csv")).unwrap();
    let rows: Vec<csv::StringRecord> = csv::Reader::from_reader(ranking.as_bytes())
        .records()
        .map(|r| r.unwrap())
        .collect();
    for r in &rows {
        match &r[2] {
            // ranked: trusted, or use with care (issue 31's verdict levels)
            "fine" => assert!(
                &r[1] == "1" && ["trusted", "use with care"].contains(&&r[5]),
                "{r:?}"
            ),
            "coarse" => {
                assert_eq!((&r[1], &r[5]), ("", "not trusted"));
                assert!(r[8].contains("prony_rms_log10_storage"), "{r:?}");
            }
            other => panic!("{other}"),
        }
    }
    let friction = out.join("reports/coarse/friction.csv");
    let reasons = crate::support::column(&friction, "not_trusted");
    assert!(!reasons.is_empty());
    assert!(
        reasons
            .iter()
            .all(|r| r.contains("prony_rms_log10_storage")),
        "{reasons:?}"
    );
    assert!(crate::support::table_meta(&friction)["not_trusted"]
        .to_string()
        .contains("prony_rms_log10_storage"));
    let sheet = std::fs::read_to_string(out.join("reports/coarse/datasheet.html")).unwrap();
    assert!(
        sheet.contains("Verdict: not trusted"),
        "the datasheet states the verdict"
    );
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn two_runs_on_one_output_folder_both_succeed_and_leftovers_are_handled() {
    let dir = temp_dir("hard-twice-in");
    let out = temp_dir("hard-twice-out");
    std::fs::write(dir.join("a.csv"), rubber_csv(&[0.0, 20.0, 40.0], 15)).unwrap();
    // A temp file of a killed run (pid above Linux's pid_max, so never alive) and the report of a
    // compound that is gone from the input.
    std::fs::create_dir_all(out.join("fits")).unwrap();
    let stale = out.join("fits/.a.tmp-4294967-0.json");
    std::fs::write(&stale, "{").unwrap();
    std::fs::create_dir_all(out.join("reports/gone")).unwrap();
    let spawn = || {
        Command::new(bin())
            .arg("run")
            .arg(&dir)
            .arg("--out")
            .arg(&out)
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap()
    };
    let (a, b) = (spawn(), spawn());
    let (a, b) = (a.wait_with_output().unwrap(), b.wait_with_output().unwrap());
    assert!(a.status.success(), "{}", text(&a.stderr));
    assert!(b.status.success(), "{}", text(&b.stderr));
    assert!(!stale.exists());
    assert!(!out.join(".viscoroll.lock").exists());
    let index = std::fs::read_to_string(out.join("reports/index.html")).unwrap();
    assert!(index.contains("reports/gone") && index.contains("no longer in the input"));
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn usage_errors_are_printed_in_full_with_a_suggestion() {
    let o = Command::new(bin())
        .args(["run", "--forse"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    let e = text(&o.stderr);
    assert!(
        e.contains("--forse") && e.contains("a similar argument exists: '--force'"),
        "{e}"
    );
    let o = Command::new(bin()).arg("roll").output().unwrap();
    let e = text(&o.stderr);
    for arg in ["--radius-mm", "--load-n-per-m", "--speed-m-s"] {
        assert!(e.contains(arg), "{arg} missing from: {e}");
    }
    let o = Command::new(bin())
        .args(["rank", "--json"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["kind"], "usage");
    // No doubled text: a cause is not printed again after the error that holds it.
    let o = Command::new(bin())
        .args(["rank", "/nonexistent/fit.json"])
        .output()
        .unwrap();
    let e = text(&o.stderr);
    let first = e.find("/nonexistent/fit.json").unwrap();
    assert!(
        e[first + 1..].find("/nonexistent/fit.json").is_none(),
        "{e}"
    );
}

#[test]
fn scene_numbers_out_of_range_are_refused_naming_the_field() {
    let dir = temp_dir("hard-scene-in");
    std::fs::write(dir.join("a.csv"), rubber_csv(&[0.0, 20.0], 5)).unwrap();
    for (key, v) in [
        ("speed_m_s", "1e300"),
        ("load_n_per_m", "-1"),
        ("roll_radius_mm", "nan"),
    ] {
        let mut scene = String::from("[[scene]]\nname = \"s\"\n");
        for (k, d) in [
            ("roll_radius_mm", "50"),
            ("load_n_per_m", "1000"),
            ("speed_m_s", "1"),
        ] {
            scene.push_str(&format!("{k} = {}\n", if k == key { v } else { d }));
        }
        scene.push_str("temps_c = [20]\n");
        std::fs::write(dir.join("s.toml"), scene).unwrap();
        let o = Command::new(bin())
            .arg("run")
            .arg(&dir)
            .arg("--scenes")
            .arg(dir.join("s.toml"))
            .arg("--out")
            .arg(dir.join("out"))
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(1));
        assert!(text(&o.stderr).contains(key), "{}", text(&o.stderr));
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn run_takes_tref_and_a_measurement_json_written_by_ingest() {
    let dir = temp_dir("hard-json-in");
    let out = temp_dir("hard-json-out");
    let csv = dir.join("raw.csv.keep");
    std::fs::write(&csv, rubber_csv(&[0.0, 20.0, 40.0], 15)).unwrap();
    let o = Command::new(bin())
        .arg("ingest")
        .arg(&csv)
        .args(["--format", "generic", "-o"])
        .arg(dir.join("m.json"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", text(&o.stderr));
    let o = run_main(&dir, &out, &["--tref", "20"]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let fit: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("fits/m.json")).unwrap()).unwrap();
    assert_eq!(fit["shift_law"]["t_ref_c"].as_f64(), Some(20.0));
    // refused by the command line's temperature parser (crate::limits), as any invalid value: 2
    let o = run_main(&dir, &out, &["--tref", "1e9"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("--tref"));
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&out);
}

/// Issue 15, large files: no pass grows with the size of the file. Two isotherms of 3000 points (more
/// than `tts::clean::THIN_ABOVE_POINTS` = 1000 each) are thinned to 1000 group means each before the
/// shifting, so the master curve and the Prony QP see 2000 points, and the fit says so where the
/// user looks (the datasheet). The 1e6-row figures: `cargo bench --bench large_input`.
#[test]
fn a_large_isotherm_is_thinned_and_the_fit_says_so() {
    let dir = temp_dir("hard-thin-in");
    let out = temp_dir("hard-thin-out");
    std::fs::write(dir.join("dense.csv"), rubber_csv(&[0.0, 40.0], 3000)).unwrap();
    let o = run_main(&dir, &out, &["--no-bands"]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let fit: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("fits/dense.json")).unwrap())
            .unwrap();
    assert_eq!(fit["master_curve"].as_array().unwrap().len(), 2000);
    assert_eq!(fit["prony_info"]["n_points"].as_u64(), Some(2000));
    let warnings = fit["tts"]["warnings"].to_string();
    assert_eq!(
        warnings
            .matches("3000 points at distinct frequencies thinned to 1000 means of 3 consecutive")
            .count(),
        2,
        "{warnings}"
    );
    let sheet = std::fs::read_to_string(out.join("reports/dense/datasheet.html")).unwrap();
    assert!(sheet.contains("thinned to 1000 means"));
    // friction.csv: each fit warning once in full in its sidecar, its code at the end of every
    // row's note.
    let csv_path = out.join("reports/dense/friction.csv");
    let (warnings, notes) = fit_warnings_and_notes(&csv_path);
    assert_eq!(
        warnings
            .iter()
            .filter(|l| l.contains("thinned to 1000 means"))
            .count(),
        2,
        "{warnings:?}"
    );
    let codes = format!(
        "fit warnings F1–F{} (see friction.meta.json)",
        warnings.len()
    );
    assert!(!notes.is_empty());
    for n in &notes {
        assert!(n.ends_with(&codes), "{n:?} does not point at {codes}");
    }
    // A small export (20 points per isotherm) is untouched.
    std::fs::write(dir.join("dense.csv"), rubber_csv(&[0.0, 20.0, 40.0], 20)).unwrap();
    let o = run_main(&dir, &out, &["--force", "--no-bands"]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let fit: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("fits/dense.json")).unwrap())
            .unwrap();
    assert_eq!(fit["master_curve"].as_array().unwrap().len(), 60);
    assert!(!fit["tts"]["warnings"].to_string().contains("thinned"));
    let (warnings, _) = fit_warnings_and_notes(&csv_path);
    assert!(warnings.iter().all(|l| !l.contains("thinned")));
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&out);
}

/// Issue 15, temperatures: an isotherm at 1e9 °C is refused by every command that reads DMA data
/// (the check is in the read path, crate::dma::plausible), with one error naming the file, the line
/// of its first point and the temperature column: `ingest` on the export, `master` and `fit` on a
/// measurement JSON whose isotherm was edited to 1e9 °C.
#[test]
fn ingest_master_and_fit_refuse_an_isotherm_at_1e9_c_naming_file_line_and_column() {
    let dir = temp_dir("hard-hot-cmds");
    let hot = dir.join("hot.csv");
    // Header on line 1, five rows at 0 °C on lines 2–6: the first 1e9 °C row is line 7.
    std::fs::write(&hot, rubber_csv(&[0.0, 1e9], 5)).unwrap();
    let o = Command::new(bin())
        .arg("ingest")
        .arg(&hot)
        .output()
        .unwrap();
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("hot.csv: line 7, column `temperature`") && err.contains("above 1000 °C"),
        "{err}"
    );
    assert_eq!(err.matches("above 1000 °C").count(), 1, "one error: {err}");
    // A measurement JSON edited by hand: `master` and `fit` refuse it the same way.
    let good = dir.join("good.csv");
    std::fs::write(&good, rubber_csv(&[0.0, 20.0, 40.0], 5)).unwrap();
    let m_json = dir.join("m.json");
    let o = Command::new(bin())
        .arg("ingest")
        .arg(&good)
        .arg("-o")
        .arg(&m_json)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", text(&o.stderr));
    let mut m: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&m_json).unwrap()).unwrap();
    let iso = &mut m["isotherms"][2];
    iso["temp_nominal_c"] = 1e9.into();
    iso["temp_mean_c"] = 1e9.into();
    let first_line = iso["points"][0]["line"].as_u64().unwrap();
    for p in iso["points"].as_array_mut().unwrap() {
        p["temp_c"] = 1e9.into();
    }
    std::fs::write(&m_json, m.to_string()).unwrap();
    for args in [
        vec![
            "master".to_string(),
            m_json.display().to_string(),
            "--tref".into(),
            "20".into(),
        ],
        vec![
            "fit".to_string(),
            m_json.display().to_string(),
            "-o".into(),
            dir.join("f.json").display().to_string(),
        ],
    ] {
        let o = Command::new(bin()).args(&args).output().unwrap();
        let err = text(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{args:?}: {err}");
        assert!(
            err.contains(&format!(
                "good.csv: line {first_line}, column `temperature`"
            )) && err.contains("above 1000 °C"),
            "{args:?}: {err}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 15, plausibility: one storage modulus 1000× too high in the middle of the 20 °C isotherm
/// breaks the Prony fit (out of its bounds, exit 3). The data check names file, line, column and
/// value with the 10³ suggestion, and the fit names the same line and value as the point that breaks
/// it, in the datasheet. Line: header 1, 12 rows at 0 °C (2–13), the 20 °C row k = 6 is line 20.
#[test]
fn a_single_far_off_point_names_its_file_line_and_value() {
    let dir = temp_dir("hard-one-off-in");
    let out = temp_dir("hard-one-off-out");
    let csv = rubber_csv(&[0.0, 20.0, 40.0], 12);
    let mut lines: Vec<String> = csv.lines().map(String::from).collect();
    let cells: Vec<&str> = lines[19].split(',').collect();
    assert_eq!(cells[0], "20");
    let e1: f64 = cells[2].parse().unwrap();
    let bad = format!("{},{},{:.6e},{}", cells[0], cells[1], e1 * 1e3, cells[3]);
    lines[19] = bad;
    std::fs::write(dir.join("bad.csv"), lines.join("\n") + "\n").unwrap();
    let o = run_main(&dir, &out, &[]);
    assert_eq!(o.status.code(), Some(3), "{}", text(&o.stderr));
    let sheet = std::fs::read_to_string(out.join("reports/bad/datasheet.html")).unwrap();
    let value = format!("{:.4e} Pa", e1 * 1e3);
    assert!(
        sheet.contains(&format!("line 20: column `E'`: storage modulus {value}"))
            && sheet.contains("about 10^3 times too high"),
        "the data check"
    );
    assert!(
        sheet.contains(&format!("bad.csv: line 20: storage modulus {value}"))
            && sheet.contains("this one point breaks the fit"),
        "the fit"
    );
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&out);
}

/// Peak resident memory of this process in MB (Linux `VmHWM`; NaN elsewhere).
fn peak_rss_mb() -> f64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse::<f64>().ok())
        })
        .map_or(f64::NAN, |kb| kb / 1024.0)
}

/// Issue 15's large-file figure: a CSV of 1e6 rows in 2 isotherms, ingested (target ≤ 5 s) and
/// fitted (≤ 10 s) in ≤ 1 GB. Prints a table; not timed as a pass/fail test (speed is measured, not
/// asserted): `cargo test --release --test tests -- --ignored large_csv --nocapture`.
#[test]
#[ignore = "a measurement, not a check: run with --ignored --nocapture"]
fn large_csv_ingest_and_fit_timings() {
    use viscoroll::dma::{read_files, IngestOptions};
    let dir = temp_dir("hard-large");
    let path = dir.join("large.csv");
    std::fs::write(&path, rubber_csv(&[0.0, 40.0], 500_000)).unwrap();
    let bytes = std::fs::metadata(&path).unwrap().len();
    let t = std::time::Instant::now();
    let m = read_files(&[&path], &IngestOptions::default()).unwrap();
    let ingest_s = t.elapsed().as_secs_f64();
    let rss_ingest = peak_rss_mb();
    let t = std::time::Instant::now();
    let fit = viscoroll::pipeline::fit_measurement(
        "large",
        &m,
        &viscoroll::pipeline::FitOptions::default(),
    );
    let fit_s = t.elapsed().as_secs_f64();
    eprintln!("| rows | file MB | ingest s | peak MB after ingest | fit s | peak MB | fit |");
    eprintln!(
        "| {} | {:.1} | {ingest_s:.2} | {rss_ingest:.0} | {fit_s:.2} | {:.0} | {} |",
        m.isotherms.iter().map(|i| i.points.len()).sum::<usize>(),
        bytes as f64 / 1e6,
        peak_rss_mb(),
        match &fit {
            Ok(f) => format!("ok, {} Prony terms", f.relaxation.terms.len()),
            Err(e) => format!("error: {e}"),
        }
    );
    let _ = std::fs::remove_dir_all(&dir);
}
