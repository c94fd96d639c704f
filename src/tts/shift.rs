//! Automatic horizontal shifting (docs/MATH.md §6): input the isotherms prepared in log–log
//! ([`Prepared`]: x = log10 f, one or more channels y = log10 E′, log10 E″ or log10 tan δ, each with
//! a clamped cubic spline), output log10 a_T of each isotherm relative to a reference isotherm.
//!
//! 1. **Pairwise.** For each pair of neighbours (a colder, b warmer) the relative shift
//!    d = s_b − s_a minimises the mean squared mismatch of their overlapping parts: every point of a
//!    that falls inside b's shifted range is compared with b's spline and vice versa,
//!    r = y_a(x_p) − S_b(x_p − d) and r = y_b(x_q) − S_a(x_q + d), over all channels. A grid scan of
//!    every d that leaves at least `min_overlap_points` points overlapping (so barely overlapping
//!    isotherms are still tried everywhere, and a noisy E″ cannot trap a local search), then a
//!    golden-section refinement. Chained from the coldest isotherm.
//! 2. **Global.** All shifts at once: Levenberg–Marquardt least squares on the same residuals over
//!    all pairs up to `pair_reach` apart in temperature (next-neighbours tie down a pair that barely
//!    overlaps), with the overlap sets frozen within an outer iteration and recomputed between them.
//!    The reference isotherm's shift is fixed at 0. Standard errors from the sandwich covariance
//!    (docs/MATH.md eq. 6.2: each point's noise carried through every residual it enters).

use super::interp::Spline;
use nalgebra::{DMatrix, DVector};

/// One isotherm ready for shifting.
#[derive(Debug, Clone)]
pub(crate) struct Prepared {
    /// log10 f, strictly increasing.
    pub x: Vec<f64>,
    /// The compared quantities, each with its values at `x` and its spline.
    pub channels: Vec<(Vec<f64>, Spline)>,
    /// Weight of each channel in this isotherm's pairs (empty: all 1). A pair weighs channel c by
    /// √(w_a,c · w_b,c), the same whichever isotherm a point comes from.
    pub weights: Vec<f64>,
}

impl Prepared {
    /// Build from log10 f (strictly increasing) and channel values.
    pub(crate) fn new(x: Vec<f64>, channels: Vec<Vec<f64>>) -> Prepared {
        let channels = channels
            .into_iter()
            .map(|y| {
                let s = Spline::new(&x, &y);
                (y, s)
            })
            .collect();
        Prepared {
            x,
            channels,
            weights: Vec::new(),
        }
    }

    /// The same isotherm with channel weights (see [`Prepared::weights`]).
    pub(crate) fn with_weights(mut self, weights: Vec<f64>) -> Prepared {
        self.weights = weights;
        self
    }

    /// Median |d y/d log10 f| of channel `c` over this isotherm's points (its spline's slope).
    pub(crate) fn median_abs_slope(&self, c: usize) -> f64 {
        let mut s: Vec<f64> = self
            .x
            .iter()
            .map(|&x| self.channels[c].1.eval(x).1.abs())
            .filter(|v| v.is_finite())
            .collect();
        if s.is_empty() {
            return 0.0;
        }
        s.sort_by(f64::total_cmp);
        s[s.len() / 2]
    }

    /// Slope of the least-squares line through channel `c` against x (0 for one point).
    fn line_slope(&self, c: usize) -> f64 {
        let y = &self.channels[c].0;
        let n = self.x.len() as f64;
        let (mx, my) = (self.x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
        let (mut sxy, mut sxx) = (0.0, 0.0);
        for (x, y) in self.x.iter().zip(y) {
            sxy += (x - mx) * (y - my);
            sxx += (x - mx) * (x - mx);
        }
        if sxx > 0.0 {
            sxy / sxx
        } else {
            0.0
        }
    }

    fn x_min(&self) -> f64 {
        self.x[0]
    }

    fn x_max(&self) -> f64 {
        self.x[self.x.len() - 1]
    }
}

/// A point of one isotherm that overlaps the other of a pair.
#[derive(Debug, Clone, Copy)]
pub(crate) struct OverlapPoint {
    /// The point belongs to the colder isotherm a (else to b).
    pub from_a: bool,
    /// Its index.
    pub point: usize,
}

/// The points of a and b that overlap the other's range when b is shifted by d = s_b − s_a
/// relative to a.
pub(crate) fn overlap_points(a: &Prepared, b: &Prepared, d: f64) -> Vec<OverlapPoint> {
    let mut out = Vec::new();
    let tol = 1e-12;
    for (p, &x) in a.x.iter().enumerate() {
        let t = x - d;
        if t >= b.x_min() - tol && t <= b.x_max() + tol {
            out.push(OverlapPoint {
                from_a: true,
                point: p,
            });
        }
    }
    for (q, &x) in b.x.iter().enumerate() {
        let t = x + d;
        if t >= a.x_min() - tol && t <= a.x_max() + tol {
            out.push(OverlapPoint {
                from_a: false,
                point: q,
            });
        }
    }
    out
}

/// Residual of one overlapping point in one channel and its derivative with respect to d.
///
/// From a: r = y_a(x_p) − S_b(x_p − d), dr/dd = +S_b′; from b: r = y_b(x_q) − S_a(x_q + d),
/// dr/dd = −S_a′. With d = s_b − s_a: ∂r/∂s_b = dr/dd, ∂r/∂s_a = −dr/dd.
pub(crate) fn residual(
    a: &Prepared,
    b: &Prepared,
    d: f64,
    op: OverlapPoint,
    channel: usize,
) -> (f64, f64) {
    let (r, drdd) = if op.from_a {
        let (v, s) = b.channels[channel].1.eval(a.x[op.point] - d);
        (a.channels[channel].0[op.point] - v, s)
    } else {
        let (v, s) = a.channels[channel].1.eval(b.x[op.point] + d);
        (b.channels[channel].0[op.point] - v, -s)
    };
    if a.weights.is_empty() || b.weights.is_empty() {
        (r, drdd)
    } else {
        let w = (a.weights[channel] * b.weights[channel]).sqrt();
        (w * r, w * drdd)
    }
}

/// Mean squared mismatch of a pair at d and the number of overlapping points; `None` when fewer
/// than `min_points` overlap.
fn pair_cost(a: &Prepared, b: &Prepared, d: f64, min_points: usize) -> Option<(f64, usize)> {
    let ops = overlap_points(a, b, d);
    if ops.len() < min_points {
        return None;
    }
    let nch = a.channels.len();
    let mut sum = 0.0;
    for &op in &ops {
        for c in 0..nch {
            let (r, _) = residual(a, b, d, op, c);
            sum += r * r;
        }
    }
    Some((sum / (ops.len() * nch) as f64, ops.len()))
}

/// Whether the overlap of a pair at d = s_b − s_a determines d (docs/MATH.md §6.6): at least
/// `2·min_points` points overlap (an isotherm pushed against the end of the scan, where the data do
/// not overlap, keeps only about `min_points`), and the shift's standard error from the pair alone,
/// σ_d = √(s² / Σ g²) with s² = Σ r²/(m − 1) over its m weighted residuals and g each residual's
/// sensitivity to d taken from the least-squares line of the other isotherm's channel (not its
/// spline, whose slope on flat noisy data is the noise's), is at most `max_std` decades: a flat
/// channel (E′ below T_g) leaves Σ g² ≈ 0.
pub(crate) fn pair_determined(
    a: &Prepared,
    b: &Prepared,
    d: f64,
    min_points: usize,
    max_std: f64,
) -> bool {
    let ops = overlap_points(a, b, d);
    if ops.len() < 2 * min_points {
        return false;
    }
    let nch = a.channels.len();
    let (sa, sb): (Vec<f64>, Vec<f64>) =
        (0..nch).map(|c| (a.line_slope(c), b.line_slope(c))).unzip();
    let (mut rr, mut gg, mut m) = (0.0, 0.0, 0usize);
    for &op in &ops {
        for c in 0..nch {
            let (r, _) = residual(a, b, d, op, c);
            let w = if a.weights.is_empty() || b.weights.is_empty() {
                1.0
            } else {
                (a.weights[c] * b.weights[c]).sqrt()
            };
            // A point of a is compared with b's curve, and vice versa.
            let g = w * if op.from_a { sb[c] } else { sa[c] };
            rr += r * r;
            gg += g * g;
            m += 1;
        }
    }
    let std = (rr / (m.saturating_sub(1).max(1)) as f64 / gg).sqrt();
    std <= max_std
}

/// Result of the pairwise search for one neighbour pair.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PairShift {
    /// d = s_b − s_a (log10 units).
    pub d: f64,
    /// RMS mismatch at d (log10 units).
    pub rms: f64,
}

/// Pairwise search (step 1 of the module docs); `None` when no shift leaves `min_points`
/// overlapping.
pub(crate) fn pair_shift(
    a: &Prepared,
    b: &Prepared,
    grid_step: f64,
    min_points: usize,
) -> Option<PairShift> {
    let lo = a.x_min() - b.x_max();
    let hi = a.x_max() - b.x_min();
    let n = ((hi - lo) / grid_step).ceil().max(1.0) as usize;
    let mut best: Option<(f64, f64)> = None;
    for i in 0..=n {
        let d = lo + (hi - lo) * i as f64 / n as f64;
        if let Some((c, _)) = pair_cost(a, b, d, min_points) {
            if best.map_or(true, |(_, bc)| c < bc) {
                best = Some((d, c));
            }
        }
    }
    let (d0, c0) = best?;
    let h = (hi - lo) / n as f64;
    let f = |d: f64| pair_cost(a, b, d, min_points).map_or(f64::INFINITY, |(c, _)| c);
    let (d, c) = golden_min(f, d0 - h, d0 + h, 1e-10);
    let (d, c) = if c <= c0 { (d, c) } else { (d0, c0) };
    Some(PairShift { d, rms: c.sqrt() })
}

/// How well one channel superposes on its own: the RMS over neighbour pairs of that channel's
/// mismatch at its own best pairwise shift (log10 units); `None` if no pair overlaps.
pub(crate) fn channel_scatter(
    iso: &[Prepared],
    channel: usize,
    grid_step: f64,
    min_points: usize,
) -> Option<f64> {
    let single: Vec<Prepared> = iso
        .iter()
        .map(|p| Prepared::new(p.x.clone(), vec![p.channels[channel].0.clone()]))
        .collect();
    let rms: Vec<f64> = single
        .windows(2)
        .filter_map(|w| pair_shift(&w[0], &w[1], grid_step, min_points).map(|p| p.rms))
        .collect();
    (!rms.is_empty()).then(|| (rms.iter().map(|r| r * r).sum::<f64>() / rms.len() as f64).sqrt())
}

/// Golden-section minimisation of `f` on [lo, hi] down to a bracket of width `tol`.
pub(crate) fn golden_min(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64, tol: f64) -> (f64, f64) {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let mut x1 = hi - g * (hi - lo);
    let mut x2 = lo + g * (hi - lo);
    let (mut f1, mut f2) = (f(x1), f(x2));
    while hi - lo > tol {
        if f1 <= f2 {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = f(x1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = f(x2);
        }
    }
    if f1 <= f2 {
        (x1, f1)
    } else {
        (x2, f2)
    }
}

/// The global refinement's result.
#[derive(Debug, Clone)]
pub(crate) struct GlobalShifts {
    /// log10 a_T of each isotherm relative to the reference one.
    pub shifts: Vec<f64>,
    /// Standard error of each shift (0 for the reference).
    pub std_err: Vec<f64>,
    /// Covariance of the shifts (eq. 6.2), n×n, zero in the reference's row and column; empty
    /// when JᵀJ is singular.
    pub covariance: Vec<Vec<f64>>,
    /// Outer iterations used.
    pub iterations: usize,
}

type PairSet = Vec<(usize, usize, Vec<OverlapPoint>)>;

fn pair_sets(iso: &[Prepared], s: &[f64], reach: usize, min_points: usize) -> PairSet {
    let mut sets = Vec::new();
    for a in 0..iso.len() {
        for b in a + 1..iso.len().min(a + reach + 1) {
            let ops = overlap_points(&iso[a], &iso[b], s[b] - s[a]);
            if ops.len() >= min_points {
                sets.push((a, b, ops));
            }
        }
    }
    sets
}

fn cost(iso: &[Prepared], s: &[f64], sets: &PairSet) -> f64 {
    let nch = iso[0].channels.len();
    let mut sum = 0.0;
    for (a, b, ops) in sets {
        for &op in ops {
            for c in 0..nch {
                let (r, _) = residual(&iso[*a], &iso[*b], s[*b] - s[*a], op, c);
                sum += r * r;
            }
        }
    }
    sum
}

/// RMS mismatch of each isotherm's overlaps with the isotherms up to `reach` away (log10 units,
/// all channels), at shifts `s`; `None` where it overlaps nothing.
pub(crate) fn overlap_rms(
    iso: &[Prepared],
    s: &[f64],
    reach: usize,
    min_points: usize,
) -> Vec<Option<f64>> {
    let n = iso.len();
    let nch = iso[0].channels.len();
    let mut sum = vec![0.0; n];
    let mut cnt = vec![0usize; n];
    for (a, b, ops) in pair_sets(iso, s, reach, min_points) {
        let d = s[b] - s[a];
        for op in ops {
            for c in 0..nch {
                let (r, _) = residual(&iso[a], &iso[b], d, op, c);
                for k in [a, b] {
                    sum[k] += r * r;
                    cnt[k] += 1;
                }
            }
        }
    }
    (0..n)
        .map(|i| (cnt[i] > 0).then(|| (sum[i] / cnt[i] as f64).sqrt()))
        .collect()
}

/// Global least-squares refinement (step 2 of the module docs), starting from `start`, with the
/// shift of isotherm `reference` held at 0.
pub(crate) fn refine_global(
    iso: &[Prepared],
    start: &[f64],
    reference: usize,
    reach: usize,
    min_points: usize,
) -> GlobalShifts {
    let n = iso.len();
    let mut s: Vec<f64> = start.iter().map(|v| v - start[reference]).collect();
    // Parameter index of each isotherm (the reference has none).
    let param: Vec<Option<usize>> = (0..n)
        .map(|i| match i.cmp(&reference) {
            std::cmp::Ordering::Less => Some(i),
            std::cmp::Ordering::Equal => None,
            std::cmp::Ordering::Greater => Some(i - 1),
        })
        .collect();
    let np = n - 1;
    let mut iterations = 0;
    let mut jtj = DMatrix::<f64>::zeros(np, np);
    let mut sets = pair_sets(iso, &s, reach, min_points);
    for outer in 0..20 {
        iterations = outer + 1;
        sets = pair_sets(iso, &s, reach, min_points);
        let mut mu = 1e-3;
        for _inner in 0..30 {
            let jtr = normal_equations(iso, &s, &sets, &param, &mut jtj);
            let (accepted, step_max, stalled) =
                levenberg_marquardt_step(iso, &mut s, &sets, &param, &jtj, &jtr, &mut mu);
            // Converged: no step lowers the cost, the step is below 1e-12 decades, or the cost no
            // longer falls (relative 1e-15, rounding).
            if !accepted || step_max < 1e-12 || stalled {
                break;
            }
        }
        let new_sets = pair_sets(iso, &s, reach, min_points);
        let same = new_sets.len() == sets.len()
            && new_sets
                .iter()
                .zip(&sets)
                .all(|(x, y)| x.0 == y.0 && x.1 == y.1 && x.2.len() == y.2.len());
        // The inner loop converged on these sets; done when the shifts leave them unchanged.
        if same {
            break;
        }
    }
    normal_equations(iso, &s, &sets, &param, &mut jtj);
    let mut std_err = vec![0.0; n];
    let mut covariance = Vec::new();
    if let Some(inv) = jtj.clone().try_inverse() {
        let cov = &inv * point_noise_covariance(iso, &s, &sets, &param) * &inv;
        covariance = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| match (param[i], param[j]) {
                        (Some(pi), Some(pj)) => cov[(pi, pj)],
                        _ => 0.0,
                    })
                    .collect()
            })
            .collect();
        for i in 0..n {
            if let Some(pi) = param[i] {
                std_err[i] = cov[(pi, pi)].max(0.0).sqrt();
            }
        }
    }
    GlobalShifts {
        shifts: s,
        std_err,
        covariance,
        iterations,
    }
}

/// The middle of the shifts' sandwich covariance (docs/MATH.md §6.2, eq. 6.2): Σ_c σ_c² G_c G_cᵀ,
/// G_c = Jᵀ ∂r/∂y over the measured points y of channel c. Every point enters several residuals,
/// as a point compared with a neighbour's spline and through its own isotherm's spline where the
/// neighbours' points are compared with it, up to `reach` pairs each way; σ²(JᵀJ)⁻¹ counts those
/// residuals as independent and understated the shifts' error 2–4× on synthetic exports of known
/// law (tests/master_plateau.rs `shift_standard_errors_cover_the_truth`). The residuals are linear
/// in the points (a spline is linear in its values: ∂S/∂y_j = β_j, the spline through the unit
/// vector e_j); σ_c² is the points' variance that accounts for the residuals found,
/// σ_c² = Σ r² / Σ ‖∂r/∂y‖² over channel c's residuals, × m/(m − p) for the p shifts fitted.
fn point_noise_covariance(
    iso: &[Prepared],
    s: &[f64],
    sets: &PairSet,
    param: &[Option<usize>],
) -> DMatrix<f64> {
    let np = param.iter().flatten().count();
    let nch = iso[0].channels.len();
    // β_j of every isotherm: the spline through the unit vector e_j at its own abscissae.
    let basis: Vec<Vec<super::interp::Spline>> = iso
        .iter()
        .map(|p| {
            (0..p.x.len())
                .map(|j| {
                    let mut e = vec![0.0; p.x.len()];
                    e[j] = 1.0;
                    super::interp::Spline::new(&p.x, &e)
                })
                .collect()
        })
        .collect();
    // g[c][i][j]: Jᵀ ∂r/∂y for point j of isotherm i in channel c.
    let mut g: Vec<Vec<Vec<DVector<f64>>>> = (0..nch)
        .map(|_| {
            iso.iter()
                .map(|p| vec![DVector::zeros(np); p.x.len()])
                .collect()
        })
        .collect();
    let (mut rr, mut dd, mut m) = (vec![0.0; nch], vec![0.0; nch], 0usize);
    for (a, b, ops) in sets {
        let d = s[*b] - s[*a];
        for &op in ops {
            // the compared point (isotherm, index) and the spline's isotherm and abscissa
            let (own, other, t) = if op.from_a {
                ((*a, op.point), *b, iso[*a].x[op.point] - d)
            } else {
                ((*b, op.point), *a, iso[*b].x[op.point] + d)
            };
            for c in 0..nch {
                let (r, drdd) = residual(&iso[*a], &iso[*b], d, op, c);
                let w = if iso[*a].weights.is_empty() || iso[*b].weights.is_empty() {
                    1.0
                } else {
                    (iso[*a].weights[c] * iso[*b].weights[c]).sqrt()
                };
                let mut jrow = DVector::<f64>::zeros(np);
                if let Some(pa) = param[*a] {
                    jrow[pa] -= drdd;
                }
                if let Some(pb) = param[*b] {
                    jrow[pb] += drdd;
                }
                g[c][own.0][own.1] += w * &jrow;
                let mut norm2 = w * w;
                for (j, beta) in basis[other].iter().enumerate() {
                    let bj = w * beta.eval(t).0;
                    if bj != 0.0 {
                        g[c][other][j] -= bj * &jrow;
                        norm2 += bj * bj;
                    }
                }
                rr[c] += r * r;
                dd[c] += norm2;
                m += 1;
            }
        }
    }
    let dof = m as f64 / (m.saturating_sub(np).max(1)) as f64;
    let mut mid = DMatrix::<f64>::zeros(np, np);
    for c in 0..nch {
        if dd[c] <= 0.0 {
            continue;
        }
        let var = rr[c] / dd[c] * dof;
        for gi in g[c].iter().flatten() {
            mid += var * gi * gi.transpose();
        }
    }
    mid
}

/// The Gauss–Newton normal equations of the overlap residuals at shifts `s`: JᵀJ into `jtj`
/// (overwritten), Jᵀr returned. ∂r/∂s_b = dr/dd, ∂r/∂s_a = −dr/dd; the reference (no parameter)
/// has no row.
fn normal_equations(
    iso: &[Prepared],
    s: &[f64],
    sets: &PairSet,
    param: &[Option<usize>],
    jtj: &mut DMatrix<f64>,
) -> DVector<f64> {
    let nch = iso[0].channels.len();
    jtj.fill(0.0);
    let mut jtr = DVector::<f64>::zeros(jtj.nrows());
    for (a, b, ops) in sets {
        let d = s[*b] - s[*a];
        for &op in ops {
            for c in 0..nch {
                let (r, drdd) = residual(&iso[*a], &iso[*b], d, op, c);
                // ∂r/∂s_b = dr/dd, ∂r/∂s_a = −dr/dd.
                let entries = [(param[*a], -drdd), (param[*b], drdd)];
                for &(pi, gi) in &entries {
                    let Some(pi) = pi else { continue };
                    jtr[pi] += gi * r;
                    for &(pj, gj) in &entries {
                        if let Some(pj) = pj {
                            jtj[(pi, pj)] += gi * gj;
                        }
                    }
                }
            }
        }
    }
    jtr
}

/// One Levenberg–Marquardt step from `s` with damping `mu` (JᵀJ + μ diag(JᵀJ)): up to 12 tries,
/// the damping raised ×4 after a step that raises the cost (×10 when the matrix is not positive
/// definite) and lowered ÷3 after an accepted one, which replaces `s`. Returns whether a step was
/// accepted, its largest component and whether the cost stalled (fell by ≤ 1e-15 relative).
#[allow(clippy::too_many_arguments)]
fn levenberg_marquardt_step(
    iso: &[Prepared],
    s: &mut Vec<f64>,
    sets: &PairSet,
    param: &[Option<usize>],
    jtj: &DMatrix<f64>,
    jtr: &DVector<f64>,
    mu: &mut f64,
) -> (bool, f64, bool) {
    let (n, np) = (s.len(), jtj.nrows());
    let c0 = cost(iso, s, sets);
    for _try in 0..12 {
        let mut m = jtj.clone();
        for i in 0..np {
            m[(i, i)] += *mu * jtj[(i, i)].max(1e-12) + 1e-14;
        }
        let Some(chol) = m.cholesky() else {
            *mu *= 10.0;
            continue;
        };
        let delta = chol.solve(&(-jtr));
        let mut trial = s.clone();
        for i in 0..n {
            if let Some(pi) = param[i] {
                trial[i] += delta[pi];
            }
        }
        let c1 = cost(iso, &trial, sets);
        if c1 <= c0 {
            let step_max = delta.amax();
            let stalled = c0 - c1 <= 1e-15 * c0;
            *s = trial;
            *mu = (*mu / 3.0).max(1e-12);
            return (true, step_max, stalled);
        }
        *mu *= 4.0;
    }
    (false, 0.0, false)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn iso(shift: f64, xs: &[f64]) -> Prepared {
        // A smooth sigmoid master curve y(x_r), sampled at x_r = x + shift.
        let f = |x: f64| (1.0 + (1.5 * x).tanh()) + 0.1 * x;
        let g = |x: f64| 0.5 * (-(x * x) / 4.0).exp() - 1.0;
        Prepared::new(
            xs.to_vec(),
            vec![
                xs.iter().map(|&x| f(x + shift)).collect(),
                xs.iter().map(|&x| g(x + shift)).collect(),
            ],
        )
    }

    #[test]
    fn pair_finds_a_known_offset() {
        // Two samplings of the same smooth curve, offset by −0.73 decades: the pairwise search
        // must find d = −0.73 to the spline's interpolation error (dense grid: ~1e-6 or better).
        let xs: Vec<f64> = (0..31).map(|i| -1.0 + 0.1 * i as f64).collect();
        let a = iso(0.0, &xs);
        let b = iso(-0.73, &xs);
        let p = pair_shift(&a, &b, 0.01, 3).unwrap();
        assert!((p.d + 0.73).abs() < 1e-6, "{}", p.d);
    }

    #[test]
    fn global_recovers_shifts_of_barely_overlapping_chain() {
        // Five isotherms 2 decades wide, 1.8 decades apart (0.2 decade overlap, 3 points each
        // way): the global refinement recovers every shift to the interpolation error.
        let xs: Vec<f64> = (0..21).map(|i| -1.0 + 0.1 * i as f64).collect();
        let truth = [3.6, 1.8, 0.0, -1.8, -3.6];
        let isos: Vec<Prepared> = truth.iter().map(|&s| iso(s, &xs)).collect();
        let mut chain = vec![0.0];
        for i in 0..4 {
            let p = pair_shift(&isos[i], &isos[i + 1], 0.01, 3).unwrap();
            chain.push(chain[i] + p.d);
        }
        let g = refine_global(&isos, &chain, 2, 2, 3);
        for (s, t) in g.shifts.iter().zip(truth) {
            assert!((s - t).abs() < 1e-5, "{s} vs {t}");
        }
    }
}
