//! Fifth phase of the master curve: the quality figures of each isotherm at its final shifts — the
//! overlap mismatch of log10 E′ and of log10 E″ with the nearest neighbours, van Gurp–Palmen and the local Kramers–Kronig rule
//! ([`super::quality`]) — their flags against the bounds, and the summary [`MasterQuality`].

use super::channels::Channels;
use super::clean::Clean;
use super::horizontal::Horizontal;
use super::quality::{kramers_kronig_local, van_gurp_palmen, QualityBounds};
use super::quality_types::{IsothermShift, MasterQuality};
use super::settings::{MasterSettings, VerticalShift};
use super::shift::{overlap_rms, Prepared};

/// The overlap figures compare each isotherm with its nearest neighbours only, whatever pair reach
/// the shifting used (docs/MATH.md §6.5): a figure held to a fixed bound must not change its meaning
/// with an estimation setting (on the DMA-suite set the warmest isotherm's E′ figure is 0.044, 0.049
/// and 0.055 at reach 1, 2 and 3 under the storage criterion, at the same shifts within 0.01 decade).
const QUALITY_REACH: usize = 1;

/// The flag of an isotherm whose shift the overlaps do not determine (docs/MATH.md §6.6).
pub(crate) const SHIFT_NOT_DETERMINED: &str = "shift not determined by overlap";

/// The shift and quality figures of every isotherm, and their summary; `kind` names the moduli in
/// the flags (E′, E″ or G′, G″).
pub(super) fn assess(
    iso: &[Clean],
    ch: &Channels,
    h: &Horizontal,
    log_b: &[f64],
    settings: &MasterSettings,
    kind: crate::ModulusKind,
) -> (Vec<IsothermShift>, MasterQuality) {
    let n = iso.len();
    let min_pts = settings.min_overlap_points;
    let shifts = &h.shifts;
    // log10 E′ and log10 E″ at the final factors: the joint channels carry the b_T known before
    // shifting (none or T/T_ref); a fitted b_T comes after.
    let fitted_b = settings.vertical == VerticalShift::Fitted;
    let alone = |c: usize| -> Vec<Prepared> {
        ch.joint
            .iter()
            .zip(log_b)
            .map(|(p, &b)| {
                let y = &p.channels[c].0;
                let y = if fitted_b {
                    y.iter().map(|v| v - b).collect()
                } else {
                    y.clone()
                };
                Prepared::new(p.x.clone(), vec![y])
            })
            .collect()
    };
    let overlap = overlap_rms(&alone(0), shifts, QUALITY_REACH, min_pts);
    let loss_overlap = overlap_rms(&alone(1), shifts, QUALITY_REACH, min_pts);
    let vgp = van_gurp_palmen(
        &ch.joint,
        &if settings.vertical == VerticalShift::Fitted {
            log_b.to_vec()
        } else {
            vec![0.0; n]
        },
    );
    let bounds = settings.bounds;
    let mut flags_all = Vec::new();
    let mut isotherms = Vec::with_capacity(n);
    for (i, c) in iso.iter().enumerate() {
        let kk = kramers_kronig_local(&ch.joint[i]);
        let mut flags = isotherm_flags(&bounds, kind, overlap[i], loss_overlap[i], vgp[i], kk);
        if !h.determined[i] {
            flags.push(SHIFT_NOT_DETERMINED.to_string());
        }
        for f in &flags {
            flags_all.push(format!("{:.2} °C: {f}", c.temp));
        }
        isotherms.push(IsothermShift {
            measurement_index: c.index,
            temp_nominal_c: c.nominal,
            temp_c: c.temp,
            log10_a_t: shifts[i],
            log10_a_t_std: h.std_err[i],
            log10_b_t: log_b[i],
            points_used: c.x.len(),
            points_dropped: c.dropped,
            overlap_rms_log10: overlap[i],
            loss_overlap_rms_log10: loss_overlap[i],
            vgp_rms_deg: vgp[i],
            kk_median_log10_ratio: kk,
            flags,
            shift_channel: ch.carried.get(i).cloned().flatten(),
            shift_determined: h.determined[i],
        });
    }
    let quality = summary(&isotherms, ch, h.iterations, bounds);
    let quality = MasterQuality {
        flags: flags_all,
        ..quality
    };
    (isotherms, quality)
}

/// The master curve's summary of its isotherms' figures (flags left to the caller).
fn summary(
    isotherms: &[IsothermShift],
    ch: &Channels,
    iterations: usize,
    bounds: QualityBounds,
) -> MasterQuality {
    let max_of = |it: &mut dyn Iterator<Item = f64>| it.fold(0.0f64, f64::max);
    let ov: Vec<f64> = isotherms
        .iter()
        .filter_map(|s| s.overlap_rms_log10)
        .collect();
    let vgp = || isotherms.iter().filter_map(|s| s.vgp_rms_deg);
    MasterQuality {
        bounds,
        overlap_rms_max_log10: max_of(&mut ov.iter().copied()),
        overlap_rms_log10: if ov.is_empty() {
            0.0
        } else {
            (ov.iter().map(|v| v * v).sum::<f64>() / ov.len() as f64).sqrt()
        },
        loss_overlap_rms_max_log10: max_of(
            &mut isotherms.iter().filter_map(|s| s.loss_overlap_rms_log10),
        ),
        vgp_rms_max_deg: max_of(&mut vgp()),
        kk_max_abs_log10_ratio: max_of(
            &mut isotherms
                .iter()
                .filter_map(|s| s.kk_median_log10_ratio.map(f64::abs)),
        ),
        thermorheologically_simple: vgp().all(|v| v <= bounds.vgp_rms_max_deg),
        global_iterations: iterations,
        channel_scatter_log10: ch.channel_scatter_log10.clone(),
        point_temperature_correction_max_log10: 0.0,
        point_temperature_passes: 0,
        flags: Vec::new(),
        left_out_c: Vec::new(),
        shift_covariance_log10: Vec::new(),
        shift_not_determined_c: isotherms
            .iter()
            .filter(|s| !s.shift_determined)
            .map(|s| s.temp_c)
            .collect(),
    }
}

/// The flags of one isotherm against the bounds: its overlap RMS (or no overlap at all), E″ alone at
/// these shifts, van Gurp–Palmen, and the local Kramers–Kronig ratio.
fn isotherm_flags(
    bounds: &QualityBounds,
    kind: crate::ModulusKind,
    overlap: Option<f64>,
    loss_overlap: Option<f64>,
    vgp: Option<f64>,
    kk: Option<f64>,
) -> Vec<String> {
    let (storage, loss, _) = kind.symbols();
    let mut flags = Vec::new();
    if let Some(o) = overlap {
        if o > bounds.overlap_rms_max_log10 {
            flags.push(format!(
                "overlap RMS {o:.3} > {} (log10)",
                bounds.overlap_rms_max_log10
            ));
        }
    } else {
        flags.push("overlaps no other isotherm".to_string());
    }
    if let Some(o) = loss_overlap {
        if o > bounds.overlap_rms_max_log10 {
            flags.push(format!(
                "{loss} alone overlap RMS {o:.3} > {} (log10) at these shifts",
                bounds.overlap_rms_max_log10
            ));
        }
    }
    if let Some(v) = vgp {
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
                "Kramers–Kronig: median log10((π/2)d{storage}/dlnω / {loss}) = {k:.2}, |·| > {}",
                bounds.kk_max_abs_log10_ratio
            ));
        }
    }
    flags
}
