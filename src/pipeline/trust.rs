//! What the main job may claim (issue 31): each point's replicate-specimen frictions, whether it is
//! determined, its band with the between-specimen term (`finish_points`); the band of a scene
//! mean (`standing_band`); and scene means over the temperatures the ranked compounds share
//! (`share_windows`).
//!
//! Input: a compound's points in a scene (bands from crate::bands already on them), its replicate
//! specimens' own points, its bootstrap ratios; output: the same points and standings, finished.
//! Math: the between-specimen term docs/MATH.md §16 (crate::bands::between).

use crate::bands::{between_sd_ln, mean_band, widen};
use crate::results::{CompoundOutcome, FrictionBand, FrictionPoint, SceneSet};

/// Finish a scene's points: each specimen's friction at the point (`specimen_points`, one list per
/// replicate specimen, empty with one specimen), whether the point is determined (its band before
/// the between-specimen term, its distance beyond `measured_c`: `FrictionPoint::determine`), then
/// its band widened by the spread between specimens (eq. 16.3; the prior with one specimen).
pub(crate) fn finish_points(
    points: &mut [FrictionPoint],
    specimen_points: &[Vec<FrictionPoint>],
    measured_c: Option<(f64, f64)>,
) {
    let n = specimen_points.len().max(1);
    for p in points.iter_mut() {
        p.specimens = specimen_points
            .iter()
            .map(|sp| {
                sp.iter()
                    .find(|q| q.temp_c == p.temp_c && q.error.is_none())
                    .map_or(f64::NAN, |q| q.friction)
            })
            .collect();
        p.determine(measured_c);
        if let Some(b) = p.band {
            p.band = Some(widen(b, between_sd_ln(&p.specimens), n));
        }
    }
}

/// The band of the mean friction over `temps_c` (crate::bands::mean_band), widened by the spread
/// between the specimens' own means over the same temperatures (eq. 16.3).
pub(crate) fn standing_band(
    points: &[FrictionPoint],
    ratios: &[Vec<f64>],
    temps_c: &[f64],
) -> Option<FrictionBand> {
    let band = mean_band(points, ratios, temps_c)?;
    let used: Vec<&FrictionPoint> = temps_c
        .iter()
        .filter_map(|t| points.iter().find(|p| p.temp_c == *t))
        .collect();
    let n = used.first().map_or(0, |p| p.specimens.len());
    let means: Vec<f64> = (0..n)
        .map(|k| used.iter().map(|p| p.specimens[k]).sum::<f64>() / used.len() as f64)
        .collect();
    Some(widen(band, between_sd_ln(&means), n.max(1)))
}

/// Per scene, the ranked compounds' means over the temperatures they all share: a standing whose
/// own window is wider keeps it in `own_temps_c` and gets its mean and band over the shared ones.
/// `ratios` holds per compound and scene the bootstrap ratios (empty without bands). When the
/// ranked compounds share no temperature, each keeps its own window and says so in its reasons
/// (use with care).
pub(crate) fn share_windows(
    outcomes: &mut [CompoundOutcome],
    ratios: &[Vec<Vec<Vec<f64>>>],
    scenes: &SceneSet,
) {
    for (k, spec) in scenes.scene.iter().enumerate() {
        let ranked: Vec<usize> = (0..outcomes.len())
            .filter(|&i| {
                outcomes[i].error.is_none()
                    && outcomes[i]
                        .standing(&spec.name)
                        .is_some_and(|s| s.trusted())
            })
            .collect();
        if ranked.len() < 2 {
            continue;
        }
        let windows: Vec<Vec<f64>> = ranked
            .iter()
            .map(|&i| {
                outcomes[i]
                    .standing(&spec.name)
                    .map_or(vec![], |s| s.temps_c.clone())
            })
            .collect();
        let shared: Vec<f64> = windows[0]
            .iter()
            .copied()
            .filter(|t| windows.iter().all(|w| w.contains(t)))
            .collect();
        for (&i, own) in ranked.iter().zip(&windows) {
            if *own == shared {
                continue;
            }
            let o = &mut outcomes[i];
            let points = o
                .friction
                .iter()
                .find(|(s, _)| *s == spec.name)
                .map(|(_, p)| p.clone())
                .unwrap_or_default();
            let Some(st) = o.standings.iter_mut().find(|s| s.scene == spec.name) else {
                continue;
            };
            if shared.is_empty() {
                st.care.push(
                    "no temperature shared with the other ranked compounds: its mean is over \
                     its own window, not comparable"
                        .into(),
                );
                continue;
            }
            st.own_temps_c = own.clone();
            st.temps_c = shared.clone();
            let f: Vec<f64> = shared
                .iter()
                .filter_map(|t| points.iter().find(|p| p.temp_c == *t))
                .map(|p| p.friction)
                .collect();
            st.mean_friction = Some(f.iter().sum::<f64>() / f.len() as f64);
            st.band = ratios
                .get(i)
                .and_then(|r| r.get(k))
                .filter(|r| !r.is_empty())
                .and_then(|r| standing_band(&points, r, &shared));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::results::{standing, SceneStanding};

    fn point(temp_c: f64, friction: f64) -> FrictionPoint {
        FrictionPoint {
            temp_c,
            log10_a_t: 0.0,
            friction,
            resistance_n_per_m: friction,
            contact_length_mm: 1.0,
            extrapolated: false,
            error: None,
            model: String::new(),
            model_reason: String::new(),
            warnings: vec![],
            band: None,
            specimens: vec![],
            undetermined: None,
            error_estimate: None,
        }
    }

    fn outcome(name: &str, scene: &str, pts: Vec<FrictionPoint>) -> CompoundOutcome {
        CompoundOutcome {
            compound: name.into(),
            fit_path: None,
            fit_action: None,
            standings: vec![standing(scene, &pts, &[], &[], false)],
            friction: vec![(scene.into(), pts)],
            untrusted: vec![],
            warnings: vec![],
            error: None,
            seconds: 0.0,
            specimens: 1,
        }
    }

    #[test]
    fn means_are_taken_over_the_shared_temperatures_and_the_own_window_is_kept() {
        let scenes = SceneSet::shipped();
        let s = scenes.scene[0].name.clone();
        let a = outcome(
            "a",
            &s,
            vec![point(-20.0, 8.0), point(0.0, 1.0), point(20.0, 3.0)],
        );
        let mut b = outcome(
            "b",
            &s,
            vec![point(-20.0, 1.0), point(0.0, 2.0), point(20.0, 2.0)],
        );
        // b's −20 °C is not determined: it counts nowhere, so a's mean loses it too
        b.friction[0].1[0].undetermined = Some("not determined: test".into());
        b.standings = vec![standing(&s, &b.friction[0].1, &[], &[], false)];
        let mut outs = vec![a, b];
        share_windows(&mut outs, &[vec![], vec![]], &scenes);
        let st: &SceneStanding = outs[0].standing(&s).unwrap();
        assert_eq!(st.temps_c, [0.0, 20.0]);
        assert_eq!(st.own_temps_c, [-20.0, 0.0, 20.0]);
        assert_eq!(st.mean_friction, Some(2.0));
        let st = outs[1].standing(&s).unwrap();
        assert!(st.own_temps_c.is_empty());
        assert_eq!(st.mean_friction, Some(2.0));
        assert!(st.care.iter().any(|c| c.contains("not determined at -20")));
    }

    #[test]
    fn a_point_with_a_band_over_the_ratio_or_far_beyond_the_data_is_not_determined() {
        let mut pts = vec![point(-40.0, 1.0), point(0.0, 1.0), point(10.0, 1.0)];
        pts[1].band = Some(FrictionBand {
            p05: 0.09,
            p50: 1.0,
            p95: 1.0,
        });
        pts[2].band = Some(FrictionBand {
            p05: 0.5,
            p50: 1.0,
            p95: 2.0,
        });
        finish_points(&mut pts, &[], Some((-25.0, 100.0)));
        // −40 °C is 15 K below −25 °C (limit 10 K); 1/0.09 = 11.1 > 10; 4 ≤ 10
        assert!(pts[0].undetermined.as_deref().unwrap().contains("15 K"));
        assert!(pts[1].undetermined.as_deref().unwrap().contains("11.1"));
        assert!(pts[2].undetermined.is_none());
        // the between-specimen prior widens the determined band after the test
        let b = pts[2].band.unwrap();
        assert!(b.p95 > 2.0 && b.p05 < 0.5 && b.p50 == 1.0);
    }
}
