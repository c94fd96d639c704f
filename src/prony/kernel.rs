//! The Prony-series kernels of the dynamic moduli (thesis eq. 2.9 transformed to the frequency
//! domain) and their evaluation for a [`RelaxationSpectrum`].
//!
//! For E(t) = E∞ + Σᵢ Eᵢ e^(−t/ρᵢ):
//!
//! ```text
//!   E′(ω) = E∞ + Σᵢ Eᵢ (ωρᵢ)² / (1 + (ωρᵢ)²)
//!   E″(ω) =      Σᵢ Eᵢ  ωρᵢ   / (1 + (ωρᵢ)²)
//! ```
//!
//! ω is the angular frequency in rad/s (ω = 2πf). These free functions serve the fit and the plots;
//! they do not replace spectrum methods owned by the `creep`/spectra stage.

use crate::prony::RelaxationSpectrum;

/// Storage kernel (ωρ)²/(1+(ωρ)²) of one Maxwell element; `w_rho` = ωρ (dimensionless).
#[inline]
pub(crate) fn storage_kernel(w_rho: f64) -> f64 {
    let x2 = w_rho * w_rho;
    x2 / (1.0 + x2)
}

/// Loss kernel ωρ/(1+(ωρ)²) of one Maxwell element; `w_rho` = ωρ (dimensionless).
#[inline]
pub(crate) fn loss_kernel(w_rho: f64) -> f64 {
    w_rho / (1.0 + w_rho * w_rho)
}

/// (E′, E″) in Pa of `spectrum` at angular frequency `omega_rad_s`.
pub fn dynamic_moduli_pa(spectrum: &RelaxationSpectrum, omega_rad_s: f64) -> (f64, f64) {
    let mut storage = spectrum.modulus_inf_pa;
    let mut loss = 0.0;
    for term in &spectrum.terms {
        let w_rho = omega_rad_s * term.tau_s;
        storage += term.modulus_pa * storage_kernel(w_rho);
        loss += term.modulus_pa * loss_kernel(w_rho);
    }
    (storage, loss)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::ModulusKind;
    use crate::prony::RelaxationTerm;

    #[test]
    fn single_maxwell_element_limits_and_peak() {
        let s = RelaxationSpectrum {
            kind: ModulusKind::Tensile,
            poisson: 0.5,
            modulus_inf_pa: 1e6,
            terms: vec![RelaxationTerm {
                modulus_pa: 1e9,
                tau_s: 1e-3,
            }],
        };
        // ω → 0: E′ → E∞, E″ → 0; ω → ∞: E′ → E∞ + E₁ (the glassy modulus).
        let (e1, l1) = dynamic_moduli_pa(&s, 1e-9);
        assert!((e1 - 1e6).abs() < 1e-6 * 1e6 && l1 < 1e-2);
        let (e2, _) = dynamic_moduli_pa(&s, 1e15);
        assert!((e2 - (1e6 + 1e9)).abs() < 1e-9 * 1e9);
        // At ωρ = 1 the loss peaks at E₁/2 and E′ = E∞ + E₁/2 (exact, up to rounding).
        let (e3, l3) = dynamic_moduli_pa(&s, 1e3);
        assert!((l3 - 5e8).abs() < 1e-6);
        assert!((e3 - (1e6 + 5e8)).abs() < 1e-6);
    }
}
