//! Stage `pipeline`: the main job, from a folder of DMA exports to fits and reports.

pub mod compound_fit;

pub use compound_fit::CompoundFit;
