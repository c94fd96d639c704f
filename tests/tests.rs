//! Integration tests: one binary (links once on a 2-core CI). Each file under tests/ is a module.
mod prony_ems_ca;
mod report_plots;
