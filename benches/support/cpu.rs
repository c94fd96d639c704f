//! CPU time for the bench binaries that print tables (included by `#[path]`; benches cannot share a
//! library module otherwise). On a shared machine the wall time moves with the other load, the CPU
//! time much less; a 2-thread job's CPU / 2 is what it takes on two idle cores.

/// CPU time of this process so far (user + system, every thread), s: fields 14 and 15 of
/// /proc/self/stat in clock ticks (100 per second on Linux); NaN where it cannot be read.
pub fn cpu_s() -> f64 {
    let Ok(stat) = std::fs::read_to_string("/proc/self/stat") else {
        return f64::NAN;
    };
    // The command name (field 2) may hold spaces: count from the closing parenthesis.
    let rest = stat.rsplit_once(')').map_or("", |r| r.1);
    let f: Vec<f64> = rest
        .split_whitespace()
        .skip(11)
        .take(2)
        .filter_map(|v| v.parse().ok())
        .collect();
    if f.len() == 2 {
        (f[0] + f[1]) / 100.0
    } else {
        f64::NAN
    }
}
