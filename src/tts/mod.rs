//! Stage `tts`: time–temperature superposition. Horizontal (and optional vertical) shifts of the
//! isotherms of a [`crate::Measurement`], WLF and Arrhenius fits of log a_T → master curve and
//! [`ShiftLaw`] (MATH.md §6).

use serde::{Deserialize, Serialize};

mod error;
pub mod fit_laws;
mod interp;
mod master;
pub mod point_temps;
pub mod quality;
mod shift;
pub mod vertical;

pub use error::TtsError;
pub use fit_laws::{rereference_wlf, ArrheniusFit, ShiftResidual, WlfFit};
pub use master::{
    build_master_curve, IsothermShift, LawChoice, MasterCurve, MasterPoint, MasterQuality,
    MasterSettings, ShiftCriterion, ShiftSource, TemperatureBasis, VerticalShift,
};
pub use quality::QualityBounds;

/// Universal gas constant R in J/(mol·K).
pub const GAS_CONSTANT_J_PER_MOL_K: f64 = 8.314_462_618;
/// 0 °C in K.
pub const ZERO_CELSIUS_K: f64 = 273.15;

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
}

#[cfg(test)]
mod roundtrip_tests;
