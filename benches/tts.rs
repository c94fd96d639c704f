//! Master-curve construction (automatic shifting, fits, quality) on synthetic measurements of the
//! sizes of the real sets: EMS-CA (21 isotherms × 10 frequencies) and the DMA-suite tensile set
//! (22 isotherms × 60 frequencies), 1 % noise. Run: `cargo bench --bench tts`.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use viscoroll::testdata::{broad_spectrum, log_spaced, synthetic_measurement, SyntheticSettings};
use viscoroll::tts::{build_master_curve, MasterSettings};
use viscoroll::ShiftLaw;

fn bench(c: &mut Criterion) {
    let law = ShiftLaw::Wlf {
        t_ref_c: 25.0,
        c1: 13.5,
        c2_k: 141.19,
    };
    // EMS-CA layout: −50…100 °C every 7.5 K; frequencies 0.1–100 Hz.
    let temps: Vec<f64> = (0..21).map(|i| -50.0 + 7.5 * i as f64).collect();
    let mut s = SyntheticSettings::new(temps, law.clone());
    s.noise_rel = 0.01;
    let ems = synthetic_measurement(&broad_spectrum(), &s);
    // DMA-suite layout: 0…105 °C every 5 K, 60 frequencies 0.1–89 Hz.
    let temps: Vec<f64> = (0..22).map(|i| 5.0 * i as f64).collect();
    let mut s = SyntheticSettings::new(temps, law);
    s.freqs_hz = log_spaced(0.1, 89.0, 60);
    s.noise_rel = 0.01;
    let suite = synthetic_measurement(&broad_spectrum(), &s);
    let st = MasterSettings::default();
    c.bench_function("master_curve_21x10_ems_ca_size", |b| {
        b.iter(|| build_master_curve(black_box(&ems), &st).unwrap())
    });
    c.bench_function("master_curve_22x60_dmasuite_size", |b| {
        b.iter(|| build_master_curve(black_box(&suite), &st).unwrap())
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
