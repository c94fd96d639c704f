//! The gap between the roll and the surface outside the contact, accurately: behind the rear edge
//! (where the surface is still depressed and, when β < 0, the roll is still descending) and ahead of
//! the front edge.
//!
//! Input: the reduced problem of the `auto` scheme ([`Modes`], lumping scale s) and its
//! [`LambdaSolution`]; output: the gap g(ξ) over the depth scale λ²/8 at chosen points
//! ([`GapEvaluator::gap_ratio`]) and a scan of the whole region behind the contact ([`rear_scan`]).
//!
//! # Math (docs/MATH.md §11)
//! Off the contact the surface displacement is still eq. 3.19 with v(0) = 0,
//! ρv(ξ) = s∫₀^λ Q′(ξ′)[K̂(−ξ′) − K̂(ξ−ξ′)]dξ′, K̂(x) = ln|x| + Σᵢ (f̂ᵢ/bᵢ)h(bᵢx) (docs/MATH.md §2; with
//! fast modes lumped Q′K = Q′·sK̂, module [`crate::contact::numerics::reduction`]), and the roll sits at depth ξβ − ξ²/2
//! (eq. 3.22), so g(ξ) = ρv(ξ) − (ξβ − ξ²/2) must be ≥ 0. The two parts of K̂ are integrated apart:
//!
//! - **Elastic part, in closed form.** With ξ′ = L(1+s), L = λ/2, Q′ = √(1−s²)ΣFₙU_{n−1}(s) and, for
//!   |t| ≥ 1 (t = ξ/L − 1), t = (z + 1/z)/2, |z| ≥ 1, ζ = 1/z:
//!   ln|t−s| = ln(|z|/2) − 2Σₖ ζᵏTₖ(s)/k (generating function of Tₖ), and
//!   ∫√(1−s²)U_{n−1}Tₖ ds = (π/4)(δ_{k,n−1} − δ_{k,n+1}), ∫√(1−s²)U_{n−1} ds = (π/2)δ_{n1}; so
//!   ∫₋₁¹√(1−s²)U_{n−1}(s)ln|t−s|ds = (π/2)[δ_{n1}ln(|z|/2) − ζ^{n−1}/(n−1)·[n≥2] + ζ^{n+1}/(n+1)].
//!   Taking the difference between t = −1 (ζ = −1, the rear edge ξ′ = 0 of K̂(−ξ′)) and t gives
//!   E(ξ) = s·L·(π/2)·[−θ′F₁ − Σ_{n≥2}Fₙ((−1)^{n−1} − ζ^{n−1})/(n−1) + Σ_{n≥1}Fₙ((−1)^{n+1} − ζ^{n+1})/(n+1)],
//!   θ′ = acosh|t| = ln|z|, ζ = ∓e^{−θ′} behind/ahead; (−1)ᵐ − ζᵐ = (−1)ᵐ(1 − e^{−mθ′}) behind is
//!   formed with `exp_m1`. This removes the ln singularity at ξ′ = 0 and the near-singularity of
//!   ln|ξ−ξ′| for ξ close to the edges, exactly (Hertz check: g = (L²/2)(sinh 2θ′/2 − θ′) behind).
//! - **Creep part, by quadrature.** Σᵢ (sf̂ᵢ/bᵢ)∫Q′[h(−bᵢξ′) − h(bᵢ(ξ−ξ′))]dξ′ with ξ′ = L(1+cos θ),
//!   16-point Gauss–Legendre panels in θ graded geometrically (ratio 2) towards the front edge θ = 0
//!   down to 0.05/√μ_max (the pressure's layers e^{−μθ²/2}) and towards the rear edge θ = π down to
//!   0.05·min(1, 1/√c_max, √(|ξ|_min/L)) (h(−bξ′) ≈ bξ′(ln bξ′ + γ − 1) turns into ln bξ′ at
//!   π − θ ≈ √(2/c); ln|ξ−ξ′| is near-singular at π − θ ≈ √(2|ξ|/L)). h is regular (h(0) = 0,
//!   h ≈ x ln|x|), so every panel sees an analytic integrand or a |x|⁴ln|x| end point.
//!
//! Accuracy (unit tests below): against the exact one-term solution (module [`super::exact`]) with
//! an independent adaptive quadrature of eq. 3.19 in ξ′ (different variable and nodes, full kernel
//! with its log) the gap agrees to ≤ 2.5e−12 of λ²/8 (f/b = 1e−3…1e3 at ξ = −1e−3 λ … −2 λ and ahead);
//! a seven-mode spectrum (c = 5e−4…5e4) agrees with a 24-point, ratio-1.4 rule to ≤ 1e−11; the Hertz
//! case matches its closed form to 1e−12. The computed pressure's own error (~tol) comes on top.
//!
//! Cost (`cargo bench --bench contact_gap`, tol 1e−6, N′ = 1, 2-core machine): +0.39 ms per solve
//! for one term, +1.3 ms for the 10-term and +2.0 ms for the 30-term spectrum of the bench table
//! (56, 519 and 497 Chebyshev terms since fast modes are lumped with a measured correction; before
//! that, 13 706 and 22 860 terms cost +24 and +40 ms: the pressure at ~250 nodes, O(nodes × terms)).
//! Hence `contact_check` looks at ~8 points first and runs the full [`rear_scan`] only when a gap
//! is closed or nearly so; `AutoSettings::gap_check = false` skips it (as the pipeline does).
//!
//! # β < 0 and the rear edge: what the scans show
//! Next to the rear edge the pressure is Q′ ≈ q_r√ξ′ and only the glassy (log) part of the kernel is
//! singular, so the gap opens like the Hertz one: g ≈ (2π/3)·q_r·|ξ|^{3/2} (Hertz: q_r = √λ/π and
//! g = (L²/2)(sinh(2θ′)/2 − θ′) ≈ (L²/3)θ′³), positive whenever the pressure is. Further back, β < 0
//! means the roll is still descending behind the edge; it would re-touch only if the surface,
//! which keeps creeping down after the load has passed, rose back faster than the roll descends. A
//! second contact zone would then be needed. The scan of tests/contact_rear.rs (`scan`, ignored:
//! 4 877 cases, 535 with β < 0: the one-term (f/b, bλ) plane, 300 random 20–40-term spectra over
//! 20–24 decades, 400 random scenes and 456 scenes of two measured compounds over V 1e−6…1e3 m/s,
//! N 1…1e6 N/m, R 0.01…1 m) found no such case: in every β < 0 case the smallest gap is the one next
//! to the edge; at the lowest point the gap is wide open (+8.8 λ²/8 for f = 10, b = 0.01, λ = 1).
//! No proof is known to us, so the check stays in every solve. The only negative gaps found (5 of the
//! 400 random scenes) were wrong solutions of the solver at tol 1e−6 (a re-solve at tol 1e−10 gives
//! another λ and an open gap; tests/data/rear_gap_wrong_solution_case.json): the check flags them.

use crate::contact::numerics::at_lambda::LambdaSolution;
use crate::contact::numerics::chebyshev::theta_w;
use crate::contact::numerics::modes::Modes;
use crate::special::chebyshev::{clenshaw, first_kind_coefficients, sine_series};
use crate::special::gauss_legendre::gauss_legendre;
use crate::special::{expm_ei, kernel_bracket, EULER_GAMMA};
use std::f64::consts::PI;
use std::sync::OnceLock;

/// Evaluates the gap at points outside one contact solution (nodes and pressures precomputed).
#[derive(Debug, Clone)]
pub struct GapEvaluator {
    lambda: f64,
    beta: f64,
    scale: f64,
    coefficients: Vec<f64>,
    /// (sᵢ fᵢ/bᵢ, bᵢ) of the creep part, s·f̂ᵢ = fᵢ (full strengths of the kept modes).
    creep: Vec<(f64, f64)>,
    /// Quadrature nodes ξ′ₖ.
    xi_nodes: Vec<f64>,
    /// Weights × L sin θ × Q′(θₖ).
    weights: Vec<f64>,
    /// Σ_k W_k·Σᵢ(sf̂ᵢ/bᵢ)h(−bᵢξ′ₖ): the rear-edge constant of the creep part.
    rear_constant: f64,
    /// C_a = Σ_{n≥2} Fₙ(−1)^{n−1}/(n−1) and C_b = Σ_{n≥1} Fₙ(−1)^{n+1}/(n+1) (the ζ = −1 sums).
    c_a: f64,
    c_b: f64,
}

/// Gauss–Legendre order per panel.
const GL_ORDER: usize = 10;

impl GapEvaluator {
    /// Set up for a solution of the reduced problem; `closest` is the smallest |distance| (in ξ) from a
    /// contact edge at which the gap will be asked for (it sets the rear/front grading).
    pub fn new(modes: &Modes, scale: f64, sol: &LambdaSolution, closest: f64) -> GapEvaluator {
        Self::with_rule(modes, scale, sol, closest, GL_ORDER, 2.0)
    }

    /// As [`GapEvaluator::new`] with a given Gauss–Legendre order and panel growth ratio (> 1).
    pub(crate) fn with_rule(
        modes: &Modes,
        scale: f64,
        sol: &LambdaSolution,
        closest: f64,
        order: usize,
        ratio: f64,
    ) -> GapEvaluator {
        let l = 0.5 * sol.lambda;
        let creep: Vec<(f64, f64)> = modes
            .f
            .iter()
            .zip(&modes.b)
            .map(|(&f, &b)| (scale * f / b, b))
            .collect();
        let mu_max = sol.mu_max.max(1.0);
        let c_max = modes.b.iter().fold(0.0_f64, |m, &b| m.max(b * l));
        let near = (closest.abs() / l).clamp(1e-12, 1.0);
        let th_front = (0.5 / mu_max.sqrt()).min(0.05 * near.sqrt());
        let th_rear = 0.05 * (1.0 / c_max.max(1.0).sqrt()).min(near.sqrt());
        let mut edges = vec![0.0];
        let mut e = th_front;
        while e < 0.5 * PI {
            edges.push(e);
            e *= ratio;
        }
        let mut rear = Vec::new();
        let mut e = th_rear;
        while e < 0.5 * PI {
            rear.push(PI - e);
            e *= ratio;
        }
        edges.push(0.5 * PI);
        edges.extend(rear.into_iter().rev());
        edges.push(PI);
        let (gx, gw) = gauss_legendre(order);
        let mut xi_nodes = Vec::with_capacity(edges.len() * GL_ORDER);
        let mut weights = Vec::with_capacity(edges.len() * GL_ORDER);
        for win in edges.windows(2) {
            let (a, b) = (win[0], win[1]);
            let (h, m) = (0.5 * (b - a), 0.5 * (a + b));
            for (x, w) in gx.iter().zip(&gw) {
                let th = m + h * x;
                // ξ′ = L(1 + cos θ) = 2L cos²(θ/2), without cancellation near θ = π
                let c2 = (0.5 * th).cos();
                xi_nodes.push(2.0 * l * c2 * c2);
                weights.push(w * h * l * th.sin() * sine_series(&sol.coefficients, th));
            }
        }
        let rear_constant = xi_nodes
            .iter()
            .zip(&weights)
            .map(|(&xp, &w)| w * creep_kernel(&creep, -xp))
            .sum();
        let sign = |m: usize| if m % 2 == 0 { 1.0 } else { -1.0 };
        let (mut c_a, mut c_b) = (0.0, 0.0);
        for (n, &fn_) in sol.coefficients.iter().enumerate().skip(1) {
            if n >= 2 {
                c_a += fn_ * sign(n - 1) / (n - 1) as f64;
            }
            c_b += fn_ * sign(n + 1) / (n + 1) as f64;
        }
        GapEvaluator {
            c_a,
            c_b,
            lambda: sol.lambda,
            beta: sol.beta,
            scale,
            coefficients: sol.coefficients.clone(),
            creep,
            xi_nodes,
            weights,
            rear_constant,
        }
    }

    /// Number of quadrature nodes (a cost measure).
    #[cfg(test)]
    pub fn nodes(&self) -> usize {
        self.xi_nodes.len()
    }

    /// ρv(ξ) for ξ outside [0, λ] (NaN inside).
    pub(crate) fn displacement(&self, xi: f64) -> f64 {
        let (lam, l) = (self.lambda, 0.5 * self.lambda);
        let behind = xi < 0.0;
        let sigma = if behind {
            -xi / l
        } else if xi > lam {
            (xi - lam) / l
        } else {
            return f64::NAN;
        };
        let (theta, w) = theta_w(sigma);
        let zeta = if behind { -w } else { w };
        let a = &self.coefficients;
        // elastic part (module doc):
        // −θ′F₁ − Σ Fₙ((−1)^{n−1} − ζ^{n−1})/(n−1) + Σ Fₙ((−1)^{n+1} − ζ^{n+1})/(n+1)
        // = −θ′F₁ − C_a + C_b + Σ_{n≥2} Fₙζ^{n−1}/(n−1) − Σ_{n≥1} Fₙζ^{n+1}/(n+1), the ζ-sums cut
        // where |ζ|ⁿ < e^{−41} (≈ 1e−18; ζ = ±e^{−θ′}).
        let n_cut = if theta > 0.0 {
            ((41.0 / theta).ceil() as usize + 2).min(a.len())
        } else {
            a.len()
        };
        let mut s = -theta * a.get(1).copied().unwrap_or(0.0) - self.c_a + self.c_b;
        let mut zp = 1.0; // ζ^{n−1}
        for (n, &fn_) in a.iter().enumerate().take(n_cut).skip(1) {
            if n >= 2 {
                s += fn_ * zp / (n - 1) as f64;
            }
            s -= fn_ * zp * zeta * zeta / (n + 1) as f64;
            zp *= zeta;
        }
        let elastic = self.scale * l * 0.5 * PI * s;
        let creep: f64 = if self.creep.is_empty() {
            0.0
        } else {
            self.rear_constant
                - self
                    .xi_nodes
                    .iter()
                    .zip(&self.weights)
                    .map(|(&xp, &wk)| wk * creep_kernel(&self.creep, xi - xp))
                    .sum::<f64>()
        };
        elastic + creep
    }

    /// g(ξ)/(λ²/8) with g = ρv(ξ) − (ξβ − ξ²/2) (≥ 0: the surface is below the roll).
    pub fn gap_ratio(&self, xi: f64) -> f64 {
        let depth = self.lambda * self.lambda / 8.0;
        (self.displacement(xi) - (xi * self.beta - 0.5 * xi * xi)) / depth
    }
}

/// Σᵢ (sfᵢ/bᵢ)h(bᵢx).
fn creep_kernel(creep: &[(f64, f64)], x: f64) -> f64 {
    creep.iter().map(|&(r, b)| r * bracket(b * x)).sum()
}

/// h(x) (docs/MATH.md §2) as `crate::special::kernel_bracket`, with a fast path for −45 ≤ x ≤ −6: there
/// h = ln y + γ − e^{−y}Ei(y), y = −x, and e^{−y}Ei(y) (≈ 1/y, analytic) comes from a table of
/// degree-[`EI_DEGREE`] Chebyshev interpolants on unit intervals, built once from
/// `crate::special::expm_ei` (the library's Ei costs ~1.5 µs per call in this range, as its series
/// needs ~y terms; the table ~20 ns). Agreement with `kernel_bracket`: 4.0e−16 relative at worst (unit test).
fn bracket(x: f64) -> f64 {
    if (-EI_TABLE_TO..=-EI_TABLE_FROM).contains(&x) {
        let y = -x;
        y.ln() + EULER_GAMMA - expm_ei_table(y)
    } else {
        kernel_bracket(x)
    }
}

const EI_TABLE_FROM: f64 = 6.0;
const EI_TABLE_TO: f64 = 45.0;
const EI_DEGREE: usize = 20;

/// e^{−y}Ei(y) for y in [6, 45] from the interpolant table.
fn expm_ei_table(y: f64) -> f64 {
    static TABLE: OnceLock<Vec<[f64; EI_DEGREE + 1]>> = OnceLock::new();
    let table = TABLE.get_or_init(|| {
        let pieces = (EI_TABLE_TO - EI_TABLE_FROM) as usize;
        (0..pieces)
            .map(|p| {
                let a = EI_TABLE_FROM + p as f64;
                first_kind_coefficients::<{ EI_DEGREE + 1 }>(expm_ei, a, a + 1.0)
            })
            .collect()
    });
    let p = ((y - EI_TABLE_FROM) as usize).min(table.len() - 1);
    let t = 2.0 * (y - (EI_TABLE_FROM + p as f64)) - 1.0;
    clenshaw(&table[p], t)
}

/// Where the smallest gap behind the contact lies, and how small it is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RearScan {
    /// min g/(λ²/8) over the scanned points behind the rear edge.
    pub min_gap_ratio: f64,
    /// ξ (< 0) where it was found.
    pub at_xi: f64,
    /// min g/(λ²/8) over the points ahead of the front edge.
    pub min_gap_ahead_ratio: f64,
}

/// Offsets behind the rear edge, as fractions of λ (log-spaced 1e−3 … 8) — the region where the
/// surface recovers; β-related points are added when β < 0.
const BEHIND: [f64; 9] = [1e-3, 1e-2, 0.04, 0.12, 0.3, 0.6, 1.2, 2.5, 6.0];
/// Offsets ahead of the front edge (fractions of λ).
const AHEAD: [f64; 3] = [0.02, 0.3, 1.5];

/// The check run after every `auto` solve: a quick look (gap at 1e−3, 1e−2, 0.1, 0.5, 2 λ behind, at
/// β and 2β when β < 0, and at 0.05 λ, 1 λ ahead: 7–9 points), and the full
/// [`rear_scan`] only when the quick look finds a closed gap, or one below 1e−3 of λ²/8 at 0.1 λ or
/// further behind. The kernel of
/// eq. 3.19 behind the contact (negative arguments of h, through Ei) costs ~1.5 µs per evaluation,
/// so the full scan costs ~(25 points × ~200 nodes × modes) evaluations: it runs only when needed.
pub(crate) fn contact_check(modes: &Modes, scale: f64, sol: &LambdaSolution) -> RearScan {
    let lam = sol.lambda;
    let ev = GapEvaluator::new(modes, scale, sol, 1e-3 * lam);
    let mut behind: Vec<f64> = [1e-3, 1e-2, 0.1, 0.5, 2.0]
        .iter()
        .map(|k| -k * lam)
        .collect();
    if sol.beta < 0.0 {
        behind.extend([sol.beta, 2.0 * sol.beta]);
    }
    let (mut g_min, mut at) = (f64::INFINITY, 0.0);
    let mut far_ok = true;
    for &x in &behind {
        let g = ev.gap_ratio(x);
        if g < g_min || g.is_nan() {
            g_min = g;
            at = x;
        }
        // next to the edge the gap opens like |ξ|^{3/2} and may be small; it need only be open
        far_ok &= if x >= -1e-2 * lam { g > 0.0 } else { g >= 1e-3 };
    }
    let min_ahead = [0.05, 1.0]
        .iter()
        .map(|k| ev.gap_ratio(lam * (1.0 + k)))
        .fold(f64::INFINITY, f64::min);
    if far_ok && min_ahead > 0.0 {
        return RearScan {
            min_gap_ratio: g_min,
            at_xi: at,
            min_gap_ahead_ratio: min_ahead,
        };
    }
    rear_scan(modes, scale, sol)
}

/// Gap behind the contact at 9 offsets (1e−3 λ … 6 λ) and, when β < 0, at 0.5…2.5 × β (the roll's
/// lowest point and beyond), plus 3 points ahead of the front edge; then an interior minimum behind
/// that comes within 0.1 of λ²/8 is refined by golden-section search between its neighbours.
pub fn rear_scan(modes: &Modes, scale: f64, sol: &LambdaSolution) -> RearScan {
    let lam = sol.lambda;
    let ev = GapEvaluator::new(modes, scale, sol, BEHIND[0] * lam);
    let mut xs: Vec<f64> = BEHIND.iter().map(|k| -k * lam).collect();
    if sol.beta < 0.0 {
        xs.extend([0.5, 1.0, 1.5, 2.5].iter().map(|k| k * sol.beta));
    }
    xs.sort_by(|a, b| b.total_cmp(a)); // from the edge backwards
    let g: Vec<f64> = xs.iter().map(|&x| ev.gap_ratio(x)).collect();
    let (mut k_min, mut g_min) = (0, f64::INFINITY);
    for (k, &v) in g.iter().enumerate() {
        if v < g_min || v.is_nan() {
            k_min = k;
            g_min = v;
        }
    }
    let mut at = xs[k_min];
    // refine an interior minimum that comes within 0.1·λ²/8 of closing (a minimum at the first
    // point is the edge itself, g ~ |ξ|^{3/2}; a wide-open interior minimum needs no refinement)
    if k_min > 0 && k_min + 1 < xs.len() && g_min < 0.1 {
        let (mut a, mut b) = (xs[k_min + 1], xs[k_min - 1]);
        let r = 0.5 * (5f64.sqrt() - 1.0);
        let mut c = b - r * (b - a);
        let mut d = a + r * (b - a);
        let (mut gc, mut gd) = (ev.gap_ratio(c), ev.gap_ratio(d));
        for _ in 0..24 {
            if gc < gd {
                b = d;
                d = c;
                gd = gc;
                c = b - r * (b - a);
                gc = ev.gap_ratio(c);
            } else {
                a = c;
                c = d;
                gc = gd;
                d = a + r * (b - a);
                gd = ev.gap_ratio(d);
            }
        }
        let (x, v) = if gc < gd { (c, gc) } else { (d, gd) };
        if v < g_min {
            g_min = v;
            at = x;
        }
    }
    let min_ahead = AHEAD
        .iter()
        .map(|k| ev.gap_ratio(lam * (1.0 + k)))
        .fold(f64::INFINITY, f64::min);
    RearScan {
        min_gap_ratio: g_min,
        at_xi: at,
        min_gap_ahead_ratio: min_ahead,
    }
}

#[cfg(test)]
mod tests {
    use super::super::exact::one_term_at_lambda;
    use super::*;
    use crate::contact::numerics::at_lambda::{solve_at_lambda, QuadratureSettings};
    use crate::contact::numerics::kernel::Kernel;
    use crate::contact::problem::CreepTerm;
    use crate::special::gauss_legendre::Integrator;

    #[test]
    fn spectrum_gap_converged_against_a_finer_rule() {
        // Seven modes from slow to fast (c = bλ/2 from 5e−4 to 5e4, μ up to ~1e6): the default rule
        // (order 10, ratio 2) against order 24 with ratio 1.4; both share only the pressure.
        let terms: Vec<CreepTerm> = (0..7)
            .map(|k| {
                let b = 10f64.powi(k - 3);
                CreepTerm { f: 20.0 * b, b }
            })
            .collect();
        let m = Modes::new(&terms);
        let lam = 1.0;
        let sol = solve_at_lambda(&m, lam, QuadratureSettings::default());
        let coarse = GapEvaluator::new(&m, 1.0, &sol, 1e-3 * lam);
        let fine = GapEvaluator::with_rule(&m, 1.0, &sol, 1e-3 * lam, 24, 1.4);
        for &xi in &[-1e-3, -1e-2, -0.12, -1.2, -6.0, 1.02, 1.3, 2.5] {
            let (a, b) = (coarse.gap_ratio(xi), fine.gap_ratio(xi));
            eprintln!(
                "ξ {xi}: {a:.15e} vs {b:.15e} (nodes {} / {})",
                coarse.nodes(),
                fine.nodes()
            );
            // the accuracy claimed in the module doc
            assert!(
                (a - b).abs() < 1e-10 * (1.0 + b.abs()),
                "ξ {xi}: {a} vs {b}"
            );
        }
    }

    #[test]
    fn fast_bracket_matches_the_library() {
        let mut worst: f64 = 0.0;
        for k in 0..=20000 {
            let x = -6.0 - 39.0 * k as f64 / 20000.0;
            let (a, b) = (bracket(x), kernel_bracket(x));
            worst = worst.max(((a - b) / b).abs());
        }
        // both are accurate to a few ulp of h (≈ 2…4.4 here); measured 4.04e−16 relative
        assert!(worst < 1e-15, "{worst:e}");
    }

    #[test]
    fn hertz_gap_matches_closed_form() {
        // Elastic: g = (L²/2)(sinh(2θ′)/2 − θ′)·… behind and ahead (symmetric); from the module doc's
        // formula with F₁ = L/π: ρv = (L²/2)(−θ′ + (1 − e^{−2θ′})/2), roll ξβ − ξ²/2 with β = L.
        let m = Modes::new(&[]);
        let sol = solve_at_lambda(&m, 2.0, QuadratureSettings::default());
        let ev = GapEvaluator::new(&m, 1.0, &sol, 1e-3);
        let l = 1.0;
        for &xi in &[-1e-3, -0.1, -1.0, -7.0, 2.001, 2.5, 9.0] {
            let t: f64 = xi / l - 1.0;
            let th = t.abs().acosh();
            let rho_v = 0.5 * l * l * (-th + 0.5 * (1.0 - (-2.0 * th).exp()));
            let g = (rho_v - (xi * l - 0.5 * xi * xi)) / 0.5;
            let got = ev.gap_ratio(xi);
            // closed form vs closed form: rounding only (acosh near 1 loses ~√ε·… absolute 1e−12)
            assert!(
                (got - g).abs() < 1e-12 * (1.0 + g.abs()),
                "{xi}: {got} vs {g}"
            );
            assert!(got > 0.0);
        }
    }

    /// Independent route: eq. 3.19 with the full kernel (log included) and the exact one-term
    /// pressure (contact::exact), integrated adaptively in ξ′ = λu² near the rear edge (removes the
    /// √ξ′ ln ξ′ end point) and ξ′ = λ − λv² near the front edge.
    fn gap_by_quadrature(term: CreepTerm, lambda: f64, xi: f64) -> f64 {
        let ex = one_term_at_lambda(term, lambda).unwrap();
        let k = Kernel::new(&[term]).unwrap();
        let mut ig = Integrator::new(20);
        let half = 0.5 * lambda;
        let f_rear = |u: f64| {
            let xp = lambda * u * u;
            ex.pressure(xp) * (k.k(-xp) - k.k(xi - xp)) * 2.0 * lambda * u
        };
        let f_front = |v: f64| {
            let xp = lambda - lambda * v * v;
            ex.pressure(xp) * (k.k(-xp) - k.k(xi - xp)) * 2.0 * lambda * v
        };
        let ur = (half / lambda).sqrt();
        // geometric initial panels towards the rear edge u = 0 and towards the front layer
        let mut e1 = vec![0.0];
        let mut e = ur * 1e-6;
        while e < ur {
            e1.push(e);
            e *= 4.0;
        }
        e1.push(ur);
        let mut e2 = vec![0.0];
        let mut e = ur * 1e-6;
        while e < ur {
            e2.push(e);
            e *= 4.0;
        }
        e2.push(ur);
        let rho_v = ig.integrate(f_rear, &e1, 1e-14) + ig.integrate(f_front, &e2, 1e-14);
        (rho_v - (xi * ex.beta - 0.5 * xi * xi)) / (lambda * lambda / 8.0)
    }

    #[test]
    fn one_term_gap_matches_independent_quadrature() {
        for &(f, b, lam) in &[
            (10.0, 0.01, 1.0),
            (10.0, 1.0, 1.0),
            (1000.0, 1.0, 0.3),
            (3.0, 20.0, 1.0),
        ] {
            let term = CreepTerm { f, b };
            let m = Modes::new(&[term]);
            let sol = solve_at_lambda(&m, lam, QuadratureSettings::default());
            let scan_pts = [
                -1e-3 * lam,
                -0.05 * lam,
                -0.5 * lam,
                -2.0 * lam,
                sol.beta.min(-0.3 * lam),
                1.02 * lam,
                1.5 * lam,
            ];
            let ev = GapEvaluator::new(&m, 1.0, &sol, 1e-3 * lam);
            for &xi in &scan_pts {
                let got = ev.gap_ratio(xi);
                let want = gap_by_quadrature(term, lam, xi);
                eprintln!("f {f} b {b} λ {lam} ξ {xi:.4}: {got:.15e} vs {want:.15e}");
                // both routes are accurate to ~1e−12 of λ²/8; the solution itself to ~1e−13
                assert!(
                    (got - want).abs() < 1e-10,
                    "f {f} b {b} ξ {xi}: {got} vs {want}"
                );
            }
        }
    }
}
