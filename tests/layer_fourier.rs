//! The bonded layer through the public seam `contact::roll` against an elastic contact solved here
//! by another method: an FFT solution on a periodic grid (issue 30, item 7). Nothing of
//! `src/contact` is used for the reference; only the problem statement (docs/MATH.md §1.1) is shared.
//!
//! **The problem.** Plane strain, frictionless: a rigid roll of radius R under a load N per unit
//! width on an elastic layer of thickness h, Young's modulus E and Poisson's ratio ν, bonded to a
//! rigid base. The gap g(x) = x²/(2R) − δ + u(x) ≥ 0, the pressure p ≥ 0, p·g = 0, ∫p dx = N,
//! u the surface's deflection into the layer.
//!
//! **The layer's surface compliance, derived here.** z points into the layer (surface z = 0, base
//! z = h). For a load p cos kx take the Airy function φ = f(z) cos kx with f⁗ − 2k²f″ + k⁴f = 0, so
//! σ_xx = f″cos kx, σ_zz = −k²f cos kx, σ_xz = k f′ sin kx; plane-strain Hooke's law integrated gives
//! u_x = [(1−ν)f″ + νk²f] sin kx/(2μk) and u_z = [(1−ν)f‴ − (2−ν)k²f′] cos kx/(2μk²) (the shear
//! strain fixes u_z; its z-derivative is ε_zz by the biharmonic equation). With s = kz, t = kh,
//! f = (p/k²)·g(s), g = (1 + Bs) cosh s + (−B + Ds) sinh s satisfies σ_zz = −p cos kx and σ_xz = 0 at
//! s = 0; the bonded base, u_x = u_z = 0 at s = t, reads
//!
//!   B[t ch + a sh] + D[c ch + t sh] = −ch,   B[c ch − t sh] + D[a sh − t ch] = sh,
//!
//! with ch = cosh t, sh = sinh t, a = 1 − 2ν, c = 2(1 − ν). The surface deflection is
//! u_z(0) = ((1 − ν)/μ)(p/k)·B, so the compliance is
//!
//!   C(k) = 2(1 − ν²)/(E|k|) · F(|k|h),
//!   F(t) = B = (κ sinh 2t − 2t)/(κ cosh 2t + 2t² + (1 + κ²)/2),   κ = 3 − 4ν = a + c.
//!
//! It is the function of the layer on a rigid base in the literature (Meijers 1968, Appl. Sci. Res.
//! 18, 353; Johnson, Contact Mechanics, 1985, §5.9 for the thin limits) and of docs/MATH.md §14.2.
//! Its limits (checked in `bonded_layer_factor_has_its_limits`): F → 1 as t → ∞ (half-space,
//! C = 2(1 − ν²)/(E|k|)); F ≈ t(1 − 2ν)/(2(1 − ν)²) for t → 0 and ν < ½ (a Winkler bed of
//! constrained columns, C(0) = h(1 + ν)(1 − 2ν)/(E(1 − ν))); F ≈ 2t³/3 for ν = ½ (C ≈ k²h³/(3μ), the
//! thin incompressible layer u = −(h³/(3μ))p″ of Johnson §5.9).
//!
//! **The reference solver.** Period L, n = 2^m nodes x_j = (j − n/2)·L/n (a node at the roll's
//! lowest point), u = IDFT(C(k_m)·DFT(p)) with k_m the DFT's wavenumbers (a radix-2 FFT written
//! below); C(0) is irrelevant (a uniform deflection is absorbed in δ). The pressure is found by the
//! constrained conjugate gradient of Polonsky & Keer (Wear 231, 1999, 206–219): conjugate directions
//! on the contact set, nodes of negative gap and no pressure re-admitted, the load restored by
//! scaling after each step, until the pressure changes by < 1e−10·N. The period is ≥ 5 l and
//! ≥ 20 h: the layer's kernel decays like e^(−0.74|x|/h) (0.74 = the root of cos y = y, the first
//! zero of F's denominator on the imaginary axis at ν = ½); measured at h/l = 1, a period of 11 h
//! moves the peak by 9e−6 against 22 h. At h/l ≈ 5 the period is 8 h (= 39 l; 5 h and 10 h differ
//! by 3e−5 in the peak, 8 h and 10 h by < 3e−6). The contact length is twice the root of a
//! least-squares quadratic through p² over the outer nodes of the contact (the outer 10 %, at most
//! h/10 wide, at least 8 nodes, the last node but one and the last left out: the spectral solution
//! rings there), because p ∝ √(distance to the edge) at every edge of a body that is locally a
//! half-space; wider windows reach into the thin layer's interior and bias l by up to 2e−3.
//!
//! **Its accuracy.** `grid_convergence` (`#[ignore]`d, 11 s) prints each case at the test's grid
//! and at half and double its spacing. Halving the spacing from the test's grid (800–3300 nodes
//! over the contact) moves l by ≤ 3.0e−5 (from the coarser grid ≤ 7.1e−5) and the peak by
//! ≤ 4.2e−7 (≤ 1.4e−6): first order or better in the spacing for l (the edge's ringing), faster for
//! the peak. On Hertz's half-space (`reference_matches_hertz`, period 20 l) the solver is within
//! 5e−4, the periodic images' bias; on a period of 80 l, l is within 1e−4 at 200 nodes over the
//! contact and 6e−5 at 400, the peak within 3e−5, the images' bias (measured while writing this).
//!
//! **The comparison** (`layer_through_roll_matches_the_fourier_reference`). `contact::roll` with a
//! standard linear solid rolling so fast against its retardation time (V·τ ≫ l) that it is elastic
//! with E_g, as in tests/body_seam.rs, on `Body::Layer { thickness_m: h }` at h/l = 0.039, 0.171,
//! 0.995 and 4.88 for ν = ½ (the first is the thin incompressible layer that tests/body_seam.rs
//! cannot test through its h³ law) and 0.125 and 0.888 for ν = 0.3. Measured differences, l / peak
//! pressure / p(±l/4) in units of the peak: 1.3e−5 / 6e−8 / 8e−8, 2.4e−5 / 1e−7 / 6e−8,
//! 2.6e−5 / 3.0e−7 / 1.4e−6, 1.3e−5 / 3.1e−6 / 2.2e−6; ν = 0.3: 2.4e−6 / 5e−8 / 2.8e−7,
//! 9.8e−6 / 9e−9 / 1.0e−6. Tolerances 1e−4, 1e−5, 1e−4 (at `LENGTH_TOL`).
//!
//! **A cover 1 % thicker** handed to `roll` (injected once, reverted) fails 16 of the 18 checks: l
//! is off by 5.5e−3, 4.4e−3, 1.6e−3, 9.1e−5 (ν = ½, h/l from thin to thick) and 3.1e−3, 1.4e−3
//! (ν = 0.3); the peak by −5.8e−3, −4.9e−3, −1.8e−3, −1.0e−4 and −3.4e−3, −1.5e−3; only at
//! h/l = 4.88 do l and p(±l/4) (5.8e−5) stay inside their tolerances, where the peak still fails.
//! A load 1 % higher fails all 18 (l off by 2.2e−3 to 4.9e−3, the peak by 5.0e−3 to 7.9e−3), a
//! radius 1 % larger 17 (l and the peak off by ≥ 2.1e−3; p(±l/4) of the thinnest layer moves by
//! only 1.6e−5). The speed does not enter an elastic limit: tests/body_seam.rs checks it.

use std::f64::consts::PI;

use viscoroll::contact::{roll, Body, ContactSettings, Scene};
use viscoroll::creep::relaxation_to_creep;
use viscoroll::prony::{RelaxationSpectrum, RelaxationTerm};
use viscoroll::ModulusKind;

const RADIUS_M: f64 = 0.1;
const LOAD_N_PER_M: f64 = 1000.0;
/// Glassy tensile modulus (the elastic limit compared) and relaxed one, Pa.
const E_GLASSY_PA: f64 = 1e7;
const E_RELAXED_PA: f64 = 2e6;

/// In-place radix-2 FFT of (re, im), n a power of two; `inverse` takes e^(+2πijm/n) and divides
/// by n. `w` holds e^(−2πik/n), k < n/2.
fn fft(re: &mut [f64], im: &mut [f64], w: &[(f64, f64)], inverse: bool) {
    let n = re.len();
    let mut j = 0;
    for i in 1..n {
        let mut bit = n >> 1;
        while j & bit != 0 {
            j ^= bit;
            bit >>= 1;
        }
        j |= bit;
        if i < j {
            re.swap(i, j);
            im.swap(i, j);
        }
    }
    let sign = if inverse { -1.0 } else { 1.0 };
    let mut len = 2;
    while len <= n {
        let half = len / 2;
        let stride = n / len;
        for start in (0..n).step_by(len) {
            for k in 0..half {
                let (wr, wi) = w[k * stride];
                let wi = sign * wi;
                let (a, b) = (start + k, start + k + half);
                let (xr, xi) = (re[b] * wr - im[b] * wi, re[b] * wi + im[b] * wr);
                re[b] = re[a] - xr;
                im[b] = im[a] - xi;
                re[a] += xr;
                im[a] += xi;
            }
        }
        len *= 2;
    }
    if inverse {
        let s = 1.0 / n as f64;
        re.iter_mut().chain(im.iter_mut()).for_each(|v| *v *= s);
    }
}

/// The bonded layer's factor F(t), t = |k|h (module doc); written in e^(−2t) above t = 1.
fn layer_factor(t: f64, nu: f64) -> f64 {
    let kappa = 3.0 - 4.0 * nu;
    let c = (1.0 + kappa * kappa) / 2.0;
    if t < 1.0 {
        (kappa * (2.0 * t).sinh() - 2.0 * t) / (kappa * (2.0 * t).cosh() + 2.0 * t * t + c)
    } else {
        let e2 = (-2.0 * t).exp();
        let num = -kappa * (-4.0 * t).exp_m1() / 2.0 - 2.0 * t * e2;
        let den = kappa * (1.0 + e2 * e2) / 2.0 + (2.0 * t * t + c) * e2;
        num / den
    }
}

/// An elastic body of the reference: a bonded layer of thickness h, or the half-space (None).
#[derive(Clone, Copy, Debug)]
struct Elastic {
    e_pa: f64,
    nu: f64,
    thickness_m: Option<f64>,
}

/// The reference's solution.
struct Reference {
    contact_length_m: f64,
    peak_pa: f64,
    dx_m: f64,
    x0_m: f64,
    p_pa: Vec<f64>,
}

impl Reference {
    /// Linear interpolation of the pressure at `x_m`.
    fn pressure_at(&self, x_m: f64) -> f64 {
        let f = (x_m - self.x0_m) / self.dx_m;
        let i = f.floor() as usize;
        let w = f - i as f64;
        self.p_pa[i] * (1.0 - w) + self.p_pa[i + 1] * w
    }
}

impl Elastic {
    /// Surface compliance C(k) in m²/N per unit width: û = C·p̂.
    fn compliance(&self, k: f64) -> f64 {
        let k = k.abs();
        if k == 0.0 {
            return 0.0; // a uniform deflection: absorbed in the approach δ
        }
        let c = 2.0 * (1.0 - self.nu * self.nu) / (self.e_pa * k);
        match self.thickness_m {
            None => c,
            Some(h) => c * layer_factor(k * h, self.nu),
        }
    }

    /// The roll's contact on a period `period_m` with n nodes (module doc).
    fn solve(&self, period_m: f64, n: usize) -> Reference {
        assert!(n.is_power_of_two());
        let dx = period_m / n as f64;
        let x: Vec<f64> = (0..n).map(|j| (j as f64 - (n / 2) as f64) * dx).collect();
        let w: Vec<(f64, f64)> = (0..n / 2)
            .map(|k| {
                let a = -2.0 * PI * k as f64 / n as f64;
                (a.cos(), a.sin())
            })
            .collect();
        let kernel: Vec<f64> = (0..n)
            .map(|m| {
                let m = if m <= n / 2 {
                    m as f64
                } else {
                    m as f64 - n as f64
                };
                self.compliance(2.0 * PI * m / period_m)
            })
            .collect();
        let (mut re, mut im) = (vec![0.0; n], vec![0.0; n]);
        let mut convolve = |f: &[f64]| -> Vec<f64> {
            re.copy_from_slice(f);
            im.iter_mut().for_each(|v| *v = 0.0);
            fft(&mut re, &mut im, &w, false);
            for ((r, i), c) in re.iter_mut().zip(im.iter_mut()).zip(&kernel) {
                *r *= c;
                *i *= c;
            }
            fft(&mut re, &mut im, &w, true);
            re.clone()
        };
        let roll: Vec<f64> = x.iter().map(|x| x * x / (2.0 * RADIUS_M)).collect();
        // start from a uniform pressure over a twentieth of the period
        let mut p: Vec<f64> = x
            .iter()
            .map(|&x| f64::from(u8::from(x.abs() < period_m / 40.0)))
            .collect();
        let scale = LOAD_N_PER_M / (p.iter().sum::<f64>() * dx);
        p.iter_mut().for_each(|v| *v *= scale);
        let mut t = vec![0.0; n];
        let (mut g_old, mut conjugate) = (1.0, false);
        for iteration in 0.. {
            assert!(iteration < 2000, "the reference does not converge");
            let u = convolve(&p);
            let active: Vec<usize> = (0..n).filter(|&i| p[i] > 0.0).collect();
            let mut gap: Vec<f64> = u.iter().zip(&roll).map(|(u, z)| u + z).collect();
            let mean = active.iter().map(|&i| gap[i]).sum::<f64>() / active.len() as f64;
            gap.iter_mut().for_each(|g| *g -= mean);
            let g_norm: f64 = active.iter().map(|&i| gap[i] * gap[i]).sum();
            let beta = if conjugate { g_norm / g_old } else { 0.0 };
            g_old = g_norm;
            let mut direction = vec![0.0; n];
            for &i in &active {
                direction[i] = gap[i] + beta * t[i];
            }
            t = direction;
            let r = convolve(&t);
            let r_mean = active.iter().map(|&i| r[i]).sum::<f64>() / active.len() as f64;
            let gt: f64 = active.iter().map(|&i| gap[i] * t[i]).sum();
            let rt: f64 = active.iter().map(|&i| (r[i] - r_mean) * t[i]).sum();
            let step = gt / rt;
            let p_old = p.clone();
            for &i in &active {
                p[i] = (p[i] - step * t[i]).max(0.0);
            }
            conjugate = true;
            for i in 0..n {
                if p_old[i] == 0.0 && gap[i] < 0.0 {
                    p[i] = -step * gap[i];
                    conjugate = false;
                }
            }
            let scale = LOAD_N_PER_M / (p.iter().sum::<f64>() * dx);
            p.iter_mut().for_each(|v| *v *= scale);
            let change: f64 = p
                .iter()
                .zip(&p_old)
                .map(|(a, b)| (a - b).abs())
                .sum::<f64>()
                * dx;
            if change < 1e-10 * LOAD_N_PER_M {
                break;
            }
        }
        let centre = n / 2;
        let mut last = centre;
        while p[last + 1] > 0.0 {
            last += 1;
        }
        let width = (last - centre) / 10;
        let width = self
            .thickness_m
            .map_or(width, |h| width.min((h / (10.0 * dx)) as usize))
            .max(8);
        let edge = edge_root(
            &x[last - width..=last - 2],
            &p[last - width..=last - 2],
            x[last],
        );
        Reference {
            contact_length_m: 2.0 * edge,
            peak_pa: p[centre],
            dx_m: dx,
            x0_m: x[0],
            p_pa: p,
        }
    }
}

/// The root next to `near` of the least-squares quadratic through (x, p²) (in the variable
/// (x − near)/span, span the window's width, for conditioning).
fn edge_root(x: &[f64], p: &[f64], near: f64) -> f64 {
    let span = near - x[0];
    let mut a = [[0.0; 3]; 3];
    let mut b = [0.0; 3];
    for (&xi, &pi) in x.iter().zip(p) {
        let v = (xi - near) / span;
        let phi = [1.0, v, v * v];
        for (r, row) in a.iter_mut().enumerate() {
            b[r] += phi[r] * pi * pi;
            for (arc, pc) in row.iter_mut().zip(&phi) {
                *arc += phi[r] * pc;
            }
        }
    }
    for k in 0..3 {
        let pivot = a[k];
        for r in k + 1..3 {
            let f = a[r][k] / pivot[k];
            for (arc, pc) in a[r].iter_mut().zip(&pivot).skip(k) {
                *arc -= f * pc;
            }
            b[r] -= f * b[k];
        }
    }
    let mut q = [0.0; 3];
    for r in (0..3).rev() {
        let s: f64 = (r + 1..3).map(|c| a[r][c] * q[c]).sum();
        q[r] = (b[r] - s) / a[r][r];
    }
    let mut v = -q[0] / q[1];
    for _ in 0..30 {
        v -= (q[0] + q[1] * v + q[2] * v * v) / (q[1] + 2.0 * q[2] * v);
    }
    near + v * span
}

/// One compared case: Poisson's ratio, thickness (m) and the grid (period in m, log2 n).
struct Case {
    nu: f64,
    thickness_m: f64,
    period_m: f64,
    log2_n: u32,
}

/// h/l ≈ 0.05, 0.2, 1, 5 at ν = ½, 0.2 and 1 at ν = 0.3 (l from the reference).
const CASES: [Case; 6] = [
    Case {
        nu: 0.5,
        thickness_m: 2e-5,
        period_m: 2.5e-3,
        log2_n: 14,
    },
    Case {
        nu: 0.5,
        thickness_m: 4e-4,
        period_m: 1.2e-2,
        log2_n: 13,
    },
    Case {
        nu: 0.5,
        thickness_m: 5.5e-3,
        period_m: 0.12,
        log2_n: 14,
    },
    Case {
        nu: 0.5,
        thickness_m: 3e-2,
        period_m: 0.24,
        log2_n: 15,
    },
    Case {
        nu: 0.3,
        thickness_m: 4e-4,
        period_m: 1.6e-2,
        log2_n: 13,
    },
    Case {
        nu: 0.3,
        thickness_m: 5.5e-3,
        period_m: 0.12,
        log2_n: 14,
    },
];

impl Case {
    fn reference(&self, refine: i32) -> Reference {
        let body = Elastic {
            e_pa: E_GLASSY_PA,
            nu: self.nu,
            thickness_m: Some(self.thickness_m),
        };
        body.solve(self.period_m, 1 << (self.log2_n as i32 + refine))
    }
}

/// What the comparison reads of `roll`'s solution.
struct Rolled {
    contact_length_m: f64,
    max_pressure_pa: f64,
    offset_m: f64,
    x_m: Vec<f64>,
    pressure_pa: Vec<f64>,
}

/// The roll on the layer at V = 1 m/s with a standard linear solid of relaxation time 1e6 s
/// (retardation 5e6 s): the compliance grows by (J∞ − J_g)/J_g · l/(Vτ) < 1e−8 while a point
/// crosses the contact, elastic with E_g.
fn rolled(case: &Case, thickness_m: f64) -> Rolled {
    let relaxation = RelaxationSpectrum {
        kind: ModulusKind::Tensile,
        poisson: case.nu,
        modulus_inf_pa: E_RELAXED_PA,
        terms: vec![RelaxationTerm {
            modulus_pa: E_GLASSY_PA - E_RELAXED_PA,
            tau_s: 1e6,
        }],
    };
    let (creep, _) = relaxation_to_creep(&relaxation).expect("a solid");
    let scene = Scene {
        radius_m: RADIUS_M,
        load_n_per_m: LOAD_N_PER_M,
        speed_m_s: 1.0,
        poisson: None,
        body: Body::Layer { thickness_m },
    };
    let r = roll(&scene, &creep, &ContactSettings::default()).expect("solves");
    Rolled {
        contact_length_m: r.contact_length_m,
        max_pressure_pa: r.max_pressure_pa,
        offset_m: r.offset_m,
        x_m: r.x_m,
        pressure_pa: r.pressure_pa,
    }
}

/// Linear interpolation in a profile (x increasing).
fn interpolate(x: &[f64], y: &[f64], at: f64) -> f64 {
    let i = x.partition_point(|&v| v <= at).clamp(1, x.len() - 1);
    let w = (at - x[i - 1]) / (x[i] - x[i - 1]);
    y[i - 1] * (1.0 - w) + y[i] * w
}

/// The factor F(t) has the limits of the module doc.
#[test]
fn bonded_layer_factor_has_its_limits() {
    for nu in [0.0, 0.3, 0.45, 0.5] {
        // half-space: 1 − F ≈ (2t² + …)·2e^(−2t)/κ, < 1e−12 at t = 20
        assert!((layer_factor(20.0, nu) - 1.0).abs() < 1e-12);
        // the two forms agree at t = 1
        let kappa = 3.0 - 4.0 * nu;
        let direct =
            (kappa * 2f64.sinh() - 2.0) / (kappa * 2f64.cosh() + 2.0 + (1.0 + kappa * kappa) / 2.0);
        assert!((layer_factor(1.0, nu) / direct - 1.0).abs() < 1e-14);
        // thin: the next term is O(t²) relative
        let t = 1e-4;
        let want = if nu < 0.5 {
            t * (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu).powi(2))
        } else {
            2.0 * t.powi(3) / 3.0
        };
        assert!((layer_factor(t, nu) / want - 1.0).abs() < 1e-6, "ν {nu}");
    }
}

/// The reference solver reproduces Hertz's half-space contact, l = 2√(4RN(1−ν²)/(πE)),
/// p₀ = 2N/(πa): within 1e−3 on a period of 20 l (the periodic images lower the peak by ≈ 5e−4,
/// measured; 1/16 of it on 80 l) with 400 nodes over the contact.
#[test]
fn reference_matches_hertz() {
    let body = Elastic {
        e_pa: E_GLASSY_PA,
        nu: 0.5,
        thickness_m: None,
    };
    let a = (4.0 * RADIUS_M * LOAD_N_PER_M * 0.75 / (PI * E_GLASSY_PA)).sqrt();
    let r = body.solve(40.0 * a, 1 << 13);
    let dl = r.contact_length_m / (2.0 * a) - 1.0;
    let dp = r.peak_pa / (2.0 * LOAD_N_PER_M / (PI * a)) - 1.0;
    println!("Hertz: l off by {dl:.1e}, p₀ off by {dp:.1e}");
    assert!(dl.abs() < 1e-3 && dp.abs() < 1e-3, "{dl:e} {dp:e}");
}

/// Prints each case's reference at half, the test's and double the resolution.
#[test]
#[ignore = "a measurement (≈ 30 s): cargo test --test tests grid_convergence -- --ignored --nocapture"]
fn grid_convergence() {
    for case in &CASES {
        let sols: Vec<Reference> = (-1..=1).map(|r| case.reference(r)).collect();
        let l = sols[1].contact_length_m;
        for (r, s) in (-1..=1).zip(&sols) {
            println!(
                "ν {} h {:e} m, h/l {:.3}, l/dx {:.0} (refine {r}): l {:.8e} m, peak {:.8e} Pa, p(l/4) {:.8e} Pa",
                case.nu,
                case.thickness_m,
                case.thickness_m / l,
                s.contact_length_m / s.dx_m,
                s.contact_length_m,
                s.peak_pa,
                s.pressure_at(l / 4.0)
            );
        }
    }
}

/// Tolerances (relative): the reference's grid error (`grid_convergence`: a halved spacing moves
/// l by ≤ 3e−5 and the peak by ≤ 4.2e−7) and period bias (< 3e−6), and `roll`'s tolerance 1e−6.
/// The profile at ±l/4 is read from `roll`'s 129 nodes by linear interpolation, whose error
/// (Δx)²p″/8 ≈ 6e−5 of the peak for a Hertz-like profile sets its tolerance.
const LENGTH_TOL: f64 = 1e-4;
const PEAK_TOL: f64 = 1e-5;
const PROFILE_TOL: f64 = 1e-4;

#[test]
fn layer_through_roll_matches_the_fourier_reference() {
    let mut failures = Vec::new();
    for case in &CASES {
        let reference = case.reference(0);
        let got = rolled(case, case.thickness_m);
        let l = reference.contact_length_m;
        let dl = got.contact_length_m / l - 1.0;
        let dp = got.max_pressure_pa / reference.peak_pa - 1.0;
        let quarter: Vec<f64> = [-0.25, 0.25]
            .iter()
            .map(|f| {
                let x = f * l;
                (interpolate(&got.x_m, &got.pressure_pa, x + got.offset_m)
                    - reference.pressure_at(x))
                    / reference.peak_pa
            })
            .collect();
        let line = format!(
            "ν {} h/l {:.3}: l {:.6e} m off by {dl:.1e}, peak {:.6e} Pa off by {dp:.1e}, p(∓l/4) off by {:.1e} {:.1e} of the peak",
            case.nu,
            case.thickness_m / l,
            l,
            reference.peak_pa,
            quarter[0],
            quarter[1],
        );
        println!("{line}");
        // a symmetric elastic contact: the roll's profile is centred
        assert!(
            got.offset_m.abs() < 1e-6 * l,
            "{line}: offset {:e} m",
            got.offset_m
        );
        if dl.abs() > LENGTH_TOL {
            failures.push(format!("{line}: contact length"));
        }
        if dp.abs() > PEAK_TOL {
            failures.push(format!("{line}: peak pressure"));
        }
        if quarter.iter().any(|q| q.abs() > PROFILE_TOL) {
            failures.push(format!("{line}: pressure at ±l/4"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
