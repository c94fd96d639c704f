//! Stage `pipeline`: the main job, from a folder of DMA exports to fits and reports.
//!
//! Input: a folder of exports (or a `compounds.toml`), a [`SceneSet`] and an output folder; output:
//! fit files, friction in the scenes, and the reports (written by crate::report), plus a
//! [`RunSummary`]. The result types live one floor down, in crate::results.

mod compare;
pub(crate) mod compounds;
pub(crate) mod error;
pub(crate) mod fit_compound;
pub(crate) mod fit_time;
mod folder;
pub(crate) mod roll_fit;
pub(crate) mod run;
pub(crate) mod scenes;
pub(crate) mod shard;
pub(crate) mod specimens;
pub(crate) mod trust;
pub(crate) mod tuning;

/// The fit file's types (crate::results::compound_fit), at their former path.
pub(crate) use crate::results::CompoundFit;
pub use error::PipelineError;
pub use fit_compound::{
    fit_files, fit_master_curve, fit_measurement, fit_measurement_master, FitOptions,
};
pub use fit_time::fit_pyvisco_time_master;
pub use roll_fit::{fit_spectrum_at, point_band, roll_source_at, CreepSource};
pub use run::{run_all, RunOptions};
pub(crate) use run::{run_all_with_progress, ProgressEvent};
pub(crate) use run::{RunStatus, RunSummary};
pub(crate) use scenes::SceneSet;
pub use scenes::{friction_maps, friction_vs_temperature, pipeline_map_settings, COVER_TOL};
pub use tuning::FitTuning;
