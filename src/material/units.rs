//! Unit constants and defaults shared by the stages (SI inside; temperatures at the edges in °C).

/// Universal gas constant R in J/(mol·K).
pub const GAS_CONSTANT_J_PER_MOL_K: f64 = 8.314_462_618;

/// 0 °C in K.
pub const ZERO_CELSIUS_K: f64 = 273.15;

/// Poisson's ratio of an incompressible rubber, the serde default of every spectrum's `poisson`.
pub fn default_poisson() -> f64 {
    0.5
}
