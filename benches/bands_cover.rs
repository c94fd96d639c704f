//! Covered bands, cheap against full (issue 16, cost of the bands): on the shipped compounds
//! (data/), the covered scene's (conveyor-idler, 5 mm cover) replicate ratios by the full bootstrap
//! (every replicate solved on the cover, `scene_bands_by` with `CoverMode::Full`), by 8 replicates on the cover at
//! every temperature and the rest from their half-space ratios by regression (eq. 15.6b,
//! `CoverMode::EveryTemp`) and by the main job's estimate (the same 8 solved at every other
//! temperature and carried between them, eq. 15.6c, `scene_ratios_on`): CPU time of each in a
//! 2-thread pool, and per temperature the band's log half-width ln(p95/p05)/2 and its median
//! ln(p50/F) by each. Run: `cargo bench --bench bands_cover`.

use std::time::Instant;
use viscoroll::bands::{
    band_of, build_ensemble, scene_bands_by, scene_bands_on, BandSettings, CoverMode,
};
use viscoroll::dma::{read_files, IngestOptions};
use viscoroll::pipeline::fit_measurement_master;
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
            "{:<18} {:>6} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>7} {:>7} {:>8}",
            "compound", "T °C", "w full", "w every", "w main", "m full", "m every", "m main",
            "every/f", "main/f", "carried"
        );
        // (ratio of half-widths to the full's: every temperature, main job's) over the points
        // whose full half-width exceeds 0.01, and over all
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [0.0f64; 2];
        let mut lo_all = [f64::INFINITY; 2];
        let mut hi_all = [0.0f64; 2];
        let mut max_dm = [0.0f64; 2];
        let mut costs = Vec::new();
        for (name, files) in sets {
            let m = read_files(&files, &IngestOptions::default()).unwrap();
            let (fit, master) = fit_measurement_master(name, &m, &FitOptions::default()).unwrap();
            let e = build_ensemble(&master, &m, &fit, &bs).unwrap();
            let timed = |f: &dyn Fn() -> Vec<Vec<f64>>| {
                let (t, c) = (Instant::now(), cpu_s());
                let r = f();
                (r, t.elapsed().as_secs_f64(), cpu_s() - c)
            };
            let scene = spec.scene();
            let temps = &spec.temps_c;
            let (full, t_full, c_full) =
                timed(&|| scene_bands_by(&fit, &e, &scene, cover_m, temps, &bs, CoverMode::Full).ratios);
            let (every, t_every, c_every) =
                timed(&|| scene_bands_by(&fit, &e, &scene, cover_m, temps, &bs, CoverMode::EveryTemp).ratios);
            let (t, c) = (Instant::now(), cpu_s());
            let main_bands = scene_bands_on(&fit, &e, &scene, cover_m, temps, &bs);
            let (t_main, c_main) = (t.elapsed().as_secs_f64(), cpu_s() - c);
            let main = main_bands.ratios.clone();
            costs.push((name, t_full, c_full, t_every, c_every, t_main, c_main));
            for (i, temp) in temps.iter().enumerate() {
                let (Some(a), Some(b), Some(c)) = (
                    band_of(1.0, &full[i]),
                    band_of(1.0, &every[i]),
                    band_of(1.0, &main[i]),
                ) else {
                    println!("{name:<18} {temp:>6} no band");
                    continue;
                };
                let w = |b: &viscoroll::results::FrictionBand| (b.p95 / b.p05).ln() / 2.0;
                let (wa, wb, wc) = (w(&a), w(&b), w(&c));
                for (j, r) in [wb / wa, wc / wa].into_iter().enumerate() {
                    lo_all[j] = lo_all[j].min(r);
                    hi_all[j] = hi_all[j].max(r);
                    if wa > 0.01 {
                        lo[j] = lo[j].min(r);
                        hi[j] = hi[j].max(r);
                    }
                }
                max_dm[0] = max_dm[0].max((b.p50.ln() - a.p50.ln()).abs());
                max_dm[1] = max_dm[1].max((c.p50.ln() - a.p50.ln()).abs());
                println!(
                    "{name:<18} {temp:>6} {wa:>9.4} {wb:>9.4} {wc:>9.4} {:>+9.4} {:>+9.4} {:>+9.4} {:>7.2} {:>7.2} {:>8}",
                    a.p50.ln(),
                    b.p50.ln(),
                    c.p50.ln(),
                    wb / wa,
                    wc / wa,
                    main_bands.carried_ln[i].map_or("solved".into(), |s| format!("{s:.4}"))
                );
            }
        }
        for (j, what) in ["every temperature", "main job (carried)"].iter().enumerate() {
            println!(
                "half-width {what}/full: {:.2} … {:.2} where full > 0.01, {:.2} … {:.2} at all; \
                 |median − full's| ≤ {:.4}",
                lo[j], hi[j], lo_all[j], hi_all[j], max_dm[j]
            );
        }
        println!(
            "\n{:<18} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}",
            "compound", "full wall", "full CPU", "every wall", "every CPU", "main wall", "main CPU"
        );
        for (name, a, b, c, d, e, f) in costs {
            println!("{name:<18} {a:>10.2} {b:>10.2} {c:>10.2} {d:>10.2} {e:>10.2} {f:>10.2}");
        }
    });
}
