//! The hostile-input suite of issue 28: one seeded, replayable generator per family — symlink plants
//! in the output folder, lock-file states, tampered fit files, work-budget edges, special files,
//! broken tables, hostile strings — each drawing its cases from the test's seed (tests/seed.rs:
//! `VISCOROLL_SEED=N` replays a run). The CI share draws a few cases per family; the `--ignored`
//! tests draw many more and run inputs at the work budget's limits.

use super::pipeline_hardening::rubber_csv;
use super::seed::{scene_with, seed, Rng};
use super::support::{bin, data_dir, run_main, stderr, temp_dir, viscoroll};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// One scene, two temperatures, no maps: the cheapest main job.
const SCENES: &str = "[[scene]]\nname = \"s\"\nroll_radius_mm = 100.0\nload_n_per_m = 2000.0\nspeed_m_s = 1.0\ntemps_c = [0.0, 20.0]\n";

/// An input folder with one compound `a` and the cheap scenes.
fn input_folder(tag: &str) -> PathBuf {
    let dir = temp_dir(tag);
    std::fs::write(dir.join("a.csv"), rubber_csv(&[0.0, 20.0, 40.0], 12)).unwrap();
    std::fs::write(dir.join("scenes.toml"), SCENES).unwrap();
    dir
}

fn quick_run(dir: &Path, out: &Path, extra: &[&str]) -> std::process::Output {
    let mut args = vec!["--no-bands"];
    args.extend_from_slice(extra);
    run_main(dir, out, &args)
}

/// Every regular file below `dir` with its bytes (symlinks not followed).
fn snapshot(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut v = Vec::new();
    let Ok(rd) = std::fs::read_dir(dir) else {
        return v;
    };
    for e in rd.flatten() {
        let t = e.file_type().unwrap();
        if t.is_dir() {
            v.extend(snapshot(&e.path()));
        } else if t.is_file() {
            v.push((e.path(), std::fs::read(e.path()).unwrap()));
        }
    }
    v.sort();
    v
}

/// Symlink plants: a link at a final name (ranking.csv, index.html, a fit file), at a guessable
/// temporary name, or in place of a sub-folder (fits/, reports/, reports/a/). Nothing outside the
/// output folder changes; a symlinked sub-folder fails the run (or its compound) naming the link.
fn symlink_plants(cases: usize, rng: &mut Rng) {
    let dir = input_folder("hostile-plant-in");
    for case in 0..cases {
        let out = temp_dir("hostile-plant-out");
        let outside = temp_dir("hostile-plant-outside");
        std::fs::write(outside.join("victim.txt"), b"precious").unwrap();
        let before = snapshot(&outside);
        let plant = *rng.pick(&[
            "reports/ranking.csv",
            "reports/index.html",
            "fits/a.json",
            "reports/a/friction.csv",
            "fits/.a.tmp-1-0.json",
            "fits",
            "reports",
            "reports/a",
        ]);
        let link = out.join(plant);
        std::fs::create_dir_all(link.parent().unwrap()).unwrap();
        let is_folder = !plant.contains('.');
        let target = if is_folder {
            outside.clone()
        } else {
            outside.join("victim.txt")
        };
        std::os::unix::fs::symlink(&target, &link).unwrap();
        let o = quick_run(&dir, &out, &[]);
        let err = stderr(&o);
        assert_eq!(snapshot(&outside), before, "case {case} ({plant}): {err}");
        if is_folder {
            assert_ne!(o.status.code(), Some(0), "case {case} ({plant}): {err}");
            assert!(
                err.contains("symbolic link"),
                "case {case} ({plant}): {err}"
            );
        } else {
            assert!(
                o.status.code().is_some_and(|c| c == 0 || c == 3),
                "case {case} ({plant}): {err}"
            );
        }
        let _ = std::fs::remove_dir_all(&out);
        let _ = std::fs::remove_dir_all(&outside);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn symlinks_planted_in_the_output_folder_are_never_followed() {
    let mut rng = Rng(seed("hostile symlink plants"));
    symlink_plants(3, &mut rng);
}

/// Lock states: a lock file that is empty, garbage, a negative or foreign pid, or binary never
/// blocks (`--wait 0` would fail at once if it did); a lock held by a live process makes a run say
/// at once who holds it and give up after `--wait`.
#[test]
fn a_lock_file_never_blocks_and_a_held_lock_is_reported_at_once() {
    let mut rng = Rng(seed("hostile lock states"));
    let dir = input_folder("hostile-lock-in");
    let out = temp_dir("hostile-lock-out");
    let states: [&[u8]; 7] = [
        b"",
        b"hello",
        b"-5",
        b"1",
        b"4294967",
        b"\0\xff\xfe",
        b"99999999999",
    ];
    for _ in 0..2 {
        let content = *rng.pick(&states);
        std::fs::write(out.join(".viscoroll.lock"), content).unwrap();
        let o = quick_run(&dir, &out, &["--wait", "0"]);
        assert!(
            o.status.code().is_some_and(|c| c == 0 || c == 3),
            "{content:?}: {}",
            stderr(&o)
        );
    }
    // Held by this test process: the run waits 1 s, naming our pid, then fails.
    let held =
        viscoroll::fsutil::DirLock::acquire(&out, std::time::Duration::ZERO, &|_| {}).unwrap();
    let o = quick_run(&dir, &out, &["--wait", "1"]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    let me = format!("process {}", std::process::id());
    assert!(
        err.contains("waiting up to 1 s") && err.contains(&me),
        "{err}"
    );
    drop(held);
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&out);
}

/// Ways to tamper with a fit file, each applied to its JSON. The first two and the last are then
/// resealed with a valid content hash ([`reseal`]), so only the validation can catch them.
fn tamper(fit: &mut serde_json::Value, how: usize) -> &'static str {
    match how {
        0 => {
            fit["shift_law"] = serde_json::json!({"law": "table", "t_ref_c": 20.0, "points": []});
            "empty shift table"
        }
        1 => {
            fit["relaxation"]["terms"][0]["modulus_pa"] = serde_json::json!(-1e6);
            "negative modulus"
        }
        2 => {
            fit.as_object_mut().unwrap().remove("content_sha256");
            "no content hash"
        }
        3 => {
            let t = fit["relaxation"]["terms"][0]["tau_s"].as_f64().unwrap();
            fit["relaxation"]["terms"][0]["tau_s"] = serde_json::json!(t * 1.0001);
            "one number changed"
        }
        _ => {
            fit["relaxation"]["kind"] =
                serde_json::json!(if fit["relaxation"]["kind"] == "tensile" {
                    "shear"
                } else {
                    "tensile"
                });
            "inconsistent kinds"
        }
    }
}

/// A fit JSON with a content hash that matches its (tampered) content, as a careful forger would
/// write it.
fn reseal(fit: serde_json::Value) -> serde_json::Value {
    let mut f: viscoroll::results::CompoundFit = serde_json::from_value(fit).unwrap();
    f.content_sha256 = Some(f.content_hash().unwrap());
    serde_json::to_value(&f).unwrap()
}

/// Tampered fits: `roll` and `export` refuse them with a clear error; `run` fits again, says so
/// and replaces the file.
#[test]
fn a_tampered_fit_is_refused_by_roll_and_export_and_refitted_by_run() {
    let mut rng = Rng(seed("hostile tampered fits"));
    let dir = input_folder("hostile-fit-in");
    let out = temp_dir("hostile-fit-out");
    let o = quick_run(&dir, &out, &[]);
    assert!(
        o.status.code().is_some_and(|c| c == 0 || c == 3),
        "{}",
        stderr(&o)
    );
    let path = out.join("fits/a.json");
    let good: serde_json::Value = serde_json::from_slice(&std::fs::read(&path).unwrap()).unwrap();
    assert!(good["content_sha256"].is_string());
    let p = path.display().to_string();
    for _ in 0..2 {
        let mut fit = good.clone();
        let how = rng.below(5);
        let what = tamper(&mut fit, how);
        if matches!(how, 0 | 1 | 4) {
            fit = reseal(fit);
        }
        std::fs::write(&path, serde_json::to_string_pretty(&fit).unwrap()).unwrap();
        let roll = viscoroll(&[
            "roll",
            &p,
            "--temp-c",
            "20",
            "--radius-mm",
            "100",
            "--load-n-per-m",
            "2000",
            "--speed-m-s",
            "1",
        ]);
        assert_eq!(roll.status.code(), Some(1), "{what}: {}", stderr(&roll));
        assert!(
            stderr(&roll).contains("not a trustworthy fit file"),
            "{what}: {}",
            stderr(&roll)
        );
        let export = viscoroll(&["export", &p, "--to", "abaqus"]);
        assert_eq!(export.status.code(), Some(1), "{what}: {}", stderr(&export));
        assert!(
            stderr(&export).contains("not a trustworthy fit file"),
            "{what}"
        );
        let o = quick_run(&dir, &out, &["--json"]);
        let summary: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        let a = &summary["compounds"][0];
        let summary = if a.is_null() {
            &summary["detail"]["compounds"][0]
        } else {
            a
        };
        assert_eq!(summary["fit_action"], "refitted", "{what}: {}", stderr(&o));
        assert!(
            summary["warnings"]
                .to_string()
                .contains("failed its content hash"),
            "{what}"
        );
        // the file is whole again: roll takes it
        let roll = viscoroll(&[
            "roll",
            &p,
            "--temp-c",
            "20",
            "--radius-mm",
            "100",
            "--load-n-per-m",
            "2000",
            "--speed-m-s",
            "1",
        ]);
        assert_eq!(roll.status.code(), Some(0), "{what}: {}", stderr(&roll));
    }
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn sizes_at_the_limits_are_accepted_and_beyond_them_refused_naming_key_and_limit() {
    let mut rng = Rng(seed("hostile budget edges"));
    // the command line: contact --n beyond the limit, temperatures below absolute zero
    // `contact --n` beyond the work budget (src/limits.rs CONTACT_N_MAX, 2000 intervals)
    let n = (2001 + rng.below(20_000)).to_string();
    let o = viscoroll(&["contact", "--creep", "1:1", "--lambda", "1", "--n", &n]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("2000"), "{}", stderr(&o));
    let t = format!("{}", -273.16 - rng.below(10_000) as f64);
    let o = viscoroll(&[
        "roll",
        "x.json",
        "--temp-c",
        &t,
        "--radius-mm",
        "100",
        "--load-n-per-m",
        "2000",
        "--speed-m-s",
        "1",
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("-273.15"), "{}", stderr(&o));
}

/// Wait for a child at most `secs` seconds (kill it and fail if it hangs).
fn wait_bounded(mut child: std::process::Child, secs: u64, what: &str) -> std::process::Output {
    let start = std::time::Instant::now();
    loop {
        if child.try_wait().unwrap().is_some() {
            return child.wait_with_output().unwrap();
        }
        if start.elapsed().as_secs() > secs {
            let _ = child.kill();
            panic!("{what} hung for {secs} s");
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
}

/// Special files: a FIFO, a symlink to /dev/zero, a socket-less device name, a folder named
/// `*.csv` — each fails its own compound at once; the good compound gets its report.
#[test]
fn fifos_devices_and_odd_entries_fail_alone_without_blocking() {
    let mut rng = Rng(seed("hostile special files"));
    let dir = input_folder("hostile-special-in");
    let out = temp_dir("hostile-special-out");
    let kind = rng.below(3);
    let odd = dir.join("odd.csv");
    match kind {
        0 => assert!(Command::new("mkfifo").arg(&odd).status().unwrap().success()),
        1 => std::os::unix::fs::symlink("/dev/zero", &odd).unwrap(),
        _ => std::os::unix::fs::symlink("/dev/null", &odd).unwrap(),
    }
    let child = Command::new(bin())
        .args(["run", "--no-bands", "--out"])
        .arg(&out)
        .arg(&dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let o = wait_bounded(child, 120, "run over a special file");
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    let line = err
        .lines()
        .find(|l| l.starts_with("odd: FAILED"))
        .unwrap_or_else(|| panic!("{err}"));
    assert!(line.contains("only regular files are read"), "{line}");
    assert!(out.join("reports/a/datasheet.html").is_file(), "{err}");
    // ingest of the same file: refused at once
    let child = Command::new(bin())
        .arg("ingest")
        .arg(&odd)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let o = wait_bounded(child, 60, "ingest of a special file");
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&out);
}

/// Broken tables: a stray text or NUL line anywhere inside the table loses no row (a warning names
/// its line); CR-only line ends and UTF-16BE read as the plain file; a second storage column is an
/// error naming both, unless `--columns` picks one.
fn broken_tables(cases: usize, rng: &mut Rng) {
    use viscoroll::dma::{read_bytes, IngestOptions};
    let plain = rubber_csv(&[0.0, 20.0, 40.0], 10);
    let read = |bytes: Vec<u8>, opts: &IngestOptions| read_bytes(&[("t.csv".into(), bytes)], opts);
    let opts = IngestOptions::default();
    let base = read(plain.clone().into_bytes(), &opts).unwrap();
    let points =
        |m: &viscoroll::Measurement| m.isotherms.iter().map(|i| i.points.len()).sum::<usize>();
    let n = points(&base);
    let lines: Vec<&str> = plain.lines().collect();
    for case in 0..cases {
        let stray = *rng.pick(&["garbage", "\0\0\0\0", "-- note --", "#", "x;y", "nan nan"]);
        let at = 2 + rng.below(lines.len() - 2); // below the header and the first data row
        let mut v: Vec<&str> = lines.clone();
        v.insert(at, stray);
        let text = v.join("\n");
        let m = read(text.into_bytes(), &opts)
            .unwrap_or_else(|e| panic!("case {case} {stray:?} at {at}: {e}"));
        assert_eq!(points(&m), n, "case {case}: {stray:?} at line {}", at + 1);
        let named = format!("line {}", at + 1);
        assert!(
            m.warnings.iter().any(|w| w.contains(&named)),
            "case {case}: {:?}",
            m.warnings
        );
    }
    // every text format: the shipped TRIOS LIMS, DMA-suite and pyvisco exports, and TRIOS text and
    // Proteus written by testdata; the stray goes just above a random data row (not the first)
    let mut texts: Vec<(String, Vec<u8>)> = [
        "trios-aresg2-lims/frequency_sweep_tts.txt",
        "dmasuite-tensile/T20.txt",
        "pyvisco-ems-ca/freq_user_raw.csv",
    ]
    .iter()
    .map(|f| (f.to_string(), std::fs::read(data_dir().join(f)).unwrap()))
    .collect();
    let compound = &viscoroll::testdata::realistic_compounds()[0];
    let protocol = viscoroll::testdata::DmaProtocol {
        temps_c: vec![0.0, 20.0, 40.0],
        ..Default::default()
    };
    let rows = viscoroll::testdata::dma_rows(compound, &protocol);
    for f in [
        viscoroll::testdata::ExportFormat::TriosText,
        viscoroll::testdata::ExportFormat::Proteus,
    ] {
        texts.push((format!("{f:?}.{}", f.extension()), f.write(&rows)));
    }
    for (name, bytes) in texts {
        let base = read_bytes(&[(name.clone(), bytes.clone())], &opts).unwrap();
        let n = points(&base);
        let data_lines: Vec<usize> = base
            .isotherms
            .iter()
            .flat_map(|i| i.points.iter().map(|p| p.line))
            .filter(|&l| l > 1)
            .collect();
        let at = data_lines[1 + rng.below(data_lines.len() - 1)]; // 1-based line of a data row
        let stray = *rng.pick(&["garbage", "\0\0\0\0", "-- note --", "x;y", "nan nan"]);
        // the files may end lines with CR LF (Proteus): insert with the file's own ending
        let text = String::from_utf8_lossy(&bytes).into_owned();
        let eol = if text.contains("\r\n") { "\r\n" } else { "\n" };
        let mut v: Vec<&str> = text.split(eol).collect();
        v.insert(at - 1, stray);
        let broken: Vec<u8> = if name.starts_with("Proteus") {
            // cp1252 as written: the inserted line is ASCII, so bytes are rebuilt from the original
            let mut out = Vec::new();
            let mut line = 0;
            for chunk in bytes.split_inclusive(|&b| b == b'\n') {
                line += 1;
                if line == at {
                    out.extend_from_slice(stray.as_bytes());
                    out.extend_from_slice(eol.as_bytes());
                }
                out.extend_from_slice(chunk);
            }
            out
        } else {
            v.join(eol).into_bytes()
        };
        let m = read_bytes(&[(name.clone(), broken)], &opts)
            .unwrap_or_else(|e| panic!("{name}: {stray:?} at line {at}: {e}"));
        assert_eq!(points(&m), n, "{name}: {stray:?} at line {at}");
        let named = format!("line {at}");
        assert!(
            m.warnings.iter().any(|w| w.contains(&named)),
            "{name}: {stray:?} at line {at}: {:?}",
            m.warnings
        );
    }
    let cr = plain.replace('\n', "\r");
    assert_eq!(points(&read(cr.into_bytes(), &opts).unwrap()), n);
    let be: Vec<u8> = plain.encode_utf16().flat_map(|u| u.to_be_bytes()).collect();
    assert_eq!(points(&read(be, &opts).unwrap()), n);
    // a second E' column at ten times the values
    let dup: String = plain
        .lines()
        .enumerate()
        .map(|(i, l)| {
            let f: Vec<&str> = l.split(',').collect();
            let extra = if i == 0 {
                "E' [Pa]".to_string()
            } else {
                format!("{:e}", f[2].parse::<f64>().unwrap() * 10.0)
            };
            format!("{l},{extra}\n")
        })
        .collect();
    let e = read(dup.clone().into_bytes(), &opts)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("two columns mean the storage modulus")
            && e.contains("column 3")
            && e.contains("column 5"),
        "{e}"
    );
}

#[test]
fn tables_lose_no_row_silently() {
    let mut rng = Rng(seed("hostile broken tables"));
    broken_tables(8, &mut rng);
}

/// Hostile strings (the CSV cells: src/tests/hostile_budget.rs): a long scene name is refused before any work; stdout on a full
/// device ends with exit 1, no panic.
#[test]
fn hostile_strings_and_full_devices_are_handled() {
    // a 5000-character scene name: refused at input, the reason whole and short
    let dir = input_folder("hostile-name-in");
    let out = temp_dir("hostile-name-out");
    std::fs::write(
        dir.join("scenes.toml"),
        scene_with(&"n".repeat(5000), 2, 0, 0, 0.0),
    )
    .unwrap();
    let o = quick_run(&dir, &out, &[]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("5000 characters") && err.contains("64"),
        "{err}"
    );
    assert!(
        !out.join("fits").exists(),
        "work was done before the name was checked"
    );
    // stdout on a full device
    if Path::new("/dev/full").exists() {
        let full = std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap();
        let o = Command::new(bin())
            .args(["contact", "--creep", "1:1", "--lambda", "1", "--json"])
            .stdout(full)
            .output()
            .unwrap();
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&out);
}

/// The longer run: many more cases of every family.
#[test]
#[ignore = "hostile-input suite, long run (several minutes): cargo test --test tests hostile -- --ignored"]
fn hostile_long_run() {
    let mut rng = Rng(seed("hostile long run"));
    symlink_plants(16, &mut rng);
    broken_tables(300, &mut rng);
}
