//! A 100-compound library through the main job (issue 16 item 4; goal ≤ 60 s on 2 cores): synthetic
//! DMA exports from the test-data module (viscoroll::testdata::realistic, the four known-truth
//! rubbers of tests/known_truth.rs, each with 25 noise seeds of its default protocol: 33 isotherms
//! × 13 frequencies, 1 % / 3 % noise, ±1.5 K drift), written as CSV files into one folder and run
//! as `viscoroll run` runs it (every fit made: a fresh output folder), with the shipped scenes, in a
//! 2-thread pool. Prints a table: with bands (the default) and, unless `--bands-only`, with
//! `--no-bands`. Run: `cargo bench --bench library` (`-- --n 20` for a smaller library).

use std::time::Instant;
use viscoroll::pipeline::{run_all, RunOptions};
use viscoroll::testdata::realistic::{dma_csv, dma_rows, realistic_compounds, DmaProtocol};

/// CPU time of this process so far (user + system, every thread), s, from /proc/self/stat (100
/// ticks per second on Linux); NaN where it cannot be read. On a shared machine the wall time moves
/// with the other load, the CPU time much less.
fn cpu_s() -> f64 {
    let Ok(stat) = std::fs::read_to_string("/proc/self/stat") else {
        return f64::NAN;
    };
    let rest = stat.rsplit_once(')').map_or("", |r| r.1);
    let f: Vec<f64> = rest
        .split_whitespace()
        .skip(11)
        .take(2)
        .filter_map(|v| v.parse().ok())
        .collect();
    if f.len() == 2 {
        (f[0] + f[1]) / 100.0
    } else {
        f64::NAN
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args
        .iter()
        .position(|a| a == "--n")
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(100);
    let bands_only = args.iter().any(|a| a == "--bands-only");
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
