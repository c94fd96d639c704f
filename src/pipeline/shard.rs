//! Shards of the main job for array jobs on a cluster (`viscoroll run --shard K/N`, then
//! `viscoroll rank --out OUT`): each shard runs part of the compounds into one shared output
//! folder, and the merge writes the one ranking and index the whole run would have written.
//!
//! Which compounds a shard runs ([`Shard::takes`]): the compounds of the input folder in discovery
//! order (the order of `compounds.toml`, else the sorted file and folder names, after names are
//! made unique: crate::pipeline::compounds::discover), numbered from 0; shard K of N (K counted
//! from 0, as Slurm's `--array=0-(N-1)` and a Kubernetes indexed Job's `JOB_COMPLETION_INDEX`)
//! runs the compounds whose number i has i mod N = K. Every compound is in exactly one shard.
//!
//! What a shard writes: its compounds' fit files and report folders as a whole run does, and
//! instead of `reports/ranking.csv` and `reports/index.html` its `ShardFile` at
//! `OUT/shards/K-of-N/summary.json` (written last: it marks the shard done). A shard locks
//! `OUT/shards/K-of-N/`, not the whole folder, so the shards of one run work side by side, and it
//! leaves temporary files alone (another node's live files look dead from here).
//!
//! The merge (`merge_shards`): reads every shard file under `OUT/shards/`, checks that they are
//! the N shards of one run (same N, same scenes, same compound count, every compound once), puts
//! the outcomes back in discovery order, compares the ranked compounds' bands as the whole run does
//! and writes `reports/ranking.csv` and `reports/index.html` (the tan δ proxies from the fit files
//! in `OUT/fits/`). Friction is not solved again: the ranking is the whole run's, to the bit.

use super::compare::compare_ranked;
use super::error::{io, PipelineError};
use super::folder::{fit_path, LOCK_WAIT};
use crate::report::{write_file, write_index, write_ranking, write_workbook, TanDeltaProxy};
use crate::results::{CompoundFit, RunSummary, SceneSet};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// Shard `index` of `count` (`index` counted from 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// Which shard, 0 ≤ index < count.
    pub index: usize,
    /// How many shards.
    pub count: usize,
}

impl std::str::FromStr for Shard {
    type Err = String;

    /// `K/N` with 0 ≤ K < N.
    fn from_str(s: &str) -> Result<Self, String> {
        let (k, n) = s
            .split_once('/')
            .ok_or_else(|| format!("{s:?}: expected K/N (shard K of N, K counted from 0)"))?;
        let k: usize = k
            .trim()
            .parse()
            .map_err(|_| format!("{s:?}: K is not a whole number ≥ 0"))?;
        let n: usize = n
            .trim()
            .parse()
            .map_err(|_| format!("{s:?}: N is not a whole number ≥ 1"))?;
        if n == 0 {
            return Err(format!("{s:?}: N must be at least 1"));
        }
        if k >= n {
            return Err(format!(
                "{s:?}: K counts from 0, so it must be below N (the shards of 4 are 0/4 … 3/4)"
            ));
        }
        Ok(Shard { index: k, count: n })
    }
}

impl std::fmt::Display for Shard {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl Shard {
    /// Whether this shard runs the compound numbered `i` in discovery order.
    pub fn takes(&self, i: usize) -> bool {
        i % self.count == self.index
    }

    /// The shard's folder under the output folder: `OUT/shards/K-of-N`.
    pub fn dir(&self, out_dir: &Path) -> PathBuf {
        shards_dir(out_dir).join(format!("{}-of-{}", self.index, self.count))
    }

    /// The shard's file: `OUT/shards/K-of-N/summary.json`.
    pub fn file(&self, out_dir: &Path) -> PathBuf {
        self.dir(out_dir).join("summary.json")
    }
}

/// `OUT/shards`.
fn shards_dir(out_dir: &Path) -> PathBuf {
    out_dir.join("shards")
}

/// What a finished shard leaves for the merge.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub(crate) struct ShardFile {
    /// Which shard, counted from 0.
    pub shard_index: usize,
    /// How many shards.
    pub shard_count: usize,
    /// How many compounds the input folder holds (all shards).
    pub compounds_total: usize,
    /// The discovery number of each of the shard's compounds (same order as `summary.compounds`).
    pub positions: Vec<usize>,
    /// The scenes the shard solved.
    pub scenes: SceneSet,
    /// The shard's summary (its compounds only).
    pub summary: RunSummary,
}

/// Write a shard's file (atomically; see the module docs).
pub(crate) fn write_shard_file(out_dir: &Path, file: &ShardFile) -> Result<PathBuf, PipelineError> {
    let shard = Shard {
        index: file.shard_index,
        count: file.shard_count,
    };
    let path = shard.file(out_dir);
    let text = serde_json::to_string(file).map_err(|e| PipelineError::Setting {
        field: "shard".into(),
        message: format!("the shard's summary cannot be written as JSON: {e}"),
    })?;
    write_file(&path, text.as_bytes())?;
    Ok(path)
}

/// A merge error: the shard files do not make one whole run.
fn not_whole(out_dir: &Path, message: String) -> PipelineError {
    PipelineError::Config {
        path: shards_dir(out_dir),
        message,
    }
}

/// Read every shard file under `OUT/shards/` (sorted by folder name).
fn read_shard_files(out_dir: &Path) -> Result<Vec<ShardFile>, PipelineError> {
    let dir = shards_dir(out_dir);
    let entries = std::fs::read_dir(&dir).map_err(io(&dir))?;
    let mut paths: Vec<PathBuf> = entries
        .flatten()
        .map(|e| e.path().join("summary.json"))
        .filter(|p| p.is_file())
        .collect();
    paths.sort();
    let mut files = Vec::new();
    for p in &paths {
        let text = std::fs::read_to_string(p).map_err(io(p))?;
        let f: ShardFile = serde_json::from_str(&text).map_err(|e| PipelineError::Config {
            path: p.clone(),
            message: format!("not a shard summary of this version: {e}"),
        })?;
        files.push(f);
    }
    Ok(files)
}

/// Check that `files` are the N shards of one run; returns the scenes.
fn check_whole(out_dir: &Path, files: &[ShardFile]) -> Result<SceneSet, PipelineError> {
    let Some(first) = files.first() else {
        return Err(not_whole(
            out_dir,
            "no finished shard (no shards/K-of-N/summary.json): run `viscoroll run --shard K/N` first".into(),
        ));
    };
    let n = first.shard_count;
    let mut missing: Vec<usize> = (0..n).collect();
    for f in files {
        if f.shard_count != n {
            return Err(not_whole(out_dir, format!(
                "shards of different counts ({n} and {}): remove the folder's shards/ left by an earlier run and run the shards again",
                f.shard_count
            )));
        }
        if f.scenes != first.scenes
            || f.compounds_total != first.compounds_total
            || f.summary.allow_extrapolation != first.summary.allow_extrapolation
        {
            return Err(not_whole(out_dir, format!(
                "shard {}/{n} ran other scenes, settings or input than shard {}/{n}: run every shard with the same input and options",
                f.shard_index, first.shard_index
            )));
        }
        missing.retain(|&k| k != f.shard_index);
    }
    if !missing.is_empty() {
        let list: Vec<String> = missing.iter().map(|k| format!("{k}/{n}")).collect();
        return Err(not_whole(
            out_dir,
            format!(
                "shard(s) {} not finished (no summary.json yet)",
                list.join(", ")
            ),
        ));
    }
    Ok(first.scenes.clone())
}

/// Merge the shards of a run in `out_dir` (see the module docs): writes `reports/ranking.csv`,
/// the workbook `reports/viscoroll.xlsx` when `xlsx` (crate::report::workbook) and
/// `reports/index.html`, and returns the whole run's summary (outcomes in discovery order).
pub(crate) fn merge_shards(out_dir: &Path, xlsx: bool) -> Result<RunSummary, PipelineError> {
    let _lock =
        crate::fsutil::DirLock::acquire(out_dir, LOCK_WAIT, &|_| {}).map_err(io(out_dir))?;
    let files = read_shard_files(out_dir)?;
    let scenes = check_whole(out_dir, &files)?;
    let total = files[0].compounds_total;
    let mut slots: Vec<Option<crate::results::CompoundOutcome>> = vec![None; total];
    let mut notes: Vec<String> = Vec::new();
    for f in &files {
        if f.positions.len() != f.summary.compounds.len() {
            return Err(not_whole(
                out_dir,
                format!("shard {}/{}: damaged summary", f.shard_index, f.shard_count),
            ));
        }
        for (&i, o) in f.positions.iter().zip(&f.summary.compounds) {
            match slots.get_mut(i) {
                Some(slot @ None) => *slot = Some(o.clone()),
                _ => {
                    return Err(not_whole(out_dir, format!(
                        "compound {} (number {i}) is claimed twice or out of range: the shards ran different inputs",
                        o.compound
                    )))
                }
            }
        }
        for n in &f.summary.notes {
            if !notes.contains(n) {
                notes.push(n.clone());
            }
        }
    }
    if slots.iter().any(Option::is_none) {
        return Err(not_whole(
            out_dir,
            "some compounds are in no shard: the shards ran different inputs".into(),
        ));
    }
    let mut outcomes: Vec<_> = slots.into_iter().flatten().collect();
    let comparisons = compare_ranked(&mut outcomes, &scenes);
    let mut proxies = Vec::new();
    for o in outcomes.iter().filter(|o| o.error.is_none()) {
        let p = fit_path(out_dir, &o.compound);
        match CompoundFit::read(&p) {
            Ok(fit) => proxies.push(TanDeltaProxy::of(&fit)),
            Err(e) => notes.push(crate::results::cap_line(&format!(
                "{}: fit file not read for the index's tan δ column: {e}",
                o.compound
            ))),
        }
    }
    let reports = out_dir.join("reports");
    let summary = RunSummary {
        compounds: outcomes,
        notes,
        allow_extrapolation: files[0].summary.allow_extrapolation,
        ranking_csv: reports.join("ranking.csv"),
        index_html: reports.join("index.html"),
        comparisons,
    };
    write_ranking(
        &summary.ranking_csv,
        &summary.compounds,
        &scenes,
        summary.allow_extrapolation,
    )?;
    if xlsx {
        write_workbook(&summary)?;
    }
    write_index(&reports, &summary, &scenes, &proxies)?;
    Ok(summary)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_refuses_shard_specs() {
        let s: Shard = "2/4".parse().unwrap();
        assert_eq!((s.index, s.count), (2, 4));
        assert_eq!(s.to_string(), "2/4");
        for bad in ["4/4", "1/0", "x/2", "3", "-1/2", "1/2/3"] {
            assert!(bad.parse::<Shard>().is_err(), "{bad}");
        }
    }

    #[test]
    fn every_compound_is_in_exactly_one_shard() {
        for n in 1..6 {
            for i in 0..23 {
                let owners = (0..n)
                    .filter(|&k| Shard { index: k, count: n }.takes(i))
                    .count();
                assert_eq!(owners, 1, "compound {i} of {n} shards");
            }
        }
    }
}
