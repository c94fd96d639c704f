//! Real lab files, second wave (issue 18): headers with units in the names, a column mapping,
//! RheoCompass in English, German and French, multi-step exports, tensile or shear from the file's
//! evidence (the same error without it), RepTate `.osc` sweeps and `.tts` master curves.
//!
//! The fixtures under tests/data/formats/ were written for these tests from one shear model
//! (20 Maxwell terms, WLF C1 = 8.86, C2 = 101.6 K at 0 °C) with 6 significant digits, so the same
//! point read from two layouts agrees to 2e-5 relative (two roundings of 5e-6 and a few more
//! through ω = 2πf, K → °C and E = 3G).

use std::path::{Path, PathBuf};
use viscoroll::dma::{self, ColumnMap, DmaError, IngestOptions, Measurement};
use viscoroll::tts::{build_master_curve, master_curve_from_reduced, MasterSettings};
use viscoroll::{ModulusKind, ShiftLaw};

fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/formats")
        .join(name)
}

fn read(name: &str, opts: &IngestOptions) -> Result<Measurement, DmaError> {
    dma::read_files(&[fixture(name)], opts)
}

/// Relative agreement of two layouts of the same points (module docs).
const SAME: f64 = 2e-5;

fn assert_same_points(a: &Measurement, b: &Measurement, scale_b: f64, what: &str) {
    assert_eq!(a.isotherms.len(), b.isotherms.len(), "{what}");
    for (x, y) in a.isotherms.iter().zip(&b.isotherms) {
        assert!((x.temp_nominal_c - y.temp_nominal_c).abs() < 0.5, "{what}");
        assert_eq!(x.points.len(), y.points.len(), "{what}");
        for (p, q) in x.points.iter().zip(&y.points) {
            for (u, v) in [
                (p.freq_hz, q.freq_hz),
                (p.storage_pa, q.storage_pa * scale_b),
                (p.loss_pa, q.loss_pa * scale_b),
            ] {
                assert!((u / v - 1.0).abs() < SAME, "{what}: {u} vs {v}");
            }
        }
    }
}

fn evidence(m: &Measurement) -> &str {
    m.sources[0]
        .metadata
        .get("mode evidence")
        .map(String::as_str)
        .unwrap_or("")
}

#[test]
fn units_in_the_names_read_without_options() {
    let g = read("epdm_units_in_names.csv", &IngestOptions::default()).unwrap();
    assert_eq!(g.kind, ModulusKind::Shear);
    assert_eq!(g.isotherms.len(), 4);
    assert!(g.isotherms.iter().all(|i| i.points.len() == 6));
    // The first row of the file, as written: 0.1 Hz, −9.97 °C, 3.06082e6 Pa, 1.07626e6 Pa.
    let p = &g.isotherms[0].points[0];
    assert_eq!(
        (p.freq_hz, p.temp_c, p.storage_pa, p.loss_pa),
        (0.1, Some(-9.97), 3.06082e6, 1.07626e6)
    );
    let units: Vec<&str> = g.sources[0]
        .columns
        .iter()
        .map(|c| c.unit.as_str())
        .collect();
    assert_eq!(units, ["Hz", "°C", "Pa", "Pa"]);
    // ω in rad/s, T in K, E′ in MPa and tan δ: the same material as E = 3G.
    let e = read("units_in_names_tensile.txt", &IngestOptions::default()).unwrap();
    assert_eq!(e.kind, ModulusKind::Tensile);
    assert_same_points(&e, &g, 3.0, "tensile twin");
    assert!(evidence(&e).contains("E_storage"), "{}", evidence(&e));
}

#[test]
fn a_column_mapping_reads_names_no_reader_knows() {
    let err = read("mapped_columns.csv", &IngestOptions::default()).unwrap_err();
    assert!(matches!(err, DmaError::MissingColumn { .. }), "{err}");
    let opts = IngestOptions {
        columns: ColumnMap::parse("freq=Frq,temp=Tmp,storage=Mod1,loss=Mod2").unwrap(),
        mode: Some(ModulusKind::Tensile),
        ..IngestOptions::default()
    };
    let m = read("mapped_columns.csv", &opts).unwrap();
    let g = read("epdm_units_in_names.csv", &IngestOptions::default()).unwrap();
    assert_same_points(&m, &g, 3.0, "mapped");
    // Without --mode the mapped `Mod1` says neither E nor G, and the file says nothing either.
    let no_mode = IngestOptions {
        mode: None,
        ..opts.clone()
    };
    let err = read("mapped_columns.csv", &no_mode).unwrap_err();
    assert!(matches!(err, DmaError::AmbiguousMode { .. }), "{err}");
    // A mapped name that is not there is named, with the columns that are.
    let wrong = IngestOptions {
        columns: ColumnMap::parse("storage=Mod9").unwrap(),
        ..opts
    };
    let err = read("mapped_columns.csv", &wrong).unwrap_err().to_string();
    assert!(err.contains("Mod9") && err.contains("`Mod1`"), "{err}");
}

#[test]
fn rheocompass_in_french_german_and_english_with_the_mode_from_the_file() {
    let g = read("epdm_units_in_names.csv", &IngestOptions::default()).unwrap();
    // French, `Interval données:`, comma decimals, UTF-16LE; an MCR device: shear.
    let fr = read(
        "rheocompass_fr_interval_donnees.csv",
        &IngestOptions::default(),
    )
    .unwrap();
    assert_eq!(fr.sources[0].format, "rheocompass");
    assert_eq!(fr.kind, ModulusKind::Shear);
    assert_eq!(fr.isotherms.len(), 3);
    assert!(evidence(&fr).contains("MCR 302"), "{}", evidence(&fr));
    let nominal: Vec<f64> = fr.isotherms.iter().map(|i| i.temp_nominal_c).collect();
    assert_eq!(nominal, [0.0, 10.0, 20.0]);
    // German tension test "TF-Sweep_Zug" on an MCR: the test name beats the device, tensile.
    let de = read("rheocompass_de_tf_zug.csv", &IngestOptions::default()).unwrap();
    assert_eq!(de.kind, ModulusKind::Tensile);
    assert!(evidence(&de).contains("Zug"), "{}", evidence(&de));
    // Written as E = 3G of the same model at 0 and 10 °C (the French file's first two isotherms).
    let mut fr2 = fr.clone();
    fr2.isotherms.truncate(2);
    assert_same_points(&de, &fr2, 3.0, "German tension vs French shear");
    // English with an amplitude sweep first: skipped with a note naming it.
    let en = read(
        "rheocompass_en_amplitude_then_sweeps.csv",
        &IngestOptions::default(),
    )
    .unwrap();
    assert_eq!(en.isotherms.len(), 3);
    assert_eq!(en.kind, ModulusKind::Shear);
    assert!(
        en.warnings
            .iter()
            .any(|w| w.contains("`Amplitude Sweep 20 °C` skipped") && w.contains("amplitude")),
        "{:?}",
        en.warnings
    );
    assert_same_points(&en, &fr, 1.0, "English vs French");
    // The frequencies of the shared model agree with the units-in-names file at 0 °C too.
    assert!((fr.isotherms[0].points[0].freq_hz - g.isotherms[1].points[0].freq_hz).abs() < 1e-6);
}

#[test]
fn without_evidence_every_reader_gives_the_same_error_asking_for_mode() {
    let rc = read("rheocompass_en_no_evidence.csv", &IngestOptions::default()).unwrap_err();
    let trios_text = "Filename\tx.tri\n\n[step]\nFrequency sweep (25.0 °C)\n\
        Angular frequency\tStorage modulus\tLoss modulus\tTemperature\n\
        rad/s\tPa\tPa\t°C\n1\t1e6\t1e5\t25\n10\t2e6\t2e5\t25\n100\t3e6\t3e5\t25\n";
    let generic = "Frequency,Temperature,Storage modulus,Loss modulus\nHz,°C,MPa,MPa\n\
        1,25,1,0.1\n10,25,2,0.2\n100,25,3,0.3\n";
    let inputs = [
        ("plain.txt", trios_text.as_bytes().to_vec()),
        ("plain.csv", generic.as_bytes().to_vec()),
    ];
    let mut errors = vec![rc];
    for (name, bytes) in inputs {
        errors.push(
            dma::read_bytes(&[(name.to_string(), bytes)], &IngestOptions::default()).unwrap_err(),
        );
    }
    for e in &errors {
        assert!(matches!(e, DmaError::AmbiguousMode { .. }), "{e}");
        let s = e.to_string();
        assert!(
            s.contains("give --mode tensile or --mode shear")
                && s.contains("names no geometry, test or instrument"),
            "{s}"
        );
    }
    // With --mode the same file reads, and says why.
    let m = read(
        "rheocompass_en_no_evidence.csv",
        &IngestOptions {
            mode: Some(ModulusKind::Shear),
            ..IngestOptions::default()
        },
    )
    .unwrap();
    assert_eq!(evidence(&m), "--mode");
}

#[test]
fn trios_multi_step_export_skips_each_non_sweep_step_by_name() {
    let m = read("trios_multistep.txt", &IngestOptions::default()).unwrap();
    assert_eq!(m.sources[0].format, "trios-text");
    assert_eq!(m.kind, ModulusKind::Shear);
    assert!(evidence(&m).contains("DHR-2"), "{}", evidence(&m));
    let nominal: Vec<f64> = m.isotherms.iter().map(|i| i.temp_nominal_c).collect();
    assert_eq!(nominal, [25.0, 40.0]);
    for step in ["Flow ramp - 1", "Amplitude sweep - 2", "Time sweep - 5"] {
        assert!(
            m.warnings
                .iter()
                .any(|w| w.contains(&format!("step `{step}` skipped"))),
            "{step}: {:?}",
            m.warnings
        );
    }
    let err = read("trios_no_sweep.txt", &IngestOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("no usable oscillatory frequency sweep")
            && err.contains("Flow ramp - 1")
            && err.contains("Amplitude sweep - 2"),
        "{err}"
    );
}

fn reptate(name: &str) -> PathBuf {
    fixture(&format!("reptate/{name}"))
}

#[test]
fn reptate_osc_sweeps_read_with_their_temperatures_and_no_false_warning() {
    let files: Vec<PathBuf> = [
        "EPDM_0C_FS_PP8.osc",
        "EPDM_10C_FS_PP8.osc",
        "EPDM_20C_FS_PP8.osc",
    ]
    .iter()
    .map(|n| reptate(n))
    .collect();
    let m = dma::read_files(&files, &IngestOptions::default()).unwrap();
    assert!(m.sources.iter().all(|s| s.format == "reptate"));
    assert_eq!(m.kind, ModulusKind::Shear);
    let nominal: Vec<f64> = m.isotherms.iter().map(|i| i.temp_nominal_c).collect();
    assert_eq!(nominal, [0.0, 10.0, 20.0]);
    assert!(m.isotherms.iter().all(|i| i.points.len() == 13));
    // T from the header (0 and 10 °C) or the name (20 °C): no "from the file name" warning, no
    // nominal-offset finding.
    assert!(m.warnings.is_empty(), "{:?}", m.warnings);
    assert!(
        !m.issues.iter().any(|i| i.flag == dma::Flag::NominalOffset),
        "{:?}",
        m.issues
    );
    // ω in rad/s by RepTate's layout when no unit row is written: 0.1 rad/s = 0.1/2π Hz.
    let f0 = m.isotherms[1].points[0].freq_hz;
    assert!((f0 * 2.0 * std::f64::consts::PI / 0.1 - 1.0).abs() < 1e-12);
    // The shifts of the three sweeps are those of the WLF law that made them (−8.86ΔT/(101.6+ΔT)):
    // 13 points over 3 decades superpose to well within 0.01 decade.
    let mc = build_master_curve(
        &m,
        &MasterSettings {
            tref_c: Some(0.0),
            ..MasterSettings::default()
        },
    )
    .unwrap();
    for s in &mc.isotherms {
        let truth = -8.86 * s.temp_nominal_c / (101.6 + s.temp_nominal_c);
        assert!(
            (s.log10_a_t - truth).abs() < 0.01,
            "{}: {} vs {truth}",
            s.temp_nominal_c,
            s.log10_a_t
        );
    }
}

#[test]
fn reptate_tts_master_curve_with_its_wlf_constants() {
    let r = dma::reptate::read_master(&reptate("EPDM_master_T0.tts"), &IngestOptions::default())
        .unwrap();
    assert_eq!(r.t_ref_c, 0.0);
    assert_eq!(
        r.shift_law,
        Some(ShiftLaw::Wlf {
            t_ref_c: 0.0,
            c1: 8.86,
            c2_k: 101.6
        })
    );
    assert_eq!(r.measurement.isotherms.len(), 1);
    assert_eq!(r.measurement.isotherms[0].points.len(), 33);
    let law = r.shift_law.clone().unwrap();
    let mc = master_curve_from_reduced(&r.measurement, &law).unwrap();
    assert_eq!(mc.points.len(), 33);
    assert_eq!(mc.shift_law, law);
    assert_eq!(mc.kind, ModulusKind::Shear);
    // The master curve agrees with the 10 °C sweep moved by the header's law: G′ of the sweep's
    // first point (0.1 rad/s at 10 °C) equals the master's at a_T·ω, interpolated in log–log
    // between neighbours 0.25 decade apart (curvature error below 1 %).
    let sweep =
        dma::read_files(&[reptate("EPDM_10C_FS_PP8.osc")], &IngestOptions::default()).unwrap();
    let p = &sweep.isotherms[0].points[0];
    let fr = p.freq_hz * 10f64.powf(law.log10_a_t(10.0));
    let k = mc.points.partition_point(|q| q.reduced_freq_hz < fr);
    let (a, b) = (&mc.points[k - 1], &mc.points[k]);
    let t = (fr.ln() - a.reduced_freq_hz.ln()) / (b.reduced_freq_hz.ln() - a.reduced_freq_hz.ln());
    let g = (a.storage_pa.ln() * (1.0 - t) + b.storage_pa.ln() * t).exp();
    assert!(
        (g / p.storage_pa - 1.0).abs() < 0.01,
        "{g} vs {}",
        p.storage_pa
    );
}

#[test]
fn shift_table_with_units_in_the_names_and_a_stated_reference() {
    let dir = std::env::temp_dir().join(format!("viscoroll-dma-formats-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("shifts.csv");
    std::fs::write(&p, "T_C,log10_aT\n-10,1.2\n10,-0.8\n30,-2.1\n").unwrap();
    let err = dma::read_shift_factors(&p).unwrap_err().to_string();
    assert!(err.contains("reference temperature"), "{err}");
    let law = dma::read_shift_table(&p, Some(0.0)).unwrap();
    assert_eq!(
        law,
        ShiftLaw::Table {
            t_ref_c: 0.0,
            points: vec![(-10.0, 1.2), (10.0, -0.8), (30.0, -2.1)]
        }
    );
    let kelvin = dir.join("shifts_k.csv");
    std::fs::write(&kelvin, "T_K;log_aT\n263.15;1.2\n283.15;0\n").unwrap();
    let law = dma::read_shift_factors(Path::new(&kelvin)).unwrap();
    assert!((law.t_ref_c() - 10.0).abs() < 1e-12);
}
