//! Known-answer master curves for tests, benches and doctests: a smooth, rubber-like relaxation
//! spectrum and master-curve points generated from it (exact, or with seeded multiplicative noise).
//!
//! Input: a spectrum (or its parameters); output: [`MasterPoint`]s. Generator: thesis eq. 2.9 in the
//! frequency domain ([`super::kernel`]).

use super::kernel::dynamic_moduli_pa;
use super::{MasterPoint, RelaxationSpectrum, RelaxationTerm};
use crate::material::ModulusKind;
use std::f64::consts::PI;

/// A rubber-like spectrum at the given relaxation times: E∞ = 1 MPa and a Gaussian bump in log10 ρ
/// (centre 1e-4 s, width 2 decades) whose strengths sum to about 1 GPa (glassy/rubbery ≈ 1000, like a
/// filled elastomer through its glass transition).
pub(crate) fn rubber_like_spectrum(taus_s: &[f64]) -> RelaxationSpectrum {
    let centre = -4.0f64;
    let width = 2.0f64;
    let raw: Vec<f64> = taus_s
        .iter()
        .map(|t| (-0.5 * ((t.log10() - centre) / width).powi(2)).exp())
        .collect();
    let sum: f64 = raw.iter().sum();
    RelaxationSpectrum {
        kind: ModulusKind::Tensile,
        poisson: 0.5,
        modulus_inf_pa: 1e6,
        terms: taus_s
            .iter()
            .zip(&raw)
            .map(|(&tau_s, &w)| RelaxationTerm {
                modulus_pa: 1e9 * w / sum,
                tau_s,
            })
            .collect(),
    }
}

/// Master-curve points of `spectrum`, `per_decade` log-spaced reduced frequencies from `freq_min_hz`
/// to `freq_max_hz`, each modulus multiplied by (1 + `noise_rel`·g) with g a seeded standard normal.
pub(crate) fn master_points(
    spectrum: &RelaxationSpectrum,
    freq_min_hz: f64,
    freq_max_hz: f64,
    per_decade: f64,
    noise_rel: f64,
    seed: u64,
) -> Vec<MasterPoint> {
    let (l0, l1) = (freq_min_hz.log10(), freq_max_hz.log10());
    let n = (((l1 - l0) * per_decade).round() as usize + 1).max(2);
    let mut rng = Normal::new(seed);
    (0..n)
        .map(|k| {
            let f = 10f64.powf(l0 + (l1 - l0) * k as f64 / (n - 1) as f64);
            let (e1, e2) = dynamic_moduli_pa(spectrum, 2.0 * PI * f);
            MasterPoint::new(
                f,
                e1 * (1.0 + noise_rel * rng.next()),
                e2 * (1.0 + noise_rel * rng.next()),
            )
        })
        .collect()
}

/// A small seeded standard-normal generator (SplitMix64 + Box–Muller), so fixtures need no RNG crate.
struct Normal {
    state: u64,
}

impl Normal {
    fn new(seed: u64) -> Self {
        Self { state: seed }
    }

    fn uniform(&mut self) -> f64 {
        // SplitMix64 (Steele, Lea & Flood 2014).
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        ((z >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    fn next(&mut self) -> f64 {
        let (u1, u2) = (self.uniform(), self.uniform());
        (-2.0 * u1.ln()).sqrt() * (2.0 * PI * u2).cos()
    }
}
