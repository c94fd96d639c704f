//! The bonded viscoelastic layer solved by the thesis' collocation scheme (thesis §3.2, eq. 3.25,
//! Fig. 3; the same discretisation as `thesis`) with the layer kernel of
//! [`super::kernel`], at given contact length and at given load (the bracketed load loop of
//! [`crate::contact::load`]).
//!
//! Input: a [`LayerKernel`], λ or N′, the number of intervals n; output: a
//! [`DimensionlessSolution`] (scheme `layer`) and, at given load, an error estimate and the contact
//! checks ([`LayerAnswer`]).
//!
//! Eq. 3.25 holds for any kernel of the form K(ξ) + const: ∫₀^λ Q′(ξ′)[K(−ξ′) − K(ξ−ξ′)]dξ′ = ξβ − ξ²/2.
//! With hat functions of half-width Δ = λ/n the matrix entries are the hat averages A(i − j) of the
//! layer kernel (Toeplitz), rows i = 1…n, unknowns Q₁…Q_{n−1} and β.
//!
//! Convergence: the layer kernel has the half-space's log singularity plus a C^∞ part, so the scheme
//! keeps the half-space's orders (docs/DEVLOG.md "Speed and accuracy of the thesis scheme": λ first order in
//! Δ, ρF/N at given load ≈ 2.8 when the front-edge layer is resolved) once Δ also resolves the
//! layer's own length h′ (the pressure varies on that scale near the contact ends of a thin layer).
//! The error estimate compares the solutions at n/2 and n (λ and β Richardson-extrapolated, see
//! [`solve_layer_at_load`]), which doubles n until the estimate meets the tolerance, n reaches its
//! cap or the kernel table would cost more than `KERNEL_WORK_BUDGET` (layers thinner than
//! ~λ/100; a warning says so).
//!
//! # Speed (measured; issue 14 asks ≤ 2 ms at tol 1e−4 and ≤ 10 ms at 1e−6 per load point)
//! `cargo bench --bench contact_layer` profiles one solve at given λ (quiet machine, h = λ, ν = ½):
//! n = 256 costs 3 ms (1 term) to 6 ms (30 terms over 24 decades), of which the kernel table (half-
//! space part 0.1–1.7 ms, Fourier correction 1–1.8 ms) and the dense LU (≈ 2 ms) share about
//! equally; n = 1024 costs 155–171 ms, the LU ≈ 150 ms of it. A load point needs ~6 solves per n and
//! n doubled from 16 to where the Richardson estimate meets tol: n = 64–128 at 1e−3, 256–1024 at 1e−4,
//! and at 1e−6 n ~ 10⁴–10⁵ (first order), out of reach. So this scheme gives 4–30 ms at 1e−3 and
//! 20 ms–1 s at 1e−4 (docs/DEVLOG.md table) and cannot meet the goals, as the brief expected. The
//! options weighed (the Toeplitz solve was not built; the spectral solver was):
//! - keep the hat scheme and solve the Toeplitz-plus-rank-two system in O(n²) (Levinson with a
//!   bordering/Sherman–Morrison step; the kernel table cannot be reused across the load loop's λ
//!   iterations: it depends on λ through Δ relative to h′ and the creep lengths): removes the LU (the
//!   n = 1024 cost falls to its kernel table, 4–13 ms measured) but not the first order: 1e−6 still
//!   needs n ~ 10⁵;
//! - **a spectrally convergent solver** — built: [`super::spectral`] (the `auto` reduction with the
//!   layer term as a polynomial right-hand side, the design suggested here; the independent elastic
//!   solver of `elastic_check.rs` is its f = 0 case and agrees to 1e−13). It is the layer body's
//!   default; this scheme remains the fallback for covers too thin for its degree cap (h/λ below
//!   ≈ 0.016 at tol 1e−3, ≈ 0.03 at 1e−6) and the given-λ solver of `Body::Layer`.
//!
//! The assembly and solve are the thesis scheme's (`crate::contact::numerics::hat::solve_hat_system`,
//! shared: the system is the same for any kernel of the form K + const).

use super::kernel::LayerKernel;
use crate::contact::error::{positive, ContactError};
use crate::contact::load::{solve_at_load as load_loop, LoadSettings};
use crate::contact::problem::{BodyAnswer, DimensionlessSolution};

/// Settings of the layer solve at given load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LayerSettings {
    /// Relative tolerance on ρF/N and λ (estimate from the n/2 solve). Default 1e−3.
    pub tol: f64,
    /// First n (≥ 8; n/2 is solved too). Default 32.
    pub n_start: usize,
    /// Largest n (dense LU, O(n³)). Default 1024.
    pub n_max: usize,
    /// Load loop settings.
    pub load: LoadSettings,
    /// Solve by the spectral solver ([`super::spectral`]) first, this hat scheme only where the
    /// cover is too thin for it (default true; `layer_at_load`).
    pub spectral: bool,
    /// Largest degree of the spectral solver's layer term (default 48; module doc of
    /// [`super::spectral`]: the switch to this scheme).
    pub p_max: usize,
    /// Warm start of the spectral solver (λ guess, d ln N′/d ln λ), e.g. from a neighbouring map
    /// node; [`super::spectral::SpectralSettings::start`]. Default `None`.
    pub start: Option<(f64, f64)>,
    /// Run the spectral solver's closing contact checks ([`super::spectral::SpectralSettings::checks`]:
    /// the answer is the same without them, its check ratios NaN). The hat scheme always runs its
    /// own. Default true.
    pub checks: bool,
}

impl Default for LayerSettings {
    fn default() -> Self {
        Self {
            tol: 1e-3,
            n_start: 32,
            n_max: 1024,
            load: LoadSettings::default(),
            spectral: true,
            p_max: 48,
            start: None,
            checks: true,
        }
    }
}

/// A layer solution at given load with its checks.
#[derive(Debug, Clone, PartialEq)]
pub struct LayerAnswer {
    /// The solution at the finest n.
    pub solution: DimensionlessSolution,
    /// max(|Δλ|/λ, |Δ(ρF/N)|/|ρF/N|) between n/2 and n.
    pub error_estimate: f64,
    /// Smallest nodal pressure over the largest (≥ 0 for a valid contact, up to the scheme's ripple).
    pub min_pressure_ratio: f64,
    /// Smallest gap outside the contact (within λ/2 of either end) over the largest indentation.
    pub min_gap_ratio: f64,
    /// Warnings (tolerance not reached, contact checks).
    pub warnings: Vec<String>,
}

/// Solve eq. 3.25 on the layer at contact length `lambda` with `n` intervals.
pub fn solve_at_lambda(
    kernel: &LayerKernel,
    lambda: f64,
    n: usize,
) -> Result<DimensionlessSolution, ContactError> {
    positive("lambda", lambda)?;
    crate::contact::numerics::hat::check_intervals(n)?;
    let ratio = lambda / kernel.thickness();
    if ratio > LAMBDA_OVER_THICKNESS_MAX {
        return Err(ContactError::OutOfRange {
            scheme: "bonded-layer (a cover this thin against its contact is a Winkler foundation)",
            quantity: "contact length / cover thickness",
            value: ratio,
            bound: "at most",
            limit: LAMBDA_OVER_THICKNESS_MAX,
        });
    }
    let h = lambda / n as f64;
    let a = kernel.hat_averages(n, h);
    // the thesis' assembly and solve, shared (the system is the same for any kernel K + const)
    crate::contact::numerics::hat::solve_hat_system(&a, n, lambda, "layer")
}

/// An initial guess of λ at load N′ for the load loop: the glassy half-space width 2√N′ or, when
/// smaller, the thin-layer width (glassy constrained Winkler λ = (6c_W N′)^{1/3}, or the h³ law
/// λ = 2(15πh′³N′/2)^{1/5} at ν = ½, whichever is larger).
pub(crate) fn lambda_guess(load: f64, thickness: f64, nu: f64) -> f64 {
    use crate::contact::numerics::winkler::{winkler_coefficient, WinklerColumns};
    let hs = 2.0 * load.sqrt();
    let h3 = 2.0 * (7.5 * std::f64::consts::PI * thickness.powi(3) * load).powf(0.2);
    let w = winkler_coefficient(WinklerColumns::Constrained, thickness, nu)
        .map(|c| (6.0 * c * load).cbrt())
        .unwrap_or(0.0);
    hs.min(h3.max(w))
}

/// Solve at load N′ with `n` intervals (one load loop; the tests' fixed-n reference).
#[cfg(test)]
pub(crate) fn solve_at_load_n(
    kernel: &LayerKernel,
    load: f64,
    n: usize,
    settings: &LoadSettings,
    sum_f_over_b: f64,
) -> Result<DimensionlessSolution, ContactError> {
    solve_near(kernel, load, n, settings, None, sum_f_over_b)
}

/// The load loop at `n`, started from `near` (a coarser solve's λ) when given: the loop brackets λ
/// from 2√N′ up to 2√N′·√(1 + Σf/b), so its variable is rescaled to start at 0.995·λ_near with a
/// bracket of ±0.5 % (a coarse λ at n/2 is off by ~1/n; the loop widens the bracket by 1.25 when
/// needed). Saves about half the solves of a cold start.
fn solve_near(
    kernel: &LayerKernel,
    load: f64,
    n: usize,
    settings: &LoadSettings,
    near: Option<f64>,
    sum_f_over_b: f64,
) -> Result<DimensionlessSolution, ContactError> {
    positive("load N'", load)?;
    let (start, sfb) = match near {
        Some(l) => (0.995 * l, 1.01f64.powi(2) - 1.0),
        None => (
            lambda_guess(load, kernel.thickness(), kernel.poisson()),
            sum_f_over_b,
        ),
    };
    let scale = start / (2.0 * load.sqrt());
    load_loop(load, sfb, settings, |l| {
        solve_at_lambda(kernel, l * scale, n)
    })
}

/// Solve at load N′ to the settings' tolerance (n doubled from `n_start`), with checks.
///
/// λ and β converge to first order in Δ (observed order 1.00–1.01 for the half-space, docs/DEVLOG.md), so
/// they are Richardson-extrapolated, X_R(n) = 2X(n) − X(n/2), and their estimate is
/// |X_R(n) − X_R(n/2)| (the change of the extrapolation, which bounds the error of the coarser
/// extrapolation); ρF/N at given load converges faster (order ≈ 2.8 where the front layer is resolved)
/// and is taken from the finest n with the estimate [`FRICTION_SAFETY`]·|ρF/N(n) − ρF/N(n/2)|: on a
/// thin cover it converges only to first order, where the bare difference is the error itself. The pressure profile is the
/// finest solve's, its positions stretched to the extrapolated λ.
pub fn solve_layer_at_load(
    kernel: &LayerKernel,
    load: f64,
    settings: &LayerSettings,
) -> Result<LayerAnswer, ContactError> {
    let sfb = kernel.half_space().sum_f_over_b();
    let mut n = settings.n_start.max(8);
    let mut coarse = solve_near(kernel, load, n / 2, &settings.load, None, sfb)?;
    let mut prev_rich: Option<(f64, f64)> = None;
    let mut warnings = Vec::new();
    loop {
        let fine = solve_near(kernel, load, n, &settings.load, Some(coarse.lambda), sfb)?;
        let rich = (
            2.0 * fine.lambda - coarse.lambda,
            2.0 * fine.beta - coarse.beta,
        );
        let est_size = match prev_rich {
            // The change of the extrapolation, times RICHARDSON_SAFETY (see there).
            Some((l, b)) => RICHARDSON_SAFETY * rel(rich.0, l).max((rich.1 - b).abs() / rich.0),
            None => {
                rel(fine.lambda, coarse.lambda).max((fine.beta - coarse.beta).abs() / fine.lambda)
            }
        };
        let est = est_size.max(FRICTION_SAFETY * rel(fine.friction_rho, coarse.friction_rho));
        let over_budget = kernel_work(2 * n, fine.lambda, kernel.thickness()) > KERNEL_WORK_BUDGET;
        if est <= settings.tol || 2 * n > settings.n_max || over_budget {
            if est > settings.tol {
                warnings.push(format!(
                    "tolerance not reached: layer estimate {est:.1e} > tol {:.1e} at the largest n = {n}{} \
                     (a layer thin against the contact needs n ≳ 10·λ/h; the Winkler or h³ limit applies there)",
                    settings.tol,
                    if over_budget && 2 * n <= settings.n_max {
                        format!(" (cover/contact length {:.1e}: a finer kernel table would cost more than the budget)", kernel.thickness() / fine.lambda)
                    } else {
                        String::new()
                    }
                ));
            }
            let (min_pressure_ratio, min_gap_ratio) = contact_checks(kernel, &fine)?;
            if min_pressure_ratio < -1e-3 {
                warnings.push(format!(
                    "contact check: negative pressure inside the contact (min/max = {min_pressure_ratio:.2e})"
                ));
            }
            if min_gap_ratio < -1e-3 {
                warnings.push(format!(
                    "contact check: the body penetrates the roll outside the contact (min gap/indentation = {min_gap_ratio:.2e})"
                ));
            }
            let mut solution = fine;
            let stretch = rich.0 / solution.lambda;
            for x in solution.xi.iter_mut() {
                *x *= stretch;
            }
            solution.lambda = rich.0;
            solution.beta = rich.1;
            solution.error_estimate = Some(est);
            return Ok(LayerAnswer {
                solution,
                error_estimate: est,
                min_pressure_ratio,
                min_gap_ratio,
                warnings,
            });
        }
        prev_rich = Some(rich);
        coarse = fine;
        n *= 2;
    }
}

/// Largest contact length over cover thickness, λ/h′, at which one solve at λ is made. The kernel
/// table's linear quadrature has GL_ORDER·T_MAX·x_max/h′ nodes, x_max ≈ 1.5λ for the contact checks
/// (module doc of [`super::kernel`]), so at this bound a table holds about 4·10⁶ nodes (≈ 100 MB) and costs
/// ≈ 0.2 s at the starting n. Covers the scenes accept (h ≥ 10⁻⁴ R, `limits::COVER_OVER_RADIUS_MIN`)
/// under contacts of a ≤ 0.3 R stay below 3·10³; beyond it the thin-cover limits apply (the `auto`
/// choice takes the Winkler foundation there). Only a bracket search on a wild spectrum (a bootstrap
/// replicate fitted to a far-off point) reached it: λ/h′ ≈ 10⁵–10⁶, 4 GB per table, before this bound.
pub(crate) const LAMBDA_OVER_THICKNESS_MAX: f64 = 1e4;

/// Largest work (kernel-table operations, [`kernel_work`]) of one solve at given λ that the n-doubling
/// of [`solve_layer_at_load`] starts: about 0.1 s. Only layers thinner than ~λ/100 reach it before
/// n = 512 (the correction's quadrature needs panels of width ~h/2 up to k = 27/h over |x| ≤ 1.5λ).
pub(crate) const KERNEL_WORK_BUDGET: f64 = 1e8;

/// Operations of the layer kernel table at n intervals on a contact λ over a layer h′ (module doc of
/// [`super::kernel`]: (2m+1)·10·(panels), m = 1.5n for the contact checks, panels ≈ 30 + 27·1.5λ/h′·2).
pub(crate) fn kernel_work(n: usize, lambda: f64, thickness: f64) -> f64 {
    let m = 1.5 * n as f64;
    (2.0 * m + 1.0) * 10.0 * (30.0 + 81.0 * lambda / thickness)
}

/// Safety factor on the change of the Richardson-extrapolated λ and β between n/2 and n, used as
/// their error estimate: the property sweep (`tests/layer_props.rs`, `VISCOROLL_SEED=0x6e96a9fbdb9288b`
/// case 46: 3 terms, J∞/J_g = 150, h/λ = 0.4, ν = 0.27) found the bare change 1.9 times below the
/// true error of λ where the extrapolation is not yet asymptotic; 3 leaves a margin.
pub(crate) const RICHARDSON_SAFETY: f64 = 3.0;

/// Safety factor on the change of ρF/N between n/2 and n, used as its error estimate. Where the
/// front-edge layer is resolved ρF/N converges at order ≈ 2.8 and the change over-states the error
/// ~6×, but on a thin compressible cover it converges to first order: `tests/layer_thin_gains.rs`
/// (4 terms, h′ = 0.083, h/λ 0.063, ν 0.456) measured relative errors 2.4e−2, 1.1e−2, 5.4e−3,
/// 2.7e−3, 1.3e−3, 6.7e−4 at n = 32…1024 (Δ/h 0.5…0.02), the change 0.999 of the error, so the bare
/// change had no margin (an estimate of 6.71e−4 for an error of 6.70e−4). At order q the error is
/// the change over 2^q − 1; 2 leaves a margin of 2 at first order and bounds orders down to 0.58.
pub const FRICTION_SAFETY: f64 = 2.0;

/// Relative difference (0 for equal values).
fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / a.abs().max(b.abs())
    }
}

/// The answer at contact length λ with `n` intervals (rounded down to an even number, at least 4):
/// the solution, its error estimated from the same solve at n/2 (the largest relative change of β,
/// N′ and ρF/N) and its contact checks ([`contact_checks`]).
pub fn answer_at_lambda(
    kernel: &LayerKernel,
    lambda: f64,
    n: usize,
) -> Result<BodyAnswer, ContactError> {
    let n = n.max(4) / 2 * 2;
    let fine = solve_at_lambda(kernel, lambda, n)?;
    let coarse = solve_at_lambda(kernel, lambda, n / 2)?;
    let error_estimate = rel(fine.beta, coarse.beta)
        .max(rel(fine.load, coarse.load))
        .max(rel(fine.friction_rho, coarse.friction_rho));
    let (min_pressure_ratio, min_gap_ratio) = contact_checks(kernel, &fine)?;
    Ok(BodyAnswer {
        error_estimate,
        min_pressure_ratio,
        min_gap_ratio,
        warnings: Vec::new(),
        solution: fine,
    })
}

/// Pressure and gap checks of a solution: min nodal pressure / max, and the smallest gap at the nodes
/// within λ/2 outside either contact end over the largest indentation (eq. 3.25's left side minus
/// its right side; inside it vanishes).
pub fn contact_checks(
    kernel: &LayerKernel,
    sol: &DimensionlessSolution,
) -> Result<(f64, f64), ContactError> {
    let n = sol.n;
    let max_q = sol.pressure.iter().cloned().fold(0.0, f64::max);
    let min_q = sol.pressure.iter().cloned().fold(f64::INFINITY, f64::min);
    let ext = n / 2;
    let h = sol.lambda / n as f64;
    let m = n + ext;
    let a = kernel.check_hat_averages(m, h);
    let at = |k: i64| a[(k + m as i64) as usize];
    // s(i) = Σⱼ Qⱼ[A(−j) − A(i−j)] − (iΔβ − (iΔ)²/2): the body's deflection (eq. 3.19, relative to
    // the rear edge) minus the roll's depth (eq. 3.22); the roll is above the surface where s ≥ 0.
    let s = |i: i64| -> f64 {
        let x = i as f64 * h;
        let mut v = 0.0;
        for j in 1..n {
            v += sol.pressure[j] * (at(-(j as i64)) - at(i - j as i64));
        }
        v - (x * sol.beta - 0.5 * x * x)
    };
    let depth = sol.beta * sol.beta / 2.0; // the indentation scale (λ²/8 for Hertz)
    let mut min_gap = f64::INFINITY;
    for i in (-(ext as i64)..0).chain((n as i64 + 1)..=(n + ext) as i64) {
        min_gap = min_gap.min(s(i));
    }
    Ok((min_q / max_q, min_gap / depth.max(f64::MIN_POSITIVE)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::problem::CreepTerm;

    /// A solve at λ/h′ beyond the bound is refused before any kernel table is built (a bracket search
    /// on a wild bootstrap replicate asked for λ/h′ ≈ 10⁵–10⁶: gigabytes of quadrature nodes), and
    /// the largest ratio the bound admits is still solved.
    #[test]
    fn a_contact_far_longer_than_the_cover_is_refused_not_tabulated() {
        let terms = [CreepTerm { f: 1.0, b: 1.0 }];
        let kernel = LayerKernel::new(&terms, 1e-3, 0.5).unwrap();
        let beyond = 1.01 * LAMBDA_OVER_THICKNESS_MAX * 1e-3;
        match solve_at_lambda(&kernel, beyond, 8) {
            Err(ContactError::OutOfRange { value, limit, .. }) => {
                assert!(value > limit && (value / 1.01e4 - 1.0).abs() < 1e-12)
            }
            other => panic!("expected OutOfRange, got {other:?}"),
        }
        let within = 0.99 * LAMBDA_OVER_THICKNESS_MAX * 1e-3;
        assert!(solve_at_lambda(&kernel, within, 8).is_ok());
    }
}
