//! Synthetic time-domain exports (docs/MATH.md §18): relaxation E(t) or creep D(t) isotherms of a
//! known [`RelaxationSpectrum`] shifted by a known [`ShiftLaw`], with seeded multiplicative noise, as
//! the generic CSV that [`crate::dma::time_domain`] reads (`T [°C], time [s], E(t) [MPa]` or
//! `D(t) [1/MPa]`).

use super::SplitMix64;
use crate::dma::time_domain::TimeMode;
use crate::{RelaxationSpectrum, ShiftLaw};

/// What [`time_domain_csv`] makes.
#[derive(Debug, Clone)]
pub struct TimeSettings {
    /// Isotherm temperatures, °C.
    pub temps_c: Vec<f64>,
    /// Time window of every isotherm, s.
    pub window_s: (f64, f64),
    /// Points per decade of time.
    pub per_decade: usize,
    /// Relative standard deviation of the multiplicative Gaussian noise (0.01 = 1 %).
    pub noise_rel: f64,
    /// Seed.
    pub seed: u64,
}

/// The CSV of `mode` isotherms of `spectrum` under `law` (module docs).
pub fn time_domain_csv(
    spectrum: &RelaxationSpectrum,
    mode: TimeMode,
    law: &ShiftLaw,
    s: &TimeSettings,
) -> String {
    let creep = match mode {
        TimeMode::Creep => Some(
            crate::creep::relaxation_to_creep(spectrum)
                .expect("a solid")
                .0,
        ),
        TimeMode::Relaxation => None,
    };
    let mut rng = SplitMix64::new(s.seed);
    let mut out = match mode {
        TimeMode::Relaxation => "T [°C],time [s],E(t) [MPa]\n",
        TimeMode::Creep => "T [°C],time [s],D(t) [1/MPa]\n",
    }
    .to_string();
    let (t0, t1) = s.window_s;
    let n = ((t1 / t0).log10() * s.per_decade as f64).round() as usize;
    for &temp in &s.temps_c {
        let a_t = 10f64.powf(law.log10_a_t(temp));
        for k in 0..=n {
            let t = t0 * 10f64.powf(k as f64 / s.per_decade as f64);
            let noise = 1.0 + s.noise_rel * rng.normal();
            let v = match &creep {
                None => spectrum.relaxation_modulus(t / a_t) / 1e6,
                Some(c) => c.creep_compliance(t / a_t) * 1e6,
            };
            out.push_str(&format!("{temp},{t:.6e},{:.8e}\n", v * noise));
        }
    }
    out
}
