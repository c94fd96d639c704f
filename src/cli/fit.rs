//! `viscoroll fit`: Master curve + Prony fit + creep spectrum → a fit file.

/// Arguments of `viscoroll fit`.
#[derive(Debug, clap::Args)]
pub struct Args {}

/// Run `viscoroll fit`.
pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("`viscoroll fit` is not implemented yet")
}
