//! Plausibility of a [`Measurement`] in its stated units: values no DMA of a polymer can give are
//! refused, values that look like a unit mix-up are flagged with a suggestion.
//!
//! Input: a [`Measurement`] (SI inside: Pa, Hz, °C); output: `Err(reason)` for a temperature below
//! absolute zero or above `MAX_TEMP_C` (no polymer is measured there; an isotherm at 1e9 °C would
//! otherwise send the shift-law fits and scans into astronomically long loops), or the warnings to
//! add to `Measurement::warnings`. The flags: moduli 10³× or 10⁶× below every polymer's range (kPa or
//! MPa read as Pa), or above it; temperatures that look like kelvins labelled °C; frequencies above
//! `MAX_FREQ_HZ`; a storage modulus that rises with temperature.

use super::Measurement;

/// Highest isotherm temperature accepted, °C (rubber decomposes long before; DMA ovens stop ~600 °C).
pub(crate) const MAX_TEMP_C: f64 = 1000.0;
/// Highest frequency not flagged, Hz (DMA and rheometers stop near 1e3–1e4 Hz; ultrasound starts at 2e4).
pub(crate) const MAX_FREQ_HZ: f64 = 1e7;
/// Range of the storage modulus of polymers, Pa: soft gels ~1e3, glassy polymers ~1e10.
pub(crate) const POLYMER_MODULUS_PA: (f64, f64) = (1e3, 2e10);

fn median(mut v: Vec<f64>) -> Option<f64> {
    v.retain(|x| x.is_finite());
    if v.is_empty() {
        return None;
    }
    v.sort_by(f64::total_cmp);
    Some(v[v.len() / 2])
}

/// Where an isotherm's temperature comes from: the file, the line (or sheet row) of its first point
/// outside [−273.15, `MAX_TEMP_C`] °C (else of its first point) and the temperature column, if any.
fn temperature_place(m: &Measurement, iso: &super::Isotherm) -> String {
    let file = m.sources.get(iso.source).map_or("", |s| s.path.as_str());
    let bad = |t: f64| !(-273.15..=MAX_TEMP_C).contains(&t);
    let point = iso
        .points
        .iter()
        .find(|p| p.temp_c.is_some_and(bad))
        .or(iso.points.first());
    let mut place = file.to_string();
    if let Some(p) = point {
        match &iso.sheet {
            Some(sheet) => place.push_str(&format!(": sheet `{sheet}` row {}", p.line)),
            None => place.push_str(&format!(": line {}", p.line)),
        }
    }
    let column = m.sources.get(iso.source).and_then(|s| {
        ["temperature", "set temperature"]
            .iter()
            .find_map(|q| s.columns.iter().find(|c| c.quantity == *q))
    });
    if let Some(c) = column {
        place.push_str(&format!(", column `{}`", c.name));
    }
    place
}

/// Refuse impossible temperatures (see the module docs), naming the file, line and column.
pub fn refuse_impossible(m: &Measurement) -> Result<(), String> {
    for iso in &m.isotherms {
        for (what, t) in [
            ("nominal", iso.temp_nominal_c),
            ("mean measured", iso.temp_mean_c),
        ] {
            if t.is_nan() {
                continue; // a missing temperature is the checks' business
            }
            if t < -273.15 {
                return Err(format!(
                    "{}: isotherm {what} temperature {t} °C is below absolute zero (−273.15 °C): is the column in another unit?",
                    temperature_place(m, iso)
                ));
            }
            if t > MAX_TEMP_C {
                return Err(format!(
                    "{}: isotherm {what} temperature {t:e} °C is above {MAX_TEMP_C} °C, where no polymer is measured: the column is damaged or in another unit",
                    temperature_place(m, iso)
                ));
            }
        }
    }
    Ok(())
}

/// Both checks, as every reader applies them: impossible temperatures refused, suspected unit
/// mix-ups added to `m.warnings`.
pub fn check(m: &mut Measurement) -> Result<(), super::DmaError> {
    refuse_impossible(m).map_err(|message| super::DmaError::Implausible { message })?;
    let w = warnings(m);
    m.warnings.extend(w);
    Ok(())
}

/// A measurement JSON (the serde form of [`Measurement`] that `viscoroll ingest -o` writes, bare or
/// under `"measurement"`), parsed straight into the type (no JSON tree: a 1e6-point file stays
/// within its own size) and checked like any export ([`check`]). `name` labels the errors.
pub fn measurement_from_json(name: &str, text: &str) -> Result<Measurement, super::DmaError> {
    #[derive(serde::Deserialize)]
    struct Wrapped {
        measurement: Measurement,
    }
    let mut m = match serde_json::from_str::<Measurement>(text) {
        Ok(m) => m,
        Err(bare) => match serde_json::from_str::<Wrapped>(text) {
            Ok(w) => w.measurement,
            Err(_) => {
                return Err(super::DmaError::Structure {
                    file: name.to_string(),
                    location: format!("line {}, column {}", bare.line(), bare.column()),
                    message: format!(
                        "not a measurement JSON written by `viscoroll ingest`: {bare}"
                    ),
                })
            }
        },
    };
    check(&mut m)?;
    Ok(m)
}

/// Warnings, each with a suggestion, for values that look like a unit mix-up.
pub fn warnings(m: &Measurement) -> Vec<String> {
    let mut w = Vec::new();
    let points = || m.isotherms.iter().flat_map(|i| &i.points);
    if let Some(e) = median(points().map(|p| p.storage_pa).collect()) {
        let (lo, hi) = POLYMER_MODULUS_PA;
        if e < lo {
            // The factor that brings the median into the range where filled and unfilled rubbers
            // sit (1e5 Pa and up): a 5 MPa rubber read as Pa is 5 Pa, ×10³ would still be too soft.
            let factor = if e * 1e3 < 1e5 {
                "10⁶ (MPa read as Pa?)"
            } else {
                "10³ (kPa read as Pa?)"
            };
            w.push(format!(
                "median storage modulus {e:.3e} Pa lies below every polymer's range ({lo:e}–{hi:e} Pa), by about {factor}: state the unit (modulus_unit in compounds.toml, --modulus-unit)"
            ));
        } else if e > hi {
            w.push(format!(
                "median storage modulus {e:.3e} Pa lies above every polymer's range ({lo:e}–{hi:e} Pa): were the values in Pa but labelled kPa or MPa? State the unit (modulus_unit, --modulus-unit)"
            ));
        }
    }
    let temps: Vec<f64> = m
        .isotherms
        .iter()
        .map(|i| i.temp_nominal_c)
        .filter(|t| t.is_finite())
        .collect();
    if !temps.is_empty() && temps.iter().all(|t| (150.0..=500.0).contains(t)) {
        let (lo, hi) = temps
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), t| {
                (a.min(*t), b.max(*t))
            });
        w.push(format!(
            "every isotherm lies between {lo} and {hi} °C, where rubber degrades: are these kelvins labelled °C? State the unit (temp_unit = \"K\", --temp-unit K)"
        ));
    }
    if let Some(f) = points()
        .map(|p| p.freq_hz)
        .filter(|f| f.is_finite())
        .reduce(f64::max)
    {
        if f > MAX_FREQ_HZ {
            w.push(format!(
                "frequency {f:e} Hz is above {MAX_FREQ_HZ:e} Hz, beyond any DMA: is the column in another unit, or damaged?"
            ));
        }
    }
    // Storage modulus against temperature: the coldest isotherm should be the stiffest.
    let by_t: Vec<(f64, f64)> = m
        .isotherms
        .iter()
        .filter_map(|i| {
            Some((
                i.temp_nominal_c,
                median(i.points.iter().map(|p| p.storage_pa).collect())?,
            ))
        })
        .filter(|(t, _)| t.is_finite())
        .collect();
    let cold = by_t.iter().min_by(|a, b| a.0.total_cmp(&b.0));
    let hot = by_t.iter().max_by(|a, b| a.0.total_cmp(&b.0));
    if let (Some(&(tc, ec)), Some(&(th, eh))) = (cold, hot) {
        if th > tc && eh > 2.0 * ec {
            w.push(format!(
                "storage modulus rises with temperature ({ec:.3e} Pa at {tc} °C, {eh:.3e} Pa at {th} °C): are the temperatures assigned to the wrong isotherms, or did the sample cure during the test?"
            ));
        }
    }
    w
}

impl Measurement {
    /// A measurement JSON, parsed and checked like any export (`measurement_from_json`).
    pub fn from_json(name: &str, text: &str) -> Result<Self, super::DmaError> {
        measurement_from_json(name, text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dma::{DataPoint, Isotherm};

    fn m(temps: &[f64], modulus: impl Fn(f64) -> f64, freq_hz: f64) -> Measurement {
        let mut m: Measurement = serde_json::from_value(serde_json::json!({
            "sources": [], "kind": "tensile", "poisson": 0.5, "isotherms": [], "warnings": []
        }))
        .unwrap_or_else(|e| panic!("a bare measurement: {e}"));
        for &t in temps {
            m.isotherms.push(Isotherm {
                temp_nominal_c: t,
                temp_mean_c: t,
                source: 0,
                points: (0..5)
                    .map(|k| DataPoint {
                        freq_hz: freq_hz * (k + 1) as f64,
                        storage_pa: modulus(t),
                        loss_pa: modulus(t) / 10.0,
                        temp_c: Some(t),
                        line: k,
                        flags: vec![],
                    })
                    .collect(),
                nominal_source: String::new(),
                sheet: None,
                label: None,
            });
        }
        m
    }

    #[test]
    fn impossible_temperatures_are_refused() {
        let e = refuse_impossible(&m(&[20.0, 1e9], |_| 1e7, 1.0)).unwrap_err();
        assert!(e.contains("1e9") && e.contains("above"), "{e}");
        // The place: the first point of the isotherm (line 0 here; no file or column in this
        // bare measurement).
        assert!(e.starts_with(": line 0:"), "{e}");
        let e = refuse_impossible(&m(&[-300.0, 20.0], |_| 1e7, 1.0)).unwrap_err();
        assert!(e.contains("absolute zero"), "{e}");
        assert!(refuse_impossible(&m(&[-100.0, 200.0], |_| 1e7, 1.0)).is_ok());
    }

    #[test]
    fn unit_mix_ups_are_flagged_with_a_suggestion() {
        // a sane rubber: stiffer when cold, MPa range, 1–5 Hz
        assert!(warnings(&m(&[-20.0, 20.0, 60.0], |t| 1e7 * (1.0 - t / 100.0), 1.0)).is_empty());
        let w = warnings(&m(&[0.0, 20.0], |_| 5.0, 1.0)); // MPa read as Pa
        assert!(
            w.iter()
                .any(|w| w.contains("10⁶") && w.contains("modulus_unit")),
            "{w:?}"
        );
        let w = warnings(&m(&[0.0, 20.0], |_| 5e3 / 1e1 * 1e-0, 1.0)); // 500 Pa: kPa read as Pa
        assert!(w.iter().any(|w| w.contains("10³")), "{w:?}");
        let w = warnings(&m(
            &[253.15, 293.15, 333.15],
            |t| 1e7 * (400.0 - t) / 100.0,
            1.0,
        ));
        assert!(w.iter().any(|w| w.contains("kelvins")), "{w:?}");
        let w = warnings(&m(&[0.0, 20.0], |t| 1e7 * (1.0 - t / 100.0), 1e8));
        assert!(w.iter().any(|w| w.contains("beyond any DMA")), "{w:?}");
        let w = warnings(&m(&[0.0, 60.0], |t| 1e6 * (1.0 + t), 1.0));
        assert!(
            w.iter().any(|w| w.contains("rises with temperature")),
            "{w:?}"
        );
    }
}
