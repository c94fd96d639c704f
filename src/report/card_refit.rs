//! A spectrum refitted with fewer terms for a card format with a cap on Prony cards (LS-DYNA's
//! `*MAT_GENERAL_VISCOELASTIC` takes at most [`super::cards::LSDYNA_MAX_TERMS`]). Input: the
//! spectrum and, when there is one, the fit file it came from; output: `CardRefit` — the refitted
//! spectrum, its RMS log10 errors of E′ and E″, and what it was fitted against.
//!
//! The refit is the project's Prony QP with term reduction (docs/MATH.md §5, [`crate::prony`]): to
//! the fit file's master curve with the fit's own Prony settings, or, for a bare spectrum, to its own
//! E′, E″ at 10 points per decade (at least 10 intervals) over the frequencies 1/(2πτ) of its
//! relaxation times, with the default settings.

use crate::prony::{fit_prony, log10_errors, MasterPoint, PronyError, PronySettings};
use crate::results::CompoundFit;
use crate::RelaxationSpectrum;
use std::f64::consts::PI;

/// The result of [`refit_for_cards`].
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct CardRefit {
    /// The refitted spectrum.
    pub spectrum: RelaxationSpectrum,
    /// RMS log10 errors of E′ and E″ against the data it was fitted to.
    pub rms_log10: [f64; 2],
    /// What it was fitted to, for the card's note.
    pub against: &'static str,
}

/// Refit `spectrum` with at most `max_cards` cards (E∞, when positive, takes one): to the fit file's
/// master curve, or to the spectrum's own moduli (module doc).
pub(crate) fn refit_for_cards(
    spectrum: &RelaxationSpectrum,
    fit: Option<&CompoundFit>,
    max_cards: usize,
) -> Result<CardRefit, PronyError> {
    let (points, settings, against): (Vec<MasterPoint>, PronySettings, &str) = match fit {
        Some(f) => (
            f.master_curve.clone(),
            f.settings.prony.clone(),
            "the fit file's master curve",
        ),
        None => (
            own_moduli(spectrum),
            PronySettings::default(),
            match spectrum.kind {
                crate::ModulusKind::Shear => "the spectrum's own G′, G″",
                crate::ModulusKind::Tensile => "the spectrum's own E′, E″",
            },
        ),
    };
    let cards_for_inf = usize::from(spectrum.modulus_inf_pa > 0.0);
    let settings = PronySettings {
        reduce_terms: true,
        max_terms: Some(max_cards.saturating_sub(cards_for_inf).max(1)),
        target_rms_log10: None,
        ..settings
    };
    let refit = fit_prony(&points, spectrum.kind, spectrum.poisson, &settings)?;
    let e = log10_errors(&points, &refit.spectrum);
    Ok(CardRefit {
        spectrum: refit.spectrum,
        rms_log10: [e.rms_storage, e.rms_loss],
        against,
    })
}

/// The spectrum's own E′, E″ at 10 points per decade (at least 10 intervals) over 1/(2πτ_max) …
/// 1/(2πτ_min).
fn own_moduli(spectrum: &RelaxationSpectrum) -> Vec<MasterPoint> {
    let (lo, hi) = spectrum
        .terms
        .iter()
        .fold((f64::INFINITY, 0f64), |(a, b), t| {
            (a.min(t.tau_s), b.max(t.tau_s))
        });
    let (f0, f1) = (1.0 / (2.0 * PI * hi), 1.0 / (2.0 * PI * lo));
    let n = (((f1 / f0).log10() * 10.0).ceil() as usize).max(10);
    (0..=n)
        .map(|k| {
            let f = f0 * (f1 / f0).powf(k as f64 / n as f64);
            let (e1, e2) = spectrum.complex_modulus(2.0 * PI * f);
            MasterPoint::new(f, e1, e2)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::prony::RelaxationTerm;
    use crate::ModulusKind;

    /// A 30-term spectrum (one term per 0.3 decade over 9 decades) refitted for 18 cards: at most 17
    /// relaxation terms beside E∞, fitted to its own moduli to better than 0.01 decade RMS (a smooth
    /// spectrum sampled this densely is followed closely by half as many terms; the bound is loose
    /// against the few 1e−3 the QP reaches, tight against a wrong grid or a dropped E∞).
    #[test]
    fn a_long_spectrum_fits_in_eighteen_cards() {
        let spectrum = RelaxationSpectrum {
            kind: ModulusKind::Tensile,
            poisson: 0.5,
            modulus_inf_pa: 2e6,
            terms: (0..30)
                .map(|j| RelaxationTerm {
                    modulus_pa: 1e6,
                    tau_s: 10f64.powf(-6.0 + 0.3 * j as f64),
                })
                .collect(),
        };
        let r = refit_for_cards(&spectrum, None, 18).unwrap();
        assert!(r.spectrum.terms.len() <= 17, "{}", r.spectrum.terms.len());
        assert!(r.spectrum.modulus_inf_pa > 0.0);
        assert!(
            r.rms_log10[0] < 0.01 && r.rms_log10[1] < 0.01,
            "{:?}",
            r.rms_log10
        );
        assert_eq!(r.against, "the spectrum's own E′, E″");
    }
}
