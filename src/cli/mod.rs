//! Command-line interface: clap subcommands, one file each; error reporting and exit codes.
//!
//! Every computing command takes `--json` and then prints exactly one JSON object on stdout; human
//! text goes to stderr. A failure prints one message on stderr — the error and its causes, each
//! once — and with `--json` also one object `{"error": …, "kind": …}` on stdout, with the same exit
//! code. Exit codes (`EXIT_CODES`): 0 success, 1 bad input or a failed computation, 2 usage error
//! (clap's full message, with its "a similar argument exists" tips), 3 `run` finished but some
//! results are not trusted.

/// `println!` for the CLI: through [`output::write_stream`] (escaped; a failed write sets the exit
/// code instead of panicking).
macro_rules! outln {
    () => { $crate::cli::output::write_stream(false, format_args!("\n")) };
    ($($t:tt)*) => { $crate::cli::output::write_stream(false, format_args!("{}\n", format_args!($($t)*))) };
}
/// `print!` for the CLI, as [`outln`].
#[allow(unused_macros)]
macro_rules! out {
    ($($t:tt)*) => { $crate::cli::output::write_stream(false, format_args!($($t)*)) };
}
/// `eprintln!` for the CLI, as [`outln`].
macro_rules! errln {
    () => { $crate::cli::output::write_stream(true, format_args!("\n")) };
    ($($t:tt)*) => { $crate::cli::output::write_stream(true, format_args!("{}\n", format_args!($($t)*))) };
}

mod completions;
mod contact;
mod convert;
mod export;
mod fit;
mod ingest;
mod master;
mod output;
mod rank;
mod roll;
mod roll_args;
mod roll_band;
mod roll_cover;
mod roll_print;
mod run;
mod spectrum_input;
mod tuning_args;

use clap::{Parser, Subcommand};

/// clap's parser of every temperature argument: a number in °C within the work budget's range
/// (crate::limits::temperature_c: not below absolute zero, not above 1000 °C).
fn temp_c(s: &str) -> Result<f64, String> {
    let t: f64 = s
        .trim()
        .parse()
        .map_err(|e| format!("{s:?} is not a number: {e}"))?;
    crate::limits::temperature_c("temperature", t)
        .map(|()| t)
        .map_err(|e| e.reason)
}

/// The exit codes, as printed by `--help`.
pub(crate) const EXIT_CODES: &str = "Exit codes: 0 success; 1 bad input or a failed computation (for `run`: \
some compound failed, or the folder holds none); 2 usage error; 3 `run` finished, but some results \
are not trusted (a fit out of its quality bounds, or a friction that could not be computed: listed \
apart in ranking.csv and index.html). With --json a failure also prints {\"error\": …, \"kind\": …} \
on stdout.";

/// An error that ends the program with its own exit code (the message is printed as usual).
#[derive(Debug)]
pub(crate) struct Exit {
    /// The exit code.
    pub code: i32,
    /// `kind` in the JSON error object.
    pub kind: &'static str,
    /// The message.
    pub message: String,
    /// What the command found anyway (e.g. the run summary), printed with `--json` under `detail`.
    pub detail: Option<serde_json::Value>,
}

impl std::fmt::Display for Exit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Exit {}

/// viscoroll: from DMA measurements of a rubber compound to its rolling loss.
#[derive(Debug, Parser)]
#[command(name = "viscoroll", version, about, long_about = None, after_help = EXIT_CODES)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// The dimensionless problem of the thesis (ch. 3–4): one creep spectrum f:b, at given λ or load N'.
    #[command(after_help = EXIT_CODES)]
    Contact(contact::Args),
    /// One dimensional scene: a roll on a compound's creep spectrum → friction, contact length, pressure.
    #[command(after_help = EXIT_CODES)]
    Roll(roll::Args),
    /// Convert a relaxation spectrum to a creep spectrum (exact or Park & Schapery).
    #[command(after_help = EXIT_CODES)]
    Convert(convert::Args),
    /// Write FEA material cards (Abaqus, ANSYS, LS-DYNA) from a spectrum or fit.
    #[command(after_help = EXIT_CODES)]
    Export(export::Args),
    /// Read DMA exports and report what was found.
    #[command(after_help = EXIT_CODES)]
    Ingest(ingest::Args),
    /// Master curve by time–temperature superposition, with WLF and Arrhenius fits.
    #[command(after_help = EXIT_CODES)]
    Master(master::Args),
    /// Master curve + Prony fit + creep spectrum → a fit file.
    #[command(after_help = EXIT_CODES)]
    Fit(fit::Args),
    /// The main job: every compound of a folder → fits, friction, datasheets, ranking.
    #[command(after_help = EXIT_CODES)]
    Run(run::Args),
    /// Rank fit files by predicted rolling friction in a scene.
    #[command(after_help = EXIT_CODES)]
    Rank(rank::Args),
    /// Print a shell completion script (bash, zsh, fish, elvish, powershell) on stdout.
    #[command(after_help = EXIT_CODES)]
    Completions(completions::CompletionArgs),
    /// Print the man page (roff) on stdout: `viscoroll man > viscoroll.1`, `viscoroll man fit`.
    #[command(after_help = EXIT_CODES)]
    Man(completions::ManArgs),
}

impl Command {
    /// Whether the command was asked for JSON output.
    fn json(&self) -> bool {
        match self {
            Command::Contact(a) => a.json,
            Command::Roll(a) => a.json,
            Command::Convert(a) => a.json,
            Command::Export(a) => a.json,
            Command::Ingest(a) => a.json,
            Command::Master(a) => a.json,
            Command::Fit(a) => a.json,
            Command::Run(a) => a.json,
            Command::Rank(a) => a.json,
            Command::Completions(_) | Command::Man(_) => false,
        }
    }
}

/// The message of an error and its causes, each cause once: a cause whose text the message already
/// holds (an error that prints its source, `ingest: X` over `X`) is not repeated.
pub fn error_text(e: &anyhow::Error) -> String {
    let mut text = String::new();
    for cause in e.chain() {
        let c = cause.to_string();
        if text.contains(&c) {
            continue;
        }
        if !text.is_empty() {
            text.push_str(": ");
        }
        text.push_str(&c);
    }
    crate::results::cap_line(&text)
}

/// Report a failure: the message on stderr; with `json`, one JSON object on stdout too
/// (`{"error", "kind", "exit_code"}`, and `detail` when the command has one).
fn fail(
    json: bool,
    code: i32,
    kind: &str,
    message: &str,
    detail: Option<&serde_json::Value>,
) -> i32 {
    errln!("viscoroll: {message}");
    if json {
        let mut obj = serde_json::json!({"error": message, "kind": kind, "exit_code": code});
        if let Some(d) = detail {
            obj["detail"] = d.clone();
        }
        outln!("{}", output::versioned(obj));
    }
    code
}

/// Parse the command line, run the command, report an error once; returns the exit code.
pub fn run() -> i32 {
    quiet_broken_pipe();
    run_with(std::env::args_os().collect())
}

/// [`run`] on given arguments (the first is the program name).
pub(crate) fn run_with(args: Vec<std::ffi::OsString>) -> i32 {
    let cli = match Cli::try_parse_from(&args) {
        Ok(cli) => cli,
        Err(e) if !e.use_stderr() => {
            // --help and --version: clap's own text on stdout.
            let _ = e.print();
            return 0;
        }
        Err(e) => {
            // A usage error: clap's whole message (what is wrong, the missing arguments, its
            // "a similar argument exists" tip, the usage line). Exit code 2.
            let json = args.iter().any(|a| a == "--json");
            let text = e.render().to_string();
            let text = text.trim_end().trim_start_matches("error: ");
            return fail(json, 2, "usage", text, None);
        }
    };
    let json = cli.command.json();
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
        Command::Completions(args) => completions::completions(args),
        Command::Man(args) => completions::man(args),
    };
    let code = match result {
        Ok(()) => 0,
        Err(e) => match e.downcast_ref::<Exit>() {
            Some(x) => fail(
                json,
                x.code,
                x.kind,
                &crate::results::cap_line(&x.message),
                x.detail.as_ref(),
            ),
            None => fail(json, 1, "error", &error_text(&e), None),
        },
    };
    output::stream_exit_code(code)
}

/// A backstop for any print that does not go through [`output::write_stream`] (a library's): a
/// closed stdout (`viscoroll … --json | head`) exits quietly with code 0, any other failed print
/// (a full device) with code 1, instead of the standard library's panic and backtrace.
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
        if msg.starts_with("failed printing to std") {
            std::process::exit(1);
        }
        default_hook(info);
    }));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, thiserror::Error)]
    #[error("ingest: {0}")]
    struct Outer(#[from] Inner);

    #[derive(Debug, thiserror::Error)]
    #[error("file.csv: no data")]
    struct Inner;

    #[test]
    fn a_cause_already_in_the_message_is_not_repeated() {
        let e = anyhow::Error::new(Outer(Inner));
        assert_eq!(error_text(&e), "ingest: file.csv: no data");
        let e = anyhow::Error::new(Inner).context("reading fit files");
        assert_eq!(error_text(&e), "reading fit files: file.csv: no data");
    }
}
