//! src/special against high-precision reference values (tests/data/special_reference.csv, written once
//! by tools/gen_special_reference.py with mpmath at 120 digits; CI does not need Python).
//!
//! Print the accuracy table (max relative error per function and range):
//! `cargo test --release --test tests special_accuracy_table -- --nocapture`

use viscoroll::special::{
    e1, ei, exp_e1, expm_ei, kernel_bracket, kernel_bracket_int1, kernel_bracket_int2, EULER_GAMMA,
};

const TABLE: &str = include_str!("data/special_reference.csv");

struct Row {
    func: String,
    x: f64,
    value: f64,
}

fn table() -> Vec<Row> {
    TABLE
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("function"))
        .map(|l| {
            let mut it = l.split(',');
            let func = it.next().unwrap().to_string();
            let x: f64 = it.next().unwrap().parse().unwrap();
            let value: f64 = it.next().unwrap().parse().unwrap();
            Row { func, x, value }
        })
        .collect()
}

fn eval(func: &str, x: f64) -> f64 {
    match func {
        "e1" => e1(x),
        "exp_e1" => exp_e1(x),
        "ei" => ei(x),
        "expm_ei" => expm_ei(x),
        "h" => kernel_bracket(x),
        "h1" => kernel_bracket_int1(x),
        "h2" => kernel_bracket_int2(x),
        other => panic!("unknown function {other} in the reference table"),
    }
}

/// Size of the largest piece of the closed form of h, H₁, H₂ at x (L = γ + ln|x|): near the negative
/// zeros of these functions only an absolute error of a few ulp of this size can be asked for.
fn piece_scale(func: &str, x: f64) -> f64 {
    let l = EULER_GAMMA + x.abs().ln();
    let g = if x > 0.0 { exp_e1(x) } else { -expm_ei(-x) };
    let base = l.abs().max(g.abs());
    match func {
        "h" => base,
        "h1" => base.max((x * (l - 1.0)).abs()),
        _ => base
            .max((x * (l - 1.0)).abs())
            .max((0.5 * x * x * (l - 1.5)).abs()),
    }
}

fn range_label(x: f64) -> &'static str {
    let a = x.abs();
    match (x > 0.0, a) {
        (true, a) if a < 1e-3 => "(1e-12, 1e-3)",
        (true, a) if a < 1.0 => "[1e-3, 1)",
        (true, a) if a < 45.0 => "[1, 45)",
        (true, _) => "[45, 1e12]",
        (false, a) if a < 1e-3 => "-(1e-12, 1e-3)",
        (false, a) if a < 1.0 => "-[1e-3, 1)",
        (false, a) if a < 45.0 => "-[1, 45)",
        (false, _) => "-[45, 1e12]",
    }
}

/// Relative error, except near a zero of h, H₁, H₂ on the negative axis, where the error is measured
/// relative to the size of the cancelling pieces (what a double can resolve there).
fn error_of(row: &Row) -> f64 {
    let got = eval(&row.func, row.x);
    let rel = ((got - row.value) / row.value).abs();
    if matches!(row.func.as_str(), "h" | "h1" | "h2") && row.x < -1.0 && row.x > -4.0 {
        let abs_scaled = (got - row.value).abs() / piece_scale(&row.func, row.x);
        rel.min(abs_scaled)
    } else {
        rel
    }
}

/// Every tabled value to 1e-14 relative (a few dozen ulp: the target).
#[test]
fn special_functions_match_reference_table() {
    let rows = table();
    assert!(
        rows.len() > 5000,
        "reference table truncated: {} rows",
        rows.len()
    );
    let mut worst: Option<(f64, &Row)> = None;
    for row in &rows {
        let err = error_of(row);
        assert!(!err.is_nan(), "NaN for {}({})", row.func, row.x);
        if worst.is_none_or(|(w, _)| err > w) {
            worst = Some((err, row));
        }
    }
    let (err, row) = worst.unwrap();
    assert!(
        err <= 1e-14,
        "worst: {}({:e}) = {} vs {} (error {err:e})",
        row.func,
        row.x,
        eval(&row.func, row.x),
        row.value
    );
}

/// Prints max relative error per function and range (run with --nocapture).
#[test]
fn special_accuracy_table() {
    let rows = table();
    let mut acc: std::collections::BTreeMap<(String, &str), (f64, f64, usize)> = Default::default();
    for row in &rows {
        let err = error_of(row);
        let e = acc
            .entry((row.func.clone(), range_label(row.x)))
            .or_insert((0.0, 0.0, 0));
        if err > e.0 {
            e.0 = err;
            e.1 = row.x;
        }
        e.2 += 1;
    }
    println!(
        "{:<8} {:<16} {:>6} {:>10} {:>12}",
        "function", "x range", "points", "max err", "at x"
    );
    for ((f, r), (err, x, n)) in &acc {
        println!("{f:<8} {r:<16} {n:>6} {err:>10.2e} {x:>12.5e}");
    }
}
