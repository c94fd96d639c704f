//! `viscoroll ingest`: Read DMA exports and report what was found.

/// Arguments of `viscoroll ingest`.
#[derive(Debug, clap::Args)]
pub struct Args {}

/// Run `viscoroll ingest`.
pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("`viscoroll ingest` is not implemented yet")
}
