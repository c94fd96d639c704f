//! Stage `pipeline`: the main job, from a folder of DMA exports to fits and reports.
