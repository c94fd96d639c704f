//! The load loop: find the contact length λ whose solution carries a prescribed load N′ (thesis ch. 4).
//!
//! Input: N′₀, Σfᵢ/bᵢ and any solver at given λ (a closure: thesis scheme, exact solution…); output:
//! the [`DimensionlessSolution`] at the λ found, with `iterations` = number of solves.
//!
//! The thesis iterates by secant from λ₁ = 2√N′₀, λ₀ = λ₁/2 ([`thesis_secant`], kept for comparison). At
//! low speeds the true λ is up to √(1 + Σf/b) times the elastic start (docs/MATH.md §3) and the secant runs
//! off (λ ≤ 0 or no convergence). Here instead: N′ grows monotonically with λ and lies between the
//! glassy and the relaxed Hertz values, N′ ∈ [λ²/(4(1+Σf/b)), λ²/4], so λ ∈ [2√N′₀, 2√((1+Σf/b)N′₀)]
//! brackets the root. The bracket is widened (×/÷ 1.25, up to [`LoadSettings::max_expand`] times) to
//! absorb the discretisation error of a coarse grid, then Brent's method (inverse quadratic
//! interpolation, secant and bisection; Brent 1973, ch. 4) on u = log λ with the residual
//! F(u) = log(N′(eᵘ)/N′₀) (nearly linear: N′ ∝ λ² at both speed limits) keeps the root bracketed.
//!
//! References: R. P. Brent, *Algorithms for Minimization without Derivatives*, Prentice-Hall 1973, ch. 4.

use super::error::{positive, ContactError};
use super::DimensionlessSolution;

/// Settings of the load loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadSettings {
    /// Relative tolerance on the load: stop when |N′(λ) − N′₀| ≤ `rel_tol`·N′₀. Default 1e-10 (far
    /// below any discretisation error, and Brent converges superlinearly, so it costs few solves).
    pub rel_tol: f64,
    /// Stop also when the bracket on λ is narrower than this, relative (the load is then accepted if
    /// within `accept_tol`). Default 1e-10: N′(λ) carries rounding noise of ≈ 1e-9 relative at n ≈ 200
    /// (the collocation matrix of a first-kind equation has condition ≈ 1e4), so Brent cannot always
    /// meet `rel_tol`; λ is then known to 1e-10 anyway.
    pub lambda_rel_tol: f64,
    /// Loosest relative load error accepted when the λ bracket has collapsed. Default 1e-8.
    pub accept_tol: f64,
    /// Largest number of solves. Default 100.
    pub max_solves: usize,
    /// How many times each end of the initial bracket may be widened by 1.25. Default 40 (a factor 7500).
    pub max_expand: usize,
}

impl Default for LoadSettings {
    fn default() -> Self {
        Self {
            rel_tol: 1e-10,
            lambda_rel_tol: 1e-10,
            accept_tol: 1e-8,
            max_solves: 100,
            max_expand: 40,
        }
    }
}

/// Solve for the contact length that carries load `load` (N′₀), with the solver `solve` at given λ.
///
/// `sum_f_over_b` = Σfᵢ/bᵢ sets the initial bracket (relaxed Hertz width). The returned solution has
/// `iterations` set to the number of solves made (bracketing included).
pub fn solve_at_load<F>(
    load: f64,
    sum_f_over_b: f64,
    settings: &LoadSettings,
    mut solve: F,
) -> Result<DimensionlessSolution, ContactError>
where
    F: FnMut(f64) -> Result<DimensionlessSolution, ContactError>,
{
    positive("load N'", load)?;
    if !(sum_f_over_b.is_finite() && sum_f_over_b >= 0.0) {
        return Err(ContactError::BadValue {
            field: "sum of f/b".into(),
            expected: "finite and >= 0",
            value: sum_f_over_b,
        });
    }
    let solves = std::cell::Cell::new(0usize);
    let mut eval = |lambda: f64| -> Result<(f64, DimensionlessSolution), ContactError> {
        solves.set(solves.get() + 1);
        let s = solve(lambda)?;
        let r = if s.load > 0.0 && s.load.is_finite() {
            (s.load / load).ln()
        } else {
            f64::NEG_INFINITY
        };
        Ok((r, s))
    };

    let ((lo, f_lo), (hi, f_hi), best) = bracket(load, sum_f_over_b, settings, &mut eval)?;
    if best.0.abs() <= settings.rel_tol {
        return finish_with(best.1, solves.get());
    }
    brent(((lo, f_lo), (hi, f_hi)), best, settings, &mut eval, &solves)
}

/// A solve at λ: (ln(N′(λ)/N′₀), the solution).
type Eval<'a> = dyn FnMut(f64) -> Result<(f64, DimensionlessSolution), ContactError> + 'a;

/// The initial bracket [lo, hi] of λ from the glassy and relaxed Hertz widths, widened by 1.25 at
/// either end until the residual changes sign; returns both ends with their residuals and the best
/// solution seen.
#[allow(clippy::type_complexity)]
fn bracket(
    load: f64,
    sum_f_over_b: f64,
    settings: &LoadSettings,
    eval: &mut Eval<'_>,
) -> Result<((f64, f64), (f64, f64), (f64, DimensionlessSolution)), ContactError> {
    // Initial bracket from the glassy and relaxed Hertz widths (docs/MATH.md §3).
    let mut lo = 2.0 * load.sqrt();
    let mut hi = lo * (1.0 + sum_f_over_b).sqrt();
    if hi <= lo * 1.0001 {
        hi = lo * 1.0001;
    }
    let (mut f_lo, mut s_lo) = eval(lo)?;
    let mut hi_eval = None;
    let mut expand = 0;
    while f_lo > 0.0 {
        if expand == settings.max_expand {
            return Err(unbracketed(load, lo, hi, f_lo, f64::NAN));
        }
        hi = lo;
        lo /= 1.25;
        let (f, s) = eval(lo)?;
        hi_eval = Some((f_lo, std::mem::replace(&mut s_lo, s)));
        f_lo = f;
        expand += 1;
    }
    let (mut f_hi, s_hi) = match hi_eval {
        Some(v) => v,
        None => eval(hi)?,
    };
    let mut best = if f_hi.abs() < f_lo.abs() {
        (f_hi, s_hi)
    } else {
        (f_lo, s_lo)
    };
    expand = 0;
    while f_hi < 0.0 {
        if expand == settings.max_expand {
            return Err(unbracketed(load, lo, hi, f_lo, f_hi));
        }
        lo = hi;
        f_lo = f_hi;
        hi *= 1.25;
        let (f, s) = eval(hi)?;
        f_hi = f;
        if f.abs() < best.0.abs() {
            best = (f, s);
        }
        expand += 1;
    }
    Ok(((lo, f_lo), (hi, f_hi), best))
}

/// Brent's method on u = log λ from the bracket, until the load is met to `rel_tol` (or to
/// `accept_tol` once the bracket has collapsed to the resolution of λ, or the steps chase the
/// rounding noise of N′(λ)); `solves` counts the solves made.
fn brent(
    ((lo, f_lo), (hi, f_hi)): ((f64, f64), (f64, f64)),
    mut best: (f64, DimensionlessSolution),
    settings: &LoadSettings,
    eval: &mut Eval<'_>,
    solves: &std::cell::Cell<usize>,
) -> Result<DimensionlessSolution, ContactError> {
    // Brent's method on u = log λ, residual f(u) = log(N′/N′₀); the root stays between b and c.
    let (mut a, mut fa) = (lo.ln(), f_lo);
    let (mut b, mut fb) = (hi.ln(), f_hi);
    let (mut c, mut fc) = (a, fa);
    let (mut d, mut e) = (b - a, b - a);
    loop {
        if (fb > 0.0) == (fc > 0.0) {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol = 2.0 * f64::EPSILON * b.abs().max(1.0);
        let m = 0.5 * (c - b);
        let stop_err = |solves: usize| ContactError::NotConverged {
            iterations: solves,
            lambda_lo: b.min(c).exp(),
            lambda_hi: b.max(c).exp(),
            residual: fb.exp_m1().abs(),
        };
        if best.0.abs() <= settings.rel_tol {
            return finish_with(best.1, solves.get());
        }
        if m.abs() <= tol.max(0.5 * settings.lambda_rel_tol) {
            // Bracket collapsed to the resolution of λ: accept if the load is met to `accept_tol`.
            if best.0.abs() <= settings.rel_tol.max(settings.accept_tol) {
                return finish_with(best.1, solves.get());
            }
            return Err(stop_err(solves.get()));
        }
        if solves.get() >= settings.max_solves {
            return Err(stop_err(solves.get()));
        }
        (d, e) = crate::special::brent::brent_step(
            (a, b, c),
            (fa, fb, fc),
            m,
            tol,
            (d, e),
            fa.is_finite() && fc.is_finite(),
        );
        a = b;
        fa = fb;
        let step = if d.abs() > tol { d } else { tol.copysign(m) };
        b += step;
        let (f_new, s_new) = eval(b.exp())?;
        fb = f_new;
        if f_new.abs() < best.0.abs() {
            best = (f_new, s_new);
        }
        // Noise floor: a step of < 1e-7 in log λ that still leaves the load within `accept_tol`
        // means the rounding noise of N′(λ) (≈ 1e-9) is being chased; stop there.
        if step.abs() < 1e-7 && best.0.abs() <= settings.accept_tol {
            return finish_with(best.1, solves.get());
        }
    }
}

fn unbracketed(load: f64, lo: f64, hi: f64, f_lo: f64, f_hi: f64) -> ContactError {
    ContactError::Unbracketed {
        load,
        lambda_lo: lo,
        lambda_hi: hi,
        load_lo: load * f_lo.exp(),
        load_hi: load * f_hi.exp(),
    }
}

fn finish_with(
    mut s: DimensionlessSolution,
    solves: usize,
) -> Result<DimensionlessSolution, ContactError> {
    s.iterations = solves;
    Ok(s)
}

/// The thesis' load iteration (ch. 4, Fig. 4), as printed: secant on N′(λ) from λ₁ = 2√N′₀, λ₀ = λ₁/2
/// (with N′(λ₀) taken as 0), stopping when |N′₀ − N′ᵢ| ≤ `tol`. Kept to show where it fails: returns
/// [`ContactError::NotConverged`] if λ leaves (0, ∞) or `max_iter` solves pass.
pub fn thesis_secant<F>(
    load: f64,
    tol: f64,
    max_iter: usize,
    mut solve: F,
) -> Result<DimensionlessSolution, ContactError>
where
    F: FnMut(f64) -> Result<DimensionlessSolution, ContactError>,
{
    positive("load N'", load)?;
    let mut lam_prev = load.sqrt(); // λ₀ = λ₁/2
    let mut n_prev = 0.0; // N₀ = 0
    let mut lam = 2.0 * load.sqrt(); // λ₁
    for it in 1..=max_iter {
        let s = solve(lam)?;
        if (load - s.load).abs() <= tol {
            return finish_with(s, it);
        }
        let next = lam + (s.load - load) / (s.load - n_prev) * (lam_prev - lam);
        if !(next.is_finite() && next > 0.0) {
            return Err(ContactError::NotConverged {
                iterations: it,
                lambda_lo: lam.min(lam_prev),
                lambda_hi: lam.max(lam_prev),
                residual: ((s.load - load) / load).abs(),
            });
        }
        lam_prev = lam;
        n_prev = s.load;
        lam = next;
    }
    Err(ContactError::NotConverged {
        iterations: max_iter,
        lambda_lo: lam.min(lam_prev),
        lambda_hi: lam.max(lam_prev),
        residual: f64::NAN,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fake(lambda: f64, load: f64) -> DimensionlessSolution {
        DimensionlessSolution {
            scheme: "fake".into(),
            lambda,
            beta: lambda / 2.0,
            load,
            friction_rho: 0.0,
            xi: vec![],
            pressure: vec![],
            n: 0,
            iterations: 0,
            error_estimate: None,
            auto: None,
            warnings: Vec::new(),
        }
    }

    #[test]
    fn finds_the_root_of_a_known_load_curve() {
        // N′(λ) = λ²/(4(1 + c·λ/(1+λ))): monotone, between the relaxed (1 + c) and glassy Hertz loads.
        let c = 999.0;
        let curve = |l: f64| l * l / (4.0 * (1.0 + c * l / (1.0 + l)));
        for &target in &[1e-6, 0.25, 1e4] {
            let s = solve_at_load(target, c, &LoadSettings::default(), |l| {
                Ok(fake(l, curve(l)))
            })
            .unwrap();
            assert!(
                (s.load / target - 1.0).abs() <= 1e-10,
                "N' = {target}: {}",
                s.load
            );
            assert!(s.iterations <= 15, "{} solves", s.iterations);
        }
    }

    #[test]
    fn unbracketed_load_names_the_bracket() {
        // A solver whose load never reaches the target: the error carries the last bracket tried.
        let err = solve_at_load(
            1.0,
            3.0,
            &LoadSettings {
                max_expand: 3,
                ..Default::default()
            },
            |l| Ok(fake(l, 1e-3 * l.min(2.0))),
        )
        .unwrap_err();
        match err {
            ContactError::Unbracketed {
                load,
                lambda_lo,
                lambda_hi,
                load_hi,
                ..
            } => {
                assert_eq!(load, 1.0);
                assert!(lambda_lo < lambda_hi && load_hi < 1.0);
                assert!(err_text(load, lambda_lo, lambda_hi).contains("not bracketed"));
            }
            other => panic!("expected Unbracketed, got {other:?}"),
        }
    }

    fn err_text(load: f64, lo: f64, hi: f64) -> String {
        unbracketed(load, lo, hi, -1.0, -1.0).to_string()
    }

    #[test]
    fn rejects_bad_load() {
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(solve_at_load(bad, 1.0, &LoadSettings::default(), |l| Ok(fake(l, l))).is_err());
        }
    }
}
