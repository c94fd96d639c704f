//! Hand-written physical references for the tests that check friction in SI units (issue 19).
//!
//! Nothing here calls the project's scene conversion (`contact::scene`), its friction maps or its
//! relaxation → creep conversion: the standard linear solid's creep function, the thesis' §3.2
//! dimensionless groups and Hertz's line contact are written out again below, from the thesis and
//! textbook formulas, so that a wrong factor in the project's own conversion cannot cancel out.
//! The only library call is the exact one-term solution of the dimensionless problem
//! (`viscoroll::contact::exact`, checked to 1e-14 against a 30-digit mpmath evaluation in
//! src/contact/body/half_space/exact.rs, tests at its foot), which has no units in it.
//!
//! Standard linear solid (SLS). Relaxation M(t) = M∞ + (M₀ − M∞)e^(−t/τ_r) (M = E tensile or G shear).
//! Its creep compliance (Laplace: s·M̄(s)·s·J̄(s) = 1, one pole) is
//! J(t) = J_g + J₁(1 − e^(−t/τ_c)), J_g = 1/M₀, J_g + J₁ = 1/M∞, τ_c = τ_r·M₀/M∞ (Ferry,
//! *Viscoelastic Properties of Polymers*, ch. 3; Tschoegl 1989 §3.4).
//!
//! Dimensionless groups (thesis §3.2, eq. 3.8, 3.20–3.24), with the thesis' own choice T = τ₁ = τ_c:
//! μ₀ the glassy shear modulus (E₀/(2(1+ν)) for tensile data), ξ = x/(VT), ρ = R/(VT),
//! Q′ = ρ·((1−ν)/μ₀)·q/π, N′ = ρ·((1−ν)/μ₀)·(2/π)·N*/(VT), f = (J₁/J_g)(T/τ_c) = J₁/J_g, b = T/τ_c = 1,
//! F/N = (ρF/N)/ρ, contact length l = λ·VT, offset of the contact's centre ahead of the lowest point
//! (λ/2 − β)·VT.
//!
//! Hertz line contact (Johnson, *Contact Mechanics*, 1985, §4.3, eq. 4.45 and 4.46; plane strain):
//! half-width a = √(4N*R/(πE*)), peak pressure p₀ = 2N*/(πa), E* = E/(1−ν²) for a rigid roll.

pub use crate::sls::{Kind, Sls};
pub use crate::support::temp_dir;
use std::f64::consts::PI;
use viscoroll::contact::CreepTerm;
use viscoroll::contact::{one_term_at_load, OneTermExact};

/// A scene in SI units.
#[derive(Debug, Clone, Copy)]
pub struct SceneSi {
    pub radius_m: f64,
    pub load_n_per_m: f64,
    pub speed_m_s: f64,
}

/// What a roll on the SLS gives, in SI units.
#[derive(Debug, Clone)]
pub struct Expected {
    /// F*/N*.
    pub friction: f64,
    /// Contact length l in m.
    pub contact_length_m: f64,
    /// (λ/2 − β)·VT in m.
    pub offset_m: f64,
    /// Largest contact pressure in Pa.
    pub peak_pressure_pa: f64,
    /// The dimensionless solution at T = τ_c.
    pub sol: OneTermExact,
    /// V·T in m.
    pub vt_m: f64,
    /// q/Q′ = π/(ρ·C) in Pa.
    pub pressure_scale_pa: f64,
}

impl Expected {
    /// The contact pressure in Pa at x (m, from the roll's lowest point, positive toward the front
    /// edge): ξ = x/(VT) + β.
    pub fn pressure_pa(&self, x_m: f64) -> f64 {
        self.pressure_scale_pa * self.sol.pressure(x_m / self.vt_m + self.sol.beta)
    }
}

/// The exact answer for `sls` (its retardation time multiplied by `a_t`, a shift factor) in `scene`,
/// by the thesis' scaling with T = τ_c·a_T (module docs).
pub fn exact_sls(sls: &Sls, scene: &SceneSi, a_t: f64) -> Expected {
    let nu = sls.poisson;
    let t = sls.tau_creep_s() * a_t;
    let vt = scene.speed_m_s * t;
    let rho = scene.radius_m / vt;
    let c = (1.0 - nu) / sls.glassy_shear_pa(nu);
    let load = rho * c * (2.0 / PI) * scene.load_n_per_m / vt;
    let term = CreepTerm {
        f: sls.creep_strength_per_pa() * sls.glassy_pa,
        b: 1.0,
    };
    let sol = one_term_at_load(term, load).expect("exact one-term solution");
    // Largest Q′: a fine scan, then golden-section refinement around the best sample (Q′ is smooth
    // and has one maximum on the contact).
    let m = 4000;
    let (mut best, mut best_q) = (0usize, 0.0f64);
    for i in 1..m {
        let q = sol.pressure(sol.lambda * i as f64 / m as f64);
        if q > best_q {
            best = i;
            best_q = q;
        }
    }
    let (mut lo, mut hi) = (
        sol.lambda * (best - 1) as f64 / m as f64,
        sol.lambda * (best + 1) as f64 / m as f64,
    );
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..80 {
        let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if sol.pressure(x1) > sol.pressure(x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    let q_max = sol.pressure(0.5 * (lo + hi)).max(best_q);
    Expected {
        friction: sol.friction_rho / rho,
        contact_length_m: sol.lambda * vt,
        offset_m: (0.5 * sol.lambda - sol.beta) * vt,
        peak_pressure_pa: PI * q_max / (rho * c),
        sol,
        vt_m: vt,
        pressure_scale_pa: PI / (rho * c),
    }
}

/// Hertz line contact of a rigid roll on an elastic half-space of plane-strain modulus `e_star`:
/// (contact length 2a, peak pressure p₀) in (m, Pa).
pub fn hertz(scene: &SceneSi, e_star: f64) -> (f64, f64) {
    let a = (4.0 * scene.load_n_per_m * scene.radius_m / (PI * e_star)).sqrt();
    (2.0 * a, 2.0 * scene.load_n_per_m / (PI * a))
}

/// Relative difference a/b − 1.
pub fn rel(a: f64, b: f64) -> f64 {
    a / b - 1.0
}

/// The thesis scheme with Richardson's extrapolation R = 2X(1280) − X(640) at a given contact
/// length, through `viscoroll contact` (an independent discretisation: piecewise-linear
/// collocation, closed-form kernel, no mode reduction). Returns (N′, ρF/N) of R.
pub fn thesis_richardson(creep_arg: &str, lambda: f64) -> (f64, f64) {
    let solve = |n: usize| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_viscoroll"))
            .args([
                "contact",
                "--creep",
                creep_arg,
                "--lambda",
                &format!("{lambda:e}"),
                "--n",
                &n.to_string(),
                "--json",
            ])
            .output()
            .expect("binary runs");
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        (
            v["load"].as_f64().unwrap(),
            v["friction_rho"].as_f64().unwrap(),
        )
    };
    let (l1, f1) = solve(640);
    let (l2, f2) = solve(1280);
    (2.0 * l2 - l1, 2.0 * f2 - f1)
}

/// Rolling friction of a tensile or shear creep spectrum J(t) = J_g + ΣJᵢ(1 − e^(−t/τᵢ)) in a scene,
/// checked at a given contact length `contact_length_m` by [`thesis_richardson`], with the thesis'
/// §3.2 scaling written out (T = l/V, so λ = 1): ρ = R/l, C = (1−ν)/μ₀ (μ₀ = 1/(2(1+ν)J_g) for
/// tensile compliances, 1/J_g for shear), N′ = ρ·C·(2/π)·N*/l, fᵢ = (Jᵢ/J_g)(T/τᵢ), bᵢ = T/τᵢ.
/// Returns (F/N of R, N′ of R over the scene's N′ − 1): the second is 0 when the contact length is
/// the right one for the load (N′ grows like λ² near it).
pub fn friction_at_length(
    spectrum: &viscoroll::CreepSpectrum,
    poisson: f64,
    scene: &SceneSi,
    contact_length_m: f64,
) -> (f64, f64) {
    let jg = spectrum.compliance_glassy_per_pa;
    let mu0 = match spectrum.kind {
        viscoroll::ModulusKind::Tensile => 1.0 / (2.0 * (1.0 + poisson) * jg),
        viscoroll::ModulusKind::Shear => 1.0 / jg,
    };
    let c = (1.0 - poisson) / mu0;
    let l = contact_length_m;
    let t = l / scene.speed_m_s;
    let rho = scene.radius_m / l;
    let load = rho * c * (2.0 / PI) * scene.load_n_per_m / l;
    let creep_arg = spectrum
        .terms
        .iter()
        .map(|term| {
            let b = t / term.tau_s;
            format!("{:e}:{:e}", term.compliance_per_pa / jg * b, b)
        })
        .collect::<Vec<_>>()
        .join(",");
    let (load_r, friction_rho_r) = thesis_richardson(&creep_arg, 1.0);
    (friction_rho_r / rho, load_r / load - 1.0)
}

/// A one-compound folder through `viscoroll run`: a synthetic export of the first realistic compound
/// (17 isotherms, −60…100 °C) named `sls`, with `scenes_toml`; then the fit file's relaxation and
/// creep spectra replaced by `sls` and the job run again. The fit is reused (same inputs, same
/// settings), so every friction in the reports is the SLS's, shifted by the fit's own law. `extra`:
/// more `run` arguments. Returns (the temp folder to remove, the compound's reports folder).
pub fn job_on_sls(
    tag: &str,
    scenes_toml: &str,
    sls: &Sls,
    extra: &[&str],
) -> (std::path::PathBuf, std::path::PathBuf) {
    use crate::support::{json, viscoroll};
    use viscoroll::testdata::{dma_csv, dma_rows, realistic_compounds, DmaProtocol};
    let dir = temp_dir(tag);
    let input = dir.join("in");
    std::fs::create_dir_all(&input).unwrap();
    let protocol = DmaProtocol {
        temps_c: (0..=16).map(|i| -60.0 + 10.0 * i as f64).collect(),
        ..DmaProtocol::default()
    };
    std::fs::write(
        input.join("sls.csv"),
        dma_csv(&dma_rows(&realistic_compounds()[0], &protocol)),
    )
    .unwrap();
    let scenes = input.join("scenes.toml");
    std::fs::write(&scenes, scenes_toml).unwrap();
    let out = dir.join("out");
    let job = |expect: &str| {
        let mut args = vec![
            "run",
            input.to_str().unwrap(),
            "--scenes",
            scenes.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--json",
        ];
        args.extend_from_slice(extra);
        let v = json(&viscoroll(&args));
        assert!(
            v.to_string().contains(expect),
            "fit action {expect} expected: {v}"
        );
    };
    job("fitted");
    let fit_path = out.join("fits").join("sls.json");
    let mut fit: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&fit_path).unwrap()).unwrap();
    fit["creep"] = serde_json::from_str(&sls.creep_json()).unwrap();
    fit["relaxation"] = serde_json::json!({
        "kind": "tensile", "poisson": 0.5, "modulus_inf_pa": sls.relaxed_pa,
        "terms": [{"modulus_pa": sls.glassy_pa - sls.relaxed_pa, "tau_s": sls.tau_relax_s}]
    });
    std::fs::write(&fit_path, super::support::sealed_fit_json(fit)).unwrap();
    job("reused");
    let report = out.join("reports").join("sls");
    (dir, report)
}

/// The rows of a report CSV as header → cell maps.
pub fn csv_rows(path: &std::path::Path) -> Vec<std::collections::HashMap<String, String>> {
    let (head, rows) = crate::support::table(path);
    rows.into_iter()
        .map(|r| head.iter().cloned().zip(r).collect())
        .collect()
}
