//! Parameter checks shared by the stages and their typed error [`MaterialError`]: positive finite
//! values, Poisson's ratio, WLF constants, a shift law defined at a temperature. Messages name the
//! field and the offending value.

/// What is wrong with a material parameter; messages name the field and the value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum MaterialError {
    /// A scalar field is not finite or outside its admissible range.
    #[error("{field} = {value} is invalid: {expected}")]
    InvalidValue {
        /// The JSON field name, e.g. `terms[3].tau_s`.
        field: String,
        /// The value found.
        value: f64,
        /// What was expected, in words.
        expected: &'static str,
    },
    /// The shift law gives no finite a_T at this temperature (WLF below its asymptote T_ref − C2).
    #[error("the shift law gives log10 a_T = {log10_a_t} at {temp_c} °C (WLF below T_ref − C2?)")]
    ShiftUndefined {
        /// Requested temperature in °C.
        temp_c: f64,
        /// log10 a_T found.
        log10_a_t: f64,
    },
}

/// Check that `value` is finite and > 0 (or ≥ 0 when `allow_zero`).
pub fn check_positive(
    field: impl FnOnce() -> String,
    value: f64,
    allow_zero: bool,
) -> Result<(), MaterialError> {
    let ok = value.is_finite() && (value > 0.0 || (allow_zero && value == 0.0));
    if ok {
        Ok(())
    } else {
        Err(MaterialError::InvalidValue {
            field: field(),
            value,
            expected: if allow_zero {
                "a finite number ≥ 0"
            } else {
                "a finite number > 0"
            },
        })
    }
}

/// Poisson's ratio must lie in (−1, 0.5] for an isotropic solid.
pub fn check_poisson(value: f64) -> Result<(), MaterialError> {
    if value.is_finite() && value > -1.0 && value <= 0.5 {
        Ok(())
    } else {
        Err(MaterialError::InvalidValue {
            field: "poisson".into(),
            value,
            expected: "Poisson's ratio in (−1, 0.5]",
        })
    }
}

/// WLF constants of a physical shift law (docs/MATH.md §6): C1 > 0 (a_T falls with temperature) and
/// C2 > 0 K (the asymptote T_ref − C2 lies below T_ref), both finite, and T_ref a finite
/// temperature above absolute zero.
pub fn check_wlf_constants(t_ref_c: f64, c1: f64, c2_k: f64) -> Result<(), MaterialError> {
    if !(t_ref_c.is_finite() && t_ref_c > -super::ZERO_CELSIUS_K) {
        return Err(MaterialError::InvalidValue {
            field: "t_ref_c".into(),
            value: t_ref_c,
            expected: "a finite temperature above −273.15 °C",
        });
    }
    check_positive(|| "c1".into(), c1, false)?;
    check_positive(|| "c2_k".into(), c2_k, false)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checks_name_the_field() {
        assert!(check_positive(|| "x".into(), 0.0, true).is_ok());
        let e = check_positive(|| "terms[2].tau_s".into(), 0.0, false).unwrap_err();
        assert!(e.to_string().contains("terms[2].tau_s = 0"), "{e}");
        assert!(check_positive(|| "x".into(), f64::NAN, true).is_err());
        assert!(check_poisson(0.5).is_ok());
        assert!(check_poisson(0.51).is_err());
        assert!(check_poisson(-1.0).is_err());
    }

    #[test]
    fn wlf_constants_must_be_positive() {
        assert!(check_wlf_constants(25.0, 8.86, 101.6).is_ok());
        let e = check_wlf_constants(25.0, 8.86, -5.0)
            .unwrap_err()
            .to_string();
        assert!(e.contains("c2_k = -5"), "{e}");
        assert!(check_wlf_constants(25.0, 0.0, 101.6).is_err());
        assert!(check_wlf_constants(-300.0, 8.86, 101.6).is_err());
    }
}
