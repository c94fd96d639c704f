//! `viscoroll run` over a folder holding relaxation isotherms (issue 29, item 3; docs/MATH.md §18):
//! the file is recognised as time-domain data by its header, fitted in time, and its friction
//! points are marked not determined where the data do not determine them (eqs. 18.3, 18.6), the
//! others ranked.

use crate::support::{col, run_main, stderr, table, temp_dir};
use viscoroll::dma::TimeMode;
use viscoroll::testdata::{time_domain_csv, TimeSettings};

#[test]
fn run_fits_relaxation_isotherms_in_time_and_ranks_only_what_they_determine() {
    let dir = temp_dir("td-run-in");
    let out = temp_dir("td-run-out");
    let law = viscoroll::ShiftLaw::Wlf {
        t_ref_c: 20.0,
        c1: 8.86,
        c2_k: 101.6,
    };
    let s = TimeSettings {
        temps_c: (0..=20).map(|k| -40.0 + 5.0 * k as f64).collect(),
        window_s: (1.0, 1e4),
        per_decade: 10,
        noise_rel: 0.01,
        seed: 11,
    };
    let csv = time_domain_csv(
        &viscoroll::testdata::broad_spectrum(),
        TimeMode::Relaxation,
        &law,
        &s,
    );
    std::fs::write(dir.join("relaxed.csv"), csv).unwrap();
    // the shipped half-space scene only (the one of the accuracy table)
    std::fs::write(
        dir.join("scenes.toml"),
        "[[scene]]\nname = \"conveyor-idler-half-space\"\nroll_radius_mm = 66.5\n\
         load_n_per_m = 10000.0\nspeed_m_s = 4.0\n\
         temps_c = [-40.0, -30.0, -20.0, -10.0, 0.0, 10.0, 20.0, 30.0, 40.0]\n",
    )
    .unwrap();
    let o = run_main(&dir, &out, &["--no-bands", "--tref", "20"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let fit: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(out.join("fits").join("relaxed.json")).unwrap(),
    )
    .unwrap();
    assert!(
        fit["prony_info"]["time_domain"]["function"] == "E(t)",
        "{}",
        fit["prony_info"]
    );
    let (h, rows) = table(&out.join("reports").join("relaxed").join("friction.csv"));
    let (t, und) = (col(&h, "temp_c"), col(&h, "undetermined"));
    let undetermined = |temp: &str| {
        let r = rows.iter().find(|r| r[t] == temp).unwrap();
        !r[und].is_empty() && r[und] != "false"
    };
    // as in the library's accuracy test: −40…−10 °C not determined, 0…40 °C determined
    for temp in ["-40", "-30", "-20", "-10"] {
        assert!(undetermined(temp), "{temp}: {rows:?}");
    }
    for temp in ["0", "10", "20", "30", "40"] {
        assert!(!undetermined(temp), "{temp}: {rows:?}");
    }
    // ranked on the determined temperatures, with the time-domain care note
    let (h, rows) = table(&out.join("reports").join("ranking.csv"));
    let r = rows
        .iter()
        .find(|r| r[col(&h, "compound")] == "relaxed")
        .unwrap();
    assert_eq!(r[col(&h, "rank")], "1", "{r:?}");
    assert!(r[col(&h, "note")].contains("time-domain"), "{r:?}");
}
