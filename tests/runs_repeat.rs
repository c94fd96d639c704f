//! A job folder used the way the README shows (issue 31, items 4 and 7): `viscoroll run .` in a
//! folder of compound sub-folders and a `scenes.toml`, twice; `rank` on its fit files from the same
//! folder; the contact tolerance set per scene and by `--tol`, each point's solver error estimate
//! in friction.csv.
//!
//! The compound is the shipped TRIOS LSR sweep (shear data, one export) on one half-space scene
//! with few temperatures, so the job stays short.

use crate::support::{bin, col, data_dir, table, temp_dir};
use std::path::Path;
use std::process::{Command, Output};

/// A job folder: `lsr/` with the TRIOS export, and `scenes.toml` with one scene (`extra` lines added
/// to it).
fn job_folder(tag: &str, extra: &str) -> std::path::PathBuf {
    let dir = temp_dir(tag);
    std::fs::create_dir_all(dir.join("lsr")).unwrap();
    std::fs::copy(
        data_dir().join("trios-aresg2-lims/frequency_sweep_tts.txt"),
        dir.join("lsr/frequency_sweep_tts.txt"),
    )
    .unwrap();
    std::fs::write(
        dir.join("scenes.toml"),
        format!(
            "[[scene]]\nname = \"wheel\"\nroll_radius_mm = 100.0\nload_n_per_m = 5000.0\n\
             speed_m_s = 2.0\ntemps_c = [0.0, 20.0, 40.0]\n{extra}"
        ),
    )
    .unwrap();
    dir
}

/// `viscoroll ARGS…` run in `dir`.
fn in_dir(dir: &Path, args: &[&str]) -> Output {
    Command::new(bin())
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap()
}

fn text(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The numbers of a friction.csv column (empty cells as NaN).
fn numbers(path: &Path, name: &str) -> Vec<f64> {
    let (h, rows) = table(path);
    let k = col(&h, name);
    rows.iter()
        .map(|r| r[k].parse().unwrap_or(f64::NAN))
        .collect()
}

#[test]
fn a_second_run_in_the_same_folder_reads_only_its_inputs_and_rank_takes_its_scenes() {
    let dir = job_folder("repeat", "");
    let first = in_dir(&dir, &["run", "."]);
    let log = text(&first);
    assert!(first.status.success(), "{log}");
    // plain English, and the scenes file is named as the scenes used, not skipped as an export
    assert!(log.contains("lsr: new fit, 1 scene,"), "{log}");
    assert!(log.contains("1 compound (0 failed"), "{log}");
    assert!(
        !log.contains("fitted fit") && !log.contains("1 scenes"),
        "{log}"
    );
    assert!(log.contains("scenes from ./scenes.toml"), "{log}");
    assert!(!log.contains("not a DMA export"), "{log}");

    let second = in_dir(&dir, &["run", "."]);
    let log2 = text(&second);
    assert!(second.status.success(), "the second run failed: {log2}");
    assert!(log2.contains("lsr: reused fit, 1 scene,"), "{log2}");
    // the first run's fits/ and reports/ are not compounds, nor noted as skipped
    assert!(!log2.contains("skipped"), "{log2}");
    let (_, ranking) = table(&dir.join("reports/ranking.csv"));
    assert_eq!(ranking.len(), 1, "one compound ranked in one scene");

    // rank from the same folder: ./scenes.toml, with the bands `run` gave
    let o = in_dir(&dir, &["rank", "fits/lsr.json", "--json"]);
    assert!(o.status.success(), "{}", text(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["scene"]["name"], "wheel");
    assert!(v["scenes_from"].as_str().unwrap().contains("scenes.toml"));
    let r = &v["ranking"][0];
    let band = &r["band"];
    assert!(!band.is_null(), "rank gave no band: {r}");
    // the same band of the mean as the run's ranking.csv (one computation: to the last digits)
    let csv = dir.join("reports/ranking.csv");
    for (key, column) in [
        ("p05", "mean_friction_p05"),
        ("p50", "mean_friction_p50"),
        ("p95", "mean_friction_p95"),
    ] {
        let (want, got) = (numbers(&csv, column)[0], band[key].as_f64().unwrap());
        assert!(
            (want - got).abs() <= 1e-12 * want.abs(),
            "{key}: rank {got}, run {want}"
        );
    }
    for p in r["friction"].as_array().unwrap() {
        assert!(!p["band"].is_null(), "a point without its band: {p}");
    }
    // --no-bands: none
    let o = in_dir(&dir, &["rank", "fits/lsr.json", "--json", "--no-bands"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v["ranking"][0]["band"].is_null());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_tolerance_is_set_per_scene_or_by_tol_and_each_point_gives_its_error_estimate() {
    // a loose scene tolerance, then a tight one from --tol (the scene sets none)
    let loose = job_folder("tol-loose", "tol = 1e-2\n");
    let o = in_dir(&loose, &["run", ".", "--no-bands", "--tol", "1e-9"]);
    assert!(o.status.success(), "{}", text(&o));
    let tight = job_folder("tol-tight", "");
    let o = in_dir(&tight, &["run", ".", "--no-bands", "--tol", "1e-9"]);
    assert!(o.status.success(), "{}", text(&o));
    let csv = |d: &Path| d.join("reports/lsr/friction.csv");
    let (f_loose, e_loose) = (
        numbers(&csv(&loose), "friction"),
        numbers(&csv(&loose), "error_estimate"),
    );
    let (f_tight, e_tight) = (
        numbers(&csv(&tight), "friction"),
        numbers(&csv(&tight), "error_estimate"),
    );
    assert_eq!(f_loose.len(), 3);
    for i in 0..3 {
        // each estimate within its own tolerance (the scene's wins over --tol)
        assert!(e_tight[i] <= 1e-9, "tight estimate {}", e_tight[i]);
        assert!(e_loose[i] <= 1e-2, "loose estimate {}", e_loose[i]);
        // and the loose answer's true error (against the tight one) within its estimate plus the
        // tight one's
        let err = (f_loose[i] - f_tight[i]).abs() / f_tight[i];
        assert!(
            err <= e_loose[i] + e_tight[i],
            "point {i}: error {err:e} beyond the estimate {:e}",
            e_loose[i]
        );
    }
    // out of range: refused, naming the setting
    let o = in_dir(&tight, &["run", ".", "--tol", "0.5"]);
    assert!(
        !o.status.success() && text(&o).contains("--tol"),
        "{}",
        text(&o)
    );
    let bad = job_folder("tol-bad", "tol = 0.5\n");
    let o = in_dir(&bad, &["run", "."]);
    assert!(
        !o.status.success() && text(&o).contains("tol"),
        "{}",
        text(&o)
    );
    for d in [loose, tight, bad] {
        let _ = std::fs::remove_dir_all(&d);
    }
}
