//! `viscoroll export`: FEA material cards (Abaqus, ANSYS, LS-DYNA) from a relaxation spectrum JSON
//! ([`crate::RelaxationSpectrum`]) or a fit file, with a WLF shift (`--wlf`, or from a fit file the
//! WLF fit of its master curve's shifts when that law holds). Formats and the documentation they
//! were checked against: [`crate::report::cards`].
//!
//! LS-DYNA takes at most 18 Prony cards: a longer spectrum is refitted with at most 18 cards (the
//! β = 0 equilibrium card included) to the fit file's master curve, or to the spectrum's own E′, E″
//! (10 points per decade over its relaxation times) when a bare spectrum was given; the refit's RMS
//! log10 errors are stated in the card and on stderr. A WLF law from a fit file is written when it
//! describes the shifts ([`crate::report::card_shift`]: RMS ≤ 0.1 decade, 0 < C2 ≤ 1000 K); when it
//! holds over part of the temperatures only, the WLF fitted over that range is written with the
//! range and its RMS in a warning in the card. A fit whose master curve used Arrhenius, or whose WLF
//! is withheld while an Arrhenius fit of its shifts holds, gets an Arrhenius shift where the target
//! has one (Abaqus `*TRS, DEFINITION=ARRHENIUS`, ANSYS `TB,SHIFT … TN`; LS-DYNA none, said why);
//! otherwise the card gets no shift and says why.
//!
//! `--to pyvisco` writes a fit file's master curve and shift factors in pyvisco's CSV layouts
//! ([`crate::dma::pyvisco`]): `-o NAME.csv` and `NAME__shift_factors.csv` beside it, the shift
//! factors at pyvisco's set temperatures (whole degrees, the value pyvisco's raw-data path looks
//! them up by; [`pyvisco_set_shifts`]), and the Prony terms in pyvisco's layout
//! (`NAME__prony_terms.csv`, crate::prony::pyvisco_csv). From a bare spectrum (JSON, or pyvisco's
//! Prony-term CSV, which every command that reads a relaxation spectrum accepts) it writes the
//! Prony-term CSV alone to `-o`.
//!
//! `--json` prints one object `{ "format", "input", "output", "card" }`. Without `--json` and without
//! `-o` the card text goes to stdout.

use super::output::write_atomic;
use super::spectrum_input::read_spectrum_input;
use crate::report::card_refit::{refit_for_cards, CardRefit};
use crate::report::card_shift::{card_shift, CardShift};
use crate::report::cards::{self, BulkRelaxation, CardOptions};
use crate::{RelaxationSpectrum, ShiftLaw};
use anyhow::Context;
use std::path::PathBuf;

/// Target program.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Target {
    /// Abaqus `*VISCOELASTIC, TIME=PRONY` (+ `*TRS, DEFINITION=WLF`).
    Abaqus,
    /// ANSYS APDL `TB,PRONY … SHEAR` (+ `TB,SHIFT … WLF`).
    Ansys,
    /// LS-DYNA `*MAT_GENERAL_VISCOELASTIC`.
    Lsdyna,
    /// pyvisco's master-curve CSV (`-o NAME.csv`), shift-factor CSV (`NAME__shift_factors.csv`) and
    /// Prony-term CSV (`NAME__prony_terms.csv`) of a fit file, the layouts pyvisco's
    /// `load.user_master` and `load.user_shift` read and its Prony fit writes; of a bare spectrum,
    /// the Prony-term CSV alone.
    Pyvisco,
}

/// Bulk relaxation (Abaqus kᵢ).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Bulk {
    /// kᵢ = 0: elastic bulk response.
    Elastic,
    /// kᵢ = gᵢ: constant Poisson's ratio.
    SameAsShear,
}

/// Arguments of `viscoroll export`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Relaxation spectrum JSON file or fit file (`fits/NAME.json`).
    pub file: PathBuf,
    /// Target program.
    #[arg(long, value_enum)]
    pub to: Target,
    /// WLF shift law "TREF_C,C1,C2" (reference temperature in °C, C1, C2 in K) for *TRS / TB,SHIFT /
    /// TREF,A,B; omitted: from a fit file its WLF law if it describes the shifts, else its Arrhenius
    /// law (Abaqus, ANSYS), else no shift card.
    #[arg(long, value_name = "TREF_C,C1,C2")]
    pub wlf: Option<String>,
    /// Material id (ANSYS MAT, LS-DYNA MID).
    #[arg(long, default_value_t = 1)]
    pub material_id: u32,
    /// Mass density in kg/m³ for LS-DYNA's RO (default: left blank).
    #[arg(long)]
    pub density_kg_m3: Option<f64>,
    /// Bulk relaxation for Abaqus kᵢ.
    #[arg(long, value_enum, default_value = "elastic")]
    pub bulk: Bulk,
    /// Write the card to this file (atomically).
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
    /// Overwrite OUT if it exists.
    #[arg(long)]
    pub force: bool,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
}

/// The shift law of a fit file for a card ([`card_shift`] on its table of shifts and its law).
fn shift_from_fit(fit: &crate::pipeline::CompoundFit) -> CardShift {
    let shifts = fit.tts.as_ref().map(|t| t.shifts.as_slice()).unwrap_or(&[]);
    card_shift(shifts, &fit.shift_law)
}

fn parse_wlf(s: &str) -> anyhow::Result<ShiftLaw> {
    let v: Vec<f64> = s
        .split(',')
        .map(|t| t.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .with_context(|| format!("--wlf {s}: expected three numbers TREF_C,C1,C2"))?;
    if v.len() != 3 || v.iter().any(|x| !x.is_finite()) {
        anyhow::bail!("--wlf {s}: expected three finite numbers TREF_C,C1,C2");
    }
    if v[2] <= 0.0 {
        anyhow::bail!("--wlf {s}: C2 = {} K must be > 0", v[2]);
    }
    Ok(ShiftLaw::Wlf {
        t_ref_c: v[0],
        c1: v[1],
        c2_k: v[2],
    })
}

/// The shift-factor file written beside pyvisco's master-curve file `NAME.csv`:
/// `NAME__shift_factors.csv` (the name pyvisco's example pair uses).
pub fn pyvisco_shift_path(master: &std::path::Path) -> PathBuf {
    let stem = master
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "master".into());
    master.with_file_name(format!("{stem}__shift_factors.csv"))
}

/// The Prony-term file written beside pyvisco's master-curve file `NAME.csv`:
/// `NAME__prony_terms.csv`.
pub fn pyvisco_terms_path(master: &std::path::Path) -> PathBuf {
    let stem = master
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "master".into());
    master.with_file_name(format!("{stem}__prony_terms.csv"))
}

/// The shifts at pyvisco's set temperatures: each isotherm's temperature rounded to a whole degree,
/// ties to even, as pyvisco's raw-data loaders (`load.Eplexor_raw`, `load.user_raw`) round each
/// set's mean temperature and then look its shift factor up by that value (a mean of 99.985 °C is
/// the 100 °C set; a set measured at −42.45 °C is pyvisco's −42 °C set). When two isotherms round to
/// one degree, the shifts as they are, with a note why.
pub fn pyvisco_set_shifts(shifts: &[(f64, f64)]) -> (Vec<(f64, f64)>, Option<String>) {
    let mut out: Vec<(f64, f64)> = Vec::new();
    for &(t, a) in shifts {
        let r = t.round_ties_even();
        if out.iter().any(|&(m, _)| m == r) {
            return (
                shifts.to_vec(),
                Some(format!(
                    "shift factors written at the measured temperatures: two isotherms round to \
                     {r} °C, pyvisco's set temperature (it would match both to one row)"
                )),
            );
        }
        out.push((r, a));
    }
    (out, None)
}

/// `export --to pyvisco` of a bare spectrum: its Prony terms in pyvisco's layout at `-o`.
fn export_pyvisco_terms(args: &Args, spectrum: &RelaxationSpectrum) -> anyhow::Result<()> {
    let out = args
        .output
        .as_ref()
        .ok_or_else(|| anyhow::anyhow!("--to pyvisco writes a file: give it with -o NAME.csv"))?;
    write_atomic(
        out,
        crate::prony::pyvisco_csv::pyvisco_terms_csv(spectrum).as_bytes(),
        args.force,
    )?;
    if args.json {
        let obj = serde_json::json!({
            "format": "pyvisco",
            "input": args.file.display().to_string(),
            "output": out.display().to_string(),
            "terms": spectrum.terms.len(),
        });
        outln!("{}", super::output::versioned(obj));
    } else {
        errln!(
            "viscoroll export: pyvisco Prony terms ({} terms) → {}",
            spectrum.terms.len(),
            out.display()
        );
    }
    Ok(())
}

/// The master curve in pyvisco's layout: frequency domain (`f, E_stor, E_loss`), or for a fit made
/// in time (docs/MATH.md §18) its time-domain master curve (`t, E_relax`): the fitted E(t) at the
/// data's reduced times t = 1/(2π f) of the fit file's points (the fit file keeps the fitted
/// spectrum's values there, not the measured ones), so pyvisco fits it in the domain it was
/// measured in.
fn pyvisco_master_text(fit: &crate::pipeline::CompoundFit, points: &[(f64, f64, f64)]) -> String {
    if fit.prony_info.time_domain.is_none() {
        return crate::dma::pyvisco::master_csv(fit.relaxation.kind, points);
    }
    let mut times: Vec<(f64, f64)> = points
        .iter()
        .map(|&(f, _, _)| {
            let t = 1.0 / (2.0 * std::f64::consts::PI * f);
            (t, fit.relaxation.relaxation_modulus(t))
        })
        .collect();
    times.sort_by(|a, b| a.0.total_cmp(&b.0));
    crate::dma::pyvisco_time::time_master_csv(fit.relaxation.kind, &times)
}

/// `export --to pyvisco`: the fit file's master curve, shifts and Prony terms in pyvisco's CSV
/// layouts (a bare spectrum: its Prony terms).
fn export_pyvisco(args: &Args, input: &super::spectrum_input::SpectrumInput) -> anyhow::Result<()> {
    let Some(fit) = input.fit.as_ref() else {
        return export_pyvisco_terms(args, &input.spectrum);
    };
    let out = args.output.as_ref().ok_or_else(|| {
        anyhow::anyhow!("--to pyvisco writes three files: give the master curve's with -o NAME.csv")
    })?;
    let shifts: Vec<(f64, f64)> = match (&fit.tts, &fit.shift_law) {
        (Some(t), _) if !t.shifts.is_empty() => t.shifts.clone(),
        (_, ShiftLaw::Table { points, .. }) => points.clone(),
        _ => anyhow::bail!(
            "{}: the fit file holds no table of shift factors",
            args.file.display()
        ),
    };
    let t_ref = fit.shift_law.t_ref_c();
    // pyvisco reads log a_T relative to the master curve's temperature: refer the table to it.
    let at_ref = fit.shift_law.log10_a_t(t_ref);
    let shifts: Vec<(f64, f64)> = shifts.iter().map(|&(t, a)| (t, a - at_ref)).collect();
    let (shifts, note) = pyvisco_set_shifts(&shifts);
    if let Some(n) = &note {
        errln!("viscoroll export: {n}");
    }
    let points: Vec<(f64, f64, f64)> = fit
        .master_curve
        .iter()
        .map(|p| (p.reduced_freq_hz, p.storage_pa, p.loss_pa))
        .collect();
    let master_text = pyvisco_master_text(fit, &points);
    let shift_text = crate::dma::pyvisco::shift_csv(&shifts);
    let shift_out = pyvisco_shift_path(out);
    let terms_out = pyvisco_terms_path(out);
    if !args.force {
        for p in [out, &shift_out, &terms_out] {
            if p.exists() {
                anyhow::bail!(
                    "{} exists; not overwritten (use --force to replace it)",
                    p.display()
                );
            }
        }
    }
    write_atomic(out, master_text.as_bytes(), args.force)?;
    write_atomic(&shift_out, shift_text.as_bytes(), args.force)?;
    write_atomic(
        &terms_out,
        crate::prony::pyvisco_csv::pyvisco_terms_csv(&fit.relaxation).as_bytes(),
        args.force,
    )?;
    if args.json {
        let obj = serde_json::json!({
            "format": "pyvisco",
            "input": args.file.display().to_string(),
            "output": out.display().to_string(),
            "shift_factors": shift_out.display().to_string(),
            "prony_terms": terms_out.display().to_string(),
            "note": note,
            "points": points.len(),
            "temperatures": shifts.len(),
            "t_ref_c": t_ref,
        });
        outln!("{}", super::output::versioned(obj));
    } else {
        errln!(
            "viscoroll export: pyvisco master curve ({}{} points at T_ref = {t_ref} °C) → {}; \
             shift factors ({} temperatures) → {}",
            if fit.prony_info.time_domain.is_some() {
                "time domain, t, E_relax: the fitted E(t) at the data's reduced times; "
            } else {
                ""
            },
            points.len(),
            out.display(),
            shifts.len(),
            shift_out.display()
        );
    }
    Ok(())
}

/// A spectrum with more terms than LS-DYNA's cards hold, refitted ([`refit_for_cards`]) with a note
/// of the refit's errors; a shorter one as it is.
fn fit_lsdyna(
    mut spectrum: RelaxationSpectrum,
    fit: Option<&crate::pipeline::CompoundFit>,
    notes: &mut Vec<String>,
) -> anyhow::Result<RelaxationSpectrum> {
    let cards = spectrum.terms.len() + usize::from(spectrum.modulus_inf_pa > 0.0);
    if cards > cards::LSDYNA_MAX_TERMS {
        let CardRefit {
            spectrum: refit,
            rms_log10: rms,
            against,
        } = refit_for_cards(&spectrum, fit, cards::LSDYNA_MAX_TERMS)
            .context("refitting with fewer terms for LS-DYNA")?;
        notes.push(format!(
            "refitted from {} to {} Prony terms for LS-DYNA (at most {} cards): RMS log10 E' {:.4}, E'' {:.4} against {against}",
            spectrum.terms.len(),
            refit.terms.len(),
            cards::LSDYNA_MAX_TERMS,
            rms[0],
            rms[1]
        ));
        spectrum = refit;
    }
    Ok(spectrum)
}

/// Run `viscoroll export`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let input = read_spectrum_input(&args.file)?;
    if args.to == Target::Pyvisco {
        return export_pyvisco(&args, &input);
    }
    let mut spectrum = input.spectrum;
    let mut notes: Vec<String> = Vec::new();
    let shift = match (args.wlf.as_deref(), &input.fit) {
        (Some(w), _) => Some(parse_wlf(w)?),
        (None, Some(fit)) => {
            let chosen = shift_from_fit(fit);
            notes.extend(chosen.notes);
            chosen.law
        }
        (None, None) => None,
    };
    if args.to == Target::Lsdyna {
        spectrum = fit_lsdyna(spectrum, input.fit.as_ref(), &mut notes)?;
    }
    if let Some(d) = args.density_kg_m3 {
        if !(d.is_finite() && d > 0.0) {
            anyhow::bail!("--density-kg-m3 {d}: must be a positive number");
        }
    }
    let options = CardOptions {
        material_id: args.material_id,
        bulk: match args.bulk {
            Bulk::Elastic => BulkRelaxation::Elastic,
            Bulk::SameAsShear => BulkRelaxation::SameAsShear,
        },
        density_kg_m3: args.density_kg_m3,
    };
    let (name, target) = match args.to {
        Target::Abaqus => ("abaqus", cards::CardTarget::Abaqus),
        Target::Ansys => ("ansys", cards::CardTarget::Ansys),
        Target::Lsdyna => ("lsdyna", cards::CardTarget::Lsdyna),
        // Written by export_pyvisco before any card work.
        Target::Pyvisco => anyhow::bail!("pyvisco files are not a card"),
    };
    let (card, card_notes) = cards::card(target, &spectrum, shift.as_ref(), &options)
        .with_context(|| format!("{}", args.file.display()))?;
    let dropped = card_notes.iter().any(|n| n.contains("no shift in the"));
    notes.extend(card_notes);
    let shift_label = match (&shift, dropped) {
        (Some(ShiftLaw::Wlf { .. }), false) => " + WLF shift",
        (Some(ShiftLaw::Arrhenius { .. }), false) => " + Arrhenius shift",
        _ => "",
    };
    let prefix = match args.to {
        Target::Abaqus => "**",
        Target::Ansys => "!",
        Target::Lsdyna | Target::Pyvisco => "$",
    };
    let card: String = notes
        .iter()
        .map(|n| format!("{prefix} {n}\n"))
        .chain(std::iter::once(card))
        .collect();
    for n in &notes {
        errln!("viscoroll export: {n}");
    }
    if let Some(out) = &args.output {
        write_atomic(out, card.as_bytes(), args.force)?;
    }
    if args.json {
        let obj = serde_json::json!({
            "format": name,
            "input": args.file.display().to_string(),
            "output": args.output.as_ref().map(|p| p.display().to_string()),
            "card": card,
            "notes": notes,
        });
        outln!("{}", super::output::versioned(obj));
    } else {
        if args.output.is_none() {
            out!("{card}");
        }
        errln!(
            "viscoroll export: {name} card, {} terms{}",
            spectrum.terms.len(),
            shift_label
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Means round to pyvisco's set temperatures (ties to even, as numpy's round); two isotherms
    /// on one degree keep the measured temperatures, with a note.
    #[test]
    fn shifts_move_to_pyvisco_set_temperatures() {
        let (s, note) = pyvisco_set_shifts(&[(99.985, -11.7), (-42.451, 8.0), (2.5, 1.0)]);
        assert_eq!(s, [(100.0, -11.7), (-42.0, 8.0), (2.0, 1.0)]);
        assert!(note.is_none());
        let both = [(20.4, 1.0), (19.6, 2.0)];
        let (s, note) = pyvisco_set_shifts(&both);
        assert_eq!(s, both);
        assert!(note.is_some_and(|n| n.contains("20 °C")));
    }
}
