//! Integration tests: one binary (links once on a 2-core CI). Each file under tests/ is a module.
mod contact_auto;
mod contact_thesis;
mod contact_exact;
mod special_functions;
