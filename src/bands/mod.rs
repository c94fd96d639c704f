//! Stage `bands`: uncertainty bands on every friction number, from the measurement's own scatter
//! propagated through the shifts, the Prony fit, the creep conversion and the contact solve by a
//! bootstrap (docs/MATH.md §15).
//!
//! Input: a compound's [`MasterCurve`](crate::tts::MasterCurve), its measurement and its
//! [`CompoundFit`](crate::results::CompoundFit); output: a
//! [`BandEnsemble`](crate::results::BandEnsemble) of refitted replicates (saved in the fit file),
//! and from it [`FrictionBand`](crate::results::FrictionBand)s per scene and temperature, bands of
//! a scene's mean friction and [`PairComparison`](crate::results::PairComparison)s. Sits above
//! results, tts, prony, creep and contact, below pipeline.
//!
//! The math (docs/MATH.md §15):
//!
//! 1. Scatter from the data. The residual of master point p against the fitted Prony series,
//!    r_p = ln(E′_p/Ê′(ω_p)) and likewise for E″ (eq. 15.1), holds the isotherm overlap mismatch and
//!    the fit residual together. The shift stage's least squares over the isotherm overlaps gives
//!    the covariance of the isotherms' log a_T relative to the reference isotherm (eq. 6.2); the drift of
//!    an isotherm's point temperatures gives σ_T,k = sd(T_points)/√n (0 when the file has none).
//! 2. Shifts (eq. 15.2): replicate shift errors δ = L z, L the Cholesky factor of that covariance
//!    (a master curve without one, an older file's: a random walk from the reference on the
//!    standard errors). The law at T_k gets δ_k + (d log a_T/dT)·σ_T,k·z.
//! 3. Moduli (eq. 15.3, wild residual bootstrap): E′*_p = Ê′(ω_p)·exp(z_p r_p), E″ alike, placed at
//!    the reduced frequency ω_p·10^δ_k of its isotherm k. Each replicate is refitted (eq. 15.4): the
//!    Prony QP near the fit's own λ (the λ search is not redone: one QP instead of twelve), then the
//!    exact creep conversion.
//! 4. The fit's own choices (model error, eqs. 15.10–15.12, super::model): each replicate adds
//!    another shift criterion's shifts (weighted by a standard normal), the shift table's
//!    interpolation error at each interval's middle, and is refitted at λ·10^U(−1,1) on a
//!    relaxation-time grid moved within its step. A fit file without an ensemble gets one from its
//!    own master curve ([`ensemble_from_fit`]; the shifts' scatter is then left out, and said).
//! 5. Contact: each replicate's creep spectrum, shifted by its own law log a_T(T) + δ(T) (δ linear
//!    between isotherms, constant beyond the ends), is rolled at the scene's temperatures; the ratio
//!    F_b/F̂ to the fit's own friction solved at the same tolerance carries the scatter.
//! 6. Band (eq. 15.5): with d_b = ln(F_b/F̂), mean m and standard deviation s over the replicates,
//!    p50 = F·e^m and p05, p95 = F·e^(m ∓ 1.645 s) (log-normal: smoother than empirical 5 %
//!    quantiles of 32 replicates). A covered scene's ratios are solved on the covered body the
//!    main job solves (`auto` at 1e−3, eq. 15.6): 8 replicates on the body the fit's own solve
//!    chose, started from its contact length, the rest from their half-space ratios (eq. 15.6b),
//!    at every other temperature where the cover/half-space ratio can be carried between them
//!    (eq. 15.6c). Scenes with the same roll and temperatures share their half-space solves.
//!    The band of a scene mean takes per replicate the mean of F_t·ratio_(b,t).
//!    Model error beyond the data: a point beyond the measured temperatures gets the spread of the
//!    shift law's tail assumptions (eq. 15.8); a point whose rolling frequency V/l (l the contact
//!    length of the body solved), reduced by a_T, lies beyond the measured master curve gets the
//!    change of F/N when the spectrum is continued past the window's edge with the edge's density
//!    (eq. 15.9), from half a decade inside the edge on, ramped up to it (eq. 15.9c); each as one standard
//!    deviation, drawn into every replicate (super::scene). A replicate solve that fails is
//!    counted: the band says how many of how many and why, and is refused when more than a
//!    quarter failed (also for the refits of the ensemble).
//! 7. Pairs (eq. 15.7): P(F_A < F_B) = Φ((ln p50_B − ln p50_A)/√(s_A² + s_B²)), compounds
//!    independent (separate measurements); tied when it lies strictly between 0.05 and 0.95.
//!
//! The half-space solver's error is carried into the band (eq. 15.5b: each quantile moved outwards
//! by the fit's solve's error estimate plus the median replicate's). Left out: the covered solver's
//! own error (≤ 1e−3, far below the bands), systematic
//! errors of the instrument (clamping, compliance, thermocouple calibration) that the data cannot
//! show.

pub(crate) mod between;
pub(crate) mod compare;
pub(crate) mod ensemble;
pub(crate) mod error;
pub(crate) mod friction;
pub(crate) mod model;
pub(crate) mod rng;
pub(crate) mod scene;
pub(crate) mod window;

pub use between::PRIOR_SD_LN;
pub(crate) use between::{between_sd_ln, specimens_note, widen};
pub use compare::comparisons;
pub(crate) use compare::prob_text;
pub(crate) use ensemble::FROM_FIT_FILE_NOTE;
pub use ensemble::{build_ensemble, ensemble_from_fit};
pub(crate) use error::not_computed;
pub use error::BandError;
pub(crate) use friction::{band_of, mean_band, CoverSolve};
pub(crate) use scene::{half_space_ratios, HalfSpaceRatios, SceneRatios};
pub use scene::{scene_bands_given, scene_bands_on};
#[cfg(test)]
pub(crate) use window::WindowSide;
pub(crate) use window::WIDENED_NOTE_START;

/// Settings of the bands.
#[derive(Debug, Clone, PartialEq)]
pub struct BandSettings {
    /// Bootstrap replicates (default 32: the log standard deviation of a band is then known to
    /// about 1/√(2·31) ≈ 13 %).
    pub replicates: usize,
    /// Seed of the resampling.
    pub seed: u64,
    /// Relative tolerance of the replicates' half-space solves (default 1e-3; a cover's are solved
    /// at the main job's 1e−3 or this if looser). The nominal friction of the ratio is solved at
    /// the same tolerance, so most of the solver error cancels in F_b/F̂: measured against both
    /// solved at 1e−8 on the synthetic library, |error of F_b/F̂| ≤ 6.5e−5 (p95 2.8e−5; 5.2e−6 at
    /// 1e−4), against bands of ±0.3 % and wider, at 0.7 of the CPU of 1e−4 (the former bench
    /// `bands_levers`, removed in issue 30: docs/DEVLOG.md). What does not cancel is carried into the band: each quantile is moved
    /// outwards by the fit's solve's error estimate plus the median replicate's (eq. 15.5b;
    /// 1.3e−4 median, 4e−4 at most on that library).
    pub contact_tol: f64,
    /// Draw the fit's own choices into each replicate (eqs. 15.10–15.12; default true). On the
    /// held-out calibration set (docs/MATH.md §15, "Calibration on the held-out set") they raise
    /// the 90 % band's coverage from 86 % to 90.5 % at 2× the median half-width; without them the
    /// band is the data's scatter alone, as before issue 32.
    pub model_error: bool,
}

impl Default for BandSettings {
    fn default() -> Self {
        Self {
            replicates: 32,
            seed: 16,
            contact_tol: 1e-3,
            model_error: true,
        }
    }
}

impl BandSettings {
    /// Check: 8 … 10 000 replicates, tolerance in [1e-8, 1e-2].
    pub fn validate(&self) -> Result<(), BandError> {
        if !(8..=10_000).contains(&self.replicates) {
            return Err(BandError::Settings(format!(
                "replicates must be in 8 … 10000, got {}",
                self.replicates
            )));
        }
        if !(self.contact_tol.is_finite() && (1e-8..=1e-2).contains(&self.contact_tol)) {
            return Err(BandError::Settings(format!(
                "contact_tol must be in [1e-8, 1e-2], got {}",
                self.contact_tol
            )));
        }
        Ok(())
    }
}
