//! Settings of the Prony fit ([`PronySettings`]) and the rule that picks the regularisation weight
//! ([`WeightRule`]). One flat struct; every field has its default and the reason for it beside it.

use super::PronyError;
use serde::{Deserialize, Serialize};

/// How the weight λ of the second-difference (Tikhonov) term is chosen (docs/MATH.md §5).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "rule", rename_all = "snake_case")]
pub enum WeightRule {
    /// Corner of the L-curve: the λ of largest curvature of (log‖r‖, log‖Lx‖) over the λ grid
    /// (Hansen & O'Leary 1993). Needs no error model, but where the curve has no clear corner it
    /// fits a curvature artefact: on exact data from a non-smooth (sparse) spectrum it chose λ = 1e-4
    /// and an RMS log10 error of 0.09 (unit test `zero_terms_are_dropped` setting), GCV 1e-9 and 6e-5.
    LCurve,
    /// Generalised cross-validation (Golub, Heath & Wahba 1979), the default: minimise
    /// m‖r‖²/(m − tr H)², H the influence matrix of the non-negative solution's free (non-zero)
    /// terms. It estimates the prediction error, so it goes to small λ on exact data and to the
    /// noise level on noisy data, without a corner to find.
    Gcv,
    /// A fixed weight λ (dimensionless, in the scaled problem of `crate::prony::fit`).
    Fixed {
        /// λ ≥ 0.
        lambda: f64,
    },
}

/// Settings of [`crate::prony::fit_prony`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct PronySettings {
    /// Relaxation times per decade (default 2: a discrete series on a smooth spectrum ripples; from
    /// exact data of a smooth spectrum the largest E″ error measured 6 % at 1 per decade, 0.7 % at 1.5,
    /// 0.1 % at 2, so 2 keeps the ripple below DMA scatter; fewer terms for FEA cards: lower it).
    pub terms_per_decade: f64,
    /// Decades the relaxation times extend beyond the data window at each end (default 0.5: a
    /// Maxwell element acts over about ±1 decade around ωρ = 1; times much further out are
    /// unidentifiable and would trade off against E∞).
    pub margin_decades: f64,
    /// Weight of the E″ residuals relative to the E′ residuals (default 1: both relative errors count
    /// alike). Lower it when E″ is known to scatter more than E′ (its relative error is the phase
    /// error over tan δ) or when the data are not Kramers–Kronig consistent and E′ matters more.
    pub loss_weight: f64,
    /// Rule that chooses the regularisation weight (default GCV).
    pub weight_rule: WeightRule,
    /// Smallest λ of the search grid (default 1e-9, λ in units of ‖A‖²_F/‖L‖²_F: its bias on exact
    /// smooth data is ~1e-8 relative, below the 1e-6 a noise-free round trip must reach).
    pub lambda_min: f64,
    /// Largest λ of the search grid (default 1e2: the spectrum is then a straight line in log ρ and
    /// the misfit is far above any measured scatter).
    pub lambda_max: f64,
    /// Number of log-spaced λ values searched (default 12, one per decade of the default range: the
    /// GCV minimum and the L-curve corner are broad, and each value costs one QP solve).
    pub lambda_count: usize,
    /// A term is dropped as zero when its largest relative contribution to any fitted datum,
    /// max_k Eᵢ·kernel(ω_kρᵢ)/datum_k, is below this (default 1e-7: ten times the solver's 1e-8
    /// tolerance on the scaled problem, where an active bound leaves ~1e-9, and four orders below
    /// measured DMA scatter, so dropping cannot change the fit visibly).
    pub drop_threshold: f64,
    /// Iteration limit of each QP solve (clarabel; default 200, its own default).
    pub max_iter: u32,
    /// Reduce the dense grid spectrum to the fewest terms at free positions that meet the target
    /// (`crate::prony::terms`; EMS-CA 65 → 28 terms, TRIOS 32 → 19 at no worse RMS log10 error of
    /// E′ and E″ against the data; figures in that module's docs; `max_terms` or `target_rms_log10` imply it). Default false: on the known-truth
    /// compounds the reduced fit is no worse against the noisy data but up to 3.7× worse in E′ against
    /// the true spectrum (high-tg-tread 0.0032 → 0.0120 decade), so the main job keeps the dense,
    /// regularised fit; `fit --reduce`, `--max-terms` and `--target-rms` ask for the reduction.
    pub reduce_terms: bool,
    /// At most this many relaxation terms (E∞ not counted) after the reduction (default none).
    /// When the target cannot be met within it, the fit with this many terms is kept and
    /// [`crate::prony::PronyInfo::term_target_met`] is false.
    pub max_terms: Option<usize>,
    /// Target RMS log10 error [E′, E″] of the reduction (default none: the dense fit's own errors,
    /// i.e. the fewest terms that are no less accurate than the grid fit in either modulus).
    pub target_rms_log10: Option<[f64; 2]>,
    /// The reduction minimises log residuals ln(fit/datum) instead of the relative residuals of the
    /// dense fit (default false: relative, the dense fit's own measure, so its accuracy is a target
    /// the reduction can always reach; log residuals trade E′ against E″ differently and do not let
    /// E″ collapse where it is under-fitted, which matters below ~15 terms).
    pub log_residuals: bool,
}

impl Default for PronySettings {
    fn default() -> Self {
        Self {
            terms_per_decade: 2.0,
            margin_decades: 0.5,
            loss_weight: 1.0,
            weight_rule: WeightRule::Gcv,
            lambda_min: 1e-9,
            lambda_max: 1e2,
            lambda_count: 12,
            drop_threshold: 1e-7,
            max_iter: 200,
            reduce_terms: false,
            max_terms: None,
            target_rms_log10: None,
            log_residuals: false,
        }
    }
}

impl PronySettings {
    /// Check every field before any work.
    pub fn validate(&self) -> Result<(), PronyError> {
        let bad = |field, value, reason| {
            Err(PronyError::BadSetting {
                field,
                value,
                reason,
            })
        };
        if !(self.terms_per_decade.is_finite()
            && self.terms_per_decade > 0.0
            && self.terms_per_decade <= 10.0)
        {
            return bad(
                "terms_per_decade",
                self.terms_per_decade,
                "expected 0 < value ≤ 10",
            );
        }
        if !(self.margin_decades.is_finite() && (0.0..=3.0).contains(&self.margin_decades)) {
            return bad(
                "margin_decades",
                self.margin_decades,
                "expected 0 ≤ value ≤ 3",
            );
        }
        if !(self.loss_weight.is_finite() && self.loss_weight > 0.0) {
            return bad(
                "loss_weight",
                self.loss_weight,
                "expected a finite value > 0",
            );
        }
        if !(self.lambda_min.is_finite() && self.lambda_min > 0.0) {
            return bad("lambda_min", self.lambda_min, "expected a finite value > 0");
        }
        if !(self.lambda_max.is_finite() && self.lambda_max > self.lambda_min) {
            return bad(
                "lambda_max",
                self.lambda_max,
                "expected a finite value > lambda_min",
            );
        }
        if self.lambda_count < 3 {
            return bad(
                "lambda_count",
                self.lambda_count as f64,
                "expected at least 3 (a corner needs 3 points)",
            );
        }
        crate::limits::at_most(
            "lambda_count",
            self.lambda_count,
            crate::limits::PRONY_LAMBDA_COUNT_MAX,
        )?;
        if let Some(m) = self.max_terms {
            crate::limits::at_most("max_terms", m, crate::limits::PRONY_TERMS_MAX)?;
        }
        if !(self.drop_threshold.is_finite() && (0.0..1.0).contains(&self.drop_threshold)) {
            return bad(
                "drop_threshold",
                self.drop_threshold,
                "expected 0 ≤ value < 1",
            );
        }
        if let WeightRule::Fixed { lambda } = self.weight_rule {
            if !(lambda.is_finite() && lambda >= 0.0) {
                return bad("weight_rule.lambda", lambda, "expected a finite value ≥ 0");
            }
        }
        if self.max_iter == 0 {
            return bad("max_iter", 0.0, "expected at least 1");
        }
        if self.max_terms == Some(0) {
            return bad("max_terms", 0.0, "expected at least 1");
        }
        if let Some(t) = self.target_rms_log10 {
            for v in t {
                if !(v.is_finite() && v > 0.0) {
                    return bad("target_rms_log10", v, "expected finite values > 0");
                }
            }
        }
        Ok(())
    }
}
