//! Command-line interface: clap subcommands, one file each; error reporting and exit codes.
//!
//! Every computing command takes `--json` and then prints exactly one JSON object on stdout; human
//! text goes to stderr. Exit codes: 0 success, 1 bad input or a failed computation, 2 unexpected
//! error (including usage errors reported by clap).

mod contact;
mod convert;
mod export;
mod fit;
mod ingest;
mod master;
mod output;
mod rank;
mod roll;
mod roll_cover;
mod run;

use clap::{Parser, Subcommand};

/// viscoroll: from DMA measurements of a rubber compound to its rolling loss.
#[derive(Debug, Parser)]
#[command(name = "viscoroll", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// The dimensionless problem of the thesis (ch. 3–4): one creep spectrum f:b, at given λ or load N'.
    Contact(contact::Args),
    /// One dimensional scene: a roll on a compound's creep spectrum → friction, contact length, pressure.
    Roll(roll::Args),
    /// Convert a relaxation spectrum to a creep spectrum (exact or Park & Schapery).
    Convert(convert::Args),
    /// Write FEA material cards (Abaqus, ANSYS, LS-DYNA) from a spectrum or fit.
    Export(export::Args),
    /// Read DMA exports and report what was found.
    Ingest(ingest::Args),
    /// Master curve by time–temperature superposition, with WLF and Arrhenius fits.
    Master(master::Args),
    /// Master curve + Prony fit + creep spectrum → a fit file.
    Fit(fit::Args),
    /// The main job: every compound of a folder → fits, friction, datasheets, ranking.
    Run(run::Args),
    /// Rank fit files by predicted rolling friction in a scene.
    Rank(rank::Args),
}

/// Parse the command line, run the command, report an error once; returns the exit code.
pub fn run() -> i32 {
    quiet_broken_pipe();
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if !e.use_stderr() => {
            // --help and --version: clap's own text on stdout.
            let _ = e.print();
            return 0;
        }
        Err(e) => {
            // A usage error: one line (clap's first line, which names the argument and value),
            // then where to read more. Exit code 2.
            let text = e.to_string();
            let first = text.lines().next().unwrap_or("bad arguments");
            let first = first.trim_start_matches("error: ");
            eprintln!("viscoroll: {first} (see `viscoroll --help`)");
            return 2;
        }
    };
    let result: anyhow::Result<()> = match cli.command {
        Command::Contact(args) => contact::run(args),
        Command::Roll(args) => roll::run(args),
        Command::Convert(args) => convert::run(args),
        Command::Export(args) => export::run(args),
        Command::Ingest(args) => ingest::run(args),
        Command::Master(args) => master::run(args),
        Command::Fit(args) => fit::run(args),
        Command::Run(args) => run::run(args),
        Command::Rank(args) => rank::run(args),
    };
    match result {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("viscoroll: {e:#}");
            1
        }
    }
}

/// A closed stdout (`viscoroll … --json | head`) is not an error: exit quietly with code 0 instead
/// of the standard library's "failed printing to stdout: Broken pipe" panic.
fn quiet_broken_pipe() {
    let default_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let msg = info
            .payload()
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| info.payload().downcast_ref::<&str>().copied())
            .unwrap_or("");
        if msg.contains("Broken pipe") {
            std::process::exit(0);
        }
        default_hook(info);
    }));
}
