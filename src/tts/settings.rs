//! Settings of the master-curve construction ([`MasterSettings`] and its choices), plain serde with
//! defaults, and their check.

use super::error::TtsError;
use super::quality::QualityBounds;
use crate::material::{ShiftLaw, ZERO_CELSIUS_K};
use serde::{Deserialize, Serialize};

/// Where the horizontal shifts come from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(tag = "mode", rename_all = "snake_case")]
pub enum ShiftSource {
    /// Automatic shifting of the data.
    #[default]
    Auto,
    /// A given law (WLF, Arrhenius or a table): log10 a_T(T) − log10 a_T(T_ref).
    Given {
        /// The law.
        law: ShiftLaw,
    },
}

/// What the automatic shifting compares.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum ShiftCriterion {
    /// log10 E′ and log10 E″ jointly, each weighted by the inverse of its own scatter.
    Joint,
    /// log10 tan δ (independent of any vertical shift).
    TanDelta,
    /// log10 E′ and log10 E″, each weighted per isotherm by the information it carries there: its
    /// local slope against its scatter, (|d log M/d log f| / σ)², as a share of both channels'
    /// (docs/MATH.md §6). Where E′ is flat (the rubbery plateau) E″ carries the shift; in the
    /// transition E′ does, as with [`ShiftCriterion::Storage`]; below T_g E′ alone (E″ there holds
    /// secondary relaxations that do not superpose). The channel is chosen per isotherm, and each
    /// isotherm reports the channel that carried it. The default: on the synthetic rubbers of
    /// tests/master_plateau.rs it holds every shift from T_g + 20 K up within 0.03 decade of the
    /// truth, where E′ alone misses the rubbery plateau by up to 0.26 decade.
    #[default]
    SlopeWeighted,
    /// log10 E′ only: on the real EMS-CA and DMA-suite sets E″ carries an instrument upturn at the
    /// top frequency and a secondary relaxation below T_g that do not superpose, and E′ alone
    /// superposes them best (overlap RMS 0.004 and 0.021 against 0.045 and 0.028 jointly); it
    /// cannot place isotherms on a plateau, where E′ is flat.
    Storage,
}

/// The vertical shift b_T.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum VerticalShift {
    /// No vertical shift (b_T = 1), the default for tensile rubbers.
    #[default]
    None,
    /// From the residual offset of log10 E′ (horizontal shifts then from tan δ).
    Fitted,
    /// b_T = T/T_ref in kelvin (constant density).
    Temperature,
}

/// Which temperature of an isotherm is used for shifting and the laws.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum TemperatureBasis {
    /// The mean measured temperature (`temp_mean_c`).
    #[default]
    Mean,
    /// The nominal (set) temperature (`temp_nominal_c`).
    Nominal,
}

/// Which law becomes the master curve's [`ShiftLaw`] after automatic shifting.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum LawChoice {
    /// The one of WLF and Arrhenius with the smaller RMS residual.
    #[default]
    Auto,
    /// WLF.
    Wlf,
    /// Arrhenius.
    Arrhenius,
    /// The table of the measured shifts.
    Table,
}

/// Settings of the master-curve construction; every field has a default (`serde(default)`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct MasterSettings {
    /// Reference temperature in °C. Default: the temperature of the middle isotherm (its shift is
    /// then exactly 0, with no law involved).
    pub tref_c: Option<f64>,
    /// Automatic shifting or a given law. Default automatic.
    pub shift: ShiftSource,
    /// What the automatic shifting compares. Default slope-weighted, a channel chosen per isotherm
    /// (see [`ShiftCriterion::SlopeWeighted`]).
    pub criterion: ShiftCriterion,
    /// Vertical shift. Default none.
    pub vertical: VerticalShift,
    /// Temperature of an isotherm. Default the mean measured one (the nominal can be off by kelvins).
    pub temperature: TemperatureBasis,
    /// Which law to use. Default the better of WLF and Arrhenius by RMS.
    pub law: LawChoice,
    /// Fewest points (both isotherms together) that must overlap for a pair to count. Default 3:
    /// the fewest that determine a shift in the presence of one outlier.
    pub min_overlap_points: usize,
    /// Pairs up to this many isotherms apart (in temperature order) enter the global refinement.
    /// Default 3: next-neighbours tie down a neighbour pair that barely overlaps, and each isotherm
    /// tied to six others averages the noise (on the synthetic rubbers of tests/master_plateau.rs the
    /// worst shift from T_g + 20 K up fell from 0.0315 to 0.029 decade; 2 was the default before).
    pub pair_reach: usize,
    /// Step of the pairwise grid scan in decades. Default 0.01 (the golden-section refinement then
    /// brackets the minimum to 1e-10).
    pub grid_step_decades: f64,
    /// Fit WLF and Arrhenius only to the isotherms with temperatures in [min, max] °C (e.g. above
    /// T_g, where WLF holds); `None`: all. The residuals are reported for the fitted isotherms.
    pub law_fit_range_c: Option<(f64, f64)>,
    /// Floor of a channel's scatter in the joint criterion's weights, log10 units. Default 0.002
    /// (0.5 % in modulus, below the noise of any DMA): noise-free channels then weigh alike.
    pub channel_scatter_floor_log10: f64,
    /// Quality bounds.
    pub bounds: QualityBounds,
    /// Move each point that has its own measured temperature to its isotherm's temperature before
    /// shifting (`super::point_temps`: f → f·10^(s·(T_p − T_i)), s = d log10 a_T/dT from a first
    /// shifting pass, or from the given law). Default off here (`viscoroll master` shows the data as
    /// measured); the main job turns it on: on synthetic exports with ±1.5 K drift it removed most
    /// of the shift error at the cold end (tests/known_truth.rs).
    pub correct_point_temperatures: bool,
}

impl Default for MasterSettings {
    fn default() -> Self {
        MasterSettings {
            tref_c: None,
            shift: ShiftSource::Auto,
            criterion: ShiftCriterion::SlopeWeighted,
            vertical: VerticalShift::None,
            temperature: TemperatureBasis::Mean,
            law: LawChoice::Auto,
            min_overlap_points: 3,
            pair_reach: 3,
            grid_step_decades: 0.01,
            channel_scatter_floor_log10: 0.002,
            law_fit_range_c: None,
            bounds: QualityBounds::default(),
            correct_point_temperatures: false,
        }
    }
}

impl MasterSettings {
    /// Check every field; called by `build_master_curve` before any work.
    pub fn validate(&self) -> Result<(), TtsError> {
        if let Some(t) = self.tref_c {
            if !t.is_finite() || t <= -ZERO_CELSIUS_K {
                return Err(TtsError::BadTemperature {
                    field: "tref_c".into(),
                    value: t,
                });
            }
        }
        if self.min_overlap_points < 2 {
            return Err(TtsError::BadSetting {
                field: "min_overlap_points",
                value: self.min_overlap_points.to_string(),
                expected: "at least 2",
            });
        }
        if self.pair_reach < 1 {
            return Err(TtsError::BadSetting {
                field: "pair_reach",
                value: self.pair_reach.to_string(),
                expected: "at least 1",
            });
        }
        if !(self.grid_step_decades > 0.0 && self.grid_step_decades <= 0.5) {
            return Err(TtsError::BadSetting {
                field: "grid_step_decades",
                value: self.grid_step_decades.to_string(),
                expected: "in (0, 0.5] decades",
            });
        }
        if !(self.channel_scatter_floor_log10 > 0.0 && self.channel_scatter_floor_log10.is_finite())
        {
            return Err(TtsError::BadSetting {
                field: "channel_scatter_floor_log10",
                value: self.channel_scatter_floor_log10.to_string(),
                expected: "finite and > 0",
            });
        }
        if let Some((lo, hi)) = self.law_fit_range_c {
            if !(lo.is_finite() && hi.is_finite() && lo < hi) {
                return Err(TtsError::BadSetting {
                    field: "law_fit_range_c",
                    value: format!("({lo}, {hi})"),
                    expected: "finite (min, max) with min < max, °C",
                });
            }
        }
        Ok(())
    }
}
