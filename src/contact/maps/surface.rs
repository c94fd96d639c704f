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
//! the panel's interpolation estimate is e_x + e_y (the interpolation error is bounded by the
//! neglected coefficients of both directions; the corner block is counted twice).
//!
//! # Error budget (node errors and the Lebesgue constants)
//! The nodes are layer solves with errors εⱼₖ (each below its estimate, the solver's own). The
//! surface is linear in the node values, so at any point its error is at most the interpolation
//! error of the exact values plus the interpolant of the εⱼₖ, and the latter is bounded by
//! Λ_{n_x}·Λ_{n_y}·max|εⱼₖ|: the Lebesgue constant of tensor-product interpolation is the product of
//! the 1-D ones, and at the n + 1 Chebyshev–Lobatto points Λ_n ≤ (2/π)·ln(n + 1) + 1 (ATAP,
//! Theorem 15.2): 2.0 at n = 4, 2.4 at 8, 2.8 at 16, 3.2 at 32, so the product is 5–8 here. A
//! panel is done when e_x + e_y + Λ_{n_x}Λ_{n_y}·ν ≤ tol, ν the largest node estimate of its
//! grid (the interpolation keeps at least tol/2 of the budget: more nodes cannot make up for node
//! solves short of their tolerance; the surface's estimate then exceeds tol and the map says so);
//! [`CoveredSurface::error_estimate`] is the largest e_x + e_y + Λ_{n_x}Λ_{n_y}·ν of a panel.
//!
//! The nodes are solved at [`MapSettings::node_tol_ratio`]·tol (default 1/100): the spectral layer
//! solve costs about the same at 1e−3 and at 1e−6 (5–10 ms, the former bench `maps_covered`, removed in issue 30 (docs/DEVLOG.md)), so a
//! tight node tolerance is nearly free and leaves ~90 % of the tolerance to the interpolation.
//! (Before: node solves at tol/10 and the interpolation held to tol/2, with the largest node
//! estimate added once, without the Lebesgue factor. On the conveyor-idler maps of the four
//! synthetic compounds that asked 85–165 layer solves where 45–85 now suffice.)
//!
//! # Refinement
//! A panel over its budget doubles its degree in the direction with the larger estimate (reusing
//! the nodes: the Lobatto points of n are those of 2n with even index; one direction at a time,
//! since doubling both at once took 297 layer solves where 165 sufficed on the shipped compounds),
//! and past the largest degree is halved in that direction. Every distinct point is solved once
//! ([`super::nodes`]: neighbouring panels share their edges, a refined panel keeps its nodes), from
//! a warm start, all pending chains of nodes in parallel (rayon).
//!
//! Directions: x = ln s starts with [`MapSettings::panel_width`] and degree
//! [`MapSettings::start_degree`] ([`MapSettings::covered`]: four decades, degree 8). y = ln η starts
//! with panels of [`ETA_PANEL_WIDTH`] (two decades) at the degree [`eta_start_degree`] picks from the
//! panel's width w: the coefficients in y decay geometrically, |c_k| ≈ 0.1·ρ^−k with ρ ≈ 7/w
//! (measured along lines of the maps of EMS-CA, TRIOS and the four synthetic compounds: w = 0.69,
//! a factor 2 in η, ρ ≈ 10; w = 1.6, ρ ≈ 5), and the start is the lowest degree whose tail is
//! predicted below tol/10: degree 4 for a scene's factor 4 in load at 1e−3, 6 for the benchmark's
//! factor 25. A scene's maps span a factor of 2–4 in load (η ∝ 1/√N*), so most maps need a low
//! degree in η. A start too low costs one doubling (its nodes kept), one too high a few nodes.

use super::covered_problem::CoveredProblem;
use super::nodes::NodeTable;
use super::{FrictionMapError, MapSettings, MAX_PANELS};
use crate::special::chebyshev::{clenshaw, lobatto_coefficients};
use std::f64::consts::PI;

/// Initial panel width in y = ln η: two decades of the cover over the glassy contact length.
pub(crate) const ETA_PANEL_WIDTH: f64 = 2.0 * std::f64::consts::LN_10;
/// Starting degree in y: 0, chosen per panel by [`eta_start_degree`].
pub(crate) const ETA_START_DEGREE: usize = 0;
/// Largest degree in y before a panel is halved in y.
pub(crate) const ETA_MAX_DEGREE: usize = 16;

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
    /// Interpolation estimate e_x + e_y.
    estimate: f64,
    /// Λ_x·Λ_y times the largest node estimate of the panel (module doc).
    node_bound: f64,
}

impl Panel {
    fn contains(&self, x: f64, y: f64) -> bool {
        x >= self.a && x <= self.b && y >= self.c && y <= self.d
    }

    /// ln λ of the panel's interpolant at (x, y) (clamped into the panel).
    fn ln_lambda(&self, x: f64, y: f64) -> f64 {
        let t = ((2.0 * x - self.a - self.b) / (self.b - self.a)).clamp(-1.0, 1.0);
        let u = ((2.0 * y - self.c - self.d) / (self.d - self.c)).clamp(-1.0, 1.0);
        clenshaw_2d(&self.lambda, self.ny, t, u)
    }
}

/// Upper bound of the Lebesgue constant of interpolation at the n + 1 Chebyshev–Lobatto points,
/// Λ_n ≤ (2/π)·ln(n + 1) + 1 (Trefethen, ATAP, Theorem 15.2).
pub(super) fn lebesgue(n: usize) -> f64 {
    2.0 / PI * ((n + 1) as f64).ln() + 1.0
}

/// The degrees a panel can start with in y, each with the index where its tail estimate starts
/// (n − ⌊n/4⌋).
const ETA_DEGREES: [usize; 7] = [4, 5, 6, 8, 10, 12, 16];

/// Starting degree in y of a panel of width `w` in ln η for the map tolerance `tol` (module doc):
/// the smallest of [`ETA_DEGREES`] whose tail c_{n−⌊n/4⌋}…c_n is predicted below tol/10 by the
/// measured decay |c_k| ≈ 0.1·ρ^−k, ρ ≈ 7/w.
pub(super) fn eta_start_degree(w: f64, tol: f64) -> usize {
    let rho = (7.0 / w).max(1.5);
    let needed = (1.0 / tol).ln() / rho.ln();
    ETA_DEGREES
        .into_iter()
        .find(|&n| (n - n / 4) as f64 >= needed)
        .unwrap_or(ETA_MAX_DEGREE)
}

/// The i-th of the n + 1 Lobatto points of [lo, hi], from hi (i = 0) to lo (i = n), with exact ends
/// and midpoint, so that grids sharing a point give it the same bits (module doc of [`super::nodes`]).
pub(super) fn lobatto(lo: f64, hi: f64, i: usize, n: usize) -> f64 {
    if i == 0 {
        hi
    } else if i == n {
        lo
    } else if 2 * i == n {
        0.5 * (lo + hi)
    } else {
        0.5 * (lo + hi) + 0.5 * (hi - lo) * (PI * i as f64 / n as f64).cos()
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
    /// Largest Λ_x·Λ_y·(largest node estimate) of a panel: what the node errors can add to the
    /// interpolant (module doc).
    pub node_error_bound: f64,
    /// Largest interpolation + node bound of a panel: the relative error bound the map reports.
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

/// A panel waiting for nodes: its rectangle, degrees, and the interpolant it refines (its λ
/// starts the new nodes' solves).
struct Pending {
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    nx: usize,
    ny: usize,
    guess: Option<std::sync::Arc<Panel>>,
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
            guess: None,
        }
    }

    fn point(&self, j: usize, k: usize) -> (f64, f64) {
        (
            lobatto(self.a, self.b, j, self.nx),
            lobatto(self.c, self.d, k, self.ny),
        )
    }

    /// The grid points, row j (x) by row, with the guess of λ there.
    fn grid(&self) -> impl Iterator<Item = (f64, f64, Option<f64>)> + '_ {
        let w = self.ny + 1;
        (0..(self.nx + 1) * w).map(move |i| {
            let (x, y) = self.point(i / w, i % w);
            (x, y, self.guess.as_ref().map(|g| g.ln_lambda(x, y).exp()))
        })
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

/// A panel's (ln φ, ln λ) values on its grid and the largest node estimate among them (every
/// point is in `table`).
fn panel_values(q: &Pending, table: &NodeTable) -> (Vec<f64>, Vec<f64>, f64) {
    let size = (q.nx + 1) * (q.ny + 1);
    let (mut phi, mut lambda, mut worst) =
        (Vec::with_capacity(size), Vec::with_capacity(size), 0.0f64);
    for (x, y, _) in q.grid() {
        let n = table
            .get(x, y)
            .expect("every grid point was solved in this round or before");
        phi.push(n.ln_phi);
        lambda.push(n.ln_lambda);
        worst = worst.max(n.error_estimate);
    }
    (phi, lambda, worst)
}

/// The panels of one refinement round: those finished, the next round's pending ones, and the limits.
struct Round<'a> {
    done: &'a mut Vec<Panel>,
    next: &'a mut Vec<Pending>,
    /// Panels pending in this round (for the panel cap).
    pending: usize,
    /// The map's tolerance: a panel's interpolation estimate plus its node bound must meet it.
    tol: f64,
    /// Starting and largest degree in x, starting degree in y (0: [`eta_start_degree`]).
    nx0: usize,
    nx_max: usize,
    ny0: usize,
}

impl Round<'_> {
    /// The starting degree in y of a panel [c, d].
    fn ny_start(&self, c: f64, d: f64) -> usize {
        if self.ny0 > 0 {
            self.ny0.max(2)
        } else {
            eta_start_degree(d - c, self.tol)
        }
    }
}

impl Round<'_> {
    /// Fit panel `q` to its values: done when its estimate meets the budget (module doc), else
    /// doubled in the direction with the larger estimate or halved there past the largest degree.
    fn refine(&mut self, q: &Pending, table: &NodeTable) -> Result<(), FrictionMapError> {
        let (nx, ny) = (q.nx, q.ny);
        let (phi_v, lambda_v, worst_node) = panel_values(q, table);
        let node_bound = lebesgue(nx) * lebesgue(ny) * worst_node;
        // what the node errors leave to the interpolation, but at least half the tolerance (node
        // solves short of their tolerance cannot be helped by more nodes; the surface's estimate
        // then exceeds tol and says so)
        let budget = (self.tol - node_bound).max(0.5 * self.tol);
        let phi = coefficients_2d(&phi_v, nx, ny);
        let lambda = coefficients_2d(&lambda_v, nx, ny);
        let (px, py) = tails_2d(&phi, nx, ny);
        let (lx, ly) = tails_2d(&lambda, nx, ny);
        let (ex, ey) = (px.max(lx), py.max(ly));
        let estimate = ex + ey;
        let panel = Panel {
            a: q.a,
            b: q.b,
            c: q.c,
            d: q.d,
            ny,
            phi,
            lambda,
            estimate,
            node_bound,
        };
        if estimate <= budget {
            self.done.push(panel);
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
                    tol: budget,
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
            let guess = std::sync::Arc::new(panel);
            for (a, b) in halves(q.a, q.b, split_x) {
                for (c, d) in halves(q.c, q.d, split_y) {
                    let ny1 = if split_y { self.ny_start(c, d) } else { ny };
                    self.next.push(Pending {
                        guess: Some(guess.clone()),
                        ..Pending::fresh(a, b, c, d, nx1, ny1)
                    });
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
                guess: Some(std::sync::Arc::new(panel)),
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
        let tol = if settings.node_tol_ratio > 0.0 && settings.node_tol_ratio <= 1.0 {
            settings.node_tol_ratio * settings.tol
        } else {
            super::COVERED_NODE_TOL_RATIO * settings.tol
        };
        let ny0 = settings.eta_start_degree.min(ETA_MAX_DEGREE);
        let ny_start = |c: f64, d: f64| {
            if ny0 > 0 {
                ny0.max(2)
            } else {
                eta_start_degree(d - c, settings.tol)
            }
        };
        let eta_width = if settings.eta_panel_width.is_finite() && settings.eta_panel_width > 0.0 {
            settings.eta_panel_width
        } else {
            ETA_PANEL_WIDTH
        };
        let nx0 = settings.start_degree.clamp(4, 64);
        let nx_max = settings.max_degree.clamp(nx0, 256);
        let mut pending: Vec<Pending> = Vec::new();
        for &(a, b) in &pieces(x_lo, x_hi, width) {
            for &(c, d) in &pieces(y_lo, y_hi, eta_width) {
                pending.push(Pending::fresh(a, b, c, d, nx0, ny_start(c, d)));
            }
        }
        let mut done: Vec<Panel> = Vec::new();
        let mut table = NodeTable::default();
        while !pending.is_empty() {
            let wanted: Vec<(f64, f64, Option<f64>)> =
                pending.iter().flat_map(|q| q.grid()).collect();
            table.solve(problem, &wanted, tol)?;
            let mut next = Vec::new();
            let mut round = Round {
                done: &mut done,
                next: &mut next,
                pending: pending.len(),
                tol: settings.tol,
                nx0,
                nx_max,
                ny0,
            };
            for q in &pending {
                round.refine(q, &table)?;
            }
            pending = next;
        }
        let largest = |f: fn(&Panel) -> f64| done.iter().map(f).fold(0.0, f64::max);
        Ok(CoveredSurface {
            interpolation_estimate: largest(|p| p.estimate),
            node_estimate: table.largest_estimate,
            node_error_bound: largest(|p| p.node_bound),
            error_estimate: largest(|p| p.estimate + p.node_bound),
            solves: table.solves,
            node_tol: tol,
            warnings: table.warnings,
            panels: done,
        })
    }

    /// Number of panels.
    #[cfg(test)]
    pub fn panels(&self) -> usize {
        self.panels.len()
    }

    /// Each panel's rectangle [a, b] × [c, d] in (ln s, ln η) and degrees (n_x, n_y).
    #[cfg(test)]
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
