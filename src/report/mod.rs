//! Stage `report`: plots, datasheets, friction maps, rankings and FEA export cards.

pub mod cards;
pub mod plots;
