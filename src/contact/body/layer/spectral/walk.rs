//! The spectral layer's one load loop: every solve at λ is made at the degree and reduction of the
//! answer, so that the loop's last two solves are the answer's (no separate coarse loop).
//!
//! Input: the load problem's fixed parts (creep terms, h′, ν, the Laplace rule, tol, the degree
//! cap) and the model lumping gains; output: the solves made, each with its p/2 and p/4 companions
//! ([`super::at_lambda::solve_at_lambda_triple`], one set of columns), the reduction and degree they
//! were made with, for [`super::at_load`] to calibrate, carry to the root and estimate.
//!
//! # What a solve does
//! At each λ the secant asks for (`secant::secant_until`):
//! 1. the modes are selected at λ ([`select`]: fast modes lumped, slow ones dropped within 0.3·tol
//!    of ρF/N and N′, with the ρF/N/λ of the solve before; the first solve, whose N′ only has to aim
//!    the secant, with the budgets of tol 1e−3 and ρF/N/λ = 1e−2, as the former coarse loop did);
//! 2. the degree is the larger of the rule [`degree_for`] at λ and the degree the loop has reached;
//! 3. the triple (p, p/2, p/4) is solved at λ, its degree error measured with the model gains, and
//!    when the p/2 check fails (against 0.3·tol over the lumping's amplification, `degree_budget`) the degree for the *next* solve is raised by the measured convergence
//!    rate (`degree::next_degree`): the raise costs no solve of its own (the solve that showed it still
//!    aims the secant; the former loop re-solved at the same λ after each raise).
//!
//! A change of reduction or degree starts a new *generation*. The loop stops only when its last two
//! solves are of one generation and no raise is pending, so that the answer's reduction, degree and
//! p/2 check are those of the last solve and the carry to the root ([`super::at_load`], `to_root`)
//! is a linear interpolation between two solves of one discretisation.
//!
//! # The stop: the carry's error (the interpolation remainder)
//! The loop stops before the secant's next step when carrying the last solve (at uₙ, u = ln λ)
//! linearly to the root u* through the solve before it (at uₙ₋₁) is accurate enough. For an output
//! y(u) the linear interpolant through uₙ₋₁, uₙ misses y(u*) by ½y″(ζ)(u* − uₙ)(u* − uₙ₋₁) (the
//! remainder of linear interpolation; e.g. Süli & Mayers, *An Introduction to Numerical Analysis*,
//! CUP 2003, Thm 6.2), so relative to y by (C/2)·d·D with d = |u* − uₙ| (the secant's proposed step),
//! D = |u* − uₙ₋₁| ≤ d + |uₙ − uₙ₋₁| and C ≥ |y″/y| (for β: |β″|/λ). [`CARRY_CURVATURE`] = C/2 is
//! measured (its doc). The loop stops when that is ≤ [`CARRY_SHARE`]·tol; the answer's estimate
//! counts it again at the carry actually made (after the measured gains moved the root).

use super::at_lambda::{solve_at_lambda_triple, LaplaceRule};
use super::degree::{
    corrected, degree_budget, degree_error, degree_for, next_degree, unscale, Triple,
};
use crate::contact::numerics::at_lambda::LambdaSolution;
use crate::contact::numerics::correction::lumped_weight_times_lambda;
use crate::contact::numerics::reduction::{select, Reduction};
use crate::contact::problem::CreepTerm;

/// Half the largest relative curvature |y″/y| in u = ln λ of the outputs carried to the root
/// (ln N′, ρF/N, β/λ; module doc), with a margin: measured by second differences of three solves
/// at Δu = 1e−2 around the root (`tests::carry_curvature_is_bounded`, and a scratch sweep of 1-,
/// 10- and 30-term spectra, h/λ_HS = 0.05…30, ν = 0…½, 60 cases): |ρF/N″/ρF/N| ≤ 1.2 (10 terms,
/// thin compressible covers), |β″|/λ ≤ 0.52, |ln N′″| ≤ 0.69 (with this test's cases). A single Debye peak ρF/N ∝ x/(1+x²),
/// x = eᵘ, has ρF/N″/ρF/N = 1 − 2sech²u ∈ [−1, 1]. C = 6 is five times the largest measured.
pub const CARRY_CURVATURE: f64 = 3.0;

/// The share of tol the loop's stop leaves to the carry's error (module doc).
pub const CARRY_SHARE: f64 = 0.05;

/// One solve of the loop: its triple (reduced to the full problem's scale, without the lumping
/// correction), the generation, degree and ρF/N/λ.
pub struct Visit {
    pub generation: usize,
    pub p: usize,
    pub triple: Triple,
}

/// The loop's state (module doc).
pub struct Walk<'a> {
    terms: &'a [CreepTerm],
    thickness: f64,
    nu: f64,
    rule: LaplaceRule,
    tol: f64,
    cap: usize,
    /// Model lumping gains (g_F, g_N) at the start.
    pub model: (f64, f64),
    /// The reduction of the last solve (`None` before the first).
    pub red: Option<Reduction>,
    /// The degree the next solve is made at (at least).
    pub p: usize,
    /// W = Σwᵢ of the lumped modes at λ = 1 for `red`.
    pub wl: f64,
    generation: usize,
    fr_over_l: Option<f64>,
    /// The last three solves, oldest first.
    pub seen: Vec<Visit>,
    /// Solves made.
    pub solves: usize,
}

impl<'a> Walk<'a> {
    /// A loop with nothing solved yet; `p_floor` is the least degree of its solves.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        terms: &'a [CreepTerm],
        (thickness, nu): (f64, f64),
        rule: LaplaceRule,
        tol: f64,
        cap: usize,
        model: (f64, f64),
        p_floor: usize,
        fr_over_l: Option<f64>,
    ) -> Self {
        Walk {
            terms,
            thickness,
            nu,
            rule,
            tol,
            cap,
            model,
            red: None,
            p: p_floor,
            wl: 0.0,
            generation: 0,
            fr_over_l,
            seen: Vec::new(),
            solves: 0,
        }
    }

    /// Solve at λ (module doc, steps 1–3); returns the solution at p with the model's lumping
    /// correction, whose N′ the secant reads.
    pub fn solve(&mut self, lambda: f64) -> LambdaSolution {
        let (terms, tol, model) = (self.terms, self.tol, self.model);
        let red = match self.fr_over_l {
            None => {
                let ct = tol.max(1e-3);
                select(terms, lambda, 0.3 * ct * 1e-2, 0.3 * ct, model)
            }
            Some(f) => select(terms, lambda, 0.3 * tol * f, 0.3 * tol, model),
        };
        let p = self
            .p
            .max(degree_for(0.5 * lambda, self.thickness, tol))
            .min(self.cap);
        let same = self.red.as_ref().is_some_and(|r| {
            r.kept == red.kept && r.lumped == red.lumped && r.dropped == red.dropped
        }) && self.seen.last().is_some_and(|v| v.p == p);
        if !same {
            self.generation += 1;
            self.wl = lumped_weight_times_lambda(terms, &red);
            self.red = Some(red);
        }
        self.p = p;
        let red = self.red.as_ref().expect("set above");
        let (a, b, c) =
            solve_at_lambda_triple(&red.modes, lambda, self.thickness, self.nu, p, self.rule);
        let triple = (unscale(red, a), unscale(red, b), unscale(red, c));
        self.solves += 1;
        let g = (model.0, model.1, 0.0);
        let at_p = corrected(triple.0.clone(), self.wl, g);
        let e = degree_error(&corrected(triple.1.clone(), self.wl, g), &at_p);
        let e = e.0.max(e.1);
        if e > degree_budget(terms, red, lambda, tol) && p < self.cap {
            self.p = next_degree(p, e, tol, 0.5 * lambda / self.thickness, self.cap);
        }
        self.fr_over_l = Some(at_p.friction_rho / lambda);
        if self.seen.len() == 3 {
            self.seen.remove(0);
        }
        self.seen.push(Visit {
            generation: self.generation,
            p,
            triple,
        });
        at_p
    }

    /// Whether the last two solves are of one generation and the next would be too (module doc).
    pub fn settled(&self) -> bool {
        let n = self.seen.len();
        n >= 2
            && self.seen[n - 1].generation == self.seen[n - 2].generation
            && self.seen[n - 1].p == self.p
    }

    /// The loop's stop before a step d = |u* − uₙ| that follows a step `last` = |uₙ − uₙ₋₁|
    /// (module doc).
    pub fn done(&self, d: f64, last: Option<f64>) -> bool {
        let Some(last) = last else {
            return false;
        };
        self.settled() && CARRY_CURVATURE * d * (d + last) <= CARRY_SHARE * self.tol
    }
}

#[cfg(test)]
mod tests {
    use super::CARRY_CURVATURE;
    use crate::contact::body::layer::spectral::at_lambda::solve_at_lambda;
    use crate::contact::body::layer::spectral::{solve_spectral_at_load, SpectralSettings};
    use crate::contact::numerics::at_lambda::LambdaSolution;
    use crate::contact::numerics::modes::Modes;
    use crate::contact::problem::CreepTerm;

    #[test]
    fn carry_curvature_is_bounded() {
        // The relative curvatures in u = ln λ of the outputs the carry moves (ln N′, ρF/N, β/λ), by
        // second differences of three unreduced solves at Δu = 1e−2 around the root (the
        // difference's own error is O(Δu²·y⁗) and rounding ~1e−16/Δu² = 1e−12): on a one-term and a
        // ten-term spectrum, thin and thick covers, ν = 0 and ½. Measured ≤ 1.2 over the doc's
        // 60-case sweep; the carry's bound assumes C = 2·CARRY_CURVATURE = 6.
        let ten: Vec<CreepTerm> = (0..10)
            .map(|k| {
                let b = 10f64.powf(-4.0 + 8.0 * k as f64 / 9.0);
                CreepTerm { f: 99.9 * b, b }
            })
            .collect();
        let mut worst = 0.0_f64;
        for terms in [vec![CreepTerm { f: 10.0, b: 1.0 }], ten] {
            let modes = Modes::new(&terms);
            for (h, nu) in [(0.3, 0.0), (0.3, 0.5), (3.0, 0.5), (30.0, 0.3)] {
                let st = SpectralSettings {
                    tol: 1e-6,
                    checks: false,
                    ..SpectralSettings::default()
                };
                let a = solve_spectral_at_load(&terms, 0.25, h, nu, &st)
                    .unwrap()
                    .expect("accepted");
                let lam = a.solution.lambda;
                let du = 1e-2;
                let s: Vec<LambdaSolution> = [-1.0, 0.0, 1.0]
                    .iter()
                    .map(|k: &f64| solve_at_lambda(&modes, lam * (k * du).exp(), h, nu, 24, 0.3))
                    .collect();
                let d2 = |f: &dyn Fn(&LambdaSolution) -> f64| {
                    (f(&s[0]) - 2.0 * f(&s[1]) + f(&s[2])) / (du * du)
                };
                let c = [
                    d2(&|x| x.load.ln()).abs(),
                    (d2(&|x| x.friction_rho) / s[1].friction_rho).abs(),
                    d2(&|x| x.beta / lam).abs(),
                ];
                eprintln!("{} terms, h′ {h}, ν {nu}: {c:.3?}", terms.len());
                worst = c.iter().fold(worst, |w, v| w.max(*v));
            }
        }
        assert!(worst <= 2.0 * CARRY_CURVATURE, "{worst}");
        assert!(worst > 0.05, "the differences see the curvature: {worst}");
    }
}
