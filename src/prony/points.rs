//! The plain data the Prony fit and its term reduction share: master-curve points ([`MasterPoint`])
//! and the log10 errors of a spectrum against them ([`log10_errors`], docs/MATH.md §5).
//!
//! Input: points and a [`RelaxationSpectrum`]; output: [`Log10Errors`]. Below both `fit` and `terms`.

use super::kernel::dynamic_moduli_pa;
use super::RelaxationSpectrum;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// RMS and largest |log10(fit/datum)| of E′ and E″.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Log10Errors {
    /// RMS log10 error of E′.
    pub rms_storage: f64,
    /// RMS log10 error of E″.
    pub rms_loss: f64,
    /// Largest |log10 error| of E′.
    pub max_storage: f64,
    /// Largest |log10 error| of E″.
    pub max_loss: f64,
}

/// log10 errors of `spectrum` against master-curve points (independent of how it was fitted).
pub fn log10_errors(points: &[MasterPoint], spectrum: &RelaxationSpectrum) -> Log10Errors {
    let (mut ss, mut sl, mut ms, mut ml) = (0.0, 0.0, 0.0f64, 0.0f64);
    for p in points {
        let (e1, e2) = dynamic_moduli_pa(spectrum, 2.0 * PI * p.reduced_freq_hz);
        let d1 = (e1 / p.storage_pa).log10();
        let d2 = (e2 / p.loss_pa).log10();
        ss += d1 * d1;
        sl += d2 * d2;
        ms = ms.max(d1.abs());
        ml = ml.max(d2.abs());
    }
    let m = points.len().max(1) as f64;
    Log10Errors {
        rms_storage: (ss / m).sqrt(),
        rms_loss: (sl / m).sqrt(),
        max_storage: ms,
        max_loss: ml,
    }
}

/// One point of a master curve at the reference temperature: the input of the Prony fit.
///
/// A plain type so that the fit does not depend on how the master curve was built.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MasterPoint {
    /// Reduced frequency a_T·f in Hz (ω = 2π·reduced_freq_hz).
    pub reduced_freq_hz: f64,
    /// Storage modulus E′ (or G′) in Pa.
    pub storage_pa: f64,
    /// Loss modulus E″ (or G″) in Pa.
    pub loss_pa: f64,
}
