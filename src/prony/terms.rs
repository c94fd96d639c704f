//! Prony term control (docs/MATH.md §5): from a dense non-negative spectrum on the fixed grid to the fewest
//! terms, at free positions, that reach a target accuracy — and the trade table of terms against the
//! RMS log10 errors of E′ and E″ on the way.
//!
//! Input: master-curve points ([`MasterPoint`]), the relaxation-time grid of the dense fit, a
//! [`TermControl`]; output: the chosen [`RelaxationSpectrum`] and the [`TermTrade`] rows.
//!
//! # Method
//! The residuals are those of [`crate::prony::fit`] (relative to each datum, E″ rows × `loss_weight`),
//! with the relaxation times now unknowns too, as u_j = ln ρ_j:
//!
//! ```text
//!   r′_k = (x₀ + Σ_j x_j K′(ω_k e^{u_j})) S/E′_k − 1,   K′(z) = z²/(1+z²),  z dK′/dz = 2z²/(1+z²)²
//!   r″_k = (     Σ_j x_j K″(ω_k e^{u_j})) S/E″_k − 1,   K″(z) = z/(1+z²),   z dK″/dz = z(1−z²)/(1+z²)²
//! ```
//!
//! 1. **Start**: the non-negative least-squares solution (λ = 0) on the dense grid. Unregularised
//!    NNLS is sparse by itself (an active bound wherever a term does not pay), so it is the densest
//!    spectrum worth reducing.
//! 2. **Positions**: for the terms kept, minimise ‖r‖² over u with the weights eliminated (variable
//!    projection: x(u) = NNLS(A(u), b), so x ≥ 0 always), by Levenberg–Marquardt on u with the
//!    Jacobian J_kj = x_j ∂A_kj/∂u_j at fixed x (Kaufman's simplification of the variable-projection
//!    Jacobian). Steps are capped at one decade and positions kept inside the grid's window.
//! 3. **Prune**: remove the term whose removal (weights re-solved) raises ‖r‖² least, re-optimise the
//!    positions, record the errors; repeat down to one term. Each row of the trade table is a local
//!    optimum for its count.
//! 4. **Choose** the fewest terms whose RMS log10 errors meet the target (and at most `max_terms`).
//! 5. **Second start** for the chosen count: as many times log-spaced over the window, positions
//!    optimised; the better of the two (greedy paths end in local optima).
//!
//! Measured on the shipped compounds (default settings, target = the dense fit's own errors):
//! EMS-CA 65 → 28 terms (RMS log10 E′ 0.0317 → 0.0312, E″ 0.0921 → 0.0912), TRIOS 32 → 19
//! (0.0071 → 0.0069, 0.0156 → 0.0145); DMA-suite: no count below its 55 meets both figures to the
//! last digit (33 terms are 0.5 % worse in E″), so its dense fit is kept.
//!
//! NNLS is Lawson & Hanson's active-set algorithm (1974, ch. 23), on the thin-QR reduced problem
//! ‖R x − Qᵀb‖ (A = QR), which has the conditioning of A, not of AᵀA.
//!
//! # References
//! * Lawson, C. L. & Hanson, R. J. (1974), Solving Least Squares Problems, Prentice-Hall, ch. 23.
//! * Golub, G. H. & Pereyra, V. (1973), The differentiation of pseudo-inverses and nonlinear least
//!   squares problems whose variables separate, SIAM J. Numer. Anal. 10, 413–432; Kaufman, L. (1975),
//!   A variable projection method for solving separable nonlinear least squares problems, BIT 15, 49–57.

use super::kernel::{loss_kernel, storage_kernel};
use super::points::{log10_errors, Log10Errors, MasterPoint};
use super::{PronyError, RelaxationSpectrum, RelaxationTerm};
use crate::material::ModulusKind;
use nalgebra::{DMatrix, DVector};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// What the term reduction aims for (fields of [`crate::prony::PronySettings`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TermControl {
    /// Keep at most this many relaxation terms (E∞ not counted).
    pub max_terms: Option<usize>,
    /// Target RMS log10 error of E′.
    pub target_storage: f64,
    /// Target RMS log10 error of E″.
    pub target_loss: f64,
    /// Minimise log residuals c ln(fit/datum) instead of the relative residuals c (fit/datum − 1)
    /// of the dense fit.
    pub log_residuals: bool,
    /// Stop once a count within the cap has met the target and a smaller one misses it by
    /// `STOP_FACTOR` (false: the whole trade down to one term).
    pub stop_early: bool,
}

/// One row of the trade table: the best spectrum found with `n_terms` terms and its errors.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TermTrade {
    /// Relaxation terms (E∞ not counted).
    pub n_terms: usize,
    /// RMS log10(E′_fit/E′_data).
    pub rms_log10_storage: f64,
    /// RMS log10(E″_fit/E″_data).
    pub rms_log10_loss: f64,
    /// Largest |log10(E′_fit/E′_data)|.
    pub max_abs_log10_storage: f64,
    /// Largest |log10(E″_fit/E″_data)|.
    pub max_abs_log10_loss: f64,
}

/// The result of [`reduce_terms`].
#[derive(Debug, Clone, PartialEq)]
pub struct Reduced {
    /// The chosen spectrum.
    pub spectrum: RelaxationSpectrum,
    /// Every count tried, from the most terms to one.
    pub trade: Vec<TermTrade>,
    /// Whether the chosen spectrum meets both targets.
    pub target_met: bool,
}

/// Levenberg–Marquardt iterations per term count (each one NNLS solve of n+1 unknowns; the decrease
/// of ‖r‖² has levelled off long before this on the shipped compounds).
const LM_MAX_ITER: usize = 20;
/// Positions are optimised only from this many terms down (the trade table's interesting rows).
const LM_MAX_TERMS: usize = 40;
/// With [`TermControl::stop_early`], the reduction stops once a count misses the target by this
/// factor in either modulus (fewer terms only do worse: each count's optimum is at least as bad as
/// the next larger count's, up to the local optima of the greedy path).
const STOP_FACTOR: f64 = 2.0;
/// Gauss–Newton steps of the log-residual weights per position set, and their stopping gain.
const GN_MAX_ITER: usize = 8;
const GN_REL_TOL: f64 = 1e-6;
/// Stop LM when a step lowers ‖r‖² by less than this fraction.
const LM_REL_TOL: f64 = 1e-7;

/// Reduce to the fewest terms that meet `control` (module docs). `grid_s` is the dense fit's grid
/// (its ends bound the positions), `scale` the modulus scale S of the fit.
#[allow(clippy::too_many_arguments)]
pub fn reduce_terms(
    points: &[MasterPoint],
    grid_s: &[f64],
    scale: f64,
    loss_weight: f64,
    kind: ModulusKind,
    poisson: f64,
    control: &TermControl,
) -> Result<Reduced, PronyError> {
    let prob = Separable::new(points, scale, loss_weight, grid_s, control.log_residuals);
    // 1. NNLS on the grid.
    let mut u: Vec<f64> = grid_s.iter().map(|t| t.ln()).collect();
    let mut x = prob.weights(&u, None);
    keep_positive(&mut u, &mut x);
    let mut trade = Vec::new();
    let mut states: Vec<(Vec<f64>, Vec<f64>)> = Vec::new();
    let mut met_once = false;
    loop {
        // 2. Positions (above LM_MAX_TERMS the removals cost almost nothing and LM would be slow).
        if u.len() <= LM_MAX_TERMS {
            prob.optimise_positions(&mut u, &mut x);
        }
        keep_positive(&mut u, &mut x);
        let spectrum = prob.spectrum(&u, &x, kind, poisson);
        let e = log10_errors(points, &spectrum);
        let n = u.len();
        // Counts strictly fall (each pass removes at least one term), so each row is new.
        trade.push(TermTrade::of(n, &e));
        states.push((u.clone(), x.clone()));
        let row = trade[trade.len() - 1];
        let far_off = row.rms_log10_storage > STOP_FACTOR * control.target_storage
            || row.rms_log10_loss > STOP_FACTOR * control.target_loss;
        met_once |= !far_off && control.meets(&row) && n <= control.max_terms.unwrap_or(n);
        if n <= 1 || (control.stop_early && far_off && met_once) {
            break;
        }
        // 3. Prune the term whose removal costs least.
        // A NaN cost (never seen; a degenerate column) ends the reduction rather than the program.
        let Some((j, xj)) = cheapest_removal(&prob, &u, &x) else {
            break;
        };
        u.remove(j);
        x = prob.weights(&u, Some(&xj));
        keep_positive(&mut u, &mut x);
        if u.is_empty() {
            break;
        }
    }
    // 4. Choose.
    let Some((i, target_met)) = choose(&trade, control) else {
        return Err(PronyError::Solver(
            "term reduction found no spectrum (no term survived the NNLS start)".into(),
        ));
    };
    let (mut u, mut x) = states[i].clone();
    // 5. A second start for the chosen count.
    if let Some((u2, x2)) = second_start(&prob, &u, &x) {
        let e2 = log10_errors(points, &prob.spectrum(&u2, &x2, kind, poisson));
        if !target_met || control.meets_errors(&e2) {
            u = u2;
            x = x2;
        }
    }
    let spectrum = prob.spectrum(&u, &x, kind, poisson);
    let e = log10_errors(points, &spectrum);
    trade[i] = TermTrade::of(u.len(), &e);
    let target_met = target_met && control.meets_errors(&e);
    Ok(Reduced {
        spectrum,
        trade,
        target_met,
    })
}

impl TermTrade {
    /// The row of `n_terms` terms with the errors `e`.
    fn of(n_terms: usize, e: &Log10Errors) -> Self {
        TermTrade {
            n_terms,
            rms_log10_storage: e.rms_storage,
            rms_log10_loss: e.rms_loss,
            max_abs_log10_storage: e.max_storage,
            max_abs_log10_loss: e.max_loss,
        }
    }
}

impl TermControl {
    /// Whether a trade row meets both RMS targets.
    fn meets(&self, t: &TermTrade) -> bool {
        t.rms_log10_storage <= self.target_storage && t.rms_log10_loss <= self.target_loss
    }
    /// Whether errors meet both RMS targets.
    fn meets_errors(&self, e: &Log10Errors) -> bool {
        e.rms_storage <= self.target_storage && e.rms_loss <= self.target_loss
    }
}

/// Step 3: the term whose removal costs least and the warm-start weights without it, ranked on the
/// problem linearised at the current fit. ‖M x − t‖² = ‖R x − Qᵀt‖² + ‖(I − QQᵀ) t‖² with M = QR,
/// so each candidate is an NNLS on R without column j (n+1 rows, not 2m), warm-started from the
/// current set. None when no candidate has a finite cost.
fn cheapest_removal(prob: &Separable, u: &[f64], x: &[f64]) -> Option<(usize, Vec<f64>)> {
    let n = u.len();
    let (ms, t) = prob.linearised(&prob.design(u), Some(x));
    let qr = ms.qr();
    let (r, qtt) = (qr.r(), qr.q().transpose() * &t);
    let mut best: Option<(f64, usize, Vec<f64>)> = None;
    for j in 0..n {
        let cols: Vec<usize> = (0..=n).filter(|&c| c != j + 1).collect();
        let rj = r.select_columns(cols.iter());
        let passive: Vec<bool> = cols.iter().map(|&c| x[c] > 0.0).collect();
        let xj = nnls(&rj, &qtt, Some(&passive));
        let cost = (&rj * DVector::from_column_slice(&xj) - &qtt).norm_squared();
        if cost.is_finite() && best.as_ref().map_or(true, |b| cost < b.0) {
            best = Some((cost, j, xj));
        }
    }
    best.map(|(_, j, xj)| (j, xj))
}

/// Step 4: the row to keep and whether it meets the targets — the fewest terms within the cap that
/// meet both, or else the most terms allowed (the best this count gives). None when no row is within
/// the cap.
fn choose(trade: &[TermTrade], control: &TermControl) -> Option<(usize, bool)> {
    let cap = control.max_terms.unwrap_or(usize::MAX);
    trade
        .iter()
        .enumerate()
        .filter(|(_, t)| t.n_terms <= cap && control.meets(t))
        .min_by_key(|(_, t)| t.n_terms)
        .map(|(i, _)| (i, true))
        .or_else(|| {
            // Not reachable within the cap: the most terms allowed (the best this count gives).
            trade
                .iter()
                .enumerate()
                .filter(|(_, t)| t.n_terms <= cap)
                .max_by_key(|(_, t)| t.n_terms)
                .map(|(i, _)| (i, false))
        })
}

/// Step 5: a second start for the chosen count — the same number of times log-spaced over the
/// window, positions optimised. The greedy path is one local optimum; this start is returned when it
/// keeps the count and costs less than (u, x).
fn second_start(prob: &Separable, u: &[f64], x: &[f64]) -> Option<(Vec<f64>, Vec<f64>)> {
    let n = u.len();
    if !(1..=LM_MAX_TERMS).contains(&n) {
        return None;
    }
    let mut u2: Vec<f64> = (0..n)
        .map(|j| prob.u_lo + (prob.u_hi - prob.u_lo) * (j as f64 + 0.5) / n as f64)
        .collect();
    let mut x2 = prob.weights(&u2, None);
    keep_positive(&mut u2, &mut x2);
    prob.optimise_positions(&mut u2, &mut x2);
    keep_positive(&mut u2, &mut x2);
    (!u2.is_empty() && u2.len() == n && prob.cost(&u2, &x2) < prob.cost(u, x)).then_some((u2, x2))
}

/// Drop the terms whose weight came out zero (x[0] is E∞ and stays).
fn keep_positive(u: &mut Vec<f64>, x: &mut Vec<f64>) {
    let mut k = 0;
    let mut xs = vec![x[0]];
    u.retain(|_| {
        k += 1;
        let keep = x[k] > 0.0;
        if keep {
            xs.push(x[k]);
        }
        keep
    });
    *x = xs;
}

/// Model/datum ratios below this are floored before the logarithm (a term-less region of E″ would
/// otherwise give ln 0; 1e-6 is six decades off, far beyond any fit worth reporting).
const RATIO_FLOOR: f64 = 1e-6;

/// The separable least-squares problem of the module docs, in log residuals.
struct Separable {
    /// ω_k in rad/s.
    omega: Vec<f64>,
    /// S/E′_k.
    s1: Vec<f64>,
    /// S/E″_k.
    s2: Vec<f64>,
    /// Row weights c: the points' weights, times loss_weight on the E″ rows.
    c: DVector<f64>,
    /// Modulus scale S in Pa.
    scale: f64,
    /// Bounds of u = ln ρ (the grid's ends).
    u_lo: f64,
    u_hi: f64,
    /// Log residuals c ln q (true) or relative residuals c (q − 1) (false).
    log: bool,
}

impl Separable {
    fn new(
        points: &[MasterPoint],
        scale: f64,
        loss_weight: f64,
        grid_s: &[f64],
        log: bool,
    ) -> Self {
        let m = points.len();
        // The fit's row weights (eq. 5.1) times `loss_weight` on the E″ rows.
        let mut c = DVector::from_element(2 * m, 1.0);
        for (k, p) in points.iter().enumerate() {
            c[k] = p.weight[0];
            c[m + k] = loss_weight * p.weight[1];
        }
        let (lo, hi) = grid_s
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), t| {
                (a.min(t.ln()), b.max(t.ln()))
            });
        Self {
            omega: points
                .iter()
                .map(|p| 2.0 * PI * p.reduced_freq_hz)
                .collect(),
            s1: points.iter().map(|p| scale / p.storage_pa).collect(),
            s2: points.iter().map(|p| scale / p.loss_pa).collect(),
            c,
            scale,
            u_lo: lo,
            u_hi: hi,
            log,
        }
    }

    /// A(u): 2m × (n+1) model/datum ratios per unit x, column 0 the E∞ column (q = A x).
    fn design(&self, u: &[f64]) -> DMatrix<f64> {
        let m = self.omega.len();
        let mut a = DMatrix::zeros(2 * m, u.len() + 1);
        for k in 0..m {
            a[(k, 0)] = self.s1[k];
            for (j, &uj) in u.iter().enumerate() {
                let z = self.omega[k] * uj.exp();
                a[(k, j + 1)] = storage_kernel(z) * self.s1[k];
                a[(m + k, j + 1)] = loss_kernel(z) * self.s2[k];
            }
        }
        a
    }

    /// Weighted residuals c_k ln q_k (log) or c_k (q_k − 1) (relative).
    fn residuals(&self, a: &DMatrix<f64>, x: &[f64]) -> DVector<f64> {
        let q = a * DVector::from_column_slice(x);
        if self.log {
            q.zip_map(&self.c, |qk, ck| ck * qk.max(RATIO_FLOOR).ln())
        } else {
            q.zip_map(&self.c, |qk, ck| ck * (qk - 1.0))
        }
    }

    /// ‖c ln(A(u) x)‖².
    fn cost(&self, u: &[f64], x: &[f64]) -> f64 {
        self.residuals(&self.design(u), x).norm_squared()
    }

    /// The problem linearised at x₀ (ln q ≈ ln q₀ + (q − q₀)/q₀): rows c_k/q₀_k · A, target
    /// c_k (1 − ln q₀_k). Without x₀, q₀ = 1: the relative residuals of [`crate::prony::fit`].
    fn linearised(&self, a: &DMatrix<f64>, x0: Option<&[f64]>) -> (DMatrix<f64>, DVector<f64>) {
        let q0 = match x0 {
            Some(x) if self.log => (a * DVector::from_column_slice(x)).map(|q| q.max(RATIO_FLOOR)),
            _ => DVector::from_element(a.nrows(), 1.0),
        };
        let mut ms = a.clone();
        let mut t = DVector::zeros(a.nrows());
        for k in 0..a.nrows() {
            let f = self.c[k] / q0[k];
            ms.row_mut(k).scale_mut(f);
            t[k] = self.c[k] * (1.0 - q0[k].ln());
        }
        (ms, t)
    }

    /// ∂(c ln q)/∂u_j at fixed x, as the columns of J (2m × n).
    fn jacobian(&self, u: &[f64], x: &[f64], a: &DMatrix<f64>) -> DMatrix<f64> {
        let m = self.omega.len();
        let q = if self.log {
            a * DVector::from_column_slice(x)
        } else {
            DVector::from_element(a.nrows(), 1.0)
        };
        let mut jac = DMatrix::zeros(2 * m, u.len());
        for k in 0..m {
            let (f1, f2) = (
                self.c[k] * self.s1[k] / q[k].max(RATIO_FLOOR),
                self.c[m + k] * self.s2[k] / q[m + k].max(RATIO_FLOOR),
            );
            for (j, &uj) in u.iter().enumerate() {
                let z = self.omega[k] * uj.exp();
                let d = 1.0 + z * z;
                let dk1 = 2.0 * z * z / (d * d);
                let dk2 = z * (1.0 - z * z) / (d * d);
                jac[(k, j)] = x[j + 1] * dk1 * f1;
                jac[(m + k, j)] = x[j + 1] * dk2 * f2;
            }
        }
        jac
    }

    /// x(u) = argmin_{x ≥ 0} ‖c ln(A(u) x)‖² by Gauss–Newton on the linearisation, each step an
    /// NNLS, halved back towards the previous x (a convex combination stays ≥ 0) until the log cost
    /// falls. `start`: a non-negative x to linearise at first (else the relative-residual fit).
    fn weights(&self, u: &[f64], start: Option<&[f64]>) -> Vec<f64> {
        let a = self.design(u);
        let mut x: Vec<f64> = match start {
            Some(x0) if x0.iter().any(|&v| v > 0.0) => x0.to_vec(),
            _ => {
                let (ms, t) = self.linearised(&a, None);
                solve_nnls(&ms, &t, None)
            }
        };
        let mut cost = self.residuals(&a, &x).norm_squared();
        // Relative residuals are linear in x: one NNLS is the answer.
        let iterations = if self.log { GN_MAX_ITER } else { 1 };
        for _ in 0..iterations {
            let (ms, t) = self.linearised(&a, Some(&x));
            let passive: Vec<bool> = x.iter().map(|&v| v > 0.0).collect();
            let xn = solve_nnls(&ms, &t, Some(&passive));
            let mut step = 1.0;
            let mut accepted = None;
            for _ in 0..6 {
                let xt: Vec<f64> = x
                    .iter()
                    .zip(&xn)
                    .map(|(&o, &n)| o + step * (n - o))
                    .collect();
                let ct = self.residuals(&a, &xt).norm_squared();
                if ct < cost {
                    accepted = Some((xt, ct));
                    break;
                }
                step *= 0.5;
            }
            let Some((xt, ct)) = accepted else { break };
            let gain = (cost - ct) / cost.max(f64::MIN_POSITIVE);
            x = xt;
            cost = ct;
            if gain < GN_REL_TOL {
                break;
            }
        }
        x
    }

    /// Levenberg–Marquardt on u with x = x(u) (module docs, step 2).
    fn optimise_positions(&self, u: &mut Vec<f64>, x: &mut Vec<f64>) {
        let n = u.len();
        if n == 0 {
            return;
        }
        let mut cost = self.cost(u, x);
        let mut mu = 1e-3;
        let max_step = 10f64.ln();
        for _ in 0..LM_MAX_ITER {
            let a = self.design(u);
            let r = self.residuals(&a, x);
            let jac = self.jacobian(u, x, &a);
            let jtj = jac.transpose() * &jac;
            let g = jac.transpose() * &r;
            let mut improved = false;
            for _ in 0..10 {
                let mut h = jtj.clone();
                for i in 0..n {
                    h[(i, i)] += mu * jtj[(i, i)].max(1e-12);
                }
                let Some(ch) = h.cholesky() else {
                    mu *= 10.0;
                    continue;
                };
                let step = ch.solve(&(-&g));
                let un: Vec<f64> = u
                    .iter()
                    .zip(step.iter())
                    .map(|(ui, s)| (ui + s.clamp(-max_step, max_step)).clamp(self.u_lo, self.u_hi))
                    .collect();
                let xn = self.weights(&un, Some(x));
                let cn = self.cost(&un, &xn);
                if cn < cost {
                    let gain = (cost - cn) / cost.max(f64::MIN_POSITIVE);
                    *u = un;
                    *x = xn;
                    cost = cn;
                    mu = (mu / 3.0).max(1e-12);
                    improved = gain > LM_REL_TOL;
                    break;
                }
                mu *= 4.0;
            }
            if !improved {
                break;
            }
        }
    }

    fn spectrum(
        &self,
        u: &[f64],
        x: &[f64],
        kind: ModulusKind,
        poisson: f64,
    ) -> RelaxationSpectrum {
        let mut terms: Vec<RelaxationTerm> = u
            .iter()
            .zip(&x[1..])
            .map(|(&uj, &xj)| RelaxationTerm {
                modulus_pa: xj * self.scale,
                tau_s: uj.exp(),
            })
            .collect();
        terms.sort_by(|a, b| a.tau_s.total_cmp(&b.tau_s));
        RelaxationSpectrum {
            kind,
            poisson,
            modulus_inf_pa: x[0] * self.scale,
            terms,
        }
    }
}

/// argmin_{x ≥ 0} ‖M x − t‖ through the thin QR of M (NNLS on ‖R x − Qᵀt‖).
fn solve_nnls(m: &DMatrix<f64>, t: &DVector<f64>, passive: Option<&[bool]>) -> Vec<f64> {
    let qr = m.clone().qr();
    let qtt = qr.q().transpose() * t;
    nnls(&qr.r(), &qtt, passive)
}

/// Lawson–Hanson NNLS: argmin_{x ≥ 0} ‖R x − c‖ for a small R, optionally starting from a
/// passive (free) set, e.g. the previous solution's.
fn nnls(r: &DMatrix<f64>, c: &DVector<f64>, start: Option<&[bool]>) -> Vec<f64> {
    let n = r.ncols();
    let mut x = DVector::<f64>::zeros(n);
    let mut passive = start.map_or_else(|| vec![false; n], <[bool]>::to_vec);
    let tol = 1e-12 * r.norm().max(1.0) * c.norm().max(1.0);
    // Warm start: solve on the given free set, dropping the non-positive components until the
    // unconstrained solution on what is left is positive (a feasible point to start from).
    for _ in 0..n {
        let idx: Vec<usize> = (0..n).filter(|&j| passive[j]).collect();
        if idx.is_empty() {
            break;
        }
        let z_p = least_squares(&r.select_columns(idx.iter()), c);
        if z_p.iter().all(|&v| v > 0.0) {
            for (k, &j) in idx.iter().enumerate() {
                x[j] = z_p[k];
            }
            break;
        }
        for (k, &j) in idx.iter().enumerate() {
            if z_p[k] <= 0.0 {
                passive[j] = false;
            }
        }
    }
    for _outer in 0..3 * n + 10 {
        let w = r.transpose() * (c - r * &x);
        let cand = (0..n)
            .filter(|&j| !passive[j] && w[j] > tol)
            .max_by(|&a, &b| w[a].total_cmp(&w[b]));
        let Some(jmax) = cand else { break };
        passive[jmax] = true;
        for _inner in 0..3 * n + 10 {
            let idx: Vec<usize> = (0..n).filter(|&j| passive[j]).collect();
            if idx.is_empty() {
                break;
            }
            let z_p = least_squares(&r.select_columns(idx.iter()), c);
            if z_p.iter().all(|&v| v > 0.0) {
                x.fill(0.0);
                for (k, &j) in idx.iter().enumerate() {
                    x[j] = z_p[k];
                }
                break;
            }
            // Step from x towards z as far as feasibility allows; the blocking terms leave P.
            let mut alpha = 1.0f64;
            for (k, &j) in idx.iter().enumerate() {
                if z_p[k] <= 0.0 {
                    let d = x[j] - z_p[k];
                    if d > 0.0 {
                        alpha = alpha.min(x[j] / d);
                    }
                }
            }
            let mut left = false;
            for (k, &j) in idx.iter().enumerate() {
                x[j] += alpha * (z_p[k] - x[j]);
                if x[j] <= 0.0 || (z_p[k] <= 0.0 && x[j] <= 1e-300) {
                    x[j] = 0.0;
                    passive[j] = false;
                    left = true;
                }
            }
            // Guarantee progress: at least the most negative component leaves.
            if !left {
                let (kmin, _) = z_p
                    .iter()
                    .enumerate()
                    .min_by(|a, b| a.1.total_cmp(b.1))
                    .expect("non-empty");
                passive[idx[kmin]] = false;
                x[idx[kmin]] = 0.0;
            }
        }
    }
    x.iter().map(|v| v.max(0.0)).collect()
}

/// Least squares min ‖M z − c‖ by QR (M has full column rank in practice; a rank-deficient M gets
/// the SVD's minimum-norm answer).
fn least_squares(m: &DMatrix<f64>, c: &DVector<f64>) -> DVector<f64> {
    let qr = m.clone().qr();
    let qtc = qr.q().transpose() * c;
    let r = qr.r();
    let small = (0..r.ncols().min(r.nrows())).any(|i| r[(i, i)].abs() < 1e-13 * r.norm());
    if !small {
        if let Some(z) = r.solve_upper_triangular(&qtc) {
            return z;
        }
    }
    m.clone()
        .svd(true, true)
        .solve(c, 1e-13)
        .unwrap_or_else(|_| DVector::zeros(m.ncols()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// NNLS against a case solved by hand: R = I, c = (1, −2, 3) → x = (1, 0, 3).
    #[test]
    fn nnls_clips_the_negative_component() {
        let r = DMatrix::<f64>::identity(3, 3);
        let c = DVector::from_column_slice(&[1.0, -2.0, 3.0]);
        let x = nnls(&r, &c, None);
        // QR round-off: a few ulps.
        for (a, b) in x.iter().zip([1.0, 0.0, 3.0]) {
            assert!((a - b).abs() < 1e-14, "{x:?}");
        }
    }

    /// Exact data from three Maxwell elements off the grid: the reduction must find three terms and
    /// put them back at the true times (to 1e-4 in ln ρ: LM converges quadratically on a zero-residual
    /// problem, so only the stopping rule limits it).
    #[test]
    fn three_exact_terms_are_recovered_off_grid() {
        let truth = RelaxationSpectrum {
            kind: ModulusKind::Tensile,
            poisson: 0.5,
            modulus_inf_pa: 1e6,
            terms: vec![
                RelaxationTerm {
                    modulus_pa: 3e8,
                    tau_s: 2.7e-6,
                },
                RelaxationTerm {
                    modulus_pa: 5e7,
                    tau_s: 3.3e-3,
                },
                RelaxationTerm {
                    modulus_pa: 1e7,
                    tau_s: 0.71,
                },
            ],
        };
        let pts = crate::prony::synthetic::master_points(&truth, 1e-3, 1e7, 10.0, 0.0, 1);
        let grid = crate::prony::relaxation_times_s(1e-3, 1e7, &Default::default());
        let control = TermControl {
            max_terms: None,
            target_storage: 1e-5,
            target_loss: 1e-5,
            log_residuals: false,
            stop_early: false,
        };
        let red = reduce_terms(&pts, &grid, 3e8, 1.0, ModulusKind::Tensile, 0.5, &control).unwrap();
        assert!(red.target_met, "{:?}", red.trade);
        assert_eq!(red.spectrum.terms.len(), 3, "{:?}", red.trade);
        for (a, b) in red.spectrum.terms.iter().zip(&truth.terms) {
            assert!((a.tau_s / b.tau_s).ln().abs() < 1e-4, "{a:?} vs {b:?}");
            assert!(
                (a.modulus_pa / b.modulus_pa - 1.0).abs() < 1e-4,
                "{a:?} vs {b:?}"
            );
        }
    }
}
