//! Bad input: each class gives its own message naming file, place, column and value; the data
//! checks flag (and keep) bad points; no input bytes make a reader panic.

use super::dma_real::data;
use proptest::prelude::*;
use viscoroll::dma::{self, DmaError, Flag, IngestOptions, Measurement, Severity};
use viscoroll::ModulusKind;

fn err(name: &str, text: &str, opts: &IngestOptions) -> (DmaError, String) {
    match dma::read_bytes(&[(name.to_string(), text.as_bytes().to_vec())], opts) {
        Ok(_) => panic!("{name} was read"),
        Err(e) => {
            let s = e.to_string();
            (e, s)
        }
    }
}

fn ok(name: &str, text: &str, opts: &IngestOptions) -> Measurement {
    dma::read_bytes(&[(name.to_string(), text.as_bytes().to_vec())], opts)
        .unwrap_or_else(|e| panic!("{e}"))
}

const GOOD: &str = "f,E',E'',T\nHz,MPa,MPa,°C\n1,10,1,20\n10,11,1.1,20\n1,5,2,30\n10,6,2.1,30\n";

#[test]
fn unit_errors_name_the_column_and_the_fix() {
    let d = IngestOptions::default();
    ok("good.csv", GOOD, &d);

    let (e, s) = err("nounit.csv", "f,E',E'',T\n1,10,1,20\n10,11,1,20\n", &d);
    assert!(matches!(e, DmaError::MissingUnit { .. }));
    assert_eq!(
        s,
        "nounit.csv: line 1: column `f` (frequency) has no unit; units are never guessed: give it with --freq-unit"
    );

    let (e, s) = err("mpa.csv", &GOOD.replace("Hz,MPa,MPa", "Hz,mPa,MPa"), &d);
    assert!(matches!(e, DmaError::UnknownUnit { .. }));
    assert_eq!(s, "mpa.csv: line 1: column `E'` (storage modulus): unknown unit `mPa` (expected Pa, kPa, MPa, GPa, N/m², N/mm², psi, dyn/cm²)");

    let (_, s) = err("pers.csv", &GOOD.replace("Hz,", "1/s,"), &d);
    assert_eq!(
        s,
        "pers.csv: line 1: column `f` (frequency): unknown unit `1/s` (expected Hz, kHz, rad/s)"
    );

    let kpa = IngestOptions {
        modulus_unit: dma::units::ModulusUnit::parse("kPa"),
        ..IngestOptions::default()
    };
    let (e, s) = err("conflict.csv", GOOD, &kpa);
    assert!(matches!(e, DmaError::UnitConflict { .. }));
    assert!(
        s.starts_with("conflict.csv: line 1: column `E'` is in `MPa` but --modulus-unit"),
        "{s}"
    );
}

#[test]
fn missing_columns_and_bad_cells_are_named() {
    let d = IngestOptions::default();
    let (e, s) = err("nomod.csv", "f,X,T\nHz,MPa,°C\n1,10,20\n10,11,20\n", &d);
    assert!(matches!(e, DmaError::MissingColumn { .. }));
    assert!(
        s.starts_with("nomod.csv: line 1: no modulus column (looked for E′ and E″"),
        "{s}"
    );
    assert!(
        s.ends_with("the columns are: `f` [Hz], `X` [MPa], `T` [°C]"),
        "{s}"
    );

    let (e, s) = err("nofreq.csv", "g,E',E'',T\nHz,MPa,MPa,°C\n1,10,1,20\n", &d);
    assert!(matches!(e, DmaError::MissingColumn { .. }));
    assert!(
        s.starts_with("nofreq.csv: line 1: no frequency column"),
        "{s}"
    );

    let (e, s) = err(
        "text.csv",
        &GOOD.replace("10,11,1.1,20", "10,abc,1.1,20"),
        &d,
    );
    assert!(matches!(e, DmaError::BadNumber { .. }));
    assert_eq!(
        s,
        "text.csv: line 4: column `E'`: cannot read `abc` as a number"
    );

    let (e, s) = err("header.csv", "f,E',E'',T\nHz,MPa,MPa,°C\n", &d);
    assert!(matches!(e, DmaError::NoData { .. }));
    assert!(s.starts_with("header.csv: no data rows"), "{s}");

    let (_, s) = err("empty.csv", "", &d);
    assert_eq!(s, "empty.csv: no data rows (the file is empty)");
}

#[test]
fn tensile_or_shear_is_never_guessed() {
    let d = IngestOptions::default();
    let amb = "f,Storage modulus,Loss modulus,T\nHz,MPa,MPa,°C\n1,10,1,20\n10,11,1,20\n";
    let (e, s) = err("amb.csv", amb, &d);
    assert!(matches!(e, DmaError::AmbiguousMode { .. }));
    assert_eq!(s, "amb.csv: line 1: column `Storage modulus` does not say whether it is tensile (E) or shear (G), and the file names no geometry, test or instrument that does; give --mode tensile or --mode shear");
    let shear = IngestOptions {
        mode: Some(ModulusKind::Shear),
        ..IngestOptions::default()
    };
    assert_eq!(ok("amb.csv", amb, &shear).kind, ModulusKind::Shear);
    let (e, _) = err("good.csv", GOOD, &shear);
    assert!(matches!(e, DmaError::MixedMode { .. }));

    let two = [
        ("a.csv".to_string(), GOOD.as_bytes().to_vec()),
        ("b.csv".to_string(), GOOD.replace("E'", "G'").into_bytes()),
    ];
    let e = dma::read_bytes(&two, &d).unwrap_err();
    assert_eq!(
        e.to_string(),
        "b.csv: holds shear moduli but tensile was expected (a.csv holds tensile moduli)"
    );
}

#[test]
fn temperature_comes_from_the_file_or_is_refused() {
    let d = IngestOptions::default();
    let (e, s) = err("sweep.csv", "f,E',E''\nHz,MPa,MPa\n1,10,1\n10,11,1\n", &d);
    assert!(matches!(e, DmaError::NoTemperature { .. }));
    assert_eq!(s, "sweep.csv: line 3: no temperature: the file has no temperature column and no set temperature");
    // …unless the file name states it.
    let m = ok("T25.csv", "f,E',E''\nHz,MPa,MPa\n1,10,1\n10,11,1\n", &d);
    assert_eq!(m.isotherms[0].temp_nominal_c, 25.0);
    assert!(m.warnings[0].contains("using 25 °C from the file name"));
}

#[test]
fn broken_instrument_files_say_what_is_wrong() {
    let d = IngestOptions::default();
    let (e, s) = err(
        "a.txt",
        "[Version]\nTA Instruments LIMS export format version\t0\n",
        &d,
    );
    assert!(matches!(e, DmaError::Structure { .. }));
    assert_eq!(
        s,
        "a.txt: whole file: TRIOS LIMS export without any `[Step]` block"
    );

    let (_, s) = err(
        "p.txt",
        "#DECIMAL:FOO\n#SEPARATOR:TAB\n##f/Hz\tE'/MPa\n",
        &d,
    );
    assert_eq!(
        s,
        "p.txt: line 1: #DECIMAL must be POINT or COMMA, found `FOO`"
    );

    let eplexor = IngestOptions {
        format: Some(dma::Format::Eplexor),
        ..IngestOptions::default()
    };
    let (e, s) = err("text.csv", GOOD, &eplexor);
    assert!(matches!(e, DmaError::UnknownFormat { .. }));
    assert!(s.contains("`eplexor` needs an Excel workbook"), "{s}");

    let mut xls = std::fs::read(data("pyvisco-ems-ca/freq_Eplexor_raw.xls")).unwrap();
    xls.truncate(3000);
    let e = dma::read_bytes(&[("cut.xls".into(), xls)], &d).unwrap_err();
    assert!(matches!(e, DmaError::Excel { .. }));
    assert!(
        e.to_string()
            .starts_with("cut.xls: cannot read the Excel workbook: "),
        "{e}"
    );
}

#[test]
fn missing_files_and_bad_settings_are_refused() {
    let d = IngestOptions::default();
    let e = dma::read_files(&["no/such/file.csv"], &d).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("no/such/file.csv: cannot read the file: "),
        "{e}"
    );

    let bad = IngestOptions {
        poisson: 0.7,
        ..IngestOptions::default()
    };
    let e = dma::read_bytes(&[("good.csv".into(), GOOD.into())], &bad).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid setting poisson = 0.7: Poisson's ratio must lie in (−1, 0.5]"
    );

    let none: [&str; 0] = [];
    assert_eq!(
        dma::read_files(&none, &d).unwrap_err().to_string(),
        "no input files"
    );
}

#[test]
fn checks_flag_and_keep_bad_points() {
    // Two isotherms; lines (1-based): 3–12 at 20 °C, 13–16 at 30 °C.
    let text = "f,E',E'',T\nHz,MPa,MPa,°C\n\
        0.1,10,1,20\n\
        0.3,10.5,1.05,20\n\
        1,11,1.1,20\n\
        2,---,1.2,20\n\
        3,NaN,1.3,20\n\
        5,200,1.4,20.1\n\
        7,13,1.45,20\n\
        10,14,-1,20\n\
        10,15,1.5,20\n\
        20,16,1.6,20\n\
        1,5,2,30\n\
        0.5,5.5,2.1,30\n\
        10,6,0,30\n\
        100,7,2.3,30\n";
    let m = ok("checks.csv", text, &IngestOptions::default());
    assert_eq!(m.isotherms.len(), 2);
    assert_eq!(m.summary.points, 14, "every point kept");
    let flags = |line: usize| -> Vec<String> {
        m.isotherms
            .iter()
            .flat_map(|i| &i.points)
            .find(|p| p.line == line)
            .unwrap()
            .flags
            .clone()
    };
    assert_eq!(flags(6), ["missing"]);
    assert_eq!(flags(7), ["not_a_number"]);
    // E' 200 MPa at 5 Hz between 11 MPa (1 Hz) and 13 MPa (7 Hz): 1.2 decades off their line.
    assert_eq!(flags(8), ["outlier"]);
    assert_eq!(flags(10), ["non_positive"]);
    assert_eq!(flags(11), ["duplicate_frequency"]);
    assert_eq!(flags(14), ["non_monotonic"]);
    assert_eq!(flags(15), ["non_positive"]);
    for clean in [3, 4, 5, 9, 12, 13, 16] {
        assert!(flags(clean).is_empty(), "line {clean}: {:?}", flags(clean));
    }
    let msg = |flag: Flag| {
        m.issues
            .iter()
            .find(|i| i.flag == flag)
            .unwrap_or_else(|| panic!("{flag:?}"))
            .message
            .clone()
    };
    assert_eq!(msg(Flag::Missing), "checks.csv: line 6: column `E'`: storage modulus is missing; the point is kept, flagged `missing`");
    assert_eq!(msg(Flag::NotANumber), "checks.csv: line 7: column `E'`: storage modulus is NaN; the point is kept, flagged `not_a_number`");
    assert_eq!(msg(Flag::NonPositive), "checks.csv: line 10: column `E''`: loss modulus -1e6 is not positive; the point is kept, flagged `non_positive`");
    assert_eq!(
        msg(Flag::DuplicateFrequency),
        "checks.csv: line 11: column `f`: frequency 10 Hz appears twice in the isotherm at 20.0 °C"
    );
    assert_eq!(msg(Flag::NonMonotonic), "checks.csv: line 14: column `f`: frequency 0.5 Hz after 1 Hz goes against the sweep of the isotherm at 30.0 °C");
    assert!(
        msg(Flag::Outlier).starts_with(
            "checks.csv: line 8: column `E'`: storage modulus 2.0000e8 Pa is 1.20 decades"
        ),
        "{}",
        msg(Flag::Outlier)
    );
    assert_eq!(m.summary.errors, 4);
    assert_eq!(m.summary.by_flag.get("outlier"), Some(&1));
    assert!(m
        .issues
        .iter()
        .filter(|i| i.severity == Severity::Error)
        .all(|i| matches!(i.flag, Flag::Missing | Flag::NotANumber | Flag::NonPositive)));
    // One isotherm only: a warning for the whole measurement.
    let one = ok(
        "one.csv",
        "f,E',E'',T\nHz,MPa,MPa,°C\n1,10,1,20\n10,11,1,20\n",
        &IngestOptions::default(),
    );
    assert_eq!(one.issues[0].flag, Flag::SingleIsotherm);
    assert_eq!(
        one.issues[0].message,
        "only one isotherm (at 20.0 °C): a master curve needs several temperatures"
    );
    // NaN survives the JSON round trip (serde_json writes null).
    let back: Measurement = serde_json::from_str(&serde_json::to_string(&m).unwrap()).unwrap();
    let p = back.isotherms[0]
        .points
        .iter()
        .find(|p| p.line == 7)
        .unwrap();
    assert!(p.storage_pa.is_nan());
}

#[test]
fn damaged_xls_dimensions_are_refused_before_allocation() {
    let good = std::fs::read(data("pyvisco-ems-ca/freq_Eplexor_raw.xls")).unwrap();
    assert_eq!(dma::xls_guard::check(&good), Ok(()));
    let master = std::fs::read(data("pyvisco-ems-ca/freq_Eplexor_master.xls")).unwrap();
    assert_eq!(dma::xls_guard::check(&master), Ok(()));
    // The EPLEXOR file's DIMENSIONS record (type 0x0200, length 10: first row, last row + 1, first
    // column, last column + 1, u16 each) is at byte 7856: `00 02 0a 00 00 00 d4 00 00 00 14 00`.
    let at = 7856;
    assert_eq!(
        good[at..at + 12],
        [0x00, 0x02, 0x0A, 0x00, 0, 0, 0xD4, 0, 0, 0, 0x14, 0]
    );
    let mut bad = good.clone();
    bad[at + 6..at + 8].copy_from_slice(&[0xFF, 0xFF]);
    bad[at + 10..at + 12].copy_from_slice(&[0xFF, 0xFF]);
    let e = dma::read_bytes(&[("dims.xls".into(), bad)], &IngestOptions::default()).unwrap_err();
    assert!(
        e.to_string().starts_with(
            "dims.xls: cannot read the Excel workbook: a sheet declares 65535 rows × 65535 columns"
        ),
        "{e}"
    );
    // A FAT sector id far past the end of the file (header DIFAT entry 0 at byte 0x4C).
    let mut bad = good.clone();
    bad[0x4C..0x50].copy_from_slice(&0x4000_0000u32.to_le_bytes());
    let e = dma::read_bytes(&[("fat.xls".into(), bad)], &IngestOptions::default()).unwrap_err();
    assert!(
        e.to_string().contains("lies beyond the end of the file"),
        "{e}"
    );
}

fn no_panic(name: &str, bytes: Vec<u8>) {
    let opts = IngestOptions::default();
    // Ok or Err are both fine; a panic fails the test.
    let _ = dma::read_bytes(&[(name.to_string(), bytes)], &opts);
}

fn seeds() -> Vec<(&'static str, Vec<u8>)> {
    let mut v: Vec<(&'static str, Vec<u8>)> = vec![("good.csv", GOOD.as_bytes().to_vec())];
    let trios = std::fs::read(data("trios-aresg2-lims/frequency_sweep_tts.txt")).unwrap();
    v.push(("trios.txt", trios[..6000].to_vec()));
    v.push((
        "T0.txt",
        std::fs::read(data("dmasuite-tensile/T0.txt")).unwrap(),
    ));
    let dir = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/synthetic");
    v.push((
        "rc.csv",
        std::fs::read(dir.join("rheocompass_de.csv")).unwrap(),
    ));
    v.push((
        "p.txt",
        std::fs::read(dir.join("proteus_ascii.txt")).unwrap(),
    ));
    v.push(("t.txt", std::fs::read(dir.join("trios_text.txt")).unwrap()));
    v
}

proptest! {
    // 200 random inputs per property keep the run well under a second.
    // The run's seed (tests/seed.rs), printed so that a failure can be replayed.
    #![proptest_config(ProptestConfig { cases: 200, rng_seed: proptest::test_runner::RngSeed::Fixed(crate::tests::seed::seed("dma_errors::never_panic")), .. ProptestConfig::default() })]

    #[test]
    fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        no_panic("random.bin", bytes);
    }

    #[test]
    fn mutated_exports_never_panic(seed in 0usize..6, edits in proptest::collection::vec((any::<u32>(), any::<u8>(), 0u8..3), 1..12)) {
        let (name, mut bytes) = seeds().swap_remove(seed);
        for (pos, b, op) in edits {
            if bytes.is_empty() { break; }
            let i = pos as usize % bytes.len();
            match op {
                0 => bytes[i] = b,
                1 => { bytes.remove(i); }
                _ => bytes.insert(i, b),
            }
        }
        no_panic(name, bytes);
    }

}

proptest! {
    // Each case parses a 95 kB workbook (~0.1 s in the test profile): 40 cases keep this short;
    // for a longer hunt: raise `cases` (run with cases = 1000 once before merging).
    #![proptest_config(ProptestConfig { cases: 40, rng_seed: proptest::test_runner::RngSeed::Fixed(crate::tests::seed::seed("dma_errors::excel")), .. ProptestConfig::default() })]

    // calamine 0.31 allocates rows × cols of a damaged cell address or DIMENSIONS record at once (an
    // abort, not a panic): dma::xls_guard refuses those first; this found the case.
    #[test]
    fn mutated_excel_never_panics(edits in proptest::collection::vec((any::<u32>(), any::<u8>()), 1..6)) {
        let mut bytes = std::fs::read(data("pyvisco-ems-ca/freq_Eplexor_raw.xls")).unwrap();
        for (pos, b) in edits {
            let i = pos as usize % bytes.len();
            bytes[i] = b;
        }
        no_panic("mutated.xls", bytes);
    }
}
