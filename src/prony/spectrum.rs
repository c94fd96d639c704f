//! Evaluation of a [`RelaxationSpectrum`] (thesis eq. 2.9): E(t), E′(ω), E″(ω), tan δ, |E*|, the
//! instantaneous modulus E₀; validation; the spectrum at another temperature through a [`ShiftLaw`];
//! tensile ↔ shear conversion.
//!
//! Input and output: [`RelaxationSpectrum`] (plain serde type of `prony/mod.rs`). Errors are the shared
//! [`MaterialError`] of the ground floor (the creep stage wraps it in its own error).
//!
//! Formulas (generalised Maxwell model, one term Eᵢe^(−t/ρᵢ) ↔ Eᵢ iωρᵢ/(1 + iωρᵢ)):
//! E′(ω) = E∞ + Σ Eᵢω²ρᵢ²/(1 + ω²ρᵢ²), E″(ω) = Σ Eᵢωρᵢ/(1 + ω²ρᵢ²), E₀ = E(0) = E∞ + Σ Eᵢ.

use crate::material::{
    check_poisson, check_positive, debye, shift_at, AtTemperature, MaterialError, ModulusKind,
    ShiftLaw,
};
use crate::prony::{RelaxationSpectrum, RelaxationTerm};

impl RelaxationSpectrum {
    /// Instantaneous (glassy) modulus E₀ = E(0) = E∞ + Σ Eᵢ in Pa.
    pub fn instantaneous_modulus(&self) -> f64 {
        self.modulus_inf_pa + self.terms.iter().map(|t| t.modulus_pa).sum::<f64>()
    }

    /// Relaxation modulus E(t) = E∞ + Σ Eᵢ e^(−t/ρᵢ) in Pa at `t_s` ≥ 0 (eq. 2.9).
    pub fn relaxation_modulus(&self, t_s: f64) -> f64 {
        self.modulus_inf_pa
            + self
                .terms
                .iter()
                .map(|r| r.modulus_pa * (-t_s / r.tau_s).exp())
                .sum::<f64>()
    }

    /// (E′, E″) at ω in rad/s, in Pa.
    pub fn complex_modulus(&self, omega_rad_s: f64) -> (f64, f64) {
        let mut re = self.modulus_inf_pa;
        let mut im = 0.0;
        for r in &self.terms {
            let (_, d2, d1) = debye(omega_rad_s * r.tau_s);
            re += r.modulus_pa * d2;
            im += r.modulus_pa * d1;
        }
        (re, im)
    }

    /// Storage modulus E′(ω) in Pa, ω in rad/s.
    pub fn storage_modulus(&self, omega_rad_s: f64) -> f64 {
        self.complex_modulus(omega_rad_s).0
    }

    /// Loss modulus E″(ω) in Pa, ω in rad/s.
    pub fn loss_modulus(&self, omega_rad_s: f64) -> f64 {
        self.complex_modulus(omega_rad_s).1
    }

    /// Loss tangent tan δ = E″/E′ at ω in rad/s.
    pub(crate) fn tan_delta(&self, omega_rad_s: f64) -> f64 {
        let (re, im) = self.complex_modulus(omega_rad_s);
        im / re
    }

    /// Dynamic modulus |E*(ω)| = √(E′² + E″²) in Pa, ω in rad/s.
    pub fn abs_complex_modulus(&self, omega_rad_s: f64) -> f64 {
        let (re, im) = self.complex_modulus(omega_rad_s);
        re.hypot(im)
    }

    /// Check that the spectrum is admissible: E∞ ≥ 0, Eᵢ ≥ 0, ρᵢ > 0, all finite, E₀ > 0,
    /// ν in (−1, 0.5]. (E∞ = 0, a fluid, is admissible here: crate::creep::fluid_to_creep.)
    pub fn validate(&self) -> Result<(), MaterialError> {
        check_poisson(self.poisson)?;
        check_positive(|| "modulus_inf_pa".into(), self.modulus_inf_pa, true)?;
        for (i, r) in self.terms.iter().enumerate() {
            check_positive(|| format!("terms[{i}].modulus_pa"), r.modulus_pa, true)?;
            check_positive(|| format!("terms[{i}].tau_s"), r.tau_s, false)?;
        }
        check_positive(
            || "instantaneous modulus E∞ + Σ terms[].modulus_pa".into(),
            self.instantaneous_modulus(),
            false,
        )
    }

    /// The spectrum at `temp_c` (°C): every ρᵢ multiplied by a_T = 10^(log10 a_T) of `law`. When
    /// `measured_range_c` (lowest, highest measured temperature in °C) is given, a temperature outside
    /// it is allowed but flagged as `extrapolated`.
    pub fn at_temperature(
        &self,
        law: &ShiftLaw,
        temp_c: f64,
        measured_range_c: Option<(f64, f64)>,
    ) -> Result<AtTemperature<RelaxationSpectrum>, MaterialError> {
        let (log10_a_t, extrapolated) = shift_at(law, temp_c, measured_range_c)?;
        let a_t = 10f64.powf(log10_a_t);
        let mut spectrum = self.clone();
        for r in &mut spectrum.terms {
            r.tau_s *= a_t;
        }
        Ok(AtTemperature {
            spectrum,
            temp_c,
            log10_a_t,
            extrapolated,
        })
    }

    /// The same material as a modulus of another kind: G = E/(2(1+ν)) (Poisson's ratio constant in time).
    pub fn to_kind(&self, kind: ModulusKind) -> RelaxationSpectrum {
        let f = self.kind.to_tensile_factor(self.poisson) / kind.to_tensile_factor(self.poisson);
        RelaxationSpectrum {
            kind,
            poisson: self.poisson,
            modulus_inf_pa: self.modulus_inf_pa * f,
            terms: self
                .terms
                .iter()
                .map(|r| RelaxationTerm {
                    modulus_pa: r.modulus_pa * f,
                    tau_s: r.tau_s,
                })
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sls() -> RelaxationSpectrum {
        RelaxationSpectrum {
            kind: ModulusKind::Tensile,
            poisson: 0.5,
            modulus_inf_pa: 1e6,
            terms: vec![RelaxationTerm {
                modulus_pa: 9e6,
                tau_s: 1e-3,
            }],
        }
    }

    #[test]
    fn standard_linear_solid_limits() {
        let s = sls();
        assert_eq!(s.instantaneous_modulus(), 1e7);
        assert_eq!(s.relaxation_modulus(0.0), 1e7);
        assert_eq!(s.relaxation_modulus(1e3), 1e6);
        // ωρ = 1: E′ = E∞ + E/2, E″ = E/2, peak of E″ (to rounding).
        let (re, im) = s.complex_modulus(1e3);
        assert!((re - 5.5e6).abs() < 1e-8 && (im - 4.5e6).abs() < 1e-8);
        assert!((s.tan_delta(1e3) - 4.5 / 5.5).abs() < 1e-15);
        assert!((s.abs_complex_modulus(1e3) - 5.5e6f64.hypot(4.5e6)).abs() < 1e-8);
        assert_eq!(s.storage_modulus(1e300), 1e7);
        assert_eq!(s.storage_modulus(0.0), 1e6);
    }

    #[test]
    fn kramers_kronig_local_rule_holds_for_a_broad_spectrum() {
        // For a spectrum spread evenly over many decades E″ ≈ (π/2) dE′/d ln ω (docs/MATH.md §6); 4 terms per
        // decade make the local rule good to a few per cent in the middle of the window.
        let terms = (0..60)
            .map(|k| RelaxationTerm {
                modulus_pa: 1e6,
                tau_s: 10f64.powf(-7.5 + k as f64 * 0.25),
            })
            .collect();
        let s = RelaxationSpectrum {
            kind: ModulusKind::Tensile,
            poisson: 0.5,
            modulus_inf_pa: 1e5,
            terms,
        };
        let w = 1.0;
        let h: f64 = 1e-4;
        let d = (s.storage_modulus(w * h.exp()) - s.storage_modulus(w * (-h).exp())) / (2.0 * h);
        let rel = (std::f64::consts::FRAC_PI_2 * d / s.loss_modulus(w) - 1.0).abs();
        assert!(rel < 0.03, "{rel}");
    }

    #[test]
    fn validation_rejects_negative_strength() {
        let mut s = sls();
        s.terms[0].modulus_pa = -1.0;
        assert!(s
            .validate()
            .unwrap_err()
            .to_string()
            .contains("terms[0].modulus_pa"));
    }

    #[test]
    fn shear_is_a_third_of_tensile_for_incompressible() {
        let g = sls().to_kind(ModulusKind::Shear);
        assert!((g.instantaneous_modulus() - 1e7 / 3.0).abs() < 1e-8);
    }

    #[test]
    fn shift_scales_times() {
        let law = ShiftLaw::Table {
            t_ref_c: 0.0,
            points: vec![(0.0, 0.0), (10.0, -2.0)],
        };
        let s = sls().at_temperature(&law, 10.0, Some((0.0, 10.0))).unwrap();
        assert!(!s.extrapolated);
        assert!((s.spectrum.terms[0].tau_s - 1e-5).abs() < 1e-20);
    }
}
