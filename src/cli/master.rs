//! `viscoroll master`: Master curve by time–temperature superposition, with WLF and Arrhenius fits.

/// Arguments of `viscoroll master`.
#[derive(Debug, clap::Args)]
pub struct Args {}

/// Run `viscoroll master`.
pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("`viscoroll master` is not implemented yet")
}
