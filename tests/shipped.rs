//! Readers of shipped files shared by the integration tests and the crate's own tests (src/tests/
//! includes this file): pyvisco's EMS-CA master curve and the CSV tables the main job writes.

use std::path::{Path, PathBuf};
use viscoroll::prony::MasterPoint;

/// Read `f [Hz], E_stor [MPa], E_loss [MPa]` (a name row, then a unit row) into points in Pa.
pub fn ems_ca_master() -> Vec<MasterPoint> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/data/pyvisco-ems-ca/freq_user_master.csv"
    );
    let mut rdr = csv::ReaderBuilder::new()
        .has_headers(true)
        .trim(csv::Trim::All)
        .from_path(path)
        .expect("open EMS-CA master curve");
    let mut out = Vec::new();
    for (i, rec) in rdr.records().enumerate() {
        let rec = rec.expect("csv record");
        if i == 0 {
            // Unit row: the conversion below relies on it.
            assert_eq!((&rec[0], &rec[1], &rec[2]), ("Hz", "MPa", "MPa"));
            continue;
        }
        let v: Vec<f64> = rec.iter().map(|s| s.parse().expect("number")).collect();
        out.push(MasterPoint::new(v[0], v[1] * 1e6, v[2] * 1e6));
    }
    out
}

/// A CSV table written by the main job: its header and rows as text. Read strictly, as a reader
/// with no comment handling would (pandas' default): the csv crate refuses a row whose width
/// differs from the header's, and a `#` line would be a row of one field.
pub fn table(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut rd = csv::ReaderBuilder::new().from_reader(text.as_bytes());
    let header: Vec<String> = rd
        .headers()
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .iter()
        .map(str::to_string)
        .collect();
    let rows = rd
        .records()
        .map(|r| {
            r.unwrap_or_else(|e| panic!("{}: {e}", path.display()))
                .iter()
                .map(str::to_string)
                .collect()
        })
        .collect();
    (header, rows)
}

/// The path of `rel` under the shipped data folder (`data/`).
pub fn data(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("data")
        .join(rel)
}
