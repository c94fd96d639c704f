//! Options from Python: a JSON object of the keyword arguments given (keys are the CLI's flag names
//! with `_` for `-`; absent or `null` means the CLI's default). An unknown key is refused, so a
//! misspelt option never passes unnoticed.

use crate::{stage_err, Stage};
use pyo3::PyResult;
use serde_json::{Map, Value};

/// The options of one call.
pub(crate) struct Opts {
    map: Map<String, Value>,
    stage: Stage,
}

impl Opts {
    /// Parse `json` (an object) and refuse keys not in `known`.
    pub fn parse(stage: Stage, json: &str, known: &[&str]) -> PyResult<Self> {
        let map: Map<String, Value> = serde_json::from_str(json).map_err(stage_err(stage))?;
        if let Some(k) = map.keys().find(|k| !known.contains(&k.as_str())) {
            return Err(stage_err(stage)(anyhow::anyhow!(
                "unknown option `{k}` (known: {})",
                known.join(", ")
            )));
        }
        Ok(Self { map, stage })
    }

    fn get(&self, key: &str) -> Option<&Value> {
        self.map.get(key).filter(|v| !v.is_null())
    }

    fn wrong(&self, key: &str, what: &str) -> pyo3::PyErr {
        stage_err(self.stage)(anyhow::anyhow!("option `{key}`: expected {what}"))
    }

    /// A number.
    pub fn f64(&self, key: &str) -> PyResult<Option<f64>> {
        self.get(key)
            .map(|v| v.as_f64().ok_or_else(|| self.wrong(key, "a number")))
            .transpose()
    }

    /// A whole number ≥ 0.
    pub fn usize(&self, key: &str) -> PyResult<Option<usize>> {
        self.get(key)
            .map(|v| {
                v.as_u64()
                    .map(|n| n as usize)
                    .ok_or_else(|| self.wrong(key, "a whole number ≥ 0"))
            })
            .transpose()
    }

    /// A string.
    pub fn str(&self, key: &str) -> PyResult<Option<String>> {
        self.get(key)
            .map(|v| {
                v.as_str()
                    .map(str::to_string)
                    .ok_or_else(|| self.wrong(key, "a string"))
            })
            .transpose()
    }

    /// A flag (absent: false).
    pub fn flag(&self, key: &str) -> PyResult<bool> {
        self.get(key)
            .map(|v| v.as_bool().ok_or_else(|| self.wrong(key, "true or false")))
            .transpose()
            .map(|b| b.unwrap_or(false))
    }
}
