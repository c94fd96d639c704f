//! Property tests of the `auto` contact solver (issue 4, "what it must show", 2nd bullet) over random
//! spectra (1–40 terms, retardation times log-uniform over 24 decades, J∞/J_g up to 1e4) and random
//! scenes (V 1e−6…1e3 m/s, N 1…1e6 N/m, R 0.01…1 m, all log-uniform):
//!
//! 1. the error estimate of a tol 1e−6 solve is confirmed by a tol 1e−10 solve: |difference| ≤
//!    estimate (plus the tighter solve's own estimate) for friction and contact length, unless the
//!    solve flagged its own answer as invalid (failed contact check; counted and printed);
//! 2. pressure non-negative within the tolerance (min Q′/max Q′ ≥ −tol);
//! 3. friction ≥ 0 (dissipation cannot be negative) within the solve's own error estimate;
//! 4. friction → 0 at both speed limits, with the slopes of the known asymptotics.
//!
//! A seeded generator (SplitMix64) draws the cases from the run's seed (tests/seed.rs): a fresh one
//! on every run unless `VISCOROLL_SEED` is set, printed at the start of each test so that a failure
//! can be replayed. CI runs `CI_CASES` cases of 1–3 and `CI_LIMITS` of 4; the larger sweep is
//! `#[ignore]`d: `cargo test --release --lib contact_props::sweep -- --ignored --nocapture`.
//! The regression tests that need one particular case (`a_slow_mode_only_shifts_beta…`: CI case 28
//! of the former fixed seed 0x5EED_0004; the lumping-cap test) keep their fixed seeds.

use viscoroll::contact::{
    roll, AutoSettings, Body, ContactSettings, Diagnostics, DimensionlessSolution, RollSolution,
    Scene, Scheme,
};
use viscoroll::creep::{CreepSpectrum, RetardationTerm};

/// The `auto` diagnostics of an answer (every solve here uses the `auto` scheme).
fn diag(s: &DimensionlessSolution) -> &Diagnostics {
    s.diagnostics.as_ref().expect("auto diagnostics")
}

/// Cases of properties 1–3 in CI (each is two solves, tol 1e−6 and 1e−10).
const CI_CASES: usize = 400;
/// Cases of property 4 in CI (each is ~25 solves at tol 1e−6).
const CI_LIMITS: usize = 40;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    /// log-uniform in [lo, hi]
    fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi / lo).ln() * self.next()).exp()
    }
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

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// 1–40 terms, times log-uniform in [1e−12, 1e12] s, strengths random (log-uniform over 4
/// decades, so a few modes may dominate) normalised to J∞/J_g = ratio ∈ [1.01, 1e4] (log-uniform).
fn random_spectrum(rng: &mut Rng) -> (CreepSpectrum, usize, f64) {
    let n = 1 + (rng.next() * 40.0) as usize;
    let ratio = rng.log_uniform(1.01, 1e4);
    let mut w: Vec<f64> = (0..n).map(|_| rng.log_uniform(1e-4, 1.0)).collect();
    let sw: f64 = w.iter().sum();
    w.iter_mut().for_each(|x| *x *= (ratio - 1.0) / sw);
    let jg = 1e-9;
    let spec = CreepSpectrum {
        kind: Default::default(),
        poisson: 0.5,
        compliance_glassy_per_pa: jg,
        terms: w
            .iter()
            .map(|&x| RetardationTerm {
                compliance_per_pa: x * jg,
                tau_s: rng.log_uniform(1e-12, 1e12),
            })
            .collect(),
    };
    (spec, n, ratio)
}

fn random_scene(rng: &mut Rng) -> Scene {
    Scene {
        radius_m: rng.log_uniform(0.01, 1.0),
        load_n_per_m: rng.log_uniform(1.0, 1e6),
        speed_m_s: rng.log_uniform(1e-6, 1e3),
        poisson: None,
        body: Body::HALF_SPACE,
    }
}

/// Outcome of properties 1–3 for one case.
#[derive(Debug, Default)]
struct Outcome {
    estimate_ok: bool,
    flagged: bool,
    pressure_ok: bool,
    friction_ok: bool,
}

fn check_case(spec: &CreepSpectrum, scene: &Scene, label: &str) -> Outcome {
    let a = roll(scene, spec, &settings(1e-6)).unwrap();
    let b = roll(scene, spec, &settings(1e-10)).unwrap();
    let est = a.dimensionless.error_estimate.unwrap();
    let est_b = b.dimensionless.error_estimate.unwrap();
    // both zero (every mode lumped, e.g. τ ≪ the contact time; estimate 1 = 100 %): no error
    let e_fr = if a.friction == 0.0 && b.friction == 0.0 {
        0.0
    } else {
        rel(a.friction, b.friction)
    };
    let e_l = rel(a.contact_length_m, b.contact_length_m);
    let flagged = a
        .dimensionless
        .warnings
        .iter()
        .any(|w| w.starts_with("contact condition fails"));
    // an answer outside its tolerance says so, and only then
    for (s, tol) in [(&a, 1e-6), (&b, 1e-10)] {
        let said = s
            .dimensionless
            .warnings
            .iter()
            .any(|w| w.starts_with("tolerance not reached"));
        let zero = s
            .dimensionless
            .warnings
            .iter()
            .any(|w| w.starts_with("every creep mode"));
        assert_eq!(
            said,
            s.dimensionless.error_estimate.unwrap() > tol && !zero,
            "{label}: {:?}",
            s.dimensionless.warnings
        );
    }
    let o = Outcome {
        estimate_ok: e_fr <= est + est_b && e_l <= est + est_b,
        flagged,
        pressure_ok: diag(&a.dimensionless).min_pressure_ratio >= -1e-6
            && diag(&b.dimensionless).min_pressure_ratio >= -1e-10,
        // dissipation cannot be negative: F ≥ 0 within the solve's own stated error (a friction at
        // round-off level, e.g. −2.3e−20 with an estimate of 48 = 4800 %, is zero within it;
        // VISCOROLL_SEED=0x820c61a833790fb case 172)
        friction_ok: a.friction >= -est * a.friction.abs()
            && b.friction >= -est_b * b.friction.abs(),
    };
    if !(o.estimate_ok && o.pressure_ok && o.friction_ok) || flagged || est > 1e-6 {
        eprintln!(
            "{label}: fr {:.4e} vs {:.4e} (err {e_fr:.1e}), l err {e_l:.1e}, est {est:.1e} (tight {est_b:.1e}), \
             minp {:.1e}/{:.1e}, modes {}/{}, flagged {flagged}, {o:?}",
            a.friction,
            b.friction,
            diag(&a.dimensionless).min_pressure_ratio,
            diag(&b.dimensionless).min_pressure_ratio,
            diag(&a.dimensionless).modes_used,
            diag(&a.dimensionless).modes_total
        );
    }
    o
}

/// Runs `cases` random cases of properties 1–3; returns (indices of estimate failures, flagged,
/// other failures).
fn run_cases(seed: u64, cases: usize) -> (Vec<usize>, usize, usize) {
    let mut rng = Rng(seed);
    let (mut bad_est, mut flagged, mut bad_other) = (Vec::new(), 0, 0);
    for k in 0..cases {
        let (spec, n, ratio) = random_spectrum(&mut rng);
        let scene = random_scene(&mut rng);
        let label = format!(
            "case {k} (n {n}, J∞/J_g {ratio:.2e}, V {:.2e}, N {:.2e}, R {:.3})",
            scene.speed_m_s, scene.load_n_per_m, scene.radius_m
        );
        let o = check_case(&spec, &scene, &label);
        // A flagged answer carries "contact condition fails … this answer is not valid": its
        // estimate is no claim, so it is counted apart (the rear-edge scan found such wrong
        // solutions in 5 of 400 random scenes at tol 1e−6; see tests/contact_rear.rs).
        if !o.estimate_ok && !o.flagged {
            bad_est.push(k);
        }
        flagged += usize::from(o.flagged);
        bad_other += usize::from(!(o.pressure_ok && o.friction_ok));
    }
    (bad_est, flagged, bad_other)
}

#[test]
fn estimate_confirmed_pressure_and_friction_non_negative() {
    let seed = crate::tests::seed::seed(
        "contact_props::estimate_confirmed_pressure_and_friction_non_negative",
    );
    let (bad_est, flagged, bad_other) = run_cases(seed, CI_CASES);
    eprintln!(
        "{CI_CASES} cases: estimate failures {bad_est:?}, {flagged} flagged, {bad_other} other"
    );
    assert_eq!(bad_other, 0);
    assert!(bad_est.is_empty(), "estimate failures: {bad_est:?}");
}

/// A very slow mode against an exact law. For c = bL ≪ 1 a mode's term in the differentiated
/// eq. 3.25 (src/contact/body/half_space/auto/at_lambda.rs) is Ṽ(t) = d∫₀^∞e^{−cσ}H̃(t+σ)dσ with H̃ ≈ F₁/(2σ) far ahead of
/// the contact, so Ṽ = −(dF₁/2)·ln c + (terms free of c) + O(c ln c). A constant in the equation
/// is taken up by β alone: pressure, λ and N′ do not move, and ∂β/∂ln b = πdF₁/2 = f·N′/2
/// (d = fL, N′ = πLF₁), so ρF/N + (f·N′/2)·ln b is independent of b. CI case 28 (the slow end,
/// ρF/N/λ = 3.2e−5, so a β error of ε·λ is ~1e−11 of ρF/N) with its slowest mode (f fixed) moved
/// over c = 1e−12…1e−6 in quarter decades: the invariant must hold to 1e−9 relative (round-off of
/// ρF/N ≈ 8ε·λ/ρF/N ≈ 1e−10 per solve; the O(c ln c) rest is ≤ 1e−6·14 of the mode's 2e−5 effect).
/// Until the Bessel coefficients were trimmed relative to order 1 (src/special/bessel.rs) it
/// jumped by 5.6e−7 near c = 2.5e−9, where the n = 2 coefficient fell below the old cut.
#[test]
fn a_slow_mode_only_shifts_beta_by_f_n_ln_b_over_2() {
    use viscoroll::contact::numerics::at_lambda::{solve_at_lambda, QuadratureSettings};
    use viscoroll::contact::numerics::reduction::build;
    let mut rng = Rng(0x5EED_0004);
    let mut case = None;
    for _ in 0..=28 {
        let spec = random_spectrum(&mut rng).0;
        case = Some((spec, random_scene(&mut rng)));
    }
    let (spec, scene) = case.unwrap();
    let mut terms = scene.dimensionless(&spec).unwrap().terms;
    terms.sort_by(|a, b| a.b.total_cmp(&b.b));
    let lambda = 32.3047413818;
    let l = 0.5 * lambda;
    let c: Vec<f64> = terms.iter().map(|t| t.b * l).collect();
    assert!(
        c[0] < 1e-9 && c[1] < 1e-7 && c[4] > 1e4,
        "case 28 changed: c = {c:?}"
    );
    // modes 0..=4 kept (0 moved, 1–3 slow or in between), 5.. lumped as the solver does
    let q = QuadratureSettings::default();
    let solve = |c0: f64| {
        let mut t = terms.clone();
        t[0].b = c0 / l;
        let red = build(&t, (0..5).collect(), (5..t.len()).collect(), vec![]);
        let s = solve_at_lambda(&red.modes, lambda, q);
        let load = s.load / red.scale;
        (
            s.friction_rho + 0.5 * t[0].f * load * t[0].b.ln(),
            load,
            s.friction_rho,
        )
    };
    let (inv0, load0, fr0) = solve(1e-6);
    let mut worst = 0.0f64;
    for k in 1..=24 {
        let (inv, load, _) = solve(10f64.powf(-6.0 - 0.25 * k as f64));
        assert!(
            ((load - load0) / load0).abs() < 1e-12,
            "N′ moved: {load} vs {load0}"
        );
        worst = worst.max(((inv - inv0) / fr0).abs());
    }
    let (_, _, fr_slowest) = solve(1e-12);
    eprintln!(
        "slow mode moved over c = 1e-12…1e-6: ρF/N changes by {:.2e} relative, the invariant by \
         ≤ {worst:.1e}",
        (fr_slowest - fr0) / fr0
    );
    assert!(
        (fr_slowest - fr0) / fr0 > 1e-5,
        "the law's effect is too small to test"
    );
    assert!(
        worst < 1e-9,
        "ρF/N + (f N′/2) ln b moved by {worst:.1e} of ρF/N"
    );
}

/// Friction at speed v for one spectrum and scene (load, radius).
fn friction(spec: &CreepSpectrum, scene: &Scene, v: f64) -> RollSolution {
    let s = Scene {
        speed_m_s: v,
        ..*scene
    };
    roll(&s, spec, &settings(1e-6)).unwrap()
}

/// Property 4 for one spectrum and scene. With τ in [τ_min, τ_max] and l₀ the contact length at
/// V = 1 m/s, take V_slow = 1e−4·l₀/τ_max and V_fast = 1e4·l₀/τ_min. The contact is longer at slow
/// speeds (relaxed) and shorter at fast ones (glassy), so every mode has c = l/(2Vτ) ≥ 500 at
/// 0.1·V_slow and ≥ 50 at V_slow, and c ≤ 5e−5 at V_fast. There:
/// - slow end: every mode is relaxed; its friction is ρF/N ≈ λ·r/(2(1+r)c) ∝ V (module `reduce`), so
///   a tenfold slower speed gives 0.1× the friction, up to O(1/c_min) ≤ 2 % (asserted: 0.09…0.11);
/// - fast end: every mode is glassy; ρF/N ≈ 0.26·λ·r·c·ln(1/c) ∝ ln(V)/V, so a tenfold faster speed
///   gives 0.1·(1 + ln 10/(1 + ln(1/c))) with ln(1/c) ≥ 9.9: between 0.1 and 0.121 (asserted:
///   0.095…0.13);
/// - both ends are a small fraction of the peak over the swept speeds (asserted: < 5 %; the per-mode
///   asymptotes give ≈ 1/(2c) ≤ 1 % and c·ln(1/c) ≤ 5e−4 of a mode's own scale).
///
/// Speeds much further out are not used: there the solver lumps modes with c > 1e7 whatever the
/// budget (src/contact/body/half_space/auto/reduction.rs, `C_MAX`) and says so through its estimate (tested below).
fn check_limits(spec: &CreepSpectrum, scene: &Scene, label: &str) {
    let tau_min = spec
        .terms
        .iter()
        .map(|t| t.tau_s)
        .fold(f64::INFINITY, f64::min);
    let tau_max = spec.terms.iter().map(|t| t.tau_s).fold(0.0, f64::max);
    let l0 = friction(spec, scene, 1.0).contact_length_m;
    let v_slow = 1e-4 * l0 / tau_max;
    let v_fast = 1e4 * l0 / tau_min;
    // peak over 1 point per decade between the two ends
    let decades = (v_fast / v_slow).log10();
    let steps = decades.ceil() as usize;
    let peak = (1..steps)
        .map(|k| {
            friction(
                spec,
                scene,
                v_slow * 10f64.powf(k as f64 * decades / steps as f64),
            )
        })
        .map(|r| r.friction)
        .fold(0.0, f64::max);
    let ends: Vec<RollSolution> = [v_slow, 0.1 * v_slow, v_fast, 10.0 * v_fast]
        .iter()
        .map(|&v| friction(spec, scene, v))
        .collect();
    let fr: Vec<f64> = ends.iter().map(|r| r.friction).collect();
    let e: Vec<f64> = ends
        .iter()
        .map(|r| r.dimensionless.error_estimate.unwrap())
        .collect();
    let (s1, s2, f1, f2) = (fr[0], fr[1], fr[2], fr[3]);
    // The error estimates at the slow end are far above tol (4.4e−2 at tol 1e−6 in CI case 1, while
    // the tol 1e−6 and 1e−10 answers agree to 1e−9: see the report); they are printed, not
    // asserted. The slopes checked below are an independent check of these answers.
    eprintln!(
        "{label}: peak {peak:.3e}; slow {s1:.3e} ({:.2e} of peak), ratio {:.4}; fast {f1:.3e} ({:.2e} of peak), ratio {:.4}; estimates {:.1e} {:.1e} {:.1e} {:.1e}",
        s1 / peak,
        s2 / s1,
        f1 / peak,
        f2 / f1,
        e[0],
        e[1],
        e[2],
        e[3]
    );
    for v in [s1, s2, f1, f2] {
        assert!(v >= 0.0, "{label}");
    }
    assert!(s1 < 5e-2 * peak && f1 < 5e-2 * peak, "{label}");
    assert!(
        (s2 / s1 - 0.1).abs() < 0.01,
        "{label}: slow ratio {}",
        s2 / s1
    );
    assert!(
        f2 / f1 > 0.095 && f2 / f1 < 0.13,
        "{label}: fast ratio {}",
        f2 / f1
    );
}

fn run_limits(seed: u64, cases: usize) {
    let mut rng = Rng(seed);
    for k in 0..cases {
        let (spec, n, ratio) = random_spectrum(&mut rng);
        let scene = random_scene(&mut rng);
        let label = format!(
            "limits {k} (n {n}, J∞/J_g {ratio:.2e}, N {:.2e}, R {:.3})",
            scene.load_n_per_m, scene.radius_m
        );
        check_limits(&spec, &scene, &label);
    }
}

#[test]
fn friction_vanishes_at_both_speed_limits_with_the_asymptotic_slopes() {
    run_limits(
        crate::tests::seed::seed(
            "contact_props::friction_vanishes_at_both_speed_limits_with_the_asymptotic_slopes",
        ),
        CI_LIMITS,
    );
}

#[test]
#[ignore = "larger sweep (about 2 min in release); run with --ignored --nocapture"]
fn sweep() {
    let mut bad_other = 0;
    let base = crate::tests::seed::seed("contact_props::sweep");
    for seed in [base, base ^ 0xC0FF_EE01] {
        let (bad_est, flagged, other) = run_cases(seed, 2000);
        eprintln!(
            "seed {seed:#x}, 2000 cases: {} estimate failures {bad_est:?}, {flagged} flagged, {other} other",
            bad_est.len()
        );
        bad_other += other + bad_est.len();
        run_limits(seed + 1, 100);
    }
    assert_eq!(bad_other, 0);
}

#[test]
fn beyond_the_lumping_cap_the_corrected_friction_follows_the_slow_limit() {
    // At V = 1e−8·l₀/τ_max every mode has c > 1e7 and is lumped whatever the budget (reduce.rs,
    // C_MAX). The reduced problem is elastic, and the friction comes entirely from the first-order
    // lumping correction (controlled.rs), which is the slow-end asymptote ρF/N ∝ 1/c ∝ V. Check it
    // against that limit: a tenfold slower speed gives a tenfold smaller friction. The remaining
    // terms are O(1/c) ≤ 1e−6 relative (c > 1e7), so 1e−4 leaves a wide margin. At 1e−16·l₀/τ_max
    // (c > 1e15) the calibration cannot keep the mode it measures with (its expansion would need
    // ~1e9 Chebyshev terms; a random slow-end scene once asked for 13 GB and was killed), so it
    // keeps a probe of the same compliance (controlled.rs, `calibrate`): same law, same checks.
    let mut rng = Rng(0x5EED_0044);
    let (spec, _, _) = random_spectrum(&mut rng);
    let scene = random_scene(&mut rng);
    let tau_max = spec.terms.iter().map(|t| t.tau_s).fold(0.0, f64::max);
    let l0 = friction(&spec, &scene, 1.0).contact_length_m;
    for slow in [1e-8, 1e-16] {
        let v1 = slow * l0 / tau_max;
        let a = friction(&spec, &scene, v1);
        let b = friction(&spec, &scene, 0.1 * v1);
        eprintln!(
            "V {v1:.3e}: F/N {:.6e} est {:?} modes {}; V/10: F/N {:.6e}",
            a.friction,
            a.dimensionless.error_estimate,
            diag(&a.dimensionless).modes_used,
            b.friction
        );
        assert_eq!(diag(&a.dimensionless).modes_used, 0);
        assert!(a.friction > 0.0);
        let ratio = a.friction / b.friction;
        assert!((ratio / 10.0 - 1.0).abs() < 1e-4, "ratio {ratio}");
        let est = a.dimensionless.error_estimate.unwrap();
        assert!(est.is_finite() && est <= 1e-3, "estimate {est}");
    }
}

/// The estimate on measured compounds over the whole reduced variable s = l_g/(V·a_T) (a scene's
/// dimensionless problem depends on nothing else; src/contact/maps/): the creep spectra
/// of the TRIOS (32 terms over 15 decades, J∞/J_g 7.6e4) and EMS-CA (65 terms over 32 decades)
/// fits, ln s = −48…8 in steps of 1 (from far on the glassy side to beyond the relaxed end), at tol
/// 1e−4 and 1e−6 against tol 1e−10: |difference| ≤ the two estimates, in ρF/N and λ. Before the
/// Bessel cut was fixed (src/special/bessel.rs) TRIOS missed by up to 1.8e4× its estimate
/// (error 2.7e−2 at ln s ≈ −38…−46, estimates ~1e−6).
#[test]
fn estimate_holds_across_the_reduced_variable_on_measured_compounds() {
    use viscoroll::contact::maps::ReducedProblem;
    for name in ["rear_scan_trios_creep.json", "rear_scan_ems_ca_creep.json"] {
        let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
        let spec: CreepSpectrum =
            serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
        let p = ReducedProblem::new(&spec, None).unwrap();
        let solve = |x: f64, tol: f64| {
            let s = AutoSettings {
                gap_check: false,
                ..settings(tol).auto
            };
            p.solve(x, &s).unwrap()
        };
        let mut worst = 0.0f64;
        for k in 0..=56 {
            let x = -48.0 + k as f64;
            let r = solve(x, 1e-10);
            for tol in [1e-4, 1e-6] {
                let a = solve(x, tol);
                let e = rel(a.friction_rho, r.friction_rho).max(rel(a.lambda, r.lambda));
                let ratio = e / (a.error_estimate + r.error_estimate);
                worst = worst.max(ratio);
                assert!(
                    ratio <= 1.0,
                    "{name} ln s {x} tol {tol:e}: error {e:.2e}, estimates {:.2e} + {:.2e}",
                    a.error_estimate,
                    r.error_estimate
                );
                assert!(
                    a.friction_rho > 0.0,
                    "{name} ln s {x}: ρF/N {}",
                    a.friction_rho
                );
            }
        }
        eprintln!("{name}: worst error / estimate over ln s = −48…8: {worst:.2}");
    }
}
