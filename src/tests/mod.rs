//! The crate's own tests that reach into its internals (issue 30: the library shows only the stages'
//! entry points and their types). Each file was an integration test under `tests/`; it moved here
//! unchanged, its `viscoroll::` paths resolved by `extern crate self as viscoroll` (src/lib.rs).
//! Tests that run the `viscoroll` binary, or use only the public API, stay under `tests/`. The
//! helpers both sets use are one file each under `tests/`, included here by path: the seed of
//! randomized tests (`seed.rs`), the standard linear solid (`sls.rs`), readers of shipped files
//! (`shipped.rs`).

#[path = "../../tests/seed.rs"]
mod seed;
// Shared with the integration tests: each side uses part of them.
#[allow(dead_code)]
#[path = "../../tests/shipped.rs"]
mod shipped;
#[allow(dead_code)]
#[path = "../../tests/sls.rs"]
mod sls;

mod auto_budget;
mod bands_calibration;
mod bands_window;
mod cards_vendor;
mod contact_auto;
mod contact_props;
mod contact_rear;
mod contact_thesis;
mod contact_thesis_vs_exact;
mod dma_errors;
mod dma_formats;
mod dma_real;
mod fit_search_gaps;
mod fuzz_inputs;
mod hostile_budget;
mod layer_degree;
mod layer_props;
mod layer_thin_gains;
mod master_plateau;
mod mutation_gaps;
mod prony_terms;
mod report_plots;
mod special_functions;
mod spectra_cards;
mod spectra_exact;
mod time_vendor;
