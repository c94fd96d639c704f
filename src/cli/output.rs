//! Output files of the CLI: [`crate::fsutil::write_atomic`] with the CLI's messages (never replace
//! an existing file unless asked to).

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
