//! Quirk twins: the tests write the real `freq_user_raw.csv` (21 isotherms, EPLEXOR) in the ways
//! exports differ (UTF-16, semicolons with decimal commas, units inside names, K and rad/s, shear
//! only, |E*| with tan δ only, Latin-1 whitespace) and check each reads to the same measurement as
//! the plain file. The synthetic vendor-layout files under tests/data/synthetic/ must match it too.

use crate::shipped::data;
use std::f64::consts::PI;
use std::path::PathBuf;
use viscoroll::dma::{self, IngestOptions, Measurement};
use viscoroll::ModulusKind;

/// (f Hz, E' MPa, E'' MPa, T °C, set) of freq_user_raw.csv, lines 3–212.
fn rows() -> Vec<[f64; 5]> {
    let text = std::fs::read_to_string(data("pyvisco-ems-ca/freq_user_raw.csv")).unwrap();
    text.lines()
        .skip(2)
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.trim().parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3], v[4]]
        })
        .collect()
}

fn plain() -> Measurement {
    dma::read_files(
        &[data("pyvisco-ems-ca/freq_user_raw.csv")],
        &IngestOptions::default(),
    )
    .unwrap()
}

/// A fresh directory under target/ for files written by a test.
fn scratch(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("dma_quirks")
        .join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn read_bytes(name: &str, bytes: Vec<u8>) -> Measurement {
    dma::read_bytes(&[(name.to_string(), bytes)], &IngestOptions::default())
        .unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Same isotherms (count, nominal, points, values within `rel`, temperatures within `abs_t` K).
fn assert_same(a: &Measurement, b: &Measurement, rel: f64, abs_t: f64, what: &str) {
    assert_eq!(a.kind, b.kind, "{what}");
    assert_eq!(a.isotherms.len(), b.isotherms.len(), "{what}");
    for (i, (x, y)) in a.isotherms.iter().zip(&b.isotherms).enumerate() {
        assert_eq!(x.temp_nominal_c, y.temp_nominal_c, "{what}: isotherm {i}");
        assert!(
            (x.temp_mean_c - y.temp_mean_c).abs() <= abs_t,
            "{what}: isotherm {i}"
        );
        assert_eq!(x.points.len(), y.points.len(), "{what}: isotherm {i}");
        for (p, q) in x.points.iter().zip(&y.points) {
            let close = |u: f64, v: f64| (u - v).abs() <= rel * v.abs();
            assert!(
                close(p.freq_hz, q.freq_hz),
                "{what}: f {} vs {}",
                p.freq_hz,
                q.freq_hz
            );
            assert!(
                close(p.storage_pa, q.storage_pa),
                "{what}: M' {} vs {}",
                p.storage_pa,
                q.storage_pa
            );
            assert!(
                close(p.loss_pa, q.loss_pa),
                "{what}: M'' {} vs {}",
                p.loss_pa,
                q.loss_pa
            );
            match (p.temp_c, q.temp_c) {
                (Some(s), Some(t)) => assert!((s - t).abs() <= abs_t, "{what}"),
                (s, t) => assert_eq!(s, t, "{what}"),
            }
            assert_eq!(p.flags, q.flags, "{what}");
        }
    }
    assert_eq!(a.summary.points, b.summary.points, "{what}");
    assert_eq!(a.summary.by_flag, b.summary.by_flag, "{what}");
}

/// Rust's `{}` writes the shortest decimal that reads back to the same double.
fn table(
    header: &[&str],
    units: Option<&[&str]>,
    sep: &str,
    body: impl Fn(&[f64; 5]) -> Vec<f64>,
    comma: bool,
) -> String {
    let mut s = header.join(sep) + "\n";
    if let Some(u) = units {
        s += &(u.join(sep) + "\n");
    }
    for r in rows() {
        let cells: Vec<String> = body(&r)
            .iter()
            .map(|v| {
                let t = format!("{v}");
                if comma {
                    t.replace('.', ",")
                } else {
                    t
                }
            })
            .collect();
        s += &(cells.join(sep) + "\n");
    }
    s
}

fn same_values(r: &[f64; 5]) -> Vec<f64> {
    r.to_vec()
}

#[test]
fn utf16_semicolon_comma_and_latin1_twins_read_the_same() {
    let base = plain();
    // Values written exactly as in the file: equality to the last bit.
    let tsv = table(
        &["f", "E'", "E''", "T", "Set"],
        Some(&["Hz", "MPa", "MPa", "°C", "-"]),
        "\t",
        same_values,
        false,
    );
    let mut le = vec![0xFF, 0xFE];
    let mut be = vec![0xFE, 0xFF];
    for u in tsv.encode_utf16() {
        le.extend_from_slice(&u.to_le_bytes());
        be.extend_from_slice(&u.to_be_bytes());
    }
    let m = read_bytes("utf16le.txt", le);
    assert_eq!(m.sources[0].encoding, "UTF-16LE");
    assert_same(&m, &base, 0.0, 0.0, "UTF-16LE tab");
    assert_same(
        &read_bytes("utf16be.txt", be),
        &base,
        0.0,
        0.0,
        "UTF-16BE tab",
    );

    let semi = table(
        &["f", "E'", "E''", "T", "Set"],
        Some(&["Hz", "MPa", "MPa", "°C", "-"]),
        ";",
        same_values,
        true,
    );
    let m = read_bytes("semicolon.csv", semi.into_bytes());
    assert_eq!(
        m.sources[0]
            .metadata
            .get("decimal mark")
            .map(|s| s.as_str()),
        Some("comma")
    );
    assert_same(&m, &base, 0.0, 0.0, "semicolon + decimal comma");

    // Latin-1, whitespace-separated, bracketed unit row with a Latin-1 degree sign.
    let ws = table(
        &["f", "E'", "E\"", "Ts", "Set"],
        Some(&["[Hz]", "[MPa]", "[MPa]", "[°C]", "[]"]),
        "   ",
        same_values,
        false,
    );
    let latin1: Vec<u8> = ws.chars().map(|c| c as u32 as u8).collect();
    let m = read_bytes("latin1.txt", latin1);
    assert_eq!(m.sources[0].encoding, "windows-1252");
    assert_same(&m, &base, 0.0, 0.0, "Latin-1 whitespace");
}

#[test]
fn units_inside_names_read_the_same() {
    let base = plain();
    for header in [
        [
            "Frequency / Hz",
            "Storage modulus E' / MPa",
            "Loss modulus E'' / MPa",
            "Temperature / °C",
            "Segment",
        ],
        ["f (Hz)", "E' (MPa)", "E'' (MPa)", "T (°C)", "Set"],
        ["f [Hz]", "E'[MPa]", "E''[MPa]", "Temp. [°C]", "Set"],
        ["f in Hz", "E' in MPa", "E'' in MPa", "T in °C", "Set"],
    ] {
        let s = table(&header, None, ",", same_values, false);
        assert_same(
            &read_bytes("names.csv", s.into_bytes()),
            &base,
            0.0,
            0.0,
            header[1],
        );
    }
}

#[test]
fn kelvin_and_rad_per_s_read_the_same() {
    let base = plain();
    let s = table(
        &["omega", "E'", "E''", "T", "Set"],
        Some(&["rad/s", "GPa", "kPa", "K", "-"]),
        ",",
        |r| vec![2.0 * PI * r[0], r[1] / 1e3, r[2] * 1e3, r[3] + 273.15, r[4]],
        false,
    );
    // ω → f: one multiplication and one division (≤ 2 roundings); MPa → GPa → Pa and MPa → kPa → Pa
    // likewise: relative 1e-15 covers them. T + 273.15 − 273.15: absolute error ≤ 1e-13 K.
    assert_same(
        &read_bytes("kelvin.csv", s.into_bytes()),
        &base,
        1e-15,
        1e-13,
        "K and rad/s",
    );
}

#[test]
fn shear_only_twin_converts_back_to_the_same_tensile_moduli() {
    let base = plain();
    let s = table(
        &["f", "G'", "G''", "T", "Set"],
        Some(&["Hz", "MPa", "MPa", "°C", "-"]),
        ",",
        |r| vec![r[0], r[1] / 3.0, r[2] / 3.0, r[3], r[4]],
        false,
    );
    let m = read_bytes("shear.csv", s.into_bytes());
    assert_eq!(m.kind, ModulusKind::Shear);
    // ν = 0.5 (default): E = 2(1 + ν) G = 3 G; /3 then ·3 is within 2 roundings.
    assert_same(&m.to_tensile(), &base, 1e-15, 0.0, "shear only");
}

#[test]
fn complex_modulus_with_tan_delta_only_reads_the_same() {
    let base = plain();
    let s = table(
        &["f", "|E*|", "tan delta", "T", "Set"],
        Some(&["Hz", "MPa", "-", "°C", "-"]),
        ",",
        |r| vec![r[0], r[1].hypot(r[2]), r[2] / r[1], r[3], r[4]],
        false,
    );
    // |E*| = √(E'² + E''²), tan δ = E''/E' and back (E' = |E*|/√(1 + tan²δ), E'' = E'·tan δ): a
    // handful of roundings, 1e-14 relative.
    assert_same(
        &read_bytes("complex.csv", s.into_bytes()),
        &base,
        1e-14,
        0.0,
        "|E*| + tan δ",
    );
    // The phase angle in degrees instead of tan δ.
    let s = table(
        &["f", "E*", "phase angle", "T", "Set"],
        Some(&["Hz", "MPa", "°", "°C", "-"]),
        ",",
        |r| {
            vec![
                r[0],
                r[1].hypot(r[2]),
                r[2].atan2(r[1]).to_degrees(),
                r[3],
                r[4],
            ]
        },
        false,
    );
    assert_same(
        &read_bytes("phase.csv", s.into_bytes()),
        &base,
        1e-13,
        0.0,
        "|E*| + δ",
    );
}

#[test]
fn one_file_per_isotherm_reads_the_same_as_one_file() {
    let base = plain();
    let dir = scratch("per_isotherm");
    let mut paths = Vec::new();
    for set in 0..21 {
        let mut s = String::from("f,E',E'',T\nHz,MPa,MPa,°C\n");
        for r in rows().iter().filter(|r| r[4] == set as f64) {
            s += &format!("{},{},{},{}\n", r[0], r[1], r[2], r[3]);
        }
        let p = dir.join(format!("sweep{set:02}.csv"));
        std::fs::write(&p, s).unwrap();
        paths.push(p);
    }
    let m = dma::read_files(&paths, &IngestOptions::default()).unwrap();
    assert_eq!(m.sources.len(), 21);
    assert_eq!(m.isotherms.len(), 21);
    for (x, y) in m.isotherms.iter().zip(&base.isotherms) {
        assert_eq!(x.temp_nominal_c, y.temp_nominal_c);
        assert_eq!(x.temp_mean_c, y.temp_mean_c);
        for (p, q) in x.points.iter().zip(&y.points) {
            assert_eq!(
                (p.freq_hz, p.storage_pa, p.loss_pa, p.temp_c),
                (q.freq_hz, q.storage_pa, q.loss_pa, q.temp_c)
            );
        }
    }
}

#[test]
fn synthetic_vendor_layouts_match_the_real_csv() {
    let base = plain();
    let mut first3 = base.clone();
    first3.isotherms.truncate(3);
    first3.summary.points = 30;
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/synthetic");
    for (file, format, kind) in [
        ("rheocompass_en.csv", "rheocompass", ModulusKind::Shear),
        ("rheocompass_de.csv", "rheocompass", ModulusKind::Shear),
        ("rheocompass_fr.csv", "rheocompass", ModulusKind::Shear),
        ("trios_text.txt", "trios-text", ModulusKind::Shear),
        ("proteus_ascii.txt", "proteus", ModulusKind::Tensile),
    ] {
        let m = dma::read_files(&[dir.join(file)], &IngestOptions::default()).unwrap();
        assert_eq!(m.sources[0].format, format, "{file}");
        assert_eq!(m.kind, kind, "{file}");
        let e = m.to_tensile();
        // Written with 12 significant digits (make_synthetic.py): relative 5e-12 per value, a few
        // roundings more through ω and G = E/3.
        assert_eq!(e.isotherms.len(), 3, "{file}");
        for (x, y) in e.isotherms.iter().zip(&first3.isotherms) {
            assert_eq!(x.temp_nominal_c, y.temp_nominal_c, "{file}");
            assert!((x.temp_mean_c - y.temp_mean_c).abs() < 1e-12, "{file}");
            for (p, q) in x.points.iter().zip(&y.points) {
                for (u, v) in [
                    (p.freq_hz, q.freq_hz),
                    (p.storage_pa, q.storage_pa),
                    (p.loss_pa, q.loss_pa),
                ] {
                    assert!((u - v).abs() <= 1e-11 * v.abs(), "{file}: {u} vs {v}");
                }
            }
        }
    }
}
