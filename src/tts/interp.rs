//! Interpolation of one isotherm in log–log: a cubic spline through the points (x = log10 f,
//! y = log10 of a modulus), clamped at both ends with the slope of the cubic through the four end
//! points, so the interpolation error is O(h⁴) up to the ends (de Boor, *A Practical Guide to
//! Splines*, ch. IV). Beyond the ends it extrapolates along the end tangent.
//!
//! Used by the shifting ([`super::shift`]) and the quality checks ([`super::quality`]).

/// A C² cubic spline in Hermite form (knots, values, slopes).
#[derive(Debug, Clone)]
pub(crate) struct Spline {
    x: Vec<f64>,
    y: Vec<f64>,
    m: Vec<f64>,
}

impl Spline {
    /// Spline through (x, y); `x` strictly increasing, at least 2 points (checked by the caller).
    pub(crate) fn new(x: &[f64], y: &[f64]) -> Spline {
        let n = x.len();
        debug_assert!(n >= 2 && y.len() == n);
        let mut m = vec![0.0; n];
        if n == 2 {
            let s = (y[1] - y[0]) / (x[1] - x[0]);
            m[0] = s;
            m[1] = s;
            return Spline {
                x: x.to_vec(),
                y: y.to_vec(),
                m,
            };
        }
        let k = n.min(4);
        m[0] = lagrange_slope(&x[..k], &y[..k], x[0]);
        m[n - 1] = lagrange_slope(&x[n - k..], &y[n - k..], x[n - 1]);
        // C² conditions at interior knots i = 1..n−2 (h_i = x_{i+1} − x_i):
        //   m_{i−1}/h_{i−1} + 2(1/h_{i−1} + 1/h_i) m_i + m_{i+1}/h_i
        //     = 3[(y_i − y_{i−1})/h_{i−1}² + (y_{i+1} − y_i)/h_i²]
        // Tridiagonal, diagonally dominant: Thomas algorithm.
        let ni = n - 2;
        let mut diag = vec![0.0; ni];
        let mut upper = vec![0.0; ni];
        let mut lower = vec![0.0; ni];
        let mut rhs = vec![0.0; ni];
        for j in 0..ni {
            let i = j + 1;
            let h0 = x[i] - x[i - 1];
            let h1 = x[i + 1] - x[i];
            lower[j] = 1.0 / h0;
            diag[j] = 2.0 * (1.0 / h0 + 1.0 / h1);
            upper[j] = 1.0 / h1;
            rhs[j] = 3.0 * ((y[i] - y[i - 1]) / (h0 * h0) + (y[i + 1] - y[i]) / (h1 * h1));
        }
        rhs[0] -= lower[0] * m[0];
        rhs[ni - 1] -= upper[ni - 1] * m[n - 1];
        for j in 1..ni {
            let w = lower[j] / diag[j - 1];
            diag[j] -= w * upper[j - 1];
            rhs[j] -= w * rhs[j - 1];
        }
        m[ni] = rhs[ni - 1] / diag[ni - 1];
        for j in (0..ni - 1).rev() {
            m[j + 1] = (rhs[j] - upper[j] * m[j + 2]) / diag[j];
        }
        Spline {
            x: x.to_vec(),
            y: y.to_vec(),
            m,
        }
    }

    /// Value and slope dy/dx at `t`.
    pub(crate) fn eval(&self, t: f64) -> (f64, f64) {
        let n = self.x.len();
        if t <= self.x[0] {
            return (self.y[0] + self.m[0] * (t - self.x[0]), self.m[0]);
        }
        if t >= self.x[n - 1] {
            return (
                self.y[n - 1] + self.m[n - 1] * (t - self.x[n - 1]),
                self.m[n - 1],
            );
        }
        let i = self.x.partition_point(|&v| v <= t).clamp(1, n - 1) - 1;
        let h = self.x[i + 1] - self.x[i];
        let s = (t - self.x[i]) / h;
        let (y0, y1, m0, m1) = (self.y[i], self.y[i + 1], self.m[i] * h, self.m[i + 1] * h);
        // Cubic Hermite basis on [0, 1].
        let s2 = s * s;
        let s3 = s2 * s;
        let v = (2.0 * s3 - 3.0 * s2 + 1.0) * y0
            + (s3 - 2.0 * s2 + s) * m0
            + (-2.0 * s3 + 3.0 * s2) * y1
            + (s3 - s2) * m1;
        let d = (6.0 * s2 - 6.0 * s) * y0
            + (3.0 * s2 - 4.0 * s + 1.0) * m0
            + (-6.0 * s2 + 6.0 * s) * y1
            + (3.0 * s2 - 2.0 * s) * m1;
        (v, d / h)
    }
}

/// Slope at `t` of the polynomial through the points (xs, ys) (Lagrange form).
fn lagrange_slope(xs: &[f64], ys: &[f64], t: f64) -> f64 {
    let k = xs.len();
    let mut slope = 0.0;
    for j in 0..k {
        let mut denom = 1.0;
        for m in 0..k {
            if m != j {
                denom *= xs[j] - xs[m];
            }
        }
        // d/dt Π_{m≠j} (t − x_m) = Σ_{l≠j} Π_{m≠j,l} (t − x_m)
        let mut num = 0.0;
        for l in 0..k {
            if l == j {
                continue;
            }
            num += xs
                .iter()
                .enumerate()
                .filter(|&(m, _)| m != j && m != l)
                .map(|(_, &xm)| t - xm)
                .product::<f64>();
        }
        slope += ys[j] * num / denom;
    }
    slope
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_cubics_exactly() {
        // A clamped spline whose end slopes are exact reproduces any cubic (its error term is
        // proportional to the 4th derivative), so only rounding remains.
        let f = |x: f64| 0.3 * x * x * x - x * x + 2.0 * x - 1.0;
        let x: Vec<f64> = vec![-1.0, -0.7, -0.1, 0.4, 0.5, 1.3, 2.0];
        let y: Vec<f64> = x.iter().map(|&v| f(v)).collect();
        let s = Spline::new(&x, &y);
        for i in 0..=60 {
            let t = -1.0 + 3.0 * i as f64 / 60.0;
            let (v, d) = s.eval(t);
            assert!((v - f(t)).abs() < 1e-12, "{t}: {v} vs {}", f(t));
            let exact_d = 0.9 * t * t - 2.0 * t + 2.0;
            assert!((d - exact_d).abs() < 1e-11);
        }
    }

    #[test]
    fn fourth_order_convergence_on_a_smooth_function() {
        // Error of a clamped cubic spline is O(h⁴): halving h must cut it by ≈ 16 (≥ 10 allowed for
        // the pre-asymptotic range).
        let err = |n: usize| {
            let x: Vec<f64> = (0..n).map(|i| 3.0 * i as f64 / (n - 1) as f64).collect();
            let y: Vec<f64> = x.iter().map(|v| v.sin()).collect();
            let s = Spline::new(&x, &y);
            (0..300)
                .map(|i| {
                    let t = 3.0 * i as f64 / 299.0;
                    (s.eval(t).0 - t.sin()).abs()
                })
                .fold(0.0, f64::max)
        };
        let (e1, e2) = (err(11), err(21));
        assert!(e1 / e2 > 10.0, "{e1} {e2}");
    }
}
