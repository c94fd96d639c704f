//! One step of Brent's root finder (Brent 1973, *Algorithms for Minimization without Derivatives*,
//! ch. 4). Input: the bracket state (a, b, c), its values, the half-width m, the step tolerance and
//! the previous steps (d, e); output: the next step and the new memory. Used by the contact stage's
//! load loop (`contact::load`), which keeps the bracket, stopping rules and bookkeeping.

/// The next step `d` (and the previous-step memory `e`) of Brent's method on the bracket [b, c]
/// with last iterate a: inverse quadratic interpolation (or the secant when a = c) when it is
/// accepted, else bisection (`d = e = m`, m = (c − b)/2). `interpolate` is false when the caller
/// forbids interpolation (e.g. the last steps were too small or a value is not finite).
pub(crate) fn brent_step(
    (a, b, c): (f64, f64, f64),
    (fa, fb, fc): (f64, f64, f64),
    m: f64,
    tol: f64,
    (d, e): (f64, f64),
    interpolate: bool,
) -> (f64, f64) {
    if !(interpolate && e.abs() >= tol && fa.abs() > fb.abs()) {
        return (m, m);
    }
    let s = fb / fa;
    let (mut p, mut q);
    if a == c {
        // Secant.
        p = 2.0 * m * s;
        q = 1.0 - s;
    } else {
        // Inverse quadratic interpolation.
        let qa = fa / fc;
        let r = fb / fc;
        p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
        q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
    }
    if p > 0.0 {
        q = -q;
    } else {
        p = -p;
    }
    if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
        (p / q, d)
    } else {
        (m, m)
    }
}
