//! Which compounds a folder holds ([`discover`]): an explicit `compounds.toml`, or one compound per
//! sub-folder and per export file at the top level.
//!
//! Input: a folder and the paths the run itself owns there (its output folders, the scenes file);
//! output: [`CompoundInput`]s (name, files, per-compound settings) and notes on what was skipped or
//! renamed. Without a listing, the run's own paths, `compounds.toml`, `scenes.toml` and hidden
//! entries (a lock, a temp file) are passed over without a note, so a second run in the same
//! folder never reads the first one's `fits/` or `reports/`. Names become file names under the output folder, so they are
//! sanitised ([`sanitise_name`]: no separators, no leading dot, no `..`) and made unique.
//!
//! `compounds.toml` (each `[[compound]]`; every key but `name` and `files` optional):
//! ```toml
//! [[compound]]
//! name = "lsr"
//! files = ["lsr/*.txt"]          # `*` within the last path component
//! format = "trios-text"           # reader, as `ingest --format`
//! mode = "shear"                  # tensile or shear, when the file does not say
//! poisson = 0.49
//! modulus_unit = "MPa"            # units the file does not state
//! freq_unit = "Hz"
//! temp_unit = "°C"
//! columns = { freq = "Frq", storage = "Mod1", loss = "Mod2" }  # as `ingest --columns` (keys:
//!                                 # freq, temp, set_temp, storage, loss, complex, tan_delta, phase,
//!                                 # segment); also the string "freq=Frq,storage=Mod1,loss=Mod2"
//! tref_c = 20.0                   # reference temperature of the master curve
//! prony = { terms_per_decade = 1.5 }   # keys of the Prony settings (fit file `settings.prony`)
//! # The options of `viscoroll master` / `fit` / `run`, same names and values (crate::pipeline::tuning):
//! criterion = "slope-weighted"    # slope-weighted (default), storage, joint, tan-delta
//! shift = "auto"                  # auto, wlf:C1,C2, arrhenius:EA (at tref_c) or a file
//! vertical = "none"               # none, fitted, temperature
//! law = "table"                   # table (default of fit and run), auto, wlf, arrhenius
//! fit_range = "-30:60"            # WLF/Arrhenius fitted over these temperatures, °C
//! nominal = false                 # shift with the nominal (set) temperatures
//! max_terms = 18                  # at most this many relaxation terms
//! target_rms = "0.012,0.10"       # the fewest terms that reach these RMS log10 errors
//! reduce = false                  # the fewest terms no less accurate than the dense fit
//! loss_weight = 0.12              # weight of E″ against E′ in the Prony fit (default 1)
//! ```
//!
//! Replicate specimens of one compound (issue 31): `specimens` instead of `files`, one entry per
//! specimen — a file, a `*` pattern (the files it matches) or a folder (the exports in it). The fit
//! pools them (crate::pipeline::specimens) and the bands carry the spread between them
//! (crate::bands::between):
//! ```toml
//! [[compound]]
//! name = "ems-ca"
//! specimens = ["pyvisco-ems-ca/freq_Eplexor_raw.xls", "pyvisco-ems-ca-specimen2/freq_Eplexor_raw.xls"]
//! ```
//! Without a listing, a compound folder whose exports sit in sub-folders (and none beside them) is
//! one compound with a specimen per sub-folder.
//!
//! A master curve already shifted, in pyvisco's CSV layout, is one compound too: `files` is the
//! master-curve CSV alone and `shift_factors` its shift-factor CSV (crate::dma::pyvisco):
//! ```toml
//! [[compound]]
//! name = "ems-ca-pyvisco"
//! files = ["pyvisco-ems-ca/freq_user_master.csv"]
//! shift_factors = "pyvisco-ems-ca/freq_user_master__shift_factors.csv"
//! ```

use super::error::{io, PipelineError};
use super::tuning::{self, FitTuning};
use crate::dma::IngestOptions;
use crate::prony::PronySettings;
use crate::ModulusKind;
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// One compound to run: its name, the exports that make its measurement, and its settings.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CompoundInput {
    /// Name (file stem or folder name, or as listed), sanitised.
    pub name: String,
    /// The export files (or measurement JSON files written by `viscoroll ingest`); with replicate
    /// specimens, every specimen's files.
    pub files: Vec<PathBuf>,
    /// The files of each replicate specimen (empty: one specimen, `files`).
    pub specimens: Vec<Vec<PathBuf>>,
    /// Per-compound settings from `compounds.toml`.
    pub settings: CompoundSettings,
    /// Why the compound cannot run (an unreadable folder, a setting out of range or beyond the work
    /// budget), if it cannot: it then fails alone.
    pub unreadable: Option<String>,
}

/// Per-compound settings of `compounds.toml`, resolved.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CompoundSettings {
    /// Reader options (format, mode, Poisson's ratio, units).
    pub ingest: Option<IngestOptions>,
    /// Reference temperature of the master curve in °C.
    pub tref_c: Option<f64>,
    /// Prony settings.
    pub prony: Option<PronySettings>,
    /// pyvisco's shift-factor CSV of a master curve given as the compound's one file.
    pub shift_factors: Option<PathBuf>,
    /// The master-curve and Prony options given (`criterion`, `law`, `max_terms`, …).
    pub tuning: FitTuning,
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
    #[serde(default)]
    files: Vec<String>,
    #[serde(default)]
    specimens: Vec<String>,
    #[serde(default)]
    format: Option<String>,
    #[serde(default)]
    mode: Option<String>,
    #[serde(default)]
    poisson: Option<f64>,
    #[serde(default)]
    modulus_unit: Option<String>,
    #[serde(default)]
    freq_unit: Option<String>,
    #[serde(default)]
    temp_unit: Option<String>,
    #[serde(default)]
    tref_c: Option<f64>,
    #[serde(default)]
    prony: Option<toml::Table>,
    #[serde(default)]
    shift_factors: Option<String>,
    #[serde(default)]
    columns: Option<ColumnsSetting>,
    #[serde(default)]
    shift: Option<String>,
    #[serde(default)]
    vertical: Option<String>,
    #[serde(default)]
    criterion: Option<String>,
    #[serde(default)]
    law: Option<String>,
    #[serde(default)]
    fit_range: Option<String>,
    #[serde(default)]
    nominal: Option<bool>,
    #[serde(default)]
    max_terms: Option<usize>,
    #[serde(default)]
    target_rms: Option<String>,
    #[serde(default)]
    reduce: Option<bool>,
    #[serde(default)]
    loss_weight: Option<f64>,
}

/// `columns` of a compound: a table `{ freq = "Frq", … }` or the `ingest --columns` string.
#[derive(Deserialize)]
#[serde(untagged)]
enum ColumnsSetting {
    Spec(String),
    Table(toml::Table),
}

impl ListedCompound {
    /// The master-curve and Prony options, each checked (the message names the key); a `shift`
    /// file is found from `dir`.
    fn tuning(&self, dir: &Path) -> Result<FitTuning, String> {
        Ok(FitTuning {
            shift: self
                .shift
                .as_deref()
                .map(|s| tuning::parse_shift(s, self.tref_c, dir))
                .transpose()?,
            vertical: self
                .vertical
                .as_deref()
                .map(tuning::parse_vertical)
                .transpose()?,
            criterion: self
                .criterion
                .as_deref()
                .map(tuning::parse_criterion)
                .transpose()?,
            law: self.law.as_deref().map(tuning::parse_law).transpose()?,
            fit_range_c: self
                .fit_range
                .as_deref()
                .map(tuning::parse_fit_range)
                .transpose()
                .map_err(|e| format!("fit_range: {e}"))?,
            nominal: self.nominal.unwrap_or(false),
            max_terms: match self.max_terms {
                Some(0) => return Err("max_terms = 0: expected at least 1".into()),
                n => n,
            },
            target_rms: self
                .target_rms
                .as_deref()
                .map(tuning::parse_target_rms)
                .transpose()
                .map_err(|e| format!("target_rms: {e}"))?,
            reduce: self.reduce.unwrap_or(false),
            loss_weight: self
                .loss_weight
                .map(tuning::check_loss_weight)
                .transpose()
                .map_err(|e| format!("loss_weight: {e}"))?,
        })
    }

    /// The settings, each checked (the message names the key).
    fn settings(&self, dir: &Path) -> Result<CompoundSettings, String> {
        let mut o = IngestOptions::default();
        let mut any = false;
        if let Some(f) = &self.format {
            o.format = Some(f.parse().map_err(|e| format!("format: {e}"))?);
            any = true;
        }
        if let Some(m) = &self.mode {
            o.mode = Some(match m.to_ascii_lowercase().as_str() {
                "tensile" | "tension" | "e" => ModulusKind::Tensile,
                "shear" | "g" => ModulusKind::Shear,
                _ => return Err(format!("mode `{m}`: expected tensile or shear")),
            });
            any = true;
        }
        if let Some(p) = self.poisson {
            if !(p > -1.0 && p <= 0.5) {
                return Err(format!("poisson = {p}: must lie in (−1, 0.5]"));
            }
            o.poisson = p;
            any = true;
        }
        if let Some(u) = &self.modulus_unit {
            o.set_unit("modulus", u)
                .map_err(|e| format!("modulus_unit {e}"))?;
            any = true;
        }
        if let Some(u) = &self.freq_unit {
            o.set_unit("freq", u)
                .map_err(|e| format!("freq_unit {e}"))?;
            any = true;
        }
        if let Some(u) = &self.temp_unit {
            o.set_unit("temp", u)
                .map_err(|e| format!("temp_unit {e}"))?;
            any = true;
        }
        if let Some(c) = &self.columns {
            o.columns = column_map(c)?;
            any = true;
        }
        if let Some(t) = self.tref_c {
            if !(t.is_finite() && (-273.15..=1000.0).contains(&t)) {
                return Err(format!(
                    "tref_c = {t}: must be a temperature in °C in [−273.15, 1000]"
                ));
            }
        }
        let prony = self.prony.as_ref().map(prony_settings).transpose()?;
        if let Some(p) = &prony {
            // within range and the work budget (crate::limits) before any work
            p.validate().map_err(|e| format!("prony: {e}"))?;
        }
        Ok(CompoundSettings {
            ingest: any.then_some(o),
            tref_c: self.tref_c,
            prony,
            shift_factors: None,
            tuning: self.tuning(dir)?,
        })
    }
}

/// The `columns` setting: a `--columns` spec, or a table of quantity = column name (names may not
/// hold `,` or `=`, the spec's separators).
fn column_map(c: &ColumnsSetting) -> Result<crate::dma::ColumnMap, String> {
    Ok(match c {
        ColumnsSetting::Spec(spec) => {
            crate::dma::ColumnMap::parse(spec).map_err(|e| format!("columns: {e}"))?
        }
        ColumnsSetting::Table(t) => {
            let mut spec = Vec::new();
            for (k, v) in t {
                let v = v.as_str().ok_or_else(|| {
                    format!("columns: `{k}` must be a column name (a string), got {v}")
                })?;
                if v.contains([',', '=']) {
                    return Err(format!(
                        "columns: `{k}` = `{v}`: a column name may not hold `,` or `=`"
                    ));
                }
                spec.push(format!("{k}={v}"));
            }
            crate::dma::ColumnMap::parse(&spec.join(",")).map_err(|e| format!("columns: {e}"))?
        }
    })
}

/// The `prony` table: the listed keys over the defaults, so a partial table is enough; an unknown
/// key is an error.
fn prony_settings(table: &toml::Table) -> Result<PronySettings, String> {
    // The listed keys over the defaults, so a partial table is enough.
    let mut v =
        serde_json::to_value(PronySettings::default()).map_err(|e| format!("prony: {e}"))?;
    let over = serde_json::to_value(table).map_err(|e| format!("prony: {e}"))?;
    if let (Some(base), Some(over)) = (v.as_object_mut(), over.as_object()) {
        for (k, x) in over {
            if !base.contains_key(k) {
                return Err(format!("prony: unknown key `{k}`"));
            }
            base.insert(k.clone(), x.clone());
        }
    }
    serde_json::from_value(v).map_err(|e| format!("prony: {e}"))
}

/// File extensions taken as DMA exports when there is no listing (`json`: a measurement written by
/// `viscoroll ingest`).
const EXPORT_EXTENSIONS: [&str; 8] = ["txt", "csv", "tsv", "dat", "xls", "xlsx", "osc", "json"];

/// Longest compound name kept, in bytes.
const MAX_NAME_BYTES: usize = 100;

/// A compound name safe as a file name inside the output folder: letters, digits, `-`, `_`, `.`
/// and `+` kept, anything else (separators, spaces, control characters) replaced by `_`; runs of
/// dots shortened to one (no `..`), no leading dot (no hidden file), at most 100 bytes, never empty.
pub fn sanitise_name(raw: &str) -> String {
    let mut s: String = raw
        .chars()
        .map(|c| {
            if c.is_alphanumeric() || matches!(c, '-' | '_' | '.' | '+') {
                c
            } else {
                '_'
            }
        })
        .collect();
    while s.contains("..") {
        s = s.replace("..", ".");
    }
    while s.starts_with('.') {
        s.remove(0);
    }
    if s.len() > MAX_NAME_BYTES {
        let mut end = MAX_NAME_BYTES;
        while !s.is_char_boundary(end) {
            end -= 1;
        }
        s.truncate(end);
    }
    if s.is_empty() {
        s.push_str("compound");
    }
    s
}

/// Sanitise every name and make them unique (case-insensitively, for case-insensitive file systems)
/// with `-2`, `-3`, …; a note for each name that changed.
fn settle_names(compounds: &mut [CompoundInput], notes: &mut Vec<String>) {
    let mut seen: Vec<String> = Vec::new();
    for c in compounds.iter_mut() {
        let base = sanitise_name(&c.name);
        let mut name = base.clone();
        let mut k = 2;
        while seen.contains(&name.to_lowercase()) {
            name = format!("{base}-{k}");
            k += 1;
        }
        if name != c.name {
            notes.push(crate::results::cap_line(&format!(
                "compound {:?} is named {name} in the outputs",
                c.name
            )));
            c.name = name.clone();
        }
        seen.push(name.to_lowercase());
    }
}

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

/// The export files directly in `dir`, sorted.
fn exports_in(dir: &Path) -> Result<Vec<PathBuf>, PipelineError> {
    Ok(sorted_entries(dir)?
        .into_iter()
        .filter(|f| f.is_file() && is_export(f))
        .collect())
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

/// Whether a folder entry is the run's own (one of `own`, or a file the run reads as settings) or
/// hidden: passed over without a note.
fn is_own_or_hidden(p: &Path, own: &[PathBuf]) -> bool {
    let name = p
        .file_name()
        .map(|n| n.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    if name.starts_with('.') || name == "scenes.toml" || name == "compounds.toml" {
        return true;
    }
    let canon = |q: &Path| std::fs::canonicalize(q).unwrap_or_else(|_| q.to_path_buf());
    let p = canon(p);
    own.iter().any(|o| canon(o) == p)
}

/// The compounds under `dir` and notes on skipped entries (see the module docs); `own` are the
/// paths the run writes or reads as settings (output folder, `fits/`, `reports/`, scenes file),
/// never taken as compounds.
pub fn discover(
    dir: &Path,
    own: &[PathBuf],
) -> Result<(Vec<CompoundInput>, Vec<String>), PipelineError> {
    let listing = dir.join("compounds.toml");
    let mut notes = Vec::new();
    let mut out = if listing.exists() {
        listed(dir, &listing, &mut notes)?
    } else {
        in_folder(dir, own, &mut notes)?
    };
    settle_names(&mut out, &mut notes);
    Ok((out, notes))
}

/// The compounds `compounds.toml` (at `listing`) names, in its order.
fn listed(
    dir: &Path,
    listing: &Path,
    notes: &mut Vec<String>,
) -> Result<Vec<CompoundInput>, PipelineError> {
    let text = crate::fsutil::read_regular_to_string(listing, crate::limits::SETTINGS_BYTES_MAX)
        .map_err(io(listing))?;
    let l: Listing = toml::from_str(&text).map_err(|e| PipelineError::Config {
        path: listing.to_path_buf(),
        message: e.to_string(),
    })?;
    l.compound
        .into_iter()
        .map(|c| listed_compound(dir, listing, c, notes))
        .collect()
}

/// One compound of `compounds.toml`: its files (`files`: one specimen) or specimens (a file, a
/// pattern or a folder each) and its settings; a bad setting (or name) fails its compound only
/// (`unreadable`), a listing that contradicts itself fails the run.
fn listed_compound(
    dir: &Path,
    listing: &Path,
    c: ListedCompound,
    notes: &mut Vec<String>,
) -> Result<CompoundInput, PipelineError> {
    let config = |message: String| PipelineError::Config {
        path: listing.to_path_buf(),
        message: format!("compound {:?}: {message}", c.name),
    };
    if c.files.is_empty() == c.specimens.is_empty() {
        return Err(config(
            "give either `files` (one specimen) or `specimens` (one entry per replicate \
             specimen: a file, a pattern or a folder)"
                .into(),
        ));
    }
    let mut files = Vec::new();
    for f in &c.files {
        let got = expand(dir, f)?;
        if got.is_empty() {
            notes.push(format!("{}: `{f}` matches no file", c.name));
        }
        files.extend(got);
    }
    let mut specimens = Vec::new();
    for f in &c.specimens {
        let full = dir.join(f);
        let got: Vec<PathBuf> = if full.is_dir() {
            exports_in(&full)?
        } else {
            expand(dir, f)?
                .into_iter()
                .filter(|p| p.is_file())
                .collect()
        };
        if got.is_empty() {
            return Err(config(format!("specimen `{f}` matches no export")));
        }
        files.extend(got.iter().cloned());
        specimens.push(got);
    }
    if specimens.len() == 1 {
        specimens.clear();
    }
    let checked = crate::limits::name("name", &c.name)
        .map_err(|e| e.to_string())
        .and_then(|()| c.settings(dir));
    let mut settings = match checked {
        Ok(s) => s,
        Err(message) => {
            return Ok(CompoundInput {
                name: c.name,
                files,
                unreadable: Some(format!("{}: {message}", listing.display())),
                ..CompoundInput::default()
            });
        }
    };
    if let Some(sf) = &c.shift_factors {
        if files.len() != 1 {
            return Err(config(format!(
                "with shift_factors, `files` must name the one master-curve CSV ({} files found)",
                files.len()
            )));
        }
        settings.shift_factors = Some(dir.join(sf));
    }
    if !specimens.is_empty() && settings.shift_factors.is_some() {
        return Err(config(
            "a master curve read already shifted (shift_factors) has one specimen".into(),
        ));
    }
    Ok(CompoundInput {
        name: c.name,
        files,
        specimens,
        settings,
        unreadable: None,
    })
}

/// Without `compounds.toml`: every export in `dir` a compound, every folder of exports (or of
/// specimen folders) a compound; the run's own entries and hidden ones passed over.
fn in_folder(
    dir: &Path,
    own: &[PathBuf],
    notes: &mut Vec<String>,
) -> Result<Vec<CompoundInput>, PipelineError> {
    let mut out = Vec::new();
    for p in sorted_entries(dir)? {
        if is_own_or_hidden(&p, own) {
            continue;
        }
        let name = p
            .file_stem()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        if p.is_dir() {
            let dir_name = p
                .file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or(name);
            out.extend(folder_compound(&p, dir_name, notes));
        } else if is_export(&p) {
            out.push(CompoundInput {
                name,
                files: vec![p],
                ..CompoundInput::default()
            });
        } else {
            notes.push(format!("{}: not a DMA export, skipped", p.display()));
        }
    }
    Ok(out)
}

/// The compound of folder `p` named `name`: its exports, or its sub-folders' as replicate
/// specimens; an unreadable folder fails its compound only, a folder without exports is skipped
/// with a note.
fn folder_compound(p: &Path, name: String, notes: &mut Vec<String>) -> Option<CompoundInput> {
    let mut files: Vec<PathBuf> = match exports_in(p) {
        Ok(v) => v,
        Err(e) => {
            return Some(CompoundInput {
                name,
                unreadable: Some(e.to_string()),
                ..CompoundInput::default()
            });
        }
    };
    let mut specimens = Vec::new();
    if files.is_empty() {
        // replicate specimens: a sub-folder of exports each (an unreadable one is skipped
        // with the others; the compound then fails or runs on what could be read)
        for sub in sorted_entries(p)
            .unwrap_or_default()
            .into_iter()
            .filter(|s| s.is_dir())
        {
            let got = match exports_in(&sub) {
                Ok(v) => v,
                Err(e) => {
                    notes.push(format!("{e}: specimen folder skipped"));
                    continue;
                }
            };
            if !got.is_empty() {
                files.extend(got.iter().cloned());
                specimens.push(got);
            }
        }
        if specimens.len() == 1 {
            specimens.clear();
        }
    }
    if files.is_empty() {
        notes.push(format!(
            "{}: no DMA export in the folder, skipped",
            p.display()
        ));
        return None;
    }
    Some(CompoundInput {
        name,
        files,
        specimens,
        ..CompoundInput::default()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shipped_listing_names_three_compounds_with_files() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("data");
        let (c, notes) = discover(&dir, &[]).unwrap();
        assert!(notes.is_empty(), "{notes:?}");
        let names: Vec<&str> = c.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(names, ["ems-ca", "dmasuite-tensile", "trios-aresg2-lims"]);
        // data/dmasuite-tensile holds 22 isotherm files T0.txt … T105.txt (plus its LICENSE).
        assert_eq!(c[1].files.len(), 22);
        assert!(c.iter().all(|c| c.files.iter().all(|f| f.is_file())));
    }

    #[test]
    fn specimens_come_from_the_listing_or_from_sub_folders() {
        let dir = std::env::temp_dir().join(format!("viscoroll-specimens-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        for sub in ["a/s1", "a/s2", "b"] {
            std::fs::create_dir_all(dir.join(sub)).unwrap();
        }
        for f in ["a/s1/x.txt", "a/s2/y.txt", "a/s2/z.txt", "b/w.txt"] {
            std::fs::write(dir.join(f), "").unwrap();
        }
        // no listing: folder a holds its exports in two sub-folders, b beside it one export
        let (c, _) = discover(&dir, &[]).unwrap();
        assert_eq!(c.len(), 2);
        assert_eq!(c[0].specimens.len(), 2);
        assert_eq!(c[0].specimens[1].len(), 2);
        assert_eq!(c[0].files.len(), 3);
        assert!(c[1].specimens.is_empty());
        // listed: a folder and a file, one specimen each
        std::fs::write(
            dir.join("compounds.toml"),
            "[[compound]]\nname = \"p\"\nspecimens = [\"a/s2\", \"b/w.txt\"]\n",
        )
        .unwrap();
        let (c, _) = discover(&dir, &[]).unwrap();
        assert_eq!(c[0].specimens.len(), 2);
        assert_eq!(c[0].specimens[0].len(), 2);
        assert_eq!(c[0].files.len(), 3);
        // both keys, or a specimen matching nothing, are refused
        for bad in [
            "files = [\"b/w.txt\"]\nspecimens = [\"b/w.txt\"]",
            "specimens = [\"nothing/here.txt\", \"b/w.txt\"]",
        ] {
            std::fs::write(
                dir.join("compounds.toml"),
                format!("[[compound]]\nname = \"p\"\n{bad}\n"),
            )
            .unwrap();
            assert!(discover(&dir, &[]).is_err(), "{bad}");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn names_are_sanitised_and_unique() {
        assert_eq!(sanitise_name("../../etc/passwd"), "_._etc_passwd");
        assert_eq!(sanitise_name("/abs/path"), "_abs_path");
        assert_eq!(sanitise_name(".."), "compound");
        assert_eq!(sanitise_name("a\\b:c d"), "a_b_c_d");
        assert_eq!(sanitise_name("EPDM 70+"), "EPDM_70+");
        assert_eq!(sanitise_name(&"é".repeat(80)).len(), 100);
        let mut c = vec![
            CompoundInput {
                name: "a/b".into(),
                ..Default::default()
            },
            CompoundInput {
                name: "a_b".into(),
                ..Default::default()
            },
            CompoundInput {
                name: "A_B".into(),
                ..Default::default()
            },
        ];
        let mut notes = vec![];
        settle_names(&mut c, &mut notes);
        let names: Vec<&str> = c.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(names, ["a_b", "a_b-2", "A_B-3"]);
        assert_eq!(notes.len(), 3, "{notes:?}");
    }

    #[test]
    fn listed_settings_are_checked_and_a_partial_prony_table_fills_from_defaults() {
        let dir = std::env::temp_dir().join(format!("viscoroll-listing-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("compounds.toml"),
            "[[compound]]\nname = \"x\"\nfiles = [\"a.txt\"]\nmode = \"shear\"\npoisson = 0.45\ntref_c = 20\nprony = { terms_per_decade = 1.5 }\n",
        )
        .unwrap();
        let (c, _) = discover(&dir, &[]).unwrap();
        let s = &c[0].settings;
        assert_eq!(s.tref_c, Some(20.0));
        let ingest = s.ingest.as_ref().unwrap();
        assert_eq!(
            (ingest.mode, ingest.poisson),
            (Some(ModulusKind::Shear), 0.45)
        );
        let p = s.prony.as_ref().unwrap();
        assert_eq!(p.terms_per_decade, 1.5);
        // The options of `master`/`fit`/`run` under their names.
        std::fs::write(
            dir.join("compounds.toml"),
            "[[compound]]\nname = \"x\"\nfiles = [\"a.txt\"]\ncriterion = \"storage\"\nlaw = \"wlf\"\nfit_range = \"-30:60\"\nvertical = \"fitted\"\nmax_terms = 18\nloss_weight = 0.12\n",
        )
        .unwrap();
        let (c2, _) = discover(&dir, &[]).unwrap();
        let t = &c2[0].settings.tuning;
        assert_eq!(t.criterion, Some(crate::tts::ShiftCriterion::Storage));
        assert_eq!(t.law, Some(crate::tts::LawChoice::Wlf));
        assert_eq!(t.fit_range_c, Some((-30.0, 60.0)));
        assert_eq!(t.vertical, Some(crate::tts::VerticalShift::Fitted));
        assert_eq!(t.max_terms, Some(18));
        assert_eq!(t.loss_weight, Some(0.12));
        assert_eq!(p.max_iter, PronySettings::default().max_iter);
        for bad in [
            "poisson = 0.7",
            "mode = \"bend\"",
            "prony = { nope = 1 }",
            "criterion = \"e-prime\"",
            "fit_range = \"60:-30\"",
            "target_rms = \"0\"",
            "loss_weight = -1",
            "law = \"vft\"",
            "shift = \"wlf:1,2\"",
            "tref_c = 1e9",
        ] {
            std::fs::write(
                dir.join("compounds.toml"),
                format!("[[compound]]\nname = \"x\"\nfiles = [\"a.txt\"]\n{bad}\n"),
            )
            .unwrap();
            // a bad setting fails its compound only (issue 28), naming the key
            let (found, _) = discover(&dir, &[]).unwrap();
            let e = found[0].unreadable.clone().unwrap_or_default();
            let key = bad.split(' ').next().unwrap();
            assert!(e.contains(key), "{bad}: {e}");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
