//! Exact interconversion of Prony spectra: [`RelaxationSpectrum`] → [`CreepSpectrum`]
//! ([`relaxation_to_creep`]) and back ([`creep_to_relaxation`]), from the poles and residues of
//! 1/(s·Ē(s)) (docs/MATH.md §4).
//!
//! With rᵢ = 1/ρᵢ, the modulus in the Laplace domain is M(s) = s·Ē(s) = E∞ + Σ Eᵢ s/(s + rᵢ) and the
//! compliance is s·J̄(s) = 1/M(s) = J_g + Σ Jⱼσⱼ/(s + σⱼ) (eq. 2.12 transformed; σⱼ = 1/τⱼ). So
//! - the retardation rates σⱼ are the roots of M(−σ) = E∞ − Σ Eᵢσ/(rᵢ − σ) = 0. M(−σ) falls strictly
//!   from +∞ to −∞ between consecutive poles rᵢ < rᵢ₊₁ and from E∞ > 0 to −∞ on (0, r₁), and stays
//!   above E₀ beyond the last pole, so there is exactly one root in each of the N intervals;
//! - Jⱼσⱼ is the residue of 1/M at −σⱼ: Jⱼ = 1/(σⱼ M′(−σⱼ)), M′(−σ) = Σ Eᵢrᵢ/(rᵢ − σ)² > 0, so Jⱼ > 0;
//! - J_g = 1/E₀ (eq. 2.20), and J∞ = J_g + Σ Jⱼ = 1/E∞.
//!
//! Creep → relaxation is the mirror image: the relaxation rates are the roots of
//! s·J̄(s) = J_g + Σ Jⱼσⱼ/(σⱼ − r) = 0 at s = −r (one between consecutive σⱼ and one above the
//! largest), Eᵢ = 1/(rᵢ Σⱼ Jⱼσⱼ/(σⱼ − rᵢ)²), E∞ = 1/J∞.
//!
//! Numerics. Each root is found by bisection in a form that loses no precision when a root lies
//! extremely close to a pole (a weak term, or 24 decades of rates): the unknown is the offset d from
//! the nearer end ("anchor") of its interval, x = anchor + d, so the small differences x − pᵢ are
//! computed as (anchor − pᵢ) + d without cancellation. The bracketed function is
//! h(x) = ln P(x) − ln N(x), where P and N are the sums of the positive and of the negative terms of
//! M(−σ) (or of s·J̄(s)): no cancellation either, monotone, and well scaled whatever the strengths.
//! Bisection runs first geometrically in |d| (any number of decades) and then arithmetically down to
//! adjacent doubles; it cannot fail on a bracket. The residue sums are sums of positive terms.
//!
//! Accuracy (measured on 1000 random spectra, 1–40 terms over 24 decades, strengths over 8 decades:
//! `cargo run --release --example park_schapery_table`): max |E*J* − 1| = 1.6e-15 over
//! ω = 1e-20…1e20 rad/s in both directions; the round trip relaxation → creep → relaxation returns
//! E(t), E*(ω), E∞ and every ρᵢ to ≤ 5.3e-15 relative. The individual strengths of two nearly
//! coincident relaxation times (relative gap g) are ill-conditioned: the retardation term between them
//! is weak (Jⱼ ∝ g²) and its time, stored to 1 ulp, is known to ε/g of the gap, so the split of strength
//! between the pair moves by up to ~ε/g (measured 4.7e-12 of E(ρᵢ) for g = 1e-4) while their sum and
//! the functions do not. Plain-double evaluation of h lost this much on every function too (6.5e-12),
//! hence the double-double sums in `PoleSeries::h`.
//!
//! Degenerate input, handled explicitly:
//! - E∞ = 0 (a fluid): [`CreepError::Fluid`]. Its creep function has a flow term t/η₀ (eq. 2.11) that a
//!   [`CreepSpectrum`] (a solid, eq. 2.12) cannot hold; rather than drop or fake it we refuse.
//!   [`fluid_to_creep`] converts it exactly into a [`FluidCreep`]: the solid part plus η₀ (MATH §17).
//! - Zero-strength terms are removed (they are no poles); their count is reported.
//! - Equal or nearly equal times (relative difference ≤ 8 ε) are merged into one term with the summed
//!   strength (the change of E(t) is below 8 ε relative); the count is reported.
//! - A term so weak that its root lies closer to its pole than the smallest double can resolve
//!   (strength below ≈ 1e-290 of the others) contributes nothing representable and is dropped; counted.

use super::error::CreepError;
use super::{CreepSpectrum, RetardationTerm};
use crate::prony::{RelaxationSpectrum, RelaxationTerm};
use serde::{Deserialize, Serialize};

/// What the exact conversion did to the input besides converting it.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct ExactInfo {
    /// Input terms with zero strength, removed.
    pub zero_terms_removed: usize,
    /// Input terms merged into a neighbour with (nearly) the same time.
    pub terms_merged: usize,
    /// Terms whose converted strength is not representable (underflow), dropped.
    pub negligible_terms_dropped: usize,
}

/// Exact relaxation → creep conversion (docs/MATH.md §4). The spectrum is validated first.
pub fn relaxation_to_creep(
    relax: &RelaxationSpectrum,
) -> Result<(CreepSpectrum, ExactInfo), CreepError> {
    relax.validate()?;
    let e_inf = relax.modulus_inf_pa;
    if e_inf == 0.0 {
        let viscosity_pa_s = relax.terms.iter().map(|t| t.modulus_pa * t.tau_s).sum();
        return Err(CreepError::Fluid { viscosity_pa_s });
    }
    let mut info = ExactInfo::default();
    let poles = clean_terms(
        relax.terms.iter().map(|t| (t.tau_s, t.modulus_pa)),
        &mut info,
    );
    let e0 = e_inf + poles.iter().map(|p| p.2).sum::<f64>();
    let series = PoleSeries {
        c: e_inf,
        p: poles.iter().map(|p| p.0).collect(),
        p_lo: poles.iter().map(|p| p.1).collect(),
        w: poles.iter().map(|p| p.2).collect(),
        num_is_x: true,
        positive_above: true,
    };
    let mut terms = Vec::with_capacity(poles.len());
    let n = series.p.len();
    for k in 0..n {
        let lo = if k == 0 { 0.0 } else { series.p[k - 1] };
        let hi = series.p[k];
        match series.root(lo, k.checked_sub(1), Some(hi), Some(k)) {
            Some(root) => {
                let jj = series.strength(&root);
                if jj > 0.0 && jj.is_finite() {
                    terms.push(RetardationTerm {
                        compliance_per_pa: jj,
                        tau_s: 1.0 / root.x,
                    });
                } else {
                    info.negligible_terms_dropped += 1;
                }
            }
            None => info.negligible_terms_dropped += 1,
        }
    }
    // Longest retardation time first, like the usual listing (order is immaterial).
    terms.sort_by(|a, b| b.tau_s.total_cmp(&a.tau_s));
    Ok((
        CreepSpectrum {
            kind: relax.kind,
            poisson: relax.poisson,
            compliance_glassy_per_pa: 1.0 / e0,
            terms,
        },
        info,
    ))
}

/// A fluid's creep function (docs/MATH.md §17): J(t) = J_g + Σⱼ Jⱼ(1 − e^(−t/τⱼ)) + t/η₀, the solid
/// part as a [`CreepSpectrum`] and the flow term's viscosity η₀ (of the spectrum's kind).
#[derive(Debug, Clone, PartialEq)]
pub struct FluidCreep {
    /// J_g and the retardation terms (N − 1 of them for N relaxation terms).
    pub solid: CreepSpectrum,
    /// Zero-shear viscosity η₀ = Σ Eᵢρᵢ in Pa·s (tensile or shear, as the spectrum's kind).
    pub viscosity_pa_s: f64,
}

impl FluidCreep {
    /// J(t) in 1/Pa at `t_s` ≥ 0, flow term included.
    #[cfg(test)]
    pub fn creep_compliance(&self, t_s: f64) -> f64 {
        self.solid.creep_compliance(t_s) + t_s / self.viscosity_pa_s
    }

    /// (J′, J″) at ω with J* = J′ − iJ″: the flow term adds 1/(ωη₀) to J″.
    pub(crate) fn complex_compliance(&self, omega_rad_s: f64) -> (f64, f64) {
        let (j1, j2) = self.solid.complex_compliance(omega_rad_s);
        (j1, j2 + 1.0 / (omega_rad_s * self.viscosity_pa_s))
    }

    /// max over `omegas_rad_s` of |E*(ω)·J*(ω) − 1|, flow term included (as [`max_product_error`]).
    pub fn max_product_error(&self, relax: &RelaxationSpectrum, omegas_rad_s: &[f64]) -> f64 {
        omegas_rad_s
            .iter()
            .map(|&w| {
                let (e1, e2) = relax.complex_modulus(w);
                let (j1, j2) = self.complex_compliance(w);
                (e1 * j1 + e2 * j2 - 1.0).hypot(e2 * j1 - e1 * j2)
            })
            .fold(0.0, f64::max)
    }
}

/// Exact relaxation → creep conversion of a fluid, E∞ = 0 (docs/MATH.md §17): M(−σ) = −Σ Eᵢσ/(rᵢ − σ)
/// has the root σ = 0 (the flow term t/η₀, from 1/M(s) ≈ 1/(η₀s) near 0) and one root between each
/// pair of consecutive relaxation rates (none in (0, r₁), where every term is negative), found and
/// weighed as in [`relaxation_to_creep`]. A spectrum with E∞ > 0 is refused (use
/// [`relaxation_to_creep`]).
pub fn fluid_to_creep(relax: &RelaxationSpectrum) -> Result<(FluidCreep, ExactInfo), CreepError> {
    relax.validate()?;
    if relax.modulus_inf_pa != 0.0 {
        return Err(CreepError::InvalidSetting {
            setting: "modulus_inf_pa",
            reason: format!(
                "{:e} > 0: a solid; its creep spectrum has no flow term",
                relax.modulus_inf_pa
            ),
        });
    }
    let mut info = ExactInfo::default();
    let poles = clean_terms(
        relax.terms.iter().map(|t| (t.tau_s, t.modulus_pa)),
        &mut info,
    );
    let e0 = poles.iter().map(|p| p.2).sum::<f64>();
    let viscosity_pa_s: f64 = relax.terms.iter().map(|t| t.modulus_pa * t.tau_s).sum();
    let series = PoleSeries {
        c: 0.0,
        p: poles.iter().map(|p| p.0).collect(),
        p_lo: poles.iter().map(|p| p.1).collect(),
        w: poles.iter().map(|p| p.2).collect(),
        num_is_x: true,
        positive_above: true,
    };
    let mut terms = Vec::with_capacity(poles.len().saturating_sub(1));
    for k in 1..series.p.len() {
        match series.root(series.p[k - 1], Some(k - 1), Some(series.p[k]), Some(k)) {
            Some(root) => {
                let jj = series.strength(&root);
                if jj > 0.0 && jj.is_finite() {
                    terms.push(RetardationTerm {
                        compliance_per_pa: jj,
                        tau_s: 1.0 / root.x,
                    });
                } else {
                    info.negligible_terms_dropped += 1;
                }
            }
            None => info.negligible_terms_dropped += 1,
        }
    }
    terms.sort_by(|a, b| b.tau_s.total_cmp(&a.tau_s));
    Ok((
        FluidCreep {
            solid: CreepSpectrum {
                kind: relax.kind,
                poisson: relax.poisson,
                compliance_glassy_per_pa: 1.0 / e0,
                terms,
            },
            viscosity_pa_s,
        },
        info,
    ))
}

/// Exact creep → relaxation conversion (the mirror of [`relaxation_to_creep`]). The spectrum is
/// validated first; E∞ = 1/J∞ > 0 always (a creep spectrum of a solid).
pub fn creep_to_relaxation(
    creep: &CreepSpectrum,
) -> Result<(RelaxationSpectrum, ExactInfo), CreepError> {
    creep.validate()?;
    let mut info = ExactInfo::default();
    let poles = clean_terms(
        creep.terms.iter().map(|t| (t.tau_s, t.compliance_per_pa)),
        &mut info,
    );
    let jg = creep.compliance_glassy_per_pa;
    let j_inf = jg + poles.iter().map(|p| p.2).sum::<f64>();
    let series = PoleSeries {
        c: jg,
        p: poles.iter().map(|p| p.0).collect(),
        p_lo: poles.iter().map(|p| p.1).collect(),
        w: poles.iter().map(|p| p.2).collect(),
        num_is_x: false,
        positive_above: false,
    };
    let n = series.p.len();
    let mut terms = Vec::with_capacity(n);
    for k in 0..n {
        let hi = if k + 1 < n {
            Some(series.p[k + 1])
        } else {
            None
        };
        let hi_idx = if k + 1 < n { Some(k + 1) } else { None };
        match series.root(series.p[k], Some(k), hi, hi_idx) {
            Some(root) => {
                let ei = series.strength(&root);
                if ei > 0.0 && ei.is_finite() {
                    terms.push(RelaxationTerm {
                        modulus_pa: ei,
                        tau_s: 1.0 / root.x,
                    });
                } else {
                    info.negligible_terms_dropped += 1;
                }
            }
            None => info.negligible_terms_dropped += 1,
        }
    }
    terms.sort_by(|a, b| b.tau_s.total_cmp(&a.tau_s));
    Ok((
        RelaxationSpectrum {
            kind: creep.kind,
            poisson: creep.poisson,
            modulus_inf_pa: 1.0 / j_inf,
            terms,
        },
        info,
    ))
}

/// max over `omegas_rad_s` of |E*(ω)·J*(ω) − 1| (J* = J′ − iJ″): the defining identity of a
/// relaxation/creep pair in the frequency domain; 0 for an exact conversion.
pub fn max_product_error(
    relax: &RelaxationSpectrum,
    creep: &CreepSpectrum,
    omegas_rad_s: &[f64],
) -> f64 {
    omegas_rad_s
        .iter()
        .map(|&w| {
            let (e1, e2) = relax.complex_modulus(w);
            let (j1, j2) = creep.complex_compliance(w);
            // (E′ + iE″)(J′ − iJ″) = E′J′ + E″J″ + i(E″J′ − E′J″)
            let re = e1 * j1 + e2 * j2 - 1.0;
            let im = e2 * j1 - e1 * j2;
            re.hypot(im)
        })
        .fold(0.0, f64::max)
}

/// The frequencies a conversion of `relax` is checked over ([`max_product_error`]): its own window
/// of relaxation times ± 4 decades, 8 points per decade, as (ω_min, ω_max, the ω's) in rad/s
/// (`convert` and the Python package report these).
pub fn check_frequencies(relax: &RelaxationSpectrum) -> (f64, f64, Vec<f64>) {
    let taus = relax.terms.iter().map(|t| t.tau_s);
    let (tmin, tmax) = taus.fold((f64::INFINITY, 0f64), |(a, b), t| (a.min(t), b.max(t)));
    let (wmin, wmax) = if tmax > 0.0 {
        (1e-4 / tmax, 1e4 / tmin)
    } else {
        (1.0, 1.0)
    };
    let n = ((wmax / wmin).log10() * 8.0).ceil().max(1.0) as usize;
    let omegas: Vec<f64> = (0..=n)
        .map(|k| wmin * (wmax / wmin).powf(k as f64 / n as f64))
        .collect();
    (wmin, wmax, omegas)
}

/// (time, strength) pairs → (rate as a double-double hi + lo, strength): drop zero strengths, sort by
/// rate, merge nearly equal rates (the first time of a merged group is kept, strengths summed).
///
/// The rate 1/τ is carried as hi + lo with lo = (1 − hi·τ)/τ from a fused multiply-add, so a root that
/// lies a few ulp from its pole is located relative to the exact pole 1/τ, not to its rounding.
fn clean_terms(
    terms: impl Iterator<Item = (f64, f64)>,
    info: &mut ExactInfo,
) -> Vec<(f64, f64, f64)> {
    let mut v: Vec<(f64, f64, f64)> = Vec::new();
    for (tau, w) in terms {
        if w == 0.0 {
            info.zero_terms_removed += 1;
        } else {
            let hi = 1.0 / tau;
            let lo = (-hi).mul_add(tau, 1.0) / tau;
            v.push((hi, lo, w));
        }
    }
    v.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut out: Vec<(f64, f64, f64)> = Vec::with_capacity(v.len());
    for (hi, lo, w) in v {
        if let Some(last) = out.last_mut() {
            if hi - last.0 <= 8.0 * f64::EPSILON * hi {
                last.2 += w;
                info.terms_merged += 1;
                continue;
            }
        }
        out.push((hi, lo, w));
    }
    out
}

/// c + Σ ±wᵢ·qᵢ(x)/|x − pᵢ| with qᵢ = x (`num_is_x`) or pᵢ; a term is positive when x lies above its
/// pole (`positive_above`) or below it (otherwise).
///
/// Relaxation → creep: c = E∞, pᵢ = rᵢ, wᵢ = Eᵢ, qᵢ = x, positive above (M(−σ)).
/// Creep → relaxation: c = J_g, pᵢ = σⱼ, wᵢ = Jⱼ, qᵢ = pᵢ, positive below (s·J̄(s) at s = −r).
struct PoleSeries {
    c: f64,
    p: Vec<f64>,
    /// Low parts of the poles: the exact pole is p + p_lo.
    p_lo: Vec<f64>,
    w: Vec<f64>,
    num_is_x: bool,
    positive_above: bool,
}

/// x = anchor + anchor_lo + d, with x − pᵢ = d exactly for the anchor pole.
struct Point {
    anchor: f64,
    anchor_lo: f64,
    anchor_idx: Option<usize>,
    d: f64,
    x: f64,
}

impl PoleSeries {
    fn point(&self, anchor: f64, anchor_idx: Option<usize>, d: f64) -> Point {
        let anchor_lo = anchor_idx.map_or(0.0, |i| self.p_lo[i]);
        Point {
            anchor,
            anchor_lo,
            anchor_idx,
            d,
            x: anchor + (anchor_lo + d),
        }
    }

    /// x − pᵢ without cancellation.
    #[inline]
    fn diff(&self, pt: &Point, i: usize) -> f64 {
        if pt.anchor_idx == Some(i) {
            pt.d
        } else {
            (pt.anchor - self.p[i]) + ((pt.anchor_lo - self.p_lo[i]) + pt.d)
        }
    }

    /// (P − N)/(P + N), which has the sign of h = ln P − ln N. P and N are summed in double-double
    /// arithmetic (≈ 32 digits), so that the sign is right even where P and N agree to many digits:
    /// next to a weak term whose pole is close to the root, the root is fixed by P = N at a level
    /// far below the rounding of P and N in plain doubles (see the accuracy note above).
    fn h(&self, pt: &Point) -> f64 {
        let mut pos = (self.c, 0.0);
        let mut neg = (0.0, 0.0);
        // x as a double-double: anchor + (anchor_lo + d).
        let x = dd_add(two_sum(pt.anchor, pt.d), (pt.anchor_lo, 0.0));
        for i in 0..self.p.len() {
            let dx = if pt.anchor_idx == Some(i) {
                (pt.d, 0.0)
            } else {
                dd_add(
                    two_sum(pt.anchor, -self.p[i]),
                    two_sum(pt.anchor_lo - self.p_lo[i], pt.d),
                )
            };
            let q = if self.num_is_x {
                x
            } else {
                (self.p[i], self.p_lo[i])
            };
            let abs_dx = if dx.0 < 0.0 { (-dx.0, -dx.1) } else { dx };
            let t = dd_div(dd_mul_f(q, self.w[i]), abs_dx);
            if (dx.0 > 0.0) == self.positive_above {
                pos = dd_add(pos, t);
            } else {
                neg = dd_add(neg, t);
            }
        }
        if !(pos.0.is_finite() && neg.0.is_finite()) {
            return if pos.0.is_infinite() && neg.0.is_finite() {
                1.0
            } else if neg.0.is_infinite() && pos.0.is_finite() {
                -1.0
            } else {
                f64::NAN
            };
        }
        let diff = dd_add(pos, (-neg.0, -neg.1));
        diff.0 / (pos.0 + neg.0)
    }

    /// 1/(x·Σ wᵢpᵢ/(x − pᵢ)²): the strength Jⱼ = 1/(σⱼM′(−σⱼ)) (relaxation → creep) or
    /// Eᵢ = 1/(rᵢ Σ Jⱼσⱼ/(σⱼ − rᵢ)²) (creep → relaxation). Evaluated as (m/x)·(m/Σ wᵢpᵢ(m/dᵢ)²) with
    /// m = min |dᵢ|, so that (x − pᵢ)² never underflows for a root that hugs its pole.
    fn strength(&self, pt: &Point) -> f64 {
        let m = (0..self.p.len())
            .map(|i| self.diff(pt, i).abs())
            .fold(f64::INFINITY, f64::min);
        let scaled: f64 = (0..self.p.len())
            .map(|i| {
                let q = m / self.diff(pt, i);
                self.w[i] * self.p[i] * q * q
            })
            .sum();
        (m / pt.x) * (m / scaled)
    }

    /// The root of h in (lo, hi) (hi = None: unbounded), lo and hi being poles (indices given) or 0.
    /// None when the root is closer to a pole than doubles can resolve.
    fn root(
        &self,
        lo: f64,
        lo_idx: Option<usize>,
        hi: Option<f64>,
        hi_idx: Option<usize>,
    ) -> Option<Point> {
        // Sign of h just above lo: +∞ for relaxation → creep (the pole term at lo, or N → 0 at x → 0,
        // dominates P), −∞ for creep → relaxation.
        let s_lo = if self.positive_above { 1.0 } else { -1.0 };
        let (anchor, anchor_idx, dir, d_far) = match hi {
            Some(hi) => {
                let half = (hi - lo) / 2.0;
                let mid = self.point(lo, lo_idx, half);
                if self.h(&mid) * s_lo > 0.0 {
                    (hi, hi_idx, -1.0, hi - (lo + half))
                } else {
                    (lo, lo_idx, 1.0, half)
                }
            }
            None => {
                // Beyond the last pole: expand until h has the far sign.
                let mut d = lo.max(f64::MIN_POSITIVE);
                let mut guard = 0;
                while self.h(&self.point(lo, lo_idx, d)) * s_lo > 0.0 {
                    d *= 2.0;
                    guard += 1;
                    if guard > 2100 || !d.is_finite() {
                        return None;
                    }
                }
                (lo, lo_idx, 1.0, d)
            }
        };
        // Sign expected next to the anchor.
        let s_anchor = if dir > 0.0 { s_lo } else { -s_lo };
        let h_at = |m: f64| self.h(&self.point(anchor, anchor_idx, dir * m));
        // Near side: shrink |d| until h has the anchor's sign.
        let mut a = d_far;
        let mut b = d_far; // far side, sign −s_anchor
        loop {
            a *= 1e-4;
            if a < f64::MIN_POSITIVE * 1e4 {
                return None;
            }
            let ha = h_at(a);
            if ha.is_nan() {
                return None;
            }
            if ha * s_anchor > 0.0 {
                break;
            }
            b = a;
        }
        // Geometric bisection while the bracket spans more than a factor 1.001.
        while b > a * 1.001 {
            let m = a.sqrt() * b.sqrt();
            if h_at(m) * s_anchor > 0.0 {
                a = m;
            } else {
                b = m;
            }
        }
        // Arithmetic bisection down to adjacent doubles.
        loop {
            let m = a + (b - a) / 2.0;
            if m <= a || m >= b {
                break;
            }
            let hm = h_at(m);
            if hm == 0.0 {
                a = m;
                b = m;
                break;
            }
            if hm * s_anchor > 0.0 {
                a = m;
            } else {
                b = m;
            }
        }
        let m = if h_at(a).abs() <= h_at(b).abs() { a } else { b };
        Some(self.point(anchor, anchor_idx, dir * m))
    }
}

// Double-double arithmetic (value = hi + lo, |lo| ≤ ulp(hi)/2): error-free sum and product
// (Knuth's two-sum, fused multiply-add), then the usual renormalised operations.

fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

fn dd_add(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let (s, e) = two_sum(a.0, b.0);
    quick_two_sum(s, e + (a.1 + b.1))
}

fn dd_mul_f(a: (f64, f64), b: f64) -> (f64, f64) {
    let p = a.0 * b;
    let e = a.0.mul_add(b, -p);
    quick_two_sum(p, e + a.1 * b)
}

fn dd_div(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let q1 = a.0 / b.0;
    // r = a − q1·b, exactly enough: q1·b as a double-double.
    let p = dd_add(dd_mul_f(b, q1), (0.0, 0.0));
    let r = dd_add(a, (-p.0, -p.1));
    let q2 = r.0 / b.0;
    quick_two_sum(q1, q2)
}

impl RelaxationSpectrum {
    /// The frequencies a conversion of this spectrum is checked over (`check_frequencies`):
    /// (ω_min, ω_max, the ω's) in rad/s.
    pub fn check_frequencies(&self) -> (f64, f64, Vec<f64>) {
        check_frequencies(self)
    }

    /// max over `omegas_rad_s` of |E*(ω)·J*(ω) − 1| against `creep` (`max_product_error`).
    pub fn max_product_error(&self, creep: &CreepSpectrum, omegas_rad_s: &[f64]) -> f64 {
        max_product_error(self, creep, omegas_rad_s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::ModulusKind;

    fn relax(e_inf: f64, terms: &[(f64, f64)]) -> RelaxationSpectrum {
        RelaxationSpectrum {
            kind: ModulusKind::Tensile,
            poisson: 0.5,
            modulus_inf_pa: e_inf,
            terms: terms
                .iter()
                .map(|&(e, tau)| RelaxationTerm {
                    modulus_pa: e,
                    tau_s: tau,
                })
                .collect(),
        }
    }

    #[test]
    fn standard_linear_solid_has_the_textbook_creep_function() {
        // E(t) = E∞ + E₁e^(−t/ρ) ↔ J(t) = 1/E₀ + (1/E∞ − 1/E₀)(1 − e^(−t/τ)), τ = ρE₀/E∞.
        let (c, _) = relaxation_to_creep(&relax(1e6, &[(9e6, 1e-3)])).unwrap();
        assert_eq!(c.terms.len(), 1);
        assert!((c.compliance_glassy_per_pa * 1e7 - 1.0).abs() < 1e-15);
        // 1e-15 ≈ 4.5 ε: the root is found to adjacent doubles, then 1/x and the quotients each round.
        assert!((c.terms[0].tau_s / 1e-2 - 1.0).abs() < 1e-15);
        assert!((c.terms[0].compliance_per_pa / 9e-7 - 1.0).abs() < 1e-15);
    }

    #[test]
    fn two_terms_against_the_quadratic_formula() {
        // E∞ − E₁σ/(r₁−σ) − E₂σ/(r₂−σ) = 0 ⇔ (E∞+E₁+E₂)σ² − (E∞(r₁+r₂) + E₁r₂ + E₂r₁)σ + E∞r₁r₂ = 0.
        let (e_inf, e1, r1, e2, r2) = (1.0, 2.0, 1.0, 3.0, 100.0);
        let (c, _) = relaxation_to_creep(&relax(e_inf, &[(e1, 1.0 / r1), (e2, 1.0 / r2)])).unwrap();
        let a = e_inf + e1 + e2;
        let b = e_inf * (r1 + r2) + e1 * r2 + e2 * r1;
        let cc = e_inf * r1 * r2;
        let disc = (b * b - 4.0 * a * cc).sqrt();
        let small = 2.0 * cc / (b + disc);
        let large = (b + disc) / (2.0 * a);
        let mut rates: Vec<f64> = c.terms.iter().map(|t| 1.0 / t.tau_s).collect();
        rates.sort_by(f64::total_cmp);
        assert!((rates[0] / small - 1.0).abs() < 1e-14 && (rates[1] / large - 1.0).abs() < 1e-14);
        // J∞ = 1/E∞ from the residues.
        assert!((c.compliance_relaxed() * e_inf - 1.0).abs() < 1e-14);
    }

    #[test]
    fn fluid_is_refused_with_its_viscosity() {
        let e = relaxation_to_creep(&relax(0.0, &[(2.0, 3.0)])).unwrap_err();
        assert_eq!(
            e,
            CreepError::Fluid {
                viscosity_pa_s: 6.0
            }
        );
    }

    /// Maxwell model E(t) = E₁e^(−t/ρ): J(t) = 1/E₁ + t/(E₁ρ) exactly, no retardation term.
    #[test]
    fn maxwell_fluid_has_the_textbook_creep_function() {
        let (f, info) = fluid_to_creep(&relax(0.0, &[(2e6, 1e-3)])).unwrap();
        assert_eq!(info, ExactInfo::default());
        assert!(f.solid.terms.is_empty());
        assert_eq!(f.solid.compliance_glassy_per_pa, 5e-7);
        assert_eq!(f.viscosity_pa_s, 2e3);
        assert!((f.creep_compliance(1.0) / (5e-7 + 1.0 / 2e3) - 1.0).abs() < 1e-15);
        assert!(fluid_to_creep(&relax(1.0, &[(2e6, 1e-3)])).is_err());
    }

    /// A fluid of several terms against identities that do not use the roots: E*·J* = 1 at every ω
    /// (flow term included), J_g = 1/ΣEᵢ, and the steady-state compliance
    /// J_e = J_g + ΣJⱼ = Σ Eᵢρᵢ² / η₀² (the t → ∞ intercept of J(t) − t/η₀, from the Laplace
    /// expansion 1/M(s) = 1/(η₀s) + Σ Eᵢρᵢ²/η₀² + O(s)).
    #[test]
    fn fluid_of_several_terms_satisfies_the_identities() {
        let terms = [
            (3e8, 1e-7),
            (2e7, 1e-4),
            (5e6, 1e-1),
            (1e5, 1e2),
            (1e4, 1e4),
        ];
        let r = relax(0.0, &terms);
        let (f, info) = fluid_to_creep(&r).unwrap();
        assert_eq!(info, ExactInfo::default());
        assert_eq!(f.solid.terms.len(), terms.len() - 1);
        let eta: f64 = terms.iter().map(|t| t.0 * t.1).sum();
        let je = terms.iter().map(|t| t.0 * t.1 * t.1).sum::<f64>() / (eta * eta);
        assert!((f.solid.compliance_relaxed() / je - 1.0).abs() < 1e-13);
        let omegas: Vec<f64> = (-60..=60).map(|k| 10f64.powf(k as f64 * 0.25)).collect();
        let worst = f.max_product_error(&r, &omegas);
        // A few hundred ε: sums of 5 terms spanning 11 decades of times.
        assert!(worst < 1e-13, "{worst:e}");
    }

    /// The solid path converges to the fluid as E∞ → 0⁺: its longest retardation term runs away
    /// (τ → ∞) with J/τ → 1/η₀, and the other terms tend to the fluid's.
    #[test]
    fn solid_tends_to_the_fluid_as_e_inf_vanishes() {
        let terms = [(3e8, 1e-7), (2e7, 1e-4), (5e6, 1e-1), (1e5, 1e2)];
        let (f, _) = fluid_to_creep(&relax(0.0, &terms)).unwrap();
        for eps in [1e-6, 1e-9] {
            let (c, _) = relaxation_to_creep(&relax(eps, &terms)).unwrap();
            let long = c.terms[0];
            // J₁/τ₁ − 1/η₀ and the other terms move by O(E∞/E(longest ρ)) relative.
            let tol = 100.0 * eps / 1e5;
            assert!(
                (long.compliance_per_pa / long.tau_s * f.viscosity_pa_s - 1.0).abs() < tol,
                "{eps}"
            );
            for (a, b) in c.terms[1..].iter().zip(&f.solid.terms) {
                assert!((a.tau_s / b.tau_s - 1.0).abs() < tol, "{eps} {a:?} {b:?}");
                assert!((a.compliance_per_pa / b.compliance_per_pa - 1.0).abs() < tol);
            }
        }
    }

    #[test]
    fn duplicates_and_zero_terms_are_handled() {
        let (c, info) = relaxation_to_creep(&relax(
            1.0,
            &[(1.0, 1.0), (0.0, 5.0), (2.0, 1.0), (4.0, 1e-3)],
        ))
        .unwrap();
        assert_eq!(info.zero_terms_removed, 1);
        assert_eq!(info.terms_merged, 1);
        let (c2, _) = relaxation_to_creep(&relax(1.0, &[(3.0, 1.0), (4.0, 1e-3)])).unwrap();
        assert_eq!(c.terms.len(), 2);
        for (a, b) in c.terms.iter().zip(&c2.terms) {
            assert!((a.tau_s / b.tau_s - 1.0).abs() < 1e-15);
            assert!((a.compliance_per_pa / b.compliance_per_pa - 1.0).abs() < 1e-14);
        }
    }

    #[test]
    fn nearly_equal_times_and_a_very_weak_term_convert_exactly() {
        // Times 1e-9 apart (relative) and a term 1e-200 weaker than the rest: roots hug their poles.
        let r = relax(
            1.0,
            &[(1.0, 1.0), (1.0, 1.0 + 1e-9), (1e-200, 1e-6), (1e3, 1e-9)],
        );
        let (c, info) = relaxation_to_creep(&r).unwrap();
        assert_eq!(info, ExactInfo::default(), "{c:?}");
        assert_eq!(c.terms.len(), 4);
        assert!(c.terms.iter().all(|t| t.compliance_per_pa > 0.0));
        let omegas: Vec<f64> = (-60..=60).map(|k| 10f64.powf(k as f64 * 0.25)).collect();
        // 1e-13: a few hundred ε; the product involves sums of 4 terms of size ≤ 1.
        assert!(max_product_error(&r, &c, &omegas) < 1e-13);
        assert!((c.compliance_relaxed() - 1.0).abs() < 1e-13);
    }

    #[test]
    fn creep_back_to_relaxation() {
        let r = relax(1e6, &[(9e6, 1e-3), (5e7, 1e-6)]);
        let (c, _) = relaxation_to_creep(&r).unwrap();
        let (r2, _) = creep_to_relaxation(&c).unwrap();
        assert!((r2.modulus_inf_pa / 1e6 - 1.0).abs() < 1e-14);
        let mut got: Vec<_> = r2.terms.clone();
        got.sort_by(|a, b| a.tau_s.total_cmp(&b.tau_s));
        assert!(
            (got[0].tau_s / 1e-6 - 1.0).abs() < 1e-14 && (got[1].tau_s / 1e-3 - 1.0).abs() < 1e-14
        );
        assert!(
            (got[0].modulus_pa / 5e7 - 1.0).abs() < 1e-13
                && (got[1].modulus_pa / 9e6 - 1.0).abs() < 1e-13
        );
    }

    #[test]
    fn shifting_commutes_with_conversion() {
        // Scaling every time by a_T scales every root by 1/a_T and leaves strengths unchanged, so
        // convert-then-shift equals shift-then-convert to rounding (a few ε).
        let law = crate::material::ShiftLaw::Wlf {
            t_ref_c: 25.0,
            c1: 13.5,
            c2_k: 141.19,
        };
        let r = relax(1e6, &[(9e6, 1e-3), (5e7, 1e-6), (3e8, 2e-9)]);
        let a = relaxation_to_creep(&r.at_temperature(&law, 60.0, None).unwrap().spectrum)
            .unwrap()
            .0;
        let b = relaxation_to_creep(&r)
            .unwrap()
            .0
            .at_temperature(&law, 60.0, None)
            .unwrap()
            .spectrum;
        for (x, y) in a.terms.iter().zip(&b.terms) {
            assert!((x.tau_s / y.tau_s - 1.0).abs() < 1e-14);
            assert!((x.compliance_per_pa / y.compliance_per_pa - 1.0).abs() < 1e-14);
        }
    }
}
