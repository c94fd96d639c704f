//! Integration tests: one binary (links once on a 2-core CI). Each file under tests/ is a module.
mod contact_auto;
mod contact_exact;
mod contact_thesis;
mod special_functions;
