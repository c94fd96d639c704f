//! Prony fit on the EMS-CA master curve (data/pyvisco-ems-ca/freq_user_master.csv: 206 points over
//! 26 decades), default settings (2 per decade → 55 times, GCV over 12 λ, i.e. 12 clarabel QP solves),
//! and the same with 0.6 per decade (18 terms). Measures the whole `fit_prony` call: design matrix,
//! QR, λ search, term dropping and error figures. Target (issue 7): master curve + Prony fit + creep
//! conversion ≤ 100 ms for EMS-CA.
//!
//! Run: `cargo bench --bench prony` (prints a table: median and fastest call).

#[path = "support/timing.rs"]
mod timing;

use std::hint::black_box;
use viscoroll::prony::{fit_prony, MasterPoint, PronySettings};
use viscoroll::ModulusKind;

fn ems_ca_master() -> Vec<MasterPoint> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/data/pyvisco-ems-ca/freq_user_master.csv"
    );
    let text = std::fs::read_to_string(path).expect("EMS-CA master curve");
    text.lines()
        .skip(2) // name row, unit row (Hz, MPa, MPa)
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let v: Vec<f64> = l
                .split(',')
                .map(|s| s.trim().parse().expect("number"))
                .collect();
            MasterPoint::new(v[0], v[1] * 1e6, v[2] * 1e6)
        })
        .collect()
}

fn main() {
    let pts = ems_ca_master();
    timing::header("prony: fit_prony on the EMS-CA master curve");
    for per_decade in [2.0, 0.6] {
        let s = PronySettings {
            terms_per_decade: per_decade,
            ..PronySettings::default()
        };
        timing::row(&format!("per_decade_{per_decade}"), || {
            fit_prony(black_box(&pts), ModulusKind::Tensile, 0.5, black_box(&s)).unwrap()
        });
    }
}
