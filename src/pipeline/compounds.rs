//! Which compounds a folder holds ([`discover`]): an explicit `compounds.toml`, or one compound per
//! sub-folder and per export file at the top level.
//!
//! Input: a folder; output: [`CompoundInput`]s (name + files) and notes on what was skipped.

use super::error::{io, PipelineError};
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// One compound to run: its name and the exports that make its measurement.
#[derive(Debug, Clone, PartialEq)]
pub struct CompoundInput {
    /// Name (file stem or folder name, or as listed).
    pub name: String,
    /// The export files.
    pub files: Vec<PathBuf>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Listing {
    compound: Vec<ListedCompound>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ListedCompound {
    name: String,
    files: Vec<String>,
}

/// File extensions taken as DMA exports when there is no listing.
const EXPORT_EXTENSIONS: [&str; 6] = ["txt", "csv", "tsv", "dat", "xls", "xlsx"];

fn is_export(path: &Path) -> bool {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    !name.starts_with('.')
        && !name.starts_with("license")
        && !name.starts_with("notice")
        && !name.starts_with("readme")
        && EXPORT_EXTENSIONS.contains(&ext.as_str())
}

fn sorted_entries(dir: &Path) -> Result<Vec<PathBuf>, PipelineError> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(io(dir))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .collect();
    v.sort();
    Ok(v)
}

/// `*` within the last path component only.
fn expand(dir: &Path, pattern: &str) -> Result<Vec<PathBuf>, PipelineError> {
    let full = dir.join(pattern);
    let name = full
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    if !name.contains('*') {
        return Ok(vec![full]);
    }
    let parent = full.parent().unwrap_or(dir);
    let (pre, post) = name.split_once('*').unwrap_or((&name, ""));
    Ok(sorted_entries(parent)?
        .into_iter()
        .filter(|p| {
            p.is_file()
                && p.file_name().is_some_and(|n| {
                    let n = n.to_string_lossy();
                    n.len() >= pre.len() + post.len() && n.starts_with(pre) && n.ends_with(post)
                })
        })
        .collect())
}

/// The compounds under `dir` and notes on skipped entries (see the module docs).
pub fn discover(dir: &Path) -> Result<(Vec<CompoundInput>, Vec<String>), PipelineError> {
    let listing = dir.join("compounds.toml");
    let mut notes = Vec::new();
    if listing.exists() {
        let text = std::fs::read_to_string(&listing).map_err(io(&listing))?;
        let l: Listing = toml::from_str(&text).map_err(|e| PipelineError::Config {
            path: listing.clone(),
            message: e.to_string(),
        })?;
        let mut out = Vec::new();
        for c in l.compound {
            let mut files = Vec::new();
            for f in &c.files {
                let got = expand(dir, f)?;
                if got.is_empty() {
                    notes.push(format!("{}: `{f}` matches no file", c.name));
                }
                files.extend(got);
            }
            out.push(CompoundInput {
                name: c.name,
                files,
            });
        }
        return Ok((out, notes));
    }
    let mut out = Vec::new();
    for p in sorted_entries(dir)? {
        let name = p
            .file_stem()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        if p.is_dir() {
            let files: Vec<PathBuf> = sorted_entries(&p)?
                .into_iter()
                .filter(|f| f.is_file() && is_export(f))
                .collect();
            if files.is_empty() {
                notes.push(format!(
                    "{}: no DMA export in the folder, skipped",
                    p.display()
                ));
            } else {
                let dir_name = p
                    .file_name()
                    .map(|n| n.to_string_lossy().into_owned())
                    .unwrap_or(name);
                out.push(CompoundInput {
                    name: dir_name,
                    files,
                });
            }
        } else if is_export(&p) {
            out.push(CompoundInput {
                name,
                files: vec![p],
            });
        } else {
            notes.push(format!("{}: not a DMA export, skipped", p.display()));
        }
    }
    Ok((out, notes))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shipped_listing_names_three_compounds_with_files() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("data");
        let (c, notes) = discover(&dir).unwrap();
        assert!(notes.is_empty(), "{notes:?}");
        let names: Vec<&str> = c.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(names, ["ems-ca", "dmasuite-tensile", "trios-aresg2-lims"]);
        // data/dmasuite-tensile holds 22 isotherm files T0.txt … T105.txt (plus its LICENSE).
        assert_eq!(c[1].files.len(), 22);
        assert!(c.iter().all(|c| c.files.iter().all(|f| f.is_file())));
    }
}
