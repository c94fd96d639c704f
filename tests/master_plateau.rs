//! Shifting where E′ is flat (issue 18): a synthetic rubber with a known WLF law whose upper
//! isotherms sit on the rubbery plateau (viscoroll::testdata::realistic, `nr-br-idler`: tan δ peak at
//! 1 Hz ≈ −52 °C, E₀/E∞ = 900; isotherms −60 … +100 °C every 5 K at 13 frequencies 0.1–100 Hz, 1 %
//! noise on E′, 3 % on E″, measured temperatures within ±1.5 K), read as `viscoroll run` reads it
//! and shifted with E′ alone (the default) and with the slope-weighted criterion. The error of each
//! isotherm's shift is measured against the true law at the isotherm's own temperature, relative to
//! the reference: log a_T(T) − log a_T(T_ref).
//!
//! Acceptance (the figure): slope-weighted shifts within 0.05 decade of the truth at every
//! temperature from T_g + 20 K (−32 °C) upward. The per-temperature table prints with
//! `cargo test --test tests master_plateau -- --nocapture`.

use viscoroll::dma::{self, IngestOptions};
use viscoroll::testdata::realistic::{dma_csv, dma_rows, realistic_compounds, DmaProtocol};
use viscoroll::tts::{build_master_curve, MasterCurve, MasterSettings, ShiftCriterion};

/// The bound, decades.
const BOUND_DECADES: f64 = 0.05;
/// T_g (tan δ peak at 1 Hz) + 20 K of `nr-br-idler`, °C.
const FROM_C: f64 = -52.0 + 20.0;

fn errors(mc: &MasterCurve, law: &viscoroll::ShiftLaw) -> Vec<(f64, f64)> {
    let at_ref = law.log10_a_t(mc.t_ref_c);
    mc.isotherms
        .iter()
        .map(|s| (s.temp_c, s.log10_a_t - (law.log10_a_t(s.temp_c) - at_ref)))
        .collect()
}

#[test]
fn slope_weighted_shifts_hold_on_the_rubbery_plateau() {
    let compound = realistic_compounds()
        .into_iter()
        .find(|c| c.name == "nr-br-idler")
        .unwrap();
    let csv = dma_csv(&dma_rows(&compound, &DmaProtocol::default()));
    let m = dma::read_bytes(
        &[("nr-br-idler.csv".to_string(), csv.into_bytes())],
        &IngestOptions::default(),
    )
    .unwrap();
    let build = |criterion| {
        build_master_curve(
            &m,
            &MasterSettings {
                criterion,
                correct_point_temperatures: true,
                ..MasterSettings::default()
            },
        )
        .unwrap()
    };
    let before = build(ShiftCriterion::Storage);
    let after = build(ShiftCriterion::SlopeWeighted);
    assert_eq!(before.t_ref_c, after.t_ref_c);
    let (eb, ea) = (
        errors(&before, &compound.law),
        errors(&after, &compound.law),
    );
    println!("T (°C)    error E′ alone   error slope-weighted   carried by");
    for ((t, b), ((_, a), s)) in eb.iter().zip(ea.iter().zip(&after.isotherms)) {
        println!(
            "{t:>7.2}   {b:>+13.4}   {a:>+20.4}   {}",
            s.shift_channel.as_deref().unwrap_or("-")
        );
    }
    let worst = |e: &[(f64, f64)]| {
        e.iter()
            .filter(|(t, _)| *t >= FROM_C)
            .map(|(_, v)| v.abs())
            .fold(0.0, f64::max)
    };
    println!(
        "worst from {FROM_C} °C up: E′ alone {:.4}, slope-weighted {:.4} decade",
        worst(&eb),
        worst(&ea)
    );
    assert!(
        worst(&ea) <= BOUND_DECADES,
        "slope-weighted worst {:.4} > {BOUND_DECADES}",
        worst(&ea)
    );
    // Where E′ is flat E″ carries the shift: the hottest isotherm says so.
    assert_eq!(
        after.isotherms.last().unwrap().shift_channel.as_deref(),
        Some("E″")
    );
}
