//! Integration tests: one binary (links once on a 2-core CI). Each file under tests/ is a module.
mod contact_cli;
mod contact_exact;
mod contact_scene;
mod contact_thesis;
mod dma_errors;
mod dma_quirks;
mod dma_real;
mod ingest_cli;
mod master_cli;
mod pipeline_cli;
mod prony_ems_ca;
mod report_plots;
mod special_functions;
mod spectra_cards;
mod spectra_cli;
mod spectra_exact;
mod master_real;
