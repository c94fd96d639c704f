//! Reading every shared DMA export in data/ (the `dma` stage end to end: read, hash, detect, parse,
//! units, isotherms, checks). Target (issue 6): all of them in ≤ 100 ms.
//! The shift-factor list inside an Eplexor master export was read on its own here before issue 30;
//! its reader is crate-internal now, so `all_shared_files` reads that export whole (`read_files`,
//! as the `eplexor_master_xls` row) and the user's shift-factor CSV (`read_shift_factors`, public).
//! Run: `cargo bench --bench ingest`.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::path::PathBuf;
use viscoroll::dma::{self, IngestOptions};

fn data(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("data")
        .join(rel)
}

fn sets() -> Vec<(&'static str, Vec<PathBuf>)> {
    vec![
        (
            "eplexor_raw_xls",
            vec![data("pyvisco-ems-ca/freq_Eplexor_raw.xls")],
        ),
        (
            "eplexor_master_xls",
            vec![data("pyvisco-ems-ca/freq_Eplexor_master.xls")],
        ),
        (
            "user_raw_csv",
            vec![data("pyvisco-ems-ca/freq_user_raw.csv")],
        ),
        (
            "trios_lims",
            vec![data("trios-aresg2-lims/frequency_sweep_tts.txt")],
        ),
        (
            "dmasuite_22_files",
            (0..=105)
                .step_by(5)
                .map(|t| data(&format!("dmasuite-tensile/T{t}.txt")))
                .collect(),
        ),
    ]
}

fn bench(c: &mut Criterion) {
    let opts = IngestOptions::default();
    let sets = sets();
    let mut g = c.benchmark_group("ingest");
    g.sample_size(20);
    for (name, paths) in &sets {
        g.bench_function(*name, |b| {
            b.iter(|| black_box(dma::read_files(paths, &opts).unwrap()))
        });
    }
    g.bench_function("all_shared_files", |b| {
        b.iter(|| {
            for (_, paths) in &sets {
                black_box(dma::read_files(paths, &opts).unwrap());
            }
            let shift = data("pyvisco-ems-ca/freq_user_master__shift_factors.csv");
            black_box(dma::read_shift_factors(&shift).unwrap());
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
