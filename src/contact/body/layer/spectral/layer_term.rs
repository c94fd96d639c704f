//! The layer's correction to the half-space equation, G(t) = −d(ρv_R)/dξ, as a matrix acting on the
//! pressure's Chebyshev coefficients (module doc of [`super`]).
//!
//! Input: the reduced creep terms, L = λ/2, h′, ν and the degree p; output: [`LayerTerm`], the
//! Chebyshev coefficients g_m (m = 0…p) of the degree-p interpolant of G at the Lobatto points for
//! each pressure basis function √(1−t²)U_k (k = 0…n_J − 1).
//!
//! # Formula
//! ρv_R is the part of the deflection removed by the rigid base: transform Ĝ_R(k) = πR(|k|h′)Φ(k)/|k|
//! (module doc of [`super::super::kernel`]). With Q′ = √(1−t²)Σa_kU_k(t), t = (ξ − L)/L, and the
//! transform ∫√(1−u²)U_k(u)e^{−iκu}du = π(k+1)(−i)^kJ_{k+1}(κ)/κ (Gradshteyn & Ryzhik 7.355;
//! A&S 9.1.20), κ = kL, the inverse transform of ik·Ĝ_R·Q̂ folded onto κ > 0 (Φ(−k) = Φ(k)*) gives
//!
//! ```text
//!   G(t) = π Σ_k a_k ∫₀^∞ (R(κh′/L)/κ) Im[Φ(κ/L)(k+1)(−i)^k J_{k+1}(κ) e^{iκt}] dκ.
//! ```
//!
//! Checks: for f = 0 and even k this is π(−1)^{k/2}(k+1)∫R J_{k+1}(κ)sin(κt)/κ dκ, the independent
//! elastic solver's term (`elastic_check.rs`); G is C^∞ on the contact and varies on the scale h′/L
//! (R decays like e^{−2κh′/L}), so its interpolant converges geometrically in p once p ≳ L/h′.
//!
//! # Quadrature
//! κ ∈ [κ_lo, 1]: 14-point Gauss–Legendre panels of width 2 in ln κ (the poles of Φ(κ/L) at
//! κ = −ic_i lie π/2 off the real axis in ln κ: ellipse parameter ≈ 3.4, error ≲ 3.4^{−28} ≈ 1e−15
//! of a panel's part; R's singularities at κ ~ L/h′ are nearer, measured in the test). Below the poles the integrand is bounded by (π/2)(Σrᵢκ/cᵢ + sκ) (|R| ≤ 1,
//! J_{k+1}(κ) ≤ (κ/2)^{k+1}/(k+1)!, Im Φ(κ/L) ≤ Σrᵢκ/cᵢ, rᵢ = f̂ᵢ/bᵢ, s = 1 + Σrᵢ), so cutting at
//! κ_lo = √(4e−15/(π(Σrᵢ/cᵢ + s))) leaves out ≤ 1e−15 (`LogRule::production`; a test compares
//! the rule with one of half the panel width, 16 points and κ_lo a thousand times smaller).
//! κ ∈ [1, κ_hi], κ_hi = 20L/h′
//! (R < 2e−15 beyond, T_MAX): 16-point panels of width ≤ 4 (at most eight radians of e^{iκ(t±1)},
//! J_{k+1} oscillates slower; the Gauss error for e^{iωx} with ω = 4 on 16 nodes is ~(eω/64)^{32}
//! < 1e−20). At a node κ only orders k + 1 ≤ min(κ + 12κ^{1/3} + 30, n with (κ/2)ⁿ/n! < 1e−22)
//! carry weight (J_n(κ) < 1e−20
//! beyond), which keeps the log region cheap. J_n by Miller's backward recurrence normalised by
//! J₀ + 2ΣJ₂ₖ = 1 (A&S 9.1.46, 9.12).
//!
//! # Evaluation: two matrix products
//! With wₙ the weights at the nodes κₙ, Φₙ = pr + i·pi and vₙₖ = πwₙ(k+1)J_{k+1}(κₙ), the factor
//! (−i)^k is real for even k (c = ±v) and imaginary for odd k (c = iγ, γ = ∓v), so
//!
//! ```text
//!   even k: G_k(t) = Σₙ cₙₖ (pr sin κₙt + pi cos κₙt),   odd k: G_k(t) = Σₙ γₙₖ (pr cos κₙt − pi sin κₙt),
//! ```
//!
//! and at the mirrored Lobatto point −t only the sign of the sine parts changes. The values at the
//! p + 1 points are therefore [pr sin; pi cos]·C_even and [pr cos; pi sin]·Γ_odd at the points
//! t ≥ 0 (two products of (p + 2) × nodes by nodes × n_J/2, SIMD matrix multiplication), the
//! Chebyshev coefficients a DCT-I matrix times those values, and G for all columns of the solve one
//! more product ([`LayerTerm::apply_all`]).
//!
//! Cost (issue 14, docs/DEVLOG.md "Speed work" round 5): the products are formed node-major (each node's
//! C/Γ entries one contiguous column, written once) and split at κ = 1, where the log part's nodes
//! carry only the orders k + 1 ≤ 19 of (κ/2)ⁿ/n!; Miller's recurrence runs [`LANES`] nodes side by
//! side and its normalisation 1/(J₀ + 2ΣJ₂ₖ) is folded into the node's weight (one division per
//! node, not per order); on the panels of [1, κ_hi], κ = m + h·x (centre m, half-width h, Gauss
//! abscissa x) and sin κt = sin mt·cos hxt + cos mt·sin hxt with the hxt values shared by all
//! panels, so one sine-cosine pair per panel and point instead of per node and point (the same
//! accuracy: sin κt with κt rounded is off by ~1e−16·κt as well). The node arrays come from a small
//! per-thread pool (`pooled_zeros`): allocated afresh, their pages were faulted in every solve.
//! `LayerTerm::reference`, the straightforward build, is kept for the tests (≤ 1e−13 of the largest
//! coefficient, `fast_build_matches_the_reference`).

use crate::contact::body::layer::compliance::layer_defect;
use crate::contact::numerics::modes::Modes;
use crate::special::gauss_legendre::gauss_legendre;
use nalgebra::DMatrix;
use std::cell::RefCell;
use std::f64::consts::PI;
use std::sync::OnceLock;

/// R(t) < 2e−15 beyond t = κh′/L = 20 ((4t²/κ)e^{−2t}, module doc of `compliance`).
const T_MAX: f64 = 20.0;

/// J₀…J_nmax at x > 0 (Miller's backward recurrence, normalised by J₀ + 2ΣJ₂ₖ = 1).
#[cfg(test)]
pub fn bessel_j(x: f64, nmax: usize) -> Vec<f64> {
    let mut out = [Vec::new()];
    bessel_j_lanes(&[x], nmax, &mut out);
    let [j] = out;
    j
}

/// Lanes of [`bessel_j_lanes`]: independent recurrences run side by side, so that their
/// multiply-add chains overlap (one recurrence alone waits on each step's latency).
pub const LANES: usize = 8;

/// [`bessel_j`] at up to [`LANES`] points at once: `out[q]` = J₀…J_nmax at `xs[q]`. Each lane starts
/// at the highest start the lanes need (a higher start only makes Miller's algorithm more accurate).
#[cfg(test)]
pub fn bessel_j_lanes(xs: &[f64], nmax: usize, out: &mut [Vec<f64>]) {
    let w = xs.len().min(LANES).min(out.len());
    let mut j = Vec::new();
    let norm = miller_lanes(&xs[..w], nmax, &mut j);
    for (q, o) in out[..w].iter_mut().enumerate() {
        o.clear();
        o.extend(j[..=nmax].iter().map(|r| r[q] / norm[q]));
    }
}

/// Miller's backward recurrence of [`bessel_j_lanes`] at up to [`LANES`] points, unnormalised:
/// `j[n][q]` ∝ J_n(xs[q]) for n ≤ nmax (`j` is a scratch buffer, reused between calls), and the
/// normalisations J₀ + 2ΣJ₂ₖ of each lane (J_n = j[n][q]/norm[q]).
fn miller_lanes(xs: &[f64], nmax: usize, j: &mut Vec<[f64; LANES]>) -> [f64; LANES] {
    let w = xs.len().min(LANES);
    let start = xs[..w]
        .iter()
        .map(|&x| {
            let top = nmax as f64 + x;
            2 * ((top + 20.0 + (40.0 * top).sqrt()) as usize / 2 + 1)
        })
        .max()
        .unwrap_or(2);
    let mut tox = [0.0; LANES];
    for (t, &x) in tox.iter_mut().zip(&xs[..w]) {
        *t = 2.0 / x;
    }
    j.clear();
    j.resize(start + 2, [0.0; LANES]);
    j[start] = [1e-30; LANES];
    for k in (1..=start).rev() {
        let kf = k as f64;
        let (lo, hi) = j.split_at_mut(k);
        let (jk, jk1) = (hi[0], hi[1]);
        let mut big = false;
        for q in 0..LANES {
            let v = kf * tox[q] * jk[q] - jk1[q];
            lo[k - 1][q] = v;
            big |= v.abs() > 1e250;
        }
        if big {
            for row in j[k - 1..].iter_mut() {
                for (q, v) in row.iter_mut().enumerate() {
                    if q < w {
                        *v *= 1e-250;
                    }
                }
            }
        }
    }
    // J₀ + 2ΣJ₂ₖ, all lanes in one pass (each lane's sum in the order of `Iterator::sum`)
    let mut even = [-0.0_f64; LANES];
    for r in j.iter().skip(2).step_by(2) {
        for (e, v) in even.iter_mut().zip(r) {
            *e += v;
        }
    }
    let mut norm = [1.0; LANES];
    for q in 0..w {
        norm[q] = j[0][q] + 2.0 * even[q];
    }
    norm
}

/// Number of pressure coefficients the layer term sees at κ_hi (module doc).
pub fn orders_needed(kappa_hi: f64) -> usize {
    (kappa_hi + 12.0 * kappa_hi.cbrt() + 30.0).ceil() as usize
}

/// The layer term as a matrix: `coef[m][k]` = Chebyshev coefficient m of G for a_k = 1.
#[derive(Debug, Clone)]
pub struct LayerTerm {
    /// (p + 1) × n_J.
    pub coef: DMatrix<f64>,
    /// G at the p + 1 Lobatto points for a_k = 1, (p + 1) × n_J (kept for [`LayerTerm::halved`]).
    values: DMatrix<f64>,
    /// Number of pressure orders n_J.
    pub orders: usize,
}

/// The rule on the logarithmic part κ ∈ [κ_lo, 1] (module doc).
#[derive(Debug, Clone, Copy)]
struct LogRule {
    /// Panel width in ln κ.
    width: f64,
    /// Gauss–Legendre points per panel.
    points: usize,
    /// Lower end κ_lo.
    lo: f64,
}

impl LogRule {
    /// The rule used: panels of width 2 in ln κ with 14 points (the poles of Φ(κ/L) lie π/2 off the
    /// real ln κ axis: ellipse parameter ρ = π/2 + √(π²/4 + 1) ≈ 3.4 for the half-width 1, Gauss
    /// error ≲ ρ^{−28} ≈ 1e−15 of the panel's part), cut at κ_lo with the neglected part ≤ 1e−15
    /// (module doc: the integrand is ≤ (π/2)(Σ rᵢκ/cᵢ + s·κ) below the poles, so ∫₀^{κ_lo} ≤
    /// (π/4)κ_lo²(Σ rᵢ/cᵢ + s), rᵢ = f̂ᵢ/bᵢ, cᵢ = bᵢL, s = 1 + Σrᵢ).
    fn production(modes: &Modes, l: f64) -> LogRule {
        let (mut sum_rc, mut s) = (0.0, 1.0);
        for (f, b) in modes.f.iter().zip(&modes.b) {
            sum_rc += f / (b * b * l);
            s += f / b;
        }
        let lo = (4e-15 / (PI * (sum_rc + s))).sqrt().min(1e-3);
        LogRule {
            width: 2.0,
            points: 14,
            lo,
        }
    }
}

/// Gauss–Legendre rule of `points` points, computed once for the 14 and 16 points used.
fn gauss_rule(points: usize) -> (Vec<f64>, Vec<f64>) {
    static G14: OnceLock<(Vec<f64>, Vec<f64>)> = OnceLock::new();
    static G16: OnceLock<(Vec<f64>, Vec<f64>)> = OnceLock::new();
    match points {
        14 => G14.get_or_init(|| gauss_legendre(14)).clone(),
        16 => G16.get_or_init(|| gauss_legendre(16)).clone(),
        _ => gauss_legendre(points),
    }
}

/// Quadrature nodes of the module doc: κ and weight·R(κh′/L)/κ, the first `n_log` on the log part
/// [κ_lo, min(κ_hi, 1)], then `LINEAR_POINTS`-point Gauss panels of equal width on [1, κ_hi]
/// (their centres in `panels`, half-width `half`, abscissae `gx`).
struct Nodes {
    kappa: Vec<f64>,
    weight: Vec<f64>,
    n_log: usize,
    panels: Vec<f64>,
    half: f64,
    gx: Vec<f64>,
}

/// Gauss points per panel on [1, κ_hi].
const LINEAR_POINTS: usize = 16;

fn nodes(rule: LogRule, kappa_hi: f64, thickness_over_l: f64, nu: f64) -> Nodes {
    let (mut kappa, mut weight) = (Vec::new(), Vec::new());
    let k_mid = kappa_hi.min(1.0);
    let k_lo = rule.lo.min(0.5 * k_mid);
    let (gx, gw) = gauss_rule(rule.points);
    let (va, vb) = (k_lo.ln(), k_mid.ln());
    let np = ((vb - va) / rule.width).ceil().max(1.0) as usize;
    for p in 0..np {
        let a = va + (vb - va) * p as f64 / np as f64;
        let b = va + (vb - va) * (p + 1) as f64 / np as f64;
        let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
        for (x, w) in gx.iter().zip(&gw) {
            let k = (mid + half * x).exp();
            kappa.push(k);
            weight.push(k * half * w * layer_defect(k * thickness_over_l, nu) / k);
        }
    }
    let n_log = kappa.len();
    let (gx, gw) = gauss_rule(LINEAR_POINTS);
    let mut panels = Vec::new();
    let mut half_width = 0.0;
    if kappa_hi > k_mid {
        let np = ((kappa_hi - k_mid) / 4.0).ceil().max(1.0) as usize;
        half_width = 0.5 * (kappa_hi - k_mid) / np as f64;
        for p in 0..np {
            let a = k_mid + (kappa_hi - k_mid) * p as f64 / np as f64;
            let b = k_mid + (kappa_hi - k_mid) * (p + 1) as f64 / np as f64;
            let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
            panels.push(mid);
            for (x, w) in gx.iter().zip(&gw) {
                let k = mid + half * x;
                kappa.push(k);
                weight.push(half * w * layer_defect(k * thickness_over_l, nu) / k);
            }
        }
    }
    Nodes {
        kappa,
        weight,
        n_log,
        panels,
        half: half_width,
        gx,
    }
}

/// The DCT-I matrix from values at the p + 1 Lobatto points to Chebyshev coefficients (as
/// `special::chebyshev::lobatto_coefficients`), with the 2p distinct cosines cos(πj/p) computed once
/// (cos(πmi/p) = cos(π(mi mod 2p)/p)).
fn dct(p: usize) -> DMatrix<f64> {
    let cosines: Vec<f64> = (0..2 * p)
        .map(|j| (PI * j as f64 / p as f64).cos())
        .collect();
    DMatrix::<f64>::from_fn(p + 1, p + 1, |m, i| {
        let edge = if m == 0 || m == p { 0.5 } else { 1.0 };
        let w = if i == 0 || i == p { 0.5 } else { 1.0 };
        edge * w * 2.0 / p as f64 * cosines[(m * i) % (2 * p)]
    })
}

thread_local! {
    /// Buffers of [`LayerTerm::new`]'s node arrays, kept between calls: a load point's solves ask
    /// for arrays of nearly the same sizes (~0.1–0.5 MB), and allocating them afresh costs page
    /// faults and clearing whole pages each time.
    static POOL: RefCell<Vec<Vec<f64>>> = const { RefCell::new(Vec::new()) };
}

/// Buffers kept in the pool at most, and the largest kept (f64s: 8 MB; larger ones, from covers
/// far thinner than any accepted solve, are freed).
const POOL_BUFFERS: usize = 4;
const POOL_MAX_LEN: usize = 1 << 20;

/// A zero rows × cols matrix on a buffer from the thread's pool.
fn pooled_zeros(rows: usize, cols: usize) -> DMatrix<f64> {
    let mut v = POOL.with(|p| p.borrow_mut().pop()).unwrap_or_default();
    v.clear();
    v.resize(rows * cols, 0.0);
    DMatrix::from_vec(rows, cols, v)
}

/// Hand a matrix's buffer back to the thread's pool.
fn recycle(m: DMatrix<f64>) {
    let v: Vec<f64> = m.data.into();
    if v.capacity() <= POOL_MAX_LEN {
        POOL.with(|p| {
            let mut p = p.borrow_mut();
            if p.len() < POOL_BUFFERS {
                p.push(v);
            }
        });
    }
}

/// X = B·L for the node-major B (orders × nodes) and L (nodes × rows): the linear-panel nodes
/// (from `n_log` on) in one product, the log-part nodes, whose Bessel orders stop below
/// `orders_log` (κ < 1: few orders), added on the first `orders_log` rows only.
fn product(b: &DMatrix<f64>, left: &DMatrix<f64>, n_log: usize, orders_log: usize) -> DMatrix<f64> {
    let (orders, nn) = b.shape();
    let n_lin = nn - n_log;
    let mut x = if n_lin > 0 {
        b.columns(n_log, n_lin) * left.rows(n_log, n_lin)
    } else {
        DMatrix::<f64>::zeros(orders, left.ncols())
    };
    let ol = orders_log.min(orders);
    if n_log > 0 && ol > 0 {
        x.rows_mut(0, ol)
            .gemm(1.0, &b.view((0, 0), (ol, n_log)), &left.rows(0, n_log), 1.0);
    }
    x
}

/// The DCT-I matrix as first written, one cosine per entry (reference of [`dct`]).
#[cfg(test)]
fn dct_reference(p: usize) -> DMatrix<f64> {
    DMatrix::<f64>::from_fn(p + 1, p + 1, |m, i| {
        let edge = if m == 0 || m == p { 0.5 } else { 1.0 };
        let w = if i == 0 || i == p { 0.5 } else { 1.0 };
        edge * w * 2.0 / p as f64 * (PI * (m * i) as f64 / p as f64).cos()
    })
}

/// sin x and cos x for 0 ≤ x ≤ 1 by their Taylor series to x¹⁷/17! and x¹⁸/18! (remainders
/// ≤ 1/19! ≈ 8e−18 and 1/20! ≈ 4e−19; a few ulp of rounding in the nested sums, test
/// `unit_sin_cos_matches_the_library`), without the library's argument reduction: the log part's
/// κt < 1 asks for about (p/2 + 1)·130 pairs per layer term. Outside [0, 1] the library's.
fn sin_cos_unit(x: f64) -> (f64, f64) {
    if !(0.0..=1.0).contains(&x) {
        return x.sin_cos();
    }
    let x2 = x * x;
    // 1/(2k+1)! and 1/(2k)!
    const S: [f64; 8] = [
        -1.0 / 6.0,
        1.0 / 120.0,
        -1.0 / 5040.0,
        1.0 / 362_880.0,
        -1.0 / 39_916_800.0,
        1.0 / 6_227_020_800.0,
        -1.0 / 1_307_674_368_000.0,
        1.0 / 355_687_428_096_000.0,
    ];
    const C: [f64; 9] = [
        -0.5,
        1.0 / 24.0,
        -1.0 / 720.0,
        1.0 / 40_320.0,
        -1.0 / 3_628_800.0,
        1.0 / 479_001_600.0,
        -1.0 / 87_178_291_200.0,
        1.0 / 20_922_789_888_000.0,
        -1.0 / 6_402_373_705_728_000.0,
    ];
    let mut s = 0.0;
    for c in S.iter().rev() {
        s = (s + c) * x2;
    }
    let mut c = 0.0;
    for k in C.iter().rev() {
        c = (c + k) * x2;
    }
    (x + x * s, 1.0 + c)
}

/// Orders n ≥ 1 beyond which J_n(κ) < 1e−22 by J_n(κ) ≤ (κ/2)ⁿ/n! (for κ < 1; else `usize::MAX`).
fn small_kappa_orders(kappa: f64) -> usize {
    if kappa >= 1.0 {
        return usize::MAX;
    }
    let (mut n, mut term) = (1usize, 0.5 * kappa);
    while term >= 1e-22 && n < 60 {
        n += 1;
        term *= 0.5 * kappa / n as f64;
    }
    n
}

/// The κ range of a layer term at half-length `l`, thickness h′ and degree `p`: (h′/L, κ_hi, the
/// orders needed at κ_hi). A solve at degree p is only ever accepted with L/h′ ≤ 2p
/// (`degree::degree_for` with tol ≤ 0.1), so beyond L/h′ = max(2p, 200) the κ range is truncated:
/// such a solve only steers a load loop's bracket (e.g. a very soft bootstrap replicate, contact
/// lengths of metres on a 5 mm cover), and its cost (∝ κ_hi²·p) and memory stay bounded.
fn kappa_range(l: f64, thickness: f64, p: usize) -> (f64, f64, usize) {
    let h_over_l = thickness / l;
    let kappa_hi = (T_MAX / h_over_l).min(T_MAX * (2.0 * p as f64).max(200.0));
    (h_over_l, kappa_hi, orders_needed(kappa_hi))
}

/// (module doc, "Evaluation") The rows i = 0…p/2 of the Lobatto points t_i = cos(πi/p) ≥ 0; the
/// mirrored rows p − i follow from the parity of sin and cos ([`unfold`]).
fn lobatto_half(p: usize) -> Vec<f64> {
    (0..=p / 2)
        .map(|i| (PI * i as f64 / p as f64).cos())
        .collect()
}

/// The values G at the p + 1 Lobatto points for a_k = 1, (p + 1) × `orders`, from the products
/// at the half rows (`xe`, `xo`: orders/2 × 2(p/2 + 1), [`product`]): the even orders' row i is
/// x₂ + x₁ and its mirror p − i is x₂ − x₁; the odd orders' x₃ − x₄ and x₃ + x₄.
fn unfold(xe: &DMatrix<f64>, xo: &DMatrix<f64>, p: usize, orders: usize) -> DMatrix<f64> {
    let half = p / 2;
    let mut values = DMatrix::<f64>::zeros(p + 1, orders);
    for i in 0..=half {
        for k in 0..orders {
            let (plus, minus) = if k % 2 == 0 {
                let (x1, x2) = (xe[(k / 2, i)], xe[(k / 2, half + 1 + i)]);
                (x2 + x1, x2 - x1)
            } else {
                let (x3, x4) = (xo[(k / 2, i)], xo[(k / 2, half + 1 + i)]);
                (x3 - x4, x3 + x4)
            };
            values[(i, k)] = plus;
            values[(p - i, k)] = minus;
        }
    }
    values
}

/// The factors of a layer term's products ([`LayerTerm::with_rule`]): per node (a column of the
/// `bt_*`, a row of the `lt_*`) the orders' Bessel factors and the left factors at the half rows.
struct Factors {
    bt_even: DMatrix<f64>,
    bt_odd: DMatrix<f64>,
    lt_even: DMatrix<f64>,
    lt_odd: DMatrix<f64>,
    /// p/2.
    half: usize,
}

impl Factors {
    /// Every node's Bessel factors (k+1)(−i)^k J_{k+1}(κ)·πw (Miller's recurrence by lanes, the
    /// orders down to the last above 1e−22 of the norm) and Φ(κ/L); on the log nodes also the left
    /// factors. Returns Φ at every node and the most orders used on a log node.
    fn fill_nodes(
        &mut self,
        modes: &Modes,
        l: f64,
        nodes: &Nodes,
        wanted: &[usize],
        ts: &[f64],
    ) -> (Vec<(f64, f64)>, usize) {
        let half = self.half;
        let nn = nodes.kappa.len();
        // Φ(κ/L) = 1 + Σf̂/(b − iκ/L) = 1 + Σf̂(b + iκ/L)/(b² + (κ/L)²): fᵢbᵢ once per mode
        let fb: Vec<f64> = modes.f.iter().zip(&modes.b).map(|(f, b)| f * b).collect();
        let mut phi = vec![(0.0, 0.0); nn];
        let mut scratch = Vec::new();
        let mut used_log = 1;
        for (c, (xs, wc)) in nodes
            .kappa
            .chunks(LANES)
            .zip(wanted.chunks(LANES))
            .enumerate()
        {
            let nmax = wc.iter().copied().max().unwrap_or(1);
            let norm = miller_lanes(xs, nmax, &mut scratch);
            for (q, (&kappa, &want)) in xs.iter().zip(wc).enumerate() {
                let n = c * LANES + q;
                let mut used = want;
                while used > 1 && (scratch[used][q] / norm[q]).abs() < 1e-22 {
                    used -= 1;
                }
                if n < nodes.n_log {
                    used_log = used_log.max(used);
                }
                // (k+1)(−i)^k J_{k+1} πw: (−i)^k = 1, −i, −1, i
                let ww = PI * nodes.weight[n] / norm[q];
                let (ce, co) = (self.bt_even.column_mut(n), self.bt_odd.column_mut(n));
                let (ce, co) = (ce.data.into_slice_mut(), co.data.into_slice_mut());
                for k in 0..used {
                    let v = ww * ((k + 1) as f64 * scratch[k + 1][q]);
                    match k % 4 {
                        0 => ce[k / 2] = v,
                        1 => co[k / 2] = -v,
                        2 => ce[k / 2] = -v,
                        _ => co[k / 2] = v,
                    }
                }
                let kk = kappa / l;
                let (mut pr, mut pi) = (1.0, 0.0);
                for ((f, b), fb) in modes.f.iter().zip(&modes.b).zip(&fb) {
                    let inv = 1.0 / (b * b + kk * kk);
                    pr += fb * inv;
                    pi += f * kk * inv;
                }
                phi[n] = (pr, pi);
                if n < nodes.n_log {
                    for (i, &t) in ts.iter().enumerate() {
                        let (sn, cs) = sin_cos_unit(kappa * t);
                        self.lt_even[(n, i)] = pr * sn;
                        self.lt_even[(n, half + 1 + i)] = pi * cs;
                        self.lt_odd[(n, i)] = pr * cs;
                        self.lt_odd[(n, half + 1 + i)] = pi * sn;
                    }
                }
            }
        }
        (phi, used_log)
    }

    /// The left factors on the linear panels: sin/cos of κt by the angle sums, κ = m + hx (centre
    /// m, half-width h, abscissa x) and sin(κt) = sin(mt)cos(hxt) + cos(mt)sin(hxt), with the
    /// LINEAR_POINTS·(p/2+1) values at hxt shared by all panels (error ~1e−16 of 1, as sin(κt)
    /// with κt rounded).
    fn fill_panels(&mut self, nodes: &Nodes, ts: &[f64], phi: &[(f64, f64)]) {
        let half = self.half;
        let offsets: Vec<(f64, f64)> = nodes
            .gx
            .iter()
            .flat_map(|&x| ts.iter().map(move |&t| (nodes.half * x * t).sin_cos()))
            .collect();
        for (pp, &m) in nodes.panels.iter().enumerate() {
            let centre: Vec<(f64, f64)> = ts.iter().map(|&t| (m * t).sin_cos()).collect();
            for g in 0..LINEAR_POINTS {
                let n = nodes.n_log + pp * LINEAR_POINTS + g;
                let (pr, pi) = phi[n];
                for (i, &(sm, cm)) in centre.iter().enumerate() {
                    let (so, co) = offsets[g * (half + 1) + i];
                    let (sn, cs) = (sm * co + cm * so, cm * co - sm * so);
                    self.lt_even[(n, i)] = pr * sn;
                    self.lt_even[(n, half + 1 + i)] = pi * cs;
                    self.lt_odd[(n, i)] = pr * cs;
                    self.lt_odd[(n, half + 1 + i)] = pi * sn;
                }
            }
        }
    }
}

impl LayerTerm {
    /// The matrix for the reduced `modes` (Φ = 1 + Σf̂/(b − ik)) at half-length `l`, thickness
    /// `thickness` = h′, Poisson's ratio `nu`, degree `p` (≥ 2).
    pub fn new(modes: &Modes, l: f64, thickness: f64, nu: f64, p: usize) -> LayerTerm {
        Self::with_rule(modes, l, thickness, nu, p, LogRule::production(modes, l))
    }

    /// [`LayerTerm::new`] with the log panels' rule `rule`: the nodes in κ, per node the Bessel
    /// factors of the orders and the left factors at the half rows ([`Factors::fill_nodes`], on
    /// the linear panels by the angle sums [`Factors::fill_panels`]), their products, the values at
    /// the Lobatto points ([`unfold`]) and their Chebyshev coefficients.
    fn with_rule(
        modes: &Modes,
        l: f64,
        thickness: f64,
        nu: f64,
        p: usize,
        rule: LogRule,
    ) -> LayerTerm {
        let (h_over_l, kappa_hi, orders) = kappa_range(l, thickness, p);
        let nodes = nodes(rule, kappa_hi, h_over_l, nu);
        let nn = nodes.kappa.len();
        let half = p / 2;
        let rows = 2 * (half + 1);
        let ts = lobatto_half(p);
        let (ne, no) = (orders.div_ceil(2), orders / 2);
        // node-major transposes (one contiguous column per node): bt_even[(k/2, n)] = c_{n,k},
        // bt_odd[((k−1)/2, n)] = γ_{n,k}; and the left factors [pr·sin; pi·cos], [pr·cos; pi·sin]
        // at the half rows, transposed (nodes × rows)
        let mut f = Factors {
            bt_even: pooled_zeros(ne, nn),
            bt_odd: pooled_zeros(no, nn),
            lt_even: pooled_zeros(nn, rows),
            lt_odd: pooled_zeros(nn, rows),
            half,
        };
        // orders beyond κ + 12κ^{1/3} + 30 carry nothing (J_n(κ) < 1e−20 there), and for small κ
        // far fewer: J_{k+1}(κ) ≤ (κ/2)^{k+1}/(k+1)! (below κ = 1 that bound is < 30 ≤ both others)
        let wanted: Vec<usize> = nodes
            .kappa
            .iter()
            .map(|&kappa| {
                let small = small_kappa_orders(kappa);
                if small < 30 {
                    small
                } else {
                    orders_needed(kappa).min(orders).min(small)
                }
            })
            .collect();
        let (phi, used_log) = f.fill_nodes(modes, l, &nodes, &wanted, &ts);
        if !nodes.panels.is_empty() {
            f.fill_panels(&nodes, &ts, &phi);
        }
        let xe = product(&f.bt_even, &f.lt_even, nodes.n_log, used_log.div_ceil(2));
        let xo = product(&f.bt_odd, &f.lt_odd, nodes.n_log, used_log / 2);
        for m in [f.bt_even, f.bt_odd, f.lt_even, f.lt_odd] {
            recycle(m);
        }
        let values = unfold(&xe, &xo, p, orders);
        // Chebyshev coefficients of the interpolant (DCT-I at the Lobatto points)
        LayerTerm {
            coef: dct(p) * &values,
            values,
            orders,
        }
    }

    /// [`LayerTerm::new`] as first written (one Bessel division per value, nodes × orders products
    /// over all nodes, one sine and cosine per node and point, one cosine per DCT entry): the
    /// straightforward reference of the tests.
    #[cfg(test)]
    pub(crate) fn reference(modes: &Modes, l: f64, thickness: f64, nu: f64, p: usize) -> LayerTerm {
        Self::with_rule_reference(modes, l, thickness, nu, p, LogRule::production(modes, l))
    }

    #[cfg(test)]
    fn with_rule_reference(
        modes: &Modes,
        l: f64,
        thickness: f64,
        nu: f64,
        p: usize,
        rule: LogRule,
    ) -> LayerTerm {
        let (h_over_l, kappa_hi, orders) = kappa_range(l, thickness, p);
        let nodes: Vec<(f64, f64)> = {
            let nd = nodes(rule, kappa_hi, h_over_l, nu);
            nd.kappa.into_iter().zip(nd.weight).collect()
        };
        let nn = nodes.len();
        let half = p / 2;
        let ts = lobatto_half(p);
        let (ne, no) = (orders.div_ceil(2), orders / 2);
        // B_even[n][k/2] = c_{n,k}, B_odd[n][(k−1)/2] = γ_{n,k}; left factors [pr·sin; pi·cos] and
        // [pr·cos; pi·sin] at the half rows
        let mut b_even = DMatrix::<f64>::zeros(nn, ne);
        let mut b_odd = DMatrix::<f64>::zeros(nn, no);
        let mut left_e = DMatrix::<f64>::zeros(2 * (half + 1), nn);
        let mut left_o = DMatrix::<f64>::zeros(2 * (half + 1), nn);
        // orders beyond κ + 12κ^{1/3} + 30 carry nothing (J_n(κ) < 1e−20 there), and for small κ
        // far fewer: J_{k+1}(κ) ≤ (κ/2)^{k+1}/(k+1)!
        let wanted: Vec<usize> = nodes
            .iter()
            .map(|&(kappa, _)| {
                orders_needed(kappa)
                    .min(orders)
                    .min(small_kappa_orders(kappa))
            })
            .collect();
        let mut js: Vec<Vec<f64>> = vec![Vec::new(); nn];
        for (chunk, (jc, wc)) in nodes
            .chunks(LANES)
            .zip(js.chunks_mut(LANES).zip(wanted.chunks(LANES)))
        {
            let xs: Vec<f64> = chunk.iter().map(|&(k, _)| k).collect();
            let nmax = wc.iter().copied().max().unwrap_or(1);
            bessel_j_lanes(&xs, nmax, jc);
        }
        for (n, &(kappa, w)) in nodes.iter().enumerate() {
            // Φ(κ/L)
            let kk = kappa / l;
            let (mut pr, mut pi) = (1.0, 0.0);
            for (f, b) in modes.f.iter().zip(&modes.b) {
                let d = b * b + kk * kk;
                pr += f * b / d;
                pi += f * kk / d;
            }
            let mut used = wanted[n];
            let j = &js[n];
            while used > 1 && j[used].abs() < 1e-22 {
                used -= 1;
            }
            let ww = PI * w;
            // (k+1)(−i)^k J_{k+1}: (−i)^k = 1, −i, −1, i
            for k in 0..used {
                let v = ww * (k + 1) as f64 * j[k + 1];
                match k % 4 {
                    0 => b_even[(n, k / 2)] = v,
                    1 => b_odd[(n, k / 2)] = -v,
                    2 => b_even[(n, k / 2)] = -v,
                    _ => b_odd[(n, k / 2)] = v,
                }
            }
            for (i, &t) in ts.iter().enumerate() {
                let (sn, cs) = (kappa * t).sin_cos();
                left_e[(i, n)] = pr * sn;
                left_e[(half + 1 + i, n)] = pi * cs;
                left_o[(i, n)] = pr * cs;
                left_o[(half + 1 + i, n)] = pi * sn;
            }
        }
        let xe = (&left_e * &b_even).transpose();
        let xo = (&left_o * &b_odd).transpose();
        let values = unfold(&xe, &xo, p, orders);
        // Chebyshev coefficients of the interpolant (DCT-I at the Lobatto points)
        LayerTerm {
            coef: dct_reference(p) * &values,
            values,
            orders,
        }
    }

    /// The layer term of degree p/2 (p even): the Lobatto points of p/2 are the even ones of p,
    /// t_{2i} = cos(πi/(p/2)), so only its DCT is new.
    pub fn halved(&self) -> LayerTerm {
        let p = self.values.nrows() - 1;
        let q = p / 2;
        let values = DMatrix::<f64>::from_fn(q + 1, self.orders, |i, k| self.values[(2 * i, k)]);
        LayerTerm {
            coef: dct(q) * &values,
            values,
            orders: self.orders,
        }
    }

    /// Chebyshev coefficients g_m of G for each column's H̃ coefficients (a_k = h_{k+1}), by one
    /// matrix product.
    pub fn apply_all(&self, hs: &[&[f64]]) -> Vec<Vec<f64>> {
        let h = DMatrix::<f64>::from_fn(self.orders, hs.len(), |k, c| {
            hs[c].get(k + 1).copied().unwrap_or(0.0)
        });
        let g = &self.coef * h;
        g.column_iter()
            .map(|c| c.iter().copied().collect())
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bessel_values() {
        // A&S Table 9.1 (10 digits).
        let j = bessel_j(1.0, 3);
        assert!((j[0] - 0.765_197_686_6).abs() < 1e-10 && (j[1] - 0.440_050_585_7).abs() < 1e-10);
        let j = bessel_j(10.0, 2);
        assert!((j[0] + 0.245_935_764_5).abs() < 1e-10 && (j[1] - 0.043_472_746_17).abs() < 1e-10);
    }
}

#[cfg(test)]
mod reference_tests {
    use super::*;
    use crate::contact::problem::CreepTerm;

    #[test]
    fn unit_sin_cos_matches_the_library() {
        // Taylor remainders ≤ 8e−18 plus a few ulp of rounding: 3e−16 absolute allowed
        let mut worst = 0.0_f64;
        for k in 0..=20_000 {
            let x = k as f64 / 20_000.0 * (1.0 - 1e-17) + 1e-300 * (k % 3) as f64;
            let (s, c) = sin_cos_unit(x);
            let (s0, c0) = x.sin_cos();
            worst = worst.max((s - s0).abs()).max((c - c0).abs());
        }
        assert!(worst < 3e-16, "{worst:e}");
        let (s, c) = sin_cos_unit(2.5);
        assert_eq!((s, c), 2.5_f64.sin_cos());
        println!("worst |difference| on [0, 1]: {worst:.1e}");
    }

    #[test]
    fn fast_build_matches_the_reference() {
        // The build (normalisation folded into the weight, node-major products split at κ = 1,
        // angle sums on the linear panels, DCT from 2p cosines) against the straightforward one:
        // the same sums in another order and sin(κt) by an angle sum, whose error is that of
        // rounding κt (≈ 1e−16·κt ≤ 1e−14 at κ ≤ 20L/h′ ≈ 200 here); measured ≤ 2e−15 of the largest
        // coefficient on these cases, 1e−13 allowed.
        let spectra: Vec<Vec<CreepTerm>> = vec![
            vec![],
            vec![CreepTerm { f: 3.0, b: 0.5 }],
            (0..12)
                .map(|k| {
                    let b = 10f64.powf(-8.0 + k as f64);
                    CreepTerm { f: 30.0 * b, b }
                })
                .collect(),
        ];
        let mut worst = 0.0_f64;
        for terms in &spectra {
            let m = Modes::new(terms);
            for (l, h) in [
                (0.5, 0.05),
                (0.5, 0.3),
                (2.0, 0.25),
                (0.05, 1.0),
                (5.0, 0.5),
            ] {
                for (nu, p) in [(0.5, 8), (0.3, 20), (0.0, 32)] {
                    let fast = LayerTerm::new(&m, l, h, nu, p);
                    let slow = LayerTerm::reference(&m, l, h, nu, p);
                    assert_eq!(fast.coef.shape(), slow.coef.shape());
                    let big = slow.coef.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
                    for (a, b) in fast.coef.iter().zip(slow.coef.iter()) {
                        worst = worst.max((a - b).abs() / big);
                        assert!(
                            (a - b).abs() <= 1e-13 * big,
                            "L {l} h {h} ν {nu} p {p}: {a} vs {b} (largest {big})"
                        );
                    }
                }
            }
        }
        println!("worst difference / largest coefficient: {worst:.1e}");
    }
}

#[cfg(test)]
mod quadrature_tests {
    use super::*;
    use crate::contact::problem::CreepTerm;

    #[test]
    fn log_rule_matches_a_denser_rule() {
        // The production rule (width 2, 14 points, κ_lo from the bound) against width 0.5, 16 points
        // and κ_lo a thousand times smaller, on spectra whose modes (poles of Φ) sit in the log
        // region, a thin and a thick cover (L/h′ = 0.05: R's own singularities at κ ~ L/h′ fall in
        // the log region too). Measured: ≤ 6e−13 of the largest coefficient (the former rule, width
        // 1 with 8 points and κ_lo = 1e−8·min(c_min, 1), was off by up to 2e−11); 3e−12 allowed.
        let spectra: Vec<Vec<CreepTerm>> = vec![
            vec![CreepTerm { f: 3.0, b: 0.5 }],
            (0..12)
                .map(|k| {
                    let b = 10f64.powf(-8.0 + k as f64);
                    CreepTerm { f: 30.0 * b, b }
                })
                .collect(),
        ];
        for terms in &spectra {
            let m = Modes::new(terms);
            for (l, h) in [(0.5, 0.3), (2.0, 0.25), (0.05, 1.0)] {
                let fast = LayerTerm::new(&m, l, h, 0.4, 16);
                let prod = LogRule::production(&m, l);
                let dense = LogRule {
                    width: 0.5,
                    points: 16,
                    lo: 1e-3 * prod.lo,
                };
                let slow = LayerTerm::with_rule(&m, l, h, 0.4, 16, dense);
                let big = slow.coef.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
                for (a, b) in fast.coef.iter().zip(slow.coef.iter()) {
                    assert!(
                        (a - b).abs() <= 3e-12 * big,
                        "L {l} h {h}: {a} vs {b} (largest {big})"
                    );
                }
            }
        }
    }
}

#[cfg(test)]
mod dct_tests {
    use super::*;
    use crate::special::chebyshev::lobatto_coefficients;

    #[test]
    fn layer_term_interpolant_matches_the_shared_dct() {
        // the inlined DCT must give `lobatto_coefficients` of the same values (to rounding)
        let m = Modes::new(&[crate::contact::problem::CreepTerm { f: 3.0, b: 0.5 }]);
        let lt = LayerTerm::new(&m, 0.5, 0.3, 0.3, 12);
        // values of the interpolant of order k at the Lobatto points, back from the coefficients
        for k in [0usize, 3, 7] {
            let col: Vec<f64> = (0..=12)
                .map(|i| {
                    let t = (PI * i as f64 / 12.0).cos();
                    let c: Vec<f64> = lt.coef.column(k).iter().copied().collect();
                    crate::special::chebyshev::clenshaw(&c, t)
                })
                .collect();
            let again = lobatto_coefficients(&col);
            for (a, c) in again.iter().zip(lt.coef.column(k).iter()) {
                assert!((a - c).abs() < 1e-12 * (1.0 + a.abs()), "{a} vs {c}");
            }
        }
    }
}
