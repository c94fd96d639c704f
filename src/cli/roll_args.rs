//! The arguments of `viscoroll roll` ([`Args`]), below the command's files that read them (`roll`,
//! `roll_cover`, `roll_print`, `roll_band`).
//!
//! Input: the command line (clap); output: [`Args`].

use crate::contact::Scheme;
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
