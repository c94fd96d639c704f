//! The sidecar of each CSV table the tool writes: `NAME.csv` has one header row and no comment
//! lines, so any CSV reader takes it as it is; what used to be its `#` lines — provenance, the
//! settings, the notes that hold for the whole table — is `NAME.meta.json` beside it (`CsvMeta`,
//! its JSON Schema in docs/schemas/csv-meta.schema.json). A note that belongs to a row stays on the
//! row (friction.csv's `note` and `not_trusted` columns; ranking.csv's `note`).
//!
//! Input: the table's text and its `CsvMeta`; output: both files, each written atomically
//! ([`crate::report::write_file`]).

use super::error::{write_file, ReportError};
use crate::results::InputHash;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// The version of the sidecar's layout ([`CsvMeta::schema_version`]): raised when a field changes
/// meaning or goes away.
pub(crate) const CSV_META_SCHEMA_VERSION: u32 = 1;

/// What a CSV table is and where it came from (`NAME.meta.json` beside `NAME.csv`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct CsvMeta {
    /// [`CSV_META_SCHEMA_VERSION`].
    pub schema_version: u32,
    /// The file it describes (`friction.csv`), beside it.
    pub table: String,
    /// What the table holds, in a line.
    pub description: String,
    /// Tool name (`viscoroll`).
    pub tool: String,
    /// Tool version (the crate version).
    pub tool_version: String,
    /// The compound, for a compound's table; `None` for a table of the whole run.
    pub compound: Option<String>,
    /// The input files with their SHA-256 (a compound's DMA exports); empty for the ranking.
    pub inputs: Vec<InputHash>,
    /// The settings the table was made with (the fit's resolved settings, a tolerance, the
    /// ranking's rule), by name.
    pub settings: serde_json::Map<String, serde_json::Value>,
    /// Why the compound's fit is not trusted (empty when it is); every row of friction.csv carries
    /// them too, in `not_trusted`.
    pub not_trusted: Vec<String>,
    /// Warnings that hold for every row (the fit's: data, master curve, bands), in order: the
    /// `F1`, `F2`, … that every row of friction.csv points at from its `note`.
    pub warnings: Vec<String>,
    /// Notes on reading the table.
    pub notes: Vec<String>,
}

impl CsvMeta {
    /// A sidecar of this tool's version for `table`, with no compound, input, setting or note yet.
    pub fn new(table: &str, description: &str) -> Self {
        Self {
            schema_version: CSV_META_SCHEMA_VERSION,
            table: table.to_string(),
            description: description.to_string(),
            tool: "viscoroll".to_string(),
            tool_version: env!("CARGO_PKG_VERSION").to_string(),
            compound: None,
            inputs: Vec::new(),
            settings: serde_json::Map::new(),
            not_trusted: Vec::new(),
            warnings: Vec::new(),
            notes: Vec::new(),
        }
    }

    /// The same with `key` set to `value` in [`CsvMeta::settings`].
    pub fn setting(mut self, key: &str, value: impl Serialize) -> Self {
        let v = serde_json::to_value(value).unwrap_or(serde_json::Value::Null);
        self.settings.insert(key.to_string(), v);
        self
    }
}

/// `NAME.meta.json` for `NAME.csv`.
pub(crate) fn meta_path(csv: &Path) -> PathBuf {
    csv.with_extension("meta.json")
}

/// Write the table `csv_text` to `path` and its sidecar beside it ([`meta_path`]).
pub(crate) fn write_table(path: &Path, csv_text: &str, meta: &CsvMeta) -> Result<(), ReportError> {
    write_file(path, csv_text.as_bytes())?;
    // A map of strings and plain values: serialising cannot fail.
    let json = serde_json::to_string_pretty(meta).unwrap_or_default();
    write_file(&meta_path(path), format!("{json}\n").as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sidecar_sits_beside_its_table_and_reads_back() {
        assert_eq!(
            meta_path(Path::new("reports/a/friction.csv")),
            Path::new("reports/a/friction.meta.json")
        );
        let dir = std::env::temp_dir().join(format!("viscoroll-csvmeta-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let mut m = CsvMeta::new("t.csv", "a test table").setting("tol", 1e-3);
        m.warnings.push("w".into());
        write_table(&dir.join("t.csv"), "a,b\n1,2\n", &m).unwrap();
        assert_eq!(
            std::fs::read_to_string(dir.join("t.csv")).unwrap(),
            "a,b\n1,2\n"
        );
        let back: CsvMeta =
            serde_json::from_str(&std::fs::read_to_string(dir.join("t.meta.json")).unwrap())
                .unwrap();
        assert_eq!(back, m);
        assert_eq!(back.settings["tol"], 1e-3);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
