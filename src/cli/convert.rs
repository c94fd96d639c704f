//! `viscoroll convert`: Convert a relaxation spectrum to a creep spectrum (exact or Park & Schapery).

/// Arguments of `viscoroll convert`.
#[derive(Debug, clap::Args)]
pub struct Args {}

/// Run `viscoroll convert`.
pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("`viscoroll convert` is not implemented yet")
}
