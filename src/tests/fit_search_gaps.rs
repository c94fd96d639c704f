//! Gaps in the fit and shift stages found by mutation testing (issue 19, item 6; docs/DEVLOG.md "Mutation
//! testing"): what the Prony fit reports about its λ search, and the per-channel scatter the joint
//! shift criterion weighs by. Data from formulas written here (Cole–Cole, the WLF 1955 universal
//! constants), not from the fitter's own model; the references are recomputed from the answer.
//!
//! Surviving mutants they catch: `prony/fit.rs` `Problem::norms` (‖Ax − b‖, ‖Lx‖) replaced by
//! constants — only the weight rules read them, and the fits stayed within their error bounds;
//! `tts/shift.rs` `pair_shift`'s coarse grid moved off [lo, hi] (`lo + …` → `lo − …`) and
//! `channel_scatter`'s mean over pairs (`/` → `%`) — the global refinement absorbed both in the
//! shifts, but the scatters that weigh the joint criterion's channels were wrong.

use std::f64::consts::PI;
use viscoroll::dma::{self, IngestOptions};
use viscoroll::prony::{
    fit_prony, relaxation_times_s, LambdaCandidate, MasterPoint, PronySettings, WeightRule,
};
use viscoroll::tts::{build_master_curve, MasterSettings, ShiftCriterion};
use viscoroll::ModulusKind;

/// Glassy and relaxed modulus (Pa), τ (s) at the reference temperature, Cole–Cole α.
const E0: f64 = 1e9;
const EINF: f64 = 3e6;
const TAU: f64 = 1e-6;
const ALPHA: f64 = 0.5;

/// (E′, E″) of the Cole–Cole solid at angular frequency ω (rad/s): E* = E∞ + (E₀ − E∞)·(iωτ)^α/(1 +
/// (iωτ)^α), written out in real and imaginary parts.
fn cole_cole(omega: f64) -> (f64, f64) {
    let r = (omega * TAU).powf(ALPHA);
    let phi = ALPHA * PI / 2.0;
    let d = 1.0 + 2.0 * r * phi.cos() + r * r;
    (
        EINF + (E0 - EINF) * (r * phi.cos() + r * r) / d,
        (E0 - EINF) * r * phi.sin() / d,
    )
}

/// A deterministic stream of uniform numbers in [−1, 1) (64-bit LCG, Knuth's MMIX constants).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
}

/// (E′, E″) of a Prony series at ω, written out: E∞ + Σ Eⱼ ω²τⱼ²/(1 + ω²τⱼ²), Σ Eⱼ ωτⱼ/(1 + ω²τⱼ²).
fn prony_moduli(e_inf: f64, terms: &[(f64, f64)], omega: f64) -> (f64, f64) {
    terms.iter().fold((e_inf, 0.0), |(s, l), &(e, tau)| {
        let wt = omega * tau;
        (
            s + e * wt * wt / (1.0 + wt * wt),
            l + e * wt / (1.0 + wt * wt),
        )
    })
}

/// The Prony fit's λ search, under both weight rules, on Cole–Cole moduli with 1 % multiplicative
/// noise (61 points over 8 decades): the residual norm and seminorm reported at the chosen λ are
/// recomputed from the fitted spectrum — ‖r‖² = Σ(E′_fit/E′ − 1)² + Σ(E″_fit/E″ − 1)² (relative
/// residuals, loss weight 1) and ‖Lx‖ = the second differences of the term moduli on the grid over
/// the largest E′ datum — and along the search ‖r‖ must not fall and ‖Lx‖ must not rise as λ grows
/// (the trade-off of any penalised least-squares problem over a convex set).
#[test]
fn prony_weight_search_reports_the_norms_of_its_solutions() {
    let mut rng = Lcg(19);
    let points: Vec<MasterPoint> = (0..61)
        .map(|k| {
            let f = 10f64.powf(-2.0 + 8.0 * k as f64 / 60.0);
            let (e1, e2) = cole_cole(2.0 * PI * f);
            MasterPoint::new(
                f,
                e1 * (1.0 + 0.01 * rng.next()),
                e2 * (1.0 + 0.01 * rng.next()),
            )
        })
        .collect();
    for rule in [WeightRule::LCurve, WeightRule::Gcv] {
        let settings = PronySettings {
            weight_rule: rule,
            ..PronySettings::default()
        };
        let fit = fit_prony(&points, ModulusKind::Tensile, 0.5, &settings).unwrap();
        let info = &fit.info;
        let chosen = info
            .lambda_search
            .iter()
            .find(|c| c.lambda == info.lambda)
            .expect("the chosen λ is one of the search's");
        // ‖r‖ from the spectrum.
        let terms: Vec<(f64, f64)> = fit
            .spectrum
            .terms
            .iter()
            .map(|t| (t.modulus_pa, t.tau_s))
            .collect();
        let r2: f64 = points
            .iter()
            .map(|p| {
                let (e1, e2) = prony_moduli(
                    fit.spectrum.modulus_inf_pa,
                    &terms,
                    2.0 * PI * p.reduced_freq_hz,
                );
                (e1 / p.storage_pa - 1.0).powi(2) + (e2 / p.loss_pa - 1.0).powi(2)
            })
            .sum();
        // The terms dropped after the solve (each moving any datum by < drop_threshold = 1e-7,
        // relatively) change ‖r‖ by at most √(2·61)·1e-7·(terms dropped) ≈ 1e-6·(terms dropped) of
        // an absolute value ≈ 0.1: 1e-4 relative covers 100 dropped terms.
        let dropped = info.n_terms_grid - info.n_terms_kept;
        assert!(
            (r2.sqrt() - chosen.residual_norm).abs() <= 1e-4 * chosen.residual_norm,
            "{rule:?}: ‖r‖ reported {:e}, from the spectrum {:e} ({dropped} terms dropped)",
            chosen.residual_norm,
            r2.sqrt()
        );
        // ‖Lx‖ from the spectrum, the kept terms placed back on the grid (dropped ones are 0).
        let seminorm = seminorm_on_grid(&points, &terms, &settings, info.n_terms_grid);
        // A dropped term has x·(its largest relative effect) < 1e-7; its effect is ≳ 1e-3 for grid
        // times inside the data's window ± 0.5 decade, so each moves ‖Lx‖ by ≲ 2.5e-4 (the second
        // difference weights 1, 2, 1) against ‖Lx‖ ≈ 0.01–1 here: 5 % covers it, while the constant
        // mutants (0 or 1) are off by 100 % or more.
        assert!(
            (seminorm - chosen.seminorm).abs() <= 0.05 * chosen.seminorm.max(seminorm),
            "{rule:?}: ‖Lx‖ reported {:e}, from the spectrum {seminorm:e}",
            chosen.seminorm
        );
        assert!(chosen.residual_norm > 0.0 && chosen.seminorm > 0.0);
        assert_trade_off(rule, &info.lambda_search);
        // The search spans the trade-off: ‖r‖ grows by more than the solver's noise over it.
        let (first, last) = (
            info.lambda_search.first().unwrap(),
            info.lambda_search.last().unwrap(),
        );
        assert!(last.residual_norm > 1.01 * first.residual_norm);
        assert!(last.seminorm < 0.99 * first.seminorm);
    }
}

/// ‖Lx‖ of the fitted terms placed back on the grid of `settings` over the data (dropped terms
/// are 0), the moduli scaled by the largest E′ datum.
fn seminorm_on_grid(
    points: &[MasterPoint],
    terms: &[(f64, f64)],
    settings: &PronySettings,
    n_grid: usize,
) -> f64 {
    let f_min = points[0].reduced_freq_hz;
    let f_max = points[60].reduced_freq_hz;
    let grid = relaxation_times_s(f_min, f_max, settings);
    assert_eq!(grid.len(), n_grid);
    let scale = points.iter().map(|p| p.storage_pa).fold(0.0, f64::max);
    let x: Vec<f64> = grid
        .iter()
        .map(|&tau| {
            terms
                .iter()
                .find(|&&(_, t)| (t / tau - 1.0).abs() < 1e-12)
                .map_or(0.0, |&(e, _)| e / scale)
        })
        .collect();
    x.windows(3)
        .map(|w| (w[0] - 2.0 * w[1] + w[2]).powi(2))
        .sum::<f64>()
        .sqrt()
}

/// Along the weight search ‖r‖ must not fall and ‖Lx‖ must not rise as λ grows.
fn assert_trade_off(rule: WeightRule, search: &[LambdaCandidate]) {
    // The trade-off along the search (solver tolerance ~1e-8 on the scaled problem: 1e-6
    // relative slack).
    for w in search.windows(2) {
        assert!(w[1].lambda > w[0].lambda);
        assert!(
            w[1].residual_norm >= w[0].residual_norm * (1.0 - 1e-6),
            "{rule:?}: ‖r‖ fell from {:e} to {:e} as λ rose to {:e}",
            w[0].residual_norm,
            w[1].residual_norm,
            w[1].lambda
        );
        assert!(
            w[1].seminorm <= w[0].seminorm * (1.0 + 1e-6),
            "{rule:?}: ‖Lx‖ rose from {:e} to {:e} as λ rose to {:e}",
            w[0].seminorm,
            w[1].seminorm,
            w[1].lambda
        );
    }
}

/// WLF 1955 universal law, log10 a_T relative to 20 °C.
fn wlf_universal(t_c: f64) -> f64 {
    -8.86 * (t_c - 20.0) / (101.6 + t_c - 20.0)
}

/// A plain CSV export of Cole–Cole isotherms at `temps_c` (13 frequencies 0.1–100 Hz, shifted by
/// the WLF universal law), with a multiplicative log-uniform noise of standard deviation `sigma`
/// decades on E′ and E″ (uniform in ±√3·σ), the same noise for an isotherm whatever the set it is in.
fn export(temps_c: &[f64], sigma: f64) -> Vec<u8> {
    let mut s = String::from("Frequency,E',E'',Temperature,Segment\nHz,MPa,MPa,°C,-\n");
    for (seg, &t) in temps_c.iter().enumerate() {
        let mut rng = Lcg(1000 + t as u64);
        let a_t = 10f64.powf(wlf_universal(t));
        for j in 0..13 {
            let f = 10f64.powf(-1.0 + 3.0 * j as f64 / 12.0);
            let (e1, e2) = cole_cole(2.0 * PI * f * a_t);
            let n1 = 10f64.powf(3f64.sqrt() * sigma * rng.next());
            let n2 = 10f64.powf(3f64.sqrt() * sigma * rng.next());
            s.push_str(&format!(
                "{f:.6e},{:.9e},{:.9e},{t:.2},{seg}\n",
                e1 * n1 * 1e-6,
                e2 * n2 * 1e-6
            ));
        }
    }
    s.into_bytes()
}

/// The joint criterion's channel scatters (MasterQuality::channel_scatter_log10: the RMS over
/// neighbour pairs of each channel's mismatch at its own best pairwise shift), on isotherms at 0,
/// 10 and 20 °C with σ = 0.02 decade of noise: (1) the level — two noisy curves compared at the
/// right shift differ by about √2·σ pointwise less what the interpolant averages out, so each
/// scatter lies between 0.5σ and 2σ (and far above the 0.002 floor a failed pair search falls back
/// to); (2) the mean over pairs — the three-isotherm scatter squared is the mean of the two
/// two-isotherm ones squared (the same pairs with the same data), to round-off.
#[test]
fn joint_criterion_channel_scatter_is_the_rms_over_neighbour_pairs() {
    let sigma = 0.02;
    let scatter = |temps: &[f64]| -> Vec<f64> {
        let m = dma::read_bytes(
            &[("cole-cole.csv".to_string(), export(temps, sigma))],
            &IngestOptions::default(),
        )
        .unwrap();
        let mc = build_master_curve(
            &m,
            &MasterSettings {
                criterion: ShiftCriterion::Joint,
                ..MasterSettings::default()
            },
        )
        .unwrap();
        mc.quality.channel_scatter_log10.clone()
    };
    let all = scatter(&[0.0, 10.0, 20.0]);
    let low = scatter(&[0.0, 10.0]);
    let high = scatter(&[10.0, 20.0]);
    assert_eq!(all.len(), 2, "{all:?}");
    for (c, name) in ["E′", "E″"].iter().enumerate() {
        for s in [all[c], low[c], high[c]] {
            assert!(
                s > 0.5 * sigma && s < 2.0 * sigma,
                "{name}: scatter {s:e} vs noise σ = {sigma} (all {all:?}, 0/10 {low:?}, 10/20 {high:?})"
            );
        }
        let mean_sq = 0.5 * (low[c] * low[c] + high[c] * high[c]);
        assert!(
            (all[c] * all[c] - mean_sq).abs() <= 1e-9 * mean_sq,
            "{name}: three isotherms {:e}² vs the pairs' mean square {mean_sq:e}",
            all[c]
        );
    }
}
