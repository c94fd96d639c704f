//! Stage `report`: everything the user reads — a compound's report folder (datasheet, plots,
//! friction tables), the ranking, the index page, plots and FEA export cards.
//!
//! Input: the saved results ([`crate::results`]): fits, friction points and maps, run outcomes;
//! output: files, each written atomically through `write_file` (the crate's one atomic writer,
//! [`crate::fsutil`]). CSV goes through the csv crate (`csv_text`): one header row, no comment
//! lines, a sidecar `NAME.meta.json` beside each table (`csv_meta`). Imports only downward
//! (results and the stages); the pipeline calls it.

pub(crate) mod card_refit;
pub(crate) mod card_shift;
pub(crate) mod cards;
pub(crate) mod chart;
pub(crate) mod csv_meta;
pub(crate) mod csv_text;
pub(crate) mod datasheet;
pub(crate) mod error;
pub(crate) mod html;
pub(crate) mod index;
pub(crate) mod plots;
pub(crate) mod ranking;
pub(crate) mod ticks;
pub(crate) mod workbook;

pub use cards::CardContents;
pub use datasheet::{write_report, Measured};
pub(crate) use error::write_file;
pub use error::ReportError;
pub use index::write_index;
pub(crate) use index::TanDeltaProxy;
pub(crate) use ranking::ranked;
pub use ranking::write_ranking;
pub use workbook::write_workbook;
