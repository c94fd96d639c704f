//! Reading every shared DMA export in data/ (the `dma` stage end to end: read, hash, detect, parse,
//! units, isotherms, checks). Target (issue 6): all of them in ≤ 100 ms.
//! The shift-factor list inside an Eplexor master export was read on its own here before issue 30;
//! its reader is crate-internal now, so `all_shared_files` reads that export whole (`read_files`,
//! as the `eplexor_master_xls` row) and the user's shift-factor CSV (`read_shift_factors`, public).
//! Run: `cargo bench --bench ingest` (prints a table: median and fastest call).

#[path = "support/timing.rs"]
mod timing;

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

fn main() {
    let opts = IngestOptions::default();
    let sets = sets();
    timing::header("ingest: dma::read_files on the shipped exports");
    for (name, paths) in &sets {
        timing::row(name, || dma::read_files(paths, &opts).unwrap());
    }
    timing::row("all_shared_files", || {
        for (_, paths) in &sets {
            std::hint::black_box(dma::read_files(paths, &opts).unwrap());
        }
        let shift = data("pyvisco-ems-ca/freq_user_master__shift_factors.csv");
        dma::read_shift_factors(&shift).unwrap()
    });
}
