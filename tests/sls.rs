//! The standard linear solid of the physical-reference tests (tests/reference.rs, whose module doc
//! gives its creep function and sources), on its own so that the crate's own tests (src/tests/)
//! include the same file.

/// Which modulus the SLS is given in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kind {
    /// Young's modulus E.
    Tensile,
    /// Shear modulus G.
    Shear,
}

/// A standard linear solid (see the module docs), moduli in Pa, times in s.
#[derive(Debug, Clone, Copy)]
pub struct Sls {
    pub kind: Kind,
    pub poisson: f64,
    /// Glassy (instantaneous) modulus M₀.
    pub glassy_pa: f64,
    /// Relaxed (equilibrium) modulus M∞.
    pub relaxed_pa: f64,
    /// Relaxation time τ_r.
    pub tau_relax_s: f64,
}

impl Sls {
    /// Retardation (creep) time τ_c = τ_r·M₀/M∞.
    pub fn tau_creep_s(&self) -> f64 {
        self.tau_relax_s * self.glassy_pa / self.relaxed_pa
    }

    /// J₁ = 1/M∞ − 1/M₀.
    pub fn creep_strength_per_pa(&self) -> f64 {
        1.0 / self.relaxed_pa - 1.0 / self.glassy_pa
    }

    /// Glassy shear modulus μ₀: G₀, or E₀/(2(1+ν)).
    pub fn glassy_shear_pa(&self, poisson: f64) -> f64 {
        match self.kind {
            Kind::Shear => self.glassy_pa,
            Kind::Tensile => self.glassy_pa / (2.0 * (1.0 + poisson)),
        }
    }

    /// Plane-strain modulus E* = E/(1−ν²) = 2G/(1−ν) of the glassy (`glassy`) or relaxed material.
    pub fn plane_strain_pa(&self, glassy: bool) -> f64 {
        let m = if glassy {
            self.glassy_pa
        } else {
            self.relaxed_pa
        };
        match self.kind {
            Kind::Tensile => m / (1.0 - self.poisson * self.poisson),
            Kind::Shear => 2.0 * m / (1.0 - self.poisson),
        }
    }

    /// The creep-spectrum JSON that `viscoroll roll` reads (docs/USER_GUIDE.md, "Creep spectrum JSON").
    pub fn creep_json(&self) -> String {
        format!(
            r#"{{"kind": "{}", "poisson": {:e}, "compliance_glassy_per_pa": {:e},
 "terms": [{{"compliance_per_pa": {:e}, "tau_s": {:e}}}]}}"#,
            match self.kind {
                Kind::Tensile => "tensile",
                Kind::Shear => "shear",
            },
            self.poisson,
            1.0 / self.glassy_pa,
            self.creep_strength_per_pa(),
            self.tau_creep_s()
        )
    }
}
