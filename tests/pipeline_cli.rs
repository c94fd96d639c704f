//! `viscoroll run` on the shipped data/ (three compounds) into a temp folder, and `rank`/`roll` on its
//! fit files: files exist, friction is finite and positive, contact lengths lie between the glassy
//! and the relaxed Hertz lengths (an independent closed form), fits are reused, a different fit is
//! not overwritten without --force, and a broken compound fails alone.

use crate::support::{bin, data_dir, run_main, temp_dir};
use std::path::{Path, PathBuf};
use std::process::Command;

const COMPOUNDS: [&str; 3] = ["ems-ca", "dmasuite-tensile", "trios-aresg2-lims"];

/// Rows of reports/NAME/friction.csv: (scene, temp_c, friction, contact_length_mm).
fn friction_rows(path: &Path) -> Vec<(String, f64, f64, f64)> {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with("scene,"))
        .map(|l| {
            let c: Vec<&str> = l.split(',').collect();
            (
                c[0].to_string(),
                c[1].parse().unwrap(),
                c[2].parse().unwrap(),
                c[4].parse().unwrap(),
            )
        })
        .collect()
}

/// Hertz contact length 2a of a rigid cylinder on a half-space of modulus E (plane strain):
/// a² = 4NR(1−ν²)/(πE) (Johnson, Contact Mechanics, eq. 4.43), in mm.
fn hertz_length_mm(radius_mm: f64, load_n_per_m: f64, e_pa: f64, nu: f64) -> f64 {
    let a2 =
        4.0 * load_n_per_m * radius_mm * 1e-3 * (1.0 - nu * nu) / (std::f64::consts::PI * e_pa);
    2.0 * a2.sqrt() * 1e3
}

#[test]
fn run_on_shipped_data_then_rank_roll_and_reuse() {
    let out = temp_dir("pipe-main");
    let o = run_main(&data_dir(), &out, &["--json"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    let summary: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(summary["compounds"].as_array().unwrap().len(), 3);

    let scenes: toml::Value =
        toml::from_str(&std::fs::read_to_string(data_dir().join("scenes.toml")).unwrap()).unwrap();
    let scenes = scenes["scene"].as_array().unwrap();
    for name in COMPOUNDS {
        let fit_path = out.join("fits").join(format!("{name}.json"));
        let fit: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&fit_path).unwrap()).unwrap();
        assert!(
            fit["creep"]["terms"]
                .as_array()
                .is_some_and(|t| !t.is_empty()),
            "{name}"
        );
        let rep = out.join("reports").join(name);
        let html = std::fs::read_to_string(rep.join("datasheet.html")).unwrap();
        // Inline SVG plots (isotherms, master, shifts, friction) and the three FEA cards.
        assert!(html.matches("<svg").count() >= 4, "{name}");
        for needle in [
            "*VISCOELASTIC, TIME=PRONY",
            "TB,PRONY",
            "*MAT_GENERAL_VISCOELASTIC",
            "tan δ peak",
            "sha256",
        ] {
            assert!(
                html.to_lowercase().contains(&needle.to_lowercase()),
                "{name}: {needle}"
            );
        }
        for f in ["isotherms.png", "master.png", "friction.svg"] {
            assert!(rep.join(f).is_file(), "{name}: {f}");
        }
        // Friction maps against speed and load: every listed point solved, finite and positive.
        let map = std::fs::read_to_string(rep.join("friction_map.csv")).unwrap();
        let map_rows: Vec<f64> = map
            .lines()
            .filter(|l| !l.starts_with("scene,"))
            .map(|l| l.rsplit(',').next().unwrap().parse().unwrap())
            .collect();
        let expected_map: usize = scenes
            .iter()
            .map(|s| {
                let n = |k: &str| s.get(k).and_then(|v| v.as_array()).map_or(0, |a| a.len());
                n("map_temps_c") * (n("map_speeds_m_s") + n("map_loads_n_per_m"))
            })
            .sum();
        assert!(expected_map > 0);
        assert_eq!(map_rows.len(), expected_map, "{name}");
        assert!(
            map_rows.iter().all(|f| f.is_finite() && *f > 0.0),
            "{name}: {map_rows:?}"
        );
        // PNG twins: every SVG chart has a PNG beside it, a valid PNG (signature, IHDR first, the
        // plot size 900 × 640 of report::plots::PLOT_SIZE), linked from the datasheet.
        let svgs: Vec<String> = std::fs::read_dir(&rep)
            .unwrap()
            .filter_map(|e| e.ok()?.file_name().into_string().ok())
            .filter(|f| f.ends_with(".svg"))
            .collect();
        // 10 charts before covers; the covered conveyor-idler has no speed × load map (its maps are
        // solved point by point, without the 2-D grid), so 9 now.
        assert!(svgs.len() >= 9, "{name}: {svgs:?}");
        for svg in &svgs {
            let png = svg.replace(".svg", ".png");
            let bytes = std::fs::read(rep.join(&png)).unwrap_or_default();
            assert!(
                bytes.len() > 33
                    && bytes[..8] == *b"\x89PNG\r\n\x1a\n"
                    && &bytes[12..16] == b"IHDR",
                "{name}: {png} is not a PNG"
            );
            let dim = |k: usize| u32::from_be_bytes(bytes[k..k + 4].try_into().unwrap());
            assert_eq!((dim(16), dim(20)), (900, 640), "{name}: {png}");
            assert!(
                html.contains(&format!("href=\"{png}\"")),
                "{name}: link to {png}"
            );
        }
        // The 2-D map: 30 × 30 speeds × loads per map temperature, every value finite and positive.
        let grid = std::fs::read_to_string(rep.join("friction_map_2d.csv")).unwrap();
        let grid_rows: Vec<Vec<f64>> = grid
            .lines()
            .filter(|l| !l.starts_with("scene,"))
            .map(|l| l.split(',').skip(1).map(|v| v.parse().unwrap()).collect())
            .collect();
        // Every scene with maps has the grid (a cover's from the 2-D interpolant of contact::maps).
        let expected_grid: usize = scenes
            .iter()
            .map(|s| {
                s.get("map_temps_c")
                    .and_then(|v| v.as_array())
                    .map_or(0, |a| a.len())
                    * 900
            })
            .sum();
        assert_eq!(grid_rows.len(), expected_grid, "{name}");
        assert!(
            grid_rows
                .iter()
                .all(|r| r[3].is_finite() && r[3] > 0.0 && r[4] > 0.0),
            "{name}: a 2-D map value is not finite and positive"
        );
        for s in scenes.iter().filter(|s| s.get("map_temps_c").is_some()) {
            assert!(rep
                .join(format!(
                    "friction_{}_map2d.png",
                    s["name"].as_str().unwrap()
                ))
                .is_file());
        }
        // Glassy and relaxed moduli of the fitted relaxation spectrum.
        let e_inf = fit["relaxation"]["modulus_inf_pa"].as_f64().unwrap();
        let e0 = e_inf
            + fit["relaxation"]["terms"]
                .as_array()
                .unwrap()
                .iter()
                .map(|t| t["modulus_pa"].as_f64().unwrap())
                .sum::<f64>();
        let kind_factor = if fit["relaxation"]["kind"] == "shear" {
            3.0
        } else {
            1.0
        }; // E = 2(1+ν)G, ν = 0.5
        let rows = friction_rows(&rep.join("friction.csv"));
        let expected_rows: usize = scenes
            .iter()
            .map(|s| s["temps_c"].as_array().unwrap().len())
            .sum();
        assert_eq!(rows.len(), expected_rows, "{name}");
        for (scene, t, f, l) in &rows {
            assert!(
                f.is_finite() && *f > 0.0,
                "{name} {scene} {t} °C: friction {f}"
            );
            let s = scenes
                .iter()
                .find(|s| s["name"].as_str() == Some(scene))
                .unwrap();
            let (r, n) = (
                s["roll_radius_mm"].as_float().unwrap(),
                s["load_n_per_m"].as_float().unwrap(),
            );
            let lg = hertz_length_mm(r, n, e0 * kind_factor, 0.5);
            let lr = hertz_length_mm(r, n, e_inf * kind_factor, 0.5);
            // The viscoelastic contact is stiffer than the relaxed and softer than the glassy
            // half-space; 1 % slack for the thesis scheme's first-order error at n = 200 (h = λ/200).
            assert!(
                *l >= lg * 0.99 && *l <= lr * 1.01,
                "{name} {scene} {t}: {lg} <= {l} <= {lr}"
            );
        }
    }
    // In a real browser (only where Chromium is installed; CI does not need it): screenshots of
    // the EMS-CA datasheet and the index, no console message, the first screen in the DOM.
    crate::report_browser::check_pages(&out, "ems-ca");
    // The ranking lists every compound once per scene, in increasing mean friction.
    let ranking = std::fs::read_to_string(out.join("reports/ranking.csv")).unwrap();
    for s in scenes {
        let sname = s["name"].as_str().unwrap();
        let rows: Vec<Vec<&str>> = ranking
            .lines()
            .filter(|l| l.starts_with(&format!("{sname},")))
            .map(|l| l.split(',').collect())
            .collect();
        let mut names: Vec<&str> = rows.iter().map(|r| r[2]).collect();
        let means: Vec<f64> = rows.iter().map(|r| r[3].parse().unwrap()).collect();
        assert!(means.windows(2).all(|w| w[0] <= w[1]), "{means:?}");
        names.sort();
        let mut want = COMPOUNDS.to_vec();
        want.sort();
        assert_eq!(names, want);
    }
    let index = std::fs::read_to_string(out.join("reports/index.html")).unwrap();
    assert!(COMPOUNDS
        .iter()
        .all(|c| index.contains(&format!("{c}/datasheet.html"))));

    // `roll FIT --temp-c` is the same computation as the report's row (same solver, same shift).
    let csv = friction_rows(&out.join("reports/ems-ca/friction.csv"));
    let (scene, t, f, _) = &csv[4];
    let s = scenes
        .iter()
        .find(|s| s["name"].as_str() == Some(scene))
        .unwrap();
    // A covered scene: the same body choice at the main job's cover tolerance (COVER_TOL = 1e−3).
    let cover: Vec<String> = match s.get("cover_thickness_mm").and_then(|v| v.as_float()) {
        Some(h) => vec![
            "--cover-mm".into(),
            h.to_string(),
            "--tol".into(),
            "1e-3".into(),
        ],
        None => vec![],
    };
    let o = Command::new(bin())
        .arg("roll")
        .arg(out.join("fits/ems-ca.json"))
        .args(["--temp-c", &t.to_string(), "--json"])
        .args(&cover)
        .args([
            "--radius-mm",
            &s["roll_radius_mm"].as_float().unwrap().to_string(),
        ])
        .args([
            "--load-n-per-m",
            &s["load_n_per_m"].as_float().unwrap().to_string(),
        ])
        .args([
            "--speed-m-s",
            &s["speed_m_s"].as_float().unwrap().to_string(),
        ])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    // The CSV prints the shortest round-trip form ({:e}), so equality is exact.
    assert_eq!(v["friction"].as_f64().unwrap(), *f);
    assert_eq!(v["extrapolated"], false);
    // Below the lowest measured temperature (EMS-CA: −50 °C) the shift is flagged as extrapolated.
    let roll = |file: &Path, temp: Option<&str>| {
        let mut c = Command::new(bin());
        c.arg("roll").arg(file);
        if let Some(t) = temp {
            c.args(["--temp-c", t]);
        }
        c.args([
            "--radius-mm",
            "66.5",
            "--load-n-per-m",
            "10000",
            "--speed-m-s",
            "4",
            "--json",
        ])
        .output()
        .unwrap()
    };
    let o = roll(&out.join("fits/ems-ca.json"), Some("-60"));
    assert!(o.status.success());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["extrapolated"], true);
    assert!(v["warnings"][0].as_str().unwrap().contains("extrapolated"));
    // A fit file needs --temp-c; a bare spectrum refuses it (it has no shift law).
    let o = roll(&out.join("fits/ems-ca.json"), None);
    assert!(!o.status.success() && String::from_utf8_lossy(&o.stderr).contains("--temp-c"));
    let o = roll(&data_dir().join("spectra/example_creep.json"), Some("20"));
    assert!(!o.status.success() && String::from_utf8_lossy(&o.stderr).contains("no shift law"));
    assert!(roll(&data_dir().join("spectra/example_creep.json"), None)
        .status
        .success());

    // rank: every compound, ordered, temperature table.
    let fits: Vec<PathBuf> = COMPOUNDS
        .iter()
        .map(|c| out.join("fits").join(format!("{c}.json")))
        .collect();
    let o = Command::new(bin())
        .arg("rank")
        .args(&fits)
        .args(["--scene", "tyre-like", "--json"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let r = v["ranking"].as_array().unwrap();
    assert_eq!(r.len(), 3);
    assert!(r
        .windows(2)
        .all(|w| w[0]["mean_friction"].as_f64() <= w[1]["mean_friction"].as_f64()));
    let o = Command::new(bin())
        .arg("rank")
        .args(&fits)
        .args(["--scene", "nope"])
        .output()
        .unwrap();
    assert!(!o.status.success() && String::from_utf8_lossy(&o.stderr).contains("no such scene"));

    // Re-run: fits reused; a changed fit file is kept unless --force.
    // (the reuse and --force re-runs without bands: they check which fits are made, not the bands)
    let o = run_main(&data_dir(), &out, &["--no-bands"]);
    assert!(o.status.success());
    assert_eq!(
        String::from_utf8_lossy(&o.stderr)
            .matches("reused fit")
            .count(),
        3,
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let p = out.join("fits/ems-ca.json");
    let text = std::fs::read_to_string(&p).unwrap().replacen(
        "\"terms_per_decade\": 2.0",
        "\"terms_per_decade\": 1.5",
        1,
    );
    // sealed again: a fit the tool made with other settings (an unsealed edit is refitted)
    let text = super::support::sealed_fit_json(serde_json::from_str(&text).unwrap());
    std::fs::write(&p, &text).unwrap();
    let o = run_main(&data_dir(), &out, &["--no-bands"]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("--force"));
    assert_eq!(
        std::fs::read_to_string(&p).unwrap(),
        text,
        "the changed fit was overwritten"
    );
    let o = run_main(&data_dir(), &out, &["--force", "--no-bands"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_ne!(std::fs::read_to_string(&p).unwrap(), text);
    std::fs::remove_dir_all(&out).unwrap();
}

#[test]
fn a_broken_compound_fails_alone() {
    let dir = temp_dir("pipe-broken-in");
    let out = temp_dir("pipe-broken-out");
    std::fs::copy(
        data_dir().join("trios-aresg2-lims/frequency_sweep_tts.txt"),
        dir.join("lsr.txt"),
    )
    .unwrap();
    std::fs::write(dir.join("junk.csv"), "this is not,a DMA export\n1,2\n").unwrap();
    std::fs::write(dir.join("notes.md"), "skipped").unwrap();
    let o = run_main(&dir, &out, &["--no-bands"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("notes.md") && err.contains("not a DMA export"),
        "{err}"
    );
    let index = std::fs::read_to_string(out.join("reports/index.html")).unwrap();
    assert!(
        index.contains("Failed compounds") && index.contains("junk"),
        "{index}"
    );
    assert!(out.join("reports/lsr/datasheet.html").is_file());
    std::fs::remove_dir_all(&dir).unwrap();
    std::fs::remove_dir_all(&out).unwrap();
}
