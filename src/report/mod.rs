//! Stage `report`: everything the user reads — a compound's report folder (datasheet, plots,
//! friction tables), the ranking, the index page, plots and FEA export cards.
//!
//! Input: the saved results ([`crate::results`]): fits, friction points and maps, run outcomes;
//! output: files, each written atomically through [`write_file`] (the crate's one atomic writer,
//! [`crate::fsutil`]). CSV goes through the csv crate ([`csv_text`]): one header row, no comment
//! lines, a sidecar `NAME.meta.json` beside each table ([`csv_meta`]). Imports only downward
//! (results and the stages); the pipeline calls it.

pub mod card_refit;
pub mod card_shift;
pub mod cards;
pub mod chart;
pub mod csv_meta;
pub mod csv_text;
pub mod datasheet;
pub mod error;
pub mod html;
pub mod index;
pub mod plots;
pub mod ranking;
pub mod ticks;
pub mod workbook;

pub use datasheet::{write_report, Measured};
pub use error::{write_file, ReportError};
pub use index::{index_html, write_index, TanDeltaProxy};
pub use ranking::{ranked, ranking_csv, write_ranking};
pub use workbook::write_workbook;
