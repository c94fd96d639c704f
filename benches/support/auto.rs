//! The auto scheme at given load through the public entry, shared by the contact benches.

use viscoroll::contact::{
    solve_at_load, AutoSettings, ContactError, ContactSettings, CreepTerm, DimensionlessSolution,
    Scheme,
};

/// The auto scheme at load N′: `contact::solve_at_load` with `Scheme::Auto` and these auto settings.
pub fn solve_auto_at_load(
    terms: &[CreepTerm],
    load: f64,
    auto: &AutoSettings,
) -> Result<DimensionlessSolution, ContactError> {
    let settings = ContactSettings {
        scheme: Scheme::Auto,
        auto: *auto,
        ..Default::default()
    };
    solve_at_load(terms, load, &settings)
}
