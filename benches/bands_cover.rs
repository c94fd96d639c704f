//! Covered bands, cheap against full (issue 16, cost of the bands): on the shipped compounds
//! (data/), the covered scene's (conveyor-idler, 5 mm cover) replicate ratios by the full bootstrap
//! (every replicate solved on the cover, `scene_ratios_full_on`) and by the main job's estimate
//! (8 replicates on the cover, the rest from their half-space ratios by regression, eq. 15.6b,
//! `scene_ratios_on`): CPU time of each in a 2-thread pool, and per temperature the band's log
//! half-width ln(p95/p05)/2 and its median ln(p50/F) by both. Run:
//! `cargo bench --bench bands_cover`.

use std::time::Instant;
use viscoroll::bands::{
    band_of, build_ensemble, scene_ratios_full_on, scene_ratios_on, BandSettings,
};
use viscoroll::dma::{read_files, IngestOptions};
use viscoroll::pipeline::fit_compound::fit_measurement_master;
use viscoroll::pipeline::FitOptions;
use viscoroll::results::SceneSet;

#[path = "support/cpu.rs"]
mod cpu;
use cpu::cpu_s;

fn main() {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .expect("a 2-thread pool");
    pool.install(|| {
        let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data");
        let bs = BandSettings::default();
        let scenes = SceneSet::shipped();
        let spec = scenes
            .scene
            .iter()
            .find(|s| s.cover_thickness_mm.is_some())
            .expect("a shipped covered scene");
        let cover_m = spec.cover_thickness_mm.map(|h| h * 1e-3);
        let mut suite: Vec<String> = std::fs::read_dir(data.join("dmasuite-tensile"))
            .unwrap()
            .filter_map(|e| {
                let p = e.ok()?.path();
                (p.extension()? == "txt").then(|| p.display().to_string())
            })
            .collect();
        suite.sort();
        let sets = [
            (
                "ems-ca",
                vec![data
                    .join("pyvisco-ems-ca/freq_Eplexor_raw.xls")
                    .display()
                    .to_string()],
            ),
            ("dmasuite-tensile", suite),
            (
                "trios-aresg2-lims",
                vec![data
                    .join("trios-aresg2-lims/frequency_sweep_tts.txt")
                    .display()
                    .to_string()],
            ),
        ];
        println!(
            "scene {} ({} mm cover), 2 threads; half-width w = ln(p95/p05)/2, median m = ln(p50/F)",
            spec.name,
            spec.cover_thickness_mm.unwrap_or(f64::NAN)
        );
        println!(
            "{:<18} {:>6} {:>9} {:>9} {:>9} {:>9} {:>8}",
            "compound", "T °C", "w full", "w cheap", "m full", "m cheap", "w ratio"
        );
        let mut worst: f64 = 1.0;
        let mut best: f64 = 1.0;
        let mut costs = Vec::new();
        for (name, files) in sets {
            let m = read_files(&files, &IngestOptions::default()).unwrap();
            let (fit, master) = fit_measurement_master(name, &m, &FitOptions::default()).unwrap();
            let e = build_ensemble(&master, &m, &fit, &bs).unwrap();
            let (t, c) = (Instant::now(), cpu_s());
            let full = scene_ratios_full_on(&fit, &e, &spec.scene(), cover_m, &spec.temps_c, &bs);
            let (t_full, c_full) = (t.elapsed().as_secs_f64(), cpu_s() - c);
            let (t, c) = (Instant::now(), cpu_s());
            let cheap = scene_ratios_on(&fit, &e, &spec.scene(), cover_m, &spec.temps_c, &bs);
            let (t_cheap, c_cheap) = (t.elapsed().as_secs_f64(), cpu_s() - c);
            costs.push((name, t_full, c_full, t_cheap, c_cheap));
            for (i, temp) in spec.temps_c.iter().enumerate() {
                let (Some(a), Some(b)) = (band_of(1.0, &full[i]), band_of(1.0, &cheap[i])) else {
                    println!("{name:<18} {temp:>6} no band");
                    continue;
                };
                let (wa, wb) = ((a.p95 / a.p05).ln() / 2.0, (b.p95 / b.p05).ln() / 2.0);
                worst = worst.max(wb / wa);
                best = best.min(wb / wa);
                println!(
                    "{name:<18} {temp:>6} {wa:>9.4} {wb:>9.4} {:>+9.4} {:>+9.4} {:>8.2}",
                    a.p50.ln(),
                    b.p50.ln(),
                    wb / wa
                );
            }
        }
        println!("half-width cheap/full: {best:.2} … {worst:.2}");
        println!(
            "\n{:<18} {:>12} {:>12} {:>12} {:>12}",
            "compound", "full wall s", "full CPU s", "cheap wall s", "cheap CPU s"
        );
        for (name, a, b, c, d) in costs {
            println!("{name:<18} {a:>12.2} {b:>12.2} {c:>12.2} {d:>12.2}");
        }
    });
}
