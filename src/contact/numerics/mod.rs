//! The numerics several bodies share, below the bodies: the kernel of the viscoelastic half-space and
//! its hat collocation, the retardation modes, the Chebyshev pieces and the N×N solve at λ of the
//! error-controlled schemes, the mode reduction, and the closed-form Winkler foundation.
//!
//! Input: creep terms ([`CreepTerm`](crate::contact::problem::CreepTerm)), λ, n or the quadrature
//! settings; output: kernels, modes, reductions and solutions at λ for a body's solver to use. This
//! folder imports only the ground of `contact` (`problem`, `error`), the load loop (`load`, for the
//! Winkler foundation at given load) and `special`, never `body/`; the half-space
//! (`body/half_space/`), the bonded layer (`body/layer/`), the Winkler foundations
//! (`body/winkler/`) and the test-only cover on springs (`body/on_springs/`) stand on it and import
//! nothing of each other.
//! - [`kernel`]: the kernel K(ξ) of eq. 3.19 and its hat averages (docs/MATH.md §2); the layer's
//!   kernel is this one minus a smooth correction;
//! - [`hat`]: the piecewise-linear (hat) collocation of eq. 3.25–3.26, the thesis scheme on the
//!   half-space, and the system the layer's hat scheme solves;
//! - [`modes`]: the roots κⱼ (docs/MATH.md §7);
//! - [`chebyshev`]: the exponentials' Chebyshev coefficients and the exterior transform (§7, §10);
//! - [`at_lambda`]: the N×N solve at given λ (§7) and its [`at_lambda::LambdaSolution`];
//! - [`reduction`]: the mode selection, lumping and dropping (§8);
//! - [`correction`]: the lumping correction's shared pieces (§8): the lumped weight W, the
//!   calibration solve's terms, the measured gains, the gains applied;
//! - [`winkler`]: the viscoelastic Winkler foundation of any coefficient c_W in closed form, and the
//!   coefficients of uniaxial and constrained columns (the bonded layer's thin compressible limit).
//!
//! Not here, because one body alone uses them: how each scheme calibrates and bounds its lumping
//! correction (`body/half_space/auto/correction.rs`; the spectral layer measures its gains at two
//! degrees, `body/layer/spectral/at_load.rs`; [`correction`] says what differs) and the layer's
//! Volterra memory terms (`body/layer/spectral/volterra.rs`).

pub mod at_lambda;
pub mod chebyshev;
pub mod correction;
pub mod hat;
pub mod kernel;
pub mod modes;
pub mod reduction;
pub mod winkler;
