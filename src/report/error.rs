//! Errors of the `report` stage ([`ReportError`]) and its one way to write a file
//! ([`write_file`]: the crate's atomic writer, [`crate::fsutil`], with the path in the error).

use std::path::{Path, PathBuf};
use thiserror::Error;

/// Why a report file could not be written.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum ReportError {
    /// A plot could not be drawn.
    #[error("plot: {0}")]
    Plot(#[from] super::plots::PlotError),
    /// A file or folder could not be written.
    #[error("{path}: {source}")]
    Io {
        /// The path.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
}

/// Wrap an I/O error with its path.
pub(crate) fn io(path: &Path) -> impl FnOnce(std::io::Error) -> ReportError + '_ {
    move |source| ReportError::Io {
        path: path.to_path_buf(),
        source,
    }
}

/// Write `bytes` to `path` atomically (temp file in the same folder, then rename), replacing an
/// earlier report file of the same name: report files are the tool's own outputs.
pub fn write_file(path: &Path, bytes: &[u8]) -> Result<(), ReportError> {
    crate::fsutil::write_atomic(path, bytes, true).map_err(io(path))
}
