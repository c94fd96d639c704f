//! Known-answer data shared by tests, doctests and benches of every stage: relaxation spectra with
//! closed-form moduli and synthetic DMA measurements made from them.
//!
//! A [`RelaxationSpectrum`] E(t) = E∞ + Σ Eᵢ e^(−t/τᵢ) (thesis eq. 2.9) has the dynamic moduli
//!
//! ```text
//! E′(ω) = E∞ + Σ Eᵢ (ωτᵢ)² / (1 + (ωτᵢ)²),     E″(ω) = Σ Eᵢ ωτᵢ / (1 + (ωτᵢ)²).
//! ```
//!
//! [`synthetic_measurement`] evaluates them at the reduced angular frequency ω_r = 2π f a_T(T) of a
//! given [`ShiftLaw`] (time–temperature superposition, docs/MATH.md §6) for each isotherm, with seeded
//! multiplicative Gaussian noise and a seeded offset of the actual temperature from the nominal one.

pub(crate) mod realistic;
pub(crate) mod time_domain;

pub use realistic::{
    dma_csv, dma_rows, non_overlapping_compounds, realistic_compounds, DmaProtocol, ExportFormat,
    RealisticCompound,
};
pub use time_domain::{time_domain_csv, TimeSettings};

use crate::dma::{DataPoint, Isotherm, Measurement, SourceFile};
use crate::prony::{RelaxationSpectrum, RelaxationTerm};
use crate::{ModulusKind, ShiftLaw};
use std::collections::BTreeMap;

/// Storage modulus E′(ω) of a Prony series, ω in rad/s.
pub(crate) fn storage_modulus(spectrum: &RelaxationSpectrum, omega_rad_s: f64) -> f64 {
    spectrum.modulus_inf_pa
        + spectrum
            .terms
            .iter()
            .map(|t| {
                let wt = omega_rad_s * t.tau_s;
                t.modulus_pa * wt * wt / (1.0 + wt * wt)
            })
            .sum::<f64>()
}

/// Loss modulus E″(ω) of a Prony series, ω in rad/s.
pub(crate) fn loss_modulus(spectrum: &RelaxationSpectrum, omega_rad_s: f64) -> f64 {
    spectrum
        .terms
        .iter()
        .map(|t| {
            let wt = omega_rad_s * t.tau_s;
            t.modulus_pa * wt / (1.0 + wt * wt)
        })
        .sum()
}

/// `n` values from `a` to `b` (both > 0), equally spaced in log.
pub(crate) fn log_spaced(a: f64, b: f64, n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![a];
    }
    let (la, lb) = (a.log10(), b.log10());
    (0..n)
        .map(|i| 10f64.powf(la + (lb - la) * i as f64 / (n - 1) as f64))
        .collect()
}

/// A broad tensile spectrum shaped like a glassy-to-rubbery polymer (E′ ≈ 9 GPa glassy, 90 MPa
/// rubbery, like the EMS-CA data): 2 terms per decade, τ = 10⁻¹²…10⁴ s, strengths on a
/// log-normal bell centred at τ = 10⁻⁴ s with a width of 2.5 decades.
pub fn broad_spectrum() -> RelaxationSpectrum {
    let terms = (0..=32)
        .map(|i| {
            let log_tau = -12.0 + 0.5 * i as f64;
            let z = (log_tau + 4.0) / 2.5;
            RelaxationTerm {
                modulus_pa: 7.0e8 * (-0.5 * z * z).exp(),
                tau_s: 10f64.powf(log_tau),
            }
        })
        .collect();
    RelaxationSpectrum {
        kind: ModulusKind::Tensile,
        poisson: 0.5,
        modulus_inf_pa: 9.0e7,
        terms,
    }
}

/// What [`synthetic_measurement`] makes.
#[derive(Debug, Clone)]
pub struct SyntheticSettings {
    /// Nominal temperatures of the isotherms in °C.
    pub temps_c: Vec<f64>,
    /// Frequencies of every isotherm in Hz.
    pub freqs_hz: Vec<f64>,
    /// The shift law used to generate the data (the answer a shifting should find).
    pub law: ShiftLaw,
    /// Relative standard deviation of the multiplicative Gaussian noise on E′ and E″ (0.01 = 1 %).
    pub noise_rel: f64,
    /// Actual temperature − nominal is drawn uniformly in ±this, per isotherm, in K. The data are
    /// generated at the actual temperature, which is reported as `temp_mean_c` and per point.
    pub temp_offset_k: f64,
    /// Seed of the generator (same seed, same data).
    pub seed: u64,
}

impl SyntheticSettings {
    /// EMS-CA-like layout: `temps_c` isotherms × 10 frequencies 0.1–100 Hz (3⅓ per decade), no
    /// noise, no temperature offset.
    pub fn new(temps_c: Vec<f64>, law: ShiftLaw) -> SyntheticSettings {
        SyntheticSettings {
            temps_c,
            freqs_hz: log_spaced(0.1, 100.0, 10),
            law,
            noise_rel: 0.0,
            temp_offset_k: 0.0,
            seed: 1,
        }
    }
}

/// Isothermal sweeps of `spectrum` shifted by `settings.law` (see the module docs).
pub fn synthetic_measurement(
    spectrum: &RelaxationSpectrum,
    settings: &SyntheticSettings,
) -> Measurement {
    let mut rng = SplitMix64::new(settings.seed);
    let mut isotherms = Vec::with_capacity(settings.temps_c.len());
    let mut line = 1;
    for &nominal in &settings.temps_c {
        let actual = nominal + settings.temp_offset_k * (2.0 * rng.uniform() - 1.0);
        let a_t = 10f64.powf(settings.law.log10_a_t(actual));
        let points = settings
            .freqs_hz
            .iter()
            .map(|&f| {
                let w = 2.0 * std::f64::consts::PI * f * a_t;
                let storage =
                    storage_modulus(spectrum, w) * (1.0 + settings.noise_rel * rng.normal());
                let loss = loss_modulus(spectrum, w) * (1.0 + settings.noise_rel * rng.normal());
                line += 1;
                DataPoint {
                    freq_hz: f,
                    storage_pa: storage,
                    loss_pa: loss,
                    temp_c: Some(actual),
                    line,
                    flags: vec![],
                }
            })
            .collect();
        isotherms.push(Isotherm {
            temp_nominal_c: nominal,
            temp_mean_c: actual,
            source: 0,
            points,
            nominal_source: "synthetic".into(),
            sheet: None,
            label: None,
        });
    }
    Measurement {
        sources: vec![SourceFile {
            path: "synthetic".into(),
            sha256: String::new(),
            format: "synthetic".into(),
            metadata: BTreeMap::new(),
            encoding: String::new(),
            columns: vec![],
        }],
        kind: spectrum.kind,
        poisson: spectrum.poisson,
        isotherms,
        warnings: vec![],
        issues: vec![],
        summary: Default::default(),
    }
}

/// A small seeded generator (SplitMix64, Steele, Lea & Flood 2014), enough for test noise.
#[derive(Debug, Clone)]
pub(crate) struct SplitMix64(u64);

impl SplitMix64 {
    /// Generator with the given seed.
    pub fn new(seed: u64) -> SplitMix64 {
        SplitMix64(seed)
    }

    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Standard normal (Box–Muller).
    pub fn normal(&mut self) -> f64 {
        let u1 = 1.0 - self.uniform();
        let u2 = self.uniform();
        (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn moduli_limits() {
        // ω → 0: E′ → E∞, E″ → 0; ω → ∞: E′ → E∞ + ΣEᵢ (the glassy modulus).
        let s = broad_spectrum();
        let sum: f64 = s.terms.iter().map(|t| t.modulus_pa).sum();
        assert!((storage_modulus(&s, 1e-12) / s.modulus_inf_pa - 1.0).abs() < 1e-6);
        assert!(loss_modulus(&s, 1e-12) < 1e-6 * s.modulus_inf_pa);
        assert!((storage_modulus(&s, 1e20) / (s.modulus_inf_pa + sum) - 1.0).abs() < 1e-6);
    }

    #[test]
    fn noise_has_the_stated_spread() {
        // 20 000 normals: sample sd within 3 % of 1 (its standard error is 1/√(2n) ≈ 0.5 %).
        let mut r = SplitMix64::new(7);
        let n = 20_000;
        let xs: Vec<f64> = (0..n).map(|_| r.normal()).collect();
        let mean = xs.iter().sum::<f64>() / n as f64;
        let sd = (xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n as f64).sqrt();
        assert!(mean.abs() < 0.03 && (sd - 1.0).abs() < 0.03, "{mean} {sd}");
    }
}
