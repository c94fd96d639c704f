//! The interpolant of ln φ(ln s) and ln λ(ln s) (φ = ρF/N) on a range of ln s: Chebyshev panels
//! at the Lobatto points, refined until the coefficient tail meets the tolerance (module doc of
//! [`super`]).
//!
//! Input: a [`ReducedProblem`], a range of x = ln s, [`MapSettings`]; output: [`ReducedCurve`].

use super::reduced::{node_tol, Node, ReducedProblem};
use super::{FrictionMapError, MapSettings, MAX_PANELS};
use crate::contact::body::half_space::auto::AutoSettings;
use crate::special::chebyshev::{clenshaw, lobatto_coefficients};
use rayon::prelude::*;
use std::f64::consts::PI;

/// One panel: Chebyshev coefficients of ln φ and ln λ on [a, b].
#[derive(Debug, Clone, PartialEq)]
struct Panel {
    a: f64,
    b: f64,
    phi: Vec<f64>,
    lambda: Vec<f64>,
    estimate: f64,
}

/// The interpolant of ln φ(ln s) and ln λ(ln s) on a range of ln s.
#[derive(Debug, Clone, PartialEq)]
pub struct ReducedCurve {
    panels: Vec<Panel>,
    /// Largest panel error estimate (absolute, in ln φ and ln λ ≈ relative in φ and λ).
    pub error_estimate: f64,
    /// Node solves made.
    pub solves: usize,
    /// Tolerance of the node solves.
    pub node_tol: f64,
}

/// Error estimate of a Chebyshev interpolant from its coefficients: twice the sum of the last
/// quarter of them (see the module doc).
pub(super) fn tail(c: &[f64]) -> f64 {
    let n = c.len() - 1;
    2.0 * c[n - n / 4..].iter().map(|x| x.abs()).sum::<f64>()
}

/// Check a map tolerance: in [1e−10, 1e−2].
pub(super) fn check_tol(tol: f64) -> Result<(), FrictionMapError> {
    if (1e-10..=1e-2).contains(&tol) {
        Ok(())
    } else {
        Err(FrictionMapError::BadValue {
            field: "tol".into(),
            value: tol,
            expected: "in [1e-10, 1e-2]",
        })
    }
}

/// A panel waiting for nodes: [a, b], its degree, and ln φ and ln λ at the Lobatto points of half
/// that degree when it was just doubled (the even points are reused), else empty.
struct Pending {
    a: f64,
    b: f64,
    n: usize,
    phi: Vec<f64>,
    lambda: Vec<f64>,
}

impl Pending {
    fn fresh(a: f64, b: f64, n: usize) -> Self {
        Pending {
            a,
            b,
            n,
            phi: vec![],
            lambda: vec![],
        }
    }
}

/// The initial panels: [x_lo, x_hi] in equal pieces of at most `width`, exact ends (so every
/// query's x lies inside).
fn initial_panels(x_lo: f64, x_hi: f64, width: f64, n0: usize) -> Vec<Pending> {
    let m = ((x_hi - x_lo) / width).ceil().max(1.0) as usize;
    let at = |k: usize| match k {
        0 => x_lo,
        k if k == m => x_hi,
        k => x_lo + (x_hi - x_lo) * k as f64 / m as f64,
    };
    (0..m)
        .map(|k| Pending::fresh(at(k), at(k + 1), n0))
        .collect()
}

/// The new nodes (panel, index, x) of every pending panel: all n + 1 Lobatto points for a fresh
/// panel, the odd-indexed ones after a doubling (cos(π·2j/2n) = cos(πj/n) are known).
fn new_nodes(pending: &[Pending]) -> Vec<(usize, usize, f64)> {
    pending
        .iter()
        .enumerate()
        .flat_map(|(p, q)| {
            let fresh = q.phi.is_empty();
            let (mid, half) = (0.5 * (q.a + q.b), 0.5 * (q.b - q.a));
            (0..=q.n)
                .filter(move |k| fresh || k % 2 == 1)
                .map(move |k| (p, k, mid + half * (PI * k as f64 / q.n as f64).cos()))
        })
        .collect()
}

/// Each pending panel's values at its n + 1 points: the known even ones and the new `nodes`.
fn fill(
    pending: &[Pending],
    wanted: &[(usize, usize, f64)],
    nodes: &[Node],
) -> Vec<(Vec<f64>, Vec<f64>)> {
    let mut filled: Vec<(Vec<f64>, Vec<f64>)> = pending
        .iter()
        .map(|q| {
            let mut phi = vec![f64::NAN; q.n + 1];
            let mut lambda = vec![f64::NAN; q.n + 1];
            for (j, (&f, &l)) in q.phi.iter().zip(&q.lambda).enumerate() {
                phi[2 * j] = f;
                lambda[2 * j] = l;
            }
            (phi, lambda)
        })
        .collect();
    for (&(p, k, _), node) in wanted.iter().zip(nodes) {
        filled[p].0[k] = node.ln_phi;
        filled[p].1[k] = node.ln_lambda;
    }
    filled
}

/// What becomes of a filled panel: done (its estimate meets the budget), doubled, or halved.
enum Step {
    Done(Panel),
    Double(Pending),
    /// The two halves, and the estimate that failed.
    Split([Pending; 2], f64),
}

/// Coefficients and estimate of a filled panel, and the next step (module doc of [`super`]).
fn step(
    q: &Pending,
    phi_v: Vec<f64>,
    lambda_v: Vec<f64>,
    budget: f64,
    n0: usize,
    n_max: usize,
) -> Step {
    let phi = lobatto_coefficients(&phi_v);
    let lambda = lobatto_coefficients(&lambda_v);
    let estimate = tail(&phi).max(tail(&lambda));
    if estimate <= budget {
        Step::Done(Panel {
            a: q.a,
            b: q.b,
            phi,
            lambda,
            estimate,
        })
    } else if 2 * q.n <= n_max {
        Step::Double(Pending {
            a: q.a,
            b: q.b,
            n: 2 * q.n,
            phi: phi_v,
            lambda: lambda_v,
        })
    } else {
        let mid = 0.5 * (q.a + q.b);
        Step::Split(
            [Pending::fresh(q.a, mid, n0), Pending::fresh(mid, q.b, n0)],
            estimate,
        )
    }
}

impl ReducedCurve {
    /// Build the interpolant on [x_lo, x_hi] (x = ln s) to `settings.tol` (see the module doc).
    pub fn build(
        problem: &ReducedProblem,
        x_lo: f64,
        x_hi: f64,
        settings: &MapSettings,
    ) -> Result<Self, FrictionMapError> {
        check_tol(settings.tol)?;
        if !(x_lo.is_finite() && x_hi.is_finite() && x_hi >= x_lo) {
            return Err(FrictionMapError::BadValue {
                field: "ln s range".into(),
                value: x_hi - x_lo,
                expected: "finite ends with x_hi ≥ x_lo",
            });
        }
        let width = if settings.panel_width.is_finite() && settings.panel_width > 0.0 {
            settings.panel_width
        } else {
            MapSettings::default().panel_width
        };
        // Pad a degenerate range so the panel has a width (a single point is still interpolated).
        let (x_lo, x_hi) = if x_hi - x_lo < 1e-3 {
            (x_lo - 0.05, x_hi + 0.05)
        } else {
            (x_lo, x_hi)
        };
        let node_settings = AutoSettings {
            tol: node_tol(settings.tol),
            max_iterations: 100,
            profile_points: 8,
            gap_check: false,
        };
        let budget = 0.5 * settings.tol;
        let n0 = settings.start_degree.clamp(4, 64);
        let n_max = settings.max_degree.clamp(n0, 256);
        let mut pending = initial_panels(x_lo, x_hi, width, n0);
        let mut done: Vec<Panel> = Vec::new();
        let mut solves = 0;
        while !pending.is_empty() {
            let wanted = new_nodes(&pending);
            let nodes: Vec<Node> = wanted
                .par_iter()
                .map(|&(_, _, x)| problem.node(x, &node_settings))
                .collect::<Result<_, _>>()?;
            solves += nodes.len();
            let filled = fill(&pending, &wanted, &nodes);
            let mut next = Vec::new();
            for (q, (phi_v, lambda_v)) in pending.iter().zip(filled) {
                match step(q, phi_v, lambda_v, budget, n0, n_max) {
                    Step::Done(p) => done.push(p),
                    Step::Double(d) => next.push(d),
                    Step::Split(_, estimate)
                        if done.len() + next.len() + pending.len() >= MAX_PANELS =>
                    {
                        return Err(FrictionMapError::NotConverged {
                            estimate,
                            tol: budget,
                            panels: done.len() + pending.len(),
                        });
                    }
                    Step::Split(halves, _) => next.extend(halves),
                }
            }
            pending = next;
        }
        done.sort_by(|p, q| p.a.total_cmp(&q.a));
        let error_estimate = done.iter().map(|p| p.estimate).fold(0.0, f64::max);
        Ok(ReducedCurve {
            panels: done,
            error_estimate,
            solves,
            node_tol: node_settings.tol,
        })
    }

    /// Range [x_lo, x_hi] of ln s covered.
    pub fn range(&self) -> (f64, f64) {
        (
            self.panels.first().map_or(f64::NAN, |p| p.a),
            self.panels.last().map_or(f64::NAN, |p| p.b),
        )
    }

    /// Number of panels.
    #[cfg(test)]
    pub fn panels(&self) -> usize {
        self.panels.len()
    }

    /// (ρF/N, λ) at x = ln s; `None` outside the range.
    pub fn eval(&self, x: f64) -> Option<(f64, f64)> {
        let (lo, hi) = self.range();
        if !(x >= lo && x <= hi) {
            return None;
        }
        // panels are sorted and contiguous: the last one starting at or below x
        let i = self.panels.partition_point(|p| p.a <= x).max(1) - 1;
        let p = &self.panels[i];
        let t = ((2.0 * x - p.a - p.b) / (p.b - p.a)).clamp(-1.0, 1.0);
        Some((clenshaw(&p.phi, t).exp(), clenshaw(&p.lambda, t).exp()))
    }
}
