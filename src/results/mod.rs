//! Results as plain serde data, the floor below `pipeline` and `report`: the fit file of a compound
//! ([`CompoundFit`]), the scenes and what a compound does in them (`scene`), and the outcome of the
//! main job ([`RunSummary`]).
//!
//! Input: what the stages hand on (measurement, shift law, Prony fit, creep spectrum, contact
//! solutions); output: types that are saved, read back and written into reports. Imports only the
//! stages below it (dma, tts, prony, creep, contact's `Scene`).

pub(crate) mod band_ensemble;
pub(crate) mod compound_fit;
mod line;
pub(crate) mod outcome;
pub(crate) mod scene;

pub(crate) use band_ensemble::offset_at;
pub use band_ensemble::BandEnsemble;
pub(crate) use band_ensemble::{BandReplicate, ModelErrorSummary, ScatterEstimate};
pub use compound_fit::{
    CompoundFit, CompoundFitError, FitSettings, MeasurementSummary, TtsSummary,
};
pub(crate) use compound_fit::{InputHash, QualityFigure};
pub(crate) use outcome::{cap_line, standing};
pub use outcome::{
    CompoundOutcome, PairComparison, RunStatus, RunSummary, SceneStanding, TrustLevel,
};
pub use scene::{
    FrictionBand, FrictionMaps, FrictionPoint, MapPoint, SceneError, SceneSet, SceneSpec,
};
pub(crate) use scene::{EXTRAPOLATION_LIMIT_K, UNDETERMINED_BAND_RATIO};

/// `n` and the noun, plural unless `n` is 1: "1 scene", "3 scenes" (`noun` takes an `s`).
pub(crate) fn counted(n: usize, noun: &str) -> String {
    if n == 1 {
        format!("1 {noun}")
    } else {
        format!("{n} {noun}s")
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn counted_is_singular_for_one_only() {
        assert_eq!(super::counted(1, "scene"), "1 scene");
        assert_eq!(super::counted(0, "scene"), "0 scenes");
        assert_eq!(super::counted(3, "compound"), "3 compounds");
    }
}
