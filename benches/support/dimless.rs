//! Dimensionless creep terms as a dimensional scene, so that a bench can reach every body through the
//! public entries `contact::roll` / `contact::roll_cover` and still compare against the half-space
//! solved on the same terms by `contact::solve_at_load` (included by `#[path]`).
//!
//! `Scene::dimensionless` scales time by T = l_g/V and lengths by V·T with l_g = 2√(2RCN/π) the glassy
//! contact length (docs/MATH.md §3). Choosing V = l_g makes T = 1 s, so a term (f, b) is the
//! retardation term τ = 1/b, J = J_g·f/b, and the load is N′ = (R/VT)·C·(2/π)·N/VT = 1/4 for every
//! R, N: the benches' load. A dimensionless thickness h is h·l_g in m.

use viscoroll::contact::{Body, CreepTerm, Scene};
use viscoroll::creep::RetardationTerm;
use viscoroll::{CreepSpectrum, ModulusKind};

/// The load N′ every scene of [`scene_of`] has.
pub const LOAD: f64 = 0.25;

/// A scene (R = 1 m, N = 1e4 N/m, ν as given) and a shear creep spectrum (J_g = 1e−8 1/Pa) whose
/// dimensionless problem is `terms` at N′ = 1/4; the body is `body_of(l_g)` with l_g = V·T in m.
pub fn scene_of(
    terms: &[CreepTerm],
    poisson: f64,
    body_of: impl Fn(f64) -> Body,
) -> (Scene, CreepSpectrum) {
    let (r, n, jg) = (1.0, 1e4, 1e-8);
    let c = (1.0 - poisson) * jg; // shear compliance factor of Scene::dimensionless
    let l_g = 2.0 * (2.0 * r * c * n / std::f64::consts::PI).sqrt();
    let spectrum = CreepSpectrum {
        kind: ModulusKind::Shear,
        poisson,
        compliance_glassy_per_pa: jg,
        terms: terms
            .iter()
            .map(|t| RetardationTerm {
                compliance_per_pa: jg * t.f / t.b,
                tau_s: 1.0 / t.b,
            })
            .collect(),
    };
    let scene = Scene {
        radius_m: r,
        load_n_per_m: n,
        speed_m_s: l_g,
        poisson: Some(poisson),
        body: body_of(l_g),
    };
    (scene, spectrum)
}

/// Panic unless a solved scene's dimensionless problem (`terms`, `load`) is `want` at [`LOAD`] to
/// rounding: the scaling above holds.
pub fn assert_same(terms: &[CreepTerm], load: f64, want: &[CreepTerm]) {
    let close = |a: f64, b: f64| (a / b - 1.0).abs() < 1e-12;
    assert!(
        close(load, LOAD)
            && terms.len() == want.len()
            && terms
                .iter()
                .zip(want)
                .all(|(a, b)| close(a.f, b.f) && close(a.b, b.b)),
        "the scene's dimensionless problem is not the bench's terms at N' = 1/4"
    );
}
