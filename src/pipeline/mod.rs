//! Stage `pipeline`: the main job, from a folder of DMA exports to fits and reports.
//!
//! Input: a folder of exports (or a `compounds.toml`), a [`SceneSet`] and an output folder; output:
//! fit files, friction in the scenes, and the reports (written by crate::report), plus a
//! [`RunSummary`]. The result types live one floor down, in crate::results.

mod compare;
pub mod compounds;
pub mod error;
pub mod fit_compound;
pub mod fit_time;
mod folder;
pub mod roll_fit;
pub mod run;
pub mod scenes;
pub mod shard;
pub mod specimens;
pub mod trust;
pub mod tuning;

/// The fit file's types (crate::results::compound_fit), at their former path.
pub use crate::results::compound_fit;
pub use crate::results::CompoundFit;
pub use error::PipelineError;
pub use fit_compound::{
    fit_files, fit_master_curve, fit_measurement, fit_or_reuse, fit_or_reuse_master, FitOptions,
};
pub use run::{
    run_all, run_all_with_progress, CompoundOutcome, ProgressEvent, RunOptions, RunStatus,
    RunSummary,
};
pub use scenes::{SceneSet, SceneSpec};
pub use tuning::FitTuning;
