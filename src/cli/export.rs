//! `viscoroll export`: Write FEA material cards (Abaqus, ANSYS, LS-DYNA) from a spectrum or fit.

/// Arguments of `viscoroll export`.
#[derive(Debug, clap::Args)]
pub struct Args {}

/// Run `viscoroll export`.
pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("`viscoroll export` is not implemented yet")
}
