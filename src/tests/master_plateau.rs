//! Shifting by default where E′ is flat or the isotherms do not overlap (issues 18 and 32).
//!
//! 1. **Plateaus.** The four synthetic rubbers of viscoroll::testdata::realistic (known spectra and
//!    WLF laws, each with a rubbery plateau; isotherms −60 … +100 °C every 5 K at 13 frequencies
//!    0.1–100 Hz, 1 % noise on E′, 3 % on E″, measured temperatures within ±1.5 K), read as
//!    `viscoroll run` reads them and shifted with the default settings of the main job. The error of
//!    each isotherm's shift is measured against the true law at the isotherm's own temperature,
//!    relative to the reference: log a_T(T) − log a_T(T_ref). Acceptance (issue 32): every shift from
//!    T_g + 20 K up within 0.03 decade of the truth, T_g the tan δ peak at 1 Hz of the true material.
//! 2. **Isotherms that do not overlap.** Two rubbers with a narrow glass transition and a steep WLF
//!    law (`non_overlapping_compounds`), stepped every 5 K from T_g − 30 K: near and below T_g
//!    neighbours lie 2–6 decades apart and E′ is flat. Acceptance: every shift the master curve calls
//!    determined by overlap is within 0.05 decade of the truth (the others are flagged and left
//!    where their overlaps put them, not moved by a law: docs/MATH.md §6.6); the determined shifts
//!    fall strictly with temperature, and the flags reach the warnings. The 0.03 from
//!    T_g + 20 K up is met on both (narrow-tg 0.0107, narrow-tg-filled 0.0086).
//!
//! The per-temperature tables print with `cargo test --lib master_plateau -- --nocapture`.

use viscoroll::dma::{self, IngestOptions};
use viscoroll::pipeline::FitOptions;
use viscoroll::testdata::{
    dma_csv, dma_rows, non_overlapping_compounds, realistic_compounds, DmaProtocol,
    RealisticCompound,
};
use viscoroll::tts::{build_master_curve, MasterCurve, ShiftCriterion};

/// The bound from T_g + 20 K up, decades.
const BOUND_DECADES: f64 = 0.03;
/// Bound on a shift called determined anywhere, decades: above the noise-driven error of the
/// isotherms nearest T_g (≈ 0.02 measured), far below a misplaced isotherm (decades).
const DETERMINED_BOUND_DECADES: f64 = 0.05;

/// T_g of a compound: the temperature of the tan δ peak at 1 Hz of the true material (0.1 K grid).
fn t_g(c: &RealisticCompound) -> f64 {
    let tan_d = |t: f64| {
        let w = 2.0 * std::f64::consts::PI * 10f64.powf(c.law.log10_a_t(t));
        c.spectrum.loss_modulus(w) / c.spectrum.storage_modulus(w)
    };
    let (mut best, mut at) = (0.0, f64::NAN);
    for k in 0..=2000 {
        let t = -100.0 + 0.1 * k as f64;
        let v = tan_d(t);
        if v.is_finite() && v > best {
            (best, at) = (v, t);
        }
    }
    at
}

/// The master curve of `c` measured under `protocol`, read as `viscoroll run` reads it, with the
/// main job's settings and the criterion `criterion` (`None`: the default).
fn master(
    c: &RealisticCompound,
    protocol: &DmaProtocol,
    criterion: Option<ShiftCriterion>,
) -> MasterCurve {
    let csv = dma_csv(&dma_rows(c, protocol));
    let m = dma::read_bytes(
        &[(format!("{}.csv", c.name), csv.into_bytes())],
        &IngestOptions::default(),
    )
    .unwrap();
    let mut settings = FitOptions::default().master;
    if let Some(k) = criterion {
        settings.criterion = k;
    }
    build_master_curve(&m, &settings).unwrap()
}

/// (T, fitted − true shift) of every isotherm.
fn errors(mc: &MasterCurve, law: &viscoroll::ShiftLaw) -> Vec<(f64, f64)> {
    let at_ref = law.log10_a_t(mc.t_ref_c);
    mc.isotherms
        .iter()
        .map(|s| (s.temp_c, s.log10_a_t - (law.log10_a_t(s.temp_c) - at_ref)))
        .collect()
}

fn worst_from(e: &[(f64, f64)], from_c: f64) -> f64 {
    e.iter()
        .filter(|(t, _)| *t >= from_c)
        .map(|(_, v)| v.abs())
        .fold(0.0, f64::max)
}

#[test]
fn default_shifts_hold_on_the_rubbery_plateau() {
    let protocol = DmaProtocol::default();
    let mut bad = Vec::new();
    println!("compound         T_g °C   worst from T_g+20 K: default   E′ alone (decades)");
    for c in realistic_compounds() {
        let tg = t_g(&c);
        let by_default = master(&c, &protocol, None);
        let storage = master(&c, &protocol, Some(ShiftCriterion::Storage));
        let (ed, es) = (errors(&by_default, &c.law), errors(&storage, &c.law));
        let (wd, ws) = (worst_from(&ed, tg + 20.0), worst_from(&es, tg + 20.0));
        println!("{:<15} {tg:>7.1}   {wd:>27.4}   {ws:>18.4}", c.name);
        println!("    T (°C)   default    E′ alone   carried by   determined");
        for ((t, d), ((_, s), iso)) in ed.iter().zip(es.iter().zip(&by_default.isotherms)) {
            println!(
                "   {t:>7.2}   {d:>+8.4}   {s:>+8.4}   {:>10}   {}",
                iso.shift_channel.as_deref().unwrap_or("-"),
                iso.shift_determined
            );
        }
        if wd > BOUND_DECADES {
            bad.push(format!("{}: worst {wd:.4} > {BOUND_DECADES}", c.name));
        }
        // These isotherms overlap by 1.3–2.6 decades: every shift from T_g up is determined. Deep in
        // the glass E′ is flat and may leave a shift undetermined, flagged (high-tg-tread at
        // −59.3 °C, 63 K below its T_g, measured 2026-11-28 with the law placement removed).
        assert!(
            by_default
                .isotherms
                .iter()
                .all(|i| i.shift_determined || i.temp_c < tg),
            "{}: {:?}",
            c.name,
            by_default.warnings
        );
    }
    assert!(bad.is_empty(), "{bad:?}");
}

/// A non-overlapping compound stepped every 5 K from T_g − 30 K: its T_g, default master curve and
/// the shifts' errors.
fn stepped_through_tg(c: &RealisticCompound) -> (f64, MasterCurve, Vec<(f64, f64)>) {
    let tg = t_g(c);
    let protocol = DmaProtocol {
        temps_c: (0..=19)
            .map(|k| (tg - 30.0).round() + 5.0 * k as f64)
            .collect(),
        ..DmaProtocol::default()
    };
    let mc = master(c, &protocol, None);
    let e = errors(&mc, &c.law);
    (tg, mc, e)
}

/// The goal on the non-overlapping rubbers: every shift from T_g + 20 K up within 0.03
/// decade. Met since E″ carries the glass where it superposes (docs/MATH.md eq. 6.1): narrow-tg
/// 0.0107, narrow-tg-filled 0.0086 (before: narrow-tg 0.0344 at 30.3 °C, its glassy isotherms
/// placed by a flat E′ and the chain from them pulling the plateau's shifts).
#[test]
fn non_overlapping_shifts_from_tg_plus_20_within_goal() {
    for c in non_overlapping_compounds() {
        let (tg, _, e) = stepped_through_tg(&c);
        let worst = worst_from(&e, tg + 20.0);
        println!("{}: worst from T_g + 20 K {worst:.4}", c.name);
        assert!(
            worst <= BOUND_DECADES,
            "{}: worst from T_g + 20 K {worst:.4} > {BOUND_DECADES}",
            c.name
        );
    }
}

#[test]
fn isotherms_that_do_not_overlap_are_flagged_and_left_in_place() {
    for c in non_overlapping_compounds() {
        let (tg, mc, e) = stepped_through_tg(&c);
        println!(
            "\n{} (T_g {tg:.1} °C): T_ref {:.2} °C\n    T (°C)   error (dec)   true step   determined   ±std",
            c.name, mc.t_ref_c
        );
        let mut prev: Option<f64> = None;
        for ((t, err), iso) in e.iter().zip(&mc.isotherms) {
            let step = prev.map_or(f64::NAN, |p| c.law.log10_a_t(p) - c.law.log10_a_t(*t));
            prev = Some(*t);
            println!(
                "   {t:>7.2}   {err:>+11.4}   {step:>9.2}   {:>10}   {:.3}",
                iso.shift_determined, iso.log10_a_t_std
            );
        }
        for w in &mc.warnings {
            println!("    warning: {w}");
        }
        // Where a neighbour pair truly overlaps by fewer than 2·min_overlap_points = 6 frequencies
        // (13 points 0.25 decade apart over 3 decades: a true step above 1.5 decades), §6.6 cannot
        // call the pair determined, so something is flagged. narrow-tg has steps of 2.6–2.8 decades
        // below T_g; narrow-tg-filled, whose tan δ peak at 1 Hz (its T_g here) sits at 8.4 °C
        // because of its filler tail, is stepped from −21 °C, all true steps ≤ 1.39 decades: it
        // checks that nothing is flagged falsely (every shift then within the determined bound).
        let window_decades = 3.0;
        let spacing_decades = 0.25;
        let max_true_step = e
            .windows(2)
            .map(|w| c.law.log10_a_t(w[0].0) - c.law.log10_a_t(w[1].0))
            .fold(0.0f64, f64::max);
        let true_overlap_points =
            ((window_decades - max_true_step) / spacing_decades).floor() + 1.0;
        let undetermined: Vec<f64> = mc
            .isotherms
            .iter()
            .filter(|i| !i.shift_determined)
            .map(|i| i.temp_c)
            .collect();
        if true_overlap_points < 6.0 {
            assert!(!undetermined.is_empty(), "{}: nothing flagged", c.name);
        }
        assert_eq!(mc.quality.shift_not_determined_c, undetermined);
        assert_eq!(
            mc.warnings
                .iter()
                .any(|w| w.contains("shift not determined by overlap")),
            !undetermined.is_empty(),
            "{:?}",
            mc.warnings
        );
        for ((t, err), iso) in e.iter().zip(&mc.isotherms) {
            if iso.shift_determined {
                assert!(
                    err.abs() <= DETERMINED_BOUND_DECADES,
                    "{} at {t:.1} °C: determined, but {err:+.3} decade off",
                    c.name
                );
                assert!(
                    iso.flags.iter().all(|f| !f.contains("not determined")),
                    "{:?}",
                    iso.flags
                );
            } else {
                assert!(iso.flags.iter().any(|f| f.contains("not determined")));
            }
        }
        // Every shift from T_g + 20 K up within the determined bound here; the 0.03 is
        // asserted by non_overlapping_shifts_from_tg_plus_20_within_goal.
        let worst = worst_from(&e, tg + 20.0);
        assert!(
            worst <= DETERMINED_BOUND_DECADES,
            "{}: worst from T_g + 20 K {worst:.4} > {DETERMINED_BOUND_DECADES}",
            c.name
        );
        // The determined shifts fall strictly with temperature (the flagged ones stay where their
        // overlaps put them, docs/MATH.md §6.6, and are not asserted on).
        let determined: Vec<_> = mc.isotherms.iter().filter(|i| i.shift_determined).collect();
        for w in determined.windows(2) {
            assert!(
                w[1].log10_a_t < w[0].log10_a_t,
                "{}: shifts not monotonic at {:.1}/{:.1} °C",
                c.name,
                w[0].temp_c,
                w[1].temp_c
            );
        }
    }
}

/// A glass whose E″ superposes is shifted by E″ (docs/MATH.md §6.2): the held-out high-T_g rubber
/// (T_g ≈ +20 °C) measured −60 … +100 °C, whose E′ below about 0 °C is flat within its 1 % noise.
/// Before, E′ alone carried every glassy isotherm: the overlaps placed them 2–7 decades off, out of
/// order, flagged as not determined, and the Prony fit got that broken master curve. Now E″, which
/// falls by a decade per decade of frequency there and superposes within its 3 % noise, carries
/// them: every isotherm that is called determined is within the determined bound of the truth, and
/// the determined ones reach at least 40 K below T_g (at the coldest isotherms the temperature's
/// drift within a sweep, ±1.5 K on a WLF law of 0.3 decade per kelvin there, may still spread an
/// isotherm more than its noise, and the run stops there, flagged).
#[test]
fn a_glass_whose_loss_superposes_is_shifted_by_it() {
    let c = viscoroll::testdata::realistic::held_out_compounds()
        .into_iter()
        .find(|c| c.name == "high-tg")
        .unwrap();
    let tg = t_g(&c);
    let mc = master(&c, &DmaProtocol::default(), None);
    let e = errors(&mc, &c.law);
    println!("high-tg (T_g {tg:.1} °C)\n    T (°C)   error (dec)   carried by   determined");
    for ((t, err), iso) in e.iter().zip(&mc.isotherms) {
        println!(
            "   {t:>7.2}   {err:>+11.4}   {:>10}   {}",
            iso.shift_channel.as_deref().unwrap_or("-"),
            iso.shift_determined
        );
    }
    let glassy_by_loss = mc
        .isotherms
        .iter()
        .filter(|i| i.temp_c < tg && i.shift_channel.as_deref() == Some("E″"))
        .count();
    assert!(glassy_by_loss > 0, "E″ carries no glassy isotherm");
    for ((t, err), iso) in e.iter().zip(&mc.isotherms) {
        assert!(
            iso.shift_determined || *t < tg - 40.0,
            "{t:.1} °C: not determined"
        );
        if iso.shift_determined {
            assert!(
                err.abs() <= DETERMINED_BOUND_DECADES,
                "{t:.1} °C: determined, but {err:+.3} decade off"
            );
        }
    }
}

/// Where the shifts' error comes from (a tool, prints): the held-out compounds measured with noise
/// and drift, noise alone, drift alone and neither, shifted as the main job shifts them.
#[test]
#[ignore = "diagnostic table; run with --nocapture"]
fn shift_error_sources() {
    let mut opts = FitOptions::default();
    opts.master.correct_point_temperatures = true;
    println!("compound             both    noise   drift   neither   (rms error of determined shifts, decades)");
    for c in viscoroll::testdata::realistic::held_out_compounds() {
        let mut row = Vec::new();
        for (n1, n2, d) in [
            (0.01, 0.03, 1.5),
            (0.01, 0.03, 0.0),
            (0.0, 0.0, 1.5),
            (0.0, 0.0, 0.0),
        ] {
            let mut acc = Vec::new();
            for seed in 1..=4u64 {
                let protocol = DmaProtocol {
                    noise_storage_rel: n1,
                    noise_loss_rel: n2,
                    drift_bound_k: d,
                    seed,
                    ..DmaProtocol::default()
                };
                let csv = dma_csv(&dma_rows(&c, &protocol));
                let m = dma::read_bytes(
                    &[(format!("{}.csv", c.name), csv.into_bytes())],
                    &IngestOptions::default(),
                )
                .unwrap();
                let mc = build_master_curve(&m, &opts.master).unwrap();
                for ((_, e), i) in errors(&mc, &c.law).iter().zip(&mc.isotherms) {
                    if i.shift_determined {
                        acc.push(e * e);
                    }
                }
            }
            row.push((acc.iter().sum::<f64>() / acc.len() as f64).sqrt());
        }
        println!(
            "{:<18} {:>7.4} {:>7.4} {:>7.4} {:>9.4}",
            c.name, row[0], row[1], row[2], row[3]
        );
    }
}

/// The shifts' standard errors mean what they say (docs/MATH.md eq. 6.2): on the eight held-out
/// compounds measured as the main job's tests measure them (1 % / 3 % noise, ±1.5 K drift, seeds
/// 1–3), the true shift of a determined isotherm lies within ±1.645 standard errors of the found one
/// for 80–97 % of the isotherms (90 % expected; the isotherms of one master curve share their
/// errors along the chain, so the 700-odd are far fewer independent draws). With σ²(JᵀJ)⁻¹, which
/// counts every residual as independent although each point enters up to a dozen, 40 % were.
#[test]
fn shift_standard_errors_cover_the_truth() {
    let (mut inside, mut n) = (0usize, 0usize);
    let mut z2 = 0.0;
    for c in viscoroll::testdata::realistic::held_out_compounds() {
        for seed in 1..=3u64 {
            let protocol = DmaProtocol {
                seed,
                ..DmaProtocol::default()
            };
            let mc = master_corrected(&c, &protocol);
            for ((_, e), i) in errors(&mc, &c.law).iter().zip(&mc.isotherms) {
                if i.shift_determined && i.log10_a_t_std > 0.0 {
                    let z = e / i.log10_a_t_std;
                    z2 += z * z;
                    n += 1;
                    inside += usize::from(z.abs() <= 1.645);
                }
            }
        }
    }
    let frac = inside as f64 / n as f64;
    println!(
        "{inside}/{n} = {:.1} % within ±1.645 σ; rms z {:.2}",
        100.0 * frac,
        (z2 / n as f64).sqrt()
    );
    assert!((0.80..=0.97).contains(&frac), "{frac:.3}");
}

/// The master curve as the main job builds it (points moved to their isotherm's temperature).
fn master_corrected(c: &RealisticCompound, protocol: &DmaProtocol) -> MasterCurve {
    let csv = dma_csv(&dma_rows(c, protocol));
    let m = dma::read_bytes(
        &[(format!("{}.csv", c.name), csv.into_bytes())],
        &IngestOptions::default(),
    )
    .unwrap();
    build_master_curve(&m, &FitOptions::default().master).unwrap()
}
