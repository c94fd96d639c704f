//! Errors of the `pipeline` stage ([`PipelineError`]): each names the compound, file or field.

use std::path::PathBuf;
use thiserror::Error;

/// Why a step of the main job failed.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum PipelineError {
    /// Reading the DMA exports failed.
    #[error("ingest: {0}")]
    Ingest(#[from] crate::dma::DmaError),
    /// The master curve could not be built.
    #[error("master curve: {0}")]
    Master(#[from] crate::tts::TtsError),
    /// The Prony fit failed.
    #[error("Prony fit: {0}")]
    Prony(#[from] crate::prony::PronyError),
    /// Relaxation → creep conversion or a temperature shift failed.
    #[error("creep spectrum: {0}")]
    Creep(#[from] crate::creep::CreepError),
    /// The contact solve failed.
    #[error("contact: {0}")]
    Contact(#[from] crate::contact::ContactError),
    /// A friction map could not be built.
    #[error("friction map: {0}")]
    Map(#[from] crate::contact::maps::FrictionMapError),
    /// A fit file could not be read or written.
    #[error("{0}")]
    Fit(#[from] crate::results::CompoundFitError),
    /// A report file could not be written.
    #[error("{0}")]
    Report(#[from] crate::report::ReportError),
    /// A scenes file could not be read or is not valid.
    #[error("{0}")]
    Scene(#[from] crate::results::SceneError),
    /// A scenes or compounds file is not valid.
    #[error("{path}: {message}")]
    Config {
        /// The file.
        path: PathBuf,
        /// What is wrong (names the key).
        message: String,
    },
    /// A file or folder could not be read or written.
    #[error("{path}: {source}")]
    Io {
        /// The path.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The fit file holds a different fit (other inputs or settings) and `force` was not given.
    #[error("{path}: holds a fit of other inputs or settings; pass --force to replace it")]
    FitDiffers {
        /// The fit file.
        path: PathBuf,
    },
    /// A setting is not valid (names the field).
    #[error("{field}: {message}")]
    Setting {
        /// The option or key.
        field: String,
        /// What is wrong.
        message: String,
    },
    /// The measurement holds values no polymer DMA can give.
    #[error("implausible data: {message}")]
    Implausible {
        /// The compound.
        compound: String,
        /// What is impossible, and where.
        message: String,
    },
    /// The input is not a folder.
    #[error("{path} is not a folder")]
    NotAFolder {
        /// The path given.
        path: PathBuf,
    },
    /// The input folder holds no compound to run.
    #[error("{path}: no DMA export or compound found{}", if notes.is_empty() { String::new() } else { format!(" ({notes})") })]
    NoCompounds {
        /// The folder.
        path: PathBuf,
        /// What was skipped there.
        notes: String,
    },
    /// The computation of a compound stopped on an internal error (a bug; the other compounds run on).
    #[error("internal error while computing {compound}: {message} (please report it)")]
    Internal {
        /// The compound.
        compound: String,
        /// The panic's message.
        message: String,
    },
    /// Time-domain data could not be read (crate::dma::time_domain).
    #[error(transparent)]
    TimeData(Box<crate::dma::time_domain::TimeDataError>),
    /// Creep data could not be fitted (crate::creep::time_fit).
    #[error(transparent)]
    CreepFit(Box<crate::creep::time_fit::CreepFitError>),
    /// A fit file has no creep spectrum.
    #[error("{compound}: the fit has no creep spectrum")]
    NoCreep {
        /// The compound.
        compound: String,
    },
}

impl From<crate::dma::time_domain::TimeDataError> for PipelineError {
    fn from(e: crate::dma::time_domain::TimeDataError) -> Self {
        PipelineError::TimeData(Box::new(e))
    }
}

impl From<crate::creep::time_fit::CreepFitError> for PipelineError {
    fn from(e: crate::creep::time_fit::CreepFitError) -> Self {
        PipelineError::CreepFit(Box::new(e))
    }
}

/// Wrap an I/O error with its path.
pub(crate) fn io(path: &std::path::Path) -> impl FnOnce(std::io::Error) -> PipelineError + '_ {
    move |source| PipelineError::Io {
        path: path.to_path_buf(),
        source,
    }
}
