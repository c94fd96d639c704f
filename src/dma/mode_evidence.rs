//! Tensile or shear from what a file says about its test, never guessed: the geometry (tension,
//! film, cantilever, 3-point bending against parallel plate, cone, torsion), the test or step name
//! ("Zug", "tension", "torsion"), the instrument type (RSA-G2, DMA 850, Q800, EPLEXOR against ARES,
//! DHR, MCR rheometers) and, last, the names of other columns (torque → a rotational rheometer).
//!
//! Input: the metadata (key → value), the step or result names and the column names of a read file
//! ([`RawFile`]); output: the kind and the evidence in words, or `None` (then the column names or
//! `--mode` must say, else every reader gives the same [`super::DmaError::AmbiguousMode`]).
//! The strongest evidence wins: geometry, then test name, then instrument, then columns; two pieces
//! of the same strength that disagree give no answer (and the error asks for `--mode`).

use super::table::RawFile;
use crate::material::ModulusKind;

/// Words of a geometry, test name or instrument that mean tensile (E) or shear (G), lower case.
const TENSILE_GEOMETRY: &[&str] = &[
    "tension",
    "tensile",
    "film",
    "fiber",
    "fibre",
    "cantilever",
    "3-point",
    "three-point",
    "3 point",
    "three point",
    "bending",
    "linear-dma",
    "linear dma",
    "zug",
    "biege",
    "traction",
    "flexion",
    "compression",
];
const SHEAR_GEOMETRY: &[&str] = &[
    "parallel plate",
    "parallel-plate",
    "plate-plate",
    "cone",
    "torsion",
    "shear sandwich",
    "platte",
    "kegel",
    "plan-plan",
    "plan plan",
    "cône",
    "cisaillement",
    "couette",
    "concentric cylinder",
    "pp",
    "cp",
    "srf",
];
const TENSILE_TEST: &[&str] = &["zug", "tension", "tensile", "traction", "bending", "biege"];
const SHEAR_TEST: &[&str] = &["torsion", "shear", "scher", "cisaillement"];
const TENSILE_INSTRUMENT: &[&str] = &[
    "rsa-g2", "rsa g2", "rsag2", "rsa3", "rsa-iii", "dma 850", "dma850", "q800", "dma q800",
    "eplexor", "dma 242", "dma242", "dma 1", "dma+", "metravib", "dma 8000",
];
const SHEAR_INSTRUMENT: &[&str] = &[
    "ares",
    "aresg2",
    "ares-g2",
    "dhr",
    "discovery hr",
    "hr-1",
    "hr-2",
    "hr-3",
    "hr-10",
    "hr-20",
    "hr-30",
    "mcr",
    "mars",
    "kinexus",
    "ar-g2",
    "ar2000",
    "rheometer",
];

/// Metadata keys that name a geometry, a test, an instrument (lower case, without a trailing `:`).
const GEOMETRY_KEYS: &[&str] = &[
    "geometry",
    "geometry name",
    "geometry type",
    "measuring system",
    "messsystem",
    "système de mesure",
    "systeme de mesure",
    "clamp",
    "clamp type",
    "fixture",
    "probenhalter",
];
const TEST_KEYS: &[&str] = &[
    "test",
    "test name",
    "procedure name",
    "procedure",
    "essai",
    "versuch",
    "filename",
    "project",
    "projekt",
    "projet",
    "mode",
];
const INSTRUMENT_KEYS: &[&str] = &[
    "instrument type",
    "instrument name",
    "instrument",
    "device",
    "gerät",
    "appareil",
    "model",
];

fn first_match(text: &str, words: &[&str]) -> Option<String> {
    let l = text.to_lowercase();
    words
        .iter()
        .find(|w| contains_word(&l, w))
        .map(|w| w.to_string())
}

/// `w` in `l` not inside a longer word of letters (so `mcr` is not found in `mcrx`, `zug` is found
/// in `tf-sweep_zug`).
fn contains_word(l: &str, w: &str) -> bool {
    l.match_indices(w).any(|(i, _)| {
        let before = l[..i].chars().next_back();
        let after = l[i + w.len()..].chars().next();
        !before.is_some_and(char::is_alphabetic) && !after.is_some_and(char::is_alphabetic)
    })
}

/// One level of evidence: every (kind, why) found among `texts` (label, value).
fn level(
    texts: &[(String, String)],
    what: &str,
    tensile: &[&str],
    shear: &[&str],
) -> Option<(ModulusKind, String)> {
    let mut found: Vec<(ModulusKind, String)> = Vec::new();
    for (label, value) in texts {
        let t = first_match(value, tensile);
        let s = first_match(value, shear);
        match (t, s) {
            (Some(w), None) => found.push((
                ModulusKind::Tensile,
                format!("{what} {label} `{value}` (\"{w}\": tensile)"),
            )),
            (None, Some(w)) => found.push((
                ModulusKind::Shear,
                format!("{what} {label} `{value}` (\"{w}\": shear)"),
            )),
            _ => {}
        }
    }
    let first = found.first()?.0;
    if found.iter().all(|f| f.0 == first) {
        Some((first, found[0].1.clone()))
    } else {
        None
    }
}

/// Tensile or shear from a read file's metadata, step names and column names (module docs), with
/// the evidence in words. `file` is the path as given: a test name in it counts as a test name.
pub(crate) fn infer(raw: &RawFile, file: &str) -> Option<(ModulusKind, String)> {
    let meta = |keys: &[&str]| -> Vec<(String, String)> {
        raw.metadata
            .iter()
            .filter(|(k, _)| {
                let k = k.trim().trim_end_matches(':').to_lowercase();
                keys.contains(&k.as_str())
            })
            .map(|(k, v)| (format!("`{}`", k.trim().trim_end_matches(':')), v.clone()))
            .collect()
    };
    if let Some(e) = level(
        &meta(GEOMETRY_KEYS),
        "geometry:",
        TENSILE_GEOMETRY,
        SHEAR_GEOMETRY,
    ) {
        return Some(e);
    }
    let mut tests = meta(TEST_KEYS);
    for b in &raw.blocks {
        if let Some(l) = &b.label {
            tests.push(("step".into(), l.clone()));
        }
    }
    if let Some(stem) = std::path::Path::new(file)
        .file_stem()
        .and_then(|s| s.to_str())
    {
        tests.push(("file name".into(), stem.to_string()));
    }
    if let Some(e) = level(&tests, "test name:", TENSILE_TEST, SHEAR_TEST) {
        return Some(e);
    }
    if let Some(e) = level(
        &meta(INSTRUMENT_KEYS),
        "instrument:",
        TENSILE_INSTRUMENT,
        SHEAR_INSTRUMENT,
    ) {
        return Some(e);
    }
    raw.mode_hint.clone()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dma::table::Block;

    fn raw(meta: &[(&str, &str)], steps: &[&str]) -> RawFile {
        RawFile {
            metadata: meta
                .iter()
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect(),
            blocks: steps
                .iter()
                .map(|s| Block {
                    label: Some(s.to_string()),
                    ..Block::default()
                })
                .collect(),
            mode_hint: None,
            ..RawFile::default()
        }
    }

    #[test]
    fn geometry_beats_instrument_and_test_name_beats_instrument() {
        // An MCR rheometer with a tension fixture measures E.
        let r = raw(
            &[
                ("Device", "MCR 702e"),
                ("Measuring System", "TF-DMA tension"),
            ],
            &[],
        );
        let (k, why) = infer(&r, "x.csv").unwrap();
        assert_eq!(k, ModulusKind::Tensile);
        assert!(why.contains("geometry"), "{why}");
        // The case: an MCR export of "TF-Sweep_Zug".
        let r = raw(&[("Device", "MCR 702e")], &["TF-Sweep_Zug"]);
        assert_eq!(infer(&r, "x.csv").unwrap().0, ModulusKind::Tensile);
        let r = raw(
            &[("Instrument type", "AresG2")],
            &["Frequency sweep (25 °C)"],
        );
        let (k, why) = infer(&r, "x.txt").unwrap();
        assert_eq!(k, ModulusKind::Shear);
        assert!(why.contains("AresG2") || why.contains("ares"), "{why}");
        let r = raw(&[("Instrument type", "RSA-G2")], &[]);
        assert_eq!(infer(&r, "x.txt").unwrap().0, ModulusKind::Tensile);
    }

    #[test]
    fn no_evidence_or_a_tie_gives_none() {
        assert!(infer(&raw(&[("Operator", "AB")], &["Frequency sweep"]), "a.csv").is_none());
        // Two steps of the same strength that disagree: no answer.
        let r = raw(&[], &["torsion sweep", "tension sweep"]);
        assert!(infer(&r, "a.csv").is_none());
        // A word inside a longer word does not count.
        assert!(infer(&raw(&[("Device", "MCRX")], &[]), "a.csv").is_none());
    }
}
