//! The master curve: input a [`Measurement`] and [`MasterSettings`], output a [`MasterCurve`]
//! (reduced-frequency points, the shift of each isotherm, WLF and Arrhenius fits, the chosen
//! [`ShiftLaw`], quality figures and the settings used). MATH.md §6.
//!
//! Steps: clean each isotherm (finite, positive f, E′, E″; sorted; repeated frequencies averaged
//! in log) → optional vertical factor from temperature → horizontal shifts (automatic,
//! [`super::shift`], or from a given law) → optional fitted vertical shifts ([`super::vertical`]) →
//! WLF and Arrhenius fits ([`super::fit_laws`]) and re-referencing to T_ref → quality figures
//! ([`super::quality`]) → reduced points ω_r = a_T ω, E_r = E / b_T.

use super::error::TtsError;
use super::fit_laws::{fit_arrhenius, fit_wlf, ArrheniusFit, WlfFit};
use super::point_temps::{correct_point_temperatures, slopes_from_shifts};
use super::quality::{kramers_kronig_local, van_gurp_palmen, QualityBounds};
use super::shift::{channel_scatter, overlap_rms, pair_shift, refine_global, Prepared};
use super::vertical::{fit_vertical, log10_b_t_temperature};
use super::{ShiftLaw, ZERO_CELSIUS_K};
use crate::{Measurement, ModulusKind};
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
    /// log10 E′ only, the default: on the real EMS-CA and DMA-suite sets E″ carries an
    /// instrument upturn at the top frequency and a secondary relaxation below T_g that do not
    /// superpose, and E′ alone superposes best (overlap RMS 0.004 and 0.021 against 0.045 and
    /// 0.028 jointly).
    #[default]
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
    /// What the automatic shifting compares. Default log10 E′ (see [`ShiftCriterion::Storage`]).
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
    /// Default 2: next-neighbours tie down a neighbour pair that barely overlaps.
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
    /// shifting ([`super::point_temps`]: f → f·10^(s·(T_p − T_i)), s = d log10 a_T/dT from a first
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
            criterion: ShiftCriterion::Storage,
            vertical: VerticalShift::None,
            temperature: TemperatureBasis::Mean,
            law: LawChoice::Auto,
            min_overlap_points: 3,
            pair_reach: 2,
            grid_step_decades: 0.01,
            channel_scatter_floor_log10: 0.002,
            law_fit_range_c: None,
            bounds: QualityBounds::default(),
            correct_point_temperatures: false,
        }
    }
}

impl MasterSettings {
    /// Check every field; called by [`build_master_curve`] before any work.
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

/// One point of the master curve.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MasterPoint {
    /// Reduced frequency a_T · f in Hz.
    pub reduced_freq_hz: f64,
    /// Reduced storage modulus E′/b_T in Pa.
    pub storage_pa: f64,
    /// Reduced loss modulus E″/b_T in Pa.
    pub loss_pa: f64,
    /// Temperature of the isotherm it came from, °C.
    pub temp_c: f64,
    /// Index of that isotherm in `MasterCurve::isotherms`.
    pub isotherm: usize,
}

/// The shift of one isotherm and its quality figures.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct IsothermShift {
    /// Index in `Measurement::isotherms`.
    pub measurement_index: usize,
    /// Nominal temperature, °C.
    pub temp_nominal_c: f64,
    /// Temperature used for the shift laws, °C.
    pub temp_c: f64,
    /// log10 a_T relative to T_ref.
    pub log10_a_t: f64,
    /// Standard error of log10 a_T from the global least squares (0 for the reference isotherm
    /// and for a given law).
    pub log10_a_t_std: f64,
    /// log10 b_T (0 without vertical shift).
    pub log10_b_t: f64,
    /// Points used.
    pub points_used: usize,
    /// Points left out (non-finite or non-positive f, E′ or E″; repeated frequencies merged).
    pub points_dropped: usize,
    /// RMS mismatch of its overlaps, log10 units (`None`: overlaps nothing).
    pub overlap_rms_log10: Option<f64>,
    /// RMS mismatch of log10 E″ alone in its overlaps at the final shifts (log10 units): with the
    /// default E′ criterion, whether E″ superposes with the shifts found from E′ (a direct test of
    /// thermorheological simplicity).
    #[serde(default)]
    pub loss_overlap_rms_log10: Option<f64>,
    /// van Gurp–Palmen RMS against its neighbours, degrees.
    pub vgp_rms_deg: Option<f64>,
    /// Median log10 of (π/2)·dE′/d ln ω over E″ (local Kramers–Kronig).
    pub kk_median_log10_ratio: Option<f64>,
    /// Quality figures out of bounds, in words.
    pub flags: Vec<String>,
}

/// Summary of the quality figures.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MasterQuality {
    /// The bounds applied.
    pub bounds: QualityBounds,
    /// Worst overlap RMS over the isotherms, log10 units.
    pub overlap_rms_max_log10: f64,
    /// RMS over all isotherms' overlap RMS, log10 units.
    pub overlap_rms_log10: f64,
    /// Worst E″-alone overlap RMS at the final shifts, log10 units.
    #[serde(default)]
    pub loss_overlap_rms_max_log10: f64,
    /// Worst van Gurp–Palmen RMS, degrees.
    pub vgp_rms_max_deg: f64,
    /// Largest |median log10 ratio| of the local Kramers–Kronig rule.
    pub kk_max_abs_log10_ratio: f64,
    /// All van Gurp–Palmen figures within bound.
    pub thermorheologically_simple: bool,
    /// Outer iterations of the global shift refinement (0 for a given law).
    pub global_iterations: usize,
    /// Joint criterion: scatter of log10 E′ and log10 E″ each superposed alone (the inverse
    /// weights), log10 units; empty for other criteria.
    pub channel_scatter_log10: Vec<f64>,
    /// Largest per-point temperature correction applied, decades of frequency (0 when off).
    #[serde(default)]
    pub point_temperature_correction_max_log10: f64,
    /// Corrected shifting passes run (0 when off).
    #[serde(default)]
    pub point_temperature_passes: usize,
    /// Every flag, prefixed with its isotherm's temperature.
    pub flags: Vec<String>,
}

/// A master curve with its shift law and quality figures.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MasterCurve {
    /// Tensile or shear moduli.
    pub kind: ModulusKind,
    /// Poisson's ratio carried from the measurement.
    pub poisson: f64,
    /// Reference temperature, °C.
    pub t_ref_c: f64,
    /// Points sorted by reduced frequency.
    pub points: Vec<MasterPoint>,
    /// Shift of each isotherm, in order of temperature.
    pub isotherms: Vec<IsothermShift>,
    /// WLF fit of the shifts at T_ref (`None` if it failed, see `warnings`).
    pub wlf: Option<WlfFit>,
    /// Arrhenius fit of the shifts at T_ref.
    pub arrhenius: Option<ArrheniusFit>,
    /// The law used from here on (the better fit, or as chosen or given).
    pub shift_law: ShiftLaw,
    /// Quality figures.
    pub quality: MasterQuality,
    /// The settings used (resolved: `tref_c` is filled in).
    pub settings: MasterSettings,
    /// Warnings (isotherms skipped, a law that failed to fit, …).
    pub warnings: Vec<String>,
}

struct Clean {
    index: usize,
    nominal: f64,
    temp: f64,
    x: Vec<f64>,
    log_s: Vec<f64>,
    log_l: Vec<f64>,
    dropped: usize,
}

fn clean(
    m: &Measurement,
    basis: TemperatureBasis,
    warnings: &mut Vec<String>,
) -> Result<Vec<Clean>, TtsError> {
    let mut out = Vec::new();
    for (index, iso) in m.isotherms.iter().enumerate() {
        let temp = match basis {
            TemperatureBasis::Mean => iso.temp_mean_c,
            TemperatureBasis::Nominal => iso.temp_nominal_c,
        };
        if !temp.is_finite() || temp <= -ZERO_CELSIUS_K {
            let field = match basis {
                TemperatureBasis::Mean => "temp_mean_c",
                TemperatureBasis::Nominal => "temp_nominal_c",
            };
            return Err(TtsError::BadTemperature {
                field: format!("isotherms[{index}].{field}"),
                value: temp,
            });
        }
        let mut pts: Vec<(f64, f64, f64)> = iso
            .points
            .iter()
            .filter(|p| {
                [p.freq_hz, p.storage_pa, p.loss_pa]
                    .iter()
                    .all(|v| v.is_finite() && *v > 0.0)
            })
            .map(|p| (p.freq_hz.log10(), p.storage_pa.log10(), p.loss_pa.log10()))
            .collect();
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        // Merge repeated frequencies (mean of the logs).
        let mut x: Vec<f64> = Vec::new();
        let mut ls: Vec<f64> = Vec::new();
        let mut ll: Vec<f64> = Vec::new();
        let mut k = 0;
        while k < pts.len() {
            let mut j = k;
            while j < pts.len() && pts[j].0 - pts[k].0 <= 1e-9 {
                j += 1;
            }
            let c = (j - k) as f64;
            x.push(pts[k..j].iter().map(|p| p.0).sum::<f64>() / c);
            ls.push(pts[k..j].iter().map(|p| p.1).sum::<f64>() / c);
            ll.push(pts[k..j].iter().map(|p| p.2).sum::<f64>() / c);
            k = j;
        }
        let dropped = iso.points.len() - x.len();
        if x.len() < 3 {
            warnings.push(format!(
                "isotherm {index} ({temp} °C) skipped: {} usable point(s) at distinct frequencies, 3 needed",
                x.len()
            ));
            continue;
        }
        out.push(Clean {
            index,
            nominal: iso.temp_nominal_c,
            temp,
            x,
            log_s: ls,
            log_l: ll,
            dropped,
        });
    }
    if out.len() < 2 {
        return Err(TtsError::TooFewIsotherms {
            found: out.len(),
            needed: 2,
        });
    }
    out.sort_by(|a, b| a.temp.total_cmp(&b.temp));
    for w in out.windows(2) {
        if (w[1].temp - w[0].temp).abs() < 1e-9 {
            return Err(TtsError::DuplicateTemperature {
                first: w[0].index,
                second: w[1].index,
                temp_c: w[0].temp,
            });
        }
    }
    Ok(out)
}

fn interp_at(temps: &[f64], vals: &[f64], t: f64) -> f64 {
    let pts: Vec<(f64, f64)> = temps.iter().copied().zip(vals.iter().copied()).collect();
    ShiftLaw::Table {
        t_ref_c: t,
        points: pts,
    }
    .log10_a_t(t)
}

/// Build the master curve of `measurement` (see the module docs); with
/// `correct_point_temperatures`, first move every point to its isotherm's temperature
/// ([`super::point_temps`]) with the slopes of the given law or of a first shifting pass.
pub fn build_master_curve(
    measurement: &Measurement,
    settings: &MasterSettings,
) -> Result<MasterCurve, TtsError> {
    let has_point_temps = measurement
        .isotherms
        .iter()
        .any(|i| i.points.iter().any(|p| p.temp_c.is_some()));
    if !settings.correct_point_temperatures || !has_point_temps {
        return build_once(measurement, settings);
    }
    settings.validate()?;
    let temp_of = |i: &crate::dma::Isotherm| match settings.temperature {
        TemperatureBasis::Mean => i.temp_mean_c,
        TemperatureBasis::Nominal => i.temp_nominal_c,
    };
    let slopes_of = |mc: &MasterCurve| {
        let shifts: Vec<(f64, f64)> = mc
            .isotherms
            .iter()
            .map(|i| (i.temp_c, i.log10_a_t))
            .collect();
        let mut by_index = vec![f64::NAN; measurement.isotherms.len()];
        for (i, v) in mc.isotherms.iter().zip(slopes_from_shifts(&shifts)) {
            by_index[i.measurement_index] = v;
        }
        by_index
    };
    let (mut mc, largest, passes) = match &settings.shift {
        // Central difference of the law over ±0.5 K (its curvature error is far below the
        // correction's own second-order term); one pass.
        ShiftSource::Given { law } => {
            let slopes: Vec<f64> = measurement
                .isotherms
                .iter()
                .map(|i| {
                    let t = temp_of(i);
                    law.log10_a_t(t + 0.5) - law.log10_a_t(t - 0.5)
                })
                .collect();
            let (corrected, largest) =
                correct_point_temperatures(measurement, &slopes, settings.temperature);
            (build_once(&corrected, settings)?, largest, 1)
        }
        // Slopes from the shifts of the previous pass, applied to the measured points, until the
        // shifts move by less than POINT_TEMPERATURE_TOL_LOG10 (a fixed point: the slopes of the
        // corrected shifts reproduce them). On the shipped DMA-suite set (3 K drift per sweep) the
        // first correction moved the end shifts by 0.65 decade, the second by 0.045.
        ShiftSource::Auto => {
            let mut mc = build_once(measurement, settings)?;
            let mut largest = 0.0;
            let mut passes = 0;
            while passes < POINT_TEMPERATURE_MAX_PASSES {
                let (corrected, l) =
                    correct_point_temperatures(measurement, &slopes_of(&mc), settings.temperature);
                let next = build_once(&corrected, settings)?;
                let moved = mc
                    .isotherms
                    .iter()
                    .zip(&next.isotherms)
                    .map(|(a, b)| (a.log10_a_t - b.log10_a_t).abs())
                    .fold(0.0, f64::max);
                mc = next;
                largest = l;
                passes += 1;
                if moved < POINT_TEMPERATURE_TOL_LOG10 {
                    break;
                }
            }
            (mc, largest, passes)
        }
    };
    mc.quality.point_temperature_correction_max_log10 = largest;
    mc.quality.point_temperature_passes = passes;
    Ok(mc)
}

/// The per-point temperature correction stops when no shift moves by more than this (decades):
/// a tenth of the shift error the correction removes at the cold end of the synthetic tests.
const POINT_TEMPERATURE_TOL_LOG10: f64 = 0.005;
/// At most this many corrected shifting passes (each costs one master-curve construction).
const POINT_TEMPERATURE_MAX_PASSES: usize = 4;

fn build_once(
    measurement: &Measurement,
    settings: &MasterSettings,
) -> Result<MasterCurve, TtsError> {
    settings.validate()?;
    let mut warnings = Vec::new();
    let iso = clean(measurement, settings.temperature, &mut warnings)?;
    let n = iso.len();
    let temps: Vec<f64> = iso.iter().map(|c| c.temp).collect();
    let t_ref = settings.tref_c.unwrap_or(temps[(n - 1) / 2]);
    let k0 = (0..n)
        .min_by(|&a, &b| {
            (temps[a] - t_ref)
                .abs()
                .total_cmp(&(temps[b] - t_ref).abs())
        })
        .unwrap_or(0);

    // Vertical factor from temperature (known before shifting).
    let mut log_b: Vec<f64> = match settings.vertical {
        VerticalShift::Temperature => temps
            .iter()
            .map(|&t| log10_b_t_temperature(t, t_ref))
            .collect(),
        _ => vec![0.0; n],
    };
    let joint: Vec<Prepared> = iso
        .iter()
        .zip(&log_b)
        .map(|(c, &b)| {
            Prepared::new(
                c.x.clone(),
                vec![
                    c.log_s.iter().map(|v| v - b).collect(),
                    c.log_l.iter().map(|v| v - b).collect(),
                ],
            )
        })
        .collect();
    let use_tan = settings.criterion == ShiftCriterion::TanDelta
        || settings.vertical == VerticalShift::Fitted;
    let tan: Vec<Prepared> = if use_tan {
        iso.iter()
            .map(|c| {
                Prepared::new(
                    c.x.clone(),
                    vec![c.log_l.iter().zip(&c.log_s).map(|(l, s)| l - s).collect()],
                )
            })
            .collect()
    } else {
        Vec::new()
    };
    let storage: Vec<Prepared> = if settings.criterion == ShiftCriterion::Storage && !use_tan {
        joint
            .iter()
            .map(|p| Prepared::new(p.x.clone(), vec![p.channels[0].0.clone()]))
            .collect()
    } else {
        Vec::new()
    };
    // Joint criterion: each channel weighted by the inverse of its own scatter (how well it
    // superposes alone, floored at `channel_scatter_floor_log10`), i.e. maximum likelihood with an
    // unknown variance per channel: a channel that cannot be superposed (an instrument resonance in
    // E″, a secondary relaxation) then gives way to the one that can.
    let mut channel_scatter_log10 = Vec::new();
    let weighted: Vec<Prepared> =
        if !use_tan && storage.is_empty() && settings.shift == ShiftSource::Auto {
            let floor = settings.channel_scatter_floor_log10;
            channel_scatter_log10 = (0..2)
                .map(|c| {
                    channel_scatter(
                        &joint,
                        c,
                        settings.grid_step_decades,
                        settings.min_overlap_points,
                    )
                    .unwrap_or(floor)
                    .max(floor)
                })
                .collect();
            joint
                .iter()
                .map(|p| {
                    Prepared::new(
                        p.x.clone(),
                        (0..2)
                            .map(|c| {
                                p.channels[c]
                                    .0
                                    .iter()
                                    .map(|v| v / channel_scatter_log10[c])
                                    .collect()
                            })
                            .collect(),
                    )
                })
                .collect()
        } else {
            Vec::new()
        };
    let shifting = if use_tan {
        &tan
    } else if !storage.is_empty() {
        &storage
    } else if !weighted.is_empty() {
        &weighted
    } else {
        &joint
    };
    let (reach, min_pts) = (settings.pair_reach, settings.min_overlap_points);

    // Horizontal shifts, log10 a_T relative to T_ref.
    let (mut shifts, std_err, overlap, iterations, given) = match &settings.shift {
        ShiftSource::Auto => {
            let mut chain = vec![0.0; n];
            for i in 0..n - 1 {
                let p = pair_shift(
                    &shifting[i],
                    &shifting[i + 1],
                    settings.grid_step_decades,
                    min_pts,
                )
                .ok_or(TtsError::NoOverlap {
                    temp_a_c: temps[i],
                    temp_b_c: temps[i + 1],
                    min_points: min_pts,
                })?;
                chain[i + 1] = chain[i] + p.d;
            }
            let g = refine_global(shifting, &chain, k0, reach, min_pts);
            // Overlap figures in log10 units (not weighted).
            let o = if weighted.is_empty() {
                g.overlap_rms
            } else {
                overlap_rms(&joint, &g.shifts, reach, min_pts)
            };
            (g.shifts, g.std_err, o, g.iterations, None)
        }
        ShiftSource::Given { law } => {
            let at_ref = law.log10_a_t(t_ref);
            let mut s = Vec::with_capacity(n);
            for &t in &temps {
                let v = law.log10_a_t(t) - at_ref;
                if !v.is_finite() {
                    return Err(TtsError::LawNotFinite {
                        temp_c: t,
                        value: v,
                    });
                }
                s.push(v);
            }
            let o = overlap_rms(shifting, &s, reach, min_pts);
            (s, vec![0.0; n], o, 0, Some(law.clone()))
        }
    };
    if settings.vertical == VerticalShift::Fitted {
        log_b = fit_vertical(&joint, &shifts, k0, reach, min_pts);
    }

    // Laws, first at the reference isotherm's temperature, then re-referenced to T_ref.
    let fit_both = |s: &[f64], tr: f64, warnings: &mut Vec<String>| {
        let pts: Vec<(f64, f64)> = temps
            .iter()
            .copied()
            .zip(s.iter().copied())
            .filter(|p| {
                settings
                    .law_fit_range_c
                    .map_or(true, |(lo, hi)| p.0 >= lo && p.0 <= hi)
            })
            .collect();
        let w = fit_wlf(&pts, tr)
            .map_err(|e| warnings.push(e.to_string()))
            .ok();
        let a = fit_arrhenius(&pts, tr)
            .map_err(|e| warnings.push(e.to_string()))
            .ok();
        (w, a)
    };
    let choose = |w: &Option<WlfFit>, a: &Option<ArrheniusFit>, s: &[f64], tr: f64| -> ShiftLaw {
        let table = ShiftLaw::Table {
            t_ref_c: tr,
            points: temps.iter().copied().zip(s.iter().copied()).collect(),
        };
        match (settings.law, w, a) {
            (LawChoice::Table, _, _) => table,
            (LawChoice::Wlf, Some(w), _) => w.law(),
            (LawChoice::Arrhenius, _, Some(a)) => a.law(),
            (LawChoice::Auto, Some(w), Some(a)) => {
                if w.rms_log10 <= a.rms_log10 {
                    w.law()
                } else {
                    a.law()
                }
            }
            (_, Some(w), _) => w.law(),
            (_, _, Some(a)) => a.law(),
            _ => table,
        }
    };
    let (wlf, arrhenius, shift_law) = if let Some(law) = given {
        let (w, a) = fit_both(&shifts, t_ref, &mut warnings);
        (w, a, law)
    } else {
        // Fit at the reference isotherm's temperature T₀ (its shift is exactly 0 there), choose,
        // then move to T_ref: the shifts by the chosen law's value at T_ref, the chosen law exactly
        // (same function), the other law refitted to the moved shifts.
        let t0 = temps[k0];
        let (w0, a0) = fit_both(&shifts, t0, &mut warnings);
        let law0 = choose(&w0, &a0, &shifts, t0);
        if (t_ref - t0).abs() <= 1e-12 {
            (w0, a0, law0)
        } else {
            let off = law0.log10_a_t(t_ref);
            if !off.is_finite() {
                return Err(TtsError::LawNotFinite {
                    temp_c: t_ref,
                    value: off,
                });
            }
            for s in &mut shifts {
                *s -= off;
            }
            if settings.vertical == VerticalShift::Fitted {
                let b_ref = interp_at(&temps, &log_b, t_ref);
                for b in &mut log_b {
                    *b -= b_ref;
                }
            }
            let all: Vec<(f64, f64)> = temps.iter().copied().zip(shifts.iter().copied()).collect();
            let pts: Vec<(f64, f64)> = all
                .iter()
                .copied()
                .filter(|p| {
                    settings
                        .law_fit_range_c
                        .map_or(true, |(lo, hi)| p.0 >= lo && p.0 <= hi)
                })
                .collect();
            let mut tmp = Vec::new();
            let (wr, ar) = fit_both(&shifts, t_ref, &mut tmp);
            let w = match (&law0, &w0) {
                (ShiftLaw::Wlf { .. }, Some(w)) => w.rereferenced(&pts, t_ref),
                _ => wr,
            };
            let a = match (&law0, &a0) {
                (ShiftLaw::Arrhenius { .. }, Some(a)) => Some(a.rereferenced(&pts, t_ref)),
                _ => ar,
            };
            let law = match law0 {
                ShiftLaw::Table { .. } => ShiftLaw::Table {
                    t_ref_c: t_ref,
                    points: all.clone(),
                },
                ShiftLaw::Wlf { .. } => w
                    .as_ref()
                    .map(WlfFit::law)
                    .unwrap_or_else(|| choose(&w, &a, &shifts, t_ref)),
                ShiftLaw::Arrhenius { .. } => a
                    .as_ref()
                    .map(ArrheniusFit::law)
                    .unwrap_or_else(|| choose(&w, &a, &shifts, t_ref)),
            };
            (w, a, law)
        }
    };

    if let Some(w) = &wlf {
        if w.c2_k > 1e4 {
            warnings.push(format!(
                "WLF C2 = {:.3e} K at the search bound: the shifts are nearly linear in T and WLF \
                 is degenerate (C1/C2 = {:.4} per K); see the Arrhenius fit or the table",
                w.c2_k,
                w.c1 / w.c2_k
            ));
        }
    }

    // Quality.
    let loss_only: Vec<Prepared> = joint
        .iter()
        .map(|p| Prepared::new(p.x.clone(), vec![p.channels[1].0.clone()]))
        .collect();
    let loss_overlap = overlap_rms(&loss_only, &shifts, reach, min_pts);
    let vgp = van_gurp_palmen(
        &joint,
        &if settings.vertical == VerticalShift::Fitted {
            log_b.clone()
        } else {
            vec![0.0; n]
        },
    );
    let bounds = settings.bounds;
    let mut flags_all = Vec::new();
    let mut isotherms = Vec::with_capacity(n);
    for (i, c) in iso.iter().enumerate() {
        let kk = kramers_kronig_local(&joint[i]);
        let mut flags = Vec::new();
        if let Some(o) = overlap[i] {
            if o > bounds.overlap_rms_max_log10 {
                flags.push(format!(
                    "overlap RMS {o:.3} > {} (log10)",
                    bounds.overlap_rms_max_log10
                ));
            }
        } else {
            flags.push("overlaps no other isotherm".to_string());
        }
        if let Some(o) = loss_overlap[i] {
            if o > bounds.overlap_rms_max_log10 {
                flags.push(format!(
                    "E″ alone overlap RMS {o:.3} > {} (log10) at these shifts",
                    bounds.overlap_rms_max_log10
                ));
            }
        }
        if let Some(v) = vgp[i] {
            if v > bounds.vgp_rms_max_deg {
                flags.push(format!(
                    "van Gurp–Palmen RMS {v:.2}° > {}°",
                    bounds.vgp_rms_max_deg
                ));
            }
        }
        if let Some(k) = kk {
            if k.abs() > bounds.kk_max_abs_log10_ratio {
                flags.push(format!(
                    "Kramers–Kronig: median log10((π/2)dE′/dlnω / E″) = {k:.2}, |·| > {}",
                    bounds.kk_max_abs_log10_ratio
                ));
            }
        }
        for f in &flags {
            flags_all.push(format!("{:.2} °C: {f}", c.temp));
        }
        isotherms.push(IsothermShift {
            measurement_index: c.index,
            temp_nominal_c: c.nominal,
            temp_c: c.temp,
            log10_a_t: shifts[i],
            log10_a_t_std: std_err[i],
            log10_b_t: log_b[i],
            points_used: c.x.len(),
            points_dropped: c.dropped,
            overlap_rms_log10: overlap[i],
            loss_overlap_rms_log10: loss_overlap[i],
            vgp_rms_deg: vgp[i],
            kk_median_log10_ratio: kk,
            flags,
        });
    }
    let max_of = |it: &mut dyn Iterator<Item = f64>| it.fold(0.0f64, f64::max);
    let ov: Vec<f64> = overlap.iter().flatten().copied().collect();
    let quality = MasterQuality {
        bounds,
        overlap_rms_max_log10: max_of(&mut ov.iter().copied()),
        overlap_rms_log10: if ov.is_empty() {
            0.0
        } else {
            (ov.iter().map(|v| v * v).sum::<f64>() / ov.len() as f64).sqrt()
        },
        loss_overlap_rms_max_log10: max_of(&mut loss_overlap.iter().flatten().copied()),
        vgp_rms_max_deg: max_of(&mut vgp.iter().flatten().copied()),
        kk_max_abs_log10_ratio: max_of(
            &mut isotherms
                .iter()
                .filter_map(|s| s.kk_median_log10_ratio.map(f64::abs)),
        ),
        thermorheologically_simple: vgp.iter().flatten().all(|&v| v <= bounds.vgp_rms_max_deg),
        global_iterations: iterations,
        channel_scatter_log10,
        point_temperature_correction_max_log10: 0.0,
        point_temperature_passes: 0,
        flags: flags_all,
    };

    // Reduced points.
    let mut points = Vec::new();
    for (i, c) in iso.iter().enumerate() {
        let (a, b) = (10f64.powf(shifts[i]), 10f64.powf(log_b[i]));
        for k in 0..c.x.len() {
            points.push(MasterPoint {
                reduced_freq_hz: 10f64.powf(c.x[k]) * a,
                storage_pa: 10f64.powf(c.log_s[k]) / b,
                loss_pa: 10f64.powf(c.log_l[k]) / b,
                temp_c: c.temp,
                isotherm: i,
            });
        }
    }
    points.sort_by(|p, q| p.reduced_freq_hz.total_cmp(&q.reduced_freq_hz));
    let mut resolved = settings.clone();
    resolved.tref_c = Some(t_ref);
    Ok(MasterCurve {
        kind: measurement.kind,
        poisson: measurement.poisson,
        t_ref_c: t_ref,
        points,
        isotherms,
        wlf,
        arrhenius,
        shift_law,
        quality,
        settings: resolved,
        warnings,
    })
}
