//! Axis ticks of the report's plots: 1-2-5 steps on linear axes, decades (with 2 and 5 inside short
//! spans) on log axes, and tick labels a reader takes in at a glance (`0.02`, `500`, `10⁻⁴`, `2·10⁵`,
//! never `3.98e-4` or `5012`).
//!
//! Input: an axis range; output: tick positions (in the axis' own coordinate: the value on a linear
//! axis, log10 of the value on a log axis) and their labels. Pure functions, no drawing.

/// Most ticks wanted on an axis (fewer is fine, at least two when the range allows).
const MAX_TICKS: usize = 9;

/// Ticks on a linear axis over [lo, hi]: multiples of the smallest step in {1, 2, 5}·10ᵏ that
/// gives at most `MAX_TICKS` ticks (empty for an empty or non-finite range).
pub(crate) fn linear_ticks(lo: f64, hi: f64) -> Vec<f64> {
    ticks_of_step(lo, hi, |_| true)
}

/// Multiples of the smallest step in {1, 2, 5}·10ᵏ over [lo, hi] that give at most [`MAX_TICKS`]
/// ticks and that `accept` takes (empty for an empty or non-finite range).
fn ticks_of_step(lo: f64, hi: f64, accept: impl Fn(&[f64]) -> bool) -> Vec<f64> {
    if !(lo.is_finite() && hi.is_finite() && hi > lo) {
        return vec![];
    }
    let span = hi - lo;
    let mut k = (span / MAX_TICKS as f64).log10().floor() as i32 - 1;
    loop {
        for m in [1.0, 2.0, 5.0] {
            let step = m * 10f64.powi(k);
            let first = (lo / step).ceil();
            let last = (hi / step).floor();
            if last - first + 1.0 <= MAX_TICKS as f64 {
                // multiples of the step, rounded to the step's decimals so labels print exactly
                let t: Vec<f64> = (first as i64..=last as i64)
                    .map(|i| round_to_step(i as f64 * step, step))
                    .collect();
                if t.len() < 2 || accept(&t) {
                    return t;
                }
            }
        }
        k += 1;
    }
}

fn round_to_step(v: f64, step: f64) -> f64 {
    let decimals = (-step.log10().floor()).max(0.0) as i32;
    let s = 10f64.powi(decimals);
    (v * s).round() / s
}

/// Ticks on a log axis whose range is [lo, hi] in log10 of the value: decades (every 2nd, 5th,
/// 10th… decade over a wide span), with the 2 and 5 of each decade added when the span is under
/// three decades. Under one decade: the 1, 2 and 5 of each decade when they give at least three
/// ticks, else linear 1-2-5 ticks of the values (6000, 7000, 8000 or 1020, 1040 …), with a step
/// large enough that no two ticks stand closer than a tenth of the axis (linear ticks crowd at
/// the top of a log axis). Returned as log10 of the tick values.
pub(crate) fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
    if !(lo.is_finite() && hi.is_finite() && hi > lo) {
        return vec![];
    }
    let span = hi - lo;
    let (d0, d1) = (lo.floor() as i64, hi.ceil() as i64);
    let within = |m: &[f64]| {
        (d0..=d1)
            .flat_map(|d| m.iter().map(move |m| d as f64 + m.log10()))
            .filter(|t| *t >= lo - 1e-9 && *t <= hi + 1e-9)
            .count()
    };
    if span < 1.0 && within(&[1.0, 2.0, 5.0]) < 3 {
        let apart = |t: &[f64]| {
            t.windows(2)
                .all(|w| w[0] > 0.0 && (w[1] / w[0]).log10() >= 0.1 * span)
        };
        return ticks_of_step(10f64.powf(lo), 10f64.powf(hi), apart)
            .into_iter()
            .filter(|v| *v > 0.0)
            .map(f64::log10)
            .collect();
    }
    let mantissas: &[f64] = if span < 3.0 { &[1.0, 2.0, 5.0] } else { &[1.0] };
    let every = if mantissas.len() > 1 {
        1
    } else {
        // decades per tick: 1, 2, 5, 10, 20 … so that at most MAX_TICKS remain
        let mut e = 1i64;
        let mut i = 0;
        while (span / e as f64) > MAX_TICKS as f64 - 1.0 {
            e = [1, 2, 5][(i + 1) % 3] * 10i64.pow(((i + 1) / 3) as u32);
            i += 1;
        }
        e
    };
    let mut v = Vec::new();
    for d in d0..=d1 {
        if d.rem_euclid(every) != 0 {
            continue;
        }
        for m in mantissas {
            let t = d as f64 + m.log10();
            if t >= lo - 1e-9 && t <= hi + 1e-9 {
                v.push(t);
            }
        }
    }
    v
}

/// Superscript digits of an integer exponent (`-4` → `⁻⁴`).
fn superscript(n: i64) -> String {
    n.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            _ => '⁹',
        })
        .collect()
}

/// The label of a tick value: plain decimals in [0.001, 1e5) (`0.02`, `2.5`, `500`, `20000`),
/// else `10ⁿ` or `m·10ⁿ` with the mantissa to three significant digits.
pub(crate) fn tick_label(v: f64) -> String {
    let a = v.abs();
    if !v.is_finite() {
        return String::new();
    }
    if a < 1e-300 {
        return "0".into();
    }
    if (1e-3..1e5).contains(&a) {
        // at most 4 significant digits, trailing zeros cut
        let decimals = (3 - a.log10().floor() as i32).clamp(0, 6) as usize;
        let t = format!("{v:.decimals$}");
        return if t.contains('.') {
            t.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            t
        };
    }
    let mut e = a.log10().floor() as i64;
    let mut m = v / 10f64.powi(e as i32);
    if (m.abs() - 10.0).abs() < 1e-9 {
        m /= 10.0;
        e += 1;
    }
    let sign = if v < 0.0 { "-" } else { "" };
    if (m.abs() - 1.0).abs() < 1e-9 {
        format!("{sign}10{}", superscript(e))
    } else {
        let mt = format!("{:.2}", m.abs());
        let mt = mt.trim_end_matches('0').trim_end_matches('.');
        format!("{sign}{mt}·10{}", superscript(e))
    }
}

/// The label of a tick on a log axis (position = log10 of the value).
pub(crate) fn log_tick_label(log10_v: f64) -> String {
    tick_label(10f64.powf(log10_v))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every tick's mantissa (value / 10^floor(log10 value)) is 1, 2 or 5.
    fn is_125(v: f64) -> bool {
        if v == 0.0 {
            return true;
        }
        let m = v.abs() / 10f64.powf(v.abs().log10().floor());
        [1.0, 2.0, 5.0, 10.0].iter().any(|k| (m - k).abs() < 1e-9)
    }

    #[test]
    fn linear_ticks_step_in_1_2_5_and_cover_the_range() {
        for (lo, hi) in [
            (-40.0, 40.0),
            (-43.7, 61.2),
            (0.0, 1.0),
            (2.3e-4, 4.1e-4),
            (1000.0, 6310.0),
            (-0.013, 0.002),
        ] {
            let t = linear_ticks(lo, hi);
            assert!(t.len() >= 2 && t.len() <= MAX_TICKS, "{lo}..{hi}: {t:?}");
            assert!(t.iter().all(|v| *v >= lo && *v <= hi), "{lo}..{hi}: {t:?}");
            let step = t[1] - t[0];
            assert!(is_125(step), "{lo}..{hi}: step {step}");
            // the step is the smallest 1-2-5 step that fits: a step one notch finer would give too many
            assert!(t
                .windows(2)
                .all(|w| ((w[1] - w[0]) - step).abs() < 1e-9 * step));
        }
        assert_eq!(
            linear_ticks(-40.0, 40.0),
            [-40.0, -30.0, -20.0, -10.0, 0.0, 10.0, 20.0, 30.0, 40.0]
        );
        assert!(linear_ticks(1.0, 1.0).is_empty());
        assert!(linear_ticks(f64::NAN, 1.0).is_empty());
    }

    #[test]
    fn log_ticks_are_decades_or_1_2_5_within_short_spans() {
        // 20 decades: every 5th decade (every 2nd would give 11 ticks)
        let t = log_ticks(-10.2, 9.7);
        assert_eq!(t, [-10.0, -5.0, 0.0, 5.0]);
        // 1.5 decades: 1, 2, 5 of each decade
        let t: Vec<f64> = log_ticks((2.3e-4f64).log10(), (6.1e-3f64).log10())
            .iter()
            .map(|l| 10f64.powf(*l))
            .collect();
        assert_eq!(t.len(), 4, "{t:?}"); // 5·10⁻⁴, 10⁻³, 2·10⁻³, 5·10⁻³
        assert!(t.iter().all(|v| is_125(*v)), "{t:?}");
        // under a decade: 1, 2, 5 when they give three ticks, else linear
        // 1-2-5 steps of the values, no two ticks closer than a tenth of the axis: 1000 … 3000 by
        // 500, 6000 … 9000 by 1000 (by 500, 9000 and 9500 would touch), 1000 … 1120 by 20, and
        // 10000 … 40000 by 10000 (by 5000, 35000 and 40000 would touch)
        let values = |lo: f64, hi: f64| -> Vec<f64> {
            log_ticks(lo, hi).iter().map(|l| 10f64.powf(*l)).collect()
        };
        let v = values(-3.0, -2.1); // 10⁻³, 2·10⁻³, 5·10⁻³
        assert!(v.len() == 3 && v.iter().all(|x| is_125(*x)), "{v:?}");
        for (lo, hi, step) in [
            (3.0, 3.5, 500.0),
            (3.75, 3.99, 1000.0),
            (3.0, 3.05, 20.0),
            (4.0, 40000f64.log10(), 10000.0),
        ] {
            let v = values(lo, hi);
            assert!(v.len() >= 3, "{lo}..{hi}: {v:?}");
            for w in v.windows(2) {
                assert!(
                    (w[1] - w[0] - step).abs() < 1e-9 * step,
                    "{lo}..{hi}: {v:?}"
                );
            }
            assert!(v
                .iter()
                .all(|x| (x / step - (x / step).round()).abs() < 1e-9));
            assert!(v
                .windows(2)
                .all(|w| (w[1] / w[0]).log10() >= 0.1 * (hi - lo)));
            // the labels are the plain multiples (no 5623.41…)
            for t in log_ticks(lo, hi) {
                let l = log_tick_label(t);
                assert!(l.len() <= 5 && !l.contains('·'), "{l}");
            }
        }
        // 6 decades: each decade
        assert_eq!(log_ticks(-0.5, 5.5).len(), 6);
    }

    #[test]
    fn labels_are_short_and_exact() {
        for (v, s) in [
            (0.02, "0.02"),
            (500.0, "500"),
            (20000.0, "20000"),
            (2.5, "2.5"),
            (1e-4, "10⁻⁴"),
            (2e5, "2·10⁵"),
            (1e9, "10⁹"),
            (-40.0, "-40"),
            (0.0, "0"),
            (0.001, "0.001"),
        ] {
            assert_eq!(tick_label(v), s, "{v}");
        }
        // log positions come back to exact labels despite 10^x rounding
        assert_eq!(log_tick_label(-4.0), "10⁻⁴");
        assert_eq!(log_tick_label((5e-4f64).log10()), "5·10⁻⁴");
        assert_eq!(log_tick_label(3.0), "1000");
    }
}
