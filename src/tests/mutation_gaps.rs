//! Tests that close gaps found by mutation testing (issue 19, item 6; docs/DEVLOG.md "Mutation testing"):
//! each pins a behaviour that a surviving cargo-mutants mutant changed without any test failing,
//! against a reference computed here by a different route (geometry, limits, exact solutions).

use crate::tests::sls::{Kind, Sls};
use viscoroll::contact::roll_cover;
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
        body: Body::HALF_SPACE,
    };
    let solve = |cover_m: f64| {
        let on_cover = Scene {
            body: Body::HalfSpace {
                cover_m: Some(cover_m),
            },
            ..scene
        };
        roll_cover(&on_cover, &spectrum, 1e-6).expect("solves")
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
        body: Body::HALF_SPACE,
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
    let scene = Scene {
        body: Body::Auto {
            thickness_m: cover_m,
        },
        ..scene
    };
    let hs = roll_cover(&scene, &fast_only, tol).expect("solves");
    let lambda = hs.roll.dimensionless.lambda;
    assert!(lambda > 1.0 && lambda < 2.5, "λ = {lambda}");
    assert!(matches!(hs.model, Body::HalfSpace { .. }), "{}", hs.reason);
    let slow = roll_cover(&scene, &with_slow, tol).expect("solves");
    assert!(
        !matches!(slow.model, Body::HalfSpace { .. }),
        "{}",
        slow.reason
    );
}

/// The gap ratio's minimum over ξ ∈ [−6λ, 0) by brute force: 3 000 points, then 2 000 points across
/// the best one's neighbours (spacing 4e−6 λ; the ratio's curvature is O(10/λ²), so the sampled
/// minimum is within ~1e−10 of the true one).
fn dense_min(ev: &viscoroll::contact::half_space::rear_gap::GapEvaluator, lam: f64) -> (f64, f64) {
    let scan = |a: f64, b: f64, n: usize| {
        (0..=n)
            .map(|i| a + (b - a) * i as f64 / n as f64)
            .filter(|&x| x < 0.0)
            .map(|x| (ev.gap_ratio(x), x))
            .fold((f64::INFINITY, 0.0), |m, p| if p.0 < m.0 { p } else { m })
    };
    let (_, x0) = scan(-6.0 * lam, -1e-3 * lam, 3000);
    let h = 6.0 * lam / 3000.0;
    scan(x0 - 2.0 * h, (x0 + 2.0 * h).min(-1e-3 * lam), 2000)
}

/// `rear_gap::rear_scan` (docs/MATH.md §3: the gap behind the contact) is a minimiser: its coarse
/// points, then a golden-section search between the neighbours of an interior minimum that comes
/// within 0.1·λ²/8 of closing. Checked against brute force on the same gap function. The solved
/// one-term contacts keep the minimum at the rear edge (the 4 877-case scan found no other), so the
/// roll's lowest point β is moved behind the contact by hand (1…3.3 λ): the rigid profile ξβ − ξ²/2
/// then dips into the recovering surface and the gap has an interior minimum < 0 — on either side
/// of its nearest coarse point for the four β. Surviving mutants: the minimum's selection (`<`
/// replaced), the golden-section bracket narrowed to one side of the coarse minimum.
#[test]
fn rear_scan_finds_the_interior_minimum_of_the_gap() {
    use viscoroll::contact::half_space::rear_gap::{rear_scan, GapEvaluator};
    use viscoroll::contact::numerics::at_lambda::{solve_at_lambda, QuadratureSettings};
    use viscoroll::contact::numerics::modes::Modes;
    use viscoroll::contact::CreepTerm;
    let lam = 1.0;
    let m = Modes::new(&[CreepTerm { f: 10.0, b: 0.1 }]);
    let solved = solve_at_lambda(&m, lam, QuadratureSettings::default());
    for beta in [-1.0, -1.7, -2.2, -3.3] {
        let mut sol = solved.clone();
        sol.beta = beta * lam;
        let ev = GapEvaluator::new(&m, 1.0, &sol, 1e-3 * lam);
        let (g_want, x_want) = dense_min(&ev, lam);
        let s = rear_scan(&m, 1.0, &sol);
        eprintln!(
            "β {beta}: scan {:.12e} at {:.6} ; brute force {g_want:.12e} at {x_want:.6}",
            s.min_gap_ratio, s.at_xi
        );
        assert!(g_want < 0.1, "β {beta}: no refinement case ({g_want})");
        // golden section: 24 steps shrink the bracket by 0.618^24 ≈ 1e−5, so the value is within
        // ~1e−9 of the minimum; brute force within ~1e−10.
        assert!(
            (s.min_gap_ratio - g_want).abs() < 1e-8,
            "β {beta}: {} vs {g_want}",
            s.min_gap_ratio
        );
        assert!(
            (s.at_xi - x_want).abs() < 1e-3 * lam,
            "β {beta}: at {}",
            s.at_xi
        );
    }
}

/// The same minimiser when the roll's lowest point β lies far behind the contact (β = −8 λ and
/// −15 λ, beyond the last fixed offset 6 λ of the scan): the rigid profile ξβ − ξ²/2 is deepest at
/// ξ = β, so the gap's minimum lies near the lowest point, ξ* = β + ρv′(ξ*), where the surface
/// recovers slowly — a second contact would form there first. Checked against brute force over
/// [−3|β|, 0) (the minimum within 1e−8 of λ²/8 and its place within 1e−3 λ) and against the
/// geometry (ξ* within 0.5|β| of β). Surviving mutant: the points at 0.5…2.5 β not added
/// (`rear_gap.rs`, `sol.beta < 0.0` made `== 0.0`): the scan then stopped at −6 λ, 2–9 λ short.
#[test]
fn rear_scan_reaches_the_lowest_point_of_the_roll_far_behind() {
    use viscoroll::contact::half_space::rear_gap::{rear_scan, GapEvaluator};
    use viscoroll::contact::numerics::at_lambda::{solve_at_lambda, QuadratureSettings};
    use viscoroll::contact::numerics::modes::Modes;
    use viscoroll::contact::CreepTerm;
    let lam = 1.0;
    let m = Modes::new(&[CreepTerm { f: 10.0, b: 0.1 }]);
    let solved = solve_at_lambda(&m, lam, QuadratureSettings::default());
    for beta in [-8.0, -15.0] {
        let mut sol = solved.clone();
        sol.beta = beta * lam;
        let ev = GapEvaluator::new(&m, 1.0, &sol, 1e-3 * lam);
        let (g_want, x_want) = dense_min_over(&ev, lam, 3.0 * beta.abs() * lam);
        let s = rear_scan(&m, 1.0, &sol);
        eprintln!(
            "β {beta}: scan {:.12e} at {:.6} ; brute force {g_want:.12e} at {x_want:.6}",
            s.min_gap_ratio, s.at_xi
        );
        assert!(
            (x_want - sol.beta).abs() < 0.5 * sol.beta.abs(),
            "β {beta}: the minimum at {x_want}, not near the lowest point"
        );
        // tolerances as in `rear_scan_finds_the_interior_minimum_of_the_gap` (golden section to
        // ~1e−9, brute force ~1e−10 of λ²/8 relative to the gap's O(β²/λ²) size here: 1e−8 scaled)
        let scale = g_want.abs().max(1.0);
        assert!(
            (s.min_gap_ratio - g_want).abs() < 1e-8 * scale,
            "β {beta}: {} vs {g_want}",
            s.min_gap_ratio
        );
        assert!(
            (s.at_xi - x_want).abs() < 1e-3 * lam,
            "β {beta}: at {}",
            s.at_xi
        );
    }
}

/// On solved contacts (one term; β > 0 for f = 10, b = 1 and β < 0 for b = 0.1 and 0.01, the roll
/// still descending behind the edge) the gap behind the contact is smallest next to the rear edge,
/// where it opens like |ξ|^{3/2} (docs/MATH.md §11; the 4 877-case scan found no other minimum):
/// `rear_scan` reports the first point, 1e−3 λ behind the edge, with the gap open, and brute force
/// over [−6 λ, −1e−3 λ] finds nothing smaller. Surviving mutant: `k_min > 0` made `>= 0` in the
/// refinement's guard (`rear_gap.rs`), which then takes the edge point as an interior minimum and
/// indexes before the first point.
#[test]
fn rear_scan_of_a_solved_contact_finds_the_gap_smallest_at_the_rear_edge() {
    use viscoroll::contact::half_space::rear_gap::{rear_scan, GapEvaluator};
    use viscoroll::contact::numerics::at_lambda::{solve_at_lambda, QuadratureSettings};
    use viscoroll::contact::numerics::modes::Modes;
    use viscoroll::contact::CreepTerm;
    let lam = 1.0;
    for b in [1.0, 0.1, 0.01] {
        let m = Modes::new(&[CreepTerm { f: 10.0, b }]);
        let sol = solve_at_lambda(&m, lam, QuadratureSettings::default());
        let ev = GapEvaluator::new(&m, 1.0, &sol, 1e-3 * lam);
        let (g_want, x_want) = dense_min(&ev, lam);
        let s = rear_scan(&m, 1.0, &sol);
        eprintln!(
            "b {b} (β {:.4}): scan {:.6e} at {} ; brute force {g_want:.6e} at {x_want}",
            sol.beta, s.min_gap_ratio, s.at_xi
        );
        assert!(
            s.min_gap_ratio > 0.0,
            "b {b}: gap closed {}",
            s.min_gap_ratio
        );
        assert_eq!(s.at_xi, -1e-3 * lam, "b {b}: minimum not at the edge");
        // brute force samples the same function at the same edge point (and finer elsewhere)
        assert!(
            (s.min_gap_ratio - g_want).abs() <= 1e-12 * g_want.abs().max(1e-6),
            "b {b}: {} vs {g_want}",
            s.min_gap_ratio
        );
    }
}

/// As [`dense_min`] over ξ ∈ [−`reach`, 0): 3 000 points, then 2 000 across the best one's
/// neighbours.
fn dense_min_over(
    ev: &viscoroll::contact::half_space::rear_gap::GapEvaluator,
    lam: f64,
    reach: f64,
) -> (f64, f64) {
    let scan = |a: f64, b: f64, n: usize| {
        (0..=n)
            .map(|i| a + (b - a) * i as f64 / n as f64)
            .filter(|&x| x < 0.0)
            .map(|x| (ev.gap_ratio(x), x))
            .fold((f64::INFINITY, 0.0), |m, p| if p.0 < m.0 { p } else { m })
    };
    let (_, x0) = scan(-reach, -1e-3 * lam, 3000);
    let h = reach / 3000.0;
    scan(x0 - 2.0 * h, (x0 + 2.0 * h).min(-1e-3 * lam), 2000)
}

/// The bonded layer's kernel correction (`layer::kernel`, module doc: A_D(j) = −∫₀^∞ (R(kh′)/k)·
/// Re[Φ(k)·Δ·(sinc²(kΔ/2)e^{ikjΔ} − 1)] dk up to one constant) against an independent composite
/// quadrature of the differences A_D(j) − A_D(0), whose integrand R/k·Re[Φ Δ sinc² (e^{ikjΔ} − 1)]
/// is finite at k = 0: 20-point Gauss–Legendre panels of width ¼ in ln k from 1e−12 to 1/X, then of
/// width 0.05/X in k (0.05 radian of e^{ikx}, |x| ≤ X) up to 30/h′, where R < 1e−24. X = (m+1)Δ = 41
/// puts the library's split between its log and its linear panels at k = 1/X; the surviving mutant
/// moved it to k = X (here past k_hi = 27/h′: log panels of width ½ in ln k up to k_hi, across
/// hundreds of radians of the oscillation). With X = 4.1 that mutant was still within 1e−11 (10-point
/// panels of ~1 radian): a long contact against the layer (λ ≫ h′) is the case it breaks.
#[test]
fn layer_kernel_correction_matches_an_independent_quadrature() {
    use viscoroll::contact::body::layer::compliance::layer_defect;
    use viscoroll::contact::body::layer::LayerKernel;
    use viscoroll::contact::CreepTerm;
    use viscoroll::special::gauss_legendre::gauss_legendre;
    let terms = [CreepTerm { f: 5.0, b: 0.5 }, CreepTerm { f: 20.0, b: 0.05 }];
    let (h, nu, m, delta) = (1.0, 0.45, 40usize, 1.0);
    let k = LayerKernel::new(&terms, h, nu).expect("kernel");
    let a = k.correction_hat_averages(m, delta);
    let x_max = (m as f64 + 1.0) * delta;
    let (gx, gw) = gauss_legendre(20);
    let phi = |k: f64| {
        terms.iter().fold((1.0, 0.0), |(re, im), t| {
            let d = t.b * t.b + k * k;
            (re + t.f * t.b / d, im + t.f * k / d)
        })
    };
    // f_j(k) = R(kh)/k · Re[Φ(k)·Δ·sinc²(kΔ/2)·(e^{ikjΔ} − 1)], for all j at once.
    let add = |kk: f64, wk: f64, acc: &mut Vec<f64>| {
        let (pr, pi) = phi(kk);
        let u = 0.5 * kk * delta;
        let s2 = if u < 1e-8 { 1.0 } else { (u.sin() / u).powi(2) };
        let r = layer_defect(kk * h, nu) / kk;
        for (j, v) in acc.iter_mut().enumerate() {
            let th = kk * j as f64 * delta;
            let (er, ei) = (th.cos() - 1.0, th.sin());
            *v += wk * r * delta * s2 * (pr * er - pi * ei);
        }
    };
    let mut want = vec![0.0; m + 1];
    let (v0, v1) = (1e-12f64.ln(), (1.0 / x_max).ln());
    let np = ((v1 - v0) / 0.25).ceil() as usize;
    for p in 0..np {
        let (a0, b0) = (
            v0 + (v1 - v0) * p as f64 / np as f64,
            v0 + (v1 - v0) * (p + 1) as f64 / np as f64,
        );
        for (x, w) in gx.iter().zip(&gw) {
            let v = 0.5 * (a0 + b0) + 0.5 * (b0 - a0) * x;
            add(v.exp(), v.exp() * 0.5 * (b0 - a0) * w, &mut want);
        }
    }
    let (k0, k1) = (1.0 / x_max, 30.0 / h);
    let np = ((k1 - k0) / (0.05 / x_max)).ceil() as usize;
    for p in 0..np {
        let (a0, b0) = (
            k0 + (k1 - k0) * p as f64 / np as f64,
            k0 + (k1 - k0) * (p + 1) as f64 / np as f64,
        );
        for (x, w) in gx.iter().zip(&gw) {
            add(
                0.5 * (a0 + b0) + 0.5 * (b0 - a0) * x,
                0.5 * (b0 - a0) * w,
                &mut want,
            );
        }
    }
    let scale = want.iter().fold(0f64, |s, v| s.max(v.abs()));
    let mut worst = 0f64;
    for j in 0..=m {
        // A_D(j) − A_D(0) = −∫ f_j; the kernel is even in j only for Φ real, so check both signs:
        // A_D(−j) is the conjugate-phase integral, −∫ R/k·Re[Φ Δ s²(e^{−ikjΔ} − 1)].
        let got = a[m + j] - a[m];
        worst = worst.max((got + want[j]).abs());
    }
    eprintln!("layer kernel correction: worst |ΔA_D| error {worst:.3e} (scale {scale:.3e})");
    // Both rules converge exponentially (module doc): measured 7.8e−11 against a scale of 685
    // (1.1e−13 relative), so 1e−11 of the scale leaves a margin of ~90 for other platforms (the
    // mutant with the split at k = X: 0.2).
    assert!(
        worst < 1e-11 * scale.max(1.0),
        "{worst:e} vs scale {scale:e}"
    );
}

/// The load loop's contract (`contact::load::solve_at_load`): a sum Σfᵢ/bᵢ (J∞/J_g − 1) that is not
/// finite and ≥ 0 is refused with a typed error before any solve. Surviving mutant: the check's
/// `&&` made `||` (infinite or negative sums passed).
#[test]
fn the_load_loop_refuses_a_bad_sum_of_f_over_b() {
    use viscoroll::contact::load::{solve_at_load, LoadSettings};
    use viscoroll::contact::{ContactError, DimensionlessSolution};
    for bad in [f64::NAN, f64::INFINITY, -1.0] {
        let r = solve_at_load(
            1.0,
            bad,
            &LoadSettings::default(),
            |_: f64| -> Result<DimensionlessSolution, ContactError> {
                panic!("solved with Σf/b = {bad}")
            },
        );
        assert!(
            matches!(r, Err(ContactError::BadValue { .. })),
            "Σf/b = {bad}: {r:?}"
        );
    }
}
