//! `run --shard K/N` and `rank --out` (issue 29 item 7): four shards of an 8-compound library
//! (synthetic EPLEXOR-like exports from crate::testdata::realistic, `--no-bands` to keep the cost
//! small) merge into the ranking one whole run writes, byte for byte; each shard ran exactly its
//! compounds (numbers i with i mod 4 = K in sorted-name order); the merge refuses while a shard is
//! missing and names it.

use crate::support::{run_main, stderr, temp_dir, viscoroll};
use viscoroll::testdata::{dma_csv, dma_rows, realistic_compounds, DmaProtocol};

/// A library of `n` compounds: `C{k:02}.csv` (sorted names = numbering), each a realistic base
/// compound with its own noise seed.
fn library(dir: &std::path::Path, n: usize) -> Vec<String> {
    let bases = realistic_compounds();
    (0..n)
        .map(|k| {
            let base = &bases[k % bases.len()];
            let protocol = DmaProtocol {
                seed: 7000 + k as u64,
                ..DmaProtocol::default()
            };
            let name = format!("C{k:02}");
            std::fs::write(
                dir.join(format!("{name}.csv")),
                dma_csv(&dma_rows(base, &protocol)),
            )
            .unwrap();
            name
        })
        .collect()
}

/// The fit files' compound names in `out/fits`, sorted.
fn fitted(out: &std::path::Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(out.join("fits"))
        .map(|d| {
            d.flatten()
                .map(|e| e.path().file_stem().unwrap().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

#[test]
fn four_shards_merge_into_the_whole_runs_ranking() {
    let root = temp_dir("shards");
    let input = root.join("lib");
    std::fs::create_dir_all(&input).unwrap();
    let names = library(&input, 8);
    let whole = root.join("whole");
    let o = run_main(&input, &whole, &["--no-bands"]);
    assert!(o.status.code().is_some_and(|c| c != 2), "{}", stderr(&o));
    let sharded = root.join("sharded");
    for k in 0..3 {
        let o = run_main(
            &input,
            &sharded,
            &["--no-bands", "--shard", &format!("{k}/4")],
        );
        assert!(o.status.code().is_some_and(|c| c != 2), "{}", stderr(&o));
        // shard k ran compounds k and k + 4, and nothing of the others
        let want: Vec<String> = (0..=k)
            .flat_map(|j| [names[j].clone(), names[j + 4].clone()])
            .collect::<std::collections::BTreeSet<_>>()
            .into_iter()
            .collect();
        assert_eq!(fitted(&sharded), want, "after shard {k}/4");
        assert!(!sharded.join("reports/ranking.csv").exists());
    }
    let o = viscoroll(&["rank", "--out", sharded.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("3/4"), "{}", stderr(&o));
    let o = run_main(&input, &sharded, &["--no-bands", "--shard", "3/4"]);
    assert!(o.status.code().is_some_and(|c| c != 2), "{}", stderr(&o));
    let o = viscoroll(&["rank", "--out", sharded.to_str().unwrap(), "--json"]);
    assert!(o.status.code().is_some_and(|c| c != 2), "{}", stderr(&o));
    let merged = std::fs::read_to_string(sharded.join("reports/ranking.csv")).unwrap();
    let one = std::fs::read_to_string(whole.join("reports/ranking.csv")).unwrap();
    assert_eq!(merged, one);
    assert!(one.lines().count() > 8, "{one}");
    // the merge writes the whole run's workbook too, byte for byte (its tables and fits are the
    // same, and the file carries no time of its own)
    let book = |d: &std::path::Path| std::fs::read(d.join("reports/viscoroll.xlsx")).unwrap();
    assert!(book(&sharded) == book(&whole), "the workbooks differ");
    let index = std::fs::read_to_string(sharded.join("reports/index.html")).unwrap();
    assert!(names.iter().all(|n| index.contains(n.as_str())));
    assert_eq!(fitted(&sharded), fitted(&whole));
    // a shard spec that does not name a shard is a usage error
    let o = run_main(&input, &sharded, &["--shard", "4/4"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let _ = std::fs::remove_dir_all(&root);
}
