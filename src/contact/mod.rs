//! Stage `contact`: a rigid cylinder rolling steadily on a viscoelastic half-space (thesis ch. 3–4).
//!
//! Input: a [`crate::CreepSpectrum`] (+ shift law and temperature) and a dimensional scene; output: the
//! contact solution (pressure, contact length, offset, rolling-friction coefficient).
