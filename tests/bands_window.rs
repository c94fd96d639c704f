//! The frequency-window term of the bands (issue 16; crate::bands::window, docs/MATH.md eq. 15.9):
//! a synthetic compound whose master curve is truncated at its high-frequency end gets a wider,
//! flagged band where the rolling frequency lies beyond the measured window, and no term inside it.
//!
//! The compound is viscoroll::testdata::realistic's nr-tread measured twice: over −60 … +100 °C
//! (the default protocol) and over −40 … +100 °C only. Its master curve's top then falls from
//! 100 Hz·a_T(−60) to 100 Hz·a_T(−40), and at −40 °C the tyre-like scene's rolling frequency V/l
//! (20 m/s over a contact of ~10 mm: ~2 kHz) lies beyond it, while −40 °C is still a measured
//! temperature (no eq. 15.8 term).

use std::path::PathBuf;
use viscoroll::bands::{build_ensemble, scene_bands_on, BandSettings, SceneRatios, WindowSide};
use viscoroll::contact::roll;
use viscoroll::creep::relaxation_to_creep;
use viscoroll::dma::{read_files, IngestOptions};
use viscoroll::pipeline::fit_compound::fit_measurement_master;
use viscoroll::pipeline::scenes::{friction_vs_temperature, pipeline_contact_settings, SceneSet};
use viscoroll::pipeline::FitOptions;
use viscoroll::results::FrictionPoint;
use viscoroll::testdata::realistic::{dma_csv, dma_rows, realistic_compounds, DmaProtocol};

const TEMPS_C: [f64; 4] = [-40.0, -30.0, -10.0, 20.0];

/// The tyre-like scene's points at [`TEMPS_C`] and their band ratios for the compound measured
/// from `lowest_c` up, and the true friction at each point.
fn banded(lowest_c: f64, tag: &str) -> (Vec<FrictionPoint>, SceneRatios, Vec<f64>) {
    let compound = realistic_compounds()
        .into_iter()
        .find(|c| c.name == "nr-tread")
        .unwrap();
    let protocol = DmaProtocol {
        temps_c: (0..=32)
            .map(|i| -60.0 + 5.0 * i as f64)
            .filter(|t| *t >= lowest_c)
            .collect(),
        seed: 1,
        ..DmaProtocol::default()
    };
    let dir = std::env::temp_dir().join(format!("viscoroll-window-{}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path: PathBuf = dir.join("nr-tread.csv");
    std::fs::write(&path, dma_csv(&dma_rows(&compound, &protocol))).unwrap();
    let m = read_files(&[path], &IngestOptions::default()).unwrap();
    let (mut fit, master) = fit_measurement_master("nr-tread", &m, &FitOptions::default()).unwrap();
    let bs = BandSettings::default();
    fit.bands = Some(build_ensemble(&master, &m, &fit, &bs).unwrap());
    let mut spec = SceneSet::shipped()
        .scene
        .into_iter()
        .find(|s| s.name == "tyre-like")
        .unwrap();
    spec.temps_c = TEMPS_C.to_vec();
    assert!(spec.cover_thickness_mm.is_none(), "a half-space scene");
    let settings = pipeline_contact_settings();
    let points = friction_vs_temperature(&fit, &spec, &settings).unwrap();
    let r = scene_bands_on(
        &fit,
        fit.bands.as_ref().unwrap(),
        &spec.scene(),
        None,
        &spec.temps_c,
        &bs,
    );
    let (true_creep, _) = relaxation_to_creep(&compound.spectrum).unwrap();
    let truth = TEMPS_C
        .iter()
        .map(|&t| {
            let mut c = true_creep.clone();
            for term in &mut c.terms {
                term.tau_s *= 10f64.powf(compound.law.log10_a_t(t));
            }
            roll(&spec.scene(), &c, &settings).unwrap().friction
        })
        .collect();
    let _ = std::fs::remove_dir_all(&dir);
    (points, r, truth)
}

/// ln(p95/p05)/2 of the point's band.
fn half_width(r: &SceneRatios, i: usize, f: f64) -> f64 {
    let b = r.point_band(i, f).0.expect("a band");
    (b.p95 / b.p05).ln() / 2.0
}

#[test]
fn a_truncated_master_curve_widens_and_flags_the_points_beyond_its_window() {
    let (full_pts, full, _) = banded(-60.0, "full");
    let (cut_pts, cut, truth) = banded(-40.0, "cut");
    for (i, t) in TEMPS_C.iter().enumerate() {
        let (hw_full, hw_cut) = (
            half_width(&full, i, full_pts[i].friction),
            half_width(&cut, i, cut_pts[i].friction),
        );
        let band = cut.point_band(i, cut_pts[i].friction).0;
        let band = band.unwrap();
        println!(
            "{t} °C: half-width full {hw_full:.4}, truncated {hw_cut:.4}; window term {:?}; \
             truth {:.4e} in {:.4e} … {:.4e}",
            cut.window[i]
                .as_ref()
                .map(|w| (w.excess.decades, w.s_ln.clone())),
            truth[i],
            band.p05,
            band.p95
        );
        // measured temperatures throughout: no shift-law tail term on either
        assert!(cut.tail_ln[i].is_none() && full.tail_ln[i].is_none());
        // the full protocol's window reaches every point's rolling frequency
        assert!(full.window[i].is_none(), "{t} °C: {:?}", full.window[i]);
    }
    // −40 °C: beyond the truncated window's top, flagged "in frequency", and wider
    let w = cut.window[0]
        .as_ref()
        .expect("−40 °C lies beyond the truncated window");
    assert_eq!(w.excess.side, WindowSide::High);
    let s = *w.s_ln.as_ref().unwrap();
    let notes = cut.point_band(0, cut_pts[0].friction).1;
    assert!(
        notes
            .iter()
            .any(|n| n.starts_with("band widened for extrapolation in frequency")),
        "{notes:?}"
    );
    let (hw_full, hw_cut) = (
        half_width(&full, 0, full_pts[0].friction),
        half_width(&cut, 0, cut_pts[0].friction),
    );
    assert!(hw_cut > hw_full, "{hw_cut} vs {hw_full}");
    // the term enters as s·v_b with v_b standard normal, independent of the data's scatter: the
    // band's log sd is ≥ s up to the sampling error of 32 draws (an sd known to ±13 %, so 3 of
    // those below is 0.6 s)
    assert!(hw_cut >= 0.6 * 1.645 * s, "{hw_cut} vs s = {s}");
    // the truncated fit's friction there misses the truth by far more than the data's scatter
    // (the full protocol's band at that point, ±0.8 %) could explain — its fitted spectrum ends at
    // the window — and the widened band reaches it
    let miss = (truth[0] / cut_pts[0].friction).ln().abs();
    println!(
        "−40 °C: truncated fit's F/N {:.4e}, |ln(truth/F)| = {miss:.3}",
        cut_pts[0].friction
    );
    assert!(miss > 10.0 * hw_full, "{miss} vs {hw_full}");
    let band = cut.point_band(0, cut_pts[0].friction).0.unwrap();
    assert!(
        band.p05 <= truth[0] && truth[0] <= band.p95,
        "truth {:.4e} outside {:.4e} … {:.4e}",
        truth[0],
        band.p05,
        band.p95
    );
    // inside the truncated window: no term, no note of it
    for (i, p) in cut_pts.iter().enumerate().skip(1) {
        if cut.window[i].is_none() {
            let notes = cut.point_band(i, p.friction).1;
            assert!(
                notes.iter().all(|n| !n.contains("in frequency")),
                "{notes:?}"
            );
        }
    }
}
