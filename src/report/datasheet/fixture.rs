//! Test fixture: a [`CompoundFit`] with a chosen spectrum, shift law and measured temperatures.

use crate::dma::{DataPoint, Isotherm, Measurement, SourceFile};
use crate::prony::synthetic::{master_points, rubber_like_spectrum};
use crate::prony::{fit_prony, relaxation_times_s, PronySettings};
use crate::results::CompoundFit;
use crate::{ModulusKind, RelaxationSpectrum, ShiftLaw};
use std::collections::BTreeMap;

/// A fit whose relaxation spectrum is `spectrum`, its law `law`, measured at two isotherms at the
/// ends of `range_c` (°C); its creep spectrum the exact conversion of `spectrum`.
pub(crate) fn fit_with(
    spectrum: RelaxationSpectrum,
    law: ShiftLaw,
    range_c: (f64, f64),
) -> CompoundFit {
    let s = PronySettings::default();
    let truth = rubber_like_spectrum(&relaxation_times_s(1e-2, 1e4, &s));
    let pts = master_points(&truth, 1e-2, 1e4, 5.0, 0.0, 1);
    let mut prony = fit_prony(&pts, ModulusKind::Tensile, 0.5, &s).unwrap();
    prony.spectrum = spectrum;
    let iso = |t: f64| Isotherm {
        temp_nominal_c: t,
        temp_mean_c: t,
        source: 0,
        nominal_source: String::new(),
        sheet: None,
        label: None,
        points: vec![DataPoint {
            freq_hz: 1.0,
            storage_pa: 1e7,
            loss_pa: 1e6,
            temp_c: None,
            line: 1,
            flags: vec![],
        }],
    };
    let m = Measurement {
        sources: vec![SourceFile {
            path: "a.txt".into(),
            sha256: "ab".repeat(32),
            format: "synthetic".into(),
            metadata: BTreeMap::from([
                ("Material".to_string(), "SBR <tread>".to_string()),
                ("Operator".to_string(), "A. Tester".to_string()),
            ]),
            encoding: String::new(),
            columns: vec![],
        }],
        kind: ModulusKind::Tensile,
        poisson: 0.5,
        isotherms: vec![iso(range_c.0), iso(range_c.1)],
        warnings: vec![],
        issues: vec![],
        summary: Default::default(),
    };
    let mut fit = CompoundFit::new("demo", &m, law, pts, prony, s);
    fit.creep = crate::creep::relaxation_to_creep(&fit.relaxation)
        .ok()
        .map(|(c, _)| c);
    fit
}
