//! Replicate specimens (issue 31, docs/MATH.md §16) on the two shipped EMS-CA specimens: entered as
//! one compound, the pooled band holds both specimens' own frictions at every shipped scene point;
//! entered as two compounds, they are not declared different (tied in every scene); and the
//! default between-specimen prior `PRIOR_SD_LN` is what the pair's data give (eq. 16.4).

use crate::support::{col, data_dir, run_main, table, temp_dir};

/// Writes a compounds.toml naming the pair three ways: pooled, and each specimen alone.
fn folder() -> std::path::PathBuf {
    let dir = temp_dir("replicates");
    let d = data_dir();
    let a = d.join("pyvisco-ems-ca/freq_Eplexor_raw.xls");
    let b = d.join("pyvisco-ems-ca-specimen2/freq_Eplexor_raw.xls");
    let (a, b) = (a.display(), b.display());
    std::fs::write(
        dir.join("compounds.toml"),
        format!(
            "[[compound]]\nname = \"ems-ca-pooled\"\nspecimens = [{a:?}, {b:?}]\n\n\
             [[compound]]\nname = \"ems-ca-1\"\nfiles = [{a:?}]\n\n\
             [[compound]]\nname = \"ems-ca-2\"\nfiles = [{b:?}]\n"
        ),
    )
    .unwrap();
    std::fs::copy(d.join("scenes.toml"), dir.join("scenes.toml")).unwrap();
    dir
}

#[test]
fn the_pooled_band_holds_both_specimens_and_the_pair_apart_is_tied() {
    let dir = folder();
    let out = dir.join("out");
    let o = run_main(&dir, &out, &["--json"]);
    // exit 0 (all trusted) or 3 (use with care / not trusted): finished either way
    assert!(
        matches!(o.status.code(), Some(0) | Some(3)),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let summary: serde_json::Value =
        serde_json::from_slice(&o.stdout).expect("one JSON object on stdout");

    // 1. the pooled compound: both specimens inside the band at every shipped scene point
    let f = out.join("reports/ems-ca-pooled/friction.csv");
    let (h, rows) = table(&f);
    let (lo, hi, sp) = (
        col(&h, "friction_p05"),
        col(&h, "friction_p95"),
        col(&h, "specimen_frictions"),
    );
    let mut d2 = Vec::new();
    let mut worst: f64 = 0.0;
    for r in &rows {
        let s: Vec<f64> = r[sp].split(' ').map(|x| x.parse().unwrap()).collect();
        assert_eq!(s.len(), 2, "{r:?}");
        let (p05, p95): (f64, f64) = (r[lo].parse().unwrap(), r[hi].parse().unwrap());
        for x in &s {
            assert!(
                *x >= p05 && *x <= p95,
                "{} at {} °C: specimen F/N {x:e} outside the band {p05:e}…{p95:e}",
                r[0],
                r[1]
            );
        }
        let d = (s[0] / s[1]).ln();
        worst = worst.max(d.abs().exp());
        d2.push(d * d / 2.0);
    }
    assert_eq!(
        rows.len(),
        27,
        "the three shipped scenes × nine temperatures"
    );
    eprintln!("specimen ratio up to {worst:.2} over {} points", rows.len());

    // 2. the prior is what the pair gives (eq. 16.4), to the two decimals it is stated with
    let s0 = (d2.iter().sum::<f64>() / d2.len() as f64).sqrt();
    assert!(
        (s0 - viscoroll::bands::PRIOR_SD_LN).abs() < 0.005,
        "the pair gives s0 = {s0:.4}, PRIOR_SD_LN = {}",
        viscoroll::bands::PRIOR_SD_LN
    );

    // 3. the two specimens as two compounds: tied wherever both are ranked
    let mut pairs = 0;
    for c in summary["comparisons"].as_array().unwrap() {
        let (a, b) = (c["a"].as_str().unwrap(), c["b"].as_str().unwrap());
        if [a, b].contains(&"ems-ca-1") && [a, b].contains(&"ems-ca-2") {
            pairs += 1;
            assert!(c["tied"].as_bool().unwrap(), "{c}");
        }
    }
    assert!(pairs >= 1, "no comparison of the two specimens: {summary}");
    let _ = std::fs::remove_dir_all(&dir);
}
