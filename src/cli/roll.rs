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
//! (crate::bands::scene_ratios_on, docs/MATH.md eq. 15.6); `--model winkler` (the conveyor tools'
//! model, not the one the bands solve) has none.

use super::roll_print::{Answer, Shift};
use crate::contact::{AutoSettings, Body, ContactSettings, Scene, Scheme};
use crate::pipeline::roll_fit::{roll_source_at, CreepSource, SourceRoll};
use anyhow::{bail, Context};
use std::path::PathBuf;

/// Arguments of `viscoroll roll`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Creep spectrum, JSON (`kind`, `poisson`, `compliance_glassy_per_pa`, `terms`: [{`compliance_per_pa`, `tau_s`}]),
    /// or a fit file (`viscoroll run`'s fits/NAME.json) together with --temp-c.
    #[arg(value_name = "SPECTRUM.json|FIT.json")]
    pub spectrum: PathBuf,
    /// Temperature in °C (fit files only: the spectrum is shifted there by the fit's shift law).
    #[arg(long, allow_negative_numbers = true, value_parser = super::temp_c)]
    pub temp_c: Option<f64>,
    /// Roll radius in mm (> 0).
    #[arg(long, allow_negative_numbers = true)]
    pub radius_mm: f64,
    /// Load per unit width in N/m (> 0).
    #[arg(long, allow_negative_numbers = true)]
    pub load_n_per_m: f64,
    /// Rolling speed in m/s (> 0).
    #[arg(long, allow_negative_numbers = true)]
    pub speed_m_s: f64,
    /// Poisson's ratio in [0, 0.5] (default: the spectrum's, itself 0.5 by default).
    #[arg(long, allow_negative_numbers = true)]
    pub poisson: Option<f64>,
    /// Number of intervals of the thesis scheme.
    #[arg(long, default_value_t = 200)]
    pub n: usize,
    /// Discretisation: `auto` (error-controlled, default), `thesis` (piecewise linear, `--n`) or
    /// `exact` (one creep term only).
    #[arg(long, default_value_t = Scheme::Auto)]
    pub scheme: Scheme,
    /// Relative tolerance on friction and contact length for `--scheme auto` (1e-12 … 0.1).
    #[arg(long, default_value_t = 1e-6)]
    pub tol: f64,
    /// Rubber cover thickness in mm on a rigid carcass (absent: a half-space).
    #[arg(long, allow_negative_numbers = true)]
    pub cover_mm: Option<f64>,
    /// Body: `auto` (default with a cover: the cheapest within --tol of the layer), `half-space`,
    /// `layer` (bonded to a rigid carcass) or `winkler` (uniaxial columns, as conveyor design tools).
    #[arg(long)]
    pub model: Option<String>,
    /// Skip the uncertainty band (a fit file made by `viscoroll fit` or `run` carries the bootstrap
    /// ensemble it needs; for one without, an ensemble is made from the fit file; see crate::bands).
    #[arg(long)]
    pub no_bands: bool,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
}

/// A friction band with the notes the main job gives the same point (widened beyond the measured
/// temperatures, eq. 15.8, or frequencies, eq. 15.9; replicates that failed), or why there is none.
pub(super) struct RollBand {
    /// The 90 % band, or why there is none.
    pub band: Result<crate::results::FrictionBand, String>,
    /// The band's notes, as in friction.csv's note column.
    pub notes: Vec<String>,
}

impl From<Result<crate::results::FrictionBand, String>> for RollBand {
    fn from(band: Result<crate::results::FrictionBand, String>) -> Self {
        Self {
            band,
            notes: Vec::new(),
        }
    }
}

/// The 90 % band of the friction `friction` of `scene` at `--temp-c` (crate::bands), on a cover of
/// `cover_m` bonded to a rigid carcass (solved as the main job solves a covered scene, eq. 15.6) or
/// on the half-space (`None`), with its notes, or why there is none.
pub(super) fn band(
    args: &Args,
    source: &CreepSource,
    scene: &Scene,
    cover_m: Option<f64>,
    friction: f64,
) -> RollBand {
    band_or_why(args, source, scene, cover_m, friction).unwrap_or_else(|why| Err(why).into())
}

fn band_or_why(
    args: &Args,
    source: &CreepSource,
    scene: &Scene,
    cover_m: Option<f64>,
    friction: f64,
) -> Result<RollBand, String> {
    if args.no_bands {
        return Err("skipped (--no-bands)".into());
    }
    let (CreepSource::Fit(fit), Some(t)) = (source, args.temp_c) else {
        return Err("a bare creep spectrum carries no measurement scatter: bands need a fit file (`viscoroll fit` or `run`)".into());
    };
    let settings = crate::bands::BandSettings::default();
    // A fit file without an ensemble gets one made from the fit file alone (its note says what
    // that leaves out).
    let made;
    let ensemble = match fit.bands.as_ref() {
        Some(e) => e,
        None => {
            made = crate::bands::ensemble_from_fit(fit, &settings)
                .map_err(|e| format!("no ensemble could be made from the fit file: {e}"))?;
            &made
        }
    };
    let bands = crate::bands::scene_bands_on(fit, ensemble, scene, cover_m, &[t], &settings);
    let (band, mut notes) = bands.point_band(0, friction);
    // The between-specimen term as `run` adds it (docs/MATH.md §16): a fit file does not carry its
    // specimens' own frictions, so the default spread of one specimen applies, and the note says so.
    let band = band.map(|b| crate::bands::widen(b, crate::bands::between_sd_ln(&[]), 1));
    notes.push(crate::bands::specimens_note(1, crate::bands::PRIOR_SD_LN));
    if fit.bands.is_none() {
        notes.push(crate::bands::FROM_FIT_FILE_NOTE.to_string());
    }
    Ok(match band {
        Some(b) => RollBand { band: Ok(b), notes },
        None if notes.is_empty() => {
            Err("too few replicate solves succeeded for a band".to_string()).into()
        }
        None => Err(notes.join("; ")).into(),
    })
}

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
        body: Body::HalfSpace,
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
    let band = band(&args, &source, &scene, None, r.roll.friction);
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
    if let Some(a) = &d.auto {
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

/// The band's JSON fields (`friction_p05`, `friction_p50`, `friction_p95`, null without one,
/// `bands_note` why there is none, and `bands_notes` what the band carries) into `json`, and its
/// text lines.
pub(super) fn band_fields(
    rb: &RollBand,
    json: &mut serde_json::Map<String, serde_json::Value>,
) -> String {
    let band = &rb.band;
    for (k, v) in [
        ("friction_p05", band.as_ref().ok().map(|b| b.p05)),
        ("friction_p50", band.as_ref().ok().map(|b| b.p50)),
        ("friction_p95", band.as_ref().ok().map(|b| b.p95)),
    ] {
        json.insert(k.into(), serde_json::json!(v));
    }
    json.insert("bands_note".into(), serde_json::json!(band.as_ref().err()));
    json.insert("bands_notes".into(), serde_json::json!(rb.notes));
    match band {
        Ok(b) => {
            let mut line = format!(
                "friction 90 % band  = {:.6e} … {:.6e} (median {:.6e})",
                b.p05, b.p95, b.p50
            );
            for n in &rb.notes {
                line.push_str(&format!("\n  band note: {n}"));
            }
            line
        }
        Err(why) => format!("friction band: none: {why}"),
    }
}
