//! Time-domain exports of instruments (issue 29 item 3): Anton Paar RheoCompass and Netzsch Proteus
//! relaxation and creep files (tests/data/time_vendor, written for the test after the layouts the
//! frequency readers document; see the README there) read into relaxation or creep isotherms in SI,
//! with the mode and kind said from the file's evidence, and bad files refused naming file, line
//! and column. The values are checked against the closed forms the files were written from.

use std::path::PathBuf;
use viscoroll::dma::time_domain::{read_time_files, time_data_from_bytes, TimeDataError, TimeMode};
use viscoroll::ModulusKind;

fn file(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/time_vendor")
        .join(name)
}

/// Largest relative difference of every point from `truth(t / a_T)` with the isotherms' a_T.
fn worst(
    d: &viscoroll::dma::time_domain::TimeData,
    a_t: &[f64],
    truth: impl Fn(f64) -> f64,
) -> f64 {
    let truth = &truth;
    d.isotherms
        .iter()
        .zip(a_t)
        .flat_map(|(i, a)| {
            i.points
                .iter()
                .map(move |p| (p.value / truth(p.time_s / a) - 1.0).abs())
        })
        .fold(0.0, f64::max)
}

#[test]
fn rheocompass_relaxation_in_english_reads_shear_from_its_measuring_system() {
    let d = read_time_files(&[file("rheocompass_relaxation_en.csv")], 0.5).unwrap();
    assert_eq!((d.mode, d.kind), (TimeMode::Relaxation, ModulusKind::Shear));
    assert_eq!(d.sources[0].format, "rheocompass");
    assert!(d.evidence[0].contains("PP25"), "{:?}", d.evidence);
    let temps: Vec<f64> = d.isotherms.iter().map(|i| i.temp_c).collect();
    assert_eq!(temps, [20.0, 40.0]);
    // the strain-step intervals are skipped with a note; the interval time (since the step) is read
    assert!(
        d.warnings.iter().any(|w| w.contains("skipped")),
        "{:?}",
        d.warnings
    );
    assert_eq!(d.isotherms[0].points[0].time_s, 0.5);
    // written with 17 significant digits and a decimal comma: read back to 1 ulp
    let w = worst(&d, &[1.0, 0.1], |t| 1e6 * (1.0 + 9.0 * (-t / 10.0).exp()));
    assert!(w < 1e-15, "{w}");
}

#[test]
fn rheocompass_creep_in_german_reads_its_compliance() {
    let d = read_time_files(&[file("rheocompass_creep_de.csv")], 0.5).unwrap();
    assert_eq!((d.mode, d.kind), (TimeMode::Creep, ModulusKind::Shear));
    assert!(d.evidence[0].contains("CP50"), "{:?}", d.evidence);
    assert_eq!(d.isotherms.len(), 2);
    assert_eq!(d.isotherms[1].temp_c, 50.0);
    // `Intervallzeit` (since the step) is taken, not `Zeit` (elapsed)
    assert_eq!(d.isotherms[0].points[0].time_s, 1.0);
    let w = worst(&d, &[1.0, 0.1], |t| 1e-6 * (1.0 + t / (t + 10.0)));
    assert!(w < 1e-15, "{w}");
}

#[test]
fn proteus_creep_and_relaxation_read_their_mode_lines_decimals_and_separators() {
    let d = read_time_files(&[file("proteus_creep.txt")], 0.5).unwrap();
    assert_eq!((d.mode, d.kind), (TimeMode::Creep, ModulusKind::Tensile));
    assert_eq!(d.sources[0].format, "proteus");
    assert!(
        d.evidence[0].to_lowercase().contains("tension"),
        "{:?}",
        d.evidence
    );
    // minutes → s; 1/MPa → 1/Pa
    assert_eq!(d.isotherms[0].points[0].time_s, 30.0);
    let w = worst(&d, &[1.0, 0.01], |t| {
        1e-9 * (2.0 + (t / 60.0) / (t / 60.0 + 1.0))
    });
    assert!(w < 1e-14, "{w}");
    let d = read_time_files(&[file("proteus_relaxation.txt")], 0.5).unwrap();
    assert_eq!(
        (d.mode, d.kind),
        (TimeMode::Relaxation, ModulusKind::Tensile)
    );
    assert!(
        d.evidence[0].to_lowercase().contains("bending"),
        "{:?}",
        d.evidence
    );
    let temps: Vec<f64> = d.isotherms.iter().map(|i| i.temp_c).collect();
    assert_eq!(temps, [-10.0, 10.0]);
    let w = worst(&d, &[1.0, 0.1], |t| 1e9 * (0.1 + 0.9 * (-t / 100.0).exp()));
    assert!(w < 1e-14, "{w}");
}

// the reader's own error, as the library returns it
#[allow(clippy::result_large_err)]
fn read(name: &str, text: &str) -> Result<viscoroll::dma::time_domain::TimeData, TimeDataError> {
    time_data_from_bytes(&[(name.into(), text.as_bytes().to_vec())], 0.5)
}

#[test]
fn bad_instrument_files_are_refused_naming_file_line_and_column() {
    let rc = |system: &str, modulus: &str, unit: &str, v: &str| {
        format!(
            "Project:\tx\n{system}Result:\tRelaxation 20 °C\nInterval data:\tPoint No.\tInterval Time\t{modulus}\tTemperature\n\t\t[s]\t[{unit}]\t[°C]\n\t1\t1\t{v}\t20\n\t2\t2\t5\t20\n\t3\t3\t4\t20\n"
        )
    };
    // no measuring system, test name or device that says tension or shear: never assumed
    let e = read("rc.csv", &rc("", "Relaxation Modulus", "Pa", "6")).unwrap_err();
    assert!(
        matches!(
            e,
            TimeDataError::NoKind {
                line: 3,
                column: 3,
                ..
            }
        ),
        "{e}"
    );
    assert!(e.to_string().starts_with("rc.csv:3:3:"), "{e}");
    // with it, the same file reads
    assert!(read(
        "rc.csv",
        &rc("Measuring System:\tPP25\n", "Relaxation Modulus", "Pa", "6")
    )
    .is_ok());
    // a unit no modulus has, and a cell that is not a number
    let sys = "Measuring System:\tPP25\n";
    let e = read("rc.csv", &rc(sys, "Relaxation Modulus", "1/Pa", "6")).unwrap_err();
    assert!(
        matches!(e, TimeDataError::UnknownUnit { column: 3, .. }),
        "{e}"
    );
    let e = read("rc.csv", &rc(sys, "Relaxation Modulus", "Pa", "x")).unwrap_err();
    assert!(
        matches!(
            e,
            TimeDataError::BadCell {
                line: 6,
                column: 3,
                ..
            }
        ),
        "{e}"
    );
    // Proteus: a time column that runs on across the isotherms is elapsed time, refused
    let p = "#MODE:Tension\n#DECIMAL:POINT\n#SEPARATOR:SEMICOLON\n##Temp./°C;Time/min;E(t)/MPa\n0;1;9\n0;2;8\n0;3;7\n20;4;6\n20;5;5\n20;6;4\n";
    let e = read("p.txt", p).unwrap_err();
    assert!(
        matches!(
            e,
            TimeDataError::ElapsedTime {
                line: 8,
                column: 2,
                ..
            }
        ),
        "{e}"
    );
    assert!(e.to_string().starts_with("p.txt:8:2:"), "{e}");
    // restarting per segment, the same file reads (E is tensile by its symbol and #MODE)
    let ok = p
        .replace("20;4;", "20;1;")
        .replace("20;5;", "20;2;")
        .replace("20;6;", "20;3;");
    assert_eq!(read("p.txt", &ok).unwrap().kind, ModulusKind::Tensile);
    // a Proteus frequency sweep is not time-domain data
    let e = read(
        "p.txt",
        "#MODE:Tension\n##Temp./°C;Time/min;Freq./Hz;E'/MPa\n0;1;1;9\n",
    )
    .unwrap_err();
    assert!(matches!(e, TimeDataError::NoTimeData { .. }), "{e}");
}

/// `run` routes a compound to the time-domain path by the same evidence (decoded as the readers
/// decode: RheoCompass writes UTF-16).
#[test]
fn run_recognises_the_instrument_files_as_time_domain_data() {
    for f in [
        "rheocompass_relaxation_en.csv",
        "rheocompass_creep_de.csv",
        "proteus_creep.txt",
        "proteus_relaxation.txt",
    ] {
        assert!(
            viscoroll::pipeline::fit_time::files_are_time_data(&[file(f)]),
            "{f}"
        );
    }
    let sweep =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/synthetic/proteus_ascii.txt");
    assert!(!viscoroll::pipeline::fit_time::files_are_time_data(&[
        sweep
    ]));
}
