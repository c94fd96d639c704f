//! A 100-compound library through the main job (issue 16 item 4; goal ≤ 60 s on 2 cores): synthetic
//! DMA exports from the test-data module (viscoroll::testdata::realistic, the four known-truth
//! rubbers of tests/known_truth.rs, each with 25 noise seeds of its default protocol: 33 isotherms
//! × 13 frequencies, 1 % / 3 % noise, ±1.5 K drift), written as CSV files into one folder and run
//! as `viscoroll run` runs it (every fit made: a fresh output folder), with the shipped scenes, in a
//! 2-thread pool. Prints a table: with bands (the default) and, unless `--bands-only`, with
//! `--no-bands`. Run: `cargo bench --bench library` (`-- --n 20` for a smaller library).
//!
//! `-- --profile K`: instead, the main job's stages one by one on the first K compounds of the
//! library, in a 1-thread pool (so wall time = CPU time): master curve + fit, the bands' ensemble,
//! and per scene the friction table, its bands and its maps (with the maps' node solves); prints
//! the CPU seconds per compound of each (the report writing is the rest of the run's time). All
//! through the public API (issue 30): the bands of each scene by `bands::scene_bands_given` with
//! the friction table's solves handed on as the main job does; the replicates' half-space ratios,
//! which the main job shares between scenes with the same roll, are crate-internal, so here each
//! scene's bands solve their own (a covered scene's bands row includes its half-space solves).

use std::path::Path;
use std::time::Instant;
use viscoroll::contact::{AutoSettings, Body, ContactSettings, Scheme};
use viscoroll::pipeline::{
    friction_maps, friction_vs_temperature, pipeline_map_settings, run_all, RunOptions,
};
use viscoroll::testdata::{dma_csv, dma_rows, realistic_compounds, DmaProtocol};

#[path = "support/cpu.rs"]
mod cpu;
use cpu::cpu_s;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args
        .iter()
        .position(|a| a == "--n")
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(100);
    let bands_only = args.iter().any(|a| a == "--bands-only");
    let profile: Option<usize> = args
        .iter()
        .position(|a| a == "--profile")
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok());
    let root = std::env::temp_dir().join(format!("viscoroll-bench-library-{}", std::process::id()));
    let input = root.join("compounds");
    std::fs::create_dir_all(&input).expect("a temp folder");
    let bases = realistic_compounds();
    let t0 = Instant::now();
    for k in 0..n {
        let base = &bases[k % bases.len()];
        let protocol = DmaProtocol {
            seed: 1000 + k as u64,
            ..DmaProtocol::default()
        };
        let path = input.join(format!("{}-{:03}.csv", base.name, k));
        std::fs::write(&path, dma_csv(&dma_rows(base, &protocol))).expect("write an export");
    }
    println!(
        "library: {n} compounds written in {:.1} s",
        t0.elapsed().as_secs_f64()
    );
    if let Some(k) = profile {
        profile_stages(&input, &root, k.min(n));
        let _ = std::fs::remove_dir_all(&root);
        return;
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .expect("a 2-thread pool");
    println!(
        "| bands | compounds | failed | not trusted | wall (s) | per compound (s) | CPU (s) | CPU per compound (s) |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|");
    for bands in [true, false] {
        if !bands && bands_only {
            continue;
        }
        let out = root.join(format!("out-{bands}"));
        let mut opts = RunOptions::for_folder(&input, &out, None, None).expect("options");
        if !bands {
            opts.bands = None;
        }
        let (t, c0) = (Instant::now(), cpu_s());
        let summary = pool.install(|| run_all(&opts, &|_| {})).expect("the run");
        let s = t.elapsed().as_secs_f64();
        let cpu = cpu_s() - c0;
        println!(
            "| {} | {} | {} | {} | {s:.1} | {:.2} | {cpu:.1} | {:.2} |",
            if bands { "yes" } else { "no (--no-bands)" },
            summary.compounds.len(),
            summary.failures(),
            summary.untrusted(),
            s / n as f64,
            cpu / n as f64
        );
    }
    let _ = std::fs::remove_dir_all(&root);
}

/// The main job's stages on the first `k` compounds of `input`, one thread, CPU seconds per
/// compound of each (module doc).
fn profile_stages(input: &Path, root: &Path, k: usize) {
    let opts =
        RunOptions::for_folder(input, &root.join("out-profile"), None, None).expect("options");
    let bs = opts.bands.clone().expect("bands on by default");
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a 1-thread pool");
    let mut files: Vec<_> = std::fs::read_dir(input)
        .expect("the library folder")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .collect();
    files.sort();
    // (stage, CPU s summed over compounds, count of solves summed)
    let mut rows: Vec<(String, f64, usize)> = Vec::new();
    let mut add = |name: String, t: f64, solves: usize| match rows.iter_mut().find(|r| r.0 == name)
    {
        Some(r) => {
            r.1 += t;
            r.2 += solves;
        }
        None => rows.push((name, t, solves)),
    };
    // the main job's contact settings (crate::pipeline's): auto, no gap check
    let contact = ContactSettings {
        scheme: Scheme::Auto,
        auto: AutoSettings {
            gap_check: false,
            ..AutoSettings::default()
        },
        ..ContactSettings::default()
    };
    let map_settings = pipeline_map_settings();
    pool.install(|| {
        for f in files.iter().take(k) {
            let name = f.file_stem().and_then(|s| s.to_str()).unwrap_or("c");
            let c0 = cpu_s();
            let m = viscoroll::dma::read_files(std::slice::from_ref(f), &Default::default())
                .expect("reads");
            let (mut fit, master) =
                viscoroll::pipeline::fit_measurement_master(name, &m, &opts.fit).expect("fits");
            let c1 = cpu_s();
            add("read + master curve + fit".into(), c1 - c0, 0);
            fit.bands = viscoroll::bands::build_ensemble(&master, &m, &fit, &bs).ok();
            let c2 = cpu_s();
            add("bands: ensemble (refits)".into(), c2 - c1, 0);
            for spec in &opts.scenes.scene {
                let body = if spec.cover_thickness_mm.is_some() {
                    "cover"
                } else {
                    "half-space"
                };
                let c0 = cpu_s();
                let points = friction_vs_temperature(&fit, spec, &contact).expect("table");
                let c1 = cpu_s();
                add(
                    format!("{} ({body}): friction table", spec.name),
                    c1 - c0,
                    points.len(),
                );
                if let Some(e) = fit.bands.as_ref() {
                    // as the main job hands them on (crate::pipeline::run)
                    let nominal: Vec<(f64, f64, Option<Body>)> = points
                        .iter()
                        .map(|p| {
                            let body = [
                                Body::HALF_SPACE,
                                Body::Layer {
                                    thickness_m: f64::NAN,
                                },
                                Body::Winkler { height_m: f64::NAN },
                            ]
                            .into_iter()
                            .find(|m| m.name() == p.model);
                            (p.friction, p.contact_length_mm * 1e-3, body)
                        })
                        .collect();
                    viscoroll::bands::scene_bands_given(
                        &fit,
                        e,
                        &spec.scene(),
                        &spec.temps_c,
                        &bs,
                        &nominal,
                        None,
                    );
                }
                let c2 = cpu_s();
                add(format!("{} ({body}): bands", spec.name), c2 - c1, 0);
                if !spec.map_temps_c.is_empty() {
                    let maps = friction_maps(&fit, spec, &map_settings).expect("maps");
                    add(
                        format!("{} ({body}): maps", spec.name),
                        cpu_s() - c2,
                        maps.solves,
                    );
                }
            }
        }
    });
    println!("profile: {k} compounds, 1 thread; CPU s per compound (solves per compound)\n");
    println!("| stage | CPU per compound (s) | solves per compound |\n|---|---:|---:|");
    let total: f64 = rows.iter().map(|r| r.1).sum();
    for (name, t, solves) in &rows {
        println!(
            "| {name} | {:.3} | {} |",
            t / k as f64,
            if *solves > 0 {
                format!("{:.0}", *solves as f64 / k as f64)
            } else {
                String::new()
            }
        );
    }
    println!(
        "| total (without the reports) | {:.3} | |",
        total / k as f64
    );
}
