//! The main job's numbers do not move under refactoring: `viscoroll run` on the shipped data with the
//! scenes frozen in `tests/data/golden/scenes.toml` must reproduce the friction tables, friction maps
//! and ranking captured before the contact/report redesign (issue 13), value by value, to 1e-12
//! relative. The captured files are plain outputs of commit dbcaff5; a change that is meant to move a
//! number (new physics, a different ranking rule) updates the file it moves and says why in its commit.
//!
//! Columns are matched by name and rows by position, so new columns may be added without touching the
//! golden files; a golden column that disappears fails.

use crate::support::{data_dir, run_main, table, temp_dir};
use std::path::{Path, PathBuf};

/// Relative tolerance: the refactor must not change the arithmetic, only where it lives. 1e-12 leaves
/// room for a reordered sum of a few terms (a few ulps), nothing more.
const REL_TOL: f64 = 1e-12;

fn golden() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/golden")
}

fn same_value(want: &str, got: &str) -> bool {
    match (want.parse::<f64>(), got.parse::<f64>()) {
        (Ok(w), Ok(g)) if w.is_finite() && g.is_finite() => {
            (w - g).abs() <= REL_TOL * w.abs().max(g.abs()) || w == g
        }
        _ => want == got,
    }
}

fn compare(want_path: &Path, got_path: &Path) {
    let (wh, wr) = table(want_path);
    let (gh, gr) = table(got_path);
    assert_eq!(
        wr.len(),
        gr.len(),
        "{}: {} rows, golden has {}",
        got_path.display(),
        gr.len(),
        wr.len()
    );
    for (wc, name) in wh.iter().enumerate() {
        let gc = gh
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("{}: column {name} is gone", got_path.display()));
        for (i, (w, g)) in wr.iter().zip(&gr).enumerate() {
            assert!(
                same_value(&w[wc], &g[gc]),
                "{} row {} column {name}: {} (golden {})",
                got_path.display(),
                i + 1,
                g[gc],
                w[wc]
            );
        }
    }
}

#[test]
fn main_job_reproduces_the_captured_friction_tables_maps_and_ranking() {
    let out = temp_dir("golden");
    let scenes = golden().join("scenes.toml");
    let status = run_main(&data_dir(), &out, &["--scenes", scenes.to_str().unwrap()]);
    assert!(
        status.status.success(),
        "run failed: {}",
        String::from_utf8_lossy(&status.stderr)
    );
    let reports = out.join("reports");
    compare(&golden().join("ranking.csv"), &reports.join("ranking.csv"));
    for compound in ["ems-ca", "dmasuite-tensile", "trios-aresg2-lims"] {
        for file in ["friction.csv", "friction_map.csv"] {
            compare(
                &golden().join(compound).join(file),
                &reports.join(compound).join(file),
            );
        }
    }
    let _ = std::fs::remove_dir_all(&out);
}
