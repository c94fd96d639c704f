//! `viscoroll export`: FEA material cards (Abaqus, ANSYS, LS-DYNA) from a relaxation spectrum JSON
//! ([`crate::RelaxationSpectrum`]; fit files come later), with an optional WLF shift (`--wlf`).
//! Formats and the documentation they were checked against: [`crate::report::cards`].
//!
//! `--json` prints one object `{ "format", "input", "output", "card" }`. Without `--json` and without
//! `-o` the card text goes to stdout.

use super::output::write_atomic;
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
    /// Relaxation spectrum JSON file.
    pub file: PathBuf,
    /// Target program.
    #[arg(long, value_enum)]
    pub to: Target,
    /// WLF shift law "TREF_C,C1,C2" (reference temperature in °C, C1, C2 in K) for *TRS / TB,SHIFT /
    /// TREF,A,B; omitted: no shift card.
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

/// Run `viscoroll export`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let text = std::fs::read_to_string(&args.file)
        .with_context(|| format!("cannot read {}", args.file.display()))?;
    let spectrum: RelaxationSpectrum = serde_json::from_str(&text)
        .with_context(|| format!("{}: not a relaxation spectrum JSON", args.file.display()))?;
    let shift = args.wlf.as_deref().map(parse_wlf).transpose()?;
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
    let (name, card) = match args.to {
        Target::Abaqus => ("abaqus", cards::abaqus(&spectrum, shift.as_ref(), &options)),
        Target::Ansys => ("ansys", cards::ansys(&spectrum, shift.as_ref(), &options)),
        Target::Lsdyna => ("lsdyna", cards::lsdyna(&spectrum, shift.as_ref(), &options)),
    };
    let card = card.with_context(|| format!("{}", args.file.display()))?;
    if let Some(out) = &args.output {
        write_atomic(out, card.as_bytes(), args.force)?;
    }
    if args.json {
        let obj = serde_json::json!({
            "format": name,
            "input": args.file.display().to_string(),
            "output": args.output.as_ref().map(|p| p.display().to_string()),
            "card": card,
        });
        println!("{}", serde_json::to_string(&obj)?);
    } else {
        if args.output.is_none() {
            print!("{card}");
        }
        eprintln!(
            "viscoroll export: {name} card, {} terms{}",
            spectrum.terms.len(),
            if shift.is_some() { " + WLF shift" } else { "" }
        );
    }
    Ok(())
}
