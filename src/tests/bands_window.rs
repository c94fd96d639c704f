//! The frequency-window term of the bands (issue 16; crate::bands::window, docs/MATH.md eq. 15.9):
//! a synthetic compound whose master curve is truncated at its high-frequency end gets a wider,
//! flagged band where the rolling frequency lies beyond the measured window, a ramped term in the
//! window's last half decade (eq. 15.9c) and none further inside; the band's width has no step
//! where the frequency crosses the edge; on a cover the rolling frequency is the cover's own V/l.
//!
//! The compound is viscoroll::testdata::realistic's nr-tread measured twice: over −60 … +100 °C
//! (the default protocol) and over −40 … +100 °C only. Its master curve's top then falls from
//! 100 Hz·a_T(−60) to 100 Hz·a_T(−40), and at −40 °C the tyre-like scene's rolling frequency V/l
//! (20 m/s over a half-space contact of 5.4 mm: 3.7 kHz) lies beyond it, while −40 °C is still a
//! measured temperature (no eq. 15.8 term).

use std::path::PathBuf;
use viscoroll::bands::window::{measured_window_hz, RAMP_DECADES};
use viscoroll::bands::{build_ensemble, scene_bands_on, BandSettings, SceneRatios, WindowSide};
use viscoroll::contact::roll;
use viscoroll::creep::relaxation_to_creep;
use viscoroll::dma::{read_files, IngestOptions};
use viscoroll::pipeline::fit_measurement_master;
use viscoroll::pipeline::scenes::{friction_vs_temperature, pipeline_contact_settings, SceneSet};
use viscoroll::pipeline::FitOptions;
use viscoroll::results::{CompoundFit, FrictionPoint, SceneSpec};
use viscoroll::testdata::{dma_csv, dma_rows, realistic_compounds, DmaProtocol, RealisticCompound};

const TEMPS_C: [f64; 4] = [-40.0, -30.0, -10.0, 20.0];

/// nr-tread measured from `lowest_c` up (−60 … +100 °C every 5 K, seed 1), fitted with its
/// bootstrap ensemble as the main job does, and the true compound.
fn truncated_fit(lowest_c: f64, tag: &str) -> (CompoundFit, RealisticCompound) {
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
    fit.bands = Some(build_ensemble(&master, &m, &fit, &BandSettings::default()).unwrap());
    let _ = std::fs::remove_dir_all(&dir);
    (fit, compound)
}

/// The shipped tyre-like scene at `temps_c`.
fn tyre_like(temps_c: &[f64]) -> SceneSpec {
    let mut spec = SceneSet::shipped()
        .scene
        .into_iter()
        .find(|s| s.name == "tyre-like")
        .unwrap();
    spec.temps_c = temps_c.to_vec();
    spec
}

/// The tyre-like scene's points at [`TEMPS_C`] and their band ratios for the compound measured
/// from `lowest_c` up, and the true friction at each point.
fn banded(lowest_c: f64, tag: &str) -> (Vec<FrictionPoint>, SceneRatios, Vec<f64>) {
    let (fit, compound) = truncated_fit(lowest_c, tag);
    let bs = BandSettings::default();
    let spec = tyre_like(&TEMPS_C);
    assert!(spec.cover_thickness_mm.is_none(), "a half-space scene");
    let settings = pipeline_contact_settings();
    let points = friction_vs_temperature(&fit, &spec, &settings).unwrap();
    let r = scene_bands_on(
        &fit,
        fit.bands.as_ref().unwrap(),
        &spec.scene(),
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
    // further inside the truncated window than the ramp's half decade: no term, no note of it
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

/// Δ, the decades of the reduced rolling frequency V/l·a_T above the top of the fit's measured
/// window, from the point's contact length.
fn decades_above(fit: &CompoundFit, spec: &SceneSpec, p: &FrictionPoint) -> f64 {
    let (_, hi) = measured_window_hz(fit).unwrap();
    (spec.speed_m_s / (p.contact_length_mm * 1e-3) * 10f64.powf(p.log10_a_t) / hi).log10()
}

#[test]
fn the_window_term_has_no_step_at_the_edge_of_the_window() {
    // nr-tread measured from −40 °C: the tyre scene's reduced rolling frequency crosses the top of
    // the window a few kelvin above −40 °C. Find where Δ runs from +0.3 to −(RAMP + 0.2) decades
    // on a 1 K grid, then sweep that range finely.
    let (fit, _) = truncated_fit(-40.0, "sweep");
    let settings = pipeline_contact_settings();
    let coarse: Vec<f64> = (0..=30).map(|k| -40.0 + k as f64).collect();
    let spec = tyre_like(&coarse);
    let pts = friction_vs_temperature(&fit, &spec, &settings).unwrap();
    let d: Vec<f64> = pts.iter().map(|p| decades_above(&fit, &spec, p)).collect();
    println!("Δ on the coarse grid: {d:?}");
    let first = d
        .iter()
        .rposition(|&x| x > 0.3)
        .expect("a point 0.3 decades above");
    let last = d
        .iter()
        .position(|&x| x < -(RAMP_DECADES + 0.2))
        .expect("a point well inside");
    assert!(first < last);
    let (t0, t1) = (coarse[first], coarse[last]);
    // the fine sweep: step h = 0.05 K
    let h = 0.05;
    let n = ((t1 - t0) / h).round() as usize;
    let fine: Vec<f64> = (0..=n).map(|k| t0 + h * k as f64).collect();
    let spec = tyre_like(&fine);
    let pts = friction_vs_temperature(&fit, &spec, &settings).unwrap();
    let r = scene_bands_on(
        &fit,
        fit.bands.as_ref().unwrap(),
        &spec.scene(),
        &fine,
        &BandSettings::default(),
    );
    let hw: Vec<f64> = (0..fine.len()).map(|i| half_width(&r, i, 1.0)).collect();
    for (i, t) in fine.iter().enumerate() {
        println!(
            "{t:.2} °C: Δ {:+.3}, term {:?}, half-width {:.4}",
            decades_above(&fit, &spec, &pts[i]),
            r.window[i].as_ref().map(|w| w.s_ln.clone()),
            hw[i]
        );
    }
    let max_jump = |step: usize| {
        hw.iter()
            .step_by(step)
            .zip(hw.iter().step_by(step).skip(1))
            .map(|(a, b)| (b - a).abs())
            .fold(0.0f64, f64::max)
    };
    println!(
        "largest jump: {:.4} at 0.05 K, {:.4} at 0.1 K",
        max_jump(1),
        max_jump(2)
    );
    // The term starts half a decade inside the window and no further in (the contact lengths
    // here are the main job's, at 1e-4 of the band's: 0.01 decade left for that at the border).
    let mut ramped = 0;
    for (i, p) in pts.iter().enumerate() {
        let delta = decades_above(&fit, &spec, p);
        if delta < -(RAMP_DECADES + 0.01) {
            assert!(r.window[i].is_none(), "{} °C: {:?}", fine[i], r.window[i]);
        } else if delta > -(RAMP_DECADES - 0.01) {
            assert!(r.window[i].is_some(), "{} °C", fine[i]);
            ramped += usize::from(delta < 0.0);
        }
    }
    assert!(ramped > 10, "the sweep crosses the ramp ({ramped} points)");
    // The term's size at the edge, s_e (the first point inside): a term switched on at full size
    // there, as before eq. 15.9c, makes the band's log half-width step by about 1.645 s_e (the
    // data's own half-width, 0.015 there, is small against it). The sweep's largest jump between
    // neighbours 0.05 K apart must stay under a tenth of that ...
    let edge = pts
        .iter()
        .position(|p| decades_above(&fit, &spec, p) <= 0.0)
        .unwrap();
    let s_e = *r.window[edge].as_ref().unwrap().s_ln.as_ref().unwrap();
    let bound = 0.1 * 1.645 * s_e;
    println!("s_e = {s_e:.4}, bound {bound:.4}");
    assert!(
        max_jump(1) < bound,
        "largest jump {:.4} ≥ {bound:.4}",
        max_jump(1)
    );
    // ... and halve when the step halves (a continuous width; a step at the edge would stay):
    // 0.6 leaves room for the sweep's largest slope not falling on the same pair of points.
    assert!(
        max_jump(1) < 0.6 * max_jump(2),
        "{} vs {}",
        max_jump(1),
        max_jump(2)
    );
}

#[test]
fn a_cover_reads_its_rolling_frequency_from_its_own_shorter_contact() {
    // The tyre scene on a 0.5 mm cover of nr-tread measured from −40 °C: the bonded layer's contact
    // is 2.6–2.9 mm where the half-space's is 7.4–10 mm, so V/l is 0.4–0.5 decades higher. At
    // −28 °C the half-space's l puts the reduced rolling frequency 0.6 decades inside the window's
    // top (no term), the cover's 0.1 inside (the ramp nearly at full weight); at −30 °C 0.25
    // inside against 0.2 beyond.
    let (fit, _) = truncated_fit(-40.0, "cover");
    let settings = pipeline_contact_settings();
    let temps = [-30.0, -28.0, -24.0];
    let hs = tyre_like(&temps);
    let mut cover = tyre_like(&temps);
    cover.cover_thickness_mm = Some(0.5);
    let p_hs = friction_vs_temperature(&fit, &hs, &settings).unwrap();
    let p_cov = friction_vs_temperature(&fit, &cover, &settings).unwrap();
    let d_hs: Vec<f64> = p_hs.iter().map(|p| decades_above(&fit, &hs, p)).collect();
    let d_cov: Vec<f64> = p_cov
        .iter()
        .map(|p| decades_above(&fit, &cover, p))
        .collect();
    println!("Δ half-space {d_hs:?}, cover {d_cov:?}");
    assert!(p_cov.iter().all(|p| p.model == "layer"), "{p_cov:?}");
    // the premise: the two lengths put −28 °C on either side of the ramp's start, −30 °C on
    // either side of the edge
    assert!(d_hs[1] < -RAMP_DECADES - 0.05 && d_cov[1] > -RAMP_DECADES + 0.05);
    assert!(d_hs[0] < 0.0 && d_cov[0] > 0.0);
    let r = scene_bands_on(
        &fit,
        fit.bands.as_ref().unwrap(),
        &cover.scene(),
        &temps,
        &BandSettings::default(),
    );
    for (i, p) in p_cov.iter().enumerate() {
        let (band, notes) = r.point_band(i, p.friction);
        println!(
            "{} °C: window {:?}, band {:?}, notes {notes:?}",
            p.temp_c, r.window[i], band
        );
    }
    // −30 and −28 °C: the term, its reduced frequency from the cover's own contact length (the
    // band's nominal cover solve is the main job's: auto at 1e−3, so the same l to round-off)
    for i in 0..2 {
        let w = r.window[i].as_ref().expect("a window term on the cover");
        assert_eq!(w.excess.side, WindowSide::High);
        let f_cov =
            cover.speed_m_s / (p_cov[i].contact_length_mm * 1e-3) * 10f64.powf(p_cov[i].log10_a_t);
        assert!(
            (w.excess.reduced_freq_hz / f_cov - 1.0).abs() < 1e-9,
            "{} vs {f_cov}",
            w.excess.reduced_freq_hz
        );
        assert!((w.excess.decades - d_cov[i]).abs() < 1e-9);
        let s = *w.s_ln.as_ref().unwrap();
        assert!(s > 0.0);
        let (band, notes) = r.point_band(i, p_cov[i].friction);
        assert!(
            notes
                .iter()
                .any(|n| n.starts_with("band widened for extrapolation in frequency")),
            "{notes:?}"
        );
        // the band carries the term (as in the test above: 0.6 s for the sampling error of 32)
        let b = band.unwrap();
        assert!((b.p95 / b.p05).ln() / 2.0 >= 0.6 * 1.645 * s);
    }
    // beyond the edge at −30 °C by the cover's contact, inside by the half-space's
    assert!(r.window[0].as_ref().unwrap().excess.decades > 0.0);
    assert!(r.window[1].as_ref().unwrap().excess.decades < 0.0);
    // −24 °C: 0.7 decades inside even on the cover: no term
    assert!(r.window[2].is_none(), "{:?}", r.window[2]);
}
