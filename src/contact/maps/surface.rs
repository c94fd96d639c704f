//! The interpolant of ln φ(ln s, ln η) and ln λ(ln s, ln η) (φ = ρF/N on the bonded layer) on a
//! rectangle: tensor-product Chebyshev panels at the Lobatto points, refined per direction until the
//! coefficient tail meets the tolerance (module doc of [`super::covered`]).
//!
//! Input: a [`CoveredProblem`], the ranges of x = ln s and y = ln η, [`MapSettings`]; output:
//! [`CoveredSurface`].
//!
//! # Method
//! A panel [a, b] × [c, d] holds the values at the (n_x + 1)(n_y + 1) points
//! (x_j, y_k) = (mid_x + half_x·cos(πj/n_x), mid_y + half_y·cos(πk/n_y)); its coefficients
//! c_jk of Σ c_jk T_j(t) T_k(u) follow from the 1-D discrete cosine transform along y for each j
//! and then along x for each k (Trefethen, *Approximation Theory and Approximation Practice*, ch. 3
//! and 8; the tensor product of the 1-D interpolants). As in 1-D ([`super`]) the estimate in each
//! direction is twice the sum of the magnitudes of the last quarter of the coefficients in that
//! direction, summed over the other index: e_x = 2 Σ_{j ≥ n_x − ⌊n_x/4⌋} Σ_k |c_jk|, e_y likewise, and
//! the panel's estimate is e_x + e_y (the interpolation error is bounded by the neglected coefficients
//! of both directions; the corner block is counted twice). A panel whose estimate exceeds half the
//! tolerance doubles its degree in the direction with the larger estimate (reusing the nodes: the
//! Lobatto points of n are those of 2n with even index; one direction at a time, since doubling both
//! at once took 297 layer solves where 165 sufficed on the shipped compounds), and past the largest
//! degree is halved in that direction; all pending nodes are solved in parallel (rayon).
//!
//! Directions: x = ln s starts with [`MapSettings::panel_width`] and degree
//! [`MapSettings::start_degree`] like the 1-D maps; y = ln η starts with panels of
//! [`ETA_PANEL_WIDTH`] (two decades) and degree [`ETA_START_DEGREE`]: a scene's maps span a factor
//! of 2–4 in load (η ∝ 1/√N*), so most maps need a low degree in η.
//!
//! Node solves: the layer at [`super::node_tol`] (a tenth of the map's tolerance, the layer's own
//! floor 1e−4 permitting); the surface's [`CoveredSurface::error_estimate`] is the largest panel
//! estimate (≤ tol/2) plus the largest node estimate of the layer solver.

use super::covered::{CoveredNode, CoveredProblem};
use super::reduced::node_tol;
use super::{FrictionMapError, MapSettings, MAX_PANELS};
use crate::special::chebyshev::{clenshaw, lobatto_coefficients};
use rayon::prelude::*;
use std::f64::consts::PI;

/// Initial panel width in y = ln η: two decades of the cover over the glassy contact length.
pub const ETA_PANEL_WIDTH: f64 = 2.0 * std::f64::consts::LN_10;
/// Starting degree in y (5 nodes).
pub const ETA_START_DEGREE: usize = 4;
/// Largest degree in y before a panel is halved in y.
pub const ETA_MAX_DEGREE: usize = 16;
/// Distinct node warnings kept (a bound on the report's length).
const MAX_WARNINGS: usize = 8;

/// One panel: coefficients of ln φ and ln λ on [a, b] × [c, d], row j (degree in x) of length n_y + 1.
#[derive(Debug, Clone, PartialEq)]
struct Panel {
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    ny: usize,
    phi: Vec<f64>,
    lambda: Vec<f64>,
    estimate: f64,
}

impl Panel {
    fn contains(&self, x: f64, y: f64) -> bool {
        x >= self.a && x <= self.b && y >= self.c && y <= self.d
    }
}

/// The interpolant of ln φ and ln λ over a rectangle of (ln s, ln η).
#[derive(Debug, Clone, PartialEq)]
pub struct CoveredSurface {
    panels: Vec<Panel>,
    /// Largest panel interpolation estimate (absolute in ln φ and ln λ ≈ relative in φ and λ).
    pub interpolation_estimate: f64,
    /// Largest error estimate of the layer solver at the nodes.
    pub node_estimate: f64,
    /// interpolation + node estimate: the relative error bound the map reports.
    pub error_estimate: f64,
    /// Node solves made.
    pub solves: usize,
    /// Tolerance asked of the node solves.
    pub node_tol: f64,
    /// Distinct warnings of the node solves (at most a few).
    pub warnings: Vec<String>,
}

/// Coefficients of the tensor-product interpolant from values v[j·(n_y+1) + k] at the Lobatto grid.
pub(super) fn coefficients_2d(v: &[f64], nx: usize, ny: usize) -> Vec<f64> {
    let w = ny + 1;
    let mut c = Vec::with_capacity(v.len());
    for j in 0..=nx {
        c.extend(lobatto_coefficients(&v[j * w..(j + 1) * w]));
    }
    for k in 0..w {
        let col: Vec<f64> = (0..=nx).map(|j| c[j * w + k]).collect();
        for (j, cj) in lobatto_coefficients(&col).into_iter().enumerate() {
            c[j * w + k] = cj;
        }
    }
    c
}

/// Tail estimates (e_x, e_y) of 2-D coefficients (module doc).
pub(super) fn tails_2d(c: &[f64], nx: usize, ny: usize) -> (f64, f64) {
    let w = ny + 1;
    let (jx, ky) = (nx - nx / 4, ny - ny / 4);
    let (mut ex, mut ey) = (0.0, 0.0);
    for j in 0..=nx {
        for k in 0..=ny {
            let m = c[j * w + k].abs();
            if j >= jx {
                ex += m;
            }
            if k >= ky {
                ey += m;
            }
        }
    }
    (2.0 * ex, 2.0 * ey)
}

/// The 2-D series at t, u ∈ [−1, 1].
pub(super) fn clenshaw_2d(c: &[f64], ny: usize, t: f64, u: f64) -> f64 {
    let row: Vec<f64> = c.chunks(ny + 1).map(|r| clenshaw(r, u)).collect();
    clenshaw(&row, t)
}

/// A panel waiting for nodes: its degrees and the values already known (at the grid of `old`).
struct Pending {
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    nx: usize,
    ny: usize,
    /// (n_x, n_y, ln φ, ln λ) of the previous grid when a degree was just doubled.
    old: Option<(usize, usize, Vec<f64>, Vec<f64>)>,
}

impl Pending {
    fn fresh(a: f64, b: f64, c: f64, d: f64, nx: usize, ny: usize) -> Self {
        Pending {
            a,
            b,
            c,
            d,
            nx,
            ny,
            old: None,
        }
    }

    /// Index into `old` of grid point (j, k), if it was solved already.
    fn known(&self, j: usize, k: usize) -> Option<usize> {
        let (ox, oy, _, _) = self.old.as_ref()?;
        let (jx, ky) = (j * ox, k * oy);
        (jx % self.nx == 0 && ky % self.ny == 0).then(|| (jx / self.nx) * (oy + 1) + ky / self.ny)
    }

    fn point(&self, j: usize, k: usize) -> (f64, f64) {
        let node = |lo: f64, hi: f64, i: usize, n: usize| {
            0.5 * (lo + hi) + 0.5 * (hi - lo) * (PI * i as f64 / n as f64).cos()
        };
        (
            node(self.a, self.b, j, self.nx),
            node(self.c, self.d, k, self.ny),
        )
    }
}

/// `m` equal pieces of [lo, hi] with exact ends.
fn pieces(lo: f64, hi: f64, width: f64) -> Vec<(f64, f64)> {
    let m = ((hi - lo) / width).ceil().max(1.0) as usize;
    let at = |k: usize| match k {
        0 => lo,
        k if k == m => hi,
        k => lo + (hi - lo) * k as f64 / m as f64,
    };
    (0..m).map(|k| (at(k), at(k + 1))).collect()
}

/// Pad a degenerate range so a panel has a width (a single value is still interpolated).
fn padded((lo, hi): (f64, f64)) -> (f64, f64) {
    if hi - lo < 1e-3 {
        (lo - 0.05, hi + 0.05)
    } else {
        (lo, hi)
    }
}

/// Check that both ranges have finite ends with hi ≥ lo.
fn check_ranges(x_range: (f64, f64), y_range: (f64, f64)) -> Result<(), FrictionMapError> {
    for (name, (lo, hi)) in [("ln s range", x_range), ("ln(h/l_g) range", y_range)] {
        if !(lo.is_finite() && hi.is_finite() && hi >= lo) {
            return Err(FrictionMapError::BadValue {
                field: name.into(),
                value: hi - lo,
                expected: "finite ends with hi ≥ lo",
            });
        }
    }
    Ok(())
}

/// The grid points of the pending panels not solved yet: (panel, index, x, y).
fn wanted_nodes(pending: &[Pending]) -> Vec<(usize, usize, f64, f64)> {
    pending
        .iter()
        .enumerate()
        .flat_map(|(p, q)| {
            let w = q.ny + 1;
            (0..(q.nx + 1) * w)
                .filter(move |i| q.known(i / w, i % w).is_none())
                .map(move |i| {
                    let (x, y) = q.point(i / w, i % w);
                    (p, i, x, y)
                })
        })
        .collect()
}

/// Each pending panel's (ln φ, ln λ) values on its grid: the known ones from `old`, the rest from
/// the node solves `nodes` at the points `wanted`.
fn filled_values(
    pending: &[Pending],
    wanted: &[(usize, usize, f64, f64)],
    nodes: &[CoveredNode],
) -> Vec<(Vec<f64>, Vec<f64>)> {
    let mut filled: Vec<(Vec<f64>, Vec<f64>)> = pending
        .iter()
        .map(|q| {
            let size = (q.nx + 1) * (q.ny + 1);
            let (mut phi, mut lambda) = (vec![f64::NAN; size], vec![f64::NAN; size]);
            if let Some((_, _, op, ol)) = &q.old {
                for i in 0..size {
                    if let Some(o) = q.known(i / (q.ny + 1), i % (q.ny + 1)) {
                        phi[i] = op[o];
                        lambda[i] = ol[o];
                    }
                }
            }
            (phi, lambda)
        })
        .collect();
    for (&(p, i, _, _), node) in wanted.iter().zip(nodes) {
        filled[p].0[i] = node.ln_phi;
        filled[p].1[i] = node.ln_lambda;
    }
    filled
}

/// The panels of one refinement round: those finished, the next round's pending ones, and the limits.
struct Round<'a> {
    done: &'a mut Vec<Panel>,
    next: &'a mut Vec<Pending>,
    /// Panels pending in this round (for the panel cap).
    pending: usize,
    /// Half the map's tolerance: a panel's estimate must meet it.
    budget: f64,
    /// Starting and largest degree in x.
    nx0: usize,
    nx_max: usize,
}

impl Round<'_> {
    /// Fit panel `q` to its values: done when its estimate meets the budget, else doubled in the
    /// direction with the larger estimate or halved there past the largest degree.
    fn refine(
        &mut self,
        q: &Pending,
        phi_v: Vec<f64>,
        lambda_v: Vec<f64>,
    ) -> Result<(), FrictionMapError> {
        let (nx, ny) = (q.nx, q.ny);
        let phi = coefficients_2d(&phi_v, nx, ny);
        let lambda = coefficients_2d(&lambda_v, nx, ny);
        let (px, py) = tails_2d(&phi, nx, ny);
        let (lx, ly) = tails_2d(&lambda, nx, ny);
        let (ex, ey) = (px.max(lx), py.max(ly));
        let estimate = ex + ey;
        if estimate <= self.budget {
            self.done.push(Panel {
                a: q.a,
                b: q.b,
                c: q.c,
                d: q.d,
                ny,
                phi,
                lambda,
                estimate,
            });
            return Ok(());
        }
        // refine the direction holding the larger part of the estimate (the other one, if
        // still over half the budget, in a later round: fewer nodes than doubling both)
        let (want_x, want_y) = (ex >= ey, ey > ex);
        let split_x = want_x && 2 * nx > self.nx_max;
        let split_y = want_y && 2 * ny > ETA_MAX_DEGREE;
        if split_x || split_y {
            if self.done.len() + self.next.len() + self.pending >= MAX_PANELS {
                return Err(FrictionMapError::NotConverged {
                    estimate,
                    tol: self.budget,
                    panels: self.done.len() + self.pending,
                });
            }
            let halves = |lo: f64, hi: f64, split: bool| {
                let mid = 0.5 * (lo + hi);
                if split {
                    vec![(lo, mid), (mid, hi)]
                } else {
                    vec![(lo, hi)]
                }
            };
            let nx1 = if split_x { self.nx0 } else { nx };
            let ny1 = if split_y { ETA_START_DEGREE } else { ny };
            for (a, b) in halves(q.a, q.b, split_x) {
                for (c, d) in halves(q.c, q.d, split_y) {
                    self.next.push(Pending::fresh(a, b, c, d, nx1, ny1));
                }
            }
        } else {
            self.next.push(Pending {
                a: q.a,
                b: q.b,
                c: q.c,
                d: q.d,
                nx: if want_x { 2 * nx } else { nx },
                ny: if want_y { 2 * ny } else { ny },
                old: Some((nx, ny, phi_v, lambda_v)),
            });
        }
        Ok(())
    }
}

impl CoveredSurface {
    /// Build the interpolant on x_range × y_range (x = ln s, y = ln η) to `settings.tol` (module doc).
    pub fn build(
        problem: &CoveredProblem,
        x_range: (f64, f64),
        y_range: (f64, f64),
        settings: &MapSettings,
    ) -> Result<Self, FrictionMapError> {
        super::curve::check_tol(settings.tol)?;
        check_ranges(x_range, y_range)?;
        let width = if settings.panel_width.is_finite() && settings.panel_width > 0.0 {
            settings.panel_width
        } else {
            MapSettings::default().panel_width
        };
        let ((x_lo, x_hi), (y_lo, y_hi)) = (padded(x_range), padded(y_range));
        let tol = node_tol(settings.tol);
        let budget = 0.5 * settings.tol;
        let nx0 = settings.start_degree.clamp(4, 64);
        let nx_max = settings.max_degree.clamp(nx0, 256);
        let mut pending: Vec<Pending> = Vec::new();
        for &(a, b) in &pieces(x_lo, x_hi, width) {
            for &(c, d) in &pieces(y_lo, y_hi, ETA_PANEL_WIDTH) {
                pending.push(Pending::fresh(a, b, c, d, nx0, ETA_START_DEGREE));
            }
        }
        let mut done: Vec<Panel> = Vec::new();
        let (mut solves, mut node_estimate) = (0, 0.0f64);
        let mut warnings: Vec<String> = Vec::new();
        while !pending.is_empty() {
            let wanted = wanted_nodes(&pending);
            let nodes: Vec<CoveredNode> = wanted
                .par_iter()
                .map(|&(_, _, x, y)| problem.node(x, y, tol))
                .collect::<Result<_, _>>()?;
            solves += nodes.len();
            for n in &nodes {
                node_estimate = node_estimate.max(n.error_estimate);
                for w in &n.warnings {
                    if warnings.len() < MAX_WARNINGS && !warnings.contains(w) {
                        warnings.push(w.clone());
                    }
                }
            }
            let filled = filled_values(&pending, &wanted, &nodes);
            let mut next = Vec::new();
            let mut round = Round {
                done: &mut done,
                next: &mut next,
                pending: pending.len(),
                budget,
                nx0,
                nx_max,
            };
            for (q, (phi_v, lambda_v)) in pending.iter().zip(filled) {
                round.refine(q, phi_v, lambda_v)?;
            }
            pending = next;
        }
        let interpolation_estimate = done.iter().map(|p| p.estimate).fold(0.0, f64::max);
        Ok(CoveredSurface {
            panels: done,
            interpolation_estimate,
            node_estimate,
            error_estimate: interpolation_estimate + node_estimate,
            solves,
            node_tol: tol,
            warnings,
        })
    }

    /// Number of panels.
    pub fn panels(&self) -> usize {
        self.panels.len()
    }

    /// Each panel's rectangle [a, b] × [c, d] in (ln s, ln η) and degrees (n_x, n_y).
    pub fn panel_shapes(&self) -> Vec<([f64; 4], (usize, usize))> {
        self.panels
            .iter()
            .map(|p| ([p.a, p.b, p.c, p.d], (p.phi.len() / (p.ny + 1) - 1, p.ny)))
            .collect()
    }

    /// (ρF/N, λ) at x = ln s, y = ln η; `None` outside the rectangle.
    pub fn eval(&self, x: f64, y: f64) -> Option<(f64, f64)> {
        let p = self.panels.iter().find(|p| p.contains(x, y))?;
        let t = ((2.0 * x - p.a - p.b) / (p.b - p.a)).clamp(-1.0, 1.0);
        let u = ((2.0 * y - p.c - p.d) / (p.d - p.c)).clamp(-1.0, 1.0);
        Some((
            clenshaw_2d(&p.phi, p.ny, t, u).exp(),
            clenshaw_2d(&p.lambda, p.ny, t, u).exp(),
        ))
    }
}
