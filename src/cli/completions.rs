//! `viscoroll completions SHELL` and `viscoroll man`: a shell completion script (clap_complete) and a
//! man page in roff (clap_mangen), both printed on stdout and built from the same clap definition as
//! the parser, so they list every subcommand and option there is.
//!
//! ```text
//! viscoroll completions bash > /etc/bash_completion.d/viscoroll
//! viscoroll man > viscoroll.1 && man ./viscoroll.1
//! viscoroll man fit > viscoroll-fit.1
//! ```

use clap::CommandFactory;
use std::io::Write;

/// Arguments of `viscoroll completions`.
#[derive(Debug, clap::Args)]
pub struct CompletionArgs {
    /// The shell to write the completion script for.
    #[arg(value_enum)]
    pub shell: clap_complete::Shell,
}

/// Arguments of `viscoroll man`.
#[derive(Debug, clap::Args)]
pub struct ManArgs {
    /// The page of this subcommand (`viscoroll-NAME(1)`, as the main page's SUBCOMMANDS list
    /// names it) instead of the main page.
    pub subcommand: Option<String>,
}

/// Write the completion script for `args.shell` on stdout.
pub fn completions(args: CompletionArgs) -> anyhow::Result<()> {
    let mut cmd = super::Cli::command();
    let mut out = Vec::new();
    clap_complete::generate(args.shell, &mut cmd, "viscoroll", &mut out);
    std::io::stdout().lock().write_all(&out)?;
    Ok(())
}

/// Write the man page (roff) on stdout: the synopsis, every subcommand, the exit codes; or one
/// subcommand's page.
pub fn man(args: ManArgs) -> anyhow::Result<()> {
    let mut cmd = super::Cli::command();
    cmd.build();
    let page = match &args.subcommand {
        None => cmd,
        Some(name) => {
            let sub = cmd.find_subcommand(name).cloned().ok_or_else(|| {
                let names: Vec<String> = cmd
                    .get_subcommands()
                    .map(|c| c.get_name().to_string())
                    .collect();
                anyhow::anyhow!(
                    "man {name}: no such subcommand (there are: {})",
                    names.join(", ")
                )
            })?;
            return render(clap_mangen::Man::new(sub).title(format!("viscoroll-{name}")));
        }
    };
    render(clap_mangen::Man::new(page))
}

fn render(page: clap_mangen::Man) -> anyhow::Result<()> {
    let mut out = Vec::new();
    page.render(&mut out)?;
    std::io::stdout().lock().write_all(&out)?;
    Ok(())
}
