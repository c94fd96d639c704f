//! The output folder's layout and lock, shared by the main job (`run`) and its shards (`shard`):
//! where a compound's fit file goes ([`fit_path`]) and how long a run waits for the folder's lock
//! ([`LOCK_WAIT`]).
//!
//! Input: the output folder and a compound's name; output: paths and durations.

use std::path::{Path, PathBuf};

/// How long a run waits for another run that holds the output folder.
pub const LOCK_WAIT: std::time::Duration = std::time::Duration::from_secs(1800);

/// The output folder's fit path of a compound.
pub fn fit_path(out_dir: &Path, compound: &str) -> PathBuf {
    out_dir.join("fits").join(format!("{compound}.json"))
}
