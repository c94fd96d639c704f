//! The outcome of the main job: one [`CompoundOutcome`] per compound and the [`RunSummary`] that
//! `viscoroll run --json` prints.
//!
//! Input: what the pipeline found per compound; output: plain serde data read by the ranking, the
//! index page and the CLI.

use super::scene::FrictionPoint;
use serde::Serialize;
use std::path::PathBuf;

/// The outcome of one compound.
#[derive(Debug, Clone, Serialize)]
pub struct CompoundOutcome {
    /// Compound name.
    pub compound: String,
    /// Fit file written or reused.
    pub fit_path: Option<PathBuf>,
    /// `reused`, `fitted` or `replaced`.
    pub fit_action: Option<String>,
    /// Mean friction per scene (scene name, mean F/N over its temperatures).
    pub mean_friction: Vec<(String, f64)>,
    /// Friction per scene and temperature.
    pub friction: Vec<(String, Vec<FrictionPoint>)>,
    /// Warnings (extrapolated temperatures, failed temperatures).
    pub warnings: Vec<String>,
    /// The error, if the compound failed.
    pub error: Option<String>,
    /// Wall time for this compound in seconds.
    pub seconds: f64,
}

/// The outcome of the main job.
#[derive(Debug, Clone, Serialize)]
pub struct RunSummary {
    /// One per compound, in discovery order.
    pub compounds: Vec<CompoundOutcome>,
    /// Notes on skipped entries.
    pub notes: Vec<String>,
    /// `reports/ranking.csv`.
    pub ranking_csv: PathBuf,
    /// `reports/index.html`.
    pub index_html: PathBuf,
}

impl RunSummary {
    /// Number of failed compounds.
    pub fn failures(&self) -> usize {
        self.compounds.iter().filter(|c| c.error.is_some()).count()
    }
}
