//! A spectrally convergent solver of the bonded viscoelastic layer at given λ and at given load: the
//! layer body's default (issue 14, "Numbers to reach"; the design weighed in [`super::collocation`]).
//!
//! Input: the dimensionless creep terms (fᵢ, bᵢ), λ or N′, the cover h′ = h/(VT), ν and a tolerance;
//! output: [`LambdaSolution`](crate::contact::numerics::at_lambda::LambdaSolution) at
//! given λ ([`at_lambda`]) or a [`LayerAnswer`](super::collocation::LayerAnswer) with its error
//! estimate and contact checks at given load ([`at_load`]; `None` for covers too thin for it).
//!
//! # The equation
//! The layer kernel is the half-space's minus the C^∞ correction D of [`super::kernel`]
//! (D̂(k) = −πR(|k|h′)Φ(k)/|k|). On the contact t ∈ [−1, 1] (ξ = L(1+t), L = λ/2, cᵢ = bᵢL,
//! dᵢ = fᵢL, μⱼ = κⱼL as in the half-space `auto` scheme, whose module doc derives the rest) the
//! derivative of eq. 3.25 becomes
//!
//! ```text
//!   π[H̃ + Σᵢ Ṽᵢ] = L(1+t) − β + G(t),     G = −d(ρv_R)/dξ,
//! ```
//!
//! with H̃ the finite Hilbert transform of Q′ = √(1−t²)Σa_kU_k (H̃ = ΣFₙTₙ, a_k = F_{k+1}, F₀ = 0)
//! and G the deflection slope of the correction, linear in the a_k ([`layer_term`]). G is C^∞ on the
//! scale h′/L, so its degree-p Chebyshev interpolant converges geometrically in p.
//!
//! # Reduction to (N + p + 2) linear equations
//! Split Ṽᵢ(t) = dᵢ∫_t^1e^{−cᵢ(u−t)}H̃(u)du + dᵢe^{−cᵢ(1−t)}Ĝᵢ, Ĝᵢ = ∫₀^∞e^{−cᵢσ}H̃ₑₓₜ(1+σ)dσ the
//! Laplace transform of the exterior continuation. The first part is a Volterra operator V = I + K,
//! K with the kernel k(s) = Σdᵢe^{−cᵢs}; its resolvent follows from 1/(1 + k̂(z)) =
//! Πᵢ(cᵢ+z)/Πⱼ(μⱼ+z) (the roots μⱼ of 1 + Σdᵢ/(cᵢ−μ) = 0, module `modes`):
//!
//! ```text
//!   V⁻¹g = g − Σⱼ wⱼ∫_t^1e^{−μⱼ(u−t)}g(u)du,     wⱼ = 1/Σᵢ dᵢ/(cᵢ−μⱼ)²
//! ```
//!
//! (one term: w = d, and V⁻¹V\[1\] = 1 checks by hand). So with r̃ = (L(1+t) − β + G)/π of degree p,
//! r̃ = Σx_mT_m, every solution on the contact is H̃ = Σₘ x_m V⁻¹\[T_m\] + Σⱼ Aⱼe^{μⱼ(t−1)}
//! (V e^{μⱼ(t−1)} = −Σᵢdᵢe^{−cᵢ(1−t)}/(cᵢ−μⱼ)), and the equation holds iff the coefficients of
//! every dᵢe^{−cᵢ(1−t)} cancel: N conditions Ĝᵢ[H̃] − ΣⱼAⱼ/(cᵢ−μⱼ) + (the same from V⁻¹\[T_m\]'s
//! exponential parts) = 0. Unknowns Aⱼ, x₀…x_p, β; equations: those N, F₀ = 0 (bounded at both
//! ends) and x_m = (L(δ_{m0} + δ_{m1}) − βδ_{m0} + g_m[H̃])/π for m = 0…p, g_m the Chebyshev
//! coefficients of G. For G = 0 this is exactly the `auto` reduction (p₀ + p₁t + ΣAⱼe^{μⱼ(t−1)}).
//! V⁻¹\[T_m\] is computed in Chebyshev coefficients by [`volterra`]: exactly (a tridiagonal solve)
//! for μⱼ < max(p²/4, 30), as a short polynomial plus a multiple of e^{μⱼ(t−1)} above. Fast modes
//! are lumped and slow ones dropped by the `auto` scheme's [`reduction`](crate::contact::numerics::reduction),
//! with its measured first-order lumping correction (the lumped modes' layers are far thinner than h′).
//!
//! # Convergence and error estimate (measured, the tests of [`at_lambda`])
//! Elastic (f = 0): p = 32 agrees with the independent Chebyshev–Bessel solver of `elastic_check.rs`
//! to ≤ 1e−13 for h/λ = 0.1…1, ν = 0…½ (p = 16: ≤ 2e−8 at h/λ = 0.1, 3e−13 at h/λ = 0.3).
//! Viscoelastic: p = 16 and 32 agree to 1e−15; the hat scheme's Richardson value (n = 1024) lies
//! within 2e−5 (its own accuracy); at h = 1e4·λ the half-space `auto` answer is met to ~1e−9 (the
//! physical (λ/h)² approach). The error falls like 10^{−2.5·p·h′/L}, so the degree starts at
//! p = 0.5·log₁₀(1/tol)·L/h′ ([`degree::degree_for`]; measured against degree 80 the rate is
//! 1.2/(1 + 0.3·L/h′) decades per degree, which sets the next degree when the check fails) and
//! the estimate compares p with p/2 at the λ found (the p/2 error bounds the p error: geometric
//! convergence; at the degree cap, where p/2 alone may not meet tol, 3·r·e(p/2) with r the ratio
//! of the p/2 and p/4 errors), mapped to λ through
//! d ln N′/d ln λ ≥ ½ and to ρF/N at given load with twice that, plus the reduction's and the
//! lumping correction's estimates of the `auto` scheme. Measured against tol 1e−9 refinements
//! (`tests/layer_props.rs`, property 4) the estimates are 100–1000× the true error.
//!
//! The lumping correction (ρF/N += λ·g_F·W, N′ ×= 1 + g_N·W, β += g_β·W, W = Σwᵢ of the lumped
//! modes) uses gains g measured by a solve with one lumped mode kept: a solve of the same layer
//! problem, so g carries a degree error too. It is measured at the degree p kept by the p/2 check,
//! with its p/2 companion from the same columns, and |g(p) − g(p/2)|·W is added to the estimate:
//! g converges geometrically in p like the solution (it is a difference quotient of two such
//! solutions), so the p/2 difference bounds the error of g(p) by the same argument as above. The
//! p/2 comparison of the solution cannot see this error (both degrees are corrected with the same
//! g). Until this was added, g came from the rule's first degree and was kept when the check
//! doubled it: on a thin compressible cover whose correction is 65 % of ρF/N (`tests/layer_thin_gains.rs`,
//! g_F = 0.016436, 0.016198, 0.016196 at p = 6, 12, ≥ 24), the answer at p = 48 was 1.0e−4 off
//! with an estimate of 4.1e−5; it is now 1.5e−6 off (the lumping's second-order term).
//! Last, ρF/N = L − β + … is a difference of O(λ) terms, so on a nearly elastic cover its round-off,
//! 8ε(λ + |β|)/|ρF/N| times the lumping's amplification (as in the half-space `auto` scheme), is
//! added too, and named in the warning when it is what keeps the estimate above tol.
//!
//! # Where it stops: the switch to the hat scheme
//! The layer term costs ~(L/h′)²·p per solve (κ up to 20L/h′, orders up to κ), so the degree is
//! capped at `p_max` = 48 (`LayerSettings`): covers with h′/L < 0.5·log₁₀(1/tol)/48, i.e. h/λ below
//! ≈ 0.016 at tol 1e−3 and ≈ 0.031 at 1e−6, are declined and `layer_at_load` solves them by the hat
//! collocation with a warning; the `auto` body choice takes the constrained Winkler foundation there
//! for compressible covers (docs/DEVLOG.md criterion table).
//!
//! # Speed (the former bench `layer_profile`, removed in issue 30 (docs/DEVLOG.md), docs/DEVLOG.md covers section)
//! A load point costs 4–5 solves at given λ (round 5; 5–9 before): one secant walk ([`walk`])
//! from a closed-form guess (the elastic layer seen as a half-space of the layer's compliance at
//! k = 4/λ, module [`secant`]) or the caller's warm start ([`at_load::SpectralSettings::start`]),
//! every solve at the answer's reduction and degree with its p/2 and p/4 companions from the same
//! columns ([`at_lambda::solve_at_lambda_triple`]) — a failed p/2 check raises the degree of the
//! *next* solve by the measured convergence rate, at no solve of its own — stopped when its last two
//! solves share reduction and degree and the linear carry to the root is accurate (the
//! interpolation remainder, module [`walk`]); then the lumping calibration at the last solve's λ and
//! degree (with its p/2 companion), and the carry through the last two solves (`at_load::to_root`).
//! The fine secant loop runs only where the measured gains moved the root too far for the carry;
//! the p/2 check is repeated at the λ found only when λ moved by ≥ 1e−3. The contact checks run on
//! 64 intervals (skipped with [`at_load::SpectralSettings::checks`] false: the bands' replicates).

pub(crate) mod at_lambda;
pub(crate) mod at_load;
pub(crate) mod degree;
pub(crate) mod layer_term;
pub(crate) mod secant;
pub(crate) mod volterra;
pub(crate) mod walk;

pub use at_load::{solve_spectral_at_load, SpectralSettings};

/// Test spectra: `n` creep terms with rates b log-spaced from 1e−12 over `decades` decades and
/// J∞/J_g = 1e3 shared equally (f = 999·b/n).
#[cfg(test)]
pub(crate) fn spread_terms(n: usize, decades: f64) -> Vec<crate::contact::problem::CreepTerm> {
    (0..n)
        .map(|k| {
            let b = 10f64.powf(-12.0 + decades * k as f64 / (n - 1) as f64);
            crate::contact::problem::CreepTerm {
                f: 999.0 / n as f64 * b,
                b,
            }
        })
        .collect()
}
