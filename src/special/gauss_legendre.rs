//! Adaptive Gauss–Legendre quadrature of smooth (analytic) integrands on finite intervals.
//!
//! Input: a closure f(x) → f64, a list of panel edges, a relative tolerance; output: the integral.
//! Used by the exact contact solution (`contact::exact`), whose integrals are analytic in the
//! integration variable but have features on very different scales (1/√c, 1/√p, log 1/p), and for
//! the fixed rules of the gap check (`contact` half-space body, `rear_gap`).
//!
//! Method: on each panel compare the m-point Gauss–Legendre rule with the sum of the same rule on the two
//! halves; accept when they agree to `tol` times the running magnitude of the whole integral, otherwise
//! bisect. Nodes and weights come from Newton's method on the three-term Legendre recurrence
//! ((k+1)P_{k+1} = (2k+1)xP_k − kP_{k−1}; weights 2/((1−x²)P′ₘ(x)²), A&S 25.4.29).

/// Gauss–Legendre nodes (in (−1, 1)) and weights of order m.
pub fn gauss_legendre(m: usize) -> (Vec<f64>, Vec<f64>) {
    let mut x = vec![0.0; m];
    let mut w = vec![0.0; m];
    let mf = m as f64;
    for i in 0..m.div_ceil(2) {
        // Tricomi's initial guess for the i-th largest root.
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (mf + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (p, d) = legendre_and_derivative(m, z);
            dp = d;
            let dz = p / d;
            z -= dz;
            if dz.abs() < 1e-16 {
                break;
            }
        }
        let (_, d) = legendre_and_derivative(m, z);
        if d.is_finite() {
            dp = d;
        }
        x[i] = z;
        x[m - 1 - i] = -z;
        let wi = 2.0 / ((1.0 - z * z) * dp * dp);
        w[i] = wi;
        w[m - 1 - i] = wi;
    }
    (x, w)
}

fn legendre_and_derivative(m: usize, z: f64) -> (f64, f64) {
    let mut p0 = 1.0;
    let mut p1 = z;
    for k in 1..m {
        let kf = k as f64;
        let p2 = ((2.0 * kf + 1.0) * z * p1 - kf * p0) / (kf + 1.0);
        p0 = p1;
        p1 = p2;
    }
    // P′ₘ(z) = m(zPₘ − Pₘ₋₁)/(z² − 1).
    let d = m as f64 * (z * p1 - p0) / (z * z - 1.0);
    (p1, d)
}

/// A reusable adaptive integrator (holds its nodes).
pub(crate) struct Integrator {
    x: Vec<f64>,
    w: Vec<f64>,
    /// Panels processed in the last call (a cost measure for tests/benchmarks).
    pub panels: usize,
}

impl Integrator {
    /// An integrator using the m-point Gauss–Legendre rule.
    pub fn new(m: usize) -> Self {
        let (x, w) = gauss_legendre(m);
        Integrator { x, w, panels: 0 }
    }

    fn rule(&self, f: &mut impl FnMut(f64) -> f64, a: f64, b: f64) -> f64 {
        let h = 0.5 * (b - a);
        let mid = 0.5 * (a + b);
        let mut s = 0.0;
        for (xi, wi) in self.x.iter().zip(&self.w) {
            s += wi * f(mid + h * xi);
        }
        s * h
    }

    /// ∫ f over [edges\[0\], edges\[last\]], with the given edges as initial panels; relative tolerance `tol`
    /// against the magnitude of the whole integral (integrands here are of one sign or nearly so).
    pub(crate) fn integrate(
        &mut self,
        mut f: impl FnMut(f64) -> f64,
        edges: &[f64],
        tol: f64,
    ) -> f64 {
        self.panels = 0;
        let mut stack: Vec<(f64, f64, f64, usize)> = Vec::new();
        let mut total_est = 0.0;
        for win in edges.windows(2) {
            let (a, b) = (win[0], win[1]);
            if b > a {
                let v = self.rule(&mut f, a, b);
                total_est += v.abs();
                stack.push((a, b, v, 0));
            }
        }
        let mut result = 0.0;
        while let Some((a, b, whole, depth)) = stack.pop() {
            self.panels += 1;
            let m = 0.5 * (a + b);
            let left = self.rule(&mut f, a, m);
            let right = self.rule(&mut f, m, b);
            let halves = left + right;
            let err = (halves - whole).abs();
            // Non-finite values cannot be refined away: accept them (the NaN/∞ propagates to the caller).
            if err <= tol * total_est.max(f64::MIN_POSITIVE)
                || !err.is_finite()
                || depth >= 60
                || m <= a
                || m >= b
            {
                result += halves;
            } else {
                stack.push((a, m, left, depth + 1));
                stack.push((m, b, right, depth + 1));
            }
        }
        result
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rule_is_exact_for_polynomials_of_degree_2m_minus_1() {
        let (x, w) = gauss_legendre(20);
        // ∫₋₁¹ x^k dx = 2/(k+1) for even k, 0 for odd; exact up to degree 39 (rounding ~1e-15).
        for k in 0..40 {
            let s: f64 = x.iter().zip(&w).map(|(xi, wi)| wi * xi.powi(k)).sum();
            let want = if k % 2 == 0 {
                2.0 / (k as f64 + 1.0)
            } else {
                0.0
            };
            assert!((s - want).abs() < 1e-14, "k={k}");
        }
    }

    #[test]
    fn adaptive_integrates_a_narrow_peak() {
        // ∫₀^∞ e^(−x²/(2s²)) dx = s√(π/2) with s = 1e-3 on [0, 1]: needs bisection near 0.
        let s = 1e-3;
        let mut q = Integrator::new(20);
        let v = q.integrate(|x| (-x * x / (2.0 * s * s)).exp(), &[0.0, 1.0], 1e-15);
        let want = s * (std::f64::consts::PI / 2.0).sqrt();
        assert!(((v - want) / want).abs() < 1e-13);
    }
}
