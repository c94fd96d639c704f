//! Surface compliance of an elastic layer of thickness h bonded to a rigid base (plane strain), in
//! Fourier space; the Winkler foundation it tends to when the layer is thin is
//! `contact::numerics::winkler`.
//!
//! Input: the dimensionless wave number t = |k|h and Poisson's ratio ν; output: the factor F(t) by
//! which the layer's compliance differs from the half-space's.
//!
//! # The bonded layer (derivation)
//! Layer 0 ≤ z ≤ h (z into the body), rigid base at z = h (u_x = u_z = 0), surface z = 0 free of shear
//! and loaded by a pressure p cos kx. Navier's equations in plane strain for u_x = U(z) sin kx,
//! u_z = W(z) cos kx, with λ_L, μ the Lamé constants,
//!
//! ```text
//!   μU″ − (λ_L+2μ)k²U − (λ_L+μ)kW′ = 0,     (λ_L+2μ)W″ − μk²W + (λ_L+μ)kU′ = 0,
//! ```
//!
//! have the solutions (A + Bz)e^{kz} + (C + Dz)e^{−kz}; the four constants follow from the two base
//! and the two surface conditions (σ_xz = 0, σ_zz = −p cos kx). The surface deflection is
//!
//! ```text
//!   W(0) = ((1−ν)/μ)·(p/|k|)·F(|k|h),
//!   F(t) = [κ sinh 2t − 2t] / [κ cosh 2t + 2t² + (1+κ²)/2],     κ = 3 − 4ν,
//! ```
//!
//! the classical result for a layer bonded to a rigid base (Johnson, *Contact Mechanics*, CUP 1985,
//! §5.9 and the references there; Meijers, Appl. Sci. Res. 18, 1968; Vorovich et al. 1974). We
//! checked the closed form against a Chebyshev collocation of the boundary-value problem above (ν = 0,
//! 0.3, 0.45, 0.49; t = 0.05…3: 12 digits alike); the unit tests check its three limits:
//! - t → ∞: F → 1, the half-space (Boussinesq–Flamant) compliance (1−ν)/(μ|k|) (thesis eq. 3.1–3.4);
//! - t → 0, ν < ½: F ≈ t(1−2ν)/(2(1−ν)²), i.e. W(0) = p·h/M with M = 2μ(1−ν)/(1−2ν) the constrained
//!   (oedometric) modulus: the thin compressible layer is a Winkler foundation of stiffness k = M/h;
//! - t → 0, ν = ½ (κ = 1): F ≈ 2t³/3, i.e. W(0) = h³k²p/(3μ), in real space u = −(h³/(3μ))p″:
//!   the thin incompressible layer's h³ law (Johnson §5.9).
//!
//! For numerical work we need R(t) = 1 − F(t) ≥ 0 without cancellation; subtracting the fractions,
//!
//! ```text
//!   R(t) = [κe^{−2t} + 2t² + 2t + (1+κ²)/2] / [κ cosh 2t + 2t² + (1+κ²)/2],
//! ```
//!
//! which decays like (4t²/κ)e^{−2t}: the layer differs from the half-space only at wavelengths
//! longer than about h.
//!
//! # Units of the rolling problem
//! In the thesis' units (§3.2: lengths in V·T, Q′ = (R/VT)·C·q/π with C = (1−ν)/μ₀) the half-space's
//! scaled deflection ρ·v has the Fourier multiplier π/|k| (the transform of −log|ξ|); the layer's is
//! π·F(|k|h′)/|k| with h′ = h/(VT). Its thin compressible limit, the Winkler foundation
//! ρ·v = c_W·Q′ of constrained columns, has c_W = π·h′/(M·C) = π·h′(1−2ν)/(2(1−ν)²)
//! (`numerics::winkler::winkler_coefficient`, with the uniaxial columns of conveyor design tools).

/// κ = 3 − 4ν (plane strain Kolosov constant).
pub(crate) fn kolosov(nu: f64) -> f64 {
    3.0 - 4.0 * nu
}

/// F(t) = [κ sinh 2t − 2t]/[κ cosh 2t + 2t² + (1+κ²)/2], t = |k|h ≥ 0: the layer's compliance over
/// the half-space's at wave number k.
pub(crate) fn layer_factor(t: f64, nu: f64) -> f64 {
    1.0 - layer_defect(t, nu)
}

/// R(t) = 1 − F(t) in the cancellation-free form of the module doc (R(0) = 1, R(∞) = 0).
pub fn layer_defect(t: f64, nu: f64) -> f64 {
    let t = t.abs();
    let k = kolosov(nu);
    let c = 0.5 * (1.0 + k * k);
    let poly = 2.0 * t * t + c;
    if t > 20.0 {
        // Divide by e^{2t}: R = [κe^{−4t} + (2t² + 2t + c)e^{−2t}] / [κ(1 + e^{−4t})/2 + poly·e^{−2t}].
        let e2 = (-2.0 * t).exp();
        let e4 = e2 * e2;
        (k * e4 + (poly + 2.0 * t) * e2) / (0.5 * k * (1.0 + e4) + poly * e2)
    } else {
        (k * (-2.0 * t).exp() + poly + 2.0 * t) / (k * (2.0 * t).cosh() + poly)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_space_limit() {
        // F(t) → 1 like (4t²/κ)e^{−2t}: at t = 30 that is 1e−23, below double precision.
        for nu in [0.0, 0.3, 0.5] {
            assert!((layer_factor(30.0, nu) - 1.0).abs() < 1e-15);
            let r = layer_defect(10.0, nu);
            let lead = 4.0 * 100.0 / kolosov(nu) * (-20.0f64).exp();
            // next terms are relative O(1/t) = 10 %
            assert!((r / lead - 1.0).abs() < 0.3, "nu {nu}: {r} vs {lead}");
        }
    }

    #[test]
    fn thin_compressible_is_constrained_winkler() {
        // F(t)/t → (1−2ν)/(2(1−ν)²); the next term is O(t²), so at t = 1e−4 the ratio holds to ~1e−8.
        for nu in [0.0, 0.25, 0.45] {
            let t = 1e-4;
            let want = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu) * (1.0 - nu));
            let got = layer_factor(t, nu) / t;
            assert!((got / want - 1.0).abs() < 1e-6, "nu {nu}: {got} vs {want}");
        }
    }

    #[test]
    fn thin_incompressible_is_h_cubed_law() {
        // ν = ½: F(t) = 2t³/3 + O(t⁵); at t = 1e−3 relative 1e−6 (and 1 − F loses ~1e−16/1e−9 = 1e−7).
        let t = 1e-3;
        let got = layer_factor(t, 0.5);
        assert!((got / (2.0 * t * t * t / 3.0) - 1.0).abs() < 1e-5, "{got}");
    }

    #[test]
    fn defect_form_matches_direct_fraction() {
        // The two algebraic forms agree where neither cancels (t ~ 1): to rounding.
        for nu in [0.0, 0.2, 0.5] {
            for t in [0.3_f64, 1.0, 3.0, 19.0, 21.0] {
                let k = kolosov(nu);
                let direct = (k * (2.0 * t).sinh() - 2.0 * t)
                    / (k * (2.0 * t).cosh() + 2.0 * t * t + 0.5 * (1.0 + k * k));
                assert!((layer_factor(t, nu) - direct).abs() < 1e-14, "{nu} {t}");
            }
        }
    }
}
