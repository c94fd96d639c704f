//! Fits of the shift factors log10 a_T(T) (docs/MATH.md §6): input (temperature, log10 a_T) pairs and a
//! reference temperature; output [`WlfFit`] and [`ArrheniusFit`], each with its residuals, and the
//! exact re-referencing of a WLF law to another reference temperature.
//!
//! - WLF (Williams, Landel & Ferry 1955): log10 a_T = −C₁ (T − T_ref) / (C₂ + T − T_ref). For a fixed
//!   C₂ the model is linear in C₁, so C₁ = −Σ sᵢ gᵢ / Σ gᵢ² with gᵢ = (Tᵢ − T_ref)/(C₂ + Tᵢ − T_ref);
//!   C₂ is found by a 1-D search of that profile (grid in ln(C₂ − C₂,min), golden section), where
//!   C₂,min = max(T_ref − Tᵢ) keeps the asymptote below every measured temperature; a few
//!   Gauss–Newton steps on (C₁, C₂) then polish to full precision.
//! - Arrhenius: log10 a_T = E_a/(R ln 10) · (1/T − 1/T_ref), T in K; linear least squares in E_a.
//! - Re-referencing WLF to T′: C₁′ = C₁C₂/(C₂ + T′ − T_ref), C₂′ = C₂ + T′ − T_ref (Ferry,
//!   *Viscoelastic Properties of Polymers*, 3rd ed., ch. 11), exact: the law is the same function.

use super::error::TtsError;
use super::shift::golden_min;
use crate::material::{ShiftLaw, GAS_CONSTANT_J_PER_MOL_K, ZERO_CELSIUS_K};
use serde::{Deserialize, Serialize};

/// One temperature's shift factor beside a law's value.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ShiftResidual {
    /// Temperature in °C.
    pub temp_c: f64,
    /// log10 a_T from the shifting.
    pub log10_a_t: f64,
    /// log10 a_T of the fitted law.
    pub fitted_log10_a_t: f64,
    /// log10_a_t − fitted_log10_a_t.
    pub residual: f64,
}

/// A WLF fit of the shift factors.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct WlfFit {
    /// Reference temperature in °C.
    pub t_ref_c: f64,
    /// C₁ (dimensionless).
    pub c1: f64,
    /// C₂ in K.
    pub c2_k: f64,
    /// RMS of the residuals (log10 units).
    pub rms_log10: f64,
    /// The residual at each temperature.
    pub residuals: Vec<ShiftResidual>,
}

impl WlfFit {
    /// This fit moved exactly to `new_t_ref_c` (module docs), with its residuals against
    /// `points` (the shifts relative to the new reference). `None` below the asymptote.
    pub(crate) fn rereferenced(&self, points: &[(f64, f64)], new_t_ref_c: f64) -> Option<WlfFit> {
        let (c1, c2_k) = rereference_wlf(self.c1, self.c2_k, self.t_ref_c, new_t_ref_c)?;
        let law = ShiftLaw::Wlf {
            t_ref_c: new_t_ref_c,
            c1,
            c2_k,
        };
        let (rms_log10, residuals) = residuals(points, &law);
        Some(WlfFit {
            t_ref_c: new_t_ref_c,
            c1,
            c2_k,
            rms_log10,
            residuals,
        })
    }

    /// The law.
    pub fn law(&self) -> ShiftLaw {
        ShiftLaw::Wlf {
            t_ref_c: self.t_ref_c,
            c1: self.c1,
            c2_k: self.c2_k,
        }
    }
}

/// An Arrhenius fit of the shift factors.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ArrheniusFit {
    /// Reference temperature in °C.
    pub t_ref_c: f64,
    /// Activation energy E_a in J/mol.
    pub activation_energy_j_per_mol: f64,
    /// RMS of the residuals (log10 units).
    pub rms_log10: f64,
    /// The residual at each temperature.
    pub residuals: Vec<ShiftResidual>,
}

impl ArrheniusFit {
    /// This fit moved exactly to `new_t_ref_c` (same E_a), with its residuals against `points`.
    pub(crate) fn rereferenced(&self, points: &[(f64, f64)], new_t_ref_c: f64) -> ArrheniusFit {
        let law = ShiftLaw::Arrhenius {
            t_ref_c: new_t_ref_c,
            activation_energy_j_per_mol: self.activation_energy_j_per_mol,
        };
        let (rms_log10, residuals) = residuals(points, &law);
        ArrheniusFit {
            t_ref_c: new_t_ref_c,
            activation_energy_j_per_mol: self.activation_energy_j_per_mol,
            rms_log10,
            residuals,
        }
    }

    /// The law.
    pub fn law(&self) -> ShiftLaw {
        ShiftLaw::Arrhenius {
            t_ref_c: self.t_ref_c,
            activation_energy_j_per_mol: self.activation_energy_j_per_mol,
        }
    }
}

/// WLF constants re-referenced exactly from `t_ref_c` to `new_t_ref_c`: (C₁′, C₂′). `None` when the
/// new reference lies at or below the asymptote T_ref − C₂.
pub fn rereference_wlf(c1: f64, c2_k: f64, t_ref_c: f64, new_t_ref_c: f64) -> Option<(f64, f64)> {
    let c2_new = c2_k + new_t_ref_c - t_ref_c;
    (c2_new > 0.0).then(|| (c1 * c2_k / c2_new, c2_new))
}

fn residuals(points: &[(f64, f64)], law: &ShiftLaw) -> (f64, Vec<ShiftResidual>) {
    let res: Vec<ShiftResidual> = points
        .iter()
        .map(|&(t, s)| {
            let f = law.log10_a_t(t);
            ShiftResidual {
                temp_c: t,
                log10_a_t: s,
                fitted_log10_a_t: f,
                residual: s - f,
            }
        })
        .collect();
    let rms = (res.iter().map(|r| r.residual * r.residual).sum::<f64>() / res.len() as f64).sqrt();
    (rms, res)
}

/// WLF fit of (temperature °C, log10 a_T) at reference `t_ref_c` (see the module docs).
pub(crate) fn fit_wlf(points: &[(f64, f64)], t_ref_c: f64) -> Result<WlfFit, TtsError> {
    let distinct = points
        .iter()
        .filter(|p| (p.0 - t_ref_c).abs() > 1e-9)
        .count();
    if distinct < 2 {
        return Err(TtsError::LawFit {
            law: "WLF",
            reason: format!(
                "{distinct} temperature(s) away from T_ref = {t_ref_c} °C; at least 2 are needed"
            ),
        });
    }
    let c2_min = points
        .iter()
        .map(|p| t_ref_c - p.0)
        .fold(f64::NEG_INFINITY, f64::max)
        .max(0.0);
    let profile = |c2: f64| wlf_profile(points, t_ref_c, c2);
    // u = ln(C₂ − C₂,min) on [ln 1e-3 K, ln 1e5 K]: C₂ up to 10⁵ K covers Arrhenius-like data.
    let (u_lo, u_hi) = (1e-3f64.ln(), 1e5f64.ln());
    let n = 400;
    let c2_of = |u: f64| c2_min + u.exp();
    let mut best = (u_lo, f64::INFINITY);
    for i in 0..=n {
        let u = u_lo + (u_hi - u_lo) * i as f64 / n as f64;
        let ss = profile(c2_of(u)).1;
        if ss < best.1 {
            best = (u, ss);
        }
    }
    let h = (u_hi - u_lo) / n as f64;
    let (u, _) = golden_min(|u| profile(c2_of(u)).1, best.0 - h, best.0 + h, 1e-12);
    let c2 = c2_of(u);
    let c1 = profile(c2).0;
    let (c1, c2) = wlf_polish(points, t_ref_c, c1, c2, (c2_min, c2_of(u_hi)));
    if !(c1.is_finite() && c2.is_finite()) {
        return Err(TtsError::LawFit {
            law: "WLF",
            reason: "the fit did not converge to finite constants".into(),
        });
    }
    let law = ShiftLaw::Wlf {
        t_ref_c,
        c1,
        c2_k: c2,
    };
    let (rms, res) = residuals(points, &law);
    Ok(WlfFit {
        t_ref_c,
        c1,
        c2_k: c2,
        rms_log10: rms,
        residuals: res,
    })
}

/// Profile cost of the WLF fit: the best C₁ for this C₂ (linear least squares) and its sum of
/// squares.
fn wlf_profile(points: &[(f64, f64)], t_ref_c: f64, c2: f64) -> (f64, f64) {
    let (mut sg, mut gg) = (0.0, 0.0);
    for &(t, s) in points {
        let dt = t - t_ref_c;
        let g = dt / (c2 + dt);
        sg += s * g;
        gg += g * g;
    }
    let c1 = -sg / gg;
    (c1, wlf_sum_of_squares(points, t_ref_c, c1, c2))
}

/// Σ (s + C₁ ΔT/(C₂ + ΔT))² over the points.
fn wlf_sum_of_squares(points: &[(f64, f64)], t_ref_c: f64, c1: f64, c2: f64) -> f64 {
    points
        .iter()
        .map(|&(t, s)| {
            let dt = t - t_ref_c;
            let r = s + c1 * dt / (c2 + dt);
            r * r
        })
        .sum::<f64>()
}

/// Gauss–Newton polish on (C₁, C₂): r = s + C₁ g, ∂r/∂C₁ = g, ∂r/∂C₂ = −C₁ g/(C₂ + ΔT). A step that
/// leaves C₂ in (`c2_bounds.0`, `c2_bounds.1`] or raises the sum of squares ends it.
fn wlf_polish(
    points: &[(f64, f64)],
    t_ref_c: f64,
    mut c1: f64,
    mut c2: f64,
    c2_bounds: (f64, f64),
) -> (f64, f64) {
    let ss_of = |c1: f64, c2: f64| wlf_sum_of_squares(points, t_ref_c, c1, c2);
    for _ in 0..20 {
        let (mut a11, mut a12, mut a22, mut b1, mut b2) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for &(t, s) in points {
            let dt = t - t_ref_c;
            let g = dt / (c2 + dt);
            let r = s + c1 * g;
            let j1 = g;
            let j2 = -c1 * g / (c2 + dt);
            a11 += j1 * j1;
            a12 += j1 * j2;
            a22 += j2 * j2;
            b1 += j1 * r;
            b2 += j2 * r;
        }
        let det = a11 * a22 - a12 * a12;
        if det.abs() <= f64::MIN_POSITIVE {
            break;
        }
        let d1 = -(a22 * b1 - a12 * b2) / det;
        let d2 = -(a11 * b2 - a12 * b1) / det;
        let (n1, n2) = (c1 + d1, c2 + d2);
        if n2.is_nan() || n2 <= c2_bounds.0 || n2 > c2_bounds.1 || ss_of(n1, n2) > ss_of(c1, c2) {
            break;
        }
        let small = d1.abs() <= 1e-15 * c1.abs() && d2.abs() <= 1e-15 * c2.abs();
        c1 = n1;
        c2 = n2;
        if small {
            break;
        }
    }
    (c1, c2)
}

/// Arrhenius fit of (temperature °C, log10 a_T) at reference `t_ref_c` (see the module docs).
pub(crate) fn fit_arrhenius(points: &[(f64, f64)], t_ref_c: f64) -> Result<ArrheniusFit, TtsError> {
    let t0 = t_ref_c + ZERO_CELSIUS_K;
    let (mut sh, mut hh) = (0.0, 0.0);
    for &(t, s) in points {
        let h = 1.0 / (t + ZERO_CELSIUS_K) - 1.0 / t0;
        sh += s * h;
        hh += h * h;
    }
    if hh <= 0.0 {
        return Err(TtsError::LawFit {
            law: "Arrhenius",
            reason: format!("no temperature away from T_ref = {t_ref_c} °C"),
        });
    }
    let ea = sh / hh * GAS_CONSTANT_J_PER_MOL_K * std::f64::consts::LN_10;
    let law = ShiftLaw::Arrhenius {
        t_ref_c,
        activation_energy_j_per_mol: ea,
    };
    let (rms, res) = residuals(points, &law);
    Ok(ArrheniusFit {
        t_ref_c,
        activation_energy_j_per_mol: ea,
        rms_log10: rms,
        residuals: res,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(law: &ShiftLaw, temps: &[f64]) -> Vec<(f64, f64)> {
        temps.iter().map(|&t| (t, law.log10_a_t(t))).collect()
    }

    #[test]
    fn wlf_recovers_exact_constants() {
        // Exact WLF values: the fit must return C₁, C₂ to near rounding (1e-9 relative leaves room
        // for the conditioning of the 2-parameter problem).
        let temps: Vec<f64> = (0..15).map(|i| -40.0 + 10.0 * i as f64).collect();
        for (c1, c2) in [(13.5, 141.19), (8.86, 101.6), (17.44, 51.6)] {
            let law = ShiftLaw::Wlf {
                t_ref_c: 20.0,
                c1,
                c2_k: c2,
            };
            let temps: Vec<f64> = temps
                .iter()
                .copied()
                .filter(|t| t - 20.0 + c2 > 5.0)
                .collect();
            let f = fit_wlf(&sample(&law, &temps), 20.0).unwrap();
            assert!((f.c1 / c1 - 1.0).abs() < 1e-9, "{} vs {c1}", f.c1);
            assert!((f.c2_k / c2 - 1.0).abs() < 1e-9, "{} vs {c2}", f.c2_k);
            assert!(f.rms_log10 < 1e-10);
        }
    }

    #[test]
    fn arrhenius_recovers_exact_energy() {
        let law = ShiftLaw::Arrhenius {
            t_ref_c: 50.0,
            activation_energy_j_per_mol: 1.2e5,
        };
        let f = fit_arrhenius(&sample(&law, &[0.0, 20.0, 40.0, 60.0, 80.0]), 50.0).unwrap();
        assert!((f.activation_energy_j_per_mol / 1.2e5 - 1.0).abs() < 1e-12);
    }

    #[test]
    fn rereferenced_wlf_is_the_same_function_and_the_same_fit() {
        // Same law: log a_T(T; T′) = log a_T(T; T_ref) − log a_T(T′; T_ref) for every T.
        let (c1, c2, t0, t1) = (13.5, 141.19, 25.0, -5.0);
        let (c1n, c2n) = rereference_wlf(c1, c2, t0, t1).unwrap();
        let old = ShiftLaw::Wlf {
            t_ref_c: t0,
            c1,
            c2_k: c2,
        };
        let new = ShiftLaw::Wlf {
            t_ref_c: t1,
            c1: c1n,
            c2_k: c2n,
        };
        for t in [-50.0, -20.0, 0.0, 40.0, 100.0] {
            let d = old.log10_a_t(t) - old.log10_a_t(t1) - new.log10_a_t(t);
            assert!(d.abs() < 1e-12, "{t}: {d}");
        }
        // A fit re-referenced exactly keeps its residuals when the shifts are moved by the
        // fitted law's value at T′ (what build_master_curve does).
        let pts: Vec<(f64, f64)> = [-40.0, -20.0, 0.0, 20.0, 40.0, 60.0, 80.0]
            .iter()
            .enumerate()
            .map(|(i, &t)| (t, old.log10_a_t(t) + 0.05 * ((i * 7 % 5) as f64 - 2.0)))
            .collect();
        let f0 = fit_wlf(&pts, t0).unwrap();
        let off = f0.law().log10_a_t(t1);
        let moved: Vec<(f64, f64)> = pts.iter().map(|&(t, s)| (t, s - off)).collect();
        let f1 = f0.rereferenced(&moved, t1).unwrap();
        for (r0, r1) in f0.residuals.iter().zip(&f1.residuals) {
            assert!((r0.residual - r1.residual).abs() < 1e-12);
        }
    }
}
