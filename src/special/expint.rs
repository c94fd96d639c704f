//! Exponential integrals E1 and Ei, plain and scaled (eˣE1(x), e⁻ˣEi(x)), in double precision over the
//! whole range where the value is representable (MATH.md §2).
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
//! - eˣE1(x), x ≤ 1: the series above (−γ − ln x and Ein(x) cancel at most by a factor 3.6, at x = 1).
//! - eˣE1(x), x > 1: the continued fraction eˣE1(x) = 1/(x+1− 1²/(x+3− 2²/(x+5− …))) (A&S 5.1.22 in
//!   its even contraction), evaluated by the modified Lentz method; it needs ≈ 45 levels at x = 1 and
//!   fewer beyond.
//! - Ei(x), 0 < x < 40: the series rewritten about Ei's only positive zero x₀ = 0.3725074107813666…
//!   (two doubles, hi + lo). Because Ei(x₀) = 0, γ + ln x₀ = −Σ x₀ᵏ/(k·k!), hence
//!   `Ei(x) = ln(x/x₀) + (x − x₀)·Σ_{k≥1} Pₖ/(k·k!)`, `Pₖ = (xᵏ − x₀ᵏ)/(x − x₀) = Σ_{j<k} xʲx₀^{k−1−j} > 0`.
//!   Both parts have the sign of x − x₀, so nothing cancels anywhere, including at the zero;
//!   ln(x/x₀) is taken as log1p((x − x₀)/x₀) when x is within a factor 2 of x₀.
//! - Ei(x) for 0 < x < 45 uses the series about the zero (all terms positive, ≈ 130 terms at 45).
//! - e⁻ˣEi(x), x ≥ 45: the asymptotic series (1/x)·Σ_{k≥0} k!/xᵏ (A&S 5.1.51), stopped when a term no
//!   longer changes the sum; its best truncation error (≈ √(2πx)·e⁻ˣ relative) is below 1e-18
//!   from x = 45 on (see `ASYMPTOTIC_EI_FROM`).
//! - For x < 0, Ei(x) = −E1(−x) and e⁻ˣEi(x) = −e^{|x|}E1(|x|), so the E1 branches serve.

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

/// Switch from the E1 series to the continued fraction.
const E1_SERIES_UP_TO: f64 = 1.0;

/// E1(x) = ∫ₓ^∞ e⁻ᵗ/t dt for x > 0. E1(0) = +∞; NaN for x < 0 or NaN. Underflows to 0 past x ≈ 745.
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
        // e^{-x} may be subnormal or zero: split it so the product keeps what precision there is.
        let half = (-0.5 * x).exp();
        half * (half * exp_e1_cf(x))
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
    if x < ASYMPTOTIC_EI_FROM {
        ei_series_about_zero(x)
    } else {
        let half = (0.5 * x).exp();
        half * (half * expm_ei_asymptotic(x))
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
        (-x).exp() * ei_series_about_zero(x)
    } else {
        expm_ei_asymptotic(x)
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

/// E1(x) = −γ − ln x + Ein(x) for 0 < x ≤ 1 (A&S 5.1.11).
fn e1_series(x: f64) -> f64 {
    // Sum the two O(1) pieces first; their cancellation is at worst a factor 3.6 at x = 1.
    (ein_small(x) - EULER_GAMMA) - x.ln()
}

/// eˣE1(x) for x > 1 by the continued fraction
/// eˣE1(x) = 1/(x+1 − 1²/(x+3 − 2²/(x+5 − …))) (A&S 5.1.22, even part), modified Lentz.
fn exp_e1_cf(x: f64) -> f64 {
    const TINY: f64 = 1e-300;
    let mut b = x + 1.0;
    let mut c = 1.0 / TINY;
    let mut d = 1.0 / b;
    let mut h = d;
    for i in 1..1000 {
        let fi = i as f64;
        let a = -fi * fi;
        b += 2.0;
        d = a * d + b;
        if d.abs() < TINY {
            d = TINY;
        }
        c = b + a / c;
        if c.abs() < TINY {
            c = TINY;
        }
        d = 1.0 / d;
        let del = c * d;
        h *= del;
        if (del - 1.0).abs() < 1e-17 {
            break;
        }
    }
    h
}

/// Ei(x) for 0 < x < 45 by the series about the zero x₀ (module doc):
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

/// e⁻ˣEi(x) ≈ (1/x)·Σ_{k≥0} k!/xᵏ for x ≥ 45 (A&S 5.1.51), stopped at the first term that no
/// longer changes the sum or starts to grow.
fn expm_ei_asymptotic(x: f64) -> f64 {
    let mut term = 1.0_f64;
    let mut sum = 1.0_f64;
    let mut k = 0.0_f64;
    loop {
        k += 1.0;
        let next = term * k / x;
        if next >= term {
            break;
        }
        term = next;
        let new = sum + term;
        if new == sum {
            break;
        }
        sum = new;
    }
    sum / x
}
