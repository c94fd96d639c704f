//! Replicate specimens of one compound (issue 31): their measurements pooled into the one the fit
//! takes ([`pool`]), and each specimen's own friction in the scenes, from which the bands take the
//! spread between specimens (crate::bands::between, docs/MATH.md §16).
//!
//! Input: one [`Measurement`] per specimen (read alike, same modulus kind); output: the pooled
//! [`Measurement`] and notes on what could not be pooled. Pooling is the lab's averaging of
//! replicate curves: at each temperature every specimen measured (nominal temperatures within
//! [`SAME_TEMP_K`]), at each frequency every specimen measured there (within [`SAME_FREQ_LN`] in
//! ln f), E′ and E″ are the geometric means of the specimens' values (eq. 16.1), the point
//! temperature their mean. Points and isotherms not measured on every specimen are left out (a
//! note says how many), so the pooled curve never jumps from one specimen to another.

use super::error::PipelineError;
use crate::dma::{DataPoint, Isotherm};
use crate::Measurement;

/// Nominal temperatures closer than this (K) are the same isotherm of two specimens.
pub const SAME_TEMP_K: f64 = 0.5;
/// Frequencies closer than this in ln f (2 %) are the same frequency of two specimens.
pub const SAME_FREQ_LN: f64 = 0.02;

/// The specimens' measurements pooled (see the module docs), and notes on what was left out. An
/// error when their modulus kinds differ or they share no isotherm.
pub fn pool(
    compound: &str,
    specimens: &[Measurement],
) -> Result<(Measurement, Vec<String>), PipelineError> {
    let refuse = |message: String| PipelineError::Setting {
        field: "specimens".into(),
        message: format!("compound {compound}: {message}"),
    };
    let first = specimens
        .first()
        .ok_or_else(|| refuse("no specimen".into()))?;
    if let Some(k) = specimens.iter().position(|m| m.kind != first.kind) {
        return Err(refuse(format!(
            "specimen {} holds {:?} moduli, specimen 1 {:?}: replicates must be measured alike",
            k + 1,
            specimens[k].kind,
            first.kind
        )));
    }
    let mut pooled = first.clone();
    pooled.sources = specimens.iter().flat_map(|m| m.sources.clone()).collect();
    pooled.warnings = Vec::new();
    pooled.issues = specimens.iter().flat_map(|m| m.issues.clone()).collect();
    for (k, m) in specimens.iter().enumerate() {
        pooled.warnings.extend(
            m.warnings
                .iter()
                .map(|w| format!("specimen {}: {w}", k + 1)),
        );
    }
    let (mut left_isotherms, mut left_points) = (0usize, 0usize);
    pooled.isotherms = Vec::new();
    for iso in &first.isotherms {
        let twins: Option<Vec<&Isotherm>> = specimens[1..]
            .iter()
            .map(|m| {
                m.isotherms
                    .iter()
                    .find(|j| (j.temp_nominal_c - iso.temp_nominal_c).abs() < SAME_TEMP_K)
            })
            .collect();
        let Some(twins) = twins else {
            left_isotherms += 1;
            continue;
        };
        let mut points = Vec::new();
        for p in &iso.points {
            let same: Option<Vec<&DataPoint>> = twins
                .iter()
                .map(|j| {
                    j.points
                        .iter()
                        .find(|q| (q.freq_hz.ln() - p.freq_hz.ln()).abs() < SAME_FREQ_LN)
                })
                .collect();
            match same {
                Some(same) => points.push(pooled_point(p, &same)),
                None => left_points += 1,
            }
        }
        if points.is_empty() {
            left_isotherms += 1;
            continue;
        }
        let temps: Vec<f64> = points.iter().filter_map(|p| p.temp_c).collect();
        pooled.isotherms.push(Isotherm {
            temp_mean_c: if temps.is_empty() {
                iso.temp_mean_c
            } else {
                temps.iter().sum::<f64>() / temps.len() as f64
            },
            points,
            ..iso.clone()
        });
    }
    if pooled.isotherms.is_empty() {
        return Err(refuse(
            "the specimens share no isotherm (same nominal temperature and frequencies), so \
             they cannot be pooled"
                .into(),
        ));
    }
    let mut notes = Vec::new();
    let extra: usize = specimens[1..]
        .iter()
        .map(|m| m.isotherms.len())
        .sum::<usize>()
        .saturating_sub((specimens.len() - 1) * pooled.isotherms.len());
    if left_isotherms + left_points + extra > 0 {
        notes.push(format!(
            "replicate specimens pooled where all {} were measured: {} isotherm(s) and {} \
             point(s) of specimen 1 and {extra} isotherm(s) of the others left out",
            specimens.len(),
            left_isotherms,
            left_points
        ));
    }
    pooled.warnings.extend(notes.iter().cloned());
    Ok((pooled, notes))
}

/// One pooled point: geometric means of E′ and E″ (eq. 16.1), mean temperature, every flag.
fn pooled_point(p: &DataPoint, twins: &[&DataPoint]) -> DataPoint {
    let n = 1.0 + twins.len() as f64;
    let geo = |f: fn(&DataPoint) -> f64| {
        ((f(p).ln() + twins.iter().map(|q| f(q).ln()).sum::<f64>()) / n).exp()
    };
    let temps: Vec<f64> = std::iter::once(p)
        .chain(twins.iter().copied())
        .filter_map(|q| q.temp_c)
        .collect();
    let mut flags = p.flags.clone();
    for f in twins.iter().flat_map(|q| &q.flags) {
        if !flags.contains(f) {
            flags.push(f.clone());
        }
    }
    DataPoint {
        freq_hz: geo(|q| q.freq_hz),
        storage_pa: geo(|q| q.storage_pa),
        loss_pa: geo(|q| q.loss_pa),
        temp_c: (!temps.is_empty()).then(|| temps.iter().sum::<f64>() / temps.len() as f64),
        line: p.line,
        flags,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn specimen(scale: f64, temps: &[f64]) -> Measurement {
        use crate::testdata::{broad_spectrum, synthetic_measurement, SyntheticSettings};
        let law = crate::ShiftLaw::Wlf {
            c1: 8.86,
            c2_k: 101.6,
            t_ref_c: 0.0,
        };
        let all = vec![-20.0, 0.0, 20.0, 40.0];
        let mut m = synthetic_measurement(&broad_spectrum(), &SyntheticSettings::new(all, law));
        if !temps.is_empty() {
            m.isotherms.retain(|i| {
                temps
                    .iter()
                    .any(|t| (t - i.temp_nominal_c).abs() < SAME_TEMP_K)
            });
        }
        for i in &mut m.isotherms {
            for p in &mut i.points {
                p.storage_pa *= scale;
                p.loss_pa *= scale;
            }
        }
        m
    }

    #[test]
    fn pooled_moduli_are_the_geometric_means_where_every_specimen_measured() {
        let base = specimen(1.0, &[]);
        let temps: Vec<f64> = base.isotherms.iter().map(|i| i.temp_nominal_c).collect();
        assert!(temps.len() >= 3, "{temps:?}");
        let a = specimen(2.0, &temps);
        let b = specimen(0.5, &temps[1..]);
        let (p, notes) = pool("x", &[a.clone(), b]).unwrap();
        // √(2·0.5) = 1: the pooled moduli are the unscaled ones, on the isotherms both measured
        assert_eq!(p.isotherms.len(), temps.len() - 1);
        for (pi, bi) in p.isotherms.iter().zip(&base.isotherms[1..]) {
            for (q, r) in pi.points.iter().zip(&bi.points) {
                assert!((q.storage_pa / r.storage_pa - 1.0).abs() < 1e-12);
                assert!((q.loss_pa / r.loss_pa - 1.0).abs() < 1e-12);
            }
        }
        assert_eq!(p.sources.len(), 2 * a.sources.len());
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert!(notes[0].contains("1 isotherm(s)"), "{notes:?}");
    }

    #[test]
    fn specimens_without_a_shared_isotherm_or_of_different_kinds_are_refused() {
        let base = specimen(1.0, &[]);
        let t: Vec<f64> = base.isotherms.iter().map(|i| i.temp_nominal_c).collect();
        let a = specimen(1.0, &t[..1]);
        let b = specimen(1.0, &t[1..2]);
        let e = pool("x", &[a.clone(), b]).unwrap_err().to_string();
        assert!(e.contains("share no isotherm"), "{e}");
        let mut c = a.clone();
        c.kind = match a.kind {
            crate::ModulusKind::Tensile => crate::ModulusKind::Shear,
            _ => crate::ModulusKind::Tensile,
        };
        let e = pool("x", &[a, c]).unwrap_err().to_string();
        assert!(e.contains("measured alike"), "{e}");
    }
}
