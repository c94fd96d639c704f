//! Mode reduction of the `auto` scheme: which retardation modes a scene needs.
//!
//! Input: creep terms (fᵢ, bᵢ), the contact length λ and error budgets; output: [`Reduction`] (kept,
//! lumped and dropped modes, the rescaled problem and the estimated errors).
//!
//! With L = λ/2, cᵢ = bᵢL (contact half-time over τᵢ), rᵢ = fᵢ/bᵢ = Jᵢ/J_g:
//! - **Fast modes (cᵢ ≫ 1) are lumped into the glassy compliance.** For bξ → ∞ the kernel term
//!   (fᵢ/bᵢ)h(bᵢξ) → (fᵢ/bᵢ)(ln|ξ| + const) (MATH.md §2), so K → s·ln|ξ| + Σ_kept, s = 1 + Σ_fast rᵢ;
//!   dividing eq. 3.25 by s gives the same problem for Q̂ = sQ′ with f̂ᵢ = fᵢ/s (β, λ and ρF/N are
//!   unchanged, N′ = N̂/s). Dropping such a mode instead would miss its whole compliance.
//!   The error is the mode's boundary layer. Measured on the exact one-term solution (λ fixed, c from
//!   10 to 1e6, r = 1 and 1000): ρF/N/λ → r/(2(1+r)c) and N′(1+r) − 1 → r/((1+r)c) to < 1 % for c ≥ 30.
//! - **Slow modes (μᵢ = (1+rᵢ)cᵢ ≪ 1) are dropped.** Over the contact time they creep by only
//!   Jᵢ·t/τᵢ; their term in K is (fᵢ/bᵢ)h(bᵢξ) ≈ fᵢξ(1 − γ − ln|bᵢξ|) → 0 with bᵢ at fixed fᵢ/bᵢ.
//!   Lumping them would add their full compliance, which they never reach. Measured (same cases,
//!   c from 1e−8 to 1e−2): ρF/N/λ ≈ 0.26·r·c·ln(1/c) and 1 − N′ ≤ r·c·μ·(2 + ln(1/μ)).
//!
//! Each estimate is used with a safety factor 2 and only in its asymptotic range (fast: c ≥ 30,
//! slow: μ ≤ 0.05); modes between are always kept. Modes are lumped/dropped cheapest first while the
//! summed estimates stay inside the budgets. The estimates are per mode in isolation; a mode's
//! effect within a spectrum is smaller (the other modes add compliance), so the sums are upper bounds
//! in the tests we ran (tests/contact_auto.rs compares tol 1e−6 solves with tol 1e−9 solves).

use super::modes::Modes;
use super::CreepTerm;

/// The outcome of a mode selection at one λ.
#[derive(Debug, Clone)]
pub struct Reduction {
    /// Indices (into the input terms) of modes kept.
    pub kept: Vec<usize>,
    /// How many kept slow modes were merged into one (0 or ≥ 2).
    pub merged: usize,
    /// Merge threshold on μ used.
    pub merge_mu: f64,
    /// Modes in the reduced problem (merged slow modes count once).
    pub modes_used: usize,
    /// Indices of fast modes lumped into the glassy compliance.
    pub lumped: Vec<usize>,
    /// Indices of slow modes dropped.
    pub dropped: Vec<usize>,
    /// s = 1 + Σ_lumped fᵢ/bᵢ (Q′ = Q̂/s, N′ = N̂/s).
    pub scale: f64,
    /// The reduced problem (f̂ = f/s for kept modes).
    pub modes: Modes,
    /// Estimated absolute error of ρF/N divided by λ.
    pub friction_over_lambda_error: f64,
    /// Estimated relative error of N′ at this λ.
    pub load_error: f64,
}

/// (ρF/N/λ error, relative N′ error) of one mode, when its estimate applies.
type Estimate = Option<(f64, f64)>;

/// Per-mode error estimates when lumped (fast) and dropped (slow).
fn estimates(t: &CreepTerm, l: f64) -> (Estimate, Estimate) {
    let c = t.b * l;
    let r = t.f / t.b;
    let mu = (1.0 + r) * c;
    let fast = (c >= 30.0).then(|| {
        let q = r / (1.0 + r);
        (2.0 * q / (2.0 * c), 2.0 * q / c)
    });
    let slow = (mu <= 0.05).then(|| {
        let fr = 2.0 * 0.3 * r * c * (1.0 + (1.0 / c).ln());
        let ld = 2.0 * r * c * mu * (2.0 + (1.0 / mu).ln());
        (fr, ld)
    });
    (fast, slow)
}

/// Select modes at contact length λ within the budgets (absolute on ρF/N/λ, relative on N′).
///
/// Kept slow modes with μ ≤ `merge_mu` are merged into one (see the body); the caller picks
/// `merge_mu` = min(0.05, 1e−14/tol): solving them separately would lose ~1e−16/μ relative, more than
/// 1 % of the tolerance below that μ.
pub fn select(
    terms: &[CreepTerm],
    lambda: f64,
    fr_budget: f64,
    load_budget: f64,
    merge_mu: f64,
) -> Reduction {
    let l = 0.5 * lambda;
    // candidates: (cost measure, index, is_fast, fr error, load error)
    let mut cand: Vec<(f64, usize, bool, f64, f64)> = Vec::new();
    for (i, t) in terms.iter().enumerate() {
        if t.f <= 0.0 {
            continue;
        }
        let (fast, slow) = estimates(t, l);
        if let Some((e_fr, e_ld)) = fast {
            cand.push((
                (e_fr / fr_budget).max(e_ld / load_budget),
                i,
                true,
                e_fr,
                e_ld,
            ));
        } else if let Some((e_fr, e_ld)) = slow {
            cand.push((
                (e_fr / fr_budget).max(e_ld / load_budget),
                i,
                false,
                e_fr,
                e_ld,
            ));
        }
    }
    cand.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (mut sum_fr, mut sum_ld) = (0.0, 0.0);
    let mut lumped = Vec::new();
    let mut dropped = Vec::new();
    // Hard cap: a mode with c > C_MAX needs ~√(83μ) > 3e4 Chebyshev terms; it is lumped whatever the
    // budget, and its estimate counts (so the reported error says when the tolerance is not met).
    const C_MAX: f64 = 1e7;
    cand.retain(|&(_, i, fast, e_fr, e_ld)| {
        if fast && terms[i].b * l > C_MAX {
            sum_fr += e_fr;
            sum_ld += e_ld;
            lumped.push(i);
            false
        } else {
            true
        }
    });
    for &(_, i, fast, e_fr, e_ld) in &cand {
        if sum_fr + e_fr > fr_budget || sum_ld + e_ld > load_budget {
            break;
        }
        sum_fr += e_fr;
        sum_ld += e_ld;
        if fast {
            lumped.push(i);
        } else {
            dropped.push(i);
        }
    }
    let kept: Vec<usize> = (0..terms.len())
        .filter(|i| terms[*i].f > 0.0 && !lumped.contains(i) && !dropped.contains(i))
        .collect();
    let scale = 1.0 + lumped.iter().map(|&i| terms[i].f / terms[i].b).sum::<f64>();
    // Kept slow modes (μ ≤ 0.05) are merged into one: to first order in bξ their kernel terms are
    // fξ(1 − γ − ln b) − fξ ln|ξ| (module doc), reproduced exactly by F = Σf, ln B = Σf ln b / F.
    // Several such modes give nearly equal columns in the reduced system (they differ by O(μ)), so
    // solving them separately loses ~1/μ digits; merged, one well-conditioned column remains.
    // Error: the second-order terms, O(bξ) relative to the first (and the merged mode keeps most of
    // them, B being a weighted geometric mean of the bᵢ); we take 2·max(cᵢ, B·L) times the drop
    // estimate of each merged mode.
    let slow_kept: Vec<usize> = kept
        .iter()
        .copied()
        .filter(|&i| {
            let t = terms[i];
            (1.0 + t.f / t.b) * t.b * l <= merge_mu.min(0.05)
        })
        .collect();
    let mut merged = 0;
    let mut reduced: Vec<CreepTerm> = Vec::new();
    if slow_kept.len() >= 2 {
        let fs: f64 = slow_kept.iter().map(|&i| terms[i].f).sum();
        let lnb: f64 = slow_kept
            .iter()
            .map(|&i| terms[i].f * terms[i].b.ln())
            .sum::<f64>()
            / fs;
        let c_merged = lnb.exp() * l;
        for &i in &slow_kept {
            let t = terms[i];
            if let (_, Some((e_fr, e_ld))) = estimates(&t, l) {
                let k = 2.0 * (t.b * l).max(c_merged);
                sum_fr += k * e_fr;
                sum_ld += k * e_ld;
            }
        }
        merged = slow_kept.len();
        reduced.push(CreepTerm {
            f: fs / scale,
            b: lnb.exp(),
        });
    }
    reduced.extend(
        kept.iter()
            .filter(|i| merged == 0 || !slow_kept.contains(i))
            .map(|&i| CreepTerm {
                f: terms[i].f / scale,
                b: terms[i].b,
            }),
    );
    let modes_used = reduced.len();
    Reduction {
        merge_mu: merge_mu.min(0.05),
        kept,
        merged,
        modes_used,
        lumped,
        dropped,
        scale,
        modes: Modes::new(&reduced),
        friction_over_lambda_error: sum_fr,
        load_error: sum_ld,
    }
}

/// Re-evaluate the error estimates of a given selection at another λ.
pub fn estimate_at(terms: &[CreepTerm], red: &Reduction, lambda: f64) -> (f64, f64) {
    let l = 0.5 * lambda;
    let mut fr = 0.0;
    let mut ld = 0.0;
    for &i in &red.lumped {
        let t = &terms[i];
        let (c, r) = (t.b * l, t.f / t.b);
        let q = r / (1.0 + r);
        // outside the asymptotic range the whole effect is bounded by the one-term maximum
        fr += if c >= 30.0 { q / c } else { q };
        ld += if c >= 30.0 { 2.0 * q / c } else { 1.0 };
    }
    // merged slow modes: second-order estimate as in `select`
    if red.merged >= 2 {
        for &i in &red.kept {
            let t = &terms[i];
            let (c, r) = (t.b * l, t.f / t.b);
            let mu = (1.0 + r) * c;
            if mu <= red.merge_mu {
                let k = 2.0 * c.max(red.modes.b[0] * l);
                fr += k * 0.6 * r * c * (1.0 + (1.0 / c).ln());
                ld += k * 2.0 * r * c * mu * (2.0 + (1.0 / mu).ln());
            }
        }
    }
    for &i in &red.dropped {
        let t = &terms[i];
        let (c, r) = (t.b * l, t.f / t.b);
        let mu = (1.0 + r) * c;
        if mu <= 0.05 {
            fr += 0.6 * r * c * (1.0 + (1.0 / c).ln());
            ld += 2.0 * r * c * mu * (2.0 + (1.0 / mu).ln());
        } else {
            fr += r;
            ld += 1.0;
        }
    }
    (fr, ld)
}
