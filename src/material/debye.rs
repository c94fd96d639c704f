//! The Debye terms of one relaxation (or retardation) term at x = ωτ: the storage and loss parts of
//! iωτ/(1 + iωτ) and 1/(1 + iωτ) (thesis eq. 2.9 and 2.12 in the frequency domain).

/// (1/(1+x²), x²/(1+x²), x/(1+x²)) for x = ωτ ≥ 0, each to full relative precision and without
/// overflow (x up to 1e308).
#[inline]
pub fn debye(x: f64) -> (f64, f64, f64) {
    if x <= 1.0 {
        let d = 1.0 + x * x;
        (1.0 / d, x * x / d, x / d)
    } else {
        let y = 1.0 / x;
        let d = 1.0 + y * y;
        (y * y / d, 1.0 / d, y / d)
    }
}

#[cfg(test)]
mod tests {
    use super::debye;

    #[test]
    fn halves_at_one_and_no_overflow_at_the_ends() {
        assert_eq!(debye(1.0), (0.5, 0.5, 0.5));
        // x = 1e200: x² overflows, the terms do not; 1/(1+x²) = 1e-400 underflows to 0.
        let (a, b, c) = debye(1e200);
        assert_eq!((a, b), (0.0, 1.0));
        assert!((c / 1e-200 - 1.0).abs() < 1e-15);
        let (a, b, c) = debye(1e-200);
        assert_eq!((a, b), (1.0, 0.0));
        assert!((c / 1e-200 - 1.0).abs() < 1e-15);
        // The storage parts add to 1 (to rounding) at any x.
        for x in [1e-3, 0.7, 3.0, 1e5] {
            let (a, b, _) = debye(x);
            assert!((a + b - 1.0).abs() < 1e-15, "{x}");
        }
    }
}
