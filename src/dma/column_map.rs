//! [`ColumnMap`]: which column holds which quantity, stated by the user for exports whose column
//! names no reader knows (`viscoroll ingest --columns freq=Frq,storage=Mod1,loss=Mod2`, or a
//! `[compound.columns]` table in compounds.toml). A plain serde struct of the reader options.
//!
//! A mapped name is matched against the column names as written (after a unit in the name is split
//! off), ignoring case, spaces and `_`. A mapped column that is not in the file is an error naming
//! the columns there are. Units still come from the file or the `--*-unit` options, and the kind
//! (tensile or shear) from the names, the file's evidence or `--mode`; never guessed.

use serde::{Deserialize, Serialize};

/// Column names per quantity; `None`: found by name as usual.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ColumnMap {
    /// Frequency (Hz or rad/s by its unit).
    pub freq: Option<String>,
    /// Measured temperature.
    pub temp: Option<String>,
    /// Set (nominal) temperature.
    pub set_temp: Option<String>,
    /// Storage modulus E′ or G′.
    pub storage: Option<String>,
    /// Loss modulus E″ or G″.
    pub loss: Option<String>,
    /// Magnitude of the complex modulus |E*| or |G*|.
    pub complex: Option<String>,
    /// Loss factor tan δ.
    pub tan_delta: Option<String>,
    /// Phase angle δ.
    pub phase: Option<String>,
    /// Segment or isotherm number.
    pub segment: Option<String>,
}

/// The keys of [`ColumnMap::parse`], for messages.
pub(crate) const COLUMN_MAP_KEYS: &str =
    "freq, temp, set_temp, storage, loss, complex, tan_delta, phase, segment";

impl ColumnMap {
    /// Parse `key=name,key=name` (keys: `COLUMN_MAP_KEYS`); a name may not hold `,` or `=`.
    pub fn parse(spec: &str) -> Result<ColumnMap, String> {
        let mut m = ColumnMap::default();
        for part in spec.split(',').map(str::trim).filter(|p| !p.is_empty()) {
            let (k, v) = part
                .split_once('=')
                .ok_or_else(|| format!("`{part}`: expected key=column name"))?;
            let (k, v) = (k.trim(), v.trim());
            if v.is_empty() {
                return Err(format!("`{part}`: empty column name"));
            }
            let slot = match k.to_ascii_lowercase().as_str() {
                "freq" | "frequency" => &mut m.freq,
                "temp" | "temperature" => &mut m.temp,
                "set_temp" => &mut m.set_temp,
                "storage" => &mut m.storage,
                "loss" => &mut m.loss,
                "complex" => &mut m.complex,
                "tan_delta" | "tan" => &mut m.tan_delta,
                "phase" => &mut m.phase,
                "segment" => &mut m.segment,
                _ => return Err(format!("unknown key `{k}` (one of: {COLUMN_MAP_KEYS})")),
            };
            if slot.is_some() {
                return Err(format!("`{k}` given twice"));
            }
            *slot = Some(v.to_string());
        }
        Ok(m)
    }

    /// Whether nothing is mapped.
    pub fn is_empty(&self) -> bool {
        *self == ColumnMap::default()
    }

    /// Every (key, name) mapped.
    pub fn entries(&self) -> Vec<(&'static str, &str)> {
        [
            ("freq", &self.freq),
            ("temp", &self.temp),
            ("set_temp", &self.set_temp),
            ("storage", &self.storage),
            ("loss", &self.loss),
            ("complex", &self.complex),
            ("tan_delta", &self.tan_delta),
            ("phase", &self.phase),
            ("segment", &self.segment),
        ]
        .into_iter()
        .filter_map(|(k, v)| v.as_deref().map(|v| (k, v)))
        .collect()
    }
}

/// A name reduced for matching a mapped name: lower case, without spaces and `_`.
pub(crate) fn mapping_key(name: &str) -> String {
    name.chars()
        .filter(|c| !c.is_whitespace() && *c != '_')
        .flat_map(char::to_lowercase)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_refuses_unknown_keys() {
        let m = ColumnMap::parse("freq=Frq, storage = Mod 1,loss=Mod2").unwrap();
        assert_eq!(m.freq.as_deref(), Some("Frq"));
        assert_eq!(m.storage.as_deref(), Some("Mod 1"));
        assert_eq!(m.entries().len(), 3);
        assert!(ColumnMap::parse("fre=Frq")
            .unwrap_err()
            .contains("unknown key"));
        assert!(ColumnMap::parse("freq=a,freq=b")
            .unwrap_err()
            .contains("twice"));
        assert!(ColumnMap::parse("freq").is_err());
        assert_eq!(mapping_key("Mod_1 "), "mod1");
        // Plain serde, as compounds.toml holds it.
        let t: ColumnMap = serde_json::from_str(r#"{"freq":"Frq","loss":"L"}"#).unwrap();
        assert_eq!(t.loss.as_deref(), Some("L"));
        assert!(serde_json::from_str::<ColumnMap>(r#"{"frq":"x"}"#).is_err());
    }
}
