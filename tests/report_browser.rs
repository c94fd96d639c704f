//! The report pages in a real browser, where Chromium is installed (CI need not have it: the check
//! skips with a note). [`check_pages`] is called by `pipeline_cli` on the output of its main job on
//! the shipped data (no second run): for a datasheet and the index it takes a 1400 × 900 screenshot
//! (the first screen; kept in the output folder to look at), checks the page logged no console
//! message (no JavaScript and no resource error: every plot is inline SVG), and reads the DOM
//! Chromium built to check the first screen's content came through the parser.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// The Chromium executable, if any.
fn chromium() -> Option<PathBuf> {
    [
        "/usr/bin/chromium",
        "/usr/bin/chromium-browser",
        "/usr/bin/google-chrome",
    ]
    .iter()
    .map(PathBuf::from)
    .find(|p| p.is_file())
}

/// Run headless Chromium on `page` with `args`; (stdout, stderr). Waits at most 90 s.
fn headless(exe: &Path, page: &Path, profile: &Path, args: &[String]) -> (String, String) {
    let out = profile.with_extension("out");
    let err = profile.with_extension("err");
    let mut child = Command::new(exe)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--hide-scrollbars",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--enable-logging=stderr",
            "--v=0",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(args)
        .arg(format!("file://{}", page.canonicalize().unwrap().display()))
        .stdout(Stdio::from(std::fs::File::create(&out).unwrap()))
        .stderr(Stdio::from(std::fs::File::create(&err).unwrap()))
        .spawn()
        .expect("chromium starts");
    for _ in 0..900 {
        if child.try_wait().unwrap().is_some() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(100));
    }
    if child.try_wait().unwrap().is_none() {
        let _ = child.kill();
        let _ = child.wait();
        panic!("chromium did not finish {page:?} in 90 s");
    }
    (
        std::fs::read_to_string(&out).unwrap_or_default(),
        std::fs::read_to_string(&err).unwrap_or_default(),
    )
}

/// Lines of Chromium's log that report a message of the page (console output, uncaught errors,
/// files that failed to load).
fn page_messages(stderr: &str) -> Vec<&str> {
    stderr
        .lines()
        .filter(|l| {
            l.contains(":CONSOLE")
                || l.contains("Uncaught")
                || l.contains("net::ERR_FILE_NOT_FOUND")
        })
        .collect()
}

/// Screenshot `page` at 1400 × 900 into `png`, check its console is silent and its DOM holds
/// every one of `needles`.
fn check_page(exe: &Path, page: &Path, png: &Path, needles: &[&str]) {
    let profile = png.with_extension("profile");
    let (_, err) = headless(
        exe,
        page,
        &profile,
        &[
            "--window-size=1400,900".into(),
            format!("--screenshot={}", png.display()),
        ],
    );
    let bytes = std::fs::read(png).unwrap_or_default();
    assert!(
        bytes.len() > 24 && bytes[..8] == *b"\x89PNG\r\n\x1a\n",
        "no screenshot of {page:?}"
    );
    let dim = |k: usize| u32::from_be_bytes(bytes[k..k + 4].try_into().unwrap());
    assert_eq!((dim(16), dim(20)), (1400, 900), "{png:?}");
    let messages = page_messages(&err);
    assert!(messages.is_empty(), "{page:?} logged: {messages:?}");
    let (dom, err) = headless(exe, page, &profile, &["--dump-dom".into()]);
    let messages = page_messages(&err);
    assert!(messages.is_empty(), "{page:?} logged: {messages:?}");
    for n in needles {
        assert!(dom.contains(n), "{page:?}: the DOM lacks {n:?}");
    }
    eprintln!("screenshot of {}: {}", page.display(), png.display());
}

/// The browser checks of the main job's pages in `out` (see the module docs); `compound` names a
/// compound whose datasheet is checked.
pub fn check_pages(out: &Path, compound: &str) {
    let Some(exe) = chromium() else {
        eprintln!("note: Chromium not installed; the browser check of the report pages is skipped");
        return;
    };
    let reports = out.join("reports");
    check_page(
        &exe,
        &reports.join(compound).join("datasheet.html"),
        &out.join("datasheet-screenshot.png"),
        &[
            "Verdict: ",
            "at 1 Hz, E″ peak",
            "tan δ at 60 °C, 10 Hz",
            "Rolling friction F/N",
            "<svg",
        ],
    );
    check_page(
        &exe,
        &reports.join("index.html"),
        &out.join("index-screenshot.png"),
        &[
            "Compounds and rolling friction",
            "rank by tan δ",
            "Rank at each temperature",
            "<svg",
        ],
    );
}

#[test]
fn console_lines_of_chromium_are_recognised() {
    // as Chromium 13x logs them with --enable-logging=stderr --v=0
    let log =
        "[1:1:1125/183836.308098:INFO:CONSOLE:1] \"boom\", source: file:///tmp/err.html (1)\n\
               [1:1:1125/183836.3:INFO:CONSOLE:1] \"Uncaught ReferenceError: f is not defined\"\n\
               [1:1:1125/183836.4:WARNING:gpu_init.cc(1)] no GPU\n";
    assert_eq!(page_messages(log).len(), 2);
}
