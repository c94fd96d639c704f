//! First phase of the master curve: each isotherm of a [`Measurement`] cleaned for shifting — finite,
//! positive f, E′ and E″ in log10, sorted by frequency, repeated frequencies merged (mean of the
//! logs); isotherms with fewer than 3 distinct frequencies skipped with a warning; sorted by
//! temperature, a repeated temperature an error.

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
