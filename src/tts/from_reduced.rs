//! A master curve that arrives already shifted (a RepTate `.tts` file, read by
//! [`crate::dma::reptate::read_master`]): its points, one isotherm at the reference temperature, and
//! the shift law stated with it → [`MasterCurve`], so that the stages after `tts` take it like one
//! built here. No shifting is done; the quality figures of shifting are zero or absent.

use super::error::TtsError;
use super::master::{IsothermShift, MasterCurve, MasterPoint, MasterQuality};
use super::settings::{MasterSettings, ShiftSource};
use crate::dma::{Isotherm, Measurement};
use crate::material::ShiftLaw;

/// The master curve of `reduced` (one isotherm whose frequencies are reduced frequencies at its
/// temperature) with the given `law`: points with finite, positive f, E′ and E″ kept, sorted by
/// frequency; the reference temperature is the isotherm's nominal temperature, and `law` must be
/// 0 there (it is moved there if not: log10 a_T − log10 a_T(T_ref)).
pub fn master_curve_from_reduced(
    reduced: &Measurement,
    law: &ShiftLaw,
) -> Result<MasterCurve, TtsError> {
    let [iso] = reduced.isotherms.as_slice() else {
        return Err(TtsError::BadSetting {
            field: "isotherms",
            value: reduced.isotherms.len().to_string(),
            expected: "exactly one isotherm of reduced points",
        });
    };
    let t_ref = iso.temp_nominal_c;
    let at_ref = law.log10_a_t(t_ref);
    if !at_ref.is_finite() {
        return Err(TtsError::LawNotFinite {
            temp_c: t_ref,
            value: at_ref,
        });
    }
    let shift_law = referred_to(law, t_ref);
    let mut points = usable_points(iso, t_ref);
    points.sort_by(|p, q| p.reduced_freq_hz.total_cmp(&q.reduced_freq_hz));
    if points.len() < 3 {
        return Err(TtsError::TooFewPoints {
            index: 0,
            temp_c: t_ref,
            found: points.len(),
            needed: 3,
        });
    }
    let settings = MasterSettings {
        tref_c: Some(t_ref),
        shift: ShiftSource::Given {
            law: shift_law.clone(),
        },
        ..MasterSettings::default()
    };
    Ok(MasterCurve {
        kind: reduced.kind,
        poisson: reduced.poisson,
        t_ref_c: t_ref,
        isotherms: vec![IsothermShift {
            measurement_index: 0,
            temp_nominal_c: t_ref,
            temp_c: t_ref,
            log10_a_t: 0.0,
            log10_a_t_std: 0.0,
            log10_b_t: 0.0,
            points_used: points.len(),
            points_dropped: iso.points.len() - points.len(),
            overlap_rms_log10: None,
            loss_overlap_rms_log10: None,
            vgp_rms_deg: None,
            kk_median_log10_ratio: None,
            flags: Vec::new(),
            shift_channel: None,
            shift_determined: true,
        }],
        points,
        wlf: None,
        arrhenius: None,
        shift_law,
        quality: MasterQuality {
            bounds: settings.bounds,
            overlap_rms_max_log10: 0.0,
            overlap_rms_log10: 0.0,
            loss_overlap_rms_max_log10: 0.0,
            vgp_rms_max_deg: 0.0,
            kk_max_abs_log10_ratio: 0.0,
            thermorheologically_simple: true,
            global_iterations: 0,
            channel_scatter_log10: Vec::new(),
            point_temperature_correction_max_log10: 0.0,
            point_temperature_passes: 0,
            flags: Vec::new(),
            left_out_c: Vec::new(),
        shift_covariance_log10: Vec::new(),
        shift_not_determined_c: Vec::new(),
        },
        settings,
        warnings: vec![format!(
            "master curve read already shifted (reference {t_ref} °C); its shifts were not checked here"
        )],
    })
}

/// `law` referred to `t_ref` (WLF keeps its form; other laws as they are).
fn referred_to(law: &ShiftLaw, t_ref: f64) -> ShiftLaw {
    match law {
        ShiftLaw::Wlf { c1, c2_k, t_ref_c } if (*t_ref_c - t_ref).abs() > 1e-12 => {
            // Same function referred to T_ref (WLF keeps its form: C1' = C1 C2/(C2 + ΔT),
            // C2' = C2 + ΔT with ΔT = T_ref − T_r).
            let dt = t_ref - t_ref_c;
            ShiftLaw::Wlf {
                t_ref_c: t_ref,
                c1: c1 * c2_k / (c2_k + dt),
                c2_k: c2_k + dt,
            }
        }
        other => other.clone(),
    }
}

/// The isotherm's points with finite, positive f, E′ and E″, at `t_ref`, in file order.
fn usable_points(iso: &Isotherm, t_ref: f64) -> Vec<MasterPoint> {
    iso.points
        .iter()
        .filter(|p| {
            [p.freq_hz, p.storage_pa, p.loss_pa]
                .iter()
                .all(|v| v.is_finite() && *v > 0.0)
        })
        .map(|p| MasterPoint {
            reduced_freq_hz: p.freq_hz,
            storage_pa: p.storage_pa,
            loss_pa: p.loss_pa,
            temp_c: t_ref,
            isotherm: 0,
        })
        .collect()
}
