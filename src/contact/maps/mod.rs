//! Friction maps from one reduced variable: a compound's rolling friction over many speeds, loads and
//! temperatures from a 1-D interpolant of the dimensionless contact solution.
//!
//! Input: a `CreepSpectrum` at its reference temperature (+ the shift law's log10 a_T per
//! temperature) and map points (radius, load, speed, a_T); output: [`ReducedCurve`] (the interpolant,
//! with its error estimate and solve count) and, per point, friction F*/N* and contact length.
//!
//! # Why one variable suffices (exact; docs/MATH.md §13)
//! A scene (R, N*, V) on J(t) = J_g + Σᵢ Jᵢ(1 − e^(−t/(a_T τᵢ))) at temperature T (the shift acts on
//! the times only, docs/MATH.md §6) is made dimensionless in [`crate::contact::scene`] with
//! T_c = l_g/V, l_g = 2√(2RCN*/π) the glassy Hertz length, C = (1−ν)/μ₀ (thesis eq. 3.8, 3.24):
//!
//! - bᵢ = T_c/(a_T τᵢ) = s/τᵢ and fᵢ = (Jᵢ/J_g)·bᵢ with the **reduced variable s = l_g/(V·a_T)** (s),
//! - N′ = (R/l_g)·C·(2/π)·N*/l_g = 1/4 for every scene, ρ = R/l_g.
//!
//! So the dimensionless problem (eq. 3.25 with the load condition eq. 3.24), and hence its solution
//! φ = ρF/N, λ and β, depends on the compound and on s alone. Back in SI units (eq. 3.12):
//!
//!   F*/N* = φ(s)·l_g/R,   contact length l = λ(s)·l_g,   F* = (F*/N*)·N*.
//!
//! Speed, load, radius and temperature enter only through s and the two scale factors; the tests
//! check this against direct `contact::roll` solves of scenes sharing s.
//!
//! # The interpolant
//! y₁ = ln φ and y₂ = ln λ are smooth functions of x = ln s (λ runs from 1 at the glassy end to
//! √(J∞/J_g) at the relaxed end; φ is a loss peak spread over the spectrum's decades, with power-law
//! tails). Working with logarithms makes an absolute error in y a relative error in φ and λ. On
//! [x_lo, x_hi] (the range the map needs) we use piecewise Chebyshev interpolation: each panel
//! (initially [`MapSettings::panel_width`], four decades of s) holds the degree-n interpolant at the
//! n+1 Chebyshev–Lobatto points cos(πk/n), coefficients by the discrete cosine transform
//! (Trefethen, *Approximation Theory and Approximation Practice*, ch. 3–4, 8).
//!
//! Error estimate: twice the sum of the magnitudes of the last quarter of the coefficients. For a
//! resolved function they decay geometrically and bound the neglected tail; for an unresolved one
//! they plateau and the estimate stays large. (A discrete spectrum with terms every 0.5 decade puts
//! ripples of relative size ~1e−5 and period 0.5 decade on ln φ; the last two coefficients alone
//! happened to be small on such a plateau and let a 3e−5 error pass at tol 1e−5, which is why the
//! estimate looks at a quarter of them.) A panel whose estimate exceeds half the map's tolerance
//! doubles its degree (16 → 32, reusing the nodes, since the Lobatto points of n are those of 2n
//! with even index), then is halved; all pending nodes are solved in parallel (rayon). The node
//! solves use the `auto` scheme at [`node_tol`] (≤ tol/10, so the solver's error times the Lebesgue
//! constant, ≈ 3 for n ≤ 32, stays below a third of the tolerance).
//!
//! Measured (tests, 33-term spectrum over 16 decades, 12 random off-node scenes against 1e−8 direct
//! solves): at tol 1e−4 the estimate 2.3e−5 and the worst error 3e−8; at tol 1e−6, 6.9e−8 and
//! 4.9e−9. With the estimate from the last quarter alone (no factor 2) the worst error was 1.4× the
//! estimate, still inside the tolerance thanks to the half-tolerance budget; the factor 2 covers it.

mod covered;
mod covered_problem;
#[cfg(test)]
mod covered_tests;
mod curve;
mod nodes;
mod reduced;
mod surface;

pub use covered::covered_map;
pub use covered_problem::CoveredProblem;
pub use curve::ReducedCurve;
pub use reduced::ReducedProblem;
#[cfg(test)]
pub use surface::CoveredSurface;

use crate::contact::error::ContactError;
use rayon::prelude::*;

/// Largest number of panels (a bound on the work: ~16 solves each; never reached in the tests).
const MAX_PANELS: usize = 512;

/// Why a friction map could not be built.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum FrictionMapError {
    /// A value of the spectrum or a map point is not usable.
    #[error("{field} = {value}: {expected}")]
    BadValue {
        /// The field.
        field: String,
        /// Its value.
        value: f64,
        /// What was expected.
        expected: &'static str,
    },
    /// A node solve failed.
    #[error("contact solve at reduced time s = {s_s:e} s: {source}")]
    Solve {
        /// The reduced variable s = l_g/(V·a_T) in s.
        s_s: f64,
        /// The solver's error.
        source: ContactError,
    },
    /// The friction at a node is not positive (ln φ undefined).
    #[error("friction ρF/N = {phi:e} at reduced time s = {s_s:e} s is not > 0; the map cannot be interpolated in ln F/N")]
    NonPositive {
        /// s in s.
        s_s: f64,
        /// ρF/N.
        phi: f64,
    },
    /// Refinement did not reach the tolerance within the panel limit.
    #[error("interpolation error {estimate:e} > tolerance {tol:e} after {panels} panels")]
    NotConverged {
        /// Estimate reached.
        estimate: f64,
        /// Tolerance asked for.
        tol: f64,
        /// Panels used.
        panels: usize,
    },
}

/// Settings of a map.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapSettings {
    /// Relative tolerance on F/N and contact length at every map point (default 1e−6, the main
    /// job's direct-solve tolerance; allowed 1e−10 … 1e−2).
    pub tol: f64,
    /// Initial panel width in ln s (default 4·ln 10, four decades: on the shipped compounds this with
    /// degrees 16 → 32 took the fewest solves of the widths 3–8 decades and degrees 12–64 tried).
    pub panel_width: f64,
    /// Starting degree n of each panel's Chebyshev interpolant (n + 1 nodes; default 16).
    pub start_degree: usize,
    /// Largest degree before a panel is halved (default 32); degrees double, reusing the nodes.
    pub max_degree: usize,
    /// Covered maps: initial panel width in y = ln η (default `surface::ETA_PANEL_WIDTH`).
    pub eta_panel_width: f64,
    /// Covered maps: starting degree in y; 0 (the default) chooses it per panel from the panel's
    /// width and the tolerance ([`CoveredSurface`]).
    pub eta_start_degree: usize,
    /// Covered maps: the layer node solves' tolerance as a fraction of `tol` (default
    /// [`COVERED_NODE_TOL_RATIO`]; the node errors enter the surface's estimate times the Lebesgue
    /// constants, [`CoveredSurface`]).
    pub node_tol_ratio: f64,
}

/// Default tolerance of a covered map's node solves over the map's: the spectral layer solve costs
/// about the same at 1e−3 and 1e−6 (the former bench `maps_covered`, removed in issue 30 (docs/DEVLOG.md)), so its
/// error, times the Lebesgue constants (≈ 5–6), is kept small beside the interpolation's.
pub const COVERED_NODE_TOL_RATIO: f64 = 0.01;

impl Default for MapSettings {
    fn default() -> Self {
        MapSettings {
            tol: 1e-6,
            panel_width: 4.0 * std::f64::consts::LN_10,
            start_degree: 16,
            max_degree: 32,
            eta_panel_width: surface::ETA_PANEL_WIDTH,
            eta_start_degree: surface::ETA_START_DEGREE,
            node_tol_ratio: COVERED_NODE_TOL_RATIO,
        }
    }
}

impl MapSettings {
    /// The settings of a covered map at `tol`: panels of four decades in s starting at degree 8 in
    /// s (doubled to 16 and 32 reusing the nodes; measured on the shipped and synthetic compounds,
    /// `cargo bench --bench maps`: fewer layer solves than starting at 12 or 16, or panels of 3 or
    /// 6 decades), the degree in η chosen per panel.
    pub fn covered(tol: f64) -> Self {
        MapSettings {
            tol,
            start_degree: 8,
            ..MapSettings::default()
        }
    }
}

/// One point of a map, in SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapQuery {
    /// Roll radius in m.
    pub radius_m: f64,
    /// Load per unit width in N/m.
    pub load_n_per_m: f64,
    /// Speed in m/s.
    pub speed_m_s: f64,
    /// Shift factor a_T (not its log).
    pub a_t: f64,
}

/// The answer at one map point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapValue {
    /// F*/N* (eq. 3.12).
    pub friction: f64,
    /// Contact length in m.
    pub contact_length_m: f64,
}

/// Friction and contact length at every query from one interpolant built over their range of s
/// (module doc). Queries must have finite positive fields.
pub fn friction_map(
    problem: &ReducedProblem,
    queries: &[MapQuery],
    settings: &MapSettings,
) -> Result<(Vec<MapValue>, ReducedCurve), FrictionMapError> {
    let xs = reduced_times(problem, queries)?;
    let lo = xs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = xs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let curve = ReducedCurve::build(problem, lo, hi, settings)?;
    let values = queries
        .par_iter()
        .zip(xs.par_iter())
        .map(|(q, &x)| {
            let (phi, lambda) = curve
                .eval(x)
                .expect("every query's ln s lies in the interpolant's range by construction");
            let lg = problem.glassy_length_m(q.radius_m, q.load_n_per_m);
            MapValue {
                // F*/N* = (ρF/N)/ρ with ρ = R/l_g; l = λ·l_g.
                friction: phi * lg / q.radius_m,
                contact_length_m: lambda * lg,
            }
        })
        .collect();
    Ok((values, curve))
}

/// x = ln s of every query (checked: finite positive fields, at least one query).
pub(crate) fn reduced_times(
    problem: &ReducedProblem,
    queries: &[MapQuery],
) -> Result<Vec<f64>, FrictionMapError> {
    if queries.is_empty() {
        return Err(FrictionMapError::BadValue {
            field: "points".into(),
            value: 0.0,
            expected: "at least one map point",
        });
    }
    let mut xs = Vec::with_capacity(queries.len());
    for (i, q) in queries.iter().enumerate() {
        for (name, v) in [
            ("radius_m", q.radius_m),
            ("load_n_per_m", q.load_n_per_m),
            ("speed_m_s", q.speed_m_s),
            ("a_t", q.a_t),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(FrictionMapError::BadValue {
                    field: format!("point {i}: {name}"),
                    value: v,
                    expected: "finite and > 0",
                });
            }
        }
        let x = problem
            .reduced_time_s(q.radius_m, q.load_n_per_m, q.speed_m_s, q.a_t)
            .ln();
        if !x.is_finite() {
            return Err(FrictionMapError::BadValue {
                field: format!("point {i}: ln s"),
                value: x,
                expected: "finite (a_T or the speed out of range)",
            });
        }
        xs.push(x);
    }
    Ok(xs)
}

// Tests of the reduced-variable friction maps: the exact scaling against direct scene solves, the
// interpolant against direct solves at random off-node points, the Chebyshev machinery on known
// functions, and input errors.
#[cfg(test)]
mod tests {
    use super::curve::tail;
    use super::*;
    use crate::contact::{roll, AutoSettings, Body, ContactSettings, Scene, Scheme};
    use crate::special::chebyshev::{clenshaw, lobatto_coefficients};
    use crate::testdata::{broad_spectrum, SplitMix64};
    use crate::CreepSpectrum;
    use crate::ShiftLaw;
    use std::f64::consts::PI;

    fn creep() -> CreepSpectrum {
        crate::creep::relaxation_to_creep(&broad_spectrum())
            .expect("broad spectrum converts")
            .0
    }

    /// A WLF law with the universal constants (Williams, Landel & Ferry 1955) at T_ref = 20 °C:
    /// log a_T from +12.8 at −40 °C to −2.5 at +60 °C.
    fn wlf() -> ShiftLaw {
        ShiftLaw::Wlf {
            t_ref_c: 20.0,
            c1: 8.86,
            c2_k: 101.6,
        }
    }

    /// Reference solves: the `auto` scheme at 1e−8 (its 1e−7…1e−9 solves agree to ~1e−9).
    fn reference() -> AutoSettings {
        AutoSettings {
            tol: 1e-8,
            gap_check: false,
            ..AutoSettings::default()
        }
    }

    /// [`reference`] for the direct solves of whole scenes.
    fn reference_roll() -> ContactSettings {
        ContactSettings {
            scheme: Scheme::Auto,
            auto: reference(),
            ..ContactSettings::default()
        }
    }

    fn rel(a: f64, b: f64) -> f64 {
        ((a - b) / b).abs()
    }

    #[test]
    fn scenes_sharing_s_share_the_dimensionless_answer() {
        let c = creep();
        let law = wlf();
        let p = ReducedProblem::new(&c, None).unwrap();
        // Base scene at 0 °C; the others change R, N*, V and T so that s = l_g/(V a_T) is unchanged:
        // l_g ∝ √(R N*), so R×9 needs V×3, N*×4 needs V×2, and T → T′ needs V×a_T(T)/a_T(T′).
        let a = |t: f64| 10f64.powf(law.log10_a_t(t));
        let (r0, n0, v0, t0) = (0.05, 5000.0, 2.0, 0.0);
        let cases = [
            (r0, n0, v0, t0),
            (9.0 * r0, n0, 3.0 * v0, t0),
            (r0, 4.0 * n0, 2.0 * v0, t0),
            (r0, n0, v0 * a(t0) / a(10.0), 10.0),
            (4.0 * r0, 0.25 * n0, v0 * a(t0) / a(-10.0), -10.0),
        ];
        let s0 = p.reduced_time_s(r0, n0, v0, a(t0));
        let mut first: Option<(f64, f64)> = None;
        for &(r, n, v, t) in &cases {
            assert!(rel(p.reduced_time_s(r, n, v, a(t)), s0) < 1e-12);
            let at = c.at_temperature(&law, t, None).unwrap();
            let scene = Scene {
                radius_m: r,
                load_n_per_m: n,
                speed_m_s: v,
                poisson: None,
                body: Body::HALF_SPACE,
            };
            let sol = roll(&scene, &at.spectrum, &reference_roll()).unwrap();
            let d = &sol.dimensionless;
            // Same dimensionless problem up to rounding of bᵢ (~1e−15), each solve within 1e−8 of it.
            match first {
                None => first = Some((d.friction_rho, d.lambda)),
                Some((fr, la)) => {
                    assert!(
                        rel(d.friction_rho, fr) < 3e-8,
                        "{t} °C: {} vs {fr}",
                        d.friction_rho
                    );
                    assert!(rel(d.lambda, la) < 3e-8, "{t} °C: {} vs {la}", d.lambda);
                }
            }
            // The exact scalings back to SI: F/N = φ·l_g/R, l = λ·l_g.
            let lg = p.glassy_length_m(r, n);
            assert!(rel(sol.friction, d.friction_rho * lg / r) < 1e-12);
            assert!(rel(sol.contact_length_m, d.lambda * lg) < 1e-12);
        }
        // And the reduced solve at ln s0 is that same answer.
        let red = p.solve(s0.ln(), &reference()).unwrap();
        let (fr, la) = first.unwrap();
        assert!(rel(red.friction_rho, fr) < 3e-8 && rel(red.lambda, la) < 3e-8);
    }

    #[test]
    fn different_s_reproduce_roll() {
        let c = creep();
        let law = wlf();
        let p = ReducedProblem::new(&c, None).unwrap();
        for &(r, n, v, t) in &[
            (0.0665, 1e4, 4.0, -30.0),
            (0.3, 2e4, 20.0, 20.0),
            (0.0665, 3e3, 0.5, 50.0),
        ] {
            let at = c.at_temperature(&law, t, None).unwrap();
            let scene = Scene {
                radius_m: r,
                load_n_per_m: n,
                speed_m_s: v,
                poisson: None,
                body: Body::HALF_SPACE,
            };
            let direct = roll(&scene, &at.spectrum, &reference_roll()).unwrap();
            let s = p.reduced_time_s(r, n, v, 10f64.powf(at.log10_a_t));
            let red = p.solve(s.ln(), &reference()).unwrap();
            let lg = p.glassy_length_m(r, n);
            // Both at 1e−8: agreement to a few 1e−8.
            assert!(
                rel(red.friction_rho * lg / r, direct.friction) < 3e-8,
                "{t} °C"
            );
            assert!(
                rel(red.lambda * lg, direct.contact_length_m) < 3e-8,
                "{t} °C"
            );
        }
    }

    #[test]
    fn map_matches_direct_solves_at_random_points() {
        let c = creep();
        let law = wlf();
        let p = ReducedProblem::new(&c, None).unwrap();
        let mut rng = SplitMix64::new(8);
        let mut pick = |lo: f64, hi: f64| lo + (hi - lo) * rng.uniform();
        // 300 random scenes: V in 0.5…40 m/s, N* in 2…50 kN/m (log-uniform), T in −40…60 °C.
        let scenes: Vec<(f64, f64, f64, f64)> = (0..300)
            .map(|k| {
                let r = if k % 2 == 0 { 0.0665 } else { 0.3 };
                let v = pick(0.5f64.ln(), 40f64.ln()).exp();
                let n = pick(2e3f64.ln(), 5e4f64.ln()).exp();
                let t = pick(-40.0, 60.0);
                (r, n, v, t)
            })
            .collect();
        let queries: Vec<MapQuery> = scenes
            .iter()
            .map(|&(r, n, v, t)| MapQuery {
                radius_m: r,
                load_n_per_m: n,
                speed_m_s: v,
                a_t: 10f64.powf(law.log10_a_t(t)),
            })
            .collect();
        // Every 25th point against a direct scene solve (random points are off the nodes).
        let direct: Vec<(usize, f64, f64)> = scenes
            .iter()
            .enumerate()
            .step_by(25)
            .map(|(k, &(r, n, v, t))| {
                let at = c.at_temperature(&law, t, None).unwrap();
                let scene = Scene {
                    radius_m: r,
                    load_n_per_m: n,
                    speed_m_s: v,
                    poisson: None,
                    body: Body::HALF_SPACE,
                };
                let d = roll(&scene, &at.spectrum, &reference_roll()).unwrap();
                (k, d.friction, d.contact_length_m)
            })
            .collect();
        // The map's tolerance must hold for F/N and the contact length at the main job's 1e−4 and at
        // 1e−6, with the 1e−8 reference's own error negligible beside it.
        for tol in [1e-4, 1e-6] {
            let settings = MapSettings {
                tol,
                ..MapSettings::default()
            };
            let (values, curve) = friction_map(&p, &queries, &settings).unwrap();
            assert!(curve.error_estimate <= 0.5 * tol);
            assert_eq!(values.len(), queries.len());
            let mut worst = 0.0f64;
            for &(k, f, l) in &direct {
                let m = values[k];
                let e = rel(m.friction, f).max(rel(m.contact_length_m, l));
                assert!(e <= tol, "tol {tol:e}: point {k} {:?}: {e:e}", scenes[k]);
                worst = worst.max(e);
            }
            eprintln!(
                "tol {tol:e}: map vs direct: worst relative error {worst:.2e}; estimate {:.2e}, {} solves, {} panels",
                curve.error_estimate,
                curve.solves,
                curve.panels()
            );
            assert!(
                worst > 0.0,
                "the map is an interpolant, not a copy of the solves"
            );
        }
    }

    #[test]
    fn chebyshev_interpolation_is_exact_for_polynomials_and_estimates_exp() {
        // T₃ sampled at the 17 Lobatto points has coefficients δ_j3 (to rounding).
        let n = 16;
        let t: Vec<f64> = (0..=n).map(|k| (PI * k as f64 / n as f64).cos()).collect();
        let c = lobatto_coefficients(
            &t.iter()
                .map(|&x| 4.0 * x * x * x - 3.0 * x)
                .collect::<Vec<_>>(),
        );
        for (j, cj) in c.iter().enumerate() {
            let want = if j == 3 { 1.0 } else { 0.0 };
            assert!((cj - want).abs() < 1e-14, "c[{j}] = {cj}");
        }
        // e^{4x} on [−1, 1]: the degree-16 interpolant's true error (≈ 2·I₁₇(4) ≈ 1e−9, the first
        // neglected coefficient, c_j = 2I_j(4)) is below the estimate Σ_{j≥12}|c_j| ≈ 2I₁₂(4) ≈ 2e−5.
        let f = |x: f64| (4.0 * x).exp();
        let c = lobatto_coefficients(&t.iter().map(|&x| f(x)).collect::<Vec<_>>());
        let est = tail(&c);
        let err = (0..=1000)
            .map(|k| -1.0 + 2.0 * k as f64 / 1000.0)
            .map(|x| (clenshaw(&c, x) - f(x)).abs())
            .fold(0.0, f64::max);
        assert!(err <= est && est < 1e-4, "error {err:e}, estimate {est:e}");
    }

    #[test]
    fn bad_inputs_name_the_field() {
        let c = creep();
        let p = ReducedProblem::new(&c, None).unwrap();
        let q = MapQuery {
            radius_m: 0.1,
            load_n_per_m: 1e4,
            speed_m_s: 0.0,
            a_t: 1.0,
        };
        let e = friction_map(&p, &[q], &MapSettings::default()).unwrap_err();
        assert!(e.to_string().contains("speed_m_s"), "{e}");
        let e = friction_map(&p, &[], &MapSettings::default()).unwrap_err();
        assert!(e.to_string().contains("points"), "{e}");
        let bad_tol = MapSettings {
            tol: 0.5,
            ..MapSettings::default()
        };
        let q = MapQuery {
            speed_m_s: 1.0,
            ..q
        };
        let e = friction_map(&p, &[q], &bad_tol).unwrap_err();
        assert!(e.to_string().contains("tol"), "{e}");
        let e = ReducedProblem::new(&c, Some(0.7)).unwrap_err();
        assert!(e.to_string().contains("poisson"), "{e}");
    }
}
