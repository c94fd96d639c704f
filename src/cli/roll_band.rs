//! The friction band of `viscoroll roll` (crate::bands), shared by its half-space and covered paths:
//! the band of one point with the notes the main job gives it ([`band`]) and its JSON fields and text
//! line ([`band_fields`]).
//!
//! Input: the command's [`Args`], the creep source, the scene and the friction; output: a [`RollBand`].

use super::roll_args::Args;
use crate::contact::Scene;
use crate::pipeline::roll_fit::CreepSource;

/// The band's JSON fields (`friction_p05`, `friction_p50`, `friction_p95`, null without one,
/// `bands_note` why there is none, and `bands_notes` what the band carries) into `json`, and its
/// text lines.
pub(super) fn band_fields(
    rb: &RollBand,
    json: &mut serde_json::Map<String, serde_json::Value>,
) -> String {
    let band = &rb.band;
    for (k, v) in [
        ("friction_p05", band.as_ref().ok().map(|b| b.p05)),
        ("friction_p50", band.as_ref().ok().map(|b| b.p50)),
        ("friction_p95", band.as_ref().ok().map(|b| b.p95)),
    ] {
        json.insert(k.into(), serde_json::json!(v));
    }
    json.insert("bands_note".into(), serde_json::json!(band.as_ref().err()));
    json.insert("bands_notes".into(), serde_json::json!(rb.notes));
    match band {
        Ok(b) => {
            let mut line = format!(
                "friction 90 % band  = {:.6e} … {:.6e} (median {:.6e})",
                b.p05, b.p95, b.p50
            );
            for n in &rb.notes {
                line.push_str(&format!("\n  band note: {n}"));
            }
            line
        }
        Err(why) => format!("friction band: none: {why}"),
    }
}

/// A friction band with the notes the main job gives the same point (widened beyond the measured
/// temperatures, eq. 15.8, or frequencies, eq. 15.9; replicates that failed), or why there is none.
pub(super) struct RollBand {
    /// The 90 % band, or why there is none.
    pub band: Result<crate::results::FrictionBand, String>,
    /// The band's notes, as in friction.csv's note column.
    pub notes: Vec<String>,
}

impl From<Result<crate::results::FrictionBand, String>> for RollBand {
    fn from(band: Result<crate::results::FrictionBand, String>) -> Self {
        Self {
            band,
            notes: Vec::new(),
        }
    }
}

/// The 90 % band of the friction `friction` of `scene` at `--temp-c` (crate::bands), on the scene's
/// body: on its cover bonded to a rigid carcass (solved as the main job solves a covered scene,
/// eq. 15.6) or on the half-space, with its notes, or why there is none.
pub(super) fn band(args: &Args, source: &CreepSource, scene: &Scene, friction: f64) -> RollBand {
    band_or_why(args, source, scene, friction).unwrap_or_else(|why| Err(why).into())
}

fn band_or_why(
    args: &Args,
    source: &CreepSource,
    scene: &Scene,
    friction: f64,
) -> Result<RollBand, String> {
    if args.no_bands {
        return Err("skipped (--no-bands)".into());
    }
    Ok(
        match crate::pipeline::point_band(source, scene, args.temp_c, friction) {
            Ok((b, notes)) => RollBand { band: Ok(b), notes },
            Err(why) => Err(why).into(),
        },
    )
}
