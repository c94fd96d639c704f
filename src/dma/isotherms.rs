//! Split the points of one file into isothermal frequency sweeps and give each its nominal (set) and
//! mean measured temperature. [`RawPoint`]s → [`Group`]s.
//!
//! A new isotherm starts at a new block (TRIOS step, RheoCompass interval), a new segment number or
//! set temperature, where the measured temperature jumps by more than `split_jump_k` from the
//! previous point, or where the frequency turns back against the sweep direction (EPLEXOR exports
//! have no segment column) while the measured temperature has moved by more than `same_temp_k` from
//! the mean of the sweep so far. A frequency that turns back at the same temperature stays in the
//! sweep and is flagged by the checks, not split off. Measured temperatures drift by several kelvin
//! within one step (up to 3.1 K in the shared `dmasuite-tensile` data), which a gradual drift between
//! consecutive points does not mistake for a new step.
//!
//! The nominal temperature is, in order: the set temperature the file states (step name, set
//! temperature column), the temperature in the file name (`T25.txt`, `25C.csv`) when the file holds
//! one isotherm; else, for three or more isotherms, the nearest point of the file's temperature step
//! grid (step Δ = median spacing of the sorted means rounded to 0.5 K, origin = median of
//! mean_i − k_i·Δ rounded to 0.5 K; source `step grid`); else the mean measured temperature rounded to
//! 0.5 K (`rounded mean`). Rounding each mean alone is not enough: EPLEXOR's 17.5 °C step of the
//! shared data has a mean of 17.85 °C.

use super::columns::RawPoint;

/// Settings of the split.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SplitSettings {
    /// A jump of the measured temperature between consecutive points larger than this (K) starts a
    /// new isotherm. Default 3 K: above the point-to-point drift seen in real exports (≤ 1.7 K in
    /// `dmasuite-tensile`), below the smallest step in use (5 K).
    pub split_jump_k: f64,
    /// A frequency turning back starts a new isotherm only if the temperature has moved more than
    /// this (K) from the sweep's mean. Default 1 K.
    pub same_temp_k: f64,
}

impl Default for SplitSettings {
    fn default() -> Self {
        SplitSettings {
            split_jump_k: 3.0,
            same_temp_k: 1.0,
        }
    }
}

/// One isotherm before checks.
#[derive(Debug, Clone)]
pub struct Group {
    /// Its points, in file order.
    pub points: Vec<RawPoint>,
    /// Nominal temperature in °C.
    pub nominal_c: f64,
    /// Where the nominal came from: `file`, `file name`, `rounded mean`.
    pub nominal_source: &'static str,
    /// Mean measured temperature in °C (nominal if none measured).
    pub mean_c: f64,
}

/// Temperature written as the whole file stem: `T25`, `T-10`, `t_5`, `25C`, `25°C`, `T25C`.
pub(crate) fn temperature_from_file_name(path: &str) -> Option<f64> {
    let stem = std::path::Path::new(path).file_stem()?.to_str()?;
    let s = stem
        .strip_prefix(['T', 't'])
        .map(|s| s.strip_prefix('_').unwrap_or(s))
        .unwrap_or(stem);
    let s = s
        .strip_suffix("°C")
        .or_else(|| s.strip_suffix("degC"))
        .or_else(|| s.strip_suffix('C'))
        .unwrap_or(s);
    if s.is_empty() || s == stem && !stem.ends_with('C') {
        return None;
    }
    let ok = s
        .chars()
        .enumerate()
        .all(|(i, c)| c.is_ascii_digit() || c == '.' || (i == 0 && c == '-'));
    if !ok {
        return None;
    }
    s.parse::<f64>().ok()
}

/// Split one file's points into isotherms.
pub fn split(points: Vec<RawPoint>, name_temp_c: Option<f64>, set: &SplitSettings) -> Vec<Group> {
    // Sweep direction from the majority of consecutive steps (most exports sweep upwards; rotational
    // rheometers often downwards).
    let (mut up, mut down) = (0usize, 0usize);
    for w in points.windows(2) {
        if w[0].block == w[1].block {
            if w[1].freq_hz > w[0].freq_hz {
                up += 1;
            } else if w[1].freq_hz < w[0].freq_hz {
                down += 1;
            }
        }
    }
    let ascending = up >= down;
    let mut groups: Vec<Vec<RawPoint>> = Vec::new();
    let mut cur: Vec<RawPoint> = Vec::new();
    let (mut sum_t, mut n_t) = (0.0, 0usize);
    for p in points {
        let new = match cur.last() {
            None => false,
            Some(prev) => {
                let seg_change = p.segment != prev.segment;
                let nominal_change = match (p.nominal_c, prev.nominal_c) {
                    (Some(a), Some(b)) => a != b,
                    (a, b) => a.is_some() != b.is_some(),
                };
                let jump = match (p.temp_c, prev.temp_c) {
                    (Some(a), Some(b)) => (a - b).abs() > set.split_jump_k,
                    _ => false,
                };
                let turned = if ascending {
                    p.freq_hz < prev.freq_hz
                } else {
                    p.freq_hz > prev.freq_hz
                };
                let labelled = p.segment.is_some() || p.nominal_c.is_some();
                let moved = match p.temp_c {
                    Some(t) if n_t > 0 => (t - sum_t / n_t as f64).abs() > set.same_temp_k,
                    _ => true,
                };
                p.block != prev.block
                    || seg_change
                    || nominal_change
                    || jump
                    || (!labelled && turned && moved)
            }
        };
        if new {
            groups.push(std::mem::take(&mut cur));
            sum_t = 0.0;
            n_t = 0;
        }
        if let Some(t) = p.temp_c.filter(|t| t.is_finite()) {
            sum_t += t;
            n_t += 1;
        }
        cur.push(p);
    }
    if !cur.is_empty() {
        groups.push(cur);
    }
    let single = groups.len() == 1;
    groups
        .into_iter()
        .map(|pts| {
            let temps: Vec<f64> = pts
                .iter()
                .filter_map(|p| p.temp_c)
                .filter(|t| t.is_finite())
                .collect();
            let mean = (!temps.is_empty()).then(|| temps.iter().sum::<f64>() / temps.len() as f64);
            let stated = pts.iter().find_map(|p| p.nominal_c);
            let (nominal_c, nominal_source) = match (stated, name_temp_c.filter(|_| single), mean) {
                (Some(t), _, _) => (t, "file"),
                (None, Some(t), _) => (t, "file name"),
                (None, None, Some(m)) => ((m * 2.0).round() / 2.0, "rounded mean"),
                // No temperature at all: the caller refuses such files before splitting.
                (None, None, None) => (f64::NAN, "none"),
            };
            Group {
                mean_c: mean.unwrap_or(nominal_c),
                nominal_c,
                nominal_source,
                points: pts,
            }
        })
        .collect()
}

/// The temperature step grid (origin, step Δ) of a set of isotherm means, both rounded to 0.5 K
/// (see the module docs); `None` for fewer than three isotherms or a spacing below 0.5 K.
pub(crate) fn step_grid(means: &[f64]) -> Option<(f64, f64)> {
    if means.len() < 3 || means.iter().any(|m| !m.is_finite()) {
        return None;
    }
    let half = |x: f64| (x * 2.0).round() / 2.0;
    let mut means = means.to_vec();
    means.sort_by(f64::total_cmp);
    let mut diffs: Vec<f64> = means.windows(2).map(|w| w[1] - w[0]).collect();
    diffs.sort_by(f64::total_cmp);
    let step = half(diffs[diffs.len() / 2]);
    if step < 0.5 {
        return None;
    }
    let mut origins: Vec<f64> = means
        .iter()
        .map(|m| m - ((m - means[0]) / step).round() * step)
        .collect();
    origins.sort_by(f64::total_cmp);
    Some((half(origins[origins.len() / 2]), step))
}

/// The grid point nearest to `t`.
pub(crate) fn on_grid(t: f64, (origin, step): (f64, f64)) -> f64 {
    origin + ((t - origin) / step).round() * step
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dma::table::Loc;

    fn pt(f: f64, t: f64) -> RawPoint {
        RawPoint {
            loc: Loc::Line(1),
            block: 0,
            freq_hz: f,
            storage_pa: 1.0,
            loss_pa: 1.0,
            temp_c: Some(t),
            nominal_c: None,
            segment: None,
            missing: vec![],
        }
    }

    #[test]
    fn splits_where_frequency_drops_back_at_a_new_temperature() {
        let mut pts = Vec::new();
        for (k, t) in [-50.0, -42.5, -35.0].iter().enumerate() {
            for (i, f) in [0.1, 1.0, 10.0].iter().enumerate() {
                // Drift of 0.4 K within a sweep.
                pts.push(pt(*f, t + 0.2 * i as f64 - 0.1 * k as f64));
            }
        }
        let g = split(pts, None, &SplitSettings::default());
        assert_eq!(g.len(), 3);
        assert_eq!(g[1].nominal_c, -42.5);
        assert_eq!(g[1].nominal_source, "rounded mean");
        // A mean 0.35 K above its step rounds to the wrong half-kelvin but sits on the grid.
        let grid = step_grid(&[-49.9, -42.15, -35.0, -27.4]).unwrap();
        assert_eq!(grid, (-50.0, 7.5));
        assert_eq!(on_grid(-42.15, grid), -42.5);
        assert_eq!(step_grid(&[20.0, 20.1, 20.2]), None);
        // A repeated frequency at the same temperature is not a new isotherm.
        let pts = vec![pt(0.1, 20.0), pt(1.0, 20.1), pt(0.5, 20.2), pt(10.0, 20.1)];
        assert_eq!(split(pts, Some(20.0), &SplitSettings::default()).len(), 1);
    }

    #[test]
    fn reads_temperatures_from_file_names() {
        assert_eq!(temperature_from_file_name("data/T0.txt"), Some(0.0));
        assert_eq!(temperature_from_file_name("T105.txt"), Some(105.0));
        assert_eq!(temperature_from_file_name("T-10.csv"), Some(-10.0));
        assert_eq!(temperature_from_file_name("25C.csv"), Some(25.0));
        assert_eq!(temperature_from_file_name("freq_user_raw.csv"), None);
        assert_eq!(temperature_from_file_name("Test.csv"), None);
        assert_eq!(temperature_from_file_name("25.csv"), None);
    }
}
