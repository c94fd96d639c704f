//! First phase of the master curve: each isotherm of a [`Measurement`] cleaned for shifting — finite,
//! positive f, E′ and E″ in log10, sorted by frequency, repeated frequencies merged (mean of the
//! logs); isotherms with fewer than 3 distinct frequencies skipped with a warning; sorted by
//! temperature, a repeated temperature an error. An isotherm of more than [`THIN_ABOVE_POINTS`]
//! distinct frequencies is thinned ([`thin`]) so that no later pass grows with the size of the file.

use super::error::TtsError;
use super::settings::TemperatureBasis;
use crate::dma::Measurement;
use crate::material::ZERO_CELSIUS_K;

/// One isotherm in log10, ready for shifting.
pub(super) struct Clean {
    /// Index in `Measurement::isotherms`.
    pub index: usize,
    /// Nominal temperature, °C.
    pub nominal: f64,
    /// Temperature used (per the basis), °C.
    pub temp: f64,
    /// log10 f, strictly increasing.
    pub x: Vec<f64>,
    /// log10 E′.
    pub log_s: Vec<f64>,
    /// log10 E″.
    pub log_l: Vec<f64>,
    /// Points left out or merged.
    pub dropped: usize,
}

/// An isotherm with more distinct frequencies than this is thinned to this many points. Real DMA
/// sweeps have 10–100 points per isotherm (the shipped exports at most a few hundred), so they are
/// never thinned; 1000 points still resolve a curve over 3 decades at 300 per decade, far beyond
/// the ≈ 1 term per decade a Prony series can follow.
pub const THIN_ABOVE_POINTS: usize = 1000;

/// What [`thin`] did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Thinned {
    /// Points before thinning.
    pub from: usize,
    /// Largest RMS deviation of log10 E′ from its group mean, decades.
    pub scatter_storage_log10: f64,
    /// Same for log10 E″.
    pub scatter_loss_log10: f64,
}

/// Replace (x, ys, yl) — sorted by x — by the means of `max` groups of consecutive points whose sizes
/// differ by at most one (group g holds points ⌊g·n/max⌋ … ⌊(g+1)·n/max⌋ − 1), when n > `max`.
///
/// Equal counts make every mean stand for the same number of points, so a least-squares fit through
/// the means with equal weights is the fit through all points with count weights: for a model that
/// is linear over a group, Σ_groups Σ_k (y_k − m)² = Σ_groups [k·(ȳ − m)² + Σ_k (y_k − ȳ)²], whose
/// second term does not depend on the model. The group width in log f is n/max times the spacing of
/// the points, so the model's curvature inside a group is negligible for any n this triggers on.
pub(super) fn thin(
    x: &mut Vec<f64>,
    ys: &mut Vec<f64>,
    yl: &mut Vec<f64>,
    max: usize,
) -> Option<Thinned> {
    let n = x.len();
    if n <= max || max == 0 {
        return None;
    }
    let rms = |v: &[f64], mean: f64| {
        (v.iter().map(|y| (y - mean) * (y - mean)).sum::<f64>() / v.len() as f64).sqrt()
    };
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let (mut nx, mut ns, mut nl) = (
        Vec::with_capacity(max),
        Vec::with_capacity(max),
        Vec::with_capacity(max),
    );
    let (mut sc_s, mut sc_l) = (0.0f64, 0.0f64);
    for g in 0..max {
        let (a, b) = (g * n / max, (g + 1) * n / max);
        let (ms, ml) = (mean(&ys[a..b]), mean(&yl[a..b]));
        nx.push(mean(&x[a..b]));
        sc_s = sc_s.max(rms(&ys[a..b], ms));
        sc_l = sc_l.max(rms(&yl[a..b], ml));
        ns.push(ms);
        nl.push(ml);
    }
    *x = nx;
    *ys = ns;
    *yl = nl;
    Some(Thinned {
        from: n,
        scatter_storage_log10: sc_s,
        scatter_loss_log10: sc_l,
    })
}

/// The usable points (finite, positive f, E′, E″) as (log10 f, log10 E′, log10 E″) columns sorted by
/// frequency, repeated frequencies merged into the mean of their logs.
fn merged_logs(points: &[crate::dma::DataPoint]) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let mut pts: Vec<(f64, f64, f64)> = points
        .iter()
        .filter(|p| {
            [p.freq_hz, p.storage_pa, p.loss_pa]
                .iter()
                .all(|v| v.is_finite() && *v > 0.0)
        })
        .map(|p| (p.freq_hz.log10(), p.storage_pa.log10(), p.loss_pa.log10()))
        .collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (mut x, mut ls, mut ll) = (Vec::new(), Vec::new(), Vec::new());
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
    (x, ls, ll)
}

/// Clean every isotherm of `m` (see the module docs).
pub(super) fn clean(
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
        let (mut x, mut ls, mut ll) = merged_logs(&iso.points);
        if let Some(t) = thin(&mut x, &mut ls, &mut ll, THIN_ABOVE_POINTS) {
            let (storage, loss, _) = m.kind.symbols();
            warnings.push(format!(
                "isotherm {index} ({temp} °C): {} points at distinct frequencies thinned to {} means \
                 of {} consecutive points in log-frequency (largest RMS scatter within a group: \
                 {:.2e} decade in log {storage}, {:.2e} in log {loss}); the shifts and the Prony \
                 fit use the means",
                t.from,
                x.len(),
                if t.from % x.len() == 0 {
                    format!("{}", t.from / x.len())
                } else {
                    format!("{}–{}", t.from / x.len(), t.from.div_ceil(x.len()))
                },
                t.scatter_storage_log10,
                t.scatter_loss_log10
            ));
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thinning_keeps_small_input_and_averages_equal_groups() {
        let mut x: Vec<f64> = (0..10).map(f64::from).collect();
        let mut ys = x.clone();
        let mut yl: Vec<f64> = x.iter().map(|v| 2.0 * v).collect();
        assert_eq!(thin(&mut x, &mut ys, &mut yl, 10), None);
        assert_eq!(x.len(), 10);
        let t = thin(&mut x, &mut ys, &mut yl, 3).unwrap();
        // Groups {0,1,2}, {3,4,5}, {6,7,8,9}: means 1, 4, 7.5; log E″ twice that.
        assert_eq!(x, vec![1.0, 4.0, 7.5]);
        assert_eq!(ys, x);
        assert_eq!(yl, vec![2.0, 8.0, 15.0]);
        assert_eq!(t.from, 10);
        // RMS about the mean of {6,7,8,9} is √1.25, the largest.
        assert!((t.scatter_storage_log10 - 1.25f64.sqrt()).abs() < 1e-15);
        assert!((t.scatter_loss_log10 - 2.0 * 1.25f64.sqrt()).abs() < 1e-15);
    }
}
