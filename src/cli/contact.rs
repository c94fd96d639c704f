//! `viscoroll contact`: The dimensionless problem of the thesis (ch. 3–4): one creep spectrum f:b, at given λ or load N'.

/// Arguments of `viscoroll contact`.
#[derive(Debug, clap::Args)]
pub struct Args {}

/// Run `viscoroll contact`.
pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("`viscoroll contact` is not implemented yet")
}
