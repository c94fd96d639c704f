//! Calibration of the uncertainty bands (issue 16, item 1; crate::bands, docs/MATH.md §15): on the
//! known-truth synthetic compounds of tests/known_truth.rs (viscoroll::testdata::realistic: four
//! rubbers, isotherms −60 … +100 °C every 5 K, 1 % noise on E′, 3 % on E″, ±1.5 K drift) the
//! 90 % band (p05 … p95) must cover the true friction in 80–97 % of the (compound, scene,
//! temperature) points, over the shipped scenes at −40 … +60 °C every 10 K.
//!
//! The band comes from the pipeline's own path: the export written as CSV and read back, the fit
//! (`pipeline::fit_measurement_master`), the bootstrap ensemble
//! (`bands::build_ensemble`, the main job's settings), the friction (`friction_vs_temperature`, the
//! main job's contact settings) and its band (`bands::scene_bands_on` on the scene's body, + `band_of`). The true friction
//! comes from the true spectrum, converted exactly to creep and shifted by the true WLF law, through
//! the contact solver (the body of the scene); nothing of the fit or the ensemble enters it. That
//! truth is itself checked against an independent contact path in tests/known_truth.rs.
//!
//! In CI: noise seeds 1 and 2 (about 30 s on 2 cores; 252/264 = 95.5 % with eqs. 15.6b–15.9). The full
//! figure over 10 seeds (about 2 min; 1229/1320 = 93.1 %, per seed 82.6–99.2 %, median half-width
//! 0.78 %; before the fit's own choices were drawn, eqs. 15.10–15.12: 1142/1320 = 86.5 %):
//! `cargo test --release --lib bands_calibration_ten_seeds -- --ignored --nocapture`.
//! Both print the coverage per seed, compound and scene, and the misses. The 2-seed check is the
//! weaker one: single seeds range from 72 % to 98.5 %, so it catches a band that is far off (too
//! narrow or too wide by ~2×), not a few points of coverage. Those measurements reach every
//! point's rolling frequency, so neither model-error term enters them.
//!
//! Truncated measurements (the frequency-window term, eq. 15.9): the same compounds measured from
//! −20 °C up only ([`TRUNCATED_FROM_C`]), so that −40 and −30 °C lie beyond the measured
//! temperatures and at −20 °C (at some points −10 °C) the scenes' reduced rolling frequencies lie
//! 0.01–1.9 decades above the window's top; the coverage is reported apart for the points inside the window, in the ramp of
//! its last half decade (eq. 15.9c), beyond it at a measured temperature, and beyond the measured
//! temperatures. Over 10 seeds (about 1.5 min): 1150/1320 = 87.1 %; inside 689/810 = 85.1 %, ramp
//! 83/83 = 100 %, beyond the window 167/187 = 89.3 % (all 20 misses above the band), beyond the
//! temperatures 211/240 = 87.9 %:
//! `cargo test --release --lib bands_calibration_truncated_ten_seeds -- --ignored --nocapture`.
//! CI runs seeds 1–2 of it (`bands_cover_the_true_friction_on_truncated_measurements_two_seeds`).

//!
//! Held-out set (issue 32): `held_out_compounds` (8 shapes none of the bands were tuned on) × noise
//! seeds 101–110, whole range or truncated at −20 °C / +40 °C, written as plain CSV, TRIOS text or
//! Proteus ASCII; each point's band with the fit's own choices drawn (eqs. 15.10–15.12) and, beside
//! it, the data's scatter alone: `VISCOROLL_HELD_OUT_SEEDS=10 cargo test --release --lib
//! bands_calibration_held_out_ten_seeds -- --ignored --nocapture` (use the test profile, without
//! `--release`, on a shared machine; a refused band counts as a miss and is counted apart). Its
//! one-seed-each subset (`bands_cover_the_true_friction_held_out_one_seed_each`) is ignored for
//! its run time; CI checks that every refit of those 8 cases converges, with and without the
//! fit's own choices (`held_out_refits_all_converge`, about 10 s).

use std::path::PathBuf;
use viscoroll::bands::{band_of, build_ensemble, scene_bands_on, BandSettings};
use viscoroll::contact::roll_cover;
use viscoroll::contact::{roll, Body, ContactSettings, Scene};
use viscoroll::creep::relaxation_to_creep;
use viscoroll::dma::{read_files, IngestOptions};
use viscoroll::pipeline::fit_measurement_master;
use viscoroll::pipeline::scenes::{
    friction_vs_temperature, pipeline_contact_settings, SceneSet, COVER_TOL,
};
use viscoroll::pipeline::FitOptions;
use viscoroll::testdata::realistic::{
    dma_rows, held_out_compounds, realistic_compounds, DmaProtocol, ExportFormat, RealisticCompound,
};
use viscoroll::CreepSpectrum;

/// Temperatures of the comparison, °C (as tests/known_truth.rs).
const TEMPS_C: [f64; 11] = [
    -40.0, -30.0, -20.0, -10.0, 0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0,
];

/// The acceptance range of the coverage of a 90 % band.
const COVERAGE: (f64, f64) = (0.80, 0.97);

fn shifted(c: &CreepSpectrum, log10_a_t: f64) -> CreepSpectrum {
    let mut s = c.clone();
    for t in &mut s.terms {
        t.tau_s *= 10f64.powf(log10_a_t);
    }
    s
}

/// One (compound, scene, temperature) point of the calibration.
#[derive(Debug, Clone)]
struct Point {
    compound: String,
    scene: String,
    temp_c: f64,
    truth: f64,
    friction: f64,
    p05: f64,
    p95: f64,
    /// (m, s) of ln F_b/F̂.
    stats: (f64, f64),
    /// Δ of the frequency-window term (eq. 15.9; negative inside the window's edge, eq. 15.9c),
    /// `None` without one.
    window_decades: Option<f64>,
    /// Beyond the measured temperatures (the shift-law tail term, eq. 15.8).
    extrapolated: bool,
    /// (p05, p95) of the data's scatter alone (`BandSettings::model_error` off: the bands before
    /// issue 32), when compared.
    before: Option<(f64, f64)>,
    /// Whether the main job states this band as a claim: the fit is trusted and the point is
    /// determined (`FrictionPoint::determine`: band within a factor 10, temperature within 10 K
    /// of the measured ones). Points that are not are printed as "not determined" or "not
    /// trusted", never ranked.
    claimed: bool,
    /// ln(F with the fit's spectrum on the true shift law / true F): the Prony fit's share of the
    /// error (the rest, ln(F/true F) less this, is the shifts' share); `None` where not computed.
    prony_share: Option<f64>,
    /// Whether the case was measured over the protocol's whole temperature range (not truncated).
    whole_range: bool,
}

/// Mean and standard deviation of the finite ln ratios (as crate::bands::band_of reads them).
fn log_stats(r: &[f64]) -> (f64, f64) {
    let d: Vec<f64> = r
        .iter()
        .filter(|x| x.is_finite() && **x > 0.0)
        .map(|x| x.ln())
        .collect();
    let n = d.len() as f64;
    let m = d.iter().sum::<f64>() / n;
    (
        m,
        (d.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1.0)).sqrt(),
    )
}

/// Coverage of two other readings of the same replicates, for comparison (not asserted): the band
/// centred on the replicates (p50 = F·e^m, half-width 1.645 s: eq. 15.5 before issue 32) and the
/// basic bootstrap (the offset reflected: p50 = F·e^(−m)).
fn other_readings(p: &Point) -> (bool, bool) {
    let (m, s) = p.stats;
    let z = viscoroll::bands::friction::Z95;
    let inside = |c: f64| {
        p.friction * (c - z * s).exp() <= p.truth && p.truth <= p.friction * (c + z * s).exp()
    };
    (inside(m), inside(-m))
}

/// One measured compound of a calibration: the compound, the run's protocol (seed, temperatures)
/// and the export format it is written in.
struct Case {
    compound: RealisticCompound,
    protocol: DmaProtocol,
    format: ExportFormat,
    /// Also the band of the data's scatter alone ([`Point::before`]).
    compare: bool,
}

/// The default protocol (−60 … +100 °C every 5 K) with noise seed `seed`, cut to [lo, hi] °C.
fn protocol(seed: u64, lo: f64, hi: f64) -> DmaProtocol {
    let default = DmaProtocol::default();
    DmaProtocol {
        seed,
        temps_c: default
            .temps_c
            .iter()
            .copied()
            .filter(|t| (lo..=hi).contains(t))
            .collect(),
        ..default
    }
}

/// Every (scene, temperature) point of one case: its export written and read back, fitted, its
/// ensemble built, each scene's friction and band against the truth.
fn points_of_case(case: &Case) -> Vec<Point> {
    let compound = &case.compound;
    let dir = std::env::temp_dir().join(format!(
        "viscoroll-bands-{}-{}-{}-{}",
        std::process::id(),
        compound.name,
        case.protocol.seed,
        case.protocol.temps_c.len()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scenes = SceneSet::shipped();
    let settings = pipeline_contact_settings();
    // Every case uses the main job's default ensemble (with the fit's own choices, eqs.
    // 15.10–15.12); the held-out cases also build the data's scatter alone, to compare.
    let bs = BandSettings::default();
    let mut out = Vec::new();
    let path: PathBuf = dir.join(format!("{}.{}", compound.name, case.format.extension()));
    std::fs::write(
        &path,
        case.format.write(&dma_rows(compound, &case.protocol)),
    )
    .unwrap();
    let m = read_files(&[path], &IngestOptions::default()).unwrap();
    let (mut fit, master) =
        fit_measurement_master(&compound.name, &m, &FitOptions::default()).unwrap();
    fit.bands = Some(build_ensemble(&master, &m, &fit, &bs).unwrap());
    let ensemble = fit.bands.as_ref().unwrap();
    let bs_before = BandSettings {
        model_error: false,
        ..BandSettings::default()
    };
    let before = case
        .compare
        .then(|| build_ensemble(&master, &m, &fit, &bs_before).unwrap());
    let (true_creep, _) = relaxation_to_creep(&compound.spectrum).unwrap();
    let trusted = fit.untrusted_reasons().is_empty();
    for base in &scenes.scene {
        let mut spec = base.clone();
        spec.temps_c = TEMPS_C.to_vec();
        let scene = spec.scene();
        let got = friction_vs_temperature(&fit, &spec, &settings).unwrap();
        let on_true_law =
            friction_vs_temperature(&with_true_law(&fit, compound), &spec, &settings).unwrap();
        let bands = scene_bands_on(&fit, ensemble, &scene, &spec.temps_c, &bs);
        let bands_before = before
            .as_ref()
            .map(|e| scene_bands_on(&fit, e, &scene, &spec.temps_c, &bs_before));
        for (i, (p, r)) in got.iter().zip(&bands.ratios).enumerate() {
            let true_at_t = shifted(&true_creep, compound.law.log10_a_t(p.temp_c));
            let truth = true_friction(&scene, spec.cover_thickness_mm, &true_at_t, &settings);
            // A refused band (more than a quarter of the replicates' solves failed, or the
            // friction itself) is a point not covered: p05 = p95 = NaN, counted in the tables.
            let refused = viscoroll::results::FrictionBand {
                p05: f64::NAN,
                p50: f64::NAN,
                p95: f64::NAN,
            };
            let b = band_of(p.friction, r).unwrap_or(refused);
            let mut judged = p.clone();
            judged.band = Some(b);
            judged.determine(fit.measured_range_c());
            let claimed = trusted && judged.undetermined.is_none();
            out.push(Point {
                compound: compound.name.clone(),
                scene: spec.name.clone(),
                temp_c: p.temp_c,
                truth,
                friction: p.friction,
                p05: b.p05,
                p95: b.p95,
                stats: log_stats(r),
                window_decades: bands.window[i].as_ref().map(|w| w.excess.decades),
                extrapolated: bands.tail_ln[i].is_some(),
                before: bands_before.as_ref().map(|b| {
                    let b = band_of(p.friction, &b.ratios[i]).unwrap_or(refused);
                    (b.p05, b.p95)
                }),
                claimed,
                prony_share: Some((on_true_law[i].friction / truth).ln()),
                whole_range: case.protocol.temps_c.len() == DmaProtocol::default().temps_c.len(),
            });
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    out
}

/// The true friction of one point: the true creep spectrum at the point's shift, rolled as the main
/// job rolls the scene (on its cover at the main job's tolerance, or on the half-space).
fn true_friction(
    scene: &Scene,
    cover_mm: Option<f64>,
    true_at_t: &CreepSpectrum,
    settings: &ContactSettings,
) -> f64 {
    match cover_mm {
        Some(h_mm) => {
            roll_cover(
                &Scene {
                    body: Body::Auto {
                        thickness_m: h_mm * 1e-3,
                    },
                    ..*scene
                },
                true_at_t,
                settings.auto.tol.max(COVER_TOL),
            )
            .unwrap()
            .roll
            .friction
        }
        None => roll(scene, true_at_t, settings).unwrap().friction,
    }
}

/// `fit` with the compound's true shift law, referred to the fit's own reference temperature
/// (WLF re-referenced exactly, docs/MATH.md §6.4): the fitted spectrum read at the true shifts.
fn with_true_law(
    fit: &viscoroll::results::CompoundFit,
    c: &RealisticCompound,
) -> viscoroll::results::CompoundFit {
    let t_new = fit.shift_law.t_ref_c();
    let viscoroll::ShiftLaw::Wlf { t_ref_c, c1, c2_k } = c.law else {
        panic!("the held-out laws are WLF");
    };
    let d = c2_k + t_new - t_ref_c;
    let mut f = fit.clone();
    f.shift_law = viscoroll::ShiftLaw::Wlf {
        t_ref_c: t_new,
        c1: c1 * c2_k / d,
        c2_k: d,
    };
    f
}

/// Every (compound, scene, temperature) point of one noise seed of the tuning compounds
/// (`realistic_compounds`), measured from `lowest_c` up, as plain CSV.
fn points_of_seed(seed: u64, lowest_c: f64) -> Vec<Point> {
    realistic_compounds()
        .into_iter()
        .flat_map(|compound| {
            points_of_case(&Case {
                compound,
                protocol: protocol(seed, lowest_c, f64::INFINITY),
                format: ExportFormat::PlainCsv,
                compare: false,
            })
        })
        .collect()
}

fn covered(p: &Point) -> bool {
    p.p05 <= p.truth && p.truth <= p.p95
}

/// Where a point lies against the measured window and temperatures (for the coverage table).
fn class(p: &Point) -> &'static str {
    match (p.extrapolated, p.window_decades) {
        (true, _) => "beyond the measured temperatures (eq. 15.8)",
        (false, None) => "inside the window, no term",
        (false, Some(d)) if d <= 0.0 => "inside the window's last half decade (ramp, eq. 15.9c)",
        (false, Some(_)) => "beyond the window at a measured temperature (eq. 15.9)",
    }
}

/// `hit/n = x %` of the points.
fn coverage_of<'a>(pts: impl Iterator<Item = &'a Point>) -> (usize, usize) {
    pts.fold((0, 0), |(h, n), p| (h + usize::from(covered(p)), n + 1))
}

fn pct((h, n): (usize, usize)) -> String {
    if n == 0 {
        return format!("{h:>4}/{n:<4}   (none)");
    }
    format!("{h:>4}/{n:<4} = {:>5.1} %", 100.0 * h as f64 / n as f64)
}

/// Coverage table over `seeds`, the compounds measured from `lowest_c` up (per seed and compound,
/// per scene, per class of [`class`], total); returns every point.
fn calibrate(seeds: &[u64], lowest_c: f64) -> Vec<Point> {
    let mut all: Vec<(u64, Point)> = Vec::new();
    for &seed in seeds {
        let pts = points_of_seed(seed, lowest_c);
        let mut line = format!("seed {seed:>2}: {}", pct(coverage_of(pts.iter())));
        for c in ["nr-br-idler", "nr-tread", "sbr-tread", "high-tg-tread"] {
            let (h, n) = coverage_of(pts.iter().filter(|p| p.compound == c));
            line += &format!("  {c} {h}/{n}");
        }
        println!("{line}");
        all.extend(pts.into_iter().map(|p| (seed, p)));
    }
    report(all)
}

/// Print the coverage tables of `all` (seed, point): per compound (with the median relative
/// half-width and the misses above and below), per scene, per class of [`class`], the misses;
/// returns the points.
fn report(all: Vec<(u64, Point)>) -> Vec<Point> {
    let compounds = compound_names(&all);
    coverage_tables(&all, &compounds);
    class_widths(&all);
    misses_and_budget(&all);
    claims_table(&all, &compounds);
    accuracy_table(&all);
    let all: Vec<Point> = all.into_iter().map(|(_, p)| p).collect();
    println!("total: {}", pct(coverage_of(all.iter())));
    println!(
        "claimed: {}",
        pct(coverage_of(all.iter().filter(|p| p.claimed)))
    );
    all
}

/// The compounds of `all`, sorted, once each.
fn compound_names(all: &[(u64, Point)]) -> Vec<String> {
    let mut compounds: Vec<String> = all.iter().map(|(_, p)| p.compound.clone()).collect();
    compounds.dedup();
    compounds.sort();
    compounds.dedup();
    compounds
}

/// Coverage per compound, over all, per class of [`class`] (with the bands before this wave), and per scene.
fn coverage_tables(all: &[(u64, Point)], compounds: &[String]) {
    println!(
        "| compound | covered | median half-width | median log half-width | missed above / below \
         | before: covered | before: median half-width |"
    );
    println!("| --- | --- | --- | --- | --- | --- | --- |");
    let row = |name: &str, of: &[&Point]| {
        let (w, lw) = median_widths(of);
        let before: Vec<Point> = of
            .iter()
            .filter_map(|p| {
                p.before.map(|(p05, p95)| Point {
                    p05,
                    p95,
                    ..(*p).clone()
                })
            })
            .collect();
        let (bw, _) = median_widths(&before.iter().collect::<Vec<_>>());
        let refused = |f: &dyn Fn(&Point) -> f64| of.iter().filter(|p| f(p).is_nan()).count();
        println!(
            "| {name} | {} | {:.2} % | {lw:.4} | {} / {} | {} | {:.2} % | refused {} / before {} |",
            pct(coverage_of(of.iter().copied())),
            100.0 * w,
            of.iter().filter(|p| p.truth > p.p95).count(),
            of.iter().filter(|p| p.truth < p.p05).count(),
            pct(coverage_of(before.iter())),
            100.0 * bw,
            refused(&|p| p.p05),
            refused(&|p| p.before.map_or(0.0, |b| b.0))
        );
    };
    for c in compounds {
        let of: Vec<&Point> = all
            .iter()
            .map(|(_, p)| p)
            .filter(|p| &p.compound == c)
            .collect();
        row(c, &of);
    }
    let every: Vec<&Point> = all.iter().map(|(_, p)| p).collect();
    row("all", &every);
    for k in [
        "inside the window, no term",
        "inside the window's last half decade (ramp, eq. 15.9c)",
        "beyond the window at a measured temperature (eq. 15.9)",
        "beyond the measured temperatures (eq. 15.8)",
    ] {
        let of: Vec<&Point> = every.iter().copied().filter(|p| class(p) == k).collect();
        row(k, &of);
    }
    let scenes: Vec<String> = SceneSet::shipped()
        .scene
        .iter()
        .map(|s| s.name.clone())
        .collect();
    for s in &scenes {
        let c = coverage_of(all.iter().map(|(_, p)| p).filter(|p| &p.scene == s));
        println!("scene {s}: {}", pct(c));
    }
}

/// Per class of [`class`]: coverage, median log half-width, the window's reach and the misses; then
/// the median relative half-width and |error| / half-width.
fn class_widths(all: &[(u64, Point)]) {
    for k in [
        "inside the window, no term",
        "inside the window's last half decade (ramp, eq. 15.9c)",
        "beyond the window at a measured temperature (eq. 15.9)",
        "beyond the measured temperatures (eq. 15.8)",
    ] {
        let of: Vec<&Point> = all
            .iter()
            .map(|(_, p)| p)
            .filter(|p| class(p) == k)
            .collect();
        let mut w: Vec<f64> = of.iter().map(|p| (p.p95 / p.p05).ln() / 2.0).collect();
        w.sort_by(f64::total_cmp);
        let d: Vec<f64> = of.iter().filter_map(|p| p.window_decades).collect();
        let above = of.iter().filter(|p| p.truth > p.p95).count();
        let below = of.iter().filter(|p| p.truth < p.p05).count();
        println!(
            "{k:<56} {}  median log half-width {:.3}, Δ {:.2} … {:.2}; missed {above} above, \
             {below} below",
            pct(coverage_of(of.iter().copied())),
            w.get(w.len() / 2).copied().unwrap_or(f64::NAN),
            d.iter().copied().fold(f64::INFINITY, f64::min),
            d.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        );
    }
    // Relative half-width of the bands and |error| / half-width, medians.
    let mut width: Vec<f64> = all
        .iter()
        .map(|(_, p)| 0.5 * (p.p95 - p.p05) / p.friction)
        .collect();
    let mut err: Vec<f64> = all
        .iter()
        .map(|(_, p)| (p.friction - p.truth).abs() / (0.5 * (p.p95 - p.p05)))
        .collect();
    width.sort_by(f64::total_cmp);
    err.sort_by(f64::total_cmp);
    println!(
        "median relative half-width {:.2} %, median |F/N − true| / half-width {:.2}",
        100.0 * width[width.len() / 2],
        err[err.len() / 2]
    );
}

/// The first 40 misses, the error budget inside the window and the other readings of the replicates.
fn misses_and_budget(all: &[(u64, Point)]) {
    for (seed, p) in all.iter().filter(|(_, p)| !covered(p)).take(40) {
        println!(
            "missed: seed {seed} {} {} {} °C ({}): true {:.4e}, F/N {:.4e}, band {:.4e} … {:.4e}; \
             error {:+.2} % = shifts {:+.2} % + Prony {:+.2} %",
            p.compound,
            p.scene,
            p.temp_c,
            class(p),
            p.truth,
            p.friction,
            p.p05,
            p.p95,
            100.0 * (p.friction / p.truth).ln(),
            100.0 * ((p.friction / p.truth).ln() - p.prony_share.unwrap_or(f64::NAN)),
            100.0 * p.prony_share.unwrap_or(f64::NAN)
        );
    }
    println!("\nError budget inside the window (every such point; rms of ln F/F_true, per cent):");
    println!("| compound | points | total | shifts | Prony fit |\n| --- | --- | --- | --- | --- |");
    let mut names: Vec<&str> = all.iter().map(|(_, p)| p.compound.as_str()).collect();
    names.sort();
    names.dedup();
    for name in names {
        let of: Vec<&Point> = all
            .iter()
            .map(|(_, p)| p)
            .filter(|p| p.compound == name && class(p) == "inside the window, no term")
            .collect();
        let rms = |f: &dyn Fn(&Point) -> f64| {
            100.0 * (of.iter().map(|p| f(p).powi(2)).sum::<f64>() / of.len().max(1) as f64).sqrt()
        };
        let total = |p: &Point| (p.friction / p.truth).ln();
        let prony = |p: &Point| p.prony_share.unwrap_or(f64::NAN);
        println!(
            "| {name} | {} | {:.2} | {:.2} | {:.2} |",
            of.len(),
            rms(&total),
            rms(&|p| total(p) - prony(p)),
            rms(&prony)
        );
    }
    let n = all.len() as f64;
    let centred = all.iter().filter(|(_, p)| other_readings(p).0).count();
    let basic = all.iter().filter(|(_, p)| other_readings(p).1).count();
    println!(
        "other readings of the same replicates: centred on the replicates {:.1} %, basic bootstrap {:.1} %",
        100.0 * centred as f64 / n,
        100.0 * basic as f64 / n
    );
}

/// What the main job claims (trusted fit, determined point) and how often the claims cover.
fn claims_table(all: &[(u64, Point)], compounds: &[String]) {
    println!(
        "\nThe claims (trusted fit, determined point; what the main job prints as a band):\n\
         | compound | claimed | covered | median half-width | not claimed | not claimed, missed |"
    );
    println!("| --- | --- | --- | --- | --- | --- |");
    let claim_row = |name: &str, of: Vec<&Point>| {
        let claimed: Vec<&Point> = of.iter().copied().filter(|p| p.claimed).collect();
        let (w, _) = median_widths(&claimed);
        let open: Vec<&Point> = of.iter().copied().filter(|p| !p.claimed).collect();
        println!(
            "| {name} | {}/{} | {} | {:.2} % | {} | {} |",
            claimed.len(),
            of.len(),
            pct(coverage_of(claimed.iter().copied())),
            100.0 * w,
            open.len(),
            open.iter().filter(|p| !covered(p)).count()
        );
    };
    for c in compounds {
        claim_row(
            c,
            all.iter()
                .map(|(_, p)| p)
                .filter(|p| &p.compound == c)
                .collect(),
        );
    }
    claim_row("all", all.iter().map(|(_, p)| p).collect());
}

/// The point estimate's error |F/N − true|/true (issue 32, item 4), per compound: median and worst
/// over the cases measured over the whole range, and over the points the main job claims (trusted
/// fit, determined point) in every case, with the worst point named.
fn accuracy_table(all: &[(u64, Point)]) {
    println!(
        "\nEnd-to-end error of F/N (per cent):\n\
         | compound | whole range: n | median | worst | claimed: n | median | worst | worst whole-range point | worst claimed point |"
    );
    println!("| --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    let mut names: Vec<&str> = all.iter().map(|(_, p)| p.compound.as_str()).collect();
    names.sort();
    names.dedup();
    names.push("all");
    let err = |p: &Point| (p.friction / p.truth - 1.0).abs();
    let stats = |v: &[&(u64, Point)]| {
        let mut e: Vec<f64> = v
            .iter()
            .map(|(_, p)| {
                let e = err(p);
                if e.is_finite() {
                    e
                } else {
                    f64::INFINITY
                }
            })
            .collect();
        e.sort_by(f64::total_cmp);
        let med = e.get(e.len() / 2).copied().unwrap_or(f64::NAN);
        (
            e.len(),
            100.0 * med,
            100.0 * e.last().copied().unwrap_or(f64::NAN),
        )
    };
    for name in names {
        let of: Vec<&(u64, Point)> = all
            .iter()
            .filter(|(_, p)| name == "all" || p.compound == name)
            .collect();
        let whole: Vec<&(u64, Point)> = of.iter().copied().filter(|(_, p)| p.whole_range).collect();
        let claimed: Vec<&(u64, Point)> = of.iter().copied().filter(|(_, p)| p.claimed).collect();
        let (nw, mw, ww) = stats(&whole);
        let (nc, mc, wc) = stats(&claimed);
        let worst = |of: &[&(u64, Point)]| {
            of.iter()
                .max_by(|a, b| err(&a.1).total_cmp(&err(&b.1)))
                .map(|(s, p)| {
                    format!(
                        "seed {s} {} {} {} °C {:+.2} % (Prony {:+.2} %)",
                        p.compound,
                        p.scene,
                        p.temp_c,
                        100.0 * (p.friction / p.truth - 1.0),
                        100.0 * p.prony_share.unwrap_or(f64::NAN)
                    )
                })
                .unwrap_or_default()
        };
        println!(
            "| {name} | {nw} | {mw:.2} | {ww:.2} | {nc} | {mc:.2} | {wc:.2} | {} | {} |",
            worst(&whole),
            worst(&claimed)
        );
    }
}

/// Medians of the relative half-width (p95 − p05)/(2F) and of the log half-width ln(p95/p05)/2.
fn median_widths(pts: &[&Point]) -> (f64, f64) {
    let median = |v: Vec<f64>| {
        // Refused bands (NaN) left out of the widths; they count as misses in the coverage.
        let mut v: Vec<f64> = v.into_iter().filter(|x| x.is_finite()).collect();
        v.sort_by(f64::total_cmp);
        v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
    };
    (
        median(
            pts.iter()
                .map(|p| 0.5 * (p.p95 - p.p05) / p.friction)
                .collect(),
        ),
        median(pts.iter().map(|p| 0.5 * (p.p95 / p.p05).ln()).collect()),
    )
}

/// The fraction of `pts` covered.
fn total(pts: &[Point]) -> f64 {
    let (h, n) = coverage_of(pts.iter());
    h as f64 / n as f64
}

/// CI: two noise seeds (264 points); the same acceptance range as the full sweep.
#[test]
fn bands_cover_the_true_friction_two_seeds() {
    let total = total(&calibrate(&[1, 2], -60.0));
    assert!(
        (COVERAGE.0..=COVERAGE.1).contains(&total),
        "coverage {total:.3} outside {COVERAGE:?}"
    );
}

/// The figure: 10 noise seeds (1320 points).
#[test]
#[ignore = "10-seed calibration; run on demand (see the module docs)"]
fn bands_calibration_ten_seeds() {
    let total = total(&calibrate(&(1..=10).collect::<Vec<u64>>(), -60.0));
    assert!(
        (COVERAGE.0..=COVERAGE.1).contains(&total),
        "coverage {total:.3} outside {COVERAGE:?}"
    );
}

/// Lowest isotherm of the truncated measurements, °C: at −20 °C (and for some compounds and
/// scenes at −10 °C) the scenes' reduced rolling frequencies lie up to 1.9 decades above the
/// window's top (V/l is 0.8–7 kHz against the sweep's top of 100 Hz); −40 and −30 °C are beyond
/// the measured temperatures too.
const TRUNCATED_FROM_C: f64 = -20.0;

/// The points of `pts` inside the window (no term) and beyond it (Δ > 0), at measured
/// temperatures.
fn inside_and_beyond(pts: &[Point]) -> (Vec<Point>, Vec<Point>) {
    let measured = pts.iter().filter(|p| !p.extrapolated);
    (
        measured
            .clone()
            .filter(|p| p.window_decades.is_none())
            .cloned()
            .collect(),
        measured
            .filter(|p| p.window_decades.is_some_and(|d| d > 0.0))
            .cloned()
            .collect(),
    )
}

/// CI: the truncated measurements over two noise seeds (264 points, about 40 of them beyond the
/// window at a measured temperature): the total in the range, and points beyond the
/// window there to check (too few on two seeds to assert their own coverage: its sampling
/// error is ±5 %).
#[test]
fn bands_cover_the_true_friction_on_truncated_measurements_two_seeds() {
    let pts = calibrate(&[1, 2], TRUNCATED_FROM_C);
    let (_, beyond) = inside_and_beyond(&pts);
    assert!(
        beyond.len() >= 20,
        "{} points beyond the window",
        beyond.len()
    );
    let total = total(&pts);
    assert!(
        (COVERAGE.0..=COVERAGE.1).contains(&total),
        "coverage {total:.3} outside {COVERAGE:?}"
    );
}

/// The truncated measurements (isotherms from [`TRUNCATED_FROM_C`] up), 10 noise seeds (1320
/// points): the coverage inside and beyond the measured window, each in the range; the
/// points of the ramp inside the window's edge (eq. 15.9c) must not be under-covered (module docs:
/// they are over-covered, the price of a band without a step at the edge).
#[test]
#[ignore = "10-seed calibration on truncated measurements; run on demand (see the module docs)"]
fn bands_calibration_truncated_ten_seeds() {
    let pts = calibrate(&(1..=10).collect::<Vec<u64>>(), TRUNCATED_FROM_C);
    let (inside, beyond) = inside_and_beyond(&pts);
    let ramp: Vec<Point> = pts
        .iter()
        .filter(|p| !p.extrapolated && p.window_decades.is_some_and(|d| d <= 0.0))
        .cloned()
        .collect();
    println!(
        "inside {:.3} ({} points), ramp {:.3} ({}), beyond the window {:.3} ({})",
        total(&inside),
        inside.len(),
        total(&ramp),
        ramp.len(),
        total(&beyond),
        beyond.len()
    );
    assert!(
        beyond.len() >= 100,
        "{} points beyond the window",
        beyond.len()
    );
    for (what, of) in [("total", &pts), ("inside", &inside), ("beyond", &beyond)] {
        let c = total(of);
        assert!(
            (COVERAGE.0..=COVERAGE.1).contains(&c),
            "{what}: coverage {c:.3} outside {COVERAGE:?}"
        );
    }
    assert!(total(&ramp) >= COVERAGE.0, "ramp: {:.3}", total(&ramp));
}

/// The held-out calibration set (docs/MATH.md §15, "Calibration on held-out compounds"): every
/// compound of `held_out_compounds` (none of which the bands were tuned on) under each noise seed
/// of `seeds`; seed s is measured over the whole range (s mod 3 = 0), from −20 °C up (1) or up to
/// +40 °C (2), i.e. truncated at either end, and written as plain CSV, TRIOS text (shear) or
/// Proteus ASCII by (s + compound index) mod 3. Every run drifts (±1.5 K).
fn held_out_cases(seeds: &[u64]) -> Vec<(u64, Case)> {
    let mut cases = Vec::new();
    for &seed in seeds {
        for (j, compound) in held_out_compounds().into_iter().enumerate() {
            let (lo, hi) = match seed % 3 {
                0 => (f64::NEG_INFINITY, f64::INFINITY),
                1 => (TRUNCATED_FROM_C, f64::INFINITY),
                _ => (f64::NEG_INFINITY, TRUNCATED_TO_C),
            };
            cases.push((
                seed,
                Case {
                    compound,
                    protocol: protocol(seed, lo, hi),
                    format: ExportFormat::ALL[(seed as usize + j) % 3],
                    compare: true,
                },
            ));
        }
    }
    cases
}

/// Highest isotherm of the measurements truncated at the warm end, °C: +50 and +60 °C of the
/// scenes lie beyond the measured temperatures, and the slowest relaxation is not measured.
const TRUNCATED_TO_C: f64 = 40.0;

/// Calibrate on `cases`, in parallel over the cases; prints a line per case and the tables of
/// [`report`].
fn calibrate_cases(cases: Vec<(u64, Case)>) -> Vec<Point> {
    use rayon::prelude::*;
    let per_case: Vec<(u64, String, Vec<Point>)> = cases
        .par_iter()
        .map(|(seed, case)| {
            let label = format!(
                "seed {seed:>3} {:<18} {:>2} isotherms {:?}",
                case.compound.name,
                case.protocol.temps_c.len(),
                case.format
            );
            (*seed, label, points_of_case(case))
        })
        .collect();
    let mut all = Vec::new();
    for (seed, label, pts) in per_case {
        println!("{label}: {}", pct(coverage_of(pts.iter())));
        all.extend(pts.into_iter().map(|p| (seed, p)));
    }
    report(all)
}

/// The held-out set's acceptance range of a 90 % band's coverage (the goal).
const HELD_OUT_GOAL: (f64, f64) = (0.85, 0.95);

/// The figure on the held-out set: 8 compounds × 10 seeds (80 measured compounds, 2640
/// points), overall and per compound within the goal.
#[test]
#[ignore = "held-out calibration, 80 measured compounds; run on demand (see the module docs)"]
fn bands_calibration_held_out_ten_seeds() {
    // VISCOROLL_HELD_OUT_SEEDS=n runs the first n seeds only (a quicker look; the goal is
    // asserted on all 10).
    let n: u64 = std::env::var("VISCOROLL_HELD_OUT_SEEDS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(10);
    // VISCOROLL_HELD_OUT_WHOLE=1: only the seeds measured over the whole range (a look at the
    // end-to-end accuracy; the coverage goal is asserted on all ten).
    let whole = std::env::var("VISCOROLL_HELD_OUT_WHOLE").is_ok();
    let seeds: Vec<u64> = (101..=100 + n).filter(|s| !whole || s % 3 == 0).collect();
    let pts = calibrate_cases(held_out_cases(&seeds));
    if whole {
        return;
    }
    let mut failed = Vec::new();
    for c in held_out_compounds() {
        let of: Vec<Point> = pts
            .iter()
            .filter(|p| p.compound == c.name)
            .cloned()
            .collect();
        let t = total(&of);
        if !(HELD_OUT_GOAL.0..=HELD_OUT_GOAL.1).contains(&t) {
            failed.push(format!("{} {t:.3}", c.name));
        }
    }
    let t = total(&pts);
    assert!(
        (HELD_OUT_GOAL.0..=HELD_OUT_GOAL.1).contains(&t),
        "coverage {t:.3} outside {HELD_OUT_GOAL:?}"
    );
    assert!(
        failed.is_empty(),
        "per compound outside {HELD_OUT_GOAL:?}: {failed:?}"
    );
}

/// CI: one measured case of each held-out compound (8 cases, 264 points; every protocol and every
/// format appear). Tolerance: the 264 points are 8 clusters of 33 that share a fit, so they are
/// not independent; with the between-case spread of the full run (cases range over roughly
/// 70–100 %) the standard error of the mean of 8 cases is about 3.5 %; [0.80, 0.97] is the goal
/// 85–95 % widened by about 1.5 of those, which a band at 90 % fails by chance in well under 5 %
/// of draws, while a band that is 2× too narrow (coverage ≈ 60 %) or 2× too wide (≈ 100 %) fails.
#[test]
#[ignore = "several minutes in the test profile (8 cases, two ensembles each, every scene's contact solves); the refits' convergence is checked in CI by held_out_refits_all_converge"]
fn bands_cover_the_true_friction_held_out_one_seed_each() {
    let t = total(&calibrate_cases(one_seed_each()));
    assert!(
        (COVERAGE.0..=COVERAGE.1).contains(&t),
        "coverage {t:.3} outside {COVERAGE:?}"
    );
}

/// One measured case of each held-out compound (seeds 201–208: every protocol and every format
/// appear).
fn one_seed_each() -> Vec<(u64, Case)> {
    let cases: Vec<(u64, Case)> = held_out_cases(&[201, 202, 203, 204, 205, 206, 207, 208])
        .into_iter()
        .enumerate()
        .filter(|(k, _)| k % 9 == 0)
        .map(|(_, c)| c)
        .collect();
    assert_eq!(cases.len(), 8);
    cases
}

/// Every bootstrap refit of the one-seed-each held-out cases converges, with and without the fit's
/// own choices (eqs. 15.10–15.12): 0 of 32 failed in each of the 16 ensembles. Three of these
/// cases (long-plateau, high-tg, steep-glass-side) have master curves whose E′-alone shifts miss
/// the truth by 1.9–6.4 decades, so their fits miss the data by 0.65–2.5 decades rms in log E″
/// and choose λ = 1e-9; before the Prony QP's column scaling (crate::prony::fit, "Numerics")
/// 13–30 of their 32 refits failed (InsufficientProgress / NumericalError) and the band was
/// refused. About 10 s (no contact solves).
#[test]
fn held_out_refits_all_converge() {
    use rayon::prelude::*;
    let failures: Vec<String> = one_seed_each()
        .par_iter()
        .flat_map(|(seed, case)| {
            let dir = std::env::temp_dir().join(format!(
                "viscoroll-refits-{}-{}-{seed}",
                std::process::id(),
                case.compound.name
            ));
            let _ = std::fs::remove_dir_all(&dir);
            std::fs::create_dir_all(&dir).unwrap();
            let path = dir.join(format!(
                "{}.{}",
                case.compound.name,
                case.format.extension()
            ));
            std::fs::write(
                &path,
                case.format.write(&dma_rows(&case.compound, &case.protocol)),
            )
            .unwrap();
            let m = read_files(&[path], &IngestOptions::default()).unwrap();
            let (fit, master) =
                fit_measurement_master(&case.compound.name, &m, &FitOptions::default()).unwrap();
            let mut bad = Vec::new();
            for model_error in [false, true] {
                let bs = BandSettings {
                    model_error,
                    ..BandSettings::default()
                };
                match build_ensemble(&master, &m, &fit, &bs) {
                    Ok(e) if e.replicates.len() == bs.replicates && e.notes.is_empty() => {}
                    Ok(e) => bad.push(format!(
                        "{} (model error {model_error}): {} of {} refits, {:?}",
                        case.compound.name,
                        e.replicates.len(),
                        bs.replicates,
                        e.notes
                    )),
                    Err(e) => bad.push(format!(
                        "{} (model error {model_error}): {e}",
                        case.compound.name
                    )),
                }
            }
            let _ = std::fs::remove_dir_all(&dir);
            bad
        })
        .collect();
    assert!(failures.is_empty(), "{failures:#?}");
}

/// Writes every held-out case's export of the seeds in `VISCOROLL_HELD_OUT_SEEDS` (default 101–103)
/// into the folder `VISCOROLL_DUMP_DIR` (one file per case, as the calibration writes it), to look at
/// a case with the CLI: `VISCOROLL_DUMP_DIR=/tmp/h cargo test --lib dump_held_out_exports --
/// --ignored`, then `viscoroll master /tmp/h/seed102-high-tg.csv`.
#[test]
#[ignore = "a tool, not a check"]
fn dump_held_out_exports() {
    let Ok(dir) = std::env::var("VISCOROLL_DUMP_DIR") else {
        return;
    };
    let n: u64 = std::env::var("VISCOROLL_HELD_OUT_SEEDS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(3);
    std::fs::create_dir_all(&dir).unwrap();
    for (seed, case) in held_out_cases(&(101..=100 + n).collect::<Vec<u64>>()) {
        let name = format!(
            "seed{seed}-{}.{}",
            case.compound.name,
            case.format.extension()
        );
        let text = case.format.write(&dma_rows(&case.compound, &case.protocol));
        std::fs::write(PathBuf::from(&dir).join(name), text).unwrap();
    }
}

/// The Prony λ search goes on below its grid while GCV still falls (crate::prony::fit, MATH §5):
/// on the held-out long-plateau compound (seed 101, measured up to +40 °C, TRIOS text) E″ spans
/// eight decades, the grid's smallest λ smoothed the spectrum so much that the fit missed its own
/// smooth master curve by 0.108 (E′) and 0.146 (E″) decades rms, and the compound was not trusted.
/// The unregularised non-negative least squares on the same grid (scipy's NNLS, computed apart)
/// reaches 0.0043 and 0.0116; the bounds are about twice that, below the fit-quality bounds
/// (0.04, 0.15) and ten times below the failure.
#[test]
fn a_long_plateau_is_fitted_to_its_data_not_smoothed_away() {
    let (seed, case) = held_out_cases(&[101])
        .into_iter()
        .find(|(_, c)| c.compound.name == "long-plateau")
        .unwrap();
    assert_eq!(case.format, ExportFormat::TriosText);
    let dir = std::env::temp_dir().join(format!("viscoroll-plateau-{}-{seed}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("long-plateau.{}", case.format.extension()));
    std::fs::write(
        &path,
        case.format.write(&dma_rows(&case.compound, &case.protocol)),
    )
    .unwrap();
    let m = read_files(&[path], &IngestOptions::default()).unwrap();
    let (fit, _) = fit_measurement_master("long-plateau", &m, &FitOptions::default()).unwrap();
    let info = &fit.prony_info;
    assert!(
        info.rms_log10_storage < 0.01 && info.rms_log10_loss < 0.025,
        "E′ {} E″ {} at λ {}",
        info.rms_log10_storage,
        info.rms_log10_loss,
        info.lambda
    );
    assert!(info.lambda < 1e-9, "λ {}", info.lambda);
    assert!(
        fit.untrusted_reasons().is_empty(),
        "{:?}",
        fit.untrusted_reasons()
    );
    let _ = std::fs::remove_dir_all(&dir);
}
