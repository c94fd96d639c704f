//! Evaluation of a [`CreepSpectrum`] (thesis eq. 2.12): J(t), J′(ω), J″(ω), J∞; validation; the spectrum
//! at another temperature through a [`ShiftLaw`]; tensile ↔ shear conversion.
//!
//! Input and output: [`CreepSpectrum`] (plain serde type of `creep/mod.rs`); shifting gives an
//! [`AtTemperature`] (of [`crate::material`], shared with [`crate::prony::RelaxationSpectrum`]).
//!
//! Conventions: J*(ω) = J′(ω) − iJ″(ω) = 1/E*(ω) with E* = E′ + iE″ (so J″ ≥ 0), and for one term
//! Jⱼ(1 − e^(−t/τⱼ)) ↔ Jⱼ/(1 + iωτⱼ). Time–temperature superposition: a time at temperature T equals
//! a_T times the time at T_ref, so every τ is multiplied by a_T (docs/MATH.md §6).

use super::error::CreepError;
use super::{CreepSpectrum, RetardationTerm};
use crate::material::{
    check_poisson, check_positive, debye, shift_at, AtTemperature, ModulusKind, ShiftLaw,
};

impl CreepSpectrum {
    /// Relaxed (equilibrium) compliance J∞ = J_g + Σ Jⱼ in 1/Pa (eq. 2.12 at t → ∞).
    pub fn compliance_relaxed(&self) -> f64 {
        self.compliance_glassy_per_pa + self.terms.iter().map(|t| t.compliance_per_pa).sum::<f64>()
    }

    /// Creep compliance J(t) = J_g + Σ Jⱼ(1 − e^(−t/τⱼ)) in 1/Pa at `t_s` ≥ 0 (eq. 2.12).
    pub fn creep_compliance(&self, t_s: f64) -> f64 {
        self.compliance_glassy_per_pa
            + self
                .terms
                .iter()
                .map(|r| -r.compliance_per_pa * (-t_s / r.tau_s).exp_m1())
                .sum::<f64>()
    }

    /// Storage compliance J′(ω) = J_g + Σ Jⱼ/(1 + ω²τⱼ²) in 1/Pa, ω in rad/s.
    pub fn storage_compliance(&self, omega_rad_s: f64) -> f64 {
        self.compliance_glassy_per_pa
            + self
                .terms
                .iter()
                .map(|r| r.compliance_per_pa * debye(omega_rad_s * r.tau_s).0)
                .sum::<f64>()
    }

    /// Loss compliance J″(ω) = Σ Jⱼ ωτⱼ/(1 + ω²τⱼ²) in 1/Pa (≥ 0), ω in rad/s.
    pub fn loss_compliance(&self, omega_rad_s: f64) -> f64 {
        self.terms
            .iter()
            .map(|r| r.compliance_per_pa * debye(omega_rad_s * r.tau_s).2)
            .sum()
    }

    /// (J′, J″) at ω, J* = J′ − iJ″.
    pub(crate) fn complex_compliance(&self, omega_rad_s: f64) -> (f64, f64) {
        let mut re = self.compliance_glassy_per_pa;
        let mut im = 0.0;
        for r in &self.terms {
            let (d0, _, d1) = debye(omega_rad_s * r.tau_s);
            re += r.compliance_per_pa * d0;
            im += r.compliance_per_pa * d1;
        }
        (re, im)
    }

    /// Check that the spectrum is an admissible solid: J_g > 0, Jⱼ ≥ 0, τⱼ > 0, all finite, ν in (−1, 0.5].
    pub fn validate(&self) -> Result<(), CreepError> {
        check_poisson(self.poisson)?;
        check_positive(
            || "compliance_glassy_per_pa".into(),
            self.compliance_glassy_per_pa,
            false,
        )?;
        for (i, r) in self.terms.iter().enumerate() {
            check_positive(
                || format!("terms[{i}].compliance_per_pa"),
                r.compliance_per_pa,
                true,
            )?;
            check_positive(|| format!("terms[{i}].tau_s"), r.tau_s, false)?;
        }
        Ok(())
    }

    /// The spectrum at `temp_c` (°C): every τⱼ multiplied by a_T = 10^(log10 a_T) of `law`. When
    /// `measured_range_c` (lowest, highest measured temperature in °C) is given, a temperature outside
    /// it is allowed but flagged as `extrapolated`.
    pub fn at_temperature(
        &self,
        law: &ShiftLaw,
        temp_c: f64,
        measured_range_c: Option<(f64, f64)>,
    ) -> Result<AtTemperature<CreepSpectrum>, CreepError> {
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

    /// The same material as a compliance of another kind: J_shear = 2(1+ν)·J_tensile (E = 2(1+ν)G).
    pub fn to_kind(&self, kind: ModulusKind) -> CreepSpectrum {
        // Compliances scale inversely to moduli: J_kind = J_self · factor(kind)/factor(self).
        let f = kind.to_tensile_factor(self.poisson) / self.kind.to_tensile_factor(self.poisson);
        CreepSpectrum {
            kind,
            poisson: self.poisson,
            compliance_glassy_per_pa: self.compliance_glassy_per_pa * f,
            terms: self
                .terms
                .iter()
                .map(|r| RetardationTerm {
                    compliance_per_pa: r.compliance_per_pa * f,
                    tau_s: r.tau_s,
                })
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one_term() -> CreepSpectrum {
        CreepSpectrum {
            kind: ModulusKind::Tensile,
            poisson: 0.5,
            compliance_glassy_per_pa: 1e-9,
            terms: vec![RetardationTerm {
                compliance_per_pa: 9e-9,
                tau_s: 2.0,
            }],
        }
    }

    #[test]
    fn limits_of_one_term() {
        let c = one_term();
        assert_eq!(c.creep_compliance(0.0), 1e-9);
        // t = τ ln 2: half the retardation done; exact to a few ulp.
        let t = 2.0 * std::f64::consts::LN_2;
        assert!((c.creep_compliance(t) - 5.5e-9).abs() < 1e-23);
        assert!((c.compliance_relaxed() - 1e-8).abs() < 1e-23);
        // ωτ = 1: J′ = J_g + J/2, J″ = J/2 (to rounding).
        let (re, im) = c.complex_compliance(0.5);
        assert!((re - 5.5e-9).abs() < 1e-23 && (im - 4.5e-9).abs() < 1e-23);
        assert_eq!(c.storage_compliance(1e300), 1e-9);
        assert!(c.loss_compliance(1e300) < 1e-300);
    }

    #[test]
    fn validation_names_the_field() {
        let mut c = one_term();
        c.terms[0].tau_s = -1.0;
        let e = c.validate().unwrap_err().to_string();
        assert!(e.contains("terms[0].tau_s"), "{e}");
    }

    #[test]
    fn shift_multiplies_times_and_flags_extrapolation() {
        let law = ShiftLaw::Wlf {
            t_ref_c: 25.0,
            c1: 13.5,
            c2_k: 141.19,
        };
        let s = one_term()
            .at_temperature(&law, 50.0, Some((-50.0, 40.0)))
            .unwrap();
        assert!(s.extrapolated);
        let expected = 2.0 * 10f64.powf(-13.5 * 25.0 / (141.19 + 25.0));
        assert!((s.spectrum.terms[0].tau_s / expected - 1.0).abs() < 1e-14);
        let e = one_term().at_temperature(&law, 25.0 - 200.0, None);
        assert!(matches!(
            e,
            Err(CreepError::Material(
                crate::material::MaterialError::ShiftUndefined { .. }
            ))
        ));
    }

    #[test]
    fn shear_compliance_is_three_times_tensile_for_incompressible() {
        let g = one_term().to_kind(ModulusKind::Shear);
        assert!((g.compliance_glassy_per_pa - 3e-9).abs() < 1e-24);
        let back = g.to_kind(ModulusKind::Tensile);
        assert!((back.compliance_glassy_per_pa - 1e-9).abs() < 1e-24);
    }
}
