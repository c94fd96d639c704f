//! [`ModulusKind`]: whether a modulus (or compliance) is tensile or shear, and the factor between them.

use serde::{Deserialize, Serialize};

/// Which modulus a spectrum or a measurement describes.
///
/// Tensile (Young's) data E and shear data G are related by E = 2(1+ν)G for an isotropic material
/// with Poisson's ratio ν; the ratio is always stated, never guessed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum ModulusKind {
    /// Young's modulus E (tension, compression, bending).
    #[default]
    Tensile,
    /// Shear modulus G.
    Shear,
}

impl ModulusKind {
    /// Factor that converts a modulus of this kind into the tensile modulus: E = factor · M.
    pub(crate) fn to_tensile_factor(self, poisson: f64) -> f64 {
        match self {
            ModulusKind::Tensile => 1.0,
            ModulusKind::Shear => 2.0 * (1.0 + poisson),
        }
    }

    /// The letter of the modulus: `E` (tensile) or `G` (shear), for labels.
    pub(crate) fn letter(self) -> &'static str {
        match self {
            ModulusKind::Tensile => "E",
            ModulusKind::Shear => "G",
        }
    }

    /// The symbols of the storage and loss moduli and of the equilibrium modulus: (E′, E″, E∞) or
    /// (G′, G″, G∞), for labels.
    pub(crate) fn symbols(self) -> (&'static str, &'static str, &'static str) {
        match self {
            ModulusKind::Tensile => ("E′", "E″", "E∞"),
            ModulusKind::Shear => ("G′", "G″", "G∞"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shear_factor_is_three_for_incompressible_and_two_for_nu_zero() {
        assert_eq!(ModulusKind::Shear.to_tensile_factor(0.5), 3.0);
        assert_eq!(ModulusKind::Shear.to_tensile_factor(0.0), 2.0);
        assert_eq!(ModulusKind::Tensile.to_tensile_factor(0.3), 1.0);
    }

    #[test]
    fn shear_labels_are_g_and_tensile_labels_e() {
        assert_eq!(ModulusKind::Shear.symbols(), ("G′", "G″", "G∞"));
        assert_eq!(ModulusKind::Tensile.symbols(), ("E′", "E″", "E∞"));
        assert_eq!(
            (ModulusKind::Shear.letter(), ModulusKind::Tensile.letter()),
            ("G", "E")
        );
    }
}
