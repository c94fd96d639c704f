//! `viscoroll roll`: One dimensional scene: a roll on a compound's creep spectrum → friction, contact length, pressure.

/// Arguments of `viscoroll roll`.
#[derive(Debug, clap::Args)]
pub struct Args {}

/// Run `viscoroll roll`.
pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("`viscoroll roll` is not implemented yet")
}
