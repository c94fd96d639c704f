//! Issue 15's large-file figures: a CSV of 1e6 rows in 2 isotherms (the rubber-like export of
//! tests/pipeline_hardening.rs), timed through the CLI as a user runs it, with peak memory from
//! `/usr/bin/time -v` (GNU time; without it only the wall time is printed).
//!
//! `cargo bench --bench large_input` prints one table row per command:
//! `viscoroll ingest FILE` (target ≤ 5 s) and `viscoroll run DIR` (ingest, master curve, Prony fit
//! and 3 scenes; target for the fit ≤ 10 s in ≤ 1 GB). Rows per isotherm: `LARGE_ROWS` (default
//! 500000).

use std::path::Path;
use std::process::Command;
use std::time::Instant;

/// The export of `rubber_csv` in tests/pipeline_hardening.rs: E∞ = 1 MPa, one 100 MPa term at 1 ms,
/// a weak power law, WLF shifts about 20 °C; `n` log-spaced frequencies 0.1–100 Hz per temperature.
fn write_csv(path: &Path, temps_c: &[f64], n: usize) {
    use std::io::Write as _;
    let mut w = std::io::BufWriter::new(std::fs::File::create(path).unwrap());
    writeln!(w, "temperature [°C],frequency [Hz],E' [Pa],E'' [Pa]").unwrap();
    for &t in temps_c {
        let a_t = 10f64.powf(-8.0 * (t - 20.0) / (100.0 + t - 20.0));
        for k in 0..n {
            let f = 10f64.powf(-1.0 + 3.0 * k as f64 / (n - 1).max(1) as f64);
            let w_r = 2.0 * std::f64::consts::PI * f * a_t;
            let x = w_r * 1e-3;
            let e1 = 1e6 + 1e8 * x * x / (1.0 + x * x) + 1e6 * w_r.powf(0.2);
            let e2 = 1e8 * x / (1.0 + x * x) + 2e5 * w_r.powf(0.2);
            writeln!(w, "{t},{f:.6e},{e1:.6e},{e2:.6e}").unwrap();
        }
    }
}

/// Run `args` under `/usr/bin/time -v` when present: (wall s, user s, peak RSS MB, success).
fn measure(args: &[&std::ffi::OsStr]) -> (f64, f64, f64, bool) {
    let bin = env!("CARGO_BIN_EXE_viscoroll");
    let gnu_time = Path::new("/usr/bin/time").is_file();
    let mut c = if gnu_time {
        let mut c = Command::new("/usr/bin/time");
        c.arg("-v").arg(bin);
        c
    } else {
        Command::new(bin)
    };
    let t = Instant::now();
    let o = c.args(args).output().expect("viscoroll runs");
    let wall = t.elapsed().as_secs_f64();
    let err = String::from_utf8_lossy(&o.stderr);
    let field = |name: &str| {
        err.lines()
            .find_map(|l| l.trim().strip_prefix(name)?.trim().parse::<f64>().ok())
            .unwrap_or(f64::NAN)
    };
    (
        wall,
        field("User time (seconds):"),
        field("Maximum resident set size (kbytes):") / 1024.0,
        o.status.success(),
    )
}

fn main() {
    let n: usize = std::env::var("LARGE_ROWS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(500_000);
    let dir = std::env::temp_dir().join(format!("viscoroll-large-{}", std::process::id()));
    let input = dir.join("in");
    std::fs::create_dir_all(&input).unwrap();
    let csv = input.join("large.csv");
    write_csv(&csv, &[0.0, 40.0], n);
    let mb = std::fs::metadata(&csv).unwrap().len() as f64 / 1e6;
    println!(
        "{} rows in 2 isotherms, {mb:.1} MB; load average {}",
        2 * n,
        std::fs::read_to_string("/proc/loadavg")
            .unwrap_or_default()
            .trim()
    );
    println!("| command | wall s | user s | peak RSS MB | ok |");
    println!("|---|---|---|---|---|");
    let out = dir.join("out");
    let runs: [(&str, Vec<std::ffi::OsString>); 2] = [
        ("viscoroll ingest FILE", vec![csv.as_os_str().into()]),
        (
            "viscoroll run DIR (ingest + fit + 3 scenes)",
            vec![
                std::ffi::OsString::from("run"),
                input.as_os_str().into(),
                "--out".into(),
                out.as_os_str().into(),
            ],
        ),
    ];
    for (name, args) in runs {
        let refs: Vec<&std::ffi::OsStr> = args.iter().map(|a| a.as_os_str()).collect();
        let (wall, user, rss, ok) = measure(&refs);
        println!("| {name} | {wall:.2} | {user:.2} | {rss:.0} | {ok} |");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
