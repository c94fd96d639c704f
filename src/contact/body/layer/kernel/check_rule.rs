//! The layer kernel's hat averages for the contact checks: the same A(j) = A_HS(j) − A_D(j) as
//! [`LayerKernel::hat_averages`] (module doc of [`super`]), to ~1e−9 of the largest difference
//! A(j) − A(0) instead of rounding, on a third to a quarter of the correction's quadrature nodes.
//!
//! Input: m and Δ (offsets j = −m…m); output: A(j) up to one constant, for
//! [`crate::contact::body::layer::collocation::contact_checks`] (the closing checks of the spectral
//! and the hat-scheme layer solves; their thresholds are 1e−3 of the indentation, so ~1e−6 of the
//! kernel is ample).
//!
//! # The correction's rule
//! A_D(j) = −∫₀^∞ (R(kh′)/k)·Re[Φ(k)·Δ·(sinc²(kΔ/2)e^{ikjΔ} − 1)] dk (eq. A_D of the parent module
//! doc; X = (m+1)Δ the largest |x| = |jΔ|, s = 1 + Σrᵢ = Φ(0) = J∞/J_g, rᵢ = fᵢ/bᵢ).
//!
//! - **Lower cut from a bound (C1).** With z = sinc²e^{ikx} − 1 = (e^{ikx} − 1) + (sinc² − 1)e^{ikx},
//!   |Re Φz| ≤ Im Φ·k|x| + Re Φ·k²x²/2 + |Φ|·k²Δ²/12, R ≤ 1, |Φ| ≤ s, and
//!   ∫₀^{k₀} Im Φ dk = Σ(fᵢ/2)ln(1 + k₀²/bᵢ²) ≤ k₀Σrᵢ/2 (ln(1 + y²) ≤ y), so the part below k₀ is at
//!   most Δ·s·(y/2 + 7y²/24), y = k₀X. The rule cuts at k₀ = 1e−12/(sX): ≤ 1e−12·Δ, far below the
//!   differences A(j) − A(0) ≳ Δ. The collocation rule's cut 1e−8·min(bᵢ, 1/X, 1/h′) reaches
//!   k ≈ 1e−20 on a spectrum down to b = 1e−12: 12 decades of nodes that carry nothing.
//! - **Low region (C2)**, k ∈ [k₀, k_mid], k_mid = min(1/X, k_hi): 14-point Gauss–Legendre panels of
//!   width 2 in v = ln k (the layer term's rule, `spectral::layer_term`): the poles of Φ at −ibᵢ lie
//!   π/2 off the real v axis, e^{ikx} with kX ≤ 1 is entire, so the ellipse parameter for the
//!   half-width 1 is π/2 + √(π²/4 + 1) ≈ 3.4 and the error ≲ 3.4^{−28} ≈ 1e−15 of a panel's part
//!   (R's complex singularities at |k| ~ 1/h′ fall here for thick covers; measured in the test).
//! - **Linear region (C3)**, k ∈ [k_mid, k_hi], k_hi = 20/h′ (R(20) ≈ (4·20²/κ)e^{−40} ≤ 7e−15;
//!   the tail beyond is ≤ 2Δ·s·R(20)/40): 16-point panels of width ≤ min(8/X, 1/h′), i.e. at most
//!   eight radians of e^{ikx} (Gauss error for e^{iωu}, ω = 4, on 16 points: (eω/32)^{32} ≈ 1e−15)
//!   and half-width ½ in t = kh′ against R's singularities at |Im t| ≳ ½ (ellipse ≥ 1 + √2,
//!   2.4^{−32} ≈ 6e−13). The poles of slow modes near k = 0 lie beyond the first panel's end k_mid:
//!   ellipse ≥ 2, ~2e−10 of their part. e^{ikjΔ} comes by rotation in j, four nodes side by side
//!   (independent multiply-add chains).
//! - **Low region by moments (C4).** There |k·jΔ| ≤ kX ≤ 1, so with z = jΔ,
//!   sinc²e^{ikz} − 1 = (sinc² − 1) + sinc²·Σ_{n≥1}(ikz)ⁿ/n! and the low nodes' part of A_D(j) is
//!   −Σ wΔ·Re[Φ(sinc² − 1)] − Σₙ Re[(iz)ⁿMₙ]/n! with the moments Mₙ = Σ wΔ·Φ·sinc²·kⁿ: cost
//!   (nodes + 2m + 1)·n_max instead of nodes·(2m + 1). Cut at n = 22 (1/23! ≈ 4e−23 of Σ|wΔΦ|;
//!   no term exceeds Σ|wΔΦ|, so rounding stays ~e·ε of it).
//!
//! Measured against the collocation rule (test `check_rule_matches_the_collocation_rule` of the
//! parent module): ≤ 1e−8 of the largest difference allowed.
//!
//! # The half-space part: slow and fast terms summed by class
//! [`Kernel::hat_averages`] evaluates one special function per term and offset (h or h₂ of the
//! kernel bracket, docs/MATH.md §2): for 30 terms at the 193 offsets of a 64-interval check, two
//! thirds of the check's time. Per term (H = bᵢΔ, c = (fᵢ/bᵢ)Δ) its hat average is c·S(k) with
//! S(k) = Δ²h₂(kH)/H² (Δ² the second difference in k). Terms far from the grid's scales are summed
//! by class, at a cost independent of their number:
//!
//! - **Slow terms (H1)**, (m+1)H ≤ 2: the series h₂(x) = Σ_{n≥3}(xⁿ/n!)(Hₙ − γ − ln|x|) (Hₙ the
//!   harmonic numbers; module `special::kernel_bracket`, which the exact averages sum at every
//!   offset there) at x = kH gives S(k) = Σ_{n≥3}(H^{n−2}/n!)[(Hₙ − γ − ln H)·Δ²kⁿ − Δ²(kⁿln|k|)],
//!   so Σ over the slow terms is Σₙ[αₙΔ²kⁿ − βₙΔ²(kⁿln|k|)] with αₙ = Σc·H^{n−2}(Hₙ − γ − ln H)/n!,
//!   βₙ = Σc·H^{n−2}/n!. With |kH| ≤ 2 the term n is ≤ c·n²·ln(m)·2^{n−2}/n!: cut after n = 27
//!   (≤ 1e−18·c). Δ²kⁿ is summed by a recurrence of positive terms (no cancellation);
//!   Δ²(kⁿln|k|) loses ~ε·k² of its size.
//! - **Fast terms (H2)**, H ≥ 20: the split form of `Kernel::hat_averages`,
//!   S(k) = D(k) + ln H + γ − 3/2 + E(k)/H + Δ²h(kH)/H², with h(x) = ln|x| + γ + g(x) and, for
//!   |x| ≥ 2H ≥ 40 (|k| ≥ 3), the asymptotic series g(x) ~ Σₙ(−1)ⁿn!/x^{n+1} (A&S 5.1.51; the same
//!   series for x < 0, g = −e^{x}Ei(−x)) cut at n = 40 (error ≤ 40!/40⁴¹ ≈ 2e−18). So Σ over the fast
//!   terms is C₀D(k) + C₀′ + C₁E(k) + C₂Δ²ln|k| + Σₙ(−1)ⁿn!·Gₙ·Δ²k^{−n−1} with C₀ = Σc,
//!   C₀′ = Σc(ln H + γ − 3/2), C₁ = Σc/H, C₂ = Σc/H², Gₙ = Σc·H^{−n−3}; at |k| ≤ 2 each fast term
//!   is evaluated as in `Kernel::hat_averages`.
//! - **Terms between (H3)**, 1/(m+1) < H < 20 (about 5 of 30 terms over 24 decades): the split form
//!   as in `Kernel::hat_averages`, but h(x) at 3H ≤ |x| ≤ (m+1)H (beyond the series' range
//!   |x| < 2 as well) from Chebyshev interpolants of degree 32 in u = ln|x|, one for each sign of
//!   x, instead of one continued fraction or Taylor piece per offset (each costs 0.1–0.4 µs; the
//!   fraction has 140/x + 12 levels). h(e^u) = u + γ + e^{e^u}E1(e^u) is analytic in the strip
//!   |Im u| < π (E1's cut) and h(−e^u) = u + γ − e^{−e^u}Ei(e^u) is entire in u, while the range
//!   is at most ln((m+1)/3) ≤ 4.2 long (m ≤ 192): Bernstein ellipse ≥ π/2.1 + √(1 + (π/2.1)²) ≈
//!   3.3, error ≲ 3.3^{−32} ≈ 3e−17 of |h|, amplified by 4/H² ≤ 4(m+1)² in Δ²h/H².
//!
//! Measured against `Kernel::hat_averages` (test `half_space_part_matches_the_exact_averages`):
//! ≤ 1e−10 of the largest difference allowed.

use super::LayerKernel;
use crate::contact::body::layer::compliance::layer_defect;
use crate::contact::numerics::kernel::{
    add_term_hat_averages_with, half_second_diff_k2logk, second_diff_klogk, split_from, Kernel,
};
use crate::special::gauss_legendre::gauss_legendre;
use crate::special::{kernel_bracket, EULER_GAMMA};

/// R(t) ≤ 7e−15 beyond t = kh′ = 20 (C3).
const T_CHECK: f64 = 20.0;
/// Bound of the neglected low part relative to Δ (C1).
const LOW_CUT: f64 = 1e-12;
/// Last order of the low region's Taylor series in kz, |kz| ≤ 1: 1/23! ≈ 4e−23 (C4).
const LOW_ORDER: usize = 22;

impl LayerKernel {
    /// [`Self::hat_averages`] to ~1e−9 of the largest difference for the contact checks (module
    /// doc of [`check_rule`](self)), j = −m…m (index j + m), up to one constant.
    pub(crate) fn check_hat_averages(&self, m: usize, delta: f64) -> Vec<f64> {
        let mut a = half_space_check_averages(&self.half_space, m, delta);
        let x_max = (m as f64 + 1.0) * delta;
        let nodes = self.check_nodes(x_max);
        let (low, linear): (Vec<_>, Vec<_>) = nodes.into_iter().partition(|n| n.2);
        let d = self.linear_correction(m, delta, &linear);
        let d_low = self.low_correction(m, delta, &low);
        for ((x, y), z) in a.iter_mut().zip(d).zip(d_low) {
            *x -= y + z;
        }
        a
    }

    /// The linear region's part of A_D(j) (C3): Σ_nodes wΔ·sinc²·Re[Φe^{ikjΔ}] (the "−1" dropped,
    /// a constant), e^{ikjΔ} by rotation in j as in `correction_on`, four nodes side by side so
    /// that their rotation chains overlap (one chain alone waits on each step's latency).
    fn linear_correction(&self, m: usize, delta: f64, nodes: &[(f64, f64, bool)]) -> Vec<f64> {
        const W: usize = 4;
        let mut plus = vec![0.0; m + 1]; // j ≥ 0
        let mut minus = vec![0.0; m + 1]; // −j
        for chunk in nodes.chunks(W) {
            // per lane: cr = −wΔ·sinc²·Re Φ, ci = −wΔ·sinc²·Im Φ, the rotation by kΔ
            let (mut cr, mut ci) = ([0.0_f64; W], [0.0_f64; W]);
            let (mut rs, mut rc) = ([0.0_f64; W], [1.0_f64; W]);
            for (q, &(k, w, _)) in chunk.iter().enumerate() {
                let (pr, pi) = self.phi(k);
                let (_, sinc) = half_sinc(k, delta);
                let c = -w * delta * sinc * sinc;
                cr[q] = c * pr;
                ci[q] = c * pi;
                let (a, b) = (k * delta).sin_cos();
                rs[q] = a;
                rc[q] = b;
            }
            let (mut sn, mut co) = ([0.0_f64; W], [1.0_f64; W]);
            for j in 0..=m {
                let (mut re, mut im) = (0.0, 0.0);
                for q in 0..W {
                    re += cr[q] * co[q];
                    im += ci[q] * sn[q];
                    let ns = sn[q] * rc[q] + co[q] * rs[q];
                    co[q] = co[q] * rc[q] - sn[q] * rs[q];
                    sn[q] = ns;
                }
                plus[j] += re - im;
                minus[j] += re + im;
            }
        }
        let mut a = vec![0.0; 2 * m + 1];
        for j in 0..=m {
            a[m + j] = plus[j];
            a[m - j] = minus[j];
        }
        a
    }

    /// The low region's part of A_D(j) (C4): with z = jΔ, kX ≤ 1 and sinc²e^{ikz} − 1 =
    /// (sinc² − 1) + sinc²Σ_{n≥1}(ikz)ⁿ/n!, A(j) = −Σ_nodes wΔ·Re[Φ(sinc² − 1)] −
    /// Σ_{n≥1} Re[(iz)ⁿ/n!·Mₙ], Mₙ = Σ_nodes wΔ·Φ·sinc²·kⁿ.
    fn low_correction(&self, m: usize, delta: f64, nodes: &[(f64, f64, bool)]) -> Vec<f64> {
        let mut moments = [(0.0_f64, 0.0_f64); LOW_ORDER + 1];
        let mut constant = 0.0;
        for &(k, w, _) in nodes {
            let (pr, pi) = self.phi(k);
            let (u, sinc) = half_sinc(k, delta);
            // sinc² − 1 without cancellation (as in `correction_on`)
            let s2m1 = if u < 1e-2 {
                (-u * u / 6.0 + u.powi(4) / 120.0) * (sinc + 1.0)
            } else {
                sinc * sinc - 1.0
            };
            let c = -w * delta;
            constant += c * pr * s2m1;
            let (mut re, mut im) = (c * pr * sinc * sinc, c * pi * sinc * sinc);
            for mn in moments.iter_mut().skip(1) {
                re *= k;
                im *= k;
                mn.0 += re;
                mn.1 += im;
            }
        }
        let mi = m as i64;
        (-mi..=mi)
            .map(|j| {
                let z = j as f64 * delta;
                // (iz)ⁿ/n! = (re, im) by recurrence; Re[(a + ib)(mr + i·mi)] = a·mr − b·mi
                let (mut a, mut b) = (1.0_f64, 0.0_f64);
                let mut s = constant;
                for (n, mn) in moments.iter().enumerate().skip(1) {
                    let f = z / n as f64;
                    let na = -b * f;
                    b = a * f;
                    a = na;
                    s += a * mn.0 - b * mn.1;
                }
                s
            })
            .collect()
    }

    /// Quadrature nodes (k, weight·R(kh′)/k, low region?) of rules C1–C3 (module doc).
    fn check_nodes(&self, x_max: f64) -> Vec<(f64, f64, bool)> {
        let h = self.thickness;
        let k_hi = T_CHECK / h;
        let k_mid = (1.0 / x_max).min(k_hi);
        let s = 1.0 + self.terms.iter().map(|t| t.f / t.b).sum::<f64>();
        let k_lo = (LOW_CUT / (s * x_max)).min(0.5 * k_mid);
        let mut out = Vec::new();
        let mut panels = |a: f64, b: f64, width: f64, points: usize, log: bool| {
            let (gx, gw) = gauss_legendre(points);
            let np = ((b - a) / width).ceil().max(1.0) as usize;
            for p in 0..np {
                let lo = a + (b - a) * p as f64 / np as f64;
                let hi = a + (b - a) * (p + 1) as f64 / np as f64;
                let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
                for (x, w) in gx.iter().zip(&gw) {
                    let u = mid + half * x;
                    let (k, dk) = if log {
                        (u.exp(), u.exp() * half * w)
                    } else {
                        (u, half * w)
                    };
                    out.push((k, dk * layer_defect(k * h, self.poisson) / k, log));
                }
            }
        };
        panels(k_lo.ln(), k_mid.ln(), 2.0, 14, true);
        if k_hi > k_mid {
            panels(k_mid, k_hi, (8.0 / x_max).min(1.0 / h), 16, false);
        }
        out
    }
}

/// Slow terms: (m+1)H at most this (H1).
const SLOW_H_TIMES_M: f64 = 2.0;
/// Last order n of the slow terms' series (H1).
const SLOW_ORDER: usize = 27;
/// Fast terms: H at least this (H2).
const FAST_H: f64 = 20.0;
/// Last order n of the fast terms' asymptotic series of g (H2).
const FAST_ORDER: usize = 40;

/// The half-space kernel's hat averages A_HS(k), k = −m…m (index k + m), as
/// [`Kernel::hat_averages`] with the slow and fast terms summed by class (module doc, H1–H2).
pub(crate) fn half_space_check_averages(kernel: &Kernel, m: usize, delta: f64) -> Vec<f64> {
    let mi = m as i64;
    let ln_d = delta.ln();
    // D(k) at k = 0…m (even in k) and ln k at k = 0…m + 1 (0 at 0), shared by all classes
    let tables = Tables {
        d: (0..=mi).map(half_second_diff_k2logk).collect(),
        ln: (0..=mi + 1)
            .map(|k| if k == 0 { 0.0 } else { (k as f64).ln() })
            .collect(),
    };
    let mut a: Vec<f64> = (-mi..=mi)
        .map(|k| delta * (tables.d[k.unsigned_abs() as usize] + ln_d) - 1.5 * delta)
        .collect();
    let mut alpha = [0.0; SLOW_ORDER + 1];
    let mut beta = [0.0; SLOW_ORDER + 1];
    let (mut slow, mut fast) = (false, Vec::new());
    for t in kernel.terms() {
        let big_h = t.b * delta;
        let c = (t.f / t.b) * delta;
        if big_h * (m as f64 + 1.0) <= SLOW_H_TIMES_M {
            // H1: αₙ, βₙ (harmonic numbers Hₙ, H^{n−2}/n! by recurrence)
            slow = true;
            let l = EULER_GAMMA + big_h.ln();
            let (mut harmonic, mut pw) = (1.5, 0.5); // H₂ and H^{n−2}/n! at n = 2
            for n in 3..=SLOW_ORDER {
                harmonic += 1.0 / n as f64;
                pw *= big_h / n as f64; // H^{n−2}/n!
                alpha[n] += c * pw * (harmonic - l);
                beta[n] += c * pw;
            }
        } else if big_h >= FAST_H {
            fast.push((c, big_h));
        } else {
            add_middle_term(t, m, delta, &mut a);
        }
    }
    if slow {
        add_slow(&alpha, &beta, m, &tables, &mut a);
    }
    if !fast.is_empty() {
        add_fast(&fast, m, &tables, &mut a);
    }
    a
}

/// D(k) = ½Δ²(k²ln|k|) at k = 0…m and ln k at k = 0…m + 1 (0 at 0).
struct Tables {
    d: Vec<f64>,
    ln: Vec<f64>,
}

/// Chebyshev degree of the interpolants of h in ln|x| (H3).
const MIDDLE_DEGREE: usize = 32;

/// One term between the classes (H3): `Kernel::hat_averages`' split form with h(x) at
/// 3H ≤ |x| ≤ (m+1)H (and beyond the series' range |x| ≥ 2) from its Chebyshev interpolants in
/// u = ln|x| on each side, the rest evaluated.
fn add_middle_term(t: &crate::contact::problem::CreepTerm, m: usize, delta: f64, a: &mut [f64]) {
    let big_h = t.b * delta;
    let from = (split_from(big_h) - 1).max(3) as f64 * big_h;
    let to = (m as f64 + 1.0) * big_h;
    if to <= from {
        add_term_hat_averages_with(t, m, delta, a, &kernel_bracket);
        return;
    }
    let (ua, ub) = (from.ln(), to.ln());
    let (mid, half) = (0.5 * (ua + ub), 0.5 * (ub - ua));
    let n = MIDDLE_DEGREE;
    let cosines: Vec<f64> = (0..2 * n)
        .map(|q| (std::f64::consts::PI * q as f64 / n as f64).cos())
        .collect();
    // coefficients from the values at the Lobatto points u_j = mid + half·cos(πj/n) (DCT-I)
    let interpolant = |sign: f64| -> Vec<f64> {
        let v: Vec<f64> = (0..=n)
            .map(|j| kernel_bracket(sign * (mid + half * cosines[j]).exp()))
            .collect();
        (0..=n)
            .map(|k| {
                let mut s = 0.0;
                for (j, vj) in v.iter().enumerate() {
                    let w = if j == 0 || j == n { 0.5 } else { 1.0 };
                    s += w * vj * cosines[(j * k) % (2 * n)];
                }
                let edge = if k == 0 || k == n { 0.5 } else { 1.0 };
                edge * 2.0 / n as f64 * s
            })
            .collect()
    };
    let (plus, minus) = (interpolant(1.0), interpolant(-1.0));
    let bracket = |x: f64| {
        let ax = x.abs();
        if ax < 0.999_999 * from {
            return kernel_bracket(x);
        }
        let c = if x > 0.0 { &plus } else { &minus };
        crate::special::chebyshev::clenshaw(c, ((ax.ln() - mid) / half).clamp(-1.0, 1.0))
    };
    add_term_hat_averages_with(t, m, delta, a, &bracket);
}

/// Σₙ[αₙΔ²kⁿ − βₙΔ²(kⁿln|k|)] for k = −m…m (H1).
fn add_slow(alpha: &[f64], beta: &[f64], m: usize, tables: &Tables, a: &mut [f64]) {
    let mi = m as i64;
    let lnk = |j: i64| tables.ln[j.unsigned_abs() as usize];
    for (idx, ak) in a.iter_mut().enumerate() {
        let k = idx as i64 - mi;
        // at |k|: Δ²kⁿ = 2eₙ, eₙ = ((k+1)ⁿ + (k−1)ⁿ)/2 − kⁿ, by eₙ₊₁ = k·eₙ + dₙ,
        // dₙ₊₁ = k·dₙ + eₙ + kⁿ (dₙ = ((k+1)ⁿ − (k−1)ⁿ)/2): all terms ≥ 0, no cancellation; at −|k|
        // the sign (−1)ⁿ
        let kf = k.unsigned_abs() as f64;
        let sign_k = if k < 0 { -1.0 } else { 1.0 };
        let (mut e, mut d, mut pk) = (1.0, 2.0 * kf, kf * kf); // n = 2: e = 1, d = 2k, kⁿ = k²
        let (l0, l1, l2) = (lnk(k - 1), lnk(k), lnk(k + 1));
        let (x0, x1, x2) = ((k - 1) as f64, k as f64, (k + 1) as f64);
        let (mut p0, mut p1, mut p2) = (x0 * x0, x1 * x1, x2 * x2);
        let mut sg = 1.0; // (±1)ⁿ
        let mut s = 0.0;
        for n in 3..alpha.len() {
            let e_next = kf * e + d;
            d = kf * d + e + pk;
            e = e_next;
            pk *= kf;
            sg *= sign_k;
            p0 *= x0;
            p1 *= x1;
            p2 *= x2;
            s += alpha[n] * 2.0 * sg * e - beta[n] * (p2 * l2 - 2.0 * p1 * l1 + p0 * l0);
        }
        *ak += s;
    }
}

/// The fast terms (c, H) summed by class at |k| ≥ 3, each evaluated at |k| ≤ 2 (H2).
fn add_fast(fast: &[(f64, f64)], m: usize, tables: &Tables, a: &mut [f64]) {
    let mi = m as i64;
    let (mut c0, mut c0p, mut c1, mut c2) = (0.0, 0.0, 0.0, 0.0);
    let mut g = [0.0; FAST_ORDER + 1];
    for &(c, h) in fast {
        c0 += c;
        c0p += c * (h.ln() + EULER_GAMMA - 1.5);
        c1 += c / h;
        c2 += c / (h * h);
        let mut p = c / (h * h * h); // c·H^{−n−3}
        for gn in g.iter_mut() {
            *gn += p;
            p /= h;
        }
    }
    let ln_abs = |j: i64| {
        if j == 0 {
            0.0
        } else {
            (j.unsigned_abs() as f64).ln()
        }
    };
    for (idx, ak) in a.iter_mut().enumerate() {
        let k = idx as i64 - mi;
        if k.abs() <= 2 {
            for &(c, h) in fast {
                let bh = |j: i64| kernel_bracket(j as f64 * h);
                let dh = bh(k + 1) - 2.0 * bh(k) + bh(k - 1);
                *ak += c
                    * (half_second_diff_k2logk(k)
                        + (h.ln() + EULER_GAMMA - 1.5)
                        + second_diff_klogk(k) / h
                        + dh / (h * h));
            }
            continue;
        }
        let mut s = c0 * tables.d[k.unsigned_abs() as usize]
            + c0p
            + c1 * second_diff_klogk(k)
            + c2 * (ln_abs(k + 1) - 2.0 * ln_abs(k) + ln_abs(k - 1));
        // Σₙ(−1)ⁿn!·Gₙ·Δ²k^{−n−1}, stopped once a term is below 1e−18 of the sum
        let (r0, r1, r2) = (1.0 / (k - 1) as f64, 1.0 / k as f64, 1.0 / (k + 1) as f64);
        let (mut q0, mut q1, mut q2) = (r0, r1, r2); // k^{−n−1}
        let mut fact = 1.0; // (−1)ⁿn!
        for (n, gn) in g.iter().enumerate() {
            if n > 0 {
                fact *= -(n as f64);
                q0 *= r0;
                q1 *= r1;
                q2 *= r2;
            }
            let term = fact * gn * (q2 - 2.0 * q1 + q0);
            s += term;
            if n >= 2 && term.abs() <= 1e-18 * s.abs() {
                break;
            }
        }
        *ak += s;
    }
}

/// u = kΔ/2 and sinc u = sin u/u (its Taylor form below u = 1e−4, where 1 − u²/6 is exact to
/// rounding): the hat's transform factor of both correction regions.
fn half_sinc(k: f64, delta: f64) -> (f64, f64) {
    let u = 0.5 * k * delta;
    let sinc = if u < 1e-4 {
        1.0 - u * u / 6.0
    } else {
        u.sin() / u
    };
    (u, sinc)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::problem::CreepTerm;

    #[test]
    fn half_space_part_matches_the_exact_averages() {
        // The classes H1–H2 (slow terms by their series, fast ones by the asymptotic series of g)
        // against `Kernel::hat_averages` term by term: differences A(k) − A(0) relative to the
        // largest, for one term in each class and between, 30 terms over 24 decades and 60 over
        // 40, on 64- and 128-interval checks (m = 96, 192) and contact lengths 0.1…10. Both
        // evaluate the same closed forms, the series cut at ≤ 1e−16 of a term: 1e−10 allowed
        // (the loss of Δ²(kⁿln|k|) is ε·k², the interpolants' error of h is amplified by 4/H²).
        // Measured: ≤ 3.2e−11.
        let spectra: Vec<Vec<CreepTerm>> = vec![
            vec![CreepTerm { f: 10.0, b: 1.0 }],
            vec![CreepTerm { f: 1e-6, b: 1e-5 }],
            vec![CreepTerm { f: 1e5, b: 1e4 }],
            vec![CreepTerm { f: 100.0, b: 10.0 }],
            vec![CreepTerm { f: 300.0, b: 100.0 }],
            vec![CreepTerm { f: 3e3, b: 1e3 }],
            crate::contact::body::layer::spectral::spread_terms(30, 24.0),
            crate::contact::body::layer::spectral::spread_terms(60, 40.0),
        ];
        let mut worst = 0.0_f64;
        for terms in &spectra {
            let k = Kernel::new(terms).unwrap();
            for (n, lambda) in [(64, 0.1), (64, 1.0), (128, 1.0), (64, 10.0)] {
                let m = n + n / 2;
                let delta = lambda / n as f64;
                let exact = k.hat_averages(m, delta);
                let fast = half_space_check_averages(&k, m, delta);
                let big = exact
                    .iter()
                    .fold(0.0_f64, |a, v| a.max((v - exact[m]).abs()));
                for (x, y) in exact.iter().zip(&fast) {
                    let d = ((x - exact[m]) - (y - fast[m])).abs() / big;
                    worst = worst.max(d);
                    assert!(
                        d <= 1e-10,
                        "{} terms, λ {lambda}, n {n}: {d:e}",
                        terms.len()
                    );
                }
            }
        }
        println!("worst difference / largest: {worst:.1e}");
    }

    /// The gap of `contact_checks` at the nodes outside the contact, on the exact kernel averages
    /// (`LayerKernel::hat_averages`, the collocation's rule): the reference of the checks' rule.
    fn gaps_on_exact_kernel(
        kernel: &LayerKernel,
        sol: &crate::contact::problem::DimensionlessSolution,
    ) -> f64 {
        let n = sol.n;
        let ext = n / 2;
        let h = sol.lambda / n as f64;
        let m = n + ext;
        let a = kernel.hat_averages(m, h);
        let at = |k: i64| a[(k + m as i64) as usize];
        let s = |i: i64| -> f64 {
            let x = i as f64 * h;
            let v: f64 = (1..n)
                .map(|j| sol.pressure[j] * (at(-(j as i64)) - at(i - j as i64)))
                .sum();
            v - (x * sol.beta - 0.5 * x * x)
        };
        let depth = sol.beta * sol.beta / 2.0;
        (-(ext as i64)..0)
            .chain((n as i64 + 1)..=(n + ext) as i64)
            .map(s)
            .fold(f64::INFINITY, f64::min)
            / depth
    }

    #[test]
    fn checks_on_the_check_rule_match_the_exact_kernel_and_flag_wrong_solutions() {
        // `contact_checks` (64 intervals, as the spectral solver runs them) on the check rule
        // against the same gap on the exact kernel averages, for spectral answers on one term and
        // 30 terms over 24 decades, thin and thick covers, ν = 0.3 and ½: the kernels differ by
        // ≤ 6e−11 of their largest difference (tests above), which moves the gap by about that
        // times Σ|Qⱼ|·Δ/(β²/2) ~ 1: 1e−8 of the indentation allowed, five orders inside the
        // warning threshold 1e−3. A solution with β 5 % too large (the roll sinks deeper: it
        // penetrates ahead of the contact) and one with a negative node pressure must be flagged
        // (ratio < −1e−3) on both kernels.
        use crate::contact::body::layer::collocation::contact_checks;
        use crate::contact::body::layer::spectral::{solve_spectral_at_load, SpectralSettings};
        let thirty = crate::contact::body::layer::spectral::spread_terms(30, 24.0);
        let mut worst = 0.0_f64;
        for terms in [vec![CreepTerm { f: 10.0, b: 1.0 }], thirty] {
            for (h, nu) in [(0.3, 0.5), (3.0, 0.3), (30.0, 0.5)] {
                let a = solve_spectral_at_load(&terms, 0.25, h, nu, &SpectralSettings::default())
                    .unwrap()
                    .expect("accepted");
                let kernel = LayerKernel::new(&terms, h, nu).unwrap();
                let mut d = a.solution.clone();
                d.n = 64;
                d.xi = d.xi.iter().step_by(2).copied().collect();
                d.pressure = d.pressure.iter().step_by(2).copied().collect();
                let (q, g) = contact_checks(&kernel, &d).unwrap();
                let g_ref = gaps_on_exact_kernel(&kernel, &d);
                worst = worst.max((g - g_ref).abs());
                assert!(
                    (g - g_ref).abs() <= 1e-8 && g > 0.0 && q >= 0.0,
                    "{} terms, h′ {h}: gap {g:e} vs {g_ref:e}",
                    terms.len()
                );
                let mut deep = d.clone();
                deep.beta *= 1.05;
                let (_, g_deep) = contact_checks(&kernel, &deep).unwrap();
                assert!(g_deep < -1e-3 && gaps_on_exact_kernel(&kernel, &deep) < -1e-3);
                let mut neg = d.clone();
                let max_q = neg.pressure.iter().cloned().fold(0.0, f64::max);
                neg.pressure[10] = -0.01 * max_q;
                assert!(contact_checks(&kernel, &neg).unwrap().0 < -1e-3);
            }
        }
        println!("worst gap difference / indentation: {worst:.1e}");
    }
}
