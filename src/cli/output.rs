//! Output files of the CLI: [`crate::fsutil::write_atomic`] with the CLI's messages (never replace
//! an existing file unless asked to); and the version stamp of every `--json` output ([`versioned`]).

use std::path::Path;

/// Write `bytes` to `path` atomically; refuse to replace an existing file unless `force`.
pub(crate) fn write_atomic(path: &Path, bytes: &[u8], force: bool) -> anyhow::Result<()> {
    crate::fsutil::write_atomic(path, bytes, force).map_err(|e| {
        if e.kind() == std::io::ErrorKind::AlreadyExists {
            anyhow::anyhow!(
                "{} exists; not overwritten (use --force to replace it)",
                path.display()
            )
        } else {
            anyhow::anyhow!("cannot write {}: {e}", path.display())
        }
    })
}

/// Why a write to stdout or stderr failed, if one did (0 none, 1 broken pipe, 2 any other error).
static STREAM_FAILED: std::sync::atomic::AtomicU8 = std::sync::atomic::AtomicU8::new(0);

/// Text for a terminal or a pipe: every control character but newline and tab shown escaped
/// (`\u{1b}`), so escape sequences from file contents or metadata never reach the terminal.
pub(crate) fn terminal_safe(text: &str) -> std::borrow::Cow<'_, str> {
    if !text
        .chars()
        .any(|c| c.is_control() && c != '\n' && c != '\t')
    {
        return text.into();
    }
    text.chars()
        .map(|c| {
            if c.is_control() && c != '\n' && c != '\t' {
                c.escape_unicode().to_string()
            } else {
                c.to_string()
            }
        })
        .collect::<String>()
        .into()
}

/// Write to stdout (`err` false) or stderr, escaped ([`terminal_safe`]); a failed write is
/// remembered ([`stream_exit_code`]), never a panic, and later writes to a failed stream are skipped.
pub(crate) fn write_stream(err: bool, args: std::fmt::Arguments<'_>) {
    use std::io::Write as _;
    use std::sync::atomic::Ordering;
    let text = args.to_string();
    let text = terminal_safe(&text);
    let result = if err {
        std::io::stderr().lock().write_all(text.as_bytes())
    } else {
        let mut o = std::io::stdout().lock();
        o.write_all(text.as_bytes()).and_then(|()| o.flush())
    };
    if let Err(e) = result {
        let code = if e.kind() == std::io::ErrorKind::BrokenPipe {
            1
        } else {
            2
        };
        STREAM_FAILED.fetch_max(code, Ordering::Relaxed);
    }
}

/// The exit code a failed stream write calls for: `None` if none failed; a closed pipe
/// (`… | head`) keeps the command's code; any other failure (a full disk, `/dev/full`) is 1.
pub(crate) fn stream_exit_code(code: i32) -> i32 {
    match STREAM_FAILED.load(std::sync::atomic::Ordering::Relaxed) {
        2 => code.max(1),
        _ => code,
    }
}

/// Version of the layouts of the `--json` outputs, published as JSON Schemas in docs/schemas/ (one per
/// command, `error.schema.json` for the error object): raised when a field is removed, renamed or
/// changes meaning; new fields do not raise it.
pub const JSON_SCHEMA_VERSION: u32 = 1;

/// A `--json` output object with its `schema_version` ([`JSON_SCHEMA_VERSION`]).
pub(crate) fn versioned(mut value: serde_json::Value) -> serde_json::Value {
    if let Some(o) = value.as_object_mut() {
        o.insert("schema_version".into(), JSON_SCHEMA_VERSION.into());
    }
    value
}
