//! The report pages in a real browser, where Chromium is installed (CI need not have it: the check
//! skips with a note). [`check_pages`] is called by `pipeline_cli` on the output of its main job on
//! the shipped data (no second run): for a datasheet and the index it takes a 1400 × 900 screenshot
//! (the first screen; kept in the output folder to look at), checks the page logged no console
//! message (no JavaScript and no resource error: every plot is inline SVG), and reads the DOM
//! Chromium built to check the first screen's content came through the parser. Then, driven by the
//! run's own tables (issue 31), on the DOM of every datasheet and of the index:
//! - no band without its cut mark: where friction.csv holds a band that the plots clip (beyond
//!   [`BAND_CLIP_FACTOR`] times the curve's range), the page's legend explains the cut marks
//!   ([`CUT_LEGEND`]); where none is clipped, it does not;
//! - no ranked undetermined point: a point friction.csv marks as not determined (a `determined`
//!   column that is false, or a note saying "not determined") has no rank in the index's "Rank at
//!   each temperature" table;
//! - shear stays shear: the datasheet of a compound whose fit is shear names G′, G″, G∞ and never
//!   E′, E″, E∞.

use crate::shipped::table;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
/// The datasheet's legend for a band cut at the plot's edge (src/report/chart.rs `CUT_LEGEND`: a
/// spec of the page, written again here so that the test reads the page as a user would).
const CUT_LEGEND: &str = "band cut at edge";
/// Bands are drawn no further than this factor beyond the curve's own range (the datasheet's
/// `BAND_CLIP_FACTOR`, src/report/datasheet/mod.rs, written again here for the same reason).
const BAND_CLIP_FACTOR: f64 = 10.0;

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
/// every one of `needles`; the DOM.
fn check_page(exe: &Path, page: &Path, png: &Path, needles: &[&str]) -> String {
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
    dom
}

/// A friction.csv row of one compound, as the checks read it.
struct Row {
    scene: String,
    temp_c: String,
    friction: f64,
    band: Option<(f64, f64)>,
    undetermined: bool,
}

/// The rows of `reports/COMPOUND/friction.csv`.
fn rows(out: &Path, compound: &str) -> Vec<Row> {
    let (h, r) = table(&out.join("reports").join(compound).join("friction.csv"));
    let at = |name: &str| h.iter().position(|c| c == name);
    let (scene, temp, f) = (
        at("scene").unwrap(),
        at("temp_c").unwrap(),
        at("friction").unwrap(),
    );
    let (p05, p95, note) = (at("friction_p05"), at("friction_p95"), at("note"));
    let determined = at("determined");
    let num = |row: &[String], k: Option<usize>| k.and_then(|k| row[k].parse::<f64>().ok());
    r.iter()
        .map(|row| Row {
            scene: row[scene].clone(),
            temp_c: row[temp].clone(),
            friction: row[f].parse().unwrap_or(f64::NAN),
            band: num(row, p05).zip(num(row, p95)),
            undetermined: determined.is_some_and(|k| row[k] == "false")
                || note.is_some_and(|k| row[k].contains("not determined")),
        })
        .collect()
}

/// Whether the plots clip a band of `rows` in `scene`: the curve's range is that of its finite
/// positive frictions, widened by [`BAND_CLIP_FACTOR`] (crate::report::datasheet::friction_curve).
fn clipped(rows: &[Row], scene: &str) -> usize {
    let pts: Vec<&Row> = rows.iter().filter(|r| r.scene == scene).collect();
    let f = pts
        .iter()
        .map(|r| r.friction)
        .filter(|f| f.is_finite() && *f > 0.0);
    let (lo, hi) = f.fold((f64::INFINITY, 0.0f64), |(a, b), f| (a.min(f), b.max(f)));
    if lo > hi {
        return 0;
    }
    let (lo, hi) = (lo / BAND_CLIP_FACTOR, hi * BAND_CLIP_FACTOR);
    pts.iter()
        .filter_map(|r| r.band)
        .filter(|&(p05, p95)| p05 < lo || p95 > hi)
        .count()
}

/// The DOM of `page` (no screenshot), its console checked silent.
fn dom_of(exe: &Path, page: &Path, profile: &Path) -> String {
    let (dom, err) = headless(exe, page, profile, &["--dump-dom".into()]);
    let messages = page_messages(&err);
    assert!(messages.is_empty(), "{page:?} logged: {messages:?}");
    dom
}

/// The cells of the "Rank at each temperature" table of `scene` in the index's DOM: (header
/// temperatures, rows of (compound, cells)).
fn rank_table(index: &str, scene: &str) -> (Vec<String>, Vec<(String, Vec<String>)>) {
    let start = index
        .find(&format!("<h2>{scene}</h2>"))
        .unwrap_or_else(|| panic!("the index has no section for {scene}"));
    let section = &index[start..];
    let section = &section[..section[4..].find("<h2>").map_or(section.len(), |k| k + 4)];
    let Some(t) = section.find("Rank at each temperature") else {
        return (vec![], vec![]);
    };
    let tab = &section[t..];
    let tab = &tab[..tab.find("</table>").unwrap_or(tab.len())];
    let cells = |row: &str, tag: &str| -> Vec<String> {
        row.split(&format!("<{tag}"))
            .skip(1)
            .map(|c| {
                let c = &c[c.find('>').map_or(0, |k| k + 1)..];
                c[..c.find(&format!("</{tag}>")).unwrap_or(c.len())].to_string()
            })
            .collect()
    };
    let mut trs = tab.split("<tr>").skip(1);
    let head = trs.next().map(|r| cells(r, "th")).unwrap_or_default();
    let body = trs
        .map(|r| {
            let c = cells(r, "td");
            (
                c.first().cloned().unwrap_or_default(),
                c[1.min(c.len())..].to_vec(),
            )
        })
        .collect();
    (head.into_iter().skip(1).collect(), body)
}

/// The issue-31 checks of every page (see the module docs): cut marks, unranked undetermined
/// points, shear labels. Prints what it checked.
fn check_marks(exe: &Path, out: &Path, index_dom: &str) {
    let reports = out.join("reports");
    let fits = out.join("fits");
    let mut compounds: Vec<String> = std::fs::read_dir(&fits)
        .unwrap()
        .flatten()
        .filter_map(|e| {
            let n = e.file_name().to_string_lossy().into_owned();
            n.strip_suffix(".json").map(str::to_string)
        })
        .filter(|c| reports.join(c).join("friction.csv").is_file())
        .collect();
    compounds.sort();
    let (mut cut_pages, mut undetermined, mut shear) = (0, 0, 0);
    let mut index_cut = false;
    for c in &compounds {
        let rows = rows(out, c);
        let mut scenes: Vec<&str> = rows.iter().map(|r| r.scene.as_str()).collect();
        scenes.dedup();
        let cut: usize = scenes.iter().map(|s| clipped(&rows, s)).sum();
        index_cut |= cut > 0;
        let page = reports.join(c).join("datasheet.html");
        let dom = dom_of(exe, &page, &out.join(format!("dom-{c}.profile")));
        assert_eq!(
            dom.contains(CUT_LEGEND),
            cut > 0,
            "{c}: {cut} band end(s) clipped in the plots, the legend's cut line {}",
            if cut > 0 { "is missing" } else { "is there" }
        );
        cut_pages += usize::from(cut > 0);
        // undetermined points are never ranked at their temperature
        for r in rows.iter().filter(|r| r.undetermined) {
            undetermined += 1;
            let (temps, body) = rank_table(index_dom, &r.scene);
            let Some(k) = temps.iter().position(|t| *t == format!("{} °C", r.temp_c)) else {
                continue;
            };
            if let Some((_, cells)) = body.iter().find(|(n, _)| n == c) {
                let cell = cells.get(k).map_or("", String::as_str);
                assert!(
                    cell.trim().parse::<usize>().is_err(),
                    "{c} at {} °C in {} is not determined but ranked {cell}",
                    r.temp_c,
                    r.scene
                );
            }
        }
        // a shear compound's datasheet names shear moduli only
        let fit: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(fits.join(format!("{c}.json"))).unwrap())
                .unwrap();
        if fit["relaxation"]["kind"] == "shear" {
            shear += 1;
            for g in ["G′", "G″", "G∞"] {
                assert!(dom.contains(g), "{c} (shear): the datasheet lacks {g}");
            }
            for e in ["E′", "E″", "E∞"] {
                assert!(!dom.contains(e), "{c} (shear): the datasheet says {e}");
            }
        }
    }
    assert_eq!(
        index_dom.contains(CUT_LEGEND),
        index_cut,
        "the index's cut marks against the bands its overlays clip"
    );
    eprintln!(
        "browser marks: {} datasheets ({cut_pages} with clipped bands, all marked), {undetermined} \
         undetermined point(s) none ranked, {shear} shear datasheet(s) labelled G",
        compounds.len()
    );
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
    let index = check_page(
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
    check_marks(&exe, out, &index);
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
