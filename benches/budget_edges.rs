//! Issue 28's goal measured: every input the tool accepts finishes in under 60 s and 2 GB on 2 cores
//! (crate::limits). Each row runs the CLI as a user would, on the shipped EMS-CA export, with one
//! size of the work budget at its limit, bands on: the Prony settings, the scene set's work
//! (`SCENE_WORK_MAX` friction points) on a half-space, with the most map cells, over the most
//! scenes, and on the thinnest cover at the tightest tolerance, and `contact --n` at its limit. Wall time and peak memory come from `/usr/bin/time -v` (GNU time;
//! without it only the wall time is printed); the run's exit code is printed beside them (0 and 3
//! both mean it finished).
//!
//! The limits are crate-internal (`pub(crate)` in src/limits.rs, issue 30's small public API): the
//! bench reads their values from that file's text (`limit`), so the rows stay at the limits the
//! crate enforces without widening the public API.
//!
//! `cargo bench --bench budget_edges` (release), or with the test profile and no release build:
//! `cargo test --bench budget_edges`. `BUDGET_ONLY=word` runs the rows whose name holds the word.

use std::ffi::OsString;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// The value of the constant `name` in src/limits.rs (`pub(crate) const NAME: type = value;`).
fn limit(name: &str) -> f64 {
    include_str!("../src/limits.rs")
        .lines()
        .find_map(|l| {
            let rest = l.trim().strip_prefix("pub(crate) const ")?;
            let (n, rest) = rest.split_once(':')?;
            (n.trim() == name).then_some(())?;
            rest.split_once('=')?
                .1
                .trim()
                .trim_end_matches(';')
                .parse()
                .ok()
        })
        .unwrap_or_else(|| panic!("src/limits.rs has no numeric constant {name}"))
}

/// [`limit`] of a count.
fn count(name: &str) -> usize {
    limit(name) as usize
}

/// Run the CLI under `/usr/bin/time -v` when present: (wall s, peak RSS MB, exit code).
fn measure(args: &[OsString]) -> (f64, f64, Option<i32>) {
    let bin = env!("CARGO_BIN_EXE_viscoroll");
    let gnu_time = Path::new("/usr/bin/time").is_file();
    let mut c = if gnu_time {
        let mut c = Command::new("/usr/bin/time");
        c.arg("-v").arg(bin);
        c
    } else {
        Command::new(bin)
    };
    let t = Instant::now();
    let o = c.args(args).output().expect("viscoroll runs");
    let wall = t.elapsed().as_secs_f64();
    let err = String::from_utf8_lossy(&o.stderr);
    let rss = err
        .lines()
        .find_map(|l| {
            l.trim()
                .strip_prefix("Maximum resident set size (kbytes):")?
                .trim()
                .parse::<f64>()
                .ok()
        })
        .map_or(f64::NAN, |kb| kb / 1024.0);
    (wall, rss, o.status.code())
}

/// A scene of the conveyor idler (66.5 mm roll, 10 kN/m, 4 m/s) with `temps` temperatures over
/// −40 … 60 °C, a cover when given (mm), `map_temps` × (`map_n` speeds + `map_n` loads) map cells,
/// and its own tolerance when given.
fn scene(
    name: &str,
    temps: usize,
    cover_mm: Option<f64>,
    map_temps: usize,
    map_n: usize,
    tol: Option<f64>,
) -> String {
    let list = |n: usize, lo: f64, hi: f64, log: bool| -> String {
        let v: Vec<String> = (0..n)
            .map(|k| {
                let s = if n > 1 {
                    k as f64 / (n - 1) as f64
                } else {
                    0.0
                };
                let x = if log {
                    lo * (hi / lo).powf(s)
                } else {
                    lo + (hi - lo) * s
                };
                format!("{x:.6}")
            })
            .collect();
        format!("[{}]", v.join(", "))
    };
    let mut s = format!(
        "[[scene]]\nname = \"{name}\"\nroll_radius_mm = 66.5\nload_n_per_m = 10000.0\nspeed_m_s = 4.0\ntemps_c = {}\n",
        list(temps, -40.0, 60.0, false)
    );
    if let Some(h) = cover_mm {
        let _ = writeln!(s, "cover_thickness_mm = {h}");
    }
    if let Some(t) = tol {
        let _ = writeln!(s, "tol = {t:e}");
    }
    if map_temps > 0 {
        let _ = writeln!(s, "map_temps_c = {}", list(map_temps, -20.0, 40.0, false));
        let _ = writeln!(s, "map_speeds_m_s = {}", list(map_n, 0.1, 10.0, true));
        let _ = writeln!(s, "map_loads_n_per_m = {}", list(map_n, 1e3, 5e4, true));
    }
    s
}

/// A folder with the shipped EMS-CA export, `prony` settings in compounds.toml and `scenes`.
fn folder(root: &Path, name: &str, prony: &str, scenes: &str) -> PathBuf {
    let dir = root.join(name);
    std::fs::create_dir_all(&dir).unwrap();
    let data =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("data/pyvisco-ems-ca/freq_Eplexor_raw.xls");
    std::fs::copy(data, dir.join("ems-ca.xls")).unwrap();
    let prony = if prony.is_empty() {
        String::new()
    } else {
        format!("prony = {{ {prony} }}\n")
    };
    std::fs::write(
        dir.join("compounds.toml"),
        format!("[[compound]]\nname = \"ems-ca\"\nfiles = [\"ems-ca.xls\"]\n{prony}"),
    )
    .unwrap();
    std::fs::write(dir.join("scenes.toml"), scenes).unwrap();
    dir
}

fn run_args(dir: &Path) -> Vec<OsString> {
    vec![
        "run".into(),
        dir.as_os_str().into(),
        "--out".into(),
        dir.join("out").into_os_string(),
        "--json".into(),
    ]
}

fn main() {
    let root = std::env::temp_dir().join(format!("viscoroll-budget-{}", std::process::id()));
    let (contact_n_max, cover_over_radius_min) =
        (count("CONTACT_N_MAX"), limit("COVER_OVER_RADIUS_MIN"));
    let (map_cells_max, map_cells_per_point) =
        (count("MAP_CELLS_MAX"), count("MAP_CELLS_PER_POINT"));
    let (prony_lambda_count_max, scenes_max) =
        (count("PRONY_LAMBDA_COUNT_MAX"), count("SCENES_MAX"));
    let (scene_temps_max, scene_work_max) = (count("SCENE_TEMPS_MAX"), count("SCENE_WORK_MAX"));
    let only = std::env::var("BUDGET_ONLY").unwrap_or_default();
    // just above 1e-4 of the radius (1e-4 × 66.5 itself rounds below it)
    let thinnest_mm = 1.0001 * cover_over_radius_min * 66.5;
    let one = scene("idler", 9, None, 0, 0, None);
    // the work limit as two scenes: the per-scene limit of temperatures, and the rest
    let two = |cover: Option<f64>, tol: Option<f64>| -> String {
        scene("a", scene_temps_max, cover, 0, 0, tol)
            + "\n"
            + &scene("b", scene_work_max - scene_temps_max, cover, 0, 0, tol)
    };
    // 10 map temperatures × (50 + 50) = the per-scene cell limit, and temperatures up to the work
    let cells = scene("m", 9, Some(5.0), map_cells_max / 100, 50, None)
        + "\n"
        + &scene(
            "t",
            scene_work_max - 9 - map_cells_max / map_cells_per_point,
            Some(5.0),
            0,
            0,
            None,
        );
    // every scene the set may hold, 3 temperatures and 1 × (2 + 2) map cells each: 64 × 3 + 256 / 5
    let many: String = (0..scenes_max)
        .map(|k| scene(&format!("s{k}"), 3, Some(5.0), 1, 2, None))
        .collect::<Vec<_>>()
        .join("\n");
    let lambda = format!("lambda_count = {prony_lambda_count_max}");
    let rows: Vec<(String, Vec<OsString>)> = vec![
        (
            "run, one 9-temperature scene (reference)".into(),
            run_args(&folder(&root, "ref", "", &one)),
        ),
        (
            format!("run, prony.lambda_count = {prony_lambda_count_max}"),
            run_args(&folder(&root, "lambda", &lambda, &one)),
        ),
        (
            format!("run, prony.terms_per_decade = 10 (its limit), {lambda}"),
            run_args(&folder(
                &root,
                "terms",
                &format!("terms_per_decade = 10, {lambda}"),
                &one,
            )),
        ),
        (
            format!("run, {scene_work_max} temperatures on a half-space"),
            run_args(&folder(&root, "hs", "", &two(None, None))),
        ),
        (
            format!("run, {scene_work_max} points with {map_cells_max} map cells, 5 mm cover"),
            run_args(&folder(&root, "cells", "", &cells)),
        ),
        (
            format!("run, {scenes_max} scenes with maps, 5 mm cover"),
            run_args(&folder(&root, "many", "", &many)),
        ),
        (
            format!(
                "run, {scene_work_max} temperatures on the thinnest cover (h/R = {cover_over_radius_min:e}), tol 1e-10, {lambda}"
            ),
            run_args(&folder(&root, "worst", &lambda, &two(Some(thinnest_mm), Some(1e-10)))),
        ),
        (
            format!("contact --n {contact_n_max} (thesis collocation)"),
            [
                "contact",
                "--creep",
                "0.5:1,0.5:0.01",
                "--load",
                "1",
                "--n",
                &contact_n_max.to_string(),
            ]
            .iter()
            .map(OsString::from)
            .collect(),
        ),
    ];
    println!(
        "{} cores · load average {}",
        std::thread::available_parallelism().map_or(0, |n| n.get()),
        std::fs::read_to_string("/proc/loadavg")
            .unwrap_or_default()
            .trim()
    );
    println!("| input at its limit | wall s | peak RSS MB | exit |");
    println!("|---|---|---|---|");
    for (name, args) in rows {
        if !name.contains(&only) {
            continue;
        }
        let (wall, rss, code) = measure(&args);
        let code = code.map_or("signal".to_string(), |c| c.to_string());
        println!("| {name} | {wall:.1} | {rss:.0} | {code} |");
    }
    let _ = std::fs::remove_dir_all(&root);
}
