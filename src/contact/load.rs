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
//! **One loop for every scheme.** The root iteration itself is `iterate` (crate-internal): the
//! thesis and layer solvers ([`solve_at_load`]), the exact one-term solution
//! (`body::half_space::exact::one_term_at_load`: its own bracket, Brent to 4 ulp of ln λ) and the
//! auto scheme (`body::half_space::auto::load`: a guess with a model slope, `SafeSecant`, the
//! lumping correction as a shift of the target) all run through it. Each passes its solve and
//! residual, its start, a step rule (`Brent`, `SafeSecant`, the thesis' secant), which solution
//! to keep and its stopping rule; the loop counts the solves, keeps the solution and asks the rule
//! and the stopping rule at each turn.
//!
//! References: R. P. Brent, *Algorithms for Minimization without Derivatives*, Prentice-Hall 1973, ch. 4.

use super::error::{positive, ContactError};
use super::problem::DimensionlessSolution;
pub use super::settings::LoadSettings;

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
    // Brent's method on u = log λ, residual f(u) = log(N′/N′₀); the root stays between b and c.
    let mut rule = Brent::new((lo.ln(), f_lo), (hi.ln(), f_hi), 2.0);
    let seen = Seen {
        solves: solves.get(),
        g: best.0,
        sol: best.1,
    };
    let found = iterate(
        seen,
        &mut rule,
        Keep::Best,
        &mut |u| eval(u.exp()),
        &mut |t| brent_stop(t, settings),
    )?;
    finish_with(found.sol, found.solves)
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

/// The stopping rule of [`solve_at_load`]: the load met to `rel_tol` (or to `accept_tol` once the
/// bracket has collapsed to the resolution of λ, or the steps chase the rounding noise of N′(λ)).
fn brent_stop(t: &Turn<'_>, settings: &LoadSettings) -> Verdict {
    let p = t.proposal;
    // Noise floor: a step of < 1e-7 in log λ that still leaves the load within `accept_tol`
    // means the rounding noise of N′(λ) (≈ 1e-9) is being chased; stop there.
    if t.last_step.is_some_and(|s| s < 1e-7) && t.best <= settings.accept_tol {
        return Verdict::Done;
    }
    if t.best <= settings.rel_tol {
        return Verdict::Done;
    }
    let stuck = || {
        Verdict::Fail(ContactError::NotConverged {
            iterations: t.solves,
            lambda_lo: p.bracket.0.exp(),
            lambda_hi: p.bracket.1.exp(),
            residual: p.resid.exp_m1().abs(),
        })
    };
    if p.width <= p.tol.max(0.5 * settings.lambda_rel_tol) {
        // Bracket collapsed to the resolution of λ: accept if the load is met to `accept_tol`.
        if t.best <= settings.rel_tol.max(settings.accept_tol) {
            return Verdict::Done;
        }
        return stuck();
    }
    if t.solves >= settings.max_solves {
        return stuck();
    }
    Verdict::Go
}

// ---------------------------------------------------------------------------------------------
// The one root iteration. Every load loop of the crate (this file's [`solve_at_load`] and
// [`thesis_secant`], the exact one-term solution, the auto scheme) runs through [`iterate`]; what
// differs between them is passed in: the solve and its residual (with any target shift), the
// start (a bracket or a guess), the step rule ([`Brent`], [`SafeSecant`], [`ThesisStep`]), which
// solution to keep and the stopping rule.
// ---------------------------------------------------------------------------------------------

/// A step rule: it is shown every residual in the order the solves are made and proposes the next
/// iterate.
pub(crate) trait Step {
    /// The residual `g` at `u` (each solve, in order, the starting points included).
    fn observe(&mut self, u: f64, g: f64);
    /// The next iterate, with what a stopping rule needs to know of the rule's state.
    fn propose(&mut self) -> Proposal;
}

/// A step rule's proposal.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Proposal {
    /// The rule's current point (the iterate the step starts from; read by the tests).
    #[cfg_attr(not(test), allow(dead_code))]
    pub at: f64,
    /// The next iterate.
    pub next: f64,
    /// |next − current|.
    pub step: f64,
    /// The bracket (low, high) now known to hold the root.
    pub bracket: (f64, f64),
    /// Brent: the half-width |m| of the bracket; secants: the bracket's width.
    pub width: f64,
    /// The smallest step the rule takes (Brent: its ulp tolerance; secants: 0).
    pub tol: f64,
    /// The residual at the rule's current point.
    pub resid: f64,
}

/// What the stopping rule sees at each turn, before the proposed solve.
pub(crate) struct Turn<'p> {
    pub proposal: &'p Proposal,
    /// Smallest |residual| seen (start and solves of the loop).
    pub best: f64,
    /// Solves made, those before the loop (bracket, guess) included.
    pub solves: usize,
    /// Solves made by the loop itself.
    pub steps: usize,
    /// |step| that led to the current iterate (`None` before the loop's first solve).
    pub last_step: Option<f64>,
}

/// A stopping rule's verdict.
pub(crate) enum Verdict {
    /// Make the proposed solve.
    Go,
    /// Stop with the kept solution.
    Done,
    /// Stop with this error.
    Fail(ContactError),
}

/// Which solution the loop hands back.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Keep {
    /// The one of smallest |residual| (the start included).
    Best,
    /// The last solve (or the start if no solve was made).
    Last,
}

/// The state the loop starts from: the solves made before it, and the kept point's residual and
/// solution.
pub(crate) struct Seen<S> {
    pub solves: usize,
    pub g: f64,
    pub sol: S,
}

/// The loop's answer: the kept solution and the solves made (before the loop included).
pub(crate) struct Found<S> {
    pub sol: S,
    pub solves: usize,
}

/// The root iteration: ask the rule for the next iterate, let `stop` judge, solve there, show the
/// rule the residual, keep the solution (`keep`), and again.
pub(crate) fn iterate<S>(
    seen: Seen<S>,
    rule: &mut dyn Step,
    keep: Keep,
    eval: &mut dyn FnMut(f64) -> Result<(f64, S), ContactError>,
    stop: &mut dyn FnMut(&Turn<'_>) -> Verdict,
) -> Result<Found<S>, ContactError> {
    let Seen {
        mut solves,
        g,
        sol: mut kept,
    } = seen;
    let mut best = g.abs();
    let (mut steps, mut last_step) = (0usize, None);
    loop {
        let proposal = rule.propose();
        let turn = Turn {
            proposal: &proposal,
            best,
            solves,
            steps,
            last_step,
        };
        match stop(&turn) {
            Verdict::Go => {}
            Verdict::Done => return Ok(Found { sol: kept, solves }),
            Verdict::Fail(err) => return Err(err),
        }
        let (g, sol) = eval(proposal.next)?;
        solves += 1;
        steps += 1;
        last_step = Some(proposal.step);
        rule.observe(proposal.next, g);
        let better = g.abs() < best;
        if better {
            best = g.abs();
        }
        if keep == Keep::Last || better {
            kept = sol;
        }
    }
}

/// Brent's method (Brent 1973, ch. 4) on a bracket [lo, hi] with residuals of opposite signs:
/// inverse quadratic interpolation or the secant when [`crate::special::brent::brent_step`]
/// accepts it, else bisection; steps never shorter than `ulps`·ε·max(|b|, 1).
pub(crate) struct Brent {
    /// Last iterate a, best end b, other end c of the bracket [b, c], and their residuals.
    a: (f64, f64),
    b: (f64, f64),
    c: (f64, f64),
    /// The last step d and the one before e.
    d: f64,
    e: f64,
    ulps: f64,
}

impl Brent {
    /// The rule on the bracket (lo, f_lo), (hi, f_hi); `ulps` sets the smallest step.
    pub(crate) fn new(lo: (f64, f64), hi: (f64, f64), ulps: f64) -> Self {
        Self {
            a: lo,
            b: hi,
            c: lo,
            d: hi.0 - lo.0,
            e: hi.0 - lo.0,
            ulps,
        }
    }
}

impl Step for Brent {
    fn observe(&mut self, u: f64, g: f64) {
        self.a = self.b;
        self.b = (u, g);
    }

    fn propose(&mut self) -> Proposal {
        if (self.b.1 > 0.0) == (self.c.1 > 0.0) {
            self.c = self.a;
            self.d = self.b.0 - self.a.0;
            self.e = self.d;
        }
        if self.c.1.abs() < self.b.1.abs() {
            self.a = self.b;
            self.b = self.c;
            self.c = self.a;
        }
        let ((a, fa), (b, fb), (c, fc)) = (self.a, self.b, self.c);
        let tol = self.ulps * f64::EPSILON * b.abs().max(1.0);
        let m = 0.5 * (c - b);
        (self.d, self.e) = crate::special::brent::brent_step(
            (a, b, c),
            (fa, fb, fc),
            m,
            tol,
            (self.d, self.e),
            fa.is_finite() && fc.is_finite(),
        );
        let step = if self.d.abs() > tol {
            self.d
        } else {
            tol.copysign(m)
        };
        Proposal {
            at: b,
            next: b + step,
            step: step.abs(),
            bracket: (b.min(c), b.max(c)),
            width: m.abs(),
            tol,
            resid: fb,
        }
    }
}

/// A secant safeguarded by the bracket it narrows: the slope from the last two iterates when it is
/// positive, else the last slope (the first from a model); a step that leaves the bracket becomes
/// bisection unless it is already shorter than `small` (a converged step may land on the bracket
/// end it starts from).
pub(crate) struct SafeSecant {
    lo: f64,
    hi: f64,
    current: Option<(f64, f64)>,
    prev: Option<(f64, f64)>,
    /// The slope last used (dg/du).
    pub(crate) slope: f64,
    small: f64,
}

impl SafeSecant {
    /// The rule inside (lo, hi) with the model slope `slope` to start with.
    pub(crate) fn new((lo, hi): (f64, f64), slope: f64, small: f64) -> Self {
        Self {
            lo,
            hi,
            current: None,
            prev: None,
            slope,
            small,
        }
    }
}

impl Step for SafeSecant {
    fn observe(&mut self, u: f64, g: f64) {
        self.prev = self.current.replace((u, g));
    }

    fn propose(&mut self) -> Proposal {
        let (u, g) = self
            .current
            .expect("a secant proposes after its first residual");
        if g < 0.0 {
            self.lo = self.lo.max(u);
        } else {
            self.hi = self.hi.min(u);
        }
        let (lo, hi) = (self.lo, self.hi);
        let at = |next: f64| Proposal {
            at: u,
            next,
            step: (next - u).abs(),
            bracket: (lo, hi),
            width: hi - lo,
            tol: 0.0,
            resid: g,
        };
        if g == 0.0 {
            return at(u);
        }
        let s = match self.prev {
            Some((up, gp)) if (u - up).abs() > 0.0 && (g - gp) / (u - up) > 0.0 => {
                (g - gp) / (u - up)
            }
            _ => self.slope,
        };
        self.slope = s;
        let mut next = u - g / s;
        if !(next > lo && next < hi) && (g / s).abs() >= self.small {
            next = 0.5 * (lo + hi);
        }
        at(next)
    }
}

/// The thesis' secant (ch. 4, Fig. 4) on N′(λ) itself: λₙ₊₁ = λₙ + (N′ₙ − N′₀)/(N′ₙ − N′ₙ₋₁)·(λₙ₋₁ − λₙ),
/// from (λ₀, N′ = 0); the residual it is shown is N′ itself.
#[cfg(test)]
struct ThesisStep {
    load: f64,
    prev: (f64, f64),
    current: (f64, f64),
}

#[cfg(test)]
impl Step for ThesisStep {
    fn observe(&mut self, u: f64, g: f64) {
        self.prev = std::mem::replace(&mut self.current, (u, g));
    }

    fn propose(&mut self) -> Proposal {
        let ((lam_prev, n_prev), (lam, n)) = (self.prev, self.current);
        let next = lam + (n - self.load) / (n - n_prev) * (lam_prev - lam);
        Proposal {
            at: lam,
            next,
            step: (next - lam).abs(),
            bracket: (lam.min(lam_prev), lam.max(lam_prev)),
            width: (lam - lam_prev).abs(),
            tol: 0.0,
            resid: n,
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
#[cfg(test)]
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
    // λ₀ = λ₁/2 with N₀ = 0, then λ₁ = 2√N′₀
    let (lam0, lam1) = (load.sqrt(), 2.0 * load.sqrt());
    if max_iter == 0 {
        return Err(out_of_solves(0, lam1, lam0));
    }
    let first = solve(lam1)?;
    let mut rule = ThesisStep {
        load,
        prev: (lam0, 0.0),
        current: (lam1, first.load),
    };
    let seen = Seen {
        solves: 1,
        g: first.load,
        sol: first,
    };
    let found = iterate(
        seen,
        &mut rule,
        Keep::Last,
        &mut |lam| solve(lam).map(|s| (s.load, s)),
        &mut |t| {
            let p = t.proposal;
            if (load - p.resid).abs() <= tol {
                return Verdict::Done;
            }
            let (lo, hi) = p.bracket;
            if !(p.next.is_finite() && p.next > 0.0) {
                return Verdict::Fail(ContactError::NotConverged {
                    iterations: t.solves,
                    lambda_lo: lo,
                    lambda_hi: hi,
                    residual: ((p.resid - load) / load).abs(),
                });
            }
            if t.solves >= max_iter {
                // the last pair: the step not taken and the current λ
                return Verdict::Fail(out_of_solves(max_iter, p.next, p.at));
            }
            Verdict::Go
        },
    )?;
    finish_with(found.sol, found.solves)
}

/// [`thesis_secant`] out of solves: the last two λ and no residual.
#[cfg(test)]
fn out_of_solves(iterations: usize, lam: f64, lam_prev: f64) -> ContactError {
    ContactError::NotConverged {
        iterations,
        lambda_lo: lam.min(lam_prev),
        lambda_hi: lam.max(lam_prev),
        residual: f64::NAN,
    }
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
            diagnostics: None,
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
