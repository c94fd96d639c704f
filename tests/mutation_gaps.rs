//! Tests that close gaps found by mutation testing (issue 19, item 6; README "Mutation testing"):
//! each pins a behaviour that a surviving cargo-mutants mutant changed without any test failing,
//! against a reference computed here by a different route (geometry, limits, exact solutions).

use crate::reference::{Kind, Sls};
use viscoroll::contact::body::layer::{roll_cover, BodyModel, ModelChoice};
use viscoroll::contact::{Body, Scene};
use viscoroll::CreepSpectrum;

/// A tensile standard linear solid with ν = 0.3 (E₀ = 1 GPa, E∞ = 4 MPa, τ_r = 20 µs).
fn sls_spectrum() -> CreepSpectrum {
    let sls = Sls {
        kind: Kind::Tensile,
        poisson: 0.3,
        glassy_pa: 1e9,
        relaxed_pa: 4e6,
        tau_relax_s: 2e-5,
    };
    serde_json::from_str(&sls.creep_json()).expect("creep JSON of the SLS")
}

/// The cover-indentation warning (roll_cover module doc): the roll's depth below the higher contact
/// edge, by plain geometry of a parabolic roll whose lowest point lies `offset` behind the contact
/// centre — (l/2 + |offset|)²/(2R) — against 30 % of the cover. Surviving mutant: the depth's
/// 1/(2ρ) written 2/ρ (`roll_cover.rs`, the depth line).
#[test]
fn cover_indentation_warning_follows_the_roll_geometry() {
    let spectrum = sls_spectrum();
    let scene = Scene {
        radius_m: 0.05,
        load_n_per_m: 1_000.0,
        speed_m_s: 0.05,
        poisson: Some(0.3),
        body: Body::HalfSpace,
    };
    let solve = |cover_m: f64| {
        roll_cover(
            &scene,
            &spectrum,
            Some(cover_m),
            ModelChoice::HalfSpace,
            1e-6,
        )
        .expect("solves")
    };
    let warned = |w: &[String]| w.iter().any(|s| s.contains("indentation"));
    // A thick cover: the half-space answer, no warning.
    let thick = solve(1.0);
    assert!(!warned(&thick.warnings), "{:?}", thick.warnings);
    let r = &thick.roll;
    let depth_m = (0.5 * r.contact_length_m + r.offset_m.abs()).powi(2) / (2.0 * scene.radius_m);
    // The geometry is the roll's own: depth below the lowest point is x²/(2R) for both edges, and
    // the edges lie at −l/2 ± offset from the lowest point; sanity of the scale (mm-size contact).
    assert!(depth_m > 1e-5 && depth_m < 1e-3, "depth {depth_m:e} m");
    // The body solved does not depend on the cover (half-space chosen), so the same depth applies;
    // 0.25 and 0.4 of the cover sit well either side of the 30 % threshold (no rounding issue).
    let below = solve(depth_m / 0.25);
    assert!(
        !warned(&below.warnings),
        "depth/cover = 0.25 warned: {:?}",
        below.warnings
    );
    let above = solve(depth_m / 0.4);
    assert!(
        warned(&above.warnings),
        "depth/cover = 0.4 not warned: {:?}",
        above.warnings
    );
    // The reported depth in mm (printed to 2 decimals) matches the geometric one.
    let text = above
        .warnings
        .iter()
        .find(|s| s.contains("indentation"))
        .unwrap();
    let mm: f64 = text
        .split("≈ ")
        .nth(1)
        .and_then(|s| s.split(" mm").next())
        .and_then(|s| s.trim().parse().ok())
        .unwrap_or_else(|| panic!("no depth in `{text}`"));
    assert!(
        (mm - depth_m * 1e3).abs() <= 0.005 + 1e-9,
        "{mm} mm vs {} mm",
        depth_m * 1e3
    );
}

/// A tensile spectrum (ν = 0.3, E₀ = 1 GPa) with the given (Jⱼ/J_g, τⱼ in s) terms.
fn spectrum(terms: &[(f64, f64)]) -> CreepSpectrum {
    let jg = 1e-9;
    let t: Vec<String> = terms
        .iter()
        .map(|&(r, tau)| format!(r#"{{"compliance_per_pa": {:e}, "tau_s": {tau:e}}}"#, r * jg))
        .collect();
    serde_json::from_str(&format!(
        r#"{{"kind": "tensile", "poisson": 0.3, "compliance_glassy_per_pa": {jg:e}, "terms": [{}]}}"#,
        t.join(", ")
    ))
    .expect("creep JSON")
}

/// `auto`'s body choice (roll_cover module doc): the half-space is taken only when the longest
/// memory L — λ, or 1/bᵢ of any mode holding at least 1 % of the compliance (Jᵢ/J_g ≥ 0.01·S,
/// S = J∞/J_g) — is short against the cover. Designed case: a strong fast mode (J₁ = J_g,
/// τ₁ = T/10) and a weak slow one (J₂ = 0.05·J_g: 2.4 % of J∞, τ₂ = 20·T, so 1/b₂ = 20 contact
/// scales) under a cover of 40 contact scales: L = 20 and 3·(20/40)² = 0.75 > tol, so not the
/// half-space; without the slow mode L = λ ≈ 1.5 and the half-space is right (3·(1.5/40)² ≈ 4e−3).
/// Surviving mutant: S summed as Σfᵢ·bᵢ instead of Σfᵢ/bᵢ (the fast mode's b₁ = 10 makes S ≈ 101,
/// which drops the slow mode and picks the half-space).
#[test]
fn auto_keeps_a_slow_mode_holding_over_one_percent_of_the_compliance() {
    let scene = Scene {
        radius_m: 0.1,
        load_n_per_m: 1000.0,
        speed_m_s: 0.01,
        poisson: Some(0.3),
        body: Body::HalfSpace,
    };
    // T = l_g/V and l_g depend only on J_g (docs/MATH.md §1): read them from any spectrum with that J_g.
    let p = scene
        .dimensionless(&spectrum(&[(1.0, 1.0)]))
        .expect("scene");
    let (t, lg) = (p.time_scale_s, p.length_scale_m);
    let cover_m = 40.0 * lg;
    let tol = 1e-2;
    let fast_only = spectrum(&[(1.0, 0.1 * t)]);
    let with_slow = spectrum(&[(1.0, 0.1 * t), (0.05, 20.0 * t)]);
    let hs = roll_cover(&scene, &fast_only, Some(cover_m), ModelChoice::Auto, tol).expect("solves");
    let lambda = hs.roll.dimensionless.lambda;
    assert!(lambda > 1.0 && lambda < 2.5, "λ = {lambda}");
    assert_eq!(hs.model, BodyModel::HalfSpace, "{}", hs.reason);
    let slow =
        roll_cover(&scene, &with_slow, Some(cover_m), ModelChoice::Auto, tol).expect("solves");
    assert_ne!(slow.model, BodyModel::HalfSpace, "{}", slow.reason);
}
