//! Unit tests of the exact one-term solution (src/contact/exact.rs): known limits, the published
//! Goodier & Loutzenheiser figures, and an independent residual check of thesis eq. 3.25 by direct
//! quadrature with the closed-form kernel (crate::special::kernel_bracket).
use super::exact::*;
use crate::contact::error::ContactError;
use crate::contact::CreepTerm;
use crate::special::gauss_legendre::Integrator;
use crate::special::kernel_bracket;
use std::f64::consts::PI;

fn t(f: f64, b: f64) -> CreepTerm {
    CreepTerm { f, b }
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

#[test]
fn goodier_loutzenheiser_case() {
    // Goodier & Loutzenheiser (via thesis Table 1 / MATH.md §1): f = 10, b = 1, λ = 1 gives
    // β/λ ≈ 0.1952 and ρF/N ≈ 0.4308; the issue asks for agreement within 0.5 %.
    let s = one_term_at_lambda(t(10.0, 1.0), 1.0).unwrap();
    assert!(
        rel(s.beta / s.lambda, 0.1952) < 5e-3,
        "beta/lambda {}",
        s.beta
    );
    assert!(
        rel(s.friction_rho, 0.4308) < 5e-3,
        "friction {}",
        s.friction_rho
    );
}

#[test]
fn hertz_when_f_is_zero() {
    // f = 0: λ = 2√N′, β = λ/2, friction 0, Q′ = (1/π)√(ξ(λ−ξ)) (MATH.md §3), to rounding.
    for &lam in &[1e-4, 1.0, 37.0] {
        let s = one_term_at_lambda(t(0.0, 2.5), lam).unwrap();
        assert!(rel(s.load, lam * lam / 4.0) < 1e-15);
        assert!(rel(s.beta, lam / 2.0) < 1e-15);
        assert_eq!(s.friction_rho, 0.0);
        for i in 0..=20 {
            let x = lam * i as f64 / 20.0;
            let want = (x * (lam - x)).sqrt() / PI;
            assert!((s.pressure(x) - want).abs() <= 1e-15 * lam);
        }
    }
}

#[test]
fn tends_to_hertz_as_f_tends_to_zero() {
    // The creep term enters linearly in f, so the departures from Hertz must shrink like f: at f = 1e-6
    // and 1e-9 they are ~1e-6·O(1) and ~1e-9·O(1), and their ratio is 1000 to O(f).
    let lam = 1.3;
    let dev = |f: f64| {
        let s = one_term_at_lambda(t(f, 0.7), lam).unwrap();
        (
            (s.load - lam * lam / 4.0) / (lam * lam / 4.0),
            (s.beta - lam / 2.0) / lam,
            s.friction_rho,
        )
    };
    let (l6, b6, r6) = dev(1e-6);
    let (l9, b9, r9) = dev(1e-9);
    for (a, b) in [(l6, l9), (b6, b9), (r6, r9)] {
        assert!(a.abs() < 1e-5 && a.abs() > 1e-8, "deviation {a}");
        // Ratio 1000 up to the O(f) nonlinearity (1e-6) and rounding of the tiny 1e-9 deviation.
        assert!(((a / b) / 1000.0 - 1.0).abs() < 1e-5, "ratio {}", a / b);
    }
}

#[test]
fn glassy_limit_when_b_lambda_tends_to_zero() {
    // bλ → 0 at fixed f/b: the creep term fades (its contribution to K′ is (f/b)·O(bλ ln bλ)), so the
    // solution tends to the glassy Hertz one, with departures O(f·λ·ln(1/bλ)).
    let r = 3.0;
    let lam = 1.0;
    for &b in &[1e-6, 1e-8] {
        let s = one_term_at_lambda(t(r * b, b), lam).unwrap();
        let bound = 10.0 * r * b * lam * (1.0 / (b * lam)).ln();
        assert!(rel(s.load, 0.25) < bound, "b={b} load={}", s.load);
        assert!(rel(s.beta, 0.5) < bound);
        assert!(s.friction_rho > 0.0 && s.friction_rho < bound);
    }
}

#[test]
fn relaxed_limit_when_b_lambda_tends_to_infinity() {
    // bλ → ∞ at fixed f/b = r: Hertz with compliance (1 + r): N′ = λ²/(4(1+r)), β = λ/2, friction 0.
    // The departures fall like 1/(bλ) (measured: relative load deviation ≈ 1.33/(bλ) at r = 2): check
    // a bound 10/(bλ) and that a hundredfold bλ reduces them about a hundredfold.
    let r = 2.0;
    let lam = 1.0;
    let dev = |b: f64| {
        let s = one_term_at_lambda(t(r * b, b), lam).unwrap();
        let hertz = lam * lam / (4.0 * (1.0 + r));
        (
            rel(s.load, hertz),
            rel(s.beta, lam / 2.0),
            s.friction_rho / lam,
        )
    };
    let d4 = dev(1e4);
    let d6 = dev(1e6);
    for (a, b) in [(d4.0, d6.0), (d4.1, d6.1), (d4.2, d6.2)] {
        assert!(a < 10.0 / 1e4 && b < 10.0 / 1e6, "{a} {b}");
        let ratio = a / b;
        assert!(ratio > 80.0 && ratio < 125.0, "ratio {ratio}");
    }
}

/// Left side of eq. 3.25, ∫₀^λ Q′(t)[K(−t) − K(ξ−t)]dt, by adaptive Gauss–Legendre quadrature with
/// panels graded geometrically toward the log singularities (t = 0, ξ) and the square-root edges (t = λ)
/// and the front-edge layer; K(x) = ln|x| + (f/b)·h(bx) with h the closed-form kernel bracket
/// (MATH.md §2; constants cancel in the difference).
fn lhs_3_25(s: &OneTermExact, xi: f64) -> f64 {
    let CreepTerm { f, b } = s.term;
    let lam = s.lambda;
    let k = |x: f64| x.abs().ln() + (f / b) * kernel_bracket(b * x);
    let mut pts = vec![0.0, lam];
    if xi > 0.0 && xi < lam {
        pts.push(xi);
    }
    let mut edges = pts.clone();
    for &p in &pts {
        for j in 1..40 {
            let d = lam * 0.5f64.powi(j);
            if p - d > 0.0 {
                edges.push(p - d);
            }
            if p + d < lam {
                edges.push(p + d);
            }
        }
    }
    edges.sort_by(|a, b| a.partial_cmp(b).unwrap());
    edges.dedup();
    let mut q = Integrator::new(20);
    q.integrate(
        |x| {
            if x <= 0.0 || x >= lam || x == xi {
                0.0
            } else {
                s.pressure(x) * (k(-x) - k(xi - x))
            }
        },
        &edges,
        1e-14,
    )
}

#[test]
fn pressure_satisfies_eq_3_25_by_direct_quadrature() {
    // Independent of the derivation: the series pressure and β put into eq. 3.25, integrated
    // numerically with the closed-form kernel, must reproduce ξβ − ξ²/2. Tolerance 1e-12 relative to
    // the largest |ξβ − ξ²/2| on the contact: quadrature (tolerance 1e-14) and kernel (≤ 1e-15) are far
    // better (measured worst 3.8e-15); a change of β by 1e-11 relative already fails it.
    // Cases: the Goodier–Loutzenheiser one, moderate ones, f/b = 1000 at high speed, and thin front
    // layers (κλ = 1000 and 2000, layer width 1e-3 of λ) at both ends of f/b.
    let cases = [
        (10.0, 1.0, 1.0),
        (0.5, 2.0, 3.0),
        (200.0, 0.2, 0.5),
        (1e-2, 1e-3, 5.0),
        (1.0, 1e3, 1.0),
        (1e3, 1.0, 2.0),
    ];
    let mut worst = 0.0f64;
    for &(f, b, lam) in &cases {
        let s = one_term_at_lambda(t(f, b), lam).unwrap();
        let scale = (0.5 * s.beta * s.beta).max((lam * s.beta - 0.5 * lam * lam).abs());
        for i in 1..=12 {
            let xi = lam * i as f64 / 12.0 - if i == 12 { 1e-3 * lam } else { 0.0 };
            let got = lhs_3_25(&s, xi);
            let want = xi * s.beta - 0.5 * xi * xi;
            worst = worst.max((got - want).abs() / scale);
            assert!(
                (got - want).abs() < 1e-12 * scale,
                "f={f} b={b} lam={lam} xi={xi}: {got} vs {want}"
            );
        }
    }
    eprintln!("eq. 3.25 worst residual / max|rhs| = {worst:e}");
}

#[test]
fn pressure_moments_give_load_and_friction() {
    // N′ and ρF/N come from closed forms in h₁, h₂ (eq. D5); integrating the evaluated pressure
    // numerically must give the same numbers (quadrature good to ~1e-13 here).
    for &(f, b, lam) in &[(10.0, 1.0, 1.0), (1e3, 1.0, 0.3), (0.1, 10.0, 2.0)] {
        let s = one_term_at_lambda(t(f, b), lam).unwrap();
        let mut edges: Vec<f64> = (0..=64).map(|i| lam * i as f64 / 64.0).collect();
        for j in 7..40 {
            edges.push(lam * (1.0 - 0.5f64.powi(j)));
            edges.push(lam * 0.5f64.powi(j));
        }
        edges.sort_by(|a, b| a.partial_cmp(b).unwrap());
        let mut q = Integrator::new(20);
        let m0 = q.integrate(|x| s.pressure(x), &edges, 1e-14);
        let m1 = q.integrate(|x| s.pressure(x) * (x - s.beta), &edges, 1e-14);
        assert!(
            rel(2.0 * m0, s.load) < 1e-11,
            "load {} vs {}",
            2.0 * m0,
            s.load
        );
        assert!(rel(m1 / m0, s.friction_rho) < 1e-10);
    }
}

#[test]
fn pressure_nonnegative_and_zero_at_edges() {
    // Wide range of layer widths 1/κ relative to λ; sample densely near the front edge.
    for &(f, b, lam) in &[
        (10.0, 1.0, 1.0),
        (1e3, 1e-1, 10.0),
        (1e-3, 1e3, 1.0),
        (5.0, 1e-4, 1e-2),
    ] {
        let s = one_term_at_lambda(t(f, b), lam).unwrap();
        assert_eq!(s.pressure(0.0), 0.0);
        assert_eq!(s.pressure(lam), 0.0);
        let peak = (0..=200)
            .map(|i| s.pressure(lam * i as f64 / 200.0))
            .fold(0.0, f64::max);
        for i in 0..=2000 {
            let x = lam * i as f64 / 2000.0;
            let y = lam * (1.0 - 0.5f64.powf(i as f64 / 50.0));
            for z in [x, y] {
                // Rounding of the series sum is ~N·ε of the peak: allow −1e-13·peak.
                assert!(
                    s.pressure(z) >= -1e-13 * peak,
                    "f={f} b={b} lam={lam} xi={z}"
                );
            }
        }
    }
}

#[test]
fn reinsch_sum_matches_direct_sine_sum() {
    let s = one_term_at_lambda(t(300.0, 1.0), 2.0).unwrap();
    let lam = s.lambda;
    // Recover the coefficients through the public pressure at one point is not possible, so compare
    // against a direct Σ hₙ sin(nθ) with h recomputed from the same solution via pressure samples at
    // θ = πk/M (discrete sine transform), then evaluate both forms at other points.
    let m = 4 * s.series_len();
    let mut h = vec![0.0; m];
    for (n, hn) in h.iter_mut().enumerate().skip(1) {
        let mut acc = 0.0;
        for k in 1..m {
            let th = PI * k as f64 / m as f64;
            let x = 0.5 * lam * (1.0 + th.cos());
            acc += s.pressure(x) * PI * (n as f64 * th).sin();
        }
        *hn = 2.0 * acc / m as f64;
    }
    for i in 1..50 {
        let th = PI * (i as f64 + 0.37) / 50.0;
        let x = 0.5 * lam * (1.0 + th.cos());
        let direct: f64 = h
            .iter()
            .enumerate()
            .map(|(n, hn)| hn * (n as f64 * th).sin())
            .sum::<f64>()
            / PI;
        assert!(
            (direct - s.pressure(x)).abs() < 1e-12 * s.lambda,
            "theta={th}"
        );
    }
}

#[test]
fn series_truncation_converges() {
    // Dropping Bessel terms below a relative cut perturbs N′ and friction by about that cut; the
    // errors must fall with the cut and be ≤ 1e-15 relative beyond the default.
    let term = t(10.0, 1.0);
    let reference = super::exact::solve_with_cut_for_tests(term, 1.0, 1e-25);
    let mut last = f64::INFINITY;
    for &cut in &[1e-2, 1e-4, 1e-8, 1e-12, 1e-16, 1e-19] {
        let s = super::exact::solve_with_cut_for_tests(term, 1.0, cut);
        let err = rel(s.load, reference.load).max(rel(s.friction_rho, reference.friction_rho));
        eprintln!("cut {cut:e}: terms {} err {err:e}", s.series_len());
        assert!(err <= last.max(1e-15));
        assert!(err < 100.0 * cut + 1e-15, "cut={cut} err={err}");
        last = err;
    }
}

#[test]
fn load_inversion_recovers_lambda() {
    // Solve at λ, then at the load found: the same λ, β and friction to ~1e-13.
    for &(f, b, lam) in &[
        (10.0, 1.0, 1.0),
        (1e3, 1.0, 30.0),
        (1e-3, 1.0, 1e-3),
        (50.0, 1e-3, 2.0),
    ] {
        let s = one_term_at_lambda(t(f, b), lam).unwrap();
        let g = one_term_at_load(t(f, b), s.load).unwrap();
        assert!(rel(g.lambda, lam) < 1e-13, "lam {} vs {lam}", g.lambda);
        assert!(rel(g.beta, s.beta) < 1e-12);
        assert!(rel(g.friction_rho, s.friction_rho) < 1e-12);
        assert!(g.iterations > 0 && g.iterations < 60);
    }
}

#[test]
fn load_at_low_speed_exceeds_the_hertz_start() {
    // At low speed (bλ ≫ 1) λ ≈ √(1+f/b)·2√N′ (relaxed Hertz), far above the glassy start 2√N′.
    let r = 1000.0;
    let load = 1.0;
    let g = one_term_at_load(t(r * 1e3, 1e3), load).unwrap();
    let relaxed = 2.0 * ((1.0 + r) * load).sqrt();
    assert!(
        rel(g.lambda, relaxed) < 0.05,
        "lambda {} relaxed {relaxed}",
        g.lambda
    );
}

#[test]
fn bad_input_is_an_error() {
    assert!(matches!(
        one_term_at_lambda(t(-1.0, 1.0), 1.0),
        Err(ContactError::BadTerm { .. })
    ));
    assert!(matches!(
        one_term_at_lambda(t(1.0, 0.0), 1.0),
        Err(ContactError::BadTerm { .. })
    ));
    assert!(matches!(
        one_term_at_lambda(t(1.0, f64::NAN), 1.0),
        Err(ContactError::BadTerm { .. })
    ));
    assert!(matches!(
        one_term_at_lambda(t(1.0, 1.0), -2.0),
        Err(ContactError::BadValue { .. })
    ));
    assert!(matches!(
        one_term_at_lambda(t(f64::INFINITY, 1.0), 1.0),
        Err(ContactError::BadTerm { .. })
    ));
    assert!(matches!(
        one_term_at_load(t(1.0, 1.0), 0.0),
        Err(ContactError::BadValue { .. })
    ));
    assert!(matches!(
        one_term_at_lambda(t(1e12, 1.0), 1e3),
        Err(ContactError::OutOfRange {
            bound: "at most",
            ..
        })
    ));
    assert!(matches!(
        one_term_at_lambda(t(1.0, 1e-200), 1e-100),
        Err(ContactError::OutOfRange {
            bound: "at least",
            ..
        })
    ));
    // Just above the lower limit everything is still finite (and Hertz-like).
    let s = one_term_at_lambda(t(1e-240, 1e-240), 1e-9).unwrap();
    assert!(s.beta.is_finite() && s.load.is_finite() && s.friction_rho.is_finite());
    assert!(rel(s.load, 0.25e-18) < 1e-12);
}

#[test]
fn to_solution_carries_the_values() {
    let s = one_term_at_lambda(t(10.0, 1.0), 1.0).unwrap();
    let d = s.to_solution(11);
    assert_eq!(d.scheme, "exact");
    assert_eq!(d.xi.len(), 11);
    assert_eq!(d.xi[10], 1.0);
    assert_eq!(d.pressure[0], 0.0);
    assert_eq!(d.pressure[10], 0.0);
    assert_eq!(d.pressure[3], s.pressure(d.xi[3]));
    assert_eq!(
        (d.beta, d.load, d.friction_rho),
        (s.beta, s.load, s.friction_rho)
    );
}

#[test]
fn matches_high_precision_reference_table() {
    // tests/data/exact_one_term_reference.csv: the closed forms D4–D5 evaluated with mpmath at 30
    // digits (own Bessel functions and tanh-sinh quadrature; tools/gen_exact_reference.py), over
    // f/b = 1e-3…1e3 and bλ = 1e-4…1e4 with κλ ≤ 2e4, plus the corners κλ ≈ 1e4 at f/b = 1e3 and 10.
    // Target of the issue: 1e-10 relative; we assert 1e-13 (measured worst ≈ 1.05e-14, friction at
    // bλ = 1e4 where it is 1e-7 of λ).
    let txt = include_str!(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/exact_one_term_reference.csv"
    ));
    let mut rows = 0;
    let mut worst = 0.0f64;
    for line in txt
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
    {
        let v: Vec<f64> = line.split(',').map(|x| x.trim().parse().unwrap()).collect();
        let s = one_term_at_lambda(t(v[0], v[1]), v[2]).unwrap();
        for (got, want) in [(s.beta, v[3]), (s.load, v[4]), (s.friction_rho, v[5])] {
            let e = rel(got, want);
            worst = worst.max(e);
            assert!(e < 1e-13, "row {line}: {got} vs {want}");
        }
        rows += 1;
    }
    eprintln!("reference rows {rows}, worst relative error {worst:e}");
    assert!(rows >= 20);
}

#[test]
fn depends_only_on_f_over_b_and_b_lambda() {
    // Scaling ξ by s with f, b divided by s leaves eq. 3.25 invariant up to Q′ → sQ′, β → sβ
    // (N′ → s²N′, ρF/N → s·ρF/N): an independent consistency check of every code path that mixes
    // λ, b and f.
    let base = one_term_at_lambda(t(3.0, 0.5), 2.0).unwrap();
    for &s in &[1e-3, 7.0, 1e4] {
        let g = one_term_at_lambda(t(3.0 / s, 0.5 / s), 2.0 * s).unwrap();
        assert!(rel(g.beta, s * base.beta) < 1e-13);
        assert!(rel(g.load, s * s * base.load) < 1e-13);
        assert!(rel(g.friction_rho, s * base.friction_rho) < 1e-13);
        assert!(
            rel(
                g.pressure(0.3 * g.lambda),
                s * base.pressure(0.3 * base.lambda)
            ) < 1e-13
        );
    }
}

#[test]
fn load_iteration_converges_over_eight_decades_of_speed() {
    // Fixed dimensionless load, b from 1e-4 to 1e4 (speed ∝ 1/b) at f/b = 1000 (relaxed/glassy
    // compliance 1001, λ spans a factor ≈ 32): each solve must hit the load to 1e-13 and λ must lie
    // between the glassy and relaxed Hertz widths (up to the bracket's 1e-9 margin), growing with b.
    let load = 0.5;
    let mut last_lambda = 0.0;
    for k in -4..=4 {
        let b = 10f64.powi(k);
        let g = one_term_at_load(t(1000.0 * b, b), load).unwrap();
        assert!(rel(g.load, load) < 1e-13, "b={b}");
        let glassy = 2.0 * load.sqrt();
        let relaxed = 2.0 * (1001.0 * load).sqrt();
        assert!(g.lambda >= glassy * (1.0 - 1e-9) && g.lambda <= relaxed * (1.0 + 1e-9));
        assert!(g.lambda > last_lambda);
        last_lambda = g.lambda;
        assert!(g.iterations < 60, "b={b} iterations {}", g.iterations);
    }
}

#[test]
#[ignore = "exploration: cargo test --release --lib sweep_print -- --ignored --nocapture"]
fn sweep_print() {
    for &r in &[1e-3, 1.0, 1e3] {
        for &bl in &[1e-12, 1e-8, 1e-4, 1e-2, 1.0, 1e2, 1e4, 1e6, 1e8] {
            let t0 = std::time::Instant::now();
            match one_term_at_lambda(t(r * bl, bl), 1.0) {
                Ok(s) => eprintln!(
                    "r={r:e} bl={bl:e}: beta={:.15e} load={:.15e} fr={:.15e} N={} ({:?})",
                    s.beta,
                    s.load,
                    s.friction_rho,
                    s.series_len(),
                    t0.elapsed()
                ),
                Err(e) => eprintln!("r={r:e} bl={bl:e}: {e}"),
            }
        }
    }
}
