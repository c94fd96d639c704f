//! The horizontal shift law a_T(T) ([`ShiftLaw`]: WLF, Arrhenius or a table), its checks, and its
//! evaluation at a temperature for a spectrum ([`AtTemperature`], [`shift_at`]). docs/MATH.md §6.
//!
//! Time–temperature superposition: a time at temperature T equals a_T times the time at T_ref, so a
//! spectrum moves to T by multiplying every relaxation or retardation time by a_T.

use super::checks::{check_positive, check_wlf_constants, MaterialError};
use super::units::{GAS_CONSTANT_J_PER_MOL_K, ZERO_CELSIUS_K};
use serde::{Deserialize, Serialize};

/// The horizontal shift law log10 a_T(T): a time at temperature T equals a_T times the time at T_ref
/// (reduced frequency ω_r = a_T·ω).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "law", rename_all = "snake_case")]
pub enum ShiftLaw {
    /// Williams–Landel–Ferry: log10 a_T = −C1 (T − T_ref) / (C2 + T − T_ref).
    Wlf {
        /// Reference temperature in °C.
        t_ref_c: f64,
        /// C1 (dimensionless).
        c1: f64,
        /// C2 in K.
        c2_k: f64,
    },
    /// Arrhenius: log10 a_T = E_a / (R ln 10) · (1/T − 1/T_ref), temperatures in K.
    Arrhenius {
        /// Reference temperature in °C.
        t_ref_c: f64,
        /// Activation energy E_a in J/mol.
        activation_energy_j_per_mol: f64,
    },
    /// A table of (T in °C, log10 a_T), interpolated linearly in T, extrapolated linearly from the end
    /// segments.
    Table {
        /// Reference temperature in °C.
        t_ref_c: f64,
        /// (temperature in °C, log10 a_T), sorted by temperature.
        points: Vec<(f64, f64)>,
    },
}

impl ShiftLaw {
    /// The reference temperature in °C.
    pub fn t_ref_c(&self) -> f64 {
        match self {
            ShiftLaw::Wlf { t_ref_c, .. }
            | ShiftLaw::Arrhenius { t_ref_c, .. }
            | ShiftLaw::Table { t_ref_c, .. } => *t_ref_c,
        }
    }

    /// log10 a_T at temperature `temp_c` (°C). WLF below its vertical asymptote T_ref − C2 returns
    /// +∞ (the material is glassy at every finite frequency there).
    pub fn log10_a_t(&self, temp_c: f64) -> f64 {
        match self {
            ShiftLaw::Wlf { t_ref_c, c1, c2_k } => {
                let dt = temp_c - t_ref_c;
                let den = c2_k + dt;
                if den <= 0.0 {
                    f64::INFINITY
                } else {
                    -c1 * dt / den
                }
            }
            ShiftLaw::Arrhenius {
                t_ref_c,
                activation_energy_j_per_mol,
            } => {
                let t = temp_c + ZERO_CELSIUS_K;
                let t0 = t_ref_c + ZERO_CELSIUS_K;
                activation_energy_j_per_mol / (GAS_CONSTANT_J_PER_MOL_K * std::f64::consts::LN_10)
                    * (1.0 / t - 1.0 / t0)
            }
            ShiftLaw::Table { points, .. } => interpolate_linear(points, temp_c),
        }
    }

    /// Check the law's constants: WLF C1 > 0 and C2 > 0 K ([`check_wlf_constants`]); Arrhenius
    /// E_a > 0; a table of at least two finite rows at distinct, increasing temperatures.
    pub fn validate(&self) -> Result<(), MaterialError> {
        match self {
            ShiftLaw::Wlf { t_ref_c, c1, c2_k } => check_wlf_constants(*t_ref_c, *c1, *c2_k),
            ShiftLaw::Arrhenius {
                t_ref_c,
                activation_energy_j_per_mol,
            } => {
                check_positive(
                    || "t_ref_c + 273.15".into(),
                    t_ref_c + ZERO_CELSIUS_K,
                    false,
                )?;
                check_positive(
                    || "activation_energy_j_per_mol".into(),
                    *activation_energy_j_per_mol,
                    false,
                )
            }
            ShiftLaw::Table { t_ref_c, points } => {
                if !t_ref_c.is_finite() {
                    return Err(MaterialError::InvalidValue {
                        field: "t_ref_c".into(),
                        value: *t_ref_c,
                        expected: "a finite temperature in °C",
                    });
                }
                if points.len() < 2 {
                    return Err(MaterialError::InvalidValue {
                        field: "points.len()".into(),
                        value: points.len() as f64,
                        expected: "at least 2 rows of (T in °C, log10 a_T)",
                    });
                }
                for (i, w) in points.windows(2).enumerate() {
                    if w[1].0.partial_cmp(&w[0].0) != Some(std::cmp::Ordering::Greater) {
                        return Err(MaterialError::InvalidValue {
                            field: format!("points[{}].0", i + 1),
                            value: w[1].0,
                            expected: "temperatures finite, distinct and increasing",
                        });
                    }
                }
                for (i, p) in points.iter().enumerate() {
                    if !(p.0.is_finite() && p.1.is_finite()) {
                        return Err(MaterialError::InvalidValue {
                            field: format!("points[{i}]"),
                            value: if p.0.is_finite() { p.1 } else { p.0 },
                            expected: "finite (T in °C, log10 a_T)",
                        });
                    }
                }
                Ok(())
            }
        }
    }
}

fn interpolate_linear(points: &[(f64, f64)], x: f64) -> f64 {
    match points.len() {
        0 => 0.0,
        1 => points[0].1,
        n => {
            let i = points.partition_point(|p| p.0 < x).clamp(1, n - 1);
            let (x0, y0) = points[i - 1];
            let (x1, y1) = points[i];
            y0 + (y1 - y0) * (x - x0) / (x1 - x0)
        }
    }
}

/// A spectrum moved to a temperature by a shift law.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AtTemperature<S> {
    /// The spectrum at `temp_c` (all times multiplied by a_T).
    pub spectrum: S,
    /// The temperature in °C.
    pub temp_c: f64,
    /// log10 a_T used.
    pub log10_a_t: f64,
    /// True when `temp_c` lies outside the measured temperature range given by the caller: the shift
    /// law is then extrapolated and the result deserves caution.
    pub extrapolated: bool,
}

/// log10 a_T at `temp_c`, finite, and whether it is an extrapolation beyond `measured_range_c`.
pub fn shift_at(
    law: &ShiftLaw,
    temp_c: f64,
    measured_range_c: Option<(f64, f64)>,
) -> Result<(f64, bool), MaterialError> {
    if !temp_c.is_finite() {
        return Err(MaterialError::InvalidValue {
            field: "temp_c".into(),
            value: temp_c,
            expected: "a finite temperature in °C",
        });
    }
    let log10_a_t = law.log10_a_t(temp_c);
    // 10^±300 keeps every shifted time a normal double for τ between 1e-8 and 1e8 s.
    if !log10_a_t.is_finite() || log10_a_t.abs() > 300.0 {
        return Err(MaterialError::ShiftUndefined { temp_c, log10_a_t });
    }
    let extrapolated = match measured_range_c {
        Some((lo, hi)) => temp_c < lo.min(hi) || temp_c > lo.max(hi),
        None => false,
    };
    Ok((log10_a_t, extrapolated))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wlf_is_zero_at_reference_and_negative_above() {
        let law = ShiftLaw::Wlf {
            t_ref_c: 25.0,
            c1: 13.5,
            c2_k: 141.19,
        };
        assert_eq!(law.log10_a_t(25.0), 0.0);
        assert!(law.log10_a_t(50.0) < 0.0);
        // −C1 at T − T_ref → ∞ limit: approaches −C1 from above.
        assert!(law.log10_a_t(1e9) > -13.5 && law.log10_a_t(1e9) < -13.49);
    }

    #[test]
    fn table_interpolates_and_extrapolates_linearly() {
        let law = ShiftLaw::Table {
            t_ref_c: 0.0,
            points: vec![(0.0, 0.0), (10.0, -2.0), (20.0, -3.0)],
        };
        assert!((law.log10_a_t(5.0) + 1.0).abs() < 1e-15);
        assert!((law.log10_a_t(30.0) + 4.0).abs() < 1e-15);
        assert!((law.log10_a_t(-10.0) - 2.0).abs() < 1e-15);
    }

    #[test]
    fn validate_rejects_unphysical_constants() {
        let bad = ShiftLaw::Wlf {
            t_ref_c: 25.0,
            c1: 8.86,
            c2_k: 0.0,
        };
        assert!(bad.validate().unwrap_err().to_string().contains("c2_k"));
        let t = ShiftLaw::Table {
            t_ref_c: 0.0,
            points: vec![(10.0, 0.0), (10.0, -1.0)],
        };
        assert!(t.validate().is_err());
        let a = ShiftLaw::Arrhenius {
            t_ref_c: 20.0,
            activation_energy_j_per_mol: 2e5,
        };
        assert!(a.validate().is_ok());
    }

    #[test]
    fn shift_at_refuses_the_wlf_asymptote_and_flags_extrapolation() {
        let law = ShiftLaw::Wlf {
            t_ref_c: 25.0,
            c1: 13.5,
            c2_k: 141.19,
        };
        assert!(matches!(
            shift_at(&law, -200.0, None),
            Err(MaterialError::ShiftUndefined { .. })
        ));
        let (v, ex) = shift_at(&law, 50.0, Some((40.0, -50.0))).unwrap();
        assert!(ex);
        assert!((v + 13.5 * 25.0 / (141.19 + 25.0)).abs() < 1e-14);
    }
}
