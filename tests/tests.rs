//! Integration tests: one binary (links once on a 2-core CI). Each file under tests/ is a module.
mod dma_errors;
mod dma_quirks;
mod dma_real;
mod dma_xlsx;
mod ingest_cli;
