// Tests of the covered maps: the two-variable reduction against direct `roll_cover` solves of
// scenes sharing (s, η), the surface against direct solves at random off-node points, and the 2-D
// Chebyshev machinery on known functions.

use super::surface::{clenshaw_2d, coefficients_2d, eta_start_degree, lebesgue, tails_2d};
use super::*;
use crate::contact::cover::roll_cover;
use crate::contact::{Body, Scene};
use crate::testdata::{broad_spectrum, SplitMix64};
use crate::{CreepSpectrum, ShiftLaw};
use std::f64::consts::PI;

fn creep() -> CreepSpectrum {
    crate::creep::relaxation_to_creep(&broad_spectrum())
        .expect("broad spectrum converts")
        .0
}

/// WLF with the universal constants at T_ref = 20 °C (as the half-space map tests).
fn wlf() -> ShiftLaw {
    ShiftLaw::Wlf {
        t_ref_c: 20.0,
        c1: 8.86,
        c2_k: 101.6,
    }
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// The layer's direct solve of a dimensional scene on a cover of `h_m` at `tol`.
fn direct(
    c: &CreepSpectrum,
    law: &ShiftLaw,
    (r, n, v, t): (f64, f64, f64, f64),
    h_m: f64,
    tol: f64,
) -> crate::contact::cover::CoverRoll {
    let at = c.at_temperature(law, t, None).unwrap();
    let scene = Scene {
        radius_m: r,
        load_n_per_m: n,
        speed_m_s: v,
        poisson: None,
        body: Body::Layer { thickness_m: h_m },
    };
    roll_cover(&scene, &at.spectrum, tol).unwrap()
}

#[test]
fn scenes_sharing_s_and_eta_share_the_covered_answer() {
    let c = creep();
    let law = wlf();
    let a = |t: f64| 10f64.powf(law.log10_a_t(t));
    let (r0, n0, v0, t0, h0) = (0.0665, 1e4, 4.0, 0.0, 5e-3);
    let p0 = CoveredProblem::new(&c, None, h0).unwrap();
    // l_g ∝ √(R N*): R×4 doubles l_g, so V×2 keeps s and h×2 keeps η; N*×4 likewise; a change of
    // temperature is undone by the speed (s only); the cover alone moves η only.
    let cases = [
        ((r0, n0, v0, t0), h0),
        ((4.0 * r0, n0, 2.0 * v0, t0), 2.0 * h0),
        ((r0, 4.0 * n0, 2.0 * v0, t0), 2.0 * h0),
        ((r0, n0, v0 * a(t0) / a(15.0), 15.0), h0),
        (
            (9.0 * r0, 0.25 * n0, 1.5 * v0 * a(t0) / a(-10.0), -10.0),
            1.5 * h0,
        ),
    ];
    let s0 = p0.reduced.reduced_time_s(r0, n0, v0, a(t0));
    let eta0 = p0.reduced_thickness(r0, n0);
    let mut first: Option<(f64, f64)> = None;
    for &(scene, h) in &cases {
        let (r, n, v, t) = scene;
        let p = CoveredProblem::new(&c, None, h).unwrap();
        assert!(rel(p.reduced.reduced_time_s(r, n, v, a(t)), s0) < 1e-12);
        assert!(rel(p.reduced_thickness(r, n), eta0) < 1e-12);
        let sol = direct(&c, &law, scene, h, 1e-4);
        let d = &sol.roll.dimensionless;
        // The same dimensionless problem up to the rounding of bᵢ and h′ (~1e−15): the adaptive
        // layer solve takes the same steps, so the answers agree far below its 1e−4 tolerance.
        match first {
            None => first = Some((d.friction_rho, d.lambda)),
            Some((fr, la)) => {
                assert!(
                    rel(d.friction_rho, fr) < 1e-9,
                    "{scene:?}: {} vs {fr}",
                    d.friction_rho
                );
                assert!(rel(d.lambda, la) < 1e-9, "{scene:?}: {} vs {la}", d.lambda);
            }
        }
        // The exact scalings back to SI: F/N = φ·l_g/R, l = λ·l_g.
        let lg = p.reduced.glassy_length_m(r, n);
        assert!(rel(sol.roll.friction, d.friction_rho * lg / r) < 1e-12);
        assert!(rel(sol.roll.contact_length_m, d.lambda * lg) < 1e-12);
    }
    // And the node solve at (ln s0, ln η0) is that same answer.
    let node = p0.node(s0.ln(), eta0.ln(), 1e-4).unwrap();
    let (fr, la) = first.unwrap();
    assert!(rel(node.ln_phi.exp(), fr) < 1e-9 && rel(node.ln_lambda.exp(), la) < 1e-9);
}

#[test]
fn covered_map_matches_direct_solves_at_random_points() {
    let c = creep();
    let law = wlf();
    let h = 5e-3;
    let p = CoveredProblem::new(&c, None, h).unwrap();
    let mut rng = SplitMix64::new(14);
    let mut pick = |lo: f64, hi: f64| lo + (hi - lo) * rng.uniform();
    // 200 random idler-like scenes on the 5 mm cover: V 1…8 m/s, N* 5…20 kN/m (log-uniform),
    // T 0…20 °C, R 66.5 or 100 mm (η = h/l_g ≈ 1…3).
    let scenes: Vec<(f64, f64, f64, f64)> = (0..200)
        .map(|k| {
            let r = if k % 2 == 0 { 0.0665 } else { 0.1 };
            let v = pick(1f64.ln(), 8f64.ln()).exp();
            let n = pick(5e3f64.ln(), 2e4f64.ln()).exp();
            (r, n, v, pick(0.0, 20.0))
        })
        .collect();
    let queries: Vec<MapQuery> = scenes
        .iter()
        .map(|&(r, n, v, t)| MapQuery {
            radius_m: r,
            load_n_per_m: n,
            speed_m_s: v,
            a_t: 10f64.powf(law.log10_a_t(t)),
        })
        .collect();
    // The main job's covered tolerance and settings.
    let tol = 1e-3;
    let settings = MapSettings::covered(tol);
    let (values, surface) = covered_map(&p, &queries, &settings).unwrap();
    // interpolation + Λ_xΛ_y·(node estimate) of every panel within tol (surface.rs, error budget)
    assert!(surface.error_estimate <= tol, "{surface:?}");
    // 13 random scenes (off the nodes) against direct layer solves at 1e−6 (the spectral layer
    // solve costs about the same as at 1e−4; its error ≤ its estimate ≤ ~1e−6): the map must be
    // within its own estimate plus the reference's tolerance, and so within tol.
    let mut worst = 0.0f64;
    for k in (0..200).step_by(16) {
        let d = direct(&c, &law, scenes[k], h, 1e-6);
        let m = values[k];
        let e =
            rel(m.friction, d.roll.friction).max(rel(m.contact_length_m, d.roll.contact_length_m));
        assert!(
            e <= surface.error_estimate + 2e-6 && e <= tol,
            "point {k} {:?}: error {e:e}, estimate {:e}",
            scenes[k],
            surface.error_estimate
        );
        worst = worst.max(e);
    }
    eprintln!(
        "covered map tol {tol:e}: worst error {worst:.2e} against direct solves at 1e-6; estimate {:.2e} \
         (interpolation {:.2e} + nodes {:.2e}), {} solves, panels {:?}",
        surface.error_estimate,
        surface.interpolation_estimate,
        surface.node_error_bound,
        surface.solves,
        surface.panel_shapes()
    );
    assert!(
        worst > 0.0,
        "the map is an interpolant, not a copy of the solves"
    );
}

#[test]
fn tensor_chebyshev_is_exact_for_products_and_estimates_exp() {
    let (nx, ny) = (16, 8);
    let node = |k: usize, n: usize| (PI * k as f64 / n as f64).cos();
    let grid = |f: &dyn Fn(f64, f64) -> f64| -> Vec<f64> {
        (0..=nx)
            .flat_map(|j| (0..=ny).map(move |k| (j, k)))
            .map(|(j, k)| f(node(j, nx), node(k, ny)))
            .collect()
    };
    // T₃(t)·T₂(u): the single coefficient c₃₂ = 1 (to rounding), no tail.
    let c = coefficients_2d(
        &grid(&|t, u| (4.0 * t * t * t - 3.0 * t) * (2.0 * u * u - 1.0)),
        nx,
        ny,
    );
    for j in 0..=nx {
        for k in 0..=ny {
            let want = if (j, k) == (3, 2) { 1.0 } else { 0.0 };
            assert!((c[j * (ny + 1) + k] - want).abs() < 1e-14, "c[{j}][{k}]");
        }
    }
    let (ex, ey) = tails_2d(&c, nx, ny);
    assert!(ex < 1e-13 && ey < 1e-13);
    // e^{3t + 2u} = Σ c_j(3) c_k(2) T_j(t) T_k(u) with c_0(a) = I₀(a), c_j(a) = 2I_j(a) (Trefethen,
    // ATAP ch. 3). The discrete coefficients add the aliases c_{2n−k} (ATAP ch. 4): c₉(2) ≈ 6e−6 on
    // c̃₇ makes e_y ≈ 2e−3 larger than the exact tail (1e−5 relative on e_x), hence the tolerances. So:
    // e_x = 2·Σ_{j=12..16} c_j(3)·Σ_k c_k(2) and e_y = 2·Σ_{k=6..8} c_k(2)·Σ_j c_j(3). The true error,
    // between c₉(2)·e³ ≈ 1.2e−4 (the first neglected coefficient of the short side) and a few times it
    // (its alias on c̃₇ adds as much again), lies below e_x + e_y.
    let bessel_i = |n: i32, a: f64| -> f64 {
        // power series of I_n(a), 40 terms: converged to rounding for a ≤ 3
        let mut term = (0.5 * a).powi(n) / (1..=n).map(f64::from).product::<f64>();
        let mut sum = 0.0;
        for m in 0..40 {
            sum += term;
            term *= (0.25 * a * a) / (f64::from(m + 1) * f64::from(m + 1 + n));
        }
        sum
    };
    let cheb = |j: i32, a: f64| {
        if j == 0 {
            bessel_i(0, a)
        } else {
            2.0 * bessel_i(j, a)
        }
    };
    let sum_x: f64 = (0..=16).map(|j| cheb(j, 3.0)).sum();
    let sum_y: f64 = (0..=8).map(|k| cheb(k, 2.0)).sum();
    let want_x = 2.0 * (12..=16).map(|j| cheb(j, 3.0)).sum::<f64>() * sum_y;
    let want_y = 2.0 * (6..=8).map(|k| cheb(k, 2.0)).sum::<f64>() * sum_x;
    let f = |t: f64, u: f64| (3.0 * t + 2.0 * u).exp();
    let c = coefficients_2d(&grid(&f), nx, ny);
    let (ex, ey) = tails_2d(&c, nx, ny);
    assert!(
        rel(ex, want_x) < 1e-4 && rel(ey, want_y) < 5e-3,
        "{ex:e} vs {want_x:e}, {ey:e} vs {want_y:e}"
    );
    let mut err = 0.0f64;
    for a in 0..=60 {
        for b in 0..=60 {
            let (t, u) = (-1.0 + a as f64 / 30.0, -1.0 + b as f64 / 30.0);
            err = err.max((clenshaw_2d(&c, ny, t, u) - f(t, u)).abs());
        }
    }
    let first_neglected = cheb(9, 2.0) * sum_x;
    assert!(
        err <= ex + ey && err > first_neglected && err < 4.0 * first_neglected,
        "error {err:e}, estimates {ex:e} {ey:e}, first neglected {first_neglected:e}"
    );
}

#[test]
fn covered_bad_inputs_name_the_field() {
    let c = creep();
    assert!(CoveredProblem::new(&c, None, 0.0)
        .unwrap_err()
        .to_string()
        .contains("cover"));
    let p = CoveredProblem::new(&c, None, 5e-3).unwrap();
    let q = MapQuery {
        radius_m: 0.1,
        load_n_per_m: 1e4,
        speed_m_s: f64::NAN,
        a_t: 1.0,
    };
    let e = covered_map(&p, &[q], &MapSettings::default()).unwrap_err();
    assert!(e.to_string().contains("speed_m_s"), "{e}");
    assert!(covered_map(&p, &[], &MapSettings::default())
        .unwrap_err()
        .to_string()
        .contains("points"));
}

/// The idler scene's maps (0 and 20 °C, 1–6 m/s, 5–20 kN/m, 5 mm cover, R = 66.5 mm) of the four
/// synthetic rubbers of the test-data module (true spectra and WLF laws, 27–34 terms), and a wide
/// map (−20…40 °C, 0.5–40 m/s, 2–50 kN/m: η over a factor 5, a degree-6 start in η): at the main
/// job's 1e−3 with its covered settings, the estimate must hold against direct layer solves at
/// 1e−6 at random points of the rectangle (off the nodes), and stay within tol.
#[test]
fn covered_estimate_holds_on_synthetic_compounds() {
    let tol = 1e-3;
    let settings = MapSettings::covered(tol);
    let mut rng = SplitMix64::new(16);
    let mut worst_ratio = 0.0f64;
    for (i, base) in crate::testdata::realistic::realistic_compounds()
        .iter()
        .enumerate()
    {
        let c = crate::creep::relaxation_to_creep(&base.spectrum)
            .expect("converts")
            .0;
        let p = CoveredProblem::new(&c, None, 5e-3).unwrap();
        let (temps, speeds, loads) = if i == 0 {
            (vec![-20.0, 40.0], [0.5, 40.0], [2e3, 5e4])
        } else {
            (vec![0.0, 20.0], [1.0, 6.0], [5e3, 2e4])
        };
        let mut queries = Vec::new();
        for &t in &temps {
            let a_t = 10f64.powf(base.law.log10_a_t(t));
            for v in speeds {
                for n in loads {
                    queries.push(MapQuery {
                        radius_m: 0.0665,
                        load_n_per_m: n,
                        speed_m_s: v,
                        a_t,
                    });
                }
            }
        }
        let (_, surface) = covered_map(&p, &queries, &settings).unwrap();
        assert!(surface.error_estimate <= tol, "{}: {surface:?}", base.name);
        let xs: Vec<f64> = queries
            .iter()
            .map(|q| {
                p.reduced
                    .reduced_time_s(q.radius_m, q.load_n_per_m, q.speed_m_s, q.a_t)
                    .ln()
            })
            .collect();
        let ys: Vec<f64> = queries
            .iter()
            .map(|q| p.reduced_thickness(q.radius_m, q.load_n_per_m).ln())
            .collect();
        let span = |v: &[f64]| {
            let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
            (lo, v.iter().copied().fold(f64::NEG_INFINITY, f64::max) - lo)
        };
        let ((x0, dx), (y0, dy)) = (span(&xs), span(&ys));
        for _ in 0..6 {
            let (x, y) = (x0 + dx * rng.uniform(), y0 + dy * rng.uniform());
            let (phi, lambda) = surface.eval(x, y).unwrap();
            let d = p.node(x, y, 1e-6).unwrap();
            // the reference's own error ≤ its estimate (~1e−6)
            let e = (phi.ln() - d.ln_phi)
                .abs()
                .max((lambda.ln() - d.ln_lambda).abs());
            assert!(
                e <= surface.error_estimate + d.error_estimate,
                "{} at ({x}, {y}): error {e:e}, estimate {:e}",
                base.name,
                surface.error_estimate
            );
            worst_ratio = worst_ratio.max(e / surface.error_estimate);
        }
        eprintln!(
            "{}: {} solves, panels {:?}, estimate {:.1e} (interpolation {:.1e} + nodes {:.1e})",
            base.name,
            surface.solves,
            surface.panel_shapes(),
            surface.error_estimate,
            surface.interpolation_estimate,
            surface.node_error_bound
        );
    }
    eprintln!("largest error / estimate: {worst_ratio:.2}");
}

/// The Lebesgue bound of surface.rs, (2/π)·ln(n + 1) + 1, against the Lebesgue constant of the
/// Lobatto points computed directly: max over t of Σ_k |ℓ_k(t)| on a fine grid (a lower estimate
/// of the maximum, so the bound must lie above it; ATAP Theorem 15.2 says it lies above the true
/// maximum; it is also close, within 0.25 for n ≥ 4, so the estimates built on it are not loose).
#[test]
fn lebesgue_bound_holds_at_the_lobatto_points() {
    for n in [2usize, 4, 5, 6, 8, 16, 32] {
        let t: Vec<f64> = (0..=n).map(|k| (PI * k as f64 / n as f64).cos()).collect();
        let mut big = 0.0f64;
        for i in 0..=4000 {
            let x = -1.0 + 2.0 * i as f64 / 4000.0;
            let sum: f64 = (0..=n)
                .map(|k| {
                    (0..=n)
                        .filter(|&m| m != k)
                        .map(|m| (x - t[m]) / (t[k] - t[m]))
                        .product::<f64>()
                        .abs()
                })
                .sum();
            big = big.max(sum);
        }
        eprintln!("n = {n}: Λ ≥ {big:.4}, bound {:.4}", lebesgue(n));
        assert!(
            big <= lebesgue(n) && (n < 4 || lebesgue(n) - big < 0.25),
            "n = {n}: {big} vs bound {}",
            lebesgue(n)
        );
    }
}

/// The start degree in η: the lowest whose predicted tail meets tol/10 (surface.rs) — 4 for a
/// factor 2 in η at 1e−3 (w = 0.69, ρ ≈ 10: tail from c₃ ≈ 1e−4), 6 for a factor 5 (w = 1.6,
/// ρ ≈ 4.3: from c₅), more for a finer tolerance, and never above the largest degree.
#[test]
fn eta_start_degree_follows_width_and_tolerance() {
    assert_eq!(eta_start_degree(2f64.ln(), 1e-3), 4);
    assert_eq!(eta_start_degree(5f64.ln(), 1e-3), 6);
    assert!(eta_start_degree(2f64.ln(), 1e-6) > 4);
    assert!(eta_start_degree(10.0, 1e-10) <= 16);
}

/// Every distinct grid point is solved once: three panels side by side in ln s (panels of one
/// decade over three, no halving with a largest degree of 64) share their edges, and doubling keeps
/// the nodes, so the solves equal the distinct points of the final grids.
#[test]
fn every_distinct_node_is_solved_once() {
    let c = creep();
    let p = CoveredProblem::new(&c, None, 5e-3).unwrap();
    let settings = MapSettings {
        panel_width: std::f64::consts::LN_10,
        max_degree: 64,
        ..MapSettings::covered(1e-3)
    };
    let x0 = (1e-3f64).ln();
    let s = CoveredSurface::build(
        &p,
        (x0, x0 + 3.0 * std::f64::consts::LN_10),
        (0.5, 1.0),
        &settings,
    )
    .unwrap();
    let mut points = std::collections::HashSet::new();
    for ([a, b, c, d], (nx, ny)) in s.panel_shapes() {
        for j in 0..=nx {
            for k in 0..=ny {
                points.insert((
                    super::surface::lobatto(a, b, j, nx).to_bits(),
                    super::surface::lobatto(c, d, k, ny).to_bits(),
                ));
            }
        }
    }
    assert_eq!(s.panels(), 3);
    let grids: usize = s
        .panel_shapes()
        .iter()
        .map(|(_, (nx, ny))| (nx + 1) * (ny + 1))
        .sum();
    assert_eq!(s.solves, points.len());
    assert!(s.solves < grids, "{} solves, {grids} grid points", s.solves);
}
