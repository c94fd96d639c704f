//! A bounded fuzz and property suite (issue 15): mutated .xls, .xlsx and CSV exports must give a
//! measurement or an error, never a panic, an abort or an unbounded allocation; random scenes must
//! be accepted only when every number is finite and physical, and then turn into a dimensionless
//! problem without a panic. Deterministic (a fixed xorshift seed) and sized to run in a few seconds;
//! `fuzz_sweep_long` (ignored) runs 20× as many cases:
//! `cargo test --release --lib -- --ignored fuzz_sweep_long`.

use std::path::Path;
use viscoroll::dma::{read_bytes, IngestOptions};

/// xorshift64*: small, deterministic, good enough to pick bytes and positions.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// One random mutation: flip bytes, overwrite a run with 0xFF (huge sizes and ids), truncate,
/// duplicate a chunk, or splice in a number text.
fn mutate(rng: &mut Rng, base: &[u8]) -> Vec<u8> {
    let mut b = base.to_vec();
    if b.is_empty() {
        return b;
    }
    match rng.below(5) {
        0 => {
            for _ in 0..1 + rng.below(8) {
                let i = rng.below(b.len());
                b[i] ^= 1 << rng.below(8);
            }
        }
        1 => {
            let i = rng.below(b.len());
            let n = (1 + rng.below(8)).min(b.len() - i);
            b[i..i + n].fill(0xFF);
        }
        2 => b.truncate(rng.below(b.len())),
        3 => {
            let i = rng.below(b.len());
            let n = rng.below(4096).min(b.len() - i);
            let chunk = b[i..i + n].to_vec();
            let j = rng.below(b.len());
            b.splice(j..j, chunk);
        }
        _ => {
            let words: [&[u8]; 6] = [
                b"1e308",
                b"-1e9",
                b"NaN",
                b"1e-320",
                b"99999999999999999999",
                b",,,",
            ];
            let w = words[rng.below(words.len())];
            let i = rng.below(b.len());
            b.splice(i..i, w.iter().copied());
        }
    }
    b
}

fn data(p: &str) -> Vec<u8> {
    std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("data").join(p)).unwrap()
}

/// A minimal .xlsx with one sheet of numbers (the EPLEXOR reader refuses it, but only after calamine
/// has parsed it: a good base for mutations that reach calamine's zip and XML readers).
fn small_xlsx() -> Vec<u8> {
    use std::io::Write as _;
    let mut rows = String::new();
    for r in 1..=40 {
        rows.push_str(&format!(
            "<row r=\"{r}\"><c r=\"A{r}\"><v>{}</v></c><c r=\"B{r}\"><v>{}</v></c></row>",
            r as f64 * 0.5,
            1e6 * r as f64
        ));
    }
    let sheet = format!("<worksheet xmlns=\"http://schemas.openxmlformats.org/spreadsheetml/2006/main\"><dimension ref=\"A1:B40\"/><sheetData>{rows}</sheetData></worksheet>");
    let parts: [(&str, String); 5] = [
        ("[Content_Types].xml", r#"<?xml version="1.0"?><Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types"><Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/><Default Extension="xml" ContentType="application/xml"/><Override PartName="/xl/workbook.xml" ContentType="application/vnd.openxmlformats-officedocument.spreadsheetml.sheet.main+xml"/><Override PartName="/xl/worksheets/sheet1.xml" ContentType="application/vnd.openxmlformats-officedocument.spreadsheetml.worksheet+xml"/></Types>"#.into()),
        ("_rels/.rels", r#"<?xml version="1.0"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships"><Relationship Id="rId1" Type="http://schemas.openxmlformats.org/officeDocument/2006/relationships/officeDocument" Target="xl/workbook.xml"/></Relationships>"#.into()),
        ("xl/workbook.xml", r#"<?xml version="1.0"?><workbook xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main" xmlns:r="http://schemas.openxmlformats.org/officeDocument/2006/relationships"><sheets><sheet name="Exported Data" sheetId="1" r:id="rId1"/></sheets></workbook>"#.into()),
        ("xl/_rels/workbook.xml.rels", r#"<?xml version="1.0"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships"><Relationship Id="rId1" Type="http://schemas.openxmlformats.org/officeDocument/2006/relationships/worksheet" Target="worksheets/sheet1.xml"/></Relationships>"#.into()),
        ("xl/worksheets/sheet1.xml", sheet),
    ];
    let mut zip = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    // Stored, so byte mutations hit the XML itself, not only the deflate stream.
    let opt =
        zip::write::SimpleFileOptions::default().compression_method(zip::CompressionMethod::Stored);
    for (name, body) in &parts {
        zip.start_file(*name, opt).unwrap();
        zip.write_all(body.as_bytes()).unwrap();
    }
    zip.finish().unwrap().into_inner()
}

/// Read `cases` mutations of each base; every one must return (Ok or Err) without a panic.
fn sweep(cases: usize, seed: u64) {
    let bases: Vec<(&str, Vec<u8>)> = vec![
        ("m.xls", data("pyvisco-ems-ca/freq_Eplexor_raw.xls")),
        ("m.xlsx", small_xlsx()),
        ("m.csv", data("pyvisco-ems-ca/freq_user_raw.csv")),
        ("m.txt", data("trios-aresg2-lims/frequency_sweep_tts.txt")),
    ];
    let mut rng = Rng(seed);
    let opts = IngestOptions {
        mode: Some(viscoroll::ModulusKind::Tensile),
        ..IngestOptions::default()
    };
    let (mut ok, mut err) = (0, 0);
    for (name, base) in &bases {
        for case in 0..cases {
            let bytes = mutate(&mut rng, base);
            let r = std::panic::catch_unwind(|| {
                read_bytes(&[(name.to_string(), bytes.clone())], &opts)
            });
            match r {
                Ok(Ok(m)) => {
                    ok += 1;
                    // The plausibility checks take whatever ingest accepted.
                    let _ = viscoroll::dma::plausible::refuse_impossible(&m);
                    let _ = viscoroll::dma::plausible::warnings(&m);
                }
                Ok(Err(e)) => {
                    err += 1;
                    assert!(!e.to_string().is_empty());
                }
                Err(_) => {
                    let path =
                        std::env::temp_dir().join(format!("viscoroll-fuzz-{seed}-{case}-{name}"));
                    let _ = std::fs::write(&path, &bytes);
                    panic!(
                        "{name}: mutation {case} panicked; input saved to {}",
                        path.display()
                    );
                }
            }
        }
    }
    eprintln!("fuzz: {ok} read, {err} refused, 0 panics");
}

/// Random scenes: accepted only with finite, physical numbers; accepted ones make a dimensionless
/// problem (or a clear error) on a rubber-like spectrum, never a panic.
fn scene_sweep(cases: usize, seed: u64) {
    use viscoroll::pipeline::SceneSet;
    let mut rng = Rng(seed);
    let pick = |rng: &mut Rng| -> String {
        let specials = [
            "0", "-1", "1e300", "-1e300", "nan", "inf", "-inf", "1e-300", "5e-324",
        ];
        if rng.below(3) == 0 {
            specials[rng.below(specials.len())].to_string()
        } else {
            format!(
                "{:e}",
                10f64.powf(rng.below(24) as f64 - 8.0) * (1.0 + rng.below(9) as f64)
            )
        }
    };
    let creep: viscoroll::CreepSpectrum = serde_json::from_value(serde_json::json!({
        "kind": "tensile", "poisson": 0.5, "compliance_glassy_per_pa": 1e-9,
        "terms": [{"compliance_per_pa": 3e-7, "tau_s": 1e-3}]
    }))
    .unwrap();
    let mut accepted = 0;
    for _ in 0..cases {
        let (r, n, v, t) = (
            pick(&mut rng),
            pick(&mut rng),
            pick(&mut rng),
            pick(&mut rng),
        );
        let text = format!(
            "[[scene]]\nname = \"s\"\nroll_radius_mm = {r}\nload_n_per_m = {n}\nspeed_m_s = {v}\ntemps_c = [{t}]\n"
        );
        let Ok(set) = SceneSet::parse(&text, Path::new("fuzz.toml")) else {
            continue;
        };
        accepted += 1;
        let s = &set.scene[0];
        for x in [s.roll_radius_mm, s.load_n_per_m, s.speed_m_s, s.temps_c[0]] {
            assert!(x.is_finite(), "{text}");
        }
        assert!(
            s.speed_m_s <= 1e3 && s.load_n_per_m <= 1e8 && s.roll_radius_mm <= 1e5,
            "{text}"
        );
        let _ = s.scene().dimensionless(&creep);
    }
    eprintln!("scenes: {accepted} of {cases} accepted");
}

#[test]
fn mutated_exports_give_a_measurement_or_an_error_never_a_panic() {
    sweep(60, 0x9E37_79B9_7F4A_7C15);
}

#[test]
fn random_scenes_are_checked_before_they_reach_the_solver() {
    scene_sweep(2000, 0xD1B5_4A32_D192_ED03);
}

#[test]
#[ignore = "the long sweep: --ignored fuzz_sweep_long"]
fn fuzz_sweep_long() {
    sweep(1200, 0x2545_F491_4F6C_DD1D);
    scene_sweep(40_000, 0x1234_5678_9ABC_DEF1);
}

/// Issue 15, solver allocations: creep terms with f and b anywhere in 1e−300 … 1e300, alone and as
/// mixtures of a very fast and a very slow mode, through the dimensionless solvers behind `contact`
/// (at λ and at load N′ = ¼, every scheme; `roll` solves the same problem at N′ = ¼). Each answer is a
/// finite friction or an error, never a panic; the peak memory of the whole test process stays below
/// issue 15's 2 GB (VmHWM, Linux). `values` picks the grid; the CI sweep uses every other decade-100
/// value, the ignored sweep all of them.
fn creep_sweep(values: &[f64]) {
    use viscoroll::contact::{self, ContactSettings, CreepTerm, Scheme};
    let mut cases: Vec<Vec<CreepTerm>> = Vec::new();
    for &f in values {
        for &b in values {
            cases.push(vec![CreepTerm { f, b }]);
        }
    }
    // A very fast mode beside a very slow one, of either weight.
    for &(f1, b1, f2, b2) in &[
        (1.0, 1e300, 1.0, 1e-300),
        (1e300, 1e300, 1e-300, 1e-300),
        (1e-300, 1e300, 1e300, 1e-300),
        (1e6, 1e12, 1e-6, 1e-12),
        (1.0, 1e-300, 1e300, 1.0),
    ] {
        cases.push(vec![CreepTerm { f: f1, b: b1 }, CreepTerm { f: f2, b: b2 }]);
    }
    // Strong single modes (f ≫ b): a moderate c = bλ/2 but a huge μ = (b + f)λ/2 (1e10:1 at
    // N′ = 0.25 asked for 8 GB before the auto scheme capped μ at 1e9).
    for &(f, b) in &[(1e8, 1.0), (1e10, 1.0), (1e14, 1.0), (1e12, 1e-3)] {
        cases.push(vec![CreepTerm { f, b }]);
    }
    let schemes = [
        ContactSettings::default(),
        ContactSettings::thesis(200),
        ContactSettings {
            scheme: Scheme::Exact,
            ..ContactSettings::default()
        },
    ];
    let (mut ok, mut refused, mut bad) = (0, 0, Vec::<String>::new());
    for terms in &cases {
        for s in &schemes {
            if s.scheme == Scheme::Exact && terms.len() > 1 {
                continue;
            }
            for r in [
                contact::solve_at_lambda(terms, 3.0, s),
                contact::solve_at_load(terms, 0.25, s),
            ] {
                match r {
                    Ok(sol) if sol.friction_rho.is_finite() => ok += 1,
                    Ok(sol) => bad.push(format!(
                        "{terms:?} {:?}: ρF/N = {}, λ = {}",
                        s.scheme, sol.friction_rho, sol.lambda
                    )),
                    Err(e) => {
                        assert!(!e.to_string().is_empty());
                        refused += 1;
                    }
                }
            }
        }
    }
    eprintln!(
        "creep sweep: {} cases, {ok} solved, {refused} refused",
        cases.len()
    );
    let peak_mb = std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse::<f64>().ok())
        })
        .map_or(0.0, |kb| kb / 1024.0);
    assert!(peak_mb < 2048.0, "peak memory {peak_mb} MB");
}

// This sweep found a panic (debug) / unbounded allocation (release) in special::bessel's series,
// reached from the auto scheme when μ = (b + f)·λ/2 of a kept mode was astronomically large (f = 1e300,
// b = 1): n_keep = √(83 μ) overflowed usize. The auto scheme now refuses f/b > 1e15
// (auto::settings::MAX_MODE_STRENGTH) with an OutOfRange error, lumps a fast mode whose μ exceeds
// 1e9 and refuses a slow one (auto::reduction::MU_MAX).
#[test]
fn extreme_creep_terms_give_an_answer_or_an_error_in_bounded_memory() {
    creep_sweep(&[1e-300, 1e-100, 1e-6, 1.0, 1e6, 1e100, 1e300]);
}

#[test]
#[ignore = "the long creep sweep: --ignored creep_sweep_long"]
fn creep_sweep_long() {
    let values: Vec<f64> = (-30..=30).map(|k| 10f64.powi(10 * k)).collect();
    creep_sweep(&values);
}
