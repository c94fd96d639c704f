//! Wall time of a repeated call, for the bench binaries that print tables (included by `#[path]`;
//! benches cannot share a library module otherwise). One warm-up call, then calls until
//! `MIN_TOTAL_S` has passed and at least `MIN_CALLS` were made; the table gives the median call
//! (robust to a call slowed by other load on a shared machine) and the fastest.
//!
//! Written here rather than taken from criterion: the three benches that used criterion only read
//! its mean, and criterion's own dependencies (a regex engine, a CBOR codec, a template engine) were
//! compiled by every `cargo test`, since dev-dependencies are built for the tests too.

use std::time::Instant;

/// Calls are repeated for at least this long, s.
const MIN_TOTAL_S: f64 = 2.0;
/// … and at least this many times.
const MIN_CALLS: usize = 10;

/// The timing of one repeated call.
pub struct Timing {
    /// Calls timed (after the warm-up call).
    pub calls: usize,
    /// Median wall time of one call, s.
    pub median_s: f64,
    /// Fastest call, s.
    pub min_s: f64,
}

/// Times `f` as the module doc says; its result is passed to `black_box` so it is not optimised away.
pub fn time<R>(mut f: impl FnMut() -> R) -> Timing {
    std::hint::black_box(f());
    let start = Instant::now();
    let mut each = Vec::new();
    while each.len() < MIN_CALLS || start.elapsed().as_secs_f64() < MIN_TOTAL_S {
        let t = Instant::now();
        std::hint::black_box(f());
        each.push(t.elapsed().as_secs_f64());
    }
    each.sort_by(f64::total_cmp);
    Timing {
        calls: each.len(),
        median_s: each[each.len() / 2],
        min_s: each[0],
    }
}

/// The table's header.
pub fn header(title: &str) {
    println!("{title}\n\n| case | calls | median | fastest |\n| --- | --- | --- | --- |");
}

/// One row of the table: `name` timed by [`time`].
pub fn row<R>(name: &str, f: impl FnMut() -> R) {
    let t = time(f);
    println!(
        "| {name} | {} | {:.3} ms | {:.3} ms |",
        t.calls,
        1e3 * t.median_s,
        1e3 * t.min_s
    );
}
