//! Park & Schapery (thesis eq. 2.18–2.23) against the exact conversion (docs/MATH.md §4), and the measured
//! accuracy of the exact conversion itself. Prints markdown tables to stdout.
//!
//! Run: `cargo run --release --example park_schapery_table`
//!
//! Spectra: a standard linear solid; a rubber-like spectrum (E∞ = 1 MPa, E₀ = 1 GPa, Eᵢ ∝ ρᵢ^(−1/2),
//! the slope of a transition zone) sampled at 0.5, 1 and 2 times per decade; and 1000 random spectra
//! drawn like the property tests (1–40 terms, log10 ρ uniform in [−12, 12], log10 Eᵢ uniform in
//! [2, 10], log10 E∞ uniform in [4, 8]; fixed seed).
//!
//! Error measures (P&S result vs exact): `J(t)` max relative error of the creep compliance on
//! t = ρ_min/100 … 100·τ_max (8 points/decade, τ_max the longest exact retardation time); `J∞` relative
//! error of the relaxed compliance (1/E∞ exactly); `E*J*` max |E*J* − 1| on ω = 1/t over the same
//! grid; `neg` number of negative strengths; `cond` condition number of A with unit columns.

use viscoroll::creep::{
    creep_to_relaxation, park_schapery, relaxation_to_creep, ParkSchaperySettings,
    ParkSchaperyVariant,
};
use viscoroll::prony::{RelaxationSpectrum, RelaxationTerm};
use viscoroll::{CreepSpectrum, ModulusKind};

fn spectrum(e_inf: f64, terms: Vec<(f64, f64)>) -> RelaxationSpectrum {
    RelaxationSpectrum {
        kind: ModulusKind::Tensile,
        poisson: 0.5,
        modulus_inf_pa: e_inf,
        terms: terms
            .into_iter()
            .map(|(e, tau)| RelaxationTerm {
                modulus_pa: e,
                tau_s: tau,
            })
            .collect(),
    }
}

/// E∞ = 1 MPa, Σ Eᵢ = 1 GPa − 1 MPa, Eᵢ ∝ ρᵢ^(−1/2), `n` times from 1e-12 s spaced 1/`per_decade`.
fn rubber(n: usize, per_decade: f64) -> RelaxationSpectrum {
    let taus: Vec<f64> = (0..n)
        .map(|k| 10f64.powf(-12.0 + k as f64 / per_decade))
        .collect();
    let w: Vec<f64> = taus.iter().map(|t| t.powf(-0.5)).collect();
    let sum: f64 = w.iter().sum();
    spectrum(
        1e6,
        taus.iter()
            .zip(&w)
            .map(|(&t, &wi)| (wi / sum * (1e9 - 1e6), t))
            .collect(),
    )
}

struct SplitMix(u64);
impl SplitMix {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

fn random_spectrum(rng: &mut SplitMix) -> RelaxationSpectrum {
    let n = 1 + (rng.next() * 40.0) as usize;
    let terms = (0..n)
        .map(|_| {
            (
                10f64.powf(rng.uniform(2.0, 10.0)),
                10f64.powf(rng.uniform(-12.0, 12.0)),
            )
        })
        .collect();
    spectrum(10f64.powf(rng.uniform(4.0, 8.0)), terms)
}

fn grid(lo: f64, hi: f64, per_decade: f64) -> Vec<f64> {
    let (a, b) = (lo.log10(), hi.log10());
    let n = ((b - a) * per_decade).ceil().max(1.0) as usize;
    (0..=n)
        .map(|k| 10f64.powf(a + (b - a) * k as f64 / n as f64))
        .collect()
}

struct Row {
    j_t: f64,
    j_inf: f64,
    ej: f64,
    neg: usize,
    cond: f64,
}

fn compare(
    relax: &RelaxationSpectrum,
    exact: &CreepSpectrum,
    variant: ParkSchaperyVariant,
) -> Option<Row> {
    let settings = ParkSchaperySettings {
        variant,
        ..Default::default()
    };
    let (ps, info) = park_schapery(relax, &settings).ok()?;
    let rho_min = relax
        .terms
        .iter()
        .map(|t| t.tau_s)
        .fold(f64::INFINITY, f64::min);
    let tau_max = exact.terms.iter().map(|t| t.tau_s).fold(0.0, f64::max);
    let ts = grid(rho_min / 100.0, tau_max * 100.0, 8.0);
    let j_t = ts
        .iter()
        .map(|&t| (ps.creep_compliance(t) / exact.creep_compliance(t) - 1.0).abs())
        .fold(0.0, f64::max);
    let omegas: Vec<f64> = ts.iter().map(|t| 1.0 / t).collect();
    Some(Row {
        j_t,
        j_inf: (ps.compliance_relaxed() * relax.modulus_inf_pa - 1.0).abs(),
        ej: relax.max_product_error(&ps, &omegas),
        neg: info.negative_terms,
        cond: info.condition_number,
    })
}

const VARIANTS: [ParkSchaperyVariant; 3] = [
    ParkSchaperyVariant::CollocationOne,
    ParkSchaperyVariant::CollocationHalf,
    ParkSchaperyVariant::LeastSquares,
];

fn main() {
    let named: Vec<(String, RelaxationSpectrum)> = vec![
        ("SLS, E₀/E∞ = 10".into(), spectrum(1e6, vec![(9e6, 1e-3)])),
        ("rubber, 13 terms, 0.5/decade".into(), rubber(13, 0.5)),
        ("rubber, 25 terms, 1/decade".into(), rubber(25, 1.0)),
        ("rubber, 40 terms, 2/decade".into(), rubber(40, 2.0)),
    ];
    println!("## Park & Schapery (τⱼ = ρⱼ) vs exact\n");
    println!("| spectrum | variant | max rel. err J(t) | rel. err J∞ | max abs(E*J*−1) | neg. Jⱼ | cond(A) |");
    println!("|---|---|---|---|---|---|---|");
    for (name, relax) in &named {
        let (exact, _) = relaxation_to_creep(relax).expect("valid spectrum");
        for v in VARIANTS {
            match compare(relax, &exact, v) {
                Some(r) => println!(
                    "| {name} | {} | {:.2e} | {:.2e} | {:.2e} | {} | {:.2e} |",
                    v.name(),
                    r.j_t,
                    r.j_inf,
                    r.ej,
                    r.neg,
                    r.cond
                ),
                None => println!("| {name} | {} | failed (singular) | | | | |", v.name()),
            }
        }
    }

    // Random spectra: P&S statistics and the exact conversion's own accuracy.
    let mut rng = SplitMix(0x5eed_5bec);
    let spectra: Vec<RelaxationSpectrum> = (0..1000).map(|_| random_spectrum(&mut rng)).collect();
    println!("\n## Park & Schapery on 1000 random spectra (1–40 terms over 24 decades)\n");
    println!("| variant | median rel. err J(t) | max rel. err J(t) | median rel. err J∞ | spectra with neg. Jⱼ | median cond(A) | max cond(A) | failed |");
    println!("|---|---|---|---|---|---|---|---|");
    let exacts: Vec<CreepSpectrum> = spectra
        .iter()
        .map(|s| relaxation_to_creep(s).unwrap().0)
        .collect();
    for v in VARIANTS {
        let mut rows = Vec::new();
        let mut failed = 0;
        for (s, e) in spectra.iter().zip(&exacts) {
            match compare(s, e, v) {
                Some(r) => rows.push(r),
                None => failed += 1,
            }
        }
        let med = |mut x: Vec<f64>| {
            x.sort_by(f64::total_cmp);
            x[x.len() / 2]
        };
        let max = |x: &[f64]| x.iter().cloned().fold(0.0, f64::max);
        let jt: Vec<f64> = rows.iter().map(|r| r.j_t).collect();
        let ji: Vec<f64> = rows.iter().map(|r| r.j_inf).collect();
        let cd: Vec<f64> = rows.iter().map(|r| r.cond).collect();
        println!(
            "| {} | {:.2e} | {:.2e} | {:.2e} | {} / {} | {:.2e} | {:.2e} | {} |",
            v.name(),
            med(jt.clone()),
            max(&jt),
            med(ji),
            rows.iter().filter(|r| r.neg > 0).count(),
            rows.len(),
            med(cd.clone()),
            max(&cd),
            failed
        );
    }

    // Exact conversion: measured maxima over the same 1000 spectra.
    let omegas = grid(1e-20, 1e20, 8.0);
    let ts = grid(1e-16, 1e16, 4.0);
    let (mut ej, mut j0, mut jinf, mut rho, mut emod, mut et, mut einf) =
        (0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64);
    let mut min_j = f64::INFINITY;
    let (mut rev, mut estar, mut emod_sep) = (0f64, 0f64, 0f64);
    for (s, c) in spectra.iter().zip(&exacts) {
        ej = ej.max(s.max_product_error(c, &omegas));
        j0 = j0.max((c.creep_compliance(0.0) * s.instantaneous_modulus() - 1.0).abs());
        jinf = jinf.max((c.compliance_relaxed() * s.modulus_inf_pa - 1.0).abs());
        min_j = c
            .terms
            .iter()
            .map(|t| t.compliance_per_pa * s.instantaneous_modulus())
            .fold(min_j, f64::min);
        let (back, _) = creep_to_relaxation(c).unwrap();
        rev = rev.max(back.max_product_error(c, &omegas));
        for &w in &omegas {
            let (a1, a2) = s.complex_modulus(w);
            let (b1, b2) = back.complex_modulus(w);
            estar = estar.max((b1 - a1).hypot(b2 - a2) / a1.hypot(a2));
        }
        einf = einf.max((back.modulus_inf_pa / s.modulus_inf_pa - 1.0).abs());
        let mut a = s.terms.clone();
        let mut b = back.terms.clone();
        a.sort_by(|x, y| x.tau_s.total_cmp(&y.tau_s));
        b.sort_by(|x, y| x.tau_s.total_cmp(&y.tau_s));
        assert_eq!(a.len(), b.len());
        for (i, (x, y)) in a.iter().zip(&b).enumerate() {
            rho = rho.max((y.tau_s / x.tau_s - 1.0).abs());
            let err = (y.modulus_pa - x.modulus_pa).abs() / s.relaxation_modulus(x.tau_s);
            emod = emod.max(err);
            let gap = |j: usize| (a[j].tau_s / x.tau_s).ln().abs();
            let g = [i.checked_sub(1), (i + 1 < a.len()).then_some(i + 1)]
                .into_iter()
                .flatten()
                .map(gap)
                .fold(f64::INFINITY, f64::min);
            if g >= 0.01 {
                emod_sep = emod_sep.max(err);
            }
        }
        for &t in &ts {
            et = et.max((back.relaxation_modulus(t) / s.relaxation_modulus(t) - 1.0).abs());
        }
    }
    println!("\n## Exact conversion, measured over the same 1000 spectra\n");
    println!("| quantity | max over spectra |");
    println!("|---|---|");
    println!("| abs(E*J* − 1), ω = 1e-20…1e20 rad/s, 8/decade | {ej:.2e} |");
    println!("| abs(J(0)·E₀ − 1) | {j0:.2e} |");
    println!("| abs(J∞·E∞ − 1) | {jinf:.2e} |");
    println!("| min Jⱼ·E₀ (all > 0) | {min_j:.2e} |");
    println!("| creep → relaxation: abs(E*J* − 1) of its own output | {rev:.2e} |");
    println!("| round trip: abs(E*_back − E*)/abs(E*), ω = 1e-20…1e20 rad/s | {estar:.2e} |");
    println!("| round trip: rel. err E∞ | {einf:.2e} |");
    println!("| round trip: rel. err ρᵢ | {rho:.2e} |");
    println!("| round trip: abs(ΔEᵢ)/E(ρᵢ), all terms | {emod:.2e} |");
    println!(
        "| round trip: abs(ΔEᵢ)/E(ρᵢ), terms ≥ 1 % from their neighbours in τ | {emod_sep:.2e} |"
    );
    println!("| round trip: rel. err E(t), t = 1e-16…1e16 s | {et:.2e} |");
}
