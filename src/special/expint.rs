//! Exponential integrals E1 and Ei, plain and scaled (eˣE1(x), e⁻ˣEi(x)), in double precision over the
//! whole range where the value is representable (docs/MATH.md §2).
//!
//! Input: one `f64`; output: one `f64`. Owns: the series, continued fraction and asymptotic branches
//! and their switch points. Definitions (Abramowitz & Stegun 5.1.1, 5.1.2, 5.1.10, 5.1.11):
//!
//! ```text
//! E1(x) = ∫ₓ^∞ e⁻ᵗ/t dt                      (x > 0)
//! Ei(x) = PV ∫₋∞ˣ eᵗ/t dt                    (x ≠ 0),   Ei(−x) = −E1(x)
//! E1(x) = −γ − ln x + Ein(x),   Ein(x) = Σ_{k≥1} (−1)^{k+1} xᵏ/(k·k!)
//! Ei(x) =  γ + ln x + Σ_{k≥1} xᵏ/(k·k!)      (x > 0)
//! ```
//!
//! Branches (chosen so that no branch sums terms of opposite sign that cancel by more than a factor ≈ 4):
//! - E1(x), x ≤ 0.5: the series above (its two pieces −γ − ln x and Ein(x) have the same sign there).
//! - eˣE1(x), x > 0.5: the continued fraction eˣE1(x) = 1/(x+1− 1²/(x+3− 2²/(x+5− …))) (A&S 5.1.22 in
//!   its even contraction), evaluated backward from a depth ⌈140/x⌉ + 12 (≤ 292 levels).
//! - Ei(x), 0 < x < 1.5: the series rewritten about Ei's only positive zero x₀ = 0.3725074107813666…
//!   (two doubles, hi + lo). Because Ei(x₀) = 0, γ + ln x₀ = −Σ x₀ᵏ/(k·k!), hence
//!   `Ei(x) = ln(x/x₀) + (x − x₀)·Σ_{k≥1} Pₖ/(k·k!)`, `Pₖ = (xᵏ − x₀ᵏ)/(x − x₀) = Σ_{j<k} xʲx₀^{k−1−j} > 0`.
//!   Both parts have the sign of x − x₀, so nothing cancels anywhere, including at the zero;
//!   ln(x/x₀) is taken as log1p((x − x₀)/x₀) when x is within a factor 2 of x₀.
//!   This branch serves 0 < x < 1.5.
//! - Ei(x), 1.5 ≤ x < 45: the standard series (every piece positive) with its terms xᵏ/k! carried in
//!   double-double and a compensated sum (≈ 130 terms at 45); see `ei_series_standard`.
//! - e⁻ˣEi(x), x ≥ 45: the asymptotic series (1/x)·Σ_{k≥0} k!/xᵏ (A&S 5.1.51), summed (compensated)
//!   while its terms shrink and exceed 1e-18; its best truncation error (≈ √(2πx)·e⁻ˣ relative) is
//!   below 1e-18 from x = 45 on (see `ASYMPTOTIC_EI_FROM`).
//! - Unscaled values multiply by e^{∓x}; past |x| = 700 that factor is taken as a square of e^{∓x/2}
//!   so that E1 fades gracefully through the subnormals and Ei reaches the largest double.
//! - For x < 0, Ei(x) = −E1(−x) and e⁻ˣEi(x) = −e^{|x|}E1(|x|), so the E1 branches serve.
//!
//! Why not a crate (docs/MATH.md §2): statrs 0.18 `integral(x, 1)` gives E1 only (no scaled form, no Ei)
//! and, against the same mpmath table, errs up to 5.3e-15 relative at x = 1.9 (forward Lentz
//! evaluation of the same continued fraction), where the backward evaluation here stays ≤ 2.4e-16.

/// Euler–Mascheroni constant γ_E = 0.5772156649015328606… (nearest double).
pub const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// Ei's positive zero x₀ = 0.37250741078136663446… as an unevaluated sum hi + lo (hi the nearest
/// double). Values from mpmath (`findroot(ei, 0.37)` at 50 digits; tools/gen_special_reference.py
/// prints them).
const EI_ZERO_HI: f64 = 0.372_507_410_781_366_6;
const EI_ZERO_LO: f64 = 1.314_018_341_438_602_8e-17;
/// ln x₀ (nearest double), for ln(x/x₀) away from x₀.
const LN_EI_ZERO: f64 = -0.987_498_346_645_341_9;

/// From here on e⁻ˣEi(x) uses the asymptotic series. Its smallest term, relative to the sum ≈ 1,
/// is k!/xᵏ at k ≈ x, ≈ √(2πx)·e⁻ˣ: 7e-17 at x = 40, 5e-19 at x = 45. Below 45 the convergent
/// series is used (all terms positive, ≈ 130 terms at x = 45).
const ASYMPTOTIC_EI_FROM: f64 = 45.0;

/// Below this point Ei uses the series about its zero x₀; above, the standard series (all pieces
/// positive once x > e^{−γ} = 0.56; the about-zero recursion drifts by ≈ 1 ulp per 10 terms beyond).
const EI_ABOUT_ZERO_UP_TO: f64 = 1.5;

/// Switch from the E1 series to the continued fraction. Below 0.5 the series' pieces −γ − ln x and
/// Ein(x) have the same sign; between 0.5 and 1 they cancel (by up to 3.6×) and cost ≈ 8e-16, while the
/// backward fraction stays at ≈ 3e-16 (mpmath check) for ≤ 292 levels.
const E1_SERIES_UP_TO: f64 = 0.5;

/// E1(x) = ∫ₓ^∞ e⁻ᵗ/t dt for x > 0. E1(0) = +∞; NaN for x < 0 or NaN. Underflows to 0 past x ≈ 745.
#[cfg(test)]
pub fn e1(x: f64) -> f64 {
    if x.is_nan() || x < 0.0 {
        return f64::NAN;
    }
    if x == 0.0 {
        return f64::INFINITY;
    }
    if x <= E1_SERIES_UP_TO {
        e1_series(x)
    } else {
        exp_times(-x, exp_e1_cf(x))
    }
}

/// eˣ·E1(x) for x > 0, for every x without overflow (→ 1/x as x → ∞; ~ −ln x − γ as x → 0).
/// +∞ at 0, NaN for x < 0 or NaN.
pub fn exp_e1(x: f64) -> f64 {
    if x.is_nan() || x < 0.0 {
        return f64::NAN;
    }
    if x == 0.0 {
        return f64::INFINITY;
    }
    if x <= E1_SERIES_UP_TO {
        x.exp() * e1_series(x)
    } else {
        exp_e1_cf(x)
    }
}

/// Ei(x) = PV ∫₋∞ˣ eᵗ/t dt for x ≠ 0; Ei(x) = −E1(−x) for x < 0. −∞ at 0; overflows to +∞ past
/// x ≈ 716 (where the value is no longer representable).
#[cfg(test)]
pub fn ei(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    if x == 0.0 {
        return f64::NEG_INFINITY;
    }
    if x < 0.0 {
        return -e1(-x);
    }
    if x == f64::INFINITY {
        return f64::INFINITY;
    }
    if x < ASYMPTOTIC_EI_FROM {
        ei_positive(x)
    } else {
        exp_times(x, expm_ei_asymptotic(x))
    }
}

/// e⁻ˣ·Ei(x) for x ≠ 0, for every x without overflow (→ 1/x as |x| → ∞). For x < 0 this is
/// −e^{|x|}E1(|x|). Accurate near Ei's zero x₀ (relative error of a few ulp; see the module doc).
/// −∞ at 0.
pub fn expm_ei(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    if x == 0.0 {
        return f64::NEG_INFINITY;
    }
    if x < 0.0 {
        return -exp_e1(-x);
    }
    if x < ASYMPTOTIC_EI_FROM {
        (-x).exp() * ei_positive(x)
    } else {
        expm_ei_asymptotic(x)
    }
}

/// eᵃ·v without spurious overflow or underflow of eᵃ alone (|a| > 700: eᵃ = (e^{a/2})², applied
/// one factor at a time; below, one exp, one rounding fewer).
#[cfg(test)]
fn exp_times(a: f64, v: f64) -> f64 {
    if a.abs() < 700.0 {
        a.exp() * v
    } else {
        let half = (0.5 * a).exp();
        half * (half * v)
    }
}

/// Ein(x) = Σ_{k≥1} (−1)^{k+1} xᵏ/(k·k!), the entire part of E1 (A&S 5.1.11), for |x| ≲ 1.
pub(crate) fn ein_small(x: f64) -> f64 {
    // term_k = (−1)^{k+1} xᵏ/k!; the series is summed until the next term no longer changes the sum.
    let mut pow_fact = x; // (−1)^{k+1} xᵏ / k!
    let mut sum = x;
    let mut k = 1.0_f64;
    loop {
        k += 1.0;
        pow_fact *= -x / k;
        let term = pow_fact / k;
        let new = sum + term;
        if new == sum {
            break;
        }
        sum = new;
        if k > 200.0 {
            break;
        }
    }
    sum
}

/// E1(x) = −γ − ln x + Ein(x) for 0 < x ≤ 0.5 (A&S 5.1.11).
fn e1_series(x: f64) -> f64 {
    // For x ≤ 0.5 the result exceeds each piece divided by 1.5: no significant cancellation.
    (ein_small(x) - EULER_GAMMA) - x.ln()
}

/// eˣE1(x) for x > 0.5 by the continued fraction
/// eˣE1(x) = 1/(x+1 − 1²/(x+3 − 2²/(x+5 − …))) (A&S 5.1.22, even part), evaluated backward from a
/// fixed depth N. The truncation error of N levels is ≈ exp(−4√(N·x)) (checked against mpmath:
/// N = ⌈140/x⌉ + 12 leaves < 1e-19 for every x ≥ 0.3); backward evaluation of this fraction is
/// stable (all partial denominators stay ≥ x + 1), so the result is good to about 1 ulp, where the
/// forward (Lentz) product of ~100 factors lost up to 5e-15 near x = 2.
fn exp_e1_cf(x: f64) -> f64 {
    let depth = (140.0 / x).ceil().min(400.0) as u32 + 12;
    let mut tail = 0.0_f64;
    for i in (1..=depth).rev() {
        let fi = f64::from(i);
        tail = fi * fi / (x + (2.0 * fi + 1.0) - tail);
    }
    1.0 / (x + 1.0 - tail)
}

/// Ei(x) for 0 < x < 1.5 by the series about the zero x₀ (module doc):
/// Ei(x) = ln(x/x₀) + (x − x₀)·Σ_{k≥1} Pₖ/(k·k!).
fn ei_series_about_zero(x: f64) -> f64 {
    // d = x − x₀ to full relative precision: x − hi is exact (Sterbenz) when x is within a factor 2
    // of hi, and lo then restores the rest.
    let d = (x - EI_ZERO_HI) - EI_ZERO_LO;
    let log_ratio = if x > 0.5 * EI_ZERO_HI && x < 2.0 * EI_ZERO_HI {
        (d / EI_ZERO_HI).ln_1p()
    } else {
        x.ln() - LN_EI_ZERO
    };
    // Qₖ = Pₖ/k!, rₖ = x₀ᵏ/k!:  Q₁ = 1, Qₖ = (x·Q_{k−1} + r_{k−1})/k;  term = Qₖ/k.
    let x0 = EI_ZERO_HI;
    let mut q = 1.0_f64;
    let mut r = x0;
    let mut sum = 1.0_f64;
    let mut k = 1.0_f64;
    loop {
        k += 1.0;
        q = (x * q + r) / k;
        r *= x0 / k;
        let term = q / k;
        let new = sum + term;
        if new == sum || k > 500.0 {
            break;
        }
        sum = new;
    }
    log_ratio + d * sum
}

/// Ei(x) for 0 < x < 45: about the zero below [`EI_ABOUT_ZERO_UP_TO`], else the standard series.
fn ei_positive(x: f64) -> f64 {
    if x < EI_ABOUT_ZERO_UP_TO {
        ei_series_about_zero(x)
    } else {
        ei_series_standard(x)
    }
}

/// Ei(x) = γ + ln x + Σ_{k≥1} tₖ/k, tₖ = xᵏ/k! (A&S 5.1.10) for 1.5 ≤ x < 45, where every piece is
/// positive. Plain running products tₖ = t_{k−1}·x/k lose ≈ k/2 ulp by k ≈ x (1e-15 at x = 45), so
/// tₖ is carried as a double-double (error-free products by FMA) and the ≈ 130 terms are added with
/// Neumaier's compensated sum; mpmath comparison: ≤ 1 ulp in this range.
fn ei_series_standard(x: f64) -> f64 {
    let (mut t_hi, mut t_lo) = (1.0_f64, 0.0_f64);
    let mut sum = Neumaier::default();
    for k in 1..400_u32 {
        let fk = f64::from(k);
        // (t_hi + t_lo)·x exactly to double-double.
        let p = t_hi * x;
        let e = t_hi.mul_add(x, -p) + t_lo * x;
        let (p, e) = fast_two_sum(p, e);
        // (p + e)/k: quotient q, remainder (p − q·k + e)/k.
        let q = p / fk;
        let r = ((-q).mul_add(fk, p) + e) / fk;
        (t_hi, t_lo) = fast_two_sum(q, r);
        let term = t_hi / fk;
        sum.add(term);
        if f64::from(k) > x && term < 1e-18 * sum.value() {
            break;
        }
    }
    sum.add(EULER_GAMMA);
    sum.add(x.ln());
    sum.value()
}

/// Sum a + b as hi + lo with hi = fl(a + b), for |a| ≥ |b| (Dekker).
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// Neumaier's compensated summation (error ≈ 1 ulp of the result, independent of the term count).
#[derive(Default)]
pub(crate) struct Neumaier {
    sum: f64,
    comp: f64,
}

impl Neumaier {
    pub(crate) fn add(&mut self, v: f64) {
        let t = self.sum + v;
        if self.sum.abs() >= v.abs() {
            self.comp += (self.sum - t) + v;
        } else {
            self.comp += (v - t) + self.sum;
        }
        self.sum = t;
    }

    pub(crate) fn value(&self) -> f64 {
        self.sum + self.comp
    }
}

/// e⁻ˣEi(x) ≈ (1/x)·Σ_{k≥0} k!/xᵏ for x ≥ 45 (A&S 5.1.51), summed while the terms shrink and exceed
/// 1e-18 of the sum. (Stopping when a term no longer changes the sum is too early: near k ≈ x the
/// terms shrink slowly, and the neglected tail is many times the last term.)
fn expm_ei_asymptotic(x: f64) -> f64 {
    let mut term = 1.0_f64;
    let mut sum = Neumaier::default();
    sum.add(1.0);
    let mut k = 0.0_f64;
    loop {
        k += 1.0;
        let next = term * k / x;
        if next >= term || term < 1e-18 {
            break;
        }
        term = next;
        sum.add(term);
    }
    sum.value() / x
}
