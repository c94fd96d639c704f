//! The work budget: every size of an input that sets the tool's time or memory lives here, with the
//! check that names the key and the limit. Inputs are checked where they enter (command line,
//! scenes TOML, compounds.toml, fit and measurement JSON), so that every accepted input finishes
//! within the budget's goal: under 60 s and 2 GB on 2 cores (issue 28).
//!
//! Input: a key (as the user wrote it: `--n`, `prony.lambda_count`, `scene[0] (x): map_temps_c`)
//! and a value; output: `Ok` or a [`LimitError`] worded for the user. Floor 0: imports nothing of
//! the crate. How each limit was set is noted at its constant.

use thiserror::Error;

/// Smoothing weights λ the Prony fit searches (`prony.lambda_count`, default 12): each is one QP
/// solve; 1e9 asked for a 32 GB allocation and aborted the run.
pub(crate) const PRONY_LAMBDA_COUNT_MAX: usize = 60;
/// Relaxation times of a Prony fit (terms per decade × decades of the master curve, or
/// `prony.max_terms`) and terms a fit file may carry: the QP is dense in the terms (cost ~ n³ per
/// iteration, memory ~ n² ); 5000 terms took > 60 s and 800 MB.
pub(crate) const PRONY_TERMS_MAX: usize = 400;
/// Intervals of the thesis collocation (`contact --n`): an n × n dense matrix (8 n² bytes, LU ~ n³,
/// one per step of the load loop); 20000 reached 3 GB, and 4000 (128 MB) took 498 s with the load
/// loop (debug binary, loaded machine: `cargo bench --bench budget_edges`), so 2000: 1/8 of that
/// work, 32 MB per matrix. The thesis' tables use n ≤ 320; the independent checks of the layer and
/// of the `auto` scheme use up to 1280.
pub(crate) const CONTACT_N_MAX: usize = 2000;
/// Scenes in one scenes TOML (each costs a friction curve and maps per compound).
pub(crate) const SCENES_MAX: usize = 64;
/// Temperatures of a scene's friction curve (`temps_c`), each a contact solve per compound.
pub(crate) const SCENE_TEMPS_MAX: usize = 200;
/// Entries of one friction-map list (`map_temps_c`, `map_speeds_m_s`, `map_loads_n_per_m`).
pub(crate) const MAP_LIST_MAX: usize = 50;
/// Map cells of one scene: map temperatures × (map speeds + map loads); 3 × 1000 ran over 60 s and
/// 1000 map temperatures wrote 234 MB for one compound.
pub(crate) const MAP_CELLS_MAX: usize = 1000;
/// Thinnest cover against the roll radius (h / R): thinner covers need a layer solve whose degree
/// grows with contact length / thickness (1e-9 mm ran over 60 s at 800 MB); 1e-4 of a 100 mm roll
/// is 10 µm, far below any real cover.
pub(crate) const COVER_OVER_RADIUS_MIN: f64 = 1e-4;
/// Work of one compound's scene set, in friction points: Σ over its scenes of `temps_c` plus the
/// map cells divided by [`MAP_CELLS_PER_POINT`]. The per-scene limits above do not bound the set:
/// 64 scenes × 200 temperatures on the thinnest cover ran for over 15 min. A friction point with
/// its band costs at most 0.43 s (thinnest cover, tol 1e-10, 200 points in 85 s; a half-space point
/// 0.07 s), measured with the unoptimised-crate debug binary with three processes on 2 cores, so
/// an upper bound; `cargo bench --bench budget_edges` measures the set at this limit.
pub(crate) const SCENE_WORK_MAX: usize = 250;
/// Map cells that cost one friction point: maps come from one interpolant per scene, and a cell
/// cost 1/5.5 of a point on the thinnest cover (1000 cells and 9 points in 61 s) and 1/9 on a
/// half-space (8.6 s).
pub(crate) const MAP_CELLS_PER_POINT: usize = 5;
/// Characters of a compound or scene name (they become file and folder names and table cells).
pub(crate) const NAME_CHARS_MAX: usize = 64;
/// Bytes of a DMA export, measurement JSON or fit file read (a 1e6-row CSV is ~50 MB).
pub(crate) const INPUT_BYTES_MAX: u64 = 256 << 20;
/// Bytes of a settings file (scenes TOML, compounds.toml).
pub(crate) const SETTINGS_BYTES_MAX: u64 = 4 << 20;
/// Absolute zero in °C: no temperature below it is accepted anywhere.
pub(crate) const ABSOLUTE_ZERO_C: f64 = -273.15;
/// Highest temperature accepted, °C (no polymer is used above it).
pub(crate) const TEMP_MAX_C: f64 = 1000.0;

/// An input beyond the work budget or outside its domain.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{key} = {value}: {reason}")]
pub struct LimitError {
    /// The key as the user wrote it.
    pub key: String,
    /// The value given (as text).
    pub value: String,
    /// The limit, in words.
    pub reason: String,
}

/// `value` ≤ `max`, else an error naming `key` and the limit.
pub(crate) fn at_most(key: &str, value: usize, max: usize) -> Result<(), LimitError> {
    if value <= max {
        return Ok(());
    }
    Err(LimitError {
        key: key.into(),
        value: value.to_string(),
        reason: format!("more than {max}, the limit of the work budget (crate::limits)"),
    })
}

/// A temperature in °C within [−273.15, 1000] and finite.
pub fn temperature_c(key: &str, t: f64) -> Result<(), LimitError> {
    if t.is_finite() && (ABSOLUTE_ZERO_C..=TEMP_MAX_C).contains(&t) {
        return Ok(());
    }
    Err(LimitError {
        key: key.into(),
        value: t.to_string(),
        reason: format!("not a temperature in °C in [{ABSOLUTE_ZERO_C}, {TEMP_MAX_C}]"),
    })
}

/// A name of at most [`NAME_CHARS_MAX`] characters, none of them a control character.
pub(crate) fn name(key: &str, s: &str) -> Result<(), LimitError> {
    let n = s.chars().count();
    let shown = || {
        s.chars()
            .take(20)
            .flat_map(char::escape_debug)
            .collect::<String>()
    };
    if n > NAME_CHARS_MAX {
        return Err(LimitError {
            key: key.into(),
            value: format!("\"{}…\" ({n} characters)", shown()),
            reason: format!("longer than {NAME_CHARS_MAX} characters"),
        });
    }
    if s.chars().any(char::is_control) {
        return Err(LimitError {
            key: key.into(),
            value: format!("\"{}\"", shown()),
            reason: "holds a control character".into(),
        });
    }
    Ok(())
}

/// A cover thickness against the roll radius (both in the same unit).
pub fn cover(key: &str, thickness: f64, radius: f64) -> Result<(), LimitError> {
    if thickness >= COVER_OVER_RADIUS_MIN * radius {
        return Ok(());
    }
    Err(LimitError {
        key: key.into(),
        value: thickness.to_string(),
        reason: format!(
            "thinner than {COVER_OVER_RADIUS_MIN:e} of the roll radius ({radius}), the thinnest cover the work budget solves"
        ),
    })
}

/// A friction map's cells: temperatures × (speeds + loads).
pub(crate) fn map_cells(
    key: &str,
    temps: usize,
    speeds: usize,
    loads: usize,
) -> Result<(), LimitError> {
    let cells = temps.saturating_mul(speeds.saturating_add(loads));
    at_most(key, cells, MAP_CELLS_MAX).map_err(|mut e| {
        e.value =
            format!("{temps} temperatures × ({speeds} speeds + {loads} loads) = {cells} cells");
        e
    })
}

/// The work of a scene set: `points` friction points (Σ `temps_c`) and `cells` map cells, against
/// [`SCENE_WORK_MAX`].
pub(crate) fn scene_work(key: &str, points: usize, cells: usize) -> Result<(), LimitError> {
    let work = points.saturating_add(cells.div_ceil(MAP_CELLS_PER_POINT));
    at_most(key, work, SCENE_WORK_MAX).map_err(|mut e| {
        e.value = format!(
            "{points} temperatures + {cells} map cells / {MAP_CELLS_PER_POINT} = {work} friction points per compound"
        );
        e
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_check_passes_at_its_limit_and_fails_beyond_naming_key_and_limit() {
        assert!(at_most("--n", CONTACT_N_MAX, CONTACT_N_MAX).is_ok());
        let e = at_most("--n", CONTACT_N_MAX + 1, CONTACT_N_MAX)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("--n") && e.contains(&CONTACT_N_MAX.to_string()),
            "{e}"
        );
        assert!(temperature_c("t", ABSOLUTE_ZERO_C).is_ok());
        assert!(temperature_c("t", TEMP_MAX_C).is_ok());
        for t in [-273.16, -1000.0, 1000.1, f64::NAN, f64::INFINITY] {
            assert!(temperature_c("--temp-c", t)
                .unwrap_err()
                .to_string()
                .contains("--temp-c"));
        }
        assert!(name("name", &"é".repeat(NAME_CHARS_MAX)).is_ok());
        let e = name("name", &"x".repeat(5000)).unwrap_err().to_string();
        assert!(e.contains("5000 characters") && e.len() < 200, "{e}");
        assert!(name("name", "a\u{1b}[31m").is_err());
        assert!(cover("h", 1e-4 * 100.0, 100.0).is_ok());
        assert!(cover("h", 1e-12, 100.0).is_err());
        assert!(map_cells("m", 20, 25, 25).is_ok());
        assert!(map_cells("m", 3, 1000, 0)
            .unwrap_err()
            .to_string()
            .contains("3000 cells"));
        assert!(map_cells("m", usize::MAX, usize::MAX, 1).is_err());
        assert!(scene_work("w", SCENE_WORK_MAX - 2, 2 * MAP_CELLS_PER_POINT).is_ok());
        let e = scene_work("w", SCENE_WORK_MAX, 1).unwrap_err().to_string();
        assert!(
            e.contains(&format!("= {} friction points", SCENE_WORK_MAX + 1)),
            "{e}"
        );
        assert!(scene_work("w", usize::MAX, usize::MAX).is_err());
    }
}
