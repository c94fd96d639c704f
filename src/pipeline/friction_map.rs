//! Friction maps from one reduced variable: a compound's rolling friction over many speeds, loads and
//! temperatures from a 1-D interpolant of the dimensionless contact solution.
//!
//! Input: a [`CreepSpectrum`] at its reference temperature (+ the shift law's log10 a_T per
//! temperature) and map points (radius, load, speed, a_T); output: [`ReducedCurve`] (the interpolant,
//! with its error estimate and solve count) and, per point, friction F*/N* and contact length.
//!
//! # Why one variable suffices (exact)
//! A scene (R, N*, V) on J(t) = J_g + Σᵢ Jᵢ(1 − e^(−t/(a_T τᵢ))) at temperature T (the shift acts on
//! the times only, MATH.md §6) is made dimensionless in [`crate::contact::scene`] with
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
//! check this against direct `roll_auto` solves of scenes sharing s.
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

use crate::contact::half_space::auto::{solve_auto_at_load, AutoSettings};
use crate::contact::ContactError;
use crate::contact::CreepTerm;
use crate::special::chebyshev::{clenshaw, lobatto_coefficients};
use crate::{CreepSpectrum, ModulusKind};
use rayon::prelude::*;
use std::f64::consts::PI;

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
}

impl Default for MapSettings {
    fn default() -> Self {
        MapSettings {
            tol: 1e-6,
            panel_width: 4.0 * std::f64::consts::LN_10,
            start_degree: 16,
            max_degree: 32,
        }
    }
}

/// The compound's part of the dimensionless problem: Jᵢ/J_g and τᵢ (at the reference temperature),
/// and the compliance factor C.
#[derive(Debug, Clone, PartialEq)]
pub struct ReducedProblem {
    /// (Jᵢ/J_g, τᵢ in s) for the terms with Jᵢ > 0.
    pub ratios: Vec<(f64, f64)>,
    /// C = (1−ν)/μ₀ in 1/Pa (as in [`crate::contact::scene`]).
    pub compliance_factor_per_pa: f64,
}

/// The solution of the dimensionless problem at one s (N′ = 1/4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReducedSolution {
    /// ρF/N.
    pub friction_rho: f64,
    /// Contact length λ (in units of l_g).
    pub lambda: f64,
    /// Offset β of the lowest point from the rear edge (in units of l_g).
    pub beta: f64,
    /// The solver's estimated relative error of ρF/N and λ.
    pub error_estimate: f64,
}

/// One solved node: x = ln s, ln φ, ln λ, β.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Node {
    /// ln s.
    pub x: f64,
    /// ln(ρF/N).
    pub ln_phi: f64,
    /// ln λ.
    pub ln_lambda: f64,
}

impl ReducedProblem {
    /// From a creep spectrum at its reference temperature; `poisson` overrides the spectrum's.
    pub fn new(spectrum: &CreepSpectrum, poisson: Option<f64>) -> Result<Self, FrictionMapError> {
        let bad = |field: String, value: f64, expected| FrictionMapError::BadValue {
            field,
            value,
            expected,
        };
        let nu = poisson.unwrap_or(spectrum.poisson);
        if !(nu.is_finite() && (0.0..=0.5).contains(&nu)) {
            return Err(bad("poisson".into(), nu, "in [0, 0.5]"));
        }
        let jg = spectrum.compliance_glassy_per_pa;
        if !(jg.is_finite() && jg > 0.0) {
            return Err(bad("compliance_glassy_per_pa".into(), jg, "finite and > 0"));
        }
        // C = (1−ν)/μ₀ (MATH.md §1), as in contact::scene.
        let c = match spectrum.kind {
            ModulusKind::Tensile => 2.0 * (1.0 - nu * nu) * jg,
            ModulusKind::Shear => (1.0 - nu) * jg,
        };
        let mut ratios = Vec::with_capacity(spectrum.terms.len());
        for (i, t) in spectrum.terms.iter().enumerate() {
            if !(t.compliance_per_pa.is_finite() && t.compliance_per_pa >= 0.0) {
                return Err(bad(
                    format!("terms[{i}].compliance_per_pa"),
                    t.compliance_per_pa,
                    "finite and ≥ 0",
                ));
            }
            if !(t.tau_s.is_finite() && t.tau_s > 0.0) {
                return Err(bad(format!("terms[{i}].tau_s"), t.tau_s, "finite and > 0"));
            }
            if t.compliance_per_pa > 0.0 {
                ratios.push((t.compliance_per_pa / jg, t.tau_s));
            }
        }
        Ok(ReducedProblem {
            ratios,
            compliance_factor_per_pa: c,
        })
    }

    /// Glassy Hertz contact length l_g = 2√(2RCN*/π) in m.
    pub fn glassy_length_m(&self, radius_m: f64, load_n_per_m: f64) -> f64 {
        2.0 * (2.0 * radius_m * self.compliance_factor_per_pa * load_n_per_m / PI).sqrt()
    }

    /// The reduced variable s = l_g/(V·a_T) in s.
    pub fn reduced_time_s(
        &self,
        radius_m: f64,
        load_n_per_m: f64,
        speed_m_s: f64,
        a_t: f64,
    ) -> f64 {
        self.glassy_length_m(radius_m, load_n_per_m) / (speed_m_s * a_t)
    }

    /// The creep terms (fᵢ, bᵢ) of the dimensionless problem at reduced time `s_s`.
    pub fn terms(&self, s_s: f64) -> Vec<CreepTerm> {
        self.ratios
            .iter()
            .map(|&(r, tau)| {
                let b = s_s / tau;
                CreepTerm { f: r * b, b }
            })
            .collect()
    }

    /// Solve the dimensionless problem at N′ = 1/4 and reduced time s = e^x.
    pub fn solve(
        &self,
        x: f64,
        settings: &AutoSettings,
    ) -> Result<ReducedSolution, FrictionMapError> {
        let s_s = x.exp();
        let sol = solve_auto_at_load(&self.terms(s_s), 0.25, settings)
            .map_err(|source| FrictionMapError::Solve { s_s, source })?;
        let d = &sol;
        Ok(ReducedSolution {
            friction_rho: d.friction_rho,
            lambda: d.lambda,
            beta: d.beta,
            error_estimate: d.error_estimate.unwrap_or(f64::NAN),
        })
    }

    fn node(&self, x: f64, settings: &AutoSettings) -> Result<Node, FrictionMapError> {
        let ReducedSolution {
            friction_rho: phi,
            lambda,
            ..
        } = self.solve(x, settings)?;
        if !(phi > 0.0 && phi.is_finite()) {
            return Err(FrictionMapError::NonPositive { s_s: x.exp(), phi });
        }
        Ok(Node {
            x,
            ln_phi: phi.ln(),
            ln_lambda: lambda.ln(),
        })
    }
}

/// Tolerance of the node solves for a map tolerance `tol`: a tenth of it (so the solver's error times
/// the Lebesgue constant stays below a third of `tol`). It was capped at 1e−7 while the `auto` solver
/// returned, on the shipped TRIOS compound far on the glassy side (ln s ≈ −46…−20), frictions off
/// by up to 3 % (once 2–4×) with estimates of ~1e−6; the cause was the Bessel cut of
/// src/contact/chebyshev.rs, and since its fix the solver's estimate holds there
/// (tests/contact_props.rs, `estimate_holds_across_the_reduced_variable_on_measured_compounds`).
pub fn node_tol(tol: f64) -> f64 {
    0.1 * tol
}

/// One panel: Chebyshev coefficients of ln φ and ln λ on [a, b].
#[derive(Debug, Clone, PartialEq)]
struct Panel {
    a: f64,
    b: f64,
    phi: Vec<f64>,
    lambda: Vec<f64>,
    estimate: f64,
}

/// The interpolant of ln φ(ln s) and ln λ(ln s) on a range of ln s.
#[derive(Debug, Clone, PartialEq)]
pub struct ReducedCurve {
    panels: Vec<Panel>,
    /// Largest panel error estimate (absolute, in ln φ and ln λ ≈ relative in φ and λ).
    pub error_estimate: f64,
    /// Node solves made.
    pub solves: usize,
    /// Tolerance of the node solves.
    pub node_tol: f64,
}

/// Error estimate of a Chebyshev interpolant from its coefficients: twice the sum of the last
/// quarter of them (see the module doc).
fn tail(c: &[f64]) -> f64 {
    let n = c.len() - 1;
    2.0 * c[n - n / 4..].iter().map(|x| x.abs()).sum::<f64>()
}

impl ReducedCurve {
    /// Build the interpolant on [x_lo, x_hi] (x = ln s) to `settings.tol` (see the module doc).
    pub fn build(
        problem: &ReducedProblem,
        x_lo: f64,
        x_hi: f64,
        settings: &MapSettings,
    ) -> Result<Self, FrictionMapError> {
        if !(1e-10..=1e-2).contains(&settings.tol) {
            return Err(FrictionMapError::BadValue {
                field: "tol".into(),
                value: settings.tol,
                expected: "in [1e-10, 1e-2]",
            });
        }
        if !(x_lo.is_finite() && x_hi.is_finite() && x_hi >= x_lo) {
            return Err(FrictionMapError::BadValue {
                field: "ln s range".into(),
                value: x_hi - x_lo,
                expected: "finite ends with x_hi ≥ x_lo",
            });
        }
        let width = if settings.panel_width.is_finite() && settings.panel_width > 0.0 {
            settings.panel_width
        } else {
            MapSettings::default().panel_width
        };
        // Pad a degenerate range so the panel has a width (a single point is still interpolated).
        let (x_lo, x_hi) = if x_hi - x_lo < 1e-3 {
            (x_lo - 0.05, x_hi + 0.05)
        } else {
            (x_lo, x_hi)
        };
        let node_settings = AutoSettings {
            tol: node_tol(settings.tol),
            max_iterations: 100,
            profile_points: 8,
            gap_check: false,
        };
        let budget = 0.5 * settings.tol;
        let n0 = settings.start_degree.clamp(4, 64);
        let n_max = settings.max_degree.clamp(n0, 256);
        let m = ((x_hi - x_lo) / width).ceil().max(1.0) as usize;
        // Pending panels: (a, b, degree, ln φ and ln λ at the Lobatto points of that degree, or
        // at those of half the degree when it was just doubled: the even points are reused).
        struct Pending {
            a: f64,
            b: f64,
            n: usize,
            phi: Vec<f64>,
            lambda: Vec<f64>,
        }
        let mut pending: Vec<Pending> = (0..m)
            .map(|k| {
                // exact ends, so every query's x lies inside
                let a = if k == 0 {
                    x_lo
                } else {
                    x_lo + (x_hi - x_lo) * k as f64 / m as f64
                };
                let b = if k + 1 == m {
                    x_hi
                } else {
                    x_lo + (x_hi - x_lo) * (k + 1) as f64 / m as f64
                };
                Pending {
                    a,
                    b,
                    n: n0,
                    phi: vec![],
                    lambda: vec![],
                }
            })
            .collect();
        let mut done: Vec<Panel> = Vec::new();
        let mut solves = 0;
        while !pending.is_empty() {
            // The new nodes of every pending panel: all n + 1 Lobatto points for a fresh panel, the
            // odd-indexed ones after a doubling (cos(π·2j/2n) = cos(πj/n) are known).
            let wanted: Vec<(usize, usize, f64)> = pending
                .iter()
                .enumerate()
                .flat_map(|(p, q)| {
                    let fresh = q.phi.is_empty();
                    let (mid, half) = (0.5 * (q.a + q.b), 0.5 * (q.b - q.a));
                    (0..=q.n)
                        .filter(move |k| fresh || k % 2 == 1)
                        .map(move |k| (p, k, mid + half * (PI * k as f64 / q.n as f64).cos()))
                })
                .collect();
            let nodes: Vec<Node> = wanted
                .par_iter()
                .map(|&(_, _, x)| problem.node(x, &node_settings))
                .collect::<Result<_, _>>()?;
            solves += nodes.len();
            let mut filled: Vec<(Vec<f64>, Vec<f64>)> = pending
                .iter()
                .map(|q| {
                    let mut phi = vec![f64::NAN; q.n + 1];
                    let mut lambda = vec![f64::NAN; q.n + 1];
                    for (j, (&f, &l)) in q.phi.iter().zip(&q.lambda).enumerate() {
                        phi[2 * j] = f;
                        lambda[2 * j] = l;
                    }
                    (phi, lambda)
                })
                .collect();
            for (&(p, k, _), node) in wanted.iter().zip(&nodes) {
                filled[p].0[k] = node.ln_phi;
                filled[p].1[k] = node.ln_lambda;
            }
            let mut next = Vec::new();
            for (q, (phi_v, lambda_v)) in pending.iter().zip(filled) {
                let phi = lobatto_coefficients(&phi_v);
                let lambda = lobatto_coefficients(&lambda_v);
                let estimate = tail(&phi).max(tail(&lambda));
                if estimate <= budget {
                    done.push(Panel {
                        a: q.a,
                        b: q.b,
                        phi,
                        lambda,
                        estimate,
                    });
                } else if 2 * q.n <= n_max {
                    next.push(Pending {
                        a: q.a,
                        b: q.b,
                        n: 2 * q.n,
                        phi: phi_v,
                        lambda: lambda_v,
                    });
                } else if done.len() + next.len() + pending.len() >= MAX_PANELS {
                    return Err(FrictionMapError::NotConverged {
                        estimate,
                        tol: budget,
                        panels: done.len() + pending.len(),
                    });
                } else {
                    let mid = 0.5 * (q.a + q.b);
                    for (a, b) in [(q.a, mid), (mid, q.b)] {
                        next.push(Pending {
                            a,
                            b,
                            n: n0,
                            phi: vec![],
                            lambda: vec![],
                        });
                    }
                }
            }
            pending = next;
        }
        done.sort_by(|p, q| p.a.total_cmp(&q.a));
        let error_estimate = done.iter().map(|p| p.estimate).fold(0.0, f64::max);
        Ok(ReducedCurve {
            panels: done,
            error_estimate,
            solves,
            node_tol: node_settings.tol,
        })
    }

    /// Range [x_lo, x_hi] of ln s covered.
    pub fn range(&self) -> (f64, f64) {
        (
            self.panels.first().map_or(f64::NAN, |p| p.a),
            self.panels.last().map_or(f64::NAN, |p| p.b),
        )
    }

    /// Number of panels.
    pub fn panels(&self) -> usize {
        self.panels.len()
    }

    /// (ρF/N, λ) at x = ln s; `None` outside the range.
    pub fn eval(&self, x: f64) -> Option<(f64, f64)> {
        let (lo, hi) = self.range();
        if !(x >= lo && x <= hi) {
            return None;
        }
        // panels are sorted and contiguous: the last one starting at or below x
        let i = self.panels.partition_point(|p| p.a <= x).max(1) - 1;
        let p = &self.panels[i];
        let t = ((2.0 * x - p.a - p.b) / (p.b - p.a)).clamp(-1.0, 1.0);
        Some((clenshaw(&p.phi, t).exp(), clenshaw(&p.lambda, t).exp()))
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
    let lo = xs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = xs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if xs.is_empty() {
        return Err(FrictionMapError::BadValue {
            field: "points".into(),
            value: 0.0,
            expected: "at least one map point",
        });
    }
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

#[cfg(test)]
#[path = "friction_map_tests.rs"]
mod tests;
