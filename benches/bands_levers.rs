//! Levers on the cost of the bands' replicate solves (issue 16 item 4): on the first K compounds of
//! the synthetic library (as `cargo bench --bench library` writes them), the covered scene's
//! replicate solves on the cover and the half-space replicate solves, each at a few tolerances,
//! cold or warm-started from the fit's own solve; CPU per compound in one thread and the error of
//! the ratio F_b/F̂ against both solved at 1e−6 (layer) / 1e−8 (half-space). Run:
//! `cargo bench --bench bands_levers -- --k 4`.

use viscoroll::bands::friction::band_contact_settings;
use viscoroll::bands::{build_ensemble, BandSettings};
use viscoroll::contact::body::layer::collocation::contact_checks;
use viscoroll::contact::body::layer::{layer_at_load, LayerKernel, LayerSettings};
use viscoroll::contact::cover::roll_cover_from;
use viscoroll::contact::Body;
use viscoroll::contact::{roll, Scene};
use viscoroll::pipeline::RunOptions;
use viscoroll::testdata::{dma_csv, dma_rows, realistic_compounds, DmaProtocol};
use viscoroll::CreepSpectrum;

#[path = "support/cpu.rs"]
mod cpu;
use cpu::cpu_s;

fn shifted(c: &CreepSpectrum, log10_a_t: f64) -> CreepSpectrum {
    let a = 10f64.powf(log10_a_t);
    let mut s = c.clone();
    for t in &mut s.terms {
        t.tau_s *= a;
    }
    s
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let k: usize = args
        .iter()
        .position(|a| a == "--k")
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(4);
    let hs_only = args.iter().any(|a| a == "--hs-only");
    let checks = args.iter().any(|a| a == "--checks");
    let mut check_cpu = (0.0, 0.0, 0.0);
    let root = std::env::temp_dir().join(format!("viscoroll-bench-levers-{}", std::process::id()));
    let input = root.join("compounds");
    std::fs::create_dir_all(&input).expect("a temp folder");
    let bases = realistic_compounds();
    for j in 0..k {
        let base = &bases[j % bases.len()];
        let protocol = DmaProtocol {
            seed: 1000 + j as u64,
            ..DmaProtocol::default()
        };
        let path = input.join(format!("{}-{:03}.csv", base.name, j));
        std::fs::write(&path, dma_csv(&dma_rows(base, &protocol))).expect("write an export");
    }
    let opts = RunOptions::for_folder(&input, &root.join("out"), None, None).expect("options");
    let bs = opts.bands.clone().unwrap_or_default();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a 1-thread pool");
    let mut files: Vec<_> = std::fs::read_dir(&input)
        .expect("the library folder")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .collect();
    files.sort();
    let spec = opts
        .scenes
        .scene
        .iter()
        .find(|s| s.cover_thickness_mm.is_some())
        .expect("a covered scene")
        .clone();
    let scene = Scene {
        body: viscoroll::contact::Body::HALF_SPACE,
        ..spec.scene()
    };
    let cover_m = spec.cover_thickness_mm.map(|h| h * 1e-3);
    // (name, tol, warm): covered variants; (name, tol): half-space variants
    let h_m = cover_m.expect("a cover");
    let (auto, layer) = (
        Body::Auto { thickness_m: h_m },
        Body::Layer { thickness_m: h_m },
    );
    let cov_variants: [(f64, bool, Body); 4] = [
        (1e-3, false, auto),
        (1e-3, true, auto),
        (1e-3, false, layer),
        (1e-3, true, layer),
    ];
    let hs_variants = [(1e-4, 200), (1e-4, 8), (1e-3, 8), (3e-3, 8), (1e-2, 8)];
    let mut cov_cpu = vec![0.0; cov_variants.len()];
    let mut cov_err: Vec<Vec<f64>> = vec![Vec::new(); cov_variants.len()];
    let mut cov_est: Vec<Vec<f64>> = vec![Vec::new(); cov_variants.len()];
    let mut hs_cpu = vec![0.0; hs_variants.len()];
    let mut hs_err: Vec<Vec<f64>> = vec![Vec::new(); hs_variants.len()];
    let mut hs_est: Vec<Vec<f64>> = vec![Vec::new(); hs_variants.len()];
    pool.install(|| {
        for f in files.iter().take(k) {
            let name = f.file_stem().and_then(|s| s.to_str()).unwrap_or("c");
            let m = viscoroll::dma::read_files(std::slice::from_ref(f), &Default::default())
                .expect("reads");
            let (fit, master) =
                viscoroll::pipeline::fit_measurement_master(name, &m, &opts.fit).expect("fits");
            let e = build_ensemble(&master, &m, &fit, &bs).expect("an ensemble");
            let creep = fit.creep.clone().expect("a creep spectrum");
            let law = &fit.shift_law;
            for &t in &spec.temps_c {
                let nominal = shifted(&creep, law.log10_a_t(t));
                let cov_with =
                    |c: &CreepSpectrum, tol: f64, start: Option<(f64, f64)>, choice: Body| {
                        roll_cover_from(
                            &Scene {
                                body: choice,
                                ..scene
                            },
                            c,
                            tol,
                            start,
                        )
                        .map(|r| (r.roll.friction, r.roll.contact_length_m, r.error_estimate))
                    };
                let cov = |c: &CreepSpectrum, tol: f64, start: Option<(f64, f64)>| {
                    cov_with(c, tol, start, auto)
                };
                let hs = |c: &CreepSpectrum, (tol, points): (f64, usize)| {
                    let mut cs = band_contact_settings(&BandSettings {
                        contact_tol: tol,
                        ..BandSettings::default()
                    });
                    cs.auto.profile_points = points;
                    roll(&scene, c, &cs).map(|r| {
                        (
                            r.friction,
                            r.dimensionless.error_estimate.unwrap_or(f64::NAN),
                        )
                    })
                };
                if checks {
                    // the share of a layer solve its closing contact checks take
                    for r in e.replicates.iter().take(8) {
                        let c = shifted(&r.creep, r.log10_a_t(law, t));
                        let p = scene.dimensionless(&c).expect("a scene");
                        let h = cover_m.unwrap() / p.length_scale_m;
                        let ls = LayerSettings {
                            tol: 1e-3,
                            n_max: 512,
                            ..LayerSettings::default()
                        };
                        let c0 = cpu_s();
                        let a = layer_at_load(&p.terms, p.load, h, p.poisson, &ls);
                        check_cpu.0 += cpu_s() - c0;
                        let Ok(a) = a else { continue };
                        let mut d = a.solution.clone();
                        d.n = d.pressure.len() - 1;
                        let c0 = cpu_s();
                        let kernel = LayerKernel::new(&p.terms, h, p.poisson).expect("a kernel");
                        let _ = std::hint::black_box(contact_checks(&kernel, &d));
                        check_cpu.1 += cpu_s() - c0;
                        // the same solve without them (`checks: false`, the bands' replicates)
                        let c0 = cpu_s();
                        let b = layer_at_load(
                            &p.terms,
                            p.load,
                            h,
                            p.poisson,
                            &LayerSettings {
                                checks: false,
                                ..ls
                            },
                        );
                        check_cpu.2 += cpu_s() - c0;
                        let b = b.expect("solves without the checks as with them");
                        assert_eq!(
                            b.solution.friction_rho.to_bits(),
                            a.solution.friction_rho.to_bits()
                        );
                    }
                    continue;
                }
                let Ok(nom_ref) = cov(&nominal, 1e-6, None) else {
                    continue;
                };
                let nom_hs_ref = hs(&nominal, (1e-8, 8)).expect("hs").0;
                // covered: the first 8 replicates
                for (vi, &(tol, warm, choice)) in cov_variants.iter().enumerate() {
                    if hs_only {
                        break;
                    }
                    let Ok(nom) = cov(&nominal, tol, None) else {
                        continue;
                    };
                    for r in e.replicates.iter().take(8) {
                        let c = shifted(&r.creep, r.log10_a_t(law, t));
                        let Ok(reference) = cov(&c, 1e-6, None) else {
                            continue;
                        };
                        let start = warm.then_some((nom.1, f64::NAN));
                        let c0 = cpu_s();
                        let got = cov_with(&c, tol, start, choice);
                        cov_cpu[vi] += cpu_s() - c0;
                        if let Ok(g) = got {
                            let err = ((g.0 / nom.0) / (reference.0 / nom_ref.0)).ln().abs();
                            cov_err[vi].push(err);
                            cov_est[vi].push(g.2);
                        }
                    }
                }
                let reps: Vec<(CreepSpectrum, f64)> = e
                    .replicates
                    .iter()
                    .map(|r| {
                        let c = shifted(&r.creep, r.log10_a_t(law, t));
                        let reference = hs(&c, (1e-8, 8)).expect("hs").0;
                        (c, reference)
                    })
                    .collect();
                for (vi, &v) in hs_variants.iter().enumerate() {
                    let nom = hs(&nominal, v).expect("hs");
                    let c0 = cpu_s();
                    let got: Vec<_> = reps.iter().map(|(c, _)| hs(c, v)).collect();
                    hs_cpu[vi] += cpu_s() - c0;
                    for (g, (_, reference)) in got.into_iter().zip(&reps) {
                        if let Ok((g, est)) = g {
                            hs_err[vi].push(((g / nom.0) / (reference / nom_hs_ref)).ln().abs());
                            hs_est[vi].push(est + nom.1);
                        }
                    }
                }
            }
        }
    });
    if checks {
        println!(
            "layer solves (8 replicates × temperatures, tol 1e-3): {:.3} s CPU per compound, of which \
             the closing contact checks (kernel + checks, timed again alone) {:.3} s; the same \
             solves without the checks (`checks: false`) {:.3} s",
            check_cpu.0 / k as f64,
            check_cpu.1 / k as f64,
            check_cpu.2 / k as f64
        );
        return;
    }
    let stats = |v: &[f64]| {
        let mut s = v.to_vec();
        s.sort_by(f64::total_cmp);
        let q = |p: f64| {
            s.get(((s.len() as f64 - 1.0) * p) as usize)
                .copied()
                .unwrap_or(f64::NAN)
        };
        (q(0.5), q(0.95), s.last().copied().unwrap_or(f64::NAN))
    };
    println!(
        "{k} compounds, scene {}; CPU per compound in one thread",
        spec.name
    );
    println!(
        "| covered 8 × {} | CPU s | ratio error median | p95 | max | estimate median | max |",
        spec.temps_c.len()
    );
    println!("|---|---:|---:|---:|---:|---:|---:|");
    for (vi, &(tol, warm, choice)) in cov_variants.iter().enumerate() {
        let (a, b, c) = stats(&cov_err[vi]);
        let (d, _, f) = stats(&cov_est[vi]);
        println!(
            "| tol {tol:.0e} {} {choice:?} | {:.3} | {a:.1e} | {b:.1e} | {c:.1e} | {d:.1e} | {f:.1e} |",
            if warm { "warm" } else { "cold" },
            cov_cpu[vi] / k as f64
        );
    }
    println!("\n| half-space 32 × {} | CPU s | ratio error median | p95 | max | estimate e_b + e_0 median | p95 | max |", spec.temps_c.len());
    println!("|---|---:|---:|---:|---:|---:|---:|---:|");
    for (vi, &(tol, points)) in hs_variants.iter().enumerate() {
        let (a, b, c) = stats(&hs_err[vi]);
        let (d, e, f) = stats(&hs_est[vi]);
        println!(
            "| tol {tol:.0e}, {points} profile points | {:.3} | {a:.1e} | {b:.1e} | {c:.1e} | {d:.1e} | {e:.1e} | {f:.1e} |",
            hs_cpu[vi] / k as f64
        );
    }
    let _ = std::fs::remove_dir_all(&root);
}
