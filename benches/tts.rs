//! Master-curve construction (automatic shifting, WLF/Arrhenius fits, quality figures) on the real
//! sets in `data/`: EMS-CA (EPLEXOR .xls, 21 isotherms × 10 frequencies) and the DMA-analysis-suite
//! tensile set (22 isotherms × 60 frequencies), read once outside the timing, and a synthetic set
//! of the EMS-CA size with 1 % noise. Run: `cargo bench --bench tts` (prints a table: median and
//! fastest call).

#[path = "support/timing.rs"]
mod timing;

use std::hint::black_box;
use viscoroll::dma::{read_files, IngestOptions};
use viscoroll::testdata::{broad_spectrum, synthetic_measurement, SyntheticSettings};
use viscoroll::tts::{build_master_curve, MasterSettings};
use viscoroll::ShiftLaw;

fn main() {
    timing::header("tts: build_master_curve");
    let st = MasterSettings::default();
    let opts = IngestOptions::default();
    let ems = read_files(&["data/pyvisco-ems-ca/freq_Eplexor_raw.xls"], &opts).unwrap();
    timing::row("master_curve_ems_ca", || {
        build_master_curve(black_box(&ems), &st).unwrap()
    });
    let mut files: Vec<String> = std::fs::read_dir("data/dmasuite-tensile")
        .unwrap()
        .filter_map(|e| {
            let p = e.ok()?.path();
            (p.extension()? == "txt").then(|| p.display().to_string())
        })
        .collect();
    files.sort();
    let suite = read_files(&files, &opts).unwrap();
    timing::row("master_curve_dmasuite_22x60", || {
        build_master_curve(black_box(&suite), &st).unwrap()
    });
    // Synthetic, the round-trip test's law, 21 isotherms × 10 frequencies, 1 % noise.
    let law = ShiftLaw::Wlf {
        t_ref_c: 20.0,
        c1: 10.0,
        c2_k: 150.0,
    };
    let temps: Vec<f64> = (0..21).map(|i| -40.0 + 6.0 * i as f64).collect();
    let mut s = SyntheticSettings::new(temps, law);
    s.noise_rel = 0.01;
    let syn = synthetic_measurement(&broad_spectrum(), &s);
    timing::row("master_curve_synthetic_21x10", || {
        build_master_curve(black_box(&syn), &st).unwrap()
    });
}
