//! The comparisons of the ranked compounds in each scene, shared by the main job (`run`) and the
//! merge of its shards (`shard`).
//!
//! Input: the compounds' outcomes and the scenes; output: the pairs compared (with their bands) and
//! each standing's `tied_with` filled.

use crate::results::{CompoundOutcome, SceneSet};

/// For each scene, every pair of ranked compounds with a band of their mean (crate::bands::compare,
/// in ranking order), and each standing's `tied_with` filled from the ties.
pub(crate) fn compare_ranked(
    outcomes: &mut [CompoundOutcome],
    scenes: &SceneSet,
) -> Vec<crate::results::PairComparison> {
    let mut all = Vec::new();
    for spec in &scenes.scene {
        let ranked: Vec<(String, crate::results::FrictionBand)> =
            crate::report::ranked(outcomes, &spec.name)
                .into_iter()
                .filter_map(|(o, s)| s.band.map(|b| (o.compound.clone(), b)))
                .collect();
        let pairs = crate::bands::comparisons(&spec.name, &ranked);
        for o in outcomes.iter_mut() {
            let name = o.compound.clone();
            if let Some(st) = o.standings.iter_mut().find(|s| s.scene == spec.name) {
                st.tied_with = pairs
                    .iter()
                    .filter(|p| p.tied && (p.a == name || p.b == name))
                    .map(|p| {
                        if p.a == name {
                            p.b.clone()
                        } else {
                            p.a.clone()
                        }
                    })
                    .collect();
            }
        }
        all.extend(pairs);
    }
    all
}
