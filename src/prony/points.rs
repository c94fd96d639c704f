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

/// log10 errors of `spectrum` against master-curve points (independent of how it was fitted). The
/// RMS values weight each point's squared error by its weight squared, as the fit does (docs/MATH.md
/// eq. 5.1: the misfit measured against what the point is known to within), and equal the plain
/// RMS when every weight is 1; the largest errors are over the points of full weight in both moduli
/// (over all points if there are none).
pub fn log10_errors(points: &[MasterPoint], spectrum: &RelaxationSpectrum) -> Log10Errors {
    let (mut ss, mut sl, mut ws, mut wl) = (0.0, 0.0, 0.0, 0.0);
    let (mut ms, mut ml, mut ms_all, mut ml_all) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for p in points {
        let (e1, e2) = dynamic_moduli_pa(spectrum, 2.0 * PI * p.reduced_freq_hz);
        let d1 = (e1 / p.storage_pa).log10();
        let d2 = (e2 / p.loss_pa).log10();
        let (w1, w2) = (p.weight[0] * p.weight[0], p.weight[1] * p.weight[1]);
        ss += w1 * d1 * d1;
        sl += w2 * d2 * d2;
        ws += w1;
        wl += w2;
        ms_all = ms_all.max(d1.abs());
        ml_all = ml_all.max(d2.abs());
        if is_unit_weight(&p.weight) {
            ms = ms.max(d1.abs());
            ml = ml.max(d2.abs());
        }
    }
    let full = points.iter().any(|p| is_unit_weight(&p.weight));
    Log10Errors {
        rms_storage: (ss / ws.max(f64::MIN_POSITIVE)).sqrt(),
        rms_loss: (sl / wl.max(f64::MIN_POSITIVE)).sqrt(),
        max_storage: if full { ms } else { ms_all },
        max_loss: if full { ml } else { ml_all },
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
    /// Weights of this point's E′ and E″ residuals in the fit (1, 1 unless the point's reduced
    /// frequency is uncertain: `crate::tts::point_weights`, docs/MATH.md eq. 5.1).
    #[serde(default = "unit_weight", skip_serializing_if = "is_unit_weight")]
    pub weight: [f64; 2],
}

impl MasterPoint {
    /// A point with unit weights.
    pub fn new(reduced_freq_hz: f64, storage_pa: f64, loss_pa: f64) -> Self {
        Self {
            reduced_freq_hz,
            storage_pa,
            loss_pa,
            weight: unit_weight(),
        }
    }
}

fn unit_weight() -> [f64; 2] {
    [1.0, 1.0]
}

fn is_unit_weight(w: &[f64; 2]) -> bool {
    *w == unit_weight()
}

impl RelaxationSpectrum {
    /// RMS and largest |log10| errors of this spectrum's E′ and E″ on `points` (`log10_errors`).
    pub fn log10_errors(&self, points: &[MasterPoint]) -> Log10Errors {
        log10_errors(points, self)
    }
}
