//! The hostile-input families of tests/hostile.rs that need the crate's internals (issue 28): the
//! work budget's edges (src/limits.rs: every size at its limit accepted, one beyond refused with the
//! key and the limit named) and CSV cells that would run as formulas. The seeded generator and the
//! seed are those of tests/seed.rs.

use crate::tests::seed::{scene_with, seed, Rng};
use std::path::Path;
use viscoroll::limits;

/// Budget edges: every size at its limit is accepted, one beyond is refused with the key and the
/// limit named (scenes TOML, Prony settings, `contact --n`, temperatures, names).
pub(crate) fn budget_edges(cases: usize, rng: &mut Rng) {
    use viscoroll::results::SceneSet;
    let at = Path::new("scenes.toml");
    for _ in 0..cases {
        let beyond = rng.below(2) == 1;
        let b = usize::from(beyond);
        let which = rng.below(6);
        let (text, key) = match which {
            0 => (
                scene_with("s", limits::SCENE_TEMPS_MAX + b, 0, 0, 0.0),
                "temps_c",
            ),
            1 => (
                scene_with("s", 2, limits::MAP_LIST_MAX + b, 1, 0.0),
                "map_temps_c",
            ),
            2 => {
                // map_temps × map_speeds at the cells limit (20 × 50 = 1000), or one row more
                let t = limits::MAP_CELLS_MAX / limits::MAP_LIST_MAX + b;
                (scene_with("s", 2, t, limits::MAP_LIST_MAX, 0.0), "cells")
            }
            3 => (
                scene_with(&"n".repeat(limits::NAME_CHARS_MAX + b), 2, 0, 0, 0.0),
                "name",
            ),
            4 => {
                // the set's work: scenes of 200 temperatures, the last one topping it up to the
                // limit (or one point beyond), 10 map cells in the first (2 points)
                let mut left = limits::SCENE_WORK_MAX + b - 2;
                let mut text = scene_with("m", 0, 0, 0, 0.0);
                text = text.replace("temps_c = []", "temps_c = [0.0]");
                left -= 1;
                text += "map_temps_c = [0.0]\nmap_speeds_m_s = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0]\n";
                let mut k = 0;
                while left > 0 {
                    let n = left.min(limits::SCENE_TEMPS_MAX);
                    text += &scene_with(&format!("s{k}"), n, 0, 0, 0.0);
                    left -= n;
                    k += 1;
                }
                (text, "work")
            }
            _ => (
                scene_with(
                    "s",
                    2,
                    0,
                    0,
                    100.0 * limits::COVER_OVER_RADIUS_MIN * if beyond { 0.5 } else { 1.0 },
                ),
                "cover_thickness_mm",
            ),
        };
        let r = SceneSet::parse(&text, at);
        match (beyond, r) {
            (false, Ok(_)) => {}
            (true, Err(e)) => {
                let e = e.to_string();
                assert!(e.contains(key), "{e}");
                assert!(e.len() < 400, "{e}");
            }
            (beyond, r) => panic!("{key} beyond={beyond}: {r:?}"),
        }
    }
    // Prony settings and the fit's term count.
    let mut p = viscoroll::prony::PronySettings {
        lambda_count: limits::PRONY_LAMBDA_COUNT_MAX,
        ..Default::default()
    };
    assert!(p.validate().is_ok());
    p.lambda_count = 1_000_000_000;
    let e = p.validate().unwrap_err().to_string();
    assert!(
        e.contains("lambda_count") && e.contains(&limits::PRONY_LAMBDA_COUNT_MAX.to_string()),
        "{e}"
    );
    p.lambda_count = 12;
    p.max_terms = Some(limits::PRONY_TERMS_MAX + 1 + rng.below(100_000));
    assert!(p.validate().unwrap_err().to_string().contains("max_terms"));
}

#[test]
fn sizes_at_the_limits_are_accepted_and_beyond_them_refused() {
    let mut rng = Rng(seed("hostile budget edges"));
    budget_edges(12, &mut rng);
}

/// The longer run (cargo test --lib hostile_budget -- --ignored).
#[test]
#[ignore = "hostile-input suite, long run: cargo test --lib hostile_budget -- --ignored"]
fn budget_edges_long_run() {
    let mut rng = Rng(seed("hostile budget long run"));
    budget_edges(400, &mut rng);
}

/// CSV cells that would run as formulas are neutralised (numbers stay numbers) and control
/// characters are escaped (crate::report::csv_text).
#[test]
fn hostile_strings_make_safe_csv_cells() {
    let mut rng = Rng(seed("hostile strings"));
    let starts = ['=', '+', '-', '@', '\t', '\r'];
    for _ in 0..50 {
        let mut s = String::from(*rng.pick(&starts));
        for _ in 0..rng.below(12) {
            s.push(char::from(32 + rng.below(95) as u8));
        }
        s.push(*rng.pick(&['a', '\u{1b}', '\u{7}', ')']));
        let c = viscoroll::report::csv_text::cell(&s);
        assert!(c.starts_with('\''), "{s:?} -> {c:?}");
        assert!(
            !c.chars().any(|ch| ch.is_control() && ch != '\n'),
            "{s:?} -> {c:?}"
        );
        let x = (rng.next() as f64 / u64::MAX as f64 - 0.5) * 1e6;
        assert_eq!(
            viscoroll::report::csv_text::cell(&format!("{x:e}")),
            format!("{x:e}")
        );
    }
}
