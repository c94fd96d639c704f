//! The contact conditions outside the contact (issue 4, item 4): β < 0 (the roll's lowest point
//! behind the rear edge) and whether the roll re-touches the still-depressed surface behind it.
//!
//! The gap is evaluated by `contact::rear_gap` (accurate to ~1e−10 of λ²/8, unit-tested there
//! against an independent quadrature of eq. 3.19 with the exact one-term pressure). The scans below
//! look for penetration over the one-term (f, b, λ) plane, random realistic spectra and dimensional
//! scenes over the range. The full scan is `#[ignore]`d (≈ 1–2 min in release):
//! `cargo test --release --lib contact_rear::scan -- --ignored --nocapture`.

use viscoroll::contact::{
    roll, solve_at_lambda, solve_at_load, AutoSettings, Body, ContactSettings, CreepTerm,
    Diagnostics, DimensionlessSolution, Scene, Scheme,
};
use viscoroll::creep::{CreepSpectrum, RetardationTerm};

/// The `auto` diagnostics of an answer (every solve here uses the `auto` scheme).
fn diag(s: &DimensionlessSolution) -> &Diagnostics {
    s.diagnostics.as_ref().expect("auto diagnostics")
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

fn settings(tol: f64) -> ContactSettings {
    ContactSettings {
        scheme: Scheme::Auto,
        auto: AutoSettings {
            tol,
            ..AutoSettings::default()
        },
        ..ContactSettings::default()
    }
}

/// SplitMix64, as in contact_auto.rs (same cases on every run).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Counts of one scan.
#[derive(Default, Debug)]
struct Tally {
    cases: usize,
    beta_negative: usize,
    /// Flagged by the gap check (min gap < −max(tol, 1e−9) of λ²/8).
    penetrating: usize,
    /// Of those, still flagged when re-solved at tol 1e−10 (a genuine second contact).
    persisting: usize,
    /// Smallest min-gap ratio among the β < 0 cases away from the edge (|ξ| ≥ 0.05 λ).
    worst_far: f64,
    /// Smallest min-gap ratio of all cases (usually the first scan point, 1e−3 λ behind).
    worst: f64,
    worst_case: String,
}

impl Tally {
    fn new() -> Tally {
        Tally {
            worst_far: f64::INFINITY,
            worst: f64::INFINITY,
            ..Tally::default()
        }
    }
    fn add(
        &mut self,
        s: &DimensionlessSolution,
        label: &str,
        recheck: impl FnOnce() -> DimensionlessSolution,
    ) {
        let d = s;
        self.cases += 1;
        if d.beta < 0.0 {
            self.beta_negative += 1;
            if diag(s).min_gap_xi.abs() >= 0.05 * d.lambda && diag(s).min_gap_ratio < self.worst_far
            {
                self.worst_far = diag(s).min_gap_ratio;
            }
        }
        let gap_tol = diag(s).tol.max(1e-9);
        if diag(s).min_gap_ratio < -gap_tol {
            self.penetrating += 1;
            let t = recheck();
            let persists = diag(&t).min_gap_ratio < -diag(&t).tol.max(1e-9);
            if persists {
                self.persisting += 1;
            }
            eprintln!(
                "FLAGGED {label}: β/λ {:.3e} gap {:.3e} at ξ/λ {:.3e}, λ {:.6e} est {:.1e}; at tol 1e-10: \
                 λ {:.6e} gap {:.3e} (persists: {persists})",
                d.beta / d.lambda,
                diag(s).min_gap_ratio,
                diag(s).min_gap_xi / d.lambda,
                d.lambda,
                d.error_estimate.unwrap_or(f64::NAN),
                t.lambda,
                diag(&t).min_gap_ratio
            );
        }
        if diag(s).min_gap_ratio < self.worst {
            self.worst = diag(s).min_gap_ratio;
            self.worst_case = format!(
                "{label} (β/λ {:.3e}, at ξ/λ {:.3e})",
                d.beta / d.lambda,
                diag(s).min_gap_xi / d.lambda
            );
        }
    }
}

/// One term at λ = 1 with r = f/b (= J₁/J_g) and c = bλ/2: β/λ and the gap over λ² depend only on
/// (r, c) (scaling ξ → aξ maps b → b/a, f → f/a), so this plane is the whole one-term family.
fn one_term(r: f64, c: f64, tol: f64) -> DimensionlessSolution {
    let b = 2.0 * c;
    solve_at_lambda(&[CreepTerm { f: r * b, b }], 1.0, &settings(tol)).unwrap()
}

/// n terms, log-uniform times over `decades` decades centred on τ ~ T (so the glass transition
/// crosses the contact time), random strengths normalised to J∞/J_g = ratio; dimensionless at λ = 1.
fn random_terms(rng: &mut Rng, n: usize, decades: f64, ratio: f64) -> Vec<CreepTerm> {
    let mut w: Vec<f64> = (0..n).map(|_| 0.05 + rng.next()).collect();
    let sw: f64 = w.iter().sum();
    w.iter_mut().for_each(|x| *x *= (ratio - 1.0) / sw);
    w.iter()
        .map(|&r| {
            let b = 10f64.powf(decades * (rng.next() - 0.5));
            CreepTerm { f: r * b, b }
        })
        .collect()
}

fn random_spectrum(rng: &mut Rng, n: usize, decades: f64, ratio: f64) -> CreepSpectrum {
    let terms = random_terms(rng, n, decades, ratio);
    let jg = 1e-9;
    CreepSpectrum {
        kind: Default::default(),
        poisson: 0.5,
        compliance_glassy_per_pa: jg,
        terms: terms
            .iter()
            .map(|t| RetardationTerm {
                compliance_per_pa: t.f / t.b * jg,
                tau_s: 1.0 / t.b,
            })
            .collect(),
    }
}

#[test]
fn negative_beta_case_keeps_the_gap_open_and_says_so() {
    // f = 10, b = 0.01 at λ = 1 (mpmath: β = −1.8595…): the lowest point lies far behind the rear
    // edge, yet the surface stays below the roll: at ξ = β the gap is +8.82 of λ²/8 (rear_gap unit
    // test, confirmed by an independent quadrature to 1e−14), and near the edge it opens like
    // |ξ|^{3/2} (1.78e−5 at the check's nearest point, ξ = −1e−3 λ).
    let s = solve_at_lambda(&[CreepTerm { f: 10.0, b: 0.01 }], 1.0, &settings(1e-6)).unwrap();
    assert!(s.beta < -1.0);
    assert!(
        diag(&s).min_gap_ratio > 0.0 && diag(&s).min_gap_ratio < 1e-4,
        "{}",
        diag(&s).min_gap_ratio
    );
    // the smallest gap is at the point next to the edge, not around the lowest point
    assert!(
        (diag(&s).min_gap_xi + 1e-3).abs() < 1e-12,
        "{}",
        diag(&s).min_gap_xi
    );
    assert_eq!(s.warnings.len(), 1, "{:?}", s.warnings);
    assert!(s.warnings[0].starts_with("information: the roll's lowest point lies behind"));
    assert!(s.warnings[0].contains("gap behind stays open"));
    assert!(!s.warnings.iter().any(|w| w.contains("penetrates")));
}

#[test]
fn gap_opens_like_three_halves_power_behind_the_edge() {
    // g ≈ C|ξ|^{3/2} next to the rear edge (pressure ~ √ξ there): the ratio of the gaps at
    // 1e−3 λ and 1e−2 λ behind must be close to 10^{−3/2} = 0.0316 (the next term is O(|ξ|²), i.e.
    // a relative correction of order √(|ξ|/λ) ≈ 0.1 at 1e−2 λ: allow 25 %).
    use viscoroll::contact::half_space::rear_gap::GapEvaluator;
    use viscoroll::contact::numerics::at_lambda::{solve_at_lambda, QuadratureSettings};
    use viscoroll::contact::numerics::modes::Modes;
    for (f, b) in [(10.0, 0.01), (10.0, 1.0), (3.0, 20.0)] {
        let m = Modes::new(&[CreepTerm { f, b }]);
        let sol = solve_at_lambda(&m, 1.0, QuadratureSettings::default());
        let ev = GapEvaluator::new(&m, 1.0, &sol, 1e-3);
        let ratio = ev.gap_ratio(-1e-3) / ev.gap_ratio(-1e-2);
        assert!(
            (ratio / 10f64.powf(-1.5) - 1.0).abs() < 0.25,
            "f {f} b {b}: {ratio}"
        );
    }
}

#[test]
fn coarse_one_term_plane_never_penetrates() {
    // 7 × 7 of the (r, c) plane of `scan` (which runs 3 721 cases): r = J₁/J_g from 1e−2 to 1e4,
    // c = bλ/2 from 1e−6 to 1e3; β < 0 occurs in the upper-left part. No case may penetrate.
    let mut t = Tally::new();
    for i in 0..7 {
        for j in 0..7 {
            let r = 10f64.powf(-2.0 + i as f64);
            let c = 10f64.powf(-6.0 + 1.5 * j as f64);
            t.add(&one_term(r, c, 1e-6), &format!("r {r:e} c {c:e}"), || {
                one_term(r, c, 1e-10)
            });
        }
    }
    eprintln!("{t:?}");
    assert!(t.beta_negative >= 3, "{t:?}");
    assert_eq!(t.penetrating, 0, "{t:?}");
}

#[test]
#[ignore = "full scan (≈ 1–2 min release); run with --ignored --nocapture to print the counts"]
fn scan() {
    let t0 = std::time::Instant::now();
    let plane = scan_plane(t0);
    // The run's seed (tests/seed.rs; the scan's figures in docs/DEVLOG.md are from the former 4242).
    let mut rng = Rng(crate::tests::seed::seed("contact_rear::scan"));
    let spectra = scan_spectra(t0, &mut rng);
    let scenes = scan_scenes(t0, &mut rng);
    let real = scan_measured(t0);
    // genuine penetration (still there at tol 1e−10) anywhere: none found
    assert_eq!(
        plane.persisting + spectra.persisting + scenes.persisting + real.persisting,
        0
    );
}

/// `scan` part 1: the one-term plane.
fn scan_plane(t0: std::time::Instant) -> Tally {
    // 1. one-term plane (r, c), 61 × 61, log-uniform
    let mut plane = Tally::new();
    for i in 0..61 {
        for j in 0..61 {
            let r = 10f64.powf(-2.0 + 6.0 * i as f64 / 60.0);
            let c = 10f64.powf(-6.0 + 9.0 * j as f64 / 60.0);
            plane.add(
                &one_term(r, c, 1e-6),
                &format!("one term r {r:.3e} c {c:.3e}"),
                || one_term(r, c, 1e-10),
            );
        }
    }
    eprintln!(
        "one-term plane: {plane:?} ({:.1} s)",
        t0.elapsed().as_secs_f64()
    );
    plane
}

/// `scan` part 2: random realistic spectra at λ = 1.
fn scan_spectra(t0: std::time::Instant, rng: &mut Rng) -> Tally {
    // 2. random realistic spectra at λ = 1: 20–40 terms over 20–24 decades, J∞/J_g 1e2…1e4,
    // times centred on the contact time so that the transition crosses it
    // The run's seed (tests/seed.rs; the scan's figures in docs/DEVLOG.md are from the former 4242).
    let mut spectra = Tally::new();
    for k in 0..300 {
        let n = 20 + (rng.next() * 21.0) as usize;
        let decades = 20.0 + 4.0 * rng.next();
        let ratio = 10f64.powf(2.0 + 2.0 * rng.next());
        let terms = random_terms(rng, n, decades, ratio);
        // shift the whole spectrum by up to ±6 decades (moves the transition past the contact)
        let shift = 10f64.powf(12.0 * (rng.next() - 0.5));
        let terms: Vec<CreepTerm> = terms
            .iter()
            .map(|t| CreepTerm {
                f: t.f * shift,
                b: t.b * shift,
            })
            .collect();
        let s = solve_at_lambda(&terms, 1.0, &settings(1e-6)).unwrap();
        spectra.add(
            &s,
            &format!("spectrum {k} n {n} ratio {ratio:.2e} shift {shift:.2e}"),
            || solve_at_lambda(&terms, 1.0, &settings(1e-10)).unwrap(),
        );
    }
    eprintln!(
        "random spectra: {spectra:?} ({:.1} s)",
        t0.elapsed().as_secs_f64()
    );
    spectra
}

/// `scan` part 3: dimensional scenes with random spectra.
fn scan_scenes(t0: std::time::Instant, rng: &mut Rng) -> Tally {
    // 3. dimensional scenes: V 1e−6…1e3 m/s, N 1…1e6 N/m, R 0.01…1 m, random realistic spectra
    // with times over 24 decades (1e−12…1e12 s)
    let mut scenes = Tally::new();
    for k in 0..40 {
        let n = 20 + (rng.next() * 21.0) as usize;
        let ratio = 10f64.powf(2.0 + 2.0 * rng.next());
        let spec = random_spectrum(rng, n, 24.0, ratio);
        for v in [1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.1, 1.0, 10.0, 100.0, 1e3] {
            let scene = Scene {
                radius_m: 10f64.powf(-2.0 + 2.0 * rng.next()),
                load_n_per_m: 10f64.powf(6.0 * rng.next()),
                speed_m_s: v,
                poisson: None,
                body: Body::HALF_SPACE,
            };
            let a = roll(&scene, &spec, &settings(1e-6)).unwrap();
            scenes.add(
                &a.dimensionless,
                &format!(
                    "scene spectrum {k} V {v:e} N {:.2e} R {:.3}",
                    scene.load_n_per_m, scene.radius_m
                ),
                || roll(&scene, &spec, &settings(1e-10)).unwrap().dimensionless,
            );
        }
    }
    eprintln!("scenes: {scenes:?} ({:.1} s)", t0.elapsed().as_secs_f64());
    scenes
}

/// `scan` part 4: two measured compounds.
fn scan_measured(t0: std::time::Instant) -> Tally {
    // 4. two measured compounds (fits of data/pyvisco-ems-ca and data/trios-aresg2-lims by
    // `viscoroll fit`, creep part): 65 terms over 32 decades (J∞/J_g 51) and 32 terms over 15
    // decades (J∞/J_g 7.6e4), on a grid of the range
    let mut real = Tally::new();
    for name in ["rear_scan_ems_ca_creep.json", "rear_scan_trios_creep.json"] {
        let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
        let spec: CreepSpectrum =
            serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
        for k in 0..=18 {
            let v = 10f64.powf(-6.0 + 0.5 * k as f64);
            for n in [1.0, 1e2, 1e4, 1e6] {
                for r in [0.01, 0.1, 1.0] {
                    let scene = Scene {
                        radius_m: r,
                        load_n_per_m: n,
                        speed_m_s: v,
                        poisson: None,
                        body: Body::HALF_SPACE,
                    };
                    let a = roll(&scene, &spec, &settings(1e-6)).unwrap();
                    real.add(
                        &a.dimensionless,
                        &format!("{name} V {v:.2e} N {n:e} R {r}"),
                        || roll(&scene, &spec, &settings(1e-10)).unwrap().dimensionless,
                    );
                }
            }
        }
    }
    eprintln!(
        "measured compounds: {real:?} ({:.1} s)",
        t0.elapsed().as_secs_f64()
    );
    real
}

/// A case found by `scan`: with many slow modes (c = bλ/2 from 3e−11 to 5e−5) kept separately, the
/// solver returns at tol 1e−5 and 1e−6 a wrong solution (λ = 41.35, ρF/N = 6.41 against 46.91 and
/// 0.472 at tol 1e−7…1e−12) with an error estimate of 4e−7. Its pressure does not satisfy eq. 3.25,
/// and the gap behind the rear edge, which must open like |ξ|^{3/2} for any bounded positive
/// pressure satisfying it, is −4.6e−2 of λ²/8 at ξ = −2.4: the check flags it. The property
/// asserted holds whether or not the solver is fixed: at every tolerance, either the answer agrees
/// with the tol 1e−10 answer within its estimate, or a contact-condition warning is raised.
#[test]
fn a_wrong_solution_never_goes_unflagged() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/rear_gap_wrong_solution_case.json"
    );
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let load = v["load"].as_f64().unwrap();
    let terms: Vec<CreepTerm> = v["terms_f_b"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| CreepTerm {
            f: t[0].as_f64().unwrap(),
            b: t[1].as_f64().unwrap(),
        })
        .collect();
    let reference = solve_at_load(&terms, load, &settings(1e-10)).unwrap();
    for tol in [1e-3, 1e-5, 1e-6, 1e-8] {
        let s = solve_at_load(&terms, load, &settings(tol)).unwrap();
        let est = s.error_estimate.unwrap();
        let e_l = rel(s.lambda, reference.lambda);
        let e_fr = rel(s.friction_rho, reference.friction_rho);
        let flagged = s
            .warnings
            .iter()
            .any(|w| w.starts_with("contact condition fails"));
        eprintln!("tol {tol:e}: λ err {e_l:.2e} ρF/N err {e_fr:.2e} est {est:.2e} flagged {flagged} gap {:.3e}", diag(&s).min_gap_ratio);
        // the reference's own error (its estimate, 4e−6 here) is added to the allowance
        let allowance = est + reference.error_estimate.unwrap();
        assert!(
            (e_l <= allowance && e_fr <= allowance) || flagged,
            "tol {tol:e}: wrong answer not flagged: λ err {e_l:.2e}, ρF/N err {e_fr:.2e}, est {est:.2e}"
        );
    }
}
