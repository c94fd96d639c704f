//! The `dma` readers on every real export shipped in data/ (see data/SOURCES.md): isotherm counts,
//! temperatures, frequencies and moduli in Pa against values read by hand from the files (each with
//! the line or sheet row it was read from).

use std::path::PathBuf;
use viscoroll::dma::{self, Flag, IngestOptions, Measurement, Severity};
use viscoroll::{ModulusKind, ShiftLaw};

pub use super::shipped::data;

fn read(paths: &[PathBuf]) -> Measurement {
    dma::read_files(paths, &IngestOptions::default()).unwrap_or_else(|e| panic!("{e}"))
}

/// |a − b| ≤ rel·|b|.
fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs()
}

/// Find the point read from a line (or sheet row).
fn at_line(m: &Measurement, line: usize) -> (&dma::Isotherm, &dma::DataPoint) {
    m.isotherms
        .iter()
        .flat_map(|i| i.points.iter().map(move |p| (i, p)))
        .find(|(_, p)| p.line == line)
        .unwrap_or_else(|| panic!("no point from line {line}"))
}

/// The 10 frequencies of the EMS-CA sweeps as written in freq_user_raw.csv, lines 3–12.
const EMS_FREQS_HZ: [f64; 10] = [
    0.1, 0.215443, 0.464159, 1.0, 2.15443, 4.64159, 10.0, 21.5443, 46.4159, 100.0,
];

#[test]
fn eplexor_xls_has_21_isotherms_of_10_points_at_the_documented_temperatures() {
    let m = read(&[data("pyvisco-ems-ca/freq_Eplexor_raw.xls")]);
    assert_eq!(m.kind, ModulusKind::Tensile);
    assert_eq!(m.sources[0].format, "eplexor");
    // sha256sum data/pyvisco-ems-ca/freq_Eplexor_raw.xls (coreutils)
    assert_eq!(
        m.sources[0].sha256,
        "60ce5205c820699ef1f7ecdb03d31cb0f58ff105495a728ed2292ffe259b995c"
    );
    assert_eq!(
        m.sources[0]
            .metadata
            .get("Measurement type")
            .map(|s| s.as_str()),
        Some("Temp. Freq. Sweep")
    );
    assert_eq!(
        m.sources[0]
            .metadata
            .get("Material / Remark")
            .map(|s| s.as_str()),
        Some("EMS-CA")
    );
    assert_eq!(m.isotherms.len(), 21);
    for (i, iso) in m.isotherms.iter().enumerate() {
        // SOURCES.md: 21 isotherms −50 … 100 °C, i.e. steps of 7.5 K.
        let nominal = -50.0 + 7.5 * i as f64;
        assert_eq!(iso.temp_nominal_c, nominal, "isotherm {i}");
        assert_eq!(iso.nominal_source, "step grid");
        assert!(
            (iso.temp_mean_c - nominal).abs() <= 0.5,
            "isotherm {i}: {}",
            iso.temp_mean_c
        );
        assert_eq!(iso.points.len(), 10);
        for (p, f) in iso.points.iter().zip(EMS_FREQS_HZ) {
            // The sheet holds the doubles typed as these decimals: equal to the last bit.
            assert_eq!(p.freq_hz, f);
            assert!(p.flags.is_empty());
        }
        assert_eq!(iso.sheet.as_deref(), Some("Exported Data"));
    }
    // Read by hand with a spreadsheet, sheet `Exported Data`:
    // row 3:   f 0.1, T −49.9612, E' 8097.1755453452715 MPa, E'' 93.0744904454984 MPa
    // row 103: f 0.1, T 24.9569,  E' 5371.470844440021 MPa,  E'' 371.9058432051331 MPa
    // row 212: f 100, T 100.001,  E' 585.8391184361864 MPa,  E'' 223.41197000791792 MPa
    // MPa → Pa is one multiplication by 1e6: at most one rounding (relative 1.1e-16), so 4e-16.
    for (row, f, t, e1, e2) in [
        (3, 0.1, -49.9612, 8097.1755453452715, 93.0744904454984),
        (103, 0.1, 24.9569, 5371.470844440021, 371.9058432051331),
        (212, 100.0, 100.001, 585.8391184361864, 223.41197000791792),
    ] {
        let (_, p) = at_line(&m, row);
        assert_eq!(p.freq_hz, f);
        assert_eq!(p.temp_c, Some(t));
        assert!(close(p.storage_pa, e1 * 1e6, 4e-16), "row {row}");
        assert!(close(p.loss_pa, e2 * 1e6, 4e-16), "row {row}");
    }
    assert_eq!(m.summary.errors + m.summary.warnings, 0, "{:?}", m.warnings);
}

#[test]
fn eplexor_csv_twin_reads_to_the_same_isotherms_as_the_xls() {
    let x = read(&[data("pyvisco-ems-ca/freq_Eplexor_raw.xls")]);
    let c = read(&[data("pyvisco-ems-ca/freq_user_raw.csv")]);
    assert_eq!(c.sources[0].encoding, "UTF-8 BOM");
    assert_eq!(c.isotherms.len(), 21);
    // freq_user_raw.csv line 3: `0.1,8097.175545,93.07449045,-49.9612,0`
    let (iso, p) = at_line(&c, 3);
    assert_eq!((p.freq_hz, p.temp_c), (0.1, Some(-49.9612)));
    assert!(close(p.storage_pa, 8097.175545e6, 4e-16));
    assert!(close(p.loss_pa, 93.07449045e6, 4e-16));
    assert_eq!(iso.temp_nominal_c, -50.0);
    for (a, b) in x.isotherms.iter().zip(&c.isotherms) {
        assert_eq!(a.temp_nominal_c, b.temp_nominal_c);
        assert_eq!(a.points.len(), b.points.len());
        for (p, q) in a.points.iter().zip(&b.points) {
            // The CSV rounds to 10 significant digits: relative difference ≤ 5e-10.
            assert!(close(q.storage_pa, p.storage_pa, 5e-10));
            assert!(close(q.loss_pa, p.loss_pa, 5e-10));
            assert_eq!(q.freq_hz, p.freq_hz);
            assert_eq!(q.temp_c, p.temp_c);
        }
    }
}

#[test]
fn eplexor_master_export_and_its_shiftlist() {
    let m = read(&[data("pyvisco-ems-ca/freq_Eplexor_master.xls")]);
    // A master curve: all 210 points at the reference temperature (column T = 24.97374 in every row).
    assert_eq!(m.isotherms.len(), 1);
    assert_eq!(m.isotherms[0].points.len(), 210);
    // Mean of 210 equal values: the summation may round, by far less than 1e-12 K.
    assert!((m.isotherms[0].temp_mean_c - 24.97374).abs() < 1e-12);
    assert!(m.issues.iter().any(|i| i.flag == Flag::SingleIsotherm));
    // Shifted sweeps overlap: rows 86, 108 and 168 repeat a reduced frequency of an earlier row.
    let dups: Vec<&str> = m
        .issues
        .iter()
        .filter(|i| i.flag == Flag::DuplicateFrequency)
        .map(|i| i.location.as_str())
        .collect();
    assert_eq!(
        dups,
        [
            "sheet `Exported Data` row 86",
            "sheet `Exported Data` row 108",
            "sheet `Exported Data` row 168"
        ]
    );
    let (table, wlf) =
        dma::read_eplexor_shiftlist(&data("pyvisco-ems-ca/freq_Eplexor_master.xls")).unwrap();
    // Sheet `Shiftlist`: row 1 `Ref.Temp.` `25.0 °C`; row 2 `WLF` `C1 : 13.50` `C2 : 141.19 K`.
    assert_eq!(
        wlf,
        Some(ShiftLaw::Wlf {
            t_ref_c: 25.0,
            c1: 13.5,
            c2_k: 141.19
        })
    );
    let ShiftLaw::Table { t_ref_c, points } = table else {
        panic!("not a table")
    };
    assert_eq!(t_ref_c, 25.0);
    // Rows 4–24: 21 (T, shift) pairs; row 24 is (−49.98103, 15.6), row 4 (99.96349, −4.08),
    // row 16 (24.97374, 0).
    assert_eq!(points.len(), 21);
    assert!(close(points[0].0, -49.98103, 1e-15) && close(points[0].1, 15.6, 1e-14));
    assert!(close(points[20].0, 99.96349, 1e-15) && close(points[20].1, -4.08, 1e-14));
    assert!(points.contains(&(24.97374, 0.0)));
    assert!(points.windows(2).all(|w| w[0].0 < w[1].0));
}

#[test]
fn shift_factor_csv_reads_as_a_table_law() {
    let law = dma::read_shift_factors(&data("pyvisco-ems-ca/freq_user_master__shift_factors.csv"))
        .unwrap();
    let ShiftLaw::Table { t_ref_c, points } = law else {
        panic!("not a table")
    };
    // Lines 3–23 of the file: (100, −11.7) … (−50, 12.75); log_aT = 0 at T = −5 (line 17).
    assert_eq!(t_ref_c, -5.0);
    assert_eq!(points.len(), 21);
    assert_eq!(points[0], (-50.0, 12.75));
    assert_eq!(points[20], (100.0, -11.7));
}

/// Mean of column Ts over lines 3–62 of each file, computed with awk (independently of this crate):
/// `awk 'NR>2 && NF>10 {s+=$2; n++} END {print s/n}' data/dmasuite-tensile/T0.txt`.
const DMASUITE_MEANS: [(u32, f64); 4] = [(0, -2.876), (60, 56.696), (100, 98.637), (105, 103.701)];

#[test]
fn dmasuite_22_files_one_isotherm_each() {
    let nominal: Vec<u32> = (0..=105).step_by(5).collect();
    let paths: Vec<PathBuf> = nominal
        .iter()
        .map(|t| data(&format!("dmasuite-tensile/T{t}.txt")))
        .collect();
    let m = read(&paths);
    assert_eq!(m.kind, ModulusKind::Tensile);
    assert_eq!(m.isotherms.len(), 22);
    for (iso, t) in m.isotherms.iter().zip(&nominal) {
        assert_eq!(iso.temp_nominal_c, *t as f64);
        assert_eq!(iso.nominal_source, "file name");
        assert_eq!(iso.points.len(), 60);
        // The measured temperatures of these files run 1.3–3.3 K below the file names' nominal
        // values (a property of the data, reported as a `nominal_offset` warning per file).
        let off = iso.temp_mean_c - *t as f64;
        assert!((-3.35..-1.25).contains(&off), "T{t}: {off}");
        assert_eq!(iso.points[0].freq_hz, 9.99999e-2);
        assert_eq!(iso.points[59].freq_hz, 8.91251e1);
        assert!(iso.points.windows(2).all(|w| w[1].freq_hz > w[0].freq_hz));
    }
    for (t, mean) in DMASUITE_MEANS {
        let iso = m
            .isotherms
            .iter()
            .find(|i| i.temp_nominal_c == t as f64)
            .unwrap();
        // awk printed 3 decimals.
        assert!((iso.temp_mean_c - mean).abs() < 5e-4, "T{t}");
    }
    assert_eq!(m.summary.by_flag.get("nominal_offset"), Some(&22));
    assert_eq!(m.summary.flagged_points, 0);
    // T0.txt line 3:  Ts −5.91320e−01 °C, f 9.99999e−02 Hz, E' 2.93911e+03 MPa, E" 5.45177e+01 MPa
    // T0.txt line 62: Ts −3.56780 °C, f 8.91251e+01 Hz, E' 3.25938e+03 MPa, E" 1.26243e+02 MPa
    let t0 = m
        .isotherms
        .iter()
        .find(|i| i.temp_nominal_c == 0.0)
        .unwrap();
    let (p, q) = (&t0.points[0], &t0.points[59]);
    assert_eq!((p.line, q.line), (3, 62));
    assert_eq!(p.temp_c, Some(-5.91320e-1));
    assert!(close(p.storage_pa, 2.93911e9, 4e-16) && close(p.loss_pa, 5.45177e7, 4e-16));
    assert_eq!(q.temp_c, Some(-3.56780));
    assert!(close(q.storage_pa, 3.25938e9, 4e-16) && close(q.loss_pa, 1.26243e8, 4e-16));
    // T105.txt line 3: Ts 1.04500e+02, E' 2.30364e+01 MPa, E" 2.78313e+00 MPa.
    let t105 = &m.isotherms[21];
    assert_eq!(t105.points[0].temp_c, Some(104.5));
    assert!(close(t105.points[0].storage_pa, 2.30364e7, 4e-16));
    assert!(close(t105.points[0].loss_pa, 2.78313e6, 4e-16));
    // Latin-1 degree sign decoded; the trailing label line kept as metadata.
    let s0 = &m.sources[0];
    assert_eq!(s0.encoding, "windows-1252");
    assert!(s0.columns.iter().any(|c| c.name == "Ts" && c.unit == "°C"));
    assert_eq!(
        s0.metadata.get("trailing text").map(|s| s.as_str()),
        Some("]1[JAL03-01_Freq0.1-100_")
    );
    // sha256sum data/dmasuite-tensile/T0.txt
    assert_eq!(
        s0.sha256,
        "4c4ce71e20e1619f764fdce291efafa6d29997a83ba9cc6d39e1a4c2fbe7bfec"
    );
}

#[test]
fn trios_lims_20_steps_of_17_points_in_shear() {
    let m = read(&[data("trios-aresg2-lims/frequency_sweep_tts.txt")]);
    assert_eq!(m.sources[0].format, "trios-lims");
    assert_eq!(m.kind, ModulusKind::Shear);
    assert_eq!(
        m.sources[0]
            .metadata
            .get("Instrument type")
            .map(|s| s.as_str()),
        Some("AresG2")
    );
    assert_eq!(m.isotherms.len(), 20);
    for (i, iso) in m.isotherms.iter().enumerate() {
        // Step names `Frequency sweep (−40.0 °C)` … `(150.0 °C)`, sorted upwards.
        let nominal = -40.0 + 10.0 * i as f64;
        assert_eq!(iso.temp_nominal_c, nominal);
        assert_eq!(iso.nominal_source, "file");
        assert_eq!(
            iso.label.as_deref(),
            Some(format!("Frequency sweep ({nominal:.1} °C)").as_str())
        );
        // awk over column 3 per step: the largest |mean − nominal| is 0.021 K (30 °C step).
        assert!((iso.temp_mean_c - nominal).abs() <= 0.025, "{nominal}");
        assert_eq!(iso.points.len(), 17);
        // Column `Frequency` [Hz]: 0.100000001490116 … 20 (7 points per decade).
        assert_eq!(iso.points[0].freq_hz, 0.100000001490116);
        assert_eq!(iso.points[16].freq_hz, 20.0);
    }
    // Line 104 (first `Data point` of the 150 °C step): Temperature 149.977996826172 °C,
    // Storage modulus 0.010044287109375 MPa, Loss modulus 0.00328556372070312 MPa.
    let (iso, p) = at_line(&m, 104);
    assert_eq!(iso.temp_nominal_c, 150.0);
    assert_eq!(p.temp_c, Some(149.977996826172));
    assert!(close(p.storage_pa, 0.010044287109375e6, 4e-16));
    assert!(close(p.loss_pa, 0.00328556372070312e6, 4e-16));
    // Line 120 (last point of that step): 20 Hz, G' 0.03354712109375 MPa.
    let (_, p) = at_line(&m, 120);
    assert_eq!(p.freq_hz, 20.0);
    assert!(close(p.storage_pa, 0.03354712109375e6, 4e-16));
    // Line 538 (−40 °C, 20 Hz): Loss modulus −29.868376 MPa: kept, flagged, reported.
    let (iso, p) = at_line(&m, 538);
    assert_eq!(iso.temp_nominal_c, -40.0);
    assert!(close(p.loss_pa, -29.868376e6, 4e-16));
    assert_eq!(p.flags, ["non_positive"]);
    assert_eq!(m.summary.errors, 1);
    assert_eq!(m.summary.points, 340);
    let issue = &m.issues[0];
    assert_eq!(issue.severity, Severity::Error);
    assert_eq!(issue.location, "line 538");
    assert_eq!(issue.column, "Loss modulus");
    assert!(issue
        .message
        .contains("frequency_sweep_tts.txt: line 538: column `Loss modulus`"));
}

#[test]
fn shear_data_converts_to_tensile_with_the_stated_poisson_ratio() {
    let opts = IngestOptions {
        poisson: 0.45,
        ..IngestOptions::default()
    };
    let m = dma::read_files(&[data("trios-aresg2-lims/frequency_sweep_tts.txt")], &opts).unwrap();
    let e = m.to_tensile();
    assert_eq!(e.kind, ModulusKind::Tensile);
    let (p, q) = (&m.isotherms[3].points[5], &e.isotherms[3].points[5]);
    // E = 2(1 + ν) G = 2.9 G.
    assert!(close(q.storage_pa, 2.9 * p.storage_pa, 4e-16));
    assert!(close(q.loss_pa, 2.9 * p.loss_pa, 4e-16));
}

#[test]
fn measurement_json_round_trips() {
    let m = read(&[data("pyvisco-ems-ca/freq_Eplexor_raw.xls")]);
    let s = serde_json::to_string(&m).unwrap();
    let back: Measurement = serde_json::from_str(&s).unwrap();
    assert_eq!(back, m);
}
