//! Realistic synthetic rubbers with a known answer, and DMA exports made from them the way an
//! instrument would write them: the input of the end-to-end test against a known truth (issue 8).
//!
//! Input: shape parameters ([`RubberShape`]), a WLF law and a test protocol ([`DmaProtocol`]);
//! output: a [`RealisticCompound`] (true relaxation spectrum + true shift law) and the text of a
//! plain CSV export (units in a row under the names, one row per measured point, the measured
//! temperature of each point, a segment number per isotherm), which `crate::dma` reads.
//!
//! Math: E′, E″ of a Prony series (thesis eq. 2.9 in the frequency domain, [`super::storage_modulus`])
//! at ω = 2π f a_T(T) with a_T from WLF (docs/MATH.md §6) evaluated at each point's *measured* temperature.
//! Noise is multiplicative Gaussian (E′ × (1 + 0.01 g), E″ × (1 + 0.03 g) by default, g seeded
//! standard normals): a good DMA repeats E′ to about 1 % and the phase angle to a few tenths of a
//! degree, which is a few per cent of E″ where tan δ is small.

use super::{loss_modulus, storage_modulus, SplitMix64};
use crate::prony::{RelaxationSpectrum, RelaxationTerm};
use crate::{ModulusKind, ShiftLaw};
use std::fmt::Write as _;

/// The shape of a realistic relaxation spectrum: strengths Eᵢ on a skewed bell in log10 τ (the glass
/// transition: steep towards the glass, a long tail towards the rubbery plateau) plus a weak, slow
/// second bell (filler network / chain-end relaxation), scaled so that E₀/E∞ = `glassy_over_rubbery`.
#[derive(Debug, Clone, PartialEq)]
pub struct RubberShape {
    /// Number of Prony terms (log-spaced).
    pub n_terms: usize,
    /// log10 of the shortest relaxation time in s.
    pub log10_tau_min_s: f64,
    /// Decades from the shortest to the longest relaxation time.
    pub decades: f64,
    /// Rubbery (equilibrium) modulus E∞ in Pa.
    pub modulus_inf_pa: f64,
    /// E₀/E∞ = (E∞ + ΣEᵢ)/E∞.
    pub glassy_over_rubbery: f64,
    /// log10 τ (s) of the main bell's peak.
    pub log10_tau_peak_s: f64,
    /// Width (decades, one standard deviation) of the main bell towards short times.
    pub width_short_decades: f64,
    /// Width (decades) of the main bell towards long times.
    pub width_long_decades: f64,
    /// Share of ΣEᵢ in the slow second bell.
    pub slow_fraction: f64,
    /// log10 τ (s) of the slow bell.
    pub log10_tau_slow_s: f64,
    /// Width (decades) of the slow bell.
    pub width_slow_decades: f64,
}

impl RubberShape {
    /// The tensile relaxation spectrum (ν = 0.5) of this shape.
    pub fn spectrum(&self) -> RelaxationSpectrum {
        let n = self.n_terms.max(2);
        let logs: Vec<f64> = (0..n)
            .map(|i| self.log10_tau_min_s + self.decades * i as f64 / (n - 1) as f64)
            .collect();
        let bell = |x: f64, c: f64, w: f64| (-0.5 * ((x - c) / w).powi(2)).exp();
        let main: Vec<f64> = logs
            .iter()
            .map(|&x| {
                let w = if x < self.log10_tau_peak_s {
                    self.width_short_decades
                } else {
                    self.width_long_decades
                };
                bell(x, self.log10_tau_peak_s, w)
            })
            .collect();
        let slow: Vec<f64> = logs
            .iter()
            .map(|&x| bell(x, self.log10_tau_slow_s, self.width_slow_decades))
            .collect();
        let (sm, ss): (f64, f64) = (main.iter().sum(), slow.iter().sum());
        let total = self.modulus_inf_pa * (self.glassy_over_rubbery - 1.0);
        RelaxationSpectrum {
            kind: ModulusKind::Tensile,
            poisson: 0.5,
            modulus_inf_pa: self.modulus_inf_pa,
            terms: logs
                .iter()
                .zip(main.iter().zip(&slow))
                .map(|(&x, (&m, &s))| RelaxationTerm {
                    modulus_pa: total
                        * ((1.0 - self.slow_fraction) * m / sm + self.slow_fraction * s / ss),
                    tau_s: 10f64.powf(x),
                })
                .collect(),
        }
    }
}

/// A synthetic compound with its true material functions.
#[derive(Debug, Clone, PartialEq)]
pub struct RealisticCompound {
    /// Name (used as the export's file stem).
    pub name: String,
    /// What it stands for.
    pub description: String,
    /// The true relaxation spectrum at the law's reference temperature.
    pub spectrum: RelaxationSpectrum,
    /// The true horizontal shift law (WLF).
    pub law: ShiftLaw,
}

/// Four rubbers spanning the usual range: glass transitions (tan δ peak at 1 Hz) from about −52 °C
/// to about +4 °C, E₀/E∞ from 150 to 900, 27–34 terms over 20 decades, WLF constants in the
/// usual range (C1 8–17, C2 50–150 K; one has the "universal" 8.86 / 101.6 K). Each spectrum
/// reaches beyond the reduced-frequency window that −60 … +100 °C at 0.1–100 Hz covers, as a real
/// rubber's relaxation does: no isotherm lies entirely past the spectrum's fastest term, where E′
/// would be flat and E″ would fall as 1/ω (a Prony artefact, not rubber behaviour).
pub fn realistic_compounds() -> Vec<RealisticCompound> {
    vec![
        RealisticCompound {
            name: "nr-br-idler".into(),
            description: "NR/BR blend, lightly filled (idler cover): tan δ peak at 1 Hz ≈ −52 °C, \
                          E₀/E∞ = 900"
                .into(),
            spectrum: RubberShape {
                n_terms: 31,
                log10_tau_min_s: -13.0,
                decades: 20.0,
                modulus_inf_pa: 2.2e6,
                glassy_over_rubbery: 900.0,
                log10_tau_peak_s: -9.0,
                width_short_decades: 1.3,
                width_long_decades: 2.2,
                slow_fraction: 0.004,
                log10_tau_slow_s: -2.0,
                width_slow_decades: 2.0,
            }
            .spectrum(),
            law: ShiftLaw::Wlf {
                t_ref_c: -20.0,
                c1: 9.2,
                c2_k: 120.0,
            },
        },
        RealisticCompound {
            name: "nr-tread".into(),
            description: "NR, carbon-black filled: tan δ peak at 1 Hz ≈ −37 °C, E₀/E∞ = 400, the \
                          'universal' WLF constants"
                .into(),
            spectrum: RubberShape {
                n_terms: 27,
                log10_tau_min_s: -13.5,
                decades: 20.0,
                modulus_inf_pa: 5.0e6,
                glassy_over_rubbery: 400.0,
                log10_tau_peak_s: -9.3,
                width_short_decades: 1.8,
                width_long_decades: 2.4,
                slow_fraction: 0.01,
                log10_tau_slow_s: -2.0,
                width_slow_decades: 2.0,
            }
            .spectrum(),
            law: ShiftLaw::Wlf {
                t_ref_c: -5.0,
                c1: 8.86,
                c2_k: 101.6,
            },
        },
        RealisticCompound {
            name: "sbr-tread".into(),
            description: "S-SBR, silica filled: tan δ peak at 1 Hz ≈ −30 °C, E₀/E∞ = 150".into(),
            spectrum: RubberShape {
                n_terms: 34,
                log10_tau_min_s: -15.0,
                decades: 20.0,
                modulus_inf_pa: 1.2e7,
                glassy_over_rubbery: 150.0,
                log10_tau_peak_s: -10.0,
                width_short_decades: 2.0,
                width_long_decades: 3.0,
                slow_fraction: 0.03,
                log10_tau_slow_s: -2.0,
                width_slow_decades: 2.5,
            }
            .spectrum(),
            law: ShiftLaw::Wlf {
                t_ref_c: 20.0,
                c1: 9.0,
                c2_k: 150.0,
            },
        },
        RealisticCompound {
            name: "high-tg-tread".into(),
            description: "high-T_g tread (wet grip): tan δ peak at 1 Hz ≈ +4 °C, E₀/E∞ = 600; \
                          glassy at −40 °C in both scenes"
                .into(),
            spectrum: RubberShape {
                n_terms: 30,
                log10_tau_min_s: -13.0,
                decades: 20.0,
                modulus_inf_pa: 8.0e6,
                glassy_over_rubbery: 600.0,
                log10_tau_peak_s: -6.5,
                width_short_decades: 2.5,
                width_long_decades: 2.5,
                slow_fraction: 0.02,
                log10_tau_slow_s: 0.0,
                width_slow_decades: 2.5,
            }
            .spectrum(),
            law: ShiftLaw::Wlf {
                t_ref_c: 20.0,
                c1: 9.0,
                c2_k: 150.0,
            },
        },
    ]
}

/// Rubbers whose isotherms do not all overlap (issue 32): a narrow glass transition with a steep
/// WLF law (the "universal" C₁ = 17.4, C₂ = 51.6 K at T_g), so that with 5 K steps neighbouring
/// isotherms near and below T_g lie 2–6 decades apart in reduced frequency and do not overlap
/// within 0.1–100 Hz, and below T_g E′ is flat (glassy). The spectrum reaches 6 decades past the
/// coldest isotherm's window, so E″ there is a rubber's, not a Prony artefact.
/// - `narrow-tg`: T_g = −40 °C, a narrow bell (0.7 / 1.2 decades);
/// - `narrow-tg-filled`: T_g = −20 °C, the bell 0.9 / 1.6 decades, a 3 % slow filler tail.
pub fn non_overlapping_compounds() -> Vec<RealisticCompound> {
    let make =
        |name: &str, tg: f64, short: f64, long: f64, slow: f64, what: &str| RealisticCompound {
            name: name.into(),
            description: what.into(),
            spectrum: RubberShape {
                n_terms: 46,
                log10_tau_min_s: -24.0,
                decades: 30.0,
                modulus_inf_pa: 1.5e6,
                glassy_over_rubbery: 1000.0,
                log10_tau_peak_s: -1.0,
                width_short_decades: short,
                width_long_decades: long,
                slow_fraction: slow,
                log10_tau_slow_s: 3.0,
                width_slow_decades: 1.5,
            }
            .spectrum(),
            law: ShiftLaw::Wlf {
                t_ref_c: tg,
                c1: 17.4,
                c2_k: 51.6,
            },
        };
    vec![
        make(
            "narrow-tg",
            -40.0,
            0.7,
            1.2,
            0.004,
            "narrow glass transition at −40 °C, steep WLF (17.4, 51.6 K at T_g)",
        ),
        make(
            "narrow-tg-filled",
            -20.0,
            0.9,
            1.6,
            0.03,
            "narrow glass transition at −20 °C with a filler tail, steep WLF",
        ),
    ]
}

/// The τ range (log10 s) a spectrum must span for `law` so that every isotherm of −60 … +100 °C
/// at 0.1–100 Hz lies within it, one decade to spare at each end: (fastest, slowest).
#[cfg(test)]
fn tau_range_for(law: &ShiftLaw) -> (f64, f64) {
    let two_pi = 2.0 * std::f64::consts::PI;
    let fast = -(two_pi * 100.0).log10() - law.log10_a_t(-60.0);
    let slow = -(two_pi * 0.1).log10() - law.log10_a_t(100.0);
    (fast - 1.0, slow + 1.0)
}

/// A compound of the held-out set: `shape` with its τ grid laid over [`tau_range_for`] at 1.5
/// terms per decade, its main bell's peak where the loss peaks at 1 Hz at `tg_c` under `law`
/// (log10 τ_peak = −log10 2π − log10 a_T(T_g)) and its slow bell `slow_after_decades` slower (the
/// shape's own `n_terms`, `log10_tau_min_s`, `decades` and bell positions are replaced).
#[cfg(test)]
fn held_out(
    name: &str,
    description: &str,
    tg_c: f64,
    slow_after_decades: f64,
    shape: RubberShape,
    law: ShiftLaw,
) -> RealisticCompound {
    let (lo, hi) = tau_range_for(&law);
    let peak = -(2.0 * std::f64::consts::PI).log10() - law.log10_a_t(tg_c);
    let shape = RubberShape {
        n_terms: ((hi - lo) * 1.5).ceil() as usize + 1,
        log10_tau_min_s: lo,
        decades: hi - lo,
        log10_tau_peak_s: peak,
        log10_tau_slow_s: peak + slow_after_decades,
        ..shape
    };
    RealisticCompound {
        name: name.into(),
        description: description.into(),
        spectrum: shape.spectrum(),
        law,
    }
}

#[cfg(test)]
fn wlf(t_ref_c: f64, c1: f64, c2_k: f64) -> ShiftLaw {
    ShiftLaw::Wlf { t_ref_c, c1, c2_k }
}

/// Eight known-truth compounds kept apart from [`realistic_compounds`] (which the bands and the
/// fit were tuned on): the calibration set of the uncertainty bands (issue 32; docs/MATH.md §15).
/// Narrow and broad transitions, a long rubbery plateau, a high T_g, two transitions (a blend), a
/// filled rubber's low-frequency tail, a steep glass side and a T_g at the coldest isotherm, with
/// WLF constants over the usual range (C1 8–14, C2 75–150 K) and neighbouring isotherms 5 K apart
/// at most 2 decades apart at −60 °C (so a 3-decade sweep overlaps its neighbour). The τ grid of
/// each covers the window of −60 … +100 °C at 0.1–100 Hz under its own law, a decade to spare at
/// each end (no isotherm past the spectrum).
#[cfg(test)]
pub fn held_out_compounds() -> Vec<RealisticCompound> {
    let base = RubberShape {
        n_terms: 0,
        log10_tau_min_s: 0.0,
        decades: 0.0,
        modulus_inf_pa: 4.0e6,
        glassy_over_rubbery: 500.0,
        log10_tau_peak_s: 0.0,
        width_short_decades: 1.5,
        width_long_decades: 2.2,
        slow_fraction: 0.01,
        log10_tau_slow_s: 0.0,
        width_slow_decades: 2.0,
    };
    vec![
        held_out(
            "narrow-transition",
            "unfilled, narrow glass transition (bell 0.9/1.2 decades), T_g ≈ −45 °C",
            -45.0,
            7.0,
            RubberShape {
                width_short_decades: 0.9,
                width_long_decades: 1.2,
                slow_fraction: 0.002,
                glassy_over_rubbery: 1200.0,
                modulus_inf_pa: 1.5e6,
                ..base.clone()
            },
            wlf(-10.0, 10.0, 130.0),
        ),
        held_out(
            "broad-transition",
            "broad transition (bell 3.5/4.5 decades), as a heterogeneous blend, T_g ≈ −30 °C",
            -30.0,
            7.0,
            RubberShape {
                width_short_decades: 3.5,
                width_long_decades: 4.5,
                glassy_over_rubbery: 200.0,
                modulus_inf_pa: 1.0e7,
                ..base.clone()
            },
            wlf(10.0, 8.5, 140.0),
        ),
        held_out(
            "long-plateau",
            "lightly crosslinked, long rubbery plateau (no slow relaxation, E₀/E∞ = 2000), \
             T_g ≈ −55 °C",
            -55.0,
            7.0,
            RubberShape {
                width_short_decades: 1.2,
                width_long_decades: 1.6,
                slow_fraction: 0.0,
                glassy_over_rubbery: 2000.0,
                modulus_inf_pa: 1.0e6,
                ..base.clone()
            },
            wlf(-30.0, 14.0, 100.0),
        ),
        held_out(
            "high-tg",
            "high T_g (loss peak at 1 Hz near +20 °C)",
            20.0,
            6.0,
            RubberShape {
                width_short_decades: 2.0,
                width_long_decades: 2.8,
                slow_fraction: 0.02,
                ..base.clone()
            },
            wlf(30.0, 8.0, 150.0),
        ),
        held_out(
            "two-transitions",
            "immiscible blend: T_g ≈ −50 °C and a second transition 5 decades slower holding 30 %",
            -50.0,
            5.0,
            RubberShape {
                width_short_decades: 1.2,
                width_long_decades: 1.5,
                slow_fraction: 0.3,
                width_slow_decades: 1.0,
                ..base.clone()
            },
            wlf(0.0, 9.0, 130.0),
        ),
        held_out(
            "filled-tail",
            "highly filled: a broad low-frequency tail (filler network) holding 12 %, T_g ≈ −35 °C",
            -35.0,
            9.0,
            RubberShape {
                slow_fraction: 0.12,
                width_slow_decades: 3.0,
                glassy_over_rubbery: 120.0,
                modulus_inf_pa: 1.5e7,
                ..base.clone()
            },
            wlf(-10.0, 10.0, 120.0),
        ),
        held_out(
            "steep-glass-side",
            "skewed bell: steep towards the glass (0.6 decade), a long tail (3.5) towards the \
             rubber, T_g ≈ −40 °C",
            -40.0,
            7.0,
            RubberShape {
                width_short_decades: 0.6,
                width_long_decades: 3.5,
                ..base.clone()
            },
            wlf(-20.0, 14.0, 130.0),
        ),
        held_out(
            "tg-at-cold-end",
            "T_g at the coldest isotherm (≈ −58 °C, BR-like): most isotherms on the rubbery side",
            -58.0,
            7.0,
            RubberShape {
                width_short_decades: 1.4,
                width_long_decades: 2.0,
                glassy_over_rubbery: 700.0,
                modulus_inf_pa: 2.0e6,
                ..base
            },
            wlf(-40.0, 13.0, 75.0),
        ),
    ]
}

/// How the synthetic DMA run is made (isotherms, sweep, noise, temperature control).
#[derive(Debug, Clone, PartialEq)]
pub struct DmaProtocol {
    /// Nominal (set) temperatures in °C, in the order measured.
    pub temps_c: Vec<f64>,
    /// Frequencies of each sweep in Hz, in the order measured.
    pub freqs_hz: Vec<f64>,
    /// Relative standard deviation of the multiplicative noise on E′ (0.01 = 1 %).
    pub noise_storage_rel: f64,
    /// Relative standard deviation of the multiplicative noise on E″.
    pub noise_loss_rel: f64,
    /// Bound on |measured − nominal| temperature in K.
    pub drift_bound_k: f64,
    /// Seed of the noise and the temperature drift.
    pub seed: u64,
}

impl Default for DmaProtocol {
    /// −60 … +100 °C every 5 K (33 isotherms), 0.1–100 Hz at 4 per decade (13 frequencies, as a
    /// sweep of 0.1, 0.178, 0.316, 0.562, 1 … Hz), 1 % noise on E′, 3 % on E″, ±1.5 K drift.
    fn default() -> Self {
        DmaProtocol {
            temps_c: (0..=32).map(|i| -60.0 + 5.0 * i as f64).collect(),
            freqs_hz: super::log_spaced(0.1, 100.0, 13),
            noise_storage_rel: 0.01,
            noise_loss_rel: 0.03,
            drift_bound_k: 1.5,
            seed: 2026,
        }
    }
}

/// One measured point of a synthetic run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DmaRow {
    /// Segment (isotherm) number, from 0.
    pub segment: usize,
    /// Frequency in Hz.
    pub freq_hz: f64,
    /// Measured temperature in °C (the true moduli are those at this temperature).
    pub temp_c: f64,
    /// Measured E′ in Pa (true value × noise).
    pub storage_pa: f64,
    /// Measured E″ in Pa.
    pub loss_pa: f64,
}

/// The measured points of `compound` under `protocol`. Temperature of point k of a sweep of n:
/// nominal + o + s·(k/(n−1) − ½) + 0.05 g, with o uniform in ±(2/3)·bound (the controller's offset
/// of that step), s uniform in ±(2/3)·bound (the drift over the sweep) and g a standard normal
/// (sensor jitter), clamped to ±bound.
pub fn dma_rows(compound: &RealisticCompound, protocol: &DmaProtocol) -> Vec<DmaRow> {
    let mut rng = SplitMix64::new(protocol.seed);
    let b = protocol.drift_bound_k;
    let n = protocol.freqs_hz.len();
    let mut rows = Vec::with_capacity(protocol.temps_c.len() * n);
    for (segment, &nominal) in protocol.temps_c.iter().enumerate() {
        let offset = (2.0 * rng.uniform() - 1.0) * b * 2.0 / 3.0;
        let drift = (2.0 * rng.uniform() - 1.0) * b * 2.0 / 3.0;
        for (k, &f) in protocol.freqs_hz.iter().enumerate() {
            let frac = if n > 1 {
                k as f64 / (n - 1) as f64 - 0.5
            } else {
                0.0
            };
            let dev = (offset + drift * frac + 0.05 * rng.normal()).clamp(-b, b);
            let temp_c = nominal + dev;
            let w = 2.0 * std::f64::consts::PI * f * 10f64.powf(compound.law.log10_a_t(temp_c));
            let storage_pa = storage_modulus(&compound.spectrum, w)
                * (1.0 + protocol.noise_storage_rel * rng.normal());
            let loss_pa = loss_modulus(&compound.spectrum, w)
                * (1.0 + protocol.noise_loss_rel * rng.normal());
            rows.push(DmaRow {
                segment,
                freq_hz: f,
                temp_c,
                storage_pa,
                loss_pa,
            });
        }
    }
    rows
}

/// The rows as a plain CSV export: a name row, a unit row (`Hz, MPa, MPa, °C, -`), one row per point
/// (moduli in MPa to 7 significant digits, temperatures to 0.01 K, as instruments print them).
pub fn dma_csv(rows: &[DmaRow]) -> String {
    let mut s = String::from("Frequency,E',E'',Temperature,Segment\nHz,MPa,MPa,°C,-\n");
    for r in rows {
        let _ = writeln!(
            s,
            "{:.6e},{:.6e},{:.6e},{:.2},{}",
            r.freq_hz,
            r.storage_pa * 1e-6,
            r.loss_pa * 1e-6,
            r.temp_c,
            r.segment
        );
    }
    s
}

/// The export formats the synthetic runs can be written in (each read by crate::dma's own reader).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExportFormat {
    /// [`dma_csv`]: plain CSV, Hz and MPa, a segment column.
    PlainCsv,
    /// `dma_trios_text`: TA TRIOS plain text of a shear run (G = E/3), rad/s and Pa, one
    /// `[step]` per isotherm.
    TriosText,
    /// `dma_proteus`: Netzsch Proteus ASCII, decimal comma, `;`-separated, MPa, cp1252.
    Proteus,
}

impl ExportFormat {
    /// Every format.
    pub const ALL: [ExportFormat; 3] = [
        ExportFormat::PlainCsv,
        ExportFormat::TriosText,
        ExportFormat::Proteus,
    ];

    /// A file name extension for it.
    pub fn extension(self) -> &'static str {
        match self {
            ExportFormat::PlainCsv => "csv",
            ExportFormat::TriosText | ExportFormat::Proteus => "txt",
        }
    }

    /// The rows written in this format (bytes as the instrument's software writes them).
    pub fn write(self, rows: &[DmaRow]) -> Vec<u8> {
        match self {
            ExportFormat::PlainCsv => dma_csv(rows).into_bytes(),
            ExportFormat::TriosText => dma_trios_text(rows).into_bytes(),
            ExportFormat::Proteus => dma_proteus(rows),
        }
    }
}

/// The rows as TA TRIOS plain text of a shear run: G′ = E′/3, G″ = E″/3 (ν = 0.5), angular
/// frequency, one `[step]` per segment named by its nominal temperature (the mean of its points,
/// rounded to 0.5 K, as the instrument names it), 10 significant digits.
pub fn dma_trios_text(rows: &[DmaRow]) -> String {
    let mut s = String::from(
        "Filename\tsynthetic.tri\nInstrument type\tAresG2\nTrios version\t5.1.1.46572\n",
    );
    let segments = rows.iter().map(|r| r.segment).max().map_or(0, |m| m + 1);
    for seg in 0..segments {
        let pts: Vec<&DmaRow> = rows.iter().filter(|r| r.segment == seg).collect();
        if pts.is_empty() {
            continue;
        }
        let mean = pts.iter().map(|r| r.temp_c).sum::<f64>() / pts.len() as f64;
        let _ = write!(
            s,
            "\n[step]\nFrequency sweep ({:.1} °C)\nAngular frequency\tStorage modulus\tLoss modulus\tTemperature\tOscillation torque\nrad/s\tPa\tPa\t°C\tµN.m\n",
            (mean * 2.0).round() / 2.0
        );
        for r in pts {
            let _ = writeln!(
                s,
                "{:.9e}\t{:.9e}\t{:.9e}\t{:.4}\t100",
                2.0 * std::f64::consts::PI * r.freq_hz,
                r.storage_pa / 3.0,
                r.loss_pa / 3.0,
                r.temp_c
            );
        }
    }
    s
}

/// `v` in fixed notation to 8 significant digits (Proteus writes no exponents).
fn fixed8(v: f64) -> String {
    let digits = 7 - v.abs().log10().floor() as i32;
    format!("{:.*}", digits.clamp(0, 20) as usize, v)
}

/// The rows as a Netzsch Proteus ASCII export of a tensile run (`#` header lines, `##` column
/// line, decimal comma, `;`, CRLF, cp1252): temperature, time, Hz, MPa, tan δ.
pub fn dma_proteus(rows: &[DmaRow]) -> Vec<u8> {
    let mut s = String::from(
        "#EXPORTTYPE:DATA ALL\r\n#FILE:synthetic.dm2\r\n#FORMAT:NETZSCH5\r\n#FTYPE:ANSI\r\n\
         #INSTRUMENT:NETZSCH DMA 242E Artemis\r\n#MODE:Tension\r\n#DECIMAL:COMMA\r\n\
         #SEPARATOR:SEMICOLON\r\n##Temp./°C;Time/min;Freq./Hz;E'/MPa;E''/MPa;tan d\r\n",
    );
    for (i, r) in rows.iter().enumerate() {
        let line = format!(
            "{:.4};{:.1};{};{};{};{}",
            r.temp_c,
            0.5 * i as f64,
            fixed8(r.freq_hz),
            fixed8(r.storage_pa * 1e-6),
            fixed8(r.loss_pa * 1e-6),
            fixed8(r.loss_pa / r.storage_pa)
        );
        s.push_str(&line.replace('.', ","));
        s.push_str("\r\n");
    }
    // cp1252: every character here is ASCII except '°' (U+00B0, byte 0xB0 in cp1252).
    s.chars()
        .map(|c| if c == '°' { 0xB0 } else { c as u8 })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compounds_meet_the_stated_ranges() {
        for c in realistic_compounds() {
            let s = &c.spectrum;
            assert!((25..=35).contains(&s.terms.len()), "{}", c.name);
            let span = (s.terms.last().unwrap().tau_s / s.terms[0].tau_s).log10();
            assert!((span - 20.0).abs() < 1e-9, "{}", c.name);
            let e0 = s.modulus_inf_pa + s.terms.iter().map(|t| t.modulus_pa).sum::<f64>();
            let ratio = e0 / s.modulus_inf_pa;
            assert!((100.0..=1000.0).contains(&ratio), "{}: {ratio}", c.name);
            let ShiftLaw::Wlf { c1, c2_k, .. } = c.law else {
                panic!("WLF expected")
            };
            assert!((8.0..=17.0).contains(&c1) && (50.0..=150.0).contains(&c2_k));
        }
    }

    #[test]
    fn rows_follow_the_protocol() {
        let c = &realistic_compounds()[0];
        let p = DmaProtocol::default();
        let rows = dma_rows(c, &p);
        assert_eq!(rows.len(), 33 * 13);
        for r in &rows {
            let nominal = p.temps_c[r.segment];
            assert!((r.temp_c - nominal).abs() <= 1.5);
            // Noise-free value at the row's measured temperature: within 5 sd of the noise.
            let w = 2.0 * std::f64::consts::PI * r.freq_hz * 10f64.powf(c.law.log10_a_t(r.temp_c));
            let e1 = storage_modulus(&c.spectrum, w);
            assert!((r.storage_pa / e1 - 1.0).abs() < 0.05);
        }
        let text = dma_csv(&rows);
        assert_eq!(text.lines().count(), 2 + rows.len());
    }
}
