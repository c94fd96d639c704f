//! The first stages, each the library call its CLI subcommand makes: `ingest` (crate::dma::read_files
//! or read_bytes, as src/cli/ingest.rs), `master` (crate::tts::build_master_curve, or pyvisco's
//! master curve read already shifted, as src/cli/master.rs), `fit` (crate::pipeline::fit_compound
//! and the bands' ensemble, as src/cli/fit.rs) and `convert` (crate::creep, as src/cli/convert.rs),
//! and pyvisco's Prony-term CSV both ways (crate::prony::pyvisco_csv).
//!
//! In: JSON text of the library's serde types and an options object (crate::opts); out: JSON text.
//! The heavy work runs with the GIL released.

use crate::opts::Opts;
use crate::{stage_err, to_json, Stage};
use pyo3::prelude::*;
use viscoroll::dma::{self, Format, IngestOptions, Measurement};
use viscoroll::pipeline::{fit_master_curve, fit_measurement_master, FitOptions, FitTuning};
use viscoroll::tts::MasterSettings;
use viscoroll::{ModulusKind, RelaxationSpectrum};

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    use crate::arg;
    export!(m, c"ingest_files", |py, a| ingest_files(
        py,
        arg(a, 0)?,
        &arg::<String>(a, 1)?
    ));
    export!(m, c"ingest_bytes", |py, a| ingest_bytes(
        py,
        arg(a, 0)?,
        &arg::<String>(a, 1)?
    ));
    export!(m, c"master", |py, a| master(
        py,
        &arg::<String>(a, 0)?,
        &arg::<String>(a, 1)?
    ));
    export!(m, c"master_pyvisco", |_py, a| master_pyvisco(
        &arg::<String>(a, 0)?,
        arg(a, 1)?,
        &arg::<String>(a, 2)?,
        arg(a, 3)?,
        arg(a, 4)?
    ));
    export!(m, c"fit", |py, a| fit(
        py,
        &arg::<String>(a, 0)?,
        &arg::<String>(a, 1)?
    ));
    export!(m, c"fit_pyvisco", |py, a| fit_pyvisco(
        py,
        &arg::<String>(a, 0)?,
        arg(a, 1)?,
        &arg::<String>(a, 2)?,
        arg(a, 3)?,
        arg(a, 4)?,
        &arg::<String>(a, 5)?
    ));
    export!(m, c"convert", |_py, a| convert(
        &arg::<String>(a, 0)?,
        &arg::<String>(a, 1)?,
        &arg::<String>(a, 2)?
    ));
    export!(m, c"pyvisco_terms_read", |_py, a| pyvisco_terms_read(
        &arg::<String>(a, 0)?,
        arg(a, 1)?,
        arg(a, 2)?
    ));
    export!(m, c"pyvisco_terms_write", |_py, a| pyvisco_terms_write(
        &arg::<String>(a, 0)?
    ));
    export!(m, c"fit_write", |_py, a| fit_write(
        &arg::<String>(a, 0)?,
        &arg::<String>(a, 1)?,
        arg(a, 2)?
    ));
    export!(m, c"fit_read", |_py, a| fit_read(&arg::<String>(a, 0)?));
    Ok(())
}

const INGEST_KEYS: &[&str] = &[
    "format",
    "modulus_unit",
    "freq_unit",
    "temp_unit",
    "mode",
    "columns",
    "poisson",
];

/// The ingest options, as `viscoroll ingest`'s flags give them (src/cli/ingest.rs).
fn ingest_options(json: &str) -> PyResult<IngestOptions> {
    let o = Opts::parse(Stage::Ingest, json, INGEST_KEYS)?;
    let stage = Stage::Ingest;
    let bad = |key: &str, v: &str, known: &str| {
        stage_err(stage)(anyhow::anyhow!("{key} `{v}`: expected one of {known}"))
    };
    let mut opts = IngestOptions {
        poisson: o.f64("poisson")?.unwrap_or(0.5),
        ..IngestOptions::default()
    };
    if let Some(c) = o.str("columns")? {
        opts.columns = dma::ColumnMap::parse(&c)
            .map_err(|e| stage_err(stage)(anyhow::anyhow!("columns: {e}")))?;
    }
    if let Some(f) = o.str("format")? {
        opts.format = Some(
            f.parse::<Format>()
                .map_err(|e| stage_err(stage)(anyhow::anyhow!(e)))?,
        );
    }
    if let Some(u) = o.str("modulus_unit")? {
        opts.set_unit("modulus", &u)
            .map_err(|e| stage_err(stage)(anyhow::anyhow!("modulus_unit {e}")))?;
    }
    if let Some(u) = o.str("freq_unit")? {
        opts.set_unit("freq", &u)
            .map_err(|e| stage_err(stage)(anyhow::anyhow!("freq_unit {e}")))?;
    }
    if let Some(u) = o.str("temp_unit")? {
        opts.set_unit("temp", &u)
            .map_err(|e| stage_err(stage)(anyhow::anyhow!("temp_unit {e}")))?;
    }
    if let Some(m) = o.str("mode")? {
        opts.mode = Some(match m.to_ascii_lowercase().as_str() {
            "tensile" | "tension" | "e" => ModulusKind::Tensile,
            "shear" | "g" => ModulusKind::Shear,
            _ => return Err(bad("mode", &m, "tensile, shear")),
        });
    }
    Ok(opts)
}

/// Read DMA export files into one measurement (JSON).
fn ingest_files(py: Python<'_>, paths: Vec<String>, options: &str) -> PyResult<String> {
    let opts = ingest_options(options)?;
    let m = py
        .detach(|| dma::read_files(&paths, &opts))
        .map_err(stage_err(Stage::Ingest))?;
    to_json(Stage::Ingest, &m)
}

/// Read exports already in memory, each `(name, bytes)`, into one measurement (JSON).
fn ingest_bytes(py: Python<'_>, inputs: Vec<(String, Vec<u8>)>, options: &str) -> PyResult<String> {
    let opts = ingest_options(options)?;
    let m = py
        .detach(|| dma::read_bytes(&inputs, &opts))
        .map_err(stage_err(Stage::Ingest))?;
    to_json(Stage::Ingest, &m)
}

const TTS_KEYS: &[&str] = &[
    "tref",
    "shift",
    "vertical",
    "criterion",
    "law",
    "fit_range",
    "nominal",
];
const PRONY_KEYS: &[&str] = &["max_terms", "target_rms", "reduce", "no_bands", "name"];

/// The master-curve and Prony options given (src/cli/tuning_args.rs: the same names and parsers).
pub(crate) fn fit_tuning(o: &Opts, stage: Stage) -> PyResult<(Option<f64>, FitTuning)> {
    let tref = o.f64("tref")?;
    if let Some(t) = tref {
        viscoroll::limits::temperature_c("tref", t)
            .map_err(|e| stage_err(stage)(anyhow::anyhow!(e.reason)))?;
    }
    let mut t = FitTuning {
        nominal: o.flag("nominal")?,
        reduce: o.flag("reduce")?,
        max_terms: o.usize("max_terms")?,
        ..FitTuning::default()
    };
    if t.max_terms == Some(0) {
        return Err(stage_err(stage)(anyhow::anyhow!(
            "max_terms: must be at least 1"
        )));
    }
    for key in [
        "shift",
        "vertical",
        "criterion",
        "law",
        "fit_range",
        "target_rms",
    ] {
        if let Some(text) = o.str(key)? {
            t.set_text(key, &text, tref, std::path::Path::new(""))
                .map_err(|e| stage_err(stage)(anyhow::anyhow!(e)))?;
        }
    }
    Ok((tref, t))
}

/// A measurement JSON, checked like any export (crate::dma::plausible, as `master` and `fit` read it).
fn measurement(stage: Stage, json: &str) -> PyResult<Measurement> {
    Measurement::from_json("measurement", json).map_err(stage_err(stage))
}

/// The master curve of a measurement (JSON), with `viscoroll master`'s settings.
fn master(py: Python<'_>, measurement_json: &str, options: &str) -> PyResult<String> {
    let o = Opts::parse(Stage::Master, options, TTS_KEYS)?;
    let (tref, tuning) = fit_tuning(&o, Stage::Master)?;
    let m = measurement(Stage::Master, measurement_json)?;
    // `viscoroll master`: the default master settings (law: the better of WLF and Arrhenius), the
    // flags laid over them.
    let mut fit_options = FitOptions {
        master: MasterSettings {
            tref_c: tref,
            ..MasterSettings::default()
        },
        ..FitOptions::default()
    };
    tuning.apply(&mut fit_options);
    let mc = py
        .detach(|| viscoroll::tts::build_master_curve(&m, &fit_options.master))
        .map_err(stage_err(Stage::Master))?;
    to_json(Stage::Master, &mc)
}

/// pyvisco's master curve and shift factors (CSV bytes) read already shifted: (measurement JSON,
/// master-curve JSON).
fn pyvisco_pair(
    stage: Stage,
    master: (&str, &[u8]),
    shifts: (&str, &[u8]),
    poisson: f64,
    tref: Option<f64>,
) -> PyResult<(Measurement, viscoroll::tts::MasterCurve)> {
    let pv = dma::PyviscoMaster::from_bytes(master.0, master.1, shifts.0, shifts.1, poisson, tref)
        .map_err(stage_err(stage))?;
    let mc = viscoroll::tts::master_curve_from_reduced(&pv.measurement, &pv.shift_law)
        .map_err(|e| stage_err(stage)(anyhow::Error::new(e).context(master.0.to_string())))?;
    Ok((pv.measurement, mc))
}

/// `viscoroll master --master-curve M --shift-factors S`: (measurement JSON, master-curve JSON).
fn master_pyvisco(
    master_name: &str,
    master_csv: Vec<u8>,
    shift_name: &str,
    shift_csv: Vec<u8>,
    tref: Option<f64>,
) -> PyResult<(String, String)> {
    let (m, mc) = pyvisco_pair(
        Stage::Master,
        (master_name, &master_csv),
        (shift_name, &shift_csv),
        0.5,
        tref,
    )?;
    Ok((to_json(Stage::Master, &m)?, to_json(Stage::Master, &mc)?))
}

/// `viscoroll fit`'s options: the main job's defaults with the flags laid over them.
fn fit_options(options: &str) -> PyResult<(FitOptions, bool, String)> {
    let keys: Vec<&str> = TTS_KEYS.iter().chain(PRONY_KEYS).copied().collect();
    let o = Opts::parse(Stage::Fit, options, &keys)?;
    let (tref, tuning) = fit_tuning(&o, Stage::Fit)?;
    let mut fo = FitOptions::default();
    fo.master.tref_c = tref;
    tuning.apply(&mut fo);
    let name = o.str("name")?.unwrap_or_else(|| "compound".to_string());
    Ok((fo, !o.flag("no_bands")?, name))
}

/// Fit a measurement (JSON) as `viscoroll fit` does a new fit: master curve, Prony series, creep
/// spectrum, and (unless `no_bands`) the bootstrap ensemble of the bands. Returns (fit JSON, why
/// the fit carries no ensemble, when it could not be made).
fn fit(
    py: Python<'_>,
    measurement_json: &str,
    options: &str,
) -> PyResult<(String, Option<String>)> {
    let (fo, bands, name) = fit_options(options)?;
    let m = measurement(Stage::Fit, measurement_json)?;
    let (f, why) = py
        .detach(|| -> Result<_, viscoroll::pipeline::PipelineError> {
            let (mut f, master) = fit_measurement_master(&name, &m, &fo)?;
            // as crate::pipeline::fit_compound::fit_or_reuse_with_bands adds it to a new fit
            let why = match bands.then(viscoroll::bands::BandSettings::default) {
                None => None,
                Some(s) => match viscoroll::bands::build_ensemble(&master, &m, &f, &s) {
                    Ok(e) => {
                        f.bands = Some(e);
                        None
                    }
                    Err(e) => Some(e.not_computed_warning()),
                },
            };
            Ok((f, why))
        })
        .map_err(stage_err(Stage::Fit))?;
    Ok((to_json(Stage::Fit, &f)?, why))
}

/// `viscoroll fit --master-curve M --shift-factors S`: pyvisco's master curve fitted; its ensemble
/// (unless `no_bands`) made from its points alone (crate::bands::ensemble_from_fit).
fn fit_pyvisco(
    py: Python<'_>,
    master_name: &str,
    master_csv: Vec<u8>,
    shift_name: &str,
    shift_csv: Vec<u8>,
    poisson: f64,
    options: &str,
) -> PyResult<(String, Option<String>)> {
    let (mut fo, bands, name) = fit_options(options)?;
    let (m, mc) = pyvisco_pair(
        Stage::Fit,
        (master_name, &master_csv),
        (shift_name, &shift_csv),
        poisson,
        fo.master.tref_c,
    )?;
    fo.master = mc.settings.clone();
    let (f, why) = py
        .detach(|| -> Result<_, viscoroll::pipeline::PipelineError> {
            let mut f = fit_master_curve(&name, &m, &mc, &fo)?;
            let why = match bands.then(viscoroll::bands::BandSettings::default) {
                None => None,
                Some(s) => match viscoroll::bands::ensemble_from_fit(&f, &s) {
                    Ok(e) => {
                        f.bands = Some(e);
                        None
                    }
                    Err(e) => Some(e.not_computed_warning()),
                },
            };
            Ok((f, why))
        })
        .map_err(stage_err(Stage::Fit))?;
    Ok((to_json(Stage::Fit, &f)?, why))
}

/// A relaxation spectrum (JSON) → `{"method", "variant", "creep_spectrum", "checks", "info"}`, as
/// `viscoroll convert --json` prints it (src/cli/convert.rs: the same checks, over the spectrum's
/// window ± 4 decades, 8 points per decade).
fn convert(relaxation_json: &str, method: &str, variant: &str) -> PyResult<String> {
    use viscoroll::creep::{ParkSchaperySettings, ParkSchaperyVariant};
    let stage = Stage::Convert;
    let relax: RelaxationSpectrum =
        serde_json::from_str(relaxation_json).map_err(stage_err(stage))?;
    relax.validate().map_err(stage_err(stage))?;
    let (creep, variant, info) = match method {
        "exact" => {
            let (c, info) =
                viscoroll::creep::relaxation_to_creep(&relax).map_err(stage_err(stage))?;
            (
                c,
                None,
                serde_json::to_value(info).map_err(stage_err(stage))?,
            )
        }
        "park-schapery" => {
            let variant = match variant {
                "collocation-1" => ParkSchaperyVariant::CollocationOne,
                "collocation-half" => ParkSchaperyVariant::CollocationHalf,
                "least-squares" => ParkSchaperyVariant::LeastSquares,
                v => {
                    return Err(stage_err(stage)(anyhow::anyhow!(
                        "variant `{v}`: expected collocation-1, collocation-half or least-squares"
                    )))
                }
            };
            let settings = ParkSchaperySettings {
                variant,
                ..Default::default()
            };
            let (c, info) =
                viscoroll::creep::park_schapery(&relax, &settings).map_err(stage_err(stage))?;
            (
                c,
                Some(variant.name()),
                serde_json::to_value(info).map_err(stage_err(stage))?,
            )
        }
        m => {
            return Err(stage_err(stage)(anyhow::anyhow!(
                "method `{m}`: expected exact or park-schapery"
            )))
        }
    };
    let (wmin, wmax, omegas) = relax.check_frequencies();
    let product = relax.max_product_error(&creep, &omegas);
    let obj = serde_json::json!({
        "method": method,
        "variant": variant,
        "creep_spectrum": creep,
        "checks": {
            "max_abs_product_error": product,
            "omega_min_rad_s": wmin,
            "omega_max_rad_s": wmax,
            "glassy_product": creep.creep_compliance(0.0) * relax.instantaneous_modulus(),
            "relaxed_product": creep.compliance_relaxed() * relax.modulus_inf_pa,
            "negative_terms": creep.terms.iter().filter(|t| t.compliance_per_pa < 0.0).count(),
        },
        "info": info,
    });
    to_json(Stage::Convert, &obj)
}

/// pyvisco's Prony-term CSV (bytes) → a relaxation spectrum (JSON).
fn pyvisco_terms_read(name: &str, csv: Vec<u8>, poisson: f64) -> PyResult<String> {
    let s = RelaxationSpectrum::from_pyvisco_csv(name, &csv, poisson)
        .map_err(stage_err(Stage::Convert))?;
    to_json(Stage::Convert, &s)
}

/// A relaxation spectrum (JSON) → pyvisco's Prony-term CSV text.
fn pyvisco_terms_write(relaxation_json: &str) -> PyResult<String> {
    let s: RelaxationSpectrum =
        serde_json::from_str(relaxation_json).map_err(stage_err(Stage::Convert))?;
    Ok(s.to_pyvisco_csv())
}

/// Write a fit (JSON) as a fit file, as `viscoroll fit` writes it (atomically, with its content
/// hash; an existing file only with `force`).
fn fit_write(fit_json: &str, path: &str, force: bool) -> PyResult<bool> {
    let f: viscoroll::results::CompoundFit =
        serde_json::from_str(fit_json).map_err(stage_err(Stage::Fit))?;
    f.write(std::path::Path::new(path), force)
        .map_err(stage_err(Stage::Fit))?;
    Ok(true)
}

/// Read a fit file (checked as `roll` and `rank` read it) → fit JSON.
fn fit_read(path: &str) -> PyResult<String> {
    let f = viscoroll::results::CompoundFit::read(std::path::Path::new(path))
        .map_err(stage_err(Stage::Fit))?;
    to_json(Stage::Fit, &f)
}
