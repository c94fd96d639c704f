//! `viscoroll roll`: one dimensional scene, a rigid roll on a half-space with a given creep spectrum
//! (JSON, the serde form of [`crate::CreepSpectrum`]) → friction, contact length, offset, pressure.
//! A fit file (`fits/NAME.json`, [`crate::pipeline::CompoundFit`]) is accepted too, with `--temp-c T`:
//! its creep spectrum is moved to T by its shift law (`CreepSpectrum::at_temperature`, docs/MATH.md §6);
//! a T outside the measured temperatures is allowed and flagged (`extrapolated`, and a warning).
//!
//! `--json` prints one object: `friction`, `contact_length_mm`, `offset_mm`, `resistance_n_per_m`,
//! `max_pressure_mpa`, `x_mm`, `pressure_mpa`, the dimensionless problem (`lambda`, `beta`, `load`,
//! `rho`, `time_scale_s`, `creep`), the numerics (`scheme`, `n`, `iterations`) and the 90 %
//! uncertainty band `friction_p05`, `friction_p50`, `friction_p95` (crate::bands: a fit file made by
//! `viscoroll fit` or `run` carries the bootstrap ensemble; one without it, e.g. from `fit
//! --no-bands` or an older build, gets an ensemble made from the fit file alone,
//! crate::bands::ensemble_from_fit, which its notes name; a bare creep spectrum has none: null, with
//! the reason in `bands_note`), and the band's notes in `bands_notes`.
//! With a cover (`--cover-mm`) the band is solved on the covered body as in the main job
//! (crate::bands::scene_bands_on, docs/MATH.md eq. 15.6); `--model winkler` (the conveyor tools'
//! model, not the one the bands solve) has none.

pub use super::roll_args::Args;
use super::roll_band::{band, band_fields, RollBand};
use super::roll_print::{Answer, Shift};
use crate::contact::{AutoSettings, Body, ContactSettings, Scene};
use crate::pipeline::roll_fit::{roll_source_at, CreepSource, SourceRoll};
use anyhow::{bail, Context};

/// Run `viscoroll roll`.
pub fn run(args: Args) -> anyhow::Result<()> {
    for (name, v) in [
        ("--radius-mm", args.radius_mm),
        ("--load-n-per-m", args.load_n_per_m),
        ("--speed-m-s", args.speed_m_s),
    ] {
        if !(v.is_finite() && v > 0.0) {
            bail!("{name} must be finite and > 0, got {v}");
        }
    }
    if let Some(h) = args.cover_mm.filter(|h| h.is_finite() && *h > 0.0) {
        crate::limits::cover("--cover-mm", h, args.radius_mm)?;
    }
    super::spectrum_input::refuse_fluid_or_relaxation(&args.spectrum)?;
    let source = CreepSource::read(&args.spectrum)
        .with_context(|| format!("cannot read spectrum file {}", args.spectrum.display()))?;
    match (&source, args.temp_c) {
        (CreepSource::Fit(fit), None) => bail!(
            "{}: a fit file needs --temp-c (its spectrum is at T_ref = {} °C)",
            args.spectrum.display(),
            fit.shift_law.t_ref_c()
        ),
        (CreepSource::Spectrum(_), Some(_)) => bail!(
            "{}: --temp-c needs a fit file (a bare creep spectrum has no shift law)",
            args.spectrum.display()
        ),
        _ => {}
    }
    let scene = Scene {
        radius_m: args.radius_mm * 1e-3,
        load_n_per_m: args.load_n_per_m,
        speed_m_s: args.speed_m_s,
        poisson: args.poisson,
        body: Body::HALF_SPACE,
    };
    if args.cover_mm.is_some() || args.model.is_some() {
        // A cover: the body is chosen and solved by contact::body::layer (super::roll_cover).
        let (spectrum, shifted, warnings) = match (&source, args.temp_c) {
            (CreepSource::Fit(fit), Some(t)) => {
                let (at, w) = crate::pipeline::roll_fit::fit_spectrum_at(fit, t)
                    .with_context(|| format!("{}: --temp-c {t}", args.spectrum.display()))?;
                (at.spectrum.clone(), Some(at), w.into_iter().collect())
            }
            (CreepSource::Spectrum(s), _) => (s.clone(), None, Vec::new()),
            (CreepSource::Fit(_), None) => bail!("a fit file needs --temp-c"),
        };
        return super::roll_cover::run(
            &args,
            &source,
            &scene,
            &spectrum,
            shifted.as_ref(),
            warnings,
        );
    }
    let settings = ContactSettings {
        scheme: args.scheme,
        n: args.n,
        auto: AutoSettings {
            tol: args.tol,
            ..AutoSettings::default()
        },
        ..ContactSettings::default()
    };
    let r = roll_source_at(&source, args.temp_c, &scene, &settings)
        .with_context(|| format!("{}", args.spectrum.display()))?;
    let band = band(&args, &source, &scene, r.roll.friction);
    print_answer(&args, &r, &band);
    Ok(())
}

/// Print through the shared printer: the `auto` diagnostics in the JSON object, the dimensionless
/// problem and the numerics in the text.
fn print_answer(args: &Args, r: &SourceRoll, band: &RollBand) {
    let (sol, shifted) = (&r.roll, &r.shift);
    let d = &sol.dimensionless;
    let mut json_extra = serde_json::Map::new();
    let mut lines_after = vec![format!(
        "dimensionless: lambda = {:.6}, beta = {:.6}, N' = {}, rho = {:.6e}, T = {:.6e} s; {} n = {}, {} solves",
        d.lambda, d.beta, d.load, sol.problem.rho, sol.problem.time_scale_s, d.scheme, d.n, d.iterations
    )];
    if let Some(a) = &d.diagnostics {
        for (k, v) in [
            ("error_estimate", serde_json::json!(d.error_estimate)),
            ("tol", serde_json::json!(a.tol)),
            ("modes_used", serde_json::json!(a.modes_used)),
            ("modes_total", serde_json::json!(a.modes_total)),
            ("modes_lumped", serde_json::json!(a.modes_lumped)),
            ("modes_dropped", serde_json::json!(a.modes_dropped)),
            (
                "min_pressure_ratio",
                serde_json::json!(a.min_pressure_ratio),
            ),
        ] {
            json_extra.insert(k.into(), v);
        }
        lines_after.push(format!(
            "auto: error estimate {:.3e} (tol {:e}), modes used {}/{} (lumped {}, dropped {})",
            d.error_estimate.unwrap_or(f64::NAN),
            a.tol,
            a.modes_used,
            a.modes_total,
            a.modes_lumped,
            a.modes_dropped
        ));
    }
    lines_after.push(band_fields(band, &mut json_extra));
    Answer {
        args,
        sol,
        shift: shifted.as_ref().map(|a| Shift {
            temp_c: a.temp_c,
            log10_a_t: a.log10_a_t,
            extrapolated: a.extrapolated,
        }),
        terms: r.spectrum.terms.len(),
        warnings: &r.warnings,
        json_extra,
        header_suffix: String::new(),
        lines_after_header: Vec::new(),
        lines_after,
    }
    .print();
}
