//! Cost of the uncertainty bands (issue 16: at most 2 s extra per compound on 2 cores): the main
//! job on the shipped data (data/, its three compounds, the shipped scenes) with and without bands,
//! each on a fresh output folder (so every fit is made), in a 2-thread pool, alternated, best of
//! `REPEATS`; then
//! per compound the two parts of the bands alone: the bootstrap ensemble (32 refits) and the
//! replicate solves of every scene. Prints a table. Run: `cargo bench --bench bands`.

use std::time::Instant;
use viscoroll::bands::{build_ensemble, scene_bands_on, BandSettings};
use viscoroll::dma::{read_files, IngestOptions};
use viscoroll::pipeline::fit_measurement_master;
use viscoroll::pipeline::{run_all, FitOptions, RunOptions};
use viscoroll::results::SceneSet;

#[path = "support/cpu.rs"]
mod cpu;
use cpu::cpu_s;

const REPEATS: usize = 5;

fn main() {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .expect("a 2-thread pool");
    pool.install(|| {
        let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data");
        let time_run = |bands: bool, k: usize| {
            let out = std::env::temp_dir().join(format!(
                "viscoroll-bench-bands-{}-{bands}-{k}",
                std::process::id()
            ));
            let _ = std::fs::remove_dir_all(&out);
            let mut opts = RunOptions::for_folder(&data, &out, None, None).unwrap();
            if !bands {
                opts.bands = None;
            }
            let (t, c0) = (Instant::now(), cpu_s());
            let s = run_all(&opts, &|_| {}).unwrap();
            let secs = t.elapsed().as_secs_f64();
            let cpu = cpu_s() - c0;
            let _ = std::fs::remove_dir_all(&out);
            (secs, cpu, s.compounds.len())
        };
        // Alternated, so a change in the machine's load hits both alike; best of each.
        let (mut without, mut with, mut n) = (f64::INFINITY, f64::INFINITY, 0);
        let (mut cpu_without, mut cpu_with) = (f64::INFINITY, f64::INFINITY);
        for k in 0..REPEATS {
            let (w, c, _) = time_run(false, k);
            without = without.min(w);
            cpu_without = cpu_without.min(c);
            let (w, c, m) = time_run(true, k);
            with = with.min(w);
            cpu_with = cpu_with.min(c);
            n = m;
        }
        println!("main job on data/ (2 threads, fresh output, alternated, best of {REPEATS})");
        println!("{:<28} {:>10} {:>10}", "", "wall s", "CPU s");
        println!(
            "{:<28} {:>10.3} {:>10.2}",
            "--no-bands", without, cpu_without
        );
        println!("{:<28} {:>10.3} {:>10.2}", "with bands", with, cpu_with);
        println!(
            "{:<28} {:>10.3} {:>10.2}",
            "extra per compound",
            (with - without) / n as f64,
            (cpu_with - cpu_without) / n as f64
        );
        println!("\nper compound, bands alone (2 threads)");
        println!(
            "{:<20} {:>8} {:>12} {:>14} {:>10}",
            "compound", "points", "ensemble s", "solves s", "total s"
        );
        let bs = BandSettings::default();
        let scenes = SceneSet::shipped();
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
        for (name, files) in sets {
            let m = read_files(&files, &IngestOptions::default()).unwrap();
            let (fit, master) = fit_measurement_master(name, &m, &FitOptions::default()).unwrap();
            let t = Instant::now();
            let e = build_ensemble(&master, &m, &fit, &bs).unwrap();
            let te = t.elapsed().as_secs_f64();
            let t = Instant::now();
            for spec in &scenes.scene {
                // on the scene's body, as the main job (a cover: eq. 15.6b)
                std::hint::black_box(scene_bands_on(&fit, &e, &spec.scene(), &spec.temps_c, &bs));
            }
            let ts = t.elapsed().as_secs_f64();
            println!(
                "{:<20} {:>8} {:>12.3} {:>14.3} {:>10.3}",
                name,
                master.points.len(),
                te,
                ts,
                te + ts
            );
        }
    });
}
