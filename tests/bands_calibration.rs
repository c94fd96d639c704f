//! Calibration of the uncertainty bands (issue 16, item 1; crate::bands, docs/MATH.md §15): on the
//! known-truth synthetic compounds of tests/known_truth.rs (viscoroll::testdata::realistic: four
//! rubbers, isotherms −60 … +100 °C every 5 K, 1 % noise on E′, 3 % on E″, ±1.5 K drift) the
//! 90 % band (p05 … p95) must cover the true friction in 80–97 % of the (compound, scene,
//! temperature) points, over the shipped scenes at −40 … +60 °C every 10 K.
//!
//! The band comes from the pipeline's own path: the export written as CSV and read back, the fit
//! (`pipeline::fit_compound::fit_measurement_master`), the bootstrap ensemble
//! (`bands::build_ensemble`, the main job's settings), the friction (`friction_vs_temperature`, the
//! main job's contact settings) and its band (`bands::scene_ratios_on`, on the scene's cover, + `band_of`). The true friction
//! comes from the true spectrum, converted exactly to creep and shifted by the true WLF law, through
//! the contact solver (the body of the scene); nothing of the fit or the ensemble enters it. That
//! truth is itself checked against an independent contact path in tests/known_truth.rs.
//!
//! In CI: noise seeds 1 and 2 (about 30 s on 2 cores; 252/264 = 95.5 % with eqs. 15.6b–15.9). The full
//! figure over 10 seeds (about 2 min; 1142/1320 = 86.5 %, per seed 72.7–99.2 %):
//! `cargo test --release --test tests bands_calibration_ten_seeds -- --ignored --nocapture`.
//! Both print the coverage per seed, compound and scene, and the misses. The 2-seed check is the
//! weaker one: single seeds range from 72 % to 98.5 %, so it catches a band that is far off (too
//! narrow or too wide by ~2×), not a few points of coverage.

use std::path::PathBuf;
use viscoroll::bands::{band_of, build_ensemble, scene_ratios_on, BandSettings};
use viscoroll::contact::body::layer::{roll_cover, ModelChoice};
use viscoroll::contact::roll;
use viscoroll::creep::relaxation_to_creep;
use viscoroll::dma::{read_files, IngestOptions};
use viscoroll::pipeline::fit_compound::fit_measurement_master;
use viscoroll::pipeline::scenes::{
    friction_vs_temperature, pipeline_contact_settings, SceneSet, COVER_TOL,
};
use viscoroll::pipeline::FitOptions;
use viscoroll::testdata::realistic::{dma_csv, dma_rows, realistic_compounds, DmaProtocol};
use viscoroll::CreepSpectrum;

/// Temperatures of the comparison, °C (as tests/known_truth.rs).
const TEMPS_C: [f64; 11] = [
    -40.0, -30.0, -20.0, -10.0, 0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0,
];

/// The acceptance range of the coverage of a 90 % band.
const COVERAGE: (f64, f64) = (0.80, 0.97);

fn shifted(c: &CreepSpectrum, log10_a_t: f64) -> CreepSpectrum {
    let mut s = c.clone();
    for t in &mut s.terms {
        t.tau_s *= 10f64.powf(log10_a_t);
    }
    s
}

/// One point: (compound, scene, T, truth, friction, band p05, p95, (m, s) of ln F_b/F̂).
type Point = (String, String, f64, f64, f64, f64, f64, (f64, f64));

/// Mean and standard deviation of the finite ln ratios (as crate::bands::band_of reads them).
fn log_stats(r: &[f64]) -> (f64, f64) {
    let d: Vec<f64> = r
        .iter()
        .filter(|x| x.is_finite() && **x > 0.0)
        .map(|x| x.ln())
        .collect();
    let n = d.len() as f64;
    let m = d.iter().sum::<f64>() / n;
    (
        m,
        (d.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1.0)).sqrt(),
    )
}

/// Coverage of two other readings of the same replicates, for comparison (not asserted): the band
/// centred on F itself (p50 = F, half-width 1.645 s) and the basic bootstrap (the bias e^m reflected:
/// p50 = F·e^(−m)).
fn other_readings(p: &Point) -> (bool, bool) {
    let (m, s) = p.7;
    let z = viscoroll::bands::friction::Z95;
    let inside = |c: f64| p.4 * (c - z * s).exp() <= p.3 && p.3 <= p.4 * (c + z * s).exp();
    (inside(0.0), inside(-m))
}

/// Every (compound, scene, temperature) point of one noise seed.
fn points_of_seed(seed: u64) -> Vec<Point> {
    let protocol = DmaProtocol {
        seed,
        ..DmaProtocol::default()
    };
    let dir = std::env::temp_dir().join(format!("viscoroll-bands-{}-{}", std::process::id(), seed));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scenes = SceneSet::shipped();
    let settings = pipeline_contact_settings();
    let bs = BandSettings::default();
    let mut out = Vec::new();
    for compound in realistic_compounds() {
        let path: PathBuf = dir.join(format!("{}.csv", compound.name));
        std::fs::write(&path, dma_csv(&dma_rows(&compound, &protocol))).unwrap();
        let m = read_files(&[path], &IngestOptions::default()).unwrap();
        let (mut fit, master) =
            fit_measurement_master(&compound.name, &m, &FitOptions::default()).unwrap();
        fit.bands = Some(build_ensemble(&master, &m, &fit, &bs).unwrap());
        let ensemble = fit.bands.as_ref().unwrap();
        let (true_creep, _) = relaxation_to_creep(&compound.spectrum).unwrap();
        for base in &scenes.scene {
            let mut spec = base.clone();
            spec.temps_c = TEMPS_C.to_vec();
            let scene = spec.scene();
            let got = friction_vs_temperature(&fit, &spec, &settings).unwrap();
            let cover_m = spec.cover_thickness_mm.map(|h| h * 1e-3);
            let ratios = scene_ratios_on(&fit, ensemble, &scene, cover_m, &spec.temps_c, &bs);
            for (p, r) in got.iter().zip(&ratios) {
                let true_at_t = shifted(&true_creep, compound.law.log10_a_t(p.temp_c));
                let truth = match spec.cover_thickness_mm {
                    Some(h_mm) => {
                        roll_cover(
                            &scene,
                            &true_at_t,
                            Some(h_mm * 1e-3),
                            ModelChoice::Auto,
                            settings.auto.tol.max(COVER_TOL),
                        )
                        .unwrap()
                        .roll
                        .friction
                    }
                    None => roll(&scene, &true_at_t, &settings).unwrap().friction,
                };
                let b = band_of(p.friction, r).expect("a band at every point");
                out.push((
                    compound.name.clone(),
                    spec.name.clone(),
                    p.temp_c,
                    truth,
                    p.friction,
                    b.p05,
                    b.p95,
                    log_stats(r),
                ));
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    out
}

fn covered(p: &Point) -> bool {
    p.5 <= p.3 && p.3 <= p.6
}

/// Coverage table over `seeds` (per seed and compound, per scene, total); returns the total.
fn calibrate(seeds: &[u64]) -> f64 {
    let mut all: Vec<(u64, Point)> = Vec::new();
    for &seed in seeds {
        let pts = points_of_seed(seed);
        let n = pts.len();
        let hit = pts.iter().filter(|p| covered(p)).count();
        let mut line = format!(
            "seed {seed:>2}: {hit:>3}/{n} = {:>5.1} %",
            100.0 * hit as f64 / n as f64
        );
        for c in ["nr-br-idler", "nr-tread", "sbr-tread", "high-tg-tread"] {
            let of: Vec<&Point> = pts.iter().filter(|p| p.0 == c).collect();
            let h = of.iter().filter(|p| covered(p)).count();
            line += &format!("  {c} {h}/{}", of.len());
        }
        println!("{line}");
        all.extend(pts.into_iter().map(|p| (seed, p)));
    }
    let scenes: Vec<String> = SceneSet::shipped()
        .scene
        .iter()
        .map(|s| s.name.clone())
        .collect();
    for s in &scenes {
        let of: Vec<_> = all.iter().filter(|(_, p)| &p.1 == s).collect();
        let h = of.iter().filter(|(_, p)| covered(p)).count();
        println!(
            "scene {s}: {h}/{} = {:.1} %",
            of.len(),
            100.0 * h as f64 / of.len() as f64
        );
    }
    // Relative half-width of the bands and |error| / half-width, medians.
    let mut width: Vec<f64> = all.iter().map(|(_, p)| 0.5 * (p.6 - p.5) / p.4).collect();
    let mut err: Vec<f64> = all
        .iter()
        .map(|(_, p)| (p.4 - p.3).abs() / (0.5 * (p.6 - p.5)))
        .collect();
    width.sort_by(f64::total_cmp);
    err.sort_by(f64::total_cmp);
    println!(
        "median relative half-width {:.2} %, median |F/N − true| / half-width {:.2}",
        100.0 * width[width.len() / 2],
        err[err.len() / 2]
    );
    for (seed, p) in all.iter().filter(|(_, p)| !covered(p)).take(40) {
        println!(
            "missed: seed {seed} {} {} {} °C: true {:.4e}, F/N {:.4e}, band {:.4e} … {:.4e}",
            p.0, p.1, p.2, p.3, p.4, p.5, p.6
        );
    }
    let centred = all.iter().filter(|(_, p)| other_readings(p).0).count();
    let basic = all.iter().filter(|(_, p)| other_readings(p).1).count();
    println!(
        "other readings of the same replicates: centred on F {:.1} %, basic bootstrap {:.1} %",
        100.0 * centred as f64 / all.len() as f64,
        100.0 * basic as f64 / all.len() as f64
    );
    let hit = all.iter().filter(|(_, p)| covered(p)).count();
    let total = hit as f64 / all.len() as f64;
    println!("total: {hit}/{} = {:.1} %", all.len(), 100.0 * total);
    total
}

/// CI: two noise seeds (264 points); the same acceptance range as the full sweep.
#[test]
fn bands_cover_the_true_friction_two_seeds() {
    let total = calibrate(&[1, 2]);
    assert!(
        (COVERAGE.0..=COVERAGE.1).contains(&total),
        "coverage {total:.3} outside {COVERAGE:?}"
    );
}

/// The figure: 10 noise seeds (1320 points).
#[test]
#[ignore = "10-seed calibration; run on demand (see the module docs)"]
fn bands_calibration_ten_seeds() {
    let total = calibrate(&(1..=10).collect::<Vec<u64>>());
    assert!(
        (COVERAGE.0..=COVERAGE.1).contains(&total),
        "coverage {total:.3} outside {COVERAGE:?}"
    );
}
