//! The bracket of the contact kernel (MATH.md §2) and its first two antiderivatives, for every real x.
//!
//! Input: one `f64`; output: one `f64`. Owns: h, H₁ = ∫₀ˣh, H₂ = ∫₀ˣH₁, their series and closed forms
//! and the switch points between them. The kernel of thesis eq. 3.19 for γ(ζ) = Σ fᵢe^{−bᵢζ} is
//! K(ξ) = ln|ξ| + Σ (fᵢ/bᵢ)·h(bᵢξ), because
//! ∫₀^∞ e^{−bζ} ln|ξ+ζ| dζ = (ln|ξ| − ln b + g(bξ))/b (MATH.md §2), i.e.
//!
//! ```text
//! h(x) = ln|x| + γ + g(x) = ∫₀^∞ e^{−ζ} ln|1 + x/ζ| dζ,
//! g(x) = eˣE1(x) (x > 0),  g(x) = −eˣEi(−x) (x < 0),  h(0) = 0.
//! ```
//!
//! Derivation (with L = γ + ln|x|). On both sides of 0, g′ = g − 1/x, and g + ln|x| → −γ as x → 0,
//! so ∫₀ˣ g = g + L = h, i.e. h′ = g. Integrating ln|t| twice gives the closed forms
//!
//! ```text
//! h  = L + g
//! H₁ = ∫₀ˣ h  = x(L − 1) + h
//! H₂ = ∫₀ˣ H₁ = (x²/2)(L − 3/2) + H₁
//! ```
//!
//! and, since eˣEin(x) = Σ_{n≥1} Hₙxⁿ/n! (Hₙ the harmonic numbers; from u′ − u = (eˣ−1)/x) and
//! g = eˣ(Ein(x) − L) for either sign of x, one series for all three:
//!
//! ```text
//! h  = Σ_{n≥1} (xⁿ/n!)(Hₙ − L),   H₁ = Σ_{n≥2} (xⁿ/n!)(Hₙ − L),   H₂ = Σ_{n≥3} (xⁿ/n!)(Hₙ − L)
//! ```
//!
//! (each term differentiates into the previous one's: d/dx[(xⁿ/n!)(Hₙ − L)] = (x^{n−1}/(n−1)!)(H_{n−1} − L)).
//! Near 0 the closed forms cancel catastrophically (h ~ −x ln|x|, H₁ ~ −(x²/2)ln|x|, H₂ ~ −(x³/6)ln|x|
//! against O(ln|x|) pieces); the series does not.
//!
//! Branch points (x > 0): every series term is positive while L < H_{m+1} (m = 0, 1, 2 for h, H₁, H₂),
//! i.e. x < 1.53, 2.53, 3.52; every closed-form piece is positive once L > 1, 1, 3/2 (x > 1.53, 1.53,
//! 2.53). So the series is used for x < 1, 2, 3 and the closed form beyond: no cancellation at all.
//!
//! Branch points (x < 0, y = −x): the series alternates, so it is used only for y < 1, where it loses
//! less than a factor ≈ 3 to cancellation. Beyond, the closed forms with g = −e^{−y}Ei(y) (scaled, no
//! overflow for any y). Each of h, H₁, H₂ has one negative zero (x = −1.1673, −2.0937, −3.0623):
//! near it the result is a small difference and only its absolute error (≈ 1e-16 × the size of
//! the pieces) is guaranteed.

use super::expint::{exp_e1, expm_ei, EULER_GAMMA};

/// Series for x > 0 is used below these points (h, H₁, H₂); see the module doc.
const SERIES_POS_UP_TO: [f64; 3] = [1.0, 2.0, 3.0];
/// Series for x < 0 is used for |x| below this point.
const SERIES_NEG_UP_TO: f64 = 1.0;

/// h(x) = ln|x| + γ + g(x), the kernel bracket of MATH.md §2 (h(0) = 0, h′ = g).
pub fn kernel_bracket(x: f64) -> f64 {
    bracket(x, 0)
}

/// H₁(x) = ∫₀ˣ h(t) dt = x(ln|x| + γ − 1) + h(x).
pub fn kernel_bracket_int1(x: f64) -> f64 {
    bracket(x, 1)
}

/// H₂(x) = ∫₀ˣ ∫₀ˢ h(t) dt ds = (x²/2)(ln|x| + γ − 3/2) + H₁(x).
pub fn kernel_bracket_int2(x: f64) -> f64 {
    bracket(x, 2)
}

/// m-th antiderivative (m = 0, 1, 2) of h, vanishing with its derivatives at 0.
fn bracket(x: f64, m: usize) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    if x == 0.0 {
        return 0.0;
    }
    if x.is_infinite() {
        // h, H₁ → +∞ as x → +∞; as x → −∞: h → +∞, H₁ → −∞, H₂ → +∞ (leading x^m·ln|x|/m!).
        return if x > 0.0 || m % 2 == 0 {
            f64::INFINITY
        } else {
            f64::NEG_INFINITY
        };
    }
    let use_series = if x > 0.0 {
        x < SERIES_POS_UP_TO[m]
    } else {
        -x < SERIES_NEG_UP_TO
    };
    if use_series {
        return series(x, m);
    }
    let l = EULER_GAMMA + x.abs().ln();
    // g(x): eˣE1(x) for x > 0, −e^{−y}Ei(y) with y = −x for x < 0.
    let g = if x > 0.0 { exp_e1(x) } else { -expm_ei(-x) };
    match m {
        0 => l + g,
        1 => x * (l - 1.0) + (l + g),
        _ => 0.5 * x * x * (l - 1.5) + x * (l - 1.0) + (l + g),
    }
}

/// Σ_{n≥m+1} (xⁿ/n!)(Hₙ − L), L = γ + ln|x|, for moderate |x| (≤ 3).
fn series(x: f64, m: usize) -> f64 {
    let l = EULER_GAMMA + x.abs().ln();
    let mut pow_fact = 1.0_f64; // xⁿ/n!
    let mut harmonic = 0.0_f64; // Hₙ
    let mut sum = 0.0_f64;
    for n in 1..400 {
        let fnn = n as f64;
        pow_fact *= x / fnn;
        harmonic += 1.0 / fnn;
        if n <= m {
            continue;
        }
        let term = pow_fact * (harmonic - l);
        let new = sum + term;
        // Stop once the terms are below the last bit of the sum and shrinking (|x| ≤ 3 < n).
        if new == sum && fnn > x.abs() {
            break;
        }
        sum = new;
    }
    sum
}
