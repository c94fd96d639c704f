//! Stage `pipeline`: the main job, from a folder of DMA exports to fits and reports.

pub mod compound_fit;
pub mod compounds;
pub mod datasheet;
pub mod error;
pub mod fit_compound;
pub mod friction_map;
pub mod run;
pub mod scenes;

pub use compound_fit::CompoundFit;
pub use error::PipelineError;
pub use fit_compound::{fit_files, fit_measurement, fit_or_reuse, FitOptions};
pub use run::{run_all, run_all_with_progress, ProgressEvent, RunOptions, RunSummary};
pub use scenes::{SceneSet, SceneSpec};
